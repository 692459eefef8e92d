// Weight generator (paper Sec. V-C, Fig. 11): three input buffers (Y, U, V of
// the left view), a kernel of WINDOW Manhattan colour-distance units and
// weight-table lookups, and the vertical and horizontal weight buffers.
//
// Input: the colour of the ROWS x COLS read window (48 x 48), plane by plane
// (Y, then U, then V), in strips of 4 columns: for strip s, rows 0 .. ROWS-1 of
// columns 4s .. 4s+3, one 32-bit word a row, byte 0 the leftmost column. The
// strips start at the aligned memory word left of the window, cfg_ofs_i
// (0..3) columns early, so each strip word is one memory read: COLS/4 + 1
// strips a plane. The input buffers are circular over those strips, as the
// census transformer's (partial column reuse, Sec. IV): cfg_first_i > 0 means
// the window continues the previous block's 18 columns to the right, the
// buffers advance by WPR - cfg_first_i strips and only strips cfg_first_i ..
// WPR-1 of each plane are delivered.
// The memory side reads at clamped coordinates, so the weights of positions
// outside the image are those of the nearest edge pixel (docs/algorithm.md).
//
// Kernel, after the window is loaded, one step a cycle, row by row (centre
// row r = 0..BLOCK-1), as the cost aggregator consumes the weights:
//   vertical:   column c (0..COLS-1) of row r: the WINDOW weights of pixels
//               (c, r+k) against the column centre (c, r+R);
//   horizontal: output pixel x (0..BLOCK-1) of row r: the WINDOW weights of
//               column centres (x+j, r+R) against the window centre (x+R, r+R).
// BLOCK*(COLS + BLOCK) = 1188 cycles a block (paper: 1536). The kernel is
// two stages: the window of WINDOW pixels is selected and registered, the next
// cycle its distances and codes are written (the input-buffer read and the
// distance arithmetic in one cycle missed 95 MHz, docs/architecture.md
// section 10); done_o follows the last write.
//
// Weight table: the 7 colour distances at which the 3-bit weight code drops
// (code = 7 - number of thresholds <= dC), loaded at run time and converted
// from the reference's table by weight_thresholds(), so both sides use the
// same values. Weight buffers: BANKS banks, so the next block is generated
// while the cost aggregator reads the current one.
`default_nettype none

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
  parameter int BANKS  = 2,
  parameter int WPR    = COLS / 4 + 1,              // strips a plane (offset 0..3)
  parameter int SB     = $clog2(WPR),
  parameter int XB     = $clog2(COLS),
  parameter int RB     = $clog2(BLOCK),
  parameter int BB     = (BANKS > 1) ? $clog2(BANKS) : 1
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,
  input  logic [NTHR*DCB-1:0]        thr_i,        // stable while busy_o
  input  logic                       cfg_valid_i,
  output logic                       cfg_ready_o,
  input  logic [BB-1:0]              cfg_bank_i,
  input  logic [1:0]                 cfg_ofs_i,    // window column 0 is input column cfg_ofs_i
  input  logic [SB-1:0]              cfg_first_i,  // first strip delivered (0: whole window)
  input  logic                       pix_valid_i,
  output logic                       pix_ready_o,
  input  logic [31:0]                pix_data_i,
  output logic                       done_o,
  output logic                       busy_o,
  // Vertical weight buffer read: LANES columns from vrd_col_i, centre row vrd_row_i
  input  logic                       vrd_en_i,
  input  logic [BB-1:0]              vrd_bank_i,
  input  logic [RB-1:0]              vrd_row_i,
  input  logic [XB-1:0]              vrd_col_i,
  output logic [LANES*WINDOW*WB-1:0] wv_o,          // lane l, tap k at (l*WINDOW + k)*WB
  // Horizontal weight buffer read: HAGG output pixels from hrd_col_i
  input  logic                       hrd_en_i,
  input  logic [BB-1:0]              hrd_bank_i,
  input  logic [RB-1:0]              hrd_row_i,
  input  logic [RB-1:0]              hrd_col_i,
  output logic [HAGG*WINDOW*WB-1:0]  wh_o           // pixel m, tap j at (m*WINDOW + j)*WB
);

  localparam int RADIUS = WINDOW / 2;
  localparam int ENTRY  = WINDOW * WB;              // one weight-buffer entry

  if (COLS % 4 != 0 || WPR * 4 < COLS + 3 || ROWS != BLOCK + WINDOW - 1 || COLS != BLOCK + WINDOW - 1 ||
      NTHR != (1 << WB) - 1) begin : g_bad_param
    mcadsw_error_weight_gen_geometry u_error ();
  end

  // v mod n for 0 <= v < 2n.
  function automatic int wrap(input int v, input int n);
    wrap = (v >= n) ? v - n : v;
  endfunction

  // ---- Control ------------------------------------------------------------------
  typedef enum logic [1:0] {IDLE, LOAD, VERT, HORZ} state_e;
  state_e        state_q;
  logic [BB-1:0] bank_q;
  logic [1:0]    ofs_q;
  logic [SB-1:0] base_q;       // buffer strip of window strip 0
  logic [RB-1:0] r_q;
  logic [XB-1:0] c_q;          // column (vertical) or output pixel (horizontal)
  logic          pix_fire;

  logic          k_vert_q, k_horz_q;   // the kernel's second stage writes a vertical / horizontal entry
  logic          k_last_q;             // ... the block's last one
  assign cfg_ready_o = state_q == IDLE;
  assign busy_o      = state_q != IDLE || k_vert_q || k_horz_q;
  assign pix_ready_o = state_q == LOAD;
  assign pix_fire    = pix_valid_i && pix_ready_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= IDLE;
      bank_q  <= '0;
      ofs_q   <= '0;
      base_q  <= '0;
      r_q     <= '0;
      c_q     <= '0;
      k_last_q <= 1'b0;
      done_o  <= 1'b0;
    end else begin
      k_last_q <= 1'b0;
      done_o   <= k_last_q;
      case (state_q)
        IDLE: if (cfg_valid_i) begin
          state_q <= LOAD;
          bank_q  <= cfg_bank_i;
          ofs_q   <= cfg_ofs_i;
          base_q  <= SB'(wrap(32'(base_q) + WPR - 32'(cfg_first_i), WPR));
        end
        LOAD: if (win_done) begin
          state_q <= VERT;
          r_q     <= '0;
          c_q     <= '0;
        end
        VERT: begin  // the COLS columns of row r
          if (c_q == XB'(COLS - 1)) begin
            c_q     <= '0;
            state_q <= HORZ;
          end else begin
            c_q <= c_q + XB'(1);
          end
        end
        HORZ: begin  // the BLOCK output pixels of row r, then the next row
          if (c_q == XB'(BLOCK - 1)) begin
            c_q <= '0;
            if (r_q == RB'(BLOCK - 1)) begin
              state_q  <= IDLE;
              k_last_q <= 1'b1;
            end else begin
              state_q <= VERT;
              r_q     <= r_q + RB'(1);
            end
          end else begin
            c_q <= c_q + XB'(1);
          end
        end
        default: state_q <= IDLE;
      endcase
    end
  end

  // ---- Input buffers: Y, U, V, each 4 banks of column words ----------------------
  // Column c is word c/4 of bank c%4 and holds the ROWS pixels of the column, so
  // an input word (4 pixels of a row) writes one byte into each bank, and the
  // kernel reads a whole column at once ("column by column", Fig. 11).
  localparam int CW = ROWS * 8;             // column word
  logic [1:0]       in_plane;
  logic [SB-1:0]    in_strip;               // columns 4s .. 4s+3
  logic             strip_end, win_done;    // last row of a strip / of the window
  logic [4*CW-1:0]  strip_cols;             // the 4 column words of that strip

  mcadsw_strip_stage #(.ROWS(ROWS), .STRIPS(WPR), .PLANES(3)) u_stage (
    .clk_i, .rst_ni,
    .start_i (cfg_valid_i && cfg_ready_o),
    .first_i (cfg_first_i),
    .wr_i    (pix_fire),
    .data_i  (pix_data_i),
    .last_o  (strip_end),
    .done_o  (win_done),
    .plane_o (in_plane),
    .strip_o (in_strip),
    .cols_o  (strip_cols)
  );


  logic [3*CW-1:0]   column;                // Y, U, V of the column the kernel reads
  logic [4*CW-1:0]   y_rd, u_rd, v_rd;      // the word each bank presents
  logic [XB:0]       in_col;                // its buffer column: 4 base + offset + window column c
  logic [SB-1:0]     wstrip;                // buffer strip of the finished input strip
  assign in_col = (XB + 1)'(wrap(4*32'(base_q) + 32'(ofs_q) + 32'(c_q), 4*WPR));
  assign wstrip = SB'(wrap(32'(base_q) + 32'(in_strip), WPR));

  for (genvar b = 0; b < 4; b++) begin : g_ibank
    logic [CW-1:0] wr_col;                  // column 4s + b
    assign wr_col = strip_cols[b*CW +: CW];

    logic [CW-1:0] y_q [WPR];
    logic [CW-1:0] u_q [WPR];
    logic [CW-1:0] v_q [WPR];
    always_ff @(posedge clk_i) begin
      if (strip_end && in_plane == 2'd0) y_q[wstrip] <= wr_col;
      if (strip_end && in_plane == 2'd1) u_q[wstrip] <= wr_col;
      if (strip_end && in_plane == 2'd2) v_q[wstrip] <= wr_col;
    end
    assign y_rd[b*CW +: CW] = y_q[SB'(in_col[XB:2])];
    assign u_rd[b*CW +: CW] = u_q[SB'(in_col[XB:2])];
    assign v_rd[b*CW +: CW] = v_q[SB'(in_col[XB:2])];
  end
  function automatic logic [CW-1:0] bank_word(input logic [4*CW-1:0] w, input logic [1:0] b);
    bank_word = '0;
    for (int i = 0; i < 4; i++) bank_word = bank_word | (w[i*CW +: CW] & {CW{b == 2'(i)}});
  endfunction
  assign column = {bank_word(v_rd, in_col[1:0]), bank_word(u_rd, in_col[1:0]),
                   bank_word(y_rd, in_col[1:0])};

  // ---- Horizontal row buffer (Fig. 11): the centre row of the current row ---------
  // Written during row r's vertical pass (pixel r + RADIUS of column c at
  // position c), read during its horizontal pass: no second read of the input
  // buffer. One row (COLS pixels) in flip-flops: the horizontal pass takes a
  // WINDOW-pixel slice of it each cycle, and the next row's vertical pass
  // overwrites it only after the last slice was taken (stage 1, below).
  localparam int PW = 24;                   // Y, U, V of one pixel
  logic [COLS*PW-1:0] hrow_q;

  function automatic logic [DCB-1:0] absdiff(input logic [7:0] a, input logic [7:0] b);
    logic [7:0] d;
    d = (a > b) ? a - b : b - a;
    absdiff = {{(DCB - 8){1'b0}}, d};
  endfunction

  function automatic logic [DCB-1:0] cdist(input logic [PW-1:0] a, input logic [PW-1:0] b);
    cdist = absdiff(a[7:0], b[7:0]) + absdiff(a[15:8], b[15:8]) + absdiff(a[23:16], b[23:16]);
  endfunction

  // ---- Kernel: WINDOW colour distances and table lookups ----------------------------
  // Vertical (h = 0): pixels (c, r+k) against (c, r+R) from the column word;
  // horizontal (h = 1): (c+k, r+R) against (c+R, r+R) from the row buffer. The
  // WINDOW pixels are first selected as a window (one of BLOCK offsets: an
  // AND-OR multiplexer, not a bit-granular shifter), then taken at constant
  // positions. A function called only where weights are written, so a simulator
  // evaluates it in the kernel's cycles only; the hardware is the same.
  localparam int WPW = WINDOW * PW;          // a window of pixels

  // Rows r .. r + WINDOW - 1 of the column, as pixels: each plane's window is
  // one of BLOCK row offsets, then Y, U, V are interleaved at constant positions.
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
    logic [DCB-1:0] d;
    logic [WB-1:0]  passed;   // thresholds passed
    for (int k = 0; k < WINDOW; k++) begin
      d = cdist(win[k*PW +: PW], win[RADIUS*PW +: PW]);
      passed = '0;
      for (int i = 0; i < NTHR; i++) passed = passed + WB'(d >= thr[i*DCB +: DCB]);
      weight_codes[k*WB +: WB] = WB'(NTHR) - passed;
    end
  endfunction

  // The centre pixel r + RADIUS of the column goes into the horizontal row buffer.
  function automatic logic [PW-1:0] centre_pixel(input logic [3*CW-1:0] col, input logic [RB-1:0] r);
    centre_pixel = '0;
    for (int o = 0; o < BLOCK; o++)
      centre_pixel = centre_pixel | ({col[2*CW + (o + RADIUS)*8 +: 8], col[CW + (o + RADIUS)*8 +: 8],
                                      col[(o + RADIUS)*8 +: 8]} & {PW{r == RB'(o)}});
  endfunction

  always_ff @(posedge clk_i) begin
    if (state_q == VERT) hrow_q[32'(c_q)*PW +: PW] <= centre_pixel(column, r_q);
  end

  // ---- Weight buffers: one word per aggregator read ----------------------------------
  // Vertical: word (bank, r, group of LANES columns); horizontal: word (bank, r,
  // group of HAGG pixels). The kernel writes one entry of a word a cycle.
  localparam int VGRP = COLS / LANES;
  localparam int HGRP = BLOCK / HAGG;
  logic [LANES*ENTRY-1:0] vbuf_q [BANKS*BLOCK*VGRP];
  logic [HAGG*ENTRY-1:0]  hbuf_q [BANKS*BLOCK*HGRP];

  // Stage 1: the window and where its codes go.
  logic [WPW-1:0] k_win_q;
  logic [BB-1:0]  k_bank_q;
  logic [RB-1:0]  k_r_q;
  logic [XB-1:0]  k_c_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      k_vert_q <= 1'b0;
      k_horz_q <= 1'b0;
      k_bank_q <= '0;
      k_r_q    <= '0;
      k_c_q    <= '0;
    end else begin
      k_vert_q <= state_q == VERT;
      k_horz_q <= state_q == HORZ;
      k_bank_q <= bank_q;
      k_r_q    <= r_q;
      k_c_q    <= c_q;
    end
  end

  always_ff @(posedge clk_i) begin
    if (state_q == VERT || state_q == HORZ)
      k_win_q <= state_q == HORZ ? hwindow(hrow_q, c_q) : vwindow(column, r_q);
  end

  // Stage 2: distances, codes, one weight-buffer entry.
  always_ff @(posedge clk_i) begin
    if (k_vert_q || k_horz_q) begin : p_kernel
      logic [ENTRY-1:0] codes;  // one kernel for both passes
      codes = weight_codes(k_win_q, thr_i);
      if (k_vert_q)
        vbuf_q[(32'(k_bank_q)*BLOCK + 32'(k_r_q))*VGRP + 32'(k_c_q) / LANES]
              [(32'(k_c_q) % LANES)*ENTRY +: ENTRY] <= codes;
      else
        hbuf_q[(32'(k_bank_q)*BLOCK + 32'(k_r_q))*HGRP + 32'(k_c_q) / HAGG]
              [(32'(k_c_q) % HAGG)*ENTRY +: ENTRY] <= codes;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wv_o <= '0;
      wh_o <= '0;
    end else begin
      if (vrd_en_i) wv_o <= vbuf_q[(32'(vrd_bank_i)*BLOCK + 32'(vrd_row_i))*VGRP + 32'(vrd_col_i) / LANES];
      if (hrd_en_i) wh_o <= hbuf_q[(32'(hrd_bank_i)*BLOCK + 32'(hrd_row_i))*HGRP + 32'(hrd_col_i) / HAGG];
    end
  end

endmodule

`default_nettype wire
