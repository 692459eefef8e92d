# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# OpenSTA on the assembled engine netlist prepared by flow/synth.py
# (mcadsw_engine_sta.v, mcadsw_ram.lib: the memory macros' timing from
# constraints/mcadsw_ram_timing.cfg), against constraints/mcadsw.sdc.
# Environment: LIBERTY, OUT_DIR, SDC. Reports on stdout (sta.log); every endpoint
# in OUT_DIR/sta_endpoints.log (3 digits); nets between blocks in OUT_DIR/sta_crossing.txt.
set lib $::env(LIBERTY)
set out $::env(OUT_DIR)
read_liberty $lib
read_liberty $out/mcadsw_ram.lib
read_verilog $out/mcadsw_engine_sta.v
link_design mcadsw_engine
read_sdc $::env(SDC)
# A clock gate's enable must settle before its latch opens (half a period after the
# edge): no time borrowed through a gate's latch, as flow/sta_alone.tcl holds a block
# timed alone to (OpenSTA would otherwise report such a path with slack 0). The
# flattened netlist names a block's gates <instance>.clock_gate_<k>_latch.
set gate_latches [get_pins -quiet *clock_gate_*_latch/D]
if {[llength $gate_latches] > 0} { set_max_time_borrow 0 $gate_latches }
report_checks -path_delay max -digits 3 -fields {fanout cap slew}
report_wns -digits 3
report_tns -digits 3
report_worst_slack -digits 3
# Every endpoint (flow/sta.py reads the violating ones per block instance, and the worst
# slack of the rectifier's instances, reported apart from the engine).
report_checks -path_delay max -group_count 100000 -format end -digits 3 > $out/sta_endpoints.log
# Nets between blocks (pins in more than one block instance, the top's own cells
# counted as one): driver, its cell, pins, worst transition at the driver. Each
# block's ABC buffered what it saw (its inputs driven by an INVX1, its outputs
# loaded with 0.02 pF); this shows what the assembled netlist makes of it.
set f [open $out/sta_crossing.txt w]
foreach net [get_nets *] {
  set drv ""; set blocks {}; set pins [get_pins -of_objects $net]
  foreach p $pins {
    set name [get_full_name $p]
    set b [expr {[string first . $name] < 0 ? "top" : [lindex [split $name .] 0]}]
    if {[lsearch -exact $blocks $b] < 0} { lappend blocks $b }
    if {[get_property $p direction] == "output"} { set drv $p }
  }
  if {[llength $blocks] > 1 && $drv != ""} {
    set t [expr {max([get_property $drv actual_rise_transition_max], [get_property $drv actual_fall_transition_max])}]
    puts $f "[get_full_name $net] [get_full_name $drv] [get_property [get_cells -of_objects $drv] ref_name] [llength $pins] $t"
  }
}
close $f
