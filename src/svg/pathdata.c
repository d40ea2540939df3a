/*
** pathdata.c -- SVG path data into segments of four kinds (lines,
** quadratics, cubics, conics) or into cubics only (pathdata.h).
**
** The grammar of SVG 1.1 section 8.3.9 as SVG 2 section 9.3.9 reads it:
** commands M L H V C S Q T A Z (lower case: relative), repeated argument
** lists (after M they are linetos), numbers separated by whitespace and at
** most one comma or by their own signs and dots, arc flags as the single
** bytes 0 and 1.  Every loop advances through the data, so the data's
** length bounds the work (arcs: at most 4 conics, or 4 << ARCLEN_CONIC_MAXLEVEL
** cubics).
*/
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "arclen.h"
#include "curve/numeric.h"
#include "svg/decimal.h"
#include "svg/pathdata.h"

/* Degrees to radians as Lua's math.rad computes it (one multiplication). */
#define RADIANS_PER_DEGREE (ARCLEN_PI / 180.0)

static void empty(arclen_pathdata *pd) {
  pd->cubics = NULL;
  pd->kinds = NULL;
  pd->ncubics = pd->cubics_room = 0;
  pd->subpaths = NULL;
  pd->nsubpaths = pd->subpaths_room = 0;
  pd->err.kind = ARCLEN_PD_OK;
}

void arclen_pathdata_init(arclen_pathdata *pd) {
  empty(pd);
  pd->arcs = ARCLEN_PD_ARCS_CONICS;
}

/* The memory goes; the mode stays for the next parse. */
void arclen_pathdata_free(arclen_pathdata *pd) {
  free(pd->cubics);
  free(pd->kinds);
  free(pd->subpaths);
  empty(pd);
}

/* ---- the grammar's pieces ------------------------------------------------ */

static int is_space(unsigned char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}

static int is_alpha(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

static char upper(unsigned char c) {
  return (char)(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
}

/* The number of arguments of a command (upper case), -1 for no command. */
static int arg_count(char cmd) {
  switch (cmd) {
    case 'M': case 'L': case 'T': return 2;
    case 'H': case 'V': return 1;
    case 'C': return 6;
    case 'S': case 'Q': return 4;
    case 'A': return 7;
    case 'Z': return 0;
    default: return -1;
  }
}

const char *arclen_pathdata_argname(char cmd, int k) {
  static const char *const xy[] = {"x", "y"};
  static const char *const c[] = {"x1", "y1", "x2", "y2", "x", "y"};
  static const char *const a[] = {"rx", "ry", "x-axis-rotation",
    "large-arc-flag", "sweep-flag", "x", "y"};
  if (k < 1 || k > arg_count(cmd)) return "?";
  switch (cmd) {
    case 'H': return "x";
    case 'V': return "y";
    case 'C': return c[k - 1];
    case 'S': return c[k + 1];
    case 'Q': return k <= 2 ? c[k - 1] : xy[k - 3];
    case 'A': return a[k - 1];
    default: return xy[k - 1];
  }
}

/* The reader's state is the builder's (pathdata.h): the text parser and
** the builder make their records through the same functions below. */
typedef arclen_pathbuild reader;

static int fail(reader *r, int kind, size_t i) {
  arclen_pathdata_error *e = &r->pd->err;
  e->kind = kind;
  e->pos = r->d != NULL ? i + 1 : 0;         /* the builder has no text */
  e->at_end = i >= r->n;
  e->byte = i < r->n ? (unsigned char)r->d[i] : 0;
  e->start = r->at < i ? r->at : i;
  return kind;
}

static size_t skip_space(const reader *r, size_t i) {
  while (i < r->n && is_space((unsigned char)r->d[i])) i++;
  return i;
}

/* Whitespace, at most one comma, whitespace (the comma-wsp production). */
static size_t skip_sep(const reader *r, size_t i) {
  i = skip_space(r, i);
  if (i < r->n && r->d[i] == ',') i = skip_space(r, i + 1);
  return i;
}

/* The number at *i, argument k of cmd. */
static int number(reader *r, size_t *i, char cmd, int k, double *v) {
  size_t s = *i, e, exp_at;
  e = arclen_decimal_mantissa(r->d, r->n, s, &exp_at);
  if (e == s) {
    r->pd->err.cmd = cmd;
    r->pd->err.arg = k;
    return fail(r, ARCLEN_PD_NUMBER, s);
  }
  if (exp_at < r->n) {
    size_t x = arclen_decimal_exponent(r->d, r->n, exp_at);
    if (x == exp_at) return fail(r, ARCLEN_PD_EXPONENT, exp_at);
    e = x;
  }
  if (arclen_decimal_value(r->d + s, e - s, v) != 0)
    return fail(r, ARCLEN_PD_NOMEM, s);
  if (!(*v > -HUGE_VAL && *v < HUGE_VAL)) {
    r->pd->err.tok = s;
    r->pd->err.toklen = e - s;
    return fail(r, ARCLEN_PD_RANGE, s);
  }
  *i = e;
  return ARCLEN_PD_OK;
}

/* The arguments of one command instance into a[]. */
static int arguments(reader *r, size_t *i, char cmd, double *a) {
  int k, count = arg_count(cmd), rc;
  for (k = 1; k <= count; k++) {
    if (k > 1) *i = skip_sep(r, *i);
    if (cmd == 'A' && (k == 4 || k == 5)) {    /* a flag needs no separator */
      char c = *i < r->n ? r->d[*i] : 0;
      if (c != '0' && c != '1') {
        r->pd->err.cmd = cmd;
        r->pd->err.arg = k;
        return fail(r, ARCLEN_PD_FLAG, *i);
      }
      a[k - 1] = c - '0';
      (*i)++;
    } else if ((rc = number(r, i, cmd, k, &a[k - 1])) != ARCLEN_PD_OK) {
      return rc;
    }
  }
  return ARCLEN_PD_OK;
}

/* ---- the result ---------------------------------------------------------- */

/* Room for k more records; returns the first of them, NULL without
** memory.  Their kinds are cubics until the caller says otherwise. */
static double *reserve(reader *r, size_t k) {
  arclen_pathdata *pd = r->pd;
  if (pd->ncubics + k > pd->cubics_room) {
    size_t room = pd->cubics_room ? pd->cubics_room : 16;
    double *p;
    unsigned char *q;
    while (room < pd->ncubics + k) room *= 2;
    p = (double *)realloc(pd->cubics, room * ARCLEN_PD_STRIDE * sizeof(double));
    if (p == NULL) return NULL;
    pd->cubics = p;
    q = (unsigned char *)realloc(pd->kinds, room);
    if (q == NULL) return NULL;
    pd->kinds = q;
    pd->cubics_room = room;
  }
  memset(pd->kinds + pd->ncubics, ARCLEN_PD_CUBIC, k);
  return pd->cubics + ARCLEN_PD_STRIDE * pd->ncubics;
}

/* Count k records written at reserve()'s pointer into the open subpath. */
static void commit(reader *r, size_t k) {
  r->pd->ncubics += k;
  r->pd->subpaths[r->sp].n += k;
}

static int open_subpath(reader *r, double x, double y) {
  arclen_pathdata *pd = r->pd;
  arclen_subpath *s;
  if (pd->nsubpaths == pd->subpaths_room) {
    size_t room = pd->subpaths_room ? 2 * pd->subpaths_room : 8;
    arclen_subpath *p = (arclen_subpath *)realloc(pd->subpaths,
                                                  room * sizeof *p);
    if (p == NULL) return 0;
    pd->subpaths = p;
    pd->subpaths_room = room;
  }
  s = &pd->subpaths[pd->nsubpaths];
  s->x = x;
  s->y = y;
  s->first = pd->ncubics;
  s->n = 0;
  s->closed = 0;
  r->sp = (long)pd->nsubpaths++;
  return 1;
}

/* One record: kind's npts points v[] (already mapped), then w for a conic;
** the rest of the record 0. */
static int put(reader *r, unsigned char kind, const double *v, int npts,
               double w) {
  double *c = reserve(r, 1);
  int k, count = 2 * npts;
  if (c == NULL) return 0;
  for (k = 0; k < ARCLEN_PD_STRIDE; k++) c[k] = k < count ? v[k] : 0;
  if (kind == ARCLEN_PD_CONIC) c[count] = w;
  r->pd->kinds[r->pd->ncubics] = kind;
  commit(r, 1);
  return 1;
}

static int fold(reader *r, const double p[6], double w);

/* A segment of kind (npts points v[] in the data's coordinates, w for a
** conic) mapped by T: exact on every kind (the affine image of a Bezier
** curve, rational too, is the curve of the images of its control points;
** a conic keeps w).  A mapped point beyond the doubles is remembered for
** the error at the end.  A conic (of at most 90 degrees) that rounding
** made flat -- its control points coincide or are collinear -- is the
** line of its ends; one that a singular T made flat is that line where
** the line is the curve (both legs one way), else the two lines to its
** farthest point and back. */
static int emit(reader *r, unsigned char kind, double *v, int npts, double w) {
  int k;
  if (kind == ARCLEN_PD_CONIC && arclen_conic_degenerate(v)) {
    v[2] = v[4]; v[3] = v[5];
    kind = ARCLEN_PD_LINE;
    npts = 2;
  }
  if (r->T != NULL) {
    const double *T = r->T;
    for (k = 0; k < npts; k++) {
      double x = v[2 * k], y = v[2 * k + 1];
      v[2 * k] = T[0] * x + T[2] * y + T[4];
      v[2 * k + 1] = T[1] * x + T[3] * y + T[5];
      if (!(fabs(v[2 * k]) <= DBL_MAX && fabs(v[2 * k + 1]) <= DBL_MAX))
        r->overflow = 1;
    }
  }
  /* without T the points are the ones judged above: not flat */
  if (kind == ARCLEN_PD_CONIC && r->T != NULL && !r->overflow &&
      arclen_conic_degenerate(v)) {
    if ((v[2] - v[0]) * (v[4] - v[2]) + (v[3] - v[1]) * (v[5] - v[3]) >= 0) {
      v[2] = v[4]; v[3] = v[5];
      return put(r, ARCLEN_PD_LINE, v, 2, 0);
    }
    return fold(r, v, w);
  }
  return put(r, kind, v, npts, w);
}

/* The flat conic's farthest point along its line: the derivative's
** numerator there, w a (1-t)^2 + c t (1-t) + w b t^2 (the rational
** quadratic's derivative, weights 1 w 1; a, b the legs, c the chord, along
** the line, a and b of opposite signs), changes sign once in (0, 1); 64
** halvings find t to the last bit.  Then two lines, out and back. */
static int fold(reader *r, const double p[6], double w) {
  double ux = p[2] - p[0], uy = p[3] - p[1], lo = 0, hi = 1, a, b, c, m[2];
  double v[4];
  int k;
  if (ux == 0 && uy == 0) { ux = p[4] - p[2]; uy = p[5] - p[3]; }
  a = ux * (p[2] - p[0]) + uy * (p[3] - p[1]);
  b = ux * (p[4] - p[2]) + uy * (p[5] - p[3]);
  c = ux * (p[4] - p[0]) + uy * (p[5] - p[1]);
  for (k = 0; k < 64; k++) {
    double t = (lo + hi) / 2, s = 1 - t;
    double f = w * a * s * s + c * t * s + w * b * t * t;
    if ((f > 0) == (a > 0)) lo = t; else hi = t;
  }
  arclen_conic_point(p, w, (lo + hi) / 2, m);
  v[0] = p[0]; v[1] = p[1]; v[2] = m[0]; v[3] = m[1];
  if (!put(r, ARCLEN_PD_LINE, v, 2, 0)) return 0;
  v[0] = m[0]; v[1] = m[1]; v[2] = p[4]; v[3] = p[5];
  return put(r, ARCLEN_PD_LINE, v, 2, 0);
}

static int cubic(reader *r, double x0, double y0, double x1, double y1,
                 double x2, double y2, double x3, double y3) {
  double v[8];
  v[0] = x0; v[1] = y0; v[2] = x1; v[3] = y1;
  v[4] = x2; v[5] = y2; v[6] = x3; v[7] = y3;
  if (r->pd->arcs != ARCLEN_PD_ARCS_CUBICS)
    return emit(r, ARCLEN_PD_CUBIC, v, 4, 0);
  return put(r, ARCLEN_PD_CUBIC, v, 4, 0);   /* mapped at the end, as ever */
}

/* A line; as a cubic, the control points at thirds (the same curve,
** constant speed). */
static int line(reader *r, double x0, double y0, double x1, double y1) {
  double dx = x1 - x0, dy = y1 - y0;
  if (r->pd->arcs != ARCLEN_PD_ARCS_CUBICS) {
    double v[4];
    v[0] = x0; v[1] = y0; v[2] = x1; v[3] = y1;
    return emit(r, ARCLEN_PD_LINE, v, 2, 0);
  }
  return cubic(r, x0, y0, x0 + dx / 3, y0 + dy / 3, x1 - dx / 3, y1 - dy / 3,
               x1, y1);
}

/* A quadratic; as a cubic, degree-elevated: C1 = Q0 + 2/3 (Q1 - Q0), C2 =
** Q2 + 2/3 (Q1 - Q2) (the same curve). */
static int quadratic(reader *r, double x0, double y0, double qx, double qy,
                     double x1, double y1) {
  if (r->pd->arcs != ARCLEN_PD_ARCS_CUBICS) {
    double v[6];
    v[0] = x0; v[1] = y0; v[2] = qx; v[3] = qy; v[4] = x1; v[5] = y1;
    return emit(r, ARCLEN_PD_QUAD, v, 3, 0);
  }
  return cubic(r, x0, y0, x0 + 2.0 / 3 * (qx - x0), y0 + 2.0 / 3 * (qy - y0),
               x1 + 2.0 / 3 * (qx - x1), y1 + 2.0 / 3 * (qy - y1), x1, y1);
}

/* ---- arcs ------------------------------------------------------------------ */

/* The singular values of [[p r] [q s]], largest first (by hypot: a
** scale(1e-170) squares to 0, and was taken for no scale at all). */
static void singular(double p, double q, double r, double s, double *big,
                     double *small) {
  double e = (p + s) / 2, f = (p - s) / 2;
  double g = (q - r) / 2, h = (q + r) / 2;
  double u = hypot(e, g), v = hypot(f, h);
  *big = u + v;
  *small = fabs(u - v);
}

/* The arc's size after T and T's largest singular value: the image of the
** ellipse is the ellipse of the 2x2 matrix A R(phi) diag(rx, ry), whose
** semi-axes are that matrix's singular values; the chord maps by A (hx,
** hy: half of it, which cannot overflow). */
static void image_scale(const double *T, double rx, double ry, double phi,
                        double hx, double hy, double *size, double *smax) {
  double t = phi * RADIANS_PER_DEGREE, c = cos(t), s = sin(t);
  double A = T[0], B = T[1], C = T[2], D = T[3], s1, half, unused;
  singular(rx * (A * c + C * s), rx * (B * c + D * s),
           ry * (-A * s + C * c), ry * (-B * s + D * c), &s1, &unused);
  half = hypot(A * hx + C * hy, B * hx + D * hy);
  *size = s1 < half ? half : s1;
  singular(A, B, C, D, smax, &unused);
}

static int arc_fail(reader *r, int why, int code, size_t pos) {
  r->pd->err.arc = why;
  r->pd->err.code = code;
  return fail(r, ARCLEN_PD_ARC, pos);
}

/* Is |b - a| exactly r (the difference without rounding: Knuth's TwoSum
** leaves no error)? */
static int exact_gap(double a, double b, double r) {
  double d = b - a, bb = d - b, err = (b - (d - bb)) + (-a - bb);
  return err == 0 && fabs(d) == r;
}

/* The conics of an elliptical arc (SVG 1.1 F.6) from (x0, y0) to (x1,
** y1), a = rx ry rotation large sweep, pos the command's byte: at most
** four of at most 90 degrees each, exact but for rounding: each control
** point from its piece's ends, each weight from the sweep, so that an arc
** of a far centre keeps its digits (arclen_svg_arc_conics).  An arc with
** no rotation and no large-arc flag whose ends are exactly rx and ry
** apart is a quarter of the axis-aligned ellipse (F.6.5: Lambda = 1/2,
** the centre a corner of the ends' box), and so is every such arc under
** ARCLEN_PD_ARCS_QUARTERS (the basic shapes, whose ends are rounded): its
** centre and control point are the two corners of the ends' box, the
** sweep flag says which is which (positive angle: the centre c has
** cross(p0 - c, p2 - c) > 0), and w = cos 45 degrees (Floater's eq. 1 for
** a circular arc of angle 2h: w = cos h) -- the ends are the only
** rounding. */
static int arc_conics(reader *r, double x0, double y0, const double *a,
                      double x1, double y1, size_t pos) {
  double c[28], v[6];
  int kind, n, k;
  if (!isfinite(x0)) return arc_fail(r, ARCLEN_PD_ARC_X1, 0, pos);
  if (!isfinite(y0)) return arc_fail(r, ARCLEN_PD_ARC_Y1, 0, pos);
  if (!isfinite(x1)) return arc_fail(r, ARCLEN_PD_ARC_X2, 0, pos);
  if (!isfinite(y1)) return arc_fail(r, ARCLEN_PD_ARC_Y2, 0, pos);
  if (a[2] == 0 && a[3] == 0 && a[0] != 0 && a[1] != 0 &&
      (r->pd->arcs == ARCLEN_PD_ARCS_QUARTERS ||
       (exact_gap(x0, x1, fabs(a[0])) && exact_gap(y0, y1, fabs(a[1]))))) {
    int centre_first = ((x0 - x1) * (y1 - y0) > 0) == (a[4] != 0);
    if (x0 == x1 && y0 == y1) return ARCLEN_PD_OK;       /* F.6.2: omitted */
    v[0] = x0; v[1] = y0; v[4] = x1; v[5] = y1;
    /* the corners (x1, y0) and (x0, y1); the control point is the one
    ** that is not the centre */
    v[2] = centre_first ? x0 : x1;
    v[3] = centre_first ? y1 : y0;
    return emit(r, ARCLEN_PD_CONIC, v, 3, sqrt(0.5)) ? ARCLEN_PD_OK
                                                   : fail(r, ARCLEN_PD_NOMEM, pos);
  }
  kind = arclen_svg_arc_conics(x0, y0, fabs(a[0]), fabs(a[1]), a[2], a[3] != 0,
                               a[4] != 0, x1, y1, c, &n);
  if (kind == ARCLEN_SVGARC_NONE) return ARCLEN_PD_OK;   /* F.6.2: omitted */
  if (kind == ARCLEN_SVGARC_LINE)                        /* F.6.2: a line */
    return line(r, x0, y0, x1, y1) ? ARCLEN_PD_OK
                                   : fail(r, ARCLEN_PD_NOMEM, pos);
  if (kind == ARCLEN_EOVERFLOW) return arc_fail(r, ARCLEN_PD_ARC_OVERFLOW, 0, pos);
  if (kind < 0) return arc_fail(r, ARCLEN_PD_ARC_CODE, kind, pos);
  for (k = 0; k < n; k++) {
    int j;
    for (j = 0; j < 6; j++) v[j] = c[7 * k + j];
    if (!emit(r, ARCLEN_PD_CONIC, v, 3, c[7 * k + 6]))
      return fail(r, ARCLEN_PD_NOMEM, pos);
  }
  return ARCLEN_PD_OK;
}

/* The cubics of an elliptical arc (SVG 1.1 F.6) from (x0, y0) to (x1,
** y1); a = rx ry rotation large sweep; pos: the command's byte.  The Hausdorff tolerance is arc_tol
** times the arc's size, max(rx, ry, chord/2); under T the cubics are built
** in local coordinates at the tolerance that, multiplied by T's largest
** singular value (the most T can stretch a distance), is arc_tol times the
** size of the arc's image.  Without a tolerance (a zero radius, a zero
** size) level 0.  The checks and their order are arclen.svg_arc's. */
static int arc(reader *r, double x0, double y0, const double *a, double x1,
               double y1, size_t pos) {
  double rx = fabs(a[0]), ry = fabs(a[1]), c[28], tol = 0, bound;
  /* half the chord by halves and hypot: its square overflows from 1.3e154
  ** and the difference from 9e307 */
  double hx = x1 / 2 - x0 / 2, hy = y1 / 2 - y0 / 2, half = hypot(hx, hy);
  double scale = rx;
  int have_tol, kind, n, k, level = 0;
  if (r->pd->arcs != ARCLEN_PD_ARCS_CUBICS)
    return arc_conics(r, x0, y0, a, x1, y1, pos);
  if (scale < ry) scale = ry;
  if (scale < half) scale = half;
  if (r->T != NULL && scale > 0) {
    double size, smax;
    image_scale(r->T, rx, ry, a[2], hx, hy, &size, &smax);
    scale = smax > 0 ? size / smax : 0;
  }
  have_tol = scale > 0 && rx > 0 && ry > 0;
  if (have_tol) tol = r->arc_tol * scale;
  if (!isfinite(x0)) return arc_fail(r, ARCLEN_PD_ARC_X1, 0, pos);
  if (!isfinite(y0)) return arc_fail(r, ARCLEN_PD_ARC_Y1, 0, pos);
  if (!isfinite(x1)) return arc_fail(r, ARCLEN_PD_ARC_X2, 0, pos);
  if (!isfinite(y1)) return arc_fail(r, ARCLEN_PD_ARC_Y2, 0, pos);
  if (have_tol && (!(tol > 0) || !isfinite(tol)))
    return arc_fail(r, ARCLEN_PD_ARC_TOL, 0, pos);
  kind = arclen_svg_arc_conics(x0, y0, rx, ry, a[2], a[3] != 0, a[4] != 0,
                               x1, y1, c, &n);
  if (kind == ARCLEN_SVGARC_NONE) return ARCLEN_PD_OK;   /* F.6.2: omitted */
  if (kind == ARCLEN_SVGARC_LINE)                        /* F.6.2: a line */
    return line(r, x0, y0, x1, y1) ? ARCLEN_PD_OK
                                   : fail(r, ARCLEN_PD_NOMEM, pos);
  if (kind == ARCLEN_EOVERFLOW) return arc_fail(r, ARCLEN_PD_ARC_OVERFLOW, 0, pos);
  if (kind < 0) return arc_fail(r, ARCLEN_PD_ARC_CODE, kind, pos);
  for (k = 0; have_tol && k < n; k++) {       /* the level all pieces meet */
    int lk, rc = arclen_conic_level(c + 7 * k, c[7 * k + 6],
                                    ARCLEN_CONIC_MIDPOINT, tol, &lk, &bound);
    if (rc == ARCLEN_ENOCONV) {
      r->pd->err.bound = bound;
      return arc_fail(r, ARCLEN_PD_ARC_LEVEL, 0, pos);
    }
    if (rc != ARCLEN_OK) return arc_fail(r, ARCLEN_PD_ARC_CODE, rc, pos);
    if (lk > level) level = lk;
  }
  for (k = 0; k < n; k++) {
    size_t per = (size_t)1 << level;
    double *out = reserve(r, per);
    int rc;
    if (out == NULL) return fail(r, ARCLEN_PD_NOMEM, pos);
    /* a conic that rounding made degenerate leaves out unwritten */
    rc = arclen_conic_cubics(c + 7 * k, c[7 * k + 6], ARCLEN_CONIC_MIDPOINT,
                             level, out, &bound);
    if (rc == ARCLEN_EOVERFLOW) return arc_fail(r, ARCLEN_PD_ARC_CUBICS, 0, pos);
    if (rc != ARCLEN_OK) return arc_fail(r, ARCLEN_PD_ARC_DEGENERATE, 0, pos);
    commit(r, per);
  }
  return ARCLEN_PD_OK;
}

/* ---- the transform --------------------------------------------------------- */

/* Map the subpaths' starts by T, and under ARCLEN_PD_ARCS_CUBICS every
** cubic's points (exact: an affine image of a Bezier curve is the Bezier
** curve of the images of its control points; the other modes mapped each
** segment as it came, emit); a control point that overflows is an error. */
static int transform(arclen_pathdata *pd, const double *T, int overflow) {
  double A = T[0], B = T[1], C = T[2], D = T[3], E = T[4], F = T[5];
  size_t k;
  int ok = !overflow;
  for (k = 0; k < pd->nsubpaths; k++) {
    arclen_subpath *s = &pd->subpaths[k];
    double x = s->x, y = s->y;
    s->x = A * x + C * y + E;
    s->y = B * x + D * y + F;
  }
  for (k = 0; pd->arcs == ARCLEN_PD_ARCS_CUBICS && k < 4 * pd->ncubics; k++) {
    double x = pd->cubics[2 * k], y = pd->cubics[2 * k + 1];
    double u = A * x + C * y + E, v = B * x + D * y + F;
    if (!(u > -HUGE_VAL && u < HUGE_VAL && v > -HUGE_VAL && v < HUGE_VAL))
      ok = 0;
    pd->cubics[2 * k] = u;
    pd->cubics[2 * k + 1] = v;
  }
  if (ok) return ARCLEN_PD_OK;
  pd->err.kind = ARCLEN_PD_TRANSFORM;
  pd->err.pos = 0;
  return ARCLEN_PD_TRANSFORM;
}

/* ---- the reader ------------------------------------------------------------ */

/* One drawing command instance (arguments a[]); updates the current point
** (cx, cy), the subpath's start (sx, sy) and the reflected control points
** (lcx, lcy after C/S, lqx, lqy after Q/T, as lastc and lastq say). */
static int draw(reader *r, char cmd, int rel, const double *a,
                size_t cmdpos) {
  double ox = rel ? r->cx : 0, oy = rel ? r->cy : 0, x, y;
  double cx = r->cx, cy = r->cy;
  int ok = 1;
  if (r->sp < 0 && !open_subpath(r, cx, cy))   /* drawing after Z */
    return fail(r, ARCLEN_PD_NOMEM, cmdpos);
  switch (cmd) {
  case 'L':
    x = a[0] + ox; y = a[1] + oy;
    ok = line(r, cx, cy, x, y);
    break;
  case 'H':
    x = a[0] + (rel ? cx : 0); y = cy;
    ok = line(r, cx, cy, x, y);
    break;
  case 'V':
    x = cx; y = a[0] + (rel ? cy : 0);
    ok = line(r, cx, cy, x, y);
    break;
  case 'C': case 'S': {
    double x1, y1, x2, y2;
    if (cmd == 'C') {
      x1 = a[0] + ox; y1 = a[1] + oy; x2 = a[2] + ox; y2 = a[3] + oy;
      x = a[4] + ox; y = a[5] + oy;
    } else {
      if (r->lastc) { x1 = 2 * cx - r->lcx; y1 = 2 * cy - r->lcy; }
      else { x1 = cx; y1 = cy; }
      x2 = a[0] + ox; y2 = a[1] + oy; x = a[2] + ox; y = a[3] + oy;
    }
    ok = cubic(r, cx, cy, x1, y1, x2, y2, x, y);
    r->lcx = x2; r->lcy = y2;
    break;
  }
  case 'Q': case 'T': {
    double qx, qy;
    if (cmd == 'Q') {
      qx = a[0] + ox; qy = a[1] + oy; x = a[2] + ox; y = a[3] + oy;
    } else {
      if (r->lastq) { qx = 2 * cx - r->lqx; qy = 2 * cy - r->lqy; }
      else { qx = cx; qy = cy; }
      x = a[0] + ox; y = a[1] + oy;
    }
    ok = quadratic(r, cx, cy, qx, qy, x, y);
    r->lqx = qx; r->lqy = qy;
    break;
  }
  default: {                                   /* 'A' */
    int rc;
    x = a[5] + ox; y = a[6] + oy;
    rc = arc(r, cx, cy, a, x, y, cmdpos);
    if (rc != ARCLEN_PD_OK) return rc;
    break;
  }
  }
  if (!ok) return fail(r, ARCLEN_PD_NOMEM, cmdpos);
  r->lastc = cmd == 'C' || cmd == 'S';
  r->lastq = cmd == 'Q' || cmd == 'T';
  r->cx = x;
  r->cy = y;
  return ARCLEN_PD_OK;
}

/* Z, M or a drawing command (absolute unless rel), at byte cmdpos. */
static int step(reader *r, char cmd, int rel, const double *a, size_t cmdpos) {
  if (cmd == 'Z') {
    if (r->sp < 0) return fail(r, ARCLEN_PD_CLOSE_FIRST, cmdpos);
    if ((r->cx != r->sx || r->cy != r->sy) &&
        !line(r, r->cx, r->cy, r->sx, r->sy))
      return fail(r, ARCLEN_PD_NOMEM, cmdpos);
    r->pd->subpaths[r->sp].closed = 1;
    r->cx = r->sx;
    r->cy = r->sy;
    r->sp = -1;               /* a drawing command opens a new subpath here */
    r->lastc = r->lastq = 0;
    return ARCLEN_PD_OK;
  }
  if (cmd == 'M') {
    double ox = rel ? r->cx : 0, oy = rel ? r->cy : 0;
    r->cx = a[0] + ox;
    r->cy = a[1] + oy;
    r->sx = r->cx;
    r->sy = r->cy;
    if (!open_subpath(r, r->cx, r->cy)) return fail(r, ARCLEN_PD_NOMEM, cmdpos);
    r->lastc = r->lastq = 0;
    return ARCLEN_PD_OK;
  }
  return draw(r, cmd, rel, a, cmdpos);
}

static void start(reader *r, arclen_pathdata *pd, const char *d, size_t n,
                  double arc_tol, const double *T) {
  memset(r, 0, sizeof *r);
  r->pd = pd; r->d = d; r->n = n; r->arc_tol = arc_tol; r->T = T; r->sp = -1;
  pd->ncubics = pd->nsubpaths = 0;
  pd->err.kind = ARCLEN_PD_OK;
  pd->err.pos = pd->err.start = 0;
}

static int finish(reader *r) {
  if (r->pd->err.kind != ARCLEN_PD_OK) return r->pd->err.kind;
  if (!r->begun) return fail(r, ARCLEN_PD_EMPTY, 0);
  return r->T != NULL ? transform(r->pd, r->T, r->overflow) : ARCLEN_PD_OK;
}

int arclen_pathdata_parse(arclen_pathdata *pd, const char *d, size_t n,
                          double arc_tol, const double *T) {
  reader r;
  double a[7];
  char cmd = 0;                   /* the current command, 0 before any */
  int rel = 0, rc;
  size_t i;
  start(&r, pd, d, n, arc_tol, T);
  i = skip_space(&r, 0);
  if (i >= n) return fail(&r, ARCLEN_PD_EMPTY, 0);
  r.begun = 1;
  while (i < n) {
    unsigned char c = (unsigned char)d[i];
    char up = upper(c);
    size_t cmdpos = i;
    r.at = cmdpos;
    if (is_alpha(c) && arg_count(up) >= 0) {
      if (cmd == 0 && up != 'M') return fail(&r, ARCLEN_PD_NO_MOVETO, i);
      cmd = up;
      rel = c != (unsigned char)up;
      i = skip_space(&r, i + 1);
    } else if (cmd == 0) {
      return fail(&r, ARCLEN_PD_NO_MOVETO, i);
    } else if (cmd == 'Z') {
      return fail(&r, ARCLEN_PD_AFTER_Z, i);
    } else if (!((c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-')) {
      return fail(&r, ARCLEN_PD_UNKNOWN, i);
    }
    if (cmd == 'Z') {
      if ((rc = step(&r, cmd, rel, a, cmdpos)) != ARCLEN_PD_OK) return rc;
      i = skip_space(&r, i);
      continue;
    }
    if ((rc = arguments(&r, &i, cmd, a)) != ARCLEN_PD_OK) return rc;
    if ((rc = step(&r, cmd, rel, a, cmdpos)) != ARCLEN_PD_OK) return rc;
    if (cmd == 'M') cmd = 'L';  /* further pairs are implicit linetos */
    i = skip_sep(&r, i);
    /* a trailing comma must be followed by another argument list */
    if (d[i - 1] == ',' && (i >= n || is_alpha((unsigned char)d[i]))) {
      r.at = i - 1;           /* the command before the comma is complete */
      return fail(&r, ARCLEN_PD_COMMA, i - 1);
    }
  }
  return finish(&r);
}

/* ---- the builder ----------------------------------------------------------- */

void arclen_pathbuild_start(arclen_pathbuild *b, arclen_pathdata *pd,
                            double arc_tol, const double *T) {
  start(b, pd, NULL, 0, arc_tol, T);
}

int arclen_pathbuild_add(arclen_pathbuild *b, char cmd, const double *a) {
  int rc;
  if (b->pd->err.kind != ARCLEN_PD_OK) return b->pd->err.kind;  /* sticky */
  if (arg_count(cmd) < 0) return fail(b, ARCLEN_PD_UNKNOWN, 0);
  if (!b->begun && cmd != 'M') return fail(b, ARCLEN_PD_NO_MOVETO, 0);
  b->begun = 1;
  rc = step(b, cmd, 0, a, 0);
  return rc;
}

int arclen_pathbuild_finish(arclen_pathbuild *b) { return finish(b); }
