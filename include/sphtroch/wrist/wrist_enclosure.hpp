// sphtroch/wrist/wrist_enclosure.hpp — a wrist's frame F(u) and the motors' angular velocities
// omega_j (wrist.hpp) enclosed over a box of motor angles (interval arithmetic, outward
// rounded), or computed in doubles at a point by the same operations.
//
//   const sphtroch::Wrist wrist({{0.3, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   sphtroch::RoundingGuard upward;                      // REQUIRED for the interval pose
//   const sphtroch::WristEnclosure e(wrist);
//   const sphtroch::WristPose<sphtroch::Interval> f = e.pose<2>({sphtroch::Interval(0.1, 0.2), sphtroch::Interval(1.0, 1.1)});
//   f.frame[2][2];   // contains F_zz(u) for every u of the box
//
// Contract: for every u in the box U, column c of F(u) lies in pose(U).frame[c] and omega_j(u) in
// pose(U).omega[j] (componentwise); with pose_with_rates, d omega_j / d u_l (u) lies in
// omega_rate[j][l] as well (d Z_i / d u_l = Omega_{i-1,l} x Z_i, Omega_{i-1,l} = sum_{i' < i} C_i'l Z_i',
// so d omega_j / d u_l = sum_i C_ij Omega_{i-1,l} x Z_i). How: the joint angles sum_j C_ij U_j + phi_i in intervals (C_ij
// = p / q enclosed), their sines and cosines by interval_sincos_in_nearest_mode (interval/interval.hpp),
// then R_i = R_{i-1} Rz(theta_i) Rx(A_i) multiplied out, the axes Z_i = R_{i-1} z on the way. The
// natural extension: widths grow with the box, the callers intersect it with mean-value forms.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_enclosure.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/interval_vector.hpp"
#include "sphtroch/wrist/wrist.hpp"

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace sphtroch {

/// F's columns and omega_1 .. omega_m (unused ones 0), in T = double or Interval; omega_rate[j][l]
/// = d omega_j / d u_l (pose_with_rates only; 0 otherwise).
template <typename T>
struct WristPose {
  std::array<Vec3<T>, 3> frame;
  std::array<Vec3<T>, 3> omega;
  std::array<std::array<Vec3<T>, 3>, 3> omega_rate;
};

class WristEnclosure {
 public:
  /// REQUIRES the rounding mode upward (a RoundingGuard held): the coefficients are enclosed.
  explicit WristEnclosure(const Wrist& wrist) : motors_(wrist.motors()) {
    for (std::size_t i = 0; i < wrist.joints(); ++i) {
      std::vector<Interval> row;
      std::vector<double> row_d;
      for (std::size_t j = 0; j < motors_; ++j) {
        const ChainRate& c = wrist.coupling(i, j);
        row.push_back(Interval(static_cast<double>(c.p())) / Interval(static_cast<double>(c.q())));
        row_d.push_back(c.value());
      }
      interval_.rate.push_back(row);
      point_.rate.push_back(row_d);
      interval_.phase.push_back(Interval(wrist.joint(i).phase));
      point_.phase.push_back(wrist.joint(i).phase);
      interval_.twist.push_back(interval_sincos(Interval(wrist.joint(i).twist)));
      point_.twist.push_back(interval_sincos(wrist.joint(i).twist));
    }
  }

  std::size_t motors() const noexcept { return motors_; }

  /// F and omega over the box u. REQUIRES rounding upward, M == motors().
  template <std::size_t M>
  WristPose<Interval> pose(const std::array<Interval, M>& u) const {
    return pose_in<M, Interval>(u);
  }
  /// F and omega at the point u in doubles (an estimate, in the caller's rounding mode). REQUIRES M == motors().
  template <std::size_t M>
  WristPose<double> pose_at(const std::array<double, M>& u) const {
    return pose_in<M, double>(u);
  }
  /// pose(), with d omega_j / d u_l enclosed too. REQUIRES rounding upward, M == motors().
  template <std::size_t M>
  WristPose<Interval> pose_with_rates(const std::array<Interval, M>& u) const {
    return pose_in<M, Interval>(u, true);
  }
  /// pose_at(), with d omega_j / d u_l too (doubles, an estimate).
  template <std::size_t M>
  WristPose<double> pose_with_rates_at(const std::array<double, M>& u) const {
    return pose_in<M, double>(u, true);
  }

 private:
  template <std::size_t M, typename T>
  WristPose<T> pose_in(const std::array<T, M>& u, bool rates = false) const {
    const Coefficients<T>& c = coefficients<T>();
    const std::size_t k = c.phase.size();
    std::vector<T> angle(k);
    for (std::size_t i = 0; i < k; ++i) {
      T theta = c.phase[i];
      for (std::size_t j = 0; j < M; ++j) theta += c.rate[i][j] * u[j];
      angle[i] = theta;
    }
    const std::vector<std::pair<T, T>> trig = sincos_all(angle);
    std::array<Vec3<T>, 3> r = identity<T>();
    WristPose<T> out;
    for (auto& w : out.omega) w = {T(0.0), T(0.0), T(0.0)};
    for (auto& row : out.omega_rate)
      for (auto& w : row) w = {T(0.0), T(0.0), T(0.0)};
    for (std::size_t i = 0; i < k; ++i) {
      if (rates) add_rates<M>(c, i, r[2], out);  // before omega takes joint i: Omega_{i-1,l}
      for (std::size_t j = 0; j < M; ++j)
        for (int x = 0; x < 3; ++x) out.omega[j][x] += c.rate[i][j] * r[2][x];  // Z_i = R_{i-1} z
      r = times_stage(r, trig[i], c.twist[i]);
    }
    out.frame = r;
    return out;
  }

  template <typename T>
  struct Coefficients {
    std::vector<std::vector<T>> rate;
    std::vector<T> phase;
    std::vector<std::pair<T, T>> twist;  // (sin, cos)
  };

  /// omega_rate[j][l] += C_ij Omega_{i-1,l} x Z_i (out.omega holds Omega_{i-1,l} when called).
  template <std::size_t M, typename T>
  static void add_rates(const Coefficients<T>& c, std::size_t i, const Vec3<T>& z, WristPose<T>& out) {
    for (std::size_t l = 0; l < M; ++l) {
      const Vec3<T> v = cross(out.omega[l], z);
      for (std::size_t j = 0; j < M; ++j)
        for (int x = 0; x < 3; ++x) out.omega_rate[j][l][x] += c.rate[i][j] * v[x];
    }
  }

  template <typename T>
  const Coefficients<T>& coefficients() const {
    if constexpr (std::is_same_v<T, Interval>) return interval_;
    else return point_;
  }

  /// sin and cos of every joint angle: enclosures (one switch to round-to-nearest for all), or doubles.
  static std::vector<std::pair<Interval, Interval>> sincos_all(const std::vector<Interval>& angle) {
    std::vector<std::pair<Interval, Interval>> out(angle.size());
    const RoundingGuard nearest(CGAL_FE_TONEAREST);
    for (std::size_t i = 0; i < angle.size(); ++i) out[i] = interval_sincos_in_nearest_mode(angle[i]);
    return out;
  }
  static std::vector<std::pair<double, double>> sincos_all(const std::vector<double>& angle) {
    std::vector<std::pair<double, double>> out(angle.size());
    for (std::size_t i = 0; i < angle.size(); ++i) out[i] = interval_sincos(angle[i]);
    return out;
  }

  template <typename T>
  static std::array<Vec3<T>, 3> identity() {  // columns
    return {Vec3<T>{T(1.0), T(0.0), T(0.0)}, Vec3<T>{T(0.0), T(1.0), T(0.0)}, Vec3<T>{T(0.0), T(0.0), T(1.0)}};
  }

  /// R Rz(theta) Rx(A) by columns, t = (sin, cos) of theta, a = (sin, cos) of A:
  /// Rz Rx = [[c, -s ca, s sa], [s, c ca, -c sa], [0, sa, ca]].
  template <typename T>
  static std::array<Vec3<T>, 3> times_stage(const std::array<Vec3<T>, 3>& r, const std::pair<T, T>& t, const std::pair<T, T>& a) {
    std::array<Vec3<T>, 3> out;
    for (int x = 0; x < 3; ++x) {
      out[0][x] = r[0][x] * t.second + r[1][x] * t.first;
      const T y = r[1][x] * t.second - r[0][x] * t.first;  // R (Rz e_y)
      out[1][x] = y * a.second + r[2][x] * a.first;
      out[2][x] = r[2][x] * a.second - y * a.first;
    }
    return out;
  }

  std::size_t motors_;
  Coefficients<Interval> interval_;
  Coefficients<double> point_;
};

}  // namespace sphtroch
