-- arclen.henkel -- Henkel's comparison of arc length methods (H. Henkel,
-- "Calculating the Cubic Bezier Arc Length by Elliptic Integrals", 2014,
-- section 6), recomputed with arclen's own implementations.
--
-- For each of his six arcs: his rows in his order (Eqn, method), arclen's
-- length to 15 significant digits, its relative error against the 40-digit
-- reference (spec/data/curves2d.tsv, family "henkel", made by
-- tools/ref_lengths.py), arclen's step count, and Henkel's published value
-- (spec/data/henkel_published.tsv, parsed from the paper by
-- tools/henkel_published.py) with its own error.
--
--   require("arclen.repro.henkel").report()  -> the text of the six tables
--   require("arclen.repro.henkel").rows()    -> the same as data
local numtext = require("arclen.numtext")   -- numbers in any locale
local arclen = require("arclen")

local M = {}

-- Henkel's goal was an error below 1e-10: a published value further than
-- that from the 40-digit reference is flagged "off".
M.PUBLISHED_BAR = 1e-10

-- His seven rows, in his order, and the arclen method that plays each role.
-- Steps: what each method counts (see the legend printed with the tables).
M.ROWS = {
  {eqn = "2", label = "[Gravesen (1997)]", method = "gravesen"},
  {eqn = "7", label = "CQUAD integration", method = "gauss"},
  {eqn = "3", label = "Hypotenuse sum", method = "polyline"},
  {eqn = "7", label = "Trapez. rule int.", method = "trapezoid"},
  {eqn = "10", label = "Trapez. rule int.", method = "trapezoid-factored"},
  {eqn = "11", label = "[Carlson (1992)]", method = "elliptic"},
  {eqn = "2", label = "MetaPost", method = "metapost"},
}
-- Not in Henkel's tables: Gravesen's estimate with Richardson's step.
M.EXTRA = {
  {eqn = "2", label = "Gravesen+Richardson", method = "gravesen-richardson"},
}

local STEPS_OF = {
  gravesen = "pieces", ["gravesen-richardson"] = "pieces", gauss = "evals",
  polyline = "pieces", trapezoid = "pieces", ["trapezoid-factored"] = "pieces",
  elliptic = "calls", metapost = "evals",
}

-- The directory spec/data/ of the source tree this module lives in (the
-- demo runs from a clone), or of the current directory.
local function data_dir()
  local src = debug.getinfo(1, "S").source
  if src:sub(1, 1) == "@" then
    local dir = src:sub(2):match("^(.*)[/\\]lua[/\\]arclen[/\\][^/\\]+$")
    if dir then return dir .. "/spec/data/" end
  end
  return "spec/data/"
end

local function read_tsv(path)
  local f = io.open(path, "r")
  if not f then return nil end
  local header, rows = nil, {}
  for line in f:lines() do
    if line ~= "" then
      local fields = {}
      for field in (line .. "\t"):gmatch("([^\t]*)\t") do fields[#fields + 1] = field end
      if not header then
        header = fields
      else
        local row = {}
        for i, k in ipairs(header) do row[k] = fields[i] end
        rows[#rows + 1] = row
      end
    end
  end
  f:close()
  return rows
end

local KEYS = {"x0", "y0", "x1", "y1", "x2", "y2", "x3", "y3"}

local function coords(row)
  local c = {}
  for i, k in ipairs(KEYS) do c[i] = assert(numtext.tonumber(row[k]), k) end
  return c
end

local function same(a, b)
  for i = 1, 8 do if a[i] ~= b[i] then return false end end
  return true
end

-- Henkel's arcs and published rows, and the references, by arc number.
local function load(dir)
  dir = dir or data_dir()
  local pub = read_tsv(dir .. "henkel_published.tsv")
  local ref = read_tsv(dir .. "curves2d.tsv")
  local arcs = {}
  assert(pub, "arclen.henkel: " .. dir .. "henkel_published.tsv not found")
  for _, r in ipairs(pub) do
    local k = numtext.tonumber(r.arc)
    arcs[k] = arcs[k] or {curve = coords(r), published = {}}
    arcs[k].published[numtext.tonumber(r.row)] = {value = r.value, steps = r.steps}
  end
  if ref then
    for _, r in ipairs(ref) do
      if r.family == "henkel" then
        local k = numtext.tonumber(r.id:match("(%d+)$"))
        if arcs[k] then
          assert(same(arcs[k].curve, coords(r)),
                 "curves2d.tsv henkel-" .. k .. " differs from Henkel's arc")
          arcs[k].ref = r.L
        end
      end
    end
  end
  return arcs
end

-- 12 decimals cut off as Henkel printed mpost's double-mode values.
local function truncate12(x)
  local s = numtext.format("%.20f", x)
  return (s:match("^(%-?%d+%.%d%d%d%d%d%d%d%d%d%d%d%d)"))
end

local function measure(c, row)
  local ok, v, info = pcall(arclen.length, c, {method = row.method, info = true})
  if not ok then
    local msg = tostring(v)
    if msg:find("unknown method", 1, true) then
      return {failure = "method '" .. row.method .. "' not available yet"}
    end
    return {failure = msg:gsub("^.-%((.*)%)$", "%1")}
  end
  if v == nil then return {failure = info} end          -- nil, message
  return {value = v, steps = info[STEPS_OF[row.method]]}
end

-- All rows as data: for arc k, rows[k] = {curve, ref, list of
-- {eqn, label, method, value | failure, steps, err, published, pub_err, flag}}.
function M.rows(dir)
  local arcs = load(dir)
  local out = {}
  for k = 1, #arcs do
    local a = arcs[k]
    local L = a.ref and numtext.tonumber(a.ref)
    local list = {}
    local all = {}
    for i, r in ipairs(M.ROWS) do all[#all + 1] = {r, a.published[i]} end
    for _, r in ipairs(M.EXTRA) do all[#all + 1] = {r, nil} end
    for _, pair in ipairs(all) do
      local r, p = pair[1], pair[2]
      local m = measure(a.curve, r)
      local e = {eqn = r.eqn, label = r.label, method = r.method,
                 value = m.value, failure = m.failure, steps = m.steps}
      if e.value and L then e.err = math.abs(e.value - L) / L end
      if p then
        e.published, e.published_steps = p.value, p.steps
        local pv = numtext.tonumber(p.value)
        if pv and L then
          e.pub_err = math.abs(pv - L) / L
          if r.method == "metapost" then
            -- his value is mpost's double result cut to 12 decimals
            e.flag = (e.value and truncate12(e.value) == p.value) and "= mpost" or "!= mpost"
          elseif math.abs(pv - L) > M.PUBLISHED_BAR then
            e.flag = "off"
          end
        end
      end
      list[#list + 1] = e
    end
    out[k] = {curve = a.curve, ref = a.ref, rows = list}
  end
  return out
end

local function fmt_err(e)
  if e == nil then return "" end
  if e == 0 then return "0" end
  return numtext.format("%.1e", e)
end

local function curve_text(c)
  local function n(v) return (numtext.format("%.15g", v)) end
  return numtext.format("{{%s,%s},{%s,%s},{%s,%s},{%s,%s}}", n(c[1]), n(c[2]),
                       n(c[3]), n(c[4]), n(c[5]), n(c[6]), n(c[7]), n(c[8]))
end

-- The six tables as text.
function M.report(dir)
  local all = M.rows(dir)
  local b = {}
  local function w(...) b[#b + 1] = numtext.format(...) end
  w("Henkel (2014), section 6: six cubic arcs by every method, recomputed by %s\n",
    arclen._VERSION or "arclen")
  w("err: relative error against the 40-digit reference; Henkel's published values\n")
  w("beside arclen's ('off': further than %g from the reference, his own goal).\n",
    M.PUBLISHED_BAR)
  for k, a in ipairs(all) do
    w("\nArc %d  %s\n", k, curve_text(a.curve))
    w("reference length %s\n", a.ref or "(spec/data/curves2d.tsv not found)")
    w("%-4s %-20s %-18s %-8s %-9s | %-17s %-8s %-7s\n", "Eqn", "Method",
      "arclen", "err", "Steps", "Henkel", "err", "Steps")
    for _, e in ipairs(a.rows) do
      local v = e.value and numtext.format("%.15g", e.value) or "n/a"
      w("%-4s %-20s %-18s %-8s %-9s | %-17s %-8s %-7s %s\n", e.eqn, e.label,
        v, fmt_err(e.err), e.steps and numtext.format("%d", e.steps) or "",
        e.published or "(not in Henkel)", fmt_err(e.pub_err),
        e.published_steps or "", e.flag or (e.failure and "arclen: " .. e.failure) or "")
    end
  end
  w("\nSteps: Gravesen = subdivisions (rtol 1e-12; Henkel stopped on polygon - chord,\n")
  w("arclen on an error estimate, hence far fewer); CQUAD row = arclen's default\n")
  w("method 'gauss' (rtol 1e-12) and its speed evaluations; Eqn 3/7/10 rows = 10^6\n")
  w("steps as Henkel; Carlson = elliptic R-function calls; MetaPost = arc_test calls\n")
  w("(bit-identical to mpost -numbersystem=double; Henkel printed it cut to 12\n")
  w("decimals: '= mpost' checks that).  MetaPost adds 2^-17 per segment and has an\n")
  w("absolute tolerance (1/4096 at the top level), hence its ~1e-6 relative error.\n")
  return table.concat(b)
end

return M
