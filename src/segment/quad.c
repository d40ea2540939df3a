/*
** quad.c -- the quadratic Bezier P0 P1 P2: B'(t) = 2 v(t), v = a + t b, a =
** P1 - P0, b = c - a, c = P2 - P1, so the length over [t0, t1] is
** 2 int |v| dt, a sqrt/log closed form (the parabola's).  Written on
** u = v.b (|b| times the run along b) and k = |a x c| (|b| times the
** distance of the line of v from the origin), with |v| itself at the ends,
** every term is a sum of positive parts, and u1 - u0 is set to (t1 - t0)
** |b|^2 so the vertex's place cannot drift.  Where |b| is small against
** min |v| (a nearly straight segment, control point near the chord's
** middle) the closed form would divide small differences by |b|: there a
** 10-point Gauss rule, whose error is provably far below an ulp (see
** near_straight()).
*/
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "arclen.h"
#include "curve/numeric.h"
#include "segment/segment.h"

/* The set-up and a span's length each have two callers (a sub-range's
** length and the time) and must give both the same bits: one body each,
** not inlined, so that no compiler contracts their products differently
** at two sites (clang -ffp-contract=fast did: a time at L read 1 -
** 2^-50).  The whole length, inlined for speed (arclen_quad_whole), is
** the time's total too, so it needs no twin. */
#define ONE_BODY ARCLEN_NOINLINE

/* The 10-point Gauss-Legendre rule on [0, 1], nodes x < 1/2 and their
** weights (the other five mirror them). */
static const double gl10[5][2] = {
  {0.013046735741414139961, 0.0333356721543440687968},
  {0.067468316655507744634, 0.0747256745752902965729},
  {0.160295215850487796883, 0.109543181257991021998},
  {0.2833023029353764046, 0.134633359654998177546},
  {0.425562830509184394558, 0.147762112357376435087}
};

static double dot(const double *u, const double *v, int dim) {
  double s = u[0] * v[0] + u[1] * v[1];
  return dim == 3 ? s + u[2] * v[2] : s;
}

/* |v| of the scaled vectors below (components at most 1, so the squares
** neither overflow nor, where they matter, underflow): sqrt of the sum,
** within an ulp and a half, at a third of hypot's cost. */
static double norm(const double *v, int dim) {
  return sqrt(dot(v, v, dim));
}

/* |u x v| (2D: the scalar cross product's size). */
static ARCLEN_INLINE double cross_norm(const double *u, const double *v,
                                       int dim) {
  double w[3];
  if (dim == 2) return fabs(u[0] * v[1] - u[1] * v[0]);
  w[0] = u[1] * v[2] - u[2] * v[1];
  w[1] = u[2] * v[0] - u[0] * v[2];
  w[2] = u[0] * v[1] - u[1] * v[0];
  return norm(w, 3);
}

/* v(t) = (1 - t) a + t c: a and c exactly at the ends (1 a + 0 c, 0 a +
** 1 c, for finite a and c). */
static void speed_vector(const double *a, const double *c, int dim, double t,
                         double *v) {
  double s = 1 - t;            /* unrolled: dim is 2 or 3 */
  v[0] = s * a[0] + t * c[0];
  v[1] = s * a[1] + t * c[1];
  if (dim == 3) v[2] = s * a[2] + t * c[2];
}

/* The largest leg component that the set-up takes as it is (setup_dim). */
#define UNSCALED 0x1p100

/* 2^e for e in [-1022, 1023], from its bits (ldexp costs a call and a
** rounding-mode-proof path that exact powers of two do not need). */
static double pow2(int e) {
  uint64_t bits = (uint64_t)(e + 1023) << 52;
  double v;
  memcpy(&v, &bits, sizeof v);
  return v;
}

/* The exponent e of x = f 2^e, f in [1/2, 1), for x > 0 (frexp's), from
** the bits where x is normal: frexp is a call on the closed form's chain. */
static int exponent_of(double x) {
  uint64_t bits;
  int e;
  memcpy(&bits, &x, sizeof bits);
  if ((bits >> 52) & 0x7ff) return (int)((bits >> 52) & 0x7ff) - 1022;
  frexp(x, &e);
  return e;
}

/* 2 int |v| over [lo, lo + h] by the 10-point rule.  Used when m = min |v|
** there is >= 4 h |b|: the roots of |v(z)|^2 lie at distance m/|b| >= 4h
** from the interval, so the integrand is analytic in the Bernstein ellipse
** rho = 8 and bounded there by 1.5 max|v|; Trefethen's bound (ATAP, Thm
** 19.3: (64/15) M rho^(-2n)/(rho^2 - 1) on [-1, 1]) gives a relative error
** below 4 rho^-20 / 63 = 6e-20. */
static double near_straight(const double *a, const double *c, int dim,
                            double lo, double h) {
  double s = 0, v[3];
  int i;
  for (i = 0; i < 5; i++) {
    speed_vector(a, c, dim, lo + h * gl10[i][0], v);
    s += gl10[i][1] * norm(v, dim);
    speed_vector(a, c, dim, lo + h * (1 - gl10[i][0]), v);
    s += gl10[i][1] * norm(v, dim);
  }
  return 2 * h * s;
}

/* log(N/D) for N >= D > 0, w = N/D - 1 given without cancellation by the
** caller where N < 2 D.  Where N >= 2 D the rounding of N/D (2^-53 of it)
** moves the log by 1.1e-16 of at least log 2, so libm's log, 40% cheaper
** than log1p, serves and w is not needed; below, log1p(w) keeps a small
** w's digits.  An N/D past the double range (k^2 below 1e-307, N at most
** 36) leaves a term below the rounding of the rest: 0. */
static double log_ratio(double N, double D, double w) {
  double r;
  if (N < 2 * D) return log1p(w);
  r = N / D;
  return isfinite(r) ? log(r) : 0;
}

/* 2 int |v| dt over [lo, lo + h] by the closed form of the parabola's
** length, (U1 S1 - U0 S0 + K^2 log((U1 + S1)/(U0 + S0)))/|b| with U =
** v.b/|b|, K = |a x c|/|b| (|v|^2 = U^2 + K^2), S = |v|, written on u = U
** |b| = v.b (u0 given, u1 = u0 + h |b|^2 so that the vertex's place cannot
** drift), k = K |b| (given), B = |b|^2, q = |b| and S0, S1 = |v| at the ends
** (given: no quotient before the log).  Every part is a sum of positive
** terms; |b| >= 0.1 here (near_straight takes the rest). */
static ARCLEN_INLINE double closed_form(double u0, double S0, double S1,
                                        double h, double B, double q,
                                        double k) {
  double u1 = u0 + h * B, k2 = k * k, t1, w, N, D;
  if (u0 < 0 && u1 > 0) {
    /* the vertex (min |v| = K) inside: two same-sign halves from it, and
    ** asinh(U1/K) + asinh(A0/K) = log((U1 + S1)(A0 + S0)/K^2), A0 = -U0 */
    double a0 = -u0, u1a0 = u1 * a0, den;
    t1 = (u1 * S1 + a0 * S0) / B;
    /* where k^2 underflows its term is below the rounding of t1 */
    if (!(k2 > 0)) return t1;
    N = (u1 + q * S1) * (a0 + q * S0);
    /* N/k^2 - 1 = (U1 A0 + U1 S0 + A0 S1 + S1 S0 - K^2)/K^2 with S1 S0 -
    ** K^2 = (U1^2 A0^2 + K^2 (U1^2 + A0^2))/(S1 S0 + K^2), times B/B */
    den = B * S1 * S0 + k2;
    w = N >= 2 * k2 ? 0
        : (u1a0 + q * (u1 * S0 + a0 * S1) + u1a0 * (u1a0 / den)
           + k2 * ((u1 * u1 + a0 * a0) / den)) / k2;
    return t1 + k2 / (B * q) * log_ratio(N, k2, w);
  }
  if (u1 <= 0) {                  /* both ends before the vertex: reflect */
    double r = -u1;
    u1 = -u0;
    u0 = r;
    r = S1; S1 = S0; S0 = r;
  }
  if (u1 == 0) return 0;
  /* U1 S1 - U0 S0 = (U1 - U0)(U1 + U0)(U1^2 + U0^2 + K^2)/(U1 S1 + U0 S0),
  ** over q, with U1 - U0 = h q */
  t1 = h * (u1 + u0) * (u1 * u1 + u0 * u0 + k2) / (B * (u1 * S1 + u0 * S0));
  if (!(k2 > 0)) return t1;      /* k^2 below the double range: t2 is too */
  /* N/D - 1 = (h q + S1 - S0)/(U0 + S0) with S1 - S0 = h q (U1 + U0)/(S1
  ** + S0): w = h q (q (S1 + S0) + u1 + u0)/((S1 + S0) D), no cancellation */
  N = u1 + q * S1; D = u0 + q * S0;
  w = N >= 2 * D ? 0 : h * q * (q * (S1 + S0) + u1 + u0) / ((S1 + S0) * D);
  return t1 + k2 / (B * q) * log_ratio(N, D, w);
}

/* The legs' k-th components P1 - P0 and P2 - P1 of the points times s (1,
** or 1/2 where a difference overflows: exact), and the largest size. */
static ARCLEN_INLINE void leg_pair(const double *p, int dim, int k, double s,
                                   double *la, double *lc, double *mx) {
  la[k] = p[dim + k] * s - p[k] * s;
  lc[k] = p[2 * dim + k] * s - p[dim + k] * s;
  *mx = arclen_max(*mx, arclen_max(fabs(la[k]), fabs(lc[k])));
}

/* The k-th components of the legs times sc = 2^-e (ldexp where sc = 0:
** 2^-e is not a double).  Like leg_pair, called with a constant k: la and
** lc then live in registers, where a loop over k kept them in memory and
** the vectorizer reloaded two scalar stores as one (a stalled forward). */
static ARCLEN_INLINE void scale_pair(const double *la, const double *lc,
                                     int k, double sc, int e, double *a,
                                     double *c) {
  a[k] = sc > 0 ? la[k] * sc : ldexp(la[k], -e);
  c[k] = sc > 0 ? lc[k] * sc : ldexp(lc[k], -e);
}

/* arclen_quad_setup's body for a constant dim, its loops unrolled: over a
** run-time dim they were 90 of a 2D length's 635 instructions. */
static ARCLEN_INLINE void setup_dim(const double *p, int dim,
                                    arclen_quad_form *f) {
  double *a = f->a, *c = f->c, *b = f->b, mx = 0, la[3], lc[3], sc;
  int e, half = 0;
  f->dim = dim;
  f->p = p;
  f->scale = 0;
  f->up = f->down = 1;
  /* the legs unscaled in locals (constant indices: registers) and stored
  ** once scaled; stored first and scaled in place, two scalar stores came
  ** back as one wide load, a stalled store forward */
  leg_pair(p, dim, 0, 1, la, lc, &mx);
  leg_pair(p, dim, 1, 1, la, lc, &mx);
  if (dim == 3) leg_pair(p, dim, 2, 1, la, lc, &mx);
  /* the points are finite (the callers check), so a leg is infinite only
  ** where its difference overflowed: halves then, exact and finite */
  if (mx > DBL_MAX) {
    half = 1;
    mx = 0;
    leg_pair(p, dim, 0, 0.5, la, lc, &mx);
    leg_pair(p, dim, 1, 0.5, la, lc, &mx);
    if (dim == 3) leg_pair(p, dim, 2, 0.5, la, lc, &mx);
  }
  f->zero = mx == 0;
  if (f->zero) {
    f->S0 = f->Cs = -1;
    return;
  }
  /* by a power of two to [1/2, 1) where the legs are far from 1: no
  ** square over- or underflows (a product by 2^-e where that is a double,
  ** ldexp's rounding otherwise).  Within UNSCALED they are taken as they
  ** are: every product the closed form and the time's bounds take has at
  ** most six legs' factors (within 2^+-610), inside the double range, and each
  ** of +, -, *, /, sqrt (of even powers) and the log of a ratio commutes
  ** exactly with a power of two, so the results are the scaled form's bit
  ** for bit (quad_time_spec: 2^k copies), but where a term underflows or
  ** k^2 meets DBL_MIN (quad_time.c's first guess): terms far below the
  ** rounding of the rest, a guess the search certifies either way.  The
  ** scaling's chain (the largest leg, its exponent, the product) took 4
  ** of a length's 33 ns (bench_segment). */
  if (mx >= 1 / UNSCALED && mx <= UNSCALED) {
    e = 0;
    sc = 1;       /* a product by 1, not a copy: no wide reload of la */
  } else {
    e = exponent_of(mx);
    sc = e > -1000 && e < 1000 ? pow2(-e) : 0;
  }
  scale_pair(la, lc, 0, sc, e, a, c);
  scale_pair(la, lc, 1, sc, e, a, c);
  if (dim == 3) scale_pair(la, lc, 2, sc, e, a, c);
  f->scale = e + half;
  if (f->scale != 0 && f->scale > -1000 && f->scale < 1000) {
    f->up = pow2(f->scale);
    f->down = pow2(-f->scale);
  }
  b[0] = c[0] - a[0];
  b[1] = c[1] - a[1];
  if (dim == 3) b[2] = c[2] - a[2];
  f->B = dot(b, b, dim);
  f->q = sqrt(f->B);
  f->k = cross_norm(a, c, dim);                  /* a x b = a x c */
  /* the start's terms for lengths from 0: v(0) = a exactly */
  f->u0 = dot(a, b, dim);
  f->m0 = dot(a, a, dim);
  f->S0 = sqrt(f->m0);
  /* |c| from above, for the time's roundings' bounds and its lazy
  ** search's test: a square root fewer (|c| itself only in length_below;
  ** unused, the length's copy drops it) */
  f->Cs = fabs(c[0]) + fabs(c[1]) + (dim == 3 ? fabs(c[2]) : 0);
}

/* The set-up's one body for a sub-range's length and the time, both
** dimensions. */
ONE_BODY void arclen_quad_setup(const double *p, int dim, arclen_quad_form *f) {
  if (dim == 2) setup_dim(p, 2, f);
  else setup_dim(p, 3, f);
}

/* Whether near_straight() serves the span of h from v.b = u0, |v|^2 = m0
** to |v|^2 = m1 (B > 0): min |v| >= 4 h |b|, with min |v|^2 = K^2 where
** the vertex (u = 0) is inside. */
static int straight_enough(const arclen_quad_form *f, double h, double u0,
                           double m0, double m1) {
  /* branch-free (numeric.h): whether the vertex is inside is a coin toss
  ** for a time's measured points */
  int inside = (u0 < 0) & (u0 + h * f->B > 0);
  double m = arclen_choose(inside, f->k * f->k / f->B, arclen_min(m0, m1));
  return m >= 16 * h * h * f->B;
}

/* 2 int |v| over [lo, lo + h] of the scaled form, v(lo)'s u0 = v.b, m0 =
** |v|^2 and S0 = |v| given (S0 < 0: not yet taken), the end's |v|^2 and
** |v| into *m1 and *S1 (the latter only where the closed form took it,
** else -1).  *gauss: whether the short Gauss rule served. */
static ARCLEN_INLINE double span_body(const arclen_quad_form *f, double lo,
                                      double h, double u0, double m0,
                                      double S0, double *m1, double *S1,
                                      int *gauss) {
  double v1[3];
  const double *a = f->a, *c = f->c;
  int dim = f->dim;
  *gauss = 0;
  *S1 = -1;
  speed_vector(a, c, dim, lo + h, v1);
  *m1 = dot(v1, v1, dim);
  if (f->B == 0) return 2 * h * norm(a, dim);
  if (straight_enough(f, h, u0, m0, *m1)) {
    *gauss = 1;
    return near_straight(a, c, dim, lo, h);
  }
  *S1 = sqrt(*m1);
  return closed_form(u0, S0 < 0 ? sqrt(m0) : S0, *S1, h, f->B, f->q, f->k);
}

/* span's one body for a sub-range and the time's measured points. */
static ONE_BODY double span(const arclen_quad_form *f, double lo, double h,
                            double u0, double m0, double S0, double *m1,
                            double *S1, int *gauss) {
  return span_body(f, lo, h, u0, m0, S0, m1, S1, gauss);
}

/* L (of the scaled form) times 2^scale, in user units. */
static double unscaled(const arclen_quad_form *f, double L) {
  return f->scale > -1000 && f->scale < 1000 ? L * pow2(f->scale)
                                             : ldexp(L, f->scale);
}

/* The whole segment's length in user units, set-up and span inlined for
** a constant dim: no call between them spills the form (a quadratic's
** arclen_segment_length took 522 instructions through the out-of-line
** set-up and span).  The length over [0, 1] and the time's total both
** come from here, so that a time at the length is 1. */
static ARCLEN_INLINE double whole_dim(const double *p, int dim, int *gauss) {
  arclen_quad_form f;
  double m1, S1;
  setup_dim(p, dim, &f);
  *gauss = 0;
  if (f.zero) return 0;
  return unscaled(&f, span_body(&f, 0, 1, f.u0, f.m0, f.S0, &m1, &S1, gauss));
}

ONE_BODY double arclen_quad_whole(const double *p, int dim, int *gauss) {
  return dim == 2 ? whole_dim(p, 2, gauss) : whole_dim(p, 3, gauss);
}

double arclen_quad_form_length(const arclen_quad_form *f, double t,
                               double *m1, double *S1, int *gauss) {
  *gauss = 0;
  *m1 = *S1 = 0;
  if (f->zero || t == 0) return 0;
  return span(f, 0, t, f->u0, f->m0, f->S0, m1, S1, gauss);
}

int arclen_quad_form_gauss(const arclen_quad_form *f) {
  return !f->zero && f->B > 0
         && straight_enough(f, 1, f->u0, f->m0, dot(f->c, f->c, f->dim));
}

double arclen_quad_form_speed(const arclen_quad_form *f, double t) {
  double v[3];
  speed_vector(f->a, f->c, f->dim, t, v);
  return norm(v, f->dim);
}

/* The length over [t0, t1], h = |t1 - t0| in (0, 1), in user units
** (negative for t1 < t0; 0 for a point): out of line, so that the whole's
** calls keep a small frame. */
static ARCLEN_NOINLINE double part_length(const double *p, int dim, double t0,
                                          double t1, double h, int *gauss) {
  arclen_quad_form f;
  double lo = t0 < t1 ? t0 : t1, m1, S1, u0, m0, S0, v0[3], L;
  arclen_quad_setup(p, dim, &f);
  if (f.zero) return 0;
  if (lo == 0) {                /* v(0) = a: the set-up's terms */
    u0 = f.u0;
    m0 = f.m0;
    S0 = f.S0;
  } else {
    speed_vector(f.a, f.c, dim, lo, v0);
    u0 = dot(v0, f.b, dim);
    m0 = dot(v0, v0, dim);
    S0 = -1;
  }
  L = unscaled(&f, span(&f, lo, h, u0, m0, S0, &m1, &S1, gauss));
  return t1 < t0 ? -L : L;
}

int arclen_quad_length(const double *p, int dim, double t0, double t1,
                       double *len, int *gauss) {
  double h = fabs(t1 - t0), L = 0;
  int g = 0;
  if (h == 1) {                                      /* [0, 1] or [1, 0] */
    L = arclen_quad_whole(p, dim, &g);
    if (t1 < t0 && L != 0) L = -L;                   /* a point's is +0 */
  } else if (h > 0) {
    L = part_length(p, dim, t0, t1, h, &g);
  }
  if (gauss) *gauss = g;
  *len = L;
  return isfinite(L) ? ARCLEN_OK : ARCLEN_EOVERFLOW;
}

/* out into the points' bounding box: the curve's points (and its
** blossom's, for u, v in [0, 1]) are convex combinations of P0, P1, P2, so
** only rounding leaves the box -- past DBL_MAX for points at -1.797e308. */
static void into_hull(const double *p, int dim, double *out) {
  int k;
  for (k = 0; k < dim; k++) {
    double lo = fmin(p[k], fmin(p[dim + k], p[2 * dim + k]));
    double hi = fmax(p[k], fmax(p[dim + k], p[2 * dim + k]));
    out[k] = fmin(fmax(out[k], lo), hi);
  }
}

void arclen_quad_point(const double *p, int dim, double t, double *out) {
  double s = 1 - t, b0 = s * s, b1 = 2 * s * t, b2 = t * t;
  int k;
  for (k = 0; k < dim; k++)     /* Bernstein: P0 and P2 exactly at the ends */
    out[k] = b0 * p[k] + b1 * p[dim + k] + b2 * p[2 * dim + k];
  into_hull(p, dim, out);
}

void arclen_quad_derivative(const double *p, int dim, double t,
                            double *out) {
  int k;
  for (k = 0; k < dim; k++)
    out[k] = 2 * ((1 - t) * (p[dim + k] - p[k])
                  + t * (p[2 * dim + k] - p[dim + k]));
}

/* The blossom B(u, v): B(t, t) is the point, and B(t0, t0), B(t0, t1),
** B(t1, t1) are the control points of the piece from t0 to t1. */
static void blossom(const double *p, int dim, double u, double v,
                    double *out) {
  double b0 = (1 - u) * (1 - v), b1 = (1 - u) * v + u * (1 - v), b2 = u * v;
  int k;
  for (k = 0; k < dim; k++)
    out[k] = b0 * p[k] + b1 * p[dim + k] + b2 * p[2 * dim + k];
  into_hull(p, dim, out);
}

void arclen_quad_sub(const double *p, int dim, double t0, double t1,
                     double *out) {
  blossom(p, dim, t0, t0, out);
  blossom(p, dim, t0, t1, out + dim);
  blossom(p, dim, t1, t1, out + 2 * dim);
}
