#!/usr/bin/env bash
# The RTL package for another DMAX: SRC_PKG (rtl/mcadsw_pkg.sv) with DMAX and
# DISP_BITS (bits of DMAX - 1, as params.hpp's bits_for) replaced, written to
# OUT_PKG. Used by the CMake build (MCADSW_DMAX) and by scripts/synth.sh.
#   scripts/rtl_pkg_dmax.sh DMAX SRC_PKG OUT_PKG
set -euo pipefail
dmax=${1:?usage: rtl_pkg_dmax.sh DMAX SRC_PKG OUT_PKG}; src=${2:?}; dst=${3:?}
[[ "$dmax" =~ ^[0-9]+$ ]] && [ "$dmax" -ge 1 ] || { echo "rtl_pkg_dmax: DMAX '$dmax' is not a positive integer" >&2; exit 2; }
bits=0; v=$((dmax - 1)); while [ "$v" -gt 0 ]; do bits=$((bits + 1)); v=$((v >> 1)); done
sed -E "s/(localparam int DMAX +)= [0-9]+;/\1= $dmax;/; s/(localparam int DISP_BITS +)= [0-9]+;/\1= $bits;/" \
  "$src" > "$dst.tmp"
grep -q "localparam int DMAX *= $dmax;" "$dst.tmp" && grep -q "localparam int DISP_BITS *= $bits;" "$dst.tmp" ||
  { rm -f "$dst.tmp"; echo "rtl_pkg_dmax: no DMAX or DISP_BITS line in $src" >&2; exit 1; }
# Rewritten only when it changes (the build's models depend on it).
if cmp -s "$dst.tmp" "$dst"; then rm -f "$dst.tmp"; else mv "$dst.tmp" "$dst"; fi
