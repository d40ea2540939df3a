/*
** invert.c -- the time at a length for the kinds with a closed-form or
** exact length: Newton's method on f(t) = len(0, t) - s, whose derivative
** is the speed, kept inside a bracket [lo, hi] that shrinks with every
** evaluation (f(lo) < 0 < f(hi)); a step that leaves the bracket, or a
** zero speed (a cusp), is replaced by bisection.  So the iteration ends:
** Newton's convergence where it applies, bisection's halving where not,
** and a cap besides.
*/
#include <math.h>

#include "arclen.h"
#include "segment/segment.h"

/* 64 halvings take [0, 1] below one ulp of any t, so the cap is reached
** only by a length function noisier than the tolerance asked for */
#define MAX_STEPS 100

int arclen_seg_invert(arclen_seg_lenfn len, arclen_seg_speedfn speed,
                      const void *ctx, double total, double s, double tol,
                      double *t, long *evals) {
  double lo = 0, hi = 1, x, f, d, nx, best = 0, bestf = HUGE_VAL;
  int i, rc;
  if (evals) *evals = 0;
  if (!(s > 0)) { *t = 0; return ARCLEN_OK; }
  if (!(s < total)) { *t = 1; return ARCLEN_OK; }
  x = s / total;
  for (i = 0; i < MAX_STEPS; i++) {
    rc = len(ctx, x, &f);
    if (evals) (*evals)++;
    if (rc != ARCLEN_OK) return rc;
    f -= s;
    if (fabs(f) < bestf) { bestf = fabs(f); best = x; }
    if (fabs(f) <= tol) break;
    if (f < 0) lo = x; else hi = x;
    d = speed(ctx, x);
    nx = d > 0 ? x - f / d : lo + (hi - lo) / 2;
    if (!(nx > lo && nx < hi)) nx = lo + (hi - lo) / 2;
    if (nx == x || !(nx > lo && nx < hi)) break;   /* lo, hi adjacent */
    x = nx;
  }
  *t = best;
  return ARCLEN_OK;
}
