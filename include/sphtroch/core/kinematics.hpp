// sphtroch/core/kinematics.hpp — how the tracer moves along its path: speed, geodesic curvature
// and tangential acceleration at a carrier angle, and the dwell points (speed minima) of a period.
// Eigen only.
//
//   const sphtroch::TracerCurve<double> curve(train);
//   sphtroch::PathKinematics k = sphtroch::path_kinematics(curve, 0.3);   // k.speed = |omega x P|
//   std::vector<sphtroch::DwellPoint> d = sphtroch::dwell_points(curve);  // one period, by theta2
//
// Per unit carrier rate (theta2 is the time): V = dP/dtheta2 = omega x P (Eq. 47a), A = d2P/dtheta2^2
// = omega' x P + omega x (omega x P) (TracerCurve::acceleration). On the unit sphere:
//   speed                    |V|
//   tangential_acceleration  d|V|/dtheta2 = V.A / |V|
//   geodesic_curvature       det(P, V, A) / |V|^3 (> 0: the path turns left seen from outside)
// At a cusp (the tracer on a pitch cone, Eqs. 47-48) the speed is 0, the curvature unbounded and
// d|V| jumps from -|A| to +|A|: where |V| is exactly 0 the curvature is reported as +infinity and
// the tangential acceleration as 0 (the mean of the two one-sided limits). Errors: a few ulp of
// the terms, relative; the curvature's relative error grows as 1/|V| near a cusp.
// Dwell points: the local minima of |V| over one period, found where V.A (= |V| d|V|/dtheta2)
// changes sign from - to + between samples 2 pi q / (64 (|p| + q)) apart (|V|^2 is a trigonometric
// polynomial of degree |p| + q in theta2 / q, so two minima are never that close), then refined by
// bracketed secant-bisection on V.A to 1e-15 rad. A curve of constant speed has none.
#pragma once

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

namespace sphtroch {

/// The motion at one carrier angle (see header); per unit carrier rate, on the unit sphere.
struct PathKinematics {
  double speed = 0.0;                    // |dP/dtheta2|, radians of arc per radian of carrier
  double tangential_acceleration = 0.0;  // d|V|/dtheta2
  double geodesic_curvature = 0.0;       // det(P, V, A) / |V|^3, 1/radian of arc
};

/// A local minimum of the speed over one period.
struct DwellPoint {
  double param = 0.0;  // theta2 in [0, 2 pi q), radians
  Vector3d position = Vector3d::Zero();
  double speed = 0.0;
};

/// The motion at theta2 (see header).
inline PathKinematics path_kinematics(const TracerCurve<double>& curve, double theta2);

/// The speed minima of one period, in increasing theta2 (see header).
inline std::vector<DwellPoint> dwell_points(const TracerCurve<double>& curve);

// Implementation details follow.

inline PathKinematics path_kinematics(const TracerCurve<double>& curve, double theta2) {
  const Vector3d P = curve.point(theta2);
  const Vector3d V = curve.screw_axis(theta2).cross(P);
  const Vector3d A = curve.acceleration(theta2);
  const double speed = V.norm();
  if (speed == 0.0) return {0.0, 0.0, std::numeric_limits<double>::infinity()};
  return {speed, V.dot(A) / speed, P.dot(V.cross(A)) / (speed * speed * speed)};
}

namespace kinematics_detail {

/// V.A at theta2: half the derivative of |V|^2.
inline double speed_slope(const TracerCurve<double>& curve, double theta2) {
  const Vector3d V = curve.velocity(theta2);
  return V.dot(curve.acceleration(theta2));
}

/// The root of V.A in [a, b] where it goes from <= 0 to >= 0 (Illinois false position with
/// bisection steps, to 1e-15 rad).
inline double slope_root(const TracerCurve<double>& curve, double a, double b, double fa, double fb) {
  int side = 0;
  for (int it = 0; it < 200 && b - a > 1e-15; ++it) {
    double c = (fb - fa) != 0.0 ? b - fb * (b - a) / (fb - fa) : 0.5 * (a + b);
    if (!(c > a && c < b) || it % 8 == 7) c = 0.5 * (a + b);  // keep bisecting now and then
    const double fc = speed_slope(curve, c);
    if (fc == 0.0) return c;
    if (fc < 0.0) {
      a = c, fa = fc;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b = c, fb = fc;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (a + b);
}

}  // namespace kinematics_detail

inline std::vector<DwellPoint> dwell_points(const TracerCurve<double>& curve) {
  namespace d = kinematics_detail;
  const Ratio& n = curve.train().ratio();
  const double period = curve.period();
  const std::size_t samples = 64 * static_cast<std::size_t>(std::llabs(n.p()) + n.q());
  std::vector<double> slope(samples);
  for (std::size_t k = 0; k < samples; ++k) slope[k] = d::speed_slope(curve, period * double(k) / double(samples));
  std::vector<DwellPoint> out;
  for (std::size_t k = 0; k < samples; ++k) {
    const std::size_t next = (k + 1) % samples;
    if (!(slope[k] < 0.0 && slope[next] >= 0.0)) continue;  // - then +: a minimum in (t_k, t_k+1]
    const double a = period * double(k) / double(samples), b = period * double(k + 1) / double(samples);
    double t = slope[next] == 0.0 ? b : d::slope_root(curve, a, b, slope[k], slope[next]);
    if (t >= period) t -= period;
    out.push_back({t, curve.point(t), curve.velocity(t).norm()});
  }
  std::sort(out.begin(), out.end(), [](const DwellPoint& x, const DwellPoint& y) { return x.param < y.param; });
  return out;
}

}  // namespace sphtroch
