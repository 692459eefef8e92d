// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Rectifier pass (docs/algorithm.md 13, docs/blocks/rectifier.md 7): raw planes and
// meshes in, rectified planes and validity bitmaps out, on one memory port in the
// engine's protocol.
//
// Two phases. Check: every tile of every view, the nodes only (mcadsw_rect_nodes); a
// node beyond the coordinate range or a source rectangle beyond the tile buffer ends
// the pass with err_o and nothing written. Rectify: jobs (tile, plane) in order, tile
// row band by band, the view's planes inner. A producer reads a tile's nodes (once a
// tile) and loads each job's source rectangle into one of two tile buffers
// (mcadsw_rect_load); a consumer samples a loaded buffer (mcadsw_rect_sample) into the
// writer (mcadsw_rect_write), which also writes the validity bitmap on a view's first
// plane. The producer fills one buffer while the consumer samples the other; it reads
// the next tile's nodes once the consumer has copied this tile's.
//
// Planes: p = 0..5 are LY LU LV RY RU RV; planes_i says which (a view with none is
// skipped). Raw planes and rectified planes share the layout kind (tiled_i), each with
// its own stride (raster: bytes a row; tiled: bytes a 4-pixel column).
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_rect #(
  parameter int CW  = 12,
  parameter int NB  = mcadsw_rect_pkg::MESH_NODE_BITS,
  parameter int TW  = mcadsw_rect_pkg::RECT_TILE_W,
  parameter int TH  = mcadsw_rect_pkg::RECT_TILE_H,
  parameter int BW  = mcadsw_rect_pkg::RECT_BUF_W,
  parameter int BH  = mcadsw_rect_pkg::RECT_BUF_H,
  parameter int NODES = (TW / 8 + 1) * (TH / 8 + 1),
  parameter int BAW = $clog2(BH / 2 * BW / 4),
  parameter int OUTS = 8                                  // read bursts in flight
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  // Configuration, held while busy
  input  logic               start_i,
  input  logic [2:0]         step_log2_i,
  input  logic [CW-1:0]      width_i,                     // rectified frame
  input  logic [CW-1:0]      height_i,
  input  logic [CW-1:0]      raw_w_i,                     // raw views
  input  logic [CW-1:0]      raw_h_i,
  input  logic               tiled_i,
  input  logic [31:0]        raw_stride_i,
  input  logic [31:0]        stride_i,
  input  logic [6*32-1:0]    raw_base_i,                  // plane p at bits 32p
  input  logic [6*32-1:0]    base_i,
  input  logic [5:0]         planes_i,
  input  logic [2*32-1:0]    mesh_base_i,                 // view v at bits 32v
  input  logic [2*32-1:0]    valid_base_i,
  output logic               busy_o,
  output logic               done_o,                      // pulse: the pass ended (err_o with it)
  output logic [1:0]         err_o,                       // 1: a node out of range; 2: a tile's source too big
  // Memory port (docs/memory_map.md)
  output logic               mem_req_o,
  input  logic               mem_gnt_i,
  output logic               mem_we_o,
  output logic [3:0]         mem_be_o,
  output logic [31:0]        mem_addr_o,
  output logic [2:0]         mem_len_o,
  output logic [31:0]        mem_wdata_o,
  input  logic               mem_rvalid_i,
  input  logic [31:0]        mem_rdata_i
);

  // Built in only when the package says so (mcadsw_rect_none.sv otherwise).
  if (mcadsw_pkg::RECT == 0) begin : g_no_rect
    mcadsw_error_rect_in_a_build_without_it u_error ();
  end
  // ---- Frame geometry ----------------------------------------------------------------------
  // Registered from the configuration every cycle (no reset, no enable): the inputs are
  // held from the start on, so from the cycle after the start these are the frame's. The
  // first use is two cycles after the start (nx, at the first node read); registered, the
  // tile counters' enables start from flip-flops (a path from width_i through the
  // comparisons into their clock gates missed half a period when it was timed alone).
  logic [2:0]    s;
  assign s = step_log2_i;
  logic [CW-1:0] nx;                                      // nodes a row: (W - 1) >> s + 2
  logic [CW-1:0] vh;                                      // validity words a strip: ceil(H / 8)
  logic [CW-1:0] last_a, last_b;                          // the last tile column and row
  always_ff @(posedge clk_i) begin
    nx     <= ((width_i - CW'(1)) >> s) + CW'(2);
    vh     <= (height_i + CW'(7)) >> 3;
    last_a <= (width_i - CW'(1)) >> 5;
    last_b <= (height_i - CW'(1)) >> 4;
  end
  function automatic logic [2:0] first_plane(input logic [1:0] f);   // f: planes 0 and 1
    first_plane = f[0] ? 3'd0 : f[1] ? 3'd1 : 3'd2;
  endfunction
  // View v's planes: planes_i[3 v +: 3]

  // ---- Port clients --------------------------------------------------------------------------
  // Node reads (a loader instance reading the tile's node rows: "columns" of 8 bytes a
  // node), plane loads, writes.
  logic        nrd_start, nrd_busy, nrd_done, nrd_req, nrd_gnt, nrd_rvalid;
  logic [31:0] nrd_addr;
  logic [2:0]  nrd_len;
  logic        ld_start, ld_busy, ld_done, ld_req, ld_gnt, ld_rvalid;
  logic [31:0] ld_addr;
  logic [2:0]  ld_len;
  logic        wr_req, wr_gnt;
  logic [31:0] wr_addr, wr_data;
  logic [3:0]  wr_be;

  // ---- Tile front end ------------------------------------------------------------------------
  logic            nd_start, nd_busy, nd_done, nd_range, nd_empty, nd_fits;
  logic [CW-1:0]   nd_i0, nd_j0, nd_x0, nd_y0;
  logic [2:0]      nd_ncols;
  logic [1:0]      nd_nrows;
  logic [CW:0]     nd_cols, nd_rows;
  logic [NODES*NB-1:0] nd_u, nd_v;
  logic [CW-1:0]   p_a, p_b;                              // producer's tile
  logic            p_v;                                   // producer's view
  mcadsw_rect_nodes u_nodes (
    .clk_i, .rst_ni, .start_i(nd_start), .step_log2_i(s),
    .tile_x0_i(CW'({p_a, 5'b0})), .tile_y0_i(CW'({p_b, 4'b0})), .width_i, .height_i, .raw_w_i, .raw_h_i,
    .node_i0_o(nd_i0), .node_j0_o(nd_j0), .ncols_o(nd_ncols), .nrows_o(nd_nrows),
    .word_valid_i(nrd_rvalid), .word_i(mem_rdata_i), .busy_o(nd_busy), .done_o(nd_done),
    .node_u_o(nd_u), .node_v_o(nd_v), .range_err_o(nd_range), .empty_o(nd_empty), .fits_o(nd_fits),
    .src_x0_o(nd_x0), .src_y0_o(nd_y0), .src_cols_o(nd_cols), .src_rows_o(nd_rows)
  );
  // The node rows: nrows lines of 2 ncols words from mesh + (j0 nx + i0) 8, nx 8 apart.
  logic           unused_nrd_we, unused_nrd_par;
  logic [BAW-1:0] unused_nrd_addr;
  logic [15:0]    unused_nrd_even, unused_nrd_odd;
  mcadsw_rect_load u_node_reader (
    .clk_i, .rst_ni, .start_i(nrd_start),
    .base_i(mesh_base_i[32 * p_v +: 32] + {17'b0, nd_i0, 3'b0}), .tiled_i(1'b0),
    .stride_i({17'b0, nx, 3'b0}), .x0_i(CW'(0)), .y0_i(nd_j0),
    .cols_i(7'({nd_ncols, 3'b0})), .rows_i({4'b0, nd_nrows}), .busy_o(nrd_busy), .done_o(nrd_done),
    .mem_req_o(nrd_req), .mem_gnt_i(nrd_gnt), .mem_addr_o(nrd_addr), .mem_len_o(nrd_len),
    .mem_rvalid_i(nrd_rvalid), .mem_rdata_i(mem_rdata_i),
    .bank_we_o(unused_nrd_we), .bank_row_par_o(unused_nrd_par), .bank_waddr_o(unused_nrd_addr),
    .bank_wdata_even_o(unused_nrd_even), .bank_wdata_odd_o(unused_nrd_odd)
  );

  // ---- Tile buffers: two, four banks each ----------------------------------------------------
  logic            ld_we, ld_par;
  logic [BAW-1:0]  ld_waddr;
  logic [15:0]     ld_even, ld_odd;
  logic            p_q;                                   // the producer's buffer
  logic            c_q;                                   // the consumer's buffer
  logic [3:0]      smp_re;
  logic [4*BAW-1:0] smp_addr;
  logic [2*4*16-1:0] bank_rd;                            // buffer q at bits 64 q
  for (genvar q = 0; q < 2; q++) begin : g_buf
    for (genvar b = 0; b < 4; b++) begin : g_bank
      logic [15:0] mem [BH / 2 * BW / 4];
      logic [15:0] rd_q;
      always_ff @(posedge clk_i) begin
        if (ld_we && p_q == q[0] && ld_par == b[1]) mem[ld_waddr] <= b[0] ? ld_odd : ld_even;
        if (smp_re[b] && c_q == q[0]) rd_q <= mem[smp_addr[b * BAW +: BAW]];
      end
      assign bank_rd[(q * 4 + b) * 16 +: 16] = rd_q;
    end
  end

  // ---- Producer ------------------------------------------------------------------------------
  typedef enum logic [3:0] {PIdle, PNodes, PNodesRd, PNodesWait, PCheck, PLoadWait, PLoad, PLoadRun,
                            PDone} pstate_e;
  pstate_e       ps_q;
  logic          check_q;                                 // the check phase
  logic [2:0]    p_p;                                     // the producer's plane in its view
  logic [1:0]    buf_full_q;
  logic          nodes_free_q;                            // the consumer has the tile's nodes
  // The producer's tile: its rectangle, kept for its planes
  logic          pr_empty_q;
  logic [CW-1:0] pr_x0_q, pr_y0_q;
  logic [6:0]    pr_cols_q;
  logic [5:0]    pr_rows_q;
  // Handoff per buffer: the job's tile, view, plane, and whether it is the tile's first
  logic [2*CW-1:0] h_a_q, h_b_q, h_x0_q, h_y0_q;        // buffer q at bits CW q
  logic [1:0]      h_v_q, h_first_q;
  logic [5:0]      h_p_q;                              // buffer q at bits 3 q
  logic          err_range_q, err_fit_q;

  // The next plane of view v after plane p (3: none)
  function automatic logic [2:0] next_plane(input logic [2:0] f, input logic [2:0] p);
    next_plane = 3'd3;
    for (int i = 2; i >= 0; i--) if (f[i] && 32'(i) > 32'(p)) next_plane = 3'(i);
  endfunction
  logic [2:0] p_next;
  assign p_next = next_plane(p_v ? planes_i[5:3] : planes_i[2:0], p_p);
  logic tile_last_p, view_last_p;
  assign tile_last_p = p_a == last_a && p_b == last_b;
  // The next view with planes after view v (2: none)
  logic [1:0] v_has;
  assign v_has = {planes_i[5:3] != 3'b0, planes_i[2:0] != 3'b0};
  assign view_last_p = p_v || !v_has[1];

  logic cons_took_nodes;                                  // consumer copies a tile's nodes this cycle

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ps_q <= PIdle; check_q <= 1'b0; p_a <= '0; p_b <= '0; p_v <= 1'b0; p_p <= '0; p_q <= 1'b0;
      buf_full_q <= '0; nodes_free_q <= 1'b1;
      err_range_q <= 1'b0; err_fit_q <= 1'b0;
    end else begin
      if (cons_took_nodes) nodes_free_q <= 1'b1;
      if (cons_free_buf) buf_full_q[c_q] <= 1'b0;
      case (ps_q)
        PIdle: if (start_i) begin
          check_q <= 1'b1;
          p_a <= '0; p_b <= '0; p_v <= !v_has[0]; p_q <= 1'b0;
          err_range_q <= 1'b0; err_fit_q <= 1'b0;
          nodes_free_q <= 1'b1;
          ps_q <= (v_has[0] || v_has[1]) ? PNodes : PDone;
        end
        PNodes: if (nd_start) ps_q <= PNodesRd;              // the tile registered
        PNodesRd: ps_q <= PNodesWait;                        // nrd_start: its node rows
        PNodesWait: if (nd_done) begin                               // the tile's rectangle
          p_p <= first_plane(p_v ? planes_i[4:3] : planes_i[1:0]);
          if (check_q) begin
            if (nd_range || !nd_fits) begin
              err_range_q <= nd_range;
              err_fit_q <= !nd_range;
              ps_q <= PDone;
            end else ps_q <= PCheck;
          end else begin
            nodes_free_q <= 1'b0;
            ps_q <= PLoadWait;
          end
        end
        PCheck: begin                                      // the next tile, view, or the rectify phase
          ps_q <= PNodes;
          if (p_a != last_a) p_a <= p_a + CW'(1);
          else begin
            p_a <= '0;
            if (p_b != last_b) p_b <= p_b + CW'(1);
            else begin
              p_b <= '0;
              if (!view_last_p) p_v <= 1'b1;
              else begin
                check_q <= 1'b0;
                p_v <= !v_has[0];
              end
            end
          end
        end
        PLoadWait: if (!buf_full_q[p_q]) ps_q <= pr_empty_q ? PLoadRun : PLoad;
        PLoad: ps_q <= PLoadRun;                           // ld_start this cycle
        PLoadRun: if (pr_empty_q || ld_done) begin
          buf_full_q[p_q] <= 1'b1;
          p_q <= !p_q;
          if (p_next != 3'd3) begin
            p_p <= p_next;
            ps_q <= PLoadWait;
          end else if (!tile_last_p) begin
            if (p_a != last_a) p_a <= p_a + CW'(1);
            else begin
              p_a <= '0;
              p_b <= p_b + CW'(1);
            end
            ps_q <= PNodes;
          end else if (!view_last_p) begin
            p_a <= '0; p_b <= '0; p_v <= 1'b1;
            ps_q <= PNodes;
          end else ps_q <= PDone;
        end
        PDone: if (cons_idle) ps_q <= PIdle;
        default: ps_q <= PIdle;
      endcase
    end
  end
  // Data (no reset: the rectangle is written when the tile's nodes are in, a handoff
  // before its buffer is marked full)
  always_ff @(posedge clk_i) begin
    if (ps_q == PNodesWait && nd_done) begin
      pr_empty_q <= nd_empty;
      pr_x0_q <= nd_x0; pr_y0_q <= nd_y0;
      pr_cols_q <= 7'(nd_cols); pr_rows_q <= 6'(nd_rows);
    end
    if (ps_q == PLoadRun && (pr_empty_q || ld_done)) begin
      h_a_q[p_q * CW +: CW] <= p_a; h_b_q[p_q * CW +: CW] <= p_b; h_v_q[p_q] <= p_v;
      h_p_q[p_q * 3 +: 3] <= p_p;
      h_first_q[p_q] <= p_p == first_plane(p_v ? planes_i[4:3] : planes_i[1:0]);
      h_x0_q[p_q * CW +: CW] <= pr_x0_q; h_y0_q[p_q * CW +: CW] <= pr_y0_q;
    end
  end
  assign nd_start  = ps_q == PNodes && (nodes_free_q || check_q) && !nd_busy;
  assign nrd_start = ps_q == PNodesRd;
  assign ld_start  = ps_q == PLoad;
  // The loaded plane: raw base of plane 3 v + p
  logic [2:0] p_plane;
  assign p_plane = (p_v ? 3'd3 : 3'd0) + p_p;

  mcadsw_rect_load u_loader (
    .clk_i, .rst_ni, .start_i(ld_start),
    .base_i(raw_base_i[32 * p_plane +: 32]), .tiled_i, .stride_i(raw_stride_i),
    .x0_i(pr_x0_q), .y0_i(pr_y0_q), .cols_i(pr_cols_q), .rows_i(pr_rows_q),
    .busy_o(ld_busy), .done_o(ld_done),
    .mem_req_o(ld_req), .mem_gnt_i(ld_gnt), .mem_addr_o(ld_addr), .mem_len_o(ld_len),
    .mem_rvalid_i(ld_rvalid), .mem_rdata_i(mem_rdata_i),
    .bank_we_o(ld_we), .bank_row_par_o(ld_par), .bank_waddr_o(ld_waddr),
    .bank_wdata_even_o(ld_even), .bank_wdata_odd_o(ld_odd)
  );

  // ---- Consumer ------------------------------------------------------------------------------
  typedef enum logic [1:0] {CIdle, CStart, CRun} cstate_e;
  cstate_e        cs_q;
  logic [NODES*NB-1:0] cu_q, cv_q;                        // the sampled tile's nodes
  logic           smp_start, smp_busy, smp_en, smp_valid, smp_ok, smp_last;
  logic [7:0]     smp_pix;
  logic [4:0]     smp_x;
  logic [3:0]     smp_y;
  logic           wr_start, wr_done, wr_idle;
  logic           cons_free_buf, cons_idle;
  logic [CW-1:0]  c_a, c_b, c_x0, c_y0;
  logic           c_v, c_first;
  logic [2:0]     c_p;
  assign c_a = h_a_q[c_q * CW +: CW];
  assign c_b = h_b_q[c_q * CW +: CW];
  assign c_v = h_v_q[c_q];
  assign c_p = h_p_q[c_q * 3 +: 3];
  assign c_first = h_first_q[c_q];
  assign c_x0 = h_x0_q[c_q * CW +: CW];
  assign c_y0 = h_y0_q[c_q * CW +: CW];
  logic [CW-1:0] c_tx0, c_ty0;
  assign c_tx0 = CW'({c_a, 5'b0});
  assign c_ty0 = CW'({c_b, 4'b0});
  logic [5:0] c_tw;
  logic [4:0] c_th;
  assign c_tw = width_i - c_tx0 >= CW'(TW) ? 6'(TW) : 6'(width_i - c_tx0);
  assign c_th = height_i - c_ty0 >= CW'(TH) ? 5'(TH) : 5'(height_i - c_ty0);
  logic [2:0] c_plane;
  assign c_plane = (c_v ? 3'd3 : 3'd0) + c_p;
  // Addresses: the tile's first word in the rectified plane (base + off_top) and its
  // validity word (valid base + off_v). The offsets move on at a tile's first job, tiles
  // coming in order (a inner, b, the view): raster off_top = 16 b stride + 32 a, tiled
  // 8 a stride + 64 b; off_v = 32 a vh + 8 b.
  logic [31:0] c_base, c_top, c_vtop;
  assign c_base = base_i[32 * c_plane +: 32];
  logic [31:0] off_top_q, row_top_q, off_v_q, row_v_q;     // this tile's, its band's first tile's
  logic [31:0] band_top, step_top;
  assign band_top = tiled_i ? 32'd64 : {stride_i[27:0], 4'b0};
  assign step_top = tiled_i ? {stride_i[28:0], 3'b0} : 32'd32;
  assign c_top  = c_base + off_top_q;
  assign c_vtop = valid_base_i[32 * c_v +: 32] + off_v_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cs_q <= CIdle; c_q <= 1'b0;
    end else if (ps_q == PIdle && start_i) begin        // a pass: the producer starts at buffer 0
      c_q <= 1'b0;
    end else begin
      case (cs_q)
        CIdle: if (buf_full_q[c_q] && !check_q && ps_q != PIdle) cs_q <= CStart;
        CStart: if (smp_en) cs_q <= CRun;                 // sample and writer start (the core
                                                          // takes its start with en_i)
        CRun: if (wr_done) begin
          c_q <= !c_q;
          cs_q <= CIdle;
        end
        default: cs_q <= CIdle;
      endcase
    end
  end
  assign cons_took_nodes = cs_q == CIdle && buf_full_q[c_q] && !check_q && ps_q != PIdle && c_first;
  // Data (no reset): the tile's nodes and address offsets, taken at its first job (a
  // view's first tile, a = b = 0, sets the offsets)
  always_ff @(posedge clk_i) begin
    if (cons_took_nodes) begin
      cu_q <= nd_u;
      cv_q <= nd_v;
      if (c_a == '0) begin                                // a band's first tile
        row_top_q <= c_b == '0 ? 32'd0 : row_top_q + band_top;
        off_top_q <= c_b == '0 ? 32'd0 : row_top_q + band_top;
        row_v_q   <= c_b == '0 ? 32'd0 : row_v_q + 32'd8;
        off_v_q   <= c_b == '0 ? 32'd0 : row_v_q + 32'd8;
      end else begin
        off_top_q <= off_top_q + step_top;
        off_v_q   <= off_v_q + {15'b0, vh, 5'b0};
      end
    end
  end
  assign cons_free_buf   = cs_q == CRun && wr_done;
  assign cons_idle       = cs_q == CIdle && buf_full_q == 2'b00 && wr_idle && !smp_busy;
  assign smp_start = cs_q == CStart;
  assign wr_start  = cs_q == CStart;

  mcadsw_rect_sample u_sample (
    .clk_i, .rst_ni, .en_i(smp_en), .start_i(smp_start), .step_log2_i(s), .tile_y0_i(c_ty0),
    .tile_w_i(c_tw), .tile_h_i(c_th), .src_x0_i(c_x0), .src_y0_i(c_y0), .raw_w_i, .raw_h_i,
    .uv_i(c_p != 3'd0), .node_u_i(cu_q), .node_v_i(cv_q), .busy_o(smp_busy),
    .bank_re_o(smp_re), .bank_addr_o(smp_addr), .bank_rdata_i(bank_rd[c_q * 64 +: 64]),
    .pix_valid_o(smp_valid), .pix_o(smp_pix), .pix_ok_o(smp_ok), .pix_x_o(smp_x), .pix_y_o(smp_y),
    .pix_last_o(smp_last)
  );
  mcadsw_rect_write u_write (
    .clk_i, .rst_ni, .start_i(wr_start), .top_i(c_top),
    .step_row_i(tiled_i ? 32'd4 : stride_i), .step_strip_i(tiled_i ? stride_i : 32'd4),
    .tile_w_i(c_tw), .tile_h_i(c_th), .valid_en_i(c_first), .vtop_i(c_vtop),
    .vstep_strip_i({18'b0, vh, 2'b0}),
    .ready_o(smp_en), .pix_valid_i(smp_valid), .pix_i(smp_pix), .pix_ok_i(smp_ok), .pix_x_i(smp_x),
    .pix_y_i(smp_y), .pix_last_i(smp_last),
    .wr_req_o(wr_req), .wr_gnt_i(wr_gnt), .wr_addr_o(wr_addr), .wr_be_o(wr_be), .wr_data_o(wr_data),
    .done_o(wr_done), .idle_o(wr_idle)
  );

  // ---- Port arbiter: writes first, then node reads, then loads; a presented request
  //      keeps the port until granted; read data to the oldest read's client.
  mcadsw_rect_port #(.OUTS(OUTS)) u_port (
    .clk_i, .rst_ni,
    .wr_req_i(wr_req), .wr_gnt_o(wr_gnt), .wr_addr_i(wr_addr), .wr_be_i(wr_be), .wr_data_i(wr_data),
    .nrd_req_i(nrd_req), .nrd_gnt_o(nrd_gnt), .nrd_addr_i(nrd_addr), .nrd_len_i(nrd_len),
    .nrd_rvalid_o(nrd_rvalid),
    .ld_req_i(ld_req), .ld_gnt_o(ld_gnt), .ld_addr_i(ld_addr), .ld_len_i(ld_len), .ld_rvalid_o(ld_rvalid),
    .mem_req_o, .mem_gnt_i, .mem_we_o, .mem_be_o, .mem_addr_o, .mem_len_o, .mem_wdata_o, .mem_rvalid_i
  );

  // ---- Status --------------------------------------------------------------------------------
  logic done_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) done_q <= 1'b0;
    else done_q <= ps_q == PDone && cons_idle;
  end
  assign done_o = done_q;
  assign err_o  = {err_fit_q, err_range_q};
  assign busy_o = ps_q != PIdle || done_q;

  logic unused_rect;
  assign unused_rect = ^{nrd_busy, nrd_done, unused_nrd_we, unused_nrd_par, unused_nrd_addr, unused_nrd_even,
                         unused_nrd_odd, nd_rows[CW:6], nd_cols[CW:7], stride_i[31:29]};

  `MCADSW_ASSERT(load_when_idle, !ld_start || !ld_busy)

`ifdef MCADSW_CHECKS
  // verilator coverage_off
  // ---- Tile handoff (live in simulation; make formal, formal/rect_handoff.sby, proves it
  // with the submodules cut out, their outputs free but for the loader's busy and done) ----
  // The jobs loaded and not yet sampled, oldest first ({tile a, b, view, plane}), and the
  // tile whose nodes the node front end holds: the producer fills an empty buffer, the
  // consumer samples a full one, the jobs in the order loaded, and the consumer copies
  // the nodes of its own tile.
  localparam int JB = 2 * CW + 4;
  logic          f_prod, f_run_q, f_ntile_ok_q;
  logic [1:0]    f_n_q;
  logic [2*JB-1:0] f_jobs_q;
  logic [2*CW:0] f_ntile_q;
  assign f_prod = ps_q == PLoadRun && (pr_empty_q || ld_done);
  always_ff @(posedge clk_i or negedge rst_ni) begin : f_handoff
    logic [2*JB-1:0] j;
    logic [1:0]      n;
    if (!rst_ni) begin
      f_n_q <= '0; f_jobs_q <= '0; f_run_q <= 1'b0; f_ntile_q <= '0; f_ntile_ok_q <= 1'b0;
    end else begin
      j = f_jobs_q;
      n = f_n_q;
      if (cons_free_buf) begin
        j = j >> JB;
        n = n - 2'd1;
      end
      if (f_prod) begin
        j[32'(n) * JB +: JB] = {p_a, p_b, p_v, p_p};
        n = n + 2'd1;
      end
      f_jobs_q <= j;
      f_n_q <= n;
      if (ld_start) f_run_q <= 1'b1;
      else if (ld_done) f_run_q <= 1'b0;
      if (ps_q == PNodesWait && nd_done && !check_q) begin
        f_ntile_q <= {p_a, p_b, p_v};
        f_ntile_ok_q <= 1'b1;
      end else if (ps_q == PIdle) f_ntile_ok_q <= 1'b0;
    end
  end
  // The loader (cut out in the proof): busy from the cycle after its start to its done.
  `MCADSW_ASSUME(LoaderBusyFromStartToDone, ld_busy == f_run_q && (!ld_done || f_run_q))
  `MCADSW_ASSERT(LoadIntoEmptyBuffer, !f_prod || !buf_full_q[p_q])
  `MCADSW_ASSERT(SampleFullBuffer, cs_q == CIdle || buf_full_q[c_q])
  `MCADSW_ASSERT(JobsInBuffers, 32'(f_n_q) == 32'(buf_full_q[0]) + 32'(buf_full_q[1])
                                && p_q == (c_q ^ (f_n_q == 2'd1)))
  `MCADSW_ASSERT(JobsInOrder, cs_q == CIdle || {c_a, c_b, c_v, c_p} == f_jobs_q[0 +: JB])
  `MCADSW_ASSERT(NodesOfItsTile, !cons_took_nodes || (f_ntile_ok_q && {c_a, c_b, c_v} == f_ntile_q))
  `MCADSW_COVER(TileSampled, cons_free_buf && c_first)
  `MCADSW_COVER(BothBuffersFull, buf_full_q == 2'b11)
  `MCADSW_COVER(SecondTileNodes, cons_took_nodes && c_a == CW'(1))
  // verilator coverage_on
`endif
endmodule

`default_nettype wire
