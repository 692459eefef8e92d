#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Gate-level flow check on a small block (ctest gls_flow_small): synthesise
# tests/gls/small_block.sv with the project's Yosys/abc scripts onto the OSU018
# cells, simulate the netlist in Verilator with the arguments the engine's
# gate-level model uses (passed by CMake) against the RTL, cycle by cycle.
# It caught a Verilator 5.006 bug: without -fno-const-bit-op-tree, cell outputs
# of the multiplier were never assigned (5.052 passes with or without the flag).
#   tests/gls/small_gls.sh [VERILATOR ARGS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/scripts/tools.sh"  # the pinned Verilator first on PATH
lib=/usr/share/qflow/tech/osu018/osu018_stdcells.lib
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
period_ps=$(awk '/^set period/ {printf "%d", $3 * 1000}' "$root/constraints/mcadsw.sdc")
# As flow/synth_block.tcl: synth, the clock gates of flow/clock_gate.py (groups of
# 3 or more here), then the cells.
yosys -q -p "read_verilog -sv $root/tests/gls/small_block.sv; synth -top gls_small; write_json $work/ungated.json" \
  > "$work/yosys.log" 2>&1 || { cat "$work/yosys.log"; echo "small_gls: yosys failed" >&2; exit 1; }
python3 "$root/flow/clock_gate.py" "$work/ungated.json" "$work/gated.json" gls_small 3 "$work/gates.json"
yosys -q -p "read_json $work/gated.json; dfflibmap -liberty $lib;
  abc -D $period_ps -constr $root/constraints/abc_osu018.constr -liberty $lib -script $root/constraints/abc_osu018.script;
  setundef -zero; opt_clean -purge; rename gls_small gls_small_gl;
  write_verilog -noattr -noexpr -nohex -nodec $work/gl.v" >> "$work/yosys.log" 2>&1 || {
  cat "$work/yosys.log"; echo "small_gls: yosys failed" >&2; exit 1; }
# hold_q, hold_n_q and hold_r_q behind a gate each, pair_q not.
gates=$(grep -c '^ *LATCH ' "$work/gl.v" || true)
[ "$gates" = 3 ] || { cat "$work/gates.json"; echo "small_gls: $gates clock gates in the netlist, 3 expected" >&2; exit 1; }
verilator --binary --timing "$@" -Mdir "$work/obj" --top-module small_tb \
  "$root/tests/gls/small_tb.sv" "$root/tests/gls/small_block.sv" "$work/gl.v" "$root/sim/gls/osu018_cells.v" \
  > "$work/verilator.log" 2>&1 || { tail -20 "$work/verilator.log"; echo "small_gls: verilator failed" >&2; exit 1; }
"$work/obj/Vsmall_tb" | tee "$work/run.log"
grep -q "^PASS" "$work/run.log"
