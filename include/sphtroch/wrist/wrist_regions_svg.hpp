// sphtroch/wrist/wrist_regions_svg.hpp — a wrist's regions and folds as one SVG picture: the
// sphere in azimuth (x, 0 to 360 degrees) and polar angle (y, 0 at +z on top to 180 degrees), each
// region's cells filled by its count, the fold band grey, the fold polylines drawn over them, and a
// legend of the counts.
//
//   sphtroch::WristAtlasResult atlas;     // from sphtroch::wrist_fold_atlas
//   sphtroch::WristRegionsResult r;       // from sphtroch::wrist_regions
//   std::string svg = sphtroch::wrist_regions_svg(atlas, r);   // a standalone SVG 1.1 document
//
// Colours: count 0 (a void) white; counts above 0 by rank among those present, ColorBrewer's
// sequential YlGnBu (light to dark as the count grows; the 9th and later ranks share the darkest);
// a region without a certified count magenta; the fold band grey; folds dark red; the estimated
// cusps (wrist_cusps.hpp) black open circles. Cells of one
// colour next to each other in a row are one rectangle. Text is 11 px. Fold segments longer than
// 0.3 rad (polylines joined across the azimuth seam or between distant cells) are not drawn.
#pragma once

#include "sphtroch/core/types.hpp"
#include "sphtroch/draw/svg.hpp"
#include "sphtroch/wrist/wrist_atlas_result.hpp"
#include "sphtroch/wrist/wrist_regions_result.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace sphtroch {

namespace wrist_regions_svg_detail {

constexpr double kLeft = 52, kTop = 34, kWidth = 720, kHeight = 360, kLegend = 200;
inline const char* const kBand = "#bdbdbd";
inline const char* const kUncounted = "#e7298a";
inline const char* const kVoid = "#ffffff";

/// YlGnBu, 8 classes after its lightest: rank 0 the lightest.
inline std::string sequential(std::size_t rank) {
  static const char* const colours[] = {"#edf8b1", "#c7e9b4", "#7fcdbb", "#41b6c4", "#1d91c0", "#225ea8", "#253494", "#081d58"};
  return colours[std::min<std::size_t>(rank, 7)];
}

/// The colour of each distinct count present (0 white, the others by rank).
inline std::map<std::size_t, std::string> palette(const WristRegionsResult& r) {
  std::map<std::size_t, std::string> out;
  for (const WristRegion& g : r.regions)
    if (g.counted) out[g.count] = "";
  std::size_t rank = 0;
  for (auto& [count, colour] : out) colour = count == 0 ? kVoid : sequential(rank++);
  return out;
}

inline std::string cell_colour(const WristRegionsResult& r, std::size_t cell, const std::map<std::size_t, std::string>& colours) {
  const long k = cell < r.cell_region.size() ? r.cell_region[cell] : -1;  // a result not filled: all band
  if (k < 0) return kBand;
  const WristRegion& g = r.regions[static_cast<std::size_t>(k)];
  return g.counted ? colours.at(g.count) : kUncounted;
}

/// The cells as rectangles, one path per colour, runs of a colour in a row joined.
inline void draw_cells(SvgWriter& svg, const WristRegionsResult& r, const std::map<std::size_t, std::string>& colours) {
  const double pi = Constants<double>::pi();
  std::map<std::string, SvgPath> paths;
  for (std::size_t i = 0; i < r.grid.rows(); ++i) {
    const std::size_t m = r.grid.columns(i);
    for (std::size_t j = 0; j < m;) {
      const std::string c = cell_colour(r, r.grid.index(i, j), colours);
      std::size_t e = j + 1;
      while (e < m && cell_colour(r, r.grid.index(i, e), colours) == c) ++e;
      const std::array<double, 4> a = r.grid.bounds(r.grid.index(i, j)), b = r.grid.bounds(r.grid.index(i, e - 1));
      const double x0 = kLeft + kWidth * a[2] / (2 * pi), x1 = kLeft + kWidth * b[3] / (2 * pi);
      const double y0 = kTop + kHeight * a[0] / pi, y1 = kTop + kHeight * a[1] / pi;
      auto it = paths.try_emplace(c, SvgPath(2)).first;
      it->second.move_to(x0, y0), it->second.line_to(x1, y0), it->second.line_to(x1, y1), it->second.line_to(x0, y1), it->second.close();
      j = e;
    }
  }
  for (const auto& [colour, d] : paths) svg.path(d, "fill:" + colour + ";stroke:" + colour + ";stroke-width:0.3");
}

inline void draw_folds(SvgWriter& svg, const WristAtlasResult& atlas) {
  const double pi = Constants<double>::pi();
  SvgPath d(2);
  for (const WristFoldPolyline& l : atlas.polylines) {
    bool pen = false;
    Vector3d last;
    double last_x = 0;
    for (const std::size_t i : l.cells) {
      const auto& p = atlas.cells[i].point;
      const Vector3d v(p[0], p[1], p[2]);
      double phi = std::atan2(v.y(), v.x());
      if (phi < 0) phi += 2 * pi;
      const double x = kLeft + kWidth * phi / (2 * pi), y = kTop + kHeight * std::atan2(std::hypot(v.x(), v.y()), v.z()) / pi;
      const bool join = pen && WristSphereGrid::angle(last, v) < 0.3 && std::fabs(x - last_x) < kWidth / 2;
      if (join) d.line_to(x, y);
      else d.move_to(x, y);
      pen = true;
      last = v;
      last_x = x;
    }
  }
  if (!d.empty()) svg.path(d, "fill:none;stroke:#a50f15;stroke-width:1.2;stroke-linejoin:round");
}

/// The estimated cusps as small open circles.
inline void draw_cusps(SvgWriter& svg, const WristAtlasResult& atlas) {
  const double pi = Constants<double>::pi();
  for (const WristCusp& c : atlas.cusps) {
    double phi = std::atan2(c.point[1], c.point[0]);
    if (phi < 0) phi += 2 * pi;
    const double theta = std::atan2(std::hypot(c.point[0], c.point[1]), c.point[2]);
    svg.circle(kLeft + kWidth * phi / (2 * pi), kTop + kHeight * theta / pi, 3.5, "fill:none;stroke:#000;stroke-width:1.2");
  }
}

inline void draw_frame(SvgWriter& svg) {
  const char* text = "font-family:sans-serif;font-size:11px;fill:#222";
  svg.rect(kLeft, kTop, kWidth, kHeight, "fill:none;stroke:#222;stroke-width:1");
  for (int k = 0; k <= 4; ++k) {
    const double x = kLeft + kWidth * k / 4.0, y = kTop + kHeight * k / 4.0;
    svg.line(x, kTop + kHeight, x, kTop + kHeight + 4, "stroke:#222");
    svg.text(x, kTop + kHeight + 16, std::to_string(90 * k), text, "middle");
    svg.line(kLeft - 4, y, kLeft, y, "stroke:#222");
    svg.text(kLeft - 7, y + 4, std::to_string(45 * k), text, "end");
  }
  svg.text(kLeft + kWidth / 2, kTop + kHeight + 32, "azimuth of the tool axis (degrees)", text, "middle");
  svg.text(14, kTop + kHeight / 2, "polar angle (deg)", text + std::string(";writing-mode:tb"), "middle");
  svg.text(kLeft, 20, "wrist atlas: regions of the sphere by certified IK count, folds in red", "font-family:sans-serif;font-size:13px;fill:#222");
}

inline void draw_legend(SvgWriter& svg, const WristRegionsResult& r, const std::map<std::size_t, std::string>& colours) {
  const char* text = "font-family:sans-serif;font-size:11px;fill:#222";
  const double x = kLeft + kWidth + 24;
  double y = kTop + 4;
  svg.text(x, y + 8, "IK solutions", "font-family:sans-serif;font-size:12px;font-weight:bold;fill:#222");
  y += 20;
  const auto row = [&](const std::string& fill, const std::string& label) {
    svg.rect(x, y, 16, 12, "fill:" + fill + ";stroke:#222;stroke-width:0.6");
    svg.text(x + 22, y + 10, label, text);
    y += 18;
  };
  for (const auto& [count, colour] : colours) row(colour, std::to_string(count) + (count == 0 ? " (void)" : ""));
  if (std::any_of(r.regions.begin(), r.regions.end(), [](const WristRegion& g) { return !g.counted; })) row(kUncounted, "not certified");
  row(kBand, "fold band (no count)");
  svg.line(x, y + 6, x + 16, y + 6, "stroke:#a50f15;stroke-width:1.6");
  svg.text(x + 22, y + 10, "fold (atlas polylines)", text);
  y += 18;
  svg.circle(x + 8, y + 6, 3.5, "fill:none;stroke:#000;stroke-width:1.2");
  svg.text(x + 22, y + 10, "cusp (estimated)", text);
}

}  // namespace wrist_regions_svg_detail

/// The picture (see header): a standalone SVG document.
inline std::string wrist_regions_svg(const WristAtlasResult& atlas, const WristRegionsResult& r) {
  namespace d = wrist_regions_svg_detail;
  SvgWriter svg(d::kLeft + d::kWidth + d::kLegend, d::kTop + d::kHeight + 44);
  svg.title("wrist atlas: regions by IK count and folds");
  const std::map<std::size_t, std::string> colours = d::palette(r);
  d::draw_cells(svg, r, colours);
  d::draw_folds(svg, atlas);
  d::draw_cusps(svg, atlas);
  d::draw_frame(svg);
  d::draw_legend(svg, r, colours);
  return svg.finish();
}

}  // namespace sphtroch
