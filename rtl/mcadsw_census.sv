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
// coordinates, so every pixel has a value.
//
// Input buffer: 8 banks of luma column words (column p in bank p % 8), filled
// through a staging register that collects a strip and writes 4 whole columns.
// It is circular over NSTRIP strips (partial column reuse, Sec. IV): the
// window's strip s lives in buffer strip (base + s) mod NSTRIP, and a block
// that continues the previous one 18 columns to the right (cfg_first_i > 0)
// advances base by the strips its aligned origin moved (STRIPS - cfg_first_i)
// and receives only strips cfg_first_i .. STRIPS-1; the others are the
// previous block's, already in the buffer. cfg_first_i = 0 loads a whole window.
//
// Kernel: one column of ROWS codes a cycle, COLS + 1 cycles a block. Position
// (i, j) of the census buffer receives the code of the nearest in-image
// position (clamp(i, lo_x, hi_x), clamp(j, lo_y, hi_y)): the border rule of
// docs/algorithm.md, applied once, when the buffer is written.
//
// Census buffer: a ring of RING census columns (COLS + BLOCK, rounded up to a
// multiple of 8), each a column word of ROWS codes, in 8 sub-banks (ring
// column q in sub-bank q % 8), so the read port's LANES consecutive columns
// come from distinct sub-banks; it delivers LANES columns x WINDOW rows a
// cycle (Fig. 12). Each block's window starts BLOCK ring columns after the
// previous block's. Census codes depend only on the (clamped) image position,
// so a block that continues its left neighbour (cfg_first_i > 0) shares the
// neighbour's last COLS - BLOCK columns and the kernel computes only its BLOCK
// new ones (partial column reuse, Sec. IV), into ring columns the block before
// the neighbour used: the scheduler prepares a block only after that one has
// left the aggregator. A block that does not continue its neighbour (the
// first of a row band) writes all COLS columns, over the neighbour's, so its
// kernel waits until the neighbour has left the aggregator (ring_free_i).
// The read port names a block by the bank the scheduler gave it (rd_bank_i,
// two blocks in flight): the ring position of each bank's window is kept.
`default_nettype none

module mcadsw_census #(
  parameter int COLS   = mcadsw_pkg::BLOCK_COLS,   // census positions per row
  parameter int ROWS   = mcadsw_pkg::BLOCK_COLS,   // census rows (18 + 30)
  parameter int LANES  = mcadsw_pkg::LANES,
  parameter int BLOCK  = mcadsw_pkg::BLOCK,
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int CB     = mcadsw_pkg::CENSUS_BITS,
  parameter int BANKS  = 2,
  parameter int STRIPS = (COLS + 4 + 6) / 4,       // input strips (room for an offset of 3)
  parameter int SB     = $clog2(STRIPS),
  parameter int XB     = $clog2(COLS),             // column index width
  parameter int RING   = (COLS + BLOCK + 7) / 8 * 8,  // census buffer columns
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
  input  logic [SB-1:0]              cfg_first_i, // first strip delivered (0: whole window)
  input  logic                       ring_free_i, // the previous block has left the aggregator
  // Luma words of the window
  input  logic                       pix_valid_i,
  output logic                       pix_ready_o,
  input  logic [31:0]                pix_data_i,
  output logic                       done_o,      // one cycle: the bank is complete
  output logic                       busy_o,
  // Census buffer read port (cost aggregator), data one cycle after address
  input  logic                       rd_en_i,
  input  logic [BB-1:0]              rd_bank_i,
  input  logic [YB-1:0]              rd_row_i,    // first of WINDOW rows
  input  logic [XB-1:0]              rd_col_i,    // first of LANES columns
  output logic [LANES*WINDOW*CB-1:0] rd_data_o    // lane l, row k at (l*WINDOW + k)*CB
);

  localparam int SUB    = 8;                       // sub-banks (columns)
  localparam int LCOLS  = COLS + 4;                // luma columns of the window
  localparam int LROWS  = ROWS + 4;
  localparam int NSTRIP = STRIPS + STRIPS % 2;     // buffer strips: 4 NSTRIP columns, a multiple of SUB
  localparam int LDEPTH = NSTRIP * 4 / SUB;         // luma words per sub-bank
  localparam int CDEPTH = RING / SUB;              // census words per sub-bank
  localparam int LW     = LROWS * 8;               // luma column word
  localparam int CWB    = ROWS * CB;               // census column word

  if (ROWS < WINDOW || LANES != SUB || CB != 6 || STRIPS * 4 < LCOLS + 3 || COLS < BLOCK ||
      RING % SUB != 0 || RING < COLS + BLOCK) begin : g_bad_param
    mcadsw_error_census_geometry u_error ();
  end

  // v mod n for 0 <= v < 2n.
  function automatic int wrap(input int v, input int n);
    wrap = (v >= n) ? v - n : v;
  endfunction

  // ---- Control ----------------------------------------------------------------------
  typedef enum logic [2:0] {IDLE, LOAD, WAIT, KERNEL, FLUSH, FLUSH2} state_e;
  state_e        state_q;
  logic          cont_q;         // the block continues its left neighbour
  logic [QB-1:0] cpos_q;         // ring column of the block's window column 0
  logic [BANKS*QB-1:0] bpos_q;   // ... of each bank's block (read port), bank b at QB b
  logic [XB-1:0] lo_x_q, hi_x_q;
  logic [YB-1:0] lo_y_q, hi_y_q;
  logic [1:0]    ofs_q;
  logic [SB-1:0] base_q;         // buffer strip of window strip 0
  logic [XB-1:0] ki_q;           // census column the kernel writes
  logic          pix_fire;

  assign cfg_ready_o = state_q == IDLE;
  assign busy_o      = state_q != IDLE;
  assign pix_ready_o = state_q == LOAD;
  assign pix_fire    = pix_valid_i && pix_ready_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= IDLE;
      cont_q  <= 1'b0;
      cpos_q  <= '0;
      bpos_q  <= '0;
      lo_x_q  <= '0;
      hi_x_q  <= '0;
      lo_y_q  <= '0;
      hi_y_q  <= '0;
      ofs_q   <= '0;
      base_q  <= '0;
      ki_q    <= '0;
      done_o  <= 1'b0;
    end else begin
      done_o <= 1'b0;
      case (state_q)
        IDLE: if (cfg_valid_i) begin
          state_q <= LOAD;
          cont_q  <= cfg_first_i != '0;
          cpos_q  <= QB'(wrap(32'(cpos_q) + BLOCK, RING));
          bpos_q[32'(cfg_bank_i)*QB +: QB] <= QB'(wrap(32'(cpos_q) + BLOCK, RING));
          lo_x_q  <= cfg_lo_x_i;
          hi_x_q  <= cfg_hi_x_i;
          lo_y_q  <= cfg_lo_y_i;
          hi_y_q  <= cfg_hi_y_i;
          ofs_q   <= cfg_ofs_i;
          base_q  <= SB'(wrap(32'(base_q) + STRIPS - 32'(cfg_first_i), NSTRIP));
        end
        LOAD: if (win_done) begin
          // A continuing block computes only its BLOCK new columns.
          state_q <= (cont_q || ring_free_i) ? KERNEL : WAIT;
          ki_q    <= cont_q ? XB'(COLS - BLOCK) : '0;
        end
        WAIT: if (ring_free_i) state_q <= KERNEL;
        KERNEL: begin
          if (ki_q == XB'(COLS - 1)) state_q <= FLUSH;
          else ki_q <= ki_q + XB'(1);
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
  logic [SB-1:0]     in_strip;         // strip of the word being accepted
  logic              strip_end, win_done;
  logic [4*LW-1:0]   strip_cols;       // the 4 luma columns of a finished strip
  logic              in_plane_unused;

  mcadsw_strip_stage #(.ROWS(LROWS), .STRIPS(STRIPS), .PLANES(1)) u_stage (
    .clk_i, .rst_ni,
    .start_i (cfg_valid_i && cfg_ready_o),
    .first_i (cfg_first_i),
    .wr_i    (pix_fire),
    .data_i  (pix_data_i),
    .last_o  (strip_end),
    .done_o  (win_done),
    .plane_o (in_plane_unused),
    .strip_o (in_strip),
    .cols_o  (strip_cols)
  );


  // Luma input columns the kernel reads: lc .. lc + 4 (mod 4 NSTRIP), where
  // lc = 4 base + ofs + clamp(ki, lo_x, hi_x) (census position i needs window
  // luma columns i .. i+4).
  // Index arithmetic in narrow unsigned vectors: the sub-bank of a column is
  // its low 3 bits, its word the rest, wrapped by one compare-subtract (no
  // division or modulo by a constant that is not a power of two).
  localparam int LB = $clog2(4 * NSTRIP + SUB);   // luma column index, room for + 7
  logic [XB-1:0]      ic;
  logic [LB-1:0]      lc;
  logic [SUB*LW-1:0]  lsub_q;         // the word each sub-bank read (synchronous read)
  logic [SB-1:0]      wstrip;         // buffer strip of the finished input strip
  assign ic = (ki_q < lo_x_q) ? lo_x_q : (ki_q > hi_x_q) ? hi_x_q : ki_q;
  assign lc = LB'(wrap(4*32'(base_q) + 32'(ofs_q) + 32'(ic), 4*NSTRIP));
  assign wstrip = SB'(wrap(32'(base_q) + 32'(in_strip), NSTRIP));

  for (genvar b = 0; b < SUB; b++) begin : g_lsub
    // Buffer strip t holds columns 4t .. 4t+3: sub-bank b receives column
    // 4t + (b % 4) when t has the parity of b / 4.
    logic [LW-1:0] wr_col;
    assign wr_col = strip_cols[(b % 4)*LW +: LW];

    logic [LW-1:0] mem_q [LDEPTH];
    always_ff @(posedge clk_i) begin
      if (strip_end && wstrip[0] == 1'(b / 4)) mem_q[wstrip[SB-1:1]] <= wr_col;
    end
    // Read: the one of columns lc .. lc+7 that lives in this sub-bank.
    // Its word: that of lc, or the next one when b is below lc's sub-bank.
    localparam int LWB = $clog2(LDEPTH + 1);
    logic [LWB-1:0] pw;
    logic [3:0]     bd;                  // b - (lc mod 8); bit 3: the borrow, b below it
    logic [2:0]     bd_unused;
    assign bd = 4'(b) - {1'b0, lc[2:0]};
    assign bd_unused = bd[2:0];
    assign pw = LWB'(lc[LB-1:3]) + LWB'(bd[3]);
    always_ff @(posedge clk_i) begin
      if (state_q == KERNEL)
        lsub_q[b*LW +: LW] <= mem_q[$clog2(LDEPTH)'(pw >= LWB'(LDEPTH) ? pw - LWB'(LDEPTH) : pw)];
    end
  end

  // The sub-bank word of luma column p: an 8:1 multiplexer.
  function automatic logic [LW-1:0] luma_col(input logic [SUB*LW-1:0] rd, input logic [2:0] b);
    luma_col = '0;
    for (int i = 0; i < SUB; i++) luma_col = luma_col | (rd[i*LW +: LW] & {LW{b == 3'(i)}});
  endfunction

  // ---- Kernel: a column of codes (Fig. 2 template, docs/algorithm.md bit order) ---
  // Written as a function and called only where a column is written, so a
  // simulator evaluates it in the kernel's COLS cycles of a block, not in every
  // cycle; the hardware is the same combinational kernel.
  function automatic logic [CWB-1:0] census_column(input logic [SUB*LW-1:0] rd, input int lcol,
                                                   input logic [YB-1:0] lo_y,
                                                   input logic [YB-1:0] hi_y);
    logic [5*LW-1:0] lcols;           // luma columns lcol .. lcol + 4
    logic [CWB-1:0]  raw;             // codes of rows 0 .. ROWS-1, unclamped
    for (int dx = 0; dx < 5; dx++) lcols[dx*LW +: LW] = luma_col(rd, 3'(lcol + dx));
    for (int j = 0; j < ROWS; j++) begin
      logic [7:0] c;
      c = lcols[2*LW + (j + 2)*8 +: 8];
      raw[j*CB + 5] = lcols[(2 + mcadsw_pkg::TAP0_DX)*LW + (j + 2 + mcadsw_pkg::TAP0_DY)*8 +: 8] <= c;
      raw[j*CB + 4] = lcols[(2 + mcadsw_pkg::TAP1_DX)*LW + (j + 2 + mcadsw_pkg::TAP1_DY)*8 +: 8] <= c;
      raw[j*CB + 3] = lcols[(2 + mcadsw_pkg::TAP2_DX)*LW + (j + 2 + mcadsw_pkg::TAP2_DY)*8 +: 8] <= c;
      raw[j*CB + 2] = lcols[(2 + mcadsw_pkg::TAP3_DX)*LW + (j + 2 + mcadsw_pkg::TAP3_DY)*8 +: 8] <= c;
      raw[j*CB + 1] = lcols[(2 + mcadsw_pkg::TAP4_DX)*LW + (j + 2 + mcadsw_pkg::TAP4_DY)*8 +: 8] <= c;
      raw[j*CB + 0] = lcols[(2 + mcadsw_pkg::TAP5_DX)*LW + (j + 2 + mcadsw_pkg::TAP5_DY)*8 +: 8] <= c;
    end
    // Rows outside the image take the code of the edge row.
    for (int j = 0; j < ROWS; j++) begin
      if (j < 32'(lo_y)) census_column[j*CB +: CB] = raw[32'(lo_y)*CB +: CB];
      else if (j > 32'(hi_y)) census_column[j*CB +: CB] = raw[32'(hi_y)*CB +: CB];
      else census_column[j*CB +: CB] = raw[j*CB +: CB];
    end
  endfunction

  // Pipeline: cycle 1 reads the luma columns of census column ki, cycle 2
  // computes its codes into col_q, cycle 3 writes them.
  logic           rd_valid_q, col_valid_q;
  logic [XB-1:0]  rd_ki_q, col_ki_q;
  logic [2:0]     rd_lc_q;        // lc mod 8: the sub-bank of the first luma column
  logic [CWB-1:0] col_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rd_valid_q  <= 1'b0;
      rd_ki_q     <= '0;
      rd_lc_q     <= '0;
      col_valid_q <= 1'b0;
      col_ki_q    <= '0;
    end else begin
      rd_valid_q  <= state_q == KERNEL;
      rd_ki_q     <= ki_q;
      rd_lc_q     <= 3'(lc);
      col_valid_q <= rd_valid_q;
      col_ki_q    <= rd_ki_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (rd_valid_q) col_q <= census_column(lsub_q, 32'(rd_lc_q), lo_y_q, hi_y_q);
  end

  // ---- Census buffer and read port ----------------------------------------------------
  logic [QB-1:0] wq, rq;        // ring columns of the column written and of the first read
  assign wq = QB'(wrap(32'(cpos_q) + 32'(col_ki_q), RING));
  assign rq = QB'(wrap(32'(bpos_q[32'(rd_bank_i)*QB +: QB]) + 32'(rd_col_i), RING));
  logic [SUB*CWB-1:0] csub_rd;
  for (genvar b = 0; b < SUB; b++) begin : g_csub
    logic [CWB-1:0] mem_q [CDEPTH];
    always_ff @(posedge clk_i) begin
      if (col_valid_q && wq[2:0] == 3'(b)) mem_q[$clog2(CDEPTH)'(wq[QB-1:3])] <= col_q;
    end
    // The lane of ring columns rq .. rq + 7 that lives in this sub-bank.
    // Its word: that of rq, or the next one when b is below rq's sub-bank.
    localparam int CWW = $clog2(CDEPTH + 1);
    logic [CWW-1:0] pw;
    logic [3:0]     bd;                  // b - (rq mod 8); bit 3: the borrow, b below it
    logic [2:0]     bd_unused;
    assign bd = 4'(b) - {1'b0, rq[2:0]};
    assign bd_unused = bd[2:0];
    assign pw = CWW'(rq[QB-1:3]) + CWW'(bd[3]);
    always_ff @(posedge clk_i) begin
      if (rd_en_i)
        csub_rd[b*CWB +: CWB] <= mem_q[$clog2(CDEPTH)'(pw >= CWW'(CDEPTH) ? pw - CWW'(CDEPTH) : pw)];
    end
  end

  logic [YB-1:0] rd_row_q;
  logic [2:0]    rd_rot_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rd_row_q <= '0;
      rd_rot_q <= '0;
    end else if (rd_en_i) begin
      rd_row_q <= rd_row_i;
      rd_rot_q <= 3'(rq);
    end
  end

  // Lane l is ring column rq + l, from sub-bank (rq + l) % 8 (an 8:1
  // multiplexer); its WINDOW codes are rows rd_row .. rd_row + WINDOW - 1 of the
  // column word (a row shifter).
  function automatic logic [CWB-1:0] sub_word(input logic [SUB*CWB-1:0] w, input logic [2:0] b);
    sub_word = '0;
    for (int i = 0; i < SUB; i++) sub_word = sub_word | (w[i*CWB +: CWB] & {CWB{b == 3'(i)}});
  endfunction
  for (genvar l = 0; l < LANES; l++) begin : g_lane
    logic [CWB-1:0] col;
    assign col = sub_word(csub_rd, rd_rot_q + 3'(l));
    assign rd_data_o[l*WINDOW*CB +: WINDOW*CB] = (WINDOW*CB)'(col >> (32'(rd_row_q)*CB));
  end

endmodule

`default_nettype wire
