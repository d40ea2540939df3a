#!/bin/sh
# tools/check-rock.sh -- the LuaRocks release as a user gets it, offline:
# pack the rocks from the work tree (tools/pack-rock.sh), install the core
# rock alone into a temporary tree (--deps-mode=none: no dkjson, no expat,
# nothing fetched), load it with the tree's paths only and run the specs
# that need no document reader on it; then install the SVG reader's rock
# too and run every spec.  The specs run in the packed source tree (no
# build/ there), under lua5.4, against the installed copy; #clone specs
# (the clone's own build) are left out.  The last line is
# "N passed, N failed".
#   KEEP=1 sh tools/check-rock.sh   keep the temporary directory
cd "$(dirname "$0")/.." || exit 2
ROOT=$(pwd)
PASSED=0
FAILED=0
T=$(mktemp -d)
[ -n "$KEEP" ] && echo "check-rock: working in $T" || trap 'rm -rf "$T"' EXIT
unset LUA_PATH LUA_CPATH LUA_PATH_5_4 LUA_CPATH_5_4 LUA_INIT LUA_INIT_5_4

ok() { echo "ok: $1"; PASSED=$((PASSED + 1)); }
bad() { echo "FAILED: $1"; FAILED=$((FAILED + 1)); }
finish() { echo; echo "$PASSED passed, $FAILED failed"; [ "$FAILED" -eq 0 ]; exit; }

# busted on PATH: a Lua script (Debian's) runs under lua5.4; a LuaRocks
# wrapper (a shell script) under the Lua it was installed for.
BUSTED=$(command -v busted) || { bad "busted not found on PATH"; finish; }
busted54() {
  if head -n 1 "$BUSTED" | grep -q '^#!.*lua'; then lua5.4 "$BUSTED" "$@"
  else "$BUSTED" "$@"; fi
}
command -v lua5.4 >/dev/null || { bad "lua5.4 not found"; finish; }

echo "== tools/pack-rock.sh (from the work tree)"
if sh tools/pack-rock.sh "$T/rock"; then ok "pack"; else bad "pack"; finish; fi
V=$(lua5.4 tools/gen_rockspec.lua --release)
CORE=$T/rock/arclen-$V-1.src.rock
SVG=$T/rock/arclen-svg-$V-1.src.rock
mkdir "$T/src"
tar -xzf "$T/rock/arclen-$V.tar.gz" -C "$T/src" || { bad "unpack the archive"; finish; }
SRC=$T/src/arclen-$V
TREE=$T/tree
LP="$TREE/share/lua/5.4/?.lua;$TREE/share/lua/5.4/?/init.lua"
CP="$TREE/lib/lua/5.4/?.so"

install() {   # install ROCK: offline, into $TREE, no dependencies fetched
  echo "== luarocks install --tree --deps-mode=none $(basename "$1")"
  if luarocks --lua-version 5.4 install --tree "$TREE" --deps-mode=none "$1" >"$T/install.log" 2>&1
  then ok "install $(basename "$1")"; else cat "$T/install.log"; bad "install $(basename "$1")"; finish; fi
}

specs() {   # specs WHAT BUSTED-OPTIONS...: the suite on the installed copy
  echo "== specs under lua5.4 ($1)"
  shift
  ( cd "$SRC" && busted54 --cpath="$CP" --lpath="$LP;spec/?.lua" \
      -o spec/summary_output.lua "$@" spec ) >"$T/out" 2>&1
  cat "$T/out"
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$T/out" | tail -1)
  if [ -z "$line" ]; then bad "busted printed no count"; return; fi
  PASSED=$((PASSED + $(echo "$line" | cut -d' ' -f1)))
  FAILED=$((FAILED + $(echo "$line" | cut -d' ' -f3)))
}

# ---- the core rock alone ------------------------------------------------
install "$CORE"
[ ! -e "$TREE/lib/lua/5.4/arclen/svgdoc.so" ] && ok "the core rock has no arclen.svgdoc" ||
  bad "the core rock installed arclen.svgdoc"
# Only the tree on the paths (no ;;): nothing of the system's, dkjson neither.
got=$(cd "$T" && LUA_PATH="$LP" LUA_CPATH="$CP" lua5.4 -e '
  local a = require "arclen"
  print(a._VERSION, ("%.17g"):format(a.length({0, 0, 10, 0, 10, 10, 0, 0})))
  print((pcall(require, "dkjson")))
  print(select(2, pcall(require, "arclen.svg")))' 2>&1)
echo "$got"
[ "$(echo "$got" | head -n 1)" = "$(printf 'arclen %s\t18.355664405650238' "$V")" ] &&
  ok "require 'arclen' from the tree alone: _VERSION and Henkel's arc 1" || bad "require 'arclen' from the tree"
[ "$(echo "$got" | sed -n 2p)" = false ] && ok "no dkjson in the tree" || bad "dkjson in the tree"
echo "$got" | sed -n 3p | grep -q "luarocks install arclen-svg" &&
  ok "require 'arclen.svg' says what to install" || bad "require 'arclen.svg' without the reader"
specs "the core rock alone; #svgdoc specs left out" --exclude-tags=svgdoc,clone

# The reader's rock without expat's header: LuaRocks stops before building
# and names it (its own message).
if luarocks --lua-version 5.4 install --tree "$T/noexpat" --deps-mode=none "$SVG" \
     EXPAT_DIR="$T/none" EXPAT_INCDIR="$T/none/include" >"$T/noexpat.log" 2>&1; then
  bad "arclen-svg installed without expat.h"
else
  grep -q "Could not find header file for EXPAT" "$T/noexpat.log" &&
    ok "arclen-svg without expat.h: LuaRocks names EXPAT" || { cat "$T/noexpat.log"; bad "arclen-svg without expat.h"; }
fi

# ---- and the SVG document reader's rock ----------------------------------
install "$SVG"
specs "the core and arclen-svg" --exclude-tags=clone
finish
