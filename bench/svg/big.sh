#!/bin/sh
# bench/svg/big.sh -- time and peak RSS on generated documents (issue 31,
# items 3 and 7): `arclen length`, `arclen stat` and svg.read (a Lua
# one-liner), and svgelements when python3 has it, on a halftone drawing
# (10^5 circles), a plotter file (paths in transformed groups, Inkscape
# layers) and files of plain paths.  The documents are generated into a
# temporary directory (bench/svg/gen_big.lua) and removed at the end.
#   BIG_FILES="halftone:100000 plotter:100 paths:10 paths:100" (default):
#     KIND:SIZE, SIZE a count of circles or megabytes
#   ARCLEN_ROOT=DIR: measure the clone at DIR instead (built), e.g. an
#     older checkout for a before/after table
#   BIG_TOOLS="length stat read svgelements" (default): what to run
# Prints one TSV row per file and tool: file, MB, elements, tool, elapsed s,
# CPU s, peak RSS MB, total.  Needs GNU time (/usr/bin/time).
cd "$(dirname "$0")/../.." || exit 2
HERE=$(pwd)
ROOT=${ARCLEN_ROOT:-$HERE}
BIG_FILES=${BIG_FILES:-"halftone:100000 plotter:100 paths:10 paths:100"}
BIG_TOOLS=${BIG_TOOLS:-"length stat read svgelements"}
LUA=${LUA_BIN:-lua5.4}
V=$($LUA -e 'print(type(jit) == "table" and "jit" or _VERSION:match("%d+%.%d+"))')
[ -x /usr/bin/time ] || { echo "big.sh: needs GNU time (apt-get install time)" >&2; exit 1; }
TMP=$(mktemp -d) || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
echo 'local d = require("arclen.svg").read(arg[1]) print("total", #d.elements, d.total)' >"$TMP/read.lua"
printf 'file\tMB\telements\ttool\tseconds\tCPU_seconds\tpeak_RSS_MB\ttotal\n'
for spec in $BIG_FILES; do
  kind=${spec%%:*} size=${spec#*:}
  f=$TMP/$kind-$size.svg
  n=$(lua5.4 bench/svg/gen_big.lua "$kind" "$size" "$f") || exit 1
  mb=$(awk -v b="$(wc -c <"$f")" 'BEGIN { printf "%.1f", b / 1e6 }')
  for tool in $BIG_TOOLS; do
    case $tool in
      length) set -- $LUA "$ROOT/bin/arclen" length "$f" ;;
      stat) set -- $LUA "$ROOT/bin/arclen" stat "$f" ;;
      read) set -- env LUA_PATH="$ROOT/lua/?.lua;$ROOT/lua/?/init.lua;;" \
              LUA_CPATH="$ROOT/build/$V/?.so;;" $LUA "$TMP/read.lua" "$f" ;;
      svgelements)
        /usr/bin/python3 -c 'import svgelements' 2>/dev/null || continue
        set -- /usr/bin/python3 "$HERE/bench/svg/svgelements_peer.py" "$f" ;;
      *) echo "big.sh: unknown tool $tool" >&2; exit 2 ;;
    esac
    if /usr/bin/time -f '%e %U %S %M' -o "$TMP/time" "$@" >"$TMP/out" 2>"$TMP/err"; then
      read -r secs user sys kb <"$TMP/time"
      case $tool in
        length) total=$(awk '$1 == "total" { print $2 }' "$TMP/out") ;;
        stat) total=$(awk '/^Totals/ { t = 1 } t && $1 == "Length:" { print $2; exit }' "$TMP/out") ;;
        read) total=$(awk '$1 == "total" { print $3 }' "$TMP/out") ;;
        svgelements) total=$(awk -F'\t' '{ print $3 }' "$TMP/out") ;;
      esac
      cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$kind:$size" "$mb" "$n" "$tool" "$secs" "$cpu" \
        "$((kb / 1024))" "$total"
    else
      printf '%s\t%s\t%s\t%s\tfailed: %s\n' "$kind:$size" "$mb" "$n" "$tool" "$(head -c 200 "$TMP/err")"
    fi
  done
  rm -f "$f"
done
