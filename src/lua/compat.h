/*
** compat.h -- the few Lua C API differences between 5.1 (and LuaJIT) and
** 5.2-5.4 that the binding meets.  One source builds for every version.
*/
#ifndef ARCLEN_COMPAT_H
#define ARCLEN_COMPAT_H

#include "lua.h"
#include "lauxlib.h"

#if !defined(LUA_VERSION_NUM) || LUA_VERSION_NUM < 502
#define lua_rawlen(L, i) lua_objlen(L, (i))
#endif

/* LuaJIT 2.1 has 5.2's luaL_setfuncs and luaL_newlib already. */
#if (!defined(LUA_VERSION_NUM) || LUA_VERSION_NUM < 502) && !defined(luaL_newlibtable)
#define luaL_newlibtable(L, l) lua_createtable(L, 0, sizeof(l) / sizeof((l)[0]) - 1)
#define luaL_newlib(L, l) (luaL_newlibtable(L, l), luaL_setfuncs(L, l, 0))
/* luaL_setfuncs as in 5.2's lauxlib.c, for nup == 0 only. */
static inline void luaL_setfuncs(lua_State *L, const luaL_Reg *l, int nup) {
  (void)nup;
  for (; l->name != NULL; l++) {
    lua_pushcfunction(L, l->func);
    lua_setfield(L, -2, l->name);
  }
}
#endif

/* lua_rawgeti returning the value's type, as it does from 5.3 on: one
** API call per number read from an array where 5.1/5.2 need two. */
#if defined(LUA_VERSION_NUM) && LUA_VERSION_NUM >= 503
#define rawgeti_type(L, t, k) lua_rawgeti(L, (t), (k))
#else
static inline int rawgeti_type(lua_State *L, int t, int k) {
  lua_rawgeti(L, t, k);
  return lua_type(L, -1);
}
#endif

#endif
