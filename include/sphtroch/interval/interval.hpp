// sphtroch/interval/interval.hpp — the interval arithmetic of the certified solvers:
// CGAL's Interval_nt (the field operations and sqrt, outward rounded), enclosures of sin and cos
// over an interval of radians and of atan and acos (which Interval_nt lacks), and the mean-value
// forms.
//
//   sphtroch::RoundingGuard upward;   // interval arithmetic REQUIRES the upward rounding mode
//   sphtroch::Interval s = sphtroch::interval_sin(sphtroch::Interval(0.1, 2.0));  // [0.0998.., 1]
//
// Contract: for every real x in X, sin(x) lies in interval_sin(X) (the same for cos).
// How: an interval narrower than kThinTrigWidth takes the mean-value form about its middle c
// (thin_sincos: one library call, first-order sharp). A wider one: the extremes of sin over
// [lo, hi] are at the ends or at pi/2 + k pi inside. The ends are
// evaluated in round-to-nearest and widened outward by at least 2 ulps: this rests on an error
// bound of 1 ulp — glibc's sincos, which documents it on x86-64 (MPFR at 200 bits confirms it in
// tests/synthesis/test_precision_points.cpp), elsewhere (the explorer's WebAssembly module, whose musl documents
// none) core/portable_trig.hpp's sin_cos, faithful, checked against MPFR in
// tests/core/test_portable_trig.cpp (up to 2^20 rad; beyond, [-1, 1] there). Whether an interior
// extreme lies inside is decided with a margin (4e-9 of a quarter turn + 1e-15 |t|) in the safe direction: a
// doubtful extreme is counted, which only widens the result. Intervals of 2 pi or more give [-1, 1].
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/interval/interval.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/portable_trig.hpp"

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

namespace interval_detail {

/// x lowered / raised by at least 2 ulps (the library's bound is 1): |x| 2^-50 is 4 to 8 ulps, and the absolute term
/// covers subnormals; computed in round-to-nearest (half an ulp lost), clamped to [-1, 1].
inline double widen_down(double x) { return std::max(x - (std::fabs(x) * 0x1p-50 + 1e-300), -1.0); }
inline double widen_up(double x) { return std::min(x + (std::fabs(x) * 0x1p-50 + 1e-300), 1.0); }

/// sin(x) and cos(x) in round-to-nearest, within 1 ulp: glibc's sincos (the same algorithm and
/// bound as sin and cos, one argument reduction) where there is one, else portable_trig.hpp's.
inline void sin_cos(double x, double& s, double& c) {
#if defined(__GLIBC__)
  ::sincos(x, &s, &c);
#else
  const SinCos<double> t = sphtroch::sin_cos(x);
  s = t.sin;
  c = t.cos;
#endif
}

/// Which quarter turns k pi / 2 (k mod 4: bit k) [lo, hi] may contain, given in quarter turns
/// t = x / (pi / 2); a doubtful one counts. The margin, 4e-9 quarter turn plus 1e-15 |t|, covers
/// the error of t (~2.6e-16 |t|: pi / 2 rounded, the division) and of t -+ margin (an ulp of t).
/// Beyond 2^40 quarter turns every extreme counts.
inline unsigned quarters_inside(double t_lo, double t_hi) {
  if (!(std::fabs(t_lo) < 0x1p40 && std::fabs(t_hi) < 0x1p40)) return 0xFu;  // beyond exact integer steps
  const double margin = 4e-9 + 1e-15 * std::max(std::fabs(t_lo), std::fabs(t_hi));
  const double first = std::ceil(t_lo - margin), last = std::floor(t_hi + margin);
  if (!(last - first < 3.0)) return last >= first ? 0xFu : 0u;  // all four residues (or none)
  unsigned bits = 0;
  for (double k = first; k <= last; k += 1.0) bits |= 1u << static_cast<unsigned>(k - 4.0 * std::floor(k / 4.0));
  return bits;
}

/// sin and cos over a thin [lo, hi] from one evaluation at its middle c: sin x = sin c +
/// cos(xi) (x - c) with |cos(xi) - cos c| <= r = max |x - c|, so sin lies within sin c +- (|cos c|
/// + r) r over the interval (cos alike). REQUIRES round-to-nearest: r and the bounds are raised
/// by 2^-50 of themselves (each is a few operations on nonnegative doubles, half an ulp apiece)
/// and sin c, cos c widened as the ends of the wide case are.
inline std::pair<Interval, Interval> thin_sincos(double lo, double hi) {
  const double c = lo + 0.5 * (hi - lo);  // in [lo, hi]; no overflow
  const double r = std::max(c - lo, hi - c) * (1.0 + 0x1p-50);
  double s_c, c_c;
  sin_cos(c, s_c, c_c);
  const double ds = (std::fabs(c_c) + r) * r * (1.0 + 0x1p-50), dc = (std::fabs(s_c) + r) * r * (1.0 + 0x1p-50);
  return {Interval(std::max(widen_down(s_c) - ds, -1.0), std::min(widen_up(s_c) + ds, 1.0)),
          Interval(std::max(widen_down(c_c) - dc, -1.0), std::min(widen_up(c_c) + dc, 1.0))};
}

}  // namespace interval_detail

/// Intervals narrower than this (radians) take thin_sincos: one library call instead of two, and
/// as sharp to first order (the extra width is at most 2 r^2).
constexpr double kThinTrigWidth = 1.0 / 8;

/// Encloses sin and cos over `x`: {sin, cos}. REQUIRES the rounding mode to nearest (the
/// library's bound holds in that mode); interval_sincos and interval_sincos_all set it.
inline std::pair<Interval, Interval> interval_sincos_in_nearest_mode(const Interval& x) {
  namespace d = interval_detail;
  const double lo = x.inf(), hi = x.sup();
  if (!(hi - lo < 6.283)) return {Interval(-1.0, 1.0), Interval(-1.0, 1.0)};  // also NaN ends
#if !defined(__GLIBC__)
  if (!(std::fabs(lo) <= kPortableTrigMax && std::fabs(hi) <= kPortableTrigMax))  // no bound known there
    return {Interval(-1.0, 1.0), Interval(-1.0, 1.0)};
#endif
  if (lo != hi && hi - lo < kThinTrigWidth) return d::thin_sincos(lo, hi);
  double s_lo, c_lo, s_hi, c_hi;
  d::sin_cos(lo, s_lo, c_lo);
  if (lo == hi)  // a point: no extreme inside
    return {Interval(d::widen_down(s_lo), d::widen_up(s_lo)), Interval(d::widen_down(c_lo), d::widen_up(c_lo))};
  d::sin_cos(hi, s_hi, c_hi);
  constexpr double kQuarter = 1.5707963267948966;
  const double t_lo = lo / kQuarter, t_hi = hi / kQuarter;  // quarter turns; error ~2.6e-16 |t| < margin
  // Extremes inside: sin = 1 at quarter 1, -1 at quarter 3; cos = 1 at quarter 0, -1 at quarter 2 (mod 4).
  const unsigned inside = d::quarters_inside(t_lo, t_hi);
  const Interval sine(inside & 8u ? -1.0 : d::widen_down(std::min(s_lo, s_hi)),
                      inside & 2u ? 1.0 : d::widen_up(std::max(s_lo, s_hi)));
  const Interval cosine(inside & 4u ? -1.0 : d::widen_down(std::min(c_lo, c_hi)),
                        inside & 1u ? 1.0 : d::widen_up(std::max(c_lo, c_hi)));
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
inline std::pair<double, double> interval_sincos(double x) {
  std::pair<double, double> r;
  interval_detail::sin_cos(x, r.first, r.second);
  return r;
}
template <std::size_t N>
std::array<std::pair<double, double>, N> interval_sincos_all(const std::array<double, N>& x) {
  std::array<std::pair<double, double>, N> out;
  for (std::size_t k = 0; k < N; ++k) out[k] = interval_sincos(x[k]);
  return out;
}

namespace interval_detail {
/// An angle lowered / raised by at least 2 ulps (the library's bound is 1); no clamping.
inline double angle_down(double x) { return x - (std::fabs(x) * 0x1p-50 + 1e-300); }
inline double angle_up(double x) { return x + (std::fabs(x) * 0x1p-50 + 1e-300); }
}  // namespace interval_detail

/// Contains atan(x) for every x in `x` (an unbounded end gives -+pi/2 widened).
inline Interval interval_atan(const Interval& x) {
  namespace d = interval_detail;
  const RoundingGuard nearest(CGAL_FE_TONEAREST);
  return Interval(d::angle_down(std::atan(x.inf())), d::angle_up(std::atan(x.sup())));
}

/// Contains acos(c) for every c in `c` intersected with [-1, 1] (REQUIRES that they meet), in [0, pi]
/// widened: acos decreases, so its ends are those of c swapped.
inline Interval interval_acos(const Interval& c) {
  namespace d = interval_detail;
  const RoundingGuard nearest(CGAL_FE_TONEAREST);
  const double lo = std::max(c.inf(), -1.0), hi = std::min(c.sup(), 1.0);
  return Interval(std::max(d::angle_down(std::acos(hi)), 0.0), d::angle_up(std::acos(lo)));
}

// The mean-value forms: enclosures of a function over a box from its value at the centre and its
// gradient enclosed over the box (first-order sharp).

/// Whether the interval contains 0 (an equation may vanish over the box it encloses).
inline bool may_vanish(const Interval& x) { return x.inf() <= 0.0 && x.sup() >= 0.0; }
/// The midpoint of x as a point interval.
inline Interval centre_of(const Interval& x) { return Interval(0.5 * (x.inf() + x.sup())); }
/// The midpoint of x (a double inside x).
inline double mid(const Interval& x) { return 0.5 * (x.inf() + x.sup()); }
/// Whether a lies in the interior of b.
inline bool strictly_inside(const Interval& a, const Interval& b) { return a.inf() > b.inf() && a.sup() < b.sup(); }

/// The mean-value form of F over a box: F(c) + sum_k dF/dx_k(X) (x_k - c_k) (fc: F at the centre
/// c; df: the gradient enclosed over the box X; dx: X - c). Encloses F over X.
template <int K>
Interval mean_value(const Interval& fc, const Interval* df, const Interval* dx) {
  Interval m = fc;
  for (int k = 0; k < K; ++k) m += df[k] * dx[k];
  return m;
}

/// The radius of x about 0: x lies within [-r, r].
inline double radius(const Interval& x) { return std::max(-x.inf(), x.sup()); }

/// sum_k G_k [-r_k, r_k] = [-s, s] with s = sum_k max|G_k| r_k (outward rounded): the terms of a
/// mean-value form on a box about its centre (r_k = radius(X_k - c_k)), without interval products.
template <int K>
Interval centred_sum(const Interval* g, const double* r) {
  Interval s(0.0);
  for (int k = 0; k < K; ++k) s += r[k] * Interval(radius(g[k]));
  return Interval(-s.sup(), s.sup());
}

/// The mean-value form of the combination sum_j nu_j F_j, its coefficients combined before they
/// meet dx (so what cancels between the F_j cancels): encloses that combination over the box for
/// any nu; a non-finite nu gives [-1, 1] (no information). fc[j], df[j]: as in mean_value.
template <int J, int K>
Interval combined_mean_value(const std::array<double, J>& nu, const std::array<Interval, J>& fc,
                             const std::array<const Interval*, J>& df, const Interval* dx) {
  for (const double v : nu)
    if (!std::isfinite(v)) return Interval(-1.0, 1.0);
  Interval m = nu[0] * fc[0];
  for (int j = 1; j < J; ++j) m += nu[j] * fc[j];
  for (int k = 0; k < K; ++k) {
    Interval coefficient = nu[0] * df[0][k];
    for (int j = 1; j < J; ++j) coefficient += nu[j] * df[j][k];
    m += coefficient * dx[k];
  }
  return m;
}

}  // namespace sphtroch
