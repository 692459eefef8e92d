// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Second simulator (Icarus Verilog, 4-state): mcadsw_engine and its AXI4 master
// (mcadsw_axi_master, as in mcadsw_top) on the memory image the C++
// harness dumped (mcadsw_sim --dump DIR), programmed by replaying the register
// writes the C++ driver made for that frame (DIR/regs.txt, "offset value" in hex;
// reg_write below maps each register of docs/registers.md onto the engine's
// configuration ports, CTRL.START onto a start pulse; the rectification registers
// of register map 1.2, RECT_CTRL .. VALID_R, onto the rectifier's ports), with a
// zero-latency AXI4 memory timed as the C++ model's (sim/axi_memory.hpp,
// latency 0): always ready, an R beat
// the cycle after its AR, a burst written and answered (B) the cycle after its
// AW and last W beat are both in. Checks that no output is X or Z after reset,
// writes the disparity plane and the counters for tests/icarus/run.sh to
// compare with the Verilator run.
`timescale 1ns/1ps
module tb_mcadsw_engine;
  localparam int MAXW = 1 << 20;           // memory words
  localparam int NTHR = mcadsw_pkg::WTHRESHOLDS;  // 7: thr0 .. thr6 below
  localparam int DCB  = mcadsw_pkg::COLOR_DIST_BITS;

  // rst_n asserted with a falling edge (sim/bench_dut.hpp says why), released below.
  logic clk = 1'b0, rst_n = 1'b1;
  initial #1 rst_n = 1'b0;
  always #5 clk = ~clk;

  int words;
  logic [31:0] mem [MAXW];
  string dir;

  // The configuration bundle (mcadsw_pkg::CFG_*), as mcadsw_regs hands it on: each field as
  // the driver writes its register; the rectifier's 0 until then, as after reset.
  logic [mcadsw_pkg::CFG_BITS-1:0] cfg;
  initial cfg[mcadsw_pkg::CFG_RECT_EN +: mcadsw_pkg::CFG_BITS - mcadsw_pkg::CFG_RECT_EN] = '0;  // RECT_EN .. VALID_MAP
  // The fields the bench reads back: the planes it dumps.
  logic [31:0] base_out, base_mask, stride, out_stride;
  logic [11:0] height;
  logic        lr;
  assign base_out   = cfg[mcadsw_pkg::CFG_BASE_OUT +: 32];
  assign base_mask  = cfg[mcadsw_pkg::CFG_BASE_MASK +: 32];
  assign stride     = cfg[mcadsw_pkg::CFG_STRIDE +: 32];
  assign out_stride = cfg[mcadsw_pkg::CFG_OUT_STRIDE +: 32];
  assign height     = cfg[mcadsw_pkg::CFG_HEIGHT +: 12];
  assign lr         = cfg[mcadsw_pkg::CFG_MODE + 1];
  logic start = 1'b0;
  logic busy, done, error;
  logic [7:0] error_code;                  // STATUS.ERROR_CODE: 0 .. 24
  logic [31:0] cnt_cycles, cnt_rd, cnt_wr, cnt_stall;
  logic mem_req, mem_gnt, mem_we, mem_rvalid, wr_idle, bus_idle, rd_err, wr_err;
  logic [3:0] mem_be, mem_len;
  logic [31:0] mem_addr, mem_wdata, mem_rdata;
  // AXI4
  logic        arvalid, rvalid = 1'b0, rready, rlast, awvalid, wvalid, wlast, bvalid = 1'b0, bready;
  logic [31:0] araddr, rdata, awaddr, wdata;
  logic [7:0]  arlen, awlen;
  logic [2:0]  arsize, awsize;
  logic [1:0]  arburst, awburst;
  logic [3:0]  wstrb;

  mcadsw_engine dut (
    .clk_i (clk), .rst_ni (rst_n),
    .cfg_i (cfg),
    .start_i (start),
    .busy_o (busy), .done_o (done), .error_o (error), .error_code_o (error_code),
    .cnt_cycles_o (cnt_cycles), .cnt_words_read_o (cnt_rd), .cnt_words_written_o (cnt_wr),
    .cnt_stall_o (cnt_stall),
    .mem_req_o (mem_req), .mem_gnt_i (mem_gnt), .mem_we_o (mem_we), .mem_be_o (mem_be),
    .mem_addr_o (mem_addr), .mem_len_o (mem_len), .mem_wdata_o (mem_wdata),
    .mem_rvalid_i (mem_rvalid), .mem_rdata_i (mem_rdata), .mem_wr_idle_i (wr_idle)
  );

  mcadsw_axi_master u_axi (
    .clk_i (clk), .rst_ni (rst_n),
    .mem_req_i (mem_req), .mem_gnt_o (mem_gnt), .mem_we_i (mem_we), .mem_be_i (mem_be),
    .mem_addr_i (mem_addr), .mem_len_i (mem_len), .mem_wdata_i (mem_wdata),
    .mem_rvalid_o (mem_rvalid), .mem_rdata_o (mem_rdata), .drain_i (1'b0), .wr_idle_o (wr_idle), .idle_o (bus_idle),
    .rd_err_o (rd_err), .wr_err_o (wr_err),
    .m_arvalid_o (arvalid), .m_arready_i (1'b1), .m_araddr_o (araddr), .m_arlen_o (arlen),
    .m_arsize_o (arsize), .m_arburst_o (arburst),
    .m_rvalid_i (rvalid), .m_rready_o (rready), .m_rdata_i (rdata), .m_rresp_i (2'b00),
    .m_rlast_i (rlast),
    .m_awvalid_o (awvalid), .m_awready_i (1'b1), .m_awaddr_o (awaddr), .m_awlen_o (awlen),
    .m_awsize_o (awsize), .m_awburst_o (awburst),
    .m_wvalid_o (wvalid), .m_wready_i (1'b1), .m_wdata_o (wdata), .m_wstrb_o (wstrb),
    .m_wlast_o (wlast), .m_bvalid_i (bvalid), .m_bready_o (bready), .m_bresp_i (2'b00)
  );

  // Zero-latency AXI4 memory: R beats one a cycle from the cycle after the AR,
  // in order (as sim/axi_memory.hpp without latency).
  logic [31:0] r_addr [1024];
  logic        r_last [1024];
  int          r_in = 0, r_out = 0;
  logic [31:0] aw_addr [1024];
  int          aw_len [1024];
  logic [35:0] w_beat [16384];
  int          aw_n = 0, w_n = 0, wlast_n = 0, done_n = 0, beat_rd = 0;
  always @(posedge clk) begin
    rvalid <= 1'b0;
    rlast  <= 1'b0;
    bvalid <= 1'b0;
    if (rst_n && arvalid) begin
      if (araddr[1:0] != 2'b00 || araddr / 4 + arlen >= words || arsize != 3'd2 ||
          araddr % 4096 + 4 * (arlen + 1) > 4096) begin
        $display("FAIL: AR out of range, misaligned, not 4-byte beats or across 4 KiB: %h len %0d",
                 araddr, arlen);
        $finish;
      end
      for (int i = 0; i <= arlen; i++) begin
        r_addr[r_in % 1024] = araddr / 4 + i;
        r_last[r_in % 1024] = i == arlen;
        r_in++;
      end
    end
    if (rst_n && r_out < r_in) begin
      rdata  <= mem[r_addr[r_out % 1024]];
      rlast  <= r_last[r_out % 1024];
      rvalid <= 1'b1;
      r_out++;
    end
    if (rst_n && awvalid) begin
      aw_addr[aw_n % 1024] = awaddr;
      aw_len[aw_n % 1024]  = awlen;
      aw_n++;
    end
    if (rst_n && wvalid) begin
      w_beat[w_n % 16384] = {wstrb, wdata};
      w_n++;
      if (wlast) wlast_n++;
    end
    if (aw_n > done_n && wlast_n > done_n) begin
      for (int i = 0; i <= aw_len[done_n % 1024]; i++) begin
        logic [31:0] a;
        logic [35:0] b;
        a = aw_addr[done_n % 1024] / 4 + i;
        b = w_beat[beat_rd % 16384];
        beat_rd++;
        if (a >= words) begin $display("FAIL: write out of range: %h", a * 4); $finish; end
        for (int k = 0; k < 4; k++) if (b[32 + k]) mem[a][k*8 +: 8] = b[k*8 +: 8];
      end
      done_n++;
      bvalid <= 1'b1;
    end
  end

  // No X or Z on any output once reset is released.
  logic [3 + $bits(error_code) + 4 * 32 + 5 - 1:0] outs;   // every bit of the concatenation below
  assign outs = {busy, done, error, error_code, cnt_cycles, cnt_rd, cnt_wr, cnt_stall, arvalid,
                 awvalid, wvalid, rready, bready};
  longint xchecks = 0;
  always @(negedge clk) begin
    if (rst_n) begin
      xchecks++;
      if ($isunknown(outs) || (arvalid && $isunknown({araddr, arlen, arsize, arburst})) ||
          (awvalid && $isunknown({awaddr, awlen, awsize, awburst})) ||
          (wvalid && $isunknown({wdata, wstrb, wlast}))) begin
        $display("FAIL: X or Z on an output at %0t: status %b, AR %b %h, AW %b %h, W %b", $time,
                 {busy, done, error, error_code}, arvalid, araddr, awvalid, awaddr, wvalid);
        $finish;
      end
    end
  end

  // Debug aid: the first X inside the aggregator's inputs and costs.
  logic seen_x = 1'b0;
  always @(negedge clk) begin
    if (rst_n && !seen_x) begin
      if (dut.u_cost_agg.ev_valid && dut.u_cost_agg.v2_valid_q && $isunknown(dut.u_cost_agg.ev)) begin
        seen_x = 1'b1;
        $display("DEBUG: X in vertical costs at %0t row %0d d %0d grp %0d: cen_l %0d cen_r %0d wv %0d",
                 $time, dut.u_cost_agg.v2_row_q, dut.u_cost_agg.v2_d_q, dut.u_cost_agg.v2_grp_q,
                 $isunknown(dut.cen_l), $isunknown(dut.cen_r), $isunknown(dut.wv));
      end
      if (dut.u_cost_agg.fc_valid && dut.u_cost_agg.h3_valid_q && $isunknown(dut.u_cost_agg.fc)) begin
        seen_x = 1'b1;
        $display("DEBUG: X in final costs at %0t row %0d d %0d grp %0d", $time,
                 dut.u_cost_agg.h3_row_q, dut.u_cost_agg.h3_d_q, dut.u_cost_agg.h3_grp_q);
      end
    end
  end

  // A register write of the driver onto the configuration ports (the fields of
  // mcadsw_regs); CTRL.START: a one-cycle start pulse at the next clock edge.
  int reg_off, reg_val;
  logic started = 1'b0;
  task automatic reg_write(input int off, input logic [31:0] v);
    case (off)
      mcadsw_pkg::REG_BASE_LY: cfg[mcadsw_pkg::CFG_BASE_LY +: 32] = v;
      mcadsw_pkg::REG_BASE_LU: cfg[mcadsw_pkg::CFG_BASE_LU +: 32] = v;
      mcadsw_pkg::REG_BASE_LV: cfg[mcadsw_pkg::CFG_BASE_LV +: 32] = v;
      mcadsw_pkg::REG_BASE_RY: cfg[mcadsw_pkg::CFG_BASE_RY +: 32] = v;
      mcadsw_pkg::REG_BASE_RU: cfg[mcadsw_pkg::CFG_BASE_RU +: 32] = v;
      mcadsw_pkg::REG_BASE_RV: cfg[mcadsw_pkg::CFG_BASE_RV +: 32] = v;
      mcadsw_pkg::REG_BASE_OUT: cfg[mcadsw_pkg::CFG_BASE_OUT +: 32] = v;
      mcadsw_pkg::REG_BASE_DL: cfg[mcadsw_pkg::CFG_BASE_DL +: 32] = v;
      mcadsw_pkg::REG_BASE_DR: cfg[mcadsw_pkg::CFG_BASE_DR +: 32] = v;
      mcadsw_pkg::REG_BASE_MASK: cfg[mcadsw_pkg::CFG_BASE_MASK +: 32] = v;
      mcadsw_pkg::REG_STRIDE: cfg[mcadsw_pkg::CFG_STRIDE +: 32] = v;
      mcadsw_pkg::REG_OUT_STRIDE: cfg[mcadsw_pkg::CFG_OUT_STRIDE +: 32] = v;
      mcadsw_pkg::REG_TILE_STRIDE: cfg[mcadsw_pkg::CFG_TILE_STRIDE +: 32] = v;
      mcadsw_pkg::REG_SIZE: begin
        cfg[mcadsw_pkg::CFG_WIDTH +: 12]  = v[mcadsw_pkg::SIZE_WIDTH_LSB +: mcadsw_pkg::SIZE_WIDTH_W];
        cfg[mcadsw_pkg::CFG_HEIGHT +: 12] = v[mcadsw_pkg::SIZE_HEIGHT_LSB +: mcadsw_pkg::SIZE_HEIGHT_W];
      end
      mcadsw_pkg::REG_DISP: cfg[mcadsw_pkg::CFG_DISP +: 8] = 8'(v[mcadsw_pkg::DISP_D_LSB +: $clog2(mcadsw_pkg::DMAX + 1)]);
      mcadsw_pkg::REG_LR_T: cfg[mcadsw_pkg::CFG_LR_T +: 8] = v[mcadsw_pkg::LR_T_T_LSB +: mcadsw_pkg::LR_T_T_W];
      mcadsw_pkg::REG_CTRL: begin
        cfg[mcadsw_pkg::CFG_MODE +: 3] = v[mcadsw_pkg::CTRL_MODE_LSB +: mcadsw_pkg::CTRL_MODE_W];
        if (v[mcadsw_pkg::CTRL_START_LSB]) begin
          @(posedge clk); #1 start = 1'b1;
          @(posedge clk); #1 start = 1'b0;
          started = 1'b1;
        end
      end
      mcadsw_pkg::REG_STATUS, mcadsw_pkg::REG_IRQ_ENABLE: ;  // no register block, no interrupt
      // Rectification (register map 1.2; the driver writes them for every frame,
      // ENABLE 0 without it), as mcadsw_regs: the fields, the addresses whole.
      mcadsw_pkg::REG_RECT_CTRL: begin
        cfg[mcadsw_pkg::CFG_RECT_EN]   = v[mcadsw_pkg::RECT_CTRL_ENABLE_LSB];
        cfg[mcadsw_pkg::CFG_RECT_STEP +: 3] = v[mcadsw_pkg::RECT_CTRL_STEP_LOG2_LSB +: mcadsw_pkg::RECT_CTRL_STEP_LOG2_W];
      end
      mcadsw_pkg::REG_RAW_SIZE: begin
        cfg[mcadsw_pkg::CFG_RAW_WIDTH +: 12]  = v[mcadsw_pkg::RAW_SIZE_WIDTH_LSB +: mcadsw_pkg::RAW_SIZE_WIDTH_W];
        cfg[mcadsw_pkg::CFG_RAW_HEIGHT +: 12] = v[mcadsw_pkg::RAW_SIZE_HEIGHT_LSB +: mcadsw_pkg::RAW_SIZE_HEIGHT_W];
      end
      mcadsw_pkg::REG_RAW_STRIDE: cfg[mcadsw_pkg::CFG_RAW_STRIDE +: 32] = v;
      mcadsw_pkg::REG_RAW_LY: cfg[mcadsw_pkg::CFG_RAW + 0*32 +: 32] = v;
      mcadsw_pkg::REG_RAW_LU: cfg[mcadsw_pkg::CFG_RAW + 1*32 +: 32] = v;
      mcadsw_pkg::REG_RAW_LV: cfg[mcadsw_pkg::CFG_RAW + 2*32 +: 32] = v;
      mcadsw_pkg::REG_RAW_RY: cfg[mcadsw_pkg::CFG_RAW + 3*32 +: 32] = v;
      mcadsw_pkg::REG_RAW_RU: cfg[mcadsw_pkg::CFG_RAW + 4*32 +: 32] = v;
      mcadsw_pkg::REG_RAW_RV: cfg[mcadsw_pkg::CFG_RAW + 5*32 +: 32] = v;
      mcadsw_pkg::REG_MESH_L: cfg[mcadsw_pkg::CFG_MESH +: 32] = v;
      mcadsw_pkg::REG_MESH_R: cfg[mcadsw_pkg::CFG_MESH + 32 +: 32] = v;
      mcadsw_pkg::REG_MESH_NODES: begin
        cfg[mcadsw_pkg::CFG_MESH_NX +: 12] = v[mcadsw_pkg::MESH_NODES_NX_LSB +: mcadsw_pkg::MESH_NODES_NX_W];
        cfg[mcadsw_pkg::CFG_MESH_NY +: 12] = v[mcadsw_pkg::MESH_NODES_NY_LSB +: mcadsw_pkg::MESH_NODES_NY_W];
      end
      mcadsw_pkg::REG_VALID_L: cfg[mcadsw_pkg::CFG_VALID_MAP +: 32] = v;
      mcadsw_pkg::REG_VALID_R: cfg[mcadsw_pkg::CFG_VALID_MAP + 32 +: 32] = v;
      default:
        if (off >= mcadsw_pkg::REG_THR0 && off < mcadsw_pkg::REG_THR0 + 4 * NTHR)
          cfg[mcadsw_pkg::CFG_THR + (off - mcadsw_pkg::REG_THR0) / 4 * DCB +: DCB] = DCB'(v);
        else begin
          $display("FAIL: register offset 'h%0h has no port in the engine", off);
          $finish;
        end
    endcase
  endtask

  initial begin
    int fd;
    longint cycles;
    int ok;
    if (!$value$plusargs("DIR=%s", dir)) begin $display("FAIL: +DIR= missing"); $finish; end
    ok = $value$plusargs("WORDS=%d", words);
    if (words <= 0 || words > MAXW) begin $display("FAIL: WORDS %0d", words); $finish; end
    $readmemh({dir, "/mem.hex"}, mem, 0, words - 1);
    repeat (4) @(posedge clk);
    #1 rst_n = 1'b1;
    fd = $fopen({dir, "/regs.txt"}, "r");
    if (fd == 0) begin $display("FAIL: no %s/regs.txt", dir); $finish; end
    while ($fscanf(fd, "%h %h\n", reg_off, reg_val) == 2) reg_write(reg_off, reg_val);
    $fclose(fd);
    if (!started) begin $display("FAIL: regs.txt has no CTRL.START"); $finish; end
    cycles = 0;
    while (!done) begin
      @(posedge clk); #1;
      cycles++;
      if (cycles > 10_000_000) begin $display("FAIL: no done after %0d cycles", cycles); $finish; end
    end
    fd = $fopen({dir, "/icarus_out.hex"}, "w");
    for (int a = base_out / 4; a < (base_out + out_stride * height) / 4; a++)
      $fwrite(fd, "%08x\n", mem[a]);
    // LR mode: the mask plane too.
    if (lr)
      for (int a = base_mask / 4; a < (base_mask + stride * height) / 4; a++)
        $fwrite(fd, "%08x\n", mem[a]);
    $fclose(fd);
    fd = $fopen({dir, "/icarus_counters.txt"}, "w");
    $fwrite(fd, "cycles %0d words_read %0d words_written %0d\n", cnt_cycles, cnt_rd, cnt_wr);
    $fclose(fd);
    $display("icarus: done after %0d cycles, error %b, %0d X checks", cnt_cycles, error, xchecks);
    $finish;
  end
endmodule
