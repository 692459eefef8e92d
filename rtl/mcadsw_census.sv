// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Mini-census transformer (paper Sec. V-B, Fig. 10): input buffer, mini-census
// kernel, census buffer. Instantiated for the left view (COLS = 48) and the
// right view (COLS = 48 + DMAX - 1, the columns x - d can reach).
//
// Input: the luma of the read window, COLS + 4 columns by ROWS + 4 rows (2
// extra on each side for the 5x5 template), in strips of 4 columns: for strip
// s, rows 0 .. ROWS+3 of columns 4s .. 4s+3, one 32-bit word a row, byte 0 the
// leftmost column (the weight generator takes the same format). The strips
// start at the aligned memory word left of the window, cfg_ofs_i (0..3)
// columns early, so that each strip word is one memory read; there are
// STRIPS = (COLS + 4 + 3 + 3) / 4 of them. The memory side reads at clamped
// coordinates, so every pixel has a value. Only strips cfg_first_i .. STRIPS-1
// arrive: a block that continues its left neighbour (cfg_cont_i) receives the
// strips the neighbour's window lacks (partial column reuse, Sec. IV); the
// first block of a row band skips the strips left of the first one the kernel
// needs (those wholly left of image column -2).
//
// Input buffer: a ring of LS strips of luma column words (a power of 2; column
// p of the ring in sub-bank p % 8, 8 sub-banks), filled through a staging
// register that collects a strip and writes 4 whole columns. Window strip s
// lives in ring strip (base + s) mod LS; base advances by the strips the
// window origin moved, so along a row band the ring is one stream of strips
// and a continuing block finds the neighbour's last strips in it. The kernel
// runs while the strips arrive: a strip is written only when the kernel no
// longer needs the ring strip it replaces, and a census column is computed
// once its 5 luma columns are in.
//
// Kernel: one column of ROWS codes a cycle (the FPGA target: a quarter of the
// rows a cycle, below). Position (i, j) of the census
// buffer receives the code of the nearest in-image position (clamp(i, lo_x,
// hi_x), clamp(j, lo_y, hi_y)): the border rule of docs/algorithm.md, applied
// once, when the buffer is written. Columns left of lo_x are computed from the
// luma of column lo_x; columns right of hi_x repeat the last computed column
// (column hi_x, or for a continuing block whose new columns are all right of
// the image, the neighbour's last column, which is column hi_x's code), so the
// kernel never needs luma strips behind the stream.
//
// Census buffer: a ring of RING census columns (COLS + BLOCK, rounded up to a
// multiple of CSUB), each a column word of ROWS codes, in CSUB sub-banks (ring
// column q in sub-bank q % CSUB), so the read port's RL consecutive columns
// come from distinct sub-banks; it delivers RL columns x WINDOW rows a cycle
// (Fig. 12). RL = LANES (8) and CSUB = 8 for the paper's engine; the right view
// of an engine with P disparities a step reads RL = LANES + P - 1 columns
// (11 for P = 4), CSUB the next power of two (16). A block that continues its left
// neighbour starts BLOCK ring columns after it, shares the neighbour's last COLS -
// BLOCK columns (codes depend only on the clamped image position) and computes only
// its BLOCK new ones, into ring columns the block before the neighbour used: the
// scheduler prepares a block only after that one has left the aggregator. The first
// block of a row band starts COLS ring columns after the previous block, so its first
// RING - COLS columns land in free ring columns; for the others its kernel waits
// until the previous block has left the aggregator (ring_free_i). The read port names
// a block by the bank the scheduler gave it (rd_bank_i, two blocks in flight): the
// ring position of each bank's window is kept.
//
// FPGA target (mcadsw_pkg::FPGA, docs/blocks/fpga_target.md): RL read ports, each
// a copy of the ring RING column words deep (block RAM: deep and at most 288 bits
// wide, no sub-banks) with its own column address; a column is written into every
// copy, and a read returns the whole column word (ROWS codes), held until the
// port's next read. The cost aggregator, which reads the left view one column a
// cycle (RL = 1) and the right view two (RL = 2: its lane shift register and the
// next group's columns), keeps the lanes and selects the window's rows itself.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_census #(
  parameter int COLS   = mcadsw_pkg::BLOCK_COLS,   // census positions per row
  parameter int ROWS   = mcadsw_pkg::BLOCK_COLS,   // census rows (18 + 30)
  parameter int LANES  = mcadsw_pkg::LANES,
  parameter bit FPGA   = 1'(mcadsw_pkg::FPGA),     // the FPGA target's buffer shape
  parameter int RL     = FPGA ? 1 : LANES,         // census columns a read (LANES + P - 1);
                                                   // FPGA: read ports
  parameter int CSUB   = 1 << $clog2(FPGA ? LANES : RL),  // census sub-banks (8 or 16)
  parameter int BLOCK  = mcadsw_pkg::BLOCK,
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int CB     = mcadsw_pkg::CENSUS_BITS,
  parameter int RPORTS = FPGA ? RL : 1,            // read addresses
  parameter int RDW    = FPGA ? RL*ROWS*CB : RL*WINDOW*CB,  // read data
  parameter int BANKS  = 2,
  parameter int STRIPS = (COLS + 4 + 6) / 4,       // input strips (room for an offset of 3)
  parameter int LS     = 4,                        // luma ring strips (a power of 2)
  parameter int SB     = $clog2(STRIPS + 1),
  parameter int XB     = $clog2(COLS),             // column index width
  parameter int RING   = (COLS + BLOCK + CSUB - 1) / CSUB * CSUB,  // census buffer columns
  parameter int QB     = $clog2(RING),             // ring column index width
  parameter int YB     = $clog2(ROWS),             // row index width
  parameter int BB     = (BANKS > 1) ? $clog2(BANKS) : 1
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,
  // Block configuration: bank to fill, in-image bounds in window coordinates
  input  logic                       cfg_valid_i,
  output logic                       cfg_ready_o,
  input  logic [BB-1:0]              cfg_bank_i,
  input  logic [XB-1:0]              cfg_lo_x_i,
  input  logic [XB-1:0]              cfg_hi_x_i,
  input  logic [YB-1:0]              cfg_lo_y_i,
  input  logic [YB-1:0]              cfg_hi_y_i,
  input  logic [1:0]                 cfg_ofs_i,   // window column 0 is input column cfg_ofs_i
  input  logic                       cfg_cont_i,  // the block continues its left neighbour
  input  logic [SB-1:0]              cfg_first_i, // first strip delivered
  input  logic                       ring_free_i, // the previous block has left the aggregator
  // Luma words of the window
  input  logic                       pix_valid_i,
  output logic                       pix_ready_o,
  input  logic [31:0]                pix_data_i,
  output logic                       done_o,      // one cycle: the bank is complete
  output logic                       busy_o,
  // Census buffer read port (cost aggregator), data one cycle after address.
  // ASIC target: RL consecutive columns from rd_col_i, lane l tap k at (l*WINDOW +
  // k)*CB. FPGA target: port p reads column rd_col_i[p XB +: XB] when rd_en_i[p],
  // its column word (ROWS codes, row j at j CB) at p ROWS CB.
  input  logic [RPORTS-1:0]          rd_en_i,
  input  logic [BB-1:0]              rd_bank_i,
  input  logic [YB-1:0]              rd_row_i,    // first of WINDOW rows (ASIC target)
  input  logic [RPORTS*XB-1:0]       rd_col_i,
  output logic [RDW-1:0]             rd_data_o
);

  localparam int SUB    = 8;                       // luma sub-banks (columns)
  localparam int CSB    = $clog2(CSUB);            // census sub-bank index width
  localparam int LROWS  = ROWS + 4;
  localparam int LSB    = $clog2(LS);
  localparam int LCB    = $clog2(4 * LS);          // ring luma column index
  localparam int LDEPTH = LS * 4 / SUB;            // luma words per sub-bank
  localparam int CDEPTH = RING / CSUB;             // census words per sub-bank
  localparam int LW     = LROWS * 8;               // luma column word
  localparam int CWB    = ROWS * CB;               // census column word
  localparam int KB     = $clog2(COLS + 4);        // luma column index in the window
  // The kernel computes a column in KCH chunks of RCH rows, one a cycle: the ASIC
  // target all at once, the FPGA target in 4 (a column's luma arrives at most every
  // 13 cycles: a strip word of 4 columns a row, ROWS + 4 rows).
  localparam int KCH    = FPGA ? 4 : 1;
  localparam int RCH    = ROWS / KCH;              // rows a chunk
  localparam int KW     = (RCH + 4) * 8;           // a chunk's luma rows of one column

  if (ROWS < WINDOW || LANES != SUB || CB != 6 || STRIPS * 4 < COLS + 4 + 3 || COLS < BLOCK ||
      RING % CSUB != 0 || RING < COLS + BLOCK || (1 << LSB) != LS || LS < 4 ||
      LDEPTH < 2 || (!FPGA && (RL < LANES || RL > CSUB)) || (1 << CSB) != CSUB ||
      RL > COLS || ROWS - WINDOW > WINDOW || RPORTS != (FPGA ? RL : 1) ||
      RDW != (FPGA ? RL*ROWS*CB : RL*WINDOW*CB) || ROWS % KCH != 0) begin : g_bad_param
    mcadsw_error_census_geometry u_error ();
  end

  // v mod n for 0 <= v < 2n.
  function automatic int wrap(input int v, input int n);
    wrap = (v >= n) ? v - n : v;
  endfunction

  // ---- Control ----------------------------------------------------------------------
  typedef enum logic [1:0] {IDLE, RUN, FLUSH, FLUSH2} state_e;
  state_e        state_q;
  logic          cont_q;         // the block continues its left neighbour
  logic [QB-1:0] cpos_q;         // ring column of the block's window column 0
  logic [BANKS*QB-1:0] bpos_q;   // ... of each bank's block (read port), bank b at QB b
  logic [XB-1:0] lo_x_q, hi_x_q;
  logic [YB-1:0] lo_y_q, hi_y_q;
  logic [1:0]    ofs_q;
  logic [LSB-1:0] base_q;        // ring strip of window strip 0
  logic [XB-1:0] ki_q;           // census column the kernel computes next
  logic          kfin_q;         // the kernel has issued its last column
  logic          loaded_q;       // the whole window has arrived
  logic [SB-1:0] wcnt_q;         // window strips in the ring (strips < wcnt_q)
  logic          pix_fire;

  // The kernel's current column and the luma it needs: window luma columns
  // lk .. lk + 4, lk = ofs + clamp(ki, lo_x, ...), in window strips lk/4 .. lk/4 + 1.
  logic [XB-1:0] ic;
  logic [KB-1:0] lk;
  logic          need_luma;      // ki <= hi_x: the column is computed, not repeated
  logic          luma_ok, ring_ok, issue;
  logic          kern_ok;        // the kernel has the column's codes but the last chunk's
  assign ic        = (ki_q < lo_x_q) ? lo_x_q : ki_q;
  assign need_luma = ki_q <= hi_x_q;
  // A band-start block's columns from RING - COLS on are the previous block's.
  assign ring_ok   = cont_q || ring_free_i || 32'(ki_q) < RING - COLS;
  assign issue     = state_q == RUN && !kfin_q && luma_ok && ring_ok && kern_ok;

  // A strip may be written when the kernel no longer needs the ring strip it
  // replaces (window strip s - LS): all strips from lk/4 on are still needed.
  logic [SB-1:0] in_strip;       // strip of the word being accepted
  logic          strip_end, win_done;
  logic          may_write;
  assign may_write   = kfin_q || !need_luma || 32'(in_strip) < 32'(lk[KB-1:2]) + LS;
  assign cfg_ready_o = state_q == IDLE;
  assign busy_o      = state_q != IDLE;
  assign pix_ready_o = state_q == RUN && !loaded_q && may_write;
  assign pix_fire    = pix_valid_i && pix_ready_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q  <= IDLE;
      cont_q   <= 1'b0;
      cpos_q   <= '0;
      bpos_q   <= '0;
      lo_x_q   <= '0;
      hi_x_q   <= '0;
      lo_y_q   <= '0;
      hi_y_q   <= '0;
      ofs_q    <= '0;
      base_q   <= '0;
      ki_q     <= '0;
      kfin_q   <= 1'b0;
      loaded_q <= 1'b0;
      wcnt_q   <= '0;
      done_o   <= 1'b0;
    end else begin
      done_o <= 1'b0;
      case (state_q)
        IDLE: if (cfg_valid_i) begin
          logic [QB-1:0] np;
          // Continuing: BLOCK columns on; band start: after the previous window.
          np = QB'(wrap(32'(cpos_q) + (cfg_cont_i ? BLOCK : COLS), RING));
          state_q  <= RUN;
          cont_q   <= cfg_cont_i;
          cpos_q   <= np;
          bpos_q[32'(cfg_bank_i)*QB +: QB] <= np;
          lo_x_q   <= cfg_lo_x_i;
          hi_x_q   <= cfg_hi_x_i;
          lo_y_q   <= cfg_lo_y_i;
          hi_y_q   <= cfg_hi_y_i;
          ofs_q    <= cfg_ofs_i;
          base_q   <= LSB'(32'(base_q) + STRIPS - 32'(cfg_first_i));
          // A continuing block computes only its BLOCK new columns.
          ki_q     <= cfg_cont_i ? XB'(COLS - BLOCK) : '0;
          kfin_q   <= 1'b0;
          loaded_q <= 1'b0;
          wcnt_q   <= cfg_first_i;
        end
        RUN: begin
          if (issue) begin
            if (ki_q == XB'(COLS - 1)) kfin_q <= 1'b1;
            else ki_q <= ki_q + XB'(1);
          end
          if (pix_fire && strip_end) wcnt_q <= wcnt_q + SB'(1);
          if (pix_fire && win_done) loaded_q <= 1'b1;
          if (kfin_q && loaded_q) state_q <= FLUSH;
        end
        FLUSH: state_q <= FLUSH2;  // the last column is read and computed
        FLUSH2: begin              // and written
          state_q <= IDLE;
          done_o  <= 1'b1;
        end
        default: state_q <= IDLE;
      endcase
    end
  end

  // ---- Input buffer -------------------------------------------------------------------
  logic [4*LW-1:0]   strip_cols;       // the 4 luma columns of a finished strip
  logic              col_valid;        // FPGA target: the strip's columns one a cycle
  logic [1:0]        col_b;            // ... column col_b of the last strip
  logic [LW-1:0]     col_word;

  mcadsw_strip_stage #(.ROWS(LROWS), .STRIPS(STRIPS), .PLANES(1), .COLUMNS(FPGA)) u_stage (
    .clk_i, .rst_ni,
    .start_i (cfg_valid_i && cfg_ready_o),
    .first_i (cfg_first_i),
    .wr_i    (pix_fire),
    .data_i  (pix_data_i),
    .last_o  (strip_end),
    .done_o  (win_done),
    .plane_o (),
    .strip_o (in_strip),
    .cols_o  (strip_cols),
    .col_valid_o (col_valid),
    .col_n_o (col_b),
    .col_o   (col_word)
  );

  logic [LSB-1:0] wstrip;         // ring strip of the finished input strip
  assign wstrip = base_q + LSB'(in_strip);

  // ---- Kernel: a column of codes (Fig. 2 template, docs/algorithm.md bit order) ---
  // Written as functions and called only where a column is computed, so a
  // simulator evaluates them in the kernel's COLS cycles of a block, not in every
  // cycle; the hardware is the same combinational kernel.
  // The codes of a chunk's RCH rows from its luma rows (RCH + 4) of columns lcol ..
  // lcol + 4 (kcols, a column every KW bits), unclamped.
  function automatic logic [RCH*CB-1:0] census_codes(input logic [5*KW-1:0] kcols);
    for (int j = 0; j < RCH; j++) begin
      logic [7:0] c;
      c = kcols[2*KW + (j + 2)*8 +: 8];
      census_codes[j*CB + 5] = kcols[(2 + mcadsw_pkg::TAP0_DX)*KW + (j + 2 + mcadsw_pkg::TAP0_DY)*8 +: 8] <= c;
      census_codes[j*CB + 4] = kcols[(2 + mcadsw_pkg::TAP1_DX)*KW + (j + 2 + mcadsw_pkg::TAP1_DY)*8 +: 8] <= c;
      census_codes[j*CB + 3] = kcols[(2 + mcadsw_pkg::TAP2_DX)*KW + (j + 2 + mcadsw_pkg::TAP2_DY)*8 +: 8] <= c;
      census_codes[j*CB + 2] = kcols[(2 + mcadsw_pkg::TAP3_DX)*KW + (j + 2 + mcadsw_pkg::TAP3_DY)*8 +: 8] <= c;
      census_codes[j*CB + 1] = kcols[(2 + mcadsw_pkg::TAP4_DX)*KW + (j + 2 + mcadsw_pkg::TAP4_DY)*8 +: 8] <= c;
      census_codes[j*CB + 0] = kcols[(2 + mcadsw_pkg::TAP5_DX)*KW + (j + 2 + mcadsw_pkg::TAP5_DY)*8 +: 8] <= c;
    end
  endfunction

  // Rows outside the image take the code of the edge row.
  function automatic logic [CWB-1:0] clamp_rows(input logic [CWB-1:0] raw,
                                                input logic [YB-1:0] lo_y,
                                                input logic [YB-1:0] hi_y);
    for (int j = 0; j < ROWS; j++) begin
      if (j < 32'(lo_y)) clamp_rows[j*CB +: CB] = raw[32'(lo_y)*CB +: CB];
      else if (j > 32'(hi_y)) clamp_rows[j*CB +: CB] = raw[32'(hi_y)*CB +: CB];
      else clamp_rows[j*CB +: CB] = raw[j*CB +: CB];
    end
  endfunction

  // Pipeline (ASIC target): cycle 1 reads the luma columns of census column ki,
  // cycle 2 computes its codes into col_q (or keeps col_q: a column right of
  // hi_x), cycle 3 writes them. (FPGA target: the chunks enter col_q up to the
  // issue cycle, the next writes the column, its rows clamped.)
  logic           rd_valid_q, rd_fresh_q, col_valid_q;
  logic [XB-1:0]  rd_ki_q, col_ki_q;
  logic [CWB-1:0] col_q;
  logic [CWB-1:0] col_wr;      // the column written (FPGA target: col_q with its rows clamped)
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rd_valid_q  <= 1'b0;
      rd_fresh_q  <= 1'b0;
      rd_ki_q     <= '0;
      col_valid_q <= 1'b0;
      col_ki_q    <= '0;
    end else begin
      rd_valid_q  <= issue;
      rd_fresh_q  <= need_luma;
      rd_ki_q     <= ki_q;
      col_valid_q <= rd_valid_q;
      col_ki_q    <= rd_ki_q;
    end
  end

  // ASIC target: ring luma columns the kernel reads: lc .. lc + 4 (mod 4 LS),
  // lc = 4 base + lk, from 8 sub-banks (the word each read in lsub_q). Index
  // arithmetic in narrow unsigned vectors: the ring is a power of 2, the sub-bank
  // of a column is its low 3 bits, its word the rest. (Declared outside the
  // target's branch for the coverage model, as lsel below.)
  logic [LCB-1:0]     lc;
  logic [SUB*LW-1:0]  lsub_q;
  logic [2:0]         rd_lc_q;        // lc mod 8: the sub-bank of the first luma column
  assign lc = LCB'({base_q, 2'b00}) + LCB'(lk);

  if (FPGA) begin : g_fpga_luma
    // FPGA target: the ring is one RAM of 4 LS luma columns, a column an entry
    // (distributed RAM, no sub-banks and no column selects). The strip stage
    // presents a finished strip's 4 columns one a cycle over the next 4 cycles
    // (COLUMNS), and they are written so. A loader reads one column a cycle, in
    // order, into a window of the 5 columns the kernel needs (a shift register):
    // column nl once it is written (nl < wcol) while the window, after this
    // cycle's issue, still lacks it (nl < lk' + 5). The kernel issues when the
    // window holds lk .. lk + 4 (nl = lk + 5) and the kernel has computed the
    // column's first KCH - 1 chunks of rows from it, one a cycle (the window stays:
    // the loader waits for the issue); the issue cycle computes the last chunk,
    // the next cycle clamps the rows. Against the ASIC target a block's first
    // column waits for its 5 loads, a column that needs a new strip for that
    // column's write and load, and every computed column for its chunks: a column
    // every KCH cycles at most (docs/blocks/fpga_target.md).
    // The chunks' codes enter col_q unclamped; rows lo_y's and hi_y's codes are
    // also held (elo_q, ehi_q: a RCH:1 select of the chunk's codes, at their
    // chunks' cycles), and the column is clamped on its way into the buffer, in
    // the cycle after its issue: rows above lo_y take elo_q, rows below hi_y
    // ehi_q (above_q, below_q: masks set with the block), so there is no ROWS:1
    // select of the edge rows and no second register of the column. (The next
    // column's first chunk may enter col_q in that cycle: the write takes the
    // column before it.)
    localparam int NB = $clog2(COLS + 11);   // window luma columns, up to 4 STRIPS and lk + 6
    logic [LW-1:0]   lmem [4*LS];
    logic [LSB-1:0]  hstrip_q;        // the ring strip of the columns written
    logic [NB-1:0]   wcol_q;          // window luma columns written: those < wcol_q
    logic [NB-1:0]   nl_q;            // the window luma column the loader reads next
    logic [5*LW-1:0] win_q;           // luma columns nl - 5 .. nl - 1, the oldest at 0
    logic [NB-1:0]   lk_next;         // lk after this cycle's issue
    logic [XB-1:0]   ki0;             // a block's first column
    logic [NB-1:0]   lk0;             // ... and its lk
    logic            load;
    localparam int KCB = $clog2(KCH);
    localparam int OCB = $clog2(RCH);
    logic [KCB-1:0]  ph_q;            // the chunk the kernel computes next
    logic [KCB-1:0]  c_lo_q, c_hi_q;  // the chunks of rows lo_y and hi_y (set with them)
    logic [OCB-1:0]  o_lo_q, o_hi_q;  // ... and the rows' places in them
    logic [ROWS-1:0] above_q, below_q;  // rows above lo_y, below hi_y
    logic            kern_win;        // the window holds a computed column's luma
    logic [RCH*CB-1:0] kcodes;        // chunk ph_q's codes, unclamped
    logic [CB-1:0]   elo_q, ehi_q;    // rows lo_y's and hi_y's codes of the column
    // Chunk c's luma rows of the window's 5 columns: rows c RCH .. c RCH + RCH + 3.
    // A KCH:1 select of constant slices (not a shifter).
    function automatic logic [5*KW-1:0] chunk_rows(input logic [5*LW-1:0] lcols, input logic [KCB-1:0] c);
      chunk_rows = '0;
      for (int k = 0; k < KCH; k++)
        if (c == KCB'(k))
          for (int dx = 0; dx < 5; dx++) chunk_rows[dx*KW +: KW] = lcols[dx*LW + k*RCH*8 +: KW];
    endfunction
    assign lk      = KB'(ofs_q) + KB'(ic);
    assign lk_next = NB'(lk) + NB'(issue && ki_q >= lo_x_q && ki_q != XB'(COLS - 1));
    assign ki0     = cfg_cont_i ? XB'(COLS - BLOCK) : '0;
    assign lk0     = NB'(cfg_ofs_i) + NB'((ki0 < cfg_lo_x_i) ? cfg_lo_x_i : ki0);
    assign load    = state_q == RUN && nl_q < wcol_q && nl_q < lk_next + NB'(5);
    assign luma_ok = !need_luma || nl_q == NB'(lk) + NB'(5);
    assign kern_win = state_q == RUN && !kfin_q && need_luma && luma_ok;
    assign kern_ok  = !need_luma || ph_q == KCB'(KCH - 1);
    // Evaluated only while the kernel runs (simulation speed; the same hardware).
    always_comb begin
      kcodes = '0;
      if (kern_win) kcodes = census_codes(chunk_rows(win_q, ph_q));
    end
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        hstrip_q <= '0;
        wcol_q   <= '0;
        nl_q     <= '0;
        ph_q     <= '0;
        c_lo_q   <= '0;
        c_hi_q   <= '0;
        o_lo_q   <= '0;
        o_hi_q   <= '0;
        above_q  <= '0;
        below_q  <= '0;
      end else begin
        if (issue) ph_q <= '0;
        else if (kern_win && ph_q != KCB'(KCH - 1)) ph_q <= ph_q + KCB'(1);
        if (state_q == IDLE && cfg_valid_i) begin
          c_lo_q <= KCB'(32'(cfg_lo_y_i) / RCH);
          o_lo_q <= OCB'(32'(cfg_lo_y_i) % RCH);
          c_hi_q <= KCB'(32'(cfg_hi_y_i) / RCH);
          o_hi_q <= OCB'(32'(cfg_hi_y_i) % RCH);
          for (int j = 0; j < ROWS; j++) begin
            above_q[j] <= j < 32'(cfg_lo_y_i);
            below_q[j] <= j > 32'(cfg_hi_y_i);
          end
        end
        if (pix_fire && strip_end) hstrip_q <= wstrip;
        if (state_q == IDLE && cfg_valid_i) begin
          wcol_q <= NB'({cfg_first_i, 2'b00});
          nl_q   <= lk0;
        end else begin
          if (state_q == RUN && col_valid) wcol_q <= wcol_q + NB'(1);
          if (load) nl_q <= nl_q + NB'(1);
        end
      end
    end
    always_ff @(posedge clk_i) begin
      if (col_valid) lmem[{hstrip_q, col_b}] <= col_word;
      if (load) win_q <= {lmem[LCB'({base_q, 2'b00}) + LCB'(nl_q)], win_q[5*LW-1:LW]};
      for (int k = 0; k < KCH; k++) if (kern_win && ph_q == KCB'(k)) col_q[k*RCH*CB +: RCH*CB] <= kcodes;
      if (kern_win && ph_q == c_lo_q) elo_q <= kcodes[32'(o_lo_q)*CB +: CB];
      if (kern_win && ph_q == c_hi_q) ehi_q <= kcodes[32'(o_hi_q)*CB +: CB];
    end
    // The column into the buffer, rows clamped.
    for (genvar j = 0; j < ROWS; j++) begin : g_clamp
      assign col_wr[j*CB +: CB] = above_q[j] ? elo_q : below_q[j] ? ehi_q : col_q[j*CB +: CB];
    end
    assign lsub_q  = '0;
    assign rd_lc_q = '0;
    logic asic_unused;
    assign asic_unused = ^{lsub_q, rd_lc_q, lc, strip_cols, rd_fresh_q, lo_y_q, hi_y_q};
    // The previous block's last column write may share the cycle of the next
    // block's configuration, never its run; the loader starts at a delivered strip.
    `MCADSW_ASSERT(StripWrittenBeforeNextBlock, !(state_q == IDLE && cfg_valid_i && col_valid && col_b != 2'd3))
    `MCADSW_ASSERT(FirstColumnDelivered, !(state_q == IDLE && cfg_valid_i && !cfg_cont_i && lk0 < NB'({cfg_first_i, 2'b00})))
    `MCADSW_ASSERT(WindowNotAhead, !(state_q == RUN && need_luma && !kfin_q && nl_q > NB'(lk) + NB'(5)))
  end else begin : g_asic_luma
    assign lk      = KB'(ofs_q) + KB'(ic);
    logic cols_unused;                    // the stage's columns one a cycle: FPGA target
    assign cols_unused = ^{col_valid, col_b, col_word};
    assign luma_ok = !need_luma || SB'(lk[KB-1:2]) + SB'(1) < wcnt_q;
    assign kern_ok = 1'b1;                // a column's codes in one cycle (KCH = 1)

    for (genvar b = 0; b < SUB; b++) begin : g_lsub
      // Ring strip t holds columns 4t .. 4t+3: sub-bank b receives column
      // 4t + (b % 4) when t has the parity of b / 4.
      logic [LW-1:0] wr_col;
      assign wr_col = strip_cols[(b % 4)*LW +: LW];

      logic [LW-1:0] mem_q [LDEPTH];
      always_ff @(posedge clk_i) begin
        if (pix_fire && strip_end && wstrip[0] == 1'(b / 4)) mem_q[wstrip[LSB-1:1]] <= wr_col;
      end
      // Read: the one of columns lc .. lc+7 that lives in this sub-bank.
      // Its word: that of lc, or the next one when b is below lc's sub-bank.
      logic [3:0]     bd;                  // b - (lc mod 8); bit 3: the borrow, b below it
      logic [2:0]     bd_unused;
      assign bd = 4'(b) - {1'b0, lc[2:0]};
      assign bd_unused = bd[2:0];
      always_ff @(posedge clk_i) begin
        if (issue) lsub_q[b*LW +: LW] <= mem_q[(LCB - 3)'(lc[LCB-1:3] + (LCB - 3)'(bd[3]))];
      end
    end

    // The sub-bank word of luma column p: an 8:1 multiplexer.
    function automatic logic [LW-1:0] luma_col(input logic [SUB*LW-1:0] rd, input logic [2:0] b);
      luma_col = '0;
      for (int i = 0; i < SUB; i++) luma_col = luma_col | (rd[i*LW +: LW] & {LW{b == 3'(i)}});
    endfunction
    // Luma columns lcol .. lcol + 4 from the sub-bank words.
    function automatic logic [5*LW-1:0] luma_cols(input logic [SUB*LW-1:0] rd, input int lcol);
      for (int dx = 0; dx < 5; dx++) luma_cols[dx*LW +: LW] = luma_col(rd, 3'(lcol + dx));
    endfunction

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) rd_lc_q <= '0;
      else rd_lc_q <= 3'(lc);
    end
    always_ff @(posedge clk_i) begin
      if (rd_valid_q && rd_fresh_q)
        col_q <= clamp_rows(census_codes(luma_cols(lsub_q, 32'(rd_lc_q))), lo_y_q, hi_y_q);
    end
    assign col_wr = col_q;
  end

  // ---- Census buffer and read port ----------------------------------------------------
  // A column is written in the cycle after it was read and computed (col_valid_q),
  // on the FPGA target in the cycle after its issue (its last chunk entered col_q
  // in the issue cycle; the rows are clamped on the way, col_wr).
  logic          wr_en;
  logic [XB-1:0] wr_ki;
  assign wr_en = FPGA ? rd_valid_q : col_valid_q;
  assign wr_ki = FPGA ? rd_ki_q : col_ki_q;
  logic [QB-1:0] wq, rq;        // ring columns of the column written and of the first read
  assign wq = QB'(wrap(32'(cpos_q) + 32'(wr_ki), RING));
  assign rq = QB'(wrap(32'(bpos_q[32'(rd_bank_i)*QB +: QB]) + 32'(rd_col_i[XB-1:0]), RING));
  // ASIC target: lane l is ring column rq + l, from sub-bank (rq + l) % CSUB: a
  // CSUB:1 multiplexer whose one-hot select is decoded from the address and
  // registered with it, so no adder or decoder lies between the sub-bank words
  // and the aggregator. Its WINDOW codes are rows rd_row .. rd_row + WINDOW - 1 of
  // the column word (a row shifter). (Declared here, outside the target's branch,
  // so that the coverage model instruments them: Verilator 5.006 records no
  // toggle points inside generate blocks.)
  logic [RL*CSUB-1:0] lsel, lsel_q;   // lane l takes sub-bank b when bit l CSUB + b is set
  for (genvar l = 0; l < RL; l++) begin : g_lsel
    logic [CSB-1:0] b;
    assign b = CSB'(rq) + CSB'(l);
    assign lsel[l*CSUB +: CSUB] = CSUB'(1) << b;
  end

  logic [YB-1:0]  rd_row_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rd_row_q <= '0;
      lsel_q   <= '0;
    end else if (rd_en_i[0]) begin
      rd_row_q <= rd_row_i;
      lsel_q   <= lsel;
    end
  end

  if (FPGA) begin : g_fpga_buf
    // A copy of the ring a port, each read at its own column.
    logic asic_unused;
    assign asic_unused = ^{lsel_q, rd_row_q, rq};
    for (genvar p = 0; p < RL; p++) begin : g_port
      (* ram_style = "block", no_rw_check *) logic [CWB-1:0] mem_q [RING];
      logic [CWB-1:0] col_rd_q;
      logic [QB-1:0]  ra;
      assign ra = QB'(wrap(32'(bpos_q[32'(rd_bank_i)*QB +: QB]) + 32'(rd_col_i[p*XB +: XB]), RING));
      always_ff @(posedge clk_i) begin
        if (wr_en) mem_q[wq] <= col_wr;
        if (rd_en_i[p]) col_rd_q <= mem_q[ra];
      end
      // The kernel writes ring columns no block in the aggregator reads: no read
      // meets the write of its column (no_rw_check: docs/blocks/fpga_target.md).
      `MCADSW_ASSERT(NoReadOfColumnWritten, !(wr_en && rd_en_i[p] && wq == ra))
      assign rd_data_o[p*CWB +: CWB] = col_rd_q;
    end
  end else begin : g_asic_buf
    logic [CSUB*CWB-1:0] csub_rd;
    for (genvar b = 0; b < CSUB; b++) begin : g_csub
      logic [CWB-1:0] mem_q [CDEPTH];
      always_ff @(posedge clk_i) begin
        if (wr_en && wq[CSB-1:0] == CSB'(b)) mem_q[$clog2(CDEPTH)'(wq[QB-1:CSB])] <= col_wr;
      end
      // The lane of ring columns rq .. rq + CSUB - 1 that lives in this sub-bank.
      // Its word: that of rq, or the next one when b is below rq's sub-bank.
      localparam int CWW = $clog2(CDEPTH + 1);
      logic [CWW-1:0] pw;
      logic [CSB:0]   bd;                  // b - (rq mod CSUB); bit CSB: the borrow, b below it
      logic [CSB-1:0] bd_unused;
      assign bd = (CSB + 1)'(b) - {1'b0, rq[CSB-1:0]};
      assign bd_unused = bd[CSB-1:0];
      assign pw = CWW'(rq[QB-1:CSB]) + CWW'(bd[CSB]);
      always_ff @(posedge clk_i) begin
        if (rd_en_i[0])
          csub_rd[b*CWB +: CWB] <= mem_q[$clog2(CDEPTH)'(pw >= CWW'(CDEPTH) ? pw - CWW'(CDEPTH) : pw)];
      end
    end

    // The lanes (lsel_q, rd_row_q above): each takes the word its one-hot select
    // names, as a parallel case over the sub-bank words padded to 16 (synthesis makes
    // the same AND-OR multiplexer; a simulator stops at the selected word instead of
    // masking all CSUB wide words).
    if (CSUB > 16) begin : g_bad_csub
      mcadsw_error_census_csub_above_16 u_error ();
    end
    logic [16*CWB-1:0] word;
    assign word = (16*CWB)'(csub_rd);
    for (genvar l = 0; l < RL; l++) begin : g_lane
      logic [CWB-1:0] col;
      logic [15:0]    sel;
      assign sel = 16'(lsel_q[l*CSUB +: CSUB]);
      // always @* rather than always_comb: Icarus Verilog 11 rejects constant selects
      // of a generate scope's signals in always_comb.
      always @* begin
        col = '0;
        (* parallel_case *)
        case (1'b1)
          sel[0]:  col = word[0*CWB +: CWB];
          sel[1]:  col = word[1*CWB +: CWB];
          sel[2]:  col = word[2*CWB +: CWB];
          sel[3]:  col = word[3*CWB +: CWB];
          sel[4]:  col = word[4*CWB +: CWB];
          sel[5]:  col = word[5*CWB +: CWB];
          sel[6]:  col = word[6*CWB +: CWB];
          sel[7]:  col = word[7*CWB +: CWB];
          sel[8]:  col = word[8*CWB +: CWB];
          sel[9]:  col = word[9*CWB +: CWB];
          sel[10]: col = word[10*CWB +: CWB];
          sel[11]: col = word[11*CWB +: CWB];
          sel[12]: col = word[12*CWB +: CWB];
          sel[13]: col = word[13*CWB +: CWB];
          sel[14]: col = word[14*CWB +: CWB];
          sel[15]: col = word[15*CWB +: CWB];
          default: col = '0;
        endcase
      end
      assign rd_data_o[l*WINDOW*CB +: WINDOW*CB] = (WINDOW*CB)'(col >> (32'(rd_row_q)*CB));
    end
  end

  // The kernel never reads a ring strip the stream has overwritten: the
  // strips it needs, lk/4 .. (lk+4)/4, are the last LS written at most.
  `MCADSW_ASSERT(LumaStripStillInRing, !(issue && need_luma && 32'(lk[KB-1:2]) + LS < 32'(wcnt_q)))

endmodule

`default_nettype wire
