// sphtroch/wrist/wrist_critical.hpp — the fold function of a 2-motor wrist, D(u) = det[P, dP/du_1,
// dP/du_2], with its gradient, enclosed over a box of motor angles or in doubles at a point, and
// points proved to lie on its zero set (the critical curve) by the one Krawczyk step.
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   sphtroch::RoundingGuard upward;                      // REQUIRED while it is built and evaluated over boxes
//   const sphtroch::WristCritical critical(wrist);
//   const auto v = critical.over({sphtroch::Interval(0.1, 0.2), sphtroch::Interval(1.0, 1.1)});
//   v.det;                                               // contains D(u) for every u of the box
//   const auto on = critical.fold_point_on_line({0.3, 0.1}, {0.0, 1.0}, 1.0);   // D = 0 at u2 = 0: a box holding such a u
//
// The fold: dP/du_j = omega_j x P (wrist.hpp), and (a x P) x (b x P) = det[a, b, P] P, so
// det[P, omega_1 x P, omega_2 x P] = |P|^2 (omega_1 x omega_2) . P. D(u) = (omega_1 x omega_2) . P
// is what is enclosed: it has the same zero set and sign (|P| = |a| > 0). Its gradient:
// dD/du_l = (rho_1l x omega_2 + omega_1 x rho_2l) . P + (omega_1 x omega_2) . (omega_l x P), rho_jl =
// d omega_j / d u_l (wrist_enclosure.hpp's pose_with_rates).
// Contract of `over`: D, its gradient, P and omega_j at every point of the box lie in the returned
// intervals (outward rounded). fold_point_on_line(c, d, reach): Newton in doubles on psi(t) = D(c + t
// d) from t = 0 (|t| |d|_inf <= reach), then the Krawczyk step (interval/krawczyk.hpp, N = 1) on
// T = [t - r, t + r] by epsilon-inflation: a box of motor angles c + K d (K inside T) that holds a
// point with D = 0 exactly, or nothing. A 2-motor wrist only (InvalidInput "coupling" otherwise).
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_critical.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/interval_vector.hpp"
#include "sphtroch/interval/krawczyk.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_enclosure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>

namespace sphtroch {

/// P(u), omega_1, omega_2, D(u) and its gradient, in T = double or Interval.
template <typename T>
struct WristFoldValue {
  Vec3<T> point;
  std::array<Vec3<T>, 2> omega;
  T det;
  std::array<T, 2> det_gradient;
};

class WristCritical {
 public:
  /// REQUIRES rounding upward; wrist.motors() == 2 (InvalidInput "coupling" otherwise).
  explicit WristCritical(const Wrist& wrist) : enclosure_(wrist) {
    if (wrist.motors() != 2)
      throw InvalidInput("coupling", wrist.coupling_text(), "3 motors: the fold curve is a 2-motor notion",
                         "a 2-column coupling (the tool axis driven by 2 motors)");
    for (int x = 0; x < 3; ++x) axis_d_[x] = wrist.axis()[x], axis_i_[x] = Interval(wrist.axis()[x]);
  }

  /// Over the box u. REQUIRES rounding upward.
  WristFoldValue<Interval> over(const IntervalBox<2>& u) const { return value<Interval>(enclosure_.pose_with_rates<2>(u), axis_i_); }
  /// At the point u in doubles (an estimate: Newton's steps, the choice of lines).
  WristFoldValue<double> at(const PointN<2>& u) const { return value<double>(enclosure_.pose_with_rates_at<2>(u), axis_d_); }

  /// A box of motor angles holding a point of the line c + t d where D = 0 exactly, found within
  /// |t| |d|_inf <= reach (see header), or nothing. REQUIRES rounding upward; c, d finite.
  std::optional<IntervalBox<2>> fold_point_on_line(const PointN<2>& c, const PointN<2>& d, double reach) const {
    const std::optional<double> t = line_root(c, d, reach);
    if (!t) return std::nullopt;
    return fold_point_at(c, d, *t);
  }

  /// Newton's iterates on psi(t) = D(c + t d) from 0 (at most 12) within |t| |d|_inf <= reach, when
  /// they settle: a step below 1e-13 (1 + |t| |d|_inf) radians of motor, or below 1e-9 after the
  /// last (the rounding of D, ~1e-16 / |grad D|, may keep them from settling further). An estimate in
  /// doubles, proved by fold_point_at.
  std::optional<double> line_root(const PointN<2>& c, const PointN<2>& d, double reach) const {
    const double dn = std::max(std::fabs(d[0]), std::fabs(d[1]));
    if (!(dn > 0) || !std::isfinite(dn)) return std::nullopt;
    double t = 0, moved = 1;
    for (int it = 0; it < 12; ++it) {
      const WristFoldValue<double> v = at({c[0] + t * d[0], c[1] + t * d[1]});
      const double step = v.det / (v.det_gradient[0] * d[0] + v.det_gradient[1] * d[1]);
      if (!std::isfinite(step)) return std::nullopt;
      t -= step;
      moved = std::fabs(step) * dn;
      if (!(std::fabs(t) * dn <= reach)) return std::nullopt;
      if (moved < 1e-13 * (1 + std::fabs(t) * dn)) return t;
    }
    if (moved < 1e-9) return t;
    return std::nullopt;
  }

  /// The Krawczyk step (N = 1) on psi over [t - r, t + r], r |d|_inf = 1e-8 max(1, |t| |d|_inf),
  /// 1/8 of it, ..., down to r = 1e-15 max(1, |t|): the box c + K d holding a root of psi (D = 0
  /// there), or nothing. REQUIRES rounding upward.
  std::optional<IntervalBox<2>> fold_point_at(const PointN<2>& c, const PointN<2>& d, double t) const {
    const double dn = std::max(std::fabs(d[0]), std::fabs(d[1]));
    if (!(dn > 0) || !std::isfinite(dn)) return std::nullopt;
    const double first = 1e-8 * std::max(1.0, std::fabs(t) * dn) / dn;
    return epsilon_inflation(first, 1.0 / 8, 1e-15 * std::max(1.0, std::fabs(t)), [&](double r) -> std::optional<IntervalBox<2>> {
      const Interval tt(t - r, t + r);
      const WristFoldValue<Interval> vt = over(along(c, d, tt)), vy = over(along(c, d, Interval(t)));
      const IntervalMatrix<1> jx{{{vt.det_gradient[0] * d[0] + vt.det_gradient[1] * d[1]}}};
      const auto inverse = midpoint_inverse<1>(midpoint<1>(jx));
      if (!inverse) return std::nullopt;
      const KrawczykStep<1> s = krawczyk_step<1>({tt}, {t}, {vy.det}, jx, *inverse);
      if (s.verdict != KrawczykVerdict::unique) return std::nullopt;
      return along(c, d, s.box[0]);
    });
  }

  /// c + t d, enclosed (c, d exact doubles). REQUIRES rounding upward.
  static IntervalBox<2> along(const PointN<2>& c, const PointN<2>& d, const Interval& t) {
    return {Interval(c[0]) + t * d[0], Interval(c[1]) + t * d[1]};
  }

 private:
  template <typename T>
  static WristFoldValue<T> value(const WristPose<T>& pose, const Vec3<T>& a) {
    WristFoldValue<T> v;
    for (int x = 0; x < 3; ++x) v.point[x] = pose.frame[0][x] * a[0] + pose.frame[1][x] * a[1] + pose.frame[2][x] * a[2];
    v.omega = {pose.omega[0], pose.omega[1]};
    const Vec3<T> n = cross(pose.omega[0], pose.omega[1]);
    v.det = dot(n, v.point);
    for (std::size_t l = 0; l < 2; ++l) {
      const Vec3<T> dn = cross(pose.omega_rate[0][l], pose.omega[1]), dm = cross(pose.omega[0], pose.omega_rate[1][l]);
      const Vec3<T> dp = cross(pose.omega[l], v.point);
      v.det_gradient[l] = dot(dn, v.point) + dot(dm, v.point) + dot(n, dp);
    }
    return v;
  }

  WristEnclosure enclosure_;
  Vec3<Interval> axis_i_;
  Vec3<double> axis_d_{};
};

/// Points at which wrist_fold_vanishes_everywhere samples D.
constexpr std::size_t kWristDegenerateSamples = 1024;

/// True when D vanishes, to 1e-12 of its scale |omega_1| |omega_2| <= (sum_i |C_i1|)(sum_i |C_i2|),
/// at kWristDegenerateSamples points of the motor torus spread by the R2 sequence (fractions
/// k (0.7548776662466927, 0.5698402909980532) of the periods): a wrist whose map u -> P(u) has rank
/// below 2 everywhere (a twist of 0 joining two joints, all twists 0, a tool axis along a joint's
/// axis). Its fold set is its whole image: no cap or atlas can be proved, so wrist_cap and
/// wrist_fold_atlas answer "not certified" at once instead of spending their box budgets. A
/// sampling test, not a proof: a true result only withholds a certificate (exit 3), never states
/// a wrong one. REQUIRES wrist.motors() == 2.
inline bool wrist_fold_vanishes_everywhere(const Wrist& wrist) {
  RoundingGuard upward;  // WristCritical's contract
  const WristCritical critical(wrist);
  const double scale = std::max(1e-300, wrist.joint_speed(0) * wrist.joint_speed(1));
  for (std::size_t k = 1; k <= kWristDegenerateSamples; ++k) {
    const double a = std::fmod(0.5 + 0.7548776662466927 * static_cast<double>(k), 1.0);
    const double b = std::fmod(0.5 + 0.5698402909980532 * static_cast<double>(k), 1.0);
    if (std::fabs(critical.at({a * wrist.period(0), b * wrist.period(1)}).det) > 1e-12 * scale) return false;
  }
  return true;
}

}  // namespace sphtroch
