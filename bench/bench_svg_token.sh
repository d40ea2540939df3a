#!/bin/sh
# bench/bench_svg_token.sh -- time and peak RSS of `arclen length` on one
# <path> whose d attribute is SIZES megabytes long (issue 31, item 4: the
# reader must be linear in the size of one token).  The documents are
# generated into a temporary directory and removed at the end.
#   SIZES="12.5 25 50 100" (default): the attribute sizes in MB (10^6 bytes)
# Needs GNU time (/usr/bin/time) for the peak RSS.
cd "$(dirname "$0")/.." || exit 2
SIZES=${SIZES:-"12.5 25 50 100"}
LUA=${LUA_BIN:-lua5.4}
V=$($LUA -e 'print(type(jit) == "table" and "jit" or _VERSION:match("%d+%.%d+"))')
make -s LUA="$V" >/dev/null || exit 1
TMP=$(mktemp -d) || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
printf 'MB\tseconds\tCPU_seconds\tpeak_RSS_MB\ttotal\n'
for mb in $SIZES; do
  f=$TMP/token-$mb.svg
  # "l1.00000000000000000000 0 " repeated: 26 bytes a unit line (few
  # cubics for the bytes: the token's size is what is measured), so the
  # total is the command count
  n=$($LUA - "$mb" "$f" <<'LUA'
    local mb, name = tonumber(arg[1]), arg[2]
    local n = math.floor(mb * 1e6 / 26)
    local f = assert(io.open(name, "wb"))
    f:write("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\">\n<path d=\"M0 0")
    local block = string.rep("l1.00000000000000000000 0 ", 10000)
    for _ = 1, math.floor(n / 10000) do f:write(block) end
    f:write(string.rep("l1.00000000000000000000 0 ", n % 10000), "\"/>\n</svg>\n")
    f:close()
    print(n)
LUA
  ) || exit 1
  /usr/bin/time -f '%e %U %S %M' -o "$TMP/time" $LUA bin/arclen length "$f" >"$TMP/out" || exit 1
  read -r secs user sys kb <"$TMP/time"
  total=$(awk '$1 == "total" { print $2 }' "$TMP/out")
  cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
  [ "$total" = "$n" ] || { echo "wrong total $total, want $n" >&2; exit 1; }
  printf '%s\t%s\t%s\t%s\t%s\n' "$mb" "$secs" "$cpu" "$((kb / 1024))" "$total"
done
