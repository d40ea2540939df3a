/*
** quad.c -- the quadratic Bezier P0 P1 P2: B'(t) = 2 v(t), v = a + t b, a =
** P1 - P0, b = c - a, c = P2 - P1, so the length over [t0, t1] is
** 2 int |v| dt, a sqrt/asinh closed form (the parabola's).  Written on
** U = v.b/|b| (the run along b) and K = |a x c|/|b| (the distance of the
** line of v from the origin), every term is a sum of positive parts, and
** U1 - U0 is set to (t1 - t0)|b| exactly so the vertex's place cannot
** drift.  Where |b| is small against min |v| (a nearly straight segment,
** control point near the chord's middle) the closed form would divide
** small differences by |b|: there a 10-point Gauss rule, whose error is
** provably far below an ulp (see near_straight()).
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "arclen.h"
#include "segment/segment.h"

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
static double cross_norm(const double *u, const double *v, int dim) {
  double w[3];
  if (dim == 2) return fabs(u[0] * v[1] - u[1] * v[0]);
  w[0] = u[1] * v[2] - u[2] * v[1];
  w[1] = u[2] * v[0] - u[0] * v[2];
  w[2] = u[0] * v[1] - u[1] * v[0];
  return norm(w, 3);
}

/* v(t) = (1 - t) a + t c: a and c exactly at the ends. */
static void speed_vector(const double *a, const double *c, int dim, double t,
                         double *v) {
  int k;
  if (t == 0 || t == 1) {
    for (k = 0; k < dim; k++) v[k] = t == 0 ? a[k] : c[k];
    return;
  }
  for (k = 0; k < dim; k++) v[k] = (1 - t) * a[k] + t * c[k];
}

/* 2^e for e in [-1022, 1023], from its bits (ldexp costs a call and a
** rounding-mode-proof path that exact powers of two do not need). */
static double pow2(int e) {
  uint64_t bits = (uint64_t)(e + 1023) << 52;
  double v;
  memcpy(&v, &bits, sizeof v);
  return v;
}

/* asinh(x) for x >= 0 as log1p(x + x^2/(1 + sqrt(1 + x^2))): the identity
** asinh x = log(x + sqrt(1 + x^2)) with the 1 taken out, every term
** positive; half the cost of libm's asinh, within a few ulps.  x^2 is
** finite here (x <= the ratio of two scaled lengths). */
static double asinh_pos(double x) {
  double x2 = x * x;
  if (x > 0x1p500) return log(x) + 0.69314718055994530942;   /* log 2x */
  return log1p(x + x2 / (1 + sqrt(1 + x2)));
}

/* asinh(x)/x, 1 at 0 (asinh keeps a tiny x's digits, so the quotient is
** within an ulp or two everywhere). */
static double asinhc(double x) {
  return x == 0 ? 1 : asinh_pos(x) / x;
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

/* 2 int |v| dt over [lo, hi] by the closed form, U0 = v(lo).b/|b|, U1 = U0 +
** h |b|, K as above (|v|^2 = U^2 + K^2). */
static double closed_form(double U0, double h, double q, double K) {
  double U1 = U0 + h * q, S0, S1, t1, t2, Y, x;
  if (U0 < 0 && U1 > 0) {
    /* the vertex (min |v| = K) inside: two same-sign halves from it */
    double A0 = -U0;
    S0 = sqrt(A0 * A0 + K * K); S1 = sqrt(U1 * U1 + K * K);
    t1 = U1 * S1 + A0 * S0;
    /* asinh(U1/K) + asinh(A0/K) = asinh((U1 S0 + A0 S1)/K^2) (sinh of a
    ** sum); where K^2 underflows the term is below the rounding of t1 */
    x = (U1 * S0 + A0 * S1) / (K * K);
    t2 = K > 0 && isfinite(x) ? K * K * asinh_pos(x) : 0;
    return (t1 + t2) / q;
  }
  if (U1 <= 0) {                  /* both ends before the vertex: reflect */
    double r = -U1;
    U1 = -U0;
    U0 = r;
  }
  if (U1 == 0) return 0;
  S0 = sqrt(U0 * U0 + K * K); S1 = sqrt(U1 * U1 + K * K);
  /* U1 S1 - U0 S0 = (U1 - U0)(U1 + U0)(U1^2 + U0^2 + K^2)/(U1 S1 + U0 S0),
  ** divided by q with U1 - U0 = h q */
  t1 = h * (U1 + U0) * (U1 * U1 + U0 * U0 + K * K) / (U1 * S1 + U0 * S0);
  /* (K^2/q)(asinh(U1/K) - asinh(U0/K)) = (K^2/q) asinh(h q Y), Y = (U1 +
  ** U0)/(U1 S0 + U0 S1) (sinh of a difference; no cancellation) */
  if (!(K * K > 0)) return t1;   /* K^2 below the double range: t2 is too */
  Y = (U1 + U0) / (U1 * S0 + U0 * S1);
  x = h * q * Y;
  /* x overflows only for K below 1e-300 (then U0 = 0, S0 = K): K^2 log x
  ** is nothing beside t1 */
  if (!isfinite(x)) return t1;
  t2 = x <= 1 ? K * K * h * Y * asinhc(x) : K * K / q * asinh_pos(x);
  return t1 + t2;
}

int arclen_quad_length(const double *p, int dim, double t0, double t1,
                       double *len, int *gauss) {
  double a[3], c[3], b[3], v0[3], v1[3], lo = t0 < t1 ? t0 : t1;
  double h = fabs(t1 - t0), q, K, m, L, mx = 0;
  int k, e, half = 0;
  if (gauss) *gauss = 0;
  for (k = 0; k < dim; k++) {
    a[k] = p[dim + k] - p[k];
    c[k] = p[2 * dim + k] - p[dim + k];
    if (!isfinite(a[k]) || !isfinite(c[k])) half = 1;
  }
  if (half)                      /* halves: exact, and no overflow */
    for (k = 0; k < dim; k++) {
      a[k] = p[dim + k] / 2 - p[k] / 2;
      c[k] = p[2 * dim + k] / 2 - p[dim + k] / 2;
    }
  for (k = 0; k < dim; k++) {
    if (fabs(a[k]) > mx) mx = fabs(a[k]);
    if (fabs(c[k]) > mx) mx = fabs(c[k]);
  }
  *len = 0;
  if (mx == 0 || h == 0) return ARCLEN_OK;
  /* by a power of two to [1/2, 1): no square over- or underflows (a
  ** product by 2^-e where that is a double, ldexp's rounding otherwise) */
  frexp(mx, &e);
  if (e > -1000 && e < 1000) {
    double sc = pow2(-e);
    for (k = 0; k < dim; k++) { a[k] *= sc; c[k] *= sc; }
  } else {
    for (k = 0; k < dim; k++) { a[k] = ldexp(a[k], -e); c[k] = ldexp(c[k], -e); }
  }
  for (k = 0; k < dim; k++) b[k] = c[k] - a[k];
  q = norm(b, dim);
  speed_vector(a, c, dim, lo, v0);
  speed_vector(a, c, dim, lo + h, v1);
  if (q == 0) {
    L = 2 * h * norm(a, dim);
  } else {
    double U0 = dot(v0, b, dim) / q, vt;
    K = cross_norm(a, c, dim) / q;   /* a x b = a x c */
    /* min |v| over the range: K where the vertex -a.b/|b|^2 is inside */
    vt = -dot(a, b, dim) / (q * q);
    m = vt > lo && vt < lo + h ? K * K
        : fmin(dot(v0, v0, dim), dot(v1, v1, dim));      /* min |v|^2 */
    if (m >= 16 * h * h * (q * q)) {                   /* min |v| >= 4 h q */
      L = near_straight(a, c, dim, lo, h);
      if (gauss) *gauss = 1;
    } else {
      L = closed_form(U0, h, q, K);
    }
  }
  L = e + half > -1000 && e + half < 1000 ? L * pow2(e + half)
                                          : ldexp(L, e + half);
  if (t1 < t0) L = -L;
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
