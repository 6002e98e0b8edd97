// explorer/wasm_census.cpp — the census of one train (classify: the root census, fast enough for
// every slider step) and its certificate (certify: the rule of `sphtroch classify`,
// exact/certified_census.hpp, compiled without GMP: see explorer/CMakeLists.txt).
#include "wasm_common.hpp"

#include "sphtroch/core/curve.hpp"
#include "sphtroch/exact/certified_census.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/extremes_and_symmetry.hpp"

namespace sphtroch::wasm {

PageCensus page_census(const GearTrain& t) {
  return {snap_to_boundaries(t, Reading{}.boundary()).train, classify_roots(t)};
}

namespace {

/// The certificate of `sphtroch classify` for the analysed train: certified_census (the polyline
/// census against root_census, escalated while they disagree) at the CLI's default settings (the
/// default reading's tangency tolerance, the default samples), as exact/analysis.hpp runs it.
/// When certified, the root census's nodes (PageCensus::roots) are the certified ones: the
/// censuses agree node for node, kind and branches included (census/node_sets.hpp).
CensusCertificate page_certificate(const PageCensus& census) {
  const Reading reading;
  return certified_census(census.analysed, polyline_census_settings(reading), root_census(census.analysed, root_census_settings(reading)))
      .certificate;
}

}  // namespace

bool page_certified(const PageCensus& census) { return page_certificate(census).certified; }

namespace {

val string_list(const std::vector<std::string>& items) {
  val out = val::array();
  for (const std::string& s : items) out.call<void>("push", s);
  return out;
}

val node_positions(const std::vector<Node>& nodes) {
  std::vector<double> xyz;
  for (const Node& node : nodes) xyz.insert(xyz.end(), node.position.data(), node.position.data() + 3);
  return float64_array(xyz);
}

val node_list(const std::vector<Node>& nodes) {
  val out = val::array();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Node& node = nodes[i];
    val item = val::object();
    item.set("id", static_cast<double>(i + 1));
    item.set("kind", std::string(to_string(node.kind)));
    item.set("x", node.position.x());
    item.set("y", node.position.y());
    item.set("z", node.position.z());
    item.set("params", float64_array(node.params));
    out.call<void>("push", item);
  }
  return out;
}

val criteria_list(const std::vector<Criterion>& criteria) {
  val out = val::array();
  for (const Criterion& c : criteria) {
    val item = val::object();
    item.set("equation", c.equation);
    item.set("statement", c.statement);
    item.set("status", std::string(to_string(c.status)));
    item.set("lowerMargin", c.lower_margin);
    item.set("upperMargin", c.upper_margin);
    item.set("prediction", c.prediction);
    out.call<void>("push", item);
  }
  return out;
}

/// The class, counts and node points of one train by the root census (PageCensus): fast enough
/// for every slider step, not certified (certify() is).
val classify(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
             const std::string& teeth) {
  return guarded([&] {
    const GearTrain t = train_text(a2, a3, n, phase, teeth).train();
    const PageCensus census = page_census(t);
    const RootClassification& c = census.roots;
    const ZExtremes z = z_extremes(t);
    const AnalyticClassification a = classify_analytic(t);
    val out = train_object(t);
    out.set("class", std::string(to_string(c.curve_class)));
    out.set("nodes", static_cast<double>(c.nodes));
    out.set("crossings", static_cast<double>(c.crossings));
    out.set("tangencies", static_cast<double>(c.tangencies));
    out.set("cusps", static_cast<double>(c.cusps));
    out.set("readOn", string_list(c.boundaries));
    out.set("nodePoints", node_list(c.node_points));
    out.set("nodePositions", node_positions(c.node_points));
    // The cusps where classify_roots finds them: on the train read onto its boundaries.
    std::vector<double> cusp_xyz;
    for (const AnalyticCusp& cusp : pitch_cone_cusps(census.analysed, kCuspResolution))
      cusp_xyz.insert(cusp_xyz.end(), cusp.position.data(), cusp.position.data() + 3);
    out.set("cuspPositions", float64_array(cusp_xyz));
    out.set("zMax", z.z_max);
    out.set("zMin", z.z_min);
    out.set("criteria", criteria_list(a.criteria));
    out.set("reportClass", a.curve_class);
    return out;
  });
}

/// The certificate of classify()'s count (page_certificate: the CLI's rule): {certified, rootNodes,
/// runs: [{samples, nodes}] (each polyline census run: uniform samples, node count), stopped (why
/// escalation stopped, "" when certified), disagreement (the last run's first difference)}.
val certify(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
            const std::string& teeth) {
  return guarded([&] {
    const CensusCertificate cert = page_certificate(page_census(train_text(a2, a3, n, phase, teeth).train()));
    val runs = val::array();
    for (std::size_t i = 0; i < cert.runs(); ++i) {
      val run = val::object();
      run.set("samples", static_cast<double>(cert.samples[i]));
      run.set("nodes", static_cast<double>(cert.polyline_nodes[i]));
      runs.call<void>("push", run);
    }
    val out = val::object();
    out.set("certified", cert.certified);
    out.set("rootNodes", static_cast<double>(cert.root_nodes));
    out.set("runs", runs);
    out.set("stopped", cert.stopped);
    out.set("disagreement", cert.disagreement);
    return out;
  });
}

}  // namespace

void register_census() {
  emscripten::function("classify", &classify);
  emscripten::function("certify", &certify);
}

}  // namespace sphtroch::wasm
