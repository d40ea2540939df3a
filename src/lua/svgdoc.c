/*
** svgdoc.c -- the Lua binding of the document reader (svgdoc/): the
** module arclen.svgdoc, a shared object of its own because it links
** libexpat, which arclen.core does without.  arclen.svg is its user.
**   svgdoc.new(opts) -> reader    opts: arc_tol, unit_px (0: user units),
**                                 hidden, stroked, max_depth, uses, stream,
**                                 max_held (the queue behind a forward use),
**                                 strict (warnings are errors)
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
**   svgdoc.gzip, svgdoc.gunzip    gzip input (svgdoc_gzip.c)
** A located error is raised as {line =, col =, msg =}; arclen.svg names
** the document in it.  Each element is {id, tag, layer, line, col,
** stroked, use, d, ctm = {a, b, c, d, e, f}, subpaths} (subpaths as
** arclen.core.svg_pathdata returns them).  Warnings come formatted as
** "NAME:LINE:COL: message".
*/
#include <string.h>

#include "lua/binding.h"
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

static svgdoc **check_reader(lua_State *L) {
  svgdoc **D = (svgdoc **)luaL_checkudata(L, 1, READER);
  if (*D == NULL) luaL_argerror(L, 1, "the reader has finished");
  return D;
}

static int reader_gc(lua_State *L) {
  svgdoc **D = (svgdoc **)luaL_checkudata(L, 1, READER);
  svgdoc_free(*D);
  *D = NULL;
  return 0;
}

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
  svgdoc **D;
  double depth, held;
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
  o.uses = opt_boolean(L, "uses");
  o.stream = opt_boolean(L, "stream");
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
  D = (svgdoc **)lua_newuserdata(L, sizeof *D);
  *D = NULL;
  luaL_getmetatable(L, READER);
  lua_setmetatable(L, -2);
  *D = svgdoc_new(&o);
  if (*D == NULL) return luaL_error(L, "not enough memory");
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

static void push_element(lua_State *L, const svgdoc_element *e);

/* The elements the last call completed, as a list (nothing when none). */
static int push_batch(lua_State *L, svgdoc *D) {
  size_t i, n = svgdoc_count(D);
  if (n == 0) return 0;
  lua_createtable(L, n > 0x7fffffff ? 0x7fffffff : (int)n, 0);
  for (i = 0; i < n; i++) {
    push_element(L, svgdoc_get(D, i));
    lua_rawseti(L, -2, (int)i + 1);
  }
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
  return svgdoc_streaming(*D) ? push_batch(L, *D) : 0;
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

static void push_element(lua_State *L, const svgdoc_element *e) {
  int k;
  lua_createtable(L, 0, 10);
  set_string(L, "id", e->id);
  set_string(L, "tag", e->tag);
  set_string(L, "layer", e->layer);
  set_string(L, "use", e->use);
  set_string(L, "d", e->d);
  lua_pushinteger(L, (lua_Integer)e->line);
  lua_setfield(L, -2, "line");
  lua_pushinteger(L, (lua_Integer)e->col);
  lua_setfield(L, -2, "col");
  lua_pushboolean(L, e->stroked);
  lua_setfield(L, -2, "stroked");
  lua_createtable(L, 6, 0);
  for (k = 0; k < 6; k++) {
    lua_pushnumber(L, e->ctm[k]);
    lua_rawseti(L, -2, k + 1);
  }
  lua_setfield(L, -2, "ctm");
  arclenL_pushsubpaths(L, &e->pd);
  lua_setfield(L, -2, "subpaths");
}

/* reader:finish(name) */
static int l_finish(lua_State *L) {
  svgdoc **D = check_reader(L);
  const char *name = luaL_checkstring(L, 2);
  const svgdoc_info *info;
  const size_t *skipped;
  size_t i, n;
  if (svgdoc_finish(*D) != 0) return raise(L, D);
  n = svgdoc_count(*D);
  lua_createtable(L, 0, 8);
  lua_createtable(L, n > 0x7fffffff ? 0x7fffffff : (int)n, 0);
  for (i = 0; i < n; i++) {
    push_element(L, svgdoc_get(*D, i));
    lua_rawseti(L, -2, (int)i + 1);
  }
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
                                 {NULL, NULL}};

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
