// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Cost aggregator and WTA (paper Sec. V-D, Figs. 12-14).
//
// One job is one 18-pixel row of the current block: for d = 0 .. D-1 the
// vertical side reads 6 column groups of LANES x WINDOW census codes (left, and
// right at x - d) with their vertical weights, one group a cycle, and writes the
// 48 vertical costs of d into one bank of the ping-pong buffer. When a bank is
// full, the horizontal side reads it for 6 cycles (33 costs a cycle, 3 final
// costs) while the vertical side fills the other bank with d + 1 (Fig. 13).
// The WTA keeps the best d of the 18 pixels and emits them, 3 a cycle, on the
// last disparity. Jobs run back to back: 6*D cycles a row in steady state
// (6 ceil(D / P) with P disparities a step, below).
//
// Read ports are synchronous: data arrive the cycle after the address (the
// census and weight buffers are RAMs). ASIC target: a step reads LANES left
// columns and LANES + P - 1 right ones at once (lrd_*, rrd_*: the first column),
// each as the window's WINDOW rows (the census buffer selects them by vrd_row_o).
// Pipeline, from the issue cycle c of a column group: c+1 census/weight data and
// Hamming + vertical sum, c+2 ping-pong write; after the 6th group, c+8 bank
// handed to the horizontal side, c+9 ping-pong read (registered) and horizontal
// weight address, c+10 horizontal sum, c+11 WTA, c+12 disparity out. The registered
// ping-pong read keeps its multiplexers out of the horizontal sum (docs/synthesis.md 1).
//
// FPGA target (mcadsw_pkg::FPGA, docs/blocks/fpga_target.md): the vertical side
// takes a row's column groups in the outer loop and its steps in the inner one
// (group g, d = 0 .. D-1, then g + 1) and writes each group's costs into a
// transposition buffer, a block RAM of LANES costs a word at (weight slot, step,
// group). Once a row's last word is written, a reader takes the row back out in
// the horizontal side's order (d, then g), a word a cycle, into the same
// ping-pong buffer, horizontal aggregators and WTA: the same sums in the same
// order, one row later. The census reads narrow in this order (P = 1): a group's 8
// left columns are the same for all its steps, and right lane l at step d + 1 is
// lane l - 1 at d. The left view is read one column a cycle (one port) into a
// shadow register of the next group's 8 column words, copied to the lanes when the
// group starts; the right view has two ports: port 0 reads lane 0's column each
// step (lanes 1 .. 7 are a shift register behind it), port 1 the next group's
// first step into a second shadow. The next row's first group is read during the
// last group (the columns do not depend on the block row); a row 0 (a new block,
// another census bank) reads it again. A group starts once its shadows are full:
// at most LANES + 1 cycles after the previous group started, so it waits only when
// D < 9, and a block's first row waits that long. A port's column word (the
// window's CROWS rows) is folded as it is read to the WINDOW taps of its block
// row, in the census buffer's folded order (tap k is row k + WINDOW when k < the
// block row, row k otherwise), so the lanes and shadows hold taps only; the next
// row's first group is folded for the next row (a block's rows come in order).
// The transposition buffer holds a row per weight slot (WEIGHT_SLOTS = 3): the
// vertical side fills row r + 1's while the reader empties row r's, and a slot is
// refilled only after the weight generator has taken it back, which it does on the
// row's last horizontal read, after the reader's last. The vertical sums take
// VLAT = 3 cycles and the horizontal ones HLAT = 2 (registered inputs and terms).
//
// P disparities a step (docs/blocks/cost_agg.md 1): a step evaluates d ..
// d + P - 1 (d = vrd_d_o, a multiple of P). The right census input holds LANES +
// P - 1 lanes, lane j at image column (column of left lane j - (P - 1)) - d, so
// disparity d + p of left lane l is right lane l + P - 1 - p. The vertical
// aggregator, the ping-pong buffer and the horizontal aggregators are P copies
// (the weights are shared); lanes with d + p >= D travel masked to the WTA.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_cost_agg #(
  parameter int DMAX   = mcadsw_pkg::DMAX,
  parameter int BLOCK  = mcadsw_pkg::BLOCK,
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int LANES  = mcadsw_pkg::LANES,
  parameter int HAGG   = mcadsw_pkg::HAGG,
  parameter int GROUPS = mcadsw_pkg::GROUPS,
  parameter int P      = 1,                  // disparities a step (1, 2, 4)
  parameter bit GORDER = 1'(mcadsw_pkg::FPGA), // vertical side group-outer (FPGA target)
  parameter int NSLOT  = mcadsw_pkg::WEIGHT_SLOTS,
  parameter int SLB    = $clog2(NSLOT),
  parameter int CB     = mcadsw_pkg::CENSUS_BITS,
  parameter int WB     = mcadsw_pkg::WEIGHT_CODE_BITS,
  parameter int VB     = mcadsw_pkg::VCOST_BITS,
  parameter int FB     = mcadsw_pkg::FCOST_BITS,
  parameter int DB     = mcadsw_pkg::DISP_BITS,
  parameter int RB     = $clog2(BLOCK),    // block row index width
  parameter int GB     = $clog2(GROUPS),   // group index width
  parameter int NB     = $clog2(DMAX + 1), // width of D
  parameter int CLB    = $clog2(GROUPS * LANES), // Ev column index width
  parameter int SPB    = DB + 4,                 // sub-pixel value: 16 d + offset
  parameter int CROWS  = GROUPS * LANES,         // census rows of a column (BLOCK + WINDOW - 1)
  parameter int RXB    = $clog2(GROUPS * LANES + DMAX - 1),  // right census column index width
  parameter int CRP    = GORDER ? 2 : 1,         // right census read ports
  parameter int CLW    = GORDER ? CROWS*CB : LANES*WINDOW*CB,          // left census read data
  parameter int CRW    = GORDER ? 2*CROWS*CB : (LANES+P-1)*WINDOW*CB   // right census read data
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  // Row jobs
  input  logic                          job_valid_i,
  output logic                          job_ready_o,
  input  logic [RB-1:0]                 job_row_i,    // block row 0 .. BLOCK-1
  input  logic [NB-1:0]                 job_disp_i,   // D, 1 .. DMAX
  input  logic [CLB-1:0]                job_last_col_i,  // last Ev column inside the image
  input  logic [SLB-1:0]                job_wslot_i,  // weight-buffer row slot of the row
  // Vertical weight buffer (data one cycle after address); block row of the census reads
  output logic                          vrd_en_o,
  output logic [RB-1:0]                 vrd_row_o,
  output logic [GB-1:0]                 vrd_grp_o,    // columns LANES*grp ..
  output logic [DB-1:0]                 vrd_d_o,      // the step's first disparity
  output logic [SLB-1:0]                vrd_slot_o,   // weight row slot
  input  logic [LANES*WINDOW*WB-1:0]    wv_i,
  // Census buffers (data one cycle after address; columns of the block's window).
  // ASIC target: one read each, LANES (left) and LANES + P - 1 (right) consecutive
  // columns, lane j tap k at (j WINDOW + k) CB; right lane j at column - d + j -
  // (P - 1), see above. FPGA target: a column word (CROWS codes) a port.
  output logic                          lrd_en_o,
  output logic [CLB-1:0]                lrd_col_o,
  output logic [CRP-1:0]                rrd_en_o,
  output logic [CRP*RXB-1:0]            rrd_col_o,
  input  logic [CLW-1:0]                cen_l_i,
  input  logic [CRW-1:0]                cen_r_i,
  // Horizontal weight buffer (data one cycle after address)
  output logic                          hrd_en_o,
  output logic [RB-1:0]                 hrd_row_o,
  output logic [GB-1:0]                 hrd_grp_o,    // pixels HAGG*grp ..
  output logic [SLB-1:0]                hrd_slot_o,   // weight row slot
  output logic                          hrd_rel_o,    // the row's last horizontal read
  input  logic [HAGG*WINDOW*WB-1:0]     wh_i,
  // Disparities, HAGG pixels a cycle; no back-pressure (the scheduler only
  // starts a job when the depth FIFO has room for its row)
  output logic                          disp_valid_o,
  output logic [RB-1:0]                 disp_row_o,
  output logic [GB-1:0]                 disp_grp_o,
  output logic [HAGG*DB-1:0]            disp_o,
  output logic                          busy_o,       // disparities still to come
  output logic                          vbusy_o,      // census and vertical weight reads still
                                                      // to come (busy_o on the ASIC target)
  // Sub-pixel values (docs/algorithm.md 12.6), two cycles after the disparities
  output logic                          sub_valid_o,
  output logic [RB-1:0]                 sub_row_o,
  output logic [GB-1:0]                 sub_grp_o,
  output logic [HAGG*SPB-1:0]           sub_o,
  output logic [HAGG*DB-1:0]            sub_d_o,      // their integer disparities
  output logic                          sub_busy_o    // sub-pixel values still to come
);
// The block test reads the vertical and final costs with their tags (ev, v2_*_q,
// fc, h3_*_q) by hierarchical reference (tests/rtl/cost_agg_tb.sv).

  if (GROUPS * LANES != BLOCK + WINDOW - 1 || GROUPS * HAGG != BLOCK ||
      (1 << DB) < DMAX || !(P == 1 || P == 2 || P == 4) || DMAX % P != 0 ||
      (GORDER && (NSLOT < 3 || P != 1 || CROWS != BLOCK + WINDOW - 1))) begin : g_bad_param
    mcadsw_error_cost_agg_geometry u_error ();
  end

  // A tag travels with each column group and output group: valid, first
  // (d == 0), last (the step holds D - 1), lane mask (d + p < D), block row, d,
  // group. Stages: v1 data cycle,
  // v2 ping-pong write, h0 bank handover, h1 ping-pong read and horizontal
  // weight address, h2 horizontal sum, h3 WTA.

  // ---- Vertical side: issue column-group reads ----------------------------
  logic          busy_q;
  logic [RB-1:0] row_q;
  logic [DB-1:0] d_q, dlast_q, dmax_q;   // step's first d, last step's first d, D - 1
  logic [P-1:0]  lanes;                  // lane p: d + p < D
  logic [CLB-1:0] last_col_q;
  logic [SLB-1:0] slot_q;
  logic [GB-1:0] grp_q;
  logic          issue_last;
  logic          accept;

  logic          tr_slot_free;   // the job's slot holds no row still to be read (FPGA)
  logic          vstall;         // the group's census columns are not in yet (FPGA)
  logic          issue;          // a step of a column group is issued
  assign issue       = busy_q && !vstall;
  assign issue_last  = issue && d_q == dlast_q && grp_q == GB'(GROUPS - 1);
  assign job_ready_o = (!busy_q || issue_last) && tr_slot_free;
  assign accept      = job_valid_i && job_ready_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q  <= 1'b0;
      row_q   <= '0;
      d_q     <= '0;
      dlast_q <= '0;
      dmax_q  <= '0;
      grp_q   <= '0;
      last_col_q <= '0;
      slot_q  <= '0;
    end else if (accept) begin
      last_col_q <= job_last_col_i;
      slot_q  <= job_wslot_i;
      busy_q  <= 1'b1;
      row_q   <= job_row_i;
      d_q     <= '0;
      dlast_q <= DB'(job_disp_i - NB'(1)) & ~(DB'(P - 1));
      dmax_q  <= DB'(job_disp_i - NB'(1));
      grp_q   <= '0;
    end else if (issue) begin
      if (issue_last) begin
        busy_q <= 1'b0;
      end else if (GORDER) begin
        // Group outer: the row's steps for group g, then g + 1.
        if (d_q == dlast_q) begin
          d_q   <= '0;
          grp_q <= grp_q + GB'(1);
        end else begin
          d_q <= d_q + DB'(P);
        end
      end else if (grp_q == GB'(GROUPS - 1)) begin
        grp_q <= '0;
        d_q   <= d_q + DB'(P);
      end else begin
        grp_q <= grp_q + GB'(1);
      end
    end
  end

  assign vrd_en_o  = issue;
  assign vrd_row_o = row_q;
  assign vrd_grp_o = grp_q;
  assign vrd_d_o   = d_q;
  assign vrd_slot_o = slot_q;

  // d_q + p < D, i.e. p <= D - 1 - d_q (d_q <= D - 1 while busy); lane 0 always.
  assign lanes[0] = 1'b1;
  for (genvar p = 1; p < P; p++) begin : g_lanes
    assign lanes[p] = DB'(p) <= dmax_q - d_q;
  end

  logic          v1_valid_q, v1_first_q, v1_last_q, v2_valid_q, v2_first_q, v2_last_q;
  logic [RB-1:0] v1_row_q, v2_row_q;
  logic [DB-1:0] v1_d_q, v2_d_q;
  logic [GB-1:0] v1_grp_q, v2_grp_q;
  logic [CLB-1:0] v1_lcol_q, v2_lcol_q;  // last in-image Ev column of the block
  logic [SLB-1:0] v1_slot_q, v2_slot_q, h0_slot_q, h1_slot_q;
  logic [P-1:0]  v1_lanes_q, v2_lanes_q, h0_lanes_q, h1_lanes_q, h2_lanes_q, h3_lanes_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      {v1_valid_q, v1_first_q, v1_last_q, v1_row_q, v1_d_q, v1_grp_q, v1_lcol_q, v1_slot_q,
       v1_lanes_q} <= '0;
      {v2_valid_q, v2_first_q, v2_last_q, v2_row_q, v2_d_q, v2_grp_q, v2_lcol_q, v2_slot_q,
       v2_lanes_q} <= '0;
    end else begin
      {v1_valid_q, v1_first_q, v1_last_q, v1_row_q, v1_d_q, v1_grp_q, v1_lcol_q, v1_slot_q,
       v1_lanes_q} <= {issue, d_q == '0, d_q == dlast_q, row_q, d_q, grp_q, last_col_q, slot_q,
                       lanes};
      {v2_valid_q, v2_first_q, v2_last_q, v2_row_q, v2_d_q, v2_grp_q, v2_lcol_q, v2_slot_q,
       v2_lanes_q} <= v1x;
    end
  end

  // The tags of v1 reach v2 with the vertical sums: one cycle, or VLAT = 3 on the
  // FPGA target (mcadsw_vert_agg's latency: inputs and products registered first).
  localparam int VLAT = (mcadsw_pkg::FPGA != 0) ? 3 : 1;
  localparam int VTW  = 3 + RB + DB + GB + CLB + SLB + P;
  logic [VTW-1:0] v1t, v1x;
  logic           vx_busy;            // tags on their way from v1 to v2
  assign v1t = {v1_valid_q, v1_first_q, v1_last_q, v1_row_q, v1_d_q, v1_grp_q, v1_lcol_q, v1_slot_q,
                v1_lanes_q};
  if (VLAT > 1) begin : g_vdelay
    mcadsw_tag_delay #(.W(VTW), .N(VLAT - 1)) u_delay (
      .clk_i, .rst_ni, .tags_i(v1t), .tags_o(v1x), .busy_o(vx_busy)
    );
  end else begin : g_vdirect
    assign v1x     = v1t;
    assign vx_busy = 1'b0;
  end

  // ---- Census lanes ------------------------------------------------------------
  // lanes_l, lanes_r: the vertical aggregator's census inputs in the v1 cycle, lane j
  // tap k at (j WINDOW + k) CB; right lane j at column - d + j - (P - 1).
  logic [LANES*WINDOW*CB-1:0]       lanes_l;
  logic [(LANES+P-1)*WINDOW*CB-1:0] lanes_r;
  logic                             feed_busy;   // census reads of the lane feed under way

  if (GORDER) begin : g_feed
    localparam int CWB = CROWS * CB;             // a census column word
    localparam int NB8 = $clog2(LANES + 1);
    // Next group's columns: group pf_grp_q, pf_n_q of LANES column reads issued,
    // the read of the previous cycle (pf_wr_q, slot pf_idx_q) written now.
    logic [GB-1:0]        pf_grp_q;
    logic [NB8-1:0]       pf_n_q;
    logic                 pf_wr_q;
    logic [NB8-1:0]       pf_idx_q;
    logic                 pf_rd, pf_ok;
    logic [RB-1:0]        pf_row_q;              // block row of group pf_grp_q
    // The lanes hold their WINDOW taps, folded when a column word is read.
    localparam int TWB = WINDOW * CB;            // a lane's taps
    logic [LANES*TWB-1:0] lq_q, lc_q;            // left: next group's columns, this group's
    logic [LANES*TWB-1:0] rp_q, rs_q;            // right: next group's first step, lanes now
                                                 // (lane 0 of each unused: port 0's taps)
    logic [CWB-1:0]       rword0, rword1;
    logic [TWB-1:0]       ltaps, rtaps0, rtaps1; // the ports' words folded
    assign rword0 = cen_r_i[0 +: CWB];
    assign rword1 = cen_r_i[CWB +: CWB];
    assign pf_rd  = pf_n_q != NB8'(LANES);
    assign pf_ok  = !pf_rd && !pf_wr_q;
    // A group's first step waits for its columns.
    assign vstall    = d_q == '0 && !(pf_ok && pf_grp_q == grp_q);
    assign feed_busy = pf_rd || pf_wr_q;

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        pf_grp_q <= '0;
        pf_row_q <= '0;
        pf_n_q   <= NB8'(LANES);        // nothing to read before a block's first row
        pf_wr_q  <= 1'b0;
        pf_idx_q <= '0;
      end else begin
        pf_wr_q  <= pf_rd;
        pf_idx_q <= pf_n_q;
        if (accept && job_row_i == '0) begin
          // A block's first row: group 0 of its bank.
          pf_grp_q <= '0;
          pf_row_q <= '0;
          pf_n_q   <= '0;
        end else if (issue && d_q == '0) begin
          // The group starts: read the next one (after the last, the next row's first;
          // a block's rows come in order, assertion NextRowPrefetched).
          pf_grp_q <= (grp_q == GB'(GROUPS - 1)) ? '0 : grp_q + GB'(1);
          pf_row_q <= (grp_q == GB'(GROUPS - 1)) ? row_q + RB'(1) : row_q;
          pf_n_q   <= '0;
        end else if (pf_rd) begin
          pf_n_q <= pf_n_q + NB8'(1);
        end
      end
    end

    always_ff @(posedge clk_i) begin
      for (int l = 0; l < LANES; l++)
        if (pf_wr_q && pf_idx_q == NB8'(l)) begin
          lq_q[l*TWB +: TWB] <= ltaps;
          rp_q[l*TWB +: TWB] <= rtaps1;
        end
      if (issue) begin
        if (d_q == '0) begin
          lc_q <= lq_q;
          rs_q <= rp_q;
        end else begin
          // Lane l takes lane l - 1's taps, lane 1 port 0's of the last step (the same
          // group, so the same block row).
          rs_q <= {rs_q[(LANES-1)*TWB-1 : TWB], rtaps0, {TWB{1'b0}}};
        end
      end
    end

    // Column reads: the next group's (left, right port 1) and lane 0's (right port 0).
    assign lrd_en_o  = pf_rd;
    assign lrd_col_o = CLB'(32'(pf_grp_q) * LANES + 32'(pf_n_q));
    assign rrd_en_o  = {pf_rd, issue};
    assign rrd_col_o = {RXB'(32'(pf_grp_q) * LANES + DMAX - 1 + 32'(pf_n_q)),
                        RXB'(32'(grp_q) * LANES + DMAX - 1 - 32'(d_q))};

    // A column word's taps in folded order for block row r: one 2:1 select a port
    // instead of one a lane. The shadows' words are folded for the row of the group
    // they are read for (pf_row_q), port 0's for the group in v1.
    function automatic logic [TWB-1:0] fold(input logic [CWB-1:0] col, input logic [RB-1:0] r);
      fold = col[TWB-1:0];
      for (int k = 0; k < CROWS - WINDOW; k++)
        if (32'(r) > k) fold[k*CB +: CB] = col[(k + WINDOW)*CB +: CB];
    endfunction
    assign ltaps  = fold(cen_l_i, pf_row_q);
    assign rtaps1 = fold(rword1, pf_row_q);
    assign rtaps0 = fold(rword0, v1_row_q);
    assign lanes_l = lc_q;
    assign lanes_r = {rs_q[LANES*TWB-1 : TWB], rtaps0};
    logic feed_unused;
    assign feed_unused = ^{rs_q[TWB-1:0], rp_q[TWB-1:0]};

    // The row a group's shadows were folded for is the row it runs in.
    `MCADSW_ASSERT(NextRowPrefetched, !(issue && d_q == '0) || pf_row_q == row_q)

    // The shadows are complete when a group copies them.
    `MCADSW_ASSERT(ShadowNotWrittenWhileCopied, !(pf_wr_q && issue && d_q == '0))
  end else begin : g_no_feed
    // ASIC target: the buffers deliver the lanes.
    assign vstall    = 1'b0;
    assign feed_busy = 1'b0;
    assign lrd_en_o  = issue;
    assign lrd_col_o = CLB'(32'(grp_q) * LANES);
    assign rrd_en_o  = issue;
    assign rrd_col_o = RXB'(32'(grp_q) * LANES + DMAX - P - 32'(d_q));
    assign lanes_l   = cen_l_i;
    assign lanes_r   = cen_r_i;
  end

  // Copy p (disparity d + p) takes right lanes P - 1 - p .. P - 1 - p + LANES - 1.
  logic [P-1:0]          ev_valid_p;
  logic                  ev_valid;
  logic [P*LANES*VB-1:0] ev;

  for (genvar p = 0; p < P; p++) begin : g_vert
    mcadsw_vert_agg #(
      .LANES(LANES), .WINDOW(WINDOW), .CB(CB), .WB(WB), .VB(VB)
    ) u_vert_agg (
      .clk_i, .rst_ni,
      .valid_i (v1_valid_q),
      .cen_l_i (lanes_l),
      .cen_r_i (lanes_r[(P-1-p)*WINDOW*CB +: LANES*WINDOW*CB]),
      .wv_i,
      .valid_o (ev_valid_p[p]),
      .ev_o    (ev[p*LANES*VB +: LANES*VB])
    );
  end
  assign ev_valid = ev_valid_p[0];

  // ---- Into the ping-pong buffer: from the vertical side, or the reader -------
  // pw_*: a ping-pong write (LANES costs of each copy) with its tags, in the
  // horizontal side's order: d ascending, groups 0 .. GROUPS-1 in consecutive cycles.
  logic          pw_valid, pw_first, pw_last;
  logic [RB-1:0] pw_row;
  logic [DB-1:0] pw_d;
  logic [GB-1:0] pw_grp;
  logic [CLB-1:0] pw_lcol;
  logic [SLB-1:0] pw_slot;
  logic [P-1:0]  pw_lanes;
  logic [P*LANES*VB-1:0] pw_data;
  logic          tr_busy;   // rows in the transposition buffer or being read from it

  if (GORDER) begin : g_transpose
    // Transposition buffer, one block RAM a copy: word (slot, step, group) holds the
    // LANES costs of that group at disparity step * P + p. Per slot, what the reader
    // needs of its row (written when the row's job is accepted).
    localparam int SMAX = DMAX / P;                    // steps a row at most
    localparam int SB   = (SMAX > 1) ? $clog2(SMAX) : 1;
    localparam int TAB  = SLB + SB + GB;               // {slot, step, group}
    localparam int TW   = LANES * VB;
    localparam int TN   = NSLOT << (SB + GB);
    function automatic logic [TAB-1:0] taddr(input logic [SLB-1:0] sl, input logic [DB-1:0] d,
                                             input logic [GB-1:0] g);
      taddr = {sl, SB'(32'(d) / P), g};
    endfunction

    logic [NSLOT*RB-1:0]  info_row_q;
    logic [NSLOT*CLB-1:0] info_lcol_q;
    logic [NSLOT*DB-1:0]  info_dlast_q, info_dmax_q;
    logic [NSLOT-1:0]     full_q;      // the slot's row is written, not yet read
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        {info_row_q, info_lcol_q, info_dlast_q, info_dmax_q} <= '0;
      end else if (accept) begin
        for (int sl = 0; sl < NSLOT; sl++)
          if (job_wslot_i == SLB'(sl)) begin
            info_row_q[sl*RB +: RB]    <= job_row_i;
            info_lcol_q[sl*CLB +: CLB] <= job_last_col_i;
            info_dlast_q[sl*DB +: DB]  <= DB'(job_disp_i - NB'(1)) & ~(DB'(P - 1));
            info_dmax_q[sl*DB +: DB]   <= DB'(job_disp_i - NB'(1));
          end
      end
    end

    // Reader: the rows in the order of their jobs (slots in turn), each once its
    // last word is written: d ascending, groups in order, a word a cycle.
    logic           rbusy_q;
    logic [SLB-1:0] rslot_q, rnext;   // slot read (the next one to read while idle)
    logic [DB-1:0]  rd_q;
    logic [GB-1:0]  rg_q;
    logic [DB-1:0]  r_dlast, r_dmax;
    logic           r_last, r_go, row_written;
    assign r_dlast = info_dlast_q[rslot_q*DB +: DB];
    assign r_dmax  = info_dmax_q[rslot_q*DB +: DB];
    assign r_last  = rbusy_q && rd_q == r_dlast && rg_q == GB'(GROUPS - 1);
    // The next row starts in the cycle after the last read of the current one.
    assign rnext   = !rbusy_q ? rslot_q : (rslot_q == SLB'(NSLOT - 1)) ? '0 : rslot_q + SLB'(1);
    assign r_go    = (!rbusy_q || r_last) && full_q[rnext];
    // The row's last word: its last group at its last step.
    assign row_written = v2_valid_q && v2_last_q && v2_grp_q == GB'(GROUPS - 1);
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        rbusy_q <= 1'b0;
        rslot_q <= '0;
        rd_q    <= '0;
        rg_q    <= '0;
        full_q  <= '0;
      end else begin
        for (int sl = 0; sl < NSLOT; sl++) begin
          if (row_written && v2_slot_q == SLB'(sl)) full_q[sl] <= 1'b1;
          else if (r_go && rnext == SLB'(sl)) full_q[sl] <= 1'b0;
        end
        if (r_go) begin
          rbusy_q <= 1'b1;
          rslot_q <= rnext;
          rd_q    <= '0;
          rg_q    <= '0;
        end else if (r_last) begin
          rbusy_q <= 1'b0;
          rslot_q <= rnext;
        end else if (rbusy_q) begin
          if (rg_q == GB'(GROUPS - 1)) begin
            rg_q <= '0;
            rd_q <= rd_q + DB'(P);
          end else begin
            rg_q <= rg_q + GB'(1);
          end
        end
      end
    end

    // The read's tags, registered with the RAM's data.
    logic [P-1:0] r_lanes;
    assign r_lanes[0] = 1'b1;
    for (genvar p = 1; p < P; p++) begin : g_rlanes
      assign r_lanes[p] = DB'(p) <= r_dmax - rd_q;
    end
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        {pw_valid, pw_first, pw_last, pw_row, pw_d, pw_grp, pw_lcol, pw_slot, pw_lanes} <= '0;
      end else begin
        {pw_valid, pw_first, pw_last, pw_row, pw_d, pw_grp, pw_lcol, pw_slot, pw_lanes} <=
            {rbusy_q, rd_q == '0, rd_q == r_dlast, info_row_q[rslot_q*RB +: RB], rd_q, rg_q,
             info_lcol_q[rslot_q*CLB +: CLB], rslot_q, r_lanes};
      end
    end

    logic [TAB-1:0] waddr, raddr;
    assign waddr = taddr(v2_slot_q, v2_d_q, v2_grp_q);
    assign raddr = taddr(rslot_q, rd_q, rg_q);
    for (genvar p = 0; p < P; p++) begin : g_tmem
      (* ram_style = "block", no_rw_check *) logic [TW-1:0] mem_q [TN];
      logic [TW-1:0] rdata_q;
      always_ff @(posedge clk_i) begin
        if (ev_valid && v2_valid_q) mem_q[waddr] <= ev[p*TW +: TW];
        if (rbusy_q) rdata_q <= mem_q[raddr];
      end
      assign pw_data[p*TW +: TW] = rdata_q;
    end

    assign tr_busy = |full_q || rbusy_q || pw_valid;
    // A job waits while its slot's row is still to be read (its record and words
    // are the reader's). In the engine the weight generator hands a slot out only
    // after the row's last horizontal read, later still, so it never waits there.
    assign tr_slot_free = !full_q[job_wslot_i] && !(rbusy_q && rslot_q == job_wslot_i);

    // The weight generator hands out its slots in turn, which is the order the
    // reader takes them in; and a row's words are written in a slot the reader is
    // not reading (the slot comes back to the weight generator only after the
    // reader's last read): no read meets the write of its word (no_rw_check).
    logic [SLB-1:0] jslot_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) jslot_q <= '0;
      else if (accept) jslot_q <= (jslot_q == SLB'(NSLOT - 1)) ? '0 : jslot_q + SLB'(1);
    end
    // The row's tags come from the slot's record, not from the vertical side.
    logic t_unused;
    assign t_unused = ^{v2_first_q, v2_row_q, v2_lcol_q, v2_lanes_q, r_dmax};
    `MCADSW_ASSERT(JobSlotsInTurn, !(accept && job_wslot_i != jslot_q))
    `MCADSW_ASSERT(NoWriteOfSlotRead, !(ev_valid && v2_valid_q && rbusy_q && v2_slot_q == rslot_q))
    `MCADSW_ASSERT(RowReadOnce, !(row_written && full_q[v2_slot_q]))
  end else begin : g_direct
    // ASIC target: the vertical side writes the ping-pong buffer itself.
    assign {pw_valid, pw_first, pw_last, pw_row, pw_d, pw_grp, pw_lcol, pw_slot, pw_lanes} =
        {ev_valid && v2_valid_q, v2_first_q, v2_last_q, v2_row_q, v2_d_q, v2_grp_q, v2_lcol_q,
         v2_slot_q, v2_lanes_q};
    assign pw_data = ev;
    assign tr_busy = 1'b0;
    assign tr_slot_free = 1'b1;
  end

  // ---- Ping-pong buffer (Fig. 13) --------------------------------------------
  logic wbank_q;       // bank the vertical side writes
  logic bank_full;     // the last group of a disparity is written this cycle

  assign bank_full = pw_valid && pw_grp == GB'(GROUPS - 1);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) wbank_q <= 1'b0;
    else if (bank_full) wbank_q <= !wbank_q;
  end

  logic          h0_valid_q, h0_first_q, h0_last_q, h0_bank_q;
  logic          h1_valid_q, h1_first_q, h1_last_q, h1_bank_q;
  logic          h2_valid_q, h2_first_q, h2_last_q;
  logic          h3_valid_q, h3_first_q, h3_last_q;
  logic [RB-1:0] h0_row_q, h1_row_q, h2_row_q, h3_row_q;
  logic [DB-1:0] h0_d_q, h1_d_q, h2_d_q, h3_d_q;
  logic [GB-1:0] h0_grp_q, h1_grp_q, h2_grp_q, h3_grp_q;
  localparam int PPW = (WINDOW + HAGG - 1) * VB;   // one copy's ping-pong read
  logic [P*PPW-1:0] pp_rd_q;     // the read of h1, registered in the buffer

  for (genvar p = 0; p < P; p++) begin : g_pingpong
    mcadsw_pingpong #(
      .COLS(GROUPS*LANES), .LANES(LANES), .HAGG(HAGG), .WINDOW(WINDOW), .VB(VB)
    ) u_pingpong (
      .clk_i, .rst_ni,
      .wr_en_i   (pw_valid),
      .wr_bank_i (wbank_q),
      .wr_grp_i  (pw_grp),
      .wr_data_i (pw_data[p*LANES*VB +: LANES*VB]),
      .wr_last_i (pw_lcol),
      .rd_en_i   (h1_valid_q),
      .rd_bank_i (h1_bank_q),
      .rd_grp_i  (h1_grp_q),
      .rd_data_o (pp_rd_q[p*PPW +: PPW])
    );
  end

  // ---- Horizontal side: 6 output groups per full bank --------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      {h0_valid_q, h0_first_q, h0_last_q, h0_bank_q, h0_row_q, h0_d_q, h0_grp_q,
       h0_slot_q, h0_lanes_q} <= '0;
    end else if (bank_full) begin
      {h0_valid_q, h0_first_q, h0_last_q, h0_bank_q, h0_row_q, h0_d_q, h0_grp_q,
       h0_slot_q, h0_lanes_q} <= {1'b1, pw_first, pw_last, wbank_q, pw_row, pw_d, GB'(0),
                                  pw_slot, pw_lanes};
    end else if (h0_valid_q) begin
      h0_valid_q <= h0_grp_q != GB'(GROUPS - 1);
      h0_grp_q   <= h0_grp_q + GB'(1);
    end
  end

  assign hrd_en_o  = h1_valid_q;
  assign hrd_row_o = h1_row_q;
  assign hrd_grp_o = h1_grp_q;
  assign hrd_slot_o = h1_slot_q;
  assign hrd_rel_o = h1_last_q && h1_grp_q == GB'(GROUPS - 1);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      {h1_valid_q, h1_first_q, h1_last_q, h1_bank_q, h1_row_q, h1_d_q, h1_grp_q,
       h1_slot_q, h1_lanes_q} <= '0;
      {h2_valid_q, h2_first_q, h2_last_q, h2_row_q, h2_d_q, h2_grp_q, h2_lanes_q} <= '0;
      {h3_valid_q, h3_first_q, h3_last_q, h3_row_q, h3_d_q, h3_grp_q, h3_lanes_q} <= '0;
    end else begin
      {h1_valid_q, h1_first_q, h1_last_q, h1_bank_q, h1_row_q, h1_d_q, h1_grp_q,
       h1_slot_q, h1_lanes_q} <= {h0_valid_q, h0_first_q, h0_last_q, h0_bank_q, h0_row_q, h0_d_q,
                                  h0_grp_q, h0_slot_q, h0_lanes_q};
      {h2_valid_q, h2_first_q, h2_last_q, h2_row_q, h2_d_q, h2_grp_q, h2_lanes_q} <=
          {h1_valid_q, h1_first_q, h1_last_q, h1_row_q, h1_d_q, h1_grp_q, h1_lanes_q};
      {h3_valid_q, h3_first_q, h3_last_q, h3_row_q, h3_d_q, h3_grp_q, h3_lanes_q} <= h2x;
    end
  end

  // The tags of h2 reach h3 with the final costs: one cycle, or HLAT = 2 on the
  // FPGA target (mcadsw_horz_agg's latency: its terms registered first).
  localparam int HLAT = (mcadsw_pkg::FPGA != 0) ? 2 : 1;
  localparam int HTW  = 3 + RB + DB + GB + P;
  logic [HTW-1:0] h2t, h2x;
  logic           hx_busy;            // tags on their way from h2 to h3
  assign h2t = {h2_valid_q, h2_first_q, h2_last_q, h2_row_q, h2_d_q, h2_grp_q, h2_lanes_q};
  if (HLAT > 1) begin : g_hdelay
    mcadsw_tag_delay #(.W(HTW), .N(HLAT - 1)) u_delay (
      .clk_i, .rst_ni, .tags_i(h2t), .tags_o(h2x), .busy_o(hx_busy)
    );
  end else begin : g_hdirect
    assign h2x     = h2t;
    assign hx_busy = 1'b0;
  end

  logic [P-1:0]          fc_valid_p;
  logic                  fc_valid;
  logic [P*HAGG*FB-1:0]  fc;     // copy p, pixel m at (p HAGG + m) FB: the WTA's order

  // FPGA target at P = 1: the three horizontal aggregators multiply on the device's
  // multipliers (93 of the ECP5-85F's 156; the rest of the SoC uses 28); at P > 1 every
  // term stays a shift.
  localparam int MULT_AGGS = (mcadsw_pkg::FPGA != 0 && P == 1) ? HAGG : 0;
  for (genvar p = 0; p < P; p++) begin : g_horz
    mcadsw_horz_agg #(
      .HAGG(HAGG), .WINDOW(WINDOW), .WB(WB), .VB(VB), .FB(FB), .MULT_AGGS(MULT_AGGS)
    ) u_horz_agg (
      .clk_i, .rst_ni,
      .valid_i (h2_valid_q),
      .ev_i    (pp_rd_q[p*PPW +: PPW]),
      .wh_i,
      .valid_o (fc_valid_p[p]),
      .fc_o    (fc[p*HAGG*FB +: HAGG*FB])
    );
  end
  assign fc_valid = fc_valid_p[0];
  // The copies run in lock step: copy 0's valid stands for all. (D - 1 is used by
  // the lane mask only when P > 1.)
  logic par_unused;
  assign par_unused = ^{ev_valid_p, fc_valid_p, dmax_q};

  // ---- WTA ------------------------------------------------------------------------
  logic [RB-1:0] disp_row_q;

  mcadsw_wta #(
    .BLOCK(BLOCK), .HAGG(HAGG), .FB(FB), .DB(DB), .P(P)
  ) u_wta (
    .clk_i, .rst_ni,
    .valid_i (fc_valid && h3_valid_q),
    .first_i (h3_first_q),
    .last_i  (h3_last_q),
    .d_i     (h3_d_q),
    .grp_i   (h3_grp_q),
    .fc_i    (fc),
    .lanes_i (h3_lanes_q),
    .valid_o (disp_valid_o),
    .grp_o   (disp_grp_o),
    .disp_o  (disp_o),
    .sub_valid_o,
    .sub_grp_o,
    .sub_o,
    .sub_d_o
  );

  logic [RB-1:0] sub_row1_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      disp_row_q <= '0;
      sub_row1_q <= '0;
      sub_row_o  <= '0;
    end else begin
      if (h3_valid_q) disp_row_q <= h3_row_q;
      sub_row1_q <= disp_row_q;
      sub_row_o  <= sub_row1_q;
    end
  end
  assign disp_row_o = disp_row_q;

  assign busy_o = busy_q || v1_valid_q || vx_busy || v2_valid_q || tr_busy || h0_valid_q ||
                  h1_valid_q || h2_valid_q || hx_busy || h3_valid_q || disp_valid_o;
  assign vbusy_o = GORDER ? (busy_q || feed_busy || v1_valid_q || vx_busy || v2_valid_q) : busy_o;
  // The sub-pixel stages follow the disparities by two cycles.
  logic sub_d1_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) sub_d1_q <= 1'b0;
    else sub_d1_q <= disp_valid_o;
  end
  assign sub_busy_o = busy_o || sub_d1_q || sub_valid_o;


  // Ping-pong ownership (docs/verification.md section 3): the vertical side never
  // writes a bank the horizontal side has still to read (h0 issues the reads of
  // the following cycles; the read in h1 in the same cycle as a write returns the
  // word from before it), and a bank is handed over only when the horizontal side
  // has finished the previous one.
  `MCADSW_ASSERT(EvWithItsTags, ev_valid == v2_valid_q)
  `MCADSW_ASSERT(FcWithItsTags, fc_valid == h3_valid_q)
  `MCADSW_ASSERT(BankNotOverwrittenBeforeRead, !(pw_valid && h0_valid_q && wbank_q == h0_bank_q))
  `MCADSW_ASSERT(BankHandedOverWhenRead, !(bank_full && h0_valid_q && h0_grp_q != GB'(GROUPS - 1)))

  // The ping-pong buffer clamps at the border as it writes, so it takes a bank's
  // groups in order 0, 1, .., GROUPS - 1; its shifted read (FPGA target) takes them
  // so too, in consecutive cycles. A write or read of group g > 0 follows that of g - 1.
`ifdef MCADSW_CHECKS
  // verilator coverage_off
  logic          pw_was_valid_q, h1_was_valid_q;
  logic [GB-1:0] pw_was_grp_q, h1_was_grp_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) {pw_was_valid_q, pw_was_grp_q, h1_was_valid_q, h1_was_grp_q} <= '0;
    else {pw_was_valid_q, pw_was_grp_q, h1_was_valid_q, h1_was_grp_q} <=
        {pw_valid, pw_grp, h1_valid_q, h1_grp_q};
  end
  // verilator coverage_on
`endif
  `MCADSW_ASSERT(WriteGroupsInOrder, !(pw_valid && pw_grp != '0 &&
                                       !(pw_was_valid_q && pw_was_grp_q + GB'(1) == pw_grp)))
  `MCADSW_ASSERT(ReadGroupsInOrder, !(h1_valid_q && h1_grp_q != '0 &&
                                      !(h1_was_valid_q && h1_was_grp_q + GB'(1) == h1_grp_q)))

`ifdef FORMAL
  // Ping-pong ownership, proven by `make formal` (formal/cost_agg_props.sv): a
  // ghost tag per bank and column group records the (row, d) of the costs last
  // written there. Whenever the horizontal side reads a bank (h1), every group of
  // that bank holds the costs of the (row, d) it reads for: the bank was filled
  // completely for that disparity and nothing overwrote it before the read.
  localparam int TAGB = RB + DB;
  logic [2*GROUPS*TAGB-1:0] own_q;     // bank b, group g at (b GROUPS + g) TAGB
  logic [2*GROUPS-1:0]      own_set_q; // written at least once since reset
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) begin
      own_q     <= '0;
      own_set_q <= '0;
    end else if (pw_valid) begin
      for (int b = 0; b < 2; b++)
        for (int g = 0; g < GROUPS; g++)
          if (wbank_q == b[0] && pw_grp == GB'(g)) begin
            own_q[(b*GROUPS + g)*TAGB +: TAGB] <= {pw_row, pw_d};
            own_set_q[b*GROUPS + g] <= 1'b1;
          end
    end
  always_comb
    if (rst_ni && h1_valid_q)
      for (int b = 0; b < 2; b++)
        for (int g = 0; g < GROUPS; g++)
          if (h1_bank_q == b[0]) begin
            assert (own_set_q[b*GROUPS + g]);
            assert (own_q[(b*GROUPS + g)*TAGB +: TAGB] == {h1_row_q, h1_d_q});
          end
`endif

  // Events the block's proof must reach (formal only): a bank handed to the
  // horizontal side, disparities and sub-pixel values out.
  `MCADSW_COVER(BankSwapped, bank_full)
  `MCADSW_COVER(DisparitiesOut, disp_valid_o)
  `MCADSW_COVER(SubpixelOut, sub_valid_o)

endmodule

`default_nettype wire
