// Post-processing stage of the LR mode (docs/algorithm.md 12.2-12.5,
// docs/architecture.md section 12): reads the left map dL and the right map dR
// back from external memory row by row and writes the LR-checked, filled,
// 3x3-median-filtered map and the validity mask.
//
// Its own 32-bit port, in the protocol of docs/memory_map.md (the top gives it
// the external port once both passes are done). Reads are pipelined (several in
// flight), writes leave through a small queue.
//
// Planes (every base a multiple of 4):
//   dL    (base_dl_i, out_stride_i): 1 byte a pixel, d; wide: a halfword a pixel,
//         d in bits DB-1:0 and offset + 8 in bits DB+4:DB (the value is 16 d + offset)
//   dR    (base_dr_i, stride_i): 1 byte a pixel, d
//   out   (base_out_i, out_stride_i): 1 byte (d) or a halfword (16 d + offset) a pixel
//   mask  (base_mask_i, stride_i): 1 byte a pixel, 255 valid, 0 filled
// Each row y runs two phases:
//   RD  the dR row into rb, then the dL row word by word (at most FD words
//       requested and not yet used); a pixel a cycle, the check
//       valid(x) = x >= d && |d - dR(x - d)| <= T, and the forward fill: vrow(x)
//       holds the pixel's value when valid, else the nearest valid value to its
//       left (and whether there is one).
//       The next row's reads start during CD (below), when no write is waiting.
//   CD  from right to left, a pixel a cycle: the fill from the right (the filled
//       value of row y replaces row y - 2 in its median row buffer, right after
//       being read), the mask bytes of row y, and the 3x3 median of row y - 1
//       (rows y - 2, y - 1 from the median row buffers, row y as it is filled;
//       edges replicated).
// After the last row a CD pass without fill makes the median of row H - 1.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_post #(
  parameter int MAXW = mcadsw_pkg::POST_MAX_WIDTH,
  parameter int DB   = mcadsw_pkg::DISP_BITS,
  parameter int VB   = DB + 4,                  // value: d, or 16 d + offset
  parameter int CW   = 12,
  parameter int AW   = 32,
  parameter int FD   = 4,                       // dL words requested and not yet used
  parameter int QD   = 8                        // write queue entries
) (
  input  logic           clk_i,
  input  logic           rst_ni,
  input  logic           start_i,
  input  logic [AW-1:0]  base_dl_i,
  input  logic [AW-1:0]  base_dr_i,
  input  logic [AW-1:0]  base_out_i,
  input  logic [AW-1:0]  base_mask_i,
  input  logic [AW-1:0]  stride_i,
  input  logic [AW-1:0]  out_stride_i,
  input  logic [CW-1:0]  width_i,               // 1 .. MAXW
  input  logic [CW-1:0]  height_i,
  input  logic [5:0]     tol_i,                 // T
  input  logic           wide_i,
  output logic           busy_o,
  output logic           done_o,                // one cycle
  output logic           mem_req_o,
  input  logic           mem_gnt_i,
  output logic           mem_we_o,
  output logic [3:0]     mem_be_o,
  output logic [AW-1:0]  mem_addr_o,
  output logic [31:0]    mem_wdata_o,
  input  logic           mem_rvalid_i,
  input  logic [31:0]    mem_rdata_i
);

  localparam int XI = $clog2(MAXW);           // pixel index (MAXW a power of 2)
  localparam int RI = XI - 2;                  // rb word index
  localparam int FI = $clog2(FD);
  localparam int QI = $clog2(QD);
  localparam int QE = 1 + CW + 4 + 32;         // queue entry: {out plane, word, be, data}

  if (MAXW < 4 || (1 << XI) != MAXW || MAXW > (1 << CW) || (1 << FI) != FD || (1 << QI) != QD ||
      QD < 8) begin : g_bad_param
    mcadsw_error_post_geometry u_error ();
  end

  // ---- Row buffers (synchronous read, one write port each) -----------------------
  logic [31:0]   rb [MAXW / 4];                // dR row, 4 pixels a word
  logic [VB+1:0] vrow [MAXW];                  // {valid, has a value, value}
  logic [VB-1:0] med0 [MAXW], med1 [MAXW];     // filled rows, row % 2

  // ---- Configuration, registered at start ------------------------------------------
  logic [AW-1:0] stride_q, ostride_q;
  logic [CW-1:0] w_q, h_q;
  logic [5:0]    tol_q;
  logic          wide_q;
  // Row addresses: dR, dL and mask of row y, output of the row being filtered.
  logic [AW-1:0] rdr_q, rdl_q, rmask_q, rout_q;

  // ---- Memory request register: held until granted --------------------------------
  logic          req_q, we_q;
  logic [3:0]    be_q;
  logic [AW-1:0] addr_q;
  logic [31:0]   wdata_q;
  assign mem_req_o   = req_q;
  assign mem_we_o    = we_q;
  assign mem_be_o    = we_q ? be_q : 4'h0;
  assign mem_addr_o  = addr_q;
  assign mem_wdata_o = we_q ? wdata_q : 32'h0;
  logic port_free;                             // no request waiting for its grant
  assign port_free = !req_q || mem_gnt_i;

  typedef enum logic [2:0] { S_IDLE, S_RD, S_BDR, S_CD, S_NEXT, S_DONE } state_e;
  state_e        st_q;
  logic [CW-1:0] y_q;

  // ---- RD: requests, responses, the dL word queue ------------------------------------
  logic [CW:0] nr, nt;                         // dR words, dR + dL words of a row
  assign nr = ({1'b0, w_q} + (CW + 1)'(3)) >> 2;
  assign nt = nr + (wide_q ? ({1'b0, w_q} + (CW + 1)'(1)) >> 1 : nr);
  logic [CW:0]   rq_q, rs_q;                   // requests issued, responses received
  logic [AW-1:0] ra_q;                         // next request's address
  logic [FI:0]   cred_q;                       // dL words requested, not yet used
  logic          rq_dl, rd_issue;
  logic          pf_q;                         // the next row's reads may start in CD
  logic [QI:0]   qc_q;                         // write queue entries (below)
  assign rq_dl    = rq_q >= nr;
  // RD, or CD and the wait after it with no write waiting: the next row's reads.
  assign rd_issue = (st_q == S_RD || (pf_q && (st_q == S_CD || st_q == S_NEXT) && qc_q == '0)) &&
                    port_free && rq_q < nt && (!rq_dl || cred_q < (FI + 1)'(FD));
  logic [FD*32-1:0] fq_q;                      // dL words received, not yet used
  logic [FI-1:0]    fw_q, fr_q;
  logic [FI:0]      fc_q;
  logic             f_push, f_pop;
  assign f_push = mem_rvalid_i && rs_q >= nr;

  // ---- RD: the check, a pixel a cycle ------------------------------------------------
  logic          wv_q;                         // word_q holds pixels still to take
  logic [31:0]   word_q;
  logic [1:0]    j_q;                          // its pixel
  logic [CW-1:0] bx_q;                         // that pixel's column
  logic          b_take, b_wlast, b_rlast;
  assign b_take  = st_q == S_RD && wv_q;
  assign b_wlast = wide_q ? j_q[0] : j_q == 2'd3;
  assign b_rlast = bx_q + CW'(1) == w_q;
  assign f_pop   = fc_q != '0 && (st_q == S_RD && (!wv_q || (b_wlast && !b_rlast)));
  logic [15:0]   b_hw;                         // wide: the pixel's halfword
  assign b_hw = j_q[0] ? word_q[31:16] : word_q[15:0];
  logic [7:0]    bd;                           // its d
  logic [VB-1:0] bv;                           // its value
  assign bd = wide_q ? 8'(b_hw[DB-1:0]) : word_q[8*j_q +: 8];
  assign bv = wide_q ? VB'({b_hw[DB-1:0], 4'b0000}) + VB'(b_hw[DB+4:DB]) - VB'(8) : VB'(bd);
  logic [15-DB-5:0] b_hw_unused;
  assign b_hw_unused = b_hw[15:DB+5];
  logic [CW:0] bxd;                            // x - d
  assign bxd = {1'b0, bx_q} - (CW + 1)'(bd);
  logic          p_valid_q, p_inb_q;           // stage 2: pixel, x - d >= 0
  logic [XI-1:0] p_x_q;
  logic [7:0]    p_d_q;
  logic [VB-1:0] p_v_q;
  logic [1:0]    p_byte_q;
  logic [31:0]   rb_q;                         // rb read data
  logic          has_l_q;                      // a valid pixel seen in this row
  logic [VB-1:0] last_l_q;
  logic          p_ok;
  logic [7:0]    p_dr;                         // dR(x - d)
  assign p_dr = rb_q[8*p_byte_q +: 8];
  assign p_ok = p_inb_q && ((p_d_q >= p_dr) ? (p_d_q - p_dr) : (p_dr - p_d_q)) <= {2'b00, tol_q};

  // ---- CD: stage 1 reads column x; 2 fills and writes the mask; 3 sorts the
  // column and shifts it in; 4 takes the median; 5 writes the output ------------------
  logic          cd_c_q;                       // fill row y (0: the last pass, median of row H - 1)
  logic          cd_d_q;                       // write medians (not in row 0's pass)
  logic          ups_q, mids_q;                // median row buffers of rows r - 1 and r
  logic [CW-1:0] cx_q;                         // next column to read
  logic          cfl_q, cend_q;                // the flush step is next / was issued
  logic          q_room;
  logic          cd_issue;
  assign cd_issue = st_q == S_CD && !cend_q && q_room;
  logic          v2_q, f2_q, v3_q, f3_q, first3_q, v4_q, v5_q;
  logic [CW-1:0] x2_q, x3_q, ox4_q, ox5_q;
  logic [VB+1:0] vrow_q;
  logic [VB-1:0] m0_q, m1_q;
  logic [3*VB-1:0] col3_q;                     // {up, mid, down} of column x3
  logic [3*VB-1:0] c0_q, c1_q, c2_q;           // sorted columns x, x + 1, x + 2
  logic [VB-1:0] med5_q;
  logic          has_r_q;
  logic [VB-1:0] last_r_q;
  logic [31:0]   mword_q, oword_q;
  logic [3:0]    mbe_q, obe_q;

  // Stage 2: the filled value.
  logic          px_valid, px_has;
  logic [VB-1:0] px_val, filled, up_v, mid_v;
  assign {px_valid, px_has, px_val} = vrow_q;
  assign filled = px_valid ? px_val :
                  !px_has ? (has_r_q ? last_r_q : '0) :
                  !has_r_q ? px_val :
                  (px_val < last_r_q) ? px_val : last_r_q;
  assign up_v  = ups_q ? m1_q : m0_q;
  assign mid_v = mids_q ? m1_q : m0_q;

  // Median of nine from three sorted columns: the median of the largest minimum,
  // the median of the medians and the smallest maximum.
  function automatic logic [3*VB-1:0] sort3(input logic [3*VB-1:0] col);
    logic [VB-1:0] a, b, c, t;
    {a, b, c} = col;
    if (a > b) begin t = a; a = b; b = t; end
    if (b > c) begin t = b; b = c; c = t; end
    if (a > b) begin t = a; a = b; b = t; end
    sort3 = {a, b, c};                         // a <= b <= c
  endfunction
  function automatic logic [VB-1:0] med3(input logic [VB-1:0] a, input logic [VB-1:0] b,
                                         input logic [VB-1:0] c);
    logic [VB-1:0] lo, hi;
    lo = (a < b) ? a : b;
    hi = (a < b) ? b : a;
    hi = (hi < c) ? hi : c;
    med3 = (lo > hi) ? lo : hi;
  endfunction
  function automatic logic [VB-1:0] median9(input logic [3*VB-1:0] s0, input logic [3*VB-1:0] s1,
                                            input logic [3*VB-1:0] s2);
    logic [VB-1:0] lo, hi, a, b;
    lo = s0[2*VB +: VB];
    if (s1[2*VB +: VB] > lo) lo = s1[2*VB +: VB];
    if (s2[2*VB +: VB] > lo) lo = s2[2*VB +: VB];
    hi = s0[0 +: VB];
    if (s1[0 +: VB] < hi) hi = s1[0 +: VB];
    if (s2[0 +: VB] < hi) hi = s2[0 +: VB];
    a = med3(s0[VB +: VB], s1[VB +: VB], s2[VB +: VB]);
    b = med3(lo, a, hi);
    median9 = b;
  endfunction

  // ---- Write queue: mask words (stage 2) and output words (stage 5) -----------------
  logic [QD*QE-1:0] q_q;
  logic [QI-1:0]    qw_q, qr_q;
  logic             qa_push, qb_push, q_pop;   // a: mask, b: output
  logic [QE-1:0]    qa_e, qb_e, q_head;
  logic [QI-1:0]    qw_b;                      // entry of an output word
  assign qw_b = qw_q + QI'(qa_push);
  // Issue a pixel only while the queue can take what the pixels in flight
  // may still push: at most one mask and three output words (stages 1 to 5).
  assign q_room = qc_q <= (QI + 1)'(QD - 5);
  assign q_head = q_q[qr_q*QE +: QE];
  logic          e_out;                        // the head entry's fields
  logic [CW-1:0] e_k;
  logic [3:0]    e_be;
  logic [31:0]   e_data;
  assign {e_out, e_k, e_be, e_data} = q_head;
  assign q_pop  = qc_q != '0 && port_free && (st_q == S_CD || st_q == S_NEXT || st_q == S_DONE);

  // Stage 2 mask word, stage 5 output word.
  logic [7:0]    mbyte;
  assign mbyte = px_valid ? 8'hff : 8'h00;
  assign qa_push = v2_q && !f2_q && cd_c_q && x2_q[1:0] == 2'b00;
  assign qa_e = {1'b0, x2_q >> 2, mbe_q | 4'b0001, mword_q | {24'h0, mbyte}};
  logic [31:0] o_data;
  logic [3:0]  o_be;
  logic        o_last;                         // the pixel is the lowest of its word
  // Byte b of the word: this pixel's (8-bit: byte x % 4; wide: bytes 2 (x % 2) and
  // 2 (x % 2) + 1), or the word's so far.
  for (genvar b = 0; b < 4; b++) begin : g_obyte
    logic mine;
    assign mine = wide_q ? ox5_q[0] == 1'(b / 2) : ox5_q[1:0] == 2'(b);
    assign o_data[8*b +: 8] = !mine ? oword_q[8*b +: 8] :
                              (wide_q && b % 2 == 1) ? 8'(16'(med5_q) >> 8) : 8'(med5_q);
    assign o_be[b] = mine || obe_q[b];
  end
  assign o_last  = wide_q ? !ox5_q[0] : ox5_q[1:0] == 2'b00;
  assign qb_push = v5_q && cd_d_q && o_last;
  assign qb_e = {1'b1, wide_q ? ox5_q >> 1 : ox5_q >> 2, o_be, o_data};

  // ---- Buffer ports -------------------------------------------------------------------
  always_ff @(posedge clk_i) begin
    if (mem_rvalid_i && rs_q < nr) rb[rs_q[RI-1:0]] <= mem_rdata_i;
    if (b_take) rb_q <= rb[bxd[RI+1:2]];
  end
  always_ff @(posedge clk_i) begin
    if (p_valid_q) vrow[p_x_q] <= {p_ok, p_ok || has_l_q, p_ok ? p_v_q : last_l_q};
    if (cd_issue && !cfl_q) vrow_q <= vrow[XI'(cx_q)];
  end
  logic mw_en;                                 // stage 2 writes the filled value
  assign mw_en = v2_q && !f2_q && cd_c_q;
  always_ff @(posedge clk_i) begin
    if (mw_en && !y_q[0]) med0[XI'(x2_q)] <= filled;
    if (cd_issue && !cfl_q) m0_q <= med0[XI'(cx_q)];
  end
  always_ff @(posedge clk_i) begin
    if (mw_en && y_q[0]) med1[XI'(x2_q)] <= filled;
    if (cd_issue && !cfl_q) m1_q <= med1[XI'(cx_q)];
  end

  // Start a CD pass: fill (and median of the previous row) or the last median.
  task automatic start_cd(input logic fill, input logic medians);
    cd_c_q  <= fill;
    cd_d_q  <= medians;
    // Median rows: row r - 1 (clamped) and row r, r = y - 1 (fill) or y (last).
    if (fill) begin
      mids_q <= !y_q[0];
      ups_q  <= (y_q == CW'(1)) ? !y_q[0] : y_q[0];
    end else begin
      mids_q <= y_q[0];
      ups_q  <= (y_q == '0) ? y_q[0] : !y_q[0];
    end
    cx_q    <= w_q - CW'(1);
    cfl_q   <= 1'b0;
    cend_q  <= 1'b0;
    has_r_q <= 1'b0;
    mword_q <= '0;
    mbe_q   <= '0;
    oword_q <= '0;
    obe_q   <= '0;
    st_q    <= S_CD;
  endtask

  // The reads of a row: dR from dr_row, then dL (from rdl_q).
  task automatic start_reads(input logic [AW-1:0] dr_row);
    ra_q   <= dr_row;
    rq_q   <= '0;
    rs_q   <= '0;
    cred_q <= '0;
  endtask

  // Start the RD phase of row y (its reads started already).
  task automatic start_rd;
    wv_q    <= 1'b0;
    bx_q    <= '0;
    has_l_q <= 1'b0;
    st_q    <= S_RD;
  endtask

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      st_q <= S_IDLE;
      stride_q <= '0;
      ostride_q <= '0;
      w_q <= '0;
      h_q <= '0;
      tol_q <= '0;
      wide_q <= '0;
      rdr_q <= '0;
      rdl_q <= '0;
      rmask_q <= '0;
      rout_q <= '0;
      req_q <= '0;
      we_q <= '0;
      be_q <= '0;
      addr_q <= '0;
      wdata_q <= '0;
      y_q <= '0;
      rq_q <= '0;
      rs_q <= '0;
      ra_q <= '0;
      cred_q <= '0;
      pf_q <= '0;
      fq_q <= '0;
      fw_q <= '0;
      fr_q <= '0;
      fc_q <= '0;
      wv_q <= '0;
      word_q <= '0;
      j_q <= '0;
      bx_q <= '0;
      p_valid_q <= '0;
      p_inb_q <= '0;
      p_x_q <= '0;
      p_d_q <= '0;
      p_v_q <= '0;
      p_byte_q <= '0;
      has_l_q <= '0;
      last_l_q <= '0;
      cd_c_q <= '0;
      cd_d_q <= '0;
      ups_q <= '0;
      mids_q <= '0;
      cx_q <= '0;
      cfl_q <= '0;
      cend_q <= '0;
      v2_q <= '0;
      f2_q <= '0;
      v3_q <= '0;
      f3_q <= '0;
      first3_q <= '0;
      v4_q <= '0;
      v5_q <= '0;
      x2_q <= '0;
      x3_q <= '0;
      ox4_q <= '0;
      ox5_q <= '0;
      col3_q <= '0;
      c0_q <= '0;
      c1_q <= '0;
      c2_q <= '0;
      med5_q <= '0;
      has_r_q <= '0;
      last_r_q <= '0;
      mword_q <= '0;
      oword_q <= '0;
      mbe_q <= '0;
      obe_q <= '0;
      q_q <= '0;
      qw_q <= '0;
      qr_q <= '0;
      qc_q <= '0;
      done_o <= 1'b0;
    end else begin
      done_o <= 1'b0;
      if (req_q && mem_gnt_i) req_q <= 1'b0;

      // ---- RD: read requests (dR words, then dL words within the credit) ----------
      if (rd_issue) begin
        req_q  <= 1'b1;
        we_q   <= 1'b0;
        addr_q <= ra_q;
        ra_q   <= (rq_q + (CW + 1)'(1) == nr) ? rdl_q : ra_q + AW'(4);
        rq_q   <= rq_q + 1'b1;
      end
      if (mem_rvalid_i) rs_q <= rs_q + 1'b1;
      cred_q <= cred_q + (FI + 1)'(rd_issue && rq_dl) - (FI + 1)'(f_pop);
      if (f_push) begin
        fq_q[fw_q*32 +: 32] <= mem_rdata_i;
        fw_q <= fw_q + 1'b1;
      end
      if (f_pop) fr_q <= fr_q + 1'b1;
      fc_q <= fc_q + (FI + 1)'(f_push) - (FI + 1)'(f_pop);

      // ---- RD: the pixels of the dL words ------------------------------------------
      p_valid_q <= b_take;
      if (b_take) begin
        p_inb_q  <= !bxd[CW];
        p_x_q    <= XI'(bx_q);
        p_d_q    <= bd;
        p_v_q    <= bv;
        p_byte_q <= bxd[1:0];
        bx_q     <= bx_q + CW'(1);
        j_q      <= j_q + 2'd1;
        if (b_rlast) begin
          wv_q <= 1'b0;
          st_q <= S_BDR;
        end else if (b_wlast) begin
          wv_q <= f_pop;
          j_q  <= '0;
        end
      end
      if (f_pop) begin
        word_q <= fq_q[fr_q*32 +: 32];
        wv_q   <= 1'b1;
        j_q    <= '0;
      end
      // Stage 2: the check and the forward fill.
      if (p_valid_q && p_ok) begin
        has_l_q  <= 1'b1;
        last_l_q <= p_v_q;
      end

      // ---- CD -------------------------------------------------------------------------
      // Stage 1: read column cx, or the flush step after column 0.
      v2_q <= cd_issue;
      if (cd_issue) begin
        f2_q <= cfl_q;
        x2_q <= cx_q;
        if (cfl_q) cend_q <= 1'b1;
        else if (cx_q == '0) cfl_q <= 1'b1;
        else cx_q <= cx_q - CW'(1);
      end
      // Stage 2: the fill from the right, the mask byte, the column.
      v3_q <= v2_q;
      if (v2_q) begin
        f3_q     <= f2_q;
        x3_q     <= x2_q;
        first3_q <= x2_q + CW'(1) == w_q;
        col3_q   <= {up_v, mid_v, cd_c_q ? filled : mid_v};
        if (!f2_q && cd_c_q) begin
          if (px_valid) begin
            has_r_q  <= 1'b1;
            last_r_q <= px_val;
          end
          if (x2_q[1:0] == 2'b00) begin
            mword_q <= '0;
            mbe_q   <= '0;
          end else begin
            mword_q[8*x2_q[1:0] +: 8] <= mbyte;
            mbe_q[x2_q[1:0]] <= 1'b1;
          end
        end
      end
      // Stage 3: sort the column, shift it in (the first one twice: right edge;
      // the flush step shifts column 0 in again: left edge).
      v4_q <= v3_q && !(first3_q && !f3_q);
      if (v3_q) begin
        if (f3_q) begin
          c1_q  <= c0_q;
          c2_q  <= c1_q;
          ox4_q <= '0;
        end else begin
          c0_q  <= sort3(col3_q);
          c1_q  <= first3_q ? sort3(col3_q) : c0_q;
          c2_q  <= c1_q;
          ox4_q <= x3_q + CW'(1);
        end
      end
      // Stage 4: the median of column ox4.
      v5_q <= v4_q;
      if (v4_q) begin
        med5_q <= median9(c0_q, c1_q, c2_q);
        ox5_q  <= ox4_q;
      end
      // Stage 5: the output word.
      if (v5_q && cd_d_q) begin
        if (o_last) begin
          oword_q <= '0;
          obe_q   <= '0;
        end else begin
          oword_q <= o_data;
          obe_q   <= o_be;
        end
      end

      // ---- Write queue ----------------------------------------------------------------
      if (qa_push) q_q[qw_q*QE +: QE] <= qa_e;
      if (qb_push) q_q[qw_b*QE +: QE] <= qb_e;
      qw_q <= qw_q + QI'(qa_push) + QI'(qb_push);
      if (q_pop) begin
        req_q   <= 1'b1;
        we_q    <= 1'b1;
        addr_q  <= (e_out ? rout_q : rmask_q) + AW'({e_k, 2'b00});
        be_q    <= e_be;
        wdata_q <= e_data;
        qr_q    <= qr_q + 1'b1;
      end
      qc_q <= qc_q + (QI + 1)'(qa_push) + (QI + 1)'(qb_push) - (QI + 1)'(q_pop);

      // ---- Sequencer ------------------------------------------------------------------
      case (st_q)
        S_IDLE: if (start_i) begin
          stride_q <= stride_i;
          ostride_q <= out_stride_i;
          w_q <= width_i;
          h_q <= height_i;
          tol_q <= tol_i;
          wide_q <= wide_i;
          rdr_q <= base_dr_i;
          rdl_q <= base_dl_i;
          rmask_q <= base_mask_i;
          rout_q <= base_out_i;
          y_q <= '0;
          pf_q <= 1'b0;
          start_reads(base_dr_i);
          start_rd();
        end
        S_RD: ;                                  // left by the last pixel (above)
        // The last pixel's check happens in this cycle; CD reads from the next.
        // Row y + 1's reads may start during CD: its dR row goes into rb (free
        // in CD), its first dL words into the word queue.
        S_BDR: begin
          start_cd(1'b1, y_q != '0);
          rdr_q <= rdr_q + stride_q;
          rdl_q <= rdl_q + ostride_q;
          pf_q  <= y_q + CW'(1) < h_q;
          start_reads(rdr_q + stride_q);
        end
        S_CD: if (cend_q && !v2_q && !v3_q && !v4_q && !v5_q) st_q <= S_NEXT;
        S_NEXT: if (qc_q == '0) begin
          // Row y done (its mask, the median of row y - 1); the output row moves
          // to row y once it has been written.
          if (y_q != '0) rout_q <= rout_q + ostride_q;
          pf_q <= 1'b0;
          if (!cd_c_q) st_q <= S_DONE;            // that was the last pass (no fill)
          else if (y_q + CW'(1) < h_q) begin
            y_q     <= y_q + CW'(1);
            rmask_q <= rmask_q + stride_q;
            start_rd();
          end else begin
            start_cd(1'b0, 1'b1);
          end
        end
        S_DONE: if (!req_q) begin
          done_o <= 1'b1;
          st_q   <= S_IDLE;
        end
        default: st_q <= S_IDLE;
      endcase
    end
  end

  assign busy_o = st_q != S_IDLE;

  // ---- Invariants -------------------------------------------------------------------------
  // The write queue takes every word the pixels in flight push (q_room keeps room
  // for them), the dL word queue every word requested (the credit), and a request
  // waits for its grant before the next one.
  `MCADSW_ASSERT(WriteQueueFits, 32'(qc_q) + 32'(qa_push) + 32'(qb_push) <= QD + 32'(q_pop))
  `MCADSW_ASSERT(WordQueueFits, !(f_push && !f_pop && fc_q == (FI + 1)'(FD)))
  `MCADSW_ASSERT(CreditWithinQueue, cred_q <= (FI + 1)'(FD))
  `MCADSW_ASSERT(OneRequestAtATime, !(port_free == 1'b0 && (rd_issue || q_pop)))
  `MCADSW_ASSERT(QuietWhenIdle, st_q != S_IDLE || (!req_q && qc_q == '0))

endmodule

`default_nettype wire
