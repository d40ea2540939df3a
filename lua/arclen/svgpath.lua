-- arclen.svgpath -- SVG path data (the `d` attribute, SVG 1.1 section 8.3
-- and SVG 2 section 9.3) to segments.  The reader is C
-- (src/svg/pathdata.c, bound as arclen.core.svg_pathdata) or, without the
-- C core, arclen.pure_svgpath; this module gives it the interface
-- arclen.path expects.
--
-- parse(d, arc_tol [, T [, arcs]]) returns the segments of all subpaths
-- as records packed in one string of doubles (8 each: the kind's numbers,
-- then zeros) with their kinds, and the subpaths in order:
--   {packed = string, n = segments, kinds = string or nil,
--    [j] = {x = x0, y = y0, closed = bool, n = its segments}}
-- arcs "conics" (nil too): L H V Z give lines (L), Q T quadratics (Q), C S
-- cubics (C), A at most four conics of at most 90 degrees (R: P0 P1 P2 w,
-- weights 1 w 1), all exactly; kinds is nil when every segment is a cubic.
-- arcs "cubics": cubics only, kinds nil -- lines with the control points
-- at thirds (the same curve, speed constant), quadratics degree-elevated
-- (C1 = Q0 + 2/3 (Q1 - Q0), C2 = Q2 + 2/3 (Q1 - Q2): the same curve),
-- elliptical arcs through the conversion of arclen.svg_arc (Floater's
-- mid-point scheme) at a Hausdorff distance of at most arc_tol * max(rx,
-- ry, chord/2).  T ({a, b, c, d, e, f} as SVG's matrix(a b c d e f),
-- optional) maps every control point (exact for every kind; a conic keeps
-- its weight); an arc made of cubics keeps its tolerance relative to the
-- size of its image.  Errors are raised as {pos = byte position, msg =
-- text} tables (pos nil for the transform's overflow); the caller turns
-- them into "bad argument" messages.
local svg_pathdata = require("arclen.engine").svg_pathdata

local M = {}

local sqrt, abs, min, max = math.sqrt, math.abs, math.min, math.max

function M.parse(d, arc_tol, T, arcs)
  local subpaths, msg, pos = svg_pathdata(d, arc_tol, T, arcs)
  if subpaths == nil then error({pos = pos, msg = msg}, 0) end
  return subpaths
end

-- segment_end(seg, kind) -> x, y: the last point of a 2D segment (seg its
-- numbers, kind "line", "quad", "cubic" or "conic" as arclen.path's
-- p:segment(k) reports it; nil: a cubic).
function M.segment_end(seg, kind)
  if kind == "conic" then return seg[5], seg[6] end
  local n = kind == "line" and 4 or kind == "quad" and 6 or 8
  return seg[n - 1], seg[n]
end

-- The real roots in (0, 1) of a t^2 + b t + c (a, b, c from one segment's
-- coordinate), passed to f; the stable quadratic formula.
local function roots01(a, b, c, f)
  local function at(t) if t > 0 and t < 1 then f(t) end end
  if abs(a) < 1e-300 then      -- as good as linear (svg.stat's cubics of before)
    if b ~= 0 then at(-c / b) end
    return
  end
  local disc = b * b - 4 * a * c
  if disc < 0 then return end
  local q = -0.5 * (b + (b >= 0 and 1 or -1) * sqrt(disc))
  at(q / a)
  if q ~= 0 then at(c / q) end
end

-- The range of one coordinate (p: its values at the control points) on
-- [0, 1]: the ends and the derivative's zeros inside.
local function range(kind, p, w)
  local lo, hi = p[1], p[1]
  local last = kind == "line" and 2 or kind == "cubic" and 4 or 3
  lo, hi = min(lo, p[last]), max(hi, p[last])
  local function add(v) if v < lo then lo = v end if v > hi then hi = v end end
  if kind == "quad" then         -- B'(t)/2 = (p1 - p0)(1 - t) + (p2 - p1) t
    roots01(0, p[1] - 2 * p[2] + p[3], p[2] - p[1], function(t)
      local u = 1 - t
      add(u * u * p[1] + 2 * u * t * p[2] + t * t * p[3])
    end)
  elseif kind == "cubic" then    -- B'(t)/3 = a t^2 + b t + c
    roots01(-p[1] + 3 * p[2] - 3 * p[3] + p[4], 2 * (p[1] - 2 * p[2] + p[3]), p[2] - p[1],
      function(t)
        local u = 1 - t
        add(u * u * u * p[1] + 3 * u * u * t * p[2] + 3 * u * t * t * p[3] + t * t * t * p[4])
      end)
  elseif kind == "conic" then
    -- the numerator of the rational quadratic's derivative (weights 1 w 1):
    -- w (p1 - p0) (1-t)^2 + (p2 - p0) t (1-t) + w (p2 - p1) t^2
    local a0, a1, a2 = w * (p[2] - p[1]), p[3] - p[1], w * (p[3] - p[2])
    roots01(a0 - a1 + a2, a1 - 2 * a0, a0, function(t)
      local u = 1 - t
      local b0, b1, b2 = u * u, 2 * w * t * u, t * t
      add((b0 * p[1] + b1 * p[2] + b2 * p[3]) / (b0 + b1 + b2))
    end)
  end
  return lo, hi
end

-- segment_box(seg, kind) -> x0, y0, x1, y1: the bounding box of a 2D
-- segment (kind as segment_end's): each coordinate's extremes on [0, 1].
function M.segment_box(seg, kind)
  kind = kind or "cubic"
  local n = kind == "line" and 2 or kind == "cubic" and 4 or 3
  local xs, ys = {}, {}
  for i = 1, n do xs[i], ys[i] = seg[2 * i - 1], seg[2 * i] end
  local x0, x1 = range(kind, xs, seg[7])
  local y0, y1 = range(kind, ys, seg[7])
  return x0, y0, x1, y1
end

return M
