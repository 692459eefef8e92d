# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# The assembled netlist as OpenSTA reads it (flow/synth.py): flattened, nets split
# to bits, wire-to-wire assigns replaced by BUFX2. Every instantiated module must be
# defined, a cell or a macro, with matching port widths (hierarchy -check; a
# resized port is an error flow/synth.py finds in the log).
# Environment: RAM_MODEL, LIBERTY, NETLIST, OUT_V; TOP (optional, default mcadsw_engine).
yosys read_verilog -lib $::env(RAM_MODEL)
yosys read_liberty -lib $::env(LIBERTY)
yosys read_verilog $::env(NETLIST)
set top [expr {[info exists ::env(TOP)] ? $::env(TOP) : "mcadsw_engine"}]
yosys hierarchy -check -top $top
yosys flatten
# Single-bit nets, so that bits of one wire that alias another bit merge
# instead of becoming buffers (a write enable fanned out to 384 aliases did).
yosys splitnets
yosys opt_clean -purge
yosys insbuf -buf BUFX2 A Y
yosys write_verilog -noattr -noexpr -nohex -nodec $::env(OUT_V)
