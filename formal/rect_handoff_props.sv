// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Formal environment of the rectifier pass's tile handoff (rtl/rect/mcadsw_rect.sv), for
// `make formal` (formal/rect_handoff.sby). The properties are in the block's
// `ifdef MCADSW_CHECKS` section (live in simulation too): the producer loads a job only
// into an empty tile buffer, the consumer samples only a full one, the jobs are sampled in
// the order they were loaded (a list of the jobs in the buffers), and the consumer copies
// the nodes of the tile it samples. The proof cuts the submodules out (formal/
// rect_handoff.sby: their outputs free in every cycle), so it holds whenever and in
// whatever order the node front end, the node reader, the sampler, the writer and the port
// finish; the loader's busy and done keep its protocol (the block's MCADSW_ASSUME). The
// configuration is any constant of the trace (a frame's registers are held while the pass
// runs); a start only while idle.
`default_nettype none

module rect_handoff_props (
  input logic        clk_i,
  input logic        rst_ni,
  input logic        start_i,
  input logic        mem_gnt_i,
  input logic        mem_rvalid_i,
  input logic [31:0] mem_rdata_i
);
  (* anyconst *) logic [2:0]  step_log2;
  (* anyconst *) logic [11:0] width, height, raw_w, raw_h;
  (* anyconst *) logic        tiled;
  (* anyconst *) logic [31:0] raw_stride, stride;
  (* anyconst *) logic [5:0]  planes;
  logic        busy, done, mem_req, mem_we;
  logic [1:0]  err;
  logic [3:0]  mem_be;
  logic [31:0] mem_addr, mem_wdata;
  logic [2:0]  mem_len;
  mcadsw_rect dut (
    .clk_i, .rst_ni, .start_i, .step_log2_i(step_log2), .width_i(width), .height_i(height),
    .raw_w_i(raw_w), .raw_h_i(raw_h), .tiled_i(tiled), .raw_stride_i(raw_stride), .stride_i(stride),
    .raw_base_i('0), .base_i('0), .planes_i(planes), .mesh_base_i('0), .valid_base_i('0),
    .busy_o(busy), .done_o(done), .err_o(err),
    .mem_req_o(mem_req), .mem_gnt_i, .mem_we_o(mem_we), .mem_be_o(mem_be), .mem_addr_o(mem_addr),
    .mem_len_o(mem_len), .mem_wdata_o(mem_wdata), .mem_rvalid_i, .mem_rdata_i
  );

  `include "props_reset.svh"

  always_comb if (busy) assume (!start_i);

  logic unused;
  assign unused = ^{past_ok, done, err, mem_req, mem_we, mem_be, mem_addr, mem_wdata, mem_len};
endmodule

`default_nettype wire
