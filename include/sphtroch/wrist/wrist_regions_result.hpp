// sphtroch/wrist/wrist_regions_result.hpp — what wrist_regions (wrist_regions.hpp) answers: the
// regions of the sphere that a 2-motor wrist's folds cut out, each a connected set of grid cells
// proved free of folds, with its certified number of IK solutions, its area, and the consistency
// checks across the folds.
//
//   sphtroch::WristRegionsResult r;        // filled by sphtroch::wrist_regions (wrist_regions.hpp)
//   r.regions.push_back({});
//   r.regions.front().count = 4;           // IK solutions at every direction of the region's cells
//   r.workspace_area;                      // steradians of cells proved to have count > 0
//
// No dependency but the grid (Eigen only): the front ends read it without the interval headers.
#pragma once

#include "sphtroch/core/types.hpp"
#include "sphtroch/wrist/wrist_sphere_grid.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// A region: grid cells joined through shared edges, every one proved to meet no fold. `count`
/// (when `counted`) is wrist_ik's certified count at `point`, the centre of one of its cells, and
/// so the count at every direction of every cell of the region.
struct WristRegion {
  std::size_t count = 0;
  bool counted = false;
  std::array<double, 3> point{};  ///< unit; where the count was certified
  double area = 0;                ///< steradians: the sum of its cells' areas (a lower bound of the true region's)
  std::size_t cells = 0;
  std::size_t ik_boxes = 0;       ///< wrist_ik's work for the count
};

/// Two regions reached from each other across a run of fold-band cells (a row, or a column of the
/// grid): their counts, and the strands that may meet the run (groups of touching atlas cells).
struct WristRegionCrossing {
  std::size_t from = 0, to = 0;
  std::size_t strands = 0;
  long delta = 0;  ///< count(to) - count(from)
};

struct WristRegionsResult {
  std::vector<WristRegion> regions;              ///< largest area first
  std::vector<long> cell_region;                 ///< per grid cell: its region, or -1 (a fold-band cell)
  WristSphereGrid grid{1.0};                     ///< the cells (replaced by wrist_regions)
  double fold_band_area = 0;                     ///< steradians of cells that may meet a fold (no count claimed there)
  double workspace_area = 0;                     ///< steradians of region cells with count > 0
  double void_area = 0;                          ///< steradians of region cells with count 0
  std::vector<std::size_t> voids;                ///< regions with count 0
  std::size_t band_cells = 0;
  std::size_t crossings = 0;                     ///< band runs between two regions checked
  std::size_t crossings_by_two = 0;              ///< of them, |delta| = 2
  std::vector<WristRegionCrossing> violations;   ///< crossings with delta odd or |delta| > 2 strands (at most 16 kept)
  bool parity_ok = true;                         ///< every count of one parity (the degree of P mod 2)
  double fold_radius = 0;                        ///< radians: the largest cap radius that holds a critical cell's image
  bool certified = false;                        ///< every region counted, the checks passed, the atlas complete
  std::string why;                               ///< not certified: what is missing
  std::size_t ik_boxes = 0;                      ///< wrist_ik's work, all regions

  /// The region of the cell holding d (unit), or none when that cell is in the fold band.
  std::optional<std::size_t> region_of(const Vector3d& d) const {
    const long r = cell_region[grid.cell_of(d)];
    if (r < 0) return std::nullopt;
    return static_cast<std::size_t>(r);
  }
};

}  // namespace sphtroch
