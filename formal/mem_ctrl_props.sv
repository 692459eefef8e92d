// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Formal properties of the memory controller (rtl/mcadsw_mem_ctrl.sv), for
// `make formal` (formal/mem_ctrl.sby: SymbiYosys, Yices). Every input is
// free except for the assumptions below, which state what the rest of the
// engine and the memory guarantee (docs/memory_map.md):
//   - a requestor keeps its request (and address, length, write data) until
//     its grant; the memory returns read data only while beats are outstanding.
// Asserted:
//   1. at most one grant a cycle (readers and the depth FIFO's write);
//   2. the depth FIFO's priority: a write request is presented at once unless
//      the port holds a read it presented before and could not place;
//   3. the external request, once presented, stays unchanged until its grant;
//   4. round robin: a requesting reader sees at most NR - 1 read grants to
//      other readers before its own;
//   5. read data goes to exactly one reader, and only to one with beats of its
//      own outstanding (per-reader beat counts).
// 4 and 5 are the block's own (its `ifdef FORMAL` section), with the invariants that
// close the proof by induction.
`default_nettype none

module mem_ctrl_props #(
  parameter int NR = 3,
  parameter int AW = 8
) (
  input logic             clk_i,
  input logic             rst_ni,
  input logic [NR-1:0]    rd_req_i,
  input logic [NR*AW-1:0] rd_addr_i,
  input logic [NR*4-1:0]  rd_len_i,
  input logic             wr_req_i,
  input logic [AW-1:0]    wr_addr_i,
  input logic [3:0]       wr_be_i,
  input logic [31:0]      wr_wdata_i,
  input logic             mem_gnt_i,
  input logic             mem_rvalid_i,
  input logic [31:0]      mem_rdata_i
);
  logic [NR-1:0]    rd_gnt, rd_rvalid;
  logic [31:0]      rd_rdata;
  logic             wr_gnt, mem_req, mem_we;
  logic [3:0]       mem_be, mem_len;
  logic [AW-1:0]    mem_addr;
  logic [31:0]      mem_wdata;

  mcadsw_mem_ctrl #(.NR(NR), .OUTS(4), .AW(AW)) dut (
    .clk_i, .rst_ni,
    .rd_req_i, .rd_addr_i, .rd_len_i, .rd_gnt_o (rd_gnt), .rd_rvalid_o (rd_rvalid),
    .rd_rdata_o (rd_rdata),
    .wr_req_i, .wr_addr_i, .wr_be_i, .wr_wdata_i, .wr_gnt_o (wr_gnt),
    .mem_req_o (mem_req), .mem_gnt_i, .mem_we_o (mem_we), .mem_be_o (mem_be),
    .mem_addr_o (mem_addr), .mem_len_o (mem_len), .mem_wdata_o (mem_wdata),
    .mem_rvalid_i, .mem_rdata_i
  );

  `include "props_reset.svh"

  // ---- Environment ------------------------------------------------------------------
  // Requestors hold a request until its grant.
  always_ff @(posedge clk_i) if (past_ok && rst_ni) begin
    for (int r = 0; r < NR; r++)
      if ($past(rd_req_i[r] && !rd_gnt[r])) begin
        assume (rd_req_i[r]);
        assume (rd_addr_i[r*AW +: AW] == $past(rd_addr_i[r*AW +: AW]));
        assume (rd_len_i[r*4 +: 4] == $past(rd_len_i[r*4 +: 4]));
      end
    if ($past(wr_req_i && !wr_gnt)) begin
      assume (wr_req_i);
      assume (wr_addr_i == $past(wr_addr_i) && wr_be_i == $past(wr_be_i) &&
              wr_wdata_i == $past(wr_wdata_i));
    end
  end
  // Bursts of up to 4 beats keep the solver fast (the length is carried, not
  // interpreted, beyond the beat count of the head burst).
  always_comb for (int r = 0; r < NR; r++) assume (rd_len_i[r*4 +: 4] < 4'd4);
  // The memory returns a beat only for a read burst granted before: the block's own
  // assumption (ReadDataOnlyWhenOutstanding).

  // ---- Properties -----------------------------------------------------------------------
  // 1. One grant a cycle.
  logic [NR:0] grants;
  assign grants = {wr_gnt, rd_gnt};
  always_comb if (rst_ni) assert ((grants & (grants - 1'b1)) == '0);

  // 2. The write's priority: presented at once, unless a read is held.
  logic held_read;                   // last cycle presented a read that was not granted
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) held_read <= 1'b0;
    else held_read <= mem_req && !mem_gnt_i && !mem_we;
  always_comb if (rst_ni && wr_req_i && !held_read) assert (mem_req && mem_we);
  always_comb if (rst_ni && held_read) assert (mem_req && !mem_we);

  // 3. The external request is held unchanged until granted.
  always_ff @(posedge clk_i) if (past_ok && rst_ni && $past(mem_req && !mem_gnt_i)) begin
    assert (mem_req);
    assert (mem_we == $past(mem_we) && mem_addr == $past(mem_addr) && mem_be == $past(mem_be) &&
            mem_wdata == $past(mem_wdata) && mem_len == $past(mem_len));
  end

  // 4. Round robin and 5. read data only to a reader with beats outstanding: in the
  // block's `ifdef FORMAL` section (RoundRobinBound, ReadDataOnlyToAReaderOwed), beside the
  // invariants that close the induction.
  always_comb if (rst_ni) begin
    assert (mem_rvalid_i == |rd_rvalid);
    assert ((rd_rvalid & (rd_rvalid - 1'b1)) == '0);
  end

  logic unused;
  assign unused = ^{rd_rdata, mem_be, mem_wdata};
endmodule

`default_nettype wire
