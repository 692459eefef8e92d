# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# One block of `make synth` (flow/synth.py runs one Yosys process per block, a
# pool of them at a time): the block's module from the elaborated design (every
# module derived with the top's parameters, block modules renamed by flow/synth.py),
# its sub-modules flattened into it, memories listed and mapped onto the
# MCADSW_RAM macro (constraints/macro_map.v), OSU 0.18 um flip-flops, ABC with the
# buffering script and -constr (constraints/abc_osu018.constr: block inputs and
# flip-flop outputs modelled as driven by an INVX1, outputs loaded with 0.02 pF,
# so ABC builds buffer trees on high-fanout nets, including those that enter the
# block through a port).
# Clock gating (CLOCK_GATE_MIN > 0): flow/clock_gate.py turns each group of at
# least CLOCK_GATE_MIN enable flip-flops sharing clock and enable into flip-flops
# on a clock gated by a latch and an AND gate (OSU 0.18 um has no clock-gate cell).
# Environment: MODULE (the block module; mcadsw_engine for the top's own logic),
# BLACKBOXES (for the top: the block modules, of which only the ports are kept),
# ELAB_IL, OUT_DIR, PERIOD_PS, LIBERTY, CONSTRAINTS (the constraints/ folder),
# CLOCK_GATE_MIN (0: no gating).
# Writes in OUT_DIR: clock_gates.json (with gating), memories_list.txt, memories_dump.txt, registers_dump.txt,
# area.txt (stat -liberty) and netlist.v.tmp (the block module alone:
# write_verilog skips black boxes; flow/synth.py renames it netlist.v).
set module $::env(MODULE)
set out $::env(OUT_DIR)
set lib $::env(LIBERTY)
set con $::env(CONSTRAINTS)
yosys read_rtlil $::env(ELAB_IL)
foreach bb $::env(BLACKBOXES) { yosys blackbox $bb }
yosys hierarchy -check -top $module
yosys synth -run :fine
yosys flatten
# Sub-modules are flattened into the block; drop their now unused definitions.
yosys hierarchy -top $module
# Memories: listed, then replaced by black-box macros.
yosys tee -q -o $out/memories_list.txt select -list t:\$mem_v2
yosys tee -q -o $out/memories_dump.txt dump t:\$mem_v2
# Registers of 64 bits or more (data, not control: image, census, weight and cost
# words in flip-flops), listed so that no buffer hides in flip-flops.
yosys tee -q -o $out/registers_dump.txt dump t:\$*dff* r:WIDTH>=64 %i
yosys techmap -map $con/macro_map.v t:\$mem_v2
yosys synth -run fine:
if {$::env(CLOCK_GATE_MIN) > 0} {
  yosys write_json $out/ungated.json
  yosys log [exec python3 [file join [file dirname $con] flow clock_gate.py] $out/ungated.json \
      $out/gated.json $module $::env(CLOCK_GATE_MIN) $out/clock_gates.json]
  yosys design -reset
  yosys read_json $out/gated.json
  file delete $out/ungated.json $out/gated.json
}
# Latches (the RTL's clock gates) onto the library's LATCH (constraints/latch_map.v).
yosys techmap -map $con/latch_map.v t:\$_DLATCH_N_ t:\$_DLATCH_P_
yosys dfflibmap -liberty $lib
yosys abc -D $::env(PERIOD_PS) -constr $con/abc_osu018.constr -liberty $lib -script $con/abc_osu018.script
yosys setundef -zero
yosys opt_clean -purge
yosys tee -q -o $out/area.txt stat -liberty $lib
yosys write_verilog -noattr -noexpr -nohex -nodec $out/netlist.v.tmp
