/*
** subpaths.c -- cubics read from path data (svg/pathdata.h) as the Lua
** layer takes them: {flat = {x0, y0, x1, y1, x2, y2, x3, y3, ...} (8
** numbers a cubic, all subpaths in order), n = the number of cubics, [j] =
** {x = x0, y = y0, closed = bool, n = its cubics}} -- one array of numbers
** for the whole path, not a table per cubic (arclen.path builds a path on
** it and measures it with arclen.lengths).  Shared by arclen.core's
** svg_pathdata and arclen.svgdoc.
*/
#include "lua/binding.h"
#include "svg/pathdata.h"

void arclenL_pushsubpaths(lua_State *L, const arclen_pathdata *pd) {
  size_t k, i, m = 8 * pd->ncubics;
  lua_createtable(L, (int)pd->nsubpaths, 2);
  lua_createtable(L, m > 0x7fffffff ? 0x7fffffff : (int)m, 0);
  for (i = 0; i < m; i++) {
    lua_pushnumber(L, pd->cubics[i]);
    lua_rawseti(L, -2, (int)i + 1);
  }
  lua_setfield(L, -2, "flat");
  lua_pushinteger(L, (lua_Integer)pd->ncubics);
  lua_setfield(L, -2, "n");
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
