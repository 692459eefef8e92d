// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Configuration check of a frame (docs/registers.md, error codes 1-12 and 24): the
// configuration the engine registered at the start, checked in the cycle after it.
// The verdict is combinational from the registered configuration and registered here
// (err_o, ok_o, done_o) at the end of that cycle, so that the frame controller's branch
// on it in its Check state starts from flip-flops; a non-zero code rejects the start
// before anything is read or written. The plane sizes (products of a stride and a
// height) are the one registered part: computed from the configuration as it is
// registered (cap_cfg_i at capture_i, the engine's start), so that no multiplier lies
// in front of the address compares in the check's cycle.
//
// SEQ (the FPGA target): the plane checks (overlap, beyond the address space) run one
// pair of planes a cycle, 42 cycles (4 written planes x 10, and 2 stages) from the
// cycle after capture_i, through one overlap unit instead of 30 (a frame decides
// them once; on an FPGA the parallel compares were about 3k LUT sites). done_o is
// low until they are decided and the engine's frame controller waits for it;
// without SEQ done_o is always high and the check is the combinational one
// described above.
//
// Plane sizes and ends are exact (AW + CW bits), so no plane wraps around the
// address space. The planes a mode reads and writes (docs/memory_map.md):
//   read   base view Y, U, V and match view Y (the left view as base, or the right
//          with mode bit 2); in the LR mode also the right U and V
//   write  the first pass's output: the disparity plane, or in the LR mode dL;
//          in the LR mode also dR, the disparity plane and the mask
// dL and the disparity plane have the output stride, the others the input stride.
`default_nettype none

module mcadsw_cfg_check #(
  parameter int AW   = 32,                            // address bits
  parameter int CW   = 12,                            // width / height bits
  parameter int DMAX = mcadsw_pkg::DMAX,              // largest D this build supports
  parameter int NB   = $clog2(DMAX + 1),              // D bits
  parameter int SB   = AW + CW,                       // plane sizes: stride x height (or x columns), exact
  parameter bit SEQ  = 1'(mcadsw_pkg::FPGA)           // plane checks a pair a cycle (done_o)
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  // The configuration bundle as it is being registered (the engine's capture input,
  // read at capture_i for the sizes) and as registered (fields at mcadsw_pkg::CFG_*)
  input  logic            capture_i,
  input  logic [mcadsw_pkg::CFG_BITS-1:0] cap_cfg_i,
  input  logic [mcadsw_pkg::CFG_BITS-1:0] cfg_i,
  // mcadsw_pkg::ErrNone, or the first failing check's code; registered: the verdict
  // on the configuration of the cycle before
  output logic [mcadsw_pkg::ERR_BITS-1:0] err_o,
  output logic            ok_o,              // err_o == ErrNone
  output logic            done_o,            // err_o and ok_o are the configuration's (SEQ: low
                                             // from the second cycle after capture_i for 42 cycles)
  // The sizes of the checked planes, for the rectifier's check (mcadsw_rect_check);
  // registered: valid from the cycle after capture_i
  output logic [SB-1:0]   in_size_o,         // an input plane
  output logic [SB-1:0]   size_o,            // stride x height: dR, the mask
  output logic [SB-1:0]   out_size_o         // out stride x height: the disparity plane, dL
);

  // The fields the check reads (cap_*: as being registered)
  logic [AW-1:0] cap_stride, cap_out_stride, cap_tile_stride, stride, out_stride, tile_stride;
  logic [AW-1:0] base_ly, base_lu, base_lv, base_ry, base_ru, base_rv;
  logic [AW-1:0] base_out, base_dl, base_dr, base_mask;
  logic [CW-1:0] cap_width, cap_height, width, height;
  logic [7:0]    lr_t;
  logic [NB-1:0] disp;
  logic          sub, lr, right, rect;
  assign cap_stride      = cap_cfg_i[mcadsw_pkg::CFG_STRIDE +: AW];
  assign cap_out_stride  = cap_cfg_i[mcadsw_pkg::CFG_OUT_STRIDE +: AW];
  assign cap_tile_stride = cap_cfg_i[mcadsw_pkg::CFG_TILE_STRIDE +: AW];
  assign cap_width       = cap_cfg_i[mcadsw_pkg::CFG_WIDTH +: CW];
  assign cap_height      = cap_cfg_i[mcadsw_pkg::CFG_HEIGHT +: CW];
  assign base_ly         = cfg_i[mcadsw_pkg::CFG_BASE_LY +: AW];
  assign base_lu         = cfg_i[mcadsw_pkg::CFG_BASE_LU +: AW];
  assign base_lv         = cfg_i[mcadsw_pkg::CFG_BASE_LV +: AW];
  assign base_ry         = cfg_i[mcadsw_pkg::CFG_BASE_RY +: AW];
  assign base_ru         = cfg_i[mcadsw_pkg::CFG_BASE_RU +: AW];
  assign base_rv         = cfg_i[mcadsw_pkg::CFG_BASE_RV +: AW];
  assign base_out        = cfg_i[mcadsw_pkg::CFG_BASE_OUT +: AW];
  assign base_dl         = cfg_i[mcadsw_pkg::CFG_BASE_DL +: AW];
  assign base_dr         = cfg_i[mcadsw_pkg::CFG_BASE_DR +: AW];
  assign base_mask       = cfg_i[mcadsw_pkg::CFG_BASE_MASK +: AW];
  assign stride          = cfg_i[mcadsw_pkg::CFG_STRIDE +: AW];
  assign out_stride      = cfg_i[mcadsw_pkg::CFG_OUT_STRIDE +: AW];
  assign tile_stride     = cfg_i[mcadsw_pkg::CFG_TILE_STRIDE +: AW];
  assign lr_t            = cfg_i[mcadsw_pkg::CFG_LR_T +: 8];
  assign width           = cfg_i[mcadsw_pkg::CFG_WIDTH +: CW];
  assign height          = cfg_i[mcadsw_pkg::CFG_HEIGHT +: CW];
  assign disp            = cfg_i[mcadsw_pkg::CFG_DISP +: NB];
  assign {right, lr, sub} = cfg_i[mcadsw_pkg::CFG_MODE +: 3];
  assign rect            = cfg_i[mcadsw_pkg::CFG_RECT_EN];
  logic cfg_unused;                          // the fields other blocks read
  assign cfg_unused = ^{cap_cfg_i, cfg_i};

  // The checks in priority order, check c failing gives code CODES[c].
  localparam int NCHECK = 13;
  localparam int EB = mcadsw_pkg::ERR_BITS;
  localparam logic [NCHECK*EB-1:0] CODES = {
    EB'(mcadsw_pkg::ErrNoRect),
    EB'(mcadsw_pkg::ErrLrColour), EB'(mcadsw_pkg::ErrLrWidth), EB'(mcadsw_pkg::ErrLrTolerance),
    EB'(mcadsw_pkg::ErrBeyond), EB'(mcadsw_pkg::ErrMode), EB'(mcadsw_pkg::ErrOutStride),
    EB'(mcadsw_pkg::ErrOverlap), EB'(mcadsw_pkg::ErrAlign), EB'(mcadsw_pkg::ErrStride),
    EB'(mcadsw_pkg::ErrDisp), EB'(mcadsw_pkg::ErrHeight), EB'(mcadsw_pkg::ErrWidth)};
  logic [NCHECK-1:0] fail;

  // a < b + b_size, exactly: an address below an end at or past 2^AW always is, so
  // the compare needs only the end's low AW bits (the sum itself is shared by the
  // pairs of a plane: synthesis merges the identical adders).
  function automatic logic below(input logic [AW-1:0] a, input logic [SB:0] end_);
    below = (end_ >> AW) != '0 || a < AW'(end_);
  endfunction
  function automatic logic below_end(input logic [AW-1:0] a, input logic [AW-1:0] b,
                                     input logic [SB-1:0] b_size);
    below_end = below(a, (SB + 1)'(b) + (SB + 1)'(b_size));
  endfunction
  function automatic logic overlaps(input logic [AW-1:0] a, input logic [SB-1:0] a_size,
                                    input logic [AW-1:0] b, input logic [SB-1:0] b_size);
    overlaps = below_end(a, b, b_size) && below_end(b, a, a_size);
  endfunction
  // A plane's end (base + size, exact) past the address space.
  function automatic logic past_end(input logic [SB:0] end_);
    past_end = end_ > (SB + 1)'(64'd1 << AW);
  endfunction
  function automatic logic beyond(input logic [AW-1:0] base, input logic [SB-1:0] size);
    beyond = past_end((SB + 1)'(base) + (SB + 1)'(size));
  endfunction

  // The first pass's planes: base view Y, U, V and match view Y.
  logic [AW-1:0] base_by, base_bu, base_bv, base_my, base_first;
  assign base_by    = right ? base_ry : base_ly;
  assign base_bu    = right ? base_ru : base_lu;
  assign base_bv    = right ? base_rv : base_lv;
  assign base_my    = right ? base_ly : base_ry;
  assign base_first = lr ? base_dl : base_out;

  // Planes the frame reads (in) and writes (wr), and which are enabled.
  localparam int NIN = 6, NWR = 4;
  logic [NIN*AW-1:0] in_base;
  logic [NIN-1:0]    in_en;
  logic [NWR*AW-1:0] wr_base;
  logic [NWR-1:0]    wr_en, wr_outs;   // wr_outs: the plane has the output stride
  assign in_base = {base_rv, base_ru, base_my, base_bv, base_bu, base_by};
  assign in_en   = {lr, lr, 4'b1111};
  assign wr_base = {base_mask, base_out, base_dr, base_first};
  assign wr_en   = {lr, lr, lr, 1'b1};
  assign wr_outs = 4'b0101;

  // The sizes, registered with the configuration. The input planes: raster, stride x
  // height; column-tiled, tile x the columns of 4 pixels.
  logic [SB-1:0] size, in_size, out_size;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      {size, in_size, out_size} <= '0;
    end else if (capture_i) begin : p_capture
      logic [CW-1:0] wcols;            // columns of 4 pixels
      wcols    = cap_width + CW'(3);
      wcols    = wcols >> 2;
      size     <= SB'(cap_stride) * SB'(cap_height);
      in_size  <= (cap_tile_stride != '0) ? SB'(cap_tile_stride) * SB'(wcols)
                                            : SB'(cap_stride) * SB'(cap_height);
      out_size <= SB'(cap_out_stride) * SB'(cap_height);
    end
  end

  // The plane checks: any enabled plane beyond the address space (past), any written
  // plane overlapping another enabled plane (overlap).
  logic overlap, past;
  logic [mcadsw_pkg::ERR_BITS-1:0] err;     // the verdict, before its register
  logic ok, done;
  if (!SEQ) begin : g_par
    always_comb begin
      past    = 1'b0;
      overlap = 1'b0;
      for (int i = 0; i < NIN; i++)
        past = past || (in_en[i] && beyond(in_base[i*AW +: AW], in_size));
      for (int o = 0; o < NWR; o++) begin
        past = past || (wr_en[o] && beyond(wr_base[o*AW +: AW], wr_outs[o] ? out_size : size));
        for (int i = 0; i < NIN; i++)
          overlap = overlap || (wr_en[o] && in_en[i] &&
                                overlaps(wr_base[o*AW +: AW], wr_outs[o] ? out_size : size,
                                         in_base[i*AW +: AW], in_size));
        for (int p = 0; p < NWR; p++)       // each pair once: p > o
          overlap = overlap || (p > o && wr_en[o] && wr_en[p] &&
                                overlaps(wr_base[o*AW +: AW], wr_outs[o] ? out_size : size,
                                         wr_base[p*AW +: AW], wr_outs[p] ? out_size : size));
      end
    end
    assign done = 1'b1;
  end else begin : g_seq
    // Step (o, x), o the written plane (0..NWR-1), x any plane (0..NWR-1 the written
    // ones, NWR.. the read ones): both planes' ends beyond the address space, and
    // their overlap when they are a pair (x read, or written and x > o). Every
    // written plane is an o and every read plane an x, so every plane's end is
    // checked; the steps x <= o of written planes only repeat ends. Three stages a
    // step (timing): the planes' select, their ends, the compares.
    localparam int NPL = NWR + NIN;
    logic [$clog2(NWR)-1:0] o_q;
    logic [$clog2(NPL)-1:0] x_q;
    logic                   busy_q, overlap_q, past_q;
    logic [AW-1:0]          a_base, b_base, a_base1_q, b_base1_q, a_base2_q, b_base2_q;
    logic [SB-1:0]          a_size, b_size, a_size1_q, b_size1_q;
    logic [SB:0]            a_end2_q, b_end2_q;
    logic                   a_en, b_en, pair;
    logic [1:0]             v_q, a_en_q, b_en_q, pair_q;   // [0] stage 1, [1] stage 2
    always_comb begin
      a_base = wr_base[o_q*AW +: AW];
      a_size = wr_outs[o_q] ? out_size : size;
      a_en   = wr_en[o_q];
      if (32'(x_q) < NWR) begin
        b_base = wr_base[2'(x_q)*AW +: AW];
        b_size = wr_outs[2'(x_q)] ? out_size : size;
        b_en   = wr_en[2'(x_q)];
        pair   = 32'(x_q) > 32'(o_q);
      end else begin
        b_base = in_base[3'(32'(x_q) - NWR)*AW +: AW];
        b_size = in_size;
        b_en   = in_en[3'(32'(x_q) - NWR)];
        pair   = 1'b1;
      end
    end
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        {busy_q, overlap_q, past_q} <= '0;
        o_q <= '0;
        x_q <= '0;
        {v_q, a_en_q, b_en_q, pair_q} <= '0;
        {a_base1_q, b_base1_q, a_base2_q, b_base2_q, a_size1_q, b_size1_q, a_end2_q, b_end2_q} <= '0;
      end else if (capture_i) begin
        {busy_q, overlap_q, past_q} <= 3'b100;
        o_q <= '0;
        x_q <= '0;
        v_q <= '0;
      end else begin
        // stage 0: the step's planes
        v_q[0]    <= busy_q;
        a_en_q[0] <= a_en;
        b_en_q[0] <= b_en;
        pair_q[0] <= pair;
        a_base1_q <= a_base;
        b_base1_q <= b_base;
        a_size1_q <= a_size;
        b_size1_q <= b_size;
        if (busy_q) begin
          if (32'(x_q) == NPL - 1) begin
            x_q <= '0;
            o_q <= o_q + 1'b1;
            if (32'(o_q) == NWR - 1) busy_q <= 1'b0;
          end else begin
            x_q <= x_q + 1'b1;
          end
        end
        // stage 1: their ends, exact
        v_q[1]    <= v_q[0];
        a_en_q[1] <= a_en_q[0];
        b_en_q[1] <= b_en_q[0];
        pair_q[1] <= pair_q[0];
        a_base2_q <= a_base1_q;
        b_base2_q <= b_base1_q;
        a_end2_q  <= (SB + 1)'(a_base1_q) + (SB + 1)'(a_size1_q);
        b_end2_q  <= (SB + 1)'(b_base1_q) + (SB + 1)'(b_size1_q);
        // stage 2: beyond the address space; each below the other's end
        if (v_q[1]) begin
          past_q    <= past_q || (a_en_q[1] && past_end(a_end2_q)) ||
                                 (b_en_q[1] && past_end(b_end2_q));
          overlap_q <= overlap_q || (pair_q[1] && a_en_q[1] && b_en_q[1] &&
                                     below(a_base2_q, b_end2_q) && below(b_base2_q, a_end2_q));
        end
      end
    end
    assign overlap = overlap_q;
    assign past    = past_q;
    assign done    = !busy_q && v_q == 2'b00;
  end

  always_comb begin
    logic [CW:0]   out_bytes;          // bytes of an output row
    logic          misaligned;
    logic          tiled;
    tiled     = tile_stride != '0;
    out_bytes = sub ? {width, 1'b0} : {1'b0, width};
    misaligned = 1'b0;
    for (int i = 0; i < NIN; i++)
      misaligned = misaligned || (in_en[i] && in_base[i*AW +: 2] != 2'b00);
    for (int o = 0; o < NWR; o++)
      misaligned = misaligned || (wr_en[o] && wr_base[o*AW +: 2] != 2'b00);
    // Each check on its own; the code is the first failing one's, the verdict
    // an OR of all (flat, so the frame controller's branch does not wait for the
    // priority chain).
    fail[0]  = width == '0 || 32'(width) > mcadsw_pkg::MAX_WIDTH;
    fail[1]  = height == '0 || 32'(height) > mcadsw_pkg::MAX_HEIGHT;
    fail[2]  = disp == '0 || 32'(disp) > DMAX;
    // STRIDE is the input planes' (raster) and, in the LR mode, dR's and the mask's.
    fail[3]  = ((!tiled || lr) && (stride < AW'(width) || (stride & AW'(3)) != '0)) ||
               (tiled && (tile_stride < AW'({height, 2'b00}) || (tile_stride & AW'(3)) != '0));
    fail[4]  = misaligned;
    fail[5]  = overlap;
    fail[6]  = out_stride < AW'(out_bytes) || (out_stride & AW'(3)) != '0;
    fail[7]  = lr && right;
    fail[8]  = past;
    fail[9]  = lr && 32'(lr_t) > mcadsw_pkg::LR_T_MAX;
    fail[10] = lr && 32'(width) > mcadsw_pkg::POST_MAX_WIDTH;
    // Right U and V not configured: the same base as each other or as another
    // input plane (registers left at their reset value, or copied).
    fail[11] = lr && (base_ru == base_rv || base_ru == base_by || base_ru == base_bu ||
                        base_ru == base_bv || base_ru == base_my || base_rv == base_by ||
                        base_rv == base_bu || base_rv == base_bv || base_rv == base_my);
    // A build without the rectifier (mcadsw_pkg::RECT 0) rejects rectification.
    fail[12] = rect && mcadsw_pkg::RECT == 0;
    ok  = fail == '0;
    err = mcadsw_pkg::ErrNone;
    for (int c = NCHECK - 1; c >= 0; c--)
      if (fail[c]) err = CODES[c*mcadsw_pkg::ERR_BITS +: mcadsw_pkg::ERR_BITS];
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      err_o  <= mcadsw_pkg::ErrNone;
      ok_o   <= 1'b1;
      done_o <= 1'b1;
    end else begin
      err_o  <= err;
      ok_o   <= ok;
      done_o <= done;
    end
  end

  assign in_size_o  = in_size;
  assign size_o     = size;
  assign out_size_o = out_size;

endmodule

`default_nettype wire
