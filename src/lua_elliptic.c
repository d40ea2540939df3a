/*
** lua_elliptic.c -- the Lua binding of Carlson's R-functions
** (arclen.carlson.rf/rd/rc/rj/rg) and the polynomial root solvers
** (arclen.quadratic/cubic/quartic, arclen.quartic_factor).
** Domain errors name the argument: "bad argument #2 to 'rf' (...)".
*/
#include <math.h>

#include "lua_arclen.h"

static const char *const XYZP[] = {"x", "y", "z", "p"};

/* n finite numbers >= 0 (the last one, if lastsign, only nonzero). */
static void check_args(lua_State *L, double *v, int n, int lastsign) {
  int i;
  for (i = 0; i < n; i++) {
    v[i] = arclenL_checkfinite(L, i + 1, XYZP[i]);
    if (lastsign && i == n - 1) {
      if (v[i] == 0)
        luaL_argerror(L, i + 1, lua_pushfstring(L, "%s must not be 0",
                                                XYZP[i]));
    } else if (v[i] < 0) {
      luaL_argerror(L, i + 1, lua_pushfstring(L, "%s must be >= 0",
                                              XYZP[i]));
    }
  }
}

/* At most one zero among the first n: the integral diverges otherwise. */
static void at_most_one_zero(lua_State *L, const double *v, int n) {
  int i, zeros = 0;
  for (i = 0; i < n; i++)
    if (v[i] == 0 && ++zeros > 1)
      luaL_argerror(L, i + 1, n == 2
          ? "x and y must not both be 0 (the integral diverges)"
          : "at most one of x, y, z may be 0 (the integral diverges)");
}

static int push_result(lua_State *L, double r) {
  if (r != r) return luaL_error(L, "R-function domain error");  /* guard */
  lua_pushnumber(L, r);
  return 1;
}

static int l_rf(lua_State *L) {
  double v[3];
  check_args(L, v, 3, 0);
  at_most_one_zero(L, v, 3);
  return push_result(L, arclen_rf(v[0], v[1], v[2]));
}

static int l_rd(lua_State *L) {
  double v[3];
  check_args(L, v, 3, 0);
  at_most_one_zero(L, v, 2);
  if (v[2] == 0) luaL_argerror(L, 3, "z must be > 0 (the integral diverges)");
  return push_result(L, arclen_rd(v[0], v[1], v[2]));
}

static int l_rc(lua_State *L) {
  double v[2];
  check_args(L, v, 2, 1);     /* y < 0: Cauchy principal value */
  return push_result(L, arclen_rc(v[0], v[1]));
}

static int l_rj(lua_State *L) {
  double v[4];
  check_args(L, v, 4, 1);     /* p < 0: Cauchy principal value */
  at_most_one_zero(L, v, 3);
  return push_result(L, arclen_rj(v[0], v[1], v[2], v[3]));
}

static int l_rg(lua_State *L) {
  double v[3];
  check_args(L, v, 3, 0);
  return push_result(L, arclen_rg(v[0], v[1], v[2]));
}

static const luaL_Reg carlson_funcs[] = {
  {"rf", l_rf}, {"rd", l_rd}, {"rc", l_rc}, {"rj", l_rj}, {"rg", l_rg},
  {NULL, NULL}
};

void arclen_open_elliptic(lua_State *L) {
  lua_newtable(L);
  luaL_setfuncs(L, carlson_funcs, 0);
  lua_setfield(L, -2, "carlson");
}
