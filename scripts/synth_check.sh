#!/usr/bin/env bash
# make synth-check (CI, after make test): `make synth` (hierarchical, DMAX = 64),
# then its summary against constraints/budget.json. Fails when the engine has more
# NAND2 equivalents than nand2_eq_max, a worst slack at the SDC clock below
# wns_ns_min (negative: 95 MHz missed), more on-chip memory than memory_kB_max, or
# (when the budget sets async_read_macros_max) more macros with an asynchronous read port.
#
#   scripts/synth_check.sh              synthesise (incrementally), then check
#   SUMMARY=file scripts/synth_check.sh check an existing summary only (no synthesis)
#   BUDGET=file                         another budget file
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
budget=${BUDGET:-$root/constraints/budget.json}
[ -f "$budget" ] || { echo "synth-check: no budget file $budget" >&2; exit 2; }

if [ -z "${SUMMARY:-}" ]; then
  [ -z "${DMAX:-}" ] || [ "$DMAX" = 64 ] || { echo "synth-check: the budget is for DMAX = 64 (got DMAX=$DMAX)" >&2; exit 2; }
  out=${OUT:-$root/build/synth}
  OUT=$out DMAX=64 "$root/scripts/synth.sh" || { echo "synth-check: FAILED: make synth did not complete (above)" >&2; exit 1; }
  summary=$out/summary.json
else
  summary=$SUMMARY
fi
[ -f "$summary" ] || { echo "synth-check: no summary $summary" >&2; exit 1; }

# Numbers of a flat JSON object ("key": number); the first occurrence is the top level.
# Empty when the key is absent (grep finding nothing is not an error here).
num() { { grep -o "\"$1\": *-\?[0-9][0-9.eE+-]*" "$2" || true; } | awk 'NR == 1' | sed 's/.*: *//'; }
# Memory: the engine's without the LR mode's post stage (reported apart, issue 17)
# where the summary has it, otherwise all of it.
nand2=$(num nand2_eq "$summary"); slack=$(num worst_slack_ns "$summary")
mem=$(num memory_kB_engine "$summary"); [ -n "$mem" ] || mem=$(num memory_kB "$summary")
clock=$(num clock_mhz "$summary"); dmax=$(num dmax "$summary")
max_nand2=$(num nand2_eq_max "$budget"); min_slack=$(num wns_ns_min "$budget"); max_mem=$(num memory_kB_max "$budget")
want_clock=$(num clock_mhz "$budget")
for v in nand2 mem slack max_nand2 min_slack max_mem; do
  [ -n "${!v}" ] || { echo "synth-check: '$v' missing from $summary or $budget" >&2; exit 2; }
done
[ -z "$dmax" ] || [ "$dmax" = 64 ] || { echo "synth-check: $summary is for DMAX = $dmax, the budget for DMAX = 64" >&2; exit 2; }

fail=0
check() {   # name value op limit unit explanation
  if awk -v v="$2" -v l="$4" -v op="$3" 'BEGIN {exit !((op == "<=") ? (v <= l) : (v >= l))}'; then
    printf 'synth-check: ok      %-26s %s %s (budget %s %s)\n' "$1" "$2" "$5" "$3" "$4"
  else
    printf 'synth-check: FAILED  %-26s %s %s, budget %s %s: %s\n' "$1" "$2" "$5" "$3" "$4" "$6" >&2
    fail=1
  fi
}
check "gates (NAND2 eq)" "$nand2" "<=" "$max_nand2" "" "the engine exceeds the gate budget (build/synth/report.md lists the blocks)"
check "worst slack at ${clock:-?} MHz" "$slack" ">=" "$min_slack" "ns" "timing is not met (build/synth/sta.log has the critical path, sta_endpoints.log every endpoint)"
check "on-chip memory (engine)" "$mem" "<=" "$max_mem" "kB" "the memories exceed the budget (build/synth/report.md lists them per module)"
# The whole IP (engine and SoC wrapper, mcadsw_top) where the summary has it.
soc_total=$(num soc_total_nand2_eq "$summary")
if [ -n "$soc_total" ]; then
  check "gates with the SoC wrapper" "$soc_total" "<=" "$max_nand2" "" "the engine with its AXI4-Lite registers and AXI4 master exceeds the gate budget (build/synth/report.md)"
fi
soc_slack=$(num soc_worst_slack_ns "$summary")
if [ -n "$soc_slack" ]; then
  check "SoC wrapper slack" "$soc_slack" ">=" "$min_slack" "ns" "the register block or the AXI4 master misses the clock (build/synth/soc/sta.log)"
fi
# Optional: macros with an asynchronous read port (no SRAM offers one).
max_async=$(num async_read_macros_max "$budget")
if [ -n "$max_async" ]; then
  async=$(num async_read_macros "$summary")
  [ -n "$async" ] || { echo "synth-check: 'async_read_macros' missing from $summary" >&2; exit 2; }
  check "async-read macros" "$async" "<=" "$max_async" "" "a memory is read asynchronously; real SRAMs register the address (build/synth/report.md, Memories)"
fi
if [ -n "$want_clock" ] && [ -n "$clock" ]; then
  awk -v a="$clock" -v b="$want_clock" 'BEGIN {exit !(a - b < 0.05 && b - a < 0.05)}' ||
    { echo "synth-check: FAILED  the SDC clock is $clock MHz, the budget is for $want_clock MHz" >&2; fail=1; }
fi
if [ "$fail" = 1 ]; then
  echo "synth-check: FAILED against $budget ($summary)" >&2
  exit 1
fi
echo "synth-check: passed ($summary within $budget)"
