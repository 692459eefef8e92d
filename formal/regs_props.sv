// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Formal properties of the register block's AXI4-Lite slave (rtl/mcadsw_regs.sv), for
// `make formal` (formal/regs.sby). Environment (assumed, the AXI4-Lite master's rules):
// AWVALID, WVALID and ARVALID, once high, stay high with their payload until READY;
// BREADY and RREADY are free; the engine's status inputs are free.
// Asserted (the slave's rules of the AXI4 protocol, A3.2.1 and B1, and the block's own):
//   1. BVALID and RVALID stay high with BRESP, RDATA and RRESP unchanged until READY;
//   2. a write response only for a write whose address and data were both taken, a
//      read response only for a read address taken: never more responses than requests;
//   3. at most two writes in the block (one answered, waiting for BREADY, and one in
//      its one-entry buffers) and one read, and a write whose address and data are in
//      is answered in the next cycle unless the previous response still waits;
//   4. an unmapped or unaligned read answers SLVERR with data 0; a write with SLVERR
//      changes no register.
// Covered: a write answered OKAY and one SLVERR, the address before the data and the
// data before the address, a read answered OKAY and one SLVERR, a read taken in the
// cycle after the previous one's response.
`default_nettype none

module regs_props #(
  localparam int RAB = $clog2(mcadsw_pkg::REG_SPAN)
) (
  input logic           clk_i,
  input logic           rst_ni,
  input logic           s_awvalid_i,
  input logic [RAB-1:0] s_awaddr_i,
  input logic           s_wvalid_i,
  input logic [31:0]    s_wdata_i,
  input logic [3:0]     s_wstrb_i,
  input logic           s_bready_i,
  input logic           s_arvalid_i,
  input logic [RAB-1:0] s_araddr_i,
  input logic           s_rready_i,
  input logic           busy_i,
  input logic           done_i,
  input logic           error_i,
  input logic [7:0]     error_code_i,
  input logic [31:0]    cnt_cycles_i,
  input logic [31:0]    cnt_words_read_i,
  input logic [31:0]    cnt_words_written_i,
  input logic [31:0]    cnt_stall_i
);
  logic        awready, wready, bvalid, arready, rvalid;
  logic [1:0]  bresp, rresp;
  logic [31:0] rdata, base_ly;
  logic [mcadsw_pkg::CFG_BITS-1:0] cfg;
  assign base_ly = cfg[mcadsw_pkg::CFG_BASE_LY +: 32];

  mcadsw_regs dut (
    .clk_i, .rst_ni,
    .s_awvalid_i, .s_awready_o (awready), .s_awaddr_i,
    .s_wvalid_i, .s_wready_o (wready), .s_wdata_i, .s_wstrb_i,
    .s_bvalid_o (bvalid), .s_bready_i, .s_bresp_o (bresp),
    .s_arvalid_i, .s_arready_o (arready), .s_araddr_i,
    .s_rvalid_o (rvalid), .s_rready_i, .s_rdata_o (rdata), .s_rresp_o (rresp),
    .irq_o (),
    .cfg_o (cfg),
    .start_o (), .abort_o (),
    .busy_i, .done_i, .error_i, .error_code_i,
    .cnt_cycles_i, .cnt_words_read_i, .cnt_words_written_i, .cnt_stall_i
  );

  `include "props_reset.svh"

  // ---- Environment: the master holds a request with its payload until READY ----------
  always @(posedge clk_i) if (past_ok && rst_ni) begin
    if ($past(s_awvalid_i && !awready)) assume (s_awvalid_i && s_awaddr_i == $past(s_awaddr_i));
    if ($past(s_wvalid_i && !wready))
      assume (s_wvalid_i && s_wdata_i == $past(s_wdata_i) && s_wstrb_i == $past(s_wstrb_i));
    if ($past(s_arvalid_i && !arready)) assume (s_arvalid_i && s_araddr_i == $past(s_araddr_i));
  end
  always_comb if (!rst_ni) assume (!s_awvalid_i && !s_wvalid_i && !s_arvalid_i);

  // ---- Requests and responses counted --------------------------------------------------
  logic aw_go, w_go, b_go, ar_go, r_go;
  assign aw_go = s_awvalid_i && awready;
  assign w_go  = s_wvalid_i && wready;
  assign b_go  = bvalid && s_bready_i;
  assign ar_go = s_arvalid_i && arready;
  assign r_go  = rvalid && s_rready_i;
  logic [1:0] aw_n_q, w_n_q, ar_n_q;   // taken, not yet answered (at most 2, 2, 1: checked)
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) {aw_n_q, w_n_q, ar_n_q} <= '0;
    else begin
      aw_n_q <= aw_n_q + 2'(aw_go) - 2'(b_go);
      w_n_q  <= w_n_q + 2'(w_go) - 2'(b_go);
      ar_n_q <= ar_n_q + 2'(ar_go) - 2'(r_go);
    end

  // ---- Properties ------------------------------------------------------------------------
  always @(posedge clk_i) if (past_ok && rst_ni) begin
    // 1. Responses held with their payload until READY.
    if ($past(bvalid && !s_bready_i)) assert (bvalid && bresp == $past(bresp));
    if ($past(rvalid && !s_rready_i)) assert (rvalid && rdata == $past(rdata) && rresp == $past(rresp));
    // 3. A write whose address and data are in is answered next cycle unless the previous
    //    response waits.
    if ($past(aw_n_q != 2'd0 && w_n_q != 2'd0 && !bvalid)) assert (bvalid);
    // 4. A read of an unmapped or unaligned offset: SLVERR and 0. (Offsets 0x00 .. REG_SPAN
    //    - 1; the block's own map says which are mapped: here, a misaligned one.)
    if ($past(ar_go && s_araddr_i[1:0] != 2'b00)) assert (rresp == 2'b10 && rdata == '0);
    // 4. A write answered SLVERR changed no register (BASE_LY, at offset 0x20, as a witness).
    if (bvalid && !$past(bvalid) && bresp == 2'b10) assert (base_ly == $past(base_ly));
  end
  always_comb if (rst_ni) begin
    // 2. and 3. No response without its request; at most two writes in the block (one
    //    answered and waiting for BREADY, one in its buffer) and one read.
    //    Exactly: a request taken and not answered is in the block's buffer (its READY
    //    low) or answered and waiting for READY (its response VALID).
    assert (aw_n_q == 2'(!awready) + 2'(bvalid));
    assert (w_n_q == 2'(!wready) + 2'(bvalid));
    assert (ar_n_q == 2'(rvalid));
    // Responses are OKAY or SLVERR only.
    if (bvalid) assert (bresp == 2'b00 || bresp == 2'b10);
    if (rvalid) assert (rresp == 2'b00 || rresp == 2'b10);
  end

  // ---- Covers: what the block must be able to do ------------------------------------------
  logic aw_first_q, w_first_q, r_done_q;   // r_done_q: an R handshake last cycle
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) {aw_first_q, w_first_q, r_done_q} <= '0;
    else begin
      if (aw_go && !w_go && w_n_q == 2'd0) aw_first_q <= 1'b1;
      if (w_go && !aw_go && aw_n_q == 2'd0) w_first_q <= 1'b1;
      r_done_q <= r_go;
      if (b_go) {aw_first_q, w_first_q} <= '0;
    end
  always @(posedge clk_i) if (rst_ni) begin
    WriteOk:            cover (b_go && bresp == 2'b00 && base_ly != '0);
    WriteSlverr:        cover (b_go && bresp == 2'b10);
    AddressBeforeData:  cover (b_go && aw_first_q);
    DataBeforeAddress:  cover (b_go && w_first_q);
    ReadOk:             cover (r_go && rresp == 2'b00 && rdata != '0);
    ReadSlverr:         cover (r_go && rresp == 2'b10);
    BackToBackReads:    cover (r_done_q && ar_go);
  end

endmodule

`default_nettype wire
