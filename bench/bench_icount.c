/*
** bench_icount.c -- one measure of bench_length over its 3000 random
** curves, for callgrind (bench/icount.sh): instructions are counted only
** inside measured(), so set-up outside it (the pieces of each curve, found
** with info) costs nothing.  Instruction counts do not drift with the
** machine's state as times do, and they tell where a method's time goes
** when its code is bound by how many instructions issue, not by latency.
**
**   bench_icount gl24 | one | multi | all | all15 | time | time15 | times10
**                | segcubic | quad | quadtime | quadtime15
**
** gl24: the fixed 24-point rule on every curve; one, multi: the default
** method at tol 1e-12 on the curves it integrates in one piece, in more;
** all, all15: on every curve at tol 1e-12, 1e-15; time, time15:
** arclen_time at L/2 (as bench_length asks) at tol 1e-12, 1e-15; times10:
** arclen_times on 10 distances (j + 1/2) L/10 at tol 1e-12, counted as 10
** calls (a path's walk hands a cubic about that many at k = 10 n);
** segcubic, quad: arclen_segment_length (tol 1e-12) of the cubic and of
** the quadratic on its first three points, as bench_segment times them
** (issue 31's goal: a quadratic's length 5x cheaper than a cubic's);
** quadtime, quadtime15: arclen_segment_time of that quadratic at L/2, tol
** 1e-12, 1e-15 (the goal: at most 2 of its length).
** Prints the number of calls measured.
*/
#include <stdio.h>
#include <string.h>

#include "arclen.h"
#include "bench_util.h"

#define NCURVES 3000

static double curves[8 * NCURVES];
static volatile double sink;

/* Not inlined: callgrind collects by this function's name. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static double measured(const double *c, int gl24, double rtol, double half,
                       const double *ds, int kind) {
  double t[10];
  if (kind >= 0) {
    arclen_opts o;
    arclen_opts_init(&o);
    o.rtol = rtol;
    if (half > 0) arclen_segment_time(kind, 2, c, half, NULL, &o, t, NULL);
    else arclen_segment_length(kind, 2, c, NULL, &o, t, NULL);
    return t[0];
  }
  if (ds) return arclen_times(c, 2, ds, 10, rtol, t, NULL, NULL) + t[9];
  if (half > 0) return arclen_time(c, half, rtol);
  return gl24 ? arclen_length_gl(c, 2, 24) : arclen_length(c, rtol);
}

static long pieces_of(const double *c) {
  arclen_opts o;
  arclen_info info;
  double v;
  arclen_opts_init(&o);
  arclen_length_gauss(c, 2, &o, &v, &info);
  return info.pieces;
}

int main(int argc, char **argv) {
  const char *mode = argc > 1 ? argv[1] : "";
  int gl24 = strcmp(mode, "gl24") == 0, one = strcmp(mode, "one") == 0;
  int multi = strcmp(mode, "multi") == 0, all15 = strcmp(mode, "all15") == 0;
  int time15 = strcmp(mode, "time15") == 0, time = time15 || strcmp(mode, "time") == 0;
  int times10 = strcmp(mode, "times10") == 0;
  int qt15 = strcmp(mode, "quadtime15") == 0;
  int qtime = qt15 || strcmp(mode, "quadtime") == 0;
  int kind = strcmp(mode, "segcubic") == 0 ? ARCLEN_SEG_CUBIC
             : strcmp(mode, "quad") == 0 || qtime ? ARCLEN_SEG_QUAD : -1;
  int i, j, calls = 0;
  double ds[10];
  if (!gl24 && !one && !multi && !all15 && !time && !times10 && kind < 0
      && strcmp(mode, "all") != 0) {
    fprintf(stderr, "usage: bench_icount gl24|one|multi|all|all15|time|time15|"
            "times10|segcubic|quad|quadtime|quadtime15\n");
    return 2;
  }
  bench_random_curves(curves, NCURVES, 20261121);
  for (i = 0; i < NCURVES; i++) {
    const double *c = curves + 8 * i;
    if ((one || multi) && (pieces_of(c) > 1) != multi) continue;
    double rtol = all15 || time15 || qt15 ? 1e-15 : 1e-12;
    /* L/2 outside the collected function, as bench_length's halves */
    double half = time || times10 ? arclen_length(c, 1e-15) / 2 : 0;
    if (qtime) {              /* the quadratic's, as bench_segment's */
      arclen_opts o;
      arclen_opts_init(&o);
      arclen_segment_length(ARCLEN_SEG_QUAD, 2, c, NULL, &o, &half, NULL);
      half /= 2;
    }
    for (j = 0; j < 10; j++) ds[j] = half * (2 * j + 1) / 10;
    sink = measured(c, gl24, rtol, times10 ? 0 : half, times10 ? ds : NULL, kind);
    calls += times10 ? 10 : 1;
  }
  printf("%d\n", calls);
  return 0;
}
