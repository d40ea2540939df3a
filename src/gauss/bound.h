/*
** bound.h -- an a priori bound on the error of Gauss-Legendre
** quadrature of the speed over one piece, read off the speed's branch
** points (gauss_bound.c), and the order it asks for.
*/
#ifndef ARCLEN_GAUSS_BOUND_H
#define ARCLEN_GAUSS_BOUND_H

#include <stdint.h>
#include <string.h>

#include "curve/cubic.h"

/* log2(x) within ARCLEN_LOG2_ERR, for choosing orders (callers add the
** margin): log2(m 2^e) = e + log2(1 + t), t = m - 1 in [0, 1), and
** t + t (1 - t)(0.418 - 0.148 t) is within 0.00124 of log2(1 + t) on
** [0, 1] (checked with mpmath on 10^5 points).  No division and no call:
** the exponent and mantissa are read off the bits (IEEE 754 binary64);
** zero, subnormals, inf and NaN go to log2().  Inline: the bounds call it
** on their critical path. */
#define ARCLEN_LOG2_ERR 0.0015
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double arclen_rough_log2(double x) {
  uint64_t u;
  double t;
  int e;
  memcpy(&u, &x, sizeof u);
  e = (int)(u >> 52);                   /* with the sign: > 0x7fe if < 0 */
  if ((unsigned)(e - 1) >= 0x7fe) return log2(x);
  u = (u & 0xfffffffffffffULL) | 0x3ff0000000000000ULL;
  memcpy(&t, &u, sizeof t);
  t -= 1;
  return arclen_muladd(t * (1 - t), arclen_muladd(-0.148, t, 0.418), (e - 1023) + t);
}

/* What the bound needs of a curve, once: per branch pair its upper root
** and the elementary symmetric functions of the square roots of its
** distances to the other roots of Q (t units), alone and times the Beta
** integrals at the reference order of the estimates.  ok == 0: a root lies too
** far for the fast form (beyond 2^100 scaled units), and the pieces take
** the ellipse bound. */
typedef struct arclen_cut_curve {
  const arclen_branch *br;
  int ok;
  int has_real;             /* real (double) roots: kinks to keep outside */
  int npair;                /* branch pairs (conjugate roots, im > 0) */
  double re[2], im[2];      /* their upper roots */
  double sym[2][4];         /* sym[j][i]: coefficient of Z^(i+1) */
  double symref[2][4];      /* sym[j][i] beta[i][the reference order] */
} arclen_cut_curve;

void arclen_cut_prepare(const arclen_branch *br, arclen_cut_curve *cc);

/* The bound of one piece [c - half_width, c + half_width] as a function of the order n:
**     sum_j 2^(-n lam_j) C_j(n) sum_i sym_j[i] Z_j^(i+1) beta[i][n]
** times the common factor lead 4/pi (and half_width); see gauss_bound.c. */
typedef struct arclen_cut_piece {
  int nt;                   /* terms: one per branch pair */
  int inside;               /* a real root strictly inside: must split */
  double lam[2];            /* log2(rho^2), rounded down */
  double ilam[2];           /* 1/lam, taken once for every estimate */
  double lref[2];           /* log2 of the term's sum at the reference order */
  double cc[2], z[2];       /* C_j(2), good at every order, and Z_j */
  double cref[2];           /* C_j(REF_ORDER), from that order on */
} arclen_cut_piece;

void arclen_cut_bound(const arclen_cut_curve *cc, double c, double half_width,
                      arclen_cut_piece *pbound);
/* The bound at order n (2 <= n <= ARCLEN_GAUSS_MAX) over 2^lgoal. */
double arclen_cut_ratio(const arclen_cut_curve *cc, const arclen_cut_piece *pbound,
                        double lgoal, int n);
/* An order n in [2, nmax] whose bound is at most 2^lgoal (lgoal includes
** log2 of the common factor), the least or within a point of it; 0 if
** none.  When ratio is not NULL it gets the bound over 2^lgoal there. */
int arclen_cut_order(const arclen_cut_curve *cc, const arclen_cut_piece *pbound,
                     double lgoal, int nmax, double *ratio);
/* The same orders for np <= ARCLEN_CUT_PIECES pieces [c_i - hh_i, c_i +
** hh_i] between the branch points br, as arclen_cut_prepare,
** arclen_cut_bound and arclen_cut_order give them, for the common case --
** two branch pairs, no real root, both within reach -- with no record
** kept between them: 1 and the orders in n[], or 0 when the case is not
** that or a piece needs a cut (no order up to nmax will do); the caller
** then takes the three. */
#define ARCLEN_CUT_PIECES 3
int arclen_cut_orders(const arclen_branch *br, int np, const double *c,
                      const double *half_width, double lgoal, int nmax, int *n);

#endif
