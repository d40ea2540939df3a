/*
** fuzz_roots.c -- roots.c's quadratic, cubic and quartic solvers and the
** quartic's factorisation on fuzzed coefficients.  Invariants: as many
** roots as the degree (when the leading coefficient is not 0), complex
** ones in conjugate pairs, factor coefficients finite unless a pair of
** roots has a sum or product beyond the double range, and each root (of
** the solvers, and of quartic_factor's two quadratics) satisfies its
** polynomial relative to the size of the coefficients:
**   |p(r)| <= K eps max|a_k| sum |r|^k   (+ subnormal rounding),
** evaluated in long double.  That is a backward error: r is an exact root
** of a polynomial whose coefficients moved by K eps of the largest.  Why
** K = 512: the roots come from quadratic factors whose coefficients
** reproduce the polynomial's to FACTOR_GOOD = 8 eps of each equation's
** terms (roots.c), and the stable quadratic adds a few eps; the terms of
** the factors' product at |r| exceed sum |a_k| |r|^k by at most
** (1 + 1)^4 = 16 when the factors' roots are no larger than r (the Newton
** polygon keeps larger roots in their own groups), so 8 * 16 = 128 eps,
** times 4 for Horner's and the quadratic's own roundings.  Measured: the
** largest ratio over the 1.4e8 executions of the change that fixed the
** spread and near-multiple cases was 3.2 eps (fuzz_roots -DFUZZ_STATS
** prints each new maximum), so K catches any real loss (those cases gave
** 1e3 to 1e15 eps).
** The size is normwise, max |a_k| sum |r|^k: componentwise (|a_k| |r|^k)
** fails on x^3 + x^2 + 1e-30, whose small roots +-1e-15 i the deflation
** returns as real +-5.6e-17 (the coefficient's relative perturbation is
** 1, the polynomial's 1e-30).
*/
#include <complex.h>

#include "arclen.h"
#include "fuzz_input.h"

#define K 512.0

#ifdef FUZZ_STATS
/* -DFUZZ_STATS: print each new largest |p(r)| / (eps size) per check, to
** measure the margin under K (the long-run figures in the comment above) */
static double worst[2];
#endif

static void check(const char *what, const double *a, int n, double re,
                  double im) {
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
#ifdef FUZZ_STATS
  {
    int w = strcmp(what, "quartic_factor") == 0;
    double r = (double)(cabsl(p) / (DBL_EPSILON * s));
    if (r > worst[w]) {
      worst[w] = r;
      fprintf(stderr, "STATS %s %.3g eps:", what, r);
      for (k = n; k >= 0; k--) fprintf(stderr, " %.17g", a[k]);
      fprintf(stderr, "\n");
    }
  }
#endif
  for (k = 0; k <= n && k < 10; k++) args[k] = a[k];
  args[10] = re;
  args[11] = im;
  /* + the rounding of a root in the subnormal range */
  if (cabsl(p) > K * DBL_EPSILON * s + 16 * 0x1p-1074 * fmaxl(1, m))
    fz_fail(what, args, 3, "residual %g of scale %g", (double)cabsl(p), (double)s);
}

/* A factor coefficient beyond the double range is +-inf by contract (the
** roots 2.83 and -8.4e307 of 1.19e-308 x^4 + x^3 - 2 x^2 - 2 x - 1 must
** pair up, their product overflows): legitimate only if two of the
** quartic's roots have a sum (q0, q2) or product (q1, q3) that large. */
static int beyond_range(int odd, const double *re, const double *im, int n) {
  long double big = 0;
  int i, j;
  for (i = 0; i < n; i++)
    for (j = i + 1; j < n; j++) {
      long double u = cabsl(re[i] + I * (long double)im[i]);
      long double v = cabsl(re[j] + I * (long double)im[j]);
      big = fmaxl(big, odd ? u * v : u + v);
    }
  return big >= (long double)DBL_MAX * (1 - 0x1p-40L);
}

/* All the roots, none lost or counted twice: their sum is -a_(n-1)/a_n.
** The residual check cannot see a root listed in place of another (the
** double root -1/2 of -x^2 (2x+1)^2 + 5e-116 x - 2e-174 came back as two
** more copies of its tiny pair).  A missing root moves the sum by its own
** size; a backward-stable solver's roots in an m-fold cluster may each
** sit eps^(1/m) of their size off (m <= 4: 1.2e-4), so 2^-8 of the sum
** of the sizes separates the two.  For the factors' roots the sizes of
** the quartic's roots count too (size): roots +-3.3e-207 make a factor
** x^2 - 1.1e-413, which is x^2 in double, their sum -4.6e-308 lost. */
static void root_sum(const char *what, const double *a, int n, const double *re,
                     const double *im, long double size) {
  long double sr = 0, si = 0, want = -(long double)a[n - 1] / a[n];
  int i;
  for (i = 0; i < n; i++) {
    sr += re[i]; si += im[i];
    size += cabsl(re[i] + I * (long double)im[i]);
  }
  size += fabsl(want);
  if (!isfinite((double)size)) return;
  if (hypotl(sr - want, si) > size * 0x1p-8L + 16 * 0x1p-1074)
    fz_fail(what, a, 1, "roots sum to %g, not %g", (double)sr, (double)want);
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
  if (deg == 2) {
    n = arclen_quadratic(a[2], a[1], a[0], re, im);
    if (a[2] != 0 && n != 2) fz_fail("quadratic count", a, 1, "%g roots %g", n, 0);
    for (i = 0; i < n; i++) check("quadratic", a, 2, re[i], im[i]);
  } else if (deg == 3) {
    n = arclen_cubic(a[3], a[2], a[1], a[0], re, im);
    if (a[3] != 0 && n != 3) fz_fail("cubic count", a, 1, "%g roots %g", n, 0);
    for (i = 0; i < n; i++) check("cubic", a, 3, re[i], im[i]);
    if (n == 3) root_sum("cubic sum", a, 3, re, im, 0);
  } else {
    n = arclen_quartic(a[4], a[3], a[2], a[1], a[0], re, im);
    if (a[4] != 0 && n != 4) fz_fail("quartic count", a, 1, "%g roots %g", n, 0);
    for (i = 0; i < n; i++) check("quartic", a, 4, re[i], im[i]);
    if (n == 4) root_sum("quartic sum", a, 4, re, im, 0);
    if (a[4] != 0 &&
        arclen_quartic_factor(a[4], a[3], a[2], a[1], a[0], q) == ARCLEN_OK) {
      /* (x^2 + q0 x + q1)(x^2 + q2 x + q3) = the quartic / a4: the
      ** factors' roots are the quartic's */
      double fr[4], fi[4];
      int j, m = 0;
      for (i = 0; i < 4; i++)
        if (!isfinite(q[i]) && !(isinf(q[i]) && beyond_range(i & 1, re, im, n)))
          fz_fail("quartic_factor", a, 1, "q%g = %g", i, q[i]);
      for (j = 0; j < 2; j++) {
        if (!isfinite(q[2 * j]) || !isfinite(q[2 * j + 1])) continue;
        m += arclen_quadratic(1, q[2 * j], q[2 * j + 1], fr + m, fi + m);
      }
      for (i = 0; i < m; i++) check("quartic_factor", a, 4, fr[i], fi[i]);
      if (m == 4) {
        long double size = 0;
        for (i = 0; i < n; i++) size += cabsl(re[i] + I * (long double)im[i]);
        root_sum("quartic_factor sum", a, 4, fr, fi, size);
      }
    }
  }
  if (n > 0) pairs("conjugates", a, n, re, im);
  return 0;
}
