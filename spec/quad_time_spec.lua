-- quad_time_spec.lua -- a quadratic's time at a length (issue 31 item 8,
-- src/segment/quad_time.c): most often the inverse of the closed form from
-- a table with the bound of its miss, no length at all; else lengths from
-- one set-up, and the last step certified by the speed's exact derivatives
-- (sigma'' = 2 k^2/|v|^3) instead of another length.  Each answer t is checked by the closed form over [0,
-- t] (arclen.segment_length, within 16 eps of 40-digit references:
-- segment_spec) on random and hostile quadratics: cusps (k = 0), straight
-- and nearly straight ones, a zero leg, tiny and huge scales, 3D, and
-- distances at 0, at L, just inside both, and between; and a sweep of
-- ascending distances (the path walks') against the single times.
local arclen = require "arclen"
local H = require "helpers"

local EPS = 2 ^ -52
local abs, max = math.abs, math.max

-- a fixed generator: the same quadratics on every host
local rand = H.uniform(12345)

local HOSTILE = {
  {"cusp: P2 = P0, turns back at t = 1/2", {0, 0, 1, 0, 0, 0}},
  {"cusp: collinear, turns back at t = 2/3", {0, 0, 2, 0, 1, 0}},
  {"collinear, no turn", {0, 0, 1, 0, 5, 0}},
  {"straight, uniform speed (b = 0)", {0, 0, 1, 1, 2, 2}},
  {"first leg 0 (speed 0 at t = 0)", {0, 0, 0, 0, 3, 1}},
  {"second leg 0 (speed 0 at t = 1)", {0, 0, 3, 1, 3, 1}},
  {"nearly straight (the Gauss branch)", {0, 0, 1.01, 1, 2, 2}},
  {"tall arch", {0, 0, 1, 100, 2, 0}},
  {"thin hairpin (k small)", {0, 0, 50, 1e-6, 0, 2e-6}},
  {"skew arch", {0.5, 1, 7, 9.25, 3, -2}},
  {"arch at 1e-300", {0, 0, 1e-300, 2e-300, 2e-300, 0}},
  {"arch at 1e300", {0, 0, 1e300, 2e300, 2e300, 0}},
  -- the C core's halved legs; the Lua engine's length overflows here
  {"past DBL_MAX/2 (halved legs)", {-9e307, 0, 9e307, 0, -3e307, 3e307}, c_only = true},
  {"3D arch", {0, 0, 0, 1, 2, 3, 2, 0, 1}},
  {"3D cusp", {0, 0, 0, 1, 1, 1, 0, 0, 0}},
  -- the first guess's branches (quad_time.c first_guess): k^2 below
  -- DBL_MIN (no log), y past the table (the asymptote), y below it (the
  -- series, at the vertex); random ones take the table, U0 < 0 < U or not
  {"hairpin, k^2 below DBL_MIN", {0, 0, 1, 1e-160, 0, 2e-160}},
  {"far from the vertex, U ~ 2e9", {0, 0, 1, 1e-9, 3, 2.5e-9}},
  {"symmetric arch, vertex at L/2", {0, 0, 1, 1, 2, 0}},
  {"far from the origin", {1e6, 1e6, 1000003.5, 1000001.25, 1000004.75, 999997.5}},
}

local function cases()
  local list = {}
  for _, c in ipairs(HOSTILE) do
    if H.engine == "c" or not c.c_only then list[#list + 1] = c end
  end
  for i = 1, 60 do
    local q = {}
    for k = 1, 6 do q[k] = 10 * rand() - 5 end
    list[#list + 1] = {"random " .. i, q}
  end
  for i = 1, 10 do
    local q = {}
    for k = 1, 9 do q[k] = 10 * rand() - 5 end
    list[#list + 1] = {"random 3D " .. i, q}
  end
  return list
end

-- the fractions of L asked for: 0, just inside both ends, and between
local FRACTIONS = {0, 1e-17, 1e-9, 0.01, 0.25, 0.5, 0.7, 0.999, 1 - 1e-9, 1 - 2 ^ -52, 1}

local function miss(seg, t, s)
  return abs(arclen.segment_length("quad", seg, {t1 = t}) - s)
end

describe("a quadratic's time at a length (quad_time.c)", function()
  -- 1e-13 and 1e-14: where the table's answer is taken or not by a bound
  -- near tol (quad_time.c direct_bound)
  local tols = H.engine == "c" and {1e-6, 1e-12, 1e-13, 1e-14, 1e-15} or {1e-6, 1e-12}
  for _, c in ipairs(cases()) do
    it(c[1] .. ": |s(t) - s| <= tol L at 0, L, just inside and between", function()
      local seg = c[2]
      local L = arclen.segment_length("quad", seg)
      for _, tol in ipairs(tols) do
        for _, f in ipairs(FRACTIONS) do
          local s = f * L
          local t = arclen.segment_time("quad", seg, s, {tol = tol})
          assert(t >= 0 and t <= 1, "t in [0, 1]")
          -- the closed form's own rounding at t: 4 eps of L (segment_spec)
          assert(miss(seg, t, s) <= tol * L + 4 * EPS * L,
                 ("tol %g f=%.17g: miss %.3g L"):format(tol, f, miss(seg, t, s) / L))
          if f == 0 then assert.are.equal(0, t) end
          if f == 1 then assert.are.equal(1, t) end
        end
      end
    end)
  end

  it("at the length of [0, t] for 200 random t, the time's length is within tol", function()
    for _, c in ipairs({HOSTILE[2], HOSTILE[8], HOSTILE[9], HOSTILE[H.engine == "c" and 13 or 12]}) do
      local seg = c[2]
      local L = arclen.segment_length("quad", seg)
      for _ = 1, 200 do
        local s = arclen.segment_length("quad", seg, {t1 = rand()})
        local t = arclen.segment_time("quad", seg, s, {tol = 1e-12})
        assert(miss(seg, t, s) <= 1e-12 * L + 4 * EPS * L, c[1])
      end
    end
  end)

  if H.engine == "c" then
    -- the lengths measured, random quadratics in [-5, 5]^2 at L/2: 3.2 on
    -- average after the total before the certified step (Hermite guess,
    -- Halley's steps on exact lengths), 1.66 with it; now at 1e-12 the
    -- table's bound answers nearly all (all but those whose y = Y/k^2 is
    -- past the table's octaves), and at 1e-15, below what that bound can
    -- certify, its answer is the guess: one length, then the step
    it("answers from the table without a length at 1e-12, with one at 1e-15", function()
      local n, none, sum15 = 0, 0, 0
      for _ = 1, 500 do
        local q = {}
        for k = 1, 6 do q[k] = 10 * rand() - 5 end
        local L = arclen.segment_length("quad", q)
        local _, info = arclen.segment_time("quad", q, L / 2, {tol = 1e-12, info = true})
        local _, info15 = arclen.segment_time("quad", q, L / 2, {tol = 1e-15, info = true})
        n = n + 1
        if info.pieces == 0 then none = none + 1 end
        sum15 = sum15 + info15.pieces
      end
      assert(none >= 0.97 * n, ("%d of %d without a length"):format(none, n))
      assert(sum15 / n <= 1.1, ("%.2f lengths on average at 1e-15"):format(sum15 / n))
    end)
  end

  -- a sweep steps from the last answer, often by more than the first
  -- guess's 1e-6 of |v|/|b|: the short step's guard (2^-16) and bound
  -- decide there (a copy that took second-order steps up to 1/8 of |v|/|b|
  -- without their remainder missed by 2.9 tol on the first of these)
  it("sweeps of random ascending distances are within tol of the closed form", function()
    local tols = H.engine == "c" and {1e-15, 1e-12, 1e-9} or {1e-12, 1e-9}
    for i = 1, 300 do
      local q = {}
      for k = 1, 6 do q[k] = 10 * rand() - 5 end
      local L = arclen.segment_length("quad", q)
      local ds = {}
      for j = 1, 2 + math.floor(rand() * 12) do ds[j] = L * rand() end
      table.sort(ds)
      for _, tol in ipairs(tols) do
        local ks, ts = {}, {}
        arclen._walk_times({q}, {[0] = 0, L}, ds, tol, false, ks, ts, "Q")
        for j, d in ipairs(ds) do
          local m = miss(q, ts[j], d)
          assert(m <= tol * L + 4 * EPS * L,
                 ("random %d, distance %d, tol %g: %.3g L"):format(i, j, tol, m / L))
        end
      end
    end
  end)

  it("a sweep of 300 ascending distances equals the single times within tol", function()
    local tol = H.engine == "c" and 1e-15 or 1e-12
    for _, c in ipairs({HOSTILE[1], HOSTILE[8], HOSTILE[10], HOSTILE[12], {"random", {-4, 3, 2, -1, 4.5, 2.5}}}) do
      local seg = c[2]
      local L = arclen.segment_length("quad", seg)
      local ds = {}
      for i = 0, 299 do ds[#ds + 1] = L * (i / 299) ^ 1.5 end
      local ks, ts = {}, {}
      arclen._walk_times({seg}, {[0] = 0, L}, ds, tol, false, ks, ts, "Q")
      local prev = 0
      for q, d in ipairs(ds) do
        local t = ts[q]
        assert(t >= prev, "times ascend")
        prev = t
        local one = arclen.segment_time("quad", seg, d, {tol = tol})
        local m1, m2 = miss(seg, t, d), miss(seg, one, d)
        assert(m1 <= tol * L + 4 * EPS * L, ("%s sweep %d: %.3g L"):format(c[1], q, m1 / L))
        assert(m2 <= tol * L + 4 * EPS * L, ("%s single %d: %.3g L"):format(c[1], q, m2 / L))
        assert(abs(arclen.segment_length("quad", seg, {t1 = t}) -
                   arclen.segment_length("quad", seg, {t1 = one})) <= 2 * tol * L + 8 * EPS * L)
      end
    end
  end)
end)

describe("a quadratic's time against 40-digit references", function()
  -- spec/data/quad_times.tsv (tools/ref_quad_times.py): the true time T at
  -- f L and the speed V there, from the textbook closed form at 60 digits
  local rows = H.tsv("quad_times.tsv")
  local function seg_of(row)
    return H.numbers(row.seg)
  end

  it("each time misses the true length by at most tol L (|t - T| V)", function()
    local n = 0
    for _, row in ipairs(rows) do
      if row.kind == "time" and (H.engine == "c" or row.name ~= "past DBL_MAX/2") then
        local seg, f, L = seg_of(row), tonumber(row.f_or_t), tonumber(row.L_or_s)
        local T, VL = tonumber(row.T), tonumber(row.VL)
        for _, tol in ipairs(H.engine == "c" and {1e-6, 1e-12, 1e-13, 1e-14, 1e-15}
                                               or {1e-6, 1e-12}) do
          local t = arclen.segment_time("quad", seg, f * L, {tol = tol})
          -- in units of L; the closed form's bound at t (segment_spec: a
          -- few eps of L)
          local m = abs(t - T) * VL
          assert(m <= 1.01 * tol + 4 * EPS,
                 ("%s f=%s tol %g: %.3g L"):format(row.name, row.f_or_t, tol, m))
          n = n + 1
        end
      end
    end
    assert(n >= 300, "rows read")
  end)

  if H.engine == "c" then
    -- quad_time.c's FORM_ROUNDING: the closed form's own rounding, without
    -- the legs' (exact here), at most 8 units of 2^-53 of the length
    it("the closed form over [0, t] is within 8 U of its value (exact legs)", function()
      local worst, n = 0, 0
      for _, row in ipairs(rows) do
        if row.kind == "rounding" then
          local seg, t, want = seg_of(row), tonumber(row.f_or_t), tonumber(row.L_or_s)
          local got = arclen.segment_length("quad", seg, {t1 = t})
          worst = max(worst, abs(got - want) / want / 2 ^ -53)
          n = n + 1
        end
      end
      assert(n >= 590, "rows read")
      assert(worst <= 8, ("%.2f U"):format(worst))
    end)
  end
end)

describe("a quadratic's time: the measure does not change", function()
  it("segment_time clamps at segment_length's total (the one whole length)", function()
    -- the time at exactly L is 1 and just below L is below 1: the total the
    -- search clamps against is the closed form's own
    for _, c in ipairs(cases()) do
      local L = arclen.segment_length("quad", c[2])
      assert.are.equal(1, arclen.segment_time("quad", c[2], L))
      if L > 0 then
        local below = L - L * 2 ^ -40
        assert(arclen.segment_time("quad", c[2], below, {tol = 1e-15}) < 1, c[1])
      end
    end
  end)

  it("the whole sweep's answers lie in [0, 1] and reach 1 at L", function()
    local seg = {0, 0, 1, 2, 2, 0}
    local L = arclen.segment_length("quad", seg)
    local ks, ts = {}, {}
    arclen._walk_times({seg}, {[0] = 0, L}, {0, L / 2, L}, 1e-12, false, ks, ts, "Q")
    assert.are.equal(0, ts[1])
    assert.are.equal(1, ts[3])
    assert(max(ts[2], 0) > 0 and ts[2] < 1)
  end)
end)

-- The set-up scales the legs by a power of two only where their largest
-- component lies outside [2^-100, 2^100] (quad.c setup_dim); inside it
-- takes them as they are, because every operation the length and the time
-- take commutes exactly with a power of two.  So a quadratic scaled by 2^k
-- has the length times 2^k and the same times, bit for bit, on both sides
-- of the range's ends: a claim the two paths must keep.
describe("a quadratic scaled by a power of two", function()
  local ks = {-300, -160, -101, -100, -99, -50, -1, 0, 1, 50, 99, 100, 101, 160, 300}
  it("has its length times 2^k and the same times, bit for bit", function()
    local gen = H.uniform(777)
    for i = 1, 40 do
      local dim = i % 4 == 0 and 3 or 2
      local q = {}
      for k = 1, 3 * dim do q[k] = 10 * gen() - 5 end
      local L = arclen.segment_length("quad", q)
      local sub = arclen.segment_length("quad", q, {t0 = 0.25, t1 = 0.8})
      local fr = {gen(), 0.5, 1 - 2 ^ -20}
      local times = {}
      for j, f in ipairs(fr) do
        times[j] = arclen.segment_time("quad", q, f * L, {tol = 1e-12})
        times[j + 3] = arclen.segment_time("quad", q, f * L, {tol = 1e-15})
      end
      for _, k in ipairs(ks) do
        local p, sc = {}, 2 ^ k
        for j = 1, #q do p[j] = q[j] * sc end
        local Lk = arclen.segment_length("quad", p)
        assert(Lk == L * sc, ("quad %d at 2^%d: length %.17g, want %.17g"):format(i, k, Lk, L * sc))
        assert.are.equal(sub * sc, arclen.segment_length("quad", p, {t0 = 0.25, t1 = 0.8}))
        for j, f in ipairs(fr) do
          for m, tol in ipairs({1e-12, 1e-15}) do
            local t = arclen.segment_time("quad", p, f * L * sc, {tol = tol})
            assert(t == times[j + 3 * (m - 1)],
                   ("quad %d at 2^%d, s = %.3g L, tol %g: t %.17g, want %.17g")
                     :format(i, k, f, tol, t, times[j + 3 * (m - 1)]))
          end
        end
      end
    end
  end)
end)
