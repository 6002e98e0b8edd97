// sphtroch/map/root_function.hpp — the root function g(b): its integer values on (0, pi) are the
// nodes of the curve. The one definition used by the root census (census/root_census.hpp: counts
// and locates nodes), the boundary events of the design map (boundary_events.hpp: where the count
// changes with a3) and the tangency refinement, so that `classify` and `boundaries` cannot
// disagree on an event. A value type over Real = long double (or any floating type).
//
//   sphtroch::RootFunction<long double> g(kPi / 3, kPi / 2, sphtroch::Ratio(5, 2));
//   const long double b = 1.0L;                 // the planet angle, in (0, pi)
//   g.g(b);  g.dg_db(b);  g.dg_da3(b);          // g and its partial derivatives
//   g.stationary(0);                            // stationary point b*, label 0 (or nothing)
//   g.node_roots();                             // #{b in (0, pi): g(b) integer}, off tangencies
//   g.solve(0.1L, 1.0L, 1.0L);                  // b with g(b) = 1 on a monotone piece
//   g.evaluations;                              // evaluations of g and g' so far
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
// horizontal projections), once for every user, so that g - g(end) keeps its relative accuracy
// near the ends. Error of g: a few ulp of Real times (|p| + q) (root_census.hpp's bound).
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace sphtroch {

template <typename Real>
class RootFunction {
 public:
  /// The train's own sines and cosines (exact identities on its boundaries: GearTrain::trig).
  explicit RootFunction(const GearTrain& train) : RootFunction(train.trig<Real>(), train.ratio()) {}
  RootFunction(const TwistTrig<Real>& t, const Ratio& n) : RootFunction(t.sin_a2, t.cos_a2, t.sin_a3, t.cos_a3, n) {}
  /// Twist angles in radians (a2, a3 in (0, pi)), n = p/q.
  RootFunction(Real a2, Real a3, const Ratio& n)
      : RootFunction(std::sin(a2), std::cos(a2), std::sin(a3), std::cos(a3), n) {}
  /// From the sines and cosines (exact identities, e.g. a2 = pi/2: sin 1, cos 0).
  RootFunction(Real sa2, Real ca2, Real sa3, Real ca3, const Ratio& n)
      : sa2_(sa2), ca2_(ca2), sa3_(sa3), ca3_(ca3), p_(static_cast<Real>(n.p())), q_(static_cast<Real>(n.q())) {
    y0_ = -(sa3_ * ca2_ + ca3_ * sa2_);  // y of C(0)  = -sin(a2 + a3)
    ypi_ = sa3_ * ca2_ - ca3_ * sa2_;    // y of C(pi) =  sin(a3 - a2)
  }

  static Real pi() { return Constants<Real>::pi(); }
  Real p() const { return p_; }
  Real q() const { return q_; }

  /// y of C(0) = -sin(a2 + a3) and of C(pi) = sin(a3 - a2): 0 exactly when the end is a pole.
  Real y_at_0() const { return y0_; }
  Real y_at_pi() const { return ypi_; }
  /// The integer values of g at the ends (trivial roots t1 = t2), for ends that are not poles.
  Real g_at_0() const { return y0_ < 0 ? -p_ : Real(0); }
  Real g_at_pi() const { return ypi_ > 0 ? q_ : q_ - p_; }
  /// Limits of g at the ends, also when they are poles: C(b) then approaches the pole tangentially
  /// to the x axis (x ~ sa3 |b - end|, y ~ O(|b - end|^2)), so az -> 0 and g -> -p/2 or q - p/2.
  Real g_limit_at_0() const { return y0_ == 0 ? -p_ / 2 : g_at_0(); }
  Real g_limit_at_pi() const { return ypi_ == 0 ? q_ - p_ / 2 : g_at_pi(); }

  /// C(b) in carrier coordinates.
  Vector3<Real> circle_point(Real b) const {
    return Vector3<Real>(sa3_ * std::sin(b), -(sa3_ * ca2_ * std::cos(b) + ca3_ * sa2_),
                         ca2_ * ca3_ - sa2_ * sa3_ * std::cos(b));
  }

  /// g(b), b in (0, pi) (see header).
  Real g(Real b) const {
    ++evaluations;
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
    ++evaluations;
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

  /// How far the quadratic of stationary_cos is from a double root, relative to the size of its
  /// terms before cancellation: |disc| / (Bm^2 + 4 |A| Cm), Bm and Cm the sums of the magnitudes
  /// of the terms of B and C (0 when A = 0). B or C that cancel to rounding noise (e.g. a3 = pi/2
  /// at cos a2 = -q/p) give a small margin, not a large one: the roots are then not resolved in Real.
  Real stationary_margin() const {
    const Real A = -q_ * sa2_ * sa2_ * sa3_ * sa3_;
    const Real B = sa2_ * sa3_ * ca3_ * (2 * q_ * ca2_ + p_);
    const Real C = q_ * (sa2_ * sa2_ + ca2_ * ca2_ * sa3_ * sa3_) + p_ * sa3_ * sa3_ * ca2_;
    const Real Bm = std::abs(sa2_ * sa3_ * ca3_) * (2 * q_ * std::abs(ca2_) + std::abs(p_));
    const Real Cm = q_ * (sa2_ * sa2_ + ca2_ * ca2_ * sa3_ * sa3_) + std::abs(p_) * sa3_ * sa3_ * std::abs(ca2_);
    const Real scale = Bm * Bm + 4 * std::abs(A) * Cm;
    return A == 0 || !(scale > 0) ? Real(0) : std::abs(B * B - 4 * A * C) / scale;
  }

  /// The stationary point b* in (0, pi) of this label, or nothing.
  std::optional<Real> stationary(int label) const {
    const auto c = stationary_cos(label);
    if (!c || !(*c > -1 && *c < 1)) return std::nullopt;
    return std::acos(*c);
  }

  /// Every stationary point of g in (0, pi), ascending, without repeats.
  std::vector<Real> stationary_points() const {
    std::vector<Real> bs;
    for (int label = 0; label < 2; ++label)
      if (const auto b = stationary(label)) bs.push_back(*b);
    std::sort(bs.begin(), bs.end());
    bs.erase(std::unique(bs.begin(), bs.end()), bs.end());
    return bs;
  }

  /// The b in [lo, hi] with g(b) = m, where g - m changes sign on [lo, hi] (a monotone piece):
  /// bisection with a Newton step from each midpoint that stays inside the bracket, to a bracket
  /// of 4 ulp of max(1, hi) (at most 200 steps).
  Real solve(Real lo, Real hi, Real m) const {
    Real flo = g(lo) - m;
    const Real eps = std::numeric_limits<Real>::epsilon();
    for (int it = 0; it < 200 && hi - lo > 4 * eps * std::max<Real>(1, hi); ++it) {
      const Real mid = (lo + hi) / 2;
      const Real fm = g(mid) - m;
      if (fm == 0) return mid;
      narrow(lo, hi, flo, mid, fm);
      const Real d = dg_db(mid);
      if (d == 0) continue;
      const Real x = mid - fm / d;
      if (!(x > lo && x < hi)) continue;
      const Real fx = g(x) - m;
      if (fx == 0) return x;
      narrow(lo, hi, flo, x, fx);
    }
    return (lo + hi) / 2;
  }

  /// Roots of g in (0, pi) counted as crossings: integers strictly inside the range of each
  /// monotone piece between 0, the stationary points and pi (REQUIRES: no stationary value of g
  /// and no end is exactly on its boundary, i.e. a3 off every event; else the count is that of
  /// one side). The curve has |p| times this many node points (root_census.hpp).
  std::int64_t node_roots() const {
    std::vector<Real> values{g_limit_at_0()};
    for (Real b : stationary_points()) values.push_back(g(b));
    values.push_back(g_limit_at_pi());
    std::int64_t roots = 0;
    for (std::size_t i = 0; i + 1 < values.size(); ++i) {
      const Real lo = std::min(values[i], values[i + 1]), hi = std::max(values[i], values[i + 1]);
      const Real first = std::floor(lo) + 1, last = std::ceil(hi) - 1;  // integers m, lo < m < hi
      if (last >= first) roots += static_cast<std::int64_t>(last - first) + 1;
    }
    return roots;
  }

  /// Evaluations of g and dg/db made through this object (the census's work counter).
  mutable std::size_t evaluations = 0;

 private:
  /// Keeps the half of [lo, hi] where g - m changes sign, given f = g(x) - m at x inside.
  static void narrow(Real& lo, Real& hi, Real& flo, Real x, Real f) {
    if ((f < 0) == (flo < 0)) {
      lo = x;
      flo = f;
    } else {
      hi = x;
    }
  }

  Real sa2_, ca2_, sa3_, ca3_, p_, q_, y0_ = 0, ypi_ = 0;
};

}  // namespace sphtroch
