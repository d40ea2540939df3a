/*
** elliptic.h -- what the files of elliptic/ share, and the one place that
** defines ELL_RHO, ELL_NMAX and ell_hypot.  The calls run one way:
** elliptic.c (the method, 2D) -> elliptic3d.c (3D) -> product.c (the
** integral by branch) -> elliptic_far.c (far-root series, J0, J1) and
** carlson.c (R-functions); no file calls back up the chain (make
** check-layers).  Not part of the public API.
**
** Every integral here is I = int_y^x |t - s1| |t - s2| dt, y < x, with the
** roots s_k = a_k + i b_k (b_k >= 0) of the complex hodograph (2D) or of
** the quartic |z'|^2 (3D); the length is |A2| I (Henkel Eqn 7-10).
*/
#ifndef ARCLEN_ELLIPTIC_H
#define ARCLEN_ELLIPTIC_H

#include <math.h>

/* sqrt(a^2 + b^2): where the larger is within 2^+-500 neither square
** overflows nor loses bits the sum needs (a smaller one that underflows is
** below its rounding), and the plain form is within an ulp of hypot at a
** fraction of its cost (libm's hypot was 1/5 of the method's time);
** elsewhere hypot. */
static inline double ell_hypot(double a, double b) {
  double m = fmax(fabs(a), fabs(b));
  if (m > 0x1p-500 && m < 0x1p500) return sqrt(a * a + b * b);
  return hypot(a, b);
}

/* Ratio (interval reach)/(distance to a root) below which that root counts
** as far: the series then converge like ELL_RHO^n (60 terms for 1e-17). */
#define ELL_RHO 0.5
#define ELL_NMAX 64

/* Far-root branches (elliptic_far.c).  near: the root whose factor is
** integrated exactly; the other is expanded in Gegenbauer C^(-1/2)
** polynomials (the generating function sqrt(1 - 2cr + r^2)). */
double arclen_ell_series_one(double an, double bn, double af, double bf,
                             double y, double x);
/* Both roots far from [y, x]: both factors expanded about the midpoint. */
double arclen_ell_series_both(double a1, double b1, double a2, double b2,
                              double y, double x);
/* I = int_y^x |t - s1||t - s2| dt by the branch that suits the roots
** (product.c); *branch names it, *calls counts R-function calls. */
double arclen_ell_product(double a1, double b1, double a2, double b2,
                          double y, double x, const char **branch,
                          long *calls);
/* 3D (elliptic3d.c): |z'|^2 split into two quadratics by the quartic
** solver, then arclen_ell_product; *len in the hodograph's units. */
int arclen_ell_length3d(const double a2[3], const double a1[3],
                        const double a0[3], double y, double x,
                        const char **branch, long *calls, double *len);
/* int_y^x |t - s| dt, s = a + ib (one factor; a series when s is far;
** elliptic_far.c, as the two below). */
double arclen_ell_single(double a, double b, double y, double x);
/* int_v^w sqrt(u^2 + b^2) du and int_v^w u sqrt(u^2 + b^2) du. */
double arclen_ell_j0(double v, double w, double b);
double arclen_ell_j1(double v, double w, double b);

/* R_F(x, y, z), R_D(x, y, z), R_J(x, y, z, p) from one duplication
** (carlson.c); each as the separate function would give it. */
void arclen_rfdj(double x, double y, double z, double p, double *rf,
                 double *rd, double *rj);

#endif
