-- conic_spec.lua -- Floater's cubic approximation of conics (seed 002):
-- the schemes, Props 2 and 13, Theorem 1, continuity at the break points,
-- the observed orders, the input forms and the exact conic lengths.
-- References: spec/data/conic_*.tsv from tools/ref_conic.py (mpmath).
local arclen = require "arclen"
local helpers = require "helpers"

local SCHEMES = {"quadratic", "g2", "midpoint", "c2", "g4"}
local sqrt, abs, max, min = math.sqrt, math.abs, math.max, math.min

-- ---- geometry used by the measurements (independent of the C code) ----

-- The rational quadratic of eq. (1) and its first two derivatives.
local function conic_eval(p, w, t)
  local x0, y0, x1, y1, x2, y2 = p[1], p[2], p[3], p[4], p[5], p[6]
  local n1x, n1y = 2 * (w * x1 - x0), 2 * (w * y1 - y0)
  local n2x, n2y = x0 - 2 * w * x1 + x2, y0 - 2 * w * y1 + y2
  local d1, d2 = 2 * (w - 1), 2 - 2 * w
  local D, D1, D2 = 1 + d1 * t + d2 * t * t, d1 + 2 * d2 * t, 2 * d2
  local function comp(n0, n1, n2)
    local N, N1, N2 = n0 + n1 * t + n2 * t * t, n1 + 2 * n2 * t, 2 * n2
    local U, U1 = N1 * D - N * D1, N2 * D - N * D2
    return N / D, U / (D * D), (U1 * D - 2 * U * D1) / D ^ 3
  end
  local x, dx, ddx = comp(x0, n1x, n2x)
  local y, dy, ddy = comp(y0, n1y, n2y)
  return x, y, dx, dy, ddx, ddy
end

-- A cubic c (8 numbers) and its derivatives up to the third.
local function cubic_eval(c, t)
  local s = 1 - t
  local function comp(a, b, cc, d)
    local p = s * s * s * a + 3 * s * s * t * b + 3 * s * t * t * cc + t * t * t * d
    local d1 = 3 * (s * s * (b - a) + 2 * s * t * (cc - b) + t * t * (d - cc))
    local d2 = 6 * (s * (cc - 2 * b + a) + t * (d - 2 * cc + b))
    local d3 = 6 * (d - 3 * cc + 3 * b - a)
    return p, d1, d2, d3
  end
  local x, dx, ddx, dddx = comp(c[1], c[3], c[5], c[7])
  local y, dy, ddy, dddy = comp(c[2], c[4], c[6], c[8])
  return x, y, dx, dy, ddx, ddy, dddx, dddy
end

-- A curve made of pieces, each a function t -> x, y, dx, dy, ddx, ddy on
-- [0, 1].  nearest(X) = min distance from the point X to the curve: the
-- best grid sample, then Newton on (C - X).C' = 0 in that piece and its
-- neighbours, clamped to [0, 1].
local function make_curve(pieces, per)
  local grid = {}
  for i, f in ipairs(pieces) do
    for k = 0, per do
      local x, y = f(k / per)
      grid[#grid + 1] = {i, k / per, x, y}
    end
  end
  -- the starting point of Newton must be in the right basin: a fine grid
  -- (conics with w far from 1 are parametrised far from uniformly)
  local curve = {pieces = pieces}
  local function newton(f, t, X, Y)
    for _ = 1, 30 do
      local x, y, dx, dy, ddx, ddy = f(t)
      local ex, ey = x - X, y - Y
      local g = ex * dx + ey * dy
      local dg = dx * dx + dy * dy + ex * ddx + ey * ddy
      local tn = t - g / dg
      if tn < 0 then tn = 0 elseif tn > 1 then tn = 1 end
      if abs(tn - t) < 1e-15 then t = tn break end
      t = tn
    end
    local x, y = f(t)
    return sqrt((x - X) ^ 2 + (y - Y) ^ 2)
  end
  function curve.nearest(X, Y)
    local best, bd = nil, math.huge
    for _, g in ipairs(grid) do
      local d = (g[3] - X) ^ 2 + (g[4] - Y) ^ 2
      if d < bd then best, bd = g, d end
    end
    local d = sqrt(bd)
    local i = best[1]
    d = min(d, newton(pieces[i], best[2], X, Y))
    if pieces[i - 1] then d = min(d, newton(pieces[i - 1], 1, X, Y)) end
    if pieces[i + 1] then d = min(d, newton(pieces[i + 1], 0, X, Y)) end
    return d
  end
  return curve
end

local function golden_max(f, lo, hi)
  local g = (sqrt(5) - 1) / 2
  local x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
  local f1, f2 = f(x1), f(x2)
  for _ = 1, 60 do
    if f1 > f2 then
      hi, x2, f2 = x2, x1, f1
      x1 = hi - g * (hi - lo); f1 = f(x1)
    else
      lo, x1, f1 = x1, x2, f2
      x2 = lo + g * (hi - lo); f2 = f(x2)
    end
  end
  return max(f1, f2)
end

-- max over the source curve of the distance to the target: dense samples,
-- then golden-section refinement at every local maximum.
local function one_sided(src, dst, per)
  local best = 0
  for _, f in ipairs(src.pieces) do
    local vals = {}
    local function dist(t) local x, y = f(t); return dst.nearest(x, y) end
    for k = 0, per do vals[k] = dist(k / per) end
    for k = 0, per do best = max(best, vals[k]) end
    for k = 1, per - 1 do
      if vals[k] >= vals[k - 1] and vals[k] >= vals[k + 1] and vals[k] > 0 then
        best = max(best, golden_max(dist, (k - 1) / per, (k + 1) / per))
      end
    end
  end
  return best
end

-- Hausdorff distance between the conic (p, w) and a list of cubics.
local function hausdorff(p, w, cubics, per)
  per = per or 24
  local cpieces = {}
  for i, c in ipairs(cubics) do
    cpieces[i] = function(t) return cubic_eval(c, t) end
  end
  -- the conic as one piece, sampled as finely as the spline
  local n = max(#cubics, 8)
  local rpieces = {}
  for i = 1, n do
    local a, b = (i - 1) / n, i / n
    rpieces[i] = function(t)
      local x, y, dx, dy, ddx, ddy = conic_eval(p, w, a + (b - a) * t)
      local h = b - a
      return x, y, dx * h, dy * h, ddx * h * h, ddy * h * h
    end
  end
  local fine = max(per, math.floor(8 * per / #cubics))
  local Q, R = make_curve(cpieces, fine), make_curve(rpieces, fine)
  return max(one_sided(Q, R, per), one_sided(R, Q, per))
end

local function pts(row)
  local p = {}
  for i, k in ipairs({"x0", "y0", "x1", "y1", "x2", "y2"}) do
    p[i] = assert(tonumber(row[k]), k)
  end
  return p
end

local function conic(p, w, opts)
  return arclen.conic({p[1], p[2]}, {p[3], p[4]}, {p[5], p[6]}, w, opts)
end

-- ---- the schemes ------------------------------------------------------

describe("conic schemes (Props 3, 4, 5, 8, 9)", function()
  -- the paper's formulas as printed (corrected as doc/papers.md reads them)
  local printed = {
    quadratic = function() return 2 / 3 end,
    g2 = function(w) return 2 / 3 * w * (sqrt(w * w + 3) - w) end,
    midpoint = function(w) return 4 / 3 * w / (1 + w) end,
    c2 = function(w) return 2 * w * w / (1 + 2 * w * w) end,
    g4 = function(w)
      return 2 * (6 * w * w + 1 - sqrt(3 * w * w + 1)) / (12 * w * w + 3)
    end,
  }
  it("lambda(w) matches the printed formulas on 0 < w < 4", function()
    for _, s in ipairs(SCHEMES) do
      for k = 1, 400 do
        local w = k / 100
        local lam = arclen.conic_scheme(s, w)
        assert.is_true(abs(lam - printed[s](w)) <= 1e-14, s .. " at w=" .. w)
      end
    end
  end)
  it("lambda(1) = 2/3 and lambda'(1) = 0, 1/3, 1/3, 4/9, 1/3 (Prop 12)", function()
    local slope = {quadratic = 0, g2 = 1 / 3, midpoint = 1 / 3, c2 = 4 / 9, g4 = 1 / 3}
    for _, s in ipairs(SCHEMES) do
      assert.is_true(abs(arclen.conic_scheme(s, 1) - 2 / 3) <= 1e-16, s)
      local h = 1e-5
      local d = (arclen.conic_scheme(s, 1 + h) - arclen.conic_scheme(s, 1 - h)) / (2 * h)
      assert.is_true(abs(d - slope[s]) <= 1e-9, s .. " slope " .. d)
    end
  end)
  it("G4: 0 < lambda < 1 for all w > 0; the positive root exceeds 1 (note 6)", function()
    for e = -60, 60 do
      local w = 10 ^ (e / 10)
      local lam = arclen.conic_scheme("g4", w)
      assert.is_true(lam > 0 and lam < 1, "w=" .. w)
      local plus = 2 * (6 * w * w + 1 + sqrt(3 * w * w + 1)) / (12 * w * w + 3)
      assert.is_true(plus > 1, "w=" .. w)
    end
  end)
  it("A, B match Prop 2's printed formulas", function()
    for _, s in ipairs(SCHEMES) do
      for _, w in ipairs({0.05, 0.3, 0.7071, 0.99, 1, 1.01, 2, 3.5, 10}) do
        local lam, A, B = arclen.conic_scheme(s, w)
        local A0 = 9 * lam ^ 2 - 12 * w * w * (1 - lam)
        local B0 = 18 * lam ^ 2 - 4 * w * w * (9 * (1 - lam) ^ 2 + 1)
        local scale = 1 + w * w
        assert.is_true(abs(A - A0) <= 1e-13 * scale, s .. " A w=" .. w)
        assert.is_true(abs(B - B0) <= 1e-13 * scale, s .. " B w=" .. w)
      end
    end
  end)
end)

-- ---- Prop 2 and Prop 13 -------------------------------------------------

describe("Prop 2: f_r(q(t)) = (1-t)^2 t^2 (A(1-t)^2 + B(1-t)t + A t^2)", function()
  it("holds for the module's cubics on random triangles", function()
    local seed = 12345
    local function rnd() seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648 end
    local worst = helpers.worst()
    for trial = 1, 60 do
      local p = {}
      for i = 1, 6 do p[i] = rnd() * 20 - 10 end
      local det = (p[3] - p[1]) * (p[6] - p[2]) - (p[4] - p[2]) * (p[5] - p[1])
      if abs(det) > 1 then
        local w = 10 ^ (rnd() * 3 - 1.5)
        for _, s in ipairs(SCHEMES) do
          local cubics = conic(p, w, {scheme = s})
          local _, A, B = arclen.conic_scheme(s, w)
          for k = 0, 20 do
            local t = k / 20
            local x, y = cubic_eval(cubics[1], t)
            -- barycentric coordinates in the triangle p0 p1 p2
            local t1 = ((x - p[1]) * (p[6] - p[2]) - (y - p[2]) * (p[5] - p[1])) / det
            local t2 = ((p[3] - p[1]) * (y - p[2]) - (p[4] - p[2]) * (x - p[1])) / det
            local t0 = 1 - t1 - t2
            local f = t1 * t1 - 4 * w * w * t0 * t2
            local u = 1 - t
            local g = u * u * t * t * (A * u * u + B * u * t + A * t * t)
            worst:add(abs(f - g) / (1 + w * w), trial .. s .. t)
          end
        end
      end
    end
    assert.is_true(worst.err <= 1e-12, worst.id .. ": " .. worst.err)
  end)
end)

describe("Prop 13: max |g| in closed form", function()
  it("agrees with dense sampling and golden-section refinement", function()
    local worst = helpers.worst()
    for _, s in ipairs(SCHEMES) do
      for e = -20, 20 do
        local w = 10 ^ (e / 10)
        local _, A, B, gn = arclen.conic_scheme(s, w)
        local function g(t)
          local u = 1 - t
          return abs(u * u * t * t * (A * u * u + B * u * t + A * t * t))
        end
        local n, best, vals = 2000, 0, {}
        for k = 0, n do vals[k] = g(k / n); best = max(best, vals[k]) end
        for k = 1, n - 1 do
          if vals[k] >= vals[k - 1] and vals[k] >= vals[k + 1] and vals[k] > 0 then
            best = max(best, golden_max(g, (k - 1) / n, (k + 1) / n))
          end
        end
        if best > 0 then
          worst:add(abs(gn - best) / best, s .. " w=" .. w)
        else
          assert.are.equal(0, gn)
        end
      end
    end
    assert.is_true(worst.err <= 1e-12, worst.id .. ": " .. worst.err)
  end)
end)

-- ---- Theorem 1 on a sweep -----------------------------------------------

describe("Theorem 1", function()
  it("is never violated on a sweep of weights, triangles, schemes, levels", function()
    local triangles = {
      {1, 0, 1, 1, 0, 1},             -- right isosceles
      {-3, 1, 2, 6, 5, -2},           -- skew
      {0, 0, 5, 0.4, 10, 0},          -- flat
    }
    local ws = {0.05, 0.2, 0.5, 0.8, 0.95, 0.999, 1.001, 1.05, 1.5, 2.5, 2.9, 5, 20}
    local worst, n, skipped = helpers.worst(), 0, 0
    for ti, p in ipairs(triangles) do
      for _, w in ipairs(ws) do
        for _, s in ipairs(SCHEMES) do
          for r = 0, 1 do
            local cubics, bound = conic(p, w, {scheme = s, level = r})
            local wr = w
            for _ = 1, r do wr = sqrt((1 + wr) / 2) end   -- eq. (4)
            local lam = arclen.conic_scheme(s, wr)
            if lam > 1 then
              assert.are.equal(math.huge, bound)   -- no theorem: no bound
              skipped = skipped + 1
            else
              local d = hausdorff(p, w, cubics, 16)
              n = n + 1
              worst:add(d / (bound + 1e-300),
                        ("tri%d w=%g %s r=%d d=%.3e bound=%.3e"):format(ti, w, s, r, d, bound))
              -- a rounding allowance of a few ulps of the coordinates
              assert.is_true(d <= bound + 1e-14,
                ("tri%d w=%g %s r=%d d=%.3e bound=%.3e"):format(ti, w, s, r, d, bound))
            end
          end
        end
      end
    end
    assert.is_true(n > 300)
    assert.is_true(skipped > 0)   -- mid-point with w > 3 has lambda > 1
    print(("\n  Theorem 1: %d cases, worst distance/bound %.4f (%s)"):format(n, worst.err, worst.id))
  end)
end)

-- ---- continuity at the break points (Props 7, 8, 9, 10) -------------------

local function curvature(c, t)
  local _, _, dx, dy, ddx, ddy, dddx, dddy = cubic_eval(c, t)
  local sp = sqrt(dx * dx + dy * dy)
  local cr = dx * ddy - dy * ddx
  local k = cr / sp ^ 3
  local dk_dt = (dx * dddy - dy * dddx) / sp ^ 3 - 3 * cr * (dx * ddx + dy * ddy) / sp ^ 5
  return k, dk_dt / sp, dx, dy, ddx, ddy
end

describe("break points", function()
  local cases = {
    {"ellipse", {1, 0, 1, 1, 0, 1}, 0.5},
    {"hyperbola", {0, 0, 2, 3, 5, 1}, 2},
    {"circle", {1, 0, 1, 1, 0, 1}, sqrt(0.5)},
  }
  for _, cs in ipairs(cases) do
    local name, p, w = cs[1], cs[2], cs[3]
    it("C1 and G2 for every scheme, C2 for c2, continuous dk/ds for g4 (" .. name .. ")", function()
      local jumps = {}
      for _, s in ipairs(SCHEMES) do
        local cubics = conic(p, w, {scheme = s, level = 3})
        local j = {c1 = 0, k = 0, c2 = 0, dk = 0}
        for i = 1, #cubics - 1 do
          local a, b = cubics[i], cubics[i + 1]
          local ka, dka, ax, ay, aax, aay = curvature(a, 1)
          local kb, dkb, bx, by, bbx, bby = curvature(b, 0)
          local sp = sqrt(ax * ax + ay * ay)
          j.c1 = max(j.c1, sqrt((ax - bx) ^ 2 + (ay - by) ^ 2) / sp)
          j.k = max(j.k, abs(ka - kb) / abs(ka))
          j.c2 = max(j.c2, sqrt((aax - bbx) ^ 2 + (aay - bby) ^ 2) / sp)
          j.dk = max(j.dk, abs(dka - dkb) / (abs(dka) + abs(dkb) + abs(ka) / sp))
        end
        jumps[s] = j
        assert.is_true(j.c1 <= 1e-13, s .. " C1 " .. j.c1)
        assert.is_true(j.k <= 1e-11, s .. " G2 " .. j.k)
      end
      assert.is_true(jumps.c2.c2 <= 1e-12, "C2 " .. jumps.c2.c2)
      assert.is_true(jumps.g4.dk <= 1e-9, "G3 " .. jumps.g4.dk)
      -- the measurements can fail: the other schemes are not C2 / G3
      assert.is_true(jumps.midpoint.c2 > 1e-4)
      assert.is_true(jumps.midpoint.dk > 1e-4)
      assert.is_true(jumps.c2.dk > 1e-4)
    end)
  end
end)

-- ---- orders, bounds and the measured distances (mpmath references) -----

describe("observed orders (spec/data/conic_hausdorff.tsv)", function()
  local rows = helpers.tsv("conic_hausdorff.tsv")
  local by = {}
  for _, row in ipairs(rows) do
    local key = row.conic .. " " .. row.scheme
    by[key] = by[key] or {}
    by[key][tonumber(row.level)] = row
  end
  it("the module's bound is >= the reference distance, and equals the reference's own bound", function()
    local worst = helpers.worst()
    for _, row in ipairs(rows) do
      local p, w = pts(row), tonumber(row.w)
      local _, bound = conic(p, w, {scheme = row.scheme, level = tonumber(row.level)})
      local h, b = tonumber(row.hausdorff), tonumber(row.bound)
      assert.is_true(h <= bound, row.conic .. " " .. row.scheme .. " " .. row.level)
      worst:add(helpers.relerr(bound, b), row.conic .. " " .. row.scheme .. " " .. row.level)
    end
    -- the reference finds max|g| by search: 1e-9 covers its 30-digit search
    assert.is_true(worst.err <= 1e-9, worst.id .. ": " .. worst.err)
  end)
  it("orders 4 (quadratic, c2) and 6 (g2, midpoint, g4) from r = 4 to 5", function()
    local want = {quadratic = 4, c2 = 4, g2 = 6, midpoint = 6, g4 = 6}
    local lines = {}
    for _, name in ipairs({"circle", "ellipse", "hyperbola"}) do
      for _, s in ipairs(SCHEMES) do
        local lv = by[name .. " " .. s]
        local d4, d5 = tonumber(lv[4].hausdorff), tonumber(lv[5].hausdorff)
        local order = math.log(d4 / d5) / math.log(2)   -- Lua 5.1: no base argument
        assert.is_true(abs(order - want[s]) <= 0.05, name .. " " .. s .. " order " .. order)
        lines[#lines + 1] = ("  %-9s %-9s r=0 %.3e  r=5 %.3e  order %.2f  d/bound(r=5) %.4f"):format(
          name, s, tonumber(lv[0].hausdorff), d5, order, d5 / tonumber(lv[5].bound))
      end
    end
    print("\n" .. table.concat(lines, "\n"))
  end)
  it("mid-point is the most accurate scheme at every level", function()
    for _, name in ipairs({"circle", "ellipse", "hyperbola"}) do
      for r = 0, 5 do
        local m = tonumber(by[name .. " midpoint"][r].hausdorff)
        for _, s in ipairs(SCHEMES) do
          assert.is_true(m <= tonumber(by[name .. " " .. s][r].hausdorff), name .. s .. r)
        end
      end
    end
  end)
  it("the module's cubics have the reference distances (levels 0-2)", function()
    local worst = helpers.worst()
    for _, row in ipairs(rows) do
      local r = tonumber(row.level)
      if r <= 2 then
        local p, w = pts(row), tonumber(row.w)
        local cubics = conic(p, w, {scheme = row.scheme, level = r})
        local d = hausdorff(p, w, cubics, 24)
        worst:add(helpers.relerr(d, tonumber(row.hausdorff)), row.conic .. " " .. row.scheme .. " " .. r)
      end
    end
    assert.is_true(worst.err <= 1e-7, worst.id .. ": " .. worst.err)
  end)
  it("the bound is sharp on the circle (distance/bound > 0.99 at r = 5)", function()
    local row = by["circle midpoint"][5]
    assert.is_true(tonumber(row.hausdorff) / tonumber(row.bound) > 0.99)
  end)
end)

describe("tol option", function()
  it("picks the smallest level whose bound is <= tol", function()
    local p = {1, 0, 1, 1, 0, 1}
    for _, s in ipairs(SCHEMES) do
      for _, tol in ipairs({1e-2, 1e-5, 1e-9, 1e-13}) do
        local cubics, bound, level = conic(p, 0.3, {scheme = s, tol = tol})
        assert.is_true(bound <= tol)
        assert.are.equal(2 ^ level, #cubics)
        if level > 0 then
          local _, b1 = conic(p, 0.3, {scheme = s, level = level - 1})
          assert.is_true(b1 > tol)
        end
      end
    end
  end)
end)

-- ---- anchors: kappa, fullcircle -----------------------------------------

describe("circle anchors", function()
  it("mid-point on a quarter circle is the kappa construction", function()
    local cubics, bound = conic({1, 0, 1, 1, 0, 1}, sqrt(0.5))
    local c = cubics[1]
    local kappa = 4 / 3 * (sqrt(2) - 1)        -- (4/3) tan(90 deg / 4)
    assert.is_true(abs(c[4] - kappa) <= 2e-16 and abs(c[5] - kappa) <= 2e-16)
    assert.are.equal(0.5522847498, tonumber(("%.10f"):format(c[4])))
    -- radial error: always outside, max 2.7253e-4 (the classic kappa handle's)
    local lo, hi = math.huge, -math.huge
    for k = 0, 2000 do
      local x, y = cubic_eval(c, k / 2000)
      local r = sqrt(x * x + y * y) - 1
      lo, hi = min(lo, r), max(hi, r)
    end
    assert.is_true(lo >= -1e-16)
    assert.are.equal(2.7253e-4, tonumber(("%.4e"):format(hi)))
    assert.is_true(hi <= bound)
  end)
  it("fullcircle is MetaPost's: 8 segments, handle 0.132608244919772", function()
    local fc = arclen.fullcircle()
    assert.are.equal(8, #fc)
    assert.are.equal(0.5, fc[1][1]); assert.are.equal(0, fc[1][2])
    for i = 1, 8 do
      local c, nx = fc[i], fc[i % 8 + 1]
      assert.are.equal(c[7], nx[1]); assert.are.equal(c[8], nx[2])
      local h1 = sqrt((c[3] - c[1]) ^ 2 + (c[4] - c[2]) ^ 2)
      local h2 = sqrt((c[7] - c[5]) ^ 2 + (c[8] - c[6]) ^ 2)
      assert.is_true(abs(h1 - 0.132608244919772) <= 1e-15, i .. ": " .. h1)
      assert.is_true(abs(h2 - 0.132608244919772) <= 1e-15, i .. ": " .. h2)
      -- counter-clockwise
      assert.is_true(c[1] * c[8] - c[2] * c[7] > 0)
    end
  end)
  it("fullcircle matches real mpost's control points (spec/data/conic_fullcircle_mpost.tsv)", function()
    -- committed data (tools/ref_conic.py with real mpost): missing is a failure
    local f = assert(io.open("spec/data/conic_fullcircle_mpost.tsv"))
    f:close()
    -- mpost builds pencircle's points in its 28-bit "fraction" type even
    -- in double mode: every value it prints is a multiple of 2^-28 (checked
    -- here), so it can differ from the exact construction by up to 2^-28
    -- (its handle is 35596755/2^28 = 0.13260824605822563).
    local fc = arclen.fullcircle()
    local worst = 0
    for _, row in ipairs(helpers.tsv("conic_fullcircle_mpost.tsv")) do
      local c = fc[tonumber(row.segment) + 1]
      for i, k in ipairs({"x0", "y0", "x1", "y1", "x2", "y2", "x3", "y3"}) do
        local v = tonumber(row[k])
        assert.are.equal(math.floor(v * 2 ^ 28), v * 2 ^ 28)
        worst = max(worst, abs(c[i] - v))
      end
    end
    assert.is_true(worst <= 2 ^ -28, worst)
    print(("\n  fullcircle vs mpost: max difference %.3e (MetaPost's 2^-28 rounding)"):format(worst))
  end)
end)

-- ---- input forms ---------------------------------------------------------

describe("input forms", function()
  it("three weights reduce to w1/sqrt(w0 w2) and trace the same curve", function()
    local p = {-1, 2, 3, 7, 6, 1}
    for _, ws in ipairs({{2, 3, 4.5}, {0.1, 5, 3}, {-1, -0.5, -2}, {1e-3, 1, 1e3}}) do
      local w = abs(ws[2]) / sqrt(abs(ws[1]) * abs(ws[3]))
      local a = conic(p, ws, {level = 2})
      local b = conic(p, w, {level = 2})
      for i = 1, #a do
        for k = 1, 8 do assert.is_true(abs(a[i][k] - b[i][k]) <= 1e-14 * 8) end
      end
      -- the three-weight rational curve lies on the normalised conic
      local det = (p[3] - p[1]) * (p[6] - p[2]) - (p[4] - p[2]) * (p[5] - p[1])
      for k = 0, 10 do
        local t = k / 10
        local b0, b1, b2 = (1 - t) ^ 2 * ws[1], 2 * t * (1 - t) * ws[2], t * t * ws[3]
        local x = (b0 * p[1] + b1 * p[3] + b2 * p[5]) / (b0 + b1 + b2)
        local y = (b0 * p[2] + b1 * p[4] + b2 * p[6]) / (b0 + b1 + b2)
        local t1 = ((x - p[1]) * (p[6] - p[2]) - (y - p[2]) * (p[5] - p[1])) / det
        local t2 = ((p[3] - p[1]) * (y - p[2]) - (p[4] - p[2]) * (x - p[1])) / det
        assert.is_true(abs(t1 * t1 - 4 * w * w * (1 - t1 - t2) * t2) <= 1e-13)
      end
    end
  end)
  it("ellipse arcs: pieces of at most 90 degrees on the ellipse", function()
    local cx, cy, rx, ry, rot = 3, -2, 5, 2, 0.4
    local function E(t)
      local X, Y = rx * math.cos(t), ry * math.sin(t)
      return cx + X * math.cos(rot) - Y * math.sin(rot), cy + X * math.sin(rot) + Y * math.cos(rot)
    end
    for _, arc in ipairs({{0, 2 * math.pi, 4}, {0.3, 1.2, 1}, {1, 1 + math.rad(91), 2},
                          {2, -1.5, 3}, {0, math.pi / 2, 1}}) do
      local a1, a2, n = arc[1], arc[2], arc[3]
      local cs = arclen.ellipse_conics(cx, cy, rx, ry, rot, a1, a2)
      assert.are.equal(n, #cs)
      local x, y = E(a1)
      assert.is_true(abs(cs[1][1] - x) <= 1e-14 and abs(cs[1][2] - y) <= 1e-14)
      x, y = E(a2)
      assert.is_true(abs(cs[n][5] - x) <= 1e-14 and abs(cs[n][6] - y) <= 1e-14)
      for i = 1, n do
        local c = cs[i]
        assert.is_true(abs(c[7] - math.cos((a2 - a1) / n / 2)) <= 1e-15)
        if i < n then assert.are.equal(c[5], cs[i + 1][1]); assert.are.equal(c[6], cs[i + 1][2]) end
      end
      local cubics, bound = arclen.ellipse_arc(cx, cy, rx, ry, rot, a1, a2, {level = 1})
      assert.are.equal(2 * n, #cubics)
      -- every piece within its bound of the ellipse
      for i = 1, n do
        local c = cs[i]
        local d = hausdorff(c, c[7], {cubics[2 * i - 1], cubics[2 * i]}, 16)
        assert.is_true(d <= bound + 1e-14)
      end
    end
  end)
  it("SVG arcs (F.6.5 with the F.6.6 radius correction)", function()
    -- the centre of an SVG arc, solved independently: in the frame where
    -- the ellipse is the unit circle, the centre is on the chord's bisector
    local function svg_centre(x1, y1, rx, ry, phi, fa, fs, x2, y2)
      local c, s = math.cos(math.rad(phi)), math.sin(math.rad(phi))
      local function to(x, y) return (c * x + s * y) / rx, (-s * x + c * y) / ry end
      local ax, ay = to(x1, y1)
      local bx, by = to(x2, y2)
      local mx, my = (ax + bx) / 2, (ay + by) / 2
      local hx, hy = (bx - ax) / 2, (by - ay) / 2
      local h2 = hx * hx + hy * hy
      local scale = 1
      if h2 > 1 then scale = sqrt(h2); hx, hy, mx, my = hx / scale, hy / scale, mx / scale, my / scale end
      local k = sqrt(max(0, 1 - hx * hx - hy * hy)) / sqrt(hx * hx + hy * hy)
      local sign = (fa == fs) and 1 or -1
      local ux, uy = mx + sign * k * hy, my - sign * k * hx
      rx, ry = rx * scale, ry * scale
      ux, uy = ux * rx, uy * ry
      return c * ux - s * uy, s * ux + c * uy, rx, ry
    end
    local cases = {
      {0, 0, 1, 1, 0, 0, 1, 2, 0},
      {0, 0, 2, 2, 0, 0, 0, 2, 0}, {0, 0, 2, 2, 0, 1, 0, 2, 0},
      {0, 0, 2, 2, 0, 0, 1, 2, 0}, {0, 0, 2, 2, 0, 1, 1, 2, 0},
      {10, 20, 30, 12, 30, 0, 1, 50, 35}, {10, 20, 30, 12, 30, 1, 0, 50, 35},
      {0, 0, 0.5, 0.25, 45, 0, 1, 3, 1},    -- radii too small: scaled up
      {1e6, 1e6, 5, 3, -20, 1, 1, 1e6 + 4, 1e6 + 2},
    }
    for ci, a in ipairs(cases) do
      local cubics, bound = arclen.svg_arc(a[1], a[2], a[3], a[4], a[5], a[6] == 1, a[7], a[8], a[9], {level = 2})
      assert.are.equal(a[1], cubics[1][1]); assert.are.equal(a[2], cubics[1][2])
      assert.are.equal(a[8], cubics[#cubics][7]); assert.are.equal(a[9], cubics[#cubics][8])
      local cx, cy, rx, ry = svg_centre(a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9])
      local c, s = math.cos(math.rad(a[5])), math.sin(math.rad(a[5]))
      local turn = 0
      for i, cb in ipairs(cubics) do
        for k = 0, 8 do
          local x, y = cubic_eval(cb, k / 8)
          local X, Y = (c * (x - cx) + s * (y - cy)) / rx, (-s * (x - cx) + c * (y - cy)) / ry
          -- within the bound (in units of the smaller radius) of the ellipse
          assert.is_true(abs(sqrt(X * X + Y * Y) - 1) * min(rx, ry) <= bound + 1e-9 * max(rx, ry),
                         "case " .. ci .. " piece " .. i)
        end
        local x0, y0 = cb[1] - cx, cb[2] - cy
        local x1, y1 = cb[7] - cx, cb[8] - cy
        turn = turn + (math.atan2 or math.atan)(x0 * y1 - y0 * x1, x0 * x1 + y0 * y1)
      end
      -- sweep flag 1 = increasing angle; large flag: more than 180 degrees
      assert.is_true((turn > 0) == (a[7] == 1), "case " .. ci .. " sweep")
      if a[3] >= 1 and ci ~= 8 then
        assert.is_true((abs(turn) > math.pi) == (a[6] == 1), "case " .. ci .. " large")
      end
    end
    -- F.6.2: equal endpoints omit the arc; a zero radius is a straight line
    local none = arclen.svg_arc(1, 1, 5, 5, 0, 0, 1, 1, 1)
    assert.are.equal(0, #none)
    local line = arclen.svg_arc(0, 0, 0, 5, 0, 0, 1, 3, 3)
    assert.are.same({{0, 0, 1, 1, 2, 2, 3, 3}}, line)
  end)
end)

-- ---- exact lengths --------------------------------------------------------

describe("conic_length", function()
  it("<= 1e-14 relative against mpmath (spec/data/conic_length.tsv)", function()
    local worst = helpers.worst()
    for _, row in ipairs(helpers.tsv("conic_length.tsv")) do
      local p = pts(row)
      local L = arclen.conic_length({p[1], p[2]}, {p[3], p[4]}, {p[5], p[6]}, tonumber(row.w))
      worst:add(helpers.relerr(L, tonumber(row.length)), row.name)
    end
    print(("\n  conic_length: worst relative error %.2e (%s)"):format(worst.err, worst.id))
    assert.is_true(worst.err <= 1e-14, worst.id .. ": " .. worst.err)
  end)
  it("an ellipse's perimeter from its four quarter conics", function()
    for _, row in ipairs(helpers.tsv("conic_perimeter.tsv")) do
      local rx, ry = tonumber(row.rx), tonumber(row.ry)
      local t = 0
      for _, c in ipairs(arclen.ellipse_conics(0, 0, rx, ry, 0.3, 0, 2 * math.pi)) do
        t = t + arclen.conic_length({c[1], c[2]}, {c[3], c[4]}, {c[5], c[6]}, c[7])
      end
      assert.is_true(helpers.relerr(t, tonumber(row.perimeter)) <= 1e-14, row.rx .. "x" .. row.ry)
    end
  end)
  it("the cubic splines' lengths against mpmath, and their error vs the exact length", function()
    local lines, worst = {}, helpers.worst()
    local geo = {circle = {{1, 0, 1, 1, 0, 1}, 0.7071067811865476},
                 ellipse = {{1, 0, 1, 1, 0, 1}, 0.5},
                 hyperbola = {{1, 0, 1, 1, 0, 1}, 2}}
    local prev = {}
    for _, row in ipairs(helpers.tsv("conic_spline_length.tsv")) do
      local g = geo[row.conic]
      local r = tonumber(row.level)
      local cubics = conic(g[1], g[2], {scheme = row.scheme, level = r})
      local L = 0
      for _, c in ipairs(cubics) do L = L + arclen.length(c) end
      worst:add(helpers.relerr(L, tonumber(row.length)), row.conic .. row.scheme .. r)
      local exact = arclen.conic_length({g[1][1], g[1][2]}, {g[1][3], g[1][4]}, {g[1][5], g[1][6]}, g[2])
      assert.is_true(helpers.relerr(exact, tonumber(row.exact)) <= 1e-14)
      local err = L - exact
      if row.scheme == "midpoint" then
        lines[#lines + 1] = ("  %-9s midpoint r=%d  spline - exact = %+.3e"):format(row.conic, r, err)
      end
      local key = row.conic .. row.scheme
      if r == 4 and abs(err) > 1e-12 then
        -- falls at least with order 4 (a factor 2^3.5 from r=3 to r=4)
        assert.is_true(abs(prev[key]) / abs(err) >= 2 ^ 3.5, key)
      end
      prev[key] = err
    end
    print("\n" .. table.concat(lines, "\n"))
    assert.is_true(worst.err <= 1e-12, worst.id .. ": " .. worst.err)
  end)
end)

-- ---- bad input -------------------------------------------------------------

describe("conic bad input", function()
  local E = helpers.error_of
  local P0, P1, P2 = {0, 0}, {1, 1}, {2, 0}
  it("names the argument", function()
    assert.matches("#4.*w must be > 0", E(arclen.conic, P0, P1, P2, 0))
    assert.matches("#4.*w must be > 0", E(arclen.conic, P0, P1, P2, -1))
    assert.matches("#4.*w must be finite", E(arclen.conic, P0, P1, P2, 0 / 0))
    assert.matches("#4.*w must be finite", E(arclen.conic, P0, P1, P2, math.huge))
    assert.matches("#4", E(arclen.conic, P0, P1, P2, "x"))
    assert.matches("#4.*one sign", E(arclen.conic, P0, P1, P2, {1, -1, 1}))
    assert.matches("#4.*one sign", E(arclen.conic, P0, P1, P2, {0, 1, 1}))
    assert.matches("#1.*p0 must be a point", E(arclen.conic, 3, P1, P2, 1))
    assert.matches("#3.*p2 must have finite", E(arclen.conic, P0, P1, {0 / 0, 1}, 1))
    assert.matches("#2.*collinear", E(arclen.conic, P0, {1, 0}, P2, 0.5))
    assert.matches("#2.*collinear", E(arclen.conic, P0, P0, P2, 0.5))
    assert.matches("#2.*collinear", E(arclen.conic, P0, P0, P0, 0.5))
    assert.matches("#5.*unknown scheme", E(arclen.conic, P0, P1, P2, 1, {scheme = "cubic"}))
    assert.matches("#5.*level must be an integer", E(arclen.conic, P0, P1, P2, 1, {level = 17}))
    assert.matches("#5.*level must be an integer", E(arclen.conic, P0, P1, P2, 1, {level = 1.5}))
    assert.matches("#5.*tol must be", E(arclen.conic, P0, P1, P2, 1, {tol = 0}))
    assert.matches("#5.*not both", E(arclen.conic, P0, P1, P2, 1, {tol = 1e-3, level = 2}))
    assert.matches("#5.*unknown option", E(arclen.conic, P0, P1, P2, 1, {lvl = 2}))
    assert.matches("#5.*not reached", E(arclen.conic, P0, P1, P2, 0.5, {scheme = "quadratic", tol = 1e-30}))
    assert.matches("#3.*rx must be > 0", E(arclen.ellipse_arc, 0, 0, 0, 1, 0, 0, 1))
    assert.matches("#7.*2%*pi", E(arclen.ellipse_arc, 0, 0, 1, 1, 0, 0, 7))
    assert.matches("#6.*large_arc", E(arclen.svg_arc, 0, 0, 1, 1, 0, 2, 1, 2, 0))
    assert.matches("#9.*y2 must be finite", E(arclen.svg_arc, 0, 0, 1, 1, 0, 0, 1, 2, 1 / 0))
    assert.matches("#2.*collinear", E(arclen.conic_length, P0, {1, 0}, P2, 0.5))
    assert.matches("#4.*w must be > 0", E(arclen.conic_length, P0, P1, P2, 0))
  end)
  it("huge and far-from-origin conics keep their accuracy", function()
    local base = {conic({0, 0, 1, 1, 2, 0}, 0.6, {level = 2})}
    for _, off in ipairs({1e8, -3e12}) do
      local moved = {conic({off, off, off + 1, off + 1, off + 2, off}, 0.6, {level = 2})}
      for i = 1, #base[1] do
        for k = 1, 8 do
          -- one rounding of the absolute coordinate
          assert.is_true(abs((moved[1][i][k] - off) - base[1][i][k]) <= abs(off) * 2.3e-16)
        end
      end
      assert.is_true(helpers.relerr(moved[2], base[2]) <= 1e-12)
    end
    for _, s in ipairs({1e-150, 1e150}) do
      local cs, b = conic({0, 0, s, s, 2 * s, 0}, 0.6, {level = 2})
      assert.is_true(helpers.relerr(b / s, base[2]) <= 1e-14)
      assert.is_true(helpers.relerr(cs[2][3] / s, base[1][2][3]) <= 1e-14)
    end
  end)
end)

-- ---- weights at the ends of the double range --------------------------------

describe("weights at the ends of the double range", function()
  -- w -> inf: the conic is the control polygon p0 p1 p2 (a degenerate
  -- hyperbola); w -> 0: the chord p0 p2.  Both are meaningful, and eq. (4)'s
  -- w_r = sqrt((1 + w)/2) brings the pieces' weights back near 1.
  local P0, P1, P2 = {1, 0}, {1, 1}, {0, 1}
  local function dist_polygon(x, y)   -- to p0 p1 (x = 1) and p1 p2 (y = 1)
    return min(abs(x - 1) + max(0, y - 1, -y), abs(y - 1) + max(0, x - 1, -x))
  end

  it("conic_scheme: lambda's limits (1 or 4/3 as w -> inf, 0 or 2/3 as w -> 0), no NaN", function()
    local limit_inf = {quadratic = 2 / 3, g2 = 1, midpoint = 4 / 3, c2 = 1, g4 = 1}
    local limit_0 = {quadratic = 2 / 3, g2 = 0, midpoint = 0, c2 = 0, g4 = 0}
    for _, s in ipairs(SCHEMES) do
      for _, w in ipairs({1e40, 1e155, 1e308}) do
        local l, A, B, g = arclen.conic_scheme(s, w)
        assert.is_true(abs(l - limit_inf[s]) <= 1e-15, s .. " lambda at " .. w)
        assert.is_true(A == A and B == B and g == g and g >= 0, s)
      end
      for _, w in ipairs({1e-40, 1e-200, 5e-324}) do
        local l, A, B, g = arclen.conic_scheme(s, w)
        assert.is_true(abs(l - limit_0[s]) <= 1e-39, s .. " lambda at " .. w)
        assert.is_true(A == A and B == B and g == g and g >= 0, s)
      end
    end
    -- ||g|| grows like w^2 (Prop 2: A, B = O(w^2)); it overflows to inf, never NaN
    local _, _, _, g = arclen.conic_scheme("midpoint", 1e150)
    assert.is_true(g > 1e298 and g < math.huge)
    assert.are.equal(math.huge, select(4, arclen.conic_scheme("midpoint", 1e308)))
  end)

  it("w = 1e308 follows the control polygon, w = 5e-324 the chord, to the bound", function()
    for _, s in ipairs(SCHEMES) do
      local cs, b = arclen.conic(P0, P1, P2, 1e308, {scheme = s, tol = 1e-6})
      assert.is_true(b <= 1e-6, s)
      for _, c in ipairs(cs) do
        for k = 1, 8 do assert.is_true(c[k] == c[k], s) end
        assert.is_true(dist_polygon(c[1], c[2]) <= 1e-12, s)   -- on the conic
      end
      cs, b = arclen.conic(P0, P1, P2, 5e-324, {scheme = s, tol = 1e-6})
      assert.is_true(b <= 1e-6, s)
      for _, c in ipairs(cs) do   -- the chord x + y = 1
        assert.is_true(abs(c[1] + c[2] - 1) <= 1e-12, s)
      end
    end
    -- level 0 at the limits: finite cubics, the bound finite (w -> 0) or inf
    local cs, b = arclen.conic(P0, P1, P2, 5e-324)
    assert.is_true(b == b and b < math.huge and cs[1][3] == 1 and abs(cs[1][4]) < 1e-300)
    cs, b = arclen.conic(P0, P1, P2, 1e308)
    assert.are.equal(math.huge, b)
    assert.is_true(cs[1][3] == 1 and abs(cs[1][4] - 4 / 3) < 1e-15)
  end)
end)

-- ---- pictures ---------------------------------------------------------------

describe("arclen.repro.conicplot", function()
  it("draws Figure 3 and the bound against the level from the module's numbers", function()
    local cp = require "arclen.repro.conicplot"
    local data = cp.lambda_data(40)
    for _, s in ipairs(SCHEMES) do
      assert.are.equal(40, #data[s])
      assert.is_true(abs(data[s][10][2] - arclen.conic_scheme(s, 1)) <= 1e-15)   -- w = 1
    end
    local text = cp.lambda_svg()
    assert.matches("^<svg", text)
    local lines = 0
    for _ in text:gmatch("<path ") do lines = lines + 1 end
    assert.is_true(lines >= 5)
    local lv = cp.level_data(3)
    for _, s in ipairs(SCHEMES) do
      for r = 2, 4 do assert.is_true(lv[s][r][2] < lv[s][r - 1][2]) end
    end
    assert.matches("^<svg", cp.levels_svg())
  end)
end)

describe("conic_length fuzz reproducers (chord <= length <= polygon)", function()
  -- legs measured after scaling by a power of two: no overflow at 1e185
  local function dist(a, b)
    local x, y = a[1] - b[1], a[2] - b[2]
    local m = math.max(math.abs(x), math.abs(y))
    if m == 0 then return 0 end
    return m * math.sqrt((x / m) ^ 2 + (y / m) ^ 2)
  end
  local cases = {
    {"spread 1e185, w = 22", {0, -5.44e185}, {-1, 22}, {129, -1}, 22},
    {"p0, p1 8 ulps apart, w = 1", {-1, -1.0000000000000018}, {-1, -1}, {10, 1}, 1},
    {"p0, p1 8 ulps apart, w = 1.5e8", {-1, -1.0000000000000018}, {-1, -1}, {10, 1}, 1.5e8},
    {"p1, p2 1 ulp apart, w = 1.5e8", {0, 0}, {1, 1}, {1.0000000000000002, 1}, 1.5e8},
    {"p1, p2 1 ulp apart, w = 1e4", {0, 0}, {1, 1}, {1.0000000000000002, 1}, 1e4},
    {"w = 1.5e8 isosceles", {0, 0}, {1, 1}, {2, 0}, 1.5e8},
  }
  for _, c in ipairs(cases) do
    it(c[1], function()
      local L = arclen.conic_length(c[2], c[3], c[4], c[5])
      local chord, poly = dist(c[2], c[4]), dist(c[2], c[3]) + dist(c[3], c[4])
      -- both bars at 1e-14 relative: the arc's own rounding (a few ulps),
      -- the reported failures were 1e-9 to 100% off
      assert.is_true(L >= chord * (1 - 1e-14), ("%.17g < chord %.17g"):format(L, chord))
      assert.is_true(L <= poly * (1 + 1e-14), ("%.17g > polygon %.17g"):format(L, poly))
    end)
  end
  it("w -> inf: the length tends to the polygon from below", function()
    local poly = 2 * math.sqrt(2)
    local prev = 0
    for _, w in ipairs({1e2, 1e4, 1e6, 1.5e8}) do
      local L = arclen.conic_length({0, 0}, {1, 1}, {2, 0}, w)
      assert.is_true(L > prev and L <= poly, w .. ": " .. L)
      prev = L
    end
    assert.is_true(poly - prev < 1e-7, "w = 1.5e8: " .. poly - prev)
  end)
end)

-- ---- the ends of the double range (found by fuzz/fuzz_conic) ---------------

describe("conic_length at the ends of the double range", function()
  -- References: tools/ref_conic.py extreme (quadrature on panels clustered
  -- at the speed's singularities, legs formed exactly from the doubles).
  -- The same 1e-14 bar as the ordinary conics: the sandwich of
  -- conic_length.c is within 1e-15 where it applies, the R_F/R_D forms
  -- within a few ulps elsewhere.
  it("<= 1e-14 relative against mpmath, or the overflow named (conic_length_extreme.tsv)", function()
    local worst, rows = helpers.worst(), 0
    for _, row in ipairs(helpers.tsv("conic_length_extreme.tsv")) do
      local p = pts(row)
      local args = {{p[1], p[2]}, {p[3], p[4]}, {p[5], p[6]}, tonumber(row.w)}
      if row.name:match("^overflow") then
        assert.matches("#1.*length exceeds the largest double",
                       helpers.error_of(arclen.conic_length, table.unpack(args)))
      else
        local L = arclen.conic_length(table.unpack(args))
        worst:add(helpers.relerr(L, tonumber(row.length)), row.name)
      end
      rows = rows + 1
    end
    assert.is_true(rows >= 15)
    print(("\n  conic_length extreme: worst relative error %.2e (%s)"):format(worst.err, worst.id))
    assert.is_true(worst.err <= 1e-14, worst.id .. ": " .. worst.err)
  end)
end)

describe("conic_length of nearly flat triangles near w = 1", function()
  -- References: tools/ref_conic.py flat (the same clustered quadrature,
  -- 40 and 50 digits agreeing to 1e-28).  The legs a = p1 - p0, c = p2 - p1
  -- and the chord p2 - p0 are each one rounding and do not close; the area
  -- and the semi-diameters must come from one triangle, or w = 1 -+ 2^-k
  -- (al = w/(1 - w^2) up to 2^52) multiplies that ulp: 1.2e-11 on the issue's
  -- case, 3.4e-10 at an apex 1.2e-7 off the chord.  Bar as for every conic.
  it("<= 1e-14 relative against mpmath (conic_length_flat.tsv)", function()
    local worst, rows = helpers.worst(), 0
    for _, row in ipairs(helpers.tsv("conic_length_flat.tsv")) do
      local p = pts(row)
      local L = arclen.conic_length({p[1], p[2]}, {p[3], p[4]}, {p[5], p[6]}, tonumber(row.w))
      worst:add(helpers.relerr(L, tonumber(row.length)), row.name)
      rows = rows + 1
    end
    assert.is_true(rows >= 200)
    print(("\n  conic_length flat: worst relative error %.2e (%s)"):format(worst.err, worst.id))
    assert.is_true(worst.err <= 1e-14, worst.id .. ": " .. worst.err)
  end)
end)

describe("conics whose legs are longer than the largest double", function()
  -- p0, p1, p2 = (-0.75, -0.75), (0.75, 0.75), (0.75, -0.75) times 2^1023: the
  -- leg p1 - p0 has components 1.5 * 2^1023 (finite) but length 1.9e308; the
  -- flatness test took that length as inf and called the conic collinear.
  -- References: tools/ref_conic.py's wide_length of the unscaled conic
  -- (1.556550901124038836689121 at w = 0.1, 1.501245372703549544033561 at
  -- w = 0.01), times 2^1023 (exact in doubles).
  local s = 2 ^ 1023
  local p0, p1, p2 = {-0.75 * s, -0.75 * s}, {0.75 * s, 0.75 * s}, {0.75 * s, -0.75 * s}
  it("are measured, to 1e-14 relative", function()
    for w, ref in pairs({[0.1] = 1.556550901124038836689121, [0.01] = 1.501245372703549544033561}) do
      local L = arclen.conic_length(p0, p1, p2, w)
      assert.is_true(helpers.relerr(L, ref * s) <= 1e-14, w .. ": " .. L)
    end
  end)
  it("and those of twice that overflow with the overflow named, not a collinear conic", function()
    assert.matches("#1.*length exceeds the largest double",
                   helpers.error_of(arclen.conic_length, {-1.5 * s, -1.5 * s}, {1.5 * s, 1.5 * s}, {1.5 * s, -1.5 * s}, 0.1))
  end)
  it("a truly collinear triangle of that size is still refused", function()
    assert.matches("collinear",
                   helpers.error_of(arclen.conic_length, p0, p1, {0.25 * s, 0.25 * s}, 0.1))
  end)
end)

describe("cubics and arcs near DBL_MAX", function()
  local function conic_of(p, w, o) return arclen.conic({p[1], p[2]}, {p[3], p[4]}, {p[5], p[6]}, w, o) end
  it("a conic scaled by 2^1020 (and 1.5 * 2^1022, whose legs are halved) gives the scaled cubics exactly", function()
    for _, s in ipairs(SCHEMES) do
      for _, sc in ipairs({{1, 2 ^ 1020}, {1.5, 2 ^ 1022}}) do
        local u = sc[1]
        local unit, ub = conic_of({-u, 0, 0, u, u, 0}, 0.7071067811865476, {scheme = s, level = 2})
        local big, bb = conic_of({-u * sc[2], 0, 0, u * sc[2], u * sc[2], 0}, 0.7071067811865476,
                                 {scheme = s, level = 2})
        for i = 1, #unit do
          for k = 1, 8 do assert.are.equal(unit[i][k] * sc[2], big[i][k]) end
        end
        assert.are.equal(ub * sc[2], bb)
      end
    end
  end)
  it("mid-point handles beyond DBL_MAX are an error naming the argument; other schemes stay inside", function()
    local p = {0, 0, 1.7e308, 0, 1.7e308, 1e308}
    assert.matches("#1.*control point of the cubics lies beyond the largest double",
                   helpers.error_of(conic_of, p, 100))
    for _, s in ipairs({"quadratic", "g2", "c2", "g4"}) do
      local cs = conic_of(p, 100, {scheme = s})
      for k = 1, 8 do assert.is_true(abs(cs[1][k]) <= 1.7e308, s) end
    end
  end)
  it("ellipse_arc: terms beyond DBL_MAX whose sum is not; an arc beyond it is named", function()
    -- rotated by 45 degrees, the conic's p1 = centre + r (cos 45 - sin 45,
    -- sin 45 + cos 45) / cos 45 = (0, -1.5e308 + 1.5e308 sqrt 2): its terms
    -- sum to 2.1e308, the point is 6.2e307
    local r, h = 1.5e308, sqrt(0.5)
    local cs = arclen.ellipse_arc(0, -r, r, r, math.pi / 4, 0, math.pi / 2, {level = 0})
    assert.are.equal(1, #cs)
    for k = 1, 8 do assert.is_true(cs[1][k] == cs[1][k] and abs(cs[1][k]) < math.huge) end
    assert.is_true(abs(cs[1][1] - r * h) <= 1e-15 * r and abs(cs[1][2] - (-r + r * h)) <= 1e-15 * r)
    assert.is_true(abs(cs[1][7] + r * h) <= 1e-15 * r and abs(cs[1][8] - (-r + r * h)) <= 1e-15 * r)
    -- the handles of the mid-point cubic: 4/3 tan(22.5 deg) r along the tangents
    local k = 4 / 3 * math.tan(math.pi / 8) * r
    assert.is_true(abs(cs[1][3] - (r * h - k * h)) <= 1e-15 * r and abs(cs[1][4] - (-r + r * h + k * h)) <= 1e-15 * r)
    assert.matches("#3.*beyond the largest double",
                   helpers.error_of(arclen.ellipse_arc, 1e308, 0, 1e308, 1, 0, 0, math.pi / 2))
  end)
  it("svg_arc: endpoints at -+1.7e308 (their difference overflows) give a finite half circle", function()
    local cs = arclen.svg_arc(-1.7e308, 0, 1.7e308, 1.7e308, 0, 0, 1, 1.7e308, 0, {level = 0})
    assert.are.equal(2, #cs)
    for _, c in ipairs(cs) do
      for k = 1, 8 do assert.is_true(c[k] == c[k] and abs(c[k]) <= 1.7e308 * (1 + 1e-15)) end
    end
    assert.are.equal(-1.7e308, cs[1][1])
    assert.is_true(abs(cs[1][8]) / 1.7e308 > 1 - 1e-15)   -- the top of the circle
  end)
end)
