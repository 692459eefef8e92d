// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_axi: the IP as vendor tools see it. A Verilog-2001 wrapper of mcadsw_top with
// the port names Vivado's IP packager and block design infer as interfaces (AXI4-Lite
// slave s_axi_*, AXI4 master m_axi_*, clock aclk, reset aresetn, interrupt), described
// by the IP-XACT component component.xml (generated: flow/ipxact.py). It adds no logic
// of its own: the ports are renamed, the AXI4-Lite protection inputs are accepted and
// not used, and the master's cache and protection outputs are constants.
//
//   - aclk clocks everything; aresetn is the active-low reset, asserted asynchronously
//     and to be released synchronously to aclk (Vivado's proc_sys_reset does).
//   - s_axi_*: the registers (docs/registers.md), 32-bit data, 8 address bits (offsets
//     0x00 .. 0xFC; higher address bits are the interconnect's). Every response OKAY but
//     for an unmapped offset (SLVERR).
//   - m_axi_*: the frame memory, 32-bit data, INCR bursts of up to 16 beats, one ID:
//     ARID/AWID are one bit, always 0, and RID/BID are not read (the responses of one ID
//     come in order, which the master relies on); ARCACHE/AWCACHE 4'b0011 (normal,
//     non-cacheable, bufferable: what Xilinx recommends for a DMA master), ARPROT/AWPROT
//     3'b000 (unprivileged, secure, data).
//   - interrupt: level, active high, while STATUS.DONE or STATUS.ERROR is set and enabled
//     in IRQ_ENABLE; cleared by writing 1 to the STATUS bit.
// The engine's configuration (DMAX, PAR, target, rectifier) is the generated package
// rtl/mcadsw_pkg.sv's (HWCONFIG reads it back), not a parameter of this wrapper.
`default_nettype none

module mcadsw_axi (
  input  wire        aclk,
  input  wire        aresetn,
  // AXI4-Lite slave: the registers
  input  wire [7:0]  s_axi_awaddr,
  input  wire [2:0]  s_axi_awprot,
  input  wire        s_axi_awvalid,
  output wire        s_axi_awready,
  input  wire [31:0] s_axi_wdata,
  input  wire [3:0]  s_axi_wstrb,
  input  wire        s_axi_wvalid,
  output wire        s_axi_wready,
  output wire [1:0]  s_axi_bresp,
  output wire        s_axi_bvalid,
  input  wire        s_axi_bready,
  input  wire [7:0]  s_axi_araddr,
  input  wire [2:0]  s_axi_arprot,
  input  wire        s_axi_arvalid,
  output wire        s_axi_arready,
  output wire [31:0] s_axi_rdata,
  output wire [1:0]  s_axi_rresp,
  output wire        s_axi_rvalid,
  input  wire        s_axi_rready,
  // AXI4 master: the frame memory
  output wire [0:0]  m_axi_arid,
  output wire [31:0] m_axi_araddr,
  output wire [7:0]  m_axi_arlen,
  output wire [2:0]  m_axi_arsize,
  output wire [1:0]  m_axi_arburst,
  output wire [3:0]  m_axi_arcache,
  output wire [2:0]  m_axi_arprot,
  output wire        m_axi_arvalid,
  input  wire        m_axi_arready,
  input  wire [0:0]  m_axi_rid,
  input  wire [31:0] m_axi_rdata,
  input  wire [1:0]  m_axi_rresp,
  input  wire        m_axi_rlast,
  input  wire        m_axi_rvalid,
  output wire        m_axi_rready,
  output wire [0:0]  m_axi_awid,
  output wire [31:0] m_axi_awaddr,
  output wire [7:0]  m_axi_awlen,
  output wire [2:0]  m_axi_awsize,
  output wire [1:0]  m_axi_awburst,
  output wire [3:0]  m_axi_awcache,
  output wire [2:0]  m_axi_awprot,
  output wire        m_axi_awvalid,
  input  wire        m_axi_awready,
  output wire [31:0] m_axi_wdata,
  output wire [3:0]  m_axi_wstrb,
  output wire        m_axi_wlast,
  output wire        m_axi_wvalid,
  input  wire        m_axi_wready,
  input  wire [0:0]  m_axi_bid,
  input  wire [1:0]  m_axi_bresp,
  input  wire        m_axi_bvalid,
  output wire        m_axi_bready,
  // level, active high
  output wire        interrupt
);

  assign m_axi_arid    = 1'b0;
  assign m_axi_awid    = 1'b0;
  assign m_axi_arcache = 4'b0011;
  assign m_axi_awcache = 4'b0011;
  assign m_axi_arprot  = 3'b000;
  assign m_axi_awprot  = 3'b000;

  // The protection inputs: every access is served alike; the response IDs: one ID.
  /* verilator lint_off UNUSEDSIGNAL */
  wire [7:0] unused_in = {s_axi_awprot, s_axi_arprot, m_axi_rid, m_axi_bid};
  /* verilator lint_on UNUSEDSIGNAL */

  mcadsw_top #(.RAB(8)) u_top (
    .clk_i       (aclk),
    .rst_ni      (aresetn),
    .s_awvalid_i (s_axi_awvalid), .s_awready_o (s_axi_awready), .s_awaddr_i  (s_axi_awaddr),
    .s_wvalid_i  (s_axi_wvalid),  .s_wready_o  (s_axi_wready),  .s_wdata_i   (s_axi_wdata),
    .s_wstrb_i   (s_axi_wstrb),
    .s_bvalid_o  (s_axi_bvalid),  .s_bready_i  (s_axi_bready),  .s_bresp_o   (s_axi_bresp),
    .s_arvalid_i (s_axi_arvalid), .s_arready_o (s_axi_arready), .s_araddr_i  (s_axi_araddr),
    .s_rvalid_o  (s_axi_rvalid),  .s_rready_i  (s_axi_rready),  .s_rdata_o   (s_axi_rdata),
    .s_rresp_o   (s_axi_rresp),
    .irq_o       (interrupt),
    .m_arvalid_o (m_axi_arvalid), .m_arready_i (m_axi_arready), .m_araddr_o  (m_axi_araddr),
    .m_arlen_o   (m_axi_arlen),   .m_arsize_o  (m_axi_arsize),  .m_arburst_o (m_axi_arburst),
    .m_rvalid_i  (m_axi_rvalid),  .m_rready_o  (m_axi_rready),  .m_rdata_i   (m_axi_rdata),
    .m_rresp_i   (m_axi_rresp),   .m_rlast_i   (m_axi_rlast),
    .m_awvalid_o (m_axi_awvalid), .m_awready_i (m_axi_awready), .m_awaddr_o  (m_axi_awaddr),
    .m_awlen_o   (m_axi_awlen),   .m_awsize_o  (m_axi_awsize),  .m_awburst_o (m_axi_awburst),
    .m_wvalid_o  (m_axi_wvalid),  .m_wready_i  (m_axi_wready),  .m_wdata_o   (m_axi_wdata),
    .m_wstrb_o   (m_axi_wstrb),   .m_wlast_o   (m_axi_wlast),
    .m_bvalid_i  (m_axi_bvalid),  .m_bready_o  (m_axi_bready),  .m_bresp_i   (m_axi_bresp)
  );

endmodule

`default_nettype wire
