/*
** bench_methods.c -- every length method of methods.c on the bench's
** random curves: median ns per curve and its ratio to the plain 24-point
** loop and to GL24 (bench_length.c says why two), for README's table of
** methods.  The slow methods run on fewer curves (the first ones of the
** same set), once each; the others over REPS calls.
*/
#include <stdio.h>
#include <string.h>

#include "arclen.h"
#include "bench_util.h"

#define NCURVES 3000
#define REPS 64

static double curves[8 * NCURVES];
static double times[NCURVES];
static volatile double sink;

/* Curves and calls per curve for a method: the fixed-step baselines take
** 10^6 steps, Gravesen's subdivision thousands of pieces. */
static void workload(const char *name, int *n, int *reps) {
  *n = NCURVES;
  *reps = REPS;
  if (!strcmp(name, "gravesen") || !strcmp(name, "gravesen-richardson")) {
    *n = 300;
    *reps = 1;
  } else if (!strcmp(name, "polyline") || !strncmp(name, "trapezoid", 9)) {
    *n = 30;
    *reps = 1;
  }
}

static double median_ns(const arclen_method *m, int n, int reps) {
  int i, r;
  for (i = 0; i < n; i++) {
    arclen_opts o;
    double t0, v;
    arclen_opts_init(&o);
    t0 = bench_now();
    for (r = 0; r < reps; r++) {
      m->length(curves + 8 * i, 2, &o, &v, NULL);
      sink = v;
    }
    times[i] = (bench_now() - t0) / reps * 1e9;
  }
  return bench_median(times, n);
}

static double median_rule(int plain) {
  int i, r;
  for (i = 0; i < NCURVES; i++) {
    const double *c = curves + 8 * i;
    double t0 = bench_now();
    for (r = 0; r < 64; r++)
      sink = plain ? bench_plain24(c) : arclen_length_gl(c, 2, 24);
    times[i] = (bench_now() - t0) / 64 * 1e9;
  }
  return bench_median(times, NCURVES);
}

int main(void) {
  const arclen_method *m;
  double plain, gl24;
  bench_random_curves(curves, NCURVES, 20261121);
  plain = median_rule(1);
  gl24 = median_rule(0);
  printf("median ns per random cubic, tol 1e-12 (default options)\n");
  printf("%-22s %7s %11s %10s %9s\n", "method", "curves", "ns", "/plain", "/GL24");
  printf("%-22s %7d %11.1f %10.2f %9.2f\n", "plain 24-point loop", NCURVES,
         plain, 1.0, plain / gl24);
  printf("%-22s %7d %11.1f %10.2f %9.2f\n", "GL24", NCURVES, gl24,
         gl24 / plain, 1.0);
  for (m = arclen_method_list(); m->name; m++) {
    int n, reps;
    double ns;
    workload(m->name, &n, &reps);
    ns = median_ns(m, n, reps);
    printf("%-22s %7d %11.1f %10.1f %9.1f\n", m->name, n, ns, ns / plain,
           ns / gl24);
  }
  return 0;
}
