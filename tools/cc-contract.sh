#!/bin/sh
# tools/cc-contract.sh -- a C compiler that contracts every a*b+c it can:
# the flags come last, so they win over the Makefile's -ffp-contract=off.
# CC=tools/cc-contract.sh builds arclen as GCC builds it by default on
# arm64 (and on x86-64 with -march=native): the spec suite must pass so.
# The real compiler is $CONTRACT_CC (default cc); -mfma is added where the
# compiler targets x86 and this processor has FMA.
real=${CONTRACT_CC:-cc}
extra="-ffp-contract=fast"
case "$($real -dumpmachine 2>/dev/null)" in
  x86_64*|i?86*)
    grep -qw fma /proc/cpuinfo 2>/dev/null && extra="$extra -mfma" ;;
esac
exec "$real" "$@" $extra
