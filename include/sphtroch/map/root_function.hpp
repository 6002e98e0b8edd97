// sphtroch/map/root_function.hpp — the root census's function g(b) (root_census.hpp) as a function of both
// the planet angle b and the tracer twist a3, with the derivatives the boundary set needs. Eigen
// only (no Eigen type even): a value type over Real = long double (or any floating type).
//
//   sphtroch::HalfTurn<long double> h(a2, a3, sphtroch::Ratio(5, 2));
//   const long double b = 1.0L;                 // the planet angle, in (0, pi)
//   h.g(b);  h.dg_db(b);  h.dg_da3(b);          // g and its partial derivatives
//   h.stationary(0);                            // stationary point b*, label 0 (or nothing)
//   h.node_roots();                             // #{b in (0, pi): g(b) integer}, off tangencies
//
// Derivation (root_census.hpp, recalled): with C(b) = Rx(a2) Rz(b) Rx(a3) z (Eq. 4 at t = 0),
// az(b) = atan2(y, x) of C(b), a non-pole node of the curve of n = p/q is a b in (0, pi) with
//   g(b) = [ p (2 az(b) - pi) + 2 q b ] / (2 pi)  an integer m,
// and each such b is |p| node points (the |p|-fold symmetry). g'(b) = 0 is a quadratic in
// c = cos b:  A c^2 + B c + C = 0,  A = -q sa2^2 sa3^2,  B = sa2 sa3 ca3 (2 q ca2 + p),
// C = q (sa2^2 + ca2^2 sa3^2) + p sa3^2 ca2. Its two roots c_0 <= c_1 label the stationary points:
// label 0 is the one with the SMALLER cos b (larger b). The labels are continuous in (a2, a3)
// wherever the discriminant is > 0, which is what lets the boundary set follow a stationary point.
//   dg/da3 at fixed b = (p / pi) d az / d a3 = (p / pi) (x y' - y x') / (x^2 + y^2), with
//   x' = ca3 sin b, y' = -(ca3 ca2 cos b - sa3 sa2) (derivatives in a3).
// At a stationary point b*(a3), d/da3 g(b*(a3), a3) = dg/da3 (envelope theorem: g_b = 0 there).
//
// Numbers: g is evaluated relative to the exact end value g(0) or g(pi) (signed angle between the
// horizontal projections), as root_census.hpp does, so that g - g(end) keeps its relative accuracy
// near the ends. Error of g: a few ulp of Real times (|p| + q) (root_census.hpp's bound).
#pragma once

#include "sphtroch/core/ratio.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace sphtroch {

template <typename Real>
class HalfTurn {
 public:
  /// Twist angles in radians (a2, a3 in (0, pi)), n = p/q.
  HalfTurn(Real a2, Real a3, const Ratio& n)
      : HalfTurn(std::sin(a2), std::cos(a2), std::sin(a3), std::cos(a3), n) {}
  /// From the sines and cosines (exact identities, e.g. a2 = pi/2: sin 1, cos 0).
  HalfTurn(Real sa2, Real ca2, Real sa3, Real ca3, const Ratio& n)
      : sa2_(sa2), ca2_(ca2), sa3_(sa3), ca3_(ca3), p_(static_cast<Real>(n.p())), q_(static_cast<Real>(n.q())) {
    y0_ = -(sa3_ * ca2_ + ca3_ * sa2_);
    ypi_ = sa3_ * ca2_ - ca3_ * sa2_;
  }

  static Real pi() { return static_cast<Real>(3.141592653589793238462643383279502884L); }

  /// y of C(0) = -sin(a2 + a3) and of C(pi) = sin(a3 - a2): 0 exactly when the end is a pole.
  Real y_at_0() const { return y0_; }
  Real y_at_pi() const { return ypi_; }
  /// The integer values of g at the ends (trivial roots t1 = t2), for ends that are not poles.
  Real g_at_0() const { return y0_ < 0 ? -p_ : Real(0); }
  Real g_at_pi() const { return ypi_ > 0 ? q_ : q_ - p_; }

  /// g(b), b in (0, pi) (see header).
  Real g(Real b) const {
    const Real x = sa3_ * std::sin(b), y = -(sa3_ * ca2_ * std::cos(b) + ca3_ * sa2_);
    const bool near_zero = b <= pi() / 2;
    const Real y_end = near_zero ? y0_ : ypi_;
    if (y_end == 0) return (p_ * (2 * std::atan2(y, x) - pi()) + 2 * q_ * b) / (2 * pi());
    const Real daz = std::atan2(-y_end * x, y_end * y);  // signed angle from (0, y_end) to (x, y)
    const Real end = near_zero ? Real(0) : pi();
    return (near_zero ? g_at_0() : g_at_pi()) + (2 * p_ * daz + 2 * q_ * (b - end)) / (2 * pi());
  }

  /// dg/db (see header).
  Real dg_db(Real b) const {
    const Real c = std::cos(b);
    const Real x = sa3_ * std::sin(b), y = -(sa3_ * ca2_ * c + ca3_ * sa2_);
    return (p_ * (sa3_ * sa3_ * ca2_ + sa3_ * ca3_ * sa2_ * c) / (x * x + y * y) + q_) / pi();
  }

  /// dg/da3 at fixed b (see header).
  Real dg_da3(Real b) const {
    const Real s = std::sin(b), c = std::cos(b);
    const Real x = sa3_ * s, y = -(sa3_ * ca2_ * c + ca3_ * sa2_);
    const Real dx = ca3_ * s, dy = -(ca3_ * ca2_ * c - sa3_ * sa2_);
    return p_ * (x * dy - y * dx) / ((x * x + y * y) * pi());
  }

  /// The root c_label (label 0: smaller, 1: larger) of the quadratic g'(b) = 0 in c = cos b, when
  /// real (nothing when the discriminant is < 0). The value may lie outside (-1, 1).
  std::optional<Real> stationary_cos(int label) const {
    const Real A = -q_ * sa2_ * sa2_ * sa3_ * sa3_;
    const Real B = sa2_ * sa3_ * ca3_ * (2 * q_ * ca2_ + p_);
    const Real C = q_ * (sa2_ * sa2_ + ca2_ * ca2_ * sa3_ * sa3_) + p_ * sa3_ * sa3_ * ca2_;
    const Real disc = B * B - 4 * A * C;
    if (!(disc >= 0) || A == 0) return std::nullopt;
    const Real s = std::sqrt(disc);
    const Real r1 = (-B - (B >= 0 ? s : -s)) / (2 * A);  // the root without cancellation
    const Real r2 = r1 != 0 ? C / (A * r1) : -B / A;
    return label == 0 ? std::min(r1, r2) : std::max(r1, r2);
  }

  /// The stationary point b* in (0, pi) of this label, or nothing.
  std::optional<Real> stationary(int label) const {
    const auto c = stationary_cos(label);
    if (!c || !(*c > -1 && *c < 1)) return std::nullopt;
    return std::acos(*c);
  }

  /// Roots of g in (0, pi) counted as crossings: integers strictly inside the range of each
  /// monotone piece between 0, the stationary points and pi (REQUIRES: no stationary value of g
  /// and no end is exactly on its boundary, i.e. a3 off every event; else the count is that of
  /// one side). The curve has |p| times this many node points (root_census.hpp).
  std::int64_t node_roots() const {
    Real breaks[2];
    int k = 0;
    for (int label = 1; label >= 0; --label)  // label 1 has the smaller b
      if (const auto b = stationary(label)) breaks[k++] = *b;
    Real values[4];
    int v = 0;
    values[v++] = y0_ == 0 ? -p_ / 2 : g_at_0();
    for (int i = 0; i < k; ++i) values[v++] = g(breaks[i]);
    values[v++] = ypi_ == 0 ? q_ - p_ / 2 : g_at_pi();
    std::int64_t roots = 0;
    for (int i = 0; i + 1 < v; ++i) {
      const Real lo = std::min(values[i], values[i + 1]), hi = std::max(values[i], values[i + 1]);
      // Integers m with lo < m < hi.
      const Real first = std::floor(lo) + 1, last = std::ceil(hi) - 1;
      if (last >= first) roots += static_cast<std::int64_t>(last - first) + 1;
    }
    return roots;
  }

 private:
  Real sa2_, ca2_, sa3_, ca3_, p_, q_, y0_ = 0, ypi_ = 0;
};

}  // namespace sphtroch
