/*
** cubic.h -- internal helpers shared by the length methods: the hodograph
** scaled by a power of two, the speed on it, and the branch points of the
** speed's analytic continuation (which decide how fast quadrature converges).
*/
#ifndef ARCLEN_CUBIC_H
#define ARCLEN_CUBIC_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "curve/numeric.h"

/* z'(t) / 2^exp = a2 t^2 + a1 t + a0, with the power of two chosen so
** that the largest coefficient lies in [0.5, 1). */
typedef struct arclen_hodo {
  int dim;
  int zero;                 /* the hodograph vanishes: a point */
  int exp;                  /* results in curve units: ldexp(x, exp) */
  double a2[3], a1[3], a0[3];
} arclen_hodo;

void arclen_hodo_scaled(const double *c, int dim, arclen_hodo *h);

/* Coordinate k of z'(t) = a2 t^2 + a1 t + a0 from the control-point
** differences (exact or correctly rounded wherever the curve sits): Henkel
** Eqn 4 differentiated, A0 = 3(P1-P0), A1 = 6((P2-P1)-(P1-P0)),
** A2 = 3((P3-P2)-2(P2-P1)+(P1-P0)). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void arclen_power_form(const double *c, int dim, int k,
                                     double *a0, double *a1, double *a2) {
  double d0 = c[dim + k] - c[k];
  double d1 = c[2 * dim + k] - c[dim + k];
  double d2 = c[3 * dim + k] - c[2 * dim + k];
  *a0 = 3 * d0;
  *a1 = 6 * (d1 - d0);
  *a2 = 3 * ((d2 - d1) - (d1 - d0));
}

/* Coordinate k of the power form into h: the largest magnitude so far
** into *big, and the coefficients' sum into *sum (inf or NaN if any of
** them overflowed, which the maximum would not show). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void arclen_hodo_coord(const double *c, int dim, int k,
                                     arclen_hodo *h, double *big,
                                     double *sum) {
  double a0, a1, a2, m;
  arclen_power_form(c, dim, k, &a0, &a1, &a2);
  m = fabs(a0) > fabs(a1) ? fabs(a0) : fabs(a1);
  m = m > fabs(a2) ? m : fabs(a2);
  *big = m > *big ? m : *big;
  *sum += (a0 + a1) + a2;
  h->a0[k] = a0;
  h->a1[k] = a1;
  h->a2[k] = a2;
}

/* arclen_hodo_scaled for the common case, inline: the power form straight
** from the points, and when its largest coefficient is a normal number the
** power of two read off its bits (frexp's e is the biased exponent less
** 1022).  Returns 0, h unfinished, when a coefficient is inf or NaN (a
** coordinate is, or a difference overflowed: every coordinate enters a
** coefficient), zero or tiny: arclen_hodo_scaled then takes care. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int arclen_hodo_quick(const double *c, int dim,
                                    arclen_hodo *h) {
  double big = 0, sum = 0, inv;
  uint64_t u;
  int k, e;
  h->dim = dim;
  h->zero = 0;
  arclen_hodo_coord(c, dim, 0, h, &big, &sum);
  arclen_hodo_coord(c, dim, 1, h, &big, &sum);
  if (dim == 3) {
    arclen_hodo_coord(c, dim, 2, h, &big, &sum);
  } else {
    h->a2[2] = h->a1[2] = h->a0[2] = 0;
  }
  memcpy(&u, &big, sizeof u);
  e = (int)(u >> 52) - 1022;              /* big >= 0: no sign bit */
  if (!(e > -1000 && e < 1000 && sum - sum == 0)) return 0;
  u = (uint64_t)(1023 - e) << 52;         /* 2^-e, normal */
  memcpy(&inv, &u, sizeof inv);
  h->exp = e;
  for (k = 0; k < dim; k++) {
    h->a2[k] *= inv;
    h->a1[k] *= inv;
    h->a0[k] *= inv;
  }
  return 1;
}
/* The hodograph of [t0, t1] in s in [-1, 1] (t = (t0 + t1)/2 + s (t1 - t0)/2),
** its coefficients correct to rounding: lengths are (t1 - t0)/2 times its. */
void arclen_hodo_local(const double *c, int dim, double t0, double t1,
                       arclen_hodo *h);
/* Speed in scaled units, |a2 t^2 + a1 t + a0| by Horner per coordinate;
** inline, since quadrature spends most of its time here. */
static inline double arclen_hodo_speed(const arclen_hodo *h, double t) {
  double x = (h->a2[0] * t + h->a1[0]) * t + h->a0[0];
  double y = (h->a2[1] * t + h->a1[1]) * t + h->a0[1];
  double z = h->dim == 3 ? (h->a2[2] * t + h->a1[2]) * t + h->a0[2] : 0;
  return sqrt(x * x + y * y + z * z);
}
/* Chord |z(b) - z(a)| in scaled units, from the antiderivative of the
** hodograph (z(t) - P0 = a2 t^3/3 + a1 t^2/2 + a0 t).  It bounds the
** length below for the quadrature's tolerance, where the ulp lost by
** multiplying with a rounded 1/3 (a division costs more) is immaterial.
** Inline and unrolled: each piece of the default method takes one, and
** the call with its loop over dim took ~60 instructions (callgrind). */
static inline double arclen_hodo_chord_part(const arclen_hodo *h, int k,
                                            double a, double b) {
  double c3 = h->a2[k] * (1.0 / 3), c2 = h->a1[k] * 0.5;
  double za = arclen_muladd(arclen_muladd(c3, a, c2), a, h->a0[k]) * a;
  double zb = arclen_muladd(arclen_muladd(c3, b, c2), b, h->a0[k]) * b;
  return zb - za;
}
static inline double arclen_hodo_chord(const arclen_hodo *h, double a,
                                       double b) {
  double dx = arclen_hodo_chord_part(h, 0, a, b);
  double dy = arclen_hodo_chord_part(h, 1, a, b);
  double dz = h->dim == 3 ? arclen_hodo_chord_part(h, 2, a, b) : 0;
  return sqrt(arclen_muladd(dz, dz, arclen_muladd(dy, dy, dx * dx)));
}
int arclen_hodo_critical(const arclen_hodo *h, double roots[3]);
int arclen_cubic_roots01(const double p[4], double roots[3]);

/* speed(z)^2 = lead2 * prod (z - r_k) over the n <= 4 roots r_k of |z'|^2,
** a real polynomial of degree 2 deg(z') that is >= 0 on the real line.
** Non-real roots (in conjugate pairs, both stored) are branch points of the
** speed.  Real roots have even multiplicity (each stored as often as it
** counts): no branch point, since |t - r| continues as +-(t - r), but a
** kink where a piece must be cut. */
typedef struct arclen_branch {
  int n;                    /* number of roots stored, with multiplicity */
  double lead2;             /* the speed's leading coefficient, squared */
  double re[4], im[4];      /* im >= 0; im == 0 marks a real root */
} arclen_branch;

void arclen_branch_points(const arclen_hodo *h, arclen_branch *b);

#endif
