-- examples/mplib_path.lua -- measure MetaPost paths from LuaTeX's mplib.
--
--   texlua examples/mplib_path.lua [BUILD_DIR]        (default build/5.3)
--   texluajit examples/mplib_path.lua build/jit
--   luatex --shell-escape examples/mplib_path.tex     (the same inside a
--                                                      document: a PDF)
--
-- LuaTeX's Lua has mplib built in.  This script runs MetaPost in double
-- mode (no format file needed: the few plain macros used are defined
-- here), draws paths, takes the knot tables from the shipped-out figure --
-- exactly what a LuaTeX document gets in its mplib callbacks -- and asks
-- arclen for their lengths, MetaPost's own path times, evenly spaced points
-- and dashes.  It checks itself and ends with "N passed, N failed".
-- inside a document (examples/mplib_path.tex), ARCLEN_BUILD names the build
local build = ARCLEN_BUILD or (arg and arg[1]) or "build/5.3"
package.cpath = build .. "/?.so;" .. package.cpath
package.path = "lua/?.lua;lua/?/init.lua;" .. package.path
assert(mplib, "run this with texlua or texluajit (LuaTeX's Lua has mplib)")

-- In a document LuaTeX searches Lua modules with kpathsea only: add a
-- searcher over package.path for arclen's Lua parts (arclen.path, ...).
if ARCLEN_BUILD then
  local searchers = package.searchers or package.loaders
  table.insert(searchers, 2, function(name)
    local file, err = package.searchpath(name, package.path)
    if not file then return err end
    return assert(loadfile(file)), file
  end)
end
-- LuaTeX searches with kpathsea before package.cpath, and could find another
-- arclen first: load the core of this build by its file name.
local open = package.loadlib(build .. "/arclen/core.so", "luaopen_arclen")
if open then package.loaded.arclen = open("arclen") end
local arclen = require("arclen")

-- MetaPost without plain.mp: ini mode, double arithmetic.
local mp = mplib.new({ini_version = true, math_mode = "double",
  find_file = function(name, mode) if mode == "w" then return name end end})
local function run(code)
  local r = mp:execute(code)
  assert(r and r.status <= 1, "mplib: " .. tostring(r and (r.term or r.error)))
  return r
end
run([[
delimiters ();
def -- = {curl 1}..{curl 1} enddef;
picture currentpicture;
]])

-- Draw a path, ship it out, and return its knot table and what MetaPost
-- itself says its arclength is (printed with %.17g in double mode).
local function mplib_path(expr)
  local r = run(("path p; p := %s; currentpicture := nullpicture;"
    .. "addto currentpicture doublepath p; show arclength p; shipout currentpicture;"):format(expr))
  local L = tonumber((r.term or r.log):match(">> ([%-%d%.e+]+)"))
  return r.fig[1]:objects()[1].path, L
end

local passed, failed = 0, 0
local function check(name, ok, detail)
  if ok then passed = passed + 1 else failed = failed + 1 end
  print(("%-4s %s%s"):format(ok and "ok" or "FAIL", name, detail and ("  " .. detail) or ""))
end

-- 1. A wave: open path through five points.
local knots, mpL = mplib_path("(0,0)..(30,20)..(60,0)..(90,20)..(120,0)")
local p = arclen.path.mplib(knots)                          -- default method, tol 1e-12
local pm = arclen.path.mplib(knots, {method = "metapost"})  -- MetaPost's own arithmetic
print(("wave: %d segments, length %.15g (MetaPost says %.17g)"):format(p:segments(), p:length(), mpL))
check("method 'metapost' reproduces mplib's arclength bit for bit", pm:length() == mpL)
-- MetaPost's length carries +2^-17 per segment and an absolute 1/4096 tolerance.
check("the accurate length is within MetaPost's error of it",
  math.abs(p:length() - mpL) <= 4 * 2 ^ -17 + 1 / 4096,
  ("difference %.3g"):format(p:length() - mpL))

-- 2. MetaPost's arctime, from MetaPost and from arclen.
local r = run("show arctime 50 of p;")
local mpT = tonumber((r.term or r.log):match(">> ([%-%d%.e+]+)"))
check("path time at distance 50 equals mplib's arctime", pm:time(50) == mpT,
  ("arclen %.17g, mplib %.17g"):format(pm:time(50), mpT))

-- 3. Eleven points evenly spaced along the wave (text on a path, markers).
print("points every tenth of the length (x, y, direction in degrees):")
for _, q in ipairs(p:resample(11)) do
  print(("  s = %8.3f  (%8.3f, %8.3f)  %7.2f"):format(q.s, q.x, q.y,
    math.deg((math.atan2 or math.atan)(q.ty, q.tx))))
end
local pts = p:resample(11)
check("resample spacing is L/10", math.abs(pts[2].s - p:length() / 10) <= 1e-12 * p:length())

-- 4. A cycle: MetaPost's fullcircle-like path, dashed.
local circle = arclen.path.mplib((mplib_path("(10,0)..(0,10)..(-10,0)..(0,-10)..cycle")))
check("a cycle in the knot table is a cyclic path", circle.cyclic and circle:segments() == 4)
local dashes = circle:dash({5, 3})
print(("circle: length %.12g, %d dashes of 5 with gaps of 3"):format(circle:length(), #dashes))
check("dashes cover 5/8 of the circle",
  math.abs(#dashes * 5 - circle:length() * 5 / 8) <= 5)

-- 5. The dashes as SVG path data (a LuaTeX document would hand them back to
-- MetaPost or to the PDF writer).
print("first dash as SVG path data: " .. dashes[1]:svg():sub(1, 72) .. " ...")

-- 6. Inside a LuaTeX document: typeset what was measured.
if ARCLEN_BUILD and tex and tex.print then
  tex.print(("The wave has %d segments and is %.6f long (MetaPost says %.6f)."):format(
    p:segments(), p:length(), mpL))
  tex.print("\\par Eleven points evenly spaced along it:\\par")
  for _, q in ipairs(pts) do
    tex.print(("$s = %.3f$: $(%.3f, %.3f)$\\par"):format(q.s, q.x, q.y))
  end
  tex.print(("The circle is %.6f long; dashed 5 on, 3 off it has %d dashes.\\par"):format(
    circle:length(), #dashes))
end

print(("%d passed, %d failed"):format(passed, failed))
if failed > 0 then os.exit(1) end
