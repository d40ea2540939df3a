/*
** cubic.c -- the geometry of one cubic Bezier curve: points, derivative,
** de Casteljau splitting, the hodograph and the speed's critical points.
*/
#include <math.h>
#include <string.h>

#include "arclen.h"
#include "curve/cubic.h"
#include "curve/numeric.h"

int arclen_check_curve(const double *c, int dim) {
  double z = 0;
  int i;
  if (dim != 2 && dim != 3) return ARCLEN_EDIM;
  /* x - x is 0 for every finite x and NaN for inf and NaN: one test at
  ** the end instead of a branch per number; two numbers a step (4 dim is
  ** even), as this runs on every call */
  for (i = 0; i < 4 * dim; i += 2) z += (c[i] - c[i]) + (c[i + 1] - c[i + 1]);
  return z == 0 ? ARCLEN_OK : ARCLEN_EINVAL;
}

/* Bernstein form: stable for t in [0, 1], exact at both ends. */
void arclen_point(const double *c, int dim, double t, double *p) {
  double s = 1 - t;
  double b0 = s * s * s, b1 = 3 * t * s * s, b2 = 3 * t * t * s, b3 = t * t * t;
  int k;
  for (k = 0; k < dim; k++)
    p[k] = b0 * c[k] + b1 * c[dim + k] + b2 * c[2 * dim + k] + b3 * c[3 * dim + k];
}

/* z'(t) = 3 [(1-t)^2 (P1-P0) + 2t(1-t) (P2-P1) + t^2 (P3-P2)] */
void arclen_derivative(const double *c, int dim, double t, double *d) {
  double s = 1 - t;
  int k;
  for (k = 0; k < dim; k++) {
    double d0 = c[dim + k] - c[k];
    double d1 = c[2 * dim + k] - c[dim + k];
    double d2 = c[3 * dim + k] - c[2 * dim + k];
    d[k] = 3 * (s * s * d0 + 2 * t * s * d1 + t * t * d2);
  }
}

/* The unit tangent at t: z'(t) normalised; where z' vanishes (a cusp, or
** a control point on its end point) the limit from the next derivatives,
** z'' (its negative at t = 1, approached from the left), then z'''; a
** point has none (zeros). */
void arclen_unit_tangent(const double *c, int dim, double t, double *v) {
  double len = 0;
  int i;
  arclen_derivative(c, dim, t, v);
  for (i = 0; i < dim; i++) len += v[i] * v[i];
  len = sqrt(len);
  if (len == 0) {
    double u = 1 - t;
    for (i = 0; i < dim; i++) {
      double p0 = c[i], p1 = c[dim + i], p2 = c[2 * dim + i], p3 = c[3 * dim + i];
      v[i] = u * (p2 - 2 * p1 + p0) + t * (p3 - 2 * p2 + p1);
      if (t == 1) v[i] = -v[i];
    }
    for (i = 0, len = 0; i < dim; i++) len += v[i] * v[i];
    len = sqrt(len);
  }
  if (len == 0) {
    for (i = 0; i < dim; i++)
      v[i] = c[3 * dim + i] - 3 * c[2 * dim + i] + 3 * c[dim + i] - c[i];
    for (i = 0, len = 0; i < dim; i++) len += v[i] * v[i];
    len = sqrt(len);
  }
  for (i = 0; i < dim; i++) v[i] = len == 0 ? 0 : v[i] / len;
}

/* The blossom (polar form) b(u1, u2, u3) by three de Casteljau steps with
** different parameters; b(t,t,t) is the point at t. */
static void blossom(const double *c, int dim, double u1, double u2, double u3,
                    double *out) {
  int k;
  for (k = 0; k < dim; k++) {
    double p0 = c[k], p1 = c[dim + k], p2 = c[2 * dim + k], p3 = c[3 * dim + k];
    double q0 = p0 + u1 * (p1 - p0), q1 = p1 + u1 * (p2 - p1), q2 = p2 + u1 * (p3 - p2);
    double r0 = q0 + u2 * (q1 - q0), r1 = q1 + u2 * (q2 - q1);
    out[k] = r0 + u3 * (r1 - r0);
  }
}

/* The control points of the curve restricted to [t0, t1], reparametrised
** to [0, 1]: b(t0,t0,t0), b(t0,t0,t1), b(t0,t1,t1), b(t1,t1,t1). */
void arclen_subcurve(const double *c, int dim, double t0, double t1,
                     double *out) {
  double tmp[12];
  blossom(c, dim, t0, t0, t0, tmp);
  blossom(c, dim, t0, t0, t1, tmp + dim);
  blossom(c, dim, t0, t1, t1, tmp + 2 * dim);
  blossom(c, dim, t1, t1, t1, tmp + 3 * dim);
  if (t0 == 0) memcpy(tmp, c, dim * sizeof(double));   /* keep ends exact */
  if (t1 == 1) memcpy(tmp + 3 * dim, c + 3 * dim, dim * sizeof(double));
  memcpy(out, tmp, 4 * dim * sizeof(double));
}

void arclen_split(const double *c, int dim, double t, double *left,
                  double *right) {
  double l[12], r[12];
  int k;
  for (k = 0; k < dim; k++) {
    double p0 = c[k], p1 = c[dim + k], p2 = c[2 * dim + k], p3 = c[3 * dim + k];
    double q0 = p0 + t * (p1 - p0), q1 = p1 + t * (p2 - p1), q2 = p2 + t * (p3 - p2);
    double r0 = q0 + t * (q1 - q0), r1 = q1 + t * (q2 - q1);
    double s = r0 + t * (r1 - r0);
    l[k] = p0; l[dim + k] = q0; l[2 * dim + k] = r0; l[3 * dim + k] = s;
    r[k] = s; r[dim + k] = r1; r[2 * dim + k] = q2; r[3 * dim + k] = p3;
  }
  if (left) memcpy(left, l, 4 * dim * sizeof(double));
  if (right) memcpy(right, r, 4 * dim * sizeof(double));
}

/* The power form of z'(t), every coordinate (arclen_power_form). */
void arclen_hodograph(const double *c, int dim, double a2[3], double a1[3],
                      double a0[3]) {
  int k;
  for (k = 0; k < dim; k++)
    arclen_power_form(c, dim, k, &a0[k], &a1[k], &a2[k]);
}

/* Coordinates beyond this may overflow in differences (P3 - P0 can exceed
** DBL_MAX); such curves are scaled down by 2^-64 first (exact). */
#define HUGE_COORD 1e300

/* Scale a hodograph by a power of two so that products cannot over- or
** underflow and every scaled value is exact (frexp gives the largest
** coefficient as m 2^e, 0.5 <= m < 1); pre64 says the input was scaled
** by 2^-64 first. */
static void scale_hodo(arclen_hodo *h, int pre64) {
  double big = 0;
  int k, e;
  for (k = 0; k < h->dim; k++) {
    double v2 = fabs(h->a2[k]), v1 = fabs(h->a1[k]), v0 = fabs(h->a0[k]);
    if (v2 > big) big = v2;
    if (v1 > big) big = v1;
    if (v0 > big) big = v0;
  }
  if (big == 0) {
    h->exp = 0;
    h->zero = 1;
    return;
  }
  frexp(big, &e);
  h->exp = e;
  if (e > -1000 && e < 1000) {      /* 2^-e is a normal double: multiply */
    double inv = ldexp(1.0, -e);
    for (k = 0; k < h->dim; k++) {
      h->a2[k] *= inv;
      h->a1[k] *= inv;
      h->a0[k] *= inv;
    }
  } else {
    for (k = 0; k < h->dim; k++) {
      h->a2[k] = ldexp(h->a2[k], -e);
      h->a1[k] = ldexp(h->a1[k], -e);
      h->a0[k] = ldexp(h->a0[k], -e);
    }
  }
  if (pre64) h->exp += 64;          /* ldexp(len, exp) overflows only if */
                                    /* the length itself does */
}

/* The curve scaled by 2^-64 into small[] when a coordinate is huge (exact);
** returns the points to use. */
static const double *tame(const double *c, int dim, double small[12],
                          int *pre64) {
  int k;
  *pre64 = 0;
  for (k = 0; k < 4 * dim; k++)
    if (fabs(c[k]) > HUGE_COORD) *pre64 = 1;
  if (!*pre64) return c;
  for (k = 0; k < 4 * dim; k++) small[k] = c[k] * 0x1p-64;
  return small;
}

/* The slow path of arclen_hodo_quick (cubic.h): overflow, zero and
** subnormal coefficients take tame() and scale_hodo(), which give the same
** result wherever the quick path applies (scaling by 2^-64 commutes with
** the rounding of differences that do not overflow). */
void arclen_hodo_scaled(const double *c, int dim, arclen_hodo *h) {
  double small[12];
  int pre64;
  if (arclen_hodo_quick(c, dim, h)) return;
  memset(h, 0, sizeof *h);
  h->dim = dim;
  c = tame(c, dim, small, &pre64);
  arclen_hodograph(c, dim, h->a2, h->a1, h->a0);
  scale_hodo(h, pre64);
}

/* ---- the hodograph about a sub-range, to full relative accuracy ------- */

/* Double-double arithmetic (numeric.h; TwoProduct as in Ogita, Rump &
** Oishi 2005, by arclen_fma: exactly rounded, MinGW included). */
typedef arclen_dd dd;

static dd dd_add(dd x, dd y) {
  dd s = arclen_two_sum(x.hi, y.hi);
  return arclen_two_sum(s.hi, s.lo + (x.lo + y.lo));
}

static dd dd_mul(dd x, dd y) {
  double p = x.hi * y.hi;
  double e = arclen_fma(x.hi, y.hi, -p) + (x.hi * y.lo + x.lo * y.hi);
  return arclen_two_sum(p, e);
}

static dd dd_of(double x) {
  dd r;
  r.hi = x;
  r.lo = 0;
  return r;
}

/* x - y with y's parts taken one at a time: the difference of two exact
** values stays exact as long as it fits in hi + lo. */
static dd dd_sub(dd x, dd y) {
  return dd_add(dd_add(x, dd_of(-y.hi)), dd_of(-y.lo));
}

/* The hodograph of [t0, t1] in the local variable s in [-1, 1],
** t = tc + hw s with hw = (t1 - t0)/2 and tc = t0 + hw held exactly:
** H(s) = z'(tc) + hw z''(tc) s + hw^2 A2 s^2, so that the length of the
** range is hw times that of H over [-1, 1].  Near a (near) cusp z'(tc) is
** a small difference of large terms: the power form and its value at tc
** are formed in double-double from the exact control-point differences,
** so each coefficient is correct to rounding however small (the speed on
** a sub-range 1e-10 wide at a near-cusp of 1e-8 kept only 8 digits). */
void arclen_hodo_local(const double *c, int dim, double t0, double t1,
                       arclen_hodo *h) {
  double small[12], hw = (t1 - t0) / 2;
  dd tc = arclen_two_sum(t0, hw), two = dd_of(2), three = dd_of(3), six = dd_of(6);
  int k, pre64;
  memset(h, 0, sizeof *h);
  h->dim = dim;
  c = tame(c, dim, small, &pre64);
  for (k = 0; k < dim; k++) {
    dd d0 = arclen_two_sum(c[dim + k], -c[k]);
    dd d1 = arclen_two_sum(c[2 * dim + k], -c[dim + k]);
    dd d2 = arclen_two_sum(c[3 * dim + k], -c[2 * dim + k]);
    dd e1 = dd_sub(d1, d0), e2 = dd_sub(d2, d1);
    dd a0 = dd_mul(three, d0), a1 = dd_mul(six, e1);
    dd a2 = dd_mul(three, dd_sub(e2, e1)), v, dv;
    v = dd_add(a0, dd_mul(tc, dd_add(a1, dd_mul(tc, a2))));   /* z'(tc) */
    dv = dd_add(a1, dd_mul(two, dd_mul(tc, a2)));            /* z''(tc) */
    h->a0[k] = v.hi + v.lo;
    h->a1[k] = (dv.hi + dv.lo) * hw;
    h->a2[k] = (a2.hi + a2.lo) * hw * hw;
  }
  scale_hodo(h, pre64);
}

/* Value of the cubic p[3] t^3 + p[2] t^2 + p[1] t + p[0]. */
static double cubic_at(const double p[4], double t) {
  return ((p[3] * t + p[2]) * t + p[1]) * t + p[0];
}

/* A root of the cubic in [lo, hi], where it changes sign and is monotone:
** Newton from the secant point, kept inside the bracket (a step leaving it
** is replaced by bisection).  Bisection alone would settle within ~1100
** halvings; the cap of 100 steps is far above what Newton needs. */
static double bracketed_root(const double p[4], double lo, double hi) {
  double flo = cubic_at(p, lo), fhi = cubic_at(p, hi);
  double t = lo - flo * (hi - lo) / (fhi - flo);
  int i;
  if (!(t > lo && t < hi)) t = lo + (hi - lo) / 2;
  for (i = 0; i < 100; i++) {
    double f = cubic_at(p, t);
    double df = (3 * p[3] * t + 2 * p[2]) * t + p[1], next;
    if (f == 0) return t;
    if ((f < 0) == (flo < 0)) lo = t; else hi = t;
    next = df != 0 ? t - f / df : lo + (hi - lo) / 2;
    if (!(next > lo && next < hi)) next = lo + (hi - lo) / 2;
    if (fabs(next - t) <= 2.3e-16 * t || next == lo || next == hi) return next;
    t = next;
  }
  return t;
}

/* Real roots in (0, 1) of p, ascending.  The interval is cut at the roots
** of p' (where p is monotone between them) and each monotone piece with a
** sign change is bisected: no root is lost to a bad initial guess. */
int arclen_cubic_roots01(const double p[4], double roots[3]) {
  double cut[4], dq[3];
  int ncut = 0, n = 0, i;
  cut[ncut++] = 0;
  /* p'(t) = 3 p3 t^2 + 2 p2 t + p1 */
  dq[2] = 3 * p[3]; dq[1] = 2 * p[2]; dq[0] = p[1];
  if (dq[2] != 0) {
    double disc = dq[1] * dq[1] - 4 * dq[2] * dq[0];
    if (disc > 0) {
      double q = -(dq[1] + copysign(sqrt(disc), dq[1])) / 2;
      double r1 = q / dq[2], r2 = q != 0 ? dq[0] / q : r1;
      if (r1 > r2) { double tmp = r1; r1 = r2; r2 = tmp; }
      if (r1 > 0 && r1 < 1) cut[ncut++] = r1;
      if (r2 > 0 && r2 < 1 && r2 != r1) cut[ncut++] = r2;
    }
  } else if (dq[1] != 0) {
    double r = -dq[0] / dq[1];
    if (r > 0 && r < 1) cut[ncut++] = r;
  }
  cut[ncut++] = 1;
  for (i = 0; i + 1 < ncut; i++) {
    double lo = cut[i], hi = cut[i + 1];
    double flo = cubic_at(p, lo), fhi = cubic_at(p, hi);
    double r;
    if (flo == 0 || fhi == 0) {       /* a root exactly on a cut */
      r = flo == 0 ? lo : hi;
    } else if ((flo < 0) != (fhi < 0)) {
      r = bracketed_root(p, lo, hi);
    } else continue;
    if (r > 0 && r < 1 && (n == 0 || r > roots[n - 1])) roots[n++] = r;
  }
  return n;
}

/* The speed's critical points: real roots in (0, 1) of
** Q'.Q'' = 2|A2|^2 t^3 + 3 (A2.A1) t^2 + (|A1|^2 + 2 A2.A0) t + A1.A0
** (Walter & Fournier Eqn 8's numerator; computed on the scaled hodograph). */
int arclen_critical_points(const double *c, int dim, double roots[3]) {
  arclen_hodo h;
  arclen_hodo_scaled(c, dim, &h);
  if (h.zero) return 0;
  return arclen_hodo_critical(&h, roots);
}

int arclen_hodo_critical(const arclen_hodo *h, double roots[3]) {
  double p[4] = {0, 0, 0, 0};
  int k;
  for (k = 0; k < h->dim; k++) {
    p[3] += 2 * h->a2[k] * h->a2[k];
    p[2] += 3 * h->a2[k] * h->a1[k];
    p[1] += h->a1[k] * h->a1[k] + 2 * h->a2[k] * h->a0[k];
    p[0] += h->a1[k] * h->a0[k];
  }
  return arclen_cubic_roots01(p, roots);
}
