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

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace sphtroch {

/// The largest phase half-width (a whole turn).
constexpr double kMaxPhaseTolerance = 6.283185307179586;

/// Throws InvalidInput naming fields[k] unless each half-width is finite and >= 0, the box's a2 and
/// a3 stay in [kMinCarrierTwist, pi - kMinCarrierTwist] and dphase <= kMaxPhaseTolerance.
inline void check_tolerance_box(const GearTrain& train, const ToleranceBox& box,
                                const std::array<std::string, 3>& fields = {"da2", "da3", "dphase"}) {
  const double lo = kMinCarrierTwist, hi = Constants<double>::pi() - kMinCarrierTwist;
  const std::string twist = "a half-width >= 0 radians that keeps the angle in [1e-6, pi - 1e-6]";
  auto check = [&](double d, double centre, const std::string& field) {
    if (!(std::isfinite(d) && d >= 0)) throw InvalidInput(field, number_text(d), "not a finite half-width >= 0", twist);
    if (!(centre - d >= lo && centre + d <= hi))
      throw InvalidInput(field, number_text(d), "the box leaves the trains' range (" + number_text(centre - d) + " .. " +
                                                    number_text(centre + d) + ")", twist);
  };
  check(box.da2, train.a2(), fields[0]);
  check(box.da3, train.a3(), fields[1]);
  if (!(std::isfinite(box.dphase) && box.dphase >= 0 && box.dphase <= kMaxPhaseTolerance))
    throw InvalidInput(fields[2], number_text(box.dphase), "outside the valid range", "a half-width in [0, 2 pi] radians");
}

/// What is proved about a tolerance box (see header).
struct BoxTolerance {
  TopologyMargin margin;
  BoxTopology topology;
  std::vector<NodeTolerance> nodes, cusps;  // in the order of the census given
};

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
