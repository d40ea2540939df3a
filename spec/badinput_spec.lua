-- Bad input to the core functions: each gets an error naming the argument
-- (lauxlib's "bad argument #n to 'f' (...)"), never a crash, hang or NaN.
local arclen = require("arclen")
local H = require("helpers")

local good = {0, 0, 10, 0, 10, 10, 0, 0}

local function raises(pattern, f, ...)
  local msg = H.error_of(f, ...)
  assert.is_not_nil(msg, "expected an error matching " .. pattern)
  assert.is_truthy(msg:find(pattern, 1, true), msg .. "  (expected: " .. pattern .. ")")
end

describe("bad curves", function()
  for _, fname in ipairs({"length", "critical"}) do
    local f = arclen[fname]
    local it = fname == "critical" and H.c_only(it, "arclen.critical") or it
    it(fname .. " rejects non-tables, wrong sizes and bad coordinates", function()
      raises("bad argument #1", f, nil)
      raises("bad argument #1", f, "0 0 1 1")
      raises("got 3", f, {1, 2, 3})
      raises("got 0", f, {})
      raises("got 9", f, {1, 2, 3, 4, 5, 6, 7, 8, 9})
      raises("curve coordinate 3 must be a number", f, {0, 0, "x", 0, 1, 1, 2, 2})
      raises("curve coordinate 4 must be finite", f, {0, 0, 1, 0 / 0, 1, 1, 2, 2})
      raises("curve coordinate 8 must be finite", f, {0, 0, 1, 1, 1, 1, 2, math.huge})
      raises("curve coordinate 1 must be finite", f, {-math.huge, 0, 1, 1, 1, 1, 2, 2})
      raises("4 points", f, {{0, 0}, {1, 1}, {2, 2}})
      raises("point 3 must be a table of 2 numbers", f, {{0, 0}, {1, 1}, {2, 2, 2}, {3, 3}})
      raises("coordinate of point 2 must be finite", f, {{0, 0}, {1, 0 / 0}, {2, 2}, {3, 3}})
    end)
  end
  it("loose numbers are checked too", function()
    raises("bad argument #3", arclen.length, 0, 0, 0 / 0, 1, 2, 2, 3, 3)
    raises("bad argument #4", arclen.length, 0, 0, 1)    -- too few: not a curve
  end)
end)

describe("bad options", function()
  it("tolerances outside [1e-15, 0.1] and NaN", function()
    for _, tol in ipairs({0, -1, 1e-16, 0.2, 0 / 0, math.huge}) do
      raises("tol must be in [1e-15, 0.1]", arclen.length, good, {tol = tol})
      raises("tol must be in [1e-15, 0.1]", arclen.time, good, 1, {tol = tol})
    end
    raises("tol must be a number", arclen.length, good, {tol = "1e-9"})
  end)
  it("ranges outside [0, 1]", function()
    raises("t0 must be in", arclen.length, good, {t0 = -0.1})
    raises("t1 must be in", arclen.length, good, {t1 = 1.5})
    raises("t1 must be in", arclen.length, good, {t1 = 0 / 0})
    raises("t0 and t1 do not apply to time", arclen.time, good, 1, {t0 = 0.5})
  end)
  it("unknown methods and options, non-table options", function()
    raises("unknown method 'simpson'", arclen.length, good, {method = "simpson"})
    raises("method must be a string", arclen.length, good, {method = 3})
    raises("unknown option 'tolerance'", arclen.length, good, {tolerance = 1e-9})
    raises("options table expected", arclen.length, good, 1e-9)
    raises("bad argument #2", arclen.length, good, "fast")
  end)
end)

describe("bad lengths and parameters", function()
  it("time needs a number that is not NaN", function()
    raises("bad argument #2", arclen.time, good)
    raises("length must be a number (not NaN)", arclen.time, good, 0 / 0)
    raises("length must be a number (not NaN)", arclen.time, good, "3")
  end)
  it("point, derivative, split and subcurve need t in [0, 1]", function()
    for _, f in ipairs({arclen.point, arclen.derivative, arclen.split}) do
      raises("t must be in [0, 1]", f, good, 1.5)
      raises("t must be in [0, 1]", f, good, -1e-300)
      raises("t must be finite", f, good, 0 / 0)
      raises("t must be a number", f, good, nil)
    end
    raises("bad argument #3", arclen.subcurve, good, 0.5, 2)
  end)
end)

describe("extreme but valid input stays finite", function()
  it("huge, tiny, denormal and far-away coordinates", function()
    local cases = {
      {0, 0, 1e300, 0, 1e300, 1e300, 0, 0},
      {0, 0, 1e-300, 0, 1e-300, 1e-300, 0, 0},
      {0, 0, 5e-324, 0, 5e-324, 5e-324, 0, 1e-323},
      {1e15, 1e15, 1e15 + 1, 1e15, 1e15 + 1, 1e15 + 1, 1e15, 1e15 + 2},
      {-1.7e308, 0, 0, 0, 0, 0, 1.7e308, 0},
    }
    for _, c in ipairs(cases) do
      local L = arclen.length(c, {tol = 1e-15})
      assert.is_true(L == L and L >= 0, "length " .. tostring(L))
      local t = arclen.time(c, L / 3)
      assert.is_true(t >= 0 and t <= 1, "time " .. tostring(t))
    end
  end)
end)

describe("argument errors name the caller's file and line", function()
  -- as luaL_argerror's: the user's call, not a line of lua/arclen/*.lua
  -- (arclen.caller); each call below is not a tail call, so its frame stays
  local function err(f)
    local ok, e = pcall(f)
    assert.is_false(ok)
    return e
  end
  local here = "^[^:]*badinput_spec%.lua:%d+: "
  it("from the path constructor, a method and the SVG reader", function()
    local p = arclen.path({{"line", 0, 0, 1, 1}})
    assert.matches(here .. "bad argument #1 to 'arclen.path'",
      err(function() local q = arclen.path({{"conic", 0, 0, 1, 1, 2, 0, -1}}); return q end))
    assert.matches(here .. "bad argument #1 to 'point'",
      err(function() local x = p:point("x"); return x end))
    assert.matches(here .. "bad argument #1 to 'resample'",
      err(function() local r = p:resample(1.5); return r end))
    assert.matches(here .. "bad argument #1 to 'arclen.path.svg'",
      err(function() local q = arclen.path.svg("M0 0 X"); return q end))
    local ok_svg, svg = pcall(require, "arclen.svg")
    if ok_svg then
      assert.matches(here .. "bad argument #2 to 'arclen.svg.parse' %(unknown option 'bogus'%)",
        err(function() local d = svg.parse("<svg/>", {bogus = 1}); return d end))
    end
  end)
end)
