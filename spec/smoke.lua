-- spec/smoke.lua BUILD_DIR -- load arclen built for this interpreter and
-- check a few exact values (Henkel's closed forms); for Lua versions and
-- LuaTeX's texlua where busted is not run.  Prints "N passed, N failed".
local dir = assert(arg and arg[1], "usage: lua spec/smoke.lua build/5.x")
package.cpath = dir .. "/?.so;" .. dir .. "/?.dll;" .. package.cpath
package.path = "lua/?.lua;lua/?/init.lua;" .. package.path

local passed, failed = 0, 0
local function check(name, ok, msg)
  if ok then
    passed = passed + 1
  else
    failed = failed + 1
    print("FAIL " .. name .. (msg and (": " .. tostring(msg)) or ""))
  end
end
local function close(a, b, tol) return math.abs(a - b) <= tol * math.abs(b) end

local ok, arclen = pcall(require, "arclen")
check("require 'arclen' under " .. _VERSION, ok, arclen)
if ok then
  check("_VERSION", type(arclen._VERSION) == "string")
  -- Henkel's curve 2 (a cusp): 20 sqrt 2 - 10; curve 5 (two cusps).
  check("cusp length", close(arclen.length({0, 0, 10, 10, 0, 10, 10, 0}, {tol = 1e-15}),
    20 * math.sqrt(2) - 10, 1e-14))
  check("two cusps length", close(arclen.length({{0, 0}, {20, 20}, {-10, -10}, {10, 10}}),
    10 * math.sqrt(2) + 4 * math.sqrt(10), 1e-12))
  check("loose numbers", arclen.length(0, 0, 1, 1, 9, 9, 10, 10) ==
    arclen.length({0, 0, 1, 1, 9, 9, 10, 10}))
  local c = {0, 0, 10, 0, 10, 10, 0, 0}
  local t = arclen.time(c, arclen.length(c) / 2)
  check("time inverts length", close(arclen.length(c, {t1 = t}), arclen.length(c) / 2, 1e-12))
  local ok2, msg = pcall(arclen.length, {1, 2, 3})
  check("bad curve raises", not ok2 and tostring(msg):find("bad argument #1", 1, true), msg)
  local ok3, msg3 = pcall(arclen.length, c, {tol = 0})
  check("bad tolerance raises", not ok3 and tostring(msg3):find("tol", 1, true), msg3)
end
print(("%d passed, %d failed"):format(passed, failed))
