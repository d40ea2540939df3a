-- The default method ("gauss") against the 40-digit references of
-- tools/ref_lengths.py.  The bounds are the method's guarantee: relative
-- error <= rtol at rtol = 1e-12, <= 1e-14 at "full precision" rtol = 1e-15.
local arclen = require("arclen")
local H = require("helpers")

-- Bound of the relative error for a requested tolerance.
local function bound(tol) return tol < 1e-14 and 1e-14 or tol end

-- 3D curves need the C core (the Lua engine measures plane cubics).
local function it_for(file)
  return file:find("3d") and H.c_only(it, "3D curves") or it
end

local function check_lengths(file)
  local rows = H.tsv(file)
  local it = it_for(file)
  for _, family in ipairs(H.families(rows)) do
    for _, tol in ipairs({1e-12, 1e-15}) do
      it(family .. ": length at t = 1/4, 1/2, 3/4, 1 within " .. bound(tol) .. " (tol " .. tol .. ")", function()
        local worst = H.worst_lengths(rows, family, function(c, t1)
          return arclen.length(c, {tol = tol, t1 = t1})
        end)
        assert.is_true(worst.err <= bound(tol),
          ("worst %s: %.3g > %.3g"):format(tostring(worst.id), worst.err, bound(tol)))
      end)
    end
  end
end

-- |s(t) - s| for the computed t, from the reference parameter T: s is
-- monotone, so |s(t) - s(T)| <= |t - T| * max speed between them, and the
-- speed is a quadratic's norm, bounded on [t, T] by its values at the ends
-- plus the hodograph's curvature term (tiny for |t - T| ~ 1e-12).
local function speed(c, t)
  local d = {arclen.derivative(c, t)}
  local s = 0
  for _, v in ipairs(d) do s = s + v * v end
  return math.sqrt(s)
end

local function check_times(file)
  local rows = H.tsv(file)
  local it = it_for(file)
  local moves = {}               -- families with a curve of positive length
  for _, row in ipairs(rows) do
    if tonumber(row.L) > 0 then moves[row.family] = true end
  end
  for _, family in ipairs(H.families(rows)) do
    for _, tol in ipairs(moves[family] and {1e-12, 1e-15} or {}) do
      it(family .. ": time at L/4, L/2, 3L/4 with |s(t) - s| <= " .. bound(tol) .. " L (tol " .. tol .. ")", function()
        local worst = H.worst()
        for _, row in ipairs(rows) do
          local L = tonumber(row.L)
          if row.family == family and L > 0 then
            local c = H.curve(row)
            for _, p in ipairs({{0.25, "T25"}, {0.5, "T50"}, {0.75, "T75"}}) do
              local T = tonumber(row[p[2]])
              local t = arclen.time(c, p[1] * L, {tol = tol})
              assert.is_true(t >= 0 and t <= 1, row.id)
              local ds = math.abs(t - T) * math.max(speed(c, t), speed(c, T))
              worst:add(ds / L, row.id .. " s=" .. p[1] .. "L")
            end
          end
        end
        assert.is_true(worst.err <= bound(tol),
          ("worst %s: %.3g > %.3g"):format(tostring(worst.id), worst.err, bound(tol)))
      end)
    end
  end
end

-- The a priori bound certifies each result: every piece's rule is chosen so
-- that the bounds sum to at most the truncation budget of the lower estimate
-- of L -- tol less a rounding reserve of 64 eps, or half of tol when that is
-- less -- so info.err <= budget L on every reference curve and sub-range,
-- and the true error stays within it plus that rounding.
local EPS = 2.220446049250313e-16
local function budget(tol) return tol - math.min(tol / 2, 64 * EPS) end
local function check_certificate(file)
  local rows = H.tsv(file)
  local it = it_for(file)
  for _, tol in ipairs({1e-8, 1e-12, 1e-15}) do
    it(file .. ": info.err <= budget L and the error <= info.err + 64 eps L (tol " .. tol .. ")", function()
      local worst_ratio, worst_id = 0, nil
      for _, row in ipairs(rows) do
        local c = H.curve(row)
        for _, p in ipairs({{0.25, "L25"}, {0.5, "L50"}, {0.75, "L75"}, {1, "L"}}) do
          local want = tonumber(row[p[2]])
          local got, info = arclen.length(c, {tol = tol, t1 = p[1], info = true})
          if want > 0 then
            local ratio = info.err / (budget(tol) * want)
            if ratio > worst_ratio then worst_ratio, worst_id = ratio, row.id .. " t1=" .. p[1] end
            assert.is_true(math.abs(got - want) <= info.err + 64 * EPS * want,
              ("%s t1=%g: error %.3g > err %.3g"):format(row.id, p[1], math.abs(got - want), info.err))
          end
        end
      end
      assert.is_true(worst_ratio <= 1, ("worst %s: info.err is %.3g of the budget"):format(tostring(worst_id), worst_ratio))
    end)
  end
end

describe("the default method's error bound (info.err)", function()
  check_certificate("curves2d.tsv")
  check_certificate("curves3d.tsv")
end)

describe("length (default method) against mpmath, 2D", function()
  check_lengths("curves2d.tsv")
end)

describe("length (default method) against mpmath, 3D", function()
  check_lengths("curves3d.tsv")
end)

describe("time (default method) against mpmath, 2D", function()
  check_times("curves2d.tsv")
end)

describe("time (default method) against mpmath, 3D", function()
  check_times("curves3d.tsv")
end)

describe("time at the ends", function()
  local c = {0, 0, 10, 0, 10, 10, 0, 0}
  local L = arclen.length(c)
  it("s <= 0 gives 0", function()
    assert.are.equal(0, arclen.time(c, 0))
    assert.are.equal(0, arclen.time(c, -5))
    assert.are.equal(0, arclen.time(c, -math.huge))
  end)
  it("s >= L gives 1", function()
    assert.are.equal(1, arclen.time(c, L * (1 + 1e-9)))
    assert.are.equal(1, arclen.time(c, 1e300))
    assert.are.equal(1, arclen.time(c, math.huge))
  end)
  it("a point: 0 below or at 0, 1 above", function()
    local p = {3, 4, 3, 4, 3, 4, 3, 4}
    assert.are.equal(0, arclen.length(p))
    assert.are.equal(0, arclen.time(p, 0))
    assert.are.equal(1, arclen.time(p, 1))
  end)
end)

describe("sub-ranges, splitting and geometry", function()
  local c = {0, 0, 10, 0, 10, 10, 0, 0}
  it("length over [t0, t1] adds up and reverses sign", function()
    local L = arclen.length(c, {tol = 1e-15})
    local a = arclen.length(c, {tol = 1e-15, t1 = 0.3})
    local b = arclen.length(c, {tol = 1e-15, t0 = 0.3})
    assert.is_true(H.relerr(a + b, L) <= 1e-14)
    assert.are.equal(-a, arclen.length(c, {tol = 1e-15, t0 = 0.3, t1 = 0}))
    assert.are.equal(0, arclen.length(c, {t0 = 0.4, t1 = 0.4}))
  end)
  it("split halves measure the range lengths", function()
    local left, right = arclen.split(c, 0.3)
    assert.is_true(H.relerr(arclen.length(left, {tol = 1e-15}),
      arclen.length(c, {tol = 1e-15, t1 = 0.3})) <= 1e-14)
    assert.is_true(H.relerr(arclen.length(right, {tol = 1e-15}),
      arclen.length(c, {tol = 1e-15, t0 = 0.3})) <= 1e-14)
    local x, y = arclen.point(c, 0.3)   -- Bernstein form vs de Casteljau
    assert.is_true(math.abs(x - left[7]) <= 1e-14 * 10 and math.abs(y - left[8]) <= 1e-14 * 10)
    assert.are.same({left[7], left[8]}, {right[1], right[2]})
  end)
  it("subcurve equals the range", function()
    local sub = arclen.subcurve(c, 0.2, 0.7)
    assert.is_true(H.relerr(arclen.length(sub, {tol = 1e-15}),
      arclen.length(c, {tol = 1e-15, t0 = 0.2, t1 = 0.7})) <= 1e-14)
  end)
  it("point and derivative at the ends are the control data", function()
    assert.are.same({0, 0}, {arclen.point(c, 0)})
    assert.are.same({0, 0}, {arclen.point(c, 1)})
    assert.are.same({30, 0}, {arclen.derivative(c, 0)})
  end)
  it("a table of 4 points and 8 loose numbers are the same curve", function()
    local pts = {{0, 0}, {10, 0}, {10, 10}, {0, 0}}
    assert.are.equal(arclen.length(c), arclen.length(pts))
    assert.are.equal(arclen.length(c), arclen.length(0, 0, 10, 0, 10, 10, 0, 0))
    assert.are.equal(arclen.time(c, 3), arclen.time(0, 0, 10, 0, 10, 10, 0, 0, 3))
  end)
  local it3 = H.c_only(it, "3D curves")
  it3("3D curves: 12 numbers or 4 points {x, y, z}", function()
    local c3 = {0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 0, 0}
    assert.is_true(H.relerr(arclen.length(c3), arclen.length(c)) <= 1e-12)
    assert.are.equal(arclen.length(c3),
      arclen.length({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 0, 0}}))
    assert.are.equal(arclen.length(c3), arclen.length(0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 0, 0))
  end)
  it3("3D stops with components of very different sizes (found by fuzz_length)", function()
    -- x runs 0 -> -1 and back to 0 (a stop at t = 1/2 in x), z lifts it by
    -- 1e-154 or 1e-80: the length is 1.5 (and 0.87 up to t = 0.7) to within
    -- the size of the lift
    assert.is_true(H.relerr(arclen.length({0, 0, 0, -1, 0, 0, -1, 0, 0, 0, 1e-154, 0}, {tol = 1e-15}), 1.5) <= 1e-14)
    assert.is_true(H.relerr(arclen.length({0, 0, 0, -1, 0, 0, -1, 0, 0, 0, 1e-80, 0}, {t1 = 0.7}), 0.87) <= 1e-12)
  end)
  it3("degenerate hodographs stay cheap (found by comparing the fuzz harnesses' speed)", function()
    -- a 3D line whose cubic term is 1e-235 of the others: |a2|^2 underflowed
    -- beside 2 a2.a1 and made the bound NaN (10^5 cuts, 4.8 million points);
    -- the curve is a uniformly run line, so the length of [0, t1] is t1 |P3 - P0|
    local line = {-1.3788107506440077e-235, -1, -2, -3, -4, -5, -6, -7, -8, -9, -10, -11}
    local L, info = arclen.length(line, {t1 = 0.185794, tol = 1e-9, info = true})
    assert.is_true(H.relerr(L, 0.185794 * 9 * math.sqrt(3)) <= 1e-9)
    assert.is_true(info.evals <= 1000, "evaluations: " .. info.evals)
    -- a cusp 1e-319 from t = 0 leaves a piece of subnormal width, where the
    -- branch-cut bound overflowed (20000 cuts); elliptic is the reference
    local cusp = {0, 0, 0, 1.6465078552955172e-317, -9, -82, 3, 0}
    local L2, i2 = arclen.length(cusp, {tol = 1e-14, info = true})
    local exact = arclen.length(cusp, {method = "elliptic"})
    assert.is_true(H.relerr(L2, exact) <= 1e-14 + 1e-13)
    assert.is_true(i2.evals <= 1000, "evaluations: " .. i2.evals)
    local t, ti = arclen.time(cusp, L2 / 3, {tol = 1e-12, info = true})
    assert.is_true(math.abs(arclen.length(cusp, {t1 = t, tol = 1e-15}) - L2 / 3) <= 1e-12 * L2)
    assert.is_true(ti.evals <= 2000, "evaluations: " .. ti.evals)
  end)
  H.c_only(it, "arclen.critical")("critical points are the speed's extrema", function()
    local cr = arclen.critical({0, 0, 10, 10, 0, 10, 10, 0})
    assert.are.equal(1, #cr)
    assert.is_true(math.abs(cr[1] - 0.5) < 1e-15)
  end)
  it("info reports the cost and an error estimate within the tolerance", function()
    local L, info = arclen.length(c, {info = true})
    assert.is_true(info.evals > 0 and info.pieces > 0)
    assert.is_true(info.err >= 0 and info.err <= 1e-12 * L)
  end)
  it("_VERSION and the method list", function()
    assert.matches("^arclen %d+%.%d+%.%d+$", arclen._VERSION)
    local names = {}
    for _, m in ipairs(arclen.methods()) do names[m] = true end
    assert.is_true(names.gauss)
  end)
end)

describe("the method registry from Lua", function()
  it("says whether a method has a time, and nil for an unknown name", function()
    assert.are.same({name = "gauss", time = true}, arclen.method("gauss"))
    assert.are.same({name = "metapost", time = true}, arclen.method("metapost"))
    assert.are.same({name = "elliptic", time = false}, arclen.method("elliptic"))
    assert.is_nil(arclen.method("no such method"))
    for _, m in ipairs(arclen.methods()) do assert.are.equal(m, arclen.method(m).name) end
    assert.has_error(function() arclen.method() end,
      "bad argument #1 to 'method' (string expected, got no value)")
  end)
  it("names the tolerance limits that every function checks", function()
    assert.are.equal(1e-15, arclen.tol_min)
    assert.are.equal(0.1, arclen.tol_max)
    assert.has_no.errors(function() arclen.length({0, 0, 1, 0, 2, 1, 3, 0}, {tol = arclen.tol_min}) end)
    assert.has_error(function() arclen.length({0, 0, 1, 0, 2, 1, 3, 0}, {tol = arclen.tol_max * 2}) end)
  end)
end)
