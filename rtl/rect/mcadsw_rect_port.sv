// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The rectifier's memory port (docs/blocks/rectifier.md 7): three clients on one port
// in the engine's protocol. Priority: the writer, then the node reader, then the plane
// loader; a request presented and not granted keeps the port (its client, lock_q) until
// its grant, so the port's request is held as the engine's memory controller expects.
// Reads come back in order: a tag a read burst (its client and beats), written at the
// grant and retired at its last beat, routes each read beat to the client of the oldest
// burst; at most OUTS bursts are in flight (no read presented beyond).
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_rect_port #(
  parameter int OUTS = 8                                  // read bursts in flight
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  // Writer: single words
  input  logic        wr_req_i,
  output logic        wr_gnt_o,
  input  logic [31:0] wr_addr_i,
  input  logic [3:0]  wr_be_i,
  input  logic [31:0] wr_data_i,
  // Node reader and plane loader: read bursts of len + 1 words
  input  logic        nrd_req_i,
  output logic        nrd_gnt_o,
  input  logic [31:0] nrd_addr_i,
  input  logic [2:0]  nrd_len_i,
  output logic        nrd_rvalid_o,
  input  logic        ld_req_i,
  output logic        ld_gnt_o,
  input  logic [31:0] ld_addr_i,
  input  logic [2:0]  ld_len_i,
  output logic        ld_rvalid_o,
  // Memory port (the read data goes to the clients directly)
  output logic        mem_req_o,
  input  logic        mem_gnt_i,
  output logic        mem_we_o,
  output logic [3:0]  mem_be_o,
  output logic [31:0] mem_addr_o,
  output logic [2:0]  mem_len_o,
  output logic [31:0] mem_wdata_o,
  input  logic        mem_rvalid_i
);

  localparam int TB = $clog2(OUTS);                       // tag index
  if (OUTS < 2 || (1 << TB) != OUTS) begin : g_bad_param
    mcadsw_error_rect_port_outs_power_of_two u_error ();
  end

  logic [1:0] sel;                                        // 0 none, 1 write, 2 node read, 3 load
  logic [1:0] lock_q;
  logic [TB:0] outs_q;                                    // read bursts in flight
  logic       tag_full;
  assign tag_full = 32'(outs_q) >= OUTS;
  always_comb begin
    sel = 2'd0;
    if (lock_q != 2'd0) sel = lock_q;
    else if (wr_req_i) sel = 2'd1;
    else if (nrd_req_i && !tag_full) sel = 2'd2;
    else if (ld_req_i && !tag_full) sel = 2'd3;
  end
  assign mem_req_o   = sel != 2'd0;
  assign mem_we_o    = sel == 2'd1;
  assign mem_be_o    = sel == 2'd1 ? wr_be_i : 4'b0;
  assign mem_addr_o  = sel == 2'd1 ? wr_addr_i : sel == 2'd2 ? nrd_addr_i : ld_addr_i;
  assign mem_len_o   = sel == 2'd2 ? nrd_len_i : sel == 2'd3 ? ld_len_i : 3'd0;
  assign mem_wdata_o = sel == 2'd1 ? wr_data_i : 32'd0;
  assign wr_gnt_o  = sel == 2'd1 && mem_gnt_i;
  assign nrd_gnt_o = sel == 2'd2 && mem_gnt_i;
  assign ld_gnt_o  = sel == 2'd3 && mem_gnt_i;

  // Tags of the reads in flight: client (0 node read, 1 load) and words
  logic [OUTS-1:0]   tag_client_q;
  logic [OUTS*4-1:0] tag_len_q;                           // burst i's words at bits 4 i
  logic [TB-1:0]     tag_wr_q, tag_rd_q;
  logic [3:0]        beat_q;
  logic              rd_last;
  assign rd_last      = mem_rvalid_i && beat_q == tag_len_q[tag_rd_q * 4 +: 4] - 4'd1;
  assign nrd_rvalid_o = mem_rvalid_i && !tag_client_q[tag_rd_q];
  assign ld_rvalid_o  = mem_rvalid_i && tag_client_q[tag_rd_q];
  logic rd_granted;
  assign rd_granted = mem_gnt_i && (sel == 2'd2 || sel == 2'd3);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      lock_q <= '0; outs_q <= '0; tag_wr_q <= '0; tag_rd_q <= '0; beat_q <= '0;
    end else begin
      lock_q <= mem_req_o && !mem_gnt_i ? sel : 2'd0;
      if (rd_granted) tag_wr_q <= tag_wr_q + 1'b1;
      if (mem_rvalid_i) beat_q <= rd_last ? 4'd0 : beat_q + 4'd1;
      if (rd_last) tag_rd_q <= tag_rd_q + 1'b1;
      outs_q <= outs_q + (TB + 1)'(rd_granted) - (TB + 1)'(rd_last);
    end
  end

  always_ff @(posedge clk_i) begin                        // tag entries: written before read
    if (rd_granted) begin
      tag_client_q[tag_wr_q] <= sel == 2'd3;
      tag_len_q[tag_wr_q * 4 +: 4] <= {1'b0, mem_len_o} + 4'd1;
    end
  end

  // What the clients and the memory keep (the rectifier's writer, node reader and
  // loader; the engine's memory controller), and what the port keeps for them.
`ifdef MCADSW_CHECKS
  // verilator coverage_off
  logic        req_held_q;                                // last cycle's request, not granted
  logic [1:0]  sel_held_q;                                // ... its client
  logic [31:0] addr_held_q, wdata_held_q;                 // ... its payload (the client's)
  logic [3:0]  be_held_q;
  logic [2:0]  len_held_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) req_held_q <= 1'b0;
    else req_held_q <= mem_req_o && !mem_gnt_i;
  end
  always_ff @(posedge clk_i) begin
    sel_held_q <= sel; addr_held_q <= mem_addr_o; wdata_held_q <= mem_wdata_o;
    be_held_q <= mem_be_o; len_held_q <= mem_len_o;
  end
  // A client whose request the port presented and the memory did not grant keeps it.
  `MCADSW_ASSUME(PresentedWriteHeld, !(req_held_q && sel_held_q == 2'd1) ||
                 (wr_req_i && wr_addr_i == addr_held_q && wr_data_i == wdata_held_q && wr_be_i == be_held_q))
  `MCADSW_ASSUME(PresentedNodeReadHeld, !(req_held_q && sel_held_q == 2'd2) ||
                 (nrd_req_i && nrd_addr_i == addr_held_q && nrd_len_i == len_held_q))
  `MCADSW_ASSUME(PresentedLoadHeld, !(req_held_q && sel_held_q == 2'd3) ||
                 (ld_req_i && ld_addr_i == addr_held_q && ld_len_i == len_held_q))
  `MCADSW_ASSUME(ReadDataOnlyWhenInFlight, !mem_rvalid_i || outs_q != '0)
  // The port's request, presented and not granted, is the same in the next cycle.
  `MCADSW_ASSERT(RequestHeldUntilGranted, !req_held_q ||
                 (mem_req_o && sel == sel_held_q && mem_addr_o == addr_held_q &&
                  mem_wdata_o == wdata_held_q && mem_be_o == be_held_q && mem_len_o == len_held_q))
  // verilator coverage_on
`endif
  `MCADSW_ASSERT(BurstsWithinTags, 32'(outs_q) <= OUTS)
  `MCADSW_ASSERT(TagPointersApart, TB'(tag_wr_q - tag_rd_q) == TB'(outs_q))
  `MCADSW_ASSERT(GrantOnlyToARequest, !(wr_gnt_o && !wr_req_i) && !(nrd_gnt_o && !nrd_req_i) &&
                                      !(ld_gnt_o && !ld_req_i))

`ifdef FORMAL
  // The read bursts granted and not yet answered in full, oldest first (client, words),
  // and the beats of the oldest received; the port against them: every read beat goes
  // to the oldest burst's client, and the tags match the list (make formal,
  // formal/rect_port.sby: with these the proof closes by induction).
  logic [OUTS-1:0]   f_client_q;
  logic [OUTS*4-1:0] f_len_q;
  logic [3:0]        f_beat_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin : f_list
    logic [OUTS-1:0]   c;
    logic [OUTS*4-1:0] l;
    logic [TB:0]       n;
    if (!rst_ni) begin
      f_client_q <= '0; f_len_q <= '0; f_beat_q <= '0;
    end else begin
      c = f_client_q;
      l = f_len_q;
      n = outs_q;
      if (mem_rvalid_i) f_beat_q <= f_beat_q + 4'd1;
      if (mem_rvalid_i && f_beat_q == f_len_q[3:0] - 4'd1) begin
        c = c >> 1;
        l = l >> 4;
        n = n - 1'b1;
        f_beat_q <= '0;
      end
      if (rd_granted) begin
        c[32'(n)] = sel == 2'd3;
        l[32'(n)*4 +: 4] = {1'b0, mem_len_o} + 4'd1;
      end
      f_client_q <= c;
      f_len_q <= l;
    end
  end
  `MCADSW_ASSERT(BeatToOldestClient, !mem_rvalid_i || (ld_rvalid_o == f_client_q[0] && nrd_rvalid_o != f_client_q[0]))
  `MCADSW_ASSERT(BeatWithinBurst, beat_q == f_beat_q &&
                                   (outs_q == '0 ? f_beat_q == '0 : f_beat_q < f_len_q[3:0]))
  for (genvar i = 0; i < OUTS; i++) begin : g_f_tags
    `MCADSW_ASSERT(TagsInOrder, 32'(outs_q) <= i ||
                   (tag_client_q[32'(TB'(tag_rd_q + TB'(i)))] == f_client_q[i] &&
                    tag_len_q[32'(TB'(tag_rd_q + TB'(i)))*4 +: 4] == f_len_q[i*4 +: 4] &&
                    f_len_q[i*4 +: 4] != '0 && f_len_q[i*4 +: 4] <= 4'd8))
  end
  `MCADSW_ASSERT(NoLockWhenFull, !(tag_full && (lock_q == 2'd2 || lock_q == 2'd3)))
`endif

  // Events the block's proof must reach: each client granted, a request held over a
  // cycle while a write waits behind it, every tag in flight, a beat to each client.
  `MCADSW_COVER(WriteGranted, wr_gnt_o)
  `MCADSW_COVER(NodeReadGranted, nrd_gnt_o)
  `MCADSW_COVER(LoadGranted, ld_gnt_o)
  `MCADSW_COVER(ReadHeldBeforeAWrite, mem_req_o && !mem_gnt_i && lock_q == 2'd3 && wr_req_i)
  `MCADSW_COVER(AllTagsInFlight, 32'(outs_q) == OUTS)
  `MCADSW_COVER(BeatToNodeReader, nrd_rvalid_o)
  `MCADSW_COVER(BeatToLoader, ld_rvalid_o && beat_q != '0)
endmodule

`default_nettype wire
