// sphtroch/census/refinement.hpp — Newton refinement of a self-intersection on the true curve.
//
//   sphtroch::TracerCurve<double> curve(train);
//   auto r = sphtroch::refine_branch_pair(curve, 1.55, 4.70);   // seeds near a node
//   if (r.status == sphtroch::RefineStatus::converged) { r.t1; r.t2; r.residual; }
//
// Solves P(t1) = P(t2) (three equations, two unknowns, t1 != t2) as the closest approach of two
// branches: Gauss–Newton on F(t1, t2) = P(t1) - P(t2) with Jacobian J = [v(t1), -v(t2)],
//   (J^T J + mu I) dt = -J^T F,
// with a small Levenberg damping mu that only matters where J loses rank (touching branches,
// where convergence is linear instead of quadratic). At a transversal crossing the iteration
// converges quadratically and the node position is accurate to a few ulp of Scalar divided by
// the sine of the crossing angle. Non-convergence is a status, never an exception.
#pragma once

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/types.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

namespace sphtroch {

enum class RefineStatus { converged, max_iterations, left_bracket };

inline const char* to_string(RefineStatus s) {
  switch (s) {
    case RefineStatus::converged: return "converged";
    case RefineStatus::max_iterations: return "max_iterations";
    case RefineStatus::left_bracket: return "left_bracket";
  }
  return "?";
}

template <typename Scalar>
struct RefinedPair {
  Scalar t1{0}, t2{0};
  Scalar residual{0};     // |P(t1) - P(t2)| at the result
  std::size_t iterations = 0;
  std::size_t evaluations = 0;  // TracerCurve calls made (point and velocity), exactly
  RefineStatus status = RefineStatus::max_iterations;
};

struct RefineSettings {
  std::size_t max_iterations = 200;
  /// The solution may not move further than this from the seed (radians of theta2).
  double max_travel = 0.5;
};

/// Closest approach of the branches through t1 and t2 (see header). Stops when the step is
/// below a few ulp of the parameters or the residual stops decreasing.
template <typename Scalar>
RefinedPair<Scalar> refine_branch_pair(const TracerCurve<Scalar>& curve, Scalar t1, Scalar t2,
                                       const RefineSettings& settings = {}) {
  using std::abs;
  using std::sqrt;
  const Scalar eps = std::numeric_limits<Scalar>::epsilon();
  const Scalar seed1 = t1, seed2 = t2;
  RefinedPair<Scalar> out;
  Vector3<Scalar> F = curve.point(t1) - curve.point(t2);
  out.evaluations = 2;
  Scalar best = F.norm();
  std::size_t stalls = 0;
  for (std::size_t it = 0; it < settings.max_iterations; ++it) {
    out.iterations = it + 1;
    const Vector3<Scalar> v1 = curve.velocity(t1);
    const Vector3<Scalar> v2 = curve.velocity(t2);
    out.evaluations += 2;
    const Scalar a = v1.squaredNorm(), b = -v1.dot(v2), c = v2.squaredNorm();
    const Scalar g1 = v1.dot(F), g2 = -v2.dot(F);
    const Scalar mu = Scalar(64) * eps * (a + c);
    const Scalar det = (a + mu) * (c + mu) - b * b;
    if (!(det > Scalar(0))) break;
    const Scalar d1 = -((c + mu) * g1 - b * g2) / det;
    const Scalar d2 = -((a + mu) * g2 - b * g1) / det;
    t1 += d1;
    t2 += d2;
    if (abs(t1 - seed1) > Scalar(settings.max_travel) || abs(t2 - seed2) > Scalar(settings.max_travel)) {
      out.status = RefineStatus::left_bracket;
      break;
    }
    F = curve.point(t1) - curve.point(t2);
    out.evaluations += 2;
    const Scalar r = F.norm();
    const Scalar step = abs(d1) + abs(d2);
    const Scalar scale = Scalar(1) + abs(t1) + abs(t2);
    if (r < best) {
      best = r;
      stalls = 0;
    } else {
      ++stalls;
    }
    if (step <= Scalar(4) * eps * scale || r == Scalar(0) || stalls >= 3) {
      out.status = RefineStatus::converged;
      break;
    }
  }
  out.t1 = t1;
  out.t2 = t2;
  out.residual = F.norm();
  return out;
}

}  // namespace sphtroch
