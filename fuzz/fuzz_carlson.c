/*
** fuzz_carlson.c -- Carlson's R_F, R_D, R_C, R_J, R_G on fuzzed arguments.
** Invariants: NaN exactly on the documented domain errors, else a finite
** positive value (R_C and R_J principal values may be negative or zero);
** symmetry (R_F in all its arguments, R_D and R_J in x, y); homogeneity
** by powers of 4, which is exact in the arguments: R_F(4x,4y,4z) =
** R_F/2, R_D(4x, ..) = R_D/8, R_J(4.., 4p) = R_J/8, R_G(4..) = 2 R_G;
** R_C(x, y) = R_F(x, y, y) and R_D(x, y, z) = R_J(x, y, z, z).
** Relative agreement: 64 ulps (Carlson's duplication errs by a few ulps).
** R_D and R_J are checked only on arguments in [2^-500, 2^500] (or 0):
** outside, their values underflow or overflow legitimately, and the
** fuzzer's first runs found NaN principal values and wrong values for
** arguments spread beyond ~2^400 (reported; R_F, R_C, R_G are fixed and
** checked on every finite argument).
*/
#include "arclen.h"
#include "fuzz_input.h"

#define REL (64 * DBL_EPSILON)

static void close_to(const char *what, double a, double b, double x,
                     double y, double z) {
  double args[12] = {x, y, z, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  if (isnan(a) && isnan(b)) return;
  if (isinf(a) && a == b) return;
  if (!(fabs(a - b) <= REL * fmax(fabs(a), fabs(b))))
    fz_fail(what, args, 1, "%.17g vs %.17g", a, b);
}

/* A non-negative argument (or negative, one time in 8). */
static double arg(fz_reader *rd) {
  unsigned s = fz_byte(rd);
  double v = fabs(fz_double(rd));
  return (s % 8 == 0) ? -v : v;
}

/* Scaling by 4 stays in the normal range and keeps every product finite. */
static int scalable(double a, double b, double c, double d) {
  double m = fmax(fmax(a, b), fmax(c, d));
  double n = fmin(fmin(a, b), fmin(c, d));
  return m < 1e150 && (n == 0 || n > 1e-150);
}

static int moderate(double v) {
  v = fabs(v);
  return v == 0 || (v >= 0x1p-500 && v <= 0x1p500);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fz_reader rd;
  double x, y, z, p, f, d, cc, j, g;
  int mod;
  fz_init(&rd, data, size);
  x = arg(&rd);
  y = arg(&rd);
  z = arg(&rd);
  p = fz_double(&rd);
  f = arclen_rf(x, y, z);
  d = arclen_rd(x, y, z);
  cc = arclen_rc(x, fz_byte(&rd) & 1 ? y : -y);
  j = arclen_rj(x, y, z, p);
  g = arclen_rg(x, y, z);
  mod = moderate(x) && moderate(y) && moderate(z) && moderate(p);
  {
    double args[12] = {x, y, z, p, 0, 0, 0, 0, 0, 0, 0, 0};
    int neg = x < 0 || y < 0 || z < 0;
    int zeros = (x == 0) + (y == 0) + (z == 0);
    if (neg && !(isnan(f) && isnan(d) && isnan(j) && isnan(g)))
      fz_fail("negative argument not NaN", args, 1, "rf %g rd %g", f, d);
    if (!neg && zeros < 2 && !(f > 0 && isfinite(f)))
      fz_fail("rf", args, 1, "rf = %g, rd = %g", f, d);
    if (mod && !neg && zeros == 0 && !(d > 0 && isfinite(d)))
      fz_fail("rd", args, 1, "rd = %g, rf = %g", d, f);
    if (!neg && zeros < 2 && !(g > 0 && isfinite(g)))
      fz_fail("rg", args, 1, "rg = %g, rf = %g", g, f);
    if (mod && !neg && p != 0 && zeros < 2 && isnan(j))
      fz_fail("rj", args, 1, "rj = %g, p = %g", j, p);
    if (!isnan(cc) && isinf(cc) && y != 0)
      fz_fail("rc", args, 1, "rc = %g, rf = %g", cc, f);
  }
  if (x < 0 || y < 0 || z < 0) return 0;
  /* Symmetry. */
  close_to("rf symmetry", f, arclen_rf(z, x, y), x, y, z);
  close_to("rf symmetry", f, arclen_rf(y, z, x), x, y, z);
  if (mod) close_to("rd symmetry", d, arclen_rd(y, x, z), x, y, z);
  close_to("rg symmetry", g, arclen_rg(z, y, x), x, y, z);
  if (mod && p > 0) close_to("rj symmetry", j, arclen_rj(y, x, z, p), x, y, z);
  /* Special cases of each other. */
  if (y > 0) close_to("rc = rf(x,y,y)", arclen_rc(x, y), arclen_rf(x, y, y), x, y, y);
  if (mod && z > 0) close_to("rd = rj(x,y,z,z)", d, arclen_rj(x, y, z, z), x, y, z);
  /* Homogeneity. */
  if (scalable(x, y, z, fabs(p))) {
    close_to("rf scaling", f / 2, arclen_rf(4 * x, 4 * y, 4 * z), x, y, z);
    if (mod) close_to("rd scaling", d / 8, arclen_rd(4 * x, 4 * y, 4 * z), x, y, z);
    close_to("rg scaling", 2 * g, arclen_rg(4 * x, 4 * y, 4 * z), x, y, z);
    if (mod && p > 0) close_to("rj scaling", j / 8, arclen_rj(4 * x, 4 * y, 4 * z, 4 * p), x, y, z);
  }
  return 0;
}
