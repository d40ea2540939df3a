/*
** fuzz_svgdoc.c -- the SVG document reader (svgdoc/, over expat) on
** fuzzed documents.  The first byte picks the options (hidden, stroked,
** units, whether <use> subtrees are kept, a small nesting cap, arcs as
** conics or cubics), the second where the document is cut in two for
** streaming; the rest is the document.  Invariants: an error has a
** message; a document read has finite CTMs, subpaths that tile their
** segments, at most the caps of elements and warnings; and the same
** document fed in one piece gives the same outcome: the same message at
** the same place, or the same elements with the same records, bit for bit
** (streaming changes nothing).
*/
#include <string.h>

#include "svgdoc/svgdoc.h"
#include "fuzz_input.h"

static const double UNITS[4] = {0, 1, 96 / 25.4, 96.0 / 72};

/* Read data[0 .. n-1], cut at cut; returns the reader (finished or
** failed). */
static svgdoc *read_doc(const svgdoc_options *o, const char *s, size_t n,
                        size_t cut, int *rc) {
  svgdoc *D = svgdoc_new(o);
  if (D == NULL) fz_fail("svgdoc", NULL, 2, "no memory for a reader", 0, 0);
  *rc = svgdoc_feed(D, s, cut);
  if (*rc == 0) *rc = svgdoc_feed(D, s + cut, n - cut);
  if (*rc == 0) *rc = svgdoc_finish(D);
  return D;
}

static void check(const svgdoc *D) {
  size_t i, k, j;
  if (svgdoc_count(D) > SVGDOC_MAX_ELEMENTS ||
      svgdoc_nwarnings(D) > SVGDOC_MAX_WARNINGS)
    fz_fail("svgdoc", NULL, 2, "%g elements, %g warnings",
            (double)svgdoc_count(D), (double)svgdoc_nwarnings(D));
  for (i = 0; i < svgdoc_count(D); i++) {
    const svgdoc_element *e = svgdoc_get(D, i);
    size_t next = 0;
    for (k = 0; k < 6; k++)
      if (!isfinite(e->ctm[k]))
        fz_fail("svgdoc", NULL, 2, "element %g: a CTM not finite", (double)i, 0);
    for (j = 0; j < e->pd.nsubpaths; j++) {
      if (e->pd.subpaths[j].first != next)
        fz_fail("svgdoc", NULL, 2, "element %g: subpath %g", (double)i,
                (double)j);
      next += e->pd.subpaths[j].n;
    }
    if (next != e->pd.ncubics || e->tag == NULL || e->d == NULL)
      fz_fail("svgdoc", NULL, 2, "element %g: %g cubics", (double)i,
              (double)e->pd.ncubics);
  }
}

static void same(const svgdoc *A, const svgdoc *B, int rc) {
  unsigned long la, ca, lb, cb;
  size_t i;
  if (rc != 0) {
    const char *ma = svgdoc_error(A, &la, &ca), *mb = svgdoc_error(B, &lb, &cb);
    if (strcmp(ma, mb) != 0 || la != lb || ca != cb)
      fz_fail("svgdoc: streaming", NULL, 2, "errors differ at lines %g, %g",
              (double)la, (double)lb);
    return;
  }
  if (svgdoc_count(A) != svgdoc_count(B))
    fz_fail("svgdoc: streaming", NULL, 2, "%g and %g elements",
            (double)svgdoc_count(A), (double)svgdoc_count(B));
  for (i = 0; i < svgdoc_count(A); i++) {
    const svgdoc_element *a = svgdoc_get(A, i), *b = svgdoc_get(B, i);
    if (a->pd.ncubics != b->pd.ncubics || a->line != b->line ||
        (a->pd.ncubics && memcmp(a->pd.cubics, b->pd.cubics,
                                 8 * a->pd.ncubics * sizeof(double)) != 0))
      fz_fail("svgdoc: streaming", NULL, 2, "element %g differs", (double)i,
              0.0);
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  svgdoc_options o;
  svgdoc *A, *B;
  const char *s = (const char *)data + 2;
  size_t n, cut;
  int ra, rb;
  unsigned long line, col;
  if (size < 2) return 0;
  n = size - 2;
  o.arc_tol = (data[0] & 1) ? 1e-12 : 1e-3;
  o.hidden = (data[0] >> 1) & 1;
  o.stroked = (data[0] >> 2) & 1;
  o.unit_px = UNITS[(data[0] >> 3) & 3];
  o.uses = (data[0] >> 5) & 1;
  o.max_depth = (data[0] >> 6) == 3 ? 8 : SVGDOC_MAX_DEPTH;
  o.arcs = (data[0] >> 7) ? ARCLEN_PD_ARCS_CUBICS : ARCLEN_PD_ARCS_CONICS;
  cut = n ? data[1] * n / 256 : 0;
  A = read_doc(&o, s, n, cut, &ra);
  if (ra != 0 && svgdoc_error(A, &line, &col) == NULL)
    fz_fail("svgdoc", NULL, 2, "failed without a message", 0, 0);
  if (ra == 0) check(A);
  B = read_doc(&o, s, n, n, &rb);
  if (ra != rb)
    fz_fail("svgdoc: streaming", NULL, 2, "outcomes %g and %g", ra, rb);
  same(A, B, ra);
  svgdoc_free(A);
  svgdoc_free(B);
  return 0;
}
