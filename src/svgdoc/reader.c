/*
** reader.c -- the walk over expat's events: a frame per open element
** (its CTM, viewport, visibility, stroke, layer), the root's coordinate
** system, the drawn shapes read into cubics and handed over as they
** come, and <use>.  When the document may contain a <use>, the subtrees
** of the elements with an id it refers to (all ids without a scan) are
** kept as their start/end events.  A <use> whose target is complete (and
** so, recursively, the targets of the uses inside it) is expanded at
** once; one that points forwards holds every element drawn after it in a
** queue, in document order, until its target ends (or the document:
** then a missing id is an error); the queue is capped.  A document
** without <use> keeps nothing but the open elements' frames.
*/
#include <expat.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "curve/numeric.h"
#include "svg/decimal.h"
#include "svgdoc/cond.h"
#include "svgdoc/css.h"
#include "svgdoc/internal.h"
#include "svgdoc/marker.h"
#include "svgdoc/paint.h"

#define SVG_NS "http://www.w3.org/2000/svg"
#define XLINK_HREF "http://www.w3.org/1999/xlink\1href"
#define INKSCAPE_GROUPMODE "http://www.inkscape.org/namespaces/inkscape\1groupmode"
#define INKSCAPE_LABEL "http://www.inkscape.org/namespaces/inkscape\1label"

const char *const svgdoc_skipped_tags[SVGDOC_NSKIPPED] = {
  "text", "image", "foreignObject", "video", "audio", "canvas", "iframe",
  "mesh"};

/* Never rendered directly (SVG 2 section 5.6 and the chapters of each);
** their content is drawn only through <use> (symbol) or not at all. */
static const char *const NOT_RENDERED[] = {
  "defs", "symbol", "clipPath", "mask", "marker", "pattern",
  "linearGradient", "radialGradient", "filter", "style", "script", "title",
  "desc", "metadata", "view", "font", "font-face", "cursor", "hatch",
  "solidcolor", "meshgradient"};
static const char *const SHAPES[] = {"path", "rect", "circle", "ellipse",
                                     "line", "polyline", "polygon"};
static const char *const GROUPS[] = {"g", "a", "switch", "svg"};
/* What a fill or stroke of url(#id) may name (SVG 2 section 13.2; librsvg's,
** without SVG 2's at-risk mesh gradients and hatches) */
static const char *const PAINT_SERVERS[] = {"linearGradient", "radialGradient",
                                            "pattern"};
/* The shapes markers are drawn on (SVG 2 section 11.6: markable elements). */
static const char *const MARKABLE[] = {"path", "line", "polyline", "polygon"};
static const char *const MARKER_PROPS[] = {"marker-start", "marker-mid",
                                           "marker-end"};

/* The entry of tag in list[0 .. n-1], or -1. */
static int find_tag(const char *const *list, int n, const char *tag) {
  int k;
  for (k = 0; k < n; k++)       /* the first byte first: a strcmp a name */
    if (list[k][0] == tag[0] && strcmp(list[k], tag) == 0) return k;
  return -1;
}
#define lookup(list, tag) find_tag(list, (int)(sizeof list / sizeof *list), tag)

typedef struct svgdoc_frame {
  svgdoc_mark mark;              /* the tmp pool when it opened */
  size_t depth;
  int skip, top, is_switch, switch_done, visible;
  int props;                     /* paint, sw, mk computed (for markers) */
  svgdoc_paint paint;            /* what its stroke and fill show */
  double sw;                     /* its stroke-width (markerUnits) */
  const char *mk[3];             /* marker-start, -mid, -end ids, or NULL */
  svgdoc_matrix ctm;
  svgdoc_viewport vp;
  const char *layer;
} svgdoc_frame;

/* A <use> to expand: what its element gives the used content. */
typedef struct svgdoc_use {
  const char *href, *id, *layer;
  unsigned long line, col;
  svgdoc_matrix ctm;
  svgdoc_viewport vp;
  int visible, has_w, has_h;
  svgdoc_paint paint;
  double w, h, sw;
  const char *mks[3];            /* the marker properties it passes on */
  const char **chain;            /* the ids being expanded around it */
  size_t nchain;
  svgdoc_marker_set *mset;       /* not a use: a shape's instances of a
                                 ** marker (href), drawn in its place */
  svgdoc_marker_set *inmk;       /* a use inside a marker's content: the
                                 ** instance it is drawn for */
  const char *inmk_id;           /* and that marker's id */
} svgdoc_use;

/* The use a replayed element belongs to. */
typedef struct svgdoc_shadow {
  int root;                      /* the used element itself */
  const svgdoc_use *u;
  const char **chain;
  size_t nchain;
} svgdoc_shadow;

struct svgdoc_held {
  svgdoc_element *e;             /* or a use (malloc'd, its strings with it) */
  svgdoc_use *u;
};

struct svgdoc_event {
  const char *tag;               /* NULL: an end event */
  const char **atts;
  unsigned long line, col;
  size_t close;                  /* the index of its end event (0: open) */
  int svgns;
  int ready;                     /* closed, and so are all its uses' targets */
  svgdoc_marker_def *mdef;       /* a <marker>: what its content inherits */
};

/* Room for one more item in the growing array *a of *room items. */
static void *grow(svgdoc *D, void *a, size_t *room, size_t used,
                  size_t size) {
  if (used == *room) {
    size_t r = *room ? 2 * *room : 64;
    void *p = realloc(a, r * size);
    if (p == NULL) svgdoc_nomem(D);
    *room = r;
    return p;
  }
  return a;
}


/* ---- ids of kept elements, ids referred to ------------------------------ */

static size_t hash(const char *s, size_t n) {
  size_t h = 5381, k;
  for (k = 0; k < n; k++) h = h * 33 + (unsigned char)s[k];
  return h;
}

/* The slot of s[0 .. n-1] in t (empty when absent; t->room > 0). */
static size_t id_slot(const svgdoc_idtable *t, const char *s, size_t n) {
  size_t i = hash(s, n) & (t->room - 1);
  while (t->keys[i] && !(strncmp(t->keys[i], s, n) == 0 && t->keys[i][n] == '\0'))
    i = (i + 1) & (t->room - 1);        /* ends: at most half the slots are full */
  return i;
}

static int find_id(const svgdoc_idtable *t, const char *s, size_t n,
                   size_t *val) {
  size_t i;
  if (t->room == 0) return 0;
  i = id_slot(t, s, n);
  if (t->keys[i] == NULL) return 0;
  if (val) *val = t->vals[i];
  return 1;
}

/* key (a string that lives as long as t) -> val; the first one stays. */
static void add_id(svgdoc *D, svgdoc_idtable *t, const char *key, size_t val) {
  size_t i, n = strlen(key);
  if (2 * (t->n + 1) > t->room) {
    size_t room = t->room ? 2 * t->room : 64, k;
    const char **keys = calloc(room, sizeof *keys);
    size_t *vals = malloc(room * sizeof *vals);
    svgdoc_idtable old = *t;
    if (keys == NULL || vals == NULL) {
      free(keys), free(vals);
      svgdoc_nomem(D);
    }
    t->keys = keys, t->vals = vals, t->room = room;
    for (k = 0; k < old.room; k++) {
      if (old.keys[k]) {
        size_t j = id_slot(t, old.keys[k], strlen(old.keys[k]));
        t->keys[j] = old.keys[k], t->vals[j] = old.vals[k];
      }
    }
    free(old.keys), free(old.vals);
  }
  i = id_slot(t, key, n);
  if (t->keys[i]) return;
  t->keys[i] = key, t->vals[i] = val;
  t->n++;
}

/* The id of a same-document reference "#id" (spaces around trimmed) into
** *id, *n; 0 for any other. */
static int ref_id(const char *href, const char **id, size_t *n) {
  const char *s = href, *e;
  if (s == NULL) return 0;
  while (svgdoc_space((unsigned char)*s)) s++;
  if (*s != '#') return 0;
  e = s + strlen(s);
  while (e > s + 1 && svgdoc_space((unsigned char)e[-1])) e--;
  *id = s + 1, *n = (size_t)(e - s - 1);
  return 1;
}

/* ---- the elements ----------------------------------------------------- */

static const char *copy(svgdoc *D, const char *s) {
  return s ? svgdoc_strdup(D, s, strlen(s)) : NULL;
}

static void free_element(svgdoc_element *e) {
  free(e);                        /* its segments are in its block (draw) */
}

/* Is a use waiting in the queue for its target, so that what is drawn
** now must wait behind it?  (Not while the queue's front is expanded.) */
static int holding(const svgdoc *D) {
  return D->held_tail > D->held_head && !D->draining;
}

/* Room for one more in the queue (its live part moved to the front when
** the room is used up). */
static void held_room(svgdoc *D) {
  if (D->held_tail == D->held_room && D->held_head > 0) {
    memmove(D->held_q, D->held_q + D->held_head,
            (D->held_tail - D->held_head) * sizeof *D->held_q);
    D->held_tail -= D->held_head;
    D->held_head = 0;
  }
  D->held_q = grow(D, D->held_q, &D->held_room, D->held_tail, sizeof *D->held_q);
}

/* Room for one more drawn element where it goes: the results, or the
** queue behind a forward use (capped: they are what the document makes
** the reader keep). */
static void reserve_out(svgdoc *D, unsigned long line, unsigned long col) {
  if (!D->o.stream && D->ndrawn + D->held_elements >= SVGDOC_MAX_ELEMENTS)
    svgdoc_fail(D, line, col, "more than %d drawn elements",
                SVGDOC_MAX_ELEMENTS);
  if (holding(D)) {
    const svgdoc_use *u = D->held_q[D->held_head].u;
    if (D->held_elements >= D->o.max_held)
      svgdoc_fail(D, u->line, u->col, "<use> of '#%s' waits for an element "
                  "not read yet, with more than %lu drawn elements behind it",
                  u->href, (unsigned long)D->o.max_held);
    held_room(D);
    return;
  }
  D->batch = grow(D, D->batch, &D->batch_room, D->nbatch, sizeof *D->batch);
}

/* Hand e over (room reserved): to the results, or into the queue. */
static void emit(svgdoc *D, svgdoc_element *e) {
  if (holding(D)) {
    D->held_q[D->held_tail].e = e, D->held_q[D->held_tail].u = NULL;
    D->held_tail++;
    D->held_elements++;
  } else {
    D->batch[D->nbatch++] = e;
    D->ndrawn++;
  }
}

/* A string into an element's own block at *at (NULL stays NULL). */
static const char *own(char **at, const char *s) {
  char *p;
  size_t n;
  if (s == NULL) return NULL;
  n = strlen(s) + 1;
  p = memcpy(*at, s, n);
  *at += n;
  return p;
}

/* The path data message of pd's error, as arclen.path.svg words it. */
static const char *pathdata_message(svgdoc *D, const arclen_pathdata *pd,
                                    const char *d) {
  size_t n = arclen_pathdata_message(pd, d, NULL, 0);
  char *m = svgdoc_alloc(D, n + 1);
  arclen_pathdata_message(pd, d, m, n + 1);
  if (pd->err.pos)
    return svgdoc_format(D, "%s at position %lu", m,
                         (unsigned long)pd->err.pos);
  return m;
}

/* x in the fewest significant digits that read back as x (locale-free),
** for numbers in messages: 1e+308, not 1.0000000000000001e+308. */
static void short_num(char buf[32], double x) {
  int digits;
  for (digits = 1; digits < 17; digits++) {        /* capped: 17 always reads back */
    double v;
    size_t n = arclen_decimal_print(buf, x, digits);
    if (arclen_decimal_value(buf, n, &v) == 0 && v == x) return;
  }
  arclen_decimal_print(buf, x, 17);
}

/* A basic shape whose arcs cannot be built because of their size (the
** scaled tolerance or the control points beyond the doubles) is named by
** the attributes that give that size, not by the arc's internals; NULL
** for any other error. */
static const char *shape_size_message(svgdoc *D, const arclen_pathdata *pd,
                                      const char *tag, const char **atts) {
  static const char *const CIRCLE[] = {"r", NULL};
  static const char *const ELLIPSE[] = {"rx", "ry", NULL};
  static const char *const RECT[] = {"x", "y", "width", "height", "rx", "ry",
                                     NULL};
  const char *const *names;
  const char *what;
  svgdoc_buffer *b = &D->scratch;
  int k;
  if (pd->err.kind != ARCLEN_PD_ARC ||
      (pd->err.arc != ARCLEN_PD_ARC_TOL && pd->err.arc != ARCLEN_PD_ARC_OVERFLOW &&
       pd->err.arc != ARCLEN_PD_ARC_CUBICS))
    return NULL;
  if (strcmp(tag, "circle") == 0) names = CIRCLE, what = "the radius is";
  else if (strcmp(tag, "ellipse") == 0) names = ELLIPSE, what = "the radii are";
  else if (strcmp(tag, "rect") == 0) names = RECT, what = "the size is";
  else return NULL;
  b->len = 0;
  for (k = 0; names[k]; k++) {
    const char *v = svgdoc_attr(atts, names[k]);
    if (v == NULL) continue;
    if (b->len) svgdoc_append(D, b, " ", 1);
    svgdoc_append(D, b, names[k], strlen(names[k]));
    svgdoc_append(D, b, "='", 2);
    svgdoc_append(D, b, v, strlen(v) > 64 ? 64 : strlen(v));
    svgdoc_append(D, b, "'", 1);
  }
  return svgdoc_format(D, "%s out of range (%s): the shape's arcs reach "
                       "beyond the largest double", what, b->len ? b->s : "");
}

/* Is an error of path data one of its grammar (what SVG 2 section 9.5.4
** renders up to), not a number beyond the doubles or a failed arc? */
static int syntax_error(int kind) {
  switch (kind) {
    case ARCLEN_PD_NO_MOVETO: case ARCLEN_PD_AFTER_Z: case ARCLEN_PD_UNKNOWN:
    case ARCLEN_PD_CLOSE_FIRST: case ARCLEN_PD_NUMBER: case ARCLEN_PD_EXPONENT:
    case ARCLEN_PD_FLAG: case ARCLEN_PD_COMMA:
      return 1;
    default:
      return 0;
  }
}

/* A drawn shape: its segments under the CTM. */
static void draw(svgdoc *D, const svgdoc_frame *f, const char *tag,
                 const svgdoc_shape *shape, const char **atts,
                 unsigned long line, unsigned long col,
                 const svgdoc_shadow *sh) {
  const double *C = f->ctm;
  const char *id = svgdoc_attr(atts, "id");
  /* a marker's content: placed by the instance, clipped to its viewport */
  const svgdoc_marker_set *mk = sh ? (sh->u->mset ? sh->u->mset : sh->u->inmk)
                                   : NULL;
  const char *use = sh && !sh->u->mset ? sh->u->href : NULL;
  const char *marker = mk ? sh->u->mset ? sh->u->href : sh->u->inmk_id : NULL;
  svgdoc_matrix full;
  int identity = C[0] == 1 && C[1] == 0 && C[2] == 0 && C[3] == 1 &&
                 C[4] == 0 && C[5] == 0;
  const char *d;
  svgdoc_shape cut;
  arclen_pathdata *pd = &D->draw_pd;   /* its arrays reused, element to element */
  svgdoc_element *e;
  char *at;
  size_t size, nums = shape->n * sizeof *shape->v, recs, subs;
  reserve_out(D, line, col);
  if (svgdoc_shape_parse(D, pd, shape, identity ? NULL : C, &d) !=
      ARCLEN_PD_OK) {
    const char *m = shape_size_message(D, pd, tag, atts), *what;
    size_t good = pd->err.start;
    if (m == NULL) {
      m = pathdata_message(D, pd, d);
      if (strcmp(tag, "path") == 0) m = svgdoc_format(D, "d: %s", m);
    }
    what = svgdoc_format(D, "<%s%s%s%s>: %s", tag, id ? " id='" : "",
                         id ? id : "", id ? "'" : "", m);
    if (!syntax_error(pd->err.kind) || strcmp(tag, "path") != 0) {
      arclen_pathdata_free(pd);
      svgdoc_fail(D, line, col, "%s", what);
    }
    /* SVG 2 section 9.5.4 (SVG 1.1 F.2): the path is rendered up to the
    ** command that holds the error, which is where the data read so far
    ** ends (a separator left before it is dropped) */
    while (good > 0 && (svgdoc_space((unsigned char)d[good - 1]) ||
                        d[good - 1] == ','))
      good--;
    arclen_pathdata_free(pd);          /* svgdoc_lenient may jump (strict) */
    if (good == 0) {
      svgdoc_lenient(D, line, col, what, "nothing drawn");
      return;
    }
    svgdoc_lenient(D, line, col, what,
            svgdoc_format(D, "drawn up to position %lu", (unsigned long)good));
    cut = *shape;
    cut.d = svgdoc_strdup(D, d, good);
    shape = &cut;                       /* the element keeps the data drawn */
    if (svgdoc_shape_parse(D, pd, shape, identity ? NULL : C, &d) !=
        ARCLEN_PD_OK) {               /* only a range error can be left */
      m = pathdata_message(D, pd, d);
      arclen_pathdata_free(pd);
      svgdoc_fail(D, line, col, "<%s%s%s%s>: d: %s", tag, id ? " id='" : "",
                  id ? id : "", id ? "'" : "", m);
    }
  }
  if (mk) {
    size_t had = pd->ncubics;
    if (svgdoc_clip_map(pd, mk->clip ? mk->box : NULL, mk->outer) != 0)
      svgdoc_nomem(D);
    if (had > 0 && pd->ncubics == 0) return;  /* the marker's clip hides it */
    svgdoc_mul(mk->outer, C, full);
    C = full;
  }
  {
    /* a control point beyond the doubles (a line from -1e308 to 1e308
    ** has its thirds there): the length cannot be a double either */
    size_t k, n = 8 * pd->ncubics;
    double top = 0;
    int finite = 1;
    for (k = 0; k < n; k++) {
      double v = fabs(pd->cubics[k]);
      if (!(v <= DBL_MAX)) finite = 0;
      else if (v > top) top = v;
    }
    if (!finite) {
      char num[32];
      short_num(num, top);
      arclen_pathdata_free(pd);
      svgdoc_fail(D, line, col, "<%s%s%s%s>: the path's length overflows "
                  "(coordinates up to %s)", tag, id ? " id='" : "",
                  id ? id : "", id ? "'" : "", num);
    }
  }
  recs = pd->ncubics * ARCLEN_PD_STRIDE * sizeof *pd->cubics;
  subs = pd->nsubpaths * sizeof *pd->subpaths;
  /* the element, its segments and its strings in one block, its own: it
  ** outlives the open elements' pool (a stream hands it over, the queue
  ** holds it); one allocation an element (the segments' own arrays, grown
  ** and freed, were a sixth of a circle's cost) */
  size = sizeof *e + nums + recs + subs + pd->ncubics +
         (shape->d ? strlen(shape->d) + 1 : 0) +
         (id ? strlen(id) + 1 : 0) + (f->layer ? strlen(f->layer) + 1 : 0) +
         (use ? strlen(use) + 1 : 0) + (marker ? strlen(marker) + 1 : 0);
  e = malloc(size);
  if (e == NULL) svgdoc_nomem(D);
  at = (char *)(e + 1);             /* the numbers first: aligned as e is */
  e->shape = *shape;
  if (nums) e->shape.v = memcpy(at, shape->v, nums);
  at += nums;
  e->pd = *pd;
  e->pd.cubics = recs ? memcpy(at, pd->cubics, recs) : NULL;
  at += recs;
  e->pd.subpaths = subs ? memcpy(at, pd->subpaths, subs) : NULL;
  at += subs;
  e->pd.kinds = pd->ncubics ? memcpy(at, pd->kinds, pd->ncubics) : NULL;
  at += pd->ncubics;
  e->pd.cubics_room = pd->ncubics, e->pd.subpaths_room = pd->nsubpaths;
  e->shape.d = own(&at, shape->d);
  e->id = own(&at, id);
  e->tag = tag;                        /* one of SHAPES */
  e->layer = own(&at, f->layer);
  e->use = own(&at, use);
  e->marker = own(&at, marker);
  e->line = line, e->col = col;
  e->stroked = svgdoc_paint_stroked(&f->paint);
  e->filled = svgdoc_paint_filled(&f->paint, tag);
  memcpy(e->ctm, C, sizeof e->ctm);
  emit(D, e);
}

static void expand(svgdoc *D, const svgdoc_use *u);
static void use_at_top(svgdoc *D, svgdoc_use *u);

/* Is a shape with paint p drawn in the document's mode: every shape, or
** those whose stroke (o.stroked), stroke or fill (o.painted) shows? */
static int shown(const svgdoc *D, const svgdoc_paint *p, const char *tag) {
  if (D->o.stroked) return svgdoc_paint_stroked(p);
  if (D->o.painted)
    return svgdoc_paint_stroked(p) || svgdoc_paint_filled(p, tag);
  return 1;
}

/* Whether a width or height of an <svg>, <symbol> or <use> is given: a
** negative one is invalid, taken as not given (auto, 100% of the
** viewport: SVG 2 reads an invalid geometry property as its initial
** value) with a warning, an error under o.strict. */
static int size_given(svgdoc *D, unsigned long line, unsigned long col,
                      const char *tag, const char *name, int has,
                      double v) {
  return has && !svgdoc_negative(D, line, col, tag, name, v, "taken as auto");
}

/* Is the CTM's linear part [[a c] [b d]] singular: is its smaller
** singular value zero?  Judged on the matrix scaled by a power of two so
** that its largest entry is in [1/2, 1) (exact), where the determinant
** a d - b c (Kahan's fma form, accurate to an ulp or so) can underflow
** only if the singular values' ratio is below ~1e-308: scale(1e-170)
** has a determinant 1e-340, zero in doubles, but singular values 1e-170. */
static int singular(const double *C) {
  double m = 0, a, b, c, d, w, err;
  int k, e;
  for (k = 0; k < 4; k++)
    if (fabs(C[k]) > m) m = fabs(C[k]);
  if (m == 0) return 1;
  (void)frexp(m, &e);
  a = ldexp(C[0], -e), b = ldexp(C[1], -e);
  c = ldexp(C[2], -e), d = ldexp(C[3], -e);
  w = b * c;                          /* Kahan: a d - w, then w's error */
  err = arclen_fma(-b, c, w);
  return arclen_fma(a, d, -w) + err == 0;
}

/* A fill or stroke of url(#id) that names no paint server takes its
** fallback (SVG 2 section 13.2), with a warning: the document is amiss. */
static void paint_servers(svgdoc *D, unsigned long line, unsigned long col,
                          const char **P) {
  static const int which[2] = {SVGDOC_FILL, SVGDOC_STROKE};
  int k;
  for (k = 0; k < 2; k++) {
    const char *v = P[which[k]], *w = svgdoc_paint_server(D, v);
    if (w == v) continue;
    svgdoc_warn(D, line, col, svgdoc_format(D, "%s '%.200s' names no paint "
                                            "server: %s is painted",
                                            svgdoc_prop_name(which[k]), v, w));
    P[which[k]] = w;
  }
}

/* The markers of a drawn shape (SVG 2 11.6.2): for each marker property
** that names one, its instances at the shape's vertices (marker-start the
** first, marker-end the last, marker-mid the others), drawn after the
** shape like a <use> of the marker in its place: at once, or behind the
** queue when the marker is not read yet.  None on the shapes of a
** marker's own content (SVG 2 11.6: markers are not drawn inside
** markers). */
static void markers(svgdoc *D, const svgdoc_frame *f, const char *tag,
                    const svgdoc_shape *shape, unsigned long line,
                    unsigned long col, const svgdoc_shadow *sh) {
  double *v, *all;
  size_t n, k;
  if (lookup(MARKABLE, tag) < 0 || (sh && (sh->u->mset || sh->u->inmk)))
    return;
  n = svgdoc_marker_vertices(D, shape, &v);
  if (n == 0) return;
  all = svgdoc_alloc(D, 3 * n * sizeof *all);
  memcpy(all, v, 3 * n * sizeof *all);
  for (k = 0; k < 3; k++) {
    svgdoc_marker_set *ms;
    svgdoc_use *u;
    size_t first = k == SVGDOC_MK_START ? 0 : k == SVGDOC_MK_MID ? 1 : n - 1;
    size_t count = k != SVGDOC_MK_MID ? 1 : n > 2 ? n - 2 : 0;
    if (f->mk[k] == NULL || count == 0) continue;
    ms = svgdoc_alloc(D, sizeof *ms);
    memset(ms, 0, sizeof *ms);
    ms->which = (int)k, ms->n = count, ms->v = all + 3 * first;
    ms->sw = f->sw, ms->vp = f->vp, ms->tag = tag;
    memcpy(ms->ctm, f->ctm, sizeof ms->ctm);
    u = svgdoc_alloc(D, sizeof *u);
    memset(u, 0, sizeof *u);
    u->href = f->mk[k], u->layer = f->layer;
    u->line = line, u->col = col;
    memcpy(u->ctm, f->ctm, sizeof u->ctm);
    u->vp = f->vp, u->visible = f->visible;
    u->paint = f->paint;             /* context-fill, context-stroke: the shape's */
    u->sw = f->sw;
    u->chain = sh ? sh->chain : NULL;
    u->nchain = sh ? sh->nchain : 0;
    u->mset = ms;
    if (sh) expand(D, u);
    else use_at_top(D, u);
  }
}

/* The child frame f of element (tag, atts) under parent; f->skip when
** nothing inside it is drawn.  sh: the use this element is replayed for. */
static void open_element(svgdoc *D, svgdoc_frame *parent, svgdoc_frame *f,
                         int svgns, const char *tag, const char **atts,
                         unsigned long line, unsigned long col,
                         const svgdoc_shadow *sh) {
  const char *P[SVGDOC_NPROPS], *s;
  svgdoc_css_match M;
  int k, shape, skipped, is_svg = strcmp(tag, "svg") == 0,
                      is_symbol = strcmp(tag, "symbol") == 0;
  f->depth = parent->depth + 1;
  f->skip = 1;
  f->props = 0;
  if (f->depth > (size_t)D->o.max_depth)
    svgdoc_fail(D, line, col, "elements nested deeper than %d", D->o.max_depth);
  if (parent->skip || !svgns) return;            /* a foreign element */
  /* SVG 2 section 5.8: one whose tests fail is not rendered; a switch
  ** renders its first child element that passes */
  if (parent->is_switch && parent->switch_done) return;
  if (!svgdoc_cond_pass(atts, D->lang)) return;
  if (parent->is_switch) parent->switch_done = 1;
  svgdoc_css_for(D, atts, sh == NULL, D->depth, line, col, &M);
  svgdoc_properties(D, line, col, atts, &M, P);
  memcpy(f->ctm, parent->ctm, sizeof f->ctm);
  f->vp = parent->vp;
  f->vp.em = svgdoc_font_size(D, line, col, P[SVGDOC_FONT_SIZE], parent->vp.em,
                              parent->vp.rem);
  f->visible = parent->visible, f->paint = parent->paint;
  f->layer = parent->layer;
  f->top = f->is_switch = f->switch_done = 0;
  if (P[SVGDOC_DISPLAY] && strcmp(P[SVGDOC_DISPLAY], "none") == 0 &&
      !D->o.hidden)
    return;
  if ((s = P[SVGDOC_VISIBILITY]) != NULL) {
    if (strcmp(s, "hidden") == 0 || strcmp(s, "collapse") == 0) f->visible = 0;
    else if (strcmp(s, "visible") == 0) f->visible = 1;
  }
  paint_servers(D, line, col, P);
  svgdoc_paint_apply(&f->paint, P, sh ? &sh->u->paint : NULL);
  f->sw = svgdoc_stroke_width(P[SVGDOC_STROKE_WIDTH], parent->sw, &f->vp);
  for (k = 0; k < 3; k++)
    f->mk[k] = svgdoc_marker_ref(D, P[SVGDOC_MARKER_START + k], parent->mk[k]);
  f->props = 1;
  if (lookup(NOT_RENDERED, tag) >= 0 && !(sh && sh->root && is_symbol)) return;
  skipped = find_tag(svgdoc_skipped_tags, SVGDOC_NSKIPPED, tag);
  if (skipped >= 0) {
    D->skipped[skipped]++;
    return;
  }
  shape = lookup(SHAPES, tag);
  if (shape < 0 && lookup(GROUPS, tag) < 0 && strcmp(tag, "use") != 0 &&
      !is_symbol)
    return;                   /* unknown: SVG 2 section 5.x, not rendered */
  f->skip = 0;
  if ((s = svgdoc_attr(atts, "transform")) != NULL && !is_svg && !is_symbol) {
    svgdoc_matrix T;
    svgdoc_transform(D, line, col, s, T);
    svgdoc_mul(f->ctm, T, f->ctm);
  }
  if (is_svg || is_symbol) {                /* a new viewport (SVG 2 section 8) */
    svgdoc_viewport pvp = parent->vp;      /* with its own font-size for em */
    const svgdoc_viewport *vp = &pvp;
    pvp.em = f->vp.em;
    double x = 0, y = 0, w = 0, h = 0, vb[4];
    int hw, hh;
    svgdoc_matrix V;
    svgdoc_len_attr(D, line, col, atts, "x", 'x', vp, &x);
    svgdoc_len_attr(D, line, col, atts, "y", 'y', vp, &y);
    if (sh && sh->root && sh->u->has_w) {
      hw = 1, w = sh->u->w;
    } else {
      hw = svgdoc_len_attr(D, line, col, atts, "width", 'x', vp, &w);
      hw = size_given(D, line, col, tag, "width", hw, w);
    }
    if (sh && sh->root && sh->u->has_h) {
      hh = 1, h = sh->u->h;
    } else {
      hh = svgdoc_len_attr(D, line, col, atts, "height", 'y', vp, &h);
      hh = size_given(D, line, col, tag, "height", hh, h);
    }
    if ((!hw || !hh) && !vp->has)
      svgdoc_fail(D, line, col, "<%s> without width and height needs a "
                  "viewport", tag);
    if (!hw) w = vp->w;
    if (!hh) h = vp->h;
    if (w == 0 || h == 0) { f->skip = 1; return; }
    svgdoc_translate(x, y, V);
    f->vp.has = 1, f->vp.w = w, f->vp.h = h;
    if (svgdoc_viewbox(D, line, col, svgdoc_attr(atts, "viewBox"), vb)) {
      if (vb[2] == 0 || vb[3] == 0) { f->skip = 1; return; }
      svgdoc_viewbox_matrix(D, line, col, vb,
                            svgdoc_attr(atts, "preserveAspectRatio"), x, y, w,
                            h, V);
      f->vp.w = vb[2], f->vp.h = vb[3];
    }
    svgdoc_mul(f->ctm, V, f->ctm);
  }
  {
    const double *C = f->ctm;
    int k;
    for (k = 0; k < 6; k++)
      if (!isfinite(C[k])) svgdoc_fail(D, line, col, "the transforms overflow");
    if (singular(C)) {                 /* SVG 2 section 8.5: not drawn */
      svgdoc_warn(D, line, col, svgdoc_format(D, "<%s>: singular transform, not drawn", tag));
      f->skip = 1;
      return;
    }
  }
  if (strcmp(tag, "g") == 0) {
    const char *mode = svgdoc_attr(atts, INKSCAPE_GROUPMODE);
    const char *id = svgdoc_attr(atts, "id");
    if (mode && strcmp(mode, "layer") == 0) {
      const char *label = svgdoc_attr(atts, INKSCAPE_LABEL);
      if (label || id) f->layer = copy(D, label ? label : id);
    } else if (parent->top && !sh) {
      D->ngroups++;
      f->layer = id ? copy(D, id) : svgdoc_format(D, "g%lu", (unsigned long)D->ngroups);
    }
  } else if (strcmp(tag, "switch") == 0) {
    f->is_switch = 1;
  }
  if (shape >= 0) {
    svgdoc_shape drawn;
    if (svgdoc_shape_get(D, line, col, tag, atts, &f->vp, &drawn) &&
        (f->visible || D->o.hidden)) {
      if (shown(D, &f->paint, tag))
        draw(D, f, SHAPES[shape], &drawn, atts, line, col, sh);
      if (f->mk[0] || f->mk[1] || f->mk[2])
        markers(D, f, SHAPES[shape], &drawn, line, col, sh);
    }
    f->skip = 1;                     /* shapes have no rendered children */
  } else if (strcmp(tag, "use") == 0) {
    const char *href = svgdoc_attr(atts, "href");
    const svgdoc_viewport *vp = &f->vp;
    double ux = 0, uy = 0, uw = 0, uh = 0;
    int hw, hh;
    if (href == NULL) href = svgdoc_attr(atts, XLINK_HREF);
    svgdoc_len_attr(D, line, col, atts, "x", 'x', vp, &ux);
    svgdoc_len_attr(D, line, col, atts, "y", 'y', vp, &uy);
    hw = svgdoc_len_attr(D, line, col, atts, "width", 'x', vp, &uw);
    hh = svgdoc_len_attr(D, line, col, atts, "height", 'y', vp, &uh);
    hw = size_given(D, line, col, "use", "width", hw, uw);
    hh = size_given(D, line, col, "use", "height", hh, uh);
    s = href;
    while (s && svgdoc_space((unsigned char)*s)) s++;
    if (href == NULL) {
      svgdoc_warn(D, line, col, "<use> without href, nothing drawn");
    } else if (*s != '#') {
      svgdoc_warn(D, line, col, svgdoc_format(D, "<use href='%s'>: only same-document "
           "references (#id) are read, nothing drawn", href));
    } else {
      svgdoc_use *u = svgdoc_alloc(D, sizeof *u);
      const char *e = s + strlen(s);
      svgdoc_matrix M;
      while (e > s + 1 && svgdoc_space((unsigned char)e[-1])) e--;
      u->href = svgdoc_strdup(D, s + 1, (size_t)(e - s - 1));
      u->id = copy(D, svgdoc_attr(atts, "id"));
      u->layer = f->layer;
      u->line = line, u->col = col;
      svgdoc_translate(ux, uy, M);
      svgdoc_mul(f->ctm, M, u->ctm);
      u->vp = *vp;
      u->visible = f->visible, u->paint = f->paint;
      u->has_w = hw, u->w = uw, u->has_h = hh, u->h = uh;
      u->sw = f->sw;
      memcpy(u->mks, f->mk, sizeof u->mks);
      u->mset = NULL;
      u->inmk = sh ? (sh->u->mset ? sh->u->mset : sh->u->inmk) : NULL;
      u->inmk_id = sh ? (sh->u->mset ? sh->u->href : sh->u->inmk_id) : NULL;
      u->chain = sh ? sh->chain : NULL;
      u->nchain = sh ? sh->nchain : 0;
      if (sh) expand(D, u);
      else use_at_top(D, u);
    }
    f->skip = 1;                     /* use's children are not rendered */
  }
}

/* The instances of marker set u->mset: the marker's content (the events
** after the marker's start, before its end) replayed for each vertex
** under the placement marker.c computes, from a frame of what the marker
** element inherits where it stands (SVG 2 11.6.2). */
static void expand_marker(svgdoc *D, const svgdoc_use *u, size_t start,
                          size_t last, svgdoc_frame *stack,
                          const svgdoc_shadow *sh) {
  const svgdoc_event *m = &D->events[start];
  size_t v, i, top;
  for (v = 0; v < u->mset->n; v++) {
    svgdoc_viewport vp;
    if (!svgdoc_marker_place(D, u->mset, v, m->atts, m->mdef, m->line, m->col,
                             &vp))
      continue;
    /* linear in the vertices, but a marker of many elements on many
    ** vertices is still a bomb: the events replayed are capped */
    D->mreplayed += last - start + 1;
    if (D->mreplayed > SVGDOC_MAX_MARKER_REPLAYED)
      svgdoc_fail(D, u->line, u->col, "markers replay more than %ld elements "
                  "(their content's start and end events, per vertex)",
                  (long)SVGDOC_MAX_MARKER_REPLAYED);
    memset(&stack[0], 0, sizeof stack[0]);
    svgdoc_translate(0, 0, stack[0].ctm);  /* the content's own coordinates */
    stack[0].vp = vp;
    stack[0].visible = m->mdef->visible, stack[0].paint = m->mdef->paint;
    stack[0].sw = m->mdef->sw, stack[0].props = 1;
    stack[0].layer = u->layer;
    for (i = start + 1, top = 0; i < last; i++) {
      const svgdoc_event *x = &D->events[i];
      if (x->tag) {
        open_element(D, &stack[top], &stack[top + 1], x->svgns, x->tag,
                     x->atts, x->line, x->col, sh);
        top++;
      } else {
        top--;
      }
    }
  }
}

/* Expand the use u now (the whole document has been read): replay its
** target's events under a frame made from the use. */
static void expand(svgdoc *D, const svgdoc_use *u) {
  size_t start, last, i, k, top = 0;
  svgdoc_frame *stack;
  svgdoc_shadow root_sh, sh;
  const char **chain;
  if (!find_id(&D->ids, u->href, strlen(u->href), &start)) {
    /* SVG 2 section 5.6: a use with an invalid reference is not rendered */
    svgdoc_lenient(D, u->line, u->col, u->mset
            ? svgdoc_format(D, "%s of '#%s': no <marker> has that id",
                            MARKER_PROPS[u->mset->which], u->href)
            : svgdoc_format(D, "<use> of '#%s': no element has that id",
                            u->href), "nothing drawn");
    return;
  }
  if (u->mset && (!D->events[start].svgns || D->events[start].mdef == NULL ||
                  strcmp(D->events[start].tag, "marker") != 0)) {
    /* kept for a <use>, but no marker: an invalid reference (SVG 2 11.6.2) */
    svgdoc_lenient(D, u->line, u->col, svgdoc_format(D, "%s of '#%s': the element "
            "with that id is not a <marker>", MARKER_PROPS[u->mset->which],
            u->href), "nothing drawn");
    return;
  }
  for (k = 0; k < u->nchain; k++) {
    if (strcmp(u->chain[k], u->href) == 0) {
      svgdoc_buffer *b = &D->scratch;
      size_t j;
      if (k + 1 == u->nchain)
        svgdoc_fail(D, u->line, u->col, "<use> of '#%s' refers to itself (or "
                    "to an element that contains it)", u->href);
      b->len = 0;
      for (j = k; j < u->nchain; j++) {
        svgdoc_append(D, b, u->chain[j], strlen(u->chain[j]));
        svgdoc_append(D, b, " -> ", 4);
      }
      svgdoc_append(D, b, u->href, strlen(u->href));
      svgdoc_fail(D, u->line, u->col, "<use> of '#%s' makes a cycle (%s)",
                  u->href, b->s);
    }
  }
  if (u->nchain >= SVGDOC_MAX_USE_DEPTH)
    svgdoc_fail(D, u->line, u->col, "<use> nested deeper than %d",
                SVGDOC_MAX_USE_DEPTH);
  last = D->events[start].close;
  if (last == 0)                   /* still open: the use is inside it */
    svgdoc_fail(D, u->line, u->col, "<use> of '#%s' refers to itself (or "
                "to an element that contains it)", u->href);
  chain = svgdoc_alloc(D, (u->nchain + 1) * sizeof *chain);
  if (u->nchain) memcpy(chain, u->chain, u->nchain * sizeof *chain);
  chain[u->nchain] = u->href;
  if (u->mset == NULL) {                 /* markers have their own budget */
    D->replayed += last - start + 1;
    if (D->replayed > SVGDOC_MAX_REPLAYED)
      svgdoc_fail(D, u->line, u->col, "<use> expansions replay more than %d "
                  "elements", SVGDOC_MAX_REPLAYED);
  }
  root_sh.root = 1, root_sh.u = u, root_sh.chain = chain;
  root_sh.nchain = u->nchain + 1;
  sh = root_sh;
  sh.root = 0;
  /* one frame stack per level of nested uses, made once and reused (a
  ** use inside the replay is one level deeper) */
  stack = D->xstacks[u->nchain];
  if (stack == NULL) {
    stack = malloc(((size_t)D->o.max_depth + 2) * sizeof *stack);
    if (stack == NULL) svgdoc_nomem(D);
    D->xstacks[u->nchain] = stack;
  }
  memset(&stack[0], 0, sizeof stack[0]);
  if (u->mset) {
    expand_marker(D, u, start, last, stack, &sh);
    return;
  }
  memcpy(stack[0].ctm, u->ctm, sizeof stack[0].ctm);
  stack[0].vp = u->vp;
  stack[0].visible = u->visible, stack[0].paint = u->paint;
  stack[0].layer = u->layer;
  stack[0].sw = u->sw, stack[0].props = 1;
  memcpy(stack[0].mk, u->mks, sizeof stack[0].mk);
  for (i = start; i <= last; i++) {
    const svgdoc_event *x = &D->events[i];
    if (x->tag) {
      open_element(D, &stack[top], &stack[top + 1], x->svgns, x->tag, x->atts,
                   x->line, x->col, i == start ? &root_sh : &sh);
      top++;
    } else {
      top--;
    }
  }
}

/* ---- uses at the top level: at once, or behind the queue ---------------- */

/* Can the use of id[0 .. n-1] be expanded now: is its target complete,
** and so (recursively) the targets of the uses inside it?  A target
** proven so stays so (ev->ready).  When not, *waiting is the id to wait
** for.  A cycle or a chain deeper than the cap counts as ready: the
** expansion reports it.  budget bounds the work of one question. */
static int ready(svgdoc *D, const char *id, size_t n, size_t depth,
                 size_t *budget, const char **waiting, size_t *wlen) {
  size_t start, i;
  svgdoc_event *ev;
  if (!find_id(&D->ids, id, n, &start) || D->events[start].close == 0) {
    if (!find_id(&D->ids, id, n, NULL) && svgdoc_bloom_absent(D, id, n, 0))
      return 1;                          /* never comes: expanding warns */
    *waiting = id, *wlen = n;
    return 0;
  }
  ev = &D->events[start];
  if (ev->ready || depth >= SVGDOC_MAX_USE_DEPTH) return 1;
  ev->ready = 2;                         /* on the way: a cycle */
  for (i = start + 1; i < ev->close; i++) {
    const svgdoc_event *x = &D->events[i];
    const char *rid, *href;
    size_t rn, at;
    if (x->tag == NULL || !x->svgns || strcmp(x->tag, "use") != 0) continue;
    if (*budget == 0) {                  /* too much to tell: wait for the end */
      ev->ready = 0;
      *waiting = "", *wlen = 0;
      return 0;
    }
    --*budget;
    href = svgdoc_attr(x->atts, "href");
    if (href == NULL) href = svgdoc_attr(x->atts, XLINK_HREF);
    if (!ref_id(href, &rid, &rn)) continue;
    if (find_id(&D->ids, rid, rn, &at) && D->events[at].ready) continue;
    if (!ready(D, rid, rn, depth + 1, budget, waiting, wlen)) {
      ev->ready = 0;
      return 0;
    }
  }
  ev->ready = 1;
  return 1;
}

/* Expand u with the open element's pool given back after. */
static void expand_top(svgdoc *D, const svgdoc_use *u) {
  svgdoc_mark m;
  svgdoc_mark_get(D, &m);
  expand(D, u);
  svgdoc_release(D, &m);
}

/* Hand over what the queue holds, in order, up to a use that must still
** wait (all of it when force: the document has ended). */
static void drain(svgdoc *D, int force) {
  while (D->held_head < D->held_tail) {
    svgdoc_held *h = &D->held_q[D->held_head];
    if (h->e) {
      D->batch = grow(D, D->batch, &D->batch_room, D->nbatch, sizeof *D->batch);
      D->batch[D->nbatch++] = h->e;
      D->ndrawn++;
      D->held_elements--;
    } else {
      size_t budget = SVGDOC_MAX_REPLAYED;
      if (!force && !ready(D, h->u->href, strlen(h->u->href), 0, &budget,
                           &D->waiting, &D->waiting_len))
        return;
      D->expanding_use = h->u;           /* freed even if it fails */
      D->held_head++;
      D->draining = 1;
      expand_top(D, D->expanding_use);
      D->draining = 0;
      free(D->expanding_use);
      D->expanding_use = NULL;
      continue;
    }
    D->held_head++;
  }
  D->held_head = D->held_tail = 0;
  D->waiting = NULL;
}

/* A <use> met in the document's own order: expanded now when nothing
** waits and its target is complete; else it waits in the queue (a copy
** with its strings: u lives in the open element's pool). */
static void use_at_top(svgdoc *D, svgdoc_use *u) {
  svgdoc_use *c;
  char *at;
  size_t budget = SVGDOC_MAX_REPLAYED, size;
  int k;
  if (!D->record ||               /* nothing kept: the missing id, now */
      (svgdoc_bloom_absent(D, u->href, strlen(u->href), 0) &&
       !find_id(&D->ids, u->href, strlen(u->href), NULL)) ||
      (!holding(D) && ready(D, u->href, strlen(u->href), 0, &budget,
                            &D->waiting, &D->waiting_len))) {
    expand_top(D, u);
    return;
  }
  held_room(D);
  /* a marker set's vertices first (aligned as c is), then the strings */
  size = sizeof *c + strlen(u->href) + 1 + (u->id ? strlen(u->id) + 1 : 0) +
         (u->layer ? strlen(u->layer) + 1 : 0);
  if (u->mset) size += sizeof *u->mset + 3 * u->mset->n * sizeof(double);
  for (k = 0; k < 3; k++) size += u->mks[k] ? strlen(u->mks[k]) + 1 : 0;
  c = malloc(size);
  if (c == NULL) svgdoc_nomem(D);
  *c = *u;
  at = (char *)(c + 1);
  if (u->mset) {
    c->mset = memcpy(at, u->mset, sizeof *u->mset);
    at += sizeof *u->mset;
    c->mset->v = memcpy(at, u->mset->v, 3 * u->mset->n * sizeof(double));
    at += 3 * u->mset->n * sizeof(double);
  }
  c->href = own(&at, u->href);
  c->id = own(&at, u->id);
  c->layer = own(&at, u->layer);
  for (k = 0; k < 3; k++) c->mks[k] = own(&at, u->mks[k]);
  c->chain = NULL, c->nchain = 0;        /* at the top level */
  if (D->waiting == u->href) D->waiting = c->href;   /* u's pool goes */
  if (!holding(D)) D->held_head = D->held_tail = 0;
  D->held_q[D->held_tail].e = NULL, D->held_q[D->held_tail].u = c;
  D->held_tail++;
}

/* ---- the root ------------------------------------------------------------ */

/* The root element: the document's coordinate system (SVG 2 section 8.2). */
static void open_root(svgdoc *D, const char **atts, unsigned long line,
                      unsigned long col, svgdoc_frame *f) {
  const char *P[SVGDOC_NPROPS], *s;
  svgdoc_css_match M;
  double vb[4], w = 0, h = 0;
  int has_vb = svgdoc_viewbox(D, line, col, svgdoc_attr(atts, "viewBox"), vb);
  int hw = 0, hh = 0;
  svgdoc_viewport none = {0, 0, 0, 16, 16};
  const char *ws = svgdoc_attr(atts, "width"), *hs = svgdoc_attr(atts, "height");
  /* the root's font-size: its em, and rem everywhere (CSS Values 3 6.1.1;
  ** on the root, em and rem refer to the initial value) */
  svgdoc_css_for(D, atts, 1, 0, line, col, &M);
  svgdoc_properties(D, line, col, atts, &M, P);
  none.em = none.rem = svgdoc_font_size(D, line, col, P[SVGDOC_FONT_SIZE],
                                        16, 16);
  if (ws && !strchr(ws, '%'))
    hw = svgdoc_len_attr(D, line, col, atts, "width", 'x', &none, &w);
  if (hs && !strchr(hs, '%'))
    hh = svgdoc_len_attr(D, line, col, atts, "height", 'y', &none, &h);
  hw = size_given(D, line, col, "svg", "width", hw, w);
  hh = size_given(D, line, col, "svg", "height", hh, h);
  memset(f, 0, sizeof *f);
  f->depth = 1;
  f->vp.em = f->vp.rem = none.em;
  if (has_vb) f->vp.has = 1, f->vp.w = vb[2], f->vp.h = vb[3];
  else if (hw && hh) f->vp.has = 1, f->vp.w = w, f->vp.h = h;
  svgdoc_translate(0, 0, f->ctm);
  if (D->o.unit_px > 0) {
    /* the viewBox onto width x height (a missing or percentage width: the
    ** viewBox's own size, one user unit per px), then px into the unit */
    svgdoc_matrix V, K;
    double k = 1 / D->o.unit_px;
    svgdoc_translate(0, 0, V);
    if (has_vb && vb[2] > 0 && vb[3] > 0)
      svgdoc_viewbox_matrix(D, line, col, vb,
                            svgdoc_attr(atts, "preserveAspectRatio"), 0, 0,
                            hw ? w : vb[2], hh ? h : vb[3], V);
    K[0] = k, K[1] = 0, K[2] = 0, K[3] = k, K[4] = 0, K[5] = 0;
    svgdoc_mul(K, V, f->ctm);
  }
  D->info.has_width = hw, D->info.width = w;
  D->info.has_height = hh, D->info.height = h;
  D->info.has_viewbox = has_vb;
  if (has_vb) memcpy(D->info.viewbox, vb, sizeof vb);
  f->skip = 1;
  if (has_vb && (vb[2] == 0 || vb[3] == 0)) {
    svgdoc_warn(D, line, col, "viewBox of zero width or height: nothing drawn");
    return;
  }
  if ((hw && w == 0) || (hh && h == 0)) {
    svgdoc_warn(D, line, col, "width or height zero: nothing drawn");
    return;
  }
  f->visible = 1, f->layer = "(root)", f->top = 1;
  svgdoc_paint_initial(&f->paint);
  if (P[SVGDOC_DISPLAY] && strcmp(P[SVGDOC_DISPLAY], "none") == 0 &&
      !D->o.hidden)
    return;
  if (!svgdoc_cond_pass(atts, D->lang)) return;  /* SVG 2 section 5.8.2 */
  f->skip = 0;
  if ((s = P[SVGDOC_VISIBILITY]) != NULL &&
      (strcmp(s, "hidden") == 0 || strcmp(s, "collapse") == 0))
    f->visible = 0;
  paint_servers(D, line, col, P);
  svgdoc_paint_apply(&f->paint, P, NULL);
  f->sw = svgdoc_stroke_width(P[SVGDOC_STROKE_WIDTH], 1, &f->vp);
  f->mk[0] = svgdoc_marker_ref(D, P[SVGDOC_MARKER_START], NULL);
  f->mk[1] = svgdoc_marker_ref(D, P[SVGDOC_MARKER_MID], NULL);
  f->mk[2] = svgdoc_marker_ref(D, P[SVGDOC_MARKER_END], NULL);
  f->props = 1;
  if ((s = svgdoc_attr(atts, "transform")) != NULL) {  /* SVG 2 allows it */
    svgdoc_matrix T;
    svgdoc_transform(D, line, col, s, T);
    svgdoc_mul(f->ctm, T, f->ctm);
  }
}

/* ---- expat's callbacks ---------------------------------------------------- */

static void position(svgdoc *D, unsigned long *line, unsigned long *col) {
  *line = (unsigned long)XML_GetCurrentLineNumber((XML_Parser)D->parser);
  *col = (unsigned long)XML_GetCurrentColumnNumber((XML_Parser)D->parser) + 1;
}

/* Does s[0 .. n-1] contain what could be a <use> or <marker> element? */
static int may_use(const char *s, size_t n) {
  size_t i;
  for (i = 0; i + 4 <= n; i++)
    if ((s[i] == '<' || s[i] == ':') && (memcmp(s + i + 1, "use", 3) == 0 ||
                                         (i + 7 <= n && memcmp(s + i + 1, "marker", 6) == 0)))
      return 1;
  return 0;
}

/* The event of an element kept for <use>: its attributes copied. */
static void keep(svgdoc *D, int svgns, const char *tag, const char **atts,
                 unsigned long line, unsigned long col, const char *id) {
  size_t n = 0, k;
  svgdoc_event *x;
  const char **a;
  svgdoc_css_match M;
  int css = svgdoc_css_any(D);
  while (atts[n]) n += 2;
  /* the sheets' declarations as they match here, in the document: the
  ** used copies take them (SVG 2 section 5.6.2) */
  if (css) svgdoc_css_match_node(D, D->depth, line, col, &M);
  D->events = grow(D, D->events, &D->events_room, D->nevents, sizeof *D->events);
  D->arena = &D->keep;                   /* kept as long as the document */
  a = svgdoc_alloc(D, (n + 1 + (css ? 4 * SVGDOC_NPROPS : 0)) * sizeof *a);
  for (k = 0; k < n; k++) a[k] = copy(D, atts[k]);
  a[n] = NULL;
  if (css) svgdoc_css_store(D, &M, a, n);
  x = &D->events[D->nevents];
  x->tag = copy(D, tag), x->atts = a, x->line = line, x->col = col;
  D->arena = &D->tmp;
  x->close = 0, x->svgns = svgns, x->ready = 0, x->mdef = NULL;
  D->open_ev[D->rec++] = D->nevents;
  if (id) add_id(D, &D->ids, svgdoc_attr(a, "id"), D->nevents);
  D->nevents++;
}

/* Element (atts) at depth (its ancestors open below it) applied to what a
** marker's content inherits: its cascaded properties (sheets matched
** live), whatever its display. */
static void marker_inherit(svgdoc *D, svgdoc_marker_def *m,
                           svgdoc_viewport *vp, const char **atts,
                           size_t depth, unsigned long line,
                           unsigned long col) {
  const char *P[SVGDOC_NPROPS], *s;
  svgdoc_css_match M;
  svgdoc_css_for(D, atts, 1, depth, line, col, &M);
  svgdoc_properties(D, line, col, atts, &M, P);
  vp->em = m->em = svgdoc_font_size(D, line, col, P[SVGDOC_FONT_SIZE], m->em,
                                    vp->rem);
  if ((s = P[SVGDOC_VISIBILITY]) != NULL) {
    if (strcmp(s, "hidden") == 0 || strcmp(s, "collapse") == 0) m->visible = 0;
    else if (strcmp(s, "visible") == 0) m->visible = 1;
  }
  /* warned of where the element itself was read */
  P[SVGDOC_FILL] = svgdoc_paint_server(D, P[SVGDOC_FILL]);
  P[SVGDOC_STROKE] = svgdoc_paint_server(D, P[SVGDOC_STROKE]);
  svgdoc_paint_apply(&m->paint, P, NULL);
  m->sw = svgdoc_stroke_width(P[SVGDOC_STROKE_WIDTH], m->sw, vp);
  s = P[SVGDOC_OVERFLOW];              /* the marker's own counts (the last) */
  m->clip = !(s && (strcmp(s, "visible") == 0 || strcmp(s, "auto") == 0));
}

/* What the content of the <marker> (atts) starting now inherits: its own
** properties over those of its ancestors (SVG 2 11.6.2: from the marker's
** ancestors, whatever their display, never from the shape that references
** it): from the nearest ancestor whose frame computed them, then down the
** open elements whose frames did not (inside <defs>, display:none), as
** the style sheets' matcher keeps them; and its overflow (the UA sheet's
** hidden: clipped to its viewport unless visible or auto). */
static svgdoc_marker_def *marker_def(svgdoc *D, const char **atts,
                                     unsigned long line, unsigned long col) {
  svgdoc_marker_def *m;
  svgdoc_viewport vp = {0, 0, 0, 16, 16};
  size_t k, from = 0;
  D->arena = &D->keep;
  m = svgdoc_alloc(D, sizeof *m);
  D->arena = &D->tmp;
  svgdoc_paint_initial(&m->paint);
  m->visible = 1, m->sw = 1, m->em = 16;
  if (D->depth > 0) vp.em = vp.rem = m->em = D->stack[0].vp.rem;
  for (k = D->depth; k-- > 0;)
    if (D->stack[k].props) {
      const svgdoc_frame *a = &D->stack[k];
      m->paint = a->paint, m->visible = a->visible, m->sw = a->sw;
      m->em = a->vp.em, vp = a->vp;
      from = k + 1;
      break;
    }
  for (k = from; k < D->depth; k++)
    marker_inherit(D, m, &vp, D->nodes[k].atts, k, line, col);
  marker_inherit(D, m, &vp, atts, D->depth, line, col);
  return m;
}

/* Is the subtree of the element with this id (NULL: none) kept for
** <use>: inside a kept one, or an id that a use may refer to? */
static int kept(const svgdoc *D, const char *id) {
  if (!D->record) return 0;
  if (D->rec > 0) return 1;
  return id && (!D->refs_given || find_id(&D->refs, id, strlen(id), NULL));
}

static void start_element(svgdoc *D, const char *qname, const char **atts) {
  svgdoc_frame *parent = D->depth ? &D->stack[D->depth - 1] : NULL;
  const char *tag = strchr(qname, '\1'), *id;
  unsigned long line, col;
  int svgns, keep_it;
  svgdoc_mark m;
  if (D->depth >= (size_t)D->o.max_depth) {
    position(D, &line, &col);
    svgdoc_fail(D, line, col, "elements nested deeper than %d", D->o.max_depth);
  }
  /* what this element takes from the pool is given back at its end */
  svgdoc_mark_get(D, &m);
  D->stack[D->depth].mark = m;
  svgns = tag == NULL || ((size_t)(tag - qname) == strlen(SVG_NS) &&
                          memcmp(qname, SVG_NS, strlen(SVG_NS)) == 0);
  /* every element, as selectors see it (a sheet may come later) */
  svgdoc_css_open(D, D->depth, tag ? tag + 1 : qname, atts);
  if (svgns && strcmp(tag ? tag + 1 : qname, "style") == 0) {
    position(D, &line, &col);
    svgdoc_css_style_start(D, atts, D->depth, line, col);
  } else if (svgns && (lookup(SHAPES, tag ? tag + 1 : qname) >= 0 ||
                       strcmp(tag ? tag + 1 : qname, "use") == 0)) {
    D->shapes_seen++;                    /* what a later sheet cannot style */
  }
  id = svgdoc_attr(atts, "id");
  keep_it = kept(D, id);
  /* inside a subtree that draws nothing and is not kept for <use>, only
  ** the depth counts */
  if (parent && parent->skip && !keep_it) {
    D->stack[D->depth].skip = 1;
    D->stack[D->depth].props = 0;
    D->stack[D->depth].depth = parent->depth + 1;
    D->depth++;
    return;
  }
  position(D, &line, &col);
  tag = tag ? tag + 1 : qname;
  if (!D->root_seen) {
    D->root_seen = 1;
    if (strcmp(tag, "svg") != 0 || !svgns) {
      if (tag != qname)
        svgdoc_fail(D, line, col, "not an SVG document: the root element is "
                    "<%s> in namespace %.*s", tag, (int)(tag - 1 - qname), qname);
      svgdoc_fail(D, line, col, "not an SVG document: the root element is <%s>",
                  tag);
    }
    open_root(D, atts, line, col, &D->stack[0]);
    D->stack[0].mark = m;
    D->depth = 1;
    return;
  }
  if (keep_it) {
    keep(D, svgns, tag, atts, line, col, id);
    atts = D->events[D->nevents - 1].atts;
    tag = D->events[D->nevents - 1].tag;
    if (svgns && strcmp(tag, "marker") == 0)
      D->events[D->nevents - 1].mdef = marker_def(D, atts, line, col);
  }
  open_element(D, &D->stack[D->depth - 1], &D->stack[D->depth], svgns, tag,
               atts, line, col, NULL);
  D->depth++;
}

static void end_element(svgdoc *D) {
  if (D->rec > 0) {
    const svgdoc_event *x;
    const char *id;
    D->events = grow(D, D->events, &D->events_room, D->nevents, sizeof *D->events);
    D->events[D->nevents].tag = NULL;
    D->events[D->nevents].ready = 0;
    D->events[D->nevents].mdef = NULL;
    x = &D->events[D->open_ev[D->rec - 1]];
    D->events[D->open_ev[D->rec - 1]].close = D->nevents;
    D->nevents++;
    D->rec--;
    id = svgdoc_attr(x->atts, "id");
    /* the element the queue's front waits for is complete: try again */
    if (id && D->held_tail > D->held_head && D->waiting && D->waiting_len > 0 &&
        strncmp(id, D->waiting, D->waiting_len) == 0 && id[D->waiting_len] == '\0')
      drain(D, 0);
  }
  if (D->style_depth) svgdoc_css_style_end(D, D->depth - 1);
  svgdoc_css_close(D, D->depth - 1);
  D->depth--;
  svgdoc_release(D, &D->stack[D->depth].mark);
}

static void entity_decl(svgdoc *D, const char *name, const char *value,
                        int value_length, const char *system) {
  unsigned long line, col;
  D->nentities++;
  position(D, &line, &col);
  if (D->nentities > SVGDOC_MAX_ENTITIES)
    svgdoc_fail(D, line, col, "more than %d entity declarations",
                SVGDOC_MAX_ENTITIES);
  if (system) return;                  /* external: expat does not read it */
  if (value && (memchr(value, '&', (size_t)value_length) ||
                value_length > SVGDOC_MAX_ENTITY_LEN))
    svgdoc_fail(D, line, col, "entity '%s' refers to other entities or is "
                "longer than %d bytes (entity expansion is refused)", name,
                SVGDOC_MAX_ENTITY_LEN);
  if (value && may_use(value, (size_t)value_length)) D->record = 1;
}

/* Each callback catches the located errors of the work it starts and
** stops the parser (later callbacks do nothing). */
#define CATCH(D, work)                                   \
  do {                                                   \
    jmp_buf jb;                                          \
    if ((D)->failed) return;                             \
    (D)->on_error = &jb;                                 \
    if (setjmp(jb) == 0) {                               \
      work;                                              \
    } else {                                             \
      XML_StopParser((XML_Parser)(D)->parser, XML_FALSE); \
    }                                                    \
    (D)->on_error = NULL;                                \
  } while (0)

static void XMLCALL on_start(void *ud, const XML_Char *name,
                             const XML_Char **atts) {
  svgdoc *D = ud;
  CATCH(D, start_element(D, name, atts));
}

static void XMLCALL on_end(void *ud, const XML_Char *name) {
  svgdoc *D = ud;
  (void)name;
  CATCH(D, end_element(D));
}

static void XMLCALL on_text(void *ud, const XML_Char *s, int len) {
  svgdoc *D = ud;
  if (D->style_depth == 0) return;        /* only a <style>'s text is read */
  CATCH(D, svgdoc_css_text(D, s, (size_t)len));
}

static void XMLCALL on_entity(void *ud, const XML_Char *name, int is_param,
                              const XML_Char *value, int value_length,
                              const XML_Char *base, const XML_Char *system,
                              const XML_Char *public_id,
                              const XML_Char *notation) {
  svgdoc *D = ud;
  (void)is_param, (void)base, (void)public_id, (void)notation;
  CATCH(D, entity_decl(D, name, value, value_length, system));
}

/* A style sheet linked by <?xml-stylesheet?> is not fetched (as @import is
** not): say so, since the paint it would give is then missing. */
static void style_pi(svgdoc *D, const char *target, const char *data) {
  unsigned long line, col;
  if (strcmp(target, "xml-stylesheet") != 0) return;
  position(D, &line, &col);
  svgdoc_warn(D, line, col, svgdoc_format(D, "<?xml-stylesheet %.200s?> is "
                                          "not read: its rules do not apply",
                                          data ? data : ""));
}

static void XMLCALL on_pi(void *ud, const XML_Char *target,
                          const XML_Char *data) {
  svgdoc *D = ud;
  CATCH(D, style_pi(D, target, data));
}

/* ---- the document ------------------------------------------------------- */

svgdoc *svgdoc_new(const svgdoc_options *o) {
  svgdoc *D = calloc(1, sizeof *D);
  if (D == NULL) return NULL;
  D->o = *o;
  D->lang = svgdoc_message("%s", o->lang ? o->lang : SVGDOC_DEFAULT_LANG);
  D->o.lang = NULL;                      /* the caller's: D->lang is ours */
  if (D->o.max_held == 0 || D->o.max_held > SVGDOC_MAX_HELD)
    D->o.max_held = SVGDOC_MAX_HELD;
  D->record = o->uses;
  D->arena = &D->tmp;
  D->stack = malloc(((size_t)o->max_depth + 2) * sizeof *D->stack);
  D->open_ev = malloc(((size_t)o->max_depth + 2) * sizeof *D->open_ev);
  D->nodes = malloc(((size_t)o->max_depth + 2) * sizeof *D->nodes);
  D->parser = XML_ParserCreateNS(NULL, '\1');
  if (D->stack == NULL || D->open_ev == NULL || D->nodes == NULL ||
      D->parser == NULL || D->lang == NULL) {
    svgdoc_free(D);
    return NULL;
  }
  XML_SetUserData((XML_Parser)D->parser, D);
  XML_SetElementHandler((XML_Parser)D->parser, on_start, on_end);
  XML_SetEntityDeclHandler((XML_Parser)D->parser, on_entity);
  XML_SetCharacterDataHandler((XML_Parser)D->parser, on_text);
  XML_SetProcessingInstructionHandler((XML_Parser)D->parser, on_pi);
  return D;
}

void svgdoc_free(svgdoc *D) {
  size_t k;
  if (D == NULL) return;
  if (D->parser) XML_ParserFree((XML_Parser)D->parser);
  if (D->scanner) XML_ParserFree((XML_Parser)D->scanner);
  for (k = 0; k < D->nbatch; k++) free_element(D->batch[k]);
  for (k = D->held_head; k < D->held_tail; k++) {
    free_element(D->held_q[k].e);
    free(D->held_q[k].u);
  }
  free(D->expanding_use);
  arclen_pathdata_free(&D->draw_pd);
  svgdoc_free_pool(D);
  for (k = 0; k < SVGDOC_NPROPS; k++) free(D->props[k].s);
  for (k = 0; k <= SVGDOC_MAX_USE_DEPTH; k++) free(D->xstacks[k]);
  free(D->scratch.s), free(D->held.s), free(D->marker_buf.s);
  svgdoc_css_free(D);
  free(D->nodes), free(D->style_text.s), free(D->style_media.s);
  free(D->stack), free(D->open_ev), free(D->events);
  free(D->ids.keys), free(D->ids.vals), free(D->refs.keys), free(D->refs.vals);
  free(D->held_q), free(D->batch), free(D->warnings), free(D->err_msg);
  free(D->lang);
  free(D->id_bloom);
  free(D);
}

/* ---- the scan for the ids uses refer to ------------------------------- */

static void end_scan(svgdoc *D) {
  if (D->scanner == NULL) return;
  /* the whole document scanned (well-formed to its end): its ids known */
  if (!D->scan_lost && XML_Parse((XML_Parser)D->scanner, NULL, 0, 1) ==
      XML_STATUS_OK)
    D->ids_known = 1;
  XML_ParserFree((XML_Parser)D->scanner);
  D->scanner = NULL;
}

/* Is the element of expanded name qname, whose local name is tag, in SVG's
** namespace (or in none: a document without xmlns is read as SVG)? */
static int in_svg_ns(const char *qname, const char *tag) {
  return tag == qname || ((size_t)(tag - 1 - qname) == strlen(SVG_NS) &&
                          memcmp(qname, SVG_NS, strlen(SVG_NS)) == 0);
}

static void XMLCALL on_scan_start(void *ud, const XML_Char *qname,
                                  const XML_Char **atts) {
  svgdoc *D = ud;
  const char *tag = strchr(qname, '\1'), *href, *id;
  size_t n;
  jmp_buf jb;
  tag = tag ? tag + 1 : qname;
  if ((id = svgdoc_attr(atts, "id")) != NULL &&
      (svgdoc_bloom_add(D, id, strlen(id), 0) != 0 ||
       (in_svg_ns(qname, tag) && lookup(PAINT_SERVERS, tag) >= 0 &&
        svgdoc_bloom_add(D, id, strlen(id), 1) != 0)))
    D->scan_lost = 1;                    /* out of memory: ids unknown */
  if (strcmp(tag, "marker") == 0 && id != NULL) {
    n = strlen(id);                      /* every marker is kept: properties */
  } else {                               /* and style sheets refer to them */
    if (strcmp(tag, "use") != 0) return;
    href = svgdoc_attr(atts, "href");
    if (href == NULL) href = svgdoc_attr(atts, XLINK_HREF);
    if (!ref_id(href, &id, &n)) return;
  }
  if (find_id(&D->refs, id, n, NULL)) return;
  D->on_error = &jb;
  if (setjmp(jb) == 0) {
    D->arena = &D->keep;
    add_id(D, &D->refs, svgdoc_strdup(D, id, n), 0);
  } else {                               /* out of memory: keep every id */
    D->scan_lost = 1;
    D->failed = 0;
    free(D->err_msg);
    D->err_msg = NULL;
    D->refs_given = 0;
    XML_StopParser((XML_Parser)D->scanner, XML_FALSE);
  }
  D->arena = &D->tmp;
  D->on_error = NULL;
}

/* The reader's refusal of nested entities, so that the scan does not
** expand what the reading proper refuses. */
static void XMLCALL on_scan_entity(void *ud, const XML_Char *name,
                                   int is_param, const XML_Char *value,
                                   int value_length, const XML_Char *base,
                                   const XML_Char *system,
                                   const XML_Char *public_id,
                                   const XML_Char *notation) {
  svgdoc *D = ud;
  (void)name, (void)is_param, (void)base, (void)system, (void)public_id;
  (void)notation;
  if (value && (memchr(value, '&', (size_t)value_length) ||
                value_length > SVGDOC_MAX_ENTITY_LEN))
    XML_StopParser((XML_Parser)D->scanner, XML_FALSE);
}

void svgdoc_scan(svgdoc *D, const char *s, size_t n) {
  XML_Parser p;
  if (D->failed || D->bytes > 0) return;    /* before the reading only */
  if (!D->refs_given) {
    if (D->scanned) return;               /* stopped: every id is kept */
    D->scanned = D->refs_given = 1;
    D->scanner = XML_ParserCreateNS(NULL, '\1');
    if (D->scanner == NULL) {
      D->refs_given = 0;
      return;
    }
    XML_SetUserData((XML_Parser)D->scanner, D);
    XML_SetStartElementHandler((XML_Parser)D->scanner, on_scan_start);
    XML_SetEntityDeclHandler((XML_Parser)D->scanner, on_scan_entity);
  }
  p = (XML_Parser)D->scanner;
  if (p == NULL) return;                  /* the scan stopped at an error */
  while (n > 0) {
    int len = n > (1u << 30) ? 1 << 30 : (int)n;
    if (XML_Parse(p, s, len, 0) != XML_STATUS_OK) {
      /* malformed (the reading says where) or stopped: what was seen is
      ** what the reading can reach before the same place */
      D->scan_lost = 1;
      end_scan(D);
      return;
    }
    s += len, n -= (size_t)len;
  }
}

/* expat's error as the reader's: "malformed XML: ..." at its place. */
static void xml_error(svgdoc *D) {
  XML_Parser p = (XML_Parser)D->parser;
  enum XML_Error code = XML_GetErrorCode(p);
  unsigned long line, col;
  char *m;
  position(D, &line, &col);
  if (code == XML_ERROR_NO_MEMORY) {
    svgdoc_set_error(D, line, col, NULL);
    return;
  }
  if (D->finished && D->bytes == 0) {
    line = col = 1;
    m = svgdoc_message("empty document");
  } else if (D->finished && !D->root_seen && code == XML_ERROR_NO_ELEMENTS) {
    m = svgdoc_message("empty document (no root element)");
  } else {
    m = svgdoc_message("malformed XML: %s", XML_ErrorString(code));
  }
  svgdoc_set_error(D, line, col, m);
}

/* expat 2.5 tokenizes an unfinished token again from its start on every
** XML_Parse call, so a token of T bytes fed in chunks of c bytes costs
** T^2 / (2c).  The input is therefore held back until it is at least as
** long as what expat left unparsed (byte counts from
** XML_GetCurrentByteIndex): each rescan is then paid for by as many new
** bytes, and the whole reading is linear in the document's size.  Input
** that completes what is open is parsed at once, so errors come with the
** feed that completes their element, as before. */
#define HELD_KEEP 262144                /* held room kept for the next token */

/* Hand s[0 .. n-1] to expat, an int's worth at a time. */
static int parse(svgdoc *D, const char *s, size_t n) {
  while (n > 0) {
    int len = n > (1u << 30) ? 1 << 30 : (int)n;
    XML_Index at;
    D->bytes += (size_t)len;
    if (XML_Parse((XML_Parser)D->parser, s, len, 0) != XML_STATUS_OK) {
      if (!D->failed) xml_error(D);
      return -1;
    }
    s += len, n -= (size_t)len;
    /* the start of the event expat stopped in: the unparsed tail */
    at = XML_GetCurrentByteIndex((XML_Parser)D->parser);
    D->held_need = at >= 0 && (size_t)at < D->bytes ? D->bytes - (size_t)at : 0;
  }
  return 0;
}

/* A stream's elements of the last call are given back. */
static void next_batch(svgdoc *D) {
  size_t k;
  if (!D->o.stream) return;
  for (k = 0; k < D->nbatch; k++) free_element(D->batch[k]);
  D->nbatch = 0;
}

int svgdoc_feed(svgdoc *D, const char *s, size_t n) {
  jmp_buf jb;
  int rc;
  if (D->failed) return -1;
  next_batch(D);
  end_scan(D);
  if (D->held.len == 0 && n >= D->held_need)
    return parse(D, s, n);              /* no long token open: at once */
  D->on_error = &jb;                    /* svgdoc_append's out of memory */
  if (setjmp(jb) != 0) {
    D->on_error = NULL;
    return -1;
  }
  svgdoc_append(D, &D->held, s, n);
  D->on_error = NULL;
  if (D->held.len < D->held_need) return 0;
  rc = parse(D, D->held.s, D->held.len);
  D->held.len = 0;
  if (D->held.room > HELD_KEEP && D->held_need < HELD_KEEP / 4) {
    free(D->held.s);                    /* the long token is over */
    D->held.s = NULL, D->held.room = 0;
  }
  return rc;
}

int svgdoc_finish(svgdoc *D) {
  jmp_buf jb;
  if (D->failed) return -1;
  next_batch(D);
  end_scan(D);
  if (D->held.len > 0 && parse(D, D->held.s, D->held.len) != 0) return -1;
  D->held.len = 0;
  D->finished = 1;
  if (XML_Parse((XML_Parser)D->parser, NULL, 0, 1) != XML_STATUS_OK) {
    if (!D->failed) xml_error(D);
    return -1;
  }
  if (!D->root_seen) {
    svgdoc_set_error(D, 1, 1, svgdoc_message("empty document (no root element)"));
    return -1;
  }
  /* what waits behind a forward use: everything is read now */
  D->on_error = &jb;
  if (setjmp(jb) == 0) drain(D, 1);
  D->on_error = NULL;
  return D->failed ? -1 : 0;
}

const char *svgdoc_error(const svgdoc *D, unsigned long *line,
                         unsigned long *col) {
  if (!D->failed) return NULL;
  *line = D->err_line, *col = D->err_col;
  return D->err_msg ? D->err_msg : "not enough memory";
}

size_t svgdoc_count(const svgdoc *D) { return D->nbatch; }

const svgdoc_element *svgdoc_get(const svgdoc *D, size_t i) {
  return D->batch[i];
}

size_t svgdoc_drawn(const svgdoc *D) { return D->ndrawn; }

int svgdoc_streaming(const svgdoc *D) { return D->o.stream; }

size_t svgdoc_nwarnings(const svgdoc *D) { return D->nwarnings; }

const svgdoc_warning *svgdoc_warning_at(const svgdoc *D, size_t i) {
  return &D->warnings[i];
}

const size_t *svgdoc_skipped(const svgdoc *D) { return D->skipped; }

size_t svgdoc_kept(const svgdoc *D) { return D->nevents; }

const svgdoc_info *svgdoc_root_info(const svgdoc *D) { return &D->info; }
