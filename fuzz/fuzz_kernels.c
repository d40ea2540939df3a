/*
** fuzz_kernels.c -- the kernels of speed_sum.c on fuzzed cubics, rules
** and pieces.  Invariant: every kernel (scalar, SSE2, AVX and AVX-512,
** those the machine lacks falling back) gives the same sum to the bit, so
** that no result depends on the machine.
*/
#include "fuzz_input.h"
#include "gauss/gauss_tables.h"
#include "gauss/speed_sum.h"

static int same(double a, double b) {
  return memcmp(&a, &b, sizeof a) == 0 || (a != a && b != b);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const int kernels[4] = {ARCLEN_KERNEL_SCALAR, ARCLEN_KERNEL_SSE2,
                                 ARCLEN_KERNEL_AVX, ARCLEN_KERNEL_AVX512};
  fz_reader rd;
  double c[12], mid, half_width, s[4];
  const arclen_gauss_rule *r;
  arclen_hodo h;
  int dim, i0, k;
  fz_init(&rd, data, size);
  dim = (fz_byte(&rd) & 1) ? 3 : 2;
  r = &arclen_gauss_rules[fz_range(&rd, 1, ARCLEN_GAUSS_MAX) - 1];
  i0 = (int)fz_range(&rd, 0, r->half);
  half_width = ldexp((double)fz_range(&rd, 1, 65535) / 65536.0, -(int)fz_range(&rd, 0, 60));
  mid = (double)fz_bits(&rd, 2) / 65535.0 * 2 - 1;
  fz_curve(&rd, dim, c);
  arclen_hodo_scaled(c, dim, &h);
  if (h.zero) return 0;
  for (k = 0; k < 4; k++)
    s[k] = arclen_speed_pairs_by(kernels[k], &h, r->x, r->w, i0, r->half,
                                 mid, half_width, 0.25);
  for (k = 1; k < 4; k++)
    if (!same(s[0], s[k]))
      fz_fail("kernels", c, dim, "scalar %.17g, kernel %g", s[0], k);
  return 0;
}
