/*
** peers.c -- the C side of `make bench-peers`: arclen's default and
** elliptic methods, GSL's CQUAD and QAGS, and the fixed 24-point Gauss rule
** that every ratio is taken to, on the same curves in one run.
**   peers CURVES            read CURVES (written by bench/peers/run.sh: one
**                           curve a line, "r" random or "a" adversarial, 8
**                           coordinates, the reference length), print one
**                           line per method:  name ns err_random err_adv
**                           (ns: median time per random curve; errors: max
**                           relative error against the reference; "nan"
**                           counts as an error of inf).
** Before timing, the random curves are checked to be bench_util.h's set.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef HAVE_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#endif

#include "arclen.h"
#include "bench_util.h"

#define MAXC 20000
#define REPS 8

static double cv[MAXC][8], ref[MAXC];
static char kind[MAXC];
static int ncurves, nrandom;
static double times[MAXC];
static volatile double sink;

typedef double (*length_fn)(const double *c);

static double plain24(const double *c) { return bench_plain24(c); }
static double gl24(const double *c) { return arclen_length_gl(c, 2, 24); }
static double gauss12(const double *c) { return arclen_length(c, 1e-12); }
static double gauss15(const double *c) { return arclen_length(c, 1e-15); }
static double elliptic(const double *c) {
  arclen_opts o;
  double L;
  arclen_opts_init(&o);
  if (arclen_length_elliptic(c, 2, &o, &L, NULL) != ARCLEN_OK) return NAN;
  return L;
}

#ifdef HAVE_GSL
/* |z'(t)| from the control points as given (what a GSL user writes). */
static double speed(double t, void *p) {
  const double *c = (const double *)p;
  double u = 1 - t, dx, dy;
  dx = 3 * (u * u * (c[2] - c[0]) + 2 * u * t * (c[4] - c[2]) + t * t * (c[6] - c[4]));
  dy = 3 * (u * u * (c[3] - c[1]) + 2 * u * t * (c[5] - c[3]) + t * t * (c[7] - c[5]));
  return sqrt(dx * dx + dy * dy);
}
static gsl_integration_cquad_workspace *cq_ws;
static gsl_integration_workspace *qa_ws;
static long gsl_failures;
static double cquad(const double *c) {
  gsl_function f;
  double r, err;
  size_t nev;
  f.function = speed;
  f.params = (void *)c;
  if (gsl_integration_cquad(&f, 0, 1, 0, 1e-12, cq_ws, &r, &err, &nev)) gsl_failures++;
  return r;
}
static double qags(const double *c) {
  gsl_function f;
  double r, err;
  f.function = speed;
  f.params = (void *)c;
  if (gsl_integration_qags(&f, 0, 1, 0, 1e-12, 1000, qa_ws, &r, &err)) gsl_failures++;
  return r;
}
#endif

static double median_ns(length_fn f) {
  int i, r;
  for (i = 0; i < nrandom; i++) {
    double t0 = bench_now();
    for (r = 0; r < REPS; r++) sink = f(cv[i]);
    times[i] = (bench_now() - t0) / REPS * 1e9;
  }
  return bench_median(times, nrandom);
}

static void report(const char *name, length_fn f) {
  double er = 0, ea = 0;
  int i;
  double ns = median_ns(f);
  for (i = 0; i < ncurves; i++) {
    double L = f(cv[i]), e;
    e = ref[i] == 0 ? fabs(L) : fabs(L - ref[i]) / ref[i];
    if (e != e) e = INFINITY;
    if (kind[i] == 'r') er = fmax(er, e); else ea = fmax(ea, e);
  }
  printf("%s\t%.1f\t%.3g\t%.3g\n", name, ns, er, ea);
  fflush(stdout);
}

int main(int argc, char **argv) {
  FILE *f;
  char line[1024];
  double gen[8 * 3000];
  int i, k;
  if (argc < 2 || !(f = fopen(argv[1], "r"))) {
    fprintf(stderr, "usage: peers CURVES\n");
    return 2;
  }
  while (ncurves < MAXC && fgets(line, sizeof line, f)) {
    char *p = line, *end;
    kind[ncurves] = *p++;
    for (k = 0; k < 8; k++) cv[ncurves][k] = strtod(p, &p);
    ref[ncurves] = strtod(p, &end);
    if (end == p) continue;
    if (kind[ncurves] == 'r') nrandom++;
    ncurves++;
  }
  fclose(f);
  bench_random_curves(gen, 3000, 20261121);
  for (i = 0; i < nrandom && i < 3000; i++)
    for (k = 0; k < 8; k++)
      if (gen[8 * i + k] != cv[i][k]) {
        fprintf(stderr, "peers: random curve %d is not bench_util.h's\n", i + 1);
        return 1;
      }
  /* first: run.sh's ratios are to it (one square root at a time, as the
  ** peers run it); then the same rule in arclen's packed loop */
  report("fixed 24-point Gauss-Legendre, plain loop (C)", plain24);
  report("fixed 24-point Gauss-Legendre, arclen_length_gl (C)", gl24);
  report("arclen gauss, tol 1e-12 (C)", gauss12);
  report("arclen gauss, tol 1e-15 (C)", gauss15);
  report("arclen elliptic (C)", elliptic);
#ifdef HAVE_GSL
  gsl_set_error_handler_off();
  cq_ws = gsl_integration_cquad_workspace_alloc(200);
  qa_ws = gsl_integration_workspace_alloc(1000);
  gsl_failures = 0;
  report("GSL cquad, epsrel 1e-12 (C)", cquad);
  fprintf(stderr, "GSL cquad: %ld calls reported failure\n", gsl_failures);
  gsl_failures = 0;
  report("GSL qags, epsrel 1e-12 (C)", qags);
  fprintf(stderr, "GSL qags: %ld calls reported failure\n", gsl_failures);
  gsl_integration_cquad_workspace_free(cq_ws);
  gsl_integration_workspace_free(qa_ws);
#else
  fprintf(stderr, "GSL: skipped (libgsl-dev not installed)\n");
#endif
  return 0;
}
