#!/bin/sh
# tools/windows-lua.sh [DIR] -- a Windows Lua 5.4 for the MinGW cross-build:
# lua54.dll, lua.exe and the headers in DIR (default build/windows/lua), built
# with x86_64-w64-mingw32-gcc from Debian's lua5.4 source package (the same
# Lua, with Debian's patches, that the Linux builds use).  Needs the
# package's source: as root it adds a deb-src line for the configured Debian
# mirror and suite when there is none, then runs apt-get update.
set -eu
OUT=${1:-build/windows/lua}
CROSS=${CROSS:-x86_64-w64-mingw32-}
WCC=${CROSS}gcc
if [ -f "$OUT/lua54.dll" ] && [ -f "$OUT/lua.exe" ] && [ -f "$OUT/include/lua.h" ]; then
  exit 0
fi

have_source() { apt-cache showsrc lua5.4 2>/dev/null | grep -q '^Package: lua5.4'; }

# The mirror and suite of the configured Debian archive: the entry whose
# suite is the release's codename (deb822 .sources files, or sources.list).
add_deb_src() {
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  [ -n "$codename" ] || { echo "windows-lua.sh: no VERSION_CODENAME in /etc/os-release" >&2; exit 1; }
  line=
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    # one stanza per paragraph: its URIs, Suites, Components and Signed-By
    line=$(awk -v cn="$codename" '
      function flush() {
        if (types ~ /(^| )deb( |$)/ && (" " suites " ") ~ (" " cn " ") && uri != "") {
          opt = signed != "" ? "[signed-by=" signed "] " : ""
          print "deb-src " opt uri " " cn " " comps; found = 1; exit
        }
        types = suites = uri = comps = signed = ""
      }
      /^[ \t]*$/ { flush(); next }
      /^Types:/ { sub(/^Types:[ \t]*/, ""); types = $0 }
      /^Suites:/ { sub(/^Suites:[ \t]*/, ""); suites = $0 }
      /^URIs:/ { sub(/^URIs:[ \t]*/, ""); uri = $1 }
      /^Components:/ { sub(/^Components:[ \t]*/, ""); comps = $0 }
      /^Signed-By:/ { sub(/^Signed-By:[ \t]*/, ""); signed = $1 }
      END { if (!found) flush() }' "$f")
    [ -n "$line" ] && break
  done
  if [ -z "$line" ] && [ -f /etc/apt/sources.list ]; then
    line=$(awk -v cn="$codename" '$1 == "deb" {
        i = 2; if ($2 ~ /^\[/) { while ($i !~ /\]$/) i++; i++ }
        if ($(i + 1) == cn) { $1 = "deb-src"; print; exit } }' /etc/apt/sources.list)
  fi
  [ -n "$line" ] || { echo "windows-lua.sh: no Debian '$codename' entry in the apt sources" >&2; exit 1; }
  echo "windows-lua.sh: adding to /etc/apt/sources.list.d/arclen-deb-src.list: $line"
  echo "$line" > /etc/apt/sources.list.d/arclen-deb-src.list
  apt-get -o DPkg::Lock::Timeout=600 update -q
}

if ! have_source; then
  if [ "$(id -u)" != 0 ]; then
    echo "windows-lua.sh: Debian's lua5.4 source is not available (no deb-src line);" \
      "run this as root once, or add a deb-src line and apt-get update" >&2
    exit 1
  fi
  add_deb_src
fi
command -v dpkg-source >/dev/null || {
  echo "windows-lua.sh: dpkg-source missing (Debian dpkg-dev)" >&2; exit 1; }

SRC=$OUT/debian-source
rm -rf "$SRC"
mkdir -p "$SRC"
if ! (cd "$SRC" && apt-get source -q lua5.4) >"$OUT/apt-source.log" 2>&1; then
  cat "$OUT/apt-source.log" >&2
  echo "windows-lua.sh: apt-get source lua5.4 failed" >&2
  exit 1
fi
dir=$(find "$SRC" -mindepth 1 -maxdepth 1 -type d -name 'lua5.4-*' | head -n 1)
if [ -z "$dir" ] || [ ! -f "$dir/src/lua.h" ]; then
  echo "windows-lua.sh: no unpacked lua5.4 source in $SRC" >&2
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
