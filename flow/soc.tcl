# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# The SoC wrapper's own logic (mcadsw_top's AXI4-Lite register block mcadsw_regs
# and AXI4 master mcadsw_axi_master), each flattened and mapped as the engine's
# blocks are (flow/synth_block.tcl: OSU 0.18 um flip-flops, ABC with the buffering
# script and -constr), then prepared for OpenSTA (flow/sta_alone.tcl times each alone).
# One Yosys process for both, as they have always run (ABC's result depends on the
# names Yosys has handed out before).
# Environment: PKG, RTL_DIR (the modules' folder), DMAX, PAR, OUT_DIR, PERIOD_PS,
# LIBERTY, CONSTRAINTS. Writes OUT_DIR/<module>_area.txt and <module>.v.
set out $::env(OUT_DIR)
set lib $::env(LIBERTY)
set con $::env(CONSTRAINTS)
foreach m {mcadsw_regs mcadsw_axi_master} {
  yosys design -reset
  yosys read_verilog -sv $::env(PKG) $::env(RTL_DIR)/$m.sv
  if {$m eq "mcadsw_regs"} { yosys chparam -set DMAX $::env(DMAX) -set PAR $::env(PAR) mcadsw_regs }
  yosys synth -top $m -flatten
  yosys dfflibmap -liberty $lib
  yosys abc -D $::env(PERIOD_PS) -constr $con/abc_osu018.constr -liberty $lib -script $con/abc_osu018.script
  yosys setundef -zero
  yosys opt_clean -purge
  yosys tee -q -o $out/${m}_area.txt stat -liberty $lib
  yosys splitnets
  yosys opt_clean -purge
  yosys insbuf -buf BUFX2 A Y
  yosys write_verilog -noattr -noexpr -nohex -nodec $out/$m.v
}
