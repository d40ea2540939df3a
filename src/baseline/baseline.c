/*
** baseline.c -- Henkel's fixed-step rows (H. Henkel, "Calculating the Cubic
** Bezier Arc Length by Elliptic Integrals", 2014, section 5): N equal steps
** (he used N = 10^6) of
**   "polyline"            the hypotenuse sum of the chords of Eqn 3;
**   "trapezoid"           the extended trapezoidal rule on the square root of
**                         the quartic radicand c4 t^4 + ... + c0 (Eqns 7, 8);
**   "trapezoid-factored"  the same rule on the factored speed of Eqn 10,
**                         |A2| sqrt(q1(t) q2(t)), q_k = (t - a_k)^2 + b_k^2,
**                         s_k = a_k + i b_k the complex roots of z'(t) (2D).
** Their errors are the rules' (O(N^-2)), plus in Eqn 7 the cancellation of
** the expanded quartic near a cusp -- which is what these rows are for.
*/
#include <float.h>
#include <math.h>
#include <stddef.h>

#include "arclen.h"
#include "curve/cplx.h"
#include "curve/numeric.h"

#define MAX_STEPS 1000000000L   /* 10^9: a few seconds; keeps loops bounded */

/* The leg vectors d_k = P_{k+1} - P_k (d[3k + i]) divided by 2^e, e
** returned, that puts the largest component in [0.5, 1): sums of squares
** then neither overflow (coordinates near DBL_MAX) nor underflow (subnormal
** ones), and the scaling is exact.  Coordinates beyond DBL_MAX/4 are
** quartered first so that no difference overflows.  The scale stays an
** exponent: 2^e itself may exceed DBL_MAX (legs near 2 DBL_MAX), so the
** callers finish with ldexp(result, e) (fuzz_length: inf/NaN otherwise). */
static int legs_scaled(const double *c, int dim, double d[9]) {
  double pre = 1.0, big = 0.0;
  int i, k, e, pre_e = 0;
  for (k = 0; k < 9; k++) d[k] = 0.0;     /* 2D leaves the z slots unset */
  for (i = 0; i < 4 * dim; i++)
    if (fabs(c[i]) > DBL_MAX / 4) { pre = 0.25; pre_e = 2; }
  for (k = 0; k < 3; k++)
    for (i = 0; i < dim; i++) {
      d[3 * k + i] = c[(k + 1) * dim + i] * pre - c[k * dim + i] * pre;
      big = fmax(big, fabs(d[3 * k + i]));
    }
  if (big == 0.0) return 0;
  frexp(big, &e);
  for (k = 0; k < 3 * 3; k++) d[k] = ldexp(d[k], -e);
  return e + pre_e;
}

/* Power basis of z(t) - z(0) per coordinate (Henkel's Eqn 4 without a0),
** from the leg vectors so that far-away curves keep their digits:
** a1 = 3 d0, a2 = 3 (d1 - d0), a3 = d2 - 2 d1 + d0; divided by 2^e, e
** returned (legs_scaled). */
static int power_basis(const double *c, int dim, double a1[3],
                       double a2[3], double a3[3]) {
  double d[9];
  int i, scale = legs_scaled(c, dim, d);
  for (i = 0; i < dim; i++) {
    double d0 = d[i], d1 = d[3 + i], d2 = d[6 + i];
    a1[i] = 3.0 * d0;
    a2[i] = 3.0 * (d1 - d0);
    a3[i] = (d2 - d1) - (d1 - d0);
  }
  return scale;
}

/* Steps and range of a baseline call; 0 or an error code. */
static int setup(int dim, const arclen_opts *o, long *n, double *t0,
                 double *t1, int dims_ok) {
  long steps = o ? o->steps : 0;
  if (dim != 2 && (dim != 3 || !dims_ok)) return ARCLEN_EDIM;
  if (steps == 0) steps = ARCLEN_BASELINE_STEPS;
  if (steps < 1 || steps > MAX_STEPS) return ARCLEN_EDOMAIN;
  *n = steps;
  *t0 = o ? o->t0 : 0.0;
  *t1 = o ? o->t1 : 1.0;
  return ARCLEN_OK;
}

static void fill_info(arclen_info *info, long evals, long n,
                      const char *branch) {
  if (info == NULL) return;
  info->evals = evals;
  info->pieces = n;
  info->depth = 0;
  info->err = 0.0;              /* no estimate: fixed rules */
  info->branch = branch;
  info->calls = 0;
}

/* Node i of N on [t0, t1]. */
static double node(double t0, double t1, long i, long n) {
  return (i == n) ? t1 : t0 + (t1 - t0) * ((double)i / (double)n);
}

int arclen_length_polyline(const double *c, int dim, const arclen_opts *o,
                           double *len, arclen_info *info) {
  double a1[3], a2[3], a3[3], t0, t1, ta;
  long n, i;
  arclen_sum sum = {0.0, 0.0};
  int rc = setup(dim, o, &n, &t0, &t1, 1), k, scale;
  if (rc != ARCLEN_OK) { *len = NAN; return rc; }
  scale = power_basis(c, dim, a1, a2, a3);
  ta = t0;
  for (i = 1; i <= n; i++) {
    double tb = node(t0, t1, i, n), h = tb - ta, s = 0.0;
    for (k = 0; k < dim; k++) {
      /* z(ta + h) - z(ta), expanded so that no large terms cancel */
      double dz = h * (a1[k] + a2[k] * (2.0 * ta + h) +
                       a3[k] * (3.0 * ta * ta + 3.0 * ta * h + h * h));
      s += dz * dz;
    }
    arclen_sum_add(&sum, sqrt(s));
    ta = tb;
  }
  fill_info(info, n, n, "polyline");
  *len = ldexp((t1 < t0) ? -(sum.s + sum.c) : sum.s + sum.c, scale);
  return ARCLEN_OK;
}

/* The extended trapezoidal rule of f over N steps of [t0, t1]. */
typedef double (*speed_fn)(const void *data, double t);

static double trapezoid(speed_fn f, const void *data, double t0, double t1,
                        long n) {
  arclen_sum sum = {0.0, 0.0};
  double ta = t0, fa = f(data, t0);
  long i;
  for (i = 1; i <= n; i++) {
    double tb = node(t0, t1, i, n), fb = f(data, tb);
    arclen_sum_add(&sum, (tb - ta) * (fa + fb) / 2.0);
    ta = tb;
    fa = fb;
  }
  return sum.s + sum.c;
}

/* Eqn 8: Q(t) = |z'(t)|^2 = c4 t^4 + c3 t^3 + c2 t^2 + c1 t + c0. */
static double quartic_speed(const void *data, double t) {
  const double *q = (const double *)data;
  double v = (((q[4] * t + q[3]) * t + q[2]) * t + q[1]) * t + q[0];
  return v > 0.0 ? sqrt(v) : 0.0;   /* rounding can make Q < 0 at a cusp */
}

int arclen_length_trapezoid(const double *c, int dim, const arclen_opts *o,
                            double *len, arclen_info *info) {
  double a1[3], a2[3], a3[3], q[5] = {0.0, 0.0, 0.0, 0.0, 0.0}, t0, t1;
  long n;
  int rc = setup(dim, o, &n, &t0, &t1, 1), k, scale;
  if (rc != ARCLEN_OK) { *len = NAN; return rc; }
  scale = power_basis(c, dim, a1, a2, a3);
  for (k = 0; k < dim; k++) {         /* Henkel's Eqn 8, summed over axes */
    q[4] += 9.0 * a3[k] * a3[k];
    q[3] += 12.0 * a3[k] * a2[k];
    q[2] += 6.0 * a3[k] * a1[k] + 4.0 * a2[k] * a2[k];
    q[1] += 4.0 * a2[k] * a1[k];
    q[0] += a1[k] * a1[k];
  }
  *len = ldexp(trapezoid(quartic_speed, q, t0, t1, n), scale);
  fill_info(info, n + 1, n, "trapezoid");
  return ARCLEN_OK;
}

/* ---- Eqn 10: the factored speed -------------------------------------- */

/* Speed as |lead| * sqrt(prod of (t - a_k)^2 + b_k^2) over nroots roots. */
typedef struct factored {
  double lead;
  int nroots;
  double a[2], b2[2];
} factored;

static double factored_speed(const void *data, double t) {
  const factored *f = (const factored *)data;
  double p = 1.0;
  int k;
  for (k = 0; k < f->nroots; k++) {
    double u = t - f->a[k];
    p *= u * u + f->b2[k];
  }
  return f->lead * sqrt(p);
}

/* Append the root s = num/den: a factor |t - s|.  A root farther than
** 2^60 from [0, 1] (the hodograph nearly drops a degree) is |s| |1 - t/s|
** = |s| to double precision: it goes into the leading factor, where
** (t - a)^2 + b^2 would overflow and make inf * 0 = NaN at the other root.
** lead |s| is taken as (lead/|den|) |num|, never through s itself: with a
** subnormal den, |s| overflows where lead |s| does not (fuzz_length: NaN
** from lead = 4e-312 times inf). */
static void add_root(factored *f, arclen_cx num, arclen_cx den) {
  double mn = hypot(num.re, num.im), md = hypot(den.re, den.im);
  arclen_cx s;
  if (mn > 0x1p60 * md) {
    f->lead = f->lead / md * mn;
    return;
  }
  s = arclen_cx_div(num, den);
  f->a[f->nroots] = s.re;
  f->b2[f->nroots] = s.im * s.im;
  f->nroots++;
}

/* Roots of A2 t^2 + A1 t + A0 (complex coefficients) without cancellation:
** q = -(A1 + d)/2 with d = +-sqrt(A1^2 - 4 A2 A0) on A1's side, then
** s1 = q/A2 and s2 = A0/q.  Fills f (f->lead divided by 2^e, e returned,
** see legs_scaled); lower degrees when A2 (and A1) vanish. */
static int factor_speed(const double *c, factored *f) {
  arclen_cx A0, A1, A2, d, q, s;
  double leg[9];
  int scale = legs_scaled(c, 2, leg);
  double d0x = leg[0], d0y = leg[1], d1x = leg[3];
  double d1y = leg[4], d2x = leg[6], d2y = leg[7];
  A0.re = 3.0 * d0x; A0.im = 3.0 * d0y;
  A1.re = 6.0 * (d1x - d0x); A1.im = 6.0 * (d1y - d0y);
  A2.re = 3.0 * ((d2x - d1x) - (d1x - d0x));
  A2.im = 3.0 * ((d2y - d1y) - (d1y - d0y));
  if (A2.re == 0.0 && A2.im == 0.0) {
    if (A1.re == 0.0 && A1.im == 0.0) {       /* constant velocity */
      f->lead = hypot(A0.re, A0.im);
      f->nroots = 0;
      return scale;
    }
    s.re = -A0.re;                             /* z' = A1 (t + A0/A1) */
    s.im = -A0.im;
    f->lead = hypot(A1.re, A1.im);
    f->nroots = 0;
    add_root(f, s, A1);
    return scale;
  }
  d = arclen_cx_sub(arclen_cx_mul(A1, A1),
                    arclen_cx_scale(4.0, arclen_cx_mul(A2, A0)));
  d = arclen_cx_sqrt(d);
  if (A1.re * d.re + A1.im * d.im < 0.0) { d.re = -d.re; d.im = -d.im; }
  q.re = -(A1.re + d.re) / 2.0;
  q.im = -(A1.im + d.im) / 2.0;
  f->lead = hypot(A2.re, A2.im);
  f->nroots = 0;
  add_root(f, q, A2);
  if (q.re == 0.0 && q.im == 0.0) {            /* A1 = A0 = 0: t^2 */
    add_root(f, arclen_cx_make(0.0, 0.0), arclen_cx_make(1.0, 0.0));
  } else {
    /* lead is |A2| or, if q/A2 went into it, |q|: divided by |q| below */
    add_root(f, A0, q);
  }
  return scale;
}

int arclen_length_trapezoid_factored(const double *c, int dim,
                                     const arclen_opts *o, double *len,
                                     arclen_info *info) {
  factored f;
  double t0, t1;
  long n;
  int rc = setup(dim, o, &n, &t0, &t1, 0), scale;
  if (rc != ARCLEN_OK) { *len = NAN; return rc; }
  scale = factor_speed(c, &f);
  *len = ldexp(trapezoid(factored_speed, &f, t0, t1, n), scale);
  fill_info(info, n + 1, n, "trapezoid-factored");
  return ARCLEN_OK;
}
