-- Henkel's fixed-step rows: "polyline" (hypotenuse sum, Eqn 3), "trapezoid"
-- (Eqn 7, the quartic radicand) and "trapezoid-factored" (Eqn 10, the speed
-- |A2| |t - s1| |t - s2| from the complex roots of z'), N = opts.steps
-- (default 10^6 as Henkel), against the 40-digit references.
local arclen = require("arclen")
local H = require("helpers")

local henkel = H.curves("curves2d.tsv", "henkel")

describe("baselines", function()
  it("N = 10^6 on Henkel's six arcs: within 1e-11 (the rules' O(h^2) error), as his rows", function()
    for _, m in ipairs({"polyline", "trapezoid", "trapezoid-factored"}) do
      local worst = H.worst()
      for _, row in ipairs(henkel) do
        local L, info = arclen.length(H.curve(row), {method = m, info = true})
        assert.are.equal(1000000, info.pieces)
        worst:add(H.relerr(L, tonumber(row.L)), row.id)
      end
      assert.is_true(worst.err <= 1e-11, m .. ": " .. worst.err .. " at " .. worst.id)
    end
  end)

  it("the rules converge as N^-2 (error ratio ~4 from N = 1000 to 2000, arc 1)", function()
    local c, L = H.curve(henkel[1]), tonumber(henkel[1].L)
    for _, m in ipairs({"polyline", "trapezoid", "trapezoid-factored"}) do
      local e1 = arclen.length(c, {method = m, steps = 1000}) - L
      local e2 = arclen.length(c, {method = m, steps = 2000}) - L
      local r = e1 / e2
      assert.is_true(r > 3.9 and r < 4.1, m .. ": ratio " .. r)
    end
  end)

  it("the polyline is inscribed: never longer than the curve (every 2D reference curve)", function()
    local worst = -math.huge
    for _, row in ipairs(H.tsv("curves2d.tsv")) do
      local L = tonumber(row.L)
      if L > 0 then
        local p = arclen.length(H.curve(row), {method = "polyline", steps = 200})
        worst = math.max(worst, (p - L) / L)
      end
    end
    assert.is_true(worst <= 1e-14, tostring(worst))
  end)

  it("Eqn 10 with stable complex roots agrees with Eqn 7 (Henkel's root finder lost 7e-9 on arc 3)", function()
    for _, row in ipairs(henkel) do
      local c = H.curve(row)
      local a = arclen.length(c, {method = "trapezoid", steps = 100000})
      local b = arclen.length(c, {method = "trapezoid-factored", steps = 100000})
      assert.is_true(H.relerr(b, a) <= 1e-12, row.id .. ": " .. H.relerr(b, a))
    end
  end)

  it("one step: the chord, and the trapezoid of the end speeds", function()
    local c = {1, 2, 4, 6, 0, 9, 5, 3}
    local p = arclen.length(c, {method = "polyline", steps = 1})
    assert.is_true(math.abs(p - math.sqrt(17)) < 1e-14, tostring(p))   -- |P3 - P0|
    -- |z'(0)| = 3 |P1 - P0| = 15, |z'(1)| = 3 |P3 - P2| = 3 sqrt(61)
    local t = arclen.length(c, {method = "trapezoid", steps = 1})
    assert.is_true(math.abs(t - (15 + 3 * math.sqrt(61)) / 2) < 1e-13)
  end)

  it("3D: polyline and trapezoid measure it, the factored form (complex roots) is 2D only", function()
    local rows = H.curves("curves3d.tsv")
    local row = rows[1]
    local c, L = H.curve(row), tonumber(row.L)
    assert.is_true(H.relerr(arclen.length(c, {method = "polyline"}), L) <= 1e-11)
    assert.is_true(H.relerr(arclen.length(c, {method = "trapezoid"}), L) <= 1e-11)
    assert.matches("does not support this dimension",
                   H.error_of(arclen.length, c, {method = "trapezoid-factored"}))
  end)

  it("ranges: [0, 1/2] and reversed", function()
    local row = henkel[1]
    local c, L50 = H.curve(row), tonumber(row.L50)
    for _, m in ipairs({"polyline", "trapezoid", "trapezoid-factored"}) do
      assert.is_true(H.relerr(arclen.length(c, {method = m, t1 = 0.5}), L50) <= 1e-11, m)
      assert.is_true(H.relerr(arclen.length(c, {method = m, t0 = 0.5, t1 = 0}), -L50) <= 1e-11, m)
    end
  end)

  it("coordinates within a factor 64 of DBL_MAX: exactly 2^k times the unscaled rules (fuzz_length: inf/NaN)", function()
    -- every rule scales its legs by a power of two, so 2^k c gives exactly
    -- 2^k L(c); before, the scale 2^e itself overflowed (legs near DBL_MAX)
    local row = henkel[1]
    local c, L = H.curve(row), tonumber(row.L)
    local big = 0
    for i = 1, #c do big = math.max(big, math.abs(c[i])) end
    local f = 1.0
    while big * f * 64 <= 1.7976931348623157e308 do f = f * 2 end
    local s = {}
    for i = 1, #c do s[i] = c[i] * f end
    for _, m in ipairs({"polyline", "trapezoid", "trapezoid-factored"}) do
      local a = arclen.length(c, {method = m, steps = 1000})
      local b = arclen.length(s, {method = m, steps = 1000})
      assert.are.equal(a * f, b, m)
      assert.is_true(H.relerr(b / f, L) <= 1e-5, m)   -- O(N^-2) at N = 1000
      assert.are.equal(-a * f, arclen.length(s, {method = m, steps = 1000, t0 = 1, t1 = 0}), m)
    end
  end)

  it("legs beyond DBL_MAX/2 on a finite length: the line x = -y, length 11 sqrt(2) 2^1020 (was inf)", function()
    -- legs 9u, u, u (u = 2^1020, 9u > DBL_MAX/2): the old scale 4 * 2^1022
    -- overflowed; 2^-1000 times the curve gives exactly 2^-1000 times
    local u, d = 2.0^1020, 2.0^-1000
    local c = {-6 * u, 6 * u, 3 * u, -3 * u, 4 * u, -4 * u, 5 * u, -5 * u}
    local s = {}
    for i = 1, #c do s[i] = c[i] * d end
    assert.is_true(H.relerr(arclen.length(c, {method = "polyline", steps = 1000}),
                            11 * math.sqrt(2) * u) <= 1e-14)
    for _, m in ipairs({"polyline", "trapezoid", "trapezoid-factored"}) do
      local a = arclen.length(c, {method = m, steps = 1000})
      assert.are.equal(arclen.length(s, {method = m, steps = 1000}), a * d, m)
      assert.is_true(H.relerr(a, 11 * math.sqrt(2) * u) <= 1e-5, m)
    end
  end)

  it("a subnormal quadratic term: no NaN (trapezoid-factored gave NaN, fuzz_length)", function()
    -- x = -3t(1 - t), y ~ 2.7e-312 (1 - t)^3: 1.5 to double precision; the
    -- speed 3|1 - 2t| is linear on each half and t = 1/2 is a node, so the
    -- trapezoid sum is exact
    local c = {0, 2.6555617666909946e-312, -1, 0, -1, 0, 0, 0}
    for _, m in ipairs({"polyline", "trapezoid", "trapezoid-factored"}) do
      assert.is_true(math.abs(arclen.length(c, {method = m, steps = 1000}) - 1.5) <= 1e-14, m)
    end
    -- hodograph with a subnormal leading coefficient (its root beyond 2^1000)
    c = {-1, -4.9406564584124654e-324, 0, 5.4322263344105125e-312,
         3.2615075307131295e-311, 3.2615075307106592e-311, -1, 0}
    local a = arclen.length(c, {method = "trapezoid-factored", steps = 1000})
    local b = arclen.length(c, {method = "trapezoid", steps = 1000})
    assert.is_true(a == a and H.relerr(a, b) <= 1e-12)
  end)

  it("bad steps are argument errors", function()
    assert.matches("steps", H.error_of(arclen.length, {0, 0, 1, 1, 2, 2, 3, 3},
                                       {method = "polyline", steps = 0}))
    assert.matches("steps", H.error_of(arclen.length, {0, 0, 1, 1, 2, 2, 3, 3},
                                       {method = "trapezoid", steps = 2.5}))
  end)
end)
