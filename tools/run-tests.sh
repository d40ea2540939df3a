#!/bin/sh
# tools/run-tests.sh -- the test command: the whole spec suite under every
# Lua found on the machine -- 5.1, 5.2, 5.3, LuaJIT, LuaTeX's texlua (with
# the 5.3 build) and texluajit (with the LuaJIT build), then 5.4 -- each
# against the fresh build in build/<version> (never an installed arclen);
# the LuaTeX example (examples/mplib_path.lua) under texlua and texluajit
# and inside a document (luatex --shell-escape examples/mplib_path.tex);
# the LuaLaTeX/LuaTeX documents of tools/check-luatex.sh (make luatex);
# the LuaRocks release packed, installed offline and passing the suite
# (tools/check-rock.sh).  The last line adds them up as "N passed, N failed".
# busted is the one on PATH.
#   SMOKE=1 tools/run-tests.sh   only a smoke run (spec/smoke.lua) under
#                                the Lua versions other than 5.4
cd "$(dirname "$0")/.." || exit 2
OUT=$(mktemp)
trap 'rm -f "$OUT"' EXIT
. tools/counting.sh    # PASSED, FAILED, count NAME (the last count in $OUT)

# busted on PATH: a Lua script (Debian's) runs under the Lua given; a
# LuaRocks wrapper (a shell script) runs under the Lua it was installed for
# (busted's --lua re-runs it through a shell that splits our ';' paths).
BUSTED=$(command -v busted) || { echo "run-tests: busted not found on PATH (sh tools/deps.sh)"; exit 1; }
busted_under() {   # busted_under BIN ARGS...
  under=$1
  shift
  if head -n 1 "$BUSTED" | grep -q '^#!.*lua'; then "$under" "$BUSTED" "$@"
  else echo "run-tests: $BUSTED is a wrapper: its own Lua, not $under"; "$BUSTED" "$@"; fi
}

suite() {   # suite LUA BIN: the busted specs under one interpreter
  echo "== specs under $2 (build/$1)"
  busted_under "$2" --cpath="build/$1/?.so" \
    --lpath="lua/?.lua;lua/?/init.lua;spec/?.lua" \
    -o spec/summary_output.lua spec 2>&1 | tee "$OUT"
  count "busted under $2"
}

# LuaTeX's texlua (Lua 5.3) and texluajit (LuaJIT) do not search Debian's
# Lua directories; busted and its modules are there.
texlua_env() {   # texlua_env ABI: LUA_PATH/LUA_CPATH for Debian's modules
  LUA_PATH="/usr/share/lua/$1/?.lua;/usr/share/lua/$1/?/init.lua;;"
  LUA_CPATH="/usr/lib/$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)/lua/$1/?.so;;"
  export LUA_PATH LUA_CPATH
}

example() {   # example LUA BIN: the LuaTeX example under texlua/texluajit
  echo "== examples/mplib_path.lua under $2 (build/$1)"
  "$2" examples/mplib_path.lua "build/$1" 2>&1 | tee "$OUT"
  count "examples/mplib_path.lua under $2"
}

smoke() {   # smoke LUA BIN: load the module and check a few values
  echo "== smoke test under $2 (build/$1)"
  "$2" spec/smoke.lua "build/$1" 2>&1 | tee "$OUT"
  count "smoke under $2"
}

# The core's areas depend one way, with no cycle between object files.
if command -v python3 >/dev/null && command -v nm >/dev/null; then
  echo "== the areas' dependencies (tools/check_layers.py over build/core)"
  python3 tools/check_layers.py build/core 2>&1 | tee "$OUT"
  count "check_layers"
else
  echo "== the areas' dependencies: skipped (needs python3 and nm; sh tools/deps.sh matrix)"
fi
for v in 5.1 5.2 5.3 jit; do
  case $v in jit) bin=luajit ;; *) bin=lua$v ;; esac
  command -v "$bin" >/dev/null || continue
  if [ -z "$SMOKE" ]; then suite "$v" "$bin"; else smoke "$v" "$bin"; fi
done
for t in texlua:5.3:5.3 texluajit:jit:5.1; do   # binary:build:module ABI
  bin=${t%%:*}; rest=${t#*:}; v=${rest%%:*}; abi=${rest#*:}
  command -v "$bin" >/dev/null && [ -f "build/$v/arclen/core.so" ] || continue
  ( texlua_env "$abi"
    if [ -z "$SMOKE" ] && [ -f "/usr/share/lua/$abi/busted/runner.lua" ]; then
      suite "$v" "$bin"; else smoke "$v" "$bin"; fi
    echo "$PASSED $FAILED" >"$OUT.totals" )
  read PASSED FAILED <"$OUT.totals"
  example "$v" "$bin"
done
rm -f "$OUT.totals"
# The same example inside a LuaTeX document (the PDF goes to build/).
if command -v luatex >/dev/null && [ -f build/5.3/arclen/core.so ]; then
  echo "== luatex --shell-escape examples/mplib_path.tex (build/5.3)"
  rm -f build/mplib_path.pdf
  luatex --shell-escape --interaction=nonstopmode --halt-on-error \
    --output-directory=build examples/mplib_path.tex >"$OUT.tex" 2>&1
  status=$?
  tee "$OUT" <"$OUT.tex"
  rm -f "$OUT.tex"
  if [ $status -ne 0 ] || [ ! -s build/mplib_path.pdf ]; then
    echo "run-tests: luatex failed or wrote no PDF: counted as 1 failure"
    FAILED=$((FAILED + 1))
  fi
  count "examples/mplib_path.tex under luatex"
fi
# The LuaTeX documents with MetaPost (make luatex: tools/check-luatex.sh).
if command -v lualatex >/dev/null && { [ -f build/5.3/arclen.so ] || [ -f build/5.3/arclen/core.so ]; }; then
  echo "== tools/check-luatex.sh (build/5.3)"
  sh tools/check-luatex.sh >"$OUT.tex" 2>&1
  tee "$OUT" <"$OUT.tex"
  rm -f "$OUT.tex"
  count "tools/check-luatex.sh"
fi
suite 5.4 lua5.4
# The path-level specs again on the Lua engine (what LuaTeX runs without
# --shell-escape): under Lua 5.4 and under texlua, LuaTeX's own Lua.
LUA_ENGINE_SPECS="spec/engine_spec.lua spec/engines_diff_spec.lua spec/length_spec.lua
  spec/times_spec.lua spec/subrange_spec.lua spec/path_spec.lua spec/badinput_spec.lua
  spec/batch_spec.lua spec/hostile_spec.lua spec/mpost_spec.lua spec/refdata_spec.lua
  spec/path_kinds_spec.lua spec/segment_spec.lua spec/conic_thin_spec.lua
  spec/conic_time_spec.lua"
engine_suite() {   # engine_suite LUA BIN: those specs with ARCLEN_ENGINE=lua
  echo "== path-level specs on the Lua engine (ARCLEN_ENGINE=lua, $2)"
  ( ARCLEN_ENGINE=lua; export ARCLEN_ENGINE
    busted_under "$2" --cpath="build/$1/?.so" \
      --lpath="lua/?.lua;lua/?/init.lua;spec/?.lua" \
      -o spec/summary_output.lua $LUA_ENGINE_SPECS ) 2>&1 | tee "$OUT"
  count "busted on the Lua engine under $2"
}
engine_suite 5.4 lua5.4
if command -v texlua >/dev/null && [ -f /usr/share/lua/5.3/busted/runner.lua ]; then
  ( texlua_env 5.3; engine_suite 5.3 texlua; echo "$PASSED $FAILED" >"$OUT.totals" )
  read PASSED FAILED <"$OUT.totals"
  rm -f "$OUT.totals"
fi
# The LuaRocks release: packed from the work tree, installed offline (the
# core rock alone, then with arclen-svg), the suite on the installed copy.
if command -v luarocks >/dev/null; then
  echo "== tools/check-rock.sh"
  sh tools/check-rock.sh >"$OUT.rock" 2>&1
  tee "$OUT" <"$OUT.rock"
  rm -f "$OUT.rock"
  count "tools/check-rock.sh"
fi
echo
echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
