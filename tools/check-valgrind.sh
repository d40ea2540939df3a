#!/bin/sh
# tools/check-valgrind.sh -- the whole spec suite under valgrind memcheck
# with the normal build (build/5.4/arclen/core.so, built here if missing).
# Errors (invalid reads/writes, uses of uninitialised values) and definite
# or indirect leaks make valgrind exit 1; "still reachable" blocks (what
# the interpreter and busted hold at exit) are not errors.  No suppression
# is needed: a leak in arclen's code shows with its stack.  Subprocesses
# (the CLI spec's) run without valgrind.  Ends with "N passed, N failed":
# the suite's counts, plus one failure if valgrind reported anything.
cd "$(dirname "$0")/.." || exit 2
OUT=build/valgrind
LOG=$OUT/specs.log
VGLOG=$OUT/valgrind.log
mkdir -p "$OUT"
if ! command -v valgrind >/dev/null; then
  echo "valgrind: not installed (apt-get install valgrind)"
  echo "0 passed, 1 failed"
  exit 1
fi
make -s LUA=5.4 >/dev/null || { echo "0 passed, 1 failed"; exit 1; }
ARCLEN_TIME_SCALE=60 valgrind --error-exitcode=99 --leak-check=full \
  --errors-for-leak-kinds=definite,indirect \
  --show-leak-kinds=definite,indirect --num-callers=30 \
  --log-file="$VGLOG" \
  lua5.4 /usr/bin/busted --cpath="build/5.4/?.so" \
    --lpath="lua/?.lua;lua/?/init.lua;spec/?.lua" \
    -o spec/summary_output.lua spec >"$LOG" 2>&1
rc=$?
line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$LOG" | tail -1)
tail -3 "$LOG"
grep -E 'ERROR SUMMARY|definitely lost|indirectly lost' "$VGLOG"
if [ -z "$line" ]; then
  echo "valgrind: the suite printed no count (exit $rc): see $LOG"
  echo "0 passed, 1 failed"
  exit 1
fi
P=$(echo "$line" | cut -d' ' -f1)
F=$(echo "$line" | cut -d' ' -f3)
if [ "$rc" -eq 99 ]; then
  echo "valgrind: errors or leaks reported, see $VGLOG"
  grep -E -A20 'Invalid|uninitialised|definitely lost in|indirectly lost in' "$VGLOG" | head -80
  F=$((F + 1))
fi
echo "$P passed, $F failed"
[ "$F" -eq 0 ]
