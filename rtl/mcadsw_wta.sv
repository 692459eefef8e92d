// Winner-takes-all (paper Fig. 12, right): keeps the smallest final cost and
// its disparity for each of the BLOCK pixels of the row being aggregated,
// HAGG pixels a cycle. Disparities arrive in increasing order and only a
// strictly smaller cost replaces the best, so ties keep the smallest d.
// On the last disparity the winners leave, HAGG a cycle.
`default_nettype none

module mcadsw_wta #(
  parameter int BLOCK = mcadsw_pkg::BLOCK,
  parameter int HAGG  = mcadsw_pkg::HAGG,
  parameter int FB    = mcadsw_pkg::FCOST_BITS,
  parameter int DB    = mcadsw_pkg::DISP_BITS,
  parameter int GB    = $clog2(BLOCK / HAGG)
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               valid_i,
  input  logic               first_i,    // d == 0: take the cost unconditionally
  input  logic               last_i,     // d == D - 1: emit the winners
  input  logic [DB-1:0]      d_i,
  input  logic [GB-1:0]      grp_i,      // pixels HAGG*grp .. HAGG*grp + HAGG - 1
  input  logic [HAGG*FB-1:0] fc_i,
  output logic               valid_o,
  output logic [GB-1:0]      grp_o,
  output logic [HAGG*DB-1:0] disp_o
);

  logic [BLOCK*FB-1:0] best_cost_q;
  logic [BLOCK*DB-1:0] best_d_q;
  logic [HAGG*FB-1:0]  win_cost;
  logic [HAGG*DB-1:0]  win_d;

  for (genvar m = 0; m < HAGG; m++) begin : g_cmp
    logic [FB-1:0] old_cost;
    logic [DB-1:0] old_d;
    assign old_cost = best_cost_q[(32'(grp_i)*HAGG + m)*FB +: FB];
    assign old_d    = best_d_q[(32'(grp_i)*HAGG + m)*DB +: DB];
    logic take;
    assign take = first_i || fc_i[m*FB +: FB] < old_cost;
    assign win_cost[m*FB +: FB] = take ? fc_i[m*FB +: FB] : old_cost;
    assign win_d[m*DB +: DB]    = take ? d_i : old_d;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      best_cost_q <= '0;
      best_d_q    <= '0;
      valid_o     <= 1'b0;
      grp_o       <= '0;
      disp_o      <= '0;
    end else begin
      valid_o <= valid_i && last_i;
      if (valid_i) begin
        best_cost_q[32'(grp_i)*HAGG*FB +: HAGG*FB] <= win_cost;
        best_d_q[32'(grp_i)*HAGG*DB +: HAGG*DB]    <= win_d;
        grp_o  <= grp_i;
        disp_o <= win_d;
      end
    end
  end

endmodule

`default_nettype wire
