// sphtroch/census/tangency_refinement.hpp — a tangency node (two branches that touch) put on the
// tangency conditions instead of the closest approach of the branches. Eigen only.
//
//   sphtroch::TangencyPair r = sphtroch::refine_tangency_pair(train, 1.0L, 2.5L);  // seeds t1, t2 (long double)
//   r.t1, r.t2;  r.points_evaluated;   // TracerCurve::point calls made (0 or 4)
//
// Why: where two branches touch, P(t1) = P(t2) has a double root; Newton on it (refinement.hpp)
// is ill conditioned and from double input the position is only fixed to ~sqrt(eps) ~ 1e-8
// (issue 13: the polyline and root censuses then disagree at n = 5/2, a3 = 1.0938177365904715).
// The tangency conditions are well conditioned: the two branches have planet angles b and -b
// (root_census.hpp step 1) and touch exactly where b is a stationary point of the root census's
// g (root_function.hpp) — a simple root of g'(b), i.e. of a quadratic in cos b, in closed form. So
// b* = the stationary point nearest to the seed's planet angle, and each branch parameter moves
// by (its planet-angle error) / n, with theta3 = n theta2 + theta_p (Eq. 3). The result is the
// position of the root census's tangency node (Rz(t1) C(b*)) to rounding.
// A seed whose planet angles are not (b, -b) with b within kTangencySeedReach of a stationary
// point (a touching pair at a pole, where b1 = b2), or whose moved pair would meet less closely
// than the seed (|P(t1) - P(t2)| larger; 4 curve evaluations), is returned unchanged.
#pragma once

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/map/root_function.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sphtroch {

/// How far (radians of planet angle) a seed may be from the tangency conditions to be moved (the
/// quadratic gap model of polyline_census.hpp puts its seed within ~1e-3 of it on small curves).
constexpr double kTangencySeedReach = 0.05;

struct TangencyPair {
  long double t1 = 0, t2 = 0;        // branch parameters theta2
  bool moved = false;                // put on the tangency conditions (else the seed, unchanged)
  long double gap = -1;              // moved: |P(t1) - P(t2)| of the result (chord); else -1
  std::size_t points_evaluated = 0;  // TracerCurve::point calls made (for the work counters)
};

/// (t1, t2) moved onto the tangency conditions (see header); unchanged when out of reach.
inline TangencyPair refine_tangency_pair(const GearTrain& train, long double t1, long double t2) {
  using Real = long double;
  const Real pi = RootFunction<Real>::pi();
  const RootFunction<Real> h(train);
  const Real n = static_cast<Real>(train.ratio().p()) / static_cast<Real>(train.ratio().q());
  const Real phase = train.phase();
  // Planet angles wrapped to (-pi, pi].
  auto planet = [&](Real tt) { return std::remainder(n * tt + phase, 2 * pi); };
  const Real b1 = planet(t1), b2 = planet(t2);
  const Real s = b1 >= 0 ? Real(1) : Real(-1);
  Real best = 0, best_d = static_cast<Real>(kTangencySeedReach);
  bool found = false;
  for (int label = 0; label < 2; ++label)
    if (const auto b = h.stationary(label)) {
      const Real d = std::abs(s * *b - b1);
      if (d < best_d) {
        best_d = d;
        best = *b;
        found = true;
      }
    }
  if (!found) return {t1, t2, false, -1, 0};
  const Real d2 = std::remainder(-s * best - b2, 2 * pi);
  if (!(std::abs(d2) < static_cast<Real>(kTangencySeedReach))) return {t1, t2, false, -1, 0};
  const Real r1 = t1 + (s * best - b1) / n, r2 = t2 + d2 / n;
  // Accept only a pair that meets at least as closely as the seed (it should, to rounding).
  const TracerCurve<Real> curve(train);
  const Real before = (curve.point(t1) - curve.point(t2)).norm(), after = (curve.point(r1) - curve.point(r2)).norm();
  if (!(after <= std::max(before, static_cast<Real>(1e-13L)))) return {t1, t2, false, -1, 4};
  return {r1, r2, true, after, 4};
}

}  // namespace sphtroch
