#!/usr/bin/env bash
# The RTL package for another configuration: SRC_PKG (rtl/mcadsw_pkg.sv) with
# DMAX, DISP_BITS (bits of DMAX - 1, as params.hpp's bits_for) and PAR (the
# disparities a step, default 1) replaced, written to OUT_PKG. Used by the CMake
# build (MCADSW_DMAX, MCADSW_PAR) and by scripts/synth.sh.
#   scripts/rtl_pkg_dmax.sh DMAX SRC_PKG OUT_PKG [PAR]
set -euo pipefail
dmax=${1:?usage: rtl_pkg_dmax.sh DMAX SRC_PKG OUT_PKG [PAR]}; src=${2:?}; dst=${3:?}; par=${4:-1}
[[ "$dmax" =~ ^[0-9]+$ ]] && [ "$dmax" -ge 1 ] || { echo "rtl_pkg_dmax: DMAX '$dmax' is not a positive integer" >&2; exit 2; }
case "$par" in 1|2|4) ;; *) echo "rtl_pkg_dmax: PAR '$par' is not 1, 2 or 4" >&2; exit 2 ;; esac
[ $((dmax % par)) -eq 0 ] || { echo "rtl_pkg_dmax: DMAX $dmax is not a multiple of PAR $par" >&2; exit 2; }
bits=0; v=$((dmax - 1)); while [ "$v" -gt 0 ]; do bits=$((bits + 1)); v=$((v >> 1)); done
sed -E "s/(localparam int DMAX +)= [0-9]+;/\1= $dmax;/; s/(localparam int DISP_BITS +)= [0-9]+;/\1= $bits;/;
        s/(localparam int PAR +)= [0-9]+;/\1= $par;/" "$src" > "$dst.tmp"
grep -q "localparam int DMAX *= $dmax;" "$dst.tmp" && grep -q "localparam int DISP_BITS *= $bits;" "$dst.tmp" &&
  grep -q "localparam int PAR *= $par;" "$dst.tmp" ||
  { rm -f "$dst.tmp"; echo "rtl_pkg_dmax: no DMAX, DISP_BITS or PAR line in $src" >&2; exit 1; }
# Rewritten only when it changes (the build's models depend on it).
if cmp -s "$dst.tmp" "$dst"; then rm -f "$dst.tmp"; else mv "$dst.tmp" "$dst"; fi
