// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// `make formal` of the frame controller (rtl/mcadsw_frame_ctrl.sv): its own
// assertions (`MCADSW_ASSERT in the block: done and errors only between frames,
// a code exactly with an error, the scheduler and post stage started in their
// states, the rectifier's blocks started in theirs and only with rectification,
// the second pass and post stage only in the LR mode, counters only within a
// frame, the marks into dR and dL only in the LR mode) and those below (the
// rectification's states, mark phases and codes) for every input sequence the
// block's `MCADSW_ASSUMEs allow (the scheduler runs and finishes only in a pass,
// the post stage, the rectification check, the rectify pass and the mark step
// finish only in their states) and the engine gives: the configuration (mode,
// rectification) is registered at the start, so it changes only while the
// controller is idle; the configuration check (mcadsw_cfg_check) reports codes
// 0 .. 12, the rectification check (mcadsw_rect_check) 0 .. 6, the rectify pass
// (mcadsw_rect) 0 .. 2.
`default_nettype none

module frame_ctrl_props (
  input logic        clk_i,
  input logic        rst_ni,
  input logic        start_i,
  input logic        cfg_lr_i,
  input logic        cfg_right_i,
  input logic        cfg_rect_i,
  input logic [mcadsw_pkg::ERR_BITS-1:0] err_i,
  input logic        chk_done_i,         // free: the check may take any number of cycles
  input logic        rchk_done_i,
  input logic [2:0]  rchk_err_i,
  input logic        rect_done_i,
  input logic [1:0]  rect_err_i,
  input logic        mark_done_i,
  input logic        sched_busy_i,
  input logic        sched_done_i,
  input logic        post_done_i,
  input logic        wr_idle_i,
  input logic        mem_req_i,
  input logic        mem_gnt_i,
  input logic        mem_we_i,
  input logic [3:0]  mem_len_i
);
  logic        accept, sched_start, to_second, pass_second, pass_post, post_start, busy, done, error;
  logic        rchk_start, rect_start, rect_sel, mark_start, mark_sel;
  logic [1:0]  mark_phase;
  logic [mcadsw_pkg::ERR_BITS-1:0] code;
  logic [31:0] cycles, rd, wr, stall;

  mcadsw_frame_ctrl dut (
    .clk_i, .rst_ni, .start_i, .cfg_lr_i, .cfg_right_i, .cfg_rect_i, .err_i,
    .ok_i (err_i == mcadsw_pkg::ErrNone), .chk_done_i, .accept_o (accept),
    .rchk_start_o (rchk_start), .rchk_done_i, .rchk_err_i,
    .rect_start_o (rect_start), .rect_done_i, .rect_err_i, .rect_sel_o (rect_sel),
    .mark_start_o (mark_start), .mark_done_i, .mark_sel_o (mark_sel), .mark_phase_o (mark_phase),
    .sched_start_o (sched_start), .sched_busy_i, .sched_done_i, .to_second_o (to_second),
    .pass_second_o (pass_second),
    .pass_post_o (pass_post), .post_start_o (post_start), .post_done_i, .wr_idle_i,
    .mem_req_i, .mem_gnt_i, .mem_we_i, .mem_len_i,
    .busy_o (busy), .done_o (done), .error_o (error), .error_code_o (code),
    .cnt_cycles_o (cycles), .cnt_words_read_o (rd), .cnt_words_written_o (wr),
    .cnt_stall_o (stall)
  );

`include "props_reset.svh"

  // The engine registers the configuration at the start: it changes only while idle.
  always @(posedge clk_i) if (past_ok && rst_ni && $past(busy)) begin
    assume (cfg_lr_i == $past(cfg_lr_i));
    assume (cfg_right_i == $past(cfg_right_i));
    assume (cfg_rect_i == $past(cfg_rect_i));
  end
  // The checks' and the rectify pass's codes: the configuration check (mcadsw_cfg_check)
  // ErrNone, ErrWidth .. ErrLrColour; the rectification check 0 .. 6 (codes 16 .. 21);
  // the rectify pass 0 .. 2 (codes 22, 23: one flag of two).
  always @(posedge clk_i) if (rst_ni) begin
    assume (err_i <= mcadsw_pkg::ErrLrColour);
    assume (rchk_err_i <= 3'd6);
    assume (rect_err_i != 2'd3);
  end

  // The frame's rectification, as the last busy cycle had it (held while busy, above).
  logic frame_rect_q;
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) frame_rect_q <= 1'b0;
    else if (busy) frame_rect_q <= cfg_rect_i;
  // The frame's mark steps into dR and dL (phases 0, 1) finished so far, its post
  // stage, its mark step into the output (phase 2).
  logic [1:0] lr_marks_q;
  logic       post_seen_q, out_marked_q;
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) begin
      lr_marks_q   <= 2'd0;
      post_seen_q  <= 1'b0;
      out_marked_q <= 1'b0;
    end else if (accept) begin
      lr_marks_q   <= 2'd0;
      post_seen_q  <= 1'b0;
      out_marked_q <= 1'b0;
    end else begin
      if (mark_sel && mark_done_i && mark_phase != 2'd2 && lr_marks_q != 2'd3) lr_marks_q <= lr_marks_q + 2'd1;
      if (mark_sel && mark_done_i && mark_phase == 2'd2) out_marked_q <= 1'b1;
      if (post_done_i) post_seen_q <= 1'b1;
    end

  always @(posedge clk_i) if (rst_ni) begin
    // The rectify pass and the mark step never own the memory port together, nor
    // outside a frame.
    assert (!(rect_sel && mark_sel));
    assert (!(rect_sel || mark_sel) || busy);
    // Without rectification the frame never enters its states: no rectifier block
    // starts, none owns the memory port.
    assert (cfg_rect_i || !(rchk_start || rect_start || mark_start || rect_sel || mark_sel));
    // A start of a rectifier block comes with its state (the memory port for the
    // rectify pass and the mark step).
    assert (!rect_start || rect_sel);
    assert (!mark_start || mark_sel);
    // The rectification's codes (16 .. 23) only for a frame with rectification, and
    // no code beyond them.
    assert (code < mcadsw_pkg::ErrRectStep || frame_rect_q);
    assert (code <= mcadsw_pkg::ErrRectFootprint);
    // The mark step's phases: 0 (dR), then 1 (dL), then the post stage, in the LR
    // mode; 2 (the output) last; no phase 3.
    assert (!mark_sel || mark_phase != 2'd3);
    assert (!(mark_sel && mark_phase == 2'd0) || lr_marks_q == 2'd0);
    assert (!(mark_sel && mark_phase == 2'd1) || lr_marks_q == 2'd1);
    assert (!(post_start && cfg_rect_i) || lr_marks_q == 2'd2);
    assert (!(mark_sel && mark_phase == 2'd2 && cfg_lr_i) || (lr_marks_q == 2'd2 && post_seen_q));
    assert (!(mark_sel && mark_phase == 2'd2 && !cfg_lr_i) || lr_marks_q == 2'd0);
    assert (!out_marked_q || !mark_sel);
    // A frame with rectification that ends without an error has marked its output.
    assert (!(done && !error && frame_rect_q) || out_marked_q);
  end

  // Each owns the memory port from its start to its done, no longer; the starts
  // are one-cycle pulses.
  always @(posedge clk_i) if (past_ok && rst_ni) begin
    assert (!(rchk_start && $past(rchk_start)));
    assert (!(rect_start && $past(rect_start)));
    assert (!(mark_start && $past(mark_start)));
    assert (!(rect_sel && !$past(rect_sel)) || rect_start);
    assert (!(mark_sel && !$past(mark_sel)) || mark_start);
    assert (!($past(rect_done_i) && $past(rect_sel)) || !rect_sel);
    assert (!($past(mark_done_i) && $past(mark_sel)) || !mark_sel);
  end

  logic unused;
  assign unused = ^{accept, sched_start, to_second, pass_second, pass_post, post_start, busy, done, error, code,
                    cycles, rd, wr, stall, mark_phase};
endmodule

`default_nettype wire
