// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Rectifier: the mark step (docs/algorithm.md 13.4, docs/blocks/rectifier.md 8). Writes
// value_i into a plane at every pixel a view's validity bitmap calls invalid, and touches
// nothing else: the invalid code into the disparity plane after a pass; in the LR mode
// 255 into dR and a flagged value into dL before the post stage.
//
// The bitmap (written by mcadsw_rect_write): word (x / 4) ceil(H / 8) + y / 8, bit
// 4 (y % 8) + x % 4, 1 valid; bits of pixels outside the frame are ignored. The plane:
// pixel (x, y) at base + y stride + x (bytes, half_i = 0) or + 2x (halfwords, half_i = 1);
// base and stride multiples of 4. The bitmap is read strip column by strip column in
// bursts of up to 8 words (never across a strip column or a 4 KiB boundary) into a queue
// of FD words (the read credit). A word whose in-frame bits are all 1 costs a cycle; any
// other costs a cycle a row (two in halfword mode), issuing a write with the row's invalid
// bytes enabled where there are any. Addresses are incremental (no multiplier). The
// configuration is held while busy_o; done_o pulses once every write is granted.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_rect_mark #(
  parameter int CW = 12,
  parameter int FD = 8                                    // bitmap words queued or in flight
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               start_i,
  input  logic [CW-1:0]      width_i,                     // 1 .. 2^CW - 1
  input  logic [CW-1:0]      height_i,
  input  logic [31:0]        valid_base_i,
  input  logic [31:0]        base_i,
  input  logic [31:0]        stride_i,
  input  logic               half_i,
  input  logic [15:0]        value_i,
  output logic               busy_o,
  output logic               done_o,
  // Memory port (docs/memory_map.md): request held until granted, reads answered in order
  output logic               mem_req_o,
  input  logic               mem_gnt_i,
  output logic               mem_we_o,
  output logic [3:0]         mem_be_o,
  output logic [31:0]        mem_addr_o,
  output logic [2:0]         mem_len_o,
  output logic [31:0]        mem_wdata_o,
  input  logic               mem_rvalid_i,
  input  logic [31:0]        mem_rdata_i
);

  // Built in only when the package says so (mcadsw_rect_none.sv otherwise).
  if (mcadsw_pkg::RECT == 0) begin : g_no_rect
    mcadsw_error_rect_in_a_build_without_it u_error ();
  end
  localparam int FB = $clog2(FD);

  // ---- Frame geometry --------------------------------------------------------------------------
  // Registered from the configuration every cycle (no reset, no enable): the inputs are held
  // from the start on, and the first use is the cycle after it. Registered, the marker's
  // enables start from flip-flops (from width_i / height_i through the masks they missed
  // half a period into their clock gates when it was timed alone).
  logic [CW-1:0] last_k, last_g;                          // the last strip column and 8-row group
  logic [3:0]    last_colmask;                            // the last strip column's columns
  logic [7:0]    last_rowmask;                            // the last group's rows
  always_ff @(posedge clk_i) begin
    last_k       <= (width_i - CW'(1)) >> 2;
    last_g       <= (height_i - CW'(1)) >> 3;
    last_colmask <= 4'b1111 >> (2'd3 - 2'(width_i - CW'(1)));
    last_rowmask <= 8'hff >> (3'd7 - 3'(height_i - CW'(1)));
  end

  // ---- Reader: the bitmap, strip column by strip column --------------------------------------
  logic          run_q;                                   // a frame is being marked
  logic          rd_more_q;                               // words left to request
  logic [CW-1:0] rk_q, rg_q;                              // the next word to request
  logic [31:0]   ra_q;                                    // its address
  logic [FB:0]   credit_q;                                // words requested and not yet popped
  logic [3:0]    burst;
  logic [CW:0]   col_left;
  logic [10:0]   to_4k;
  assign col_left = {1'b0, last_g} - {1'b0, rg_q} + (CW + 1)'(1);
  assign to_4k = 11'd1024 - 11'(ra_q[11:2]);
  always_comb begin
    burst = 4'd8;
    if (col_left < (CW + 1)'(8)) burst = 4'(col_left);
    if (to_4k < 11'(burst)) burst = 4'(to_4k);
  end
  logic rd_room;
  assign rd_room = 32'(credit_q) + 32'(burst) <= FD;
  logic rd_issue;                                         // a read burst enters the port this cycle

  // ---- Queue of bitmap words -------------------------------------------------------------------
  logic          q_pop;
  logic [31:0]   q_head;
  logic [FB:0]   q_count;
  mcadsw_fifo #(.W(32), .DEPTH(FD)) u_queue (
    .clk_i, .rst_ni, .push_i(mem_rvalid_i), .data_i(mem_rdata_i), .push2_i(1'b0), .data2_i(32'b0),
    .pop_i(q_pop), .head_o(q_head), .count_o(q_count)
  );

  // ---- Marker: the head word, row by row -------------------------------------------------------
  logic [CW-1:0] ck_q, cg_q;                              // the head word's strip column and group
  logic [2:0]    r_q;                                     // its row
  logic          h_q;                                     // the row's second word (halfwords)
  logic [31:0]   col_q;                                   // base + 4 ck (bytes) or 8 ck (halfwords)
  logic [31:0]   row_q;                                   // the row's first word: col + y stride
  logic [3:0]    colmask;                                 // the word's columns inside the frame
  logic [7:0]    rowmask;                                 // its rows inside the frame
  assign colmask = ck_q == last_k ? last_colmask : 4'b1111;
  assign rowmask = cg_q == last_g ? last_rowmask : 8'hff;
  logic all_ok;                                           // every in-frame pixel of the word valid
  always_comb begin
    all_ok = 1'b1;
    for (int r = 0; r < 8; r++)
      if (rowmask[r] && (q_head[4 * r +: 4] & colmask) != colmask) all_ok = 1'b0;
  end
  logic [3:0] inv;                                        // the row's invalid pixels
  assign inv = ~q_head[4 * r_q +: 4] & colmask;
  logic [3:0] be;
  assign be = !half_i ? inv : h_q ? {{2{inv[3]}}, {2{inv[2]}}} : {{2{inv[1]}}, {2{inv[0]}}};
  logic row_last, part_last, word_last;
  assign row_last  = r_q == 3'd7 || !rowmask[r_q + 3'd1];
  assign part_last = !half_i || h_q;
  assign word_last = ck_q == last_k && cg_q == last_g;
  logic have;                                             // a head word to mark
  assign have = run_q && q_count != '0;
  logic wr_want;                                          // the row's write, waiting for the port
  assign wr_want = have && !all_ok && be != 4'b0;
  logic slot;                                             // the port's request register is free
  assign slot = !mem_req_o || mem_gnt_i;
  logic step;                                             // the marker moves on this cycle
  assign step = have && (all_ok || !wr_want || slot);
  assign q_pop = step && (all_ok || (row_last && part_last));
  assign rd_issue = run_q && slot && !wr_want && rd_more_q && rd_room;
  logic fin_q;                                            // every word marked: the last write's grant

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      run_q <= 1'b0; fin_q <= 1'b0; rd_more_q <= 1'b0; rk_q <= '0; rg_q <= '0; ra_q <= '0; credit_q <= '0;
      ck_q <= '0; cg_q <= '0; r_q <= '0; h_q <= 1'b0; col_q <= '0; row_q <= '0;
      mem_req_o <= 1'b0; mem_we_o <= 1'b0; mem_be_o <= '0; mem_addr_o <= '0; mem_len_o <= '0;
      mem_wdata_o <= '0; done_o <= 1'b0;
    end else begin
      done_o <= 1'b0;
      if (start_i && !busy_o) begin
        run_q <= 1'b1; rd_more_q <= 1'b1; rk_q <= '0; rg_q <= '0; ra_q <= valid_base_i;
        ck_q <= '0; cg_q <= '0; r_q <= '0; h_q <= 1'b0; col_q <= base_i; row_q <= base_i;
      end
      // The port: the marker's write first, then a read burst within the credit.
      if (run_q && slot) begin
        mem_req_o <= 1'b0;
        if (wr_want) begin
          mem_req_o   <= 1'b1;
          mem_we_o    <= 1'b1;
          mem_be_o    <= be;
          mem_addr_o  <= row_q + (h_q ? 32'd4 : 32'd0);
          mem_len_o   <= 3'd0;
          mem_wdata_o <= half_i ? {2{value_i}} : {4{value_i[7:0]}};
        end else if (rd_issue) begin
          mem_req_o   <= 1'b1;
          mem_we_o    <= 1'b0;
          mem_be_o    <= 4'b0;
          mem_addr_o  <= ra_q;
          mem_len_o   <= 3'(burst - 4'd1);
          ra_q        <= ra_q + {26'b0, burst, 2'b00};
          if (rg_q + CW'(burst) > last_g) begin            // the strip column's last burst
            rg_q <= '0;
            rk_q <= rk_q + CW'(1);
            if (rk_q == last_k) rd_more_q <= 1'b0;
          end else rg_q <= rg_q + CW'(burst);
        end
      end
      credit_q <= credit_q + (rd_issue ? (FB + 1)'(burst) : '0) - (FB + 1)'(q_pop);
      // The marker
      if (step) begin
        if (all_ok) begin
          row_q <= row_q + {stride_i[28:0], 3'b000};
        end else if (part_last) begin
          h_q <= 1'b0;
          r_q <= r_q + 3'd1;
          row_q <= row_q + stride_i;
        end else h_q <= 1'b1;
        if (q_pop) begin
          r_q <= '0;
          h_q <= 1'b0;
          if (cg_q == last_g) begin                        // the next strip column
            cg_q <= '0;
            ck_q <= ck_q + CW'(1);
            col_q <= col_q + (half_i ? 32'd8 : 32'd4);
            row_q <= col_q + (half_i ? 32'd8 : 32'd4);
          end else cg_q <= cg_q + CW'(1);
          if (word_last) begin
            run_q <= 1'b0;
            fin_q <= 1'b1;
          end
        end
      end
      if (fin_q && slot) begin                            // the last write granted
        mem_req_o <= 1'b0;
        fin_q     <= 1'b0;
        done_o    <= 1'b1;
      end
    end
  end
  assign busy_o = run_q || fin_q || done_o;

  logic unused_mark;
  assign unused_mark = ^{stride_i[31:29]};

  `MCADSW_ASSUME(start_when_idle, !(start_i && busy_o))
  `MCADSW_ASSERT(credit_covers_queue, 32'(q_count) <= 32'(credit_q) && 32'(credit_q) <= FD)
  `MCADSW_ASSERT(no_read_beyond_credit, !(mem_rvalid_i && 32'(q_count) >= FD))
  `MCADSW_ASSERT(burst_in_4k, !(mem_req_o && !mem_we_o) || 13'(mem_addr_o[11:0]) + 13'({mem_len_o, 2'b00}) < 13'd4096)
endmodule

`default_nettype wire
