/*
** elliptic.c -- exact arc length of a cubic Bezier curve by Carlson's
** elliptic integral [1,1,1,1] (method "elliptic"), made robust.
**
** Henkel (seed 003, Eqns 7-11) writes the length as int sqrt(Q(t)) dt with
** the quartic Q = |z'|^2 split into two quadratics and evaluates Carlson's
** (1992) formula; it failed on exact cusps, collinear curves and near
** cusps.  Here (doc/papers.md, "Henkel"):
** - 2D: z'(t) = A2 t^2 + A1 t + A0 is a complex quadratic with roots s1,
**   s2, so sqrt(Q) = |A2| |t - s1| |t - s2| exactly: no quartic solver.
**   3D: Q is split by the quartic solver (roots.c).
** - exact cusps and collinear curves (a root on the real axis) have
**   elementary integrals; points have length exactly 0;
** - a root far from the interval is expanded in a series (elliptic_far.c);
** - otherwise Carlson's formula with the corrected list and parameters
**   free of cancellation.
*/
#include <math.h>

#include "arclen.h"
#include "curve/cplx.h"
#include "curve/cubic.h"
#include "elliptic/elliptic.h"

/* The hodograph of c (dim 2 or 3) for [y, x], scaled by an exact power of
** two so its largest coefficient is in [0.5, 1) (cubic.c); returns 0 for a
** point, else 1 with the scale's exponent in *ex (kept as an exponent: for
** coordinates near DBL_MAX the hodograph, 6 x a leg, exceeds the double
** range while the length fits -- results are set by ldexp). */
static int local_hodograph(const double *c, int dim, double y, double x,
                           double a2[3], double a1[3], double a0[3],
                           int *ex) {
  arclen_hodo h;
  int k;
  if (y == 0) {
    /* [0, x]: the power basis about 0 is the sub-curve's, up to the
    ** scale of t (which would only add a rounding) */
    arclen_hodo_scaled(c, dim, &h);
  } else {
    /* A sub-range [y, x], y > 0: its own hodograph in s in [-1, 1], each
    ** coefficient correct to rounding (cubic.c, double-double from the
    ** exact differences).  The whole curve's power basis errs by eps |h|max,
    ** which beside a stop or a near-cusp is all of a short sub-range's
    ** length; so do Bernstein points of the sub-curve formed by de
    ** Casteljau (their second difference, (x - y)^2 A2, drowned in their
    ** rounding: 4e6 relative on a range 1e-11 wide at a near-cusp,
    ** spec/data/subranges.tsv). */
    arclen_hodo_local(c, dim, y, x, &h);
  }
  if (h.zero) return 0;
  for (k = 0; k < dim; k++) {
    a2[k] = h.a2[k];
    a1[k] = h.a1[k];
    a0[k] = h.a0[k];
  }
  *ex = h.exp;
  return 1;
}

/* 2D: the complex hodograph's roots by the stable quadratic formula
** (the sign of the root of the discriminant avoids cancellation in
** A1 + d), then |A2| int |t - s1||t - s2|; *k gets |A2| or, when one root
** is beyond double range, the factor that replaces it. */
static double length2d(const double a2[3], const double a1[3],
                       const double a0[3], double y, double x,
                       const char **branch, long *calls) {
  arclen_cx A2 = arclen_cx_make(a2[0], a2[1]);
  arclen_cx A1 = arclen_cx_make(a1[0], a1[1]);
  arclen_cx A0 = arclen_cx_make(a0[0], a0[1]), d, q, s1, s2;
  double aq, m2 = fmax(fabs(a2[0]), fabs(a2[1]));
  double m1 = fmax(fabs(a1[0]), fabs(a1[1])), m0 = fmax(fabs(a0[0]), fabs(a0[1]));
  /* terms below 2^-56 of the larger lower ones are below a rounding of
  ** the length (as in elliptic3d.c); kept, a subnormal A2 beside A1 ~ 1e-323
  ** put a root near the range and the length at 0 (fuzz/fuzz_length) */
  if (m2 <= 0x1p-56 * fmax(m1, m0)) A2 = arclen_cx_make(0, 0);
  if (arclen_cx_is_zero(A2) && m1 <= 0x1p-56 * m0) A1 = arclen_cx_make(0, 0);
  if (arclen_cx_is_zero(A2) && arclen_cx_is_zero(A1)) {
    *branch = "line";                    /* constant velocity */
    return arclen_cx_abs(A0) * (x - y);
  }
  /* d = sqrt(A1^2 - 4 A2 A0) on the side of A1, q = -(A1 + d)/2 */
  d = arclen_cx_sqrt(arclen_cx_sub(arclen_cx_mul(A1, A1),
                                   arclen_cx_mul(arclen_cx_scale(4, A2), A0)));
  if (arclen_cx_mul(arclen_cx_conj(A1), d).re < 0) d = arclen_cx_neg(d);
  q = arclen_cx_div_re(arclen_cx_neg(arclen_cx_add(A1, d)), 2);
  aq = arclen_cx_abs(q);
  if (aq == 0) {              /* A1 = A0 = 0: z' = A2 t^2, a double root */
    *branch = "collinear";
    return arclen_cx_abs(A2) * (x * x * x - y * y * y) / 3;
  }
  s2 = arclen_cx_div(A0, q);
  /* |A2||t - s1| = |q - A2 t| = |q| (1 + O(|A2/q|)) for t in [0, 1]:
  ** with |A2| <= 2^-56 |q| (or A2 = 0, a degree-elevated quadratic) the
  ** far factor is the constant |q| to double precision. */
  if (arclen_cx_abs(A2) <= 0x1p-56 * aq) {
    double a = s2.re, b = fabs(s2.im);
    *branch = "quadratic";
    return aq * arclen_ell_single(a, b, y, x);
  }
  s1 = arclen_cx_div(q, A2);
  return arclen_cx_abs(A2) * arclen_ell_product(s1.re, fabs(s1.im), s2.re,
                                                fabs(s2.im), y, x, branch,
                                                calls);
}

int arclen_length_elliptic(const double *c, int dim, const arclen_opts *o,
                           double *len, arclen_info *info) {
  double a2[3], a1[3], a0[3], y = o->t0, x = o->t1, v;
  const char *branch = "point";
  long calls = 0;
  int e, ex = 0, nonzero;
  *len = NAN;
  if (info != NULL) arclen_info_init(info);
  if (dim != 2 && dim != 3) return ARCLEN_EDIM;
  e = arclen_check_curve(c, dim);
  if (e != ARCLEN_OK) return e;
  if (!(y >= 0 && y <= 1 && x >= 0 && x <= 1)) return ARCLEN_ERANGE;
  if (x < y) { v = x; x = y; y = v; }
  nonzero = x > y && local_hodograph(c, dim, y, x, a2, a1, a0, &ex);
  if (!nonzero) {
    v = 0;                               /* a point, or an empty range */
    if (x == y) branch = "empty";
  } else {
    /* the integral over [y, x], or over s in [-1, 1] of the range's own
    ** hodograph, t = (x + y)/2 + s (x - y)/2 */
    double lo = y == 0 ? 0 : -1, hi = y == 0 ? x : 1;
    double f = y == 0 ? 1 : (x - y) / 2;
    if (dim == 2) {
      v = length2d(a2, a1, a0, lo, hi, &branch, &calls);
    } else {
      e = arclen_ell_length3d(a2, a1, a0, lo, hi, &branch, &calls, &v);
      if (e != ARCLEN_OK) return e;
    }
    v *= f;
  }
  /* in hodograph units v is at most 3 (|a_k| < 1): never inf */
  if (isfinite(v)) {
    v = ldexp(v, ex);
  } else {
    /* never NaN: should a branch fail (none has on the reference sets),
    ** the error-controlled default method answers, and says so */
    arclen_opts g = *o;
    g.rtol = ARCLEN_RTOL_MIN;
    branch = "fallback";
    e = arclen_length_gauss(c, dim, &g, &v, NULL);
    if (e != ARCLEN_OK) return e;
    v = fabs(v);
  }
  *len = o->t0 > o->t1 ? -v : v;
  if (info != NULL) {
    info->branch = branch;
    info->calls = calls;
    info->pieces = 1;
  }
  return ARCLEN_OK;
}
