// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Formal properties of the AXI4 master (rtl/mcadsw_axi_master.sv), for `make
// formal`. Environment (assumed): the engine keeps a request unchanged until
// its grant, asks for aligned reads of at most 4 beats that stay inside 4 KiB
// (the window readers' rule), and the slave returns R beats and B responses
// only for transactions it accepted. RLAST is left free: the master counts
// beats.
// Asserted (the AXI4 handshake rules and the master's own):
//   1. ARVALID, AWVALID and WVALID stay high, with their payload unchanged,
//      until READY;
//   2. 4-byte INCR bursts, aligned, none across a 4 KiB boundary, AR of the
//      length the engine asked for;
//   3. WLAST: the W bursts (beats up to each WLAST) have the lengths of the AW
//      bursts, in order;
//   4. the engine gets read data only for reads it was granted, and every R
//      beat while not draining;
//   5. nothing is granted while draining;
//   6. wr_idle_o: no write granted but unanswered; idle_o: no read either.
// 3, and the counting parts of 4 and 6, are the block's own (its `ifdef FORMAL` section),
// with the invariants that close the proof by induction.
`default_nettype none

module axi_master_props #(
  parameter int AW = 16
) (
  input logic          clk_i,
  input logic          rst_ni,
  input logic          mem_req_i,
  input logic          mem_we_i,
  input logic [3:0]    mem_be_i,
  input logic [AW-1:0] mem_addr_i,
  input logic [3:0]    mem_len_i,
  input logic [31:0]   mem_wdata_i,
  input logic          drain_i,
  input logic          m_arready_i,
  input logic          m_rvalid_i,
  input logic [31:0]   m_rdata_i,
  input logic [1:0]    m_rresp_i,
  input logic          m_rlast_i,
  input logic          m_awready_i,
  input logic          m_wready_i,
  input logic          m_bvalid_i,
  input logic [1:0]    m_bresp_i
);
  logic          mem_gnt, mem_rvalid, wr_idle, idle, rd_err, wr_err;
  logic [31:0]   mem_rdata, wdata;
  logic          arvalid, rready, awvalid, wvalid, wlast, bready;
  logic [AW-1:0] araddr, awaddr;
  logic [7:0]    arlen, awlen;
  logic [2:0]    arsize, awsize;
  logic [1:0]    arburst, awburst;
  logic [3:0]    wstrb;

  mcadsw_axi_master #(.AW(AW), .BL(4), .WD(4), .ROUTS(8), .BOUTS(3)) dut (
    .clk_i, .rst_ni,
    .mem_req_i, .mem_gnt_o (mem_gnt), .mem_we_i, .mem_be_i, .mem_addr_i, .mem_len_i,
    .mem_wdata_i, .mem_rvalid_o (mem_rvalid), .mem_rdata_o (mem_rdata),
    .drain_i, .wr_idle_o (wr_idle), .idle_o (idle), .rd_err_o (rd_err), .wr_err_o (wr_err),
    .m_arvalid_o (arvalid), .m_arready_i, .m_araddr_o (araddr), .m_arlen_o (arlen),
    .m_arsize_o (arsize), .m_arburst_o (arburst),
    .m_rvalid_i, .m_rready_o (rready), .m_rdata_i, .m_rresp_i, .m_rlast_i,
    .m_awvalid_o (awvalid), .m_awready_i, .m_awaddr_o (awaddr), .m_awlen_o (awlen),
    .m_awsize_o (awsize), .m_awburst_o (awburst),
    .m_wvalid_o (wvalid), .m_wready_i, .m_wdata_o (wdata), .m_wstrb_o (wstrb), .m_wlast_o (wlast),
    .m_bvalid_i, .m_bready_o (bready), .m_bresp_i
  );

  `include "props_reset.svh"

  // ---- Environment --------------------------------------------------------------------
  always_ff @(posedge clk_i) if (past_ok && rst_ni && $past(mem_req_i && !mem_gnt)) begin
    assume (mem_req_i && mem_we_i == $past(mem_we_i) && mem_addr_i == $past(mem_addr_i) &&
            mem_len_i == $past(mem_len_i) && mem_be_i == $past(mem_be_i) &&
            mem_wdata_i == $past(mem_wdata_i));
  end
  always_comb begin
    assume (mem_addr_i[1:0] == 2'b00);
    if (!mem_we_i) assume (mem_len_i < 4'd4 && 32'(mem_addr_i[11:0]) + 4 * (32'(mem_len_i) + 1) <= 4096);
  end
  // The slave answers only what it accepted: R beats (the block's FORMAL section counts
  // the ARs' beats accepted), B responses (the block's own assumption).

  // ---- Properties -----------------------------------------------------------------------
  // 1. VALID held, payload stable, until READY.
  always_ff @(posedge clk_i) if (past_ok && rst_ni) begin
    if ($past(arvalid && !m_arready_i))
      assert (arvalid && araddr == $past(araddr) && arlen == $past(arlen) &&
              arsize == $past(arsize) && arburst == $past(arburst));
    if ($past(awvalid && !m_awready_i))
      assert (awvalid && awaddr == $past(awaddr) && awlen == $past(awlen) &&
              awsize == $past(awsize) && awburst == $past(awburst));
    if ($past(wvalid && !m_wready_i))
      assert (wvalid && wdata == $past(wdata) && wstrb == $past(wstrb) && wlast == $past(wlast));
  end

  // 2. Burst shape: 4-byte INCR beats, aligned, inside 4 KiB; AR as the engine asked.
  always_comb if (rst_ni) begin
    if (arvalid)
      assert (arsize == 3'd2 && arburst == 2'b01 && araddr[1:0] == 2'b00 &&
              32'(araddr[11:0]) + 4 * (32'(arlen) + 1) <= 4096);
    if (awvalid)
      assert (awsize == 3'd2 && awburst == 2'b01 && awaddr[1:0] == 2'b00 &&
              32'(awaddr[11:0]) + 4 * (32'(awlen) + 1) <= 4096);
  end
  logic [3:0] req_len_q;             // the length of the last read granted
  always_ff @(posedge clk_i) if (mem_req_i && mem_gnt && !mem_we_i) req_len_q <= mem_len_i;
  always_ff @(posedge clk_i) if (past_ok && rst_ni && $past(mem_req_i && mem_gnt && !mem_we_i))
    assert (arvalid && araddr == $past(mem_addr_i) && arlen == 8'($past(mem_len_i)));

  // 3. WLAST: in the block's `ifdef FORMAL` section (QueuesMatch: each W burst as long as
  // its AW, in order), with the invariants that close the induction.

  // 4. Read data to the engine only for its reads; every R beat passed on unless draining.
  // (Only for its reads: the block's ReadDataOnlyWhenOwed.)
  always_comb if (rst_ni) begin
    if (m_rvalid_i && !drain_i) assert (mem_rvalid && mem_rdata == m_rdata_i);
    assert (rready && bready);
  end

  // 5. Nothing granted while draining.
  always_comb if (rst_ni && drain_i) assert (!mem_gnt);

  // 6. Idle flags.
  // (No B or R outstanding: the block's wr_idle_o counts the B responses owed, and its
  // IdleNoReadOutstanding the R beats.)
  always_comb if (rst_ni) begin
    if (wr_idle) assert (!awvalid && !wvalid);
    if (idle) assert (wr_idle && !arvalid);
  end

  logic unused;
  assign unused = ^{rd_err, wr_err, req_len_q};
endmodule

`default_nettype wire
