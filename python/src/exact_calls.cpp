// python/src/exact_calls.cpp — see exact_calls.hpp. The module's one translation unit that
// includes exact/ (CGAL): classify, crossings, tolerance, the inverse design's reports and the
// chain's census all go through here, so the CGAL parse is paid once.
#include "exact_calls.hpp"

#include "sphtroch/exact/classification_output.hpp"

#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/chain/chain_family_events.hpp"
#include "sphtroch/chain/chain_census_output.hpp"
#include "sphtroch/chain/chain_picture.hpp"
#include "sphtroch/exact/chain_classification.hpp"
#include "sphtroch/synthesis.hpp"
#include "sphtroch/exact/scene.hpp"
#include "sphtroch/exact/self_crossings.hpp"
#include "sphtroch/tolerance.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>

namespace sphtroch::python {

namespace {

AnalysisSettings settings_of(bool literal, std::size_t census_samples) {
  AnalysisSettings s;
  s.reading.literal = literal;
  s.census_samples = census_samples;
  return s;
}

}  // namespace

std::string classification_json_text(const TrainText& text, const GearTrain& train, bool literal,
                                      std::size_t census_samples) {
  const Analysis a(train, settings_of(literal, census_samples));  // as `sphtroch classify` runs it
  return classification_json(text, a.classification()).dump();
}

std::string chain_classification_json_text(const RotationChain& chain) {
  return chain_census_json(chain, classify_chain(chain)).dump();
}

std::string chain_classification_report_text(const RotationChain& chain) { return chain_census_text(chain, classify_chain(chain)); }

std::string chain_boundaries_json_text(const RotationChain& chain, const std::string& vary) {
  std::ostringstream out;
  write_chain_events_json(out, chain, chain_family_events(chain, parse_chain_vary(vary, chain.size())));
  return out.str();
}

std::string chain_plot_svg_text(const RotationChain& chain, const PlotOptions& options, const ChainText& typed) {
  return chain_picture_svg(chain, classify_chain(chain), options, &typed);
}

std::string tolerance_json_text(const TrainText& text, const GearTrain& train, double da2, double da3, double dphase,
                                std::size_t samples, std::uint64_t seed, const ParallelProgress& progress) {
  if (samples > 0) check_monte_carlo_cost(train, ToleranceBox{da2, da3, dphase}, samples);  // refused up front
  ToleranceReport r = tolerance_report(train, ToleranceBox{da2, da3, dphase});
  if (samples > 0) run_monte_carlo(r, samples, seed, progress);
  return tolerance_json(text, r).dump();
}

std::string topology_margin_json_text(const GearTrain& train) { return topology_margin_json(topology_margin(train)).dump(); }

std::string classification_report_text(const TrainText& text, const GearTrain& train, bool literal,
                                       std::size_t census_samples) {
  const Analysis a(train, settings_of(literal, census_samples));  // as `sphtroch classify` runs it
  std::ostringstream out;
  write_classification_text(out, text, a.classification());
  return out.str();
}

std::string scene_json_text(const std::string& scene_text) {
  nlohmann::ordered_json trains = nlohmann::ordered_json::array();
  for (const SceneTrain& st : parse_scene(scene_text, "scene")) {
    const Analysis a(st.train, st.settings);
    nlohmann::ordered_json outputs = nlohmann::ordered_json::object();
    for (const SceneEffect& e : st.effects) {
      std::ostringstream out;
      write_scene_effect(out, st, a, e);  // the bytes `sphtroch scene` writes to e.path
      outputs[to_string(e.effect)] = out.str();
    }
    trains.push_back({{"name", st.name},
                      {"outputs", std::move(outputs)},
                      {"uncertified", scene_uncertified(st, a)},  // "" or why (the CLI's exit 3)
                      {"explanation", scene_explanation_json(st, a)}});
  }
  return nlohmann::ordered_json{{"trains", std::move(trains)}}.dump();
}

std::string plot_svg_text(const TrainText& text, const GearTrain& train, bool literal, std::size_t census_samples,
                          const PlotOptions& options) {
  const Analysis a(train, settings_of(literal, census_samples));  // as `sphtroch plot` runs it
  return plot_svg(text, a.analysed(), a.plot_trajectory(), a.nodes(), a.cusps(), &a.certificate(), options);
}

std::string nodes_and_cusps_json_text(const TrainText& text, const GearTrain& train, bool literal,
                                      std::size_t census_samples) {
  const Analysis a(train, settings_of(literal, census_samples));  // as `sphtroch nodes` runs it
  // The printer of `classify --json` on a classification holding only these two stages: the
  // node and cusp objects are then exactly those of the full report.
  Classification c(train, a.snapped());
  c.literal = literal;
  c.nodes = a.nodes();
  c.cusps = a.cusps();
  const nlohmann::json j = classification_json(text, c);
  const CensusCertificate& cert = a.certificate();  // the nodes are certified or say so (issue 17)
  return nlohmann::json{{"nodes", j["nodes"]},
                        {"cusps", j["cusps"]},
                        {"certified", cert.certified},
                        {"polyline_nodes", cert.polyline_nodes.back()},
                        {"root_nodes", cert.root_nodes},
                        {"stopped", cert.stopped}}
      .dump();
}

std::string precision_points_report(const std::vector<Vector3d>& points, const std::vector<Ratio>& ratios,
                                    const std::string& json_fields, const TeethSpec& teeth, bool free_axis,
                                    std::size_t threads, bool text, const ParallelProgress& progress) {
  PrecisionPointsOptions options;
  options.threads = threads;
  // One ratio at a time (the library's loop over the ratios, each independent of the others), so
  // that progress is reported between them.
  std::vector<RatioPrecisionPoints> all;
  if (progress) progress(0, ratios.size());
  for (const Ratio& n : ratios) {
    for (RatioPrecisionPoints& r : precision_points_with_census(points, {n}, options, free_axis)) all.push_back(std::move(r));
    if (progress) progress(all.size(), ratios.size());
  }
  return text ? precision_points_text(all, teeth) : precision_points_json(all, json_fields, teeth);
}

std::string fit_report(const std::vector<Vector3d>& points, const std::vector<Ratio>& ratios, const FitOptions& options,
                       const std::string& json_fields, const TeethSpec& teeth, bool text, const ParallelProgress& progress) {
  check_fit_cost(points.size(), ratios);  // the whole set's bound, as fit_with_census checks it
  std::vector<RatioFit> all;  // one ratio at a time, as for precision_points_report
  if (progress) progress(0, ratios.size());
  for (const Ratio& n : ratios) {
    for (RatioFit& r : fit_with_census(points, {n}, options)) all.push_back(std::move(r));
    if (progress) progress(all.size(), ratios.size());
  }
  return text ? fit_text(all, options, teeth) : fit_json(all, options, json_fields, teeth);
}

std::string root_classification_json_text(const GearTrain& train, bool literal) {
  return root_classification_json(classify_roots(train, Reading{literal})).dump();
}

std::string contact_name(std::uint8_t kind) { return std::string(to_string(static_cast<ArcContact>(kind))); }

CrossingsResult self_crossings(const double* xyz, std::size_t n, bool closed, bool with_pairs, std::size_t max_crossings,
                               std::size_t max_work) {
  const VertexSpan vertices(reinterpret_cast<const Eigen::Vector3d*>(xyz), n);
  CrossingSearchOptions options;
  options.max_contacts = max_crossings;
  options.max_work = max_work;
  std::vector<EdgePair> all;
  CrossingCounts c;
  const auto start = std::chrono::steady_clock::now();
  try {
    c = with_pairs ? visit_self_crossings(vertices, closed, [&all](const EdgePair& e) { all.push_back(e); }, options)
                   : count_self_crossings(vertices, closed, options);
  } catch (const InvalidInput& e) {  // the library names its argument "vertices"; Python's is "points"
    throw InvalidInput("points", e.value(), e.problem(), e.valid_range());
  }
  check_search_complete(c, options, "max_crossings", "max_work");
  CrossingsResult r;
  r.seconds_search = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.vertices = n;
  r.crossings = c.crossings;
  r.touchings = c.touchings;
  r.candidate_pairs = c.candidate_pairs;
  r.predicates = c.predicates;
  std::sort(all.begin(), all.end());  // as `sphtroch crossings --pairs` lists them, sorted
  r.pairs.reserve(2 * all.size());
  r.kinds.reserve(all.size());
  for (const EdgePair& e : all) {
    r.pairs.push_back(static_cast<std::int64_t>(e.i));
    r.pairs.push_back(static_cast<std::int64_t>(e.j));
    r.kinds.push_back(static_cast<std::uint8_t>(e.kind));
  }
  return r;
}

}  // namespace sphtroch::python
