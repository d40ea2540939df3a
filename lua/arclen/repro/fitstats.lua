-- arclen.fitstats -- Walter & Fournier's Table 1 for the length-versus-t
-- fits: per set of curves, the max of the per-curve max errors, the average
-- of the per-curve max errors, the average of the per-curve mean errors
-- (Eqn 9 on t = 0, 0.05, ..., 0.95), non-monotone fits and integrand
-- evaluations, for the paper's method and the default.
--
--   local fs = require "arclen.repro.fitstats"
--   local curves = fs.random_set(3000, 1)       -- the paper's random set
--   local row = fs.stats(curves, {method = "paper", n = 10}, {truth = "simpson"})
--   print(row.max, row.avgmax, row.avgavg, row.nonmono, row.evals)
--   fs.main()        -- prints the whole table (make fit-stats)
--
-- As a script: lua5.4 lua/arclen/fitstats.lua [--curves N] [--seed S]
--   [--fonts path] [--quick]
local numtext = require("arclen.numtext")   -- numbers in any locale
local arclen = require "arclen"

local M = {}

-- Numerical Recipes' ran1 (Park-Miller minimal standard with a Bays-Durham
-- shuffle), the generator of the paper's [pres92].  Integer arithmetic
-- below 2^53, so it runs the same on Lua 5.1-5.4 and LuaJIT.
-- Constants: IA 16807, IM 2^31 - 1, IQ 127773, IR 2836, NTAB 32 (NR 7.1).
function M.ran1(seed)
  local IA, IM, IQ, IR, NTAB = 16807, 2147483647, 127773, 2836, 32
  local NDIV = 1 + math.floor((IM - 1) / NTAB)
  local RNMX = 1 - 1.2e-7
  local idum = math.max(1, math.floor(math.abs(seed or 1)))
  local iv, iy = {}, 0
  local function step()
    local k = math.floor(idum / IQ)
    idum = IA * (idum - k * IQ) - IR * k
    if idum < 0 then idum = idum + IM end
  end
  for j = NTAB + 7, 0, -1 do
    step()
    if j < NTAB then iv[j] = idum end
  end
  iy = iv[0]
  return function()
    step()
    local j = math.floor(iy / NDIV)
    iy = iv[j]
    iv[j] = idum
    return math.min(iy / IM, RNMX)
  end
end

-- n curves with 8 coordinates uniform in [0, 10) (the paper's random set).
function M.random_set(n, seed)
  local r, curves = M.ran1(seed), {}
  for i = 1, n do
    local c = {}
    for k = 1, 8 do c[k] = 10 * r() end
    curves[i] = c
  end
  return curves
end

-- The font outlines of tools/font_cubics.py: fonts in file order, each
-- {name =, family =, curves = {...}}.
function M.font_sets(path)
  path = path or "spec/data/font_cubics.tsv"
  local f = assert(io.open(path, "r"))
  local fonts, byname = {}, {}
  local header = true
  for line in f:lines() do
    if header then
      header = false
    else
      local fam, name, _, rest = line:match("^([^\t]+)\t([^\t]+)\t([^\t]+)\t(.*)$")
      local c = {}
      for v in rest:gmatch("[^\t]+") do c[#c + 1] = numtext.tonumber(v) end
      if not byname[name] then
        byname[name] = {name = name, family = fam, curves = {}}
        fonts[#fonts + 1] = byname[name]
      end
      local list = byname[name].curves
      list[#list + 1] = c
    end
  end
  f:close()
  return fonts
end

-- Table 1's numbers for one set.  fitopts go to arclen.fit; erropts to
-- fit:errors ({truth =, inverse =, npts =}).  Also returns the per-curve
-- max errors (for histograms) in row.maxes.
function M.stats(curves, fitopts, erropts)
  local row = {curves = #curves, max = 0, avgmax = 0, avgavg = 0, nonmono = 0,
               evals = 0, maxes = {}, worst = nil, failed = 0}
  for i, c in ipairs(curves) do
    local fit = arclen.fit(c, fitopts)
    if not fit then
      row.failed = row.failed + 1
    else
      local mx, mean = fit:errors(erropts)
      row.maxes[#row.maxes + 1] = mx
      if mx > row.max then row.max, row.worst = mx, i end
      row.avgmax = row.avgmax + mx
      row.avgavg = row.avgavg + mean
      row.evals = row.evals + fit.evals
      if not fit:monotone() then row.nonmono = row.nonmono + 1 end
    end
  end
  local n = #row.maxes
  if n > 0 then
    row.avgmax, row.avgavg, row.evals = row.avgmax / n, row.avgavg / n, row.evals / n
  end
  return row
end

-- The rows of `make fit-stats`: label, fit options, error options.
M.configs = {
  {"paper n=10, qsimp truth (as published)", {method = "paper", n = 10}, {truth = "simpson"}},
  {"paper n=10", {method = "paper", n = 10}, {truth = "exact"}},
  {"paper n=3", {method = "paper", n = 3}, {truth = "exact"}},
  {"paper n=10, inverse t(s)", {method = "paper", n = 10}, {truth = "exact", inverse = true}},
  {"paper n=10, monotone projection", {method = "paper", n = 10, monotone = true}, {truth = "exact"}},
  {"hermite (default)", {}, {truth = "exact"}},
  {"hermite, inverse t(s)", {}, {truth = "exact", inverse = true}},
  {"hermite tol=1e-4", {tol = 1e-4}, {truth = "exact"}},
  {"hermite tol=1e-4, inverse", {tol = 1e-4}, {truth = "exact", inverse = true}},
}

-- The paper's Table 1 (n = 10), for the reader's comparison.
M.published = {
  {"Cooper (Bitstream)", 3401, 0.060545, 0.002432, 0.000946},
  {"Zurich (Bitstream)", 1285, 0.030641, 0.001708, 0.000737},
  {"Random", 3000, 0.087392, 0.019202, 0.007405},
}

local function fmt_row(set, label, r)
  return numtext.format("%-22s %-40s %6d  %9.6f  %9.6f  %9.6f  %5d %6.2f%%  %7.2f",
                       set, label, r.curves, r.max, r.avgmax, r.avgavg, r.nonmono,
                       100 * r.nonmono / math.max(1, r.curves), r.evals)
end

M.header = numtext.format("%-22s %-40s %6s  %9s  %9s  %9s  %13s  %7s", "set", "method",
                         "curves", "max", "avg max", "avg avg", "non-monotone",
                         "evals")

-- Print the table: published rows, then each configuration on the random
-- set and on the worst font (largest max) of each family.
function M.main(args)
  args = args or {}
  local ncurves, seed, fontpath, quick = 3000, 1, "spec/data/font_cubics.tsv", false
  local i = 1
  while i <= #args do
    local a = args[i]
    if a == "--curves" then ncurves = numtext.tonumber(args[i + 1]); i = i + 1
    elseif a == "--seed" then seed = numtext.tonumber(args[i + 1]); i = i + 1
    elseif a == "--fonts" then fontpath = args[i + 1]; i = i + 1
    elseif a == "--quick" then quick = true
    else error("fitstats: unknown argument " .. tostring(a)) end
    i = i + 1
  end
  local out = io.stdout
  out:write("Walter & Fournier's Table 1: errors |s(t)/s(1) - fit| at t = 0, 0.05, ..., 0.95\n")
  out:write("(inverse rows: |s(t_fit(u))/s(1) - u| at u = 0, 0.05, ..., 0.95; evals: speed\n")
  out:write(" evaluations per curve; truth: accurate length unless marked qsimp)\n\n")
  out:write(M.header, "\n")
  for _, p in ipairs(M.published) do
    out:write(numtext.format("%-22s %-40s %6d  %9.6f  %9.6f  %9.6f  %13s  %7s\n", p[1],
                            "published, n=10", p[2], p[3], p[4], p[5], "-", "-"))
  end
  local sets = {{numtext.format("random (ran1 seed %d)", seed), M.random_set(ncurves, seed)}}
  local fonts = {}
  local ok, result = pcall(M.font_sets, fontpath)
  if ok then fonts = result else out:write("(no font data: ", tostring(result), ")\n") end
  local configs = quick and {M.configs[1], M.configs[6]} or M.configs
  for _, set in ipairs(sets) do
    for _, cfg in ipairs(configs) do
      out:write(fmt_row(set[1], cfg[1], M.stats(set[2], cfg[2], cfg[3])), "\n")
    end
  end
  -- Fonts: per family the font with the largest paper n=10 max (as Table 1).
  local families, order = {}, {}
  for _, font in ipairs(fonts) do
    if not families[font.family] then
      families[font.family] = {}
      order[#order + 1] = font.family
    end
    local list = families[font.family]
    list[#list + 1] = font
  end
  for _, fam in ipairs(order) do
    local worst, worstmax = nil, -1
    for _, font in ipairs(families[fam]) do
      local r = M.stats(font.curves, M.configs[1][2], M.configs[1][3])
      if r.max > worstmax then worst, worstmax = font, r.max end
    end
    for _, cfg in ipairs(configs) do
      out:write(fmt_row(worst.name, cfg[1], M.stats(worst.curves, cfg[2], cfg[3])), "\n")
    end
  end
end

if ... ~= "arclen.repro.fitstats" then M.main(arg) end

return M
