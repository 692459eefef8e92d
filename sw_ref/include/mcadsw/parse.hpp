// Strict number parsing for the command-line tools (mcadsw, mcadsw_sim,
// mcadsw_sim_random): the whole argument must be the number.
#pragma once

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

}  // namespace mcadsw
