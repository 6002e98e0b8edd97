// sphtroch/wrist/wrist_sphere_grid.hpp — a grid of the unit sphere in latitude bands for the
// regions of a wrist's fold atlas (wrist_regions.hpp): cells with exact areas, a cap that holds
// each cell, edge neighbours, the cell of a direction, and the cells a cap may meet.
//
//   const sphtroch::WristSphereGrid grid(0.05);           // cells about 0.05 rad on a side
//   const std::size_t c = grid.cell_of(sphtroch::Vector3d(0.6, 0, 0.8));
//   grid.area(c);                                         // steradians, exact up to rounding
//   grid.neighbours(c);                                   // the cells sharing an edge with c
//
// Layout: R = ceil(pi / step) rows of equal polar angle h = pi / R; row i holds the polar angles
// [i h, (i + 1) h] and M_i = max(4, ceil(2 pi s_i / h)) cells of equal azimuth [2 pi j / M_i,
// 2 pi (j + 1) / M_i] (s_i the largest sin over the row), so every cell is at most about h on a
// side. A cell's area is (phi_1 - phi_0)(cos theta_0 - cos theta_1) sr.
// The cap: centre the direction at the middle polar angle and azimuth; radius the largest angle
// from it to the cell's four corners plus kWristGridMargin. Why that holds the cell: for a point
// at azimuth offset d from the centre, c . p = sin t_c sin t cos d + cos t_c cos t is least at the
// largest |d| (sin >= 0 on [0, pi]); on that meridian (|d| <= pi / 4 < pi / 2 since M_i >= 4) it is
// R cos(t - t0) with t0 in [0, pi], least at an end of any polar range: at a corner.
// Neighbours: the two cells beside it in its row (cyclic) and the cells of the rows above and below
// whose azimuth ranges overlap its own in an interval of positive length (exact integer tests), so
// the union of two neighbours is connected. Cells are indexed row by row from the north pole.
// Cost: about 4 R^2 / pi cells; the caller bounds R (wrist_regions.hpp refuses large grids).
#pragma once

#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace sphtroch {

/// Radians added to every cap radius: covers the rounding of the doubles computing it (~1e-15).
constexpr double kWristGridMargin = 1e-12;

class WristSphereGrid {
 public:
  /// REQUIRES 1e-4 <= step <= 1 (radians; the caller checks).
  explicit WristSphereGrid(double step) {
    const double pi = Constants<double>::pi();
    rows_ = static_cast<std::size_t>(std::ceil(pi / step));
    h_ = pi / static_cast<double>(rows_);
    first_.push_back(0);
    for (std::size_t i = 0; i < rows_; ++i) {
      const double t0 = h_ * static_cast<double>(i), t1 = h_ * static_cast<double>(i + 1);
      const double s = (t0 <= pi / 2 && t1 >= pi / 2) ? 1.0 : std::max(std::sin(t0), std::sin(t1));
      columns_.push_back(std::max<std::size_t>(4, static_cast<std::size_t>(std::ceil(2 * pi * s / h_))));
      first_.push_back(first_.back() + columns_.back());
    }
  }

  /// The number of cells a grid of this step has (the cost bound's measure), without building it.
  static double cells_for(double step) {
    const double rows = std::ceil(Constants<double>::pi() / step);
    return 4.0 * rows * rows / Constants<double>::pi() + 8.0 * rows;
  }

  std::size_t size() const noexcept { return first_.back(); }
  std::size_t rows() const noexcept { return rows_; }
  std::size_t columns(std::size_t row) const { return columns_[row]; }
  std::size_t index(std::size_t row, std::size_t column) const { return first_[row] + column; }
  /// The polar angle step h (radians).
  double step() const noexcept { return h_; }
  std::size_t row_of(std::size_t cell) const {
    return static_cast<std::size_t>(std::upper_bound(first_.begin(), first_.end(), cell) - first_.begin()) - 1;
  }

  /// {theta_0, theta_1, phi_0, phi_1} of the cell (radians).
  std::array<double, 4> bounds(std::size_t cell) const {
    const std::size_t i = row_of(cell), j = cell - first_[i];
    const double m = static_cast<double>(columns_[i]), two_pi = 2 * Constants<double>::pi();
    return {h_ * static_cast<double>(i), h_ * static_cast<double>(i + 1), two_pi * static_cast<double>(j) / m,
            two_pi * static_cast<double>(j + 1) / m};
  }

  static Vector3d direction(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  }
  /// The cell's centre: the direction at its middle polar angle and azimuth (inside the cell).
  Vector3d centre(std::size_t cell) const {
    const std::array<double, 4> b = bounds(cell);
    return direction((b[0] + b[1]) / 2, (b[2] + b[3]) / 2);
  }
  /// Steradians: (phi_1 - phi_0)(cos theta_0 - cos theta_1).
  double area(std::size_t cell) const {
    const std::array<double, 4> b = bounds(cell);
    return (b[3] - b[2]) * (std::cos(b[0]) - std::cos(b[1]));
  }
  /// The angle (radians) from centre(cell) to every point of the cell is at most this (see header).
  double cap_radius(std::size_t cell) const {
    const std::array<double, 4> b = bounds(cell);
    const Vector3d c = centre(cell);
    double r = 0;
    for (const double t : {b[0], b[1]})
      for (const double p : {b[2], b[3]}) r = std::max(r, angle(c, direction(t, p)));
    return r + kWristGridMargin;
  }

  /// The cell holding the direction d (not 0): by its polar angle and azimuth. A direction on an
  /// edge (within rounding) gets one of the cells it touches.
  std::size_t cell_of(const Vector3d& d) const {
    const double pi = Constants<double>::pi();
    const double theta = std::atan2(std::hypot(d.x(), d.y()), d.z());
    double phi = std::atan2(d.y(), d.x());
    if (phi < 0) phi += 2 * pi;
    const std::size_t i = std::min(rows_ - 1, static_cast<std::size_t>(std::max(0.0, theta / h_)));
    const std::size_t j = std::min(columns_[i] - 1, static_cast<std::size_t>(phi / (2 * pi) * static_cast<double>(columns_[i])));
    return index(i, j);
  }

  /// The cells sharing an edge of positive length with `cell` (see header).
  std::vector<std::size_t> neighbours(std::size_t cell) const {
    const std::size_t i = row_of(cell), j = cell - first_[i], m = columns_[i];
    std::vector<std::size_t> out{index(i, (j + 1) % m), index(i, (j + m - 1) % m)};
    for (const std::size_t r : {i - 1, i + 1}) {
      if (r >= rows_) continue;  // i - 1 wraps round to a huge value at the north pole
      const std::size_t n = columns_[r];
      for (std::size_t k = j * n / m; k * m < (j + 1) * n; ++k)
        if ((k + 1) * m > j * n) out.push_back(index(r, k));
    }
    return out;
  }

  /// Every cell that may meet the cap of centre c (unit) and radius r (radians, < pi / 2): the rows
  /// whose polar range meets [t_c - r, t_c + r], in each the azimuths within asin(sin r / sin t_c)
  /// of c's (all of them when the cap holds a pole), widened by kWristGridMargin.
  template <typename Visit>
  void for_cells_near(const Vector3d& c, double r, Visit&& visit) const {
    const double pi = Constants<double>::pi(), two_pi = 2 * pi;
    const double tc = std::atan2(std::hypot(c.x(), c.y()), c.z()), rr = r + kWristGridMargin;
    double pc = std::atan2(c.y(), c.x());
    if (pc < 0) pc += two_pi;
    const std::size_t i0 = static_cast<std::size_t>(std::max(0.0, std::floor((tc - rr) / h_)));
    const std::size_t i1 = std::min(rows_ - 1, static_cast<std::size_t>(std::max(0.0, std::floor((tc + rr) / h_))));
    const bool pole = tc - rr <= 0 || tc + rr >= pi;
    const double half = pole ? pi : std::asin(std::min(1.0, std::sin(rr) / std::sin(tc))) + kWristGridMargin;
    for (std::size_t i = i0; i <= i1; ++i) {
      const std::size_t m = columns_[i];
      if (pole || half >= pi) {
        for (std::size_t j = 0; j < m; ++j) visit(index(i, j));
        continue;
      }
      const double per = two_pi / static_cast<double>(m);
      const long lo = static_cast<long>(std::floor((pc - half) / per)), hi = static_cast<long>(std::floor((pc + half) / per));
      for (long k = lo; k <= hi && k < lo + static_cast<long>(m); ++k)
        visit(index(i, static_cast<std::size_t>(((k % static_cast<long>(m)) + static_cast<long>(m)) % static_cast<long>(m))));
    }
  }

  /// The angle between two directions, atan2(|a x b|, a . b) (radians, within ~1e-16 relative).
  static double angle(const Vector3d& a, const Vector3d& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

 private:
  std::size_t rows_ = 0;
  double h_ = 0;
  std::vector<std::size_t> columns_, first_;
};

}  // namespace sphtroch
