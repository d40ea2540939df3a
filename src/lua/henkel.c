/*
** henkel.c -- the Lua binding of what is MetaPost-specific: the table
** arclen.metapost with arclength and arctime of one cubic and of MetaPost
** paths (open or cyclic, several segments).  Where mpost reports
** "Arithmetic overflow" (a leg of 16384 or more) these return nil and
** "arithmetic overflow".  (Gravesen and the baselines are methods:
** arclen.length(c, {method = "gravesen"}) etc.)
*/
#include <string.h>

#include "lua/binding.h"

#define MAX_SEGMENTS 10000000   /* keeps the scratch allocation sane */

static int push_number_or_fail(lua_State *L, int code, double v, int arg) {
  if (code == ARCLEN_EOVERFLOW) {
    lua_pushnil(L);
    lua_pushstring(L, arclen_strerror(code));
    return 2;
  }
  if (code != ARCLEN_OK) return arclenL_argcode(L, arg, code);
  lua_pushnumber(L, v);
  return 1;
}

static void check_2d(lua_State *L, int arg, int dim) {
  if (dim != 2)
    luaL_argerror(L, arg, "MetaPost curves are 2D (8 numbers or 4 points)");
}

/* arclen.metapost.arclength(c) -> length | nil, "arithmetic overflow" */
static int l_mp_arclength(lua_State *L) {
  double c[12], len;
  int code;
  check_2d(L, 1, arclenL_checkcurve(L, 1, c));
  code = arclen_mp_arclength(c, &len, NULL);
  return push_number_or_fail(L, code, len, 1);
}

/* arclen.metapost.arctime(c, g) -> t in [0, 1] | nil, "arithmetic overflow" */
static int l_mp_arctime(lua_State *L) {
  double c[12], g, t;
  int code;
  check_2d(L, 1, arclenL_checkcurve(L, 1, c));
  g = arclenL_checkfinite(L, 2, "goal");
  code = arclen_mp_arctime(c, g, &t, NULL);
  return push_number_or_fail(L, code, t, 2);
}

/* One number of a segment table (index i of the table at t). */
static double seg_number(lua_State *L, int t, int i, int k) {
  double v;
  lua_rawgeti(L, t, i);
  if (lua_type(L, -1) != LUA_TNUMBER)
    luaL_argerror(L, 1, lua_pushfstring(L,
        "segment %d must be 8 numbers or 4 points {x, y}", k));
  v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  if (v - v != 0)
    luaL_argerror(L, 1, lua_pushfstring(L,
        "segment %d has a coordinate that is not finite", k));
  return v;
}

/* Reads segment k (table on top of the stack) into s[8]. */
static void read_segment(lua_State *L, int k, double *s) {
  int t = lua_gettop(L), i;
  if (lua_type(L, t) != LUA_TTABLE)
    luaL_argerror(L, 1, lua_pushfstring(L,
        "segment %d must be a table, got %s", k, luaL_typename(L, t)));
  if (lua_rawlen(L, t) == 8) {
    for (i = 0; i < 8; i++) s[i] = seg_number(L, t, i + 1, k);
    return;
  }
  if (lua_rawlen(L, t) != 4)
    luaL_argerror(L, 1, lua_pushfstring(L,
        "segment %d must be 8 numbers or 4 points {x, y}", k));
  for (i = 0; i < 4; i++) {
    lua_rawgeti(L, t, i + 1);
    if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 2)
      luaL_argerror(L, 1, lua_pushfstring(L,
          "segment %d must be 8 numbers or 4 points {x, y}", k));
    s[2 * i] = seg_number(L, lua_gettop(L), 1, k);
    s[2 * i + 1] = seg_number(L, lua_gettop(L), 2, k);
    lua_pop(L, 1);
  }
}

/* The path at argument 1 (a table of segments that join end to start; for a
** cyclic path the last one ends where the first starts).  Returns the
** segments in scratch memory owned by the Lua stack and their count. */
static double *check_path(lua_State *L, int cyclic, int *n) {
  size_t len;
  double *seg;
  int k;
  luaL_checktype(L, 1, LUA_TTABLE);
  len = lua_rawlen(L, 1);
  if (len < 1 || len > MAX_SEGMENTS)
    luaL_argerror(L, 1, "path must have 1 to 10^7 segments");
  seg = (double *)lua_newuserdata(L, len * 8 * sizeof(double));
  for (k = 0; k < (int)len; k++) {
    lua_rawgeti(L, 1, k + 1);
    read_segment(L, k + 1, seg + 8 * k);
    lua_pop(L, 1);
    if (k > 0 && (seg[8 * k] != seg[8 * k - 2] ||
                  seg[8 * k + 1] != seg[8 * k - 1]))
      luaL_argerror(L, 1, lua_pushfstring(L,
          "segment %d does not start where segment %d ends", k + 1, k));
  }
  if (cyclic && (seg[0] != seg[8 * len - 2] || seg[1] != seg[8 * len - 1]))
    luaL_argerror(L, 1, "cyclic path: the last segment must end where the "
                        "first starts");
  *n = (int)len;
  return seg;
}

/* arclen.metapost.path_arclength(path [, cyclic]) */
static int l_mp_path_arclength(lua_State *L) {
  int cyclic = lua_toboolean(L, 2), n, code;
  double len, *seg = check_path(L, cyclic, &n);
  code = arclen_mp_path_arclength(seg, n, cyclic, &len, NULL);
  return push_number_or_fail(L, code, len, 1);
}

/* arclen.metapost.path_arctime(path, g [, cyclic]) -> MetaPost time
** (segment index + parameter) */
static int l_mp_path_arctime(lua_State *L) {
  int cyclic = lua_toboolean(L, 3), n, code;
  double g = arclenL_checkfinite(L, 2, "goal"), t;
  double *seg = check_path(L, cyclic, &n);
  code = arclen_mp_path_arctime(seg, n, cyclic, g, &t, NULL);
  return push_number_or_fail(L, code, t, 2);
}

static const luaL_Reg metapost_funcs[] = {
  {"arclength", l_mp_arclength},
  {"arctime", l_mp_arctime},
  {"path_arclength", l_mp_path_arclength},
  {"path_arctime", l_mp_path_arctime},
  {NULL, NULL}
};

void arclen_open_henkel(lua_State *L) {
  lua_createtable(L, 0, 4);
  luaL_setfuncs(L, metapost_funcs, 0);
  /* Also package.loaded["arclen.metapost"], so that argument errors name
  ** the function ('arclen.metapost.arctime') even when it is pcall'ed. */
  lua_getfield(L, LUA_REGISTRYINDEX, "_LOADED");
  if (lua_type(L, -1) == LUA_TTABLE) {
    lua_pushvalue(L, -2);
    lua_setfield(L, -2, "arclen.metapost");
  }
  lua_pop(L, 1);
  lua_setfield(L, -2, "metapost");
}
