// Tests of sphtroch/exact/classification_output.hpp: the classification JSON parsed back and checked against the
// Classification's fields and the report's equations computed HERE (cone angle, period, z
// extremes of Eq. 4, Table 1 node counts); the text report, the plot caption and the crossings
// summary read back against the formats stated in the header. No expected text is copied from
// the code's output.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/classify.hpp"
#include "sphtroch/exact/classification_output.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace sphtroch;
using nlohmann::json;

namespace {

const double kPi = Constants<double>::pi();


std::size_t count_prefix(const std::vector<std::string>& l, const std::string& prefix) {
  std::size_t k = 0;
  for (const auto& s : l) k += s.rfind(prefix, 0) == 0;
  return k;
}

Vector3d vec(const json& j) {
  REQUIRE(j.size() == 3);
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

/// Table 1 row (f): a2 = pi/3, a3 = pi/2, n = 2: four nodes, no cusp.
struct Fig5f {
  TrainText text{"pi/3", "pi/2", "2"};
  Classification c = classify(text.train());
};

const Fig5f& fig5f() {
  static const Fig5f f;
  return f;
}

}  // namespace

TEST_CASE("classification json: the documented keys, inputs as typed, values of the Classification") {
  const Fig5f& f = fig5f();
  const json j = json::parse(classification_json(f.text, f.c).dump(2));  // through text: what a reader sees
  std::set<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.insert(k);
  CHECK(keys == std::set<std::string>{"inputs", "cone_angles", "period", "class", "counts", "nodes", "cusps",
                                      "cusp_within_resolution", "boundaries", "z_extremes", "nearest_event", "margin", "dwell_points",
                                      "symmetry", "analytic", "censuses", "agreement", "certified", "certificate", "tolerances", "work"});
  // Fig. 5(f), a3 = pi/2: the nearest events are the pole passages a3 = a2 = pi/3 and a3 = pi - a2
  // (Table 1's boundaries), pi/6 away on either side; the count is 4 between them.
  CHECK(j["nearest_event"]["kind"] == "pole");
  CHECK(std::fabs(std::fabs(j["nearest_event"]["margin"].get<double>()) - kPi / 6) < 1e-15);
  CHECK((j["nearest_event"]["nodes_above"] == 4 || j["nearest_event"]["nodes_below"] == 4));
  // In both twists: both pole lines are pi/12 away in L-infinity ((a3 - a2)/2, (pi - a2 - a3)/2);
  // the pitch cones stay below a_p <= asin(1/2) = pi/6 for n = 2, and n = 2 has no tangency locus.
  CHECK(j["margin"]["lower"].get<double>() <= kPi / 12);
  CHECK(j["margin"]["upper"].get<double>() >= kPi / 12);
  CHECK(j["margin"]["upper"].get<double>() - j["margin"]["lower"].get<double>() <= 1e-6 * kPi / 12);
  CHECK(j["margin"]["nearest"]["kind"] == "pole");
  CHECK(j["certified"] == true);  // both censuses find Table 1 row (f)'s 4 nodes
  CHECK(j["certificate"]["root_count_nodes"] == 4);
  CHECK(j["certificate"]["polyline_runs"].size() >= 1);
  CHECK(j["certificate"]["polyline_runs"].back()["nodes"] == 4);
  CHECK(j["certificate"]["stopped"] == "");
  CHECK(j["inputs"]["a2_text"] == "pi/3");
  CHECK(j["inputs"]["a3_text"] == "pi/2");
  CHECK(j["inputs"]["a2"].get<double>() == kPi / 3);
  CHECK(j["inputs"]["n"] == "2");
  CHECK(j["inputs"]["n_value"].get<double>() == 2.0);
  CHECK(j["inputs"]["literal"] == false);
  // docs/design.md: a_p = atan2(sin a2, cos a2 + n), a_s = a2 - a_p; period 2 pi q.
  const double ap = std::atan2(std::sin(kPi / 3), std::cos(kPi / 3) + 2.0);
  CHECK(j["cone_angles"]["a_p"].get<double>() == Approx(ap).epsilon(1e-14));
  CHECK(j["cone_angles"]["a_s"].get<double>() == Approx(kPi / 3 - ap).epsilon(1e-14));
  CHECK(j["period"].get<double>() == Approx(2 * kPi).epsilon(1e-15));
  CHECK(j["class"] == "nodes");
  CHECK(j["counts"]["nodes"] == 4);  // Table 1 row (f)
  CHECK(j["counts"]["cusps"] == 0);
  CHECK(j["counts"]["crossings"].get<std::size_t>() + j["counts"]["tangencies"].get<std::size_t>() == 4);
  CHECK(j["agreement"]["ok"] == true);
  CHECK(j["agreement"]["notes"].empty());
  CHECK(j["analytic"]["predicted_nodes"] == 4);  // Eqs. 43/46 apply for n = 2
  CHECK(j["tolerances"]["boundary"].get<double>() == f.c.snapped.tolerance);
  CHECK(j["tolerances"]["cusp_resolution"].get<double>() == kCuspResolution);
  CHECK(j["work"]["points_evaluated"].get<std::size_t>() == f.c.work.points_evaluated);
}

TEST_CASE("classification json: node positions round-trip exactly, longitude, latitude from them") {
  const Fig5f& f = fig5f();
  const json j = json::parse(classification_json(f.text, f.c).dump());
  REQUIRE(j["nodes"].size() == f.c.nodes.size());
  for (std::size_t k = 0; k < f.c.nodes.size(); ++k) {
    const json& n = j["nodes"][k];
    const Vector3d p = vec(n["position"]);
    CHECK(p == f.c.nodes[k].position);  // every digit
    CHECK(p.norm() == Approx(1.0).epsilon(1e-14));
    CHECK(n["longitude"].get<double>() == std::atan2(p.y(), p.x()));
    CHECK(n["latitude"].get<double>() == std::asin(p.z()));
    CHECK(n["params"].size() == n["branches"].get<std::size_t>());
    CHECK((n["kind"] == "crossing" || n["kind"] == "tangency"));
  }
}

TEST_CASE("z extremes json: z_max = cos(a2 - a3), z_min = cos(a2 + a3) (Eq. 4), |p| points each") {
  const Fig5f& f = fig5f();
  const json z = json::parse(z_extremes_json(f.c.z).dump());
  const double a2 = kPi / 3, a3 = kPi / 2;
  CHECK(z["z_max"].get<double>() == Approx(std::cos(a2 - a3)).epsilon(1e-14));
  CHECK(z["z_min"].get<double>() == Approx(std::cos(a2 + a3)).epsilon(1e-14));
  REQUIRE(z["maxima"].size() == 2);  // |p| = 2
  REQUIRE(z["minima"].size() == 2);
  for (const json& m : z["maxima"]) CHECK(vec(m["position"]).z() == Approx(std::cos(a2 - a3)).margin(1e-12));
  for (const json& m : z["minima"]) CHECK(vec(m["position"]).z() == Approx(std::cos(a2 + a3)).margin(1e-12));
}

TEST_CASE("classification text: the inputs as typed with their values, one line per node and per cusp") {
  const Fig5f& f = fig5f();
  std::ostringstream out;
  write_classification_text(out, f.text, f.c);
  const auto l = sphtroch::test::split_lines(out.str());
  const std::string a2_line = "  a2 = pi/3 = " + number_text(kPi / 3) + " rad (" + number_text(kPi / 3 * 180.0 / kPi) + " deg)";
  CHECK(std::count(l.begin(), l.end(), a2_line) == 1);
  CHECK(count_prefix(l, "  node ") == 4);
  CHECK(count_prefix(l, "  cusp ") == 0);
  CHECK(count_prefix(l, "class: nodes") == 1);
  CHECK(count_prefix(l, "    DISAGREEMENT: ") == f.c.agreement.notes.size());
  CHECK(count_prefix(l, "  agreement: yes") == 1);
  REQUIRE(count_prefix(l, "work: ") == 1);
  CHECK(l.back().rfind("work: " + std::to_string(f.c.work.points_evaluated) + " points evaluated", 0) == 0);
}

TEST_CASE("classification: a cardioid (tracer on the pitch cone, n = 1) reports its cusp in both forms") {
  const TrainText text{"pi/2", "ap", "1"};
  const Classification c = classify(text.train());
  REQUIRE(c.cusps.size() == 1);
  const json j = json::parse(classification_json(text, c).dump());
  REQUIRE(j["cusps"].size() == 1);
  CHECK(vec(j["cusps"][0]["position"]) == c.cusps[0].position);
  CHECK(j["cusps"][0]["speed"].get<double>() < 1e-12);  // zero velocity, up to rounding
  CHECK(j["inputs"]["a3_text"] == "ap");
  std::ostringstream out;
  write_classification_text(out, text, c);
  CHECK(count_prefix(sphtroch::test::split_lines(out.str()), "  cusp 1: at ") == 1);
}

TEST_CASE("plot caption: the texts as typed, the phase only when not 0, the counts") {
  const Fig5f& f = fig5f();
  std::size_t crossings = 0;
  for (const Node& n : f.c.nodes) crossings += n.kind == NodeKind::crossing;
  const std::string cap = plot_caption(f.text, f.c.snapped.train, f.c.nodes, f.c.cusps);
  CHECK(cap.rfind("a2 = pi/3, a3 = pi/2, n = 2 — 4 node(s) (", 0) == 0);
  CHECK(cap.find(std::to_string(crossings) + " crossing, " + std::to_string(4 - crossings) + " tangency") != std::string::npos);
  CHECK(cap.find("phase") == std::string::npos);
  const TrainText phased{"pi/3", "pi/2", "2", "pi/4"};
  const GearTrain t = phased.train();
  CHECK(plot_caption(phased, t, {}, {}) == "a2 = pi/3, a3 = pi/2, n = 2, phase = pi/4 — 0 node(s), 0 cusp(s)");
  const std::string svg = plot_svg(f.text, f.c.snapped.train, sample_period(TracerCurve<double>(f.c.snapped.train), 64),
                                   f.c.nodes, f.c.cusps);
  CHECK(svg.find("<svg") != std::string::npos);
  CHECK(svg.find("a2 = pi/3, a3 = pi/2, n = 2") != std::string::npos);  // the caption is in the picture
}

TEST_CASE("crossings summary: the search's counts under their names, as JSON and as text") {
  SelfCrossings sc;
  sc.crossings = {EdgePair{0, 5, ArcContact::crossing}, EdgePair{1, 7, ArcContact::crossing}};
  sc.touchings = {EdgePair{2, 9, ArcContact::touching}};
  sc.candidate_pairs = 11;
  sc.predicates = 44;
  const CrossingsSummary s = crossings_summary(sc, 12, false, "npy <f8 (12, 3)", 0.25, 0.5);
  const json j = json::parse(crossings_summary_json(s).dump());
  CHECK(j.size() == 9);
  CHECK(j["vertices"] == 12);
  CHECK(j["closed"] == false);
  CHECK(j["crossings"] == 2);
  CHECK(j["touchings"] == 1);
  CHECK(j["candidate_pairs"] == 11);
  CHECK(j["predicates"] == 44);
  CHECK(j["input_format"] == "npy <f8 (12, 3)");
  CHECK(j["seconds_read"].get<double>() == 0.25);
  CHECK(j["seconds_search"].get<double>() == 0.5);
  std::ostringstream out;
  write_crossings_summary_text(out, s);
  const auto l = sphtroch::test::split_lines(out.str());
  REQUIRE(l.size() == 6);
  CHECK(l[0] == "vertices 12 (open), read as npy <f8 (12, 3)");
  CHECK(l[1] == "crossings 2");
  CHECK(l[2] == "touchings 1");
  CHECK(l[3] == "candidate pairs 11, exact predicates 44");
  CHECK(l[4] == "seconds_read 0.25");
  CHECK(l[5] == "seconds_search 0.5");
}

TEST_CASE("root classification json: the fields of classify_roots, node points in the schema of classify's nodes") {
  const double pi = sphtroch::Constants<double>::pi();
  const sphtroch::GearTrain fig5f(pi / 3, pi / 2, sphtroch::Ratio(2));  // Fig. 5(f): 4 crossing nodes
  const sphtroch::RootClassification r = sphtroch::classify_roots(fig5f);
  const nlohmann::json j = sphtroch::root_classification_json(r);
  for (const char* key : {"a2", "a3", "boundaries", "class", "nodes", "crossings", "tangencies", "cusps", "analytic_nodes",
                          "analytic_cusps", "agrees_with_report", "node_points"})
    CHECK(j.contains(key));
  CHECK(j.size() == 12);
  CHECK(j["nodes"] == 4);
  CHECK(j["analytic_nodes"] == 4);
  CHECK(j["class"] == "nodes");
  CHECK(j["agrees_with_report"] == true);
  // One node schema: the keys of classify()'s nodes (the full classification, another route).
  const nlohmann::json full = sphtroch::classification_json(sphtroch::TrainText{"pi/3", "pi/2", "2"}, sphtroch::classify(fig5f));
  REQUIRE(j["node_points"].size() == r.node_points.size());
  for (std::size_t k = 0; k < r.node_points.size(); ++k) {
    const nlohmann::json& n = j["node_points"][k];
    for (const auto& item : full["nodes"][0].items()) CHECK(n.contains(item.key()));
    CHECK(n.size() == full["nodes"][0].size());
    const Eigen::Vector3d& p = r.node_points[k].position;
    CHECK(n["position"] == nlohmann::json::array({p.x(), p.y(), p.z()}));
    CHECK(n["longitude"].get<double>() == std::atan2(p.y(), p.x()));
    CHECK(n["kind"] == "crossing");
  }
  // No report count for n != 1, 2: null.
  CHECK(sphtroch::root_classification_json(sphtroch::classify_roots(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(7, 3))))["analytic_nodes"].is_null());
}
