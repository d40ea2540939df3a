#!/bin/sh
# bench/bench_svg.sh -- `make bench-svg`: whole SVG documents (the real
# files of spec/data/svg/: Debian packages' icons, diagrams, a tutorial)
# measured by arclen.svg at tol 1e-12 and by svgelements (python3),
# svg-path-properties and paper.js (npm, under node), in one run, each
# one's error against tools/ref_svg.py's mpmath reference
# (spec/data/svg_refs.tsv).  arclen's time is split into the reader's own
# cost (XML, transforms, path data into cubics) and the measuring's, and
# so are its instructions under callgrind (bench/svg/icount.sh).
# Peers that cannot run are skipped with a message.  Then generated
# documents (bench/svg/big.sh): a halftone drawing of 10^5 circles, a
# 100 MB plotter file and files of paths of 10 and 100 MB, the time and
# peak RSS of arclen length, arclen stat, svg.read and svgelements.
#   BENCH_REPS=N (default 5): repetitions, the best time of each counts
#   BENCH_SVG_BIG=0: leave the generated documents out
cd "$(dirname "$0")/.." || exit 2
OUT=build/bench-svg
mkdir -p "$OUT"
RES=$OUT/results.tsv
: >"$RES"
LUA=${LUA_BIN:-lua5.4}
V=$($LUA -e 'print(type(jit) == "table" and "jit" or _VERSION:match("%d+%.%d+"))')
make -s LUA=${V} >/dev/null || exit 1
FILES=$(awk -F'\t' 'NR > 1 && ($1 ~ /^real\// || $1 ~ /^graphviz\//) { print "spec/data/svg/" $1 }' \
  spec/data/svg/SOURCES.tsv)
echo "files: $(echo $FILES | wc -w) real documents (spec/data/svg/SOURCES.tsv)"

echo "== arclen.svg ($LUA, tol 1e-12)"
LUA_PATH="lua/?.lua;lua/?/init.lua;;" LUA_CPATH="build/$V/?.so;;" \
  nice $LUA bench/svg/arclen_svg.lua "$OUT" $FILES >>"$RES" || exit 1

if command -v valgrind >/dev/null; then      # counts beside the times
  LUA_PATH="lua/?.lua;lua/?/init.lua;;" LUA_CPATH="build/$V/?.so;;" LUA_BIN=$LUA \
    sh bench/svg/icount.sh $FILES
else
  echo "instructions: skipped (apt-get install valgrind)"
fi

if /usr/bin/python3 -c 'import svgelements' 2>/dev/null; then
  echo "== svgelements (python3; with scipy if installed, then without)"
  BENCH_REPS=${SVGELEMENTS_REPS:-3} nice /usr/bin/python3 bench/svg/svgelements_peer.py $FILES >>"$RES"
  # without scipy a cubic takes svgelements ~0.5 s: a few small files only
  SMALL="adwaita-edit-redo-symbolic-rtl adwaita-folder-symbolic adwaita-network-workgroup-symbolic
         adwaita-system-users-symbolic barracuda-libgeo-test"
  S=""; for s in $SMALL; do S="$S spec/data/svg/real/$s.svg"; done
  SVGELEMENTS_NO_SCIPY=1 BENCH_REPS=1 nice /usr/bin/python3 bench/svg/svgelements_peer.py $S >>"$RES"
else
  echo "svgelements: skipped (apt-get install python3-svgelements)"
fi

if command -v node >/dev/null; then
  if [ ! -d $OUT/node/node_modules/svg-path-properties ] && command -v npm >/dev/null; then
    mkdir -p $OUT/node
    cp bench/svg/node/package.json $OUT/node/
    (cd $OUT/node && npm install --no-audit --no-fund >/dev/null 2>&1) ||
      echo "npm install failed (offline?)"
  fi
  echo "== node peers (svg-path-properties, paper.js)"
  nice node bench/svg/node/peers.js "$OUT" >>"$RES"
else
  echo "svg-path-properties, paper.js: skipped (node not installed)"
fi

echo
$LUA bench/svg/summary.lua "$RES"

if [ "${BENCH_SVG_BIG:-1}" != 0 ]; then
  echo
  echo "== generated documents: time and peak RSS (bench/svg/big.sh; GNU time)"
  LUA_BIN=$LUA sh bench/svg/big.sh
fi
