// sphtroch/exact/chain_classification.hpp — the census every front end reports for a rotation
// chain (`sphtroch chain classify|nodes|plot`, Python's Chain.classify).
// A k = 2 chain with both rates not 0 is the gear train gear_train_of(chain)
// (core/rotation_chain.hpp): its nodes and cusps are the train's (Analysis: `sphtroch classify`'s
// root and polyline censuses, tangencies included), their parameters mapped to s in [0, period).
// The chain census (chain/chain_census.hpp) of the train Analysis analyses (twists
// snapped onto a boundary within 1e-10, as classify reads them) runs beside them as a third
// census, with a tenth of the box budget (a check: a tangency's boxes may stay undecided); a
// certified chain census that disagrees leaves the answer not certified.
// Every other chain: chain_census(chain).
// Cost: Analysis's (classify's) for k = 2, chain_census's bound otherwise.
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   const sphtroch::ChainCensus c = sphtroch::classify_chain(chain);  // the gear train's census
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT) && \
    !(defined(SPHTROCH_EXACT_WITHOUT_GMP) && defined(CGAL_NO_GMP) && CGAL_NO_GMP)
#error "sphtroch/exact/chain_classification.hpp needs CGAL: link the CMake target sphtroch::exact"
#endif

#include "sphtroch/chain/chain_census.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/exact/analysis.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

namespace chain_classification_detail {

/// The chain with its first two twists replaced by the analysed train's (snapped) twists.
inline RotationChain analysed_chain(const RotationChain& chain, const GearTrain& analysed) {
  std::vector<ChainStage> stages = chain.stages();
  stages[0].twist = analysed.a2();
  stages[1].twist = analysed.a3();
  return RotationChain(stages);
}

/// The k = 2 census from the gear train's censuses, checked by the chain census (see top).
inline ChainCensus train_census(const RotationChain& chain, const GearTrain& train) {
  const Analysis a(train);
  const RotationChain analysed = analysed_chain(chain, a.analysed());
  if (!(chain_census_arcs(analysed) <= static_cast<double>(kMaxChainArcs)))
    (void)chain_census(analysed);  // refused up front (InvalidInput "rates"), before either census works
  (void)a.nodes();  // the train's censuses next: what they refuse (their cost) is refused before the check runs
  const ChainCensus check = chain_census(analysed, kMaxChainBoxes / 10);
  const auto to_s = [&](double theta2) { return reduce_param(chain_param_of_theta2(chain, theta2), check.period); };
  ChainCensus c = check;
  c.multiple_unproved = c.touching_unproved = false;  // the train's census decides them (the report's criteria)
  c.method = "the gear train's root and polyline censuses (classify), checked by the chain census";
  c.nodes = a.nodes();
  for (Node& n : c.nodes) {
    for (double& t : n.params) t = to_s(t);
    std::sort(n.params.begin(), n.params.end());
  }
  c.cusps = a.cusps();
  for (Cusp& k : c.cusps) k.param = to_s(k.param);
  c.certified = a.certificate().certified;
  c.why = c.certified ? "" : "the gear train's censuses disagree: " + a.certificate().disagreement;
  if (c.certified && check.certified && (check.nodes.size() != c.nodes.size() || check.cusps.size() != c.cusps.size())) {
    c.certified = false;
    c.why = "the chain census finds " + std::to_string(check.nodes.size()) + " nodes and " + std::to_string(check.cusps.size()) +
            " cusps, the gear train's " + std::to_string(c.nodes.size()) + " and " + std::to_string(c.cusps.size());
  }
  return c;
}

}  // namespace chain_classification_detail

/// The chain's certified census (see top). Throws InvalidInput("rates") when the chain census
/// refuses the chain up front (too many arcs), ("twists") or ("rates") for what the gear
/// train's censuses refuse (a first twist near 0 with a large denominator: their cost).
inline ChainCensus classify_chain(const RotationChain& chain) {
  const std::optional<GearTrain> train = gear_train_of(chain);
  if (!train) return chain_census(chain);
  try {
    return chain_classification_detail::train_census(chain, *train);
  } catch (const InvalidInput& e) {  // the train's refusals (a2: its first twist; n: its rates) named as the chain's options
    if (e.field() == "a2") throw InvalidInput("twists", chain.twists_text(), e.problem(), "a larger first twist, or rates whose ratio has a smaller denominator");
    if (e.field() == "n") throw InvalidInput("rates", chain.rates_text(), e.problem(), e.valid_range());
    throw;
  }
}

}  // namespace sphtroch
