/*
** ellipse_table.h -- the Bernstein-ellipse quantities of the error bound
** (gauss_bound.c) as lines on short cells of x = a - 1, a the ellipse's
** semi-major axis: a lookup in place of a chain of square roots and
** divisions.  Each line bounds its quantity on its cell in the safe
** direction (tools/gen_ellipse_table.py says why and checks it).
*/
#ifndef ARCLEN_ELLIPSE_TABLE_H
#define ARCLEN_ELLIPSE_TABLE_H

/* Cells: each octave of x in [2^EMIN, 2^EMAX) in four, found from the bits
** of x: cell (bits >> SHIFT) - BASE, starting at those bits with the rest
** cleared. */
#define ARCLEN_ELLIPSE_EMIN (-36)
#define ARCLEN_ELLIPSE_EMAX 12
#define ARCLEN_ELLIPSE_SHIFT 50
#define ARCLEN_ELLIPSE_BASE ((1023 + ARCLEN_ELLIPSE_EMIN) * 4)
#define ARCLEN_ELLIPSE_CELLS ((ARCLEN_ELLIPSE_EMAX - ARCLEN_ELLIPSE_EMIN) * 4)

/* On a cell starting at x0, with dx = x - x0: lam + dx dlam <= log2(rho^2),
** ilam + dx dilam >= 1 / (lam + dx dlam), c2 + dx dc2 >= C(2) and cref +
** dx dcref >= C(32), the aliasing tail below, and sa + dx dsa >= sqrt(a)
** (the last also for an a up to 2^-47 above 1 + x). */
typedef struct arclen_ellipse_cell {
  double lam, dlam, ilam, dilam, c2, dc2, cref, dcref, sa, dsa;
} arclen_ellipse_cell;

extern const arclen_ellipse_cell arclen_ellipse_cells[ARCLEN_ELLIPSE_CELLS];

/* Bounds of the n-point rule's error on T_2n, on T_2n+2, and on T_k for
** even k in [2n + 4, 3n] (it is 0 for odd k), for every stored rule with
** n >= 2; beyond 3n it is at most 32/15.  With r = rho^-2 they bound
**     sum_{k even >= 2n} |E_n(T_k)| rho^(2n - k) <= C(n) =
**         alias[0] + alias[1] r + (alias[2] r^2 + (32/15) rho^-(n+1)) / (1 - r),
** the factor the bound of gauss_bound.c puts on each branch pair. */
extern const double arclen_gauss_alias[3];

#endif
