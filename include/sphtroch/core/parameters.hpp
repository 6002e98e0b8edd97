// sphtroch/core/parameters.hpp — the curve parameter theta2 (the carrier angle, radians) and the planet
// angle theta3 = n theta2 + theta_p (Eq. 3): one definition, one edge rule each, on any Scalar.
//
//   const double t = sphtroch::reduce_to_period(-0.5, train.period());      // in [0, 2 pi q)
//   sphtroch::periodic_distance(0.1, train.period() - 0.1, train.period());  // 0.2
//   sphtroch::theta2_at_planet_angle(train.ratio(), train.phase(), pi, 0);  // theta3 = pi there
//
// The curve closes after theta2 spans period = 2 pi q (n = p/q in lowest terms); every parameter
// the library reports is reduced to [0, period).
//
// Frames (Eq. 4): base (XYZ)1 <- carrier (XYZ)2 is Rz(theta2) Rx(a2); carrier <- planet is
// Rz(theta3) Rx(a3). Rotations take cosine and sine, so that exact values (cos a2 = 0 at
// a2 = pi/2, GearTrain::trig) pass through unrounded.
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sphtroch {

/// Rotation about z by the angle with cosine c and sine s (right-handed, radians).
template <class Scalar>
Matrix3<Scalar> rotation_z(const Scalar& c, const Scalar& s) {
  Matrix3<Scalar> r;
  r << c, -s, Scalar(0), s, c, Scalar(0), Scalar(0), Scalar(0), Scalar(1);
  return r;
}

/// Rotation about x by the angle with cosine c and sine s.
template <class Scalar>
Matrix3<Scalar> rotation_x(const Scalar& c, const Scalar& s) {
  Matrix3<Scalar> r;
  r << Scalar(1), Scalar(0), Scalar(0), Scalar(0), c, -s, Scalar(0), s, c;
  return r;
}

/// Rz(angle) for an angle in radians.
template <class Scalar>
Matrix3<Scalar> rotation_z(const Scalar& angle) {
  const SinCos<Scalar> t = sin_cos(angle);
  return rotation_z(t.cos, t.sin);
}

/// Carrier-frame coordinates to base coordinates at carrier angle theta2: Rz(theta2) Rx(a2),
/// with cos a2, sin a2 from the train's TwistTrig (exact where GearTrain::trig makes them so).
template <class Scalar>
Matrix3<Scalar> base_R_carrier(const Scalar& theta2, const TwistTrig<Scalar>& trig) {
  const SinCos<Scalar> t = sin_cos(theta2);
  return rotation_z(t.cos, t.sin) * rotation_x(trig.cos_a2, trig.sin_a2);
}

/// x reduced to [0, period), period > 0. Edge rule: a negative x within rounding of a multiple of
/// the period (x mod period + period rounds to period) reduces to 0, never to period.
template <class Scalar>
Scalar reduce_to_period(const Scalar& x, const Scalar& period) {
  using std::fmod;
  Scalar r = fmod(x, period);
  if (r < Scalar(0)) r += period;
  if (r >= period) r = Scalar(0);
  return r;
}

/// Distance of two parameters on the circle of circumference `period`: in [0, period / 2].
template <class Scalar>
Scalar periodic_distance(const Scalar& a, const Scalar& b, const Scalar& period) {
  using std::abs;
  using std::fmod;
  const Scalar d = fmod(abs(a - b), period);
  return std::min(d, Scalar(period - d));
}

/// The k-th theta2 at which the planet angle is theta3 (mod 2 pi): the solution of
/// n theta2 + theta_p = theta3 + 2 pi k, i.e. (theta3 - theta_p + 2 pi k) q / p, not reduced.
/// k = 0 .. |p| - 1 give the |p| distinct solutions in one period (after reduce_to_period).
template <class Scalar>
Scalar theta2_at_planet_angle(const Ratio& n, const Scalar& phase, const Scalar& theta3, std::int64_t k) {
  const Scalar p(static_cast<double>(n.p())), q(static_cast<double>(n.q()));
  return (theta3 - phase + Constants<Scalar>::two_pi() * Scalar(static_cast<double>(k))) * q / p;
}

/// Every theta2 in [0, period) at which theta3 = c (mod 2 pi), ascending; |p| of them.
inline std::vector<double> params_at_planet_angle(const GearTrain& train, double c) {
  std::vector<double> out;
  for (std::int64_t k = 0; k < train.ratio().abs_p(); ++k)
    out.push_back(reduce_to_period(theta2_at_planet_angle(train.ratio(), train.phase(), c, k), train.period()));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace sphtroch
