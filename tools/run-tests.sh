#!/bin/sh
# tools/run-tests.sh [LUA] -- run the spec suite under one Lua (default 5.4)
# against the fresh build in build/$LUA, never an installed arclen.
# The last line is busted's count as "N passed, N failed".
LUA=${1:-5.4}
case "$LUA" in
  jit) BIN=luajit ;;
  *) BIN=lua$LUA ;;
esac
exec "$BIN" /usr/bin/busted --cpath="build/$LUA/?.so" \
  --lpath="lua/?.lua;lua/?/init.lua;spec/?.lua" \
  -o spec/summary_output.lua spec
