/*
** marker.c -- markers (SVG 2 section 11.6): the marker properties, a
** shape's vertices and their orient="auto" angles, and the placement of
** each instance of a marker's content.  The vertices are the path's
** commands' (a path read again here, command by command: an arc is one
** segment with one vertex at each end, although the reader draws it as
** up to four conics; a Z whose line has zero length is still a segment).
*/
#include <math.h>
#include <string.h>

#include "svg/decimal.h"
#include "svgdoc/marker.h"

#define PI 3.14159265358979323846

/* ---- the properties --------------------------------------------------- */

const char *svgdoc_marker_ref(svgdoc *D, const char *value,
                              const char *parent) {
  const char *s = value, *e;
  char q = 0;
  if (s == NULL) return parent;
  if (strcmp(s, "none") == 0 || strcmp(s, "initial") == 0) return NULL;
  /* url( <string> | <url-token> ) with a same-document #id (CSS Values 4
  ** section 4.5): anything else is an invalid value, ignored */
  if (strncmp(s, "url(", 4) != 0 && strncmp(s, "URL(", 4) != 0) return parent;
  s += 4;
  while (svgdoc_space((unsigned char)*s)) s++;
  if (*s == '"' || *s == '\'') q = *s++;
  if (*s != '#') return parent;
  s++;
  for (e = s; *e && *e != ')' && (q ? *e != q : !svgdoc_space((unsigned char)*e));
       e++) {}
  if (e == s) return parent;
  {
    const char *t = e + (q && *e == q);
    while (svgdoc_space((unsigned char)*t)) t++;
    if (*t != ')' || t[1] != '\0') return parent;
  }
  return svgdoc_strdup(D, s, (size_t)(e - s));
}

double svgdoc_stroke_width(const char *value, double parent,
                           const svgdoc_viewport *vp) {
  double v;
  if (value == NULL) return parent;
  if (strcmp(value, "initial") == 0) return 1;      /* SVG 2 13.5.2 */
  /* a percentage of the viewport's diagonal / sqrt(2), as radii */
  if (!svgdoc_length_try(value, 'o', vp, &v) || v < 0) return parent;
  return v;
}

/* ---- a shape's segments, as the marker rules see them ------------------ */

/* A subpath's start (move), or a segment: its end, the directions at its
** start and end (the first non-zero derivative there), zero length. */
typedef struct mseg {
  int move, zero, close;
  double x, y, d0x, d0y, d1x, d1y;
} mseg;

typedef struct walker {
  svgdoc *D;
  size_t n, room;
  double cx, cy, sx, sy;         /* the current point, the subpath's start */
  int open;                      /* a subpath is open (not after Z) */
} walker;

static mseg *next_rec(walker *w) {
  svgdoc_buffer *b = &w->D->marker_buf;
  if ((w->n + 1) * sizeof(mseg) > b->room)
    svgdoc_reserve(w->D, b, 2 * (w->n + 1) * sizeof(mseg));
  return (mseg *)(void *)b->s + w->n++;
}

static void move_to(walker *w, double x, double y) {
  mseg *r = next_rec(w);
  memset(r, 0, sizeof *r);
  r->move = 1, r->x = x, r->y = y;
  w->cx = w->sx = x, w->cy = w->sy = y;
  w->open = 1;
}

/* A segment from the current point to (x, y) with its end directions. */
static void seg_to(walker *w, double x, double y, double d0x, double d0y,
                   double d1x, double d1y, int zero, int close) {
  mseg *r;
  if (!w->open) move_to(w, w->cx, w->cy);   /* drawing after Z */
  r = next_rec(w);
  r->move = 0, r->zero = zero, r->close = close;
  r->x = x, r->y = y, r->d0x = d0x, r->d0y = d0y, r->d1x = d1x, r->d1y = d1y;
  w->cx = x, w->cy = y;
}

static void line_to(walker *w, double x, double y) {
  double dx = x - w->cx, dy = y - w->cy;
  seg_to(w, x, y, dx, dy, dx, dy, dx == 0 && dy == 0, 0);
}

/* The first of the differences that is not zero (all zero: a point). */
static void first_dir(const double *p, int k, double *dx, double *dy) {
  int j;
  for (j = 0; j < k; j++) {
    *dx = p[4 * j + 2] - p[4 * j], *dy = p[4 * j + 3] - p[4 * j + 1];
    if (*dx != 0 || *dy != 0) return;
  }
}

/* A Bezier curve of degree deg (2 or 3) with control points P: the
** direction at t = 0 is the first of P1-P0, P2-P0, P3-P0 that is not zero,
** at t = 1 the first of Pn-Pn-1, Pn-Pn-2, ... (SVG 2 9.5: the direction of
** the first non-zero derivative). */
static void curve_to(walker *w, const double *P, int deg) {
  double a[12], b[12], d0x = 0, d0y = 0, d1x = 0, d1y = 0;
  int j, zero = 1;
  for (j = 1; j <= deg; j++) {
    a[4 * (j - 1)] = P[0], a[4 * (j - 1) + 1] = P[1];
    a[4 * (j - 1) + 2] = P[2 * j], a[4 * (j - 1) + 3] = P[2 * j + 1];
    b[4 * (j - 1)] = P[2 * (deg - j)], b[4 * (j - 1) + 1] = P[2 * (deg - j) + 1];
    b[4 * (j - 1) + 2] = P[2 * deg], b[4 * (j - 1) + 3] = P[2 * deg + 1];
    if (P[2 * j] != P[0] || P[2 * j + 1] != P[1]) zero = 0;
  }
  first_dir(a, deg, &d0x, &d0y);
  first_dir(b, deg, &d1x, &d1y);
  seg_to(w, P[2 * deg], P[2 * deg + 1], d0x, d0y, d1x, d1y, zero, 0);
}

/* An elliptical arc to (x, y) (SVG 2 9.5.1 and the centre parametrisation
** of SVG 1.1 F.6.5/F.6.6): its tangents at both ends.  Equal ends omit it;
** a zero radius makes it a line. */
static void arc_to(walker *w, double rx, double ry, double phi, int fa,
                   int fs, double x, double y) {
  double c, s, hx, hy, x1, y1, L, num, den, k, cx, cy, t1, t2, dt;
  double e0x, e0y, e1x, e1y, sg = fs ? 1 : -1;
  rx = fabs(rx), ry = fabs(ry);
  if (x == w->cx && y == w->cy) return;
  if (rx == 0 || ry == 0) {
    line_to(w, x, y);
    return;
  }
  phi = fmod(phi, 360) * (PI / 180);
  c = cos(phi), s = sin(phi);
  hx = (w->cx - x) / 2, hy = (w->cy - y) / 2;
  x1 = c * hx + s * hy, y1 = -s * hx + c * hy;
  L = (x1 / rx) * (x1 / rx) + (y1 / ry) * (y1 / ry);
  if (L > 1) rx *= sqrt(L), ry *= sqrt(L);
  num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
  den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
  k = num > 0 && den > 0 ? sqrt(num / den) : 0;
  if (fa == fs) k = -k;
  cx = k * rx * y1 / ry, cy = -k * ry * x1 / rx;
  t1 = atan2((y1 - cy) / ry, (x1 - cx) / rx);
  t2 = atan2((-y1 - cy) / ry, (-x1 - cx) / rx);
  dt = t2 - t1;
  if (!fs && dt > 0) dt -= 2 * PI;
  if (fs && dt < 0) dt += 2 * PI;
  /* d/dtheta of R(phi) (rx cos, ry sin), in the sweep's sense */
  e0x = sg * (-rx * sin(t1) * c - ry * cos(t1) * s);
  e0y = sg * (-rx * sin(t1) * s + ry * cos(t1) * c);
  e1x = sg * (-rx * sin(t1 + dt) * c - ry * cos(t1 + dt) * s);
  e1y = sg * (-rx * sin(t1 + dt) * s + ry * cos(t1 + dt) * c);
  seg_to(w, x, y, e0x, e0y, e1x, e1y, 0, 0);
}

static void close_path(walker *w) {
  double dx = w->sx - w->cx, dy = w->sy - w->cy;
  if (!w->open) return;
  seg_to(w, w->sx, w->sy, dx, dy, dx, dy, dx == 0 && dy == 0, 1);
  w->open = 0;
}

/* ---- path data, command by command ------------------------------------- */

static size_t skip(const char *d, size_t n, size_t i) {
  while (i < n && (svgdoc_space((unsigned char)d[i]) || d[i] == ',')) i++;
  return i;
}

/* The number at d[*i] (after separators); 0 when none. */
static int number(const char *d, size_t n, size_t *i, double *v) {
  size_t j = skip(d, n, *i), e;
  if (j >= n) return 0;
  e = arclen_decimal_scan(d, n, j, v);
  if (e == j || !isfinite(*v)) return 0;
  *i = e;
  return 1;
}

static int flag(const char *d, size_t n, size_t *i, int *f) {
  size_t j = skip(d, n, *i);
  if (j >= n || (d[j] != '0' && d[j] != '1')) return 0;
  *f = d[j] == '1';
  *i = j + 1;
  return 1;
}

/* The path data's commands into w, up to the first error (SVG 2 9.5.4:
** the command that holds it is not drawn). */
static void walk_path(walker *w, const char *d) {
  size_t n = strlen(d), i = 0, k;
  char cmd = 0;
  int need = 0, lastc = 0, lastq = 0;
  double lcx = 0, lcy = 0, lqx = 0, lqy = 0;
  for (k = 0; k <= n; k++) {          /* each turn reads a byte at least */
    char c, up;
    int rel, nargs, j, fa = 0, fs = 0;
    double a[7], ox, oy, P[8];
    i = skip(d, n, i);
    if (i >= n) return;
    c = d[i];
    if (strchr("MmLlHhVvCcSsQqTtAaZz", c) != NULL && c != '\0') {
      if (need) return;               /* a command without its arguments */
      i++;
      cmd = c;
      if (c == 'Z' || c == 'z') {
        close_path(w);
        lastc = lastq = 0;
        need = 0;
      } else {
        need = 1;
      }
      continue;
    }
    if (cmd == 0 || cmd == 'Z' || cmd == 'z') return;
    up = (char)(cmd >= 'a' ? cmd - 'a' + 'A' : cmd);
    rel = cmd >= 'a';
    switch (up) {
      case 'M': case 'L': case 'T': nargs = 2; break;
      case 'H': case 'V': nargs = 1; break;
      case 'C': nargs = 6; break;
      case 'S': case 'Q': nargs = 4; break;
      default: nargs = 7; break;      /* A */
    }
    for (j = 0; j < nargs; j++) {
      int ok = up == 'A' && (j == 3 || j == 4)
                   ? flag(d, n, &i, j == 3 ? &fa : &fs)
                   : number(d, n, &i, &a[j]);
      if (!ok) return;
    }
    need = 0;
    ox = rel ? w->cx : 0, oy = rel ? w->cy : 0;
    switch (up) {
      case 'M':
        move_to(w, a[0] + ox, a[1] + oy);
        cmd = rel ? 'l' : 'L';        /* pairs after M are lines */
        lastc = lastq = 0;
        continue;
      case 'L': line_to(w, a[0] + ox, a[1] + oy); break;
      case 'H': line_to(w, a[0] + (rel ? w->cx : 0), w->cy); break;
      case 'V': line_to(w, w->cx, a[0] + (rel ? w->cy : 0)); break;
      case 'C': case 'S':
        P[0] = w->cx, P[1] = w->cy;
        if (up == 'C') {
          P[2] = a[0] + ox, P[3] = a[1] + oy, P[4] = a[2] + ox, P[5] = a[3] + oy;
          P[6] = a[4] + ox, P[7] = a[5] + oy;
        } else {
          P[2] = lastc ? 2 * w->cx - lcx : w->cx;
          P[3] = lastc ? 2 * w->cy - lcy : w->cy;
          P[4] = a[0] + ox, P[5] = a[1] + oy, P[6] = a[2] + ox, P[7] = a[3] + oy;
        }
        lcx = P[4], lcy = P[5];
        curve_to(w, P, 3);
        lastc = 1, lastq = 0;
        continue;
      case 'Q': case 'T':
        P[0] = w->cx, P[1] = w->cy;
        if (up == 'Q') {
          P[2] = a[0] + ox, P[3] = a[1] + oy, P[4] = a[2] + ox, P[5] = a[3] + oy;
        } else {
          P[2] = lastq ? 2 * w->cx - lqx : w->cx;
          P[3] = lastq ? 2 * w->cy - lqy : w->cy;
          P[4] = a[0] + ox, P[5] = a[1] + oy;
        }
        lqx = P[2], lqy = P[3];
        curve_to(w, P, 2);
        lastq = 1, lastc = 0;
        continue;
      default:
        arc_to(w, a[0], a[1], a[2], fa, fs, a[5] + ox, a[6] + oy);
        break;
    }
    lastc = lastq = 0;
  }
}

/* ---- vertices ------------------------------------------------------------ */

/* The end direction of the last segment at or before r[k] (back to lo)
** that has a length, as an angle; 0 when none. */
static int dir_in(const mseg *r, size_t lo, size_t k, double *a) {
  size_t j;
  for (j = k + 1; j-- > lo;)
    if (!r[j].zero) {
      *a = atan2(r[j].d1y, r[j].d1x);
      return 1;
    }
  return 0;
}

static int dir_out(const mseg *r, size_t k, size_t hi, double *a) {
  size_t j;
  for (j = k; j < hi; j++)
    if (!r[j].zero) {
      *a = atan2(r[j].d0y, r[j].d0x);
      return 1;
    }
  return 0;
}

/* The angle of orient="auto" from the directions in and out (either may
** be missing): the bisector, half-way from in to out the short way round
** (from in plus a quarter turn when they are opposite: SVG 2 11.6.2). */
static double bisect(int hin, double in, int hout, double out) {
  double d;
  if (!hin) return hout ? out : 0;
  if (!hout) return in;
  d = out - in;
  if (d > PI) d -= 2 * PI;
  if (d <= -PI) d += 2 * PI;
  return in + d / 2;
}

size_t svgdoc_marker_vertices(svgdoc *D, const svgdoc_shape *s, double **v) {
  walker w;
  mseg *r;
  double *out;
  size_t i, j, nv = 0, k;
  memset(&w, 0, sizeof w);
  w.D = D;
  if (s->kind == SVGDOC_SHAPE_PATH) {
    walk_path(&w, s->d);
  } else if (s->n >= 2) {            /* line, polyline, polygon */
    move_to(&w, s->v[0], s->v[1]);
    for (i = 2; i + 1 < s->n; i += 2) line_to(&w, s->v[i], s->v[i + 1]);
    if (s->kind == SVGDOC_SHAPE_POLYGON) close_path(&w);
  }
  if (w.n == 0) return 0;
  /* the records stay where they are: the vertices go after them */
  svgdoc_reserve(D, &D->marker_buf, w.n * sizeof(mseg) + 3 * w.n * sizeof(double));
  r = (mseg *)(void *)D->marker_buf.s;
  out = (double *)(void *)(r + w.n);
  for (i = 0; i < w.n; i = j) {       /* a subpath: r[i] its move */
    size_t lo = i + 1;
    int closed;
    double ai = 0, ao = 0, a;
    int hi_, ho;
    for (j = lo; j < w.n && !r[j].move; j++) {}
    closed = j > lo && r[j - 1].close;
    /* its start: out of the first segment; closed, into it from the last
    ** (SVG 2 11.6.2) */
    ho = dir_out(r, lo, j, &ao);
    hi_ = closed ? dir_in(r, lo, j - 1, &ai) : 0;
    a = bisect(hi_, ai, ho, ao);
    out[3 * nv] = r[i].x, out[3 * nv + 1] = r[i].y, out[3 * nv + 2] = a;
    nv++;
    for (k = lo; k < j; k++) {
      hi_ = dir_in(r, lo, k, &ai);
      if (k + 1 < j) ho = dir_out(r, k + 1, j, &ao);
      else if (closed) ho = dir_out(r, lo, j, &ao);
      else ho = 0;
      a = bisect(hi_, ai, ho, ao);
      out[3 * nv] = r[k].x, out[3 * nv + 1] = r[k].y, out[3 * nv + 2] = a;
      nv++;
    }
  }
  *v = out;
  return nv;
}

/* ---- an instance --------------------------------------------------------- */

/* The cosine and sine of an angle of deg degrees, exact at multiples of 90. */
static void turn_of(double deg, double *c, double *s) {
  double m = fmod(deg, 360);
  if (m < 0) m += 360;
  if (m == 0) *c = 1, *s = 0;
  else if (m == 90) *c = 0, *s = 1;
  else if (m == 180) *c = -1, *s = 0;
  else if (m == 270) *c = 0, *s = -1;
  else *c = cos(m * (PI / 180)), *s = sin(m * (PI / 180));
}

/* orient's <angle> in degrees (SVG 2 11.6.2: deg, grad, rad, turn; a bare
** number is degrees); 0 when it is not one (the initial value). */
static double orient_angle(const char *s) {
  static const struct { const char *u; double k; } U[] = {
    {"", 1}, {"deg", 1}, {"grad", 0.9}, {"rad", 180 / PI}, {"turn", 360}};
  size_t n = strlen(s), i = 0, e, t;
  double v;
  int k;
  while (i < n && svgdoc_space((unsigned char)s[i])) i++;
  e = i < n ? arclen_decimal_scan(s, n, i, &v) : i;
  if (e == i) return 0;
  for (t = n; t > e && svgdoc_space((unsigned char)s[t - 1]); t--) {}
  for (k = 0; k < (int)(sizeof U / sizeof U[0]); k++)
    if (strlen(U[k].u) == t - e && strncmp(s + e, U[k].u, t - e) == 0)
      return isfinite(v * U[k].k) ? v * U[k].k : 0;
  return 0;
}

/* refX / refY: a length, or a keyword at 0, 50% or 100% of the viewBox (or
** the viewport) along its axis (SVG 2 11.6.2). */
static double ref_coord(svgdoc *D, unsigned long line, unsigned long col,
                        const char **atts, int axis, const double *vb,
                        const svgdoc_viewport *vp) {
  const char *name = axis == 'x' ? "refX" : "refY", *s = svgdoc_attr(atts, name);
  static const char *const KW[2][3] = {{"left", "center", "right"},
                                       {"top", "center", "bottom"}};
  double o = vb[axis == 'y'], size = vb[2 + (axis == 'y')];
  int k;
  if (s == NULL || svgdoc_blank(s)) return 0;
  for (k = 0; k < 3; k++) {
    size_t m = strlen(KW[axis == 'y'][k]);
    const char *t = s;
    while (svgdoc_space((unsigned char)*t)) t++;
    if (strncmp(t, KW[axis == 'y'][k], m) == 0 && svgdoc_blank(t + m))
      return o + size * k / 2;
  }
  return svgdoc_length(D, line, col, s, axis, vp, name);
}

int svgdoc_marker_place(svgdoc *D, svgdoc_marker_set *ms, size_t i,
                        const char **atts, const svgdoc_marker_def *def,
                        unsigned long line, unsigned long col,
                        svgdoc_viewport *vp) {
  double mw = 3, mh = 3, vb[4], sc, c, s, rx, ry;
  const char *o = svgdoc_attr(atts, "orient"), *u = svgdoc_attr(atts, "markerUnits");
  svgdoc_matrix V, P;
  int has_vb;
  svgdoc_len_attr(D, line, col, atts, "markerWidth", 'x', &ms->vp, &mw);
  svgdoc_len_attr(D, line, col, atts, "markerHeight", 'y', &ms->vp, &mh);
  svgdoc_nonneg(D, line, col, mw, "markerWidth");
  svgdoc_nonneg(D, line, col, mh, "markerHeight");
  if (mw == 0 || mh == 0) return 0;   /* SVG 2 11.6.2: disables rendering */
  has_vb = svgdoc_viewbox(D, line, col, svgdoc_attr(atts, "viewBox"), vb);
  svgdoc_translate(0, 0, V);
  if (has_vb) {
    if (vb[2] <= 0 || vb[3] <= 0) return 0;
    svgdoc_viewbox_matrix(D, line, col, vb,
                          svgdoc_attr(atts, "preserveAspectRatio"), 0, 0, mw,
                          mh, V);
  } else {
    vb[0] = vb[1] = 0, vb[2] = mw, vb[3] = mh;
  }
  vp->has = 1, vp->w = vb[2], vp->h = vb[3];
  vp->em = def->em, vp->rem = ms->vp.rem;
  rx = ref_coord(D, line, col, atts, 'x', vb, vp);
  ry = ref_coord(D, line, col, atts, 'y', vb, vp);
  /* markerUnits: strokeWidth (the initial value) scales by the shape's
  ** computed stroke-width */
  sc = u && strcmp(u, "userSpaceOnUse") == 0 ? 1 : ms->sw;
  if (sc == 0) return 0;
  if (o && strcmp(o, "auto") == 0) {
    c = cos(ms->v[3 * i + 2]), s = sin(ms->v[3 * i + 2]);
  } else if (o && strcmp(o, "auto-start-reverse") == 0) {
    c = cos(ms->v[3 * i + 2]), s = sin(ms->v[3 * i + 2]);
    if (ms->which == SVGDOC_MK_START) c = -c, s = -s;
  } else {
    turn_of(o ? orient_angle(o) : 0, &c, &s);
  }
  /* ctm . translate(vertex) . rotate . scale(sc) . translate(-ref') . V,
  ** ref' the reference point mapped by V (SVG 2 11.6.2) */
  P[0] = c * sc, P[1] = s * sc, P[2] = -s * sc, P[3] = c * sc;
  rx = V[0] * rx + V[4], ry = V[3] * ry + V[5];
  P[4] = ms->v[3 * i] - (P[0] * rx + P[2] * ry);
  P[5] = ms->v[3 * i + 1] - (P[1] * rx + P[3] * ry);
  svgdoc_mul(P, V, P);
  svgdoc_mul(ms->ctm, P, ms->outer);
  /* the viewport [0, mw] x [0, mh] in the content's coordinates */
  ms->clip = def->clip;
  ms->box[0] = -V[4] / V[0], ms->box[2] = (mw - V[4]) / V[0];
  ms->box[1] = -V[5] / V[3], ms->box[3] = (mh - V[5]) / V[3];
  return 1;
}
