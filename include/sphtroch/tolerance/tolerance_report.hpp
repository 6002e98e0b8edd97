// sphtroch/tolerance/tolerance_report.hpp — the report of `sphtroch tolerance` (will a train made
// within tolerances draw the census of its drawing?) and its formats: the result (the nominal
// census, the box's topology, the certified margin, each node's enclosure and sensitivities, and
// optionally a Monte Carlo run beside the proof), its JSON and its text. exact/tolerance_output.hpp
// computes it (classify's census); the result and its formats need no CGAL (tolerance_types.hpp).
//
//   sphtroch::ToleranceReport r = sphtroch::tolerance_report(train, {1e-3, 1e-3, 0.0});   // exact/
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
// the Monte Carlo figures are what sampling saw, not bounds.
#pragma once


#include "sphtroch/census/node_json.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/tolerance/tolerance_types.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
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

inline bool tolerance_certified(const ToleranceReport& r) {
  if (!r.census_certified || r.topology.verdict == BoxTopology::Verdict::undecided) return false;
  if (r.topology.verdict == BoxTopology::Verdict::changes) return true;
  for (const NodeTolerance& n : r.nodes)
    if (!n.max_displacement) return false;
  for (const NodeTolerance& n : r.cusps)
    if (!n.max_displacement) return false;
  return true;
}

namespace tolerance_report_detail {

inline nlohmann::json witness_json(const std::optional<BoundaryWitness>& w) {
  if (!w) return nullptr;
  return {{"kind", to_string(event_kind(w->boundary))}, {"name", boundary_text(w->boundary)}, {"a2", w->a2()}, {"a3", w->a3()}};
}

inline nlohmann::json points_json(const std::vector<NodeTolerance>& points) {
  nlohmann::json a = nlohmann::json::array();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const NodeTolerance& p = points[k];
    a.push_back({{"id", k + 1},
                 {"position", vector3_json(p.position)},
                 {"max_displacement", p.max_displacement ? nlohmann::json(*p.max_displacement) : nlohmann::json(nullptr)},
                 {"d_da2", p.d_da2 ? vector3_json(*p.d_da2) : nlohmann::json(nullptr)},
                 {"d_da3", p.d_da3 ? vector3_json(*p.d_da3) : nlohmann::json(nullptr)},
                 {"d_dphase", vector3_json(p.d_dphase)}});
  }
  return a;
}

inline std::string vector_text(const std::optional<Vector3d>& v) {
  if (!v) return "-";
  return "(" + report_number(v->x()) + ", " + report_number(v->y()) + ", " + report_number(v->z()) + ")";
}

inline std::string witness_text(const BoundaryWitness& w) {
  return boundary_text(w.boundary) + " at a2 = " + report_number(w.a2()) + ", a3 = " + report_number(w.a3());
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
        << (p.max_displacement ? report_number(*p.max_displacement) : std::string("not proved")) << "  " << vector_text(p.d_da2)
        << "  " << vector_text(p.d_da3) << "  " << vector_text(p.d_dphase) << "\n";
  }
}

}  // namespace tolerance_report_detail

inline nlohmann::json topology_margin_json(const TopologyMargin& m) {
  return {{"lower", m.lower}, {"upper", m.upper}, {"converged", m.converged},
          {"nearest", tolerance_report_detail::witness_json(m.nearest)}};
}

inline nlohmann::json tolerance_json(const TrainText& text, const ToleranceReport& r) {
  namespace d = tolerance_report_detail;
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
  namespace d = tolerance_report_detail;
  std::ostringstream out;
  out << "tolerance: n = " << r.train.ratio().str() << text.teeth_note() << ", a2 = " << text.a2 << ", a3 = " << text.a3
      << ", phase = " << text.phase << "\n";
  out << "box: a2 +- " << report_number(r.box.da2) << ", a3 +- " << report_number(r.box.da3) << ", phase +- "
      << report_number(r.box.dphase) << " (radians)\n";
  out << "topology: " << d::topology_line(r) << "\n";
  out << "margin: " << report_number(r.margin.lower) << " .. " << report_number(r.margin.upper)
      << " rad (certified bracket" << (r.margin.converged ? "" : ", wider than 1e-6 relative: the proof stopped at its box bound")
      << ")" << (r.margin.nearest ? "; nearest boundary " + d::witness_text(*r.margin.nearest) : std::string()) << "\n";
  if (!r.census_certified) out << "census: NOT certified (classify's two censuses disagree)\n";
  d::points_text(out, "nodes", r.nodes);
  d::points_text(out, "cusps", r.cusps);
  if (r.monte_carlo)
    out << "monte carlo (" << r.monte_carlo->samples << " trains, seed " << r.monte_carlo->seed << "; seen, not proved): "
        << r.monte_carlo->same_census << " with the nominal census, largest node shift " << report_number(r.monte_carlo->max_node_shift)
        << " rad\n";
  return out.str();
}

}  // namespace sphtroch
