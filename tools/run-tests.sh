#!/bin/sh
# tools/run-tests.sh -- the test command: the spec suite under Lua 5.4
# against the fresh build in build/5.4 (never an installed arclen), then a
# smoke run of the module built for each other Lua found on the machine
# (5.1, 5.2, 5.3, LuaJIT, LuaTeX's texlua with the 5.3 build).  The last
# line adds them up as "N passed, N failed".
#   FULL=1 tools/run-tests.sh   runs the whole suite under every Lua
cd "$(dirname "$0")/.." || exit 2
PASSED=0
FAILED=0
OUT=$(mktemp)
trap 'rm -f "$OUT"' EXIT

count() {   # add the "N passed, N failed" line of $OUT to the totals
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$OUT" | tail -1)
  if [ -z "$line" ]; then
    echo "run-tests: $1 printed no count: counted as 1 failure"
    FAILED=$((FAILED + 1))
    return
  fi
  PASSED=$((PASSED + $(echo "$line" | cut -d' ' -f1)))
  FAILED=$((FAILED + $(echo "$line" | cut -d' ' -f3)))
}

suite() {   # suite LUA BIN: the busted specs under one interpreter
  echo "== specs under $2 (build/$1)"
  "$2" /usr/bin/busted --cpath="build/$1/?.so" \
    --lpath="lua/?.lua;lua/?/init.lua;spec/?.lua" \
    -o spec/summary_output.lua spec 2>&1 | tee "$OUT"
  count "busted under $2"
}

smoke() {   # smoke LUA BIN: load the module and check a few values
  echo "== smoke test under $2 (build/$1)"
  "$2" spec/smoke.lua "build/$1" 2>&1 | tee "$OUT"
  count "smoke under $2"
}

for v in 5.1 5.2 5.3 jit; do
  case $v in jit) bin=luajit ;; *) bin=lua$v ;; esac
  command -v "$bin" >/dev/null || continue
  if [ -n "$FULL" ]; then suite "$v" "$bin"; else smoke "$v" "$bin"; fi
done
if command -v texlua >/dev/null && [ -f build/5.3/arclen.so ]; then
  smoke 5.3 texlua
fi
suite 5.4 lua5.4
# The rockspec builds and installs offline, and the installed module passes.
if command -v luarocks >/dev/null; then
  rm -rf build/rocktree
  echo "== luarocks make rockspec/arclen-scm-1.rockspec (into build/rocktree)"
  if luarocks --lua-version 5.4 make rockspec/arclen-scm-1.rockspec \
       --tree build/rocktree >build/luarocks.log 2>&1; then
    rm -f src/*.o
    echo "== specs under lua5.4 (the luarocks-installed module)"
    lua5.4 /usr/bin/busted --cpath="build/rocktree/lib/lua/5.4/?.so" \
      --lpath="build/rocktree/share/lua/5.4/?.lua;spec/?.lua" \
      -o spec/summary_output.lua spec 2>&1 | tee "$OUT"
    count "busted on the luarocks install"
  else
    cat build/luarocks.log
    echo "run-tests: luarocks make failed: counted as 1 failure"
    FAILED=$((FAILED + 1))
  fi
fi
echo
echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
