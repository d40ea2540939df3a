/*
** subpaths.c -- segments read from path data (svg/pathdata.h) as the Lua
** layer takes them: {packed = the records as a string of doubles (8 each:
** the kind's numbers, then zeros; all subpaths in order, native order), n
** = the number of segments, kinds = a string of their letters (L Q C R;
** nil when all are cubics, the format of arclen.lengths' opts.kinds), [j]
** = {x = x0, y = y0, closed = bool, n = its segments}} -- one string for
** the whole path, which the collector never looks into, not a table per
** segment (arclen.path builds a path on it and measures it with
** arclen.lengths).  Shared by arclen.core's svg_pathdata and
** arclen.svgdoc.
*/
#include <string.h>

#include "lua/binding.h"
#include "svg/pathdata.h"

void arclenL_pushsubpaths(lua_State *L, const arclen_pathdata *pd) {
  size_t k;
  lua_createtable(L, (int)pd->nsubpaths, 3);
  lua_pushlstring(L, (const char *)pd->cubics,
                  ARCLEN_PD_STRIDE * sizeof(double) * pd->ncubics);
  lua_setfield(L, -2, "packed");
  lua_pushinteger(L, (lua_Integer)pd->ncubics);
  lua_setfield(L, -2, "n");
  for (k = 0; k < pd->ncubics && pd->kinds[k] == ARCLEN_PD_CUBIC; k++) {}
  if (k < pd->ncubics) {                    /* not all cubics */
    lua_pushlstring(L, (const char *)pd->kinds, pd->ncubics);
    lua_setfield(L, -2, "kinds");
  }
  for (k = 0; k < pd->nsubpaths; k++) {
    const arclen_subpath *s = &pd->subpaths[k];
    lua_createtable(L, 0, 4);
    lua_pushnumber(L, s->x);
    lua_setfield(L, -2, "x");
    lua_pushnumber(L, s->y);
    lua_setfield(L, -2, "y");
    lua_pushboolean(L, s->closed);
    lua_setfield(L, -2, "closed");
    lua_pushinteger(L, (lua_Integer)s->n);
    lua_setfield(L, -2, "n");
    lua_rawseti(L, -2, (int)k + 1);
  }
}

/* arclen._cubics(packed) -> {cubic, ...}: a path's packed cubics (2D) as
** tables of 8 numbers, for the queries that take single cubics. */
int arclenL_unpackcubics(lua_State *L) {
  size_t len, n, k;
  const char *s = luaL_checklstring(L, 1, &len);
  int j;
  luaL_argcheck(L, len % (8 * sizeof(double)) == 0, 1,
                "packed cubics: a multiple of 64 bytes expected");
  n = len / (8 * sizeof(double));
  luaL_argcheck(L, n <= 0x7fffffff, 1, "too many cubics");
  lua_createtable(L, (int)n, 0);
  for (k = 0; k < n; k++) {
    double c[8];
    memcpy(c, s + k * sizeof c, sizeof c);
    lua_createtable(L, 8, 0);
    for (j = 0; j < 8; j++) {
      lua_pushnumber(L, c[j]);
      lua_rawseti(L, -2, j + 1);
    }
    lua_rawseti(L, -2, (int)k + 1);
  }
  return 1;
}
