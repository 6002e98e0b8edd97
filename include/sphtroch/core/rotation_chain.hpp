// sphtroch/core/rotation_chain.hpp — a gear-coupled rotation chain: k revolute joints about
// intersecting axes, joint i turning N_i times as fast as one motor parameter s (N_i an exact
// rational), each followed by a fixed twist A_i; the tool axis z of the last body traces a closed
// curve on the unit sphere, P(s) = Rz(N1 s + P1) Rx(A1) Rz(N2 s + P2) Rx(A2) ... Rz(Nk s + Pk) Rx(Ak) z.
// With k = 2, N1 = 1, P1 = 0, A1 = a2, N2 = n, P2 = theta_p, A2 = a3 it is the report's Eq. 4 (the
// gear train of core/gear_train.hpp, s = theta2), and ChainCurve<double> then computes the same
// bits as TracerCurve<double> (the same operations in the same order).
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0},
//                                        {0.5, sphtroch::ChainRate(-2, 3), 0.0},
//                                        {2.0, sphtroch::ChainRate(5, 3), 0.3}});
//   const sphtroch::ChainCurve<double> curve(chain);
//   curve.point(0.1);      // a unit vector
//   chain.period();        // 6 pi: every joint is back after s = 2 pi L / g (below)
//
// Kinematics: the last body turns with omega(s) = sum_i N_i Z_i(s), Z_i the axis of joint i in
// the base frame (Z_1 = z; Z_i = R_{i-1} z, R_i = R_{i-1} Rz(theta_i) Rx(A_i)), so dP/ds =
// omega x P, and d2P/ds2 = omega' x P + omega x (omega x P), omega' = sum_i N_i (W_{i-1} x Z_i),
// W_{i-1} = sum_{j<i} N_j Z_j the angular velocity of the body that carries joint i. A cusp is
// where P is parallel to omega (or omega = 0).
// Period: with L the lcm of the rates' denominators and g the gcd of the numerators of N_i L,
// every joint angle is back after s = 2 pi L / g. The curve may close sooner (a twist of 0 or pi
// makes joints coaxial); the period is the one every joint shares.
// Error: as TracerCurve (curve.hpp): for |s| up to the period each joint angle p s / q + P (three
// roundings) is at most 2 pi 1e6 rad (refused beyond: kMaxTurnsPerPeriod), so its absolute
// error, and the points', is below ~1e-9 in double (a few ulp of the angle); sin and cos of a
// large argument carry that rounding.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"  // reduce_phase
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/core/types.hpp"

#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// A joint's rate p/q in lowest terms, q > 0; p may be 0 (a joint that does not turn).
/// REQUIRES |p|, q <= kMaxTerm; InvalidInput("rates") otherwise.
class ChainRate {
 public:
  static constexpr std::int64_t kMaxTerm = 1000000;
  explicit ChainRate(std::int64_t p = 0, std::int64_t q = 1) {
    const std::string shown = std::to_string(p) + "/" + std::to_string(q);
    const std::string valid = "p/q with |p|, |q| <= 1000000, q != 0";
    if (q == 0) throw InvalidInput("rates", shown, "zero denominator", valid);
    if (p < -kMaxTerm * kMaxTerm || p > kMaxTerm * kMaxTerm || q < -kMaxTerm * kMaxTerm || q > kMaxTerm * kMaxTerm)
      throw InvalidInput("rates", shown, "a term too large", valid);  // (and no negation of INT64_MIN below)
    if (q < 0) p = -p, q = -q;
    const std::int64_t g = std::gcd(p < 0 ? -p : p, q);
    p_ = p / g;
    q_ = q / g;
    if ((p_ < 0 ? -p_ : p_) > kMaxTerm || q_ > kMaxTerm) throw InvalidInput("rates", shown, "a term too large", valid);
  }
  std::int64_t p() const noexcept { return p_; }
  std::int64_t q() const noexcept { return q_; }
  bool is_zero() const noexcept { return p_ == 0; }
  double value() const noexcept { return static_cast<double>(p_) / static_cast<double>(q_); }
  /// "5/3", "-2", "0".
  std::string str() const { return q_ == 1 ? std::to_string(p_) : std::to_string(p_) + "/" + std::to_string(q_); }
  bool operator==(const ChainRate& o) const noexcept { return p_ == o.p_ && q_ == o.q_; }

 private:
  std::int64_t p_ = 0, q_ = 1;
};

/// Joint i: its rate N_i, its phase P_i (radians, the joint angle at s = 0; RotationChain keeps it
/// reduced to [-pi, pi] as GearTrain does, reduce_phase) and the twist A_i (radians, [0, pi]) from
/// its axis to the next one (or to the tool axis, for the last joint).
struct ChainStage {
  double twist = 0;
  ChainRate rate;
  double phase = 0;
};

/// One twist (A) or phase (P) of stage `stage` (1-based) varied over [lo, hi] (radians): a
/// one-parameter family of chains (`chain boundaries --vary`, chain/chain_events.hpp).
struct ChainVary {
  bool twist = true;
  std::size_t stage = 1;
  double lo = 0, hi = 0;
  std::string name() const { return (twist ? "A" : "P") + std::to_string(stage); }
};

class RotationChain {
 public:
  static constexpr std::size_t kMaxStages = 16;
  /// The largest common denominator L of the rates accepted (the period is 2 pi L / g).
  static constexpr std::int64_t kMaxCommonDenominator = 1000000000;
  /// The most turns any joint makes in a period (its angle, up to 2 pi 1e6 rad, keeps ~1e-9 rad).
  static constexpr double kMaxTurnsPerPeriod = 1e6;

  /// REQUIRES 1 <= k <= kMaxStages stages, each twist in [0, pi] and each phase finite, some rate
  /// not 0 (else omega = 0: nothing moves), the rates' common denominator <= kMaxCommonDenominator.
  /// Throws InvalidInput naming "twists", "phases" or "rates".
  explicit RotationChain(std::vector<ChainStage> stages) : stages_(std::move(stages)) {
    if (stages_.empty() || stages_.size() > kMaxStages)
      throw InvalidInput("twists", std::to_string(stages_.size()) + " stages", "not a chain length", "1 to 16 stages");
    const double pi = Constants<double>::pi();
    for (std::size_t i = 0; i < stages_.size(); ++i) {
      const ChainStage& s = stages_[i];
      if (!(s.twist >= 0 && s.twist <= pi))
        throw InvalidInput("twists", report_number(s.twist) + " (stage " + std::to_string(i + 1) + ")", "outside [0, pi]", "A in [0, pi] radians");
      if (!std::isfinite(s.phase))
        throw InvalidInput("phases", report_number(s.phase) + " (stage " + std::to_string(i + 1) + ")", "not finite", "a finite angle in radians");
      stages_[i].phase = reduce_phase(s.phase);  // to [-pi, pi] as GearTrain's phase: the same curve
    }
    std::int64_t l = 1;
    for (const ChainStage& s : stages_) {
      l = std::lcm(l, s.rate.q());
      if (l > kMaxCommonDenominator)
        throw InvalidInput("rates", rates_text(), "the rates' common denominator exceeds 1e9", "rates whose denominators have an lcm <= 1e9");
    }
    std::int64_t g = 0;
    for (const ChainStage& s : stages_) g = std::gcd(g, (s.rate.p() < 0 ? -s.rate.p() : s.rate.p()) * (l / s.rate.q()));
    if (g == 0) throw InvalidInput("rates", rates_text(), "every rate is 0: nothing turns (omega = 0)", "at least one rate not 0");
    // Joint i turns |p_i| (L / q_i) / g times a period; its angle must stay small enough for
    // double to hold it to ~1e-9 rad (as a gear train's angle, at most 2 pi 1e6 rad).
    for (const ChainStage& s : stages_) {
      const double turns = std::fabs(static_cast<double>(s.rate.p())) * static_cast<double>(l / s.rate.q()) / static_cast<double>(g);
      if (turns > kMaxTurnsPerPeriod)
        throw InvalidInput("rates", rates_text(), "a joint turns " + number_text(turns) + " times in the period 2 pi L / g",
                           "rates whose joints turn at most 1e6 times a period (a period of at most 1e6 turns of each joint)");
    }
    common_denominator_ = l;
    numerator_gcd_ = g;
  }

  const std::vector<ChainStage>& stages() const noexcept { return stages_; }
  std::size_t size() const noexcept { return stages_.size(); }
  /// L, the lcm of the rates' denominators, and g, the gcd of the numerators of N_i L.
  std::int64_t common_denominator() const noexcept { return common_denominator_; }
  std::int64_t numerator_gcd() const noexcept { return numerator_gcd_; }
  /// 2 pi L / g: the s after which every joint is back (in double; ChainCurve::period in Scalar).
  double period() const { return Constants<double>::two_pi() * static_cast<double>(common_denominator_) / static_cast<double>(numerator_gcd_); }
  /// sum_i |N_i| L / g: the joints' turns in one period, all together (the sample counts' unit).
  double total_turns() const {
    double turns = 0;
    for (const ChainStage& s : stages_)
      turns += std::fabs(static_cast<double>(s.rate.p())) * static_cast<double>(common_denominator_ / s.rate.q());
    return turns / static_cast<double>(numerator_gcd_);
  }
  /// "1.5707963267948966,1,0.4": the twists as shortest round-trip doubles.
  std::string twists_text() const {
    std::string t;
    for (const ChainStage& s : stages_) t += (t.empty() ? "" : ",") + number_text(s.twist);
    return t;
  }
  /// "1,-2/3,5/3".
  std::string rates_text() const {
    std::string t;
    for (const ChainStage& s : stages_) t += (t.empty() ? "" : ",") + s.rate.str();
    return t;
  }

 private:
  std::vector<ChainStage> stages_;
  std::int64_t common_denominator_ = 1, numerator_gcd_ = 1;
};

/// The chain's curve and its derivatives in Scalar (double, long double, MPFR, intervals: any
/// type with sin_cos and field operations, as TracerCurve).
template <typename Scalar>
class ChainCurve {
 public:
  using Vec3 = Vector3<Scalar>;
  using Mat3 = Matrix3<Scalar>;

  explicit ChainCurve(const RotationChain& chain) : chain_(chain) {
    for (const ChainStage& s : chain.stages()) {
      twists_.push_back(sin_cos(Scalar(s.twist)));
      p_.push_back(Scalar(static_cast<double>(s.rate.p())));
      q_.push_back(Scalar(static_cast<double>(s.rate.q())));
      phase_.push_back(Scalar(s.phase));
    }
  }
  const RotationChain& chain() const noexcept { return chain_; }

  /// theta_i = N_i s + P_i, formed as p s / q + P (as TracerCurve's planet angle).
  Scalar joint_angle(std::size_t i, const Scalar& s) const { return p_[i] * s / q_[i] + phase_[i]; }

  /// P(s), a unit vector in the base frame: the stages applied from the last to the first, each
  /// Rx(A_i) then Rz(theta_i) written out (for k = 2 the operations of TracerCurve::point).
  Vec3 point(const Scalar& s) const {
    Vec3 v(Scalar(0), Scalar(0), Scalar(1));
    for (std::size_t i = size(); i-- > 0;) {
      const SinCos<Scalar>& a = twists_[i];
      const SinCos<Scalar> t = sin_cos(joint_angle(i, s));
      if (i + 1 == size()) {
        v = Vec3(t.sin * a.sin, -t.cos * a.sin, a.cos);  // Rz(theta) Rx(A) z
        continue;
      }
      const Scalar wy = a.cos * v.y() - a.sin * v.z();  // Rx(A) v
      const Scalar wz = a.sin * v.y() + a.cos * v.z();
      v = Vec3(t.cos * v.x() - t.sin * wy, t.sin * v.x() + t.cos * wy, wz);  // Rz(theta)
    }
    return v;
  }

  /// Z_1 .. Z_k, the joints' axes in the base frame at s.
  std::vector<Vec3> joint_axes(const Scalar& s) const {
    std::vector<Vec3> axes;
    Mat3 r = Mat3::Identity();
    for (std::size_t i = 0; i < size(); ++i) {
      axes.push_back(r.col(2));
      const SinCos<Scalar> t = sin_cos(joint_angle(i, s));
      Mat3 stage;
      stage << t.cos, -t.sin * twists_[i].cos, t.sin * twists_[i].sin, t.sin, t.cos * twists_[i].cos, -t.cos * twists_[i].sin, Scalar(0),
          twists_[i].sin, twists_[i].cos;  // Rz(theta) Rx(A)
      r = Mat3(r * stage);
    }
    return axes;
  }

  /// omega = sum_i N_i Z_i: the last body's angular velocity per unit s (its instantaneous axis).
  Vec3 angular_velocity(const Scalar& s) const { return weighted_sum(joint_axes(s), size()); }
  /// The same, by TracerCurve's name (the trace writer and path_kinematics take either curve).
  Vec3 screw_axis(const Scalar& s) const { return angular_velocity(s); }

  /// dP/ds = omega x P.
  Vec3 velocity(const Scalar& s) const { return Vec3(angular_velocity(s).cross(point(s))); }

  /// d2P/ds2 = omega' x P + omega x (omega x P), omega' = sum_i N_i (W_{i-1} x Z_i).
  Vec3 acceleration(const Scalar& s) const {
    const std::vector<Vec3> axes = joint_axes(s);
    const Vec3 p = point(s), omega = weighted_sum(axes, size());
    Vec3 omega_dot = Vec3::Zero();
    for (std::size_t i = 1; i < size(); ++i) omega_dot += (p_[i] / q_[i]) * Vec3(weighted_sum(axes, i).cross(axes[i]));
    return Vec3(omega_dot.cross(p) + omega.cross(omega.cross(p)));
  }

  /// 2 pi L / g in Scalar.
  Scalar period() const {
    return Constants<Scalar>::two_pi() * Scalar(static_cast<double>(chain_.common_denominator())) /
           Scalar(static_cast<double>(chain_.numerator_gcd()));
  }

 private:
  std::size_t size() const noexcept { return p_.size(); }
  /// sum_{i < count} N_i axes[i].
  Vec3 weighted_sum(const std::vector<Vec3>& axes, std::size_t count) const {
    Vec3 sum = Vec3::Zero();
    for (std::size_t i = 0; i < count; ++i) sum += (p_[i] / q_[i]) * axes[i];
    return sum;
  }

  RotationChain chain_;
  std::vector<SinCos<Scalar>> twists_;
  std::vector<Scalar> p_, q_, phase_;
};

/// The gear train as the k = 2 chain (the report's Eq. 4, s = theta2): stages (a2, 1, 0) and
/// (a3, n, theta_p). ChainCurve<double> of it computes TracerCurve<double>'s bits.
inline RotationChain chain_of(const GearTrain& train) {
  return RotationChain({{train.a2(), ChainRate(1), 0.0}, {train.a3(), ChainRate(train.ratio().p(), train.ratio().q()), train.phase()}});
}

/// n = N2 / N1 of a k = 2 chain whose rates are both not 0 (the ratio of gear_train_of); nullopt
/// for any other chain, and beyond Ratio's terms.
inline std::optional<Ratio> gear_ratio_of(const RotationChain& chain) {
  if (chain.size() != 2 || chain.stages()[0].rate.is_zero() || chain.stages()[1].rate.is_zero()) return std::nullopt;
  const ChainRate& first = chain.stages()[0].rate;
  const ChainRate& second = chain.stages()[1].rate;
  const std::int64_t p = second.p() * first.q(), q = second.q() * first.p();  // |terms| <= 1e12
  const std::int64_t g = std::gcd(p < 0 ? -p : p, q < 0 ? -q : q);
  try {
    return Ratio(p / g, q / g);
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

/// The gear train of a k = 2 chain whose rates are both not 0: a2 = A1, a3 = A2, n = N2 / N1
/// (gear_ratio_of), theta_p = P2 - n P1, with theta2 = N1 s + P1 (chain_param_of_theta2 maps
/// theta2 back to s). nullopt for any other chain, and when GearTrain refuses it (a twist of 0 or
/// pi, or n beyond Ratio's terms).
inline std::optional<GearTrain> gear_train_of(const RotationChain& chain) {
  const std::optional<Ratio> n = gear_ratio_of(chain);
  if (!n) return std::nullopt;
  const ChainStage& first = chain.stages()[0];
  const ChainStage& second = chain.stages()[1];
  try {
    return GearTrain(first.twist, second.twist, *n, second.phase - n->value() * first.phase);
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

/// The chain's parameter s at the train's carrier angle theta2 (gear_train_of): (theta2 - P1) / N1,
/// not reduced to a period.
inline double chain_param_of_theta2(const RotationChain& chain, double theta2) {
  const ChainStage& first = chain.stages()[0];
  return (theta2 - first.phase) / first.rate.value();
}

}  // namespace sphtroch
