/*
** bench_length.c -- the default method's speed as ratios to one fixed
** 24-point Gauss-Legendre rule (24 square roots, ~1e-3 accurate: the floor
** any accurate method must beat), measured in the same run on 3000 random
** curves.  Each curve is timed over REPS calls; the median is reported.
** The time calls ask for L/2, computed before the clock starts.
**
** Two yardsticks, both the 24-point rule: a plain loop, one square root at
** a time on the unscaled hodograph -- what a library writes, and the unit
** in which doc/benchmarks.md gives the peers' costs (kurbo 0.13 ~4.5)
** -- and arclen_length_gl(c, 2, 24), whose loop is the default method's own
** (speed_sum.c: two or four square roots per instruction), so that the
** ratio to it is what the error control costs beside the rule.
*/
#include <stdio.h>

#include "arclen.h"
#include "bench_util.h"
#include "gauss/speed_sum.h"

#define NCURVES 3000
#define REPS 64

static double curves[8 * NCURVES];
static double halves[NCURVES];   /* L/2 of each curve, for the time calls */
static volatile double sink;

typedef double (*measure_fn)(const double *c, double arg);

static double gl24(const double *c, double arg) {
  (void)arg;
  return arclen_length_gl(c, 2, 24);
}

static double plain24(const double *c, double arg) {
  (void)arg;
  return bench_plain24(c);
}

static double len(const double *c, double rtol) { return arclen_length(c, rtol); }
static double half_time(const double *c, double rtol) {
  return arclen_time(c, halves[(c - curves) / 8], rtol);
}

#define NMEASURES 6
#define BLOCK 50        /* curves timed by one measure before the next */

/* Per-curve ns of every measure, the measures taken in turn on each block
** of curves: all of them then see the machine in the same state (its speed
** drifts over seconds: a shared core, frequency steps), and each curve is
** timed after another curve's calls to the same function, as when one
** measure runs over all curves.  Then the median of each, and the mean in
** mean[] (the per-curve times are bimodal, one piece or two, and the median
** sits near the edge). */
static void median_ns(const measure_fn f[NMEASURES],
                      const double arg[NMEASURES], double med[NMEASURES],
                      double mean[NMEASURES]) {
  static double times[NMEASURES][NCURVES];
  int b, i, m, r;
  for (m = 0; m < NMEASURES; m++) mean[m] = 0;
  for (b = 0; b < NCURVES; b += BLOCK)
    for (m = 0; m < NMEASURES; m++)
      for (i = b; i < b + BLOCK && i < NCURVES; i++) {
        const double *c = curves + 8 * i;
        double t0 = bench_now();
        for (r = 0; r < REPS; r++) sink = f[m](c, arg[m]);
        times[m][i] = (bench_now() - t0) / REPS * 1e9;
        mean[m] += times[m][i] / NCURVES;
      }
  for (m = 0; m < NMEASURES; m++) med[m] = bench_median(times[m], NCURVES);
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

/* One line: measure m's median ns, its ratios to the plain loop (5) and to
** GL24 (0), the median evaluations, and the ratio of the means. */
static void row(const char *what, int m, long evals, const double *med,
                const double *mean) {
  printf("%-36s %7.1f %7.2f %7.2f %6ld %12.2f\n", what, med[m],
         med[m] / med[5], med[m] / med[0], evals, mean[m] / mean[5]);
}

int main(void) {
  static const measure_fn f[NMEASURES] = {gl24, len, len, half_time,
                                          half_time, plain24};
  static const double arg[NMEASURES] = {0, 1e-12, 1e-15, 1e-12, 1e-15, 0};
  double med[NMEASURES], mean[NMEASURES];
  int i;
  bench_random_curves(curves, NCURVES, 20261121);
  for (i = 0; i < NCURVES; i++)        /* outside the clock: time alone */
    halves[i] = 0.5 * arclen_length(curves + 8 * i, 1e-12);
  median_ns(f, arg, med, mean);
  printf("3000 random cubics in [0,10]^2, median ns per curve (%d calls "
         "each); the rules' kernel here: %s\n", REPS, arclen_speed_kernel());
  printf("%-36s %7s %7s %7s %6s %12s\n", "what", "ns", "/plain", "/GL24",
         "evals", "mean /plain");
  row("plain 24-point loop, scalar", 5, 24, med, mean);
  row("fixed 24-point rule (GL24)", 0, 24, med, mean);
  row("arclen_length rtol 1e-12", 1, median_evals(1e-12, 0), med, mean);
  row("arclen_length rtol 1e-15", 2, median_evals(1e-15, 0), med, mean);
  row("arclen_time L/2 rtol 1e-12", 3, median_evals(1e-12, 1), med, mean);
  row("arclen_time L/2 rtol 1e-15", 4, median_evals(1e-15, 1), med, mean);
  printf("time / length at 1e-12: %.2f   at 1e-15: %.2f\n", med[3] / med[1],
         med[4] / med[2]);
  return 0;
}
