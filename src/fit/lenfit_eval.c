/*
** lenfit_eval.c -- evaluating a length-versus-t fit (lenfit.c) and its
** inverse in constant time: find the span by bisection on its few knots,
** then evaluate (or invert) one functional cubic Bezier.
*/
#include <math.h>
#include <stddef.h>

#include "arclen.h"

#define INVERT_CAP 100   /* safeguarded Newton: bisection alone needs < 60 */

/* The last span whose start is <= v, by bisection on t0 or (by_value)
** on the start ordinate y[0]; both ascend along the spans. */
static int find_span(const arclen_fit *f, double v, int by_value) {
  int lo = 0, hi = f->nspans - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    double start = by_value ? f->span[mid].y[0] : f->span[mid].t0;
    if (start <= v) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

/* Bernstein cubic y(u) and its derivative dy/du, by de Casteljau. */
static double bezier(const double *y, double u, double *dy) {
  double v = 1.0 - u;
  double a = v * y[0] + u * y[1], b = v * y[1] + u * y[2],
         c = v * y[2] + u * y[3];
  double d = v * a + u * b, e = v * b + u * c;
  if (dy != NULL) *dy = 3.0 * (e - d);
  return v * d + u * e;
}

static double clamp01(double t) {
  return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
}

double arclen_fit_value(const arclen_fit *f, double t) {
  const arclen_fit_span *sp;
  t = clamp01(t);
  sp = &f->span[find_span(f, t, 0)];
  return bezier(sp->y, (t - sp->t0) / (sp->t1 - sp->t0), NULL);
}

double arclen_fit_slope(const arclen_fit *f, double t) {
  const arclen_fit_span *sp;
  double dy;
  t = clamp01(t);
  sp = &f->span[find_span(f, t, 0)];
  bezier(sp->y, (t - sp->t0) / (sp->t1 - sp->t0), &dy);
  return dy / (sp->t1 - sp->t0);
}

/* Scaled in internal units, so that a total beyond DBL_MAX still gives
** finite lengths short of it (and 0, not inf * 0, at t = 0). */
double arclen_fit_length(const arclen_fit *f, double t) {
  return ldexp(f->itotal * arclen_fit_value(f, t), f->scale_exp);
}

/* u in [0, 1] with y(u) = target, where y(0) <= target <= y(1): Newton
** kept inside a shrinking bracket, bisecting when a step leaves it.  On a
** non-monotone span (possible with method "paper") this still returns a
** root, the one the bracket closes on. */
static double invert_span(const double *y, double target) {
  double lo = 0.0, hi = 1.0, u, dy;
  int it;
  u = y[3] > y[0] ? (target - y[0]) / (y[3] - y[0]) : 0.0;
  u = clamp01(u);
  for (it = 0; it < INVERT_CAP; it++) {
    double g = bezier(y, u, &dy) - target, next;
    if (g == 0.0) return u;
    if (g < 0.0) lo = u;
    else hi = u;
    next = u - g / dy;
    if (!(dy > 0.0) || !(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (fabs(next - u) <= 1e-16 || hi - lo <= 1e-16) return next;
    u = next;
  }
  return u;
}

double arclen_fit_invert(const arclen_fit *f, double v) {
  const arclen_fit_span *sp;
  double u;
  if (!(f->itotal > 0.0) || !(v > 0.0)) return 0.0;
  if (v >= 1.0) return 1.0;
  sp = &f->span[find_span(f, v, 1)];
  u = invert_span(sp->y, v);
  return sp->t0 + u * (sp->t1 - sp->t0);
}

double arclen_fit_time(const arclen_fit *f, double s) {
  if (!(f->itotal > 0.0) || !(s > 0.0)) return 0.0;
  return arclen_fit_invert(f, ldexp(s, -f->scale_exp) / f->itotal);
}

int arclen_fit_span_monotone(const arclen_fit_span *sp) {
  /* y' is 3 * the quadratic Bernstein form with coefficients d0, d1, d2:
  ** non-negative on [0, 1] iff d0 >= 0, d2 >= 0, d1 >= -sqrt(d0 d2). */
  double d0 = sp->y[1] - sp->y[0], d1 = sp->y[2] - sp->y[1],
         d2 = sp->y[3] - sp->y[2];
  return d0 >= 0.0 && d2 >= 0.0 && (d1 >= 0.0 || d1 * d1 <= d0 * d2);
}

int arclen_fit_monotone(const arclen_fit *f) {
  int i;
  for (i = 0; i < f->nspans; i++)
    if (!arclen_fit_span_monotone(&f->span[i])) return 0;
  return 1;
}
