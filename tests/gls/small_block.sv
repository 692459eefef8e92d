// A small block for tests/gls/small_gls.sh: arithmetic like the engine's
// configuration check (a 32 x 11 multiplier, 33-bit compares) and a register
// with asynchronous reset, synthesised by the project's Yosys/abc flow and
// simulated as gates against itself as RTL. The register is not fed by the
// product: that variant hid the Verilator bug the test checks for.
module gls_small (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic [31:0] a_i,
  input  logic [10:0] b_i,
  input  logic [31:0] c_i,
  output logic [32:0] size_o,
  output logic        overlap_o,
  output logic [32:0] size_q
);
  assign size_o    = 33'(a_i) * 33'(b_i);
  assign overlap_o = ({1'b0, c_i} < {1'b0, a_i} + size_o) && ({1'b0, a_i} < {1'b0, c_i} + size_o);
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) size_q <= '0;
    else size_q <= {32'(b_i) ^ size_q[31:0], overlap_o};
endmodule
