/*
** fuzz_conic.c -- conic*.c on fuzzed conics: Floater's cubics, the
** Theorem 1 bound, the exact conic length and the arc descriptions.
** Invariants: a valid conic (arclen_conic_check) gives cubics whose first
** and last points are p0 and p2 exactly and whose pieces join exactly;
** every number is finite; the bound is >= 0 (or +inf); the exact length
** is finite, >= the chord |p2 - p0| and <= the control polygon |p1 - p0| +
** |p2 - p1| (a rational quadratic with w > 0 lies in its convex triangle
** and is convex), up to LEN_RTOL relative: the accuracy conic_length
** claims and spec/conic_spec.lua checks against mpmath (1e-14), which is
** all a length within rounding of the polygon (w -> inf) or of the chord
** (w -> 0) may overshoot by; and LEN_ATOL absolute for lengths in the
** subnormal range (a few of its ulps, 2^-1074 each).  Errors only where
** doubles cannot hold the answer: the length EOVERFLOW when the polygon
** reaches DBL_MAX, the cubics EOVERFLOW when a point is beyond 0.6 DBL_MAX
** (control points lie within 4/3 of the triangle: the mid-point scheme's
** lambda < 4/3); the ellipse and SVG arc conversions give finite conics or
** an error code, never NaN or inf.
*/
#include "arclen.h"
#include "fuzz_input.h"

#define MAXLEVEL_FUZZ 6     /* 64 pieces: enough to check joins */
#define LEN_RTOL 1e-14L
#define LEN_ATOL 0x1p-1070

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static double out[8 << MAXLEVEL_FUZZ];
  fz_reader rd;
  double p[6], w, bound, len, c[12] = {0};
  int i, level, scheme, rc;
  fz_init(&rd, data, size);
  for (i = 0; i < 6; i++) p[i] = fz_double(&rd);
  w = fz_double(&rd);
  level = (int)fz_range(&rd, 0, MAXLEVEL_FUZZ);
  scheme = (int)fz_range(&rd, 0, ARCLEN_CONIC_NSCHEMES - 1);
  for (i = 0; i < 6; i++) c[i] = p[i];
  c[6] = w;
  rc = arclen_conic_check(p, w);
  if (rc == ARCLEN_OK) {
    double pmax = 0;
    for (i = 0; i < 6; i++) pmax = fmax(pmax, fabs(p[i]));
    rc = arclen_conic_cubics(p, w, scheme, level, out, &bound);
    if (rc == ARCLEN_EOVERFLOW && pmax >= 0.6 * DBL_MAX) goto length;
    if (rc != ARCLEN_OK) fz_fail("conic_cubics", c, 3, "code %g at level %g", rc, level);
    if (!(bound >= 0)) fz_fail("conic bound", c, 3, "bound %g at level %g", bound, level);
    if (out[0] != p[0] || out[1] != p[1] || out[(8 << level) - 2] != p[4] ||
        out[(8 << level) - 1] != p[5])
      fz_fail("conic ends", c, 3, "first x %g, last x %g", out[0], out[(8 << level) - 2]);
    for (i = 0; i < (8 << level); i++)
      if (!isfinite(out[i])) fz_fail("conic cubics finite", c, 3, "out[%g] = %g", i, out[i]);
    for (i = 1; i < (1 << level); i++)
      if (out[8 * i] != out[8 * i - 2] || out[8 * i + 1] != out[8 * i - 1])
        fz_fail("conic joins", c, 3, "piece %g starts at x %g", i, out[8 * i]);
  length:
    rc = arclen_conic_length(p, w, &len, NULL);
    if (rc == ARCLEN_OK) {
      double ch[6] = {p[0], p[1], 0, 0, p[4], p[5]};
      long double chord = fz_dist(ch, 2, 0, 2);
      long double poly = fz_dist(p, 2, 0, 1) + fz_dist(p, 2, 1, 2);
      if (!isfinite(len)) fz_fail("conic length", c, 3, "length %g, polygon %g", len, (double)poly);
      if (len < chord * (1 - LEN_RTOL) - LEN_ATOL)
        fz_fail("conic length < chord", c, 3, "%.17g < %.17g", len, (double)chord);
      if (len > poly * (1 + LEN_RTOL) + LEN_ATOL)
        fz_fail("conic length > polygon", c, 3, "%.17g > %.17g", len, (double)poly);
    } else if (rc != ARCLEN_EOVERFLOW ||
               fz_dist(p, 2, 0, 1) + fz_dist(p, 2, 1, 2) < DBL_MAX * (1 - LEN_RTOL)) {
      fz_fail("conic length code", c, 3, "code %g %g", rc, 0);
    }
  } else if (rc != ARCLEN_EINVAL && rc != ARCLEN_EDOMAIN) {
    fz_fail("conic_check code", c, 3, "code %g %g", rc, 0);
  }
  /* Arc descriptions. */
  {
    double e[28], sv[7];
    int n = arclen_ellipse_conics(p[0], p[1], fabs(p[2]), fabs(p[3]), p[4],
                                  p[5], fmod(w, 7.0), e);
    if (n > 4) fz_fail("ellipse_conics count", c, 3, "n = %g %g", n, 0);
    /* points lie within 1.5 (rx + ry) of the centre (p1 at most sqrt 2 rx) */
    if (n == ARCLEN_EOVERFLOW &&
        fabsl(p[0]) + fabsl(p[1]) + 1.5L * (fabsl(p[2]) + fabsl(p[3])) < DBL_MAX)
      fz_fail("ellipse_conics overflow", c, 3, "n = %g %g", n, 0);
    for (i = 0; i < 7 * (n > 0 ? n : 0); i++)
      if (!isfinite(e[i])) fz_fail("ellipse_conics finite", c, 3, "e[%g] = %g", i, e[i]);
    rc = arclen_svg_arc_center(p[0], p[1], p[2], p[3], w, (int)(fz_byte(&rd) & 1),
                               (int)(fz_byte(&rd) & 1), p[4], p[5], sv);
    if (rc == ARCLEN_SVGARC_ARC)
      for (i = 0; i < 7; i++)
        if (!isfinite(sv[i])) fz_fail("svg_arc_center finite", c, 3, "c[%g] = %g", i, sv[i]);
  }
  return 0;
}
