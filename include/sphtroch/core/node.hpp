// sphtroch/core/node.hpp — the vocabulary of the census results, shared by every method: nodes,
// cusps and the class of a curve.
//
// Words (docs/design.md): a *branch* is a parameter value theta2 at which the curve passes through a
// point; a *node* is a point through which two or more branches pass; its kind is `crossing`
// when at least one pair of its branches crosses, `tangency` when every pair only touches.
// A *cusp* is a parameter where the velocity is exactly zero.
//
//   for (const sphtroch::Node& node : sphtroch::root_census(train).nodes)
//     node.position, node.kind, node.params;   // unit vector, crossing/tangency, theta2 of each branch
#pragma once

#include "sphtroch/core/types.hpp"

#include <cstddef>
#include <vector>

namespace sphtroch {

enum class NodeKind { crossing, tangency };

inline const char* to_string(NodeKind k) { return k == NodeKind::crossing ? "crossing" : "tangency"; }

struct Node {
  Vector3d position = Vector3d::Zero();  // unit vector, base frame
  std::vector<double> params;            // theta2 of every branch through it, in [0, period), ascending
  std::size_t branches = 0;              // params.size()
  NodeKind kind = NodeKind::crossing;
  double angle = 0.0;  // largest angle between two branch tangent lines at the node, radians in [0, pi/2]
  std::size_t crossing_pairs = 0;   // branch pairs that cross here
  std::size_t tangency_pairs = 0;   // branch pairs that only touch here
};

struct Cusp {
  Vector3d position = Vector3d::Zero();  // unit vector, base frame
  double param = 0.0;                    // theta2 in [0, period)
  double speed = 0.0;                    // |dP/dtheta2| evaluated there (0 up to rounding)
};

/// The class of a curve, as the report names them.
enum class CurveClass { simple_curve, nodes, cusps, nodes_and_cusps };

/// "simple curve", "nodes", "cusps", "nodes and cusps".
inline const char* to_string(CurveClass c) {
  switch (c) {
    case CurveClass::simple_curve: return "simple curve";
    case CurveClass::nodes: return "nodes";
    case CurveClass::cusps: return "cusps";
    case CurveClass::nodes_and_cusps: return "nodes and cusps";
  }
  return "?";
}

inline CurveClass curve_class(std::size_t nodes, std::size_t cusps) {
  return nodes > 0 ? (cusps > 0 ? CurveClass::nodes_and_cusps : CurveClass::nodes)
                   : (cusps > 0 ? CurveClass::cusps : CurveClass::simple_curve);
}

}  // namespace sphtroch
