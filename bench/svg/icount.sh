#!/bin/sh
# bench/svg/icount.sh FILE... -- instructions (callgrind) of arclen.svg on
# the files: the reader's (XML, transforms, shapes, path data into the
# paths' arrays: svg.read with measure = false) and the measuring's (every
# element's p:length() at tol 1e-12), as differences of the stages of
# bench/svg/icount.lua.  Counts, unlike times, do not drift with the
# machine's load.  Run by make bench-svg when valgrind is installed.
LUA=${LUA_BIN:-lua5.4}
count() {   # count STAGE: the total instructions of one run
  valgrind --tool=callgrind --callgrind-out-file=/dev/null \
    "$LUA" bench/svg/icount.lua "$@" 2>&1 | sed -n 's/.*Collected : *//p; s/.*I *refs: *//p' |
    tr -d ',' | head -1
}
load=$(count load "$@")
read=$(count read "$@")
measure=$(count measure "$@")
awk -v l="$load" -v r="$read" -v m="$measure" 'BEGIN {
  rd = r - l; ms = m - r
  printf "instructions (callgrind): reader %.1f M, measuring %.1f M, reader / measuring %.2f\n",
    rd / 1e6, ms / 1e6, rd / ms }'
