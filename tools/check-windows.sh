#!/bin/sh
# tools/check-windows.sh -- arclen on Windows, checked from Debian 12:
#   0. no direct fma() in src/ (arclen_fma instead: MinGW's is inexact);
#   1. `make windows`: core.dll and svgdoc.dll cross-built with MinGW
#      (-Werror) against a Windows Lua 5.4 and a static expat built from
#      Debian's source packages (tools/windows-lua.sh, windows-expat.sh),
#      and Debian's static zlib for MinGW (libz-mingw-w64-dev);
#   2. their imports: the C runtime (msvcrt or the UCRT), KERNEL32 and
#      lua54.dll, nothing else (no libgcc_s_seh-1.dll);
#   3. under Wine: spec/smoke.lua, and every spec but the two that need a
#      shell (cli) or LuaRocks (rockspec), with tools/spec-lite.lua
#      (busted's C modules are not there).
# As root on a fresh machine it installs what it needs (apt-get).  Ends with
# "N passed, N failed"; exits 1 if anything failed.
set -u
cd "$(dirname "$0")/.." || exit 1
OUT=build/windows
CROSS=x86_64-w64-mingw32-
passed=0
failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL $*"; }
finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" = 0 ] || exit 1
  exit 0
}

need=
command -v ${CROSS}gcc >/dev/null || need="$need gcc-mingw-w64-x86-64"
command -v wine >/dev/null || need="$need wine wine64"
command -v make >/dev/null || need="$need make"
command -v dpkg-source >/dev/null || need="$need dpkg-dev"
# zlib for the reader's gzip input, linked static (Makefile, WIN_ZLIB)
[ -f /usr/x86_64-w64-mingw32/lib/libz.a ] || need="$need libz-mingw-w64-dev"
if [ -n "$need" ]; then
  if [ "$(id -u)" != 0 ]; then
    echo "check-windows.sh: missing$need; as root: apt-get install$need" >&2
    bad "packages missing:$need"
    finish
  fi
  echo "check-windows.sh: installing$need"
  # shellcheck disable=SC2086
  if ! { apt-get -o DPkg::Lock::Timeout=600 update -q >/dev/null &&
         DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -q \
           --no-install-recommends $need >/dev/null; }; then
    bad "apt-get install$need"
    finish
  fi
fi

# 0. the core calls arclen_fma (curve/numeric.h), never fma(): MinGW's is
#    not exactly rounded (comment lines, "** ..." and "/* ...", aside)
direct=$(grep -rn -E '(^|[^_[:alnum:]])fma[[:space:]]*\(' src --include='*.c' --include='*.h' |
  grep -v -E '^src/curve/numeric\.h:|^[^:]*:[0-9]+:[[:space:]]*(\*\*|/\*)')
if [ -z "$direct" ]; then
  ok
else
  echo "$direct"
  bad "fma() called directly (write arclen_fma: MinGW's fma is inexact)"
fi

# 1. the cross-build; -Werror: a warning fails it
mkdir -p "$OUT"
if make -s windows >"$OUT/build.log" 2>&1; then
  ok
else
  tail -n 20 "$OUT/build.log"
  bad "make windows (log: $OUT/build.log)"
  finish
fi

# 2. what each DLL needs at load time
for dll in core svgdoc; do
  imports=$(${CROSS}objdump -p "$OUT/arclen/$dll.dll" | sed -n 's/^[[:space:]]*DLL Name: //p')
  others=$(echo "$imports" | grep -v -i -E '^(kernel32|msvcrt|ucrtbase|lua54|api-ms-win-crt-[a-z0-9-]+)\.dll$')
  if [ -z "$others" ] && echo "$imports" | grep -q -i '^lua54\.dll$'; then
    ok
  else
    bad "$dll.dll imports $(echo "$imports" | tr '\n' ' ')(only the C runtime, KERNEL32 and lua54.dll are allowed)"
  fi
done

# 3. under Wine, in a prefix of our own (created on first use, ~10 s)
WINEPREFIX=$PWD/$OUT/wine
WINEDEBUG=-all
export WINEPREFIX WINEDEBUG
LUA_EXE=$OUT/lua/lua.exe
wineserver -p 60 2>/dev/null            # one server for all runs, not one each
if ! wine "$LUA_EXE" -e "os.exit(0)" >/dev/null 2>&1; then
  bad "wine cannot run $LUA_EXE"
  finish
fi
ok
# run NAME COMMAND...: its "N passed, N failed" added up; its whole output
# shown when something failed (else in $OUT/NAME.log)
run() {
  name=$1
  shift
  "$@" 2>&1 | tr -d '\r' >"$OUT/$name.log"
  line=$(tail -n 1 "$OUT/$name.log")
  case $line in
    *" passed, 0 failed") echo "$name: $line" ;;
    *) sed "s/^/$name: /" "$OUT/$name.log" ;;
  esac
  p=$(echo "$line" | sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\1/p')
  f=$(echo "$line" | sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\2/p')
  if [ -z "$p" ]; then bad "$name: no summary line"; return; fi
  passed=$((passed + p))
  failed=$((failed + f))
}
run smoke wine "$LUA_EXE" spec/smoke.lua "$OUT"
# not here: cli and optional (run the command line through a shell),
# rockspec (LuaRocks) and ctype (glibc's tr_TR lowers 'I' to itself; Windows'
# Turkish code page lowers it to 'i': no hazard to test)
specs=
for s in spec/*_spec.lua; do
  case $s in
    */cli_spec.lua | */optional_spec.lua | */rockspec_spec.lua | */ctype_spec.lua) ;;
    *) specs="$specs $s" ;;
  esac
done
# shellcheck disable=SC2086
LUA_PATH='lua/?.lua;lua/?/init.lua;spec/?.lua' LUA_CPATH="$OUT/?.dll" \
  run specs wine "$LUA_EXE" tools/spec-lite.lua $specs
wineserver -k 2>/dev/null
finish
