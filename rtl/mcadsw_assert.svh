// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Assertions of the RTL, one text for simulation and formal (the pattern of
// lowRISC's prim_assert.sv). Include inside a module that has clk_i and rst_ni:
//
//   `MCADSW_ASSERT(name, property)   an invariant of the block: holds in every
//                                    cycle out of reset, whatever the inputs do
//   `MCADSW_ASSUME(name, property)   what the block expects of its inputs: an
//                                    assertion in simulation (the surroundings
//                                    must keep it); in `make formal` an assumption
//                                    when the block is the proof's block, an
//                                    assertion when it is one of its submodules
//   `MCADSW_COVER(name, property)    an event the proof of this block must reach
//                                    (cover); nothing in simulation or synthesis
//
// Simulation (Verilator --assert, Icarus): an immediate assertion at every clock
// edge out of reset that stops with "<instance>: <name>". `make formal`
// (SymbiYosys, formal/*.sby): the property in every step out of reset (an
// always @* check, so the last step of a trace is checked too); Yosys reads the
// proof's block with -DMCADSW_FORMAL_TOP and its submodules without it, so a submodule's
// expectation of its inputs is proven from the block that drives them, never
// assumed (ZipCPU's convention); covers are the proof's block's only. The
// choice is made again at each include (each module includes this file), so
// only that part stands outside the include guard. Synthesis (-DSYNTHESIS
// without FORMAL): nothing. Line coverage (make coverage) leaves these blocks
// out: they are not design. The names say what holds; Icarus 11 takes no
// labels on immediate assertions, so the name travels in the message.
//
// MCADSW_CHECKS is defined where the assertions are live (simulation, formal):
// bookkeeping a check needs (a counter of beats, a copy of last cycle's input)
// goes inside `ifdef MCADSW_CHECKS, so synthesis never sees it.
`ifndef MCADSW_ASSERT_SVH
`define MCADSW_ASSERT_SVH

`ifdef FORMAL
  `define MCADSW_CHECKS
  `define MCADSW_ASSERT(__name, __prop) \
    always @* if (rst_ni) assert (__prop);
`elsif SYNTHESIS
  `define MCADSW_ASSERT(__name, __prop)
  `define MCADSW_ASSUME(__name, __prop)
  `define MCADSW_COVER(__name, __prop)
`else
  `define MCADSW_CHECKS
  `define MCADSW_ASSERT(__name, __prop) \
    /* verilator coverage_off */ \
    always @(posedge clk_i or negedge rst_ni) if (rst_ni) assert (__prop) else $error("%m: %s", `"__name`"); \
    /* verilator coverage_on */
  `define MCADSW_ASSUME(__name, __prop) `MCADSW_ASSERT(__name, __prop)
  `define MCADSW_COVER(__name, __prop)
`endif

`endif

// Formal: assumption or assertion, cover or nothing, by the module being read.
`ifdef FORMAL
  `undef MCADSW_ASSUME
  `undef MCADSW_COVER
  `ifdef MCADSW_FORMAL_TOP
    `define MCADSW_ASSUME(__name, __prop) \
      always @* if (rst_ni) assume (__prop);
    `define MCADSW_COVER(__name, __prop) \
      always @* if (rst_ni) cover (__prop);
  `else
    `define MCADSW_ASSUME(__name, __prop) `MCADSW_ASSERT(__name, __prop)
    `define MCADSW_COVER(__name, __prop)
  `endif
`endif
