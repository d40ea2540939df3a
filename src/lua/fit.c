/*
** fit.c -- the Lua binding of the length-versus-t fits (lenfit.c):
**   arclen.fit(c [, {method = "hermite"|"paper", n = , tol = , monotone = }])
**   fit:length(t)  fit:value(t)  fit:time(s)  fit:spans()  fit:monotone()
**   fit:errors([{truth = "simpson"|"exact", inverse = , npts = }])
**   fit.total  fit.evals  fit.method  fit.n  fit.tol  fit.dim  fit.nspans
**   fit.critical  fit.curve
**   arclen.gauss_legendre(n) -> nodes, weights (on [0, 1])
** A fit is a userdata holding the arclen_fit header and its spans.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lua/binding.h"
#include "svg/decimal.h"

#define FIT_MT "arclen.fit"

static const char *const method_names[] = {"hermite", "paper", NULL};
static const char *const truth_names[] = {"simpson", "exact", NULL};

/* An integer option in [lo, hi] at the top of the stack. */
static int opt_int(lua_State *L, int arg, const char *key, int lo, int hi) {
  double v;
  if (lua_type(L, -1) != LUA_TNUMBER)
    luaL_argerror(L, arg, lua_pushfstring(L, "%s must be a number, got %s",
                                          key, luaL_typename(L, -1)));
  v = lua_tonumber(L, -1);
  if (!(v >= lo && v <= hi) || v != floor(v))
    luaL_argerror(L, arg, lua_pushfstring(L,
        "%s must be an integer in [%d, %d]", key, lo, hi));
  return (int)v;
}

/* The index of the string at the top of the stack in names. */
static int opt_name(lua_State *L, int arg, const char *key,
                    const char *const *names) {
  const char *s;
  int i;
  if (lua_type(L, -1) != LUA_TSTRING)
    luaL_argerror(L, arg, lua_pushfstring(L, "%s must be a string, got %s",
                                          key, luaL_typename(L, -1)));
  s = lua_tostring(L, -1);
  for (i = 0; names[i] != NULL; i++)
    if (strcmp(s, names[i]) == 0) return i;
  return luaL_argerror(L, arg, lua_pushfstring(L, "unknown %s '%s'", key, s));
}

static void check_fit_opts(lua_State *L, int arg, arclen_fit_opts *o) {
  int has_tol = 0;
  arclen_fit_opts_init(o);
  const char *key;
  if (!arclenL_optbegin(L, arg)) return;
  while ((key = arclenL_optnext(L, arg)) != NULL) {
    if (strcmp(key, "method") == 0) {
      o->method = opt_name(L, arg, "method", method_names) == 1
                      ? ARCLEN_FIT_PAPER : ARCLEN_FIT_HERMITE;
    } else if (strcmp(key, "n") == 0) {
      o->n = opt_int(L, arg, "n", 1, ARCLEN_GL_MAXN);
    } else if (strcmp(key, "tol") == 0) {
      double v;
      if (lua_type(L, -1) != LUA_TNUMBER)
        luaL_argerror(L, arg, "tol must be a number");
      v = lua_tonumber(L, -1);
      if (!(v >= ARCLEN_FIT_TOL_MIN && v <= ARCLEN_RTOL_MAX))
        luaL_argerror(L, arg, "tol must be in [1e-9, 0.1]");
      o->tol = v;
      has_tol = 1;
    } else if (strcmp(key, "monotone") == 0) {
      if (lua_type(L, -1) != LUA_TBOOLEAN)
        luaL_argerror(L, arg, "monotone must be a boolean");
      o->monotone = lua_toboolean(L, -1);
    } else {
      luaL_argerror(L, arg, lua_pushfstring(L, "unknown option '%s'", key));
    }
    lua_pop(L, 1);
  }
  if (has_tol && o->method != ARCLEN_FIT_HERMITE)
    luaL_argerror(L, arg, "tol applies to method 'hermite' only");
  if (o->monotone && o->method != ARCLEN_FIT_PAPER)
    luaL_argerror(L, arg, "monotone applies to method 'paper' only "
                          "(hermite fits are always monotone)");
}

static arclen_fit *check_fit(lua_State *L, int arg) {
  return (arclen_fit *)luaL_checkudata(L, arg, FIT_MT);
}

/* arclen.fit(c [, opts]) -> fit | nil, message (tol out of reach) */
static int l_fit(lua_State *L) {
  double c[12];
  arclen_fit_span spans[ARCLEN_FIT_MAXSPANS];
  arclen_fit f, *u;
  arclen_fit_opts o;
  int dim = arclenL_checkcurve(L, 1, c), code;
  check_fit_opts(L, 2, &o);
  code = arclen_fit_build(c, dim, &o, &f, spans, ARCLEN_FIT_MAXSPANS);
  if (code == ARCLEN_ENOCONV) {
    lua_pushnil(L);
    lua_pushfstring(L, "tol not reached within %d spans",
                    ARCLEN_FIT_MAXSPANS);
    return 2;
  }
  if (code != ARCLEN_OK) return arclenL_argcode(L, code == ARCLEN_EINVAL ? 1 : 2, code);
  u = (arclen_fit *)lua_newuserdata(L, sizeof(arclen_fit) +
                                           f.nspans * sizeof(arclen_fit_span));
  *u = f;
  u->span = (arclen_fit_span *)(u + 1);
  memcpy(u->span, spans, f.nspans * sizeof(arclen_fit_span));
  luaL_getmetatable(L, FIT_MT);
  lua_setmetatable(L, -2);
  return 1;
}

static double check_t(lua_State *L, int arg) {
  double t = arclenL_checkfinite(L, arg, "t");
  if (!(t >= 0.0 && t <= 1.0)) luaL_argerror(L, arg, "t must be in [0, 1]");
  return t;
}

/* fit:length(t) -> approximate s(t) */
static int l_length(lua_State *L) {
  arclen_fit *f = check_fit(L, 1);
  lua_pushnumber(L, arclen_fit_length(f, check_t(L, 2)));
  return 1;
}

/* fit:value(t) -> approximate s(t)/s(1) */
static int l_value(lua_State *L) {
  arclen_fit *f = check_fit(L, 1);
  lua_pushnumber(L, arclen_fit_value(f, check_t(L, 2)));
  return 1;
}

/* fit:time(s) -> approximate t with s(t) = s (s <= 0: 0; s >= total: 1) */
static int l_time(lua_State *L) {
  arclen_fit *f = check_fit(L, 1);
  lua_pushnumber(L, arclen_fit_time(f, arclenL_checkfinite(L, 2, "length")));
  return 1;
}

/* fit:spans() -> { {t0 =, t1 =, y = {y0, y1, y2, y3}, monotone =}, ... } */
static int l_spans(lua_State *L) {
  arclen_fit *f = check_fit(L, 1);
  int i;
  lua_createtable(L, f->nspans, 0);
  for (i = 0; i < f->nspans; i++) {
    const arclen_fit_span *sp = &f->span[i];
    lua_createtable(L, 0, 4);
    lua_pushnumber(L, sp->t0);
    lua_setfield(L, -2, "t0");
    lua_pushnumber(L, sp->t1);
    lua_setfield(L, -2, "t1");
    arclenL_pushnumbers(L, sp->y, 4);
    lua_setfield(L, -2, "y");
    lua_pushboolean(L, arclen_fit_span_monotone(sp));
    lua_setfield(L, -2, "monotone");
    lua_rawseti(L, -2, i + 1);
  }
  return 1;
}

/* fit:monotone() -> boolean */
static int l_monotone(lua_State *L) {
  lua_pushboolean(L, arclen_fit_monotone(check_fit(L, 1)));
  return 1;
}

/* fit:errors([opts]) -> max, mean, argmax (Eqn 9 on the paper's grid) */
static int l_errors(lua_State *L) {
  arclen_fit *f = check_fit(L, 1);
  int truth = ARCLEN_TRUTH_SIMPSON, inverse = 0, npts = 0, code;
  double max, mean, argmax;
  if (!lua_isnoneornil(L, 2)) {
    luaL_checktype(L, 2, LUA_TTABLE);
    lua_pushnil(L);
    while (lua_next(L, 2)) {
      const char *key = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2)
                                                       : "?";
      if (strcmp(key, "truth") == 0)
        truth = opt_name(L, 2, "truth", truth_names) == 1
                    ? ARCLEN_TRUTH_EXACT : ARCLEN_TRUTH_SIMPSON;
      else if (strcmp(key, "inverse") == 0)
        inverse = lua_toboolean(L, -1);
      else if (strcmp(key, "npts") == 0)
        npts = opt_int(L, 2, "npts", 0, 100000);
      else
        luaL_argerror(L, 2, lua_pushfstring(L, "unknown option '%s'", key));
      lua_pop(L, 1);
    }
  }
  code = arclen_fit_error(f, truth, inverse, npts, &max, &mean, &argmax);
  if (code != ARCLEN_OK) return arclenL_argcode(L, 2, code);
  lua_pushnumber(L, max);
  lua_pushnumber(L, mean);
  lua_pushnumber(L, argmax);
  return 3;
}

static int l_tostring(lua_State *L) {
  arclen_fit *f = check_fit(L, 1);
  char buf[128], total[32];
  arclen_decimal_print(total, f->total, 17);     /* in any locale */
  snprintf(buf, sizeof buf, "arclen.fit(%s, %d span%s, total %s)",
           method_names[f->method == ARCLEN_FIT_PAPER], f->nspans,
           f->nspans == 1 ? "" : "s", total);
  lua_pushstring(L, buf);
  return 1;
}

/* Field-like access: methods first, then the fit's numbers. */
static int l_index(lua_State *L) {
  arclen_fit *f = check_fit(L, 1);
  const char *key = luaL_checkstring(L, 2);
  luaL_getmetatable(L, FIT_MT);
  lua_getfield(L, -1, "methods");
  lua_getfield(L, -1, key);
  if (!lua_isnil(L, -1)) return 1;
  lua_pop(L, 3);
  if (strcmp(key, "total") == 0) lua_pushnumber(L, f->total);
  else if (strcmp(key, "evals") == 0) lua_pushnumber(L, (lua_Number)f->evals);
  else if (strcmp(key, "method") == 0)
    lua_pushstring(L, method_names[f->method == ARCLEN_FIT_PAPER]);
  else if (strcmp(key, "n") == 0) lua_pushnumber(L, f->n);
  else if (strcmp(key, "tol") == 0) lua_pushnumber(L, f->tol);
  else if (strcmp(key, "dim") == 0) lua_pushnumber(L, f->dim);
  else if (strcmp(key, "nspans") == 0) lua_pushnumber(L, f->nspans);
  else if (strcmp(key, "critical") == 0) arclenL_pushnumbers(L, f->crit, f->ncrit);
  else if (strcmp(key, "curve") == 0) arclenL_pushnumbers(L, f->c, 4 * f->dim);
  else lua_pushnil(L);
  return 1;
}

/* arclen.gauss_legendre(n) -> nodes, weights of the n-point rule on [0,1] */
static int l_gauss_legendre(lua_State *L) {
  double x[ARCLEN_GL_MAXN], w[ARCLEN_GL_MAXN];
  int n;
  lua_pushvalue(L, 1);
  n = opt_int(L, 1, "n", 1, ARCLEN_GL_MAXN);
  lua_pop(L, 1);
  arclen_gauss_legendre(n, x, w);
  arclenL_pushnumbers(L, x, n);
  arclenL_pushnumbers(L, w, n);
  return 2;
}

static const luaL_Reg fit_methods[] = {
  {"length", l_length},
  {"value", l_value},
  {"time", l_time},
  {"spans", l_spans},
  {"monotone", l_monotone},
  {"errors", l_errors},
  {NULL, NULL}
};

static const luaL_Reg fit_funcs[] = {
  {"fit", l_fit},
  {"gauss_legendre", l_gauss_legendre},
  {NULL, NULL}
};

void arclen_open_fit(lua_State *L) {
  luaL_newmetatable(L, FIT_MT);
  lua_newtable(L);
  luaL_setfuncs(L, fit_methods, 0);
  lua_setfield(L, -2, "methods");
  lua_pushcfunction(L, l_index);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, l_tostring);
  lua_setfield(L, -2, "__tostring");
  lua_pop(L, 1);
  luaL_setfuncs(L, fit_funcs, 0);
}
