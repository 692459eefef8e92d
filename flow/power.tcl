# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Power of the engine netlist (flow/power.py, `make power`): OpenSTA 2.0.17 with the
# OSU 0.18 um liberty's internal-power tables, each cell evaluated at the activity
# its outputs had in the netlist simulation (sim/activity/netlist_activity.cpp).
#
# Why cell by cell: this OpenSTA (Debian, 2019) has no read_vcd / read_saif; an
# activity set on a pin (sta::set_power_pin_activity) only partly reaches the power
# figures (measured: the switching power came out 59 mW where the nets' own
# capacitances and simulated transitions give 187 mW), and its activity
# propagation crashes on the clock-gated netlist (a segmentation fault in
# design_power, with or without the gates). A global activity skips the
# propagation: for each cell, the global activity is set to the mean activity and
# duty of the nets its outputs drive (flip-flops: of D and Q), then
# sta::instance_power gives its internal power (the liberty's tables at the cell's
# slews and loads, times that activity), switching (1/2 C V^2 of its output nets)
# and leakage. Clock pins keep the clock's activity (two transitions a period).
#
# Clock gates (flow/clock_gate.py): NETLIST is a power view in which the gated
# flip-flops are clocked by clk_i (flow/power.py writes it; OpenSTA charges a clock
# pin the full clock either way). GATES lists each gated flip-flop and each gate's
# AND with its gated clock net; their clock part (their power at activity 0) is
# scaled by the fraction r of cycles the gate opened (gated clock transitions / 2 a
# cycle): P = P_cell - P_zero (1 - r). The gated nets' switching (C V^2 f r) is
# flow/power.py's.
#
# Environment: LIBERTY, RAM_LIB (empty: none), NETLIST, GATES, PERIOD_NS, RUNS (a
# list of "name activity-file period-factor"), OUT. Output lines: netlist, gated,
# then per run: run (annotated cells), block (name, block, seq|comb|macro,
# internal, switching, leakage, total), correction (what gating took off),
# clock_pins (the flip-flops' clock part after gating).
set out [open $::env(OUT) w]
read_liberty $::env(LIBERTY)
if {$::env(RAM_LIB) ne ""} { read_liberty $::env(RAM_LIB) }
read_verilog $::env(NETLIST)
link_design mcadsw_engine
set period $::env(PERIOD_NS)
# The clock, and every other input port clocked by it: a cell whose inputs come
# only from ports gets no clocked arrival otherwise, and OpenSTA then ignores the
# global activity for it (its default input activity, about 0 W: measured, the
# switching of such cells went missing).
proc clock {period} {
  create_clock -name clk -period $period [get_ports clk_i]
  set inputs {}
  foreach port [all_inputs] {
    if {[get_full_name $port] ne "clk_i"} { lappend inputs $port }
  }
  set_input_delay 0.0 -clock clk $inputs
}
clock $period
set corner [sta::cmd_corner]

set cells [get_cells *]
puts $out "netlist nets [llength [get_nets *]] cells [llength $cells]"

# The block of an instance: the first part of its flat name (u_census_l...); the
# engine's own cells have none.
proc block_of {name} {
  set dot [string first . $name]
  if {$dot < 0} { return top }
  return [string range $name 0 [expr {$dot - 1}]]
}
proc is_seq {ref} { return [expr {[string match DFF* $ref] || $ref eq "LATCH"}] }

# Gated cells: "flop|gate INSTANCE GATED-NET" lines.
array set gclk {}
set nflop 0
set f [open $::env(GATES) r]
while {[gets $f line] >= 0} {
  lassign $line kind inst net
  set gclk($inst) $net
  set gated_net($net) 1
  if {$kind eq "flop"} { incr nflop }
}
close $f
puts $out "gated flops $nflop gates [array size gated_net]"

# Per cell: its name, reference, block, kind and the nets whose activity it takes
# (outputs; a flip-flop's D and Q).
set info {}
foreach c $cells {
  set n [get_full_name $c]
  set ref [get_property $c ref_name]
  set nets {}
  foreach pin [get_pins -of_objects $c] {
    set dir [get_property $pin direction]
    if {$dir eq "output" || ([string match DFF* $ref] && [string match */D [get_full_name $pin]])} {
      set net [get_nets -of_objects $pin]
      if {$net ne ""} { lappend nets [get_full_name $net] }
    }
  }
  set kind [expr {[is_seq $ref] ? "seq" : [string match MCADSW_RAM* $ref] ? "macro" : "comb"}]
  lappend info [list $c $n $kind $nets]
}

# Activity 0: the clock part of every cell that gating scales.
sta::set_power_global_activity 0.0 0.0
foreach e $info {
  lassign $e c n kind nets
  if {$kind eq "seq" || [info exists gclk($n)]} { set zero($n) [sta::instance_power $c $corner] }
}

foreach run $::env(RUNS) {
  lassign $run name file factor
  array unset act
  set fh [open $file r]
  gets $fh first
  set cycles [lindex $first 1]
  while {[gets $fh line] >= 0} {
    if {[lindex $line 0] ne "net"} continue
    set act([lindex $line 1]) [list [expr {double([lindex $line 2]) / $cycles}] \
                                   [expr {double([lindex $line 3]) / $cycles}]]
  }
  close $fh
  foreach net [array names gated_net] {
    set open($net) [expr {[info exists act($net)] ? [lindex $act($net) 0] / 2.0 : 1.0}]
  }
  # The activities are per clock cycle: a longer period lowers every density
  # (flow/power.py checks that the dynamic power halves at twice the period).
  clock [expr {$period * $factor}]
  array unset blk
  set annotated 0
  set missing 0
  set corr 0.0
  set clock_pins 0.0
  foreach e $info {
    lassign $e c n kind nets
    set a 0.0
    set d 0.0
    set k 0
    foreach net $nets {
      if {[info exists act($net)]} {
        lassign $act($net) x y
        set a [expr {$a + $x}]
        set d [expr {$d + $y}]
        incr k
      } else {
        incr missing
      }
    }
    if {$k > 0} {
      set a [expr {$a / $k}]
      set d [expr {$d / $k}]
      incr annotated
    }
    sta::set_power_global_activity $a $d
    set pw [sta::instance_power $c $corner]
    set r [expr {[info exists gclk($n)] ? $open($gclk($n)) : 1.0}]
    if {[info exists zero($n)]} {
      # The zero run is at the base period; its dynamic part scales with the clock.
      lassign $zero($n) zi zs
      set zi [expr {$zi / $factor}]
      set zs [expr {$zs / $factor}]
      if {[string match DFF* [get_property $c ref_name]]} {
        set clock_pins [expr {$clock_pins + $zi * $r}]
      }
      if {$r < 1.0} {
        lassign $pw i s l
        set i [expr {$i - $zi * (1.0 - $r)}]
        set s [expr {$s - $zs * (1.0 - $r)}]
        set corr [expr {$corr + ($zi + $zs) * (1.0 - $r)}]
        set pw [list $i $s $l [expr {$i + $s + $l}]]
      }
    }
    set key "[block_of $n],$kind"
    if {![info exists blk($key)]} { set blk($key) {0 0 0 0} }
    set acc {}
    foreach x $blk($key) y $pw { lappend acc [expr {$x + $y}] }
    set blk($key) $acc
  }
  puts $out "run $name period [expr {$period * $factor}] annotated_cells $annotated missing_nets $missing"
  puts $out "correction $name $corr"
  puts $out "clock_pins $name $clock_pins"
  foreach key [lsort [array names blk]] {
    lassign [split $key ,] b kind
    puts $out "block $name $b $kind $blk($key)"
  }
  flush $out
}
close $out
