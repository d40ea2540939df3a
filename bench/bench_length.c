/*
** bench_length.c -- the default method's speed as ratios to one fixed
** 24-point Gauss-Legendre rule (24 square roots, ~1e-3 accurate: the floor
** any accurate method must beat), measured in the same run on 3000 random
** curves.  Each curve is timed over REPS calls; the median is reported.
** The time calls ask for L/2, computed before the clock starts.
*/
#include <stdio.h>

#include "arclen.h"
#include "bench_util.h"

#define NCURVES 3000
#define REPS 64

static double curves[8 * NCURVES];
static double halves[NCURVES];   /* L/2 of each curve, for the time calls */
static double times[NCURVES];
static volatile double sink;

typedef double (*measure_fn)(const double *c, double arg);

static double gl24(const double *c, double arg) {
  (void)arg;
  return arclen_length_gl(c, 2, 24);
}
static double len(const double *c, double rtol) { return arclen_length(c, rtol); }
static double half_time(const double *c, double rtol) {
  return arclen_time(c, halves[(c - curves) / 8], rtol);
}

/* The median ns per curve; *mean gets the mean (the per-curve times are
** bimodal, one piece or two, and the median sits near the edge). */
static double median_ns(measure_fn f, double arg, double *mean) {
  int i, r;
  double sum = 0;
  for (i = 0; i < NCURVES; i++) {
    const double *c = curves + 8 * i;
    double t0 = bench_now();
    for (r = 0; r < REPS; r++) sink = f(c, arg);
    times[i] = (bench_now() - t0) / REPS * 1e9;
    sum += times[i];
  }
  *mean = sum / NCURVES;
  return bench_median(times, NCURVES);
}

static long median_evals(double rtol, int want_time) {
  static double ev[NCURVES];
  int i;
  for (i = 0; i < NCURVES; i++) {
    arclen_opts o;
    arclen_info info;
    double v;
    arclen_opts_init(&o);
    o.rtol = rtol;
    if (want_time) {
      double L;
      arclen_length_gauss(curves + 8 * i, 2, &o, &L, NULL);
      arclen_time_gauss(curves + 8 * i, 2, L / 2, &o, &v, &info);
    } else {
      arclen_length_gauss(curves + 8 * i, 2, &o, &v, &info);
    }
    ev[i] = (double)info.evals;
  }
  return (long)bench_median(ev, NCURVES);
}

int main(void) {
  double base, l12, l15, t12, t15, mb, m12, m15, mt12, mt15;
  int i;
  bench_random_curves(curves, NCURVES, 20261121);
  for (i = 0; i < NCURVES; i++)        /* outside the clock: time alone */
    halves[i] = 0.5 * arclen_length(curves + 8 * i, 1e-12);
  base = median_ns(gl24, 0, &mb);
  l12 = median_ns(len, 1e-12, &m12);
  l15 = median_ns(len, 1e-15, &m15);
  t12 = median_ns(half_time, 1e-12, &mt12);
  t15 = median_ns(half_time, 1e-15, &mt15);
  printf("3000 random cubics in [0,10]^2, median ns per curve (%d calls each)\n", REPS);
  printf("%-34s %9s %8s %7s %11s\n", "what", "ns", "ratio", "evals", "mean ratio");
  printf("%-34s %9.1f %8.2f %7d %11.2f\n", "fixed 24-point Gauss-Legendre", base, 1.0, 24, 1.0);
  printf("%-34s %9.1f %8.2f %7ld %11.2f\n", "arclen_length rtol 1e-12", l12, l12 / base, median_evals(1e-12, 0), m12 / mb);
  printf("%-34s %9.1f %8.2f %7ld %11.2f\n", "arclen_length rtol 1e-15", l15, l15 / base, median_evals(1e-15, 0), m15 / mb);
  printf("%-34s %9.1f %8.2f %7ld %11.2f\n", "arclen_time L/2 rtol 1e-12", t12, t12 / base, median_evals(1e-12, 1), mt12 / mb);
  printf("%-34s %9.1f %8.2f %7ld %11.2f\n", "arclen_time L/2 rtol 1e-15", t15, t15 / base, median_evals(1e-15, 1), mt15 / mb);
  printf("time / length at 1e-12: %.2f   at 1e-15: %.2f\n", t12 / l12, t15 / l15);
  return 0;
}
