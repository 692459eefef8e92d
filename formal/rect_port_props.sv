// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Formal environment of the rectifier's memory port (rtl/rect/mcadsw_rect_port.sv), for
// `make formal` (formal/rect_port.sby). The properties are in the block: the port's
// request held until its grant, grants only to a requesting client, at most OUTS read
// bursts in flight, and, in its `ifdef FORMAL` section, a list of the bursts in flight,
// oldest first, that every read beat's client and the tags match. Environment: the
// block's own assumptions (a presented request held by its client until granted, read
// data only while a burst is in flight); requests, payloads, grants and read beats
// otherwise free. Four bursts in flight (the rectifier's 8: the same logic, a shorter
// trace to fill them).
`default_nettype none

module rect_port_props (
  input logic        clk_i,
  input logic        rst_ni,
  input logic        wr_req_i,
  input logic [31:0] wr_addr_i,
  input logic [3:0]  wr_be_i,
  input logic [31:0] wr_data_i,
  input logic        nrd_req_i,
  input logic [31:0] nrd_addr_i,
  input logic [2:0]  nrd_len_i,
  input logic        ld_req_i,
  input logic [31:0] ld_addr_i,
  input logic [2:0]  ld_len_i,
  input logic        mem_gnt_i,
  input logic        mem_rvalid_i
);
  logic        wr_gnt, nrd_gnt, nrd_rvalid, ld_gnt, ld_rvalid;
  logic        mem_req, mem_we;
  logic [3:0]  mem_be;
  logic [31:0] mem_addr, mem_wdata;
  logic [2:0]  mem_len;
  mcadsw_rect_port #(.OUTS(4)) dut (
    .clk_i, .rst_ni,
    .wr_req_i, .wr_gnt_o(wr_gnt), .wr_addr_i, .wr_be_i, .wr_data_i,
    .nrd_req_i, .nrd_gnt_o(nrd_gnt), .nrd_addr_i, .nrd_len_i, .nrd_rvalid_o(nrd_rvalid),
    .ld_req_i, .ld_gnt_o(ld_gnt), .ld_addr_i, .ld_len_i, .ld_rvalid_o(ld_rvalid),
    .mem_req_o(mem_req), .mem_gnt_i, .mem_we_o(mem_we), .mem_be_o(mem_be), .mem_addr_o(mem_addr),
    .mem_len_o(mem_len), .mem_wdata_o(mem_wdata), .mem_rvalid_i
  );

  `include "props_reset.svh"

  // The memory grants only a request, and answers nothing in reset.
  always_comb if (!mem_req) assume (!mem_gnt_i);
  always_comb if (!rst_ni) assume (!mem_rvalid_i);
  // A write granted is a write on the port; a read granted a read of its client's length.
  always_comb if (rst_ni && mem_gnt_i) assert (mem_we == wr_gnt && (wr_gnt || mem_be == 4'b0));
  always_comb if (rst_ni && nrd_gnt) assert (mem_addr == nrd_addr_i && mem_len == nrd_len_i);
  always_comb if (rst_ni && ld_gnt) assert (mem_addr == ld_addr_i && mem_len == ld_len_i);
  always_comb if (rst_ni && wr_gnt) assert (mem_addr == wr_addr_i && mem_wdata == wr_data_i && mem_be == wr_be_i);
  // One client granted at a time, and a beat to one client.
  always_comb if (rst_ni) assert (32'(wr_gnt) + 32'(nrd_gnt) + 32'(ld_gnt) == 32'(mem_gnt_i));
  always_comb if (rst_ni) assert (32'(nrd_rvalid) + 32'(ld_rvalid) == 32'(mem_rvalid_i));

  logic unused;
  assign unused = ^{past_ok};
endmodule

`default_nettype wire
