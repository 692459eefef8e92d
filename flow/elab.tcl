# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Elaboration of the engine core for `make synth` (flow/synth.py runs it in the
# RTL directory): the package and the modules of rtl/mcadsw.f, the memory macro's
# ports, the top's DMAX and PAR, the hierarchy checked; written as RTLIL, from
# which flow/synth.py lists and renames the blocks.
# Environment: PKG (package file), RTL_MODULES (module files, space-separated),
# RAM_MODEL (sim/gls/mcadsw_ram_model.v), DMAX, PAR, OUT_IL.
yosys read_verilog -sv $::env(PKG) {*}$::env(RTL_MODULES)
yosys read_verilog -lib $::env(RAM_MODEL)
yosys chparam -set DMAX $::env(DMAX) mcadsw_engine
yosys chparam -set PAR $::env(PAR) mcadsw_engine
yosys hierarchy -check -top mcadsw_engine
yosys write_rtlil $::env(OUT_IL)
