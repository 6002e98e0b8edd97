// sphtroch/wrist/wrist_regions.hpp — the regions of the sphere that a 2-motor wrist's folds cut
// out (from its fold atlas, wrist_atlas.hpp), each with its certified number of IK solutions; the
// workspace (count > 0) and its voids (count 0).
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   const sphtroch::WristAtlasResult atlas = sphtroch::wrist_fold_atlas(wrist, 0.05);
//   const sphtroch::WristRegionsResult r = sphtroch::wrist_regions(wrist, atlas, 0.02);
//   r.regions.front().count;   // 4 = 2 |p| in the zone cos 1.5 < z < cos 0.5; the caps have 0
//
// The argument. (1) Every u with D(u) = 0 lies in a cell B of the atlas (when it is `complete`), so
// the fold set {P(u) : D(u) = 0} lies in the union of the images P(B). (2) P(B) lies in the cap of
// centre P(c) (c the middle of B, P in doubles, ~1e-15) and radius sum_j h_j sup_B |omega_j| (h_j
// the half-widths, |omega_j| enclosed by wrist_enclosure.hpp, at most sum_i |C_ij|) plus 1e-12: the
// path c + s (u - c) moves P at angular speed |sum_j (u_j - c_j) omega_j x P| <= sum_j h_j |omega_j|,
// and the angle is at most the path's length. (3) The sphere is cut into the cells of
// wrist_sphere_grid.hpp, each held by a cap of its own; a cell is clean when its cap is farther than
// the sum of radii plus 1e-9 rad from every fold cap (the grid's for_cells_near finds the cells each
// fold cap may meet): a clean cell meets no fold. (4) Clean cells sharing an edge form a connected
// union that meets no fold (flood fill): off the fold set the number of solutions is locally
// constant (P is proper on the compact torus; a regular value has a neighbourhood of constant
// count), so it is one number on each component: wrist_ik's certified count at one cell's centre.
// Components are the regions; two components of equal count that touch only through fold-band cells
// stay separate (the true region may join them). A region's area is its cells' (a lower bound of
// the true region's); the band's area is reported apart, no count is claimed there.
// Checks (a failure: not certified, named in `why`): (a) parity: every regular value has a count of
// the degree's parity, so all counts must have one parity; (b) the +-2 rule: from each region cell,
// runs of at most kWristCrossingRun band cells along its row (to the east) and to the row below
// that end in a cell of another region are crossings; a generic fold changes the count by 2, so
// the difference must be even and at most 2 s (s the strands: the groups of edge- or
// corner-adjacent atlas cells, modulo the periods, whose caps meet the run).
// A crossing with |delta| = 2 is counted in crossings_by_two; the pairs of regions are checked once.
// Cost: refused (InvalidInput "sphere-cell") when the grid has more than kMaxWristRegionCells
// cells or the step is outside [kWristRegionsMinStep, 0.5]; a wrist_ik per region (a few ms to
// tens of ms each, on `threads` workers); after kMaxWristRegionCounts regions the rest stay
// uncounted (not certified).
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_regions.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_atlas_result.hpp"
#include "sphtroch/wrist/wrist_enclosure.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_regions_checks.hpp"
#include "sphtroch/wrist/wrist_regions_result.hpp"
#include "sphtroch/wrist/wrist_sphere_grid.hpp"
#include "sphtroch/wrist/wrist_target.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// The sphere grid's default step and the range accepted (radians).
constexpr double kWristRegionsDefaultStep = 0.02;
constexpr double kWristRegionsMinStep = 3e-3;
/// Grids of more cells are refused up front (about 80 bytes of memory per cell, and a cap test or
/// two: 2e6 cells about 160 MB).
constexpr double kMaxWristRegionCells = 2e6;
/// Regions counted at most (a wrist_ik each); the rest stay uncounted.
constexpr std::size_t kMaxWristRegionCounts = 2000;
/// Radians between a clean cell's cap and every fold cap, beyond the rounding of their centres.
constexpr double kWristCleanMargin = 1e-9;

/// Refuses (InvalidInput "sphere-cell") a step outside [kWristRegionsMinStep, 0.5] or a grid above kMaxWristRegionCells.
inline void check_wrist_regions_cost(double step) {
  const std::string valid = "radians per sphere cell, 0.003 to 0.5 (default 0.02): at most 2e+06 cells, about 4 pi / step^2";
  if (!(step >= kWristRegionsMinStep && step <= 0.5)) throw InvalidInput("sphere-cell", number_text(step), "outside [0.003, 0.5]", valid);
  const double cells = WristSphereGrid::cells_for(step);
  if (cells > kMaxWristRegionCells)
    throw InvalidInput("sphere-cell", number_text(step), "too costly: the sphere grid needs " + number_text(std::round(cells)) + " cells", valid);
}

/// A cap holding the image P(B) of an atlas cell: centre (unit), radius (radians).
struct WristFoldCap {
  Vector3d centre;
  double radius = 0;
};

/// The caps of every atlas cell's image (see header, (2)). In the caller's rounding mode.
inline std::vector<WristFoldCap> wrist_fold_caps(const Wrist& wrist, const WristAtlasResult& atlas) {
  const RoundingGuard upward;
  const WristEnclosure enclosure(wrist);
  std::vector<WristFoldCap> caps;
  for (std::size_t i = 0; i < atlas.cells.size(); ++i) {
    const auto& m = atlas.cells[i].motors;
    const std::array<Interval, 2> box{Interval(m[0][0], m[0][1]), Interval(m[1][0], m[1][1])};
    const WristPose<Interval> pose = enclosure.pose<2>(box);
    WristFoldCap cap;
    double radius = 0;
    for (std::size_t j = 0; j < 2; ++j) {
      const double c = mid(box[j]);
      const double half = std::max(c - m[j][0], m[j][1] - c);  // rounded up
      Interval norm2(0.0);
      for (int x = 0; x < 3; ++x) norm2 += CGAL::square(pose.omega[j][x]);
      const double speed = std::min(CGAL::sqrt(norm2).sup(), wrist.joint_speed(j) * (1 + 1e-12));
      radius += half * speed;
    }
    cap.radius = radius + 1e-12;
    const RoundingGuard nearest(CGAL_FE_TONEAREST);  // P(c) in doubles to ~1e-15, well inside the 1e-12
    cap.centre = wrist.point<double>({mid(box[0]), mid(box[1])}).normalized();
    caps.push_back(cap);
  }
  return caps;
}

namespace wrist_regions_detail {

/// Marks every grid cell that may meet a fold cap; the atlas cells whose caps meet each marked cell.
inline void mark_band(const WristSphereGrid& grid, const std::vector<WristFoldCap>& caps, std::vector<char>& band,
                      std::vector<std::vector<std::size_t>>& meets) {
  const std::size_t n = grid.size();
  std::vector<Vector3d> centre(n);
  std::vector<double> radius(n);
  for (std::size_t c = 0; c < n; ++c) centre[c] = grid.centre(c), radius[c] = grid.cap_radius(c);
  band.assign(n, 0);
  meets.assign(n, {});
  for (std::size_t i = 0; i < caps.size(); ++i) {
    const WristFoldCap& f = caps[i];
    grid.for_cells_near(f.centre, f.radius, [&](std::size_t c) {
      if (WristSphereGrid::angle(centre[c], f.centre) > radius[c] + f.radius + kWristCleanMargin) return;
      band[c] = 1;
      meets[c].push_back(i);
    });
  }
}

/// Flood fill over clean cells through shared edges: each cell's component, or -1 in the band.
inline std::vector<long> components(const WristSphereGrid& grid, const std::vector<char>& band, std::size_t& count) {
  std::vector<long> label(grid.size(), -1);
  count = 0;
  std::vector<std::size_t> stack;
  for (std::size_t s = 0; s < grid.size(); ++s) {
    if (band[s] || label[s] >= 0) continue;
    label[s] = static_cast<long>(count);
    stack.push_back(s);
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      for (const std::size_t nb : grid.neighbours(c))
        if (!band[nb] && label[nb] < 0) label[nb] = static_cast<long>(count), stack.push_back(nb);
    }
    ++count;
  }
  return label;
}

/// Cells to try for a region's count: those whose neighbours are all in it first (away from the band).
inline std::vector<std::size_t> count_points(const WristSphereGrid& grid, const std::vector<long>& label, const std::vector<std::size_t>& cells) {
  std::vector<std::size_t> inner, edge;
  for (const std::size_t c : cells) {
    const std::vector<std::size_t> nb = grid.neighbours(c);
    const bool all = std::all_of(nb.begin(), nb.end(), [&](std::size_t x) { return label[x] == label[c]; });
    (all ? inner : edge).push_back(c);
    if (inner.size() >= 3) break;
  }
  inner.insert(inner.end(), edge.begin(), edge.end());
  if (inner.size() > 3) inner.resize(3);
  return inner;
}

/// wrist_ik at the centre of up to three of the region's cells until one is certified.
inline void count_region(const Wrist& wrist, const WristSphereGrid& grid, const std::vector<std::size_t>& tries, WristRegion& region) {
  for (const std::size_t c : tries) {
    const Vector3d p = grid.centre(c);
    const WristIkResult ik = wrist_ik(wrist, WristTarget::pointing(p));
    region.ik_boxes += ik.boxes;
    region.point = {p.x(), p.y(), p.z()};
    if (!ik.certified) continue;
    region.count = ik.solutions.size();
    region.counted = true;
    return;
  }
}

}  // namespace wrist_regions_detail

/// The regions of the wrist's fold atlas on a sphere grid of `step` radians (see header); the
/// counts on `threads` worker threads (the result does not depend on it). REQUIRES 2 motors;
/// refuses (check_wrist_regions_cost) a step outside its range or a grid above the bound. In the
/// caller's rounding mode.
inline WristRegionsResult wrist_regions(const Wrist& wrist, const WristAtlasResult& atlas, double step = kWristRegionsDefaultStep,
                                        std::size_t threads = 1) {
  namespace d = wrist_regions_detail;
  check_wrist_regions_cost(step);
  WristRegionsResult r;
  r.grid = WristSphereGrid(step);
  const std::vector<WristFoldCap> caps = wrist_fold_caps(wrist, atlas);
  for (const WristFoldCap& f : caps) r.fold_radius = std::max(r.fold_radius, f.radius);
  std::vector<char> band;
  std::vector<std::vector<std::size_t>> meets;
  d::mark_band(r.grid, caps, band, meets);
  std::size_t n = 0;
  const std::vector<long> label = d::components(r.grid, band, n);
  std::vector<std::vector<std::size_t>> cells(n);
  for (std::size_t c = 0; c < label.size(); ++c) {
    if (label[c] >= 0) cells[static_cast<std::size_t>(label[c])].push_back(c);
    else r.fold_band_area += r.grid.area(c), ++r.band_cells;
  }
  std::vector<WristRegion> regions(n);
  for (std::size_t k = 0; k < n; ++k) {
    regions[k].cells = cells[k].size();
    for (const std::size_t c : cells[k]) regions[k].area += r.grid.area(c);
  }
  std::vector<std::size_t> order(n);  // largest area first
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return regions[a].area > regions[b].area; });
  std::vector<long> rank(n);
  for (std::size_t k = 0; k < n; ++k) rank[order[k]] = static_cast<long>(k);
  r.cell_region.resize(label.size());
  for (std::size_t c = 0; c < label.size(); ++c) r.cell_region[c] = label[c] < 0 ? -1 : rank[static_cast<std::size_t>(label[c])];
  for (std::size_t k = 0; k < n; ++k) r.regions.push_back(regions[order[k]]);
  parallel_for(std::min(n, kMaxWristRegionCounts), threads, [&](std::size_t k) {
    d::count_region(wrist, r.grid, d::count_points(r.grid, label, cells[order[k]]), r.regions[k]);
  });
  for (const WristRegion& region : r.regions) r.ik_boxes += region.ik_boxes;
  wrist_regions_check(atlas, meets, r);
  return r;
}

}  // namespace sphtroch
