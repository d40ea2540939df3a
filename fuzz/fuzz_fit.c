/*
** fuzz_fit.c -- the length-versus-t fits of lenfit*.c on fuzzed cubics and
** options.  Invariants: building returns 0 or ENOCONV (a tolerance that
** needs more spans than the cap); a built fit evaluates to finite values,
** value(t) in [0, 1] up to its tolerance (when it has one), value(0) = 0, value(1) = 1,
** time(s) in [0, 1]; with a tolerance (hermite), |value(t) - s(t)/s(1)| <=
** tol at fuzzed t against gauss at 1e-13 (the fit's stated guarantee), and
** value(time(length(t))) = value(t) within tol where the fit is monotone.
*/
#include "arclen.h"
#include "fuzz_input.h"

static const arclen_fit_opts *current;

static void fail(const char *what, const double *c, int dim, const char *fmt,
                 double a, double b) {
  fprintf(stderr, "fit options: method %d, n %d, tol %g, monotone %d\n",
          current->method, current->n, current->tol, current->monotone);
  fz_fail(what, c, dim, fmt, a, b);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static arclen_fit_span spans[ARCLEN_FIT_MAXSPANS];
  fz_reader rd;
  double c[12], L;
  int dim, rc, i;
  arclen_fit f;
  arclen_fit_opts fo;
  arclen_opts o;
  unsigned mode;
  fz_init(&rd, data, size);
  dim = (fz_byte(&rd) & 1) ? 3 : 2;
  mode = fz_byte(&rd);
  arclen_fit_opts_init(&fo);
  fo.method = (mode & 1) ? ARCLEN_FIT_PAPER : ARCLEN_FIT_HERMITE;
  fo.monotone = (mode & 2) != 0 && fo.method == ARCLEN_FIT_PAPER;
  fo.n = (mode & 4) ? (int)fz_range(&rd, 1, 16) : 0;
  fo.tol = (fo.method == ARCLEN_FIT_HERMITE && (mode & 8))
               ? ldexp(1.0, -(int)fz_range(&rd, 7, 29)) : 0;  /* 2^-29 > 1e-9 */
  fz_curve(&rd, dim, c);
  current = &fo;
  arclen_opts_init(&o);
  o.rtol = 1e-13;
  if (arclen_length_gauss(c, dim, &o, &L, NULL) != ARCLEN_OK) abort();
  rc = arclen_fit_build(c, dim, &fo, &f, spans, ARCLEN_FIT_MAXSPANS);
  if (rc == ARCLEN_ENOCONV) return 0;
  if (rc != ARCLEN_OK) fail("fit_build", c, dim, "code %g, tol %g", rc, fo.tol);
  if (f.nspans < 1 || f.nspans > ARCLEN_FIT_MAXSPANS)
    fail("fit spans", c, dim, "nspans %g %g", f.nspans, 0);
  if (!(L > 0) || !isfinite(L)) return 0;   /* a point or an overflowing curve */
  /* a length within the fit's tolerance of DBL_MAX may come out inf (as in
  ** fuzz_length: +inf is allowed where the polygon, times 1 + tol, is) */
  if (fz_polygon(c, dim) * (1 + 0x1p-6L) > DBL_MAX) return 0;
  {
    double slack = (fo.tol > 0 ? fo.tol : 0.5) + 1e-12;
    double v0 = arclen_fit_value(&f, 0), v1 = arclen_fit_value(&f, 1);
    if (fabs(v0) > 1e-12 || fabs(v1 - 1) > 1e-12)
      fail("fit ends", c, dim, "value(0) = %g, value(1) = %g", v0, v1);
    for (i = 0; i < 6; i++) {
      double t = (double)fz_bits(&rd, 2) / 65535.0;
      double v = arclen_fit_value(&f, t), sl = arclen_fit_slope(&f, t);
      double len = arclen_fit_length(&f, t), tt = arclen_fit_time(&f, len);
      if (!isfinite(v) || !isfinite(sl) || !isfinite(len) || !isfinite(tt))
        fail("fit finite", c, dim, "value %g, time %g", v, tt);
      /* the paper's fixed-knot fits promise no bound (n = 1 overshoots to
      ** 1.98): the range is checked with a tolerance only */
      if (fo.tol > 0 && (v < -slack || v > 1 + slack))
        fail("fit range", c, dim, "value(t) = %g at t = %g", v, t);
      if (!(tt >= 0 && tt <= 1)) fail("fit time", c, dim, "time %g of t %g", tt, t);
      /* below 2^-960 the reference length itself is quantised by the
      ** subnormal spacing (68 ulps of 2^-1074 hold only 2 digits) */
      if (fo.tol > 0 && L > 0x1p-960) {
        double st;
        o.t1 = t;
        arclen_length_gauss(c, dim, &o, &st, NULL);
        if (fabs(v - st / L) > fo.tol * (1 + 1e-6) + 1e-12)
          fail("fit accuracy", c, dim, "|value - s/s(1)| = %.3g, tol %g",
                  fabs(v - st / L), fo.tol);
        if (arclen_fit_monotone(&f) &&
            fabs(arclen_fit_value(&f, tt) - v) > fo.tol + 1e-12)
          fail("fit inverse", c, dim, "value(time(length(t))) - value(t) = %g at %g",
                  arclen_fit_value(&f, tt) - v, t);
      }
    }
  }
  return 0;
}
