/*
** svg.c -- the Lua binding of the svg area: path data (svg/pathdata.c)
** and the numbers of SVG's attributes (svg/decimal.c).
**   arclen.svg_pathdata(d, arc_tol [, T [, arcs]]) -> subpaths
**                                         or nil, message [, position]
**     arcs "conics" (nil too): the kinds as written (L H V Z lines, Q T
**     quadratics, C S cubics, A conics, exactly); "cubics": cubics only,
**     arcs within arc_tol times their size (pathdata.h)
**   arclen.svg_number(s, i) -> value, next position; or nil
**   arclen.svg_numbers(s, cap) -> list [, position of the first bad byte];
**                                 nil when more than cap numbers
** Positions are 1-based, as string.find's.
** subpaths is {packed = the records as a string of doubles, n = segments,
** kinds = their letters (nil: all cubics), [j] = {x = x0, y = y0, closed =
** bool, n = its segments}} (lua/subpaths.c; arclen.path builds a path on
** it).
**   arclen._cubics(packed) -> {cubic, ...}: the packed cubics as tables
** Bad data is a result, not an error: the message and the 1-based byte
** position (none for the transform's overflow), which arclen.svgpath
** raises for arclen.path to turn into a "bad argument" message.
*/
#include <math.h>
#include <string.h>

#include "lua/binding.h"
#include "svg/decimal.h"
#include "svg/pathdata.h"

#define BOX "arclen.pathdata"    /* the result's memory, freed by __gc too */

static int box_gc(lua_State *L) {
  arclen_pathdata_free((arclen_pathdata *)lua_touserdata(L, 1));
  return 0;
}

/* Push nil, the message of pd's error and its position; returns their
** count. */
static int push_error(lua_State *L, const arclen_pathdata *pd, const char *d) {
  size_t n = arclen_pathdata_message(pd, d, NULL, 0);
  char *m = (char *)lua_newuserdata(L, n + 1);
  arclen_pathdata_message(pd, d, m, n + 1);
  lua_pushnil(L);
  lua_pushlstring(L, m, n);
  if (pd->err.pos == 0) return 2;
  lua_pushinteger(L, (lua_Integer)pd->err.pos);
  return 3;
}

/* The transform at arg: nil, or a table of 6 finite numbers. */
static const double *check_transform(lua_State *L, int arg, double *T) {
  int k;
  if (lua_isnoneornil(L, arg)) return NULL;
  if (lua_type(L, arg) != LUA_TTABLE || lua_rawlen(L, arg) != 6)
    luaL_argerror(L, arg, "transform must be {a, b, c, d, e, f}");
  for (k = 0; k < 6; k++) {
    lua_rawgeti(L, arg, k + 1);
    T[k] = lua_tonumber(L, -1);
    if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(T[k]))
      luaL_argerror(L, arg, "transform entries must be finite numbers");
    lua_pop(L, 1);
  }
  return T;
}

/* The arcs option at arg: nil or "conics", or "cubics". */
static int check_arcs(lua_State *L, int arg) {
  static const char *const names[] = {"conics", "cubics", NULL};
  static const int modes[] = {ARCLEN_PD_ARCS_CONICS, ARCLEN_PD_ARCS_CUBICS};
  int k;
  if (lua_isnoneornil(L, arg)) return ARCLEN_PD_ARCS_CONICS;
  if (lua_type(L, arg) == LUA_TSTRING) {
    const char *s = lua_tostring(L, arg);
    for (k = 0; names[k] != NULL; k++)
      if (strcmp(s, names[k]) == 0) return modes[k];
  }
  return luaL_argerror(L, arg, "arcs must be \"conics\" or \"cubics\"");
}

/* arclen.svg_pathdata(d, arc_tol [, T [, arcs]]) -> subpaths */
static int l_svg_pathdata(lua_State *L) {
  size_t n;
  const char *d = luaL_checklstring(L, 1, &n);
  double arc_tol = luaL_checknumber(L, 2), Tbuf[6];
  const double *T = check_transform(L, 3, Tbuf);
  int arcs = check_arcs(L, 4);
  arclen_pathdata *pd = (arclen_pathdata *)lua_newuserdata(L, sizeof *pd);
  arclen_pathdata_init(pd);
  pd->arcs = arcs;
  luaL_getmetatable(L, BOX);
  lua_setmetatable(L, -2);
  if (arclen_pathdata_parse(pd, d, n, arc_tol, T) != ARCLEN_PD_OK)
    return push_error(L, pd, d);
  arclenL_pushsubpaths(L, pd);
  arclen_pathdata_free(pd);       /* now, not at the next collection */
  return 1;
}

/* ---- numbers of attributes ---------------------------------------------- */

/* arclen.svg_number(s, i) -> value, next: the number of SVG's grammar (an
** exponent only when complete) at byte i, or nil when there is none or it
** is beyond the doubles. */
static int l_svg_number(lua_State *L) {
  size_t n, e;
  const char *s = luaL_checklstring(L, 1, &n);
  lua_Integer i = luaL_checkinteger(L, 2);
  double v;
  if (i < 1 || (size_t)i > n) return lua_pushnil(L), 1;
  e = arclen_decimal_scan(s, n, (size_t)i - 1, &v);
  if (e == (size_t)i - 1) return lua_pushnil(L), 1;
  lua_pushnumber(L, v);
  lua_pushinteger(L, (lua_Integer)e + 1);
  return 2;
}

/* arclen.svg_numbers(s, cap) -> list [, bad]: numbers separated by
** whitespace and at most one comma (points, viewBox), leading whitespace
** and commas skipped; bad is the position of the first byte that starts
** no number.  nil when more than cap numbers would be read. */
static int l_svg_numbers(lua_State *L) {
  size_t n, i, count = 0;
  const char *s = luaL_checklstring(L, 1, &n);
  lua_Integer cap = luaL_checkinteger(L, 2);
  lua_newtable(L);
  for (i = arclen_decimal_list_start(s, n); i < n;) {
    double v;
    size_t e;
    if ((lua_Integer)++count > cap) return lua_pushnil(L), 1;
    e = arclen_decimal_list_next(s, n, i, &v);
    if (e == i) {
      lua_pushinteger(L, (lua_Integer)i + 1);
      return 2;
    }
    lua_pushnumber(L, v);
    lua_rawseti(L, -2, (int)count);
    i = e;
  }
  return 1;
}

static const luaL_Reg svg_funcs[] = {
  {"svg_pathdata", l_svg_pathdata},
  {"_cubics", arclenL_unpackcubics},
  {"svg_number", l_svg_number},
  {"svg_numbers", l_svg_numbers},
  {NULL, NULL}
};

void arclen_open_svg(lua_State *L) {
  if (luaL_newmetatable(L, BOX)) {
    lua_pushcfunction(L, box_gc);
    lua_setfield(L, -2, "__gc");
  }
  lua_pop(L, 1);
  luaL_setfuncs(L, svg_funcs, 0);
}
