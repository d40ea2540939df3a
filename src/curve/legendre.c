/*
** legendre.c -- Gauss-Legendre rules of any order, computed rather than
** tabulated: the nodes are the roots of the Legendre polynomial P_n,
** found by Newton's method from Tricomi's asymptotic guess, and the
** weights are 2 / ((1 - x^2) P_n'(x)^2) (Abramowitz & Stegun 25.4.29).
*/
#include <math.h>

#include "arclen.h"
#include "curve/numeric.h"

#define NEWTON_CAP 100   /* quadratic convergence needs < 10 from the guess */

/* P_n(x) by the three-term recurrence (A&S 22.7.10); *dp gets P_n'(x). */
static double legendre_p(int n, double x, double *dp) {
  double p0 = 1.0, p1 = x;
  int k;
  if (n == 0) { *dp = 0.0; return 1.0; }
  for (k = 2; k <= n; k++) {
    double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  /* A&S 22.8.5; x is never +-1 here (roots lie strictly inside). */
  *dp = n * (x * p1 - p0) / (x * x - 1.0);
  return p1;
}

int arclen_gauss_legendre(int n, double *x, double *w) {
  int i, half = (n + 1) / 2;
  if (n < 1 || n > ARCLEN_GL_MAXN) return ARCLEN_EDOMAIN;
  for (i = 0; i < half; i++) {
    /* i-th largest root of P_n; guess from A&S 22.16.6 (Tricomi). */
    double r = cos(ARCLEN_PI * (i + 0.75) / (n + 0.5)), dp = 0.0, dx;
    int it;
    for (it = 0; it < NEWTON_CAP; it++) {
      double p = legendre_p(n, r, &dp);
      dx = p / dp;
      r -= dx;
      if (fabs(dx) <= 1e-15) break;   /* next step would be ~1e-30 */
    }
    legendre_p(n, r, &dp);
    /* Map [-1, 1] to [0, 1]: node (1 -+ r)/2, weight halved. */
    x[i] = 0.5 - 0.5 * r;
    x[n - 1 - i] = 0.5 + 0.5 * r;
    w[i] = w[n - 1 - i] = 1.0 / ((1.0 - r * r) * dp * dp);
  }
  if (n % 2 == 1) x[half - 1] = 0.5;   /* the middle root is exactly 0 */
  return ARCLEN_OK;
}
