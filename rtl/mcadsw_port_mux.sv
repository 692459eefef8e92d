// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The engine's external memory port and its four owners (docs/blocks/engine.md 1):
// the rectify pass and the mark step in their frame-controller states (rect_sel_i,
// mark_sel_i), the LR post stage from the end of the second pass until the next
// start (pass_post_i, when neither of those holds the port), and the passes' memory
// controller otherwise. The owner's request, write data and burst length reach the
// port; the grant and the read data valid reach the owner only. The frame
// controller hands the port over only between an owner's transactions (it waits for
// the writes to be answered), so no transaction spans two owners; the assertions
// below check that a request comes only from the owner.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_port_mux #(
  parameter int AW = 32
) (
  input  logic          clk_i,           // the assertions'
  input  logic          rst_ni,
  // Who owns the port (the frame controller's)
  input  logic          rect_sel_i,
  input  logic          mark_sel_i,
  input  logic          pass_post_i,
  // The rectify pass
  input  logic          rect_req_i,
  input  logic          rect_we_i,
  input  logic [3:0]    rect_be_i,
  input  logic [AW-1:0] rect_addr_i,
  input  logic [2:0]    rect_len_i,
  input  logic [31:0]   rect_wdata_i,
  output logic          rect_gnt_o,
  output logic          rect_rvalid_o,
  // The mark step
  input  logic          mark_req_i,
  input  logic          mark_we_i,
  input  logic [3:0]    mark_be_i,
  input  logic [AW-1:0] mark_addr_i,
  input  logic [2:0]    mark_len_i,
  input  logic [31:0]   mark_wdata_i,
  output logic          mark_gnt_o,
  output logic          mark_rvalid_o,
  // The post stage (single beats)
  input  logic          post_req_i,
  input  logic          post_we_i,
  input  logic [3:0]    post_be_i,
  input  logic [AW-1:0] post_addr_i,
  input  logic [31:0]   post_wdata_i,
  output logic          post_gnt_o,
  output logic          post_rvalid_o,
  // The passes' memory controller
  input  logic          eng_req_i,
  input  logic          eng_we_i,
  input  logic [3:0]    eng_be_i,
  input  logic [AW-1:0] eng_addr_i,
  input  logic [3:0]    eng_len_i,
  input  logic [31:0]   eng_wdata_i,
  output logic          eng_gnt_o,
  output logic          eng_rvalid_o,
  // The port (mcadsw_engine's mem_*; read data go to every owner)
  output logic          mem_req_o,
  input  logic          mem_gnt_i,
  output logic          mem_we_o,
  output logic [3:0]    mem_be_o,
  output logic [AW-1:0] mem_addr_o,
  output logic [3:0]    mem_len_o,
  output logic [31:0]   mem_wdata_o,
  input  logic          mem_rvalid_i
);

  logic post_sel, eng_sel;
  assign post_sel = pass_post_i && !rect_sel_i && !mark_sel_i;
  assign eng_sel  = !rect_sel_i && !mark_sel_i && !post_sel;

  assign mem_req_o   = rect_sel_i ? rect_req_i : mark_sel_i ? mark_req_i : post_sel ? post_req_i : eng_req_i;
  assign mem_we_o    = rect_sel_i ? rect_we_i : mark_sel_i ? mark_we_i : post_sel ? post_we_i : eng_we_i;
  assign mem_be_o    = rect_sel_i ? rect_be_i : mark_sel_i ? mark_be_i : post_sel ? post_be_i : eng_be_i;
  assign mem_addr_o  = rect_sel_i ? rect_addr_i : mark_sel_i ? mark_addr_i : post_sel ? post_addr_i : eng_addr_i;
  assign mem_len_o   = rect_sel_i ? {1'b0, rect_len_i} : mark_sel_i ? {1'b0, mark_len_i} :
                       post_sel ? 4'd0 : eng_len_i;
  assign mem_wdata_o = rect_sel_i ? rect_wdata_i : mark_sel_i ? mark_wdata_i :
                       post_sel ? post_wdata_i : eng_wdata_i;

  assign rect_gnt_o    = mem_gnt_i && rect_sel_i;
  assign rect_rvalid_o = mem_rvalid_i && rect_sel_i;
  assign mark_gnt_o    = mem_gnt_i && mark_sel_i;
  assign mark_rvalid_o = mem_rvalid_i && mark_sel_i;
  assign post_gnt_o    = mem_gnt_i && post_sel;
  assign post_rvalid_o = mem_rvalid_i && post_sel;
  assign eng_gnt_o     = mem_gnt_i && eng_sel;
  assign eng_rvalid_o  = mem_rvalid_i && eng_sel;

  // ---- Invariants: a request only from the port's owner, one owner ------------------------
  `MCADSW_ASSERT(PortOwnedByPostStage, !post_req_i || post_sel)
  `MCADSW_ASSERT(PortOwnedByPasses, !eng_req_i || eng_sel)
  `MCADSW_ASSERT(PortOwnedByRectifier, !rect_req_i || rect_sel_i)
  `MCADSW_ASSERT(PortOwnedByMarkStep, !mark_req_i || mark_sel_i)
  `MCADSW_ASSERT(OnePortOwner, !(rect_sel_i && mark_sel_i))

endmodule

`default_nettype wire
