// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Post stage, phase CD of a row (docs/algorithm.md 12.4-12.5, docs/blocks/post.md,
// phase CD): from right to left, a pixel a cycle, a five-stage pipeline
//   1  read column x of vrow (the row's check and forward fill, from RD) and of
//      the two median row buffers
//   2  the fill from the right (the filled value of row y replaces row y - 2 in
//      its median row buffer), the mask byte of row y
//   3  sort the column {row r - 1, row r, row r + 1}, shift it into the window
//   4  the 3x3 median of row r = y - 1 (edges replicated)
//   5  the output word
// Mask and output words go to the stage's write queue (mask_push_o,
// out_push_o; both may come in the same cycle, the mask word first).
//
// A pass: start_i with fill_i (fill row y, row_i; 0: the last pass, only the
// median of row H - 1) and medians_i (write the medians: not in row 0's pass);
// the pass issues a column each cycle with issue_en_i (the queue has room for
// what the columns in flight may push) and is over when done_o.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_post_fill #(
  parameter int MAXW = mcadsw_pkg::POST_MAX_WIDTH,
  parameter int DB   = mcadsw_pkg::DISP_BITS,
  parameter int VB   = DB + 4,                  // value: d, or 16 d + offset
  parameter int CW   = 12,
  parameter int QE   = 1 + CW + 4 + 32          // write queue entry: {out plane, word, be, data}
) (
  input  logic           clk_i,
  input  logic           rst_ni,
  // Frame (registered by the stage at its start)
  input  logic [CW-1:0]  width_i,
  input  logic           wide_i,                // output a halfword a pixel (16 d + offset)
  input  logic [CW-1:0]  row_i,                 // y
  // A pass
  input  logic           start_i,
  input  logic           fill_i,
  input  logic           medians_i,
  input  logic           issue_en_i,            // the stage is in CD and the queue has room
  output logic           fill_o,                // the pass fills (0: the last pass)
  output logic           done_o,                // every column issued and out of the pipeline
  // vrow read port (synchronous: data in the next cycle)
  output logic           vrow_re_o,
  output logic [$clog2(MAXW)-1:0] vrow_x_o,
  input  logic [VB+1:0]  vrow_data_i,
  // Words for the write queue: {1'b0 mask / 1'b1 output, word index, byte enables, data}
  output logic           mask_push_o,
  output logic [QE-1:0]  mask_entry_o,
  output logic           out_push_o,
  output logic [QE-1:0]  out_entry_o
);

  localparam int XI = $clog2(MAXW);

  // ---- Median row buffers: filled rows, by row parity (synchronous read) ---------------
  logic [VB-1:0] med0 [MAXW], med1 [MAXW];

  // ---- Pass state -----------------------------------------------------------------------
  logic          fill_q;                       // fill row y (0: the last pass)
  logic          medians_q;                    // write medians (not in row 0's pass)
  logic          up_odd_q, mid_odd_q;          // median row buffers of rows r - 1 and r
  logic [CW-1:0] col_q;                        // next column to read
  logic          flush_q, issued_q;            // the flush step is next / was issued
  logic          issue;
  assign issue  = issue_en_i && !issued_q;
  assign fill_o = fill_q;
  assign vrow_re_o = issue && !flush_q;
  assign vrow_x_o  = XI'(col_q);

  // ---- Stage 2: the filled value, the mask byte -------------------------------------------
  logic          s2_valid_q, s2_flush_q;
  logic [CW-1:0] s2_x_q;
  logic [VB-1:0] med0_q, med1_q;               // the median row buffers' read data
  logic          px_valid, px_has;
  logic [VB-1:0] px_value, filled, up_value, mid_value;
  logic          right_seen_q;                 // a valid pixel seen to the right
  logic [VB-1:0] right_q;                      // the nearest one's value
  assign {px_valid, px_has, px_value} = vrow_data_i;
  assign filled = px_valid ? px_value :
                  !px_has ? (right_seen_q ? right_q : '0) :
                  !right_seen_q ? px_value :
                  (px_value < right_q) ? px_value : right_q;
  assign up_value  = up_odd_q ? med1_q : med0_q;
  assign mid_value = mid_odd_q ? med1_q : med0_q;
  logic          fill_we;                      // stage 2 writes the filled value
  assign fill_we = s2_valid_q && !s2_flush_q && fill_q;
  logic [7:0]    mask_byte;
  logic [31:0]   mask_word_q;                  // the mask word so far (bytes 3..1)
  logic [3:0]    mask_be_q;
  assign mask_byte    = px_valid ? 8'hff : 8'h00;
  assign mask_push_o  = fill_we && s2_x_q[1:0] == 2'b00;
  assign mask_entry_o = {1'b0, s2_x_q >> 2, mask_be_q | 4'b0001, mask_word_q | {24'h0, mask_byte}};

  // ---- Stages 3 and 4: the column, the 3x3 window, its median ------------------------------
  logic          s3_valid_q, s3_flush_q, s3_first_q;
  logic [CW-1:0] s3_x_q, s4_x_q, s5_x_q;
  logic [3*VB-1:0] s3_col_q;                   // {up, mid, down} of column s3_x_q
  logic [3*VB-1:0] win0_q, win1_q, win2_q;     // sorted columns x, x + 1, x + 2
  logic          s4_valid_q, s5_valid_q;
  logic [VB-1:0] s5_median_q;

  // Median of nine from three sorted columns: the median of the largest minimum,
  // the median of the medians and the smallest maximum.
  function automatic logic [3*VB-1:0] sort3(input logic [3*VB-1:0] col);
    logic [VB-1:0] a, b, c, t;
    {a, b, c} = col;
    if (a > b) begin t = a; a = b; b = t; end
    if (b > c) begin t = b; b = c; c = t; end
    if (a > b) begin t = a; a = b; b = t; end
    sort3 = {a, b, c};                         // a <= b <= c
  endfunction
  function automatic logic [VB-1:0] med3(input logic [VB-1:0] a, input logic [VB-1:0] b,
                                         input logic [VB-1:0] c);
    logic [VB-1:0] lo, hi;
    lo = (a < b) ? a : b;
    hi = (a < b) ? b : a;
    hi = (hi < c) ? hi : c;
    med3 = (lo > hi) ? lo : hi;
  endfunction
  // The three values whose median is the median of nine: {lo, a, hi}.
  function automatic logic [3*VB-1:0] median9_parts(input logic [3*VB-1:0] s0, input logic [3*VB-1:0] s1,
                                                    input logic [3*VB-1:0] s2);
    logic [VB-1:0] lo, hi, a;
    lo = s0[2*VB +: VB];
    if (s1[2*VB +: VB] > lo) lo = s1[2*VB +: VB];
    if (s2[2*VB +: VB] > lo) lo = s2[2*VB +: VB];
    hi = s0[0 +: VB];
    if (s1[0 +: VB] < hi) hi = s1[0 +: VB];
    if (s2[0 +: VB] < hi) hi = s2[0 +: VB];
    a = med3(s0[VB +: VB], s1[VB +: VB], s2[VB +: VB]);
    median9_parts = {lo, a, hi};
  endfunction
  function automatic logic [VB-1:0] med3_of(input logic [3*VB-1:0] parts);
    med3_of = med3(parts[2*VB +: VB], parts[VB +: VB], parts[0 +: VB]);
  endfunction

  // Stage 4's median into stage 5, in one cycle on both targets (the FPGA target's
  // median in two cycles made the design harder to route: docs/blocks/fpga_target.md,
  // Timing).
  logic          s5_go;                        // a median enters stage 5
  logic [VB-1:0] s5_median;
  logic [CW-1:0] s5_x;
  logic          s4b_busy;                     // a median between two cycles: none
  if (mcadsw_pkg::FPGA != 0) begin : g_median_fpga
    assign s5_go     = s4_valid_q;
    assign s5_median = med3_of(median9_parts(win0_q, win1_q, win2_q));
    assign s5_x      = s4_x_q;
    assign s4b_busy  = 1'b0;
  end else begin : g_median_one
    assign s5_go     = s4_valid_q;
    assign s5_median = med3_of(median9_parts(win0_q, win1_q, win2_q));
    assign s5_x      = s4_x_q;
    assign s4b_busy  = 1'b0;
  end

  // ---- Stage 5: the output word --------------------------------------------------------------
  logic [31:0] out_word_q, out_data;           // the output word so far / with this pixel
  logic [3:0]  out_be_q, out_be;
  logic        out_low;                        // the pixel is the lowest of its word
  // Byte b of the word: this pixel's (8-bit: byte x % 4; wide: bytes 2 (x % 2) and
  // 2 (x % 2) + 1), or the word's so far.
  for (genvar b = 0; b < 4; b++) begin : g_obyte
    logic mine;
    assign mine = wide_i ? s5_x_q[0] == 1'(b / 2) : s5_x_q[1:0] == 2'(b);
    assign out_data[8*b +: 8] = !mine ? out_word_q[8*b +: 8] :
                                (wide_i && b % 2 == 1) ? 8'(16'(s5_median_q) >> 8) : 8'(s5_median_q);
    assign out_be[b] = mine || out_be_q[b];
  end
  assign out_low     = wide_i ? !s5_x_q[0] : s5_x_q[1:0] == 2'b00;
  assign out_push_o  = s5_valid_q && medians_q && out_low;
  assign out_entry_o = {1'b1, wide_i ? s5_x_q >> 1 : s5_x_q >> 2, out_be, out_data};

  assign done_o = issued_q && !s2_valid_q && !s3_valid_q && !s4_valid_q && !s4b_busy && !s5_valid_q;

  // ---- Buffer ports ------------------------------------------------------------------------
  always_ff @(posedge clk_i) begin
    if (fill_we && !row_i[0]) med0[XI'(s2_x_q)] <= filled;
    if (vrow_re_o) med0_q <= med0[XI'(col_q)];
  end
  always_ff @(posedge clk_i) begin
    if (fill_we && row_i[0]) med1[XI'(s2_x_q)] <= filled;
    if (vrow_re_o) med1_q <= med1[XI'(col_q)];
  end

  // ---- Data: no reset (used only under the valid bits) -----------------------------------------
  always_ff @(posedge clk_i) begin
    if (issue) s2_x_q <= col_q;
    if (fill_we && px_valid) right_q <= px_value;
    if (s2_valid_q) begin
      s3_x_q   <= s2_x_q;
      s3_col_q <= {up_value, mid_value, fill_q ? filled : mid_value};
    end
    if (s3_valid_q) begin
      if (s3_flush_q) begin
        win1_q <= win0_q;
        win2_q <= win1_q;
        s4_x_q <= '0;
      end else begin
        win0_q <= sort3(s3_col_q);
        win1_q <= s3_first_q ? sort3(s3_col_q) : win0_q;
        win2_q <= win1_q;
        s4_x_q <= s3_x_q + CW'(1);
      end
    end
    if (s5_go) begin
      s5_median_q <= s5_median;
      s5_x_q      <= s5_x;
    end
  end

  // ---- Control -----------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      fill_q       <= 1'b0;
      medians_q    <= 1'b0;
      up_odd_q     <= 1'b0;
      mid_odd_q    <= 1'b0;
      col_q        <= '0;
      flush_q      <= 1'b0;
      issued_q     <= 1'b0;
      s2_valid_q   <= 1'b0;
      s2_flush_q   <= 1'b0;
      s3_valid_q   <= 1'b0;
      s3_flush_q   <= 1'b0;
      s3_first_q   <= 1'b0;
      s4_valid_q   <= 1'b0;
      s5_valid_q   <= 1'b0;
      right_seen_q <= 1'b0;
      mask_word_q  <= '0;
      mask_be_q    <= '0;
      out_word_q   <= '0;
      out_be_q     <= '0;
    end else begin
      // Stage 1: read column col_q, or the flush step after column 0.
      s2_valid_q <= issue;
      if (issue) begin
        s2_flush_q <= flush_q;
        if (flush_q) issued_q <= 1'b1;
        else if (col_q == '0) flush_q <= 1'b1;
        else col_q <= col_q - CW'(1);
      end
      // Stage 2: the fill from the right, the mask word.
      s3_valid_q <= s2_valid_q;
      if (s2_valid_q) begin
        s3_flush_q <= s2_flush_q;
        s3_first_q <= s2_x_q + CW'(1) == width_i;
        if (fill_we) begin
          if (px_valid) right_seen_q <= 1'b1;
          if (s2_x_q[1:0] == 2'b00) begin
            mask_word_q <= '0;
            mask_be_q   <= '0;
          end else begin
            mask_word_q[8*s2_x_q[1:0] +: 8] <= mask_byte;
            mask_be_q[s2_x_q[1:0]]          <= 1'b1;
          end
        end
      end
      // Stage 3: sort the column and shift it in (the first one twice: right edge;
      // the flush step shifts column 0 in again: left edge).
      s4_valid_q <= s3_valid_q && !(s3_first_q && !s3_flush_q);
      // Stage 4: the median; stage 5: the output word.
      s5_valid_q <= s5_go;
      if (s5_valid_q && medians_q) begin
        if (out_low) begin
          out_word_q <= '0;
          out_be_q   <= '0;
        end else begin
          out_word_q <= out_data;
          out_be_q   <= out_be;
        end
      end
      // A pass starts: rows r - 1 (clamped to 0) and r of the median, r = y - 1
      // (fill) or y (the last pass).
      if (start_i) begin
        fill_q    <= fill_i;
        medians_q <= medians_i;
        if (fill_i) begin
          mid_odd_q <= !row_i[0];
          up_odd_q  <= (row_i == CW'(1)) ? !row_i[0] : row_i[0];
        end else begin
          mid_odd_q <= row_i[0];
          up_odd_q  <= (row_i == '0) ? row_i[0] : !row_i[0];
        end
        col_q        <= width_i - CW'(1);
        flush_q      <= 1'b0;
        issued_q     <= 1'b0;
        right_seen_q <= 1'b0;
        mask_word_q  <= '0;
        mask_be_q    <= '0;
        out_word_q   <= '0;
        out_be_q     <= '0;
      end
    end
  end

  `MCADSW_ASSUME(PassStartsWhenIdle, !(start_i && (s2_valid_q || s3_valid_q || s4_valid_q || s4b_busy ||
                                                 s5_valid_q)))

endmodule

`default_nettype wire
