/*
** fuzz_pathdata.c -- the SVG path-data reader (svg/pathdata.c) on fuzzed
** data.  The first byte picks the arc tolerance, the transform (none, or
** one of a few: scalings from 1e-300 to 1e200, a skew, an anisotropic
** scaling, a singular projection) and what arcs become (conics, cubics,
** or the basic shapes' quarters); the rest is the path data.  Invariants:
** an error kind the reader knows, at a position inside the data (or past
** its end by one), none only for the transform's overflow; on success the
** subpaths tile the segments in order; every record is of a known kind
** (cubics only under ARCLEN_PD_ARCS_CUBICS) with its tail zero, a conic's
** weight finite and positive and its control points not flat; every
** segment starts where the previous one of its subpath ends (bit for bit,
** as the reader joins them), the first where its subpath starts.  The
** reader is then reused (no leak across calls) on the same data: the same
** result.
*/
#include "arclen.h"
#include "svg/pathdata.h"
#include "fuzz_input.h"

static const double TOLS[4] = {1e-12, 1e-15, 1e-3, 0.1};
static const double TRANSFORMS[7][6] = {
  {1, 0, 0, 1, 0, 0}, {2, 0, 0, 2, 1, 1}, {1, 0.5, -0.3, 1.2, 5, -7},
  {1e200, 0, 0, 1e200, 0, 0}, {1e-300, 0, 0, 1e-300, 0, 0},
  {0.001, 0, 0, 1000, 0, 0}, {0, 1, -1, 0, 3, 4}
};
/* a singular map (x + y, 0): it folds conics */
static const double FOLD[6] = {1, 0, 1, 0, 0, 0};
static const int MODES[4] = {ARCLEN_PD_ARCS_CONICS, ARCLEN_PD_ARCS_CUBICS,
                             ARCLEN_PD_ARCS_QUARTERS, ARCLEN_PD_ARCS_CONICS};

/* The numbers of a record of kind k; 0 for an unknown kind. */
static int count_of(unsigned char k) {
  switch (k) {
    case ARCLEN_PD_LINE: return 4;
    case ARCLEN_PD_QUAD: return 6;
    case ARCLEN_PD_CUBIC: return 8;
    case ARCLEN_PD_CONIC: return 7;
    default: return 0;
  }
}

/* a and b equal, or both NaN (a line from an infinite point). */
static int same(double a, double b) {
  return a == b || (a != a && b != b);
}

static void check(const arclen_pathdata *pd, size_t n, int rc) {
  size_t k, i, next = 0;
  if (rc < ARCLEN_PD_OK || rc > ARCLEN_PD_NOMEM || rc != pd->err.kind)
    fz_fail("pathdata", NULL, 2, "error kind %g (err.kind %g)", rc,
            pd->err.kind);
  if (rc != ARCLEN_PD_OK) {
    if (rc == ARCLEN_PD_TRANSFORM ? pd->err.pos != 0
                                  : pd->err.pos < 1 || pd->err.pos > n + 1)
      fz_fail("pathdata", NULL, 2, "error %g at position %g", rc,
              (double)pd->err.pos);
    return;
  }
  for (k = 0; k < pd->nsubpaths; k++) {
    const arclen_subpath *s = &pd->subpaths[k];
    if (s->first != next)
      fz_fail("pathdata", NULL, 2, "subpath %g starts at cubic %g",
              (double)k, (double)s->first);
    for (i = 0; i < s->n; i++) {
      size_t r = s->first + i;
      const double *c = pd->cubics + ARCLEN_PD_STRIDE * r;
      unsigned char kind = pd->kinds[r];
      int m = count_of(kind), j;
      double x = s->x, y = s->y;
      if (m == 0 || (pd->arcs == ARCLEN_PD_ARCS_CUBICS && kind != ARCLEN_PD_CUBIC))
        fz_fail("pathdata: a bad kind", c, 2, "record %g, kind %g", (double)r,
                (double)kind);
      for (j = m; j < ARCLEN_PD_STRIDE; j++)
        if (c[j] != 0)
          fz_fail("pathdata: a tail not zero", c, 2, "record %g", (double)r, 0);
      if (kind == ARCLEN_PD_CONIC &&
          (!(c[6] > 0 && c[6] <= DBL_MAX) || arclen_conic_degenerate(c)))
        fz_fail("pathdata: a bad conic", c, 2, "record %g, w %g", (double)r,
                c[6]);
      if (i > 0) {                   /* the previous record's last point */
        const double *p = c - ARCLEN_PD_STRIDE;
        int e = pd->kinds[r - 1] == ARCLEN_PD_CONIC ? 4
                                                    : count_of(pd->kinds[r - 1]) - 2;
        x = p[e];
        y = p[e + 1];
      }
      if (!same(c[0], x) || !same(c[1], y))
        fz_fail("pathdata: a gap", c, 2, "subpath %g, segment %g", (double)k,
                (double)i);
    }
    next += s->n;
  }
  if (next != pd->ncubics)
    fz_fail("pathdata", NULL, 2, "subpaths hold %g of %g segments",
            (double)next, (double)pd->ncubics);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  arclen_pathdata pd;
  const char *d = (const char *)data + 1;
  const double *T = NULL;
  double tol;
  size_t n, ncubics;
  unsigned pick;
  int rc;
  if (size < 1) return 0;
  pick = data[0];
  n = size - 1;
  tol = TOLS[pick & 3];
  if ((pick >> 2) % 8 != 7) T = TRANSFORMS[(pick >> 2) % 8];
  if ((pick >> 5) == 7) T = FOLD;
  arclen_pathdata_init(&pd);
  pd.arcs = MODES[(pick >> 5) & 3];
  rc = arclen_pathdata_parse(&pd, d, n, tol, T);
  check(&pd, n, rc);
  ncubics = pd.ncubics;
  if (arclen_pathdata_parse(&pd, d, n, tol, T) != rc || pd.ncubics != ncubics)
    fz_fail("pathdata", NULL, 2, "a second read differs (error %g, %g segments)",
            rc, (double)ncubics);
  arclen_pathdata_free(&pd);
  return 0;
}
