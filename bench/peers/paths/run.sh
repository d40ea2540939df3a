#!/bin/sh
# bench/peers/paths/run.sh OUT -- the peers of make bench-paths on OUT/path.txt
# (written by bench/bench_paths.lua): svg-path-properties and paper.js
# under node (npm installs them into OUT/node_modules once), kurbo 0.7
# (Debian's librust-kurbo-dev, built offline).  Each writes OUT/<name>.pts
# and a line "name ns-per-point" to OUT/results.txt; a peer that cannot run
# leaves a "# name: skipped (why)" line instead.
OUT=$(cd "$1" && pwd) || exit 1     # absolute: cargo runs in another directory
HERE=$(cd "$(dirname "$0")" && pwd)
: >"$OUT/results.txt"
if command -v node >/dev/null; then
  if [ ! -d "$OUT/node_modules/svg-path-properties" ] && command -v npm >/dev/null; then
    cp "$HERE/package.json" "$OUT/package.json"
    (cd "$OUT" && npm install --no-audit --no-fund >/dev/null 2>&1) ||
      echo "# npm install failed (offline?)" >>"$OUT/results.txt"
  fi
  cp "$HERE/paths.js" "$OUT/paths.js"
  (cd "$OUT" && nice node paths.js .) || echo "# node peers: failed" >>"$OUT/results.txt"
else
  echo "# svg-path-properties, paper.js: skipped (node not installed)" >>"$OUT/results.txt"
fi
if command -v cargo >/dev/null && ls -d /usr/share/cargo/registry/kurbo-0.7* >/dev/null 2>&1; then
  if (cd "$HERE/kurbo" && CARGO_TARGET_DIR="$OUT/kurbo" cargo build --release --offline -q) \
       >"$OUT/kurbo.log" 2>&1; then
    if t=$(nice "$OUT/kurbo/release/arclen-paths-kurbo" "$OUT/path.txt" "$OUT/kurbo-0.7.pts") &&
       [ -n "$t" ]; then
      echo "kurbo-0.7 $t" >>"$OUT/results.txt"
    else
      echo "# kurbo: skipped (the built peer did not run)" >>"$OUT/results.txt"
    fi
  else
    echo "# kurbo: skipped (build failed, see $OUT/kurbo.log)" >>"$OUT/results.txt"
  fi
else
  echo "# kurbo: skipped (needs cargo, and kurbo 0.7 in /usr/share/cargo/registry: apt-get install librust-kurbo-dev)" >>"$OUT/results.txt"
fi
