# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Timing constraints of mcadsw_engine (OpenSTA, units of the OSU 0.18 um liberty:
# ns, pF). The clock is the paper's 95 MHz (Table III). The external memory
# port and the configuration are synchronous to the same clock; a fifth of the
# period is budgeted outside the engine on each side.
set period 10.526
create_clock -name clk -period $period [get_ports clk_i]
set_clock_uncertainty 0.25 [get_clocks clk]
set_clock_transition 0.15 [get_clocks clk]

set inputs [get_ports {cfg_* start_i mem_gnt_i mem_rvalid_i mem_rdata_i*}]
set_input_delay  [expr 0.2 * $period] -clock clk $inputs
set_output_delay [expr 0.2 * $period] -clock clk [all_outputs]
set_input_transition 0.3 $inputs
set_driving_cell -lib_cell BUFX2 -pin Y $inputs
set_load 0.05 [all_outputs]

# Asynchronous reset: not timed as a data path.
set_false_path -from [get_ports rst_ni]
