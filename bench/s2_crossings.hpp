// bench/s2_crossings.hpp — the crossing count of a spherical polyline through Google S2, for the
// benchmark's comparison (study e). Built only when S2 (Debian libs2-dev) is found.
//
//   std::vector<EdgeIndexPair> pairs = s2_interior_crossings(vertices, /*closed=*/true);
//
// S2 (0.10.0): one S2LaxClosedPolylineShape (or S2LaxPolylineShape when open) in a
// MutableS2ShapeIndex, s2shapeutil::VisitCrossingEdgePairs with CrossingType::INTERIOR (crossings
// interior to both edges; S2 decides them with exact predicates and symbolic perturbation). The
// visitor may see a pair more than once, so the pairs are sorted and made unique. The vertices are
// normalised to unit length first (S2Point must be unit length). The index is built inside this
// call (ForceBuild), so timing this call includes building the index.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace sphtroch_bench {

struct EdgeIndexPair {
  std::uint32_t i = 0;  // i < j
  std::uint32_t j = 0;
};

/// Every pair of edges (i < j) of the polyline whose interiors cross, according to S2.
std::vector<EdgeIndexPair> s2_interior_crossings(const std::vector<Eigen::Vector3d>& vertices, bool closed);

}  // namespace sphtroch_bench
