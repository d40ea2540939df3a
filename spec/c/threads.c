/*
** threads.c -- the C library measured from several threads at once.
**
** Every job below calls one family of the public API (src/arclen.h, path
** data of src/svg/pathdata.h and, built with -DTHREADS_SVGDOC, the
** document reader of src/svgdoc/) and writes all it gets -- numbers, codes,
** counts, strings -- as bytes into a sink.  Each job runs on the main
** thread first (its reference, twice: the two must agree); then THREADS
** threads run every job ROUNDS times -- all the same job at once, or each
** from a job of its own -- and each result must equal the reference bit
** for bit.  Built with -fsanitize=thread (tools/check-threads.sh, `make
** check-threads`), ThreadSanitizer also reports any data race on memory
** the library touches (not inside expat, which is not instrumented).
** Ends with "N passed, N failed" (one check per job run).
**
** It lives in spec/c/ because it is a test, but a C program, not a spec
** that busted loads (it loads the *_spec.lua files); later C tests go here.
**
**   threads [-t THREADS] [-r ROUNDS] [--inject-...] [file.svg ...]
**   --inject-race, --inject-mismatch: make the check fail on purpose (a
**   shared counter written by every thread; one thread's result changed by
**   a bit), to see that it can.
*/
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arclen.h"
#include "svg/pathdata.h"
#if defined(THREADS_SVGDOC)
#include "svgdoc/svgdoc.h"
#endif

#define MAX_THREADS 8
#define MAX_ROUNDS 100
#define MAX_FILES 64
#define SINK_MAX ((size_t)1 << 28)   /* a runaway job stops here */

/* ---- the sink: a job's results as bytes -------------------------------- */

typedef struct sink {
  unsigned char *b;
  size_t n, room;
  int full;             /* out of memory or beyond SINK_MAX */
} sink;

static void put(sink *s, const void *p, size_t n) {
  if (s->full || n == 0) return;   /* (p may be NULL when n is 0) */
  if (s->n + n > s->room) {
    size_t room = s->room ? s->room : 4096;
    unsigned char *b;
    while (room < s->n + n && room < SINK_MAX) room *= 2;
    if (room < s->n + n || (b = realloc(s->b, room)) == NULL) {
      s->full = 1;
      return;
    }
    s->b = b;
    s->room = room;
  }
  memcpy(s->b + s->n, p, n);
  s->n += n;
}
static void put_d(sink *s, double v) { put(s, &v, sizeof v); }
static void put_l(sink *s, long v) { put(s, &v, sizeof v); }
static void put_ds(sink *s, const double *v, size_t n) {
  put(s, v, n * sizeof *v);
}
/* A string with its terminating zero; NULL as one byte 0xff. */
static void put_s(sink *s, const char *str) {
  static const unsigned char none = 0xff;
  if (str == NULL) put(s, &none, 1);
  else put(s, str, strlen(str) + 1);
}
/* svgdoc_shape_d's pieces (a d and its terminating zero with put_s's). */
static void put_bytes(void *s, const char *bytes, size_t n) { put(s, bytes, n); }
static void put_info(sink *s, const arclen_info *in) {
  put_l(s, in->evals);
  put_l(s, in->pieces);
  put_l(s, in->depth);
  put_d(s, in->err);
  put_s(s, in->branch);
  put_l(s, in->calls);
}

/* ---- the curves --------------------------------------------------------- */

/* The README's curve, a cusp, a loop, near-lines, lines that turn back, a
** point, tiny and huge scales, a near-cusp. */
static const double CURVES2[][8] = {
  {0, 0, 10, 0, 10, 10, 0, 0},
  {0, 0, 10, 10, 0, 10, 10, 0},
  {0, 0, 1, 2, -1, 2, 0.5, 0},
  {0, 0, 1, 1e-9, 2, -1e-9, 3, 0},
  {0, 0, 1, 0, 2, 0, 3, 0},
  {0, 0, 3, 0, 1, 0, 2, 0},
  {1, 1, 1, 1, 1, 1, 1, 1},
  {0, 0, 1e-200, 3e-200, 2e-200, -1e-200, 4e-200, 1e-200},
  {-1e150, 3e150, 2e150, 1e150, -4e150, 2e150, 5e150, -1e150},
  {0, 0, 0.001, 5, 9.999, 5, 10, 0},
};
#define NCURVES2 (sizeof CURVES2 / sizeof CURVES2[0])

static const double CURVES3[][12] = {
  {0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 0, 0},
  {0, 0, 0, 1, 1, 1, 2, -1, 1, 3, 0, 2},
  {0, 0, 0, 10, 10, 5, 0, 10, 5, 10, 0, 0},
  {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3},
  {1e-100, 0, 2e-100, 3e-100, 1e-100, 0, -1e-100, 2e-100, 1e-100, 0, 0, 5e-100},
};
#define NCURVES3 (sizeof CURVES3 / sizeof CURVES3[0])

static const double TOLS[] = {1e-15, 1e-12, 1e-9, 1e-6, 1e-3, 0.1};
#define NTOLS (sizeof TOLS / sizeof TOLS[0])

/* SplitMix64 (Steele, Lea and Flood 2014, Vigna's constants): the same
** curves on any host, and no rand(). */
static double uniform(unsigned long long *state) {
  unsigned long long z = (*state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

#define NRANDOM 200
static void random_curves(double *c, int dim, unsigned long long seed) {
  int i;
  for (i = 0; i < 4 * dim * NRANDOM; i++) c[i] = 10 * uniform(&seed) - 5;
}

/* ---- the jobs ----------------------------------------------------------- */

/* The default method: length, range, time at every tolerance, 2D and 3D. */
static void job_gauss(sink *s) {
  size_t i, k;
  int j;
  for (i = 0; i < NCURVES2 + NCURVES3; i++) {
    int dim = i < NCURVES2 ? 2 : 3;
    const double *c = i < NCURVES2 ? CURVES2[i] : CURVES3[i - NCURVES2];
    for (k = 0; k < NTOLS; k++) {
      double L = dim == 2 ? arclen_length(c, TOLS[k]) : arclen_length3(c, TOLS[k]);
      arclen_opts o;
      arclen_info in;
      double v = 0;
      put_d(s, L);
      put_d(s, dim == 2 ? arclen_length_range(c, 0.2, 0.9, TOLS[k])
                        : arclen_length3_range(c, 0.2, 0.9, TOLS[k]));
      for (j = 0; j <= 4; j++)
        put_d(s, dim == 2 ? arclen_time(c, L * j / 4, TOLS[k])
                          : arclen_time3(c, L * j / 4, TOLS[k]));
      arclen_opts_init(&o);
      o.rtol = TOLS[k];
      o.t0 = 0.9;
      o.t1 = 0.1;
      arclen_info_init(&in);
      put_l(s, arclen_length_gauss(c, dim, &o, &v, &in));
      put_d(s, v);
      put_info(s, &in);
      o.t0 = 0;
      o.t1 = 1;
      arclen_info_init(&in);
      put_l(s, arclen_time_gauss(c, dim, L / 3, &o, &v, &in));
      put_d(s, v);
      put_info(s, &in);
    }
    put_d(s, arclen_length_gl(c, dim, 24));
    put_d(s, arclen_length_gl(c, dim, 64));
  }
}

/* Many distances in one pass, with points and tangents. */
static void job_times(sink *s) {
  double d[50], t[50], pts[150], tan[150];
  size_t i;
  int k;
  for (i = 0; i < NCURVES2 + NCURVES3; i++) {
    int dim = i < NCURVES2 ? 2 : 3;
    const double *c = i < NCURVES2 ? CURVES2[i] : CURVES3[i - NCURVES2];
    double L = dim == 2 ? arclen_length(c, 1e-12) : arclen_length3(c, 1e-12);
    for (k = 0; k < 50; k++) d[k] = L * (k - 2) / 45;   /* from below 0 to beyond L */
    memset(t, 0, sizeof t);
    memset(pts, 0, sizeof pts);
    memset(tan, 0, sizeof tan);
    put_l(s, arclen_times(c, dim, d, 50, 1e-12, t, pts, tan));
    put_ds(s, t, 50);
    put_ds(s, pts, 50 * (size_t)dim);
    put_ds(s, tan, 50 * (size_t)dim);
    put_l(s, arclen_times(c, dim, d, 50, 1e-6, t, NULL, NULL));
    put_ds(s, t, 50);
  }
}

/* Many curves at once, by the default method, the elliptic one and MetaPost's. */
static void job_batch(sink *s) {
  static const char *const names[] = {"gauss", "elliptic", "metapost"};
  double *c = malloc(4 * 3 * NRANDOM * sizeof *c);
  double out[NRANDOM];
  int dim, m, k;
  if (c == NULL) {
    put_s(s, "no memory");
    return;
  }
  for (dim = 2; dim <= 3; dim++) {
    random_curves(c, dim, 20261203ULL + (unsigned long long)dim);
    for (m = 0; m < 3; m++)
      for (k = 0; k < 3; k++) {
        arclen_opts o;
        long failed = -2;
        arclen_opts_init(&o);
        o.rtol = TOLS[2 * k];
        put_l(s, arclen_lengths(c, NRANDOM, dim, arclen_find_method(names[m]),
                                &o, out, &failed));
        put_l(s, failed);
        put_ds(s, out, NRANDOM);
      }
  }
  free(c);
}

/* The exact length (2D, 3D, parts of curves) and Carlson's functions. */
static void job_elliptic(sink *s) {
  static const double RANGES[][2] = {{0, 1}, {0.25, 0.75}, {1, 0}, {0.5, 0.5}};
  size_t i, r;
  int a, b, c2;
  for (i = 0; i < NCURVES2 + NCURVES3; i++) {
    int dim = i < NCURVES2 ? 2 : 3;
    const double *c = i < NCURVES2 ? CURVES2[i] : CURVES3[i - NCURVES2];
    for (r = 0; r < sizeof RANGES / sizeof RANGES[0]; r++) {
      arclen_opts o;
      arclen_info in;
      double v = 0;
      arclen_opts_init(&o);
      o.t0 = RANGES[r][0];
      o.t1 = RANGES[r][1];
      arclen_info_init(&in);
      put_l(s, arclen_length_elliptic(c, dim, &o, &v, &in));
      put_d(s, v);
      put_info(s, &in);
    }
  }
  for (a = 0; a < 6; a++)
    for (b = 0; b < 6; b++)
      for (c2 = 0; c2 < 6; c2++) {
        double x = ldexp(1.5, 40 * a - 100), y = ldexp(0.7, 40 * b - 100);
        double z = ldexp(1.1, 40 * c2 - 100);
        put_d(s, arclen_rf(x, y, z));
        put_d(s, arclen_rd(x, y, z));
        put_d(s, arclen_rc(x, (c2 & 1) ? -y : y));
        put_d(s, arclen_rj(x, y, z, (a & 1) ? -x * z : y + z));
        put_d(s, arclen_rg(x, y, z));
      }
  put_d(s, arclen_rf(0, 0, 1));   /* a domain error: NaN */
}

/* MetaPost's arclength and arctime: one cubic, paths, the method rows. */
static void job_metapost(sink *s) {
  static const double overflow[8] = {0, 0, 20000, 0, 20000, 10, 0, 10};
  double seg[8 * 4];
  size_t i;
  int k, cyc;
  for (i = 0; i < NCURVES2; i++) {
    const double *c = CURVES2[i];
    arclen_info in;
    arclen_opts o;
    double L = 0, t = 0;
    arclen_info_init(&in);
    put_l(s, arclen_mp_arclength(c, &L, &in));
    put_d(s, L);
    put_info(s, &in);
    for (k = -1; k <= 5; k++) {
      arclen_info_init(&in);
      put_l(s, arclen_mp_arctime(c, L * k / 4, &t, &in));
      put_d(s, t);
      put_info(s, &in);
    }
    arclen_opts_init(&o);
    o.t0 = 0.1;
    o.t1 = 0.8;
    put_l(s, arclen_length_metapost(c, 2, &o, &L, NULL));
    put_d(s, L);
    put_l(s, arclen_time_metapost(c, 2, L / 2, &o, &t, NULL));
    put_d(s, t);
  }
  {
    double L;
    put_l(s, arclen_mp_arclength(overflow, &L, NULL));   /* EOVERFLOW */
  }
  /* A path of four segments from the first curves, each joined to the last. */
  for (k = 0; k < 4; k++) {
    int j;
    for (j = 0; j < 8; j++) seg[8 * k + j] = CURVES2[k == 3 ? 9 : k][j] + 3 * k;
    if (k > 0) {
      seg[8 * k] = seg[8 * k - 2];
      seg[8 * k + 1] = seg[8 * k - 1];
    }
  }
  for (cyc = 0; cyc <= 1; cyc++) {
    double L = 0, t = 0;
    arclen_info in;
    if (cyc) {
      seg[30] = seg[0];
      seg[31] = seg[1];
    }
    arclen_info_init(&in);
    put_l(s, arclen_mp_path_arclength(seg, 4, cyc, &L, &in));
    put_d(s, L);
    put_info(s, &in);
    for (k = -3; k <= 12; k++) {
      put_l(s, arclen_mp_path_arctime(seg, 4, cyc, L * k / 8, &t, NULL));
      put_d(s, t);
    }
  }
}

/* Every method of the registry by name, length and time, 2D and 3D. */
static void job_methods(sink *s) {
  const arclen_method *m;
  size_t i;
  for (m = arclen_method_list(); m->name != NULL; m++) {
    put_s(s, m->name);
    put_l(s, arclen_find_method(m->name) == m);
    for (i = 0; i < NCURVES2 + NCURVES3; i++) {
      int dim = i < NCURVES2 ? 2 : 3;
      const double *c = i < NCURVES2 ? CURVES2[i] : CURVES3[i - NCURVES2];
      arclen_opts o;
      arclen_info in;
      double v = 0;
      arclen_opts_init(&o);
      o.rtol = 1e-8;
      o.steps = 2000;
      arclen_info_init(&in);
      put_l(s, m->length(c, dim, &o, &v, &in));
      put_d(s, v);
      put_info(s, &in);
      if (m->time != NULL) {
        put_l(s, m->time(c, dim, v / 3, &o, &v, NULL));
        put_d(s, v);
      }
    }
  }
  put_l(s, arclen_find_method("no such method") == NULL);
}

/* Walter & Fournier's fits: build, evaluate, measure. */
static void job_fit(sink *s) {
  arclen_fit_span *spans = malloc(ARCLEN_FIT_MAXSPANS * sizeof *spans);
  size_t i;
  int method, k;
  if (spans == NULL) {
    put_s(s, "no memory");
    return;
  }
  for (i = 0; i < NCURVES2 + NCURVES3; i++) {
    int dim = i < NCURVES2 ? 2 : 3;
    const double *c = i < NCURVES2 ? CURVES2[i] : CURVES3[i - NCURVES2];
    for (method = ARCLEN_FIT_HERMITE; method <= ARCLEN_FIT_PAPER; method++) {
      arclen_fit_opts o;
      arclen_fit f;
      double mx = 0, mean = 0, arg = 0;
      int rc;
      arclen_fit_opts_init(&o);
      o.method = method;
      o.tol = method == ARCLEN_FIT_HERMITE ? 1e-7 : 0;
      o.monotone = method == ARCLEN_FIT_PAPER;
      rc = arclen_fit_build(c, dim, &o, &f, spans, ARCLEN_FIT_MAXSPANS);
      put_l(s, rc);
      if (rc != 0) continue;
      put_l(s, f.nspans);
      put_l(s, f.evals);
      put_d(s, f.total);
      put(s, spans, (size_t)f.nspans * sizeof *spans);
      for (k = 0; k <= 20; k++) {
        double t = k / 20.0;
        put_d(s, arclen_fit_value(&f, t));
        put_d(s, arclen_fit_slope(&f, t));
        put_d(s, arclen_fit_length(&f, t));
        put_d(s, arclen_fit_time(&f, f.total * t));
        put_d(s, arclen_fit_invert(&f, t));
        put_d(s, arclen_fit_speed(&f, t));
      }
      put_l(s, arclen_fit_monotone(&f));
      put_l(s, arclen_fit_error(&f, ARCLEN_TRUTH_EXACT, 0, 0, &mx, &mean, &arg));
      put_d(s, mx);
      put_d(s, mean);
      put_d(s, arg);
      put_l(s, arclen_fit_error(&f, ARCLEN_TRUTH_SIMPSON, 1, 10, &mx, &mean, &arg));
      put_d(s, mx);
      put_d(s, mean);
      put_d(s, arg);
    }
  }
  free(spans);
}

/* Floater's conics: schemes, bounds, cubics, lengths, arcs. */
static void job_conic(sink *s) {
  static const double P[][6] = {
    {1, 0, 1, 1, 0, 1}, {0, 0, 5, 8, 10, 0}, {-3, 1, 0, 1e-3, 3, 1},
    {0, 0, 1, 1, 2, 2}};
  static const double W[] = {1e-6, 0.3, 0.7071067811865476, 1, 1.5, 40};
  double out[8 << 6], c[28], v = 0, A = 0, B = 0;
  size_t p, w;
  int sc, lev = 0, n = 0;
  for (sc = 0; sc < ARCLEN_CONIC_NSCHEMES; sc++) {
    put_s(s, arclen_conic_scheme_name(sc));
    put_l(s, arclen_conic_scheme(arclen_conic_scheme_name(sc)));
  }
  put_l(s, arclen_conic_scheme("none"));
  put_s(s, arclen_conic_scheme_name(ARCLEN_CONIC_NSCHEMES));
  for (p = 0; p < sizeof P / sizeof P[0]; p++)
    for (w = 0; w < sizeof W / sizeof W[0]; w++) {
      arclen_info in;
      double pt[2];
      put_l(s, arclen_conic_degenerate(P[p]));
      put_l(s, arclen_conic_check(P[p], W[w]));
      arclen_info_init(&in);
      put_l(s, arclen_conic_length(P[p], W[w], &v, &in));
      put_d(s, v);
      put_info(s, &in);
      arclen_conic_point(P[p], W[w], 0.3, pt);
      put_ds(s, pt, 2);
      for (sc = 0; sc < ARCLEN_CONIC_NSCHEMES; sc++) {
        put_d(s, arclen_conic_lambda(sc, W[w]));
        arclen_conic_scheme_AB(sc, W[w], &A, &B);
        put_d(s, A);
        put_d(s, B);
        put_d(s, arclen_conic_gnorm(A, B));
        for (lev = 0; lev <= ARCLEN_CONIC_MAXLEVEL; lev += 4) {
          put_l(s, arclen_conic_bound(P[p], W[w], sc, lev, &v));
          put_d(s, v);
          put_d(s, arclen_conic_weight(W[w], lev));
        }
        put_l(s, arclen_conic_level(P[p], W[w], sc, 1e-6, &lev, &v));
        put_l(s, lev);
        put_d(s, v);
        memset(out, 0, sizeof out);
        put_l(s, arclen_conic_cubics(P[p], W[w], sc, 6, out, &v));
        put_ds(s, out, 8 << 6);
        put_d(s, v);
      }
      arclen_conic_AB(W[w], 1e-9, &A, &B);
      put_d(s, A);
      put_d(s, B);
    }
  put_l(s, arclen_conic_normal_weight(0.5, 2, 3, &v));
  put_d(s, v);
  memset(c, 0, sizeof c);
  n = arclen_ellipse_conics(1, 2, 3, 1, 0.3, 0.1, -5.5, c);
  put_l(s, n);
  put_ds(s, c, 28);
  for (sc = 0; sc < 8; sc++) {
    memset(c, 0, sizeof c);
    put_l(s, arclen_svg_arc_center(0, 0, 5, 3, 30 * sc, sc & 1, (sc >> 1) & 1,
                                   7, 2, c));
    put_ds(s, c, 7);
    memset(c, 0, sizeof c);
    put_l(s, arclen_svg_arc_conics(0, 0, 5, 3, 30 * sc, sc & 1, (sc >> 1) & 1,
                                   7, 2, c, &n));
    put_l(s, n);
    put_ds(s, c, 28);
  }
}

/* Roots, the geometry of one cubic, Gauss-Legendre rules, error strings. */
static void job_roots(sink *s) {
  static const double Q[][5] = {
    {1, -10, 35, -50, 24}, {1, 0, -5, 0, 4}, {5e-324, 0, -5, 0, 4},
    {1, 4, 6, 4, 1}, {1e-10, 1, 1e10, 1, 1e-10}, {1, 0, 0, 0, -1},
    {3, -2, 1e-20, 7, 1e300}};
  double re[4], im[4], q[4] = {0, 0, 0, 0}, x[ARCLEN_GL_MAXN], w[ARCLEN_GL_MAXN];
  double p[3] = {0, 0, 0}, l[12], r[12], a2[3], a1[3], a0[3];
  size_t i;
  int k, n;
  for (i = 0; i < sizeof Q / sizeof Q[0]; i++) {
    memset(re, 0, sizeof re);
    memset(im, 0, sizeof im);
    n = arclen_quadratic(Q[i][0], Q[i][1], Q[i][2], re, im);
    put_l(s, n);
    put_ds(s, re, 2);
    put_ds(s, im, 2);
    n = arclen_cubic(Q[i][0], Q[i][1], Q[i][2], Q[i][3], re, im);
    put_l(s, n);
    put_ds(s, re, 3);
    put_ds(s, im, 3);
    n = arclen_quartic(Q[i][0], Q[i][1], Q[i][2], Q[i][3], Q[i][4], re, im);
    put_l(s, n);
    put_ds(s, re, 4);
    put_ds(s, im, 4);
    put_l(s, arclen_quartic_factor(Q[i][0], Q[i][1], Q[i][2], Q[i][3], Q[i][4], q));
    put_ds(s, q, 4);
  }
  for (i = 0; i < NCURVES2 + NCURVES3; i++) {
    int dim = i < NCURVES2 ? 2 : 3;
    const double *c = i < NCURVES2 ? CURVES2[i] : CURVES3[i - NCURVES2];
    put_l(s, arclen_check_curve(c, dim));
    for (k = 0; k <= 4; k++) {
      arclen_point(c, dim, k / 4.0, p);
      put_ds(s, p, (size_t)dim);
      arclen_derivative(c, dim, k / 4.0, p);
      put_ds(s, p, (size_t)dim);
      arclen_unit_tangent(c, dim, k / 4.0, p);
      put_ds(s, p, (size_t)dim);
    }
    arclen_split(c, dim, 0.3, l, r);
    put_ds(s, l, 4 * (size_t)dim);
    put_ds(s, r, 4 * (size_t)dim);
    arclen_subcurve(c, dim, 0.2, 0.7, l);
    put_ds(s, l, 4 * (size_t)dim);
    arclen_hodograph(c, dim, a2, a1, a0);
    put_ds(s, a2, (size_t)dim);
    put_ds(s, a1, (size_t)dim);
    put_ds(s, a0, (size_t)dim);
    n = arclen_critical_points(c, dim, p);
    put_l(s, n);
    put_ds(s, p, (size_t)n);
  }
  for (n = 0; n <= ARCLEN_GL_MAXN + 1; n++) {
    put_l(s, arclen_gauss_legendre(n, x, w));
    if (n >= 1 && n <= ARCLEN_GL_MAXN) {
      put_ds(s, x, (size_t)n);
      put_ds(s, w, (size_t)n);
    }
  }
  for (k = 1; k >= -8; k--) put_s(s, arclen_strerror(k));
  put_s(s, ARCLEN_VERSION);
}

/* SVG path data: commands of every kind, arcs, a transform, the errors. */
static void job_pathdata(sink *s) {
  static const char *const D[] = {
    "M0 0 H10 V5 A5 5 0 0 1 5 10 H0 Z",
    "m10 10 c 5 -5 10 5 15 0 s 5 5 10 0 q 5 5 10 0 t 10 0 l-50-20z M1,1 2,2",
    "M0 0 A30 50 -45 1 0 100 100 a1e3 1 0 0 0 .5.5 a0 5 0 0 1 10 0",
    "M1e308 0 L-1e308 0 M0.12345678901234567890 0 L1.5e30 7e-320",
    "M0 0 L1 1 A5 5 0 2 1 3 3",   /* flag 2: an error */
    "M0 0 L1 1 Z 3",              /* numbers after Z */
    "L1 1",                       /* no moveto */
    "M0 0 L1e400 0",              /* beyond the doubles */
    "M0 0 C1 1 2",                /* an argument missing */
    "M 0 0 1e",                   /* e without digits */
    "  ",
    "M0 0 L1 1 #",
  };
  static const double T[6] = {2, 0.5, -0.25, 3, 7, -1};
  static const char *const CMDS = "MLHVCSQTAZ";
  char buf[256];
  size_t i, k;
  int t, a;
  for (i = 0; i < sizeof D / sizeof D[0]; i++)
    for (t = 0; t < 3; t++) {
      arclen_pathdata pd;
      int rc;
      arclen_pathdata_init(&pd);
      pd.arcs = ARCLEN_PD_ARCS_CUBICS;   /* measured below as cubics */
      rc = arclen_pathdata_parse(&pd, D[i], strlen(D[i]), t == 1 ? 1e-4 : 1e-12,
                                 t == 2 ? T : NULL);
      put_l(s, rc);
      put_l(s, (long)pd.ncubics);
      put_ds(s, pd.cubics, 8 * pd.ncubics);
      put_l(s, (long)pd.nsubpaths);
      for (k = 0; k < pd.nsubpaths; k++) {
        put_d(s, pd.subpaths[k].x);
        put_d(s, pd.subpaths[k].y);
        put_l(s, (long)pd.subpaths[k].first);
        put_l(s, (long)pd.subpaths[k].n);
        put_l(s, pd.subpaths[k].closed);
      }
      put_l(s, pd.err.kind);
      put_l(s, (long)pd.err.pos);
      if (rc != ARCLEN_PD_OK) {
        put_l(s, (long)arclen_pathdata_message(&pd, D[i], buf, sizeof buf));
        put_s(s, buf);
      } else if (pd.ncubics > 0) {
        double out[64];
        long failed, n = pd.ncubics < 64 ? (long)pd.ncubics : 64;
        arclen_opts o;
        arclen_opts_init(&o);
        put_l(s, arclen_lengths(pd.cubics, n, 2, arclen_find_method("gauss"),
                                &o, out, &failed));
        put_ds(s, out, (size_t)n);
      }
      arclen_pathdata_free(&pd);
    }
  for (k = 0; CMDS[k]; k++)
    for (a = 0; a <= 8; a++) put_s(s, arclen_pathdata_argname(CMDS[k], a));
}

#if defined(THREADS_SVGDOC)
/* Documents read as a renderer draws them, then measured. */
typedef struct doc_text {
  const char *name, *s;
  size_t n;
} doc_text;

static const char *const DOCS[] = {
  ("<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink'"
   " width='100mm' height='50mm' viewBox='0 0 200 100'>"
   "<defs><path id='p' d='M0 0 C10 20 30 20 40 0'/></defs>"
   "<g transform='translate(10 5) rotate(30) scale(2 1)' style='stroke:red'>"
   "<rect x='1' y='2' width='30' height='20' rx='4'/><circle cx='5' cy='5' r='3'/>"
   "<ellipse cx='50' cy='20' rx='10' ry='4' transform='skewX(10)'/>"
   "<line x1='0' y1='0' x2='7' y2='9'/><polyline points='0,0 1,1 2,0 3,1'/>"
   "<polygon points='5 5 10 5 7 9'/><use xlink:href='#p' x='3' y='4'/>"
   "<text>skipped</text><g display='none'><path d='M0 0 L5 5'/></g>"
   "</g><path d='M0 0 A5 5 0 1 1 10 0 z' stroke-width='0.0' stroke='blue'/></svg>"),
  ("<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink'>"
   "<path d='M0 0 L1 1' transform='scale(0 1)'/><use/><use xlink:href='other.svg#a'/>"
   "<svg width='0' height='5'><path d='M0 0 L1 1'/></svg><circle r='2em' style='stroke:none'/>"
   "<use xlink:href='#c' width='4' height='4'/><symbol id='c' viewBox='0 0 2 2'><rect width='1' height='1'/></symbol></svg>"),
  "<svg xmlns='http://www.w3.org/2000/svg'><rect width='-1' height='2'/></svg>",
  "<svg xmlns='http://www.w3.org/2000/svg'><path d='M0 0 L1 1 X'/></svg>",
  "<svg xmlns='http://www.w3.org/2000/svg'><g><path d='M0 0 L1 1'/></svg>",
};
#define NDOCS (sizeof DOCS / sizeof DOCS[0])

static doc_text docs[NDOCS + MAX_FILES];
static size_t ndocs;

static void put_doc(sink *s, const svgdoc *D) {
  size_t i, k, n = svgdoc_count(D);
  const svgdoc_info *ri = svgdoc_root_info(D);
  double out[256];
  put_l(s, (long)n);
  for (i = 0; i < n; i++) {
    const svgdoc_element *e = svgdoc_get(D, i);
    put_s(s, e->id);
    put_s(s, e->tag);
    put_s(s, e->layer);
    put_s(s, e->use);
    svgdoc_shape_d(&e->shape, put_bytes, s);
    put(s, "", 1);
    put_l(s, (long)e->line);
    put_l(s, (long)e->col);
    put_l(s, e->stroked);
    put_ds(s, e->ctm, 6);
    put_l(s, (long)e->pd.ncubics);
    put_ds(s, e->pd.cubics, 8 * e->pd.ncubics);
    for (k = 0; k < e->pd.nsubpaths; k++) {
      put_l(s, (long)e->pd.subpaths[k].first);
      put_l(s, e->pd.subpaths[k].closed);
    }
    for (k = 0; k < e->pd.ncubics; k += 256) {
      long failed, m = (long)(e->pd.ncubics - k < 256 ? e->pd.ncubics - k : 256);
      arclen_opts o;
      arclen_opts_init(&o);
      put_l(s, arclen_lengths(e->pd.cubics + 8 * k, m, 2,
                              arclen_find_method("gauss"), &o, out, &failed));
      put_ds(s, out, (size_t)m);
    }
  }
  put_l(s, (long)svgdoc_nwarnings(D));
  for (i = 0; i < svgdoc_nwarnings(D); i++) {
    const svgdoc_warning *w = svgdoc_warning_at(D, i);
    put_l(s, (long)w->line);
    put_l(s, (long)w->col);
    put_s(s, w->msg);
  }
  for (i = 0; i < SVGDOC_NSKIPPED; i++) put_l(s, (long)svgdoc_skipped(D)[i]);
  put_l(s, (long)svgdoc_kept(D));
  put_l(s, ri->has_width);
  put_l(s, ri->has_height);
  put_l(s, ri->has_viewbox);
  put_d(s, ri->width);
  put_d(s, ri->height);
  put_ds(s, ri->viewbox, 4);
}

static void job_svgdoc(sink *s) {
  size_t i;
  int v;
  for (i = 0; i < ndocs; i++)
    for (v = 0; v < 2; v++) {
      svgdoc_options o;
      svgdoc *D;
      unsigned long line = 0, col = 0;
      int rc;
      o.arc_tol = v ? 1e-6 : 1e-12;
      o.unit_px = v ? 96 / 25.4 : 0;
      o.hidden = v;
      o.stroked = v;
      o.painted = 0;
      o.lang = NULL;
      o.max_depth = SVGDOC_MAX_DEPTH;
      o.uses = 1;
      o.stream = 0;                    /* collected: put_doc reads them all */
      o.max_held = 0;
      o.shape_text = 0;
      o.strict = 0;
      o.arcs = ARCLEN_PD_ARCS_CUBICS;     /* measured below as cubics */
      put_s(s, docs[i].name);
      D = svgdoc_new(&o);
      if (D == NULL) {
        put_s(s, "no memory");
        continue;
      }
      /* fed in two pieces, cut inside the document */
      rc = svgdoc_feed(D, docs[i].s, docs[i].n / 3);
      if (rc == 0) rc = svgdoc_feed(D, docs[i].s + docs[i].n / 3,
                                    docs[i].n - docs[i].n / 3);
      if (rc == 0) rc = svgdoc_finish(D);
      put_l(s, rc);
      if (rc != 0) {
        put_s(s, svgdoc_error(D, &line, &col));
        put_l(s, (long)line);
        put_l(s, (long)col);
      } else {
        put_doc(s, D);
      }
      svgdoc_free(D);
    }
}

/* The documents: the ones above and each file named. */
static int load_docs(int nfiles, char **files) {
  int i;
  for (ndocs = 0; ndocs < NDOCS; ndocs++) {
    docs[ndocs].name = "(inline)";
    docs[ndocs].s = DOCS[ndocs];
    docs[ndocs].n = strlen(DOCS[ndocs]);
  }
  for (i = 0; i < nfiles; i++) {
    FILE *f = fopen(files[i], "rb");
    char *b;
    long n;
    if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET) != 0 || (b = malloc((size_t)n + 1)) == NULL ||
        fread(b, 1, (size_t)n, f) != (size_t)n) {
      fprintf(stderr, "threads: cannot read %s\n", files[i]);
      if (f) fclose(f);
      return -1;
    }
    fclose(f);
    docs[ndocs].name = files[i];
    docs[ndocs].s = b;
    docs[ndocs].n = (size_t)n;
    ndocs++;
  }
  return 0;
}
#endif

/* Built once on the main thread, then only read, by every thread at once:
** a fit, path data, a document (the functions that read them take const). */
static arclen_fit shared_fit;
static arclen_fit_span shared_spans[ARCLEN_FIT_MAXSPANS];
static arclen_pathdata shared_pd;
#if defined(THREADS_SVGDOC)
static svgdoc *shared_doc;
#endif

static int build_shared(void) {
  static const char d[] = "M0 0 C10 20 30 20 40 0 A20 10 30 1 1 0 0 Q5 5 10 0 z";
  arclen_fit_opts o;
  arclen_fit_opts_init(&o);
  o.tol = 1e-9;
  arclen_pathdata_init(&shared_pd);
  shared_pd.arcs = ARCLEN_PD_ARCS_CUBICS;     /* measured as cubics */
  if (arclen_fit_build(CURVES2[0], 2, &o, &shared_fit, shared_spans,
                       ARCLEN_FIT_MAXSPANS) != 0 ||
      arclen_pathdata_parse(&shared_pd, d, strlen(d), 1e-12, NULL) != ARCLEN_PD_OK)
    return -1;
#if defined(THREADS_SVGDOC)
  {
    svgdoc_options so;
    so.arc_tol = 1e-12;
    so.unit_px = 0;
    so.hidden = so.stroked = so.painted = 0;
    so.lang = NULL;
    so.max_depth = SVGDOC_MAX_DEPTH;
    so.uses = 1;
    so.stream = 0;
    so.max_held = 0;
    so.shape_text = 0;
    so.strict = 0;
    so.arcs = ARCLEN_PD_ARCS_CUBICS;
    shared_doc = svgdoc_new(&so);
    if (shared_doc == NULL || svgdoc_feed(shared_doc, DOCS[0], strlen(DOCS[0])) != 0 ||
        svgdoc_finish(shared_doc) != 0)
      return -1;
  }
#endif
  return 0;
}

static void free_shared(void) {
  arclen_pathdata_free(&shared_pd);
#if defined(THREADS_SVGDOC)
  {
    size_t i;
    svgdoc_free(shared_doc);
    for (i = NDOCS; i < ndocs; i++) free((char *)docs[i].s);   /* the files */
  }
#endif
}

static void job_shared(sink *s) {
  double out[256];
  long failed, n = (long)(shared_pd.ncubics < 256 ? shared_pd.ncubics : 256);
  arclen_opts o;
  int k;
  for (k = 0; k <= 100; k++) {
    double t = k / 100.0;
    put_d(s, arclen_fit_value(&shared_fit, t));
    put_d(s, arclen_fit_slope(&shared_fit, t));
    put_d(s, arclen_fit_length(&shared_fit, t));
    put_d(s, arclen_fit_time(&shared_fit, shared_fit.total * t));
    put_d(s, arclen_fit_invert(&shared_fit, t));
  }
  put_l(s, arclen_fit_monotone(&shared_fit));
  arclen_opts_init(&o);
  put_l(s, arclen_lengths(shared_pd.cubics, n, 2, arclen_find_method("gauss"),
                          &o, out, &failed));
  put_ds(s, out, (size_t)n);
  put_l(s, (long)shared_pd.nsubpaths);
#if defined(THREADS_SVGDOC)
  put_doc(s, shared_doc);
#endif
}

typedef struct job {
  const char *name;
  void (*run)(sink *s);
} job;

static const job JOBS[] = {
  {"gauss: length, range, time at 6 tolerances", job_gauss},
  {"times: many distances, points, tangents", job_times},
  {"lengths: 200 curves at once, 3 methods", job_batch},
  {"elliptic and Carlson's R-functions", job_elliptic},
  {"metapost: arclength, arctime, paths", job_metapost},
  {"every method of the registry", job_methods},
  {"fit: build, evaluate, error", job_fit},
  {"conic: schemes, bounds, cubics, lengths, arcs", job_conic},
  {"roots, geometry, Gauss-Legendre, strerror", job_roots},
  {"path data: parse, messages, lengths", job_pathdata},
  {"shared: one fit, path data, document, read", job_shared},
#if defined(THREADS_SVGDOC)
  {"svgdoc: documents read and measured", job_svgdoc},
#endif
};
#define NJOBS ((int)(sizeof JOBS / sizeof JOBS[0]))

/* ---- the threads -------------------------------------------------------- */

static sink refs[NJOBS];
static pthread_barrier_t step;
static int rounds = 2, inject_mismatch;
static long injected;   /* --inject-race: written by every thread, unguarded */
static int inject_race;

typedef struct worker {
  pthread_t id;
  int index;
  long passed, failed;
  char first[200];      /* the first failure's description */
} worker;

/* Even rounds in step: every thread runs the same job at once, after a
** barrier, so that a race lies within one job's accesses (ThreadSanitizer
** keeps a bounded history; a long job in between can hide the older
** access).  Odd rounds each thread from a job of its own, no barrier: the
** entry points meet each other. */
static void *work(void *arg) {
  worker *w = arg;
  int r, k;
  for (r = 0; r < rounds; r++)
    for (k = 0; k < NJOBS; k++) {
      int j = r % 2 == 0 ? k : (w->index * 3 + r + k) % NJOBS;
      sink s = {NULL, 0, 0, 0};
      if (r % 2 == 0 || k == 0) pthread_barrier_wait(&step);
      JOBS[j].run(&s);
      if (inject_race) injected++;
      if (inject_mismatch && w->index == 1 && r == 0 && k == 0 && s.n > 0)
        s.b[s.n / 2] ^= 1;
      if (!s.full && s.n == refs[j].n && memcmp(s.b, refs[j].b, s.n) == 0) {
        w->passed++;
      } else {
        size_t at = 0;
        while (at < s.n && at < refs[j].n && s.b[at] == refs[j].b[at]) at++;
        if (w->failed++ == 0)
          snprintf(w->first, sizeof w->first,
                   "thread %d, round %d, %s: %lu bytes, reference %lu, first "
                   "difference at byte %lu", w->index, r, JOBS[j].name,
                   (unsigned long)s.n, (unsigned long)refs[j].n,
                   (unsigned long)at);
      }
      free(s.b);
    }
  return NULL;
}

int main(int argc, char **argv) {
  worker w[MAX_THREADS];
  int nthreads = 6, i, j;
  long passed = 0, failed = 0;
  for (i = 1; i < argc && argv[i][0] == '-'; i++) {
    if (strcmp(argv[i], "-t") == 0 && i + 1 < argc) {
      nthreads = atoi(argv[++i]);
    } else if (strcmp(argv[i], "-r") == 0 && i + 1 < argc) {
      rounds = atoi(argv[++i]);
    } else if (strcmp(argv[i], "--inject-race") == 0) {
      inject_race = 1;
    } else if (strcmp(argv[i], "--inject-mismatch") == 0) {
      inject_mismatch = 1;
    } else {
      fprintf(stderr, "threads: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  if (argc - i > MAX_FILES) {
    fprintf(stderr, "threads: at most %d files\n", MAX_FILES);
    return 2;
  }
  if (nthreads < 2 || nthreads > MAX_THREADS || rounds < 1 || rounds > MAX_ROUNDS) {
    fprintf(stderr, "threads: -t must be in [2, %d], -r in [1, %d]\n",
            MAX_THREADS, MAX_ROUNDS);
    return 2;
  }
#if defined(THREADS_SVGDOC)
  if (load_docs(argc - i, argv + i) != 0) return 2;
#else
  if (argc > i) fprintf(stderr, "threads: built without svgdoc: files ignored\n");
#endif
  if (build_shared() != 0) {
    fprintf(stderr, "threads: the shared fit, path data or document failed\n");
    return 2;
  }
  /* The references, on this thread alone; a second run must agree. */
  for (j = 0; j < NJOBS; j++) {
    sink again = {NULL, 0, 0, 0};
    JOBS[j].run(&refs[j]);
    JOBS[j].run(&again);
    if (refs[j].full || again.full || refs[j].n != again.n ||
        memcmp(refs[j].b, again.b, refs[j].n) != 0) {
      printf("%s: two runs on one thread differ\n", JOBS[j].name);
      failed++;
    }
    free(again.b);
  }
  if (pthread_barrier_init(&step, NULL, (unsigned)nthreads) != 0) {
    fprintf(stderr, "threads: no barrier\n");
    return 2;
  }
  for (i = 0; i < nthreads; i++) {
    w[i].index = i;
    w[i].passed = w[i].failed = 0;
    w[i].first[0] = 0;
    if (pthread_create(&w[i].id, NULL, work, &w[i]) != 0) {
      fprintf(stderr, "threads: cannot start thread %d\n", i);
      return 2;
    }
  }
  for (i = 0; i < nthreads; i++) {
    pthread_join(w[i].id, NULL);
    passed += w[i].passed;
    failed += w[i].failed;
    if (w[i].failed) printf("%s (%ld failed in all)\n", w[i].first, w[i].failed);
  }
  pthread_barrier_destroy(&step);
  free_shared();
  for (j = 0; j < NJOBS; j++) {
    printf("%-48s %8lu bytes\n", JOBS[j].name, (unsigned long)refs[j].n);
    free(refs[j].b);
  }
  printf("%d threads x %d rounds x %d jobs%s\n", nthreads, rounds, NJOBS,
         inject_race ? " (race injected)" : "");
  printf("%ld passed, %ld failed\n", passed, failed);
  return failed ? 1 : 0;
}
