/*
** elliptic_far.c -- the length integral int |t - s1||t - s2| dt when a root
** is far from the interval (near-quadratic cubics: |A2| << |A1| puts one
** hodograph root far away, where Carlson's [1,1,1,1] cancels like eps R^4,
** doc/papers.md, "Henkel").
**
** A far factor is a power series: with D = s - a, R = |D|, c = Re D / R,
**   |u - D| = R sqrt(1 - 2c(u/R) + (u/R)^2) = R sum_n C_n(c) (u/R)^n,
** C_n = C_n^(-1/2), the Gegenbauer polynomials of index -1/2 (generating
** function, DLMF 18.12.4), converging like (|u|/R)^n.  The near factor
** sqrt(u^2 + b^2) is integrated exactly against the powers u^n.
*/
#include <math.h>

#include "arclen.h"
#include "elliptic/elliptic.h"

/* Terms needed for ratio q = reach/R: q^n < 2^-56 (tail below rounding). */
static int terms_for(double q) {
  int n;
  if (q <= 0) return 1;
  n = (int)ceil(-56 * 0.6931471805599453 / log(q)) + 1;
  return n < ELL_NMAX ? n : ELL_NMAX;
}

/* C_0..C_{n-1} of index -1/2 at c by DLMF 18.9.1:
** n C_n = 2c(n - 3/2) C_{n-1} - (n - 3) C_{n-2}, C_0 = 1, C_1 = -c. */
static void gegenbauer(double c, int n, double *g) {
  int k;
  g[0] = 1;
  if (n > 1) g[1] = -c;
  for (k = 2; k < n; k++)
    g[k] = (2 * c * (k - 1.5) * g[k - 1] - (k - 3) * g[k - 2]) / k;
}

/* F(u) = (u r + b^2 asinh(u/b))/2, the antiderivative of sqrt(u^2+b^2). */
static double j0_anti(double u, double b) {
  double r = ell_hypot(u, b);
  if (b == 0) return u * fabs(u) / 2;
  return (u * r + b * b * asinh(u / b)) / 2;
}

/* F(w) - F(v).  With v, w of one sign the two halves of F would cancel
** when [v, w] is short against its distance from 0; then use
**   w r_w - v r_v = (w - v)(w + v)(w^2 + v^2 + b^2)/(w r_w + v r_v),
**   asinh(w/b) - asinh(v/b) = asinh((w - v)(w + v)/(w r_v + v r_w)),
** both free of cancellation (r_u = sqrt(u^2 + b^2)). */
static double j0_unit(double v, double w, double b) {
  double rv, rw, dd;
  if (!(v * w > 0)) return j0_anti(w, b) - j0_anti(v, b);
  rv = ell_hypot(v, b); rw = ell_hypot(w, b);
  dd = (w - v) * (w + v);
  return (dd * (w * w + v * v + b * b) / (w * rw + v * rv)
          + b * b * asinh(dd / (w * rv + v * rw))) / 2;
}

/* (r_w^3 - r_v^3)/3 with r^2 = u^2 + b^2; the difference of cubes is
** formed from r_w^2 - r_v^2 = (w - v)(w + v), without cancellation. */
static double j1_unit(double v, double w, double b) {
  double rw = ell_hypot(w, b), rv = ell_hypot(v, b);
  return (w - v) * (w + v) * (rw * rw + rw * rv + rv * rv) / (rw + rv) / 3;
}

/* The formulas square and cube their arguments: with a root 1e152 away
** (a hodograph whose A2, A1 are 1e-300 of A0) the cube overflowed and the
** length came out 0 (fuzz/fuzz_length).  J0 and J1 are homogeneous of
** degree 2 and 3 in (v, w, b), so arguments far from 1 are scaled by an
** exact power of two first. */
#define J_FAR 0x1p200
static int j_scale(double v, double w, double b, int *e) {
  double m = fmax(fabs(v), fmax(fabs(w), b));
  if (!(m > J_FAR || (m < 1 / J_FAR && m > 0))) return 0;
  frexp(m, e);
  return 1;
}

double arclen_ell_j0(double v, double w, double b) {
  int e;
  if (!j_scale(v, w, b, &e)) return j0_unit(v, w, b);
  return ldexp(j0_unit(ldexp(v, -e), ldexp(w, -e), ldexp(b, -e)), 2 * e);
}

double arclen_ell_j1(double v, double w, double b) {
  int e;
  if (!j_scale(v, w, b, &e)) return j1_unit(v, w, b);
  return ldexp(j1_unit(ldexp(v, -e), ldexp(w, -e), ldexp(b, -e)), 3 * e);
}

double arclen_ell_series_one(double an, double bn, double af, double bf,
                             double y, double x) {
  double dr = af - an, di = bf, r = ell_hypot(dr, di), c = dr / r;
  double v = y - an, w = x - an, reach = fmax(fabs(v), fabs(w));
  double g[ELL_NMAX], k[ELL_NMAX], sum;
  double vr = v / r, wr = w / r, rv3, rw3, pv, pw, b2 = (bn / r) * (bn / r);
  int n = terms_for(reach / r), i;
  gegenbauer(c, n, g);
  /* K_i = int u^i sqrt(u^2 + b^2) du / R^i.  Integrating by parts,
  ** J_i = [u^(i-1) rho^3]/(i+2) - (i-1) b^2 J_(i-2)/(i+2), so
  ** K_i = [(u/R)^(i-1) rho^3]/(R (i+2)) - (i-1)(b/R)^2 K_(i-2)/(i+2);
  ** stable for b <= reach (the caller's condition): the old term is damped
  ** by (b/reach)^2 (i-1)/(i+2) < 1 relative to the new one. */
  k[0] = arclen_ell_j0(v, w, bn);
  if (n > 1) k[1] = arclen_ell_j1(v, w, bn) / r;
  rv3 = pow(ell_hypot(v, bn), 3) / r;
  rw3 = pow(ell_hypot(w, bn), 3) / r;
  pv = vr; pw = wr;                    /* (u/R)^(i-1) at i = 2 */
  for (i = 2; i < n; i++) {
    k[i] = (pw * rw3 - pv * rv3) / (i + 2) - (i - 1) * b2 * k[i - 2] / (i + 2);
    pv *= vr; pw *= wr;
  }
  sum = 0;
  for (i = n - 1; i >= 0; i--) sum += g[i] * k[i];   /* small terms first */
  return r * sum;
}

double arclen_ell_series_both(double a1, double b1, double a2, double b2,
                              double y, double x) {
  double m = (x + y) / 2, h = (x - y) / 2;
  double r1 = ell_hypot(a1 - m, b1), r2 = ell_hypot(a2 - m, b2);
  double g1[ELL_NMAX], g2[ELL_NMAX], q1 = h / r1, q2 = h / r2, p, sum = 0;
  int n = terms_for(fmax(q1, q2)), i, j;
  gegenbauer((a1 - m) / r1, n, g1);
  gegenbauer((a2 - m) / r2, n, g2);
  /* alpha_j = C_j(c1) (h/R1)^j (u = h s, s in [-1, 1]); likewise beta */
  for (i = 0, p = 1; i < n; i++, p *= q1) g1[i] *= p;
  for (i = 0, p = 1; i < n; i++, p *= q2) g2[i] *= p;
  /* int_{-1}^{1} s^i ds = 2/(i+1) for even i, 0 for odd i; sum the
  ** product series' even coefficients, small ones first. */
  for (i = ((n - 1) / 2) * 2; i >= 0; i -= 2) {
    double ci = 0;
    for (j = 0; j <= i; j++) ci += g1[j] * g2[i - j];
    sum += ci * 2 / (i + 1);
  }
  return r1 * r2 * h * sum;
}

/* int_y^x |t - s| dt, s = a + ib: one factor (2D hodographs of degree 1,
** or with A2 beyond 2^-56 of the rest; 3D hodographs of degree 1).  With s
** far (h <= ELL_RHO R about the midpoint m) the shifted ends y - a, x - a
** would round the interval away (a root 1e152 away from [-1, 1]: length
** 0, fuzz/fuzz_length), so the series above is integrated term by term:
** 2h R sum_{n even} C_n(c) (h/R)^n / (n + 1). */
double arclen_ell_single(double a, double b, double y, double x) {
  double m = (x + y) / 2, h = (x - y) / 2, r = ell_hypot(a - m, b);
  double g[ELL_NMAX], q, p = 1, sum = 0;
  int n, i;
  if (!(h <= ELL_RHO * r)) return arclen_ell_j0(y - a, x - a, b);
  q = h / r;
  n = terms_for(q);
  gegenbauer((a - m) / r, n, g);
  for (i = 0; i < n; i += 2, p *= q * q) g[i] *= p / (i + 1);
  for (i = (n - 1) - (n - 1) % 2; i >= 0; i -= 2) sum += g[i];  /* small first */
  return 2 * h * r * sum;
}
