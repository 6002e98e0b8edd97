// sphtroch/synthesis/fit_grid.hpp — the grid of carrier twists a path fit screens (path_fit.hpp),
// and the map's cells at each grid column (map/map_cells.hpp), computed once per process: a design
// session fits one ratio many times, and every fit asks for the same kFitGrid columns.
//
//   const double a2 = sphtroch::fit_grid_angle(3);   // (3 + 0.5) pi / kFitGrid
//   for (const sphtroch::MapCell& c : sphtroch::fit_grid_column(3, sphtroch::Ratio(5, 2)))
//     c.lo, c.hi, c.nodes;                             // a3 intervals of one node count
//
// Memory: at most kFitColumnCache columns are kept (100 ratios' grids); beyond, a column lives in
// a ring of kFitGrid slots until kFitGrid later overflows (a reference is used within one fit's
// screening, which asks for kFitGrid columns). Thread-safe.
#pragma once

#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/map/map_cells.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <tuple>
#include <utility>
#include <vector>

namespace sphtroch {

/// Screening grid: kFitGrid x kFitGrid shapes (a2, a3), kFitGrid a2 columns for node counts.
constexpr int kFitGrid = 40;
/// Columns kept at most (100 ratios' grids).
constexpr std::size_t kFitColumnCache = 100 * kFitGrid;

/// The centre of grid step k of (0, pi): (k + 0.5) pi / kFitGrid.
inline double fit_grid_angle(int k) { return (static_cast<double>(k) + 0.5) * Constants<double>::pi() / kFitGrid; }

namespace fit_grid_detail {

/// Storage for a column computed when the cache is full (see header).
inline const std::vector<MapCell>* overflow_slot(std::vector<MapCell>&& cells) {
  static std::vector<std::vector<MapCell>> ring(kFitGrid);
  static std::size_t next = 0;
  std::vector<MapCell>& slot = ring[next++ % kFitGrid];
  slot = std::move(cells);
  return &slot;
}

}  // namespace fit_grid_detail

/// map_cells at grid column i (fit_grid_angle(i)) for n, computed once per process (see header).
inline const std::vector<MapCell>& fit_grid_column(int i, const Ratio& n) {
  static std::mutex mutex;
  static std::map<std::tuple<std::int64_t, std::int64_t, int>, std::vector<MapCell>> cache;
  const auto key = std::make_tuple(n.p(), n.q(), i);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
  }
  std::vector<MapCell> cells = map_cells(fit_grid_angle(i), n);  // outside the lock: another thread may do the same
  const std::lock_guard<std::mutex> lock(mutex);
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  if (cache.size() >= kFitColumnCache) return *fit_grid_detail::overflow_slot(std::move(cells));
  return cache.emplace(key, std::move(cells)).first->second;  // std::map: references stay valid
}

}  // namespace sphtroch
