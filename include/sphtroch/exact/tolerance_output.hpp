// sphtroch/exact/tolerance_output.hpp — `sphtroch tolerance`: will a train made within tolerances
// draw the census of its drawing? The report (the nominal census, the box's topology, the certified
// margin, each node's enclosure and sensitivities, and optionally a Monte Carlo run beside the
// proof), its JSON and its text. One home for the CLI and Python.
//
//   sphtroch::ToleranceReport r = sphtroch::tolerance_report(train, {1e-3, 1e-3, 0.0});
//   r.topology.verdict;  r.margin.lower;  r.nodes[0].max_displacement;
//   sphtroch::run_monte_carlo(r, 20, 7);                // r.monte_carlo: the spread seen by sampling
//   const sphtroch::TrainText typed{"pi/3", "pi/2", "5/2"};
//   std::cout << sphtroch::tolerance_json(typed, r).dump(2) << sphtroch::tolerance_text(typed, r);
//
// JSON (radians; vectors [x, y, z] in the base frame):
//   {"inputs": {...}, "box": {"a2", "a3", "phase"} (half-widths), "census": {"nodes", "cusps",
//    "certified"}, "topology": "holds" | "changes" | "undecided", "why": text | null,
//    "event": {"kind", "name", "a2", "a3"} | null, "margin": {"lower", "upper", "converged",
//    "nearest": {"kind", "name", "a2", "a3"} | null}, "nodes": [{"id", "position",
//    "max_displacement" (null: not proved), "d_da2", "d_da3" (null for a cusp), "d_dphase"}],
//    "cusps": [same], "monte_carlo": {"samples", "seed", "same_census", "max_node_shift"} | null}
// Certified: the census (classify's certificate), the topology (holds / changes), the margin's
// bracket, each max_displacement. The sensitivities are first-order values at the nominal train;
// the Monte Carlo figures are what sampling saw, not bounds. The train analysed is classify's
// (within 1e-10 of a boundary it is snapped onto it, docs/cli.md: classify).
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/tolerance_output.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself"
#endif

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/parallel_for.hpp"  // ParallelProgress
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/exact/classification.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/synthesis/interval/tolerance_box.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace sphtroch {

/// What sampling trains uniformly in the box saw (not a bound).
struct MonteCarloSpread {
  std::size_t samples = 0;
  std::uint64_t seed = 0;
  std::size_t same_census = 0;  // samples whose node and cusp counts equal the nominal ones
  double max_node_shift = 0;    // largest angle from a nominal node to the nearest node of a sample, radians
};

struct ToleranceReport {
  GearTrain train;  // as analysed (classify's, snapped within 1e-10 of a boundary)
  ToleranceBox box;
  std::size_t node_count = 0, cusp_count = 0;
  bool census_certified = false;
  BoxTopology topology;
  TopologyMargin margin;
  std::vector<NodeTolerance> nodes, cusps;
  std::optional<MonteCarloSpread> monte_carlo;
};

/// The report for the train and box (runs classify, the margin, the box topology, each node).
inline ToleranceReport tolerance_report(const GearTrain& train, const ToleranceBox& box);

/// Classifies `samples` trains drawn uniformly from the box (std::mt19937_64 seeded with `seed`)
/// and sets r.monte_carlo; `progress` (when set) is called with (k, samples) after the k-th train,
/// on the calling thread, and may throw to stop the run. Throws InvalidInput("samples") as
/// check_monte_carlo_cost.
inline void run_monte_carlo(ToleranceReport& r, std::size_t samples, std::uint64_t seed,
                            const ParallelProgress& progress = {});

/// Throws InvalidInput("samples") unless 1 <= samples <= kMaxToleranceSamples and
/// samples x (|p| + q)^3 (x kNearConeSampleFactor when the box's a3 range, widened by 2 da2 for the
/// cone's move with a2, comes within kNearConeSampleReach of a pitch cone) <= kMaxToleranceSampleWork
/// (core/cost_bounds.hpp): refused up front.
inline void check_monte_carlo_cost(const GearTrain& train, const ToleranceBox& box, std::size_t samples);

/// Whether everything the report states is certified: the census, a decided topology and, when
/// it holds, every node's enclosure (the CLI's exit status 3 otherwise).
inline bool tolerance_certified(const ToleranceReport& r);

/// `sphtroch tolerance --json`.
inline nlohmann::json tolerance_json(const TrainText& text, const ToleranceReport& r);
/// Its "margin" member: {"lower", "upper", "converged", "nearest": {"kind", "name", "a2", "a3"} | null}.
inline nlohmann::json topology_margin_json(const TopologyMargin& m);
/// `sphtroch tolerance`: the same for people.
inline std::string tolerance_text(const TrainText& text, const ToleranceReport& r);

// ------------------------------------------------------------------------------------------------

inline ToleranceReport tolerance_report(const GearTrain& train, const ToleranceBox& box) {
  check_tolerance_box(train, box);
  const Classification c = classify(train);
  ToleranceReport r;
  r.train = c.snapped.train;
  r.box = box;
  check_tolerance_box(r.train, box);
  r.node_count = c.nodes.size();
  r.cusp_count = c.cusps.size();
  r.census_certified = c.certificate.certified;
  BoxTolerance proved = box_tolerance(r.train, c.nodes, c.cusps, box);
  r.margin = std::move(proved.margin);
  r.topology = std::move(proved.topology);
  r.nodes = std::move(proved.nodes);
  r.cusps = std::move(proved.cusps);
  return r;
}

inline void check_monte_carlo_cost(const GearTrain& train, const ToleranceBox& box, std::size_t samples) {
  if (!(samples >= 1 && samples <= kMaxToleranceSamples))
    throw InvalidInput("samples", std::to_string(samples), "outside the valid range",
                       "integer 1 .. " + std::to_string(kMaxToleranceSamples));
  const Ratio& n = train.ratio();
  const ConeMargins cone = cone_margins(train);
  const bool near_cone = std::min(std::abs(cone.pitch), std::abs(cone.mirror)) <= box.da3 + 2 * box.da2 + kNearConeSampleReach;
  const double size = static_cast<double>(n.abs_p() + n.q());
  const double work = static_cast<double>(samples) * size * size * size * (near_cone ? kNearConeSampleFactor : 1.0);
  if (work > kMaxToleranceSampleWork)
    throw InvalidInput("samples", std::to_string(samples),
                       "estimated work " + number_text(work) + " for n = " + n.str() + (near_cone ? " next to a pitch cone" : "") + " over the bound",
                       "samples x (|p| + q)^3 (x 25 within 1e-3 rad of a pitch cone) <= 1e7 (about a minute)");
}

inline void run_monte_carlo(ToleranceReport& r, std::size_t samples, std::uint64_t seed,
                            const ParallelProgress& progress) {
  check_monte_carlo_cost(r.train, r.box, samples);
  MonteCarloSpread m;
  m.samples = samples;
  m.seed = seed;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const GearTrain& t = r.train;
  for (std::size_t k = 0; k < samples; ++k) {
    const double a2 = t.a2() + r.box.da2 * unit(rng), a3 = t.a3() + r.box.da3 * unit(rng);
    const double phase = t.phase() + r.box.dphase * unit(rng);
    const Classification c = classify(GearTrain(a2, a3, t.ratio(), phase), ClassifySettings{});
    if (c.nodes.size() == r.node_count && c.cusps.size() == r.cusp_count) ++m.same_census;
    for (const NodeTolerance& n : r.nodes) {
      double nearest = Constants<double>::pi();
      for (const Node& s : c.nodes) nearest = std::min(nearest, std::acos(std::clamp(n.position.dot(s.position), -1.0, 1.0)));
      if (!c.nodes.empty()) m.max_node_shift = std::max(m.max_node_shift, nearest);
    }
    if (progress) progress(k + 1, samples);
  }
  r.monte_carlo = m;
}

inline bool tolerance_certified(const ToleranceReport& r) {
  if (!r.census_certified || r.topology.verdict == BoxTopology::Verdict::undecided) return false;
  if (r.topology.verdict == BoxTopology::Verdict::changes) return true;
  for (const NodeTolerance& n : r.nodes)
    if (!n.max_displacement) return false;
  for (const NodeTolerance& n : r.cusps)
    if (!n.max_displacement) return false;
  return true;
}

namespace tolerance_output_detail {

inline nlohmann::json vector_json(const Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

inline nlohmann::json witness_json(const std::optional<BoundaryWitness>& w) {
  if (!w) return nullptr;
  return {{"kind", to_string(event_kind(w->boundary))}, {"name", boundary_text(w->boundary)}, {"a2", w->a2()}, {"a3", w->a3()}};
}

inline nlohmann::json points_json(const std::vector<NodeTolerance>& points) {
  nlohmann::json a = nlohmann::json::array();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const NodeTolerance& p = points[k];
    a.push_back({{"id", k + 1},
                 {"position", vector_json(p.position)},
                 {"max_displacement", p.max_displacement ? nlohmann::json(*p.max_displacement) : nlohmann::json(nullptr)},
                 {"d_da2", p.d_da2 ? vector_json(*p.d_da2) : nlohmann::json(nullptr)},
                 {"d_da3", p.d_da3 ? vector_json(*p.d_da3) : nlohmann::json(nullptr)},
                 {"d_dphase", vector_json(p.d_dphase)}});
  }
  return a;
}

inline std::string vector_text(const std::optional<Vector3d>& v) {
  if (!v) return "-";
  return "(" + number_text(v->x()) + ", " + number_text(v->y()) + ", " + number_text(v->z()) + ")";
}

inline std::string witness_text(const BoundaryWitness& w) {
  return boundary_text(w.boundary) + " at a2 = " + number_text(w.a2()) + ", a3 = " + number_text(w.a3());
}

inline std::string topology_line(const ToleranceReport& r) {
  const std::string census = std::to_string(r.node_count) + " node(s), " + std::to_string(r.cusp_count) + " cusp(s)";
  switch (r.topology.verdict) {
    case BoxTopology::Verdict::holds:
      if (r.box.da2 == 0 && r.box.da3 == 0)
        return "holds (the box fixes a2 and a3: every train in it is the nominal one turned about the sun axis, " + census + ")";
      return "holds (certified: no boundary of the design map meets the box; every train in it draws " + census + ")";
    case BoxTopology::Verdict::changes:
      return "changes (certified: " + witness_text(*r.topology.event) + " lies in the box; the nominal train draws " + census + ")";
    case BoxTopology::Verdict::undecided: break;
  }
  return "undecided (" + r.topology.why + ")";
}

inline void points_text(std::ostream& out, const std::string& what, const std::vector<NodeTolerance>& points) {
  out << what << " (" << points.size() << "): position; largest move over the box (rad, certified); d/da2; d/da3; d/dphase\n";
  for (std::size_t k = 0; k < points.size(); ++k) {
    const NodeTolerance& p = points[k];
    out << "  " << k + 1 << "  " << vector_text(p.position) << "  "
        << (p.max_displacement ? number_text(*p.max_displacement) : std::string("not proved")) << "  " << vector_text(p.d_da2)
        << "  " << vector_text(p.d_da3) << "  " << vector_text(p.d_dphase) << "\n";
  }
}

}  // namespace tolerance_output_detail

inline nlohmann::json topology_margin_json(const TopologyMargin& m) {
  return {{"lower", m.lower}, {"upper", m.upper}, {"converged", m.converged},
          {"nearest", tolerance_output_detail::witness_json(m.nearest)}};
}

inline nlohmann::json tolerance_json(const TrainText& text, const ToleranceReport& r) {
  namespace d = tolerance_output_detail;
  nlohmann::json j;
  j["inputs"] = {{"a2", text.a2}, {"a3", text.a3}, {"n", r.train.ratio().str()}, {"phase", text.phase}};
  if (!text.teeth.empty()) j["inputs"]["teeth"] = text.teeth;
  j["box"] = {{"a2", r.box.da2}, {"a3", r.box.da3}, {"phase", r.box.dphase}};
  j["census"] = {{"nodes", r.node_count}, {"cusps", r.cusp_count}, {"certified", r.census_certified}};
  j["topology"] = to_string(r.topology.verdict);
  j["why"] = r.topology.why.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.topology.why);
  j["event"] = d::witness_json(r.topology.event);
  j["margin"] = topology_margin_json(r.margin);
  j["nodes"] = d::points_json(r.nodes);
  j["cusps"] = d::points_json(r.cusps);
  j["monte_carlo"] = nullptr;
  if (r.monte_carlo)
    j["monte_carlo"] = {{"samples", r.monte_carlo->samples}, {"seed", r.monte_carlo->seed},
                        {"same_census", r.monte_carlo->same_census}, {"max_node_shift", r.monte_carlo->max_node_shift}};
  return j;
}

inline std::string tolerance_text(const TrainText& text, const ToleranceReport& r) {
  namespace d = tolerance_output_detail;
  std::ostringstream out;
  out << "tolerance: n = " << r.train.ratio().str() << text.teeth_note() << ", a2 = " << text.a2 << ", a3 = " << text.a3
      << ", phase = " << text.phase << "\n";
  out << "box: a2 +- " << number_text(r.box.da2) << ", a3 +- " << number_text(r.box.da3) << ", phase +- "
      << number_text(r.box.dphase) << " (radians)\n";
  out << "topology: " << d::topology_line(r) << "\n";
  out << "margin: " << number_text(r.margin.lower) << " .. " << number_text(r.margin.upper)
      << " rad (certified bracket" << (r.margin.converged ? "" : ", wider than 1e-6 relative: the proof stopped at its box bound")
      << ")" << (r.margin.nearest ? "; nearest boundary " + d::witness_text(*r.margin.nearest) : std::string()) << "\n";
  if (!r.census_certified) out << "census: NOT certified (classify's two censuses disagree)\n";
  d::points_text(out, "nodes", r.nodes);
  d::points_text(out, "cusps", r.cusps);
  if (r.monte_carlo)
    out << "monte carlo (" << r.monte_carlo->samples << " trains, seed " << r.monte_carlo->seed << "; seen, not proved): "
        << r.monte_carlo->same_census << " with the nominal census, largest node shift " << number_text(r.monte_carlo->max_node_shift)
        << " rad\n";
  return out.str();
}

}  // namespace sphtroch
