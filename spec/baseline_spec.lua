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

  it("bad steps are argument errors", function()
    assert.matches("steps", H.error_of(arclen.length, {0, 0, 1, 1, 2, 2, 3, 3},
                                       {method = "polyline", steps = 0}))
    assert.matches("steps", H.error_of(arclen.length, {0, 0, 1, 1, 2, 2, 3, 3},
                                       {method = "trapezoid", steps = 2.5}))
  end)
end)
