// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The rectifier's files (docs/blocks/rectifier.md), a list no build or test reads (the block benches
// name their sources in tests/rtl/CMakeLists.txt; the engine reads them through rtl/mcadsw.f). Relative to
// rtl/rect/, its package first; the engine's package (rtl/mcadsw_pkg.sv) is read before it.
mcadsw_rect_pkg.sv
mcadsw_rect_load.sv
mcadsw_rect_nodes.sv
mcadsw_rect_sample.sv
mcadsw_rect_write.sv
mcadsw_rect_port.sv
mcadsw_rect_mark.sv
mcadsw_rect_check.sv
mcadsw_rect.sv
mcadsw_rectifier.sv
