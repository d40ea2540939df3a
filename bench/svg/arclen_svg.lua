-- bench/svg/arclen_svg.lua -- arclen's side of `make bench-svg`: whole
-- documents read and measured by arclen.svg at tol 1e-12, the reader's cost
-- (XML, transforms, path data into cubics) and the measuring's (the lengths)
-- timed apart; and, for the JavaScript peers (which read no XML), every
-- drawn element's own path data with the scale of its transform.
--   lua5.4 bench/svg/arclen_svg.lua OUTDIR FILE...
-- Prints "arclen<TAB>file<TAB>total<TAB>read_s<TAB>measure_s" per file
-- (best of the repetitions) and "px-scale<TAB>file<TAB>k" (the px total
-- over the user-unit total: svgelements measures in px), writes
-- OUTDIR/elements.tsv.
local svg = require("arclen.svg")
local out, files = arg[1], {}
for i = 2, #arg do files[#files + 1] = arg[i] end
local REPS = tonumber(os.getenv("BENCH_REPS")) or 5
local clock = os.clock

-- The scale of a similarity (a rotation times s), or nil for another map.
local function similarity(C)
  local a, b, c, d = C[1], C[2], C[3], C[4]
  local s2 = a * a + b * b
  if math.abs(c * c + d * d - s2) <= 1e-12 * s2 and math.abs(a * c + b * d) <= 1e-12 * s2 then
    return math.sqrt(s2)
  end
  return nil
end

local el = assert(io.open(out .. "/elements.tsv", "w"))
for _, f in ipairs(files) do
  local best_read, best_measure, total = math.huge, math.huge, nil
  for _ = 1, REPS do
    local t0 = clock()
    local doc = svg.read(f, {measure = false})
    local t1 = clock()
    local sum = 0
    for _, e in ipairs(doc.elements) do sum = sum + e.path:length() end
    local t2 = clock()
    best_read = math.min(best_read, t1 - t0)
    best_measure = math.min(best_measure, t2 - t1)
    total = sum
  end
  print(("arclen\t%s\t%.17g\t%.6f\t%.6f"):format(f, total, best_read, best_measure))
  print(("px-scale\t%s\t%.17g\t0"):format(f, svg.read(f, {units = "px"}).total / total))
  for _, e in ipairs(svg.read(f, {measure = false}).elements) do
    local s = similarity(e.ctm)
    el:write(f, "\t", s and ("%.17g"):format(s) or "-", "\t", (e.d:gsub("%s+", " ")), "\n")
  end
end
el:close()
