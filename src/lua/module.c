/*
** module.c -- the Lua binding's shared argument checking and the core
** functions: length, time, point, derivative, split, subcurve, critical.
** Every misuse raises "bad argument #n to 'fn' (...)", as lauxlib does.
*/
#include <math.h>
#include <string.h>

#include "lua/binding.h"
#include "svg/decimal.h"

/* ---- argument checking ------------------------------------------------ */

static double field_number(lua_State *L, int arg, int t, int i,
                           const char *what, int k) {
  double v;
  lua_rawgeti(L, t, i);
  if (lua_type(L, -1) != LUA_TNUMBER) {
    lua_pop(L, 1);
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "%s %d must be a number", what, k)), 0;
  }
  v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  if (!isfinite(v))
    luaL_argerror(L, arg, lua_pushfstring(L,
        "%s %d must be finite", what, k));
  return v;
}

int arclenL_checkcurve(lua_State *L, int arg, double *c) {
  size_t n;
  int i, dim;
  arg = arg < 0 ? lua_gettop(L) + arg + 1 : arg;
  if (lua_type(L, arg) != LUA_TTABLE)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "curve expected (a table of 8 or 12 numbers or of 4 points), got %s",
        luaL_typename(L, arg)));
  n = lua_rawlen(L, arg);
  lua_rawgeti(L, arg, 1);
  if (lua_type(L, -1) == LUA_TTABLE) {          /* 4 points {x, y[, z]} */
    size_t m = lua_rawlen(L, -1);
    lua_pop(L, 1);
    if (n != 4 || (m != 2 && m != 3))
      return luaL_argerror(L, arg,
          "curve must have 4 points of 2 or 3 coordinates");
    dim = (int)m;
    for (i = 0; i < 4; i++) {
      int k;
      lua_rawgeti(L, arg, i + 1);
      if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != (size_t)dim)
        return luaL_argerror(L, arg, lua_pushfstring(L,
            "point %d must be a table of %d numbers", i + 1, dim));
      for (k = 0; k < dim; k++)
        c[i * dim + k] = field_number(L, arg, lua_gettop(L), k + 1,
                                      "coordinate of point", i + 1);
      lua_pop(L, 1);
    }
    return dim;
  }
  if (n != 8 && n != 12)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "curve must have 8 (2D) or 12 (3D) numbers, got %d", (int)n));
  /* all n on the stack, read in place and popped at once (a pop per
  ** number was a quarter of the API calls); the room is asked for, since
  ** a caller may already hold values of its own */
  luaL_checkstack(L, (int)n, "curve coordinates");
  for (i = 1; i < (int)n; i++) lua_rawgeti(L, arg, i + 1);
  for (i = 0; i < (int)n; i++) {
    int idx = i - (int)n;
    if (lua_type(L, idx) != LUA_TNUMBER)
      return luaL_argerror(L, arg, lua_pushfstring(L,
          "curve coordinate %d must be a number", i + 1));
    c[i] = lua_tonumber(L, idx);
    if (!isfinite(c[i]))
      luaL_argerror(L, arg, lua_pushfstring(L,
          "curve coordinate %d must be finite", i + 1));
  }
  lua_pop(L, (int)n);
  return n == 8 ? 2 : 3;
}

double arclenL_checkfinite(lua_State *L, int arg, const char *what) {
  double v;
  if (lua_type(L, arg) != LUA_TNUMBER)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "%s must be a number, got %s", what, luaL_typename(L, arg))), 0;
  v = lua_tonumber(L, arg);
  if (!isfinite(v))
    luaL_argerror(L, arg, lua_pushfstring(L, "%s must be finite", what));
  return v;
}

double arclenL_optfinite(lua_State *L, int arg, double def, const char *what) {
  return lua_isnoneornil(L, arg) ? def : arclenL_checkfinite(L, arg, what);
}

double arclenL_checktol(lua_State *L, int arg, double v) {
  if (!(v >= ARCLEN_RTOL_MIN && v <= ARCLEN_RTOL_MAX))
    luaL_argerror(L, arg, "tol must be in [1e-15, 0.1]");
  return v;
}

/* The value of opts[key] as a finite number in [lo, hi]. */
static double opt_number(lua_State *L, int arg, const char *key, double lo,
                         double hi) {
  double v;
  if (lua_type(L, -1) != LUA_TNUMBER)
    luaL_argerror(L, arg, lua_pushfstring(L, "%s must be a number", key));
  v = lua_tonumber(L, -1);
  if (!(v >= lo && v <= hi)) {
    char a[32], b[32];                 /* %.14g as Lua's, in any locale */
    arclen_decimal_print(a, lo, 14);
    arclen_decimal_print(b, hi, 14);
    luaL_argerror(L, arg, lua_pushfstring(L, "%s must be in [%s, %s]", key,
                                          a, b));
  }
  return v;
}

int arclenL_optbegin(lua_State *L, int arg) {
  if (lua_isnoneornil(L, arg)) return 0;
  if (lua_type(L, arg) != LUA_TTABLE)
    luaL_argerror(L, arg, lua_pushfstring(L,
        "options table expected, got %s", luaL_typename(L, arg)));
  lua_pushnil(L);
  return 1;
}

const char *arclenL_optnext(lua_State *L, int arg) {
  if (!lua_next(L, arg)) return NULL;
  if (lua_type(L, -2) != LUA_TSTRING)
    luaL_argerror(L, arg, "option names must be strings");
  return lua_tostring(L, -2);
}

static void check_opts(lua_State *L, int arg, arclenL_opts *lo,
                       int with_kinds) {
  const char *key;
  arclen_opts_init(&lo->o);
  lo->method = arclen_find_method("gauss");
  lo->info = 0;
  lo->kinds = NULL;
  lo->nkinds = 0;
  arg = arg < 0 ? lua_gettop(L) + arg + 1 : arg;
  if (!arclenL_optbegin(L, arg)) return;
  while ((key = arclenL_optnext(L, arg)) != NULL) {
    if (strcmp(key, "tol") == 0) {
      if (lua_type(L, -1) != LUA_TNUMBER)
        luaL_argerror(L, arg, "tol must be a number");
      lo->o.rtol = arclenL_checktol(L, arg, lua_tonumber(L, -1));
    } else if (strcmp(key, "method") == 0) {
      const char *name;
      if (lua_type(L, -1) != LUA_TSTRING)
        luaL_argerror(L, arg, "method must be a string");
      name = lua_tostring(L, -1);
      lo->method = arclen_find_method(name);
      if (lo->method == NULL)
        luaL_argerror(L, arg, lua_pushfstring(L, "unknown method '%s'", name));
    } else if (strcmp(key, "t0") == 0) {
      lo->o.t0 = opt_number(L, arg, "t0", 0, 1);
    } else if (strcmp(key, "t1") == 0) {
      lo->o.t1 = opt_number(L, arg, "t1", 0, 1);
    } else if (strcmp(key, "steps") == 0) {
      double v = opt_number(L, arg, "steps", 1, 1e9);
      if (v != floor(v)) luaL_argerror(L, arg, "steps must be an integer");
      lo->o.steps = (long)v;
    } else if (strcmp(key, "info") == 0) {
      lo->info = lua_toboolean(L, -1);
    } else if (with_kinds && strcmp(key, "kinds") == 0) {
      size_t i;
      if (lua_type(L, -1) != LUA_TSTRING)
        luaL_argerror(L, arg, "kinds must be a string of letters L, Q, C, R");
      lo->kinds = lua_tolstring(L, -1, &lo->nkinds);  /* held by opts */
      for (i = 0; i < lo->nkinds; i++)
        if (arclen_segment_kind_of_letter((unsigned char)lo->kinds[i]) < 0)
          luaL_argerror(L, arg, lua_pushfstring(L,
              "kinds: letter %d is not L, Q, C or R", (int)i + 1));
    } else {
      luaL_argerror(L, arg, lua_pushfstring(L, "unknown option '%s'", key));
    }
    lua_pop(L, 1);
  }
}

void arclenL_checkopts(lua_State *L, int arg, arclenL_opts *lo) {
  check_opts(L, arg, lo, 0);
}

void arclenL_checkopts_kinds(lua_State *L, int arg, arclenL_opts *lo) {
  check_opts(L, arg, lo, 1);
}

void arclenL_pushinfo(lua_State *L, const arclen_info *info) {
  lua_createtable(L, 0, 6);
  lua_pushnumber(L, (lua_Number)info->evals);
  lua_setfield(L, -2, "evals");
  lua_pushnumber(L, (lua_Number)info->pieces);
  lua_setfield(L, -2, "pieces");
  lua_pushnumber(L, (lua_Number)info->depth);
  lua_setfield(L, -2, "depth");
  lua_pushnumber(L, info->err);
  lua_setfield(L, -2, "err");
  lua_pushnumber(L, (lua_Number)info->calls);
  lua_setfield(L, -2, "calls");
  if (info->branch) {
    lua_pushstring(L, info->branch);
    lua_setfield(L, -2, "branch");
  }
}

int arclenL_argcode(lua_State *L, int arg, int code) {
  return luaL_argerror(L, arg, arclen_strerror(code));
}

/* ---- curves as a table or as 8/12 numbers ------------------------------ */

/* The curve at argument 1: a table, or 8 (2D) or 12 (3D) numbers in a row
** (hot callers avoid building a table), followed by `extra` numeric
** arguments (time's length, point's t, ...).  Returns the dimension and sets
** *next to the first argument after the curve. */
static int check_curve_args(lua_State *L, int extra, double *c, int *next) {
  if (lua_type(L, 1) == LUA_TNUMBER) {
    double v[12 + 2];                    /* extra <= 2 */
    int i, k = 0, n;
    while (k < 12 + extra && lua_type(L, k + 1) == LUA_TNUMBER) {
      v[k] = lua_tonumber(L, k + 1);     /* read once: half the API calls */
      k++;
    }
    n = k - extra == 12 ? 12 : 8;
    for (i = 0; i < n; i++)              /* else the argument's error */
      c[i] = i < k && isfinite(v[i]) ? v[i]
                                     : arclenL_checkfinite(L, i + 1, "coordinate");
    *next = n + 1;
    return n == 8 ? 2 : 3;
  }
  *next = 2;
  return arclenL_checkcurve(L, 1, c);
}

/* The result of a method call: a number (and the info table on request),
** or nil and a message for failures MetaPost itself would report (also
** arclen.segment_length's and segment_time's, segment.c). */
int arclenL_pushresult(lua_State *L, int code, double v, int arg,
                       const arclenL_opts *lo, const arclen_info *info) {
  if (code == ARCLEN_EOVERFLOW) {
    lua_pushnil(L);
    lua_pushstring(L, arclen_strerror(code));
    return 2;
  }
  if (code == ARCLEN_EDIM)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "method '%s' does not support this dimension", lo->method->name));
  if (code != ARCLEN_OK) return arclenL_argcode(L, arg, code);
  lua_pushnumber(L, v);
  if (!lo->info) return 1;
  arclenL_pushinfo(L, info);
  return 2;
}

/* arclen.length(c [, opts]) */
static int l_length(lua_State *L) {
  double c[12], len;
  arclenL_opts lo;
  arclen_info info;
  int next, dim = check_curve_args(L, 0, c, &next), code;
  arclenL_checkopts(L, next, &lo);
  code = lo.method->length(c, dim, &lo.o, &len, lo.info ? &info : NULL);
  return arclenL_pushresult(L, code, len, next, &lo, &info);
}

/* arclen.time(c, s [, opts]): the parameter t with s(t) = s; 0 for s <= 0,
** 1 for s >= the length. */
static int l_time(lua_State *L) {
  double c[12], s, t;
  arclenL_opts lo;
  arclen_info info;
  int next, dim = check_curve_args(L, 1, c, &next), code;
  s = lua_type(L, next) == LUA_TNUMBER ? lua_tonumber(L, next) : 0;
  if (lua_type(L, next) != LUA_TNUMBER || isnan(s))
    luaL_argerror(L, next, "length must be a number (not NaN)");
  arclenL_checkopts(L, next + 1, &lo);
  if (lo.o.t0 != 0 || lo.o.t1 != 1)
    luaL_argerror(L, next + 1, "t0 and t1 do not apply to time");
  if (lo.method->time == NULL)
    return luaL_argerror(L, next + 1, lua_pushfstring(L,
        "method '%s' has no time (inverse)", lo.method->name));
  code = lo.method->time(c, dim, s, &lo.o, &t, lo.info ? &info : NULL);
  return arclenL_pushresult(L, code, t, next + 1, &lo, &info);
}

static double check_t(lua_State *L, int arg) {
  double t = arclenL_checkfinite(L, arg, "t");
  if (!(t >= 0 && t <= 1)) luaL_argerror(L, arg, "t must be in [0, 1]");
  return t;
}

void arclenL_pushnumbers(lua_State *L, const double *v, int n) {
  int i;
  lua_createtable(L, n, 0);
  for (i = 0; i < n; i++) {
    lua_pushnumber(L, v[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

/* arclen.point(c, t) -> x, y[, z] */
static int l_point(lua_State *L) {
  double c[12], p[3];
  int next, dim = check_curve_args(L, 1, c, &next), k;
  arclen_point(c, dim, check_t(L, next), p);
  for (k = 0; k < dim; k++) lua_pushnumber(L, p[k]);
  return dim;
}

/* arclen.derivative(c, t) -> dx, dy[, dz] */
static int l_derivative(lua_State *L) {
  double c[12], d[3];
  int next, dim = check_curve_args(L, 1, c, &next), k;
  arclen_derivative(c, dim, check_t(L, next), d);
  for (k = 0; k < dim; k++) lua_pushnumber(L, d[k]);
  return dim;
}

/* arclen.split(c, t) -> left, right (tables of control points) */
static int l_split(lua_State *L) {
  double c[12], l[12], r[12];
  int next, dim = check_curve_args(L, 1, c, &next);
  arclen_split(c, dim, check_t(L, next), l, r);
  arclenL_pushnumbers(L, l, 4 * dim);
  arclenL_pushnumbers(L, r, 4 * dim);
  return 2;
}

/* arclen.subcurve(c, t0, t1) -> the part from t0 to t1 */
static int l_subcurve(lua_State *L) {
  double c[12], out[12], t0, t1;
  int next, dim = check_curve_args(L, 2, c, &next);
  t0 = check_t(L, next);
  t1 = check_t(L, next + 1);
  arclen_subcurve(c, dim, t0, t1, out);
  arclenL_pushnumbers(L, out, 4 * dim);
  return 1;
}

/* arclen.critical(c) -> {t...}: the speed's critical points in (0, 1) */
static int l_critical(lua_State *L) {
  double c[12], r[3];
  int next, dim = check_curve_args(L, 0, c, &next), n;
  n = arclen_critical_points(c, dim, r);
  arclenL_pushnumbers(L, r, n);
  return 1;
}

/* arclen.methods() -> {name...}: the length methods available */
static int l_methods(lua_State *L) {
  const arclen_method *m = arclen_method_list();
  int i = 0;
  lua_newtable(L);
  for (; m->name != NULL; m++) {
    lua_pushstring(L, m->name);
    lua_rawseti(L, -2, ++i);
  }
  return 1;
}

/* arclen.method(name) -> {name =, time = boolean} or nil: what the
** registry says of a method, so that callers need not probe it. */
static int l_method(lua_State *L) {
  const arclen_method *m = arclen_find_method(luaL_checkstring(L, 1));
  if (m == NULL) {
    lua_pushnil(L);
    return 1;
  }
  lua_createtable(L, 0, 2);
  lua_pushstring(L, m->name);
  lua_setfield(L, -2, "name");
  lua_pushboolean(L, m->time != NULL);
  lua_setfield(L, -2, "time");
  return 1;
}

static const luaL_Reg core_funcs[] = {
  {"length", l_length},
  {"time", l_time},
  {"point", l_point},
  {"derivative", l_derivative},
  {"split", l_split},
  {"subcurve", l_subcurve},
  {"critical", l_critical},
  {"methods", l_methods},
  {"method", l_method},
  {NULL, NULL}
};

void arclen_open_core(lua_State *L) {
  luaL_setfuncs(L, core_funcs, 0);
  lua_pushstring(L, ARCLEN_VERSION);
  lua_setfield(L, -2, "_VERSION");
  /* the tolerance limits, named once for the Lua layer too */
  lua_pushnumber(L, ARCLEN_RTOL_MIN);
  lua_setfield(L, -2, "tol_min");
  lua_pushnumber(L, ARCLEN_RTOL_MAX);
  lua_setfield(L, -2, "tol_max");
}

/* The C part of the module: require "arclen.core".  `require "arclen"`
** is lua/arclen/init.lua, which adds the Lua parts (arclen.path) to it. */
int luaopen_arclen_core(lua_State *L);

int luaopen_arclen_core(lua_State *L) {
  lua_newtable(L);
  arclen_open_core(L);
  arclen_open_conic(L);
  arclen_open_henkel(L);
  arclen_open_elliptic(L);
  arclen_open_fit(L);
  arclen_open_batch(L);
  arclen_open_times(L);
  arclen_open_svg(L);
  arclen_open_segment(L);
  /* new areas: one line each, above this line */
  return 1;
}

/* The entry point for package.loadlib(".../arclen/core.so", "luaopen_arclen")
** (LuaTeX documents): the core, registered as "arclen.core", then the whole
** module by require "arclen.init" when the Lua parts are on package.path;
** without them, the core alone. */
int luaopen_arclen(lua_State *L);

int luaopen_arclen(lua_State *L) {
  luaopen_arclen_core(L);
  lua_getglobal(L, "package");
  if (lua_istable(L, -1)) {
    lua_getfield(L, -1, "loaded");
    if (lua_istable(L, -1)) {
      lua_pushvalue(L, -3);
      lua_setfield(L, -2, "arclen.core");
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  lua_getglobal(L, "require");
  lua_pushliteral(L, "arclen.init");
  if (lua_pcall(L, 1, 1, 0) == 0 && lua_istable(L, -1)) return 1;
  lua_pop(L, 1);
  return 1;
}
