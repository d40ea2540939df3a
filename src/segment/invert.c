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
** model's guess.  A first search without the total (a single time below
** the cover's tolerance, where the total's exact length would cost as
** much as the search's own) takes tol as rtol times a certified lower
** bound of L, the chord at first and then each certified length at x plus
** the rest's chord (the kind's below), and measures the total only where
** s is not below that bound (s may reach L: t = 1 there) or Newton from
** below would pass t = 1; a total measured here is an exact length, so
** f(1) = total - s is a certified value to step from.  Certified
** values keep a bracket [lo, hi] (f(lo) < 0 < f(hi)) that every step
** stays inside (next_point: Newton's step, else one from the bracket's
** lower end, else bisection); a cap ends it besides.  Where no double t
** holds s within tol (a conic of w beyond ~2^52, whose last leg lies in t
** > 1 - 1/w), the answer is the t nearest in length of those measured and
** the end.
*/
#include <float.h>
#include <math.h>

#include "arclen.h"
#include "curve/numeric.h"
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

/* int_a^b speed by the n-point Gauss-Legendre rule (signed): the models'
** pieces, the cover's, and segment.c's guess of a conic's total. */
double arclen_seg_rule(arclen_seg_speedfn speed, const void *ctx, int n,
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
    pc[*np].v = arclen_seg_rule(speed, ctx, n, a, b);
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

/* What a search knows of the length's scale: the total (NAN until
** measured, where the caller had none; exact where measured here, so
** that f(1) = total - s is a certified value), tol and the length ref it
** is rtol times (the total, or while lazy a certified lower bound of
** it), and the exact lengths counted. */
typedef struct search_scale {
  arclen_seg_lenfn len;
  arclen_seg_belowfn below;
  const void *ctx;
  double *total, rtol, tol, ref;
  long *evals;
  int lazy, exact;
} search_scale;

/* The total's exact length where the search needs it (NAN: the caller
** had none), counted, and tol = rtol times it where the caller left tol
** to rtol (NAN) or the search was lazy; the search is lazy no more.
** Returns the length function's code. */
static int settle(search_scale *sc) {
  if (isnan(*sc->total)) {
    int rc = sc->len(sc->ctx, 1, sc->total);
    if (sc->evals) (*sc->evals)++;
    if (rc != ARCLEN_OK) return rc;
    sc->exact = 1;
  }
  if (sc->lazy || isnan(sc->tol)) sc->tol = sc->rtol * *sc->total;
  sc->ref = *sc->total;
  sc->lazy = 0;
  return ARCLEN_OK;
}

/* A lazy search's certified length at x, at least lenx (exact, or a
** model's value less its bound): the lower bound of L it gives (the
** kind's below) raises tol to rtol times it (rtol times any lower bound
** of L is within rtol L); where s is not below it, s may reach L and the
** total is measured (settle), *end set where s is at or past it (t = 1
** is the answer).  Returns the length function's code. */
static int still_below(search_scale *sc, double x, double lenx, double s,
                       int *end) {
  double lb;
  int rc;
  *end = 0;
  if (!sc->lazy) return ARCLEN_OK;
  lb = sc->below(sc->ctx, x, lenx);
  if (lb > sc->ref) { sc->ref = lb; sc->tol = sc->rtol * lb; }
  if (s < lb) return ARCLEN_OK;
  rc = settle(sc);
  *end = rc == ARCLEN_OK && !(s < *sc->total);
  return rc;
}

/* s at or past the total: t = 1 and the total's length, whose bound is
** none where it is the caller's. */
static int at_end(const search_scale *sc, double from[3], double *t) {
  *t = from[0] = 1;
  from[1] = *sc->total;
  from[2] = sc->exact ? 0 : HUGE_VAL;
  return ARCLEN_OK;
}

/* The next point after x: nx (Newton's step) where arclen_step_ok takes
** it (*last: the step before, then the step taken); else Newton's step
** from lo (f(lo) = flo), but not twice running, where it stays inside:
** the speed can fall by orders across the bracket (w = 1e100 puts a
** conic's first leg in t < 1e-99, which halving from 1 does not reach
** within the cap); else the middle, so that the bracket halves every
** second step at least. */
static double next_point(arclen_seg_speedfn speed, const void *ctx,
                         double nx, double x, double lo, double flo,
                         double hi, double *last, int *from_lo) {
  if (arclen_step_ok(nx, x, lo, hi, *last)) {
    *from_lo = 0;
  } else {
    double d = *from_lo ? 0 : speed(ctx, lo);
    nx = d > 0 ? lo - flo / d : -1;
    *from_lo = nx > lo && nx < hi;
    if (!*from_lo) nx = lo + (hi - lo) / 2;
  }
  *last = fabs(nx - x);
  return nx;
}

int arclen_seg_invert(arclen_seg_lenfn len, arclen_seg_speedfn speed,
                      arclen_seg_boundfn bound, arclen_seg_orderfn order,
                      arclen_seg_belowfn below, const void *ctx,
                      double *total, double s, double rtol, double tol,
                      double guess, double from[3], double *t, long *evals) {
  double lo = from[0], hi = 1, x0, f0, e0, x, f, d, nx, q, qerr, c0, cf, ce;
  double best = from[0], bestf = fabs(from[1] - s), bestlen = from[1];
  double besterr = from[2];
  search_scale sc;
  double last = HUGE_VAL, flo = from[1] - s;   /* the step before, f(lo) */
  int i, j, rc, end, from_lo = 0;
  if (evals) *evals = 0;
  if (!(s > 0)) { *t = from[0] = from[1] = from[2] = 0; return ARCLEN_OK; }
  sc.len = len; sc.below = below; sc.ctx = ctx; sc.total = total;
  sc.rtol = rtol; sc.tol = tol; sc.evals = evals; sc.exact = 0;
  /* a first search (from 0) for s > 0 with its first guess inside needs
  ** no total: tol is rtol times a certified lower bound of L (below's,
  ** from the chord, then from each certified length), the total measured
  ** only where s may reach L (the clamp, t = 1 at L) */
  sc.lazy = isnan(*total) && from[0] == 0 && from[1] == 0 && from[2] == 0 &&
            guess > 0 && guess < 1;
  if (sc.lazy) {
    sc.ref = below(ctx, 0, 0);
    sc.tol = rtol * sc.ref;
  } else {
    rc = settle(&sc);
    if (rc != ARCLEN_OK) return rc;
  }
  /* the certified start already answers (a distance within tol of the
  ** last one), or lies beyond s (unsorted input): start from 0 */
  if (bestf + besterr <= sc.tol) { *t = from[0]; return ARCLEN_OK; }
  if (from[1] > s) {
    lo = 0; flo = -s;
    best = 0; bestf = s; bestlen = 0; besterr = 0;
  }
  if (!sc.lazy && !(s < *total)) return at_end(&sc, from, t);
  x = guess > lo && guess < 1 ? guess : lo + (1 - lo) * (s - bestlen) / (*total - bestlen);
  if (!(x > lo && x < 1)) x = lo + (1 - lo) / 2;
  /* the first model from the nearer known point: the start, or the end
  ** (f(1) = total - s: certified where the total was measured here, a
  ** model only where it is the caller's; a lazy search has none) */
  if (sc.lazy || x - lo <= 1 - x) { x0 = lo; f0 = bestlen - s; e0 = besterr; }
  else { x0 = 1; f0 = *total - s; e0 = sc.exact ? 0 : HUGE_VAL; }
  for (i = 0; i < MAX_STEPS; i++) {
    /* Newton on the model f0 + int_x0^x speed, inside the bracket */
    model_piece pc[MODEL_STEPS + 1];
    int np = 1;
    pc[0].a = x0; pc[0].b = x; pc[0].n = MODEL_NODES;
    pc[0].v = arclen_seg_rule(speed, ctx, MODEL_NODES, x0, x);
    q = f0 + pc[0].v;
    for (j = 0; j < MODEL_STEPS && fabs(q) > sc.tol / 4; j++) {
      d = speed(ctx, x);
      if (!(d > 0)) break;
      nx = x - q / d;
      if (!(nx > lo && nx < hi) || nx == x) break;
      /* a long step (a poor guess) gets the first rule's order */
      pc[np].a = x; pc[np].b = nx;
      pc[np].n = fabs(nx - x) * 8 < fabs(x - x0) ? STEP_NODES : MODEL_NODES;
      pc[np].v = arclen_seg_rule(speed, ctx, pc[np].n, x, nx);
      q += pc[np++].v;
      x = nx;
    }
    /* the model certifies itself where its error bound (the rules',
    ** the start's, the sums' roundings) leaves |f| <= tol; the length
    ** at x is then s + q within qerr, and the next search starts there
    ** (a lazy search's where s is below L; a larger tol from the total
    ** only widens the certificate) */
    if (e0 < sc.tol &&
        model_certifies(bound, ctx, pc, np, e0, q, s, sc.tol, &qerr)) {
      rc = still_below(&sc, x, s + q - qerr, s, &end);
      if (rc != ARCLEN_OK) return rc;
      if (end) return at_end(&sc, from, t);
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
    if (i == 0 && !(e0 < sc.tol / 4)) { c0 = lo; cf = bestlen - s; ce = besterr; }
    else { c0 = x0; cf = f0; ce = e0; }
    if (ce < sc.tol / 4 && x != c0 &&
        sc.tol >= ARCLEN_SEG_COVER_RTOL * sc.ref &&
        certified_integral(speed, order, ctx, fmin(c0, x), fmax(c0, x),
                           sc.tol / 4, &q, &qerr)) {
      f = cf + (x > c0 ? q : -q);
      qerr += ce + 2 * DBL_EPSILON * (fabs(s) + fabs(f));
      rc = still_below(&sc, x, s + f - qerr, s, &end);
      if (rc != ARCLEN_OK) return rc;
      if (end) return at_end(&sc, from, t);
      if (fabs(f) + qerr <= sc.tol) {
        *t = from[0] = x;
        from[1] = s + f;
        from[2] = qerr;
        return ARCLEN_OK;
      }
      if (fabs(f) > qerr) {            /* its sign certain: the bracket moves */
        if (f < 0) { lo = x; flo = f; } else hi = x;
        if (fabs(f) < bestf) {
          bestf = fabs(f); best = x; bestlen = s + f; besterr = qerr;
        }
        x0 = x; f0 = f; e0 = qerr;
        d = speed(ctx, x);
        nx = next_point(speed, ctx, d > 0 ? x - f / d : -1, x, lo, flo, hi,
                        &last, &from_lo);
        if (nx == x || !(nx > lo && nx < hi)) break;
        x = nx;
        continue;
      }
    }
    rc = len(ctx, x, &f);
    if (evals) (*evals)++;
    if (rc != ARCLEN_OK) return rc;
    rc = still_below(&sc, x, f, s, &end);
    if (rc != ARCLEN_OK) return rc;
    if (end) return at_end(&sc, from, t);
    if (fabs(f - s) < bestf) { bestf = fabs(f - s); best = x; bestlen = f; besterr = 0; }
    f -= s;
    if (fabs(f) <= sc.tol) break;
    if (f < 0) { lo = x; flo = f; } else hi = x;
    x0 = x; f0 = f; e0 = 0;
    /* the next model's start: Newton's step on the exact value, or on the
    ** end's where it is certified (the total measured here) and nearer
    ** in length.  Near L, Newton from below overshoots t = 1 where the
    ** speed grows, and halving towards it cost an exact length a bit: a
    ** lazy search measures the total there and steps from the end */
    d = speed(ctx, x);
    if (sc.lazy && hi == 1 && d > 0 && !(x - f / d < 1)) {
      rc = settle(&sc);
      if (rc != ARCLEN_OK) return rc;
      if (!(s < *total)) return at_end(&sc, from, t);
    }
    if (sc.exact && hi == 1 && *total - s < fabs(f)) {
      x0 = 1; f0 = *total - s;
      d = speed(ctx, x0);
    }
    nx = next_point(speed, ctx, d > 0 ? x0 - f0 / d : -1, x, lo, flo, hi,
                    &last, &from_lo);
    if (nx == x || !(nx > lo && nx < hi)) break;   /* lo, hi adjacent */
    x = nx;
  }
  if (bestf + besterr > sc.tol) {       /* not met: the end, if nearer */
    rc = settle(&sc);
    if (rc != ARCLEN_OK) return rc;
    if (fabs(*total - s) < bestf) return at_end(&sc, from, t);
  }
  *t = from[0] = best;
  from[1] = bestlen;
  from[2] = besterr;
  return ARCLEN_OK;
}
