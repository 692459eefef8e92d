// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Assertions of the RTL, one text for simulation and formal (the pattern of
// lowRISC's prim_assert.sv). Include inside a module that has clk_i and rst_ni:
//
//   `MCADSW_ASSERT(name, property)   an invariant of the block: holds in every
//                                    cycle out of reset, whatever the inputs do
//   `MCADSW_ASSUME(name, property)   what the block expects of its inputs: an
//                                    assertion in simulation (the surroundings
//                                    must keep it), an assumption in `make formal`
//
// Simulation (Verilator --assert, Icarus): an immediate assertion at every clock
// edge out of reset that stops with "<instance>: <name>". `make formal` (Yosys
// read_verilog -formal -DFORMAL, scripts/formal.sh): the same property as an
// assert / assume of the proof. Synthesis (-DSYNTHESIS without FORMAL): nothing.
// Line coverage (make coverage) leaves these blocks out: they are not design.
// The names say what holds; Icarus 11 takes no labels on immediate assertions,
// so the name travels in the message.
//
// MCADSW_CHECKS is defined where the assertions are live (simulation, formal):
// bookkeeping a check needs (a counter of beats, a copy of last cycle's input)
// goes inside `ifdef MCADSW_CHECKS, so synthesis never sees it.
`ifndef MCADSW_ASSERT_SVH
`define MCADSW_ASSERT_SVH

`ifdef FORMAL
  `define MCADSW_CHECKS
  `define MCADSW_ASSERT(__name, __prop) \
    always @(posedge clk_i or negedge rst_ni) if (rst_ni) assert (__prop);
  `define MCADSW_ASSUME(__name, __prop) \
    always @(posedge clk_i or negedge rst_ni) if (rst_ni) assume (__prop);
`elsif SYNTHESIS
  `define MCADSW_ASSERT(__name, __prop)
  `define MCADSW_ASSUME(__name, __prop)
`else
  `define MCADSW_CHECKS
  `define MCADSW_ASSERT(__name, __prop) \
    /* verilator coverage_off */ \
    always @(posedge clk_i or negedge rst_ni) if (rst_ni) assert (__prop) else $error("%m: %s", `"__name`"); \
    /* verilator coverage_on */
  `define MCADSW_ASSUME(__name, __prop) `MCADSW_ASSERT(__name, __prop)
`endif

`endif
