// sphtroch/core/arc_crossing_point.hpp — where two crossing great-circle arcs meet (a construction in
// double; Eigen only). Pairs come from find_self_crossings (self_crossings.hpp), which decides
// exactly THAT they cross; this computes WHERE, approximately.
//
//   for (const sphtroch::EdgePair& e : crossings)   // find_self_crossings(v, true).crossings
//     Eigen::Vector3d x = sphtroch::arc_crossing_point(v[e.i], v[e.i + 1], v[e.j], v[(e.j + 1) % v.size()]);
//
// The two great circles meet at +-m, m = (a x b) x (c x d); the point returned is the one of the
// two that lies on arc ab (the side of a and b), normalised. Error bound: about 4 eps / sin(phi)
// radians, phi the angle between the two circles (1e-15 rad for a right angle); a near-tangent
// pair loses accuracy as 1/phi. Throws InvalidInput("arcs") when the circles coincide or an arc
// is degenerate (a x b or c x d or m is zero or not finite).
#pragma once

#include "sphtroch/core/errors.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace sphtroch {

inline Eigen::Vector3d arc_crossing_point(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                          const Eigen::Vector3d& d) {
  const Eigen::Vector3d n1 = a.cross(b).normalized();
  const Eigen::Vector3d n2 = c.cross(d).normalized();
  const Eigen::Vector3d m = n1.cross(n2);
  const double norm = m.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw InvalidInput("arcs", "(a, b), (c, d)", "the great circles coincide or an arc is degenerate",
                       "two arcs on distinct great circles, each shorter than pi with distinct ends");
  const Eigen::Vector3d x = m / norm;
  // On arc ab the point is a positive combination of a and b: the side of (a + b).
  return x.dot(a.normalized() + b.normalized()) >= 0.0 ? x : Eigen::Vector3d(-x);
}

}  // namespace sphtroch
