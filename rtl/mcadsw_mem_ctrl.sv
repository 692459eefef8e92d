// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Memory controller (paper Sec. V-E): one 32-bit external memory port shared
// by NR read requestors (census left, census right, weight generator) and the
// depth FIFO's writes. The depth FIFO has fixed highest priority (suspending
// the cost aggregator is expensive); the readers share by round robin.
//
// External port (like ibex's data port): req_o/gnt_i handshake with we_o,
// be_o, addr_o, wdata_o and, for reads, len_o; a granted read is a burst of
// len_o + 1 words at consecutive addresses (the readers ask for bursts in the
// column-tiled layout, docs/memory_map.md), returned as len_o + 1 rdata_i
// beats with rvalid_i, in order, one or more cycles later; writes are one word
// and return nothing. The requestor and length of each read burst in flight
// are kept in order, so the beats are routed back.
//
// A request the memory does not grant is presented again, unchanged (req, we,
// be, addr, wdata), until its grant, as OBI and AXI require: the choice of a
// stalled cycle is held, so neither a write nor another reader's turn can
// replace it. The requestors keep their own request stable until granted.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_mem_ctrl #(
  parameter int NR   = 3,      // read requestors
  parameter int OUTS = 16,     // reads in flight on the external port
  parameter int AW   = 32
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  // Readers
  input  logic [NR-1:0]    rd_req_i,
  input  logic [NR*AW-1:0] rd_addr_i,
  input  logic [NR*4-1:0]  rd_len_i,     // beats - 1
  output logic [NR-1:0]    rd_gnt_o,
  output logic [NR-1:0]    rd_rvalid_o,
  output logic [31:0]      rd_rdata_o,   // shared: valid for the reader with rd_rvalid_o
  // Depth FIFO writes
  input  logic             wr_req_i,
  input  logic [AW-1:0]    wr_addr_i,
  input  logic [3:0]       wr_be_i,
  input  logic [31:0]      wr_wdata_i,
  output logic             wr_gnt_o,
  // External memory
  output logic             mem_req_o,
  input  logic             mem_gnt_i,
  output logic             mem_we_o,
  output logic [3:0]       mem_be_o,
  output logic [AW-1:0]    mem_addr_o,
  output logic [3:0]       mem_len_o,    // read burst: beats - 1 (0 for writes)
  output logic [31:0]      mem_wdata_o,
  input  logic             mem_rvalid_i,
  input  logic [31:0]      mem_rdata_i
);

  localparam int IB = (NR > 1) ? $clog2(NR) : 1;
  localparam int OB = $clog2(OUTS + 1);

  // ---- Round-robin choice among readers, after the last one served ------------
  logic [IB-1:0] last_q, pick;
  logic          any_rd;
  always_comb begin
    pick   = last_q;
    any_rd = 1'b0;
    for (int i = 1; i <= NR; i++) begin
      logic [IB:0] r;                // last_q + i, wrapped (< 2 NR, so one subtraction)
      r = (IB + 1)'(last_q) + (IB + 1)'(i);
      if (r >= (IB + 1)'(NR)) r = r - (IB + 1)'(NR);
      if (!any_rd && rd_req_i[IB'(r)]) begin
        pick   = IB'(r);
        any_rd = 1'b1;
      end
    end
  end

  // ---- Read bursts in flight: requestor ids and lengths in order -----------------------
  logic [OUTS*IB-1:0] ids_q;
  logic [OUTS*4-1:0]  lens_q;
  logic [OB-1:0]      nids_q;
  logic [3:0]         beat_q;         // beats of the head burst already returned
  logic               head_last;      // this beat ends the head burst
  assign head_last = beat_q == lens_q[3:0];
  logic               rd_ok;          // room to track another read
  assign rd_ok = nids_q != OB'(OUTS);

  // ---- Held request: last cycle's request was not granted ------------------------
  logic          hold_q, hold_wr_q;   // held, and whether it is the write
  logic [IB-1:0] hold_id_q;           // the reader of a held read

  logic          write_sel, read_sel;
  logic [IB-1:0] rd_id;               // the reader presented
  assign write_sel = hold_q ? hold_wr_q : wr_req_i;   // the write has fixed highest priority
  assign read_sel  = hold_q ? !hold_wr_q : !wr_req_i && any_rd && rd_ok;
  assign rd_id     = hold_q ? hold_id_q : pick;

  assign mem_req_o   = write_sel || read_sel;
  assign mem_we_o    = write_sel;
  assign mem_be_o    = write_sel ? wr_be_i : 4'hf;
  assign mem_addr_o  = write_sel ? wr_addr_i : rd_addr_i[32'(rd_id)*AW +: AW];
  assign mem_len_o   = write_sel ? 4'd0 : rd_len_i[32'(rd_id)*4 +: 4];
  assign mem_wdata_o = write_sel ? wr_wdata_i : 32'h0;
  assign wr_gnt_o    = write_sel && mem_gnt_i;
  for (genvar r = 0; r < NR; r++) begin : g_gnt
    assign rd_gnt_o[r]    = read_sel && mem_gnt_i && rd_id == IB'(r);
    assign rd_rvalid_o[r] = mem_rvalid_i && ids_q[IB-1:0] == IB'(r);
  end
  assign rd_rdata_o = mem_rdata_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      last_q    <= '0;
      ids_q     <= '0;
      lens_q    <= '0;
      nids_q    <= '0;
      beat_q    <= '0;
      hold_q    <= 1'b0;
      hold_wr_q <= 1'b0;
      hold_id_q <= '0;
    end else begin
      logic [OUTS*IB-1:0] ids;
      logic [OUTS*4-1:0]  lens;
      logic [OB-1:0]      n;
      hold_q    <= mem_req_o && !mem_gnt_i;
      hold_wr_q <= write_sel;
      hold_id_q <= rd_id;
      ids  = ids_q;
      lens = lens_q;
      n    = nids_q;
      if (mem_rvalid_i) beat_q <= head_last ? 4'd0 : beat_q + 4'd1;
      if (mem_rvalid_i && head_last) begin
        ids  = ids >> IB;
        lens = lens >> 4;
        n    = n - OB'(1);
      end
      if (read_sel && mem_gnt_i) begin
        ids[32'(n)*IB +: IB] = rd_id;
        lens[32'(n)*4 +: 4]  = mem_len_o;
        n = n + OB'(1);
        last_q <= rd_id;
      end
      ids_q  <= ids;
      lens_q <= lens;
      nids_q <= n;
    end
  end

`ifdef MCADSW_CHECKS
  // verilator coverage_off
  logic [3:0] hold_len_q;
  always_ff @(posedge clk_i) hold_len_q <= mem_len_o;
  // verilator coverage_on
`endif
  // Invariants (docs/verification.md section 3), and what the requestors and the
  // external memory must keep.
  logic [NR:0] grants;
  assign grants = {wr_gnt_o, rd_gnt_o};
  `MCADSW_ASSERT(OneGrantPerCycle, (grants & (grants - 1'b1)) == '0)
  `MCADSW_ASSERT(ReadDataToOneReader, (rd_rvalid_o & (rd_rvalid_o - 1'b1)) == '0)
  `MCADSW_ASSUME(ReadDataOnlyWhenOutstanding, !(mem_rvalid_i && nids_q == '0))
  `MCADSW_ASSUME(RequestHeldUntilGranted, !(hold_q && (hold_wr_q ? !wr_req_i : !rd_req_i[hold_id_q])))
  `MCADSW_ASSUME(LengthHeldUntilGranted, !(hold_q && !hold_wr_q && mem_len_o != hold_len_q))

`ifdef FORMAL
  // The proof's reference (make formal, formal/mem_ctrl.sby; with these invariants the
  // proof closes by induction):
  // - each reader's beats granted and not yet routed to it (f_own_q), which the queue of
  //   bursts in flight accounts for entry by entry; read data only to a reader with beats
  //   of its own outstanding;
  // - round robin: the read grants to others while a reader waits (f_waited_q), at most
  //   NR - 1. Invariant: waited + the reader's distance after the last reader served is at
  //   most NR (each grant to another brings the reader nearer); a read held since before
  //   (picked while the reader already waited) lies no further than the reader.
  localparam int FOB = OB + 5;
  localparam int FWB = IB + 1;
  logic [NR*FOB-1:0] f_own_q;
  logic [NR*FWB-1:0] f_waited_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      f_own_q    <= '0;
      f_waited_q <= '0;
    end else begin
      for (int r = 0; r < NR; r++) begin
        f_own_q[r*FOB +: FOB] <= f_own_q[r*FOB +: FOB] - FOB'(rd_rvalid_o[r]) +
                                 (rd_gnt_o[r] ? FOB'(mem_len_o) + FOB'(1) : '0);
        if (!rd_req_i[r] || rd_gnt_o[r]) f_waited_q[r*FWB +: FWB] <= '0;
        else if (|rd_gnt_o) f_waited_q[r*FWB +: FWB] <= f_waited_q[r*FWB +: FWB] + FWB'(1);
      end
    end
  end
  // Reader r's place after reader l in the round robin: 1 .. NR (NR: r is l).
  function automatic int f_dist(input logic [IB-1:0] l, input int r);
    f_dist = r > 32'(l) ? r - 32'(l) : r + NR - 32'(l);
  endfunction
  `MCADSW_ASSERT(BurstsWithinQueue, 32'(nids_q) <= OUTS)
  `MCADSW_ASSERT(HeldReadHasRoom, !(hold_q && !hold_wr_q) || rd_ok)   // presented with room
  `MCADSW_ASSERT(HeadBeatWithinBurst, nids_q == '0 ? beat_q == '0 : beat_q <= lens_q[3:0])
  `MCADSW_ASSERT(LastServedIsAReader, 32'(last_q) < NR && (!hold_q || hold_wr_q || 32'(hold_id_q) < NR))
  for (genvar i = 0; i < OUTS; i++) begin : g_f_ids
    `MCADSW_ASSERT(QueuedIdIsAReader, 32'(nids_q) <= i || 32'(ids_q[i*IB +: IB]) < NR)
  end
  for (genvar r = 0; r < NR; r++) begin : g_f_reader
    logic [FOB-1:0] queued;                // r's beats in the queue, less the head's returned
    always_comb begin
      queued = '0;
      for (int i = 0; i < OUTS; i++)
        if (i < 32'(nids_q) && ids_q[i*IB +: IB] == IB'(r)) queued = queued + FOB'(lens_q[i*4 +: 4]) + FOB'(1);
      if (nids_q != '0 && ids_q[IB-1:0] == IB'(r)) queued = queued - FOB'(beat_q);
    end
    `MCADSW_ASSERT(OwnBeatsQueued, f_own_q[r*FOB +: FOB] == queued)
    `MCADSW_ASSERT(ReadDataOnlyToAReaderOwed, !rd_rvalid_o[r] || f_own_q[r*FOB +: FOB] != '0)
    `MCADSW_ASSERT(RoundRobinBound, 32'(f_waited_q[r*FWB +: FWB]) + f_dist(last_q, r) <= NR)
    `MCADSW_ASSERT(HeldReadNoFurther, !(hold_q && !hold_wr_q && f_waited_q[r*FWB +: FWB] != '0) ||
                                      f_dist(last_q, 32'(hold_id_q)) <= f_dist(last_q, r))
  end
`endif

  // Events the block's proof must reach (formal only): each kind of grant, read data
  // routed, and a write that waits behind a held read.
  `MCADSW_COVER(ReadGranted, |rd_gnt_o)
  `MCADSW_COVER(WriteGranted, wr_gnt_o)
  `MCADSW_COVER(ReadDataRouted, |rd_rvalid_o)
  `MCADSW_COVER(WriteBehindHeldRead, hold_q && !hold_wr_q && wr_req_i)

endmodule

`default_nettype wire
