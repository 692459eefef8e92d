// Post-processing stage of the LR mode (docs/algorithm.md 12.2-12.5,
// docs/architecture.md section 12): reads the left map dL and the right map dR
// back from external memory row by row and writes the LR-checked, filled,
// 3x3-median-filtered map and the validity mask.
//
// First version: correct and simple, one phase of a row at a time, one memory
// request at a time (its own 32-bit port, in the protocol of docs/memory_map.md;
// the top will give it the external port once both passes are done). Not yet
// in the top; the cycle target of the LR mode needs the phases overlapped.
//
// Planes (every base a multiple of 4):
//   dL    (base_dl_i, out_stride_i): 1 byte a pixel, d; wide: a halfword a pixel,
//         d in bits 7:0 and offset + 8 in bits 12:8 (the value is 16 d + offset)
//   dR    (base_dr_i, stride_i): 1 byte a pixel, d
//   out   (base_out_i, out_stride_i): 1 byte (d) or a halfword (16 d + offset) a pixel
//   mask  (base_mask_i, stride_i): 1 byte a pixel, 255 valid, 0 filled
// For each row y:
//   A  read dR row y into rb
//   B  read dL row y; valid(x) = x >= d && |d - dR(x - d)| <= T; keep the value,
//      the valid bit and the nearest valid value to the left (forward fill)
//   C  from right to left: the nearest valid value to the right, the filled value
//      into median row y % 3; write mask row y
//   D  median of row y - 1 (rows y - 2, y - 1, y, edges replicated); write it
// and after the last row, D of row H - 1.
`default_nettype none

module mcadsw_post #(
  parameter int MAXW = mcadsw_pkg::MAX_WIDTH,
  parameter int DB   = mcadsw_pkg::DISP_BITS,
  parameter int VB   = DB + 4,                  // value: d, or 16 d + offset
  parameter int CW   = 12,
  parameter int AW   = 32
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

  // ---- Row buffers (synchronous read, one write port each) -----------------------
  logic [31:0]   rb [MAXW / 4];                // dR row, 4 pixels a word
  logic [VB:0]   vrow [MAXW];                  // {valid, value}
  logic [VB:0]   fl [MAXW];                    // {has a valid pixel on the left, its value}
  logic [VB-1:0] med0 [MAXW], med1 [MAXW], med2 [MAXW];  // filled rows, row % 3

  // ---- Configuration, registered at start ------------------------------------------
  logic [AW-1:0] base_dl_q, base_dr_q, base_out_q, base_mask_q, stride_q, ostride_q;
  logic [CW-1:0] w_q, h_q;
  logic [5:0]    tol_q;
  logic          wide_q;

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

  // ---- Sequencer ------------------------------------------------------------------
  typedef enum logic [3:0] {
    S_IDLE, S_A_REQ, S_A_WAIT, S_B_REQ, S_B_WAIT, S_B_PIX, S_B_DRAIN,
    S_C_RUN, S_C_WR, S_D_RD, S_D_CMP, S_D_WR, S_DONE
  } state_e;
  state_e        st_q;
  logic [CW-1:0] y_q;                          // row being read (A, B, C)
  logic [CW-1:0] r_q;                          // row being filtered (D)
  logic          last_d_q;                     // D of the last row
  logic [CW:0]   k_q;                          // word of the row
  logic [CW:0]   x_q;                          // pixel
  logic [31:0]   word_q;                       // dL word being taken apart
  logic [AW-1:0] row_dl, row_dr, row_out, row_mask;
  assign row_dl   = base_dl_q + AW'(y_q) * ostride_q;
  assign row_dr   = base_dr_q + AW'(y_q) * stride_q;
  assign row_mask = base_mask_q + AW'(y_q) * stride_q;
  assign row_out  = base_out_q + AW'(r_q) * ostride_q;

  logic [CW:0] words_dr, words_dl;             // words of a dR / dL row
  assign words_dr = ({1'b0, w_q} + (CW + 1)'(3)) >> 2;
  assign words_dl = wide_q ? ({1'b0, w_q} + (CW + 1)'(1)) >> 1 : words_dr;

  // ---- B: the LR check, one pixel a cycle (rb read, then the check) ----------------
  logic [2:0]    pix_j_q;                      // pixel of word_q
  logic [CW:0]   bx;                           // its column
  logic [7:0]    bd;                           // its d
  logic [VB-1:0] bv;                           // its value
  assign bx = wide_q ? {k_q[CW-1:0], 1'b0} + (CW + 1)'(pix_j_q)
                     : {k_q[CW-2:0], 2'b00} + (CW + 1)'(pix_j_q);
  logic [15:0] b_hw;                           // wide: the pixel's halfword
  assign b_hw = pix_j_q[0] ? word_q[31:16] : word_q[15:0];
  assign bd = wide_q ? b_hw[7:0] : word_q[8*pix_j_q[1:0] +: 8];
  assign bv = wide_q ? VB'({b_hw[7:0], 4'b0000}) + VB'(b_hw[12:8]) - VB'(8) : VB'(bd);
  logic [2:0] b_hw_unused;
  assign b_hw_unused = b_hw[15:13];
  logic [CW:0] bxd;                            // x - d
  assign bxd = bx - (CW + 1)'(bd);
  logic          p_valid_q, p_inb_q;           // stage 2: pixel, x - d >= 0
  logic [XI-1:0] p_x_q;
  logic [7:0]    p_d_q;
  logic [VB-1:0] p_v_q;
  logic [1:0]    p_byte_q;
  logic [31:0]   rb_q;                         // rb read data
  logic          has_l_q;                      // a valid pixel seen in this row
  logic [VB-1:0] last_l_q;
  logic          p_ok;
  always_comb begin
    logic [7:0] dr;
    dr   = rb_q[8*p_byte_q +: 8];
    p_ok = p_inb_q && ((p_d_q >= dr) ? (p_d_q - dr) : (dr - p_d_q)) <= {2'b00, tol_q};
  end
  logic b_take;                                // a pixel of word_q enters stage 2
  assign b_take = st_q == S_B_PIX && bx < {1'b0, w_q} && pix_j_q < (wide_q ? 3'd2 : 3'd4);

  // ---- C: fill from the right, mask bytes -------------------------------------------
  logic          c_valid_q;                    // stage 2 of C: vrow/fl data for c_x_q
  logic [CW:0]   c_x_q;
  logic [VB:0]   vrow_q, fl_q;
  logic          has_r_q;
  logic [VB-1:0] last_r_q;
  logic [31:0]   mword_q;                      // mask word being assembled
  logic [3:0]    mbe_q;
  logic [VB-1:0] filled, fill_l;
  logic          fl_has, px_valid;
  assign {fl_has, fill_l} = fl_q;              // nearest valid value on the left
  assign px_valid = vrow_q[VB];                // this pixel passed the check
  assign filled = px_valid ? vrow_q[VB-1:0] :
                  !fl_has ? (has_r_q ? last_r_q : '0) :
                  !has_r_q ? fill_l :
                  (fill_l < last_r_q) ? fill_l : last_r_q;
  logic [1:0] med_slot_y;                      // y % 3
  logic [1:0] slot_q;

  // ---- D: 3x3 median -------------------------------------------------------------------
  logic [CW:0]   dc_q;                         // column read (0 .. W, clamped to W - 1)
  logic [1:0]    s_up_q, s_mid_q, s_dn_q;      // median slots of rows r-1, r, r+1 (clamped)
  logic [VB-1:0] m0_q, m1_q, m2_q;             // read data of the three rows at column dc - 1
  logic [3*VB-1:0] colL_q, colM_q;             // columns x - 1 and x
  logic [VB-1:0] med_out;
  logic [31:0]   oword_q;
  logic [3:0]    obe_q;

  function automatic logic [VB-1:0] row_of(input logic [1:0] s, input logic [VB-1:0] a,
                                           input logic [VB-1:0] b, input logic [VB-1:0] c);
    row_of = (s == 2'd0) ? a : (s == 2'd1) ? b : c;
  endfunction
  logic [3*VB-1:0] col_new;                    // {up, mid, down} at the column just read
  assign col_new = {row_of(s_up_q, m0_q, m1_q, m2_q), row_of(s_mid_q, m0_q, m1_q, m2_q),
                    row_of(s_dn_q, m0_q, m1_q, m2_q)};

  // Median of nine: sort each column, then the classic reduction (max of the
  // minima, median of the medians, min of the maxima; their median).
  function automatic logic [3*VB-1:0] sort3(input logic [VB-1:0] a, input logic [VB-1:0] b,
                                            input logic [VB-1:0] c);
    logic [VB-1:0] t;
    if (a > b) begin t = a; a = b; b = t; end
    if (b > c) begin t = b; b = c; c = t; end
    if (a > b) begin t = a; a = b; b = t; end
    sort3 = {a, b, c};                         // a <= b <= c
  endfunction
  function automatic logic [VB-1:0] median9(input logic [3*VB-1:0] c0, input logic [3*VB-1:0] c1,
                                            input logic [3*VB-1:0] c2);
    logic [VB-1:0] lo0, mi0, hi0, lo1, mi1, hi1, lo2, mi2, hi2, a, b, c;
    {lo0, mi0, hi0} = sort3(c0[2*VB +: VB], c0[VB +: VB], c0[0 +: VB]);
    {lo1, mi1, hi1} = sort3(c1[2*VB +: VB], c1[VB +: VB], c1[0 +: VB]);
    {lo2, mi2, hi2} = sort3(c2[2*VB +: VB], c2[VB +: VB], c2[0 +: VB]);
    a = (lo0 > lo1) ? lo0 : lo1;  a = (a > lo2) ? a : lo2;          // max of the minima
    c = (hi0 < hi1) ? hi0 : hi1;  c = (c < hi2) ? c : hi2;          // min of the maxima
    {lo0, b, hi0} = sort3(mi0, mi1, mi2);                            // median of the medians
    {lo1, mi1, hi1} = sort3(a, b, c);
    median9 = mi1;
  endfunction
  assign med_out = median9(colL_q, colM_q, col_new);

  // ---- Buffer ports -------------------------------------------------------------------
  // rb: written in A, read in B.
  always_ff @(posedge clk_i) begin
    if (st_q == S_A_WAIT && mem_rvalid_i) rb[k_q[RI-1:0]] <= mem_rdata_i;
    if (b_take) rb_q <= rb[bxd[RI+1:2]];
  end
  // vrow, fl: written in B stage 2, read in C.
  always_ff @(posedge clk_i) begin
    if (p_valid_q) begin
      vrow[p_x_q] <= {p_ok, p_v_q};
      fl[p_x_q]   <= {has_l_q, last_l_q};
    end
    if (st_q == S_C_RUN) begin
      vrow_q <= vrow[x_q[XI-1:0]];
      fl_q   <= fl[x_q[XI-1:0]];
    end
  end
  // Median rows: written in C stage 2, read in D.
  logic [XI-1:0] mw_x;                         // C stage 2 writes pixel c_x_q
  assign mw_x = XI'(c_x_q);
  logic [XI-1:0] dc_rd;
  assign dc_rd = XI'((dc_q >= {1'b0, w_q}) ? {1'b0, w_q} - (CW + 1)'(1) : dc_q);
  always_ff @(posedge clk_i) begin
    if (c_valid_q && slot_q == 2'd0) med0[mw_x] <= filled;
    if (c_valid_q && slot_q == 2'd1) med1[mw_x] <= filled;
    if (c_valid_q && slot_q == 2'd2) med2[mw_x] <= filled;
    if (st_q == S_D_RD) begin
      m0_q <= med0[dc_rd];
      m1_q <= med1[dc_rd];
      m2_q <= med2[dc_rd];
    end
  end

  function automatic logic [1:0] mod3(input logic [CW-1:0] v);
    mod3 = 2'(32'(v) % 3);
  endfunction
  assign med_slot_y = mod3(y_q);

  // Start D for row r (rows r - 1, r, r + 1, clamped to the image).
  task automatic start_d(input logic [CW-1:0] r);
    r_q     <= r;
    s_up_q  <= mod3((r == '0) ? r : r - CW'(1));
    s_mid_q <= mod3(r);
    s_dn_q  <= mod3((r + CW'(1) >= h_q) ? r : r + CW'(1));
    dc_q    <= '0;
    obe_q   <= '0;
    oword_q <= '0;
    st_q    <= S_D_RD;
  endtask

  // Next row after C of row y: D of row y - 1, or the next row's A.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      st_q <= S_IDLE;
      base_dl_q <= '0;
      base_dr_q <= '0;
      base_out_q <= '0;
      base_mask_q <= '0;
      stride_q <= '0;
      ostride_q <= '0;
      w_q <= '0;
      h_q <= '0;
      tol_q <= '0;
      wide_q <= '0;
      req_q <= '0;
      we_q <= '0;
      be_q <= '0;
      addr_q <= '0;
      wdata_q <= '0;
      y_q <= '0;
      r_q <= '0;
      last_d_q <= '0;
      k_q <= '0;
      x_q <= '0;
      word_q <= '0;
      pix_j_q <= '0;
      p_valid_q <= '0;
      p_inb_q <= '0;
      p_x_q <= '0;
      p_d_q <= '0;
      p_v_q <= '0;
      p_byte_q <= '0;
      has_l_q <= '0;
      last_l_q <= '0;
      c_valid_q <= '0;
      c_x_q <= '0;
      has_r_q <= '0;
      last_r_q <= '0;
      mword_q <= '0;
      mbe_q <= '0;
      slot_q <= '0;
      dc_q <= '0;
      s_up_q <= '0;
      s_mid_q <= '0;
      s_dn_q <= '0;
      colL_q <= '0;
      colM_q <= '0;
      oword_q <= '0;
      obe_q <= '0;
      done_o <= 1'b0;
    end else begin
      done_o <= 1'b0;
      if (req_q && mem_gnt_i) req_q <= 1'b0;
      p_valid_q <= 1'b0;
      c_valid_q <= 1'b0;
      case (st_q)
        S_IDLE: if (start_i) begin
          base_dl_q <= base_dl_i;  base_dr_q <= base_dr_i;
          base_out_q <= base_out_i; base_mask_q <= base_mask_i;
          stride_q <= stride_i;    ostride_q <= out_stride_i;
          w_q <= width_i;  h_q <= height_i;  tol_q <= tol_i;  wide_q <= wide_i;
          y_q <= '0;  k_q <= '0;
          st_q <= S_A_REQ;
        end
        // A: dR row, a word at a time.
        S_A_REQ: if (port_free) begin
          req_q <= 1'b1;
          we_q <= 1'b0;
          addr_q <= row_dr + AW'({k_q, 2'b00});
          st_q <= S_A_WAIT;
        end
        S_A_WAIT: if (mem_rvalid_i) begin
          k_q  <= k_q + 1'b1;
          if (k_q + 1'b1 == words_dr) begin
            k_q <= '0;
            has_l_q <= 1'b0;
            st_q <= S_B_REQ;
          end else st_q <= S_A_REQ;
        end
        // B: dL row, a word at a time, its pixels one a cycle.
        S_B_REQ: if (port_free) begin
          req_q <= 1'b1;
          we_q <= 1'b0;
          addr_q <= row_dl + AW'({k_q, 2'b00});
          st_q <= S_B_WAIT;
        end
        S_B_WAIT: if (mem_rvalid_i) begin
          word_q  <= mem_rdata_i;
          pix_j_q <= '0;
          st_q    <= S_B_PIX;
        end
        S_B_PIX: begin
          if (b_take) begin
            p_valid_q <= 1'b1;
            p_inb_q   <= !bxd[CW];
            p_x_q     <= XI'(bx);
            p_d_q     <= bd;
            p_v_q     <= bv;
            p_byte_q  <= bxd[1:0];
            pix_j_q   <= pix_j_q + 3'd1;
          end else begin
            // Word done: the next, or the end of the row once stage 2 drains.
            k_q <= k_q + 1'b1;
            st_q <= (k_q + 1'b1 == words_dl) ? S_B_DRAIN : S_B_REQ;
          end
        end
        S_B_DRAIN: begin
          // The last pixel's stage 2 happens in this cycle; C starts at x = W - 1.
          x_q     <= {1'b0, w_q} - (CW + 1)'(1);
          has_r_q <= 1'b0;
          slot_q  <= med_slot_y;
          mword_q <= '0;
          mbe_q   <= '0;
          st_q    <= S_C_RUN;
        end
        // C: from right to left, one pixel a cycle; a mask word is written when
        // its lowest pixel (x % 4 == 0) has been done.
        S_C_RUN: begin
          c_valid_q <= 1'b1;
          c_x_q     <= x_q;
          if (x_q[1:0] == 2'b00 || x_q == '0) st_q <= S_C_WR;
          else x_q <= x_q - 1'b1;
        end
        S_C_WR: if (port_free && !c_valid_q) begin
          req_q <= 1'b1;
          we_q <= 1'b1;
          addr_q  <= row_mask + AW'({c_x_q[CW:2], 2'b00});
          be_q    <= mbe_q;
          wdata_q <= mword_q;
          mbe_q   <= '0;
          mword_q <= '0;
          if (c_x_q == '0) begin
            // Row y filled: the median of row y - 1 can be made.
            if (y_q != '0) start_d(y_q - CW'(1));
            else st_q <= S_D_WR;                 // no median yet: next row (below)
          end else begin
            x_q  <= c_x_q - 1'b1;
            st_q <= S_C_RUN;
          end
        end
        // D: read column dc of the three rows, then shift and filter.
        S_D_RD: st_q <= S_D_CMP;
        S_D_CMP: begin
          dc_q <= dc_q + 1'b1;
          if (dc_q == '0) begin
            colL_q <= col_new;
            colM_q <= col_new;
            st_q   <= S_D_RD;
          end else begin
            // Output pixel x = dc - 1.
            logic [CW:0] ox;
            ox = dc_q - (CW + 1)'(1);
            colL_q <= colM_q;
            colM_q <= col_new;
            if (wide_q) begin
              oword_q[16*ox[0] +: 16] <= 16'(med_out);
              obe_q[2*ox[0] +: 2] <= 2'b11;
            end else begin
              oword_q[8*ox[1:0] +: 8] <= 8'(med_out);
              obe_q[ox[1:0]] <= 1'b1;
            end
            if ((wide_q ? ox[0] == 1'b1 : ox[1:0] == 2'b11) || ox + (CW + 1)'(1) == {1'b0, w_q})
              st_q <= S_D_WR;
            else st_q <= S_D_RD;
          end
        end
        S_D_WR: if (port_free) begin
          if (obe_q != '0) begin
            logic [CW:0] ox;
            ox = dc_q - (CW + 1)'(2);            // the word's last pixel
            req_q <= 1'b1;
            we_q <= 1'b1;
            addr_q  <= row_out + ((wide_q ? AW'({ox, 1'b0}) : AW'(ox)) & ~(AW'(3)));
            be_q    <= obe_q;
            wdata_q <= oword_q;
            obe_q   <= '0;
            oword_q <= '0;
          end
          if (obe_q != '0 && dc_q <= {1'b0, w_q}) st_q <= S_D_RD;
          else if (last_d_q) st_q <= S_DONE;
          else if (y_q + CW'(1) < h_q) begin
            // The next row.
            y_q  <= y_q + CW'(1);
            k_q  <= '0;
            st_q <= S_A_REQ;
          end else begin
            // After the last row's C: the median of row H - 1.
            last_d_q <= 1'b1;
            start_d(h_q - CW'(1));
          end
        end
        S_DONE: if (!req_q) begin
          last_d_q <= 1'b0;
          done_o   <= 1'b1;
          st_q     <= S_IDLE;
        end
        default: st_q <= S_IDLE;
      endcase
      // B stage 2: the check, the forward fill.
      if (p_valid_q && p_ok) begin
        has_l_q  <= 1'b1;
        last_l_q <= p_v_q;
      end
      // C stage 2: the fill from the right, the mask byte.
      if (c_valid_q) begin
        if (vrow_q[VB]) begin
          has_r_q  <= 1'b1;
          last_r_q <= vrow_q[VB-1:0];
        end
        mword_q[8*c_x_q[1:0] +: 8] <= vrow_q[VB] ? 8'hff : 8'h00;
        mbe_q[c_x_q[1:0]] <= 1'b1;
      end
    end
  end

  assign busy_o = st_q != S_IDLE;

endmodule

`default_nettype wire
