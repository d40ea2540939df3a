/*
** times.c -- many distances on one cubic in one call (arclen_times):
**   arclen.times(c, distances [, opts]) -> ts [, points [, tangents]]
** and the path layer's walk (lua/arclen/path.lua), which hands each
** segment the run of sorted distances that falls in it:
**   arclen._walk_samples(segs, cum, ds, tol, out [, tans, times [, kinds]])
**   arclen._walk_times(segs, cum, ds, tol, at_end, ks, ts [, kinds])
**   arclen._locate(segs, cum, s, tol, at_end [, kinds [, what]])  (one)
**   arclen._queries(ds, L, wrap)  (a query list read, checked and reduced)
** (segs: the list of cubics, or a 2D path's packed cubics, a string;
** with kinds, a string of one letter L, Q, C, R per segment, the segments
** of those kinds: tables of their numbers, or packed records of 8 doubles)
** The distances are read in chunks into C buffers (one set-up per chunk),
** so a long run pays neither a Lua call nor a table per distance.
*/
#include <math.h>
#include <string.h>

#include "lua/binding.h"

#define CHUNK 256        /* distances per call of arclen_times */

/* ds[i] as a number, not NaN (arg names the table). */
static double distance_at(lua_State *L, int arg, int ds, long i) {
  double v;
  if (rawgeti_type(L, ds, (int)i) != LUA_TNUMBER)
    return luaL_argerror(L, arg, lua_pushfstring(L,
        "distance %d must be a number, got %s", (int)i,
        luaL_typename(L, -1))), 0;
  v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  if (isnan(v))
    luaL_argerror(L, arg, lua_pushfstring(L, "distance %d is NaN", (int)i));
  return v;
}

/* Reads ds[i .. i + m - 1] less shift into s, checking the order (the
** previous distance is *prev); raises on bad input. */
static void read_chunk(lua_State *L, int arg, int ds, long i, long m,
                       double shift, double *prev, double *s) {
  long q;
  for (q = 0; q < m; q++) {
    double v = distance_at(L, arg, ds, i + q);
    if (v < *prev)
      luaL_argerror(L, arg, "distances must be sorted (ascending)");
    *prev = v;
    s[q] = v - shift;
  }
}

static void set_number(lua_State *L, int t, long i, double v) {
  lua_pushnumber(L, v);
  lua_rawseti(L, t, (int)i);
}

/* arclen.times(c, distances [, opts]): opts tol, points, tangents. */
static int l_times(lua_State *L) {
  double c[12], s[CHUNK], t[CHUNK], p[3 * CHUNK], v[3 * CHUNK];
  double rtol = 1e-12, prev = -HUGE_VAL;
  int dim = arclenL_checkcurve(L, 1, c), want_p = 0, want_v = 0, k, out;
  long n, i, q;
  const char *key;
  luaL_checktype(L, 2, LUA_TTABLE);
  if (arclenL_optbegin(L, 3)) {
    while ((key = arclenL_optnext(L, 3)) != NULL) {
      if (strcmp(key, "tol") == 0) {
        if (lua_type(L, -1) != LUA_TNUMBER)
          luaL_argerror(L, 3, "tol must be a number");
        rtol = arclenL_checktol(L, 3, lua_tonumber(L, -1));
      } else if (strcmp(key, "points") == 0) {
        want_p = lua_toboolean(L, -1);
      } else if (strcmp(key, "tangents") == 0) {
        want_v = lua_toboolean(L, -1);
      } else {
        luaL_argerror(L, 3, lua_pushfstring(L, "unknown option '%s'", key));
      }
      lua_pop(L, 1);
    }
  }
  if (lua_rawlen(L, 2) > 0x7fffffff / 3)
    return luaL_argerror(L, 2, "too many distances");
  n = (long)lua_rawlen(L, 2);
  lua_settop(L, 3);
  lua_createtable(L, (int)n, 0);                          /* 4: ts */
  if (want_p) lua_createtable(L, (int)(dim * n), 0);      /* points */
  else lua_pushnil(L);
  if (want_v) lua_createtable(L, (int)(dim * n), 0);      /* tangents */
  else lua_pushnil(L);
  for (i = 1; i <= n; i += CHUNK) {
    long m = n - i + 1 < CHUNK ? n - i + 1 : CHUNK;
    int rc;
    read_chunk(L, 2, 2, i, m, 0, &prev, s);
    rc = arclen_times(c, dim, s, m, rtol, t, want_p ? p : NULL,
                      want_v ? v : NULL);
    if (rc != ARCLEN_OK) return arclenL_argcode(L, 2, rc);
    for (q = 0; q < m; q++) {
      set_number(L, 4, i + q, t[q]);
      for (k = 0; k < dim; k++) {
        if (want_p) set_number(L, 5, dim * (i + q - 1) + k + 1, p[dim * q + k]);
        if (want_v) set_number(L, 6, dim * (i + q - 1) + k + 1, v[dim * q + k]);
      }
    }
  }
  out = 1 + want_p + want_v;
  if (!want_v) lua_pop(L, 1);
  if (!want_p) lua_remove(L, 5);
  return out;
}

/* A segment's run of distances: its kind and numbers, where it starts on
** the path (shift), its length, the tolerance. */
typedef struct segment_run {
  double c[ARCLEN_SEG_MAXN], shift, seglen, rtol;
  int dim, kind;
} segment_run;

/* The times of the distances s[0 .. m - 1] (less the shift) in this
** segment: 0 at or before its start, 1 at or past its length (as
** path.lua's locate), else arclen_times on what lies between; with p
** and v, the points and unit tangents there. */
static void times_of(lua_State *L, const segment_run *r, const double *s,
                     long m, double *t, double *p, double *v) {
  long q, a, b;
  int rc;
  for (a = 0; a < m && s[a] <= 0; a++) t[a] = 0;
  for (b = m; b > a && s[b - 1] >= r->seglen; b--) t[b - 1] = 1;
  if (r->kind == ARCLEN_SEG_CUBIC)
    rc = arclen_times(r->c, r->dim, s + a, b - a, r->rtol, t + a, NULL, NULL);
  else
    /* the path's length of the segment (its cumulative lengths'
    ** difference) spares a measurement: each time is certified anyway */
    rc = arclen_segment_times_of(r->kind, r->dim, r->c, r->seglen, s + a,
                                 b - a, r->rtol, t + a, NULL, NULL);
  if (rc != ARCLEN_OK) arclenL_argcode(L, 2, rc);
  for (q = 0; q < m && (p || v); q++) {
    if (p) arclen_segment_point(r->kind, r->dim, r->c, t[q], p + r->dim * q);
    if (v) arclen_segment_unit_tangent(r->kind, r->dim, r->c, t[q],
                                       v + r->dim * q);
  }
}

/* _walk_samples' upvalues: the sample tables' keys. */
enum { KEY_X = 1, KEY_TX = 4, KEY_S = 7, KEY_TIME = 8, KEYS = 8 };

/* Where the samples go: the distances' table (for s =), out and, when
** flat, the tangents' and times' tables (0: not wanted). */
typedef struct sample_sink {
  int ds, out, tans, times, flat;
  const double *d;               /* the distances, for s = when ds is 0 */
} sample_sink;

/* The samples of ds[i .. i + m - 1] (times t, points p, tangents v) in
** segment base + 1: tables {x =, y =[, z =], s =, time =, tx =, ty =[,
** tz =]} into out[i ..], or flat arrays. */
static void emit_samples(lua_State *L, const sample_sink *o, int dim,
                         double base, long i, long m, const double *t,
                         const double *p, const double *v) {
  long q;
  int k;
  for (q = 0; q < m; q++) {
    if (o->flat) {
      for (k = 0; k < dim; k++) {
        long at = dim * (i + q - 1) + k + 1;
        set_number(L, o->out, at, p[dim * q + k]);
        if (o->tans) set_number(L, o->tans, at, v[dim * q + k]);
      }
      if (o->times) set_number(L, o->times, i + q, base + t[q]);
      continue;
    }
    /* the keys are the closure's upvalues (KEY_X ..): rawset with them
    ** skips lua_setfield's lookup of the C string each time */
    lua_createtable(L, 0, 2 * dim + 2);
    for (k = 0; k < dim; k++) {
      lua_pushvalue(L, lua_upvalueindex(KEY_X + k));
      lua_pushnumber(L, p[dim * q + k]);
      lua_rawset(L, -3);
      lua_pushvalue(L, lua_upvalueindex(KEY_TX + k));
      lua_pushnumber(L, v[dim * q + k]);
      lua_rawset(L, -3);
    }
    lua_pushvalue(L, lua_upvalueindex(KEY_S));
    if (o->ds) lua_rawgeti(L, o->ds, (int)(i + q));   /* as given: 0 stays an integer */
    else lua_pushnumber(L, o->d[i + q - 1]);
    lua_rawset(L, -3);
    lua_pushvalue(L, lua_upvalueindex(KEY_TIME));
    lua_pushnumber(L, base + t[q]);
    lua_rawset(L, -3);
    lua_rawseti(L, o->out, (int)(i + q));
  }
}

/* cum[k] as a number (the path's cumulative lengths, checked when made). */
static double cum_at(lua_State *L, int cum, long k) {
  double v;
  lua_rawgeti(L, cum, (int)k);
  v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

/* Cubic k (from 1) of the packed cubics (2D) at 1 into c: its dim. */
static int packed_cubic(lua_State *L, long k, double *c) {
  int i;
  memcpy(c, lua_tostring(L, 1) + (size_t)(k - 1) * 8 * sizeof(double),
         8 * sizeof(double));
  for (i = 0; i < 8; i++)
    if (!isfinite(c[i]))
      luaL_argerror(L, 1, lua_pushfstring(L, "cubic %d: coordinate %d must be "
                                          "finite", (int)k, i + 1));
  return 2;
}

/* Whether distance x lies past the end cum of a segment (at_end: a
** distance at a joint belongs to the segment that ends there). */
static int past(double cum, double x, int at_end) {
  return at_end ? cum < x : cum <= x;
}

/* The path's segments at 1 (a list, or a 2D path's packed cubics or
** records: a string) and the kinds of kinds_arg (nil: every one a cubic):
** their count and how to read one (load_segment). */
typedef struct path_segments {
  long n;
  int packed, kinds_arg;
  const char *kinds;
} path_segments;

/* letters: whether every kind letter is checked now (a walk reads most
** segments) or each as its segment is read (one distance: O(log n)). */
static void check_segments(lua_State *L, int kinds_arg, int letters,
                           path_segments *ps) {
  ps->packed = lua_type(L, 1) == LUA_TSTRING;
  if (!ps->packed && lua_type(L, 1) != LUA_TTABLE)
    luaL_argerror(L, 1, "a list of cubics or packed cubics expected");
  ps->n = (long)lua_rawlen(L, 1);
  if (ps->packed) {
    if (ps->n % (8 * sizeof(double)) != 0)
      luaL_argerror(L, 1, "packed cubics: a multiple of 64 bytes expected");
    ps->n /= 8 * sizeof(double);
  }
  ps->kinds_arg = kinds_arg;
  ps->kinds = arclenL_optkinds(L, kinds_arg, ps->n, letters);
}

/* Segment k (from 1) into r: its kind, dim and numbers, checked. */
static void load_segment(lua_State *L, const path_segments *ps, long k,
                         segment_run *r) {
  r->kind = ps->kinds ? arclenL_kindat(L, ps->kinds_arg, ps->kinds, k)
                      : ARCLEN_SEG_CUBIC;
  if (ps->packed && !ps->kinds) r->dim = packed_cubic(L, k, r->c);
  else if (ps->packed) {
    r->dim = 2;
    arclenL_packedsegment(L, 1, lua_tostring(L, 1), k - 1, r->kind, 2, r->c);
  } else {
    lua_rawgeti(L, 1, (int)k);
    r->dim = ps->kinds ? arclenL_checksegment(L, lua_gettop(L), r->kind, r->c)
                       : arclenL_checkcurve(L, lua_gettop(L), r->c);
    lua_pop(L, 1);
  }
}

/* The segment of distance x from segment k on (x past k's end, k < n):
** a gallop and a bisection over cum (at 2), O(log gap). */
static long segment_after(lua_State *L, long k, long n, double x, int at_end) {
  long lo = k, step = 1, hi = lo + step;
  while (hi < n && past(cum_at(L, 2, hi), x, at_end)) {
    lo = hi;
    step *= 2;
    hi = lo + step;
  }
  if (hi > n) hi = n;                  /* the segment lies in (lo, hi] */
  while (hi - lo > 1) {
    long mid = (lo + hi) / 2;
    if (past(cum_at(L, 2, mid), x, at_end)) lo = mid; else hi = mid;
  }
  return hi;
}

/* Whether the walk's distances (at 3, a table) are {n =, div =}. */
static int even_spaced(lua_State *L) {
  int yes;
  lua_getfield(L, 3, "div");
  yes = !lua_isnil(L, -1);
  lua_pop(L, 1);
  return yes;
}

/* The walk's distances (at 3) into a buffer on the stack: a list of
** numbers, ascending, or {n =, div =}: the n distances len i / div (i = 0
** .. n - 1; i = div gives len itself), resample's, made here without a
** list (len: the path's length, cum[n]). */
static double *read_distances(lua_State *L, double len, long *nd) {
  double *d, prev = -HUGE_VAL, div;
  long i, n;
  if (even_spaced(L)) {
    double m;
    lua_getfield(L, 3, "div");
    lua_getfield(L, 3, "n");
    div = lua_tonumber(L, -2);
    m = lua_tonumber(L, -1);
    lua_pop(L, 2);
    if (!(m >= 0 && m <= 0x7fffffff / 3 && m == floor(m) && div >= 1 && div == floor(div)))
      luaL_argerror(L, 3, "evenly spaced distances: n an integer in [0, 715827882], "
                          "div a positive integer");
    n = (long)m;
    d = (double *)lua_newuserdata(L, sizeof(double) * (size_t)(n > 0 ? n : 1));
    for (i = 0; i < n; i++) d[i] = (double)i == div ? len : len * (double)i / div;
    *nd = n;
    return d;
  }
  if (lua_rawlen(L, 3) > 0x7fffffff / 3) luaL_argerror(L, 3, "too many distances");
  n = (long)lua_rawlen(L, 3);
  d = (double *)lua_newuserdata(L, sizeof(double) * (size_t)(n > 0 ? n : 1));
  for (i = 0; i < n; i += CHUNK)       /* checked: numbers, ascending */
    read_chunk(L, 3, 3, i + 1, n - i < CHUNK ? n - i : CHUNK, 0, &prev, d + i);
  *nd = n;
  return d;
}

/* The walk over the path of segments segs (at 1, check_segments; its
** cumulative lengths cum[0 .. n] at 2) for the ascending distances ds (at
** 3, in [0, cum[n]]) at tol (at 4): each run of ds in one segment found by
** arclen_times with the segment's set-up (times_of), with a gallop and a
** bisection to the next run's segment (segment_after), O(log gap) a run:
** O(n + k) in all, O(k log n) for few distances.  With o, the samples go
** out as emit_samples writes them; without, segment k and time t of ds[q]
** into the tables ks and ts. */
static void walk(lua_State *L, int at_end, sample_sink *o, int ks, int ts) {
  segment_run r;
  path_segments ps;
  double t[CHUNK], p[3 * CHUNK], v[3 * CHUNK], s[CHUNK];
  double *d, lo_cum, hi_cum;
  long n, nd, i, j, k, a, q;
  luaL_checktype(L, 2, LUA_TTABLE);
  luaL_checktype(L, 3, LUA_TTABLE);
  r.rtol = arclenL_checktol(L, 4, luaL_checknumber(L, 4));
  check_segments(L, 8, 1, &ps);
  n = ps.n;
  if (n == 0) return;
  d = read_distances(L, cum_at(L, 2, n), &nd);
  if (nd == 0) return;
  if (o && !o->ds) o->d = d;
  k = 1;
  hi_cum = cum_at(L, 2, 1);
  for (i = 0; i < nd; i = j + 1) {
    double x = d[i];
    if (k < n && past(hi_cum, x, at_end)) {
      k = segment_after(L, k, n, x, at_end);
      hi_cum = cum_at(L, 2, k);
    }
    j = i;
    if (k == n) j = nd - 1;
    else while (j + 1 < nd && !past(hi_cum, d[j + 1], at_end)) j++;
    /* the run d[i .. j] in segment k */
    lo_cum = cum_at(L, 2, k - 1);
    load_segment(L, &ps, k, &r);
    r.shift = lo_cum;
    r.seglen = hi_cum - lo_cum;
    for (a = i; a <= j; a += CHUNK) {
      long m = j - a + 1 < CHUNK ? j - a + 1 : CHUNK;
      for (q = 0; q < m; q++) s[q] = d[a + q] - r.shift;
      if (o) {
        times_of(L, &r, s, m, t, p, (!o->flat || o->tans) ? v : NULL);
        emit_samples(L, o, r.dim, (double)k - 1, a + 1, m, t, p, v);
      } else {
        times_of(L, &r, s, m, t, NULL, NULL);
        for (q = 0; q < m; q++) {
          lua_pushinteger(L, (lua_Integer)k);
          lua_rawseti(L, ks, (int)(a + q + 1));
          set_number(L, ts, a + q + 1, t[q]);
        }
      }
    }
  }
}

/* arclen._walk_samples(segs, cum, ds, tol, out [, tans, times [, kinds]]): the
** samples at ds (walk; ds a list, or {n =, div =}: read_distances).  With tans absent or nil, out[q] = {x =, y =[, z
** =], s =, time = k - 1 + t, tx =, ty =[, tz =]} (segment k); with tans
** a table or false, flat arrays: out gets the points (dim numbers each),
** tans the unit tangents, times the path times (each when a table).
** kinds: as walk's. */
static int l_walk_samples(lua_State *L) {
  sample_sink o;
  luaL_checktype(L, 5, LUA_TTABLE);
  luaL_checktype(L, 3, LUA_TTABLE);
  o.ds = even_spaced(L) ? 0 : 3;      /* a list, or n, div: s = from o.d */
  o.d = NULL;
  o.out = 5;
  o.flat = !lua_isnoneornil(L, 6);
  o.tans = o.flat && lua_istable(L, 6) ? 6 : 0;
  o.times = o.flat && lua_istable(L, 7) ? 7 : 0;
  lua_settop(L, 8);
  walk(L, 0, &o, 0, 0);
  return 0;
}

/* arclen._walk_times(segs, cum, ds, tol, at_end, ks, ts [, kinds]): the
** segment ks[q] and time ts[q] of each ds[q] (walk), as path.lua's locate
** gives them one by one. */
static int l_walk_times(lua_State *L) {
  int at_end = lua_toboolean(L, 5);
  luaL_checktype(L, 6, LUA_TTABLE);
  luaL_checktype(L, 7, LUA_TTABLE);
  lua_settop(L, 8);
  walk(L, at_end, NULL, 6, 7);
  return 0;
}

/* arclen._locate(segs, cum, s, tol, at_end [, kinds [, what]]) -> k, t:
** one distance s in [0, cum[n]] as the walk takes it (path.lua's locate
** for the default method: p:time, p:point, p:tangent), with no table made;
** what "point" or "tangent": the point or unit tangent there instead (dim
** numbers, as the walk's samples).  A path of no segments gives nothing. */
static int l_locate(lua_State *L) {
  static const char *const whats[] = {"time", "point", "tangent", NULL};
  segment_run r;
  path_segments ps;
  double x = luaL_checknumber(L, 3), t, out[3];
  int at_end = lua_toboolean(L, 5), what, k;
  long seg;
  luaL_checktype(L, 2, LUA_TTABLE);
  r.rtol = arclenL_checktol(L, 4, luaL_checknumber(L, 4));
  what = luaL_checkoption(L, 7, "time", whats);
  lua_settop(L, 6);
  check_segments(L, 6, 0, &ps);
  if (isnan(x)) return luaL_argerror(L, 3, "the distance is NaN");
  if (ps.n == 0) return 0;
  seg = ps.n > 1 && past(cum_at(L, 2, 1), x, at_end)
        ? segment_after(L, 1, ps.n, x, at_end) : 1;
  load_segment(L, &ps, seg, &r);
  r.shift = cum_at(L, 2, seg - 1);
  r.seglen = cum_at(L, 2, seg) - r.shift;
  x -= r.shift;
  times_of(L, &r, &x, 1, &t, what == 1 ? out : NULL, what == 2 ? out : NULL);
  if (what == 0) {
    lua_pushinteger(L, (lua_Integer)seg);
    lua_pushnumber(L, t);
    return 2;
  }
  for (k = 0; k < r.dim; k++) lua_pushnumber(L, out[k]);
  return r.dim;
}

/* arclen._array(n) -> an empty table with room for n array items, for
** the path layer's results (Lua 5.1-5.4 have no table.create). */
static int l_array(lua_State *L) {
  double n = luaL_checknumber(L, 1);
  luaL_argcheck(L, n >= 0 && n <= 0x7fffffff / 3 && n == floor(n), 1,
                "size must be an integer in [0, 715827882]");
  lua_createtable(L, (int)n, 0);
  return 1;
}

/* arclen._queries(ds, L, wrap) -> r, ascending | nil, message: path.lua's
** query list read: each ds[i] a finite number, reduced into [0, L] --
** wrapped (s - floor(s / L) L) when wrap, else clamped (to the integer 0
** below, to the value L above); an unchanged distance is copied as it is
** (an integer stays one).  ascending: whether r is. */
static int l_queries(lua_State *L) {
  double len, prev = -HUGE_VAL;
  long n, i;
  int wrap, ascending = 1;
  luaL_checktype(L, 1, LUA_TTABLE);
  len = luaL_checknumber(L, 2);
  wrap = lua_toboolean(L, 3);
  if (lua_rawlen(L, 1) > 0x7fffffff / 3)
    return luaL_argerror(L, 1, "too many distances");
  n = (long)lua_rawlen(L, 1);
  lua_settop(L, 2);
  lua_createtable(L, (int)n, 0);                            /* 3: r */
  for (i = 1; i <= n; i++) {
    double v, r;
    if (rawgeti_type(L, 1, (int)i) != LUA_TNUMBER) {
      lua_pushnil(L);
      lua_pushfstring(L, "distance %d must be a number, got %s", (int)i,
                      luaL_typename(L, -2));
      return 2;
    }
    v = lua_tonumber(L, -1);
    if (!isfinite(v)) {
      lua_pushnil(L);
      lua_pushfstring(L, "distance %d must be finite", (int)i);
      return 2;
    }
    r = v;
    if (wrap) {
      r = v - floor(v / len) * len;
      lua_pop(L, 1);
      lua_pushnumber(L, r);
    } else if (v < 0) {
      r = 0;
      lua_pop(L, 1);
      lua_pushinteger(L, 0);
    } else if (v > len) {
      r = len;
      lua_pop(L, 1);
      lua_pushvalue(L, 2);
    }
    lua_rawseti(L, 3, (int)i);
    if (r < prev) ascending = 0;
    prev = r;
  }
  lua_pushboolean(L, ascending);
  return 2;
}

static const luaL_Reg times_funcs[] = {
  {"_queries", l_queries},
  {"times", l_times},
  {"_walk_times", l_walk_times},
  {"_locate", l_locate},
  {"_array", l_array},
  {NULL, NULL}
};

void arclen_open_times(lua_State *L) {
  static const char *const keys[KEYS] = {"x", "y", "z", "tx", "ty", "tz", "s", "time"};
  int k;
  luaL_setfuncs(L, times_funcs, 0);
  for (k = 0; k < KEYS; k++) lua_pushstring(L, keys[k]);
  lua_pushcclosure(L, l_walk_samples, KEYS);
  lua_setfield(L, -2, "_walk_samples");
}
