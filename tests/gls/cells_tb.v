// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Compares sim/gls/osu018_cells.v (the two-state models the gate-level
// simulation uses) with the library's own models (osu018_stdcells.v): this
// bench runs once against each and prints every cell's outputs for every
// input combination, and a random sequence for the flip-flops; the two
// transcripts must be identical (tests/gls/check_cells.sh).
`timescale 1ns/10ps
module cells_tb;
  reg [3:0] in;
  reg clk, d, r, s;
  wire y_and2, y_and2x2, y_aoi21, y_aoi22, y_buf2, y_buf4, y_ck1, y_ck2, y_ck3;
  wire yc_fa, ys_fa, yc_ha, ys_ha, y_inv1, y_inv2, y_inv4, y_inv8, y_mux;
  wire y_nand2, y_nand3, y_nor2, y_nor3, y_oai21, y_oai22, y_or2, y_or2x2, y_xnor, y_xor;
  wire q_pos, q_neg, q_sr, q_lat;

  AND2X1  u0 (.A(in[0]), .B(in[1]), .Y(y_and2));
  AND2X2  u1 (.A(in[0]), .B(in[1]), .Y(y_and2x2));
  AOI21X1 u2 (.A(in[0]), .B(in[1]), .C(in[2]), .Y(y_aoi21));
  AOI22X1 u3 (.A(in[0]), .B(in[1]), .C(in[2]), .D(in[3]), .Y(y_aoi22));
  BUFX2   u4 (.A(in[0]), .Y(y_buf2));
  BUFX4   u5 (.A(in[0]), .Y(y_buf4));
  CLKBUF1 u6 (.A(in[0]), .Y(y_ck1));
  CLKBUF2 u7 (.A(in[0]), .Y(y_ck2));
  CLKBUF3 u8 (.A(in[0]), .Y(y_ck3));
  FAX1    u9 (.A(in[0]), .B(in[1]), .C(in[2]), .YC(yc_fa), .YS(ys_fa));
  HAX1    u10 (.A(in[0]), .B(in[1]), .YC(yc_ha), .YS(ys_ha));
  INVX1   u11 (.A(in[0]), .Y(y_inv1));
  INVX2   u12 (.A(in[0]), .Y(y_inv2));
  INVX4   u13 (.A(in[0]), .Y(y_inv4));
  INVX8   u14 (.A(in[0]), .Y(y_inv8));
  MUX2X1  u15 (.A(in[0]), .B(in[1]), .S(in[2]), .Y(y_mux));
  NAND2X1 u16 (.A(in[0]), .B(in[1]), .Y(y_nand2));
  NAND3X1 u17 (.A(in[0]), .B(in[1]), .C(in[2]), .Y(y_nand3));
  NOR2X1  u18 (.A(in[0]), .B(in[1]), .Y(y_nor2));
  NOR3X1  u19 (.A(in[0]), .B(in[1]), .C(in[2]), .Y(y_nor3));
  OAI21X1 u20 (.A(in[0]), .B(in[1]), .C(in[2]), .Y(y_oai21));
  OAI22X1 u21 (.A(in[0]), .B(in[1]), .C(in[2]), .D(in[3]), .Y(y_oai22));
  OR2X1   u22 (.A(in[0]), .B(in[1]), .Y(y_or2));
  OR2X2   u23 (.A(in[0]), .B(in[1]), .Y(y_or2x2));
  XNOR2X1 u24 (.A(in[0]), .B(in[1]), .Y(y_xnor));
  XOR2X1  u25 (.A(in[0]), .B(in[1]), .Y(y_xor));
  DFFPOSX1 u26 (.CLK(clk), .D(d), .Q(q_pos));
  DFFNEGX1 u27 (.CLK(clk), .D(d), .Q(q_neg));
  DFFSR    u28 (.CLK(clk), .D(d), .R(r), .S(s), .Q(q_sr));
  LATCH    u29 (.CLK(clk), .D(d), .Q(q_lat));

  integer i, seed;
  initial begin
    for (i = 0; i < 16; i = i + 1) begin
      in = i[3:0];
      #10;
      $display("in=%b and2=%b%b aoi21=%b aoi22=%b buf=%b%b%b%b%b fa=%b%b ha=%b%b inv=%b%b%b%b mux=%b nand=%b%b nor=%b%b oai=%b%b or=%b%b xnor=%b xor=%b",
               in, y_and2, y_and2x2, y_aoi21, y_aoi22, y_buf2, y_buf4, y_ck1, y_ck2, y_ck3,
               yc_fa, ys_fa, yc_ha, ys_ha, y_inv1, y_inv2, y_inv4, y_inv8, y_mux, y_nand2, y_nand3,
               y_nor2, y_nor3, y_oai21, y_oai22, y_or2, y_or2x2, y_xnor, y_xor);
    end
    // Flip-flops: a random sequence of data, clock edges, resets and sets (not
    // both at once: releasing both together is a race in the library's model
    // and undefined in silicon); the first edges give every flop a value.
    seed = 7;
    clk = 0; d = 0; r = 1; s = 1;
    #10 clk = 1; #10 clk = 0; #10;
    for (i = 0; i < 400; i = i + 1) begin
      d = $random(seed);
      r = ($random(seed) % 8) != 0;
      s = !r || ($random(seed) % 8) != 0;
      #5 clk = ~clk;
      #5 $display("t=%0d clk=%b d=%b r=%b s=%b pos=%b neg=%b sr=%b lat=%b", i, clk, d, r, s, q_pos, q_neg, q_sr, q_lat);
      // The latch: D changes in mid phase (transparent while CLK is high, held while low).
      #1 d = $random(seed);
      #1 $display("t=%0d clk=%b d=%b lat=%b", i, clk, d, q_lat);
    end
    $finish;
  end
endmodule
