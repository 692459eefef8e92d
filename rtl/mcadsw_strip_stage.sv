// Word buffer at the front of the input buffers (Fig. 10 / Fig. 11: "the input
// data are first packed into data words"), shared by the census transformer
// and the weight generator. The memory side delivers a window in strips of 4
// columns, one 32-bit word a row (byte b = column 4s + b); this stage collects
// the first ROWS - 1 words of a strip, and when the last row arrives presents
// the 4 complete column words, so the input buffers only ever write whole words.
`default_nettype none

module mcadsw_strip_stage #(
  parameter int ROWS = mcadsw_pkg::BLOCK_COLS,  // rows of a strip
  parameter int RB   = $clog2(ROWS)
) (
  input  logic                 clk_i,
  input  logic                 wr_i,     // a word is accepted
  input  logic [RB-1:0]        row_i,    // its row in the strip
  input  logic [31:0]          data_i,
  output logic                 last_o,   // the last row: cols_o is complete
  output logic [4*ROWS*8-1:0]  cols_o    // column b at b*ROWS*8, row y at byte y
);

  logic [(ROWS-1)*32-1:0] stage_q;

  always_ff @(posedge clk_i) begin
    if (wr_i && row_i != RB'(ROWS - 1)) stage_q[32'(row_i)*32 +: 32] <= data_i;
  end

  assign last_o = wr_i && row_i == RB'(ROWS - 1);

  for (genvar b = 0; b < 4; b++) begin : g_col
    for (genvar y = 0; y < ROWS - 1; y++) begin : g_row
      assign cols_o[(b*ROWS + y)*8 +: 8] = stage_q[y*32 + b*8 +: 8];
    end
    assign cols_o[(b*ROWS + ROWS - 1)*8 +: 8] = data_i[b*8 +: 8];
  end

endmodule

`default_nettype wire
