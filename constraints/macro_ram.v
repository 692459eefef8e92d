// On-chip memory macro, a black box for synthesis: every memory the RTL infers
// (census, weight and row buffers, input buffers) becomes one instance, so the
// gate count excludes memories as the paper's Table III does and the report
// lists their bits apart. Ports as Yosys' $mem_v2 (asynchronous or clocked read
// ports, per-bit write enables, an asynchronous reset of a clocked read
// port's output to RD_ARST_VALUE); the parameters say which.
(* blackbox *)
module MCADSW_RAM #(
  parameter SIZE = 4,
  parameter ABITS = 2,
  parameter WIDTH = 8,
  parameter RD_PORTS = 1,
  parameter WR_PORTS = 1,
  parameter RD_CLK_ENABLE = 1'b1,
  parameter RD_ARST_VALUE = 1'b0
) (
  input  [RD_PORTS-1:0]       RD_CLK,
  input  [RD_PORTS-1:0]       RD_EN,
  input  [RD_PORTS-1:0]       RD_ARST,
  input  [RD_PORTS*ABITS-1:0] RD_ADDR,
  output [RD_PORTS*WIDTH-1:0] RD_DATA,
  input  [WR_PORTS-1:0]       WR_CLK,
  input  [WR_PORTS*WIDTH-1:0] WR_EN,
  input  [WR_PORTS*ABITS-1:0] WR_ADDR,
  input  [WR_PORTS*WIDTH-1:0] WR_DATA
);
endmodule
