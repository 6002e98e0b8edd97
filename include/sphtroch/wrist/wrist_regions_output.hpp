// sphtroch/wrist/wrist_regions_output.hpp — a wrist's regions (wrist_regions.hpp) as JSON fields
// and as text, for `sphtroch wrist atlas` and every front end that reports them.
//
//   sphtroch::WristRegionsResult r;                      // from sphtroch::wrist_regions
//   nlohmann::json j = sphtroch::wrist_regions_json(r);  // the fields below (merged into the atlas's JSON)
//   std::string t = sphtroch::wrist_regions_text(r);     // for people
//
// JSON: "regions" [{"id" "R1", "count" (null when not certified), "point" [x, y, z] (unit: where
// the count was certified), "area_sr" {"cells", "upper"}, "cells"}] largest first; "area_sr.cells"
// is the area of the region's grid cells, all with that count (a lower bound of the true region's
// area), "upper" is 4 pi minus the cells of regions with another count (an upper bound: the true
// region holds none of them; null when a count is missing); "fold_band_area_sr" (cells that may
// meet a fold: no count claimed); "workspace_area_sr" {"cells", "upper"} (count > 0; upper adds
// the band); "void_area_sr" (cells with count 0), "voids" ["R..", ...]; "regions_certified",
// "regions_why"; "checks" {"parity", "crossings", "crossings_by_two", "violations" [{"from", "to",
// "delta", "strands"}]}; "sphere_grid" {"step" (radians), "cells", "band_cells"}; "fold_radius"
// (radians: the largest cap holding a critical cell's image).
#pragma once

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/wrist/wrist_atlas_output.hpp"
#include "sphtroch/wrist/wrist_regions_result.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <sstream>
#include <string>

namespace sphtroch {

/// 4 pi minus the areas of the counted regions whose count differs from region k's; none when some region is uncounted.
inline std::optional<double> wrist_region_area_upper(const WristRegionsResult& r, std::size_t k) {
  double other = 0;
  for (const WristRegion& g : r.regions) {
    if (!g.counted) return std::nullopt;
    if (g.count != r.regions[k].count) other += g.area;
  }
  return 4 * Constants<double>::pi() - other;
}

inline nlohmann::json wrist_regions_json(const WristRegionsResult& r) {
  nlohmann::json j, regions = nlohmann::json::array(), voids = nlohmann::json::array();
  for (std::size_t k = 0; k < r.regions.size(); ++k) {
    const WristRegion& g = r.regions[k];
    const std::optional<double> upper = wrist_region_area_upper(r, k);
    regions.push_back({{"id", "R" + std::to_string(k + 1)},
                       {"count", g.counted ? nlohmann::json(g.count) : nlohmann::json(nullptr)},
                       {"point", g.point},
                       {"area_sr", {{"cells", g.area}, {"upper", upper ? nlohmann::json(*upper) : nlohmann::json(nullptr)}}},
                       {"cells", g.cells}});
  }
  for (const std::size_t v : r.voids) voids.push_back("R" + std::to_string(v + 1));
  j["regions"] = regions;
  j["fold_band_area_sr"] = r.fold_band_area;
  j["workspace_area_sr"] = {{"cells", r.workspace_area}, {"upper", r.workspace_area + r.fold_band_area}};
  j["void_area_sr"] = r.void_area;
  j["voids"] = voids;
  j["regions_certified"] = r.certified;
  j["regions_why"] = r.why;
  nlohmann::json violations = nlohmann::json::array();
  for (const WristRegionCrossing& v : r.violations)
    violations.push_back({{"from", "R" + std::to_string(v.from + 1)}, {"to", "R" + std::to_string(v.to + 1)}, {"delta", v.delta}, {"strands", v.strands}});
  j["checks"] = {{"parity", r.parity_ok}, {"crossings", r.crossings}, {"crossings_by_two", r.crossings_by_two}, {"violations", violations}};
  j["sphere_grid"] = {{"step", r.grid.step()}, {"cells", r.grid.size()}, {"band_cells", r.band_cells}};
  j["fold_radius"] = r.fold_radius;
  return j;
}

/// The regions for people: at most `shown` of them (largest first), then the totals.
inline std::string wrist_regions_text(const WristRegionsResult& r, std::size_t shown = 20) {
  std::ostringstream out;
  out << "regions: " << r.regions.size() << " (grid cells of " << number_text(r.grid.step()) << " rad joined where no fold can be; "
      << r.band_cells << " of " << r.grid.size() << " cells in the fold band, " << number_text(r.fold_band_area) << " sr, no count claimed)\n";
  for (std::size_t k = 0; k < r.regions.size() && k < shown; ++k) {
    const WristRegion& g = r.regions[k];
    out << "  R" << k + 1 << "  count " << (g.counted ? std::to_string(g.count) : std::string("not certified")) << ", "
        << number_text(g.area) << " sr in " << g.cells << " cells, counted at (" << number_text(g.point[0]) << ", " << number_text(g.point[1])
        << ", " << number_text(g.point[2]) << ")\n";
  }
  if (r.regions.size() > shown) out << "  ... " << r.regions.size() - shown << " smaller region(s) (--json lists them)\n";
  out << "workspace (count > 0): at least " << number_text(r.workspace_area) << " sr, at most " << number_text(r.workspace_area + r.fold_band_area)
      << " sr; voids (count 0): " << r.voids.size() << " region(s), " << number_text(r.void_area) << " sr\n";
  out << "checks: counts of one parity " << (r.parity_ok ? "yes" : "NO") << "; " << r.crossings << " crossing(s) of the band checked, "
      << r.crossings_by_two << " differ by 2, " << r.violations.size() << " violation(s)\n";
  out << "regions " << (r.certified ? "certified" : "NOT certified: " + r.why) << "\n";
  return out.str();
}

/// `sphtroch wrist atlas --json` (and Python's Wrist.atlas): the atlas's object
/// (wrist_atlas_output.hpp) with the regions' members, "atlas_certified" (the atlas's own
/// certificate) and "certified" (both).
inline nlohmann::json wrist_atlas_report_json(const Wrist& wrist, const WristAtlasResult& atlas, const WristRegionsResult& regions) {
  nlohmann::json j = wrist_atlas_json(wrist, atlas);
  j.update(wrist_regions_json(regions));
  j["atlas_certified"] = atlas.certified;
  j["certified"] = atlas.certified && regions.certified;
  return j;
}

}  // namespace sphtroch
