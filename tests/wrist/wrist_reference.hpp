// tests/wrist/wrist_reference.hpp — the wrist written again for the tests, independently of
// include/sphtroch/wrist/: the frame as a product of Eigen AngleAxis rotations in long double, and
// an inverse-kinematics count by a dense torus grid, Gauss-Newton and de-duplication (no
// intervals, no Krawczyk); the fold determinant det[P, dP/du_1, dP/du_2] by differentiating the
// product of rotation matrices factor by factor (no angular velocities).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <numeric>
#include <vector>

namespace sphtroch::test {

using Vec3L = Eigen::Matrix<long double, 3, 1>;
using Mat3L = Eigen::Matrix<long double, 3, 3>;

/// A wrist as the tests draw it: twists, phases, coupling entries p/q by rows, tool axis.
struct WristModel {
  std::vector<double> twist, phase;
  std::vector<std::vector<std::pair<int, int>>> coupling;  // [joint][motor] = (p, q), q > 0
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();

  std::size_t motors() const { return coupling.front().size(); }
  /// lcm of column j's denominators, each fraction in lowest terms (0 = 0/1).
  long period_turns(std::size_t j) const {
    long l = 1;
    for (const auto& row : coupling) l = std::lcm(l, static_cast<long>(row[j].second / std::gcd(std::abs(row[j].first), row[j].second)));
    return l;
  }
  long double period(std::size_t j) const { return 2 * 3.141592653589793238462643383279502884L * period_turns(j); }
  /// sum_i |C_ij|.
  double speed(std::size_t j) const {
    double s = 0;
    for (const auto& row : coupling) s += std::fabs(double(row[j].first) / row[j].second);
    return s;
  }
  long double angle(std::size_t i, const std::vector<long double>& u) const {
    long double t = phase[i];
    for (std::size_t j = 0; j < u.size(); ++j) t += (long double)coupling[i][j].first * u[j] / coupling[i][j].second;
    return t;
  }
  /// F(u) = prod_i Rz(theta_i) Rx(A_i) (AngleAxis products).
  Mat3L frame(const std::vector<long double>& u) const {
    Mat3L r = Mat3L::Identity();
    for (std::size_t i = 0; i < twist.size(); ++i)
      r = r * Eigen::AngleAxis<long double>(angle(i, u), Vec3L::UnitZ()).toRotationMatrix() *
          Eigen::AngleAxis<long double>(twist[i], Vec3L::UnitX()).toRotationMatrix();
    return r;
  }
  Vec3L point(const std::vector<long double>& u) const { return frame(u) * axis.cast<long double>().normalized(); }

  /// P and dP/du_j = omega_j x P for 2 motors, omega_j = sum_i C_ij Z_i (Z_i the axis of joint
  /// i), the rotations Rz Rx written out in S (double for Newton's many steps; frame() is the
  /// AngleAxis product in long double).
  template <typename S>
  void point_and_jacobian(const S (&u)[2], Eigen::Matrix<S, 3, 1>& p, Eigen::Matrix<S, 3, 2>& jac) const {
    using V = Eigen::Matrix<S, 3, 1>;
    using M = Eigen::Matrix<S, 3, 3>;
    M r = M::Identity();
    V omega[2] = {V::Zero(), V::Zero()};
    for (std::size_t i = 0; i < twist.size(); ++i) {
      S theta = S(phase[i]);
      for (std::size_t j = 0; j < 2; ++j) {
        const S rate = S(coupling[i][j].first) / S(coupling[i][j].second);
        omega[j] += rate * r.col(2);
        theta += rate * u[j];
      }
      const S s = std::sin(theta), c = std::cos(theta), sa = std::sin(S(twist[i])), ca = std::cos(S(twist[i]));
      M stage;
      stage << c, -s * ca, s * sa, s, c * ca, -c * sa, 0, sa, ca;
      r = M(r * stage);
    }
    p = r * axis.cast<S>().normalized();
    for (int j = 0; j < 2; ++j) jac.col(j) = omega[j].cross(p);
  }
};

/// det[P, dP/du_1, dP/du_2] of a 2-motor wrist in S: F = prod_i Rz(theta_i) Rx(A_i), dF/du_j =
/// sum_i C_ij (prod_{i' < i} ...) Rz'(theta_i) Rx(A_i) (prod_{i' > i} ...), Rz' = d Rz / d theta,
/// each product multiplied out; P = F a, dP/du_j = (dF/du_j) a.
template <typename S>
S fold_det(const WristModel& w, const S (&u)[2]) {
  using M = Eigen::Matrix<S, 3, 3>;
  using V = Eigen::Matrix<S, 3, 1>;
  const std::size_t k = w.twist.size();
  std::vector<M> rz(k), drz(k), rx(k);
  for (std::size_t i = 0; i < k; ++i) {
    S theta = S(w.phase[i]);
    for (std::size_t j = 0; j < 2; ++j) theta += S(w.coupling[i][j].first) * u[j] / S(w.coupling[i][j].second);
    const S c = std::cos(theta), s = std::sin(theta), ca = std::cos(S(w.twist[i])), sa = std::sin(S(w.twist[i]));
    rz[i] << c, -s, 0, s, c, 0, 0, 0, 1;
    drz[i] << -s, -c, 0, c, -s, 0, 0, 0, 0;
    rx[i] << 1, 0, 0, 0, ca, -sa, 0, sa, ca;
  }
  const V a = w.axis.cast<S>().normalized();
  M f = M::Identity();
  for (std::size_t i = 0; i < k; ++i) f = M(f * rz[i] * rx[i]);
  V d[2] = {V::Zero(), V::Zero()};
  for (std::size_t i = 0; i < k; ++i) {
    M g = M::Identity();
    for (std::size_t l = 0; l < k; ++l) g = M(g * (l == i ? drz[l] : rz[l]) * rx[l]);
    const V dp = g * a;
    for (std::size_t j = 0; j < 2; ++j) d[j] += (S(w.coupling[i][j].first) / S(w.coupling[i][j].second)) * dp;
  }
  M m;
  m << f * a, d[0], d[1];
  return m.determinant();
}

/// The points of a dense grid's edges (spacing h radians of joint motion per motor, wrapping round
/// the torus) where fold_det changes sign, each bisected 60 times along its edge: (u_1, u_2), motor
/// j in [0, T_j).
inline std::vector<std::array<long double, 2>> fold_sign_changes(const WristModel& m, double h) {
  std::size_t n[2];
  for (std::size_t j = 0; j < 2; ++j) n[j] = static_cast<std::size_t>(std::ceil(double(m.period(j)) * m.speed(j) / h));
  const auto at = [&](double a, double b) {
    const double u[2] = {double(m.period(0)) * a / double(n[0]), double(m.period(1)) * b / double(n[1])};
    return fold_det<double>(m, u);
  };
  std::vector<double> det(n[0] * n[1]);
  for (std::size_t a = 0; a < n[0]; ++a)
    for (std::size_t b = 0; b < n[1]; ++b) det[a * n[1] + b] = at(double(a), double(b));
  std::vector<std::array<long double, 2>> out;
  for (std::size_t a = 0; a < n[0]; ++a)
    for (std::size_t b = 0; b < n[1]; ++b)
      for (int dir = 0; dir < 2; ++dir) {
        const double d0 = det[a * n[1] + b];
        const double d1 = dir == 0 ? det[((a + 1) % n[0]) * n[1] + b] : det[a * n[1] + (b + 1) % n[1]];
        if ((d0 > 0) == (d1 > 0)) continue;
        double lo = 0, hi = 1;  // along the edge, det's sign at lo is d0's
        for (int it = 0; it < 60; ++it) {
          const double t = 0.5 * (lo + hi);
          const double d = dir == 0 ? at(double(a) + t, double(b)) : at(double(a), double(b) + t);
          ((d > 0) == (d0 > 0) ? lo : hi) = t;
        }
        const double t = 0.5 * (lo + hi);
        out.push_back({m.period(0) * (double(a) + (dir == 0 ? t : 0)) / n[0], m.period(1) * (double(b) + (dir == 1 ? t : 0)) / n[1]});
      }
  return out;
}

/// The pointing solutions of a 2-motor wrist counted without intervals: P on a grid of spacing
/// h / sum_i |C_ij| per motor (computed once, in doubles); for a target t, Gauss-Newton on P(u) - t from every
/// grid point with |P - t| <= 1.05 h (the nearest grid point of a root is within h of it: |dP/du_j|
/// <= sum_i |C_ij|), in doubles to |P - t| < 1e-14; roots with |P - t| < 1e-13 by the AngleAxis
/// product in long double kept once (motors compared modulo their periods; iterates that come
/// within 1e-7 of a root found are that root).
class GridCount {
 public:
  GridCount(const WristModel& w, double h) : w_(w), h_(h) {
    for (std::size_t j = 0; j < 2; ++j) n_[j] = static_cast<std::size_t>(std::ceil(double(w.period(j)) * w.speed(j) / h));
    points_.reserve(n_[0] * n_[1]);
    for (std::size_t a = 0; a < n_[0]; ++a)
      for (std::size_t b = 0; b < n_[1]; ++b) {
        const std::vector<long double> g = grid(a, b);
        const double u[2] = {double(g[0]), double(g[1])};
        Eigen::Vector3d p;
        Eigen::Matrix<double, 3, 2> jac;
        w_.point_and_jacobian(u, p, jac);
        points_.push_back(p);
      }
  }

  std::vector<std::vector<long double>> roots(const Eigen::Vector3d& t) const {
    std::vector<std::vector<long double>> found;
    for (std::size_t a = 0; a < n_[0]; ++a)
      for (std::size_t b = 0; b < n_[1]; ++b) {
        if ((points_[a * n_[1] + b] - t).norm() > 1.05 * h_) continue;
        const std::vector<long double> start = grid(a, b);
        double u[2] = {double(start[0]), double(start[1])};
        if (!gauss_newton(u, t, found)) continue;
        const std::vector<long double> root{u[0], u[1]};
        if ((w_.point(root) - t.cast<long double>()).norm() > 1e-13L) continue;  // checked by the AngleAxis product
        if (std::none_of(found.begin(), found.end(), [&](const std::vector<long double>& v) { return same(root, v); })) found.push_back(root);
      }
    return found;
  }

  /// Whether u and v are one point of the torus (within 1e-8 radians of joint motion).
  bool same(const std::vector<long double>& u, const std::vector<long double>& v) const { return near(u, v, 1e-8); }

  /// Whether u and v are within `d` radians of joint motion in each motor, modulo the periods.
  bool near(const std::vector<long double>& u, const std::vector<long double>& v, double d) const {
    for (std::size_t j = 0; j < 2; ++j)
      if (std::fabs(std::remainder(u[j] - v[j], w_.period(j))) * w_.speed(j) > d) return false;
    return true;
  }

 private:
  std::vector<long double> grid(std::size_t a, std::size_t b) const {
    return {w_.period(0) * a / n_[0], w_.period(1) * b / n_[1]};
  }

  /// Gauss-Newton steps in doubles (at most 60, each at most 0.5 rad of joint motion) to |P - t|
  /// < 1e-14; false once an iterate is within 1e-7 rad of joint motion of a root in `found` (it is
  /// that root).
  bool gauss_newton(double (&u)[2], const Eigen::Vector3d& t, const std::vector<std::vector<long double>>& found) const {
    Eigen::Vector3d p;
    Eigen::Matrix<double, 3, 2> jac;
    for (int it = 0; it < 60; ++it) {
      w_.point_and_jacobian(u, p, jac);
      const Eigen::Vector3d r = p - t;
      if (r.norm() < 1e-14) return true;
      if (it % 4 == 3 && std::any_of(found.begin(), found.end(), [&](const std::vector<long double>& v) { return near({u[0], u[1]}, v, 1e-7); }))
        return false;
      const Eigen::Vector2d step = (jac.transpose() * jac).ldlt().solve(-jac.transpose() * r);
      if (!step.allFinite()) return false;
      double scale = 1;
      for (int j = 0; j < 2; ++j) scale = std::max(scale, std::fabs(step(j)) * w_.speed(std::size_t(j)) / 0.5);
      for (int j = 0; j < 2; ++j) u[j] += step(j) / scale;
    }
    return false;
  }

  WristModel w_;
  double h_;
  std::size_t n_[2] = {0, 0};
  std::vector<Eigen::Vector3d> points_;
};

}  // namespace sphtroch::test
