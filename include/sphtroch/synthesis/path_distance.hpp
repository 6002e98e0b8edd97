// sphtroch/synthesis/path_distance.hpp — how far a point is from the curve of a train: the nearest
// curve point (its theta2), the tracer point with its derivatives in theta2 and in the train's
// parameters (a2, a3, phase), and a quick latitude estimate for screening many shapes. The
// distance geometry of `fit` (path_fit.hpp). Eigen only; radians throughout.
//
//   const sphtroch::FitShape s{1.0, 2.0, 0.5, 0.3};        // a2, a3, n = p/q as a double, phase
//   sphtroch::CurveJet j = sphtroch::curve_jet(s, 0.7);     // P(0.7), dP/dtheta2, d2P/dtheta2^2, dP/da2, ...
//   const double period = 2 * sphtroch::Constants<double>::pi() * 2;   // 2 pi q, n = 1/2
//   double t = sphtroch::nearest_param(s, 1, period, j.point);         // 0.7 again: |p| = 1
//
// Model (Eqs. 3, 4): P(t) = Rz(t) C(u), u = n t + phase, C(u) = Rx(a2) Rz(u) Rx(a3) z, the planet's
// circle in the carrier frame. With Z2 = Rx(a2) z (the planet axis) and Omega = z + n Z2:
//   dC/du = Z2 x C,  dP/dt = Rz(t) (Omega x C),  d2P/dt2 = Rz(t) (z x (Omega x C) + n Omega x (Z2 x C)),
//   dP/da2 = Rz(t) (x x C),  dP/dphase = Rz(t) (Z2 x C),  dP/da3 = Rz(t) Rx(a2) Rz(u) (0, -cos a3, -sin a3).
// The curve of phase f is the curve of phase 0 turned by -f/n about Z, and it is symmetric under
// the turn by 2 pi/|p| (the phase is defined modulo 2 pi/q as a set).
//
// Nearest point. At its latitude z, a point meets the curve where the planet circle does:
// cos u = (cos a2 cos a3 - z) / (sin a2 sin a3), u = +-u0, which gives 2|p| candidate theta2 per
// period (fewer when z is beyond the curve's z range: the extreme is taken). The nearest
// candidates are refined by Newton on (P(t) - P_i) . dP/dt = 0. This finds the nearest point
// whenever it lies on a branch that reaches the point's latitude within the branch's Newton basin:
// always for points near the curve (the use here), not a global guarantee for far points.
#pragma once

#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace sphtroch {

/// The parameters of one train as the fit varies them: a2, a3 (radians, in (0, pi)), n as a
/// double (p/q), phase (radians), with the sines and cosines of a2 and a3 (a value: construct a
/// new one to change a2 or a3).
struct FitShape {
  FitShape() : FitShape(1.0, 1.0, 1.0, 0.0) {}
  FitShape(double a2_, double a3_, double n_, double phase_)
      : a2(a2_), a3(a3_), n(n_), phase(phase_), s2(std::sin(a2_)), c2(std::cos(a2_)), s3(std::sin(a3_)), c3(std::cos(a3_)) {}
  double a2, a3, n, phase;
  double s2, c2, s3, c3;
};

/// The tracer point at theta2 and its derivatives (see header).
struct CurveJet {
  Vector3d point, d_t, d_tt, d_a2, d_a3, d_phase;
};

namespace path_distance_detail {

/// Rx(a2) Rz(u) w for w = (0, -sin a, cos a), given sin, cos of a2, u and a.
inline Vector3d circle(const FitShape& s, double su, double cu, double sw, double cw) {
  return Vector3d(sw * su, -(sw * s.c2 * cu + cw * s.s2), s.c2 * cw - s.s2 * sw * cu);
}

/// Rz(t) a, given sin t and cos t.
inline Vector3d turn(double st, double ct, const Vector3d& a) {
  return Vector3d(ct * a.x() - st * a.y(), st * a.x() + ct * a.y(), a.z());
}

}  // namespace path_distance_detail

/// C(u) = Rx(a2) Rz(u) Rx(a3) z, the planet circle in the carrier frame.
inline Vector3d planet_circle_point(const FitShape& s, double u) {
  return path_distance_detail::circle(s, std::sin(u), std::cos(u), s.s3, s.c3);
}

/// The tracer point P(t) alone.
inline Vector3d curve_point(const FitShape& s, double t) {
  const double u = s.n * t + s.phase;
  return path_distance_detail::turn(std::sin(t), std::cos(t), path_distance_detail::circle(s, std::sin(u), std::cos(u), s.s3, s.c3));
}

inline CurveJet curve_jet(const FitShape& s, double t) {
  using path_distance_detail::circle;
  const double u = s.n * t + s.phase, su = std::sin(u), cu = std::cos(u), st = std::sin(t), ct = std::cos(t);
  const Vector3d c = circle(s, su, cu, s.s3, s.c3), dc_a3 = circle(s, su, cu, s.c3, -s.s3);
  const Vector3d z(0, 0, 1), x(1, 0, 0), z2(0, -s.s2, s.c2), omega = z + s.n * z2;
  const Vector3d dc_u = z2.cross(c), v = omega.cross(c);
  auto turn = [&](const Vector3d& a) { return path_distance_detail::turn(st, ct, a); };
  CurveJet j;
  j.point = turn(c);
  j.d_t = turn(v);
  j.d_tt = turn(z.cross(v) + s.n * omega.cross(dc_u));
  j.d_a2 = turn(x.cross(c));
  j.d_a3 = turn(dc_a3);
  j.d_phase = turn(dc_u);
  return j;
}

/// The local nearest point: Newton on h(t) = |P(t) - target|^2 / 2 from t (at most `steps` steps;
/// a step that does not lower h is halved). Returns the refined t.
inline double nearest_param_from(const FitShape& s, const Vector3d& target, double t, int steps = 8) {
  CurveJet j = curve_jet(s, t);
  double h = (j.point - target).squaredNorm();
  for (int k = 0; k < steps; ++k) {
    const Vector3d r = j.point - target;
    const double g = r.dot(j.d_t), H = j.d_t.squaredNorm() + r.dot(j.d_tt);
    double step = H > 0 ? -g / H : -g / std::max(j.d_t.squaredNorm(), 1e-300);
    if (!(std::abs(step) > 1e-15)) break;
    step = std::clamp(step, -0.5, 0.5);
    bool lowered = false;
    for (int halving = 0; halving < 20 && !lowered; ++halving, step /= 2) {
      const double ht = (curve_point(s, t + step) - target).squaredNorm();
      if (ht < h) {
        t += step;
        j = curve_jet(s, t);
        h = ht;
        lowered = true;
      }
    }
    if (!lowered) break;
  }
  return t;
}

/// The planet angle u in [0, pi] where the planet circle of the shape reaches latitude z (clamped
/// to the circle's z range), and by how much z is beyond that range (the angle, radians).
struct LatitudeMatch {
  double u = 0.0, beyond = 0.0;
};
inline LatitudeMatch latitude_match(const FitShape& s, double z) {
  const double s2 = s.s2, c2 = s.c2, s3 = s.s3, c3 = s.c3;
  const double cu = (c2 * c3 - z) / std::max(s2 * s3, 1e-300);
  const double u = std::acos(std::clamp(cu, -1.0, 1.0));
  const double z_reached = c2 * c3 - s2 * s3 * std::cos(u);
  const double beyond = std::abs(std::acos(std::clamp(z, -1.0, 1.0)) - std::acos(std::clamp(z_reached, -1.0, 1.0)));
  return {u, cu < -1 || cu > 1 ? beyond : 0.0};
}

/// theta2 in [0, 2 pi q) of the curve point nearest `target` (see header). abs_p = |p|, period =
/// 2 pi q. REQUIRES s.a2, s.a3 in (0, pi), s.n = p/q.
inline double nearest_param(const FitShape& s, std::int64_t abs_p, double period, const Vector3d& target) {
  const double two_pi = Constants<double>::two_pi();
  const LatitudeMatch m = latitude_match(s, target.z());
  // Candidates: u = +-u0 + 2 pi j - phase = n t, j = 0 .. |p| - 1 (one period of t).
  std::array<std::pair<double, double>, 3> best;  // (squared distance, t), smallest first
  best.fill({1e300, 0.0});
  for (int sign = -1; sign <= 1; sign += 2) {
    for (std::int64_t j = 0; j < abs_p; ++j) {
      const double t = std::fmod((sign * m.u + two_pi * static_cast<double>(j) - s.phase) / s.n, period);
      const double t0 = t < 0 ? t + period : t;
      const double d = (curve_point(s, t0) - target).squaredNorm();
      if (d < best[2].first) {
        best[2] = {d, t0};
        std::sort(best.begin(), best.end());
      }
    }
  }
  double t_best = best[0].second, d_best = 1e300;
  for (const auto& [d0, t0] : best) {
    if (d0 >= 1e299) continue;
    const double t = nearest_param_from(s, target, t0);
    const double d = (curve_point(s, t) - target).squaredNorm();
    if (d < d_best) {
      d_best = d;
      t_best = t;
    }
  }
  const double r = std::fmod(t_best, period);
  return r < 0 ? r + period : r;
}

/// A distance in cos (f = target . P) within which nearest_param_certified's answer is of the
/// global nearest point's.
constexpr double kNearestSlack = 1e-10;

/// theta2 in [0, 2 pi q) of the curve point nearest `target`, certified: branch and bound on
/// f(t) = target . P(t) (the cosine of the distance) over one period, from a local answer
/// `t_start` (nearest_param's). |d2P/dt2| <= (1 + |n|)^2 (P turns at rates 1 and n), so on
/// [a, b] f <= max(f(a), f(b)) + (1 + |n|)^2 (b - a)^2 / 8; a span that cannot beat the best by
/// more than kNearestSlack is dropped, the others halved; the best is polished by Newton. The
/// answer's cos distance is within kNearestSlack of the global one (its distance within
/// kNearestSlack / sin(distance) for a point off the curve; for a point on it, Newton's polish
/// gives 0 when t_start or the best sample lies in that foot's basin). Cost: about
/// 4.5 (q + |p|) + 40 curve points (|p|, q: the ratio's terms); spans narrower than
/// sqrt(8 kNearestSlack) / (1 + |n|) are never halved, so at most 2 period (1 + |n|) / 2.8e-5
/// (a target equidistant from a long arc). REQUIRES: target unit, period = 2 pi q.
inline double nearest_param_certified(const FitShape& s, double period, const Vector3d& target, double t_start) {
  struct Span {
    double a, b, fa, fb;
  };
  const double l2 = (1.0 + std::abs(s.n)) * (1.0 + std::abs(s.n));
  const auto f = [&](double t) { return target.dot(curve_point(s, t)); };
  double t_best = t_start, f_best = f(t_start);
  const auto spans = static_cast<std::size_t>(std::ceil(period * (1.0 + std::abs(s.n)) / std::sqrt(2.0)));  // slack 1/4 each
  std::vector<Span> stack;
  double a = 0.0, fa = f(a);
  for (std::size_t k = 1; k <= spans; ++k) {
    const double b = period * static_cast<double>(k) / static_cast<double>(spans), fb = f(b);
    stack.push_back({a, b, fa, fb});
    a = b, fa = fb;
  }
  while (!stack.empty()) {
    const Span x = stack.back();
    stack.pop_back();
    const double h = x.b - x.a, top = std::max(x.fa, x.fb);
    if (top > f_best) f_best = top, t_best = x.fa >= x.fb ? x.a : x.b;
    if (top + l2 * h * h / 8 <= f_best + kNearestSlack) continue;
    const double m = 0.5 * (x.a + x.b), fm = f(m);
    stack.push_back({x.a, m, x.fa, fm});
    stack.push_back({m, x.b, fm, x.fb});
  }
  const double t = nearest_param_from(s, target, t_best);
  if (f(t) > f_best) t_best = t;
  const double r = std::fmod(t_best, period);
  return r < 0 ? r + period : r;
}

/// The two curve points nearest `target` on different branches (see header: the 2|p| crossings
/// of its latitude, each refined by Newton), as theta2 in [0, 2 pi q): where a node at `target`
/// has its two branches. The second is the first again when no other branch comes near.
inline std::pair<double, double> two_branch_feet(const FitShape& s, std::int64_t abs_p, double period,
                                                 const Vector3d& target) {
  const double two_pi = Constants<double>::two_pi();
  const LatitudeMatch m = latitude_match(s, target.z());
  std::vector<std::pair<double, double>> feet;  // (squared distance, t)
  for (int sign = -1; sign <= 1; sign += 2)
    for (std::int64_t j = 0; j < abs_p; ++j) {
      double t = std::fmod((sign * m.u + two_pi * static_cast<double>(j) - s.phase) / s.n, period);
      t = std::fmod(nearest_param_from(s, target, t < 0 ? t + period : t), period);
      if (t < 0) t += period;
      feet.push_back({(curve_point(s, t) - target).squaredNorm(), t});
    }
  std::sort(feet.begin(), feet.end());
  for (std::size_t k = 1; k < feet.size(); ++k)
    if (std::abs(std::remainder(feet[k].second - feet[0].second, period)) > 1e-6)
      return {feet[0].second, feet[k].second};
  return {feet[0].second, feet[0].second};
}

/// Spherical distance (radians) between two unit vectors.
inline double sphere_distance(const Vector3d& a, const Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace sphtroch
