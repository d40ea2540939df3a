/*
** quadrature.c -- the default length method ("gauss"): Gauss-Legendre on
** pieces whose order is chosen from an a priori error bound.
**
** The speed f = sqrt(Q) is analytic inside the Bernstein ellipse E_rho of a
** piece that reaches up to the nearest branch point (branch.c).  For such f,
** |f| <= M on E_rho, the n-point rule errs by at most
**     (64/15) M rho^(2-2n) / (rho^2 - 1)      on [-1, 1]
** (Trefethen, "Approximation Theory and Approximation Practice", Thm 19.3,
** whose I_n has n+1 points; it follows from |a_k| <= 2 M rho^-k, Thm 8.1).
** The bound cannot be fooled by two rules agreeing by accident: it is read
** off the geometry.  [t0, t1] is cut at the feet of the branch points
** (where near-cusps put the speed's minima), then pieces are bisected while
** no order up to NMAX meets their share of the tolerance.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "arclen.h"
#include "cubic.h"
#include "gauss_tables.h"

#define NMAX 48          /* highest order used before bisecting instead */
#define MAXDEPTH 60      /* bisection levels below a critical piece */
#define MAXSTACK (4 + 2 * MAXDEPTH)  /* pending pieces: depth-first search */
#define RHO_CAP 64.0     /* a larger ellipse only inflates M */
/* Cap on bisections per integration: the depth cap alone allows 2^60
** pieces when every piece fails; 10^5 is far above what rtol 1e-15 needs
** on the hardest reference curve (found by fuzz/fuzz_length). */
#define MAXSPLITS 100000L

/* The rule with n points, or the smallest one with more. */
static const arclen_gauss_rule *rule_at_least(int n) {
  const arclen_gauss_rule *r = arclen_gauss_rules;
  while (r[1].n != 0 && r->n < n) r++;
  return r;
}

/* hh * sum w_i f(c + hh x_i): the rule on [c - hh, c + hh]. */
static double apply_rule(const arclen_hodo *h, const arclen_gauss_rule *r,
                         double c, double hh) {
  double s = 0;
  int i = 0;
  if (r->n % 2) {
    s = r->w[0] * arclen_hodo_speed(h, c);
    i = 1;
  }
  for (; i < r->half; i++)
    s += r->w[i] * (arclen_hodo_speed(h, c - hh * r->x[i]) +
                    arclen_hodo_speed(h, c + hh * r->x[i]));
  return hh * s;
}

/* log(x) within 3e-6, for choosing orders (the callers add a margin):
** log(m 2^e) = e log 2 + 2 atanh((m - 1)/(m + 1)), m in [1, 2), so the
** atanh series in z <= 1/3 converges fast.  The exponent and mantissa are
** read off the bits (IEEE 754 binary64); zero, subnormals, inf and NaN go
** to log(). */
static double rough_log(double x) {
  uint64_t u;
  double m, z, z2;
  int e;
  memcpy(&u, &x, sizeof u);
  e = (int)((u >> 52) & 0x7ff);
  if (e == 0 || e == 0x7ff || (u >> 63)) return log(x);
  u = (u & 0xfffffffffffffULL) | 0x3ff0000000000000ULL;
  memcpy(&m, &u, sizeof m);
  z = (m - 1) / (m + 1);
  z2 = z * z;
  return (e - 1023) * 0.69314718055994531 +
         2 * z * (1 + z2 * (1.0 / 3 + z2 * (1.0 / 5 + z2 * (1.0 / 7 + z2 / 9))));
}

/* rho of the Bernstein ellipse with foci c -+ hh through the point z:
** the semi-axis sum a + b = rho, with a = (|z - f1| + |z - f2|) / 2. */
static double ellipse_rho(double c, double hh, double re, double im) {
  double u = (re - c) / hh, v = im / hh, a;
  if (fabs(u) + v > 1e100) return HUGE_VAL;   /* squares would overflow */
  a = (sqrt((u - 1) * (u - 1) + v * v) + sqrt((u + 1) * (u + 1) + v * v)) / 2;
  return a + sqrt((a - 1) * (a + 1));
}

typedef struct piece_bound {
  double rho;         /* reach of analyticity, capped at RHO_CAP */
  double c;           /* hh * (64/15) M rho^2 / (rho^2 - 1) */
  int inside;         /* a real (double) root strictly inside: must split */
} piece_bound;

static void bound_piece(const arclen_branch *br, double c, double hh,
                        piece_bound *pb) {
  double rho = HUGE_VAL, m, alpha;
  int k;
  pb->inside = 0;
  for (k = 0; k < br->n; k += 2) {     /* roots come in conjugate pairs */
    if (br->im[k] == 0) {            /* no branch point, but a kink inside */
      if (fabs(br->re[k] - c) < hh * (1 - 1e-12)) pb->inside = 1;
    } else {
      double r = ellipse_rho(c, hh, br->re[k], br->im[k]);
      if (r < rho) rho = r;
    }
  }
  if (rho > RHO_CAP) rho = RHO_CAP;
  pb->rho = rho;
  /* M <= lead * prod sqrt(|c - r_k| + alpha), alpha the ellipse's
  ** semi-major axis in t units: every |z - r_k| on it is at most that;
  ** a conjugate pair contributes |c - r_k| + alpha. */
  alpha = hh * (rho + 1 / rho) / 2;
  m = br->lead;
  for (k = 0; k < br->n; k += 2)
    m *= sqrt((br->re[k] - c) * (br->re[k] - c) + br->im[k] * br->im[k]) + alpha;
  pb->c = hh * (64.0 / 15.0) * m * rho * rho / ((rho - 1) * (rho + 1));
}

/* The smallest order whose bound c rho^(-2n) is <= target, or NULL past
** NMAX.  The logs are rough (3e-6): n gets a margin of 1e-3 (a factor of
** 1.002 on the bound) and the bound of the chosen order is computed
** exactly. */
static const arclen_gauss_rule *choose_rule(const piece_bound *pb,
                                            double target) {
  const arclen_gauss_rule *r;
  /* A bound that underflowed to 0 (a piece of subnormal width next to a
  ** root) is met by any rule; bisecting it could never make it positive. */
  if (pb->c == 0 && target >= 0) return rule_at_least(2);
  if (!(pb->c > 0) || !(target > 0)) return NULL;
  if (pb->c <= target) {
    r = rule_at_least(2);
  } else {
    double n, rate = 2 * rough_log(pb->rho) - 1e-5;
    if (!(rate > 0)) return NULL;           /* rho ~ 1: no order will do */
    n = (rough_log(pb->c / target) + 1e-3) / rate;
    if (!(n <= NMAX)) return NULL;          /* also catches NaN */
    r = rule_at_least(n < 2 ? 2 : (int)ceil(n));
  }
  return r;
}

typedef struct span { double a, b; int depth; } span;

/* The state of one adaptive integration over [t0, t1] (t0 < t1). */
typedef struct integrator {
  arclen_hodo h;
  arclen_branch br;
  double rtol, lest, width;   /* tolerance, lower bound of L, t1 - t0 */
  double mins[2];             /* feet of near branch points in (t0, t1) */
  int nmin;
  span stack[MAXSTACK];
  int top;
  long evals, pieces, splits;
  int depth;
  double err;                 /* sum of accepted pieces' bounds */
  int want_err;               /* info requested: sum the bounds */
} integrator;

static void push(integrator *in, double a, double b, int depth) {
  if (in->top < MAXSTACK) {
    in->stack[in->top].a = a;
    in->stack[in->top].b = b;
    in->stack[in->top].depth = depth;
    in->top++;
  }
}

/* Set up: the cuts are the feet of the branch points near [t0, t1] (the
** real part of each conjugate pair, and each real root): as a branch point
** nears the axis the speed dips to a minimum (a near-cusp) right below it,
** so these are the speed's minima that matter -- the roots of Q'.Q'' that
** lie under no nearby branch point cost a piece and gain nothing.  L is
** bounded below by the sum of chords between cuts, so every piece's share
** of the tolerance is safe. */
static void start(integrator *in, const double *c, int dim, double t0,
                  double t1, double rtol) {
  int i, j;
  double prev;
  memset(in, 0, sizeof *in);
  arclen_hodo_scaled(c, dim, &in->h);
  arclen_branch_points(&in->h, &in->br);
  in->rtol = rtol;
  in->width = t1 - t0;
  for (i = 0; i < in->br.n; i += 2) {
    double foot = in->br.re[i];
    if (foot > t0 && foot < t1 && in->br.im[i] < 0.5 * in->width) {
      for (j = in->nmin; j > 0 && in->mins[j - 1] > foot; j--)
        in->mins[j] = in->mins[j - 1];     /* insertion: keep ascending */
      in->mins[j] = foot;
      in->nmin++;
    }
  }
  prev = t0;
  for (i = 0; i <= in->nmin; i++) {
    double next = i < in->nmin ? in->mins[i] : t1;
    in->lest += arclen_hodo_chord(&in->h, prev, next);
    prev = next;
  }
  /* Cut at every foot right away. */
  push(in, in->nmin ? in->mins[in->nmin - 1] : t0, t1, 0);
  for (i = in->nmin - 1; i >= 0; i--)
    push(in, i ? in->mins[i - 1] : t0, in->mins[i], 0);
}

/* Where to cut a piece: at a foot of a branch point inside it (the one
** nearest its middle), else in the middle. */
static double cut_point(const integrator *in, double a, double b) {
  double mid = a + (b - a) / 2, best = mid, dist = HUGE_VAL;
  double margin = 1e-3 * (b - a);
  int i;
  for (i = 0; i < in->nmin; i++) {
    double m = in->mins[i];
    if (m > a + margin && m < b - margin && fabs(m - mid) < dist) {
      best = m;
      dist = fabs(m - mid);
    }
  }
  return best;
}

/* The rule for [a, b] that meets its share of the tolerance, or NULL. */
static const arclen_gauss_rule *rule_for(const integrator *in, double a,
                                         double b, piece_bound *pb) {
  double share = in->rtol * in->lest * (b - a) / in->width;
  bound_piece(&in->br, a + (b - a) / 2, (b - a) / 2, pb);
  if (pb->inside) return NULL;
  return choose_rule(pb, share);
}

/* Pop the next piece (in increasing t) and integrate it.  A piece is cut
** (at a foot inside it, else in the middle) when no order up to NMAX meets
** its share of the tolerance.  Returns 0 when no piece is
** left; else the accepted piece [*from, *to] and its length. */
static int next_piece(integrator *in, double *from, double *to, double *len,
                      const arclen_gauss_rule **rule) {
  while (in->top > 0) {
    span s = in->stack[--in->top];
    double c = s.a + (s.b - s.a) / 2, hh = (s.b - s.a) / 2;
    double err = 0, cut = cut_point(in, s.a, s.b);
    piece_bound pb;
    const arclen_gauss_rule *r = rule_for(in, s.a, s.b, &pb);
    if (r == NULL && s.depth < MAXDEPTH && in->splits < MAXSPLITS &&
        cut > s.a && cut < s.b) {
      in->splits++;
      push(in, cut, s.b, s.depth + 1);
      push(in, s.a, cut, s.depth + 1);
      continue;
    }
    if (r == NULL) {          /* bisection floor: a piece of ~1e-18 width */
      r = rule_at_least(NMAX);
      err = 2 * hh * pb.c;    /* crude: width x a bound of f near the piece */
    } else if (in->want_err) {
      err = pb.c * pow(pb.rho, -2.0 * r->n);
    }
    *len = apply_rule(&in->h, r, c, hh);
    in->evals += r->n;
    in->pieces++;
    if (s.depth > in->depth) in->depth = s.depth;
    in->err += err;
    *from = s.a;
    *to = s.b;
    if (rule) *rule = r;
    return 1;
  }
  return 0;
}

static int check_args(const double *c, int dim, const arclen_opts *o) {
  int e = arclen_check_curve(c, dim);
  if (e) return e;
  if (!(o->rtol >= ARCLEN_RTOL_MIN && o->rtol <= ARCLEN_RTOL_MAX))
    return ARCLEN_ETOL;
  if (!(o->t0 >= 0 && o->t0 <= 1 && o->t1 >= 0 && o->t1 <= 1))
    return ARCLEN_ERANGE;
  return ARCLEN_OK;
}

static void fill_info(arclen_info *info, const integrator *in, int exp) {
  if (!info) return;
  info->evals = in->evals;
  info->pieces = in->pieces;
  info->depth = in->depth;
  info->err = ldexp(in->err, exp);
  info->branch = NULL;
  info->calls = 0;
}

int arclen_length_gauss(const double *c, int dim, const arclen_opts *o,
                        double *len, arclen_info *info) {
  integrator in;
  double a = o->t0, b = o->t1, sum = 0, pa, pb, piece;
  int e = check_args(c, dim, o);
  *len = NAN;
  if (info) arclen_info_init(info);
  if (e) return e;
  if (a == b) { *len = 0; return ARCLEN_OK; }
  if (a > b) { double t = a; a = b; b = t; }
  start(&in, c, dim, a, b, o->rtol * 0.5);  /* half for rounding */
  in.want_err = info != NULL;
  if (!in.h.zero && in.lest > 0) {
    while (next_piece(&in, &pa, &pb, &piece, NULL)) sum += piece;
  } else if (!in.h.zero) {
    /* Zero chords between every pair of cuts but a moving point: the
    ** curve returns to where it was; bound L below by a coarse rule. */
    in.lest = 0.5 * apply_rule(&in.h, rule_at_least(8), 0.5, 0.5) * in.width;
    if (in.lest > 0)
      while (next_piece(&in, &pa, &pb, &piece, NULL)) sum += piece;
  }
  *len = ldexp(o->t0 > o->t1 ? -sum : sum, in.h.exp);
  fill_info(info, &in, in.h.exp);
  return ARCLEN_OK;
}

/* Safeguarded Newton for s(t) = goal inside an accepted piece [a, b] whose
** length is plen (goal in [0, plen]): s(t) is increasing, so [lo, hi]
** always brackets the answer, and a step leaving it is replaced by
** bisection.  Each s(t) is the piece's rule on [a, t] (a sub-interval keeps
** the piece's branch-point distance or better). */
static double solve_in_piece(integrator *in, double a, double b, double plen,
                             double goal, double tol,
                             const arclen_gauss_rule *r) {
  double lo = a, hi = b, t = a + (b - a) * (goal / plen);
  int it;
  for (it = 0; it < 100; it++) {
    double g = apply_rule(&in->h, r, a + (t - a) / 2, (t - a) / 2) - goal;
    double f = arclen_hodo_speed(&in->h, t), next;
    in->evals += r->n + 1;
    if (fabs(g) <= tol) break;
    if (g < 0) lo = t; else hi = t;
    next = f > 0 ? t - g / f : lo + (hi - lo) / 2;
    if (!(next > lo && next < hi)) next = lo + (hi - lo) / 2;
    if (next == t || hi - lo <= 4e-16 * fmax(fabs(hi), 1e-300)) break;
    t = next;
  }
  return t;
}

int arclen_time_gauss(const double *c, int dim, double s,
                      const arclen_opts *o, double *t, arclen_info *info) {
  integrator in;
  arclen_opts full = *o;
  double cum = 0, pa, pb, piece, goal;
  const arclen_gauss_rule *r;
  int e;
  full.t0 = 0;
  full.t1 = 1;
  e = check_args(c, dim, &full);
  *t = NAN;
  if (info) arclen_info_init(info);
  if (e) return e;
  if (isnan(s)) return ARCLEN_EINVAL;
  if (s <= 0) { *t = 0; return ARCLEN_OK; }
  start(&in, c, dim, 0, 1, o->rtol * 0.25);
  in.want_err = info != NULL;
  if (in.h.zero) { *t = 1; return ARCLEN_OK; }
  if (!(in.lest > 0))
    in.lest = 0.5 * apply_rule(&in.h, rule_at_least(8), 0.5, 0.5);
  goal = ldexp(s, -in.h.exp);
  *t = 1;
  while (next_piece(&in, &pa, &pb, &piece, &r)) {
    if (cum + piece >= goal) {
      if (in.top == 0 && goal >= cum + piece) break;   /* s >= L: t = 1 */
      *t = solve_in_piece(&in, pa, pb, piece, goal - cum,
                          o->rtol * 0.25 * in.lest, r);
      break;
    }
    cum += piece;
  }
  fill_info(info, &in, in.h.exp);
  return ARCLEN_OK;
}

double arclen_length_gl(const double *c, int dim, int n) {
  arclen_hodo h;
  arclen_hodo_scaled(c, dim, &h);
  if (h.zero) return 0;
  return ldexp(apply_rule(&h, rule_at_least(n), 0.5, 0.5), h.exp);
}

/* ---- the plain API ---------------------------------------------------- */

static double length_of(const double *c, int dim, double t0, double t1,
                        double rtol) {
  arclen_opts o;
  double len;
  arclen_opts_init(&o);
  o.rtol = rtol;
  o.t0 = t0;
  o.t1 = t1;
  arclen_length_gauss(c, dim, &o, &len, NULL);
  return len;
}

static double time_of(const double *c, int dim, double s, double rtol) {
  arclen_opts o;
  double t;
  arclen_opts_init(&o);
  o.rtol = rtol;
  arclen_time_gauss(c, dim, s, &o, &t, NULL);
  return t;
}

double arclen_length(const double c[8], double rtol) {
  return length_of(c, 2, 0, 1, rtol);
}
double arclen_length_range(const double c[8], double t0, double t1,
                           double rtol) {
  return length_of(c, 2, t0, t1, rtol);
}
double arclen_time(const double c[8], double s, double rtol) {
  return time_of(c, 2, s, rtol);
}
double arclen_length3(const double c[12], double rtol) {
  return length_of(c, 3, 0, 1, rtol);
}
double arclen_length3_range(const double c[12], double t0, double t1,
                            double rtol) {
  return length_of(c, 3, t0, t1, rtol);
}
double arclen_time3(const double c[12], double s, double rtol) {
  return time_of(c, 3, s, rtol);
}
