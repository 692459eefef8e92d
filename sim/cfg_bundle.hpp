// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The engine's configuration bundle as a Verilator port (mcadsw_regs's cfg_o,
// mcadsw_engine's cfg_i): its fields from the table they are generated from
// (sw_ref/include/mcadsw/regs.hpp kCfgFields, the package's CFG_*), each at most
// 64 bits wide.
#pragma once

#include "mcadsw/regs.hpp"
#include "vbits.hpp"

namespace mcadsw::sim {

template <typename Port>
inline uint64_t get_cfg(const Port& cfg, regs::Cfg f) {
  return get_bits(cfg, regs::cfg_lsb(f), regs::cfg_width(f));
}

template <typename Port>
inline void set_cfg(Port& cfg, regs::Cfg f, uint64_t value) {
  set_bits(cfg, regs::cfg_lsb(f), regs::cfg_width(f), value);
}

// Element I, WIDTH bits wide, of an array field: THR i (kThrBits), RAW plane p, MESH and
// VALID_MAP L (0) and R (1) (32 bits each).
template <typename Port>
inline uint64_t get_cfg(const Port& cfg, regs::Cfg f, int i, int width) {
  return get_bits(cfg, regs::cfg_lsb(f) + i * width, width);
}

template <typename Port>
inline void set_cfg(Port& cfg, regs::Cfg f, int i, int width, uint64_t value) {
  set_bits(cfg, regs::cfg_lsb(f) + i * width, width, value);
}

}  // namespace mcadsw::sim
