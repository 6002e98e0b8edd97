// sphtroch/chain/chain_census_output.hpp — the chain census (chain/chain_census.hpp) as
// JSON and as text, for `sphtroch chain classify` (and every front end that reports a chain); the
// picture is chain/chain_picture.hpp's.
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   const sphtroch::ChainCensus c = sphtroch::chain_census(chain);
//   nlohmann::json j = sphtroch::chain_census_json(chain, c);   // the schema below
//   std::string t = sphtroch::chain_census_text(chain, c);      // for people: the chain as read, then the census
//
// JSON: "chain" {"twists", "rates" (exact, "p/q"), "phases" (as reduced), "period" (2 pi L / g),
// "curve_period" (the census's: shorter when coaxial joints make the curve repeat)}; "class"
// ("unknown" when not certified);
// "certified"; "certificate" {"method", "why", "arcs", "arc_pairs", "boxes", "undecided",
// "cusp_resolution", "cusp_zone"}; "counts" {"nodes", "cusps", "crossings", "tangencies"}; "nodes"
// and "cusps" in the schema of `sphtroch classify --json` (classification_output.hpp), with
// params and param values of the motor parameter s.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_census_output.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/census/node_json.hpp"
#include "sphtroch/chain/chain_census.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/number_text.hpp"

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

/// The stages' twists or phases (radians) as a person reads them and --twists / --phases take
/// them: "1.5707963267948966,0.4".
inline std::string chain_angles_text(const RotationChain& chain, double ChainStage::*angle) {
  std::string t;
  for (const ChainStage& s : chain.stages()) t += (t.empty() ? "" : ",") + report_number(s.*angle);
  return t;
}

/// The census for people: a header with the chain as read (its stages, rates, period, twists
/// and phases: what a chain read from a URDF turned into), the class, the nodes and the cusps.
inline std::string chain_census_text(const RotationChain& chain, const ChainCensus& c) {
  std::ostringstream out;
  out << "chain: " << chain.size() << " stages, rates " << chain.rates_text() << ", period " << report_number(chain.period());
  if (c.period != chain.period()) out << " (the curve repeats after " << report_number(c.period) << ")";
  out << "\ntwists: " << chain_angles_text(chain, &ChainStage::twist) << " rad\nphases: " << chain_angles_text(chain, &ChainStage::phase)
      << " rad\nclass: " << chain_class_text(c)
      << (c.certified ? " (certified)" : " (NOT certified: " + c.why + ")") << "\nnodes: " << c.nodes.size() << "\n";
  std::size_t id = 0;
  for (const Node& n : c.nodes) {
    out << "  N" << ++id << "  (" << report_number(n.position.x()) << ", " << report_number(n.position.y()) << ", "
        << report_number(n.position.z()) << ")  " << n.branches << " branches, s =";
    for (const double p : n.params) out << ' ' << report_number(p);
    out << '\n';
  }
  out << "cusps: " << c.cusps.size() << " (within " << report_number(kChainCuspResolution) << " sum |N_i| of zero speed)\n";
  id = 0;
  for (const Cusp& k : c.cusps)
    out << "  C" << ++id << "  (" << report_number(k.position.x()) << ", " << report_number(k.position.y()) << ", "
        << report_number(k.position.z()) << ")  s = " << report_number(k.param) << '\n';
  return out.str();
}

}  // namespace sphtroch
