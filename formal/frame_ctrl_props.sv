// `make formal` of the frame controller (rtl/mcadsw_frame_ctrl.sv): its own
// assertions (`MCADSW_ASSERT in the block: done and errors only between frames,
// a code exactly with an error, the scheduler and post stage started in their
// states, the second pass and post stage only in the LR mode, counters only
// within a frame) for every input sequence the block's `MCADSW_ASSUMEs allow
// (the scheduler runs and finishes only in a pass, the post stage only in its
// state) and the engine gives: the configuration's mode is registered at the
// start, so it changes only while the controller is idle.
`default_nettype none

module frame_ctrl_props (
  input logic        clk_i,
  input logic        rst_ni,
  input logic        start_i,
  input logic        cfg_lr_i,
  input logic        cfg_right_i,
  input logic [3:0]  err_i,
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
  logic [3:0]  code;
  logic [31:0] cycles, rd, wr, stall;

  mcadsw_frame_ctrl dut (
    .clk_i, .rst_ni, .start_i, .cfg_lr_i, .cfg_right_i, .err_i, .ok_i (err_i == 4'd0), .accept_o (accept),
    .sched_start_o (sched_start), .sched_busy_i, .sched_done_i, .to_second_o (to_second),
    .pass_second_o (pass_second),
    .pass_post_o (pass_post), .post_start_o (post_start), .post_done_i, .wr_idle_i,
    .mem_req_i, .mem_gnt_i, .mem_we_i, .mem_len_i,
    .busy_o (busy), .done_o (done), .error_o (error), .error_code_o (code),
    .cnt_cycles_o (cycles), .cnt_words_read_o (rd), .cnt_words_written_o (wr),
    .cnt_stall_o (stall)
  );

`include "props_reset.svh"

  // The engine registers the mode at the start: it changes only while idle.
  always @(posedge clk_i) if (past_ok && rst_ni && $past(busy)) begin
    assume (cfg_lr_i == $past(cfg_lr_i));
    assume (cfg_right_i == $past(cfg_right_i));
  end

  logic unused;
  assign unused = ^{accept, sched_start, to_second, pass_second, pass_post, post_start, busy, done, error, code,
                    cycles, rd, wr, stall};
endmodule

`default_nettype wire
