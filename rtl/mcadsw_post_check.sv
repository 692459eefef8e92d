// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Post stage, phase RD of a row (docs/algorithm.md 12.2-12.3, docs/blocks/post.md,
// phase RD): reads the row's dR words into the dR row buffer, then its dL words
// (at most FD requested and not yet used), and takes one pixel of dL a cycle:
//   the LR check  valid(x) = x >= d && |d - dR(x - d)| <= T (and dL not flagged
//                 by the rectifier's mark step: docs/algorithm.md 13.4)
//   the forward fill: the pixel's entry of the row buffer vrow holds
//   {valid, has a value, value}: its own value when valid, else the nearest valid
//   value to its left (and whether there is one).
// The stage (rtl/mcadsw_post.sv) owns the memory port, the row addresses and
// vrow; this block asks for a read (read_o) when the stage lets it (read_en_i),
// takes every read response, and writes vrow a pixel a cycle.
//
// A row: reads_start_i (the dR row's address in dr_row_i), then pixels_start_i
// and pixels_en_i while the pixels run; row_end_o in the cycle the last pixel is
// taken, its check and its vrow entry follow in the next cycle. The next row's
// reads may start before its pixels (the stage starts them during CD).
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_post_check #(
  parameter int MAXW = mcadsw_pkg::POST_MAX_WIDTH,
  parameter int DB   = mcadsw_pkg::DISP_BITS,
  parameter int VB   = DB + 4,                  // value: d, or 16 d + offset
  parameter int CW   = 12,
  parameter int AW   = 32,
  parameter int FD   = 4                        // dL words requested and not yet used
) (
  input  logic           clk_i,
  input  logic           rst_ni,
  // Frame (registered by the stage at its start)
  input  logic [CW-1:0]  width_i,
  input  logic [5:0]     tol_i,                 // T
  input  logic           wide_i,                // dL a halfword a pixel (16 d + offset)
  // Reads of a row: dR words from dr_row_i, then dL words from dl_row_i
  input  logic           reads_start_i,
  input  logic [AW-1:0]  dr_row_i,
  input  logic [AW-1:0]  dl_row_i,
  input  logic           read_en_i,             // the port is free and the stage lets reads go
  output logic           read_o,                // a read of read_addr_o now
  output logic [AW-1:0]  read_addr_o,
  input  logic           rvalid_i,
  input  logic [31:0]    rdata_i,
  // Pixels of a row
  input  logic           pixels_start_i,
  input  logic           pixels_en_i,           // the stage is in RD
  output logic           row_end_o,             // the row's last pixel is taken (one cycle)
  // vrow write port: {valid, has a value, value} of column vrow_x_o
  output logic           vrow_we_o,
  output logic [$clog2(MAXW)-1:0] vrow_x_o,
  output logic [VB+1:0]  vrow_data_o
);

  localparam int XI = $clog2(MAXW);            // pixel index (MAXW a power of 2)
  localparam int RI = XI - 2;                  // dR row word index
  localparam int FI = $clog2(FD);

  // ---- dR row buffer (synchronous read, one write port) --------------------------------
  logic [31:0] dr_row [MAXW / 4];              // 4 pixels a word

  // ---- Reads: the dR words, then the dL words within the credit --------------------------
  logic [CW:0]   dr_words, row_words;          // dR words, dR + dL words of a row
  assign dr_words  = ({1'b0, width_i} + (CW + 1)'(3)) >> 2;
  assign row_words = dr_words + (wide_i ? ({1'b0, width_i} + (CW + 1)'(1)) >> 1 : dr_words);
  logic [CW:0]   asked_q, answered_q;          // words requested, responses received
  logic [AW-1:0] addr_q;                       // the next request's address
  logic [FI:0]   credit_q;                     // dL words requested, not yet used
  logic          asking_dl;
  assign asking_dl = asked_q >= dr_words;
  assign read_o = read_en_i && asked_q < row_words && (!asking_dl || credit_q < (FI + 1)'(FD));
  assign read_addr_o = addr_q;

  // The dL words received and not yet used.
  logic          dl_push, dl_pop;
  logic [31:0]   dl_head;
  logic [FI:0]   dl_count;
  assign dl_push = rvalid_i && answered_q >= dr_words;
  mcadsw_fifo #(.W(32), .DEPTH(FD)) u_dl_words (
    .clk_i, .rst_ni,
    .push_i (dl_push), .data_i (rdata_i), .push2_i (1'b0), .data2_i (32'h0),
    .pop_i (dl_pop), .head_o (dl_head), .count_o (dl_count)
  );

  // ---- Stage 1: take a pixel of the current dL word -------------------------------------
  logic          word_valid_q;                 // word_q holds pixels still to take
  logic [31:0]   word_q;
  logic [1:0]    slot_q;                       // the pixel's byte (or halfword) in word_q
  logic [CW-1:0] x_q;                          // that pixel's column
  logic          take, word_last, row_last;
  assign take      = pixels_en_i && word_valid_q;
  assign word_last = wide_i ? slot_q[0] : slot_q == 2'd3;
  assign row_last  = x_q + CW'(1) == width_i;
  assign dl_pop    = dl_count != '0 && pixels_en_i && (!word_valid_q || (word_last && !row_last));
  assign row_end_o = take && row_last;
  logic [15:0]   half;                         // wide: the pixel's halfword
  assign half = slot_q[0] ? word_q[31:16] : word_q[15:0];
  logic [7:0]    d;                            // its d
  logic [VB-1:0] value;                        // its value
  assign d     = wide_i ? 8'(half[DB-1:0]) : word_q[8*slot_q +: 8];
  assign value = wide_i ? VB'({half[DB-1:0], 4'b0000}) + VB'(half[DB+4:DB]) - VB'(8) : VB'(d);
  logic [15-DB-5:0] half_unused;
  assign half_unused = half[15:DB+5];
  // A pixel the rectifier's mark step flagged (invalid in the left view after
  // rectification, docs/algorithm.md 13.4): bit 7 of its byte, bit 15 of its
  // halfword (d <= 127 and the scratch format leave both 0 otherwise). It fails the check.
  logic          flag;
  assign flag = wide_i ? half[15] : d[7];
  logic [CW:0]   match_x;                      // x - d
  assign match_x = {1'b0, x_q} - (CW + 1)'(d);

  // ---- Stage 2: the check against dR(x - d), the forward fill ----------------------------
  logic          s2_valid_q, s2_inside_q;      // a pixel; x - d >= 0
  logic [XI-1:0] s2_x_q;
  logic [7:0]    s2_d_q;
  logic [VB-1:0] s2_value_q;
  logic [1:0]    s2_byte_q;                    // dR(x - d)'s byte in its word
  logic [31:0]   dr_word_q;                    // dR row buffer read data
  logic          seen_q;                       // a valid pixel seen in this row
  logic [VB-1:0] last_q;                       // the last valid pixel's value
  logic          s2_ok;
  // The check as a difference on both targets (the FPGA target's window of compares
  // made the design harder to route: docs/blocks/fpga_target.md, Timing).
  if (mcadsw_pkg::FPGA != 0) begin : g_ok_fpga
    logic [7:0] d_right;                       // dR(x - d)
    assign d_right = dr_word_q[8*s2_byte_q +: 8];
    assign s2_ok = s2_inside_q &&
                   ((s2_d_q >= d_right) ? (s2_d_q - d_right) : (d_right - s2_d_q)) <= {2'b00, tol_i};
  end else begin : g_ok_diff
    logic [7:0] d_right;                       // dR(x - d)
    assign d_right = dr_word_q[8*s2_byte_q +: 8];
    assign s2_ok = s2_inside_q &&
                   ((s2_d_q >= d_right) ? (s2_d_q - d_right) : (d_right - s2_d_q)) <= {2'b00, tol_i};
  end
  assign vrow_we_o   = s2_valid_q;
  assign vrow_x_o    = s2_x_q;
  assign vrow_data_o = {s2_ok, s2_ok || seen_q, s2_ok ? s2_value_q : last_q};

  always_ff @(posedge clk_i) begin
    if (rvalid_i && answered_q < dr_words) dr_row[answered_q[RI-1:0]] <= rdata_i;
    if (take) dr_word_q <= dr_row[match_x[RI+1:2]];
  end

  // Data: no reset (used only under the valid bits below).
  always_ff @(posedge clk_i) begin
    if (dl_pop) word_q <= dl_head;
    if (take) begin
      s2_x_q     <= XI'(x_q);
      s2_d_q     <= d;
      s2_value_q <= value;
      s2_byte_q  <= match_x[1:0];
    end
    if (s2_valid_q && s2_ok) last_q <= s2_value_q;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      asked_q      <= '0;
      answered_q   <= '0;
      addr_q       <= '0;
      credit_q     <= '0;
      word_valid_q <= 1'b0;
      slot_q       <= '0;
      x_q          <= '0;
      s2_valid_q   <= 1'b0;
      s2_inside_q  <= 1'b0;
      seen_q       <= 1'b0;
    end else begin
      if (read_o) begin
        addr_q  <= (asked_q + (CW + 1)'(1) == dr_words) ? dl_row_i : addr_q + AW'(4);
        asked_q <= asked_q + 1'b1;
      end
      if (rvalid_i) answered_q <= answered_q + 1'b1;
      credit_q <= credit_q + (FI + 1)'(read_o && asking_dl) - (FI + 1)'(dl_pop);
      if (reads_start_i) begin
        addr_q     <= dr_row_i;
        asked_q    <= '0;
        answered_q <= '0;
        credit_q   <= '0;
      end

      s2_valid_q <= take;
      if (take) begin
        s2_inside_q <= !match_x[CW] && !flag;
        x_q         <= x_q + CW'(1);
        slot_q      <= slot_q + 2'd1;
        if (row_last) word_valid_q <= 1'b0;
        else if (word_last) begin
          word_valid_q <= dl_pop;
          slot_q       <= '0;
        end
      end
      if (dl_pop) begin
        word_valid_q <= 1'b1;
        slot_q       <= '0;
      end
      if (s2_valid_q && s2_ok) seen_q <= 1'b1;
      if (pixels_start_i) begin
        word_valid_q <= 1'b0;
        x_q          <= '0;
        seen_q       <= 1'b0;
      end
    end
  end

  // The dL word queue takes every word requested (the credit).
  `MCADSW_ASSERT(CreditWithinQueue, credit_q <= (FI + 1)'(FD))
  `MCADSW_ASSERT(CreditCoversQueue, dl_count <= credit_q)
  `MCADSW_ASSUME(NoReadWhileReadsStart, !(reads_start_i && (read_o || rvalid_i)))

endmodule

`default_nettype wire
