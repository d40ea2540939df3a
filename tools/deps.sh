#!/bin/sh
# tools/deps.sh [base|matrix|refs|all] -- make sure the Debian packages a
# task needs are installed; as root, install the missing ones (apt-get),
# otherwise print the command that would.
#   base    build the module and run the specs under Lua 5.4 (default)
#   matrix  also Lua 5.1, 5.2, 5.3, LuaJIT, LuaTeX (texlua, the plain
#           luatex format from texlive-base, LuaLaTeX with luamplib from
#           texlive-luatex, lualatex from texlive-latex-base, MetaPost's
#           plain.mp from texlive-metapost), LuaRocks with git and zip
#           (make rock: git archive, the rockspec put back; make ctan),
#           pgf from texlive-pictures (the TikZ library), poppler-utils to
#           render the TeX examples, python3 for the check of the core's
#           layers, python3-mpmath for tools/check-quad-bound.sh, locales
#           with de_DE.UTF-8 and tr_TR.UTF-8 made by localedef for
#           spec/locale_spec.lua and spec/ctype_spec.lua
#           (base has libexpat1-dev for the SVG document reader,
#           arclen.svgdoc, zlib1g-dev for its gzip input (.svgz), and
#           lua-dkjson for --json)
#   refs    regenerate spec/data (python3-mpmath, real MetaPost;
#           python3-svgelements: tools/ref_svg.py's second opinion;
#           python3-tinycss2, python3-cssselect2: its style sheets;
#           gir1.2-rsvg-2.0, python3-gi, python3-gi-cairo, python3-cairo,
#           python3-lxml: tools/ref_rsvg.py, librsvg's opinion)
# Without dpkg and apt-get (macOS, Alpine, Fedora, Arch, FreeBSD, MSYS2) it
# prints what to install there for base -- a C compiler, make, Lua 5.4 with
# its headers, busted, expat, zlib, pkg-config -- and fails unless the commands are
# all found (headers are not checked: make says what it misses).
set -e

# The install lines for a system other than Debian's, by what it says it is.
other_system() {
  case $(uname -s 2>/dev/null) in
    Darwin) sys=brew ;;
    MINGW*|MSYS*) sys=msys2 ;;
    FreeBSD) sys=freebsd ;;
    *) ids=$( . "${OS_RELEASE:-/etc/os-release}" 2>/dev/null && echo "$ID $ID_LIKE")
       case " $ids " in
         *" alpine "*) sys=apk ;;
         *" fedora "*|*" rhel "*|*" centos "*) sys=dnf ;;
         *" arch "*) sys=pacman ;;
         *) sys=all ;;
       esac ;;
  esac
  echo "tools/deps.sh: no dpkg/apt-get here; for 'make' and the specs install:" >&2
  if [ $sys = brew ] || [ $sys = all ]; then
    echo "  macOS:   xcode-select --install; brew install lua luarocks pkg-config" >&2
    echo "           (expat and zlib are in the SDK); luarocks install busted" >&2
  fi
  if [ $sys = apk ] || [ $sys = all ]; then
    echo "  Alpine:  apk add build-base pkgconf lua5.4 lua5.4-dev expat-dev zlib-dev luarocks5.4;" >&2
    echo "           luarocks-5.4 install busted" >&2
  fi
  if [ $sys = dnf ] || [ $sys = all ]; then
    echo "  Fedora:  dnf install gcc make pkgconf-pkg-config lua lua-devel expat-devel zlib-devel luarocks;" >&2
    echo "           luarocks install busted" >&2
  fi
  if [ $sys = pacman ] || [ $sys = all ]; then
    echo "  Arch:    pacman -S --needed base-devel lua expat zlib luarocks; luarocks install busted" >&2
  fi
  if [ $sys = freebsd ] || [ $sys = all ]; then
    echo "  FreeBSD: pkg install lua54 lua54-luarocks expat gmake pkgconf (zlib is in base);" >&2
    echo "           luarocks54 install busted (then gmake, not make)" >&2
  fi
  if [ $sys = msys2 ] || [ $sys = all ]; then
    echo "  MSYS2 (UCRT64): pacman -S --needed make mingw-w64-ucrt-x86_64-{gcc,lua,lua-luarocks,expat,zlib,pkgconf};" >&2
    echo "           luarocks install busted" >&2
  fi
  echo "  optional: luarocks install dkjson (arclen --json)" >&2
  missing=""
  command -v cc >/dev/null 2>&1 || command -v gcc >/dev/null 2>&1 || command -v clang >/dev/null 2>&1 || missing="$missing cc"
  command -v gmake >/dev/null 2>&1 || command -v make >/dev/null 2>&1 || missing="$missing make"
  lua54=""
  for l in lua5.4 lua54 lua-5.4 lua; do
    if command -v $l >/dev/null 2>&1 && $l -v 2>&1 | grep -q "^Lua 5\.4"; then lua54=$l; break; fi
  done
  [ -n "$lua54" ] || missing="$missing lua5.4"
  command -v busted >/dev/null 2>&1 || missing="$missing busted"
  if [ -n "$missing" ]; then
    echo "tools/deps.sh: not found:$missing" >&2
    return 1
  fi
  [ -x "$(command -v lua5.4)" ] || echo "tools/deps.sh: Lua 5.4 is '$lua54': make LUA_BIN=$lua54 demo" >&2
  return 0
}
BASE="gcc make libc6-dev lua5.4 liblua5.4-dev lua-busted libexpat1-dev zlib1g-dev lua-dkjson"
MATRIX="lua5.1 liblua5.1-0-dev lua5.2 liblua5.2-dev lua5.3 liblua5.3-dev luajit libluajit-5.1-dev texlive-binaries texlive-base texlive-luatex texlive-latex-base texlive-metapost luarocks poppler-utils python3 python3-mpmath locales git zip texlive-pictures"
REFS="python3 python3-mpmath python3-svgelements python3-tinycss2 python3-cssselect2 gir1.2-rsvg-2.0 python3-gi python3-gi-cairo python3-cairo python3-lxml texlive-binaries texlive-base python3-fonttools fonts-urw-base35"
case "${1:-base}" in
  base) WANT="$BASE" ;;
  matrix) WANT="$BASE $MATRIX" ;;
  refs) WANT="$REFS" ;;
  all) WANT="$BASE $MATRIX $REFS" ;;
  *) echo "usage: sh tools/deps.sh [base|matrix|refs|all]" >&2; exit 2 ;;
esac
if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  case "${1:-base}" in
    base) ;;
    *) echo "tools/deps.sh: '$1' lists Debian packages (the Lua matrix, LuaTeX, references);" \
         "elsewhere install their equivalents by hand" >&2 ;;
  esac
  if other_system; then exit 0; else exit 1; fi
fi
MISSING=""
for p in $WANT; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || MISSING="$MISSING $p"
done
# The locales the specs run under (after the packages): de_DE.UTF-8, a
# comma decimal point (spec/locale_spec.lua), and tr_TR.UTF-8, whose
# tolower('I') is not 'i' (spec/ctype_spec.lua).
test_locales() {
  case "${1:-base}" in matrix|all) ;; *) return 0 ;; esac
  for l in de_DE tr_TR; do
    locale -a 2>/dev/null | grep -qi "^$l\.utf-\?8\$" && continue
    if [ "$(id -u)" = 0 ]; then
      echo "tools/deps.sh: generating the locale $l.UTF-8"
      localedef -i $l -f UTF-8 $l.UTF-8 || return 1
    else
      echo "run as root: localedef -i $l -f UTF-8 $l.UTF-8" >&2
      return 1
    fi
  done
}
[ -z "$MISSING" ] && { test_locales "$1"; exit $?; }
if [ "$(id -u)" = 0 ]; then
  echo "tools/deps.sh: installing$MISSING"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends $MISSING >/dev/null
  test_locales "$1"
else
  echo "tools/deps.sh: missing Debian packages:$MISSING" >&2
  echo "run as root: apt-get install$MISSING" >&2
  exit 1
fi
