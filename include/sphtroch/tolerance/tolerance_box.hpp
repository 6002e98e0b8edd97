// sphtroch/tolerance/tolerance_box.hpp — the certified answers for a tolerance box about a
// train whose census is given: the margin, the box's topology and each node's and cusp's
// enclosure. Needs CGAL's interval headers only, so the explorer (WebAssembly) computes what
// `sphtroch tolerance` prints (exact/tolerance_output.hpp adds classify's census, Monte Carlo and
// the formats).
//
//   const sphtroch::GearTrain train(1.0, 2.0, sphtroch::Ratio(5, 2));
//   const sphtroch::ToleranceBox box{1e-3, 1e-3, 0.0};
//   sphtroch::check_tolerance_box(train, box);   // InvalidInput naming "da2", "da3" or "dphase"
//   const sphtroch::BoxTolerance t = sphtroch::box_tolerance(train, {}, {}, box);  // no nodes given
//   t.margin.lower;  t.topology.verdict;          // radians; holds | changes | undecided
//
// Contract: `nodes` and `cusps` are the census of `train` (crossing nodes with their two
// parameters, cusps with theirs); the topology of a box that fixes a2 and a3 is `holds` (the
// phase turns the curve about the sun axis: the census cannot change).
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/tolerance/tolerance_box.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/tolerance/node_tolerance.hpp"
#include "sphtroch/tolerance/topology_margin.hpp"
#include "sphtroch/tolerance/tolerance_types.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace sphtroch {




/// The margin, the topology and the enclosures for the box about `train`, whose census is
/// `nodes`, `cusps` (see header). Throws InvalidInput as check_tolerance_box.
inline BoxTolerance box_tolerance(const GearTrain& train, const std::vector<Node>& nodes, const std::vector<Cusp>& cusps,
                                  const ToleranceBox& box) {
  check_tolerance_box(train, box);
  BoxTolerance r;
  r.margin = topology_margin(train);
  r.topology = (box.da2 == 0 && box.da3 == 0) ? BoxTopology{BoxTopology::Verdict::holds, std::nullopt, "", 0}
                                              : box_topology(train, box.da2, box.da3);
  for (const Node& n : nodes) r.nodes.push_back(node_tolerance(train, n, box));
  for (const Cusp& k : cusps) r.cusps.push_back(cusp_tolerance(train, k, box));
  return r;
}

}  // namespace sphtroch
