// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Post-processing stage of the LR mode (docs/algorithm.md 12.2-12.5,
// docs/blocks/post.md): reads the left map dL and the right map dR
// back from external memory row by row and writes the LR-checked, filled,
// 3x3-median-filtered map and the validity mask.
//
// Its own 32-bit port, in the protocol of docs/memory_map.md (the top gives it
// the external port once both passes are done). Reads are pipelined (several in
// flight), writes leave through a small queue.
//
// Planes (every base a multiple of 4):
//   dL    (base_dl_i, out_stride_i): 1 byte a pixel, d; wide: a halfword a pixel,
//         d in bits DB-1:0 and offset + 8 in bits DB+4:DB (the value is 16 d + offset)
//   dR    (base_dr_i, stride_i): 1 byte a pixel, d
//   out   (base_out_i, out_stride_i): 1 byte (d) or a halfword (16 d + offset) a pixel
//   mask  (base_mask_i, stride_i): 1 byte a pixel, 255 valid, 0 filled
// Each row y runs two phases, each a block of its own:
//   RD  rtl/mcadsw_post_check.sv: the dR row into its row buffer, then the dL
//       row word by word; a pixel a cycle, the LR check and the forward fill
//       into the row buffer vrow (here: RD writes it, CD reads it).
//       The next row's reads start during CD, when no write is waiting.
//   CD  rtl/mcadsw_post_fill.sv: from right to left, a pixel a cycle, the fill
//       from the right, the mask bytes of row y, and the 3x3 median of row y - 1.
// After the last row a CD pass without fill makes the median of row H - 1.
// This block owns the sequence of the phases (the state machine below), the
// frame's row addresses, the memory port's request register, vrow and the write
// queue (rtl/mcadsw_fifo.sv) that mask and output words leave through.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_post #(
  parameter int MAXW = mcadsw_pkg::POST_MAX_WIDTH,
  parameter int DB   = mcadsw_pkg::DISP_BITS,
  parameter int VB   = DB + 4,                  // value: d, or 16 d + offset
  parameter int CW   = 12,
  parameter int AW   = 32,
  parameter int FD   = 4,                       // dL words requested and not yet used
  parameter int QD   = 8                        // write queue entries
) (
  input  logic           clk_i,
  input  logic           rst_ni,
  input  logic           start_i,
  input  logic [AW-1:0]  base_dl_i,
  input  logic [AW-1:0]  base_dr_i,
  input  logic [AW-1:0]  base_out_i,
  input  logic [AW-1:0]  base_mask_i,
  input  logic [AW-1:0]  stride_i,
  input  logic [AW-1:0]  out_stride_i,
  input  logic [CW-1:0]  width_i,               // 1 .. MAXW
  input  logic [CW-1:0]  height_i,
  input  logic [5:0]     tol_i,                 // T
  input  logic           wide_i,
  output logic           busy_o,
  output logic           done_o,                // one cycle
  output logic           mem_req_o,
  input  logic           mem_gnt_i,
  output logic           mem_we_o,
  output logic [3:0]     mem_be_o,
  output logic [AW-1:0]  mem_addr_o,
  output logic [31:0]    mem_wdata_o,
  input  logic           mem_rvalid_i,
  input  logic [31:0]    mem_rdata_i
);

  localparam int XI = $clog2(MAXW);           // pixel index (MAXW a power of 2)
  localparam int QI = $clog2(QD);
  localparam int QE = 1 + CW + 4 + 32;         // queue entry: {out plane, word, be, data}

  if (MAXW < 4 || (1 << XI) != MAXW || MAXW > (1 << CW) || (1 << $clog2(FD)) != FD ||
      (1 << QI) != QD || QD < 8) begin : g_bad_param
    mcadsw_error_post_geometry u_error ();
  end

  // ---- Phases of a row --------------------------------------------------------------------
  typedef enum logic [2:0] {
    StIdle,
    StCheck,       // RD: the row's pixels through the check and the forward fill
    StCheckEnd,    // the last pixel's check; CD starts with the next cycle
    StFill,        // CD: fill, mask, median
    StRowEnd,      // wait for the row's words to leave the write queue
    StDone         // wait for the last write's grant
  } state_e;
  state_e        state_q;
  logic [CW-1:0] y_q;                          // the row in RD or CD

  // ---- Configuration, registered at start ---------------------------------------------------
  logic [AW-1:0] stride_q, out_stride_q;
  logic [CW-1:0] width_q, height_q;
  logic [5:0]    tol_q;
  logic          wide_q;
  // Row addresses: dR, dL and mask of row y, output of the row being filtered.
  logic [AW-1:0] dr_row_q, dl_row_q, mask_row_q, out_row_q;
  logic          early_q;                      // the next row's reads may start in CD

  // ---- Memory request register: held until granted ----------------------------------------
  logic          req_q, we_q;
  logic [3:0]    be_q;
  logic [AW-1:0] addr_q;
  logic [31:0]   wdata_q;
  assign mem_req_o   = req_q;
  assign mem_we_o    = we_q;
  assign mem_be_o    = we_q ? be_q : 4'h0;
  assign mem_addr_o  = addr_q;
  assign mem_wdata_o = we_q ? wdata_q : 32'h0;
  logic port_free;                             // no request waiting for its grant
  assign port_free = !req_q || mem_gnt_i;

  // ---- Write queue: mask words and output words -----------------------------------------------
  logic          mask_push, out_push, wq_pop;
  logic [QE-1:0] mask_entry, out_entry, wq_head;
  logic [QI:0]   wq_count;
  mcadsw_fifo #(.W(QE), .DEPTH(QD)) u_write_queue (
    .clk_i, .rst_ni,
    .push_i (mask_push), .data_i (mask_entry), .push2_i (out_push), .data2_i (out_entry),
    .pop_i (wq_pop), .head_o (wq_head), .count_o (wq_count)
  );
  logic          head_out;                     // the head entry: output (1) or mask plane
  logic [CW-1:0] head_word;                    // its word in the row
  logic [3:0]    head_be;
  logic [31:0]   head_data;
  assign {head_out, head_word, head_be, head_data} = wq_head;
  assign wq_pop = wq_count != '0 && port_free &&
                  (state_q == StFill || state_q == StRowEnd || state_q == StDone);
  // CD issues a pixel only while the queue can take what the pixels in flight
  // may still push: at most one mask and three output words (stages 1 to 5).
  logic          wq_room;
  assign wq_room = wq_count <= (QI + 1)'(QD - 5);

  // ---- vrow: {valid, has a value, value} of each column (RD writes, CD reads) -------------------
  logic [VB+1:0]  vrow [MAXW];
  logic           vrow_we, vrow_re;
  logic [XI-1:0]  vrow_wx, vrow_rx;
  logic [VB+1:0]  vrow_wdata, vrow_rdata_q;
  always_ff @(posedge clk_i) begin
    if (vrow_we) vrow[vrow_wx] <= vrow_wdata;
    if (vrow_re) vrow_rdata_q <= vrow[vrow_rx];
  end

  // ---- RD ----------------------------------------------------------------------------------------
  logic          fill_start, fill_fill, fill, fill_done;   // CD's pass (below)
  logic          reads_start, pixels_start, read_en, read, row_end;
  logic [AW-1:0] reads_dr_row, read_addr;
  // RD, or CD and the wait after it with no write waiting: the next row's reads.
  assign read_en = (state_q == StCheck ||
                    (early_q && (state_q == StFill || state_q == StRowEnd) && wq_count == '0)) &&
                   port_free;
  assign reads_start  = (state_q == StIdle && start_i) || state_q == StCheckEnd;
  assign reads_dr_row = state_q == StIdle ? base_dr_i : dr_row_q + stride_q;
  assign pixels_start = (state_q == StIdle && start_i) ||
                        (state_q == StRowEnd && wq_count == '0 && fill && y_q + CW'(1) < height_q);
  mcadsw_post_check #(.MAXW(MAXW), .DB(DB), .VB(VB), .CW(CW), .AW(AW), .FD(FD)) u_check (
    .clk_i, .rst_ni,
    .width_i (width_q), .tol_i (tol_q), .wide_i (wide_q),
    .reads_start_i (reads_start), .dr_row_i (reads_dr_row), .dl_row_i (dl_row_q),
    .read_en_i (read_en), .read_o (read), .read_addr_o (read_addr),
    .rvalid_i (mem_rvalid_i), .rdata_i (mem_rdata_i),
    .pixels_start_i (pixels_start), .pixels_en_i (state_q == StCheck), .row_end_o (row_end),
    .vrow_we_o (vrow_we), .vrow_x_o (vrow_wx), .vrow_data_o (vrow_wdata)
  );

  // ---- CD ----------------------------------------------------------------------------------------
  // From RD: fill row y and write the medians of row y - 1 (none after row 0).
  // After the last row: the last pass, the medians of row H - 1.
  assign fill_start = state_q == StCheckEnd ||
                      (state_q == StRowEnd && wq_count == '0 && fill && y_q + CW'(1) >= height_q);
  assign fill_fill  = state_q == StCheckEnd;
  mcadsw_post_fill #(.MAXW(MAXW), .DB(DB), .VB(VB), .CW(CW), .QE(QE)) u_fill (
    .clk_i, .rst_ni,
    .width_i (width_q), .wide_i (wide_q), .row_i (y_q),
    .start_i (fill_start), .fill_i (fill_fill), .medians_i (!fill_fill || y_q != '0),
    .issue_en_i (state_q == StFill && wq_room), .fill_o (fill), .done_o (fill_done),
    .vrow_re_o (vrow_re), .vrow_x_o (vrow_rx), .vrow_data_i (vrow_rdata_q),
    .mask_push_o (mask_push), .mask_entry_o (mask_entry),
    .out_push_o (out_push), .out_entry_o (out_entry)
  );

  // ---- Sequencer ---------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q      <= StIdle;
      y_q          <= '0;
      stride_q     <= '0;
      out_stride_q <= '0;
      width_q      <= '0;
      height_q     <= '0;
      tol_q        <= '0;
      wide_q       <= 1'b0;
      dr_row_q     <= '0;
      dl_row_q     <= '0;
      mask_row_q   <= '0;
      out_row_q    <= '0;
      early_q      <= 1'b0;
      req_q        <= 1'b0;
      we_q         <= 1'b0;
      be_q         <= '0;
      addr_q       <= '0;
      wdata_q      <= '0;
      done_o       <= 1'b0;
    end else begin
      done_o <= 1'b0;
      // The port: a read of RD, or the write queue's head (never both: reads wait
      // for an empty queue).
      if (req_q && mem_gnt_i) req_q <= 1'b0;
      if (read) begin
        req_q  <= 1'b1;
        we_q   <= 1'b0;
        addr_q <= read_addr;
      end
      if (wq_pop) begin
        req_q   <= 1'b1;
        we_q    <= 1'b1;
        addr_q  <= (head_out ? out_row_q : mask_row_q) + AW'({head_word, 2'b00});
        be_q    <= head_be;
        wdata_q <= head_data;
      end

      case (state_q)
        StIdle: if (start_i) begin
          stride_q     <= stride_i;
          out_stride_q <= out_stride_i;
          width_q      <= width_i;
          height_q     <= height_i;
          tol_q        <= tol_i;
          wide_q       <= wide_i;
          dr_row_q     <= base_dr_i;
          dl_row_q     <= base_dl_i;
          mask_row_q   <= base_mask_i;
          out_row_q    <= base_out_i;
          y_q          <= '0;
          early_q      <= 1'b0;
          state_q      <= StCheck;
        end
        StCheck: if (row_end) state_q <= StCheckEnd;
        // The last pixel's check happens in this cycle; CD reads from the next.
        // Row y + 1's reads may start during CD: its dR row goes into the dR row
        // buffer (free in CD), its first dL words into the word queue.
        StCheckEnd: begin
          dr_row_q <= dr_row_q + stride_q;
          dl_row_q <= dl_row_q + out_stride_q;
          early_q  <= y_q + CW'(1) < height_q;
          state_q  <= StFill;
        end
        StFill: if (fill_done) state_q <= StRowEnd;
        StRowEnd: if (wq_count == '0) begin
          // Row y done (its mask, the median of row y - 1); the output row moves
          // to row y once it has been written.
          if (y_q != '0) out_row_q <= out_row_q + out_stride_q;
          early_q <= 1'b0;
          if (!fill) state_q <= StDone;           // that was the last pass (no fill)
          else if (y_q + CW'(1) < height_q) begin
            y_q        <= y_q + CW'(1);
            mask_row_q <= mask_row_q + stride_q;
            state_q    <= StCheck;
          end else begin
            state_q <= StFill;
          end
        end
        StDone: if (!req_q) begin
          done_o  <= 1'b1;
          state_q <= StIdle;
        end
        default: state_q <= StIdle;
      endcase
    end
  end

  assign busy_o = state_q != StIdle;

  // ---- Invariants ---------------------------------------------------------------------------------
  // A request waits for its grant before the next one; the port carries a read or
  // a write, never both; an idle stage leaves the port alone.
  `MCADSW_ASSERT(OneRequestAtATime, !(!port_free && (read || wq_pop)))
  `MCADSW_ASSERT(ReadOrWrite, !(read && wq_pop))
  `MCADSW_ASSERT(QuietWhenIdle, state_q != StIdle || (!req_q && wq_count == '0))

endmodule

`default_nettype wire
