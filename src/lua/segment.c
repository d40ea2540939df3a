/*
** segment.c -- segments of four kinds (line, quad, cubic, conic) from Lua:
**   arclen.segment_length(kind, seg [, opts]) -> length [, info]
**   arclen.segment_time(kind, seg, s [, opts]) -> t [, info]
**   arclen.segment_point(kind, seg, t) -> x, y [, z]
**   arclen.segment_derivative(kind, seg, t) -> dx, dy [, dz]
**   arclen.segment_sub(kind, seg, t0, t1) -> seg'
**   arclen._segments(packed, kinds, dim) -> {seg, ...}
** seg is a table of the kind's numbers (the points, then a conic's
** weight); opts as arclen.length's (method applies to cubics).  The
** argument checks the other binding files share are here too.
*/
#include <math.h>
#include <string.h>

#include "lua/binding.h"

int arclenL_checkkind(lua_State *L, int arg) {
  const char *name;
  int kind;
  if (lua_type(L, arg) != LUA_TSTRING)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "segment kind expected (line, quad, cubic or conic), got %s",
        luaL_typename(L, arg)));
  name = lua_tostring(L, arg);
  kind = arclen_segment_kind(name);
  if (kind < 0)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "unknown segment kind '%s' (line, quad, cubic or conic)", name));
  return kind;
}

/* The error of a segment whose numbers are read (code from
** arclen_segment_check); what names it ("segment 3: ", or ""). */
static int segment_error(lua_State *L, int arg, const char *what, int kind,
                         int dim, const double *seg) {
  int i, n = arclen_segment_count(kind, dim);
  for (i = 0; i < n; i++)
    if (!isfinite(seg[i]))
      return luaL_argerror(L, arg, lua_pushfstring(L,
          "%snumber %d must be finite", what, i + 1));
  return luaL_argerror(L, arg, lua_pushfstring(L,
      "%sconic weight (number %d) must be positive", what, n));
}

int arclenL_checksegment(lua_State *L, int arg, int kind, double *seg) {
  int n, i, dim, n2 = arclen_segment_count(kind, 2);
  int n3 = arclen_segment_count(kind, 3);
  arg = arg < 0 ? lua_gettop(L) + arg + 1 : arg;
  if (lua_type(L, arg) != LUA_TTABLE)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "segment expected (a table of %d or %d numbers), got %s", n2, n3,
        luaL_typename(L, arg)));
  n = (int)lua_rawlen(L, arg);
  if (n != n2 && n != n3)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "a %s has %d (2D) or %d (3D) numbers, got %d",
        arclen_segment_kind_name(kind), n2, n3, n));
  dim = n == n2 ? 2 : 3;
  for (i = 0; i < n; i++) {
    if (rawgeti_type(L, arg, i + 1) != LUA_TNUMBER)
      return luaL_argerror(L, arg, lua_pushfstring(L,
          "number %d must be a number, got %s", i + 1, luaL_typename(L, -1)));
    seg[i] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  if (arclen_segment_check(kind, dim, seg) != ARCLEN_OK)
    segment_error(L, arg, "", kind, dim, seg);
  return dim;
}

int arclenL_kindat(lua_State *L, int arg, const char *kinds, long k) {
  int kind = arclen_segment_kind_of_letter((unsigned char)kinds[k - 1]);
  if (kind < 0)
    luaL_argerror(L, arg, lua_pushfstring(L,
        "kinds: letter %d is not L, Q, C or R", (int)k));
  return kind;
}

const char *arclenL_optkinds(lua_State *L, int arg, long n, int letters) {
  size_t len;
  long i;
  const char *k;
  if (lua_isnoneornil(L, arg)) return NULL;
  if (lua_type(L, arg) != LUA_TSTRING)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "kinds must be a string of letters L, Q, C, R, got %s",
        luaL_typename(L, arg))), NULL;
  k = lua_tolstring(L, arg, &len);
  if ((long)len != n)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "kinds must have one letter per segment (%d), got %d", (int)n,
        (int)len)), NULL;
  for (i = 1; letters && i <= n; i++) arclenL_kindat(L, arg, k, i);
  return k;
}

void arclenL_packedsegment(lua_State *L, int arg, const char *packed,
                           long k, int kind, int dim, double *seg) {
  int n = arclen_segment_count(kind, dim);
  memcpy(seg, packed + (size_t)k * 4 * (size_t)dim * sizeof(double),
         (size_t)n * sizeof(double));
  if (arclen_segment_check(kind, dim, seg) != ARCLEN_OK) {
    lua_pushfstring(L, "segment %d (%s): ", (int)k + 1,
                    arclen_segment_kind_name(kind));
    segment_error(L, arg, lua_tostring(L, -1), kind, dim, seg);
  }
}

/* arclen.segment_length(kind, seg [, opts]) */
static int l_segment_length(lua_State *L) {
  double seg[ARCLEN_SEG_MAXN], len;
  arclenL_opts lo;
  arclen_info info;
  int kind = arclenL_checkkind(L, 1), dim = arclenL_checksegment(L, 2, kind, seg);
  int code;
  arclenL_checkopts(L, 3, &lo);
  code = arclen_segment_length(kind, dim, seg, lo.method, &lo.o, &len,
                               lo.info ? &info : NULL);
  return arclenL_pushresult(L, code, len, 3, &lo, &info);
}

/* arclen.segment_time(kind, seg, s [, opts]): s clamped to [0, L] */
static int l_segment_time(lua_State *L) {
  double seg[ARCLEN_SEG_MAXN], s, t;
  arclenL_opts lo;
  arclen_info info;
  int kind = arclenL_checkkind(L, 1), dim = arclenL_checksegment(L, 2, kind, seg);
  int code;
  s = lua_type(L, 3) == LUA_TNUMBER ? lua_tonumber(L, 3) : 0;
  if (lua_type(L, 3) != LUA_TNUMBER || isnan(s))
    luaL_argerror(L, 3, "length must be a number (not NaN)");
  arclenL_checkopts(L, 4, &lo);
  if (lo.o.t0 != 0 || lo.o.t1 != 1)
    luaL_argerror(L, 4, "t0 and t1 do not apply to time");
  if (kind == ARCLEN_SEG_CUBIC && lo.method->time == NULL)
    return luaL_argerror(L, 4, lua_pushfstring(L,
        "method '%s' has no time (inverse)", lo.method->name));
  code = arclen_segment_time(kind, dim, seg, s, lo.method, &lo.o, &t,
                             lo.info ? &info : NULL);
  return arclenL_pushresult(L, code, t, 4, &lo, &info);
}

static double check_t(lua_State *L, int arg, const char *what) {
  double t = arclenL_checkfinite(L, arg, what);
  if (!(t >= 0 && t <= 1))
    luaL_argerror(L, arg, lua_pushfstring(L, "%s must be in [0, 1]", what));
  return t;
}

/* arclen.segment_point(kind, seg, t) -> x, y [, z] */
static int l_segment_point(lua_State *L) {
  double seg[ARCLEN_SEG_MAXN], p[3];
  int kind = arclenL_checkkind(L, 1), dim = arclenL_checksegment(L, 2, kind, seg);
  int k;
  arclen_segment_point(kind, dim, seg, check_t(L, 3, "t"), p);
  for (k = 0; k < dim; k++) lua_pushnumber(L, p[k]);
  return dim;
}

/* arclen.segment_derivative(kind, seg, t) -> dx, dy [, dz] */
static int l_segment_derivative(lua_State *L) {
  double seg[ARCLEN_SEG_MAXN], d[3];
  int kind = arclenL_checkkind(L, 1), dim = arclenL_checksegment(L, 2, kind, seg);
  int k;
  arclen_segment_derivative(kind, dim, seg, check_t(L, 3, "t"), d);
  for (k = 0; k < dim; k++) lua_pushnumber(L, d[k]);
  return dim;
}

/* arclen.segment_sub(kind, seg, t0, t1) -> the piece, a new table */
static int l_segment_sub(lua_State *L) {
  double seg[ARCLEN_SEG_MAXN], out[ARCLEN_SEG_MAXN], t0, t1;
  int kind = arclenL_checkkind(L, 1), dim = arclenL_checksegment(L, 2, kind, seg);
  t0 = check_t(L, 3, "t0");
  t1 = check_t(L, 4, "t1");
  arclen_segment_sub(kind, dim, seg, t0, t1, out);
  arclenL_pushnumbers(L, out, arclen_segment_count(kind, dim));
  return 1;
}

/* arclen._segments(packed, kinds, dim) -> {seg, ...}: packed segments
** (records of 4 dim doubles) as tables of their kind's numbers; kinds nil:
** all cubics (dim absent: 2). */
static int l_segments(lua_State *L) {
  size_t len;
  const char *packed = luaL_checklstring(L, 1, &len), *kinds;
  int dim = (int)luaL_optinteger(L, 3, 2);
  long n, k;
  size_t rec;
  luaL_argcheck(L, dim == 2 || dim == 3, 3, "dimension must be 2 or 3");
  rec = 4 * (size_t)dim * sizeof(double);
  if (len % rec != 0)
    return luaL_argerror(L, 1, lua_pushfstring(L,
        "packed segments: a multiple of %d bytes expected", (int)rec));
  luaL_argcheck(L, len / rec <= 0x7fffffff, 1, "too many segments");
  n = (long)(len / rec);
  kinds = arclenL_optkinds(L, 2, n, 1);
  lua_createtable(L, (int)n, 0);
  for (k = 0; k < n; k++) {
    double seg[ARCLEN_SEG_MAXN];
    int kind = kinds ? arclen_segment_kind_of_letter((unsigned char)kinds[k])
                     : ARCLEN_SEG_CUBIC;
    arclenL_packedsegment(L, 1, packed, k, kind, dim, seg);
    arclenL_pushnumbers(L, seg, arclen_segment_count(kind, dim));
    lua_rawseti(L, -2, (int)k + 1);
  }
  return 1;
}

static const luaL_Reg segment_funcs[] = {
  {"segment_length", l_segment_length},
  {"segment_time", l_segment_time},
  {"segment_point", l_segment_point},
  {"segment_derivative", l_segment_derivative},
  {"segment_sub", l_segment_sub},
  {"_segments", l_segments},
  {NULL, NULL}
};

void arclen_open_segment(lua_State *L) {
  luaL_setfuncs(L, segment_funcs, 0);
}
