/*
** bench_util.h -- what the benchmarks share: a seeded generator for the
** random curve set (control points uniform in [0, 10]^2), a monotonic
** clock, and the median of per-curve times.
*/
#ifndef ARCLEN_BENCH_UTIL_H
#define ARCLEN_BENCH_UTIL_H

#include <stdint.h>
#include <stdlib.h>
#include <time.h>

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

#endif
