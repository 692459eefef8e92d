// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The second simulator's files (tests/icarus/run.sh, tests/cocotb): the frame's
// memory and register writes before the run, its output planes and counters after it.
#pragma once

#include <string>

#include "engine_bench.hpp"
#include "frame_layout.hpp"
#include "memory_model.hpp"
#include "mcadsw/ref.hpp"

namespace mcadsw::sim::bench {

// Files for tests/icarus/run.sh: mem.hex ($readmemh, one 32-bit word a line,
// byte 0 in bits 7:0), regs.txt (the register writes the driver makes to
// configure and start the frame, "offset value" in hex, which the Verilog bench
// replays onto the engine's configuration ports), config.txt (plusargs: the
// memory's size), and after the run verilator_out.hex (the disparity plane's
// words, then in the LR mode the mask plane's), verilator_regions.txt (where those
// words are: "base bytes" in hex and decimal, a line a plane, in the order of
// verilator_out.hex; tests/cocotb reads it) and verilator_counters.txt.
void dump_before(const std::string& dir, MemoryModel& mem, const RawConfig& c, const WeightTable& table);
void dump_after(const std::string& dir, MemoryModel& mem, const Layout& lay, const EngineResult& r);

}  // namespace mcadsw::sim::bench
