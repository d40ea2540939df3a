#!/bin/sh
# tools/debian-source.sh PACKAGE DIR -- Debian's source of PACKAGE, Debian's
# patches applied, unpacked under DIR (apt-get source); prints the unpacked
# tree's path.  apt-get source needs a deb-src line: as root this adds one
# for the configured Debian mirror and suite when there is none (the
# entry whose suite is the release's codename) and runs apt-get update.
set -eu
PKG=$1
DIR=$2
me=debian-source.sh

have_source() { apt-cache showsrc "$PKG" 2>/dev/null | grep -q "^Package: $PKG\$"; }

add_deb_src() {
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  [ -n "$codename" ] || { echo "$me: no VERSION_CODENAME in /etc/os-release" >&2; exit 1; }
  line=
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    # deb822: one stanza per paragraph; its URIs, Suites, Components, Signed-By
    line=$(awk -v cn="$codename" '
      function flush() {
        if (types ~ /(^| )deb( |$)/ && (" " suites " ") ~ (" " cn " ") && uri != "") {
          opt = signed != "" ? "[signed-by=" signed "] " : ""
          print "deb-src " opt uri " " cn " " comps; found = 1; exit
        }
        types = suites = uri = comps = signed = ""
      }
      /^[ \t]*$/ { flush(); next }
      /^Types:/ { sub(/^Types:[ \t]*/, ""); types = $0 }
      /^Suites:/ { sub(/^Suites:[ \t]*/, ""); suites = $0 }
      /^URIs:/ { sub(/^URIs:[ \t]*/, ""); uri = $1 }
      /^Components:/ { sub(/^Components:[ \t]*/, ""); comps = $0 }
      /^Signed-By:/ { sub(/^Signed-By:[ \t]*/, ""); signed = $1 }
      END { if (!found) flush() }' "$f")
    [ -n "$line" ] && break
  done
  if [ -z "$line" ] && [ -f /etc/apt/sources.list ]; then
    # one-line format, options in [...] kept
    line=$(awk -v cn="$codename" '$1 == "deb" {
        i = 2; if ($2 ~ /^\[/) { while ($i !~ /\]$/) i++; i++ }
        if ($(i + 1) == cn) { $1 = "deb-src"; print; exit } }' /etc/apt/sources.list)
  fi
  [ -n "$line" ] || { echo "$me: no Debian '$codename' entry in the apt sources" >&2; exit 1; }
  echo "$me: adding to /etc/apt/sources.list.d/arclen-deb-src.list: $line" >&2
  echo "$line" > /etc/apt/sources.list.d/arclen-deb-src.list
  apt-get -o DPkg::Lock::Timeout=600 update -q >&2
}

if ! have_source; then
  if [ "$(id -u)" != 0 ]; then
    echo "$me: Debian's $PKG source is not available (no deb-src line);" \
      "run this as root once, or add a deb-src line and apt-get update" >&2
    exit 1
  fi
  add_deb_src
fi
command -v dpkg-source >/dev/null || {
  echo "$me: dpkg-source missing (Debian dpkg-dev)" >&2; exit 1; }

rm -rf "$DIR"
mkdir -p "$DIR"
if ! (cd "$DIR" && apt-get source -q "$PKG") >"$DIR/apt-source.log" 2>&1; then
  cat "$DIR/apt-source.log" >&2
  echo "$me: apt-get source $PKG failed" >&2
  exit 1
fi
tree=$(find "$DIR" -mindepth 1 -maxdepth 1 -type d | head -n 1)
[ -n "$tree" ] || { echo "$me: nothing unpacked in $DIR" >&2; exit 1; }
echo "$tree"
