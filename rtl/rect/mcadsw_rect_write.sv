// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Rectifier: the writer of one tile's plane (docs/blocks/rectifier.md 6). It takes the
// sampling core's pixels in strip order, puts each 4 pixels of a strip row into one
// output word (byte enables for a row that ends inside a word at the frame's right edge)
// and, when asked, each 8 rows of a strip's validity bits into one word of the view's
// validity bitmap (bit 4 (y % 8) + x % 4, 1 valid; bits of pixels outside the tile 0).
//
// Addresses come from the caller, who keeps them incrementally: top_i is the address of
// the tile's first pixel word, a strip row lies step_row_i further (raster: the stride;
// column-tiled: 4) and a strip step_strip_i (raster: 4; tiled: the tile stride);
// vtop_i is the validity word of the tile's first strip and first 8 rows, the next 8
// rows 4 bytes further, the next strip vstep_strip_i (4 ceil(H / 8)) further.
//
// Words leave through a queue (mcadsw_fifo, two pushes a cycle: a pixel word and a
// validity word may complete together) to a write port in the engine's protocol;
// ready_o (the sampling core's en_i) holds the stream while the queue could overflow.
// idle_o: no word in the queue or on the port.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_rect_write #(
  parameter int DEPTH = 4
) (
  input  logic         clk_i,
  input  logic         rst_ni,
  // A tile's plane (registered at start_i, while idle)
  input  logic         start_i,
  input  logic [31:0]  top_i,
  input  logic [31:0]  step_row_i,
  input  logic [31:0]  step_strip_i,
  input  logic [5:0]   tile_w_i,                 // 1 .. 32
  input  logic [4:0]   tile_h_i,                 // 1 .. 16
  input  logic         valid_en_i,               // write the validity words too
  input  logic [31:0]  vtop_i,
  input  logic [31:0]  vstep_strip_i,
  // The sampling core's stream, taken at a clock edge with ready_o
  output logic         ready_o,
  input  logic         pix_valid_i,
  input  logic [7:0]   pix_i,
  input  logic         pix_ok_i,
  input  logic [4:0]   pix_x_i,
  input  logic [3:0]   pix_y_i,
  input  logic         pix_last_i,
  // Write port (docs/memory_map.md): the request held until granted
  output logic         wr_req_o,
  input  logic         wr_gnt_i,
  output logic [31:0]  wr_addr_o,
  output logic [3:0]   wr_be_o,
  output logic [31:0]  wr_data_o,
  output logic         done_o,                   // pulses when the tile's last pixel is taken
  output logic         idle_o
);
  localparam int QW = 32 + 4 + 32;               // {addr, be, data}

  logic [31:0] step_row_q, step_strip_q, vstep_q;
  logic [5:0]  tw_q;
  logic [4:0]  th_q;
  logic        ven_q;
  logic [31:0] strip_q, addr_q;                  // the strip's first word, this row's word
  logic [31:0] vstrip_q;                         // the strip's first validity word
  logic [31:0] word_q;                           // pixels of the word being filled
  logic [3:0]  be_q;
  logic [31:0] vbits_q;                          // the strip's 8-row validity word being filled

  logic take;
  assign take = ready_o && pix_valid_i;
  logic [1:0] bx;
  assign bx = pix_x_i[1:0];
  logic word_end, row_end, vgroup_end, strip_end;
  assign word_end   = bx == 2'd3 || {1'b0, pix_x_i} == tw_q - 6'd1;
  assign strip_end  = word_end && {1'b0, pix_y_i} == th_q - 5'd1;
  assign vgroup_end = word_end && (pix_y_i[2:0] == 3'd7 || strip_end);
  assign row_end    = word_end;

  // The words completed by this pixel
  logic [31:0] word_n, vbits_n;
  logic [3:0]  be_n;
  logic [4:0] vbit;                                    // 4 (y % 8) + x % 4
  assign vbit    = {pix_y_i[2:0], bx};
  assign word_n  = (word_q & ~(32'hff << {bx, 3'b000})) | (32'(pix_i) << {bx, 3'b000});
  assign be_n    = be_q | (4'b0001 << bx);
  assign vbits_n = (vbits_q & ~(32'd1 << vbit)) | (32'(pix_ok_i) << vbit);
  logic push_pix, push_v;
  assign push_pix = take && word_end;
  assign push_v   = take && vgroup_end && ven_q;
  logic [31:0] vaddr;
  assign vaddr = vstrip_q + (pix_y_i[3] ? 32'd4 : 32'd0);

  logic [QW-1:0] head;
  logic [$clog2(DEPTH):0] count;
  logic pop;
  mcadsw_fifo #(.W(QW), .DEPTH(DEPTH)) u_queue (
    .clk_i, .rst_ni,
    .push_i (push_pix), .data_i ({addr_q, be_n, word_n}),
    .push2_i(push_v),   .data2_i({vaddr, 4'hf, vbits_n}),
    .pop_i  (pop), .head_o(head), .count_o(count)
  );
  // The port's request register: the queue's head, popped into it when free.
  assign pop = count != '0 && (!wr_req_o || wr_gnt_i);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wr_req_o <= 1'b0; wr_addr_o <= '0; wr_be_o <= '0; wr_data_o <= '0;
    end else if (!wr_req_o || wr_gnt_i) begin
      wr_req_o <= count != '0;
      {wr_addr_o, wr_be_o, wr_data_o} <= count != '0 ? head : '0;
    end
  end
  // Room for two pushes after this cycle's pop
  assign ready_o = 32'(count) + 2 <= DEPTH + 32'(pop);
  assign idle_o  = count == '0 && !wr_req_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      step_row_q <= '0; step_strip_q <= '0; vstep_q <= '0; tw_q <= '0; th_q <= '0; ven_q <= 1'b0;
      strip_q <= '0; addr_q <= '0; vstrip_q <= '0; word_q <= '0; be_q <= '0; vbits_q <= '0;
      done_o <= 1'b0;
    end else begin
      done_o <= take && pix_last_i;
      if (start_i) begin
        step_row_q <= step_row_i; step_strip_q <= step_strip_i; vstep_q <= vstep_strip_i;
        tw_q <= tile_w_i; th_q <= tile_h_i; ven_q <= valid_en_i;
        strip_q <= top_i; addr_q <= top_i; vstrip_q <= vtop_i;
        word_q <= '0; be_q <= '0; vbits_q <= '0;
      end else if (take) begin
        word_q <= row_end ? '0 : word_n;
        be_q   <= row_end ? '0 : be_n;
        vbits_q <= vgroup_end ? '0 : vbits_n;
        if (strip_end) begin
          strip_q  <= strip_q + step_strip_q;
          addr_q   <= strip_q + step_strip_q;
          vstrip_q <= vstrip_q + vstep_q;
        end else if (row_end) begin
          addr_q <= addr_q + step_row_q;
        end
      end
    end
  end

  `MCADSW_ASSUME(start_when_idle, !(start_i && pix_valid_i))
  `MCADSW_ASSERT(queue_no_overflow, !(push_pix || push_v) || 32'(count) + 32'(push_pix) + 32'(push_v) <= DEPTH + 32'(pop))
endmodule

`default_nettype wire
