// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Formal environment of the queue of the post stage and the rectifier (rtl/mcadsw_fifo.sv),
// for `make formal` (formal/fifo.sby). The properties are in the block: its count
// within the depth and equal to the distance of its pointers, and, in its `ifdef FORMAL`
// section, a list of the entries pushed and not yet popped, oldest first, that every held
// entry and the head match. Environment: the block's own assumptions (no push beyond the
// depth, no pop of an empty queue); data, pushes and pops otherwise free. Small entries
// (8 bits) and the post stage's depth (4): the logic does not depend on the width.
`default_nettype none

module fifo_props (
  input logic       clk_i,
  input logic       rst_ni,
  input logic       push_i,
  input logic [7:0] data_i,
  input logic       push2_i,
  input logic [7:0] data2_i,
  input logic       pop_i
);
  logic [7:0] head;
  logic [2:0] count;
  mcadsw_fifo #(.W(8), .DEPTH(4)) dut (
    .clk_i, .rst_ni, .push_i, .data_i, .push2_i, .data2_i, .pop_i,
    .head_o (head), .count_o (count)
  );

  `include "props_reset.svh"

  always_comb if (!rst_ni) assume (!push_i && !push2_i && !pop_i);

  logic unused;
  assign unused = ^{head, count, past_ok};
endmodule

`default_nettype wire
