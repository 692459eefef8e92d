#!/usr/bin/env bash
# The SoC wrapper's own logic (issue 19), for `make synth`: the AXI4-Lite
# register block (mcadsw_regs) and the AXI4 master (mcadsw_axi_master) that
# mcadsw_axi_top puts around the engine, each flattened and mapped onto the same
# OSU 0.18 um cells as the engine (dfflibmap, ABC with the liberty), without the
# engine flow's buffering script; area in NAND2 equivalents. Their timing is not
# analysed (the engine's STA is of mcadsw_top).
#
#   scripts/synth_soc.sh RTL_DIR OUT_DIR LIBERTY DMAX PAR
# Writes OUT_DIR/yosys.log, regs_area.txt, master_area.txt and nand2.txt
# ("<regs> <master>" NAND2 eq).
set -euo pipefail
[ $# -eq 5 ] || { echo "usage: $0 RTL_DIR OUT_DIR LIBERTY DMAX PAR" >&2; exit 2; }
rtl=$1; out=$2; lib=$3; dmax=$4; par=$5
yosys_bin=${YOSYS:-yosys}
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
abc -liberty $lib
opt_clean
tee -q -o $out/$1_area.txt stat -liberty $lib
YS
}
{
  map mcadsw_regs "$rtl/mcadsw_regs.sv"
  map mcadsw_axi_master "$rtl/mcadsw_axi_master.sv"
} > "$out/soc.ys"
"$yosys_bin" -q -l "$out/yosys.log" "$out/soc.ys" > /dev/null
nand2_area=$(awk '/cell *\(NAND2X1\)/ {c=1} c && /area/ {gsub(/[^0-9.]/, "", $0); print; exit}' "$lib")
eq() { awk -v a="$nand2_area" '/Chip area for module/ {printf "%d", $NF / a + 0.5}' "$out/$1_area.txt"; }
echo "$(eq mcadsw_regs) $(eq mcadsw_axi_master)" > "$out/nand2.txt"
