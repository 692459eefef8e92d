// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Formal properties of the depth FIFO (rtl/mcadsw_depth_fifo.sv), for `make
// formal`. Environment (assumed, as the scheduler and the cost aggregator
// behave): a descriptor is pushed only with space_o; descriptor k carries
// output address {k, 12'h000} (a tag in the upper bits, the row's columns
// below), columns x .. x + n - 1 inside 0 .. xend - 1 < 4096 with at least one
// at or right of xlo (the scheduler's blocks); values arrive
// group by group for the rows in descriptor order, only for rows with a
// descriptor, and every value of row k equals k's tag (k mod 16); the frame
// configuration (raw 8-bit output; mirrored or not) is stable.
// Asserted:
//   1. no overflow, no underflow: written rows never outrun the filled ones,
//      and space_o / empty_o agree with the rows pushed and written;
//   2. data out in order: rows are written in descriptor order (tags k, k + 1,
//      ...), each row's bytes are that row's values, and only pixels of the
//      row's columns are enabled.
`default_nettype none

module depth_fifo_props #(
  // A 16-bit address: a 4-bit row tag above the 12 bits of a row's columns. The tags
  // of the 5 rows the FIFO can hold at once (4 queued, 1 being written) stay distinct;
  // with 8 tag bits (AW = 20) the same proof took 4.5x as long (docs/results.md).
  parameter int AW = 16,
  parameter int CW = 12
) (
  input logic          clk_i,
  input logic          rst_ni,
  input logic          desc_push_i,
  input logic [CW-1:0] desc_x_i,
  input logic [4:0]    desc_n_i,
  input logic          mirror_i,
  input logic [1:0]    xlo_i,
  input logic [CW-1:0] xend_i,
  input logic          disp_valid_i,
  input logic          wr_gnt_i
);
  // A block row of 6 pixels in 2 groups of HAGG = 3 (the engine's is 18 in 6):
  // the same logic, so that a trace of a few cycles carries several rows.
  localparam int BLOCK = 6;
  localparam int HAGG  = mcadsw_pkg::HAGG;
  localparam int DB    = mcadsw_pkg::DISP_BITS;
  localparam int NG    = BLOCK / HAGG;
  localparam int GB    = $clog2(NG);
  localparam int TB    = AW - 12;      // tag bits

  logic               space, empty, wr_req;
  logic [AW-1:0]      wr_addr;
  logic [3:0]         wr_be;
  logic [31:0]        wr_wdata;
  logic [TB-1:0]      push_n_q, fill_n_q, done_n_q;  // rows pushed, filled, written
  logic [GB-1:0]      grp_q;
  logic [HAGG*DB-1:0] disp;
  for (genvar m = 0; m < HAGG; m++) begin : g_val
    assign disp[m*DB +: DB] = DB'(fill_n_q);
  end

  mcadsw_depth_fifo #(.BLOCK(BLOCK), .HAGG(HAGG), .AW(AW), .CW(CW)) dut (
    .clk_i, .rst_ni,
    .desc_push_i, .desc_addr_i ({push_n_q, 12'h000}), .desc_x_i, .desc_n_i,
    .space_o (space), .empty_o (empty),
    .wide_i (1'b0), .pack_i (1'b0), .mirror_i, .xlo_i, .xend_i,
    .disp_valid_i, .disp_grp_i (grp_q), .disp_i (disp),
    .sub_valid_i (1'b0), .sub_grp_i ('0), .sub_i ('0), .sub_d_i ('0),
    .wr_req_o (wr_req), .wr_addr_o (wr_addr), .wr_be_o (wr_be), .wr_wdata_o (wr_wdata),
    .wr_gnt_i
  );

  `include "props_reset.svh"

  // ---- Environment ------------------------------------------------------------------
  // The configuration of the first cycle, held for the whole trace.
  logic          mirror_q;
  logic [1:0]    xlo_q;
  logic [CW-1:0] xend_q;
  always_ff @(posedge clk_i) if (init) {mirror_q, xlo_q, xend_q} <= {mirror_i, xlo_i, xend_i};
  always_comb if (!init) assume (mirror_i == mirror_q && xlo_i == xlo_q && xend_i == xend_q);
  always_comb begin
    assume (xend_i[1:0] == 2'b00 && xend_i >= CW'(8) && xend_i <= CW'(64));
    assume (xlo_i == 2'd0 || mirror_i);
    if (desc_push_i) begin
      assume (!init && space);
      assume (desc_n_i >= 5'd1 && desc_n_i <= 5'(BLOCK));
      assume (32'(desc_x_i) + 32'(desc_n_i) <= 32'(xend_i));
      assume (32'(desc_x_i) + 32'(desc_n_i) > 32'(xlo_i));  // a pixel inside the image
    end
    if (disp_valid_i) assume (fill_n_q != push_n_q);   // the row has a descriptor
    if (!rst_ni) assume (!desc_push_i && !disp_valid_i);
  end
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) begin
      push_n_q <= '0;
      fill_n_q <= '0;
      grp_q    <= '0;
    end else begin
      if (desc_push_i) push_n_q <= push_n_q + 1'b1;
      if (disp_valid_i) begin
        grp_q <= (grp_q == GB'(NG - 1)) ? '0 : grp_q + 1'b1;
        if (grp_q == GB'(NG - 1)) fill_n_q <= fill_n_q + 1'b1;
      end
    end

  // ---- Properties -----------------------------------------------------------------------
  // The row being written: the tag of the write address; it moves to the next
  // tag when a write of a new row appears.
  logic [TB-1:0] tag;
  assign tag = wr_addr[AW-1:12];
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) done_n_q <= '0;
    else if (wr_req && wr_gnt_i && tag != done_n_q) done_n_q <= tag;
  always_comb if (rst_ni) begin
    // 2. In order: the row written is the oldest unwritten one, or the next.
    if (wr_req) assert (tag == done_n_q || tag == done_n_q + 1'b1);
    // 1. No underflow: only rows whose values are all in (filled) are written,
    //    at most 4 rows (ROWSQ) behind the filling.
    if (wr_req) assert (TB'(fill_n_q - tag) >= TB'(1) && TB'(fill_n_q - tag) <= TB'(4));
    // 1. space_o: at most 4 rows (ROWSQ) between pushed and written.
    assert (TB'(push_n_q - done_n_q) <= TB'(5));
    if (empty) assert (!wr_req);
    // 2. Bytes: enabled only inside the image row, and holding the row's value.
    for (int b = 0; b < 4; b++)
      if (wr_req && wr_be[b]) begin
        assert (wr_wdata[b*8 +: 8] == 8'(DB'(tag)));
        assert (32'(wr_addr[11:0]) + b < 32'(xend_i));
      end
    if (wr_req) assert (wr_be != '0);
  end
endmodule

`default_nettype wire
