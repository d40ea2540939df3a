/*
** elliptic.c -- exact arc length of a cubic Bezier curve by Carlson's
** elliptic integral [1,1,1,1] (method "elliptic"), made robust.
**
** Henkel (seed 003, Eqns 7-11) writes the length as int sqrt(Q(t)) dt with
** the quartic Q = |z'|^2 split into two quadratics and evaluates Carlson's
** (1992) formula; it failed on exact cusps, collinear curves and near
** cusps.  Here (shared/notes/elliptic.md):
** - 2D: z'(t) = A2 t^2 + A1 t + A0 is a complex quadratic with roots s1,
**   s2, so sqrt(Q) = |A2| |t - s1| |t - s2| exactly: no quartic solver.
**   3D: Q is split by the quartic solver (roots.c).
** - exact cusps and collinear curves (a root on the real axis) have
**   elementary integrals; points have length exactly 0;
** - a root far from the interval is expanded in a series (elliptic_far.c);
** - otherwise Carlson's formula with the corrected list and parameters
**   free of cancellation.
*/
#include <complex.h>
#include <math.h>

#include "arclen.h"
#include "cubic.h"
#include "elliptic.h"

/* A root this close to the real axis, relative to the interval length,
** is treated as on it: the integrand changes by less than b^2 log(1/b)
** ~ 2e-17 relative (b = 1e-9), and Carlson's R_F would diverge. */
#define CUSP_B 1e-9

/* int_p^q |t - a1| |t - a2| dt with p < q and no a_k inside (p, q): the
** integrand is a quadratic of one sign, so Simpson's rule is exact and
** adds three values of one sign. */
static double simpson_real(double a1, double a2, double p, double q) {
  double m = (p + q) / 2;
  return (q - p) / 6 * (fabs((p - a1) * (p - a2)) + 4 * fabs((m - a1) * (m - a2))
                        + fabs((q - a1) * (q - a2)));
}

/* Both roots real: split [y, x] at the roots inside it. */
static double closed_real(double a1, double a2, double y, double x) {
  double cut[4], s = 0;
  int n = 0, i;
  double lo = fmin(a1, a2), hi = fmax(a1, a2);
  cut[n++] = y;
  if (lo > y && lo < x) cut[n++] = lo;
  if (hi > y && hi < x && hi != lo) cut[n++] = hi;
  cut[n++] = x;
  for (i = 0; i + 1 < n; i++) s += simpson_real(a1, a2, cut[i], cut[i + 1]);
  return s;
}

/* int_p^q (t - a) sqrt((t - a2)^2 + b2^2) dt with u = t - a2:
** = J1 + (a2 - a) J0 (moments of the second factor). */
static double cusp_piece(double a, double a2, double b2, double p, double q) {
  double v = p - a2, w = q - a2;
  return arclen_ell_j1(v, w, b2) + (a2 - a) * arclen_ell_j0(v, w, b2);
}

/* Exact cusp: root 1 real (b1 = 0), root 2 anywhere. */
static double closed_cusp(double a1, double a2, double b2, double y,
                          double x) {
  if (a1 <= y) return cusp_piece(a1, a2, b2, y, x);
  if (a1 >= x) return -cusp_piece(a1, a2, b2, y, x);
  return -cusp_piece(a1, a2, b2, y, a1) + cusp_piece(a1, a2, b2, a1, x);
}

/* r - w and r + w for r = hypot(w, b) >= |w|: the one that would cancel
** is b^2 / (the other) (shared/notes/elliptic.md). */
static void diffsum(double r, double w, double b, double *minus,
                    double *plus) {
  if (w >= 0) { *plus = r + w; *minus = *plus > 0 ? b * b / *plus : 0; }
  else { *minus = r - w; *plus = *minus > 0 ? b * b / *minus : 0; }
}

/* zeta^2 = (xi + eta)^2 - (x - y)^2 for xi = |x - s|, eta = |y - s|:
** [(xi - u) + (eta + v)] [(xi + u) + (eta - v)], u = x - a, v = y - a. */
static double zeta2(double xi, double eta, double u, double v, double b) {
  double xm, xp, em, ep;
  diffsum(xi, u, b, &xm, &xp);
  diffsum(eta, v, b, &em, &ep);
  return (xm + ep) * (xp + em);
}

/* Carlson (1992) [1,1,1,1] for monic q_k = (t - a_k)^2 + b_k^2 (h_k = 1,
** f_k = a_k^2 + b_k^2, g_k = -2 a_k), integral from y to x > y, with the
** two corrections of the seed's transcription (X0 with eta1', the factor
** 4 h1 h2 delta12^2) and the cancellation-free parameters of the note. */
static double carlson_1111(double a1, double b1, double a2, double b2,
                           double y, double x, long *calls) {
  double l = x - y;
  double u1 = x - a1, v1 = y - a1, u2 = x - a2, v2 = y - a2;
  double xi1 = hypot(u1, b1), eta1 = hypot(v1, b1);
  double xi2 = hypot(u2, b2), eta2 = hypot(v2, b2);
  double xi1p = u1 / xi1, eta1p = v1 / eta1;
  double bb = xi1p * xi2 - eta1p * eta2;
  double ee = u1 * xi1 * xi2 - v1 * eta1 * eta2;
  double th1 = 2 * (b1 * b1 + u1 * v1), th2 = 2 * (b2 * b2 + u2 * v2);
  double z1 = zeta2(xi1, eta1, u1, v1, b1), z2 = zeta2(xi2, eta2, u2, v2, b2);
  double uu = (xi1 * eta2 + eta1 * xi2) / l;
  double m2 = (z1 / l) * (z2 / l);
  double d11 = 4 * b1 * b1, d22 = 4 * b2 * b2;
  double da = a1 - a2;
  double d12 = 2 * (da * da + b1 * b1 + b2 * b2);
  double rm = hypot(da, b1 - b2), rp = hypot(da, b1 + b2);
  double del = 2 * rm * rp, dp = (rp + rm) * (rp + rm);
  double dm = 16 * (b1 * b1) * (b2 * b2) / dp;
  double lm2 = m2 + dm, lp2 = m2 + dp;
  double rf = arclen_rf(m2, lm2, lp2), rd = arclen_rd(m2, lm2, lp2);
  double g = 2 * del * dp * rd / 3 + del / (2 * uu)
             + (d12 * th1 - d11 * th2) / (4 * xi1 * eta1 * uu);
  double sig = g - dp * rf + bb;
  double a1111 = xi1 * xi2 - eta1 * eta2;
  double s = (xi1 * eta1 * th2 + xi2 * eta2 * th1) / (l * l);
  double lam0 = d11, om2 = m2 + lam0;
  double psi0 = 2 * (a2 - a1);
  double x0 = -(xi1p * xi2 + eta1p * eta2) / l;
  double mu0 = 1 / (xi1 * eta1);
  double t0 = mu0 * s + 2;
  double v02 = mu0 * mu0 * (s * s + lam0 * uu * uu);
  double b02 = (s * s / (uu * uu) + lam0) * om2 * om2;
  double a02 = b02 + lam0 * (dp - lam0) * (lam0 - dm);
  double h0 = d11 * psi0 * (arclen_rj(m2, lm2, lp2, om2) / 3
                            + arclen_rc(a02, b02) / 2)
              - x0 * arclen_rc(t0 * t0, v02);
  *calls += 5;
  return (d22 - d11) * (psi0 * h0 + (lam0 - d12) * rf) / 8
         - (3 * psi0 * psi0 - 4 * d12) * (sig + d12 * rf) / 24
         + (del * del * rf - psi0 * a1111) / 12 + ee / 3;
}

/* I = int_y^x |t - s1||t - s2| dt (y < x, b_k >= 0): pick the branch. */
double arclen_ell_product(double a1, double b1, double a2, double b2,
                          double y, double x, const char **branch,
                          long *calls) {
  double m = (x + y) / 2, h = (x - y) / 2, l = x - y;
  double r1 = hypot(a1 - m, b1), r2 = hypot(a2 - m, b2);
  double reach1 = fmax(fabs(x - a1), fabs(y - a1));
  double reach2 = fmax(fabs(x - a2), fabs(y - a2));
  /* both roots far: the integrand is analytic well beyond [y, x] */
  if (h <= ELL_RHO * r1 && h <= ELL_RHO * r2) {
    *branch = "series-both";
    return arclen_ell_series_both(a1, b1, a2, b2, y, x);
  }
  if (b1 <= CUSP_B * l) b1 = 0;
  if (b2 <= CUSP_B * l) b2 = 0;
  /* one root far from the other root's reach: series in the far factor */
  if (fmax(b1, reach1) <= ELL_RHO * hypot(a2 - a1, b2)) {
    *branch = "series-far";
    return arclen_ell_series_one(a1, b1, a2, b2, y, x);
  }
  if (fmax(b2, reach2) <= ELL_RHO * hypot(a1 - a2, b1)) {
    *branch = "series-far";
    return arclen_ell_series_one(a2, b2, a1, b1, y, x);
  }
  if (b1 == 0 && b2 == 0) {
    *branch = "collinear";
    return closed_real(a1, a2, y, x);
  }
  if (b1 == 0 || b2 == 0) {
    *branch = "cusp";
    return b1 == 0 ? closed_cusp(a1, a2, b2, y, x)
                   : closed_cusp(a2, a1, b1, y, x);
  }
  *branch = "carlson";
  return carlson_1111(a1, b1, a2, b2, y, x, calls);
}

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
  double complex A2 = a2[0] + I * a2[1], A1 = a1[0] + I * a1[1];
  double complex A0 = a0[0] + I * a0[1], d, q, s1, s2;
  double aq, m2 = fmax(fabs(a2[0]), fabs(a2[1]));
  double m1 = fmax(fabs(a1[0]), fabs(a1[1])), m0 = fmax(fabs(a0[0]), fabs(a0[1]));
  /* terms below 2^-56 of the larger lower ones are below a rounding of
  ** the length (as in elliptic3d.c); kept, a subnormal A2 beside A1 ~ 1e-323
  ** put a root near the range and the length at 0 (fuzz/fuzz_length) */
  if (m2 <= 0x1p-56 * fmax(m1, m0)) A2 = 0;
  if (A2 == 0 && m1 <= 0x1p-56 * m0) A1 = 0;
  if (A2 == 0 && A1 == 0) {              /* constant velocity: a line */
    *branch = "line";
    return cabs(A0) * (x - y);
  }
  d = csqrt(A1 * A1 - 4 * A2 * A0);
  if (creal(conj(A1) * d) < 0) d = -d;
  q = -(A1 + d) / 2;
  aq = cabs(q);
  if (aq == 0) {              /* A1 = A0 = 0: z' = A2 t^2, a double root */
    *branch = "collinear";
    return cabs(A2) * (x * x * x - y * y * y) / 3;
  }
  s2 = A0 / q;
  /* |A2||t - s1| = |q - A2 t| = |q| (1 + O(|A2/q|)) for t in [0, 1]:
  ** with |A2| <= 2^-56 |q| (or A2 = 0, a degree-elevated quadratic) the
  ** far factor is the constant |q| to double precision. */
  if (cabs(A2) <= 0x1p-56 * aq) {
    double a = creal(s2), b = fabs(cimag(s2));
    *branch = "quadratic";
    return aq * arclen_ell_single(a, b, y, x);
  }
  s1 = q / A2;
  return cabs(A2) * arclen_ell_product(creal(s1), fabs(cimag(s1)), creal(s2),
                                     fabs(cimag(s2)), y, x, branch, calls);
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
