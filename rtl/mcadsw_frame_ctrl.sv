// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Frame controller of the engine: takes a start, has the registered
// configuration checked, runs the passes of the frame's mode one after the
// other, and owns busy, done, the error code and the frame's counters
// (docs/blocks/engine.md 3, frame controller, and docs/blocks/rectifier.md; docs/memory_map.md, status).
//
//   StIdle ── start ──> StSettle ──> StCheck ──(error)──────────────────> StIdle, done + error
//                                  (waits for the check: chk_done_i)
//                          │ ok, rectification (RECT_CTRL.ENABLE):
//                          │   StRectCheck (codes 16..21) -> StRect (the rectify pass;
//                          │   codes 22, 23) -> StRectDrain (its writes answered) ──┐
//                          │ ok: the left view as base   the right view as base (mode bit 2)
//                          v                                   v
//                     StLeftPass ──(LR mode)──> StRightPass <──┘
//                          │ (else)               │ (LR mode: post stage next) (else)
//                          │                      v                             │
//                          │           StDrain (writes in flight) -> StPost     │
//                          v                                          v         v
//                        StDone: every write answered (wr_idle_i) -> StIdle, done
//
// With rectification, the mark step (StMarkWait: the writes before it answered;
// StMark) runs in phases (mark_phase_o): without LR, after the pass, phase 2 (the
// invalid code into the output at the base view's invalid pixels); in the LR mode,
// after the right pass, phase 0 (255 into dR at the right view's invalid pixels) and
// phase 1 (a flag into dL at the left view's), then the post stage, then phase 2.
//
// A pass starts the block scheduler in its first cycle (sched_start_o) and ends
// with the scheduler's done. In the LR mode the left map (pass 1, the left view
// as base, written to dL) is followed by the right map (pass 2, the right view as
// base, dR); the post stage reads both back, so it starts only once every write
// of the passes is answered (StDrain). A frame is done once every one of its
// writes is answered. The pass (pass_second_o, pass_post_o) holds until the next
// start: the post stage keeps the memory port until then. The rectify pass and the
// mark step own the memory port in their states (rect_sel_o, mark_sel_o).
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_frame_ctrl (
  input  logic        clk_i,
  input  logic        rst_ni,
  // Host
  input  logic        start_i,              // ignored while busy_o
  // Configuration registered at the start (accept_o) and its check
  input  logic        cfg_lr_i,             // LR mode: left map, right map, post stage
  input  logic        cfg_right_i,          // the right view as base
  input  logic        cfg_rect_i,           // rectify the raw planes first
  input  logic [mcadsw_pkg::ERR_BITS-1:0] err_i,   // valid in StCheck (the check's result registered:
                                            // the configuration settles through it in StSettle)
  input  logic        ok_i,                 // err_i == ErrNone (the check's flat verdict)
  input  logic        chk_done_i,           // err_i and ok_i decided (StCheck waits for it)
  output logic        accept_o,             // register the configuration now
  // Rectification: the check of its registers, the rectify pass, the mark step
  output logic        rchk_start_o,         // one cycle
  input  logic        rchk_done_i,          // one cycle, with rchk_err_i
  input  logic [2:0]  rchk_err_i,           // 0, or code 15 + rchk_err_i
  output logic        rect_start_o,         // one cycle
  input  logic        rect_done_i,          // one cycle, with rect_err_i
  input  logic [1:0]  rect_err_i,           // 0, or code 21 + rect_err_i
  output logic        rect_sel_o,           // the rectify pass owns the memory port
  output logic        mark_start_o,         // one cycle
  input  logic        mark_done_i,          // one cycle
  output logic        mark_sel_o,           // the mark step owns the memory port
  output logic [1:0]  mark_phase_o,         // 0 dR, 1 dL (LR, before the post stage), 2 the output
  // Passes and post stage
  output logic        sched_start_o,        // a pass starts (one cycle)
  input  logic        sched_busy_i,
  input  logic        sched_done_i,         // the pass's last block row is out (one cycle)
  output logic        to_second_o,          // the LR mode's second pass begins with the next cycle
  output logic        pass_second_o,        // the LR mode's second pass (right map), or later
  output logic        pass_post_o,          // the LR mode's post stage owns the memory port
  output logic        post_start_o,         // one cycle
  input  logic        post_done_i,          // one cycle
  // No write requested, buffered or unanswered in the memory system
  input  logic        wr_idle_i,
  // The engine's memory port, for the counters
  input  logic        mem_req_i,
  input  logic        mem_gnt_i,
  input  logic        mem_we_i,
  input  logic [3:0]  mem_len_i,            // read burst: beats - 1
  // Status
  output logic        busy_o,
  output logic        done_o,               // frame finished or rejected since the start
  output logic        error_o,              // configuration rejected; nothing was written
  output logic [mcadsw_pkg::ERR_BITS-1:0] error_code_o,
  output logic [31:0] cnt_cycles_o,
  output logic [31:0] cnt_words_read_o,
  output logic [31:0] cnt_words_written_o,
  output logic [31:0] cnt_stall_o           // cycles with a request and no grant
);

  typedef enum logic [3:0] {
    StIdle, StCheck, StLeftPass, StRightPass, StDrain, StPost, StDone,
    StRectCheck, StRect, StRectDrain, StMarkWait, StMark, StSettle
  } state_e;
  // The pass whose planes the engine uses (held after the frame until the next start).
  typedef enum logic [1:0] { PassFirst, PassSecond, PassPost } pass_e;

  state_e state_q, state_d;
  pass_e  pass_q, pass_d;
  logic   done_q, done_d, error_q, error_d;
  logic [1:0] mphase_q, mphase_d;
  logic [mcadsw_pkg::ERR_BITS-1:0] code_q, code_d;
  logic   sched_start_q, post_start_q, rchk_start_q, rect_start_q, mark_start_q;

  assign accept_o = state_q == StIdle && start_i;

  // The frame's end: done once every write is answered. (Icarus 11 wants an
  // explicit cast for an enum from ?:, hence the if / else here and below.)
  function automatic state_e frame_end(input logic idle);
    if (idle) frame_end = StIdle;
    else frame_end = StDone;
  endfunction
  // A pass's end without LR, the post stage's end: the mark step first with rectification.
  function automatic state_e pass_end(input logic rect, input logic idle);
    if (rect) pass_end = StMarkWait;
    else pass_end = frame_end(idle);
  endfunction
  // The LR mode's right pass's end: the post stage once every write is answered,
  // with rectification the marks into dR and dL first.
  function automatic state_e lr_end(input logic rect, input logic idle);
    if (rect) lr_end = StMarkWait;
    else if (idle) lr_end = StPost;
    else lr_end = StDrain;
  endfunction
  function automatic state_e first_pass(input logic right);
    if (right) first_pass = StRightPass;
    else first_pass = StLeftPass;
  endfunction

  always_comb begin
    state_d = state_q;
    pass_d  = pass_q;
    done_d  = done_q;
    error_d = error_q;
    code_d  = code_q;
    mphase_d = mphase_q;
    case (state_q)
      StIdle: if (start_i) begin
        state_d = StSettle;
        pass_d  = PassFirst;
        done_d  = 1'b0;
        error_d = 1'b0;
        code_d  = mcadsw_pkg::ErrNone;
      end
      StSettle: state_d = StCheck;                  // the check's result registered at its end
      StCheck: if (chk_done_i) begin
        code_d = err_i;
        if (!ok_i) begin
          state_d = StIdle;
          done_d  = 1'b1;
          error_d = 1'b1;
        end else if (cfg_rect_i) begin
          state_d = StRectCheck;
        end else begin
          state_d = first_pass(cfg_right_i);
        end
      end
      StRectCheck: if (rchk_done_i) begin
        if (rchk_err_i != 3'd0) begin
          state_d = StIdle;
          error_d = 1'b1;
          code_d  = mcadsw_pkg::ERR_BITS'(32'(mcadsw_pkg::ErrRectStep) - 1 + 32'(rchk_err_i));
        end else state_d = StRect;
      end
      StRect: if (rect_done_i) begin
        if (rect_err_i != 2'd0) begin
          state_d = StIdle;
          error_d = 1'b1;
          code_d  = mcadsw_pkg::ERR_BITS'(32'(mcadsw_pkg::ErrMeshRange) - 1 + 32'(rect_err_i));
        end else state_d = StRectDrain;
      end
      StRectDrain: if (wr_idle_i) state_d = first_pass(cfg_right_i);
      StLeftPass: if (sched_done_i) begin
        if (cfg_lr_i) begin
          state_d = StRightPass;
          pass_d  = PassSecond;
        end else begin
          state_d  = pass_end(cfg_rect_i, wr_idle_i);
          mphase_d = 2'd2;
        end
      end
      StRightPass: if (sched_done_i) begin
        if (cfg_lr_i) begin
          state_d  = lr_end(cfg_rect_i, wr_idle_i);
          pass_d   = PassPost;
          mphase_d = 2'd0;
        end else begin
          state_d  = pass_end(cfg_rect_i, wr_idle_i);
          mphase_d = 2'd2;
        end
      end
      StDrain: if (wr_idle_i) state_d = StPost;
      StMarkWait: if (wr_idle_i) state_d = StMark;
      StMark: if (mark_done_i) begin
        if (mphase_q == 2'd0) begin
          state_d  = StMarkWait;
          mphase_d = 2'd1;
        end else if (mphase_q == 2'd1) begin
          state_d  = StDrain;
          mphase_d = 2'd2;
        end else begin
          state_d  = frame_end(wr_idle_i);
        end
      end
      StPost: if (post_done_i) state_d = pass_end(cfg_rect_i, wr_idle_i);
      StDone: if (wr_idle_i) state_d = StIdle;
      default: state_d = StIdle;
    endcase
    if (state_q != StIdle && state_q != StCheck && state_d == StIdle) done_d = 1'b1;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q       <= StIdle;
      pass_q        <= PassFirst;
      done_q        <= 1'b0;
      error_q       <= 1'b0;
      code_q        <= mcadsw_pkg::ErrNone;
      mphase_q      <= 2'd2;
      sched_start_q <= 1'b0;
      post_start_q  <= 1'b0;
      rchk_start_q  <= 1'b0;
      rect_start_q  <= 1'b0;
      mark_start_q  <= 1'b0;
    end else begin
      state_q       <= state_d;
      pass_q        <= pass_d;
      done_q        <= done_d;
      error_q       <= error_d;
      code_q        <= code_d;
      mphase_q      <= mphase_d;
      sched_start_q <= (state_d == StLeftPass || state_d == StRightPass) && state_d != state_q;
      post_start_q  <= state_d == StPost && state_q != StPost;
      rchk_start_q  <= state_d == StRectCheck && state_q != StRectCheck;
      rect_start_q  <= state_d == StRect && state_q != StRect;
      mark_start_q  <= state_d == StMark && state_q != StMark;
    end
  end

  assign sched_start_o = sched_start_q;
  assign post_start_o  = post_start_q;
  assign rchk_start_o  = rchk_start_q;
  assign rect_start_o  = rect_start_q;
  assign mark_start_o  = mark_start_q;
  assign rect_sel_o    = state_q == StRect;
  assign mark_sel_o    = state_q == StMark;
  assign mark_phase_o  = mphase_q;
  assign to_second_o   = pass_d == PassSecond && pass_q != PassSecond;
  assign pass_second_o = pass_q == PassSecond;
  assign pass_post_o   = pass_q == PassPost;
  assign busy_o        = state_q != StIdle;
  assign done_o        = done_q;
  assign error_o       = error_q;
  assign error_code_o  = code_q;

  // ---- Counters: from the start; cycles while the scheduler runs, in the LR
  // mode from its first pass to the post stage's end, with rectification from its
  // check to the mark step's end, and while the last writes are answered.
  logic count;
  assign count = sched_busy_i || state_q == StDone ||
                 (cfg_lr_i && state_q != StIdle && state_q != StSettle && state_q != StCheck) ||
                 state_q == StRectCheck || state_q == StRect || state_q == StRectDrain ||
                 state_q == StMarkWait || state_q == StMark;
  logic [31:0] cycles_d, rd_d, wr_d, stall_d;
  always_comb begin
    cycles_d = cnt_cycles_o;
    rd_d     = cnt_words_read_o;
    wr_d     = cnt_words_written_o;
    stall_d  = cnt_stall_o;
    if (accept_o) begin
      cycles_d = '0;
      rd_d     = '0;
      wr_d     = '0;
      stall_d  = '0;
    end else if (count) begin
      cycles_d = cnt_cycles_o + 32'd1;
      // A granted read is a burst of mem_len_i + 1 words.
      if (mem_req_i && mem_gnt_i && !mem_we_i) rd_d = cnt_words_read_o + 32'(mem_len_i) + 32'd1;
      wr_d    = cnt_words_written_o + 32'(mem_req_i && mem_gnt_i && mem_we_i);
      stall_d = cnt_stall_o + 32'(mem_req_i && !mem_gnt_i);
    end
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cnt_cycles_o        <= '0;
      cnt_words_read_o    <= '0;
      cnt_words_written_o <= '0;
      cnt_stall_o         <= '0;
    end else begin
      cnt_cycles_o        <= cycles_d;
      cnt_words_read_o    <= rd_d;
      cnt_words_written_o <= wr_d;
      cnt_stall_o         <= stall_d;
    end
  end

  // ---- What the controller expects of the engine, and what it keeps ----------------------
  // The scheduler runs and finishes only in a pass, the post stage only in StPost.
  `MCADSW_ASSUME(SchedOnlyInAPass, !(sched_busy_i || sched_done_i) ||
                                   state_q == StLeftPass || state_q == StRightPass)
  `MCADSW_ASSUME(PostDoneOnlyInPost, !post_done_i || state_q == StPost)
  `MCADSW_ASSUME(RectCheckDoneOnlyInItsState, !rchk_done_i || state_q == StRectCheck)
  `MCADSW_ASSUME(RectDoneOnlyInItsState, !rect_done_i || state_q == StRect)
  `MCADSW_ASSUME(MarkDoneOnlyInItsState, !mark_done_i || state_q == StMark)
  // Done and a rejected start are reported only between frames, with a code
  // exactly when there is an error.
  `MCADSW_ASSERT(DoneOnlyWhenIdle, !done_o || !busy_o)
  `MCADSW_ASSERT(ErrorOnlyWithDone, !error_o || done_o)
  `MCADSW_ASSUME(OkIffNoCode, state_q != StCheck || !chk_done_i || ok_i == (err_i == mcadsw_pkg::ErrNone))
  `MCADSW_ASSERT(CodeIffError, error_o == (error_code_o != mcadsw_pkg::ErrNone))
  // The scheduler starts in the first cycle of a pass; the post stage in its own state.
  `MCADSW_ASSERT(SchedStartInAPass, !sched_start_o || state_q == StLeftPass ||
                                    state_q == StRightPass)
  `MCADSW_ASSERT(PostStartInPost, !post_start_o || (state_q == StPost && pass_post_o))
  // The rectifier's blocks start in their states, and only with rectification.
  `MCADSW_ASSERT(RectStartsInItsStates, !(rchk_start_o || rect_start_o || mark_start_o) ||
                                        (cfg_rect_i && (state_q == StRectCheck || state_q == StRect ||
                                                        state_q == StMark)))
  // A gated block is started, and owns the port, only while its clock runs: the rectifier's
  // in a rectified frame outside the passes, the post stage's in the LR mode (the engine's
  // clock enables, mcadsw_clock_gate). Between frames the port stays with the post stage
  // after an LR frame, whose configuration (and so its clock) stays until the next start.
  `MCADSW_ASSERT(RectifierOnlyWithItsClock, !(rchk_start_o || rect_start_o || mark_start_o ||
                                              rect_sel_o || mark_sel_o) || (cfg_rect_i && !sched_busy_i))
  `MCADSW_ASSERT(PostOnlyWithItsClock, !(post_start_o || pass_post_o) || cfg_lr_i || !busy_o)
  // The marks into dR and dL only in the LR mode, before its post stage.
  `MCADSW_ASSERT(LrMarksOnlyInLr, !(mark_sel_o && mphase_q != 2'd2) || (cfg_lr_i && pass_post_o))
  // The LR mode alone has a second pass and a post stage.
  `MCADSW_ASSERT(SecondPassOnlyInLr, !(pass_second_o || pass_post_o) || cfg_lr_i || !busy_o)
  // The counters run only within a frame.
  `MCADSW_ASSERT(CountOnlyWhenBusy, !count || busy_o)

  // The controller's state (each holds in every reachable state; also what a proof by
  // induction needs): no code while a frame runs (a start clears it, it is set only
  // with the return to idle); the rectification's states only for a frame that
  // rectifies.
  `MCADSW_ASSERT(NoCodeWhileBusy, !busy_o || code_q == mcadsw_pkg::ErrNone)
  `MCADSW_ASSERT(RectStatesOnlyWithRect, cfg_rect_i || !(state_q == StRectCheck || state_q == StRect ||
                                                        state_q == StRectDrain || state_q == StMarkWait ||
                                                        state_q == StMark))
  // The LR mode's post stage and its drain come after its passes (and marks), the
  // marks into dR and dL only in the LR mode, between its passes and the post stage.
  `MCADSW_ASSERT(PostStatesAfterLrPasses, !(state_q == StPost || state_q == StDrain) ||
                                          (cfg_lr_i && pass_q == PassPost &&
                                           mphase_q == (cfg_rect_i ? 2'd2 : 2'd0)))
  `MCADSW_ASSERT(LrMarkPhasesInLr, !((state_q == StMark || state_q == StMarkWait) && mphase_q != 2'd2) ||
                                   (cfg_lr_i && pass_q == PassPost))
  `MCADSW_ASSERT(NoMarkPhase3, mphase_q != 2'd3)
  `MCADSW_ASSERT(FirstPassBeforeThePasses, pass_q == PassFirst ||
                                           !(state_q == StSettle || state_q == StCheck ||
                                             state_q == StRectCheck || state_q == StRect ||
                                             state_q == StRectDrain || state_q == StLeftPass))

  // Events the block's proof must reach (formal only): a frame done, a start
  // rejected, the LR mode's post stage, a rectified frame's mark step.
  `MCADSW_COVER(FrameDone, done_o && !error_o)
  `MCADSW_COVER(StartRejected, error_o)
  `MCADSW_COVER(PostStage, post_start_o)
  `MCADSW_COVER(MarkStep, mark_start_o)

endmodule

`default_nettype wire
