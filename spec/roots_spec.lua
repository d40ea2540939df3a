-- Polynomial roots (src/roots.c) against mpmath (tools/ref_roots.py): each
-- root within the accuracy attainable once the coefficients are rounded to
-- double (column bounds, per root, computed by perturbing the coefficients
-- or from the roots' condition numbers).  The hostile rows (a subnormal
-- leading coefficient, +-1e308 in the middle, root groups up to 2^1330
-- apart) check the Newton-polygon split; roots beyond the double range are
-- expected as +-inf.
local arclen = require("arclen")
local H = require("helpers")

local function parse_roots(s)
  local out = {}
  for re, im in s:gmatch("([^,;]+),([^;]+)") do
    out[#out + 1] = {tonumber(re), tonumber(im)}
  end
  return out
end

local function parse_list(s)
  local out = {}
  for v in s:gmatch("[^;]+") do out[#out + 1] = tonumber(v) end
  return out
end

-- A part of a true root beyond the double range (tonumber gives +-inf)
-- must come out as that same infinity; the finite parts are measured.
local function dist(g, r)
  local d = {0, 0}
  for k = 1, 2 do
    if r[k] == math.huge or r[k] == -math.huge then
      if g[k] ~= r[k] then return math.huge end
    else
      d[k] = math.abs(g[k] - r[k])
    end
  end
  -- scaled where the squares would overflow (an error of 1e262 beside a
  -- root of 1e278 gave inf: "no computed root matches"); below, as ever
  -- (errors under 1e-162 square to 0: a factor whose product of roots is
  -- below the subnormal range, 5e-12 x 1e-321, cannot carry its tiny root)
  local s = math.max(d[1], d[2])
  if s > 1e150 then return s * math.sqrt((d[1] / s) ^ 2 + (d[2] / s) ^ 2) end
  return math.sqrt(d[1] ^ 2 + d[2] ^ 2)
end

-- Match every true root to its nearest unused computed root and assert
-- each error within its bound; extra(computed_root), if given, checks more.
local function match_roots(label, got, truth, bounds, extra)
  local used = {}
  for i, r in ipairs(truth) do
    local best, bi = math.huge, nil
    for j, g in ipairs(got) do
      if not used[j] and dist(g, r) < best then best, bi = dist(g, r), j end
    end
    assert.is_truthy(bi, ("%s root %d: no computed root matches"):format(label, i))
    used[bi] = true
    assert.is_true(best <= bounds[i], ("%s root %d (%.17g%+.17gi): error %.3g > bound %.3g"):format(
      label, i, r[1], r[2], best, bounds[i]))
    if extra then extra(got[bi]) end
  end
end

describe("roots", function()
  for _, row in ipairs(H.tsv("roots.tsv")) do
    it(row.id .. " (degree " .. row.deg .. "): every root within the attainable accuracy", function()
      local deg = tonumber(row.deg)
      local a = {}
      for _, k in ipairs({"a4", "a3", "a2", "a1", "a0"}) do
        if row[k] ~= "" then a[#a + 1] = tonumber(row[k]) end
      end
      local got = (deg == 4 and arclen.quartic or deg == 3 and arclen.cubic
                   or arclen.quadratic)(table.unpack(a))
      local truth, bounds = parse_roots(row.roots), parse_list(row.bounds)
      assert.are.equal(deg, #got)
      match_roots(row.id, got, truth, bounds)
    end)
  end

  it("quartic_factor splits a positive quartic into two real quadratics", function()
    -- (x^2 - 2x + 2)(x^2 + 4x + 13): roots 1 +- i, -2 +- 3i
    local p1, q1, p2, q2 = arclen.quartic_factor(1, 2, 7, -18, 26)
    local f = {{p1, q1}, {p2, q2}}
    table.sort(f, function(u, v) return u[1] < v[1] end)
    assert.is_true(math.abs(f[1][1] + 2) < 1e-14 and math.abs(f[1][2] - 2) < 1e-14)
    assert.is_true(math.abs(f[2][1] - 4) < 1e-14 and math.abs(f[2][2] - 13) < 1e-14)
  end)

  it("quartic_factor at the ends of the double range: factors beyond it are inf, never NaN", function()
    -- 5e-324 x^4 - 5 x^2 + 4: roots +-sqrt(0.8) and +-sqrt(5 / 5e-324) = +-1.006e162
    local p1, q1, p2, q2 = arclen.quartic_factor(5e-324, 0, -5, 0, 4)
    local f = {{p1, q1}, {p2, q2}}
    table.sort(f, function(u, v) return u[2] > v[2] end)
    assert.is_true(f[1][1] == 0 and math.abs(f[1][2] + 0.8) < 2e-16, tostring(f[1][2]))
    assert.are.equal(-math.huge, f[2][2])
    -- x^4 + 1e308 x^2 + 4 = (x^2 + 4e-308)(x^2 + 1e308) to rounding
    p1, q1, p2, q2 = arclen.quartic_factor(1, 0, 1e308, 0, 4)
    f = {{p1, q1}, {p2, q2}}
    table.sort(f, function(u, v) return u[2] < v[2] end)
    assert.is_true(f[1][1] == 0 and math.abs(f[1][2] / 4e-308 - 1) < 4e-16, tostring(f[1][2]))
    assert.is_true(f[2][1] == 0 and math.abs(f[2][2] / 1e308 - 1) < 4e-16, tostring(f[2][2]))
  end)

  it("quartic_factor's factors hold small roots beside a large one to their own scale", function()
    -- 2^-15 x^4 + 2 x^3 + 3 x^2 + 3: one root near -65536, three of size 1;
    -- a residual measured against the largest coefficient left the small
    -- factor's roots at 1.5e-11 (fuzz/fuzz_roots).  Bar: the harness's
    -- backward error, |p(z)| <= 4096 eps sum |a_k| |z|^k.
    local a = {3, 0, 3, 2, 2^-15}           -- a[k+1] is the coefficient of x^k
    local p1, q1, p2, q2 = arclen.quartic_factor(a[5], a[4], a[3], a[2], a[1])
    for _, f in ipairs({{p1, q1}, {p2, q2}}) do
      for _, z in ipairs(arclen.quadratic(1, f[1], f[2])) do
        local x, y, pr, pi, s = z[1], z[2], 0, 0, 0
        local az = math.sqrt(x * x + y * y)
        for k = 5, 1, -1 do
          pr, pi = pr * x - pi * y + a[k], pr * y + pi * x
          s = s * az + math.abs(a[k])
        end
        assert.is_true(math.sqrt(pr * pr + pi * pi) <= 4096 * 2^-52 * s,
          string.format("root %.17g%+.17gi: residual %g of scale %g", x, y,
            math.sqrt(pr * pr + pi * pi), s))
      end
    end
  end)

  it("lower degrees when leading coefficients vanish; bad input names the argument", function()
    assert.are.equal(1, #arclen.quadratic(0, 2, -4))
    assert.are.equal(2, #arclen.quartic(0, 0, 1, 0, -1))
    -- not tail calls: LuaJIT names only a function called by name from a live frame
    local function q(...) local r = arclen.quartic(...) return r end
    assert.matches("bad argument #3 to 'quartic' %(a2 must be finite%)",
      H.error_of(function() local r = q(1, 2, 1 / 0, 4, 5) return r end) or "")
    assert.matches("bad argument #1 to 'quartic_factor' %(a4 must not be 0",
      H.error_of(function() local r = arclen.quartic_factor(0, 1, 2, 3, 4) return r end) or "")
  end)
end)

-- The quartics that fuzz/fuzz_roots found
-- wrong, with exact roots (tools/ref_roots_fuzz.py, sympy CRootOf) and per
-- root the error attainable after the coefficients' rounding (a
-- near-double root's is ~sqrt(eps)).  Judged three ways: every root (of
-- arclen.quartic, and of quartic_factor's two factors) within that bound
-- of the truth; each with backward error |p(z)| <= 512 eps max|a_k| sum
-- |z|^k, the harness's bar (fuzz/fuzz_roots.c says why 512); and the
-- factors' product reproducing the quartic's coefficients to 512 eps of
-- their terms.
describe("roots: fuzz reproducers (roots_fuzz.tsv)", function()
  local EPS = 2 ^ -52
  -- |p(z)| and the harness's bar for it, both divided by max(1, |z|)^n
  -- (for |z| > 1 the reversed polynomial at 1/z: no overflow at 1e278)
  local function backward(a, z)     -- a[k+1]: coefficient of x^k
    local x, y, n = z[1], z[2], #a - 1
    local az = math.sqrt(x * x + y * y)
    local rev = az > 1
    if rev then x, y, az = x / az / az, -y / az / az, 1 / az end
    local pr, pi, s, m = 0, 0, 0, 0
    for i = n + 1, 1, -1 do
      local k = rev and n + 2 - i or i
      pr, pi = pr * x - pi * y + a[k], pr * y + pi * x
      s = s * az + 1
      m = math.max(m, math.abs(a[k]))
    end
    local tiny = 16 * 2 ^ -1074 * math.max(1, m) * (rev and az ^ n or 1)
    return math.sqrt(pr * pr + pi * pi), 512 * EPS * m * s + tiny
  end
  local function check_roots(id, what, a, got, truth, bounds)
    match_roots(id .. " " .. what, got, truth, bounds, function(g)
      local res, lim = backward(a, g)
      assert.is_true(res <= lim, ("%s %s root %.17g%+.17gi: residual %.3g > %.3g"):format(
        id, what, g[1], g[2], res, lim))
    end)
  end
  for _, row in ipairs(H.tsv("roots_fuzz.tsv")) do
    local c = {tonumber(row.a4), tonumber(row.a3), tonumber(row.a2), tonumber(row.a1), tonumber(row.a0)}
    local a = {c[5], c[4], c[3], c[2], c[1]}
    local truth, bounds = parse_roots(row.roots), parse_list(row.bounds)
    it(row.id .. " (was: " .. row.note .. "): quartic's roots", function()
      local got = arclen.quartic(table.unpack(c))
      assert.are.equal(4, #got)
      check_roots(row.id, "quartic", a, got, truth, bounds)
    end)
    it(row.id .. ": quartic_factor's factors", function()
      local q = {arclen.quartic_factor(table.unpack(c))}
      local got, finite = {}, true
      for j = 0, 1 do
        local p, r = q[2 * j + 1], q[2 * j + 2]
        if p ~= p or r ~= r then error("NaN factor coefficient") end
        if math.abs(p) == math.huge or math.abs(r) == math.huge then
          finite = false     -- by contract only beyond the double range
        else
          for _, z in ipairs(arclen.quadratic(1, p, r)) do got[#got + 1] = z end
        end
      end
      if finite then
        check_roots(row.id, "factor", a, got, truth, bounds)
        -- (x^2 + q1 x + q2)(x^2 + q3 x + q4) against a / a4, each equation
        -- to 512 eps of its terms, where terms below DBL_MIN (fewer than 53
        -- bits) count as DBL_MIN times the factors' size (-6.3e-326 is no
        -- double: q = -0; p = +-1e-322 come out as 7.9e-323 each)
        local m = {c[2] / c[1], c[3] / c[1], c[4] / c[1], c[5] / c[1]}
        local f = {q[1] + q[3], q[2] + q[4] + q[1] * q[3], q[1] * q[4] + q[3] * q[2], q[2] * q[4]}
        local w = {math.abs(q[1]) + math.abs(q[3]),
                   math.abs(q[2]) + math.abs(q[4]) + math.abs(q[1] * q[3]),
                   math.abs(q[1] * q[4]) + math.abs(q[3] * q[2]), math.abs(q[2] * q[4])}
        local qs = 1 + math.abs(q[1]) + math.abs(q[2]) + math.abs(q[3]) + math.abs(q[4])
        -- (polish-blind-underflow: the pair +-2.7e74 i has real part 3e-11,
        -- which the roots give as 0; the x^2 coefficient (7.1e148 for 0)
        -- needs it: it now comes from that equation)
        for k = 1, 4 do
          local lim = 512 * EPS * math.max(w[k] + math.abs(m[k]), 2 ^ -1022 * qs)
          assert.is_true(math.abs(f[k] - m[k]) <= lim, ("%s: x^%d coefficient %.17g, want %.17g (limit %.3g)"):format(
            row.id, 4 - k, f[k], m[k], lim))
        end
      else
        -- the one row whose factor must overflow: its real roots 2.83 and
        -- -8.4e307 pair up (q = their product, beyond DBL_MAX); the other
        -- factor is the complex pair
        assert.are.equal("factor-beyond-range", row.id)
        assert.are.equal(2, #got)
        local pt, pb = {}, {}
        for i, z in ipairs(truth) do
          if z[2] ~= 0 then pt[#pt + 1], pb[#pb + 1] = z, bounds[i] end
        end
        check_roots(row.id, "factor", a, got, pt, pb)
      end
    end)
  end
end)
