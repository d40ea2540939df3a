-- arclen.svgpath -- SVG path data (the `d` attribute, SVG 1.1 section 8.3
-- and SVG 2 section 9.3) to cubic Bezier segments.  The reader is C
-- (src/svg/pathdata.c, bound as arclen.core.svg_pathdata); this module
-- gives it the interface arclen.path expects.
--
-- parse(d, arc_tol [, T]) returns the cubics of all subpaths packed in one
-- string of doubles (x0, y0, x1, y1, x2, y2, x3, y3 each; arclen._cubics
-- makes tables of them) and the subpaths in order:
--   {packed = string, n = cubics,
--    [j] = {x = x0, y = y0, closed = bool, n = its cubics}}  Lines become cubics with the
-- control points at thirds (the same curve, speed constant); quadratics are
-- degree-elevated (C1 = Q0 + 2/3 (Q1 - Q0), C2 = Q2 + 2/3 (Q1 - Q2): the same
-- curve); elliptical arcs go through the conversion of arclen.svg_arc
-- (Floater's mid-point scheme) at a Hausdorff distance of at most arc_tol *
-- max(rx, ry, chord/2).  T ({a, b, c, d, e, f} as SVG's matrix(a b c d e
-- f), optional) maps every point; an arc then keeps its tolerance relative
-- to the size of its image.  Errors are raised as {pos = byte position,
-- msg = text} tables (pos nil for the transform's overflow); the caller
-- turns them into "bad argument" messages.
local svg_pathdata = require("arclen.engine").svg_pathdata

local M = {}

function M.parse(d, arc_tol, T)
  local subpaths, msg, pos = svg_pathdata(d, arc_tol, T)
  if subpaths == nil then error({pos = pos, msg = msg}, 0) end
  return subpaths
end

return M
