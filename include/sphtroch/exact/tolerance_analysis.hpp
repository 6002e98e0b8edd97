// sphtroch/exact/tolerance_analysis.hpp — the definition of tolerance_report()
// (tolerance_output.hpp declares it): classify's census, then the interval proofs of
// tolerance/tolerance_box.hpp (the margin, the box's topology, each node's enclosure). Included by
// tolerance_output.hpp unless SPHTROCH_SEPARATE_EXACT is defined; exact_implementation.hpp
// instantiates it for sphtroch::compiled.
//
//   #include <sphtroch/exact/tolerance_analysis.hpp>   // needs sphtroch::exact (CGAL)
//   const sphtroch::GearTrain train(1.0, 2.0, sphtroch::Ratio(5, 2));
//   const sphtroch::ToleranceReport r = sphtroch::tolerance_report(train, sphtroch::ToleranceBox{1e-3, 1e-3, 0.0});
//   r.topology.verdict;   // holds | changes | undecided
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/tolerance_analysis.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact"
#endif

#include "sphtroch/exact/analysis.hpp"  // classify()'s definition
#include "sphtroch/exact/tolerance_output.hpp"
#include "sphtroch/tolerance/tolerance_box.hpp"

#include <type_traits>
#include <utility>

namespace sphtroch {

template <typename Box>
ToleranceReport tolerance_report(const GearTrain& train, const Box& box) {
  static_assert(std::is_same_v<Box, ToleranceBox>, "tolerance_report takes a ToleranceBox");
  check_tolerance_box(train, box);
  const Classification c = classify(train);
  ToleranceReport r;
  r.train = c.snapped.train;
  r.box = box;
  check_tolerance_box(r.train, box);
  r.node_count = c.nodes.size();
  r.cusp_count = c.cusps.size();
  r.census_certified = c.certificate.certified;
  BoxTolerance proved = box_tolerance(r.train, c.nodes, c.cusps, box);
  r.margin = std::move(proved.margin);
  r.topology = std::move(proved.topology);
  r.nodes = std::move(proved.nodes);
  r.cusps = std::move(proved.cusps);
  return r;
}

}  // namespace sphtroch
