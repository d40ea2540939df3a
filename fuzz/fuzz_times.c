/*
** fuzz_times.c -- arclen_times (many distances on one cubic in one pass)
** on fuzzed cubics and runs of sorted distances (evenly spaced, clustered,
** repeated, beyond both ends).  Invariants: t in [0, 1] and ascending;
** s <= 0 gives 0; every t within rtol L of the truth, as arclen_time's
** (s(t) measured by gauss at 1e-14, plus the rounding allowance); the
** points are arclen_point's at those t; unsorted or NaN distances are
** refused with all t NaN.
*/
#include "arclen.h"
#include "fuzz_input.h"

#define ULPS (32 * DBL_EPSILON)
#define MAXN 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fz_reader rd;
  double c[12], rtol, L, s[MAXN], t[MAXN], p[3 * MAXN], v[3 * MAXN];
  int dim, n, i, k;
  unsigned mode;
  arclen_opts o;
  fz_init(&rd, data, size);
  dim = (fz_byte(&rd) & 1) ? 3 : 2;
  rtol = ldexp(1.0, -(int)fz_range(&rd, 4, 49));
  n = (int)fz_range(&rd, 0, MAXN);
  mode = fz_byte(&rd);
  fz_curve(&rd, dim, c);
  arclen_opts_init(&o);
  o.rtol = 1e-14;
  if (arclen_length_gauss(c, dim, &o, &L, NULL) != ARCLEN_OK)
    fz_fail("gauss length", c, dim, "failed %g %g", 0, 0);
  if (!isfinite(L)) return 0;
  for (i = 0; i < n; i++) {
    double u = (double)fz_bits(&rd, 2) / 65535.0;
    if (mode & 1) u = (double)i / (n > 1 ? n - 1 : 1);          /* even */
    if (mode & 2) u = 0.5 + (u - 0.5) * 1e-6;                  /* clustered */
    s[i] = (u * 1.25 - 0.125) * L;
  }
  for (i = 1; i < n; i++)                                       /* insertion sort */
    for (k = i; k > 0 && s[k] < s[k - 1]; k--) {
      double x = s[k]; s[k] = s[k - 1]; s[k - 1] = x;
    }
  if ((mode & 4) && n > 2) s[n / 2] = s[n / 2 - 1];            /* repeated */
  if (arclen_times(c, dim, s, n, rtol, t, p, v) != ARCLEN_OK)
    fz_fail("times", c, dim, "failed, n %g rtol %g", n, rtol);
  for (i = 0; i < n; i++) {
    double q[3], st;
    if (!(t[i] >= 0 && t[i] <= 1)) fz_fail("times", c, dim, "t %g at s %g", t[i], s[i]);
    if (i > 0 && t[i] < t[i - 1]) fz_fail("times", c, dim, "t %g after %g", t[i], t[i - 1]);
    if (s[i] <= 0 && t[i] != 0) fz_fail("times", c, dim, "t %g for s %g <= 0", t[i], s[i]);
    arclen_point(c, dim, t[i], q);
    for (k = 0; k < dim; k++)
      if (memcmp(&q[k], &p[dim * i + k], sizeof q[k]))
        fz_fail("times", c, dim, "point %g, arclen_point %g", p[dim * i + k], q[k]);
    if (s[i] > 0 && s[i] < L) {
      arclen_opts_init(&o);
      o.rtol = 1e-14;
      o.t1 = t[i];
      arclen_length_gauss(c, dim, &o, &st, NULL);
      if (fabs(st - s[i]) > (rtol + 1e-14 + 2 * ULPS) * L + 0x1p-1000)
        fz_fail("times", c, dim, "s(t) = %.17g, goal %.17g", st, s[i]);
    }
  }
  if (n > 1 && s[1] < HUGE_VAL) {   /* refused: not ascending (s overflows past L ~ DBL_MAX) */
    double x = s[0];
    s[0] = HUGE_VAL;
    if (arclen_times(c, dim, s, n, rtol, t, NULL, NULL) != ARCLEN_EDOMAIN || !isnan(t[0]))
      fz_fail("times", c, dim, "unsorted distances accepted, n %g %g", n, 0);
    s[0] = x;
  }
  return 0;
}
