// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// MCADSW disparity engine core (paper Fig. 9; mcadsw_top wraps it for an SoC), wiring only:
// the configuration and its views, its check, the frame controller, the scheduler, the window
// geometry, the memory side (controller and window readers), the census transformers, the
// weight generator, the cost aggregator with WTA, the depth FIFO; beyond the paper the LR post
// stage, the rectifier and the owner of the external port. docs/blocks/engine.md describes
// the wiring, docs/memory_map.md the configuration, status and memory layout.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_engine #(
  parameter int AW   = 32,
  parameter int CW   = 12,                          // width / height / coordinate bits
  parameter int DMAX = mcadsw_pkg::DMAX,
  parameter int PAR  = mcadsw_pkg::PAR,             // disparities a step (1, 2, 4)
  parameter int NB   = $clog2(DMAX + 1),
  parameter int NTHR = mcadsw_pkg::WTHRESHOLDS,
  parameter int DCB  = mcadsw_pkg::COLOR_DIST_BITS
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  // Configuration: one bundle, its fields at mcadsw_pkg::CFG_* (generated from the register
  // map, sw_ref/include/mcadsw/regs.hpp; docs/memory_map.md), sampled when start_i is accepted
  input  logic [mcadsw_pkg::CFG_BITS-1:0] cfg_i,
  input  logic                start_i,         // ignored while busy_o
  // Status
  output logic                busy_o,
  output logic                done_o,          // frame finished (or rejected) since start
  output logic                error_o,         // configuration rejected; nothing was written
  output logic [7:0]          error_code_o,    // docs/registers.md
  output logic [31:0]         cnt_cycles_o,
  output logic [31:0]         cnt_words_read_o,
  output logic [31:0]         cnt_words_written_o,
  output logic [31:0]         cnt_stall_o,     // cycles with a request and no grant
  // External memory
  output logic                mem_req_o,
  input  logic                mem_gnt_i,
  output logic                mem_we_o,
  output logic [3:0]          mem_be_o,
  output logic [AW-1:0]       mem_addr_o,
  output logic [3:0]          mem_len_o,       // read burst: beats - 1 (writes: 0)
  output logic [31:0]         mem_wdata_o,
  input  logic                mem_rvalid_i,
  input  logic [31:0]         mem_rdata_i,
  // No write requested, buffered or unanswered in the memory system (AXI4:
  // mcadsw_axi_master's wr_idle_o; a port that completes writes at their grant:
  // 1). The LR post stage starts, and done_o rises, only with it.
  input  logic                mem_wr_idle_i
);

  localparam int COLS   = mcadsw_pkg::BLOCK_COLS;      // 48
  localparam int RCOLS  = COLS + DMAX - 1;            // 111
  localparam int LANES  = mcadsw_pkg::LANES;
  localparam int HAGG   = mcadsw_pkg::HAGG;
  localparam int WINDOW = mcadsw_pkg::WINDOW;
  localparam int CB     = mcadsw_pkg::CENSUS_BITS;
  localparam int WB     = mcadsw_pkg::WEIGHT_CODE_BITS;
  localparam int DB     = mcadsw_pkg::DISP_BITS;
  localparam int RLANES = LANES + PAR - 1;            // right census columns a read
  localparam bit FPGA   = mcadsw_pkg::FPGA != 0;      // the FPGA target's shapes

  // The right census read of a step stays in the window only if DMAX is a
  // multiple of PAR (the last step's first d is then at most DMAX - PAR).
  if (!(PAR == 1 || PAR == 2 || PAR == 4) || DMAX % PAR != 0) begin : g_bad_param
    mcadsw_error_top_par_not_1_2_4_or_dmax_not_a_multiple u_error ();
  end

  // ---- Configuration: registered at the start, checked, then fixed for the frame ----------
  // mcadsw_pass_cfg: the configuration registered (cfg_q, fields at mcadsw_pkg::CFG_*), the
  // pass view, the rectifier's and the mark step's views (docs/blocks/engine.md 1).
  logic                            accept, to_second, pass_second, pass_post, tiled, post_wide;
  logic                            right, wide, pack;  // right view as base; 16-bit output; LR scratch
  logic [mcadsw_pkg::CFG_BITS-1:0] cfg_q;
  logic [CW-1:0]                   height_q, xend;
  logic [AW-1:0]                   stride_q, tile_q, rect_stride, mark_valid, mark_base, mark_stride;
  logic [AW-1:0]                   base_by, base_bu, base_bv, base_my, base_out, pass_stride;
  logic [1:0]                      mark_phase, xlo;
  logic                            mark_half;
  logic [15:0]                     mark_value;
  logic [5:0]                      rect_planes;
  logic [3:0]                      wr_outs;
  logic [4*AW-1:0]                 wr_base;
  assign height_q = cfg_q[mcadsw_pkg::CFG_HEIGHT +: CW];
  assign stride_q = cfg_q[mcadsw_pkg::CFG_STRIDE +: AW];
  assign tile_q   = cfg_q[mcadsw_pkg::CFG_TILE_STRIDE +: AW];

  mcadsw_pass_cfg #(.AW(AW), .CW(CW)) u_pass_cfg (
    .clk_i, .rst_ni, .cfg_i,
    .accept_i (accept), .to_second_i (to_second), .pass_second_i (pass_second),
    .mark_phase_i (mark_phase), .cfg_q_o (cfg_q),
    .rect_planes_o (rect_planes), .tiled_o (tiled),
    .rect_stride_o (rect_stride), .wr_base_o (wr_base), .wr_outs_o (wr_outs),
    .pass_by_o (base_by), .pass_bu_o (base_bu), .pass_bv_o (base_bv), .pass_my_o (base_my),
    .pass_out_o (base_out), .pass_stride_o (pass_stride), .pass_xend_o (xend), .pass_xlo_o (xlo),
    .pass_right_o (right), .pass_wide_o (wide), .pass_pack_o (pack), .post_wide_o (post_wide),
    .mark_valid_o (mark_valid), .mark_base_o (mark_base), .mark_stride_o (mark_stride),
    .mark_half_o (mark_half), .mark_value_o (mark_value)
  );

  // The check's verdict is registered (docs/blocks/engine.md 2); plane sizes are exact.
  localparam int SB = AW + CW;
  logic [mcadsw_pkg::ERR_BITS-1:0] cfg_err_q;
  logic                            cfg_ok_q, cfg_done_q;
  logic [SB-1:0]                   in_size, size, out_size;
  mcadsw_cfg_check #(.AW(AW), .CW(CW), .DMAX(DMAX), .NB(NB), .SB(SB)) u_cfg_check (
    .clk_i, .rst_ni, .capture_i (accept), .cap_cfg_i (cfg_i), .cfg_i (cfg_q),
    .err_o (cfg_err_q), .ok_o (cfg_ok_q), .done_o (cfg_done_q),
    .in_size_o (in_size), .size_o (size), .out_size_o (out_size)
  );

  // ---- Frame controller: the passes, busy / done, error code, counters --------------------
  logic sched_busy, sched_done, go, post_start, post_done;
  logic rchk_start, rchk_done, rect_start, rect_done, rect_sel, mark_start, mark_done, mark_sel;
  logic [2:0] rchk_err;
  logic [1:0] rect_err;
  logic [mcadsw_pkg::ERR_BITS-1:0] error_code;
  assign error_code_o = 8'(error_code);

  mcadsw_frame_ctrl u_frame_ctrl (
    .clk_i, .rst_ni, .start_i,
    .cfg_lr_i (cfg_q[mcadsw_pkg::CFG_MODE + 1]), .cfg_right_i (cfg_q[mcadsw_pkg::CFG_MODE + 2]),
    .cfg_rect_i (cfg_q[mcadsw_pkg::CFG_RECT_EN]), .err_i (cfg_err_q),
    .ok_i (cfg_ok_q), .chk_done_i (cfg_done_q), .accept_o (accept),
    .rchk_start_o (rchk_start), .rchk_done_i (rchk_done), .rchk_err_i (rchk_err),
    .rect_start_o (rect_start), .rect_done_i (rect_done), .rect_err_i (rect_err),
    .rect_sel_o (rect_sel), .mark_start_o (mark_start), .mark_done_i (mark_done),
    .mark_sel_o (mark_sel), .mark_phase_o (mark_phase),
    .sched_start_o (go), .sched_busy_i (sched_busy), .sched_done_i (sched_done),
    .to_second_o (to_second), .pass_second_o (pass_second), .pass_post_o (pass_post),
    .post_start_o (post_start), .post_done_i (post_done), .wr_idle_i (mem_wr_idle_i),
    .mem_req_i (mem_req_o), .mem_gnt_i, .mem_we_i (mem_we_o), .mem_len_i (mem_len_o),
    .busy_o, .done_o, .error_o, .error_code_o (error_code),
    .cnt_cycles_o, .cnt_words_read_o, .cnt_words_written_o, .cnt_stall_o
  );

  // ---- Block scheduler -----------------------------------------------------------------
  localparam int SLB = $clog2(mcadsw_pkg::WEIGHT_SLOTS);
  logic               prep_start, prep_bank, prep_cont, agg_bank, agg_active, agg_busy, wrow_ready;
  logic               cl_done, cr_done, wg_done;   // the preparers' (one cycle each)
  logic               job_valid, job_ready, desc_push, fifo_space, fifo_empty;
  logic signed [CW:0] prep_x0, prep_y0;
  logic [4:0]         prep_rows, job_row, desc_n;
  logic [SLB-1:0]     wrow_slot;
  logic [5:0]         job_last_col;
  logic [AW-1:0]      desc_addr;
  logic [CW-1:0]      desc_x;

  mcadsw_scheduler #(.CW(CW), .AW(AW)) u_scheduler (
    .clk_i, .rst_ni, .start_i (go), .width_i (xend), .height_i (height_q), .out_base_i (base_out),
    .stride_i (pass_stride), .busy_o (sched_busy), .done_o (sched_done),
    .prep_start_o (prep_start), .prep_bank_o (prep_bank), .prep_x0_o (prep_x0), .prep_y0_o (prep_y0),
    .prep_cont_o (prep_cont), .prep_rows_o (prep_rows), .prep_done_i ({wg_done, cr_done, cl_done}),
    .agg_active_o (agg_active), .agg_bank_o (agg_bank), .job_valid_o (job_valid),
    .job_ready_i (job_ready), .wrow_ready_i (wrow_ready), .job_row_o (job_row),
    .job_last_col_o (job_last_col), .agg_busy_i (agg_busy),
    .desc_push_o (desc_push), .desc_addr_o (desc_addr), .desc_x_o (desc_x), .desc_n_o (desc_n),
    .fifo_space_i (fifo_space), .fifo_empty_i (fifo_empty)
  );

  // ---- Window geometry of the block being prepared -----------------------------------------
  localparam int LSTRIPS = (COLS + 4 + 6) / 4;      // census left reader  (14 strips)
  localparam int RSTRIPS = (RCOLS + 4 + 6) / 4;     // census right reader (30; 46 at DMAX = 128)
  localparam int RSB     = $clog2(RSTRIPS + 1);
  localparam int WSTRIPS = COLS / 4 + 1;            // weight reader       (13)
  localparam int RXB     = $clog2(RCOLS);           // right census column index
  logic signed [CW:0] lx_rd, rx_rd, wx_rd, cen_y0;
  logic [3:0]         l_strips, w_strips, cl_first, w_first;
  logic [RSB-1:0]     r_strips, cr_first;
  logic [5:0]         cl_lo_x, cl_hi_x, cen_lo_y, cen_hi_y, w_lo;
  logic [RXB-1:0]     cr_lo_x, cr_hi_x;
  logic [1:0]         cl_ofs, cr_ofs, w_ofs;

  mcadsw_win_geom #(.CW(CW), .DMAX(DMAX), .COLS(COLS), .RCOLS(RCOLS), .LSTRIPS(LSTRIPS),
                    .RSTRIPS(RSTRIPS), .WSTRIPS(WSTRIPS), .RSB(RSB), .RXB(RXB)) u_win_geom (
    .x0_i (prep_x0), .y0_i (prep_y0), .cont_i (prep_cont), .xlo_i (xlo), .xend_i (xend),
    .height_i (height_q),
    .lrd_x0_o (lx_rd), .lrd_strips_o (l_strips), .rrd_x0_o (rx_rd), .rrd_strips_o (r_strips),
    .wrd_x0_o (wx_rd), .wrd_strips_o (w_strips), .cen_y0_o (cen_y0),
    .cl_lo_x_o (cl_lo_x), .cl_hi_x_o (cl_hi_x), .cl_ofs_o (cl_ofs), .cl_first_o (cl_first),
    .cr_lo_x_o (cr_lo_x), .cr_hi_x_o (cr_hi_x), .cr_ofs_o (cr_ofs), .cr_first_o (cr_first),
    .cen_lo_y_o (cen_lo_y), .cen_hi_y_o (cen_hi_y),
    .w_ofs_o (w_ofs), .w_first_o (w_first), .w_lo_o (w_lo)
  );

  // ---- Memory controller and window readers ----------------------------------------------
  logic          wr_req, wr_gnt, eng_req, eng_gnt, eng_we, eng_rvalid;
  logic          lpix_valid, lpix_ready, rpix_valid, rpix_ready, wpix_valid, wpix_ready;
  logic [3:0]    wr_be, eng_be, eng_len;
  logic [AW-1:0] wr_addr, eng_addr;
  logic [31:0]   wr_wdata, eng_wdata, lpix, rpix, wpix;

  mcadsw_fetch #(.AW(AW), .CW(CW), .COLS(COLS), .LSTRIPS(LSTRIPS), .RSTRIPS(RSTRIPS),
                 .WSTRIPS(WSTRIPS), .RSB(RSB)) u_fetch (
    .clk_i, .rst_ni, .start_i (prep_start),
    .base_y_i (base_by), .base_u_i (base_bu), .base_v_i (base_bv), .base_m_i (base_my),
    .stride_i (stride_q), .tile_i (tile_q), .xend_i (xend), .xlo_i (xlo), .mirror_i (right),
    .height_i (height_q), .cen_y0_i (cen_y0), .w_y0_i (prep_y0),
    .lx0_i (lx_rd), .lstrips_i (l_strips), .rx0_i (rx_rd), .rstrips_i (r_strips),
    .wx0_i (wx_rd), .wstrips_i (w_strips),
    .lpix_valid_o (lpix_valid), .lpix_ready_i (lpix_ready), .lpix_o (lpix),
    .rpix_valid_o (rpix_valid), .rpix_ready_i (rpix_ready), .rpix_o (rpix),
    .wpix_valid_o (wpix_valid), .wpix_ready_i (wpix_ready), .wpix_o (wpix),
    .wr_req_i (wr_req), .wr_addr_i (wr_addr), .wr_be_i (wr_be), .wr_wdata_i (wr_wdata),
    .wr_gnt_o (wr_gnt),
    .mem_req_o (eng_req), .mem_gnt_i (eng_gnt), .mem_we_o (eng_we), .mem_be_o (eng_be),
    .mem_addr_o (eng_addr), .mem_len_o (eng_len), .mem_wdata_o (eng_wdata),
    .mem_rvalid_i (eng_rvalid), .mem_rdata_i
  );

  // ---- Post stage (LR mode), rectify pass and mark step: each owns the port in its states --
  logic          post_req, post_we, post_gnt, post_rvalid, post_clk, rect_clk;  // clocks: gated
  logic [3:0]    post_be;
  logic [AW-1:0] post_addr;
  logic [31:0]   post_wdata;

  mcadsw_clock_gate u_post_gate (.clk_i, .en_i (cfg_q[mcadsw_pkg::CFG_MODE + 1]), .off_i (1'b0), .clk_o (post_clk));
  mcadsw_clock_gate u_rect_gate (.clk_i, .en_i (cfg_q[mcadsw_pkg::CFG_RECT_EN]), .off_i (sched_busy), .clk_o (rect_clk));
  mcadsw_post #(.DB(DB), .CW(CW), .AW(AW)) u_post (
    .clk_i (post_clk), .rst_ni, .start_i (post_start),
    .base_dl_i (cfg_q[mcadsw_pkg::CFG_BASE_DL +: AW]), .base_dr_i (cfg_q[mcadsw_pkg::CFG_BASE_DR +: AW]),
    .base_out_i (cfg_q[mcadsw_pkg::CFG_BASE_OUT +: AW]), .base_mask_i (cfg_q[mcadsw_pkg::CFG_BASE_MASK +: AW]),
    .stride_i (stride_q), .out_stride_i (cfg_q[mcadsw_pkg::CFG_OUT_STRIDE +: AW]),
    .width_i (cfg_q[mcadsw_pkg::CFG_WIDTH +: CW]), .height_i (height_q),
    .tol_i (cfg_q[mcadsw_pkg::CFG_LR_T +: 6]), .wide_i (post_wide), .busy_o (), .done_o (post_done),
    .mem_req_o (post_req), .mem_gnt_i (post_gnt), .mem_we_o (post_we), .mem_be_o (post_be),
    .mem_addr_o (post_addr), .mem_wdata_o (post_wdata), .mem_rvalid_i (post_rvalid), .mem_rdata_i
  );

  // Rectification (docs/blocks/rectifier.md): the check of its registers, pass and mark step.
  logic          rect_req, rect_we, rect_gnt, rect_rvalid, mark_req, mark_we, mark_gnt, mark_rvalid;
  logic [3:0]    rect_be, mark_be;
  logic [AW-1:0] rect_addr, mark_addr;
  logic [2:0]    rect_len, mark_len;
  logic [31:0]   rect_wdata, mark_wdata;
  mcadsw_rectifier #(.AW(AW), .CW(CW), .SB(SB)) u_rectifier (
    .clk_i (rect_clk), .rst_ni, .cfg_i (cfg_q),
    .tiled_i (tiled), .planes_i (rect_planes), .stride_i (rect_stride), .out_base_i (wr_base),
    .outs_i (wr_outs), .in_size_i (in_size), .size_i (size), .out_size_i (out_size),
    .mark_valid_i (mark_valid), .mark_base_i (mark_base),
    .mark_stride_i (mark_stride), .mark_half_i (mark_half), .mark_value_i (mark_value),
    .chk_start_i (rchk_start), .chk_done_o (rchk_done), .chk_err_o (rchk_err),
    .rect_start_i (rect_start), .rect_done_o (rect_done), .rect_err_o (rect_err),
    .mark_start_i (mark_start), .mark_done_o (mark_done),
    .rect_req_o (rect_req), .rect_gnt_i (rect_gnt), .rect_we_o (rect_we), .rect_be_o (rect_be),
    .rect_addr_o (rect_addr), .rect_len_o (rect_len), .rect_wdata_o (rect_wdata),
    .rect_rvalid_i (rect_rvalid),
    .mark_req_o (mark_req), .mark_gnt_i (mark_gnt), .mark_we_o (mark_we), .mark_be_o (mark_be),
    .mark_addr_o (mark_addr), .mark_len_o (mark_len), .mark_wdata_o (mark_wdata),
    .mark_rvalid_i (mark_rvalid), .mem_rdata_i
  );

  mcadsw_port_mux #(.AW(AW)) u_port_mux (
    .clk_i, .rst_ni, .rect_sel_i (rect_sel), .mark_sel_i (mark_sel), .pass_post_i (pass_post),
    .rect_req_i (rect_req), .rect_we_i (rect_we), .rect_be_i (rect_be), .rect_addr_i (rect_addr),
    .rect_len_i (rect_len), .rect_wdata_i (rect_wdata), .rect_gnt_o (rect_gnt),
    .rect_rvalid_o (rect_rvalid),
    .mark_req_i (mark_req), .mark_we_i (mark_we), .mark_be_i (mark_be), .mark_addr_i (mark_addr),
    .mark_len_i (mark_len), .mark_wdata_i (mark_wdata), .mark_gnt_o (mark_gnt),
    .mark_rvalid_o (mark_rvalid),
    .post_req_i (post_req), .post_we_i (post_we), .post_be_i (post_be), .post_addr_i (post_addr),
    .post_wdata_i (post_wdata), .post_gnt_o (post_gnt), .post_rvalid_o (post_rvalid),
    .eng_req_i (eng_req), .eng_we_i (eng_we), .eng_be_i (eng_be), .eng_addr_i (eng_addr),
    .eng_len_i (eng_len), .eng_wdata_i (eng_wdata), .eng_gnt_o (eng_gnt), .eng_rvalid_o (eng_rvalid),
    .mem_req_o, .mem_gnt_i, .mem_we_o, .mem_be_o, .mem_addr_o, .mem_len_o, .mem_wdata_o,
    .mem_rvalid_i
  );

  // ---- Census transformers and weight generator ---------------------------------------------
  // Census reads (mcadsw_cost_agg): ASIC target one of LANES (left) and RLANES (right)
  // columns, the window's rows; FPGA target column words, one left and two right ports.
  localparam int CRP = FPGA ? 2 : 1;                   // right census read ports
  localparam int CLW = FPGA ? COLS*CB : LANES*WINDOW*CB;
  localparam int CRW = FPGA ? CRP*COLS*CB : RLANES*WINDOW*CB;
  logic                       vrd_en, hrd_en, hrd_rel, lrd_en;
  logic [4:0]                 vrd_row;
  logic [2:0]                 vrd_grp, hrd_grp;
  logic [SLB-1:0]             vrd_slot, hrd_slot;
  logic [5:0]                 lrd_col;
  logic [CRP-1:0]             rrd_en;
  logic [CRP*RXB-1:0]         rrd_col;
  logic [CLW-1:0]             cen_l;
  logic [CRW-1:0]             cen_r;
  logic [LANES*WINDOW*WB-1:0] wv;
  logic [HAGG*WINDOW*WB-1:0]  wh;

  mcadsw_census #(.COLS(COLS)) u_census_l (
    .clk_i, .rst_ni, .cfg_valid_i (prep_start), .cfg_ready_o (), .cfg_bank_i (prep_bank),
    .cfg_lo_x_i (cl_lo_x), .cfg_hi_x_i (cl_hi_x), .cfg_lo_y_i (cen_lo_y), .cfg_hi_y_i (cen_hi_y),
    .cfg_ofs_i (cl_ofs), .cfg_cont_i (prep_cont), .cfg_first_i (cl_first),
    .ring_free_i (!agg_active), .done_o (cl_done), .busy_o (),
    .pix_valid_i (lpix_valid), .pix_ready_o (lpix_ready), .pix_data_i (lpix),
    .rd_en_i (lrd_en), .rd_bank_i (agg_bank), .rd_row_i (6'(vrd_row)),
    .rd_col_i (lrd_col), .rd_data_o (cen_l)
  );

  // ASIC target: a step (d .. d + PAR - 1) reads RLANES right columns from column
  // grp LANES + DMAX - 1 - d - (PAR - 1) of the window (docs/blocks/census.md).
  mcadsw_census #(.COLS(RCOLS), .RL(FPGA ? CRP : RLANES)) u_census_r (
    .clk_i, .rst_ni, .cfg_valid_i (prep_start), .cfg_ready_o (), .cfg_bank_i (prep_bank),
    .cfg_lo_x_i (cr_lo_x), .cfg_hi_x_i (cr_hi_x), .cfg_lo_y_i (cen_lo_y), .cfg_hi_y_i (cen_hi_y),
    .cfg_ofs_i (cr_ofs), .cfg_cont_i (prep_cont), .cfg_first_i (cr_first),
    .ring_free_i (!agg_active), .done_o (cr_done), .busy_o (),
    .pix_valid_i (rpix_valid), .pix_ready_o (rpix_ready), .pix_data_i (rpix),
    .rd_en_i (rrd_en), .rd_bank_i (agg_bank), .rd_row_i (6'(vrd_row)),
    .rd_col_i (rrd_col), .rd_data_o (cen_r)
  );

  mcadsw_weight_gen u_weight_gen (
    .clk_i, .rst_ni, .thr_i (cfg_q[mcadsw_pkg::CFG_THR +: NTHR*DCB]),
    .cfg_valid_i (prep_start), .cfg_ready_o (), .done_o (wg_done), .busy_o (),
    .cfg_ofs_i (w_ofs), .cfg_first_i (w_first), .cfg_lo_i (w_lo), .cfg_rows_i (prep_rows),
    .pix_valid_i (wpix_valid), .pix_ready_o (wpix_ready), .pix_data_i (wpix),
    .row_ready_o (wrow_ready), .rd_slot_o (wrow_slot), .row_take_i (desc_push),
    .vrd_en_i (vrd_en), .vrd_slot_i (vrd_slot), .vrd_grp_i (vrd_grp), .wv_o (wv),
    .hrd_en_i (hrd_en), .hrd_slot_i (hrd_slot), .hrd_grp_i (hrd_grp), .hrd_rel_i (hrd_rel),
    .wh_o (wh)
  );

  // ---- Cost aggregator, WTA and depth FIFO ---------------------------------------------------
  // Sub-pixel values follow the disparities by two cycles; the scheduler follows vbusy_o, the
  // census and weight banks' last use (docs/blocks/cost_agg.md).
  localparam int VB = DB + 4;
  logic               disp_valid, sub_valid;
  logic [2:0]         disp_grp, sub_grp;
  logic [HAGG*DB-1:0] disp, sub_d;
  logic [HAGG*VB-1:0] sub;

  mcadsw_cost_agg #(.P(PAR)) u_cost_agg (
    .clk_i, .rst_ni, .job_valid_i (job_valid), .job_ready_o (job_ready), .job_row_i (job_row),
    .job_disp_i (cfg_q[mcadsw_pkg::CFG_DISP +: NB]), .job_last_col_i (job_last_col),
    .job_wslot_i (wrow_slot), .vrd_en_o (vrd_en), .vrd_row_o (vrd_row), .vrd_grp_o (vrd_grp),
    .vrd_d_o (), .vrd_slot_o (vrd_slot), .wv_i (wv), .cen_l_i (cen_l), .cen_r_i (cen_r),
    .lrd_en_o (lrd_en), .lrd_col_o (lrd_col), .rrd_en_o (rrd_en), .rrd_col_o (rrd_col),
    .hrd_en_o (hrd_en), .hrd_row_o (), .hrd_grp_o (hrd_grp), .hrd_slot_o (hrd_slot),
    .hrd_rel_o (hrd_rel), .wh_i (wh), .busy_o (), .vbusy_o (agg_busy),
    .disp_valid_o (disp_valid), .disp_row_o (), .disp_grp_o (disp_grp), .disp_o (disp),
    .sub_valid_o (sub_valid), .sub_row_o (), .sub_grp_o (sub_grp), .sub_o (sub), .sub_d_o (sub_d),
    .sub_busy_o ()
  );

  // Values: d, 16 d + offset, or the LR mode's scratch format (docs/blocks/engine.md 7).
  mcadsw_depth_fifo #(.AW(AW), .CW(CW), .DB(DB)) u_depth_fifo (
    .clk_i, .rst_ni, .desc_push_i (desc_push), .desc_addr_i (desc_addr), .desc_x_i (desc_x),
    .desc_n_i (desc_n), .space_o (fifo_space), .empty_o (fifo_empty),
    .wide_i (wide), .pack_i (pack), .mirror_i (right), .xlo_i (xlo), .xend_i (xend),
    .disp_valid_i (disp_valid), .disp_grp_i (disp_grp), .disp_i (disp),
    .sub_valid_i (sub_valid), .sub_grp_i (sub_grp), .sub_i (sub), .sub_d_i (sub_d),
    .wr_req_o (wr_req), .wr_addr_o (wr_addr), .wr_be_o (wr_be), .wr_wdata_o (wr_wdata), .wr_gnt_i (wr_gnt)
  );

  // ---- Invariants -------------------------------------------------------------------------
  // Blocks are prepared and rows aggregated only while the frame runs (the memory
  // port's owners: mcadsw_port_mux).
  `MCADSW_ASSERT(WorkOnlyWhenBusy, !(prep_start || job_valid) || busy_o)

endmodule

`default_nettype wire
