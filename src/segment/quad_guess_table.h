/*
** quad_guess_table.h -- polynomials for quad_time.c's first guess, which
** inverts the parabola's length in its own variable: G(U) = U sqrt(1 + U^2)
** + asinh U, and log for the guess's asinh (tools/gen_quad_guess.py fits
** and checks them; the guess needs ~1e-5, the certified step decides).
*/
#ifndef ARCLEN_QUAD_GUESS_TABLE_H
#define ARCLEN_QUAD_GUESS_TABLE_H

/* G^-1(y) for y in [2^j, 2^(j+1)), JMIN <= j < JMAX: row j - JMIN holds
** c0 .. c_DEG of the polynomial in r = m - 3/2, m = y 2^-j (within 2e-6
** of sqrt(1 + U^2)). */
#define ARCLEN_QG_JMIN (-6)
#define ARCLEN_QG_JMAX 16
#define ARCLEN_QG_DEG 5
extern const double
  arclen_qg_ginv[ARCLEN_QG_JMAX - ARCLEN_QG_JMIN][ARCLEN_QG_DEG + 1];

/* log m for m in [1, 2): c0 .. c_LOG_DEG in r = m - 3/2 (within 2e-6). */
#define ARCLEN_QG_LOG_DEG 6
extern const double arclen_qg_log[ARCLEN_QG_LOG_DEG + 1];

#endif
