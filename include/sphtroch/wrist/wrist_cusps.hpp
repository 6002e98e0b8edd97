// sphtroch/wrist/wrist_cusps.hpp — where the fold polylines of a 2-motor wrist's atlas
// (wrist_atlas.hpp) pass a cusp: the kernel of dP turns across the critical curve's tangent
// between two neighbouring fold points. An estimate for the picture and the report, not a proof.
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   const sphtroch::WristAtlasResult atlas = sphtroch::wrist_fold_atlas(wrist, 0.1);
//   sphtroch::wrist_fold_cusps(wrist, atlas).size();   // 0: the base x gear train's folds are circles
//
// At a fold point u (D(u) = 0) the columns v_j = omega_j x P of dP are parallel; the kernel k of
// dP is (|v_2|^2, -v_1 . v_2) or (-v_1 . v_2, |v_1|^2), the longer. The image of the critical
// curve has a cusp where k is tangent to the curve, that is where g = k . grad D / (|k| |grad D|)
// vanishes. Along each polyline k and grad D are each kept of one sense (flipped when their dot with
// the previous point's is negative: grad D turns over where the curve passes a node of D), and a
// change of sign of g between two points where |g| >= kWristCuspSignFloor, with no such point between
// them, is reported as a cusp at the fold point between them of least |g| (its P and motors). A
// closed polyline is read from its first point, not round its seam. Doubles (wrist_critical.hpp's
// `at`); the cusp lies within about one cell of the point reported when the curve is smooth there;
// a cusp where g only touches 0, or in a stretch where |g| stays below the floor, is not seen.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_cusps.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/interval/interval.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_atlas_result.hpp"
#include "sphtroch/wrist/wrist_critical.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace sphtroch {

namespace wrist_cusps_detail {

/// The kernel of dP at the fold point u (unit, in motor space) and grad D there (unit); zero vectors when degenerate.
inline std::array<std::array<double, 2>, 2> kernel_and_gradient(const WristCritical& critical, const std::array<double, 2>& u) {
  const WristFoldValue<double> v = critical.at(PointN<2>{u[0], u[1]});
  const Vector3d p(v.point[0], v.point[1], v.point[2]);
  const Vector3d v1 = Vector3d(v.omega[0][0], v.omega[0][1], v.omega[0][2]).cross(p);
  const Vector3d v2 = Vector3d(v.omega[1][0], v.omega[1][1], v.omega[1][2]).cross(p);
  std::array<double, 2> k{v2.squaredNorm(), -v1.dot(v2)};
  const std::array<double, 2> k2{-v1.dot(v2), v1.squaredNorm()};
  if (std::hypot(k2[0], k2[1]) > std::hypot(k[0], k[1])) k = k2;
  std::array<double, 2> g{v.det_gradient[0], v.det_gradient[1]};
  for (auto* w : {&k, &g}) {
    const double n = std::hypot((*w)[0], (*w)[1]);
    if (n > 0) (*w)[0] /= n, (*w)[1] /= n;
  }
  return {k, g};
}

}  // namespace wrist_cusps_detail

/// Below this |g| the sign is not read (a stretch where the kernel runs along the curve: its image a point).
constexpr double kWristCuspSignFloor = 1e-3;

/// The cusps along the atlas's polylines (see header). REQUIRES 2 motors. In the caller's rounding mode.
inline std::vector<WristCusp> wrist_fold_cusps(const Wrist& wrist, const WristAtlasResult& atlas) {
  const RoundingGuard upward;
  const WristCritical critical(wrist);
  const RoundingGuard nearest(CGAL_FE_TONEAREST);
  std::vector<WristCusp> out;
  for (std::size_t l = 0; l < atlas.polylines.size(); ++l) {
    const std::vector<std::size_t>& cells = atlas.polylines[l].cells;
    std::vector<double> g;
    std::array<double, 2> kp{0, 0}, gp{0, 0};
    for (const std::size_t i : cells) {
      auto [k, grad] = wrist_cusps_detail::kernel_and_gradient(critical, atlas.cells[i].point_motors);
      if (k[0] * kp[0] + k[1] * kp[1] < 0) k = {-k[0], -k[1]};
      if (grad[0] * gp[0] + grad[1] * gp[1] < 0) grad = {-grad[0], -grad[1]};  // through a node of the curve
      kp = k, gp = grad;
      g.push_back(k[0] * grad[0] + k[1] * grad[1]);
    }
    std::size_t last = cells.size();  // the last point whose |g| is read
    for (std::size_t b = 0; b < cells.size(); ++b) {
      if (std::fabs(g[b]) < kWristCuspSignFloor) continue;
      if (last < cells.size() && g[last] * g[b] < 0) {
        std::size_t at = last;  // the smallest |g| from last to b
        for (std::size_t x = last; x <= b; ++x)
          if (std::fabs(g[x]) < std::fabs(g[at])) at = x;
        const WristFoldCell& c = atlas.cells[cells[at]];
        out.push_back({c.point, c.point_motors, l});
      }
      last = b;
    }
  }
  return out;
}

}  // namespace sphtroch
