/*
** integrator.c -- the default method's adaptive integration (integrator.h
** has the method): the set-up, the pieces' bounds and rules, the stack of
** pieces to cut, taken in increasing t by the length and the inverse.
*/
#include "gauss/integrator.h"

/* log2(rho^2) from g = rho^2 - 1, never above the true value: the
** alternating series ln(1 + g) >= g - g^2/2 for small g, else the rough
** log less its error. */
static double log_rho2_below(double g) {
  return g < 0.0625 ? g * (1 - g / 2) * 1.4426950408889634
                    : arclen_rough_log2(1 + g) - ARCLEN_LOG2_ERR;
}

void arclen_bound_piece(const arclen_branch *br, double c, double half_width,
                        piece_bound *pbound) {
  double e = E_CAP, inv = 1 / half_width, d[4], a, g, prod, rho2;
  int k, np = 0;
  pbound->inside = 0;
  for (k = 0; k < br->n; k += 2) {     /* roots come in conjugate pairs */
    double dr = br->re[k] - c, im = br->im[k];
    if (fabs(dr) + im > 1e100 * half_width) {  /* far: squares would overflow */
      d[np++] = fabs(dr) + im;         /* >= the distance */
      continue;
    }
    d[np++] = sqrt(dr * dr + im * im);
    if (im == 0) {                     /* no branch point, but a kink */
      if (fabs(dr) < half_width * (1 - 1e-12)) pbound->inside = 1;
    } else {
      /* in units of half_width (no underflow for tiny pieces); both forms are
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
  a = half_width * sqrt(1 + e);                        /* semi-major axis, t units */
  prod = sqrt(br->lead2);
  for (k = 0; k < np; k++) prod *= d[k] + a;
  pbound->m = prod;
  pbound->e = e;
  pbound->log_rho2 = log_rho2_below(g);
  /* log2(C / target), C = half_width (64/15) M rho^2 / (rho^2 - 1) and target =
  ** rtol len_lower 2 half_width / width, but for logk, the factors common to all pieces
  ** (arclen_integ_start()); the product is taken whole when it is a normal number. */
  prod *= rho2 / g;
  if (prod > 1e-300 && prod < 1e300) {
    pbound->logc = arclen_rough_log2(prod) + ARCLEN_LOG2_ERR;
  } else {                                     /* huge or tiny parts */
    pbound->logc = 0.5 * log2(br->lead2) + log2(rho2) - log2(g);
    for (k = 0; k < np; k++) pbound->logc += log2(d[k] + a);
  }
}

/* The smallest order whose bound C rho^(-2n) is <= the target, or NULL
** past NMAX.  logc is an upper bound and log_rho2 a lower bound (their
** rough logs carry ARCLEN_LOG2_ERR), so n is never too small. */
static const arclen_gauss_rule *choose_rule(const piece_bound *pbound,
                                            double logk) {
  double n, logc = pbound->logc + logk;
  if (pbound->inside) return NULL;
  if (logc <= 0) return arclen_rule_at_least(2);       /* C <= target already */
  if (!(pbound->log_rho2 > 0)) return NULL;         /* rho ~ 1: no order will do */
  n = logc / pbound->log_rho2;
  if (!(n <= NMAX)) return NULL;                /* also catches NaN */
  return arclen_rule_at_least(n < 2 ? 2 : (int)ceil(n));
}


/* [a, b] and its bound into s. */
static void bound_span(const integrator *in, span *s, double a, double b,
                       int depth) {
  s->a = a;
  s->b = b;
  s->depth = depth;
  if (in->cc.ok)
    arclen_cut_bound(&in->cc, a + (b - a) / 2, (b - a) / 2, &s->u.cut);
  else
    arclen_bound_piece(&in->br, a + (b - a) / 2, (b - a) / 2, &s->u.pbound);
}

/* Push [a, b] with its bound.  The bound is taken here, not when the piece
** is popped: the pieces pushed together (the first cuts, the halves of a
** cut) have independent bounds, whose chains of square roots and divisions
** then run side by side, and beside the chords in arclen_integ_start(). */
static void push(integrator *in, double a, double b, int depth) {
  if (in->top >= MAXSTACK) return;
  bound_span(in, &in->stack[in->top++], a, b, depth);
}


/* Set up: the cuts are the feet of the branch points near [t0, t1] (the
** real part of each conjugate pair, and each real root): as a branch point
** nears the axis the speed dips to a minimum (a near-cusp) right below it,
** so these are the speed's minima that matter -- the roots of Q'.Q'' that
** lie under no nearby branch point cost a piece and gain nothing.  L is
** bounded below by the sum of chords between cuts, so every piece's share
** of the tolerance, rtol len_lower w / width for width w, is safe.  Returns 0
** when there is nothing to integrate (a point, or a zero speed). */
int arclen_integ_start(integrator *in, const double *c, int dim, double t0,
                 double t1, double rtol, double share) {
  int i;
  double iw;
  /* h, br and cc are filled below; the stack is filled by push() before
  ** pop reads it */
  in->len_lower = in->logk = in->lgoal = in->err = 0;
  in->nmin = in->top = in->depth = in->want_err = in->prepared = 0;
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
  in->nmin = arclen_feet_of(&in->br, t0, t1, share * in->width, in->mins);
  in->t0 = t0;
  in->t1 = t1;
  for (i = 0; i <= in->nmin; i++) {
    in->chords[i] = arclen_hodo_chord(&in->h, arclen_first_from(in, i), arclen_first_to(in, i));
    in->len_lower += in->chords[i];
  }
  /* Zero chords between every pair of cuts but a moving point: the curve
  ** returns to where it was; bound L below by a coarse rule. */
  if (!(in->len_lower > 0))
    in->len_lower = 0.5 * arclen_apply_rule(&in->h, arclen_rule_at_least(8), t0 + in->width / 2,
                                in->width / 2);
  if (!(in->len_lower > 0)) return 0;
  /* 1/width (1 or 1/2) goes into the log: a division fewer */
  in->lead_log = arclen_lead_log2(in->br.lead2);
  iw = in->width == 1 ? 1 : in->width == 2 ? 0.5 : 1 / in->width;
  in->lgoal = arclen_goal_log2(in->rtol, in->len_lower, iw, in->lead_log);
  return 1;
}

/* What the pieces' bounds need of the curve (bound.c), or the
** ellipse bound's target when a root lies too far for that; taken after
** arclen_integ_start() by the curves whose first pieces arclen_cut_orders does not
** serve, and by time. */
void arclen_integ_prepare_bounds(integrator *in) {
  if (in->prepared) return;
  in->prepared = 1;
  arclen_cut_prepare(&in->br, &in->cc);
  if (!in->cc.ok)
    in->logk = arclen_rough_log2((32.0 / 15.0) * in->width / in->rtol) -
              arclen_rough_log2(in->len_lower) + 2 * ARCLEN_LOG2_ERR;   /* an upper bound */
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
    if (n) r = arclen_rule_at_least(n);
  } else {
    r = choose_rule(&s->u.pbound, in->logk);
  }
  if (r && in->want_err)
    *err = in->rtol * in->len_lower * ((s->b - s->a) / in->width) *
           (in->cc.ok ? ratio : exp2(s->u.pbound.logc + in->logk -
                                     r->n * s->u.pbound.log_rho2));
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
  return arclen_apply_rule(&in->h, r, a + (b - a) / 2, (b - a) / 2);
}

/* Pop the next piece (in increasing t) and integrate it.  A piece is cut
** (cut_point) when no order up to NMAX meets its share of the tolerance.
** Returns 0 when no piece is left; else the accepted piece [*from, *to]
** and its length; or, before its rule or any cut, a piece whose chord
** reaches past open_below, open: *len = HUGE_VAL and *rule = NULL (the
** caller needs neither; open_below = HUGE_VAL: never). */
int arclen_integ_next_piece(integrator *in, double open_below, double *from,
                            double *to, double *len,
                            const arclen_gauss_rule **rule) {
  while (in->top > 0) {
    const span *s = &in->stack[--in->top];
    double a = s->a, b = s->b, err;
    int depth = s->depth;
    const arclen_gauss_rule *r;
    if (open_below < HUGE_VAL &&
        arclen_chord_holds(arclen_hodo_chord(&in->h, a, b), open_below)) {
      *len = HUGE_VAL;
      *from = a;
      *to = b;
      if (rule) *rule = NULL;
      return 1;
    }
    r = span_rule(in, s, &err);
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
      piece_bound ebound;
      arclen_bound_piece(&in->br, a + (b - a) / 2, (b - a) / 2, &ebound);
      r = arclen_rule_at_least(FLOOR_ORDER);
      err = 2 * (b - a) * ebound.m;      /* crude: the rule and the integral */
    }                                /* are each at most width x M */
    *len = accept(in, s, r, err);
    *from = a;
    *to = b;
    if (rule) *rule = r;
    return 1;
  }
  return 0;
}

/* First piece i alone, for the stack to cut and pop before piece i + 1. */
void arclen_integ_push_one(integrator *in, int i) {
  push(in, arclen_first_from(in, i), arclen_first_to(in, i), 0);
}

/* sum plus a first piece that no order up to NMAX meets, cut on the
** stack (its pieces added one by one, in increasing t). */
static double integrate_cut(integrator *in, const span *s, double sum) {
  double pa, pbound, piece;
  in->stack[in->top++] = *s;
  while (arclen_integ_next_piece(in, HUGE_VAL, &pa, &pbound, &piece, NULL)) sum += piece;
  return sum;
}

/* The first pieces' middles c and half-widths half_width, and their orders n
** straight from the branch points (arclen_cut_orders): 1, or 0 when those
** are not to be had (a real or far root, a piece to cut). */
void arclen_integ_first_pieces(const integrator *in, double *c, double *half_width) {
  int i;
  for (i = 0; i <= in->nmin; i++) {
    half_width[i] = (arclen_first_to(in, i) - arclen_first_from(in, i)) / 2;
    c[i] = arclen_first_from(in, i) + half_width[i];
  }
}

int arclen_integ_orders_of(const integrator *in, int i0, int i1, const double *c,
                           const double *half_width, int *n) {
  return arclen_cut_orders(&in->br, i1 - i0, c + i0, half_width + i0, in->lgoal, NMAX,
                           n + i0);
}

int arclen_integ_first_orders(const integrator *in, double *c, double *half_width,
                        int *n) {
  arclen_integ_first_pieces(in, c, half_width);
  return arclen_integ_orders_of(in, 0, in->nmin + 1, c, half_width, n);
}

/* The whole integral.  The first pieces (at most three, between the feet)
** take their bounds and orders together, so that their chains of square
** roots and divisions run side by side; then the rules.  Most curves get
** their orders straight from the branch points (arclen_cut_orders); the
** rest -- the error asked for, a real or far root, a piece to be cut --
** take the records of prepare_bounds, and the stack for the cuts. */
double arclen_integ_integrate(integrator *in) {
  span s[ARCLEN_CUT_PIECES];
  double err[ARCLEN_CUT_PIECES], sum = 0;
  const arclen_gauss_rule *r[ARCLEN_CUT_PIECES];
  int i;
  if (!in->want_err) {
    double c[ARCLEN_CUT_PIECES], half_width[ARCLEN_CUT_PIECES];
    int n[ARCLEN_CUT_PIECES];
    if (arclen_integ_first_orders(in, c, half_width, n)) {
      for (i = 0; i <= in->nmin; i++) {
        in->evals += n[i];
        in->pieces++;
        sum += arclen_apply_rule(&in->h, arclen_rule_at_least(n[i]), c[i], half_width[i]);
      }
      return sum;
    }
  }
  arclen_integ_prepare_bounds(in);
  for (i = 0; i <= in->nmin; i++) {
    bound_span(in, &s[i], arclen_first_from(in, i), arclen_first_to(in, i), 0);
    r[i] = span_rule(in, &s[i], &err[i]);
  }
  for (i = 0; i <= in->nmin; i++)
    sum = r[i] ? sum + accept(in, &s[i], r[i], err[i])
               : integrate_cut(in, &s[i], sum);
  return sum;
}

int arclen_integ_check_args(const double *c, int dim, double rtol, double t0,
                      double t1) {
  int e = arclen_check_curve(c, dim);
  if (e) return e;
  if (!(rtol >= ARCLEN_RTOL_MIN && rtol <= ARCLEN_RTOL_MAX))
    return ARCLEN_ETOL;
  if (!(t0 >= 0 && t0 <= 1 && t1 >= 0 && t1 <= 1)) return ARCLEN_ERANGE;
  return ARCLEN_OK;
}

/* x in the integrator's scaled units and local variable as a length of
** the curve: x unit 2^exp, with unit's exponent folded into exp so that
** neither product over- or underflows on the way. */
double arclen_integ_curve_units(const integrator *in, double x) {
  int k;
  double m;
  if (in->unit == 1) return arclen_times_pow2(x, in->h.exp);
  m = frexp(in->unit, &k);
  return ldexp(x * m, in->h.exp + k);
}

void arclen_integ_fill_info(arclen_info *info, const integrator *in, int exp) {
  if (!info) return;
  info->evals = in->evals;
  info->pieces = in->pieces;
  info->depth = in->depth;
  info->err = ldexp(in->err, exp);
  info->branch = NULL;
  info->calls = 0;
}
