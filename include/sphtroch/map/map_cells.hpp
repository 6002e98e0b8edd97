// sphtroch/map/map_cells.hpp — the cells of the (a2, a3) design map along one a2 (the a3 intervals
// between consecutive boundary events, each with its node count) and a train's distance to the
// nearest boundary of the map. Eigen only; built on the boundary set (boundary_events.hpp).
//
//   std::vector<sphtroch::MapCell> cells = sphtroch::map_cells(1.1, sphtroch::Ratio(2));
//   cells.front().lo;  cells.back().hi;  cells[0].nodes;     // 0 .. pi, the node count of each
//   double m = sphtroch::map_margin(1.1, 0.9, sphtroch::Ratio(2));   // radians in the (a2, a3) plane
//
// map_margin is first order: for each event of the boundary set at the train's a2, its a3 distance
// times the cosine of the boundary's slope (from the boundary set at a2 + 1e-4, or a2 - 1e-4 at the
// top of the range), the nearest of them. An upper estimate: a boundary that does not cross this a2
// (a tangency locus's fold just beyond it) is not seen. With no event at a2, the distance to the
// ends of the a3 range.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/map/boundary_events.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace sphtroch {

/// One cell of the map along an a2: a3 in (lo, hi), where the curve has `nodes` node points.
struct MapCell {
  double lo, hi;
  std::int64_t nodes;
};

/// The cells along a2, ascending from a3 = 0 to pi (one cell when no event lies at a2). Throws
/// InvalidInput naming "a2" outside (0, pi) (boundary_set).
inline std::vector<MapCell> map_cells(double a2, const Ratio& n) {
  const double pi = Constants<double>::pi();
  const BoundarySet b = boundary_set(a2, n);
  std::vector<MapCell> cells;
  double lo = 0;
  std::int64_t count = b.events.empty() ? node_count_off_events(a2, pi / 2, n) : b.events.front().nodes_below;
  for (std::size_t k = 0; k <= b.events.size(); ++k) {
    const double hi = k < b.events.size() ? b.events[k].a3 : pi;
    cells.push_back({lo, hi, count});
    if (k < b.events.size()) {
      count = b.events[k].nodes_above;
      lo = hi;
    }
  }
  return cells;
}

/// Distance in the (a2, a3) plane to the nearest boundary of the map (see header); `on_cone`: the
/// train lies on a pitch cone by design, which is not counted. Throws InvalidInput naming "a2" or
/// "a3" outside (0, pi).
inline double map_margin(double a2, double a3, const Ratio& n, bool on_cone = false) {
  const double pi = Constants<double>::pi();
  if (!(a3 > 0 && a3 < pi)) throw InvalidInput("a3", report_number(a3), "outside the valid range", "(0, pi) radians");
  const double h = a2 + 1e-4 < pi - 1e-6 ? 1e-4 : -1e-4;
  const BoundarySet here = boundary_set(a2, n), near = boundary_set(a2 + h, n);
  double margin = std::numeric_limits<double>::infinity();
  for (const BoundaryEvent& e : here.events) {
    if (on_cone && e.kind == BoundaryEventKind::pitch_cone && std::abs(e.a3 - a3) < 1e-9) continue;
    double slope = 0, nearest = 0.05;
    for (const BoundaryEvent& f : near.events)
      if (f.kind == e.kind && f.name == e.name && std::abs(f.a3 - e.a3) < nearest) {
        nearest = std::abs(f.a3 - e.a3);
        slope = (f.a3 - e.a3) / h;
      }
    margin = std::min(margin, std::abs(a3 - e.a3) / std::sqrt(1 + slope * slope));
  }
  return std::isfinite(margin) ? margin : std::min(a3, pi - a3);
}

}  // namespace sphtroch
