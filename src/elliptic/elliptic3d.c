/*
** elliptic3d.c -- the elliptic length of a space cubic.  |z'(t)|^2 is a
** sum of three squares, not |complex quadratic|^2: the quartic
** Q = c4 t^4 + ... + c0 (Henkel Eqn 8 with a z term) is written as
** c4 |t - s1|^2 |t - s2|^2 by its roots in the upper half plane
** (roots/roots3d.c, which keeps their imaginary parts to full accuracy near
** a cusp), and the length is then sqrt(c4) int |t - s1||t - s2| dt, the
** same integral as in the plane (product.c).
*/
#include <math.h>

#include "arclen.h"
#include "elliptic/elliptic.h"
#include "roots/roots3d.h"

static double dot3(const double *u, const double *v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

static double maxabs3(const double *u) {
  return fmax(fabs(u[0]), fmax(fabs(u[1]), fabs(u[2])));
}

int arclen_ell_length3d(const double a2[3], const double a1[3],
                        const double a0[3], double y, double x,
                        const char **branch, long *calls, double *len) {
  double n2, n1, m2 = maxabs3(a2), m1 = maxabs3(a1), m0 = maxabs3(a0);
  double re[2], im[2];
  int e;
  /* A term below 2^-56 of the larger lower ones changes the length by less
  ** than a rounding (int |z'| >= max(|A1|, |A0|)/2 on the range, which
  ** has length <= 2), and its square would underflow: dropped.  (A
  ** sub-range's own hodograph keeps residues like 1e-160 of the others
  ** that the whole curve's rounding made 0; kept, they gave 5% errors.) */
  if (m2 <= 0x1p-56 * fmax(m1, m0)) {
    /* z' = A1 t + A0: |A1| |t - s| with s = a + ib, a = -A1.A0/|A1|^2
    ** and b = |A1 x A0|/|A1|^2 (the cross product, free of cancellation) */
    double cx, cy, cz, a, b;
    if (m1 <= 0x1p-56 * m0) {
      *branch = "line";
      *len = sqrt(dot3(a0, a0)) * (x - y);
      return ARCLEN_OK;
    }
    n1 = sqrt(dot3(a1, a1));
    cx = a1[1] * a0[2] - a1[2] * a0[1];
    cy = a1[2] * a0[0] - a1[0] * a0[2];
    cz = a1[0] * a0[1] - a1[1] * a0[0];
    a = -dot3(a1, a0) / (n1 * n1);
    b = sqrt(cx * cx + cy * cy + cz * cz) / (n1 * n1);
    *branch = "quadratic";
    *len = n1 * arclen_ell_single(a, b, y, x);
    return ARCLEN_OK;
  }
  n2 = sqrt(dot3(a2, a2));
  e = arclen_roots3d(a2, a1, a0, re, im);
  if (e != ARCLEN_OK) return e;
  *len = n2 * arclen_ell_product(re[0], im[0], re[1], im[1],
                                 y, x, branch, calls);
  return ARCLEN_OK;
}
