#!/bin/sh
# tools/windows-expat.sh [DIR] -- expat for the MinGW cross-build of the
# document reader (arclen.svgdoc): a static libexpat.a and its headers in
# DIR (default build/windows/expat), compiled with x86_64-w64-mingw32-gcc
# from Debian's expat source package (tools/debian-source.sh) with the
# features of Debian's own build (DTDs, namespaces, 1024 context bytes).
# Static (XML_STATIC), so that svgdoc.dll needs no libexpat DLL beside it.
set -eu
OUT=${1:-build/windows/expat}
CROSS=${CROSS:-x86_64-w64-mingw32-}
WCC=${CROSS}gcc
if [ -f "$OUT/lib/libexpat.a" ] && [ -f "$OUT/include/expat.h" ]; then
  exit 0
fi

dir=$(sh "$(dirname "$0")/debian-source.sh" expat "$OUT/debian-source")
lib=$dir/expat/lib
if [ ! -f "$lib/xmlparse.c" ]; then
  echo "windows-expat.sh: no expat source in $dir" >&2
  exit 1
fi

# what CMake or configure would write; Windows's entropy is rand_s (_WIN32)
OBJ=$OUT/obj
mkdir -p "$OBJ" "$OUT/lib" "$OUT/include"
cat >"$OBJ/expat_config.h" <<'CONFIG'
#define BYTEORDER 1234
#define XML_CONTEXT_BYTES 1024
#define XML_DTD 1
#define XML_NS 1
#define HAVE_STDINT_H 1
#define HAVE_STDLIB_H 1
#define HAVE_STRING_H 1
CONFIG
for f in xmlparse xmlrole xmltok; do
  "$WCC" -std=gnu99 -O2 -DXML_STATIC -I"$OBJ" -I"$lib" -c "$lib/$f.c" -o "$OBJ/$f.o"
done
rm -f "$OUT/lib/libexpat.a"
"${CROSS}ar" rcs "$OUT/lib/libexpat.a" "$OBJ/xmlparse.o" "$OBJ/xmlrole.o" "$OBJ/xmltok.o"
cp "$lib/expat.h" "$lib/expat_external.h" "$OUT/include/"
echo "windows-expat.sh: $OUT/lib/libexpat.a ($(basename "$dir"))"
