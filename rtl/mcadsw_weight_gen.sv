// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Weight generator (paper Sec. V-C, Fig. 11): the Y, U, V input buffer of the
// left view, a kernel of WINDOW Manhattan colour-distance units and weight-table
// lookups, and the vertical and horizontal weight buffers, which hold NSLOT
// aggregation rows: the kernel makes row r + 1 while the cost aggregator works
// on row r (paper Sec. V-F: the aggregator starts once a row's weights are
// ready). NSLOT is 2, or 3 on the FPGA target, whose cost aggregator reads a row's
// horizontal weights a row after its vertical ones (mcadsw_cost_agg).
// docs/blocks/weight_gen.md and docs/budget.md 3.
//
// Loader. Input: the colour of the ROWS x COLS read window (48 x 48) in strips
// of 4 columns, strip by strip, and Y, U, V of each strip in turn: for strip s
// and plane p, rows 0 .. ROWS-1 of columns 4s .. 4s+3, one 32-bit word a row,
// byte 0 the leftmost column. The strips start at the aligned memory word left
// of the window, cfg_ofs_i (0..3) columns early, so each strip word is one
// memory read: WPR = COLS/4 + 1 strips. The input buffer is a ring of RS = WPR
// + NEW strips (one synchronous-read RAM a plane, a strip of 4 column words an
// entry): a window's strip s lives in ring strip (base + s) mod RS, and each
// window's base is WPR - cfg_first_i strips after the previous one's. Only
// strips cfg_first_i .. WPR-1 are delivered:
//  - a block that continues its left neighbour (partial column reuse, Sec. IV)
//    receives only the NEW or fewer strips the neighbour's window lacks; they
//    land in ring strips the neighbour does not use;
//  - the first block of a row band skips the strips wholly left of the image
//    (cfg_first_i of them; the kernel replicates image column 0, window column
//    cfg_lo_i, for the columns before it). Its first NEW strips land in free
//    ring strips; the others overwrite the previous block's window, so the
//    loader waits for them until the kernel has made that block's last row.
// done_o pulses when the window is in the buffer (the block is prepared).
//
// Kernel: the rows of a block in order (cfg_rows_i of them, the rows the cost
// aggregator will ask for), each into a free row slot, one step a cycle:
//   vertical:   column c (0..COLS-1) of row r: the WINDOW weights of pixels
//               (c, r+k) against the column centre (c, r+R);
//   horizontal: output pixel x (0..BLOCK-1) of row r: the WINDOW weights of
//               column centres (x+j, r+R) against the window centre (x+R, r+R).
// COLS + 1 + BLOCK = 67 cycles a row. Pipeline: the input-buffer read
// (address registered), the window selection (registered), the distances and
// codes (written). The centre row r+R of every column goes into a row buffer
// of flip-flops during the vertical pass (Fig. 11); the horizontal pass reads
// it, one cycle after the vertical pass's last column is in it.
// Memory side reads at clamped coordinates, so the weights of positions
// outside the image are those of the nearest edge pixel (docs/algorithm.md).
//
// Row slots: row_ready_o says the oldest row not yet handed out is complete,
// in slot rd_slot_o; row_take_i hands it to the aggregator (a row job). The
// aggregator reads the slot through vrd_* and hrd_* (data the cycle after the
// address) and frees it with hrd_rel_i on its last horizontal read.
//
// FPGA target (mcadsw_pkg::FPGA, docs/blocks/fpga_target.md): the input buffer is
// one block RAM a plane with a chunk of a column (ROWS / KPH rows) an entry, and
// the kernel places its codes in the census buffer's folded order (mcadsw_census:
// tap k is row k + WINDOW when k < r, row k otherwise), so neither pass selects a
// window of pixels; a vertical entry holds its codes in that order. The kernel
// makes an entry in KPH cycles, a chunk a cycle (mcadsw_pkg::WEIGHT_KPH: 2 when
// DMAX >= 23, so a row takes 134 cycles instead of 67, hidden behind the
// aggregator's 6 D + 1 for D >= 23; KPH = 1: the folded window's 31 pixels in
// 31 units). Same values.
//
// Weight table: the 7 colour distances at which the 3-bit weight code drops
// (code = 7 - number of thresholds <= dC), loaded at run time and converted
// from the reference's table by weight_thresholds(), so both sides use the
// same values.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_weight_gen #(
  parameter int COLS   = mcadsw_pkg::BLOCK_COLS,
  parameter int ROWS   = mcadsw_pkg::BLOCK_COLS,
  parameter int BLOCK  = mcadsw_pkg::BLOCK,
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int LANES  = mcadsw_pkg::LANES,
  parameter int HAGG   = mcadsw_pkg::HAGG,
  parameter int WB     = mcadsw_pkg::WEIGHT_CODE_BITS,
  parameter int DCB    = mcadsw_pkg::COLOR_DIST_BITS,
  parameter int NTHR   = mcadsw_pkg::WTHRESHOLDS,
  parameter bit FPGA   = 1'(mcadsw_pkg::FPGA),      // the FPGA target's buffer shapes
  parameter int NSLOT  = mcadsw_pkg::WEIGHT_SLOTS,  // row slots (2; FPGA target 3)
  parameter int KPH    = mcadsw_pkg::WEIGHT_KPH,    // kernel cycles an entry (FPGA target; ASIC 1)
  parameter int SLB    = $clog2(NSLOT),
  parameter int WPR    = COLS / 4 + 1,              // strips a window (offset 0..3)
  parameter int NEW    = (BLOCK + 3) / 4,           // most strips a continuing block adds (5)
  parameter int RS     = WPR + NEW,                 // ring strips (18)
  parameter int SB     = $clog2(WPR),
  parameter int XB     = $clog2(COLS),
  parameter int RB     = $clog2(BLOCK + 1),
  parameter int VGRP   = COLS / LANES,              // vertical words a row (6)
  parameter int HGRP   = BLOCK / HAGG,              // horizontal words a row (6)
  parameter int GB     = $clog2(VGRP > HGRP ? VGRP : HGRP)
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,
  input  logic [NTHR*DCB-1:0]        thr_i,        // stable while a frame runs
  // Loader: a block's window
  input  logic                       cfg_valid_i,
  output logic                       cfg_ready_o,
  input  logic [1:0]                 cfg_ofs_i,    // window column 0 is input column cfg_ofs_i
  input  logic [SB-1:0]              cfg_first_i,  // first strip delivered
  input  logic [XB-1:0]              cfg_lo_i,     // window column of image column 0 (0 inside)
  input  logic [RB-1:0]              cfg_rows_i,   // rows to make, 1 .. BLOCK
  input  logic                       pix_valid_i,
  output logic                       pix_ready_o,
  input  logic [31:0]                pix_data_i,
  output logic                       done_o,       // one cycle: the window is loaded
  output logic                       busy_o,
  // Row slots
  output logic                       row_ready_o,
  output logic [SLB-1:0]             rd_slot_o,
  input  logic                       row_take_i,
  // Vertical weight buffer read: LANES columns of group vrd_grp_i of a slot
  input  logic                       vrd_en_i,
  input  logic [SLB-1:0]             vrd_slot_i,
  input  logic [GB-1:0]              vrd_grp_i,
  output logic [LANES*WINDOW*WB-1:0] wv_o,          // lane l, tap k at (l*WINDOW + k)*WB
  // Horizontal weight buffer read: HAGG output pixels of group hrd_grp_i of a slot
  input  logic                       hrd_en_i,
  input  logic [SLB-1:0]             hrd_slot_i,
  input  logic [GB-1:0]              hrd_grp_i,
  input  logic                       hrd_rel_i,     // this read is the slot's last
  output logic [HAGG*WINDOW*WB-1:0]  wh_o           // pixel m, tap j at (m*WINDOW + j)*WB
);

  localparam int RADIUS = WINDOW / 2;
  localparam int ENTRY  = WINDOW * WB;              // one weight-buffer entry
  localparam int RSB    = $clog2(RS);
  localparam int CR     = ROWS / KPH;               // rows a chunk of a column (ASIC: ROWS)
  localparam int PHB    = KPH > 1 ? $clog2(KPH) : 1;  // a cycle of an entry, a chunk

  if (COLS % 4 != 0 || WPR * 4 < COLS + 3 || ROWS != BLOCK + WINDOW - 1 ||
      COLS != BLOCK + WINDOW - 1 || NTHR != (1 << WB) - 1 || VGRP * LANES != COLS ||
      HGRP * HAGG != BLOCK || LANES != 8 || NEW < (BLOCK + 3) / 4 ||
      ROWS - WINDOW > WINDOW || NSLOT < 2 || KPH < 1 || (!FPGA && KPH != 1) ||
      ROWS % KPH != 0 || (KPH > 1 && CR > WINDOW)) begin : g_bad_param
    mcadsw_error_weight_gen_geometry u_error ();
  end

  // v mod n for 0 <= v < 2n.
  function automatic int wrap(input int v, input int n);
    wrap = (v >= n) ? v - n : v;
  endfunction

  // ---- Loader --------------------------------------------------------------------
  logic           l_busy_q;        // a window is being loaded
  logic           pend_q;          // a loaded window waits for the kernel
  logic [RSB-1:0] l_base_q;        // ring strip of window strip 0 (last configured window)
  logic [SB-1:0]  l_first_q;
  logic [1:0]     l_ofs_q;
  logic [XB-1:0]  l_lo_q;
  logic [RB-1:0]  l_rows_q;
  logic           gen_busy;        // the kernel still reads a window (the previous block's)

  logic [1:0]       in_plane;
  logic [SB-1:0]    in_strip;               // columns 4s .. 4s+3
  logic             strip_end, win_done;    // last row of a strip / of the window
  localparam int CW = ROWS * 8;             // column word
  logic [4*CW-1:0]  strip_cols;             // the 4 column words of that strip
  logic             cfg_fire, pix_fire;
  logic [SB-1:0]    new_idx;                // strip's index among the delivered ones

  assign cfg_ready_o = !l_busy_q && !pend_q;
  assign cfg_fire    = cfg_valid_i && cfg_ready_o;
  assign new_idx     = in_strip - l_first_q;
  // Strips beyond the first NEW land on the previous window's ring strips.
  assign pix_ready_o = l_busy_q && !(gen_busy && new_idx >= SB'(NEW));
  assign pix_fire    = pix_valid_i && pix_ready_o;

  localparam int CNB = $clog2(4 * KPH);
  logic             col_valid;              // FPGA target: the strip's column chunks one a cycle:
  logic [CNB-1:0]   col_n;                  // chunk col_n / 4 of column col_n % 4
  logic [CR*8-1:0]  col_word;
  mcadsw_strip_stage #(.ROWS(ROWS), .STRIPS(WPR), .PLANES(3), .COLUMNS(FPGA), .CHUNKS(KPH)) u_stage (
    .clk_i, .rst_ni,
    .start_i (cfg_fire),
    .first_i (cfg_first_i),
    .wr_i    (pix_fire),
    .data_i  (pix_data_i),
    .last_o  (strip_end),
    .done_o  (win_done),
    .plane_o (in_plane),
    .strip_o (in_strip),
    .cols_o  (strip_cols),
    .col_valid_o (col_valid),
    .col_n_o (col_n),
    .col_o   (col_word)
  );

  // ---- Kernel control ------------------------------------------------------------
  typedef enum logic [2:0] {IDLE, ROW, VERT, GAP, HORZ} state_e;
  state_e         state_q;
  logic [RSB-1:0] g_base_q;
  logic [1:0]     g_ofs_q;
  logic [XB-1:0]  g_lo_q;
  logic [RB-1:0]  g_rows_q;
  logic [RB-1:0]  r_q;
  logic [XB-1:0]  c_q;             // column (vertical) or output pixel (horizontal)
  logic [GB-1:0]  hg_q;            // horizontal: word (group of HAGG pixels) ...
  logic [1:0]     hm_q;            // ... and pixel in it
  logic [SLB-1:0] wslot_q;         // slot the kernel fills
  logic [NSLOT-1:0] occ_q;         // slot holds a row the aggregator has not released
  logic [NSLOT-1:0] rdy_q;         // slot holds a complete row not yet handed out
  logic [SLB-1:0] rslot_q;         // oldest row not handed out
  logic           k_done_q;        // the kernel's last write of a row (stage 2)
  logic [SLB-1:0] k_slot2_q;
  logic           w_done;          // the last write of a row done (stage 2, FPGA: 3) ...
  logic [SLB-1:0] w_slot;          // ... and its slot
  logic [PHB-1:0] kph_q;           // the pass's cycle of its column or pixel (0 .. KPH-1; ASIC 0)
  logic           k_adv;           // its last: the pass moves to its next column or pixel
  logic           k_first;         // its first
  logic           k_busy;          // a row's last entry still in the kernel's stages

  // The slot after s: slots are used in turn.
  function automatic logic [SLB-1:0] next_slot(input logic [SLB-1:0] s);
    next_slot = (s == SLB'(NSLOT - 1)) ? '0 : s + SLB'(1);
  endfunction

  assign gen_busy = state_q != IDLE;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      l_busy_q  <= 1'b0;
      pend_q    <= 1'b0;
      l_base_q  <= '0;
      l_first_q <= '0;
      l_ofs_q   <= '0;
      l_lo_q    <= '0;
      l_rows_q  <= '0;
      done_o    <= 1'b0;
      state_q   <= IDLE;
      g_base_q  <= '0;
      g_ofs_q   <= '0;
      g_lo_q    <= '0;
      g_rows_q  <= '0;
      r_q       <= '0;
      c_q       <= '0;
      hg_q      <= '0;
      hm_q      <= '0;
      wslot_q   <= '0;
      occ_q     <= '0;
      rdy_q     <= '0;
      rslot_q   <= '0;
    end else begin
      done_o <= 1'b0;
      // Loader
      if (cfg_fire) begin
        l_busy_q  <= 1'b1;
        l_base_q  <= RSB'(wrap(32'(l_base_q) + WPR - 32'(cfg_first_i), RS));
        l_first_q <= cfg_first_i;
        l_ofs_q   <= cfg_ofs_i;
        l_lo_q    <= cfg_lo_i;
        l_rows_q  <= cfg_rows_i;
      end
      if (pix_fire && win_done) begin
        l_busy_q <= 1'b0;
        pend_q   <= 1'b1;
        done_o   <= 1'b1;
      end
      // Kernel
      case (state_q)
        IDLE: if (pend_q) begin       // take the loaded window
          pend_q   <= 1'b0;
          state_q  <= ROW;
          g_base_q <= l_base_q;
          g_ofs_q  <= l_ofs_q;
          g_lo_q   <= l_lo_q;
          g_rows_q <= l_rows_q;
          r_q      <= '0;
        end
        ROW: if (!occ_q[wslot_q]) begin
          state_q <= VERT;
          c_q     <= '0;
        end
        VERT: if (k_adv) begin        // the COLS columns of row r
          if (c_q == XB'(COLS - 1)) state_q <= GAP;
          else c_q <= c_q + XB'(1);
        end
        GAP: begin                    // the last centre pixel reaches the row buffer
          state_q <= HORZ;
          c_q     <= '0;
          hg_q    <= '0;
          hm_q    <= '0;
        end
        HORZ: if (k_adv) begin        // the BLOCK output pixels of row r
          c_q <= c_q + XB'(1);
          if (hm_q == 2'(HAGG - 1)) begin
            hm_q <= '0;
            hg_q <= hg_q + GB'(1);
          end else begin
            hm_q <= hm_q + 2'd1;
          end
          if (c_q == XB'(BLOCK - 1)) begin
            wslot_q <= next_slot(wslot_q);
            if (r_q == g_rows_q - RB'(1)) begin
              state_q <= IDLE;
            end else begin
              state_q <= ROW;
              r_q     <= r_q + RB'(1);
            end
          end
        end
        default: state_q <= IDLE;
      endcase
      // Slots: taken when the kernel starts a row, freed by the aggregator's last read.
      for (int s = 0; s < NSLOT; s++) begin
        if (state_q == ROW && !occ_q[wslot_q] && wslot_q == SLB'(s)) occ_q[s] <= 1'b1;
        else if (hrd_en_i && hrd_rel_i && hrd_slot_i == SLB'(s)) occ_q[s] <= 1'b0;
        if (w_done && w_slot == SLB'(s)) rdy_q[s] <= 1'b1;
        else if (row_take_i && rslot_q == SLB'(s)) rdy_q[s] <= 1'b0;
      end
      if (row_take_i) rslot_q <= next_slot(rslot_q);
    end
  end

  if (KPH > 1) begin : g_kph
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) kph_q <= '0;
      else         kph_q <= (state_q == VERT || state_q == HORZ) && !k_adv ? kph_q + PHB'(1) : '0;
    end
  end else begin : g_kph1
    assign kph_q = '0;
  end
  assign k_adv   = kph_q == PHB'(KPH - 1);
  assign k_first = kph_q == '0;

  assign busy_o      = l_busy_q || pend_q || gen_busy || k_busy;
  assign row_ready_o = rdy_q[rslot_q];
  assign rd_slot_o   = rslot_q;

  // ---- Input buffer: a ring of RS strips of 4 columns a plane -----------------------
  // Ring column p = 4 t + b is column b of ring strip t; the kernel reads one column
  // a cycle ("column by column", Fig. 11), all ROWS rows of Y, U and V.
  localparam int CB = $clog2(4 * RS);        // ring column index
  logic [CB-1:0]  rcol;                      // ring column of the kernel's column c
  logic [XB-1:0]  cc;                        // c, with image column 0 replicated to its left
  logic [RSB-1:0] wstrip;                    // ring strip of the finished input strip
  assign cc     = (c_q < g_lo_q) ? g_lo_q : c_q;
  assign rcol   = CB'(wrap(4*32'(g_base_q) + 32'(g_ofs_q) + 32'(cc), 4*RS));
  assign wstrip = RSB'(wrap(32'(l_base_q) + 32'(in_strip), RS));

  // The vertical pass reads a column in KPH chunks of CR rows, a chunk a cycle,
  // the chunk with the centre row r + RADIUS first (k_chunk); ASIC target: one.
  logic [3*CR*8-1:0] chunk;                  // stage 1: the chunk read, {V, U, Y}
  logic [1:0]        s1_sel_q;               // ASIC target: its column in the strip
  logic [PHB-1:0]    k_chunk;                // the chunk the vertical pass reads

  // The chunk of a column that holds its centre row r + RADIUS.
  function automatic int centre_chunk(input logic [RB-1:0] r);
    centre_chunk = 0;
    for (int o = 0; o < BLOCK; o++) if (r == RB'(o)) centre_chunk = (o + RADIUS) / CR;
  endfunction
  assign k_chunk = PHB'(wrap(centre_chunk(r_q) + 32'(kph_q), KPH));

  if (FPGA) begin : g_fpga_in
    // FPGA target: one RAM a plane, a chunk of a ring column an entry (address
    // {ring column, chunk}; 4 RS x KPH entries of CR bytes: block RAM). The strip
    // stage presents a finished strip's column chunks one a cycle over the next
    // 4 KPH cycles (COLUMNS); the kernel never reads them that early
    // (ColumnWrittenBeforeRead), so no read meets the write of its entry
    // (no_rw_check: docs/blocks/fpga_target.md).
    localparam int CHB = $clog2(KPH);        // chunk bits of an address (0: KPH = 1)
    localparam int AB  = CB + CHB;
    (* ram_style = "block", no_rw_check *) logic [CR*8-1:0] y_mem [(4*RS) << CHB];
    (* ram_style = "block", no_rw_check *) logic [CR*8-1:0] u_mem [(4*RS) << CHB];
    (* ram_style = "block", no_rw_check *) logic [CR*8-1:0] v_mem [(4*RS) << CHB];
    logic [CR*8-1:0] y_rd_q, u_rd_q, v_rd_q;
    logic [1:0]      hplane_q;
    logic [RSB-1:0]  hstrip_q;
    logic [AB-1:0]   waddr, raddr;           // {ring column, chunk}
    assign waddr = AB'(((4*32'(hstrip_q) + 32'(col_n[1:0])) << CHB) + (32'(col_n) >> 2));
    assign raddr = AB'((32'(rcol) << CHB) + 32'(k_chunk));
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        hplane_q <= '0;
        hstrip_q <= '0;
      end else if (pix_fire && strip_end) begin
        hplane_q <= in_plane;
        hstrip_q <= wstrip;
      end
    end
    always_ff @(posedge clk_i) begin
      if (col_valid && hplane_q == 2'd0) y_mem[waddr] <= col_word;
      if (col_valid && hplane_q == 2'd1) u_mem[waddr] <= col_word;
      if (col_valid && hplane_q == 2'd2) v_mem[waddr] <= col_word;
    end
    always_ff @(posedge clk_i) begin
      if (state_q == VERT) begin
        y_rd_q <= y_mem[raddr];
        u_rd_q <= u_mem[raddr];
        v_rd_q <= v_mem[raddr];
      end
    end
    assign chunk = {v_rd_q, u_rd_q, y_rd_q};
    logic sel_unused;                        // the ASIC target's column select and strip word
    assign sel_unused = ^{s1_sel_q, strip_cols};
    `MCADSW_ASSERT(ColumnWrittenBeforeRead, !(state_q == VERT && col_valid && rcol[CB-1:2] == (CB-2)'(hstrip_q)))
  end else begin : g_asic_in
    // ASIC target: one RAM a plane, entry t the 4 column words of ring strip t
    // (column b at b*CW, row y at byte y); the kernel reads a whole strip and
    // takes one column.
    logic [4*CW-1:0] y_mem [RS];
    logic [4*CW-1:0] u_mem [RS];
    logic [4*CW-1:0] v_mem [RS];
    logic [4*CW-1:0] y_rd_q, u_rd_q, v_rd_q;
    logic cols_unused;                       // the stage's chunks one a cycle: FPGA target
    assign cols_unused = ^{col_valid, col_n, col_word, k_chunk};
    always_ff @(posedge clk_i) begin
      if (pix_fire && strip_end && in_plane == 2'd0) y_mem[wstrip] <= strip_cols;
      if (pix_fire && strip_end && in_plane == 2'd1) u_mem[wstrip] <= strip_cols;
      if (pix_fire && strip_end && in_plane == 2'd2) v_mem[wstrip] <= strip_cols;
    end
    always_ff @(posedge clk_i) begin
      if (state_q == VERT) begin
        y_rd_q <= y_mem[RSB'(rcol[CB-1:2])];
        u_rd_q <= u_mem[RSB'(rcol[CB-1:2])];
        v_rd_q <= v_mem[RSB'(rcol[CB-1:2])];
      end
    end
    function automatic logic [CW-1:0] bank_word(input logic [4*CW-1:0] w, input logic [1:0] b);
      bank_word = '0;
      for (int i = 0; i < 4; i++) bank_word = bank_word | (w[i*CW +: CW] & {CW{b == 2'(i)}});
    endfunction
    assign chunk = {bank_word(v_rd_q, s1_sel_q), bank_word(u_rd_q, s1_sel_q),
                    bank_word(y_rd_q, s1_sel_q)};
  end

  // ---- Kernel pipeline -------------------------------------------------------------
  // Stage 1 (vertical only): a chunk of the column from the input buffer (its
  // first: the centre pixel). Stage 2: distances, codes, one weight-buffer entry
  // (FPGA target: over KPH cycles, a chunk a cycle).
  localparam int PW  = 24;                   // Y, U, V of one pixel
  localparam int WPW = WINDOW * PW;          // a window of pixels
  logic           s1_q;                      // stage 1 holds a chunk of a vertical column ...
  logic           s1_first_q;                // ... its first
  logic [PHB-1:0] s1_ch_q;                   // ... which
  logic [RB-1:0]  s1_r_q;
  logic [XB-1:0]  s1_c_q;
  logic [SLB-1:0] s1_slot_q;

  // Horizontal row buffer (Fig. 11): the centre row of the current row, COLS
  // pixels in flip-flops, written by the vertical pass, read by the horizontal one.
  logic [COLS*PW-1:0] hrow_q;

  function automatic logic [DCB-1:0] absdiff(input logic [7:0] a, input logic [7:0] b);
    logic [7:0] d;
    d = (a > b) ? a - b : b - a;
    absdiff = {{(DCB - 8){1'b0}}, d};
  endfunction

  function automatic logic [DCB-1:0] cdist(input logic [PW-1:0] a, input logic [PW-1:0] b);
    cdist = absdiff(a[7:0], b[7:0]) + absdiff(a[15:8], b[15:8]) + absdiff(a[23:16], b[23:16]);
  endfunction

  // The weight code of a colour distance: 7 - the thresholds it reaches.
  function automatic logic [WB-1:0] code_of(input logic [DCB-1:0] d, input logic [NTHR*DCB-1:0] thr);
    logic [WB-1:0]   passed;
    logic [NTHR-1:0] th;
    passed = '0;
    // An adder on both targets (a thermometer and a priority select on the FPGA target
    // made the design harder to route: docs/blocks/fpga_target.md, Timing).
    if (FPGA) begin
      th = '0;
      for (int i = 0; i < NTHR; i++) passed = passed + WB'(d >= thr[i*DCB +: DCB]);
    end else begin
      th = '0;
      for (int i = 0; i < NTHR; i++) passed = passed + WB'(d >= thr[i*DCB +: DCB]);
    end
    code_of = WB'(NTHR) - passed;
  endfunction

  // The centre pixel r + RADIUS of the column, from the chunk that holds it (the
  // vertical pass's first), goes into the horizontal row buffer.
  function automatic logic [PW-1:0] centre_pixel(input logic [3*CR*8-1:0] ch, input logic [RB-1:0] r);
    centre_pixel = '0;
    for (int o = 0; o < BLOCK; o++)
      centre_pixel = centre_pixel | ({ch[2*CR*8 + ((o + RADIUS) % CR)*8 +: 8], ch[CR*8 + ((o + RADIUS) % CR)*8 +: 8],
                                      ch[((o + RADIUS) % CR)*8 +: 8]} & {PW{r == RB'(o)}});
  endfunction

  logic           k_vert_q, k_horz_q;        // stage 2 writes a vertical / horizontal entry
  logic [SLB-1:0] k_slot_q;
  logic [GB-1:0]  k_grp_q;                   // entry: word and position in it
  logic [2:0]     k_pos_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      s1_q      <= 1'b0;
      s1_first_q <= 1'b0;
      s1_ch_q   <= '0;
      s1_sel_q  <= '0;
      s1_r_q    <= '0;
      s1_c_q    <= '0;
      s1_slot_q <= '0;
      k_vert_q  <= 1'b0;
      k_horz_q  <= 1'b0;
      k_slot_q  <= '0;
      k_grp_q   <= '0;
      k_pos_q   <= '0;
      k_done_q  <= 1'b0;
      k_slot2_q <= '0;
    end else begin
      s1_q      <= state_q == VERT;
      s1_first_q <= k_first;
      s1_ch_q   <= k_chunk;
      s1_sel_q  <= rcol[1:0];
      s1_r_q    <= r_q;
      s1_c_q    <= c_q;
      s1_slot_q <= wslot_q;
      // An entry's tags with its first chunk (vertical) or cycle (horizontal).
      k_vert_q  <= s1_q && s1_first_q;
      k_horz_q  <= state_q == HORZ && k_first;
      if (s1_q && s1_first_q) begin
        k_slot_q <= s1_slot_q;
        k_grp_q  <= GB'(s1_c_q[XB-1:3]);
        k_pos_q  <= s1_c_q[2:0];
      end else if (state_q == HORZ && k_first) begin
        k_slot_q <= wslot_q;
        k_grp_q  <= hg_q;
        k_pos_q  <= 3'(hm_q);
      end
      // The row is complete with its last horizontal entry.
      k_done_q  <= state_q == HORZ && k_first && c_q == XB'(BLOCK - 1);
      k_slot2_q <= wslot_q;
    end
  end

  always_ff @(posedge clk_i) begin
    // Decoded pixel by pixel (constant part-selects, no shifter across the row).
    if (s1_q && s1_first_q)
      for (int c = 0; c < COLS; c++)
        if (s1_c_q == XB'(c)) hrow_q[c*PW +: PW] <= centre_pixel(chunk, s1_r_q);
  end

  // ---- Weight buffers: NSLOT row slots, one word per aggregator read ---------------
  // Vertical: word (slot, group of LANES columns); horizontal: word (slot, group
  // of HAGG pixels). Stage 2 writes one entry of a word a cycle. ASIC target: one
  // RAM each, an entry written into its word's position; FPGA target: one RAM an
  // entry position (LANES and HAGG of them, an entry a word, no partial writes),
  // all read at the same address.
  localparam int VENTRY = WINDOW * WB;       // one vertical entry

  if (FPGA) begin : g_fpga_kernel
    // FPGA target: no window select of pixels, and an entry in KPH cycles, a
    // chunk of CR rows (columns) a cycle. The kernel register takes a chunk of the
    // column (vertical; the centre's chunk first) or of the centre row
    // (horizontal; in order), and NU = CR distance units compare it with the
    // centre, so the codes of all ROWS rows (columns) j; the window's WINDOW are
    // placed in folded order: code k is that of row (column) k + WINDOW when k < a,
    // k otherwise (a = r, or x; a 2:1 select of the first ROWS - WINDOW). KPH = 1
    // (CR = ROWS > WINDOW: FOLD): the register takes the column's or the row's
    // WINDOW pixels in that order instead, and WINDOW units compare them. The
    // folded codes are the vertical entry as the census buffer folds it
    // (mcadsw_census); the horizontal entry, the codes of columns x .. x + WINDOW
    // - 1 in order, is them rotated by x: code j is folded code (j + x) mod WINDOW.
    localparam bit FOLD = CR > WINDOW;       // KPH = 1: the pixels folded, WINDOW units
    localparam int NU   = FOLD ? WINDOW : CR;   // distance units
    localparam int UPX  = NU * PW;
    localparam int SW   = 3 + SLB;           // stage-2 flags: vertical, horizontal, done, slot
    localparam int FAB  = SLB + GB;          // weight-buffer address {slot, word}: no product
    logic [UPX-1:0] k_px_q;                  // the units' pixels
    logic [PW-1:0]  k_ctr_q;                 // the centre
    logic [RB-1:0]  k_at_q;                  // row r (vertical) or pixel x (horizontal)
    logic [PHB-1:0] k_ch_q;                  // the chunk in the units
    logic [KPH*SW-1:0] kst;                  // the stage-2 flags in the entry's cycle p at p*SW
    logic           k_mid;                   // stage 2 in an entry's cycle before its last

    // Rows (pixels) a .. a + WINDOW - 1 of ROWS pixels px (row j at j*PW) in folded order.
    function automatic logic [WPW-1:0] fold_pixels(input logic [ROWS*PW-1:0] px, input logic [RB-1:0] a);
      fold_pixels = px[WPW-1:0];
      for (int k = 0; k < ROWS - WINDOW; k++)
        if (k < 32'(a)) fold_pixels[k*PW +: PW] = px[(k + WINDOW)*PW +: PW];
    endfunction
    // A chunk's rows as pixels: Y, U, V of row j interleaved at j*PW.
    function automatic logic [CR*PW-1:0] chunk_pixels(input logic [3*CR*8-1:0] ch);
      for (int j = 0; j < CR; j++)
        chunk_pixels[j*PW +: PW] = {ch[2*CR*8 + j*8 +: 8], ch[CR*8 + j*8 +: 8], ch[j*8 +: 8]};
    endfunction
    // Chunk q of the centre row: a KPH:1 select of constant slices.
    function automatic logic [CR*PW-1:0] row_chunk(input logic [COLS*PW-1:0] row, input logic [PHB-1:0] q);
      row_chunk = '0;
      for (int i = 0; i < KPH; i++) row_chunk = row_chunk | (row[i*CR*PW +: CR*PW] & {(CR*PW){q == PHB'(i)}});
    endfunction

    if (FOLD) begin : g_fold_px
      always_ff @(posedge clk_i) begin
        if (s1_q) k_px_q <= fold_pixels(chunk_pixels(chunk), s1_r_q);
        else if (state_q == HORZ) k_px_q <= fold_pixels(hrow_q, RB'(c_q));
      end
    end else begin : g_chunk_px
      always_ff @(posedge clk_i) begin
        if (s1_q) k_px_q <= chunk_pixels(chunk);
        else if (state_q == HORZ) k_px_q <= row_chunk(hrow_q, kph_q);
      end
    end
    always_ff @(posedge clk_i) begin
      if (s1_q) begin
        k_ch_q <= s1_ch_q;
        if (s1_first_q) begin
          k_ctr_q <= centre_pixel(chunk, s1_r_q);
          k_at_q  <= s1_r_q;
        end
      end else if (state_q == HORZ) begin
        k_ch_q <= kph_q;
        if (k_first) begin
          for (int c = 0; c < BLOCK; c++)
            if (c_q == XB'(c)) k_ctr_q <= hrow_q[(c + RADIUS)*PW +: PW];
          k_at_q <= RB'(c_q);
        end
      end
    end

    // The codes of the register's NU pixels.
    function automatic logic [NU*WB-1:0] unit_codes(input logic [UPX-1:0] px, input logic [PW-1:0] ctr,
                                                    input logic [NTHR*DCB-1:0] thr);
      for (int k = 0; k < NU; k++) unit_codes[k*WB +: WB] = code_of(cdist(px[k*PW +: PW], ctr), thr);
    endfunction
    // The WINDOW codes of rows (columns) a .. a + WINDOW - 1 of the ROWS codes in folded order.
    function automatic logic [ENTRY-1:0] fold_codes(input logic [ROWS*WB-1:0] codes, input logic [RB-1:0] a);
      fold_codes = codes[ENTRY-1:0];
      for (int k = 0; k < ROWS - WINDOW; k++)
        if (k < 32'(a)) fold_codes[k*WB +: WB] = codes[(k + WINDOW)*WB +: WB];
    endfunction
    // Code j of the horizontal entry: folded code (j + x) mod WINDOW, a rotation by
    // x codes, one constant rotation a bit of x (x < WINDOW; no product x * WB,
    // which Yosys would place on a multiplier).
    function automatic logic [ENTRY-1:0] unfold(input logic [ENTRY-1:0] codes, input logic [RB-1:0] x);
      unfold = codes;
      for (int b = 0; b < RB; b++)
        if (x[b]) unfold = ENTRY'({unfold, unfold} >> ((1 << b)*WB));
    endfunction
    // Stage 2 takes KPH cycles, a chunk's codes a cycle (kst: its flags, delayed a
    // cycle at a time; the entry's tags and centre stand until its last cycle
    // ends, the next entry coming KPH cycles later). Stage 3 (FPGA target only):
    // the codes registered, then placed and written; a row is ready a cycle later
    // than on the ASIC target, and its passes take KPH times the cycles.
    logic [NU*WB-1:0]  k_units;              // this cycle's codes
    logic [ENTRY-1:0]  k_codes;              // the entry's codes in folded order (its last cycle)
    logic [SW-1:0]     k_last;               // the stage-2 flags in the entry's last cycle
    logic              k_last_en;
    logic [ENTRY-1:0]  k3_codes_q;
    logic [RB-1:0]     k3_at_q;
    logic              k3_vert_q, k3_horz_q, k3_done_q;
    logic [SLB-1:0]    k3_slot_q;
    logic [2:0]        k3_pos_q;
    logic [FAB-1:0]    k3_addr_q;
    assign kst[SW-1:0] = {k_vert_q, k_horz_q, k_done_q, k_slot2_q};
    for (genvar p = 1; p < KPH; p++) begin : g_kst
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) kst[p*SW +: SW] <= '0;
        else         kst[p*SW +: SW] <= kst[(p-1)*SW +: SW];
      end
    end
    logic [KPH-1:0] k_in_stage;              // an entry in the stage's cycle p
    for (genvar p = 0; p < KPH; p++) begin : g_in_stage
      assign k_in_stage[p] = kst[p*SW + SW - 1] || kst[p*SW + SW - 2];
    end
    always_comb begin
      k_busy = k3_done_q;
      for (int p = 0; p < KPH; p++) k_busy = k_busy || kst[p*SW + SLB];
    end
    assign k_mid     = (k_in_stage & ~(KPH'(1) << (KPH - 1))) != '0;
    assign k_units   = unit_codes(k_px_q, k_ctr_q, thr_i);
    assign k_last    = kst[(KPH-1)*SW +: SW];
    assign k_last_en = k_in_stage[KPH-1];
    if (FOLD) begin : g_fold_codes
      assign k_codes = k_units;
      logic ch_unused;
      assign ch_unused = ^{k_ch_q, k_mid};
    end else begin : g_acc
      logic [ROWS*WB-1:0] acc_q;             // the earlier chunks' codes, chunk q at q*CR*WB
      logic [ROWS*WB-1:0] rows;              // the ROWS codes, this cycle's chunk from the units
      always_ff @(posedge clk_i) begin
        if (k_mid)
          for (int q = 0; q < KPH; q++)
            if (k_ch_q == PHB'(q)) acc_q[q*NU*WB +: NU*WB] <= k_units;
      end
      always_comb begin
        rows = acc_q;
        for (int q = 0; q < KPH; q++)
          if (k_ch_q == PHB'(q)) rows[q*NU*WB +: NU*WB] = k_units;
      end
      assign k_codes = fold_codes(rows, k_at_q);
    end
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        {k3_vert_q, k3_horz_q, k3_done_q, k3_slot_q} <= '0;
      end else begin
        {k3_vert_q, k3_horz_q, k3_done_q, k3_slot_q} <= k_last;
      end
    end
    always_ff @(posedge clk_i) begin
      if (k_last_en) begin
        k3_codes_q <= k_codes;
        k3_at_q    <= k_at_q;
        k3_pos_q   <= k_pos_q;
        k3_addr_q  <= {k_slot_q, k_grp_q};
      end
    end
    assign w_done = k3_done_q;
    assign w_slot = k3_slot_q;
    // One entry in stage 2 at a time: its tags and centre stand for its KPH cycles.
    `MCADSW_ASSERT(OneEntryInStage2, (k_in_stage & (k_in_stage - KPH'(1))) == '0)
    logic [VENTRY-1:0] k_ventry;
    logic [ENTRY-1:0]  k_hentry;
    logic [FAB-1:0]    vrd_addr, hrd_addr;
    assign vrd_addr = {vrd_slot_i, vrd_grp_i};
    assign hrd_addr = {hrd_slot_i, hrd_grp_i};
    assign k_ventry = k3_codes_q;
    assign k_hentry = unfold(k3_codes_q, k3_at_q);
    for (genvar e = 0; e < LANES; e++) begin : g_vmem
      (* ram_style = "block", no_rw_check *) logic [VENTRY-1:0] mem_q [2**FAB];
      always_ff @(posedge clk_i) begin
        if (k3_vert_q && k3_pos_q == 3'(e)) mem_q[k3_addr_q] <= k_ventry;
        if (vrd_en_i) wv_o[e*VENTRY +: VENTRY] <= mem_q[vrd_addr];
      end
    end
    for (genvar e = 0; e < HAGG; e++) begin : g_hmem
      (* ram_style = "block", no_rw_check *) logic [ENTRY-1:0] mem_q [2**FAB];
      always_ff @(posedge clk_i) begin
        if (k3_horz_q && k3_pos_q == 3'(e)) mem_q[k3_addr_q] <= k_hentry;
        if (hrd_en_i) wh_o[e*ENTRY +: ENTRY] <= mem_q[hrd_addr];
      end
    end
    // The kernel fills a slot the aggregator does not read: no read meets the
    // write of its entry (the RAMs are no_rw_check, docs/blocks/fpga_target.md).
    `MCADSW_ASSERT(NoVertReadOfEntryWritten, !(k3_vert_q && vrd_en_i && k3_addr_q == vrd_addr))
    `MCADSW_ASSERT(NoHorzReadOfEntryWritten, !(k3_horz_q && hrd_en_i && k3_addr_q == hrd_addr))
  end else begin : g_asic_kernel
    localparam int VAB = $clog2(NSLOT * VGRP);
    localparam int HAB = $clog2(NSLOT * HGRP);
    logic [VAB-1:0] k_vaddr;
    logic [HAB-1:0] k_haddr;
    assign k_vaddr = VAB'(32'(k_slot_q)*VGRP + 32'(k_grp_q));
    assign k_haddr = HAB'(32'(k_slot_q)*HGRP + 32'(k_grp_q));
    assign w_done = k_done_q;
    assign w_slot = k_slot2_q;
    assign k_busy = k_done_q;
    logic ch_unused;                         // a column in one chunk
    assign ch_unused = ^{s1_ch_q, s1_first_q};
    // ASIC target: rows r .. r + WINDOW - 1 of the column, as pixels: each plane's
    // window is one of BLOCK row offsets (an AND-OR multiplexer, not a
    // bit-granular shifter), then Y, U, V are interleaved at constant positions;
    // WINDOW distance units against the window's centre. Functions called only
    // where their result is written, so a simulator evaluates them in the kernel's
    // cycles only; the hardware is the same.
    function automatic logic [WPW-1:0] vwindow(input logic [3*CW-1:0] col, input logic [RB-1:0] r);
      logic [3*WINDOW*8-1:0] planes;    // Y, U, V windows
      planes = '0;
      for (int o = 0; o < BLOCK; o++)
        planes = planes | ({col[2*CW + o*8 +: WINDOW*8], col[CW + o*8 +: WINDOW*8], col[o*8 +: WINDOW*8]} &
                           {(3*WINDOW*8){r == RB'(o)}});
      for (int k = 0; k < WINDOW; k++)
        vwindow[k*PW +: PW] = {planes[2*WINDOW*8 + k*8 +: 8], planes[WINDOW*8 + k*8 +: 8], planes[k*8 +: 8]};
    endfunction

    function automatic logic [WPW-1:0] hwindow(input logic [COLS*PW-1:0] row, input logic [XB-1:0] c);
      hwindow = '0;
      for (int o = 0; o < BLOCK; o++) hwindow = hwindow | (row[o*PW +: WPW] & {WPW{c == XB'(o)}});
    endfunction

    function automatic logic [ENTRY-1:0] weight_codes(input logic [WPW-1:0] win,
                                                      input logic [NTHR*DCB-1:0] thr);
      for (int k = 0; k < WINDOW; k++)
        weight_codes[k*WB +: WB] = code_of(cdist(win[k*PW +: PW], win[RADIUS*PW +: PW]), thr);
    endfunction

    logic [LANES*VENTRY-1:0] vbuf_q [NSLOT*VGRP];
    logic [HAGG*ENTRY-1:0]   hbuf_q [NSLOT*HGRP];
    logic [WPW-1:0] k_win_q;
    always_ff @(posedge clk_i) begin
      if (s1_q) k_win_q <= vwindow(chunk, s1_r_q);
      else if (state_q == HORZ) k_win_q <= hwindow(hrow_q, c_q);
    end

    always_ff @(posedge clk_i) begin
      if (k_vert_q || k_horz_q) begin : p_kernel
        logic [ENTRY-1:0] codes;  // one kernel for both passes
        codes = weight_codes(k_win_q, thr_i);
        if (k_vert_q) vbuf_q[k_vaddr][32'(k_pos_q)*VENTRY +: VENTRY] <= codes;
        else          hbuf_q[k_haddr][32'(k_pos_q)*ENTRY +: ENTRY] <= codes;
      end
    end

    always_ff @(posedge clk_i) begin
      if (vrd_en_i) wv_o <= vbuf_q[VAB'(32'(vrd_slot_i)*VGRP + 32'(vrd_grp_i))];
      if (hrd_en_i) wh_o <= hbuf_q[HAB'(32'(hrd_slot_i)*HGRP + 32'(hrd_grp_i))];
    end
  end

  // What the cost aggregator keeps: a row taken once ready, reads of occupied
  // slots, a window configured once the previous one is taken.
  `MCADSW_ASSUME(RowTakenWhenReady, !(row_take_i && !row_ready_o))
  `MCADSW_ASSUME(ReadOfOccupiedSlot, !(vrd_en_i && !occ_q[vrd_slot_i]) && !(hrd_en_i && !occ_q[hrd_slot_i]))
  `MCADSW_ASSUME(ConfiguredWhenReady, !(cfg_valid_i && !cfg_ready_o))

endmodule

`default_nettype wire
