-- arclen.pure_gauss -- the default method ("gauss") in plain Lua, for the
-- Lua engine (arclen.pure): the length of a plane cubic, and its inverse,
-- within tol * L, as the C core's src/gauss/ gives them (doc/method.md).
--
-- The speed |z'(t)| of z(t) = sum P_i B_i(t) is |A2 t^2 + A1 t + A0| for
-- the hodograph read as a complex quadratic, so the speed is |A2| |t - s1|
-- |t - s2| on the real line: its analytic continuation stops only at s1,
-- s2 and their conjugates (the branch points; closed form, no quartic).
-- A piece [c - h, c + h] gets the least Gauss-Legendre order n whose
-- Bernstein-ellipse bound
--     h (64/15) M rho^(2 - 2n) / (rho^2 - 1)       (Trefethen, ATAP Thm 19.3)
-- is within its share of the tolerance, rho the ellipse through the nearest
-- branch point and M >= |speed| on it; a piece no order up to 128 meets is
-- cut (at a branch point's foot, or graded towards it).  The C core bounds
-- the same pieces more tightly (by the branch cuts, bound.c) and so needs
-- fewer points; the guarantee is the same.
--
-- Units: the hodograph is scaled by a power of two (exact), so that the
-- result depends neither on the curve's size nor on where it sits; lengths
-- inside are in scaled units and leave multiplied by unit 2^exp.
local rules = require("arclen.pure_rules")

local abs, sqrt, floor, log = math.abs, math.sqrt, math.floor, math.log
local huge = math.huge

local M = {}

-- ---- powers of two, exact ----------------------------------------------

-- POW2[e] = 2^e for e in [-1074, 1023], by doubling and halving (exact; no
-- pow() from the host's libm).
local POW2 = {[0] = 1.0}      -- a float: integer doubling wraps (5.3+)
for e = 1, 1023 do POW2[e] = POW2[e - 1] * 2 end
for e = -1, -1074, -1 do POW2[e] = POW2[e + 1] / 2 end

-- x 2^e, exact unless the result over- or underflows: two steps when 2^e
-- itself is not a double.
local function mul_pow2(x, e)
  if e >= -1022 and e <= 1023 then return x * POW2[e] end
  local h = e > 0 and floor(e / 2) or -floor(-e / 2)
  return x * POW2[h] * POW2[e - h]
end

-- The e with 2^(e-1) <= x < 2^e for a finite x > 0 (frexp's exponent),
-- settled by exact comparisons, so that it does not depend on log().
local LN2 = log(2)
local function exponent(x)
  local e = floor(log(x) / LN2) + 1
  if e > 1024 then e = 1024 elseif e < -1073 then e = -1073 end
  for _ = 1, 4 do
    if e > -1073 and POW2[e - 1] > x then e = e - 1
    elseif e < 1024 and POW2[e] <= x then e = e + 1
    else break end
  end
  return e
end

-- ---- the hodograph -------------------------------------------------------

-- Error-free transformations (pure_rules): exact for operands below 2^995
-- (tame() sees to that).
local two_sum, two_prod = rules.two_sum, rules.two_prod
-- Double-double (hi, lo) sum and product.
local function dd_add(xh, xl, yh, yl)
  local s, e = two_sum(xh, yh)
  return two_sum(s, e + (xl + yl))
end
local function dd_mul(xh, xl, yh, yl)
  local p, e = two_prod(xh, yh)
  return two_sum(p, e + (xh * yl + xl * yh))
end

-- Coordinates beyond this may overflow in differences, or in Veltkamp's
-- split (which multiplies by 2^27): such a curve is scaled by 2^-64 first
-- (exact), as the C core does beyond 1e300 (cubic.c).
local HUGE_COORD = 1e290

-- The hodograph of the plane cubic c (8 numbers) over [t0, t1]: for the
-- whole curve z'(t) = A2 t^2 + A1 t + A0 on [0, 1] (A0 = 3 d0, A1 = 6 (d1 -
-- d0), A2 = 3 (d2 - 2 d1 + d0), d_i = P_{i+1} - P_i); for a part, about
-- its middle tc on [-1, 1]: H(u) = z'(tc) + hw z''(tc) u + hw^2 A2 u^2 (t =
-- tc + hw u), formed in double-double from the exact differences, so that
-- a part beside a near-cusp keeps its relative precision.  Returns h =
-- {x2, x1, x0, y2, y1, y0 (the scaled coefficients), lo, hi (the range
-- of the variable), unit, exp (a length over [lo, hi] in scaled units,
-- times unit 2^exp, is the curve's)}, or nil when the hodograph is zero
-- (a point).
function M.hodograph(c, t0, t1)
  local pre = 1.0
  for i = 1, 8 do
    if abs(c[i]) > HUGE_COORD then pre = POW2[-64] end
  end
  local coef, lo, hi, unit = {}, 0, 1, 1
  for k = 1, 2 do
    local p0, p1, p2, p3 = c[k] * pre, c[k + 2] * pre, c[k + 4] * pre, c[k + 6] * pre
    if t0 == 0 and t1 == 1 then
      local d0, d1, d2 = p1 - p0, p2 - p1, p3 - p2
      coef[3 * k - 2] = 3 * ((d2 - d1) - (d1 - d0))
      coef[3 * k - 1] = 6 * (d1 - d0)
      coef[3 * k] = 3 * d0
    else
      local hw = (t1 - t0) / 2
      local tch, tcl = two_sum(t0, hw)
      local d0h, d0l = two_sum(p1, -p0)
      local d1h, d1l = two_sum(p2, -p1)
      local d2h, d2l = two_sum(p3, -p2)
      local e1h, e1l = dd_add(d1h, d1l, -d0h, -d0l)
      local e2h, e2l = dd_add(d2h, d2l, -d1h, -d1l)
      local a0h, a0l = dd_mul(3, 0, d0h, d0l)
      local a1h, a1l = dd_mul(6, 0, e1h, e1l)
      local a2h, a2l = dd_mul(3, 0, dd_add(e2h, e2l, -e1h, -e1l))
      -- z'(tc) = a0 + tc (a1 + tc a2), z''(tc) = a1 + 2 tc a2
      local vh, vl = dd_mul(tch, tcl, a2h, a2l)
      vh, vl = dd_add(a1h, a1l, vh, vl)
      vh, vl = dd_mul(tch, tcl, vh, vl)
      vh, vl = dd_add(a0h, a0l, vh, vl)
      local wh, wl = dd_mul(tch, tcl, a2h, a2l)
      wh, wl = dd_add(a1h, a1l, 2 * wh, 2 * wl)
      coef[3 * k - 2] = (a2h + a2l) * hw * hw
      coef[3 * k - 1] = (wh + wl) * hw
      coef[3 * k] = vh + vl
      lo, hi, unit = -1, 1, hw
    end
  end
  local big = 0
  for i = 1, 6 do
    local v = coef[i]
    if not (v - v == 0) then             -- inf or NaN: never a silent zero
      error("arclen.pure: the hodograph overflowed (please report the curve)", 0)
    end
    if abs(v) > big then big = abs(v) end
  end
  if big == 0 then return nil end
  local e = exponent(big)
  for i = 1, 6 do coef[i] = mul_pow2(coef[i], -e) end
  return {x2 = coef[1], x1 = coef[2], x0 = coef[3], y2 = coef[4], y1 = coef[5],
          y0 = coef[6], lo = lo, hi = hi, unit = unit,
          exp = e + (pre == 1.0 and 0 or 64)}
end

-- The speed at t (scaled units).
local function speed(h, t)
  local x = (h.x2 * t + h.x1) * t + h.x0
  local y = (h.y2 * t + h.y1) * t + h.y0
  return sqrt(x * x + y * y)
end

-- |z(b) - z(a)| from the antiderivative of the hodograph: a lower bound of
-- the length between (for the tolerance's share).
local function chord(h, a, b)
  local x3, x2, y3, y2 = h.x2 / 3, h.x1 / 2, h.y2 / 3, h.y1 / 2
  local dx = ((x3 * b + x2) * b + h.x0) * b - ((x3 * a + x2) * a + h.x0) * a
  local dy = ((y3 * b + y2) * b + h.y0) * b - ((y3 * a + y2) * a + h.y0) * a
  return sqrt(dx * dx + dy * dy)
end

-- ---- branch points ----------------------------------------------------------

-- An imaginary part below this relative size is rounding: the root is
-- real (a cusp), a kink of the speed rather than a branch point.
local REAL_RTOL = 1e-14

-- The roots of the hodograph as a complex quadratic A2 t^2 + A1 t + A0:
-- br = {n = count, re = {}, im = {} (im >= 0: one of each conjugate
-- pair), lead = |A2| (or the factor that stands for it)}, so that speed =
-- lead prod |t - r_k|.  Cancellation-free: q = -(A1 + d)/2 with d the
-- square root of the discriminant on the side of A1, roots q/A2 and A0/q
-- (Kahan's form of the quadratic formula, in complex arithmetic written
-- out in real numbers).
local function add(br, re, im)
  im = abs(im)
  if re - re ~= 0 or im - im ~= 0 then return end        -- inf or NaN
  if im <= REAL_RTOL * (1 + abs(re)) then im = 0 end
  local n = br.n + 1
  br.n, br.re[n], br.im[n] = n, re, im
end

function M.branch_points(h)
  local br = {n = 0, re = {}, im = {}, lead = 0}
  local x2, y2, x1, y1, x0, y0 = h.x2, h.y2, h.x1, h.y1, h.x0, h.y0
  local n2, n1 = x2 * x2 + y2 * y2, x1 * x1 + y1 * y1
  if n2 > 0 then
    local dr = (x1 * x1 - y1 * y1) - 4 * (x2 * x0 - y2 * y0)
    local di = 2 * x1 * y1 - 4 * (x2 * y0 + y2 * x0)
    local w = (sqrt(dr * dr + di * di) + abs(dr)) / 2
    local s = sqrt(w)
    local qr, qi
    if s > 0 then                     -- d = sqrt(D), on the side of A1
      local o = di / (2 * s)
      local ur, ui
      if dr >= 0 then ur, ui = s, o else ur, ui = abs(o), di < 0 and -s or s end
      if x1 * ur + y1 * ui < 0 then ur, ui = -ur, -ui end
      qr, qi = -(x1 + ur) / 2, -(y1 + ui) / 2
    else
      qr, qi = -x1 / 2, -y1 / 2
    end
    br.lead = sqrt(n2)
    if qr == 0 and qi == 0 then       -- A1 = A0 = 0: a double root at 0
      add(br, 0, 0)
      add(br, 0, 0)
      return br
    end
    local qq = qr * qr + qi * qi
    if qq * POW2[-700] > n2 then
      -- q/A2 beyond 2^350: on [0, 1] |A2| |t - q/A2| = |A2 t - q| is |q| to
      -- 2^-340, so that root is dropped and |q| (rounded up) leads instead
      br.lead = sqrt(qq) * (1 + POW2[-50])
    else                              -- q/A2 = q conj(A2) / |A2|^2
      add(br, (qr * x2 + qi * y2) / n2, (qi * x2 - qr * y2) / n2)
    end
    add(br, (x0 * qr + y0 * qi) / qq, (y0 * qr - x0 * qi) / qq)   -- A0/q
  elseif n1 > 0 then                  -- a quadratic: z' linear, one root
    br.lead = sqrt(n1)
    add(br, -(x0 * x1 + y0 * y1) / n1, -(y0 * x1 - x0 * y1) / n1)
  else
    br.lead = sqrt(x0 * x0 + y0 * y0) -- a line run at constant speed
  end
  return br
end

-- ---- the bound of one piece ---------------------------------------------

-- The Bernstein ellipse is capped at rho = 64: a larger one only inflates M.
local E_CAP = 1023.5000610351562
local NMAX = 128          -- the highest order before a piece is cut instead
local FLOOR_ORDER = 48    -- the rule of a piece that cannot be cut further
local MAXDEPTH = 60       -- cuts below a first piece
local MAXSPLITS = 100000  -- cuts in one integration
local GRADE = 8           -- a graded cut: this many times the distance
local LOG2_MARGIN = 1e-9  -- what log() may lose, in the orders' logs

-- For the piece [c - hw, c + hw]: log2 of the bound's constant C = hw
-- (64/15) M rho^2 / (rho^2 - 1), a lower bound of log2(rho^2), M, the
-- ellipse's e = b^2 (in units of hw) and whether a real root (a kink) lies
-- inside.  The ellipse through z = u + iv (units of hw, foci +-1) has
-- a^2 = 1 + e, b^2 = e with e = (p + sqrt(p^2 + 4 v^2)) / 2, p = |z|^2 - 1
-- (for p < 0 the form 2 v^2 / (sqrt(p^2 + 4 v^2) - p), free of
-- cancellation); rho = a + b.  On it |z - r| <= |c - r| + hw a for every
-- root r, so M = lead prod (|c - r_k| + hw a).
local function piece_bound(br, c, hw)
  local e, inside, n = E_CAP, false, br.n
  local d1, d2 = 0, 0                               -- |c - r_k| (n <= 2 in 2D)
  for k = 1, n do
    local dr, im = br.re[k] - c, br.im[k]
    local d
    if abs(dr) + im > 1e100 * hw then
      d = abs(dr) + im                  -- far: >= the distance, no overflow
    else
      d = sqrt(dr * dr + im * im)
      if im == 0 then
        if abs(dr) < hw * (1 - 1e-12) then inside = true end
      else
        local u, v = dr / hw, im / hw
        local p = u * u + v * v - 1
        local r = sqrt(p * p + 4 * v * v)
        local ek = p >= 0 and (p + r) / 2 or 2 * v * v / (r - p)
        if ek < e then e = ek end
      end
    end
    if k == 1 then d1 = d else d2 = d end
  end
  local g = 2 * e + 2 * sqrt(e * (1 + e))           -- rho^2 - 1
  local a = hw * sqrt(1 + e)                        -- the semi-major axis
  local m = br.lead
  if n >= 1 then m = m * (d1 + a) end
  if n >= 2 then m = m * (d2 + a) end
  local logc
  local cst = hw * (64 / 15) * m * ((1 + g) / g)
  if cst > 1e-300 and cst < 1e300 then
    logc = log(cst) / LN2
  else                                              -- huge or tiny parts
    logc = log(hw * 64 / 15) + log(br.lead) + log(1 + g) - log(g)
    if n >= 1 then logc = logc + log(d1 + a) end
    if n >= 2 then logc = logc + log(d2 + a) end
    logc = logc / LN2
  end
  -- log2(1 + g) from below: g - g^2/2 <= ln(1 + g) for small g
  local lrho2 = g < 0.0625 and g * (1 - g / 2) / LN2 or log(1 + g) / LN2
  return logc + LOG2_MARGIN, lrho2 * (1 - LOG2_MARGIN), m, e, inside
end

-- The least order on the ladder at or above n.
local ORDERS = rules.orders
local LADDER = {}
do
  local j = 1
  for n = 1, NMAX do
    while ORDERS[j] < n do j = j + 1 end
    LADDER[n] = ORDERS[j]
  end
end

-- The rule for a piece: the least order whose bound is within target, and
-- that bound; nil past NMAX (or a kink inside).
local function choose(br, c, hw, target)
  local logc, lrho2, _, _, inside = piece_bound(br, c, hw)
  if inside then return nil end
  local lt = log(target) / LN2
  local need
  if logc <= lt then need = 2
  elseif not (lrho2 > 0) then return nil
  else need = (logc - lt) / lrho2 end
  if not (need <= NMAX) then return nil end         -- also NaN
  local n = need < 2 and 2 or LADDER[math.ceil(need)]
  return rules[n], 2 ^ (logc - n * lrho2)
end

-- hw sum w_i f(c + hw x_i): the rule on [c - hw, c + hw].
local function apply(h, r, c, hw)
  local x, w = r.x, r.w
  local x2, x1, x0, y2, y1, y0 = h.x2, h.x1, h.x0, h.y2, h.y1, h.y0
  local sum, i0 = 0, 1
  if x[1] == 0 then
    local vx, vy = (x2 * c + x1) * c + x0, (y2 * c + y1) * c + y0
    sum = w[1] * sqrt(vx * vx + vy * vy)
    i0 = 2
  end
  for i = i0, #x do
    local t, u = c - hw * x[i], c + hw * x[i]
    local ax, ay = (x2 * t + x1) * t + x0, (y2 * t + y1) * t + y0
    local bx, by = (x2 * u + x1) * u + x0, (y2 * u + y1) * u + y0
    sum = sum + w[i] * (sqrt(ax * ax + ay * ay) + sqrt(bx * bx + by * by))
  end
  return hw * sum
end

-- ---- the adaptive integration ------------------------------------------

-- Where to cut [a, b]: at the foot of a branch point inside it (the one
-- nearest its middle); else, when the nearest branch point lies off one
-- end, GRADE times its distance from that end (a graded mesh towards the
-- singularity); else in the middle.
local function cut_point(br, a, b)
  local mid, best, dist = a + (b - a) / 2, nil, huge
  local margin = 1e-3 * (b - a)
  for k = 1, br.n do
    local re = br.re[k]
    if re > a + margin and re < b - margin and abs(re - mid) < dist then
      best, dist = re, abs(re - mid)
    end
  end
  if best then return best end
  for k = 1, br.n do
    local re, im = br.re[k], br.im[k]
    local off = re < a and a - re or (re > b and re - b or 0)
    local d = GRADE * (off + im)
    if im > 0 and d > margin and d < dist then
      dist = d
      best = re < mid and a + d or b - d
    end
  end
  if best and dist < (b - a) / 2 then return best end
  return mid
end

-- An integration of h over [lo, hi] to within target (scaled units):
-- the pieces come in increasing t from I:next() -> a, b, len, rule (nil
-- when none is left).  cuts: the first pieces' inner ends, ascending.
local Integration = {}
Integration.__index = Integration

local function integration(h, br, lo, hi, cuts, target)
  local I = setmetatable({h = h, br = br, width = hi - lo, target = target,
    stack = {}, top = 0, evals = 0, pieces = 0, depth = 0, splits = 0, err = 0},
    Integration)
  local ends = {lo}
  for i = 1, #cuts do ends[#ends + 1] = cuts[i] end
  ends[#ends + 1] = hi
  for i = #ends - 1, 1, -1 do I:push(ends[i], ends[i + 1], 0) end
  return I
end

function Integration:push(a, b, depth)
  local top = self.top + 1
  self.top = top
  self.stack[top] = {a, b, depth}
end

function Integration:next()
  while self.top > 0 do
    local s = self.stack[self.top]
    self.top = self.top - 1
    local a, b, depth = s[1], s[2], s[3]
    local c, hw = a + (b - a) / 2, (b - a) / 2
    local r, err = choose(self.br, c, hw, self.target * ((b - a) / self.width))
    if not r and depth < MAXDEPTH and self.splits < MAXSPLITS then
      local cut = cut_point(self.br, a, b)
      if cut > a and cut < b then
        self.splits = self.splits + 1
        self:push(cut, b, depth + 1)
        self:push(a, cut, depth + 1)
        r = false
      end
    end
    if r ~= false then
      if not r then                 -- the floor: a piece of ~1e-18 width
        local _, _, m = piece_bound(self.br, c, hw)
        r, err = rules[FLOOR_ORDER], 2 * (b - a) * m
      end
      self.evals = self.evals + r.n
      self.pieces = self.pieces + 1
      if depth > self.depth then self.depth = depth end
      self.err = self.err + err
      return a, b, apply(self.h, r, c, hw), r
    end
  end
  return nil
end

-- The feet of the branch points over (lo, hi) less than share of the
-- width above it: where near-cusps put the speed's minima, and every cusp.
local function feet(br, lo, hi, share)
  local cuts = {}
  for k = 1, br.n do
    local re = br.re[k]
    if re > lo and re < hi and br.im[k] < share * (hi - lo) then
      cuts[#cuts + 1] = re
    end
  end
  table.sort(cuts)
  return cuts
end

-- The share of the width within which a foot is a first cut: it grows
-- with the digits asked for (the C core's footcut, integrator.h).
local function footcut(rtol)
  local f = -0.0015 * log(rtol) / LN2 - 0.005
  return f < 0.02 and 0.02 or (f > 0.1 and 0.1 or f)
end

-- Rounding's part of the tolerance: 64 eps relative, or half of rtol when
-- that is less (as the C core's truncation budget).
local RESERVE = 64 * 2.220446049250313e-16
local function budget(rtol)
  return rtol - (rtol / 2 < RESERVE and rtol / 2 or RESERVE)
end

-- A lower bound of the length over [lo, hi] between the cuts: the sum of
-- chords.  Where they vanish (a curve back where it started at every
-- cut) the chords of 4, then 16 equal parts of each piece, still true
-- lower bounds; only where those vanish too, half an 8-point rule, as the
-- C core takes it.
local PARTS = {1, 4, 16}
local function lower_length(h, lo, hi, cuts)
  local ends = {lo}
  for i = 1, #cuts do ends[#ends + 1] = cuts[i] end
  ends[#ends + 1] = hi
  for _, parts in ipairs(PARTS) do
    local sum = 0
    for i = 1, #ends - 1 do
      local a, w = ends[i], (ends[i + 1] - ends[i]) / parts
      for j = 1, parts do
        sum = sum + chord(h, a + (j - 1) * w, j == parts and ends[i + 1] or a + j * w)
      end
    end
    if sum > 0 then return sum end
  end
  return 0.5 * apply(h, rules[8], lo + (hi - lo) / 2, (hi - lo) / 2)
end

-- x in scaled units (and the local variable of a part) as a length.
local function curve_units(h, x)
  return mul_pow2(x * h.unit, h.exp)
end

-- The length of the plane cubic c over [t0, t1] (t0 > t1: negative) to
-- within rtol of itself; with want_info, also {evals, pieces, depth, err}.
function M.length(c, t0, t1, rtol, want_info)
  local a, b = t0 < t1 and t0 or t1, t0 < t1 and t1 or t0
  local info = want_info and {evals = 0, pieces = 0, depth = 0, err = 0, calls = 0} or nil
  if a == b then return 0, info end
  local h = M.hodograph(c, a, b)
  if not h then return 0, info end
  local br = M.branch_points(h)
  local tol = budget(rtol)
  local cuts = feet(br, h.lo, h.hi, footcut(tol))
  local low = lower_length(h, h.lo, h.hi, cuts)
  if not (low > 0) then return 0, info end
  local target, sum = tol * low, 0
  if not info then
    -- the common case first: every first piece meets its share with one
    -- rule (the same pieces, rules and sums as the integration below)
    local from, width = h.lo, h.hi - h.lo
    for i = 1, #cuts + 1 do
      local to = cuts[i] or h.hi
      local mid, hw = from + (to - from) / 2, (to - from) / 2
      local r = choose(br, mid, hw, target * ((to - from) / width))
      if not r then sum = nil; break end
      sum = sum + apply(h, r, mid, hw)
      from = to
    end
    if sum then return curve_units(h, t0 > t1 and -sum or sum) end
    sum = 0
  end
  local I = integration(h, br, h.lo, h.hi, cuts, target)
  for _ = 1, 2 * MAXSPLITS + 8 do
    local pa, _, len = I:next()
    if not pa then break end
    sum = sum + len
  end
  if info then
    info.evals, info.pieces, info.depth = I.evals, I.pieces, I.depth
    info.err = curve_units(h, I.err)
  end
  local len = curve_units(h, sum)
  return t0 > t1 and -len or len, info
end

-- ---- the inverse -----------------------------------------------------------

-- The integral of the speed over [x, y] within target (scaled units):
-- inside an accepted piece this is one short rule, mostly.
local function sub_integral(h, br, x, y, target, count)
  if not (y > x) then return 0 end
  local r = choose(br, x + (y - x) / 2, (y - x) / 2, target)
  if r then                           -- one rule: the integration's first piece
    count.evals = count.evals + r.n
    return apply(h, r, x + (y - x) / 2, (y - x) / 2)
  end
  local I = integration(h, br, x, y, {}, target)
  local sum = 0
  for _ = 1, 2 * MAXSPLITS + 8 do
    local pa, _, len = I:next()
    if not pa then break end
    sum = sum + len
  end
  count.evals = count.evals + I.evals
  return sum
end

-- A first guess for s(t) = goal in [a, b] (s from a): the cubic Hermite
-- interpolant of s from 0, plen and the speeds at the ends, inverted by
-- three Newton steps on u = (t - a)/(b - a) kept in (0, 1).
local function hermite_guess(h, a, b, plen, goal)
  local w = b - a
  local fa, fb, u = w * speed(h, a), w * speed(h, b), goal / plen
  for _ = 1, 3 do
    local u2 = u * u
    local u3 = u2 * u
    local s = plen * (3 * u2 - 2 * u3) + fa * (u - 2 * u2 + u3) + fb * (u3 - u2) - goal
    local ds = plen * (6 * u - 6 * u2) + fa * (1 - 4 * u + 3 * u2) + fb * (3 * u2 - 2 * u)
    local nxt = ds > 0 and u - s / ds or -1
    if not (nxt > 0 and nxt < 1) then break end
    u = nxt
  end
  return a + w * u
end

-- s(t) = goal in the accepted piece [a, b] of length plen (goal in (0,
-- plen)) within tol: safeguarded Newton, always bracketed.  s(t) is the
-- nearer end of the bracket (its s known) plus the integral between; the
-- k-th integral may err by tol 2^-k, so the known values err by less than
-- tol more than the piece's length did.  At most 100 steps; a step that
-- leaves the bracket is replaced by bisection.
local function solve_in_piece(h, br, a, b, plen, goal, tol, count)
  local lo, slo, hi, shi = a, 0, b, plen
  local t, share = hermite_guess(h, a, b, plen, goal), tol / 2
  if not (t > lo and t < hi) then t = lo + (hi - lo) / 2 end
  for _ = 1, 100 do
    local g
    if t - lo <= hi - t then g = slo + sub_integral(h, br, lo, t, share, count) - goal
    else g = shi - sub_integral(h, br, t, hi, share, count) - goal end
    share = share / 2
    local f = speed(h, t)
    count.evals = count.evals + 1
    if g < 0 then lo, slo = t, g + goal
    elseif g > 0 then hi, shi = t, g + goal end
    if abs(g) <= tol then break end
    local nxt = f > 0 and t - g / f or lo + (hi - lo) / 2
    if not (nxt > lo and nxt < hi) then nxt = lo + (hi - lo) / 2 end
    if nxt == t or hi - lo <= 4e-16 * (abs(hi) > 1e-300 and abs(hi) or 1e-300) then break end
    t = nxt
  end
  return t
end

-- The whole curve's pieces for the inverse: cut at the feet within 0.2 of
-- the width (a sharp dip in a piece defeats the Hermite guess), the pieces'
-- errors within a quarter of rtol.  Returns nil for a point.
local TIME_FOOTCUT = 0.2
local function time_setup(c, rtol)
  local h = M.hodograph(c, 0, 1)
  if not h then return nil end
  local br = M.branch_points(h)
  local cuts = feet(br, 0, 1, TIME_FOOTCUT)
  local low = lower_length(h, 0, 1, cuts)
  if not (low > 0) then return nil end
  return {h = h, br = br, I = integration(h, br, 0, 1, cuts, rtol * 0.25 * low),
          tol = rtol * 0.25 * low, cum = 0, count = {evals = 0}}
end

-- The t of each distance of the ascending list s (curve units) on the
-- plane cubic c, each with |s(t) - s| <= rtol L: one walk over the pieces,
-- each distance solved inside the piece that holds it.  s <= 0 gives 0, s
-- at or past the end 1.  Returns ts and the count of speed evaluations.
function M.times(c, s, rtol)
  local ts, n = {}, #s
  local q = 1
  while q <= n and s[q] <= 0 do ts[q] = 0; q = q + 1 end
  if q > n then return ts, 0 end
  local S = time_setup(c, rtol)
  if not S then
    for i = q, n do ts[i] = 1 end
    return ts, 0
  end
  local h, I = S.h, S.I
  local cum = 0
  for _ = 1, 2 * MAXSPLITS + 8 do
    if q > n then break end
    local a, b, plen = I:next()
    if not a then break end
    local last = I.top == 0
    while q <= n do
      local goal = mul_pow2(s[q], -h.exp)
      if goal > cum + plen or (goal == cum + plen and not last) then break end
      if goal >= cum + plen then
        ts[q] = 1                     -- at or past the end
      elseif goal <= cum then
        ts[q] = a
      else
        ts[q] = solve_in_piece(h, S.br, a, b, plen, goal - cum, S.tol, S.count)
      end
      q = q + 1
    end
    cum = cum + plen
  end
  for i = q, n do ts[i] = 1 end       -- past the last piece's end
  return ts, I.evals + S.count.evals
end

return M
