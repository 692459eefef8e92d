# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# `make fpga` (flow/synth.py fpga): Yosys synth_xilinx for a 7-series part maps the
# top (mcadsw_top by default: the engine behind its AXI4-Lite registers; an IP
# core, so no I/O buffers or clock buffer) to LUTs, flip-flops, block RAMs, LUT
# RAMs and DSP48E1s; the cell counts go to OUT_DIR/stat.txt.
# Environment: PKG (the configuration's package), RTL_MODULES (module files,
# space-separated), RTL_DIR (the RTL folder: the `include of mcadsw_assert.svh from
# rtl/rect/ is found there), TOP, OUT_DIR.
set top $::env(TOP)
yosys read_verilog -sv -D SYNTHESIS -I$::env(RTL_DIR) $::env(PKG) {*}$::env(RTL_MODULES)
yosys hierarchy -check -top $top
yosys synth_xilinx -family xc7 -top $top -noiopad -noclkbuf
yosys tee -o $::env(OUT_DIR)/stat.txt stat
