// sphtroch/draw/diverging_colour.hpp — a diverging colour map for a quantity centred on a
// neutral value (a ratio to its mean: below blue, at it near white, above red), as fills and as
// the SVG gradient of its legend, so that the legend shows exactly the colours the fills take.
// The clinostat picture's dwell map (machine/clinostat_plot.hpp) uses it. No dependencies.
//
//   sphtroch::diverging_colour(0.5);    // "#f7f7f7": the centre
//   sphtroch::diverging_colour(0.0);    // "#053061": the low end (dark blue)
//   sphtroch::diverging_colour(1.0);    // "#67001f": the high end (dark red)
//   std::string defs = sphtroch::diverging_gradient("scale");   // <linearGradient id="scale" ...>
//
// Contracts:
//  1. The stops are ColorBrewer's RdBu with 11 classes (Cynthia Brewer, colorbrewer2.org),
//     ordered from blue (f = 0) to red (f = 1), equally spaced in f; the centre f = 0.5 is the
//     palette's own neutral #f7f7f7. Between stops the colour is linear in sRGB components,
//     rounded to the nearest integer; f is clamped to [0, 1] (NaN counts as 0.5).
//  2. diverging_gradient(id) is one <linearGradient> (left to right, in the box of the shape it
//     fills) with the same stops at the same offsets; SVG interpolates gradients in sRGB, so a
//     bar filled with it shows at each x the colour diverging_colour gives there.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace sphtroch {

/// The map's stops as sRGB triples, from f = 0 (blue) to f = 1 (red) (contract 1).
inline const std::array<std::array<int, 3>, 11>& diverging_stops() {
  static const std::array<std::array<int, 3>, 11> stops{{{5, 48, 97},
                                                        {33, 102, 172},
                                                        {67, 147, 195},
                                                        {146, 197, 222},
                                                        {209, 229, 240},
                                                        {247, 247, 247},
                                                        {253, 219, 199},
                                                        {244, 165, 130},
                                                        {214, 96, 77},
                                                        {178, 24, 43},
                                                        {103, 0, 31}}};
  return stops;
}

namespace detail {

/// "#rrggbb" of an sRGB triple (components in 0 .. 255).
inline std::string hex_colour(const std::array<int, 3>& rgb) {
  static const char* const hex = "0123456789abcdef";
  std::string out = "#";
  for (const int v : rgb) {
    out += hex[v / 16];
    out += hex[v % 16];
  }
  return out;
}

}  // namespace detail

/// The colour at f (contract 1), as "#rrggbb".
inline std::string diverging_colour(double f) {
  const auto& stops = diverging_stops();
  const double last = static_cast<double>(stops.size() - 1);
  const double x = std::isnan(f) ? 0.5 * last : std::clamp(f, 0.0, 1.0) * last;
  const std::size_t i = std::min(stops.size() - 2, static_cast<std::size_t>(x));
  const double w = x - static_cast<double>(i);
  std::array<int, 3> rgb{};
  for (std::size_t c = 0; c < 3; ++c)
    rgb[c] = static_cast<int>(std::lround((1 - w) * stops[i][c] + w * stops[i + 1][c]));
  return detail::hex_colour(rgb);
}

/// The map as an SVG <linearGradient id="id"> from left (f = 0) to right (f = 1) (contract 2);
/// goes inside <defs>. REQUIRES: id an XML name.
inline std::string diverging_gradient(const std::string& id) {
  const auto& stops = diverging_stops();
  std::string out = "<linearGradient id=\"" + id + "\" x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\">";
  for (std::size_t k = 0; k < stops.size(); ++k)
    out += "<stop offset=\"" + std::to_string(k * 100 / (stops.size() - 1)) + "%\" stop-color=\"" + detail::hex_colour(stops[k]) + "\"/>";
  return out + "</linearGradient>\n";
}

}  // namespace sphtroch
