// MCADSW engine for an SoC (issue 19): the engine (mcadsw_top) behind the
// AXI4-Lite register block (mcadsw_regs, docs/registers.md) with its interrupt.
// The external memory port is still the engine's 32-bit request/grant port
// (docs/memory_map.md); the AXI4 master that replaces it is the next step of
// issue 19.
`default_nettype none

module mcadsw_axi_top #(
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
  // External memory (mcadsw_top's port)
  output logic            mem_req_o,
  input  logic            mem_gnt_i,
  output logic            mem_we_o,
  output logic [3:0]      mem_be_o,
  output logic [31:0]     mem_addr_o,
  output logic [31:0]     mem_wdata_o,
  input  logic            mem_rvalid_i,
  input  logic [31:0]     mem_rdata_i
);

  localparam int AW   = 32;
  localparam int CW   = 12;
  localparam int NB   = $clog2(DMAX + 1);
  localparam int NTHR = mcadsw_pkg::WTHRESHOLDS;
  localparam int DCB  = mcadsw_pkg::COLOR_DIST_BITS;

  logic [AW-1:0]       base_ly, base_lu, base_lv, base_ry, base_ru, base_rv, base_out, base_dl,
                       base_dr, base_mask, stride, out_stride;
  logic [2:0]          mode;
  logic [7:0]          lr_t;
  logic [CW-1:0]       width, height;
  logic [NB-1:0]       disp;
  logic [NTHR*DCB-1:0] thr;
  logic                start, busy, done, error;
  logic [3:0]          error_code;
  logic [31:0]         cnt_cycles, cnt_words_read, cnt_words_written, cnt_stall;

  mcadsw_regs #(.AW(AW), .CW(CW), .DMAX(DMAX), .PAR(PAR), .NB(NB), .NTHR(NTHR), .DCB(DCB),
                .RAB(RAB)) u_regs (
    .clk_i, .rst_ni,
    .s_awvalid_i, .s_awready_o, .s_awaddr_i, .s_wvalid_i, .s_wready_o, .s_wdata_i, .s_wstrb_i,
    .s_bvalid_o, .s_bready_i, .s_bresp_o, .s_arvalid_i, .s_arready_o, .s_araddr_i,
    .s_rvalid_o, .s_rready_i, .s_rdata_o, .s_rresp_o, .irq_o,
    .cfg_base_ly_o (base_ly), .cfg_base_lu_o (base_lu), .cfg_base_lv_o (base_lv),
    .cfg_base_ry_o (base_ry), .cfg_base_ru_o (base_ru), .cfg_base_rv_o (base_rv),
    .cfg_base_out_o (base_out), .cfg_base_dl_o (base_dl), .cfg_base_dr_o (base_dr),
    .cfg_base_mask_o (base_mask), .cfg_stride_o (stride), .cfg_out_stride_o (out_stride),
    .cfg_mode_o (mode), .cfg_lr_t_o (lr_t), .cfg_width_o (width), .cfg_height_o (height),
    .cfg_disp_o (disp), .cfg_thr_o (thr), .start_o (start),
    .busy_i (busy), .done_i (done), .error_i (error), .error_code_i (error_code),
    .cnt_cycles_i (cnt_cycles), .cnt_words_read_i (cnt_words_read),
    .cnt_words_written_i (cnt_words_written), .cnt_stall_i (cnt_stall)
  );

  mcadsw_top #(.AW(AW), .CW(CW), .DMAX(DMAX), .PAR(PAR), .NB(NB), .NTHR(NTHR), .DCB(DCB)) u_engine (
    .clk_i, .rst_ni,
    .cfg_base_ly_i (base_ly), .cfg_base_lu_i (base_lu), .cfg_base_lv_i (base_lv),
    .cfg_base_ry_i (base_ry), .cfg_base_ru_i (base_ru), .cfg_base_rv_i (base_rv),
    .cfg_base_out_i (base_out), .cfg_base_dl_i (base_dl), .cfg_base_dr_i (base_dr),
    .cfg_base_mask_i (base_mask), .cfg_stride_i (stride), .cfg_out_stride_i (out_stride),
    .cfg_mode_i (mode), .cfg_lr_t_i (lr_t), .cfg_width_i (width), .cfg_height_i (height),
    .cfg_disp_i (disp), .cfg_thr_i (thr), .start_i (start),
    .busy_o (busy), .done_o (done), .error_o (error), .error_code_o (error_code),
    .cnt_cycles_o (cnt_cycles), .cnt_words_read_o (cnt_words_read),
    .cnt_words_written_o (cnt_words_written), .cnt_stall_o (cnt_stall),
    .mem_req_o, .mem_gnt_i, .mem_we_o, .mem_be_o, .mem_addr_o, .mem_wdata_o, .mem_rvalid_i,
    .mem_rdata_i
  );

endmodule

`default_nettype wire
