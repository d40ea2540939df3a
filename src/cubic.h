/*
** cubic.h -- internal helpers shared by the length methods: the hodograph
** scaled by a power of two, the speed on it, and the branch points of the
** speed's analytic continuation (which decide how fast quadrature converges).
*/
#ifndef ARCLEN_CUBIC_H
#define ARCLEN_CUBIC_H

/* z'(t) / scale = a2 t^2 + a1 t + a0, with scale a power of two chosen so
** that the largest coefficient lies in [0.5, 1). */
typedef struct arclen_hodo {
  int dim;
  int zero;                 /* the hodograph vanishes: a point */
  double scale;
  double a2[3], a1[3], a0[3];
} arclen_hodo;

void arclen_hodo_scaled(const double *c, int dim, arclen_hodo *h);
double arclen_hodo_speed(const arclen_hodo *h, double t);
double arclen_hodo_chord(const arclen_hodo *h, double a, double b);
int arclen_hodo_critical(const arclen_hodo *h, double roots[3]);
int arclen_cubic_roots01(const double p[4], double roots[3]);

/* speed(z)^2 = lead^2 * prod (z - r_k) over the roots r_k of |z'|^2, a real
** polynomial of degree 2 * deg(z').  Complex roots come in conjugate pairs;
** a real double root (a cusp) is reported once with multiplicity 2, which
** makes it no branch point. */
typedef struct arclen_branch {
  int n;                    /* number of distinct roots stored */
  double lead;              /* leading coefficient of the speed (scaled) */
  double re[4], im[4];      /* roots (upper half-plane and real ones) */
  int mult[4];              /* 1: simple (branch point), 2: double (not) */
} arclen_branch;

void arclen_branch_points(const arclen_hodo *h, arclen_branch *b);

#endif
