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
// column lo or width-1, inside the strip's own word. One read per strip word.
//
// Mirrored (the right view as base, docs/architecture.md section 12), the
// window's columns are the pass's: pass column c is image column
// width - 1 - c (width a multiple of 4), and the image occupies the pass's
// columns lo .. width - 1. An aligned strip word is then an aligned memory
// word with its bytes in reverse order.
// Requests run ahead of the responses (up to OUTS in flight, responses in
// order).
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
  // Window: started by start_i, which takes x0_i, y0_i and strips_i; base_i,
  // stride_i, width_i and height_i are stable while busy_o
  input  logic                 start_i,
  input  logic [PLANES*AW-1:0] base_i,     // byte address of pixel (0,0) of each plane
  input  logic [AW-1:0]        stride_i,   // bytes per image row, multiple of 4
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

  function automatic int clampi(input int v, input int lo, input int n);
    clampi = (v < lo) ? lo : (v > n - 1) ? n - 1 : v;
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

  // The window origin and strip count, registered at start_i: the address
  // arithmetic starts from flip-flops, not from the block arithmetic in the top
  // (that path to the external address was critical, docs/architecture.md section 10).
  logic signed [CW:0]   x0_q, y0_q;
  logic [SB-1:0]        strips_q;

  logic          busy_q;
  logic [QW-1:0] rq_q, rs_q;         // strip word being requested / assembled
  logic          rq_done, rs_done;
  logic [PB-1:0] rs_plane_unused;
  logic [SB-1:0] rs_strip;
  logic [RB-1:0] rs_row_unused;
  assign rq_done = rq_q[QW-1];       // the request side needs only done; addresses come from pos_q
  assign {rs_done, rs_plane_unused, rs_strip, rs_row_unused} = rs_q;
  logic [QW-1:0] rs_next;
  assign rs_next = next_pos(rs_q, strips_q);
  logic [OB-1:0] inflight_q;         // requested, response not consumed yet

  // Clamped column of byte b of strip s.
  function automatic int col_of(input logic [SB-1:0] s, input int b,
                                input logic signed [CW:0] x0, input logic [1:0] lo,
                                input logic [CW-1:0] w);
    col_of = clampi(32'(x0) + 4*32'(s) + b, 32'(lo), 32'(w));
  endfunction

  // ---- Request side -------------------------------------------------------------
  // The request address is a register (addr_q), loaded a cycle ahead: in the
  // cycle after start_i for the first strip word (no request in that cycle), then
  // at each grant for the next one. Its position (pos_q) carries the parts of
  // its address as registers, updated step by step, so the address is a sum of
  // three registers and no multiplier lies on the per-request path:
  //   yoff_q = clamp(y0 + row) * stride (the product only at start_i, then
  //            + stride while the clamped row moves, back to yoff0_q at row 0);
  //   xoff_q = the image column of the strip word's memory word, from the
  //            unclamped pass column xabs_q = x0 + 4 strip.
  logic          addr_ok_q;          // addr_q holds the address of rq_q
  logic [AW-1:0] addr_q, addr_next;
  logic [QW-1:0] pos_q, pos_next;    // the position whose address is loaded next
  logic          p_done_unused;
  logic [PB-1:0] p_plane;
  logic [SB-1:0] p_strip_unused;
  logic [RB-1:0] p_row;
  logic [AW-1:0] yoff_q, yoff0_q;
  logic signed [CW+1:0] yabs_q;      // y0 + row, unclamped
  logic signed [CW+1:0] xabs_q;      // x0 + 4 strip, unclamped
  logic [CW-1:0] xoff_q;
  assign {p_done_unused, p_plane, p_strip_unused, p_row} = pos_q;
  assign pos_next = next_pos(pos_q, strips_q);
  assign addr_next = base_i[32'(p_plane)*AW +: AW] + yoff_q + AW'(xoff_q);

  // The first image column of the memory word holding pass column x (clamped).
  function automatic logic [CW-1:0] mem_col(input logic signed [CW+1:0] x, input logic [1:0] lo,
                                            input logic [CW-1:0] w, input logic mirror);
    logic [CW-1:0] word;
    word = CW'(4 * (clampi(32'(x), 32'(lo), 32'(w)) / 4));
    mem_col = mirror ? w - word - CW'(4) : word;
  endfunction
  function automatic logic [AW-1:0] row_off(input logic signed [CW+1:0] y,
                                            input logic [CW-1:0] h, input logic [AW-1:0] stride);
    row_off = AW'(clampi(32'(y), 0, 32'(h))) * stride;
  endfunction
  logic advance;                     // addr_q takes addr_next: pos_q moves on
  assign advance = (busy_q && !addr_ok_q) || (req_o && gnt_i);

  // The response buffer is the pipeline itself: stop requesting when OUTS
  // responses could be waiting for the block.
  assign req_o  = busy_q && addr_ok_q && !rq_done && inflight_q != OB'(OUTS);
  assign addr_o = addr_q;

  // ---- Response side ---------------------------------------------------------------
  // Responses wait in a small FIFO until the block takes the strip word.
  logic [OUTS*32-1:0] fifo_q;
  logic [OB-1:0]      fcount_q;
  logic               pop;
  // A strip word is ready when its response is; byte b is column
  // clamp(x0 + 4s + b), i.e. byte b, or the edge column's byte where clamped.
  logic [31:0] head;
  assign head        = fifo_q[31:0];
  assign pix_valid_o = busy_q && !rs_done && fcount_q != '0;
  for (genvar b = 0; b < 4; b++) begin : g_byte
    int c;
    assign c = col_of(rs_strip, b, x0_q, lo_i, width_i);
    assign pix_data_o[b*8 +: 8] = head[(mirror_i ? 3 - c % 4 : c % 4)*8 +: 8];
  end
  assign pop = pix_valid_o && pix_ready_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q       <= 1'b0;
      addr_ok_q    <= 1'b0;
      addr_q       <= '0;
      pos_q        <= '0;
      yoff_q       <= '0;
      yoff0_q      <= '0;
      yabs_q       <= '0;
      xabs_q       <= '0;
      xoff_q       <= '0;
      x0_q         <= '0;
      y0_q         <= '0;
      strips_q     <= '0;
      rq_q         <= '0;
      rs_q         <= '0;
      inflight_q   <= '0;
      fifo_q       <= '0;
      fcount_q     <= '0;
    end else begin
      if (start_i && !busy_q) begin
        busy_q       <= 1'b1;
        addr_ok_q    <= 1'b0;
        x0_q         <= x0_i;
        y0_q         <= y0_i;
        strips_q     <= strips_i;
        rq_q         <= '0;
        rs_q         <= '0;
        pos_q        <= '0;
        yoff_q       <= row_off((CW + 2)'(y0_i), height_i, stride_i);
        yoff0_q      <= row_off((CW + 2)'(y0_i), height_i, stride_i);
        yabs_q       <= (CW + 2)'(y0_i);
        xabs_q       <= (CW + 2)'(x0_i);
        xoff_q       <= mem_col((CW + 2)'(x0_i), lo_i, width_i, mirror_i);
      end
      if (busy_q && !addr_ok_q) addr_ok_q <= 1'b1;
      if (req_o && gnt_i) rq_q <= next_pos(rq_q, strips_q);
      if (advance) begin
        addr_q <= addr_next;
        pos_q  <= pos_next;
        if (pos_next[RB-1:0] == '0) begin
          // Row 0 of the next plane or strip.
          yoff_q <= yoff0_q;
          yabs_q <= (CW + 2)'(y0_q);
        end else begin
          // The clamped row moves only while y0 + row + 1 lies inside the image.
          if (yabs_q >= 0 && yabs_q < $signed({2'b00, height_i}) - (CW + 2)'(1))
            yoff_q <= yoff_q + stride_i;
          yabs_q <= yabs_q + (CW + 2)'(1);
        end
        if (p_row == RB'(ROWS - 1) && p_plane == PB'(PLANES - 1)) begin
          // The next strip.
          xabs_q <= xabs_q + (CW + 2)'(4);
          xoff_q <= mem_col(xabs_q + (CW + 2)'(4), lo_i, width_i, mirror_i);
        end
      end
      // FIFO: push the response, pop the strip word.
      begin
        logic [OUTS*32-1:0] f;
        logic [OB-1:0]      n;
        f = fifo_q;
        n = fcount_q;
        if (pop) begin
          f = f >> 32;
          n = n - OB'(1);
        end
        if (rvalid_i) begin
          f[32'(n)*32 +: 32] = rdata_i;
          n = n + OB'(1);
        end
        fifo_q   <= f;
        fcount_q <= n;
      end
      inflight_q <= inflight_q + OB'(req_o && gnt_i) - OB'(pop);
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
      assert (!(start_i && !busy_q && x0_i[1:0] != 2'b00))
        else $error("win_reader: window origin %0d is not word-aligned", x0_i);
    end
  end
`endif

endmodule

`default_nettype wire
