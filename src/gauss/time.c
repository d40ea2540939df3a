/*
** time.c -- the default method's inverse ("gauss"): the parameter t at
** which the length from 0 reaches s, by safeguarded Newton inside the
** integrator's piece that holds s (integrator.h).
*/
#include "gauss/integrator.h"

/* Whether a Newton step d from t (d = -g/f) lands within tol of the goal
** without evaluating there: s(t + d) - goal = g + f d + R = R (up to the
** rule error of g, which the tolerance's other half covers), and Taylor
** gives |R| <= max |f'| d^2 / 2.  On the piece f is analytic inside its
** Bernstein ellipse with |f| <= M, which holds a disc of radius
** r = a_semi - 1 = e / (sqrt(1 + e) + 1) (times hh) about every point of
** the piece, so |f'| <= M / r (Cauchy's estimate). */
static double disc_radius(const piece_bound *pb, double hh) {
  return hh * pb->e / (sqrt(1 + pb->e) + 1);
}

static int newton_certified(const piece_bound *pb, double hh, double d,
                            double tol) {
  return pb->m * d * d <= 2 * tol * disc_radius(pb, hh);
}

/* The speed's first and second derivatives at t, where it is f > 0:
** f1 = (z' . z'')/f and f2 = (|z''|^2 + z' . z''' - f1^2)/f. */
static void speed_slopes(const arclen_hodo *h, double t, double f,
                         double *f1, double *f2) {
  double p = 0, q = 0;
  int k;
  for (k = 0; k < h->dim; k++) {
    double v = (h->a2[k] * t + h->a1[k]) * t + h->a0[k];
    double v1 = 2 * h->a2[k] * t + h->a1[k];
    p += v * v1;
    q += v1 * v1 + v * 2 * h->a2[k];
  }
  *f1 = p / f;
  *f2 = (q - *f1 * *f1) / f;
}

/* The step to the root of the Taylor polynomial of second order, from the
** Newton step d = -g/f and the slope f1 of the speed: e = d - c with c =
** f1 d^2 / (2 f) makes g + f e + f1 e^2 / 2 = (f1 / 2) c (c - 2 d), and
** the remainder is at most max |f''| |e|^3 / 6 with |f''| <= 2 M / r^2
** (Cauchy, as for newton_certified).  Returns e when the two are within
** tol (1/1024 of it kept for rounding), else 0 (e = 0 means g = 0, which
** the caller has taken already). */
static double second_order_step(const piece_bound *pb, double hh, double d,
                                double f, double f1, double tol) {
  double r = disc_radius(pb, hh), c = f1 * d * d / (2 * f), e = d - c;
  double res = fabs(f1 / 2 * c * (c - 2 * d)) +
               pb->m * fabs(e * e * e) / (3 * r * r);
  return res <= tol * (1 - 1.0 / 1024) ? e : 0;
}

/* A first guess for s(t) = goal in [a, b]: the cubic Hermite interpolant
** of s from its values 0, plen and slopes (the speeds) at the ends,
** inverted by three Newton steps on u = (t - a)/(b - a) kept in (0, 1).
** Three, not more: each is a division on the path to the answer, and
** refine_guess() takes the guess much closer for the cost of one. */
#define HERMITE_STEPS 3
static double hermite_guess(const arclen_hodo *h, double a, double b,
                            double plen, double goal) {
  double w = b - a, fa = w * arclen_hodo_speed(h, a);
  double fb = w * arclen_hodo_speed(h, b), u = goal / plen;
  int it;
  for (it = 0; it < HERMITE_STEPS; it++) {
    double u2 = u * u, u3 = u2 * u;
    double s = plen * (3 * u2 - 2 * u3) + fa * (u - 2 * u2 + u3) +
               fb * (u3 - u2) - goal;
    double ds = plen * (6 * u - 6 * u2) + fa * (1 - 4 * u + 3 * u2) +
                fb * (3 * u2 - 2 * u);
    double next = ds > 0 ? u - s / ds : -1;
    if (!(next > 0 && next < 1)) break;      /* keep the last good u */
    u = next;
  }
  return a + w * u;
}

/* A better guess, no bound: s(t) from the piece's own rule r on the nearer
** part of [a, b] (about as good as on the piece), then the third-order
** step from it (series reversion).  The Hermite guess errs by up to ~1e-2
** of the piece where a branch point stands near it; this step saves most
** of the certified evaluations that would follow. */
static double refine_guess(integrator *in, double a, double b, double plen,
                           double goal, const arclen_gauss_rule *r,
                           double t) {
  double sg, f;
  if (t - a <= b - t)
    sg = arclen_apply_rule(&in->h, r, a + (t - a) / 2, (t - a) / 2) - goal;
  else
    sg = plen - arclen_apply_rule(&in->h, r, t + (b - t) / 2, (b - t) / 2) - goal;
  f = arclen_hodo_speed(&in->h, t);
  in->evals += r->n + 1;
  if (f > 0) {
    /* the root of g + f e + f1 e^2/2 + f2 e^3/6 by series reversion in
    ** d = -g/f: e = d - (f1/2f) d^2 + (f1^2/2f^2 - f2/6f) d^3 */
    double d = -sg / f, f1, f2, e;
    speed_slopes(&in->h, t, f, &f1, &f2);
    e = d + d * d * (-f1 / (2 * f) +
                     d * (f1 * f1 / (2 * f * f) - f2 / (6 * f)));
    if (t + e > a && t + e < b) return t + e;
  }
  return t;
}

/* The integral over [x, y] inside an accepted piece to within target
** (scaled units).  The piece's Bernstein ellipse (eb, half-width hp) holds
** the disc of radius r = hp (a_semi - 1) about every point of the piece
** (disc_radius), so a short [x, y] of half-width h has the
** ellipse of semi-minor axis r inside it, rho = r/h + sqrt(1 + (r/h)^2),
** with |f| <= M there: the ellipse bound (integrator.h's head) at that
** rho sets its order, for a few operations.  A longer one takes its own
** branch-cut bound, or the piece's rule r when that is not at hand. */
static double sub_integral(integrator *in, double x, double y, double target,
                           const piece_bound *eb, double hp,
                           const arclen_gauss_rule *r) {
  double c = x + (y - x) / 2, h = (y - x) / 2;
  double rad = disc_radius(eb, hp);
  int n = 0;
  if (!(h > 0)) return 0;
  if (h < rad / 2) {
    double beta = rad / h, rho = beta + sqrt(1 + beta * beta);
    double lnum = arclen_rough_log2(h * (64.0 / 15.0) * eb->m / target) -
                  arclen_rough_log2(rho * rho - 1) + 2 * ARCLEN_LOG2_ERR;
    double nn = 1 + lnum / (2 * (arclen_rough_log2(rho) - ARCLEN_LOG2_ERR));
    n = nn <= 2 ? 2 : nn < ARCLEN_GAUSS_MAX ? (int)ceil(nn) : 0;
  }
  if (!n && !eb->inside && eb->log_rho2 > 0) {
    /* The piece's own ellipse: [x, y] lies in the piece, so the ellipse of
    ** [x, y] with the piece's rho lies inside the piece's (the Green's
    ** function of a subset is the larger), where |f| <= M: the bound at
    ** the piece's rho, M and 2^logc = M rho^2/(rho^2 - 1), scaled by h. */
    double nn = (arclen_rough_log2(h * (64.0 / 15.0) / target) + ARCLEN_LOG2_ERR +
                 eb->logc) / eb->log_rho2;
    n = nn <= 2 ? 2 : nn < ARCLEN_GAUSS_MAX ? (int)ceil(nn) : 0;
  }
  if (!n && in->cc.ok) {
    arclen_cut_piece cp;
    double lg = arclen_rough_log2(target) - arclen_rough_log2(h) - in->lkl - 2 * ARCLEN_LOG2_ERR;
    arclen_cut_bound(&in->cc, c, h, &cp);
    n = arclen_cut_order(&in->cc, &cp, lg, ARCLEN_GAUSS_MAX, NULL);
  }
  if (n) r = arclen_rule_at_least(n);
  in->evals += r->n;
  return arclen_apply_rule(&in->h, r, c, h);
}

/* Safeguarded Newton for s(t) = goal inside an accepted piece [a, b] whose
** length is plen (goal in [0, plen]): s is increasing, so the bracket
** [lo, hi] always holds the answer, and a step leaving it is replaced by
** bisection.  s(t) is taken from the nearer end of the bracket, whose s is
** known, plus the integral between (sub_integral): near the answer these
** are short and need few points.  The k-th such integral may err by
** tol 2^-(k+1), so every s known errs by less than tol in all. */
static double solve_in_piece(integrator *in, double a, double b, double plen,
                             double goal, double tol,
                             const arclen_gauss_rule *r) {
  double lo = a, hi = b, slo = 0, shi = plen, share = tol / 2;
  double t = hermite_guess(&in->h, a, b, plen, goal);
  piece_bound eb;             /* the piece's ellipse: M and e for Cauchy */
  int it;
  arclen_bound_piece(&in->br, a + (b - a) / 2, (b - a) / 2, &eb);
  in->evals += 2;
  t = refine_guess(in, a, b, plen, goal, r, t);
  for (it = 0; it < 100; it++) {
    double g, f, next;
    if (t - lo <= hi - t)
      g = slo + sub_integral(in, lo, t, share, &eb, (b - a) / 2, r) - goal;
    else
      g = shi - sub_integral(in, t, hi, share, &eb, (b - a) / 2, r) - goal;
    share /= 2;
    f = arclen_hodo_speed(&in->h, t);
    in->evals++;
    if (fabs(g) <= tol) break;
    if (g < 0) {
      lo = t;
      slo = g + goal;
    } else {
      hi = t;
      shi = g + goal;
    }
    next = f > 0 ? t - g / f : lo + (hi - lo) / 2;
    if (!(f > 0 && next > lo && next < hi)) {   /* a Newton step only */
      next = lo + (hi - lo) / 2;
    } else if (newton_certified(&eb, (b - a) / 2, next - t, tol)) {
      return next;
    } else {
      double f1, f2, e;
      speed_slopes(&in->h, t, f, &f1, &f2);
      e = second_order_step(&eb, (b - a) / 2, -g / f, f, f1, tol);
      if (e != 0 && t + e > lo && t + e < hi) return t + e;
    }
    if (next == t || hi - lo <= 4e-16 * fmax(fabs(hi), 1e-300)) break;
    t = next;
  }
  return t;
}

/* time cuts at the feet within 0.2 of the width, more than the length
** does: a piece where the speed dips sharply defeats the Hermite guess
** (off by up to half the piece), and each further Newton step is a chain
** of a bound, a rule and a division (doc/benchmarks.md: the shares tried). */
#define TIME_FOOTCUT 0.2

/* time's common case, as arclen_integ_integrate() takes it: the first pieces' orders
** straight from the branch points (arclen_cut_orders), then their rules in
** increasing t up to the piece that holds the goal.  Returns 0, with
** nothing done, when those orders are not to be had (a piece to cut, a
** real or far root): the caller then takes the stack. */
static int time_first_pieces(integrator *in, double goal, double *t) {
  double c[ARCLEN_CUT_PIECES], hh[ARCLEN_CUT_PIECES], cum = 0;
  int n[ARCLEN_CUT_PIECES], i;
  if (!arclen_integ_first_orders(in, c, hh, n)) return 0;
  arclen_integ_prepare_bounds(in);                   /* for sub_integral's cut bounds */
  for (i = 0; i <= in->nmin; i++) {
    const arclen_gauss_rule *r = arclen_rule_at_least(n[i]);
    double piece = arclen_apply_rule(&in->h, r, c[i], hh[i]);
    in->evals += r->n;
    in->pieces++;
    if (cum + piece >= goal) {
      if (i == in->nmin && goal >= cum + piece) return 1;   /* t = 1 */
      *t = solve_in_piece(in, arclen_first_from(in, i), arclen_first_to(in, i), piece,
                          goal - cum, in->rtol * in->lest, r);
      return 1;
    }
    cum += piece;
  }
  return 1;                            /* s >= L: t = 1 */
}

int arclen_time_gauss(const double *c, int dim, double s,
                      const arclen_opts *o, double *t, arclen_info *info) {
  integrator in;
  double cum = 0, pa, pb, piece, goal;
  const arclen_gauss_rule *r;
  int e;
  e = arclen_integ_check_args(c, dim, o->rtol, 0, 1);   /* time ignores o->t0, t1 */
  *t = NAN;
  if (info) arclen_info_init(info);
  if (e) return e;
  if (isnan(s)) return ARCLEN_EINVAL;
  if (s <= 0) { *t = 0; return ARCLEN_OK; }
  if (!arclen_integ_start(&in, c, dim, 0, 1, o->rtol * 0.25, TIME_FOOTCUT)) {
    *t = 1;              /* a point: every s > 0 is past its end */
    return ARCLEN_OK;
  }
  in.want_err = info != NULL;
  goal = ldexp(s, -in.h.exp);
  *t = 1;
  if (!in.want_err && time_first_pieces(&in, goal, t)) {
    arclen_integ_fill_info(info, &in, in.h.exp);
    return ARCLEN_OK;
  }
  arclen_integ_prepare_bounds(&in);
  arclen_integ_push_initial(&in);
  while (arclen_integ_next_piece(&in, &pa, &pb, &piece, &r)) {
    if (cum + piece >= goal) {
      if (in.top == 0 && goal >= cum + piece) break;   /* s >= L: t = 1 */
      *t = solve_in_piece(&in, pa, pb, piece, goal - cum,
                          o->rtol * 0.25 * in.lest, r);
      break;
    }
    cum += piece;
  }
  arclen_integ_fill_info(info, &in, in.h.exp);
  return ARCLEN_OK;
}
