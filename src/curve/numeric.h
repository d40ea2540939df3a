/*
** numeric.h -- small exact-arithmetic pieces every area may use: pi, the
** error-free sum of two doubles and Neumaier's compensated sum.  Not part
** of the public API.
*/
#ifndef ARCLEN_NUMERIC_H
#define ARCLEN_NUMERIC_H

#include <math.h>

#define ARCLEN_PI 3.14159265358979323846

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
  return fma(a, b, c);
}
#else
static inline double arclen_muladd(double a, double b, double c) {
  return a * b + c;
}
#endif

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

/* Neumaier's compensated sum (1974): s + c, with the error of each
** addition carried in c whichever operand is larger. */
typedef struct arclen_sum { double s, c; } arclen_sum;

static inline void arclen_sum_add(arclen_sum *g, double x) {
  double t = g->s + x;
  if (fabs(g->s) >= fabs(x)) g->c += (g->s - t) + x;
  else g->c += (x - t) + g->s;
  g->s = t;
}

#endif
