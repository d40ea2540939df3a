#!/bin/sh
# tools/check-quad-bound.sh -- the quadratic time's table bound against
# mpmath: bench/quad_bound's answers on 3000 quadratics of five families
# at 19 distances each, their misses measured at 50 digits by
# tools/check_quad_bound.py, at tol 1e-12 and 1e-13 (the bound over every
# t in [0, 1)) and 1e-14 (the bound at the table's own t).  One check a
# tol: it fails where any miss exceeds its bound.  Needs python3-mpmath
# (tools/deps.sh matrix).  Ends with "N passed, N failed".
cd "$(dirname "$0")/.." || exit 2
PY=${PYTHON:-python3}
if ! $PY -c 'import mpmath' 2>/dev/null; then
  echo "check-quad-bound: $PY has no mpmath (apt-get install python3-mpmath)"
  echo "0 passed, 1 failed"
  exit 1
fi
if ! make -s lib >/dev/null || ! make -s -C bench bin/quad_bound >/dev/null; then
  echo "check-quad-bound: the build failed"
  echo "0 passed, 1 failed"
  exit 1
fi
passed=0 failed=0
for tol in 1e-12 1e-13 1e-14; do
  printf 'tol %s: ' "$tol"
  if ./bench/bin/quad_bound 3000 "$tol" | $PY tools/check_quad_bound.py; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
  fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
