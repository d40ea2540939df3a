/*
** integrator.h -- the default method's adaptive integrator, shared by the
** length (length.c) and the inverse (time.c).  Internal to gauss/.
**
** The speed f = sqrt(Q) is analytic but for the branch points (branch.c),
** and the error of the n-point rule on a piece is bounded along the cuts
** from them (bound.c).  Curves with a root too far for that take the
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
#ifndef ARCLEN_GAUSS_INTEGRATOR_H
#define ARCLEN_GAUSS_INTEGRATOR_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "arclen.h"
#include "curve/cubic.h"
#include "curve/numeric.h"
#include "gauss/bound.h"
#include "gauss/gauss_tables.h"
#include "gauss/speed_sum.h"

/* Inline where the default method's common path takes them. */
#if defined(__GNUC__)
#define HOT_INLINE __attribute__((always_inline)) inline
#else
#define HOT_INLINE inline
#endif

/* The range is cut at the foot of a branch point nearer to it than
** footcut(rtol) times its width; a piece that no order up to NMAX meets is
** cut GRADE times its nearest branch point's distance from the near end.
** A cut pays when one piece would need many more points than two, and the
** points grow with the bits asked for, so the share grows linearly with
** the bits, within [0.02, 0.1] (doc/benchmarks.md has the measurements). */
static inline double arclen_footcut(double rtol) {
  double f = arclen_muladd(-0.0015, arclen_rough_log2(rtol), -0.005);
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
static inline const arclen_gauss_rule *arclen_rule_at_least(int n) {
  return &arclen_gauss_rules[n < 1 ? 0 : n > ARCLEN_GAUSS_MAX
                                             ? ARCLEN_GAUSS_MAX - 1 : n - 1];
}

/* half * sum w_i f(c + half x_i): the rule on [c - half, c + half]. */
static inline double arclen_apply_rule(const arclen_hodo *h,
                                       const arclen_gauss_rule *r, double c,
                                       double half) {
  if (r->n % 2)
    return arclen_speed_rule(h, r->x, r->w, 1, r->half, c, half,
                             r->w[0] * arclen_hodo_speed(h, c));
  return arclen_speed_rule(h, r->x, r->w, 0, r->half, c, half, 0);
}

/* The bound for one piece [c - half_width, c + half_width], in units of half_width (u = (t - c)/half_width).
** For a branch point z = u + iv the Bernstein ellipse through it has
** semi-axes a, b with a^2 - 1 = b^2 = e, where (|z|^2 - 1 = p)
**     e = (p + sqrt(p^2 + 4 v^2)) / 2 = 2 v^2 / (sqrt(p^2 + 4 v^2) - p),
** the second form for p < 0 (no cancellation next to the interval); then
** rho = a + b and rho^2 - 1 = 2 e + 2 sqrt(e (1 + e)), also cancellation
** free.  The nearest branch point (least e) sets the ellipse.  On it every
** |z - r_k| <= |c - r_k| + half_width a, so M <= lead prod (|c - r_k| + half_width a). */
typedef struct piece_bound {
  double logc;        /* log2 of the bound's constant over the target, but
                      ** for the factors common to all pieces (logk) */
  double log_rho2;    /* a lower bound of log2(rho^2): what a point gains */
  double m;           /* M >= |f| on the ellipse (scaled units) */
  double e;           /* the ellipse's b^2 / half_width^2, e as above */
  int inside;         /* a real (double) root strictly inside: must split */
} piece_bound;

/* A pending piece and its bound: from the branch cuts (bound.c), or
** the ellipse bound when the curve has a root too far for that. */
typedef struct span {
  double a, b;
  int depth;
  union {
    arclen_cut_piece cut;     /* in->cc.ok */
    piece_bound pbound;           /* otherwise */
  } u;
} span;

/* The state of one adaptive integration over [t0, t1] (t0 < t1). */
typedef struct integrator {
  arclen_hodo h;
  arclen_branch br;
  arclen_cut_curve cc;
  double rtol, len_lower, width;   /* tolerance, lower bound of L, t1 - t0 */
  double t0, t1;              /* the range, [-1, 1] for a sub-range */
  double unit;                /* dt/ds: the result's factor (sub-ranges) */
  double logk;                /* log2((32/15) width / (rtol len_lower)) */
  double lgoal;               /* log2(2 rtol len_lower / (width lead 4/pi)) */
  double lead_log;                 /* log2(lead 4/pi), rounded up */
  double mins[ARCLEN_CUT_PIECES - 1];  /* feet of near branch points */
  double chords[ARCLEN_CUT_PIECES];    /* of the first pieces: L's lower bound */
  int nmin;
  int top;
  long evals, pieces, splits;
  int depth;
  double err;                 /* sum of accepted pieces' bounds */
  int want_err;               /* info requested: sum the bounds */
  int prepared;               /* cc and logk taken (prepare_bounds) */
  span stack[MAXSTACK];       /* last: start() leaves it uninitialised */
} integrator;

/* The ends of first piece i (0 <= i <= nmin), between the feet. */
static inline double arclen_first_from(const integrator *in, int i) {
  return i ? in->mins[i - 1] : in->t0;
}
static inline double arclen_first_to(const integrator *in, int i) {
  return i < in->nmin ? in->mins[i] : in->t1;
}

/* The feet of br's branch points over (t0, t1) less than cut above it,
** ascending into mins (at most two: a pair each); returns their number. */
static HOT_INLINE int arclen_feet_of(const arclen_branch *br, double t0, double t1,
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
static HOT_INLINE double arclen_lead_log2(double lead2) {
  return arclen_muladd(0.5, arclen_rough_log2(lead2 * (16 / (ARCLEN_PI * ARCLEN_PI))),
                       ARCLEN_LOG2_ERR);
}

/* log2 of the pieces' common target, 2 rtol len_lower / (width lead 4/pi),
** from below; iw = 1/width, lead_log = lead_log2(). */
static HOT_INLINE double arclen_goal_log2(double rtol, double len_lower, double iw,
                                   double lead_log) {
  return arclen_rough_log2(2 * rtol * len_lower * iw) - lead_log - ARCLEN_LOG2_ERR;
}

/* x 2^e, as ldexp(x, e) but for the common e without a call: 2^e is then
** a normal number, and the one product rounds as ldexp does (also into
** subnormals). */
static inline double arclen_times_pow2(double x, int e) {
  if (e >= -1022 && e <= 1023) {
    uint64_t u = (uint64_t)(e + 1023) << 52;         /* 2^e, exact */
    double m;
    memcpy(&m, &u, sizeof m);
    return x * m;
  }
  return ldexp(x, e);
}


/* Whether a piece of chord `chord` holds the distance s from its start:
** a chord is never longer than its arc, and 2^-40 of it covers its
** rounding.  The one test of an open piece on both of time's paths. */
static inline int arclen_chord_holds(double chord, double s) {
  return s < chord * (1 - 0x1p-40);
}

/* The part of rtol the rules' errors may take; the rest is for rounding,
** which stays below 64 eps relative (the specs hold the result to that
** beyond info.err), or half of rtol when that is less. */
#define ROUNDING_RESERVE (64 * 2.220446049250313e-16)
static inline double arclen_truncation_budget(double rtol) {
  return rtol - (rtol / 2 < ROUNDING_RESERVE ? rtol / 2 : ROUNDING_RESERVE);
}

/* integrator.c: the ellipse bound of [c - half_width, c + half_width] (see piece_bound). */
void arclen_bound_piece(const arclen_branch *br, double c, double half_width,
                        piece_bound *pbound);
/* Set up in over [t0, t1] with the truncation budget rtol and the feet cut
** within share of the width; 0 when there is nothing to integrate. */
int arclen_integ_start(integrator *in, const double *c, int dim, double t0,
                       double t1, double rtol, double share);
/* The bounds' records (cut bounds, or the ellipse bound's target). */
void arclen_integ_prepare_bounds(integrator *in);
/* The first pieces' middles, half-widths and orders; 0: not to be had. */
int arclen_integ_first_orders(const integrator *in, double *c, double *half_width,
                              int *n);
/* The same in two steps: the middles and half-widths of the first pieces,
** then the orders of pieces i0 <= i < i1 into n[i] (0: not to be had). */
void arclen_integ_first_pieces(const integrator *in, double *c, double *half_width);
int arclen_integ_orders_of(const integrator *in, int i0, int i1, const double *c,
                           const double *half_width, int *n);
/* First piece i alone onto the stack (the caller takes the next first
** piece once next_piece has popped its parts). */
void arclen_integ_push_one(integrator *in, int i);
/* The next accepted piece [*from, *to] in increasing t, its length and
** rule (rule may be NULL); 0 when none is left.  A piece whose chord
** reaches past open_below (a distance from its start; HUGE_VAL: never)
** is returned open, before its rule or any cut: length HUGE_VAL, rule
** NULL, neither taken. */
int arclen_integ_next_piece(integrator *in, double open_below, double *from,
                            double *to, double *len,
                            const arclen_gauss_rule **rule);
/* The whole integral over the range set up by arclen_integ_start. */
double arclen_integ_integrate(integrator *in);
/* The argument check of the gauss entry points (an ARCLEN_ code). */
int arclen_integ_check_args(const double *c, int dim, double rtol, double t0,
                            double t1);
/* x in the integrator's scaled units as a length of the curve. */
double arclen_integ_curve_units(const integrator *in, double x);
/* The counts into info (when not NULL), err scaled by 2^exp. */
void arclen_integ_fill_info(arclen_info *info, const integrator *in, int exp);

#endif
