// sphtroch/census/node_json.hpp — nodes and cusps as JSON: the schema of `sphtroch classify
// --json`'s "nodes" and "cusps", which every census's report shares (the gear train's
// classification, the rotation chain's census).
//
//   const sphtroch::RootClassification c = sphtroch::classify_roots(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(2)));
//   nlohmann::json j = sphtroch::node_list_json(c.node_points);   // [{"id": "N1", "position": [x, y, z], ...}]
//
// Node: "id" (N1, N2, ...: the plot's label, the CSV's id), "position" [x, y, z], "longitude" and
// "latitude" (radians), "params" (the branch parameters), "branches", "kind" ("crossing" or
// "tangency"), "angle" (radians), "crossing_pairs", "tangency_pairs". Cusp: "id" (C1, ...),
// "position", "param", "speed".
#pragma once

#include "sphtroch/core/node.hpp"
#include "sphtroch/core/types.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace sphtroch {

/// [x, y, z].
inline nlohmann::json vector3_json(const Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

/// The nodes in the header's schema, numbered in their order.
inline nlohmann::json node_list_json(const std::vector<Node>& nodes) {
  nlohmann::json out = nlohmann::json::array();
  for (const Node& n : nodes)
    out.push_back({{"id", "N" + std::to_string(out.size() + 1)},
                   {"position", vector3_json(n.position)},
                   {"longitude", std::atan2(n.position.y(), n.position.x())},
                   {"latitude", std::asin(std::clamp(n.position.z(), -1.0, 1.0))},
                   {"params", n.params},
                   {"branches", n.branches},
                   {"kind", to_string(n.kind)},
                   {"angle", n.angle},
                   {"crossing_pairs", n.crossing_pairs},
                   {"tangency_pairs", n.tangency_pairs}});
  return out;
}

/// The cusps in the header's schema, numbered in their order.
inline nlohmann::json cusp_list_json(const std::vector<Cusp>& cusps) {
  nlohmann::json out = nlohmann::json::array();
  for (const Cusp& k : cusps)
    out.push_back({{"id", "C" + std::to_string(out.size() + 1)}, {"position", vector3_json(k.position)}, {"param", k.param},
                   {"speed", k.speed}});
  return out;
}

}  // namespace sphtroch
