// sphtroch/atlas/atlas_svg.hpp — the atlas (atlas.hpp) drawn as a standalone SVG map: a2 horizontal,
// a3 vertical (upwards), cells coloured by the census's class (simple curve; nodes, shaded by
// the node count — AtlasNodeShades spreads the counts present over eight blues; cusps; nodes
// and cusps), the report's boundary curves drawn over them, cells
// where the census and the report disagree outlined, tick labels in multiples of pi, a legend.
// Eigen only.
//
//   std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);
//   std::string svg = render_atlas_svg(spec, cells);          // write it to atlas.svg
//
// Contracts
//  1. Cells equal in colour and adjacent along a2 (same a3 row) are one <rect>: the file grows
//     with the number of class changes, not with G^2 (128 x 128, n = 2: about 30 kB).
//  2. Every boundary of atlas_boundary_kinds(spec.ratio) is one <path> inside
//     <g class="boundary" data-kind="KIND">, a polyline of kAtlasBoundarySteps segments of
//     a3 = f(a2) over the a2 range, clipped to the map: a3 = a_p(a2) = atan2(sin a2, cos a2 + n),
//     pi - a_p(a2), and for |p| >= 2 also a2 and pi - a2. The legend names each with the
//     report's equation (Eq. 24 for n = 1; Eqs. 43, 46 for n = 2).
//  2b. Every self-tangency locus of boundary_events.hpp (boundary_loci over the a2 range, the same
//     kAtlasBoundarySteps samples) is one <path> in <g class="boundary" data-kind="tangency"
//     data-m="M">; the legend names them (none for n = 1, 2, which have no such locus).
//  3. Every disagreeing cell (agree == false, or cusp counts differ) is outlined by one <rect>
//     in <g class="disagreements">; the legend gives their number.
//  4. The legend lists the classes present (node counts present), in <g class="legend">.
//  REQUIRES: cells.size() == spec.grid^2, row-major as compute_atlas returns them (assertion).
#pragma once

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/draw/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace sphtroch {

/// Segments per boundary polyline (a 512 px map: one per pixel).
constexpr std::size_t kAtlasBoundarySteps = 512;

struct AtlasSvgOptions {
  double map_px = 512;  // side of the square map, px; [64, 8192]
  std::string title;    // empty: "Curve classes over (α2, α3), n = ..., G × G cells"
};

/// The map (see header).
inline std::string render_atlas_svg(const AtlasSpec& spec, const std::vector<AtlasCell>& cells,
                                    const AtlasSvgOptions& options = {});

/// Shades of the `nodes` class for one map: the distinct node counts present, spread evenly over
/// eight blues from light (fewest) to dark (most); with more than eight distinct counts the
/// largest ones share the darkest blue, labelled ">= N nodes".
class AtlasNodeShades {
 public:
  explicit AtlasNodeShades(const std::vector<AtlasCell>& cells);
  /// Fill colour of a cell: its class, and for `nodes` its shade.
  const char* colour(const AtlasCell& cell) const;
  struct Entry {
    std::uint32_t nodes;  // the count (the smallest one of the last, shared shade)
    bool and_more;        // the shade is shared by every larger count
    std::size_t cells;
    const char* colour;
  };
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::map<std::uint32_t, const char*> shade_;
  std::vector<Entry> entries_;
};

/// Fill colour of a class (for `nodes` the middle blue; maps shade it with AtlasNodeShades).
inline const char* atlas_class_colour(AtlasClass c);

/// Legend label of one boundary for this ratio, with the report's equation where it has one.
inline std::string atlas_boundary_label(BoundaryKind kind, const Ratio& ratio);

// =============================================================================================
// Implementation details follow.
// =============================================================================================

namespace atlas_svg_detail {
// Light to medium-dark, so that the boundary curves stay visible over every shade.
inline const char* const kBlues[8] = {"#e3eef9", "#cfe1f2", "#b5d4e9", "#93c3df",
                                      "#6daed5", "#4b97c9", "#2f7ebc", "#1864aa"};
/// The self-tangency loci over the map's a2 range, at kAtlasBoundarySteps samples (2 threads).
inline std::vector<Locus> tangency_loci(const AtlasSpec& spec) {
  std::vector<Locus> out;
  for (Locus& l : boundary_loci(spec.ratio, spec.a2.lo, spec.a2.hi, kAtlasBoundarySteps, 2))
    if (l.kind == BoundaryEventKind::tangency) out.push_back(std::move(l));
  return out;
}

}  // namespace atlas_svg_detail

inline const char* atlas_class_colour(AtlasClass c) {
  switch (c) {
    case AtlasClass::simple_curve: return "#ececec";
    case AtlasClass::nodes: return atlas_svg_detail::kBlues[4];
    case AtlasClass::cusps: return "#d62728";
    case AtlasClass::nodes_and_cusps: return "#9467bd";
  }
  return "#000000";
}

inline AtlasNodeShades::AtlasNodeShades(const std::vector<AtlasCell>& cells) {
  std::map<std::uint32_t, std::size_t> counts;  // node count -> cells of class `nodes`
  for (const AtlasCell& c : cells)
    if (c.numeric_class() == AtlasClass::nodes) ++counts[c.nodes];
  const std::size_t m = counts.size();
  std::size_t k = 0;
  for (const auto& [n, cells_with_n] : counts) {
    // m <= 8: spread over the palette (rounded k * 7 / (m - 1)); m > 8: ranks 0..6 their own
    // shade, the rest the last.
    const std::size_t index = m == 1 ? 4 : m <= 8 ? (k * 7 + (m - 1) / 2) / (m - 1) : std::min<std::size_t>(k, 7);
    const char* colour = atlas_svg_detail::kBlues[index];
    shade_[n] = colour;
    if (!entries_.empty() && entries_.back().colour == colour) {
      entries_.back().and_more = true;
      entries_.back().cells += cells_with_n;
    } else {
      entries_.push_back(Entry{n, false, cells_with_n, colour});
    }
    ++k;
  }
}

inline const char* AtlasNodeShades::colour(const AtlasCell& cell) const {
  const AtlasClass c = cell.numeric_class();
  if (c != AtlasClass::nodes) return atlas_class_colour(c);
  const auto it = shade_.find(cell.nodes);
  return it == shade_.end() ? atlas_class_colour(c) : it->second;
}

inline std::string atlas_boundary_label(BoundaryKind kind, const Ratio& ratio) {
  const bool n1 = ratio == Ratio(1), n2 = ratio == Ratio(2);
  switch (kind) {
    case BoundaryKind::pitch_cone:
    case BoundaryKind::half_a2:
      return n1   ? "α3 = αp = α2/2: Eq. 24, lower end (cusp)"
             : n2 ? "α3 = αp: Eq. 43, lower end (2 cusps)"
                  : "α3 = αp: pitch cone (cusps)";
    case BoundaryKind::mirror_pitch_cone:
    case BoundaryKind::pi_minus_half_a2:
      return n1   ? "α3 = π − αp = π − α2/2: Eq. 24, upper end (cusp)"
             : n2 ? "α3 = π − αp: Eq. 46, upper end (2 cusps)"
                  : "α3 = π − αp: mirror pitch cone (cusps)";
    case BoundaryKind::a2:
      return n2 ? "α3 = α2: Eq. 46, lower end (north pole)" : "α3 = α2: north pole on the curve";
    case BoundaryKind::pi_minus_a2:
      return n2 ? "α3 = π − α2: Eq. 43, upper end (south pole)" : "α3 = π − α2: south pole on the curve";
    case BoundaryKind::tangency: return "self-tangency (two branches touch)";
  }
  return "?";
}

namespace atlas_svg_detail {

inline const char* boundary_style(BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::pitch_cone:
    case BoundaryKind::half_a2: return "fill:none;stroke:#e6550d;stroke-width:2";
    case BoundaryKind::mirror_pitch_cone:
    case BoundaryKind::pi_minus_half_a2: return "fill:none;stroke:#e6550d;stroke-width:2;stroke-dasharray:7 4";
    case BoundaryKind::a2: return "fill:none;stroke:#238b45;stroke-width:2";
    case BoundaryKind::pi_minus_a2: return "fill:none;stroke:#238b45;stroke-width:2;stroke-dasharray:7 4";
    case BoundaryKind::tangency: return "fill:none;stroke:#d62728;stroke-width:1.5;stroke-dasharray:2 2";
  }
  return "fill:none;stroke:#000";
}

/// k pi / d as text: "0", "π", "3π", "π/4", "3π/4".
inline std::string pi_label(long k, long d) {
  if (k == 0) return "0";
  const long g = std::gcd(k < 0 ? -k : k, d);
  k /= g;
  d /= g;
  std::string s = (k == 1 ? "" : k == -1 ? "−" : std::to_string(k)) + "π";
  if (d != 1) s += "/" + std::to_string(d);
  return s;
}

struct Tick {
  double value;
  std::string label;
};

/// Ticks at multiples of pi/d in [lo, hi], d the first of 1, 2, 4, 8, 12, 24, ... giving at
/// least 4; ranges narrower than pi/3072 get 5 evenly spaced decimal ticks.
inline std::vector<Tick> ticks(double lo, double hi) {
  const double pi = Constants<double>::pi();
  std::vector<Tick> out;
  const long ds[] = {1, 2, 4, 8, 12, 24, 48, 96, 192, 384, 768, 1536, 3072};
  for (long d : ds) {
    const long k0 = static_cast<long>(std::ceil(lo * static_cast<double>(d) / pi - 1e-9));
    const long k1 = static_cast<long>(std::floor(hi * static_cast<double>(d) / pi + 1e-9));
    if (k1 - k0 + 1 >= 4) {
      for (long k = k0; k <= k1; ++k) out.push_back(Tick{pi * static_cast<double>(k) / static_cast<double>(d), pi_label(k, d)});
      return out;
    }
  }
  for (int k = 0; k <= 4; ++k) {
    const double v = lo + (hi - lo) * k / 4.0;
    out.push_back(Tick{v, svg_number(v, 6)});
  }
  return out;
}

}  // namespace atlas_svg_detail

inline std::string render_atlas_svg(const AtlasSpec& spec, const std::vector<AtlasCell>& cells,
                                    const AtlasSvgOptions& options) {
  using namespace atlas_svg_detail;
  spec.validate();
  SPHTROCH_ASSERT(cells.size() == spec.cells(), "render_atlas_svg: one cell per grid point");
  if (!(options.map_px >= 64 && options.map_px <= 8192))
    throw InvalidInput("map_px", number_text(options.map_px), "outside the valid range", "[64, 8192] px");
  const std::size_t g = spec.grid;
  const double map = options.map_px;
  const double left = 72, top = 48, bottom = 64, legend_w = 330;
  const double width = left + map + 24 + legend_w, height = top + map + bottom;
  const double cell = map / static_cast<double>(g);
  auto x_of = [&](double a2) { return left + (a2 - spec.a2.lo) / (spec.a2.hi - spec.a2.lo) * map; };
  auto y_of = [&](double a3) { return top + map - (a3 - spec.a3.lo) / (spec.a3.hi - spec.a3.lo) * map; };
  const AtlasSummary summary = summarize_atlas(cells, spec.ratio);
  const AtlasNodeShades shades(cells);

  SvgWriter svg(width, height, 2);
  const std::string title = options.title.empty() ? "Curve classes over (α2, α3), n = " + spec.ratio.str() + ", " +
                                                        std::to_string(g) + " × " + std::to_string(g) + " cells"
                                                  : options.title;
  svg.title(title);
  svg.rect(0, 0, width, height, "fill:#ffffff");
  svg.text(left, 28, title, "font-family:sans-serif;font-size:16px;font-weight:bold");

  // Cells: one rect per run of equal colour along a2 (contract 1).
  svg.begin_group("shape-rendering:crispEdges", "class=\"cells\"");
  for (std::size_t j = 0; j < g; ++j) {
    std::size_t i = 0;
    while (i < g) {
      const AtlasCell& c = cells[i * g + j];
      const char* colour = shades.colour(c);
      std::size_t run = 1;
      while (i + run < g) {
        const AtlasCell& d = cells[(i + run) * g + j];
        if (shades.colour(d) != colour) break;
        ++run;
      }
      // Rects overlap their right/top neighbour by a hair so no background shows between them.
      svg.rect(left + static_cast<double>(i) * cell, top + map - static_cast<double>(j + 1) * cell,
               static_cast<double>(run) * cell + 0.01, cell + 0.01, std::string("fill:") + colour);
      i += run;
    }
  }
  svg.end_group();

  // Boundaries (contract 2), clipped to the map.
  svg.raw("<defs><clipPath id=\"atlas-map-clip\"><rect x=\"" + svg.num(left) + "\" y=\"" + svg.num(top) +
          "\" width=\"" + svg.num(map) + "\" height=\"" + svg.num(map) + "\"/></clipPath></defs>\n");
  svg.begin_group({}, "clip-path=\"url(#atlas-map-clip)\"");
  const std::vector<BoundaryKind> kinds = atlas_boundary_kinds(spec.ratio);
  for (BoundaryKind kind : kinds) {
    SvgPath d(2);
    for (std::size_t s = 0; s <= kAtlasBoundarySteps; ++s) {
      const double a2 = spec.a2.lo + (spec.a2.hi - spec.a2.lo) * static_cast<double>(s) / kAtlasBoundarySteps;
      const double y = std::clamp(y_of(atlas_boundary_a3(kind, a2, spec.ratio)), -10 * map, 10 * map);
      if (s == 0) d.move_to(x_of(a2), y);
      else d.line_to(x_of(a2), y);
    }
    svg.begin_group(boundary_style(kind), std::string("class=\"boundary\" data-kind=\"") + to_string(kind) + "\"");
    svg.path(d, "");
    svg.end_group();
  }
  // The self-tangency loci (contract 2b), one path per locus.
  std::size_t tangency_loci = 0;
  for (const Locus& l : atlas_svg_detail::tangency_loci(spec)) {
    if (l.points.size() < 2) continue;
    SvgPath d(2);
    for (std::size_t s = 0; s < l.points.size(); ++s) {
      const double y = std::clamp(y_of(l.points[s].a3), -10 * map, 10 * map);
      if (s == 0) d.move_to(x_of(l.points[s].a2), y);
      else d.line_to(x_of(l.points[s].a2), y);
    }
    svg.begin_group(boundary_style(BoundaryKind::tangency),
                    "class=\"boundary\" data-kind=\"tangency\" data-m=\"" + std::to_string(l.m) + "\"");
    svg.path(d, "");
    svg.end_group();
    ++tangency_loci;
  }
  svg.end_group();

  // Disagreeing cells (contract 3).
  svg.begin_group("fill:none;stroke:#ff00ff;stroke-width:1.5", "class=\"disagreements\"");
  for (std::size_t k : summary.disagreements) {
    const AtlasCell& c = cells[k];
    const double s = std::max(cell, 3.0);
    svg.rect(left + (static_cast<double>(c.i) + 0.5) * cell - s / 2, top + map - (static_cast<double>(c.j) + 0.5) * cell - s / 2,
             s, s, "");
  }
  svg.end_group();

  // Frame, ticks, axis titles.
  svg.rect(left, top, map, map, "fill:none;stroke:#333333;stroke-width:1");
  const std::string tick_text = "font-family:sans-serif;font-size:12px;fill:#333333";
  for (const Tick& t : ticks(spec.a2.lo, spec.a2.hi)) {
    const double x = x_of(t.value);
    svg.line(x, top + map, x, top + map + 5, "stroke:#333333");
    svg.text(x, top + map + 19, t.label, tick_text, "middle");
  }
  for (const Tick& t : ticks(spec.a3.lo, spec.a3.hi)) {
    const double y = y_of(t.value);
    svg.line(left - 5, y, left, y, "stroke:#333333");
    svg.text(left - 8, y + 4, t.label, tick_text, "end");
  }
  svg.text(left + map / 2, top + map + 44, "α2 (carrier twist), rad", "font-family:sans-serif;font-size:13px", "middle");
  const double ly = top + map / 2;
  svg.raw("<text x=\"" + svg.num(left - 48) + "\" y=\"" + svg.num(ly) + "\" transform=\"rotate(-90 " + svg.num(left - 48) +
          " " + svg.num(ly) + ")\" text-anchor=\"middle\" style=\"font-family:sans-serif;font-size:13px\">" +
          xml_escape("α3 (tracer twist), rad") + "</text>\n");

  // Legend (contract 4).
  const double lx = left + map + 24;
  double y = top + 6;
  const std::string head = "font-family:sans-serif;font-size:13px;font-weight:bold";
  const std::string body = "font-family:sans-serif;font-size:12px";
  svg.begin_group({}, "class=\"legend\"");
  svg.text(lx, y + 4, "cells: root-count census", head);
  y += 20;
  auto swatch = [&](const char* colour, const std::string& label) {
    svg.rect(lx, y - 10, 16, 12, std::string("stroke:#999999;stroke-width:0.5;fill:") + colour);
    svg.text(lx + 24, y, label, body);
    y += 18;
  };
  const auto count = [&](AtlasClass c) { return summary.by_class[static_cast<int>(c)]; };
  if (count(AtlasClass::simple_curve) > 0)
    swatch(atlas_class_colour(AtlasClass::simple_curve),
           "simple curve (" + std::to_string(count(AtlasClass::simple_curve)) + " cells)");
  for (const AtlasNodeShades::Entry& e : shades.entries())
    swatch(e.colour, (e.and_more ? "≥ " : "") + std::to_string(e.nodes) + (e.nodes == 1 && !e.and_more ? " node" : " nodes") +
                         " (" + std::to_string(e.cells) + " cells)");
  if (count(AtlasClass::cusps) > 0)
    swatch(atlas_class_colour(AtlasClass::cusps), "cusps (" + std::to_string(count(AtlasClass::cusps)) + " cells)");
  if (count(AtlasClass::nodes_and_cusps) > 0)
    swatch(atlas_class_colour(AtlasClass::nodes_and_cusps),
           "nodes and cusps (" + std::to_string(count(AtlasClass::nodes_and_cusps)) + " cells)");
  if (summary.with_tangencies > 0) {
    svg.text(lx, y, "(" + std::to_string(summary.with_tangencies) + " cells with a tangency node: a pole node)", body);
    y += 18;
  }
  y += 10;
  svg.text(lx, y, "boundaries: the report's criteria", head);
  y += 20;
  for (BoundaryKind kind : kinds) {
    svg.line(lx, y - 4, lx + 28, y - 4, boundary_style(kind));
    svg.text(lx + 36, y, atlas_boundary_label(kind, spec.ratio), body);
    y += 18;
  }
  if (tangency_loci > 0) {
    svg.line(lx, y - 4, lx + 28, y - 4, boundary_style(BoundaryKind::tangency));
    svg.text(lx + 36, y, "self-tangency loci (" + std::to_string(tangency_loci) + "): two branches touch", body);
    y += 18;
  }
  y += 10;
  svg.rect(lx, y - 10, 12, 12, "fill:none;stroke:#ff00ff;stroke-width:1.5");
  const std::string predicted = spec.ratio == Ratio(1) ? "Eq. 24 and the pitch-cone criterion"
                                : spec.ratio == Ratio(2) ? "Eqs. 43, 46 and the pitch-cone criterion"
                                                         : "the pitch-cone criterion (cusps only)";
  svg.text(lx + 24, y,
           "census ≠ report: " + std::to_string(summary.disagreements.size()) + " cells (" +
               std::to_string(summary.disagreements_off_boundaries) + " off the boundaries)",
           body);
  y += 18;
  svg.text(lx + 24, y, "(report: " + predicted + ")", body);
  y += 18;
  svg.text(lx, y + 8, std::string(spec.reading.literal ? "literal reading" : "default reading") + "; cell centres sampled", body);
  svg.end_group();
  return svg.finish();
}

}  // namespace sphtroch
