-- arclen.conicplot -- pictures of Floater's conic schemes:
--   lambda(w) of the five schemes on 0 < w < 4 (the paper's Figure 3), and
--   the error bound of Theorem 1 against the subdivision level r.
-- The numbers come from the module; the drawing from arclen.repro.svgplot.
--   local cp = require "arclen.repro.conicplot"
--   cp.write_lambda("lambda.svg"); cp.write_levels("levels.svg")
local arclen = require "arclen"
local svg = require "arclen.repro.svgplot"

local M = {}

M.schemes = {"quadratic", "g2", "midpoint", "c2", "g4"}
M.labels = {
  quadratic = "quadratic (Prop 3), order 4",
  g2 = "G2 Hermite (Prop 4), order 6",
  midpoint = "mid-point (Prop 5), order 6",
  c2 = "C2 spline (Prop 8), order 4",
  g4 = "G4 spline (Props 9-10), order 6",
}

-- {scheme = {{w, lambda}, ...}} on (0, 4].
function M.lambda_data(n)
  n = n or 400
  local data = {}
  for _, s in ipairs(M.schemes) do
    local pts = {}
    for k = 1, n do
      local w = 4 * k / n
      pts[#pts + 1] = {w, (arclen.conic_scheme(s, w))}
    end
    data[s] = pts
  end
  return data
end

-- {scheme = {{r, bound}, ...}}: Theorem 1's bound at levels 0..rmax for the
-- conic (p0, p1, p2, w) (default: the unit quarter circle).
function M.level_data(rmax, p0, p1, p2, w)
  rmax = rmax or 6
  p0, p1, p2, w = p0 or {1, 0}, p1 or {1, 1}, p2 or {0, 1}, w or math.sqrt(0.5)
  local data = {}
  for _, s in ipairs(M.schemes) do
    local pts = {}
    for r = 0, rmax do
      local _, bound = arclen.conic(p0, p1, p2, w, {scheme = s, level = r})
      pts[#pts + 1] = {r, bound}
    end
    data[s] = pts
  end
  return data
end

local function series(data, transform)
  local out = {}
  for _, s in ipairs(M.schemes) do
    local pts = {}
    for i, p in ipairs(data[s]) do pts[i] = transform and transform(p) or p end
    out[#out + 1] = {label = M.labels[s], points = pts}
  end
  return out
end

-- The SVG text of Figure 3.
function M.lambda_svg()
  return svg.lineplot{
    title = "Floater's Figure 3: lambda(w) of the five schemes",
    xlabel = "weight w", ylabel = "lambda(w)",
    xrange = {0, 4}, yrange = {0, 1.2}, legend = "bottomright",
    series = series(M.lambda_data()),
    marks = {{x = 1, label = "w = 1: lambda = 2/3"}},
  }
end

-- The SVG text of the error bound against the level (log scale).
-- (a line per scheme with a marker at each level)
function M.levels_svg()
  local fig = svg.figure{
    title = "Theorem 1's bound on a quarter circle, against the level r",
    xlabel = "subdivision level r (2^r cubics)", ylabel = "Hausdorff bound",
    xrange = {0, 6}, ylog = true, legend = "bottomleft",
  }
  for i, sr in ipairs(series(M.level_data(6))) do
    local color = svg.palette[i]
    fig:line(sr.points, {label = sr.label, color = color})
    fig:markers(sr.points, {color = color, shape = "circle", size = 3})
  end
  return fig:render()
end

function M.write_lambda(path) return svg.write(path, M.lambda_svg()) end
function M.write_levels(path) return svg.write(path, M.levels_svg()) end

return M
