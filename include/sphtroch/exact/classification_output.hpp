// sphtroch/exact/classification_output.hpp — the reports of an analysis, as `sphtroch classify`, `plot`, `crossings`
// and a scene print them: the classification as text and as JSON, the z extremes as JSON, the
// plot's caption and SVG, and the summary of a polyline crossing search. Needs sphtroch::exact
// (it prints a Classification) and nlohmann-json.
//
//   sphtroch::TrainText text{"pi/2", "pi/2", "2"};
//   sphtroch::Classification c = sphtroch::classify(text.train());
//   std::cout << sphtroch::classification_json(text, c).dump(2) << "\n";   // classify --json
//   sphtroch::write_classification_text(std::cout, text, c);               // classify
//
// Contracts:
//  1. `text` echoes the angles as the user wrote them (a2_text, a3_text, the plot caption); every
//     number comes from the Classification, printed as report_number writes it in text (the
//     shortest round-trip digits, 1e-5, 0 for -0: number_text.hpp), as JSON numbers (round-trip)
//     in JSON; measured times in
//     text reports have 3 significant digits (seconds_text), in JSON every digit.
//  2. classification_json: one object with the keys inputs, cone_angles, period, class, counts,
//     nodes, cusps, cusp_within_resolution, boundaries, z_extremes, nearest_event, margin (the
//     certified margin: topology_margin.hpp, as tolerance_report.hpp's topology_margin_json), symmetry, analytic, censuses,
//     agreement, tolerances, work (docs/cli.md: classify --json documents each field). nlohmann::json
//     sorts keys when dumped. Node longitude/latitude are radians, atan2(y, x) and asin(z).
//  3. The text report states the same facts in words, with degrees beside radians for the inputs
//     and node positions, and every disagreement of the censuses on its own "DISAGREEMENT:" line.
//  4. plot_caption: "a2 = A2, a3 = A3, n = p/q[, phase = PH] — N node(s)[ (C crossing, T tangency)],
//     K cusp(s)", the phase shown when the analysed phase is not 0.
//  5. root_classification_json (the Eigen-only classification, Python's classify_roots()): a2,
//     a3, boundaries, class, nodes, crossings, tangencies, cusps, analytic_nodes (null without a
//     report's count), analytic_cusps, agrees_with_report, node_points; each node point is an
//     object of classification_json's "nodes" (one node schema for every result).
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/classification_output.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself"
#endif

#include "sphtroch/exact/classification.hpp"
#include "sphtroch/tolerance/topology_margin.hpp"  // the certified margin
#include "sphtroch/tolerance/tolerance_report.hpp"  // its JSON (topology_margin_json)
#include "sphtroch/map/criteria.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/census/node_assembly.hpp"
#include "sphtroch/census/node_json.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/exact/polyline_census.hpp"
#include "sphtroch/exact/self_crossings.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/core/types.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace sphtroch {

/// `classify --json` (contract 2).
inline nlohmann::json classification_json(const TrainText& text, const Classification& c);

/// The root-count classification (contract 5).
inline nlohmann::json root_classification_json(const RootClassification& c);

/// `classify` (contract 3).
inline void write_classification_text(std::ostream& out, const TrainText& text, const Classification& c);

/// {"z_max", "z_min", "maxima": [{"param", "position": [x, y, z]}], "minima": [...]}: the
/// "z_extremes" object of classify --json and a scene's extrema effect.
inline nlohmann::json z_extremes_json(const ZExtremes& z);

/// The caption of `plot` (contract 4); `analysed` is the train the nodes belong to.
/// With a certificate that is not certified, the caption ends " — UNCERTIFIED (root-count census: N)".
inline std::string plot_caption(const TrainText& text, const GearTrain& analysed, const std::vector<Node>& nodes,
                                const std::vector<Cusp>& cusps, const CensusCertificate* certificate = nullptr);

/// `plot`: the sphere picture of `trajectory` with nodes, cusps and plot_caption (svg_plot.hpp),
/// drawn with `options` (view, size, labels; its caption is replaced).
inline std::string plot_svg(const TrainText& text, const GearTrain& analysed, const Trajectory<double>& trajectory,
                            const std::vector<Node>& nodes, const std::vector<Cusp>& cusps,
                            const CensusCertificate* certificate = nullptr, PlotOptions options = {});

/// What `sphtroch crossings` reports about one search.
struct CrossingsSummary {
  std::size_t vertices = 0;
  bool closed = true;
  std::size_t crossings = 0;        // SelfCrossings::crossings.size()
  std::size_t touchings = 0;        // SelfCrossings::touchings.size()
  std::size_t candidate_pairs = 0;
  std::size_t predicates = 0;
  std::string input_format;         // PolylineInput::format
  double seconds_read = 0.0;
  double seconds_search = 0.0;
};

/// The summary of a search over a polyline of `vertices` vertices read as `input_format`.
inline CrossingsSummary crossings_summary(const SelfCrossings& sc, std::size_t vertices, bool closed,
                                          const std::string& input_format, double seconds_read,
                                          double seconds_search);
/// The same from the counts of count_self_crossings / visit_self_crossings.
inline CrossingsSummary crossings_summary(const CrossingCounts& c, bool closed, const std::string& input_format,
                                          double seconds_read, double seconds_search);

/// `crossings --json`: the fields of CrossingsSummary under their own names ("closed", ...).
inline nlohmann::json crossings_summary_json(const CrossingsSummary& s);

/// `crossings`: one fact per line ("vertices N (closed), read as F", "crossings N", ...).
inline void write_crossings_summary_text(std::ostream& out, const CrossingsSummary& s);

// ---------------------------------------------------------------------------------------------
// Implementation details follow.

namespace report_detail {

inline std::string vec_text(const Vector3d& v) {
  return "(" + report_number(v.x()) + ", " + report_number(v.y()) + ", " + report_number(v.z()) + ")";
}

inline double longitude(const Vector3d& p) { return std::atan2(p.y(), p.x()); }
inline double latitude(const Vector3d& p) { return std::asin(std::clamp(p.z(), -1.0, 1.0)); }

inline nlohmann::json inputs_json(const TrainText& text, const Classification& c) {
  const GearTrain& in = c.input;
  nlohmann::json j = {{"a2", in.a2()},          {"a3", in.a3()},       {"a2_text", text.a2},
                      {"a3_text", text.a3},     {"n", in.ratio().str()}, {"n_value", in.n()},
                      {"phase", in.phase_given()}, {"phase_reduced", in.phase()}, {"literal", c.literal}};
  if (!text.teeth.empty()) j["teeth"] = parse_teeth(text.teeth, "teeth").str();  // as given: 39:15, not 13:5
  return j;
}

inline nlohmann::json boundaries_json(const Classification& c) {
  nlohmann::json hits = nlohmann::json::array();
  for (const Boundary& b : c.snapped.hits) hits.push_back({{"boundary", b.name}, {"value", b.value}, {"margin", b.margin}});
  return {{"on", hits},
          {"a2_right_angle", c.snapped.a2_snapped},
          {"tolerance", c.snapped.tolerance},
          {"pitch_cone_margin", c.cone.pitch},
          {"mirror_pitch_cone_margin", c.cone.mirror}};
}

inline nlohmann::json symmetry_json(const Symmetry& s) {
  nlohmann::json planes = nlohmann::json::array();
  for (const auto& p : s.planes)
    planes.push_back({{"normal", vector3_json(p.normal)}, {"azimuth", p.azimuth}, {"param_offset", p.param_offset}});
  return {{"rotation_order", s.rotation_order}, {"mirror_planes", planes}};
}

inline nlohmann::json analytic_json(const AnalyticClassification& a) {
  using nlohmann::json;
  json criteria = json::array();
  for (const Criterion& k : a.criteria)
    criteria.push_back({{"equation", k.equation},
                        {"statement", k.statement},
                        {"status", to_string(k.status)},
                        {"lower", k.lower},
                        {"upper", k.upper},
                        {"lower_margin", k.lower_margin},
                        {"upper_margin", k.upper_margin},
                        {"prediction", k.prediction}});
  return {{"applicable", a.applicable},
          {"predicted_nodes", a.predicted_nodes ? json(*a.predicted_nodes) : json(nullptr)},
          {"predicted_cusps", a.predicted_cusps},
          {"class", a.curve_class},
          {"criteria", criteria}};
}

inline nlohmann::json censuses_json(const Classification& c) {
  return {{"polyline",
           {{"nodes", c.polyline.nodes.size()},
            {"samples", c.polyline.samples},
            {"polyline_crossings", c.polyline.polyline_crossings},
            {"polyline_touchings", c.polyline.polyline_touchings},
            {"near_misses", c.polyline.near_misses},
            {"newton_rejected", c.polyline.newton_failures}}},
          {"root_count",
           {{"nodes", c.root.nodes.size()},
            {"roots", c.root.roots.size()},
            {"north_pole_node", c.root.north_pole_node},
            {"south_pole_node", c.root.south_pole_node},
            {"error_bound", c.root.error_bound}}}};
}

inline nlohmann::json agreement_json(const CensusAgreement& a) {
  using nlohmann::json;
  return {{"ok", a.ok()},
          {"censuses_agree", a.censuses_agree},
          {"analytic_agrees", a.analytic_agrees ? json(*a.analytic_agrees) : json(nullptr)},
          {"notes", a.notes}};
}

inline nlohmann::json certificate_json(const Classification& c) {
  nlohmann::json runs = nlohmann::json::array();
  for (std::size_t k = 0; k < c.certificate.runs(); ++k)
    runs.push_back({{"samples", c.certificate.samples[k]},
                    {"nodes", c.certificate.polyline_nodes[k]},
                    {"difference", c.certificate.differences[k]}});
  return {{"certified", c.certified()},
          {"polyline_runs", runs},
          {"root_count_nodes", c.certificate.root_nodes},
          {"stopped", c.certificate.stopped}};
}

/// The words for an uncertified result: both counts (docs/cli.md: Certified counts).
inline std::string uncertified_text(const Classification& c) {
  return "UNCERTIFIED: the polyline census finds " + std::to_string(c.polyline.nodes.size()) +
         " node(s), the root-count census " + std::to_string(c.certificate.root_nodes) +
         (c.agreement.analytic_agrees.value_or(true) ? std::string() : std::string(", the report's criteria disagree"));
}

inline nlohmann::json tolerances_json(const Classification& c) {
  return {{"boundary", c.snapped.tolerance},          {"cusp_resolution", kCuspResolution},
          {"tangency", c.tangency_tolerance},         {"node_residual", kNodeResidual},
          {"node_merge_distance", kNodeMergeDistance}, {"agreement_distance", kAgreementDistance},
          {"branch_grouping", kBranchParamTolerance},  {"lens_scan_angle", kLensScanAngle}};
}

inline nlohmann::json work_json(const Work& w) {
  return {{"points_evaluated", w.points_evaluated},
          {"predicates", w.predicates},
          {"newton_steps", w.newton_steps},
          {"root_function_evaluations", w.root_evaluations},
          {"seconds", w.seconds}};
}

// The sections of the text report, in order.

inline void text_inputs(std::ostream& out, const TrainText& text, const Classification& c) {
  const GearTrain& in = c.input;
  const GearTrain& tr = c.snapped.train;
  out << "inputs\n";
  out << "  a2 = " << text.a2 << " = " << report_number(in.a2()) << " rad (" << report_number(degrees(in.a2())) << " deg)\n";
  out << "  a3 = " << text.a3 << " = " << report_number(in.a3()) << " rad (" << report_number(degrees(in.a3())) << " deg)\n";
  out << "  n = " << in.ratio().str() << text.teeth_note() << ", phase = " << report_number(in.phase_given()) << " rad";
  if (in.phase() != in.phase_given()) out << " (reduced to " << report_number(in.phase()) << ")";
  out << "\n";
  out << "  reading: " << (c.literal ? "literal (the given doubles)" : "default (boundaries within tolerance are snapped)")
      << "\n";
  out << "cone angles\n  a_p = " << report_number(tr.planet_cone()) << " rad, a_s = " << report_number(tr.sun_cone())
      << " rad; period 2*pi*q = " << report_number(tr.period()) << " rad\n";
}

inline void text_boundaries(std::ostream& out, const Classification& c) {
  out << "boundaries (tolerance " << report_number(c.snapped.tolerance) << " rad)\n";
  if (c.snapped.a2_snapped) out << "  a2 = pi/2 (margin " << report_number(c.snapped.a2_margin) << ")\n";
  for (const Boundary& b : c.snapped.hits) out << "  on " << b.name << " (margin " << report_number(b.margin) << ")\n";
  if (!c.snapped.a2_snapped && c.snapped.hits.empty()) out << "  none within tolerance\n";
  out << "  margin to pitch cone a3 - a_p = " << report_number(c.cone.pitch) << ", to mirror a3 - (pi - a_p) = "
      << report_number(c.cone.mirror) << "\n\n";
}

inline void text_nodes_and_cusps(std::ostream& out, const Classification& c) {
  out << "class: " << to_string(c.curve_class) << " — " << c.nodes.size() << " node(s) (" << c.crossings
      << " crossing, " << c.tangencies << " tangency), " << c.cusps.size() << " cusp(s)"
      << (c.cusp_within_resolution ? " [cusp within resolution " + report_number(kCuspResolution) + " rad]" : "") << "\n";
  out << "certified: " << (c.certified() ? "yes (two independent censuses agree)" : "NO — " + uncertified_text(c)) << "\n";
  std::size_t i = 0;
  for (const Node& n : c.nodes) {
    out << "  node " << ++i << ": " << to_string(n.kind) << ", " << n.branches << " branches, at " << vec_text(n.position)
        << "\n          lon " << report_number(degrees(longitude(n.position))) << " deg, lat "
        << report_number(degrees(latitude(n.position))) << " deg; theta2 =";
    for (double t : n.params) out << ' ' << report_number(t);
    out << "; angle " << report_number(n.angle) << " rad\n";
  }
  i = 0;
  for (const Cusp& k : c.cusps)
    out << "  cusp " << ++i << ": at " << vec_text(k.position) << ", theta2 = " << report_number(k.param) << ", speed "
        << report_number(k.speed) << "\n";
}

/// "nearest event: <name> at a3 = A (a3 + M rad): N -> M nodes" (boundary_events.hpp).
inline void text_nearest_event(std::ostream& out, const Classification& c) {
  if (!c.nearest_event) return;
  const BoundaryEvent& e = *c.nearest_event;
  const double margin = e.a3 - c.snapped.train.a3();
  out << "\nnearest event in a3 at this a2 (sphtroch boundaries): " << e.name << " at a3 = " << report_number(e.a3)
      << " (a3 " << (margin < 0 ? "- " : "+ ") << report_number(std::abs(margin)) << " rad): nodes " << e.nodes_below
      << " -> " << e.nodes_above << " across it\n";
}

/// "certified margin (sphtroch tolerance): L .. U rad in (a2, a3) to <boundary> at a2 = .., a3 = .."
inline void text_certified_margin(std::ostream& out, const Classification& c) {
  const TopologyMargin m = topology_margin(c.snapped.train);
  out << "certified margin (sphtroch tolerance): " << report_number(m.lower) << " .. " << report_number(m.upper)
      << " rad in (a2, a3)" << (m.nearest ? " to " + boundary_text(m.nearest->boundary) + " at a2 = " + report_number(m.nearest->a2()) +
                                                 ", a3 = " + report_number(m.nearest->a3())
                                           : std::string())
      << (m.converged ? "" : " (the proof stopped at its box bound)") << "\n";
}

/// "dwell points (speed minima): k" and one line each.
inline void text_dwell_points(std::ostream& out, const Classification& c) {
  out << "\ndwell points (speed minima of |dP/dtheta2|, per unit carrier rate): " << c.dwell_points.size() << "\n";
  std::size_t i = 0;
  for (const DwellPoint& d : c.dwell_points)
    out << "  dwell " << ++i << ": theta2 = " << report_number(d.param) << ", speed " << report_number(d.speed) << " at "
        << vec_text(d.position) << "\n";
}

inline void text_extremes_and_symmetry(std::ostream& out, const Classification& c) {
  out << "\nz extremes (Eqs. 14/15, 32-35 generalised)\n  z_max = " << report_number(c.z.z_max) << " at theta2 =";
  for (const auto& p : c.z.maxima) out << ' ' << report_number(p.param);
  out << "\n  z_min = " << report_number(c.z.z_min) << " at theta2 =";
  for (const auto& p : c.z.minima) out << ' ' << report_number(p.param);
  out << "\nsymmetry: " << c.symmetry_planes.rotation_order << "-fold about Z1; mirror planes with normals at azimuth";
  for (const auto& p : c.symmetry_planes.planes) out << ' ' << report_number(p.azimuth);
  out << " rad\n";
}

inline void text_criteria(std::ostream& out, const AnalyticClassification& a) {
  out << "\nthe report's criteria\n";
  for (const Criterion& k : a.criteria)
    out << "  " << k.equation << ": " << k.statement << " — " << to_string(k.status) << " (margins "
        << report_number(k.lower_margin) << ", " << report_number(k.upper_margin) << "): " << k.prediction << "\n";
  out << "  predicted: "
      << (a.predicted_nodes ? std::to_string(*a.predicted_nodes) + " node(s)"
                            : std::string("nodes not given by the report for this n"))
      << ", " << a.predicted_cusps << " cusp(s)\n";
}

inline void text_censuses(std::ostream& out, const Classification& c) {
  out << "\ncensuses side by side\n";
  out << "  polyline (exact CGAL predicates + Newton): " << c.polyline.nodes.size() << " node(s) from "
      << c.polyline.samples << " samples, " << c.polyline.polyline_crossings << " polyline crossings, "
      << c.polyline.polyline_touchings << " touchings, " << c.polyline.near_misses << " near misses\n";
  out << "  root count (1D, interval of b in (0, pi)): " << c.root.nodes.size() << " node(s) from "
      << c.root.roots.size() << " root(s)" << (c.root.north_pole_node ? " + north pole" : "")
      << (c.root.south_pole_node ? " + south pole" : "") << "\n";
  if (c.certificate.runs() > 1) {
    out << "  escalation: polyline census runs of";
    for (std::size_t k = 0; k < c.certificate.runs(); ++k)
      out << (k ? ", " : " ") << c.certificate.samples[k] << " samples (" << c.certificate.polyline_nodes[k] << " nodes)";
    out << "\n";
  }
  out << "  agreement: " << (c.agreement.ok() ? "yes" : "NO") << "\n";
  for (const auto& note : c.agreement.notes) out << "    DISAGREEMENT: " << note << "\n";
}

inline void text_tolerances_and_work(std::ostream& out, const Classification& c) {
  out << "\ntolerances: boundary " << report_number(c.snapped.tolerance) << " rad, cusp resolution "
      << report_number(kCuspResolution) << " rad, tangency " << report_number(c.tangency_tolerance) << ", node residual "
      << report_number(kNodeResidual) << ", node merge " << report_number(kNodeMergeDistance) << ", agreement "
      << report_number(kAgreementDistance) << ", branch grouping " << report_number(kBranchParamTolerance)
      << " rad, lens scan below " << report_number(kLensScanAngle) << " rad\n";
  out << "work: " << c.work.points_evaluated << " points evaluated, " << c.work.predicates << " exact predicates, "
      << c.work.newton_steps << " Newton steps, " << c.work.root_evaluations << " root-function evaluations, "
      << seconds_text(c.work.seconds) << " s\n";
}

}  // namespace report_detail

inline nlohmann::json z_extremes_json(const ZExtremes& z) {
  using nlohmann::json;
  json zmax = json::array(), zmin = json::array();
  for (const auto& p : z.maxima) zmax.push_back({{"param", p.param}, {"position", vector3_json(p.position)}});
  for (const auto& p : z.minima) zmin.push_back({{"param", p.param}, {"position", vector3_json(p.position)}});
  return {{"z_max", z.z_max}, {"z_min", z.z_min}, {"maxima", zmax}, {"minima", zmin}};
}

inline nlohmann::json root_classification_json(const RootClassification& c) {
  return {{"a2", c.a2},
          {"a3", c.a3},
          {"boundaries", c.boundaries},
          {"class", to_string(c.curve_class)},
          {"nodes", c.nodes},
          {"crossings", c.crossings},
          {"tangencies", c.tangencies},
          {"cusps", c.cusps},
          {"analytic_nodes", c.analytic_nodes ? nlohmann::json(*c.analytic_nodes) : nlohmann::json(nullptr)},
          {"analytic_cusps", c.analytic_cusps},
          {"agrees_with_report", c.agrees_with_report()},
          {"node_points", node_list_json(c.node_points)}};
}

/// Nodes and cusps in the schema of classify --json's "nodes" and "cusps" (every census's report uses it).

inline nlohmann::json classification_json(const TrainText& text, const Classification& c) {
  namespace d = report_detail;
  const GearTrain& tr = c.snapped.train;
  nlohmann::json j;
  j["inputs"] = d::inputs_json(text, c);
  j["cone_angles"] = {{"a_p", tr.planet_cone()}, {"a_s", tr.sun_cone()}};
  j["period"] = tr.period();
  j["class"] = to_string(c.curve_class);
  j["certified"] = c.certified();
  j["certificate"] = d::certificate_json(c);
  j["counts"] = {{"nodes", c.nodes.size()}, {"cusps", c.cusps.size()}, {"crossings", c.crossings},
                 {"tangencies", c.tangencies}};
  j["nodes"] = node_list_json(c.nodes);
  j["cusps"] = cusp_list_json(c.cusps);
  j["cusp_within_resolution"] = c.cusp_within_resolution;
  j["boundaries"] = d::boundaries_json(c);
  j["z_extremes"] = z_extremes_json(c.z);
  j["nearest_event"] = nullptr;
  if (c.nearest_event) {
    const BoundaryEvent& e = *c.nearest_event;
    j["nearest_event"] = {{"a3", e.a3}, {"kind", to_string(e.kind)}, {"name", e.name}, {"margin", e.a3 - c.snapped.train.a3()},
                          {"nodes_below", e.nodes_below}, {"nodes_above", e.nodes_above}};
  }
  j["margin"] = topology_margin_json(topology_margin(c.snapped.train));
  j["dwell_points"] = nlohmann::json::array();
  for (const DwellPoint& p : c.dwell_points)
    j["dwell_points"].push_back({{"param", p.param}, {"position", vector3_json(p.position)}, {"speed", p.speed}});
  j["symmetry"] = d::symmetry_json(c.symmetry_planes);
  j["analytic"] = d::analytic_json(c.analytic);
  j["censuses"] = d::censuses_json(c);
  j["agreement"] = d::agreement_json(c.agreement);
  j["tolerances"] = d::tolerances_json(c);
  j["work"] = d::work_json(c.work);
  return j;
}

inline void write_classification_text(std::ostream& out, const TrainText& text, const Classification& c) {
  namespace d = report_detail;
  out << "sphtroch classify — spherical planetary gear train (Lin & Tsai 1990)\n\n";
  d::text_inputs(out, text, c);
  d::text_boundaries(out, c);
  d::text_nodes_and_cusps(out, c);
  d::text_nearest_event(out, c);
  d::text_certified_margin(out, c);
  d::text_dwell_points(out, c);
  d::text_extremes_and_symmetry(out, c);
  d::text_criteria(out, c.analytic);
  d::text_censuses(out, c);
  d::text_tolerances_and_work(out, c);
}

inline std::string plot_caption(const TrainText& text, const GearTrain& analysed, const std::vector<Node>& nodes,
                                const std::vector<Cusp>& cusps, const CensusCertificate* certificate) {
  std::size_t crossings = 0, tangencies = 0;
  for (const Node& n : nodes) (n.kind == NodeKind::crossing ? crossings : tangencies)++;
  std::string caption = plot_caption_text(text, analysed, crossings, tangencies, cusps.size());  // svg_plot.hpp
  if (certificate && !certificate->certified)
    caption += " — UNCERTIFIED (root-count census: " + std::to_string(certificate->root_nodes) + ")";
  return caption;
}

inline std::string plot_svg(const TrainText& text, const GearTrain& analysed, const Trajectory<double>& trajectory,
                            const std::vector<Node>& nodes, const std::vector<Cusp>& cusps,
                            const CensusCertificate* certificate, PlotOptions options) {
  options.caption = plot_caption(text, analysed, nodes, cusps, certificate);
  return render_sphere_svg(trajectory, nodes, cusps, options);
}

inline CrossingsSummary crossings_summary(const SelfCrossings& sc, std::size_t vertices, bool closed,
                                          const std::string& input_format, double seconds_read,
                                          double seconds_search) {
  CrossingsSummary s;
  s.vertices = vertices;
  s.closed = closed;
  s.crossings = sc.crossings.size();
  s.touchings = sc.touchings.size();
  s.candidate_pairs = sc.candidate_pairs;
  s.predicates = sc.predicates;
  s.input_format = input_format;
  s.seconds_read = seconds_read;
  s.seconds_search = seconds_search;
  return s;
}

inline CrossingsSummary crossings_summary(const CrossingCounts& c, bool closed, const std::string& input_format,
                                          double seconds_read, double seconds_search) {
  CrossingsSummary s;
  s.vertices = c.vertices;
  s.closed = closed;
  s.crossings = c.crossings;
  s.touchings = c.touchings;
  s.candidate_pairs = c.candidate_pairs;
  s.predicates = c.predicates;
  s.input_format = input_format;
  s.seconds_read = seconds_read;
  s.seconds_search = seconds_search;
  return s;
}

inline nlohmann::json crossings_summary_json(const CrossingsSummary& s) {
  return {{"vertices", s.vertices},           {"closed", s.closed},
          {"crossings", s.crossings},         {"touchings", s.touchings},
          {"candidate_pairs", s.candidate_pairs}, {"predicates", s.predicates},
          {"input_format", s.input_format},   {"seconds_read", s.seconds_read},
          {"seconds_search", s.seconds_search}};
}

inline void write_crossings_summary_text(std::ostream& out, const CrossingsSummary& s) {
  out << "vertices " << s.vertices << (s.closed ? " (closed)" : " (open)") << ", read as " << s.input_format
      << "\ncrossings " << s.crossings << "\ntouchings " << s.touchings << "\ncandidate pairs " << s.candidate_pairs
      << ", exact predicates " << s.predicates << "\nseconds_read " << seconds_text(s.seconds_read)
      << "\nseconds_search " << seconds_text(s.seconds_search) << "\n";
}

}  // namespace sphtroch
