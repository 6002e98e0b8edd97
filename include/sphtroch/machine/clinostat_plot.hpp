// sphtroch/machine/clinostat_plot.hpp — the picture of `sphtroch clinostat --plot`: the dwell map
// in the Mollweide (equal-area) projection with its colour scale, and M(W) against W with epsilon
// and the time to epsilon.
//
//   sphtroch::ClinostatPlot plot;
//   plot.title = "1.33 / 2 rpm";
//   plot.cells = {{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}};
//   plot.dwell_s = {60.0};
//   plot.windows = {{60.0, 0.3, 0.3}, {600.0, 0.03, 0.03}};
//   plot.epsilon = 0.05;
//   plot.first_below_s = 600.0;
//   const std::string svg = sphtroch::clinostat_plot_svg(plot);
//
// Left, the dwell map: each cell (its outline, unit vectors in the sample frame: HEALPix's
// cell_outlines in dwell_map.hpp) in the Mollweide projection (longitude atan2(y, x), latitude
// asin z; 2 t + sin 2t = pi sin(latitude) by Newton), cells across the date line drawn on both
// sides, clipped to the ellipse; each cell's paths have the class "cell-<its index>". Its colour says how the cell's dwell compares with the mean dwell
// (the duration over the number of cells: what an even coverage gives every cell), so that pole
// bias and holes show at a glance:
//  - colour = dwell / mean dwell on a diverging map centred at 1 (draw/diverging_colour.hpp:
//    ColorBrewer RdBu, blue below the mean, near white at it, red above), on a log scale symmetric
//    about 1 and clipped at the 5th and 95th percentiles of the visited cells, spanning at least
//    1/2 .. 2 (draw/ratio_scale.hpp); cells beyond a clip take the end colour;
//  - cells never visited (dwell 0) are grey kUnvisitedColour, a colour not on the map;
//  - the legend is the map itself as a gradient bar (the fills' colours, continuous) with ticks at
//    powers of two, the clipped ends and the grey swatch with the count of unvisited cells.
// Right, M(W) (its certified upper bound) against W: W linear with ticks at 1, 2 or 5 times a
// power of ten, M on a logarithmic scale with labelled decades and unlabelled ticks at 2 .. 9 times
// each, epsilon dashed; the first window W with M(W) <= epsilon (first_below_s) a dotted vertical
// line, the windows from stays_below_from_s on (every one below epsilon, of any length) a shaded
// band; both times written under the panel. Every text is at least 11 px.
#pragma once

#include "sphtroch/core/types.hpp"
#include "sphtroch/draw/diverging_colour.hpp"
#include "sphtroch/draw/ratio_scale.hpp"
#include "sphtroch/draw/svg.hpp"
#include "sphtroch/draw/text_layout.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// The fill of a cell never visited: a neutral grey, not on the diverging map.
constexpr const char* kUnvisitedColour = "#969696";

struct ClinostatPlot {
  std::string title;
  std::vector<std::vector<Vector3d>> cells;  ///< each cell's outline (unit vectors); may be empty
  std::vector<double> dwell_s;               ///< seconds per cell (same order as cells)
  struct Window {
    double window_s, lower, upper;
  };
  std::vector<Window> windows;               ///< M(W) at increasing W; may be empty
  std::string window_note;                   ///< drawn under the M(W) panel's heading when not empty
  std::optional<double> epsilon;
  std::optional<double> first_below_s;       ///< the first window W with M(W) <= epsilon (time_to_epsilon.hpp)
  std::optional<double> stays_below_from_s;  ///< every window from this length on is below epsilon
};

/// The fill of a cell with `dwell` seconds on `scale` (the header's rule).
inline std::string clinostat_cell_colour(const RatioScale& scale, double dwell) {
  return dwell > 0 && scale.mean > 0 ? diverging_colour(scale.position(dwell)) : kUnvisitedColour;
}

namespace detail {

/// Mollweide x in [-2 sqrt 2, 2 sqrt 2], y in [-sqrt 2, sqrt 2] (y up) of longitude and latitude.
inline Eigen::Vector2d mollweide(double longitude, double latitude) {
  const double pi = Constants<double>::pi();
  double t = latitude;
  for (int k = 0; k < 50 && std::fabs(std::fabs(latitude) - pi / 2) > 1e-12; ++k) {
    const double f = 2 * t + std::sin(2 * t) - pi * std::sin(latitude), d = 2 + 2 * std::cos(2 * t);
    if (d == 0) break;
    t -= f / d;
  }
  return {2 * std::sqrt(2.0) / pi * longitude * std::cos(t), std::sqrt(2.0) * std::sin(t)};
}

/// Text with a white halo under its glyphs (readable over lines and fills).
inline void halo_text(SvgWriter& svg, double x, double y, const std::string& text, const std::string& style, const char* anchor) {
  svg.text(x, y, text, style + ";stroke:#ffffff;stroke-width:3;stroke-linejoin:round", anchor);
  svg.text(x, y, text, style, anchor);
}

/// The cells, each filled by clinostat_cell_colour inside the ellipse's clip, shifted by 0, -2 pi
/// and 2 pi in longitude (the shifts that reach the ellipse), each path of class "cell-<index>".
inline void draw_dwell_cells(SvgWriter& svg, const ClinostatPlot& p, const RatioScale& scale, double x0, double y0, double scale_px) {
  const double pi = Constants<double>::pi(), rx = 2 * std::sqrt(2.0) * scale_px;
  svg.begin_group("", "id=\"cells\" clip-path=\"url(#sphere)\"");
  for (std::size_t c = 0; c < p.cells.size() && c < p.dwell_s.size(); ++c) {
    const std::string fill = "stroke:none;fill:" + clinostat_cell_colour(scale, p.dwell_s[c]);
    std::vector<double> lon, lat;
    for (const Vector3d& v : p.cells[c]) {
      double l = std::atan2(v.y(), v.x());
      if (!lon.empty()) l += 2 * pi * std::round((lon.front() - l) / (2 * pi));  // unwrapped about the first
      lon.push_back(l);
      lat.push_back(std::asin(std::clamp(v.z(), -1.0, 1.0)));
    }
    for (const double shift : {0.0, -2 * pi, 2 * pi}) {
      SvgPath d(svg.decimals());
      double left = x0 + rx, right = x0 - rx;
      for (std::size_t k = 0; k < lon.size(); ++k) {
        const Eigen::Vector2d m = mollweide(lon[k] + shift, lat[k]);
        const double x = x0 + scale_px * m.x();
        left = std::min(left, x);
        right = std::max(right, x);
        if (k == 0) d.move_to(x, y0 - scale_px * m.y());
        else d.line_to(x, y0 - scale_px * m.y());
      }
      if (right <= x0 - rx || left >= x0 + rx) continue;  // wholly outside the ellipse
      d.close();
      svg.raw("<path class=\"cell-" + std::to_string(c) + "\" d=\"" + d.str() + "\" style=\"" + xml_escape(fill) + "\"/>\n");
    }
  }
  svg.end_group();
}

/// The dwell map's legend under it, from y: the gradient bar with its ticks, the grey swatch of the
/// unvisited cells, and what the colour means.
inline void draw_dwell_legend(SvgWriter& svg, const ClinostatPlot& p, const RatioScale& scale, double left, double right, double y) {
  const std::string small = "font:11px sans-serif;fill:#333333";
  const double bar_right = right - 130, bar_w = bar_right - left;
  svg.begin_group("", "id=\"dwell-legend\"");
  svg.raw("<defs>" + diverging_gradient("dwell-scale") + "</defs>\n");
  svg.rect(left, y, bar_w, 12, "fill:url(#dwell-scale);stroke:#666666;stroke-width:0.5");
  for (const RatioScale::Tick& t : scale.ticks()) {
    const double x = left + t.position * bar_w;
    svg.line(x, y + 12, x, y + 17, "stroke:#333333;stroke-width:1");
    svg.text(x, y + 29, t.text, small, "middle");
  }
  std::size_t unvisited = 0;
  for (std::size_t c = 0; c < p.cells.size() && c < p.dwell_s.size(); ++c) unvisited += p.dwell_s[c] > 0 ? 0 : 1;
  svg.rect(bar_right + 14, y, 16, 12, std::string("fill:") + kUnvisitedColour + ";stroke:#666666;stroke-width:0.5");
  svg.text(bar_right + 36, y + 10, "not visited (" + std::to_string(unvisited) + ")", small);
  svg.text(left, y + 47,
           "dwell / mean dwell (mean " + picture_number(scale.mean, 3) + " s per cell), log scale, ends at the 5th and 95th",
           small);
  svg.text(left, y + 62,
           "percentiles of the visited cells (" + picture_number(scale.low_ratio(), 2) + " and " +
               picture_number(scale.high_ratio(), 2) + "); blue below the mean, red above",
           small);
  svg.end_group();
}

inline void draw_dwell_map(SvgWriter& svg, const ClinostatPlot& p, double x0, double y0, double scale_px) {
  const RatioScale scale = ratio_scale(std::vector<double>(p.dwell_s.begin(), p.dwell_s.begin() + static_cast<std::ptrdiff_t>(
                                                                                   std::min(p.dwell_s.size(), p.cells.size()))));
  const double rx = 2 * std::sqrt(2.0) * scale_px, ry = std::sqrt(2.0) * scale_px;
  svg.raw("<clipPath id=\"sphere\"><ellipse cx=\"" + svg.num(x0) + "\" cy=\"" + svg.num(y0) + "\" rx=\"" + svg.num(rx) +
          "\" ry=\"" + svg.num(ry) + "\"/></clipPath>\n");
  draw_dwell_cells(svg, p, scale, x0, y0, scale_px);
  svg.raw("<ellipse cx=\"" + svg.num(x0) + "\" cy=\"" + svg.num(y0) + "\" rx=\"" + svg.num(rx) + "\" ry=\"" + svg.num(ry) +
          "\" style=\"fill:none;stroke:#444;stroke-width:1\"/>\n");
  draw_dwell_legend(svg, p, scale, x0 - rx, x0 + rx, y0 + ry + 14);
  svg.text(x0, y0 - ry - 10, "time in each cell against the mean (Mollweide, equal area; sample frame)", "font:13px sans-serif",
           "middle");
}

/// The step of the ticks of a linear axis over `span`: 1, 2 or 5 times a power of ten, giving 4 to
/// 10 ticks.
inline double linear_tick_step(double span) {
  const double unit = std::pow(10.0, std::floor(std::log10(span / 4)));
  for (const double m : {1.0, 2.0, 5.0})
    if (span / (m * unit) <= 10) return m * unit;
  return 10 * unit;
}

/// The M(W) panel's axes: W's ticks (linear) and M's decades with their minor ticks (log); px, py
/// map W and M to the page.
template <typename Px, typename Py>
void draw_window_axes(SvgWriter& svg, double x0, double y0, double w, double h, double w_min, double w_max, double bottom,
                      const Px& px, const Py& py) {
  const std::string small = "font:11px sans-serif;fill:#333333";
  for (double e = bottom; e <= 0; ++e) {
    const double y = py(std::pow(10.0, e));
    svg.line(x0, y, x0 + w, y, "stroke:#dddddd;stroke-width:1");
    svg.line(x0 - 6, y, x0, y, "stroke:#444444;stroke-width:1");
    svg.text(x0 - 9, y + 4, picture_number(std::pow(10.0, e), 1), small, "end");
    for (int m = 2; m <= 9 && e < 0; ++m) {
      const double ym = py(m * std::pow(10.0, e));
      svg.line(x0 - 3, ym, x0, ym, "stroke:#444444;stroke-width:1");
    }
  }
  const double step = linear_tick_step(w_max - w_min);
  for (double k = std::ceil(w_min / step); k * step <= w_max * (1 + 1e-12); ++k) {
    const double x = px(k * step);
    svg.line(x, y0 + h, x, y0 + h + 5, "stroke:#444444;stroke-width:1");
    svg.text(x, y0 + h + 18, picture_number(k * step, 6), small, "middle");
  }
  svg.text(x0 + w / 2, y0 + h + 34, "window W (s)", small, "middle");
}

/// Epsilon, the first window below it and the windows all below it on the M(W) panel, and both
/// times in words under it.
template <typename Px, typename Py>
void draw_epsilon_marks(SvgWriter& svg, const ClinostatPlot& p, double x0, double y0, double w, double h, double w_min,
                        double w_max, const Px& px, const Py& py) {
  if (!p.epsilon) return;
  const std::string red = "font:11px sans-serif;fill:#c00000";
  if (p.stays_below_from_s && *p.stays_below_from_s < w_max) {
    const double x = px(std::max(w_min, *p.stays_below_from_s));
    svg.rect(x, y0, x0 + w - x, h, "fill:#2ca02c;fill-opacity:0.12;stroke:none");
    svg.line(x, y0, x, y0 + h, "stroke:#2ca02c;stroke-width:1.2");
  }
  if (p.first_below_s && *p.first_below_s >= w_min && *p.first_below_s <= w_max) {
    const double x = px(*p.first_below_s);
    svg.line(x, y0, x, y0 + h, "stroke:#c00000;stroke-width:1.2;stroke-dasharray:2,3");
  }
  svg.line(x0, py(*p.epsilon), x0 + w, py(*p.epsilon), "stroke:#c00000;stroke-width:1;stroke-dasharray:5,4");
  halo_text(svg, x0 + w - 4, py(*p.epsilon) - 5, "epsilon = " + picture_number(*p.epsilon) + " g0", red, "end");
  std::string words = "first window below epsilon: " + (p.first_below_s ? picture_number(*p.first_below_s) + " s (dotted)" : "none");
  if (p.stays_below_from_s) words += "; every window from " + picture_number(*p.stays_below_from_s) + " s on is below (shaded)";
  double y = y0 + h + 54;
  for (const std::string& line : wrap_text(words, w, 11)) {
    svg.text(x0, y, line, "font:11px sans-serif;fill:#333333");
    y += 14;
  }
}

inline void draw_window_curve(SvgWriter& svg, const ClinostatPlot& p, double x0, double y0, double w, double h) {
  svg.rect(x0, y0, w, h, "fill:none;stroke:#444;stroke-width:1");
  svg.text(x0 + w / 2, y0 - 10, "M(W): the worst mean over a window of W seconds (g0)", "font:13px sans-serif", "middle");
  if (p.windows.empty()) return;
  const double w_max = p.windows.back().window_s, w_min = p.windows.front().window_s;
  double low = 1;
  for (const auto& v : p.windows) low = std::min(low, std::max(v.upper, 1e-6));
  if (p.epsilon) low = std::min(low, *p.epsilon / 2);
  const double top = 0, bottom = std::min(-1.0, std::floor(std::log10(low)));  // at least one decade
  const auto px = [&](double window) { return x0 + w * (window - w_min) / std::max(1e-9, w_max - w_min); };
  const auto py = [&](double m) { return y0 + h * (top - std::log10(std::max(m, std::pow(10.0, bottom)))) / (top - bottom); };
  draw_window_axes(svg, x0, y0, w, h, w_min, w_max, bottom, px, py);
  draw_epsilon_marks(svg, p, x0, y0, w, h, w_min, w_max, px, py);
  SvgPath d(svg.decimals());
  for (std::size_t k = 0; k < p.windows.size(); ++k) {
    if (k == 0) d.move_to(px(p.windows[k].window_s), py(p.windows[k].upper));
    else d.line_to(px(p.windows[k].window_s), py(p.windows[k].upper));
  }
  svg.path(d, "fill:none;stroke:#1f5fa8;stroke-width:1.5");
  if (!p.window_note.empty()) halo_text(svg, x0 + w / 2, y0 + 16, p.window_note, "font:11px sans-serif;fill:#555555", "middle");
}

}  // namespace detail

/// The SVG text of the picture (1100 x 500 px).
inline std::string clinostat_plot_svg(const ClinostatPlot& p) {
  SvgWriter svg(1100, 500);
  svg.title(p.title);
  svg.rect(0, 0, 1100, 500, "fill:white;stroke:none");
  svg.text(550, 24, p.title, "font:bold 14px sans-serif", "middle");
  detail::draw_dwell_map(svg, p, 270, 215, 85);
  detail::draw_window_curve(svg, p, 630, 70, 430, 320);
  return svg.finish();
}

}  // namespace sphtroch
