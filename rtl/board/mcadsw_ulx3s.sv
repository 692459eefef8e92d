// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The board shell the FPGA flow places the SoC top in (flow/ecp5.py soc; ULX3S 85F,
// LFE5U-85F-6BG381C; pins in constraints/ulx3s.lpf). It is a place-and-route shell,
// not a demonstration: the SoC's NIN input and NOUT output bits (about 100 and 170) are
// more than the board's free pins, so
//   - the engine clock comes from the board's 25 MHz oscillator through the ECP5's PLL
//     (EHXPLLL: 25 MHz x CLKFB_DIV / CLKI_DIV, 75 MHz by default), and the reset from
//     button FIRE1 (active high), synchronised and held until the PLL locks;
//   - every input of mcadsw_top is a bit of a shift register loaded serially from pin
//     ser_i (the FTDI's TXD), so no input is a constant the synthesis could propagate;
//   - every output of mcadsw_top is folded into a multiple-input signature register (each
//     cycle: shift by one and XOR all outputs in) whose last bit drives pin ser_o (the
//     FTDI's RXD), so every output bit reaches a pin and none of the logic that drives it
//     can be removed; the interrupt and STATUS-like outputs also drive the LEDs.
// flow/ecp5.py soc lists the cells of each block of the placed netlist, so that nothing
// optimised away goes unnoticed. A board demonstration would put a UART or JTAG bridge
// on the AXI4-Lite port and an SDRAM controller on the AXI4 master (docs/results.md).
`default_nettype none

module mcadsw_ulx3s #(
  // PLL: 25 MHz x CLKFB_DIV / CLKI_DIV; the VCO (that x CLKOP_DIV) within 400 .. 800 MHz.
  parameter int CLKI_DIV  = 1,
  parameter int CLKFB_DIV = 3,
  parameter int CLKOP_DIV = 8
) (
  input  wire       clk_25mhz,
  input  wire       btn_fire1,   // reset, active high
  input  wire       ser_i,       // FTDI TXD: the inputs' shift register
  output wire       ser_o,       // FTDI RXD: the outputs' signature
  output wire [7:0] led
);

  localparam int RAB  = $clog2(mcadsw_pkg::REG_SPAN);
  localparam int NIN  = 2 * RAB + 32 + 4 + 6 + 2 + 32 + 2 + 1 + 2 + 2;   // data inputs
  localparam int NOUT = 2 + 1 + 2 + 1 + 1 + 32 + 2 + 1                  // AXI4-Lite, irq
                      + 1 + 32 + 8 + 3 + 2 + 1                          // AR, R
                      + 1 + 32 + 8 + 3 + 2 + 1 + 32 + 4 + 1 + 1;        // AW, W, B

  // ---- Clock and reset -------------------------------------------------------------
  wire clk, locked;
  (* FREQUENCY_PIN_CLKI = "25" *)
  (* ICP_CURRENT = "12" *) (* LPF_RESISTOR = "8" *) (* MFG_ENABLE_FILTEROPAMP = "1" *)
  (* MFG_GMCREF_SEL = "2" *)
  EHXPLLL #(
    .PLLRST_ENA("DISABLED"), .INTFB_WAKE("DISABLED"), .STDBY_ENABLE("DISABLED"),
    .DPHASE_SOURCE("DISABLED"), .OUTDIVIDER_MUXA("DIVA"), .OUTDIVIDER_MUXB("DIVB"),
    .OUTDIVIDER_MUXC("DIVC"), .OUTDIVIDER_MUXD("DIVD"),
    .CLKI_DIV(CLKI_DIV), .CLKOP_ENABLE("ENABLED"), .CLKOP_DIV(CLKOP_DIV), .CLKOP_CPHASE(CLKOP_DIV / 2 - 1),
    .CLKOP_FPHASE(0), .FEEDBK_PATH("CLKOP"), .CLKFB_DIV(CLKFB_DIV)
  ) u_pll (
    .RST(1'b0), .STDBY(1'b0), .CLKI(clk_25mhz), .CLKOP(clk), .CLKFB(clk),
    .PHASESEL0(1'b0), .PHASESEL1(1'b0), .PHASEDIR(1'b1), .PHASESTEP(1'b1), .PHASELOADREG(1'b1),
    .PLLWAKESYNC(1'b0), .ENCLKOP(1'b0), .LOCK(locked)
  );

  // Reset: asserted at once (the PLL unlocked or the button pressed), released two
  // clock edges after both end (flip-flops power up at 0: in reset).
  wire arst_n = locked & ~btn_fire1;
  reg  rst_meta, rst_n;
  always @(posedge clk or negedge arst_n)
    if (!arst_n) {rst_n, rst_meta} <= 2'b00;
    else         {rst_n, rst_meta} <= {rst_meta, 1'b1};

  // ---- Inputs: a serial-in shift register ------------------------------------------
  reg [NIN-1:0] in_q;
  always @(posedge clk) in_q <= {in_q[NIN-2:0], ser_i};

  wire [RAB-1:0] s_awaddr, s_araddr;
  wire [31:0]    s_wdata, m_rdata;
  wire [3:0]     s_wstrb;
  wire           s_awvalid, s_wvalid, s_bready, s_arvalid, s_rready, m_arready;
  wire [1:0]     m_rresp, m_bresp;
  wire           m_rvalid, m_rlast, m_awready, m_wready, m_bvalid;
  assign {s_awaddr, s_araddr, s_wdata, s_wstrb, s_awvalid, s_wvalid, s_bready, s_arvalid,
          s_rready, m_arready, m_rvalid, m_rlast, m_rdata, m_rresp, m_awready, m_wready,
          m_bvalid, m_bresp} = in_q;

  // ---- The SoC ---------------------------------------------------------------------
  wire        s_awready, s_wready, s_bvalid, s_arready, s_rvalid, irq;
  wire [1:0]  s_bresp, s_rresp, m_arburst, m_awburst;
  wire [31:0] s_rdata, m_araddr, m_awaddr, m_wdata;
  wire [7:0]  m_arlen, m_awlen;
  wire [2:0]  m_arsize, m_awsize;
  wire [3:0]  m_wstrb;
  wire        m_arvalid, m_rready, m_awvalid, m_wvalid, m_wlast, m_bready;

  mcadsw_top u_soc (
    .clk_i(clk), .rst_ni(rst_n),
    .s_awvalid_i(s_awvalid), .s_awready_o(s_awready), .s_awaddr_i(s_awaddr),
    .s_wvalid_i(s_wvalid), .s_wready_o(s_wready), .s_wdata_i(s_wdata), .s_wstrb_i(s_wstrb),
    .s_bvalid_o(s_bvalid), .s_bready_i(s_bready), .s_bresp_o(s_bresp),
    .s_arvalid_i(s_arvalid), .s_arready_o(s_arready), .s_araddr_i(s_araddr),
    .s_rvalid_o(s_rvalid), .s_rready_i(s_rready), .s_rdata_o(s_rdata), .s_rresp_o(s_rresp),
    .irq_o(irq),
    .m_arvalid_o(m_arvalid), .m_arready_i(m_arready), .m_araddr_o(m_araddr), .m_arlen_o(m_arlen),
    .m_arsize_o(m_arsize), .m_arburst_o(m_arburst),
    .m_rvalid_i(m_rvalid), .m_rready_o(m_rready), .m_rdata_i(m_rdata), .m_rresp_i(m_rresp),
    .m_rlast_i(m_rlast),
    .m_awvalid_o(m_awvalid), .m_awready_i(m_awready), .m_awaddr_o(m_awaddr), .m_awlen_o(m_awlen),
    .m_awsize_o(m_awsize), .m_awburst_o(m_awburst),
    .m_wvalid_o(m_wvalid), .m_wready_i(m_wready), .m_wdata_o(m_wdata), .m_wstrb_o(m_wstrb),
    .m_wlast_o(m_wlast), .m_bvalid_i(m_bvalid), .m_bready_o(m_bready), .m_bresp_i(m_bresp)
  );

  // ---- Outputs: a multiple-input signature register --------------------------------
  wire [NOUT-1:0] outs = {s_awready, s_wready, s_bresp, s_bvalid, s_arready, s_rvalid, s_rdata,
                          s_rresp, irq, m_arvalid, m_araddr, m_arlen, m_arsize, m_arburst, m_rready,
                          m_awvalid, m_awaddr, m_awlen, m_awsize, m_awburst, m_wvalid, m_wdata,
                          m_wstrb, m_wlast, m_bready};
  reg [NOUT-1:0] sig_q;
  always @(posedge clk) sig_q <= {sig_q[NOUT-2:0], sig_q[NOUT-1]} ^ outs;
  assign ser_o = sig_q[NOUT-1];
  assign led   = {irq, m_arvalid, m_awvalid, m_wvalid, m_rready, s_rvalid, locked, rst_n};

endmodule

`default_nettype wire
