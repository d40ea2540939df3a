/*
** segment.c -- segments of four kinds (line, quad, cubic, conic) behind one
** call each: names and letters, checks, and the dispatch by kind of length,
** time, many times, point, derivative, tangent and sub-range.  Cubics go
** to the method asked for (the default method unless told), the other
** kinds to line.c, quad.c and conic_seg.c, a quadratic's time to
** quad_time.c and a conic's to invert.c.
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "arclen.h"
#include "curve/numeric.h"
#include "segment/segment.h"

static const char *const names[ARCLEN_SEG_NKINDS] = {
  "line", "quad", "cubic", "conic"
};
static const char letters[ARCLEN_SEG_NKINDS] = {'L', 'Q', 'C', 'R'};

int arclen_segment_kind(const char *name) {
  int k;
  for (k = 0; name != NULL && k < ARCLEN_SEG_NKINDS; k++)
    if (strcmp(name, names[k]) == 0) return k;
  return -1;
}

int arclen_segment_kind_of_letter(int letter) {
  int k;
  for (k = 0; k < ARCLEN_SEG_NKINDS; k++)
    if (letter == letters[k]) return k;
  return -1;
}

const char *arclen_segment_kind_name(int kind) {
  return kind >= 0 && kind < ARCLEN_SEG_NKINDS ? names[kind] : NULL;
}

int arclen_segment_letter(int kind) {
  return kind >= 0 && kind < ARCLEN_SEG_NKINDS ? letters[kind] : 0;
}

/* arclen_segment_count's body, static so that the check inlines it (the
** call was a twentieth of a quadratic's length). */
static int count_of(int kind, int dim) {
  if (dim != 2 && dim != 3) return 0;
  switch (kind) {
  case ARCLEN_SEG_LINE: return 2 * dim;
  case ARCLEN_SEG_QUAD: return 3 * dim;
  case ARCLEN_SEG_CUBIC: return 4 * dim;
  case ARCLEN_SEG_CONIC: return 3 * dim + 1;
  default: return 0;
  }
}

int arclen_segment_count(int kind, int dim) {
  return count_of(kind, dim);
}

/* arclen_segment_check's body, inlined at the calls below (the call and
** its loop were 61 of a quadratic's 544 instructions). */
static ARCLEN_INLINE int check_segment(int kind, int dim,
                                        const double *seg) {
  double z = 0, z2 = 0;
  if (kind < 0 || kind >= ARCLEN_SEG_NKINDS) return ARCLEN_EDOMAIN;
  if (dim != 2 && dim != 3) return ARCLEN_EDIM;
  /* x - x is 0 for a finite x, NaN for inf and NaN: one test in all, on
  ** two sums (two chains of additions, not one), in straight-line code
  ** entered at the count (a loop over it took 30 instructions of a
  ** quadratic's length) */
  switch (count_of(kind, dim)) {
  case 12: z2 += seg[11] - seg[11];   /* fall through */
  case 11: z += seg[10] - seg[10];    /* fall through */
  case 10: z2 += seg[9] - seg[9];     /* fall through */
  case 9: z += seg[8] - seg[8];       /* fall through */
  case 8: z2 += seg[7] - seg[7];      /* fall through */
  case 7: z += seg[6] - seg[6];       /* fall through */
  case 6: z2 += seg[5] - seg[5];      /* fall through */
  case 5: z += seg[4] - seg[4];       /* fall through */
  case 4: z2 += seg[3] - seg[3];      /* fall through */
  default:
    z += (seg[2] - seg[2]) + (seg[0] - seg[0]);
    z2 += seg[1] - seg[1];
  }
  if (z + z2 != 0) return ARCLEN_EINVAL;
  if (kind == ARCLEN_SEG_CONIC && !(seg[3 * dim] > 0)) return ARCLEN_EINVAL;
  return ARCLEN_OK;
}

int arclen_segment_check(int kind, int dim, const double *seg) {
  return check_segment(kind, dim, seg);
}

/* Whether rtol is one the kinds that are not cubics take. */
static int rtol_ok(double rtol) {
  return rtol >= ARCLEN_RTOL_MIN && rtol <= ARCLEN_RTOL_MAX;
}

/* The options' shared checks for the kinds that are not cubics. */
static int check_opts(const arclen_opts *o) {
  if (!rtol_ok(o->rtol)) return ARCLEN_ETOL;
  if (!(o->t0 >= 0 && o->t0 <= 1 && o->t1 >= 0 && o->t1 <= 1))
    return ARCLEN_ERANGE;
  return ARCLEN_OK;
}

/* The length over [t0, t1] of a segment that is not a cubic. */
static ARCLEN_INLINE int plain_length(int kind, int dim, const double *seg,
                                      double t0, double t1, double *len,
                                      arclen_info *info) {
  int gauss = 0, rc;
  switch (kind) {
  case ARCLEN_SEG_LINE:
    rc = arclen_line_length(seg, dim, t0, t1, len);
    if (info) info->branch = "line";
    return rc;
  case ARCLEN_SEG_QUAD:
    rc = arclen_quad_length(seg, dim, t0, t1, len, &gauss);
    if (info) {
      info->branch = gauss ? "quad-gauss" : "quad";
      info->evals += gauss ? 10 : 0;
    }
    return rc;
  default:
    return arclen_rquad_length(seg, dim, t0, t1, len, info);
  }
}

int arclen_segment_length(int kind, int dim, const double *seg,
                          const arclen_method *m, const arclen_opts *o,
                          double *len, arclen_info *info) {
  arclen_opts def;
  int rc;
  *len = NAN;
  if (info) arclen_info_init(info);
  if (o == NULL) { arclen_opts_init(&def); o = &def; }
  rc = check_segment(kind, dim, seg);
  if (rc != ARCLEN_OK) return rc;
  if (kind == ARCLEN_SEG_CUBIC)
    return m ? m->length(seg, dim, o, len, info)
             : arclen_length_gauss(seg, dim, o, len, info);
  rc = check_opts(o);
  if (rc != ARCLEN_OK) return rc;
  rc = plain_length(kind, dim, seg, o->t0, o->t1, len, info);
  if (rc != ARCLEN_OK) *len = NAN;
  return rc;
}

/* What invert.c needs of a segment: the segment, and for the speed its
** legs a = P1 - P0, c = P2 - P1, k = P2 - P0 and weight (plain_time has
** brought the points within 2^+-500, so no leg overflows and no square
** of one leaves the double range). */
typedef struct seg_ctx {
  int kind, dim;
  const double *seg;
  double a[3], c[3], k[3], w;
  double inv_w, sqrt_w;            /* 1/w and sqrt(w), for w > 1 */
} seg_ctx;

static int len_to(const void *ctx, double t, double *len) {
  const seg_ctx *c = (const seg_ctx *)ctx;
  return plain_length(c->kind, c->dim, c->seg, 0, t, len, NULL);
}

/* The speed |C'(t)| for Newton's step and invert.c's model: a conic's 2
** |w (1-t)^2 a + t (1-t) k + w t^2 c| / D^2, D = (1-t)^2 + 2 w t (1-t) +
** t^2 (the quotient rule, t^3 terms cancelled), both divided by w when w
** > 1 so that w a stays finite.  A speed that overflows anyway (w near
** DBL_MAX) only makes invert.c bisect: every answer is certified by an
** exact length. */
static double speed_at(const void *ctx, double t) {
  const seg_ctx *c = (const seg_ctx *)ctx;
  double s = 1 - t, n2 = 0, x[3], D, wa, ts, wc;
  int i;
  if (c->w <= 1) {
    wa = c->w * s * s; ts = t * s; wc = c->w * t * t;
    for (i = 0; i < c->dim; i++) x[i] = wa * c->a[i] + ts * c->k[i] + wc * c->c[i];
    D = s * s + 2 * c->w * ts + t * t;
  } else {
    double v = c->inv_w;
    ts = t * s;
    for (i = 0; i < c->dim; i++)
      x[i] = s * s * c->a[i] + ts * v * c->k[i] + t * t * c->c[i];
    D = (s * s + t * t) * v + 2 * ts;       /* D / w */
    D *= c->sqrt_w;                         /* D^2 w */
  }
  for (i = 0; i < c->dim; i++) n2 += x[i] * x[i];
  /* the squares leave the normal range (w = 9e-13 beside legs of 1e-151
  ** gave a speed of 0 over a third of the arc, and the Gauss model's
  ** bound rests on the speed's own few roundings): the norm by hypot.
  ** Above 2^-960 the largest square is normal and what underflowed is
  ** below 2^-60 of it */
  if (!(n2 > 0x1p-960 && n2 < 0x1p960))
    n2 = c->dim == 2 ? hypot(x[0], x[1]) : hypot(hypot(x[0], x[1]), x[2]);
  else
    n2 = sqrt(n2);
  return 2 * n2 / (D * D);
}

/* The n-point Gauss-Legendre rule's error for a conic's speed over [a, b]
** (Trefethen, "Approximation Theory and Approximation Practice", Thm
** 19.3, whose rule has n + 1 points): |E| <= (64/15) h M rho^-2n / (1 -
** rho^-2), h = (b - a)/2, for a speed analytic in the Bernstein ellipse
** E_rho of [a, b] and bounded by M there.  E_rho lies in the disc |z - m|
** <= R (m the middle) when its semi-major axis h (rho + 1/rho)/2 is R.
** The speed is 2 sqrt(Q)/D^2 (over w when w > 1, as speed_at), Q = N.N
** with N(t) = w a + (k - 2 w a) t + (w (a + c) - k) t^2 and D = 1 + 2 (w -
** 1) t (1 - t).  N(t) lies in the conic's plane, so in an orthonormal
** basis of it Q = (N1 + i N2)(N1 - i N2) = P(z) P(conj z)^*, P a complex
** quadratic whose Taylor coefficients at m have the sizes |P_k| = |N_k|
** (N's Taylor coefficients, Euclidean norms; no basis needed).  So in the
** disc |P| >= |N_0| - |N_1| R - |N_2| R^2 and |P| <= |N_0| + |N_1| R +
** |N_2| R^2 (both for z and conj z), likewise for D's real coefficients:
** R is taken where the lower bounds keep THETA of their values at m, so
** that neither P nor D vanishes there (sqrt(Q) analytic, the disc simply
** connected) and M <= 2 Pmax / Dmin^2.  HUGE_VAL where R <= h (no
** ellipse) or the speed is 0 at m.  Plus the rounding of the nodes
** (below).  Conics only (ctx: segment.c's seg_ctx). */
#define THETA 0.9
/* The bound's parts for [a, b]: error(n) = *c rho^-2n + *rnd (the
** truncation, and the nodes' rounding below).  0 where there is none. */
typedef struct rule_disc { double c, rho, rnd; } rule_disc;

static int conic_disc(const seg_ctx *c, double a, double b, rule_disc *out) {
  double m = (a + b) / 2, h = fabs(b - a) / 2, w = c->w, v = w > 1 ? 1 / w : 1;
  double p0 = 0, p1 = 0, p2 = 0, d0, d1, d2, x, r, rd, pmax, dmin, rho, M;
  double delta = DBL_EPSILON * (fabs(m) + h);   /* the nodes' rounding */
  int i;
  for (i = 0; i < c->dim; i++) {
    /* N's Taylor coefficients at m (divided by w when w > 1) from its
    ** Bernstein form, as speed_at: the monomial coefficients cancel near
    ** t = 1 (their sum is c, beside a and k/w) */
    double wa = w * v * c->a[i], wc = w * v * c->c[i], kk = v * c->k[i];
    double sm = 1 - m;
    double N0 = sm * sm * wa + m * sm * kk + m * m * wc;
    double N1 = -2 * sm * wa + (sm - m) * kk + 2 * m * wc, N2 = wa + wc - kk;
    p0 += N0 * N0; p1 += N1 * N1; p2 += N2 * N2;
  }
  /* D (over w when w > 1) at m: d0 + d1 z + d2 z^2, its sizes */
  x = 2 * (w - 1) * v;
  d0 = v + x * m * (1 - m); d1 = fabs(x * (1 - 2 * m)); d2 = fabs(x);
  /* squares out of the normal range (tiny or huge legs, w near 0 or
  ** DBL_MAX) leave the coefficients without their digits: no bound */
  if (!(p0 > 0x1p-900 && p0 < 0x1p900) || !(d0 > 0x1p-400)) return 0;
  p0 = sqrt(p0); p1 = sqrt(p1); p2 = sqrt(p2);
  /* the R where p1 R + p2 R^2 = THETA p0 (the root without cancellation),
  ** and D's */
  r = 2 * THETA * p0 / (p1 + sqrt(p1 * p1 + 4 * THETA * p0 * p2));
  rd = 2 * THETA * d0 / (d1 + sqrt(d1 * d1 + 4 * THETA * d0 * d2));
  if (rd < r) r = rd;
  /* the rounded nodes and ends lie within h + delta of m: the disc holds
  ** them with room for Cauchy's slope estimate (w = 1e30: a piece [1 -
  ** 3.3e-16, 1] has m 5.5e-17 off, past r - h, and its rule missed the
  ** last leg, 2.2 of a length 5.4, under a bound of 6e-12) */
  if (!(r > h * 1.0001 + 2 * delta)) return 0;
  if (r > 1e6 * h) r = 1e6 * h;     /* rho^-2n is 0 long before */
  pmax = p0 + r * (p1 + r * p2);
  dmin = d0 - r * (d1 + r * d2);    /* >= (1 - THETA) d0 */
  x = r / h;
  rho = x + sqrt((x - 1) * (x + 1));
  M = 2 * pmax / (dmin * dmin) / (w > 1 ? w : 1);
  out->rho = rho;
  out->c = 64.0 / 15 * h * M / ((1 - 1 / rho) * (1 + 1 / rho));
  /* besides the truncation, the nodes' rounding: each m +- h x_i is off
  ** by up to delta = eps (|m| + h), where the speed's slope is at most M
  ** / (r - h - delta) (Cauchy's estimate in the disc); the weights sum to
  ** 2 (w = 468 near t = 1: 5e-14 relative of a 10-node rule over 1.8e-4,
  ** the truncation 1e-19) */
  out->rnd = 2 * h * M / (r - h - delta) * delta;
  return 1;
}

static double conic_rule_error(const void *ctx, double a, double b, int n) {
  rule_disc d;
  double x;
  int k;
  if (a == b) return 0;
  if (!conic_disc((const seg_ctx *)ctx, a, b, &d)) return HUGE_VAL;
  for (x = 1, k = 0; k < n; k++) x /= d.rho * d.rho;    /* rho^-2n */
  return d.c * x + d.rnd;
}

/* The fewest nodes, up to max, whose rule over [a, b] errs by at most
** target by conic_rule_error's bound (*err: that bound); 0 when none. */
static int conic_rule_order(const void *ctx, double a, double b,
                            double target, int max, double *err) {
  rule_disc d;
  double room, x;
  int n, k;
  if (!conic_disc((const seg_ctx *)ctx, a, b, &d)) return 0;
  room = target - d.rnd;
  if (!(room > 0)) return 0;
  /* c rho^-2n <= room: n >= log(c / room) / (2 log rho), then checked
  ** by the product itself (the logs' rounding) */
  x = log(d.c / room) / (2 * log(d.rho));
  n = x < 1 ? 1 : x < max ? (int)ceil(x) : max + 1;
  if (n > max) return 0;
  for (x = 1, k = 0; k < n; k++) x /= d.rho * d.rho;
  if (d.c * x > room) {
    if (n == max) return 0;
    n++;
    x /= d.rho * d.rho;
  }
  *err = d.c * x + d.rnd;
  return n;
}

/* The first t tried for the length fraction u: the conic's parameter
** angle.  The rational quadratic (P0, P1, P2; w = cos al) traces a circle
** of half-angle al as tan(phi/2) = (2t - 1) tan(al/2), phi in [-al, al]
** (the tangent half-angle form), so for a circle the length fraction u
** gives phi = al (2u - 1) and t exactly; an ellipse is an affine image of
** such a circle and a hyperbola (w = cosh be) its tanh analogue, where the
** same angle is a fair guess.  Quadratics (and w near 1): u itself. */
static double first_guess(int kind, int dim, const double *seg, double u) {
  double w, v = 2 * u - 1;
  if (kind != ARCLEN_SEG_CONIC) return u;
  w = seg[3 * dim];
  if (w < 1 - 0x1p-20) {
    double al = acos(w);
    return 0.5 + 0.5 * tan(al * v / 2) / tan(al / 2);
  }
  if (w > 1 + 0x1p-20 && w < 1e300) {
    double be = acosh(w);
    return 0.5 + 0.5 * tanh(be * v / 2) / tanh(be / 2);
  }
  return u;
}

/* Whether the conic may be a circular arc (|a| = |c| and w = |k| / (2
** |a|), the cosine of the angle between leg and chord, within 2^-20):
** those keep the angle's first guess, exact for a circle, and the
** circle's closed-form length (plain_times), so that a circle's times stay
** its angle parameter. */
static int near_circle(const seg_ctx *c) {
  double la = 0, lc = 0, lk = 0;
  int k;
  for (k = 0; k < c->dim; k++) {
    la += c->a[k] * c->a[k];
    lc += c->c[k] * c->c[k];
    lk += c->k[k] * c->k[k];
  }
  la = sqrt(la);
  lc = sqrt(lc);
  lk = sqrt(lk);
  return c->w < 1 && fabs(la - lc) <= 0x1p-20 * la &&
         fabs(2 * c->w * la - lk) <= 0x1p-20 * lk;
}

/* A lower bound of the conic's length from lenx <= len(0, x): lenx plus
** the chord from C(x) to P2, which the arc over [x, 1] is at least (the
** inscribed polygon's bound, as quad_time.c's length_below for a
** quadratic).  The chord is P2 - C(x) = ((1-x)^2 k + 2 w x (1-x) c) / D
** from the legs (no points subtracted; over w when w > 1, as speed_at):
** positive coefficients, each component within 7 eps of its terms' sizes
** with the legs' own roundings, so less 16 eps of their sum (mag), and
** its norm and quotient within a few eps more; 0 where the squares leave
** the normal range.  All less 2^-30 of itself, which covers lenx's own
** rounding where it is an exact length (Carlson's, within a few ulps). */
static double conic_below(const void *ctx, double x, double lenx) {
  const seg_ctx *c = (const seg_ctx *)ctx;
  double s = 1 - x, p, q, D, n2 = 0, mag = 0, chord = 0;
  int i;
  if (c->w <= 1) { p = s * s; q = 2 * c->w * x * s; D = s * s + q + x * x; }
  else { p = s * s * c->inv_w; q = 2 * x * s; D = (s * s + x * x) * c->inv_w + q; }
  for (i = 0; i < c->dim; i++) {
    double v = p * c->k[i] + q * c->c[i];
    n2 += v * v;
    mag += p * fabs(c->k[i]) + q * fabs(c->c[i]);
  }
  if (n2 > 0x1p-960 && n2 < 0x1p960)
    chord = (sqrt(n2) - 16 * DBL_EPSILON * mag) / D * (1 - 8 * DBL_EPSILON);
  return (lenx + (chord > 0 ? chord : 0)) * (1 - 0x1p-30);
}

/* A conic's first t for the distance s: the cubic Hermite interpolant of
** its length from 0 and total and the speeds at the ends, inverted by two
** Newton steps from the angle's guess (first_guess), which alone errs by
** up to a third of t where the middle control point stands off the
** chord's middle; a circle's is the angle's, exact. */
static double conic_guess(const seg_ctx *c, double total, double s) {
  double u = first_guess(ARCLEN_SEG_CONIC, c->dim, c->seg, s / total);
  if (near_circle(c)) return u;
  return arclen_hermite_invert(total, speed_at(c, 0), speed_at(c, 1), s, u, 2);
}

/* invert.c's context for a conic: seg,
** or its copy scaled by 2^-e into `scaled` where its points lie far from 1
** (subnormal lengths come in steps of 2^-1074; exact but for parts below
** 2^-1022 of the largest), and its legs.  A conic whose legs are below
** 2^-500 while its points are not (far smaller than its distance from the
** origin) is moved to P0 = 0 first, so that its legs are not subnormal:
** each difference from P0 is exact (Sterbenz) or one rounding of a tiny
** one, as the legs themselves.  Returns e. */
static int setup_ctx(int kind, int dim, const double *seg, double *scaled,
                     seg_ctx *c) {
  double mx = 0, ml = 0;
  int i, e = 0, moved;
  int n = arclen_segment_count(kind, dim) - (kind == ARCLEN_SEG_CONIC);
  c->kind = kind; c->dim = dim; c->seg = seg;
  for (i = 0; i < n; i++) {
    mx = fmax(mx, fabs(seg[i]));
    ml = fmax(ml, fabs(seg[i] - seg[i % dim]));       /* |P_j - P0| */
  }
  moved = ml > 0 && ml < 0x1p-500 && mx >= 0x1p-500;
  if (moved || (mx > 0 && (mx < 0x1p-500 || mx > 0x1p500))) {
    frexp(moved ? ml : mx, &e);
    for (i = 0; i < n; i++)
      scaled[i] = ldexp(moved ? seg[i] - seg[i % dim] : seg[i], -e);
    if (kind == ARCLEN_SEG_CONIC) scaled[n] = seg[n];
    c->seg = scaled;
  }
  for (i = 0; i < dim; i++) {
    c->a[i] = c->seg[dim + i] - c->seg[i];
    c->c[i] = c->seg[2 * dim + i] - c->seg[dim + i];
    c->k[i] = c->seg[2 * dim + i] - c->seg[i];
  }
  c->w = kind == ARCLEN_SEG_CONIC ? c->seg[3 * dim] : 1;
  c->inv_w = 1 / c->w;               /* once, not at every speed */
  c->sqrt_w = sqrt(c->w);
  return e;
}

/* The time at s on the conic of c (scaled by 2^-e) whose length is *total
** in c's units (NAN: unknown, measured by the search where it needs it and
** stored), from the known point from = (t, len(0, t), its error bound) at
** or before it ({0, 0, 0}: afresh), which becomes the answer's.  A first
** search without the total guesses from TOTAL_NODES' rule of it
** (uncertified: the guess only) and takes its tol from conic_below's lower
** bounds (invert.c), so that the total's exact length (Carlson's
** integrals, as much as the search's own) is off its chain.  A line is t =
** s / L. */
#define TOTAL_NODES 6
static int ctx_time(int kind, const seg_ctx *c, int e, double *total,
                    double s, double rtol, double from[3], double *t,
                    long *evals) {
  double guess, at[3], T = *total;
  int rc;
  if (kind == ARCLEN_SEG_LINE) {     /* t uniform: s(t) = t L */
    *t = !(s > 0) ? 0 : !(s < T) ? 1 : s / T;
    from[0] = *t; from[1] = *t * T; from[2] = 0;
    if (evals) *evals = 0;
    return ARCLEN_OK;
  }
  at[0] = from[0]; at[1] = from[1]; at[2] = from[2];
  if (e != 0) {
    s = ldexp(s, -e);
    at[1] = ldexp(at[1], -e); at[2] = ldexp(at[2], -e);
  }
  if (at[0] == 0) {
    guess = conic_guess(c, isnan(T) ? arclen_seg_rule(speed_at, c, TOTAL_NODES, 0, 1)
                                    : T, s);
  } else {                           /* Newton's step from the last answer */
    double d = speed_at(c, at[0]);
    guess = d > 0 ? at[0] + (s - at[1]) / d : -1;
  }
  /* the model pays where an exact length costs Carlson's integrals (a
  ** conic, ~600 ns) */
  rc = arclen_seg_invert(len_to, speed_at, conic_rule_error,
                         conic_rule_order, conic_below, c, &T, s, rtol, NAN,
                         guess, at, t, evals);
  if (isnan(*total) && !isnan(T)) *total = T;
  from[0] = at[0]; from[1] = e ? ldexp(at[1], e) : at[1];
  from[2] = e ? ldexp(at[2], e) : at[2];
  return rc;
}

/* A conic's times at the ascending s[0 .. n-1] (scaled by 2^-e as c) from
** its cover (arclen_seg_cover): pieces of [0, 1] whose rules the bound
** certifies, in all within a quarter of rtol times the chord (a lower
** bound of the length, so of rtol L / 4).  Their sums give the length
** and, at each piece's start, a certified length from which the search
** of a distance inside it starts (or from the last answer, where later),
** from the Hermite guess inside the piece: no exact length, unless a
** search's own models fail.  0 where the cover fails (a conic too sharp
** for the bound within 2^CONIC_COVER_DEPTH pieces): the caller then
** measures the length and searches as plain_times does. */
#define CONIC_COVER_DEPTH 5
static int conic_times(const seg_ctx *c, int e, const double *s, long n,
                       double rtol, double *t, long *evals, int *rc) {
  arclen_seg_piece pc[1 << CONIC_COVER_DEPTH];
  double cum[(1 << CONIC_COVER_DEPTH) + 1], cerr[(1 << CONIC_COVER_DEPTH) + 1];
  double chord = 0, total, terr, tol, from[3] = {0, 0, 0}, fa = 0, fb = 0;
  int np = 0, i, k, at = -1;
  long j, ev;
  if (rtol < ARCLEN_SEG_COVER_RTOL) return 0;
  for (k = 0; k < c->dim; k++) chord += c->k[k] * c->k[k];
  chord = sqrt(chord);
  if (!(chord > 0) || near_circle(c) ||
      !arclen_seg_cover(speed_at, conic_rule_order, c, 0, 1, rtol * chord / 4,
                        CONIC_COVER_DEPTH, pc, &np))
    return 0;
  cum[0] = cerr[0] = 0;
  for (i = 0; i < np; i++) {
    cum[i + 1] = cum[i] + pc[i].v;
    cerr[i + 1] = cerr[i] + pc[i].e + 2 * DBL_EPSILON * cum[i + 1];
  }
  total = cum[np];
  terr = cerr[np];
  tol = rtol * (total - terr);       /* <= rtol L */
  if (!(terr <= tol / 4)) return 0;
  *rc = ARCLEN_OK;
  if (evals) *evals = 0;
  for (i = 0, j = 0; j < n; j++) {
    double sj = e ? ldexp(s[j], -e) : s[j], guess;
    if (!(sj > 0)) { t[j] = 0; continue; }
    /* s >= L, or within tol of it (terr <= tol/4): the end */
    if (sj >= total + terr - tol) { t[j] = 1; continue; }
    while (i < np - 1 && sj >= cum[i + 1]) i++;
    if (from[0] < pc[i].a || from[1] > sj) {
      double w = pc[i].b - pc[i].a, u;
      if (at != i) { fa = speed_at(c, pc[i].a); fb = speed_at(c, pc[i].b); at = i; }
      from[0] = pc[i].a; from[1] = cum[i]; from[2] = cerr[i];
      u = arclen_hermite_invert(pc[i].v, fa * w, fb * w, sj - cum[i],
                                (sj - cum[i]) / pc[i].v, 2);
      guess = pc[i].a + w * u;
    } else {                         /* Newton's step from the last answer */
      double d = speed_at(c, from[0]);
      guess = d > 0 ? from[0] + (sj - from[1]) / d : -1;
    }
    *rc = arclen_seg_invert(len_to, speed_at, conic_rule_error,
                            conic_rule_order, conic_below, c, &total, sj, rtol,
                            tol, guess, from, t + j, &ev);
    if (evals) *evals += ev;
    if (*rc != ARCLEN_OK) return 1;
  }
  return 1;
}

/* The times of the ascending s[0 .. n-1] on a quadratic set up as f, whose
** length is total (NAN: the form's own, measured where a search needs it),
** each search from the last one's answer: quad_time.c. */
static int quad_times(const arclen_quad_form *f, double total,
                      const double *s, long n, double rtol, double *t,
                      long *evals) {
  double from[3] = {0, 0, 0};
  long i, ev;
  if (evals) *evals = 0;
  for (i = 0; i < n; i++) {
    int rc = arclen_quad_time(f, &total, s[i], rtol, from, t + i, &ev);
    if (rc != ARCLEN_OK) return rc;
    if (evals) *evals += ev;
  }
  return ARCLEN_OK;
}

/* The times of the ascending s[0 .. n-1] on a segment that is not a cubic,
** whose length is total (NAN: measured where needed -- a line's and a
** circle's here, another conic's by its searches, the first of which
** needs none), in one sweep: each search starts where the last one ended
** (its time and certified length); a conic's from its cover where it has
** one (conic_times). */
static int plain_times(int kind, int dim, const double *seg, double total,
                       const double *s, long n, double rtol, double *t,
                       long *evals) {
  seg_ctx c;
  double scaled[ARCLEN_SEG_MAXN], from[3] = {0, 0, 0};
  long i, ev;
  int rc, e;
  if (kind == ARCLEN_SEG_QUAD) {
    arclen_quad_form f;
    arclen_quad_setup(seg, dim, &f);
    return quad_times(&f, total, s, n, rtol, t, evals);
  }
  e = kind == ARCLEN_SEG_LINE ? 0 : setup_ctx(kind, dim, seg, scaled, &c);
  if (kind == ARCLEN_SEG_CONIC && conic_times(&c, e, s, n, rtol, t, evals, &rc))
    return rc;
  /* a conic's total where the search needs it (ctx_time), but now a
  ** circle's (its closed form is cheap, and its guess, the angle's,
  ** exact); in the units of c, which are 2^-e of the conic's where its
  ** points lie beyond 2^+-500: a conic whose length overflows still has
  ** its times, those of the conic scaled down, bit for bit (a line's
  ** length overflows: ARCLEN_EOVERFLOW) */
  if (total > 0 && isfinite(total)) {
    if (e != 0) total = ldexp(total, -e);
  } else {
    total = NAN;
    if (kind == ARCLEN_SEG_LINE || near_circle(&c)) {
      rc = plain_length(kind, dim, kind == ARCLEN_SEG_LINE ? seg : c.seg, 0,
                        1, &total, NULL);
      if (rc != ARCLEN_OK) return rc;
    }
  }
  if (evals) *evals = 0;
  for (i = 0; i < n; i++) {
    rc = ctx_time(kind, &c, e, &total, s[i], rtol, from, t + i, &ev);
    if (rc != ARCLEN_OK) return rc;
    if (evals) *evals += ev;
  }
  return ARCLEN_OK;
}

/* A quadratic's time at s: the set-up and one search (its total, where
** it needs one, arclen_quad_length's over [0, 1]). */
static int quad_time(int dim, const double *seg, double s, double rtol,
                     double *t, arclen_info *info) {
  arclen_quad_form f;
  double total = NAN, from[3] = {0, 0, 0};
  long evals = 0;
  int gauss, rc;
  arclen_quad_setup(seg, dim, &f);
  rc = arclen_quad_time(&f, &total, s, rtol, from, t, &evals);
  if (info) {
    gauss = arclen_quad_form_gauss(&f);
    info->branch = gauss ? "quad-gauss" : "quad";
    info->evals += gauss ? 10 : 0;
    info->pieces = evals;
  }
  return rc;
}

int arclen_segment_time(int kind, int dim, const double *seg, double s,
                        const arclen_method *m, const arclen_opts *o,
                        double *t, arclen_info *info) {
  arclen_opts def;
  double total;
  long evals = 0;
  int rc;
  *t = NAN;
  if (info) arclen_info_init(info);
  if (o == NULL) { arclen_opts_init(&def); o = &def; }
  rc = check_segment(kind, dim, seg);
  if (rc != ARCLEN_OK) return rc;
  if (isnan(s)) return ARCLEN_EINVAL;
  if (kind == ARCLEN_SEG_CUBIC) {
    if (m == NULL) return arclen_time_gauss(seg, dim, s, o, t, info);
    if (m->time == NULL) return ARCLEN_EDOMAIN;
    return m->time(seg, dim, s, o, t, info);
  }
  /* check_opts' order: rtol first, then the range (here [0, 1] only) */
  if (!rtol_ok(o->rtol)) return ARCLEN_ETOL;
  if (o->t0 != 0 || o->t1 != 1) return ARCLEN_ERANGE;
  if (kind == ARCLEN_SEG_QUAD) {
    rc = quad_time(dim, seg, s, o->rtol, t, info);
    if (rc != ARCLEN_OK) *t = NAN;
    return rc;
  }
  if (kind == ARCLEN_SEG_CONIC) total = NAN;   /* its cover's (conic_times) */
  else rc = plain_length(kind, dim, seg, 0, 1, &total, info);
  if (rc == ARCLEN_OK)
    rc = plain_times(kind, dim, seg, total, &s, 1, o->rtol, t, &evals);
  if (info) info->pieces = evals;
  if (rc != ARCLEN_OK) *t = NAN;
  return rc;
}

int arclen_segment_times(int kind, int dim, const double *seg,
                         const double *s, long n, double rtol, double *t,
                         double *pts, double *tan) {
  return arclen_segment_times_of(kind, dim, seg, NAN, s, n, rtol, t, pts, tan);
}

int arclen_segment_times_of(int kind, int dim, const double *seg,
                            double len, const double *s, long n, double rtol,
                            double *t, double *pts, double *tan) {
  double prev = -HUGE_VAL;
  long i;
  int rc = check_segment(kind, dim, seg);
  if (rc != ARCLEN_OK) return rc;
  if (kind == ARCLEN_SEG_CUBIC)
    return arclen_times(seg, dim, s, n, rtol, t, pts, tan);
  if (n < 0) return ARCLEN_EDOMAIN;
  if (!rtol_ok(rtol)) return ARCLEN_ETOL;
  for (i = 0; i < n; i++) {
    if (isnan(s[i])) {
      for (i = 0; i < n; i++) t[i] = NAN;
      return ARCLEN_EINVAL;
    }
    if (s[i] < prev) return ARCLEN_EDOMAIN;
    prev = s[i];
  }
  if (n == 0) return ARCLEN_OK;
  /* the caller's length where it has one (a path's), else measured: the
  ** searches use it for their scale and first guesses, and certify with
  ** exact lengths of their own */
  rc = plain_times(kind, dim, seg, len, s, n, rtol, t, NULL);
  if (rc != ARCLEN_OK) return rc;
  for (i = 0; i < n; i++) {
    if (pts) arclen_segment_point(kind, dim, seg, t[i], pts + dim * i);
    if (tan) arclen_segment_unit_tangent(kind, dim, seg, t[i], tan + dim * i);
  }
  return ARCLEN_OK;
}

void arclen_segment_point(int kind, int dim, const double *seg, double t,
                          double *p) {
  switch (kind) {
  case ARCLEN_SEG_LINE: arclen_line_point(seg, dim, t, p); break;
  case ARCLEN_SEG_QUAD: arclen_quad_point(seg, dim, t, p); break;
  case ARCLEN_SEG_CUBIC: arclen_point(seg, dim, t, p); break;
  default: arclen_rquad_point(seg, dim, t, p); break;
  }
}

/* seg's points scaled by 2^-e into copy when they lie beyond 2^+-500
** (e = 0 and a plain copy otherwise): differences of points near DBL_MAX
** then neither overflow nor meet inf - inf.  Returns e. */
static int scaled_copy(int kind, int dim, const double *seg, double *copy) {
  int i, e = 0, n = arclen_segment_count(kind, dim);
  int np = kind == ARCLEN_SEG_CONIC ? n - 1 : n;
  double mx = 0;
  for (i = 0; i < np; i++) mx = fmax(mx, fabs(seg[i]));
  if (mx > 0x1p500 || (mx > 0 && mx < 0x1p-500)) frexp(mx, &e);
  for (i = 0; i < n; i++) copy[i] = i < np ? ldexp(seg[i], -e) : seg[i];
  return e;
}

void arclen_segment_derivative(int kind, int dim, const double *seg,
                               double t, double *d) {
  double c[ARCLEN_SEG_MAXN];
  int k, e;
  if (kind == ARCLEN_SEG_CUBIC) { arclen_derivative(seg, dim, t, d); return; }
  e = scaled_copy(kind, dim, seg, c);
  switch (kind) {
  case ARCLEN_SEG_LINE: arclen_line_derivative(c, dim, d); break;
  case ARCLEN_SEG_QUAD: arclen_quad_derivative(c, dim, t, d); break;
  default: arclen_rquad_derivative(c, dim, t, d); break;
  }
  for (k = 0; e != 0 && k < dim; k++) d[k] = ldexp(d[k], e);
}

/* v / |v| into v, or 0 (v zero); returns the norm. */
static double normalize(double *v, int dim) {
  double n = arclen_seg_norm(v, dim);
  int k;
  for (k = 0; k < dim; k++) v[k] = n > 0 ? v[k] / n : 0;
  return n;
}

/* A conic's unit tangent at t: the direction of the derivative's
** numerator n(t) = w (1-t)^2 a + t (1-t) k + w t^2 c (a = P1 - P0, c = P2
** - P1, k = P2 - P0; D(t)^2 > 0 only scales it), over w where w > 1 so
** that no term overflows (D^2 did from w ~ 1e154: the tangent was 0, then
** a direction the curve never has).  Where n vanishes, its derivative's
** direction (negated at t = 1), then its second derivative's. */
static void conic_direction(const double *seg, int dim, double t, double *v) {
  double w = seg[3 * dim], s = 1 - t, f = w > 1 ? w : 1;
  double wf = w / f, kf = 1 / f;                  /* w/f and 1/f: one is 1 */
  double a[3], c[3], kk[3];
  int k;
  for (k = 0; k < dim; k++) {
    a[k] = seg[dim + k] - seg[k];
    c[k] = seg[2 * dim + k] - seg[dim + k];
    kk[k] = seg[2 * dim + k] - seg[k];
    v[k] = wf * (s * s * a[k] + t * t * c[k]) + kf * (t * s) * kk[k];
  }
  if (normalize(v, dim) > 0) return;
  for (k = 0; k < dim; k++) {
    v[k] = 2 * wf * (t * c[k] - s * a[k]) + kf * (1 - 2 * t) * kk[k];
    if (t == 1) v[k] = -v[k];
  }
  if (normalize(v, dim) > 0) return;
  for (k = 0; k < dim; k++) v[k] = wf * (a[k] + c[k]) - kf * kk[k];
  normalize(v, dim);
}

void arclen_segment_unit_tangent(int kind, int dim, const double *seg0,
                                 double t, double *v) {
  double seg[ARCLEN_SEG_MAXN];
  int k;
  if (kind == ARCLEN_SEG_CUBIC) { arclen_unit_tangent(seg0, dim, t, v); return; }
  scaled_copy(kind, dim, seg0, seg);     /* a direction: the scale is free */
  if (kind == ARCLEN_SEG_CONIC) {
    conic_direction(seg, dim, t, v);
    return;
  }
  arclen_segment_derivative(kind, dim, seg, t, v);
  if (normalize(v, dim) > 0 || kind == ARCLEN_SEG_LINE) return;
  if (kind == ARCLEN_SEG_QUAD) {
    /* v(t) = 0 at t: the direction on leaving is b (arriving at t = 1,
    ** the motion is along -b), b = P2 - 2 P1 + P0 */
    for (k = 0; k < dim; k++) {
      v[k] = seg[2 * dim + k] - 2 * seg[dim + k] + seg[k];
      if (t == 1) v[k] = -v[k];
    }
    normalize(v, dim);
    return;
  }
}

void arclen_segment_sub(int kind, int dim, const double *seg, double t0,
                        double t1, double *out) {
  switch (kind) {
  case ARCLEN_SEG_LINE: arclen_line_sub(seg, dim, t0, t1, out); break;
  case ARCLEN_SEG_QUAD: arclen_quad_sub(seg, dim, t0, t1, out); break;
  case ARCLEN_SEG_CUBIC: arclen_subcurve(seg, dim, t0, t1, out); break;
  default: arclen_rquad_sub(seg, dim, t0, t1, out); break;
  }
}
