// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Strict number parsing for the command-line tools (mcadsw, mcadsw_sim,
// mcadsw_sim_random): the whole argument must be the number.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace mcadsw {

// Throws std::invalid_argument("<what> must be an integer, got '<s>'").
inline long parse_long(const std::string& s, const std::string& what) {
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end) throw std::invalid_argument(what + " must be an integer, got '" + s + "'");
  return v;
}

// Throws std::invalid_argument("<what> must be a number, got '<s>'").
inline double parse_double(const std::string& s, const std::string& what) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end) throw std::invalid_argument(what + " must be a number, got '" + s + "'");
  return v;
}

// A 32-bit address or size, decimal or 0x-prefixed hexadecimal. Throws
// std::invalid_argument("<what> must be a 32-bit unsigned integer, got '<s>'").
inline uint32_t parse_u32(const std::string& s, const std::string& what) {
  char* end = nullptr;
  const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
  const unsigned long long v = std::strtoull(s.c_str(), &end, hex ? 16 : 10);
  if (s.empty() || *end || s[0] == '-' || s[0] == '+' || v > 0xffffffffULL)
    throw std::invalid_argument(what + " must be a 32-bit unsigned integer, got '" + s + "'");
  return uint32_t(v);
}

}  // namespace mcadsw
