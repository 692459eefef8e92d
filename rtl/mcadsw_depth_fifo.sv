// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Depth FIFO (paper Fig. 9): collects the disparities the cost aggregator
// emits (HAGG a cycle, a block row of BLOCK pixels at a time), and writes each
// finished row to the output plane through the memory controller, as aligned
// 32-bit words with byte enables (pixels outside the image are dropped).
// Raw mode: one byte a pixel (the disparity). Wide mode (sub-pixel output,
// docs/memory_map.md): one little-endian halfword a pixel, the VB-bit value
// zero-extended, two pixels a word. Mirrored (the right view as base, docs/
// blocks/engine.md section 6): the pass's column c is image column
// xend - 1 - c, and the pass's columns below xlo are outside the image.
//
// The scheduler pushes a descriptor (output row address, first column, pixel
// count) for every row job it starts, in job order; rows leave the aggregator
// in that order. It starts a job only while space_o is high, so the
// aggregator, which has no back-pressure, never finds the FIFO full.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_depth_fifo #(
  parameter int BLOCK = mcadsw_pkg::BLOCK,
  parameter int HAGG  = mcadsw_pkg::HAGG,
  parameter int DB    = mcadsw_pkg::DISP_BITS,      // disparity bits
  parameter int ROWSQ = 4,                    // rows queued or in flight
  parameter int AW    = 32,
  parameter int CW    = 12,
  parameter bit FPGA  = 1'(mcadsw_pkg::FPGA),  // values in four LUT-RAM banks (below)
  parameter int GB    = $clog2(BLOCK / HAGG)
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  // Descriptors from the scheduler, one per row job
  input  logic               desc_push_i,
  input  logic [AW-1:0]      desc_addr_i,    // byte address of output pixel (x, y) with x = 0
  input  logic [CW-1:0]      desc_x_i,       // first column of the block
  input  logic [4:0]         desc_n_i,       // pixels of the row inside the image, 1..BLOCK
  output logic               space_o,        // another row job may start
  output logic               empty_o,        // nothing queued, nothing to write
  // Frame configuration, stable during a frame
  input  logic               wide_i,         // halfword pixels: the sub-pixel values
  input  logic               pack_i,         // with wide_i: the LR scratch format (below)
  input  logic               mirror_i,       // columns mirrored about xend - 1
  input  logic [1:0]         xlo_i,          // first column inside the image
  input  logic [CW-1:0]      xend_i,         // mirrored: a multiple of 4
  // Values from the cost aggregator: the disparities, and two cycles later the
  // sub-pixel values (16 d + offset) with their d
  input  logic               disp_valid_i,
  input  logic [GB-1:0]      disp_grp_i,
  input  logic [HAGG*DB-1:0] disp_i,
  input  logic               sub_valid_i,
  input  logic [GB-1:0]      sub_grp_i,
  input  logic [HAGG*(DB+4)-1:0] sub_i,
  input  logic [HAGG*DB-1:0] sub_d_i,
  // Writes to the memory controller
  output logic               wr_req_o,
  output logic [AW-1:0]      wr_addr_o,
  output logic [3:0]         wr_be_o,
  output logic [31:0]        wr_wdata_o,
  input  logic               wr_gnt_i
);

  // ---- The values queued (VB bits a pixel) --------------------------------------------
  // d (raw), 16 d + offset (wide), or in the LR mode's first sub-pixel pass the scratch
  // format {offset + 8, d} (pack; docs/blocks/engine.md section 7).
  localparam int SVB = DB + 4;                 // sub-pixel value bits
  localparam int VB  = DB + 5;                 // a queued value
  logic               val_valid;
  logic [GB-1:0]      val_grp;
  logic [HAGG*VB-1:0] val, disp_wide, sub_wide, sub_pack;
  for (genvar m = 0; m < HAGG; m++) begin : g_val
    logic [4:0] off8;                          // offset + 8 (0 .. 16)
    assign off8 = 5'(sub_i[m*SVB +: SVB] - {sub_d_i[m*DB +: DB], 4'b0000} + SVB'(8));
    assign disp_wide[m*VB +: VB] = VB'(disp_i[m*DB +: DB]);
    assign sub_wide[m*VB +: VB]  = VB'(sub_i[m*SVB +: SVB]);
    assign sub_pack[m*VB +: VB]  = {off8, sub_d_i[m*DB +: DB]};
  end
  assign val_valid = wide_i ? sub_valid_i : disp_valid_i;
  assign val_grp   = wide_i ? sub_grp_i : disp_grp_i;
  assign val       = pack_i ? sub_pack : wide_i ? sub_wide : disp_wide;

  localparam int QB = $clog2(ROWSQ + 1);
  localparam int PB = (ROWSQ > 1) ? $clog2(ROWSQ) : 1;

  // Row slots: descriptor and (below) the BLOCK values of each queued row.
  logic [PB-1:0]              head_q, tail_q, fill_q;  // oldest row, next free, row being filled
  logic [QB-1:0]              count_q;                  // rows with a descriptor
  logic [QB-1:0]              ready_q;                  // rows complete, not yet written
  logic [4:0]                 wofs_q;                   // next word, columns after the first

  // The head row's word being written (w_req, w_addr, w_be, w_wdata), and whether
  // it leaves the queue this cycle (w_take): granted on the port.
  logic          w_req, w_take, out_busy;
  logic [AW-1:0] w_addr;
  logic [3:0]    w_be;
  logic [31:0]   w_wdata;

  assign space_o = count_q != QB'(ROWSQ);
  assign empty_o = count_q == '0 && !out_busy;

  // ---- The row at the head, written word by word -----------------------------------
  // The row's first column inside the image: h_x, or xlo in the first block.
  // The word being written holds columns word_x .. word_x + 3 (raw) or
  // word_x .. word_x + 1 (wide), aligned: first_w (at or left of h_first) plus
  // wofs_q. Mirrored, those columns are one aligned memory word too (xend is a
  // multiple of 4), in reverse order, and the row is written from its last word
  // (last_w, holding column h_end - 1) down, so that memory addresses ascend in
  // both cases: one AXI4 INCR burst a row (mcadsw_axi_master). The row is written
  // when wofs_q reaches last_w - first_w (h_span).
  // Columns are counted from h_x, as places in the row (5 bits: a word's columns
  // lie 3 before h_x to 3 after h_end): the word's lowest column is place
  // h_pw0 +- wofs_q (h_pw0: first_w - h_x, or last_w - h_x mirrored), a column is
  // inside the image from place h_pf = h_first - h_x (0..3) to h_n - 1. The word's
  // address is h_addr plus its first image column (times 2, wide): the row's first
  // word's address h_a0 plus wofs_q (times 2).
  // row_info: those values of a row, from its descriptor and the frame
  // configuration: {h_a0, h_pw0, h_pf, h_n, h_span}.
  localparam int RI = AW + 5 + 2 + 5 + 5;
  function automatic logic [RI-1:0] row_info(input logic [AW-1:0] addr, input logic [CW-1:0] x,
                                             input logic [4:0] n, input logic wide, input logic mirror,
                                             input logic [1:0] xlo, input logic [CW-1:0] xend);
    logic [CW-1:0] first;
    logic [CW:0]   e, fw, lw, m0;
    logic [CW:1]   last;                           // a word holds 2 or 4 columns: bit 0 never selects it
    e     = {1'b0, x} + (CW + 1)'(n);              // one past the last column
    first = (x < CW'(xlo)) ? CW'(xlo) : x;
    last  = CW'((e - (CW + 1)'(1)) >> 1);
    fw    = wide ? {1'b0, first[CW-1:1], 1'b0} : {1'b0, first[CW-1:2], 2'b00};
    lw    = wide ? {last[CW:1], 1'b0} : {last[CW:2], 2'b00};
    m0    = !mirror ? fw : {1'b0, xend} - lw - (wide ? (CW + 1)'(2) : (CW + 1)'(4));
    row_info = {addr + (wide ? AW'({m0, 1'b0}) : AW'(m0)), 5'((mirror ? lw : fw) - {1'b0, x}),
                2'(first - x), n, 5'(lw - fw)};
  endfunction
  logic [RI-1:0] h_info;
  logic [AW-1:0] h_a0;
  logic [4:0]    h_pw0, h_n, h_span, pword;
  logic [1:0]    h_pf;
  assign {h_a0, h_pw0, h_pf, h_n, h_span} = h_info;
  assign pword = !mirror_i ? h_pw0 + wofs_q : h_pw0 - wofs_q;   // the word's lowest column
  if (FPGA) begin : g_info_regs
    // FPGA target: each slot's row_info, worked out at the push (the frame
    // configuration is stable): the head's writes start from registers.
    logic [ROWSQ*RI-1:0] info_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        info_q <= '0;
      end else if (desc_push_i) begin
        for (int r = 0; r < ROWSQ; r++)
          if (tail_q == PB'(r)) info_q[r*RI +: RI] <= row_info(desc_addr_i, desc_x_i, desc_n_i,
                                                                      wide_i, mirror_i, xlo_i, xend_i);
      end
    end
    assign h_info = info_q[32'(head_q)*RI +: RI];
  end else begin : g_info_comb
    // ASIC target: the descriptors; the head's row_info from its descriptor.
    localparam int DESC = AW + CW + 5;
    logic [ROWSQ*DESC-1:0] desc_q;
    logic [AW-1:0]         h_addr;
    logic [CW-1:0]         d_x;
    logic [4:0]            d_n;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        desc_q <= '0;
      end else if (desc_push_i) begin
        // Decoded slot by slot (constant part-selects): a part-select at a computed
        // offset would be a bit-granular shifter.
        for (int r = 0; r < ROWSQ; r++)
          if (tail_q == PB'(r)) desc_q[r*DESC +: DESC] <= {desc_addr_i, desc_x_i, desc_n_i};
      end
    end
    assign {h_addr, d_x, d_n} = desc_q[32'(head_q)*DESC +: DESC];
    assign h_info = row_info(h_addr, d_x, d_n, wide_i, mirror_i, xlo_i, xend_i);
  end

  // Byte b of the word: its column's place p in the row (the word's lowest plus its
  // offset in the word), enable, value v (VB bits).
  logic [4*5-1:0]  byte_p;
  logic [4*VB-1:0] byte_v;
  for (genvar b = 0; b < 4; b++) begin : g_byte
    // The place of the pass column byte b belongs to.
    localparam int OFS_RAW = b, OFS_WIDE = b / 2, OFS_RAW_M = 3 - b, OFS_WIDE_M = 1 - b / 2;
    logic [4:0]    p;
    logic [15:0]   v16;
    assign p = pword + (!mirror_i ? (wide_i ? 5'(OFS_WIDE) : 5'(OFS_RAW))
                                  : (wide_i ? 5'(OFS_WIDE_M) : 5'(OFS_RAW_M)));
    assign byte_p[b*5 +: 5] = p;
    assign w_be[b] = p >= 5'(h_pf) && p < h_n;
    assign v16 = 16'(byte_v[b*VB +: VB]);
    assign w_wdata[b*8 +: 8] = !w_be[b] ? 8'h00 :
                                  (wide_i && b % 2 == 1) ? v16[15:8] : v16[7:0];
  end

  // Row slots' values. Writes: the aggregator's group g holds places HAGG*g ..
  // HAGG*g + HAGG - 1 of the row being filled.
  if (FPGA) begin : g_ram
    // FPGA target: four banks of LUT RAM, place p of slot r in bank p % 4 at word
    // {r, p / 4}. A group's HAGG <= 4 consecutive places fall in distinct banks, and
    // a word's 4 (raw) or 2 (wide) consecutive places too: one write and one read
    // port a bank, and a 4:1 select a byte instead of a BLOCK:1 one.
    localparam int WPR = (BLOCK + 3) / 4;            // words of a row in a bank
    localparam int WRB = $clog2(WPR);
    if (HAGG > 4) begin : g_bad_param
      mcadsw_error_depth_fifo_hagg u_error ();
    end
    logic [4*VB-1:0] bank_rd;
    logic [4:0]      plo;              // the place of the word's lowest column
    assign plo = pword;
    for (genvar k = 0; k < 4; k++) begin : g_bank
      logic [VB-1:0]      mem [ROWSQ * (1 << WRB)];
      logic               we;
      logic [WRB-1:0]     wword;
      logic [VB-1:0]      wdata;
      logic [4:0]         rp;          // the place of the word this bank holds
      always_comb begin
        we = 1'b0;
        wword = '0;
        wdata = '0;
        for (int g = 0; g < BLOCK / HAGG; g++)
          for (int j = 0; j < HAGG; j++)
            if ((g*HAGG + j) % 4 == k && val_grp == GB'(g)) begin
              we = val_valid;
              wword = WRB'((g*HAGG + j) / 4);
              wdata = val[j*VB +: VB];
            end
      end
      always_ff @(posedge clk_i)
        if (we) mem[{fill_q, wword}] <= wdata;
      // Of the word's places plo .. plo + 3, the one in this bank.
      assign rp = plo + 5'((k - 32'(plo)) & 3);
      assign bank_rd[k*VB +: VB] = mem[{head_q, WRB'(rp >> 2)}];
    end
    for (genvar b = 0; b < 4; b++) begin : g_sel
      logic [VB-1:0] v;
      logic [1:0]    bk;
      assign bk = byte_p[b*5 +: 2];
      always_comb begin
        v = '0;
        for (int k = 0; k < 4; k++)
          if (bk == 2'(k)) v = bank_rd[k*VB +: VB];
      end
      assign byte_v[b*VB +: VB] = v;
    end
    logic p_unused;                    // a byte's bank is its place's two low bits
    assign p_unused = ^byte_p;
  end else begin : g_regs
    // ASIC target: the slots in flip-flops; the head row a ROWSQ:1 selection shared
    // by the four byte lanes, then a BLOCK:1 selection each.
    logic [ROWSQ*BLOCK*VB-1:0] pix_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        pix_q <= '0;
      end else if (val_valid) begin
        // Decoded slot by slot and group by group (constant part-selects): a
        // part-select at a computed offset would be a bit-granular shifter.
        for (int r = 0; r < ROWSQ; r++)
          for (int g = 0; g < BLOCK / HAGG; g++)
            if (fill_q == PB'(r) && val_grp == GB'(g))
              pix_q[(r*BLOCK + g*HAGG)*VB +: HAGG*VB] <= val;
      end
    end
    logic [BLOCK*VB-1:0] h_row;
    always_comb begin
      h_row = '0;
      for (int r = 0; r < ROWSQ; r++)
        if (head_q == PB'(r)) h_row = pix_q[r*BLOCK*VB +: BLOCK*VB];
    end
    for (genvar b = 0; b < 4; b++) begin : g_sel
      logic [VB-1:0] v;
      logic [4:0]    p;
      assign p = byte_p[b*5 +: 5];
      always_comb begin
        v = '0;
        for (int i = 0; i < BLOCK; i++)
          if (p == 5'(i)) v = h_row[i*VB +: VB];
      end
      assign byte_v[b*VB +: VB] = v;
    end
  end
  assign w_req  = ready_q != '0;
  assign w_addr = h_a0 + (wide_i ? AW'({wofs_q, 1'b0}) : AW'(wofs_q));
  // The word to the port as it is, on both targets (an output register on the FPGA
  // target made the design harder to route: docs/blocks/fpga_target.md, Timing).
  if (FPGA) begin : g_out_fpga
    assign w_take   = w_req && wr_gnt_i;
    assign {wr_req_o, wr_addr_o, wr_be_o, wr_wdata_o} = {w_req, w_addr, w_be, w_wdata};
    assign out_busy = 1'b0;
  end else begin : g_out_port
    assign w_take   = w_req && wr_gnt_i;
    assign {wr_req_o, wr_addr_o, wr_be_o, wr_wdata_o} = {w_req, w_addr, w_be, w_wdata};
    assign out_busy = 1'b0;
  end

  logic row_written;
  assign row_written = w_take && wofs_q == h_span;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      head_q  <= '0;
      tail_q  <= '0;
      fill_q  <= '0;
      count_q <= '0;
      ready_q <= '0;
      wofs_q  <= '0;
    end else begin
      if (desc_push_i) tail_q <= PB'((32'(tail_q) + 1) % ROWSQ);
      if (val_valid && val_grp == GB'(BLOCK / HAGG - 1))
        fill_q <= PB'((32'(fill_q) + 1) % ROWSQ);
      if (w_take) begin
        wofs_q <= wofs_q + (wide_i ? 5'd2 : 5'd4);
        if (row_written) begin
          head_q <= PB'((32'(head_q) + 1) % ROWSQ);
          wofs_q <= '0;
        end
      end
      count_q <= count_q + QB'(desc_push_i) - QB'(row_written);
      ready_q <= ready_q + QB'(val_valid && val_grp == GB'(BLOCK / HAGG - 1))
                         - QB'(row_written);
    end
  end

  // Invariants (docs/verification.md section 3): the scheduler pushes a row
  // descriptor only into space, the WTA sends disparities only for a queued row.
  `MCADSW_ASSUME(DescriptorPushedIntoSpace, !(desc_push_i && !space_o))
  `MCADSW_ASSUME(DisparitiesForQueuedRow, !(val_valid && ready_q == count_q))
  `MCADSW_ASSERT(WriteOnlyWithRowQueued, !(w_req && count_q == '0))

  // Events the block's proof must reach (formal only): a row written out, and the
  // queue full.
  `MCADSW_COVER(RowWritten, row_written)
  `MCADSW_COVER(QueueFull, !space_o)

endmodule

`default_nettype wire
