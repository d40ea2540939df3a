/*
** conic.c -- Floater's cubic approximation of a conic section.
**
** M. S. Floater, "An analysis of cubic approximation schemes for conic
** sections" (1996).  The conic is the rational quadratic Bezier curve
** (p0, p1, p2; weight w) of eq. (1); one cubic piece has the control points
** p0, (1-lambda) p0 + lambda p1, (1-lambda) p2 + lambda p1, p2 (eq. 2), and
** a scheme is a function lambda(w).  A spline of level r approximates the
** 2^r pieces of the subdivision scheme (eq. 4), which all share the weight
** w_r.  Theorem 1 with Prop 13's closed form bounds the Hausdorff distance.
** Corrections to the paper's text: doc/papers.md, "Floater: conics".
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "arclen.h"
#include "conic/conic.h"

static const char *const scheme_names[ARCLEN_CONIC_NSCHEMES] = {
  "quadratic", "g2", "midpoint", "c2", "g4"
};

int arclen_conic_scheme(const char *name) {
  int s;
  for (s = 0; s < ARCLEN_CONIC_NSCHEMES; s++)
    if (strcmp(name, scheme_names[s]) == 0) return s;
  return -1;
}

const char *arclen_conic_scheme_name(int scheme) {
  if (scheme < 0 || scheme >= ARCLEN_CONIC_NSCHEMES) return NULL;
  return scheme_names[scheme];
}

/* delta = lambda(w) - 2/3, in forms without cancellation near w = 1, where
** every scheme has lambda = 2/3 and the error terms A, B of Prop 2 are
** differences of O(w - 1) quantities.  u = w^2 - 1. */
static double lambda_delta(int scheme, double w) {
  double u = (w - 1) * (w + 1);
  switch (scheme) {
  case ARCLEN_CONIC_QUADRATIC:      /* Prop 3: lambda = 2/3 */
    return 0;
  case ARCLEN_CONIC_G2: {           /* Prop 4: (2/3) w (sqrt(w^2+3) - w) */
    double s = sqrt(w * w + 3);
    return 2 * u / ((s + w) * (2 * w + s));
  }
  case ARCLEN_CONIC_MIDPOINT:       /* Prop 5: (4/3) w / (1 + w) */
    return 2 * (w - 1) / (3 * (1 + w));
  case ARCLEN_CONIC_C2:             /* Prop 8: 2 w^2 / (1 + 2 w^2) */
    return 2 * u / (3 * (1 + 2 * w * w));
  case ARCLEN_CONIC_G4: {           /* Props 9-10, negative root */
    double r = sqrt(3 * w * w + 1), d = 6 * w * w + 1 + r;
    if (3 * w * w > 1)  /* 3w^2 - 1 - r = 9u(u+1)/(3w^2 - 1 + r) */
      return 2 * (9 * u * (u + 1) / (3 * w * w - 1 + r)) / (3 * d);
    return 6 * w * w / d - 2.0 / 3;
  }
  default:
    return NAN;
  }
}

/* Beyond 2^+-100 the forms in w^2 overflow or lose every digit (A and B
** are differences of O(1) terms whose sum is O(w^2) at small w), while the
** limits are meaningful: w -> inf is the control polygon (a degenerate
** hyperbola), w -> 0 the chord; subdivision brings w_r of eq. (4) back
** near 1 in a few levels.  There the forms below in 1/w, and A, B divided
** by w^2, are used. */
#define W_BIG 0x1p100
#define W_SMALL 0x1p-100

double arclen_conic_lambda(int scheme, double w) {
  double v = 1 / w;
  switch (scheme) {
  case ARCLEN_CONIC_QUADRATIC: return 2.0 / 3;
  /* 2w/(sqrt(w^2+3) + w): Prop 4's form without cancellation at large w */
  case ARCLEN_CONIC_G2:
    if (w > W_BIG) return 2 / (sqrt(1 + 3 * v * v) + 1);
    return 2 * w / (sqrt(w * w + 3) + w);
  case ARCLEN_CONIC_MIDPOINT:
    if (w > W_BIG) return 4 / (3 * (1 + v));
    return 4 * w / (3 * (1 + w));
  case ARCLEN_CONIC_C2:
    if (w > W_BIG) return 2 / (v * v + 2);
    return 2 * w * w / (1 + 2 * w * w);
  /* Prop 9's 2(6w^2+1 - sqrt(3w^2+1))/(12w^2+3), rationalised:
  ** 6w^2 / (6w^2 + 1 + sqrt(3w^2+1)) (no cancellation at small w) */
  case ARCLEN_CONIC_G4:
    if (w > W_BIG) return 6 / (6 + v * (v + sqrt(3 + v * v)));
    return 6 * w * w / (6 * w * w + 1 + sqrt(3 * w * w + 1));
  default: return NAN;
  }
}

/* lambda / w: finite at small w (where lambda ~ c w) */
static double lambda_over_w(int scheme, double w) {
  switch (scheme) {
  case ARCLEN_CONIC_QUADRATIC: return (2.0 / 3) / w;   /* inf below 1e-308 */
  case ARCLEN_CONIC_G2: return 2 / (sqrt(w * w + 3) + w);
  case ARCLEN_CONIC_MIDPOINT: return 4 / (3 * (1 + w));
  case ARCLEN_CONIC_C2: return 2 * w / (1 + 2 * w * w);
  case ARCLEN_CONIC_G4: return 6 * w / (6 * w * w + 1 + sqrt(3 * w * w + 1));
  default: return NAN;
  }
}

/* Prop 2's A / w^2 and B / w^2 in its direct form (no cancellation far
** from w = 1):  9 (lambda/w)^2 - 12 (1 - lambda),
** 18 (lambda/w)^2 - 4 (9 (1 - lambda)^2 + 1). */
static void scheme_AB_over_w2(int scheme, double w, double *a, double *b) {
  double l = arclen_conic_lambda(scheme, w);
  double lw = w > 1 ? l / w : lambda_over_w(scheme, w);
  *a = 9 * lw * lw - 12 * (1 - l);
  *b = 18 * lw * lw - 4 * (9 * (1 - l) * (1 - l) + 1);
}

/* Prop 2's A and B with lambda = 2/3 + delta expanded:
** A = 9 lambda^2 - 12 w^2 (1 - lambda) = -4u + 12 delta (1 + w^2) + 9 delta^2
** B = 18 lambda^2 - 4 w^2 (9 (1 - lambda)^2 + 1)
**   = -8u + 24 delta (1 + w^2) + 18 delta^2 (1 - 2 w^2),   u = w^2 - 1. */
void arclen_conic_AB(double w, double delta, double *A, double *B) {
  double u = (w - 1) * (w + 1), v = 1 + w * w;
  *A = -4 * u + 12 * delta * v + 9 * delta * delta;
  *B = -8 * u + 24 * delta * v + 18 * delta * delta * (1 - 2 * w * w);
}

/* Outside [W_SMALL, W_BIG] by A / w^2 and B / w^2: A and B are O(w^2),
** +-inf when that overflows (an honest value, never inf - inf). */
void arclen_conic_scheme_AB(int scheme, double w, double *A, double *B) {
  if (w > W_BIG || w < W_SMALL) {
    double a, b;
    scheme_AB_over_w2(scheme, w, &a, &b);
    *A = a * w * w; *B = b * w * w;
    return;
  }
  arclen_conic_AB(w, lambda_delta(scheme, w), A, B);
}

/* Prop 13: max over [0,1] of |g(t)|, g(t) = (1-t)^2 t^2 (A(1-t)^2 +
** B(1-t)t + A t^2).  The interior critical point u1 (u = t - 1/2) exists
** iff 3B < -2A < 0 or 3B > -2A > 0. */
double arclen_conic_gnorm(double A, double B) {
  double m;
  /* A or B overflowed (w beyond 1e154): so does ||g||, about |A| + |B| */
  if (!isfinite(A) || !isfinite(B)) return HUGE_VAL;
  m = fabs(2 * A / 64 + B / 64);
  if ((3 * B < -2 * A && -2 * A < 0) || (3 * B > -2 * A && -2 * A > 0)) {
    double d = 2 * A - B, r = A / d;      /* A^3 / d^2 without overflow */
    double m1 = 4 * fabs(A) * r * r / 27;
    if (m1 > m) m = m1;
  }
  return m;
}

double arclen_conic_weight(double w, int level) {
  int r;
  for (r = 0; r < level; r++) w = sqrt((1 + w) / 2);   /* w_r, eq. (4) */
  return w;
}

/* Theorem 1's factor for one level: (1/4) max(1/w^2, 1) ||g||, or +inf
** when lambda > 1 (the cubic leaves the triangle: Theorem 1 does not
** apply).  Multiply by |p0 - 2 p1 + p2|. */
static double level_factor(int scheme, double w) {
  double A, B;
  if (arclen_conic_lambda(scheme, w) > 1) return HUGE_VAL;
  if (w > W_BIG || w < W_SMALL) {   /* ||g|| is homogeneous in (A, B) */
    scheme_AB_over_w2(scheme, w, &A, &B);
    return w < 1 ? 0.25 * arclen_conic_gnorm(A, B)
                 : 0.25 * arclen_conic_gnorm(A, B) * w * w;
  }
  arclen_conic_scheme_AB(scheme, w, &A, &B);
  return 0.25 * (w < 1 ? 1 / (w * w) : 1) * arclen_conic_gnorm(A, B);
}

/* The legs a = p1 - p0, c = p2 - p1 and the chord k = p2 - p0 into v = ax
** ay cx cy kx ky, each one rounding of the inputs (so a short leg next to
** far-away points keeps its digits).  When a difference would overflow
** (points beyond +-DBL_MAX/2 on both sides) the halved inputs are
** differenced instead and 1 is returned: v is then half the legs (halving
** is exact but for subnormals, whose lost bit is below the difference's
** own rounding).  Otherwise 0. */
int arclen_conic_legs(const double p[6], double v[6]) {
  static const int to[6] = {2, 3, 4, 5, 4, 5}, from[6] = {0, 1, 2, 3, 0, 1};
  int i, half = 0;
  for (i = 0; i < 6; i++) {
    v[i] = p[to[i]] - p[from[i]];
    if (!isfinite(v[i])) half = 1;
  }
  if (half)
    for (i = 0; i < 6; i++) v[i] = p[to[i]] / 2 - p[from[i]] / 2;
  return half;
}

int arclen_conic_degenerate(const double p[6]) {
  double v[6], l1, l2, s, mx = 0;
  int i;
  for (i = 0; i < 6; i++)
    if (!isfinite(p[i])) return 1;
  arclen_conic_legs(p, v);   /* a half scale leaves the directions alone */
  /* a leg of components near DBL_MAX has a length beyond it (hypot = inf
  ** made the sine 0, and a valid conic "collinear"): such legs scaled by
  ** 2^-64 (exact but for parts 2^-1000 of the largest, far below the
  ** test's 16 eps) */
  for (i = 0; i < 4; i++)
    if (fabs(v[i]) > mx) mx = fabs(v[i]);
  if (mx > 0x1p1000)
    for (i = 0; i < 4; i++) v[i] *= 0x1p-64;
  l1 = hypot(v[0], v[1]); l2 = hypot(v[2], v[3]);
  if (!(l1 > 0) || !(l2 > 0)) return 1;
  /* sine of the turning angle at p1; below a few rounding errors the
  ** triangle is flat and the conic degenerates to a segment */
  s = (v[0] / l1) * (v[3] / l2) - (v[1] / l1) * (v[2] / l2);
  return !(fabs(s) > 16 * DBL_EPSILON);
}

int arclen_conic_check(const double p[6], double w) {
  int i;
  for (i = 0; i < 6; i++)
    if (!isfinite(p[i])) return ARCLEN_EINVAL;
  if (!isfinite(w) || !(w > 0) || arclen_conic_degenerate(p))
    return ARCLEN_EDOMAIN;
  return ARCLEN_OK;
}

/* Split the conic piece t[6] = (a, b, c) with weight w at its mid-point
** (eq. 4): left (a, (a + w b)/(1 + w), m), right (m, (w b + c)/(1 + w), c). */
static void split_half(const double t[6], double w, int right, double out[6]) {
  /* (a + w b)/(1 + w) = (a v + b)/(v + 1), v = 1/w, for w > 1: the sum
  ** is at most |a| + |b| (w b itself must not overflow) */
  double v = w > 1 ? 1 / w : 1, s = w > 1 ? 1 : w;
  double l1x = (t[0] * v + s * t[2]) / (v + s);
  double l1y = (t[1] * v + s * t[3]) / (v + s);
  double r1x = (s * t[2] + t[4] * v) / (v + s);
  double r1y = (s * t[3] + t[5] * v) / (v + s);
  double mx = (l1x + r1x) / 2, my = (l1y + r1y) / 2;
  if (!right) {
    out[0] = t[0]; out[1] = t[1]; out[2] = l1x; out[3] = l1y;
    out[4] = mx; out[5] = my;
  } else {
    out[0] = mx; out[1] = my; out[2] = r1x; out[3] = r1y;
    out[4] = t[4]; out[5] = t[5];
  }
}

/* Walk the 2^level pieces of level `level` in order, keeping the path from
** the root (no allocation: one triangle per depth).  Coordinates are
** relative to p0 (far-from-origin conics keep their digits), and scaled
** by 2^-*half (0, 1 or 2) so that they stay below DBL_MAX/4: sums of two
** of them, and the control points up to 4/3 of the way along a leg, do
** not overflow.  Points are written as 2^*half (t + p0 / 2^*half), which
** overflows only where the point itself is beyond DBL_MAX.  For each
** piece: the second difference |a - 2b + c| enters the bound; when out is
** not NULL, the cubic of eq. (6) is written (absolute coordinates).
** Returns max |a - 2b + c| (scaled as the coordinates). */
static double walk(const double p[6], double w, int level, double lambda,
                   double *out, int *half) {
  double tri[ARCLEN_CONIC_MAXLEVEL + 1][6], wd[ARCLEN_CONIC_MAXLEVEL + 1];
  double v[6], ox, oy, sh, dmax = 0;
  long n = 1L << level, i;
  int d;
  *half = arclen_conic_legs(p, v);
  for (d = 0; d < 6; d++)
    if (fabs(v[d]) > DBL_MAX / 4) dmax = 1;
  if (dmax > 0) {     /* halving a number this large is exact */
    for (d = 0; d < 6; d++) v[d] /= 2;
    ++*half;
    dmax = 0;
  }
  sh = ldexp(1, *half);
  ox = p[0] / sh; oy = p[1] / sh;
  tri[0][0] = tri[0][1] = 0;
  tri[0][2] = v[0]; tri[0][3] = v[1];
  tri[0][4] = v[4]; tri[0][5] = v[5];
  wd[0] = w;
  for (d = 1; d <= level; d++) wd[d] = sqrt((1 + wd[d - 1]) / 2);
  for (i = 0; i < n; i++) {
    const double *t;
    double dx, dy;
    /* the leaves i-1 and i share the path down to depth level-1-ctz(i) */
    int d0 = 0;
    if (i > 0) {
      int z = 0;
      while (!((i >> z) & 1)) z++;
      d0 = level - 1 - z;
    }
    for (d = d0; d < level; d++)
      split_half(tri[d], wd[d], (int)((i >> (level - 1 - d)) & 1), tri[d + 1]);
    t = tri[level];
    dx = t[0] - 2 * t[2] + t[4];
    dy = t[1] - 2 * t[3] + t[5];
    if (hypot(dx, dy) > dmax) dmax = hypot(dx, dy);
    if (out != NULL) {
      double *c = out + 8 * i;
      c[0] = (t[0] + ox) * sh; c[1] = (t[1] + oy) * sh;
      c[2] = ((t[0] + lambda * (t[2] - t[0])) + ox) * sh;
      c[3] = ((t[1] + lambda * (t[3] - t[1])) + oy) * sh;
      c[4] = ((t[4] + lambda * (t[2] - t[4])) + ox) * sh;
      c[5] = ((t[5] + lambda * (t[3] - t[5])) + oy) * sh;
      c[6] = (t[4] + ox) * sh; c[7] = (t[5] + oy) * sh;
    }
  }
  if (out != NULL) {  /* the ends are the conic's ends, exactly */
    out[0] = p[0]; out[1] = p[1];
    out[8 * n - 2] = p[4]; out[8 * n - 1] = p[5];
  }
  return dmax;
}

/* Theorem 1's factor times max |a - 2b + c| (given scaled by 2^-half):
** 0 stays 0 and inf stays inf, never 0 * inf. */
static double scaled_bound(double factor, double dmax, int half) {
  if (factor == 0) return 0;
  return ldexp(factor * dmax, half);
}

static int check_args(const double p[6], double w, int scheme, int level) {
  int rc = arclen_conic_check(p, w);
  if (rc != ARCLEN_OK) return rc;
  if (scheme < 0 || scheme >= ARCLEN_CONIC_NSCHEMES) return ARCLEN_EINVAL;
  if (level < 0 || level > ARCLEN_CONIC_MAXLEVEL) return ARCLEN_ERANGE;
  return ARCLEN_OK;
}

/* Eq. (18): the bound of level r. */
int arclen_conic_bound(const double p[6], double w, int scheme, int level,
                       double *bound) {
  int rc = check_args(p, w, scheme, level);
  double wr;
  *bound = NAN;
  if (rc != ARCLEN_OK) return rc;
  wr = arclen_conic_weight(w, level);
  {
    int half;
    double dmax = walk(p, w, level, 0, NULL, &half);
    *bound = scaled_bound(level_factor(scheme, wr), dmax, half);
  }
  return ARCLEN_OK;
}

int arclen_conic_level(const double p[6], double w, int scheme, double tol,
                       int *level, double *bound) {
  int r, rc = check_args(p, w, scheme, 0);
  *level = -1;
  *bound = NAN;
  if (rc != ARCLEN_OK) return rc;
  if (!(tol > 0) || !isfinite(tol)) return ARCLEN_ETOL;
  for (r = 0; r <= ARCLEN_CONIC_MAXLEVEL; r++) {
    arclen_conic_bound(p, w, scheme, r, bound);
    *level = r;
    if (*bound <= tol) return ARCLEN_OK;
  }
  return ARCLEN_ENOCONV;
}

int arclen_conic_cubics(const double p[6], double w, int scheme, int level,
                        double *out, double *bound) {
  int rc = check_args(p, w, scheme, level);
  double wr;
  if (bound != NULL) *bound = NAN;
  if (rc != ARCLEN_OK) return rc;
  wr = arclen_conic_weight(w, level);
  {
    int half;
    long i;
    double dmax = walk(p, w, level, arclen_conic_lambda(scheme, wr), out,
                       &half);
    if (bound != NULL) *bound = scaled_bound(level_factor(scheme, wr), dmax, half);
    /* lambda > 1 (the mid-point scheme beyond w = 2) puts the inner control
    ** points outside the triangle: near DBL_MAX they may not exist */
    for (i = 0; i < 8L << level; i++)
      if (!isfinite(out[i])) return ARCLEN_EOVERFLOW;
  }
  return ARCLEN_OK;
}

/* A point of the conic, eq. (1), relative to p0 then shifted back. */
void arclen_conic_point(const double p[6], double w, double t, double pt[2]) {
  double b0 = (1 - t) * (1 - t), b1 = 2 * t * (1 - t) * w, b2 = t * t;
  double den = b0 + b1 + b2;
  pt[0] = p[0] + (b1 * (p[2] - p[0]) + b2 * (p[4] - p[0])) / den;
  pt[1] = p[1] + (b1 * (p[3] - p[1]) + b2 * (p[5] - p[1])) / den;
}
