#!/bin/sh
# icount.sh -- instructions per call (callgrind) of the fixed 24-point rule
# and of the default method on bench_length's 3000 random curves, and their
# ratios: a measure of cost that does not drift with the machine's state.
# Needs valgrind; run by `make bench-icount` after bin/bench_icount is built.
set -e
cd "$(dirname "$0")"
command -v valgrind >/dev/null || { echo "icount.sh: valgrind not found" >&2; exit 1; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
count() {   # count MODE: "calls instructions"
  calls=$(valgrind --tool=callgrind --toggle-collect=measured \
            --callgrind-out-file="$out" ./bin/bench_icount "$1" 2>/dev/null)
  echo "$calls $(sed -n 's/^totals: //p' "$out")"
}
gl=$(count gl24)
echo "instructions per call, 3000 random cubics in [0,10]^2 (mean)"
printf '%-40s %7s %12s %7s\n' what calls instructions ratio
for m in gl24 one multi all all15 time time15 times10 segcubic quad quadtime \
    quadtime15; do
  if [ $m = gl24 ]; then r=$gl; else r=$(count $m); fi
  echo "$m $r $gl"
done | awk '
  $1 == "gl24" { name = "fixed 24-point Gauss-Legendre" }
  $1 == "one" { name = "arclen_length 1e-12, one-piece curves" }
  $1 == "multi" { name = "arclen_length 1e-12, curves of 2+ pieces" }
  $1 == "all" { name = "arclen_length 1e-12, every curve" }
  $1 == "all15" { name = "arclen_length 1e-15, every curve" }
  $1 == "time" { name = "arclen_time L/2 1e-12, every curve" }
  $1 == "time15" { name = "arclen_time L/2 1e-15, every curve" }
  $1 == "times10" { name = "arclen_times, 10 distances a curve (per)" }
  $1 == "segcubic" { name = "arclen_segment_length, the cubic" }
  $1 == "quad" { name = "arclen_segment_length, its quadratic" }
  $1 == "quadtime" { name = "arclen_segment_time L/2 1e-12, quadratic" }
  $1 == "quadtime15" { name = "arclen_segment_time L/2 1e-15, quadratic" }
  { per = $3 / $2; printf "%-40s %7d %12.0f %7.2f\n", name, $2, per, per / ($5 / $4) }'
