// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The on-chip memory macro MCADSW_RAM. Synthesis (flow/synth.py) reads this
// file with `read_verilog -lib`, i.e. as a black box with these ports, and maps
// every inferred memory onto it (constraints/macro_map.v), so memories stay out
// of the gate count. Gate-level simulation uses the body, a behavioural model
// with the semantics of Yosys' $mem_v2 for the features the engine's memories
// use (flow/synth.py checks that no memory uses more): rising-edge write
// ports with per-bit enables; read ports either asynchronous or clocked with an
// enable and an asynchronous reset to RD_ARST_VALUE; a clocked read returns the
// data from before a write in the same cycle.
/* verilator lint_off DECLFILENAME */
module MCADSW_RAM #(
  parameter SIZE = 4,
  parameter ABITS = 2,
  parameter WIDTH = 8,
  parameter RD_PORTS = 1,
  parameter WR_PORTS = 1,
  parameter RD_CLK_ENABLE = 1'b1,
  parameter RD_ARST_VALUE = 1'b0
) (
  input  [RD_PORTS-1:0]       RD_CLK,
  input  [RD_PORTS-1:0]       RD_EN,
  input  [RD_PORTS-1:0]       RD_ARST,
  input  [RD_PORTS*ABITS-1:0] RD_ADDR,
  output [RD_PORTS*WIDTH-1:0] RD_DATA,
  input  [WR_PORTS-1:0]       WR_CLK,
  input  [WR_PORTS*WIDTH-1:0] WR_EN,
  input  [WR_PORTS*ABITS-1:0] WR_ADDR,
  input  [WR_PORTS*WIDTH-1:0] WR_DATA
);
  reg [WIDTH-1:0] mem [0:SIZE-1];

  genvar i;
  for (i = 0; i < WR_PORTS; i = i + 1) begin : g_wr
    always @(posedge WR_CLK[i]) begin
      if (WR_ADDR[i*ABITS +: ABITS] < SIZE)
        mem[WR_ADDR[i*ABITS +: ABITS]] <= (mem[WR_ADDR[i*ABITS +: ABITS]] & ~WR_EN[i*WIDTH +: WIDTH]) |
                                          (WR_DATA[i*WIDTH +: WIDTH] & WR_EN[i*WIDTH +: WIDTH]);
    end
  end

  for (i = 0; i < RD_PORTS; i = i + 1) begin : g_rd
    wire [WIDTH-1:0] word = (RD_ADDR[i*ABITS +: ABITS] < SIZE) ? mem[RD_ADDR[i*ABITS +: ABITS]] : {WIDTH{1'b0}};
    if (RD_CLK_ENABLE[i]) begin : g_sync
      reg [WIDTH-1:0] q;
      wire [WIDTH-1:0] arst_value = RD_ARST_VALUE[i*WIDTH +: WIDTH];
      always @(posedge RD_CLK[i] or posedge RD_ARST[i])
        if (RD_ARST[i]) q <= arst_value;
        else if (RD_EN[i]) q <= word;
      assign RD_DATA[i*WIDTH +: WIDTH] = q;
    end else begin : g_async
      assign RD_DATA[i*WIDTH +: WIDTH] = word;
    end
  end
endmodule
