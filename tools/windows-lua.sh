#!/bin/sh
# tools/windows-lua.sh [DIR] -- a Windows Lua 5.4 for the MinGW cross-build:
# lua54.dll, lua.exe and the headers in DIR (default build/windows/lua), built
# with x86_64-w64-mingw32-gcc from Debian's lua5.4 source package (the same
# Lua, with Debian's patches, that the Linux builds use), fetched by
# tools/debian-source.sh (as root it adds the deb-src line apt-get source
# needs).
set -eu
OUT=${1:-build/windows/lua}
CROSS=${CROSS:-x86_64-w64-mingw32-}
WCC=${CROSS}gcc
if [ -f "$OUT/lua54.dll" ] && [ -f "$OUT/lua.exe" ] && [ -f "$OUT/include/lua.h" ]; then
  exit 0
fi

dir=$(sh "$(dirname "$0")/debian-source.sh" lua5.4 "$OUT/debian-source")
if [ ! -f "$dir/src/lua.h" ]; then
  echo "windows-lua.sh: no Lua source in $dir" >&2
  exit 1
fi

# What upstream's "mingw" target builds (Debian's Makefile is libtool's, for
# Linux): the core and the standard libraries as lua54.dll with
# LUA_BUILD_AS_DLL, and lua.exe over it.
CORE="lapi lcode lctype ldebug ldo ldump lfunc lgc llex lmem lobject lopcodes
  lparser lstate lstring ltable ltm lundump lvm lzio"
LIBS="lauxlib lbaselib lcorolib ldblib liolib lmathlib loadlib loslib lstrlib
  ltablib lutf8lib linit"
OBJ=$OUT/obj
mkdir -p "$OBJ" "$OUT/include"
objs=
for f in $CORE $LIBS; do
  "$WCC" -std=gnu99 -O2 -DLUA_COMPAT_5_3 -DLUA_BUILD_AS_DLL -c "$dir/src/$f.c" -o "$OBJ/$f.o"
  objs="$objs $OBJ/$f.o"
done
# shellcheck disable=SC2086
"$WCC" -shared -s -o "$OUT/lua54.dll" $objs
"$WCC" -std=gnu99 -O2 -DLUA_COMPAT_5_3 -DLUA_BUILD_AS_DLL -c "$dir/src/lua.c" -o "$OBJ/lua.o"
"$WCC" -s -o "$OUT/lua.exe" "$OBJ/lua.o" "$OUT/lua54.dll"
for h in lua.h luaconf.h lualib.h lauxlib.h; do cp "$dir/src/$h" "$OUT/include/"; done
echo "windows-lua.sh: $OUT/lua54.dll, lua.exe ($(basename "$dir"))"
