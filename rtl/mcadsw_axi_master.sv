// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// AXI4 master (docs/blocks/soc_top.md section 3): the engine's 32-bit
// request/grant memory port (docs/memory_map.md) on an AXI4 bus, one ID (all
// responses in order), 32-bit data, INCR bursts.
//
// Reads: each granted read is one AR, registered, of mem_len_i + 1 beats
// (ARLEN = mem_len_i; the engine's readers ask for bursts in the column-tiled
// layout and never across 4 KiB); up to ROUTS beats in flight; RREADY is always
// high, R beats go back to the engine as rvalid/rdata (the engine's readers
// take a word every cycle).
// Writes: granted writes are buffered (WD beats) and gathered into bursts of
// contiguous words: a burst is closed by a cycle without a write request, by a
// write that does not continue it, by BL beats, or before a 4 KiB boundary.
// A closed burst goes out as one AW (ARLEN = beats - 1) and its W beats (WLAST
// on the last), W never ahead of the burst's closing; at most BOUTS bursts
// wait for their B. BREADY is always high.
// wr_idle_o: no write requested, buffered, issued or unanswered: the engine
// waits for it before reading back what it wrote (LR post stage) and before
// done. drain_i (abort, response error): nothing more is granted, the writes
// already granted go out, read data is not passed on; idle_o says when every
// transaction has its response.
// Responses: RRESP / BRESP SLVERR or DECERR (bit 1 set) pulse rd_err_o /
// wr_err_o.
// SLICE (the FPGA target): requests are granted into a two-entry buffer, the
// grant is its room (a register), and the reads and writes above are taken from
// the buffer's head: the engine's request paths end at the buffer instead of
// running through this block's decisions and back as the grant. Entries already
// granted go out during a drain; the idles count them.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_axi_master #(
  parameter int AW    = 32,
  parameter int BL    = 16,   // longest write burst, beats
  parameter int WD    = 16,   // write buffer, beats (at least BL)
  parameter int ROUTS = 32,   // read beats in flight
  parameter int BOUTS = 7,    // write bursts waiting for B
  parameter bit SLICE = 1'(mcadsw_pkg::FPGA)  // requests through a two-entry buffer
) (
  input  logic          clk_i,
  input  logic          rst_ni,
  // Engine port (request/grant, docs/memory_map.md)
  input  logic          mem_req_i,
  output logic          mem_gnt_o,
  input  logic          mem_we_i,
  input  logic [3:0]    mem_be_i,
  input  logic [AW-1:0] mem_addr_i,
  input  logic [3:0]    mem_len_i,     // read: beats - 1
  input  logic [31:0]   mem_wdata_i,
  output logic          mem_rvalid_o,
  output logic [31:0]   mem_rdata_o,
  // Control and status
  input  logic          drain_i,
  output logic          wr_idle_o,
  output logic          idle_o,
  output logic          rd_err_o,
  output logic          wr_err_o,
  // AXI4 master: read address and data
  output logic          m_arvalid_o,
  input  logic          m_arready_i,
  output logic [AW-1:0] m_araddr_o,
  output logic [7:0]    m_arlen_o,
  output logic [2:0]    m_arsize_o,
  output logic [1:0]    m_arburst_o,
  input  logic          m_rvalid_i,
  output logic          m_rready_o,
  input  logic [31:0]   m_rdata_i,
  input  logic [1:0]    m_rresp_i,
  input  logic          m_rlast_i,
  // AXI4 master: write address, data, response
  output logic          m_awvalid_o,
  input  logic          m_awready_i,
  output logic [AW-1:0] m_awaddr_o,
  output logic [7:0]    m_awlen_o,
  output logic [2:0]    m_awsize_o,
  output logic [1:0]    m_awburst_o,
  output logic          m_wvalid_o,
  input  logic          m_wready_i,
  output logic [31:0]   m_wdata_o,
  output logic [3:0]    m_wstrb_o,
  output logic          m_wlast_o,
  input  logic          m_bvalid_i,
  output logic          m_bready_o,
  input  logic [1:0]    m_bresp_i
);

  localparam int RB = $clog2(ROUTS + 1);
  localparam int BB = $clog2(BOUTS + 1);
  localparam int LB = $clog2(BL);          // burst length - 1
  localparam int NB = $clog2(BL + 1);      // beats of the open burst
  localparam int DB = $clog2(WD);          // write buffer index
  localparam int ND = 2;                   // closed bursts queued (AW and W each)

  if (BL < 1 || BL > 256 || WD < BL || (WD & (WD - 1)) != 0 || BOUTS < 1 ||
      ROUTS < 1) begin : g_bad_param
    mcadsw_error_axi_master_bad_burst_or_buffer_size u_error ();
  end

  assign m_arsize_o  = 3'd2;     // 4 bytes a beat
  assign m_arburst_o = 2'b01;    // INCR
  assign m_awsize_o  = 3'd2;
  assign m_awburst_o = 2'b01;
  assign m_rready_o  = 1'b1;
  assign m_bready_o  = 1'b1;

  // ---- The request taken: the port's, or the head of the buffer (SLICE) --------------
  logic          s_req, s_we, s_drain, s_buf_wr, s_buf_any;
  logic [3:0]    s_be, s_len;
  logic [AW-1:0] s_addr;
  logic [31:0]   s_wdata;
  logic          rd_take, wr_take;
  if (SLICE) begin : g_slice
    localparam int EW = 1 + 4 + AW + 4 + 32;   // {we, be, addr, len, wdata}
    logic [2*EW-1:0] ent_q;                    // entry 0: the head
    logic [1:0]      n_q;
    logic            accept, pop;
    logic [EW-1:0]   in_ent;                   // the request granted this cycle
    assign in_ent    = {mem_we_i, mem_be_i, mem_addr_i, mem_len_i, mem_wdata_i};
    assign mem_gnt_o = !drain_i && n_q != 2'd2;
    assign accept    = mem_req_i && mem_gnt_o;
    assign pop       = rd_take || wr_take;
    assign s_req     = n_q != 2'd0;
    assign {s_we, s_be, s_addr, s_len, s_wdata} = ent_q[0 +: EW];
    assign s_drain   = 1'b0;                   // granted before the drain: they go out
    assign s_buf_any = n_q != 2'd0;
    assign s_buf_wr  = (n_q != 2'd0 && ent_q[EW-1]) || (n_q == 2'd2 && ent_q[2*EW-1]);
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ent_q <= '0;
        n_q   <= '0;
      end else begin
        logic [2*EW-1:0] e;
        logic [1:0]      n;
        e = ent_q;
        n = n_q;
        if (pop) begin
          e = e >> EW;
          n = n - 2'd1;
        end
        if (accept) begin
          if (n == 2'd0) e[0 +: EW] = in_ent;
          else           e[EW +: EW] = in_ent;
          n = n + 2'd1;
        end
        ent_q <= e;
        n_q   <= n;
      end
    end
  end else begin : g_port
    assign s_req     = mem_req_i;
    assign s_we      = mem_we_i;
    assign s_be      = mem_be_i;
    assign s_addr    = mem_addr_i;
    assign s_len     = mem_len_i;
    assign s_wdata   = mem_wdata_i;
    assign s_drain   = drain_i;
    assign s_buf_any = 1'b0;
    assign s_buf_wr  = 1'b0;
    assign mem_gnt_o = rd_take || wr_take;
  end

  // ---- Reads ---------------------------------------------------------------------------
  logic          arvalid_q;
  logic [AW-1:0] araddr_q;
  logic [3:0]    arlen_q;
  logic [RB-1:0] rd_out_q;                 // beats of reads taken from the engine, R not yet seen
  assign rd_take = s_req && !s_we && !s_drain && (!arvalid_q || m_arready_i) &&
                   (RB + 1)'(rd_out_q) + (RB + 1)'(s_len) < (RB + 1)'(ROUTS);
  assign m_arvalid_o  = arvalid_q;
  assign m_araddr_o   = araddr_q;
  assign m_arlen_o    = 8'(arlen_q);
  assign mem_rvalid_o = m_rvalid_i && !drain_i;
  assign mem_rdata_o  = m_rdata_i;
  assign rd_err_o     = m_rvalid_i && m_rresp_i[1];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      arvalid_q <= 1'b0;
      araddr_q  <= '0;
      arlen_q   <= '0;
      rd_out_q  <= '0;
    end else begin
      if (rd_take) begin
        arvalid_q <= 1'b1;
        araddr_q  <= s_addr;
        arlen_q   <= s_len;
      end else if (m_arready_i) begin
        arvalid_q <= 1'b0;
      end
      rd_out_q <= rd_out_q + (rd_take ? RB'(s_len) + RB'(1) : '0) - RB'(m_rvalid_i);
    end
  end

  // ---- Write buffer and the open burst -------------------------------------------------
  logic [WD*36-1:0] wbuf_q;                // {strobes, data} a beat
  logic [DB:0]      wwr_q, wrd_q;          // write / read pointers, one wrap bit
  logic             wbuf_full;
  assign wbuf_full = (wwr_q ^ wrd_q) == {1'b1, DB'(0)};

  logic [AW-1:0] ob_addr_q, ob_next_q;     // open burst: first word, the word that continues it
  logic [NB-1:0] ob_n_q;                   // its beats (0: none open)

  // Closed bursts: AW queue {addr, len} and W queue {len}, ND deep each, pushed together.
  logic [ND*(AW+LB)-1:0] awq_q;
  logic [ND*LB-1:0]      wlq_q;
  logic [1:0]            awq_n_q, wlq_n_q;
  logic                  desc_room;
  assign desc_room = awq_n_q != 2'(ND) && wlq_n_q != 2'(ND);

  logic wr_req, contig, need_close, do_close;
  assign wr_req     = s_req && s_we && !s_drain;
  assign contig     = s_addr == ob_next_q && s_addr[11:0] != 12'd0;
  assign need_close = ob_n_q != '0 && (ob_n_q == NB'(BL) || !contig);
  assign wr_take    = wr_req && !wbuf_full && (!need_close || desc_room);
  assign do_close   = ob_n_q != '0 && desc_room && (!wr_req || need_close);

  // ---- AW, W, B -------------------------------------------------------------------------
  logic [BB-1:0] b_out_q;                  // AWs accepted, B not yet seen
  logic [LB-1:0] wbeat_q;                  // beat of the current W burst
  logic          aw_go, w_go;
  assign m_awvalid_o = awq_n_q != 2'd0 && b_out_q != BB'(BOUTS);
  assign m_awaddr_o  = awq_q[LB +: AW];
  assign m_awlen_o   = 8'(awq_q[0 +: LB]);
  assign m_wvalid_o  = wlq_n_q != 2'd0;
  assign m_wdata_o   = wbuf_q[32'(wrd_q[DB-1:0])*36 +: 32];
  assign m_wstrb_o   = wbuf_q[32'(wrd_q[DB-1:0])*36 + 32 +: 4];
  assign m_wlast_o   = wbeat_q == wlq_q[0 +: LB];
  assign aw_go       = m_awvalid_o && m_awready_i;
  assign w_go        = m_wvalid_o && m_wready_i;
  assign wr_err_o    = m_bvalid_i && m_bresp_i[1];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wbuf_q    <= '0;
      wwr_q     <= '0;
      wrd_q     <= '0;
      ob_addr_q <= '0;
      ob_next_q <= '0;
      ob_n_q    <= '0;
      awq_q     <= '0;
      wlq_q     <= '0;
      awq_n_q   <= '0;
      wlq_n_q   <= '0;
      b_out_q   <= '0;
      wbeat_q   <= '0;
    end else begin
      if (wr_take) begin
        for (int i = 0; i < WD; i++)      // decoded: no shifter across the buffer
          if (wwr_q[DB-1:0] == DB'(i)) wbuf_q[i*36 +: 36] <= {s_be, s_wdata};
        wwr_q <= wwr_q + 1'b1;
      end
      if (w_go) wrd_q <= wrd_q + 1'b1;
      // The open burst: continued, closed, or started.
      if (wr_take && (ob_n_q == '0 || do_close)) begin
        ob_addr_q <= s_addr;
        ob_n_q    <= NB'(1);
      end else if (wr_take) begin
        ob_n_q <= ob_n_q + NB'(1);
      end else if (do_close) begin
        ob_n_q <= '0;
      end
      if (wr_take) ob_next_q <= s_addr + AW'(4);
      // AW queue: shift out at the head (slot 0), append at awq_n.
      begin
        logic [ND*(AW+LB)-1:0] q;
        logic [1:0]            n;
        q = awq_q;
        n = awq_n_q;
        if (aw_go) begin
          q = q >> (AW + LB);
          n = n - 2'd1;
        end
        if (do_close) begin
          q[32'(n)*(AW+LB) +: AW+LB] = {ob_addr_q, LB'(ob_n_q - NB'(1))};
          n = n + 2'd1;
        end
        awq_q   <= q;
        awq_n_q <= n;
      end
      begin
        logic [ND*LB-1:0] q;
        logic [1:0]       n;
        q = wlq_q;
        n = wlq_n_q;
        if (w_go && m_wlast_o) begin
          q = q >> LB;
          n = n - 2'd1;
        end
        if (do_close) begin
          q[32'(n)*LB +: LB] = LB'(ob_n_q - NB'(1));
          n = n + 2'd1;
        end
        wlq_q   <= q;
        wlq_n_q <= n;
      end
      if (w_go) wbeat_q <= m_wlast_o ? '0 : wbeat_q + LB'(1);
      b_out_q <= b_out_q + BB'(aw_go) - BB'(m_bvalid_i);
    end
  end

  assign wr_idle_o = !(mem_req_i && mem_we_i) && !s_buf_wr && ob_n_q == '0 && awq_n_q == 2'd0 &&
                     wlq_n_q == 2'd0 && b_out_q == '0;
  assign idle_o    = wr_idle_o && rd_out_q == '0 && !s_buf_any;

  // The beats of a burst are counted, RLAST is checked in simulation only.
  logic unused;
  assign unused = m_rlast_i ^ m_rresp_i[0] ^ m_bresp_i[0];

`ifdef MCADSW_CHECKS
  // verilator coverage_off
  // The lengths of the read bursts in flight, for the RLAST check.
  logic [ROUTS*4-1:0] rlen_q;
  logic [RB-1:0]      rlen_n_q;
  logic [3:0]         rbeat_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rlen_q   <= '0;
      rlen_n_q <= '0;
      rbeat_q  <= '0;
    end else begin
      logic [ROUTS*4-1:0] q;
      logic [RB-1:0]      n;
      q = rlen_q;
      n = rlen_n_q;
      if (m_rvalid_i && m_rlast_i) begin
        q = q >> 4;
        n = n - RB'(1);
      end
      if (rd_take) begin
        q[32'(n)*4 +: 4] = s_len;
        n = n + RB'(1);
      end
      rlen_q   <= q;
      rlen_n_q <= n;
      if (m_rvalid_i) rbeat_q <= m_rlast_i ? '0 : rbeat_q + 4'd1;
    end
  end
  // verilator coverage_on
`endif
  // What the slave must keep (the AXI memory model of the harness checks the bus
  // itself), and the master's own invariant.
  `MCADSW_ASSUME(ReadBeatInFlight, !(m_rvalid_i && rd_out_q == '0))
  `MCADSW_ASSUME(RlastOnLastBeat, !(m_rvalid_i && m_rlast_i != (rbeat_q == rlen_q[3:0])))
  `MCADSW_ASSUME(WriteResponseInFlight, !(m_bvalid_i && b_out_q == '0))
  `MCADSW_ASSERT(OneGrantReadOrWrite, !(wr_take && rd_take))

`ifdef FORMAL
  // The proof's reference (make formal, formal/axi_master.sby), on the engine's port
  // (SLICE = 0), with the invariants that close it by induction:
  // - reads: the slave's beats outstanding (ARs accepted) and the engine's (reads
  //   granted): the block's count is the slave's plus the AR waiting; read data goes to
  //   the engine only while it is owed some;
  // - writes: the lengths of the AW bursts accepted whose W burst is not complete (f_aq),
  //   or of the W bursts complete whose AW is not accepted (f_wq), matched in order (each
  //   W burst as long as its AW); the AW and W queues hold the same closed bursts, one
  //   queue ahead of the other by the unmatched ones; the write buffer holds exactly the
  //   beats of the W bursts not yet sent and of the open burst; no burst crosses 4 KiB.
  if (!SLICE) begin : g_f
    localparam int FRB = RB + 5;
    logic [FRB-1:0]    f_r_out_q, f_rd_eng_q;
    logic [ND*LB-1:0]  f_aq_q, f_wq_q;
    logic [1:0]        f_an_q, f_wn_q;
    logic [LB-1:0]     f_wbeats_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        f_r_out_q <= '0; f_rd_eng_q <= '0;
        f_aq_q <= '0; f_wq_q <= '0; f_an_q <= '0; f_wn_q <= '0; f_wbeats_q <= '0;
      end else begin
        logic [ND*LB-1:0] aq, wq;
        logic [1:0]       an, wn;
        f_r_out_q  <= f_r_out_q + (m_arvalid_o && m_arready_i ? FRB'(arlen_q) + FRB'(1) : '0)
                                - FRB'(m_rvalid_i);
        f_rd_eng_q <= f_rd_eng_q + (mem_req_i && mem_gnt_o && !mem_we_i ? FRB'(mem_len_i) + FRB'(1) : '0)
                                 - FRB'(m_rvalid_i);
        aq = f_aq_q; wq = f_wq_q; an = f_an_q; wn = f_wn_q;
        if (aw_go) begin
          aq[32'(an)*LB +: LB] = awq_q[0 +: LB];
          an = an + 2'd1;
        end
        if (w_go) begin
          if (m_wlast_o) begin
            wq[32'(wn)*LB +: LB] = f_wbeats_q;
            wn = wn + 2'd1;
            f_wbeats_q <= '0;
          end else begin
            f_wbeats_q <= f_wbeats_q + LB'(1);
          end
        end
        if (an != '0 && wn != '0) begin
          aq = aq >> LB; wq = wq >> LB; an = an - 2'd1; wn = wn - 2'd1;
        end
        f_aq_q <= aq; f_wq_q <= wq; f_an_q <= an; f_wn_q <= wn;
      end
    end
    `MCADSW_ASSUME(ReadBeatOfAnAcceptedAr, !m_rvalid_i || f_r_out_q != '0)
    `MCADSW_ASSERT(ReadBeatsCounted, 32'(rd_out_q) == 32'(f_r_out_q) + (arvalid_q ? 32'(arlen_q) + 1 : 0) &&
                                     f_rd_eng_q == FRB'(rd_out_q) && 32'(rd_out_q) <= ROUTS)
    `MCADSW_ASSERT(ReadDataOnlyWhenOwed, !mem_rvalid_o || f_rd_eng_q != '0)
    `MCADSW_ASSERT(IdleNoReadOutstanding, !idle_o || (f_r_out_q == '0 && !m_arvalid_o))
    `MCADSW_ASSERT(AReadWithinItsPage, !arvalid_q || 32'(araddr_q[11:0]) + 4 * (32'(arlen_q) + 1) <= 4096)

    // The AW and W queues against the unmatched bursts.
    function automatic logic [LB-1:0] f_awl(input int i);     // AW queue entry i's length
      f_awl = awq_q[i*(AW+LB) +: LB];
    endfunction
    logic f_queues_ok;
    always_comb begin
      int a, w;
      a = 32'(awq_n_q);
      w = 32'(wlq_n_q);
      f_queues_ok = a <= ND && w <= ND && (f_an_q == '0 || f_wn_q == '0);
      if (f_an_q != '0) begin
        f_queues_ok = f_queues_ok && w == a + 32'(f_an_q);
        for (int i = 0; i < ND; i++) begin
          if (i < 32'(f_an_q)) f_queues_ok = f_queues_ok && f_aq_q[i*LB +: LB] == wlq_q[i*LB +: LB];
          if (i < a && i + 32'(f_an_q) < ND)
            f_queues_ok = f_queues_ok && f_awl(i) == wlq_q[(i + 32'(f_an_q))*LB +: LB];
        end
      end else if (f_wn_q != '0) begin
        f_queues_ok = f_queues_ok && a == w + 32'(f_wn_q);
        for (int i = 0; i < ND; i++) begin
          if (i < 32'(f_wn_q)) f_queues_ok = f_queues_ok && f_wq_q[i*LB +: LB] == f_awl(i);
          if (i < w && i + 32'(f_wn_q) < ND)
            f_queues_ok = f_queues_ok && wlq_q[i*LB +: LB] == f_awl(i + 32'(f_wn_q));
        end
      end else begin
        f_queues_ok = f_queues_ok && a == w;
        for (int i = 0; i < ND; i++)
          if (i < a) f_queues_ok = f_queues_ok && f_awl(i) == wlq_q[i*LB +: LB];
      end
    end
    `MCADSW_ASSERT(QueuesMatch, f_queues_ok)
    `MCADSW_ASSERT(WBeatOfTheHeadBurst, f_wbeats_q == wbeat_q &&
                                        (wlq_n_q == '0 ? wbeat_q == '0 : wbeat_q <= wlq_q[0 +: LB]))
    // The write buffer: the beats of the W bursts not sent and of the open burst.
    logic [31:0] f_beats;
    always_comb begin
      f_beats = 32'(ob_n_q) - 32'(wbeat_q);
      for (int i = 0; i < ND; i++) if (i < 32'(wlq_n_q)) f_beats = f_beats + 32'(wlq_q[i*LB +: LB]) + 1;
    end
    `MCADSW_ASSERT(BufferHoldsTheBeats, 32'((DB + 1)'(wwr_q - wrd_q)) == f_beats && f_beats <= WD &&
                                        32'(ob_n_q) <= BL && 32'(b_out_q) <= BOUTS)
    logic [AW-1:0] f_ob_end;                               // the word after the open burst
    assign f_ob_end = ob_addr_q + AW'({ob_n_q, 2'b00});
    `MCADSW_ASSERT(OpenBurstContiguous, ob_n_q == '0 || (ob_next_q == f_ob_end && ob_addr_q[1:0] == 2'b00))
    `MCADSW_ASSERT(OpenBurstInItsPage, ob_n_q == '0 || 32'(ob_addr_q[11:0]) + 4 * 32'(ob_n_q) <= 4096)
    for (genvar i = 0; i < ND; i++) begin : g_f_aw
      `MCADSW_ASSERT(QueuedBurstInItsPage, 32'(awq_n_q) <= i ||
                     (awq_q[i*(AW+LB) + LB +: 2] == 2'b00 &&
                      32'(awq_q[i*(AW+LB) + LB +: 12]) + 4 * (32'(awq_q[i*(AW+LB) +: LB]) + 1) <= 4096))
    end
  end
`endif

  // Events the block's proof must reach (formal only): a read burst's last beat, a
  // write burst's last beat, a write response, and idle again after them.
  `MCADSW_COVER(ReadBurstDone, m_rvalid_i && m_rready_o && m_rlast_i)
  `MCADSW_COVER(WriteBurstDone, w_go && m_wlast_o)
  `MCADSW_COVER(WriteAnswered, m_bvalid_i && m_bready_o)

endmodule

`default_nettype wire
