/*
** conic.c -- the Lua binding of Floater's conic approximation:
** conic, ellipse_arc, svg_arc, fullcircle, conic_length, conic_scheme.
*/
#include <math.h>
#include <string.h>

#include "lua/binding.h"
#include "curve/numeric.h"
#include "svg/decimal.h"


/* What opts asks for: the scheme and either a level or a tolerance. */
typedef struct conic_opts {
  int scheme;
  int level;    /* -1: choose by tol */
  double tol;
} conic_opts;

static void check_conic_opts(lua_State *L, int arg, conic_opts *co) {
  int have_level = 0;
  co->scheme = ARCLEN_CONIC_MIDPOINT;
  co->level = 0;
  co->tol = 0;
  const char *key;
  if (!arclenL_optbegin(L, arg)) return;
  while ((key = arclenL_optnext(L, arg)) != NULL) {
    if (strcmp(key, "scheme") == 0) {
      if (lua_type(L, -1) != LUA_TSTRING)
        luaL_argerror(L, arg, "scheme must be a string");
      co->scheme = arclen_conic_scheme(lua_tostring(L, -1));
      if (co->scheme < 0)
        luaL_argerror(L, arg, lua_pushfstring(L,
            "unknown scheme '%s' (quadratic, g2, midpoint, c2, g4)",
            lua_tostring(L, -1)));
    } else if (strcmp(key, "level") == 0) {
      double v = lua_tonumber(L, -1);
      if (lua_type(L, -1) != LUA_TNUMBER || v != floor(v) || v < 0 ||
          v > ARCLEN_CONIC_MAXLEVEL)
        luaL_argerror(L, arg, lua_pushfstring(L,
            "level must be an integer in [0, %d]", ARCLEN_CONIC_MAXLEVEL));
      co->level = (int)v;
      have_level = 1;
    } else if (strcmp(key, "tol") == 0) {
      double v = lua_tonumber(L, -1);
      if (lua_type(L, -1) != LUA_TNUMBER || !(v > 0) || !isfinite(v))
        luaL_argerror(L, arg, "tol must be a positive finite number");
      co->tol = v;
    } else {
      luaL_argerror(L, arg, lua_pushfstring(L, "unknown option '%s'", key));
    }
    lua_pop(L, 1);
  }
  if (co->tol > 0) {
    if (have_level) luaL_argerror(L, arg, "give level or tol, not both");
    co->level = -1;
  }
}

/* A point argument {x, y}. */
static void check_point(lua_State *L, int arg, const char *name, double *xy) {
  int k;
  if (lua_type(L, arg) != LUA_TTABLE || lua_rawlen(L, arg) != 2)
    luaL_argerror(L, arg, lua_pushfstring(L,
        "%s must be a point {x, y}, got %s", name, luaL_typename(L, arg)));
  for (k = 0; k < 2; k++) {
    lua_rawgeti(L, arg, k + 1);
    if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
      luaL_argerror(L, arg, lua_pushfstring(L,
          "%s must have finite number coordinates", name));
    xy[k] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
}

/* The weight argument: w > 0, or three weights {w0, w1, w2}. */
static double check_weight(lua_State *L, int arg) {
  double w;
  if (lua_type(L, arg) == LUA_TTABLE) {
    double ws[3];
    int k;
    if (lua_rawlen(L, arg) != 3)
      luaL_argerror(L, arg, "weights must be a number or {w0, w1, w2}");
    for (k = 0; k < 3; k++) {
      lua_rawgeti(L, arg, k + 1);
      if (lua_type(L, -1) != LUA_TNUMBER)
        luaL_argerror(L, arg, "weights must be numbers");
      ws[k] = lua_tonumber(L, -1);
      lua_pop(L, 1);
    }
    if (arclen_conic_normal_weight(ws[0], ws[1], ws[2], &w) != ARCLEN_OK)
      luaL_argerror(L, arg,
          "weights must be finite, non-zero and of one sign");
    return w;
  }
  w = arclenL_checkfinite(L, arg, "w");
  if (!(w > 0)) luaL_argerror(L, arg, "w must be > 0");
  return w;
}

/* p0, p1, p2, w at arg .. arg+3 into p[6], *w; errors name the argument. */
static void check_conic(lua_State *L, int arg, double p[6], double *w) {
  check_point(L, arg, "p0", p);
  check_point(L, arg + 1, "p1", p + 2);
  check_point(L, arg + 2, "p2", p + 4);
  *w = check_weight(L, arg + 3);
  if (arclen_conic_degenerate(p))
    luaL_argerror(L, arg + 1,
        "control points are coincident or collinear (no conic)");
}

/* The level for the n conics at c (7 numbers each) under co: the given
** one, or the smallest meeting co->tol for every piece. */
static int pick_level(lua_State *L, int optarg, const double *c, int n,
                      const conic_opts *co) {
  int k, level = 0;
  if (co->level >= 0) return co->level;
  for (k = 0; k < n; k++) {
    int lk;
    double b;
    int rc = arclen_conic_level(c + 7 * k, c[7 * k + 6], co->scheme, co->tol,
                                &lk, &b);
    if (rc == ARCLEN_ENOCONV) {
      char num[32];                    /* %.14g as Lua's, in any locale */
      arclen_decimal_print(num, b, 14);
      luaL_argerror(L, optarg, lua_pushfstring(L,
          "tol not reached by level %d (bound %s)", ARCLEN_CONIC_MAXLEVEL, num));
    } else if (rc != ARCLEN_OK)
      arclenL_argcode(L, optarg, rc);
    if (lk > level) level = lk;
  }
  return level;
}

/* Push the list of cubics for n conics at one level, and return the
** largest bound.  A scratch userdata holds one conic's cubics. */
static double push_cubics(lua_State *L, const double *c, int n, int scheme,
                          int level) {
  long per = 1L << level, i;
  double *buf = (double *)lua_newuserdata(L, sizeof(double) * 8 * per);
  double bound = 0;
  int k, tbl;
  lua_createtable(L, (int)(per * n), 0);
  tbl = lua_gettop(L);
  for (k = 0; k < n; k++) {
    double b;
    int j;
    /* a conic that rounding made degenerate (an arc of radius 2 at x = 9e15)
    ** leaves buf unwritten: an error, not garbage (spec/hostile_spec.lua) */
    int rc = arclen_conic_cubics(c + 7 * k, c[7 * k + 6], scheme, level,
                                 buf, &b);
    if (rc == ARCLEN_EOVERFLOW)   /* mid-point handles beyond +-DBL_MAX */
      luaL_argerror(L, 1, "a control point of the cubics lies beyond the "
                          "largest double");
    if (rc != ARCLEN_OK)
      luaL_argerror(L, 1, "the arc is degenerate in double precision "
                          "(its control points coincide or are collinear)");
    if (b > bound || isnan(b)) bound = b;
    for (i = 0; i < per; i++) {
      lua_createtable(L, 8, 0);
      for (j = 0; j < 8; j++) {
        lua_pushnumber(L, buf[8 * i + j]);
        lua_rawseti(L, -2, j + 1);
      }
      lua_rawseti(L, tbl, (int)(k * per + i + 1));
    }
  }
  lua_remove(L, tbl - 1);   /* the scratch buffer */
  return bound;
}

/* Push cubics, bound, level for n conics; returns 3. */
static int finish(lua_State *L, int optarg, const double *c, int n,
                  const conic_opts *co) {
  int level = pick_level(L, optarg, c, n, co);
  double bound = push_cubics(L, c, n, co->scheme, level);
  lua_pushnumber(L, bound);
  lua_pushinteger(L, level);
  return 3;
}

/* arclen.conic(p0, p1, p2, w [, opts]) -> cubics, bound, level.  Any
** finite w > 0: w -> inf is the control polygon (a degenerate hyperbola),
** w -> 0 the chord, and the subdivision of eq. (4) brings the pieces'
** weights near 1; the level-0 bound is inf when ||g|| ~ w^2 overflows. */
static int l_conic(lua_State *L) {
  double c[7];
  conic_opts co;
  check_conic(L, 1, c, &c[6]);
  check_conic_opts(L, 5, &co);
  return finish(L, 5, c, 1, &co);
}

/* The arguments 1..7 (cx, cy, rx, ry, rotation, angle1, angle2) of an
** elliptic arc, checked, as at most four conics in c[28]; returns how many.
** Errors name the argument. */
static int ellipse_args(lua_State *L, double c[28]) {
  static const char *const names[7] = {
    "cx", "cy", "rx", "ry", "rotation", "angle1", "angle2"
  };
  double v[7];
  int k, n;
  for (k = 0; k < 7; k++) v[k] = arclenL_checkfinite(L, k + 1, names[k]);
  if (!(v[2] > 0)) luaL_argerror(L, 3, "rx must be > 0");
  if (!(v[3] > 0)) luaL_argerror(L, 4, "ry must be > 0");
  n = arclen_ellipse_conics(v[0], v[1], v[2], v[3], v[4], v[5], v[6] - v[5],
                            c);
  if (n == ARCLEN_ERANGE)
    luaL_argerror(L, 7, "the arc must not turn more than 2*pi");
  if (n == ARCLEN_EOVERFLOW)
    luaL_argerror(L, 3, "the arc's control points lie beyond the largest "
                        "double");
  if (n < 0) return arclenL_argcode(L, 7, n);
  return n;
}

/* arclen.ellipse_arc(cx, cy, rx, ry, rotation, angle1, angle2 [, opts]):
** radians; parametric angles (x = rx cos t, y = ry sin t, then rotated). */
static int l_ellipse_arc(lua_State *L) {
  double c[28];
  conic_opts co;
  int n = ellipse_args(L, c);
  check_conic_opts(L, 8, &co);
  return finish(L, 8, c, n, &co);
}

static int check_flag(lua_State *L, int arg, const char *name) {
  if (lua_type(L, arg) == LUA_TBOOLEAN) return lua_toboolean(L, arg);
  if (lua_type(L, arg) == LUA_TNUMBER) {
    double v = lua_tonumber(L, arg);
    if (v == 0 || v == 1) return (int)v;
  }
  return luaL_argerror(L, arg, lua_pushfstring(L,
      "%s must be a boolean or 0/1", name));
}

/* arclen.svg_arc(x1, y1, rx, ry, rotation_deg, large_arc, sweep, x2, y2
** [, opts]) -> cubics, bound, level (SVG 1.1 F.6.5, F.6.6). */
static int l_svg_arc(lua_State *L) {
  double x1 = arclenL_checkfinite(L, 1, "x1");
  double y1 = arclenL_checkfinite(L, 2, "y1");
  double rx = arclenL_checkfinite(L, 3, "rx");
  double ry = arclenL_checkfinite(L, 4, "ry");
  double rot = arclenL_checkfinite(L, 5, "rotation");
  int large = check_flag(L, 6, "large_arc");
  int sweep = check_flag(L, 7, "sweep");
  double x2 = arclenL_checkfinite(L, 8, "x2");
  double y2 = arclenL_checkfinite(L, 9, "y2");
  double c[28];
  conic_opts co;
  int kind, n;
  check_conic_opts(L, 10, &co);
  kind = arclen_svg_arc_conics(x1, y1, rx, ry, rot, large, sweep, x2, y2, c,
                               &n);
  if (kind == ARCLEN_SVGARC_NONE) {       /* F.6.2: the arc is omitted */
    lua_newtable(L);
    lua_pushnumber(L, 0);
    lua_pushinteger(L, 0);
    return 3;
  }
  if (kind == ARCLEN_SVGARC_LINE) {       /* F.6.2: a straight segment */
    double seg[8];
    int j;
    seg[0] = x1; seg[1] = y1; seg[6] = x2; seg[7] = y2;
    seg[2] = x1 + (x2 - x1) / 3; seg[3] = y1 + (y2 - y1) / 3;
    seg[4] = x2 - (x2 - x1) / 3; seg[5] = y2 - (y2 - y1) / 3;
    lua_createtable(L, 1, 0);
    lua_createtable(L, 8, 0);
    for (j = 0; j < 8; j++) {
      lua_pushnumber(L, seg[j]);
      lua_rawseti(L, -2, j + 1);
    }
    lua_rawseti(L, -2, 1);
    lua_pushnumber(L, 0);
    lua_pushinteger(L, 0);
    return 3;
  }
  if (kind == ARCLEN_EOVERFLOW)
    luaL_argerror(L, 3, "the arc's radii, centre or control points lie "
                        "beyond the largest double");
  if (kind < 0) return arclenL_argcode(L, 1, kind);
  return finish(L, 10, c, n, &co);
}

/* arclen.fullcircle() -> MetaPost's fullcircle: 8 cubics of the unit-
** diameter circle from (0.5, 0) counter-clockwise, and its bound.  Each
** quadrant is the conic (r,0) (r,r) (0,r), w = cos 45 deg, by the mid-point
** scheme at level 1 (handle (4/3) r tan(45/4 deg) = 0.1326...). */
static int l_fullcircle(lua_State *L) {
  static const double q[4][6] = {
    {0.5, 0, 0.5, 0.5, 0, 0.5}, {0, 0.5, -0.5, 0.5, -0.5, 0},
    {-0.5, 0, -0.5, -0.5, 0, -0.5}, {0, -0.5, 0.5, -0.5, 0.5, 0}
  };
  double c[28];
  int k, j;
  for (k = 0; k < 4; k++) {
    for (j = 0; j < 6; j++) c[7 * k + j] = q[k][j];
    c[7 * k + 6] = sqrt(0.5);
  }
  lua_pushnumber(L, push_cubics(L, c, 4, ARCLEN_CONIC_MIDPOINT, 1));
  return 2;
}

/* arclen.conic_length(p0, p1, p2, w [, opts]) -> exact length [, info]
** (opts.info = true adds {branch=, calls=, ...}). */
static int l_conic_length(lua_State *L) {
  double c[7], len;
  arclen_info info;
  int want_info = 0, rc;
  check_conic(L, 1, c, &c[6]);
  if (!lua_isnoneornil(L, 5)) {
    luaL_checktype(L, 5, LUA_TTABLE);
    lua_pushnil(L);
    while (lua_next(L, 5)) {
      if (lua_type(L, -2) != LUA_TSTRING ||
          strcmp(lua_tostring(L, -2), "info") != 0)
        luaL_argerror(L, 5, "unknown option (only 'info')");
      want_info = lua_toboolean(L, -1);
      lua_pop(L, 1);
    }
  }
  rc = arclen_conic_length(c, c[6], &len, &info);
  if (rc == ARCLEN_EOVERFLOW)     /* only when the polygon reaches DBL_MAX */
    luaL_argerror(L, 1, "the conic's length exceeds the largest double");
  if (rc != ARCLEN_OK) return arclenL_argcode(L, 1, rc);
  lua_pushnumber(L, len);
  if (!want_info) return 1;
  arclenL_pushinfo(L, &info);
  return 2;
}

/* arclen.ellipse_conics(cx, cy, rx, ry, rotation, angle1, angle2) -> list
** of conics {x0, y0, x1, y1, x2, y2, w} (pieces of at most 90 degrees). */
static int l_ellipse_conics(lua_State *L) {
  double c[28];
  int k, j, n = ellipse_args(L, c);
  lua_createtable(L, n, 0);
  for (k = 0; k < n; k++) {
    lua_createtable(L, 7, 0);
    for (j = 0; j < 7; j++) {
      lua_pushnumber(L, c[7 * k + j]);
      lua_rawseti(L, -2, j + 1);
    }
    lua_rawseti(L, -2, k + 1);
  }
  return 1;
}

/* arclen.conic_scheme(name, w) -> lambda, A, B, max|g| (Props 2, 13),
** for any finite w > 0; A, B, max|g| grow like w^2 and are +-inf beyond
** w ~ 1e154 (never NaN). */
static int l_conic_scheme(lua_State *L) {
  const char *name = luaL_checkstring(L, 1);
  int s = arclen_conic_scheme(name);
  double w = arclenL_checkfinite(L, 2, "w"), A, B;
  if (s < 0)
    luaL_argerror(L, 1, lua_pushfstring(L, "unknown scheme '%s'", name));
  if (!(w > 0)) luaL_argerror(L, 2, "w must be > 0");
  arclen_conic_scheme_AB(s, w, &A, &B);
  lua_pushnumber(L, arclen_conic_lambda(s, w));
  lua_pushnumber(L, A);
  lua_pushnumber(L, B);
  lua_pushnumber(L, arclen_conic_gnorm(A, B));
  return 4;
}

static const luaL_Reg conic_funcs[] = {
  {"conic", l_conic},
  {"ellipse_arc", l_ellipse_arc},
  {"svg_arc", l_svg_arc},
  {"fullcircle", l_fullcircle},
  {"conic_scheme", l_conic_scheme},
  {"conic_length", l_conic_length},
  {"ellipse_conics", l_ellipse_conics},
  {NULL, NULL}
};

void arclen_open_conic(lua_State *L) {
  luaL_setfuncs(L, conic_funcs, 0);
}
