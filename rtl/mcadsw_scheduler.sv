// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Block scheduler (paper Secs. IV, V-F, Fig. 15). Walks the 18 x 18 output
// blocks in raster order. Block p is prepared (census left and right, weights:
// three window readers and three blocks) into bank p % 2 while block p - 1 is
// aggregated from the other bank; a bank is refilled only after the block that
// used it has left the cost aggregator. Aggregation of a block issues its row
// jobs (only rows inside the image; partial blocks at the right and bottom
// edges compute the whole row and the depth FIFO drops what is outside), each
// once the weight generator has made that row's weights (wrow_ready_i).
`default_nettype none

module mcadsw_scheduler #(
  parameter int BLOCK  = mcadsw_pkg::BLOCK,
  parameter int RADIUS = mcadsw_pkg::RADIUS,
  parameter int COLS   = mcadsw_pkg::BLOCK_COLS,   // 48
  parameter int CW     = 12,
  parameter int AW     = 32
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               start_i,        // configuration below is valid and stable
  input  logic [CW-1:0]      width_i,
  input  logic [CW-1:0]      height_i,
  input  logic [AW-1:0]      out_base_i,
  input  logic [AW-1:0]      stride_i,
  output logic               busy_o,
  output logic               done_o,         // one cycle at the end of the frame
  // Preparation of a block: window origins, bank, in-image bounds
  output logic               prep_start_o,   // one cycle
  output logic               prep_bank_o,
  output logic signed [CW:0] prep_x0_o,      // left window origin (bx - 15)
  output logic signed [CW:0] prep_y0_o,      // by - 15
  output logic               prep_cont_o,    // the block continues the previous one (bx > 0)
  output logic [4:0]         prep_rows_o,    // its rows inside the image (1 .. BLOCK)
  input  logic [2:0]         prep_done_i,    // a preparer finished (one cycle each: the
                                             // census left and right, the weights)
  output logic               agg_active_o,   // a block is in the aggregator (the one before
                                             // the block being prepared, while preparing)
  // Cost aggregator
  output logic               agg_bank_o,
  output logic               job_valid_o,
  input  logic               job_ready_i,
  input  logic               wrow_ready_i,   // the weights of the next row job are made
  output logic [4:0]         job_row_o,
  output logic [5:0]         job_last_col_o,
  input  logic               agg_busy_i,
  // Depth FIFO
  output logic               desc_push_o,
  output logic [AW-1:0]      desc_addr_o,
  output logic [CW-1:0]      desc_x_o,
  output logic [4:0]         desc_n_o,
  input  logic               fifo_space_i,
  input  logic               fifo_empty_i
);

  // Block coordinates of the block being prepared (p) and aggregated (a).
  logic [CW-1:0] pbx_q, pby_q, abx_q, aby_q;
  logic          pbank_q, abank_q;
  logic          prep_busy_q, prep_valid_q;    // preparing / prepared, not yet aggregated
  logic          prep_more_q;                  // blocks left to prepare
  logic          agg_busy_q, agg_draining_q;
  logic [4:0]    arow_q, arows_q;
  logic          run_q;

  // Next block in raster order after (bx, by); last when it would start past the image.
  function automatic logic [2*CW:0] next_block(input logic [CW-1:0] bx, input logic [CW-1:0] by,
                                               input logic [CW-1:0] w, input logic [CW-1:0] h);
    logic [CW:0] nx, ny;
    nx = {1'b0, bx} + (CW + 1)'(BLOCK);
    ny = {1'b0, by};
    if (nx >= {1'b0, w}) begin
      nx = '0;
      ny = ny + (CW + 1)'(BLOCK);
    end
    next_block = {ny >= {1'b0, h}, nx[CW-1:0], ny[CW-1:0]};
  endfunction

  logic          p_last;
  logic [CW-1:0] p_nx, p_ny;
  assign {p_last, p_nx, p_ny} = next_block(pbx_q, pby_q, width_i, height_i);

  // Preparation may start when its bank is free: the other bank's block is
  // being aggregated (or none is), and no prepared block is waiting.
  logic prep_go;
  assign prep_go = run_q && prep_more_q && !prep_busy_q && !prep_valid_q;
  assign prep_start_o = prep_go;

  // The block is prepared when all three preparers have finished since its start.
  logic [2:0] pdone_q;
  logic       prep_done;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni)      pdone_q <= '0;
    else if (prep_go) pdone_q <= '0;
    else              pdone_q <= pdone_q | prep_done_i;
  end
  assign prep_done = &pdone_q;
  assign prep_bank_o  = pbank_q;
  assign prep_x0_o    = $signed({1'b0, pbx_q}) - (CW + 1)'(RADIUS);
  assign prep_y0_o    = $signed({1'b0, pby_q}) - (CW + 1)'(RADIUS);
  assign prep_cont_o  = pbx_q != '0;
  assign prep_rows_o  = ({1'b0, height_i} - {1'b0, pby_q} > (CW + 1)'(BLOCK)) ?
                        5'(BLOCK) : 5'(height_i - pby_q);

  // Aggregation of the prepared block starts when the aggregator has drained.
  logic agg_go;
  assign agg_go = run_q && prep_valid_q && !agg_busy_q;

  // Row jobs.
  logic [CW:0] y_abs;
  assign y_abs       = {1'b0, aby_q} + (CW + 1)'(arow_q);
  assign job_valid_o = agg_busy_q && !agg_draining_q && fifo_space_i && wrow_ready_i;
  assign job_row_o   = arow_q;
  assign agg_bank_o  = abank_q;
  logic [CW:0] last_col;  // last Ev column inside the image: W - 1 - (bx - 15)
  assign last_col = {1'b0, width_i} - (CW + 1)'(1) - {1'b0, abx_q} + (CW + 1)'(RADIUS);
  assign job_last_col_o = (last_col > (CW + 1)'(COLS - 1)) ? 6'(COLS - 1) : last_col[5:0];
  assign desc_push_o = job_valid_o && job_ready_i;
  assign desc_addr_o = out_base_i + AW'(y_abs) * stride_i;
  assign desc_x_o    = abx_q;
  logic [CW:0] cols_left;  // image columns from the block's first
  assign cols_left = {1'b0, width_i} - {1'b0, abx_q};
  assign desc_n_o  = (cols_left > (CW + 1)'(BLOCK)) ? 5'(BLOCK) : cols_left[4:0];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      run_q          <= 1'b0;
      pbx_q          <= '0;
      pby_q          <= '0;
      abx_q          <= '0;
      aby_q          <= '0;
      pbank_q        <= 1'b0;
      abank_q        <= 1'b0;
      prep_busy_q    <= 1'b0;
      prep_valid_q   <= 1'b0;
      prep_more_q    <= 1'b0;
      agg_busy_q     <= 1'b0;
      agg_draining_q <= 1'b0;
      arow_q         <= '0;
      arows_q        <= '0;
      done_o         <= 1'b0;
    end else begin
      done_o <= 1'b0;
      if (start_i && !run_q) begin
        run_q       <= 1'b1;
        pbx_q       <= '0;
        pby_q       <= '0;
        pbank_q     <= 1'b0;
        prep_more_q <= 1'b1;
      end
      if (prep_go) prep_busy_q <= 1'b1;
      if (prep_busy_q && prep_done && !prep_go) begin
        prep_busy_q  <= 1'b0;
        prep_valid_q <= 1'b1;
      end
      if (agg_go) begin
        // Hand the prepared block to the aggregator and move preparation on.
        prep_valid_q   <= 1'b0;
        agg_busy_q     <= 1'b1;
        agg_draining_q <= 1'b0;
        abx_q          <= pbx_q;
        aby_q          <= pby_q;
        abank_q        <= pbank_q;
        arow_q         <= '0;
        arows_q        <= prep_rows_o;
        pbx_q          <= p_nx;
        pby_q          <= p_ny;
        pbank_q        <= !pbank_q;
        prep_more_q    <= !p_last;
      end
      if (desc_push_o) begin
        arow_q <= arow_q + 5'd1;
        if (arow_q + 5'd1 == arows_q) agg_draining_q <= 1'b1;
      end
      if (agg_busy_q && agg_draining_q && !agg_busy_i && !desc_push_o) agg_busy_q <= 1'b0;
      if (run_q && !prep_more_q && !prep_busy_q && !prep_valid_q && !agg_busy_q && !agg_go &&
          fifo_empty_i) begin
        run_q  <= 1'b0;
        done_o <= 1'b1;
      end
    end
  end

  assign busy_o       = run_q;
  assign agg_active_o = agg_busy_q;

endmodule

`default_nettype wire
