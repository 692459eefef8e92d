// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// AXI4-Lite register block: the engine's configuration, control,
// status, interrupt and counters as 32-bit registers. The map (offsets, fields,
// access) is generated into mcadsw_pkg from sw_ref/include/mcadsw/regs.hpp and
// documented in docs/registers.md; docs/memory_map.md gives the meaning of each
// configuration value and the error codes.
//
// Protocol: AW and W are accepted independently (either may come first, one
// of each held); the write happens when both are held and no B response is
// pending, and B follows in the next cycle. One read at a time: AR is accepted
// when no R response is pending, R follows in the next cycle. Responses stay
// valid, with a stable payload, until they are taken. An offset outside the map
// answers SLVERR (reads 0, writes dropped); writes to read-only registers are
// dropped with OKAY. WSTRB is honoured byte by byte.
//
// CTRL.START written 1 starts a frame in the next cycle, with the registers as
// they are after the write (the engine samples its configuration at the start
// and ignores a start while busy); CTRL.ABORT written 1 pulses abort_o
// (mcadsw_top ends a running frame with it). STATUS.DONE and STATUS.ERROR are set when
// the engine's done / error rise (a frame finished, a start was rejected) and
// cleared by writing 1; an event in the cycle of the clear wins. irq_o is
// STATUS.{DONE, ERROR} and IRQ_ENABLE, OR-ed: a level until cleared.
`default_nettype none

module mcadsw_regs #(
  parameter int AW   = 32,                          // engine address width
  parameter int CW   = 12,                          // width / height bits
  parameter int DMAX = mcadsw_pkg::DMAX,
  parameter int PAR  = mcadsw_pkg::PAR,
  parameter int NTHR = mcadsw_pkg::WTHRESHOLDS,
  parameter int DCB  = mcadsw_pkg::COLOR_DIST_BITS,
  parameter int RAB  = $clog2(mcadsw_pkg::REG_SPAN) // register address bits
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  // AXI4-Lite slave (AxPROT ignored)
  input  logic                s_awvalid_i,
  output logic                s_awready_o,
  input  logic [RAB-1:0]      s_awaddr_i,
  input  logic                s_wvalid_i,
  output logic                s_wready_o,
  input  logic [31:0]         s_wdata_i,
  input  logic [3:0]          s_wstrb_i,
  output logic                s_bvalid_o,
  input  logic                s_bready_i,
  output logic [1:0]          s_bresp_o,
  input  logic                s_arvalid_i,
  output logic                s_arready_o,
  input  logic [RAB-1:0]      s_araddr_i,
  output logic                s_rvalid_o,
  input  logic                s_rready_i,
  output logic [31:0]         s_rdata_o,
  output logic [1:0]          s_rresp_o,
  output logic                irq_o,
  // The engine's configuration: one bundle, its fields at mcadsw_pkg::CFG_* (generated from
  // sw_ref/include/mcadsw/regs.hpp kCfgFields; docs/memory_map.md); and start
  output logic [mcadsw_pkg::CFG_BITS-1:0] cfg_o,
  output logic                start_o,
  output logic                abort_o,         // CTRL.ABORT written 1 (a pulse)
  // Engine status
  input  logic                busy_i,
  input  logic                done_i,
  input  logic                error_i,
  input  logic [7:0]          error_code_i,
  input  logic [31:0]         cnt_cycles_i,
  input  logic [31:0]         cnt_words_read_i,
  input  logic [31:0]         cnt_words_written_i,
  input  logic [31:0]         cnt_stall_i
);
  localparam logic [1:0] OKAY = 2'b00, SLVERR = 2'b10;
  localparam int NREG = mcadsw_pkg::REG_SPAN / 4;  // word slots decoded
  // Slots (byte offset / 4) and field positions of the generated map, by short names.
  localparam int S_ID     = mcadsw_pkg::REG_ID / 4;
  localparam int S_VER    = mcadsw_pkg::REG_VERSION / 4;
  localparam int S_HWCFG  = mcadsw_pkg::REG_HWCONFIG / 4;
  localparam int S_CTRL   = mcadsw_pkg::REG_CTRL / 4;
  localparam int S_STATUS = mcadsw_pkg::REG_STATUS / 4;
  localparam int S_IRQEN  = mcadsw_pkg::REG_IRQ_ENABLE / 4;
  localparam int S_IRQST  = mcadsw_pkg::REG_IRQ_STATUS / 4;
  localparam int S_BASE0  = mcadsw_pkg::REG_BASE_LY / 4;     // BASE_LY .. BASE_MASK: 10 slots
  localparam int S_STRIDE = mcadsw_pkg::REG_STRIDE / 4;
  localparam int S_OSTR   = mcadsw_pkg::REG_OUT_STRIDE / 4;
  localparam int S_SIZE   = mcadsw_pkg::REG_SIZE / 4;
  localparam int S_DISP   = mcadsw_pkg::REG_DISP / 4;
  localparam int S_LRT    = mcadsw_pkg::REG_LR_T / 4;
  localparam int S_TILE   = mcadsw_pkg::REG_TILE_STRIDE / 4;
  localparam int S_THR0   = mcadsw_pkg::REG_THR0 / 4;        // THR0 .. THR6: NTHR slots
  localparam int S_CYC    = mcadsw_pkg::REG_CYCLES / 4;
  localparam int S_RD     = mcadsw_pkg::REG_WORDS_READ / 4;
  localparam int S_WR     = mcadsw_pkg::REG_WORDS_WRITTEN / 4;
  localparam int S_STALL  = mcadsw_pkg::REG_STALLS / 4;
  localparam int S_RCTRL  = mcadsw_pkg::REG_RECT_CTRL / 4;
  localparam int S_RSIZE  = mcadsw_pkg::REG_RAW_SIZE / 4;
  localparam int S_RAW0   = mcadsw_pkg::REG_RAW_STRIDE / 4;  // RAW_STRIDE, RAW_LY .. RAW_RV, MESH_L, MESH_R
  localparam int NRAW     = 9;
  localparam int S_NODES  = mcadsw_pkg::REG_MESH_NODES / 4;
  localparam int S_VAL0   = mcadsw_pkg::REG_VALID_L / 4;     // VALID_L, VALID_R
  localparam int NBASE    = 10;
  localparam int F_START  = mcadsw_pkg::CTRL_START_LSB;
  localparam int F_ABORT  = mcadsw_pkg::CTRL_ABORT_LSB;
  localparam int F_MODE   = mcadsw_pkg::CTRL_MODE_LSB;
  localparam int F_BUSY   = mcadsw_pkg::STATUS_BUSY_LSB;
  localparam int F_DONE   = mcadsw_pkg::STATUS_DONE_LSB;
  localparam int F_ERROR  = mcadsw_pkg::STATUS_ERROR_LSB;
  localparam int F_CODE   = mcadsw_pkg::STATUS_ERROR_CODE_LSB;
  localparam int F_IDONE  = mcadsw_pkg::IRQ_ENABLE_DONE_LSB;  // IRQ_STATUS: the same bits
  localparam int F_IERR   = mcadsw_pkg::IRQ_ENABLE_ERROR_LSB;
  localparam int F_WIDTH  = mcadsw_pkg::SIZE_WIDTH_LSB;
  localparam int F_HEIGHT = mcadsw_pkg::SIZE_HEIGHT_LSB;
  localparam int F_D      = mcadsw_pkg::DISP_D_LSB;
  localparam int DW       = mcadsw_pkg::DISP_D_W;
  localparam int F_T      = mcadsw_pkg::LR_T_T_LSB;
  localparam int F_REN    = mcadsw_pkg::RECT_CTRL_ENABLE_LSB;
  localparam int F_RSTEP  = mcadsw_pkg::RECT_CTRL_STEP_LOG2_LSB;
  localparam int F_RW     = mcadsw_pkg::RAW_SIZE_WIDTH_LSB;
  localparam int F_RH     = mcadsw_pkg::RAW_SIZE_HEIGHT_LSB;
  localparam int F_NX     = mcadsw_pkg::MESH_NODES_NX_LSB;
  localparam int F_NY     = mcadsw_pkg::MESH_NODES_NY_LSB;

  if (AW != 32 || CW != mcadsw_pkg::SIZE_WIDTH_W || CW != mcadsw_pkg::SIZE_HEIGHT_W ||
      DMAX > (1 << DW) - 1 || NTHR != 7 || DCB > 32 || mcadsw_pkg::CTRL_MODE_W != 3 ||
      mcadsw_pkg::LR_T_T_W != 8 || S_BASE0 + NBASE - 1 != mcadsw_pkg::REG_BASE_MASK / 4 ||
      S_THR0 + NTHR - 1 != mcadsw_pkg::REG_THR6 / 4 ||
      F_IDONE != mcadsw_pkg::IRQ_STATUS_DONE_LSB ||
      F_IERR != mcadsw_pkg::IRQ_STATUS_ERROR_LSB ||
      S_RAW0 + NRAW - 1 != mcadsw_pkg::REG_MESH_R / 4 || S_VAL0 + 1 != mcadsw_pkg::REG_VALID_R / 4 ||
      mcadsw_pkg::RECT_CTRL_STEP_LOG2_W != 3 || mcadsw_pkg::RAW_SIZE_WIDTH_W != CW ||
      mcadsw_pkg::RAW_SIZE_HEIGHT_W != CW || mcadsw_pkg::MESH_NODES_NX_W != CW ||
      mcadsw_pkg::MESH_NODES_NY_W != CW || mcadsw_pkg::STATUS_ERROR_CODE_W != 8 ||
      mcadsw_pkg::CFG_WIDTH_W != CW || mcadsw_pkg::CFG_DISP_W != DW ||
      mcadsw_pkg::CFG_THR_W != NTHR * DCB) begin : g_bad_param
    mcadsw_error_regs_geometry u_error ();
  end

  // Slots that exist (everything else answers SLVERR).
  function automatic logic slot_mapped(input int s);
    slot_mapped = s == S_ID || s == S_VER || s == S_HWCFG || s == S_CTRL || s == S_STATUS ||
                  s == S_IRQEN || s == S_IRQST || (s >= S_BASE0 && s < S_BASE0 + NBASE) ||
                  s == S_STRIDE || s == S_OSTR || s == S_SIZE || s == S_DISP || s == S_LRT || s == S_TILE ||
                  (s >= S_THR0 && s < S_THR0 + NTHR) || s == S_CYC || s == S_RD || s == S_WR ||
                  s == S_STALL || s == S_RCTRL || s == S_RSIZE || (s >= S_RAW0 && s < S_RAW0 + NRAW) ||
                  s == S_NODES || s == S_VAL0 || s == S_VAL0 + 1;
  endfunction

  // ---- Register file ---------------------------------------------------------------
  logic [NBASE*32-1:0]   base_q;     // BASE_LY .. BASE_MASK, base i at 32 i
  logic [31:0]           stride_q, out_stride_q, tile_q;
  logic [2:0]            mode_q;
  logic [CW-1:0]         width_q, height_q;
  logic [DW-1:0]         disp_q;
  logic [7:0]            lr_t_q;
  logic [NTHR*DCB-1:0]   thr_q;      // threshold i at DCB i
  logic [NRAW*32-1:0]    raw_q;      // RAW_STRIDE, RAW_LY .. RAW_RV, MESH_L, MESH_R
  logic [2*32-1:0]       valid_q;    // VALID_L, VALID_R
  logic                  rect_en_q;
  logic [2:0]            rect_step_q;
  logic [CW-1:0]         raw_w_q, raw_h_q, nx_q, ny_q;
  logic                  done_q, error_q;      // STATUS sticky bits
  logic [1:0]            irq_en_q;             // bit 0 done, bit 1 error
  logic                  start_q, abort_q;
  logic                  done_d_q, error_d_q;  // the engine's levels a cycle ago

  // ---- Write channel -----------------------------------------------------------------
  logic           aw_full_q, w_full_q, bvalid_q;
  logic [RAB-1:0] awaddr_q;
  logic [31:0]    wdata_q;
  logic [3:0]     wstrb_q;
  logic [1:0]     bresp_q;
  logic           wr;                  // the held write happens this cycle
  logic [RAB-3:0] wslot;
  logic           wok;                 // ... to a mapped, aligned offset

  assign s_awready_o = !aw_full_q;
  assign s_wready_o  = !w_full_q;
  assign s_bvalid_o  = bvalid_q;
  assign s_bresp_o   = bresp_q;
  assign wr          = aw_full_q && w_full_q && !bvalid_q;
  assign wslot       = awaddr_q[RAB-1:2];

  logic [NREG-1:0] mapped;
  for (genvar s = 0; s < NREG; s++) begin : g_mapped
    assign mapped[s] = slot_mapped(s);
  end
  assign wok = wr && awaddr_q[1:0] == 2'b00 && mapped[wslot];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      aw_full_q <= 1'b0;
      w_full_q  <= 1'b0;
      bvalid_q  <= 1'b0;
      awaddr_q  <= '0;
      wdata_q   <= '0;
      wstrb_q   <= '0;
      bresp_q   <= OKAY;
    end else begin
      if (s_awvalid_i && s_awready_o) begin
        aw_full_q <= 1'b1;
        awaddr_q  <= s_awaddr_i;
      end
      if (s_wvalid_i && s_wready_o) begin
        w_full_q <= 1'b1;
        wdata_q  <= s_wdata_i;
        wstrb_q  <= s_wstrb_i;
      end
      if (wr) begin
        aw_full_q <= 1'b0;
        w_full_q  <= 1'b0;
        bvalid_q  <= 1'b1;
        bresp_q   <= wok ? OKAY : SLVERR;
      end else if (bvalid_q && s_bready_i) begin
        bvalid_q <= 1'b0;
      end
    end
  end

  // The value a write leaves in a slot: the written bytes (WSTRB) over the slot's own
  // value, merged under each slot's own write rather than over a selected old value: a
  // byte not written keeps its flip-flops (synthesis makes the strobe part of each
  // byte's enable), and no NREG:1 select of the old value lies in the write path.
  logic [NREG*32-1:0] cur;             // each slot's value as read, slot s at 32 s
  function automatic logic [31:0] merged(input logic [31:0] old);
    logic [31:0] v;
    for (int b = 0; b < 4; b++) v[8*b +: 8] = wstrb_q[b] ? wdata_q[8*b +: 8] : old[8*b +: 8];
    merged = v;
  endfunction
  logic [NREG-1:0] hit;                // slot s is written this cycle
  for (genvar s = 0; s < NREG; s++) begin : g_hit
    assign hit[s] = wok && 32'(wslot) == s;
  end

  // ---- Registers ---------------------------------------------------------------------
  for (genvar i = 0; i < NBASE; i++) begin : g_base
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) base_q[i*32 +: 32] <= '0;
      else if (hit[S_BASE0 + i]) base_q[i*32 +: 32] <= merged(cur[(S_BASE0 + i)*32 +: 32]);
    end
  end
  for (genvar i = 0; i < NRAW; i++) begin : g_raw
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) raw_q[i*32 +: 32] <= '0;
      else if (hit[S_RAW0 + i]) raw_q[i*32 +: 32] <= merged(cur[(S_RAW0 + i)*32 +: 32]);
    end
  end
  for (genvar i = 0; i < 2; i++) begin : g_valid
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) valid_q[i*32 +: 32] <= '0;
      else if (hit[S_VAL0 + i]) valid_q[i*32 +: 32] <= merged(cur[(S_VAL0 + i)*32 +: 32]);
    end
  end
  for (genvar i = 0; i < NTHR; i++) begin : g_thr
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) thr_q[i*DCB +: DCB] <= '0;
      else if (hit[S_THR0 + i]) thr_q[i*DCB +: DCB] <= DCB'(merged(cur[(S_THR0 + i)*32 +: 32]));
    end
  end

  // W1C: a byte not written clears nothing. START: the bit written 1.
  logic clr_done, clr_error, start, abort;
  assign clr_done  = hit[S_STATUS] && wstrb_q[F_DONE / 8] && wdata_q[F_DONE];
  assign clr_error = hit[S_STATUS] && wstrb_q[F_ERROR / 8] && wdata_q[F_ERROR];
  assign start     = hit[S_CTRL] && wstrb_q[F_START / 8] && wdata_q[F_START];
  assign abort     = hit[S_CTRL] && wstrb_q[F_ABORT / 8] && wdata_q[F_ABORT];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      stride_q     <= '0;
      out_stride_q <= '0;
      tile_q       <= '0;
      mode_q       <= '0;
      width_q      <= '0;
      height_q     <= '0;
      disp_q       <= '0;
      lr_t_q       <= '0;
      rect_en_q    <= 1'b0;
      rect_step_q  <= '0;
      {raw_w_q, raw_h_q, nx_q, ny_q} <= '0;
      irq_en_q     <= '0;
      start_q      <= 1'b0;
      abort_q      <= 1'b0;
      done_q       <= 1'b0;
      error_q      <= 1'b0;
      done_d_q     <= 1'b0;
      error_d_q    <= 1'b0;
    end else begin
      if (hit[S_STRIDE]) stride_q <= merged(cur[S_STRIDE*32 +: 32]);
      if (hit[S_OSTR]) out_stride_q <= merged(cur[S_OSTR*32 +: 32]);
      if (hit[S_TILE]) tile_q <= merged(cur[S_TILE*32 +: 32]);
      if (hit[S_SIZE]) begin
        width_q  <= CW'(merged(cur[S_SIZE*32 +: 32]) >> F_WIDTH);
        height_q <= CW'(merged(cur[S_SIZE*32 +: 32]) >> F_HEIGHT);
      end
      if (hit[S_DISP]) disp_q <= DW'(merged(cur[S_DISP*32 +: 32]) >> F_D);
      if (hit[S_LRT]) lr_t_q <= 8'(merged(cur[S_LRT*32 +: 32]) >> F_T);
      if (hit[S_RCTRL]) begin
        rect_en_q   <= 1'(merged(cur[S_RCTRL*32 +: 32]) >> F_REN);
        rect_step_q <= 3'(merged(cur[S_RCTRL*32 +: 32]) >> F_RSTEP);
      end
      if (hit[S_RSIZE]) begin
        raw_w_q <= CW'(merged(cur[S_RSIZE*32 +: 32]) >> F_RW);
        raw_h_q <= CW'(merged(cur[S_RSIZE*32 +: 32]) >> F_RH);
      end
      if (hit[S_NODES]) begin
        nx_q <= CW'(merged(cur[S_NODES*32 +: 32]) >> F_NX);
        ny_q <= CW'(merged(cur[S_NODES*32 +: 32]) >> F_NY);
      end
      if (hit[S_IRQEN])
        irq_en_q <= {1'(merged(cur[S_IRQEN*32 +: 32]) >> F_IERR), 1'(merged(cur[S_IRQEN*32 +: 32]) >> F_IDONE)};
      if (hit[S_CTRL]) mode_q <= 3'(merged(cur[S_CTRL*32 +: 32]) >> F_MODE);
      start_q   <= start;
      abort_q   <= abort;
      done_d_q  <= done_i;
      error_d_q <= error_i;
      // Sticky events; a rising edge wins over a clear in the same cycle.
      if (done_i && !done_d_q) done_q <= 1'b1;
      else if (clr_done) done_q <= 1'b0;
      if (error_i && !error_d_q) error_q <= 1'b1;
      else if (clr_error) error_q <= 1'b0;
    end
  end

  // ---- Read values ---------------------------------------------------------------------
  logic [1:0] irq_pend;                // {error, done} pending and enabled
  assign irq_pend = {error_q && irq_en_q[1], done_q && irq_en_q[0]};
  assign irq_o    = |irq_pend;

  // Unmapped slots read 0; each mapped slot is assigned once below.
  for (genvar s = 0; s < NREG; s++) begin : g_unmapped
    if (!slot_mapped(s)) begin : g_zero
      assign cur[s*32 +: 32] = '0;
    end
  end
  assign cur[S_ID*32 +: 32]     = mcadsw_pkg::ID_VALUE;
  assign cur[S_VER*32 +: 32]    = 32'(mcadsw_pkg::VERSION_MAJOR << mcadsw_pkg::VERSION_MAJOR_LSB) |
                                  32'(mcadsw_pkg::VERSION_MINOR << mcadsw_pkg::VERSION_MINOR_LSB);
  assign cur[S_HWCFG*32 +: 32]  = 32'(DMAX << mcadsw_pkg::HWCONFIG_DMAX_LSB) |
                                  32'(PAR << mcadsw_pkg::HWCONFIG_PAR_LSB) |
                                  32'((mcadsw_pkg::RECT == 0 ? 1 : 0) << mcadsw_pkg::HWCONFIG_NORECT_LSB);
  assign cur[S_CTRL*32 +: 32]   = 32'(mode_q) << F_MODE;
  assign cur[S_STATUS*32 +: 32] = (32'(busy_i) << F_BUSY) | (32'(done_q) << F_DONE) |
                                  (32'(error_q) << F_ERROR) | (32'(error_code_i) << F_CODE);
  assign cur[S_IRQEN*32 +: 32]  = (32'(irq_en_q[0]) << F_IDONE) | (32'(irq_en_q[1]) << F_IERR);
  assign cur[S_IRQST*32 +: 32]  = (32'(irq_pend[0]) << F_IDONE) | (32'(irq_pend[1]) << F_IERR);
  assign cur[S_BASE0*32 +: NBASE*32] = base_q;
  assign cur[S_STRIDE*32 +: 32] = stride_q;
  assign cur[S_OSTR*32 +: 32]   = out_stride_q;
  assign cur[S_TILE*32 +: 32]   = tile_q;
  assign cur[S_SIZE*32 +: 32]   = (32'(width_q) << F_WIDTH) | (32'(height_q) << F_HEIGHT);
  assign cur[S_DISP*32 +: 32]   = 32'(disp_q) << F_D;
  assign cur[S_LRT*32 +: 32]    = 32'(lr_t_q) << F_T;
  for (genvar i = 0; i < NTHR; i++) begin : g_thr_rd
    assign cur[(S_THR0 + i)*32 +: 32] = 32'(thr_q[i*DCB +: DCB]);
  end
  assign cur[S_RCTRL*32 +: 32]  = (32'(rect_en_q) << F_REN) | (32'(rect_step_q) << F_RSTEP);
  assign cur[S_RSIZE*32 +: 32]  = (32'(raw_w_q) << F_RW) | (32'(raw_h_q) << F_RH);
  assign cur[S_RAW0*32 +: NRAW*32] = raw_q;
  assign cur[S_NODES*32 +: 32]  = (32'(nx_q) << F_NX) | (32'(ny_q) << F_NY);
  assign cur[S_VAL0*32 +: 64]   = valid_q;
  assign cur[S_CYC*32 +: 32]    = cnt_cycles_i;
  assign cur[S_RD*32 +: 32]     = cnt_words_read_i;
  assign cur[S_WR*32 +: 32]     = cnt_words_written_i;
  assign cur[S_STALL*32 +: 32]  = cnt_stall_i;

  // ---- Read channel ----------------------------------------------------------------------
  logic           rvalid_q;
  logic [31:0]    rdata_q;
  logic [1:0]     rresp_q;
  logic [RAB-3:0] rslot;
  logic           rok;
  assign rslot       = s_araddr_i[RAB-1:2];
  assign rok         = s_araddr_i[1:0] == 2'b00 && mapped[rslot];
  assign s_arready_o = !rvalid_q;
  assign s_rvalid_o  = rvalid_q;
  assign s_rdata_o   = rdata_q;
  assign s_rresp_o   = rresp_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rvalid_q <= 1'b0;
      rdata_q  <= '0;
      rresp_q  <= OKAY;
    end else if (s_arvalid_i && s_arready_o) begin
      rvalid_q <= 1'b1;
      rdata_q  <= rok ? cur[32'(rslot)*32 +: 32] : '0;
      rresp_q  <= rok ? OKAY : SLVERR;
    end else if (rvalid_q && s_rready_i) begin
      rvalid_q <= 1'b0;
    end
  end

  // ---- Engine side ---------------------------------------------------------------------------
  // The bundle, field by field (DISP.D: 0 when above DMAX, so that the engine rejects the
  // start with code 3).
  assign cfg_o[mcadsw_pkg::CFG_BASE_LY +: 32]     = base_q[0*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_LU +: 32]     = base_q[1*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_LV +: 32]     = base_q[2*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_RY +: 32]     = base_q[3*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_RU +: 32]     = base_q[4*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_RV +: 32]     = base_q[5*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_OUT +: 32]    = base_q[6*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_DL +: 32]     = base_q[7*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_DR +: 32]     = base_q[8*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_BASE_MASK +: 32]   = base_q[9*32 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_STRIDE +: 32]      = stride_q;
  assign cfg_o[mcadsw_pkg::CFG_OUT_STRIDE +: 32]  = out_stride_q;
  assign cfg_o[mcadsw_pkg::CFG_TILE_STRIDE +: 32] = tile_q;
  assign cfg_o[mcadsw_pkg::CFG_MODE +: 3]         = mode_q;
  assign cfg_o[mcadsw_pkg::CFG_LR_T +: 8]         = lr_t_q;
  assign cfg_o[mcadsw_pkg::CFG_WIDTH +: CW]       = width_q;
  assign cfg_o[mcadsw_pkg::CFG_HEIGHT +: CW]      = height_q;
  assign cfg_o[mcadsw_pkg::CFG_DISP +: DW]        = (32'(disp_q) > DMAX) ? '0 : disp_q;
  assign cfg_o[mcadsw_pkg::CFG_THR +: NTHR*DCB]   = thr_q;
  assign cfg_o[mcadsw_pkg::CFG_RECT_EN]           = rect_en_q;
  assign cfg_o[mcadsw_pkg::CFG_RECT_STEP +: 3]    = rect_step_q;
  assign cfg_o[mcadsw_pkg::CFG_RAW_WIDTH +: CW]   = raw_w_q;
  assign cfg_o[mcadsw_pkg::CFG_RAW_HEIGHT +: CW]  = raw_h_q;
  assign cfg_o[mcadsw_pkg::CFG_RAW_STRIDE +: 32]  = raw_q[0 +: 32];
  assign cfg_o[mcadsw_pkg::CFG_RAW +: 6*32]       = raw_q[32 +: 6*32];
  assign cfg_o[mcadsw_pkg::CFG_MESH +: 2*32]      = raw_q[7*32 +: 2*32];
  assign cfg_o[mcadsw_pkg::CFG_MESH_NX +: CW]     = nx_q;
  assign cfg_o[mcadsw_pkg::CFG_MESH_NY +: CW]     = ny_q;
  assign cfg_o[mcadsw_pkg::CFG_VALID_MAP +: 2*32] = valid_q;
  assign start_o          = start_q;
  assign abort_o          = abort_q;

endmodule

`default_nettype wire
