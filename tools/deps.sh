#!/bin/sh
# tools/deps.sh [base|matrix|refs|all] -- make sure the Debian packages a
# task needs are installed; as root, install the missing ones (apt-get),
# otherwise print the command that would.
#   base    build the module and run the specs under Lua 5.4 (default)
#   matrix  also Lua 5.1, 5.2, 5.3, LuaJIT, LuaTeX (texlua, the plain
#           luatex format from texlive-base, LuaLaTeX with luamplib from
#           texlive-luatex, lualatex from texlive-latex-base, MetaPost's
#           plain.mp from texlive-metapost), LuaRocks, poppler-utils to
#           render the TeX examples, python3 for the check of the core's
#           layers (base has libexpat1-dev for the SVG document reader,
#           arclen.svgdoc, and lua-dkjson for the command line's --json)
#   refs    regenerate spec/data (python3-mpmath, real MetaPost;
#           python3-svgelements: tools/ref_svg.py's second opinion)
set -e
BASE="gcc make libc6-dev lua5.4 liblua5.4-dev lua-busted libexpat1-dev lua-dkjson"
MATRIX="lua5.1 liblua5.1-0-dev lua5.2 liblua5.2-dev lua5.3 liblua5.3-dev luajit libluajit-5.1-dev texlive-binaries texlive-base texlive-luatex texlive-latex-base texlive-metapost luarocks poppler-utils python3 texlive-pictures"
REFS="python3 python3-mpmath python3-svgelements texlive-binaries texlive-base python3-fonttools fonts-urw-base35"
case "${1:-base}" in
  base) WANT="$BASE" ;;
  matrix) WANT="$BASE $MATRIX" ;;
  refs) WANT="$REFS" ;;
  all) WANT="$BASE $MATRIX $REFS" ;;
  *) echo "usage: sh tools/deps.sh [base|matrix|refs|all]" >&2; exit 2 ;;
esac
MISSING=""
for p in $WANT; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || MISSING="$MISSING $p"
done
[ -z "$MISSING" ] && exit 0
if [ "$(id -u)" = 0 ]; then
  echo "tools/deps.sh: installing$MISSING"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends $MISSING >/dev/null
else
  echo "tools/deps.sh: missing Debian packages:$MISSING" >&2
  echo "run as root: apt-get install$MISSING" >&2
  exit 1
fi
