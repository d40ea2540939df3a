/*
** lua_path.c -- arclen.path, the Lua module arclen.path (lua/arclen/path.lua),
** reached from the C module: the module table gets a metatable whose
** __index loads "arclen.path" on first use of arclen.path, so that
** `require "arclen"` alone gives arclen.path(...), arclen.path.svg(d), ...
** Other keys stay absent (nil), as without the metatable.
*/
#include <string.h>

#include "lua_arclen.h"

/* __index(module, key): require the Lua part named by key, cache it. */
static int l_lazy_index(lua_State *L) {
  const char *key = lua_tostring(L, 2);
  if (lua_type(L, 2) != LUA_TSTRING || strcmp(key, "path") != 0) return 0;
  lua_getglobal(L, "require");
  lua_pushliteral(L, "arclen.path");
  lua_call(L, 1, 1);
  lua_pushvalue(L, 2);
  lua_pushvalue(L, -2);
  lua_rawset(L, 1);          /* later lookups do not come here */
  return 1;
}

void arclen_open_path(lua_State *L) {
  lua_createtable(L, 0, 1);
  lua_pushcfunction(L, l_lazy_index);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, -2);
}
