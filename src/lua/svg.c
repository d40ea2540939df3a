/*
** svg.c -- the Lua binding of the svg area: path data (svg/pathdata.c)
** and the numbers of SVG's attributes (svg/decimal.c).
**   arclen.svg_pathdata(d, arc_tol [, T]) -> subpaths
**                                         or nil, message [, position]
**   arclen.svg_number(s, i) -> value, next position; or nil
**   arclen.svg_numbers(s, cap) -> list [, position of the first bad byte];
**                                 nil when more than cap numbers
** Positions are 1-based, as string.find's.
** subpaths is a list of {x = x0, y = y0, closed = bool, [i] = cubic} with
** every cubic a table of 8 numbers (arclen.path builds a path from it).
** Bad data is a result, not an error: the message and the 1-based byte
** position (none for the transform's overflow), which arclen.svgpath
** raises for arclen.path to turn into a "bad argument" message.
*/
#include <ctype.h>
#include <math.h>

#include "lua/binding.h"
#include "svg/decimal.h"
#include "svg/pathdata.h"

#define BOX "arclen.pathdata"    /* the result's memory, freed by __gc too */

static int box_gc(lua_State *L) {
  arclen_pathdata_free((arclen_pathdata *)lua_touserdata(L, 1));
  return 0;
}

/* "'c'" for a byte (a NUL too), or the end of the data. */
static void add_byte(luaL_Buffer *b, const arclen_pathdata_error *e) {
  if (e->at_end) {
    luaL_addstring(b, "the end of the data");
    return;
  }
  luaL_addchar(b, '\'');
  luaL_addchar(b, (char)e->byte);
  luaL_addchar(b, '\'');
}

/* The inner message of arclen.svg_arc for the same failure. */
static void add_arc_reason(lua_State *L, luaL_Buffer *b,
                           const arclen_pathdata_error *e) {
  static const char *const coord[] = {"x1", "y1", "x2", "y2"};
  switch (e->arc) {
  case ARCLEN_PD_ARC_X1: case ARCLEN_PD_ARC_Y1:
  case ARCLEN_PD_ARC_X2: case ARCLEN_PD_ARC_Y2:
    luaL_addstring(b, coord[e->arc - ARCLEN_PD_ARC_X1]);
    luaL_addstring(b, " must be finite");
    break;
  case ARCLEN_PD_ARC_TOL:
    luaL_addstring(b, "tol must be a positive finite number");
    break;
  case ARCLEN_PD_ARC_OVERFLOW:
    luaL_addstring(b, "the arc's radii, centre or control points lie beyond "
                      "the largest double");
    break;
  case ARCLEN_PD_ARC_LEVEL:
    lua_pushfstring(L, "tol not reached by level %d (bound %f)",
                    ARCLEN_CONIC_MAXLEVEL, e->bound);
    luaL_addvalue(b);
    break;
  case ARCLEN_PD_ARC_CUBICS:
    luaL_addstring(b, "a control point of the cubics lies beyond the largest "
                      "double");
    break;
  case ARCLEN_PD_ARC_DEGENERATE:
    luaL_addstring(b, "the arc is degenerate in double precision (its control "
                      "points coincide or are collinear)");
    break;
  default:
    luaL_addstring(b, arclen_strerror(e->code));
  }
}

/* Push nil, the message of pd's error and its position; returns their
** count. */
static int push_error(lua_State *L, const arclen_pathdata *pd, const char *d) {
  const arclen_pathdata_error *e = &pd->err;
  luaL_Buffer b;
  lua_pushnil(L);
  luaL_buffinit(L, &b);
  switch (e->kind) {
  case ARCLEN_PD_EMPTY:
    luaL_addstring(&b, "path data is empty");
    break;
  case ARCLEN_PD_NO_MOVETO:
    luaL_addstring(&b, "path data must begin with a moveto (M or m), got ");
    add_byte(&b, e);
    break;
  case ARCLEN_PD_AFTER_Z:
    luaL_addstring(&b, "expected a command after Z, got ");
    add_byte(&b, e);
    break;
  case ARCLEN_PD_UNKNOWN:
    luaL_addstring(&b, "unknown command ");
    add_byte(&b, e);
    break;
  case ARCLEN_PD_CLOSE_FIRST:
    luaL_addstring(&b, "closepath before any moveto");
    break;
  case ARCLEN_PD_NUMBER:
    luaL_addstring(&b, "expected a number (");
    luaL_addchar(&b, e->cmd);
    luaL_addchar(&b, ' ');
    luaL_addstring(&b, arclen_pathdata_argname(e->cmd, e->arg));
    luaL_addstring(&b, "), got ");
    add_byte(&b, e);
    break;
  case ARCLEN_PD_EXPONENT:
    luaL_addstring(&b, "exponent without digits in a number");
    break;
  case ARCLEN_PD_RANGE:
    luaL_addstring(&b, "number out of range '");
    luaL_addlstring(&b, d + e->tok, e->toklen);
    luaL_addchar(&b, '\'');
    break;
  case ARCLEN_PD_FLAG:
    luaL_addstring(&b, "expected ");
    luaL_addstring(&b, arclen_pathdata_argname(e->cmd, e->arg));
    luaL_addstring(&b, " (0 or 1)");
    break;
  case ARCLEN_PD_COMMA:
    luaL_addstring(&b, "comma not followed by a number");
    break;
  case ARCLEN_PD_ARC:
    luaL_addstring(&b, "elliptical arc: ");
    add_arc_reason(L, &b, e);
    break;
  case ARCLEN_PD_TRANSFORM:
    luaL_addstring(&b, "the transform takes a coordinate out of range");
    break;
  default:
    luaL_addstring(&b, "not enough memory");
  }
  luaL_pushresult(&b);
  if (e->pos == 0) return 2;
  lua_pushinteger(L, (lua_Integer)e->pos);
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

static void push_subpaths(lua_State *L, const arclen_pathdata *pd) {
  size_t k, i;
  int j;
  lua_createtable(L, (int)pd->nsubpaths, 0);
  for (k = 0; k < pd->nsubpaths; k++) {
    const arclen_subpath *s = &pd->subpaths[k];
    const double *c = pd->cubics + 8 * s->first;
    lua_createtable(L, (int)s->n, 3);
    lua_pushnumber(L, s->x);
    lua_setfield(L, -2, "x");
    lua_pushnumber(L, s->y);
    lua_setfield(L, -2, "y");
    lua_pushboolean(L, s->closed);
    lua_setfield(L, -2, "closed");
    for (i = 0; i < s->n; i++, c += 8) {
      lua_createtable(L, 8, 0);
      for (j = 0; j < 8; j++) {
        lua_pushnumber(L, c[j]);
        lua_rawseti(L, -2, j + 1);
      }
      lua_rawseti(L, -2, (int)i + 1);
    }
    lua_rawseti(L, -2, (int)k + 1);
  }
}

/* arclen.svg_pathdata(d, arc_tol [, T]) -> subpaths */
static int l_svg_pathdata(lua_State *L) {
  size_t n;
  const char *d = luaL_checklstring(L, 1, &n);
  double arc_tol = luaL_checknumber(L, 2), Tbuf[6];
  const double *T = check_transform(L, 3, Tbuf);
  arclen_pathdata *pd = (arclen_pathdata *)lua_newuserdata(L, sizeof *pd);
  arclen_pathdata_init(pd);
  luaL_getmetatable(L, BOX);
  lua_setmetatable(L, -2);
  if (arclen_pathdata_parse(pd, d, n, arc_tol, T) != ARCLEN_PD_OK)
    return push_error(L, pd, d);
  push_subpaths(L, pd);
  arclen_pathdata_free(pd);       /* now, not at the next collection */
  return 1;
}

/* ---- numbers of attributes ---------------------------------------------- */

/* Lua's %s (isspace), for the separators of number lists. */
static int is_lua_space(unsigned char c) { return isspace(c) != 0; }

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
  size_t n, i = 0, count = 0;
  const char *s = luaL_checklstring(L, 1, &n);
  lua_Integer cap = luaL_checkinteger(L, 2);
  lua_newtable(L);
  while (i < n && (is_lua_space((unsigned char)s[i]) || s[i] == ','))
    i++;
  while (i < n) {
    double v;
    size_t e;
    if ((lua_Integer)++count > cap) return lua_pushnil(L), 1;
    e = arclen_decimal_scan(s, n, i, &v);
    if (e == i) {
      lua_pushinteger(L, (lua_Integer)i + 1);
      return 2;
    }
    lua_pushnumber(L, v);
    lua_rawseti(L, -2, (int)count);
    i = e;
    while (i < n && is_lua_space((unsigned char)s[i])) i++;
    if (i < n && s[i] == ',') i++;
    while (i < n && is_lua_space((unsigned char)s[i])) i++;
  }
  return 1;
}

static const luaL_Reg svg_funcs[] = {
  {"svg_pathdata", l_svg_pathdata},
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
