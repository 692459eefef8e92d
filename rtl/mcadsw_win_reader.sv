// Window reader: one requestor of the memory controller (Sec. V-E). Streams a
// read window of PLANES 8-bit planes to a census transformer or the weight
// generator in the strip order they take (for each plane, for each strip of 4
// columns, rows 0 .. ROWS-1; byte b = column x0 + 4s + b), reading external
// memory at clamped coordinates (docs/algorithm.md section 2): pixel (x, y) of
// the window is image pixel (clamp(x0 + x), clamp(y0 + y)).
//
// The number of strips is set per window (strips_i, 1 .. STRIPS): a block that
// continues its left neighbour reads only the strips its input buffers do not
// hold yet (partial column reuse, Sec. IV).
//
// A strip word needs the aligned memory words holding its 4 clamped columns:
// one, or two when they straddle a word boundary (only when x0 is not
// word-aligned). Requests run ahead of the responses (up to OUTS in flight,
// responses in order); the response side walks the same sequence to know how
// many responses make each strip word.
`default_nettype none

module mcadsw_win_reader #(
  parameter int ROWS   = 52,             // rows of a strip
  parameter int STRIPS = 13,             // most strips of 4 columns a plane
  parameter int PLANES = 1,              // 1 (luma) or 3 (Y, U, V)
  parameter int OUTS   = 4,              // reads in flight
  parameter int CW     = 12,             // coordinate width (signed)
  parameter int AW     = 32,
  parameter int SB     = $clog2(STRIPS + 1)
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  // Window: started by start_i, configuration stable while busy_o
  input  logic                 start_i,
  input  logic [PLANES*AW-1:0] base_i,     // byte address of pixel (0,0) of each plane
  input  logic [AW-1:0]        stride_i,   // bytes per image row, multiple of 4
  input  logic [CW-1:0]        width_i,
  input  logic [CW-1:0]        height_i,
  input  logic signed [CW:0]   x0_i,       // window origin in image coordinates
  input  logic signed [CW:0]   y0_i,
  input  logic [SB-1:0]        strips_i,   // strips a plane, 1 .. STRIPS
  output logic                 busy_o,
  // Memory controller
  output logic                 req_o,
  output logic [AW-1:0]        addr_o,
  input  logic                 gnt_i,
  input  logic                 rvalid_i,
  input  logic [31:0]          rdata_i,
  // Strip words to the block
  output logic                 pix_valid_o,
  input  logic                 pix_ready_i,
  output logic [31:0]          pix_data_o
);

  localparam int RB = $clog2(ROWS);
  localparam int PB = (PLANES > 1) ? $clog2(PLANES) : 1;
  localparam int OB = $clog2(OUTS + 1);

  if (STRIPS < 1 || 4 * STRIPS >= (1 << CW)) begin : g_bad_param
    mcadsw_error_win_reader_geometry u_error ();
  end

  function automatic int clampi(input int v, input int n);
    clampi = (v < 0) ? 0 : (v > n - 1) ? n - 1 : v;
  endfunction

  // A position in the strip sequence: {done, plane, strip, row}; done past the end.
  localparam int QW = 1 + PB + SB + RB;

  function automatic logic [QW-1:0] next_pos(input logic [QW-1:0] p, input logic [SB-1:0] strips);
    logic          done;
    logic [PB-1:0] plane;
    logic [SB-1:0] strip;
    logic [RB-1:0] row;
    {done, plane, strip, row} = p;
    if (row != RB'(ROWS - 1)) begin
      row = row + RB'(1);
    end else begin
      row = '0;
      if (strip != strips - SB'(1)) begin
        strip = strip + SB'(1);
      end else begin
        strip = '0;
        if (plane == PB'(PLANES - 1)) done = 1'b1;
        else plane = plane + PB'(1);
      end
    end
    next_pos = {done, plane, strip, row};
  endfunction

  logic          busy_q;
  logic [QW-1:0] rq_q, rs_q;         // strip word being requested / assembled
  logic          rq_done, rs_done;
  logic [PB-1:0] rq_plane, rs_plane_unused;
  logic [SB-1:0] rq_strip, rs_strip;
  logic [RB-1:0] rq_row, rs_row_unused;
  assign {rq_done, rq_plane, rq_strip, rq_row} = rq_q;
  assign {rs_done, rs_plane_unused, rs_strip, rs_row_unused} = rs_q;
  logic [QW-1:0] rs_next;
  assign rs_next = next_pos(rs_q, strips_i);
  logic          req_second_q;       // the first of a pair is requested
  logic [OB-1:0] inflight_q;         // requested, response not consumed yet

  // Clamped image column of byte b of strip s.
  function automatic int col_of(input logic [SB-1:0] s, input int b,
                                input logic signed [CW:0] x0, input logic [CW-1:0] w);
    col_of = clampi(32'(x0) + 4*32'(s) + b, 32'(w));
  endfunction

  // ---- Request side -------------------------------------------------------------
  int   rq_y, rq_c0, rq_c3;
  logic rq_pair;
  assign rq_y    = clampi(32'(y0_i) + 32'(rq_row), 32'(height_i));
  assign rq_c0   = col_of(rq_strip, 0, x0_i, width_i);
  assign rq_c3   = col_of(rq_strip, 3, x0_i, width_i);
  assign rq_pair = (rq_c0 / 4) != (rq_c3 / 4);

  // The response buffer is the pipeline itself: stop requesting when OUTS
  // responses could be waiting for the block.
  assign req_o  = busy_q && !rq_done && inflight_q != OB'(OUTS);
  assign addr_o = base_i[32'(rq_plane)*AW +: AW] + AW'(rq_y) * stride_i +
                  AW'(4 * ((req_second_q ? rq_c3 : rq_c0) / 4));

  // ---- Response side ---------------------------------------------------------------
  // Responses wait in a small FIFO until the block takes the strip word.
  logic [OUTS*32-1:0] fifo_q;
  logic [OB-1:0]      fcount_q;
  logic               pop;
  int   rs_c0;
  logic rs_pair;
  assign rs_c0   = col_of(rs_strip, 0, x0_i, width_i);
  assign rs_pair = (rs_c0 / 4) != (col_of(rs_strip, 3, x0_i, width_i) / 4);

  // A strip word is ready when its one or two responses are available.
  logic [31:0] head, second;
  assign head   = fifo_q[31:0];
  assign second = fifo_q[63:32];
  assign pix_valid_o = busy_q && !rs_done &&
                       (rs_pair ? fcount_q >= OB'(2) : fcount_q >= OB'(1));
  for (genvar b = 0; b < 4; b++) begin : g_byte
    int c;
    assign c = col_of(rs_strip, b, x0_i, width_i);
    assign pix_data_o[b*8 +: 8] = (rs_pair && c / 4 != rs_c0 / 4) ? second[(c % 4)*8 +: 8]
                                                                    : head[(c % 4)*8 +: 8];
  end
  assign pop = pix_valid_o && pix_ready_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q       <= 1'b0;
      rq_q         <= '0;
      rs_q         <= '0;
      req_second_q <= 1'b0;
      inflight_q   <= '0;
      fifo_q       <= '0;
      fcount_q     <= '0;
    end else begin
      if (start_i && !busy_q) begin
        busy_q       <= 1'b1;
        rq_q         <= '0;
        rs_q         <= '0;
        req_second_q <= 1'b0;
      end
      if (req_o && gnt_i) begin
        if (rq_pair && !req_second_q) begin
          req_second_q <= 1'b1;
        end else begin
          req_second_q <= 1'b0;
          rq_q         <= next_pos(rq_q, strips_i);
        end
      end
      // FIFO: push the response, pop one or two words for a strip word.
      begin
        logic [OUTS*32-1:0] f;
        logic [OB-1:0]      n;
        f = fifo_q;
        n = fcount_q;
        if (pop) begin
          if (rs_pair) begin
            f = f >> 64;
            n = n - OB'(2);
          end else begin
            f = f >> 32;
            n = n - OB'(1);
          end
        end
        if (rvalid_i) begin
          f[32'(n)*32 +: 32] = rdata_i;
          n = n + OB'(1);
        end
        fifo_q   <= f;
        fcount_q <= n;
      end
      inflight_q <= inflight_q + OB'(req_o && gnt_i) - (pop ? (rs_pair ? OB'(2) : OB'(1)) : OB'(0));
      if (pop) begin
        rs_q <= rs_next;
        if (rs_next[QW-1]) busy_q <= 1'b0;
      end
    end
  end

  assign busy_o = busy_q;

`ifndef SYNTHESIS
  // Invariants (docs/architecture.md section 9), checked in simulation.
  always @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      assert (!(rvalid_i && !pop && fcount_q == OB'(OUTS)))
        else $error("win_reader: response FIFO overflow");
      assert (!(rvalid_i && inflight_q == '0))
        else $error("win_reader: read data with no request of this reader in flight");
    end
  end
`endif

endmodule

`default_nettype wire
