#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Storage inventory of the RTL blocks, measured by Yosys after `proc`:
# inferred memory bits and flip-flop bits per block instance of the engine
# (census left / right, weight generator, cost aggregator with its ping-pong
# buffer), against the paper's 21.3 kB. Takes a few minutes (the census
# buffer is still a flat register array). Usage: scripts/rtl_storage.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root/rtl"
dmax=$(awk '/localparam int DMAX /{gsub(";","",$5); print $5}' mcadsw_pkg.sv)
rows=()
measure() {  # name top chparams files...
  local name=$1 top=$2 chp=$3; shift 3
  local out tmp
  tmp=$(mktemp)
  yosys -q -p "read_verilog -sv mcadsw_pkg.sv $*; ${chp:+chparam $chp $top;} hierarchy -top $top; proc; opt_clean; flatten; tee -q -o $tmp stat -width" >/dev/null
  out=$(cat "$tmp"); rm -f "$tmp"
  local mem ff
  mem=$(awk '/Number of memory bits:/{print $5}' <<<"$out" | tail -1); mem=${mem:-0}
  ff=$(awk '$1 ~ /^\$(a|s)?dffe?_[0-9]+$/ {split($1,a,"_"); s += a[2]*$2} END{print s+0}' <<<"$out")
  rows+=("$name|$mem|$ff")
  echo "measured $name" >&2
}
measure "census (left, 48 cols)" mcadsw_census "" mcadsw_strip_stage.sv mcadsw_census.sv
measure "census (right, $((48 + dmax - 1)) cols)" mcadsw_census "-set COLS $((48 + dmax - 1))" \
  mcadsw_strip_stage.sv mcadsw_census.sv
measure "weight generator" mcadsw_weight_gen "" mcadsw_strip_stage.sv mcadsw_weight_gen.sv
measure "cost aggregator + ping-pong + WTA" mcadsw_cost_agg "" \
  mcadsw_sum_tree.sv mcadsw_tag_delay.sv mcadsw_vert_agg.sv mcadsw_pingpong.sv mcadsw_horz_agg.sv mcadsw_wta.sv mcadsw_cost_agg.sv
printf "| block | memory bits | flip-flop bits | total bits | kB |\n|---|---|---|---|---|\n"
tm=0; tf=0
for r in "${rows[@]}"; do
  IFS='|' read -r n m f <<<"$r"
  printf "| %s | %d | %d | %d | %.1f |\n" "$n" "$m" "$f" $((m + f)) "$(awk -v b=$((m + f)) 'BEGIN{print b/8/1024}')"
  tm=$((tm + m)); tf=$((tf + f))
done
printf "| **total** | %d | %d | %d | %.1f |\n" $tm $tf $((tm + tf)) "$(awk -v b=$((tm + tf)) 'BEGIN{print b/8/1024}')"
printf "| paper, Table III | | | | 21.3 |\n"
