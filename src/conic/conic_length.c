/*
** conic_length.c -- the exact arc length of a conic arc (p0, p1, p2; w)
** (Floater's eq. 1), by Carlson's R_F and R_D.
**
** The arc is an affine image of a circular (w < 1) or hyperbolic (w > 1)
** arc: with m = (p0+p2)/2, d = p1 - m, h = (p2-p0)/2 it is
**   x(th) = c + U cos th + V sin th,   th in [-a, a],  a = acos w,
**   U = d w/(1-w^2), V = h/sqrt(1-w^2)            (ellipse), and
**   x(th) = c + U cosh th + V sinh th, th in [-b, b],  b = acosh w,
**   U = d w/(1-w^2), V = h/sqrt(w^2-1)            (hyperbola).
** From the conjugate semi-diameters U, V come the semi-axes A, B and the
** parameter offset th0 of the vertex.  Every length below is a sum of
** positive terms or a difference bounded away from cancellation (factor
** <= 3.4); differences of elliptic integrals at two amplitudes are never
** formed: Legendre's addition theorem (DLMF 19.11.1-2) turns them into one
** integral at amplitude psi, with sin psi computed from the span directly.
** The parabola (w = 1) has a closed form.  Everything works on the legs
** p1 - p0, p2 - p1 (one rounding each, so far-away points keep a short
** leg's digits) scaled by a power of two; where the arc is within 2^-50 of
** its one-level subdivision polygons (weights or leg ratios near the ends
** of the double range) their bracket gives the length (sandwich()).
*/
#include <float.h>
#include <math.h>

#include "arclen.h"
#include "conic/conic.h"
#include "curve/numeric.h"

#define QUARTER_PI 0.78539816339744830962

/* int_0^psi sqrt(1 - m sin^2) between amplitudes x0 < x1 (both in
** [0, pi/4] for m > 0): E(x1|m) - E(x0|m) = E(psi|m) - m s0 s1 sin psi,
** F(psi) = F(x1) - F(x0), sin psi = (s1^2 - s0^2)/(s1 c0 D0 + s0 c1 D1)
** where s1^2 - s0^2 = sin(x1 - x0) sin(x1 + x0) (span given exactly).
** E(psi|m) = sin psi R_F(cos^2, Dpsi^2, 1) - (m/3) sin^3 psi R_D(...). */
static double e_between(double x0, double span, double m, long *calls) {
  double x1 = x0 + span;
  double s0 = sin(x0), c0 = cos(x0), s1 = sin(x1), c1 = cos(x1);
  double d0 = sqrt(1 - m * s0 * s0), d1 = sqrt(1 - m * s1 * s1);
  double sp, cp2, dp2;
  if (span <= 0) return 0;
  sp = sin(span) * sin(x1 + x0) / (s1 * c0 * d0 + s0 * c1 * d1);
  if (sp > 1) sp = 1;
  cp2 = (1 - sp) * (1 + sp);
  dp2 = 1 - m * sp * sp;
  *calls += 2;
  return sp * arclen_rf(cp2, dp2, 1)
         - m / 3 * sp * sp * sp * arclen_rd(cp2, dp2, 1) - m * s0 * s1 * sp;
}

/* The ellipse x = A cos phi, y = B sin phi (A >= B) from phi = lo to lo +
** span (span < pi).  Split at the vertices and at the octant points
** k pi/4; each piece is measured from its nearest vertex: near a minor
** vertex (speed A) as A sqrt(1 - k^2 sin^2 x), near a major vertex (speed
** B) as B sqrt(1 + ((A^2-B^2)/B^2) sin^2 x). */
static double ellipse_arc(double A, double B, double lo, double span,
                          long *calls) {
  double mminor = (A - B) * (A + B) / (A * A);
  double mmajor = -(A - B) * (A + B) / (B * B);
  double total = 0, done = 0;
  long j = (long)floor(lo / QUARTER_PI);
  int guard;
  for (guard = 0; guard < 8 && done < span; guard++, j++) {
    /* piece inside octant j: [max(lo, j pi/4), min(lo+span, (j+1) pi/4)] */
    double start = lo + done;                    /* phi at the piece start */
    double room = (j + 1) * QUARTER_PI - start;  /* to the octant's end */
    /* the last piece ends inside its octant: stop there, or the rounding
    ** of `done` would leave a sliver to be measured in the next octant
    ** from the wrong vertex (A times a 1e-23 span near a major vertex of
    ** B/A = 5e-23 added 2.6e-9 relative; found by fuzz/fuzz_conic) */
    int last = span - done <= room;
    double len = last ? span - done : room, x0;
    long v;
    if (len < 0) len = 0;
    if (j % 2 == 0) {           /* vertex at j pi/4, x = phi - j pi/4 */
      x0 = start - j * QUARTER_PI;
      v = j / 2;
    } else {                    /* vertex at (j+1) pi/4, reflected */
      x0 = room - len;
      v = (j + 1) / 2;
    }
    if (x0 < 0) x0 = 0;
    if (x0 > QUARTER_PI) x0 = QUARTER_PI;
    if (v % 2 == 0)             /* phi = 0, pi: ends of the major axis */
      total += B * e_between(x0, len, mmajor, calls);
    else
      total += A * e_between(x0, len, mminor, calls);
    done += len;
    if (last) break;
  }
  return total;
}

/* The hyperbola x = A cosh tau, y = B sinh tau from tau0 to tau0 + span,
** 0 <= tau0.  With sinh tau = tan chi and G = sqrt(B^2 + A^2 sin^2 chi):
** L = [G tan chi] - (A^2/B) int sin^2 chi / sqrt(1 - m sin^2 chi), m =
** -A^2/B^2 (integration by parts); the bracket is written without
** cancellation and the integral by the addition theorem:
** D(chi1) - D(chi0) = D(psi) + s0 s1 sin psi, D = (1/3) sin^3 R_D.  The
** second term is at most half the first (pointwise). */
/* sinh t and cosh t for t >= 0 given with E = e^t: from t itself when t <
** 1 (there t has its digits), else from E, which the caller forms as a
** product of exponentials with a few roundings, while t = b + th0 ~ 70
** carries an absolute error ~ 70 eps and so would cosh(t) a relative one
** (w = 1e13: 5.6e-15). */
static void hyp(double t, double E, double *sh, double *ch) {
  if (t < 1) { *sh = sinh(t); *ch = cosh(t); return; }
  *sh = (E - 1 / E) / 2; *ch = (E + 1 / E) / 2;
}

static double hyperbola_arc(double A, double B, double t0, double E0,
                            double span, double Es, long *calls) {
  double t1 = t0 + span, E1 = E0 * Es;
  double ch0, ch1, sh0, sh1, s0, s1, shs, sh01, sa, sb, junk;
  double r = A / B, g0, g1, num, bracket, sp, cp2, dp2, q, dterm;
  hyp(t0, E0, &sh0, &ch0);
  hyp(t1, E1, &sh1, &ch1);
  hyp(span, Es, &shs, &junk);
  hyp(t0 + t1, E0 * E1, &sh01, &junk);
  hyp((t0 + t1) / 2, sqrt(E0 * E1), &sa, &junk);
  hyp(span / 2, sqrt(Es), &sb, &junk);
  s0 = sh0 / ch0; s1 = sh1 / ch1;
  if (span <= 0) return 0;
  /* G = sqrt(B^2 + A^2 tanh^2) by hypot: A/B overflows its square for
  ** very thin hyperbolas (points spread beyond 2^500) */
  g0 = hypot(B, A * s0);
  g1 = hypot(B, A * s1);
  /* G1 tan1 - G0 tan0 = sinh(span) sinh(t0+t1) [(A^2+B^2) -
  ** A^2/(ch0 ch1)^2] / (G1 sinh t1 + G0 sinh t0) */
  num = shs * sh01 / (g1 * sh1 + g0 * sh0);
  /* (A^2+B^2) - A^2/(ch0 ch1)^2 = B^2 + A^2 X (X + 2)/(ch0 ch1)^2 with
  ** X = ch0 ch1 - 1 = sinh^2((t0+t1)/2) + sinh^2(span/2): no cancellation
  ** when tau is small and A >> B (near-parabolic arcs) */
  {
    double X = sa * sa + sb * sb, cc = ch0 * ch1;
    bracket = num * (B * B + A * A * (X * (X + 2) / (cc * cc)));
  }
  /* sin psi = (s1^2 - s0^2)/(s1 c0 D0 + s0 c1 D1), c = 1/cosh, D = G/B,
  ** s1^2 - s0^2 = sinh(span) sinh(t0+t1)/(ch0 ch1)^2, and
  ** (s1 c0 D0 + s0 c1 D1) ch0 ch1 B = s1 ch1 G0 + s0 ch0 G1 */
  sp = (shs * sh01 / (ch0 * ch1)) * B
       / (s1 * ch1 * g0 + s0 * ch0 * g1);
  if (sp > 1) sp = 1;
  cp2 = (1 - sp) * (1 + sp);
  q = r * sp;
  *calls += 1;
  if (q <= 0x1p500) {
    dp2 = 1 + q * q;
    dterm = A * r * (sp * sp * sp / 3 * arclen_rd(cp2, dp2, 1) + s0 * s1 * sp);
  } else {
    /* R_D is homogeneous of degree -3/2 (DLMF 19.16.2): scaled by 1/q
    ** its arguments stay finite when q^2 would overflow;
    ** A r sp^3 q^(-3/2) = A sp^(3/2) / sqrt(r) */
    double lam = 1 / q;
    dterm = A * sp * sqrt(sp / r) / 3 * arclen_rd(cp2 * lam, q + lam, lam)
            + A * r * s0 * s1 * sp;
  }
  return bracket - dterm;
}

/* a x c = ax cy - ay cx to an ulp or two (Kahan's difference of
** products: the rounding of ay cx recovered by FMA), also for the nearly
** parallel legs of a thin conic. */
static double cross2(double ax, double ay, double cx, double cy) {
  double p = ay * cx, e = arclen_fma(-ay, cx, p), f = arclen_fma(ax, cy, -p);
  return f + e;
}

/* E = w + sqrt(w^2 - 1) (= e^acosh w) for w > 1 as a double-double:
** w^2 - 1 exactly (TwoProduct, TwoSum), its square root corrected by one
** Newton step on the residual, and the sum renormalised so that E.hi is
** E rounded: near w = 1 the part of w^2 - 1 below ph - 1 is up to 2^-26
** of it (w = 1 + 2^-26: 5e-9) and the step moves sqrt by that half, so
** the unrenormalised E.hi was 3.3e-13 off, and so was every U -+ V
** divided by 2 E.hi (w^2 - 1) (4.3e-15 of a sub-arc's length). */
static arclen_dd exp_acosh(double w) {
  double ph = w * w, sh, r;
  arclen_dd q = arclen_two_sum(ph, -1), E;
  q.lo += arclen_fma(w, w, -ph);
  sh = sqrt(q.hi);
  r = arclen_fma(-sh, sh, q.hi) + q.lo;          /* w^2 - 1 - sh^2 */
  E = arclen_two_sum(w, sh);
  E.lo += r / (2 * sh);
  return arclen_two_sum(E.hi, E.lo);
}

/* E^2 u - v for a double-double E^2, to about an ulp of the result: the
** product u E2.hi exactly (FMA), the difference by TwoSum. */
static double e2u_minus_v(arclen_dd E2, double u, double v) {
  double p = u * E2.hi, pe = arclen_fma(u, E2.hi, -p);
  arclen_dd t = arclen_two_sum(p, -v);
  return t.hi + (t.lo + pe + u * E2.lo);
}

/* Parabola (w = 1): speed 2|a + t e|, a = p1 - p0, e = p0 - 2 p1 + p2;
** L = q int_{u0}^{u1} 2 sqrt(u^2 + k^2) du with q = |e|, u = (a.e)/q^2 + t,
** k = |a x e|/q^2 (cross = |a x e| = |a x c| given from a and c: for a
** short leg e = c - a is nearly -a and a x e would cancel to 0).
** Same-sign ends: differences rewritten (u1 - u0 = 1). */
static double parabola(double ax, double ay, double ex, double ey,
                       double cross) {
  double q = hypot(ex, ey);
  double u0 = (ax * ex + ay * ey) / (q * q), u1 = u0 + 1;
  double k = cross / (q * q);
  double S0, S1, el, as;
  if (u0 < 0 && u1 > 0) {     /* the vertex is inside: two halves */
    double a0 = -u0;
    S0 = hypot(a0, k); S1 = hypot(u1, k);
    return q * ((u1 * S1 + a0 * S0) + k * k * (asinh(u1 / k) + asinh(a0 / k)));
  }
  if (u1 <= 0) { double t = -u1; u1 = -u0; u0 = t; }   /* reflect */
  S0 = hypot(u0, k); S1 = hypot(u1, k);
  /* u1 S1 - u0 S0 = (u1 + u0)(u1^2 + u0^2 + k^2)/(u1 S1 + u0 S0) */
  el = (u1 + u0) * (u1 * u1 + u0 * u0 + k * k) / (u1 * S1 + u0 * S0);
  /* asinh(u1/k) - asinh(u0/k) = asinh((u1 + u0)/(u1 S0 + u0 S1)) */
  as = asinh((u1 + u0) / (u1 * S0 + u0 * S1));
  return q * (el + k * k * as);
}

/* U - V (mv[0..1]) and U + V (mv[2..3]) for U = al d, V = s h, al =
** w/(1-w^2), s = |1-w^2|^(-1/2), with p0 at the origin, h = k/2 (x2 y2 =
** k = p2 - p0) and d = a - h (x1 y1 = a = p1 - p0): from d and h, as U, V
** and the triangle's area are, so that all of them describe one triangle.
** (The legs a, c, k are each one rounding of the inputs, so a + c - k is
** up to an ulp of k; near w = 1 al ~ 2^52 turned that into 3e-10 of a
** flat triangle's U + V when U + V was formed from c.)  For w > 1 and
** nearly parallel legs with |a| ~ E^2 |c| or |c| ~ E^2 |a| (E = w +
** sqrt(w^2 - 1) = e^acosh w: a thin hyperbola whose arc lies far out on
** one arm) one of the sums cancels.  There, with h = (a + c)/2, al = -w
** s^2, s - |al| = -s^2/E and w = (E + 1/E)/2:
**   U - V = (c - E^2 a)/den,  U + V = (E^2 c - a)/den,  den = 2 E (w^2 - 1),
** from a and c = p2 - p1 alone (each one rounding of the inputs), E^2 in
** double-double and each product exact, so each sum is within about an ulp
** of itself however far it cancels.  (The earlier form al a + g h, g =
** s^2/E, switched to this one only below 2^-10 of its terms and lost up to
** 2^10 ulps above: 1.3e-14 of the length of w = 1.1598 with |a| = E^2 |c|
** and the legs 0.18 degrees from parallel; a sub-arc of w = 6.77 lost
** 1e-12 before either, found by fuzz/fuzz_segment.)  Returns 1 when U -+
** V came from a and c, else 0. */
static int umvm(double x1, double y1, double x2, double y2, double cx,
                double cy, double w, double onew, double s, double mv[4]) {
  double al = w / onew, hx = x2 / 2, hy = y2 / 2;
  double dx = x1 - hx, dy = y1 - hy, sz;
  mv[0] = dx * al - hx * s; mv[1] = dy * al - hy * s;
  mv[2] = dx * al + hx * s; mv[3] = dy * al + hy * s;
  sz = fabs(al) * hypot(dx, dy) + s * hypot(hx, hy);
  if (w > 1 && (hypot(mv[0], mv[1]) < 0.25 * sz ||
                hypot(mv[2], mv[3]) < 0.25 * sz)) {
    arclen_dd E = exp_acosh(w), E2;
    double den = 2 * E.hi * (-onew);
    E2.hi = E.hi * E.hi;
    E2.lo = arclen_fma(E.hi, E.hi, -E2.hi) + 2 * E.hi * E.lo;
    mv[0] = -e2u_minus_v(E2, x1, cx) / den;
    mv[1] = -e2u_minus_v(E2, y1, cy) / den;
    mv[2] = e2u_minus_v(E2, cx, x1) / den;
    mv[3] = e2u_minus_v(E2, cy, y1) / den;
    return 1;
  }
  return 0;
}

/* Floater's subdivision (eq. 4) at t = 1/2 puts the arc inside the
** triangles (p0, l1, s) and (s, r1, p2), l1 = p0 + w a/(1+w), s = p0 +
** (2w a + k)/(2+2w), r1 = p2 - w c/(1+w), k = a + c; the arc is convex, so
**   lo = |2w a + k|/(2+2w) + |2w c + k|/(2+2w)  <=  L  <=
**   hi = (w |a| + w |c| + |k|)/(1+w)  (= the polygon p0 l1 s r1 p2).
** Returns 1 and the middle of [lo, hi] in *L when hi - lo <= 2^-50 lo
** (lo and hi are each a few roundings off, so a tighter test would miss
** exact cases): then it is within 2^-51 relative (plus those roundings,
** 1e-15 in all) of the length.  That is the case for w beyond about 2^50
** (hi - lo <= |c - a|/(1+w): the polygon), for w below about 2^-50
** chord/polygon (the chord), and for a leg below 2^-51 of the other (hi -
** lo <= 2 min(|a|, |c|)) -- where the forms below would need semi-axis
** ratios, Carlson arguments or (A/B)^2 beyond the double range. */
static int sandwich(const double v[6], double w, double *L) {
  double ax = v[0], ay = v[1], cx = v[2], cy = v[3], kx = v[4], ky = v[5];
  double la = hypot(ax, ay), lc = hypot(cx, cy), lk = hypot(kx, ky);
  double lo, hi, tw = w > 1 ? 2 : 2 * w, tk = w > 1 ? 1 / w : 1;
  /* divided through by w when w > 1, so that 2w a does not overflow */
  lo = (hypot(tw * ax + tk * kx, tw * ay + tk * ky)
        + hypot(tw * cx + tk * kx, tw * cy + tk * ky)) / (2 * (tk + (w > 1 ? 1 : w)));
  hi = w > 1 ? (la + lc + lk / w) / (1 + 1 / w) : (w * (la + lc) + lk) / (1 + w);
  if (hi - lo > 0x1p-50 * lo) return 0;
  *L = lo + (hi - lo) / 2;
  return 1;
}

/* The exact length of the conic with legs v (a = v[0..1], c = v[2..3], k =
** a + c = v[4..5]) by the forms above, on the legs scaled by 2^-e so
** that the largest component is in [1/2, 1). */
static double exact_length(const double v[6], double w, long *calls) {
  double px1, py1, cx, cy, px2, py2, dx, dy, hx, hy, ux, uy, vx, vy, sc, L;
  double mx = 0;
  int e, i;
  for (i = 0; i < 6; i++)
    if (fabs(v[i]) > mx) mx = fabs(v[i]);
  frexp(mx, &e);
  px1 = ldexp(v[0], -e); py1 = ldexp(v[1], -e);
  cx = ldexp(v[2], -e); cy = ldexp(v[3], -e);
  px2 = ldexp(v[4], -e); py2 = ldexp(v[5], -e);
  if (w == 1)
    return ldexp(parabola(px1, py1, cx - px1, cy - py1,
                          fabs(cross2(px1, py1, cx, cy))), e);
  {
    double onew = (1 - w) * (1 + w);          /* 1 - w^2, exact enough */
    double uv, pp, qq, A, B, cross, th0, mv[4];
    hx = px2 / 2; hy = py2 / 2;
    dx = px1 - hx; dy = py1 - hy;
    sc = w / onew;
    ux = dx * sc; uy = dy * sc;
    sc = 1 / sqrt(fabs(onew));
    vx = hx * sc; vy = hy * sc;
    uv = ux * vx + uy * vy;
    /* U x V = (w / (1 - w^2)) |1 - w^2|^(-1/2) d x h, d x h = a x c / 2:
    ** the triangle's area, not a difference of the nearly parallel U, V of
    ** a short leg.  The rounded legs a, c, k do not close (a + c - k is up
    ** to an ulp of k), so the area comes from the sides U -+ V came from:
    ** d x h from a and k (a flat triangle with w = 1 - 2^-53 lost 1.2e-11
    ** to a x c there, issue 31), a x c where a short leg c is exact and k
    ** carries an ulp of the long one (the thin hyperbolas of umvm), and
    ** where the two disagree by more than a factor 2: an area at the
    ** legs' rounding level, where a x c is what the flatness test saw (d
    ** x h came out 0 for a sub-arc of w = 9e-13; found by
    ** fuzz/fuzz_segment) */
    {
      double dh = cross2(dx, dy, hx, hy), ac = cross2(px1, py1, cx, cy) / 2;
      int from_ac = umvm(px1, py1, px2, py2, cx, cy, w, onew, sc, mv);
      if (from_ac || !(dh * ac > 0 && fabs(dh) < 2 * fabs(ac) && fabs(ac) < 2 * fabs(dh)))
        dh = ac;
      cross = fabs(dh * (w / onew) * sc);
    }
    /* |U|^2 - |V|^2 as (U - V).(U + V) */
    qq = mv[0] * mv[2] + mv[1] * mv[3];
    if (w < 1) {
      double a = acos(w), R;
      pp = (ux * ux + uy * uy + vx * vx + vy * vy) / 2;
      R = hypot(qq / 2, uv);
      A = sqrt(pp + R);
      B = cross / A;
      /* the major vertex at th0: tan 2 th0 = 2 U.V / (|U|^2 - |V|^2) */
      th0 = atan2(2 * uv, qq) / 2;
      L = ellipse_arc(A, B, -a - th0, 2 * a, calls);
    } else {
      double sq = sqrt((w - 1) * (w + 1)), b = asinh(sq), Eb = w + sq, Et;
      double um = hypot(mv[0], mv[1]), up = hypot(mv[2], mv[3]);
      pp = um * up;                                 /* A^2 + B^2 */
      if (qq >= 0) { A = sqrt((pp + qq) / 2); B = cross / A; }
      else { B = sqrt((pp - qq) / 2); A = cross / B; }
      /* the vertex: tanh 2 th0 = -2 U.V / (|U|^2 + |V|^2) = -x, i.e.
      ** th0 = log(|U - V| / |U + V|) / 2; atanh keeps th0's relative
      ** accuracy when it is small (near-parabolic arcs need that) */
      {
        double x = 2 * uv / (ux * ux + uy * uy + vx * vx + vy * vy);
        th0 = fabs(x) < 0.5 ? -0.5 * atanh(x) : 0.5 * log(um / up);
        Et = fabs(x) < 0.5 ? exp(th0) : sqrt(um / up);    /* e^th0 */
      }
      /* tau = th - th0 in [-b - th0, b - th0]; split at the vertex.  The
      ** exponentials e^tau of the ends come from e^b = w + sqrt(w^2 - 1)
      ** and e^th0, not from the rounded sums */
      if (-b - th0 < 0 && b - th0 > 0)
        L = hyperbola_arc(A, B, 0, 1, b + th0, Eb * Et, calls)
            + hyperbola_arc(A, B, 0, 1, b - th0, Eb / Et, calls);
      else if (b - th0 <= 0)
        L = hyperbola_arc(A, B, th0 - b, Et / Eb, 2 * b, Eb * Eb, calls);
      else
        L = hyperbola_arc(A, B, -b - th0, 1 / (Eb * Et), 2 * b, Eb * Eb,
                          calls);
    }
  }
  return ldexp(L, e);
}

int arclen_conic_length(const double p[6], double w, double *len,
                        arclen_info *info) {
  double v[6], L;
  long calls = 0;
  int rc = arclen_conic_check(p, w), e, i;
  *len = NAN;
  if (info != NULL) arclen_info_init(info);
  if (rc != ARCLEN_OK) return rc;
  /* the legs (each one rounding of the inputs) scaled by a power of two:
  ** no overflow, no lost digits far from the origin */
  e = arclen_conic_legs(p, v);
  {
    double mx = 0;
    int k;
    for (i = 0; i < 6; i++)
      if (fabs(v[i]) > mx) mx = fabs(v[i]);
    frexp(mx, &k);
    for (i = 0; i < 6; i++) v[i] = ldexp(v[i], -k);
    e += k;
  }
  if (!sandwich(v, w, &L)) L = exact_length(v, w, &calls);
  L = ldexp(L, e);
  if (info != NULL) {
    info->branch = w < 1 ? "ellipse" : w > 1 ? "hyperbola" : "parabola";
    info->calls = calls;
  }
  if (!isfinite(L)) return ARCLEN_EOVERFLOW;
  *len = L;
  return ARCLEN_OK;
}
