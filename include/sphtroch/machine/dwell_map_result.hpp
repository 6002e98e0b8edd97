// sphtroch/machine/dwell_map_result.hpp — what a clinostat's dwell map holds (machine/dwell_map.hpp
// computes it with HEALPix): seconds per equal-area cell, the share of cells visited, the
// uniformity, and the bounds of its walk. No HEALPix here: front ends that open HEALPix on
// demand (the tool's plugin) hold the result without it.
//
//   sphtroch::DwellMap d;   // d.dwell_s: 12 nside^2 seconds, RING order
#pragma once

#include <cstddef>
#include <vector>

namespace sphtroch {

struct DwellMap {
  int nside = 8;
  double start_s = 0, duration_s = 0;
  std::vector<double> dwell_s;  ///< seconds per cell, RING order, 12 nside^2 values
  double bound_s = 0;           ///< |dwell_s[i] - true time in cell i| <= bound_s for every i
  std::size_t visited = 0;      ///< cells with time > 0
  double visited_fraction = 0;  ///< visited / cells
  double dwell_cv = 0;          ///< coefficient of variation of dwell_s over all cells
};

constexpr double kMaxDwellSteps = 2e6;      // first-level steps of one walk
constexpr double kDwellQueryBudget = 2e7;   // query_disc calls shared by a walk's first-level steps
constexpr int kMaxDwellCarry = 65536;       // the most a step may borrow from the steps before it
constexpr int kMaxNside = 1024;

}  // namespace sphtroch
