/*
** binding.h -- what the binding files share: argument checking in the
** style of lauxlib (errors name the argument), and each area's opener.
** Internal to the module; C users include arclen.h only.
*/
#ifndef LUA_ARCLEN_H
#define LUA_ARCLEN_H

#include "lua/compat.h"
#include "arclen.h"

/* A curve argument: a table of 8 (2D) or 12 (3D) numbers, or of 4 points
** {x, y} / {x, y, z}.  Fills c (room for 12) and returns the dimension;
** raises "bad argument #arg to 'fn' (...)" on anything else. */
int arclenL_checkcurve(lua_State *L, int arg, double *c);
/* A finite number; what names it in the message ("length", "t", ...). */
double arclenL_checkfinite(lua_State *L, int arg, const char *what);
double arclenL_optfinite(lua_State *L, int arg, double def, const char *what);
/* A relative tolerance in [ARCLEN_RTOL_MIN, ARCLEN_RTOL_MAX]. */
double arclenL_checktol(lua_State *L, int arg, double v);

/* Walking an options table: arclenL_optbegin returns 0 when arg is absent
** or nil, raises unless it is a table, else starts the walk; then
**   while ((key = arclenL_optnext(L, arg)) != NULL) { value at -1; pop it }
** raises on a key that is not a string.  arg must be an absolute index. */
int arclenL_optbegin(lua_State *L, int arg);
const char *arclenL_optnext(lua_State *L, int arg);

/* The common options table at arg (absent or nil: defaults):
** tol, method, t0, t1, steps, info.  Unknown keys are an error. */
typedef struct arclenL_opts {
  arclen_opts o;
  const arclen_method *method;
  int info;                 /* opts.info == true */
  const char *kinds;        /* opts.kinds (with_kinds only), else NULL */
  size_t nkinds;            /* its length */
} arclenL_opts;
void arclenL_checkopts(lua_State *L, int arg, arclenL_opts *lo);
/* The same, also accepting kinds = a string of segment letters (L, Q, C,
** R; each checked) for arclen.lengths. */
void arclenL_checkopts_kinds(lua_State *L, int arg, arclenL_opts *lo);

/* Segments of four kinds (lua/segment.c).  A kind argument: its name
** ("line", "quad", "cubic", "conic"); returns ARCLEN_SEG_*. */
int arclenL_checkkind(lua_State *L, int arg);
/* A segment of kind: a table of its count of numbers (2D or 3D), finite,
** a conic's weight > 0.  Fills seg (room for ARCLEN_SEG_MAXN) and returns
** the dimension; raises naming arg. */
int arclenL_checksegment(lua_State *L, int arg, int kind, double *seg);
/* A kinds string at arg for n segments (nil or none: NULL, all cubics):
** one letter L, Q, C or R per segment; raises naming arg.  letters: whether
** every letter is checked here (else the caller checks the ones it reads,
** arclenL_kindat: a single lookup stays O(1)). */
const char *arclenL_optkinds(lua_State *L, int arg, long n, int letters);
/* The kind of segment k (from 1) of the kinds at arg; raises naming arg
** on a letter that is not L, Q, C or R. */
int arclenL_kindat(lua_State *L, int arg, const char *kinds, long k);
/* Record k (from 0) of packed segments (stride 4 dim doubles) into seg: its
** kind's numbers, checked; raises naming arg and the segment. */
void arclenL_packedsegment(lua_State *L, int arg, const char *packed,
                           long k, int kind, int dim, double *seg);

/* Push a new array of the n numbers v[0..n-1]. */
void arclenL_pushnumbers(lua_State *L, const double *v, int n);
/* Push an info table {evals=, pieces=, depth=, err=, branch=, calls=}. */
void arclenL_pushinfo(lua_State *L, const arclen_info *info);
/* Raise a Lua error for a C error code, naming the function's argument. */
int arclenL_argcode(lua_State *L, int arg, int code);
/* A method's result v (code ARCLEN_OK) as a number and, with lo->info,
** the info table; EOVERFLOW as nil, message; other codes as errors. */
int arclenL_pushresult(lua_State *L, int code, double v, int arg,
                       const arclenL_opts *lo, const arclen_info *info);

/* Push path data's cubics as {packed =, n =, [j] = {x =, y =, closed =, n
** =}} (lua/subpaths.c; arclen.core and arclen.svgdoc share it), and
** arclen._cubics(packed), the packed cubics as tables. */
struct arclen_pathdata;
void arclenL_pushsubpaths(lua_State *L, const struct arclen_pathdata *pd);
int arclenL_unpackcubics(lua_State *L);

/* Each area registers its functions into the module table at the top of
** the stack (module.c calls them from luaopen_arclen_core). */
void arclen_open_core(lua_State *L);
void arclen_open_conic(lua_State *L);
void arclen_open_henkel(lua_State *L);
void arclen_open_elliptic(lua_State *L);
void arclen_open_fit(lua_State *L);
void arclen_open_batch(lua_State *L);
void arclen_open_times(lua_State *L);
void arclen_open_svg(lua_State *L);
void arclen_open_segment(lua_State *L);
/* new areas: one line each, above this line */

#endif
