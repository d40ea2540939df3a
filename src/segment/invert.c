/*
** invert.c -- a conic's time at a length: the t with |f(t)| <= tol, f(t) =
** len(0, t) - s (a quadratic's is quad_time.c's).
**
** An exact length (Carlson's integrals) is the expensive step, so it only
** certifies: between two of them, Newton's
** method runs on a cheap model of f, the last certified value f(x0) plus a
** Gauss-Legendre rule of the speed from x0 (each step adds the rule over
** the step itself), and the point it settles on is measured exactly.
** Where the model was good (a smooth speed over [x0, x]: the rule's error
** falls as (|x - x0| / rho)^(2 NODES), rho the distance to the speed's
** nearest complex singularity) one exact length ends the search; where it
** was not, the next model starts from that exact value over a far shorter
** range.  Where the kind states a bound of the rule's error (segment.c's
** conic_rule_error), the model certifies itself when its
** value, its rules' bounds, its start's own bound and the roundings of
** the sums leave |f| <= tol: the short steps of a sweep over sorted
** distances then need no exact length at all, and pass their bound on.
** The answer's guarantee is always a certified |f| <= tol, never the
** model's guess.  Certified values keep a bracket [lo, hi] (f(lo) < 0 < f(hi))
** that every step stays inside, with bisection where Newton would leave it
** or the speed is 0 (a cusp); a cap ends it besides.
*/
#include <float.h>
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
/* the model's first rule, over the range from its start: 10 nodes (6, 14
** and 20 took more instructions a conic's time, doc/benchmarks.md) */
#define MODEL_NODES 10
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

/* The pieces of one model: each rule's range, order and value. */
typedef struct model_piece { double a, b, v; int n; } model_piece;

/* Whether the model's pieces, its start's error e0 and the roundings
** leave |q| <= tol: each piece's rule bound plus the rounding of its sum
** (n positive terms and the speed's few roundings each: 32 eps of it),
** taken in turn and stopped as soon as they exceed the room (the first
** piece, the long one, is where a model usually fails; below 1e-14 its
** rounding alone often leaves no room, and the bound is not taken: a sum
** of rounded nonnegative terms only grows).  *err: the total when it
** does. */
static int model_certifies(arclen_seg_boundfn bound, const void *ctx,
                           const model_piece *pc, int np, double e0,
                           double q, double s, double tol, double *err) {
  double e = e0 + 2 * DBL_EPSILON * (fabs(s) + fabs(q)), r;
  int i;
  for (i = 0; i < np && fabs(q) + e <= tol; i++) {
    r = 32 * DBL_EPSILON * fabs(pc[i].v);
    if (!(fabs(q) + (e + r) <= tol)) { e += r; break; }
    e += bound(ctx, pc[i].a, pc[i].b, pc[i].n) + r;
  }
  *err = e;
  return fabs(q) + e <= tol;
}

int arclen_seg_cover(arclen_seg_speedfn speed, arclen_seg_orderfn order,
                     const void *ctx, double a, double b, double share,
                     int depth, arclen_seg_piece *pc, int *np) {
  double e, m;
  int n = order(ctx, a, b, share, ARCLEN_SEG_COVER_NODES, &e);
  if (n > 0) {
    pc[*np].a = a;
    pc[*np].b = b;
    pc[*np].v = model(speed, ctx, n, a, b);
    /* the bound, and the rule's sum's rounding as model_certifies takes it */
    pc[*np].e = e + 32 * DBL_EPSILON * fabs(pc[*np].v);
    (*np)++;
    return 1;
  }
  if (depth <= 0) return 0;
  m = a + (b - a) / 2;
  return arclen_seg_cover(speed, order, ctx, a, m, share / 2, depth - 1, pc, np) &&
         arclen_seg_cover(speed, order, ctx, m, b, share / 2, depth - 1, pc, np);
}

/* int_a^b speed (a < b) within share by the kind's bound (arclen_seg_cover,
** CERT_DEPTH levels): *val the sum, *err its bound with the sums'
** roundings.  0 where the cover fails: the caller then takes an exact
** length. */
#define CERT_DEPTH 3
static int certified_integral(arclen_seg_speedfn speed,
                              arclen_seg_orderfn order, const void *ctx,
                              double a, double b, double share,
                              double *val, double *err) {
  arclen_seg_piece pc[1 << CERT_DEPTH];
  int np = 0, i;
  if (!arclen_seg_cover(speed, order, ctx, a, b, share, CERT_DEPTH, pc, &np))
    return 0;
  *val = *err = 0;
  for (i = 0; i < np; i++) {
    *val += pc[i].v;
    *err += pc[i].e + 2 * DBL_EPSILON * fabs(*val);
  }
  return 1;
}

int arclen_seg_invert(arclen_seg_lenfn len, arclen_seg_speedfn speed,
                      arclen_seg_boundfn bound,
                      arclen_seg_orderfn order, const void *ctx,
                      double total, double s, double tol, double guess,
                      double from[3], double *t, long *evals) {
  double lo = from[0], hi = 1, x0, f0, e0, x, f, d, nx, q, qerr, c0, cf, ce;
  double best = from[0], bestf = fabs(from[1] - s), bestlen = from[1];
  double besterr = from[2];
  int i, j, rc;
  if (evals) *evals = 0;
  /* the certified start already answers (a distance within tol of the
  ** last one), or lies beyond s (unsorted input): start from 0 */
  if (bestf + besterr <= tol) { *t = from[0]; return ARCLEN_OK; }
  if (from[1] > s) { lo = 0; best = 0; bestf = s; bestlen = 0; besterr = 0; }
  if (!(s > 0)) { *t = from[0] = from[1] = from[2] = 0; return ARCLEN_OK; }
  if (!(s < total)) {
    *t = from[0] = 1; from[1] = total; from[2] = HUGE_VAL;   /* total: the caller's */
    return ARCLEN_OK;
  }
  x = guess > lo && guess < 1 ? guess : lo + (1 - lo) * (s - bestlen) / (total - bestlen);
  if (!(x > lo && x < 1)) x = lo + (1 - lo) / 2;
  /* the first model from the nearer known point: the start, or the end
  ** (f(1) = total - s, the caller's total: a model only, no certificate) */
  if (x - lo <= 1 - x) { x0 = lo; f0 = bestlen - s; e0 = besterr; }
  else { x0 = 1; f0 = total - s; e0 = HUGE_VAL; }
  for (i = 0; i < MAX_STEPS; i++) {
    /* Newton on the model f0 + int_x0^x speed, inside the bracket */
    model_piece pc[MODEL_STEPS + 1];
    int np = 1;
    pc[0].a = x0; pc[0].b = x; pc[0].n = MODEL_NODES;
    pc[0].v = model(speed, ctx, MODEL_NODES, x0, x);
    q = f0 + pc[0].v;
    for (j = 0; j < MODEL_STEPS && fabs(q) > tol / 4; j++) {
      d = speed(ctx, x);
      if (!(d > 0)) break;
      nx = x - q / d;
      if (!(nx > lo && nx < hi) || nx == x) break;
      /* a long step (a poor guess) gets the first rule's order */
      pc[np].a = x; pc[np].b = nx;
      pc[np].n = fabs(nx - x) * 8 < fabs(x - x0) ? STEP_NODES : MODEL_NODES;
      pc[np].v = model(speed, ctx, pc[np].n, x, nx);
      q += pc[np++].v;
      x = nx;
    }
    /* the model certifies itself where its error bound (the rules',
    ** the start's, the sums' roundings) leaves |f| <= tol; the length
    ** at x is then s + q within qerr, and the next search starts there */
    if (e0 < tol &&
        model_certifies(bound, ctx, pc, np, e0, q, s, tol, &qerr)) {
      *t = from[0] = x;
      from[1] = s + q;
      from[2] = qerr;
      return ARCLEN_OK;
    }
    /* where the model's pieces do not certify (its first range is long,
    ** where a rule rarely meets its bound), the range from its certified
    ** start again by rules that do (a conic: an exact length costs
    ** Carlson's integrals, some ten such rules) -- from the search's start
    ** where the model ran from the end, whose length is the caller's total
    ** (no certificate); when not within tol, the value starts the next
    ** model as an exact one would */
    if (i == 0 && !(e0 < tol / 4)) { c0 = lo; cf = bestlen - s; ce = besterr; }
    else { c0 = x0; cf = f0; ce = e0; }
    if (ce < tol / 4 && x != c0 &&
        tol >= ARCLEN_SEG_COVER_RTOL * total &&
        certified_integral(speed, order, ctx, fmin(c0, x), fmax(c0, x),
                           tol / 4, &q, &qerr)) {
      f = cf + (x > c0 ? q : -q);
      qerr += ce + 2 * DBL_EPSILON * (fabs(s) + fabs(f));
      if (fabs(f) + qerr <= tol) {
        *t = from[0] = x;
        from[1] = s + f;
        from[2] = qerr;
        return ARCLEN_OK;
      }
      if (fabs(f) > qerr) {            /* its sign certain: the bracket moves */
        if (f < 0) lo = x; else hi = x;
        if (fabs(f) < bestf) {
          bestf = fabs(f); best = x; bestlen = s + f; besterr = qerr;
        }
        x0 = x; f0 = f; e0 = qerr;
        d = speed(ctx, x);
        nx = d > 0 ? x - f / d : lo + (hi - lo) / 2;
        if (!(nx > lo && nx < hi)) nx = lo + (hi - lo) / 2;
        if (nx == x || !(nx > lo && nx < hi)) break;
        x = nx;
        continue;
      }
    }
    rc = len(ctx, x, &f);
    if (evals) (*evals)++;
    if (rc != ARCLEN_OK) return rc;
    if (fabs(f - s) < bestf) { bestf = fabs(f - s); best = x; bestlen = f; besterr = 0; }
    f -= s;
    if (fabs(f) <= tol) break;
    if (f < 0) lo = x; else hi = x;
    x0 = x; f0 = f; e0 = 0;
    /* the next model's start: Newton's step on the exact value */
    d = speed(ctx, x);
    nx = d > 0 ? x - f / d : lo + (hi - lo) / 2;
    if (!(nx > lo && nx < hi)) nx = lo + (hi - lo) / 2;
    if (nx == x || !(nx > lo && nx < hi)) break;   /* lo, hi adjacent */
    x = nx;
  }
  *t = from[0] = best;
  from[1] = bestlen;
  from[2] = besterr;
  return ARCLEN_OK;
}
