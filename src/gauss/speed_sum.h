/*
** speed_sum.h -- the inner loop of every Gauss-Legendre rule here: the
** weighted sum of the speed at the symmetric pairs of nodes (speed_sum.c).
*/
#ifndef ARCLEN_SPEED_SUM_H
#define ARCLEN_SPEED_SUM_H

#include "curve/cubic.h"

/* The ways to run the loop; each gives the same sum to the bit. */
enum {
  ARCLEN_KERNEL_BEST,      /* the widest this machine runs */
  ARCLEN_KERNEL_SCALAR,    /* one square root at a time */
  ARCLEN_KERNEL_SSE2,      /* a pair per packed square root */
  ARCLEN_KERNEL_AVX,       /* two pairs per packed square root */
  ARCLEN_KERNEL_AVX512     /* four pairs per packed square root */
};

/* s + sum over i in [i0, half) of w[i] (f(c - half_width x[i]) + f(c + half_width x[i])),
** f the speed on h (arclen_hodo_speed): each pair's two speeds added
** first, pair i into sum (i - i0) mod 4 (s starts the first), and the
** sums added up as (s0 + s1) + (s2 + s3). */
double arclen_speed_pairs(const arclen_hodo *h, const double *x,
                          const double *w, int i0, int half, double c,
                          double half_width, double s);

/* half_width times arclen_speed_pairs: the rule's value on a piece.  The
** product is made here, in a function of its own, so that no caller's
** addition can be fused with it: the default method's fast and general
** paths add the pieces at different sites, and must agree to the bit. */
double arclen_speed_rule(const arclen_hodo *h, const double *x,
                         const double *w, int i0, int half, double c,
                         double half_width, double s);

/* The name of the kernel arclen_speed_pairs runs here: "avx512", "avx",
** "sse2" or "scalar". */
const char *arclen_speed_kernel(void);

/* The same by a given kernel (for the checks that they agree); a kernel
** this build or machine lacks falls back to a narrower one. */
double arclen_speed_pairs_by(int kernel, const arclen_hodo *h,
                             const double *x, const double *w, int i0,
                             int half, double c, double half_width, double s);

#endif
