// MCADSW disparity engine core (paper Fig. 9; mcadsw_top wraps it for an SoC):
// memory controller with a 32-bit external memory port, block scheduler, three window readers, the
// left and right mini-census transformers, the weight generator, the cost
// aggregator with WTA, and the depth FIFO. docs/architecture.md describes the
// blocks; docs/memory_map.md the configuration, status and memory layout.
`default_nettype none

module mcadsw_engine #(
  parameter int AW   = 32,
  parameter int CW   = 12,                          // width / height / coordinate bits
  parameter int DMAX = mcadsw_pkg::DMAX,
  parameter int PAR  = mcadsw_pkg::PAR,             // disparities a step (1, 2, 4; issue 18)
  parameter int NB   = $clog2(DMAX + 1),
  parameter int NTHR = mcadsw_pkg::WTHRESHOLDS,
  parameter int DCB  = mcadsw_pkg::COLOR_DIST_BITS
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  // Configuration, sampled when start_i is accepted
  input  logic [AW-1:0]       cfg_base_ly_i,   // left Y plane
  input  logic [AW-1:0]       cfg_base_lu_i,   // left U plane
  input  logic [AW-1:0]       cfg_base_lv_i,   // left V plane
  input  logic [AW-1:0]       cfg_base_ry_i,   // right Y plane
  input  logic [AW-1:0]       cfg_base_ru_i,   // right U plane (read with the right view as base, or LR)
  input  logic [AW-1:0]       cfg_base_rv_i,   // right V plane (idem)
  input  logic [AW-1:0]       cfg_base_out_i,  // disparity plane
  input  logic [AW-1:0]       cfg_base_dl_i,   // LR: scratch plane of the left map (out stride)
  input  logic [AW-1:0]       cfg_base_dr_i,   // LR: scratch plane of the right map (input stride)
  input  logic [AW-1:0]       cfg_base_mask_i, // LR: validity mask plane (input stride)
  input  logic [AW-1:0]       cfg_stride_i,    // bytes per row of the input planes
  input  logic [AW-1:0]       cfg_out_stride_i,// bytes per row of the disparity plane
  input  logic [AW-1:0]       cfg_tile_stride_i,// input planes column-tiled: bytes per 4-pixel column; 0: raster
  input  logic [2:0]          cfg_mode_i,      // bit 0 sub-pixel, bit 1 LR, bit 2 right base
  input  logic [7:0]          cfg_lr_t_i,      // LR: check tolerance T, 0 .. LR_T_MAX
  input  logic [CW-1:0]       cfg_width_i,
  input  logic [CW-1:0]       cfg_height_i,
  input  logic [NB-1:0]       cfg_disp_i,      // D
  input  logic [NTHR*DCB-1:0] cfg_thr_i,       // weight table thresholds
  input  logic                start_i,         // ignored while busy_o
  // Status
  output logic                busy_o,
  output logic                done_o,          // frame finished (or rejected) since start
  output logic                error_o,         // configuration rejected; nothing was written
  output logic [3:0]          error_code_o,    // docs/memory_map.md
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

  // The right census read of a step stays in the window only if DMAX is a
  // multiple of PAR (the last step's first d is then at most DMAX - PAR).
  if (!(PAR == 1 || PAR == 2 || PAR == 4) || DMAX % PAR != 0) begin : g_bad_param
    mcadsw_error_top_par_not_1_2_4_or_dmax_not_a_multiple u_error ();
  end

  // ---- Configuration registers and checks ------------------------------------------
  // The pass's planes: base view Y, U, V (census and weights) and match view
  // Y; the left and right view respectively, or the other way round with the
  // right view as base.
  logic [AW-1:0]       base_by_q, base_bu_q, base_bv_q, base_my_q, base_out_q, stride_q;
  logic [AW-1:0]       out_stride_q;
  logic [AW-1:0]       tile_q;         // input planes column-tiled (0: raster)
  // The pass's columns: the image lies in columns xlo_q .. xend_q - 1. With the
  // right view as base the pass runs mirrored (docs/architecture.md section 12):
  // pass column c is image column W4 - 1 - c, W4 the width rounded up to 4.
  logic [CW-1:0]       xend_q, height_q;
  logic [1:0]          xlo_q;
  logic                right_q;
  logic [CW-1:0]       width_q;        // the image width, for the checks
  logic                lr_q;           // LR mode: three passes (below)
  logic                lr_sub_q;       // LR mode with sub-pixel output
  logic                pack;           // this pass writes the LR scratch format (dL, sub-pixel)
  logic [1:0]          pass_q;         // LR: 0 left map, 1 right map, 2 post stage
  // LR mode: the planes of the later passes, T.
  logic [AW-1:0]       base_ru_q, base_rv_q, base_dl_q, base_dr_q, base_mask_q, base_fout_q;
  logic [7:0]          lr_t_q;
  logic [NB-1:0]       disp_q;
  logic [NTHR*DCB-1:0] thr_q;
  logic                sub_q;          // sub-pixel mode: 16-bit output pixels
  logic                sched_busy, sched_done, accept;
  logic [3:0]          check;

  // Error codes (docs/memory_map.md): 1 width, 2 height, 3 D, 4 input stride,
  // 5 base alignment, 6 a written plane overlaps a read or another written plane,
  // 7 output stride, 8 mode, 9 a plane reaches beyond the 32-bit address space,
  // 10 LR tolerance, 11 LR width, 12 LR right colour planes not configured.
  localparam int SB = AW + CW;         // plane sizes: stride x height (or x columns), exact
  function automatic logic overlaps(input logic [AW-1:0] a, input logic [SB-1:0] a_size,
                                    input logic [AW-1:0] b, input logic [SB-1:0] b_size);
    overlaps = (SB'(a) < SB'(b) + b_size) && (SB'(b) < SB'(a) + a_size);
  endfunction
  function automatic logic beyond(input logic [AW-1:0] base, input logic [SB-1:0] size);
    logic [SB:0] end_;
    end_   = (SB + 1)'(base) + (SB + 1)'(size);
    beyond = end_ > (SB + 1)'(64'd1 << AW);
  endfunction

  // The configured mode, and the planes it reads.
  logic cfg_sub, cfg_lr, cfg_right;
  assign {cfg_right, cfg_lr, cfg_sub} = cfg_mode_i;
  logic [AW-1:0] sel_by, sel_bu, sel_bv, sel_my;
  assign sel_by = cfg_right ? cfg_base_ry_i : cfg_base_ly_i;
  assign sel_bu = cfg_right ? cfg_base_ru_i : cfg_base_lu_i;
  assign sel_bv = cfg_right ? cfg_base_rv_i : cfg_base_lv_i;
  assign sel_my = cfg_right ? cfg_base_ly_i : cfg_base_ry_i;

  // Planes the frame reads (in: base Y, U, V, match Y; LR: right U, V) and writes
  // (wr: the first pass's output; LR: dR, the output, the mask). In LR mode the
  // first pass's output is dL, and dL and the output have the output stride, dR
  // and the mask the input stride.
  localparam int NIN = 6, NWR = 4;
  logic [NIN*AW-1:0] in_base;
  logic [NIN-1:0]    in_en;
  logic [NWR*AW-1:0] wr_base;
  logic [NWR-1:0]    wr_en, wr_outs;   // wr_outs: the plane has the output stride
  assign in_base = {base_rv_q, base_ru_q, base_my_q, base_bv_q, base_bu_q, base_by_q};
  assign in_en   = {lr_q, lr_q, 4'b1111};
  assign wr_base = {base_mask_q, base_fout_q, base_dr_q, base_out_q};
  assign wr_en   = {lr_q, lr_q, lr_q, 1'b1};
  assign wr_outs = 4'b0101;

  always_comb begin
    logic [SB-1:0] size, in_size, out_size;
    logic [CW:0]   out_bytes;          // bytes of an output row
    logic          misaligned, overlap, past;
    logic          tiled;
    logic [CW-1:0] wcols;              // columns of 4 pixels
    tiled     = tile_q != '0;
    wcols     = width_q + CW'(3);
    wcols     = wcols >> 2;
    size      = SB'(stride_q) * SB'(height_q);
    // The input planes: raster, stride x height; column-tiled, tile x the
    // columns of 4 pixels.
    in_size   = tiled ? SB'(tile_q) * SB'(wcols) : size;
    out_size  = SB'(out_stride_q) * SB'(height_q);
    out_bytes = sub_q ? {width_q, 1'b0} : {1'b0, width_q};
    misaligned = 1'b0;
    past       = 1'b0;
    overlap    = 1'b0;
    for (int i = 0; i < NIN; i++) begin
      misaligned = misaligned || (in_en[i] && in_base[i*AW +: 2] != 2'b00);
      past       = past || (in_en[i] && beyond(in_base[i*AW +: AW], in_size));
    end
    for (int o = 0; o < NWR; o++) begin
      misaligned = misaligned || (wr_en[o] && wr_base[o*AW +: 2] != 2'b00);
      past       = past || (wr_en[o] && beyond(wr_base[o*AW +: AW], wr_outs[o] ? out_size : size));
      for (int i = 0; i < NIN; i++)
        overlap = overlap || (wr_en[o] && in_en[i] &&
                              overlaps(wr_base[o*AW +: AW], wr_outs[o] ? out_size : size,
                                       in_base[i*AW +: AW], in_size));
      for (int p = 0; p < NWR; p++)         // each pair once: p > o
        overlap = overlap || (p > o && wr_en[o] && wr_en[p] &&
                              overlaps(wr_base[o*AW +: AW], wr_outs[o] ? out_size : size,
                                       wr_base[p*AW +: AW], wr_outs[p] ? out_size : size));
    end
    check = 4'd0;
    if (width_q == '0 || 32'(width_q) > mcadsw_pkg::MAX_WIDTH) check = 4'd1;
    else if (height_q == '0 || 32'(height_q) > mcadsw_pkg::MAX_HEIGHT) check = 4'd2;
    else if (disp_q == '0 || 32'(disp_q) > DMAX) check = 4'd3;
    // STRIDE is the input planes' (raster) and, in the LR mode, dR's and the mask's.
    else if ((!tiled || lr_q) && (stride_q < AW'(width_q) || (stride_q & AW'(3)) != '0))
      check = 4'd4;
    else if (tiled && (tile_q < AW'({height_q, 2'b00}) || (tile_q & AW'(3)) != '0)) check = 4'd4;
    else if (misaligned) check = 4'd5;
    else if (overlap) check = 4'd6;
    else if (out_stride_q < AW'(out_bytes) || (out_stride_q & AW'(3)) != '0) check = 4'd7;
    else if (lr_q && right_q) check = 4'd8;
    else if (past) check = 4'd9;
    else if (lr_q && 32'(lr_t_q) > mcadsw_pkg::LR_T_MAX) check = 4'd10;
    else if (lr_q && 32'(width_q) > mcadsw_pkg::POST_MAX_WIDTH) check = 4'd11;
    // Right U and V not configured: the same base as each other or as another
    // input plane (registers left at their reset value, or copied).
    else if (lr_q && (base_ru_q == base_rv_q || base_ru_q == base_by_q || base_ru_q == base_bu_q ||
                      base_ru_q == base_bv_q || base_ru_q == base_my_q || base_rv_q == base_by_q ||
                      base_rv_q == base_bu_q || base_rv_q == base_bv_q || base_rv_q == base_my_q))
      check = 4'd12;
  end

  // The right view as base runs mirrored about W4, the width rounded up to 4
  // columns; the image then lies in pass columns W4 - W .. W4 - 1.
  function automatic logic [CW-1:0] w4(input logic [CW-1:0] w);
    w4 = (w + CW'(3)) & ~(CW'(3));
  endfunction
  function automatic logic [1:0] w4_lo(input logic [CW-1:0] w);
    w4_lo = 2'(CW'(0) - w);
  endfunction

  // LR mode: the passes' ends, and the scratch format in the first pass.
  logic pass1_done, pass2_done;
  assign pass1_done = sched_done && lr_q && pass_q == 2'd0;
  assign pass2_done = sched_done && lr_q && pass_q == 2'd1;
  assign pack       = lr_sub_q && pass_q == 2'd0;
  logic lr_run_q, post_start_q, post_wait_q, post_busy, post_done;
  logic frame_end, fin_q;
  assign frame_end = (sched_done && !lr_q) || post_done;

  // A start is taken only while idle: not while the scheduler runs, nor in the
  // two cycles after an accepted start (chk_q, go_q), when busy_o is already high.
  // The configuration is registered at the start and checked in the next cycle
  // (chk_q), from the registers: the plane-size products and compares do not
  // follow the configuration ports' input delay.
  assign accept = start_i && !busy_o;
  logic chk_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      {base_by_q, base_bu_q, base_bv_q, base_my_q, base_out_q, stride_q, tile_q} <= '0;
      {out_stride_q, xend_q, xlo_q, height_q, disp_q, thr_q, sub_q, right_q} <= '0;
      {width_q, lr_q, lr_sub_q, pass_q, chk_q} <= '0;
      {base_ru_q, base_rv_q, base_dl_q, base_dr_q, base_mask_q, base_fout_q, lr_t_q} <= '0;
      done_o       <= 1'b0;
      error_o      <= 1'b0;
      error_code_o <= '0;
    end else begin
      if (accept) begin
        base_by_q  <= sel_by;
        base_bu_q  <= sel_bu;
        base_bv_q  <= sel_bv;
        base_my_q  <= sel_my;
        // LR mode: the first pass writes dL.
        base_out_q <= cfg_lr ? cfg_base_dl_i : cfg_base_out_i;
        stride_q   <= cfg_stride_i;
        out_stride_q <= cfg_out_stride_i;
        tile_q     <= cfg_tile_stride_i;
        sub_q      <= cfg_sub;
        xend_q     <= cfg_right ? w4(cfg_width_i) : cfg_width_i;
        xlo_q      <= cfg_right ? w4_lo(cfg_width_i) : 2'd0;
        right_q    <= cfg_right;
        width_q    <= cfg_width_i;
        lr_q       <= cfg_lr;
        lr_sub_q   <= cfg_lr && cfg_sub;
        pass_q     <= 2'd0;
        base_ru_q  <= cfg_base_ru_i;
        base_rv_q  <= cfg_base_rv_i;
        base_dl_q  <= cfg_base_dl_i;
        base_dr_q  <= cfg_base_dr_i;
        base_mask_q <= cfg_base_mask_i;
        base_fout_q <= cfg_base_out_i;
        lr_t_q     <= cfg_lr_t_i;
        height_q   <= cfg_height_i;
        disp_q     <= cfg_disp_i;
        thr_q      <= cfg_thr_i;
        error_o      <= 1'b0;
        error_code_o <= '0;
        done_o       <= 1'b0;
      end
      chk_q <= accept;
      if (chk_q) begin
        error_o      <= check != 4'd0;
        error_code_o <= check;
        done_o       <= check != 4'd0;
      end
      // LR mode: after the left map, the right map (the right view as base,
      // 1 byte a pixel into dR, input stride); after that the post stage.
      if (pass1_done) begin
        base_by_q  <= base_my_q;
        base_bu_q  <= base_ru_q;
        base_bv_q  <= base_rv_q;
        base_my_q  <= base_by_q;
        base_out_q <= base_dr_q;
        sub_q      <= 1'b0;
        right_q    <= 1'b1;
        xend_q     <= w4(width_q);
        xlo_q      <= w4_lo(width_q);
        pass_q     <= 2'd1;
      end
      if (pass2_done) pass_q <= 2'd2;
      if ((frame_end || fin_q) && mem_wr_idle_i) done_o <= 1'b1;
    end
  end

  // The scheduler starts the cycle after a valid configuration is checked.
  logic go_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) go_q <= 1'b0;
    else go_q <= (chk_q && check == 4'd0) || pass1_done;
  end

  // LR mode: the frame runs from the start of the first pass to the post
  // stage's done; between the passes the scheduler is idle for a cycle. The
  // post stage reads dL and dR back, so it starts once every write of the
  // passes is answered (post_wait_q: waiting for mem_wr_idle_i).
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      lr_run_q     <= 1'b0;
      post_start_q <= 1'b0;
      post_wait_q  <= 1'b0;
    end else begin
      post_start_q <= (pass2_done || post_wait_q) && mem_wr_idle_i;
      post_wait_q  <= (pass2_done || post_wait_q) && !mem_wr_idle_i;
      if (chk_q && check == 4'd0 && lr_q) lr_run_q <= 1'b1;
      if (post_done) lr_run_q <= 1'b0;
    end
  end

  // The frame's last block row (or the post stage) is over: done_o rises once
  // every write is answered (fin_q: waiting for mem_wr_idle_i).
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) fin_q <= 1'b0;
    else fin_q <= (frame_end || fin_q) && !mem_wr_idle_i;
  end

  // ---- Counters --------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cnt_cycles_o        <= '0;
      cnt_words_read_o    <= '0;
      cnt_words_written_o <= '0;
      cnt_stall_o         <= '0;
    end else if (accept) begin
      cnt_cycles_o        <= '0;
      cnt_words_read_o    <= '0;
      cnt_words_written_o <= '0;
      cnt_stall_o         <= '0;
    end else if (sched_busy || lr_run_q || fin_q) begin
      cnt_cycles_o        <= cnt_cycles_o + 32'd1;
      // A granted read is a burst of mem_len_o + 1 words.
      if (mem_req_o && mem_gnt_i && !mem_we_o)
        cnt_words_read_o <= cnt_words_read_o + 32'(mem_len_o) + 32'd1;
      cnt_words_written_o <= cnt_words_written_o + 32'(mem_req_o && mem_gnt_i && mem_we_o);
      cnt_stall_o         <= cnt_stall_o + 32'(mem_req_o && !mem_gnt_i);
    end
  end
  assign busy_o = sched_busy || go_q || chk_q || lr_run_q || fin_q;

  // ---- Block scheduler -----------------------------------------------------------------
  logic               prep_start, prep_bank, agg_bank;
  logic signed [CW:0] prep_x0, prep_y0;
  logic               prep_done;
  logic [4:0]         prep_rows;
  logic               wrow_ready, wrow_slot;
  logic               agg_active;     // census rings: the previous block still aggregates
  logic               job_valid, job_ready, agg_busy;
  logic [4:0]         job_row;
  logic [5:0]         job_last_col;
  logic               desc_push, fifo_space, fifo_empty;
  logic [AW-1:0]      desc_addr;
  logic [CW-1:0]      desc_x;
  logic [4:0]         desc_n;

  mcadsw_scheduler #(.CW(CW), .AW(AW)) u_scheduler (
    .clk_i, .rst_ni,
    .start_i        (go_q),
    .width_i        (xend_q),
    .height_i       (height_q),
    .out_base_i     (base_out_q),
    .stride_i       (pass_q == 2'd1 ? stride_q : out_stride_q),  // LR: dR has the input stride
    .busy_o         (sched_busy),
    .done_o         (sched_done),
    .prep_start_o   (prep_start),
    .prep_bank_o    (prep_bank),
    .prep_x0_o      (prep_x0),
    .prep_y0_o      (prep_y0),
    .prep_cont_o    (prep_cont),
    .prep_rows_o    (prep_rows),
    .prep_done_i    (prep_done),
    .agg_active_o   (agg_active),
    .agg_bank_o     (agg_bank),
    .job_valid_o    (job_valid),
    .job_ready_i    (job_ready),
    .wrow_ready_i   (wrow_ready),
    .job_row_o      (job_row),
    .job_last_col_o (job_last_col),
    .agg_busy_i     (agg_busy),
    .desc_push_o    (desc_push),
    .desc_addr_o    (desc_addr),
    .desc_x_o       (desc_x),
    .desc_n_o       (desc_n),
    .fifo_space_i   (fifo_space),
    .fifo_empty_i   (fifo_empty)
  );

  // In-image bounds of a window starting at x0 (size n) in an image of size w.
  // In-image bounds of a window starting at x0 (size n): the image starts at lo
  // and ends before w.
  // Bounds are window columns, up to RCOLS - 1 (the right census window).
  localparam int BW  = $clog2(RCOLS + 1);
  localparam int RXB = $clog2(RCOLS);                 // right census column index
  function automatic logic [BW-1:0] lo_bound(input logic signed [CW:0] x0, input logic [1:0] lo);
    logic signed [CW:0] l;
    l = $signed({{(CW - 1){1'b0}}, lo}) - x0;
    lo_bound = (l > 0) ? BW'(l) : '0;
  endfunction
  function automatic logic [BW-1:0] hi_bound(input logic signed [CW:0] x0, input logic [CW-1:0] w,
                                          input int n);
    logic signed [CW+1:0] h;
    h = $signed({2'b00, w}) - 1 - x0;
    hi_bound = (32'(h) > n - 1) ? BW'(n - 1) : BW'(h);
  endfunction

  logic signed [CW:0] rx0;     // right census window origin
  assign rx0 = prep_x0 - (CW + 1)'(DMAX - 1);

  // Readers start at the aligned memory word at or left of a window's first
  // input column (floor to a multiple of 4), so a strip word is one read; the
  // block skips the first (x & 3) input columns.
  logic signed [CW:0] lx_in, rx_in;       // first luma input column of the census windows
  assign lx_in = prep_x0 - (CW + 1)'(2);
  assign rx_in = rx0 - (CW + 1)'(2);
  logic signed [CW:0] lx_al, rx_al, wx_al; // aligned window origins
  assign lx_al = {lx_in[CW:2], 2'b00};
  assign rx_al = {rx_in[CW:2], 2'b00};
  assign wx_al = {prep_x0[CW:2], 2'b00};

  // Partial column reuse (Sec. IV): a block that continues its left neighbour
  // (prep_cont) finds the strips both windows share in its input buffers and
  // reads only the last `shift` strips of its window, where shift (4 or 5) is
  // how many words the aligned origin moved with the block's 18 columns.
  localparam int LSTRIPS = (COLS + 4 + 6) / 4;      // census left  (14)
  localparam int RSTRIPS = (RCOLS + 4 + 6) / 4;     // census right (30; 46 at DMAX = 128)
  localparam int RSB     = $clog2(RSTRIPS + 1);
  localparam int WSTRIPS = COLS / 4 + 1;            // weights      (13)
  function automatic logic [5:0] first_strip(input logic [1:0] xin_ofs, input logic cont,
                                             input int strips);
    // floor(x / 4) - floor((x - BLOCK) / 4) = ceil((BLOCK - x mod 4) / 4)
    first_strip = cont ? 6'(strips - (mcadsw_pkg::BLOCK + 3 - 32'(xin_ofs)) / 4) : 6'd0;
  endfunction
  logic               prep_cont;
  logic [5:0]         l_first, r_first, w_first;
  // The census windows of the first block of a row band skip the strips left of
  // the one holding image column -2, the leftmost luma the codes of column 0
  // need (the kernels compute the columns left of the image from column 0).
  // (Written -x - N'(2): Yosys 0.23 parses a unary minus before a size cast,
  // -(N)'(2), as a cast to the size -(N), i.e. +2; scripts/rtl_check.sh rejects it.)
  logic signed [CW:0] lx_skip, rx_skip;   // column lo - 2, relative to the aligned origin
  logic signed [CW:0] xlo_s;
  assign xlo_s   = $signed({{(CW - 1){1'b0}}, xlo_q});
  assign lx_skip = xlo_s - lx_al - (CW + 1)'(2);
  assign rx_skip = xlo_s - rx_al - (CW + 1)'(2);
  assign l_first = prep_cont ? first_strip(lx_in[1:0], 1'b1, LSTRIPS) :
                   (lx_skip > 0) ? 6'(lx_skip >>> 2) : 6'd0;
  assign r_first = prep_cont ? first_strip(rx_in[1:0], 1'b1, RSTRIPS) :
                   (rx_skip > 0) ? 6'(rx_skip >>> 2) : 6'd0;
  // The weight window of the first block of a row band (x0 = -15) skips the
  // strips wholly left of the image; the weight generator replicates column 0.
  logic signed [CW:0] wx_skip;           // column lo, relative to the aligned origin
  assign wx_skip = xlo_s - wx_al;
  assign w_first = prep_cont ? first_strip(prep_x0[1:0], 1'b1, WSTRIPS) :
                   (wx_skip > 0) ? 6'(wx_skip >>> 2) : 6'd0;
  logic signed [CW:0] lx_rd, rx_rd, wx_rd; // first column each reader reads
  assign lx_rd = lx_al + (CW + 1)'(4 * 32'(l_first));
  assign rx_rd = rx_al + (CW + 1)'(4 * 32'(r_first));
  assign wx_rd = wx_al + (CW + 1)'(4 * 32'(w_first));

  // ---- Memory controller and window readers ----------------------------------------------
  localparam int NR = 3;
  logic [NR-1:0]    rd_req, rd_gnt, rd_rvalid;
  logic [NR*AW-1:0] rd_addr;
  logic [NR*4-1:0]  rd_len;
  logic [31:0]      rd_rdata;
  logic             wr_req, wr_gnt;
  logic [AW-1:0]    wr_addr;
  logic [3:0]       wr_be;
  logic [31:0]      wr_wdata;
  logic             eng_req, eng_gnt, eng_we, eng_rvalid;
  logic [3:0]       eng_be;
  logic [AW-1:0]    eng_addr;
  logic [3:0]       eng_len;
  logic [31:0]      eng_wdata;

  mcadsw_mem_ctrl #(.NR(NR), .AW(AW)) u_mem_ctrl (
    .clk_i, .rst_ni,
    .rd_req_i (rd_req), .rd_addr_i (rd_addr), .rd_len_i (rd_len), .rd_gnt_o (rd_gnt),
    .rd_rvalid_o (rd_rvalid), .rd_rdata_o (rd_rdata),
    .wr_req_i (wr_req), .wr_addr_i (wr_addr), .wr_be_i (wr_be), .wr_wdata_i (wr_wdata),
    .wr_gnt_o (wr_gnt),
    .mem_req_o (eng_req), .mem_gnt_i (eng_gnt), .mem_we_o (eng_we), .mem_be_o (eng_be),
    .mem_addr_o (eng_addr), .mem_len_o (eng_len), .mem_wdata_o (eng_wdata),
    .mem_rvalid_i (eng_rvalid), .mem_rdata_i
  );

  // ---- Post stage (LR mode, pass 2): the external port is its own while it runs ----
  logic          post_req, post_we, post_sel;
  logic [3:0]    post_be;
  logic [AW-1:0] post_addr;
  logic [31:0]   post_wdata;
  assign post_sel = pass_q == 2'd2;

  mcadsw_post #(.DB(DB), .CW(CW), .AW(AW)) u_post (
    .clk_i, .rst_ni,
    .start_i (post_start_q),
    .base_dl_i (base_dl_q), .base_dr_i (base_dr_q), .base_out_i (base_fout_q),
    .base_mask_i (base_mask_q), .stride_i (stride_q), .out_stride_i (out_stride_q),
    .width_i (width_q), .height_i (height_q), .tol_i (6'(lr_t_q)), .wide_i (lr_sub_q),
    .busy_o (post_busy), .done_o (post_done),
    .mem_req_o (post_req), .mem_gnt_i (mem_gnt_i && post_sel), .mem_we_o (post_we),
    .mem_be_o (post_be), .mem_addr_o (post_addr), .mem_wdata_o (post_wdata),
    .mem_rvalid_i (mem_rvalid_i && post_sel), .mem_rdata_i
  );
  assign mem_req_o   = post_sel ? post_req : eng_req;
  assign mem_we_o    = post_sel ? post_we : eng_we;
  assign mem_be_o    = post_sel ? post_be : eng_be;
  assign mem_addr_o  = post_sel ? post_addr : eng_addr;
  assign mem_len_o   = post_sel ? 4'd0 : eng_len;
  assign mem_wdata_o = post_sel ? post_wdata : eng_wdata;
  assign eng_gnt     = mem_gnt_i && !post_sel;
  assign eng_rvalid  = mem_rvalid_i && !post_sel;

  logic        lpix_valid, lpix_ready, rpix_valid, rpix_ready, wpix_valid, wpix_ready;
  logic [31:0] lpix, rpix, wpix;
  logic        lrd_busy_unused, rrd_busy_unused, wrd_busy_unused;

  mcadsw_win_reader #(.ROWS(COLS + 4), .STRIPS(LSTRIPS), .PLANES(1), .CW(CW), .AW(AW))
  u_rd_census_l (
    .clk_i, .rst_ni,
    .start_i (prep_start), .base_i (base_by_q), .stride_i (stride_q), .tile_i (tile_q),
    .width_i (xend_q), .lo_i (xlo_q), .mirror_i (right_q), .height_i (height_q),
    .x0_i (lx_rd), .y0_i (prep_y0 - (CW + 1)'(2)),
    .strips_i (4'(LSTRIPS - 32'(l_first))),
    .busy_o (lrd_busy_unused),
    .req_o (rd_req[0]), .addr_o (rd_addr[0*AW +: AW]), .len_o (rd_len[0*4 +: 4]),
    .gnt_i (rd_gnt[0]),
    .rvalid_i (rd_rvalid[0]), .rdata_i (rd_rdata),
    .pix_valid_o (lpix_valid), .pix_ready_i (lpix_ready), .pix_data_o (lpix)
  );

  mcadsw_win_reader #(.ROWS(COLS + 4), .STRIPS(RSTRIPS), .PLANES(1), .CW(CW), .AW(AW))
  u_rd_census_r (
    .clk_i, .rst_ni,
    .start_i (prep_start), .base_i (base_my_q), .stride_i (stride_q), .tile_i (tile_q),
    .width_i (xend_q), .lo_i (xlo_q), .mirror_i (right_q), .height_i (height_q),
    .x0_i (rx_rd), .y0_i (prep_y0 - (CW + 1)'(2)),
    .strips_i (RSB'(RSTRIPS - 32'(r_first))),
    .busy_o (rrd_busy_unused),
    .req_o (rd_req[1]), .addr_o (rd_addr[1*AW +: AW]), .len_o (rd_len[1*4 +: 4]),
    .gnt_i (rd_gnt[1]),
    .rvalid_i (rd_rvalid[1]), .rdata_i (rd_rdata),
    .pix_valid_o (rpix_valid), .pix_ready_i (rpix_ready), .pix_data_o (rpix)
  );

  mcadsw_win_reader #(.ROWS(COLS), .STRIPS(WSTRIPS), .PLANES(3), .CW(CW), .AW(AW))
  u_rd_weight (
    .clk_i, .rst_ni,
    .start_i (prep_start), .base_i ({base_bv_q, base_bu_q, base_by_q}), .stride_i (stride_q), .tile_i (tile_q),
    .width_i (xend_q), .lo_i (xlo_q), .mirror_i (right_q), .height_i (height_q),
    .x0_i (wx_rd), .y0_i (prep_y0),
    .strips_i (4'(WSTRIPS - 32'(w_first))),
    .busy_o (wrd_busy_unused),
    .req_o (rd_req[2]), .addr_o (rd_addr[2*AW +: AW]), .len_o (rd_len[2*4 +: 4]),
    .gnt_i (rd_gnt[2]),
    .rvalid_i (rd_rvalid[2]), .rdata_i (rd_rdata),
    .pix_valid_o (wpix_valid), .pix_ready_i (wpix_ready), .pix_data_o (wpix)
  );

  // ---- Census transformers and weight generator ---------------------------------------------
  logic cl_done, cr_done, wg_done;
  logic cl_done_q, cr_done_q, wg_done_q;
  logic cl_busy_unused, cr_busy_unused, wg_busy_unused;
  logic cl_cfg_ready_unused, cr_cfg_ready_unused, wg_cfg_ready_unused;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) {cl_done_q, cr_done_q, wg_done_q} <= '0;
    else if (prep_start) {cl_done_q, cr_done_q, wg_done_q} <= '0;
    else begin
      if (cl_done) cl_done_q <= 1'b1;
      if (cr_done) cr_done_q <= 1'b1;
      if (wg_done) wg_done_q <= 1'b1;
    end
  end
  assign prep_done = cl_done_q && cr_done_q && wg_done_q;

  logic                       vrd_en, hrd_en;
  logic [4:0]                 vrd_row, hrd_row_unused;
  logic [2:0]                 vrd_grp, hrd_grp;
  logic                       vrd_slot, hrd_slot, hrd_rel;
  logic [DB-1:0]              vrd_d;
  logic [LANES*WINDOW*CB-1:0]  cen_l;
  logic [RLANES*WINDOW*CB-1:0] cen_r;   // see mcadsw_cost_agg: lane j at column - d + j - (PAR-1)
  logic [LANES*WINDOW*WB-1:0] wv;
  logic [HAGG*WINDOW*WB-1:0]  wh;

  mcadsw_census #(.COLS(COLS)) u_census_l (
    .clk_i, .rst_ni,
    .cfg_valid_i (prep_start), .cfg_ready_o (cl_cfg_ready_unused), .cfg_bank_i (prep_bank),
    .cfg_lo_x_i (6'(lo_bound(prep_x0, xlo_q))), .cfg_hi_x_i (6'(hi_bound(prep_x0, xend_q, COLS))),
    .cfg_lo_y_i (6'(lo_bound(prep_y0, 2'd0))), .cfg_hi_y_i (6'(hi_bound(prep_y0, height_q, COLS))),
    .cfg_ofs_i (lx_in[1:0]), .cfg_cont_i (prep_cont), .cfg_first_i (4'(l_first)),
    .ring_free_i (!agg_active),
    .pix_valid_i (lpix_valid), .pix_ready_o (lpix_ready), .pix_data_i (lpix),
    .done_o (cl_done), .busy_o (cl_busy_unused),
    .rd_en_i (vrd_en), .rd_bank_i (agg_bank), .rd_row_i (6'(vrd_row)),
    .rd_col_i (6'(32'(vrd_grp) * LANES)), .rd_data_o (cen_l)
  );

  // A step reads disparities d .. d + PAR - 1 (d = vrd_d): left lane l's columns
  // minus d + PAR - 1 .. minus d, RLANES right columns from column grp LANES +
  // DMAX - 1 - d - (PAR - 1) of the window (0 .. RCOLS - RLANES: d <= DMAX - PAR).
  mcadsw_census #(.COLS(RCOLS), .RL(RLANES)) u_census_r (
    .clk_i, .rst_ni,
    .cfg_valid_i (prep_start), .cfg_ready_o (cr_cfg_ready_unused), .cfg_bank_i (prep_bank),
    .cfg_lo_x_i (RXB'(lo_bound(rx0, xlo_q))), .cfg_hi_x_i (RXB'(hi_bound(rx0, xend_q, RCOLS))),
    .cfg_lo_y_i (6'(lo_bound(prep_y0, 2'd0))), .cfg_hi_y_i (6'(hi_bound(prep_y0, height_q, COLS))),
    .cfg_ofs_i (rx_in[1:0]), .cfg_cont_i (prep_cont), .cfg_first_i (RSB'(r_first)),
    .ring_free_i (!agg_active),
    .pix_valid_i (rpix_valid), .pix_ready_o (rpix_ready), .pix_data_i (rpix),
    .done_o (cr_done), .busy_o (cr_busy_unused),
    .rd_en_i (vrd_en), .rd_bank_i (agg_bank), .rd_row_i (6'(vrd_row)),
    .rd_col_i (RXB'(32'(vrd_grp) * LANES + DMAX - PAR - 32'(vrd_d))), .rd_data_o (cen_r)
  );

  mcadsw_weight_gen u_weight_gen (
    .clk_i, .rst_ni,
    .thr_i (thr_q),
    .cfg_valid_i (prep_start), .cfg_ready_o (wg_cfg_ready_unused),
    .cfg_ofs_i (prep_x0[1:0]), .cfg_first_i (4'(w_first)),
    .cfg_lo_i (6'(lo_bound(prep_x0, xlo_q))), .cfg_rows_i (prep_rows),
    .pix_valid_i (wpix_valid), .pix_ready_o (wpix_ready), .pix_data_i (wpix),
    .done_o (wg_done), .busy_o (wg_busy_unused),
    .row_ready_o (wrow_ready), .rd_slot_o (wrow_slot), .row_take_i (desc_push),
    .vrd_en_i (vrd_en), .vrd_slot_i (vrd_slot), .vrd_grp_i (vrd_grp), .wv_o (wv),
    .hrd_en_i (hrd_en), .hrd_slot_i (hrd_slot), .hrd_grp_i (hrd_grp), .hrd_rel_i (hrd_rel),
    .wh_o (wh)
  );

  // ---- Cost aggregator, WTA and depth FIFO ---------------------------------------------------
  logic                 disp_valid;
  logic [4:0]           disp_row_unused;
  logic [2:0]           disp_grp;
  logic [HAGG*DB-1:0]   disp;
  logic                 mon_unused;
  // Sub-pixel values (docs/algorithm.md 12.6), two cycles after the disparities.
  // They go to the depth FIFO in sub-pixel mode. The scheduler still follows
  // busy_o: the WTA's last two stages do not use the census and weight banks,
  // and the depth FIFO holds a row until its last values have arrived.
  localparam int VB = DB + 4;
  logic                 sub_valid, sub_busy_unused;
  logic [4:0]           sub_row_unused;
  logic [2:0]           sub_grp;
  logic [HAGG*VB-1:0]   sub;
  logic [HAGG*DB-1:0]   sub_d;
  // Depth FIFO values: d, 16 d + offset, or in the LR mode's first sub-pixel pass
  // the scratch format {offset + 8, d} (docs/architecture.md section 12).
  localparam int FVB = DB + 5;
  logic                 val_valid;
  logic [2:0]           val_grp;
  logic [HAGG*FVB-1:0]  val, disp_wide, sub_wide, sub_pack;
  logic                 mon_ev_valid, mon_fc_valid;
  logic [4:0]           mon_ev_row, mon_fc_row;
  logic [DB-1:0]        mon_ev_d, mon_fc_d;
  logic [2:0]           mon_ev_grp, mon_fc_grp;
  logic [PAR*LANES*mcadsw_pkg::VCOST_BITS-1:0] mon_ev;
  logic [PAR*HAGG*mcadsw_pkg::FCOST_BITS-1:0]  mon_fc;

  mcadsw_cost_agg #(.P(PAR)) u_cost_agg (
    .clk_i, .rst_ni,
    .job_valid_i (job_valid), .job_ready_o (job_ready), .job_row_i (job_row),
    .job_disp_i (disp_q), .job_last_col_i (job_last_col), .job_wslot_i (wrow_slot),
    .vrd_en_o (vrd_en), .vrd_row_o (vrd_row), .vrd_grp_o (vrd_grp), .vrd_d_o (vrd_d),
    .vrd_slot_o (vrd_slot),
    .cen_l_i (cen_l), .cen_r_i (cen_r), .wv_i (wv),
    .hrd_en_o (hrd_en), .hrd_row_o (hrd_row_unused), .hrd_grp_o (hrd_grp),
    .hrd_slot_o (hrd_slot), .hrd_rel_o (hrd_rel), .wh_i (wh),
    .disp_valid_o (disp_valid), .disp_row_o (disp_row_unused), .disp_grp_o (disp_grp),
    .disp_o (disp), .busy_o (agg_busy),
    .sub_valid_o (sub_valid), .sub_row_o (sub_row_unused), .sub_grp_o (sub_grp),
    .sub_o (sub), .sub_d_o (sub_d), .sub_busy_o (sub_busy_unused),
    .mon_ev_valid_o (mon_ev_valid), .mon_ev_row_o (mon_ev_row), .mon_ev_d_o (mon_ev_d),
    .mon_ev_grp_o (mon_ev_grp), .mon_ev_o (mon_ev),
    .mon_fc_valid_o (mon_fc_valid), .mon_fc_row_o (mon_fc_row), .mon_fc_d_o (mon_fc_d),
    .mon_fc_grp_o (mon_fc_grp), .mon_fc_o (mon_fc)
  );
  // The monitor taps are for the block-level bench; unused here.
  assign mon_unused = ^{mon_ev_valid, mon_ev_row, mon_ev_d, mon_ev_grp, mon_ev,
                        mon_fc_valid, mon_fc_row, mon_fc_d, mon_fc_grp, mon_fc,
                        lrd_busy_unused, rrd_busy_unused, wrd_busy_unused, disp_row_unused,
                        hrd_row_unused, sub_busy_unused, sub_row_unused,
                        cl_busy_unused, cr_busy_unused, wg_busy_unused,
                        cl_cfg_ready_unused, cr_cfg_ready_unused, wg_cfg_ready_unused, post_busy};

  for (genvar m = 0; m < HAGG; m++) begin : g_disp_wide
    logic [4:0] off8;                  // offset + 8 (0 .. 16)
    assign off8 = 5'(sub[m*VB +: VB] - {sub_d[m*DB +: DB], 4'b0000} + VB'(8));
    assign disp_wide[m*FVB +: FVB] = FVB'(disp[m*DB +: DB]);
    assign sub_wide[m*FVB +: FVB]  = FVB'(sub[m*VB +: VB]);
    assign sub_pack[m*FVB +: FVB]  = {off8[4:0], sub_d[m*DB +: DB]};
  end
  assign val_valid = sub_q ? sub_valid : disp_valid;
  assign val_grp   = sub_q ? sub_grp : disp_grp;
  assign val       = pack ? sub_pack : sub_q ? sub_wide : disp_wide;

  mcadsw_depth_fifo #(.AW(AW), .CW(CW), .VB(FVB)) u_depth_fifo (
    .clk_i, .rst_ni,
    .desc_push_i (desc_push), .desc_addr_i (desc_addr), .desc_x_i (desc_x), .desc_n_i (desc_n),
    .space_o (fifo_space), .empty_o (fifo_empty),
    .wide_i (sub_q), .mirror_i (right_q), .xlo_i (xlo_q), .xend_i (xend_q),
    .disp_valid_i (val_valid), .disp_grp_i (val_grp), .disp_i (val),
    .wr_req_o (wr_req), .wr_addr_o (wr_addr), .wr_be_o (wr_be), .wr_wdata_o (wr_wdata),
    .wr_gnt_i (wr_gnt)
  );

endmodule

`default_nettype wire
