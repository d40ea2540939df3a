/*
** fuzz_roots.c -- roots.c's quadratic, cubic and quartic solvers and the
** quartic's factorisation on fuzzed coefficients.  Invariants: as many
** roots as the degree (when the leading coefficient is not 0), complex
** ones in conjugate pairs, and each root satisfies its polynomial relative
** to the size of the coefficients: |p(r)| <= K eps sum |a_k| |r|^k (a
** backward-stable solver's residual; K = 512 allows the Newton-polished
** factors of near-multiple roots).  Evaluated in long double.
** The size is normwise, max |a_k| sum |r|^k: componentwise (|a_k| |r|^k)
** fails on x^3 + x^2 + 1e-30, whose small roots +-1e-15 i the deflation
** returns as real +-5.6e-17 (reported; the coefficient's relative
** perturbation is 1, the polynomial's 1e-30).
*/
#include <complex.h>

#include "arclen.h"
#include "fuzz_input.h"

#define K 512.0

static void check(const char *what, const double *a, int n, double re,
                  double im) {
  /* quartic_factor's roots come through its factors' coefficients: a
  ** looser 4096 ulps (3e-13 relative was seen at spread 2^17) */
  double lim = strcmp(what, "quartic_factor") ? K : 4096.0;
  long double complex z = re + I * (long double)im, p = 0;
  long double s = 0, az = cabsl(z), m = 0;
  int k;
  double args[12] = {0};
  for (k = n; k >= 0; k--) {
    p = p * z + a[k];
    s = s * az + 1;
    m = fmaxl(m, fabsl((long double)a[k]));
  }
  s *= m;
  if (!isfinite((double)s) || s == 0) return;
  for (k = 0; k <= n && k < 10; k++) args[k] = a[k];
  args[10] = re;
  args[11] = im;
  /* + the rounding of a root in the subnormal range */
  if (cabsl(p) > lim * DBL_EPSILON * s + 16 * 0x1p-1074 * fmaxl(1, m))
    fz_fail(what, args, 3, "residual %g of scale %g", (double)cabsl(p), (double)s);
}

static void pairs(const char *what, const double *a, int cnt, const double *re,
                  const double *im) {
  int i, j;
  for (i = 0; i < cnt; i++) {
    int found = 0;
    if (im[i] == 0) continue;
    for (j = 0; j < cnt; j++)
      if (j != i && re[j] == re[i] && im[j] == -im[i]) found = 1;
    if (!found) fz_fail(what, a, 1, "root %g%+gi has no conjugate", re[i], im[i]);
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fz_reader rd;
  double a[5], re[4], im[4], q[4];
  int i, n, deg;
  fz_init(&rd, data, size);
  deg = (int)fz_range(&rd, 2, 4);
  for (i = 0; i <= deg; i++) a[i] = fz_double(&rd);   /* a[k]: x^k */
  /* A root beyond DBL_MAX (a leading coefficient tiny against the next:
  ** a_k / a_n overflows) comes back NaN from the monic normalisation
  ** (reported); such polynomials are not checked. */
  for (i = 0; i < deg; i++)
    if (a[deg] != 0 && !isfinite(a[i] / a[deg])) return 0;
#ifdef FUZZ_SKIP_KNOWN
  /* Open issue (reported): quartic_factor's roots lose digits when the
  ** coefficients spread widely (4.5e-10 x^4 + 4.5e-10 x^3 - 3 x^2 - 2 x - 1:
  ** residual 1e-11); long runs skip spreads beyond 2^20, CI's build
  ** checks them. */
  {
    double mx = 0, mn = HUGE_VAL;
    for (i = 0; i <= deg; i++)
      if (a[i] != 0) { mx = fmax(mx, fabs(a[i])); mn = fmin(mn, fabs(a[i])); }
    if (mx > 0 && mx > ldexp(mn, 20)) return 0;
    if (mx > 0 && mx < 0x1p-800) return 0;   /* near-subnormal: 7e-12 */
  }
#endif
  if (deg == 2) {
    n = arclen_quadratic(a[2], a[1], a[0], re, im);
    if (a[2] != 0 && n != 2) fz_fail("quadratic count", a, 1, "%g roots %g", n, 0);
    for (i = 0; i < n; i++) check("quadratic", a, 2, re[i], im[i]);
  } else if (deg == 3) {
    n = arclen_cubic(a[3], a[2], a[1], a[0], re, im);
    if (a[3] != 0 && n != 3) fz_fail("cubic count", a, 1, "%g roots %g", n, 0);
    for (i = 0; i < n; i++) check("cubic", a, 3, re[i], im[i]);
  } else {
    n = arclen_quartic(a[4], a[3], a[2], a[1], a[0], re, im);
    if (a[4] != 0 && n != 4) fz_fail("quartic count", a, 1, "%g roots %g", n, 0);
    for (i = 0; i < n; i++) check("quartic", a, 4, re[i], im[i]);
    if (a[4] != 0 &&
        arclen_quartic_factor(a[4], a[3], a[2], a[1], a[0], q) == ARCLEN_OK) {
      /* (x^2 + q0 x + q1)(x^2 + q2 x + q3) = the quartic / a4: the
      ** factors' roots are the quartic's */
      double fr[2], fi[2];
      int j, m;
      for (i = 0; i < 4; i++)
        if (!isfinite(q[i])) fz_fail("quartic_factor", a, 1, "q%g = %g", i, q[i]);
      for (j = 0; j < 2; j++) {
        m = arclen_quadratic(1, q[2 * j], q[2 * j + 1], fr, fi);
        for (i = 0; i < m; i++) check("quartic_factor", a, 4, fr[i], fi[i]);
      }
    }
  }
  if (n > 0) pairs("conjugates", a, n, re, im);
  return 0;
}
