// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Rectifier: loads a tile's source rectangle of one raw plane into a tile buffer's four
// banks (docs/blocks/rectifier.md 5).
//
// At start_i: the plane (base, layout, stride), the rectangle (x0 a multiple of 4, y0,
// cols 1 .. RECT_BUF_W, rows 1 .. RECT_BUF_H). Raster planes are read row by row, column-
// tiled planes strip by strip (a strip's rows are consecutive words there), each line of
// words in bursts of up to 8 that never cross a 4 KiB boundary, on a read port in the
// engine's protocol (docs/memory_map.md: request held until granted, data in order).
// The line's first address needs a product (y0 x stride, or x0 / 4 x tile stride): a
// shift-and-add over 12 cycles at the start. Each word returned is written into two
// banks in one cycle: buffer row ly, word column k (pixels 4k .. 4k + 3 of the row,
// relative to x0): bank {ly[0], 0} gets {pixel 4k + 2, pixel 4k}, bank {ly[0], 1} gets
// {pixel 4k + 3, pixel 4k + 1}, both at word (ly >> 1) * RECT_BUF_W / 4 + k, the layout
// mcadsw_rect_sample reads. done_o pulses with the last word's write.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_rect_load #(
  parameter int CW  = 12,
  parameter int BW  = mcadsw_rect_pkg::RECT_BUF_W,
  parameter int BH  = mcadsw_rect_pkg::RECT_BUF_H,
  parameter int BAW = $clog2(BH / 2 * BW / 4)
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              start_i,
  input  logic [31:0]       base_i,
  input  logic              tiled_i,               // column-tiled plane: stride_i is the tile stride
  input  logic [31:0]       stride_i,
  input  logic [CW-1:0]     x0_i,                  // a multiple of 4
  input  logic [CW-1:0]     y0_i,
  input  logic [6:0]        cols_i,                // 1 .. BW
  input  logic [5:0]        rows_i,                // 1 .. BH
  output logic              busy_o,
  output logic              done_o,
  // Read port (docs/memory_map.md)
  output logic              mem_req_o,
  input  logic              mem_gnt_i,
  output logic [31:0]       mem_addr_o,
  output logic [2:0]        mem_len_o,             // words - 1
  input  logic              mem_rvalid_i,
  input  logic [31:0]       mem_rdata_i,
  // Bank writes: banks {p, 0} and {p, 1} of row parity p = bank_row_par_o
  output logic              bank_we_o,
  output logic              bank_row_par_o,
  output logic [BAW-1:0]    bank_waddr_o,
  output logic [15:0]       bank_wdata_even_o,     // to bank {p, 0}
  output logic [15:0]       bank_wdata_odd_o       // to bank {p, 1}
);
  localparam int XB = $clog2(BW / 4);

  typedef enum logic [1:0] {StIdle, StMul, StReq, StWait} state_e;
  state_e         state_q;
  logic           tiled_q;
  logic [31:0]    stride_q, line_q, addr_q, prod_q, mcand_q;
  logic [CW-1:0]  mplier_q;
  logic [3:0]     mstep_q;
  logic [5:0]     nlines_q, li_req_q, li_rsp_q;   // lines: rows (raster) or strips (tiled)
  logic [5:0]     llen_q, wi_req_q, wi_rsp_q;     // words a line
  logic [31:0]    add_q;                          // x0 (raster) or 4 y0 (tiled)

  // The next burst: up to 8 words, not past the line's end nor a 4 KiB boundary.
  logic [5:0]  left;
  logic [10:0] to_4k;                              // words to the next 4 KiB boundary
  logic [3:0]  burst;
  assign left  = llen_q - wi_req_q;
  assign to_4k = 11'd1024 - 11'(addr_q[11:2]);
  always_comb begin
    burst = 4'd8;
    if (left < 6'd8) burst = 4'(left);
    if (to_4k < 11'(burst)) burst = 4'(to_4k);
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      tiled_q <= 1'b0; stride_q <= '0; line_q <= '0; addr_q <= '0; prod_q <= '0; mcand_q <= '0;
      mplier_q <= '0; mstep_q <= '0; nlines_q <= '0; li_req_q <= '0; llen_q <= '0; wi_req_q <= '0;
      add_q <= '0; mem_req_o <= 1'b0; mem_addr_o <= '0; mem_len_o <= '0;
    end else begin
      case (state_q)
        StIdle: if (start_i) begin
          tiled_q  <= tiled_i;
          stride_q <= stride_i;
          // Raster: lines are rows of (cols + 3) / 4 words; tiled: strips of rows words.
          nlines_q <= tiled_i ? 6'((7'(cols_i) + 7'd3) >> 2) : rows_i;
          llen_q   <= tiled_i ? rows_i : 6'((7'(cols_i) + 7'd3) >> 2);
          mcand_q  <= stride_i;
          mplier_q <= tiled_i ? x0_i >> 2 : y0_i;
          prod_q   <= base_i;
          add_q    <= tiled_i ? 32'({y0_i, 2'b00}) : 32'(x0_i);
          mstep_q  <= '0;
          state_q  <= StMul;
        end
        StMul: begin                               // base + m x stride, one bit a cycle
          if (mplier_q[0]) prod_q <= prod_q + mcand_q;
          mplier_q <= mplier_q >> 1;
          mcand_q  <= mcand_q << 1;
          mstep_q  <= mstep_q + 4'd1;
          if (mstep_q == 4'(CW - 1)) state_q <= StWait;
          li_req_q <= '0;
          wi_req_q <= '0;
        end
        StWait: begin                              // the first line's address
          line_q  <= prod_q + add_q;
          addr_q  <= prod_q + add_q;
          state_q <= StReq;
        end
        StReq: begin
          if (!mem_req_o || mem_gnt_i) begin
            if (li_req_q < nlines_q) begin
              mem_req_o  <= 1'b1;
              mem_addr_o <= addr_q;
              mem_len_o  <= 3'(burst - 4'd1);
              if (6'(burst) == left) begin            // the line's last burst
                li_req_q <= li_req_q + 6'd1;
                wi_req_q <= '0;
                line_q   <= line_q + stride_q;
                addr_q   <= line_q + stride_q;
              end else begin
                wi_req_q <= wi_req_q + 6'(burst);
                addr_q   <= addr_q + {26'b0, burst, 2'b00};
              end
            end else begin
              mem_req_o <= 1'b0;
            end
          end
          if (done_o) state_q <= StIdle;
        end
        default: state_q <= StIdle;
      endcase
    end
  end

  // Responses: line li_rsp, word wi_rsp -> buffer row and word column.
  logic [5:0] ly, k;
  assign ly = tiled_q ? wi_rsp_q : li_rsp_q;
  assign k  = tiled_q ? li_rsp_q : wi_rsp_q;
  logic unused_lk;                                  // ly < BH and k < BW / 4
  assign unused_lk = ^{ly[5:BAW-XB+1], k[5:XB]};
  logic last_rsp;
  assign last_rsp = li_rsp_q == nlines_q - 6'd1 && wi_rsp_q == llen_q - 6'd1;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      li_rsp_q <= '0; wi_rsp_q <= '0; done_o <= 1'b0;
      bank_we_o <= 1'b0; bank_row_par_o <= 1'b0; bank_waddr_o <= '0; bank_wdata_even_o <= '0;
      bank_wdata_odd_o <= '0;
    end else begin
      done_o    <= 1'b0;
      bank_we_o <= 1'b0;
      if (state_q == StIdle && start_i) begin
        li_rsp_q <= '0;
        wi_rsp_q <= '0;
      end else if (mem_rvalid_i && state_q != StIdle) begin
        bank_we_o         <= 1'b1;
        bank_row_par_o    <= ly[0];
        bank_waddr_o      <= {ly[BAW-XB:1], k[XB-1:0]};
        bank_wdata_even_o <= {mem_rdata_i[23:16], mem_rdata_i[7:0]};
        bank_wdata_odd_o  <= {mem_rdata_i[31:24], mem_rdata_i[15:8]};
        if (wi_rsp_q == llen_q - 6'd1) begin
          wi_rsp_q <= '0;
          li_rsp_q <= li_rsp_q + 6'd1;
        end else begin
          wi_rsp_q <= wi_rsp_q + 6'd1;
        end
        done_o <= last_rsp;
      end
    end
  end

  assign busy_o = state_q != StIdle;

  `MCADSW_ASSUME(start_when_idle, !(start_i && busy_o))
  `MCADSW_ASSUME(rect_fits, !(start_i && state_q == StIdle) ||
                 (cols_i >= 7'd1 && cols_i <= 7'(BW) && rows_i >= 6'd1 && rows_i <= 6'(BH) && x0_i[1:0] == 2'b00))
  `MCADSW_ASSUME(no_stray_data, !(mem_rvalid_i && state_q == StIdle))
  `MCADSW_ASSERT(burst_in_4k, !mem_req_o || 13'(mem_addr_o[11:0]) + 13'({mem_len_o, 2'b00}) < 13'd4096)
endmodule

`default_nettype wire
