/*
** time.c -- the default method's inverse ("gauss"): the parameter t at
** which the length from 0 reaches s, by safeguarded Newton inside the
** integrator's piece that holds s (integrator.h).
*/
#include "gauss/integrator.h"
#include "gauss/ellipse_table.h"

/* Cauchy's estimates near t: f is analytic within r of [t - D, t + D]
** with |f| <= m there, so that |f^(k)| <= k! m / r^k on [t - D, t + D].
** No branch point lies within dist of the segment (dist, a lower bound of
** the nearest one's distance, the larger of its offsets along and across);
** r = 0.9 dist, and every point within r of the segment is within D + r of
** t, so |f| <= sqrt(lead2) prod (|t - re_k| + im_k + D + r) over the pairs
** (as arclen_bound_piece).  A few operations, where the piece's Bernstein
** ellipse (arclen_bound_piece) took square roots and sees only the branch
** point nearest to the piece; ok 0 where a root is too near. */
typedef struct cauchy {
  double m, r, D;
  int ok;
} cauchy;

static void cauchy_near(const arclen_branch *br, double sqlead, double t,
                        double D, cauchy *cb) {
  double dist = 1, m = sqlead;
  int k;
  for (k = 0; k < br->n; k += 2) {
    double dx = fabs(br->re[k] - t) - D, dk = dx > br->im[k] ? dx : br->im[k];
    dist = dk < dist ? dk : dist;
  }
  cb->D = D;
  cb->r = 0.9 * dist;
  for (k = 0; k < br->n; k += 2) m *= fabs(br->re[k] - t) + br->im[k] + D + cb->r;
  cb->m = m;
  cb->ok = dist > 0 && m < 1e300;
}

/* Whether a Newton step d from t (d = -g/f) lands within tol of the goal
** without evaluating there: s(t + d) - goal = g + f d + R = R (up to the
** rule error of g, which the tolerance's other half covers), and Taylor
** gives |R| <= max |f'| d^2 / 2 with |f'| <= m / r. */
static int newton_certified(const cauchy *cb, double d, double tol) {
  return cb->ok && fabs(d) <= cb->D && cb->m * d * d <= 2 * tol * cb->r;
}

/* The speed's first three derivatives at t, where it is f > 0 (inv = 1/f:
** one division on the search's chain, not one per use), from f^2 = |z'|^2
** differentiated (z'''' = 0): f1 = (z' . z'')/f, f2 = (|z''|^2 + z' .
** z''' - f1^2)/f and f3 = 3 (z'' . z''' - f1 f2)/f. */
static void speed_slopes(const arclen_hodo *h, double t, double inv,
                         double *f1, double *f2, double *f3) {
  double p = 0, q = 0, u = 0;
  int k;
  for (k = 0; k < h->dim; k++) {
    double v = (h->a2[k] * t + h->a1[k]) * t + h->a0[k];
    double v1 = 2 * h->a2[k] * t + h->a1[k];
    p += v * v1;
    q += v1 * v1 + v * 2 * h->a2[k];
    u += v1 * 2 * h->a2[k];
  }
  *f1 = p * inv;
  *f2 = (q - *f1 * *f1) * inv;
  *f3 = 3 * (u - *f1 * *f2) * inv;
}

/* The terms past d of the root of g + f e + f1 e^2/2 + f2 e^3/6 + f3
** e^4/24 = 0 by series reversion in d = -g/f: with b2 = f1/2f, b3 =
** f2/6f and b4 = f3/24f, e = d - b2 d^2 + (2 b2^2 - b3) d^3 + (5 b2 b3 -
** 5 b2^3 - b4) d^4 (inv = 1/f). */
static double reversion_tail(double d, double inv, double f1, double f2,
                             double f3) {
  double b2 = f1 * inv * 0.5, b3 = f2 * inv * (1.0 / 6), b4 = f3 * inv * (1.0 / 24);
  return d * d * (-b2 + d * (2 * b2 * b2 - b3 + d * (5 * b2 * (b3 - b2 * b2) - b4)));
}

/* The step to the root of the Taylor polynomial of second order, from the
** Newton step d = -g/f and the slope f1 of the speed: e = d - c with c =
** f1 d^2 / (2 f) makes g + f e + f1 e^2 / 2 = (f1 / 2) c (c - 2 d), and
** the remainder is at most max |f''| |e|^3 / 6 with |f''| <= 2 m / r^2
** (cauchy).  Returns e when the two are within tol (1/1024 of it kept for
** rounding), else 0 (e = 0 means g = 0, which the caller has taken
** already). */
static double second_order_step(const cauchy *cb, double d, double inv,
                                double f1, double tol) {
  double r = cb->r, c = f1 * d * d * inv * 0.5, e = d - c;
  double res = fabs(f1 / 2 * c * (c - 2 * d)) +
               cb->m * fabs(e * e * e) / (3 * r * r);
  return cb->ok && fabs(e) <= cb->D && res <= tol * (1 - 1.0 / 1024) ? e : 0;
}

/* The reversion step e = d + reversion_tail (the root of the Taylor
** polynomial of fourth order, to its own fourth order) when it is within
** tol: with g = -f d the polynomial's value there is f (e - d) + e^2 (f1/2
** + e (f2/6 + e f3/24)), and the remainder is at most max |f''''| |e|^5 /
** 120 with |f''''| <= 24 m / r^4 (cauchy).  A sweep's chained guess errs
** by ~1e-5 of the piece, whose Newton step this certifies where the
** second-order one does not; 0 when not within tol. */
static double reversion_step(const cauchy *cb, double d, double f,
                               double inv, double f1, double f2, double f3,
                               double tol) {
  double r = cb->r, tail = reversion_tail(d, inv, f1, f2, f3);
  double e = d + tail, e2 = e * e;
  double res = fabs(f * tail + e2 * (f1 / 2 + e * (f2 / 6 + e * f3 / 24))) +
               cb->m * (e2 * e2 * fabs(e)) / (5 * (r * r) * (r * r));
  return cb->ok && fabs(e) <= cb->D && res <= tol * (1 - 1.0 / 1024) ? e : 0;
}

/* A first guess for s(t) = goal in [a, b]: the cubic Hermite interpolant
** of s from its values 0, plen and slopes fa, fb (the speeds) at the ends,
** inverted by two Newton steps on u = (t - a)/(b - a) kept in (0, 1).
** Two, not more: each is a division on the path to the answer, and the
** refined guess's reversion step takes it much closer for the cost of one
** (doc/benchmarks.md: the steps tried). */
#define HERMITE_STEPS 2
static double hermite_guess(double a, double b, double fa, double fb,
                            double plen, double goal) {
  double w = b - a;
  double u = arclen_hermite_invert(plen, fa * w, fb * w, goal, goal / plen,
                                   HERMITE_STEPS);
  return a + w * u;
}

/* The piece's Bernstein ellipse holds a disc of radius r = a_semi - 1 =
** e / (sqrt(1 + e) + 1) (times half_width) about every point of the
** piece, where |f| <= M. */
static double disc_radius(const piece_bound *pbound, double half_width) {
  return half_width * pbound->e / (sqrt(1 + pbound->e) + 1);
}

/* The order for [c - h, c + h] from its own distance to the branch
** points: no branch point lies within dist of the segment (dist, a lower
** bound of the nearest one's distance, the larger of its offsets along and
** across), so the Bernstein ellipse of semi-minor axis b = 0.9 dist, which
** lies within b of the segment, holds none; every point within b of the
** segment is within h + b of c, so |f| <= M = sqrt(lead2) prod (|c - re_k|
** + im_k + h + b) over the pairs (as arclen_bound_piece); rho = (A + b)/h
** with A = sqrt(h^2 + b^2) and rho^2 - 1 = 2 b (A + b)/h^2.  The ellipse
** bound (integrator.h's head) then sets the order, a few operations where
** the piece's ellipse sees only the branch point nearest to the piece: a
** tenth of a piece away from it takes a third of the points.  The order
** holds for every sub-range too (the same b: its ellipse lies within b of
** it, so within the region of M, and its rho is larger), so it may be
** taken before the sub-range is known.  0 when no order up to the tables'
** does (a real root inside, or too near). */
static int stadium_order(const integrator *in, double c, double h,
                         double target) {
  const arclen_branch *br = &in->br;
  double dist = 32 * h, prod, b, A, lr, nn;
  int k;
  for (k = 0; k < br->n; k += 2) {
    double dx = fabs(br->re[k] - c) - h, dk = dx > br->im[k] ? dx : br->im[k];
    dist = dk < dist ? dk : dist;
  }
  if (!(dist > 0)) return 0;
  b = 0.9 * dist;
  A = sqrt(h * h + b * b);
  /* h (64/15) M / (target (rho^2 - 1)) but for sqrt(lead2), whose log2
  ** lead_log bounds from above (it carries the factor 4/pi > 1 too) */
  prod = h * h * h * (64.0 / 15.0) / (target * 2 * b * (A + b));
  for (k = 0; k < br->n; k += 2) prod *= fabs(br->re[k] - c) + br->im[k] + h + b;
  lr = arclen_rough_log2((A + b) / h) - ARCLEN_LOG2_ERR;
  if (!(prod > 0 && prod < 1e300 && lr > 0)) return 0;   /* the other bounds */
  nn = 1 + (arclen_rough_log2(prod) + in->lead_log + ARCLEN_LOG2_ERR) / (2 * lr);
  return nn <= 2 ? 2 : nn < ARCLEN_GAUSS_MAX ? (int)ceil(nn) : 0;
}

/* The order for a window [c - h, c + h] taken ahead (solve_goal), from
** the Bernstein ellipse E through its nearest branch point, where f is
** analytic: Trefethen's bound (integrator.h's head) h (64/15) M rho^(2 -
** 2n) / (rho^2 - 1) with |f| <= M on E.  It holds for every sub-range too:
** the ellipse of the same rho about a sub-range lies inside E (the
** Green's function of a subset is the larger), and the bound falls with
** the half-width.  Where a branch point stands off an end of the window,
** or low over it, E is much wider than stadium_order's stadium (rho - 1 ~
** sqrt(2 d/h) against d/h at a distance d): at L/2 on `make bench`'s
** curves it asks 32 points on average where the stadium asks 49 on the
** same windows, and finds none on 2.4% of them, not 21%
** (doc/benchmarks.md).
**
** In the window's units the branch point z has a - 1 = (|z - 1| + |z + 1|
** - 2)/2 (E's semi-major axis a, rounded down as in bound.c), and the
** ellipse table gives log2(rho^2) from below and its inverse from above;
** rho^2 / (rho^2 - 1) = rho / (2 b) <= a / b with b^2 = (a - 1)(a + 1);
** every point of E lies within h a of c, so M = sqrt(lead2) prod (|c -
** re_k| + im_k + h a) over the pairs (as arclen_bound_piece).  One
** division and two square roots a pair, where arclen_bound_piece and
** its order took eleven such operations (doc/benchmarks.md).  0 where
** there is no such order (a real root inside the window, a - 1 off the
** table, or more than the tables' points): then stadium_order's. */
static int window_order(const integrator *in, double c, double h,
                        double target) {
  const arclen_branch *br = &in->br;
  const arclen_ellipse_cell *cell;
  double inv = 1 / h, am1 = HUGE_VAL, s12 = 0, prod, dx, x, nn, ah;
  int k;
  for (k = 0; k < br->n; k += 2) {   /* the upper roots of the pairs */
    double dr = br->re[k] - c, im = br->im[k];
    if (im > 0) {
      double sk, ak = arclen_ellipse_am1(dr * inv, im * inv, &sk);
      if (ak < am1) {
        am1 = ak;
        s12 = sk;
      }
    } else if (fabs(dr) < h * (1 - 1e-12)) {
      return 0;                        /* a kink inside: no bound sees it */
    }
  }
  cell = arclen_ellipse_cell_of(am1, &dx);   /* none: no upper root, or off */
  if (!cell) return 0;
  ah = h * s12 * (0.5 + 0x1p-50);      /* h a, rounded up */
  prod = h * (64.0 / 15.0) * (s12 * (0.5 + 0x1p-50));
  for (k = 0; k < br->n; k += 2) prod *= fabs(br->re[k] - c) + br->im[k] + ah;
  x = arclen_rough_log2(prod) - arclen_rough_log2(target) + in->lead_log -
      0.5 * arclen_rough_log2(am1 * (am1 + 2)) + 3 * ARCLEN_LOG2_ERR;
  if (!(prod > 0 && prod < 1e300)) return 0;
  nn = x * (cell->ilam + dx * cell->dilam);     /* >= x / log2(rho^2) */
  return x <= 0 ? 2 : nn < ARCLEN_GAUSS_MAX ? (nn <= 2 ? 2 : (int)ceil(nn)) : 0;
}

/* The order for [x, y] inside the piece [pa, pb] to within target
** (scaled units) from [x, y]'s own distance to the branch points
** (stadium_order); where that fails (a root too near), the piece's
** Bernstein ellipse (ebound, half-width hp) holds the disc of radius r =
** hp (a_semi - 1) about every point of the piece (disc_radius), so a
** short [x, y] of half-width h has the ellipse of semi-minor axis r inside
** it, rho = r/h + sqrt(1 + (r/h)^2), with |f| <= M there: the ellipse
** bound (integrator.h's head) at that rho sets its order, for a few
** operations.  A longer one takes its own branch-cut bound.  0: no order
** up to the tables' is to be had. */
static int sub_order(integrator *in, double x, double y, double target,
                     double pa, double pb) {
  double c = x + (y - x) / 2, h = (y - x) / 2, hp = (pb - pa) / 2, rad = 0;
  piece_bound eb, *ebound = &eb;
  int n = stadium_order(in, c, h, target);
  if (!n) {
    arclen_bound_piece(&in->br, pa + hp, hp, ebound);
    rad = disc_radius(ebound, hp);
  }
  if (!n && h < rad / 2) {
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
  return n;
}

/* The integral over [x, y] inside the piece [pa, pb] to within target:
** by the order n when given (window_order's or stadium_order's for a
** range that holds it), else sub_order's; where no order is to be had,
** the piece's rule r, or in an open piece (r NULL, no rule of its own)
** the two halves, each to half the target (a graded cut towards the
** root that defeats the bounds; the integrator's caps: MAXDEPTH levels,
** MAXSPLITS halvings, then its floor rule). */
static double sub_integral(integrator *in, double x, double y, double target,
                           double pa, double pb, const arclen_gauss_rule *r,
                           int n, int depth) {
  double c = x + (y - x) / 2, h = (y - x) / 2;
  if (!(h > 0)) return 0;
  if (!n) n = sub_order(in, x, y, target, pa, pb);
  if (n) {
    r = arclen_rule_at_least(n);
  } else if (!r) {
    if (depth < MAXDEPTH && in->splits < MAXSPLITS) {
      in->splits++;
      return sub_integral(in, x, c, target / 2, pa, pb, NULL, 0, depth + 1) +
             sub_integral(in, c, y, target / 2, pa, pb, NULL, 0, depth + 1);
    }
    r = arclen_rule_at_least(FLOOR_ORDER);
  }
  in->evals += r->n;
  return arclen_apply_rule(&in->h, r, c, h);
}


/* s + e = a + b exactly (Knuth's TwoSum): a piece's s values are carried
** from point to point, and the chain of many distances would otherwise
** add a rounding per step. */
static void two_sum(double a, double b, double *s, double *e) {
  double x = a + b, bv = x - a, av = x - bv;
  *s = x;
  *e = (a - av) + (b - bv);
}

/* A point of the search whose s is known: s(t) - s(a) = s + sc (a
** compensated pair), the speed f there (< 0: not taken yet) and inv = 1/f,
** and, when slopes, its derivatives f1, f2, f3. */
typedef struct known {
  double t, s, sc, f, inv, f1, f2, f3;
  int slopes;
} known;

/* The search inside an accepted piece [a, b] of length plen with rule r:
** the bracket of the sweep, lo (s <= the goal) and hi (s above it, or the
** piece's end), sqrt(lead2) for cauchy_near, and an order taken ahead
** (eval_at, solve_goal) with the range and share it holds for.  An open
** piece has not taken its length (plen = HUGE_VAL: the chord showed that
** it holds every distance left, sweep()); its end's s is then unknown,
** each s is taken from lo, and the Hermite guess takes a rough length
** rough. */
typedef struct piece_search {
  double a, b, plen, rough, sqlead;
  const arclen_gauss_rule *r;
  known lo, hi;
  double pre_x, pre_y, pre_share;  /* an order pre_n that holds there */
  int pre_n;
} piece_search;

/* Whether hi is an open piece's end, whose s is not taken. */
static int hi_open(const piece_search *p) {
  return p->hi.s == HUGE_VAL;
}

static void set_known(known *k, double t, double s) {
  k->t = t;
  k->s = s;
  k->sc = 0;
  k->f = -1;
  k->slopes = 0;
}

static double speed_of(integrator *in, known *k) {
  if (k->f < 0) {
    k->f = arclen_hodo_speed(&in->h, k->t);
    k->inv = 1 / k->f;
    in->evals++;
  }
  return k->f;
}

/* An open piece's rough length is Simpson's rule, from the speeds at its
** ends (the Hermite guess takes them anyway) and one more in the middle:
** the Hermite cubic on [a, b] is then the integral of the quadratic
** through the three speeds.  Its inverse errs by 1.7% of the piece at the
** median at L/2 (1.5% with a 4-point rule's length, which put four square
** roots on the guess's chain where this puts one), and the refined guess
** by 1.2e-8 (1.1e-8; doc/benchmarks.md). */
static void search_piece(integrator *in, piece_search *p, double a, double b,
                         double plen, const arclen_gauss_rule *r) {
  p->a = a;
  p->b = b;
  p->plen = plen;
  p->rough = plen;
  p->r = r;
  p->sqlead = sqrt(in->br.lead2);
  p->pre_n = 0;
  set_known(&p->lo, a, 0);
  set_known(&p->hi, b, plen);
  if (plen == HUGE_VAL) {
    double mid = arclen_hodo_speed(&in->h, a + (b - a) / 2);
    p->rough = (b - a) / 6 * (speed_of(in, &p->lo) + 4 * mid +
                              speed_of(in, &p->hi));
    in->evals++;
  }
}

static void slopes_of(integrator *in, known *k) {
  if (!k->slopes && k->f > 0) {
    speed_slopes(&in->h, k->t, k->inv, &k->f1, &k->f2, &k->f3);
    k->slopes = 1;
  }
}

/* How far ahead a forward range's order is taken (eval_at), in ranges. */
#define WINDOW 4

/* s at t inside the bracket: from the nearer end whose s is known, plus
** the integral between to within share (sub_integral; near the answer it
** is short and needs few points), and the speed there.  A forward range's
** order is kept for WINDOW times its length (stadium_order's holds for
** every sub-range), which a sweep's next ranges from a higher lo lie in. */

static void eval_at(integrator *in, piece_search *p, double t,
                    double share, known *k) {
  double e, x = p->lo.t, y = t, sign = 1;
  int n;
  if (t - p->lo.t > p->hi.t - t && !hi_open(p)) {
    x = t;
    y = p->hi.t;
    sign = -1;
  }
  if (p->pre_n && share == p->pre_share && x >= p->pre_x && y <= p->pre_y) {
    n = p->pre_n;
  } else if (sign > 0) {
    p->pre_x = x;
    p->pre_y = fmin(x + WINDOW * (y - x), p->hi.t);
    p->pre_share = share;
    n = p->pre_n = stadium_order(in, p->pre_x + (p->pre_y - p->pre_x) / 2,
                                 (p->pre_y - p->pre_x) / 2, share);
  } else {
    n = 0;
  }
  two_sum(sign < 0 ? p->hi.s : p->lo.s,
          sign * sub_integral(in, x, y, share, p->a, p->b, p->r, n, 0), &k->s, &e);
  k->sc = (sign < 0 ? p->hi.sc : p->lo.sc) + e;
  k->t = t;
  k->f = -1;
  k->slopes = 0;
  speed_of(in, k);
}

/* At the refined guess, Cauchy's estimates are taken before the integral
** there, for a reach of this share of the bracket (the guess errs by
** 1.2e-8 of the piece at the median): off the integral's chain, they
** certify a short Newton step as soon as it is known; the estimates for
** the step itself (reach 2 |d|) are taken only where these do not.  A
** sweep's chained guesses, ~1e-5 off, would seldom use them. */
#define AHEAD_STEP 0x1p-16

/* Safeguarded Newton for s(t) = goal from the guess t inside the bracket:
** s is increasing, so the bracket always holds the answer, and a step
** leaving it is replaced by bisection.  The k-th integral may err by share
** 2^-k, so the s values known err by less than 2 share more than the
** bracket's did.  A step longer than half the step before is replaced by
** bisection too (arclen_step_ok: a cusp-like 3D curve took 100 steps of
** ~1e-4 and stopped a quarter of L short, fuzz_time).  The bracket is
** left holding the last points evaluated, for the next distance.
** refined: t is the refined guess. */
static double newton_search(integrator *in, piece_search *p, double t,
                            double goal, double tol, double share,
                            int refined) {
  int it;
  double last_step = HUGE_VAL;
  if (!(t > p->lo.t && t < p->hi.t))   /* a guess from outside: the middle */
    t = p->lo.t + (p->hi.t - p->lo.t) / 2;
  for (it = 0; it < 100; it++) {
    known k, *kp;
    cauchy ahead;
    double g, next, d, e, e3, lo, hi, reach = -1;
    ahead.ok = 0;
    if (it == 0 && refined) {
      reach = (p->hi.t - p->lo.t) * AHEAD_STEP;
      cauchy_near(&in->br, p->sqlead, t, reach, &ahead);
    }
    eval_at(in, p, t, share, &k);
    share /= 2;
    g = (k.s - goal) + k.sc;
    if (g <= 0) {
      p->lo = k;
      kp = &p->lo;
    } else {
      p->hi = k;
      kp = &p->hi;
    }
    if (fabs(g) <= tol) return t;
    lo = p->lo.t;
    hi = p->hi.t;
    next = lo + (hi - lo) / 2;
    if (kp->f > 0) {
      d = -g * kp->inv;
      if (t + d > lo && t + d < hi) {
        cauchy cb;
        /* the estimates for a wider reach are the weaker (dist and r fall,
        ** m grows with D), so these certify only what the step's own
        ** would (up to rounding): the same answer */
        if (2 * fabs(d) <= reach && newton_certified(&ahead, d, tol))
          return t + d;
        cauchy_near(&in->br, p->sqlead, t, 2 * fabs(d), &cb);
        if (newton_certified(&cb, d, tol)) return t + d;
        slopes_of(in, kp);
        e = second_order_step(&cb, d, kp->inv, kp->f1, tol);
        if (e != 0 && t + e > lo && t + e < hi) return t + e;
        e3 = reversion_step(&cb, d, kp->f, kp->inv, kp->f1, kp->f2, kp->f3, tol);
        if (e3 != 0 && t + e3 > lo && t + e3 < hi) return t + e3;
        /* not certified: the next point from the reversion step (series
        ** reversion), nearer than Newton's for the same slopes */
        e3 = d + reversion_tail(d, kp->inv, kp->f1, kp->f2, kp->f3);
        next = t + e3 > lo && t + e3 < hi ? t + e3 : t + d;
      }
    }
    if (!arclen_step_ok(next, t, lo, hi, last_step))
      next = lo + (hi - lo) / 2;
    if (next == t || hi - lo <= 4e-16 * fmax(fabs(hi), 1e-300)) return t;
    last_step = fabs(next - t);
    t = next;
  }
  return t;
}

/* An open piece has no order of its own: the refined guess takes this
** many points, not a share of the first certified integral's order, which
** would put that order's bound on the guess's chain (doc/benchmarks.md:
** 4 to 16 points tried). */
#define OPEN_REFINE_ORDER 8

/* The refined guess's order: a third of the piece's, for about a third
** of its digits (the certificates then need the guess within ~1e-5 of the
** piece; fewer points left more searches a second certified integral);
** short rules whole, which keeps a straight piece's times exact. */
static int refine_order(int n) {
  return n < 6 ? n : (n + 1) / 3;
}

/* A better guess, no bound: s(t) from a rule of refine_order on the
** nearer part of the bracket, then the reversion step from it (series
** reversion).  The Hermite guess errs by up to ~1e-2 of the piece where a
** branch point stands near it; this step takes it within reach of the
** certificates for a rule without its bound. */
static double refine_guess(integrator *in, const piece_search *p, double t,
                           double goal) {
  double sg, f, lo = p->lo.t, hi = p->hi.t;
  const arclen_gauss_rule *r =
      arclen_rule_at_least(p->r ? refine_order(p->r->n) : OPEN_REFINE_ORDER);
  if (t - lo <= hi - t || hi_open(p))
    sg = (p->lo.s - goal) + p->lo.sc +
         arclen_apply_rule(&in->h, r, lo + (t - lo) / 2, (t - lo) / 2);
  else
    sg = (p->hi.s - goal) + p->hi.sc -
         arclen_apply_rule(&in->h, r, t + (hi - t) / 2, (hi - t) / 2);
  f = arclen_hodo_speed(&in->h, t);
  in->evals += r->n + 1;
  if (f > 0) {
    double inv = 1 / f, d = -sg * inv, f1, f2, f3, e;
    speed_slopes(&in->h, t, inv, &f1, &f2, &f3);
    e = d + reversion_tail(d, inv, f1, f2, f3);
    if (t + e > lo && t + e < hi) return t + e;
  }
  return t;
}

/* s(t) = goal in the piece (goal in [0, plen]): the bracket moved up
** past a goal beyond hi, then
** the guess -- the reversion step from lo once lo is inside the piece
** (a sweep's next distance: its speed and slopes are known), else the
** Hermite guess on the bracket -- and the Newton search from it. */
/* The reversion step from lo is a sweep's next distance's guess, and a
** piece's first distance's when its Newton step from the piece's start is
** within this share of the piece; a longer one takes the Hermite guess. */
#define REVERSION_REACH 8

/* An open piece's first certified integral reaches this share of the
** piece past the length's fraction (doc/benchmarks.md: 1/16 to the whole
** piece tried; 1/4 with stadium_order's windows, 3/8 with window_order's). */
#define OPEN_WINDOW 0.375

static double solve_goal(integrator *in, piece_search *p, double goal,
                         double tol, double share) {
  double t = -1;
  int refined = 0;
  if (goal >= p->hi.s + p->hi.sc && p->hi.t < p->b) {
    p->lo = p->hi;                     /* the last search ended above */
    set_known(&p->hi, p->b, p->plen);
  }
  if (goal >= p->plen) return p->b;    /* on the last piece: s >= L */
  if (speed_of(in, &p->lo) > 0) {
    known *lo = &p->lo;
    double d = (goal - lo->s - lo->sc) * lo->inv;
    if (lo->t > p->a || d < (p->hi.t - lo->t) / REVERSION_REACH) {
      slopes_of(in, lo);
      t = lo->t + d + reversion_tail(d, lo->inv, lo->f1, lo->f2, lo->f3);
    }
  }
  if (!(t > p->lo.t && t < p->hi.t)) {
    double lo = p->lo.t, hi = p->hi.t, gap = goal - p->lo.s - p->lo.sc;
    int open = hi_open(p);
    double ds = open ? p->rough - p->lo.s - p->lo.sc
                     : p->hi.s - p->lo.s + (p->hi.sc - p->lo.sc);
    if (open && !(ds > gap)) ds = gap * (1 + 1.0 / 16);  /* rough fell short */
    t = hermite_guess(lo, hi, speed_of(in, &p->lo), speed_of(in, &p->hi), ds,
                      gap);
    /* the first certified integral's order (window_order), taken beside
    ** the refined guess, not after it: for the bracket's part from its
    ** nearer end to a 32nd of it past the guess (the refined guess moves
    ** it by less nine times in ten; else eval_at takes its own); in an
    ** open piece from lo to OPEN_WINDOW of the bracket past the length's
    ** fraction, known before the Hermite guess, whose chain it then runs
    ** beside */
    if (open) {
      double u = gap / ds;
      p->pre_x = lo;
      p->pre_y = fmin(lo + (hi - lo) * (u + OPEN_WINDOW), hi);
    } else if (t - lo <= hi - t) {
      p->pre_x = lo;
      p->pre_y = fmin(t + (hi - lo) / 32, hi);
    } else {
      p->pre_x = fmax(t - (hi - lo) / 32, lo);
      p->pre_y = hi;
    }
    p->pre_share = share;
    p->pre_n = window_order(in, p->pre_x + (p->pre_y - p->pre_x) / 2,
                            (p->pre_y - p->pre_x) / 2, share);
    if (!p->pre_n)
      p->pre_n = stadium_order(in, p->pre_x + (p->pre_y - p->pre_x) / 2,
                               (p->pre_y - p->pre_x) / 2, share);
    t = refine_guess(in, p, t, goal);
    refined = 1;
  }
  return newton_search(in, p, t, goal, tol, share, refined);
}

/* time cuts at the feet within 0.2 of the width, more than the length
** does: a piece where the speed dips sharply defeats the Hermite guess
** (off by up to half the piece), and each further Newton step is a chain
** of a bound, a rule and a division (doc/benchmarks.md: the shares tried). */
#define TIME_FOOTCUT 0.2

/* The pieces of the integral in increasing t: each first piece (between
** the feet) by the order of its own Bernstein ellipse (window_order: a
** few square roots, where the branch-cut bound's order is a long chain of
** tables, logs and sums that a goal in the next piece waits for; it asks
** about a third more points, doc/benchmarks.md), up to WALK_ELLIPSE_MAX points;
** else by the branch-cut bound's order straight from the branch points
** when no report is asked (their chains taken side by side, as the length
** takes them), else by the integrator's stack for that piece alone, whose
** parts and rules are the same where that order is to be had
** (spec/fastpath_spec.lua), so that the answer does not depend on which
** path gave them.  Only the pieces that the chords show to hold the last
** distance take their orders at the start (a chord is shorter than its
** arc); the rest are taken when reached. */
typedef struct piece_walk {
  int fast, k, have;
  double c[ARCLEN_CUT_PIECES], half_width[ARCLEN_CUT_PIECES];
  int n[ARCLEN_CUT_PIECES];            /* 0: the stack's */
} piece_walk;

/* The most points a first piece takes from its ellipse; past it the
** branch-cut bound's order, which is tighter (doc/benchmarks.md: 32 lost
** on the curves of two pieces, 64 to 128 read the same). */
#define WALK_ELLIPSE_MAX 64

/* The first pieces whose chords reach past the distance s (scaled): the
** pieces that certainly hold it, and all before (every one when the
** chords fall short). */
static int pieces_reaching(const integrator *in, double s) {
  double sum = 0;
  int i;
  for (i = 0; i < in->nmin; i++) {
    sum += in->chords[i];
    if (arclen_chord_holds(sum, s)) return i + 1;
  }
  return in->nmin + 1;
}

/* First piece i's share of the truncation budget (scaled units), as the
** integrator's bounds take it: rtol len_lower times its share of the
** width. */
static double piece_target(const integrator *in, double half_width) {
  return in->rtol * in->len_lower * (2 * half_width / in->width);
}

/* The orders of first pieces i0 <= i < i1: their ellipses' (their chains
** side by side), then on the fast path the branch-cut bound's for those
** whose ellipse gives none; 0 where the stack is to take the piece. */
static void walk_orders(integrator *in, piece_walk *w, int i0, int i1) {
  int i, all = 1;
  for (i = i0; i < i1; i++) {
    int n = window_order(in, w->c[i], w->half_width[i],
                         piece_target(in, w->half_width[i]));
    w->n[i] = n <= WALK_ELLIPSE_MAX ? n : 0;
    all = all && w->n[i];
  }
  if (all || !w->fast) return;
  for (i = i0; i < i1; i++)            /* 0 where the cut order fails too */
    if (!w->n[i]) arclen_integ_orders_of(in, i, i + 1, w->c, w->half_width, w->n);
}

static void walk_start(integrator *in, piece_walk *w, double s_last) {
  w->k = 0;
  w->fast = !in->want_err;
  arclen_integ_first_pieces(in, w->c, w->half_width);
  /* not the last: it may be open, and then needs no order */
  w->have = pieces_reaching(in, s_last) - 1;
  walk_orders(in, w, 0, w->have);
}

/* The next piece [*a, *b] with its rule and length *len; a piece whose
** chord shows that it holds the distance open_below from its start
** (scaled) is open, before its order or any cut (*len = HUGE_VAL, *r =
** NULL): the sweep then needs neither its length nor its rule nor the
** pieces after it.  The same rule on both paths. */
static int walk_next(integrator *in, piece_walk *w, double open_below,
                     double *a, double *b, double *len,
                     const arclen_gauss_rule **r, int *last) {
  int k;
  if (in->top > 0 && arclen_integ_next_piece(in, open_below, a, b, len, r)) {
    *last = in->top == 0 && w->k > in->nmin;   /* a part of piece k - 1 */
    return 1;
  }
  if ((k = w->k) > in->nmin) return 0;
  *a = arclen_first_from(in, k);
  *b = arclen_first_to(in, k);
  *last = k == in->nmin;
  w->k++;
  if (arclen_chord_holds(in->chords[k], open_below)) {
    *r = NULL;
    *len = HUGE_VAL;
    return 1;
  }
  if (k >= w->have) {                  /* its order, and the rest's */
    w->have = in->nmin + 1;
    walk_orders(in, w, k, w->have);
  }
  if (!w->n[k]) {                      /* the stack cuts and pops it */
    arclen_integ_prepare_bounds(in);
    arclen_integ_push_one(in, k);
    if (!arclen_integ_next_piece(in, open_below, a, b, len, r)) return 0;
    *last = in->top == 0 && k == in->nmin;
    return 1;
  }
  *r = arclen_rule_at_least(w->n[k]);
  *len = arclen_apply_rule(&in->h, *r, w->c[k], w->half_width[k]);
  if (in->want_err)                    /* the bound at n is below it */
    in->err += piece_target(in, w->half_width[k]);
  in->evals += (*r)->n;
  in->pieces++;
  return 1;
}

/* The distances s[i..] (scaled by 2^-exp) that the piece of length plen
** starting at cum holds: s <= cum + plen, and every one on the last. */
static long goals_in_piece(const double *s, long i, long n, int exp,
                           double cum, double plen, int last) {
  long j = i;
  while (j < n && (last || arclen_times_pow2(s[j], exp) <= cum + plen)) j++;
  return j - i;
}

/* The sweep: t[i] for the ascending s[i] > 0 (i < n; t preset to 1), the
** pieces in increasing t, each holding a run of distances searched one
** after the other from where the last search ended.  The distances of a
** piece share its tolerance: each one's integrals err by tol / m in all (m
** distances in the piece), so that every s value known errs by less than
** tol, as one search's do; the compensated sums keep their rounding to
** one.  The Newton certificate takes tol on top. */
static void sweep(const double *c, int dim, const double *s, long n,
                  double rtol, double *t, arclen_info *info) {
  integrator in;
  piece_walk w;
  piece_search p;
  double cum = 0, tol, pa, pb, plen, s_last;
  const arclen_gauss_rule *r;
  long i = 0, m, q;
  int last = 0;
  if (!arclen_integ_start(&in, c, dim, 0, 1, rtol * 0.25, TIME_FOOTCUT)) {
    if (info) arclen_integ_fill_info(info, &in, in.h.exp);
    return;                            /* a point: every s > 0 is past it */
  }
  in.want_err = info != NULL;
  s_last = arclen_times_pow2(s[n - 1], -in.h.exp);
  walk_start(&in, &w, s_last);
  tol = in.rtol * in.len_lower;
  while (i < n && !last) {
    if (!walk_next(&in, &w, s_last - cum, &pa, &pb, &plen, &r, &last))
      break;
    if (plen == HUGE_VAL) {            /* every distance left lies here */
      m = n - i;
      last = 1;
    } else {
      m = goals_in_piece(s, i, n, -in.h.exp, cum, plen, last);
    }
    if (m > 0) {
      double share = tol / (double)m / 2;
      search_piece(&in, &p, pa, pb, plen, r);
      for (q = 0; q < m; q++, i++) {
        if (q > 0 && s[i] == s[i - 1])
          t[i] = t[i - 1];
        else
          t[i] = solve_goal(&in, &p, arclen_times_pow2(s[i], -in.h.exp) - cum,
                            tol, share);
      }
    }
    cum += plen;
  }
  arclen_integ_fill_info(info, &in, in.h.exp);
}

int arclen_time_gauss(const double *c, int dim, double s,
                      const arclen_opts *o, double *t, arclen_info *info) {
  int e = arclen_integ_check_args(c, dim, o->rtol, 0, 1);   /* time ignores o->t0, t1 */
  *t = NAN;
  if (info) arclen_info_init(info);
  if (e) return e;
  if (isnan(s)) return ARCLEN_EINVAL;
  if (s <= 0) { *t = 0; return ARCLEN_OK; }
  *t = 1;
  sweep(c, dim, &s, 1, o->rtol, t, info);
  return ARCLEN_OK;
}

int arclen_times(const double *c, int dim, const double *s, long n,
                 double rtol, double *t, double *pts, double *tan) {
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
  if (i < n) sweep(c, dim, s + i, n - i, rtol, t + i, NULL);
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
