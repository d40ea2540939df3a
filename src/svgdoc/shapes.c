/*
** shapes.c -- the basic shapes exactly as SVG 2 chapter 10 defines them:
** rect (section 10.2, with the auto and clamping rules of rx and ry),
** circle and ellipse (10.3, 10.4: four arcs from (cx + rx, cy) in the
** positive angle direction), line (10.5), polyline and polygon (10.6,
** 10.7).  A shape is kept as its few numbers (svgdoc_shape) and walked as
** the commands of its path data: into the segment builder (svg/pathdata.c)
** directly, or written as text when its d is asked for.  The text's numbers
** have 17 significant digits, so it reads back to the same doubles and the
** two give the same records bit for bit; its arcs are quarters of
** axis-aligned ellipses from corner to corner, so the reader makes each the
** exact conic through its box's corner (ARCLEN_PD_ARCS_QUARTERS): the
** shape's points rounded once are the only rounding.
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "arclen.h"
#include "svg/decimal.h"
#include "svgdoc/internal.h"

/* ---- the shapes' numbers --------------------------------------------- */

/* rx or ry: 1 with its value, 0 when absent, blank or "auto". */
static int radius(svgdoc *D, unsigned long line, unsigned long col,
                  const char **atts, const char *name, int kind,
                  const svgdoc_viewport *vp, double *v) {
  const char *s = svgdoc_attr(atts, name), *p;
  if (s == NULL) return 0;
  for (p = s; svgdoc_space((unsigned char)*p); p++) {}
  if (strncmp(p, "auto", 4) == 0 && svgdoc_blank(p + 4)) return 0;
  return svgdoc_len_attr(D, line, col, atts, name, kind, vp, v);
}

/* The numbers of points="" into the pool; their count.  An error in them
** (SVG 2 section 10.6: a number that is not one, an odd count) is what a
** renderer passes over: the pairs before it are drawn, with a warning
** (an error under o.strict), as for path data. */
static size_t points(svgdoc *D, unsigned long line, unsigned long col,
                     const char *tag, const char **atts,
                     const double **out) {
  const char *s = svgdoc_attr(atts, "points");
  svgdoc_buffer *b = &D->scratch;
  size_t n, i, count = 0;
  double v;
  double *copy;
  if (s == NULL) s = "";
  n = strlen(s);
  b->len = 0;
  for (i = arclen_decimal_list_start(s, n); i < n;) {
    size_t e = arclen_decimal_list_next(s, n, i, &v);
    if (e == i) {
      svgdoc_lenient(D, line, col, svgdoc_format(D, "<%s>: points: not a "
                     "number at character %lu", tag, (unsigned long)(i + 1)),
                     count >= 2 ? "drawn up to it" : "nothing drawn");
      count -= count % 2;
      break;
    }
    i = e;
    svgdoc_append(D, b, (const char *)&v, sizeof v);
    count++;
  }
  if (count % 2 == 1) {
    svgdoc_lenient(D, line, col, svgdoc_format(D, "<%s>: points: an odd "
                   "number of coordinates", tag),
                   count >= 3 ? "the last one left out" : "nothing drawn");
    count--;
  }
  copy = svgdoc_alloc(D, count * sizeof *copy + 1);
  if (count) memcpy(copy, b->s, count * sizeof *copy);
  *out = copy;
  return count;
}

int svgdoc_shape_get(svgdoc *D, unsigned long line, unsigned long col,
                     const char *tag, const char **atts,
                     const svgdoc_viewport *vp, svgdoc_shape *s) {
  double *v = NULL;
  s->d = NULL;
  s->n = 0;
  s->v = NULL;
  if (strcmp(tag, "path") == 0) {
    s->kind = SVGDOC_SHAPE_PATH;
    s->d = svgdoc_attr(atts, "d");
    return s->d != NULL && !svgdoc_blank(s->d);      /* SVG 2 9.3.9 */
  }
  if (strcmp(tag, "polyline") == 0 || strcmp(tag, "polygon") == 0) {
    s->kind = tag[4] == 'l' ? SVGDOC_SHAPE_POLYLINE : SVGDOC_SHAPE_POLYGON;
    s->n = points(D, line, col, tag, atts, &s->v);
    return s->n >= 2;
  }
  v = svgdoc_alloc(D, 6 * sizeof *v);
  s->v = v;
  if (strcmp(tag, "rect") == 0) {
    double x = 0, y = 0, w = 0, h = 0, rx = 0, ry = 0;
    int hx, hy;
    svgdoc_len_attr(D, line, col, atts, "x", 'x', vp, &x);
    svgdoc_len_attr(D, line, col, atts, "y", 'y', vp, &y);
    svgdoc_len_attr(D, line, col, atts, "width", 'x', vp, &w);
    svgdoc_len_attr(D, line, col, atts, "height", 'y', vp, &h);
    /* a negative size is taken as not given: 0, the rect not drawn; a
    ** negative radius as auto */
    if (svgdoc_negative(D, line, col, tag, "width", w, "not drawn") ||
        svgdoc_negative(D, line, col, tag, "height", h, "not drawn"))
      return 0;
    hx = radius(D, line, col, atts, "rx", 'x', vp, &rx);
    hy = radius(D, line, col, atts, "ry", 'y', vp, &ry);
    if (hx && svgdoc_negative(D, line, col, tag, "rx", rx, "taken as auto"))
      hx = 0;
    if (hy && svgdoc_negative(D, line, col, tag, "ry", ry, "taken as auto"))
      hy = 0;
    if (w == 0 || h == 0) return 0;
    /* auto: the other radius, else 0; then each clamped to half the side */
    if (!hx) rx = hy ? ry : 0;
    if (!hy) ry = hx ? rx : 0;
    if (rx > w / 2) rx = w / 2;
    if (ry > h / 2) ry = h / 2;
    s->kind = SVGDOC_SHAPE_RECT;
    s->n = 6;
    v[0] = x, v[1] = y, v[2] = w, v[3] = h, v[4] = rx, v[5] = ry;
    return 1;
  }
  if (strcmp(tag, "circle") == 0 || strcmp(tag, "ellipse") == 0) {
    double cx = 0, cy = 0, rx = 0, ry = 0;
    svgdoc_len_attr(D, line, col, atts, "cx", 'x', vp, &cx);
    svgdoc_len_attr(D, line, col, atts, "cy", 'y', vp, &cy);
    if (tag[0] == 'c') {            /* a negative r is taken as 0 */
      svgdoc_len_attr(D, line, col, atts, "r", 'o', vp, &rx);
      if (svgdoc_negative(D, line, col, tag, "r", rx, "not drawn")) return 0;
      ry = rx;
    } else {                        /* a negative radius is taken as auto */
      int hx = radius(D, line, col, atts, "rx", 'x', vp, &rx);
      int hy = radius(D, line, col, atts, "ry", 'y', vp, &ry);
      if (hx && svgdoc_negative(D, line, col, tag, "rx", rx,
                                hy && ry >= 0 ? "taken as auto" : "not drawn"))
        hx = 0;
      if (hy && svgdoc_negative(D, line, col, tag, "ry", ry,
                                hx ? "taken as auto" : "not drawn"))
        hy = 0;
      if (!hx) rx = hy ? ry : 0;             /* auto: the other one */
      if (!hy) ry = hx ? rx : 0;
    }
    if (rx == 0 || ry == 0) return 0;
    s->kind = SVGDOC_SHAPE_ELLIPSE;
    s->n = 4;
    v[0] = cx, v[1] = cy, v[2] = rx, v[3] = ry;
    return 1;
  }
  /* line */
  v[0] = v[1] = v[2] = v[3] = 0;
  svgdoc_len_attr(D, line, col, atts, "x1", 'x', vp, &v[0]);
  svgdoc_len_attr(D, line, col, atts, "y1", 'y', vp, &v[1]);
  svgdoc_len_attr(D, line, col, atts, "x2", 'x', vp, &v[2]);
  svgdoc_len_attr(D, line, col, atts, "y2", 'y', vp, &v[3]);
  s->kind = SVGDOC_SHAPE_LINE;
  s->n = 4;
  return 1;
}

/* ---- the walk: a shape's commands ------------------------------------ */

typedef void (*command_fn)(void *ctx, char cmd, const double *a);

/* A quarter arc of radii rx, ry to (x, y), positive angle direction. */
static void quarter(command_fn f, void *ctx, double rx, double ry, double x,
                    double y) {
  double a[7];
  a[0] = rx, a[1] = ry, a[2] = 0, a[3] = 0, a[4] = 1, a[5] = x, a[6] = y;
  f(ctx, 'A', a);
}

static void two(command_fn f, void *ctx, char cmd, double x, double y) {
  double a[2];
  a[0] = x, a[1] = y;
  f(ctx, cmd, a);
}

static void one(command_fn f, void *ctx, char cmd, double x) {
  f(ctx, cmd, &x);
}

/* The absolute commands of s's path data, in order, to f (not a path). */
static void walk(const svgdoc_shape *s, command_fn f, void *ctx) {
  const double *v = s->v;
  size_t k;
  switch (s->kind) {
  case SVGDOC_SHAPE_RECT: {
    double x = v[0], y = v[1], w = v[2], h = v[3], rx = v[4], ry = v[5];
    if (rx == 0 || ry == 0) {
      two(f, ctx, 'M', x, y);
      one(f, ctx, 'H', x + w);
      one(f, ctx, 'V', y + h);
      one(f, ctx, 'H', x);
    } else {                           /* SVG 2 section 10.2, steps 1-10 */
      two(f, ctx, 'M', x + rx, y);
      one(f, ctx, 'H', x + w - rx);
      quarter(f, ctx, rx, ry, x + w, y + ry);
      one(f, ctx, 'V', y + h - ry);
      quarter(f, ctx, rx, ry, x + w - rx, y + h);
      one(f, ctx, 'H', x + rx);
      quarter(f, ctx, rx, ry, x, y + h - ry);
      one(f, ctx, 'V', y + ry);
      quarter(f, ctx, rx, ry, x + rx, y);
    }
    f(ctx, 'Z', NULL);
    break;
  }
  case SVGDOC_SHAPE_ELLIPSE: {
    double cx = v[0], cy = v[1], rx = v[2], ry = v[3];
    two(f, ctx, 'M', cx + rx, cy);
    quarter(f, ctx, rx, ry, cx, cy + ry);
    quarter(f, ctx, rx, ry, cx - rx, cy);
    quarter(f, ctx, rx, ry, cx, cy - ry);
    quarter(f, ctx, rx, ry, cx + rx, cy);
    f(ctx, 'Z', NULL);
    break;
  }
  case SVGDOC_SHAPE_LINE:
    two(f, ctx, 'M', v[0], v[1]);
    two(f, ctx, 'L', v[2], v[3]);
    break;
  default:                                   /* polyline, polygon */
    two(f, ctx, 'M', v[0], v[1]);
    for (k = 2; k + 1 < s->n; k += 2) two(f, ctx, 'L', v[k], v[k + 1]);
    if (s->kind == SVGDOC_SHAPE_POLYGON) f(ctx, 'Z', NULL);
    break;
  }
}

/* ---- the walk as text ------------------------------------------------ */

typedef struct text {
  void (*put)(void *ctx, const char *bytes, size_t n);
  void *ctx;
  int first, spaced_m;      /* polylines and polygons write "M x y" */
} text;

static void text_command(void *p, char cmd, const double *a) {
  text *t = p;
  int k, count = cmd == 'A' ? 7 : cmd == 'Z' ? 0 : cmd == 'M' || cmd == 'L' ? 2 : 1;
  char num[32];
  if (!t->first) t->put(t->ctx, " ", 1);
  t->first = 0;
  t->put(t->ctx, &cmd, 1);
  if (cmd == 'M' && t->spaced_m) t->put(t->ctx, " ", 1);
  for (k = 0; k < count; k++) {
    if (k > 0) t->put(t->ctx, " ", 1);
    svgdoc_num(num, a[k]);             /* the flags 0 0 1 as "0 0 1" */
    t->put(t->ctx, num, strlen(num));
  }
}

void svgdoc_shape_d(const svgdoc_shape *s,
                    void (*put)(void *ctx, const char *bytes, size_t n),
                    void *ctx) {
  text t;
  if (s->kind == SVGDOC_SHAPE_PATH) {
    put(ctx, s->d, strlen(s->d));
    return;
  }
  t.put = put, t.ctx = ctx, t.first = 1;
  t.spaced_m = s->kind == SVGDOC_SHAPE_POLYLINE ||
               s->kind == SVGDOC_SHAPE_POLYGON;
  walk(s, text_command, &t);
}

typedef struct counted {
  char *at;
  size_t n;
} counted;

static void count_bytes(void *p, const char *bytes, size_t n) {
  (void)bytes;
  ((counted *)p)->n += n;
}

static void copy_bytes(void *p, const char *bytes, size_t n) {
  counted *c = p;
  memcpy(c->at + c->n, bytes, n);
  c->n += n;
}

const char *svgdoc_shape_text(svgdoc *D, const svgdoc_shape *s) {
  counted c = {NULL, 0};
  if (s->kind == SVGDOC_SHAPE_PATH) return s->d;
  svgdoc_shape_d(s, count_bytes, &c);
  c.at = svgdoc_alloc(D, c.n + 1);
  c.n = 0;
  svgdoc_shape_d(s, copy_bytes, &c);
  c.at[c.n] = '\0';
  return c.at;
}

/* ---- the walk into segments ------------------------------------------ */

typedef struct build {
  arclen_pathbuild b;
  int finite;               /* every number so far finite */
} build;

/* A number beyond the doubles (x + width overflowing) is not built: the
** text route reports it as the text's reader always has. */
static void build_command(void *p, char cmd, const double *a) {
  build *t = p;
  int k, count = cmd == 'A' ? 7 : cmd == 'Z' ? 0 : cmd == 'M' || cmd == 'L' ? 2 : 1;
  for (k = 0; k < count; k++)
    if (!isfinite(a[k])) t->finite = 0;
  if (t->finite) arclen_pathbuild_add(&t->b, cmd, a);
}

/* Is the length of pd's lines and conics beyond the doubles?  Only when
** their control polygon's is (a curve is no longer than its control
** polygon) are the conics measured (exactly, Carlson's integrals). */
static int length_overflows(const arclen_pathdata *pd) {
  double polygon = 0, length = 0;
  size_t k;
  for (k = 0; k < pd->ncubics; k++) {
    const double *c = pd->cubics + ARCLEN_PD_STRIDE * k;
    polygon += hypot(c[2] - c[0], c[3] - c[1]);
    if (pd->kinds[k] != ARCLEN_PD_LINE)
      polygon += hypot(c[4] - c[2], c[5] - c[3]);
  }
  if (polygon <= DBL_MAX) return 0;
  for (k = 0; k < pd->ncubics; k++) {
    const double *c = pd->cubics + ARCLEN_PD_STRIDE * k;
    double len;
    if (pd->kinds[k] == ARCLEN_PD_LINE) len = hypot(c[2] - c[0], c[3] - c[1]);
    else if (arclen_conic_length(c, c[6], &len, NULL) != ARCLEN_OK) return 1;
    length += len;
  }
  return !(length <= DBL_MAX);
}

int svgdoc_shape_parse(svgdoc *D, arclen_pathdata *pd, const svgdoc_shape *s,
                       const double *T, const char **d) {
  int rc = ARCLEN_PD_EMPTY, built = 0;
  *d = s->d;
  if (D->o.arcs == ARCLEN_PD_ARCS_CUBICS) pd->arcs = ARCLEN_PD_ARCS_CUBICS;
  else if (s->kind == SVGDOC_SHAPE_PATH) pd->arcs = ARCLEN_PD_ARCS_CONICS;
  else pd->arcs = ARCLEN_PD_ARCS_QUARTERS;     /* this file's own data */
  if (s->kind != SVGDOC_SHAPE_PATH && !D->o.shape_text) {
    build t;
    arclen_pathbuild_start(&t.b, pd, D->o.arc_tol, T);
    t.finite = 1;
    walk(s, build_command, &t);
    rc = arclen_pathbuild_finish(&t.b);
    built = t.finite && rc == ARCLEN_PD_OK;
  }
  /* a path; or the text of a shape the builder refused, for the error's
  ** place in the text as the message quotes it */
  if (!built) {
    if (*d == NULL) *d = svgdoc_shape_text(D, s);
    rc = arclen_pathdata_parse(pd, *d, strlen(*d), D->o.arc_tol, T);
  }
  /* a basic shape (lines and conics only) whose length is beyond the
  ** doubles is out of range as its cubics were: the reader names its
  ** size attributes (reader.c, shape_size_message) */
  if (rc == ARCLEN_PD_OK && pd->arcs == ARCLEN_PD_ARCS_QUARTERS &&
      length_overflows(pd)) {
    pd->err.kind = rc = ARCLEN_PD_ARC;
    pd->err.arc = ARCLEN_PD_ARC_OVERFLOW;
    pd->err.pos = 0;
  }
  if (rc != ARCLEN_PD_OK && *d == NULL) *d = svgdoc_shape_text(D, s);
  return rc;
}
