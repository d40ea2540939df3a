/*
** reader.c -- the walk over expat's events: a frame per open element
** (its CTM, viewport, visibility, stroke, layer), the root's coordinate
** system, the drawn shapes read into cubics as they come, and <use>.
** <use> may point forwards: when the document may contain a <use>, the
** subtrees of elements with an id are kept as their start/end events and
** the uses are expanded once the whole document has been read; a
** document without <use> keeps nothing but its results.
*/
#include <expat.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "curve/numeric.h"
#include "svg/decimal.h"
#include "svgdoc/internal.h"

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

/* The entry of tag in list[0 .. n-1], or -1. */
static int find_tag(const char *const *list, int n, const char *tag) {
  int k;
  for (k = 0; k < n; k++)
    if (strcmp(list[k], tag) == 0) return k;
  return -1;
}
#define lookup(list, tag) find_tag(list, (int)(sizeof list / sizeof *list), tag)

typedef struct svgdoc_frame {
  size_t depth;
  int skip, top, is_switch, switch_done, visible, stroked;
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
  int visible, stroked, has_w, has_h;
  double w, h;
  const char **chain;            /* the ids being expanded around it */
  size_t nchain;
} svgdoc_use;

/* The use a replayed element belongs to. */
typedef struct svgdoc_shadow {
  int root;                      /* the used element itself */
  const svgdoc_use *u;
  const char **chain;
  size_t nchain;
} svgdoc_shadow;

struct svgdoc_out {
  svgdoc_element *e;             /* or a use */
  svgdoc_use *u;
};

struct svgdoc_event {
  const char *tag;               /* NULL: an end event */
  const char **atts;
  unsigned long line, col;
  size_t close;                  /* the index of its end event */
  int svgns;
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

static void warn(svgdoc *D, unsigned long line, unsigned long col,
                 const char *msg) {
  svgdoc_warning *w;
  if (D->nwarnings >= SVGDOC_MAX_WARNINGS) return;
  if (D->warnings == NULL) {
    D->warnings = malloc(SVGDOC_MAX_WARNINGS * sizeof *D->warnings);
    if (D->warnings == NULL) svgdoc_nomem(D);
  }
  w = &D->warnings[D->nwarnings++];
  w->line = line, w->col = col, w->msg = msg;
}

/* ---- ids of kept elements ------------------------------------------------ */

static size_t hash(const char *s) {
  size_t h = 5381;
  for (; *s; s++) h = h * 33 + (unsigned char)*s;
  return h;
}

/* The slot of id in the table (empty when absent). */
static size_t id_slot(const svgdoc *D, const char *id) {
  size_t i = hash(id) & (D->ids_room - 1);
  while (D->ids[i] && strcmp(D->ids[i], id) != 0) i = (i + 1) & (D->ids_room - 1);
  return i;
}

static int find_id(const svgdoc *D, const char *id, size_t *ev) {
  size_t i;
  if (D->ids_room == 0) return 0;
  i = id_slot(D, id);
  if (D->ids[i] == NULL) return 0;
  *ev = D->id_event[i];
  return 1;
}

/* The first element with an id keeps it (duplicates are ignored). */
static void add_id(svgdoc *D, const char *id, size_t ev) {
  size_t i;
  if (2 * (D->nids + 1) > D->ids_room) {
    size_t room = D->ids_room ? 2 * D->ids_room : 64, k;
    const char **ids = calloc(room, sizeof *ids);
    size_t *evs = malloc(room * sizeof *evs);
    const char **old = D->ids;
    size_t *old_ev = D->id_event, old_room = D->ids_room;
    if (ids == NULL || evs == NULL) {
      free(ids), free(evs);
      svgdoc_nomem(D);
    }
    D->ids = ids, D->id_event = evs, D->ids_room = room;
    for (k = 0; k < old_room; k++) {
      if (old[k]) {
        size_t j = id_slot(D, old[k]);
        D->ids[j] = old[k], D->id_event[j] = old_ev[k];
      }
    }
    free(old), free(old_ev);
  }
  i = id_slot(D, id);
  if (D->ids[i]) return;
  D->ids[i] = id, D->id_event[i] = ev;
  D->nids++;
}

/* ---- the elements ----------------------------------------------------- */

static const char *copy(svgdoc *D, const char *s) {
  return s ? svgdoc_strdup(D, s, strlen(s)) : NULL;
}

/* An element drawn (or a use to expand later) in document order; while
** the uses are expanded, straight into the drawn list. */
static void emit(svgdoc *D, svgdoc_element *e, svgdoc_use *u) {
  if ((D->expanding ? D->ndrawn : D->nout) >= SVGDOC_MAX_ELEMENTS)
    svgdoc_fail(D, e ? e->line : u->line, e ? e->col : u->col,
                "more than %d drawn elements", SVGDOC_MAX_ELEMENTS);
  if (D->expanding) {
    D->drawn = grow(D, D->drawn, &D->drawn_room, D->ndrawn, sizeof *D->drawn);
    D->drawn[D->ndrawn++] = e;
  } else {
    D->out = grow(D, D->out, &D->out_room, D->nout, sizeof *D->out);
    D->out[D->nout].e = e, D->out[D->nout].u = u;
    D->nout++;
  }
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

/* A drawn shape: its path data into cubics under the CTM. */
static void draw(svgdoc *D, const svgdoc_frame *f, const char *tag,
                 const char *d, const char **atts, unsigned long line,
                 unsigned long col, const svgdoc_shadow *sh) {
  const double *C = f->ctm;
  const char *id = svgdoc_attr(atts, "id");
  int identity = C[0] == 1 && C[1] == 0 && C[2] == 0 && C[3] == 1 &&
                 C[4] == 0 && C[5] == 0;
  svgdoc_element *e = svgdoc_alloc(D, sizeof *e);
  arclen_pathdata_init(&e->pd);
  /* kept before the parse, so that svgdoc_free frees its cubics */
  D->all = grow(D, D->all, &D->all_room, D->nall, sizeof *D->all);
  D->all[D->nall++] = e;
  if (svgdoc_shape_parse(D, &e->pd, tag, d, identity ? NULL : C) !=
      ARCLEN_PD_OK) {
    const char *m = shape_size_message(D, &e->pd, tag, atts);
    if (m == NULL) {
      m = pathdata_message(D, &e->pd, d);
      if (strcmp(tag, "path") == 0) m = svgdoc_format(D, "d: %s", m);
    }
    svgdoc_fail(D, line, col, "<%s%s%s%s>: %s", tag, id ? " id='" : "",
                id ? id : "", id ? "'" : "", m);
  }
  {
    /* a control point beyond the doubles (a line from -1e308 to 1e308
    ** has its thirds there): the length cannot be a double either */
    size_t k, n = 8 * e->pd.ncubics;
    double top = 0;
    int finite = 1;
    for (k = 0; k < n; k++) {
      double v = fabs(e->pd.cubics[k]);
      if (!(v <= DBL_MAX)) finite = 0;
      else if (v > top) top = v;
    }
    if (!finite) {
      char num[32];
      short_num(num, top);
      svgdoc_fail(D, line, col, "<%s%s%s%s>: the path's length overflows "
                  "(coordinates up to %s)", tag, id ? " id='" : "",
                  id ? id : "", id ? "'" : "", num);
    }
  }
  e->id = copy(D, id);
  e->tag = tag;
  e->layer = f->layer;
  e->use = sh ? sh->u->href : NULL;
  e->d = strcmp(tag, "path") == 0 ? copy(D, d) : d;   /* shapes' are pooled */
  e->line = line, e->col = col;
  e->stroked = f->stroked;
  memcpy(e->ctm, C, sizeof e->ctm);
  emit(D, e, NULL);
}

static void expand(svgdoc *D, const svgdoc_use *u);

/* Lua's tonumber(s) == 0 for the number-like prefix of a stroke-width
** (a width of zero draws no stroke), read in any locale. */
static int zero_width(const char *s) {
  size_t n = strspn(s, "0123456789.eE+-");
  double v;
  return n > 0 && arclen_decimal_scan(s, n, 0, &v) == n && v == 0;
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

/* The child frame f of element (tag, atts) under parent; f->skip when
** nothing inside it is drawn.  sh: the use this element is replayed for. */
static void open_element(svgdoc *D, svgdoc_frame *parent, svgdoc_frame *f,
                         int svgns, const char *tag, const char **atts,
                         unsigned long line, unsigned long col,
                         const svgdoc_shadow *sh) {
  const char *P[SVGDOC_NPROPS], *s;
  int shape, skipped, is_svg = strcmp(tag, "svg") == 0,
                      is_symbol = strcmp(tag, "symbol") == 0;
  f->depth = parent->depth + 1;
  f->skip = 1;
  if (f->depth > (size_t)D->o.max_depth)
    svgdoc_fail(D, line, col, "elements nested deeper than %d", D->o.max_depth);
  if (parent->skip || !svgns) return;            /* a foreign element */
  if (parent->is_switch) {      /* SVG 2 section 5.8: the first that passes */
    if (parent->switch_done || svgdoc_attr(atts, "requiredExtensions")) return;
    parent->switch_done = 1;
  }
  svgdoc_properties(D, atts, P);
  memcpy(f->ctm, parent->ctm, sizeof f->ctm);
  f->vp = parent->vp;
  f->visible = parent->visible, f->stroked = parent->stroked;
  f->layer = parent->layer;
  f->top = f->is_switch = f->switch_done = 0;
  if (P[SVGDOC_DISPLAY] && strcmp(P[SVGDOC_DISPLAY], "none") == 0 &&
      !D->o.hidden)
    return;
  if ((s = P[SVGDOC_VISIBILITY]) != NULL) {
    if (strcmp(s, "hidden") == 0 || strcmp(s, "collapse") == 0) f->visible = 0;
    else if (strcmp(s, "visible") == 0) f->visible = 1;
  }
  if ((s = P[SVGDOC_STROKE]) != NULL) {
    if (strcmp(s, "none") == 0) f->stroked = 0;
    else if (strcmp(s, "inherit") != 0) f->stroked = 1;
  }
  if ((s = P[SVGDOC_STROKE_WIDTH]) != NULL && zero_width(s)) f->stroked = 0;
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
    const svgdoc_viewport *vp = &parent->vp;
    double x = 0, y = 0, w = 0, h = 0, vb[4];
    int hw, hh;
    svgdoc_matrix V;
    svgdoc_len_attr(D, line, col, atts, "x", 'x', vp, &x);
    svgdoc_len_attr(D, line, col, atts, "y", 'y', vp, &y);
    if (sh && sh->root && sh->u->has_w) hw = 1, w = sh->u->w;
    else hw = svgdoc_len_attr(D, line, col, atts, "width", 'x', vp, &w);
    if (sh && sh->root && sh->u->has_h) hh = 1, h = sh->u->h;
    else hh = svgdoc_len_attr(D, line, col, atts, "height", 'y', vp, &h);
    if ((!hw || !hh) && !vp->has)
      svgdoc_fail(D, line, col, "<%s> without width and height needs a "
                  "viewport", tag);
    if (!hw) w = vp->w;
    if (!hh) h = vp->h;
    svgdoc_nonneg(D, line, col, w, "width");
    svgdoc_nonneg(D, line, col, h, "height");
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
      warn(D, line, col, svgdoc_format(D, "<%s>: singular transform, not drawn", tag));
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
    const char *d = svgdoc_shape_data(D, line, col, tag, atts, &f->vp);
    if (d && (f->visible || D->o.hidden) && (f->stroked || !D->o.stroked))
      draw(D, f, SHAPES[shape], d, atts, line, col, sh);
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
    s = href;
    while (s && svgdoc_space((unsigned char)*s)) s++;
    if (href == NULL) {
      warn(D, line, col, "<use> without href, nothing drawn");
    } else if (*s != '#') {
      warn(D, line, col, svgdoc_format(D, "<use href='%s'>: only same-document "
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
      u->visible = f->visible, u->stroked = f->stroked;
      u->has_w = hw, u->w = uw, u->has_h = hh, u->h = uh;
      u->chain = sh ? sh->chain : NULL;
      u->nchain = sh ? sh->nchain : 0;
      if (sh) expand(D, u);
      else emit(D, NULL, u);
    }
    f->skip = 1;                     /* use's children are not rendered */
  }
}

/* Expand the use u now (the whole document has been read): replay its
** target's events under a frame made from the use. */
static void expand(svgdoc *D, const svgdoc_use *u) {
  size_t start, last, i, k, top = 0;
  svgdoc_frame *stack;
  svgdoc_shadow root_sh, sh;
  const char **chain;
  if (!find_id(D, u->href, &start))
    svgdoc_fail(D, u->line, u->col, "<use> of '#%s': no element has that id",
                u->href);
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
  chain = svgdoc_alloc(D, (u->nchain + 1) * sizeof *chain);
  if (u->nchain) memcpy(chain, u->chain, u->nchain * sizeof *chain);
  chain[u->nchain] = u->href;
  last = D->events[start].close;
  D->replayed += last - start + 1;
  if (D->replayed > SVGDOC_MAX_REPLAYED)
    svgdoc_fail(D, u->line, u->col, "<use> expansions replay more than %d "
                "elements", SVGDOC_MAX_REPLAYED);
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
  memcpy(stack[0].ctm, u->ctm, sizeof stack[0].ctm);
  stack[0].vp = u->vp;
  stack[0].visible = u->visible, stack[0].stroked = u->stroked;
  stack[0].layer = u->layer;
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

/* ---- the root ------------------------------------------------------------ */

/* The root element: the document's coordinate system (SVG 2 section 8.2). */
static void open_root(svgdoc *D, const char **atts, unsigned long line,
                      unsigned long col, svgdoc_frame *f) {
  const char *P[SVGDOC_NPROPS], *s;
  double vb[4], w = 0, h = 0;
  int has_vb = svgdoc_viewbox(D, line, col, svgdoc_attr(atts, "viewBox"), vb);
  int hw = 0, hh = 0;
  svgdoc_viewport none = {0, 0, 0};
  const char *ws = svgdoc_attr(atts, "width"), *hs = svgdoc_attr(atts, "height");
  if (ws && !strchr(ws, '%'))
    hw = svgdoc_len_attr(D, line, col, atts, "width", 'x', &none, &w);
  if (hs && !strchr(hs, '%'))
    hh = svgdoc_len_attr(D, line, col, atts, "height", 'y', &none, &h);
  if (hw) svgdoc_nonneg(D, line, col, w, "width");
  if (hh) svgdoc_nonneg(D, line, col, h, "height");
  memset(f, 0, sizeof *f);
  f->depth = 1;
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
    warn(D, line, col, "viewBox of zero width or height: nothing drawn");
    return;
  }
  if ((hw && w == 0) || (hh && h == 0)) {
    warn(D, line, col, "width or height zero: nothing drawn");
    return;
  }
  f->visible = 1, f->stroked = 0, f->layer = "(root)", f->top = 1;
  svgdoc_properties(D, atts, P);
  if (P[SVGDOC_DISPLAY] && strcmp(P[SVGDOC_DISPLAY], "none") == 0 &&
      !D->o.hidden)
    return;
  f->skip = 0;
  if ((s = P[SVGDOC_VISIBILITY]) != NULL &&
      (strcmp(s, "hidden") == 0 || strcmp(s, "collapse") == 0))
    f->visible = 0;
  if ((s = P[SVGDOC_STROKE]) != NULL && strcmp(s, "none") != 0 &&
      strcmp(s, "inherit") != 0)
    f->stroked = 1;
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

/* Does s[0 .. n-1] contain what could be a <use> element? */
static int may_use(const char *s, size_t n) {
  size_t i;
  for (i = 0; i + 4 <= n; i++)
    if ((s[i] == '<' || s[i] == ':') && memcmp(s + i + 1, "use", 3) == 0)
      return 1;
  return 0;
}

/* The event of an element kept for <use>: its attributes copied. */
static void keep(svgdoc *D, int svgns, const char *tag, const char **atts,
                 unsigned long line, unsigned long col, const char *id) {
  size_t n = 0, k;
  svgdoc_event *x;
  const char **a;
  while (atts[n]) n += 2;
  a = svgdoc_alloc(D, (n + 1) * sizeof *a);
  for (k = 0; k < n; k++) a[k] = copy(D, atts[k]);
  a[n] = NULL;
  D->events = grow(D, D->events, &D->events_room, D->nevents, sizeof *D->events);
  x = &D->events[D->nevents];
  x->tag = copy(D, tag), x->atts = a, x->line = line, x->col = col;
  x->close = 0, x->svgns = svgns;
  D->open_ev[D->rec++] = D->nevents;
  if (id) add_id(D, svgdoc_attr(a, "id"), D->nevents);
  D->nevents++;
}

static void start_element(svgdoc *D, const char *qname, const char **atts) {
  svgdoc_frame *parent = D->depth ? &D->stack[D->depth - 1] : NULL;
  const char *tag = strchr(qname, '\1'), *id;
  unsigned long line, col;
  int svgns;
  if (D->depth >= (size_t)D->o.max_depth) {
    position(D, &line, &col);
    svgdoc_fail(D, line, col, "elements nested deeper than %d", D->o.max_depth);
  }
  id = svgdoc_attr(atts, "id");
  /* inside a subtree that draws nothing and is not kept for <use>, only
  ** the depth counts */
  if (parent && parent->skip && !(D->record && (D->rec > 0 || id))) {
    D->stack[D->depth].skip = 1;
    D->stack[D->depth].depth = parent->depth + 1;
    D->depth++;
    return;
  }
  position(D, &line, &col);
  svgns = tag == NULL || ((size_t)(tag - qname) == strlen(SVG_NS) &&
                          memcmp(qname, SVG_NS, strlen(SVG_NS)) == 0);
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
    D->depth = 1;
    return;
  }
  if (D->record && (D->rec > 0 || id)) {
    keep(D, svgns, tag, atts, line, col, id);
    atts = D->events[D->nevents - 1].atts;
    tag = D->events[D->nevents - 1].tag;
  }
  open_element(D, &D->stack[D->depth - 1], &D->stack[D->depth], svgns, tag,
               atts, line, col, NULL);
  D->depth++;
}

static void end_element(svgdoc *D) {
  if (D->rec > 0) {
    D->events = grow(D, D->events, &D->events_room, D->nevents, sizeof *D->events);
    D->events[D->nevents].tag = NULL;
    D->events[D->open_ev[D->rec - 1]].close = D->nevents;
    D->nevents++;
    D->rec--;
  }
  D->depth--;
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

static void XMLCALL on_entity(void *ud, const XML_Char *name, int is_param,
                              const XML_Char *value, int value_length,
                              const XML_Char *base, const XML_Char *system,
                              const XML_Char *public_id,
                              const XML_Char *notation) {
  svgdoc *D = ud;
  (void)is_param, (void)base, (void)public_id, (void)notation;
  CATCH(D, entity_decl(D, name, value, value_length, system));
}

/* ---- the document ------------------------------------------------------- */

svgdoc *svgdoc_new(const svgdoc_options *o) {
  svgdoc *D = calloc(1, sizeof *D);
  if (D == NULL) return NULL;
  D->o = *o;
  D->record = o->uses;
  D->stack = malloc(((size_t)o->max_depth + 2) * sizeof *D->stack);
  D->open_ev = malloc(((size_t)o->max_depth + 2) * sizeof *D->open_ev);
  D->parser = XML_ParserCreateNS(NULL, '\1');
  if (D->stack == NULL || D->open_ev == NULL || D->parser == NULL) {
    svgdoc_free(D);
    return NULL;
  }
  XML_SetUserData((XML_Parser)D->parser, D);
  XML_SetElementHandler((XML_Parser)D->parser, on_start, on_end);
  XML_SetEntityDeclHandler((XML_Parser)D->parser, on_entity);
  return D;
}

void svgdoc_free(svgdoc *D) {
  size_t k;
  if (D == NULL) return;
  if (D->parser) XML_ParserFree((XML_Parser)D->parser);
  for (k = 0; k < D->nall; k++) arclen_pathdata_free(&D->all[k]->pd);
  svgdoc_free_pool(D);
  for (k = 0; k < SVGDOC_NPROPS; k++) free(D->props[k].s);
  for (k = 0; k <= SVGDOC_MAX_USE_DEPTH; k++) free(D->xstacks[k]);
  free(D->scratch.s), free(D->held.s);
  free(D->stack), free(D->open_ev), free(D->events);
  free(D->ids), free(D->id_event), free(D->out), free(D->drawn);
  free(D->all), free(D->warnings), free(D->err_msg);
  free(D);
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

int svgdoc_feed(svgdoc *D, const char *s, size_t n) {
  jmp_buf jb;
  int rc;
  if (D->failed) return -1;
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
  size_t k;
  if (D->failed) return -1;
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
  /* expand the uses, in document order */
  D->on_error = &jb;
  D->expanding = 1;
  if (setjmp(jb) == 0) {
    for (k = 0; k < D->nout; k++) {
      if (D->out[k].u) {
        expand(D, D->out[k].u);
      } else {
        emit(D, D->out[k].e, NULL);
      }
    }
  }
  D->on_error = NULL;
  return D->failed ? -1 : 0;
}

const char *svgdoc_error(const svgdoc *D, unsigned long *line,
                         unsigned long *col) {
  if (!D->failed) return NULL;
  *line = D->err_line, *col = D->err_col;
  return D->err_msg ? D->err_msg : "not enough memory";
}

size_t svgdoc_count(const svgdoc *D) { return D->ndrawn; }

const svgdoc_element *svgdoc_get(const svgdoc *D, size_t i) {
  return D->drawn[i];
}

size_t svgdoc_nwarnings(const svgdoc *D) { return D->nwarnings; }

const svgdoc_warning *svgdoc_warning_at(const svgdoc *D, size_t i) {
  return &D->warnings[i];
}

const size_t *svgdoc_skipped(const svgdoc *D) { return D->skipped; }

size_t svgdoc_kept(const svgdoc *D) { return D->nevents; }

const svgdoc_info *svgdoc_root_info(const svgdoc *D) { return &D->info; }
