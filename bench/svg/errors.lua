-- bench/svg/errors.lua -- arclen.svg's error on every document of
-- spec/data/svg_refs.tsv at a tolerance: worst relative error and worst
-- error over the guaranteed bound (tol L + 2 pi arc_tol arcscale).
--   lua5.4 bench/svg/errors.lua [TOL]
local svg = require("arclen.svg")
local tol = tonumber(arg[1]) or 1e-12
local worst, wfile, ratio, rfile, n = 0, nil, 0, nil, 0
for line in io.lines("spec/data/svg_refs.tsv") do
  local f, units, option, count, L, _, scale = line:match(
    "^([^\t#]+)\t([^\t]+)\t([^\t]+)\t(%d+)\t([^\t]+)\t([^\t]+)\t([^\t]+)$")
  if f then
    local o = {tol = tol, units = units}
    if option ~= "-" then o[option] = true end
    local doc = svg.read("spec/data/svg/" .. f, o)
    local ref = tonumber(L)
    local err = math.abs(doc.total - ref)
    local rel = err / ref
    local r = err / (tol * ref + 2 * math.pi * tol * tonumber(scale))
    n = n + 1
    if rel > worst then worst, wfile = rel, f .. " " .. units .. " " .. option end
    if r > ratio then ratio, rfile = r, f .. " " .. units .. " " .. option end
    assert(#doc.elements == tonumber(count), f)
  end
end
print(("%d documents at tol %g: worst relative error %.3g (%s); worst error / bound %.3g (%s)"):format(
  n, tol, worst, wfile, ratio, rfile))
