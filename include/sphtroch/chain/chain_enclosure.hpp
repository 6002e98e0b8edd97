// sphtroch/chain/chain_enclosure.hpp — enclosures of a rotation chain's point P(s), its
// velocity P'(s) and acceleration P''(s) over an interval of the motor parameter s (interval
// arithmetic, outward rounded): the evaluations behind the chain's certified census
// (chain_census.hpp).
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   sphtroch::RoundingGuard upward;                      // REQUIRED while the jets are computed
//   const sphtroch::ChainEnclosure e(chain);
//   sphtroch::ChainJet j = e.jet(sphtroch::Interval(0.1, 0.2));
//   j.point[0];   // contains P_x(s) for every s in [0.1, 0.2]
//
// Contract: for every s in S, P(s), P'(s), P''(s) of ChainCurve (core/rotation_chain.hpp) lie in
// jet(S).point, .velocity, .acceleration (componentwise).
// How: the joint angles N_i S + P_i in intervals (N_i = p_i / q_i enclosed), their sines and
// cosines by interval_sincos (interval/interval.hpp), the frames R_i = R_{i-1} Rz Rx
// multiplied out in intervals; omega = sum N_i Z_i, P' = omega x P, P'' = omega' x P + omega x
// (omega x P) with omega' = sum_i N_i (W_{i-1} x Z_i) (the formulas of rotation_chain.hpp).
// The natural extension overestimates in proportion to the width of S; `sharp_jet` intersects it
// with the mean-value forms P(c) + P'(S)(S - c) and P'(c) + P''(S)(S - c) (first-order sharp).
// Along a family (ChainWidening: the twists and phases move with d), `family_jet` also encloses
// dP/dd and dP'/dd: a change of phase i turns everything after joint i about Z_i, a change of
// twist i everything after Rx(A_i) about X_i = R_{i+1} e_x, so with eta = sum_i (phase_sign_i Z_i
// + twist_sign_i X_i), dP/dd = eta x P, dZ_j/dd = eta_{<j} x Z_j, domega/dd = sum_j N_j eta_{<j} x
// Z_j and dP'/dd = domega/dd x P + omega x dP/dd (eta_{<j}: the terms of stages before j).
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_enclosure.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/interval_vector.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace sphtroch {

/// P, P', P'' enclosed over an interval of s.
struct ChainJet {
  IntervalVec3 point, velocity, acceleration;
};

/// A jet with the derivatives along the family (see header).
struct FamilyJet {
  ChainJet jet;
  IntervalVec3 point_d, velocity_d;
};

/// A one-parameter family around a chain: stage i's twist is twist_i + twist_sign[i] d and its
/// phase phase_i + phase_sign[i] d, for every d in `offset` (signs -1, 0 or 1; empty: all 0).
struct ChainWidening {
  std::vector<int> twist_sign, phase_sign;
  Interval offset{0.0};
};

class ChainEnclosure {
 public:
  /// REQUIRES the rounding mode upward (a RoundingGuard held). With `widening`, the enclosures
  /// hold for every chain of that family (contract above, for each d in the offset).
  explicit ChainEnclosure(const RotationChain& chain, const ChainWidening& widening = {}) {
    const auto sign = [](const std::vector<int>& v, std::size_t i) { return i < v.size() ? v[i] : 0; };
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const ChainStage& s = chain.stages()[i];
      const Interval twist = Interval(s.twist) + Interval(double(sign(widening.twist_sign, i))) * widening.offset;
      rate_.push_back(Interval(static_cast<double>(s.rate.p())) / Interval(static_cast<double>(s.rate.q())));
      phase_.push_back(Interval(s.phase) + Interval(double(sign(widening.phase_sign, i))) * widening.offset);
      twist_.push_back(interval_sincos(twist));
      twist_sign_.push_back(Interval(double(sign(widening.twist_sign, i))));
      phase_sign_.push_back(Interval(double(sign(widening.phase_sign, i))));
    }
  }

  /// The enclosures over S (natural extension). REQUIRES rounding upward.
  ChainJet jet(const Interval& s) const {
    const std::size_t k = rate_.size();
    const std::vector<std::pair<Interval, Interval>> trig = joint_trig(s);
    std::array<IntervalVec3, 3> r = identity();
    std::vector<IntervalVec3> axes(k);
    for (std::size_t i = 0; i < k; ++i) {
      axes[i] = r[2];
      r = times_stage(r, trig[i], twist_[i]);
    }
    ChainJet j;
    j.point = r[2];
    IntervalVec3 omega = zero(), omega_dot = zero();
    for (std::size_t i = 0; i < k; ++i) {
      if (i > 0) add_scaled(omega_dot, rate_[i], cross(omega, axes[i]));  // omega here is W_{i-1}
      add_scaled(omega, rate_[i], axes[i]);
    }
    j.velocity = cross(omega, j.point);
    const IntervalVec3 a = cross(omega_dot, j.point), b = cross(omega, j.velocity);
    j.acceleration = {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    return j;
  }

  /// jet(S) with dP/dd and dP'/dd over S and the whole offset (header). REQUIRES rounding upward.
  FamilyJet family_jet(const Interval& s) const {
    const std::vector<std::pair<Interval, Interval>> trig = joint_trig(s);
    std::array<IntervalVec3, 3> r = identity();
    IntervalVec3 omega = zero(), omega_dot = zero(), omega_d = zero(), eta = zero();
    for (std::size_t i = 0; i < rate_.size(); ++i) {
      const IntervalVec3 axis = r[2];
      add_scaled(omega_dot, rate_[i], cross(omega, axis));  // omega, eta here: of the stages before i
      add_scaled(omega_d, rate_[i], cross(eta, axis));
      add_scaled(omega, rate_[i], axis);
      add_scaled(eta, phase_sign_[i], axis);
      r = times_stage(r, trig[i], twist_[i]);
      add_scaled(eta, twist_sign_[i], r[0]);  // X_i
    }
    FamilyJet f;
    f.jet.point = r[2];
    f.jet.velocity = cross(omega, r[2]);
    const IntervalVec3 a = cross(omega_dot, r[2]), b = cross(omega, f.jet.velocity);
    f.jet.acceleration = {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    f.point_d = cross(eta, r[2]);
    const IntervalVec3 c = cross(omega_d, r[2]), e = cross(omega, f.point_d);
    f.velocity_d = {c[0] + e[0], c[1] + e[1], c[2] + e[2]};
    return f;
  }

  /// jet(S) narrowed by the mean-value forms about the middle of S (see header). REQUIRES rounding upward.
  ChainJet sharp_jet(const Interval& s) const {
    ChainJet wide = jet(s);
    const Interval c = centre_of(s);
    const ChainJet mid = jet(c);
    const Interval d = s - c;
    for (int x = 0; x < 3; ++x) {
      wide.point[x] = narrowed(wide.point[x], mid.point[x] + wide.velocity[x] * d);
      wide.velocity[x] = narrowed(wide.velocity[x], mid.velocity[x] + wide.acceleration[x] * d);
    }
    return wide;
  }

 private:
  Interval angle(std::size_t i, const Interval& s) const { return rate_[i] * s + phase_[i]; }
  /// sin and cos of every joint angle over S.
  std::vector<std::pair<Interval, Interval>> joint_trig(const Interval& s) const {
    std::vector<std::pair<Interval, Interval>> trig(rate_.size());
    const RoundingGuard nearest(CGAL_FE_TONEAREST);
    for (std::size_t i = 0; i < rate_.size(); ++i) trig[i] = interval_sincos_in_nearest_mode(angle(i, s));
    return trig;
  }
  static std::array<IntervalVec3, 3> identity() {  // columns of R
    return {IntervalVec3{Interval(1), Interval(0), Interval(0)}, IntervalVec3{Interval(0), Interval(1), Interval(0)},
            IntervalVec3{Interval(0), Interval(0), Interval(1)}};
  }

  static IntervalVec3 zero() { return {Interval(0), Interval(0), Interval(0)}; }
  static void add_scaled(IntervalVec3& sum, const Interval& f, const IntervalVec3& v) {
    for (int x = 0; x < 3; ++x) sum[x] += f * v[x];
  }
  /// The intersection of two enclosures of the same quantity (both hold it, so they meet).
  static Interval narrowed(const Interval& a, const Interval& b) {
    const double lo = std::max(a.inf(), b.inf()), hi = std::min(a.sup(), b.sup());
    return lo <= hi ? Interval(lo, hi) : a;
  }
  /// R Rz(theta) Rx(A), by columns: with t = (sin, cos) of theta, a = (sin, cos) of A,
  /// Rz Rx = [[c, -s ca, s sa], [s, c ca, -c sa], [0, sa, ca]].
  static std::array<IntervalVec3, 3> times_stage(const std::array<IntervalVec3, 3>& r, const std::pair<Interval, Interval>& t,
                                                 const std::pair<Interval, Interval>& a) {
    const Interval& st = t.first;
    const Interval& ct = t.second;
    const Interval& sa = a.first;
    const Interval& ca = a.second;
    std::array<IntervalVec3, 3> out;
    for (int x = 0; x < 3; ++x) {
      out[0][x] = r[0][x] * ct + r[1][x] * st;
      const Interval y = r[1][x] * ct - r[0][x] * st;  // R (Rz e_y)
      out[1][x] = y * ca + r[2][x] * sa;
      out[2][x] = r[2][x] * ca - y * sa;
    }
    return out;
  }

  std::vector<Interval> rate_, phase_, twist_sign_, phase_sign_;
  std::vector<std::pair<Interval, Interval>> twist_;
};

}  // namespace sphtroch
