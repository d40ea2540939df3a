/*
** bench_util.h -- what the benchmarks share: a seeded generator for the
** random curve set (control points uniform in [0, 10]^2), a monotonic
** clock, the median of per-curve times, and the plain 24-point loop.
*/
#ifndef ARCLEN_BENCH_UTIL_H
#define ARCLEN_BENCH_UTIL_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

#include "gauss/gauss_tables.h"

/* xorshift64* (Vigna): a fixed seed gives the same set on every machine. */
static inline double bench_uniform(uint64_t *s) {
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return (double)((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

static inline void bench_random_curves(double *c, int n, uint64_t seed) {
  int i;
  for (i = 0; i < 8 * n; i++) c[i] = 10 * bench_uniform(&seed);
}

static inline double bench_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int bench_cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static inline double bench_median(double *v, int n) {
  qsort(v, n, sizeof *v, bench_cmp);
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* The fixed 24-point Gauss-Legendre rule as a plain loop, one square root
** at a time on the unscaled hodograph of a plane cubic: what a library
** without packed square roots runs, and the unit in which
** doc/benchmarks.md gives the peers' costs. */
static inline double bench_plain24(const double *c) {
  const arclen_gauss_rule *r = &arclen_gauss_rules[23];
  double ax[3], ay[3], s = 0;
  int i;
  ax[0] = 3 * (c[2] - c[0]);
  ay[0] = 3 * (c[3] - c[1]);
  ax[1] = 6 * (c[4] - 2 * c[2] + c[0]);
  ay[1] = 6 * (c[5] - 2 * c[3] + c[1]);
  ax[2] = 3 * (c[6] - 3 * c[4] + 3 * c[2] - c[0]);
  ay[2] = 3 * (c[7] - 3 * c[5] + 3 * c[3] - c[1]);
  for (i = 0; i < r->half; i++) {
    double t0 = 0.5 - 0.5 * r->x[i], t1 = 0.5 + 0.5 * r->x[i];
    double x0 = (ax[2] * t0 + ax[1]) * t0 + ax[0];
    double y0 = (ay[2] * t0 + ay[1]) * t0 + ay[0];
    double x1 = (ax[2] * t1 + ax[1]) * t1 + ax[0];
    double y1 = (ay[2] * t1 + ay[1]) * t1 + ay[0];
    s += r->w[i] * (sqrt(x0 * x0 + y0 * y0) + sqrt(x1 * x1 + y1 * y1));
  }
  return 0.5 * s;
}

#endif
