// sphtroch/exact/interval_trig.hpp — enclosures of sin and cos over an interval of radians, for
// CGAL's Interval_nt (which has the field operations and sqrt, not the trigonometric functions).
//
//   sphtroch::RoundingGuard upward;   // interval arithmetic REQUIRES the upward rounding mode
//   sphtroch::Interval s = sphtroch::interval_sin(sphtroch::Interval(0.1, 2.0));  // [0.0998.., 1]
//
// Contract: for every real x in X, sin(x) lies in interval_sin(X) (the same for cos).
// How: the extremes of sin over [lo, hi] are at the ends or at pi/2 + k pi inside. The ends are
// evaluated by the C library in round-to-nearest and widened outward by at least 2 ulps:
// this rests on the library's error bound (glibc documents at most 1 ulp for sin/cos of a double
// on x86-64; MPFR at 200 bits confirms it in test_precision_points.cpp). Whether an interior
// extreme lies inside is decided with a margin (1e-9 of a quarter turn) in the safe direction: a
// doubtful extreme is counted, which only widens the result. Intervals of 2 pi or more give [-1, 1].
#pragma once

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <utility>

namespace sphtroch {

/// The interval type of the certified solvers. Its operations REQUIRE the rounding mode upward:
/// hold a RoundingGuard (it sets the mode and restores the caller's) while computing with it.
using Interval = CGAL::Interval_nt<false>;
using RoundingGuard = CGAL::Protect_FPU_rounding<true>;

namespace interval_trig_detail {

/// x lowered / raised by at least 2 ulps (the library's bound is 1): |x| 2^-50 is 4 to 8 ulps, and the absolute term
/// covers subnormals; computed in round-to-nearest (half an ulp lost), clamped to [-1, 1].
inline double widen_down(double x) { return std::max(x - (std::fabs(x) * 0x1p-50 + 1e-300), -1.0); }
inline double widen_up(double x) { return std::min(x + (std::fabs(x) * 0x1p-50 + 1e-300), 1.0); }

/// Whether [lo, hi] may contain a point offset + k pi / 2 with k = 4 j + shift, in quarter turns
/// from `base` (t = (x - base) / (pi / 2)); true when in doubt (a margin of 1e-9 quarter turn).
inline bool may_contain_quarter(double t_lo, double t_hi, int shift) {
  constexpr double kMargin = 1e-9;
  const double a = (t_lo - shift) / 4 - kMargin, b = (t_hi - shift) / 4 + kMargin;
  return std::floor(b) >= std::ceil(a);
}

}  // namespace interval_trig_detail

/// Encloses sin and cos over `x`: {sin, cos}. REQUIRES the rounding mode to nearest (the
/// library's bound holds in that mode); interval_sincos and interval_sincos_all set it.
inline std::pair<Interval, Interval> interval_sincos_in_nearest_mode(const Interval& x) {
  namespace d = interval_trig_detail;
  const double lo = x.inf(), hi = x.sup();
  if (!(hi - lo < 6.283)) return {Interval(-1.0, 1.0), Interval(-1.0, 1.0)};  // also NaN ends
  if (lo == hi) {  // a point: no extreme inside
    const double s = std::sin(lo), c = std::cos(lo);
    return {Interval(d::widen_down(s), d::widen_up(s)), Interval(d::widen_down(c), d::widen_up(c))};
  }
  const double s_lo = std::sin(lo), s_hi = std::sin(hi), c_lo = std::cos(lo), c_hi = std::cos(hi);
  constexpr double kQuarter = 1.5707963267948966;
  const double t_lo = lo / kQuarter, t_hi = hi / kQuarter;  // quarter turns; errors ~1e-14 << margin
  // Extremes inside: sin = 1 at quarter 1, -1 at quarter 3; cos = 1 at quarter 0, -1 at quarter 2 (mod 4).
  const Interval sine(d::may_contain_quarter(t_lo, t_hi, 3) ? -1.0 : d::widen_down(std::min(s_lo, s_hi)),
                      d::may_contain_quarter(t_lo, t_hi, 1) ? 1.0 : d::widen_up(std::max(s_lo, s_hi)));
  const Interval cosine(d::may_contain_quarter(t_lo, t_hi, 2) ? -1.0 : d::widen_down(std::min(c_lo, c_hi)),
                        d::may_contain_quarter(t_lo, t_hi, 0) ? 1.0 : d::widen_up(std::max(c_lo, c_hi)));
  return {sine, cosine};
}

/// Encloses sin and cos over `x` (see the header for the guarantee): {sin, cos}.
inline std::pair<Interval, Interval> interval_sincos(const Interval& x) {
  const RoundingGuard nearest(CGAL_FE_TONEAREST);
  return interval_sincos_in_nearest_mode(x);
}

/// interval_sincos of each, with one change of rounding mode for all (the mode switches cost
/// more than the sines).
template <std::size_t N>
std::array<std::pair<Interval, Interval>, N> interval_sincos_all(const std::array<Interval, N>& x) {
  const RoundingGuard nearest(CGAL_FE_TONEAREST);
  std::array<std::pair<Interval, Interval>, N> out;
  for (std::size_t k = 0; k < N; ++k) out[k] = interval_sincos_in_nearest_mode(x[k]);
  return out;
}

/// Contains sin(x) for every x in `x`.
inline Interval interval_sin(const Interval& x) { return interval_sincos(x).first; }
/// Contains cos(x) for every x in `x`.
inline Interval interval_cos(const Interval& x) { return interval_sincos(x).second; }

/// The same names for doubles, so that one template evaluates a function in either type.
inline std::pair<double, double> interval_sincos(double x) { return {std::sin(x), std::cos(x)}; }
template <std::size_t N>
std::array<std::pair<double, double>, N> interval_sincos_all(const std::array<double, N>& x) {
  std::array<std::pair<double, double>, N> out;
  for (std::size_t k = 0; k < N; ++k) out[k] = {std::sin(x[k]), std::cos(x[k])};
  return out;
}

}  // namespace sphtroch
