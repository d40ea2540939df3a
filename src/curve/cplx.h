/*
** cplx.h -- complex numbers as a pair of doubles, for the few places that
** need them (the 2D hodograph's roots, complex Newton in roots/roots3d.c).
** Not C99's complex types: MSVC has none, and GCC calls libgcc's __muldc3
** and __divdc3 for them (a DLL of its own under MinGW).  The operations
** round as GCC's inline complex code does under -ffp-contract=off, so the
** results are those of the former C99 code, bit for bit (doc/testing.md,
** "Windows"); a real operand is applied to each part alone, as C99 Annex
** G.5.1 does.  Not part of the public API.
*/
#ifndef ARCLEN_CPLX_H
#define ARCLEN_CPLX_H

#include <float.h>
#include <math.h>

typedef struct arclen_cx { double re, im; } arclen_cx;

static inline arclen_cx arclen_cx_make(double re, double im) {
  arclen_cx z;
  z.re = re;
  z.im = im;
  return z;
}

static inline arclen_cx arclen_cx_add(arclen_cx a, arclen_cx b) {
  return arclen_cx_make(a.re + b.re, a.im + b.im);
}

static inline arclen_cx arclen_cx_sub(arclen_cx a, arclen_cx b) {
  return arclen_cx_make(a.re - b.re, a.im - b.im);
}

/* a + x, x real: the imaginary part is untouched (a -0 stays -0) */
static inline arclen_cx arclen_cx_add_re(arclen_cx a, double x) {
  return arclen_cx_make(a.re + x, a.im);
}

/* x a, x real */
static inline arclen_cx arclen_cx_scale(double x, arclen_cx a) {
  return arclen_cx_make(x * a.re, x * a.im);
}

/* a / x, x real */
static inline arclen_cx arclen_cx_div_re(arclen_cx a, double x) {
  return arclen_cx_make(a.re / x, a.im / x);
}

static inline arclen_cx arclen_cx_neg(arclen_cx a) {
  return arclen_cx_make(-a.re, -a.im);
}

static inline arclen_cx arclen_cx_conj(arclen_cx a) {
  return arclen_cx_make(a.re, -a.im);
}

/* (a + bi)(c + di) = (ac - bd) + (ad + bc)i, four products, no fusing
** (the textbook formula; NaN and infinities are not recovered as Annex
** G.5.1 would: the callers' operands are finite and scaled) */
static inline arclen_cx arclen_cx_mul(arclen_cx a, arclen_cx b) {
  return arclen_cx_make(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re);
}

/* |a| without overflow or underflow */
static inline double arclen_cx_abs(arclen_cx a) { return hypot(a.re, a.im); }

static inline int arclen_cx_is_zero(arclen_cx a) {
  return a.re == 0 && a.im == 0;
}

static inline int arclen_cx_eq(arclen_cx a, arclen_cx b) {
  return a.re == b.re && a.im == b.im;
}

/* a / b by Smith's algorithm (CACM 5(8), 1962, Alg. 116): divide by the
** larger part of b first, so that |b|^2 is never formed.  When the ratio
** underflows, a / d is formed before the product with c (Baudin & Smith,
** "A robust complex division in Scilab", 2012).  The operands are first
** moved away from the ends of the range by a power of two (exact): halved
** when b is within a factor 2 of overflow; multiplied by 2^52 when b is
** below 2^-52, or when a part of a is below DBL_MIN (its digits would be
** lost in the products) and the scaling cannot overflow.  A zero b is the
** caller's to exclude. */
static inline arclen_cx arclen_cx_div(arclen_cx a, arclen_cx b) {
  const double up = 1 / DBL_EPSILON, top = DBL_MAX / 2 * DBL_EPSILON;
  double x = a.re, y = a.im, c = b.re, d = b.im, r, den;
  double big = fmax(fabs(c), fabs(d));
  if (big >= DBL_MAX / 2) {
    x /= 2; y /= 2; c /= 2; d /= 2;
  } else if (big < DBL_EPSILON ||
             (big < top && ((fabs(x) < DBL_MIN && fabs(y) < top) ||
                            (fabs(y) < DBL_MIN && fabs(x) < top)))) {
    x *= up; y *= up; c *= up; d *= up;
  }
  if (fabs(c) < fabs(d)) {
    r = c / d;
    den = c * r + d;
    if (fabs(r) > DBL_MIN)
      return arclen_cx_make((x * r + y) / den, (y * r - x) / den);
    return arclen_cx_make((c * (x / d) + y) / den, (c * (y / d) - x) / den);
  }
  r = d / c;
  den = d * r + c;
  if (fabs(r) > DBL_MIN)
    return arclen_cx_make((y * r + x) / den, (y - x * r) / den);
  return arclen_cx_make((d * (y / c) + x) / den, (y - d * (x / c)) / den);
}

/* The principal square root (Kahan, "Branch cuts for complex elementary
** functions", 1987): t = sqrt((|x| + |a|)/2) has no cancellation, and the
** other part is y/(2t) (Re(root) Im(root) = y/2).  On the axes the roots
** are read off directly.  Parts beyond DBL_MAX/4 are scaled by 1/4 (so
** |x| + |a| cannot overflow), both below 2 DBL_MIN by 2^54 (so (|x| +
** |a|)/2 keeps its digits), and the root scaled back by the square root of
** that power of two, exactly. */
static inline arclen_cx arclen_cx_sqrt(arclen_cx a) {
  double x = a.re, y = a.im, t, u;
  int e = 0;
  if (y == 0) {
    if (x < 0) return arclen_cx_make(0, copysign(sqrt(-x), y));
    return arclen_cx_make(fabs(sqrt(x)), copysign(0, y));
  }
  if (x == 0) {             /* halving a subnormal |y| would lose a bit */
    t = fabs(y) >= 2 * DBL_MIN ? sqrt(0.5 * fabs(y)) : 0.5 * sqrt(2 * fabs(y));
    return arclen_cx_make(t, copysign(t, y));
  }
  if (fabs(x) > DBL_MAX / 4 || fabs(y) > DBL_MAX / 4) {
    x = ldexp(x, -2);
    y = ldexp(y, -2);
    e = 1;
  } else if (fabs(x) < 2 * DBL_MIN && fabs(y) < 2 * DBL_MIN) {
    x = ldexp(x, 54);
    y = ldexp(y, 54);
    e = -27;
  }
  t = sqrt(0.5 * (hypot(x, y) + fabs(x)));
  u = 0.5 * (y / t);
  if (x > 0) return arclen_cx_make(ldexp(t, e), ldexp(u, e));
  return arclen_cx_make(ldexp(fabs(u), e), copysign(ldexp(t, e), y));
}

#endif
