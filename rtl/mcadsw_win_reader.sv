// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Window reader: one requestor of the memory controller (Sec. V-E). Streams a
// read window of PLANES 8-bit planes to a census transformer or the weight
// generator in the strip order they take (for each strip of 4 columns, for
// each plane, rows 0 .. ROWS-1; byte b = column x0 + 4s + b), reading external
// memory at clamped coordinates (docs/algorithm.md section 2): pixel (x, y) of
// the window is image pixel (clamp(x0 + x), clamp(y0 + y)).
//
// The number of strips is set per window (strips_i, 1 .. STRIPS): a block that
// continues its left neighbour reads only the strips its input buffers do not
// hold yet (partial column reuse, Sec. IV).
//
// The window origin x0 is word-aligned (the top starts every window at the
// aligned word at or left of its first column), so the 4 clamped columns of a
// strip word always lie in one memory word: clamping moves a column only to
// column lo or width-1, inside the strip's own word.
//
// Mirrored (the right view as base, docs/blocks/engine.md section 6), the
// window's columns are the pass's: pass column c is image column
// width - 1 - c (width a multiple of 4), and the image occupies the pass's
// columns lo .. width - 1. An aligned strip word is then an aligned memory
// word with its bytes in reverse order.
//
// Reads: a strip plane's rows clamp to the image rows clamp(y0) ..
// clamp(y0 + ROWS - 1); each of those K memory words is read once, and rows
// clamped to the same image row repeat its word on the way out (the response
// side keeps the word until the row after it maps elsewhere).
// Layouts (docs/memory_map.md): raster, pixel (x, y) at base + y stride + x,
// one read (a burst of 1) a word; or column-tiled (tile_i != 0), pixel (x, y)
// at base + (x / 4) tile + 4 y + x % 4, where a strip plane's K words are
// consecutive: read bursts of up to BL beats (len_o + 1), none across a 4 KiB
// boundary. A burst is requested only when the response FIFO (OUTS words)
// has room for all of it; responses come in order.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_win_reader #(
  parameter int ROWS   = 52,             // rows of a strip
  parameter int STRIPS = 13,             // most strips of 4 columns a plane
  parameter int PLANES = 1,              // 1 (luma) or 3 (Y, U, V)
  parameter int OUTS   = 8,              // words in flight (response FIFO)
  parameter int BL     = 8,              // longest read burst, beats (tiled layout)
  parameter int CW     = 12,             // coordinate width (signed)
  parameter int AW     = 32,
  parameter int SB     = $clog2(STRIPS + 1)
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  // Window: started by start_i, which takes x0_i, y0_i and strips_i; base_i,
  // stride_i, tile_i, width_i and height_i are stable while busy_o
  input  logic                 start_i,
  input  logic [PLANES*AW-1:0] base_i,     // byte address of pixel (0,0) of each plane
  input  logic [AW-1:0]        stride_i,   // raster: bytes per image row, multiple of 4
  input  logic [AW-1:0]        tile_i,     // column-tiled: bytes per 4-pixel column; 0: raster
  input  logic [CW-1:0]        width_i,    // columns lo_i .. width_i - 1 are the image's
  input  logic [1:0]           lo_i,
  input  logic                 mirror_i,
  input  logic [CW-1:0]        height_i,
  input  logic signed [CW:0]   x0_i,       // window origin in image coordinates, a multiple of 4
  input  logic signed [CW:0]   y0_i,
  input  logic [SB-1:0]        strips_i,   // strips a plane, 1 .. STRIPS
  output logic                 busy_o,
  // Memory controller
  output logic                 req_o,
  output logic [AW-1:0]        addr_o,
  output logic [3:0]           len_o,      // beats of the burst - 1
  input  logic                 gnt_i,
  input  logic                 rvalid_i,
  input  logic [31:0]          rdata_i,
  // Strip words to the block
  output logic                 pix_valid_o,
  input  logic                 pix_ready_i,
  output logic [31:0]          pix_data_o
);

  localparam int RB  = $clog2(ROWS);
  localparam int PB  = (PLANES > 1) ? $clog2(PLANES) : 1;
  localparam int OB  = $clog2(OUTS + 1);
  localparam int NLB = $clog2(BL + 1);

  if (STRIPS < 1 || 4 * STRIPS >= (1 << CW) || BL < 1 || BL > 16 || BL > OUTS ||
      BL > ROWS) begin : g_bad_param
    mcadsw_error_win_reader_geometry u_error ();
  end

  function automatic int clampi(input int v, input int lo, input int n);
    clampi = (v < lo) ? lo : (v > n - 1) ? n - 1 : v;
  endfunction

  // A position in the strip sequence: {done, plane, strip, row}; done past the
  // end. The response side counts the ROWS rows of a strip plane, the request
  // side its K words (row = word k, last = K - 1).
  localparam int QW = 1 + PB + SB + RB;

  function automatic logic [QW-1:0] next_pos(input logic [QW-1:0] p, input logic [RB-1:0] last,
                                             input logic [SB-1:0] strips);
    logic          done;
    logic [PB-1:0] plane;
    logic [SB-1:0] strip;
    logic [RB-1:0] row;
    {done, plane, strip, row} = p;
    if (row != last) begin
      row = row + RB'(1);
    end else begin
      row = '0;
      if (plane != PB'(PLANES - 1)) begin
        plane = plane + PB'(1);
      end else begin
        plane = '0;
        if (strip != strips - SB'(1)) strip = strip + SB'(1);
        else done = 1'b1;
      end
    end
    next_pos = {done, plane, strip, row};
  endfunction

  // n words on (1 <= n, not past the strip plane's last word).
  function automatic logic [QW-1:0] adv_pos(input logic [QW-1:0] p, input logic [NLB-1:0] n,
                                            input logic [RB-1:0] last, input logic [SB-1:0] strips);
    logic [RB:0] r;
    r = (RB + 1)'(p[RB-1:0]) + (RB + 1)'(n);
    if (r > (RB + 1)'(last)) adv_pos = next_pos({p[QW-1:RB], last}, last, strips);
    else adv_pos = {p[QW-1:RB], RB'(r)};
  endfunction

  // The window origin and strip count, registered at start_i; the address terms
  // are computed from them in the next two cycles (init_q: the clamps, then the
  // multiplier; on the FPGA target the product's shift and add), each from flip-flops, not from the block arithmetic in the top
  // (those paths were critical, docs/synthesis.md section 1).
  logic signed [CW:0]   x0_q, y0_q;
  logic [SB-1:0]        strips_q;
  logic [CW-1:0]        ylo_q;       // clamp(y0): the image row of a strip plane's word 0
  logic [RB-1:0]        klast_q;     // K - 1: clamp(y0 + ROWS - 1) - clamp(y0)

  logic          busy_q;
  logic [1:0]    init_q;             // the cycles after start_i: address terms computed
  logic [QW-1:0] rq_q, rs_q;         // word being requested / row being delivered
  logic          rq_done, rs_done;
  logic [PB-1:0] rs_plane_unused;
  logic [SB-1:0] rs_strip;
  logic [RB-1:0] rs_row;
  assign rq_done = rq_q[QW-1];       // the request side needs only done; addresses come from pos_q
  assign {rs_done, rs_plane_unused, rs_strip, rs_row} = rs_q;
  logic [OB-1:0] inflight_q;         // words requested, not yet delivered for the last time

  // Clamped column of byte b of strip s.
  function automatic int col_of(input logic [SB-1:0] s, input int b,
                                input logic signed [CW:0] x0, input logic [1:0] lo,
                                input logic [CW-1:0] w);
    col_of = clampi(32'(x0) + 4*32'(s) + b, 32'(lo), 32'(w));
  endfunction

  // ---- Request side -------------------------------------------------------------
  // The request address is a register (addr_q), loaded a cycle ahead: in the
  // second cycle after start_i for the first burst (no request before), then
  // at each grant for the next one. Its position (pos_q) carries the parts of
  // its address as registers, updated step by step, so the address is a sum of
  // three terms and no multiplier lies on the per-request path:
  //   raster: yoff_q = (ylo + k) * stride (the product only at start_i, then
  //           + stride a word, back to yoff0_q at word 0); xo_q = the image
  //           column of the strip word's memory word;
  //   tiled:  4 (ylo + k); xo_q = that memory word's column of words times tile
  //           (the product only at start_i, then +- tile when the next strip's
  //           word differs).
  // A reader's one multiplier is shared: clamp(y0) * stride or word(x0) * tile,
  // computed once a window, two cycles after start_i (FPGA target: by shift and
  // add, up to CW cycles more).
  logic          tiled;
  assign tiled = tile_i != '0;
  logic          addr_ok_q;          // addr_q holds the address of rq_q
  logic [AW-1:0] addr_q, addr_next;
  logic [NLB-1:0] len_q, len_next;   // beats of addr_q's burst / of the one loaded next
  logic [QW-1:0] pos_q, pos_next;    // the position whose address is loaded next
  logic          p_done_unused;
  logic [PB-1:0] p_plane;
  logic [SB-1:0] p_strip_unused;
  logic [RB-1:0] p_k;
  logic [AW-1:0] yoff_q, yoff0_q, yterm;
  logic signed [CW+1:0] xabs_q;      // x0 + 4 strip, unclamped
  logic [CW-1:0] xoff_q;             // image column of the strip word's memory word
  logic [AW-1:0] xo_q;               // its byte offset in the plane (raster: xoff_q)
  assign {p_done_unused, p_plane, p_strip_unused, p_k} = pos_q;
  logic [CW-1:0] ycur;               // image row of pos_q's word
  assign ycur      = ylo_q + CW'(p_k);
  assign yterm     = tiled ? AW'(ycur) << 2 : yoff_q;
  assign addr_next = base_i[32'(p_plane)*AW +: AW] + yterm + xo_q;

  // Burst length of pos_q's word: tiled, the words to the strip plane's last,
  // to the 4 KiB boundary, at most BL; raster, 1.
  logic [10:0] page_left;             // words to the next 4 KiB boundary
  logic [RB:0] words_left;            // words of the strip plane from pos_q's on
  assign page_left  = 11'd1024 - 11'(addr_next[11:2]);
  assign words_left = (RB + 1)'(klast_q) + (RB + 1)'(1) - (RB + 1)'(p_k);
  always_comb begin
    len_next = NLB'(1);
    if (tiled) begin
      len_next = NLB'(BL);
      if (words_left < (RB + 1)'(BL)) len_next = NLB'(words_left);
      if (page_left < 11'(len_next)) len_next = NLB'(page_left);
    end
  end

  // The first image column of the memory word holding pass column x (clamped).
  function automatic logic [CW-1:0] mem_col(input logic signed [CW+1:0] x, input logic [1:0] lo,
                                            input logic [CW-1:0] w, input logic mirror);
    logic [CW-1:0] word;
    word = CW'(4 * (clampi(32'(x), 32'(lo), 32'(w)) / 4));
    mem_col = mirror ? w - word - CW'(4) : word;
  endfunction
  // In the cycle after start_i the first column's memory word and the strip
  // plane's rows (xoff_q, ylo_q, klast_q); in the next, from those, the raster
  // row offset clamp(y0) * stride or the tiled column offset word(x0) * tile
  // (prod0, valid when mul_done).
  logic [CW-1:0] col0, ylo0, yhi0;
  logic [AW-1:0] mul_b, prod0;
  logic          mul_done;
  assign col0  = mem_col((CW + 2)'(x0_q), lo_i, width_i, mirror_i);
  assign ylo0  = CW'(clampi(32'(y0_q), 0, 32'(height_i)));
  assign yhi0  = CW'(clampi(32'(y0_q) + ROWS - 1, 0, 32'(height_i)));
  assign mul_b = tiled ? tile_i : stride_i;
  if (mcadsw_pkg::FPGA != 0) begin : g_fpga_mul
    // FPGA target: the product by shift and add, one bit of the row or word column
    // a cycle from its lowest, until the bits left are 0 (at most CW cycles; 0
    // cycles for a product by 0), so a reader takes no multiplier of the device's
    // fixed rows and no adders between it and the address logic. The operand is
    // the one ylo_q or xoff_q takes in the same cycle.
    logic [CW-1:0] ma_q;
    logic [AW-1:0] mb_q, acc_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ma_q  <= '0;
        mb_q  <= '0;
        acc_q <= '0;
      end else if (init_q[0]) begin
        ma_q  <= tiled ? CW'(col0[CW-1:2]) : ylo0;
        mb_q  <= mul_b;
        acc_q <= '0;
      end else if (ma_q != '0) begin
        if (ma_q[0]) acc_q <= acc_q + mb_q;
        ma_q <= ma_q >> 1;
        mb_q <= mb_q << 1;
      end
    end
    assign mul_done = ma_q == '0;
    assign prod0    = acc_q;
  end else begin : g_asic_mul
    logic [AW-1:0] mul_a;
    assign mul_a    = tiled ? AW'(xoff_q[CW-1:2]) : AW'(ylo_q);
    assign prod0    = mul_a * mul_b;
    assign mul_done = 1'b1;
  end
  // pos_next: adv_pos(pos_q, len_next, ...), its test made without the sum: the
  // burst ends the strip plane's column (next: the next plane or strip) when it
  // takes every word left (tiled: they fit BL and the page; raster: the last).
  logic col_end;
  assign col_end  = tiled ? words_left <= (RB + 1)'(BL) && 11'(words_left) <= page_left
                          : p_k == klast_q;
  assign pos_next = col_end ? next_pos({pos_q[QW-1:RB], klast_q}, klast_q, strips_q)
                            : {pos_q[QW-1:RB], p_k + RB'(len_next)};
  logic advance;                     // addr_q takes addr_next: pos_q moves on
  assign advance = (busy_q && init_q == '0 && !addr_ok_q) || (req_o && gnt_i);
  logic strip_end;                   // pos_q's burst ends its strip (all planes)
  assign strip_end = col_end && p_plane == PB'(PLANES - 1);
  logic [CW-1:0] xoff_next;
  logic          xo_up, xo_down;     // tiled: the next strip's word is one on / one back
  // The next strip's word by the clamp, on both targets (the FPGA target's form from
  // registers made the design harder to route: docs/blocks/fpga_target.md, Timing).
  if (mcadsw_pkg::FPGA != 0) begin : g_xnext_fpga
    assign xoff_next = mem_col(xabs_q + (CW + 2)'(4), lo_i, width_i, mirror_i);
    assign xo_up     = xoff_next > xoff_q;
    assign xo_down   = xoff_next < xoff_q;
  end else begin : g_xnext_clamp
    assign xoff_next = mem_col(xabs_q + (CW + 2)'(4), lo_i, width_i, mirror_i);
    assign xo_up     = xoff_next > xoff_q;
    assign xo_down   = xoff_next < xoff_q;
  end

  // The response buffer is the pipeline itself: stop requesting when the
  // burst's words would not all fit.
  assign req_o  = busy_q && addr_ok_q && !rq_done &&
                  (OB + 1)'(inflight_q) + (OB + 1)'(len_q) <= (OB + 1)'(OUTS);
  assign addr_o = addr_q;
  assign len_o  = 4'(len_q - NLB'(1));

  // ---- Response side ---------------------------------------------------------------
  // Responses wait in a small FIFO until the block takes the strip word. Row r
  // of a strip plane (image row clamp(y0 + r)) shows the head word; the head is
  // popped after the row unless the next row maps to the same image row (rows
  // above the image share row 0's word, rows below share the last row's).
  // The FIFO is a ring: entries written in place (a decoded write) and read at the
  // head pointer, so no entry moves (a shifting queue would put a 3:1 select in
  // front of every bit).
  localparam int FPB = (OUTS > 1) ? $clog2(OUTS) : 1;
  logic [OUTS*32-1:0] fifo_q;
  logic [FPB-1:0]     fwr_q, frd_q;      // the entry written next, the head
  logic [OB-1:0]      fcount_q;
  logic               pop, pop_word;
  logic signed [CW+1:0] rsy_q;       // y0 + rs_row, unclamped
  // A strip word is ready when its response is; byte b is column
  // clamp(x0 + 4s + b), i.e. byte b, or the edge column's byte where clamped.
  logic [31:0] head;
  assign head        = fifo_q[32'(frd_q)*32 +: 32];
  assign pix_valid_o = busy_q && !rs_done && fcount_q != '0;
  for (genvar b = 0; b < 4; b++) begin : g_byte
    int c;
    assign c = col_of(rs_strip, b, x0_q, lo_i, width_i);
    assign pix_data_o[b*8 +: 8] = head[(mirror_i ? 3 - c % 4 : c % 4)*8 +: 8];
  end
  assign pop      = pix_valid_o && pix_ready_i;
  assign pop_word = pop && (rs_row == RB'(ROWS - 1) ||
                            (rsy_q >= 0 && rsy_q < $signed({2'b00, height_i}) - (CW + 2)'(1)));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q       <= 1'b0;
      init_q       <= '0;
      addr_ok_q    <= 1'b0;
      addr_q       <= '0;
      len_q        <= '0;
      xo_q         <= '0;
      pos_q        <= '0;
      yoff_q       <= '0;
      yoff0_q      <= '0;
      xabs_q       <= '0;
      xoff_q       <= '0;
      x0_q         <= '0;
      y0_q         <= '0;
      ylo_q        <= '0;
      klast_q      <= '0;
      strips_q     <= '0;
      rq_q         <= '0;
      rs_q         <= '0;
      rsy_q        <= '0;
      inflight_q   <= '0;
      fifo_q       <= '0;
      fwr_q        <= '0;
      frd_q        <= '0;
      fcount_q     <= '0;
    end else begin
      if (start_i && !busy_q) begin
        busy_q       <= 1'b1;
        init_q       <= 2'b01;
        addr_ok_q    <= 1'b0;
        x0_q         <= x0_i;
        y0_q         <= y0_i;
        strips_q     <= strips_i;
        rq_q         <= '0;
        rs_q         <= '0;
        rsy_q        <= (CW + 2)'(y0_i);
        pos_q        <= '0;
      end
      if (init_q[0]) begin
        init_q       <= 2'b10;
        ylo_q        <= ylo0;
        klast_q      <= RB'(yhi0 - ylo0);
        xabs_q       <= (CW + 2)'(x0_q);
        xoff_q       <= col0;
      end
      if (init_q[1] && mul_done) begin
        init_q       <= 2'b00;
        yoff_q       <= tiled ? '0 : prod0;
        yoff0_q      <= tiled ? '0 : prod0;
        xo_q         <= tiled ? prod0 : AW'(xoff_q);
      end
      if (busy_q && init_q == '0 && !addr_ok_q) addr_ok_q <= 1'b1;
      if (req_o && gnt_i) rq_q <= adv_pos(rq_q, len_q, klast_q, strips_q);
      if (advance) begin
        addr_q <= addr_next;
        len_q  <= len_next;
        pos_q  <= pos_next;
        // Raster (one word a burst): the next image row, or row clamp(y0) of
        // the next plane or strip.
        yoff_q <= col_end ? yoff0_q : yoff_q + stride_i;
        if (strip_end) begin
          // The next strip: its memory word, one word column on or the same.
          xabs_q <= xabs_q + (CW + 2)'(4);
          xoff_q <= xoff_next;
          if (!tiled) xo_q <= AW'(xoff_next);
          else if (xo_up) xo_q <= xo_q + tile_i;
          else if (xo_down) xo_q <= xo_q - tile_i;
        end
      end
      // FIFO: push the response, pop the word after its last row.
      if (rvalid_i) begin
        for (int i = 0; i < OUTS; i++)
          if (fwr_q == FPB'(i)) fifo_q[i*32 +: 32] <= rdata_i;
        fwr_q <= (fwr_q == FPB'(OUTS - 1)) ? '0 : fwr_q + FPB'(1);
      end
      if (pop_word) frd_q <= (frd_q == FPB'(OUTS - 1)) ? '0 : frd_q + FPB'(1);
      fcount_q <= fcount_q + OB'(rvalid_i) - OB'(pop_word);
      inflight_q <= inflight_q + (req_o && gnt_i ? OB'(len_q) : '0) - OB'(pop_word);
      if (pop) begin
        rs_q  <= next_pos(rs_q, RB'(ROWS - 1), strips_q);
        rsy_q <= rs_row == RB'(ROWS - 1) ? (CW + 2)'(y0_q) : rsy_q + (CW + 2)'(1);
        if (next_pos(rs_q, RB'(ROWS - 1), strips_q) >> (QW - 1) != '0) busy_q <= 1'b0;
      end
    end
  end

  assign busy_o = busy_q;

  // Invariants (docs/verification.md section 3), and what the scheduler and
  // the memory controller must keep.
  `MCADSW_ASSERT(ResponseFifoFits, !(rvalid_i && !pop_word && fcount_q == OB'(OUTS)))
  `MCADSW_ASSUME(ReadDataOnlyWhenInFlight, !(rvalid_i && inflight_q == '0))
  `MCADSW_ASSUME(WindowOriginWordAligned, !(start_i && !busy_q && x0_i[1:0] != 2'b00))
  `MCADSW_ASSERT(NoRowsLeftWhenAllDelivered, !(busy_q && !rs_done && rq_done && inflight_q == '0))

endmodule

`default_nettype wire
