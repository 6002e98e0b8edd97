// sphtroch/classification.hpp — everything `sphtroch classify` reports about one gear train:
// the numeric node census (polyline + Newton), the independent root-count census, the cusps, the
// report's analytic criteria side by side, z extremes and symmetry planes, with the work done.
//
//   #include <sphtroch/classification.hpp>    // needs sphtroch::exact (CGAL)
//   sphtroch::Classification c = sphtroch::classify(train);
//   c.curve_class;          // "simple curve", "nodes", "cusps", "nodes and cusps"
//   c.nodes, c.cusps;       // nodes (crossing / tangency, branches) and cusps, refined positions
//   c.agreement.ok;         // both numeric censuses and (n = 1, 2) the report's criteria agree
//
// Decisions (stated in every report):
//  * Default reading: an input within settings.boundary_tolerance of a boundary (a3 = a_p,
//    pi - a_p, a2, pi - a2; a2 = pi/2) is analysed exactly on it (boundary_snap.hpp).
//    settings.literal analyses the given doubles as they are.
//  * Nodes are those of the polyline census (exact CGAL crossings + near misses, refined by
//    Newton on the true curve); the root-count census must find the same node points (positions
//    within kAgreementDistance, same kinds) or the disagreement is listed.
//  * Cusps: where a3 is within kCuspResolution of a pitch cone (exactly 0 after snapping), at the
//    parameters of the pitch-cone criterion, each verified by its speed |dP/dtheta2|.
#pragma once

#include "sphtroch/analytic.hpp"
#include "sphtroch/boundary_snap.hpp"
#include "sphtroch/curve.hpp"
#include "sphtroch/node.hpp"
#include "sphtroch/pitch_cone.hpp"
#include "sphtroch/polyline_census.hpp"
#include "sphtroch/root_census.hpp"

#include <chrono>
#include <utility>
#include <string>
#include <vector>

namespace sphtroch {

/// Node points of the two censuses match when closer than this (chord).
constexpr double kAgreementDistance = 1e-8;

struct ClassifySettings {
  bool literal = false;                          // analyse the doubles as given
  double boundary_tolerance = kBoundaryTolerance;  // default reading only
  std::size_t samples = 0;                       // polyline census samples; 0 = default
};

struct CensusAgreement {
  bool censuses_agree = true;           // polyline vs root-count census
  std::optional<bool> analytic_agrees;  // report's criteria vs numeric (n = 1, 2 only)
  std::vector<std::string> notes;       // every disagreement, in words
  bool ok() const { return censuses_agree && analytic_agrees.value_or(true); }
};

struct ClassificationWork {
  std::size_t points_evaluated = 0;
  std::size_t predicates = 0;
  std::size_t newton_steps = 0;
  std::size_t root_evaluations = 0;
  double seconds = 0.0;
};

struct Classification {
  Classification(GearTrain given, SnappedTrain analysed) : input(std::move(given)), snapped(std::move(analysed)) {}
  GearTrain input;                 // as given
  SnappedTrain snapped;            // the train analysed, and the boundaries it was put on
  bool literal = false;
  std::vector<Node> nodes;
  std::vector<Cusp> cusps;
  bool cusp_within_resolution = false;  // a cone within kCuspResolution but not exactly on it
  std::size_t crossings = 0;       // node points of kind crossing
  std::size_t tangencies = 0;      // node points of kind tangency
  std::string curve_class;
  PolylineCensus polyline;
  RootCensus root;
  AnalyticClassification analytic;
  ZExtremes z;
  Symmetry symmetry_planes;
  ConeMargins cone;
  CensusAgreement agreement;
  ClassificationWork work;
  double tangency_tolerance = 0.0;
};

namespace detail {
inline bool same_node_sets(const std::vector<Node>& a, const std::vector<Node>& b, std::string& why) {
  if (a.size() != b.size()) {
    why = std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " node points";
    return false;
  }
  for (const Node& n : a) {
    const auto it = std::find_if(b.begin(), b.end(), [&](const Node& m) {
      return (m.position - n.position).norm() <= kAgreementDistance && m.kind == n.kind && m.branches == n.branches;
    });
    if (it == b.end()) {
      why = "no match for the " + std::string(to_string(n.kind)) + " node at (" + to_text(n.position.x()) + ", " +
            to_text(n.position.y()) + ", " + to_text(n.position.z()) + ")";
      return false;
    }
  }
  return true;
}
}  // namespace detail

/// Classifies one gear train (see header). Never throws for a valid GearTrain.
inline Classification classify(const GearTrain& input, const ClassifySettings& settings = {}) {
  const auto start = std::chrono::steady_clock::now();
  Classification c(input, snap_to_boundaries(input, settings.literal ? 0.0 : settings.boundary_tolerance));
  c.literal = settings.literal;
  const GearTrain& train = c.snapped.train;
  c.tangency_tolerance = settings.literal ? 0.0 : kTangencyTolerance;

  PolylineCensusSettings ps;
  ps.samples = settings.samples;
  ps.tangency_tolerance = c.tangency_tolerance;
  c.polyline = polyline_census(train, ps);
  RootCensusSettings rs;
  rs.tangency_tolerance = c.tangency_tolerance;
  c.root = root_census(train, rs);
  c.nodes = c.polyline.nodes;
  for (const Node& n : c.nodes) (n.kind == NodeKind::crossing ? c.crossings : c.tangencies)++;

  // Cusps from the pitch-cone criterion, verified by the velocity.
  c.cone = cone_margins(train);
  const TracerCurve<double> curve(train);
  for (const AnalyticCusp& a : pitch_cone_cusps(train, kCuspResolution)) {
    Cusp k;
    k.param = a.param;
    k.position = curve.point(a.param);
    k.speed = curve.velocity(a.param).norm();
    c.cusps.push_back(k);
  }
  c.cusp_within_resolution = !c.cusps.empty() && c.cone.pitch != 0.0 && c.cone.mirror != 0.0;
  c.work.points_evaluated += 2 * c.cusps.size();  // point and velocity of each cusp

  c.analytic = classify_analytic(train, settings.literal ? 0.0 : settings.boundary_tolerance);
  c.z = z_extremes(train);
  c.symmetry_planes = symmetry(train);

  const bool has_nodes = !c.nodes.empty(), has_cusps = !c.cusps.empty();
  c.curve_class = has_nodes ? (has_cusps ? "nodes and cusps" : "nodes") : (has_cusps ? "cusps" : "simple curve");

  // Agreement.
  std::string why;
  if (!detail::same_node_sets(c.polyline.nodes, c.root.nodes, why)) {
    c.agreement.censuses_agree = false;
    c.agreement.notes.push_back("polyline census vs root-count census: " + why);
  }
  if (c.analytic.predicted_nodes) {
    const bool nodes_ok = *c.analytic.predicted_nodes == c.nodes.size();
    const bool cusps_ok = c.analytic.predicted_cusps == c.cusps.size();
    c.agreement.analytic_agrees = nodes_ok && cusps_ok;
    if (!nodes_ok)
      c.agreement.notes.push_back("report's criteria predict " + std::to_string(*c.analytic.predicted_nodes) +
                                  " nodes, the census finds " + std::to_string(c.nodes.size()));
    if (!cusps_ok)
      c.agreement.notes.push_back("report's criteria predict " + std::to_string(c.analytic.predicted_cusps) +
                                  " cusps, found " + std::to_string(c.cusps.size()));
  }

  c.work.points_evaluated += c.polyline.work.points_evaluated;
  c.work.predicates = c.polyline.work.predicates;
  c.work.newton_steps = c.polyline.work.newton_steps;
  c.work.root_evaluations = c.root.evaluations;
  c.work.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

}  // namespace sphtroch
