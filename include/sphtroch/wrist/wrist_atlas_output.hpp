// sphtroch/wrist/wrist_atlas_output.hpp — a 2-motor wrist's fold atlas (wrist_atlas.hpp) as JSON and
// as text, for `sphtroch wrist atlas` and every front end that reports it.
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   sphtroch::WristAtlasResult r;   // from sphtroch::wrist_fold_atlas(wrist)
//   nlohmann::json j = sphtroch::wrist_atlas_json(wrist, r);   // the schema below
//   std::string t = sphtroch::wrist_atlas_text(wrist, r);      // for people
//
// JSON: "certified", "cell_width" (radians of joint motion), "enclosure" (radians: every fold
// point within it of a listed point, when certified), "cells" [{"motors" [[lo, hi], [lo, hi]]
// (radians, motor j's range as searched), "image" [[lo, hi] x 3] (the box holding P over the
// cell), "point" [x, y, z] (a fold point proved in the cell, unit; null when none),
// "point_motors" [u_1, u_2] (null with it)}], "polylines" [{"points" [[x, y, z], ...], "motors"
// [[u_1, u_2], ...], "closed"}], "cusps" [{"point" [x, y, z], "motors" [u_1, u_2], "polyline"}]
// (estimated where the kernel of dP turns across the curve, wrist_cusps.hpp; not certified),
// "cells_without_point", "wrist" (as wrist ik's), "certificate"
// {"method", "why" ("" when certified), "boxes"}. Numbers are doubles printed to round-trip.
#pragma once

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_atlas_result.hpp"
#include "sphtroch/wrist/wrist_ik_output.hpp"  // wrist_json, wrist_tuple_text

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace sphtroch {

inline nlohmann::json wrist_atlas_json(const Wrist& wrist, const WristAtlasResult& r) {
  nlohmann::json j;
  j["certified"] = r.certified;
  j["cell_width"] = r.cell_width;
  j["enclosure"] = r.enclosure;
  nlohmann::json cells = nlohmann::json::array();
  for (const WristFoldCell& c : r.cells)
    cells.push_back({{"motors", c.motors},
                     {"image", c.image},
                     {"point", c.has_point ? nlohmann::json(c.point) : nlohmann::json(nullptr)},
                     {"point_motors", c.has_point ? nlohmann::json(c.point_motors) : nlohmann::json(nullptr)}});
  j["cells"] = cells;
  nlohmann::json lines = nlohmann::json::array();
  for (const WristFoldPolyline& l : r.polylines) {
    nlohmann::json points = nlohmann::json::array(), motors = nlohmann::json::array();
    for (const std::size_t i : l.cells) {
      points.push_back(r.cells[i].point);
      motors.push_back(r.cells[i].point_motors);
    }
    lines.push_back({{"points", points}, {"motors", motors}, {"closed", l.closed}});
  }
  j["polylines"] = lines;
  nlohmann::json cusps = nlohmann::json::array();
  for (const WristCusp& c : r.cusps) cusps.push_back({{"point", c.point}, {"motors", c.motors}, {"polyline", c.polyline}});
  j["cusps"] = cusps;
  j["cells_without_point"] = r.cells_without_point;
  j["wrist"] = wrist_json(wrist, r.periods);
  j["certificate"] = {{"method", "interval bisection of the motor torus: cells where det[P, dP/du1, dP/du2] excludes 0 dropped; "
                                 "a fold point proved in each cell left by the Krawczyk test on a line"},
                      {"why", r.why},
                      {"boxes", r.boxes}};
  return j;
}

inline std::string wrist_atlas_text(const Wrist& wrist, const WristAtlasResult& r) {
  std::ostringstream out;
  out << "wrist: " << wrist.joints() << " joints, " << wrist.motors() << " motors, coupling " << wrist.coupling_text() << ", periods "
      << wrist_tuple_text(r.periods) << "\n";
  out << "critical curve: " << r.cells.size() << " cells of " << number_text(r.cell_width) << " rad of joint motion where det may vanish"
      << " (every other cell proved det != 0), " << r.cells_without_point << " without a proved fold point\n";
  out << "fold polylines: " << r.polylines.size() << ", every fold point within " << number_text(r.enclosure) << " rad of a vertex"
      << (r.certified ? " (certified)" : " (NOT certified: " + r.why + ")") << "\n";
  out << "cusps: " << r.cusps.size() << " (estimated along the polylines, not certified)\n";
  std::size_t id = 0;
  for (const WristFoldPolyline& l : r.polylines) {
    const WristFoldCell& first = r.cells[l.cells.front()];
    out << "  F" << ++id << "  " << l.cells.size() << " points, " << (l.closed ? "closed" : "open") << ", from "
        << wrist_tuple_text({first.point[0], first.point[1], first.point[2]}) << "\n";
  }
  return out.str();
}

}  // namespace sphtroch
