// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The RTL of the MCADSW engine: every tool reads this list (CMake/Verilator,
// Yosys, Icarus, the formal, mutation, FPGA and synthesis flows; scripts/rtl_files.sh
// prints it as paths). One file a line, relative to this folder, the package
// first; `verilator -f mcadsw.f` and `iverilog -c mcadsw.f` work from rtl/.
// A configuration other than DMAX 64 / PAR 1 replaces mcadsw_pkg.sv with its own
// (make sim-build, make synth DMAX=<n> PAR=<p>). A build without the rectifier
// (package RECT = 0) reads rect/mcadsw_rect_none.sv instead of the rect/ modules
// below (scripts/rtl_files.sh --no-rect).
mcadsw_pkg.sv
rect/mcadsw_rect_pkg.sv
mcadsw_axi_master.sv
mcadsw_census.sv
mcadsw_cfg_check.sv
mcadsw_cost_agg.sv
mcadsw_depth_fifo.sv
mcadsw_clock_gate.sv
mcadsw_engine.sv
mcadsw_fetch.sv
mcadsw_fifo.sv
mcadsw_frame_ctrl.sv
mcadsw_horz_agg.sv
mcadsw_mem_ctrl.sv
mcadsw_pass_cfg.sv
mcadsw_pingpong.sv
mcadsw_port_mux.sv
mcadsw_post.sv
mcadsw_post_check.sv
mcadsw_post_fill.sv
mcadsw_regs.sv
mcadsw_scheduler.sv
mcadsw_strip_stage.sv
mcadsw_sum_tree.sv
mcadsw_tag_delay.sv
mcadsw_top.sv
mcadsw_vert_agg.sv
mcadsw_weight_gen.sv
mcadsw_win_geom.sv
mcadsw_win_reader.sv
mcadsw_wta.sv
rect/mcadsw_rect_load.sv
rect/mcadsw_rect_nodes.sv
rect/mcadsw_rect_sample.sv
rect/mcadsw_rect_write.sv
rect/mcadsw_rect_port.sv
rect/mcadsw_rect_mark.sv
rect/mcadsw_rect_check.sv
rect/mcadsw_rect.sv
rect/mcadsw_rectifier.sv
