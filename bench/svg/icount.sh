#!/bin/sh
# bench/svg/icount.sh FILE... -- instructions (callgrind) of arclen.svg on
# the files: the reader's (XML, transforms, shapes, path data into the
# paths' arrays: svg.read with measure = false) and the measuring's (every
# element's p:length() at tol 1e-12), as differences of the stages of
# bench/svg/icount.lua; then where the reader's go (callgrind_annotate,
# inclusive counts of the read stage).  Counts, unlike times, do not drift
# with the machine's load.  Run by make bench-svg when valgrind is installed.
LUA=${LUA_BIN:-lua5.4}
OUT=$(mktemp)
trap 'rm -f "$OUT"' EXIT
count() {   # count STAGE FILE...: the total instructions of one run
  valgrind --tool=callgrind --callgrind-out-file="$OUT" \
    "$LUA" bench/svg/icount.lua "$@" 2>&1 | sed -n 's/.*I *refs: *//p' | tr -d ',' | head -1
}
load=$(count load "$@")
measure=$(count measure "$@")
read=$(count read "$@")      # last: its profile stays in $OUT
awk -v l="$load" -v r="$read" -v m="$measure" 'BEGIN {
  rd = r - l; ms = m - r
  printf "instructions (callgrind): reader %.1f M, measuring %.1f M, reader / measuring %.2f\n",
    rd / 1e6, ms / 1e6, rd / ms }'
# inclusive counts of the reader's parts (symbols of arclen.svgdoc)
callgrind_annotate --inclusive=yes "$OUT" 2>/dev/null | awk '
  BEGIN {
    n = split("svgdoc.c:l_feed$|reader.c:on_start$|pathdata.c:arclen_pathdata_parse$|" \
              "shapes.c:svgdoc_shape_data$|XML_GetCurrentLineNumber|svgdoc.c:l_finish$|" \
              "subpaths.c:arclenL_pushsubpaths$", sym, "|")
    what[1] = "expat with the reader callbacks (feed)"
    what[2] = "  the callbacks: frames, attributes, shapes, path data"
    what[3] = "    path data into cubics (arcs converted)"
    what[4] = "    basic shapes as path data"
    what[5] = "    positions (line, column: expat)"
    what[6] = "the results into Lua tables (finish)"
    what[7] = "  the cubics (packed) and their subpaths"
  }
  { for (i = 1; i <= n; i++) if (!(i in v) && $0 ~ sym[i]) { x = $1; gsub(",", "", x); v[i] = x } }
  END { for (i = 1; i <= n; i++) if (i in v) printf "  %-56s %6.1f M\n", what[i], v[i] / 1e6 }'
