// sphtroch/exact/chain_census_output.hpp — the chain census (census/interval/chain_census.hpp) as
// JSON, as text and as a picture, for `sphtroch chain classify|plot` (and every front end that
// reports a chain).
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   const sphtroch::ChainCensus c = sphtroch::chain_census(chain);
//   nlohmann::json j = sphtroch::chain_census_json(chain, c);   // the schema below
//   std::string t = sphtroch::chain_census_text(chain, c);      // for people
//   const sphtroch::ChainCurve<double> curve(chain);
//   const std::size_t n = sphtroch::chain_plot_sample_count(chain);
//   std::string svg = sphtroch::chain_plot_svg(chain, sphtroch::sample(curve, sphtroch::UniformSampling<double>{curve.period(), n, n, true}), c);
//
// JSON: "chain" {"twists", "rates" (exact, "p/q"), "phases" (as reduced), "period" (2 pi L / g),
// "curve_period" (the census's: shorter when coaxial joints make the curve repeat)}; "class"
// ("unknown" when not certified);
// "certified"; "certificate" {"method", "why", "arcs", "arc_pairs", "boxes", "undecided",
// "cusp_resolution", "cusp_zone"}; "counts" {"nodes", "cusps", "crossings", "tangencies"}; "nodes"
// and "cusps" in the schema of `sphtroch classify --json` (classification_output.hpp), with
// params and param values of the motor parameter s.
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT) && \
    !(defined(SPHTROCH_EXACT_WITHOUT_GMP) && defined(CGAL_NO_GMP) && CGAL_NO_GMP)
#error "sphtroch/exact/chain_census_output.hpp needs CGAL: link the CMake target sphtroch::exact"
#endif

#include "sphtroch/census/interval/chain_census.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/exact/classification_output.hpp"

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace sphtroch {

inline nlohmann::json chain_json(const RotationChain& chain, const ChainCensus& c) {
  nlohmann::json twists = nlohmann::json::array(), rates = nlohmann::json::array(), phases = nlohmann::json::array();
  for (const ChainStage& s : chain.stages()) {
    twists.push_back(s.twist);
    rates.push_back(s.rate.str());
    phases.push_back(s.phase);
  }
  return {{"twists", twists}, {"rates", rates}, {"phases", phases}, {"period", chain.period()}, {"curve_period", c.period}};
}

/// The curve's class (classification.hpp's names) when the census is certified; "unknown" when it
/// is not (a census stopped early has not found every node: its list is not a class).
inline std::string chain_class_text(const ChainCensus& c) {
  return c.certified ? to_string(curve_class(c.nodes.size(), c.cusps.size())) : "unknown";
}

inline nlohmann::json chain_census_json(const RotationChain& chain, const ChainCensus& c) {
  nlohmann::json j;
  j["chain"] = chain_json(chain, c);
  j["class"] = chain_class_text(c);
  j["certified"] = c.certified;
  j["certificate"] = {{"method", c.method},
                      {"why", c.why},
                      {"arcs", c.arcs},
                      {"arc_pairs", c.arc_pairs},
                      {"boxes", c.boxes},
                      {"undecided", c.undecided},
                      {"cusp_resolution", kChainCuspResolution},
                      {"cusp_zone", c.cusp_zone}};
  std::size_t crossings = 0;
  for (const Node& n : c.nodes) crossings += n.kind == NodeKind::crossing ? 1 : 0;
  j["counts"] = {{"nodes", c.nodes.size()}, {"cusps", c.cusps.size()}, {"crossings", crossings}, {"tangencies", c.nodes.size() - crossings}};
  j["nodes"] = node_list_json(c.nodes);
  j["cusps"] = cusp_list_json(c.cusps);
  return j;
}

inline std::string chain_census_text(const RotationChain& chain, const ChainCensus& c) {
  std::ostringstream out;
  out << "chain: " << chain.size() << " stages, rates " << chain.rates_text() << ", period " << number_text(chain.period());
  if (c.period != chain.period()) out << " (the curve repeats after " << number_text(c.period) << ")";
  out << "\nclass: " << chain_class_text(c)
      << (c.certified ? " (certified)" : " (NOT certified: " + c.why + ")") << "\nnodes: " << c.nodes.size() << "\n";
  std::size_t id = 0;
  for (const Node& n : c.nodes) {
    out << "  N" << ++id << "  (" << number_text(n.position.x()) << ", " << number_text(n.position.y()) << ", "
        << number_text(n.position.z()) << ")  " << n.branches << " branches, s =";
    for (const double p : n.params) out << ' ' << number_text(p);
    out << '\n';
  }
  out << "cusps: " << c.cusps.size() << " (within " << number_text(kChainCuspResolution) << " sum |N_i| of zero speed)\n";
  id = 0;
  for (const Cusp& k : c.cusps)
    out << "  C" << ++id << "  (" << number_text(k.position.x()) << ", " << number_text(k.position.y()) << ", "
        << number_text(k.position.z()) << ")  s = " << number_text(k.param) << '\n';
  return out.str();
}

/// The caption of `chain plot`: "twists A1,..,Ak, rates N1,..,Nk[, phases ..] — N node(s)
/// (C crossing, T tangency), K cusp(s)", the twists and phases as shortest round-trip doubles,
/// the phases shown when one is not 0; " — NOT CERTIFIED: why" when the census is not certified.
inline std::string chain_plot_caption(const RotationChain& chain, const ChainCensus& c) {
  std::string twists, phases;
  bool any_phase = false;
  for (const ChainStage& s : chain.stages()) {
    twists += (twists.empty() ? "" : ",") + number_text(s.twist);
    phases += (phases.empty() ? "" : ",") + number_text(s.phase);
    any_phase = any_phase || s.phase != 0.0;
  }
  std::size_t crossings = 0;
  for (const Node& n : c.nodes) crossings += n.kind == NodeKind::crossing ? 1 : 0;
  std::string caption = "twists " + twists + ", rates " + chain.rates_text() + (any_phase ? ", phases " + phases : "") + " — " +
                        std::to_string(c.nodes.size()) + " node(s)";
  if (!c.nodes.empty())
    caption += " (" + std::to_string(crossings) + " crossing, " + std::to_string(c.nodes.size() - crossings) + " tangency)";
  caption += ", " + std::to_string(c.cusps.size()) + " cusp(s)";
  return c.certified ? caption : caption + " — NOT CERTIFIED: " + c.why;
}

/// `chain plot`: the sphere picture (draw/svg_plot.hpp) of `trajectory` (the chain's curve) with
/// the census's nodes and cusps and chain_plot_caption, drawn with `options` (its caption replaced).
inline std::string chain_plot_svg(const RotationChain& chain, const Trajectory<double>& trajectory, const ChainCensus& c,
                                  PlotOptions options = {}) {
  options.caption = chain_plot_caption(chain, c);
  return render_sphere_svg(trajectory, c.nodes, c.cusps, options);
}

}  // namespace sphtroch
