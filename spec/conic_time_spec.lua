-- conic_time_spec.lua -- a conic's time at a length below the cover's
-- tolerance (1e-13, src/segment/segment.h): at tol 1e-15 and 1e-14 the
-- search takes tol from certified lower bounds of L and measures the total
-- only where s may reach it (src/segment/invert.c), so every answer must
-- still be within tol L, and t = 1 at and past L.
-- References: spec/data/conic_times.tsv from tools/ref_conic_times.py
-- (mpmath: L at 60 and 70 digits agreeing to 1e-40, T where the length
-- from 0 is s and the speed V there, 25 digits): circular arcs, ellipses
-- down to w = 1e-9, the parabola, hyperbolas up to w = 1e6, thin and
-- near-degenerate triangles, 2D and 3D; s from 1e-12 L to (1 - 1e-12) L.
local arclen = require "arclen"
local H = require "helpers"

local abs, max = math.abs, math.max
local rows = H.tsv("conic_times.tsv")

-- The exact length's own error besides tol (spec/segment_spec.lua's conic
-- bound); the Lua engine promises 1e-12, its floor.
local BOUND = H.engine == "c" and 4e-15 or 1e-12
local TOLS = H.engine == "c" and {1e-15, 1e-14} or {1e-12}

local function cells(row)
  local out = {}
  for s, T, V in row.times:gmatch("(%S+):(%S+):(%S+)") do
    out[#out + 1] = {tonumber(s), tonumber(T), tonumber(V)}
  end
  return out
end

-- |t - T| V (the length between t and the reference T, the speed smooth
-- on that scale) against tol L + the bound's L + two ulps of t at the
-- speed (t is a double: where w = 1e6 turns its corner within 1e-6 of an
-- end, an ulp of t is a length)
local function room(tol, L, t, V)
  local ulp = 2 ^ (math.floor(math.log(max(t, 1e-300), 2)) - 52)
  return (tol + BOUND) * L + 2 * V * ulp
end

describe("a conic's time at tol 1e-15 and 1e-14 (spec/data/conic_times.tsv)", function()
  it("has the family: circles, w from 1e-9 to 1e6, thin, 3D, s near 0 and L", function()
    local wmin, wmax, circles, three, thin = 1, 1, 0, 0, 0
    for _, row in ipairs(rows) do
      local seg = H.numbers(row.seg)
      wmin = math.min(wmin, seg[#seg])
      wmax = max(wmax, seg[#seg])
      if row.name:find("circle") then circles = circles + 1 end
      if row.dim == "3" then three = three + 1 end
      if row.name:find("thin") then thin = thin + 1 end
      assert(#cells(row) == 9, row.name)
    end
    assert(#rows >= 30 and wmin <= 1e-9 and wmax >= 1e6 and circles >= 5 and three >= 5 and thin >= 2,
           ("%d rows, w %g .. %g, %d circles, %d 3D"):format(#rows, wmin, wmax, circles, three))
  end)

  it("segment_time: |t - T| V <= tol L + the bound + the step of t, at every s", function()
    local worst, n = H.worst(), 0
    for _, row in ipairs(rows) do
      local seg, L = H.numbers(row.seg), tonumber(row.L)
      for _, tol in ipairs(TOLS) do
        for _, c in ipairs(cells(row)) do
          local s, T, V = c[1], c[2], c[3]
          local t = arclen.segment_time("conic", seg, s, {tol = tol})
          worst:add(abs(t - T) * V / room(tol, L, t, V),
                    ("%s (%sD) at s %.17g, tol %g: t %.17g, T %.17g"):format(row.name, row.dim, s, tol, t, T))
          n = n + 1
        end
      end
    end
    print(("\n  conic times: %d, worst miss / room %.2f (%s)"):format(n, worst.err, worst.id))
    assert(worst.err <= 1, ("%s: %.3g of the room"):format(worst.id, worst.err))
  end)

  it("t = 1 at and past L; t = 0 at and before 0", function()
    for _, row in ipairs(rows) do
      local seg, L = H.numbers(row.seg), tonumber(row.L)
      for _, tol in ipairs(TOLS) do
        -- past L by more than tol: t = 1 is the only answer
        for _, s in ipairs({L * (1 + 1e-13), 2 * L, 1e300}) do
          assert.are.equal(1, arclen.segment_time("conic", seg, s, {tol = tol}), row.name .. " " .. s)
        end
        for _, s in ipairs({0, -1}) do
          assert.are.equal(0, arclen.segment_time("conic", seg, s, {tol = tol}), row.name .. " " .. s)
        end
        -- L itself (the reference rounded): 1, or a t within tol of it
        local t = arclen.segment_time("conic", seg, L, {tol = tol})
        if t ~= 1 then
          local got = arclen.segment_length("conic", seg, {t1 = t})
          assert(abs(got - L) <= (tol + BOUND) * L, ("%s: t %.17g at L"):format(row.name, t))
        end
      end
    end
  end)

  it("a sweep (the path's walk) of the same distances, with the length and 1e-9 off", function()
    -- arclen_segment_times_of: the first search from 0, each next from the
    -- last answer; the path's length of the segment is the caller's
    local worst = H.worst()
    for _, row in ipairs(rows) do
      local seg, L = H.numbers(row.seg), tonumber(row.L)
      local letter = "R"
      local cs = cells(row)
      local ds = {}
      for q, c in ipairs(cs) do ds[q] = c[1] end
      for _, tol in ipairs(TOLS) do
        for _, off in ipairs({1, 1 + 1e-9, 1 - 1e-9}) do
          local ks, ts = {}, {}
          arclen._walk_times({seg}, {[0] = 0, L * off}, ds, tol, false, ks, ts, letter)
          for q, c in ipairs(cs) do
            local t, T, V = ts[q], c[2], c[3]
            -- a length 1e-9 short clamps the last distances to t = 1
            if not (off < 1 and c[1] >= L * off) then
              worst:add(abs(t - T) * V / room(tol, L, t, V),
                        ("%s (%sD) off %.9g at s %.17g, tol %g"):format(row.name, row.dim, off, c[1], tol))
            end
          end
        end
      end
    end
    print(("\n  conic sweeps: worst miss / room %.2f (%s)"):format(worst.err, worst.id))
    assert(worst.err <= 1, ("%s: %.3g of the room"):format(worst.id, worst.err))
  end)

  -- the exact lengths' count is the C core's (info.pieces)
  if H.engine == "c" then
    it("at tol 1e-15 a time at L/2 takes one exact length, not the total's besides", function()
      -- bench_segment's conics (w = 0.7, points in [0, 10]^2): tol from
      -- the lower bound of L at the search's own length, the total off the
      -- chain (invert.c); info.pieces counts every exact length, the
      -- total's too where it is measured.  Near L the total is needed
      -- (s may reach it, or Newton from below overshoots t = 1): at most
      -- two then, as before the change (one and the total)
      local uniform = H.uniform(20261204)
      local one, n, most = 0, 0, 0
      for _ = 1, 200 do
        local seg = {}
        for q = 1, 6 do seg[q] = 10 * uniform() end
        seg[7] = 0.7
        local L = arclen.segment_length("conic", seg)
        for _, f in ipairs({0.5, 0.99999, 1 - 1e-7, 1 - 1e-12}) do
          local t, info = arclen.segment_time("conic", seg, f * L, {tol = 1e-15, info = true})
          local got = arclen.segment_length("conic", seg, {t1 = t})
          assert(abs(got - f * L) <= (1e-15 + BOUND) * L)
          if f == 0.5 then
            n = n + 1
            if info.pieces <= 1 then one = one + 1 end
          end
          most = max(most, info.pieces)
        end
      end
      -- measured 2026-12-04: 200 of 200 at L/2, at most 2 near L (the
      -- total's exact length is counted since session 19)
      assert(one >= 0.95 * n and most <= 2, ("%d of %d, at most %d"):format(one, n, most))
    end)
  end
end)

-- Weights far past 1 put the two legs of the control polygon into t's
-- corners: the first leg into t < ~1/w, where doubles are dense, the last
-- into 1 - t < ~1/w, where no double lies between 1 - 2^-53 and 1.  The
-- references are the legs themselves: for w >= 1e30 and t < 1e-20 the
-- point is P0 + u (P1 - P0) to 1e-50, u = 2wt(1-t) / D, so T = u / (2 w (1
-- - u)) at u = s / |P1 - P0|, and the speed there |P1 - P0| 2 w (1 - u)^2.
describe("a conic's time where w puts a leg into a corner of t", function()
  local P0, P1, P2 = {0, 0}, {3, 1}, {1, 2}
  local a, b = math.sqrt(10), math.sqrt(5)      -- |P1 - P0|, |P2 - P1|
  local function seg(w) return {P0[1], P0[2], P1[1], P1[2], P2[1], P2[2], w} end

  it("the first leg (t < 1/w) within tol, w = 1e30, 1e100, 1e300", function()
    for _, w in ipairs({1e30, 1e100, 1e300}) do
      if H.engine ~= "c" and w >= 2 ^ 510 then   -- its angle form squares w
        local ok, err = pcall(arclen.segment_length, "conic", seg(w))
        assert(not ok and err:find("weight .*must be below 2%^510 on the Lua engine"), err)
      else
        local L = arclen.segment_length("conic", seg(w))
        assert(abs(L - (a + b)) <= BOUND * L, ("w %g: L %.17g"):format(w, L))
        for _, tol in ipairs(H.engine == "c" and {1e-9, 1e-15} or {1e-9}) do
          for k = 1, 19 do
            local u = k / 20
            local s, T, V = u * a, u / (2 * w * (1 - u)), a * 2 * w * (1 - u) ^ 2
            local t = arclen.segment_time("conic", seg(w), s, {tol = tol})
            assert(abs(t - T) * V <= room(tol, L, t, V),
                   ("w %g, tol %g, s %.17g: t %.17g, T %.17g"):format(w, tol, s, t, T))
          end
        end
      end
    end
  end)

  -- the C core's search (src/segment/invert.c); the Lua engine searches
  -- in the conic's angle and rounds its answer to t, 1 on this leg
  -- (CHANGELOG, known limitations)
  if H.engine == "c" then
  it("the last leg (1 - t < 1/w): the nearer of the t below 1 and t = 1", function()
    -- every double t < 1 is at length a (to 1e-13 for w = 1e30); t = 1 at a + b
    for _, w in ipairs({1e30, 1e100, 1e300}) do
      for k = 1, 9 do
        local s = a + b * (k / 10)
        local t = arclen.segment_time("conic", seg(w), s, {tol = 1e-9})
        if k < 5 then
          assert(t < 1, ("w %g, s %.17g: t %.17g"):format(w, s, t))
          local got = arclen.segment_length("conic", seg(w), {t1 = t})
          assert(abs(got - a) <= 1e-12 * a, ("w %g, s %.17g: t %.17g at %.17g"):format(w, s, t, got))
        elseif k > 5 then
          assert.are.equal(1, t, ("w %g, s %.17g"):format(w, s))
        end
      end
    end
  end)
  end
end)
