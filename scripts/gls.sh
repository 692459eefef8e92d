#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# make gls: gate-level simulation. The OSU 0.18 um netlist written by
# `make synth` (flow/synth.py) runs in the same Verilator harness as the RTL (models of the
# cells: sim/gls/osu018_cells.v; of the memory macros: sim/gls/mcadsw_ram_model.v)
# on small crops of Teddy, in the raw mode, in the LR mode and with the right view as base and
# sub-pixel output, and on a rectified crop (register map 1.2: camera C's raw Teddy views through
# its calibration's step-8 meshes, with invalid pixels); every disparity is compared with the
# reference (the harness's scoreboard; with rectification the rectified planes and validity
# bitmaps too) and the disparity map with the RTL's, byte for byte.
#
#   scripts/gls.sh            the netlist of `make synth` (DMAX = 64, build/synth)
#   DMAX=16 scripts/gls.sh    a reduced configuration (build/synth_dmax16; the harness is
#                             built for the same DMAX, as the netlist's package is)
#   FRAME=1 scripts/gls.sh    also a whole Middlebury frame (Tsukuba 384x288, D = 16,
#                             632k cycles: about 4 min at 3 kcycles/s) against the reference
# The netlist is synthesised first if it is missing (with BUILD_DIR/bin/gen_rtl_pkg,
# which make gls builds).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dmax=${DMAX:-64}
build=${BUILD_DIR:-$root/build}
if [ "$dmax" = 64 ]; then synth_dir=$build/synth; else synth_dir=$build/synth_dmax$dmax; fi
netlist=$synth_dir/mcadsw_engine_osu018.v
gls_build=$build/gls_dmax$dmax
out=$build/gls
d=$(( dmax < 16 ? dmax : 16 ))
crop=100,100,40,24
mkdir -p "$out"

if [ ! -f "$netlist" ]; then
  echo "gls: no netlist at $netlist, synthesising it (DMAX=$dmax)"
  python3 "$root/flow/synth.py" synth --dmax "$dmax" --out "$synth_dir" --build "$build"
fi
# The cell models cover the combinational cells and flip-flops only.
if grep -Eq '^\s*(TBUFX1|TBUFX2) ' "$netlist"; then
  echo "gls: the netlist uses a tri-state buffer, which sim/gls/osu018_cells.v does not model" >&2
  exit 1
fi

# Debian's Verilator 5.006 builds the gate-level model (docs/tool_notes.md section 2:
# 5.052, the RTL models' version, did not finish its inlining pass on the engine's
# netlist in 18 minutes, nor its scope pass with inlining off in 16).
vroot=/usr/share/verilator
[ -f "$vroot/verilator-config.cmake" ] || {
  echo "gls: Debian's Verilator missing at $vroot (run scripts/bootstrap.sh)" >&2; exit 1; }
echo "gls: building the gate-level model (Verilator $(/usr/bin/verilator --version | cut -d" " -f2), $gls_build)"
# -O1: the generated model of a netlist of ~400k cells takes far longer to
# compile at -O3 than it runs on a small crop.
cmake -S "$root" -B "$gls_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMCADSW_DMAX="$dmax" \
      -DMCADSW_VERILATOR_ROOT="$vroot" \
      -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DMCADSW_GLS_NETLIST="$netlist" -DMCADSW_BLOCK_BENCHES=none > /dev/null
start=$(date +%s)
cmake --build "$gls_build" --target mcadsw_sim_gls mcadsw_sim > "$out/build.log" 2>&1 || {
  tail -30 "$out/build.log"; echo "gls: build failed (log: $out/build.log)" >&2; exit 1; }
echo "gls: model built in $(( $(date +%s) - start )) s"

left=$root/data/cif/teddy/left.png
right=$root/data/cif/teddy/right.png
# gls_vs_rtl NAME CROP WHAT FLAGS...: the crop at D in one mode through the netlist
# and the RTL (each checked against the reference by the harness); their maps
# must be identical. pair_left=... pair_right=... before it: another pair than
# the bundled Teddy.
gls_vs_rtl() {
  local name=$1 crop=$2 what=$3; shift 3
  local l=${pair_left:-$left} r=${pair_right:-$right}
  echo "gls: Teddy crop $crop at D = $d, $what, netlist vs reference"
  "$gls_build/bin/mcadsw_sim_gls" "$l" "$r" -d "$d" --crop "$crop" "$@" \
      --name "gls_$name" --out "$out/gls_$name.png" --json "$out/gls_$name.json"
  "$gls_build/bin/mcadsw_sim" "$l" "$r" -d "$d" --crop "$crop" "$@" \
      --name "rtl_$name" --out "$out/rtl_$name.png" --json "$out/rtl_$name.json"
  if cmp -s "$out/gls_$name.png" "$out/rtl_$name.png"; then
    echo "gls: netlist and RTL maps ($what) are identical; both equal the reference"
  else
    echo "gls: netlist and RTL maps ($what) differ ($out/gls_$name.png, $out/rtl_$name.png)" >&2
    exit 1
  fi
}
gls_vs_rtl raw "$crop" "raw mode"
# The other modes at gate level: the right view as base (mirrored pass, a width
# with W % 4 = 2) with sub-pixel output (16-bit PNG), and the LR mode (three
# passes and the post stage: check, fill, median; the harness compares the mask
# plane with the reference too), sub-pixel, a width with W % 4 = 3.
gls_vs_rtl right_sub 100,100,42,24 "right view as base, sub-pixel" --right --subpixel
gls_vs_rtl lr_sub 100,100,43,20 "LR mode, sub-pixel, T = 2" --lr --subpixel -T 2
# The rectifier at gate level: camera C's raw views (data/raw/C/cif/teddy), step-8
# meshes, a 48x24 crop at 16,8 of the rectified frame that takes in the left view's
# invalid strips (left columns, top rows: invalid codes in the map, about 15k cycles).
raw_c=$root/data/raw/C/cif/teddy
pair_left=$raw_c/left.png pair_right=$raw_c/right.png \
  gls_vs_rtl rect_c 16,8,48,24 "rectified (camera C, step 8, invalid strips)" \
  --calib "$raw_c/calib.yml" --step 8
if [ "${FRAME:-0}" = 1 ]; then
  echo "gls: whole frame, Tsukuba 384x288 at D = 16, netlist vs reference (about 6 min)"
  mb=$root/data/middlebury/tsukuba
  "$gls_build/bin/mcadsw_sim_gls" "$mb/left.png" "$mb/right.png" -d 16 --name gls_tsukuba \
      --out "$out/gls_tsukuba.png" --json "$out/gls_tsukuba.json"
fi
