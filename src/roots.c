/*
** roots.c -- roots of real quadratics, cubics and quartics, in the manner
** of Orellana & De Michele, ACM TOMS Algorithm 1010 (2020): scaling, a
** dominant root of a cubic resolvent polished by Newton, the quartic split
** into two real quadratic factors, Newton polishing of the factors'
** coefficients, and quadratics solved without cancellation.
** The code is ours; the method follows that paper.
*/
#include <math.h>

#include "arclen.h"

#define NEWTON_CAP 16     /* quadratic convergence; guards NaN/limit cycles */

/* Roots of a2 x^2 + a1 x + a0; the one that would cancel in -a1 +- sqrt(d)
** comes from the product of the roots instead.  Returns the count. */
int arclen_quadratic(double a2, double a1, double a0, double re[2],
                     double im[2]) {
  double d, q, m = fmax(fabs(a1), sqrt(fabs(a2)) * sqrt(fabs(a0)));
  if (a2 == 0) {
    if (a1 == 0) return 0;
    re[0] = -a0 / a1; im[0] = 0;
    return 1;
  }
  /* The roots do not change when every coefficient is scaled by a power of
  ** two (exact): with m ~ 1, a1^2 and a2 a0 neither underflow (subnormal
  ** coefficients gave a root 0.25 for +-2.9e-143i) nor overflow (found by
  ** fuzz/fuzz_roots); a2 and a0 stay finite since |a2 a0| <= m^2. */
  if (m < 0x1p-450 || m > 0x1p450) {
    int e;
    frexp(m, &e);
    a2 = ldexp(a2, -e); a1 = ldexp(a1, -e); a0 = ldexp(a0, -e);
  }
  /* the discriminant with one rounding error: fma keeps a1^2's low bits */
  {
    double p = a1 * a1, pe = fma(a1, a1, -p);
    double r = 4 * a2 * a0, re_ = fma(4 * a2, a0, -r);
    d = (p - r) + (pe - re_);
  }
  if (d >= 0) {
    q = -(a1 + copysign(sqrt(d), a1)) / 2;
    if (q == 0) { re[0] = re[1] = 0; im[0] = im[1] = 0; return 2; }
    re[0] = q / a2; re[1] = a0 / q;
    im[0] = im[1] = 0;
  } else {
    re[0] = re[1] = -a1 / (2 * a2);
    im[0] = sqrt(-d) / (2 * fabs(a2));
    im[1] = -im[0];
  }
  return 2;
}

/* Monic cubic x^3 + b x^2 + c x + d at x, and its derivative. */
static double cubic_val(double b, double c, double d, double x, double *dv) {
  *dv = (3 * x + 2 * b) * x + c;
  return ((x + b) * x + c) * x + d;
}

/* The real root of largest value (three real roots) or the single real
** root, by Cardano/Viete on the depressed cubic, polished by Newton. */
static double cubic_root(double b, double c, double d) {
  double p = c - b * b / 3, q = (2 * b * b / 27 - c / 3) * b + d;
  double x, fx, dv, best, bestf;
  double disc = q * q / 4 + p * p * p / 27;
  int i;
  if (disc > 0) {
    double u = cbrt(-q / 2 - copysign(sqrt(disc), q));
    x = (u != 0 ? u - p / (3 * u) : 0) - b / 3;
  } else {
    double m = sqrt(-p / 3), ar = (m > 0) ? (3 * q) / (2 * p * m) : 0;
    ar = fmax(-1, fmin(1, ar));
    x = 2 * m * cos(acos(ar) / 3) - b / 3;   /* the largest root */
  }
  best = x; bestf = fabs(cubic_val(b, c, d, x, &dv));
  for (i = 0; i < NEWTON_CAP && bestf > 0 && dv != 0; i++) {
    x -= cubic_val(b, c, d, x, &dv) / dv;
    fx = fabs(cubic_val(b, c, d, x, &dv));
    if (!(fx < bestf)) break;
    best = x; bestf = fx;
  }
  return best;
}

/* Power-of-two s with the scaled coefficients a_k / s^(n-k) near 1. */
static double poly_scale(const double *a, int n) {
  double m = 0;
  int k, e;
  for (k = 1; k <= n; k++)
    if (a[k] != 0) m = fmax(m, pow(fabs(a[k]), 1.0 / k));
  if (m == 0 || !isfinite(m)) return 1;
  frexp(m, &e);
  return ldexp(1.0, e);
}

int arclen_cubic(double a3, double a2, double a1, double a0, double re[3],
                 double im[3]) {
  double a[4], s, b, c, d, r, e, f, f1, f2;
  int n, k;
  if (a3 == 0) return arclen_quadratic(a2, a1, a0, re, im);
  a[0] = 1; a[1] = a2 / a3; a[2] = a1 / a3; a[3] = a0 / a3;
  s = poly_scale(a, 3);
  b = a[1] / s; c = a[2] / (s * s); d = a[3] / (s * s * s);
  r = cubic_root(b, c, d);
  /* deflate: x^3 + b x^2 + c x + d = (x - r)(x^2 + e x + f); f from the
  ** equation that leaves the smaller residual in the other one */
  e = b + r;
  f1 = c + r * e;
  f2 = r != 0 ? -d / r : f1;
  f = fabs(r * f1 + d) <= fabs(f2 - r * e - c) ? f1 : f2;
  n = arclen_quadratic(1, e, f, re + 1, im + 1);
  re[0] = r; im[0] = 0;
  for (k = 0; k < 1 + n; k++) { re[k] *= s; im[k] *= s; }
  return 1 + n;
}

/* Residual of the factorisation (x^2+p1 x+q1)(x^2+p2 x+q2) of the monic
** quartic x^4 + a x^3 + b x^2 + c x + d, and its Jacobian. */
static void factor_residual(const double *v, const double *m, double *f,
                            double jac[4][4]) {
  double p1 = v[0], q1 = v[1], p2 = v[2], q2 = v[3];
  f[0] = p1 + p2 - m[0];
  f[1] = q1 + q2 + p1 * p2 - m[1];
  f[2] = p1 * q2 + p2 * q1 - m[2];
  f[3] = q1 * q2 - m[3];
  if (jac == NULL) return;
  jac[0][0] = 1;  jac[0][1] = 0;  jac[0][2] = 1;  jac[0][3] = 0;
  jac[1][0] = p2; jac[1][1] = 1;  jac[1][2] = p1; jac[1][3] = 1;
  jac[2][0] = q2; jac[2][1] = p2; jac[2][2] = q1; jac[2][3] = p1;
  jac[3][0] = 0;  jac[3][1] = q2; jac[3][2] = 0;  jac[3][3] = q1;
}

/* Solve J x = f (4x4) by elimination with partial pivoting; 0 if singular. */
static int solve4(double j[4][4], double *f) {
  int i, k, r;
  for (k = 0; k < 4; k++) {
    int p = k;
    for (i = k + 1; i < 4; i++) if (fabs(j[i][k]) > fabs(j[p][k])) p = i;
    if (j[p][k] == 0) return 0;
    if (p != k) {
      double t;
      for (r = 0; r < 4; r++) { t = j[k][r]; j[k][r] = j[p][r]; j[p][r] = t; }
      t = f[k]; f[k] = f[p]; f[p] = t;
    }
    for (i = k + 1; i < 4; i++) {
      double l = j[i][k] / j[k][k];
      for (r = k; r < 4; r++) j[i][r] -= l * j[k][r];
      f[i] -= l * f[k];
    }
  }
  for (k = 3; k >= 0; k--) {
    for (r = k + 1; r < 4; r++) f[k] -= j[k][r] * f[r];
    f[k] /= j[k][k];
  }
  return 1;
}

static double resid_norm(const double *v, const double *m) {
  double f[4];
  factor_residual(v, m, f, NULL);
  return fabs(f[0]) + fabs(f[1]) + fabs(f[2]) + fabs(f[3]);
}

/* Monic quartic x^4 + m0 x^3 + m1 x^2 + m2 x + m3 (scaled) into
** v = {p1, q1, p2, q2}. */
static void factor_monic(const double *m, double *v) {
  double a = m[0], b = m[1], c = m[2], d = m[3];
  /* Ferrari: quartic = (x^2 + a x/2 + y/2)^2 - (e x + f)^2 where y is a
  ** root of the resolvent y^3 - b y^2 + (ac - 4d) y + (4bd - a^2 d - c^2);
  ** the largest root makes e^2 = a^2/4 - b + y >= 0 (Algorithm 1010's
  ** LDL^T pivot). */
  double y = cubic_root(-b, a * c - 4 * d, 4 * b * d - a * a * d - c * c);
  double e2 = a * a / 4 - b + y, f2 = y * y / 4 - d, g = a * y / 2 - c;
  double e, f, best, jac[4][4], fv[4], w[4];
  int i, k;
  if (e2 < 0) e2 = 0;
  if (f2 < 0) f2 = 0;
  /* e f = g/2: take the better-determined one from its square */
  if (e2 * e2 >= f2 * f2 && e2 > 0) { e = sqrt(e2); f = g / (2 * e); }
  else if (f2 > 0) { f = sqrt(f2); e = g / (2 * f); }
  else { e = 0; f = 0; }
  /* p = a/2 +- e, q = y/2 +- f; the smaller of each pair from the
  ** products q1 q2 = d (and p1 + p2 = a is refined by Newton below) */
  v[0] = a / 2 + e; v[2] = a / 2 - e;
  v[1] = y / 2 + f; v[3] = y / 2 - f;
  if (fabs(v[1]) > fabs(v[3]) && v[1] != 0) v[3] = d / v[1];
  else if (v[3] != 0) v[1] = d / v[3];
  /* Newton on the four coefficient equations while the residual falls */
  best = resid_norm(v, m);
  for (i = 0; i < NEWTON_CAP && best > 0; i++) {
    factor_residual(v, m, fv, jac);
    if (!solve4(jac, fv)) break;
    for (k = 0; k < 4; k++) w[k] = v[k] - fv[k];
    {
      double r = resid_norm(w, m);
      if (!(r < best)) break;
      best = r;
      for (k = 0; k < 4; k++) v[k] = w[k];
    }
  }
}

int arclen_quartic_factor(double a4, double a3, double a2, double a1,
                          double a0, double q[4]) {
  double a[5], m[4], s;
  if (a4 == 0 || !isfinite(a4) || !isfinite(a3) || !isfinite(a2)
      || !isfinite(a1) || !isfinite(a0))
    return ARCLEN_EDOMAIN;
  a[0] = 1; a[1] = a3 / a4; a[2] = a2 / a4; a[3] = a1 / a4; a[4] = a0 / a4;
  s = poly_scale(a, 4);
  m[0] = a[1] / s; m[1] = a[2] / (s * s); m[2] = a[3] / (s * s * s);
  m[3] = a[4] / (s * s * s * s);
  factor_monic(m, q);
  q[0] *= s; q[1] *= s * s; q[2] *= s; q[3] *= s * s;
  return ARCLEN_OK;
}

/* Newton on the quartic itself for one root (complex arithmetic by hand),
** kept only while |p| falls: it sharpens roots that the factor split left
** coarse (clusters), and never makes one worse. */
static void polish_root(const double *a, double *zr, double *zi) {
  double best = HUGE_VAL, xr = *zr, xi = *zi;
  int it, k;
  for (it = 0; it < NEWTON_CAP; it++) {
    double pr = a[0], pi = 0, dr = 0, di = 0, t, den, ap;
    for (k = 1; k <= 4; k++) {            /* Horner for p and p' */
      t = dr * xr - di * xi + pr; di = dr * xi + di * xr + pi; dr = t;
      t = pr * xr - pi * xi + a[k]; pi = pr * xi + pi * xr; pr = t;
    }
    ap = hypot(pr, pi);
    if (!(ap < best)) break;
    best = ap; *zr = xr; *zi = xi;
    den = dr * dr + di * di;
    if (ap == 0 || den == 0) break;
    xr -= (pr * dr + pi * di) / den;
    xi -= (pi * dr - pr * di) / den;
  }
}

int arclen_quartic(double a4, double a3, double a2, double a1, double a0,
                   double re[4], double im[4]) {
  double q[4], a[5];
  int n, k;
  if (a4 == 0) return arclen_cubic(a3, a2, a1, a0, re, im);
  if (arclen_quartic_factor(a4, a3, a2, a1, a0, q) != ARCLEN_OK) return 0;
  n = arclen_quadratic(1, q[0], q[1], re, im);
  n += arclen_quadratic(1, q[2], q[3], re + n, im + n);
  a[0] = a4; a[1] = a3; a[2] = a2; a[3] = a1; a[4] = a0;
  for (k = 0; k < n; k++) polish_root(a, &re[k], &im[k]);
  return n;
}
