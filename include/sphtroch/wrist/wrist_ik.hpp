// sphtroch/wrist/wrist_ik.hpp — every inverse-kinematics solution of a geared wrist on its whole
// motor torus, each certified the only root in its box: 2 motors pointing the tool axis at a
// direction, or 3 motors holding an orientation (the square systems of wrist_ik_system.hpp).
//
//   // the base x gear train wrist: twists 0, 1, 0.5; coupling 1,0;0,1;0,2 (n = 2)
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   const sphtroch::WristIkResult r = sphtroch::wrist_ik(wrist, sphtroch::WristTarget::pointing(sphtroch::Vector3d(0.6, 0, 0.8)));
//   r.certified;           // true
//   r.solutions.size();    // 4: 2 |p| with p = 2, the target inside the zone cos(1.5) < z < cos(0.5)
//
// Method (wrist_ik_search.hpp): branch and bound over the torus [0, T_1] x ... (shifted by
// kWristStartOffset of a period, so that round values of u do not fall on box faces), from a grid
// of start boxes in which no joint angle moves more than kWristStartWidth radians. A box is
// excluded when an equation's enclosure (the natural extension met with the mean-value form)
// misses 0, or when the sign's enclosure stays below its value at every true root (|t| |a|, or
// 3). Otherwise the Krawczyk step (interval/krawczyk.hpp's krawczyk_step, Y the inverse of J at
// the box's centre) decides: none (excluded); unique (the one root of f in the box, narrowed by
// further steps to a few ulps, is a true root when the sign is above the system's threshold over
// that enclosure, else the antipode or a half-turn: the box is decided either way); or narrowed
// (the box replaced by its meet with K, again while it shrinks). Undecided boxes below
// kWristNewtonWidth try Newton's method in doubles and epsilon-inflation, whose proof box is grown
// while ||I - Y J(U)|| < 1 (at most one root in U) into a region U: boxes inside a known region
// are done. Undecided boxes below kWristMinWidth are left undecided. Widths are scaled: a motor's
// width times its joint speed sum_i |C_ij| (radians of joint motion).
// A root found twice (on a shared face, or a period apart) is one root: its enclosure lies in the
// other's region, up to whole periods (enclosed; regions moved inward).
// Guarantee: when `certified`, `solutions` holds every solution on the torus once, the root within
// box_radius (radians, every motor) of the printed angles, motors in [0, T_j). Otherwise `why`
// says what is undecided, and `on_fold` that every undecided box may hold a root where J is
// singular (the target on a fold of u -> P(u), or a singular orientation: a double root).
// Cost: refused up front (check_wrist_ik_cost: InvalidInput "coupling" with the count) when the
// start grid would exceed kMaxWristStartBoxes boxes; a search stops after max_boxes boxes or
// kMaxWristUndecided undecided ones (not certified). The work is counted in `boxes`.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_ik.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_ik_result.hpp"
#include "sphtroch/wrist/wrist_ik_search.hpp"
#include "sphtroch/wrist/wrist_target.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sphtroch {

/// Problems whose start grid has more boxes are refused up front (check_wrist_ik_cost).
constexpr double kMaxWristStartBoxes = 200000;

/// The number of start boxes, prod_j max(1, ceil(T_j sum_i |C_ij| / kWristStartWidth)): the
/// search's least work, and what its cost grows with.
inline double wrist_ik_start_boxes(const Wrist& wrist) {
  double boxes = 1;
  for (std::size_t j = 0; j < wrist.motors(); ++j)
    boxes *= std::max(1.0, std::ceil(wrist.period(j) * wrist.joint_speed(j) / kWristStartWidth));
  return boxes;
}

/// Refuses (InvalidInput "coupling") a wrist whose start grid exceeds kMaxWristStartBoxes.
inline void check_wrist_ik_cost(const Wrist& wrist) {
  const double boxes = wrist_ik_start_boxes(wrist);
  if (boxes > kMaxWristStartBoxes)
    throw InvalidInput("coupling", wrist.coupling_text(),
                       "too costly: the motor torus needs " + number_text(boxes) +
                           " start boxes (prod_j T_j sum_i |C_ij| radians of joint motion, 1 radian a box)",
                       "a wrist needing at most " + number_text(kMaxWristStartBoxes) + " start boxes: smaller rates or denominators");
}

/// Every solution of the wrist's inverse kinematics for the target (see header). REQUIRES a
/// target of the wrist's kind (pointing: 2 motors, orientation: 3; InvalidInput otherwise); refuses
/// a wrist above the cost bound (check_wrist_ik_cost). In the caller's rounding mode.
inline WristIkResult wrist_ik(const Wrist& wrist, const WristTarget& target, std::size_t max_boxes = kMaxWristBoxes) {
  check_wrist_ik_cost(wrist);
  if (wrist.motors() == 2) return WristIkSearch<2>(wrist, target, max_boxes).run();
  return WristIkSearch<3>(wrist, target, max_boxes).run();
}

}  // namespace sphtroch
