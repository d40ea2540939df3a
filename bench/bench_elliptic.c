/*
** bench_elliptic.c -- time per curve of method "elliptic" next to the
** default method ("gauss", rtol 1e-12 and 1e-15) and the fixed 24-point
** Gauss rule (the speed floor), on 3000 random curves in [0, 10]^2 (fixed
** seed); and the time per call of each Carlson R-function.  Ratios within
** one run are what counts (a shared 2-core machine is noisy): the ratio to
** the plain 24-point loop is also taken curve by curve, each curve's loop
** and method timed back to back, medians over the set, three passes (load
** that comes and goes then hits both sides alike).
*/
#include <math.h>
#include <stdio.h>

#include "arclen.h"
#include "bench_util.h"
#include "elliptic/elliptic.h"

#define NCURVES 3000
#define REPS 20
#define NARGS 4096

static double sink;   /* keeps the optimiser from dropping the work */

static double time_method(arclen_length_fn fn, const double *c, double rtol) {
  arclen_opts o;
  double t0, len;
  int r, i;
  arclen_opts_init(&o);
  o.rtol = rtol;
  t0 = bench_now();
  for (r = 0; r < REPS; r++)
    for (i = 0; i < NCURVES; i++) {
      fn(c + 8 * i, 2, &o, &len, NULL);
      sink += len;
    }
  return (bench_now() - t0) / (REPS * NCURVES) * 1e9;
}

static double time_gl24(const double *c) {
  double t0 = bench_now();
  int r, i;
  for (r = 0; r < REPS; r++)
    for (i = 0; i < NCURVES; i++) sink += arclen_length_gl(c + 8 * i, 2, 24);
  return (bench_now() - t0) / (REPS * NCURVES) * 1e9;
}

/* Median over the curves of (method's ns, plain loop's ns), each curve's
** pair timed back to back; prints the two medians and their ratio. */
static void interleaved(const double *c) {
  static double tp[NCURVES], te[NCURVES];
  arclen_opts o;
  int i, r;
  arclen_opts_init(&o);
  for (i = 0; i < NCURVES; i++) {
    double t0 = bench_now(), len;
    for (r = 0; r < 64; r++) sink += bench_plain24(c + 8 * i);
    tp[i] = (bench_now() - t0) / 64 * 1e9;
    t0 = bench_now();
    for (r = 0; r < 16; r++) {
      arclen_length_elliptic(c + 8 * i, 2, &o, &len, NULL);
      sink += len;
    }
    te[i] = (bench_now() - t0) / 16 * 1e9;
  }
  {
    double p = bench_median(tp, NCURVES), e = bench_median(te, NCURVES);
    printf("  interleaved: plain loop %6.1f ns, elliptic %7.1f ns: %5.2f plain loops\n",
           p, e, e / p);
  }
}

/* Log-uniform arguments in [1e-3, 1e3]: the range the length formula meets. */
static void random_args(double *v, int n, uint64_t seed) {
  int i;
  for (i = 0; i < n; i++) v[i] = pow(10, 6 * bench_uniform(&seed) - 3);
}

int main(void) {
  static double c[8 * NCURVES], v[NARGS + 3];
  double gl, t0, ns;
  int r, i;
  arclen_info info;
  arclen_opts o;
  long calls = 0;
  bench_random_curves(c, NCURVES, 20261121);
  random_args(v, NARGS + 3, 1995);

  gl = time_gl24(c);
  printf("per curve (mean over %d curves x %d reps)\n",
         NCURVES, REPS);
  printf("  %-24s %9.1f ns   1.0x\n", "gl24 (fixed, ~1e-3)", gl);
  ns = time_method(arclen_length_gauss, c, 1e-12);
  printf("  %-24s %9.1f ns  %5.1fx\n", "gauss rtol 1e-12", ns, ns / gl);
  ns = time_method(arclen_length_gauss, c, 1e-15);
  printf("  %-24s %9.1f ns  %5.1fx\n", "gauss rtol 1e-15", ns, ns / gl);
  ns = time_method(arclen_length_elliptic, c, 1e-12);
  printf("  %-24s %9.1f ns  %5.1fx\n", "elliptic (exact)", ns, ns / gl);
  arclen_opts_init(&o);
  for (i = 0; i < NCURVES; i++) {
    double len;
    arclen_length_elliptic(c + 8 * i, 2, &o, &len, &info);
    calls += info.calls;
  }
  printf("  elliptic: %.2f R-function calls per curve\n",
         (double)calls / NCURVES);
  for (r = 0; r < 3; r++) interleaved(c);

  printf("per R-function call (arguments log-uniform in [1e-3, 1e3])\n");
#define TIME_R(name, expr)                                              \
  t0 = bench_now();                                                     \
  for (r = 0; r < REPS * 20; r++)                                       \
    for (i = 0; i < NARGS; i++) sink += (expr);                         \
  printf("  %-4s %7.1f ns\n", name,                                     \
         (bench_now() - t0) / (REPS * 20.0 * NARGS) * 1e9);
  TIME_R("rf", arclen_rf(v[i], v[i + 1], v[i + 2]))
  TIME_R("rd", arclen_rd(v[i], v[i + 1], v[i + 2]))
  TIME_R("rc", arclen_rc(v[i], v[i + 1]))
  TIME_R("rj", arclen_rj(v[i], v[i + 1], v[i + 2], v[i + 3]))
  TIME_R("rg", arclen_rg(v[i], v[i + 1], v[i + 2]))
  /* R_F, R_D, R_J of one x, y, z: three duplications, or one (rfdj) */
  TIME_R("f+d+j", arclen_rf(v[i], v[i + 1], v[i + 2])
                  + arclen_rd(v[i], v[i + 1], v[i + 2])
                  + arclen_rj(v[i], v[i + 1], v[i + 2], v[i + 3]))
  {
    double f, d, j;
    TIME_R("rfdj", (arclen_rfdj(v[i], v[i + 1], v[i + 2], v[i + 3], &f, &d, &j),
                    f + d + j))
  }
  if (sink == 42) printf("\n");
  return 0;
}
