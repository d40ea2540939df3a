#!/bin/sh
# bench/peers/run.sh -- `make bench-peers`: arclen against the libraries a
# user would otherwise pick, in one run, on the same curves:
#   - the 3000 random cubics of bench/bench_util.h (seed 20261121) with
#     40-digit references (bench/peers/random3000.tsv, made by
#     tools/ref_bench_curves.py), and
#   - an adversarial set: the nearcusp, cusp, collinear, scale and offset
#     families of spec/data/curves2d.tsv with their references.
# Each peer prints: name, median ns per random curve, max relative error
# on the random set and on the adversarial set.  The table adds the ratio
# to the fixed 24-point Gauss-Legendre rule, as a plain loop (one square
# root at a time), measured in the same run.
# Peers that cannot be built or run are skipped with a message.
cd "$(dirname "$0")/../.." || exit 2
OUT=build/peers
mkdir -p "$OUT"
CURVES=$OUT/curves.txt
RES=$OUT/results.tsv
: >"$RES"

# the curves: kind, 8 coordinates, reference length
awk -F'\t' 'NR > 1 { printf "r %s %s %s %s %s %s %s %s %s\n", $2, $3, $4, $5, $6, $7, $8, $9, $10 }' \
  bench/peers/random3000.tsv >"$CURVES"
awk -F'\t' 'NR > 1 && ($2 == "nearcusp" || $2 == "cusp" || $2 == "collinear" ||
             $2 == "scale" || $2 == "offset") {
  printf "a %s %s %s %s %s %s %s %s %s\n", $4, $5, $6, $7, $8, $9, $10, $11, $15 }' \
  spec/data/curves2d.tsv >>"$CURVES"
NR=$(grep -c '^r' "$CURVES")
NA=$(grep -c '^a' "$CURVES")
echo "curves: $NR random (bench_util.h, seed 20261121), $NA adversarial (curves2d.tsv: nearcusp cusp collinear scale offset)"

# C: arclen, the GL24 baseline, GSL
make -s lib >/dev/null || exit 1
CFLAGS_P="-O2 -std=c99 -Wall -Wextra -D_POSIX_C_SOURCE=200809L -Isrc -Ibench"
if [ -f /usr/include/gsl/gsl_integration.h ]; then
  cc $CFLAGS_P -DHAVE_GSL bench/peers/peers.c build/libarclen.a -lgsl -lgslcblas -lm -o $OUT/peers || exit 1
else
  echo "GSL: skipped (apt-get install libgsl-dev)"
  cc $CFLAGS_P bench/peers/peers.c build/libarclen.a -lm -o $OUT/peers || exit 1
fi
echo "== C peers (arclen, GL24, GSL)"
nice $OUT/peers "$CURVES" | tee -a "$RES" || exit 1

# Rust: kurbo 0.7 from Debian, built offline
if command -v cargo >/dev/null && [ -d /usr/share/cargo/registry ] &&
   ls -d /usr/share/cargo/registry/kurbo-0.7* >/dev/null 2>&1; then
  echo "== kurbo (cargo build --offline against /usr/share/cargo/registry)"
  if (cd bench/peers/kurbo && CARGO_TARGET_DIR=../../../$OUT/kurbo \
        cargo build --release --offline -q) >$OUT/kurbo.log 2>&1; then
    nice $OUT/kurbo/release/arclen-peer-kurbo "$CURVES" | tee -a "$RES"
  else
    echo "kurbo: skipped (build failed, see $OUT/kurbo.log)"
  fi
else
  echo "kurbo: skipped (needs cargo and apt-get install librust-kurbo-dev)"
fi

# JavaScript: bezier-js and paper.js under node
if command -v node >/dev/null; then
  if [ ! -d bench/peers/node/node_modules/bezier-js ] && command -v npm >/dev/null; then
    (cd bench/peers/node && npm install --no-audit --no-fund >/dev/null 2>&1) ||
      echo "npm install failed (offline?)"
  fi
  echo "== node peers"
  nice node bench/peers/node/peers.js "$CURVES" | tee -a "$RES"
else
  echo "bezier-js, paper.js: skipped (node not installed)"
fi

# MetaPost
if command -v mpost >/dev/null; then
  echo "== MetaPost (one batch job)"
  mkdir -p $OUT/mpost
  lua5.4 bench/peers/mpost_peer.lua "$CURVES" $OUT/mpost | tee -a "$RES"
else
  echo "MetaPost: skipped (apt-get install texlive-binaries texlive-base)"
fi

echo
lua5.4 - "$RES" "$NR" "$NA" <<'LUA'
local rows = {}
for line in io.lines(arg[1]) do
  local name, ns, er, ea = line:match("^([^\t]+)\t(%S+)\t(%S+)\t(%S+)")
  if name then rows[#rows + 1] = {name, tonumber(ns), tonumber(er), tonumber(ea)} end
end
local base = rows[1] and rows[1][1]:match("24%-point") and rows[1][2]
if not base then print("no GL24 baseline measured"); os.exit(1) end
print(("| method (%s random curves, %s adversarial) | ns per curve (median) | ratio to the plain 24-point loop | max rel. error, random | max rel. error, adversarial |")
  :format(arg[2], arg[3]))
print("|---|---|---|---|---|")
local function e(x) return x == math.huge and "inf (NaN)" or ("%.1e"):format(x) end
for _, r in ipairs(rows) do
  print(("| %s | %.0f | %.1f | %s | %s |"):format(r[1], r[2], r[2] / base, e(r[3]), e(r[4])))
end
LUA
