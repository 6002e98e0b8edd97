// Header-only mode (no SPHTROCH_SEPARATE_EXACT): classify() defined and instantiated here too.
// See test_separate_compilation.cpp.
#include "sphtroch/classify.hpp"

#include <cstddef>
#include <cstdint>

std::size_t classify_nodes_header_only(double a2, double a3, std::int64_t p, std::int64_t q) {
  return sphtroch::classify(sphtroch::GearTrain(a2, a3, sphtroch::Ratio(p, q))).nodes.size();
}
