/*
** roots.c -- roots of real quadratics, cubics and quartics, in the manner
** of Orellana & De Michele, ACM TOMS Algorithm 1010 (2020): scaling, a
** root of a cubic resolvent (two forms, every root tried), the quartic
** split into two real quadratic factors, Newton polishing of the factors'
** coefficients, and quadratics solved without cancellation; roots of
** widely spread sizes by groups of the Newton polygon, a group's factor
** polished on the whole polynomial (Bairstow).
** The code is ours; the method follows that paper.
*/
#include <float.h>
#include <limits.h>
#include <math.h>

#include "arclen.h"
#include "roots/roots3d.h"
#include "curve/numeric.h"

#define NEWTON_CAP 16     /* quadratic convergence; guards NaN/limit cycles */

/* |a + ib|: sqrt(a^2 + b^2) where the larger part is within 2^+-500 (no
** square overflows, none that matters underflows; within an ulp of
** hypot), else hypot.  libm's hypot was a third of the quartic's time. */
static double mag(double a, double b) {
  double m = fmax(fabs(a), fabs(b));
  if (m > 0x1p-500 && m < 0x1p500) return sqrt(a * a + b * b);
  return hypot(a, b);
}

/* Roots of a2 x^2 + a1 x + a0; the one that would cancel in -a1 +- sqrt(d)
** comes from the product of the roots instead.  Returns the count. */
int arclen_quadratic(double a2, double a1, double a0, double re[2],
                     double im[2]) {
  double d, q, m = fmax(fabs(a1), sqrt(fabs(a2)) * sqrt(fabs(a0)));
  if (a2 == 0) {
    if (a1 == 0) return 0;
    re[0] = -a0 / a1; im[0] = 0;
    return 1;
  }
  /* The roots do not change when every coefficient is scaled by a power of
  ** two (exact): with m ~ 1, a1^2 and a2 a0 neither underflow (subnormal
  ** coefficients gave a root 0.25 for +-2.9e-143i) nor overflow (found by
  ** fuzz/fuzz_roots). */
  if (a0 == 0) {               /* x (a2 x + a1): no discriminant needed */
    re[0] = 0; re[1] = -a1 / a2;
    im[0] = im[1] = 0;
    return 2;
  }
  if (m < 0x1p-450 || m > 0x1p450) {
    int e;
    frexp(m, &e);
    /* ... but never so far that a2 or a0 overflows (a0 tiny, a2 = 47) */
    e = e > ilogb(fmax(fabs(a2), fabs(a0))) - 1020
            ? e : ilogb(fmax(fabs(a2), fabs(a0))) - 1020;
    a2 = ldexp(a2, -e); a1 = ldexp(a1, -e); a0 = ldexp(a0, -e);
  }
  /* the discriminant with one rounding error: fma keeps a1^2's low bits */
  {
    double p = a1 * a1, pe = arclen_fma(a1, a1, -p);
    /* 4 (a2 a0), not (4 a2) a0: a2 near DBL_MAX with a0 = 0 gave inf * 0 */
    double t = a2 * a0, r = 4 * t, re_ = 4 * arclen_fma(a2, a0, -t);
    d = (p - r) + (pe - re_);
  }
  if (d >= 0) {
    q = -(a1 + copysign(sqrt(d), a1)) / 2;
    if (q == 0) { re[0] = re[1] = 0; im[0] = im[1] = 0; return 2; }
    re[0] = q / a2; re[1] = a0 / q;
    im[0] = im[1] = 0;
  } else {
    re[0] = re[1] = -a1 / (2 * a2);
    im[0] = sqrt(-d) / (2 * fabs(a2));
    im[1] = -im[0];
  }
  return 2;
}

/* Monic cubic x^3 + b x^2 + c x + d at x, and its derivative. */
static double cubic_val(double b, double c, double d, double x, double *dv) {
  *dv = (3 * x + 2 * b) * x + c;
  return ((x + b) * x + c) * x + d;
}

/* x polished by Newton on the monic cubic, kept while |value| falls. */
static double cubic_polish(double b, double c, double d, double x) {
  double fx, dv, best = x, bestf = fabs(cubic_val(b, c, d, x, &dv));
  int i;
  for (i = 0; i < NEWTON_CAP && bestf > 0 && dv != 0; i++) {
    x -= cubic_val(b, c, d, x, &dv) / dv;
    fx = fabs(cubic_val(b, c, d, x, &dv));
    if (!(fx < bestf)) break;
    best = x; bestf = fx;
  }
  return best;
}

/* The real root of largest value (three real roots) or the single real
** root, by Cardano/Viete on the depressed cubic, polished by Newton. */
static double cubic_root(double b, double c, double d) {
  double p = c - b * b / 3, q = (2 * b * b / 27 - c / 3) * b + d;
  double x, disc = q * q / 4 + p * p * p / 27;
  if (disc > 0) {
    double u = cbrt(-q / 2 - copysign(sqrt(disc), q));
    x = (u != 0 ? u - p / (3 * u) : 0) - b / 3;
  } else {
    double m = sqrt(-p / 3), ar = (m > 0) ? (3 * q) / (2 * p * m) : 0;
    ar = fmax(-1, fmin(1, ar));
    x = 2 * m * cos(acos(ar) / 3) - b / 3;   /* the largest root */
  }
  return cubic_polish(b, c, d, x);
}

/* Residual of the factorisation (x^2+p1 x+q1)(x^2+p2 x+q2) of the monic
** quartic x^4 + a x^3 + b x^2 + c x + d, and its Jacobian. */
static void factor_residual(const double *v, const double *m, double *f,
                            double jac[4][4]) {
  double p1 = v[0], q1 = v[1], p2 = v[2], q2 = v[3];
  f[0] = p1 + p2 - m[0];
  f[1] = q1 + q2 + p1 * p2 - m[1];
  f[2] = p1 * q2 + p2 * q1 - m[2];
  f[3] = q1 * q2 - m[3];
  if (jac == NULL) return;
  jac[0][0] = 1;  jac[0][1] = 0;  jac[0][2] = 1;  jac[0][3] = 0;
  jac[1][0] = p2; jac[1][1] = 1;  jac[1][2] = p1; jac[1][3] = 1;
  jac[2][0] = q2; jac[2][1] = p2; jac[2][2] = q1; jac[2][3] = p1;
  jac[3][0] = 0;  jac[3][1] = q2; jac[3][2] = 0;  jac[3][3] = q1;
}

/* Solve J x = f (4x4) by elimination with partial pivoting; 0 if singular. */
static int solve4(double j[4][4], double *f) {
  int i, k, r;
  for (k = 0; k < 4; k++) {
    int p = k;
    for (i = k + 1; i < 4; i++) if (fabs(j[i][k]) > fabs(j[p][k])) p = i;
    if (j[p][k] == 0) return 0;
    if (p != k) {
      double t;
      for (r = 0; r < 4; r++) { t = j[k][r]; j[k][r] = j[p][r]; j[p][r] = t; }
      t = f[k]; f[k] = f[p]; f[p] = t;
    }
    for (i = k + 1; i < 4; i++) {
      double l = j[i][k] / j[k][k];
      for (r = k; r < 4; r++) j[i][r] -= l * j[k][r];
      f[i] -= l * f[k];
    }
  }
  for (k = 3; k >= 0; k--) {
    for (r = k + 1; r < 4; r++) f[k] -= j[k][r] * f[r];
    f[k] /= j[k][k];
  }
  return 1;
}

/* Componentwise backward error of the factorisation: each equation's
** residual relative to the size of its terms, so a factor of small
** coefficients (roots 2^-17 beside one of 1) is held to its own scale,
** not to the largest coefficient's (found by fuzz/fuzz_roots). */
static double resid_norm(const double *v, const double *m) {
  double f[4], w[4], r = 0;
  int k;
  factor_residual(v, m, f, NULL);
  w[0] = fabs(v[0]) + fabs(v[2]) + fabs(m[0]);
  w[1] = fabs(v[1]) + fabs(v[3]) + fabs(v[0] * v[2]) + fabs(m[1]);
  w[2] = fabs(v[0] * v[3]) + fabs(v[2] * v[1]) + fabs(m[2]);
  w[3] = fabs(v[1] * v[3]) + fabs(m[3]);
  /* terms below DBL_MIN are rounded absolutely (subnormal): 9.9e-324 +
  ** 9.9e-324 - 2e-323 is "relative error 1" (7 x^4 + 1.2e-321 x^3 + 126
  ** x^2 + 122 then lost its true factors: fuzz/fuzz_roots) */
  for (k = 0; k < 4; k++) r += fabs(f[k]) / fmax(w[k], DBL_MIN);
  return r;
}

/* The monic cubic y^3 + b y^2 + c y + d (scaled): its largest real root
** and the deflated quadratic y^2 + e y + f. */
static double cubic_deflate(double b, double c, double d, double *e,
                            double *f) {
  double r = cubic_root(b, c, d), f1, f2;
  /* f from the equation that leaves the smaller residual in the other */
  *e = b + r;
  f1 = c + r * *e;
  f2 = r != 0 ? -d / r : f1;
  *f = fabs(r * f1 + d) <= fabs(f2 - r * *e - c) ? f1 : f2;
  return r;
}

/* Residual at or below this (a sum of four relative residuals, each
** evaluated with about two roundings) is rounding noise: stop there. */
#define FACTOR_GOOD (8 * DBL_EPSILON)

/* Newton on the four coefficient equations from v; v ends as the iterate
** of least residual, which is returned.  A step may raise the residual
** on the way to convergence (as Bairstow's first step does in
** polish_factor), so the iteration goes on until STALL steps in a row
** bring nothing better.  The cap is above NEWTON_CAP: at a double pair of
** factors (x^2 + x/2 + 1/2)^2 the Jacobian (whose determinant is the
** factors' resultant) is singular and Newton only halves the error per
** step, from the ~eps^(1/4) that a double root of the resolvent leaves in
** e = sqrt(e^2) down to the sqrt(eps) whose square is the rounding level
** of the residual: about 13 halvings. */
#define FACTOR_NEWTON_CAP 40
#define STALL 3

static double factor_newton(const double *m, double *v) {
  double best = resid_norm(v, m), jac[4][4], fv[4], w[4], r;
  int i, k, stall = 0;
  for (k = 0; k < 4; k++) w[k] = v[k];
  for (i = 0; i < FACTOR_NEWTON_CAP && best > FACTOR_GOOD / 8; i++) {
    factor_residual(w, m, fv, jac);
    if (!solve4(jac, fv)) break;
    for (k = 0; k < 4; k++) w[k] -= fv[k];
    r = resid_norm(w, m);
    if (!(r == r) || !isfinite(w[0] + w[1] + w[2] + w[3])) break;
    if (r < best) {
      best = r; stall = 0;
      for (k = 0; k < 4; k++) v[k] = w[k];
    } else if (++stall >= STALL) {
      break;
    }
  }
  return best;
}

/* Ferrari's split of the monic quartic x^4 + a x^3 + b x^2 + c x + d:
** quartic = F^2 - D^2 = (F - D)(F + D), F = x^2 + (a/2) x + y/2,
** D = e x + f, where e^2 = a^2/4 - b + y, f^2 = y^2/4 - d and
** e f = (a y/2 - c)/2, y a root of the classical resolvent
**   y^3 - b y^2 + (ac - 4d) y + (4bd - a^2 d - c^2) = 0.
** Its largest root makes e^2 >= 0 (real factors).  The same in u = e^2,
** shifted by B = b - a^2/4 from the coefficients, with g = (a/2) B - c:
**   u^3 + (2B - a^2/4) u^2 + (B^2 - 4d - a g) u - g^2 = 0,
** y/2 = (B + u)/2, e f = (g + u a/2)/2; its value at 0 is -g^2 <= 0, so
** it has a root u >= 0.  Each form holds its small roots to their own
** size, which the other's shift loses: near a double pair of factors
** u ~ |g| while y = 2 + 2.7e-12 in x^4 - 5.4e-12 x^3 + 2 x^2 + 1 (the
** y-resolvent's constant 8 - a^2 rounds to 8: no real split survives);
** with one root far beyond the other three (2^-17: 3.05e-5 x^4 + 9 x^3
** - 43 x^2 + 51 x + 1) y ~ tiny while all three u crowd about a^2/4
** (fuzz/fuzz_roots, both).  A candidate root gives e^2, y/2 = f0 and e f;
** variant 0 takes the larger of e, f from its square and the other from
** e f; variant 1 both from their squares (sign from e f): when both
** squares are rounding noise the quotient can be noise over noise. */
static void ferrari_start(const double *m, double e2, double f0, double ef,
                          int variant, double *v) {
  double a2 = m[0] / 2, d = m[3], f2 = f0 * f0 - d, e, f;
  if (e2 < 0) e2 = 0;
  if (f2 < 0) f2 = 0;
  if (variant == 1) { e = sqrt(e2); f = copysign(sqrt(f2), ef); }
  else if (e2 * e2 >= f2 * f2 && e2 > 0) { e = sqrt(e2); f = ef / e; }
  else if (f2 > 0) { f = sqrt(f2); e = ef / f; }
  else { e = 0; f = 0; }
  /* the smaller q from q1 q2 = d */
  v[0] = a2 + e; v[2] = a2 - e;
  v[1] = f0 + f; v[3] = f0 - f;
  if (fabs(v[1]) > fabs(v[3]) && v[1] != 0) v[3] = d / v[1];
  else if (v[3] != 0) v[1] = d / v[3];
}

static int poly_roots(const double *p, int n, double *re, double *im);

/* Monic quartic x^4 + m0 x^3 + m1 x^2 + m2 x + m3 (scaled) into
** v = {p1, q1, p2, q2}: Ferrari's split from a root of a resolvent
** (ferrari_start), then Newton on the factors' coefficients (Algorithm
** 1010).  The largest root gives real factors; but where it is double, as
** for a double pair of factors (-(2x^2+x+1)^2 rounded), rounding can make
** it a complex pair, and taking the one real root instead gave a garbage
** split (relative residual 12).  So every root of both resolvents is
** tried, the real part of a complex pair as a real candidate, keeping the
** least residual; the resolvents are solved by the Newton polygon, as
** their small roots sit beside roots of size 1. */
static void factor_monic(const double *m, double *v) {
  double a = m[0], b = m[1], c = m[2], d = m[3], a2 = a / 2;
  double B = b - a2 * a2, g = a2 * B - c, res[2][4], r[3], ri[3];
  double best = HUGE_VAL, w[4], t;
  int pass, form, i, k, variant, nr;
  res[0][3] = 1; res[0][2] = 2 * B - a2 * a2;
  res[0][1] = B * B - 4 * d - 2 * a2 * g; res[0][0] = -g * g;
  res[1][3] = 1; res[1][2] = -b; res[1][1] = a * c - 4 * d;
  res[1][0] = 4 * b * d - a * a * d - c * c;
  /* pass 0: the largest root of the u-form by Cardano (Algorithm 1010's
  ** dominant root), which serves nearly always, at a third of the cost;
  ** then every root of the u-form, then of the y-form */
  for (pass = 0; pass < 3 && best > FACTOR_GOOD; pass++) {
    form = pass == 2;
    if (pass == 0) {
      r[0] = cubic_root(res[0][2], res[0][1], res[0][0]); ri[0] = 0; nr = 1;
    } else {
      nr = poly_roots(res[form], 3, r, ri);
    }
    for (i = 0; i < nr && best > FACTOR_GOOD; i++) {
      double e2, f0, ef;
      if (ri[i] < 0) continue;       /* a complex pair: its real part once */
      if (form == 0) { e2 = r[i]; f0 = (B + r[i]) / 2; ef = (g + a2 * r[i]) / 2; }
      else { e2 = a2 * a2 - b + r[i]; f0 = r[i] / 2; ef = (a2 * r[i] - c) / 2; }
      for (variant = 0; variant < 2 && best > FACTOR_GOOD; variant++) {
        ferrari_start(m, e2, f0, ef, variant, w);
        t = factor_newton(m, w);
        if (t < best || best == HUGE_VAL) {   /* (v is always set) */
          best = isnan(t) ? HUGE_VAL * 0.5 : t;
          for (k = 0; k < 4; k++) v[k] = w[k];
        }
      }
    }
  }
}

/* ---- scaling and the Newton polygon ------------------------------------
** A polynomial is held by power: p[j] is the coefficient of x^j, j = 0..n,
** p[n] != 0.  Every scaled coefficient is formed by exponent arithmetic,
** p[j] / p[h] * 2^(E (j - h)) = ldexp(f_j / f_h, e_j - e_h + E (j - h))
** with p[j] = f_j 2^e_j (frexp): no power s^k is ever formed, so neither a
** subnormal leading coefficient nor 1e308 in the middle overflows. */

/* Neighbouring edges of the Newton polygon whose root magnitudes differ by
** more than 2^SPLIT_BITS are solved apart.  One scaled solve of the whole
** polynomial loses the middle root of (x - 1e-30)(x + 1)(x - 1e30) (the
** cubic's deflation cancels; spec/roots_spec.lua's spread-* rows), while a
** group solved alone starts Newton on the whole polynomial within about
** 2^-SPLIT_BITS relative, which it sharpens in a few steps.  Measured: 6 to
** 30 pass every row of spec/data/roots.tsv, 300 does not; 16 is the middle.
** Below it the polygon's magnitudes are too coarse to separate roots (a
** conjugate pair can lie on two edges about one bit apart). */
#ifndef SPLIT_BITS
#define SPLIT_BITS 16
#endif

typedef struct {
  double f[5];       /* frexp fractions of p[j] (0 for p[j] == 0) */
  int e[5];          /* and exponents */
  double l[5];       /* log2 |p[j]| */
  int n;
} poly;

/* Only the frexp parts (f, e), which dd_value's scaling reads: the
** logs of poly_init cost as much as a Newton step. */
static void poly_init_fe(poly *P, const double *p, int n) {
  int j;
  P->n = n;
  for (j = 0; j <= n; j++) P->f[j] = frexp(p[j], &P->e[j]);
}

static void poly_init(poly *P, const double *p, int n) {
  int j;
  P->n = n;
  for (j = 0; j <= n; j++) {
    P->f[j] = frexp(p[j], &P->e[j]);
    P->l[j] = p[j] != 0 ? P->e[j] + log2(fabs(P->f[j])) : -HUGE_VAL;
  }
}

/* p[j] / p[h] * 2^(E (j - h)), or 0 */
static double scaled(const poly *P, int j, int h, int E) {
  if (P->f[j] == 0) return 0;
  return ldexp(P->f[j] / P->f[h], P->e[j] - P->e[h] + E * (j - h));
}

/* Power-of-two exponent E with the monic sub-polynomial p[lo..hi] / p[hi]
** in y = x / 2^E having coefficients <= 1 (Fujiwara-style bound: the
** largest |p[hi-k]/p[hi]|^(1/k), rounded up to a power of two). */
static int group_scale(const poly *P, int lo, int hi) {
  double m = -HUGE_VAL;
  int k;
  for (k = 1; k <= hi - lo; k++)
    if (P->f[hi - k] != 0) m = fmax(m, (P->l[hi - k] - P->l[hi]) / k);
  return m == -HUGE_VAL ? 0 : (int)floor(m) + 1;
}

/* The upper convex hull of the points (j, log2|p[j]|), j = lo..n with
** p[j] != 0: its vertices into v[], returns their count.  An edge from j1
** to j2 carries j2 - j1 roots of magnitude about 2^((l_j1 - l_j2)/(j2 - j1))
** (the Newton polygon), the magnitudes growing with j. */
static int newton_polygon(const poly *P, int lo, int *v) {
  int j, m = 0;
  for (j = lo; j <= P->n; j++) {
    if (P->f[j] == 0) continue;
    while (m >= 2) {   /* drop v[m-1] if it lies on or below the chord */
      int a = v[m - 2], b = v[m - 1];
      if ((P->l[b] - P->l[a]) * (j - a) <= (P->l[j] - P->l[a]) * (b - a)) m--;
      else break;
    }
    v[m++] = j;
  }
  return m;
}

static double edge_bits(const poly *P, int a, int b) {
  return (P->l[a] - P->l[b]) / (b - a);
}

/* Newton on the whole polynomial scaled to x = 2^E y (coefficients c[j],
** all <= about 1 near the group's roots, so Horner cannot overflow),
** for one root, kept only while its backward error |p| / sum |c_k| |x|^k
** falls: it sharpens roots that the factor split or the group's neglected
** coefficients left coarse, and never makes one worse.  Not |p| alone: at
** a double root p' ~ 0 and a step may land on another root of smaller
** |p| (the double root -1/2 of -x^2 (2x+1)^2 + 5e-116 x - 2e-174 went to
** the tiny pair at 0: two roots lost; fuzz/fuzz_roots).  Nor a step of
** more than a quarter of the root's size: that is a jump to another root
** (from the double root -1 of -x^2 (x+1)^2 + 1.1e-75 x - 4e-323 to 0,
** where the scaled constant term underflows: an exact root of c). */
static void polish_root(const double *c, int n, double *zr, double *zi) {
  double best = HUGE_VAL, xr = *zr, xi = *zi, r0 = mag(xr, xi);
  const double z0r = *zr, z0i = *zi;
  int it, k;
  for (it = 0; it < NEWTON_CAP; it++) {
    double pr = c[n], pi = 0, dr = 0, di = 0, t, den, ap, s = fabs(c[n]);
    double ax = mag(xr, xi), rel;
    for (k = n - 1; k >= 0; k--) {        /* Horner for p and p' */
      t = dr * xr - di * xi + pr; di = dr * xi + di * xr + pi; dr = t;
      t = pr * xr - pi * xi + c[k]; pi = pr * xi + pi * xr; pr = t;
      s = s * ax + fabs(c[k]);
    }
    ap = mag(pr, pi);
    rel = ap > 0 ? ap / s : 0;
    if (!(rel < best) || mag(xr - z0r, xi - z0i) > r0 / 4) break;
    best = rel; *zr = xr; *zi = xi;
    den = dr * dr + di * di;
    if (ap == 0 || den == 0) break;
    xr -= (pr * dr + pi * di) / den;
    xi -= (pi * dr - pr * di) / den;
  }
}

/* The remainder of c[0..n] / (y^2 + u y + v), n <= 4, is b1 (y + u) + b0
** by the recurrence b_k = c_k - u b_(k+1) - v b_(k+2) (Bairstow); b, and
** its derivatives bu, bv in u and v, for k = 0, 1. */
static void bairstow(const double *c, int n, double u, double v, double *b,
                     double *bu, double *bv) {
  double x[7] = {0}, xu[7] = {0}, xv[7] = {0};
  int k;
  for (k = n; k >= 0; k--) {
    x[k] = c[k] - u * x[k + 1] - v * x[k + 2];
    xu[k] = -x[k + 1] - u * xu[k + 1] - v * xu[k + 2];
    xv[k] = -x[k + 2] - u * xv[k + 1] - v * xv[k + 2];
  }
  for (k = 0; k < 2; k++) { b[k] = x[k]; bu[k] = xu[k]; bv[k] = xv[k]; }
}

/* How well the roots of y^2 + u y + v solve c[0..n]: the largest
** componentwise backward error |c(z)| / sum |c_k| |z|^k over them (the
** fuzz invariant; Horner's rounding puts its floor near n eps).  A
** residual of the remainder (b1, b0) is no yardstick: it is rounded
** against terms far larger than the small root's own (spread 2^-17 of
** the scale: 2e-13 relative left in a factor's root). */
static double factor_bwd(const double *c, int n, double u, double v) {
  double re[2], im[2], worst = 0;
  int i, k, nr = arclen_quadratic(1, u, v, re, im);
  for (i = 0; i < nr; i++) {
    double pr = c[n], pi = 0, s = fabs(c[n]), az = mag(re[i], im[i]), t;
    for (k = n - 1; k >= 0; k--) {
      t = pr * re[i] - pi * im[i] + c[k];
      pi = pr * im[i] + pi * re[i]; pr = t;
      s = s * az + fabs(c[k]);
    }
    t = mag(pr, pi);
    if (t > 0) worst = fmax(worst, s > 0 ? t / s : HUGE_VAL);
    if (!(t < HUGE_VAL)) return HUGE_VAL;        /* NaN or overflow */
  }
  return worst;
}

/* The quadratic factor y^2 + u y + v of a group, found from the group's
** own coefficients, polished by Newton on Bairstow's remainder of the
** whole scaled polynomial c[0..n], ending at the iterate whose roots
** solve c best (factor_bwd).  Per-root Newton (polish_root)
** stalls at a near-double pair, where p' is about 0: -x (x+1)^2 +
** 3.75e-12 x^4 kept the group's double root -1 (relative residual
** 3.8e-13, fuzz/fuzz_roots); the pair's factor is well-determined even
** where its roots are not.  The Jacobian is singular at an exact double
** root, so, as for the quartic's factors, convergence there is linear:
** FACTOR_NEWTON_CAP.  The first step from the group's coefficients may
** raise factor_bwd (3.05e-5 x^4 + 25 x^3 - 115 x^2 - x: the small root
** overshoots) before the second lands: the best iterate is kept, as in
** factor_newton.  Below eps the measure is Horner's rounding: done. */
static void polish_factor(const double *c, int n, double *u, double *v) {
  double b[2], bu[2], bv[2], det, nu = *u, nv = *v, r;
  double best = factor_bwd(c, n, *u, *v), rho = fmax(fabs(*u), sqrt(fabs(*v)));
  double u0 = *u, v0 = *v;
  int i, stall = 0;
  for (i = 0; i < FACTOR_NEWTON_CAP && best > DBL_EPSILON; i++) {
    bairstow(c, n, nu, nv, b, bu, bv);
    det = bu[1] * bv[0] - bv[1] * bu[0];
    if (det == 0 || !isfinite(det)) break;
    nu -= (b[1] * bv[0] - bv[1] * b[0]) / det;
    nv -= (bu[1] * b[0] - b[1] * bu[0]) / det;
    if (!isfinite(nu) || !isfinite(nv)) break;
    /* the group's own factor is within about 2^-SPLIT_BITS of the true
    ** one: a step far beyond (a singular Jacobian at a double root) is
    ** headed for another group's roots, which solve c as well */
    if (fabs(nu - u0) > rho / 16 || fabs(nv - v0) > rho * rho / 16) break;
    r = factor_bwd(c, n, nu, nv);
    if (r < best) {
      best = r; stall = 0; *u = nu; *v = nv;
    } else if (++stall >= STALL) {
      break;
    }
  }
}

/* Roots (in y) of the monic y^d + m[0] y^(d-1) + ... + m[d-1], d <= 4, a
** group of the whole polynomial c[0..n] in the same scale. */
static int group_roots(const double *m, int d, const double *c, int n,
                       double *re, double *im) {
  double v[4], e, f;
  int k;
  switch (d) {
    case 1: re[0] = -m[0]; im[0] = 0; return 1;
    case 2:
      e = m[0]; f = m[1];
      polish_factor(c, n, &e, &f);
      return arclen_quadratic(1, e, f, re, im);
    case 3:
      re[0] = cubic_deflate(m[0], m[1], m[2], &e, &f); im[0] = 0;
      polish_factor(c, n, &e, &f);
      return 1 + arclen_quadratic(1, e, f, re + 1, im + 1);
    default:
      factor_monic(m, v);
      k = arclen_quadratic(1, v[0], v[1], re, im);
      return k + arclen_quadratic(1, v[2], v[3], re + k, im + k);
  }
}

/* The groups of the Newton polygon: it is cut where the root magnitudes of
** two neighbouring edges lie more than 2^SPLIT_BITS apart.  Group g spans
** powers gs[g]..gs[g+1].  Returns the count. */
static int split_groups(const poly *P, int lo, int *gs) {
  int v[5] = {0, 0, 0, 0, 0}, nv = newton_polygon(P, lo, v), i, ng = 0;
  double prev = 0;
  gs[0] = v[0];
  for (i = 0; i + 1 < nv; i++) {
    double bits = edge_bits(P, v[i], v[i + 1]);
    if (i > 0 && bits - prev > SPLIT_BITS) gs[++ng] = v[i];
    prev = bits;
  }
  gs[++ng] = v[nv - 1];
  return ng;
}

/* ---- origin shift for clustered roots ----------------------------------
** Roots clustered far from 0 (10000, 10001, 10010, 10100: Algorithm 1010's
** case 17) are ill-determined by the coefficients in x, but well-separated
** in y = x - s about their centroid s = -c[d-1] / (d c[d]) (Algorithm
** 1010's shift).  The coefficients of p(y + s) come from a Taylor shift
** in double-double, so the only new error is one rounding of each. */

/* a + b = s + *e exactly (TwoSum, curve/numeric.h) */
static double two_sum(double a, double b, double *e) {
  arclen_dd r = arclen_two_sum(a, b);
  *e = r.lo;
  return r.hi;
}

/* b[0..d] := coefficients of p(y + s) for p(x) = sum b[j] x^j, by the
** repeated synthetic division b[j] += s b[j+1] (j = d-1..i, i = 0..d-1),
** each step in double-double: hi + lo, lo from fma and TwoSum. */
static void taylor_shift(double *b, int d, double s) {
  double lo[5] = {0, 0, 0, 0, 0};
  int i, j;
  for (i = 0; i < d; i++)
    for (j = d - 1; j >= i; j--) {
      double ph = s * b[j + 1];
      double pe = arclen_fma(s, b[j + 1], -ph) + s * lo[j + 1];
      double e, h = two_sum(b[j], ph, &e);
      e += lo[j] + pe;
      b[j] = h + e;                 /* renormalise (|e| <= ulp(h)) */
      lo[j] = e - (b[j] - h);
    }
}

/* The largest root magnitude of the monic b (b[d] = 1) by its Newton
** polygon: max over k of |b[d-k]|^(1/k), within a factor 2d of it. */
static double root_radius(const double *b, int d) {
  double r = 0;
  int k;
  for (k = 1; k <= d; k++) r = fmax(r, pow(fabs(b[d - k]), 1.0 / k));
  return r;
}

/* Shift when the roots' radius about the centroid (root_radius) is below
** |s| / SHIFT_GAIN: the shifted roots' sizes, hence the perturbation bound
** sum |b_k| |y|^k, drop by about that factor.  Measured: case 17 of
** spec/data/roots1010.tsv (radius 59 about s = 10028) is shifted for gains
** up to 169; both roots specs pass for every gain from 1 to 128. */
#ifndef SHIFT_GAIN
#define SHIFT_GAIN 2
#endif

static int poly_roots_(const double *p, int n, double *re, double *im,
                       int may_shift);

/* The d roots (in the scale 2^E) of the monic c[0..d], c[d] = 1, solved
** about the centroid if that pays (see SHIFT_GAIN); 0 if not shifted. */
static int shifted_roots(const double *c, int d, int E, double *re,
                         double *im) {
  double b[5], s = -c[d - 1] / d;
  int j, k;
  if (d < 3 || s == 0) return 0;
  for (j = 0; j <= d; j++) b[j] = c[j];
  taylor_shift(b, d, s);
  if (!(root_radius(b, d) * SHIFT_GAIN < fabs(s))) return 0;
  poly_roots_(b, d, re, im, 0);
  for (k = 0; k < d; k++) {
    re[k] = ldexp(re[k] + s, E); im[k] = ldexp(im[k], E);
  }
  return 1;
}

/* A quartic whose Newton polygon splits 3 + 1: the lone root r, polished
** on the whole, is divided out (by backward deflation, from the constant
** term, when it is the largest root; forward when the smallest: both
** stable), and the exact cubic cofactor is solved as a polynomial of its
** own, centroid shift included.  The cubic group's own coefficients miss
** r's pull on a near-triple cluster, whose spread (the cube root of it)
** no polishing recovers: 2.9e-11 x^4 - (x + 1)^3 kept -1 (8700 eps;
** fuzz/fuzz_roots).  0 if r is beyond the cluster's scale (out of range:
** its pull is then below rounding) and the groups are solved apart. */
static int roots_3_1(const poly *P, const int *gs, double *re, double *im) {
  int top = gs[2] - gs[1] == 1, la = top ? gs[1] : gs[0];
  int ca = top ? gs[0] : gs[1], El = group_scale(P, la, la + 1);
  int Ec = group_scale(P, ca, ca + 3), j, k;
  double cl[5], cc[5], C[4], r = -scaled(P, la, la + 1, El), ri = 0, R;
  for (j = 0; j <= 4; j++) {
    cl[j] = scaled(P, j, la + 1, El);
    cc[j] = scaled(P, j, ca + 3, Ec);
  }
  polish_root(cl, 4, &r, &ri);
  R = ldexp(r, El - Ec);
  if (!isfinite(R) || fabs(R) < DBL_MIN) return 0;
  if (top) {                  /* cc(y) = (y - R) C(y), from the constant */
    C[0] = -cc[0] / R;
    for (k = 1; k < 3; k++) C[k] = (C[k - 1] - cc[k]) / R;
    C[3] = cc[4];
  } else {                    /* from the leading coefficient */
    C[3] = cc[4];
    for (k = 2; k >= 0; k--) C[k] = cc[k + 1] + R * C[k + 1];
  }
  if (C[3] == 0 || !isfinite(C[0] + C[1] + C[2])) return 0;
  j = top ? 0 : 1;            /* the lower group's roots first */
  poly_roots_(C, 3, re + j, im + j, 1);
  for (k = j; k < j + 3; k++) {
    polish_root(cc, 4, &re[k], &im[k]);
    re[k] = ldexp(re[k], Ec); im[k] = ldexp(im[k], Ec);
  }
  j = top ? 3 : 0;
  re[j] = ldexp(r, El); im[j] = 0;
  return 1;
}

/* All n roots of the polynomial p (by power, p[n] != 0, finite), each
** group of the Newton polygon solved alone in its own scale, then polished
** on the whole polynomial in that scale.  A root beyond the double range
** comes out as +-inf in re or im: the honest answer, never NaN.  One group
** with clustered roots is solved about its centroid (may_shift, once). */
static int poly_roots_(const double *p, int n, double *re, double *im,
                       int may_shift) {
  poly P;
  int lo = 0, gs[5], ng, g, k, j, cnt = 0;
  poly_init(&P, p, n);
  while (lo < n && p[lo] == 0) {          /* x^lo divides p: exact zeros */
    re[cnt] = 0; im[cnt] = 0; cnt++; lo++;
  }
  if (lo == n) return cnt;
  /* the rest from p / x^lo (exact): kept in, those zeros are exact roots
  ** that the polishing can fall into (-x^2 (x+1)^2 + 7.4e-68 x: the
  ** double root -1 became 0, 0; fuzz/fuzz_roots) */
  if (lo > 0) return lo + poly_roots_(p + lo, n - lo, re + lo, im + lo, may_shift);
  ng = split_groups(&P, lo, gs);
  if (ng == 1 && may_shift) {
    double c[5];
    int E = group_scale(&P, lo, n);
    for (j = lo; j <= n; j++) c[j - lo] = scaled(&P, j, n, E);
    if (shifted_roots(c, n - lo, E, re + cnt, im + cnt)) return n;
  }
  if (n == 4 && lo == 0 && ng == 2 && gs[1] != 2 &&
      roots_3_1(&P, gs, re, im))
    return 4;
  for (g = 0; g < ng; g++) {
    int a = gs[g], b = gs[g + 1], d = b - a, E = group_scale(&P, a, b);
    double m[4], c[5];
    for (k = 1; k <= d; k++) m[k - 1] = scaled(&P, b - k, b, E);
    for (j = 0; j <= n; j++) c[j] = scaled(&P, j, b, E);
    group_roots(m, d, c, n, re + cnt, im + cnt);
    for (k = cnt; k < cnt + d; k++) {
      polish_root(c, n, &re[k], &im[k]);
      re[k] = ldexp(re[k], E); im[k] = ldexp(im[k], E);
    }
    cnt += d;
  }
  return cnt;
}

static int poly_roots(const double *p, int n, double *re, double *im) {
  return poly_roots_(p, n, re, im, 1);
}

/* ---- one Newton step with the residual in double-double ----------------
** Polished in double, a root is placed only to the rounding of Horner's
** sum, ~ n eps sum |p_k| |z|^k / |p'(z)|: 2e-11 in the imaginary part of
** 1000 + i beside the root 1e8 (Algorithm 1010's case 8, whose integer
** coefficients are exact).  With p(z) summed in double-double (compensated
** Horner: every product and sum split into its value and exact error,
** Ogita, Rump & Oishi 2005; Graillat, Langlois & Louvet 2009) the value's
** own error is ~ eps^2 times the sum, so one Newton step from a root good
** to ~sqrt(eps) lands within an ulp or two of the root of the
** coefficients as given -- the attainable accuracy when they are exact
** (Algorithm 1010 reaches it by Newton on its factors in the same way). */

/* a b = p + *e exactly (TwoProduct by a fused multiply-add: arclen_fma
** rounds once, so a b - p comes out exact whatever the compiler contracts;
** Dekker's split in plain arithmetic does not survive contraction of its
** own products).  dd_value's terms stay within 2^+-540: no underflow in e. */
static double two_prod(double a, double b, double *e) {
  double p = a * b;
  *e = arclen_fma(a, b, -p);
  return p;
}

/* p(z) for p[0..n] scaled to c_j = p_j 2^(E j - M), M the exponent of the
** largest term at |z| = 2^E (so the sum stays near 1), in complex
** double-double; the value to double in *vr, *vi, the derivative (plain
** Horner) in *dr, *di, |p''(z)| in *d2, the backward error |p(z)| / sum |p_k| |z|^k in
** *bwd (accurate where the plain one is rounding noise).  Returns 0 if a scaled coefficient is subnormal
** and not negligible: the scaling would round it. */
static int dd_value(const poly *P, const double *p, int n, int E, double zr,
                    double zi, double *vr, double *vi, double *dr, double *di,
                    double *bwd, double *d2) {
  double c[5], hr, lr, hi = 0, li = 0, pr = 0, pi = 0, t, sz = 0, az;
  double qr = 0, qi = 0;
  int j, M = INT_MIN, plain = E > -60 && E < 60;
  if (E < -1100 || E > 1100) return 0;  /* (ilogb of a finite nonzero z) */
  /* coefficients within 2^+-300 and |z| within 2^+-60: every term and its
  ** rounding error are normal doubles unscaled (the common case; the
  ** scaling below costs as much as the sum) */
  for (j = 0; j <= n && plain; j++)
    if (p[j] != 0 && !(fabs(p[j]) > 0x1p-300 && fabs(p[j]) < 0x1p300))
      plain = 0;
  if (plain) {
    for (j = 0; j <= n; j++) c[j] = p[j];
    E = 0; M = 0;
  } else {
    for (j = 0; j <= n; j++)
      if (P->f[j] != 0 && P->e[j] + E * j > M) M = P->e[j] + E * j;
    for (j = 0; j <= n; j++) {
      c[j] = P->f[j] == 0 ? 0 : ldexp(P->f[j], P->e[j] + E * j - M);
      if (c[j] != 0 && fabs(c[j]) < DBL_MIN && P->e[j] + E * j - M > -1000)
        return 0;
    }
    zr = ldexp(zr, -E); zi = ldexp(zi, -E);
  }
  az = mag(zr, zi);
  for (j = n; j >= 0; j--) sz = sz * az + fabs(c[j]);
  hr = c[n]; lr = 0;
  for (j = n - 1; j >= 0; j--) {
    double e1, e2, e3, e4, s, a, b;
    t = qr * zr - qi * zi + pr;           /* p''/2 and p' by plain Horner */
    qi = qr * zi + qi * zr + pi; qr = t;
    t = pr * zr - pi * zi + hr;
    pi = pr * zi + pi * zr + hi; pr = t;
    a = two_prod(hr, zr, &e1);
    b = two_prod(-hi, zi, &e2);
    s = two_sum(a, b, &e3);
    s = two_sum(s, c[j], &e4);
    t = e1 + e2 + e3 + e4 + (lr * zr - li * zi);
    a = two_prod(hr, zi, &e1);
    b = two_prod(hi, zr, &e2);
    hi = two_sum(a, b, &e3);
    li = e1 + e2 + e3 + (lr * zi + li * zr);
    hr = s + t; lr = t - (hr - s);        /* renormalise both parts */
    t = hi + li; li = li - (t - hi); hi = t;
  }
  *bwd = sz > 0 ? mag(hr, hi) / sz : 0;
  if (plain) {
    *dr = pr; *di = pi; *vr = hr; *vi = hi; *d2 = 2 * mag(qr, qi);
  } else {
    *dr = ldexp(pr, M - E); *di = ldexp(pi, M - E);   /* d/dz, z = 2^E y */
    *vr = ldexp(hr, M); *vi = ldexp(hi, M);
    *d2 = ldexp(2 * mag(qr, qi), M - 2 * E);                 /* |p''(z)| */
  }
  return isfinite(*vr + *vi + *dr + *di);
}

/* The step is taken only where Newton is in its quadratic basin: smaller
** than 2^-20 of |z| (the double polish leaves simple roots far closer) and
** than a quarter of the distance to every other root (a near-double pair
** must not fall into one root: fuzz/fuzz_roots' lesson in polish_root).
** Conjugate pairs are stepped as pairs (conj of the step), so they stay
** exact conjugates. */
#define DD_STEP_REL 0x1p-20
#define DD_STEPS 4        /* quadratic convergence from 2^-20: 2 or 3 */

/* A close pair with a real centre m (two near reals, or a conjugate pair
** near the axis) is ill-placed by Newton in x: each root only to ~ eps /
** split, and no step is allowed (a quarter of the split).  About m the
** polynomial p(m + y), its coefficients from the double-double Taylor
** shift (one rounding each, which moves small roots by their own relative
** eps), holds the pair as its two smallest roots y, well separated in
** their own scale (the centroid shift of Algorithm 1010, taken at the
** pair): 905 and 905 + 2^-18 beside 7000 and -32 came out 905 +- 1.2e-5 i,
** an error 4x the split.  The pair is replaced if both roots' residuals in
** double-double then fall.  CLOSE_PAIR: the double solver leaves a
** near-double pair split by ~ sqrt(eps) |m| ~ 2^-26 |m| at most. */
#define CLOSE_PAIR 0x1p-8

static void split_close_pair(const poly *P, const double *p, int n, int cnt,
                             double *re, double *im) {
  double best = HUGE_VAL, b[5], yr[4], yi[4], nr[2], ni[2], m, old = 0, neu = 0;
  double vr, vi, dr, di, bw, d2;
  int k, j, bk = -1, bj = -1, i, ny, s[2] = {-1, -1};
  for (k = 0; k < cnt; k++)
    for (j = k + 1; j < cnt; j++) {
      double d = mag(re[j] - re[k], im[j] - im[k]);
      int real_centre = (im[k] == 0 && im[j] == 0) ||
                        (re[j] == re[k] && im[j] == -im[k]);
      if (real_centre && d < best) { best = d; bk = k; bj = j; }
    }
  if (bk < 0) return;
  m = (re[bk] + re[bj]) / 2;
  if (!(best <= CLOSE_PAIR * fabs(m)) || m == 0) return;   /* (0: exact) */
  for (i = 0; i <= n; i++) b[i] = p[i] / p[n];
  taylor_shift(b, n, m);
  for (i = 0; i <= n; i++) if (!isfinite(b[i])) return;
  ny = poly_roots_(b, n, yr, yi, 0);
  for (i = 0; i < ny; i++) {           /* the two smallest y */
    double a = mag(yr[i], yi[i]);
    if (s[0] < 0 || a < mag(yr[s[0]], yi[s[0]])) { s[1] = s[0]; s[0] = i; }
    else if (s[1] < 0 || a < mag(yr[s[1]], yi[s[1]])) s[1] = i;
  }
  /* and they must be a pair again: two reals or exact conjugates (of a
  ** triple cluster the two smallest may be one of each: -(x + 1)^3) */
  if (s[1] < 0 || !((yi[s[0]] == 0 && yi[s[1]] == 0) ||
                    (yr[s[0]] == yr[s[1]] && yi[s[0]] == -yi[s[1]])))
    return;
  for (i = 0; i < 2; i++) {
    int q = i == 0 ? bk : bj, e;
    nr[i] = m + yr[s[i]]; ni[i] = yi[s[i]];
    if (!isfinite(nr[i] + ni[i])) return;
    e = ilogb(fabs(m)) + 1;
    if (!dd_value(P, p, n, e, re[q], im[q], &vr, &vi, &dr, &di, &bw, &d2)) return;
    old = fmax(old, bw);
    if (!dd_value(P, p, n, e, nr[i], ni[i], &vr, &vi, &dr, &di, &bw, &d2)) return;
    neu = fmax(neu, bw);
  }
  if (!(neu < old)) return;
  re[bk] = nr[0]; im[bk] = ni[0]; re[bj] = nr[1]; im[bj] = ni[1];
}

static void refine_roots(const double *p, int n, int cnt, double *re,
                         double *im) {
  poly P;
  int k, j, it;
  poly_init_fe(&P, p, n);
  if (n >= 2) split_close_pair(&P, p, n, cnt, re, im);
  for (k = 0; k < cnt; k++) {
    double az = mag(re[k], im[k]), gap = HUGE_VAL, moved = 0;
    for (j = 0; j < cnt && im[k] < 0; j++)
      if (re[j] == re[k] && im[j] == -im[k]) break;
    if (im[k] < 0 && j < cnt) continue;   /* stepped with its partner */
    if (!(az > 0) || !(az < HUGE_VAL)) continue;
    for (j = 0; j < cnt; j++)
      if (j != k && !(re[j] == re[k] && im[j] == -im[k]))
        gap = fmin(gap, mag(re[j] - re[k], im[j] - im[k]));
    if (im[k] != 0) gap = fmin(gap, 2 * fabs(im[k]));   /* the pair's own split */
    /* a step leaves ~ st^2 |p''| / (2 |p'|) (Newton's quadratic error):
    ** another is taken only while that exceeds a quarter ulp */
    for (it = 0; it < DD_STEPS; it++) {
      double vr, vi, dr, di, den, sr, si, st, b, d2;
      if (!dd_value(&P, p, n, ilogb(az) + 1, re[k], im[k], &vr, &vi, &dr, &di,
                    &b, &d2))
        break;
      den = dr * dr + di * di;
      if (!(den > 0) || !isfinite(den)) break;
      sr = (vr * dr + vi * di) / den;
      si = (vi * dr - vr * di) / den;
      st = mag(sr, si);
      if (!(moved + st <= DD_STEP_REL * az && moved + st <= gap / 4)) break;
      moved += st;
      for (j = 0; j < cnt; j++)
        if (j != k && im[k] > 0 && re[j] == re[k] && im[j] == -im[k]) {
          re[j] -= sr; im[j] += si;
        }
      re[k] -= sr;
      if (im[k] != 0) im[k] -= si;
      if (!(st * st * d2 > DBL_EPSILON / 4 * az * sqrt(den))) break;
    }
  }
}

static int all_finite(const double *a, int n) {
  int k;
  for (k = 0; k <= n; k++) if (!isfinite(a[k])) return 0;
  return 1;
}

/* Roots of a3 x^3 + a2 x^2 + a1 x + a0; see poly_roots for huge spreads. */
int arclen_cubic(double a3, double a2, double a1, double a0, double re[3],
                 double im[3]) {
  double p[4];
  if (a3 == 0) return arclen_quadratic(a2, a1, a0, re, im);
  int n;
  p[0] = a0; p[1] = a1; p[2] = a2; p[3] = a3;
  if (!all_finite(p, 3)) return 0;
  n = poly_roots(p, 3, re, im);
  refine_roots(p, 3, n, re, im);
  return n;
}

/* The quartic's roots without the double-double step (roots3d.h): for
** callers whose coefficients are rounded sums (|z'|^2 of a hodograph),
** where the last bit of the given coefficients' roots is no truth and the
** step's ~300 ns buy nothing (gauss/branch.c's branch points could take
** this; arclen_quartic keeps the step). */
int arclen_quartic_plain(double a4, double a3, double a2, double a1,
                         double a0, double re[4], double im[4]) {
  double p[5];
  if (a4 == 0) return arclen_cubic(a3, a2, a1, a0, re, im);
  p[0] = a0; p[1] = a1; p[2] = a2; p[3] = a3; p[4] = a4;
  if (!all_finite(p, 4)) return 0;
  return poly_roots(p, 4, re, im);
}

int arclen_quartic(double a4, double a3, double a2, double a1, double a0,
                   double re[4], double im[4]) {
  double p[5];
  if (a4 == 0) return arclen_cubic(a3, a2, a1, a0, re, im);
  int n;
  p[0] = a0; p[1] = a1; p[2] = a2; p[3] = a3; p[4] = a4;
  if (!all_finite(p, 4)) return 0;
  n = poly_roots(p, 4, re, im);
  refine_roots(p, 4, n, re, im);
  return n;
}

/* x^2 + q[0] x + q[1] with the roots (r1, +-i1) and (r2, i2): a conjugate
** pair, or two reals (0 times an infinite root is the exact 0). */
static void pair_factor(double r1, double i1, double r2, double i2,
                        double *q) {
  if (i1 != 0) { q[0] = -2 * r1; q[1] = r1 * r1 + i1 * i1; return; }
  (void)i2;
  q[0] = -(r1 + r2);
  q[1] = (r1 == 0 || r2 == 0) ? 0 : r1 * r2;
}

/* The factors q from paired roots, Newton-polished as a whole in the
** quartic's own scale x = 2^E y (the roots are each polished on p, but a
** pair's coefficients then carry each root's error, eps / separation for
** a near-double root), kept only if the residual falls.  Skipped where a
** scaled coefficient of p or q is below 2^-200 (or underflows): one scale
** cannot hold every group then, and the residual would be blind. */
static void factor_polish(const poly *P, double *q) {
  double m[4], c[5], v[4], w[4];
  int k, E = group_scale(P, 0, 4);
  for (k = 1; k <= 4; k++) m[k - 1] = c[4 - k] = scaled(P, 4 - k, 4, E);
  c[4] = 1;
  v[0] = ldexp(q[0], -E); v[1] = ldexp(q[1], -2 * E);
  v[2] = ldexp(q[2], -E); v[3] = ldexp(q[3], -2 * E);
  for (k = 0; k < 4; k++) {       /* (2^-200: products of two, and c_k z^k
                                   ** at the roots, stay normal; below, the
                                   ** residuals go blind: x (1.2e-308 x^3 +
                                   ** 1.4e-149 x^2 + 1) got a root 6e-11) */
    if (!isfinite(v[k]) || (q[k] != 0 && fabs(v[k]) < 0x1p-200)) return;
    if (P->f[3 - k] != 0 && fabs(m[k]) < 0x1p-200) return;
    w[k] = v[k];
  }
  /* Newton lowers the coefficients' residual; keep it if the factors'
  ** roots still solve p to rounding (FACTOR_GOOD) or better than before.
  ** Paired roots of a near-triple cluster (2.9e-11 x^4 - (x+1)^3) solve p
  ** to 1e-21 but reproduce its coefficients only to 8e-10; Newton's
  ** factors reproduce them to 2e-16 and solve p to 6e-17. */
  if (!(factor_newton(m, w) < resid_norm(v, m)) ||
      !(fmax(factor_bwd(c, 4, w[0], w[1]), factor_bwd(c, 4, w[2], w[3])) <=
        fmax(FACTOR_GOOD, fmax(factor_bwd(c, 4, v[0], v[1]),
                               factor_bwd(c, 4, v[2], v[3])))))
    return;
  q[0] = ldexp(w[0], E); q[1] = ldexp(w[1], 2 * E);
  q[2] = ldexp(w[2], E); q[3] = ldexp(w[3], 2 * E);
}

/* factor_bwd for x^2 + u x + v (unscaled) on the whole p, each root's
** residual in double-double (dd_value): HUGE_VAL where it cannot say. */
static double factor_bwd_dd(const poly *P, const double *p, double u,
                            double v) {
  double re[2], im[2], worst = 0, vr, vi, dr, di, b, d2;
  int i, nr = arclen_quadratic(1, u, v, re, im);
  for (i = 0; i < nr; i++) {
    double az = mag(re[i], im[i]);
    if (!(az < HUGE_VAL)) return HUGE_VAL;
    if (az == 0) { if (P->f[0] != 0) return HUGE_VAL; continue; }
    if (!dd_value(P, p, 4, ilogb(az) + 1, re[i], im[i], &vr, &vi, &dr, &di, &b,
                  &d2))
      return HUGE_VAL;
    worst = fmax(worst, b);
  }
  return worst;
}

/* The factors' roots, refined on the whole quartic (refine_roots), give
** the factors again (pair_factor: one rounding per coefficient); a factor
** is replaced where its roots then solve p better in double-double.  The
** factors' own Newton (factor_newton, polish_factor) measures its residual
** in double and stops at that rounding: 1000001 - 1.2e-10 for the
** exact 1000001 of (x^2 - 2000 x + 1000001)(x - 1e8)(x - 11). */
static void factor_refine(const double *p, const poly *P, double *q) {
  double re[4], im[4], r[2], w[4], m[4], v0[4], v1[4];
  int k = 0, j, E, changed = 0;
  k += arclen_quadratic(1, q[0], q[1], re, im);
  if (k != 2) return;
  k += arclen_quadratic(1, q[2], q[3], re + 2, im + 2);
  if (k != 4) return;
  refine_roots(p, 4, 4, re, im);
  for (j = 0; j < 4; j++) w[j] = q[j];
  for (j = 0; j < 2; j++) {
    pair_factor(re[2 * j], fabs(im[2 * j]), re[2 * j + 1], im[2 * j + 1], r);
    if (r[0] == q[2 * j] && r[1] == q[2 * j + 1]) continue;   /* the same */
    changed = 1;
    if (isfinite(r[0] + r[1]) &&
        factor_bwd_dd(P, p, r[0], r[1]) < factor_bwd_dd(P, p, q[2 * j], q[2 * j + 1])) {
      w[2 * j] = r[0]; w[2 * j + 1] = r[1];
    }
  }
  if (!changed) return;
  /* and only if the factors still multiply out to p (in its own scale, as
  ** factor_polish): near a double pair each root solves p to rounding while
  ** the four together miss its coefficients by ~ the pair's split (the x^3
  ** coefficient 3e-9 off in roots_fuzz.tsv's near-double-complex-pair) */
  E = group_scale(P, 0, 4);
  for (j = 1; j <= 4; j++) m[j - 1] = scaled(P, 4 - j, 4, E);
  for (j = 0; j < 4; j++) {
    v0[j] = ldexp(q[j], -(j % 2 + 1) * E);
    v1[j] = ldexp(w[j], -(j % 2 + 1) * E);
  }
  if (!(resid_norm(v1, m) <= fmax(FACTOR_GOOD, resid_norm(v0, m)))) return;
  for (j = 0; j < 4; j++) q[j] = w[j];
}

/* The largest relative residual of the coefficient equations that hold
** the linear coefficients, (x^2 + q0 x + q1)(x^2 + q2 x + q3) against the
** monic m: q0 + q2 = m0, q1 + q3 + q0 q2 = m1, q0 q3 + q2 q1 = m2, each
** relative to its terms; HUGE_VAL where a product leaves the range. */
static double linear_resid(const double *q, const double *m) {
  double r[3], w[3], worst = 0;
  int k;
  r[0] = q[0] + q[2] - m[0];
  w[0] = fabs(q[0]) + fabs(q[2]) + fabs(m[0]);
  r[1] = q[1] + q[3] + q[0] * q[2] - m[1];
  w[1] = fabs(q[1]) + fabs(q[3]) + fabs(q[0] * q[2]) + fabs(m[1]);
  r[2] = q[0] * q[3] + q[2] * q[1] - m[2];
  w[2] = fabs(q[0] * q[3]) + fabs(q[2] * q[1]) + fabs(m[2]);
  for (k = 0; k < 3; k++) {
    if (!isfinite(r[k]) || !isfinite(w[k])) return HUGE_VAL;
    if (w[k] > 0) worst = fmax(worst, fabs(r[k]) / w[k]);
  }
  return worst;
}

/* A linear coefficient can be far below its factor's roots (a conjugate
** pair 3e-11 +- 2.7e74 i beside the real root -1.2e159: its real part is
** 1e-85 of its size, which the roots, and so pair_factor, give as 0), and
** then the sum of the roots (the x^3 equation) cannot hold it.  It is
** well set by the other equations, which Algorithm 1010 also solves for
** the smaller coefficients: q2 = (m1 - q1 - q3)/q0 from the x^2 equation
** or (m2 - q0 q3)/q1 from the x equation (and likewise q0).  Where the
** equations miss by more than rounding (FACTOR_GOOD), a candidate that
** makes them hold to rounding (linear_resid) is taken. */
static void linear_from_equations(const double *p, double *q) {
  double m[3], w[4], best;
  int j, k;
  poly P;
  poly_init_fe(&P, p, 4);
  for (k = 0; k < 3; k++) {
    m[k] = p[3 - k] / p[4];
    if (!isfinite(m[k])) return;
  }
  for (j = 0; j < 4; j += 2) {
    int o = 2 - j;                /* the other factor's linear coefficient */
    double cand[2];
    cand[0] = q[o] != 0 ? (m[1] - q[1] - q[3]) / q[o] : HUGE_VAL;
    cand[1] = q[o + 1] != 0 ? (m[2] - q[o] * q[j + 1]) / q[o + 1] : HUGE_VAL;
    best = linear_resid(q, m);
    if (!(best > FACTOR_GOOD)) continue;    /* the equations hold already */
    for (k = 0; k < 2; k++) {
      double r, b0;
      int i;
      if (!isfinite(cand[k])) continue;
      for (i = 0; i < 4; i++) w[i] = q[i];
      w[j] = cand[k];
      r = linear_resid(w, m);
      /* and the factor's roots must still solve p (factor_bwd_dd): the
      ** equations can be as blind to a wrong coefficient (-1.2e-237 (x^4
      ** + x^3) + 66 x^2 + 65 x + 3.3e-316 took a factor root 9e-8 off,
      ** where a subnormal root left the old factor's test unable to say:
      ** fuzz/fuzz_roots) */
      b0 = factor_bwd_dd(&P, p, q[j], q[j + 1]);
      if (r <= FACTOR_GOOD && b0 < HUGE_VAL && /* (HUGE_VAL: cannot tell) */
          factor_bwd_dd(&P, p, cand[k], q[j + 1]) <= fmax(FACTOR_GOOD, b0)) {
        best = r; q[j] = cand[k];
      }
    }
  }
}

static int quartic_factor(double a4, double a3, double a2, double a1,
                          double a0, double q[4], int refine) {
  double p[5], re[4], im[4];
  poly P;
  int gs[5], ng, i, k, used[4] = {0, 0, 0, 0}, nq = 0;
  p[0] = a0; p[1] = a1; p[2] = a2; p[3] = a3; p[4] = a4;
  if (a4 == 0 || !all_finite(p, 4)) return ARCLEN_EDOMAIN;
  poly_init(&P, p, 4);
  ng = p[0] == 0 ? 0 : split_groups(&P, 0, gs);
  if (ng == 1) {                /* one scale: Ferrari and Newton, scaled */
    double m[4], v[4];
    int E = group_scale(&P, 0, 4);
    for (k = 1; k <= 4; k++) m[k - 1] = scaled(&P, 4 - k, 4, E);
    factor_monic(m, v);
    q[0] = ldexp(v[0], E); q[1] = ldexp(v[1], 2 * E);
    q[2] = ldexp(v[2], E); q[3] = ldexp(v[3], 2 * E);
    if (refine) factor_refine(p, &P, q);
    return ARCLEN_OK;
  }
  /* spread roots: a group of degree 2 is a factor, y^2 + m0 y + m1 in
  ** x = 2^E y, once Bairstow has polished it on the whole polynomial (its
  ** own coefficients neglect the other groups: 2^-SPLIT_BITS-sized
  ** relative errors, residual 8e-8 found by fuzz/fuzz_roots); the other
  ** roots pair up, conjugates together, reals by size (largest with next
  ** largest).  poly_roots lists group g's roots at gs[g]..gs[g+1]-1
  ** (exact zeros, if any, first). */
  poly_roots(p, 4, re, im);
  for (i = 0; i < ng && p[0] != 0 && nq == 0; i++) {
    int b = gs[i + 1], E = group_scale(&P, gs[i], b);
    double c[5], u, v;
    if (b - gs[i] != 2) continue;
    u = scaled(&P, b - 1, b, E); v = scaled(&P, b - 2, b, E);
    for (k = 0; k <= 4; k++) c[k] = scaled(&P, k, b, E);
    polish_factor(c, 4, &u, &v);
    q[0] = ldexp(u, E); q[1] = ldexp(v, 2 * E);
    /* or the pair of its roots, each polished on p, if they solve c
    ** better: Bairstow fails where the group's small root lies beside
    ** another group's (9.6e-6 from a constant term that underflows to
    ** 0 in this scale: factor roots 1.3e10 eps; fuzz/fuzz_roots) */
    {
      double r[2];
      int g = gs[i];
      pair_factor(ldexp(re[g], -E), ldexp(fabs(im[g]), -E), ldexp(re[g + 1], -E),
                  ldexp(im[g + 1], -E), r);
      if (factor_bwd(c, 4, r[0], r[1]) < factor_bwd(c, 4, u, v)) {
        q[0] = ldexp(r[0], E); q[1] = ldexp(r[1], 2 * E);
      }
    }
    used[gs[i]] = used[gs[i] + 1] = 1;
    nq = 1;
  }
  for (; nq < 2; nq++) {
    int s = -1, t = -1;
    for (k = 0; k < 4; k++)        /* the unused root of largest size */
      if (!used[k] && (s < 0 || mag(re[k], im[k]) > mag(re[s], im[s])))
        s = k;
    used[s] = 1;
    for (k = 0; k < 4; k++)        /* its conjugate, or the next real */
      if (!used[k] && (im[s] != 0 ? im[k] == -im[s] && re[k] == re[s]
            : im[k] == 0 && (t < 0 || fabs(re[k]) > fabs(re[t]))))
        t = k;
    if (t < 0)                     /* no exact conjugate: the nearest */
      for (k = 0; k < 4; k++)
        if (!used[k] && (t < 0 || mag(re[k] - re[s], im[k] + im[s])
                         < mag(re[t] - re[s], im[t] + im[s])))
          t = k;
    used[t] = 1;
    pair_factor(re[s], fabs(im[s]), re[t], im[t], q + 2 * nq);
  }
  factor_polish(&P, q);
  if (refine) factor_refine(p, &P, q);
  linear_from_equations(p, q);
  return ARCLEN_OK;
}

int arclen_quartic_factor(double a4, double a3, double a2, double a1,
                          double a0, double q[4]) {
  return quartic_factor(a4, a3, a2, a1, a0, q, 1);
}

/* Without factor_refine's double-double step: roots3d.c polishes the
** roots on the hodograph's own form of the quartic, which the rounded
** coefficients given here do not hold (their last bit is no truth), and
** the step cost the 3D methods ~1 us a curve. */
int arclen_quartic_factor_plain(double a4, double a3, double a2, double a1,
                                double a0, double q[4]) {
  return quartic_factor(a4, a3, a2, a1, a0, q, 0);
}
