// sphtroch/exact/classification.hpp — everything `sphtroch classify` reports about one gear train:
// the numeric node census (polyline + Newton), the independent root-count census, the cusps, the
// report's analytic criteria side by side, z extremes and symmetry planes, with the work done.
//
//   #include <sphtroch/classify.hpp>          // needs sphtroch::exact (CGAL)
//   sphtroch::Classification c = sphtroch::classify(train);
//   c.curve_class;          // CurveClass::nodes; to_string(c.curve_class) == "nodes"
//   c.nodes, c.cusps;       // nodes (crossing / tangency, branches) and cusps, refined positions
//   c.agreement.ok();       // both numeric censuses and (n = 1, 2) the report's criteria agree
//
// Decisions (stated in every report):
//  * Default reading: an input within settings.reading.boundary_tolerance of a boundary (a3 = a_p,
//    pi - a_p, a2, pi - a2; a2 = pi/2) is analysed exactly on it (boundary_snap.hpp).
//    settings.reading.literal analyses the given doubles as they are.
//  * Nodes are those of the polyline census (exact CGAL crossings + near misses, refined by
//    Newton on the true curve); the root-count census must find the same node points (positions
//    within kAgreementDistance, same kinds) or the disagreement is listed.
//  * The stages (and their memo and work counters) are those of sphtroch::Analysis
//    (analysis.hpp); classify() is Analysis(train, settings).classification().
//  * Cusps: where a3 is within kCuspResolution of a pitch cone (exactly 0 after snapping), at the
//    parameters of the pitch-cone criterion, each verified by its speed |dP/dtheta2|.
//
// This header holds the types, the assembly and the declaration of classify(); its definition is
// the classification stage of Analysis (analysis.hpp). To call classify() include classify.hpp
// (or sphtroch.hpp), which also gives the definition unless SPHTROCH_SEPARATE_EXACT is defined:
// see classify.hpp for separate compilation. Eigen headers only: no CGAL here.
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/classification.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself"
#endif

#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/extremes_and_symmetry.hpp"
#include "sphtroch/map/boundary_snap.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/kinematics.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/census/node_sets.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/census/polyline_census_result.hpp"
#include "sphtroch/census/root_census.hpp"
#include "sphtroch/census/root_classification.hpp"
#include "sphtroch/core/work.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <utility>
#include <string>
#include <vector>

namespace sphtroch {

struct ClassifySettings {
  Reading reading;          // default, or literal: the doubles as given (core/reading.hpp)
  std::size_t samples = 0;  // polyline census samples; 0 = default
};

struct CensusAgreement {
  bool censuses_agree = true;           // polyline vs root-count census
  std::optional<bool> analytic_agrees;  // report's criteria vs numeric (n = 1, 2 only)
  std::vector<std::string> notes;       // every disagreement, in words
  bool ok() const { return censuses_agree && analytic_agrees.value_or(true); }
};

/// Exit status of the tool when what it printed is not certified (docs/cli.md: Errors and limits).
constexpr int kUncertifiedExitStatus = 3;

/// The work of every stage a classification needed (work.hpp).
using ClassificationWork = Work;

struct Classification {
  Classification() = default;  // Fig. 3's train, nothing computed (a regular value type)
  Classification(GearTrain given, SnappedTrain analysed) : input(std::move(given)), snapped(std::move(analysed)) {}
  GearTrain input;                 // as given
  SnappedTrain snapped;            // the train analysed, and the boundaries it was put on
  bool literal = false;
  std::vector<Node> nodes;
  std::vector<Cusp> cusps;
  bool cusp_within_resolution = false;  // a cone within kCuspResolution but not exactly on it
  std::size_t crossings = 0;       // node points of kind crossing
  std::size_t tangencies = 0;      // node points of kind tangency
  CurveClass curve_class = CurveClass::simple_curve;  // to_string: "simple curve", "nodes", ...
  PolylineCensus polyline;
  RootCensus root;
  AnalyticClassification analytic;
  ZExtremes z;
  Symmetry symmetry_planes;
  ConeMargins cone;
  CensusAgreement agreement;
  CensusCertificate certificate;   // the polyline census runs behind `nodes` (certified_census.hpp)
  /// The design's robustness: the boundary event (boundary_events.hpp) nearest the analysed a3 at
  /// its a2 — where a tolerance on a3 would change the node count (nodes_below -> nodes_above
  /// across it); its a3 minus the analysed a3 is the signed margin. Nothing when a2 has no event.
  std::optional<BoundaryEvent> nearest_event;
  /// Where the tracer slows down: the speed minima of a period (core/kinematics.hpp), 0 at a cusp.
  std::vector<DwellPoint> dwell_points;
  ClassificationWork work;
  /// Every count printed is one two independent methods agree on (and the report's criteria,
  /// where they give one): agreement.ok().
  bool certified() const { return agreement.ok(); }
  double tangency_tolerance = 0.0;
};


/// The stage results a classification is assembled from (Analysis::classification() passes its
/// memoized stages; every reference must outlive the call).
struct ClassificationInputs {
  const GearTrain& input;                // as given
  const SnappedTrain& snapped;           // the train analysed
  bool literal;
  const PolylineCensus& polyline;
  const CensusCertificate& certificate;
  const RootCensus& root;
  const std::vector<Cusp>& cusps;
  const AnalyticClassification& analytic;
  const ZExtremes& z;
  const Symmetry& symmetry;
};

/// The classification of those results: counts, class, cone margins, and the agreement of the
/// two censuses (same node sets, same_node_sets) and of the report's criteria (n = 1, 2),
/// every disagreement in words. `work` is left zero (the caller sums its stages).
inline Classification assemble_classification(const ClassificationInputs& in) {
  Classification c(in.input, in.snapped);
  c.literal = in.literal;
  c.tangency_tolerance = Reading{in.literal}.tangency();
  c.polyline = in.polyline;
  c.certificate = in.certificate;
  c.root = in.root;
  c.nodes = c.polyline.nodes;
  for (const Node& n : c.nodes) (n.kind == NodeKind::crossing ? c.crossings : c.tangencies)++;
  c.cone = cone_margins(in.snapped.train);
  c.cusps = in.cusps;
  c.cusp_within_resolution = !c.cusps.empty() && c.cone.pitch != 0.0 && c.cone.mirror != 0.0;
  c.analytic = in.analytic;
  c.z = in.z;
  c.symmetry_planes = in.symmetry;
  c.curve_class = curve_class(c.nodes.size(), c.cusps.size());
  const GearTrain& analysed = in.snapped.train;
  c.nearest_event = nearest_event(boundary_set(analysed.a2(), analysed.ratio()), analysed.a3());
  c.dwell_points = dwell_points(TracerCurve<double>(analysed));

  std::string why;
  const bool same = same_node_sets(c.polyline.nodes, c.root.nodes, why);
  if (!same || !c.certificate.certified) {  // the certificate is the census's own check of the same
    c.agreement.censuses_agree = false;
    c.agreement.notes.push_back("polyline census vs root-count census: " + (same ? c.certificate.disagreement : why));
    if (!c.certificate.stopped.empty()) c.agreement.notes.push_back("escalation stopped: " + c.certificate.stopped);
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
  return c;
}

/// Classifies one gear train (see header). Throws InvalidInput for bad settings (field
/// "boundary_tolerance", "census_samples") and the census cost bound (field "n"). Defined in
/// analysis.hpp as the classification stage of an Analysis (one code path for `sphtroch
/// classify` and a scene's classification); its `work` is that of the stages it ran.
/// A template only for separate compilation (see header): call it as classify(train[, settings]).
template <typename Settings = ClassifySettings>
Classification classify(const GearTrain& input, const Settings& settings = Settings{});

}  // namespace sphtroch
