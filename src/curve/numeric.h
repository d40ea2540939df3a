/*
** numeric.h -- small exact-arithmetic pieces every area may use: pi, the
** error-free sum of two doubles and Neumaier's compensated sum, and the
** step rule of the bracketed searches.  Not part of the public API.
*/
#ifndef ARCLEN_NUMERIC_H
#define ARCLEN_NUMERIC_H

#include <math.h>
#include <string.h>

#define ARCLEN_PI 3.14159265358979323846

/* A double-double number hi + lo (Dekker 1971). */
typedef struct arclen_dd { double hi, lo; } arclen_dd;

/* TwoSum (Knuth; Ogita, Rump & Oishi 2005, Alg. 3.1): hi + lo = a + b
** exactly, hi the rounded sum.  Needs no FMA and no ordering of a, b. */
static inline arclen_dd arclen_two_sum(double a, double b) {
  double s = a + b, bb = s - a;
  arclen_dd r;
  r.hi = s;
  r.lo = (a - (s - bb)) + (b - bb);
  return r;
}

/* TwoProduct without fma (Dekker 1971, Veltkamp's split into 26-bit
** halves): hi + lo = a b exactly when |a|, |b| lie in [2^-400, 2^500]
** (no half overflows, no partial product underflows). */
static inline arclen_dd arclen_two_prod_split(double a, double b) {
  const double split = 134217729.0;                  /* 2^27 + 1 */
  double ca = split * a, cb = split * b;
  double ah = ca - (ca - a), al = a - ah, bh = cb - (cb - b), bl = b - bh;
  arclen_dd r;
  r.hi = a * b;
  r.lo = ((ah * bh - r.hi) + ah * bl + al * bh) + al * bl;
  return r;
}

/* a b + c rounded once, as C99's fma should.  MinGW-w64's fma (libmingwex
** 10, Debian 12's cross-compiler) is not: fma(0x1.ff7ced9168761p-1,
** -0x1.6d1cbffffffdap+4, 0x1.6cbf480000001p+4) is 2^-69 off, and the
** double-double sub-range hodograph (cubic.c) lost 7 digits.  There (and
** wherever ARCLEN_SOFT_FMA is defined) Boldo & Melquiond's emulation
** ("Emulation of FMA and correctly rounded sums: proved algorithms using
** rounding to odd", IEEE TC 57(4), 2008, Alg. 5.4): a b = uh + ul and
** c + uh = th + tl exactly, v = tl + ul rounded to odd, the result th + v
** rounded to nearest.  Operands outside TwoProduct's range above go to
** the library's fma (arclen's are scaled, far inside it).  A target with
** an FMA instruction (-mfma: __FMA__; arm64) gets it for fma(), exact; only
** without one is the emulation used -- where no contraction can fuse the
** split's products either. */
#if defined(__MINGW32__) && !defined(ARCLEN_SOFT_FMA) && \
    !defined(__FMA__) && !defined(__ARM_FEATURE_FMA)
#define ARCLEN_SOFT_FMA 1
#endif
#if defined(ARCLEN_SOFT_FMA)
static inline double arclen_fma(double a, double b, double c) {
  double fa = fabs(a), fb = fabs(b), v, e, bb;
  arclen_dd u, t;
  unsigned long long bits;
  if (!(fa >= 0x1p-400 && fa <= 0x1p500 && fb >= 0x1p-400 && fb <= 0x1p500 &&
        fabs(c) <= 0x1p1000))
    return fma(a, b, c);                /* zeros, inf, NaN, extreme ranges */
  u = arclen_two_prod_split(a, b);
  t = arclen_two_sum(c, u.hi);
  /* v = tl + ul rounded to odd: round to nearest, and if that was inexact
  ** and gave an even significand, step one ulp toward the exact sum */
  v = t.lo + u.lo;
  bb = v - t.lo;
  e = (t.lo - (v - bb)) + (u.lo - bb);
  memcpy(&bits, &v, sizeof bits);
  if (e != 0 && (bits & 1) == 0)
    v = nextafter(v, e > 0 ? HUGE_VAL : -HUGE_VAL);
  return t.hi + v;
}
#else
#define arclen_fma fma
#endif

/* a b + c, rounded once where the target has a fused multiply-add and
** twice where it has none: a compiler contracts only into an FMA
** instruction, so this is what every build for one target computes,
** whatever its -ffp-contract.  Used where two code paths must agree to
** the bit (the default method's fast and general paths): a product left
** to the compiler may be fused at one inlined site and not at another.
** Macros: GCC's (__FP_FAST_FMA), C99's, x86's -mfma, ARM's ACLE. */
#if defined(FP_FAST_FMA) || defined(__FP_FAST_FMA) || defined(__FMA__) || \
    defined(__ARM_FEATURE_FMA)
static inline double arclen_muladd(double a, double b, double c) {
  return arclen_fma(a, b, c);     /* the instruction: exact */
}
#else
static inline double arclen_muladd(double a, double b, double c) {
  return a * b + c;
}
#endif

/* max, min and a choice without a branch (a maxsd, a minsd, masks), for
** comparisons that are coin tosses from one input to the next (a sign, which
** of two sizes is larger), where a branch is mispredicted half the time,
** a few ns each.  The bits are those of the plain ?: (fmax, fmin are calls
** under -std=c99, and treat NaN otherwise). */
static inline double arclen_max(double x, double y) { return x > y ? x : y; }
static inline double arclen_min(double x, double y) { return x < y ? x : y; }
static inline double arclen_choose(int c, double x, double y) { /* c ? x : y */
  unsigned long long bx, by, mask = 0ULL - (unsigned long long)(c != 0);
  memcpy(&bx, &x, sizeof bx);
  memcpy(&by, &y, sizeof by);
  bx = (bx & mask) | (by & ~mask);
  memcpy(&x, &bx, sizeof x);
  return x;
}

/* Neumaier's compensated sum (1974): s + c, with the error of each
** addition carried in c whichever operand is larger. */
typedef struct arclen_sum { double s, c; } arclen_sum;

static inline void arclen_sum_add(arclen_sum *g, double x) {
  double t = g->s + x;
  if (fabs(g->s) >= fabs(x)) g->c += (g->s - t) + x;
  else g->c += (x - t) + g->s;
  g->s = t;
}

/* u in (0, 1) where the cubic Hermite interpolant of a length s(u) -- 0
** and total at the ends, slopes fa and fb there (the speeds times the
** width) -- reaches goal: Newton's steps from u0, at most steps of them,
** the last one kept inside (0, 1).  A first guess of the time at a length
** for a cubic's piece (gauss/time.c) and a quadratic (segment.c). */
static inline double arclen_hermite_invert(double total, double fa, double fb,
                                           double goal, double u, int steps) {
  int it;
  for (it = 0; it < steps; it++) {
    double u2 = u * u, u3 = u2 * u;
    double g = total * (3 * u2 - 2 * u3) + fa * (u - 2 * u2 + u3) +
               fb * (u3 - u2) - goal;
    double dg = total * (6 * u - 6 * u2) + fa * (1 - 4 * u + 3 * u2) +
                fb * (3 * u2 - 2 * u);
    double next = dg > 0 ? u - g / dg : -1;
    if (!(next > 0 && next < 1)) break;      /* keep the last good u */
    u = next;
  }
  return u;
}

/* Whether a bracketed search takes its step from x to nx: nx inside (lo,
** hi) and at most half the step before, last (Numerical Recipes' rtsafe
** rule: steps from the fast side of a steep fall in the speed towards the
** slow one crawl); else it halves the bracket, which then halves at least
** every second step.  A NaN nx is refused. */
static inline int arclen_step_ok(double nx, double x, double lo, double hi,
                                 double last) {
  return nx > lo && nx < hi && fabs(nx - x) <= last / 2;
}

#endif
