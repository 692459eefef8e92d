// Mini-census transformer (paper Sec. V-B, Fig. 10): input buffer, mini-census
// kernel, census buffer. Instantiated for the left view (COLS = 48) and the
// right view (COLS = 48 + DMAX - 1, the columns x - d can reach).
//
// Input: the luma of the read window, (COLS + 4) x (ROWS + 4) pixels (2 extra
// on each side for the 5x5 template), row by row, 4 pixels per 32-bit word,
// byte 0 the leftmost pixel, each row padded to whole words. The memory side
// reads at clamped coordinates, so every pixel of the window has a value.
//
// Input buffer: a 6-row line buffer; row u + 5 loads while the kernel works on
// the code row that needs luma rows u .. u + 4.
//
// Kernel: one code a cycle, only for window positions inside the image
// (cfg lo/hi bounds). Census buffer: BANKS banks of ROWS x COLS codes, so the
// next block is prepared while the cost aggregator reads the current one.
// Its read port delivers LANES columns x WINDOW rows a cycle (Fig. 12) and
// clamps every row and column index to the in-image bounds of the bank: this
// is the border rule of docs/algorithm.md (a position outside the image reads
// the code of the nearest edge pixel).
`default_nettype none

module mcadsw_census #(
  parameter int COLS   = mcadsw_pkg::BLOCK_COLS,   // census positions per row
  parameter int ROWS   = mcadsw_pkg::BLOCK_COLS,   // census rows (18 + 30)
  parameter int LANES  = mcadsw_pkg::LANES,
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int CB     = mcadsw_pkg::CENSUS_BITS,
  parameter int BANKS  = 2,
  parameter int XB     = $clog2(COLS),             // column index width
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

  localparam int LCOLS = COLS + 4;             // luma columns of the window
  localparam int LROWS = ROWS + 4;
  localparam int WPR   = (LCOLS + 3) / 4;      // words per luma row
  localparam int LW    = WPR * 4;              // bytes per line-buffer row
  localparam int SLOTS = 6;
  localparam int UB    = $clog2(LROWS + 1);    // luma row counter width
  localparam int WB    = $clog2(WPR + 1);

  if (ROWS < WINDOW || COLS < LANES || CB != 6) begin : g_bad_param
    mcadsw_error_census_geometry u_error ();
  end

  // ---- Configuration ---------------------------------------------------------
  logic          busy_q;
  logic [BB-1:0] bank_q;
  logic [XB-1:0] lo_x_q, hi_x_q;
  logic [YB-1:0] hi_y_q;
  logic [BANKS*XB-1:0] blo_x_q, bhi_x_q;  // bounds of each bank, for the read port
  logic [BANKS*YB-1:0] blo_y_q, bhi_y_q;

  assign cfg_ready_o = !busy_q;
  assign busy_o      = busy_q;

  // ---- Input buffer ------------------------------------------------------------
  logic [SLOTS*LW*8-1:0] lbuf_q;
  logic [UB-1:0]         in_row_q;    // luma row being loaded
  logic [WB-1:0]         in_word_q;
  logic [YB:0]           kc_q;        // code row the kernel works on
  logic [XB-1:0]         ki_q;        // code column
  logic                  k_done_q;    // every code row written
  logic                  in_done;
  logic                  pix_fire;

  assign in_done     = in_row_q == UB'(LROWS);
  // Row u may load once the kernel no longer needs row u - 6 (slot reuse).
  assign pix_ready_o = busy_q && !in_done &&
                       (k_done_q || 32'(in_row_q) <= 32'(kc_q) + 5);
  assign pix_fire    = pix_valid_i && pix_ready_o;

  // ---- Kernel (Fig. 2 template, bit order of docs/algorithm.md) ---------------
  logic k_go;
  assign k_go = busy_q && !k_done_q && 32'(in_row_q) > 32'(kc_q) + 4;

  function automatic logic [7:0] luma(input logic [SLOTS*LW*8-1:0] buf_v,
                                      input int row, input int col);
    luma = buf_v[((row % SLOTS)*LW + col)*8 +: 8];
  endfunction

  logic [CB-1:0] code;
  always_comb begin
    logic [7:0] centre;
    int r, c;
    r = 32'(kc_q) + 2;
    c = 32'(ki_q) + 2;
    centre = luma(lbuf_q, r, c);
    code[5] = luma(lbuf_q, r + mcadsw_pkg::TAP0_DY, c + mcadsw_pkg::TAP0_DX) <= centre;
    code[4] = luma(lbuf_q, r + mcadsw_pkg::TAP1_DY, c + mcadsw_pkg::TAP1_DX) <= centre;
    code[3] = luma(lbuf_q, r + mcadsw_pkg::TAP2_DY, c + mcadsw_pkg::TAP2_DX) <= centre;
    code[2] = luma(lbuf_q, r + mcadsw_pkg::TAP3_DY, c + mcadsw_pkg::TAP3_DX) <= centre;
    code[1] = luma(lbuf_q, r + mcadsw_pkg::TAP4_DY, c + mcadsw_pkg::TAP4_DX) <= centre;
    code[0] = luma(lbuf_q, r + mcadsw_pkg::TAP5_DY, c + mcadsw_pkg::TAP5_DX) <= centre;
  end

  // ---- Census buffer ------------------------------------------------------------
  logic [BANKS*ROWS*COLS*CB-1:0] cbuf_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q    <= 1'b0;
      bank_q    <= '0;
      lo_x_q    <= '0;
      hi_x_q    <= '0;
      hi_y_q    <= '0;
      blo_x_q   <= '0;
      bhi_x_q   <= '0;
      blo_y_q   <= '0;
      bhi_y_q   <= '0;
      in_row_q  <= '0;
      in_word_q <= '0;
      kc_q      <= '0;
      ki_q      <= '0;
      k_done_q  <= 1'b0;
      done_o    <= 1'b0;
    end else begin
      done_o <= 1'b0;
      if (cfg_valid_i && cfg_ready_o) begin
        busy_q    <= 1'b1;
        bank_q    <= cfg_bank_i;
        lo_x_q    <= cfg_lo_x_i;
        hi_x_q    <= cfg_hi_x_i;
        hi_y_q    <= cfg_hi_y_i;
        blo_x_q[32'(cfg_bank_i)*XB +: XB] <= cfg_lo_x_i;
        bhi_x_q[32'(cfg_bank_i)*XB +: XB] <= cfg_hi_x_i;
        blo_y_q[32'(cfg_bank_i)*YB +: YB] <= cfg_lo_y_i;
        bhi_y_q[32'(cfg_bank_i)*YB +: YB] <= cfg_hi_y_i;
        in_row_q  <= '0;
        in_word_q <= '0;
        kc_q      <= {1'b0, cfg_lo_y_i};
        ki_q      <= cfg_lo_x_i;
        k_done_q  <= 1'b0;
      end else if (busy_q) begin
        if (pix_fire) begin
          if (in_word_q == WB'(WPR - 1)) begin
            in_word_q <= '0;
            in_row_q  <= in_row_q + UB'(1);
          end else begin
            in_word_q <= in_word_q + WB'(1);
          end
        end
        if (k_go) begin
          if (ki_q == hi_x_q) begin
            ki_q <= lo_x_q;
            kc_q <= kc_q + (YB + 1)'(1);
            if (kc_q == {1'b0, hi_y_q}) k_done_q <= 1'b1;
          end else begin
            ki_q <= ki_q + XB'(1);
          end
        end
        if (k_done_q && in_done) begin
          busy_q <= 1'b0;
          done_o <= 1'b1;
        end
      end
    end
  end

  // Line buffer and census buffer are RAMs: written, never reset (a read of a
  // position before it is written is prevented by the bank handshake).
  always_ff @(posedge clk_i) begin
    if (pix_fire) lbuf_q[((32'(in_row_q) % SLOTS)*LW + 32'(in_word_q)*4)*8 +: 32] <= pix_data_i;
    if (k_go) cbuf_q[((32'(bank_q)*ROWS + 32'(kc_q))*COLS + 32'(ki_q))*CB +: CB] <= code;
  end

  // ---- Read port: LANES x WINDOW codes, indices clamped to the bank's bounds ---
  logic [LANES*WINDOW*CB-1:0] rd_d;
  logic [XB-1:0] rlo_x, rhi_x;
  logic [YB-1:0] rlo_y, rhi_y;
  assign rlo_x = blo_x_q[32'(rd_bank_i)*XB +: XB];
  assign rhi_x = bhi_x_q[32'(rd_bank_i)*XB +: XB];
  assign rlo_y = blo_y_q[32'(rd_bank_i)*YB +: YB];
  assign rhi_y = bhi_y_q[32'(rd_bank_i)*YB +: YB];

  for (genvar l = 0; l < LANES; l++) begin : g_lane
    logic [XB:0] col_raw;
    logic [XB-1:0] col;
    assign col_raw = {1'b0, rd_col_i} + (XB + 1)'(l);
    assign col = (col_raw < {1'b0, rlo_x}) ? rlo_x :
                 (col_raw > {1'b0, rhi_x}) ? rhi_x : col_raw[XB-1:0];
    for (genvar k = 0; k < WINDOW; k++) begin : g_row
      logic [YB:0] row_raw;
      logic [YB-1:0] row;
      assign row_raw = {1'b0, rd_row_i} + (YB + 1)'(k);
      assign row = (row_raw < {1'b0, rlo_y}) ? rlo_y :
                   (row_raw > {1'b0, rhi_y}) ? rhi_y : row_raw[YB-1:0];
      assign rd_d[(l*WINDOW + k)*CB +: CB] =
          cbuf_q[((32'(rd_bank_i)*ROWS + 32'(row))*COLS + 32'(col))*CB +: CB];
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) rd_data_o <= '0;
    else if (rd_en_i) rd_data_o <= rd_d;
  end

endmodule

`default_nettype wire
