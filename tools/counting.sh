# tools/counting.sh -- sourced by the test scripts: PASSED and FAILED, and
# count NAME, which adds the last "N passed, N failed" line of the file
# $OUT to them (a step that printed none counts as one failure).
PASSED=0
FAILED=0
count() {
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$OUT" | tail -1)
  if [ -z "$line" ]; then
    echo "${0##*/}: $1 printed no count: counted as 1 failure"
    FAILED=$((FAILED + 1))
    return
  fi
  PASSED=$((PASSED + $(echo "$line" | cut -d' ' -f1)))
  FAILED=$((FAILED + $(echo "$line" | cut -d' ' -f3)))
}
