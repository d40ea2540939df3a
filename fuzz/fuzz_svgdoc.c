/*
** fuzz_svgdoc.c -- the SVG document reader (svgdoc/, over expat) on
** fuzzed documents.  The first byte picks the options (hidden, stroked,
** units, whether <use> subtrees are kept, a small nesting cap, whether the
** stream is given a scan for the ids uses refer to), the second where the
** document is cut in two; the rest is the document.  It is read as a
** stream (the elements handed over per feed, each checked and folded into
** a digest, then given back) in two pieces, and collected in one piece.
** Invariants: an error has a message; every element has a finite CTM,
** subpaths that tile its segments, a tag and its d; at most the caps of
** elements and warnings; and both readings give the same outcome: the same
** message at the same place, or the same elements in the same order with
** the same records, bit for bit (streaming and chunks change nothing).
** The stream builds basic shapes from their numbers, the collected reading
** parses their path data as text (shape_text): the same records and errors.
** The second byte's lowest bit also chooses arcs as conics or cubics, its
** highest strict (without a scan).
*/
#include <string.h>

#include "svgdoc/svgdoc.h"
#include "fuzz_input.h"

static const double UNITS[4] = {0, 1, 96 / 25.4, 96.0 / 72};

/* What the elements handed over come to: their count and an FNV-1a hash
** of each one's place, d, records and kinds, in order. */
typedef struct digest {
  size_t count;
  unsigned long long h;
} digest;

static void fold(digest *g, const void *p, size_t n) {
  const unsigned char *b = p;
  size_t k;
  for (k = 0; k < n; k++) g->h = (g->h ^ b[k]) * 1099511628211ULL;
}

static void fold_bytes(void *g, const char *bytes, size_t n) {
  fold(g, bytes, n);
}

/* Check the elements D holds now and fold them into g. */
static void take(const svgdoc *D, digest *g) {
  size_t i, k, j;
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
    if (next != e->pd.ncubics || e->tag == NULL ||
        (e->shape.kind == SVGDOC_SHAPE_PATH ? e->shape.d == NULL
                                            : e->shape.n < 2 || !e->shape.v))
      fz_fail("svgdoc", NULL, 2, "element %g: %g cubics", (double)i,
              (double)e->pd.ncubics);
    g->count++;
    fold(g, &e->line, sizeof e->line);
    fold(g, &e->col, sizeof e->col);
    fold(g, e->tag, strlen(e->tag));
    if (e->use) fold(g, e->use, strlen(e->use));
    if (e->marker) {                   /* a marker's content: its id, apart */
      fold(g, "#", 1);
      fold(g, e->marker, strlen(e->marker));
    }
    svgdoc_shape_d(&e->shape, fold_bytes, g);
    if (e->pd.ncubics) fold(g, e->pd.cubics, 8 * e->pd.ncubics * sizeof(double));
    if (e->pd.kinds) fold(g, e->pd.kinds, e->pd.ncubics);
  }
}

/* Read data[0 .. n-1] as a stream cut at cut (scan: the whole of it
** scanned first), or collected in one piece; returns the reader (finished
** or failed), the digest in g. */
static svgdoc *read_doc(const svgdoc_options *o, const char *s, size_t n,
                        size_t cut, int scan, int *rc, digest *g) {
  svgdoc *D = svgdoc_new(o);
  g->count = 0, g->h = 14695981039346656037ULL;
  if (D == NULL) fz_fail("svgdoc", NULL, 2, "no memory for a reader", 0, 0);
  if (scan) {
    svgdoc_scan(D, s, cut);
    svgdoc_scan(D, s + cut, n - cut);
  }
  *rc = svgdoc_feed(D, s, cut);
  if (*rc == 0 && o->stream) take(D, g);
  if (*rc == 0) *rc = svgdoc_feed(D, s + cut, n - cut);
  if (*rc == 0 && o->stream) take(D, g);
  if (*rc == 0) *rc = svgdoc_finish(D);
  if (*rc == 0) take(D, g);
  if (svgdoc_nwarnings(D) > SVGDOC_MAX_WARNINGS ||
      (*rc == 0 && g->count != svgdoc_drawn(D)))
    fz_fail("svgdoc", NULL, 2, "%g warnings, %g drawn",
            (double)svgdoc_nwarnings(D), (double)svgdoc_drawn(D));
  return D;
}

/* Is m expat's verdict on the bytes (xml_error in reader.c)? */
static int expat_verdict(const char *m) {
  return strncmp(m, "malformed XML: ", 15) == 0 ||
         strncmp(m, "empty document", 14) == 0;
}

static void same(const svgdoc *A, const svgdoc *B, int rc, const digest *ga,
                 const digest *gb) {
  unsigned long la, ca, lb, cb;
  if (rc != 0) {
    const char *ma = svgdoc_error(A, &la, &ca), *mb = svgdoc_error(B, &lb, &cb);
    /* expat's own verdict on malformed bytes depends on where the input
    ** was cut ("t\0\0" whole: a syntax error at 1:1, "t" then "\0\0": an
    ** invalid token at 1:2; "\t\0" whole: no root element, cut: an invalid
    ** token): both must be expat's verdict, nothing more */
    if (expat_verdict(ma) && expat_verdict(mb)) return;
    if (strcmp(ma, mb) != 0 || la != lb || ca != cb)
      fz_fail("svgdoc: streaming", NULL, 2, "errors differ at lines %g, %g",
              (double)la, (double)lb);
    return;
  }
  if (ga->count != gb->count || ga->h != gb->h)
    fz_fail("svgdoc: streaming", NULL, 2, "%g and %g elements, or they differ",
            (double)ga->count, (double)gb->count);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  svgdoc_options o;
  svgdoc *A, *B;
  const char *s = (const char *)data + 2;
  size_t n, cut;
  int ra, rb, scan;
  digest ga, gb;
  unsigned long line, col;
  if (size < 2) return 0;
  n = size - 2;
  o.arc_tol = (data[0] & 1) ? 1e-12 : 1e-3;
  o.hidden = (data[0] >> 1) & 1;
  o.stroked = (data[0] >> 2) & 1;
  o.painted = (data[1] >> 1) & 1;        /* with cut: bits shared, harmless */
  o.lang = (data[1] >> 2) & 1 ? "de, en-US" : NULL;
  o.unit_px = UNITS[(data[0] >> 3) & 3];
  o.uses = (data[0] >> 5) & 1;
  o.max_depth = (data[0] >> 6) == 3 ? 8 : SVGDOC_MAX_DEPTH;
  scan = (data[0] >> 6) == 2;
  o.max_held = 0;                        /* the default cap */
  /* strict (warnings are errors) where both readings meet them in the
  ** same order: without the scan (its ids pass a missing use over early) */
  o.strict = scan ? 0 : (data[1] >> 7) & 1;
  o.arcs = (data[1] & 1) ? ARCLEN_PD_ARCS_CUBICS : ARCLEN_PD_ARCS_CONICS;
  cut = n ? data[1] * n / 256 : 0;
  o.stream = 1;
  o.shape_text = 0;       /* A's basic shapes built from their numbers */
  A = read_doc(&o, s, n, cut, scan, &ra, &ga);
  if (ra != 0 && svgdoc_error(A, &line, &col) == NULL)
    fz_fail("svgdoc", NULL, 2, "failed without a message", 0, 0);
  o.stream = 0;
  o.shape_text = 1;       /* B's basic shapes through their text: the same */
  B = read_doc(&o, s, n, n, 0, &rb, &gb);
  if (ra != rb)
    fz_fail("svgdoc: streaming", NULL, 2, "outcomes %g and %g", ra, rb);
  same(A, B, ra, &ga, &gb);
  svgdoc_free(A);
  svgdoc_free(B);
  return 0;
}
