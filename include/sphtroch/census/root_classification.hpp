// sphtroch/census/root_classification.hpp — the class of one train by the root-count census, Eigen only
// (no polyline, no CGAL; 12-14x cheaper than classify() of classification.hpp), and the class
// intervals of a sweep of a3 at fixed a2 and n.
//
//   sphtroch::RootClassification c = sphtroch::classify_roots(train);      // default reading
//   c.curve_class == sphtroch::CurveClass::nodes;  c.nodes;  c.node_points;  c.cusps;
//   c.analytic_nodes;                // the report's count (n = 1, 2), or nullopt
//   std::vector<sphtroch::A3Interval> v = sphtroch::classify_a3_range(pi / 3, sphtroch::Ratio(2), 0.01, pi - 0.01, 721);
//
// Reading (as classification.hpp): by default a train within `boundary_tolerance` (radians) of a
// boundary (pitch cone, pole passage, a2 = pi/2) is analysed on it; `literal` analyses the doubles
// as given (tolerances 0). Node points come from the root census (root_census.hpp: tangency
// tolerance kTangencyTolerance, or 0 when literal); cusps from the pitch-cone test
// (pitch_cone.hpp, resolution kCuspResolution); the report's prediction from criteria.hpp.
// Errors: InvalidInput (field "boundary_tolerance", "count", "a3_range") on bad settings; the
// census cost bound of cost_bounds.hpp (field "n").
#pragma once

#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/closed_form_boundaries.hpp"
#include "sphtroch/map/boundary_snap.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/census/root_census.hpp"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// The reading of classify_roots (core/reading.hpp: default or literal, boundary tolerance).
using RootClassificationSettings = Reading;

/// One train classified by the root census. A regular value type.
struct RootClassification {
  double a2 = 0.0, a3 = 0.0;           // the train analysed (after the boundary reading), radians
  std::vector<std::string> boundaries;  // the boundaries it was read on (names), empty if none
  std::size_t nodes = 0;               // node points: crossings + tangencies
  std::size_t crossings = 0;
  std::size_t tangencies = 0;
  std::size_t cusps = 0;
  CurveClass curve_class = CurveClass::simple_curve;
  std::optional<std::size_t> analytic_nodes;  // the report's count; nullopt unless n = 1, 2
  std::size_t analytic_cusps = 0;             // pitch-cone criterion (every n)
  std::vector<Node> node_points;              // positions, branches, kind (node.hpp)
  /// Nodes and cusps equal the report's criteria (where it has them).
  bool agrees_with_report() const {
    return cusps == analytic_cusps && (!analytic_nodes || *analytic_nodes == nodes);
  }
};

inline RootClassification classify_roots(const GearTrain& train, const RootClassificationSettings& settings = {}) {
  settings.validate();
  const double tolerance = settings.boundary();
  const SnappedTrain snapped = snap_to_boundaries(train, tolerance);
  const GearTrain& t = snapped.train;
  RootClassification c;
  c.a2 = t.a2();
  c.a3 = t.a3();
  for (const Boundary& b : snapped.hits) c.boundaries.push_back(b.name);
  RootCensusSettings rs;
  rs.tangency_tolerance = settings.tangency();
  c.node_points = root_census(t, rs).nodes;
  for (const Node& n : c.node_points) ++(n.kind == NodeKind::crossing ? c.crossings : c.tangencies);
  c.nodes = c.crossings + c.tangencies;
  c.cusps = pitch_cone_cusps(t, kCuspResolution).size();
  c.curve_class = curve_class(c.nodes, c.cusps);
  const AnalyticClassification a = classify_analytic(t, tolerance);
  c.analytic_cusps = a.predicted_cusps;
  c.analytic_nodes = a.predicted_nodes;
  return c;
}

/// A run of a3 values of one class and node/cusp count in a sweep.
struct A3Interval {
  double a3_first = 0.0, a3_last = 0.0;  // first and last sample of the run, radians
  std::size_t samples = 0;
  CurveClass curve_class = CurveClass::simple_curve;
  std::size_t nodes = 0, cusps = 0;
};

/// classify_roots at `count` evenly spaced a3 in [lo, hi] (both ends included; count >= 2), runs
/// of equal (class, nodes, cusps) merged. The true class changes between two samples of
/// neighbouring runs. Cost: count root censuses. Throws InvalidInput: "a2" / "n" as GearTrain
/// does, "a3_range" unless 0 < lo < hi < pi, "count" unless 2 <= count <= 1e6.
inline std::vector<A3Interval> classify_a3_range(double a2, const Ratio& n, double lo, double hi, std::size_t count,
                                                 const RootClassificationSettings& settings = {}) {
  const double pi = Constants<double>::pi();
  if (!(lo > 0.0 && lo < hi && hi < pi))
    throw InvalidInput("a3_range", report_number(lo) + ":" + number_text(hi), "not inside (0, pi) or empty",
                       "0 < lo < hi < pi radians");
  if (count < 2 || count > 1000000)
    throw InvalidInput("count", std::to_string(count), "outside the valid range", "integer 2 .. 1000000");
  std::vector<A3Interval> runs;
  for (std::size_t k = 0; k < count; ++k) {
    const double a3 = k + 1 == count ? hi : lo + (hi - lo) * static_cast<double>(k) / static_cast<double>(count - 1);
    const RootClassification c = classify_roots(GearTrain(a2, a3, n), settings);
    if (!runs.empty() && runs.back().curve_class == c.curve_class && runs.back().nodes == c.nodes &&
        runs.back().cusps == c.cusps) {
      runs.back().a3_last = a3;
      ++runs.back().samples;
    } else {
      runs.push_back(A3Interval{a3, a3, 1, c.curve_class, c.nodes, c.cusps});
    }
  }
  return runs;
}

}  // namespace sphtroch
