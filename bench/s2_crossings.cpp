// bench/s2_crossings.cpp — see s2_crossings.hpp. The only translation unit that includes S2.
#include "s2_crossings.hpp"

#include <s2/mutable_s2shape_index.h>
#include <s2/s2crossing_edge_query.h>
#include <s2/s2lax_loop_shape.h>
#include <s2/s2lax_polyline_shape.h>
#include <s2/s2point.h>
#include <s2/s2shapeutil_visit_crossing_edge_pairs.h>

#include <algorithm>
#include <memory>

namespace sphtroch_bench {

std::vector<EdgeIndexPair> s2_interior_crossings(const std::vector<Eigen::Vector3d>& vertices, bool closed) {
  std::vector<S2Point> points;
  points.reserve(vertices.size());
  for (const Eigen::Vector3d& v : vertices) points.push_back(S2Point(v.x(), v.y(), v.z()).Normalize());
  MutableS2ShapeIndex index;
  if (closed)
    index.Add(std::make_unique<S2LaxClosedPolylineShape>(points));
  else
    index.Add(std::make_unique<S2LaxPolylineShape>(points));
  index.ForceBuild();
  std::vector<EdgeIndexPair> pairs;
  s2shapeutil::VisitCrossingEdgePairs(
      index, s2shapeutil::CrossingType::INTERIOR,
      [&pairs](const s2shapeutil::ShapeEdge& a, const s2shapeutil::ShapeEdge& b, bool /*is_interior*/) {
        const auto ea = static_cast<std::uint32_t>(a.id().edge_id), eb = static_cast<std::uint32_t>(b.id().edge_id);
        pairs.push_back({std::min(ea, eb), std::max(ea, eb)});
        return true;
      });
  std::sort(pairs.begin(), pairs.end(),
            [](const EdgeIndexPair& x, const EdgeIndexPair& y) { return x.i != y.i ? x.i < y.i : x.j < y.j; });
  pairs.erase(std::unique(pairs.begin(), pairs.end(),
                          [](const EdgeIndexPair& x, const EdgeIndexPair& y) { return x.i == y.i && x.j == y.j; }),
              pairs.end());
  return pairs;
}

}  // namespace sphtroch_bench
