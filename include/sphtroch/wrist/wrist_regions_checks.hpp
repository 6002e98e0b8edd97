// sphtroch/wrist/wrist_regions_checks.hpp — the consistency checks of a wrist's regions
// (wrist_regions.hpp) and their summary: the parity of the counts, the +-2 rule across the fold
// band, the workspace and void areas, and whether the whole is certified.
//
//   sphtroch::WristRegionsResult r;            // regions, cell_region and grid filled
//   sphtroch::WristAtlasResult atlas;          // the atlas they came from (its `complete`)
//   std::vector<std::vector<std::size_t>> meets(r.grid.size());   // per band cell, the atlas cells whose caps meet it
//   sphtroch::wrist_regions_check(atlas, meets, r);
//   r.certified;                               // false here: no region counted and the atlas incomplete
//
// Parity: every regular value's count has the parity of the degree of P (the torus to the sphere),
// so two counted regions of different parity mean a wrong count: not certified. The +-2 rule: a
// walk from a region cell east along its row, or south through the cells holding its centre's
// azimuth, over at most kWristCrossingRun band cells to a cell of another region is a crossing of
// the band; each fold strand crossed changes the count by +-2 (a generic fold), so delta = count(to)
// - count(from) must be even with |delta| <= 2 s, s the strands that may meet the run: the groups
// of atlas cells whose caps meet it, cells joined when their motor ranges touch (modulo the
// periods). A strand is a piece of the critical curve; two pieces mapped onto one fold (a torus
// that covers the poses twice) are two strands, and a cusp or a fold crossed twice gives 0. The
// bound is a consistency check, not a proof: a strand crossed twice in one sense would fail it. A failure is a violation (not certified, the first 16
// kept); each pair of regions is reported once in `crossings`, and crossings_by_two counts the
// pairs that differ by exactly 2.
#pragma once

#include "sphtroch/wrist/wrist_atlas_result.hpp"
#include "sphtroch/wrist/wrist_regions_result.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// The longest run of band cells a crossing check walks.
constexpr std::size_t kWristCrossingRun = 8;

namespace wrist_regions_checks_detail {

/// The cells of a walk from `cell`: east along its row, or south along its centre's azimuth (at most kWristCrossingRun + 1).
inline std::vector<std::size_t> walk(const WristSphereGrid& grid, std::size_t cell, bool east) {
  const std::size_t i = grid.row_of(cell), j = cell - grid.index(i, 0), m = grid.columns(i);
  std::vector<std::size_t> out;
  const double azimuth = (static_cast<double>(j) + 0.5) / static_cast<double>(m);  // turns
  for (std::size_t k = 1; k <= kWristCrossingRun + 1; ++k) {
    if (east) {
      out.push_back(grid.index(i, (j + k) % m));
      continue;
    }
    if (i + k >= grid.rows()) break;
    const std::size_t n = grid.columns(i + k);
    out.push_back(grid.index(i + k, std::min(n - 1, static_cast<std::size_t>(azimuth * static_cast<double>(n)))));
  }
  return out;
}

/// Whether atlas cells a and b touch or overlap in both motors, modulo the periods.
inline bool touching(const WristAtlasResult& atlas, std::size_t a, std::size_t b) {
  for (std::size_t j = 0; j < 2; ++j) {
    const auto& x = atlas.cells[a].motors[j];
    const auto& y = atlas.cells[b].motors[j];
    const double t = atlas.periods[j], reach = ((x[1] - x[0]) + (y[1] - y[0])) / 2 * (1 + 1e-9);
    double d = std::fmod(std::fabs((x[0] + x[1]) / 2 - (y[0] + y[1]) / 2), t);
    if (std::min(d, t - d) > reach) return false;
  }
  return true;
}

/// The number of groups of touching atlas cells among `cells` (union-find).
inline std::size_t strands(const WristAtlasResult& atlas, const std::vector<std::size_t>& cells) {
  std::vector<std::size_t> parent(cells.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::size_t groups = cells.size();
  for (std::size_t a = 0; a < cells.size(); ++a)
    for (std::size_t b = a + 1; b < cells.size(); ++b)
      if (root(a) != root(b) && touching(atlas, cells[a], cells[b])) parent[root(a)] = root(b), --groups;
  return groups;
}

/// Checks the crossing starting at `cell` along `path` (see header); records the pair once.
inline void check_crossing(const WristAtlasResult& atlas, std::size_t cell, const std::vector<std::size_t>& path,
                           const std::vector<std::vector<std::size_t>>& meets,
                           std::map<std::pair<std::size_t, std::size_t>, bool>& seen, WristRegionsResult& r) {
  const auto from = static_cast<std::size_t>(r.cell_region[cell]);
  std::vector<std::size_t> crossed;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const long to = r.cell_region[path[k]];
    if (to < 0) {
      for (const std::size_t s : meets[path[k]])
        if (std::find(crossed.begin(), crossed.end(), s) == crossed.end()) crossed.push_back(s);
      continue;
    }
    if (k == 0 || static_cast<std::size_t>(to) == from) return;
    const auto t = static_cast<std::size_t>(to);
    if (!r.regions[from].counted || !r.regions[t].counted) return;
    const long delta = static_cast<long>(r.regions[t].count) - static_cast<long>(r.regions[from].count);
    const std::size_t s = delta % 2 == 0 && std::labs(delta) <= 2 ? 1 : strands(atlas, crossed);  // grouped only when needed
    const bool ok = delta % 2 == 0 && static_cast<std::size_t>(std::labs(delta)) <= 2 * s;
    const auto key = std::minmax(from, t);
    const auto it = seen.find(key);
    if (it == seen.end()) {
      seen[key] = ok;
      ++r.crossings;
      if (std::labs(delta) == 2) ++r.crossings_by_two;
    }
    if (!ok && (it == seen.end() || it->second) && r.violations.size() < 16) r.violations.push_back({from, t, s, delta});
    if (!ok) seen[key] = false;
    return;
  }
}

}  // namespace wrist_regions_checks_detail

/// The checks and the summary (see header). REQUIRES r.regions, r.cell_region, r.grid filled;
/// meets[c] the atlas cells whose caps meet band cell c.
inline void wrist_regions_check(const WristAtlasResult& atlas, const std::vector<std::vector<std::size_t>>& meets, WristRegionsResult& r) {
  namespace d = wrist_regions_checks_detail;
  std::map<std::pair<std::size_t, std::size_t>, bool> seen;
  for (std::size_t c = 0; c < r.cell_region.size(); ++c)
    if (r.cell_region[c] >= 0)
      for (const bool east : {true, false}) d::check_crossing(atlas, c, d::walk(r.grid, c, east), meets, seen, r);
  std::size_t uncounted = 0;
  int parity = -1;
  for (std::size_t k = 0; k < r.regions.size(); ++k) {
    const WristRegion& g = r.regions[k];
    if (!g.counted) {
      ++uncounted;
      continue;
    }
    (g.count > 0 ? r.workspace_area : r.void_area) += g.area;
    if (g.count == 0) r.voids.push_back(k);
    if (parity < 0) parity = static_cast<int>(g.count % 2);
    else if (static_cast<int>(g.count % 2) != parity) r.parity_ok = false;
  }
  std::string why;
  const auto add = [&why](const std::string& s) { why += (why.empty() ? "" : "; ") + s; };
  if (!atlas.complete) add("the atlas's search stopped: the fold band may miss folds");
  if (r.regions.empty()) add("no cell of the sphere was proved free of folds (a smaller --sphere-cell or --width may find some)");
  if (uncounted > 0) add(std::to_string(uncounted) + " region(s) without a certified count");
  if (!r.parity_ok) add("the counts are not all of one parity (the degree of P mod 2)");
  for (const WristRegionCrossing& v : r.violations)
    add("regions R" + std::to_string(v.from + 1) + " and R" + std::to_string(v.to + 1) + " differ by " + std::to_string(v.delta) +
        " across " + std::to_string(v.strands) + " fold strand(s) (the +-2 rule)");
  r.certified = why.empty();
  r.why = why;
}

}  // namespace sphtroch
