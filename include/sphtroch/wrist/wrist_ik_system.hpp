// sphtroch/wrist/wrist_ik_system.hpp — a wrist's inverse kinematics as a square system f(u) = 0
// in the m motor angles, with its Jacobian and a sign that tells the true roots from the others,
// in doubles at a point or enclosed over a box (the equations of wrist_ik.hpp's search).
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   sphtroch::RoundingGuard upward;   // REQUIRED while it is built and evaluated over boxes
//   const sphtroch::WristIkSystem<2> s(wrist, sphtroch::WristTarget::pointing(sphtroch::Vector3d(0.6, 0, 0.8)));
//   const auto v = s.over({sphtroch::Interval(0.0, 0.1), sphtroch::Interval(2.0, 2.1)});   // f, J, sign over the box
//
// m = 2, pointing at t (a unit double vector, exact as stored): w = P(u) x t vanishes exactly when
// P is parallel to t. The two equations are the components of w other than the index k of the
// largest |t_k| (w is orthogonal to t, so w_k t_k = -(the other two terms): those two vanish only
// when w = 0). Roots: P = +t (true) and P = -t (the antipode). sign = t . P, which is |t| |a| at
// a true root (its largest value), -|t| |a| at the antipode.
// m = 3, orientation R* (the exact rotation of the target's quaternion, enclosed): E = R*^T F(u);
// the equations are vee(E - E^T) = (E_21 - E_12, E_02 - E_20, E_10 - E_01), which vanish exactly when
// E is symmetric: E = I (true) or E a half-turn. sign = trace E: 3 at a true root (its largest
// value), -1 at a half-turn.
// Derivatives: dF/du_j = [omega_j]x F (wrist.hpp), so dP/du_j = omega_j x P and column c of
// dF/du_j is omega_j x F_c. Contract of `over`: every f, J, sign and sign gradient at every point
// of the box lies in the returned intervals.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_ik_system.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/interval_vector.hpp"
#include "sphtroch/interval/krawczyk.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_enclosure.hpp"
#include "sphtroch/wrist/wrist_target.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>

namespace sphtroch {

template <std::size_t M>
class WristIkSystem {
  static_assert(M == 2 || M == 3, "a wrist has 2 motors (pointing) or 3 (orientation)");

 public:
  /// f, its Jacobian jac[row][motor], the sign quantity and its gradient, in T.
  template <typename T>
  struct Value {
    std::array<T, M> f;
    std::array<std::array<T, M>, M> jac;
    T sign;
    std::array<T, M> sign_gradient;
  };

  /// REQUIRES rounding upward; wrist.motors() == M and a target of the matching kind (InvalidInput
  /// "target" or "target-frame" otherwise).
  WristIkSystem(const Wrist& wrist, const WristTarget& target) : enclosure_(wrist) {
    check_kind(wrist, target);
    const Vector3d a = wrist.axis();
    if constexpr (M == 2) {
      const Vector3d t = target.direction;
      drop_ = 0;
      for (int x = 1; x < 3; ++x)
        if (std::fabs(t[x]) > std::fabs(t[drop_])) drop_ = x;
      for (int x = 0; x < 3; ++x) {
        target_d_[0][x] = t[x], axis_d_[x] = a[x];
        target_i_[0][x] = Interval(t[x]), axis_i_[x] = Interval(a[x]);
      }
      const Interval tt = dot(target_i_[0], target_i_[0]), aa = dot(axis_i_, axis_i_);
      peak_ = CGAL::sqrt(tt) * CGAL::sqrt(aa);
      threshold_ = 0.0;
    } else {
      enclose_rotation(target.rotation);
      peak_ = Interval(3.0);
      threshold_ = 1.0;
    }
  }

  /// f, J, sign over the box. REQUIRES rounding upward.
  Value<Interval> over(const IntervalBox<M>& u) const { return value<Interval>(enclosure_.pose<M>(u)); }
  /// The same at a point, in doubles (an estimate for Newton's steps and the bisection's choice).
  Value<double> at(const PointN<M>& u) const { return value<double>(enclosure_.pose_at<M>(u)); }

  /// The sign at every true root (|t| |a|, or 3), enclosed: a box whose sign stays below it holds none.
  const Interval& peak() const noexcept { return peak_; }
  /// A root of f whose sign is above this is a true root; below it, the antipode or a half-turn.
  double threshold() const noexcept { return threshold_; }

 private:
  static void check_kind(const Wrist& wrist, const WristTarget& target) {
    if (wrist.motors() != M) throw InvalidInput("coupling", wrist.coupling_text(), "not " + std::to_string(M) + " columns", "the system's motor count");
    const bool pointing = target.kind == WristTarget::Kind::pointing;
    if (M == 2 && !pointing)
      throw InvalidInput("target-frame", "an orientation", "a 2-motor wrist cannot hold a frame (3 conditions, 2 motors)",
                         "--target X,Y,Z with 2 motors, --target-frame with 3");
    if (M == 3 && pointing)
      throw InvalidInput("target", "a direction", "a 3-motor wrist points along it on whole curves of motor angles",
                         "--target-frame with 3 motors, --target X,Y,Z with 2");
  }

  /// R(q) for q = (w, x, y, z): (1 / |q|^2) [[w2+x2-y2-z2, 2(xy-wz), 2(xz+wy)], ...], enclosed
  /// (an exact rotation), by columns; and in doubles.
  void enclose_rotation(const Eigen::Quaterniond& q) {
    const Interval w(q.w()), x(q.x()), y(q.y()), z(q.z());
    const Interval n = w * w + x * x + y * y + z * z;
    const Interval r[3][3] = {{w * w + x * x - y * y - z * z, 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)},
                              {2.0 * (x * y + w * z), w * w - x * x + y * y - z * z, 2.0 * (y * z - w * x)},
                              {2.0 * (x * z - w * y), 2.0 * (y * z + w * x), w * w - x * x - y * y + z * z}};
    const Matrix3d rd = q.normalized().toRotationMatrix();
    for (int c = 0; c < 3; ++c)
      for (int row = 0; row < 3; ++row) {
        target_i_[c][row] = r[row][c] / n;
        target_d_[c][row] = rd(row, c);
      }
  }

  template <typename T>
  const std::array<Vec3<T>, 3>& target() const {
    if constexpr (std::is_same_v<T, Interval>) return target_i_;
    else return target_d_;
  }
  template <typename T>
  const Vec3<T>& axis() const {
    if constexpr (std::is_same_v<T, Interval>) return axis_i_;
    else return axis_d_;
  }

  template <typename T>
  Value<T> value(const WristPose<T>& pose) const {
    if constexpr (M == 2) return pointing(pose);
    else return orienting(pose);
  }

  template <typename T>
  Value<T> pointing(const WristPose<T>& pose) const {
    const Vec3<T>& a = axis<T>();
    const Vec3<T>& t = target<T>()[0];
    Vec3<T> p;
    for (int x = 0; x < 3; ++x) p[x] = pose.frame[0][x] * a[0] + pose.frame[1][x] * a[1] + pose.frame[2][x] * a[2];
    const int i = (drop_ + 1) % 3, j = (drop_ + 2) % 3;
    Value<T> v;
    const Vec3<T> w = cross(p, t);
    v.f = {w[i], w[j]};
    v.sign = dot(t, p);
    for (std::size_t l = 0; l < M; ++l) {
      const Vec3<T> dp = cross(pose.omega[l], p), dw = cross(dp, t);
      v.jac[0][l] = dw[i];
      v.jac[1][l] = dw[j];
      v.sign_gradient[l] = dot(t, dp);
    }
    return v;
  }

  /// vee(E - E^T) of E_rc = R*_r . G_c (G: F's columns or their derivatives), and trace E.
  template <typename T>
  std::pair<std::array<T, 3>, T> skew_and_trace(const std::array<Vec3<T>, 3>& g) const {
    const std::array<Vec3<T>, 3>& r = target<T>();
    const auto e = [&](int row, int c) { return dot(r[row], g[c]); };
    return {{e(2, 1) - e(1, 2), e(0, 2) - e(2, 0), e(1, 0) - e(0, 1)}, e(0, 0) + e(1, 1) + e(2, 2)};
  }

  template <typename T>
  Value<T> orienting(const WristPose<T>& pose) const {
    Value<T> v;
    const auto [f, trace] = skew_and_trace<T>(pose.frame);
    for (std::size_t r = 0; r < M; ++r) v.f[r] = f[r];
    v.sign = trace;
    for (std::size_t l = 0; l < M; ++l) {
      std::array<Vec3<T>, 3> d;
      for (int c = 0; c < 3; ++c) d[c] = cross(pose.omega[l], pose.frame[c]);
      const auto [df, dtrace] = skew_and_trace<T>(d);
      for (std::size_t r = 0; r < M; ++r) v.jac[r][l] = df[r];
      v.sign_gradient[l] = dtrace;
    }
    return v;
  }

  WristEnclosure enclosure_;
  int drop_ = 2;
  std::array<Vec3<Interval>, 3> target_i_;  // pointing: [0] = t; orientation: R*'s columns
  std::array<Vec3<double>, 3> target_d_;
  Vec3<Interval> axis_i_;
  Vec3<double> axis_d_{};
  Interval peak_{0.0};
  double threshold_ = 0;
};

}  // namespace sphtroch
