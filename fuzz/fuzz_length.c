/*
** fuzz_length.c -- every length method of methods.c on fuzzed cubics.
** Invariants (finite inputs, a valid tolerance and range):
**   - the call succeeds (or says the dimension is not supported; MetaPost
**     may report its arithmetic overflow, as mpost does);
**   - the length is finite (+inf only when the control polygon itself,
**     times 1 + the method's tolerance, exceeds DBL_MAX) and has the sign
**     of t1 - t0;
**   - on [0, 1]: chord (1 - tol) <= L <= polygon (1 + tol), tol the
**     method's guarantee plus a few ulps;
**   - error-controlled methods agree with "gauss" within the sum of their
**     tolerances; on a sub-range, L(t0, t1) + L(t1, 1) = L(t0, 1);
**   - "gauss"'s info.err certifies it: at rtol and at 1e-15 the two
**     lengths differ by at most the sum of their info.err plus 64 eps of
**     rounding each (the reserve its tolerance keeps);
**   - "gauss"'s fast path (no report asked: length_fast, or the first
**     pieces' orders from arclen_cut_orders) gives the general path's
**     length (info asked: the cut records) to the bit, and so does the
**     plain API.
** The baselines run with at most 2000 steps (their 10^6 default is a
** reference row, not a fuzz target).
*/
#include "arclen.h"
#include "fuzz_input.h"

/* Rounding allowance of one call: the specs assert <= 1e-14 at rtol 1e-15
** (README); 32 ulps = 7.1e-15. */
#define ULPS (32 * DBL_EPSILON)
#define TINY 0x1p-1000            /* absolute slack for subnormal curves */

typedef struct row {
  double tol;        /* relative guarantee, 0: no bound checked */
  int controlled;    /* compared with gauss */
} row;

/* What each method guarantees at the requested rtol. */
static row guarantee(const char *name, double rtol, long steps) {
  row r = {0, 0};
  (void)steps;
  if (!strcmp(name, "gauss") || !strcmp(name, "gravesen") ||
      !strcmp(name, "gravesen-richardson")) {
    r.tol = rtol;
    r.controlled = 1;
  } else if (!strcmp(name, "elliptic")) {
    r.tol = 1e-12;           /* exact up to rounding; README claims <= 1e-13 */
    r.controlled = 1;
  } else if (!strcmp(name, "polyline")) {
    r.tol = 0;               /* inscribed: between chord and L, checked below */
  } else if (!strcmp(name, "metapost")) {
    r.tol = 0.02;            /* absolute Simpson tolerance, see below */
  } else {
    r.tol = 2.0;             /* trapezoid rules: speed <= 3 polygon */
  }
  return r;
}

static int slow_method(const char *name) {
  return !strcmp(name, "gravesen") || !strcmp(name, "gravesen-richardson");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fz_reader rd;
  double c[12], rtol, ref = 0, t0 = 0, t1 = 1;
  int dim, have_ref = 0;
  long steps;
  unsigned mode;
  const arclen_method *m;
  long double chord, poly;
  fz_init(&rd, data, size);
  dim = (fz_byte(&rd) & 1) ? 3 : 2;
  mode = fz_byte(&rd);
  rtol = ldexp(1.0, -(int)fz_range(&rd, 4, 49));    /* 2^-4 .. ~1.8e-15 */
  steps = fz_range(&rd, 1, 2000);
  if (mode & 1) {
    t0 = (double)fz_bits(&rd, 2) / 65535.0;
    t1 = (double)fz_bits(&rd, 2) / 65535.0;
  }
  fz_curve(&rd, dim, c);
  chord = fz_chord(c, dim);
  poly = fz_polygon(c, dim);

  for (m = arclen_method_list(); m->name; m++) {
    arclen_opts o;
    arclen_info info;
    double len, a;
    row g = guarantee(m->name, rtol, steps);
    int rc;
    arclen_opts_init(&o);
    o.rtol = rtol;
    o.t0 = t0;
    o.t1 = t1;
    o.steps = steps;
    /* Gravesen at tight tolerances on cusps costs 10^5+ subdivisions: a
    ** loose tolerance keeps the fuzzer fast; termination at 1e-12 is the
    ** hostile spec's job. */
    if (slow_method(m->name) && o.rtol < 1e-9) o.rtol = 1e-9;
    g = guarantee(m->name, o.rtol, steps);
    rc = m->length(c, dim, &o, &len, &info);
    if (rc == ARCLEN_EDIM) continue;
    if (rc == ARCLEN_EOVERFLOW && !strcmp(m->name, "metapost")) continue;
    if (rc != ARCLEN_OK)
      fz_fail(m->name, c, dim, "error code %g (rtol %g)", rc, o.rtol);
    a = fabs(len);
    /* a rule's value may exceed DBL_MAX where its bound poly (1 + tol)
    ** does (trapezoid: 1.5 x 1.4e308 on one step) */
    if (isnan(len) || (isinf(len) && poly * (1 + g.tol) <= DBL_MAX))
      fz_fail(m->name, c, dim, "length %g, polygon %g", len, (double)poly);
    /* MetaPost adds 2^-17 to every segment, even a point (as mpost does). */
    if ((t0 > t1 && len > 0) || (t0 < t1 && len < 0) ||
        (t0 == t1 && len != 0 && strcmp(m->name, "metapost")))
      fz_fail(m->name, c, dim, "sign of %g, t1 - t0 = %g", len, t1 - t0);
    if (t0 == 0 && t1 == 1 && isfinite(len)) {
      /* + the rounding of a power-basis or subdivision formulation:
      ** absolute, ~eps times the curve's size (polyline with 1 step gave
      ** 0 for a chord of 5e-195 on a curve of size 10) */
      long double lo = chord * (1 - g.tol - ULPS) - TINY - 64 * DBL_EPSILON * poly;
      long double hi = poly * (1 + g.tol + ULPS) + TINY;
      if (!strcmp(m->name, "metapost")) {   /* + 2^-17 bias, abs. tolerance */
        lo = chord * 0.98L - 0x1p-10;
        hi = poly * 1.02L + 0x1p-10;
      }
      if (!strcmp(m->name, "polyline")) hi = poly * (1 + ULPS) + TINY;
      if (a < lo) fz_fail(m->name, c, dim, "length %.17g < chord %.17g", a, (double)chord);
      if (a > hi) fz_fail(m->name, c, dim, "length %.17g > polygon %.17g", a, (double)poly);
    }
    if (!strcmp(m->name, "gauss") && isfinite(len)) {
      ref = len;
      have_ref = 1;
    } else if (g.controlled && have_ref && isfinite(len)) {
      double gt = fmax(rtol, 1e-15);
      /* a sub-range is cut out with arclen_subcurve (absolute rounding
      ** ~eps |P|), gauss integrates it directly */
      double cut = (t0 != 0 || t1 != 1) ? 64 * DBL_EPSILON * (double)poly : 0;
      if (fabs(len - ref) > (g.tol + gt + 2 * ULPS) * fabs(ref) + TINY + cut) {
        fprintf(stderr, "rtol %g, range [%g, %g]\n", o.rtol, t0, t1);
        fz_fail(m->name, c, dim, "length %.17g, gauss %.17g", len, ref);
      }
    }
  }

  /* The default method's certificate, against itself at full precision. */
  {
    arclen_opts o;
    arclen_info i1, i2;
    double l1, l2;
    arclen_opts_init(&o);
    o.rtol = rtol > 1e-15 ? rtol : 1e-15;
    o.t0 = t0;
    o.t1 = t1;
    if (arclen_length_gauss(c, dim, &o, &l1, &i1) != ARCLEN_OK) abort();
    o.rtol = 1e-15;
    if (arclen_length_gauss(c, dim, &o, &l2, &i2) != ARCLEN_OK) abort();
    if (isfinite(l1) && isfinite(l2) &&
        fabs(l1 - l2) > i1.err + i2.err + 128 * DBL_EPSILON * fabs(l2) + TINY) {
      fprintf(stderr, "rtol %g, range [%g, %g], info.err %.3g and %.3g\n",
              rtol, t0, t1, i1.err, i2.err);
      fz_fail("gauss info.err", c, dim, "%.17g at rtol, %.17g at 1e-15", l1, l2);
    }
  }

  /* The fast and the general path of the default method: one result. */
  {
    arclen_opts o;
    arclen_info info;
    double lf, lg;
    arclen_opts_init(&o);
    o.rtol = rtol > 1e-15 ? rtol : 1e-15;
    o.t0 = t0;
    o.t1 = t1;
    if (arclen_length_gauss(c, dim, &o, &lf, NULL) != ARCLEN_OK) abort();
    if (arclen_length_gauss(c, dim, &o, &lg, &info) != ARCLEN_OK) abort();
    if (memcmp(&lf, &lg, sizeof lf))
      fz_fail("gauss fast path", c, dim, "%a without info, %a with", lf, lg);
    lg = dim == 2 ? arclen_length_range(c, t0, t1, o.rtol)
                  : arclen_length3_range(c, t0, t1, o.rtol);
    if (memcmp(&lf, &lg, sizeof lf))
      fz_fail("gauss plain API", c, dim, "%a by the method, %a plain", lf, lg);
  }

  /* Additivity of the default method on a sub-range. */
  if (t0 < t1) {
    arclen_opts o;
    double l01, l0t, lt1;
    arclen_opts_init(&o);
    o.rtol = rtol > 1e-15 ? rtol : 1e-15;
    o.t0 = t0; o.t1 = 1;
    if (arclen_length_gauss(c, dim, &o, &l01, NULL) != ARCLEN_OK) abort();
    o.t0 = t0; o.t1 = t1;
    if (arclen_length_gauss(c, dim, &o, &l0t, NULL) != ARCLEN_OK) abort();
    o.t0 = t1; o.t1 = 1;
    if (arclen_length_gauss(c, dim, &o, &lt1, NULL) != ARCLEN_OK) abort();
    if (isfinite(l01) &&
        fabs(l0t + lt1 - l01) > (2 * o.rtol + 3 * ULPS) * l01 + TINY)
      fz_fail("gauss additivity", c, dim, "L(t0,t1)+L(t1,1) = %.17g, L(t0,1) = %.17g",
              l0t + lt1, l01);
  }
  return 0;
}
