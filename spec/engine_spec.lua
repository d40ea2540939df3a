-- spec/engine_spec.lua -- the choice of engine (lua/arclen/engine.lua) and
-- the Lua engine's interface (lua/arclen/pure.lua): the same names as the
-- C core, the same argument checks, and an error naming the C core for
-- what only the C core has.  Runs on both engines.
local arclen = require("arclen")
local pure = require("arclen.pure")
local H = require("helpers")

local has_core, core = pcall(require, "arclen.core")
if not has_core then core = nil end

-- The module loaded afresh with package.loaded[name] = value set first
-- (and everything arclen* forgotten, then restored).
local function fresh_arclen(setup)
  local saved = {}
  for name, mod in pairs(package.loaded) do
    if name == "arclen" or name:sub(1, 7) == "arclen." then saved[name] = mod end
  end
  for name in pairs(saved) do package.loaded[name] = nil end
  setup()
  local ok, res = pcall(require, "arclen")
  for name in pairs(package.loaded) do
    if name == "arclen" or name:sub(1, 7) == "arclen." then package.loaded[name] = nil end
  end
  for name, mod in pairs(saved) do package.loaded[name] = mod end
  assert(ok, res)
  return res
end

describe("the choice of engine", function()
  it("reports arclen.engine: 'lua' under ARCLEN_ENGINE=lua, else the C core where it loads", function()
    local want = os.getenv("ARCLEN_ENGINE") == "lua" and "lua" or (has_core and "c" or "lua")
    assert.are.equal(want, arclen.engine)
    assert.are.equal(want, H.engine)
  end)

  it("takes the Lua engine when package.loaded['arclen.core'] is false", function()
    local m = fresh_arclen(function() package.loaded["arclen.core"] = false end)
    assert.are.equal("lua", m.engine)
    assert.is_true(m.path({{0, 0, 1, 0, 2, 0, 3, 0}}):length() == 3)
  end)

  it("the path layer measures with the chosen engine", function()
    local engine = require("arclen.engine")
    assert.are.equal(arclen.length, engine.length)
    local calls, real = 0, engine.length
    engine.length = function(...) calls = calls + 1; return real(...) end
    local ok, err = pcall(function() arclen.path({{0, 0, 1, 0, 2, 1, 3, 0}}):length() end)
    engine.length = real
    assert(ok, err)
    assert.are.equal(1, calls)
  end)
end)

describe("the Lua engine's interface", function()
  it("has every name of the C core: the same function, or one that names the C core", function()
    if not core then return end    -- nothing to compare with: checked where the C core loads
    for name, v in pairs(core) do
      assert.is_not_nil(pure[name], "arclen.pure lacks " .. name)
      assert.are.equal(type(v), type(pure[name]), name)
      if type(v) == "table" then
        for k in pairs(v) do assert.is_not_nil(pure[name][k], name .. "." .. k) end
      end
    end
    assert.are.equal(core._VERSION, pure._VERSION)
    assert.are.equal(core.tol_min, pure.tol_min)
    assert.are.equal(core.tol_max, pure.tol_max)
  end)

  it("raises an error naming the C core for 3D, other methods, arcs and the C-only functions", function()
    local c = {0, 0, 10, 0, 10, 10, 0, 0}
    local E = H.error_of
    assert.matches("#1 to 'length' %(a 3D curve needs the C core", E(pure.length, {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}))
    assert.matches("#1 to 'time' %(a 3D curve needs the C core", E(pure.time, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 1))
    assert.matches("#1 to 'point' %(a 3D curve needs", E(pure.point, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}, 0.5))
    assert.matches("#2 to 'length' %(method 'elliptic' needs the C core", E(pure.length, c, {method = "elliptic"}))
    assert.matches("#3 to 'time' %(method 'metapost' needs the C core", E(pure.time, c, 1, {method = "metapost"}))
    assert.matches("lualatex %-%-shell%-escape", E(pure.length, c, {method = "trapezoid"}))
    assert.matches("unknown method 'nope'", E(pure.length, c, {method = "nope"}))
    assert.matches("arclen.metapost.path_arctime needs the C core", E(pure.metapost.path_arctime, {c}, 1))
    assert.matches("arclen.svg_arc needs the C core", E(pure.svg_arc))
    assert.matches("arclen.lengths3 needs the C core", E(pure.lengths3, {}))
    local _, msg = pure.svg_pathdata("M0 0 A 5 5 0 0 1 10 0", 1e-12, nil, "cubics")
    assert.matches("arcs need the C core", msg)
    -- a path names it when it measures
    assert.matches("needs the C core", E(pure.length, c, {method = "metapost"}))
    assert.matches("needs the C core", E(function()
      return arclen.path({c}, {method = "elliptic"}):length()
    end) or (arclen.engine == "c" and "needs the C core" or "no error"))
  end)

  it("checks arguments as the C core does, with the same messages", function()
    if not core then return end
    local c = {0, 0, 10, 0, 10, 10, 0, 0}
    local calls = {
      {"length"}, {"length", "x"}, {"length", {1, 2, 3}}, {"length", {0, 0, "x", 0, 1, 1, 2, 2}},
      {"length", {0, 0, 1, 0 / 0, 1, 1, 2, 2}}, {"length", {{0, 0}, {1, 1}, {2, 2}}},
      {"length", {{0, 0}, {1, 1}, {2}, {3, 3}}}, {"length", {{0, 0}, {1, 0 / 0}, {2, 2}, {3, 3}}},
      {"length", 0, 0, 0 / 0, 1, 2, 2, 3, 3}, {"length", 0, 0, 1},
      {"length", c, 5}, {"length", c, {tol = 0}}, {"length", c, {tol = "x"}}, {"length", c, {x = 1}},
      {"length", c, {t0 = 2}}, {"length", c, {method = 1}}, {"length", c, {[1] = 2}},
      {"time", c}, {"time", c, 0 / 0}, {"time", c, 1, {t0 = 0.5}}, {"time", c, 1, {tol = 1}},
      {"point", c}, {"point", c, 2}, {"point", c, 0 / 0}, {"derivative", c, -1},
      {"subcurve", c, 0.5}, {"split", c, "x"},
      {"lengths", 3}, {"lengths", {1, 2, 3}}, {"lengths", {0, 0, 1, 1, 2, 2, "x", 3}},
      {"lengths", {0, 0, 1, 1, 2, 2, 3, 1 / 0}}, {"lengths", c, {info = true}},
      {"times", c, {2, 1}}, {"times", c, {1, "x"}}, {"times", c, {0 / 0}}, {"times", c, {1}, {x = 1}},
      {"times", c, {1}, {tol = 2}}, {"_array", -1}, {"method"},
    }
    local unpack = table.unpack or unpack
    for _, call in ipairs(calls) do
      local name, n = call[1], #call
      local okc, mc = pcall(core[name], unpack(call, 2, n))
      local okl, ml = pcall(pure[name], unpack(call, 2, n))
      assert.are.equal(okc, okl, name .. ": one raised, the other not")
      -- the C core's function name comes from the call's debug info ('?'
      -- under pcall): compare the argument and the message
      local function gist(m) return (tostring(m):gsub("^.-bad argument", "bad argument"):gsub("to '[^']*'", "to f")) end
      assert.are.equal(gist(mc), gist(ml), name)
    end
  end)
end)
