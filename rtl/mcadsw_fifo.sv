// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// A small first-in first-out queue in flip-flops: up to two entries pushed in a
// cycle (the second after the first), one popped, the head readable without a
// pop (first-word fall-through). Used by the post stage for its dL word queue
// (one push a cycle) and its write queue (a mask word and an output word may
// arrive in the same cycle).
//
// The entries are one packed vector, so that synthesis keeps them as registers
// (an unpacked array would be inferred as a memory with an asynchronous read).
// Only the pointers and the count are reset: an entry is read only after it has
// been written. Overflow and underflow are the user's to prevent (count_o says
// how many entries are held); the assertions below stop a simulation that
// breaks them.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_fifo #(
  parameter int W     = 32,                 // bits of an entry
  parameter int DEPTH = 4                   // entries, a power of 2 (>= 2)
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               push_i,        // data_i enters the queue
  input  logic [W-1:0]       data_i,
  input  logic               push2_i,       // data2_i enters too, after data_i (or alone)
  input  logic [W-1:0]       data2_i,
  input  logic               pop_i,         // the head leaves (count_o != 0)
  output logic [W-1:0]       head_o,        // the oldest entry (valid while count_o != 0)
  output logic [$clog2(DEPTH):0] count_o
);

  localparam int PI = $clog2(DEPTH);       // pointer bits

  if (DEPTH < 2 || (1 << PI) != DEPTH) begin : g_bad_param
    mcadsw_error_fifo_depth_not_a_power_of_2 u_error ();
  end

  logic [DEPTH*W-1:0] entries_q;
  logic [PI-1:0]      wr_q, rd_q, wr2;     // next entry written, the head; data2_i's entry
  logic [PI:0]        count_q;

  assign wr2 = wr_q + PI'(push_i);

  // Writes decoded entry by entry (docs/architecture.md 1.3: a part-select at the
  // pointer is a shifter of all DEPTH x W bits; at W = 68, DEPTH = 4 synth_ecp5 made
  // 3 293 LUT4 of it, 832 decoded): each entry's enable and its choice of data_i or
  // data2_i (when both push, wr2 != wr_q).
  logic [DEPTH-1:0] en, second;
  always_comb begin
    for (int e = 0; e < DEPTH; e++) begin
      second[e] = !(push_i && wr_q == PI'(e));
      en[e]     = !second[e] || (push2_i && wr2 == PI'(e));
    end
  end
  always_ff @(posedge clk_i) begin
    for (int e = 0; e < DEPTH; e++)
      if (en[e]) entries_q[e*W +: W] <= second[e] ? data2_i : data_i;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wr_q    <= '0;
      rd_q    <= '0;
      count_q <= '0;
    end else begin
      wr_q    <= wr_q + PI'(push_i) + PI'(push2_i);
      if (pop_i) rd_q <= rd_q + 1'b1;
      count_q <= count_q + (PI + 1)'(push_i) + (PI + 1)'(push2_i) - (PI + 1)'(pop_i);
    end
  end

  assign head_o  = entries_q[rd_q*W +: W];
  assign count_o = count_q;

  `MCADSW_ASSUME(NoOverflow, 32'(count_q) + 32'(push_i) + 32'(push2_i) <= DEPTH + 32'(pop_i))
  `MCADSW_ASSUME(NoPopWhenEmpty, !(pop_i && count_q == '0))
  `MCADSW_ASSERT(CountWithinDepth, 32'(count_q) <= DEPTH)
  `MCADSW_ASSERT(CountIsPointerDistance, PI'(wr_q - rd_q) == PI'(count_q))

`ifdef FORMAL
  // The queue as a list of the entries pushed and not yet popped, oldest first, and the
  // block against it: every held entry, at its place from the head, and so the head
  // (make formal, formal/fifo.sby: with these the proof closes by induction).
  logic [DEPTH*W-1:0] f_list_q;
  always_ff @(posedge clk_i) begin : f_list
    logic [DEPTH*W-1:0] l;
    logic [PI:0]        n;
    l = f_list_q;
    n = count_q;
    if (pop_i) begin
      l = l >> W;
      n = n - 1'b1;
    end
    if (push_i) begin
      l[32'(n)*W +: W] = data_i;
      n = n + 1'b1;
    end
    if (push2_i) l[32'(n)*W +: W] = data2_i;
    f_list_q <= l;
  end
  for (genvar i = 0; i < DEPTH; i++) begin : g_f_held
    `MCADSW_ASSERT(HeldInOrder, 32'(count_q) <= i ||
                                entries_q[32'(PI'(rd_q + PI'(i)))*W +: W] == f_list_q[i*W +: W])
  end
  `MCADSW_ASSERT(HeadIsOldest, count_q == '0 || head_o == f_list_q[W-1:0])
`endif

  // Events the block's proof must reach (formal only): the queue full, two entries pushed
  // in a cycle, a push and a pop in the same cycle of a full queue, the head pointer
  // wrapping around.
  `MCADSW_COVER(Full, 32'(count_q) == DEPTH)
  `MCADSW_COVER(TwoPushes, push_i && push2_i)
  `MCADSW_COVER(PushPopWhenFull, 32'(count_q) == DEPTH && push_i && pop_i)
  `MCADSW_COVER(HeadWraps, pop_i && rd_q == PI'(DEPTH - 1))

endmodule

`default_nettype wire
