#!/bin/sh
# tools/check-builds.sh -- the spec suite (Lua 5.4) on the module as other
# compilers and flags build it, each in build/<name>/:
#   contract        GCC contracting every a*b+c it can (tools/cc-contract.sh:
#                   -ffp-contract=fast, and -mfma where the processor has it)
#   clang           clang as it comes (contraction within expressions)
#   clang-contract  clang with -ffp-contract=fast (-mfma): pragmas ignored
# No result of arclen may depend on these: every spec passes on each.
# Ends with a line "N passed, N failed"; builds missing a compiler are
# counted as a failure (sh tools/deps.sh matrix installs clang).
cd "$(dirname "$0")/.." || exit 2
OUT=$(mktemp)
trap 'rm -f "$OUT"' EXIT
. tools/counting.sh    # PASSED, FAILED, count NAME (the last count in $OUT)

run() {   # run NAME MAKE-ARGS...: build into build/NAME, run the specs
  name=$1
  shift
  echo "== specs under lua5.4 on the $name build"
  if ! make -s -j2 BUILD="build/$name" "$@" >"$OUT" 2>&1; then
    cat "$OUT"
    echo "check-builds: the $name build failed: counted as 1 failure"
    FAILED=$((FAILED + 1))
    return
  fi
  lua5.4 "$(command -v busted)" --cpath="build/$name/5.4/?.so" \
    --lpath="lua/?.lua;lua/?/init.lua;spec/?.lua" \
    -o spec/summary_output.lua spec 2>&1 | tee "$OUT"
  count "the $name build"
}

run contract CC="$PWD/tools/cc-contract.sh"
if command -v clang >/dev/null; then
  run clang CC=clang
  CONTRACT_CC=clang run clang-contract CC="$PWD/tools/cc-contract.sh"
else
  echo "check-builds: clang not found (sh tools/deps.sh matrix): counted as 1 failure"
  FAILED=$((FAILED + 1))
fi
echo
echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
