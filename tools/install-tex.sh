#!/bin/sh
# tools/install-tex.sh [TEXMFHOME] -- make install-tex: arclen for TeX in
# the TDS layout, under TEXMFHOME (default: kpsewhich's TEXMFHOME):
#   tex/lualatex/arclen/arclen.sty              \usepackage{arclen}
#   tex/generic/arclen/tikzlibraryarclen.code.tex   \usetikzlibrary{arclen}
#   tex/luatex/arclen/arclen.lua, arclen/*.lua  require "arclen", "arclen.path", ...
#   metapost/arclen/arclen.mp                   input arclen;
#   scripts/arclen/arclen/core.so               the C core (Lua 5.3), for
#                                               --shell-escape runs, if built
# kpathsea maps require "arclen.path" to arclen/path.lua and "arclen" to
# arclen.lua (not arclen/init.lua), hence the two places of the Lua files.
cd "$(dirname "$0")/.." || exit 2
T=${1:-$(kpsewhich -var-value TEXMFHOME 2>/dev/null)}
[ -n "$T" ] || { echo "install-tex: no TEXMFHOME (give TEXMFHOME=DIR)" >&2; exit 2; }
set -e
install -d "$T/tex/lualatex/arclen" "$T/tex/generic/arclen" "$T/tex/luatex/arclen/arclen" \
  "$T/metapost/arclen"
install -m 644 tex/arclen.sty "$T/tex/lualatex/arclen/"
install -m 644 tex/tikzlibraryarclen.code.tex "$T/tex/generic/arclen/"
install -m 644 lua/arclen/init.lua "$T/tex/luatex/arclen/arclen.lua"
for f in lua/arclen/*.lua; do
  case "$f" in */init.lua|*/cli.lua|*/luatex.lua) ;; *) install -m 644 "$f" "$T/tex/luatex/arclen/arclen/" ;; esac
done
install -m 644 mp/arclen.mp "$T/metapost/arclen/"
if [ -f build/5.3/arclen/core.so ]; then
  install -d "$T/scripts/arclen/arclen"
  install -m 755 build/5.3/arclen/core.so "$T/scripts/arclen/arclen/"
  core="and the C core (scripts/arclen/arclen/core.so, for --shell-escape runs)"
else
  core="without the C core (make LUA=5.3 first to add it for --shell-escape runs)"
fi
echo "install-tex: arclen installed in $T $core"
if [ -f "$T/ls-R" ]; then
  echo "install-tex: $T has an ls-R file: run  mktexlsr $T  so that kpathsea sees the new files"
else
  echo "install-tex: $T has no ls-R file: kpathsea searches it directly, no mktexlsr needed"
fi
