/*
** quad_time.c -- a quadratic's time at a length: the t with |s(t) - g| <=
** tol, s(t) = 2 int_0^t |v|, v = a + t b (quad.c's form, set up once).
**
** The first t inverts the closed form through a table of the parabola's
** inverse length (first_guess, quad_inverse_table.c) and is the answer,
** without any length, where the bound of its miss is within tol
** (direct_bound: at tol 1e-12 nearly always).  Else it starts the search.
** Each length from 0 is quad.c's closed form from the set-up (one square
** root, |v(t)|, and one log), and the last step needs none: the speed
** sigma = 2|v| has sigma' = 2 v.b/|v| and, since v x b = a x c is
** constant, sigma'' = 2 (|v|^2 |b|^2 - (v.b)^2)/|v|^3 = 2 k^2/|v|^3
** exactly (k = |a x c|), and so on (step_from).  From a point x where f =
** s(x) - g is known, the root e of the Taylor polynomial of s - g (series
** reversion) leaves |f(x + e)| at most the polynomial's value there plus
** Taylor's remainder, which the closed-form derivative bounds with |v| >=
** max(k/|b|, |v(x)| - |b| |e|) on the step (k/|b| is |v|'s least value,
** at the vertex; |dv/dt| = |b|).  Where that, the known value's own error
** and the step's roundings stay within tol, x + e is the answer without
** another length (as src/gauss/time.c's second_order_step on a cubic);
** a step below 2^-16 of |v|/|b|, as from the first guess, takes the
** second-order polynomial and a shorter bound (short_bound).
** Else x + e is measured and the step repeats, inside a bracket of
** measured points, bisecting where a step leaves it (a cusp: |v| = 0 at
** the vertex when k = 0) or is longer than half the step before
** (arclen_step_ok), capped.  A sweep over ascending distances (the path
** walks) steps from the last answer first, carrying its bound.
*/
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "arclen.h"
#include "curve/numeric.h"
#include "segment/quad_inverse_table.h"
#include "segment/segment.h"

/* 64 halvings take [0, 1] below one ulp of any t, so the cap is reached
** only by a length noisier than the tolerance asked for */
#define MAX_STEPS 100

/* The unit roundoff, 2^-53. */
#define U (DBL_EPSILON / 2)

/* The mantissa's bits below a piece's (PIECE_BITS) and their weight in
** the piece's r in [-1, 1): 2 NSUB 2^-52 */
#define PIECE_BITS (52 - ARCLEN_QI_NSUB_BITS)
#define PIECE_SCALE (2.0 * ARCLEN_QI_NSUB / 4503599627370496.0)

/* G^-1's table covers y in [TABLE_MIN, TABLE_MAX) (quad_inverse_table.h) */
#define TABLE_MIN (1.0 / (1 << -ARCLEN_QI_JMIN))
#define TABLE_MAX ((double)(1L << ARCLEN_QI_JMAX))

/* The closed form's rounding, in units of U of its value: a sum of
** positive terms (quad.c: u1 - u0 set exactly, no difference of nearly
** equal values), each a product or quotient of a few rounded factors (the
** squares' sums, the roots, log or log1p within an ulp of their value).
** Against mpmath on quadratics with exact legs it read at most 4.6 U on
** tools/ref_quad_times.py's 600 (2D, 3D, hairpins, collinear legs) and
** 6.2 U on 3000 more in a scratch set (the legs' own rounding is the set-up's,
** shared by every length of the segment: a change of the curve by an ulp,
** not of the measure).  The Gauss branch (quad.c: truncation below 1e-19)
** adds ten positive terms, each within 3 U, with nine roundings: 12 U at
** worst, so 16 there. */
#define FORM_ROUNDING 8
#define GAUSS_ROUNDING 16

/* x times 2^e for the form's scale (both powers exact within +-1000). */
static double times_pow2(double x, int e, double p) {
  return e > -1000 && e < 1000 ? x * p : ldexp(x, e);
}

/* 1/3! and 1/4! as products: a division by a constant is a divsd (the
** divider is one unit, ~4 cycles apart); each is within U/2 of its value,
** an extra rounding inside the evaluation's 16 U and the bound's 2^-10 */
#define C6 (1.0 / 6)
#define C24 (1.0 / 24)

/* The bound of |s(x + e) - g| for the second-order step e = d - b2 d^2
** (t1 = sigma tail, t2 = sigma' e^2/2: the quadratic Taylor polynomial's
** value is t1 + t2), where step_from found |b||e| <= 2^-16 S (eps below)
** and dS <= S/16.  Its terms are step_from's for a polynomial of second
** order, each bounded on the values at hand:
**   remainder: max|sigma''| |e|^3/6 with sigma'' = 2k^2/|v|^3 <= 2|b|^2/|v|
**      (k = |v x b| <= |v||b|) and |v| >= S - dS - |b||e| >= 0.937 S on the
**      step: B |e|^3/(3 0.937 S) with B, 1/S within a few U, 0.37 B|e|^3/S;
**   the derivatives' errors, 3/2 (2 dS|e| + (2 du/S + |sigma'| (dS/S + 2U))
**      e^2/2): with e^2/S <= eps |e|/|b|, du/|b| = U (4 (|a| + 2x|b|) +
**      |u|/|b|) <= 2 dS (|b| <= |a| + |c|, |u| <= |b| |v| <= 1.1 |b| S) and
**      |sigma'| e^2/2 <= 1.1 eps S |e|, 2US <= dS: the e^2 term is within
**      4.3 eps dS |e|, so the whole within 3.001 dS |e|;
**   the evaluation's rounding, 16 U of the terms' sizes, as in step_from;
**   x + e rounded (U (x + |e|)) where the speed is at most 2 (S + dS +
**      |b||e|) <= 2.13 S: 2.2 U S (x + |e|). */
static double short_bound(const arclen_quad_form *F, double x, double f,
                          double err, double S, double inv, double t2,
                          double t1, double ae, double dS) {
  return fabs(t1 + t2) + err
         + ae * (3.001 * dS + 32 * U * S + 0.37 * F->B * ae * ae * inv)
         + 16 * U * (fabs(f) + fabs(t2)) + 2.2 * U * S * (x + ae);
}

/* The step from x, where f = s(x) - g within err and |v(x)| = S > 0:
** x + *e with the bound *bound of |s(x + *e) - g|; 1 when that is within
** tol.  The speed's derivatives at x are exact expressions (the head):
** sigma = 2S, sigma' = 2u/S, sigma'' = 2k^2/S^3, sigma''' = -6k^2 u/S^5 (u
** = v.b), so e is, past the short step (below 2^-16 of |v|/|b|: the
** quadratic polynomial's root, short_bound), the root of the Taylor
** polynomial of fourth order by series reversion (as src/gauss/time.c's reversion_tail), whose value
** there is computed, and the remainder is max|sigma''''| |e|^5/120 with
** sigma'''' = 6k^2 (5u^2 - B S^2)/S^7, at most 24 k^2 B/|v|^5 in size
** (u^2 <= B S^2), and |v| >= m on the step.  The roundings, against the
** exact parabola of the scaled legs a and c (bounds in units of U, to
** first order, then times 3/2 where dS <= S/16; |c| is taken as Cs,
** above it):
**   S: speed_vector's components within 3 (|a_i| + |c_i|) of theirs (1 -
**      x itself rounded), the norm 2 of itself: dS = 6 (|a| + |c|) + 3 S
**      (near a cusp S is far below |a|: the error is not relative);
**   u = u0 + x B: u0 = a.b with b = c - a rounded, 3 |a||b|; B 4 of
**      itself; the product and the sum: du = 4 (|a| q + 2 x B) + |u|;
**   k = |a x c|: 6 |a||c| (the products before the difference);
** each derivative's error from those (first order), each times |e|^n/n!;
** the polynomial's own evaluation (f + sigma e = sigma tail to 3 |f| + 1
** sigma |e|, each term a few): 16 of the terms' sizes; and m from below
** with S - dS and (k - dk)/q.  The remainder's 24/120 is 0.2 rounded up. */
static int step_from(const arclen_quad_form *F, double x, double f,
                     double err, double S, double tol, double *e,
                     double *bound) {
  double u = F->u0 + x * F->B, inv = 1 / S, k = F->k, k2;
  double sig = 2 * S, s1 = 2 * u * inv, s2, s3;
  double h = inv / 2, d = -f * h;                       /* h = 1/sigma */
  double b2 = s1 * h / 2, b3, b4;
  double tail, ae, e2, e3, m, m2, t1, t2, t3, t4, dS, du, dk, dk2, rS, r;
  double kmin;
  /* the short step first: second order (e = d - b2 d^2) where it is below
  ** 2^-16 of |v|/|b|, certified by short_bound; else the fourth order */
  tail = -b2 * d * d;
  *e = d + tail;
  ae = fabs(*e);
  dS = U * (6 * (F->S0 + F->Cs) + 3 * S);
  if (F->q * ae <= 0x1p-16 * S && dS <= S / 16) {
    *bound = short_bound(F, x, f, err, S, inv, s1 / 2 * *e * *e, sig * tail,
                         ae, dS);
    if (*bound <= tol * (1 - 1.0 / 1024)) return 1;
  }
  k2 = k * k;
  s2 = 2 * k2 * inv * inv * inv;
  s3 = -3 * s2 * u * inv * inv;
  b3 = s2 * h * C6;
  b4 = s3 * h * C24;
  tail = d * d * (-b2 + d * (2 * b2 * b2 - b3
                             + d * (5 * b2 * (b3 - b2 * b2) - b4)));
  *e = d + tail;
  ae = fabs(*e);
  e2 = *e * *e;
  e3 = e2 * ae;
  /* the polynomial at e: f + sigma e = sigma tail (sigma d = -f); where
  ** it alone exceeds tol (a guess far off) the rest is not needed */
  t1 = sig * tail; t2 = s1 / 2 * e2;
  t3 = s2 * C6 * e2 * *e; t4 = s3 * C24 * e2 * e2;
  *bound = fabs(t1 + t2 + t3 + t4) + err;
  if (!(*bound <= tol)) return 0;
  du = U * (4 * (F->S0 * F->q + 2 * x * F->B) + fabs(u));
  dk = 6 * U * F->S0 * F->Cs;
  dk2 = (2 * k + dk) * dk;                    /* |k^2 - k_true^2| */
  rS = dS * inv;
  m = S - dS - F->q * (1 + 8 * U) * ae;  /* |v| on [x, x + e], from below */
  kmin = F->q > 0 ? (k - dk) / F->q * (1 - 4 * U) : 0;
  if (kmin > m) m = kmin;                       /* the least |v|, from below */
  if (!(m > 0) || !(rS <= 1.0 / 16)) return 0;
  m2 = m * m;
  /* the derivatives' errors times |e|^n/n! */
  r = 2 * dS * ae
      + (2 * du * inv + fabs(s1) * (rS + 2 * U)) * e2 / 2
      + (2 * dk2 * inv * inv * inv + s2 * (3 * rS + 4 * U)) * e3 * C6
      + (6 * (dk2 * fabs(u) + k2 * du) * inv * inv * inv * inv * inv
         + fabs(s3) * (5 * rS + 6 * U)) * e2 * e2 * C24;
  *bound += 0.2 * (k + dk) * (k + dk) * F->B / (m2 * m2 * m) * (e2 * e3)
           + 1.5 * r
           + 16 * U * (sig * ae + fabs(f) + fabs(t2) + fabs(t3) + fabs(t4))
           /* x + e rounded to a double moves by U (x + |e|), where the
           ** speed is at most 2 (|v(x)| + |b| |e|) */
           + 2 * (S + dS + F->q * ae) * U * (x + ae);
  /* the bound's own few roundings: a margin of 2^-10 */
  return *bound <= tol * (1 - 1.0 / 1024);
}

/* The measured point x: s(x), |v(x)| into *S and the bound of s(x)'s
** rounding (in units of U of it) into *r. */
static double measure(const arclen_quad_form *F, double x, double *S,
                      double *r) {
  double m1, S1, len;
  int gauss;
  len = arclen_quad_form_length(F, x, &m1, &S1, &gauss);
  *S = S1 >= 0 ? S1 : sqrt(m1);
  *r = gauss ? GAUSS_ROUNDING : FORM_ROUNDING;
  return len;
}

/* G^-1(y) for 0 <= y < 2^ARCLEN_QI_JMAX, G(U) = U sqrt(1 + U^2) + asinh U:
** below the table U = y/2 - y^3/48 (G = 2U + U^3/3 - U^5/20 ..., the next
** term 13 y^5/3840 is below 1e-11 of U there), else the piece's polynomial
** (quad_inverse_table.h: within ARCLEN_QI_EPS units of U of G^-1(y)). */
static ARCLEN_INLINE double g_inverse(double y) {
  const double *c;
  uint64_t bits, row;
  double r, r2;
  if (y < TABLE_MIN) return y / 2 * (1 - y * y / 24);
  /* from the bits: the row (the exponent and the mantissa's top bits,
  ** octave and piece counted on from the table's first) and r, the other
  ** bits as the place in the piece: an integer below 2^48 times 2^-47,
  ** less 1, all exact (the piece's centre at 0) */
  memcpy(&bits, &y, sizeof bits);
  row = (bits >> PIECE_BITS) - ((uint64_t)(1023 + ARCLEN_QI_JMIN)
                                << ARCLEN_QI_NSUB_BITS);
  c = arclen_qi_ginv[row >> ARCLEN_QI_NSUB_BITS][row & (ARCLEN_QI_NSUB - 1)];
  r = (double)(int64_t)(bits & (((uint64_t)1 << PIECE_BITS) - 1)) * PIECE_SCALE
      - 1;
  r2 = r * r;
  return ((c[0] + c[1] * r) + r2 * (c[2] + c[3] * r))
         + r2 * r2 * ((c[4] + c[5] * r) + r2 * (c[6] + c[7] * r));
}

/* The bound of |s(t) - g| for first_guess's t from the table, where every
** step from the legs a and c (exact: the curve) to t is a rounding or the
** table's error, none a measured length.  The form's values against those
** of the exact a, c (first order, units of U; 3D's dot products the worst):
** u0 = a.b with b = c - a rounded, du0 = 4 |a||b| (5 S0 q); B = |b|^2,
** 5 of itself (dB = 6 B); k = |a x c|, dk = 6 S0 Cs (step_from's);
** Su0 = q S0 against |a||b| = sqrt(u0^2 + k^2) (Lagrange's identity), 7
** (dR = 8 Su0); g B q against g |b|^3, 10.5.  So Y = H(u0) + g |b|^3,
** summed as T1 + T3 + T2 (T1 = u0 Su0, T2 = k^2 w, T3 = g B q, two sums:
** 2.1 of their sizes), is off by dY:
**   T1: its product (1), dR and du0's share: 11.1 |T1| + du0 Su0;
**   T2: w = log((|u0| + Su0) k/k^2) = asinh(|u0|/k) with the argument off
**      by 5.1 U (five roundings) + (du0 + dR)/Su0 + 1.02 dk/k = 18.2 U +
**      1.02 dk/k relative (dk <= k/64) and log within an ulp, k^2 itself
**      (2k + dk) dk and its product (1): k^2 (18.4 U + 5.2 U |w|) + 1.03 k
**      dk + (2k + dk) dk |w|;
**   T3: 14.2 of itself.
** u = k U with U = G^-1(y) within ARCLEN_QI_EPS, the product (1), and y =
** Y/k^2 (three roundings: k^2 y within 3.1 U of Y): u is off from the
** exact H^-1(Y) by (EPS + 1.01) U |u| + (dY + 3.1 U |Y|)/(2 min R) (H' =
** 2R, R = sqrt(u^2 + k^2) = |b||v|) and from the true k's by dk k
** asinh(|u|/k)/R <= dk min(1, 6.4 k/R) (dH/dk = 2k asinh(u/k) at fixed u;
** |U| < 256 in the table, asinh < 6.4).  t = (u - u0)/B, d = u - u0
** rounded, moves u0 + t B by U dd (dd >= 6 t B + 3.2 |d|: 3.2 U |d|, and
** the true u0, B by du0 + t dB).
** The true point is within D of the true goal's u, so s(t) within 2 max R
** D/|b|^3, max R and min R within R +- (2D + dk) on the way, where D and
** dk are below R/4096: max R/min R < 1 + 2^-9.  R from above without a
** root, Ru = max(|u|, k) + min(|u|, k)/2 (at most 3/2 of max(|u|, k), so
** 6.4 k/R <= 9.6 k/Ru), and M = 2 Ru D with no quotient: (1 + 2^-9) M/(B
** q), 1/(B q) = q/B^2.  The margins the caller takes (2^-10) cover the
** bound's own roundings.  Infinite where a check fails (the search then
** measures).  Every term grows with |u| and dd and falls with R^2, so the
** caller gives amax >= |u|, R2 <= u^2 + k^2 and dd: the table's own u
** (bound_at), or their bounds over every t in [0, 1) (first_guess: the
** bound then waits on Y, not on the table's answer). */
static ARCLEN_INLINE double direct_bound(const arclen_quad_form *F,
                                         double Y, double w, double Su0,
                                         double gBq, double iB, double amax,
                                         double R2, double dd) {
  double k = F->k, k2 = k * k, q = F->q, au0 = fabs(F->u0);
  double du0 = 5 * U * F->S0 * q, dk = 6 * U * F->S0 * F->Cs;
  double aw = fabs(w), Ru, dY, M;
  Ru = arclen_max(amax, k) + arclen_min(amax, k) / 2;         /* >= |b||v| */
  dY = U * (11.1 * au0 * Su0 + 14.2 * gBq + k2 * (18.4 + 5.2 * aw))
       + du0 * Su0 + 1.03 * k * dk + (2 * k + dk) * dk * aw;
  M = 2 * Ru * (du0 + U * dd + (ARCLEN_QI_EPS + 1.01) * U * amax)
      + (dY + 3.1 * U * fabs(Y)) * (1 + 1.0 / 512)
      + 2 * dk * arclen_min(Ru, 9.6 * k);
  if (!(64 * dk <= k && 4096 * 4096 * dk * dk <= R2 && 2048 * M <= R2))
    return HUGE_VAL;
  return M * (1 + 1.0 / 512) * q * (iB * iB);
}

/* direct_bound at the table's u, d and t: tighter than over [0, 1) (the
** tolerances below 512 U of g, 1e-14 and less, need it), out of line: the
** common path keeps none of its registers. */
static ARCLEN_NOINLINE double bound_at(const arclen_quad_form *F, double Y,
                                       double w, double Su0, double gBq,
                                       double iB, double u, double d,
                                       double t) {
  return direct_bound(F, Y, w, Su0, gBq, iB, fabs(u), u * u + F->k * F->k,
                      6 * t * F->B + 3.2 * fabs(d));
}

/* Whether the goal lies below L by more than M, so that t < 1 is the
** answer and not the clamp's t = 1 at L (else the search decides): L >=
** s(t) + 2 (1 - t) min |v| with s(t) >= g - M and |v| from below on [t,
** 1] (at least R/|b| past the vertex, where it grows, and k/|b|
** anywhere). */
static int before_end(const arclen_quad_form *F, double u, double t,
                      double M, double iB) {
  double k = F->k, dk = 6 * U * F->S0 * F->Cs, au = fabs(u);
  return (1 - t)
         * arclen_choose(u >= 0, arclen_max(au, k) * (1 - 1.0 / 1024), k - dk)
         * F->q * iB >= M;
}

/* The first t for the goal g, without the total: in u = v.b = u0 + t B,
** with S = sqrt(u^2 + k^2) (= |b| |v|), s(t) = (H(u) - H(u0))/|b|^3 with
** H(u) = u S + k^2 asinh(u/k) (the parabola's length; H' = 2S), so the
** goal's u solves H(u) = Y = H(u0) + g |b|^3, that is G(U) = y = Y/k^2
** for U = u/k.  Where y is in the table's range, t comes with the bound of
** its length's miss (direct_bound) in *bound, most often the answer
** without a length where it may be within room (the tol, or its bound from
** above); else *bound is infinite and t a guess for the search.  wide:
** room is at least 512 U of g, where the bound over every t in [0, 1)
** serves (at tol 1e-12 as often as the table's own t's, 9% less time).
** For y past the table U^2 = y - 1/2 - log(2U) - O(1/U^2) with log(2U) =
** log(4y)/2 - O(log y / y): u^2 = |Y| - k^2 (1/2 + log(4|y|)/2), within
** 1e-9; k = 0 (collinear legs) is the case u^2 = |Y| exactly.  Below the
** table, its series (g_inverse).  b = 0 (uniform speed 2|a|): g/(2|a|). */
static ARCLEN_INLINE double first_guess(const arclen_quad_form *F, double g,
                                        double room, int wide,
                                        double *bound) {
  double u0 = F->u0, k = F->k, k2 = k * k, B = F->B, q = F->q;
  double Su0 = q * F->S0, gBq = g * B * q, Y = u0 * Su0 + gBq, y = HUGE_VAL;
  double u, w = 0, iB, ik2, d, t, Y0 = Y;
  *bound = HUGE_VAL;
  if (B == 0) return g / (2 * F->S0);
  iB = 1 / B;                     /* waits on B only, not on the guess */
  if (k2 >= DBL_MIN) {  /* else k^2 asinh(u0/k) < 1e-305, left out: y huge */
    ik2 = 1 / k2;         /* y = Y ik2: a product, ik2 waits on k only */
    w = log((fabs(u0) + Su0) * k * ik2);     /* asinh(|u0|/k); 1/k = k/k^2 */
    Y += k2 * (u0 < 0 ? -w : w);
    y = Y * ik2;
  }
  if (fabs(y) < TABLE_MAX) {
    /* the bound is at least its T3 term, 14.2 U g: not tried past room */
    int tried = fabs(y) >= TABLE_MIN && room >= 16 * U * g;
    double M = HUGE_VAL;
    if (wide && tried) {
      /* over every t in [0, 1), so that it waits on Y, not on the
      ** table's answer, and runs beside it: u in [u0, u0 + B (1 + 3U)],
      ** so |u| at most umax, at least umin (0 where the vertex may lie
      ** inside); |u| <= sqrt(|Y|) (G(U) >= U^2), with |Y| from above
      ** before the log: |w| <= z (the log's argument) where z >= 1, and
      ** |w| < 0.02 where z < 1 (z >= (1 - 1/64)(1 - 4U) where 64 dk <= k,
      ** direct_bound's first check); t B and |d| each within 1.01 of
      ** min(B, umax - u0), so dd below 9.3 of it */
      double slack = 0x1p-40 * (fabs(u0) + B);
      double umax = arclen_max(fabs(u0), fabs(u0 + B)) + slack;
      double umin = arclen_max(arclen_max(u0, -(u0 + B) - slack), 0);
      double Yup = fabs(Y0) + k * (fabs(u0) + Su0) + 0.02 * k2;
      umax = arclen_min(umax, sqrt(Yup) * (1 + 0x1p-40));
      /* R^2 >= |Y|/2 too (|H(u)| <= |u| R + k |u| <= 2 R^2) */
      M = direct_bound(F, Y, w, Su0, gBq, iB, umax,
                       arclen_max(umin * umin + k2,
                                  fabs(Y) / 2 * (1 - 0x1p-40)),
                       9.3 * arclen_min(B, umax - u0));
    }
    /* y's sign without a branch (a coin toss from one segment to the
    ** next); y = -0 (Y's underflow only) gives u = -0, the same d */
    u = copysign(k * g_inverse(fabs(y)), y);
    d = u - u0;
    t = d * iB;
    if (!wide && tried) M = bound_at(F, Y, w, Su0, gBq, iB, u, d, t);
    if (M < HUGE_VAL && before_end(F, u, t, M, iB)) *bound = M;
    return t;
  }
  /* far from the vertex, or k^2 below DBL_MIN */
  w = fabs(Y);
  if (k2 >= DBL_MIN && isfinite(y)) w -= k2 * (0.5 + 0.5 * log(4 * fabs(y)));
  u = w > 0 ? sqrt(w) : 0;
  if (Y < 0) u = -u;
  return (u - u0) * iB;
}

/* The segment's length in its units, measured where the caller has none
** (*total not positive and finite); 0 where it overflows. */
static int know_total(const arclen_quad_form *F, double *total) {
  int gauss;
  if (*total > 0 && isfinite(*total)) return 1;
  *total = arclen_quad_whole(F->p, F->dim, &gauss);  /* the length's bits */
  return isfinite(*total);
}

/* A lower bound of the scaled length from the measured point x: s(x) = len
** (within 16 U) plus 2 (1 - x) min |v| over [x, 1], where |v| grows past
** the vertex (u = v.b >= 0: S = |v(x)|), falls up to it (u(1) <= 0: |c|
** = |v(1)|) or is least there.  The least |v| of all is k/|b|, from below
** (k - dk)/q as in step_from; S and |c| are taken less 32 U (S0 + Cs),
** which covers their roundings (step_from's dS) and, where u's sign is in
** doubt (|u| <= du), |v(x)| - k/|b| <= du/q <= 13 U (S0 + Cs).  All less
** 2^-30 of itself, which covers len's rounding. */
static double length_below(const arclen_quad_form *F, double x, double len,
                           double S) {
  double m, slack = 32 * U * (F->S0 + F->Cs);
  int past = F->u0 + x * F->B >= 0;       /* a coin toss: no branch on it */
  if (!past & (F->u0 + F->B <= 0)) m = arclen_quad_form_speed(F, 1) - slack;
  else m = arclen_choose(past, S - slack,
                         (F->k - 6 * U * F->S0 * F->Cs) / F->q * (1 - 4 * U));
  return (len + 2 * (1 - x) * (m > 0 ? m : 0)) * (1 - 0x1p-30);
}

/* s at or past the length total: t = 1, the total's length (no bound). */
static int at_end(double total, double from[3], double *t) {
  *t = from[0] = 1;
  from[1] = total;
  from[2] = HUGE_VAL;
  return ARCLEN_OK;
}

/* A lazy search's end: the total measured (where the caller has none) and
** the scaled T and tol from it.  1 where the search goes on; else 0 with
** *rc: the length overflows, or s is at or past it (t = 1, at_end). */
static int settle(const arclen_quad_form *F, double *total, double rtol,
                  double s, double *T, double *tol, double from[3],
                  double *t, int *rc) {
  if (!know_total(F, total)) {
    *rc = ARCLEN_EOVERFLOW;
    return 0;
  }
  if (!(s < *total)) {
    *rc = at_end(*total, from, t);
    return 0;
  }
  *T = times_pow2(*total, -F->scale, F->down);
  *tol = times_pow2(rtol * *total, -F->scale, F->down);
  return 1;
}

/* Whether the bound bnd of a length's miss is within tol (in a lazy
** search, L >= s(x) >= g - bnd for x < 1 gives rtol (g - bnd)), less the
** margin of the bound's own roundings. */
static int within(double bnd, int lazy, double rtol, double g, double tol) {
  return bnd <= (lazy ? rtol * (g - bnd) : tol) * (1 - 1.0 / 1024);
}

/* The certified answer t at the distance s, with the bound of its length's
** miss (scaled) into from. */
static int answer(const arclen_quad_form *F, double t, double s, double bnd,
                  double from[3], double *out) {
  *out = from[0] = t;
  from[1] = s;
  from[2] = times_pow2(bnd, F->scale, F->up);
  return ARCLEN_OK;
}

int arclen_quad_time(const arclen_quad_form *F, double *total, double s,
                     double rtol, double from[3], double *t, long *evals) {
  int e2 = -F->scale, i, lazy, ok, rc;
  double down = F->down, up = F->up;
  double g, T = NAN, tol = 0, lo, hi = 1, x = -1, f, err, S, e = 0, bnd, len, r;
  double best, bestf, bestlen, besterr, last = HUGE_VAL;
  *evals = 0;
  if (F->zero) {                     /* a point: every length is 0 */
    *t = from[0] = from[1] = from[2] = 0;
    return ARCLEN_OK;
  }
  /* the scaled form's units: exact (powers of two; a goal that becomes
  ** subnormal loses digits below 2^-1074 of a length near 1) */
  g = times_pow2(s, e2, down);
  /* A first search (from 0) for an s in (0, S0 + Cs), at least the
  ** control polygon's length (>= L), needs no total: tol comes from a
  ** lower bound of L after its first length (length_below), so the
  ** total's closed form is off the search's chain; it is measured only
  ** where that bound is too strict or s may reach L (the clamp below, t =
  ** 1 at L). */
  lazy = !(*total > 0 && isfinite(*total)) && from[0] == 0 && from[1] == 0
         && from[2] == 0 && s > 0 && g < F->S0 + F->Cs && e2 > -1000
         && e2 < 1000;
  if (!lazy) {
    if (!know_total(F, total)) return ARCLEN_EOVERFLOW;
    tol = rtol * *total;
    /* the certified start already answers (a distance within tol of the
    ** last one), or lies beyond s (unsorted input): start from 0 */
    if (fabs(from[1] - s) + from[2] <= tol) { *t = from[0]; return ARCLEN_OK; }
    if (from[1] > s) from[0] = from[1] = from[2] = 0;
    if (!(s > 0)) { *t = from[0] = from[1] = from[2] = 0; return ARCLEN_OK; }
    /* total: the caller's, no bound of its own */
    if (!(s < *total)) return at_end(*total, from, t);
    T = times_pow2(*total, e2, down);
    tol = times_pow2(tol, e2, down);
  }
  lo = from[0];
  if (!(lo > 0)) {
    /* the table's answer where its bound is within tol: in a lazy search
    ** L >= s(x) >= g - bnd for x < 1 gives tol */
    double room = lazy ? rtol * g : tol;
    x = first_guess(F, g, room, room >= 512 * U * g, &bnd);
    if (x >= 0 && x < 1 && within(bnd, lazy, rtol, g, tol))
      return answer(F, x, s, bnd, from, t);
  }
  /* the search's start: the last answer's length and its bound */
  bestlen = times_pow2(from[1], e2, down);
  besterr = times_pow2(from[2], e2, down);
  if (lo > 0) {
    /* a sweep's last answer: the step from it, its bound carried */
    S = arclen_quad_form_speed(F, lo);     /* no length measured there */
    f = bestlen - g;
    if (S > 0 && step_from(F, lo, f, besterr + U * fabs(f), S, tol, &e, &bnd)
        && lo + e > lo && lo + e < 1)
      return answer(F, lo + e, s, bnd, from, t);
    x = S > 0 ? lo + e : -1;
  }
  best = lo;
  bestf = fabs(bestlen - g);
  if (!(x > lo && x < hi) && lazy) {          /* the fallbacks need T */
    lazy = 0;
    if (!settle(F, total, rtol, s, &T, &tol, from, t, &rc)) return rc;
  }
  if (!(x > lo && x < hi)) x = lo + (hi - lo) * (g - bestlen) / (T - bestlen);
  if (!(x > lo && x < hi)) x = lo + (hi - lo) / 2;
  for (i = 0; i < MAX_STEPS; i++) {
    len = measure(F, x, &S, &r);
    ++*evals;
    f = len - g;
    /* the closed form's rounding and the difference's */
    err = r * U * len + U * fabs(f);
    if (lazy) {
      double below = length_below(F, x, len, S);
      if (g < below) {
        tol = rtol * below;
      } else {                     /* s may be L or past it: the clamp */
        lazy = 0;
        if (!settle(F, total, rtol, s, &T, &tol, from, t, &rc)) return rc;
      }
    }
    /* a measured length within tol answers (the closed form is the
    ** length's reference, as for arclen_quad_length itself) */
    if (fabs(f) <= tol || fabs(f) < bestf) {
      best = x; bestf = fabs(f); bestlen = len; besterr = err;
      if (fabs(f) <= tol) break;
    }
    if (f < 0) lo = x; else hi = x;
    ok = S > 0 && step_from(F, x, f, err, S, tol, &e, &bnd)
         && x + e > lo && x + e < hi;
    if (!ok && lazy) {       /* too strict a tol, perhaps: L's own, again */
      lazy = 0;
      if (!settle(F, total, rtol, s, &T, &tol, from, t, &rc)) return rc;
      ok = S > 0 && step_from(F, x, f, err, S, tol, &e, &bnd)
           && x + e > lo && x + e < hi;
    }
    if (ok) return answer(F, x + e, s, bnd, from, t);
    e = S > 0 ? x + e : -1;                 /* not certified: measure it */
    if (!arclen_step_ok(e, x, lo, hi, last)) e = lo + (hi - lo) / 2;
    if (e == x || !(e > lo && e < hi)) break;      /* lo, hi adjacent */
    last = fabs(e - x);
    x = e;
  }
  *t = from[0] = best;
  from[1] = times_pow2(bestlen, F->scale, up);
  from[2] = times_pow2(besterr, F->scale, up);
  return ARCLEN_OK;
}
