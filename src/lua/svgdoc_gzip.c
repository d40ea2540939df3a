/*
** svgdoc_gzip.c -- gzip input for arclen.svg, in the module arclen.svgdoc
** (src/svgdoc/gzip.c over zlib, an optional dependency):
**   svgdoc.gzip -> boolean        built with zlib
**   svgdoc.gunzip() -> g          an inflater (an error without zlib)
**   g:feed(s)                     the next compressed bytes (after read
**                                 returned nil)
**   g:read() -> string or nil     the next at most 64 KiB inflated; nil
**                                 when the bytes fed are used up
**   g:finish()                    at the end: an error if it is truncated
** Errors are raised as strings (arclen.svg names the file in them).
*/
#include "lua/binding.h"
#include "svgdoc/gzip.h"

#define GUNZIP "arclen.svgdoc.gunzip"
#define PIECE 65536                      /* bytes inflated per read */

/* The userdata: the inflater and the room for one piece of output. */
typedef struct gunzip_ud {
  svgdoc_gunzip *g;
  char out[PIECE];
} gunzip_ud;

static gunzip_ud *check_gunzip(lua_State *L) {
  gunzip_ud *u = (gunzip_ud *)luaL_checkudata(L, 1, GUNZIP);
  if (u->g == NULL) luaL_argerror(L, 1, "the inflater has finished");
  return u;
}

static int gunzip_gc(lua_State *L) {
  gunzip_ud *u = (gunzip_ud *)luaL_checkudata(L, 1, GUNZIP);
  svgdoc_gunzip_free(u->g);
  u->g = NULL;
  return 0;
}

static int l_gunzip(lua_State *L) {
  gunzip_ud *u;
  if (!svgdoc_gunzip_available())
    return luaL_error(L, "arclen.svgdoc was built without zlib");
  u = (gunzip_ud *)lua_newuserdata(L, sizeof *u);
  u->g = NULL;
  luaL_getmetatable(L, GUNZIP);
  lua_setmetatable(L, -2);
  u->g = svgdoc_gunzip_new();
  if (u->g == NULL) return luaL_error(L, "not enough memory");
  return 1;
}

static int l_feed(lua_State *L) {
  gunzip_ud *u = check_gunzip(L);
  size_t n;
  const char *s = luaL_checklstring(L, 2, &n);
  if (svgdoc_gunzip_feed(u->g, s, n) != 0) return luaL_error(L, "not enough memory");
  return 0;
}

static int l_read(lua_State *L) {
  gunzip_ud *u = check_gunzip(L);
  long n = svgdoc_gunzip_read(u->g, u->out, PIECE);
  if (n < 0) {
    lua_pushstring(L, svgdoc_gunzip_error(u->g));
    return lua_error(L);
  }
  if (n == 0) return 0;
  lua_pushlstring(L, u->out, (size_t)n);
  return 1;
}

static int l_finish(lua_State *L) {
  gunzip_ud *u = check_gunzip(L);
  if (svgdoc_gunzip_finish(u->g) != 0) {
    lua_pushstring(L, svgdoc_gunzip_error(u->g));
    return lua_error(L);
  }
  return 0;
}

static const luaL_Reg gunzip_methods[] = {
  {"feed", l_feed}, {"read", l_read}, {"finish", l_finish}, {NULL, NULL}};

/* Into the module's table on the stack's top: gzip and gunzip. */
void arclenL_open_gzip(lua_State *L) {
  if (luaL_newmetatable(L, GUNZIP)) {
    lua_pushcfunction(L, gunzip_gc);
    lua_setfield(L, -2, "__gc");
    luaL_newlib(L, gunzip_methods);
    lua_setfield(L, -2, "__index");
  }
  lua_pop(L, 1);
  lua_pushboolean(L, svgdoc_gunzip_available());
  lua_setfield(L, -2, "gzip");
  lua_pushcfunction(L, l_gunzip);
  lua_setfield(L, -2, "gunzip");
}
