/*
** fuzz_carlson.c -- Carlson's R_F, R_D, R_C, R_J, R_G on fuzzed arguments.
** Invariants: NaN exactly on the documented domain errors, else a finite
** positive value (R_C and R_J principal values may be negative or zero);
** symmetry (R_F in all its arguments, R_D and R_J in x, y); homogeneity
** by powers of 4, which is exact in the arguments: R_F(4x,4y,4z) =
** R_F/2, R_D(4x, ..) = R_D/8, R_J(4.., 4p) = R_J/8, R_G(4..) = 2 R_G;
** R_C(x, y) = R_F(x, y, y) and R_D(x, y, z) = R_J(x, y, z, z).
** Relative agreement: 64 ulps (Carlson's duplication errs by a few ulps).
** R_D and R_J symmetry and finiteness are checked only on arguments in
** [2^-500, 2^500] (or 0): outside, their values underflow or overflow
** legitimately.  Over the whole double range (subnormals included) the
** exact homogeneity R(4^k v) = 2^-k R, 8^-k R (R_D, R_J), 2^k R (R_G) is
** checked with k up to +-600 wherever the scaling is exact on the
** arguments and both values are normal doubles: R_D lost 7e-10 at
** (2.5e-237, 4e231, 1e-232) and gave inf for (2.5, 4e200, 1e-300); and
** the mean bounds of R_F and R_D and the sum of R_D over the cyclic
** orders, DLMF 19.21.7, which sees what every scaling repeats.
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

/* v scaled by 4^k, or -1 when that is not exact (underflow, overflow). */
static double scaled(double v, int k) {
  double w = ldexp(v, 2 * k);
  return ldexp(w, -2 * k) == v && isfinite(w) ? w : -1;
}

static int normal(double v) {
  return isnormal(v) && isfinite(v);
}

/* f = R(v), fs = R(4^k v) for R homogeneous of degree -e/(2k) (e = k for
** R_F, R_C; 3k for R_D, R_J; -k for R_G): R(v) = 2^e R(4^k v).  Checked
** when fs and its rescaling are normal (f must then equal it), or f and
** its rescaling are (fs must). */
static void homogeneous(const char *what, double f, double fs, int e,
                        const double *a) {
  double r = ldexp(fs, e), t = ldexp(f, -e);
  double args[12] = {a[0], a[1], a[2], a[3], a[4], e, 0, 0, 0, 0, 0, 0};
  if ((normal(fs) && normal(r) && !(fabs(f - r) <= REL * fabs(r)))
      || (normal(f) && normal(t) && !(fabs(fs - t) <= REL * fabs(t))))
    fz_fail(what, args, 1, "R = %.17g, 2^e R(4^k v) = %.17g", f, r);
}

/* Homogeneity over the whole range, k from the input in [-600, 600]. */
static void check_scaling(fz_reader *rd, double x, double y, double z,
                          double p, double f, double d, double j, double g) {
  int k = (int)fz_range(rd, -600, 600);
  double xs = scaled(x, k), ys = scaled(y, k), zs = scaled(z, k);
  double ps = scaled(fabs(p), k);
  double a[5] = {x, y, z, p, k};
  if (xs < 0 || ys < 0 || zs < 0) return;
  homogeneous("rf homogeneity", f, arclen_rf(xs, ys, zs), k, a);
  homogeneous("rd homogeneity", d, arclen_rd(xs, ys, zs), 3 * k, a);
  homogeneous("rg homogeneity", g, arclen_rg(xs, ys, zs), -k, a);
  if (ys > 0) {
    homogeneous("rc homogeneity", arclen_rc(x, y), arclen_rc(xs, ys), k, a);
    homogeneous("rc pv homogeneity", arclen_rc(x, -y), arclen_rc(xs, -ys), k, a);
  }
  if (ps > 0 && p > 0)
    homogeneous("rj homogeneity", j, arclen_rj(xs, ys, zs, ps), 3 * k, a);
}

/* Bounds from the integrands (DLMF 19.16.1, 19.16.5): with weights w_i
** summing to 1, t + G <= prod (t + v_i)^w_i <= t + A (the geometric mean
** is superadditive; AM-GM), so A^-1/2 <= R_F <= G^-1/2 with A, G the
** means of x, y, z, and A^-3/2 <= R_D <= G^-3/2 with the weights 1/5, 1/5,
** 3/5 (DLMF 19.24 has the general form).  Logarithms keep G in range;
** exp(u) errs by ~|u| ulps through the rounding of u: slack 8 (1 + |u|)
** ulps (1.07e308 thrice: u = -354.9, hi was 6e-14 low). */
static void check_bounds(double x, double y, double z, double f, double d) {
  double args[12] = {x, y, z, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  double slack, lo, hi, u, s;
  if (!(x > 0 && y > 0 && z > 0)) return;
  /* the sum of subnormals is exact where x / 3 is not (5e-324 thrice) */
  s = x + y + z;
  lo = s < HUGE_VAL ? sqrt(3.0) / sqrt(s) : 1 / sqrt(x / 3 + y / 3 + z / 3);
  u = -(log(x) + log(y) + log(z)) / 6;
  hi = exp(u);
  slack = 8 * DBL_EPSILON * (1 + fabs(u));
  if (normal(lo) && normal(hi) && !(f >= lo * (1 - slack) && f <= hi * (1 + slack))) {
    args[3] = hi;
    fz_fail("rf bounds", args, 1, "%.17g not >= %.17g (<= args[3])", f, lo);
  }
  s = x + y + 3 * z;
  if (!(s < HUGE_VAL)) s = 5 * (x / 5 + y / 5 + 3 * (z / 5));
  lo = sqrt(5.0) / sqrt(s) * (5 / s);
  u = -0.3 * (log(x) + log(y) + 3 * log(z));
  hi = exp(u);
  slack = 8 * DBL_EPSILON * (1 + fabs(u));
  if (normal(lo) && normal(hi) && !(d >= lo * (1 - slack) && d <= hi * (1 + slack))) {
    args[3] = hi;
    fz_fail("rd bounds", args, 1, "%.17g not >= %.17g (<= args[3])", d, lo);
  }
}

/* DLMF 19.21.7: R_D(x,y,z) + R_D(y,z,x) + R_D(z,x,y) = 3 / sqrt(xyz), an
** identity between different argument orders (homogeneity cannot see an
** error that every scaling repeats: rd(2.5e-237, 4e231, 1e-232) was 7e-10
** off at every power of 4).  The right side from mantissas and exponents,
** as sqrt(x) sqrt(y) sqrt(z) may leave the double range. */
static void check_rd_sum(double x, double y, double z, double d) {
  double args[12] = {x, y, z, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  double m = 1, rhs, sum;
  int i, e, et = 0;
  const double v[3] = {x, y, z};
  if (!(x > 0 && y > 0 && z > 0)) return;
  for (i = 0; i < 3; i++) {
    m *= frexp(sqrt(v[i]), &e);
    et += e;
  }
  rhs = ldexp(3 / m, -et);
  if (!normal(rhs)) return;
  sum = d + arclen_rd(y, z, x) + arclen_rd(z, x, y);
  if (!(fabs(sum - rhs) <= REL * rhs))
    fz_fail("rd sum (DLMF 19.21.7)", args, 1, "%.17g vs %.17g", sum, rhs);
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
  check_bounds(x, y, z, f, d);
  check_rd_sum(x, y, z, d);
  check_scaling(&rd, x, y, z, p, f, d, j, g);
  if (scalable(x, y, z, fabs(p))) {
    close_to("rf scaling", f / 2, arclen_rf(4 * x, 4 * y, 4 * z), x, y, z);
    if (mod) close_to("rd scaling", d / 8, arclen_rd(4 * x, 4 * y, 4 * z), x, y, z);
    close_to("rg scaling", 2 * g, arclen_rg(4 * x, 4 * y, 4 * z), x, y, z);
    if (mod && p > 0) close_to("rj scaling", j / 8, arclen_rj(4 * x, 4 * y, 4 * z, 4 * p), x, y, z);
  }
  return 0;
}
