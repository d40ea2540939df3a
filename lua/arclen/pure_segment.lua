-- arclen.pure_segment -- the segments other than cubics in plain Lua, for
-- the Lua engine (arclen.pure): lines, quadratic Beziers and conics
-- (rational quadratics with weights (1, w, 1), Floater's eq. 1), 2D and
-- 3D: length, time at a length, point, derivative, sub-range.  The
-- numbers are checked by the caller (pure.lua); here c is a list of floats
-- in the contract's order (points, then w) and d the dimension.
--
-- Lengths: a line by a scaled hypot; a quadratic in closed form, every
-- difference rewritten as a sum of positive terms; a conic as the affine
-- image of a circular (w < 1) or hyperbolic (w > 1) arc, its speed in the
-- angle integrated by Gauss-Legendre on pieces bounded by the speed's
-- branch points (a circle's speed is
-- constant there, so its length is exact at any tol); w = 1 is a
-- quadratic.  Times: the inverse by safeguarded Newton steps on those
-- lengths, within tol * L.
local rules = require("arclen.pure_rules")

local abs, sqrt, log, huge = math.abs, math.sqrt, math.log, math.huge
local sin, cos, atan, exp, floor = math.sin, math.cos, math.atan, math.exp, math.floor

local M = {}

-- kind name -> {letter, points}; the letters of the packed kinds string.
M.KINDS = {line = {letter = "L", npts = 2}, quad = {letter = "Q", npts = 3},
           cubic = {letter = "C", npts = 4}, conic = {letter = "R", npts = 3, w = true}}
M.NAME = {L = "line", Q = "quad", C = "cubic", R = "conic"}

-- The count of numbers of a kind in d dimensions.
function M.count(kind, d)
  local k = M.KINDS[kind]
  return k.npts * d + (k.w and 1 or 0)
end

-- ---- small exact-enough helpers ----------------------------------------

local LN2 = log(2)

-- log(1 + x) to a few ulps (Goldberg's trick: the rounding of 1 + x cancels).
local function log1p(x)
  local u = 1 + x
  if u == 1 then return x end
  return log(u) * x / (u - 1)
end

local function asinh(x)
  local ax, r = abs(x), nil
  if ax > 1e8 then r = log(ax) + LN2          -- 1/(4 x^2) below an ulp
  else r = log1p(ax + ax * ax / (1 + sqrt(1 + ax * ax))) end
  return x < 0 and -r or r
end

-- sinh and cosh (gone from Lua 5.4's math): small |x| by the series, so
-- that sinh keeps its relative precision.
local function sinh_cosh(x)
  local ax = abs(x)
  if ax < 0.5 then
    local x2, term, sh = x * x, x, x
    for k = 1, 12 do
      term = term * x2 / ((2 * k) * (2 * k + 1))
      sh = sh + term
    end
    return sh, sqrt(1 + sh * sh)
  end
  local e = exp(ax)
  local sh, ch = (e - 1 / e) / 2, (e + 1 / e) / 2
  return x < 0 and -sh or sh, ch
end

local function tanh(x)
  local sh, ch = sinh_cosh(x)
  return sh / ch
end

local function tan(x) return sin(x) / cos(x) end

local atan2 = math.atan2 or math.atan          -- Lua 5.1's name, 5.4's

-- Error-free transformations (pure_rules): exact for operands below 2^995
-- (conic_scaled keeps the coordinates below 2^200).
local two_sum, two_prod = rules.two_sum, rules.two_prod

-- a1 b2 - a2 b1 to about an ulp of itself (each product exact, then the
-- difference of the high parts plus that of the low ones): the area of
-- nearly parallel legs, which the plain form rounds to eps of the products.
local function cross_exact(a1, a2, b1, b2)
  local p, pe = two_prod(a1, b2)
  local q, qe = two_prod(a2, b1)
  return (p - q) + (pe - qe)
end

-- |v| for a vector of d components, scaled so that no square over- or
-- underflows.
local function norm(v, d)
  local m = 0
  for i = 1, d do if abs(v[i]) > m then m = abs(v[i]) end end
  if m == 0 or m == huge then return m end
  local s = 0
  for i = 1, d do
    local q = v[i] / m
    s = s + q * q
  end
  return m * sqrt(s)
end
M.norm = norm

-- Point i (1-based) of c as a list of d numbers.
local function pt(c, i, d)
  local p = {}
  for j = 1, d do p[j] = c[(i - 1) * d + j] end
  return p
end

local function diff(p, q, d)
  local r = {}
  for j = 1, d do r[j] = p[j] - q[j] end
  return r
end

-- ---- lines -----------------------------------------------------------

local function line_length(c, d)
  return norm(diff(pt(c, 2, d), pt(c, 1, d), d), d)
end

-- Gauss-Legendre on [a, b] with rule R (nodes symmetric about 0).
local function gl(f, a, b, R)
  local c, h = (a + b) / 2, (b - a) / 2
  local s = 0
  for i = 1, #R.x do
    local x, wt = R.x[i], R.w[i]
    if x == 0 then s = s + wt * f(c)
    else s = s + wt * (f(c - h * x) + f(c + h * x)) end
  end
  return s * h
end

-- ---- quadratic Beziers -------------------------------------------------

-- The quadratic's speed 2 |A + t B| (A = P1 - P0, B = P2 - 2 P1 + P0) as
-- its coefficients a = B.B, b = A.B, c = A.A and K = |A x B|^2 = a c - b^2
-- (from the legs P1 - P0, P2 - P1, so that it does not cancel), all scaled
-- by 1/m^2 (m the largest leg component; the length is m times the
-- scaled one).
local function quad_setup(c, d)
  local A, E, B = {}, {}, {}
  local m = 0
  for j = 1, d do
    A[j] = c[d + j] - c[j]
    E[j] = c[2 * d + j] - c[d + j]
    if abs(A[j]) > m then m = abs(A[j]) end
    if abs(E[j]) > m then m = abs(E[j]) end
  end
  local q = {m = m}
  if m == 0 then return q end
  for j = 1, d do
    A[j] = A[j] / m
    E[j] = E[j] / m
    B[j] = E[j] - A[j]
  end
  local a, b, cc = 0, 0, 0
  for j = 1, d do
    a = a + B[j] * B[j]
    b = b + A[j] * B[j]
    cc = cc + A[j] * A[j]
  end
  local K
  if d == 2 then
    local x = A[1] * E[2] - A[2] * E[1]      -- A x B = A x E
    K = x * x
  else
    local x = A[2] * E[3] - A[3] * E[2]
    local y = A[3] * E[1] - A[1] * E[3]
    local z = A[1] * E[2] - A[2] * E[1]
    K = x * x + y * y + z * z
  end
  q.A, q.B, q.a, q.b, q.c, q.K, q.d = A, B, a, b, cc, K, d
  return q
end

-- The speed |dP/dt| at t (in the curve's units).
local function quad_speed(q, t)
  if q.m == 0 then return 0 end
  local v = {}
  for j = 1, q.d do v[j] = 2 * (q.A[j] + t * q.B[j]) end
  return q.m * norm(v, q.d)
end

-- The length of the quadratic between t0 <= t1:
--   L = [U R + K asinh(U / sqrt K)]_{U0}^{U1} / a^(3/2),  U = a t + b,
--   R = sqrt(U^2 + K),
-- as the integral of 2 sqrt((U^2 + K) / a) dt.  Ends of one sign: both
-- differences rewritten without cancellation (U1 - U0 = a (t1 - t0)):
--   U1 R1 - U0 R0 = (U1 - U0)(U1 + U0)(U1^2 + U0^2 + K) / (U1 R1 + U0 R0)
--   asinh(U1/k) - asinh(U0/k) = asinh((U1 - U0)(U1 + U0) / (U1 R0 + U0 R1))
-- (the second by asinh x - asinh y = asinh(x sqrt(1+y^2) - y sqrt(1+x^2))).
-- The two terms are each of the size of L but depend on K = |A x B|^2
-- strongly where L does not: when the speed's branch points (-b +- i
-- sqrt K)/a lie far from [t0, t1] (nearly straight, or a short piece),
-- the formula would lose the digits K lost to its cancellation.  There
-- the speed is analytic on the Bernstein ellipse rho >= 3 through them,
-- and 20-point Gauss-Legendre is within 64/15 rho^-38/(rho^2-1) < 4e-19
-- relative (Trefethen, ATAP Thm 19.3, whose rule has n + 1 = 20 points).
-- No turn at all (a below 1e-32 c): the chord.
local GL20 = rules[20]
local function quad_length(q, t0, t1)
  if q.m == 0 or t1 <= t0 then return 0 end
  local a, b, K = q.a, q.b, q.K
  if a <= 1e-32 * q.c then
    -- P(t1) - P(t0) = (t1 - t0)(2 A + (t1 + t0) B)
    local v, s = {}, t1 + t0
    for j = 1, q.d do v[j] = 2 * q.A[j] + s * q.B[j] end
    return q.m * (t1 - t0) * norm(v, q.d)
  end
  local hw = (t1 - t0) / 2
  local x = (-b / a - (t0 + hw)) / hw          -- the branch points in [-1, 1]'s frame
  local y = sqrt(K) / a / hw
  local sf = (sqrt((x - 1) ^ 2 + y * y) + sqrt((x + 1) ^ 2 + y * y)) / 2
  if sf >= 1.67 then                             -- rho = sf + sqrt(sf^2 - 1) >= 3
    return gl(function(t) return quad_speed(q, t) end, t0, t1, GL20)
  end
  local U0, U1, dU = a * t0 + b, a * t1 + b, a * (t1 - t0)
  local br
  if U0 < 0 and U1 > 0 then                    -- the vertex is inside: two sums
    local R0, R1 = sqrt(U0 * U0 + K), sqrt(U1 * U1 + K)
    br = U1 * R1 - U0 * R0
    if K > 0 then
      local k = sqrt(K)
      br = br + K * (asinh(U1 / k) - asinh(U0 / k))
    end
  else
    if U1 <= 0 then U0, U1 = -U1, -U0 end      -- reflect: 0 <= U0 < U1
    local R0, R1 = sqrt(U0 * U0 + K), sqrt(U1 * U1 + K)
    local sum = U1 + U0
    br = dU * sum * (U1 * U1 + U0 * U0 + K) / (U1 * R1 + U0 * R0)
    if K > 0 then br = br + K * asinh(dU * sum / (U1 * R0 + U0 * R1)) end
  end
  return q.m * br / (a * sqrt(a))
end

-- ---- conics -------------------------------------------------------------

-- E = w + sqrt(w^2 - 1) (= e^acosh w) for w > 1 as a double-double whose
-- high part is E rounded: w^2 - 1 exactly, its square root corrected by
-- one Newton step on the residual, the sum renormalised (near w = 1 the
-- step moves the root by up to 2^-26 of itself; conic_length.c's
-- exp_acosh).
local function exp_acosh(w)
  local ph, pe = two_prod(w, w)
  local qh, ql = two_sum(ph, -1)
  ql = ql + pe
  local sh = sqrt(qh)
  local p, e = two_prod(sh, sh)
  local r = ((qh - p) - e) + ql               -- w^2 - 1 - sh^2 (qh - p exact)
  local eh, el = two_sum(w, sh)
  return two_sum(eh, el + r / (2 * sh))
end

-- E^2 u - v for a double-double E^2 to about an ulp of the result: the
-- product u E2h exact, the difference by TwoSum.
local function e2u_minus_v(E2h, E2l, u, v)
  local p, pe = two_prod(u, E2h)
  local t, tl = two_sum(p, -v)
  return t + (tl + pe + u * E2l)
end

-- Past 1/4 of their terms (sz = |U| + |V|) one of kp = V + U, km = V - U
-- of a hyperbola cancels: a thin hyperbola, legs nearly parallel with |a|
-- ~ E^2 |c| or |c| ~ E^2 |a| (a = P1 - P0, c = P2 - P1), its arc far out
-- on one arm.  There (h = (a + c)/2, w = (E + 1/E)/2)
--   V + U = (E^2 c - a)/den,  V - U = (E^2 a - c)/den,  den = 2 E (w^2 - 1)
-- from the legs alone, each within about an ulp of itself however far it
-- cancels (doc/accuracy.md, thin hyperbolas: R = |kp||km|/2 fell to 0 at
-- w = 1000 and the arc was taken for a circle).  Returns true when kp and
-- km were so replaced.  (E^2 |a| must stay below 2^995 for the exact
-- products: beyond w ~ 2^349 the plain sums stay.)
local function thin_sums(a, c, w, wm1, kp, km, sz, d)
  if not (norm(kp, d) < 0.25 * sz or norm(km, d) < 0.25 * sz) then return false end
  local Eh, El = exp_acosh(w)
  local E2h, E2e = two_prod(Eh, Eh)
  if not (E2h < 2 ^ 700) then return false end
  local E2l = E2e + 2 * Eh * El
  local den = 2 * Eh * wm1
  for j = 1, d do
    kp[j] = e2u_minus_v(E2h, E2l, c[j], a[j]) / den
    km[j] = e2u_minus_v(E2h, E2l, a[j], c[j]) / den
  end
  return true
end

-- The conic (P0, P1, P2; w) as c + U cos th + V sin th, th in [-al, al],
-- al = acos w (w < 1), or c + U cosh th + V sinh th, th in [-al, al], al =
-- acosh w (w > 1), with m = (P0 + P2)/2, D = P1 - m, h = (P2 - P0)/2:
--   U = D w / (1 - w^2),  V = h / sqrt|1 - w^2|
-- (at th = 0 the curve's midpoint (m + w P1)/(1 + w), at the ends P0, P2).
-- The rational parameter is the half-angle one: tan(th/2) = (2t - 1)
-- tan(al/2) (tanh for w > 1).  The speed in th is |V cos th - U sin th|
-- (|V cosh th + U sinh th|), smooth on [-al, al]: constant on a circle.
local function conic_setup(c, d)
  local w = c[3 * d + 1]
  local k = {w = w, d = d}
  if w == 1 then
    k.quad = quad_setup(c, d)
    return k
  end
  local U, V = {}, {}
  local one = (1 - w) * (1 + w)              -- exact enough: 1 - w exact near 1
  local hyp = w > 1
  local s = 1 / sqrt(abs(one))
  local sc = w / one
  -- For w > 1 the speed is |(V + U) e^th + (V - U) e^-th| / 2 (kp, km:
  -- V + U and V - U); see thin_sums where one of them cancels.
  local kp, km = {}, {}
  local Dv, Hv, A, C = {}, {}, {}, {}
  for j = 1, d do
    local p0, p1, p2 = c[j], c[d + j], c[2 * d + j]
    local h = (p2 - p0) / 2
    local D = (p1 - p0) - h                   -- P1 - m, from the legs
    U[j] = D * w / one
    V[j] = h * s
    Dv[j], Hv[j], A[j], C[j] = D, h, p1 - p0, p2 - p1
    if hyp then kp[j], km[j] = V[j] + U[j], V[j] - U[j] end
  end
  -- |U x V|^2 = (sc s)^2 |D x h|^2 (D x h = a x c / 2) from the sides U
  -- and V came from, each product exact: U and V of a thin conic are
  -- nearly parallel and their own cross product would keep only eps of
  -- their size.
  local cr = {}
  local function crosses(P, Q, f)
    if d == 2 then cr[1] = f * cross_exact(P[1], P[2], Q[1], Q[2]) return end
    cr[1] = f * cross_exact(P[2], P[3], Q[2], Q[3])
    cr[2] = f * cross_exact(P[3], P[1], Q[3], Q[1])
    cr[3] = f * cross_exact(P[1], P[2], Q[1], Q[2])
  end
  crosses(Dv, Hv, 1)
  if hyp and thin_sums(A, C, w, -one, kp, km, abs(sc) * norm(Dv, d) + s * norm(Hv, d), d) then
    crosses(A, C, 0.5)                       -- a, c: the sides kp, km came from
  end
  local X = 0
  for j = 1, #cr do X = X + (sc * s * cr[j]) ^ 2 end
  k.kp, k.km = kp, km
  local al
  if hyp then al = log1p((w - 1) + sqrt(-one))           -- acosh w
  else al = 2 * atan(sqrt((1 - w) / (1 + w))) end        -- acos w, accurate near 1
  k.U, k.V, k.hyp, k.al = U, V, hyp, al
  k.th = hyp and tanh(al / 2) or tan(al / 2)
  if hyp then
    -- 1 - tanh(al/2) = 2/(E + 1), E = e^al = w + sqrt(w^2 - 1): the
    -- mapping of t near the ends without cancellation (th_of_t)
    local E = w + sqrt(-one)
    k.omt, k.th = 2 / (E + 1), ((w - 1) + sqrt(-one)) / (E + 1)
    local _, ch = sinh_cosh(al / 2)
    k.chh = ch
  end
  -- The speed's branch points.  With uu = |U|^2, vv = |V|^2, uv = U.V and
  -- X = |U x V|^2 = uu vv - uv^2:
  --   ellipse:   speed^2 = p + R cos(2 th - phi),  p = (vv + uu)/2,
  --              R = |((vv - uu)/2, -uv)|: zero at 2 th - phi = pi +- i eta,
  --              eta = acosh(p/R), p - R = X/(p + R);
  --   hyperbola: speed^2 = a0 + R cosh(2 th + psi), from |kp e^th + km
  --              e^-th|^2 / 4: a0 = kp.km/2 (= (vv - uu)/2), R = |kp||km|/2
  --              (= sqrt(b0^2 - c0^2), b0 = (vv + uu)/2, c0 = uv, which
  --              cancels where kp or km does), psi = log(|kp|/|km|) (=
  --              atanh(c0/b0)): zero at 2 th + psi = +- i eta, eta =
  --              acos(-a0/R) = 2 asin(sqrt((R + a0)/(2R))), (R + a0)(R - a0)
  --              = X, the smaller factor from the larger.
  -- Feet (real parts) and the half-height eta/2 of the branch points;
  -- none on a circle (R = 0: the speed is constant).
  local uu, vv, uv = 0, 0, 0
  for j = 1, d do
    uu, vv, uv = uu + U[j] * U[j], vv + V[j] * V[j], uv + U[j] * V[j]
  end
  k.feet = {}
  if not hyp then
    local p, R = (vv + uu) / 2, sqrt(((vv - uu) / 2) ^ 2 + uv * uv)
    k.p, k.R = p, R
    if R > 0 then
      local x = X / (p + R) / R                 -- p/R - 1
      local eta = log1p(x + sqrt(x * (x + 2)))  -- acosh(1 + x)
      local phi = atan2(-uv, (vv - uu) / 2)
      for j = -2, 2 do k.feet[#k.feet + 1] = (phi + math.pi) / 2 + j * math.pi end
      k.eta2 = eta / 2
    end
  else
    local a0, np, nm = 0, norm(kp, d), norm(km, d)
    for j = 1, d do a0 = a0 + kp[j] * km[j] / 2 end
    local R = np * nm / 2
    k.a0, k.R = a0, R
    if R > 0 then
      local psi = log(np / nm)
      local rpa = a0 <= 0 and X / (R - a0) or R + a0
      local eta = 2 * math.asin(math.min(1, sqrt(rpa / (2 * R))))
      k.feet[1] = -psi / 2
      k.eta2 = eta / 2
      k.psi = psi
    end
  end
  return k
end

local function conic_speed_th(k, th)
  local v = {}
  if k.hyp then
    if abs(th) < 0.5 then
      local sh, ch = sinh_cosh(th)
      for j = 1, k.d do v[j] = k.V[j] * ch + k.U[j] * sh end
    else
      local e = exp(th)
      local ie = 1 / e
      for j = 1, k.d do v[j] = (k.kp[j] * e + k.km[j] * ie) / 2 end
    end
  else
    local ct, st = cos(th), sin(th)
    for j = 1, k.d do v[j] = k.V[j] * ct - k.U[j] * st end
  end
  return norm(v, k.d)
end

-- The angle of the rational parameter t and back.
-- A hyperbola's ends move fast in t (the speed there is 2 w |P1 - P0|):
-- th = 2 atanh((2t - 1) T) = log(((1 - T) + 2 t T) / ((1 - T) + 2 (1 - t) T))
-- and t = (T + tanh(th/2)) / (2T) = sinh((al + th)/2) / (2 T cosh(al/2)
-- cosh(th/2)) (tanh a + tanh b = sinh(a + b) / (cosh a cosh b)), 1 - t
-- likewise with al - th, keep their digits near the ends.
local function th_of_t(k, t)
  if t == 0 then return -k.al end
  if t == 1 then return k.al end
  if k.hyp then
    -- the ratio minus one, 2 T (2t - 1) / (o + 2 (1 - t) T), through
    -- log1p when small: log of a ratio near 1 keeps only eps absolute,
    -- all of th's digits when al = acosh w is tiny (w just above 1)
    local T, o = k.th, k.omt
    local den = o + 2 * (1 - t) * T
    local x = 2 * T * (2 * t - 1) / den
    if abs(x) < 0.5 then return log1p(x) end
    return log((o + 2 * t * T) / den)
  end
  return 2 * atan((2 * t - 1) * k.th)
end

local function t_of_th(k, th)
  if th <= -k.al then return 0 end
  if th >= k.al then return 1 end
  local t
  if k.hyp then
    local _, ch = sinh_cosh(th / 2)
    local den = 2 * k.th * k.chh * ch
    if th <= 0 then t = sinh_cosh((k.al + th) / 2) / den
    else t = 1 - sinh_cosh((k.al - th) / 2) / den end
  else
    t = (1 + tan(th / 2) / k.th) / 2
  end
  if t < 0 then return 0 elseif t > 1 then return 1 end
  return t
end


local EPS = 2.220446049250313e-16

-- The conic's length between angles a < b, within rtol/4 of budget
-- (density times the width: the caller's share of tol L) by Gauss-Legendre
-- on pieces whose order meets Trefethen's bound (ATAP Thm 19.3, whose
-- rule has n + 1 points: for n points)
--   |E| <= (64/15) hw M rho^(2 - 2n) / (rho^2 - 1)
-- with rho inside the Bernstein ellipse through the nearest branch point
-- (conic_setup) and M >= speed on it; a piece no order up to 128 meets is
-- cut at a branch point's foot inside it, else in half.
local ORDERS = {8, 12, 16, 24, 32, 48, 64, 96, 128}
local MAX_CONIC_PIECES = 2000

-- max |speed| on the ellipse of parameter r about [c - hw, c + hw].
local function conic_bound(k, c, hw, r)
  local half_minor, half_major = hw * (r - 1 / r) / 2, hw * (r + 1 / r) / 2
  if k.hyp then
    local xr = math.max(abs(2 * (c - half_major) + k.psi), abs(2 * (c + half_major) + k.psi))
    local _, ch = sinh_cosh(xr)
    return sqrt(abs(k.a0) + k.R * ch)
  end
  local _, ch = sinh_cosh(2 * half_minor)
  return sqrt(k.p + k.R * ch)
end

local function conic_length_th(k, a, b, rtol, density)
  if b <= a then return 0, 0 end
  if not k.eta2 then
    if k.hyp then
      -- kp or km zero (a degenerate hyperbola: collinear points): the
      -- speed is |kp| e^th / 2 or |km| e^-th / 2
      local np, nm = norm(k.kp, k.d), norm(k.km, k.d)
      local shh = sinh_cosh((b - a) / 2)
      return shh * (np * exp((a + b) / 2) + nm * exp(-(a + b) / 2)), 1
    end
    return (b - a) * conic_speed_th(k, (a + b) / 2), 1   -- a circle (or a point)
  end
  if not density then
    -- a lower bound of the length over the width: the chord's,
    --   C(b) - C(a) = 2 sin(hw) (-sin(m) U + cos(m) V)      (ellipse)
    --              = 2 sinh(hw) (sinh(m) U + cosh(m) V)      (hyperbola)
    -- (m, hw the middle and half-width: no cancellation); a closed conic
    -- (P0 = P2) takes a quarter of the mean speed at 16 points
    -- (far from 0, sinh(m) U + cosh(m) V as (kp e^m + km e^-m)/2, as in
    -- conic_speed_th)
    local m, h = (a + b) / 2, (b - a) / 2
    local v = {}
    if k.hyp and abs(m) >= 0.5 then
      local shh, e = sinh_cosh(h), exp(m)
      for j = 1, k.d do v[j] = shh * (k.kp[j] * e + k.km[j] / e) end
    else
      local cu, cv
      if k.hyp then
        local sh, ch = sinh_cosh(m)
        local shh = sinh_cosh(h)
        cu, cv = 2 * shh * sh, 2 * shh * ch
      else
        cu, cv = -2 * sin(h) * sin(m), 2 * sin(h) * cos(m)
      end
      for j = 1, k.d do v[j] = cu * k.U[j] + cv * k.V[j] end
    end
    density = norm(v, k.d) / (b - a)
    if not (density > 0) then
      density = 0
      for i = 1, 16 do density = density + conic_speed_th(k, a + (i - 0.5) * (b - a) / 16) end
      density = density / 64
    end
  end
  local f = function(th) return conic_speed_th(k, th) end
  local total, evals, pieces = 0, 0, 0
  local stack = {{a, b}}
  while #stack > 0 do
    local top = table.remove(stack)
    local x, y = top[1], top[2]
    local c, hw = (x + y) / 2, (y - x) / 2
    -- the nearest branch point's rho
    local rho, foot = huge, nil
    for _, ft in ipairs(k.feet) do
      local ux, uy = (ft - c) / hw, k.eta2 / hw
      local sf = (sqrt((ux - 1) ^ 2 + uy * uy) + sqrt((ux + 1) ^ 2 + uy * uy)) / 2
      local r = sf + sqrt((sf - 1) * (sf + 1))
      if r < rho then rho, foot = r, ft end
    end
    local target = 0.25 * rtol * density * (y - x)
    -- the rounding's floor: the rule's own rounding is some eps of the
    -- piece's length, and density (y - x) is its share of the whole, where
    -- M hw can be far above both (a hyperbola's speed grows as e^|th| out
    -- to the ellipse's ends: 4 eps M hw let 8 points on [-3.6, 3.6] of w =
    -- 18 err 2e-10)
    local floor_err = 2 * EPS * density * (y - x)
    local done = false
    if rho > 1.05 then
      local r = 1 + (rho - 1) * 0.9
      local M = conic_bound(k, c, hw, r)
      for _, n in ipairs(ORDERS) do
        local bound = (64 / 15) * hw * M * r ^ (2 - 2 * n) / (r * r - 1)
        if bound <= target or bound <= floor_err then
          total = total + gl(f, x, y, rules[n])
          evals = evals + n
          done = true
          break
        end
      end
    end
    pieces = pieces + 1
    if not done then
      if pieces > MAX_CONIC_PIECES then
        total = total + gl(f, x, y, rules[128])
        evals = evals + 128
      else
        local cut = (foot and foot > x + 0.01 * (y - x) and foot < y - 0.01 * (y - x)) and foot or c
        stack[#stack + 1] = {cut, y}
        stack[#stack + 1] = {x, cut}
      end
    end
  end
  return total, evals
end

-- ---- the kinds' functions -----------------------------------------------

-- A conic's length is measured to 1e-14 whatever tol (as the C core's
-- exact one: its pieces' orders grow only with log(1/tol)); its times
-- keep tol.
local CONIC_RTOL = 1e-14

-- The point at t.
function M.point(kind, c, d, t)
  local out = {}
  if kind == "line" then
    local s = 1 - t
    for j = 1, d do out[j] = s * c[j] + t * c[d + j] end
  elseif kind == "quad" then
    local s = 1 - t
    local b0, b1, b2 = s * s, 2 * t * s, t * t
    for j = 1, d do out[j] = b0 * c[j] + b1 * c[d + j] + b2 * c[2 * d + j] end
  else  -- conic: N(t)/D(t), exact at the ends
    local w, s = c[3 * d + 1], 1 - t
    if t == 0 then for j = 1, d do out[j] = c[j] end return out end
    if t == 1 then for j = 1, d do out[j] = c[2 * d + j] end return out end
    local b0, b1, b2 = s * s, 2 * w * t * s, t * t
    local den = b0 + b1 + b2
    for j = 1, d do out[j] = (b0 * c[j] + b1 * c[d + j] + b2 * c[2 * d + j]) / den end
  end
  return out
end

-- The derivative in t (the rational one for a conic:
-- 2 [w (1-t)^2 (P1-P0) + t (1-t) (P2-P0) + w t^2 (P2-P1)] / D(t)^2).
function M.derivative(kind, c, d, t)
  local out = {}
  if kind == "line" then
    for j = 1, d do out[j] = c[d + j] - c[j] end
  elseif kind == "quad" then
    local s = 1 - t
    for j = 1, d do out[j] = 2 * (s * (c[d + j] - c[j]) + t * (c[2 * d + j] - c[d + j])) end
  else
    -- as 2 (W (s^2 a + t^2 c) + t s k / D) / D, W = w / D: D^2 overflows
    -- from w ~ 1e154, D never (the C core's form)
    local w, s = c[3 * d + 1], 1 - t
    local den = s * s + 2 * w * t * s + t * t
    local W = w / den
    for j = 1, d do
      local p0, p1, p2 = c[j], c[d + j], c[2 * d + j]
      out[j] = 2 * (W * (s * s * (p1 - p0) + t * t * (p2 - p1)) + t * s * (p2 - p0) / den) / den
    end
  end
  return out
end

-- The direction where the derivative vanishes (a unit vector's limit):
-- a quadratic's second derivative (its negative at t = 1, approached from
-- the left); a conic's chord P2 - P0 (P1 on an end point); a line has none.
function M.fallback_direction(kind, c, d, t)
  local v = {}
  if kind == "quad" then
    for j = 1, d do
      v[j] = c[2 * d + j] - 2 * c[d + j] + c[j]
      if t == 1 then v[j] = -v[j] end
    end
  elseif kind == "conic" then
    for j = 1, d do v[j] = c[2 * d + j] - c[j] end
  else
    for j = 1, d do v[j] = 0 end
  end
  return v
end

-- The segment c scaled by a power of two (exact: the lengths scale with
-- it) where the largest of its first n numbers (its coordinates) lies
-- outside (lo, hi), the rest (a conic's weight) kept; returns the segment
-- to measure and the factor its lengths carry, as two doubles whose
-- product it is (up to 2^1074: a subnormal segment).  Ordinary sizes are
-- left as they are.
local function pow2_scaled(c, n, lo, hi)
  local m = 0
  for j = 1, n do
    local v = abs(c[j])
    if v > m then m = v end
  end
  if m == 0 or (m > lo and m < hi) then return c, 1, 1 end
  local e = -floor(log(m) / LN2)
  local h = floor(e / 2)
  local f, f2 = 2 ^ h, 2 ^ (e - h)
  local out = {}
  for j = 1, #c do out[j] = j <= n and c[j] * f * f2 or c[j] end
  return out, f, f2
end

-- A conic far from 1 in size, so that the squares of its speed neither
-- underflow nor overflow.  One far smaller than its distance from the
-- origin (its legs below 2^-200, its points not) is moved to P0 = 0
-- first, so that its legs are not subnormal: each difference from P0 is
-- exact (Sterbenz) or one rounding of a tiny one, as the legs themselves.
local function conic_scaled(c, d)
  local n, m, ml = 3 * d, 0, 0
  for j = 1, n do
    local v, l = abs(c[j]), abs(c[j] - c[(j - 1) % d + 1])
    if v > m then m = v end
    if l > ml then ml = l end
  end
  if ml > 0 and ml < 2 ^ -200 and m >= 2 ^ -200 then
    local moved = {}
    for j = 1, n do moved[j] = c[j] - c[(j - 1) % d + 1] end
    moved[n + 1] = c[n + 1]
    c = moved
  end
  return pow2_scaled(c, n, 2 ^ -200, 2 ^ 200)
end

-- A line or quadratic whose legs may overflow (points from 2^1000; the C
-- core halves them).
local function big_scaled(kind, c, d)
  return pow2_scaled(c, (kind == "line" and 2 or 3) * d, 0, 2 ^ 1000)
end

-- The piece [t0, t1] (t0 < t1) of the conic c as a conic of its own legs
-- a', c', k', formed directly from the legs a = P1 - P0, c = P2 - P1, k =
-- P2 - P0 (conic_seg.c's piece_legs, which derives them): with the
-- blossom's weights W00, W01, W11 and H(t) = w (1-t)^2 a + t (1-t) k + w
-- t^2 c,
--   a' = (t1 - t0) H(t0) / (W01 W00),  c' = (t1 - t0) H(t1) / (W01 W11),
--   k' = (t1 - t0) [2w (1-t0)(1-t1) a + ((1-t1) t0 + (1-t0) t1) k
--                   + 2w t0 t1 c] / (W00 W11),   w' = W01 / sqrt(W00 W11);
-- as points of which two legs are exact and the longest is their sum.
-- Measured in the angle of the whole conic instead, a short piece lost
-- eps |th| of its width (1.7e-13 of [0.001, 0.002] of w = 1.5).
local function wfrac(w, x, W)            -- w x / W, no w x near 2^1024
  if w > 1 then return x / (W / w) end
  return w * x / W
end
local function piece_legs(c, d, t0, t1)
  local w = c[3 * d + 1]
  local W00 = (1 - t0) * (1 - t0) + 2 * w * t0 * (1 - t0) + t0 * t0
  local W11 = (1 - t1) * (1 - t1) + 2 * w * t1 * (1 - t1) + t1 * t1
  local W01 = (1 - t0) * (1 - t1) + w * ((1 - t0) * t1 + t0 * (1 - t1)) + t0 * t1
  local h = t1 - t0
  -- H(t) in positive terms: w (1 - 2t) a + t (w t + 1 - t) k for t <= 1/2,
  -- w (2t - 1) c + (1 - t) (w (1 - t) + t) k above; returns the
  -- coefficient of a or c, which (1: a, 2: c), and that of k
  local function terms(t)
    if t <= 0.5 then return w * (1 - 2 * t), 1, t * (w * t + (1 - t)) end
    return w * (2 * t - 1), 2, (1 - t) * (w * (1 - t) + t)
  end
  local f0, i0, g0 = terms(t0)
  local f1, i1, g1 = terms(t1)
  f0, g0 = h * (f0 / W00) / W01, h * (g0 / W00) / W01
  f1, g1 = h * (f1 / W11) / W01, h * (g1 / W11) / W01
  local ea = 2 * (h * (1 - t0) / W00) * wfrac(w, 1 - t1, W11)
  local ek = (h / W00) * (((1 - t1) * t0 + (1 - t0) * t1) / W11)
  local ec = 2 * (h * t1 / W11) * wfrac(w, t0, W00)
  local ap, cp, kp, la, lc, lk = {}, {}, {}, 0, 0, 0
  for j = 1, d do
    local p0, p1, p2 = c[j], c[d + j], c[2 * d + j]
    local leg = {p1 - p0, p2 - p1}
    local k = p2 - p0
    ap[j] = f0 * leg[i0] + g0 * k
    cp[j] = f1 * leg[i1] + g1 * k
    kp[j] = ea * leg[1] + ek * k + ec * leg[2]
    la, lc, lk = math.max(la, abs(ap[j])), math.max(lc, abs(cp[j])), math.max(lk, abs(kp[j]))
  end
  local out = {}
  for j = 1, d do
    if lk >= la and lk >= lc then          -- P1' = 0: a', c' exact
      out[j], out[d + j], out[2 * d + j] = -ap[j], 0, cp[j]
    elseif la >= lc then                   -- P2' = 0: c', k' exact
      out[j], out[d + j], out[2 * d + j] = -kp[j], -cp[j], 0
    else                                   -- P0' = 0: a', k' exact
      out[j], out[d + j], out[2 * d + j] = 0, ap[j], kp[j]
    end
  end
  out[3 * d + 1] = W01 / (sqrt(W00) * sqrt(W11))
  return out
end

-- The length; the second result counts the speed evaluations.
function M.length(kind, c, d, rtol)
  if rtol > CONIC_RTOL then rtol = CONIC_RTOL end
  local f, f2
  if kind == "line" or kind == "quad" then c, f, f2 = big_scaled(kind, c, d) end
  if kind == "line" then return line_length(c, d) / f / f2, 1 end
  if kind == "quad" then return quad_length(quad_setup(c, d), 0, 1) / f / f2, 1 end
  c, f, f2 = conic_scaled(c, d)
  local k = conic_setup(c, d)
  if k.quad then return quad_length(k.quad, 0, 1) / f / f2, 1 end
  local v, e = conic_length_th(k, -k.al, k.al, rtol)
  return v / f / f2, e
end

-- The length from t0 to t1 (t0 < t1); the second result counts the
-- evaluations.
function M.length_range(kind, c, d, rtol, t0, t1)
  if rtol > CONIC_RTOL then rtol = CONIC_RTOL end
  local f, f2
  if kind == "line" or kind == "quad" then c, f, f2 = big_scaled(kind, c, d) end
  if kind == "line" then return (t1 - t0) * line_length(c, d) / f / f2, 1 end
  if kind == "quad" then return quad_length(quad_setup(c, d), t0, t1) / f / f2, 1 end
  c, f, f2 = conic_scaled(c, d)
  if c[3 * d + 1] == 1 then return quad_length(quad_setup(c, d), t0, t1) / f / f2, 1 end
  local k = conic_setup(piece_legs(c, d, t0, t1), d)
  if k.quad then return quad_length(k.quad, 0, 1) / f / f2, 1 end
  local v, e = conic_length_th(k, -k.al, k.al, rtol)
  return v / f / f2, e
end

-- The times of the ascending distances s[1..] (each in [0, L], L the
-- segment's length as measured by M.length), each with |s(t) - s| <=
-- tol L; returns the times and the count of evaluations.
function M.times(kind, c, d, L, s, rtol)
  local ts, evals = {}, 0
  if kind == "line" then
    for q = 1, #s do
      local t = L > 0 and s[q] / L or 0
      ts[q] = t < 0 and 0 or (t > 1 and 1 or t)
    end
    return ts, #s
  end
  local len, speed, lo0, hi0, to_t
  do                                      -- in the scaled segment's units
    local f, f2
    if kind == "conic" then c, f, f2 = conic_scaled(c, d) else c, f, f2 = big_scaled(kind, c, d) end
    if f ~= 1 or f2 ~= 1 then
      local scaled = {}
      for q = 1, #s do scaled[q] = s[q] * f * f2 end
      -- a length beyond the doubles (L = inf) is finite there
      s, L = scaled, L < huge and L * f * f2 or M.length(kind, c, d, rtol)
    end
  end
  local goal_tol = 0.5 * rtol * L
  if kind == "quad" or (kind == "conic" and c[3 * d + 1] == 1) then
    local q = quad_setup(c, d)
    len = function(a, b) evals = evals + 1; return quad_length(q, a, b) end
    speed = function(t) return quad_speed(q, t) end
    lo0, hi0, to_t = 0, 1, function(t) return t end
  else
    local k = conic_setup(c, d)
    local density = L / (2 * k.al)
    len = function(a, b)
      local v, e = conic_length_th(k, a, b, rtol, density)
      evals = evals + e
      return v
    end
    speed = function(th) return conic_speed_th(k, th) end
    lo0, hi0 = -k.al, k.al
    to_t = function(th) return t_of_th(k, th) end
  end
  -- a sweep: the anchor (x, at distance sa) only moves forward
  local ax, sa = lo0, 0
  for q = 1, #s do
    local goal = s[q]
    if goal <= 0 then ts[q] = 0
    elseif goal >= L then ts[q] = 1
    else
      if goal < sa then ax, sa = lo0, 0 end       -- not ascending: start over
      local lo, hi = ax, hi0
      local v0 = speed(ax)
      local x = v0 > 0 and ax + (goal - sa) / v0 or (ax + hi) / 2
      if not (x > lo and x < hi) then x = (lo + hi) / 2 end
      local found = nil
      for _ = 1, 100 do
        local v = sa + len(ax, x)
        local f = v - goal
        if abs(f) <= goal_tol then found = x break end
        if f < 0 then
          lo, ax, sa = x, x, v                     -- the anchor moves on
        else
          hi = x
        end
        local sp = speed(x)
        local nx = sp > 0 and x - f / sp or nil
        if not nx or not (nx > lo and nx < hi) then nx = (lo + hi) / 2 end
        if nx == x or hi - lo <= 0 then found = x break end
        x = nx
      end
      ts[q] = to_t(found or x)
    end
  end
  return ts, evals
end

-- The piece from t0 to t1 (t0 > t1: reversed), of the same kind; the ends
-- exact where t is 0 or 1.
function M.sub(kind, c, d, t0, t1)
  local out = {}
  local function put(i, p) for j = 1, d do out[(i - 1) * d + j] = p[j] end end
  if kind == "line" then
    put(1, M.point(kind, c, d, t0))
    put(2, M.point(kind, c, d, t1))
    return out
  end
  if kind == "quad" then
    -- blossom b(u, v) = (1-u)(1-v) P0 + ((1-u) v + u (1-v)) P1 + u v P2
    local function blossom(u, v)
      local p = {}
      for j = 1, d do
        local p0, p1, p2 = c[j], c[d + j], c[2 * d + j]
        local a0, a1 = p0 + u * (p1 - p0), p1 + u * (p2 - p1)
        p[j] = a0 + v * (a1 - a0)
      end
      return p
    end
    put(1, M.point(kind, c, d, t0))
    put(2, blossom(t0, t1))
    put(3, M.point(kind, c, d, t1))
    return out
  end
  -- conic: the blossom of the homogeneous curve (P0, 1), (w P1, w), (P2, 1)
  local w = c[3 * d + 1]
  local function hblossom(u, v)
    local p, wt = {}, 0
    local a0w, a1w = 1 + u * (w - 1), w + u * (1 - w)
    wt = a0w + v * (a1w - a0w)
    for j = 1, d do
      local h0, h1, h2 = c[j], w * c[d + j], c[2 * d + j]
      local a0, a1 = h0 + u * (h1 - h0), h1 + u * (h2 - h1)
      p[j] = a0 + v * (a1 - a0)
    end
    return p, wt
  end
  local q0, w0 = hblossom(t0, t0)
  local q1, w1 = hblossom(t0, t1)
  local q2, w2 = hblossom(t1, t1)
  for j = 1, d do q0[j], q1[j], q2[j] = q0[j] / w0, q1[j] / w1, q2[j] / w2 end
  put(1, t0 == 0 and pt(c, 1, d) or t0 == 1 and pt(c, 3, d) or q0)
  put(2, q1)
  put(3, t1 == 0 and pt(c, 1, d) or t1 == 1 and pt(c, 3, d) or q2)
  out[3 * d + 1] = w1 / sqrt(w0 * w2)       -- weights (w0, w1, w2) -> (1, w', 1)
  return out
end

-- The conic as its own angle parametrization, for the specs.
M._conic_setup, M._th_of_t, M._t_of_th = conic_setup, th_of_t, t_of_th
M._floor = floor

return M
