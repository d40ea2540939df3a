/*
** bench_latency.c -- how long each step of the default method's set-up
** takes when nothing else can run beside it: every call's input waits on
** the previous call's result (a term of ~1e-300 that leaves it unchanged),
** so the times are the steps' dependent chains, not their throughput.  On
** the bench's random curves that take one piece (the median curve's kind),
** the steps the set-up runs one after the other before its first speed
** evaluation -- the hodograph, its branch points, the order from them --
** and the chord beside them; then the whole length and the fixed 24-point
** rule in the same mode.  Mean ns per call, the least of three rounds.
*/
#include <stdio.h>
#include <string.h>

#include "arclen.h"
#include "bench_util.h"
#include "curve/cubic.h"
#include "gauss/bound.h"

#define NCURVES 3000
#define ROUNDS 3
#define REPS 100

static double curves[8 * NCURVES];
static arclen_hodo hodo[NCURVES];
static arclen_branch branch[NCURVES];
static int one[NCURVES], none;
static volatile double sink;

enum { HODO, BRANCH, CHORD, ORDER, LENGTH, GL24, NSTEPS };
static const char *names[NSTEPS] = {
  "hodograph, scaled (shared with GL24)", "branch points", "chord",
  "order from the branch points", "arclen_length, tol 1e-12",
  "fixed 24-point Gauss-Legendre"};

/* One call of step s on curve i, its input offset by dep; returns a value
** of its result for the next call to wait on. */
static double step(int s, int i, double dep) {
  double c[8];
  memcpy(c, curves + 8 * i, sizeof c);
  c[0] += dep;
  switch (s) {
    case HODO: {
      arclen_hodo h;
      arclen_hodo_scaled(c, 2, &h);
      return h.a0[0];
    }
    case BRANCH: {
      arclen_hodo h = hodo[i];
      arclen_branch b;
      h.a0[0] += dep;
      arclen_branch_points(&h, &b);
      return b.re[0];
    }
    case CHORD: {
      arclen_hodo h = hodo[i];
      h.a0[0] += dep;
      return arclen_hodo_chord(&h, 0, 1);
    }
    case ORDER: {
      double mid = 0.5 + dep, half_width = 0.5;
      int n = 0;
      arclen_cut_orders(&branch[i], 1, &mid, &half_width, -40, 128, &n);
      return n;
    }
    case LENGTH: return arclen_length(c, 1e-12);
    default: return arclen_length_gl(c, 2, 24);
  }
}

int main(void) {
  double best[NSTEPS];
  int i, k, r, s;
  bench_random_curves(curves, NCURVES, 20261121);
  for (i = 0; i < NCURVES; i++) {
    arclen_opts o;
    arclen_info info;
    double v;
    arclen_opts_init(&o);
    arclen_length_gauss(curves + 8 * i, 2, &o, &v, &info);
    one[i] = info.pieces == 1;
    none += one[i];
    arclen_hodo_scaled(curves + 8 * i, 2, &hodo[i]);
    arclen_branch_points(&hodo[i], &branch[i]);
  }
  for (s = 0; s < NSTEPS; s++) best[s] = 1e30;
  for (k = 0; k < ROUNDS; k++)
    for (s = 0; s < NSTEPS; s++) {
      double dep = 0, t0 = bench_now(), ns;
      for (r = 0; r < REPS; r++)
        for (i = 0; i < NCURVES; i++)
          if (one[i]) dep = step(s, i, dep) * 1e-300;
      ns = (bench_now() - t0) / ((double)REPS * none) * 1e9;
      if (ns < best[s]) best[s] = ns;
      sink = dep;
    }
  printf("latency, ns per call, %d one-piece curves of 3000 random cubics\n",
         none);
  for (s = 0; s < NSTEPS; s++) printf("  %-40s %7.1f\n", names[s], best[s]);
  return 0;
}
