/*
** fuzz_pathdata.c -- the SVG path-data reader (svg/pathdata.c) on fuzzed
** data.  The first byte picks the arc tolerance and the transform (none,
** or one of a few: scalings from 1e-300 to 1e200, a skew, an anisotropic
** scaling), the rest is the path data.  Invariants: an error kind the
** reader knows, at a position inside the data (or past its end by one),
** none only for the transform's overflow; on success the subpaths tile
** the cubics in order, and every cubic starts where the previous one of
** its subpath ends (bit for bit, as the reader joins them), the first
** where its subpath starts.  The reader is then reused (no leak across
** calls) on the same data: the same result.
*/
#include "svg/pathdata.h"
#include "fuzz_input.h"

static const double TOLS[4] = {1e-12, 1e-15, 1e-3, 0.1};
static const double TRANSFORMS[7][6] = {
  {1, 0, 0, 1, 0, 0}, {2, 0, 0, 2, 1, 1}, {1, 0.5, -0.3, 1.2, 5, -7},
  {1e200, 0, 0, 1e200, 0, 0}, {1e-300, 0, 0, 1e-300, 0, 0},
  {0.001, 0, 0, 1000, 0, 0}, {0, 1, -1, 0, 3, 4}
};

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
      const double *c = pd->cubics + 8 * (s->first + i);
      double x = i ? c[-2] : s->x, y = i ? c[-1] : s->y;
      if (!same(c[0], x) || !same(c[1], y))
        fz_fail("pathdata: a gap", c, 2, "subpath %g, cubic %g", (double)k,
                (double)i);
    }
    next += s->n;
  }
  if (next != pd->ncubics)
    fz_fail("pathdata", NULL, 2, "subpaths hold %g of %g cubics",
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
  arclen_pathdata_init(&pd);
  rc = arclen_pathdata_parse(&pd, d, n, tol, T);
  check(&pd, n, rc);
  ncubics = pd.ncubics;
  if (arclen_pathdata_parse(&pd, d, n, tol, T) != rc || pd.ncubics != ncubics)
    fz_fail("pathdata", NULL, 2, "a second read differs (error %g, %g cubics)",
            rc, (double)ncubics);
  arclen_pathdata_free(&pd);
  return 0;
}
