# Power of the engine netlist (flow/power.py, `make power`): OpenSTA 2.0.17 with the
# OSU 0.18 um liberty's internal-power tables and every net's activity from the
# netlist simulation (sim/activity/netlist_activity.cpp). This OpenSTA has no
# read_vcd / read_saif, its set_power_activity -pins is broken (it calls a missing
# get_pins_error and skips output pins), and an activity set on a pin does not
# propagate through the logic; so the activity of every net is set on every pin of
# the net with sta::set_power_pin_activity, the command set_power_activity uses.
# Environment: LIBERTY, RAM_LIB, NETLIST, PERIOD_NS (the clock), RUNS (a list of
# "name activity-file period-factor"), OUT (results, one line each).
set out [open $::env(OUT) w]
read_liberty $::env(LIBERTY)
read_liberty $::env(RAM_LIB)
read_verilog $::env(NETLIST)
link_design mcadsw_engine
set period $::env(PERIOD_NS)
# Nothing but the simulation sets an activity: the input ports 0 (a global
# activity would override every pin's, measured: so none is set). A pin's activity
# counts only when set after the clock exists (measured), hence the clock first.
set_power_activity -input -activity 0.0 -duty 0.0
create_clock -name clk -period $period [get_ports clk_i]

set nets [get_nets *]
set cells [get_cells *]
puts $out "netlist nets [llength $nets] cells [llength $cells]"

# The block an instance belongs to: the first part of its flat name (u_census_l...),
# the engine's own cells have none.
proc block_of {name} {
  set dot [string first . $name]
  if {$dot < 0} { return top }
  return [string range $name 0 [expr {$dot - 1}]]
}

# Sets every net's activity (transitions per clock cycle) and duty from a file of
# "net NAME TRANSITIONS HIGH-CYCLES" lines after "cycles N". Returns the number
# of nets annotated and of pins.
proc annotate {file} {
  global nets
  set f [open $file r]
  gets $f first
  set cycles [lindex $first 1]
  array unset act
  while {[gets $f line] >= 0} {
    if {[lindex $line 0] ne "net"} continue
    set act([lindex $line 1]) [list [expr {double([lindex $line 2]) / $cycles}] \
                                   [expr {double([lindex $line 3]) / $cycles}]]
  }
  close $f
  set n 0
  set p 0
  foreach net $nets {
    set name [get_full_name $net]
    # The clock pins keep the clock's activity (two transitions a period).
    if {$name eq "clk_i" || ![info exists act($name)]} continue
    lassign $act($name) a d
    incr n
    foreach pin [get_pins -of_objects $net] {
      sta::set_power_pin_activity $pin $a $d
      incr p
    }
  }
  return [list $n $p]
}

foreach run $::env(RUNS) {
  lassign $run name file factor
  create_clock -name clk -period $period [get_ports clk_i]
  lassign [annotate $file] n p
  # The activities are per clock cycle: a longer period lowers every net's
  # transition density (the dynamic power's check, flow/power.py).
  create_clock -name clk -period [expr {$period * $factor}] [get_ports clk_i]
  set corner [sta::cmd_corner]
  puts $out "run $name period [expr {$period * $factor}] annotated_nets $n annotated_pins $p"
  puts $out "design $name [sta::design_power $corner]"
  array unset blk
  foreach c $cells {
    set b [block_of [get_full_name $c]]
    set ref [get_property $c ref_name]
    set seq [expr {[string match DFF* $ref] ? "seq" : [string match MCADSW_RAM* $ref] ? "macro" : "comb"}]
    set pw [sta::instance_power $c $corner]
    if {![info exists blk($b,$seq)]} { set blk($b,$seq) {0 0 0 0} }
    set acc {}
    foreach x $blk($b,$seq) y $pw { lappend acc [expr {$x + $y}] }
    set blk($b,$seq) $acc
  }
  foreach key [lsort [array names blk]] {
    lassign [split $key ,] b seq
    puts $out "block $name $b $seq $blk($key)"
  }
  flush $out
}
close $out
