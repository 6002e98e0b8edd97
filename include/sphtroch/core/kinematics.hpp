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
// d|V| jumps from -|A| to +|A|: where |V| <= 8 epsilon |omega| (0 at the rounding level) the
// speed is reported as 0 and the curvature and tangential acceleration, undefined there, as 0
// (read speed 0 as "cusp"). Errors: a few ulp of the terms, relative; the curvature's relative
// error grows as 1/|V| near a cusp.
// Dwell points, in closed form: omega has a constant length and omega.P = Z1.P + n Z2.P =
// c - s cos theta3 with c = cos a3 (cos a2 + n), s = sin a2 sin a3 > 0 (P_z of Eq. 4, Z2.P =
// cos a3), so |V|^2 = |omega|^2 - (c - s cos theta3)^2 depends on theta3 alone. Its minima are at
// theta3 = 0 (mod 2 pi) when c < s and at theta3 = pi when c > -s (where the second derivative of
// (c - s cos theta3)^2, 2 s (c - s) and -2 s (c + s), is negative); theta3 = n theta2 + theta_p meets each
// |p| times a period, at theta2 = (j pi - theta_p) q / p. So a period has |p| or 2 |p| dwell
// points, however close to each other (a3 near atan2(cos a2 + n, sin a2), where c = s, puts two
// shallow minima close together).
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

/// The motion at theta2 (see header). Curve: TracerCurve<double> or any curve with point,
/// screw_axis (its angular velocity) and acceleration (ChainCurve<double>: s for theta2).
template <typename Curve>
PathKinematics path_kinematics(const Curve& curve, double theta2);

/// The speed minima of one period, in increasing theta2 (see header).
inline std::vector<DwellPoint> dwell_points(const TracerCurve<double>& curve);

// Implementation details follow.

template <typename Curve>
PathKinematics path_kinematics(const Curve& curve, double theta2) {
  const Vector3d P = curve.point(theta2);
  const Vector3d omega = curve.screw_axis(theta2);
  const Vector3d V = omega.cross(P);
  const Vector3d A = curve.acceleration(theta2);
  const double speed = V.norm();
  if (speed <= 8 * std::numeric_limits<double>::epsilon() * omega.norm()) return {0.0, 0.0, 0.0};  // a cusp
  return {speed, V.dot(A) / speed, P.dot(V.cross(A)) / (speed * speed * speed)};
}

inline std::vector<DwellPoint> dwell_points(const TracerCurve<double>& curve) {
  const GearTrain& train = curve.train();
  const TwistTrig<double>& trig = curve.trig();
  const double n = train.ratio().value();
  const double c = trig.cos_a3 * (trig.cos_a2 + n), s = trig.sin_a2 * trig.sin_a3;
  const double pi = Constants<double>::pi(), period = curve.period();
  const auto p = static_cast<double>(train.ratio().p()), q = static_cast<double>(train.ratio().q());
  std::vector<DwellPoint> out;
  for (std::int64_t j = 0; j < 2 * std::llabs(train.ratio().p()); ++j) {
    if (!(j % 2 == 0 ? c < s : c > -s)) continue;  // theta3 = j pi is a speed maximum
    double t = std::fmod((double(j) * pi - train.phase()) * q / p, period);
    if (t < 0) t += period;
    if (t >= period) t = 0.0;
    out.push_back({t, curve.point(t), path_kinematics(curve, t).speed});
  }
  std::sort(out.begin(), out.end(), [](const DwellPoint& x, const DwellPoint& y) { return x.param < y.param; });
  return out;
}

}  // namespace sphtroch
