-- segment_spec.lua -- segments of four kinds (issue 31): line, quad, cubic
-- and conic (rational quadratic, weights 1, w, 1), 2D and 3D, through
-- arclen.segment_length / _time / _point / _derivative / _sub, the kinds
-- in arclen.lengths and the walks, and bad input naming its argument.
-- References: spec/data/segments_lengths.tsv from tools/ref_segments.py
-- (mpmath quad of the speed from the definitions, 40 digits).
local arclen = require "arclen"
local H = require "helpers"

local EPS = 2 ^ -52
local abs, max = math.abs, math.max
local unpack = table.unpack or unpack
local rows = H.tsv("segments_lengths.tsv")

-- The bounds the C core's methods guarantee, relative to the length:
-- line: each coordinate difference one rounding and hypot within an ulp
-- (3D: two hypots), so 4 eps; quad: the legs one rounding each, then a
-- closed form of sums of positive terms (a dozen roundings, none
-- amplified: U1 - U0 is set exactly) or a Gauss rule whose truncation is
-- below 1e-19 (quad.c), so 16 eps; conic: arclen_conic_length's own
-- (conic_spec: 9.5e-16 on its references) plus the sub-arc's control points
-- (one blossom each, a few roundings), so 4e-15.  The Lua engine promises
-- the tolerance (1e-12 relative) only.
local BOUND = {line = 4 * EPS, quad = 16 * EPS, conic = 4e-15}
local function bound(kind)
  return H.engine == "c" and BOUND[kind] or 1e-12
end

local function seg_of(row)
  return H.numbers(row.seg)
end

-- the largest coordinate: what a sub-range's rounded control points are
-- relative to
local function size(s, kind, dim)
  local n = kind == "conic" and 3 * dim or #s
  local m = 0
  for i = 1, n do m = max(m, abs(s[i])) end
  return m
end

describe("segments of four kinds (issue 31)", function()
  describe("lengths against 40-digit references", function()
    for _, row in ipairs(rows) do
      it(row.name .. ": length from 0 to 1/4, 1/2, 3/4, 1 within " ..
         (H.engine == "c" and "the closed form's bound" or "tol"), function()
        local s = seg_of(row)
        for _, p in ipairs({{0.25, "L25"}, {0.5, "L50"}, {0.75, "L75"}, {1, "L"}}) do
          local want = tonumber(row[p[2]])
          local got = arclen.segment_length(row.kind, s, {t1 = p[1]})
          local err = H.relerr(got, want)
          assert(err <= bound(row.kind), ("%s t1=%g: %.3g relative (bound %.3g)")
            :format(row.name, p[1], err, bound(row.kind)))
        end
        -- the whole length, also with the tolerance at its loosest: a
        -- closed form or an exact length does not depend on it
        local L = tonumber(row.L)
        assert(H.relerr(arclen.segment_length(row.kind, s, {tol = 0.1}), L) <= bound(row.kind))
      end)
      it(row.name .. ": the piece [0.2, 0.7], by t0/t1 and by segment_sub", function()
        local s = seg_of(row)
        local want = tonumber(row.L2070)
        local dim = tonumber(row.dim)
        local got = arclen.segment_length(row.kind, s, {t0 = 0.2, t1 = 0.7})
        -- a conic's piece is measured on its own control points, rounded
        -- at the coordinates' scale: 4 eps |P| over the piece's length more
        local b = bound(row.kind)
        if row.kind == "conic" then b = b + 4 * EPS * size(s, row.kind, dim) / want end
        local e = H.relerr(got, want)
        assert(e <= b, ("%s t0/t1: %.3g (bound %.3g)"):format(row.name, e, b))
        local back = arclen.segment_length(row.kind, s, {t0 = 0.7, t1 = 0.2})
        assert.are.equal(-got, back)
        -- segment_sub's numbers are rounded: the length moves by their
        -- rounding (eps times the coordinates) over the length
        local sub = arclen.segment_sub(row.kind, s, 0.2, 0.7)
        assert.are.equal(#s, #sub)
        local tolsub = bound(row.kind) + 16 * EPS * size(s, row.kind, dim) / want
        local err = H.relerr(arclen.segment_length(row.kind, sub), want)
        assert(err <= tolsub, ("%s sub: %.3g (bound %.3g)"):format(row.name, err, tolsub))
      end)
    end
  end)

  describe("a quadratic's closed form, branch by branch", function()
    -- spec/data/quad_branches.tsv (tools/ref_quad_branches.py, which checks
    -- that each row reaches the branch of quad.c it names): the vertex in
    -- the range or not (or both ends before it), the log's argument at least
    -- 2 or below (log1p), collinear points, nearly straight, extreme scales
    -- a leg P1 - P0 or P2 - P1 past DBL_MAX: the C core halves the points
    -- first, the Lua engine scales them by a power of two (pure_segment.lua,
    -- big_scaled); both are held to the reference
    for _, row in ipairs((H.tsv("quad_branches.tsv"))) do
      it(row.name .. " (" .. row.branch .. ") within " ..
         (H.engine == "c" and "the closed form's bound" or "tol"), function()
        local s, want = seg_of(row), tonumber(row.L)
        local t0, t1 = tonumber(row.t0), tonumber(row.t1)
        local got = arclen.segment_length("quad", s, {t0 = t0, t1 = t1})
        local err = H.relerr(got, want)
        assert(err <= bound("quad"), ("%s: %.3g relative (bound %.3g)")
          :format(row.name, err, bound("quad")))
        assert.are.equal(-got, arclen.segment_length("quad", s, {t0 = t1, t1 = t0}))
      end)
    end
  end)

  describe("time at a length", function()
    for _, row in ipairs(rows) do
      it(row.name .. ": |s(t) - s| <= tol L at s = L/3, 2L/3", function()
        local s, L = seg_of(row), tonumber(row.L)
        for _, tol in ipairs({1e-6, 1e-10, 1e-14}) do
          for _, q in ipairs({{1 / 3, "T33", "V33"}, {2 / 3, "T67", "V67"}}) do
            local T, V = tonumber(row[q[2]]), tonumber(row[q[3]])
            local t = arclen.segment_time(row.kind, s, q[1] * L, {tol = tol})
            assert(t >= 0 and t <= 1)
            -- the length between t and the true T is about |t - T| V (the
            -- speed is smooth there); the reference's own rounding adds eps
            local miss = abs(t - T) * V
            assert(miss <= 1.01 * tol * L + 4 * EPS * L,
                   ("%s tol %g s=%s: %.3g L"):format(row.name, tol, q[2], miss / L))
          end
        end
        assert.are.equal(0, arclen.segment_time(row.kind, s, -1))
        assert.are.equal(1, arclen.segment_time(row.kind, s, 2 * L + 1))
      end)
    end
  end)

  describe("a quadratic's time at a length (few exact lengths)", function()
    -- quad_time.c: the closed form's inverse from a table, the answer
    -- where the bound of its miss is within tol; else from each length
    -- measured by the closed form a step certified by the speed's exact
    -- derivatives (no length of its own); on the reference quadratics at
    -- seven fractions and three tolerances this took 3.67 exact lengths on
    -- average and 9 at most with Newton from the length fraction, 2.26 and
    -- 5 with a Hermite guess and Halley's steps on exact lengths, 1.43 and
    -- 5 with the certified step, 0.77 and 2 with the table's answer
    it("within tol L, and in few exact lengths" ..
       (H.engine == "c" and "" or " [Lua engine: its own search; the guarantee only]"), function()
      local n, sum, worst = 0, 0, 0
      for _, row in ipairs(rows) do
        if row.kind == "quad" then
          local s, L = seg_of(row), tonumber(row.L)
          for _, f in ipairs({0.01, 0.1, 1 / 3, 0.5, 2 / 3, 0.9, 0.99}) do
            for _, tol in ipairs(H.engine == "c" and {1e-6, 1e-12, 1e-15} or {1e-6, 1e-12}) do
              local t, info = arclen.segment_time("quad", s, f * L, {tol = tol, info = true})
              local got = arclen.segment_length("quad", s, {t1 = t})
              assert(abs(got - f * L) <= tol * L + 4 * EPS * L,
                     ("%s f=%g tol %g: %.3g L"):format(row.name, f, tol, abs(got - f * L) / L))
              n, sum, worst = n + 1, sum + info.pieces, max(worst, info.pieces)
            end
          end
        end
      end
      if H.engine == "c" then
        assert(sum / n <= 1 and worst <= 3,
               ("%.2f exact lengths on average, %d at most"):format(sum / n, worst))
      end
    end)
  end)

  describe("a conic's time at a length (a Gauss model between exact lengths)", function()
    -- segment.c/invert.c: Newton on a Gauss-Legendre model of the length,
    -- every answer certified by an exact length; what is certified is the
    -- guarantee, whatever the model's error (sharp and thin conics included)
    it("the circle's time is its tangent half-angle parameter", function()
      -- the quarter circle (1,0) (1,1) (0,1), w = cos(pi/4): the point at
      -- angle phi from (1,0) has tan((phi - pi/4)/2) = (2t - 1) tan(pi/8)
      local r = math.sqrt(0.5)
      local L = math.pi / 2
      for _, tol in ipairs({1e-6, 1e-12, 1e-15}) do
        for _, f in ipairs({0.01, 0.3, 0.5, 0.77, 0.999}) do
          local t = arclen.segment_time("conic", {1, 0, 1, 1, 0, 1, r}, f * L, {tol = tol})
          local T = 0.5 + 0.5 * math.tan((f * L - math.pi / 4) / 2) / math.tan(math.pi / 8)
          -- the speed is near 1.1 everywhere: |t - T| V <= tol L, V <= 1.2
          assert(abs(t - T) * 1.2 <= 1.01 * tol * L + bound("conic") * L,
                 ("tol %g f %g: t %.17g T %.17g"):format(tol, f, t, T))
        end
      end
    end)
    it("|len(0, t) - s| <= tol L on sharp, thin and near-parabolic conics", function()
      local tris = {{0, 0, 5, 9, 10, 0}, {0, 0, 100, 1, 0, 0.5}, {0, 0, 1, 1e-3, 2, 0},
                    {3, 1, -4, 7, 9, 2}, {0, 0, 1e6, 1e6, 1, 0}}
      local worst = 0
      for _, p in ipairs(tris) do
        for _, w in ipairs({1e-6, 0.01, 0.7, 1, 1 + 2 ^ -40, 1.5, 100, 1e6}) do
          local seg = {p[1], p[2], p[3], p[4], p[5], p[6], w}
          local L = arclen.segment_length("conic", seg)
          -- (w = 1 + 2^-40 is the hyperbolic form near the parabola, acosh w
          -- ~ 1.3e-6: the Lua engine's t -> angle map once lost 1e-11 L
          -- there; the Lua engine is held to 1e-12, its floor)
          for _, tol in ipairs(H.engine == "c" and {1e-6, 1e-12, 1e-15} or {1e-6, 1e-12}) do
            for _, f in ipairs({1e-9, 0.05, 0.3, 0.5, 0.8, 1 - 1e-9}) do
              local t = arclen.segment_time("conic", seg, f * L, {tol = tol})
              local got = arclen.segment_length("conic", seg, {t1 = t})
              -- the exact lengths' own error (bound, above) besides tol; and
              -- where the speed is huge (w = 1e6 moves along a leg while t
              -- is within 1e-6 of 1) the nearest double t may miss by up to
              -- its ulp times the speed
              local dx, dy = arclen.segment_derivative("conic", seg, t)
              local ulp = 2 ^ (math.floor(math.log(max(t, 1e-300), 2)) - 52)
              local room = tol + bound("conic") + 2 * math.sqrt(dx * dx + dy * dy) * ulp / L
              local miss = abs(got - f * L) / L
              worst = max(worst, miss / room)
              assert(miss <= room, ("w %g tol %g f %g: miss %.3g, room %.3g"):format(w, tol, f, miss, room))
            end
          end
        end
      end
      assert(worst > 1e-3)   -- the check can fail: misses are not all 0
    end)
    it("random conics: within tol L, most without an exact length", function()
      -- the searches start from the cover's certified pieces (segment.c
      -- conic_times, invert.c arclen_seg_cover), no exact length unless a
      -- model fails; checked against the exact (Carlson) length of [0, t]
      local uniform = H.uniform(20261203)
      local fresh, calls = 0, 0
      for _ = 1, 150 do
        local seg = {}
        for q = 1, 6 do seg[q] = 10 * uniform() - 5 end
        seg[7] = 0.2 + 1.6 * uniform()
        local L = arclen.segment_length("conic", seg, {tol = 1e-15})
        for _, tol in ipairs(H.engine == "c" and {1e-12, 1e-15} or {1e-12}) do
          for _, f in ipairs({0.1, 0.5, 0.9}) do
            local t, info = arclen.segment_time("conic", seg, f * L, {tol = tol, info = true})
            local got = arclen.segment_length("conic", seg, {t1 = t, tol = 1e-15})
            local room = tol + bound("conic")
            assert(abs(got - f * L) / L <= room,
                   ("tol %g f %g: miss %.3g L"):format(tol, f, abs(got - f * L) / L))
            if info and tol == 1e-12 then
              calls = calls + 1
              if info.pieces == 0 then fresh = fresh + 1 end
            end
          end
        end
      end
      -- measured 2026-12-03: 441 of these 450 (13 before)
      if H.engine == "c" then assert(fresh >= 0.75 * calls, ("%d of %d"):format(fresh, calls)) end
    end)
  end)

  describe("point, derivative, sub", function()
    it("the speed at the reference times is |segment_derivative|", function()
      local function speed(kind, s, t)
        local d = {arclen.segment_derivative(kind, s, t)}
        local m, v = 0, 0
        for i = 1, #d do m = max(m, abs(d[i])) end
        for i = 1, #d do v = v + (d[i] / m) ^ 2 end   -- no overflow at 1e300
        return m * math.sqrt(v)
      end
      for _, row in ipairs(rows) do
        local s = seg_of(row)
        for _, q in ipairs({{"T33", "V33"}, {"T67", "V67"}}) do
          -- T is rounded to a double: where the speed changes fast (w =
          -- 38272 turns its corner within 1e-4 of t) its neighbours' speeds
          -- bracket the reference
          local T, want = tonumber(row[q[1]]), tonumber(row[q[2]])
          local a, b = speed(row.kind, s, T * (1 - EPS)), speed(row.kind, s, math.min(1, T * (1 + EPS)))
          local lo, hi = math.min(a, b) * (1 - 1e-13), math.max(a, b) * (1 + 1e-13)
          assert(H.relerr(speed(row.kind, s, T), want) <= 1e-13 or (want >= lo and want <= hi),
                 row.name)
        end
      end
    end)
    it("ends are the segment's first and last points exactly", function()
      for _, row in ipairs(rows) do
        local s, dim = seg_of(row), tonumber(row.dim)
        local n = ({line = 2, quad = 3, conic = 3})[row.kind]
        local p0 = {arclen.segment_point(row.kind, s, 0)}
        local p1 = {arclen.segment_point(row.kind, s, 1)}
        for k = 1, dim do
          assert.are.equal(s[k], p0[k])
          assert.are.equal(s[(n - 1) * dim + k], p1[k])
        end
      end
    end)
    it("a sub-range starts and ends at the points of t0 and t1; t0 > t1 reverses", function()
      for _, row in ipairs(rows) do
        local s, dim = seg_of(row), tonumber(row.dim)
        local n = ({line = 2, quad = 3, conic = 3})[row.kind]
        local sub = arclen.segment_sub(row.kind, s, 0.7, 0.2)
        local a = {arclen.segment_point(row.kind, s, 0.7)}
        local b = {arclen.segment_point(row.kind, s, 0.2)}
        local scale = size(s, row.kind, dim)
        for k = 1, dim do
          assert(abs(sub[k] - a[k]) <= 8 * EPS * scale, row.name)
          assert(abs(sub[(n - 1) * dim + k] - b[k]) <= 8 * EPS * scale, row.name)
        end
        if row.kind == "conic" then assert(sub[#sub] > 0) end
      end
    end)
    it("a quarter circle's point at 1/2 is on the circle at 45 degrees", function()
      local r = math.sqrt(0.5)
      local x, y = arclen.segment_point("conic", {1, 0, 1, 1, 0, 1, r}, 0.5)
      assert(abs(x - r) <= 2 * EPS and abs(y - r) <= 2 * EPS)
    end)
    it("a circle of four conics measures 2 pi whatever the tolerance", function()
      local r = math.sqrt(0.5)
      local q = {{1, 0, 1, 1, 0, 1}, {0, 1, -1, 1, -1, 0}, {-1, 0, -1, -1, 0, -1},
                 {0, -1, 1, -1, 1, 0}}
      for _, tol in ipairs({1e-15, 1e-6, 0.1}) do
        local sum = 0
        for _, p in ipairs(q) do
          p[7] = r
          sum = sum + arclen.segment_length("conic", p, {tol = tol})
        end
        -- r = sqrt(1/2) rounded: w is cos(pi/4) to 2^-53 relative, and the
        -- length's derivative in w is small (the arc stays near the circle)
        assert(H.relerr(sum, 2 * math.pi) <= (H.engine == "c" and 4e-15 or 1e-12))
      end
    end)
  end)

  describe("cubics go to arclen.length / arclen.time", function()
    local c = {0, 0, 1, 2, 3, 2, 4, 0}
    it("the same numbers, method and options included", function()
      assert.are.equal(arclen.length(c), arclen.segment_length("cubic", c))
      assert.are.equal(arclen.length(c, {tol = 1e-6, t0 = 0.1, t1 = 0.6}),
                       arclen.segment_length("cubic", c, {tol = 1e-6, t0 = 0.1, t1 = 0.6}))
      assert.are.equal(arclen.time(c, 2), arclen.segment_time("cubic", c, 2))
      local x, y = arclen.point(c, 0.3)
      local u, v = arclen.segment_point("cubic", c, 0.3)
      assert.are.equal(x, u); assert.are.equal(y, v)
    end)
    H.c_only(it, "method 'elliptic'")("method applies to cubics", function()
      assert.are.equal(arclen.length(c, {method = "elliptic"}),
                       arclen.segment_length("cubic", c, {method = "elliptic"}))
    end)
  end)

  describe("kinds in lengths, _segments and the walks", function()
    local r = math.sqrt(0.5)
    local segs = {{0, 0, 3, 4}, {3, 4, 4, 6, 6, 4}, {6, 4, 7, 5, 8, 4, 9, 3},
                  {9, 3, 9, 4, 8, 4, r}}
    local kinds, names = "LQCR", {"line", "quad", "cubic", "conic"}
    local function pack()
      local parts = {}
      for _, s in ipairs(segs) do
        local rec = {}
        for i = 1, 8 do rec[i] = s[i] or 0 end
        parts[#parts + 1] = string.pack("<dddddddd", unpack(rec))
      end
      return table.concat(parts)
    end
    local packed = string.pack and pack() or nil
    it("lengths(packed, {kinds =}) is each segment_length", function()
      if not packed then return end          -- Lua 5.1: no string.pack
      local L = arclen.lengths(packed, {kinds = kinds})
      for i, s in ipairs(segs) do
        assert.are.equal(arclen.segment_length(names[i], s), L[i])
      end
      local back = arclen._segments(packed, kinds, 2)
      for i, s in ipairs(segs) do assert.are.same(s, back[i]) end
    end)
    it("packed records walk by kind too; lengths3 reads 3D records by kind", function()
      if not packed then return end
      local L = arclen.lengths(packed, {kinds = kinds})
      local cum, acc = {[0] = 0}, 0
      for i = 1, #L do acc = acc + L[i]; cum[i] = acc end
      local ds = {0, acc / 3, acc / 2, acc}
      local ks, ts, ks2, ts2 = {}, {}, {}, {}
      arclen._walk_times(packed, cum, ds, 1e-12, false, ks, ts, kinds)
      arclen._walk_times(segs, cum, ds, 1e-12, false, ks2, ts2, kinds)
      assert.are.same(ks2, ks)
      assert.are.same(ts2, ts)
      local rec3 = {}
      local s3 = {{0, 0, 0, 1, 2, 2}, {0, 0, 0, 1, 0, 1, 0, 1, 1}, {1, 0, 0, 1, 1, 0, 0, 1, 0, r}}
      for _, s in ipairs(s3) do
        for i = 1, 12 do rec3[#rec3 + 1] = s[i] or 0 end
      end
      local L3 = arclen.lengths3(rec3, {kinds = "LQR"})
      assert.are.equal(3, L3[1])
      assert.are.equal(arclen.segment_length("quad", s3[2]), L3[2])
      assert(H.relerr(L3[3], math.pi / 2) <= (H.engine == "c" and 4e-15 or 1e-12))
    end)
    it("the walks dispatch by kind", function()
      local cum, acc = {[0] = 0}, 0
      for i, s in ipairs(segs) do
        acc = acc + arclen.segment_length(names[i], s)
        cum[i] = acc
      end
      local ds = {}
      for i = 0, 40 do ds[#ds + 1] = acc * i / 40 end
      local ks, ts = {}, {}
      arclen._walk_times(segs, cum, ds, 1e-12, false, ks, ts, kinds)
      for q, d in ipairs(ds) do
        local k, t = ks[q], ts[q]
        local got = cum[k - 1] + arclen.segment_length(names[k], segs[k], {t1 = t})
        assert(abs(got - d) <= 2e-12 * acc, ("distance %g: %g"):format(d, got))
      end
      local out = {}
      arclen._walk_samples(segs, cum, ds, 1e-12, out, nil, nil, kinds)
      for q = 1, #ds do
        local k = math.floor(out[q].time) + 1
        if k > #segs then k = #segs end
        local x, y = arclen.segment_point(names[k], segs[k], out[q].time - (k - 1))
        assert(abs(out[q].x - x) <= 1e-12 and abs(out[q].y - y) <= 1e-12)
      end
    end)
  end)

  describe("a conic sub-arc whose area is at its legs' rounding level", function()
    -- found by fuzz/fuzz_segment: the sub-arc [0, 0.066392] of this w = 9e-13
    -- conic has a + c - k of the order of its area; its area from d x h came
    -- out 0 (and the length inf) where the flatness test, from a x c, saw a
    -- conic
    it("is measured, and the pieces add up to the whole", function()
      local seg = {-1.5183436525095476e-179, -1.5183436525095476e-179,
                   -1.5424428511605764e-179, -1.5424428511605768e-179,
                   3.5044228282074424e-278, 0, 9.0949470177292824e-13}
      local L = arclen.segment_length("conic", seg)
      local a = arclen.segment_length("conic", seg, {t1 = 0.066392})
      local b = arclen.segment_length("conic", seg, {t0 = 0.066392})
      assert(a > 0 and b > 0)
      assert(H.relerr(a + b, L) <= (H.engine == "c" and 1e-14 or 1e-12), a + b .. " " .. L)
    end)
  end)

  describe("a conic whose speed's squares underflow", function()
    -- found by fuzz/fuzz_segment: w = 9e-13 beside legs of 1e-151 (not
    -- scaled: above 2^-500) made |N|^2 underflow, the speed 0 over a third
    -- of the arc, and the Gauss model certified a time 0.35% of L off
    it("its time at a length is within tol", function()
      local seg = {0, 8.8902337181024104e-162, 6.6146299031785094e-181,
                   8.5058996478694533e-151, 0, 0, 9.0949470177292824e-13}
      local L = arclen.segment_length("conic", seg)
      for _, f in ipairs({0.125, 0.25, 0.5, 0.9}) do
        local t = arclen.segment_time("conic", seg, f * L)
        local got = arclen.segment_length("conic", seg, {t1 = t})
        assert(abs(got - f * L) <= (1e-12 + bound("conic")) * L, f .. ": " .. abs(got - f * L) / L)
      end
    end)
  end)

  describe("a conic far smaller than its distance from the origin", function()
    -- found by fuzz/fuzz_segment: a 3D conic of legs 1.5e-323 at z =
    -- 6.7e-16 (w = 1e8) was searched on its legs as they were (its points,
    -- not its legs, set the scale), subnormal, and a time went back (2.4e-9
    -- after 3.0e-9).  Moved to P0 = 0 and scaled, a conic of subnormal legs
    -- at z = 1 is its copy at the origin 2^1070 times larger, to the bit:
    -- its times at the (subnormal) distances s are the copy's at s 2^1070
    for _, w in ipairs({0.7, 1e8}) do
      local seg = {0, 0, 1, 2^-1072, 2^-1072, 1, 2^-1071, 0, 1, w}
      local copy = {0, 0, 0, 0.25, 0.25, 0, 0.5, 0, 0, w}
      it("w = " .. w .. ": its times are its copy's, ascending", function()
        local Lc, prev = arclen.segment_length("conic", copy), 0
        for k = 1, 7 do
          local s = Lc * k / 8 * 2^-1070          -- subnormal: rounded
          local t = arclen.segment_time("conic", seg, s)
          local tc = arclen.segment_time("conic", copy, s * 2^535 * 2^535)
          assert(t == tc, k .. ": " .. t .. " against the copy's " .. tc)
          assert(t >= prev, k .. ": " .. t .. " after " .. prev)
          prev = t
        end
      end)
    end
  end)

  describe("the walk's sweep over one segment's distances", function()
    -- times.c hands a run of sorted distances to arclen_segment_times_of
    -- with the path's length of the segment; each search starts at the
    -- last answer (its time and length), each answer certified by an exact
    -- length or, on a conic, by the Gauss model's own error bound from the
    -- last exact one: so even a path length 1e-9 off leaves every time
    -- within tol
    local cases = {{"conic", "R", {0, 0, 100, 1, 0, 0.5, 30}},
                   {"conic", "R", {0, 0, 5, 9, 10, 0, 0.01}},
                   {"conic", "R", {3, 1, -4, 7, 9, 2, 0.7}},
                   -- w = 468: the speed steep near t = 1, where a 10-node
                   -- rule's nodes alone (rounded to t's ulp) cost 5e-14
                   {"conic", "R", {-3.4321088809520006, 8.1505298055708408, -3.7847012095153332,
                                   -1.809632945805788, 7.8112630918622017, 4.6219694893807173,
                                   468.28736855416804}},
                   {"quad", "Q", {0, 0, 100, 1, 0, 0.5}}}
    for _, c in ipairs(cases) do
      it(c[1] .. " (" .. table.concat(c[3], " ") .. "): 500 distances, tol 1e-15, a length 1e-9 off", function()
        local L = arclen.segment_length(c[1], c[3])
        local tol = H.engine == "c" and 1e-15 or 1e-12
        for _, off in ipairs({1, 1 + 1e-9, 1 - 1e-9}) do
          local ds = {}
          for i = 0, 499 do ds[#ds + 1] = L * 0.99 * (i / 499) ^ 2 end
          local ks, ts = {}, {}
          arclen._walk_times({c[3]}, {[0] = 0, L * off}, ds, tol, false, ks, ts, c[2])
          local prev = 0
          for q, d in ipairs(ds) do
            local t = ts[q]
            assert(t >= prev, "times ascend")
            prev = t
            local got = arclen.segment_length(c[1], c[3], {t1 = t})
            -- and the nearest double t's reach where the speed is steep
            local dx, dy = arclen.segment_derivative(c[1], c[3], t)
            local ulp = 2 ^ (math.floor(math.log(max(t, 1e-300), 2)) - 52)
            assert(abs(got - d) <= (tol + bound(c[1])) * L + 2 * math.sqrt(dx * dx + dy * dy) * ulp,
                   ("off %.9g distance %d: miss %.3g L"):format(off, q, abs(got - d) / L))
          end
        end
      end)
    end
  end)

  describe("bad input names its argument", function()
    local function err(f, ...) return H.error_of(f, ...) or "no error" end
    local cases = {
      {"unknown kind", {"spline", {0, 0, 1, 1}}, "#1 .*unknown segment kind 'spline'"},
      {"kind not a string", {3, {0, 0, 1, 1}}, "#1 .*segment kind expected"},
      {"not a table", {"line", 5}, "#2 .*segment expected"},
      {"wrong count", {"quad", {0, 0, 1, 1, 2}}, "#2 .*a quad has 6 %(2D%) or 9 %(3D%) numbers, got 5"},
      {"a cubic's count", {"cubic", {0, 0, 1, 1}}, "#2 .*a cubic has 8 %(2D%) or 12 %(3D%) numbers, got 4"},
      {"NaN", {"line", {0, 0 / 0, 1, 1}}, "#2 .*number 2 must be finite"},
      {"infinity", {"conic", {0, 0, 1, 1, 2, math.huge, 0.5}}, "#2 .*number 6 must be finite"},
      {"a string number", {"line", {0, "x", 1, 1}}, "#2 .*number 2 must be a number"},
      {"w = 0", {"conic", {0, 0, 1, 1, 2, 0, 0}}, "#2 .*weight .*must be positive"},
      {"w < 0", {"conic", {0, 0, 1, 1, 2, 0, -1}}, "#2 .*weight .*must be positive"},
      {"w infinite", {"conic", {0, 0, 1, 1, 2, 0, math.huge}}, "#2 .*must be finite"},
      {"bad tol", {"quad", {0, 0, 1, 1, 2, 0}, {tol = 2}}, "#3 .*tol"},
      {"bad option", {"quad", {0, 0, 1, 1, 2, 0}, {bogus = 1}}, "#3 .*unknown option"},
    }
    for _, c in ipairs(cases) do
      it("segment_length: " .. c[1], function()
        local msg = err(arclen.segment_length, unpack(c[2]))
        -- (Lua 5.1 and LuaJIT name the function '?' under pcall)
        assert(msg:find("bad argument") and msg:find(c[3]), msg)
      end)
    end
    it("segment_time, _point, _derivative, _sub: s, t, t0, t1", function()
      local q = {0, 0, 1, 1, 2, 0}
      assert.truthy(err(arclen.segment_time, "quad", q, 0 / 0):find("#3 .*length must be a number"))
      assert.truthy(err(arclen.segment_time, "quad", q, "x"):find("#3"))
      assert.truthy(err(arclen.segment_point, "quad", q, 1.5):find("#3 .*t must be in %[0, 1%]"))
      assert.truthy(err(arclen.segment_derivative, "quad", q, 0 / 0):find("#3 .*t must be"))
      assert.truthy(err(arclen.segment_sub, "quad", q, 0, 2):find("#4 .*t1 must be in"))
      assert.truthy(err(arclen.segment_sub, "line", {0, 0, 1}, 0, 1):find("#2 .*a line has 4"))
    end)
    it("lengths' kinds: the count and the letters", function()
      local p = {0, 0, 1, 1, 0, 0, 0, 0}
      assert.truthy(err(arclen.lengths, p, {kinds = "LL"}):find("#2 .*one letter per segment %(1%), got 2"))
      assert.truthy(err(arclen.lengths, p, {kinds = "X"}):find("#2 .*letter 1 is not L, Q, C or R"))
      assert.truthy(err(arclen.lengths, p, {kinds = 7}):find("#2 .*kinds must be a string"))
      local w = {0, 0, 1, 1, 2, 0, -1, 0}
      assert.truthy(err(arclen.lengths, w, {kinds = "R"}):find("#1 .*segment 1: conic weight must be positive"))
      assert.are.equal(math.sqrt(2), arclen.lengths(p, {kinds = "L"})[1])
    end)
    it("the walks' kinds: one letter per segment", function()
      local segs = {{0, 0, 1, 0}}
      local msg = err(arclen._walk_times, segs, {[0] = 0, 1}, {0.5}, 1e-12, false, {}, {}, "LQ")
      assert.truthy(msg:find("#8 .*one letter per segment"), msg)
      msg = err(arclen._walk_times, segs, {[0] = 0, 1}, {0.5}, 1e-12, false, {}, {}, "Z")
      assert.truthy(msg:find("#8 .*letter 1 is not"), msg)
    end)
  end)
end)

describe("a conic's derivative and tangent at large weights", function()
  -- (0,0) (1,1) (2,0) at t = 1/2: the numerator 2 (w/4 (1,1) + (2,0)/4 +
  -- w/4 (1,-1)) = (w + 1, 0) over D^2 = (w + 1)^2 / 4: (4/(w + 1), 0).  D^2
  -- overflowed from w ~ 1e154: 0, and p:tangent gave (0, -1)
  local H = require("helpers")
  local weights = {3, 1e100, 1e150}
  if H.engine == "c" then    -- the Lua engine takes w below 2^510
    for _, w in ipairs({1e160, 1e200, 1e300, 1.7e308}) do weights[#weights + 1] = w end
  end
  it("is 4/(w + 1) along x at t = 1/2", function()
    for _, w in ipairs(weights) do
      local dx, dy = arclen.segment_derivative("conic", {0, 0, 1, 1, 2, 0, w}, 0.5)
      local want = 4 / (w + 1)
      assert.is_true(math.abs(dx - want) <= 4 * 2 ^ -52 * want, ("w %g: %g"):format(w, dx))
      assert.are.equal(0, dy)
    end
  end)
  it("gives the path's tangents between the legs' directions, never 0 or NaN", function()
    -- the curve turns from (1, 1)/sqrt 2 to (1, -1)/sqrt 2 within ~1/w of
    -- t = 1/2, so a distance's t there (tol) may fall anywhere in the turn
    local r = math.sqrt(0.5)
    for _, w in ipairs(weights) do
      local p = arclen.path({{"conic", 0, 0, 1, 1, 2, 0, w}})
      local L = p:length()
      for _, s in ipairs({0, 0.25 * L, 0.5 * L, 0.75 * L, L}) do
        local tx, ty = p:tangent(s)
        local what = ("w %g, s %g: %g %g"):format(w, s / L, tx, ty)
        assert.is_true(math.abs(tx * tx + ty * ty - 1) <= 1e-15, what)
        assert.is_true(tx >= r - 1e-15 and math.abs(ty) <= r + 1e-15, what)
      end
      local tx, ty = p:tangent(0)
      assert.is_true(math.abs(tx - r) <= 1e-15 and math.abs(ty - r) <= 1e-15)
      tx, ty = p:tangent(L)
      assert.is_true(math.abs(tx - r) <= 1e-15 and math.abs(ty + r) <= 1e-15)
    end
  end)
end)
