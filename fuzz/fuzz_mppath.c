/*
** fuzz_mppath.c -- MetaPost's path arclength and arctime (metapost.c) on
** fuzzed paths of 1..8 segments, open or cyclic.  Invariants: 0 or the
** overflow mpost reports; a finite length >= 0; arctime of a goal in
** [0, length] is a time in [0, n] (n segments); arctime of the length is
** n on an open path; negative goals give 0 on an open path.
*/
#include "arclen.h"
#include "fuzz_input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fz_reader rd;
  double seg[8 * 8], len, t, goal;
  int n, cyclic, i, rc;
  fz_init(&rd, data, size);
  n = (int)fz_range(&rd, 1, 8);
  cyclic = fz_byte(&rd) & 1;
  seg[0] = fz_double(&rd);
  seg[1] = fz_double(&rd);
  for (i = 0; i < n; i++) {
    int k;
    if (i > 0) { seg[8 * i] = seg[8 * i - 2]; seg[8 * i + 1] = seg[8 * i - 1]; }
    for (k = 2; k < 8; k++) seg[8 * i + k] = fz_double(&rd);
  }
  if (cyclic) { seg[8 * n - 2] = seg[0]; seg[8 * n - 1] = seg[1]; }
  goal = (double)fz_bits(&rd, 2) / 65535.0 * 1.2 - 0.1;
  rc = arclen_mp_path_arclength(seg, n, cyclic, &len, NULL);
  if (rc == ARCLEN_EOVERFLOW) return 0;
  if (rc != ARCLEN_OK) fz_fail("mp_path_arclength", seg, 2, "code %g, n %g", rc, n);
  if (!(len >= 0) || !isfinite(len))
    fz_fail("mp_path_arclength", seg, 2, "length %g, n %g", len, n);
  goal *= len;
  rc = arclen_mp_path_arctime(seg, n, cyclic, goal, &t, NULL);
  if (rc == ARCLEN_EOVERFLOW) return 0;
  if (rc != ARCLEN_OK) fz_fail("mp_path_arctime", seg, 2, "code %g, goal %g", rc, goal);
  if (!isfinite(t)) fz_fail("mp_path_arctime", seg, 2, "time %g, goal %g", t, goal);
  if (!cyclic) {
    if (goal < 0 && t != 0) fz_fail("mp_path_arctime", seg, 2, "time %g for goal %g < 0", t, goal);
    if (goal >= 0 && !(t >= 0 && t <= n))
      fz_fail("mp_path_arctime", seg, 2, "time %g outside [0, n], goal %g", t, goal);
    if (goal >= len && t != n)
      fz_fail("mp_path_arctime", seg, 2, "time %g for goal >= length %g", t, len);
  } else if (goal >= 0 && goal <= len && !(t >= 0 && t <= n)) {
    fz_fail("mp_path_arctime cyclic", seg, 2, "time %g, goal %g", t, goal);
  }
  return 0;
}
