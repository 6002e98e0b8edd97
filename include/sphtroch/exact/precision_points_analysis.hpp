// sphtroch/exact/precision_points_analysis.hpp — the definition of precision_points_with_census()
// (precision_points_output.hpp declares it): the certified searches of synthesis/ (interval
// arithmetic), then classify() and topology_margin() of every train found. <sphtroch/synthesis.hpp>
// includes it unless SPHTROCH_SEPARATE_EXACT is defined; exact_implementation.hpp instantiates it
// for sphtroch::compiled.
//
//   const sphtroch::TracerCurve<double> curve(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(1, 2), 0.3));
//   std::vector<sphtroch::Vector3d> pts = {curve.point(0.5), curve.point(2.0), curve.point(7.0)};
//   auto all = sphtroch::precision_points_with_census(pts, {sphtroch::Ratio(1, 2)});
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/precision_points_analysis.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact"
#endif

#include "sphtroch/exact/analysis.hpp"  // classify()'s definition
#include "sphtroch/exact/precision_points_output.hpp"
#include "sphtroch/synthesis/free_axis_points.hpp"
#include "sphtroch/synthesis/precision_points.hpp"
#include "sphtroch/tolerance/topology_margin.hpp"

#include <type_traits>
#include <utility>
#include <vector>

namespace sphtroch {

template <typename Options>
std::vector<RatioPrecisionPoints> precision_points_with_census(const std::vector<Vector3d>& points, const std::vector<Ratio>& ratios,
                                                               const Options& options, bool free_axis) {
  static_assert(std::is_same_v<Options, PrecisionPointsOptions>, "precision_points_with_census takes PrecisionPointsOptions");
  std::vector<RatioPrecisionPoints> all;
  for (const Ratio& n : ratios) {
    RatioPrecisionPoints rs{n, free_axis ? free_axis_points(points, n, options) : precision_points(points, n, options), {}, {},
                            free_axis};
    for (const auto& s : rs.result.solutions) {
      rs.census.push_back(classify(s.train));
      rs.margins.push_back(topology_margin(s.train));
    }
    all.push_back(std::move(rs));
  }
  return all;
}

}  // namespace sphtroch
