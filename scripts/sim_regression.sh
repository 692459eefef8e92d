#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# The `make sim` regression: the Verilated engine on the bundled pairs (and a
# small crop, quick to trace with WAVES=1), every
# disparity compared with the reference; raw mode, the sub-pixel mode
# (16-bit output, docs/algorithm.md 12.6), the right view as base (12.1;
# no error figure: the bundled ground truth is the left view's) and the LR mode
# (12.2-12.5: output, mask and both scratch maps compared), and column-tiled
# input planes. Prints one row per case, writes
# BUILD/sim/summary.json, exits non-zero on any mismatch, timeout or error.
#   scripts/sim_regression.sh BUILD_DIR [CASE] [WAVES]
# CASE: run only that case; WAVES=1: also write BUILD/sim/CASE.fst and a
# gtkwave save file BUILD/sim/CASE.gtkw grouping the signals by block.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}; only=${2:-}; waves=${3:-0}
bin=$build/bin/mcadsw_sim
[ -x "$bin" ] || { echo "sim_regression: $bin is not built" >&2; exit 1; }
out=$build/sim; mkdir -p "$out"
data=$root/data

# name | set | pair | D | scale | extra options
cases=(
  "cif_tsukuba|cif|tsukuba|64|16|"
  "cif_venus|cif|venus|64|8|"
  "cif_teddy|cif|teddy|64|4|"
  "cif_cones|cif|cones|64|4|"
  "tsukuba|middlebury|tsukuba|16|16|"
  "venus|middlebury|venus|20|8|"
  "teddy|middlebury|teddy|60|4|"
  "cones|middlebury|cones|60|4|"
  "tsukuba_random_latency|middlebury|tsukuba|16|16|--random-latency 1"
  "teddy_crop|cif|teddy|64|4|--crop 100,100,74,38"
  "cif_teddy_sub|cif|teddy|64|4|--subpixel"
  "tsukuba_sub|middlebury|tsukuba|16|16|--subpixel"
  "venus_sub|middlebury|venus|20|8|--subpixel"
  "teddy_sub|middlebury|teddy|60|4|--subpixel"
  "cones_sub|middlebury|cones|60|4|--subpixel"
  "teddy_crop_sub_stride|cif|teddy|64|4|--crop 100,100,74,38 --subpixel --out-stride 1000 --random-latency 2"
  "cif_teddy_right|cif|teddy|64|4|--right"
  "tsukuba_right_sub|middlebury|tsukuba|16|16|--right --subpixel"
  "venus_right|middlebury|venus|20|8|--right"
  "teddy_right_sub|middlebury|teddy|60|4|--right --subpixel"
  "cones_right|middlebury|cones|60|4|--right"
  "cif_teddy_lr|cif|teddy|64|4|--lr"
  "cif_teddy_lr_sub|cif|teddy|64|4|--lr --subpixel"
  "tsukuba_lr|middlebury|tsukuba|16|16|--lr"
  "venus_lr|middlebury|venus|20|8|--lr"
  "teddy_lr|middlebury|teddy|60|4|--lr"
  "cones_lr_sub|middlebury|cones|60|4|--lr --subpixel"
  "teddy_crop_lr_sub_latency|cif|teddy|64|4|--crop 100,100,74,38 --lr --subpixel -T 3 --random-latency 4"
  # Column-tiled input planes (read bursts, docs/memory_map.md), at zero latency and with a
  # DDR-like memory (30 wait states, an AR at most every 8 clocks), raster for comparison.
  "cif_tsukuba_tiled|cif|tsukuba|64|16|--tiled"
  "cif_tsukuba_ddr|cif|tsukuba|64|16|--latency 30 --ar-interval 8"
  "cif_tsukuba_tiled_ddr|cif|tsukuba|64|16|--tiled --latency 30 --ar-interval 8"
  "cones_right_tiled|middlebury|cones|60|4|--right --tiled --tile-stride 1600 --random-latency 5"
  "teddy_crop_lr_tiled|cif|teddy|64|4|--crop 100,100,74,38 --lr --tiled --random-latency 6"
  # Disparities up to about 120 (data/cif_x2: 2x upscaled Teddy and Cones) at
  # D = the build's DMAX (64 by default, 128 with make sim DMAX=128).
  "cif_x2_teddy_dDMAX|cif_x2|teddy|DMAX|2|"
  "cif_x2_cones_dDMAX|cif_x2|cones|DMAX|2|"
  # VGA (640x480, data/vga_x2): cycles and frame rate of the wider frames.
  "vga_x2_teddy_dDMAX|vga_x2|teddy|DMAX|2|"
  # Raw camera frames rectified by the engine (docs/blocks/rectifier.md; data/raw:
  # cameras A, B, C made from the pairs above, their calibration files): the rectified planes,
  # validity bitmaps and depth compared; no error figure (the invalid code is no disparity).
  # B at zero latency is the speed bar's case (2.70 M cycles), tiled with the DDR-like memory
  # the second bar (2.95 M); C has invalid strips (sub-pixel: 0xFFFF there); the LR mode
  # with its marks (dR 255, dL flagged before the post stage; the code after it).
  "cif_teddy_rect_b|raw/B/cif|teddy|64|4|"
  "cif_teddy_rect_b_tiled_ddr|raw/B/cif|teddy|64|4|--tiled --latency 30 --ar-interval 8"
  "cif_teddy_rect_c_sub|raw/C/cif|teddy|64|4|--subpixel --step 8"
  "teddy_rect_a_right_s32|raw/A/middlebury|teddy|60|4|--right --step 32 --random-latency 7"
  "cif_teddy_rect_b_lr|raw/B/cif|teddy|64|4|--lr"
  "cif_teddy_rect_c_lr_sub|raw/C/cif|teddy|64|4|--lr --subpixel --random-latency 8"
)
# The build's DMAX (CMake MCADSW_DMAX), for the cases above that run at it.
dmax=$(awk -F= '/^MCADSW_DMAX:/ {print $2}' "$build/CMakeCache.txt" 2>/dev/null)
dmax=${dmax:-64}
for i in "${!cases[@]}"; do cases[$i]=${cases[$i]//DMAX/$dmax}; done

# A build without the rectifier (CMake MCADSW_RECT=OFF, make sim RECT=0) leaves out the
# rectified cases, and says so.
norect=$(awk -F= '/^MCADSW_RECT:/ {print $2}' "$build/CMakeCache.txt" 2>/dev/null)
selected=()
skipped=()
for c in "${cases[@]}"; do
  IFS='|' read -r name set pair d scale extra <<<"$c"
  if [ -n "$only" ] && [ "$only" != "$name" ]; then continue; fi
  if [ "$norect" = OFF ] && [ "${set#raw/}" != "$set" ]; then skipped+=("$name"); continue; fi
  selected+=("$c")
done
if [ ${#skipped[@]} -gt 0 ]; then
  echo "sim_regression: a build without the rectifier: ${#skipped[@]} rectified case(s) left out (${skipped[*]})"
  if [ ${#selected[@]} -eq 0 ]; then exit 0; fi
fi
if [ ${#selected[@]} -eq 0 ]; then
  echo "sim_regression: unknown case '$only'; cases:" >&2
  for c in "${cases[@]}"; do echo "  ${c%%|*}" >&2; done
  exit 2
fi

run_case() {
  IFS='|' read -r name set pair d scale extra <<<"$1"
  dir=$data/$set/$pair
  wave_opt=()
  if [ "$waves" = 1 ]; then wave_opt=(--waves "$out/$name.fst"); fi
  gt_opt=(--gt "$dir/gt.png" --scale "$scale" --masks "$dir")
  case " $extra " in *" --right "*) gt_opt=() ;; esac
  # A raw camera pair (data/raw/<camera>/<set>/<pair>): rectified with its calibration.
  case $set in raw/*) gt_opt=(--calib "$dir/calib.yml") ;; esac
  # shellcheck disable=SC2086
  "$bin" "$dir/left.png" "$dir/right.png" -d "$d" --name "$name" "${gt_opt[@]}" \
    --out "$out/$name.png" --json "$out/$name.json" "${wave_opt[@]}" $extra \
    > "$out/$name.log" 2> "$out/$name.err"
}
export -f run_case
export bin out data waves

echo "== make sim: Verilated engine vs reference, ${#selected[@]} case(s), 2 at a time (logs in $out) =="
status=0
printf '%s\n' "${selected[@]}" | xargs -P 2 -I{} bash -c 'run_case "$@"' _ {} || status=1

rows=()
for c in "${selected[@]}"; do
  name=${c%%|*}
  grep -qw BIT-EXACT "$out/$name.log" 2>/dev/null || status=1
  cat "$out/$name.log" 2>/dev/null || true
  grep -v '^  \.\.\.' "$out/$name.err" 2>/dev/null || true
  [ -f "$out/$name.json" ] && rows+=("$(cat "$out/$name.json")")
done
{ echo "["; (IFS=,; printf '%s\n' "${rows[*]}"); echo "]"; } > "$out/summary.json"
echo "summary: $out/summary.json"

if [ "$waves" = 1 ] && [ -n "$only" ]; then
  gtkw=$out/$only.gtkw
  # Open on the first block's preparation: from the first prep_start to the
  # first prep_done (times in ps, fstminer lists first occurrences), a tenth
  # more on each side, marker at prep_done. gtkwave shows 2^-zoom time units in
  # 200 pixels (calczoom()): zoom = -log2(span * 200 / 1000) for a 1000-pixel wave pane.
  eng=mcadsw_top.u_engine   # the engine inside the model's top (rtl/mcadsw_top.sv)
  first() { fstminer -d "$out/$only.fst" -m 1 2>/dev/null | awk -v s="TOP.$eng.$1" '!f && $2 == s {sub(/^#/, "", $1); print $1; f = 1}'; }
  t0=$(first prep_start); t1=$(first prep_done)
  window=""
  if [ -n "$t0" ] && [ -n "$t1" ]; then
    window=$(awk -v a="$t0" -v b="$t1" 'BEGIN {m = (b - a) / 10; s = a - m; if (s < 0) s = 0
      printf "[timestart] %d\n*%.6f %d\n", s, -log((b - a + 2 * m) / 5) / log(2), b}')
  fi
  # Full names as the FST holds them: vectors carry their range (mem_addr_o[31:0]).
  facs=$( (fst2vcd "$out/$only.fst" 2>/dev/null || true) | awk '$1 == "$enddefinitions" {exit}
    $1 == "$scope" {p[++n] = $3} $1 == "$upscope" {n--}
    $1 == "$var" {s = p[1]; for (i = 2; i <= n; i++) s = s "." p[i]; print s "." $5 ($6 != "$end" ? $6 : "")}')
  fac() { awk -v s="$1" '$0 == s || index($0, s "[") == 1 {print; exit}' <<<"$facs"; }
  {
    echo "[dumpfile] \"$out/$only.fst\""
    echo "[size] 1600 900"
    [ -n "$window" ] && echo "$window"
    for grp in "Registers (AXI4-Lite):mcadsw_top.u_regs:s_awvalid_i s_awready_o s_wvalid_i s_wready_o s_bvalid_o s_bready_i s_arvalid_i s_rvalid_o start_o irq_o" \
               "AXI4 master:mcadsw_top.u_axi_master:m_arvalid_o m_arready_i m_araddr_o m_arlen_o m_rvalid_i m_rlast_i m_awvalid_o m_awready_i m_awaddr_o m_awlen_o m_wvalid_o m_wready_i m_wlast_o m_bvalid_i wr_idle_o drain_i" \
               "Top:$eng:start_i busy_o done_o error_o mem_req_o mem_gnt_i mem_we_o mem_addr_o mem_rvalid_i mem_wr_idle_i" \
               "Scheduler:$eng.u_scheduler:prep_start_o prep_bank_o prep_done_i agg_bank_o job_valid_o job_ready_i job_row_o" \
               "Memory controller:$eng.u_mem_ctrl:rd_req_i rd_gnt_o rd_rvalid_o wr_req_i wr_gnt_o" \
               "Census left:$eng.u_census_l:state_q pix_valid_i pix_ready_o wcnt_q ki_q ring_free_i done_o" \
               "Census right:$eng.u_census_r:state_q pix_valid_i pix_ready_o wcnt_q ki_q ring_free_i done_o" \
               "Weight generator:$eng.u_weight_gen:state_q pix_valid_i pix_ready_o done_o r_q occ_q row_ready_o row_take_i" \
               "Cost aggregator:$eng.u_cost_agg:busy_q row_q d_q grp_q h2_valid_q disp_valid_o disp_grp_o" \
               "Depth FIFO:$eng.u_depth_fifo:count_q ready_q wr_req_o wr_gnt_i wr_addr_o wr_be_o" \
               "Post stage (LR):$eng.u_post:st_q y_q bx_q cx_q qc_q mem_req_o mem_gnt_i mem_we_o mem_addr_o"; do
      IFS=: read -r title scope sigs <<<"$grp"
      echo "@800200"; echo "-$title"; echo "@22"   # values in hex
      for s in $sigs; do
        f=$(fac "TOP.$scope.$s"); [ -n "$f" ] || { echo "sim_regression: no signal TOP.$scope.$s in the waves" >&2; exit 1; }
        echo "$f"
      done
      echo "@1000200"; echo "-$title"
    done
  } > "$gtkw"
  echo "waves: $out/$only.fst, one cycle = 10.526 ns (95 MHz); gtkwave save file $gtkw opens on the"
  echo "       first block's preparation${t1:+ (marker at prep_done, $(awk -v t="$t1" 'BEGIN {printf "%.1f us", t / 1e6}'))}; open with: make wave CASE=$only"
fi

if [ $status -ne 0 ]; then
  echo "make sim: FAILED (see the rows above)"; exit 1
fi
echo "make sim: all ${#selected[@]} case(s) bit-exact"
