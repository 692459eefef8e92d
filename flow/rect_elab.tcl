# Elaboration of the rectifier (issue 32, rtl/rect/) for `make synth`, which maps and
# times it apart from the engine (flow/rect.py): the engine's package, its FIFO (the
# writer's queue), the rectifier's package and modules (rtl/rect/rect.f), the memory
# macro's ports; written as RTLIL for flow/synth_block.tcl.
# Environment: TOP (mcadsw_rect, mcadsw_rect_mark or mcadsw_rect_check), PKG (the engine's
# package file), RTL_DIR, RTL_MODULES (the rectifier's
# files, its package first, paths), RAM_MODEL, OUT_IL.
yosys read_verilog -sv -I$::env(RTL_DIR) $::env(PKG) $::env(RTL_DIR)/mcadsw_fifo.sv {*}$::env(RTL_MODULES)
yosys read_verilog -lib $::env(RAM_MODEL)
yosys hierarchy -check -top $::env(TOP)
yosys write_rtlil $::env(OUT_IL)
