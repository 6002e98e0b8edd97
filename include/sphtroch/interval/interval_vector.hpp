// sphtroch/interval/interval_vector.hpp — 3-vectors of intervals (or of doubles: the same
// templates evaluate one formula in either type) and the little algebra the certified solvers
// share: dot, cross, difference, a point as thin intervals, hulls and overlap tests.
//
//   sphtroch::RoundingGuard upward;   // REQUIRED while intervals are computed
//   const sphtroch::IntervalVec3 a = sphtroch::thin_vector(Vector3d::UnitX()), b = sphtroch::thin_vector(Vector3d::UnitY());
//   sphtroch::cross(a, b)[2];          // contains 1: the products are outward rounded
//
// Contract: each result encloses the exact result for every choice of the operands inside their
// intervals (interval.hpp's arithmetic); with doubles, the plain floating-point result.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/interval/interval_vector.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/types.hpp"
#include "sphtroch/interval/interval.hpp"

#include <algorithm>
#include <array>

namespace sphtroch {

/// A 3-vector of T (double or Interval).
template <typename T>
using Vec3 = std::array<T, 3>;
/// A vector of three intervals: a box in space.
using IntervalVec3 = Vec3<Interval>;

/// a x b (b's components of any type that multiplies T).
template <typename T, typename U>
Vec3<T> cross(const Vec3<T>& a, const std::array<U, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
/// a . b, summed in the order x, y, z (b: anything indexable 0..2).
template <typename T, typename U>
T dot(const Vec3<T>& a, const U& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
/// a - b.
template <typename T>
Vec3<T> difference(const Vec3<T>& a, const Vec3<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
/// The point v as three point intervals.
inline IntervalVec3 thin_vector(const Vector3d& v) { return {Interval(v.x()), Interval(v.y()), Interval(v.z())}; }
/// Whether some component excludes 0 (then the vector is not 0 anywhere in the box).
inline bool excludes_zero(const IntervalVec3& v) { return !may_vanish(v[0]) || !may_vanish(v[1]) || !may_vanish(v[2]); }
/// The smallest box holding both.
inline IntervalVec3 hull(const IntervalVec3& a, const IntervalVec3& b) {
  IntervalVec3 h;
  for (int k = 0; k < 3; ++k) h[k] = Interval(std::min(a[k].inf(), b[k].inf()), std::max(a[k].sup(), b[k].sup()));
  return h;
}
/// Whether the two boxes meet.
inline bool boxes_meet(const IntervalVec3& a, const IntervalVec3& b) {
  for (int k = 0; k < 3; ++k)
    if (a[k].sup() < b[k].inf() || b[k].sup() < a[k].inf()) return false;
  return true;
}

}  // namespace sphtroch
