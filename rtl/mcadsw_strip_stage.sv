// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Word buffer at the front of the input buffers (Fig. 10 / Fig. 11: "the input
// data are first packed into data words"), shared by the census transformer
// and the weight generator. The memory side delivers a window of PLANES planes
// in strips of 4 columns, one 32-bit word a row (byte b = column 4s + b),
// strip by strip, and each strip plane by plane (so a strip's Y, U and V are
// in the buffer together). This stage counts the words, collects the
// first ROWS - 1 words of a strip, and when the last row arrives presents the
// 4 complete column words with the strip's plane and index, so the input
// buffers only ever write whole words. A window may start at strip first_i
// (the strips before it are still in the input buffer from the previous,
// horizontally adjacent block: partial column reuse, Sec. IV); every plane
// then delivers strips first_i .. STRIPS-1.
//
// COLUMNS (the FPGA target's input buffers, a column chunk an entry): the
// finished strip's 4 column words also leave in CHUNKS chunks of ROWS / CHUNKS
// rows, one chunk of one column a cycle in the 4 CHUNKS cycles after its last
// word, chunk by chunk (col_n_o = 4 c + b: chunk c of column b in col_o), from
// the stage itself rather than a copy of it. The next strip's words, one a cycle
// at most, overwrite the stage's rows 0 .. 2 before chunk 0 of column 3 leaves
// (word n, presented in the (n+1)-th cycle after the last word, meets the next
// strip's rows 0 .. n - 1), so those rows and the last row (which never enters
// the stage) are kept apart: 128 flip-flops instead of 4 ROWS x 8. The later
// chunks' rows (from ROWS / CHUNKS on) stand until they leave.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_strip_stage #(
  parameter int ROWS   = mcadsw_pkg::BLOCK_COLS,  // rows of a strip
  parameter int STRIPS = 13,                      // strips a plane
  parameter int PLANES = 1,
  parameter bit COLUMNS = 0,                     // col_o: the column chunks one a cycle
  parameter int CHUNKS = 1,                      // chunks a column
  parameter int NB     = $clog2(4 * CHUNKS),     // col_n_o
  parameter int RB     = $clog2(ROWS),
  parameter int SB     = $clog2(STRIPS),
  parameter int PB     = (PLANES > 1) ? $clog2(PLANES) : 1
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 start_i,   // a new window begins with the next word
  input  logic [SB-1:0]        first_i,   // its first strip (sampled with start_i)
  input  logic                 wr_i,      // a word is accepted
  input  logic [31:0]          data_i,
  output logic                 last_o,    // this word ends a strip: cols_o is complete
  output logic                 done_o,    // this word ends the window
  output logic [PB-1:0]        plane_o,   // plane and strip of the word
  output logic [SB-1:0]        strip_o,
  output logic [4*ROWS*8-1:0]  cols_o,    // column b at b*ROWS*8, row y at byte y
  output logic                 col_valid_o,         // COLUMNS: col_o holds ...
  output logic [NB-1:0]        col_n_o,             // ... chunk col_n_o / 4 of column col_n_o % 4
  output logic [ROWS/CHUNKS*8-1:0] col_o            //     of the last strip
);

  if (COLUMNS && (ROWS % CHUNKS != 0 || ROWS / CHUNKS < 4 * CHUNKS - 1)) begin : g_bad_param
    mcadsw_error_strip_stage_chunks u_error ();   // a later chunk's rows overwritten before they leave
  end

  logic [RB-1:0]          row_q;
  logic [SB-1:0]          first_q;
  logic [(ROWS-1)*32-1:0] stage_q;

  assign last_o = wr_i && row_q == RB'(ROWS - 1);
  assign done_o = last_o && strip_o == SB'(STRIPS - 1) && plane_o == PB'(PLANES - 1);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      row_q   <= '0;
      first_q <= '0;
      strip_o <= '0;
      plane_o <= '0;
    end else if (start_i) begin
      row_q   <= '0;
      first_q <= first_i;
      strip_o <= first_i;
      plane_o <= '0;
    end else if (wr_i) begin
      row_q <= last_o ? '0 : row_q + RB'(1);
      if (last_o) begin
        if (plane_o == PB'(PLANES - 1)) begin
          plane_o <= '0;
          strip_o <= (strip_o == SB'(STRIPS - 1)) ? first_q : strip_o + SB'(1);
        end else begin
          plane_o <= plane_o + PB'(1);
        end
      end
    end
  end

  // The stage holds the words column by column (column b, row y at byte
  // b*(ROWS-1) + y), so the columns leave it as whole slices. The write is
  // decoded row by row (constant part-selects): a part-select at a computed
  // offset would be a bit-granular shifter across the whole stage.
  always_ff @(posedge clk_i) begin
    if (wr_i && !last_o)
      for (int r = 0; r < ROWS - 1; r++)
        if (row_q == RB'(r))
          for (int b = 0; b < 4; b++) stage_q[(b*(ROWS - 1) + r)*8 +: 8] <= data_i[b*8 +: 8];
  end

  for (genvar b = 0; b < 4; b++) begin : g_col
    assign cols_o[b*ROWS*8 +: (ROWS - 1)*8] = stage_q[b*(ROWS - 1)*8 +: (ROWS - 1)*8];
    assign cols_o[(b*ROWS + ROWS - 1)*8 +: 8] = data_i[b*8 +: 8];
  end

  if (COLUMNS) begin : g_columns
    localparam int KEPT = 3;                // rows the next strip reaches before chunk 0 of column 3
    localparam int CR   = ROWS / CHUNKS;    // rows a chunk
    localparam int NW   = 4 * CHUNKS;       // words presented a strip
    logic [4*KEPT*8-1:0] kept_q;            // rows 0 .. KEPT-1, column b at b*KEPT*8
    logic [31:0]         last_q;            // the last row, column b at byte b
    logic                valid_q;
    logic [NB-1:0]       n_q;
    logic [ROWS*8-1:0]   col;               // column n_q % 4
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        valid_q <= 1'b0;
        n_q     <= '0;
      end else if (last_o) begin
        valid_q <= 1'b1;
        n_q     <= '0;
      end else if (valid_q) begin
        valid_q <= n_q != NB'(NW - 1);
        n_q     <= n_q + NB'(1);
      end
    end
    always_ff @(posedge clk_i) begin
      if (last_o) begin
        for (int i = 0; i < 4; i++) kept_q[i*KEPT*8 +: KEPT*8] <= stage_q[i*(ROWS - 1)*8 +: KEPT*8];
        last_q <= data_i;
      end
    end
    // AND-OR selects of constant slices: column b of the strip, then chunk c of it.
    function automatic logic [ROWS*8-1:0] strip_col(input logic [(ROWS-1)*32-1:0] stage,
                                                    input logic [4*KEPT*8-1:0] kept,
                                                    input logic [31:0] last, input logic [1:0] b);
      strip_col = '0;
      for (int i = 0; i < 4; i++)
        strip_col = strip_col | ({last[i*8 +: 8], stage[(i*(ROWS - 1) + KEPT)*8 +: (ROWS - 1 - KEPT)*8],
                                  kept[i*KEPT*8 +: KEPT*8]} & {(ROWS*8){b == 2'(i)}});
    endfunction
    function automatic logic [CR*8-1:0] col_chunk(input logic [ROWS*8-1:0] c_word, input logic [NB-1:0] n);
      col_chunk = '0;
      for (int c = 0; c < CHUNKS; c++)
        col_chunk = col_chunk | (c_word[c*CR*8 +: CR*8] & {(CR*8){32'(n) / 4 == c}});
    endfunction
    assign col   = strip_col(stage_q, kept_q, last_q, n_q[1:0]);
    assign col_o = col_chunk(col, n_q);
    assign col_valid_o = valid_q;
    assign col_n_o     = n_q;
    // A strip's words are out before the next one ends, and no word reaches a row
    // KEPT .. ROWS - 2 that a chunk still to leave reads from the stage.
    `MCADSW_ASSERT(StripsRowsApart, !(last_o && valid_q))
    `MCADSW_ASSERT(KeptRowsSuffice, !(wr_i && !last_o && valid_q && row_q >= RB'(KEPT) &&
                                     4*(32'(row_q) / CR) + 3 > 32'(n_q)))
  end else begin : g_no_columns
    assign col_valid_o = 1'b0;
    assign col_n_o     = '0;
    assign col_o       = '0;
  end

endmodule

`default_nettype wire
