#!/bin/sh
# tools/pack-rock.sh [OUTDIR] -- pack the release's LuaRocks source rocks
# from the work tree, offline (make rock: OUTDIR build/rock).  Writes
#   OUTDIR/arclen-V.tar.gz            the tracked files as they are in the
#                                     work tree (git archive), in arclen-V/
#   OUTDIR/arclen-V-1.src.rock        the core (Lua and libm only)
#   OUTDIR/arclen-svg-V-1.src.rock    the SVG document reader (over expat)
# V is the release of src/arclen.h.  `luarocks pack` fetches a rockspec's
# source into a temporary directory and resolves a relative file or
# git+file URL there (LuaRocks 3.8, fetch.get_sources), so no committed
# rockspec packs from a clone: each is packed from a copy whose source is
# the archive's absolute file:// URL, and the rock then gets the committed
# rockspec back (its source the archive's name, as it is published), with
# zip where it is installed.  Installing a .src.rock unpacks the archive
# inside it and fetches nothing.
set -e
cd "$(dirname "$0")/.."
OUT=${1:-build/rock}
fail() { echo "pack-rock: $*" >&2; exit 1; }
command -v luarocks >/dev/null || fail "needs luarocks (Debian: apt-get install luarocks)"
command -v git >/dev/null && git rev-parse --git-dir >/dev/null 2>&1 ||
  fail "needs a git clone (the archive is git archive of the work tree)"
LUA=
for l in lua5.4 lua5.3 lua5.2 lua5.1 lua luajit; do
  if command -v "$l" >/dev/null; then LUA=$l; break; fi
done
[ -n "$LUA" ] || fail "needs a Lua interpreter"
V=$("$LUA" tools/gen_rockspec.lua --release)
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
case $OUT in *'|'*|*'"'*) fail "OUTDIR must not contain | or \"" ;; esac

# The tracked files with the work tree's changes: git stash create makes a
# commit of them without touching the work tree or the stash (none: HEAD).
rev=$(git stash create)
[ -n "$rev" ] || rev=HEAD
new=$(git ls-files --others --exclude-standard -- src lua bin rockspec)
[ -z "$new" ] || echo "pack-rock: untracked, not packed (git add them):" $new >&2
ARCHIVE=arclen-$V.tar.gz
git archive --format=tar --prefix="arclen-$V/" "$rev" | gzip -n -9 >"$OUT/$ARCHIVE"

for p in arclen arclen-svg; do
  rs=$p-$V-1.rockspec
  [ -f "rockspec/$rs" ] || fail "no rockspec/$rs (lua5.4 tools/gen_rockspec.lua --write)"
  sed "s|^source = { url = \"[^\"]*\"|source = { url = \"file://$OUT/$ARCHIVE\"|" \
    "rockspec/$rs" >"$OUT/$rs"
  grep -q "^source = { url = \"file://" "$OUT/$rs" || fail "rockspec/$rs: no source line to point at the archive"
  rm -f "$OUT/$p-$V-1.src.rock"
  (cd "$OUT" && luarocks pack "$rs") || fail "luarocks pack $rs failed"
  if command -v zip >/dev/null; then
    # -j: stored as its base name, replacing the copy's entry
    zip -q -j "$OUT/$p-$V-1.src.rock" "rockspec/$rs"
  fi
  rm -f "$OUT/$rs"
  echo "pack-rock: $OUT/$p-$V-1.src.rock"
done
