# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# OpenSTA on one block alone, at the SDC's clock with the engine's port budget: a fifth
# of the period outside the block on each side of every input and output. Used for the
# SoC wrapper's blocks (flow/soc.py: mcadsw_regs, mcadsw_axi_master). (The rectifier,
# inside the engine, is timed with it: flow/sta_engine.tcl.)
# Environment: LIBERTY, NETLIST, MODULE, PERIOD_NS; RAM_LIB (optional: the liberty of the
# block's memory macros, flow/sta.py).
read_liberty $::env(LIBERTY)
if {[info exists ::env(RAM_LIB)]} { read_liberty $::env(RAM_LIB) }
read_verilog $::env(NETLIST)
link_design $::env(MODULE)
set period $::env(PERIOD_NS)
create_clock -name clk -period $period [get_ports clk_i]
set_clock_uncertainty 0.25 [get_clocks clk]
set_clock_transition 0.15 [get_clocks clk]
set inputs [delete_from_list [all_inputs] [get_ports {clk_i rst_ni}]]
set_input_delay  [expr 0.2 * $period] -clock clk $inputs
set_output_delay [expr 0.2 * $period] -clock clk [all_outputs]
set_input_transition 0.3 $inputs
set_driving_cell -lib_cell BUFX2 -pin Y $inputs
set_load 0.05 [all_outputs]
set_false_path -from [get_ports rst_ni]
# A clock gate's enable must settle before its latch opens (half a period after the
# edge), as every enable of the engine does: no time borrowed through a gate's latch
# (OpenSTA would otherwise report such a path with slack 0). Blocks without clock gates
# (the SoC wrapper's) have no such pins.
set gate_latches [get_pins -quiet clock_gate_*_latch/D]
if {[llength $gate_latches] > 0} { set_max_time_borrow 0 $gate_latches }
report_checks -path_delay max -digits 3 -fields {fanout cap slew}
report_wns -digits 3
report_worst_slack -digits 3
