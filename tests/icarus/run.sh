#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Second simulator: the same small pair through Verilator (mcadsw_sim --dump)
# and through Icarus Verilog (4-state, tests/icarus/tb_mcadsw_engine.sv) from the
# memory image the C++ harness wrote; the disparity planes and the counters
# must be identical, and no output may be X after reset. Runs the raw mode,
# the sub-pixel mode (16-bit output plane) and the right view as base with
# sub-pixel output (mirrored pass), and the LR mode with sub-pixel output (three
# passes; the output and mask planes are compared), and the right view as base
# from column-tiled input planes (read bursts), and a rectified frame (register
# map 1.2): camera C's raw Teddy views (data/raw/C/cif/teddy) through its
# calibration's step-8 meshes, a 32x16 crop at 16,8 of the rectified frame that
# takes in the left view's invalid strips (its left columns and top rows), so
# the output plane holds invalid codes (255), whole words and words mixed with
# valid disparities. The memory image holds the raw planes and the meshes; the
# rectified planes and validity bitmaps the engine writes are not in the dump,
# so only through the disparity plane (the harness compares them with the
# reference on the Verilator side).
#   tests/icarus/run.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
work=${KEEP_DIR:-$(mktemp -d)}; [ -n "${KEEP_DIR:-}" ] || trap 'rm -rf "$work"' EXIT; mkdir -p "$work"
left=$root/data/cif/teddy/left.png
right=$root/data/cif/teddy/right.png
crop=${CROP:-150,120,22,12}
d=${D:-10}

cd "$root/rtl"
mods=$("$root/scripts/rtl_files.sh" --no-pkg .)
iverilog -g2012 -I. -o "$work/tb" mcadsw_pkg.sv $mods "$root/tests/icarus/tb_mcadsw_engine.sv" 2> "$work/iverilog.log" || {
  cat "$work/iverilog.log"; echo "icarus: compile failed" >&2; exit 1; }
raw=$root/data/raw/C/cif/teddy
for mode in raw subpixel right_subpixel lr_subpixel right_tiled rect_crop; do
  run=$work/$mode; mkdir -p "$run"
  in=("$left" "$right" -d "$d" --crop "$crop")
  case $mode in
    raw) flags=() ;;
    subpixel) flags=(--subpixel) ;;
    lr_subpixel) flags=(--subpixel --lr) ;;
    right_tiled) flags=(--right --tiled) ;;
    rect_crop)  # ~7.3k cycles: about 25 s of Icarus
      in=("$raw/left.png" "$raw/right.png" -d 16 --crop "${RECT_CROP:-16,8,32,16}")
      flags=(--calib "$raw/calib.yml" --step 8) ;;
    *) flags=(--subpixel --right) ;;
  esac
  "$build/bin/mcadsw_sim" "${in[@]}" "${flags[@]}" --dump "$run" > "$run/verilator.log"
  tail -1 "$run/verilator.log"
  # shellcheck disable=SC2046
  vvp -n "$work/tb" +DIR="$run" $(cat "$run/config.txt") | tee "$run/vvp.log"
  grep -q "^FAIL" "$run/vvp.log" && exit 1
  [ -f "$run/icarus_out.hex" ] || { echo "icarus: no output ($mode)" >&2; exit 1; }
  if ! cmp -s "$run/icarus_out.hex" "$run/verilator_out.hex"; then
    diff "$run/icarus_out.hex" "$run/verilator_out.hex" | head; echo "icarus: $mode output planes differ" >&2; exit 1
  fi
  if ! cmp -s "$run/icarus_counters.txt" "$run/verilator_counters.txt"; then
    cat "$run/icarus_counters.txt" "$run/verilator_counters.txt"; echo "icarus: $mode counters differ" >&2; exit 1
  fi
  echo "icarus ($mode): output plane ($(wc -l < "$run/icarus_out.hex") words) and counters identical to Verilator's: $(cat "$run/icarus_counters.txt")"
done
