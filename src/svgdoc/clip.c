/*
** clip.c -- a path's segments cut to an axis-aligned rectangle (a
** marker's viewport, SVG 2 11.6.2 under overflow: hidden), then mapped.
** Each coordinate of each kind is a Bernstein polynomial in t of degree
** at most 3 (a conic's, x(t) - c, has the sign of its numerator, the
** weights (1, w, 1) being positive): the t where it crosses a side are
** found on the pieces where it is monotone (split at the roots of its
** derivative, at most 2), by bisection to the last bit; the sub-ranges
** between crossings whose middle lies inside are kept, through
** arclen_segment_sub.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "arclen.h"
#include "svgdoc/marker.h"

#define MAX_CUTS 26            /* 4 sides x (3 roots + piece ends) + 0, 1 */

/* de Casteljau on b[0 .. d] at t. */
static double bern(const double *b, int d, double t) {
  double c[4];
  int i, j;
  for (i = 0; i <= d; i++) c[i] = b[i];
  for (j = 1; j <= d; j++)
    for (i = 0; i <= d - j; i++) c[i] = c[i] + t * (c[i + 1] - c[i]);
  return c[0];
}

/* The roots in (0, 1) of the Bernstein polynomial b[0 .. d] added to t[]. */
static void roots(const double *b, int d, double *t, int *nt) {
  double piece[4], db[3], p0, p1, p2;
  int np = 0, i, k;
  piece[np++] = 0;
  /* the derivative d (b[i+1] - b[i]) in power form: its roots split [0,1] */
  for (i = 0; i < d; i++) db[i] = b[i + 1] - b[i];
  if (d == 2) {
    double den = db[0] - db[1];                 /* db0 (1-t) + db1 t = 0 */
    if (den != 0) {
      double r = db[0] / den;
      if (r > 0 && r < 1) piece[np++] = r;
    }
  } else if (d == 3) {
    /* db0 (1-t)^2 + 2 db1 t (1-t) + db2 t^2 = p2 t^2 + p1 t + p0 */
    double r[2], disc;
    int nr = 0;
    p0 = db[0], p1 = 2 * (db[1] - db[0]), p2 = db[0] - 2 * db[1] + db[2];
    if (p2 == 0) {
      if (p1 != 0) r[nr++] = -p0 / p1;
    } else if ((disc = p1 * p1 - 4 * p2 * p0) >= 0) {
      double q = -(p1 + (p1 < 0 ? -1 : 1) * sqrt(disc)) / 2;  /* stable */
      if (q != 0) r[nr++] = p0 / q;
      r[nr++] = q / p2;
    }
    if (nr == 2 && r[0] > r[1]) {
      double x = r[0];
      r[0] = r[1], r[1] = x;
    }
    for (k = 0; k < nr; k++)
      if (r[k] > piece[np - 1] && r[k] < 1) piece[np++] = r[k];
  }
  piece[np++] = 1;
  for (k = 0; k + 1 < np; k++) {
    double a = piece[k], c = piece[k + 1], fa = bern(b, d, a), fc = bern(b, d, c);
    int it;
    if (fa == 0 && a > 0) t[(*nt)++] = a;
    if ((fa < 0) == (fc < 0) || fa == 0 || fc == 0) continue;
    for (it = 0; it < 200; it++) {     /* bisection: the last bit, capped */
      double m = a + (c - a) / 2, fm;
      if (m <= a || m >= c) break;
      fm = bern(b, d, m);
      if (fm == 0) { a = c = m; break; }
      if ((fm < 0) == (fa < 0)) a = m, fa = fm;
      else c = m;
    }
    t[(*nt)++] = a + (c - a) / 2;
  }
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* Is the point p inside box (sides included)? */
static int inside(const double *p, const double *box) {
  return p[0] >= box[0] && p[0] <= box[2] && p[1] >= box[1] && p[1] <= box[3];
}

typedef struct out {
  double *rec;
  unsigned char *kinds;
  size_t n, room;
  arclen_subpath *sp;
  size_t nsp, sproom;
} out;

static int put(out *o, unsigned char kind, const double *r) {
  if (o->n == o->room) {
    size_t room = o->room ? 2 * o->room : 16;
    double *p = realloc(o->rec, room * ARCLEN_PD_STRIDE * sizeof *p);
    unsigned char *q;
    if (p == NULL) return -1;
    o->rec = p;
    q = realloc(o->kinds, room);
    if (q == NULL) return -1;
    o->kinds = q, o->room = room;
  }
  memcpy(o->rec + ARCLEN_PD_STRIDE * o->n, r, ARCLEN_PD_STRIDE * sizeof *r);
  o->kinds[o->n++] = kind;
  return 0;
}

static int open_sp(out *o, double x, double y) {
  if (o->nsp == o->sproom) {
    size_t room = o->sproom ? 2 * o->sproom : 8;
    arclen_subpath *p = realloc(o->sp, room * sizeof *p);
    if (p == NULL) return -1;
    o->sp = p, o->sproom = room;
  }
  o->sp[o->nsp].x = x, o->sp[o->nsp].y = y;
  o->sp[o->nsp].first = o->n, o->sp[o->nsp].n = 0, o->sp[o->nsp].closed = 0;
  o->nsp++;
  return 0;
}

/* Segment r of kind letter cut to box into o; *cont: the last piece put
** ended at this segment's start (so a piece from t = 0 continues it). */
static int cut(out *o, unsigned char letter, const double *r,
               const double *box, int *cont) {
  int kind = arclen_segment_kind_of_letter(letter), d, side, nt = 0, k;
  double t[MAX_CUTS], b[4], piece[ARCLEN_PD_STRIDE];
  switch (kind) {
    case ARCLEN_SEG_LINE: d = 1; break;
    case ARCLEN_SEG_QUAD: case ARCLEN_SEG_CONIC: d = 2; break;
    default: d = 3; break;
  }
  t[nt++] = 0;
  for (side = 0; side < 4; side++) {
    int axis = side & 1;
    double c = box[side];
    for (k = 0; k <= d; k++) {
      b[k] = r[2 * k + axis] - c;
      if (kind == ARCLEN_SEG_CONIC && k == 1) b[k] *= r[6];
    }
    roots(b, d, t, &nt);
  }
  t[nt++] = 1;
  qsort(t, (size_t)nt, sizeof *t, cmp);
  for (k = 0; k + 1 < nt; k++) {
    double a = t[k], e = t[k + 1], p[2];
    int j;
    if (!(e > a)) continue;
    arclen_segment_point(kind, 2, r, a + (e - a) / 2, p);
    if (!inside(p, box)) {
      *cont = 0;
      continue;
    }
    /* the kept range runs on while the next ones are inside too */
    for (j = k + 1; j + 1 < nt; j++) {
      double q[2];
      if (!(t[j + 1] > t[j])) continue;
      arclen_segment_point(kind, 2, r, t[j] + (t[j + 1] - t[j]) / 2, q);
      if (!inside(q, box)) break;
      e = t[j + 1];
    }
    memset(piece, 0, sizeof piece);
    if (a == 0 && e == 1) memcpy(piece, r, sizeof piece);
    else arclen_segment_sub(kind, 2, r, a, e, piece);
    if (!(*cont && a == 0) && open_sp(o, piece[0], piece[1]) != 0) return -1;
    if (put(o, (unsigned char)letter, piece) != 0) return -1;
    o->sp[o->nsp - 1].n++;
    *cont = e == 1;
    while (k + 1 < nt && t[k + 1] < e) k++;
  }
  return 0;
}

/* Point x, y mapped by M in place. */
static void map(const double *M, double *x, double *y) {
  double u = M[0] * *x + M[2] * *y + M[4];
  *y = M[1] * *x + M[3] * *y + M[5];
  *x = u;
}

int svgdoc_clip_map(arclen_pathdata *pd, const double *box, const double *M) {
  size_t s, i;
  if (box) {
    out o;
    memset(&o, 0, sizeof o);
    for (s = 0; s < pd->nsubpaths; s++) {
      const arclen_subpath *sp = &pd->subpaths[s];
      int cont = 0, whole = 1;
      size_t first = o.nsp;
      for (i = sp->first; i < sp->first + sp->n; i++) {
        unsigned char letter = pd->kinds ? pd->kinds[i] : ARCLEN_PD_CUBIC;
        size_t before = o.n;
        if (cut(&o, letter, pd->cubics + ARCLEN_PD_STRIDE * i, box, &cont) != 0) {
          free(o.rec), free(o.kinds), free(o.sp);
          arclen_pathdata_free(pd);
          return -1;
        }
        if (o.n != before + 1 || !cont) whole = 0;
      }
      /* a subpath kept whole keeps its Z */
      if (whole && o.nsp == first + 1 && sp->n > 0) o.sp[first].closed = sp->closed;
    }
    free(pd->cubics), free(pd->kinds), free(pd->subpaths);
    pd->cubics = o.rec, pd->kinds = o.kinds, pd->ncubics = o.n;
    pd->cubics_room = o.room;
    pd->subpaths = o.sp, pd->nsubpaths = o.nsp, pd->subpaths_room = o.sproom;
  }
  if (M) {
    for (i = 0; i < pd->ncubics; i++) {
      double *r = pd->cubics + ARCLEN_PD_STRIDE * i;
      unsigned char letter = pd->kinds ? pd->kinds[i] : ARCLEN_PD_CUBIC;
      int k, np = letter == ARCLEN_PD_LINE ? 2 : letter == ARCLEN_PD_CUBIC ? 4 : 3;
      for (k = 0; k < np; k++) map(M, &r[2 * k], &r[2 * k + 1]);
    }
    for (s = 0; s < pd->nsubpaths; s++)
      map(M, &pd->subpaths[s].x, &pd->subpaths[s].y);
  }
  return 0;
}
