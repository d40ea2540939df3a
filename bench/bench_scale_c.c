/*
** bench_scale_c.c -- the C loop that make bench-scale holds arclen.lengths
** to: arclen_length over the same N curves as bench/bench_scale.lua (its
** Park-Miller generator, seed 20261121, coordinates 10 u in [0, 10)), from
** one flat array, one arclen_length call per curve (the call that
** arclen.lengths makes for the default method).  Prints ns per curve, the
** least of RUNS passes (second argument, 3 by default; bench_scale.lua
** asks for 1, to pair one pass with one arclen.lengths call), in CPU time
** as the Lua script's os.clock: on a shared machine wall time counts the
** other processes' turns.
*/
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "arclen.h"

static double cpu_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv) {
  long n = argc > 1 ? atol(argv[1]) : 1000000, i;
  int runs = argc > 2 ? atoi(argv[2]) : 3;
  double *c = malloc(sizeof *c * 8 * (size_t)n), best = 1e300, sum = 0;
  long long seed = 20261121 % 2147483647;
  int r;
  if (!c) return 1;
  for (i = 0; i < 8 * n; i++) {
    seed = (seed * 48271) % 2147483647;
    c[i] = 10 * ((double)seed / 2147483647);
  }
  for (r = 0; r < runs; r++) {
    double t0 = cpu_now(), t;
    sum = 0;
    for (i = 0; i < n; i++) sum += arclen_length(c + 8 * i, 1e-12);
    t = cpu_now() - t0;
    if (t < best) best = t;
  }
  printf("C loop, arclen_length over the same curves %9.0f ns/curve (sum %.10g)\n",
         best / (double)n * 1e9, sum);
  free(c);
  return 0;
}
