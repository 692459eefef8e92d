#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# make formal: bounded proofs of the control blocks' properties (formal/*_props.sv)
# with Yosys's SAT solver: every assertion holds in every cycle of every trace of
# DEPTH cycles from reset (bounded model check, `sat -seq DEPTH -prove-asserts
# -set-assumes -set-init-zero`: the registers start at 0, their reset values).
# Temporal induction does not close for these properties without invariants
# on the blocks' internal state (tried: `sat -tempinduct`, base case proven to
# 11-12 cycles, the induction step fails), so the depth is the guarantee.
#   scripts/formal.sh [BUILD_DIR]            all checks; BUILD_DIR/formal/summary.json
#   scripts/formal.sh [BUILD_DIR] --selftest each check against a mutant of its block
#                                            that breaks one property: must FAIL
#   ONLY="frame_ctrl ..." scripts/formal.sh ...  only these checks (names below); no
#                                            summary.json is written
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}; mode=${2:-}
out=$build/formal; mkdir -p "$out"
command -v yosys > /dev/null || { echo "formal: yosys missing (run scripts/bootstrap.sh)" >&2; exit 1; }

# name | RTL files (the block first, then its submodules) | depth | mutant for
# --selftest (sed expression on the block's file)
checks=(
  "mem_ctrl|mcadsw_mem_ctrl.sv|10|s/assign write_sel = hold_q ? hold_wr_q : wr_req_i;/assign write_sel = hold_q ? hold_wr_q : wr_req_i \&\& !any_rd;/"
  "axi_master|mcadsw_axi_master.sv|10|s/assign contig     = s_addr == ob_next_q \&\& s_addr\[11:0\] != 12'd0;/assign contig     = s_addr == ob_next_q;/"
  "depth_fifo|mcadsw_depth_fifo.sv|8|s/if (desc_push_i) tail_q <= PB'((32'(tail_q) + 1) % ROWSQ);/if (desc_push_i) tail_q <= tail_q;/"
  "cost_agg|mcadsw_cost_agg.sv mcadsw_vert_agg.sv mcadsw_pingpong.sv mcadsw_horz_agg.sv mcadsw_wta.sv mcadsw_sum_tree.sv|28|s/    else if (bank_full) wbank_q <= !wbank_q;/    else if (bank_full) wbank_q <= wbank_q;/"
  "frame_ctrl|mcadsw_frame_ctrl.sv|24|s/state_q != StCheck \&\& state_d == StIdle) done_d = 1'b1;/state_q != StCheck \&\& state_d != StCheck) done_d = 1'b1;/"
)

run_check() {  # name "rtl_files" depth [mutant_sed]
  local name=$1 depth=$3 mut=${4:-} log=$out/$1.log f
  local -a files=($2)
  local file=${files[0]} src=$root/rtl/${files[0]} subs=""
  for f in "${files[@]:1}"; do subs+=" $root/rtl/$f"; done
  if [ -n "$mut" ]; then
    src=$out/$name.mutant.sv
    sed "$mut" "$root/rtl/$file" > "$src"
    if cmp -s "$src" "$root/rtl/$file"; then echo "formal: the $name mutant does not apply" >&2; return 2; fi
    log=$out/$name.mutant.log
  fi
  yosys -q -l "$log" -p "read_verilog -sv -formal -DFORMAL -DSYNTHESIS -I $root/formal -I $root/rtl $root/rtl/mcadsw_pkg.sv $src$subs $root/formal/${name}_props.sv
    prep -top ${name}_props; async2sync; flatten; opt -fast
    sat -seq $depth -prove-asserts -set-assumes -set-init-zero -verify" > /dev/null 2>&1
}

rows=(); status=0
only=${ONLY:-}
for o in $only; do
  known=0   # bash alone: a pipe into grep -q can fail on a match under pipefail (SIGPIPE)
  for c in "${checks[@]}"; do [ "${c%%|*}" = "$o" ] && known=1; done
  [ $known = 1 ] || { echo "formal: no check named '$o'" >&2; exit 2; }
done
for c in "${checks[@]}"; do
  IFS='|' read -r name file depth mut <<<"$c"
  [ -z "$only" ] || [[ " $only " == *" $name "* ]] || continue
  t0=$(date +%s)
  if [ "$mode" = --selftest ]; then
    rm -f "$out/$name.mutant.log"
    rc=0
    run_check "$name" "$file" "$depth" "$mut" || rc=$?
    if [ "$rc" = 0 ]; then
      echo "formal selftest: $name mutant PASSED the proof: the properties miss it" >&2; status=1
    elif [ "$rc" = 2 ]; then
      echo "formal selftest: $name mutant not applied: its sed expression no longer matches rtl/$file" >&2; status=1
    elif ! grep -q "model found: FAIL" "$out/$name.mutant.log"; then
      echo "formal selftest: $name mutant: no counterexample (log $out/$name.mutant.log)" >&2; status=1
    else echo "formal selftest: $name mutant fails the proof with a counterexample, as it must ($(( $(date +%s) - t0 )) s)"; fi
    continue
  fi
  if run_check "$name" "$file" "$depth"; then res=proven; else res=FAILED; status=1; fi
  secs=$(( $(date +%s) - t0 ))
  checks_n=$(grep -c "Import proof for assert" "$out/$name.log" || true)
  echo "formal: $name: $res for every trace of $depth cycles from reset ($checks_n assertion checks, assertions x cycles; $secs s; log $out/$name.log)"
  rows+=("$name	$res	$depth	$checks_n	$secs")
done
if [ "$mode" != --selftest ] && [ -z "$only" ]; then
  printf '%s\n' "${rows[@]}" | python3 -c '
import json, sys
keys = ("check", "result", "bmc_depth", "assertion_checks", "seconds")
rows = [dict(zip(keys, line.rstrip("\n").split("\t"))) for line in sys.stdin if line.strip()]
for r in rows:
    for k in keys[2:]:
        r[k] = int(r[k])
json.dump(rows, sys.stdout, indent=2)
print()' > "$out/summary.json"
  echo "formal: summary $out/summary.json"
fi
exit $status
