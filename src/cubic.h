/*
** cubic.h -- internal helpers shared by the length methods: the hodograph
** scaled by a power of two, the speed on it, and the branch points of the
** speed's analytic continuation (which decide how fast quadrature converges).
*/
#ifndef ARCLEN_CUBIC_H
#define ARCLEN_CUBIC_H

#include <math.h>

/* z'(t) / 2^exp = a2 t^2 + a1 t + a0, with the power of two chosen so
** that the largest coefficient lies in [0.5, 1). */
typedef struct arclen_hodo {
  int dim;
  int zero;                 /* the hodograph vanishes: a point */
  int exp;                  /* results in curve units: ldexp(x, exp) */
  double a2[3], a1[3], a0[3];
} arclen_hodo;

void arclen_hodo_scaled(const double *c, int dim, arclen_hodo *h);
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
  double za = ((c3 * a + c2) * a + h->a0[k]) * a;
  double zb = ((c3 * b + c2) * b + h->a0[k]) * b;
  return (zb - za) * (zb - za);
}
static inline double arclen_hodo_chord(const arclen_hodo *h, double a,
                                       double b) {
  double s = arclen_hodo_chord_part(h, 0, a, b) +
             arclen_hodo_chord_part(h, 1, a, b);
  if (h->dim == 3) s += arclen_hodo_chord_part(h, 2, a, b);
  return sqrt(s);
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
