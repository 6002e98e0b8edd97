// tests/fuzz/fuzz_common.hpp — what every fuzz target shares: an invariant check that names the
// failed condition on stderr and then traps (a libFuzzer crash with a readable reason).
#pragma once

#include <cstdio>
#include <cstring>
#include <string>

#define FUZZ_CHECK(condition)                                                                  \
  do {                                                                                         \
    if (!(condition)) {                                                                        \
      std::fprintf(stderr, "fuzz invariant failed: %s at %s:%d\n", #condition, __FILE__, __LINE__); \
      __builtin_trap();                                                                        \
    }                                                                                          \
  } while (0)

namespace fuzz {

/// Bitwise equality of doubles (tells -0 from 0; NaNs equal when their bits are).
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// A message part the tool prints on its one error line: not empty, no line break.
inline bool one_line(const std::string& s) { return !s.empty() && s.find_first_of("\r\n") == std::string::npos; }

}  // namespace fuzz
