-- method = "elliptic" (src/elliptic.c) against the 40-digit references of
-- tools/ref_lengths.py (spec/data/curves2d.tsv, curves3d.tsv) and of
-- tools/ref_hard.py (spec/data/hard2d.tsv, hard3d.tsv: reversals near a line
-- at 1e-2 .. 1e-12, coincident pairs and triples and such points moved apart
-- by 1e-4 .. 1e-15, near-cusps to 1e-15).  Bounds: every curve <= 1e-14
-- relative, Henkel's six arcs <= 5e-15.  Why 1e-14 holds: every branch now
-- sums terms within ~6x the result (Carlson's [1,1,1,1] with R_D traded for
-- R_G, src/elliptic/product.c), each from a handful of roundings and
-- R-functions good to a few eps: 6 x ~8 eps ~ 1e-14; measured 2.9e-15.
local arclen = require("arclen")
local H = require("helpers")

local function elliptic(c, t0, t1)
  return arclen.length(c, {method = "elliptic", t0 = t0, t1 = t1, info = true})
end

local function check_file(file)
  local rows = H.tsv(file)
  for _, family in ipairs(H.families(rows)) do
    local bound = family == "henkel" and 5e-15 or 1e-14
    it(file .. " " .. family .. ": s(1/4), s(1/2), s(3/4), L within " .. bound, function()
      local worst = H.worst_lengths(rows, family, function(c, t1)
        return elliptic(c, 0, t1)
      end)
      assert.is_true(worst.err <= bound,
        ("worst %s: %.3g > %.3g"):format(tostring(worst.id), worst.err, bound))
    end)
  end
end

describe("elliptic", function()
  check_file("curves2d.tsv")
  check_file("curves3d.tsv")   -- 3D: quartic split, roots polished
  check_file("hard2d.tsv")     -- reversals, coincident points, near-cusps
  check_file("hard3d.tsv")     -- the same in space (|z'|^2 split by roots.c)

  -- Where the digits went before: near a fold the hodograph root
  -- is within b1 << 1 of the range, the arguments M^2, Lm^2 of R_F and R_D
  -- both ~ b1^2, and both R-functions diverge like log(1/b1) in Carlson's sum
  -- (terms to 50x the integral: 2.7e-14 on reversal-83, 2.85e-14 on
  -- nearcusp-139).  With R_D traded for R_G the weight of R_F is O(b1^2).
  it("the hard curves that lost digits take the Carlson branch and keep them", function()
    local rows = H.tsv("hard2d.tsv")
    local want = {["reversal-83"] = true, ["coincident-156"] = true}
    local seen = 0
    for _, row in ipairs(rows) do
      if want[row.id] then
        seen = seen + 1
        local got, info = elliptic(H.curve(row), 0, 0.5)
        assert.are.equal("carlson", info.branch)
        assert.is_true(H.relerr(got, tonumber(row.L50)) <= 5e-15,
          ("%s: %.3g"):format(row.id, H.relerr(got, tonumber(row.L50))))
      end
    end
    assert.are.equal(2, seen)
  end)

  -- Henkel's failures (seed 003, Sec. 6), by name.
  local henkel = {}
  for _, row in ipairs(H.curves("curves2d.tsv", "henkel")) do
    henkel[tonumber(row.id:match("(%d+)$"))] = row
  end
  local function case(n, branch, exact)
    local row = henkel[n]
    local got, info = elliptic(H.curve(row), 0, 1)
    assert.are.equal(branch, info.branch)
    assert.is_true(H.relerr(got, tonumber(row.L)) <= 5e-15)
    if exact then assert.is_true(H.relerr(got, exact) <= 5e-15) end
    return info
  end

  it("well-behaved arc (curve 1) by Carlson's [1,1,1,1] with 5 R-calls", function()
    local info = case(1, "carlson")
    assert.are.equal(5, info.calls)
  end)
  it("cusp (curve 2): closed form 20 sqrt 2 - 10", function()
    case(2, "cusp", 20 * math.sqrt(2) - 10)
  end)
  it("near cusp (curve 3) keeps its digits", function()
    -- the hodograph root is 3e-10 off the axis: the cusp closed form is
    -- exact to b^2 log(1/b) ~ 1e-18 (Carlson's R_F would diverge)
    case(3, "cusp")
  end)
  it("collinear (curve 4): 10 sqrt 2", function()
    case(4, "collinear", 10 * math.sqrt(2))
  end)
  it("two cusps (curve 5) does not hang: 10 sqrt 2 + 4 sqrt 10", function()
    case(5, "collinear", 10 * math.sqrt(2) + 4 * math.sqrt(10))
  end)
  it("two near cusps (curve 6) keeps its digits", function()
    case(6, "carlson")
  end)

  it("a point has length 0 exactly; empty and reversed ranges", function()
    local p = {3, 4, 3, 4, 3, 4, 3, 4}
    assert.are.equal(0, (elliptic(p, 0, 1)))
    local c = H.curve(henkel[1])
    assert.are.equal(0, (elliptic(c, 0.3, 0.3)))
    local a, b = elliptic(c, 0.2, 0.7), elliptic(c, 0.7, 0.2)
    assert.are.equal(a, -b)
  end)

  -- 3D roots of Q = |z'|^2 that are multiple: Newton on Q pins them only to
  -- ~sqrt(eps) (erred 6e-9); the pair is rebuilt from its centre (src/roots/roots3d.c).
  -- Closed forms, and the default method at tol 1e-15 on sub-ranges.
  local function multiple(c, exact)
    assert.is_true(H.relerr(elliptic(c, 0, 1), exact) <= 1e-14)
    for _, r in ipairs({{0, 0.5}, {0.3, 0.9}, {0.9, 1}, {0.49, 0.51}}) do
      local want = arclen.length(c, {tol = 1e-15, t0 = r[1], t1 = r[2]})
      assert.is_true(H.relerr(elliptic(c, r[1], r[2]), want) <= 1e-14,
        ("[%g, %g]"):format(r[1], r[2]))
    end
  end
  it("3D double complex pair: Q = 18 (3t^2 - 3t + 1)^2, length 3/sqrt 2", function()
    multiple({0, 0, 0, 0, -1, -1, -1, -1, 0, 0, 0, 0}, 3 / math.sqrt(2))
  end)
  it("3D quadruple real root: a collinear stop, length = its chord", function()
    local h = 4.370938204228878
    multiple({0, h, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, h)
  end)

  -- Space cubics whose Q = |z'|^2 has roots close together (tools/ref_close3d.py,
  -- mpmath): a near double complex pair (hodograph nearly in a plane through
  -- the origin) erred 3.5e-11, a perturbed collinear stop 3.6e-7 (sub-range
  -- beside it 1.5e-5), fuzz-found 3D stops 7e-6.  Close roots are now set in a
  -- frame about their cluster (src/roots/roots3d.c).  The bound: 1e-14.
  describe("close roots of |z'|^2 in 3D (close3d.tsv)", function()
    local rows = H.tsv("close3d.tsv")
    for _, family in ipairs(H.families(rows)) do
      it(family .. ": s(1/4), s(1/2), s(3/4), L and a sub-range by the cluster within 1e-14", function()
        local worst = H.worst_lengths(rows, family, function(c, t1)
          return elliptic(c, 0, t1)
        end)
        for _, row in ipairs(rows) do
          if row.family == family then
            local t0, t1 = tonumber(row.t0), tonumber(row.t1)
            local got = elliptic(H.curve(row), t0, t1)
            assert.is_true(got == got, row.id .. ": NaN")
            worst:add(H.relerr(got, tonumber(row.Lsub)),
              ("%s [%.17g, %.17g]"):format(row.id, t0, t1))
          end
        end
        assert.is_true(worst.err <= 1e-14,
          ("worst %s: %.3g > 1e-14"):format(tostring(worst.id), worst.err))
      end)
      -- the default method reads its error bound off the same roots
      -- (src/branch.c): a stop's quadruple root came out of Q's coefficients
      -- to eps^(1/4) and gauss erred 7e-9 at tol 1e-15
      it(family .. ": the default method at tol 1e-15 within 1e-14 (3D branch points)", function()
        local worst = H.worst_lengths(rows, family, function(c, t1)
          return arclen.length(c, {tol = 1e-15, t1 = t1})
        end)
        for _, row in ipairs(rows) do
          if row.family == family then
            local t0, t1 = tonumber(row.t0), tonumber(row.t1)
            local got = arclen.length(H.curve(row), {tol = 1e-15, t0 = t0, t1 = t1})
            worst:add(H.relerr(got, tonumber(row.Lsub)),
              ("%s [%.17g, %.17g]"):format(row.id, t0, t1))
          end
        end
        assert.is_true(worst.err <= 1e-14,
          ("worst %s: %.3g > 1e-14"):format(tostring(worst.id), worst.err))
      end)
    end
  end)

  it("a curve near DBL_MAX: the scale is an exponent, the length finite", function()
    -- hodograph 3 x 9e307 > DBL_MAX; gave inf (found by fuzz/fuzz_length).
    -- P1 = P2 = P3 = 0: a straight line to the origin, its length |P0|
    -- (111 beside 9e307 changes it by 1e-612 relative)
    local cases = {
      {{111, -8.9873684494978208e307, 0, 0, 0, 0, 0, 0}, 8.9873684494978208e307},
      {{-3.9595441405013419e307, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 3.9595441405013419e307},
    }
    for _, case in ipairs(cases) do
      local got = elliptic(case[1], 0, 1)
      assert.is_true(H.relerr(got, case[2]) <= 1e-15, tostring(got))
    end
  end)

  it("a line whose control points carry a residue of 1e-304 .. 1e-100: sub-ranges exact", function()
    -- legs (-2, -2) (+ the residue): speed 6 sqrt 2 to 1e-100, length 6 sqrt 2 (t1 - t0).
    -- A sub-range's own hodograph keeps the residue as A2, A1 ~ 1e-300 of A0: 2D put
    -- the root 1e152 away and the shifted range rounded to nothing, or (subnormal
    -- A2 beside A1 ~ 1e-323) a root near the range (length 0); 3D
    -- squared them into subnormals (errors up to 5%).  Found by fuzz/fuzz_length.
    local curves = {
      {7.2911220195563967e-304, -1, -2, -3, -4, -5, -6, -7},
      {2.5197347937903574e-322, -1, -2, -3, -4, -5, -6, -7},
      {7.2911220195563967e-304, -1, 0, -2, -3, 0, -4, -5, 0, -6, -7, 0},
      {1e-160, -1, 0, -2, -3, 0, -4, -5, 0, -6, -7, 0},
      {1e-100, -1, 0, -2, -3, 0, -4, -5, 0, -6, -7, 0},
      {0, -1, 1e-120, -2, -3, 0, -4, -5, 0, -6, -7, 0},
    }
    for i, c in ipairs(curves) do
      for _, r in ipairs({{0.3, 0.7}, {0, 0.5}, {0.5, 1}, {0, 1}, {0.9, 0.123}, {0.41, 0.5257}}) do
        local got = elliptic(c, r[1], r[2])
        assert.is_true(H.relerr(got, 6 * math.sqrt(2) * (r[2] - r[1])) <= 1e-15,
          ("curve %d [%g, %g]: %.17g"):format(i, r[1], r[2], got))
      end
    end
  end)

  it("a near-quadratic cubic takes the far-root series", function()
    -- degree-elevated quadratic (0,0) (3,6) (6,0), perturbed by 1e-6
    local c = {0, 0, 2, 4, 4, 4 + 1e-6, 6, 0}
    local _, info = elliptic(c, 0, 1)
    assert.is_truthy(info.branch:match("^series") or info.branch == "quadratic")
  end)

  it("never NaN, never negative, on wild curves (tiny, huge, far away, degenerate)", function()
    local seed = 12345
    local function rnd()   -- a small LCG: the spec must not depend on math.random
      seed = (seed * 1103515245 + 12345) % 2147483648
      return seed / 2147483648
    end
    local scales = {1e-300, 1e-150, 1e-12, 1, 1e12, 1e150, 1e300}
    for i = 1, 2000 do
      local s = scales[i % #scales + 1]
      local off = (i % 3 == 0) and 1e6 * s or 0
      local c = {}
      for k = 1, 8 do c[k] = off + s * (rnd() - 0.5) end
      if i % 5 == 0 then c[3], c[4] = c[1], c[2] end          -- coincident
      if i % 7 == 0 then for k = 1, 8, 2 do c[k + 1] = 2 * c[k] end end  -- collinear
      local t0, t1 = rnd(), rnd()
      local got = elliptic(c, t0, t1)
      assert.is_true(got == got and math.abs(got) < math.huge, "NaN/inf for curve " .. i)
      if t1 >= t0 then assert.is_true(got >= 0) end
    end
  end)
end)
