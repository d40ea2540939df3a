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

# ---- arclen for every LaTeX document: make install-tex into a temporary
# TEXMFHOME, then the documents of examples/tex/ (tikz_marks: markings,
# bending, text along a path; mp_arclen and plain_mp: input arclen; in
# luamplib, LaTeX and plain; tikz_errors: bad input; tikz_bench: 1000
# markings; pdflatex: the error under pdfLaTeX) compiled from a directory
# outside the clone, in LuaTeX's default mode (no --shell-escape: the Lua
# engine), with --shell-escape (the C core), and without the TikZ library
# (stock pgf, reported beside).  tools/check_tex.py compares the positions
# they wrote with tools/ref_tex.py's mpmath references.
echo "== arclen.sty, \usetikzlibrary{arclen}, input arclen; (examples/tex/)"
if command -v python3 >/dev/null && kpsewhich tikz.sty >/dev/null 2>&1; then
  TT=$(mktemp -d)
  sh tools/install-tex.sh "$TT/texmf" >"$OUT/install-tex.out" 2>&1 \
    && ok "make install-tex into a temporary TEXMFHOME" || bad "install-tex failed ($OUT/install-tex.out)"
  mkdir -p "$TT/run" "$OUT/tex"
  cp examples/tex/*.tex examples/tex/*.mp "$TT/run/"
  # ltex JOB ESC [TEX]: one lualatex run in $TT/run (ESC "" or
  # --shell-escape), timed
  ltex() {
    job=$1; esc=$2
    src=${3:-$job.tex}
    t0=$(now)
    (cd "$TT/run" && TEXMFHOME="$TT/texmf" lualatex $esc --interaction=nonstopmode \
      --jobname="$job" "$src" >"$job.out" 2>&1)
    st=$?
    t1=$(now)
    secs=$(awk "BEGIN { printf \"%.2f\", $t1 - $t0 }")
    echo "== lualatex ${esc:-(default mode)} $job: exit $st, $secs s wall"
  }
  ltex tikz_marks "";  tm_lua=$st
  ltex tikz_marks_c --shell-escape tikz_marks.tex
  ltex tikz_marks_stock "" '\def\stockpgf{}\input{tikz_marks}'
  ltex tikz_marks_luamath "" '\def\withluamath{}\input{tikz_marks}'
  ltex mp_arclen "";   mp_lua=$st
  cp "$TT/run/mp_arclen.mpd" "$TT/run/mp_arclen_lua.mpd" 2>/dev/null
  ltex mp_arclen_c --shell-escape mp_arclen.tex
  ltex tikz_errors ""
  (cd "$TT/run" && TEXMFHOME="$TT/texmf" luatex --interaction=nonstopmode plain_mp.tex >plain_mp.out 2>&1)
  st=$?
  echo "== luatex (default mode) plain_mp: exit $st"
  if command -v pdflatex >/dev/null; then
    (cd "$TT/run" && TEXMFHOME="$TT/texmf" pdflatex --interaction=nonstopmode pdflatex.tex >pdflatex.out 2>&1)
    tr -d '\n' <"$TT/run/pdflatex.log" | grep -q "Package arclen Error: arclen needs LuaLaTeX: run lualatex, not pdflatex" \
      && ok "pdfLaTeX: arclen.sty stops with a clear error" || bad "pdfLaTeX: no clear error from arclen.sty"
  fi
  [ $st -eq 0 ] && ok "plain_mp: no TeX error (plain LuaTeX, default mode)" || bad "plain_mp: exit $st"
  # an unknown pgf: a warning, pgf left as it is; " active when the
  # library is read: the same exact marks
  ltex unknown_pgf "" '\def\unknownpgf{}\input{tikz_marks}'
  tr -d '\n' <"$TT/run/unknown_pgf.log" | grep -q "pgf 9.9.9 is not a version this library knows" \
    && ok "unknown pgf version: a warning" || bad "unknown pgf version: no warning"
  cmp -s "$TT/run/unknown_pgf.pos" "$TT/run/tikz_marks_stock.pos" \
    && ok "unknown pgf version: pgf left as it is (the marks are stock pgf's)" \
    || bad "unknown pgf version: the marks are not stock pgf's"
  ltex active_quote "" '\def\activequote{}\input{tikz_marks}'
  # the engine option: lua under --shell-escape, c where the core cannot load
  ltex engine_lua --shell-escape '\PassOptionsToPackage{engine=lua}{arclen}\input{tikz_marks}'
  grep -q "Package arclen Info: engine lua (engine=lua)" "$TT/run/engine_lua.log" \
    && ok "engine=lua: the Lua engine under --shell-escape" || bad "engine=lua: not the Lua engine"
  ltex engine_c "" '\PassOptionsToPackage{engine=c}{arclen}\input{tikz_marks}'
  tr -d '\n' <"$TT/run/engine_c.log" | grep -q "arclen: engine=c needs --shell-escape" \
    && ok "engine=c in the default mode: a clear error, then the Lua engine" || bad "engine=c: no clear error"
  [ $tm_lua -eq 0 ] && ok "tikz_marks: no TeX error (default mode)" || bad "tikz_marks: exit $tm_lua"
  [ $mp_lua -eq 0 ] && ok "mp_arclen: no TeX error (default mode)" || bad "mp_arclen: exit $mp_lua"
  # luamplib reports MetaPost's errors as warnings: look for them
  for j in mp_arclen mp_arclen_c plain_mp; do
    n=$(grep -c "^(luamplib) *! " "$TT/run/$j.log")
    [ "$n" -eq 0 ] && ok "$j: no MetaPost error" || bad "$j: $n MetaPost errors (see its log)"
  done
  grep -q "Package arclen Info: engine lua (binary modules need --shell-escape)" "$TT/run/tikz_marks.log" \
    && ok "default mode: the Lua engine, reported in the log" || bad "default mode: no 'engine lua' in the log"
  grep -q "Package arclen Info: engine c," "$TT/run/tikz_marks_c.log" \
    && ok "--shell-escape: the C core, reported in the log" || bad "--shell-escape: no 'engine c' in the log"
  for pair in "tikz_marks exact tikz_marks.pos" "tikz_marks_c exact tikz_marks_c.pos tikz_marks.pos" \
      "tikz_marks_luamath exact tikz_marks_luamath.pos" \
      "active_quote exact active_quote.pos" \
      "mp_arclen mp mp_arclen_lua.mpd" "mp_arclen_c mp mp_arclen.mpd" "plain_mp mp plain_mp.mpd"; do
    set -- $pair
    name=$1; shift
    (cd "$TT/run" && python3 "$OLDPWD/tools/check_tex.py" "$@") >"$OUT/tex/$name.check" 2>&1
    line=$(tail -1 "$OUT/tex/$name.check")
    echo "     $name: $line"
    case "$line" in *" passed, 0 failed") ok "$name: positions against mpmath ($line)" ;;
      *) bad "$name: $line"; grep FAIL "$OUT/tex/$name.check" | head -5 ;; esac
  done
  echo "== stock pgf on the same marks (tools/check_tex.py stock; not a check)"
  (cd "$TT/run" && python3 "$OLDPWD/tools/check_tex.py" stock tikz_marks_stock.pos) >"$OUT/tex/stock.check" 2>&1
  grep -E "step: [0-9]+ marks|step: worst position|len100: worst position|frac0.5: worst position|text: worst position|bending tight" \
    "$OUT/tex/stock.check"
  # bad input: arclen's message for the huge curve, no "Dimension too large"
  # before that picture (pgf's own arithmetic overflows on it after), the
  # run to its end
  E="$TT/run/tikz_errors.log"
  grep -q "arclen: a curve of the path is 35317.9pt long, beyond TeX's largest dimension" "$E" \
    && ok "bad input: a curve longer than TeX's dimensions is an arclen error" || bad "bad input: no arclen message for the huge curve"
  huge=$(grep -n "longer than TeX's largest" examples/tex/tikz_errors.tex | cut -d: -f1)
  early=$(grep -A6 "^! Dimension too large" "$E" | grep -o "^l\.[0-9]*" | tr -d l. | awk -v h="$huge" '$1 < h' | wc -l)
  [ "$early" -eq 0 ] && ok "bad input: no 'Dimension too large' on one point, zero-length segments, coincident handles, empty text, a length beyond the path" \
    || bad "bad input: $early 'Dimension too large' before the huge curve"
  pdftotext "$TT/run/tikz_errors.pdf" - 2>/dev/null | grep -q "The run got here" \
    && ok "bad input: the run went on to the end" || bad "bad input: the run stopped"
  echo "== 1000 markings (examples/tex/tikz_bench.tex, whole lualatex runs)"
  ltex tikz_bench "";       b1=$secs
  ltex tikz_bench_stock "" '\def\stockpgf{}\input{tikz_bench}'; b2=$secs
  ltex tikz_bench_c --shell-escape tikz_bench.tex; b3=$secs
  ltex bench_empty "" '\def\benchempty{}\input{tikz_bench}'; b0=$secs
  echo "     whole runs: arclen $b1 s (Lua engine), $b3 s (C core), stock pgf $b2 s;" \
    "the figure alone (minus the run without it, $b0 s):" \
    "$(awk "BEGIN { printf \"%.2f s, %.2f s, %.2f s\", $b1 - $b0, $b3 - $b0, $b2 - $b0 }")"
  [ -s "$TT/run/tikz_bench.pdf" ] && ok "1000 markings: a PDF" || bad "1000 markings: no PDF"
  for j in tikz_marks tikz_marks_stock mp_arclen tikz_errors; do
    cp "$TT/run/$j.log" "$TT/run/$j.pdf" "$OUT/tex/" 2>/dev/null
    pdftoppm -r 80 -png "$TT/run/$j.pdf" "$OUT/tex/$j" 2>/dev/null \
      && ok "$j: rendered to PNG ($OUT/tex/)" || bad "$j: pdftoppm failed"
  done
  cp "$TT/run"/*.pos "$TT/run"/*.mpd "$OUT/tex/" 2>/dev/null
  rm -rf "$TT"
else
  bad "examples/tex: needs python3 and pgf (texlive-pictures; sh tools/deps.sh matrix)"
fi

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
