// sphtroch/core/cost_bounds.hpp — what a node census may cost, decided before any work.
//
//   sphtroch::check_census_cost(Ratio(301, 100));   // fine: ~1.2e5 node points, ~6 s
//   try { sphtroch::check_census_cost(Ratio(1000000)); }   // ~1e12 nodes:
//   catch (const sphtroch::InvalidInput& e) { e.field(); }  // "n", with the bound in e.valid_range()
//
// A closed trochoid of ratio p/q has about |p| (|p| + q) node points (13/5: 221 = 13 * 17;
// 7/3: 63; 101/40: 14140 = 101 * 140), and the censuses' cost grows with the square of that
// (measured on this project's 2-core machine: 101/40 0.44 s and 17 MB for `classify`, 301/100
// 6.1 s and 100 MB; an atlas cell 26 ms and 2 s). Inputs are legal for any p, q <= 1e6, so a
// census of a ratio beyond kMaxCensusNodes is refused up front (exit 2 in the tool) instead of
// running for hours or exhausting memory; `trace` has no such bound (it costs N samples).
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/ratio.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sphtroch {

/// |p| (|p| + q): the order of the node count of the closed curve of ratio p/q.
inline double estimated_nodes(const Ratio& n) {
  const double p = static_cast<double>(n.abs_p()), q = static_cast<double>(n.q());
  return p * (p + q);
}

/// The largest estimated_nodes a census (classify, nodes, plot, scene effects, atlas cells)
/// accepts: 301/100 (1.2e5, ~6 s) passes, 1001/400 (1.4e6, hours) does not.
constexpr double kMaxCensusNodes = 2e5;

/// Defaults of the tool's (and the Python module's) limits on a polyline crossing search
/// (self_crossings.hpp, CrossingSearchOptions::max_contacts, max_work): crossings +
/// touchings (the rows --pairs may write, ~20 bytes each), and work (candidate edge pairs +
/// overlapping box pairs), ~100-200 ns per unit on random vertices here (5e7: ~5-10 s; memory O(N)
/// when only counting).
constexpr std::size_t kDefaultMaxCrossings = 10'000'000;
constexpr std::size_t kDefaultMaxCrossingWork = 50'000'000;
/// The largest value either limit accepts.
/// (On a 32-bit size_t, e.g. WebAssembly, the largest size_t.)
constexpr std::size_t kMaxCrossingLimit =
    static_cast<std::size_t>(std::min<std::uint64_t>(1'000'000'000'000'000ULL, SIZE_MAX));

/// Throws InvalidInput(field, n, ...) when a census of this ratio would exceed kMaxCensusNodes.
inline void check_census_cost(const Ratio& n, const std::string& field = "n") {
  const double e = estimated_nodes(n);
  if (e > kMaxCensusNodes)
    throw InvalidInput(field, n.str(),
                       "its curve has about |p|(|p|+q) = " + number_text(e) +
                           " node points, beyond what a node census does in bounded time and memory",
                       "|p|(|p|+q) <= 200000 for a census (e.g. 301/100); `sphtroch trace` has no such bound");
}

/// Bound on fixed-frame precision points with their censuses over a ratio set: the sum over the
/// ratios of |p| (|p| + q)^2 (about 2 (|p| + q)^2 trains, each censused at a cost ~|p|). Measured
/// 2026-11-27 on this 2-core machine (one core, three points): n = 10, 20, 29 took 0.8, 7.6, 28 s
/// (0.6 to 1.1 ms a unit), so the bound is ~30 s; --ratios 7,7 is 23318, n = 40 (67240) is refused.
constexpr double kMaxPointsCensusWork = 30000;

inline double points_census_work(const std::vector<Ratio>& ratios) {
  double work = 0;
  for (const Ratio& n : ratios) work += static_cast<double>(n.abs_p()) * static_cast<double>(n.abs_p() + n.q()) * static_cast<double>(n.abs_p() + n.q());
  return work;
}

/// Refuses (InvalidInput naming `field` = `value`, the ratio or set as given) fixed-frame
/// precision points over `ratios` beyond kMaxPointsCensusWork, before any work.
inline void check_points_census_work(const std::vector<Ratio>& ratios, const std::string& field, const std::string& value) {
  const double work = points_census_work(ratios);
  if (work > kMaxPointsCensusWork)
    throw InvalidInput(field, value, "estimated work with the censuses " + std::to_string(static_cast<long long>(work)) + " over the bound",
                       "sum over the ratios of |p| (|p| + q)^2 <= 30000 (n = 29 is 26100; --ratios 7,7 is 23318)");
}

/// The work bounds of the inverse design over a ratio set, as the sum over its ratios of
/// (|p| + q)^2 (ratio_work, io/ratio_set.hpp; --ratios 7,7 is 4832). Precision points with a
/// fixed frame: the unknowns Delta span 2 pi q and the equations turn |n| times faster; path
/// fits: the screening and the census grow with |p| and q; the free axis (five points, 18
/// searches in eight unknowns, ~10-30 s for one small ratio on two cores): 500 allows
/// --ratios 3,3 (208), not 4,4 (504). Measured in bench/ (docs/performance.md).
constexpr double kMaxPointsWork = 20000;
constexpr double kMaxFitWork = 20000;
constexpr double kMaxFreeAxisWork = 500;

/// The largest node or cusp count a fit may be asked for (--nodes, --cusps).
constexpr std::size_t kMaxWantedCount = 100000000;

/// The most Monte Carlo trains `tolerance --samples` classifies (each one a classify, ~1-10 ms).
constexpr std::size_t kMaxToleranceSamples = 100000;
/// The bound on samples x (|p| + q)^3 (a classify costs about (|p| + q)^3 x 0.007 ms: 1e7 is about
/// a minute on one core; 1,700 samples for n = 13/5, none for n = 301/100).
constexpr double kMaxToleranceSampleWork = 1e7;
/// How many times a classify costs within kNearConeSampleReach of a pitch cone (the near-cusp
/// loops: about 20 times a classify away from the cones, for n = 5/2).
constexpr double kNearConeSampleFactor = 25;
/// A tolerance box whose a3 range comes this close to a pitch cone (radians) samples near it.
constexpr double kNearConeSampleReach = 1e-3;

}  // namespace sphtroch
