#!/bin/sh
# tools/check-sanitizers.sh -- the whole spec suite against a module built
# with AddressSanitizer and UndefinedBehaviorSanitizer (gcc), in
# build/asan/ (the normal build is untouched).  lua5.4 itself is not
# instrumented: the ASan runtime is preloaded, leak detection is off (the
# interpreter's own allocations at exit are not arclen's; leaks are
# valgrind's job, tools/check-valgrind.sh), and any ASan or UBSan report
# counts as a failure.  Ends with "N passed, N failed".
cd "$(dirname "$0")/.." || exit 2
CC=${CC:-gcc}
OUT=build/asan
LOG=$OUT/specs.log
SAN="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
mkdir -p "$OUT"
if ! make -s BUILD="$OUT" CC="$CC" CFLAGS="-O1 -g $SAN" LUA=5.4 \
     "$OUT/5.4/arclen/core.so" "$OUT/5.4/arclen/svgdoc.so" >"$OUT/build.log" 2>&1; then
  cat "$OUT/build.log"
  echo "0 passed, 1 failed"
  exit 1
fi
ASAN_LIB=$($CC -print-file-name=libasan.so)
UBSAN_LIB=$($CC -print-file-name=libubsan.so)
# halt_on_error: a report ends the process, so it cannot go unnoticed.
ARCLEN_TIME_SCALE=10 ASAN_OPTIONS=detect_leaks=0:halt_on_error=1:abort_on_error=0:detect_stack_use_after_return=1 \
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
LD_PRELOAD="$ASAN_LIB $UBSAN_LIB" \
  lua5.4 /usr/bin/busted --cpath="$OUT/5.4/?.so" \
    --lpath="lua/?.lua;lua/?/init.lua;spec/?.lua" \
    -o spec/summary_output.lua spec >"$LOG" 2>&1
rc=$?
line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$LOG" | tail -1)
reports=$(grep -c -E 'ERROR: AddressSanitizer|runtime error:|ERROR: LeakSanitizer' "$LOG")
grep -E -A12 'ERROR: AddressSanitizer|runtime error:' "$LOG" | head -60
tail -3 "$LOG"
if [ -z "$line" ]; then
  echo "sanitizers: the suite printed no count (exit $rc): see $LOG"
  echo "0 passed, 1 failed"
  exit 1
fi
P=$(echo "$line" | cut -d' ' -f1)
F=$(echo "$line" | cut -d' ' -f3)
if [ "$reports" -gt 0 ]; then
  echo "sanitizers: $reports report(s) in $LOG"
  F=$((F + reports))
fi
echo "$P passed, $F failed"
[ "$F" -eq 0 ]
