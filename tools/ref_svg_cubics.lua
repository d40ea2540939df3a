-- tools/ref_svg_cubics.lua -- the SVG readers' all-cubic results, recorded
-- (spec/data/svg_cubics.tsv) so that `arcs = "cubics"` can be checked bit
-- for bit against the readers as they were before they kept the segment
-- kinds (recorded on 2026-12-03 from the reader of that day, which had no
-- arcs option and made cubics of everything).  Recorded again on
-- 2026-12-04, when an arc's control points came to be written from their
-- pieces' ends and their half angles from the sweep (src/conic/conic_arc.c):
-- 135 of the 382 rows moved, each number by at most 1.9 ulps of its path's
-- size.  The 14 "arc-huge" rows, an error until then (half the chord's
-- square overflowed), are cubics since.
--
--   lua5.4 tools/ref_svg_cubics.lua > spec/data/svg_cubics.tsv
-- with LUA_PATH='lua/?.lua;lua/?/init.lua;;' LUA_CPATH='build/5.4/?.so;;'.
-- Run today it must print the same file (it asks for arcs = "cubics").
--
-- Columns: id, src ("d": path data; "doc": an SVG document, one row per
-- drawn element), arc_tol, T (path data: six numbers or "-"), input (the
-- path data, or the document on one line), elem (the element's index and
-- tag; "-" for path data), subpaths (x y closed n per subpath, ";"
-- between), packed (every double of the cubics, %.17g, space separated).
local core = require("arclen.core")
local svgdoc = require("arclen.svgdoc")

local function num(x) return ("%.17g"):format(x) end

local function unpack_doubles(s)
  local out = {}
  for i = 1, #s, 8 do out[#out + 1] = num((string.unpack("=d", s, i))) end
  return table.concat(out, " ")
end

local function subpaths_text(R)
  local parts = {}
  for j = 1, #R do
    local s = R[j]
    parts[j] = ("%s %s %d %d"):format(num(s.x), num(s.y), s.closed and 1 or 0, s.n)
  end
  return #parts > 0 and table.concat(parts, ";") or "-"
end

local PATHS = {
  -- every command, absolute and relative, repeats, S/T reflections, Z
  {"lines", "M1 2 L4 6 H10 V0 h-3 v2 l-1 -1 Z"},
  {"rel", "m1 2 l3 4 h6 v-6 c1 1 2 1 3 0 q1 3 2 0 z"},
  {"cubics", "M0 0 C1 2 3 2 4 0 S7 -2 8 0 s1 1 2 0 c1 1 2 1 3 0"},
  {"quads", "M0 0 Q2 3 4 0 T8 0 t2 0 q1 3 2 0 Q1 1 0 0"},
  {"reflect-after-line", "M0 0 L4 0 S7 -2 8 0 L9 9 T10 0"},
  {"repeat", "M0 0 1 0 1 1 m1 1 2 0 0 2 C1 1 2 1 3 0 4 -1 5 -1 6 0"},
  {"after-z", "M0 0 L1 0 Z L0 5 z m3 3 l1 1 Z"},
  {"thirds", "M0.1 0.2 L0.7 1.3 L-3.3 1e-7 Q0.3 0.1 1e3 -2.5"},
  {"big", "M1e300 -1e300 L-1e300 1e300 Q1e300 1e300 0 0"},
  {"tiny", "M1e-310 0 L0 1e-310 Q2e-310 2e-310 0 0"},
  -- arcs: flags, rotations, radii scaled up, degenerate cases
  {"arc-half", "M10 0 A10 10 0 1 1 -10 0"},
  {"arc-flags00", "M0 0 A5 3 30 0 0 4 4"},
  {"arc-flags01", "M0 0 A5 3 30 0 1 4 4"},
  {"arc-flags10", "M0 0 A5 3 30 1 0 4 4"},
  {"arc-flags11", "M0 0 A5 3 30 1 1 4 4"},
  {"arc-rel", "M1 1 a5,5 0 01 10,0 a2 7 -45 1 0 -3 -3"},
  {"arc-small-radii", "M0 0 A1 1 0 0 1 10 0 A0.5 2 60 1 1 0 7"},
  {"arc-zero-radius", "M0 0 A0 5 0 0 1 3 3 A5 0 0 0 1 6 0"},
  {"arc-same-ends", "M1 1 A5 5 0 0 1 1 1 L2 2"},
  {"arc-near-full", "M10 0 A10 10 0 1 1 10 -0.001"},
  {"arc-rot-big", "M3 4 A7 2 400 1 0 -6 2 A3 3 -720 0 1 0 0"},
  {"arc-quarters", "M20 10 A10 5 0 0 1 10 15 A10 5 0 0 1 0 10 A10 5 0 0 1 10 5 A10 5 0 0 1 20 10 Z"},
  {"arc-subnormal", "M0 0 A1 1 0 0 1 1e-320 0"},
  {"arc-huge", "M-1e307 0 A1e307 1e307 0 0 1 1e307 0"},
}
-- arc_tol 1e-12 (many cubics per arc) under two transforms only
local TOLS = {1e-3, 1e-6, 1e-12}
local function wanted(tol, ti) return tol > 1e-12 or ti <= 2 end
local TRANSFORMS = {
  false,
  {2, 0, 0, 3, 5, -7},
  {0.6, 0.8, -0.8, 0.6, 1, 2},
  {1, 0, 0.5, 1, 0, 0},
  {1e-3, 2e-4, -3e-4, 5e-3, 0, 0},
  {-1, 0, 0, 1, 0, 0},
}

local function tsv_row(fields) print(table.concat(fields, "\t")) end

tsv_row({"id", "src", "arc_tol", "T", "input", "elem", "subpaths", "packed"})
for _, p in ipairs(PATHS) do
  for _, tol in ipairs(TOLS) do
    for ti, T in ipairs(TRANSFORMS) do if wanted(tol, ti) then
      local R, msg = core.svg_pathdata(p[2], tol, T or nil, "cubics")
      local id = ("%s/%g/T%d"):format(p[1], tol, ti)
      local Ttext = T and table.concat(T, " ") or "-"
      if R then
        tsv_row({id, "d", num(tol), Ttext, p[2], "-", subpaths_text(R),
          R.n > 0 and unpack_doubles(R.packed) or "-"})
      else
        tsv_row({id, "d", num(tol), Ttext, p[2], "-", "error", msg})
      end
    end end
  end
end

local DOCS = {
  {"rect", [[<svg xmlns="http://www.w3.org/2000/svg"><rect x="1" y="2" width="30" height="20"/><rect x="0.1" y="0.2" width="0.3" height="0.7" rx="0.05"/><rect x="-5" y="-5" width="10" height="4" rx="3" ry="1"/><rect width="10" height="10" ry="20"/><rect width="8" height="6" rx="auto" ry="2"/><rect width="0" height="5"/></svg>]]},
  {"round", [[<svg xmlns="http://www.w3.org/2000/svg"><circle cx="3" cy="4" r="10"/><circle r="1"/><circle cx="0.1" cy="-0.7" r="0.2"/><ellipse cx="5" cy="6" rx="7" ry="2"/><ellipse rx="3"/><ellipse cx="1e6" cy="1e-6" rx="1e-6" ry="1e6"/><circle r="0"/></svg>]]},
  {"lines", [[<svg xmlns="http://www.w3.org/2000/svg"><line x1="1" y1="2" x2="7" y2="-3"/><polyline points="0,0 1,1 2,0 3,1"/><polygon points="0 0 4 0 4 3"/><polyline points="5 5"/><line/></svg>]]},
  {"transformed", [[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 50" width="200mm" height="100mm"><g transform="rotate(30) scale(2 0.5)"><circle cx="10" cy="10" r="5"/><rect x="1" y="1" width="10" height="8" rx="2"/><path d="M0 0 A5 5 0 0 1 10 0 Q12 4 8 8 L0 0"/></g><g transform="skewX(20) translate(3 4)"><ellipse cx="2" cy="3" rx="4" ry="1"/><polygon points="0 0 1 0 0 1"/></g></svg>]]},
  {"use", [[<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"><defs><circle id="c" r="2"/></defs><use xlink:href="#c" x="5" y="5"/><use href="#c" transform="scale(3)"/></svg>]]},
}

for _, doc in ipairs(DOCS) do
  for _, tol in ipairs({1e-3, 1e-6}) do
    local r = svgdoc.new({arc_tol = tol, max_depth = 1000, uses = true, arcs = "cubics"})
    r:feed(doc[2])
    local res = r:finish("fixture")
    for k, e in ipairs(res.elements) do
      local R = e.subpaths
      tsv_row({("%s/%g"):format(doc[1], tol), "doc", num(tol), "-", doc[2],
        ("%d %s"):format(k, e.tag), subpaths_text(R),
        R.n > 0 and unpack_doubles(R.packed) or "-"})
    end
  end
end
