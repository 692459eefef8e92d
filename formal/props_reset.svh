// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Shared by the formal/*_props.sv wrappers: reset in the first cycle of every
// trace (init), free afterwards; past_ok: the previous cycle was out of reset,
// so $past values are of a running block.
logic init = 1'b1;
always_ff @(posedge clk_i) init <= 1'b0;
always_comb if (init) assume (!rst_ni);
logic past_ok = 1'b0;
always_ff @(posedge clk_i) past_ok <= rst_ni;
