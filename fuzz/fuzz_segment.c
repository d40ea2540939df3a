/*
** fuzz_segment.c -- segments of four kinds (segment/) on fuzzed points and
** weights.  Invariants, for line, quad and conic (and the dispatch of
** cubics to the default method, to the bit): the length is finite or an
** overflow, at least the chord and at most the control polygon; the pieces
** [0, u] and [u, 1] add up to the whole (by t0/t1 and by segment_sub);
** times are in [0, 1], ascending with the length, and |s(t) - s| <= rtol L;
** point, derivative and tangent are never NaN.
*/
#include "arclen.h"
#include "fuzz_input.h"

#define ULPS (64 * DBL_EPSILON)

static void fail(const char *what, int kind, const double *seg, int dim,
                 const char *fmt, double a, double b) {
  int i, n = arclen_segment_count(kind, dim);
  fprintf(stderr, "INVARIANT FAILED: %s (%s, dim %d): ", what,
          arclen_segment_kind_name(kind), dim);
  fprintf(stderr, fmt, a, b);
  fprintf(stderr, "\nsegment:");
  for (i = 0; i < n; i++) fprintf(stderr, " %.17g", seg[i]);
  fprintf(stderr, "\n");
  abort();
}

/* |P_j - P_i| in long double. */
static long double dist(const double *s, int dim, int i, int j) {
  long double q = 0;
  int k;
  for (k = 0; k < dim; k++) {
    long double d = (long double)s[j * dim + k] - (long double)s[i * dim + k];
    q += d * d;
  }
  return sqrtl(q);
}

static double length(int kind, int dim, const double *s, double t0,
                     double t1, int *rc) {
  arclen_opts o;
  double L;
  arclen_opts_init(&o);
  o.rtol = 1e-14;
  o.t0 = t0;
  o.t1 = t1;
  *rc = arclen_segment_length(kind, dim, s, NULL, &o, &L, NULL);
  return L;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fz_reader rd;
  double c[12], s[ARCLEN_SEG_MAXN], sub[ARCLEN_SEG_MAXN], v[3];
  double L, L1, L2, u, rtol, big = 0, allow, tprev = 0;
  long double chord, poly;
  int kind, dim, rc, npts, i, k;
  fz_init(&rd, data, size);
  kind = (int)(fz_byte(&rd) % 4);
  dim = (fz_byte(&rd) & 1) ? 3 : 2;
  rtol = ldexp(1.0, -(int)fz_range(&rd, 4, 49));
  u = (double)fz_bits(&rd, 2) / 65535.0;
  fz_curve(&rd, dim, c);
  npts = kind == ARCLEN_SEG_LINE ? 2 : kind == ARCLEN_SEG_CUBIC ? 4 : 3;
  for (i = 0; i < npts * dim; i++) s[i] = c[i];
  if (kind == ARCLEN_SEG_CONIC)    /* w in [2^-40, 2^41): all three conics */
    s[3 * dim] = ldexp(1 + fz_byte(&rd) / 256.0, (int)fz_range(&rd, -40, 40));
  for (i = 0; i < npts * dim; i++) big = fmax(big, fabs(s[i]));
  if (arclen_segment_check(kind, dim, s) != ARCLEN_OK)
    fail("check", kind, s, dim, "valid input refused %g %g", 0, 0);

  L = length(kind, dim, s, 0, 1, &rc);
  if (kind == ARCLEN_SEG_CUBIC) {
    arclen_opts o;
    double g;
    arclen_opts_init(&o);
    o.rtol = 1e-14;
    if (arclen_length_gauss(s, dim, &o, &g, NULL) != rc ||
        (rc == ARCLEN_OK && memcmp(&g, &L, sizeof g)))
      fail("cubic dispatch", kind, s, dim, "%a, gauss %a", L, g);
    return 0;                      /* the cubic's own harnesses do the rest */
  }
  if (rc == ARCLEN_EOVERFLOW) return 0;
  if (rc != ARCLEN_OK || !(L >= 0) || !isfinite(L))
    fail("length", kind, s, dim, "code %g, length %g", rc, L);
  chord = dist(s, dim, 0, npts - 1);
  poly = 0;
  for (i = 0; i + 1 < npts; i++) poly += dist(s, dim, i, i + 1);
  /* rounding of the legs (eps |P| each) and of the closed forms */
  allow = ULPS * (double)poly + 8 * DBL_EPSILON * big + 0x1p-1070;
  if (kind == ARCLEN_SEG_CONIC) allow += 4e-15 * (double)poly;
  if ((long double)L < chord - allow || (long double)L > poly + allow)
    fail("bounds", kind, s, dim, "length %.17g outside [chord, polygon] %.17g",
         L, (double)poly);

  /* the pieces add up: by t0/t1, and by the pieces' own control points */
  L1 = length(kind, dim, s, 0, u, &rc);
  if (rc != ARCLEN_OK) fail("length [0, u]", kind, s, dim, "code %g u %g", rc, u);
  L2 = length(kind, dim, s, u, 1, &rc);
  if (rc != ARCLEN_OK) fail("length [u, 1]", kind, s, dim, "code %g u %g", rc, u);
  /* halves: L1 + L2 may round past DBL_MAX where L is just below it */
  if (fabs(L1 / 2 + L2 / 2 - L / 2) > allow)
    fail("additivity", kind, s, dim, "pieces %.17g, whole %.17g", L1 / 2 + L2 / 2, L / 2);
  arclen_segment_sub(kind, dim, s, u, 1, sub);
  if (arclen_segment_check(kind, dim, sub) == ARCLEN_OK) {
    double Ls = length(kind, dim, sub, 0, 1, &rc);
    if (rc == ARCLEN_OK && fabs(Ls - L2) > 2 * allow + 64 * DBL_EPSILON * big)
      fail("sub", kind, s, dim, "sub's length %.17g, range's %.17g", Ls, L2);
  } else if (kind != ARCLEN_SEG_CONIC || u < 1) {
    fail("sub", kind, s, dim, "piece from %g not a valid segment %g", u, 0);
  }

  /* times: ascending, in [0, 1], within rtol L */
  for (k = 0; k <= 8; k++) {
    double goal = L / 8 * k, t, st;
    arclen_opts o;
    arclen_opts_init(&o);
    o.rtol = rtol < ARCLEN_RTOL_MIN ? ARCLEN_RTOL_MIN : rtol;
    rc = arclen_segment_time(kind, dim, s, goal, NULL, &o, &t, NULL);
    if (rc != ARCLEN_OK || !(t >= 0 && t <= 1))
      fail("time", kind, s, dim, "code %g, t %g", rc, t);
    if (t < tprev) fail("time order", kind, s, dim, "t %g after %g", t, tprev);
    tprev = t;
    st = length(kind, dim, s, 0, t, &rc);
    {
      /* t itself is a double: where the speed is huge (a conic of w ~ 1e10
      ** turns its corner within 1e-10 of t) an ulp of t is a length */
      double d[3], sp = 0, grain;
      arclen_segment_derivative(kind, dim, s, t, d);
      for (i = 0; i < dim; i++) sp = fmax(sp, fabs(d[i]));
      grain = 4 * sp * dim * DBL_EPSILON;
      if (fabs(st - goal) > o.rtol * L + 2 * allow + grain)
        fail("time", kind, s, dim, "s(t) %.17g for goal %.17g", st, goal);
    }
    arclen_segment_point(kind, dim, s, t, v);
    for (i = 0; i < dim; i++)
      if (isnan(v[i])) fail("point", kind, s, dim, "NaN at t %g %g", t, 0);
    arclen_segment_derivative(kind, dim, s, t, v);
    for (i = 0; i < dim; i++)
      if (isnan(v[i])) fail("derivative", kind, s, dim, "NaN at t %g %g", t, 0);
    arclen_segment_unit_tangent(kind, dim, s, t, v);
    for (i = 0; i < dim; i++)
      if (isnan(v[i])) fail("tangent", kind, s, dim, "NaN at t %g %g", t, 0);
  }
  return 0;
}
