// sphtroch/map/extremes_and_symmetry.hpp — two closed forms of the report for every n: the z
// extremes of the curve (Eqs. 14/15 for n = 1, 32-35 for n = 2, generalised) and its |p| vertical
// mirror planes. Like criteria.hpp, nothing here samples the curve. Angles in radians.
//
//   using namespace sphtroch;
//   GearTrain fig5g(kPi / 3, 2 * kPi / 3, Ratio(2));
//   ZExtremes z = z_extremes(fig5g);        // z_max = cos(a2 - a3) at theta3 = pi (mod 2 pi) ...
//   Symmetry s = symmetry(fig5g);           // 2 mirror planes: M P(t) = P(offset - t)
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/parameters.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphtroch {

struct CurvePoint {
  double param = 0.0;                    // theta2 in [0, period)
  Vector3d position = Vector3d::Zero();  // P(theta2)
};

/// z = -cos(theta3) sin a2 sin a3 + cos a2 cos a3 (Eq. 4, third row): z_max = cos(a2 - a3) where
/// theta3 = pi (mod 2 pi), z_min = cos(a2 + a3) where theta3 = 0; |p| points each per period.
/// n = 1, phase 0: Eqs. 14, 15; n = 2, phase 0: Eqs. 32-35.
struct ZExtremes {
  double z_max = 0.0;
  double z_min = 0.0;
  std::vector<CurvePoint> maxima;  // ascending by param
  std::vector<CurvePoint> minima;
};

inline ZExtremes z_extremes(const GearTrain& train);

/// A vertical mirror plane through Z1: reflecting the curve in it maps P(t) to P(t'), with
/// t' = param_offset - t (mod period).
struct MirrorPlane {
  Vector3d normal = Vector3d::UnitX();  // unit, z = 0; its azimuth in [0, pi)
  double azimuth = 0.0;                 // angle of the normal from X1 about Z1, in [0, pi)
  double param_offset = 0.0;            // t' = param_offset - t, reduce mod period; in [0, period)
};

struct Symmetry {
  std::size_t rotation_order = 1;   // |p|: invariant under Rz(2 pi / |p|)
  std::vector<MirrorPlane> planes;  // |p| planes, ascending azimuth
};

inline Symmetry symmetry(const GearTrain& train);

/// t' = plane.param_offset - t reduced to [0, period).
inline double mirror_parameter(const MirrorPlane& plane, double t, double period);

namespace extremes_detail {

/// Base-frame position of a carrier-frame vector at carrier angle theta2 (parameters.hpp frames).
inline Vector3d base_from_carrier(const GearTrain& train, double theta2, const Vector3d& p_carrier) {
  return Vector3d(base_R_carrier(theta2, train.trig<double>()) * p_carrier);
}

}  // namespace extremes_detail

inline ZExtremes z_extremes(const GearTrain& train) {
  // dz/dtheta2 = n sin(th3) sin a2 sin a3 (Eq. 4 third row; Eqs. 13, 31): stationary where
  // sin th3 = 0. th3 = pi: carrier-frame tracer (0, sin a3, cos a3), Rx(a2) turns it into
  // (0, -sin(a2 - a3), cos(a2 - a3)); th3 = 0: (0, -sin a3, cos a3) -> (0, -sin(a2 + a3), cos(a2 + a3)).
  const TwistTrig<double> t = train.trig<double>();
  ZExtremes z;
  z.z_max = t.cos_a2 * t.cos_a3 + t.sin_a2 * t.sin_a3;  // cos(a2 - a3)  (Eqs. 14, 32, 33)
  z.z_min = t.cos_a2 * t.cos_a3 - t.sin_a2 * t.sin_a3;  // cos(a2 + a3)  (Eqs. 15, 34, 35)
  for (double t2 : params_at_planet_angle(train, Constants<double>::pi()))
    z.maxima.push_back(CurvePoint{t2, extremes_detail::base_from_carrier(train, t2, Vector3d(0.0, t.sin_a3, t.cos_a3))});
  for (double t2 : params_at_planet_angle(train, 0.0))
    z.minima.push_back(CurvePoint{t2, extremes_detail::base_from_carrier(train, t2, Vector3d(0.0, -t.sin_a3, t.cos_a3))});
  return z;
}

inline Symmetry symmetry(const GearTrain& train) {
  // Derivation (phase 0). The carrier-frame tracer c(th3) = (sin th3 sin a3, -cos th3 sin a3, cos a3)
  // has c(-th3) = M_x c(th3) with M_x = diag(-1, 1, 1); M_x commutes with Rx(a2) and
  // Rz(-t) M_x = M_x Rz(t), so P(-t) = M_x P(t). Also t -> t + 2 pi q/p advances th3 by 2 pi, so
  // P(t + 2 pi q/p) = Rz(2 pi q/p) P(t). Hence, for k = 0 .. |p| - 1, with beta = 2 pi k q/p,
  //   Rz(beta) M_x P(t) = Rz(beta) P(-t) = P(beta' - t),   beta' = 2 pi k q / p,
  // and Rz(beta) M_x is the reflection in the vertical plane whose normal has azimuth beta/2.
  // The azimuths pi k q/p (mod pi) are |p| distinct values (q is invertible mod p): |p| planes.
  // Phase (Eq. 8): P_ph(t) = Rz(-d) P_0(t + d), d = theta_p/n: every normal turns by -d and
  // t' = (beta' - 2 d) - t.
  const Ratio& n = train.ratio();
  const double p = static_cast<double>(n.p()), q = static_cast<double>(n.q());
  const double d = train.phase() / train.n();
  const double period = train.period();
  Symmetry s;
  s.rotation_order = static_cast<std::size_t>(n.abs_p());
  for (std::int64_t k = 0; k < n.abs_p(); ++k) {
    const double kk = static_cast<double>(k);
    MirrorPlane plane;
    plane.azimuth = reduce_to_period(Constants<double>::pi() * kk * q / p - d, Constants<double>::pi());
    plane.normal = Vector3d(std::cos(plane.azimuth), std::sin(plane.azimuth), 0.0);
    plane.param_offset = reduce_to_period(Constants<double>::two_pi() * kk * q / p - 2.0 * d, period);
    s.planes.push_back(plane);
  }
  std::sort(s.planes.begin(), s.planes.end(),
            [](const MirrorPlane& a, const MirrorPlane& b) { return a.azimuth < b.azimuth; });
  return s;
}

inline double mirror_parameter(const MirrorPlane& plane, double t, double period) {
  return reduce_to_period(plane.param_offset - t, period);
}

}  // namespace sphtroch
