/*
** carlson.c -- Carlson's symmetric elliptic integrals R_F, R_D, R_C, R_J,
** R_G for real arguments, by the duplication theorem.
**
** Source: B. C. Carlson, "Numerical computation of real or complex elliptic
** integrals", Numerical Algorithms 10 (1995) 13-26, arXiv math/9409227
** (below "C95"), Algorithms 1-4 and Eqns (2.14), (2.21)-(2.22).  R_G from
** DLMF 19.21.10.  A domain error (a negative argument, too many zeros, an
** infinite value of the integral, a non-finite argument) gives NaN.
*/
#include <float.h>
#include <math.h>

#include "arclen.h"
#include "elliptic/elliptic.h"

/* Stopping rules in the manner of C95: iterate until 4^-m Q < |A_m|, where
** Q = c * max |A_0 - x_i|, i.e. until every |X_i| < 1/c.  C95's series end
** at degree 5 (error O(X^6), c = (3r)^(-1/6) = 426 for R_F, (r/4)^(-1/6) =
** 645 for R_D, R_J at r = 2^-54); here they run to degree 7 (DLMF 19.36.1,
** 19.36.2, Carlson & Johnson), the first omitted terms of degree 8 with
** coefficients below 1 (those kept are below 0.2), so |X| < 2^-7 leaves a
** truncation error below 2^-56 / (1 - 2^-7): about one duplication step
** fewer (log4 of 426/128 and 645/128).  Checked against mpmath: at X =
** 0.017 the degree-7 series err 1e-19 (R_F 1e-17), the degree-5 6e-16.
** (R_C: closed forms.) */
#define RF_C 128.0
#define RDJ_C 128.0

/* Every iteration divides the spread of the arguments by 4 while A_m
** tends to a limit of the size of the largest argument over log^2 of the
** spread, so the loop stops after ~log4(Q/A) steps: fewer than 60 even for
** 1e-300 against 1e300.  The cap is only a guard. */
#define DUP_MAX 100

/* Arguments beyond 2^+-500 are scaled by an exact power of 4 first
** (the R-functions are homogeneous): R_D and R_J form products like
** sqrt(z)^3 that must stay within double range.  Arguments spread wider
** than 2^1000 cannot all be kept: the largest is brought to 2^500 and the
** tiniest may underflow (zero, or a domain error if that makes two). */
#define BIG 0x1p500
#define SMALL 0x1p-500

static double max3(double a, double b, double c) {
  double m = a > b ? a : b;
  return m > c ? m : c;
}

/* k such that 4^k centres the arguments' range [mn, mx] (mn the smallest
** nonzero one) on 1, or 0 when nothing is beyond 2^+-500. */
static int scale_exp(const double *v, int n) {
  double mx = 0, mn = HUGE_VAL;
  int i;
  for (i = 0; i < n; i++) {
    mx = fmax(mx, v[i]);
    if (v[i] > 0) mn = fmin(mn, v[i]);
  }
  /* an infinite argument (r of R_J's principal value overflows) would make
  ** ilogb INT_MAX and the sum below overflow (UBSan, fuzz_carlson) */
  if (mx == 0 || !(mx < HUGE_VAL) || (mx <= BIG && mn >= SMALL)) return 0;
  if (ilogb(mx) - ilogb(mn) > 1000) return (500 - ilogb(mx)) / 2;
  return -(ilogb(mx) + ilogb(mn)) / 4;
}

static int ok_arg(double v) { return v >= 0 && v < HUGE_VAL; }

/* All n arguments 0 or within [2^-500, 2^500]: nothing to narrow or
** scale (the common case; the checks below cost 1/3 of R_F's time). */
static int moderate(const double *v, int n) {
  int i;
  for (i = 0; i < n; i++)
    if (v[i] != 0 && !(v[i] >= SMALL && v[i] <= BIG)) return 0;
  return 1;
}

/* The smallest nonzero of n arguments (HUGE_VAL if none). */
static double min_pos(const double *v, int n) {
  double mn = HUGE_VAL;
  int i;
  for (i = 0; i < n; i++)
    if (v[i] > 0) mn = fmin(mn, v[i]);
  return mn;
}

/* max / (smallest nonzero) of n arguments, as a binary exponent. */
static int spread_exp(const double *v, int n) {
  double mx = 0, mn = HUGE_VAL;
  int i;
  for (i = 0; i < n; i++) {
    mx = fmax(mx, v[i]);
    if (v[i] > 0) mn = fmin(mn, v[i]);
  }
  return mx == 0 ? 0 : ilogb(mx) - ilogb(mn);
}

/* Arguments spread wider than 2^1000 cannot be scaled into range without
** the tiniest underflowing (R_F(2^700, 2^-1074, 2^-1074) then ran into the
** iteration cap: 1e27 times too large, found by fuzz/fuzz_carlson; R_D
** lost 7e-10 at (2.5e-237, 4e231, 1e-232) and overflowed beyond).  The
** duplication step v <- (v + lambda)/4 (C95 (2.3)) brings the tiniest up to
** ~sqrt(max min): at most 4 steps bring any finite arguments within
** 2^1000.  Written v/4 + lambda/4 so that nothing overflows near DBL_MAX.
** R_F and R_C are unchanged by a step; R_D and R_J (given p, n = 4) gain
** the terms of C95 (2.8), (2.9), weighted 4^-m and added to *sum (*fourn
** returns 4^-m): 3 / (sqrt(z) (z + lambda)) for R_D, and for R_J
** 6 R_C(1, 1 + e) / d with d = (sqrt p + sqrt x)(sqrt p + sqrt y)
** (sqrt p + sqrt z), 1 + e = 2 sqrt(p) (p + lambda) / d as in rj_dup.
** d can pass 2^1024, so it is kept as a mantissa and an exponent.  Every
** term is below the value, so none overflows when the value is finite. */
static double rc_pos(double x, double y);

static void compress(double *v, int n, double *sum, double *fourn) {
  int i, m;
  for (m = 0; m < 4 && spread_exp(v, n) > 1000; m++) {
    double s[4], lam4;
    for (i = 0; i < n; i++) s[i] = sqrt(v[i]);
    lam4 = s[0] * s[1] / 4 + s[0] * s[2] / 4 + s[1] * s[2] / 4;
    if (n == 3 && sum)                                   /* R_D */
      *sum += *fourn * 3 / 4 / s[2] / (v[2] / 4 + lam4);
    if (n == 4) {                                        /* R_J */
      int e[3], es, eh, ed;
      double dm = 1, g, h, ope;
      for (i = 0; i < 3; i++) dm *= frexp(s[3] + s[i], &e[i]);
      ed = e[0] + e[1] + e[2];
      g = frexp(s[3], &es);
      h = frexp(v[3] / 4 + lam4, &eh);
      ope = ldexp(8 * g * h / dm, es + eh - ed);
      *sum += *fourn * ldexp(6 * rc_pos(1, ope) / dm, -ed);
    }
    for (i = 0; i < n; i++) v[i] = v[i] / 4 + lam4;
    *fourn /= 4;
  }
}

static void compress_rf(double v[3]) {
  double fourn = 1;
  compress(v, 3, NULL, &fourn);
}

/* R_F's series to degree 7, DLMF 19.36.1: C95 (2.2)'s 1 - E2/10 + E3/14
** + E2^2/24 - 3 E2 E3/44, then - 5 E2^3/208 + 3 E3^2/104 + E2^2 E3/16. */
static double series_f(double e2, double e3) {
  return 1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44
         - 5 * e2 * e2 * e2 / 208 + 3 * e3 * e3 / 104 + e2 * e2 * e3 / 16;
}

/* C95 Algorithm 1 (R_F), arguments >= 0 with at most one zero. */
static double rf_dup(double x, double y, double z) {
  double a0 = (x + y + z) / 3, a = a0, x0 = x, y0 = y;
  double q = RF_C * max3(fabs(a0 - x), fabs(a0 - y), fabs(a0 - z));
  double fourn = 1, dx, dy, dz, e2, e3;
  int m;
  for (m = 0; m < DUP_MAX && q * fourn >= fabs(a); m++) {
    double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    double lam = sx * sy + sx * sz + sy * sz;
    x = (x + lam) / 4; y = (y + lam) / 4; z = (z + lam) / 4;
    a = (a + lam) / 4;
    fourn /= 4;
  }
  /* X = (A0 - x0)/(4^m A_m): from the inputs, free of cancellation. */
  dx = (a0 - x0) * fourn / a;
  dy = (a0 - y0) * fourn / a;
  dz = -dx - dy;
  e2 = dx * dy - dz * dz;
  e3 = dx * dy * dz;
  return series_f(e2, e3) / sqrt(a);
}

double arclen_rf(double x, double y, double z) {
  int k, zeros = (x == 0) + (y == 0) + (z == 0);
  if (!ok_arg(x) || !ok_arg(y) || !ok_arg(z) || zeros > 1) return NAN;
  {
    double v[3] = {x, y, z};
    if (moderate(v, 3)) return rf_dup(x, y, z);
    compress_rf(v);
    x = v[0]; y = v[1]; z = v[2];
    k = scale_exp(v, 3);
  }
  if (k == 0) return rf_dup(x, y, z);
  x = ldexp(x, 2 * k); y = ldexp(y, 2 * k); z = ldexp(z, 2 * k);
  return ldexp(rf_dup(x, y, z), k);        /* R_F(4^k v) = 2^-k R_F(v) */
}

/* The series of C95 (2.7)/(2.12) shared by R_D and R_J,
** 1 - 3E2/14 + E3/6 + 9E2^2/88 - 3E4/22 - 9E2E3/52 + 3E5/26, to degree 7
** (DLMF 19.36.2): - E2^3/16 + 3E3^2/40 + 3E2E4/20 + 45E2^2E3/272
** - 9(E3E4 + E2E5)/68. */
static double series_dj(double e2, double e3, double e4, double e5) {
  return 1 - 3 * e2 / 14 + e3 / 6 + 9 * e2 * e2 / 88 - 3 * e4 / 22
         - 9 * e2 * e3 / 52 + 3 * e5 / 26
         - e2 * e2 * e2 / 16 + 3 * e3 * e3 / 40 + 3 * e2 * e4 / 20
         + 45 * e2 * e2 * e3 / 272 - 9 * (e3 * e4 + e2 * e5) / 68;
}

/* C95 Algorithm 4 (R_D); x, y >= 0, at most one zero; z > 0. */
static double rd_dup(double x, double y, double z) {
  double a0 = (x + y + 3 * z) / 5, a = a0, x0 = x, y0 = y;
  double q = RDJ_C * max3(fabs(a0 - x), fabs(a0 - y), fabs(a0 - z));
  double fourn = 1, sum = 0, dx, dy, dz, xy, zz;
  int m;
  for (m = 0; m < DUP_MAX && q * fourn >= fabs(a); m++) {
    double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    double lam = sx * sy + sx * sz + sy * sz;
    sum += fourn / (sz * (z + lam));
    x = (x + lam) / 4; y = (y + lam) / 4; z = (z + lam) / 4;
    a = (a + lam) / 4;
    fourn /= 4;
  }
  dx = (a0 - x0) * fourn / a;
  dy = (a0 - y0) * fourn / a;
  dz = -(dx + dy) / 3;
  xy = dx * dy; zz = dz * dz;
  return fourn * series_dj(xy - 6 * zz, (3 * xy - 8 * zz) * dz,
                           3 * (xy - zz) * zz, xy * zz * dz)
           / (a * sqrt(a))
         + 3 * sum;
}

double arclen_rd(double x, double y, double z) {
  int k;
  if (!ok_arg(x) || !ok_arg(y) || !ok_arg(z) || z == 0 || (x == 0 && y == 0))
    return NAN;
  {
    double v[3] = {x, y, z}, sum = 0, fourn = 1;
    int e;
    if (moderate(v, 3)) return rd_dup(x, y, z);
    compress(v, 3, &sum, &fourn);
    x = v[0]; y = v[1]; z = v[2];
    k = scale_exp(v, 3);
    x = ldexp(x, 2 * k); y = ldexp(y, 2 * k); z = ldexp(z, 2 * k);
    /* R_D(4^k v) = 8^-k R_D(v); fourn = 4^-m is exact */
    frexp(fourn, &e);
    return ldexp(rd_dup(x, y, z), 3 * k + e - 1) + sum;
  }
}

/* R_C is elementary (C95 (2.5)-(2.6), DLMF 19.2.17-19.2.18):
**   y > x: atan(sqrt((y - x)/x)) / sqrt(y - x),
**   y < x: atanh(sqrt((x - y)/x)) / sqrt(x - y),
** one atan or log1p where C95's Algorithm 2 took ~log4 of the spread
** duplication steps with a square root each (R_J takes an R_C in every one
** of its steps).  atanh(s) = log1p(2s/(1 - s))/2 with 1 - s = (y/x)/(1 + s),
** free of cancellation however small y/x.  Near y = x, e = (y - x)/x is
** small and the series of C95 (2.13) in e, R_C(1, 1 + e) =
** sum (-e)^k/(2k + 1), is summed instead: for |e| <= 2^-8 seven terms leave
** |e|^7/15 < 2^-59.  Each form is a few roundings of well-conditioned
** operations (the value's relative condition in e, s and y/x is <= 1).
** x >= 0, y > 0, both within 2^+-500 (the callers scale). */
#define RC_SERIES 0x1p-8

static double rc_dup(double x, double y) {
  double d = y - x, e, s;
  if (x == 0) return 1.5707963267948966 / sqrt(y);         /* pi / 2 */
  e = d / x;
  if (fabs(e) <= RC_SERIES)
    return (1 - e * (1.0 / 3 - e * (1.0 / 5 - e * (1.0 / 7 - e * (1.0 / 9
            - e * (1.0 / 11 - e * (1.0 / 13))))))) / sqrt(x);
  if (d > 0) {
    s = sqrt(e);
    return atan(s) / sqrt(d);
  }
  s = sqrt(-e);
  return log1p(2 * s * (1 + s) * (x / y)) / 2 / sqrt(-d);
}

/* R_C(1, y), y > 0, the form R_J's duplication takes at every step: as
** rc_dup with x = 1 (1 - s = y/(1 + s), so 2s/(1 - s) = 2s(1 + s)/y). */
static double rc_one(double y) {
  double e = y - 1, s;
  if (fabs(e) <= RC_SERIES)
    return 1 - e * (1.0 / 3 - e * (1.0 / 5 - e * (1.0 / 7 - e * (1.0 / 9
           - e * (1.0 / 11 - e * (1.0 / 13))))));
  s = sqrt(fabs(e));
  if (e > 0) return atan(s) / s;
  return log1p(2 * s * (1 + s) / y) / (2 * s);
}

static double rc_pos(double x, double y) {
  double v[3] = {x, y, y};   /* R_C(x, y) = R_F(x, y, y) */
  int k;
  if (moderate(v, 2)) return rc_dup(x, y);
  compress_rf(v);
  x = v[0]; y = v[1];
  k = scale_exp(v, 2);
  if (k == 0) return rc_dup(x, y);
  return ldexp(rc_dup(ldexp(x, 2 * k), ldexp(y, 2 * k)), k);
}

double arclen_rc(double x, double y) {
  if (!ok_arg(x) || !(y == y) || fabs(y) == HUGE_VAL || y == 0) return NAN;
  if (y > 0) return rc_pos(x, y);
  /* Cauchy principal value, C95 (2.14):
  ** R_C(x, y) = sqrt(x/(x - y)) R_C(x - y, -y) for y < 0. */
  if (x == 0) return 0;
  /* sqrt(x) / sqrt(x - y): x / (x - y) underflowed for x = 1e-201,
  ** y = -4.5e170 (0 for 7.5e-272) */
  if (x - y < HUGE_VAL) return sqrt(x) / sqrt(x - y) * rc_pos(x - y, -y);
  /* x - y = 4 w overflows (rc(DBL_MAX, -DBL_MAX), fuzz_carlson):
  ** sqrt(x - y) = 2 sqrt(w), R_C(4w, -y) = R_C(w, -y/4) / 2 */
  {
    double w = x / 4 - y / 4;
    return sqrt(x) / sqrt(w) * rc_pos(w, -y / 4) / 4;
  }
}

static double rc_pos(double x, double y);

/* R_J's lambda_m involves x, y, z only, so p_m - x_m = 4^-m (p - x): for p
** far above x, y, z the duplication closes the gap only by 4 per step and
** C95's stopping test needs log4(p / x) of them (about 500 for
** rj(1, 2, 3, 1e300); the cap of 100 left the series at X ~ 1:
** rj(1, 2, 3, 2^500) was 2.7e-195 for 6.7e-151).  Once x, y, z agree to
** RJ_SETTLED relative, the rest is R_J(mu, mu, mu, p_m) with mu their mean
** (R_J is symmetric in x, y, z, so the first-order error vanishes: what is
** left is O(RJ_SETTLED^2) = 2^-80), in closed form (DLMF 19.20.7 with
** x = y, R_C(mu, mu) = mu^-1/2):
**   R_J(mu, mu, mu, p) = 3 (mu^-1/2 - R_C(mu, p)) / (p - mu).
** For p >= RJ_FAR mu the subtraction loses under 1.1x: R_C(mu, 256 mu)
** = acos(1/16) / sqrt(255 mu) = 0.094 mu^-1/2. */
#define RJ_SETTLED 0x1p-40
#define RJ_FAR 256

static double rj_equal(double mu, double p) {
  return 3 * (1 / sqrt(mu) - rc_pos(mu, p)) / (p - mu);
}

/* C95 Algorithm 3 (R_J); x, y, z >= 0 with at most one zero, p > 0. */
static double rj_dup(double x, double y, double z, double p) {
  double a0 = (x + y + z + 2 * p) / 5, a = a0, x0 = x, y0 = y, z0 = z;
  double q = RDJ_C * fmax(max3(fabs(a0 - x), fabs(a0 - y), fabs(a0 - z)),
                          fabs(a0 - p));
  double fourn = 1, sum = 0, dx, dy, dz, dp, e2, e3, xyz;
  int m;
  for (m = 0; m < DUP_MAX && q * fourn >= fabs(a); m++) {
    double mu = (x + y + z) / 3, sx, sy, sz, sp, lam, d, ope;
    if (p >= RJ_FAR * mu
        && max3(fabs(x - mu), fabs(y - mu), fabs(z - mu)) <= RJ_SETTLED * mu)
      return fourn * rj_equal(mu, p) + 6 * sum;
    sx = sqrt(x); sy = sqrt(y); sz = sqrt(z); sp = sqrt(p);
    lam = sx * sy + sx * sz + sy * sz;
    d = (sp + sx) * (sp + sy) * (sp + sz);
    /* R_C(1, 1 + e_m) with e_m = (p-x)(p-y)(p-z)/d_m^2.  When p is much
    ** smaller than x, y, z (every near-cusp Bezier curve) e_m is near -1
    ** and 1 + e_m cancels; expanding (p-x)(p-y)(p-z) = d_m prod(sp - s.)
    ** gives 1 + e_m = 2 sqrt(p_m)(p_m + lambda_m)/d_m without the
    ** subtraction.  Used always: it measured better for every e_m. */
    ope = 2 * sp * (p + lam) / d;
    sum += fourn / d * rc_one(ope);
    x = (x + lam) / 4; y = (y + lam) / 4; z = (z + lam) / 4;
    p = (p + lam) / 4;
    a = (a + lam) / 4;
    fourn /= 4;
  }
  dx = (a0 - x0) * fourn / a;
  dy = (a0 - y0) * fourn / a;
  dz = (a0 - z0) * fourn / a;
  dp = -(dx + dy + dz) / 2;
  xyz = dx * dy * dz;
  e2 = dx * dy + dx * dz + dy * dz - 3 * dp * dp;
  e3 = xyz + 2 * e2 * dp + 4 * dp * dp * dp;
  return fourn * series_dj(e2, e3, (2 * xyz + e2 * dp + 3 * dp * dp * dp) * dp,
                           xyz * dp * dp)
           / (a * sqrt(a))
         + 6 * sum;
}

/* R_J's spread may come from p alone, with x, y, z subnormal: lambda is
** then subnormal too and each compress step would lose bits (R_J(2.5e-321,
** 2.5e-321, 2.5e-321, 11) was 3e-4 off, fuzz_carlson).  Scaling up by 4^k
** is exact, so the smallest nonzero argument is first brought to the
** normal range when the largest allows: returns k. */
static int lift_subnormal(double *v, int n) {
  double mx = 0, mn = HUGE_VAL;
  int i, k;
  for (i = 0; i < n; i++) {
    mx = fmax(mx, v[i]);
    if (v[i] > 0) mn = fmin(mn, v[i]);
  }
  if (mx == 0 || mn >= DBL_MIN) return 0;
  k = (DBL_MIN_EXP - 1 - ilogb(mn)) / 2 + 1;
  if (k > (1020 - ilogb(mx)) / 2) k = (1020 - ilogb(mx)) / 2;
  if (k <= 0) return 0;
  for (i = 0; i < n; i++) v[i] = ldexp(v[i], 2 * k);
  return k;
}

static double rj_pos(double x, double y, double z, double p) {
  double v[4] = {x, y, z, p}, sum = 0, fourn = 1;
  int k, e, k0;
  if (moderate(v, 4)) return rj_dup(x, y, z, p);
  k0 = lift_subnormal(v, 4);
  if (k0 > 0)                  /* R_J(v) = 8^k R_J(4^k v), DLMF 19.20.12 ff. */
    return ldexp(rj_pos(v[0], v[1], v[2], v[3]), 3 * k0);
  compress(v, 4, &sum, &fourn);
  k = scale_exp(v, 4);
  if (spread_exp(v, 4) > 1000) {
    /* p far above x, y, z, which duplication cannot narrow: scale_exp's
    ** 2^500 top pushed them subnormal (R_J(4e-323 thrice, 2.7e154) was
    ** inf, fuzz_carlson).  rj_dup's products (d, A^3/2) stay finite for
    ** a top up to 2^660, so the smallest is kept normal within that. */
    int lo = (DBL_MIN_EXP - 1 - ilogb(min_pos(v, 4))) / 2 + 1;
    int hi = (660 - ilogb(max3(v[0], v[1], fmax(v[2], v[3])))) / 2;
    if (k < lo) k = lo < hi ? lo : hi;
  }
  frexp(fourn, &e);
  return ldexp(rj_dup(ldexp(v[0], 2 * k), ldexp(v[1], 2 * k),
                      ldexp(v[2], 2 * k), ldexp(v[3], 2 * k)),
               3 * k + e - 1) + sum;
}

/* R_J's Cauchy principal value, p < 0 (DLMF 19.20.14, C95 (2.22)), written
** with x <= y <= z, q = -p > 0 and r = z - (z - x)(z - y)/(z + q)
** = (z(x + q) + y(z - x))/(z + q) > 0 (the sum form does not cancel):
** (z + q) R_J(x,y,z,-q) = (r - z) R_J(x,y,z,r) - 3 R_F(x,y,z)
**                         + 3 sqrt(xyz/(xy + rq)) R_C(xy + rq, rq).
** (checked against mpmath's principal value, tools/ref_carlson.py)
** The arguments come centred on 1 (arclen_rj), all within 2^+-500 unless
** they spread beyond 2^1000, so products of two stay in range; xyz is
** formed as z (xy / (xy + rq)): x, y, z of 1e200 with p = -1 gave inf. */
static double rj_pv(double x, double y, double z, double p) {
  double t, q, r, v;
  if (x > y) { t = x; x = y; y = t; }
  if (y > z) { t = y; y = z; z = t; }
  if (x > y) { t = x; x = y; y = t; }
  q = -p;
  t = (z - x) * (z - y) / (z + q);       /* z - r */
  r = (z * (x + q) + y * (z - x)) / (z + q);
  v = -t * rj_pos(x, y, z, r) - 3 * arclen_rf(x, y, z);
  if (x > 0) {
    double xy = x * y, w = xy + r * q;
    v += 3 * sqrt(z * (xy / w)) * rc_pos(w, r * q);
  }
  return v / (z + q);
}

/* The same reduction for arguments spread beyond 2^1000, unscaled: a
** common power of 4 cannot hold them all (the tiniest flushed to 0, so
** rj(5.2e-202, 5.5e273, 8.1e189, -7.9e-207) was NaN), while each R-function
** of the reduction narrows its own arguments (compress).  Every product is
** formed with ratios near 1, so none overflows or underflows where the
** terms are finite: z - r = (z - x) ((z - y)/(z + q)), r = (x + q)
** (z/(z + q)) + y ((z - x)/(z + q)) (z ((x + q)/(z + q)) went subnormal:
** 1.8e-13 off), xy + rq as mantissas and exponents. */
static double rj_pv_wide(double x, double y, double z, double p) {
  double t, q, r, v, zq;
  if (x > y) { t = x; x = y; y = t; }
  if (y > z) { t = y; y = z; z = t; }
  if (x > y) { t = x; x = y; y = t; }
  q = -p;
  zq = z + q;
  /* z + q beyond DBL_MAX: R_J(v) = R_J(v/4)/8 (homogeneity), once */
  if (!(zq < HUGE_VAL)) return rj_pv_wide(x / 4, y / 4, z / 4, p / 4) / 8;
  t = (z - x) * ((z - y) / zq);
  r = (x + q) * (z / zq) + y * ((z - x) / zq);
  v = -(t / zq) * rj_pos(x, y, z, r) - 3 * (arclen_rf(x, y, z) / zq);
  if (x > 0) {
    /* 3 sqrt(xyz/w) R_C(w, rq), w = xy + rq: xy and rq can each pass the
    ** double range, so they are kept as mantissa and exponent (frexp);
    ** with B the larger and S the smaller, w = B (1 + S/B), R_C(w, rq) =
    ** R_C(1, rq/w) / sqrt(w) and the term is 3 sqrt(xyz) R_C(1, rq/w) / w. */
    int ex, ey, er, eq, ez, exy, erq, eb, ew;
    double fxy = frexp(x, &ex) * frexp(y, &ey), frq = frexp(r, &er) * frexp(q, &eq);
    double fz = frexp(z, &ez), fb, ratio, fw, c, num;
    exy = ex + ey; erq = er + eq;
    if (exy + log2(fxy) >= erq + log2(frq)) {
      fb = fxy; eb = exy; ratio = ldexp(frq / fxy, erq - exy);
    } else {
      fb = frq; eb = erq; ratio = ldexp(fxy / frq, exy - erq);
    }
    fw = fb * (1 + ratio); ew = eb;               /* w = fw 2^ew */
    c = rc_pos(1, ldexp(frq / fw, erq - ew));     /* rq / w <= 1 */
    if (ez % 2 != 0) { fz *= 2; ez--; }           /* sqrt(z) = sqrt(fz) 2^(ez/2) */
    if (exy % 2 != 0) { fxy *= 2; exy--; }
    num = 3 * sqrt(fz) * sqrt(fxy) * c / fw;
    num /= frexp(zq, &eq);                        /* / (z + q) */
    v += ldexp(num, ez / 2 + exy / 2 - ew - eq);
  }
  return v;
}

double arclen_rj(double x, double y, double z, double p) {
  int k;
  if (!ok_arg(x) || !ok_arg(y) || !ok_arg(z) || !(p == p)
      || fabs(p) == HUGE_VAL || p == 0)
    return NAN;
  if (p > 0) {
    if ((x == 0) + (y == 0) + (z == 0) > 1) return NAN;
    return rj_pos(x, y, z, p);
  }
  /* The principal value's products overflow beyond 2^512 (rj(1, 2, 3,
  ** -1e308) gave NaN) and its R_J(x, y, z, r) for x, y, z of 1e-300 (a
  ** NaN from 0 * inf): R_J is homogeneous of degree -3/2 (DLMF 19.20.12
  ** ff.), R_J(v) = 8^k R_J(4^k v), exact in binary, so the arguments are
  ** centred on 1 first as for p > 0 (scale_exp); the value (about
  ** -3 R_F / |p|, -2.2e-308 at (1, 2, 3, -1e308)) is representable.  A
  ** second argument flushed to 0 by that is a domain error (NaN). */
  {
    double v[4] = {x, y, z, -p};
    if (spread_exp(v, 4) > 1000) return rj_pv_wide(x, y, z, p);
    k = scale_exp(v, 4);
  }
  x = ldexp(x, 2 * k); y = ldexp(y, 2 * k); z = ldexp(z, 2 * k);
  p = ldexp(p, 2 * k);
  if ((x == 0) + (y == 0) + (z == 0) > 1 || p == 0) return NAN;
  return ldexp(rj_pv(x, y, z, p), 3 * k);
}

/* R_G by DLMF 19.21.10 with z the middle argument, so that
** (x - z)(y - z) <= 0 and nothing cancels:
** 2 R_G = z R_F - (x - z)(y - z) R_D / 3 + sqrt(x y / z). */
double arclen_rg(double x, double y, double z) {
  double t;
  int e, k;
  if (!ok_arg(x) || !ok_arg(y) || !ok_arg(z)) return NAN;
  if (x > y) { t = x; x = y; y = t; }
  if (y > z) { t = y; y = z; z = t; }
  if (x > y) { t = x; x = y; y = t; }
  /* now x <= y <= z; put the middle one last */
  /* R_G(0, 0, z) = sqrt(z)/2, and R_G(x, y, z) = sqrt(z)/2 (1 + O(y/z
  ** log(z/y))) for x <= y << z: below y/z = 2^-120 the correction is under
  ** 1e-33, while R_D(x, z, y) ~ 1/(y sqrt z) would overflow (fuzz_carlson) */
  if (y <= ldexp(z, -120)) return sqrt(z) / 2;
  /* R_G(4^-k x, 4^-k y, 4^-k z) = 2^-k R_G (homogeneity, exact in binary):
  ** bring z into [1/4, 4) so that subnormal arguments do not give 0 * inf
  ** in the R_D term, nor huge ones an overflowing x z (fuzz/fuzz_carlson). */
  frexp(z, &e);
  k = e / 2;
  x = ldexp(x, -2 * k);
  y = ldexp(y, -2 * k);
  z = ldexp(z, -2 * k);
  return ldexp((y * arclen_rf(x, z, y) +
                (y - x) * (z - y) * arclen_rd(x, z, y) / 3 +
                sqrt(x * z / y)) / 2, k);
}

/* R_F(x, y, z), R_D(x, y, z) and R_J(x, y, z, p) together, as Carlson's
** [1,1,1,1] needs them (product.c): the duplication's lambda = sqrt(xy) +
** sqrt(xz) + sqrt(yz) (C95 (2.3)) is symmetric in x, y, z, so one sequence
** x_m, y_m, z_m serves all three, each with its own mean A_m (C95
** Algorithms 1, 3, 4: (x + y + z)/3, (x + y + 3z)/5, (x + y + z + 2p)/5,
** all stepped as (A + lambda)/4) and its own stopping test; the loop ends
** when the last is met.  The square roots and the loop, 3/5 of the work
** of the three calls apart, are shared.  Arguments outside the plain case
** (non-moderate, p far above x, y, z, a domain edge) go to the separate
** functions, which scale, compress and settle as they need. */
void arclen_rfdj(double x, double y, double z, double p, double *rf,
                 double *rd, double *rj) {
  double v[4] = {x, y, z, p};
  double af0 = (x + y + z) / 3, ad0 = (x + y + 3 * z) / 5;
  double aj0 = (x + y + z + 2 * p) / 5, af = af0, ad = ad0, aj = aj0;
  double x0 = x, y0 = y, z0 = z, p0 = p, qf, qd, qj, fourn = 1;
  double sumd = 0, sumj = 0, dx, dy, dz, dp, e2, e3, xy, zz, xyz;
  int m;
  if (!ok_arg(x) || !ok_arg(y) || !(z > 0 && z < HUGE_VAL) ||
      !(p > 0 && p < HUGE_VAL) || (x == 0) + (y == 0) > 0 || !moderate(v, 4) ||
      p > RJ_FAR * max3(x, y, z)) {
    *rf = arclen_rf(x, y, z);
    *rd = arclen_rd(x, y, z);
    *rj = arclen_rj(x, y, z, p);
    return;
  }
  qf = RF_C * max3(fabs(af0 - x), fabs(af0 - y), fabs(af0 - z));
  qd = RDJ_C * max3(fabs(ad0 - x), fabs(ad0 - y), fabs(ad0 - z));
  qj = RDJ_C * fmax(max3(fabs(aj0 - x), fabs(aj0 - y), fabs(aj0 - z)),
                    fabs(aj0 - p));
  /* p <= RJ_FAR max(x, y, z): the gap p - x closes by 4 a step like the
  ** others', so the cap is as far off as for R_F */
  for (m = 0; m < DUP_MAX && (qf * fourn >= af || qd * fourn >= ad ||
                              qj * fourn >= aj); m++) {
    double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z), sp = sqrt(p);
    double lam = sx * sy + sx * sz + sy * sz;
    double id = 1 / ((sp + sx) * (sp + sy) * (sp + sz));
    sumd += fourn / (sz * (z + lam));
    sumj += fourn * id * rc_one(2 * sp * (p + lam) * id);    /* as rj_dup */
    x = (x + lam) / 4; y = (y + lam) / 4; z = (z + lam) / 4;
    p = (p + lam) / 4;
    af = (af + lam) / 4; ad = (ad + lam) / 4; aj = (aj + lam) / 4;
    fourn /= 4;
  }
  dx = (af0 - x0) * fourn / af;                         /* R_F, as rf_dup */
  dy = (af0 - y0) * fourn / af;
  dz = -dx - dy;
  e2 = dx * dy - dz * dz;
  e3 = dx * dy * dz;
  *rf = series_f(e2, e3) / sqrt(af);
  dx = (ad0 - x0) * fourn / ad;                         /* R_D, as rd_dup */
  dy = (ad0 - y0) * fourn / ad;
  dz = -(dx + dy) / 3;
  xy = dx * dy; zz = dz * dz;
  *rd = fourn * series_dj(xy - 6 * zz, (3 * xy - 8 * zz) * dz,
                          3 * (xy - zz) * zz, xy * zz * dz) / (ad * sqrt(ad))
        + 3 * sumd;
  dx = (aj0 - x0) * fourn / aj;                         /* R_J, as rj_dup */
  dy = (aj0 - y0) * fourn / aj;
  dz = (aj0 - z0) * fourn / aj;
  dp = -(dx + dy + dz) / 2;
  (void)p0;
  xyz = dx * dy * dz;
  e2 = dx * dy + dx * dz + dy * dz - 3 * dp * dp;
  e3 = xyz + 2 * e2 * dp + 4 * dp * dp * dp;
  *rj = fourn * series_dj(e2, e3, (2 * xyz + e2 * dp + 3 * dp * dp * dp) * dp,
                          xyz * dp * dp) / (aj * sqrt(aj))
        + 6 * sumj;
}
