-- spec/overflow_spec.lua -- lengths beyond the doubles, on both engines
-- alike: a path whose length overflows (p:length() is inf) refuses every
-- query by distance under the name of the method called; a line's or
-- quadratic's length and time, and a conic's length, are nil, "arithmetic
-- overflow" where the length overflows, and a conic's time there is the
-- time of the same conic scaled down; the Lua engine refuses a conic
-- weight from 2^510 when the path is built.
local arclen = require("arclen")
local H = require("helpers")

local OVERFLOW = "arithmetic overflow"

-- f's error message without the position a Lua error carries.
local function error_of(f, ...)
  local msg = H.error_of(f, ...)
  assert.is_string(msg, "no error")
  return (msg:gsub("^[^\n]-:%d+: ", ""))
end

describe("a path whose length overflows", function()
  local paths = {
    one = function() return arclen.path({{"line", -1e308, 0, 1e308, 0}}) end,
    -- each segment's length is a double, their sum is not
    sum = function() return arclen.path({{"line", 0, 0, 1e308, 0}, {"line", 1e308, 0, 0, 0}}) end,
    svg = function() return arclen.path.svg("M-1e308 0 L1e308 0") end,
    cubic = function() return arclen.path({{-1e308, 0, 0, 0, 0, 0, 1e308, 0}}) end,
  }
  local queries = {
    time = function(p) return p:time(1) end,
    point = function(p) return p:point(1) end,
    tangent = function(p) return p:tangent(1) end,
    sub = function(p) return p:sub(0, 1) end,
    split = function(p) return p:split(1) end,
    resample = function(p) return p:resample(3) end,
    points = function(p) return p:points({1, 2}) end,
    samples = function(p) return p:samples({1, 2}) end,
    dash = function(p) return p:dash({1e307, 1e307}) end,
  }
  for name, make in pairs(paths) do
    it(name .. ": length inf, every query by distance an error naming the method", function()
      local p = make()
      assert.are.equal(math.huge, p:length())
      for q, f in pairs(queries) do
        assert.are.equal(("'%s': arithmetic overflow (the path's length is beyond the doubles)")
          :format(q), error_of(f, p), name .. " " .. q)
      end
      assert.are.equal("'resample': arithmetic overflow (the path's length is beyond the doubles)",
        error_of(p.resample, p, {step = 1e300}))
      assert.are.equal(math.huge, p:length())   -- and the length stays what it was
    end)
  end

  it("before its length is known, and after", function()
    local p = paths.sum()
    assert.are.equal("'point': arithmetic overflow (the path's length is beyond the doubles)",
      error_of(p.point, p, 1))
    assert.are.equal(math.huge, p:length())
    assert.are.equal("'time': arithmetic overflow (the path's length is beyond the doubles)",
      error_of(p.time, p, 1))
  end)

  it("a path just inside the doubles still answers", function()
    local p = arclen.path({{"line", 0, 0, 8e307, 0}, {"line", 8e307, 0, 16e307, 0}})
    assert.are.equal(16e307, p:length())
    assert.are.equal(1.5, p:time(12e307))
    assert.are.same({12e307, 0}, {p:point(12e307)})
  end)
end)

describe("segments whose length overflows", function()
  local function same(want, ...)
    assert.are.same(want, table.pack(...))
  end
  local plain = {
    {"line", {-1e308, 0, 1e308, 0}},
    {"line", {-1e308, 0, 0, 1e308, 1e308, 0}},                     -- 3D
    {"quad", {-1e308, 0, 0, 1e308, 1e308, 0}},
    {"quad", {-1e308, 0, 0, 0, 1e308, 0}},                           -- collinear
    {"quad", {-1e308, 0, 0, 0, 1e308, 0, 1e308, 0, 0}},              -- 3D
  }
  for _, case in ipairs(plain) do
    local kind, seg = case[1], case[2]
    it(kind .. " " .. table.concat(seg, ",") .. ": length and time nil, 'arithmetic overflow'", function()
      same({nil, OVERFLOW, n = 2}, arclen.segment_length(kind, seg))
      same({nil, OVERFLOW, n = 2}, arclen.segment_length(kind, seg, {info = true}))
      for _, s in ipairs({-1, 0, 1, 1e308, math.huge}) do
        same({nil, OVERFLOW, n = 2}, arclen.segment_time(kind, seg, s))
      end
      same({nil, OVERFLOW, n = 2}, arclen.segment_time(kind, seg, 1e308, {info = true}))
    end)
  end

  it("a part of one is measured when it is a double", function()
    assert.are.equal(5e307, arclen.segment_length("line", {-1e308, 0, 1e308, 0}, {t0 = 0.25, t1 = 0.5}))
    assert.are.equal(-5e307, arclen.segment_length("line", {-1e308, 0, 1e308, 0}, {t0 = 0.5, t1 = 0.25}))
    -- half of P1 - P0 is (1.7e308, 1.7e308), whose norm is beyond the
    -- doubles: a quarter of the diagonal 3.4e308 sqrt 2 is 1.2e308
    local d = arclen.segment_length("line", {-1.7e308, -1.7e308, 1.7e308, 1.7e308}, {t0 = 0.25, t1 = 0.5})
    assert.is_true(math.abs(d - 0.85e308 * math.sqrt(2)) <= 2 * 2 ^ -52 * d, d)
    -- 2e308 / 4: the middle quarter of a straight quadratic, t uniform
    local q = arclen.segment_length("quad", {-1e308, 0, 0, 0, 1e308, 0}, {t0 = 0.25, t1 = 0.5})
    assert.is_true(math.abs(q - 5e307) <= 1e-14 * 5e307, q)
  end)

  it("a quadratic whose legs overflow and whose length does not", function()
    -- out to (1e308, 1e308) / 2 and back: 2 sqrt(2) 1e308 / 2
    local seg, want = {0, 0, 1e308, 1e308, 0, 0}, math.sqrt(2) * 1e308
    local L = arclen.segment_length("quad", seg)
    assert.is_true(math.abs(L - want) <= 1e-14 * want, L)
    -- the turning point at half the length (a cusp: t within tol L there)
    local t = arclen.segment_time("quad", seg, want / 2)
    assert.is_true(math.abs(arclen.segment_length("quad", seg, {t1 = t}) - L / 2) <= 1e-12 * L, t)
    -- halved (exact), the same quadratic in smaller numbers
    local half = arclen.segment_length("quad", {0, 0, 0.5e308, 0.5e308, 0, 0})
    assert.are.equal(half * 2, L)
  end)

  -- A conic's time at s is that of the conic scaled by 2^-1024 at s 2^-1024
  -- (a power of two: every rounding the same, in both engines), which
  -- holds |length(0..t) - s| <= tol L, at every tol (the C core searches
  -- in the scaled conic's units, with or without its cover).
  local conics = {
    {-1e308, 0, 0, 1e308, 1e308, 0, 0.5},
    {-1e308, 0, 0, 0, 1e308, 0, 0.5},                                -- collinear
    {-1e308, 0, 0, 0, 1e308, 0, 2},
    {1.5e308, 0, 1.5e308, 1.5e308, 0, 1.5e308, math.sqrt(0.5)},      -- a quarter circle
    {1.5e308, 0, 1.5e308, 1.5e308, 0, 1.5e308, 1e3},   -- (w far above: Known limitations)
    {1.5e308, 0, 1.5e308, 1.5e308, 0, 1.5e308, 1e-10},
    {-1e308, 0, 0, 0, 1e308, 0, 1e308, 0, 0, 0.7},                   -- 3D
  }
  for _, seg in ipairs(conics) do
    it("conic " .. table.concat(seg, ",") .. ": length nil, the time that of the conic scaled down", function()
      same({nil, OVERFLOW, n = 2}, arclen.segment_length("conic", seg))
      same({nil, OVERFLOW, n = 2}, arclen.segment_length("conic", seg, {info = true}))
      local f, small = 2 ^ -1024, {}
      for i = 1, #seg - 1 do small[i] = seg[i] * f end
      small[#seg] = seg[#seg]
      local L = arclen.segment_length("conic", small)
      assert.is_true(L > 1.7976931348623157e308 * f, L)      -- the length overflows
      for _, tol in ipairs({1e-15, 1e-12, 1e-3}) do
        for _, q in ipairs({0.1, 0.5, 1.0, 1.7}) do
          local s = q * 1e308
          local t = arclen.segment_time("conic", seg, s, {tol = tol})
          assert.are.equal(arclen.segment_time("conic", small, s * f, {tol = tol}), t,
            ("tol %g s %g"):format(tol, s))
          if tol == 1e-12 then
            local miss = math.abs(arclen.segment_length("conic", small, {t1 = t}) - s * f)
            assert(miss <= tol * L, ("s %g: t %.17g misses by %.3g L"):format(s, t, miss / L))
          end
        end
        assert.are.equal(0, arclen.segment_time("conic", seg, 0, {tol = tol}))
        assert.are.equal(1, arclen.segment_time("conic", seg, math.huge, {tol = tol}))
      end
      local t, info = arclen.segment_time("conic", seg, 1e308, {info = true})
      assert.is_number(t)
      assert.is_table(info)
    end)
  end
end)

-- The engines against each other, where both load.
local has_core, core = pcall(require, "arclen.core")
if has_core and type(core) == "table" and core.segment_length then
  local pure = require("arclen.pure")
  describe("segments whose length overflows: the Lua engine against the C core", function()
    it("the same results, kind by kind", function()
      local cases = {
        {"line", {-1e308, 0, 1e308, 0}}, {"line", {0, 0, 1e308, 1e308}},
        {"quad", {-1e308, 0, 0, 1e308, 1e308, 0}}, {"quad", {0, 0, 1e308, 1e308, 0, 0}},
        {"conic", {-1e308, 0, 0, 1e308, 1e308, 0, 0.5}},
        {"conic", {1.5e308, 0, 1.5e308, 1.5e308, 0, 1.5e308, math.sqrt(0.5)}},
      }
      for _, case in ipairs(cases) do
        local kind, seg, id = case[1], case[2], case[1] .. " " .. table.concat(case[2], ",")
        local c, l = table.pack(core.segment_length(kind, seg)), table.pack(pure.segment_length(kind, seg))
        assert.are.equal(c.n, l.n, id)
        assert.are.equal(c[2], l[2], id)
        if c[1] then assert.is_true(math.abs(c[1] - l[1]) <= 1e-14 * c[1], id) end
        for _, s in ipairs({0, 1e307, 1e308}) do
          c, l = table.pack(core.segment_time(kind, seg, s)), table.pack(pure.segment_time(kind, seg, s))
          assert.are.equal(c.n, l.n, id .. " at " .. s)
          assert.are.equal(c[2], l[2], id .. " at " .. s)
          assert.are.equal(type(c[1]), type(l[1]), id .. " at " .. s)
        end
      end
    end)
  end)
end

describe("a conic weight from 2^510 on the Lua engine", function()
  local W = 2 ^ 510
  local MSG = "bad argument #1 to 'arclen.path' (segment 1 (conic): the weight w must be below "
    .. "2^510 on the Lua engine)"
  if H.engine == "c" then
    it("the C core takes it (every finite w > 0)", function()
      local p = arclen.path({{"conic", 0, 0, 1, 1, 2, 0, W}})
      assert.is_true(math.abs(p:length() - 2 * math.sqrt(2)) <= 1e-14)
      assert.is_number(arclen.segment_length("conic", {0, 0, 1, 1, 2, 0, W}))
    end)
  else
    it("is refused when the path is built, naming the argument", function()
      assert.are.equal(MSG, error_of(arclen.path, {{"conic", 0, 0, 1, 1, 2, 0, W}}))
      assert.are.equal(MSG, error_of(arclen.path, {{kind = "conic", {0, 0}, {1, 1}, {2, 0}, w = W}}))
      assert.are.equal(MSG, error_of(arclen.path, {{"conic", 0, 0, 0, 1, 1, 1, 2, 0, 0, 2 ^ 600}}))
      local p = arclen.path({{"conic", 0, 0, 1, 1, 2, 0, W / 2}})    -- below: measured
      assert.is_true(math.abs(p:length() - 2 * math.sqrt(2)) <= 1e-12)
    end)
    it("and by the segment functions", function()
      for _, f in ipairs({"segment_length", "segment_point", "segment_derivative"}) do
        local args = {"conic", {0, 0, 1, 1, 2, 0, W}}
        if f ~= "segment_length" then args[3] = 0.5 end
        assert.are.equal(("bad argument #2 to '%s' (conic weight (number 7) must be below 2^510 "
          .. "on the Lua engine)"):format(f), error_of(arclen[f], table.unpack(args)))
      end
      assert.are.equal("bad argument #2 to 'segment_time' (conic weight (number 7) must be below "
        .. "2^510 on the Lua engine)", error_of(arclen.segment_time, "conic", {0, 0, 1, 1, 2, 0, W}, 1))
    end)
  end
end)
