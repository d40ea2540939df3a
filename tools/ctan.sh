#!/bin/sh
# tools/ctan.sh -- make ctan: build/ctan/arclen.zip, the archive CTAN
# takes: arclen/ with README.md, the manual arclen.pdf and its source
# arclen-doc.tex, arclen.sty, tikzlibraryarclen.code.tex, arclen.mp and the
# Lua files (arclen.lua, arclen/*.lua).  The manual is typeset by lualatex
# in LuaTeX's default mode from a temporary TEXMFHOME made by
# tools/install-tex.sh, so its figures are drawn by the package itself.
cd "$(dirname "$0")/.." || exit 2
set -e
OUT=build/ctan
rm -rf "$OUT"
mkdir -p "$OUT/texmf" "$OUT/doc" "$OUT/arclen/arclen"
sh tools/install-tex.sh "$OUT/texmf" >/dev/null
cp tex/arclen-doc.tex "$OUT/doc/"
for run in 1 2; do
  (cd "$OUT/doc" && TEXMFHOME="$PWD/../texmf" lualatex --interaction=nonstopmode \
    --halt-on-error arclen-doc.tex >lualatex.out 2>&1) \
    || { echo "ctan: lualatex failed, see $OUT/doc/arclen-doc.log" >&2; exit 1; }
done
grep -q "Package arclen Info: engine lua" "$OUT/doc/arclen-doc.log"
A="$OUT/arclen"
cp "$OUT/doc/arclen-doc.pdf" "$A/arclen.pdf"
cp tex/README.md tex/arclen-doc.tex tex/arclen.sty tex/tikzlibraryarclen.code.tex mp/arclen.mp "$A/"
cp "$OUT/texmf/tex/luatex/arclen/arclen.lua" "$A/"
cp "$OUT/texmf/tex/luatex/arclen/arclen/"*.lua "$A/arclen/"
(cd "$OUT" && rm -f arclen.zip && zip -qr arclen.zip arclen)
echo "ctan: $OUT/arclen.zip ($(unzip -l "$OUT/arclen.zip" | tail -1 | awk '{print $2}') files; manual typeset with the Lua engine)"
