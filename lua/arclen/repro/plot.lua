-- arclen.plot -- pictures of the length-versus-t fits (Walter & Fournier
-- 1996), drawn with arclen.repro.svgplot:
--   plot.fit(c [, opts])        the true s(t)/s(1) against the fits, with the
--                               span boundaries and the "inflexion points"
--                               (the paper's Figures 2, 3 and 9)
--   plot.fit_error(c [, opts])  the signed error fit - truth along t
--   plot.histogram(sets [, o])  histograms of per-curve max errors over a set
--                               (Figures 6 and 7); sets = {{label=, values=}}
--   plot.sorted(sets [, o])     the per-curve max errors sorted (Figure 5)
-- Each returns SVG text.  opts: methods (list of {label=, opts=} given to
-- arclen.fit; default the paper's n = 10 and the default hermite), title,
-- samples (points along t, 201).
--
-- As a script (LUA_PATH=lua/?.lua, LUA_CPATH=build/5.4/?.so):
--   lua5.4 lua/arclen/plot.lua fit x0 y0 x1 y1 x2 y2 x3 y3 [out.svg]
--   lua5.4 lua/arclen/plot.lua all [dir]     every figure into dir (.)
local numtext = require("arclen.numtext")   -- numbers in any locale
local arclen = require "arclen"
local svg = require "arclen.repro.svgplot"

-- math.log has no base argument in Lua 5.1 and LuaJIT; 5.4 has no log10.
local log10 = math.log10 or function(x) return math.log(x, 10) end

local M = {}

M.default_methods = {
  {label = "paper, n = 10", opts = {method = "paper", n = 10}},
  {label = "hermite (default)", opts = {}},
}

local function curve_label(c)
  local parts = {}
  for i = 1, #c do parts[i] = numtext.format("%g", c[i]) end
  return table.concat(parts, " ")
end

-- The true s(t)/s(1) at samples+1 points, from the accurate length.
local function truth(c, samples)
  local total, pts = arclen.length(c), {}
  for k = 0, samples do
    local t = k / samples
    pts[k + 1] = {t, t == 0 and 0 or arclen.length(c, {t1 = t}) / total}
  end
  return pts
end

-- Vertical marks for the speed's critical points (the paper's "inflexion
-- points" of s(t)) and for each fit's span boundaries.
local function marks(fig, fits, at)
  local crit = fits[1] and fits[1].fit.critical or {}
  for i, t in ipairs(crit) do
    fig:vline(t, {color = "#777777", dash = "2 3", width = 1.2,
                  text = numtext.format("inflexion t = %.4f", t),
                  label = i == 1 and "inflexion points (speed's critical points)" or nil})
  end
  local shapes = {"square", "diamond", "circle"}
  for i = #fits, 1, -1 do   -- the first method drawn last, on top
    local f = fits[i]
    local spans = f.fit:spans()
    local pts = {}
    for i = 1, #spans do pts[#pts + 1] = {spans[i].t0, at(f.fit, spans[i].t0)} end
    pts[#pts + 1] = {1, at(f.fit, 1)}
    fig:markers(pts, {color = f.color, shape = shapes[(i - 1) % 3 + 1],
                      size = i == 1 and 5.5 or 4,
                      label = numtext.format("%s: span ends (%d span%s)", f.label, #spans,
                                            #spans == 1 and "" or "s")})
  end
end

local function build_fits(c, methods)
  local fits = {}
  for i, m in ipairs(methods or M.default_methods) do
    local fit = assert(arclen.fit(c, m.opts))
    fits[#fits + 1] = {label = m.label, fit = fit, color = svg.palette[i]}
  end
  return fits
end

function M.fit(c, opts)
  opts = opts or {}
  local samples = opts.samples or 200
  local fits = build_fits(c, opts.methods)
  local fig = svg.figure{
    title = opts.title or "Length against t: true (dotted) and fitted",
    xlabel = "t   (curve " .. curve_label(c) .. ")",
    ylabel = "s(t) / s(1)", xrange = {0, 1}, yrange = {0, 1},
    legend = "bottomright", width = opts.width, height = opts.height,
  }
  fig:line(truth(c, samples), {color = "#000000", dash = "2 3", width = 2.2,
                               label = "true s(t)/s(1)"})
  for _, f in ipairs(fits) do
    local pts = {}
    for k = 0, samples do pts[k + 1] = {k / samples, f.fit:value(k / samples)} end
    local maxe = f.fit:errors{truth = "exact"}
    fig:line(pts, {color = f.color, width = 1.6,
                   label = numtext.format("%s (max error %.2g)", f.label, maxe)})
  end
  marks(fig, fits, function(fit, t) return fit:value(t) end)
  return fig:render()
end

-- |fit - truth| on a log axis (opts.signed: the signed error, linear axis).
function M.fit_error(c, opts)
  opts = opts or {}
  local samples = opts.samples or 400
  local fits = build_fits(c, opts.methods)
  local tr = truth(c, samples)
  local signed = opts.signed
  local floor, top = 0, 0
  if not signed then   -- room below the curves for the legend
    floor = math.huge
    for _, f in ipairs(fits) do
      for k = 1, samples + 1 do
        local e = math.abs(f.fit:value(tr[k][1]) - tr[k][2])
        if e > 0 and e < floor then floor = e end
        if e > top then top = e end
      end
    end
    floor = 10 ^ math.floor(log10(math.max(floor, top * 1e-9)))
  end
  local fig = svg.figure{
    title = opts.title or "Error of the fits along t",
    xlabel = "t   (curve " .. curve_label(c) .. ")",
    ylabel = signed and "fit - true s(t)/s(1)" or "|fit - true s(t)/s(1)|",
    xrange = {0, 1}, ylog = not signed, legend = "bottomright",
    yrange = not signed and {floor / 1000, 10 ^ math.ceil(log10(top))} or nil,
    width = opts.width, height = opts.height,
  }
  if signed then fig:hline(0, {color = "#999999", width = 1}) end
  local function err(fit, k)
    local e = fit:value(tr[k][1]) - tr[k][2]
    return signed and e or math.abs(e)
  end
  for _, f in ipairs(fits) do
    local pts = {}
    for k = 1, samples + 1 do pts[k] = {tr[k][1], err(f.fit, k)} end
    fig:line(pts, {color = f.color, label = f.label})
  end
  -- Span ends sit on zero (signed) or low on the log axis: the fits
  -- interpolate there.
  marks(fig, fits, function() return signed and 0 or floor / 100 end)
  return fig:render()
end

-- sets: {{label =, values = {per-curve max errors}}, ...}.  opts: log
-- (log-spaced bins on a log axis, default true), bins, range, title.
function M.histogram(sets, opts)
  opts = opts or {}
  local log = opts.log ~= false
  local lo, hi = math.huge, 0
  for _, s in ipairs(sets) do
    for _, v in ipairs(s.values) do
      if v > 0 and v < lo then lo = v end
      if v > hi then hi = v end
    end
  end
  local range = opts.range
  if not range then
    if log then
      range = {10 ^ math.floor(log10(lo)), 10 ^ math.ceil(log10(hi))}
    else
      range = {0, hi}
    end
  end
  local fig = svg.figure{
    title = opts.title or "Histogram of per-curve max errors",
    xlabel = "max error |s(t)/s(1) - fit| of a curve", ylabel = "curves",
    xlog = log, legend = opts.legend or (log and "topleft" or "topright"),
    width = opts.width, height = opts.height,
  }
  for i, s in ipairs(sets) do
    local edges, counts = svg.histogram(s.values, {bins = opts.bins or 40,
                                                    range = range, log = log})
    fig:bars(edges, counts, {color = svg.palette[i], label = s.label, opacity = 0.5})
  end
  return fig:render()
end

function M.sorted(sets, opts)
  opts = opts or {}
  local fig = svg.figure{
    title = opts.title or "Per-curve max errors, sorted",
    xlabel = "curves, by increasing max error", ylabel = "max error", ylog = true,
    width = opts.width, height = opts.height,
  }
  for i, s in ipairs(sets) do
    local v = {}
    for k, x in ipairs(s.values) do v[k] = x end
    table.sort(v)
    local pts = {}
    for k, x in ipairs(v) do pts[k] = {k, x} end
    fig:line(pts, {color = svg.palette[i], label = s.label})
  end
  return fig:render()
end

-- ---- the paper's figures, for `make fit-plots` ------------------------

-- The paper's worst curve (its Figure 8; control points from Sec. 5).
M.worst = {6.885279, 0.753269, 9.738172, 4.203904, 1.734599, 8.224792,
           8.154818, 4.145680}

-- The curve with nroots critical points whose paper fit is worst.
local function worst_with_roots(curves, nroots)
  local best, worst = nil, -1
  for _, c in ipairs(curves) do
    local f = arclen.fit(c, {method = "paper"})
    if #f.critical == nroots then
      local e = f:errors()
      if e > worst then best, worst = c, e end
    end
  end
  return best
end

-- Writes every figure into dir; returns the list of paths.
function M.all(dir)
  dir = dir or "."
  local fs = require "arclen.repro.fitstats"
  local written = {}
  local function out(name, text)
    written[#written + 1] = svg.write(dir .. "/" .. name, text)
  end
  local random = fs.random_set(3000, 1)
  out("fit_worst.svg", M.fit(M.worst, {title =
      "Figure 9: the paper's worst curve (one inflexion point)"}))
  out("fit_worst_error.svg", M.fit_error(M.worst, {title =
      "The paper's worst curve: error along t"}))
  local zero = worst_with_roots(random, 0)
  if zero then out("fit_zero.svg", M.fit(zero, {title =
      "Figure 2: no inflexion point (the paper's worst such curve)"})) end
  local three = worst_with_roots(random, 3)
  if three then
    out("fit_three.svg", M.fit(three, {title =
        "Figure 3: three inflexion points, two spans (paper) vs hermite"}))
    out("fit_three_error.svg", M.fit_error(three, {title =
        "Three inflexion points: error along t"}))
  end
  local paper = fs.stats(random, {method = "paper", n = 10}, {truth = "simpson"})
  local paper3 = fs.stats(random, {method = "paper", n = 3}, {truth = "simpson"})
  local herm = fs.stats(random, {}, {truth = "exact"})
  out("hist_random.svg", M.histogram({
      {label = "paper, n = 10", values = paper.maxes},
      {label = "hermite (default)", values = herm.maxes}},
      {title = "Figure 6: per-curve max errors, 3000 random curves"}))
  out("hist_random_linear.svg", M.histogram({
      {label = "paper, n = 10", values = paper.maxes}},
      {log = false, bins = 30, title = "Figure 6 (as published): paper, n = 10, linear bins"}))
  out("sorted_random.svg", M.sorted({
      {label = "paper, n = 3", values = paper3.maxes},
      {label = "paper, n = 10", values = paper.maxes},
      {label = "hermite (default)", values = herm.maxes}},
      {title = "Figure 5: sorted per-curve max errors, 3000 random curves"}))
  local ok, fonts = pcall(fs.font_sets)
  if ok then
    local fam = {}
    for _, f in ipairs(fonts) do
      if f.family == "URWBookman" then
        for _, c in ipairs(f.curves) do fam[#fam + 1] = c end
      end
    end
    local fp = fs.stats(fam, {method = "paper", n = 10}, {truth = "simpson"})
    local fh = fs.stats(fam, {}, {truth = "exact"})
    out("hist_font.svg", M.histogram({
        {label = "paper, n = 10", values = fp.maxes},
        {label = "hermite (default)", values = fh.maxes}},
        {title = "Figure 7: per-curve max errors, URW Bookman (4 fonts)"}))
  end
  return written
end

local function main(args)
  local cmd = args[1]
  if cmd == "fit" then
    local c = {}
    for i = 2, 9 do c[#c + 1] = assert(numtext.tonumber(args[i]), "fit: 8 numbers expected") end
    local text = M.fit(c)
    if args[10] then svg.write(args[10], text) else io.write(text) end
  elseif cmd == "all" then
    for _, p in ipairs(M.all(args[2])) do print(p) end
  else
    io.stderr:write("usage: plot.lua fit x0 y0 x1 y1 x2 y2 x3 y3 [out.svg] | all [dir]\n")
    os.exit(1)
  end
end

if ... ~= "arclen.repro.plot" then main(arg) end

return M
