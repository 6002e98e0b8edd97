// sphtroch/draw/mark_density.hpp — which node and cusp markers a picture draws: all of them, none,
// or (automatic, the default of `sphtroch plot`, Python's plot and the explorer) all of them up to
// kAutoMarkLimit marks and none above it, so that a dense curve (a clinostat-like n = 133/200 has
// 26,602 nodes) stays visible. One rule for every front end; the picture states what it left out.
//
//   const sphtroch::MarkChoice m = sphtroch::choose_marks(sphtroch::MarkMode::automatic, 26602, 0);
//   m.draw;   // false
//   m.note;   // "26602 node and cusp markers hidden (more than 200)"
//
// Contracts:
//  1. all: draw every mark. none: draw none (note says how many were hidden, when any).
//  2. automatic: draw every mark when nodes + cusps <= kAutoMarkLimit, none otherwise. A ring is
//     ~1/95 of the picture's width across (svg_plot.hpp's PlotLayout::marker_radius): 200 rings
//     cover at most ~7% of the sphere's disk, more begin to hide the path they mark.
//  3. The curve is dense when the automatic rule hides its marks (dense_curve): the explorer then
//     draws its pitch cones off by default.
#pragma once

#include "sphtroch/core/errors.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace sphtroch {

/// Most marks (nodes + cusps) the automatic rule draws (contract 2).
constexpr std::size_t kAutoMarkLimit = 200;

enum class MarkMode { automatic, all, none };

struct MarkChoice {
  bool draw = true;   // draw the node and cusp markers
  std::string note;   // empty when every mark is drawn; else how many were hidden and why
};

/// "auto", "all" or "none". Throws InvalidInput(field).
inline MarkMode parse_mark_mode(std::string_view text, const std::string& field = "markers") {
  if (text == "auto") return MarkMode::automatic;
  if (text == "all") return MarkMode::all;
  if (text == "none") return MarkMode::none;
  throw InvalidInput(field, std::string(text), "not a marker mode",
                     "auto (all up to " + std::to_string(kAutoMarkLimit) + " marks, none above), all, none");
}

/// True when the automatic rule hides the marks of a curve with this many nodes and cusps.
inline bool dense_curve(std::size_t nodes, std::size_t cusps) { return nodes + cusps > kAutoMarkLimit; }

/// What a picture of a curve with `nodes` nodes and `cusps` cusps draws in `mode` (header).
inline MarkChoice choose_marks(MarkMode mode, std::size_t nodes, std::size_t cusps) {
  const std::size_t marks = nodes + cusps;
  MarkChoice c;
  c.draw = mode == MarkMode::all || (mode == MarkMode::automatic && !dense_curve(nodes, cusps));
  if (c.draw || marks == 0) return c;
  c.note = std::to_string(marks) + " node and cusp markers hidden";
  if (mode == MarkMode::automatic) c.note += " (more than " + std::to_string(kAutoMarkLimit) + ")";
  return c;
}

}  // namespace sphtroch
