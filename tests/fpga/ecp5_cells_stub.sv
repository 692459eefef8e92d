// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The ports the board shell connects of the ECP5 primitive it instantiates (EHXPLLL,
// named as in Yosys's ecp5/cells_bb.v), for linting the shell with Verilator (ctest
// fpga_board_shell_lint): a clock passed through, LOCK high. Not a model of the PLL.
`default_nettype none
/* verilator lint_off DECLFILENAME */
/* verilator lint_off UNUSEDPARAM */

module EHXPLLL #(
  parameter integer CLKI_DIV = 1, CLKFB_DIV = 1, CLKOP_DIV = 8, CLKOP_CPHASE = 0, CLKOP_FPHASE = 0,
  parameter string CLKOP_ENABLE = "", FEEDBK_PATH = "", PLLRST_ENA = "", INTFB_WAKE = "",
  parameter string STDBY_ENABLE = "", DPHASE_SOURCE = "", OUTDIVIDER_MUXA = "", OUTDIVIDER_MUXB = "",
  parameter string OUTDIVIDER_MUXC = "", OUTDIVIDER_MUXD = ""
) (
  input  wire CLKI, CLKFB, PHASESEL1, PHASESEL0, PHASEDIR, PHASESTEP, PHASELOADREG, STDBY,
  input  wire PLLWAKESYNC, RST, ENCLKOP,
  output wire CLKOP, LOCK
);
  /* verilator lint_off UNUSED */
  wire unused = &{CLKFB, PHASESEL1, PHASESEL0, PHASEDIR, PHASESTEP, PHASELOADREG, STDBY, PLLWAKESYNC,
                  RST, ENCLKOP};
  /* verilator lint_on UNUSED */
  assign CLKOP = CLKI;
  assign LOCK = 1'b1;
endmodule

/* verilator lint_on UNUSEDPARAM */
/* verilator lint_on DECLFILENAME */
`default_nettype wire
