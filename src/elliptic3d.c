/*
** elliptic3d.c -- the elliptic length of a space cubic.  |z'(t)|^2 is a
** sum of three squares, not |complex quadratic|^2, so the quartic
** Q = c4 t^4 + ... + c0 (Henkel Eqn 8 with a z term) is split into two
** real quadratics by the quartic solver (roots.c); each factor's root is
** then polished by complex Newton on Q(s) = sum_k z'_k(s)^2 evaluated from
** the hodograph itself: near a cusp every z'_k(s) is small, so this form
** keeps the root's imaginary part b to full accuracy where the expanded
** coefficients c_i would give only sqrt(eps) (shared/notes/elliptic.md).
*/
#include <complex.h>
#include <math.h>

#include "arclen.h"
#include "elliptic.h"

#define POLISH_CAP 80   /* linear phase inside a close pair, then quadratic */
#define CENTRE_CAP 40   /* Newton on Q' at a simple root: quadratic */
/* Polished roots closer than this (relative) are a cluster: Newton on Q
** pins a double root only to ~sqrt(eps), so the pair is rebuilt from its
** centre (the integral depends on the half-split d only through d^2,
** which Q at the centre gives to full accuracy). */
#define CLOSE_REL 1e-6

/* Q(s) and Q'(s) from the hodograph, s complex. */
static double complex q_eval(const double a2[3], const double a1[3],
                             const double a0[3], double complex s,
                             double complex *dq) {
  double complex q = 0, d = 0;
  int k;
  for (k = 0; k < 3; k++) {
    double complex v = (a2[k] * s + a1[k]) * s + a0[k];
    q += v * v;
    d += 2 * v * (2 * a2[k] * s + a1[k]);
  }
  *dq = d;
  return q;
}

/* Newton from s toward the root of Q in the upper half plane. */
static double complex polish(const double a2[3], const double a1[3],
                             const double a0[3], double complex s) {
  double complex best = s, dq, q = q_eval(a2, a1, a0, s, &dq);
  double bestq = cabs(q);
  int i;
  for (i = 0; i < POLISH_CAP && bestq > 0 && dq != 0; i++) {
    double complex next = s - q / dq;
    next = creal(next) + I * fabs(cimag(next));
    q = q_eval(a2, a1, a0, next, &dq);
    if (cabs(q) < bestq) { best = next; bestq = cabs(q); }
    if (cabs(next - s) <= 0x1p-60 * (1 + cabs(next))) break;
    s = next;
  }
  return best;
}

/* Q''(s); *d3 = Q'''(s) (Q'''' = 24 |A2|^2 is constant). */
static double complex q_eval2(const double a2[3], const double a1[3],
                              const double a0[3], double complex s,
                              double complex *d3) {
  double complex q2 = 0, q3 = 0;
  int k;
  for (k = 0; k < 3; k++) {
    double complex v = (a2[k] * s + a1[k]) * s + a0[k];
    double complex v1 = 2 * a2[k] * s + a1[k];
    q2 += 2 * (v1 * v1 + 2 * a2[k] * v);
    q3 += 12 * a2[k] * v1;
  }
  *d3 = q3;
  return q2;
}

/* The centre m of a close pair of roots of Q by Newton on Q', which has a
** simple root there: Q = c (t-m)^2 (t-m*)^2 gives
** Q' = 2c (t-m) (t-m*) (2t - m - m*). */
static double complex centre(const double a2[3], const double a1[3],
                             const double a0[3], double complex s) {
  double complex best = s, d1, d3;
  double bestq;
  int i;
  q_eval(a2, a1, a0, s, &d1);
  bestq = cabs(d1);
  for (i = 0; i < CENTRE_CAP && bestq > 0; i++) {
    double complex d2 = q_eval2(a2, a1, a0, s, &d3), next;
    if (d2 == 0) break;
    next = s - d1 / d2;
    q_eval(a2, a1, a0, next, &d1);
    if (cabs(d1) < bestq) { best = next; bestq = cabs(d1); }
    if (cabs(next - s) <= 0x1p-60 * (1 + cabs(next))) break;
    s = next;
  }
  return best;
}

static double dot3(const double *u, const double *v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

int arclen_ell_length3d(const double a2[3], const double a1[3],
                        const double a0[3], double y, double x,
                        const char **branch, long *calls, double *len) {
  double n2 = sqrt(dot3(a2, a2)), n1 = sqrt(dot3(a1, a1)), q[4];
  double complex s1, s2;
  int e;
  if (n2 == 0) {
    /* z' = A1 t + A0: |A1| |t - s| with s = a + ib, a = -A1.A0/|A1|^2
    ** and b = |A1 x A0|/|A1|^2 (the cross product, free of cancellation) */
    double cx, cy, cz, a, b;
    if (n1 == 0) {
      *branch = "line";
      *len = sqrt(dot3(a0, a0)) * (x - y);
      return ARCLEN_OK;
    }
    cx = a1[1] * a0[2] - a1[2] * a0[1];
    cy = a1[2] * a0[0] - a1[0] * a0[2];
    cz = a1[0] * a0[1] - a1[1] * a0[0];
    a = -dot3(a1, a0) / (n1 * n1);
    b = sqrt(cx * cx + cy * cy + cz * cz) / (n1 * n1);
    *branch = "quadratic";
    *len = n1 * arclen_ell_j0(y - a, x - a, b);
    return ARCLEN_OK;
  }
  /* Q = |A2|^2 t^4 + 2 A2.A1 t^3 + (|A1|^2 + 2 A2.A0) t^2 + 2 A1.A0 t
  **     + |A0|^2 */
  e = arclen_quartic_factor(dot3(a2, a2), 2 * dot3(a2, a1),
                            dot3(a1, a1) + 2 * dot3(a2, a0),
                            2 * dot3(a1, a0), dot3(a0, a0), q);
  if (e != ARCLEN_OK) return e;
  {
    /* Q >= 0, so its real roots are double; a factor with two distinct
    ** real roots (a near-collinear Q split the other way) is re-paired:
    ** the four roots sorted, neighbours together.  Newton starts off the
    ** real axis (on it, it would stay there). */
    double re[4], im[4], t;
    int i, j;
    arclen_quadratic(1, q[0], q[1], re, im);
    arclen_quadratic(1, q[2], q[3], re + 2, im + 2);
    if (im[0] != 0 && im[2] != 0) {
      s1 = re[0] + I * fabs(im[0]);
      s2 = re[2] + I * fabs(im[2]);
    } else {
      for (i = 1; i < 4; i++)          /* insertion sort by real part */
        for (j = i; j > 0 && re[j] < re[j - 1]; j--) {
          t = re[j]; re[j] = re[j - 1]; re[j - 1] = t;
          t = im[j]; im[j] = im[j - 1]; im[j - 1] = t;
        }
      s1 = (re[0] + re[1]) / 2 + I * fmax(fabs(re[1] - re[0]) / 2, fabs(im[0]));
      s2 = (re[2] + re[3]) / 2 + I * fmax(fabs(re[3] - re[2]) / 2, fabs(im[2]));
    }
    if (cimag(s1) == 0) s1 += I * 0x1p-30 * (1 + fabs(creal(s1)));
    if (cimag(s2) == 0) s2 += I * 0x1p-30 * (1 + fabs(creal(s2)));
  }
  s1 = polish(a2, a1, a0, s1);
  s2 = polish(a2, a1, a0, s2);
  if (cabs(s1 - s2) <= CLOSE_REL * fmax(1, cabs(s1))) {
    /* Q(m+u) = Q(m) + A u^2 + B u^3 + C u^4 about the centre (Q'(m) = 0):
    ** the pair is u = +-d - (B/2A) d^2 + O(d^3), d^2 = -Q(m)/A, so its
    ** midpoint is m - (B/2A) d^2 and its half-split squared d^2 + O(d^4) */
    double complex m = centre(a2, a1, a0, (s1 + s2) / 2), dq, b3, d2;
    double complex q0 = q_eval(a2, a1, a0, m, &dq);
    double complex a = q_eval2(a2, a1, a0, m, &b3) / 2;
    if (a != 0) {
      d2 = -q0 / a;
      m -= b3 / 6 * d2 / (2 * a);
      s1 = m + csqrt(d2);
      s2 = m - csqrt(d2);
      s1 = creal(s1) + I * fabs(cimag(s1));
      s2 = creal(s2) + I * fabs(cimag(s2));
    }
  }
  *len = n2 * arclen_ell_product(creal(s1), cimag(s1), creal(s2), cimag(s2),
                                 y, x, branch, calls);
  return ARCLEN_OK;
}
