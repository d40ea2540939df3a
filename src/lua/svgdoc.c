/*
** svgdoc.c -- the Lua binding of the document reader (svgdoc/): the
** module arclen.svgdoc, a shared object of its own because it links
** libexpat, which arclen.core does without.  arclen.svg is its user.
**   svgdoc.new(opts) -> reader    opts: arc_tol, unit_px (0: user units),
**                                 hidden, stroked, painted, lang (user
**                                 languages for systemLanguage, default
**                                 "en"), max_depth, uses, stream,
**                                 max_held (the queue behind a forward use),
**                                 shape_text (for the specs: basic shapes
**                                 written as path data and that parsed),
**                                 strict (warnings are errors),
**                                 method, tol: each element's length
**                                 computed as it is read (svgdoc/measure.c;
**                                 not for method "metapost"; arclen.svg
**                                 asks it for "gauss" only), path: a
**                                 function(subpaths) -> the element's path,
**                                 bare: an element measured comes without
**                                 its lazy fields (d of a basic shape,
**                                 ctm, subpaths, path)
**   reader:scan(s)                optional, before feed: the whole document
**                                 once, for the ids <use> refers to
**   reader:feed(s) -> elements    the next bytes of the document; with
**                                 stream, the elements they completed (a
**                                 list, or nil when none)
**                                 arcs ("conics", the default, or
**                                 "cubics")
**   reader:finish(name) -> {elements =, warnings =, skipped =, kept =,
**                           width =, height =, viewbox =}  (with stream,
**                           elements are the ones completed at the end)
**   svgdoc.isatty([which]) -> boolean  is stderr (or "stdout") a terminal
**                                 (the command line's progress line)
**   svgdoc.stat_add(e, acc) -> boolean  svg.stats()'s add of an element
**                                 without its path (l_stat_add)
**   svgdoc.gzip, svgdoc.gunzip    gzip input (svgdoc_gzip.c)
** A located error is raised as {line =, col =, msg =}; arclen.svg names
** the document in it.  Each element is {id, tag, layer, line, col,
** stroked, filled, use, d, ctm = {a, b, c, d, e, f}, subpaths, length,
** path} (subpaths as arclen.core.svg_pathdata returns them, not given
** when opts.path is; length with opts.method, unless it fails: the caller
** measures such an element itself and reports it; path with opts.path).
** Only the strings and numbers are made up front: a basic shape's d,
** ctm, subpaths and path are made when first read and kept
** (element_index), which halved the cost of a drawing of circles.
** Warnings come formatted as "NAME:LINE:COL: message".
*/
#include <math.h>
#include <string.h>

#include "lua/binding.h"
#include "svgdoc/cond.h"
#include "svgdoc/measure.h"
#include "svgdoc/svgdoc.h"

#include <stdio.h>
#if defined(_WIN32)
#include <io.h>
#define is_tty(f) (_isatty(_fileno(f)) != 0)
#elif defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#define is_tty(f) (isatty(fileno(f)) != 0)
#else
#define is_tty(f) ((void)(f), 0)         /* unknown: no progress lines */
#endif

#define READER "arclen.svgdoc.reader"

void arclenL_open_gzip(lua_State *L);    /* svgdoc_gzip.c */

/* The reader's userdata: the document's reader (first, so that a pointer
** to it is a svgdoc **), how its elements are measured, and the reference
** of their __index closure (element_index). */
typedef struct reader {
  svgdoc *D;
  const arclen_method *method;           /* NULL: lengths not computed */
  arclen_opts o;
  int index_ref;
  int bare;                              /* measured elements without lazy fields */
} reader;

static svgdoc **check_reader(lua_State *L) {
  svgdoc **D = (svgdoc **)luaL_checkudata(L, 1, READER);
  if (*D == NULL) luaL_argerror(L, 1, "the reader has finished");
  return D;
}

static int reader_gc(lua_State *L) {
  reader *R = (reader *)luaL_checkudata(L, 1, READER);
  svgdoc_free(R->D);
  R->D = NULL;
  if (R->index_ref != LUA_NOREF) luaL_unref(L, LUA_REGISTRYINDEX, R->index_ref);
  R->index_ref = LUA_NOREF;
  return 0;
}

static int element_index(lua_State *L);

static double opt_number(lua_State *L, const char *k, double dflt) {
  double v = dflt;
  lua_getfield(L, 1, k);
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TNUMBER)
      luaL_argerror(L, 1, lua_pushfstring(L, "%s must be a number", k));
    v = lua_tonumber(L, -1);
  }
  lua_pop(L, 1);
  return v;
}

static int opt_boolean(lua_State *L, const char *k) {
  int v;
  lua_getfield(L, 1, k);
  v = lua_toboolean(L, -1);
  lua_pop(L, 1);
  return v;
}

/* svgdoc.new(opts) */
static int l_new(lua_State *L) {
  svgdoc_options o;
  reader *R;
  const arclen_method *method = NULL;
  double depth, held, tol;
  luaL_checktype(L, 1, LUA_TTABLE);
  o.arc_tol = opt_number(L, "arc_tol", 1e-12);
  o.unit_px = opt_number(L, "unit_px", 0);
  depth = opt_number(L, "max_depth", SVGDOC_MAX_DEPTH);
  luaL_argcheck(L, o.arc_tol > 0 && o.arc_tol < 1, 1, "arc_tol must be in (0, 1)");
  luaL_argcheck(L, o.unit_px >= 0 && o.unit_px < 1e300, 1,
                "unit_px must be a number of px, or 0");
  luaL_argcheck(L, depth >= 1 && depth <= SVGDOC_MAX_DEPTH, 1,
                "max_depth out of range");
  o.max_depth = (int)depth;
  o.hidden = opt_boolean(L, "hidden");
  o.stroked = opt_boolean(L, "stroked");
  o.painted = opt_boolean(L, "painted");
  lua_getfield(L, 1, "lang");
  o.lang = NULL;
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TSTRING || !svgdoc_cond_lang_ok(lua_tostring(L, -1)))
      luaL_argerror(L, 1, "lang must be language tags separated by commas "
                    "(\"en\", \"de,en-US\")");
    o.lang = lua_tostring(L, -1);        /* copied by svgdoc_new */
  }
  o.uses = opt_boolean(L, "uses");
  o.stream = opt_boolean(L, "stream");
  o.shape_text = opt_boolean(L, "shape_text");   /* for the specs */
  o.strict = opt_boolean(L, "strict");
  held = opt_number(L, "max_held", SVGDOC_MAX_HELD);
  luaL_argcheck(L, held >= 1 && held <= SVGDOC_MAX_HELD, 1, "max_held out of range");
  o.max_held = (size_t)held;
  lua_getfield(L, 1, "arcs");
  o.arcs = ARCLEN_PD_ARCS_CONICS;
  if (!lua_isnil(L, -1)) {
    const char *a = lua_tostring(L, -1);
    if (lua_type(L, -1) != LUA_TSTRING ||
        (strcmp(a, "conics") != 0 && strcmp(a, "cubics") != 0))
      luaL_argerror(L, 1, "arcs must be \"conics\" or \"cubics\"");
    if (strcmp(a, "cubics") == 0) o.arcs = ARCLEN_PD_ARCS_CUBICS;
  }
  lua_pop(L, 1);
  lua_getfield(L, 1, "method");
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TSTRING ||
        (method = arclen_find_method(lua_tostring(L, -1))) == NULL)
      luaL_argerror(L, 1, "method must be the name of a known method");
    /* MetaPost measures a path's subpaths whole, not by segments: left to
    ** arclen.path */
    if (strcmp(method->name, "metapost") == 0) method = NULL;
  }
  lua_pop(L, 1);
  tol = opt_number(L, "tol", 1e-12);
  luaL_argcheck(L, tol >= ARCLEN_RTOL_MIN && tol <= ARCLEN_RTOL_MAX, 1,
                "tol out of range");
  lua_getfield(L, 1, "path");
  luaL_argcheck(L, lua_isnil(L, -1) || lua_type(L, -1) == LUA_TFUNCTION, 1,
                "path must be a function");
  /* the elements' __index: the path function (or nil), whether subpaths
  ** are shown */
  lua_pushboolean(L, lua_isnil(L, -1));
  lua_pushcclosure(L, element_index, 2);
  R = (reader *)lua_newuserdata(L, sizeof *R);
  R->D = NULL;
  R->index_ref = LUA_NOREF;
  luaL_getmetatable(L, READER);
  lua_setmetatable(L, -2);
  lua_insert(L, -2);
  R->index_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  R->method = method;
  R->bare = opt_boolean(L, "bare");
  arclen_opts_init(&R->o);
  R->o.rtol = tol;
  R->D = svgdoc_new(&o);
  if (R->D == NULL) return luaL_error(L, "not enough memory");
  lua_remove(L, -2);                     /* lang, now copied */
  return 1;
}

/* Raise the reader's located error as {line =, col =, msg =}. */
static int raise(lua_State *L, svgdoc **D) {
  unsigned long line, col;
  const char *msg = svgdoc_error(*D, &line, &col);
  lua_createtable(L, 0, 3);
  lua_pushinteger(L, (lua_Integer)line);
  lua_setfield(L, -2, "line");
  lua_pushinteger(L, (lua_Integer)col);
  lua_setfield(L, -2, "col");
  lua_pushstring(L, msg);
  lua_setfield(L, -2, "msg");
  svgdoc_free(*D);
  *D = NULL;
  return lua_error(L);
}

static void push_element(lua_State *L, const reader *R,
                         const svgdoc_element *e);

/* The elements the last call completed, as a list (nothing when none). */
static int push_batch(lua_State *L, const reader *R) {
  size_t i, n = svgdoc_count(R->D);
  if (n == 0) return 0;
  lua_rawgeti(L, LUA_REGISTRYINDEX, R->index_ref);   /* element_index */
  lua_createtable(L, n > 0x7fffffff ? 0x7fffffff : (int)n, 0);
  for (i = 0; i < n; i++) {
    push_element(L, R, svgdoc_get(R->D, i));
    lua_rawseti(L, -2, (int)i + 1);
  }
  lua_remove(L, -2);
  return 1;
}

/* reader:scan(s) */
static int l_scan(lua_State *L) {
  svgdoc **D = check_reader(L);
  size_t n;
  const char *s = luaL_checklstring(L, 2, &n);
  svgdoc_scan(*D, s, n);
  return 0;
}

/* reader:feed(s) */
static int l_feed(lua_State *L) {
  svgdoc **D = check_reader(L);
  size_t n;
  const char *s = luaL_checklstring(L, 2, &n);
  if (svgdoc_feed(*D, s, n) != 0) return raise(L, D);
  return svgdoc_streaming(*D) ? push_batch(L, (const reader *)D) : 0;
}

/* svgdoc.isatty([which]) */
static int l_isatty(lua_State *L) {
  static const char *const names[] = {"stderr", "stdout", NULL};
  int which = luaL_checkoption(L, 1, "stderr", names);
  lua_pushboolean(L, is_tty(which == 0 ? stderr : stdout));
  return 1;
}

static void set_string(lua_State *L, const char *k, const char *v) {
  if (v == NULL) return;
  lua_pushstring(L, v);
  lua_setfield(L, -2, k);
}

/* What an element's lazy fields are made of, in one userdata (in its
** metatable, [1]): the header, then the segments' records (8 doubles
** each), the shape's numbers, the subpaths, the kinds (a byte each). */
typedef union element_head {
  struct {
    const char *magic;               /* ELEMENT_MAGIC: one of these */
    size_t n, nsub, nnums;           /* segments, subpaths, shape numbers */
    int kind;                        /* the shape's (SVGDOC_SHAPE_*) */
    int flat;                        /* its path keeps these segments (gauss) */
    double ctm[6];
  } h;
  double align;                      /* the numbers follow, aligned */
} element_head;

#define REC_BYTES (ARCLEN_PD_STRIDE * sizeof(double))

/* What marks an element's userdata (its address; never written). */
static const char ELEMENT_MAGIC[] = "arclen.svgdoc.element";

static const double *head_records(const element_head *u) {
  return (const double *)(u + 1);
}
static const double *head_numbers(const element_head *u) {
  return head_records(u) + ARCLEN_PD_STRIDE * u->h.n;
}
static const arclen_subpath *head_subpaths(const element_head *u) {
  return (const arclen_subpath *)(head_numbers(u) + u->h.nnums);
}
static const unsigned char *head_kinds(const element_head *u) {
  return (const unsigned char *)(head_subpaths(u) + u->h.nsub);
}

static void add_bytes(void *b, const char *bytes, size_t n) {
  luaL_addlstring((luaL_Buffer *)b, bytes, n);
}

/* The subpaths of u as arclenL_pushsubpaths pushes a reader's. */
static void push_head_subpaths(lua_State *L, const element_head *u) {
  arclen_pathdata pd;
  arclen_pathdata_init(&pd);
  pd.cubics = (double *)head_records(u);
  pd.kinds = (unsigned char *)head_kinds(u);
  pd.ncubics = u->h.n;
  pd.subpaths = (arclen_subpath *)head_subpaths(u);
  pd.nsubpaths = u->h.nsub;
  arclenL_pushsubpaths(L, &pd);
}

/* __index of an element (a C closure: upvalue 1 the path function or nil,
** 2 whether subpaths are shown): a basic shape's d, ctm, subpaths, path,
** made from the userdata when first asked for and kept in the element;
** nil for any other key.  Writing each d up front was half the reader's
** work, making each path in Lua half of `arclen length`'s on circles
** (doc/benchmarks.md). */
static int element_index(lua_State *L) {
  const element_head *u;
  const char *k;
  if (lua_type(L, 2) != LUA_TSTRING || !lua_getmetatable(L, 1)) return 0;
  k = lua_tostring(L, 2);
  lua_rawgeti(L, -1, 1);
  u = (const element_head *)lua_touserdata(L, -1);
  if (u == NULL) return 0;
  if (strcmp(k, "d") == 0 && u->h.kind != SVGDOC_SHAPE_PATH) {
    svgdoc_shape s;
    luaL_Buffer b;
    s.kind = u->h.kind;
    s.d = NULL;
    s.n = u->h.nnums;
    s.v = head_numbers(u);
    luaL_buffinit(L, &b);
    svgdoc_shape_d(&s, add_bytes, &b);
    luaL_pushresult(&b);
  } else if (strcmp(k, "ctm") == 0) {
    int j;
    lua_createtable(L, 6, 0);
    for (j = 0; j < 6; j++) {
      lua_pushnumber(L, u->h.ctm[j]);
      lua_rawseti(L, -2, j + 1);
    }
  } else if (strcmp(k, "subpaths") == 0 && lua_toboolean(L, lua_upvalueindex(2))) {
    push_head_subpaths(L, u);
  } else if (strcmp(k, "path") == 0 && lua_isfunction(L, lua_upvalueindex(1))) {
    lua_pushvalue(L, lua_upvalueindex(1));
    push_head_subpaths(L, u);
    lua_call(L, 1, 1);
  } else {
    return 0;
  }
  lua_pushvalue(L, 2);
  lua_pushvalue(L, -2);
  lua_rawset(L, 1);                      /* kept: the same object each time */
  return 1;
}

/* The element's metatable: element_index (below the list and the element
** on the stack) and the userdata of its lazy fields. */
static void set_lazy(lua_State *L, const reader *R, const svgdoc_element *e) {
  const arclen_pathdata *pd = &e->pd;
  const svgdoc_shape *s = &e->shape;
  size_t nnums = s->kind == SVGDOC_SHAPE_PATH ? 0 : s->n;
  element_head *u;
  char *at;
  lua_createtable(L, 1, 1);
  lua_pushvalue(L, -4);
  lua_setfield(L, -2, "__index");
  u = (element_head *)lua_newuserdata(L, sizeof *u + pd->ncubics * REC_BYTES +
      nnums * sizeof(double) + pd->nsubpaths * sizeof(arclen_subpath) + pd->ncubics);
  u->h.magic = ELEMENT_MAGIC;
  u->h.flat = R->method != NULL && strcmp(R->method->name, "gauss") == 0;
  u->h.n = pd->ncubics;
  u->h.nsub = pd->nsubpaths;
  u->h.nnums = nnums;
  u->h.kind = s->kind;
  memcpy(u->h.ctm, e->ctm, sizeof u->h.ctm);
  at = (char *)(u + 1);
  if (pd->ncubics) memcpy(at, pd->cubics, pd->ncubics * REC_BYTES);
  at += pd->ncubics * REC_BYTES;
  if (nnums) memcpy(at, s->v, nnums * sizeof(double));
  at += nnums * sizeof(double);
  if (pd->nsubpaths) memcpy(at, pd->subpaths, pd->nsubpaths * sizeof(arclen_subpath));
  at += pd->nsubpaths * sizeof(arclen_subpath);
  if (pd->ncubics) memcpy(at, pd->kinds, pd->ncubics);
  lua_rawseti(L, -2, 1);
  lua_setmetatable(L, -2);
}

/* An element, with element_index and the list below it on the stack. */
static void push_element(lua_State *L, const reader *R,
                         const svgdoc_element *e) {
  /* sized for its fields (Lua rounds up to a power of two): the collector's
  ** work grows with the bytes allocated, and 16 slots were twice a
  ** circle's */
  lua_createtable(L, 0, 6 + (e->id != NULL) + (e->layer != NULL) +
                  (e->use != NULL) + (e->marker != NULL) +
                  (e->shape.kind == SVGDOC_SHAPE_PATH));
  set_string(L, "id", e->id);
  lua_pushstring(L, e->tag);
  lua_setfield(L, -2, "tag");
  set_string(L, "layer", e->layer);
  set_string(L, "use", e->use);
  set_string(L, "marker", e->marker);
  if (e->shape.kind == SVGDOC_SHAPE_PATH) set_string(L, "d", e->shape.d);
  lua_pushinteger(L, (lua_Integer)e->line);
  lua_setfield(L, -2, "line");
  lua_pushinteger(L, (lua_Integer)e->col);
  lua_setfield(L, -2, "col");
  lua_pushboolean(L, e->stroked);
  lua_setfield(L, -2, "stroked");
  lua_pushboolean(L, e->filled);
  lua_setfield(L, -2, "filled");
  if (R->method) {
    double len;
    if (svgdoc_measure(&e->pd, R->method, &R->o, &len) == ARCLEN_OK) {
      lua_pushnumber(L, len);
      lua_setfield(L, -2, "length");
      if (R->bare) return;               /* its numbers are all it needs */
    }
  }
  set_lazy(L, R, e);
}

/* ---- svg.stats()'s add in C (svgdoc.stat_add) ------------------------
** The same numbers as lua/arclen/svg.lua's Stats:add computes from the
** element's path, by the same operations in the same order (its
** svgpath.segment_box and segment_end), without making the path: `arclen
** stat` spent most of its time there. */

static double lmin(double a, double b) { return b < a ? b : a; }  /* math.min */
static double lmax(double a, double b) { return a < b ? b : a; }  /* math.max */

typedef struct span { double lo, hi; } span;

static void span_add(span *r, double v) {
  if (v < r->lo) r->lo = v;
  if (v > r->hi) r->hi = v;
}

/* x rounded to a double on its own: svg.lua's arithmetic, which this
** mirrors, rounds every product before a sum, and a compiler that
** contracts a * b + c into a fused multiply-add would not (a volatile
** store, as metapost.c's pyth): the same bits on every build. */
static double rounded(double x) {
  volatile double v = x;
  return v;
}

/* The value at t of one coordinate p of a segment of kind (svgpath.lua's
** callbacks of range). */
static double coord_at(int kind, const double *p, double w, double t) {
  double u = 1 - t;
  if (kind == ARCLEN_SEG_QUAD)
    return rounded(u * u * p[0]) + rounded(2 * u * t * p[1]) + rounded(t * t * p[2]);
  if (kind == ARCLEN_SEG_CUBIC)
    return rounded(u * u * u * p[0]) + rounded(3 * u * u * t * p[1]) +
           rounded(3 * u * t * t * p[2]) + rounded(t * t * t * p[3]);
  {
    double b0 = rounded(u * u), b1 = rounded(2 * w * t * u), b2 = rounded(t * t);
    return (rounded(b0 * p[0]) + rounded(b1 * p[1]) + rounded(b2 * p[2])) / (b0 + b1 + b2);
  }
}

static void at01(int kind, const double *p, double w, double t, span *r) {
  if (t > 0 && t < 1) span_add(r, coord_at(kind, p, w, t));
}

/* svgpath.lua's roots01: the real roots in (0, 1) of a t^2 + b t + c. */
static void roots01(double a, double b, double c, int kind, const double *p,
                    double w, span *r) {
  double disc, q;
  if (fabs(a) < 1e-300) {
    if (b != 0) at01(kind, p, w, -c / b, r);
    return;
  }
  disc = rounded(b * b) - rounded(4 * a * c);
  if (disc < 0) return;
  q = -0.5 * (b + (b >= 0 ? 1 : -1) * sqrt(disc));
  at01(kind, p, w, q / a, r);
  if (q != 0) at01(kind, p, w, c / q, r);
}

/* svgpath.lua's range: one coordinate's extremes on [0, 1]. */
static span coord_range(int kind, const double *p, double w) {
  span r;
  int last = kind == ARCLEN_SEG_LINE ? 1 : kind == ARCLEN_SEG_CUBIC ? 3 : 2;
  r.lo = lmin(p[0], p[last]);
  r.hi = lmax(p[0], p[last]);
  if (kind == ARCLEN_SEG_QUAD) {
    roots01(0, p[0] - 2 * p[1] + p[2], p[1] - p[0], kind, p, w, &r);
  } else if (kind == ARCLEN_SEG_CUBIC) {
    roots01(-p[0] + rounded(3 * p[1]) - rounded(3 * p[2]) + p[3], 2 * (p[0] - 2 * p[1] + p[2]),
            p[1] - p[0], kind, p, w, &r);
  } else if (kind == ARCLEN_SEG_CONIC) {
    double a0 = rounded(w * (p[1] - p[0])), a1 = p[2] - p[0], a2 = rounded(w * (p[2] - p[1]));
    roots01(a0 - a1 + a2, a1 - 2 * a0, a0, kind, p, w, &r);
  }
  return r;
}

/* Neumaier's step, as svg.lua's neumaier. */
static void neumaier(double *sum, double *comp, double x) {
  double t = *sum + x;
  if (fabs(*sum) >= fabs(x)) *comp += (*sum - t) + x;
  else *comp += (x - t) + *sum;
  *sum = t;
}

static double get_num(lua_State *L, int t, const char *k) {
  double v;
  lua_getfield(L, t, k);
  v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

static void set_num(lua_State *L, int t, const char *k, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, t, k);
}

static void add_int(lua_State *L, int t, const char *k, lua_Integer d) {
  lua_Integer v;
  lua_getfield(L, t, k);
  v = lua_tointeger(L, -1);
  lua_pop(L, 1);
  lua_pushinteger(L, v + d);
  lua_setfield(L, t, k);
}

/* svgdoc.stat_add(e, acc) -> true, acc updated as Stats:add would; false
** (nothing done) for an element that is not the reader's, whose path has
** been made or is not made of these segments, or without a length. */
static int l_stat_add(lua_State *L) {
  const element_head *u;
  const double *rec;
  const unsigned char *kinds;
  const arclen_subpath *sub;
  double length, sum, comp, endx = 0, endy = 0, box[4];
  int has_end, has_box, j;
  size_t k, first;
  luaL_checktype(L, 1, LUA_TTABLE);
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_settop(L, 2);
  lua_pushboolean(L, 0);                          /* 3: the answer "no" */
  if (!lua_getmetatable(L, 1)) return 1;
  lua_rawgeti(L, -1, 1);
  u = (const element_head *)lua_touserdata(L, -1);
  if (u == NULL || lua_rawlen(L, -1) < sizeof *u || u->h.magic != ELEMENT_MAGIC ||
      !u->h.flat) {
    lua_pushboolean(L, 0);
    return 1;
  }
  lua_settop(L, 2);
  lua_pushliteral(L, "path");
  lua_rawget(L, 1);
  lua_pushliteral(L, "length");
  lua_rawget(L, 1);
  if (!lua_isnil(L, 3) || lua_type(L, 4) != LUA_TNUMBER) {
    lua_pushboolean(L, 0);
    return 1;
  }
  length = lua_tonumber(L, 4);
  lua_settop(L, 2);
  rec = head_records(u);
  kinds = head_kinds(u);
  sub = head_subpaths(u);
  sum = get_num(L, 2, "length"), comp = get_num(L, 2, "lc");
  neumaier(&sum, &comp, length);
  set_num(L, 2, "length", sum), set_num(L, 2, "lc", comp);
  add_int(L, 2, "elements", 1);
  /* the path's subpaths: those with segments (path.lua, build_flat) */
  {
    lua_Integer nsub = 0;
    for (k = 0; k < u->h.nsub; k++) nsub += sub[k].n > 0;
    add_int(L, 2, "paths", nsub);
    add_int(L, 2, "segments", (lua_Integer)u->h.n);
  }
  lua_getfield(L, 2, "endx");
  has_end = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (has_end) endx = get_num(L, 2, "endx"), endy = get_num(L, 2, "endy");
  sum = get_num(L, 2, "travel"), comp = get_num(L, 2, "tc");
  for (first = 0, k = 0; k < u->h.nsub; k++) {     /* capped: the subpaths */
    size_t last;
    const double *a, *b;
    int lk;
    if (sub[k].n == 0) continue;
    a = rec + ARCLEN_PD_STRIDE * first;
    last = first + sub[k].n - 1;
    b = rec + ARCLEN_PD_STRIDE * last;
    if (has_end) {
      /* svg.lua's sqrt(dx * dx + dy * dy), each square rounded */
      double dx = a[0] - endx, dy = a[1] - endy;
      neumaier(&sum, &comp, sqrt(rounded(dx * dx) + rounded(dy * dy)));
    }
    lk = arclen_segment_kind_of_letter(kinds[last]);
    j = lk == ARCLEN_SEG_LINE ? 2 : lk == ARCLEN_SEG_CUBIC ? 6 : 4;   /* segment_end */
    endx = b[j], endy = b[j + 1], has_end = 1;
    first = last + 1;
  }
  set_num(L, 2, "travel", sum), set_num(L, 2, "tc", comp);
  if (has_end) set_num(L, 2, "endx", endx), set_num(L, 2, "endy", endy);
  /* the bounding box (svg.lua's box_add of each segment_box) */
  lua_getfield(L, 2, "box");
  if (lua_type(L, 3) != LUA_TTABLE) {
    lua_pushboolean(L, 0);       /* cannot happen: Stats:add makes it */
    return 1;
  }
  lua_rawgeti(L, 3, 1);
  has_box = !lua_isnil(L, -1);
  lua_pop(L, 1);
  for (j = 0; j < 4 && has_box; j++) {
    lua_rawgeti(L, 3, j + 1);
    box[j] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  for (k = 0; k < u->h.n; k++) {
    const double *c = rec + ARCLEN_PD_STRIDE * k;
    int kind = arclen_segment_kind_of_letter(kinds[k]), m, i;
    double xs[4], ys[4];
    span x, y;
    m = kind == ARCLEN_SEG_LINE ? 2 : kind == ARCLEN_SEG_CUBIC ? 4 : 3;
    for (i = 0; i < m; i++) xs[i] = c[2 * i], ys[i] = c[2 * i + 1];
    x = coord_range(kind, xs, c[6]);
    y = coord_range(kind, ys, c[6]);
    if (!has_box) {
      box[0] = x.lo, box[1] = y.lo, box[2] = x.hi, box[3] = y.hi;
      has_box = 1;
      continue;
    }
    if (x.lo < box[0]) box[0] = x.lo;
    if (y.lo < box[1]) box[1] = y.lo;
    if (x.hi > box[2]) box[2] = x.hi;
    if (y.hi > box[3]) box[3] = y.hi;
  }
  for (j = 0; j < 4 && has_box; j++) {
    lua_pushnumber(L, box[j]);
    lua_rawseti(L, 3, j + 1);
  }
  lua_pushboolean(L, 1);
  return 1;
}

/* reader:finish(name) */
static int l_finish(lua_State *L) {
  svgdoc **D = check_reader(L);
  const char *name = luaL_checkstring(L, 2);
  const svgdoc_info *info;
  const size_t *skipped;
  size_t i, n;
  if (svgdoc_finish(*D) != 0) return raise(L, D);
  lua_createtable(L, 0, 8);
  if (!push_batch(L, (const reader *)D)) lua_newtable(L);
  lua_setfield(L, -2, "elements");
  n = svgdoc_nwarnings(*D);
  lua_createtable(L, (int)n, 0);
  for (i = 0; i < n; i++) {
    const svgdoc_warning *w = svgdoc_warning_at(*D, i);
    lua_pushfstring(L, "%s:%d:%d: %s", name, (int)w->line, (int)w->col, w->msg);
    lua_rawseti(L, -2, (int)i + 1);
  }
  lua_setfield(L, -2, "warnings");
  skipped = svgdoc_skipped(*D);
  lua_newtable(L);
  for (i = 0; i < SVGDOC_NSKIPPED; i++) {
    if (skipped[i] == 0) continue;
    lua_pushinteger(L, (lua_Integer)skipped[i]);
    lua_setfield(L, -2, svgdoc_skipped_tags[i]);
  }
  lua_setfield(L, -2, "skipped");
  lua_pushinteger(L, (lua_Integer)svgdoc_kept(*D));
  lua_setfield(L, -2, "kept");
  lua_pushinteger(L, (lua_Integer)svgdoc_drawn(*D));
  lua_setfield(L, -2, "drawn");
  info = svgdoc_root_info(*D);
  if (info->has_width) {
    lua_pushnumber(L, info->width);
    lua_setfield(L, -2, "width");
  }
  if (info->has_height) {
    lua_pushnumber(L, info->height);
    lua_setfield(L, -2, "height");
  }
  if (info->has_viewbox) {
    lua_createtable(L, 4, 0);
    for (i = 0; i < 4; i++) {
      lua_pushnumber(L, info->viewbox[i]);
      lua_rawseti(L, -2, (int)i + 1);
    }
    lua_setfield(L, -2, "viewbox");
  }
  svgdoc_free(*D);                 /* now, not at the next collection */
  *D = NULL;
  return 1;
}

static const luaL_Reg reader_methods[] = {
  {"scan", l_scan}, {"feed", l_feed}, {"finish", l_finish}, {NULL, NULL}};

static const luaL_Reg funcs[] = {{"new", l_new}, {"isatty", l_isatty},
                                 {"stat_add", l_stat_add}, {NULL, NULL}};

#if defined(_WIN32)
__declspec(dllexport)
#endif
int luaopen_arclen_svgdoc(lua_State *L) {
  if (luaL_newmetatable(L, READER)) {
    lua_pushcfunction(L, reader_gc);
    lua_setfield(L, -2, "__gc");
    luaL_newlib(L, reader_methods);
    lua_setfield(L, -2, "__index");
  }
  lua_pop(L, 1);
  luaL_newlib(L, funcs);
  arclenL_open_gzip(L);          /* gzip input (svgdoc_gzip.c) */
  return 1;
}
