/*
** product.c -- the integral at the heart of the elliptic method,
** I = int_y^x |t - s1| |t - s2| dt (y < x, s_k = a_k + i b_k, b_k >= 0),
** by the branch that suits the roots: a series when a root is far from the
** interval (elliptic_far.c), elementary closed forms when a root is on the
** real axis (an exact cusp, a collinear curve), and otherwise Carlson's
** (1992) [1,1,1,1] formula with R_F, R_D, R_J (carlson.c) and parameters
** written free of cancellation.  The plane and the space method both end
** here (elliptic.c, elliptic3d.c); the length is |A2| I (Henkel Eqn 7-10).
*/
#include <math.h>

#include "arclen.h"
#include "elliptic/elliptic.h"

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

/* r - w and r + w for r = ell_hypot(w, b) >= |w|: the one that would cancel
** is b^2 / (the other) (doc/papers.md, "Henkel"). */
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
** 4 h1 h2 delta12^2) and the cancellation-free parameters of the note.
**
** Near a cusp (b1 -> 0 with a1 inside [y, x]) M^2 and Lm^2 = M^2 + dm
** tend to 0 together and R_F(M^2, Lm^2, Lp^2), R_D(M^2, Lm^2, Lp^2) both
** diverge like log(1/b1), while the integral stays finite: Carlson's sum
** cancelled to 50x its value (2.9e-14 at b1 ~ 1e-7).  So R_D is traded for
** R_G by DLMF 19.21.10 (2 R_G = z R_F - (x - z)(y - z) R_D/3 + sqrt(xy/z),
** here (x - z)(y - z) = dp (dp - dm) = 2 delta dp), and R_G is written
** with its middle argument Lm^2 last, where all three terms are positive:
**   2 R_G = Lm^2 R_F + (2 delta/3) dm R_D(M^2, Lp^2, Lm^2)
**           + 2 delta sqrt(M^2/(Lm^2 Lp^2)) + sqrt(M^2 Lm^2/Lp^2).
** The coefficients of R_F then sum in closed form to
**   K = 2 b1^2 (da^2 + 4 b2^2/3) + dm (da^2 - 2 b1^2 - 2 b2^2)/6,
** O(b1^2), so the divergent part carries no weight; with b1 <= b2 (the
** caller's order) every term is within ~6x the integral. */
static double carlson_1111(double a1, double b1, double a2, double b2,
                           double y, double x, long *calls) {
  double l = x - y;
  double u1 = x - a1, v1 = y - a1, u2 = x - a2, v2 = y - a2;
  double xi1 = ell_hypot(u1, b1), eta1 = ell_hypot(v1, b1);
  double xi2 = ell_hypot(u2, b2), eta2 = ell_hypot(v2, b2);
  double xi1p = u1 / xi1, eta1p = v1 / eta1;
  double bb = xi1p * xi2 - eta1p * eta2;
  double ee = u1 * xi1 * xi2 - v1 * eta1 * eta2;
  double th1 = 2 * (b1 * b1 + u1 * v1), th2 = 2 * (b2 * b2 + u2 * v2);
  double z1 = zeta2(xi1, eta1, u1, v1, b1), z2 = zeta2(xi2, eta2, u2, v2, b2);
  double uu = (xi1 * eta2 + eta1 * xi2) / l;
  double m2 = (z1 / l) * (z2 / l);
  double d11 = 4 * b1 * b1, d22 = 4 * b2 * b2;
  double da = a1 - a2, da2 = da * da, bs = b1 * b1 + b2 * b2;
  double d12 = 2 * (da2 + bs);
  double rm = ell_hypot(da, b1 - b2), rp = ell_hypot(da, b1 + b2);
  double del = 2 * rm * rp, dp = (rp + rm) * (rp + rm);
  double dm = 16 * (b1 * b1) * (b2 * b2) / dp;
  double lm2 = m2 + dm, lp2 = m2 + dp;
  double rf, rdm, rj;
  /* 3 psi0^2 - 4 delta12 with psi0 = -2 da */
  double w = 4 * da2 - 8 * bs;
  double kf = 2 * (b1 * b1) * (da2 + 4 * (b2 * b2) / 3) + dm * (da2 - 2 * bs) / 6;
  double gr = del / (2 * uu) + (d12 * th1 - d11 * th2) / (4 * xi1 * eta1 * uu);
  double rg2;
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
  double h0;
  /* R_F, R_D(M^2, Lp^2, Lm^2), R_J(M^2, Lm^2, Lp^2, Omega^2) by one
  ** duplication of (M^2, Lp^2, Lm^2) (R_F and R_J are symmetric in x, y, z) */
  arclen_rfdj(m2, lp2, lm2, om2, &rf, &rdm, &rj);
  rg2 = 2 * del * (dm * rdm / 3 + sqrt(m2 / lm2 / lp2));
  h0 = d11 * psi0 * (rj / 3 + arclen_rc(a02, b02) / 2)
       - x0 * arclen_rc(t0 * t0, v02);
  *calls += 5;
  return (d22 - d11) * psi0 * h0 / 8 + w * (rg2 - gr - bb) / 24
         - psi0 * a1111 / 12 + ee / 3 + kf * rf;
}

/* I = int_y^x |t - s1||t - s2| dt (y < x, b_k >= 0): pick the branch. */
double arclen_ell_product(double a1, double b1, double a2, double b2,
                          double y, double x, const char **branch,
                          long *calls) {
  double m = (x + y) / 2, h = (x - y) / 2, l = x - y;
  double r1 = ell_hypot(a1 - m, b1), r2 = ell_hypot(a2 - m, b2);
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
  if (fmax(b1, reach1) <= ELL_RHO * ell_hypot(a2 - a1, b2)) {
    *branch = "series-far";
    return arclen_ell_series_one(a1, b1, a2, b2, y, x);
  }
  if (fmax(b2, reach2) <= ELL_RHO * ell_hypot(a1 - a2, b1)) {
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
  /* the root nearer the axis first: its b1^2 weights the divergent R_F */
  return b1 <= b2 ? carlson_1111(a1, b1, a2, b2, y, x, calls)
                  : carlson_1111(a2, b2, a1, b1, y, x, calls);
}
