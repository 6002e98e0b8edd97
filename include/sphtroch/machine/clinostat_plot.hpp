// sphtroch/machine/clinostat_plot.hpp — the picture of `sphtroch clinostat --plot`: the dwell map
// in the Mollweide (equal-area) projection with its colour scale, and M(W) against W with epsilon.
//
//   sphtroch::ClinostatPlot plot;
//   plot.title = "1.33 / 2 rpm";
//   plot.cells = {{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}};
//   plot.dwell_s = {60.0};
//   plot.windows = {{60.0, 0.3, 0.3}, {600.0, 0.03, 0.03}};
//   const std::string svg = sphtroch::clinostat_plot_svg(plot);
//
// Left: each cell (its outline, unit vectors in the sample frame: HEALPix's cell_outlines in
// dwell_map.hpp) filled by its dwell time on viridis (light: little, dark: much) from 0 to the
// largest dwell, in the Mollweide projection (longitude atan2(y, x), latitude asin z; 2 t + sin 2t
// = pi sin(latitude) by Newton), cells across the date line drawn on both sides, clipped to the
// ellipse. Right: M(W) (its certified upper bound) against W on a logarithmic scale, epsilon dashed.
#pragma once

#include "sphtroch/draw/svg.hpp"
#include "sphtroch/draw/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

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
};

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

inline void draw_dwell_map(SvgWriter& svg, const ClinostatPlot& p, double x0, double y0, double scale) {
  const double pi = Constants<double>::pi();
  const double peak = p.dwell_s.empty() ? 0 : *std::max_element(p.dwell_s.begin(), p.dwell_s.end());
  const double rx = 2 * std::sqrt(2.0) * scale, ry = std::sqrt(2.0) * scale;
  svg.raw("<clipPath id=\"sphere\"><ellipse cx=\"" + svg.num(x0) + "\" cy=\"" + svg.num(y0) + "\" rx=\"" + svg.num(rx) +
          "\" ry=\"" + svg.num(ry) + "\"/></clipPath>\n");
  svg.begin_group("", "clip-path=\"url(#sphere)\"");
  for (std::size_t c = 0; c < p.cells.size() && c < p.dwell_s.size(); ++c) {
    const std::string fill = "stroke:none;fill:" + viridis_colour(peak > 0 ? p.dwell_s[c] / peak : 0);
    std::vector<double> lon, lat;
    for (const Vector3d& v : p.cells[c]) {
      double l = std::atan2(v.y(), v.x());
      if (!lon.empty()) l += 2 * pi * std::round((lon.front() - l) / (2 * pi));  // unwrapped about the first
      lon.push_back(l);
      lat.push_back(std::asin(std::clamp(v.z(), -1.0, 1.0)));
    }
    for (const double shift : {0.0, -2 * pi, 2 * pi}) {
      SvgPath d(svg.decimals());
      for (std::size_t k = 0; k < lon.size(); ++k) {
        const Eigen::Vector2d m = mollweide(lon[k] + shift, lat[k]);
        if (k == 0) d.move_to(x0 + scale * m.x(), y0 - scale * m.y());
        else d.line_to(x0 + scale * m.x(), y0 - scale * m.y());
      }
      d.close();
      svg.path(d, fill);
    }
  }
  svg.end_group();
  svg.raw("<ellipse cx=\"" + svg.num(x0) + "\" cy=\"" + svg.num(y0) + "\" rx=\"" + svg.num(rx) + "\" ry=\"" + svg.num(ry) +
          "\" style=\"fill:none;stroke:#444;stroke-width:1\"/>\n");
  for (int k = 0; k <= 4; ++k) {  // the colour scale
    const double f = k / 4.0;
    svg.rect(x0 - rx + k * rx / 2.5, y0 + ry + 18, rx / 2.5, 10, "stroke:none;fill:" + viridis_colour(f));
    svg.text(x0 - rx + k * rx / 2.5, y0 + ry + 42, number_text(std::round(f * peak * 10) / 10) + " s", "font:11px sans-serif");
  }
  svg.text(x0, y0 - ry - 10, "seconds per cell (Mollweide, equal area; sample frame)", "font:13px sans-serif", "middle");
}

inline void draw_window_curve(SvgWriter& svg, const ClinostatPlot& p, double x0, double y0, double w, double h) {
  svg.rect(x0, y0, w, h, "fill:none;stroke:#444;stroke-width:1");
  svg.text(x0 + w / 2, y0 - 10, "M(W): the worst mean over a window of W seconds (g0)", "font:13px sans-serif", "middle");
  if (!p.window_note.empty()) svg.text(x0 + w / 2, y0 + 14, p.window_note, "font:11px sans-serif;fill:#555", "middle");
  if (p.windows.empty()) return;
  const double w_max = p.windows.back().window_s, w_min = p.windows.front().window_s;
  double low = 1;
  for (const auto& v : p.windows) low = std::min(low, std::max(v.upper, 1e-6));
  if (p.epsilon) low = std::min(low, *p.epsilon / 2);
  const double top = 0, bottom = std::min(-1.0, std::floor(std::log10(low)));  // at least one decade
  const auto px = [&](double window) { return x0 + w * (window - w_min) / std::max(1e-9, w_max - w_min); };
  const auto py = [&](double m) { return y0 + h * (top - std::log10(std::max(m, std::pow(10.0, bottom)))) / (top - bottom); };
  for (double e = bottom; e <= top; ++e) {
    svg.line(x0, py(std::pow(10.0, e)), x0 + w, py(std::pow(10.0, e)), "stroke:#ddd;stroke-width:1");
    svg.text(x0 - 6, py(std::pow(10.0, e)) + 4, "1e" + number_text(e), "font:11px sans-serif", "end");
  }
  SvgPath d(svg.decimals());
  for (std::size_t k = 0; k < p.windows.size(); ++k) {
    if (k == 0) d.move_to(px(p.windows[k].window_s), py(p.windows[k].upper));
    else d.line_to(px(p.windows[k].window_s), py(p.windows[k].upper));
  }
  svg.path(d, "fill:none;stroke:#21918c;stroke-width:1.5");
  if (p.epsilon) {
    svg.line(x0, py(*p.epsilon), x0 + w, py(*p.epsilon), "stroke:#c00;stroke-width:1;stroke-dasharray:5,4");
    svg.text(x0 + w - 4, py(*p.epsilon) - 4, "epsilon = " + number_text(*p.epsilon) + " g0", "font:11px sans-serif;fill:#c00", "end");
  }
  svg.text(x0, y0 + h + 16, number_text(w_min) + " s", "font:11px sans-serif");
  svg.text(x0 + w, y0 + h + 16, number_text(w_max) + " s", "font:11px sans-serif", "end");
  svg.text(x0 + w / 2, y0 + h + 16, "window W", "font:11px sans-serif", "middle");
}

}  // namespace detail

/// The SVG text of the picture (1100 x 480 px).
inline std::string clinostat_plot_svg(const ClinostatPlot& p) {
  SvgWriter svg(1100, 480);
  svg.title(p.title);
  svg.rect(0, 0, 1100, 480, "fill:white;stroke:none");
  svg.text(550, 24, p.title, "font:bold 14px sans-serif", "middle");
  detail::draw_dwell_map(svg, p, 270, 230, 85);
  detail::draw_window_curve(svg, p, 620, 80, 440, 320);
  return svg.finish();
}

}  // namespace sphtroch
