#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Bad input to `make synth` and `make fpga` (flow/synth.py synth, fpga) gives
# one clear message and a non-zero exit, and leaves no summary.json of an earlier
# run behind as if it were the new result. No synthesis runs: the cases stop at
# the configuration check (gen_rtl_pkg), the tool checks, at elaboration (a few
# seconds) or at the first block (Yosys replaced by a stub that fails block runs).
# Then `make synth-check`'s checker on summaries within and over a budget, and the
# reading of the engine's endpoint slacks per instance (the rectifier's worst slack).
#   tests/synth/bad_input.sh [GEN_RTL_PKG]   (about 30 s; needs yosys, sta, the OSU018
#                                            liberty and gen_rtl_pkg, default build/bin/)
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
gen=${1:-${GEN_RTL_PKG:-$root/build/bin/gen_rtl_pkg}}
[ -x "$gen" ] || { echo "bad_input: no gen_rtl_pkg at $gen (cmake --build build --target gen_rtl_pkg)"; exit 1; }
# The interpreter itself (not a wrapper script: the no_yosys case runs it with a bare PATH).
py=$(python3 -c 'import sys; print(sys.executable)') || { echo "bad_input: python3 not found"; exit 1; }
driver=$root/flow/synth.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0

# expect NAME RC_WANTED REGEX -- CMD...: run CMD (OUT in the environment, the output
# directory, with stale result files $stale_files in it) and check exit code,
# message, and that the stale files are gone.
stale_files="summary.json mcadsw_engine_osu018.v"
expect() {
  local name=$1 want_rc=$2 regex=$3; shift 4
  local out=$work/out_$name
  mkdir -p "$out"
  local f
  for f in $stale_files; do echo '{"stale": true}' > "$out/$f"; done
  local t0=$SECONDS rc=0
  OUT=$out "$@" > "$work/$name.out" 2> "$work/$name.err" || rc=$?
  local ok=1
  if [ "$rc" != "$want_rc" ]; then echo "  exit $rc, wanted $want_rc"; ok=0; fi
  if ! grep -Eq "$regex" "$work/$name.err"; then echo "  stderr lacks /$regex/"; ok=0; fi
  for f in $stale_files; do
    if [ -e "$out/$f" ]; then echo "  stale $f left in OUT"; ok=0; fi
  done
  if [ "$ok" = 1 ]; then
    echo "ok   $name (exit $rc, $((SECONDS - t0)) s): $(grep -E "$regex" "$work/$name.err" | head -1)"
  else
    echo "FAIL $name"; sed 's/^/  stderr: /' "$work/$name.err" | tail -15; fails=$((fails + 1))
  fi
}
# synth ARGS...: the synthesis driver into $OUT with the generator.
synth() { "$py" "$driver" synth --out "$OUT" --gen-rtl-pkg "$gen" "$@"; }

# Unknown or unsupported DMAX (1 .. 128), checked by gen_rtl_pkg.
expect dmax_zero  2 "DMAX='0' is not supported: an integer from 1 to 128" -- synth --dmax 0
expect dmax_text  2 "DMAX='abc' is not supported" -- synth --dmax abc
expect dmax_above 2 "DMAX='129' is not supported" -- synth --dmax 129
expect dmax_neg   2 "DMAX='-4' is not supported" -- synth --dmax=-4
expect dmax_zeros 2 "DMAX='064' is not supported" -- synth --dmax 064
# PAR: 1, 2 or 4, and DMAX a multiple of it.
expect par_three  2 "PAR='3' is not supported: 1, 2 or 4" -- synth --par 3
expect par_text   2 "PAR='x' is not supported" -- synth --par x
expect par_dmax   2 "DMAX=18 is not a multiple of PAR=4" -- synth --dmax 18 --par 4
# The clock gating's group size (0: no gating).
expect gate_text  2 "clock-gate-min 'x' is not a non-negative integer" -- synth --clock-gate-min x
expect gate_neg   2 "clock-gate-min '-1' is not a non-negative integer" -- synth --clock-gate-min=-1
# No generator.
expect no_gen     2 "gen_rtl_pkg not found at $work/none" -- "$py" "$driver" synth --out "$work/out_no_gen" --gen-rtl-pkg "$work/none"

# make fpga (flow/synth.py fpga): the same checks (the same generator), before any synthesis.
stale_files="summary.json report.md"
fpga() { "$py" "$driver" fpga --out "$OUT" --gen-rtl-pkg "$gen" "$@"; }
expect fpga_dmax_zero 2 "fpga: gen_rtl_pkg: DMAX='0' is not supported: an integer from 1 to 128" -- fpga --dmax 0
expect fpga_dmax_text 2 "DMAX='x1' is not supported" -- fpga --dmax x1
expect fpga_par_three 2 "PAR='3' is not supported: 1, 2 or 4" -- fpga --par 3
expect fpga_par_dmax  2 "DMAX=10 is not a multiple of PAR=4" -- fpga --dmax 10 --par 4
expect fpga_par_two   2 "the FPGA target takes one disparity a step .PAR=1., not PAR=2" -- fpga --par 2
stale_files="summary.json mcadsw_engine_osu018.v"

# A missing tool: a PATH with everything the driver needs except yosys.
bin=$work/bin; mkdir -p "$bin"
for t in sta; do
  p=$(command -v "$t") && ln -sf "$p" "$bin/$t"
done
expect no_yosys 2 "'yosys' not found in PATH" -- env PATH="$bin" "$py" "$driver" synth --out "$work/out_no_yosys" --gen-rtl-pkg "$gen"

# A broken source: elaboration fails, the message names the file (Yosys's error).
rtl=$work/rtl; cp -r "$root/rtl" "$rtl"
sed -i '0,/endmodule/s/endmodule/  this is not verilog;\nendmodule/' "$rtl/mcadsw_depth_fifo.sv"
expect broken_source 1 "elaboration of mcadsw_engine failed" -- synth --rtl "$rtl"
grep -q "mcadsw_depth_fifo.sv" "$work/broken_source.err" ||
  { echo "FAIL broken_source: the message does not name mcadsw_depth_fifo.sv"; fails=$((fails + 1)); }

# A failing block: a Yosys stub that elaborates with the real Yosys and fails every
# block run with an error in the block's log.
real_yosys=$(command -v yosys)
cat > "$work/yosys_stub" <<STUB
#!/usr/bin/env bash
case "\$*" in
  *elab.tcl*) exec "$real_yosys" "\$@" ;;
  -V) exec "$real_yosys" -V ;;
esac
log=""; prev=""
for a in "\$@"; do [ "\$prev" = -l ] && log=\$a; prev=\$a; done
[ -n "\$log" ] && printf 'reading the design\nERROR: simulated failure of this block (tests/synth/bad_input.sh)\n' > "\$log"
exit 1
STUB
chmod +x "$work/yosys_stub"
expect failing_block 1 "block '[a-z_]+' \(module mcadsw_[a-z_]+\) failed" -- synth --yosys "$work/yosys_stub"
grep -q "simulated failure of this block" "$work/failing_block.err" ||
  { echo "FAIL failing_block: the log tail is not in the message"; fails=$((fails + 1)); }
grep -q "no summary.json written" "$work/failing_block.err" ||
  { echo "FAIL failing_block: no final line"; fails=$((fails + 1)); }

# make synth-check's checker (flow/synth.py check; a budget of its own, independent of
# constraints/budget.json's figures) on summaries over budget, and on one within it.
echo '{"nand2_eq_max": 563000, "wns_ns_min": 0, "memory_kB_max": 57.1, "clock_mhz": 95.0}' > "$work/budget.json"
echo '{"dmax": 64, "nand2_eq": 600000, "memory_kB": 57.0, "clock_mhz": 95.0, "wns_ns": -0.2, "worst_slack_ns": -0.2}' > "$work/over.json"
rc=0; "$py" "$driver" check --budget $work/budget.json --summary $work/over.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 1 ] && grep -q "FAILED  gates" "$work/check.out" && grep -q "FAILED  worst slack" "$work/check.out" &&
   ! grep -q "FAILED  on-chip memory" "$work/check.out"; then echo "ok   synth_check gates and slack over budget (exit 1)"
else echo "FAIL synth_check gates and slack over budget (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
echo '{"dmax": 64, "nand2_eq": 500000, "memory_kB": 57.2, "clock_mhz": 95.0, "wns_ns": 0, "worst_slack_ns": 0.3}' > "$work/mem.json"
rc=0; "$py" "$driver" check --budget $work/budget.json --summary $work/mem.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 1 ] && grep -q "FAILED  on-chip memory" "$work/check.out" && ! grep -q "FAILED  gates" "$work/check.out"; then
  echo "ok   synth_check memory over budget (exit 1)"
else echo "FAIL synth_check memory over budget (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
echo '{"dmax": 64, "nand2_eq": 500000, "memory_kB": 57.0, "clock_mhz": 95.0, "wns_ns": 0, "worst_slack_ns": 0.3}' > "$work/within.json"
rc=0; "$py" "$driver" check --budget $work/budget.json --summary $work/within.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 0 ]; then echo "ok   synth_check within budget"
else echo "FAIL synth_check within budget (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
# The engine within budget, its SoC wrapper not: the total over the gate budget, a
# wrapper block missing the clock.
echo '{"dmax": 64, "nand2_eq": 500000, "soc_total_nand2_eq": 570000, "soc_worst_slack_ns": -0.1, "memory_kB": 57.0, "clock_mhz": 95.0, "wns_ns": 0, "worst_slack_ns": 0.3}' > "$work/soc.json"
rc=0; "$py" "$driver" check --budget $work/budget.json --summary $work/soc.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 1 ] && grep -q "FAILED  gates with the SoC wrapper" "$work/check.out" &&
   grep -q "FAILED  SoC wrapper slack" "$work/check.out" && ! grep -q "FAILED  gates (NAND2" "$work/check.out"; then
  echo "ok   synth_check SoC wrapper over budget (exit 1)"
else echo "FAIL synth_check SoC wrapper over budget (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
# A budget that forbids asynchronous-read macros: a summary with one fails, one
# without the figure is an error (exit 2), one with none passes.
echo '{"nand2_eq_max": 563000, "wns_ns_min": 0, "memory_kB_max": 57.1, "async_read_macros_max": 0, "clock_mhz": 95.0}' > "$work/budget_async.json"
echo '{"dmax": 64, "nand2_eq": 500000, "memory_kB": 57.0, "async_read_macros": 1, "clock_mhz": 95.0, "wns_ns": 0, "worst_slack_ns": 0.3}' > "$work/async.json"
rc=0; "$py" "$driver" check --budget $work/budget_async.json --summary $work/async.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 1 ] && grep -q "FAILED  async-read macros" "$work/check.out" && ! grep -q "FAILED  on-chip memory" "$work/check.out"; then
  echo "ok   synth_check asynchronous-read macro (exit 1)"
else echo "FAIL synth_check asynchronous-read macro (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
rc=0; "$py" "$driver" check --budget $work/budget_async.json --summary $work/within.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 2 ] && grep -q "async_read_macros' missing" "$work/check.out"; then
  echo "ok   synth_check summary without the asynchronous-read count (exit 2)"
else echo "FAIL synth_check summary without the asynchronous-read count (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
sed 's/"async_read_macros": 1/"async_read_macros": 0/' "$work/async.json" > "$work/sync.json"
rc=0; "$py" "$driver" check --budget $work/budget_async.json --summary $work/sync.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 0 ] && grep -q "ok      async-read macros" "$work/check.out"; then echo "ok   synth_check no asynchronous-read macro"
else echo "FAIL synth_check no asynchronous-read macro (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
# A budget with the rectifier's limits: a summary without its figures is an
# error (exit 2); its gates, memory and slack each fail on their own; within passes.
echo '{"nand2_eq_max": 563000, "wns_ns_min": 0, "memory_kB_max": 57.1, "rect_nand2_eq_max": 60000, "rect_memory_kB_max": 4.0, "clock_mhz": 95.0}' > "$work/budget_rect.json"
rc=0; "$py" "$driver" check --budget $work/budget_rect.json --summary $work/within.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 2 ] && grep -q "rect_nand2_eq' missing" "$work/check.out"; then
  echo "ok   synth_check summary without the rectifier's figures (exit 2)"
else echo "FAIL synth_check summary without the rectifier's figures (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
rect_ok='"rect_nand2_eq": 59000, "rect_memory_kB": 4.0, "rect_worst_slack_ns": 0.1, "rect_async_read_macros": 0'
echo "{\"dmax\": 64, \"nand2_eq\": 500000, \"memory_kB\": 57.0, \"clock_mhz\": 95.0, \"wns_ns\": 0, \"worst_slack_ns\": 0.3, $rect_ok}" > "$work/rect_within.json"
rc=0; "$py" "$driver" check --budget $work/budget_rect.json --summary $work/rect_within.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 0 ] && grep -q "ok      rectifier gates" "$work/check.out"; then echo "ok   synth_check rectifier within budget"
else echo "FAIL synth_check rectifier within budget (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
for bad in '"rect_nand2_eq": 59000/"rect_nand2_eq": 60001/rectifier gates' \
           '"rect_memory_kB": 4.0/"rect_memory_kB": 4.1/rectifier memory' \
           '"rect_worst_slack_ns": 0.1/"rect_worst_slack_ns": -0.01/rectifier slack' \
           '"rect_async_read_macros": 0/"rect_async_read_macros": 1/rectifier async-read'; do
  from=${bad%%/*}; rest=${bad#*/}; to=${rest%%/*}; what=${rest#*/}
  sed "s|$from|$to|" "$work/rect_within.json" > "$work/rect_over.json"
  rc=0; "$py" "$driver" check --budget $work/budget_rect.json --summary $work/rect_over.json > "$work/check.out" 2>&1 || rc=$?
  if [ "$rc" = 1 ] && grep -q "FAILED  $what" "$work/check.out" && [ "$(grep -c 'FAILED  ' "$work/check.out")" = 1 ]; then
    echo "ok   synth_check $what over budget (exit 1)"
  else echo "FAIL synth_check $what over budget (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi
done
# The rectifier's slack is null when the engine's STA had no endpoint of one of its
# instances (flow/synth.py warns): an error (exit 2), not a pass.
sed 's|"rect_worst_slack_ns": 0.1|"rect_worst_slack_ns": null|' "$work/rect_within.json" > "$work/rect_null.json"
rc=0; "$py" "$driver" check --budget $work/budget_rect.json --summary $work/rect_null.json > "$work/check.out" 2>&1 || rc=$?
if [ "$rc" = 2 ] && grep -q "rect_worst_slack_ns' missing" "$work/check.out"; then
  echo "ok   synth_check rectifier slack null (exit 2)"
else echo "FAIL synth_check rectifier slack null (exit $rc)"; cat "$work/check.out"; fails=$((fails + 1)); fi

# The rectifier's worst slack is read from the engine's sta_endpoints.log (flow/sta.py
# endpoint_slack): every endpoint whose flattened name starts with the instance and a
# dot, u_rect not taking u_rect_mark's; the violating ones per block instance.
cat > "$work/sta_endpoints.log" <<'LOG'
max_delay/setup group clk

                                     Required   Actual
Endpoint                                Delay    Delay    Slack
---------------------------------------------------------------
u_rect_mark._7_/D (DFFPOSX1)            10.050   10.150   -0.100 (VIOLATED)
u_rect._100_/D (DFFPOSX1)               10.050    8.847    1.203 (MET)
u_rect.banks_0/WR_DATA[3] (MCADSW_RAM_S256_W16_A8_SYNC_WE)   10.000    3.000    7.000 (MET)
u_post._15412_/D (DFFPOSX1)             10.050   10.250   -0.200 (VIOLATED)
_2023_/D (DFFSR)                        10.180   10.490   -0.310 (VIOLATED)
mem_addr_o[31] (output)                  8.170    7.220    0.950 (MET)
u_rect_mark.clock_gate_0_and/B (AND2X2) 10.280    5.450    4.830 (MET)
LOG
got=$(cd "$root/flow" && "$py" -B -c 'import sys, sta
viol, inst = sta.endpoint_slack(sys.argv[1], ["u_rect", "u_rect_mark", "u_rect_check"])
print(sorted(viol.items()), sorted(inst.items()))' "$work/sta_endpoints.log" 2>&1)
want="[('top', (1, -0.31)), ('u_post', (1, -0.2)), ('u_rect_mark', (1, -0.1))] [('u_rect', (2, 1.203)), ('u_rect_check', (0, None)), ('u_rect_mark', (2, -0.1))]"
if [ "$got" = "$want" ]; then echo "ok   sta endpoint_slack per instance (the rectifier's worst slack)"
else echo "FAIL sta endpoint_slack per instance: got $got, wanted $want"; fails=$((fails + 1)); fi

if [ "$fails" -ne 0 ]; then echo "bad_input: $fails case(s) failed"; exit 1; fi
echo "bad_input: all cases passed"
