// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// MCADSW stereo-depth IP, the top a user instantiates: the engine core (mcadsw_engine) behind the
// AXI4-Lite register block (mcadsw_regs, docs/registers.md) with its interrupt,
// and its memory port on an AXI4 master (mcadsw_axi_master).
//
// A frame ends early, with DONE and ERROR, when a read or write response is
// SLVERR or DECERR (error code 13 or 14) or CTRL.ABORT is written while busy
// (code 15): the engine is held in reset (drain_q) while the AXI4 master
// completes the transactions in flight (the writes already granted go out,
// read data is dropped), then released; STATUS.BUSY stays high until then.
// The first cause is reported. The counters restart from 0 with the engine.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_top #(
  parameter int DMAX = mcadsw_pkg::DMAX,
  parameter int PAR  = mcadsw_pkg::PAR,
  parameter int RAB  = $clog2(mcadsw_pkg::REG_SPAN)
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  // AXI4-Lite slave: registers
  input  logic            s_awvalid_i,
  output logic            s_awready_o,
  input  logic [RAB-1:0]  s_awaddr_i,
  input  logic            s_wvalid_i,
  output logic            s_wready_o,
  input  logic [31:0]     s_wdata_i,
  input  logic [3:0]      s_wstrb_i,
  output logic            s_bvalid_o,
  input  logic            s_bready_i,
  output logic [1:0]      s_bresp_o,
  input  logic            s_arvalid_i,
  output logic            s_arready_o,
  input  logic [RAB-1:0]  s_araddr_i,
  output logic            s_rvalid_o,
  input  logic            s_rready_i,
  output logic [31:0]     s_rdata_o,
  output logic [1:0]      s_rresp_o,
  output logic            irq_o,
  // AXI4 master: frame memory (one ID, 32-bit data)
  output logic            m_arvalid_o,
  input  logic            m_arready_i,
  output logic [31:0]     m_araddr_o,
  output logic [7:0]      m_arlen_o,
  output logic [2:0]      m_arsize_o,
  output logic [1:0]      m_arburst_o,
  input  logic            m_rvalid_i,
  output logic            m_rready_o,
  input  logic [31:0]     m_rdata_i,
  input  logic [1:0]      m_rresp_i,
  input  logic            m_rlast_i,
  output logic            m_awvalid_o,
  input  logic            m_awready_i,
  output logic [31:0]     m_awaddr_o,
  output logic [7:0]      m_awlen_o,
  output logic [2:0]      m_awsize_o,
  output logic [1:0]      m_awburst_o,
  output logic            m_wvalid_o,
  input  logic            m_wready_i,
  output logic [31:0]     m_wdata_o,
  output logic [3:0]      m_wstrb_o,
  output logic            m_wlast_o,
  input  logic            m_bvalid_i,
  output logic            m_bready_o,
  input  logic [1:0]      m_bresp_i
);

  localparam int AW   = 32;
  localparam int CW   = 12;
  localparam int NB   = $clog2(DMAX + 1);
  localparam int NTHR = mcadsw_pkg::WTHRESHOLDS;
  localparam int DCB  = mcadsw_pkg::COLOR_DIST_BITS;

  logic [mcadsw_pkg::CFG_BITS-1:0] cfg;   // the configuration bundle (mcadsw_pkg::CFG_*)
  logic                start, abort, busy, done, error;
  logic [7:0]          error_code;
  logic                eng_busy, eng_done, eng_error;
  logic [7:0]          eng_code;
  logic [31:0]         cnt_cycles, cnt_words_read, cnt_words_written, cnt_stall;

  mcadsw_regs #(.AW(AW), .CW(CW), .DMAX(DMAX), .PAR(PAR), .NTHR(NTHR), .DCB(DCB),
                .RAB(RAB)) u_regs (
    .clk_i, .rst_ni,
    .s_awvalid_i, .s_awready_o, .s_awaddr_i, .s_wvalid_i, .s_wready_o, .s_wdata_i, .s_wstrb_i,
    .s_bvalid_o, .s_bready_i, .s_bresp_o, .s_arvalid_i, .s_arready_o, .s_araddr_i,
    .s_rvalid_o, .s_rready_i, .s_rdata_o, .s_rresp_o, .irq_o,
    .cfg_o (cfg),
    .start_o (start), .abort_o (abort),
    .busy_i (busy), .done_i (done), .error_i (error), .error_code_i (error_code),
    .cnt_cycles_i (cnt_cycles), .cnt_words_read_i (cnt_words_read),
    .cnt_words_written_i (cnt_words_written), .cnt_stall_i (cnt_stall)
  );

  // ---- Early end: a response error or an abort ---------------------------------------------
  logic       drain_q, ended_q, bus_idle, wr_idle, rd_err, wr_err, eng_rst_n;
  logic [mcadsw_pkg::ERR_BITS-1:0] end_code_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      drain_q    <= 1'b0;
      ended_q    <= 1'b0;
      end_code_q <= '0;
    end else begin
      if (!drain_q && (rd_err || wr_err || (abort && eng_busy))) begin
        drain_q    <= 1'b1;
        end_code_q <= rd_err ? mcadsw_pkg::ErrReadResponse :
                      wr_err ? mcadsw_pkg::ErrWriteResponse : mcadsw_pkg::ErrAborted;
      end else if (drain_q && bus_idle) begin
        drain_q <= 1'b0;
        ended_q <= 1'b1;
      end
      if (start && !busy) ended_q <= 1'b0;
    end
  end
  // The engine's reset: the system's, or the drain (a register, so glitch-free).
  assign eng_rst_n  = rst_ni && !drain_q;
  assign busy       = eng_busy || drain_q;
  assign done       = eng_done || ended_q;
  assign error      = eng_error || ended_q;
  assign error_code = ended_q ? 8'(end_code_q) : eng_code;

  logic          mem_req, mem_gnt, mem_we, mem_rvalid;
  logic [3:0]    mem_be, mem_len;
  logic [AW-1:0] mem_addr;
  logic [31:0]   mem_wdata, mem_rdata;

  mcadsw_engine #(.AW(AW), .CW(CW), .DMAX(DMAX), .PAR(PAR), .NB(NB), .NTHR(NTHR), .DCB(DCB)) u_engine (
    .clk_i, .rst_ni (eng_rst_n),
    .cfg_i (cfg),
    .start_i (start),
    .busy_o (eng_busy), .done_o (eng_done), .error_o (eng_error), .error_code_o (eng_code),
    .cnt_cycles_o (cnt_cycles), .cnt_words_read_o (cnt_words_read),
    .cnt_words_written_o (cnt_words_written), .cnt_stall_o (cnt_stall),
    .mem_req_o (mem_req), .mem_gnt_i (mem_gnt), .mem_we_o (mem_we), .mem_be_o (mem_be),
    .mem_addr_o (mem_addr), .mem_len_o (mem_len), .mem_wdata_o (mem_wdata),
    .mem_rvalid_i (mem_rvalid),
    .mem_rdata_i (mem_rdata), .mem_wr_idle_i (wr_idle)
  );

  mcadsw_axi_master #(.AW(AW)) u_axi_master (
    .clk_i, .rst_ni,
    .mem_req_i (mem_req), .mem_gnt_o (mem_gnt), .mem_we_i (mem_we), .mem_be_i (mem_be),
    .mem_addr_i (mem_addr), .mem_len_i (mem_len), .mem_wdata_i (mem_wdata),
    .mem_rvalid_o (mem_rvalid),
    .mem_rdata_o (mem_rdata),
    .drain_i (drain_q), .wr_idle_o (wr_idle), .idle_o (bus_idle), .rd_err_o (rd_err),
    .wr_err_o (wr_err),
    .m_arvalid_o, .m_arready_i, .m_araddr_o, .m_arlen_o, .m_arsize_o, .m_arburst_o,
    .m_rvalid_i, .m_rready_o, .m_rdata_i, .m_rresp_i, .m_rlast_i,
    .m_awvalid_o, .m_awready_i, .m_awaddr_o, .m_awlen_o, .m_awsize_o, .m_awburst_o,
    .m_wvalid_o, .m_wready_i, .m_wdata_o, .m_wstrb_o, .m_wlast_o,
    .m_bvalid_i, .m_bready_o, .m_bresp_i
  );

  // ---- Invariants -------------------------------------------------------------------------
  // A frame ended early reports a bus error or an abort; the engine is held in
  // reset, and the IP busy, until the AXI4 master has nothing in flight.
  `MCADSW_ASSERT(EndedWithABusCode, !ended_q || end_code_q == mcadsw_pkg::ErrReadResponse ||
                                    end_code_q == mcadsw_pkg::ErrWriteResponse ||
                                    end_code_q == mcadsw_pkg::ErrAborted)
  `MCADSW_ASSERT(DrainKeepsBusy, !drain_q || busy)
  `MCADSW_ASSERT(EndedNotBusy, !ended_q || !eng_busy)

endmodule

`default_nettype wire
