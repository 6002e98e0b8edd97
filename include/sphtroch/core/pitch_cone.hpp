// sphtroch/core/pitch_cone.hpp — how far the tracer is from the planet's pitch cone and its mirror.
//
//   sphtroch::ConeMargins m = sphtroch::cone_margins(train);
//   m.pitch;    // a3 - a_p, radians (0 exactly when a3 was given as "ap")
//   m.mirror;   // a3 - (pi - a_p)
//   m.on_pitch_cone(), m.on_mirror_cone();  // |margin| <= kCuspResolution
//
// The velocity vanishes (a cusp) exactly when P is parallel to omega, i.e. a3 = a_p or
// a3 = pi - a_p (docs/design.md; report Sec. 4.2 and Eq. 47). Margins are computed in long double from
// the train's sin/cos (trig<long double>()), so a tracer put on a cone symbolically has margin 0.
#pragma once

#include "sphtroch/core/gear_train.hpp"

#include <cmath>

namespace sphtroch {

/// Below this distance from a pitch cone (radians) a near-cusp loop is not resolved: its size is
/// ~|a3 - a_p| and its branch parameters ~sqrt(|a3 - a_p|) apart, and the curve is reported as a
/// cusp within resolution. Equal to the default boundary tolerance, so that the default and the
/// literal readings agree on which loops exist.
constexpr double kCuspResolution = 1e-10;

struct ConeMargins {
  double pitch = 0.0;   // a3 - a_p
  double mirror = 0.0;  // a3 - (pi - a_p)
  bool on_pitch_cone(double tol = kCuspResolution) const { return std::abs(pitch) <= tol; }
  bool on_mirror_cone(double tol = kCuspResolution) const { return std::abs(mirror) <= tol; }
};

inline ConeMargins cone_margins(const GearTrain& train) {
  using Real = long double;
  const auto t = train.trig<Real>();
  const Real wy = t.sin_a2;
  const Real wz = t.cos_a2 + static_cast<Real>(train.ratio().p()) / static_cast<Real>(train.ratio().q());
  // Signed angle from the reference direction (cos r, sin r) to (cos a3, sin a3).
  auto angle_from = [&](Real c_ref, Real s_ref) {
    return static_cast<double>(std::atan2(t.sin_a3 * c_ref - t.cos_a3 * s_ref, t.cos_a3 * c_ref + t.sin_a3 * s_ref));
  };
  ConeMargins m;
  m.pitch = angle_from(wz, wy);    // a_p = atan2(wy, wz)
  m.mirror = angle_from(-wz, wy);  // pi - a_p
  return m;
}

}  // namespace sphtroch
