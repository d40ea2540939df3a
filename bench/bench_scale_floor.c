/*
** bench_scale_floor.c -- the floor of arclen.lengths under the public Lua
** C API: src/lua/batch.c itself, built with the length of each curve
** replaced by a copy of its first number, so that what is left is reading
** and checking the numbers (lua_rawgeti and lua_tonumber each) and
** filling the result.  make bench-scale builds it as a module of its own
** (bench_scale_floor.so, luaopen_bench_scale_floor) and bench_scale.lua
** times it in turn with arclen.lengths and the C loop.
*/
#include "lua/binding.h"

#define arclen_length_range(c, t0, t1, rtol) ((c)[0])
#define arclen_length3_range(c, t0, t1, rtol) ((c)[0])
#include "lua/batch.c"

int luaopen_bench_scale_floor(lua_State *L);
int luaopen_bench_scale_floor(lua_State *L) {
  lua_newtable(L);
  arclen_open_batch(L);
  return 1;
}
