// Header-only mode (no SPHTROCH_SEPARATE_EXACT): classify() defined and instantiated here too.
// See test_separate_compilation.cpp.
#include "sphtroch/classify.hpp"
#include "sphtroch/tolerance.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

std::size_t classify_nodes_header_only(double a2, double a3, std::int64_t p, std::int64_t q) {
  return sphtroch::classify(sphtroch::GearTrain(a2, a3, sphtroch::Ratio(p, q))).nodes.size();
}

std::string tolerance_json_header_only(double a2, double a3, std::int64_t p, std::int64_t q, double half_width) {
  const sphtroch::GearTrain train(a2, a3, sphtroch::Ratio(p, q));
  const sphtroch::ToleranceReport r = sphtroch::tolerance_report(train, {half_width, half_width, 0.0});
  const sphtroch::TrainText typed{sphtroch::number_text(a2), sphtroch::number_text(a3), sphtroch::Ratio(p, q).str()};
  return sphtroch::tolerance_json(typed, r).dump();
}
