/*
** invert.c -- the time at a length for the kinds with a closed-form or
** exact length: the t with |f(t)| <= tol, f(t) = len(0, t) - s.
**
** An exact length (a closed form, or Carlson's integrals for a conic) is
** the expensive step, so it only certifies: between two of them, Newton's
** method runs on a cheap model of f, the last certified value f(x0) plus a
** Gauss-Legendre rule of the speed from x0 (each step adds the rule over
** the step itself), and the point it settles on is measured exactly.
** Where the model was good (a smooth speed over [x0, x]: the rule's error
** falls as (|x - x0| / rho)^(2 NODES), rho the distance to the speed's
** nearest complex singularity) one exact length ends the search; where it
** was not, the next model starts from that exact value over a far shorter
** range.  The answer's guarantee is the certified |f| <= tol alone, never
** the model.  Certified values keep a bracket [lo, hi] (f(lo) < 0 < f(hi))
** that every step stays inside, with bisection where Newton would leave it
** or the speed is 0 (a cusp); a cap ends it besides.
*/
#include <math.h>

#include "arclen.h"
#include "gauss/gauss_tables.h"
#include "segment/segment.h"

/* 64 halvings take [0, 1] below one ulp of any t, so the cap is reached
** only by a length function noisier than the tolerance asked for */
#define MAX_STEPS 100
/* model steps between two exact lengths: Newton's quadratic convergence
** needs 3-4 from a fair guess; more only chase a model that is off */
#define MODEL_STEPS 8
/* the rule over each Newton step of the model, much shorter than the
** range the model started with: 5 nodes integrate degree 9 */
#define STEP_NODES 5

/* int_a^b speed by the n-point Gauss-Legendre rule (signed). */
static double model(arclen_seg_speedfn speed, const void *ctx, int n,
                    double a, double b) {
  const arclen_gauss_rule *r = &arclen_gauss_rules[n - 1];
  double m = (a + b) / 2, h = (b - a) / 2, sum = 0;
  int i;
  if (h == 0) return 0;
  for (i = 0; i < r->half; i++) {
    double x = h * r->x[i];
    sum += r->x[i] == 0 ? r->w[i] * speed(ctx, m)
                  : r->w[i] * (speed(ctx, m - x) + speed(ctx, m + x));
  }
  return h * sum;
}

int arclen_seg_invert(arclen_seg_lenfn len, arclen_seg_speedfn speed,
                      const void *ctx, double total, double s, double tol,
                      double guess, int nodes, double from[2], double *t,
                      long *evals) {
  double lo = from[0], hi = 1, x0, f0, x, f, d, nx, q;
  double best = from[0], bestf = fabs(from[1] - s), bestlen = from[1];
  int i, j, rc;
  if (evals) *evals = 0;
  /* the certified start already answers (a distance within tol of the
  ** last one), or lies beyond s (unsorted input): start from 0 */
  if (bestf <= tol) { *t = from[0]; return ARCLEN_OK; }
  if (from[1] > s) { lo = 0; best = 0; bestf = s; bestlen = 0; }
  if (!(s > 0)) { *t = from[0] = from[1] = 0; return ARCLEN_OK; }
  if (!(s < total)) { *t = from[0] = 1; from[1] = total; return ARCLEN_OK; }
  x = guess > lo && guess < 1 ? guess : lo + (1 - lo) * (s - bestlen) / (total - bestlen);
  if (!(x > lo && x < 1)) x = lo + (1 - lo) / 2;
  /* the first model from the nearer certified point: the start, or the
  ** end (f(1) = total - s, exact too) */
  if (x - lo <= 1 - x) { x0 = lo; f0 = bestlen - s; } else { x0 = 1; f0 = total - s; }
  for (i = 0; i < MAX_STEPS; i++) {
    /* Newton on the model f0 + int_x0^x speed, inside the bracket */
    q = nodes > 0 ? f0 + model(speed, ctx, nodes, x0, x) : 0;
    for (j = 0; nodes > 0 && j < MODEL_STEPS && fabs(q) > tol / 4; j++) {
      d = speed(ctx, x);
      if (!(d > 0)) break;
      nx = x - q / d;
      if (!(nx > lo && nx < hi) || nx == x) break;
      /* a long step (a poor guess) gets the first rule's order */
      q += model(speed, ctx, fabs(nx - x) * 8 < fabs(x - x0) ? STEP_NODES : nodes,
                 x, nx);
      x = nx;
    }
    rc = len(ctx, x, &f);
    if (evals) (*evals)++;
    if (rc != ARCLEN_OK) return rc;
    if (fabs(f - s) < bestf) { bestf = fabs(f - s); best = x; bestlen = f; }
    f -= s;
    if (fabs(f) <= tol) break;
    if (f < 0) lo = x; else hi = x;
    x0 = x; f0 = f;
    /* the next model's start: Newton's step on the exact value */
    d = speed(ctx, x);
    nx = d > 0 ? x - f / d : lo + (hi - lo) / 2;
    if (!(nx > lo && nx < hi)) nx = lo + (hi - lo) / 2;
    if (nx == x || !(nx > lo && nx < hi)) break;   /* lo, hi adjacent */
    x = nx;
  }
  *t = from[0] = best;
  from[1] = bestlen;
  return ARCLEN_OK;
}
