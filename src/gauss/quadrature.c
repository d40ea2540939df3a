/*
** quadrature.c -- the default length method ("gauss"): Gauss-Legendre on
** pieces whose order is chosen from an a priori error bound.
**
** The speed f = sqrt(Q) is analytic but for the branch points (branch.c),
** and the error of the n-point rule on a piece is bounded along the cuts
** from them (gauss_bound.c).  Curves with a root too far for that take the
** Bernstein-ellipse bound: f is analytic inside the ellipse E_rho that
** reaches the nearest branch point, and with |f| <= M on E_rho the rule
** errs by at most
**     (64/15) M rho^(2-2n) / (rho^2 - 1)      on [-1, 1]
** (Trefethen, "Approximation Theory and Approximation Practice", Thm 19.3,
** whose I_n has n+1 points; it follows from |a_k| <= 2 M rho^-k, Thm 8.1).
** Neither bound can be fooled by two rules agreeing by accident: both are
** read off the geometry.  [t0, t1] is cut at the feet of the branch points
** (where near-cusps put the speed's minima), then a piece that no order up
** to NMAX meets is cut again, closer to its nearest branch point (a graded
** mesh).  A sub-range is integrated on its own hodograph (cubic.c), so a
** short range beside a near-cusp keeps its relative precision.
*/
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "arclen.h"
#include "curve/cubic.h"
#include "gauss/bound.h"
#include "gauss/gauss_tables.h"
#include "gauss/speed_sum.h"

/* The range is cut at the foot of a branch point nearer to it than
** footcut(rtol) times its width; a piece that no order up to NMAX meets is
** cut GRADE times its nearest branch point's distance from the near end.
** A cut pays when one piece would need many more points than two, and the
** points grow with the bits asked for: on the bench's random curves the
** least time (median and mean; make bench's curves, a cut at every foot
** below the share against none) came at 0.04 of the width for rtol 1e-9,
** 0.05-0.06 for 1e-12 and 0.07 for 1e-15, so the share is linear in the
** bits, between 0.02 and 0.1.  (With one square root per point, 0.1 had
** been best at 1e-12: the dearer the points, the more a cut saves.)  A
** second piece costs ~40 ns (its bounds, the estimates below the
** reference order, a chord, a rule), as much as some 80 packed
** evaluations, so few long pieces beat many short ones; a share of 0.2,
** GRADE 4, NMAX 48 took 10% more time than 0.05 with GRADE 8, NMAX 128. */
static double footcut(double rtol) {
  double f = -0.0015 * arclen_rough_log2(rtol) - 0.005;
  return f < 0.02 ? 0.02 : f > 0.1 ? 0.1 : f;
}
#define GRADE 8.0
#define NMAX 128         /* highest order used before cutting instead */
#define FLOOR_ORDER 48   /* the rule of a piece that cannot be cut further */
#define MAXDEPTH 60      /* bisection levels below a critical piece */
#define MAXSTACK (4 + 2 * MAXDEPTH)  /* pending pieces: depth-first search */
/* e = b^2 of the ellipse with rho = 64 ((rho - 1/rho)/2 squared): a larger
** ellipse only inflates M. */
#define E_CAP 1023.5000610351562
/* Cap on bisections per integration: the depth cap alone allows 2^60
** pieces when every piece fails; 10^5 is far above what rtol 1e-15 needs
** on the hardest reference curve (found by fuzz/fuzz_length). */
#define MAXSPLITS 100000L

/* The rule with n points (1 <= n <= ARCLEN_GAUSS_MAX, every order is
** tabulated at index n - 1 by tools/gen_gauss_tables.py), clamped into
** that range. */
static const arclen_gauss_rule *rule_at_least(int n) {
  return &arclen_gauss_rules[n < 1 ? 0 : n > ARCLEN_GAUSS_MAX
                                             ? ARCLEN_GAUSS_MAX - 1 : n - 1];
}

/* hh * sum w_i f(c + hh x_i): the rule on [c - hh, c + hh]. */
static double apply_rule(const arclen_hodo *h, const arclen_gauss_rule *r,
                         double c, double hh) {
  if (r->n % 2)
    return hh * arclen_speed_pairs(h, r->x, r->w, 1, r->half, c, hh,
                                   r->w[0] * arclen_hodo_speed(h, c));
  return hh * arclen_speed_pairs(h, r->x, r->w, 0, r->half, c, hh, 0);
}

#define rough_log2 arclen_rough_log2
#define LOG2_ERR ARCLEN_LOG2_ERR

/* The bound for one piece [c - hh, c + hh], in units of hh (u = (t - c)/hh).
** For a branch point z = u + iv the Bernstein ellipse through it has
** semi-axes a, b with a^2 - 1 = b^2 = e, where (|z|^2 - 1 = p)
**     e = (p + sqrt(p^2 + 4 v^2)) / 2 = 2 v^2 / (sqrt(p^2 + 4 v^2) - p),
** the second form for p < 0 (no cancellation next to the interval); then
** rho = a + b and rho^2 - 1 = 2 e + 2 sqrt(e (1 + e)), also cancellation
** free.  The nearest branch point (least e) sets the ellipse.  On it every
** |z - r_k| <= |c - r_k| + hh a, so M <= lead prod (|c - r_k| + hh a). */
typedef struct piece_bound {
  double logc;        /* log2 of the bound's constant over the target, but
                      ** for the factors common to all pieces (logk) */
  double log_rho2;    /* a lower bound of log2(rho^2): what a point gains */
  double m;           /* M >= |f| on the ellipse (scaled units) */
  double e;           /* the ellipse's b^2 / hh^2, e as above */
  int inside;         /* a real (double) root strictly inside: must split */
} piece_bound;

/* log2(rho^2) from g = rho^2 - 1, never above the true value: the
** alternating series ln(1 + g) >= g - g^2/2 for small g, else the rough
** log less its error. */
static double log_rho2_below(double g) {
  return g < 0.0625 ? g * (1 - g / 2) * 1.4426950408889634
                    : rough_log2(1 + g) - LOG2_ERR;
}

static void bound_piece(const arclen_branch *br, double c, double hh,
                        piece_bound *pb) {
  double e = E_CAP, inv = 1 / hh, d[4], a, g, prod, rho2;
  int k, np = 0;
  pb->inside = 0;
  for (k = 0; k < br->n; k += 2) {     /* roots come in conjugate pairs */
    double dr = br->re[k] - c, im = br->im[k];
    if (fabs(dr) + im > 1e100 * hh) {  /* far: squares would overflow */
      d[np++] = fabs(dr) + im;         /* >= the distance */
      continue;
    }
    d[np++] = sqrt(dr * dr + im * im);
    if (im == 0) {                     /* no branch point, but a kink */
      if (fabs(dr) < hh * (1 - 1e-12)) pb->inside = 1;
    } else {
      /* in units of hh (no underflow for tiny pieces); both forms are
      ** computed and chosen by arithmetic: the sign of p is random, and a
      ** branch on it mispredicted a third of the time */
      double u = dr * inv, v = im * inv, p = u * u + v * v - 1;
      double m = (fabs(p) + sqrt(p * p + 4 * v * v)) / 2;
      double e_in = v * v / m;           /* p < 0: |p| <= 1, m is finite */
      double ek = e_in + (m - e_in) * (0.5 + copysign(0.5, p));
      e = ek < e ? ek : e;
    }
  }
  g = 2 * e + 2 * sqrt(e * (1 + e));          /* rho^2 - 1 */
  rho2 = 1 + g;
  a = hh * sqrt(1 + e);                        /* semi-major axis, t units */
  prod = sqrt(br->lead2);
  for (k = 0; k < np; k++) prod *= d[k] + a;
  pb->m = prod;
  pb->e = e;
  pb->log_rho2 = log_rho2_below(g);
  /* log2(C / target), C = hh (64/15) M rho^2 / (rho^2 - 1) and target =
  ** rtol lest 2 hh / width, but for logk, the factors common to all pieces
  ** (start()); the product is taken whole when it is a normal number. */
  prod *= rho2 / g;
  if (prod > 1e-300 && prod < 1e300) {
    pb->logc = rough_log2(prod) + LOG2_ERR;
  } else {                                     /* huge or tiny parts */
    pb->logc = 0.5 * log2(br->lead2) + log2(rho2) - log2(g);
    for (k = 0; k < np; k++) pb->logc += log2(d[k] + a);
  }
}

/* The smallest order whose bound C rho^(-2n) is <= the target, or NULL
** past NMAX.  logc is an upper bound and log_rho2 a lower bound (their
** rough logs carry LOG2_ERR), so n is never too small. */
static const arclen_gauss_rule *choose_rule(const piece_bound *pb,
                                            double logk) {
  double n, logc = pb->logc + logk;
  if (pb->inside) return NULL;
  if (logc <= 0) return rule_at_least(2);       /* C <= target already */
  if (!(pb->log_rho2 > 0)) return NULL;         /* rho ~ 1: no order will do */
  n = logc / pb->log_rho2;
  if (!(n <= NMAX)) return NULL;                /* also catches NaN */
  return rule_at_least(n < 2 ? 2 : (int)ceil(n));
}

/* A pending piece and its bound: from the branch cuts (gauss_bound.c), or
** the ellipse bound when the curve has a root too far for that. */
typedef struct span {
  double a, b;
  int depth;
  union {
    arclen_cut_piece cut;     /* in->cc.ok */
    piece_bound pb;           /* otherwise */
  } u;
} span;

/* The state of one adaptive integration over [t0, t1] (t0 < t1). */
typedef struct integrator {
  arclen_hodo h;
  arclen_branch br;
  arclen_cut_curve cc;
  double rtol, lest, width;   /* tolerance, lower bound of L, t1 - t0 */
  double t0, t1;              /* the range, [-1, 1] for a sub-range */
  double unit;                /* dt/ds: the result's factor (sub-ranges) */
  double logk;                /* log2((32/15) width / (rtol lest)) */
  double lgoal;               /* log2(2 rtol lest / (width lead 4/pi)) */
  double lkl;                 /* log2(lead 4/pi), rounded up */
  double mins[ARCLEN_CUT_PIECES - 1];  /* feet of near branch points */
  int nmin;
  int top;
  long evals, pieces, splits;
  int depth;
  double err;                 /* sum of accepted pieces' bounds */
  int want_err;               /* info requested: sum the bounds */
  span stack[MAXSTACK];       /* last: start() leaves it uninitialised */
} integrator;

/* [a, b] and its bound into s. */
static void bound_span(const integrator *in, span *s, double a, double b,
                       int depth) {
  s->a = a;
  s->b = b;
  s->depth = depth;
  if (in->cc.ok)
    arclen_cut_bound(&in->cc, a + (b - a) / 2, (b - a) / 2, &s->u.cut);
  else
    bound_piece(&in->br, a + (b - a) / 2, (b - a) / 2, &s->u.pb);
}

/* Push [a, b] with its bound.  The bound is taken here, not when the piece
** is popped: the pieces pushed together (the first cuts, the halves of a
** cut) have independent bounds, whose chains of square roots and divisions
** then run side by side, and beside the chords in start(). */
static void push(integrator *in, double a, double b, int depth) {
  if (in->top >= MAXSTACK) return;
  bound_span(in, &in->stack[in->top++], a, b, depth);
}

/* The ends of first piece i (0 <= i <= nmin), between the feet. */
static double first_from(const integrator *in, int i) {
  return i ? in->mins[i - 1] : in->t0;
}
static double first_to(const integrator *in, int i) {
  return i < in->nmin ? in->mins[i] : in->t1;
}

/* Inline where the default method's common path takes them. */
#if defined(__GNUC__)
#define HOT_INLINE __attribute__((always_inline)) inline
#else
#define HOT_INLINE inline
#endif

/* The feet of br's branch points over (t0, t1) less than cut above it,
** ascending into mins (at most two: a pair each); returns their number. */
static HOT_INLINE int feet_of(const arclen_branch *br, double t0, double t1,
                              double cut, double *mins) {
  int i, j, n = 0;
  for (i = 0; i < br->n; i += 2) {
    double foot = br->re[i];
    if (foot > t0 && foot < t1 && br->im[i] < cut) {
      for (j = n; j > 0 && mins[j - 1] > foot; j--)
        mins[j] = mins[j - 1];             /* insertion: keep ascending */
      mins[j] = foot;
      n++;
    }
  }
  return n;
}

/* log2(lead 4/pi), rounded up, from the lead's square: its square root
** goes into the log, a square root fewer. */
static HOT_INLINE double lead_log2(double lead2) {
  return 0.5 * rough_log2(lead2 * (16 / (3.14159265358979323846 *
                                         3.14159265358979323846))) +
         LOG2_ERR;
}

/* log2 of the pieces' common target, 2 rtol lest / (width lead 4/pi),
** from below; iw = 1/width, lkl = lead_log2(). */
static HOT_INLINE double goal_log2(double rtol, double lest, double iw,
                                   double lkl) {
  return rough_log2(2 * rtol * lest * iw) - lkl - LOG2_ERR;
}

/* Set up: the cuts are the feet of the branch points near [t0, t1] (the
** real part of each conjugate pair, and each real root): as a branch point
** nears the axis the speed dips to a minimum (a near-cusp) right below it,
** so these are the speed's minima that matter -- the roots of Q'.Q'' that
** lie under no nearby branch point cost a piece and gain nothing.  L is
** bounded below by the sum of chords between cuts, so every piece's share
** of the tolerance, rtol lest w / width for width w, is safe.  Returns 0
** when there is nothing to integrate (a point, or a zero speed). */
static int start(integrator *in, const double *c, int dim, double t0,
                 double t1, double rtol, double share) {
  int i;
  double iw;
  /* h, br and cc are filled below; the stack is filled by push() before
  ** pop reads it */
  in->lest = in->logk = in->lgoal = in->err = 0;
  in->nmin = in->top = in->depth = in->want_err = 0;
  in->evals = in->pieces = in->splits = 0;
  in->unit = 1;
  if (t0 == 0 && t1 == 1) {
    arclen_hodo_scaled(c, dim, &in->h);
  } else {              /* a sub-range: its own hodograph, on [-1, 1] */
    arclen_hodo_local(c, dim, t0, t1, &in->h);
    in->unit = (t1 - t0) / 2;
    t0 = -1;
    t1 = 1;
  }
  if (in->h.zero) return 0;
  arclen_branch_points(&in->h, &in->br);
  in->rtol = rtol;
  in->width = t1 - t0;
  in->nmin = feet_of(&in->br, t0, t1, share * in->width, in->mins);
  in->t0 = t0;
  in->t1 = t1;
  for (i = 0; i <= in->nmin; i++)
    in->lest += arclen_hodo_chord(&in->h, first_from(in, i), first_to(in, i));
  /* Zero chords between every pair of cuts but a moving point: the curve
  ** returns to where it was; bound L below by a coarse rule. */
  if (!(in->lest > 0))
    in->lest = 0.5 * apply_rule(&in->h, rule_at_least(8), t0 + in->width / 2,
                                in->width / 2);
  if (!(in->lest > 0)) return 0;
  /* 1/width (1 or 1/2) goes into the log: a division fewer */
  in->lkl = lead_log2(in->br.lead2);
  iw = in->width == 1 ? 1 : in->width == 2 ? 0.5 : 1 / in->width;
  in->lgoal = goal_log2(in->rtol, in->lest, iw, in->lkl);
  return 1;
}

/* What the pieces' bounds need of the curve (gauss_bound.c), or the
** ellipse bound's target when a root lies too far for that; taken after
** start() by the curves whose first pieces arclen_cut_orders does not
** serve, and by time. */
static void prepare_bounds(integrator *in) {
  arclen_cut_prepare(&in->br, &in->cc);
  if (!in->cc.ok)
    in->logk = rough_log2((32.0 / 15.0) * in->width / in->rtol) -
              rough_log2(in->lest) + 2 * LOG2_ERR;   /* an upper bound */
}

/* Where to cut a piece: at a foot of a branch point inside it (the one
** nearest its middle); else, when the nearest branch point lies off one
** end, at GRADE times its distance from that end (a geometric mesh towards
** the singularity: each piece then sees it at the same relative distance,
** so no piece needs a high order); else in the middle. */
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
  if (dist < HUGE_VAL) return best;
  for (i = 0; i < in->br.n; i += 2) {
    double re = in->br.re[i], im = in->br.im[i];
    double off = re < a ? a - re : re > b ? re - b : 0;
    double d = GRADE * (off + im);
    if (im > 0 && d > margin && d < dist) {   /* real roots: no singularity */
      dist = d;
      best = re < mid ? a + d : b - d;
    }
  }
  return dist < (b - a) / 2 ? best : mid;
}

/* The rule for span s: the least order whose bound meets its share of the
** tolerance, or NULL past NMAX; *err gets that bound when info is wanted. */
static const arclen_gauss_rule *span_rule(const integrator *in,
                                          const span *s, double *err) {
  const arclen_gauss_rule *r = NULL;
  double ratio = 0;
  *err = 0;
  if (in->cc.ok) {
    int n = arclen_cut_order(&in->cc, &s->u.cut, in->lgoal, NMAX,
                             in->want_err ? &ratio : NULL);
    if (n) r = rule_at_least(n);
  } else {
    r = choose_rule(&s->u.pb, in->logk);
  }
  if (r && in->want_err)
    *err = in->rtol * in->lest * ((s->b - s->a) / in->width) *
           (in->cc.ok ? ratio : exp2(s->u.pb.logc + in->logk -
                                     r->n * s->u.pb.log_rho2));
  return r;
}

/* Integrate the accepted span s by rule r and count it. */
static double accept(integrator *in, const span *s,
                     const arclen_gauss_rule *r, double err) {
  double a = s->a, b = s->b;
  in->evals += r->n;
  in->pieces++;
  if (s->depth > in->depth) in->depth = s->depth;
  in->err += err;
  return apply_rule(&in->h, r, a + (b - a) / 2, (b - a) / 2);
}

/* Pop the next piece (in increasing t) and integrate it.  A piece is cut
** (cut_point) when no order up to NMAX meets its share of the tolerance.
** Returns 0 when no piece is left; else the accepted piece [*from, *to]
** and its length. */
static int next_piece(integrator *in, double *from, double *to, double *len,
                      const arclen_gauss_rule **rule) {
  while (in->top > 0) {
    const span *s = &in->stack[--in->top];
    double a = s->a, b = s->b, err;
    int depth = s->depth;
    const arclen_gauss_rule *r = span_rule(in, s, &err);
    if (r == NULL && depth < MAXDEPTH && in->splits < MAXSPLITS) {
      double cut = cut_point(in, a, b);
      if (cut > a && cut < b) {        /* s is overwritten from here on */
        in->splits++;
        push(in, cut, b, depth + 1);
        push(in, a, cut, depth + 1);
        continue;
      }
    }
    if (r == NULL) {          /* bisection floor: a piece of ~1e-18 width */
      piece_bound eb;
      bound_piece(&in->br, a + (b - a) / 2, (b - a) / 2, &eb);
      r = rule_at_least(FLOOR_ORDER);
      err = 2 * (b - a) * eb.m;      /* crude: the rule and the integral */
    }                                /* are each at most width x M */
    *len = accept(in, s, r, err);
    *from = a;
    *to = b;
    if (rule) *rule = r;
    return 1;
  }
  return 0;
}

/* The first pieces, between the feet, in increasing t. */
static void push_initial(integrator *in) {
  int i;
  for (i = in->nmin; i >= 0; i--)      /* the stack pops the first first */
    push(in, first_from(in, i), first_to(in, i), 0);
}

/* sum plus a first piece that no order up to NMAX meets, cut on the
** stack (its pieces added one by one, in increasing t). */
static double integrate_cut(integrator *in, const span *s, double sum) {
  double pa, pb, piece;
  in->stack[in->top++] = *s;
  while (next_piece(in, &pa, &pb, &piece, NULL)) sum += piece;
  return sum;
}

/* The first pieces' middles c and half-widths hh, and their orders n
** straight from the branch points (arclen_cut_orders): 1, or 0 when those
** are not to be had (a real or far root, a piece to cut). */
static int first_orders(const integrator *in, double *c, double *hh,
                        int *n) {
  int i;
  for (i = 0; i <= in->nmin; i++) {
    hh[i] = (first_to(in, i) - first_from(in, i)) / 2;
    c[i] = first_from(in, i) + hh[i];
  }
  return arclen_cut_orders(&in->br, in->nmin + 1, c, hh, in->lgoal, NMAX, n);
}

/* The whole integral.  The first pieces (at most three, between the feet)
** take their bounds and orders together, so that their chains of square
** roots and divisions run side by side; then the rules.  Most curves get
** their orders straight from the branch points (arclen_cut_orders); the
** rest -- the error asked for, a real or far root, a piece to be cut --
** take the records of prepare_bounds, and the stack for the cuts. */
static double integrate(integrator *in) {
  span s[ARCLEN_CUT_PIECES];
  double err[ARCLEN_CUT_PIECES], sum = 0;
  const arclen_gauss_rule *r[ARCLEN_CUT_PIECES];
  int i;
  if (!in->want_err) {
    double c[ARCLEN_CUT_PIECES], hh[ARCLEN_CUT_PIECES];
    int n[ARCLEN_CUT_PIECES];
    if (first_orders(in, c, hh, n)) {
      for (i = 0; i <= in->nmin; i++) {
        in->evals += n[i];
        in->pieces++;
        sum += apply_rule(&in->h, rule_at_least(n[i]), c[i], hh[i]);
      }
      return sum;
    }
  }
  prepare_bounds(in);
  for (i = 0; i <= in->nmin; i++) {
    bound_span(in, &s[i], first_from(in, i), first_to(in, i), 0);
    r[i] = span_rule(in, &s[i], &err[i]);
  }
  for (i = 0; i <= in->nmin; i++)
    sum = r[i] ? sum + accept(in, &s[i], r[i], err[i])
               : integrate_cut(in, &s[i], sum);
  return sum;
}

static int check_args(const double *c, int dim, double rtol, double t0,
                      double t1) {
  int e = arclen_check_curve(c, dim);
  if (e) return e;
  if (!(rtol >= ARCLEN_RTOL_MIN && rtol <= ARCLEN_RTOL_MAX))
    return ARCLEN_ETOL;
  if (!(t0 >= 0 && t0 <= 1 && t1 >= 0 && t1 <= 1)) return ARCLEN_ERANGE;
  return ARCLEN_OK;
}

/* x 2^e, as ldexp(x, e) but for the common e without a call: 2^e is then
** a normal number, and the one product rounds as ldexp does (also into
** subnormals). */
static double times_pow2(double x, int e) {
  if (e >= -1022 && e <= 1023) {
    uint64_t u = (uint64_t)(e + 1023) << 52;         /* 2^e, exact */
    double m;
    memcpy(&m, &u, sizeof m);
    return x * m;
  }
  return ldexp(x, e);
}

/* x in the integrator's scaled units and local variable as a length of
** the curve: x unit 2^exp, with unit's exponent folded into exp so that
** neither product over- or underflows on the way. */
static double in_curve_units(const integrator *in, double x) {
  int k;
  double m;
  if (in->unit == 1) return times_pow2(x, in->h.exp);
  m = frexp(in->unit, &k);
  return ldexp(x * m, in->h.exp + k);
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

/* The part of rtol the rules' errors may take; the rest is for rounding,
** which stays below 64 eps relative (the specs hold the result to that
** beyond info.err), or half of rtol when that is less. */
#define ROUNDING_RESERVE (64 * 2.220446049250313e-16)
static double truncation_budget(double rtol) {
  return rtol - (rtol / 2 < ROUNDING_RESERVE ? rtol / 2 : ROUNDING_RESERVE);
}

/* The commonest call -- a whole plane curve, two branch pairs in reach, no
** report asked -- as start() and integrate() take it, step for step (the
** same sums in the same order, so the same result), without the
** integrator's record, the argument check (arclen_hodo_quick refuses what
** it would) or a call between the steps.  rtol is the truncation budget.
** Returns 0 when the curve is not of that kind: the caller then takes
** the general path from the start. */
static int length_fast(const double *c, double rtol, double *len) {
  arclen_hodo h;
  arclen_branch br;
  double mid[ARCLEN_CUT_PIECES], hh[ARCLEN_CUT_PIECES];
  double mins[ARCLEN_CUT_PIECES - 1];
  double lest = 0, lgoal, sum = 0;
  int n[ARCLEN_CUT_PIECES], nmin, i;
  if (!arclen_hodo_quick(c, 2, &h)) return 0;
  arclen_branch_points(&h, &br);
  if (br.n != 4) return 0;
  nmin = feet_of(&br, 0, 1, footcut(rtol), mins);
  for (i = 0; i <= nmin; i++) {
    double a = i ? mins[i - 1] : 0, b = i < nmin ? mins[i] : 1;
    lest += arclen_hodo_chord(&h, a, b);
    hh[i] = (b - a) / 2;
    mid[i] = a + hh[i];
  }
  if (!(lest > 0)) return 0;
  lgoal = goal_log2(rtol, lest, 1, lead_log2(br.lead2));   /* width 1 */
  if (!arclen_cut_orders(&br, nmin + 1, mid, hh, lgoal, NMAX, n)) return 0;
  for (i = 0; i <= nmin; i++)
    sum += apply_rule(&h, rule_at_least(n[i]), mid[i], hh[i]);
  *len = times_pow2(sum, h.exp);
  return 1;
}

/* length_fast for a call that may be of its kind. */
static int try_fast(const double *c, int dim, double t0, double t1,
                    double rtol, double *len) {
  if (dim != 2 || t0 != 0 || t1 != 1 ||
      !(rtol >= ARCLEN_RTOL_MIN && rtol <= ARCLEN_RTOL_MAX))
    return 0;
  return length_fast(c, truncation_budget(rtol), len);
}

/* The length over [t0, t1] of a checked curve (t0 > t1: negative). */
static double length_core(const double *c, int dim, double t0, double t1,
                          double rtol, arclen_info *info) {
  integrator in;
  double a = t0 < t1 ? t0 : t1, b = t0 < t1 ? t1 : t0, sum = 0;
  double budget = truncation_budget(rtol);
  if (a == b) return 0;
  if (start(&in, c, dim, a, b, budget, footcut(budget))) {
    in.want_err = info != NULL;
    sum = integrate(&in);
  }
  if (info) {
    fill_info(info, &in, in.h.exp);
    info->err = in_curve_units(&in, in.err);
  }
  return in_curve_units(&in, t0 > t1 ? -sum : sum);
}

int arclen_length_gauss(const double *c, int dim, const arclen_opts *o,
                        double *len, arclen_info *info) {
  int e;
  if (!info && try_fast(c, dim, o->t0, o->t1, o->rtol, len)) return ARCLEN_OK;
  e = check_args(c, dim, o->rtol, o->t0, o->t1);
  *len = NAN;
  if (info) arclen_info_init(info);
  if (e) return e;
  *len = length_core(c, dim, o->t0, o->t1, o->rtol, info);
  return ARCLEN_OK;
}

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
** part of [a, b] (about as good as on the piece), then the second-order
** step from it.  The Hermite guess errs by up to ~1e-2 of the piece where
** a branch point stands near it; after this step the certified
** evaluations number 2.1 on average on the bench's curves (were 3.4). */
static double refine_guess(integrator *in, double a, double b, double plen,
                           double goal, const arclen_gauss_rule *r,
                           double t) {
  double sg, f;
  if (t - a <= b - t)
    sg = apply_rule(&in->h, r, a + (t - a) / 2, (t - a) / 2) - goal;
  else
    sg = plen - apply_rule(&in->h, r, t + (b - t) / 2, (b - t) / 2) - goal;
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
** with |f| <= M there: the ellipse bound (quadrature.c's head) at that
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
    double lnum = rough_log2(h * (64.0 / 15.0) * eb->m / target) -
                  rough_log2(rho * rho - 1) + 2 * LOG2_ERR;
    double nn = 1 + lnum / (2 * (rough_log2(rho) - LOG2_ERR));
    n = nn <= 2 ? 2 : nn < ARCLEN_GAUSS_MAX ? (int)ceil(nn) : 0;
  }
  if (!n && !eb->inside && eb->log_rho2 > 0) {
    /* The piece's own ellipse: [x, y] lies in the piece, so the ellipse of
    ** [x, y] with the piece's rho lies inside the piece's (the Green's
    ** function of a subset is the larger), where |f| <= M: the bound at
    ** the piece's rho, M and 2^logc = M rho^2/(rho^2 - 1), scaled by h. */
    double nn = (rough_log2(h * (64.0 / 15.0) / target) + LOG2_ERR +
                 eb->logc) / eb->log_rho2;
    n = nn <= 2 ? 2 : nn < ARCLEN_GAUSS_MAX ? (int)ceil(nn) : 0;
  }
  if (!n && in->cc.ok) {
    arclen_cut_piece cp;
    double lg = rough_log2(target) - rough_log2(h) - in->lkl - 2 * LOG2_ERR;
    arclen_cut_bound(&in->cc, c, h, &cp);
    n = arclen_cut_order(&in->cc, &cp, lg, ARCLEN_GAUSS_MAX, NULL);
  }
  if (n) r = rule_at_least(n);
  in->evals += r->n;
  return apply_rule(&in->h, r, c, h);
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
  bound_piece(&in->br, a + (b - a) / 2, (b - a) / 2, &eb);
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
** of a bound, a rule and a division.  On the bench's curves at tol 1e-12
** (time at L/2, make bench): 0.1 367-386 ns, 0.15 343, 0.2 346-360, 0.3
** 351-371, against 410-428 with the length's 0.055. */
#define TIME_FOOTCUT 0.2

/* time's common case, as integrate() takes it: the first pieces' orders
** straight from the branch points (arclen_cut_orders), then their rules in
** increasing t up to the piece that holds the goal.  Returns 0, with
** nothing done, when those orders are not to be had (a piece to cut, a
** real or far root): the caller then takes the stack. */
static int time_first_pieces(integrator *in, double goal, double *t) {
  double c[ARCLEN_CUT_PIECES], hh[ARCLEN_CUT_PIECES], cum = 0;
  int n[ARCLEN_CUT_PIECES], i;
  if (!first_orders(in, c, hh, n)) return 0;
  prepare_bounds(in);                   /* for sub_integral's cut bounds */
  for (i = 0; i <= in->nmin; i++) {
    const arclen_gauss_rule *r = rule_at_least(n[i]);
    double piece = apply_rule(&in->h, r, c[i], hh[i]);
    in->evals += r->n;
    in->pieces++;
    if (cum + piece >= goal) {
      if (i == in->nmin && goal >= cum + piece) return 1;   /* t = 1 */
      *t = solve_in_piece(in, first_from(in, i), first_to(in, i), piece,
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
  e = check_args(c, dim, o->rtol, 0, 1);   /* time ignores o->t0, t1 */
  *t = NAN;
  if (info) arclen_info_init(info);
  if (e) return e;
  if (isnan(s)) return ARCLEN_EINVAL;
  if (s <= 0) { *t = 0; return ARCLEN_OK; }
  if (!start(&in, c, dim, 0, 1, o->rtol * 0.25, TIME_FOOTCUT)) {
    *t = 1;              /* a point: every s > 0 is past its end */
    return ARCLEN_OK;
  }
  in.want_err = info != NULL;
  goal = ldexp(s, -in.h.exp);
  *t = 1;
  if (!in.want_err && time_first_pieces(&in, goal, t)) {
    fill_info(info, &in, in.h.exp);
    return ARCLEN_OK;
  }
  prepare_bounds(&in);
  push_initial(&in);
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
  return times_pow2(apply_rule(&h, rule_at_least(n), 0.5, 0.5), h.exp);
}

/* ---- the plain API ---------------------------------------------------- */

static double length_of(const double *c, int dim, double t0, double t1,
                        double rtol) {
  double len;
  if (try_fast(c, dim, t0, t1, rtol, &len)) return len;
  if (check_args(c, dim, rtol, t0, t1)) return NAN;
  return length_core(c, dim, t0, t1, rtol, NULL);
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
