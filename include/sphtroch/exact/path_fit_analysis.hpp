// sphtroch/exact/path_fit_analysis.hpp — the definition of fit_with_census() (path_fit_output.hpp
// declares it): fit_path for each ratio, then classify() and the certified topology_margin() of
// every candidate (interval arithmetic). <sphtroch/synthesis.hpp> includes it unless
// SPHTROCH_SEPARATE_EXACT is defined; exact_implementation.hpp instantiates it for
// sphtroch::compiled.
//
//   const sphtroch::GearTrain hidden(1.1, 0.9, sphtroch::Ratio(2), 0.4);
//   const auto points = sphtroch::sample_period(sphtroch::TracerCurve<double>(hidden), 200).points;
//   sphtroch::FitOptions o;  o.nodes = 2;
//   auto fits = sphtroch::fit_with_census(points, {sphtroch::Ratio(2)}, o);
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/path_fit_analysis.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact"
#endif

#include "sphtroch/exact/analysis.hpp"  // classify()'s definition
#include "sphtroch/exact/path_fit_output.hpp"
#include "sphtroch/tolerance/topology_margin.hpp"

#include <type_traits>
#include <utility>
#include <vector>

namespace sphtroch {

template <typename Options>
std::vector<RatioFit> fit_with_census(const std::vector<Vector3d>& points, const std::vector<Ratio>& ratios,
                                      const Options& options) {
  static_assert(std::is_same_v<Options, FitOptions>, "fit_with_census takes FitOptions");
  std::vector<RatioFit> all;
  // A few more than wanted, so that a candidate the census does not confirm leaves room for the next.
  check_fit_cost(points.size(), ratios);
  FitOptions more = options;
  more.max_candidates = options.max_candidates + kFitSpareCandidates;
  for (const Ratio& n : ratios) {
    PathFit f = fit_path(points, n, more);
    RatioFit rf{n, {}, f.reason, 0};
    for (FitCandidate& c : f.candidates) {
      if (rf.candidates.size() == options.max_candidates) break;
      Classification census = classify(c.train);
      if (options.node_at) c.node_distance = census_node_distance(census, *options.node_at);
      const bool node_held = !options.node_at || (census.certified() && c.node_distance <= options.node_tolerance);
      if (!(census_confirms(census, options) && node_held)) {
        ++rf.dropped;
        continue;
      }
      TopologyMargin margin = topology_margin(census.snapped.train);
      if (options.min_margin > 0 && !(margin.lower >= options.min_margin && square_in_range(census.snapped.train, options.min_margin))) {
        ++rf.dropped;
        ++rf.too_near;
        continue;
      }
      rf.candidates.push_back({std::move(c), std::move(census), std::move(margin)});
    }
    if (rf.candidates.empty() && rf.reason.empty() && rf.dropped > 0)
      rf.reason = "n = " + n.str() + ": " +
                  (rf.too_near == rf.dropped ? "every candidate lies nearer than --min-margin " + number_text(options.min_margin) +
                                                   " rad to a change of its census or to the end of the range (0, pi) (" +
                                                   std::to_string(rf.dropped) + " candidate(s))"
                                             : "the census (classify) did not confirm the wanted counts (or node point) of any of " +
                                                   std::to_string(rf.dropped) + " candidate(s)" +
                                                   (rf.too_near ? " (" + std::to_string(rf.too_near) + " nearer than --min-margin)" : ""));
    all.push_back(std::move(rf));
  }
  return all;
}

}  // namespace sphtroch
