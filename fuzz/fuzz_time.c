/*
** fuzz_time.c -- the inverse (time) methods of methods.c on fuzzed cubics
** and goals.  Invariants: t in [0, 1]; s <= 0 gives 0, s >= L gives 1;
** for "gauss", |s(t) - s| <= rtol L (s(t) measured by gauss at 1e-14 plus
** the rounding allowance); for "metapost", t is finite in [0, 1] and its
** arclength reproduces the goal within MetaPost's absolute tolerance.
** "gauss" gives the same t to the bit with and without the report (the
** first pieces' orders from the branch points, or the cut records), and
** through the plain API.
*/
#include "arclen.h"
#include "fuzz_input.h"

#define ULPS (32 * DBL_EPSILON)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fz_reader rd;
  double c[12], rtol, frac, L, s, t;
  int dim, rc;
  arclen_opts o;
  const arclen_method *m;
  fz_init(&rd, data, size);
  dim = (fz_byte(&rd) & 1) ? 3 : 2;
  rtol = ldexp(1.0, -(int)fz_range(&rd, 4, 49));
  frac = (double)fz_bits(&rd, 2) / 65535.0 * 1.25 - 0.125;  /* beyond both ends */
  fz_curve(&rd, dim, c);
  arclen_opts_init(&o);
  o.rtol = 1e-14;
  if (arclen_length_gauss(c, dim, &o, &L, NULL) != ARCLEN_OK)
    fz_fail("gauss length", c, dim, "failed %g %g", 0, 0);
  if (!isfinite(L)) return 0;       /* the length itself overflows */
  s = frac * L;
  for (m = arclen_method_list(); m->name; m++) {
    if (!m->time) continue;
    arclen_opts_init(&o);
    o.rtol = rtol;
    rc = m->time(c, dim, s, &o, &t, NULL);
    if (rc == ARCLEN_EDIM) continue;
    if (rc == ARCLEN_EOVERFLOW && !strcmp(m->name, "metapost")) continue;
    if (rc != ARCLEN_OK) fz_fail(m->name, c, dim, "time: code %g, s %g", rc, s);
    if (!(t >= 0 && t <= 1)) fz_fail(m->name, c, dim, "time %g for s %g", t, s);
    if (s <= 0 && t != 0) fz_fail(m->name, c, dim, "time %g for s %g <= 0", t, s);
    if (!strcmp(m->name, "gauss")) {
      double st, tg;
      arclen_info info;
      if (m->time(c, dim, s, &o, &tg, &info) != ARCLEN_OK || memcmp(&t, &tg, sizeof t))
        fz_fail("gauss time with info", c, dim, "%a without info, %a with", t, tg);
      tg = dim == 2 ? arclen_time(c, s, rtol) : arclen_time3(c, s, rtol);
      if (rtol >= ARCLEN_RTOL_MIN && memcmp(&t, &tg, sizeof t))
        fz_fail("gauss plain time", c, dim, "%a by the method, %a plain", t, tg);
      if (s >= L && t != 1 && s > L * (1 + rtol))
        fz_fail(m->name, c, dim, "time %g for s %g >= L", t, s);
      if (s > 0 && s < L) {
        arclen_opts_init(&o);
        o.rtol = 1e-14;
        o.t1 = t;
        arclen_length_gauss(c, dim, &o, &st, NULL);
        if (fabs(st - s) > (rtol + 1e-14 + 2 * ULPS) * L + 0x1p-1000)
          fz_fail(m->name, c, dim, "s(t) = %.17g, goal %.17g", st, s);
      }
    } else if (!strcmp(m->name, "metapost") && s > 0) {
      double lt, lmp, sub[8];
      if (arclen_mp_arclength(c, &lmp, NULL) != ARCLEN_OK) continue;
      if (s >= lmp) {
        if (t != 1) fz_fail(m->name, c, dim, "time %g for s >= arclength %g", t, lmp);
        continue;
      }
      /* MetaPost's arctime inverts its own arclength: the arclength of the
      ** part before t is the goal within the absolute tolerance (1/4096
      ** per leaf, + 2^-17 bias) -- checked loosely, relative 2% + 2^-8. */
      arclen_subcurve(c, 2, 0, t, sub);
      if (arclen_mp_arclength(sub, &lt, NULL) != ARCLEN_OK) continue;
      {
        /* the check's own subcurve errs by ~eps |P| (curves at 1e18) */
        double big = 0;
        int i;
        for (i = 0; i < 8; i++) big = fmax(big, fabs(c[i]));
        if (fabs(lt - s) > 0.02 * lmp + 0x1p-8 + 1024 * DBL_EPSILON * big)
          fz_fail(m->name, c, dim, "arclength(0..t) = %.17g, goal %.17g", lt, s);
      }
    }
  }
  return 0;
}
