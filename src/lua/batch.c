/*
** batch.c -- arclen.lengths(coords [, opts]) and arclen.lengths3: the
** length of every cubic in a flat array of numbers (8 per curve in 2D, 12
** in 3D) -- or in a string of packed doubles (native order, as the path
** readers make it and string.pack("d", ...) does) -- in one call,
** returned as an array.  The curves are read in
** chunks into a C buffer and measured there, so a large set pays neither
** a Lua call nor a table per curve.
** opts as arclen.length's (tol, method, t0, t1, steps); info does not
** apply.  opts.kinds (a string of n letters L, Q, C, R) makes the records
** (still 4 dim numbers each) segments of those kinds (lua/segment.c): each
** measured by arclen_segment_length, runs of cubics by arclen_lengths as
** before.  Errors name the argument and the coordinate's index.
**
** Where the time goes (doc/benchmarks.md, "Many curves from Lua"): the
** public API reads a number in two calls (lua_rawgeti, lua_tonumber), so
** the loop below does only that per number -- the type and finiteness
** checks are folded into one test per block -- and arclen_lengths
** measures the default method's curves without checking them again.
*/
#include <math.h>
#include <string.h>

#include "lua/binding.h"

#define CHUNK 256      /* curves per buffer: 24 KB of stack in 3D */
#define BLOCK 48       /* numbers on the Lua stack at once (4 curves in 3D) */

/* The first bad number of a block of b on the stack top, coordinate
** first + 1 being at -b: raises its error. */
static int bad_coordinate(lua_State *L, const double *v, long first, int b) {
  int j;
  for (j = 0; j < b; j++) {
    int idx = j - b;
    long k = first + j + 1;
    if (lua_type(L, idx) != LUA_TNUMBER)
      return luaL_argerror(L, 1, lua_pushfstring(L,
          "coordinate %d must be a number, got %s", (int)k,
          luaL_typename(L, idx)));
    if (!isfinite(v[j]))
      return luaL_argerror(L, 1, lua_pushfstring(L,
          "coordinate %d must be finite", (int)k));
  }
  return 0;
}

/* coords[first + 1 .. first + count] into buf, each a finite number. */
static void read_numbers(lua_State *L, long first, long count, double *buf) {
  long i;
  for (i = 0; i < count; i += BLOCK) {
    int b = count - i < BLOCK ? (int)(count - i) : BLOCK, j, bad = 0;
    int k0 = (int)(first + i);
    double z = 0, *v = buf + i;
    for (j = 0; j < b; j++)
      bad |= rawgeti_type(L, 1, k0 + j + 1) ^ LUA_TNUMBER;
    for (j = 0; j < b; j++) v[j] = lua_tonumber(L, j - b);
    /* x - x is 0 for a finite x, NaN for inf and NaN: one test a block,
    ** in a loop of its own (no call in it to keep z in memory) */
    for (j = 0; j < b; j++) z += v[j] - v[j];
    if (bad || z != 0) bad_coordinate(L, v, first + i, b);
    lua_pop(L, b);
  }
}

/* packed[first .. first + count - 1] (doubles) into buf, each finite. */
static void read_packed(lua_State *L, const char *packed, long first,
                        long count, double *buf) {
  long i;
  double z = 0;
  memcpy(buf, packed + sizeof(double) * (size_t)first,
         sizeof(double) * (size_t)count);
  for (i = 0; i < count; i++) z += buf[i] - buf[i];
  if (z != 0)
    for (i = 0; i < count; i++)
      if (!isfinite(buf[i]))
        luaL_argerror(L, 1, lua_pushfstring(L,
            "coordinate %d must be finite", (int)(first + i + 1)));
}

/* The lengths of records first .. first + m - 1 (in buf) by their kinds:
** runs of cubics in one arclen_lengths call, the others one by one.
** Returns the code and sets *failed (index in buf) as arclen_lengths. */
static int kinds_lengths(lua_State *L, const double *buf, long first,
                         long m, int dim, const arclenL_opts *lo,
                         double *out, long *failed) {
  long i = 0, j, stride = 4 * dim;
  while (i < m) {
    int kind = arclen_segment_kind_of_letter((unsigned char)lo->kinds[first + i]);
    if (kind == ARCLEN_SEG_CUBIC) {
      long f;
      int rc;
      for (j = i + 1; j < m && lo->kinds[first + j] == 'C'; j++) {}
      rc = arclen_lengths(buf + i * stride, j - i, dim, lo->method, &lo->o,
                          out + i, &f);
      if (rc != ARCLEN_OK) { *failed = i + f; return rc; }
      i = j;
    } else {
      int rc = arclen_segment_check(kind, dim, buf + i * stride);
      if (rc == ARCLEN_EINVAL)        /* finite already: a conic's weight */
        luaL_argerror(L, 1, lua_pushfstring(L,
            "segment %d: conic weight must be positive", (int)(first + i + 1)));
      if (rc == ARCLEN_OK)
        rc = arclen_segment_length(kind, dim, buf + i * stride, lo->method,
                                   &lo->o, out + i, NULL);
      if (rc != ARCLEN_OK) { *failed = i; return rc; }
      i++;
    }
  }
  *failed = -1;
  return ARCLEN_OK;
}

static int lengths(lua_State *L, int dim, const char *fname) {
  double buf[CHUNK * 12], out[CHUNK];
  arclenL_opts lo;
  size_t len;
  long n, done, i, failed;
  int stride = 4 * dim;
  const char *packed = NULL;   /* coords as a string of packed doubles */
  if (lua_type(L, 1) == LUA_TSTRING) {
    packed = lua_tolstring(L, 1, &len);
    if (len % sizeof(double) != 0)
      return luaL_argerror(L, 1, "packed coordinates: a multiple of 8 bytes expected");
    len /= sizeof(double);
  } else if (lua_type(L, 1) == LUA_TTABLE) {
    len = lua_rawlen(L, 1);
  } else {
    return luaL_argerror(L, 1, lua_pushfstring(L,
        "table of coordinates expected (%d numbers per curve), got %s",
        stride, luaL_typename(L, 1)));
  }
  arclenL_checkopts_kinds(L, 2, &lo);
  if (lo.info)
    return luaL_argerror(L, 2, lua_pushfstring(L,
        "info does not apply to %s", fname));
  if (len % (size_t)stride != 0)
    return luaL_argerror(L, 1, lua_pushfstring(L,
        "number of coordinates must be a multiple of %d, got %d", stride,
        (int)len));
  if (len > 0x7fffffff)
    return luaL_argerror(L, 1, "too many coordinates");
  n = (long)(len / (size_t)stride);
  if (lo.kinds && (long)lo.nkinds != n)
    return luaL_argerror(L, 2, lua_pushfstring(L,
        "kinds must have one letter per segment (%d), got %d", (int)n,
        (int)lo.nkinds));
  luaL_checkstack(L, BLOCK + 4, "too many coordinates");
  lua_createtable(L, (int)n, 0);
  for (done = 0; done < n; done += CHUNK) {
    long m = n - done < CHUNK ? n - done : CHUNK;
    int rc;
    if (packed) read_packed(L, packed, done * stride, m * stride, buf);
    else read_numbers(L, done * stride, m * stride, buf);
    if (lo.kinds) rc = kinds_lengths(L, buf, done, m, dim, &lo, out, &failed);
    else rc = arclen_lengths(buf, m, dim, lo.method, &lo.o, out, &failed);
    if (rc == ARCLEN_EDIM)
      return luaL_argerror(L, 2, lua_pushfstring(L,
          "method '%s' does not support this dimension", lo.method->name));
    if (rc == ARCLEN_EOVERFLOW) {      /* MetaPost's own failure */
      lua_pushnil(L);
      lua_pushfstring(L, "%s %d: %s", lo.kinds ? "segment" : "curve",
                      (int)(done + failed + 1),
                      arclen_strerror(rc));
      return 2;
    }
    if (rc != ARCLEN_OK)
      return luaL_argerror(L, 1, lua_pushfstring(L, "%s %d: %s",
          lo.kinds ? "segment" : "curve", (int)(done + failed + 1), arclen_strerror(rc)));
    for (i = 0; i < m; i++) {
      lua_pushnumber(L, out[i]);
      lua_rawseti(L, -2, (int)(done + i + 1));
    }
  }
  return 1;
}

/* arclen.lengths(coords [, opts]) -> {L1, L2, ...}: 2D, 8 numbers each */
static int l_lengths(lua_State *L) {
  return lengths(L, 2, "lengths");
}

/* arclen.lengths3(coords [, opts]) -> {L1, L2, ...}: 3D, 12 numbers each */
static int l_lengths3(lua_State *L) {
  return lengths(L, 3, "lengths3");
}

static const luaL_Reg batch_funcs[] = {
  {"lengths", l_lengths},
  {"lengths3", l_lengths3},
  {NULL, NULL}
};

void arclen_open_batch(lua_State *L) {
  luaL_setfuncs(L, batch_funcs, 0);
}
