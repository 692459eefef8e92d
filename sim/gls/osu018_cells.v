// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Two-state models of the OSU 0.18 um standard cells, for gate-level
// simulation of the mapped netlist in Verilator (the library's own
// osu018_stdcells.v uses UDPs, which Verilator does not read). Each function is
// the liberty's `function` / `ff` / `latch` group (osu018_stdcells.lib). TBUFX1/2
// are not modelled: scripts/gls.sh rejects a netlist that uses them.
/* verilator lint_off DECLFILENAME */
module AND2X1 (input A, B, output Y); assign Y = A & B; endmodule
module AND2X2 (input A, B, output Y); assign Y = A & B; endmodule
module AOI21X1 (input A, B, C, output Y); assign Y = ~((A & B) | C); endmodule
module AOI22X1 (input A, B, C, D, output Y); assign Y = ~((A & B) | (C & D)); endmodule
module BUFX2 (input A, output Y); assign Y = A; endmodule
module BUFX4 (input A, output Y); assign Y = A; endmodule
module CLKBUF1 (input A, output Y); assign Y = A; endmodule
module CLKBUF2 (input A, output Y); assign Y = A; endmodule
module CLKBUF3 (input A, output Y); assign Y = A; endmodule
module FAX1 (input A, B, C, output YC, YS);
  assign YC = (A & B) | (B & C) | (C & A);
  assign YS = A ^ B ^ C;
endmodule
module HAX1 (input A, B, output YC, YS); assign YC = A & B; assign YS = A ^ B; endmodule
module INVX1 (input A, output Y); assign Y = ~A; endmodule
module INVX2 (input A, output Y); assign Y = ~A; endmodule
module INVX4 (input A, output Y); assign Y = ~A; endmodule
module INVX8 (input A, output Y); assign Y = ~A; endmodule
module MUX2X1 (input A, B, S, output Y); assign Y = ~((S & A) | (~S & B)); endmodule
module NAND2X1 (input A, B, output Y); assign Y = ~(A & B); endmodule
module NAND3X1 (input A, B, C, output Y); assign Y = ~(A & B & C); endmodule
module NOR2X1 (input A, B, output Y); assign Y = ~(A | B); endmodule
module NOR3X1 (input A, B, C, output Y); assign Y = ~(A | B | C); endmodule
module OAI21X1 (input A, B, C, output Y); assign Y = ~((A | B) & C); endmodule
module OAI22X1 (input A, B, C, D, output Y); assign Y = ~((A | B) & (C | D)); endmodule
module OR2X1 (input A, B, output Y); assign Y = A | B; endmodule
module OR2X2 (input A, B, output Y); assign Y = A | B; endmodule
module XNOR2X1 (input A, B, output Y); assign Y = ~(A ^ B); endmodule
module XOR2X1 (input A, B, output Y); assign Y = A ^ B; endmodule
module DFFPOSX1 (input CLK, D, output reg Q); always @(posedge CLK) Q <= D; endmodule
module DFFNEGX1 (input CLK, D, output reg Q); always @(negedge CLK) Q <= D; endmodule
// Transparent while CLK is high (enable : "CLK"): the clock gates of
// flow/clock_gate.py, whose CLK is the inverted clock.
module LATCH (input CLK, D, output reg Q); always_latch if (CLK) Q = D; endmodule
// clear (!R) and preset (!S), both active: Q = 0 (clear_preset_var1 : L).
module DFFSR (input CLK, D, R, S, output reg Q);
  always @(posedge CLK or negedge R or negedge S)
    if (!R) Q <= 1'b0;
    else if (!S) Q <= 1'b1;
    else Q <= D;
endmodule
