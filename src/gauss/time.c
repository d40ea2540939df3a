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
** r = a_semi - 1 = e / (sqrt(1 + e) + 1) (times half_width) about every point of
** the piece, so |f'| <= M / r (Cauchy's estimate). */
static double disc_radius(const piece_bound *pbound, double half_width) {
  return half_width * pbound->e / (sqrt(1 + pbound->e) + 1);
}

static int newton_certified(const piece_bound *pbound, double half_width, double d,
                            double tol) {
  return pbound->m * d * d <= 2 * tol * disc_radius(pbound, half_width);
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

/* The terms past d of the root of g + f e + f1 e^2/2 + f2 e^3/6 = 0 by
** series reversion in d = -g/f: e = d - (f1/2f) d^2 + (f1^2/2f^2 -
** f2/6f) d^3. */
static double reversion_tail(double d, double f, double f1, double f2) {
  return d * d * (-f1 / (2 * f) + d * (f1 * f1 / (2 * f * f) - f2 / (6 * f)));
}

/* The step to the root of the Taylor polynomial of second order, from the
** Newton step d = -g/f and the slope f1 of the speed: e = d - c with c =
** f1 d^2 / (2 f) makes g + f e + f1 e^2 / 2 = (f1 / 2) c (c - 2 d), and
** the remainder is at most max |f''| |e|^3 / 6 with |f''| <= 2 M / r^2
** (Cauchy, as for newton_certified).  Returns e when the two are within
** tol (1/1024 of it kept for rounding), else 0 (e = 0 means g = 0, which
** the caller has taken already). */
static double second_order_step(const piece_bound *pbound, double half_width, double d,
                                double f, double f1, double tol) {
  double r = disc_radius(pbound, half_width), c = f1 * d * d / (2 * f), e = d - c;
  double res = fabs(f1 / 2 * c * (c - 2 * d)) +
               pbound->m * fabs(e * e * e) / (3 * r * r);
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
    double d = -sg / f, f1, f2, e;
    speed_slopes(&in->h, t, f, &f1, &f2);
    e = d + reversion_tail(d, f, f1, f2);
    if (t + e > a && t + e < b) return t + e;
  }
  return t;
}

/* The integral over [x, y] inside an accepted piece to within target
** (scaled units).  The piece's Bernstein ellipse (ebound, half-width hp) holds
** the disc of radius r = hp (a_semi - 1) about every point of the piece
** (disc_radius), so a short [x, y] of half-width h has the
** ellipse of semi-minor axis r inside it, rho = r/h + sqrt(1 + (r/h)^2),
** with |f| <= M there: the ellipse bound (integrator.h's head) at that
** rho sets its order, for a few operations.  A longer one takes its own
** branch-cut bound, or the piece's rule r when that is not at hand. */
static double sub_integral(integrator *in, double x, double y, double target,
                           const piece_bound *ebound, double hp,
                           const arclen_gauss_rule *r) {
  double c = x + (y - x) / 2, h = (y - x) / 2;
  double rad = disc_radius(ebound, hp);
  int n = 0;
  if (!(h > 0)) return 0;
  if (h < rad / 2) {
    double beta = rad / h, rho = beta + sqrt(1 + beta * beta);
    double lnum = arclen_rough_log2(h * (64.0 / 15.0) * ebound->m / target) -
                  arclen_rough_log2(rho * rho - 1) + 2 * ARCLEN_LOG2_ERR;
    double nn = 1 + lnum / (2 * (arclen_rough_log2(rho) - ARCLEN_LOG2_ERR));
    n = nn <= 2 ? 2 : nn < ARCLEN_GAUSS_MAX ? (int)ceil(nn) : 0;
  }
  if (!n && !ebound->inside && ebound->log_rho2 > 0) {
    /* The piece's own ellipse: [x, y] lies in the piece, so the ellipse of
    ** [x, y] with the piece's rho lies inside the piece's (the Green's
    ** function of a subset is the larger), where |f| <= M: the bound at
    ** the piece's rho, M and 2^logc = M rho^2/(rho^2 - 1), scaled by h. */
    double nn = (arclen_rough_log2(h * (64.0 / 15.0) / target) + ARCLEN_LOG2_ERR +
                 ebound->logc) / ebound->log_rho2;
    n = nn <= 2 ? 2 : nn < ARCLEN_GAUSS_MAX ? (int)ceil(nn) : 0;
  }
  if (!n) arclen_integ_prepare_bounds(in);   /* taken when first needed */
  if (!n && in->cc.ok) {
    arclen_cut_piece cp;
    double lg = arclen_rough_log2(target) - arclen_rough_log2(h) - in->lead_log - 2 * ARCLEN_LOG2_ERR;
    arclen_cut_bound(&in->cc, c, h, &cp);
    n = arclen_cut_order(&in->cc, &cp, lg, ARCLEN_GAUSS_MAX, NULL);
  }
  if (n) r = arclen_rule_at_least(n);
  in->evals += r->n;
  return arclen_apply_rule(&in->h, r, c, h);
}

/* An accepted piece [a, b] (half-width hp), its length plen and rule r
** (scaled units), and its Bernstein ellipse ebound (M and e for Cauchy's
** estimates), shared by every search inside it. */
typedef struct piece_search {
  double a, b, plen, hp;
  const arclen_gauss_rule *r;
  piece_bound ebound;
} piece_search;

static void search_piece(integrator *in, piece_search *p, double a, double b,
                         double plen, const arclen_gauss_rule *r) {
  p->a = a;
  p->b = b;
  p->plen = plen;
  p->hp = (b - a) / 2;
  p->r = r;
  arclen_bound_piece(&in->br, a + (b - a) / 2, (b - a) / 2, &p->ebound);
  in->evals += 2;
}

/* [lo, hi] holds the answer; slo, shi: s there, from the piece's start. */
typedef struct bracket {
  double lo, slo, hi, shi;
} bracket;

/* Safeguarded Newton for s(t) = goal from the guess t inside the bracket
** (goal in [slo, shi]): s is increasing, so the bracket always holds the
** answer, and a step leaving it is replaced by bisection.  s(t) is taken
** from the nearer end of the bracket, whose s is known, plus the integral
** between (sub_integral): near the answer these are short and need few
** points.  The k-th such integral may err by share 2^-k, so the s values
** known err by less than 2 share more than the bracket's did.  The bracket
** is left holding the last points evaluated, for a search that follows. */
static double newton_search(integrator *in, const piece_search *p,
                            bracket *bk, double t, double goal, double tol,
                            double share) {
  double lo = bk->lo, hi = bk->hi, slo = bk->slo, shi = bk->shi;
  int it;
  if (t < lo || t > hi) t = lo + (hi - lo) / 2;   /* a guess from the piece */
  for (it = 0; it < 100; it++) {
    double g, f, next;
    if (t - lo <= hi - t)
      g = slo + sub_integral(in, lo, t, share, &p->ebound, p->hp, p->r) - goal;
    else
      g = shi - sub_integral(in, t, hi, share, &p->ebound, p->hp, p->r) - goal;
    share /= 2;
    f = arclen_hodo_speed(&in->h, t);
    in->evals++;
    if (g < 0) {
      lo = t;
      slo = g + goal;
    } else if (g > 0) {
      hi = t;
      shi = g + goal;
    }
    if (fabs(g) <= tol) break;
    next = f > 0 ? t - g / f : lo + (hi - lo) / 2;
    if (!(f > 0 && next > lo && next < hi)) {   /* a Newton step only */
      next = lo + (hi - lo) / 2;
    } else if (newton_certified(&p->ebound, p->hp, next - t, tol)) {
      t = next;
      break;
    } else {
      double f1, f2, e, d = -g / f, e3;
      speed_slopes(&in->h, t, f, &f1, &f2);
      e = second_order_step(&p->ebound, p->hp, d, f, f1, tol);
      if (e != 0 && t + e > lo && t + e < hi) {
        t = t + e;
        break;
      }
      /* not certified: the next point from the third-order step (series
      ** reversion, as refine_guess), nearer than Newton's for the same
      ** slopes */
      e3 = d + reversion_tail(d, f, f1, f2);
      if (t + e3 > lo && t + e3 < hi) next = t + e3;
    }
    if (next == t || hi - lo <= 4e-16 * fmax(fabs(hi), 1e-300)) break;
    t = next;
  }
  bk->lo = lo;
  bk->slo = slo;
  bk->hi = hi;
  bk->shi = shi;
  return t;
}

/* s(t) = goal inside the accepted piece [a, b] of length plen (goal in
** [0, plen]): the Hermite guess, refined, then the Newton search with the
** whole piece as its bracket and half of tol for its integrals. */
static double solve_in_piece(integrator *in, double a, double b, double plen,
                             double goal, double tol,
                             const arclen_gauss_rule *r) {
  piece_search p;
  bracket bk;
  double t = hermite_guess(&in->h, a, b, plen, goal);
  search_piece(in, &p, a, b, plen, r);
  t = refine_guess(in, a, b, plen, goal, r, t);
  bk.lo = a;
  bk.slo = 0;
  bk.hi = b;
  bk.shi = plen;
  return newton_search(in, &p, &bk, t, goal, tol, tol / 2);
}

/* time cuts at the feet within 0.2 of the width, more than the length
** does: a piece where the speed dips sharply defeats the Hermite guess
** (off by up to half the piece), and each further Newton step is a chain
** of a bound, a rule and a division (doc/benchmarks.md: the shares tried). */
#define TIME_FOOTCUT 0.2

/* time's common case, as arclen_integ_integrate() takes it: the first pieces' orders
** straight from the branch points (arclen_cut_orders), then their rules in
** increasing t up to the piece that holds the goal.  The first piece's
** order comes alone, the others' only when the goal lies past it: at L/2
** a third of the orders went to pieces never reached.  Returns 0 when
** those orders are not to be had (a piece to cut, a real or far root):
** the caller then takes the stack, whose pieces and rules before the
** goal are the same, so the answer does not depend on where it failed. */
static int time_first_pieces(integrator *in, double goal, double *t) {
  double c[ARCLEN_CUT_PIECES], half_width[ARCLEN_CUT_PIECES], cum = 0;
  int n[ARCLEN_CUT_PIECES], i;
  arclen_integ_first_pieces(in, c, half_width);
  if (!arclen_integ_orders_of(in, 0, 1, c, half_width, n)) return 0;
  for (i = 0; i <= in->nmin; i++) {
    if (i == 1 && !arclen_integ_orders_of(in, 1, in->nmin + 1, c, half_width, n))
      return 0;
    const arclen_gauss_rule *r = arclen_rule_at_least(n[i]);
    double piece = arclen_apply_rule(&in->h, r, c[i], half_width[i]);
    in->evals += r->n;
    in->pieces++;
    if (cum + piece >= goal) {
      if (i == in->nmin && goal >= cum + piece) return 1;   /* t = 1 */
      *t = solve_in_piece(in, arclen_first_from(in, i), arclen_first_to(in, i), piece,
                          goal - cum, in->rtol * in->len_lower, r);
      return 1;
    }
    cum += piece;
  }
  return 1;                            /* s >= L: t = 1 */
}

int arclen_time_gauss(const double *c, int dim, double s,
                      const arclen_opts *o, double *t, arclen_info *info) {
  integrator in;
  double cum = 0, pa, pbound, piece, goal;
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
  while (arclen_integ_next_piece(&in, &pa, &pbound, &piece, &r)) {
    if (cum + piece >= goal) {
      if (in.top == 0 && goal >= cum + piece) break;   /* s >= L: t = 1 */
      *t = solve_in_piece(&in, pa, pbound, piece, goal - cum,
                          o->rtol * 0.25 * in.len_lower, r);
      break;
    }
    cum += piece;
  }
  arclen_integ_fill_info(info, &in, in.h.exp);
  return ARCLEN_OK;
}

/* The pieces of the integral in increasing t: the first pieces with their
** orders straight from the branch points when those are to be had (as
** time_first_pieces), else the integrator's stack (as arclen_time_gauss). */
typedef struct piece_walk {
  int fast, k;
  double c[ARCLEN_CUT_PIECES], half_width[ARCLEN_CUT_PIECES];
  int n[ARCLEN_CUT_PIECES];
} piece_walk;

static int walk_next(integrator *in, piece_walk *w, double *a, double *b,
                     double *len, const arclen_gauss_rule **r, int *last) {
  if (w->fast) {
    if (w->k > in->nmin) return 0;
    *r = arclen_rule_at_least(w->n[w->k]);
    *len = arclen_apply_rule(&in->h, *r, w->c[w->k], w->half_width[w->k]);
    *a = arclen_first_from(in, w->k);
    *b = arclen_first_to(in, w->k);
    in->evals += (*r)->n;
    in->pieces++;
    *last = w->k == in->nmin;
    w->k++;
    return 1;
  }
  if (!arclen_integ_next_piece(in, a, b, len, r)) return 0;
  *last = in->top == 0;
  return 1;
}

#define CHAIN 16

/* A later distance in the same piece: the search starts from the bracket
** the previous one left (its lower end lo, where s is slo < goal), with
** the third-order step from lo as its guess (series reversion, as in
** refine_guess), so its integrals are short. */
static double chained_guess(const integrator *in, const bracket *bk,
                            double goal) {
  double f = arclen_hodo_speed(&in->h, bk->lo), t;
  if (f > 0) {
    double d = (goal - bk->slo) / f, f1, f2;
    speed_slopes(&in->h, bk->lo, f, &f1, &f2);
    t = bk->lo + d + reversion_tail(d, f, f1, f2);
    if (t > bk->lo && t < bk->hi) return t;
  }
  return bk->lo + (bk->hi - bk->lo) / 2;
}

/* The distances s[i..] that the piece of length plen starting at cum
** holds (as arclen_time_gauss decides it: s <= cum + plen, and on the last
** piece not s >= cum + plen, which is t = 1), each s scaled by 2^-exp. */
static long goals_in_piece(const double *s, long i, long n, int exp,
                           double cum, double plen, int last) {
  long j = i;
  while (j < n) {
    double g = ldexp(s[j], exp);
    if (!(cum + plen >= g) || (last && g >= cum + plen)) break;
    j++;
  }
  return j - i;
}

int arclen_times(const double *c, int dim, const double *s, long n,
                 double rtol, double *t, double *pts, double *tan) {
  integrator in;
  piece_walk w;
  double cum = 0, tol;
  long i, j;
  int e = arclen_integ_check_args(c, dim, rtol, 0, 1);
  if (!e && n < 0) e = ARCLEN_EDOMAIN;
  for (i = 0; !e && i < n; i++) {
    if (isnan(s[i])) e = ARCLEN_EINVAL;
    else if (i > 0 && s[i] < s[i - 1]) e = ARCLEN_EDOMAIN;
  }
  if (e) {
    for (i = 0; i < n; i++) t[i] = NAN;
    return e;
  }
  for (i = 0; i < n && s[i] <= 0; i++) t[i] = 0;
  for (j = i; j < n; j++) t[j] = 1;
  if (i < n && arclen_integ_start(&in, c, dim, 0, 1, rtol * 0.25,
                                  TIME_FOOTCUT)) {
    w.fast = arclen_integ_first_orders(&in, w.c, w.half_width, w.n);
    w.k = 0;
    if (!w.fast) {
      arclen_integ_prepare_bounds(&in);
      arclen_integ_push_initial(&in);
    }
    tol = in.rtol * in.len_lower;
    while (i < n) {
      double pa, pbound, plen;
      const arclen_gauss_rule *r;
      int last;
      long m, q;
      piece_search p;
      bracket bk;
      if (!walk_next(&in, &w, &pa, &pbound, &plen, &r, &last)) break;
      m = goals_in_piece(s, i, n, -in.h.exp, cum, plen, last);
      if (m > 0) {
        /* A chain of searches, each from the bracket the last one left,
        ** carries its s values on: CHAIN goals at most (then the piece's
        ** ends again), each whose integrals err by tol / CHAIN in all, so
        ** that the s values err by less than tol, as one search's do, and
        ** the chain's roundings stay within CHAIN additions. */
        double budget = tol / (double)(m < CHAIN ? m : CHAIN);
        search_piece(&in, &p, pa, pbound, plen, r);
        for (q = 0; q < m; q++, i++) {
          double goal = ldexp(s[i], -in.h.exp) - cum, guess;
          if (q > 0 && s[i] == s[i - 1]) {
            t[i] = t[i - 1];
            continue;
          }
          if (q % CHAIN == 0 || goal >= bk.shi) {   /* the piece's end */
            bk.hi = pbound;
            bk.shi = plen;
          }
          if (q % CHAIN == 0) {
            bk.lo = pa;
            bk.slo = 0;
          }
          if (bk.lo == pa) {
            guess = refine_guess(&in, pa, pbound, plen, goal, r,
                                 hermite_guess(&in.h, pa, pbound, plen, goal));
          } else {
            guess = chained_guess(&in, &bk, goal);
          }
          t[i] = newton_search(&in, &p, &bk, guess, goal, tol, budget / 2);
        }
      }
      if (last) break;
      cum += plen;
    }
  }
  /* ascending, as the distances: each t within tol L of its truth, so a t
  ** below the one before it may take that one's place and stay within */
  for (i = 1; i < n; i++)
    if (t[i] < t[i - 1]) t[i] = t[i - 1];
  if (pts || tan)
    for (i = 0; i < n; i++) {
      if (pts) arclen_point(c, dim, t[i], pts + dim * i);
      if (tan) arclen_unit_tangent(c, dim, t[i], tan + dim * i);
    }
  return ARCLEN_OK;
}
