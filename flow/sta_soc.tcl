# OpenSTA on one block of the SoC wrapper alone (flow/soc.tcl wrote its netlist),
# at the SDC's clock with the engine's port budget: a fifth of the period outside
# the block on each side of every input and output.
# Environment: LIBERTY, NETLIST, MODULE, PERIOD_NS.
read_liberty $::env(LIBERTY)
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
report_checks -path_delay max -digits 3
report_worst_slack -digits 3
