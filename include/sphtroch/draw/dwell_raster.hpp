// sphtroch/draw/dwell_raster.hpp — where on the sphere the tracer spends its time, as a picture
// sees it: the front half of the sphere cut into square screen cells, each with the share of the
// period the tracer spends in it per steradian of the sphere behind the cell. The density view of
// `sphtroch plot --style density` (svg_plot.hpp), for curves too dense to read as lines (a
// clinostat's n = 133/200 passes 26,602 times through itself). Eigen only.
//
//   using sphtroch::Vector3d;
//   const std::vector<Vector3d> points{{0, 0, 1}, {0, 1, 0}};           // a period, uniform in time
//   const sphtroch::DwellRaster r =
//       sphtroch::dwell_raster(points, Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ(), 48);
//   r.time[r.index(24, 0)];   // 0.5: share of the period in column 24 (from the left), row 0 (the top)
//   r.density(24, 0);         // that share per steradian of the sphere under the cell
//
// Contracts:
//  1. The samples are a closed period uniform in the carrier angle (sample_period), so each carries
//     1/N of the period's time; a sample whose P.view < 0 (back half) is not counted, so the shares
//     sum to the front half's share of the time (1 for a curve wholly in front), exactly up to
//     rounding in the sum.
//  2. The cells tile the square [-1, 1]^2 of screen coordinates (P.right, P.up) in `cells` x
//     `cells`; sample P goes to the cell holding its projection (edges to the higher cell, the
//     last row and column closed).
//  3. density(i, j) = time / (solid angle of the sphere's front half under the cell), the solid
//     angle taken as the cell's screen area over |P.view| at the cell centre (exact to first order
//     in the cell size; cells whose centre lies outside the disc use the smallest |P.view| of the
//     cell's inner corner, bounded below by 1/cells). A uniform dwell over the whole sphere is
//     1/(4 pi) everywhere.
//  4. Cost O(N + cells^2). REQUIRES: unit, finite points; view, right, up orthonormal; cells in
//     [4, 512] (InvalidInput "cells" otherwise).
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace sphtroch {

struct DwellRaster {
  std::size_t cells = 0;     // per side
  std::vector<double> time;  // cells x cells, row-major from the top left: share of the period
  std::size_t index(std::size_t column, std::size_t row) const { return row * cells + column; }
  /// Screen coordinates of the centre of cell (column, row), in units of the radius.
  double centre_x(std::size_t column) const { return -1.0 + (2.0 * static_cast<double>(column) + 1.0) / static_cast<double>(cells); }
  double centre_y(std::size_t row) const { return 1.0 - (2.0 * static_cast<double>(row) + 1.0) / static_cast<double>(cells); }
  /// Share of the period per steradian under cell (column, row) (contract 3).
  double density(std::size_t column, std::size_t row) const;
};

/// The dwell raster of one closed period `points` seen along `view` with screen axes `right`,
/// `up` (header).
inline DwellRaster dwell_raster(const std::vector<Vector3d>& points, const Vector3d& view, const Vector3d& right,
                                const Vector3d& up, std::size_t cells) {
  if (cells < 4 || cells > 512)
    throw InvalidInput("cells", std::to_string(cells), "outside the valid range", "4 .. 512 cells per side");
  DwellRaster r;
  r.cells = cells;
  r.time.assign(cells * cells, 0.0);
  if (points.empty()) return r;
  const double share = 1.0 / static_cast<double>(points.size());
  const double half = 0.5 * static_cast<double>(cells);
  auto cell_of = [&](double coordinate) {
    const double c = std::floor((coordinate + 1.0) * half);
    return static_cast<std::size_t>(std::clamp(c, 0.0, static_cast<double>(cells - 1)));
  };
  for (const Vector3d& p : points) {
    SPHTROCH_ASSERT(std::isfinite(p.norm()), "dwell_raster: finite points");
    if (p.dot(view) < 0) continue;
    r.time[r.index(cell_of(p.dot(right)), cells - 1 - cell_of(p.dot(up)))] += share;
  }
  return r;
}

inline double DwellRaster::density(std::size_t column, std::size_t row) const {
  const double x = centre_x(column), y = centre_y(row), h = 1.0 / static_cast<double>(cells);
  double rho2 = x * x + y * y;
  if (rho2 >= 1.0) {  // the inner corner: the part of the cell on the disc
    const double ix = std::max(0.0, std::fabs(x) - h), iy = std::max(0.0, std::fabs(y) - h);
    rho2 = std::min(1.0, ix * ix + iy * iy);
  }
  const double depth = std::max(std::sqrt(1.0 - rho2), h);
  const double solid_angle = (2 * h) * (2 * h) / depth;
  return time[index(column, row)] / solid_angle;
}

}  // namespace sphtroch
