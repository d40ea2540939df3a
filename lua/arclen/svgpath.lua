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

function M.parse(d, arc_tol, T, arcs)
  local subpaths, msg, pos = svg_pathdata(d, arc_tol, T, arcs)
  if subpaths == nil then error({pos = pos, msg = msg}, 0) end
  return subpaths
end

return M
