/*
** shapes.c -- the basic shapes as path data, exactly as SVG 2 chapter 10
** defines them: rect (section 10.2, with the auto and clamping rules of
** rx and ry), circle and ellipse (10.3, 10.4: four arcs from (cx + rx, cy)
** in the positive angle direction), line (10.5), polyline and polygon
** (10.6, 10.7).  Numbers are written with 17 significant digits, so the
** path data reads back to the same doubles; its arcs are quarters of
** axis-aligned ellipses from corner to corner, so the reader makes each
** the exact conic through its box's corner (ARCLEN_PD_ARCS_QUARTERS):
** the shape's points rounded once are the only rounding.
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "arclen.h"
#include "svg/decimal.h"
#include "svgdoc/internal.h"

/* Append the formatted numbers of fmt ("%n" per number, other bytes as
** they are) to b. */
static void put(svgdoc *D, svgdoc_buffer *b, const char *fmt, int count,
                const double *v) {
  char num[32];
  int k = 0;
  for (; *fmt; fmt++) {
    if (*fmt == '%' && fmt[1] == 'n' && k < count) {
      svgdoc_num(num, v[k++]);
      svgdoc_append(D, b, num, strlen(num));
      fmt++;
    } else {
      svgdoc_append(D, b, fmt, 1);
    }
  }
}

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

static const char *points_data(svgdoc *D, unsigned long line,
                               unsigned long col, const char **atts,
                               int close) {
  const char *s = svgdoc_attr(atts, "points");
  svgdoc_buffer *b = &D->scratch;
  size_t n, i, count = 0;
  double v[2], first[2] = {0, 0};
  char num[2][32];
  if (s == NULL) s = "";
  n = strlen(s);
  b->len = 0;
  for (i = arclen_decimal_list_start(s, n); i < n;) {
    size_t e = arclen_decimal_list_next(s, n, i, &v[count % 2]);
    if (e == i)
      svgdoc_fail(D, line, col, "points: not a number at character %lu",
                  (unsigned long)(i + 1));
    i = e;
    count++;
    if (count == 2) first[0] = v[0], first[1] = v[1];
    else if (count % 2 == 0) put(D, b, " L%n %n", 2, v);
  }
  if (count % 2 == 1)      /* SVG 2 section 10.6: an error */
    svgdoc_fail(D, line, col, "points: an odd number of coordinates");
  if (count < 2) return NULL;
  svgdoc_num(num[0], first[0]);
  svgdoc_num(num[1], first[1]);
  return svgdoc_format(D, "M %s %s%.*s%s", num[0], num[1], (int)b->len,
                       b->len ? b->s : "", close ? " Z" : "");
}

const char *svgdoc_shape_data(svgdoc *D, unsigned long line,
                              unsigned long col, const char *tag,
                              const char **atts, const svgdoc_viewport *vp) {
  svgdoc_buffer *b = &D->scratch;
  b->len = 0;
  if (strcmp(tag, "path") == 0) {
    const char *d = svgdoc_attr(atts, "d");
    if (d == NULL || svgdoc_blank(d)) return NULL;  /* SVG 2 9.3.9 */
    return d;
  }
  if (strcmp(tag, "rect") == 0) {
    double x = 0, y = 0, w = 0, h = 0, rx = 0, ry = 0;
    int hx, hy;
    svgdoc_len_attr(D, line, col, atts, "x", 'x', vp, &x);
    svgdoc_len_attr(D, line, col, atts, "y", 'y', vp, &y);
    svgdoc_len_attr(D, line, col, atts, "width", 'x', vp, &w);
    svgdoc_nonneg(D, line, col, w, "width");
    svgdoc_len_attr(D, line, col, atts, "height", 'y', vp, &h);
    svgdoc_nonneg(D, line, col, h, "height");
    hx = radius(D, line, col, atts, "rx", 'x', vp, &rx);
    hy = radius(D, line, col, atts, "ry", 'y', vp, &ry);
    if (hx) svgdoc_nonneg(D, line, col, rx, "rx");
    if (hy) svgdoc_nonneg(D, line, col, ry, "ry");
    if (w == 0 || h == 0) return NULL;
    /* auto: the other radius, else 0; then each clamped to half the side */
    if (!hx) rx = hy ? ry : 0;
    if (!hy) ry = hx ? rx : 0;
    if (rx > w / 2) rx = w / 2;
    if (ry > h / 2) ry = h / 2;
    if (rx == 0 || ry == 0) {
      double v[5];
      v[0] = x, v[1] = y, v[2] = x + w, v[3] = y + h, v[4] = x;
      put(D, b, "M%n %n H%n V%n H%n Z", 5, v);
    } else {
      double v[16];
      v[0] = x + rx, v[1] = y, v[2] = x + w - rx;
      v[3] = rx, v[4] = ry, v[5] = x + w, v[6] = y + ry;
      v[7] = y + h - ry;
      v[8] = rx, v[9] = ry, v[10] = x + w - rx, v[11] = y + h;
      v[12] = x + rx;
      put(D, b, "M%n %n H%n A%n %n 0 0 1 %n %n V%n A%n %n 0 0 1 %n %n H%n",
          13, v);
      v[0] = rx, v[1] = ry, v[2] = x, v[3] = y + h - ry;
      v[4] = y + ry;
      v[5] = rx, v[6] = ry, v[7] = x + rx, v[8] = y;
      put(D, b, " A%n %n 0 0 1 %n %n V%n A%n %n 0 0 1 %n %n Z", 9, v);
    }
  } else if (strcmp(tag, "circle") == 0 || strcmp(tag, "ellipse") == 0) {
    double cx = 0, cy = 0, rx = 0, ry = 0, v[14];
    int k;
    svgdoc_len_attr(D, line, col, atts, "cx", 'x', vp, &cx);
    svgdoc_len_attr(D, line, col, atts, "cy", 'y', vp, &cy);
    if (tag[0] == 'c') {
      svgdoc_len_attr(D, line, col, atts, "r", 'o', vp, &rx);
      ry = svgdoc_nonneg(D, line, col, rx, "r");
    } else {
      int hx = radius(D, line, col, atts, "rx", 'x', vp, &rx);
      int hy = radius(D, line, col, atts, "ry", 'y', vp, &ry);
      if (hx) svgdoc_nonneg(D, line, col, rx, "rx");
      if (hy) svgdoc_nonneg(D, line, col, ry, "ry");
      if (!hx) rx = hy ? ry : 0;             /* auto: the other one */
      if (!hy) ry = hx ? rx : 0;
    }
    if (rx == 0 || ry == 0) return NULL;
    v[0] = cx + rx, v[1] = cy;
    for (k = 0; k < 4; k++) v[2 + 3 * k] = rx, v[3 + 3 * k] = ry;
    put(D, b, "M%n %n", 2, v);
    {
      double e[8];
      e[0] = cx, e[1] = cy + ry, e[2] = cx - rx, e[3] = cy;
      e[4] = cx, e[5] = cy - ry, e[6] = cx + rx, e[7] = cy;
      for (k = 0; k < 4; k++) {
        double a[4];
        a[0] = rx, a[1] = ry, a[2] = e[2 * k], a[3] = e[2 * k + 1];
        put(D, b, " A%n %n 0 0 1 %n %n", 4, a);
      }
    }
    svgdoc_append(D, b, " Z", 2);
  } else if (strcmp(tag, "line") == 0) {
    double v[4] = {0, 0, 0, 0};
    svgdoc_len_attr(D, line, col, atts, "x1", 'x', vp, &v[0]);
    svgdoc_len_attr(D, line, col, atts, "y1", 'y', vp, &v[1]);
    svgdoc_len_attr(D, line, col, atts, "x2", 'x', vp, &v[2]);
    svgdoc_len_attr(D, line, col, atts, "y2", 'y', vp, &v[3]);
    put(D, b, "M%n %n L%n %n", 4, v);
  } else if (strcmp(tag, "polyline") == 0) {
    return points_data(D, line, col, atts, 0);
  } else {
    return points_data(D, line, col, atts, 1);
  }
  return svgdoc_strdup(D, b->s, b->len);
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

int svgdoc_shape_parse(svgdoc *D, arclen_pathdata *pd, const char *tag,
                       const char *d, const double *T) {
  int rc;
  if (D->o.arcs == ARCLEN_PD_ARCS_CUBICS) pd->arcs = ARCLEN_PD_ARCS_CUBICS;
  else if (strcmp(tag, "path") == 0) pd->arcs = ARCLEN_PD_ARCS_CONICS;
  else pd->arcs = ARCLEN_PD_ARCS_QUARTERS;     /* this file's own data */
  rc = arclen_pathdata_parse(pd, d, strlen(d), D->o.arc_tol, T);
  /* a basic shape (lines and conics only) whose length is beyond the
  ** doubles is out of range as its cubics were: the reader names its
  ** size attributes (reader.c, shape_size_message) */
  if (rc == ARCLEN_PD_OK && pd->arcs == ARCLEN_PD_ARCS_QUARTERS &&
      length_overflows(pd)) {
    pd->err.kind = rc = ARCLEN_PD_ARC;
    pd->err.arc = ARCLEN_PD_ARC_OVERFLOW;
    pd->err.pos = 0;
  }
  return rc;
}
