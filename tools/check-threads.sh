#!/bin/sh
# tools/check-threads.sh -- spec/c/threads.c: the core measured from
# several threads at once, each result compared bit for bit with the same
# computed on one thread, under ThreadSanitizer.  The core's sources (and,
# where expat's header is found, the SVG document reader's) are compiled
# with -fsanitize=thread in build/tsan/CC/ (the normal build is untouched).
# Any TSan report ends the run (halt_on_error, exit code 66) and counts as
# a failure; so does an object file with writable data (global state).
# Ends with "N passed, N failed".
#   CC=gcc sh tools/check-threads.sh      (default clang, else gcc)
#   THREADS=8 ROUNDS=6 sh tools/check-threads.sh   (default 6 threads, 4 rounds)
cd "$(dirname "$0")/.." || exit 2
if [ -z "$CC" ]; then
  if command -v clang >/dev/null 2>&1; then CC=clang; else CC=gcc; fi
fi
OUT=build/tsan/$(basename "$CC")
LOG=$OUT/threads.log
TSAN="-fsanitize=thread -fno-omit-frame-pointer"
WARN="-std=c99 -Wall -Wextra -Wpedantic -D_POSIX_C_SOURCE=200809L"
mkdir -p "$OUT"
fail() {
  echo "check-threads: $1"
  echo "0 passed, 1 failed"
  exit 1
}
# The reader joins in when expat's header is there (as the Makefile decides).
if printf '#include <expat.h>\n' | $CC -E - >/dev/null 2>&1; then
  DOC_OBJ=''
  for f in src/svgdoc/*.c; do f=${f#src/}; DOC_OBJ="$DOC_OBJ $OUT/core/${f%.c}.o"; done
  DOC_FLAGS="-DTHREADS_SVGDOC"
  DOC_LIBS="-lexpat"
  # gzip.o has zlib when the Makefile finds its header (the same test)
  if printf '#include <zlib.h>\n' | $CC -E - >/dev/null 2>&1; then DOC_LIBS="$DOC_LIBS -lz"; fi
  DOC_FILES=$(ls spec/data/svg/hand/*.svg spec/data/svg/graphviz/*.svg \
    spec/data/svg/real/adwaita-preferences-system-parental-controls-symbolic.svg \
    spec/data/svg/real/postgresql-common-dependencies.svg)
else
  echo "check-threads: expat.h not found: the SVG document reader is left out"
  DOC_OBJ='' DOC_FLAGS='' DOC_LIBS='' DOC_FILES=''
fi
# shellcheck disable=SC2086
if ! make -s BUILD="$OUT" CC="$CC" CFLAGS="-O1 -g $TSAN" "$OUT/libarclen.a" $DOC_OBJ \
     >"$OUT/build.log" 2>&1; then
  cat "$OUT/build.log"
  fail "the core did not build with $CC $TSAN"
fi
# shellcheck disable=SC2086
if ! $CC -O1 -g $TSAN $WARN -Werror $DOC_FLAGS -Isrc -o "$OUT/threads" spec/c/threads.c \
     $DOC_OBJ "$OUT/libarclen.a" $DOC_LIBS -lm -pthread >>"$OUT/build.log" 2>&1; then
  cat "$OUT/build.log"
  fail "spec/c/threads.c did not build"
fi
# No global state: no object of the core or the reader has writable data
# (.data, .bss or thread-local sections; .data.rel.ro is constant after
# loading).  One check per object.
OBJ_OK=0 OBJ_BAD=0
for o in "$OUT"/core/*/*.o; do
  w=$(objdump -h "$o" | awk '$2 ~ /^\.(data|bss|tdata|tbss)/ && $2 !~ /rel\.ro/ && $3 !~ /^0+$/ {print $2}')
  if [ -z "$w" ]; then OBJ_OK=$((OBJ_OK + 1)); else
    echo "check-threads: $o has writable data: $w"
    OBJ_BAD=$((OBJ_BAD + 1))
  fi
done
start=$(date +%s)
# shellcheck disable=SC2086
# history_size=7: the longest history (4M accesses a thread), so that an
# older access of a race is still there to report.
TSAN_OPTIONS="halt_on_error=1 exitcode=66 history_size=7 $TSAN_OPTIONS" \
  "$OUT/threads" -t "${THREADS:-6}" -r "${ROUNDS:-4}" $DOC_FILES >"$LOG" 2>&1
rc=$?
end=$(date +%s)
cat "$LOG"
echo "check-threads: $CC, $((end - start)) s"
line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$LOG" | tail -1)
if grep -q 'ThreadSanitizer' "$LOG" || [ "$rc" -eq 66 ]; then
  P=$(echo "$line" | cut -d' ' -f1)
  fail "a ThreadSanitizer report (exit $rc), after ${P:-0} passed"
fi
[ -n "$line" ] || fail "no count printed (exit $rc)"
P=$(echo "$line" | cut -d' ' -f1)
F=$(echo "$line" | cut -d' ' -f3)
echo "check-threads: $OBJ_OK objects without writable data, $OBJ_BAD with"
echo "$((P + OBJ_OK)) passed, $((F + OBJ_BAD)) failed"
[ "$rc" -eq 0 ] && [ "$OBJ_BAD" -eq 0 ]
