// sphtroch/core/curve.hpp — the tracer point, its velocity, acceleration and the screw axis,
// from the Denavit–Hartenberg rotation chain of the report (Eq. 4), templated on Scalar.
//
//   sphtroch::TracerCurve<double> curve(train);
//   Eigen::Vector3d p = curve.point(0.3);       // unit vector in the base frame (XYZ)1
//   Eigen::Vector3d v = curve.velocity(0.3);    // dP/dtheta2 = omega x P (Eq. 47a)
//
// Frames (all origins at the sphere centre O): base (XYZ)1 fixed to the sun, carrier (XYZ)2
// turned by theta2 about Z1 and twisted by a2 about X2, planet (XYZ)3 turned by
// theta3 = n*theta2 + theta_p (Eq. 3) about Z2 and twisted by a3 about X3. The tracer is Z3:
//   P = Rz(theta2) Rx(a2) Rz(theta3) Rx(a3) z                      (Eq. 4)
// Error: each component is a few ulp of Scalar for |theta2| up to the period (the argument
// n*theta2 is formed as p*theta2/q, one rounding; sin/cos of a large argument carry its
// absolute rounding error, about |theta2| * epsilon). In double, sin and cos come from
// portable_trig.hpp (below one ulp) and point() is written out, so P has the same bits on every
// IEEE platform (the explorer's WebAssembly module draws the tool's curve exactly).
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/core/parameters.hpp"
#include "sphtroch/core/types.hpp"

#include <cmath>

namespace sphtroch {

template <typename Scalar>
class TracerCurve {
 public:
  using Vec3 = Vector3<Scalar>;
  using Mat3 = Matrix3<Scalar>;

  explicit TracerCurve(const GearTrain& train)
      : train_(train),
        trig_(train.trig<Scalar>()),
        p_(Scalar(static_cast<double>(train.ratio().p()))),
        q_(Scalar(static_cast<double>(train.ratio().q()))),
        phase_(Scalar(train.phase())) {}

  const GearTrain& train() const noexcept { return train_; }
  const TwistTrig<Scalar>& trig() const noexcept { return trig_; }

  /// theta3 = n*theta2 + theta_p (Eq. 3), radians.
  Scalar planet_angle(const Scalar& theta2) const { return p_ * theta2 / q_ + phase_; }

  /// Rotation taking carrier-frame coordinates to base coordinates: Rz(theta2) Rx(a2).
  Mat3 base_R_carrier(const Scalar& theta2) const { return sphtroch::base_R_carrier(theta2, trig_); }

  /// The tracer in carrier coordinates: Rz(theta3) Rx(a3) z = (s3 sa3, -c3 sa3, ca3) (Eq. 4, right factor).
  Vec3 point_in_carrier(const Scalar& theta2) const {
    const SinCos<Scalar> t = sin_cos(planet_angle(theta2));
    return Vec3(t.sin * trig_.sin_a3, -t.cos * trig_.sin_a3, trig_.cos_a3);
  }

  /// P(theta2), a unit vector in the base frame (Eq. 4): Rz(theta2) Rx(a2) point_in_carrier,
  /// written out so that the bits do not depend on Eigen's vectorisation (with sin_cos, the
  /// explorer's WebAssembly module computes the same bits: portable_trig.hpp).
  Vec3 point(const Scalar& theta2) const {
    const SinCosPair<Scalar> angles = sin_cos_pair(planet_angle(theta2), theta2);  // = two sin_cos
    const SinCos<Scalar>& t = angles.second;
    const Vec3 v(angles.first.sin * trig_.sin_a3, -angles.first.cos * trig_.sin_a3, trig_.cos_a3);  // point_in_carrier
    const Scalar wy = trig_.cos_a2 * v.y() - trig_.sin_a2 * v.z();  // Rx(a2) v
    const Scalar wz = trig_.sin_a2 * v.y() + trig_.cos_a2 * v.z();
    return Vec3(t.cos * v.x() - t.sin * wy, t.sin * v.x() + t.cos * wy, wz);  // Rz(theta2)
  }

  /// The planet axis Z2 in base coordinates: (s2 sa2, -c2 sa2, ca2).
  Vec3 planet_axis(const Scalar& theta2) const {
    const SinCos<Scalar> t = sin_cos(theta2);
    return Vec3(t.sin * trig_.sin_a2, -t.cos * trig_.sin_a2, trig_.cos_a2);
  }

  /// omega = Z1 + n Z2, the planet's angular velocity per unit carrier rate; the instantaneous
  /// screw axis (Eq. 47a). Not normalised: |omega| = sqrt(1 + n^2 + 2 n cos a2).
  Vec3 screw_axis(const Scalar& theta2) const {
    Vec3 omega = (p_ / q_) * planet_axis(theta2);
    omega.z() += Scalar(1);
    return omega;
  }

  /// dP/dtheta2 = omega x P (Eq. 47a).
  Vec3 velocity(const Scalar& theta2) const { return Vec3(screw_axis(theta2).cross(point(theta2))); }

  /// d2P/dtheta2^2 = omega' x P + omega x (omega x P), with omega' = n (Z1 x Z2).
  Vec3 acceleration(const Scalar& theta2) const {
    const Vec3 p = point(theta2);
    const Vec3 omega = screw_axis(theta2);
    const Vec3 omega_dot = (p_ / q_) * Vec3(Vec3::UnitZ().cross(planet_axis(theta2)));
    return Vec3(omega_dot.cross(p) + omega.cross(omega.cross(p)));
  }

  /// theta2 span after which the curve closes (2*pi*q), in Scalar.
  Scalar period() const { return Constants<Scalar>::two_pi() * q_; }

 private:
  GearTrain train_;
  TwistTrig<Scalar> trig_;
  Scalar p_;
  Scalar q_;
  Scalar phase_;
};

}  // namespace sphtroch
