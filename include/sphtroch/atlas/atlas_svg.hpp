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
  std::string title;    // empty: "Curve classes over (α2, α3), n = ... [(teeth ZS:ZP)], G × G cells"
  bool degrees = false; // axes in degrees (ticks at round degrees: 0°, 45°, ...), else multiples of pi
};

/// The map (see header).
inline std::string render_atlas_svg(const AtlasSpec& spec, const std::vector<AtlasCell>& cells,
                                    const AtlasSvgOptions& options = {});

/// Shades of the `nodes` class for one map: the distinct node counts of the map's regions, spread
/// evenly over eight blues from light (fewest) to dark (most); with more than eight distinct counts
/// the largest ones share the darkest blue, labelled ">= N nodes". A count found only on a pole
/// boundary (|p| >= 2: cells with a3 = a2 or a3 = pi - a2 within 1e-12, as the diagonal cells of
/// an atlas over equal ranges are; Table 1 rows d, g) is the count of a line, not of a region: such
/// cells share one grey, listed in one legend entry (`boundary_case`), so that eight blues are
/// left for the regions (n = 13/5: 52, 65, 91, 117, 143, 169, 195, 221 each its own shade).
class AtlasNodeShades {
 public:
  /// `ratio` names the pole lines (|p| >= 2); the default, 1, has none (every count a region's).
  explicit AtlasNodeShades(const std::vector<AtlasCell>& cells, const Ratio& ratio = Ratio(1));
  /// Fill colour of a cell: its class, and for `nodes` its shade.
  const char* colour(const AtlasCell& cell) const;
  struct Entry {
    std::uint32_t nodes;  // the count (the smallest one of the last, shared shade)
    bool and_more;        // the shade is shared by every larger count
    std::size_t cells;
    const char* colour;
    std::vector<std::uint32_t> boundary_counts = {};  // non-empty: the pole boundaries' own counts
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
/// Cells whose node count only a pole boundary has (AtlasNodeShades).
inline const char* const kBoundaryCase = "#b0b0b0";
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

/// Whether a cell lies on a pole boundary of the map (see AtlasNodeShades).
inline bool on_pole_boundary(const AtlasCell& c, const Ratio& ratio) {
  constexpr double kOnLine = 1e-12;
  const double pi = Constants<double>::pi();
  return std::llabs(ratio.p()) >= 2 && (std::fabs(c.a3 - c.a2) <= kOnLine || std::fabs(c.a3 + c.a2 - pi) <= kOnLine);
}

inline AtlasNodeShades::AtlasNodeShades(const std::vector<AtlasCell>& cells, const Ratio& ratio) {
  std::map<std::uint32_t, std::size_t> counts, line_counts;  // node count -> cells of class `nodes`
  for (const AtlasCell& c : cells)
    if (c.numeric_class() == AtlasClass::nodes) ++(on_pole_boundary(c, ratio) ? line_counts : counts)[c.nodes];
  Entry line{0, false, 0, atlas_svg_detail::kBoundaryCase};
  for (const auto& [n, cells_with_n] : line_counts) {
    if (const auto it = counts.find(n); it != counts.end()) {
      it->second += cells_with_n;  // a region's count: its shade
      continue;
    }
    shade_[n] = line.colour;
    line.boundary_counts.push_back(n);
    line.cells += cells_with_n;
  }
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
  if (!line.boundary_counts.empty()) {
    line.nodes = line.boundary_counts.front();
    entries_.push_back(std::move(line));
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

/// Ticks at multiples of a round step in degrees (90, 45, 30, 15, 10, 5, 2, 1, 0.5, ... the first
/// giving at least 4) in [lo, hi] radians, labelled "45°"; values in radians.
inline std::vector<Tick> degree_ticks(double lo, double hi) {
  const double to_deg = 180.0 / Constants<double>::pi();
  std::vector<Tick> out;
  for (double step : {90.0, 45.0, 30.0, 15.0, 10.0, 5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01}) {
    const long k0 = static_cast<long>(std::ceil(lo * to_deg / step - 1e-9));
    const long k1 = static_cast<long>(std::floor(hi * to_deg / step + 1e-9));
    if (k1 - k0 + 1 < 4) continue;
    for (long k = k0; k <= k1; ++k) {
      const double deg = step * static_cast<double>(k);
      out.push_back(Tick{deg / to_deg, svg_number(deg, 6) + "°"});
    }
    return out;
  }
  for (int k = 0; k <= 4; ++k) {
    const double v = lo + (hi - lo) * k / 4.0;
    out.push_back(Tick{v, svg_number(v * to_deg, 6) + "°"});
  }
  return out;
}

}  // namespace atlas_svg_detail

namespace atlas_svg_detail {

/// The map being drawn (contracts 1-4): geometry, summary, shades and writer, one method per
/// layer; render_atlas_svg calls them in drawing order.
class AtlasCanvas {
 public:
  AtlasCanvas(const AtlasSpec& spec, const std::vector<AtlasCell>& cells, double map_px, bool degrees)
      : spec_(spec), cells_(cells), degrees_(degrees), g_(spec.grid), map_(map_px), width_(kLeft + map_ + 24 + kLegendWidth),
        height_(kTop + map_ + kBottom), cell_(map_ / static_cast<double>(g_)), summary_(summarize_atlas(cells, spec.ratio)),
        shades_(cells, spec.ratio), svg_(width_, height_, 2) {}

  /// Title, white background.
  void head(const std::string& title) {
    svg_.title(title);
    svg_.rect(0, 0, width_, height_, "fill:#ffffff");
    svg_.text(kLeft, 28, title, "font-family:sans-serif;font-size:16px;font-weight:bold");
  }

  /// Cells: one rect per run of equal colour along a2 (contract 1).
  void cells() {
    svg_.begin_group("shape-rendering:crispEdges", "class=\"cells\"");
    for (std::size_t j = 0; j < g_; ++j)
      for (std::size_t i = 0; i < g_;) i += cell_run(i, j);
    svg_.end_group();
  }

  /// The closed-form boundaries (contract 2) and the self-tangency loci (2b), clipped to the map.
  void boundaries() {
    svg_.raw("<defs><clipPath id=\"atlas-map-clip\"><rect x=\"" + svg_.num(kLeft) + "\" y=\"" + svg_.num(kTop) +
             "\" width=\"" + svg_.num(map_) + "\" height=\"" + svg_.num(map_) + "\"/></clipPath></defs>\n");
    svg_.begin_group({}, "clip-path=\"url(#atlas-map-clip)\"");
    for (BoundaryKind kind : atlas_boundary_kinds(spec_.ratio)) {
      SvgPath d(2);
      for (std::size_t s = 0; s <= kAtlasBoundarySteps; ++s) {
        const double a2 = spec_.a2.lo + (spec_.a2.hi - spec_.a2.lo) * static_cast<double>(s) / kAtlasBoundarySteps;
        to(d, s == 0, x_of(a2), y_of(atlas_boundary_a3(kind, a2, spec_.ratio)));
      }
      boundary_path(d, boundary_style(kind), std::string("class=\"boundary\" data-kind=\"") + to_string(kind) + "\"");
    }
    for (const Locus& l : tangency_loci(spec_)) {
      if (l.points.size() < 2) continue;
      SvgPath d(2);
      for (std::size_t s = 0; s < l.points.size(); ++s) to(d, s == 0, x_of(l.points[s].a2), y_of(l.points[s].a3));
      boundary_path(d, boundary_style(BoundaryKind::tangency),
                    "class=\"boundary\" data-kind=\"tangency\" data-m=\"" + std::to_string(l.m) + "\"");
      ++tangency_loci_;
    }
    svg_.end_group();
  }

  /// Disagreeing cells outlined (contract 3).
  void disagreements() {
    svg_.begin_group("fill:none;stroke:#ff00ff;stroke-width:1.5", "class=\"disagreements\"");
    for (std::size_t k : summary_.disagreements) {
      const AtlasCell& c = cells_[k];
      const double s = std::max(cell_, 3.0);
      svg_.rect(kLeft + (static_cast<double>(c.i) + 0.5) * cell_ - s / 2,
                kTop + map_ - (static_cast<double>(c.j) + 0.5) * cell_ - s / 2, s, s, "");
    }
    svg_.end_group();
  }

  /// Frame, ticks in multiples of pi (or round degrees), axis titles.
  void frame_and_axes() {
    svg_.rect(kLeft, kTop, map_, map_, "fill:none;stroke:#333333;stroke-width:1");
    const std::string tick_text = "font-family:sans-serif;font-size:12px;fill:#333333";
    const auto axis_ticks = [&](const AngleRange& r) { return degrees_ ? degree_ticks(r.lo, r.hi) : ticks(r.lo, r.hi); };
    const std::string unit = degrees_ ? "deg" : "rad";
    for (const Tick& t : axis_ticks(spec_.a2)) {
      const double x = x_of(t.value);
      svg_.line(x, kTop + map_, x, kTop + map_ + 5, "stroke:#333333");
      svg_.text(x, kTop + map_ + 19, t.label, tick_text, "middle");
    }
    for (const Tick& t : axis_ticks(spec_.a3)) {
      const double y = y_of(t.value);
      svg_.line(kLeft - 5, y, kLeft, y, "stroke:#333333");
      svg_.text(kLeft - 8, y + 4, t.label, tick_text, "end");
    }
    svg_.text(kLeft + map_ / 2, kTop + map_ + 44, "α2 (carrier twist), " + unit, "font-family:sans-serif;font-size:13px", "middle");
    const double ly = kTop + map_ / 2;
    svg_.raw("<text x=\"" + svg_.num(kLeft - 48) + "\" y=\"" + svg_.num(ly) + "\" transform=\"rotate(-90 " +
             svg_.num(kLeft - 48) + " " + svg_.num(ly) +
             ")\" text-anchor=\"middle\" style=\"font-family:sans-serif;font-size:13px\">" +
             xml_escape("α3 (tracer twist), " + unit) + "</text>\n");
  }

  /// The legend (contract 4): classes present, boundaries, disagreements, the reading.
  void legend() {
    y_ = kTop + 6;
    svg_.begin_group({}, "class=\"legend\"");
    legend_classes();
    legend_boundaries();
    legend_disagreements();
    svg_.text(lx(), y_ + 8,
              std::string(spec_.reading.literal ? "literal reading" : "default reading") + "; cell centres sampled", kBody);
    svg_.end_group();
  }

  std::string finish() { return svg_.finish(); }

 private:
  static constexpr double kLeft = 72, kTop = 48, kBottom = 64, kLegendWidth = 330;
  static constexpr const char* kHead = "font-family:sans-serif;font-size:13px;font-weight:bold";
  static constexpr const char* kBody = "font-family:sans-serif;font-size:12px";

  double x_of(double a2) const { return kLeft + (a2 - spec_.a2.lo) / (spec_.a2.hi - spec_.a2.lo) * map_; }
  double y_of(double a3) const { return kTop + map_ - (a3 - spec_.a3.lo) / (spec_.a3.hi - spec_.a3.lo) * map_; }
  double lx() const { return kLeft + map_ + 24; }
  std::size_t count(AtlasClass c) const { return summary_.by_class[static_cast<int>(c)]; }

  /// The run of cells of one colour starting at (i, j) along a2, as one rect; its length.
  std::size_t cell_run(std::size_t i, std::size_t j) {
    const char* colour = shades_.colour(cells_[i * g_ + j]);
    std::size_t run = 1;
    while (i + run < g_ && shades_.colour(cells_[(i + run) * g_ + j]) == colour) ++run;
    // Rects overlap their right/top neighbour by a hair so no background shows between them.
    svg_.rect(kLeft + static_cast<double>(i) * cell_, kTop + map_ - static_cast<double>(j + 1) * cell_,
              static_cast<double>(run) * cell_ + 0.01, cell_ + 0.01, std::string("fill:") + colour);
    return run;
  }

  /// A polyline vertex, its y clamped to 10 map sizes (an asymptote stays drawable).
  void to(SvgPath& d, bool first, double x, double y) const {
    y = std::clamp(y, -10 * map_, 10 * map_);
    if (first) d.move_to(x, y);
    else d.line_to(x, y);
  }
  void boundary_path(const SvgPath& d, const char* style, const std::string& attributes) {
    svg_.begin_group(style, attributes);
    svg_.path(d, "");
    svg_.end_group();
  }

  void swatch(const char* colour, const std::string& label) {
    svg_.rect(lx(), y_ - 10, 16, 12, std::string("stroke:#999999;stroke-width:0.5;fill:") + colour);
    svg_.text(lx() + 24, y_, label, kBody);
    y_ += 18;
  }
  void class_swatch(AtlasClass c, const std::string& name) {
    if (count(c) > 0) swatch(atlas_class_colour(c), name + " (" + std::to_string(count(c)) + " cells)");
  }
  void legend_line(const char* style, const std::string& label) {
    svg_.line(lx(), y_ - 4, lx() + 28, y_ - 4, style);
    svg_.text(lx() + 36, y_, label, kBody);
    y_ += 18;
  }

  void legend_classes() {
    svg_.text(lx(), y_ + 4, "cells: root-count census", kHead);
    y_ += 20;
    class_swatch(AtlasClass::simple_curve, "simple curve");
    for (const AtlasNodeShades::Entry& e : shades_.entries()) {
      if (!e.boundary_counts.empty()) {
        boundary_case_swatch(e);
        continue;
      }
      swatch(e.colour, (e.and_more ? "≥ " : "") + std::to_string(e.nodes) + (e.nodes == 1 && !e.and_more ? " node" : " nodes") +
                           " (" + std::to_string(e.cells) + " cells)");
    }
    class_swatch(AtlasClass::cusps, "cusps");
    class_swatch(AtlasClass::nodes_and_cusps, "nodes and cusps");
    if (summary_.with_tangencies > 0) {
      svg_.text(lx(), y_, "(" + std::to_string(summary_.with_tangencies) + " cells with a tangency node: a pole node)", kBody);
      y_ += 18;
    }
    y_ += 10;
  }

  /// "on α3 = α2, π − α2 (82 cells):" and below it "14, 40, 66 nodes" (at most six counts named).
  void boundary_case_swatch(const AtlasNodeShades::Entry& e) {
    std::string list;
    for (std::size_t k = 0; k < e.boundary_counts.size() && k < 6; ++k)
      list += (k ? ", " : "") + std::to_string(e.boundary_counts[k]);
    if (e.boundary_counts.size() > 6) list += ", …";
    swatch(e.colour, "on α3 = α2, π − α2 (" + std::to_string(e.cells) + " cells):");
    svg_.text(lx() + 24, y_, list + (e.boundary_counts.size() == 1 && e.boundary_counts[0] == 1 ? " node" : " nodes"), kBody);
    y_ += 18;
  }

  void legend_boundaries() {
    svg_.text(lx(), y_, "boundaries: the report's criteria", kHead);
    y_ += 20;
    for (BoundaryKind kind : atlas_boundary_kinds(spec_.ratio)) legend_line(boundary_style(kind), atlas_boundary_label(kind, spec_.ratio));
    if (tangency_loci_ > 0)
      legend_line(boundary_style(BoundaryKind::tangency),
                  "self-tangency loci (" + std::to_string(tangency_loci_) + "): two branches touch");
    y_ += 10;
  }

  void legend_disagreements() {
    svg_.rect(lx(), y_ - 10, 12, 12, "fill:none;stroke:#ff00ff;stroke-width:1.5");
    const std::string predicted = spec_.ratio == Ratio(1)   ? "Eq. 24 and the pitch-cone criterion"
                                  : spec_.ratio == Ratio(2) ? "Eqs. 43, 46 and the pitch-cone criterion"
                                                            : "the pitch-cone criterion (cusps only)";
    svg_.text(lx() + 24, y_,
              "census ≠ report: " + std::to_string(summary_.disagreements.size()) + " cells (" +
                  std::to_string(summary_.disagreements_off_boundaries) + " off the boundaries)",
              kBody);
    y_ += 18;
    svg_.text(lx() + 24, y_, "(report: " + predicted + ")", kBody);
    y_ += 18;
  }

  const AtlasSpec& spec_;
  const std::vector<AtlasCell>& cells_;
  const bool degrees_;
  const std::size_t g_;
  const double map_, width_, height_, cell_;
  const AtlasSummary summary_;
  const AtlasNodeShades shades_;
  SvgWriter svg_;
  std::size_t tangency_loci_ = 0;
  double y_ = 0;  // the legend's next baseline
};

}  // namespace atlas_svg_detail

inline std::string render_atlas_svg(const AtlasSpec& spec, const std::vector<AtlasCell>& cells,
                                    const AtlasSvgOptions& options) {
  spec.validate();
  SPHTROCH_ASSERT(cells.size() == spec.cells(), "render_atlas_svg: one cell per grid point");
  if (!(options.map_px >= 64 && options.map_px <= 8192))
    throw InvalidInput("map_px", report_number(options.map_px), "outside the valid range", "[64, 8192] px");
  const std::string teeth = spec.teeth ? " (teeth " + spec.teeth->str() + ")" : "";
  const std::string title = options.title.empty() ? "Curve classes over (α2, α3), n = " + spec.ratio.str() + teeth + ", " +
                                                        std::to_string(spec.grid) + " × " + std::to_string(spec.grid) + " cells"
                                                  : options.title;
  atlas_svg_detail::AtlasCanvas canvas(spec, cells, options.map_px, options.degrees);
  canvas.head(title);
  canvas.cells();
  canvas.boundaries();
  canvas.disagreements();
  canvas.frame_and_axes();
  canvas.legend();
  return canvas.finish();
}

}  // namespace sphtroch
