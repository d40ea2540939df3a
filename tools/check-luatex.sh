#!/bin/sh
# tools/check-luatex.sh -- make luatex: the LuaTeX example documents in real
# runs (LuaLaTeX with luamplib, plain LuaTeX), into build/luatex/:
#   examples/luamplib_arclen.tex   text, points, dashes, subpaths by length
#   examples/luatex_arclen.tex     plain LuaTeX: Lua alone, then mplib
#   examples/luamplib_errors.tex   bad input: messages, documented values
#   examples/luamplib_bench.tex    1000 placements, arclen vs arctime
# then the numbers they wrote against arclen in a separate texlua run
# (tools/check-luatex.lua), the error messages in the log, and each PDF's
# first page rendered to PNG (pdftoppm) to look at.  Needs the 5.3 build
# (make LUA=5.3).  Ends "N passed, N failed".
cd "$(dirname "$0")/.." || exit 2
OUT=build/luatex
PASSED=0
FAILED=0
ok() { PASSED=$((PASSED + 1)); echo "ok   $1"; }
bad() { FAILED=$((FAILED + 1)); echo "FAIL $1"; }
for t in lualatex luatex texlua; do
  command -v $t >/dev/null || { echo "check-luatex: $t not found (sh tools/deps.sh matrix)"; exit 1; }
done
if [ ! -f build/5.3/arclen.so ] && [ ! -f build/5.3/arclen/core.so ]; then
  echo "check-luatex: no build/5.3 module (make LUA=5.3)"; exit 1
fi
rm -rf "$OUT"
mkdir -p "$OUT"

now() { date +%s.%N; }
# tex ENGINE DOC [halt]: one run, data to $OUT/DOC.dat-*, its wall time
tex() {
  doc=$2
  halt=${3:+--halt-on-error}
  t0=$(now)
  ARCLEN_DATA="$OUT/$doc.dat" "$1" --shell-escape --interaction=nonstopmode $halt \
    --output-directory="$OUT" "examples/$doc.tex" >"$OUT/$doc.out" 2>&1
  status=$?
  t1=$(now)
  echo "== $1 examples/$doc.tex: exit $status, $(awk "BEGIN { printf \"%.2f\", $t1 - $t0 }") s wall"
  if [ -s "$OUT/$doc.pdf" ]; then ok "$doc: a PDF"; else bad "$doc: no PDF (see $OUT/$doc.log)"; fi
  if [ -n "$halt" ]; then
    if [ $status -eq 0 ]; then ok "$doc: no TeX or MetaPost error"
    else bad "$doc: exit $status"; grep -A3 '^!\|(luamplib) *!' "$OUT/$doc.log" | head -20; fi
  fi
}

tex lualatex luamplib_arclen halt
tex luatex luatex_arclen halt
tex lualatex luamplib_bench halt
tex lualatex luamplib_errors

# The bad-input run: every message, the run to its end (its last line in
# the PDF), the scaled warning once.  The log wraps at 79 columns and
# luamplib starts each line of MetaPost's output with "(luamplib)".
LOG=$(tr -d '\n' <"$OUT/luamplib_errors.log" | sed 's/(luamplib)  *//g')
while IFS= read -r msg; do
  case "$LOG" in *"$msg"*) ok "bad input message: $msg" ;; *) bad "bad input message missing: $msg" ;; esac
done <<'MSGS'
arclen_followtext: the path has length 0: no room for text
arclen_followtext: 13 of 32 glyphs fall beyond the ends of the path
arclen_length: a path expected, got a numeric
arclen_point: a path expected, got a string
arclen_time: the length must be a known numeric
arclen_dashed: dash pattern entry 2 must be a known numeric
arclen_dashed: dash pattern must not be all zero
arclen_followtext: align must be 'start', 'centre', 'end' or 'fit', got 'middle'
arclen_points: n must be an integer in [1, 100000]
arclen_length: unknown method 'bogus'
arclen_length: arclen_tol must be 0 (the default) or in [1e-15, 0.1]
arclen_length: 12000.00012 is beyond numbersystem scaled's range
MSGS
n=$(printf '%s' "$LOG" | grep -o "arclen warning: MetaPost runs with numbersystem scaled" | wc -l)
if [ "$n" -eq 1 ]; then ok "numbersystem scaled: warned once"; else bad "numbersystem scaled: warned $n times"; fi
if command -v pdftotext >/dev/null; then
  if pdftotext "$OUT/luamplib_errors.pdf" - 2>/dev/null | grep -q "The run got here"; then
    ok "bad input: the run went on to the end"; else bad "bad input: the run stopped"; fi
fi

# First pages as PNG, to look at.
if command -v pdftoppm >/dev/null; then
  for doc in luamplib_arclen luatex_arclen luamplib_errors luamplib_bench; do
    pdftoppm -r 80 -png -f 1 -l 1 "$OUT/$doc.pdf" "$OUT/$doc" 2>/dev/null
    if ls "$OUT/$doc"*.png >/dev/null 2>&1; then ok "$doc: rendered to PNG"
    else bad "$doc: pdftoppm failed"; fi
  done
fi

echo "== 1000 placements (seconds, each figure timed inside the run)"
sed 's/^BENCH /     /' "$OUT/luamplib_bench.dat-bench" 2>/dev/null

echo "== the numbers against arclen (texlua tools/check-luatex.lua)"
texlua tools/check-luatex.lua build/5.3 "$OUT"/*.dat-* >"$OUT/check.out" 2>&1
cat "$OUT/check.out"
line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$OUT/check.out" | tail -1)
if [ -n "$line" ]; then
  PASSED=$((PASSED + $(echo "$line" | cut -d' ' -f1)))
  FAILED=$((FAILED + $(echo "$line" | cut -d' ' -f3)))
else
  bad "tools/check-luatex.lua printed no count"
fi
echo
echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
