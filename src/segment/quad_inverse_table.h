/*
** quad_inverse_table.h -- polynomials for quad_time.c, which inverts the
** parabola's length in its own variable: G(U) = U sqrt(1 + U^2) + asinh U
** (tools/gen_quad_inverse.py fits and checks them).
*/
#ifndef ARCLEN_QUAD_INVERSE_TABLE_H
#define ARCLEN_QUAD_INVERSE_TABLE_H

/* G^-1(y) for y in [2^j, 2^(j+1)), JMIN <= j < JMAX, the octave cut into
** NSUB pieces by the mantissa m = y 2^-j: row [j - JMIN][i] holds c0 ..
** c_DEG of the polynomial in r = (m - 1 - (i + 1/2)/NSUB) 2 NSUB, in [-1,
** 1], evaluated in Estrin's order within EPS units of 2^-53 of G^-1(y)
** (its coefficients' own rounding and the evaluation's included). */
#define ARCLEN_QI_JMIN (-6)
#define ARCLEN_QI_JMAX 16
#define ARCLEN_QI_NSUB_BITS 4                 /* NSUB = 2^NSUB_BITS pieces */
#define ARCLEN_QI_NSUB (1 << ARCLEN_QI_NSUB_BITS)
#define ARCLEN_QI_DEG 7
#define ARCLEN_QI_EPS 6
/* a row of eight doubles on one cache line where the compiler can say so */
#if defined(__GNUC__)
#define ARCLEN_QI_ALIGNED __attribute__((aligned(64)))
#elif defined(_MSC_VER)
#define ARCLEN_QI_ALIGNED __declspec(align(64))
#else
#define ARCLEN_QI_ALIGNED
#endif
extern ARCLEN_QI_ALIGNED const double
  arclen_qi_ginv[ARCLEN_QI_JMAX - ARCLEN_QI_JMIN][ARCLEN_QI_NSUB]
                [ARCLEN_QI_DEG + 1];

#endif
