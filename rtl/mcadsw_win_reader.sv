// Window reader: one requestor of the memory controller (Sec. V-E). Streams a
// read window of PLANES 8-bit planes to a census transformer or the weight
// generator in the strip order they take (for each plane, for each strip of 4
// columns, rows 0 .. ROWS-1; byte b = column 4s + b), reading external memory
// at clamped coordinates (docs/algorithm.md section 2): pixel (x, y) of the
// window is image pixel (clamp(x0 + x), clamp(y0 + y)).
//
// A strip word needs the aligned memory words holding its 4 clamped columns:
// one, or two when they straddle a word boundary. Requests run ahead of the
// responses (up to OUTS in flight, responses in order); the response side
// walks the same sequence to know how many responses make each strip word.
`default_nettype none

module mcadsw_win_reader #(
  parameter int ROWS   = 52,             // rows of a strip
  parameter int STRIPS = 13,             // strips of 4 columns per plane
  parameter int PLANES = 1,              // 1 (luma) or 3 (Y, U, V)
  parameter int OUTS   = 4,              // reads in flight
  parameter int CW     = 12,             // coordinate width (signed)
  parameter int AW     = 32
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

  localparam int TOTAL = PLANES * STRIPS * ROWS;
  localparam int NB    = $clog2(TOTAL + 1);
  localparam int OB    = $clog2(OUTS + 1);

  // Position of strip word n: plane, strip, row.
  function automatic int plane_of(input int n); plane_of = n / (STRIPS * ROWS); endfunction
  function automatic int strip_of(input int n); strip_of = (n / ROWS) % STRIPS; endfunction
  function automatic int row_of(input int n);   row_of = n % ROWS;              endfunction

  function automatic int clampi(input int v, input int n);
    clampi = (v < 0) ? 0 : (v > n - 1) ? n - 1 : v;
  endfunction

  // Clamped image column of byte b of strip s, and the memory word of a column.
  function automatic int col_of(input int s, input int b, input logic signed [CW:0] x0,
                                input logic [CW-1:0] w);
    col_of = clampi(32'(x0) + 4*s + b, 32'(w));
  endfunction

  logic          busy_q;
  logic [NB-1:0] req_n_q, rsp_n_q;   // strip word being requested / assembled
  logic          req_second_q;       // the first of a pair is requested
  logic [OB-1:0] inflight_q;         // requested, response not consumed yet

  // ---- Request side -------------------------------------------------------------
  int  rq_p, rq_s, rq_y, rq_c0, rq_c3;
  logic rq_pair;
  assign rq_p    = plane_of(32'(req_n_q));
  assign rq_s    = strip_of(32'(req_n_q));
  assign rq_y    = clampi(32'(y0_i) + row_of(32'(req_n_q)), 32'(height_i));
  assign rq_c0   = col_of(rq_s, 0, x0_i, width_i);
  assign rq_c3   = col_of(rq_s, 3, x0_i, width_i);
  assign rq_pair = (rq_c0 / 4) != (rq_c3 / 4);

  // The response buffer is the pipeline itself: stop requesting when OUTS
  // responses could be waiting for the block.
  assign req_o  = busy_q && req_n_q != NB'(TOTAL) && inflight_q != OB'(OUTS);
  assign addr_o = base_i[rq_p*AW +: AW] + AW'(rq_y) * stride_i +
                  AW'(4 * ((req_second_q ? rq_c3 : rq_c0) / 4));

  // ---- Response side ---------------------------------------------------------------
  // Responses wait in a small FIFO until the block takes the strip word.
  logic [OUTS*32-1:0] fifo_q;
  logic [OB-1:0]      fcount_q;
  logic               pop;
  int  rs_s, rs_c0;
  logic rs_pair;
  assign rs_s    = strip_of(32'(rsp_n_q));
  assign rs_c0   = col_of(rs_s, 0, x0_i, width_i);
  assign rs_pair = (rs_c0 / 4) != (col_of(rs_s, 3, x0_i, width_i) / 4);

  // A strip word is ready when its one or two responses are available.
  logic [31:0] head, second;
  assign head   = fifo_q[31:0];
  assign second = fifo_q[63:32];
  assign pix_valid_o = busy_q && rsp_n_q != NB'(TOTAL) &&
                       (rs_pair ? fcount_q >= OB'(2) : fcount_q >= OB'(1));
  for (genvar b = 0; b < 4; b++) begin : g_byte
    int c;
    assign c = col_of(rs_s, b, x0_i, width_i);
    assign pix_data_o[b*8 +: 8] = (rs_pair && c / 4 != rs_c0 / 4) ? second[(c % 4)*8 +: 8]
                                                                    : head[(c % 4)*8 +: 8];
  end
  assign pop = pix_valid_o && pix_ready_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q       <= 1'b0;
      req_n_q      <= '0;
      rsp_n_q      <= '0;
      req_second_q <= 1'b0;
      inflight_q   <= '0;
      fifo_q       <= '0;
      fcount_q     <= '0;
    end else begin
      if (start_i && !busy_q) begin
        busy_q       <= 1'b1;
        req_n_q      <= '0;
        rsp_n_q      <= '0;
        req_second_q <= 1'b0;
      end
      if (req_o && gnt_i) begin
        if (rq_pair && !req_second_q) begin
          req_second_q <= 1'b1;
        end else begin
          req_second_q <= 1'b0;
          req_n_q      <= req_n_q + NB'(1);
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
        rsp_n_q <= rsp_n_q + NB'(1);
        if (rsp_n_q == NB'(TOTAL - 1)) busy_q <= 1'b0;
      end
    end
  end

  assign busy_o = busy_q;

endmodule

`default_nettype wire
