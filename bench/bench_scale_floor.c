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

/* arclen_lengths with each length replaced by the curve's first number */
static int floor_lengths(const double *c, long n, int dim, const arclen_method *m,
                         const arclen_opts *o, double *out, long *failed) {
  long i;
  (void)m;
  (void)o;
  if (failed) *failed = -1;
  for (i = 0; i < n; i++) out[i] = c[i * 4 * dim];
  return ARCLEN_OK;
}
#define arclen_lengths floor_lengths
#include "lua/batch.c"

int luaopen_bench_scale_floor(lua_State *L);
int luaopen_bench_scale_floor(lua_State *L) {
  lua_newtable(L);
  arclen_open_batch(L);
  return 1;
}
