/*
** lenfit_error.c -- measuring a length-versus-t fit as Walter & Fournier
** did (Sec. 5, Eqn 9): e(t) = |s(t)/s(1) - L_B(t)| on a grid of t, with
** the "true" length from Simpson's rule at 1e-4 fractional accuracy
** (Numerical Recipes in C, 2nd ed., qsimp/trapzd, the paper's [pres92]),
** or from the accurate adaptive Gauss-Legendre length.
*/
#include <math.h>
#include <stddef.h>

#include "arclen.h"

#define QSIMP_JMAX 20      /* Numerical Recipes' JMAX */
#define QSIMP_JMIN 5       /* NR 2nd ed.: no convergence test before j > 5 */
#define EXACT_RTOL 1e-13   /* the accurate truth; far below any fit error */
#define PAPER_EPS 1e-4     /* "Simpson's rule with 1.0e-4 of fractional
                              accuracy" (Sec. 5) */
#define GRID_CAP 100000    /* largest npts accepted */

/* NR's trapzd: the j-th refinement of the trapezoid rule, updating *s. */
static void trapzd(const arclen_fit *f, double a, double b, int j, double *s,
                   long *evals) {
  if (j == 1) {
    *s = 0.5 * (b - a) * (arclen_fit_speed(f, a) + arclen_fit_speed(f, b));
    *evals += 2;
  } else {
    long it = 1L << (j - 2), k;
    double del = (b - a) / (double)it, x = a + 0.5 * del, sum = 0.0;
    for (k = 0; k < it; k++, x += del) sum += arclen_fit_speed(f, x);
    *evals += it;
    *s = 0.5 * (*s + (b - a) * sum / (double)it);
  }
}

/* The paper's "true" length: Numerical Recipes' qsimp (Simpson by
** trapezoid refinement) at fractional accuracy eps, in internal units. */
static double length_qsimp(const arclen_fit *f, double t0, double t1,
                           double eps, long *evals) {
  double st = 0.0, s = 0.0, ost = 0.0, os = 0.0;
  long dummy = 0;
  int j;
  if (evals == NULL) evals = &dummy;
  for (j = 1; j <= QSIMP_JMAX; j++) {
    trapzd(f, t0, t1, j, &st, evals);
    s = (4.0 * st - ost) / 3.0;
    if (j > QSIMP_JMIN &&
        (fabs(s - os) < eps * fabs(os) || (s == 0.0 && os == 0.0)))
      break;
    os = s;
    ost = st;
  }
  /* NR stops with an error after JMAX; the last estimate is what it has. */
  return ldexp(s, f->scale_exp);
}

/* The true length from 0 to t, in the internal units of f. */
static double truth(const arclen_fit *f, int kind, double t) {
  arclen_opts o;
  double len = NAN;
  if (kind == ARCLEN_TRUTH_SIMPSON)
    return ldexp(length_qsimp(f, 0.0, t, PAPER_EPS, NULL),
                 -f->scale_exp);
  arclen_opts_init(&o);
  o.rtol = EXACT_RTOL;
  o.t0 = 0.0;
  o.t1 = t;
  if (arclen_length_gauss(f->cs, f->dim, &o, &len, NULL) != ARCLEN_OK)
    return NAN;
  return len;
}

int arclen_fit_error(const arclen_fit *f, int truth_kind, int inverse,
                     int npts, double *max, double *mean, double *argmax) {
  double total, u = 0.0, sum = 0.0;
  int k, count;
  *max = *mean = *argmax = 0.0;
  if (truth_kind != ARCLEN_TRUTH_SIMPSON && truth_kind != ARCLEN_TRUTH_EXACT)
    return ARCLEN_EDOMAIN;
  if (npts < 0 || npts > GRID_CAP) return ARCLEN_EDOMAIN;
  if (!(f->itotal > 0.0)) return ARCLEN_OK;   /* a point: nothing to miss */
  total = truth(f, truth_kind, 1.0);
  if (!(total > 0.0)) return ARCLEN_ENOCONV;
  /* The paper's loop "for (t = 0; t <= 1; t += 0.05)" runs 20 times. */
  count = npts == 0 ? 20 : npts + 1;
  for (k = 0; k < count; k++) {
    double t, e;
    if (npts > 0) u = (double)k / npts;
    if (inverse) {
      t = arclen_fit_invert(f, u);
      e = fabs(truth(f, truth_kind, t) / total - u);
    } else {
      t = u;
      e = fabs(truth(f, truth_kind, t) / total - arclen_fit_value(f, t));
    }
    if (isnan(e)) return ARCLEN_ENOCONV;
    if (e > *max) { *max = e; *argmax = u; }
    sum += e;
    if (npts == 0) u += 0.05;
  }
  *mean = sum / count;
  return ARCLEN_OK;
}
