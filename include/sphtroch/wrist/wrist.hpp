// sphtroch/wrist/wrist.hpp — a geared spherical wrist: k revolute joints about axes through one
// centre, driven by m = 2 or 3 motors through gears.
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(3, 2)}});
//   wrist.period(1);                                   // 4 pi: motor 2 turns joint 3 by 3/2
//   const sphtroch::Vector3d p = wrist.point<double>({0.1, 0.2});   // a unit vector
//
// Joint i turns by theta_i(u) = sum_j C_ij u_j + phi_i (u the motor angles, C the k x m coupling
// of exact fractions, phi_i the phases); the last body's frame and tool axis are
// F(u) = Rz(theta_1) Rx(A_1) Rz(theta_2) Rx(A_2) ... Rz(theta_k) Rx(A_k) and P(u) = F(u) a (A_i
// the twists, a the tool axis in the last body, z unless given). A one-column C is a rotation chain
// (core/rotation_chain.hpp); the report's gear train (Eq. 4) driven by a base motor is twists
// (0, a2, a3) with C = [1 0; 0 1; 0 n].
// Motor j's period is T_j = 2 pi L_j, L_j the lcm of the denominators in column j: every joint
// angle is back (up to whole turns) after u_j grows by T_j, so the motor torus is
// [0, T_1) x ... x [0, T_m). The kinematics: dF/du_j = [omega_j]x F with omega_j = sum_i C_ij Z_i
// (Z_i = R_{i-1} z, the axis of joint i in the base frame), so dP/du_j = omega_j x P.
// Limits (InvalidInput naming the field, the value and the valid range): 1 <= k <= 6 twists in
// [0, pi]; phases finite (kept reduced to [-pi, pi], as a chain's); 2 or 3 motors; one coupling row per
// twist, each with m entries p/q, |p| and q <= 1000; L_j <= 1000; C of rank m, checked exactly
// (an m x m minor not 0, in integers); the axis finite and not 0 (normalised).
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"  // reduce_phase
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/core/rotation_chain.hpp"  // ChainRate: an exact fraction, 0 allowed
#include "sphtroch/core/types.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// Joint i's twist A_i (radians, [0, pi]: from its axis to the next one, or to the tool) and phase
/// phi_i (radians: its angle when every motor is at 0).
struct WristJoint {
  double twist = 0;
  double phase = 0;
};

class Wrist {
 public:
  static constexpr std::size_t kMaxJoints = 6;
  /// The largest |p| and q of a coupling entry p/q.
  static constexpr std::int64_t kMaxCouplingTerm = 1000;
  /// The largest L_j (motor j's period is 2 pi L_j).
  static constexpr std::int64_t kMaxPeriodTurns = 1000;

  /// REQUIRES the limits of the header; throws InvalidInput naming "twists", "phases",
  /// "coupling" or "axis" otherwise. coupling[i][j] = C_ij (row i: joint i).
  Wrist(std::vector<WristJoint> joints, std::vector<std::vector<ChainRate>> coupling, const Vector3d& axis = Vector3d::UnitZ())
      : joints_(std::move(joints)), coupling_(std::move(coupling)) {
    check_joints();
    check_coupling_shape();
    for (std::size_t j = 0; j < motors(); ++j) period_turns_.push_back(column_lcm(j));
    check_rank();
    if (!axis.allFinite() || !(axis.norm() > 0) || !std::isfinite(axis.squaredNorm()))
      throw InvalidInput("axis", number_text(axis.x()) + "," + number_text(axis.y()) + "," + number_text(axis.z()),
                         "not a direction", "X,Y,Z: three finite numbers, not all 0 (the tool axis in the last body)");
    axis_ = axis.normalized();
  }

  std::size_t joints() const noexcept { return joints_.size(); }
  std::size_t motors() const noexcept { return coupling_.front().size(); }
  const WristJoint& joint(std::size_t i) const { return joints_[i]; }
  /// C_ij, joint i's turn per turn of motor j.
  const ChainRate& coupling(std::size_t i, std::size_t j) const { return coupling_[i][j]; }
  /// The tool axis a in the last body (unit).
  const Vector3d& axis() const noexcept { return axis_; }
  /// L_j: motor j's period is 2 pi L_j.
  std::int64_t period_turns(std::size_t j) const { return period_turns_[j]; }
  /// T_j = 2 pi L_j (in double; the solvers enclose it).
  double period(std::size_t j) const { return Constants<double>::two_pi() * static_cast<double>(period_turns_[j]); }
  /// sum_i |C_ij|: the most any joint angle moves per radian of motor j, all joints together.
  double joint_speed(std::size_t j) const {
    double s = 0;
    for (std::size_t i = 0; i < joints(); ++i) s += std::fabs(coupling_[i][j].value());
    return s;
  }

  /// theta_i(u) = sum_j C_ij u_j + phi_i, each term p u / q. REQUIRES u.size() == motors().
  template <typename Scalar>
  Scalar joint_angle(std::size_t i, const std::vector<Scalar>& u) const {
    Scalar theta(joints_[i].phase);
    for (std::size_t j = 0; j < motors(); ++j) {
      const ChainRate& c = coupling_[i][j];
      if (!c.is_zero()) theta += Scalar(static_cast<double>(c.p())) * u[j] / Scalar(static_cast<double>(c.q()));
    }
    return theta;
  }

  /// F(u) (any Scalar with sin_cos: double, long double, MPFR). REQUIRES u.size() == motors().
  template <typename Scalar>
  Matrix3<Scalar> frame(const std::vector<Scalar>& u) const {
    Matrix3<Scalar> f = Matrix3<Scalar>::Identity();
    for (std::size_t i = 0; i < joints(); ++i) {
      const SinCos<Scalar> t = sin_cos(joint_angle(i, u)), a = sin_cos(Scalar(joints_[i].twist));
      Matrix3<Scalar> stage;
      stage << t.cos, -t.sin * a.cos, t.sin * a.sin, t.sin, t.cos * a.cos, -t.cos * a.sin, Scalar(0), a.sin, a.cos;  // Rz Rx
      f = Matrix3<Scalar>(f * stage);
    }
    return f;
  }

  /// P(u) = F(u) a.
  template <typename Scalar>
  Vector3<Scalar> point(const std::vector<Scalar>& u) const {
    return frame(u) * axis_.template cast<Scalar>();
  }

  /// "A1,...,Ak" as shortest round-trip doubles.
  std::string twists_text() const {
    std::string t;
    for (const WristJoint& j : joints_) t += (t.empty() ? "" : ",") + number_text(j.twist);
    return t;
  }
  /// "1,0;0,1;0,3/2": the coupling by rows.
  std::string coupling_text() const {
    std::string t;
    for (std::size_t i = 0; i < coupling_.size(); ++i) {
      t += i == 0 ? "" : ";";
      for (std::size_t j = 0; j < coupling_[i].size(); ++j) t += (j == 0 ? "" : ",") + coupling_[i][j].str();
    }
    return t;
  }

 private:
  void check_joints() {
    if (joints_.empty() || joints_.size() > kMaxJoints)
      throw InvalidInput("twists", std::to_string(joints_.size()) + " joint(s)", "not a wrist", "1 to 6 twists A1,...,Ak");
    const double pi = Constants<double>::pi();
    for (std::size_t i = 0; i < joints_.size(); ++i) {
      const std::string at = " (joint " + std::to_string(i + 1) + ")";
      if (!(joints_[i].twist >= 0 && joints_[i].twist <= pi))
        throw InvalidInput("twists", number_text(joints_[i].twist) + at, "outside [0, pi]", "A in [0, pi] radians");
      if (!std::isfinite(joints_[i].phase))
        throw InvalidInput("phases", number_text(joints_[i].phase) + at, "not finite", "a finite angle in radians");
      joints_[i].phase = reduce_phase(joints_[i].phase);
    }
  }

  void check_coupling_shape() const {
    const std::string valid = "one row per twist, each with 2 or 3 entries p/q (|p|, q <= 1000): \"1,0;0,1;0,3/2\"";
    if (coupling_.size() != joints_.size())
      throw InvalidInput("coupling", coupling_text(),
                         std::to_string(coupling_.size()) + " row(s) for " + std::to_string(joints_.size()) + " twist(s)", valid);
    const std::size_t m = coupling_.front().size();
    if (m < 2 || m > 3) throw InvalidInput("coupling", coupling_text(), std::to_string(m) + " motor(s)", valid);
    for (std::size_t i = 0; i < coupling_.size(); ++i) {
      if (coupling_[i].size() != m)
        throw InvalidInput("coupling", coupling_text(),
                           "row " + std::to_string(i + 1) + " has " + std::to_string(coupling_[i].size()) + " entries, row 1 has " + std::to_string(m),
                           valid);
      for (const ChainRate& c : coupling_[i])
        if (c.p() > kMaxCouplingTerm || c.p() < -kMaxCouplingTerm || c.q() > kMaxCouplingTerm)
          throw InvalidInput("coupling", coupling_text(), "the entry " + c.str() + " has a term above 1000", valid);
    }
  }

  std::int64_t column_lcm(std::size_t j) const {
    std::int64_t l = 1;
    for (const auto& row : coupling_) {
      l = std::lcm(l, row[j].q());
      if (l > kMaxPeriodTurns)
        throw InvalidInput("coupling", coupling_text(),
                           "motor " + std::to_string(j + 1) + "'s denominators have an lcm above 1000 (its period 2 pi L)",
                           "columns whose denominators have an lcm L <= 1000");
    }
    return l;
  }

  /// B_ij = C_ij L_j, an integer with |B_ij| <= 1e6: its m x m minors are exact in int64
  /// (a 3 x 3 one is at most 6 (1e6)^3 = 6e18 < 2^63).
  std::int64_t scaled(std::size_t i, std::size_t j) const {
    return coupling_[i][j].p() * (period_turns_[j] / coupling_[i][j].q());
  }

  std::int64_t minor(const std::vector<std::size_t>& rows) const {
    const auto b = [&](std::size_t r, std::size_t c) { return scaled(rows[r], c); };
    if (rows.size() == 2) return b(0, 0) * b(1, 1) - b(0, 1) * b(1, 0);
    return b(0, 0) * (b(1, 1) * b(2, 2) - b(1, 2) * b(2, 1)) - b(0, 1) * (b(1, 0) * b(2, 2) - b(1, 2) * b(2, 0)) +
           b(0, 2) * (b(1, 0) * b(2, 1) - b(1, 1) * b(2, 0));
  }

  /// Rank m: some m x m minor is not 0 (every choice of m rows of at most 6).
  void check_rank() const {
    const std::size_t k = joints(), m = motors();
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = a + 1; b < k; ++b) {
        if (m == 2 && minor({a, b}) != 0) return;
        for (std::size_t c = b + 1; m == 3 && c < k; ++c)
          if (minor({a, b, c}) != 0) return;
      }
    throw InvalidInput("coupling", coupling_text(), "of rank below " + std::to_string(m) + ": the motors do not turn the joints independently",
                       "a coupling of rank m (m = 2 or 3 columns), e.g. 1,0;0,1;0,2");
  }

  std::vector<WristJoint> joints_;
  std::vector<std::vector<ChainRate>> coupling_;
  std::vector<std::int64_t> period_turns_;
  Vector3d axis_ = Vector3d::UnitZ();
};

}  // namespace sphtroch
