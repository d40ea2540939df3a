/*
** ellipse_table.h -- the Bernstein-ellipse quantities of the error bound
** (gauss_bound.c) as lines on short cells of x = a - 1, a the ellipse's
** semi-major axis: a lookup in place of a chain of square roots and
** divisions.  Each line bounds its quantity on its cell in the safe
** direction (tools/gen_ellipse_table.py says why and checks it).
*/
#ifndef ARCLEN_ELLIPSE_TABLE_H
#define ARCLEN_ELLIPSE_TABLE_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

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

/* x = a - 1 rounded down for the Bernstein ellipse through z = u + iv in
** an interval's units (foci +-1: a = (|z - 1| + |z + 1|)/2, two square
** roots side by side); next to the interval a - 1 cancels, so it is
** lowered by the sum's rounding (each root within 2 ulps).  *s12 = 2 a,
** from below too. */
static inline double arclen_ellipse_am1(double u, double v, double *s12) {
  double r1 = sqrt((u - 1) * (u - 1) + v * v);
  double r2 = sqrt((u + 1) * (u + 1) + v * v);
  *s12 = r1 + r2;
  return (*s12 - 2) * 0.5 - *s12 * 0x1p-50;
}

/* The cell of x = a - 1 and *dx = x - the cell's start (exact: Sterbenz);
** NULL where x lies off the table, or is 0, negative or NaN (its bits then
** give no cell). */
static inline const arclen_ellipse_cell *arclen_ellipse_cell_of(double am1,
                                                                double *dx) {
  uint64_t u, k;
  double x0;
  memcpy(&u, &am1, sizeof u);
  k = (u >> ARCLEN_ELLIPSE_SHIFT) - ARCLEN_ELLIPSE_BASE;
  if (k >= ARCLEN_ELLIPSE_CELLS) return NULL;
  u &= ~((1ULL << ARCLEN_ELLIPSE_SHIFT) - 1);    /* the cell's start */
  memcpy(&x0, &u, sizeof x0);
  *dx = am1 - x0;
  return &arclen_ellipse_cells[k];
}

/* Bounds of the n-point rule's error on T_2n, on T_2n+2, and on T_k for
** even k in [2n + 4, 3n] (it is 0 for odd k), for every stored rule with
** n >= 2; beyond 3n it is at most 32/15.  With r = rho^-2 they bound
**     sum_{k even >= 2n} |E_n(T_k)| rho^(2n - k) <= C(n) =
**         alias[0] + alias[1] r + (alias[2] r^2 + (32/15) rho^-(n+1)) / (1 - r),
** the factor the bound of gauss_bound.c puts on each branch pair. */
extern const double arclen_gauss_alias[3];

#endif
