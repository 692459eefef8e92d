#!/usr/bin/env bash
# The `make sim` regression: the Verilated engine on the bundled pairs (and a
# small crop, quick to trace with WAVES=1), every
# disparity compared with the reference. Prints one row per case, writes
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
)

selected=()
for c in "${cases[@]}"; do
  IFS='|' read -r name set pair d scale extra <<<"$c"
  if [ -n "$only" ] && [ "$only" != "$name" ]; then continue; fi
  selected+=("$c")
done
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
  # shellcheck disable=SC2086
  "$bin" "$dir/left.png" "$dir/right.png" -d "$d" --name "$name" --gt "$dir/gt.png" --scale "$scale" \
    --masks "$dir" --out "$out/$name.png" --json "$out/$name.json" "${wave_opt[@]}" $extra \
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
  grep -q MATCH "$out/$name.log" 2>/dev/null && ! grep -q MISMATCH "$out/$name.log" || status=1
  cat "$out/$name.log" 2>/dev/null || true
  grep -v '^  \.\.\.' "$out/$name.err" 2>/dev/null || true
  [ -f "$out/$name.json" ] && rows+=("$(cat "$out/$name.json")")
done
{ echo "["; (IFS=,; printf '%s\n' "${rows[*]}"); echo "]"; } > "$out/summary.json"
echo "summary: $out/summary.json"

if [ "$waves" = 1 ] && [ -n "$only" ]; then
  gtkw=$out/$only.gtkw
  {
    echo "[dumpfile] \"$out/$only.fst\""
    for grp in "Top:mcadsw_top:start_i busy_o done_o error_o mem_req_o mem_gnt_i mem_we_o mem_addr_o mem_rvalid_i" \
               "Scheduler:mcadsw_top.u_scheduler:prep_start_o prep_bank_o prep_done_i agg_bank_o job_valid_o job_ready_i job_row_o" \
               "Memory controller:mcadsw_top.u_mem_ctrl:rd_req_i rd_gnt_o rd_rvalid_o wr_req_i wr_gnt_o" \
               "Census left:mcadsw_top.u_census_l:state_q pix_valid_i pix_ready_o done_o" \
               "Census right:mcadsw_top.u_census_r:state_q pix_valid_i pix_ready_o done_o" \
               "Weight generator:mcadsw_top.u_weight_gen:state_q pix_valid_i pix_ready_o done_o" \
               "Cost aggregator:mcadsw_top.u_cost_agg:busy_q row_q d_q grp_q h2_valid_q disp_valid_o disp_grp_o" \
               "Depth FIFO:mcadsw_top.u_depth_fifo:count_q ready_q wr_req_o wr_gnt_i wr_addr_o wr_be_o"; do
      IFS=: read -r title scope sigs <<<"$grp"
      echo "@800200"; echo "-$title"; echo "@28"
      for s in $sigs; do echo "TOP.$scope.$s"; done
      echo "@1000200"; echo "-$title"
    done
  } > "$gtkw"
  echo "waves: $out/$only.fst (gtkwave save file $gtkw; open with: make wave CASE=$only)"
fi

if [ $status -ne 0 ]; then
  echo "make sim: FAILED (see the rows above)"; exit 1
fi
echo "make sim: all ${#selected[@]} case(s) bit-exact"
