/*
** subpaths.c -- cubics read from path data (svg/pathdata.h) as the Lua
** layer takes them: a list of {x = x0, y = y0, closed = bool, [i] =
** cubic} with every cubic a table of 8 numbers (arclen.path builds a path
** from it).  Shared by arclen.core's svg_pathdata and arclen.svgdoc.
*/
#include "lua/binding.h"
#include "svg/pathdata.h"

void arclenL_pushsubpaths(lua_State *L, const arclen_pathdata *pd) {
  size_t k, i;
  int j;
  lua_createtable(L, (int)pd->nsubpaths, 0);
  for (k = 0; k < pd->nsubpaths; k++) {
    const arclen_subpath *s = &pd->subpaths[k];
    const double *c = pd->cubics + 8 * s->first;
    lua_createtable(L, (int)s->n, 3);
    lua_pushnumber(L, s->x);
    lua_setfield(L, -2, "x");
    lua_pushnumber(L, s->y);
    lua_setfield(L, -2, "y");
    lua_pushboolean(L, s->closed);
    lua_setfield(L, -2, "closed");
    for (i = 0; i < s->n; i++, c += 8) {
      lua_createtable(L, 8, 0);
      for (j = 0; j < 8; j++) {
        lua_pushnumber(L, c[j]);
        lua_rawseti(L, -2, j + 1);
      }
      lua_rawseti(L, -2, (int)i + 1);
    }
    lua_rawseti(L, -2, (int)k + 1);
  }
}
