// sphtroch/census/polyline_census_result.hpp — what the polyline census (polyline_census.hpp) returns
// and takes, without the census itself: Eigen only, no CGAL. classification.hpp needs these types
// (a Classification holds a PolylineCensus) and includes only this header, so that a file calling
// classify() in separate mode (SPHTROCH_SEPARATE_EXACT, see classification.hpp) parses no CGAL.
//
//   sphtroch::PolylineCensusSettings s;  s.samples = 4096;   // at least kMinCensusSamples
//   sphtroch::census_sample_count(train);                    // the default: 256 (q + |p|), >= 1024
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/reading.hpp"
#include "sphtroch/census/node_assembly.hpp"
#include "sphtroch/core/sampling.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace sphtroch {

struct PolylineCensusSettings {
  std::size_t samples = 0;  // uniform samples per period; 0 = census_sample_count(train)
  /// Branches whose closest approach is within this (radians) are one tangency (default mode).
  double tangency_tolerance = 1e-10;
  /// Escalation level k (certified_census.hpp): 4^k times the uniform samples and 2^k times the
  /// dense samples around near-cusp parameters.
  unsigned escalation = 0;
};

/// The polyline census's settings for a reading (core/reading.hpp): its tangency tolerance and
/// `samples` (0: census_sample_count), as classify and the explorer run it.
inline PolylineCensusSettings polyline_census_settings(const Reading& reading, std::size_t samples = 0) {
  PolylineCensusSettings ps;
  ps.samples = samples;
  ps.tangency_tolerance = reading.tangency();
  return ps;
}

/// Work of one census, counted exactly where it is done.
struct PolylineWork {
  std::size_t points_evaluated = 0;  // TracerCurve calls: point, velocity, acceleration
  std::size_t predicates = 0;
  std::size_t candidate_pairs = 0;
  std::size_t newton_steps = 0;     // refinement iterations + branch-projection steps
  std::size_t seeds = 0;
};

struct PolylineCensus {
  std::size_t samples = 0;             // polyline vertices (uniform + refined)
  std::size_t polyline_crossings = 0;  // exact crossings of the polyline
  std::size_t polyline_touchings = 0;  // exact touching/overlap contacts of the polyline
  std::size_t near_misses = 0;         // near-miss seeds
  std::size_t newton_failures = 0;     // seeds whose refinement did not converge to a meeting
  std::size_t single_branch_groups = 0;  // meeting groups with < 2 distinct branches: not nodes, dropped
  unsigned escalation = 0;             // the settings' escalation level
  std::vector<BranchPair> pairs;
  std::vector<Node> nodes;
  PolylineWork work;
};

/// Whether a node count is certified: the polyline census and the independent root-count census
/// found the same node points (node_sets.hpp), possibly after escalation (certified_census.hpp).
struct CensusCertificate {
  bool certified = false;
  std::vector<std::size_t> samples;         // uniform samples of each polyline census run, in order
  std::vector<std::size_t> polyline_nodes;  // its node count, per run
  std::size_t root_nodes = 0;               // the root-count census's node count
  std::vector<std::string> differences;     // each run's first difference from the root census ("" = agreed)
  std::string disagreement;                 // the last run's first difference ("" when certified)
  std::string stopped;                      // why escalation stopped without agreement ("" otherwise)
  std::size_t runs() const { return samples.size(); }
};

}  // namespace sphtroch
