/*
** elliptic.c -- the Lua binding of Carlson's R-functions
** (arclen.carlson.rf/rd/rc/rj/rg) and the polynomial root solvers
** (arclen.quadratic/cubic/quartic, arclen.quartic_factor).
** Domain errors name the argument: "bad argument #2 to 'rf' (...)".
*/
#include <math.h>

#include "lua/binding.h"

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

/* arclen_rj scales a principal value's arguments under 2^501 itself
** (R_J's homogeneity); NaN is left only when that flushes a second
** argument to 0: a spread beyond what the reduction serves. */
static int l_rj(lua_State *L) {
  double v[4], r;
  check_args(L, v, 4, 1);     /* p < 0: Cauchy principal value */
  at_most_one_zero(L, v, 3);
  r = arclen_rj(v[0], v[1], v[2], v[3]);
  if (r != r)
    luaL_argerror(L, 4, "p's principal value (p < 0) is out of reach: "
                        "|p| and x, y, z spread beyond the double range");
  lua_pushnumber(L, r);
  return 1;
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

/* ---- roots ------------------------------------------------------------ */

static const char *const COEF[] = {"a4", "a3", "a2", "a1", "a0"};

/* n + 1 finite coefficients (names from a_n down to a0) into a[]. */
static void check_coeffs(lua_State *L, int n, double *a) {
  int i;
  for (i = 0; i <= n; i++) a[i] = arclenL_checkfinite(L, i + 1, COEF[4 - n + i]);
}

/* A list of roots {{re, im}, ...}. */
static int push_roots(lua_State *L, int n, const double *re,
                      const double *im) {
  int i;
  lua_createtable(L, n, 0);
  for (i = 0; i < n; i++) {
    lua_createtable(L, 2, 0);
    lua_pushnumber(L, re[i]); lua_rawseti(L, -2, 1);
    lua_pushnumber(L, im[i]); lua_rawseti(L, -2, 2);
    lua_rawseti(L, -2, i + 1);
  }
  return 1;
}

static int l_quadratic(lua_State *L) {
  double a[3], re[2], im[2];
  check_coeffs(L, 2, a);
  return push_roots(L, arclen_quadratic(a[0], a[1], a[2], re, im), re, im);
}

static int l_cubic(lua_State *L) {
  double a[4], re[3], im[3];
  check_coeffs(L, 3, a);
  return push_roots(L, arclen_cubic(a[0], a[1], a[2], a[3], re, im), re, im);
}

static int l_quartic(lua_State *L) {
  double a[5], re[4], im[4];
  check_coeffs(L, 4, a);
  return push_roots(L, arclen_quartic(a[0], a[1], a[2], a[3], a[4], re, im),
                    re, im);
}

/* arclen.quartic_factor(a4, a3, a2, a1, a0) -> p1, q1, p2, q2 with
** a4 x^4 + ... + a0 = a4 (x^2 + p1 x + q1)(x^2 + p2 x + q2). */
static int l_quartic_factor(lua_State *L) {
  double a[5], q[4];
  int i;
  check_coeffs(L, 4, a);
  if (a[0] == 0) luaL_argerror(L, 1, "a4 must not be 0 (not a quartic)");
  if (arclen_quartic_factor(a[0], a[1], a[2], a[3], a[4], q) != ARCLEN_OK)
    return luaL_error(L, "quartic_factor failed");
  for (i = 0; i < 4; i++) lua_pushnumber(L, q[i]);
  return 4;
}

static const luaL_Reg roots_funcs[] = {
  {"quadratic", l_quadratic}, {"cubic", l_cubic}, {"quartic", l_quartic},
  {"quartic_factor", l_quartic_factor},
  {NULL, NULL}
};

void arclen_open_elliptic(lua_State *L) {
  luaL_setfuncs(L, roots_funcs, 0);
  lua_newtable(L);
  luaL_setfuncs(L, carlson_funcs, 0);
  lua_setfield(L, -2, "carlson");
}
