// sphtroch/exact/interval_trig.hpp — enclosures of sin and cos over an interval of radians, for
// CGAL's Interval_nt (which has the field operations and sqrt, not the trigonometric functions).
//
//   sphtroch::RoundingGuard upward;   // interval arithmetic REQUIRES the upward rounding mode
//   sphtroch::Interval s = sphtroch::interval_sin(sphtroch::Interval(0.1, 2.0));  // [0.0998.., 1]
//
// Contract: for every real x in X, sin(x) lies in interval_sin(X) (the same for cos).
// How: the extremes of sin over [lo, hi] are at the ends or at pi/2 + k pi inside. The ends are
// evaluated by the C library and widened outward by kTrigUlps ulps: this rests on the library's
// error bound (glibc documents at most 1 ulp for sin/cos of a double on x86-64; MPFR at 200
// bits confirms it in test_precision_points.cpp). Whether an interior extreme lies inside is decided
// with a margin (1e-9 of a period) in the safe direction: a doubtful extreme is counted, which
// only widens the result. Intervals of 2 pi or more give [-1, 1].
#pragma once

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>

namespace sphtroch {

/// The interval type of the certified solvers. Its operations REQUIRE the rounding mode upward:
/// hold a RoundingGuard (it sets the mode and restores the caller's) while computing with it.
using Interval = CGAL::Interval_nt<false>;
using RoundingGuard = CGAL::Protect_FPU_rounding<true>;

/// Outward widening of a library sin/cos value, in ulps (the library's bound is 1).
constexpr int kTrigUlps = 2;

namespace interval_trig_detail {

inline double widen_down(double x) {
  for (int i = 0; i < kTrigUlps; ++i) x = std::nextafter(x, -2.0);
  return std::max(x, -1.0);
}

inline double widen_up(double x) {
  for (int i = 0; i < kTrigUlps; ++i) x = std::nextafter(x, 2.0);
  return std::min(x, 1.0);
}

/// Whether [lo, hi] may contain a point offset + 2 pi k (k integer); true when in doubt.
inline bool may_contain(double lo, double hi, double offset) {
  constexpr double kTwoPi = 6.283185307179586;
  constexpr double kMargin = 1e-9;
  const double a = (lo - offset) / kTwoPi - kMargin;
  const double b = (hi - offset) / kTwoPi + kMargin;
  return std::floor(b) >= std::ceil(a);
}

}  // namespace interval_trig_detail

/// Contains sin(x) for every x in `x` (see the header for the guarantee).
inline Interval interval_sin(const Interval& x) {
  namespace d = interval_trig_detail;
  constexpr double kHalfPi = 1.5707963267948966;
  const double lo = x.inf(), hi = x.sup();
  if (!(hi - lo < 6.283)) return Interval(-1.0, 1.0);  // also NaN ends
  const RoundingGuard nearest(CGAL_FE_TONEAREST);       // the library's bound holds in this mode
  const double s_lo = std::sin(lo), s_hi = std::sin(hi);
  const double top = d::may_contain(lo, hi, kHalfPi) ? 1.0 : d::widen_up(std::max(s_lo, s_hi));
  const double bottom = d::may_contain(lo, hi, -kHalfPi) ? -1.0 : d::widen_down(std::min(s_lo, s_hi));
  return Interval(bottom, top);
}

/// Contains cos(x) for every x in `x`.
inline Interval interval_cos(const Interval& x) {
  namespace d = interval_trig_detail;
  constexpr double kPi = 3.141592653589793;
  const double lo = x.inf(), hi = x.sup();
  if (!(hi - lo < 6.283)) return Interval(-1.0, 1.0);
  const RoundingGuard nearest(CGAL_FE_TONEAREST);
  const double c_lo = std::cos(lo), c_hi = std::cos(hi);
  const double top = d::may_contain(lo, hi, 0.0) ? 1.0 : d::widen_up(std::max(c_lo, c_hi));
  const double bottom = d::may_contain(lo, hi, kPi) ? -1.0 : d::widen_down(std::min(c_lo, c_hi));
  return Interval(bottom, top);
}

/// The same names for doubles, so that one template evaluates a function in either type.
inline double interval_sin(double x) { return std::sin(x); }
inline double interval_cos(double x) { return std::cos(x); }

}  // namespace sphtroch
