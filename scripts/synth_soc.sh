#!/usr/bin/env bash
# The SoC wrapper's own logic (issue 19), for `make synth`: the AXI4-Lite
# register block (mcadsw_regs) and the AXI4 master (mcadsw_axi_master) that
# mcadsw_top puts around the engine, each flattened and mapped as the
# engine's blocks are (scripts/synth_block.sh: OSU 0.18 um flip-flops, ABC with
# the buffering script and -constr), area in NAND2 equivalents, then timed alone
# by OpenSTA at the SDC's clock with the engine's port budget (a fifth of the
# period outside the block on each side of every input and output).
#
#   scripts/synth_soc.sh RTL_DIR OUT_DIR LIBERTY DMAX PAR
# Writes OUT_DIR/yosys.log, <module>_area.txt, <module>.v, sta.log and nand2.txt
# ("<regs NAND2 eq> <master NAND2 eq> <worst slack ns of the two>").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -eq 5 ] || { echo "usage: $0 RTL_DIR OUT_DIR LIBERTY DMAX PAR" >&2; exit 2; }
rtl=$1; out=$2; lib=$3; dmax=$4; par=$5
yosys_bin=${YOSYS:-yosys}
sdc=$root/constraints/mcadsw.sdc
period_ns=$(awk '/^set period/ {print $3}' "$sdc")
period_ps=$(awk -v p="$period_ns" 'BEGIN {printf "%d", p * 1000}')
mkdir -p "$out"
rm -f "$out/nand2.txt"
map() {   # module file...
  cat <<YS
design -reset
read_verilog -sv $rtl/mcadsw_pkg.sv ${*:2}
YS
  [ "$1" = mcadsw_regs ] && echo "chparam -set DMAX $dmax -set PAR $par mcadsw_regs"
  cat <<YS
synth -top $1 -flatten
dfflibmap -liberty $lib
abc -D $period_ps -constr $root/constraints/abc_osu018.constr -liberty $lib -script $root/constraints/abc_osu018.script
setundef -zero
opt_clean -purge
tee -q -o $out/$1_area.txt stat -liberty $lib
splitnets
opt_clean -purge
insbuf -buf BUFX2 A Y
write_verilog -noattr -noexpr -nohex -nodec $out/$1.v
YS
}
{
  map mcadsw_regs "$rtl/mcadsw_regs.sv"
  map mcadsw_axi_master "$rtl/mcadsw_axi_master.sv"
} > "$out/soc.ys"
"$yosys_bin" -q -l "$out/yosys.log" "$out/soc.ys" > /dev/null
nand2_area=$(awk '/cell *\(NAND2X1\)/ {c=1} c && /area/ {gsub(/[^0-9.]/, "", $0); print; exit}' "$lib")
eq() { awk -v a="$nand2_area" '/Chip area for module/ {printf "%d", $NF / a + 0.5}' "$out/$1_area.txt"; }

# OpenSTA, each module alone.
: > "$out/sta.log"
worst=""
for m in mcadsw_regs mcadsw_axi_master; do
  cat > "$out/sta_$m.tcl" <<TCL
read_liberty $lib
read_verilog $out/$m.v
link_design $m
set period $period_ns
create_clock -name clk -period \$period [get_ports clk_i]
set_clock_uncertainty 0.25 [get_clocks clk]
set_clock_transition 0.15 [get_clocks clk]
set inputs [delete_from_list [all_inputs] [get_ports {clk_i rst_ni}]]
set_input_delay  [expr 0.2 * \$period] -clock clk \$inputs
set_output_delay [expr 0.2 * \$period] -clock clk [all_outputs]
set_input_transition 0.3 \$inputs
set_driving_cell -lib_cell BUFX2 -pin Y \$inputs
set_load 0.05 [all_outputs]
set_false_path -from [get_ports rst_ni]
report_checks -path_delay max -digits 3
report_worst_slack -digits 3
TCL
  echo "== $m" >> "$out/sta.log"
  sta -no_splash -exit "$out/sta_$m.tcl" >> "$out/sta.log" 2>&1
  s=$(awk '/^worst slack/ {v = $NF} END {print v}' "$out/sta.log")
  [ -n "$s" ] || { echo "synth_soc: no slack from OpenSTA for $m ($out/sta.log)" >&2; exit 1; }
  if [ -z "$worst" ] || awk -v a="$s" -v b="$worst" 'BEGIN {exit !(a < b)}'; then worst=$s; fi
done
echo "$(eq mcadsw_regs) $(eq mcadsw_axi_master) $worst" > "$out/nand2.txt"
