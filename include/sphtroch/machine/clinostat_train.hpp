// sphtroch/machine/clinostat_train.hpp — the spherical planetary gear train whose tracer draws a
// clinostat's gravity path, and the map between them.
//
//   sphtroch::ClinostatSettings s;
//   s.outer = sphtroch::Rpm(133, 100);
//   s.inner = sphtroch::Rpm(2);
//   const sphtroch::Clinostat machine(s);
//   const sphtroch::ClinostatTrain ct = sphtroch::clinostat_train(machine);
//   const sphtroch::TracerCurve<double> path(*ct.train);   // ct.train is empty for a single-axis machine
//   ct.rotation * path.point(ct.theta2_at_0 + ct.theta2_rate * 60.0);   // = machine.gravity(60.0)
//
// Derivation (docs/clinostat.md). Let Q be the rotation with columns (y, -sin b u + cos b w, v):
// Q z = v and Q Rx(b) z = u. Then Rot(v, x) = Q Rz(x) Q^T and Rot(u, y) = Q Rx(b) Rz(y) Rx(-b) Q^T, so
//   g_s = Rot(v, -phi_i) Rot(u, -phi_o) g = Q Rz(-phi_i) Rx(b) Rz(-phi_o) Rx(-b) Q^T g,
// and Rx(-b) Q^T g = (0, -sin psi, -cos psi) = Rx(pi - psi) z. Hence g_s = Q P(theta2) with the
// report's Eq. 4 P(theta2) = Rz(theta2) Rx(a2) Rz(n theta2 + theta_p) Rx(a3) z for
//   a2 = beta (the sun axis is the inner axis, the planet axis the outer one),
//   a3 = pi - psi (the tracer is gravity, measured from the outer axis),
//   theta2 = -phi_i(t) (the carrier runs with the inner frame, backwards),
//   n = w_o / w_i (exact), theta_p = n phi_i0 - phi_o0 (so that n theta2 + theta_p = -phi_o(t)).
// The effective gravity of an off-centre sample is not on the sphere and has no train.
#pragma once

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/machine/clinostat.hpp"
#include "sphtroch/machine/gravity_series.hpp"

#include <optional>
#include <string>

namespace sphtroch {

struct ClinostatTrain {
  std::optional<GearTrain> train;  ///< empty for a machine that is not a two-axis train (reason)
  std::string reason;              ///< why train is empty ("" when it is not)
  double theta2_at_0 = 0;          ///< -phi_i0, radians
  double theta2_rate = 0;          ///< -2 pi w_i / 60, radians per second
  Matrix3d rotation = Matrix3d::Identity();  ///< Q: g_s(t) = Q P(theta2_at_0 + theta2_rate t)
};

namespace detail {
/// n = w_o / w_i in lowest terms, or empty with the reason when it is no gear ratio of the train.
inline std::optional<Ratio> speed_ratio(const Rpm& outer, const Rpm& inner, std::string& reason) {
  const __int128 p = static_cast<__int128>(outer.num()) * inner.den(), q = static_cast<__int128>(outer.den()) * inner.num();
  __int128 a = p < 0 ? -p : p, b = q < 0 ? -q : q;
  while (b != 0) {
    const __int128 r = a % b;
    a = b;
    b = r;
  }
  __int128 pn = p / a, qn = q / a;
  if (qn < 0) {
    pn = -pn;
    qn = -qn;
  }
  if (pn > Ratio::kMaxTerm || -pn > Ratio::kMaxTerm || qn > Ratio::kMaxTerm) {
    reason = "the speed ratio's terms exceed 1000000 (the gear train's limit)";
    return std::nullopt;
  }
  return Ratio(static_cast<std::int64_t>(pn), static_cast<std::int64_t>(qn));
}
}  // namespace detail

/// The train and map of the header; train empty (with the reason) for a single-axis machine (a
/// speed 0), parallel axes (frame angle 0 or 180), a vertical outer axis (tilt 0 or 180), or a
/// frame angle within GearTrain's carrier-twist bound of 0 or 180 degrees, or any other train
/// GearTrain refuses (its message, after "no gear train: ").
inline ClinostatTrain clinostat_train(const Clinostat& m) {
  const ClinostatSettings& s = m.settings();
  const double pi = Constants<double>::pi();
  ClinostatTrain out;
  const SinCos<double> b = m.frame_angle();
  out.rotation.col(0) = Vector3d::UnitY();
  out.rotation.col(1) = -b.sin * m.outer_axis() + b.cos * m.outer_cross_axis();
  out.rotation.col(2) = m.inner_axis();
  out.theta2_at_0 = -std::fmod(s.phase_inner_deg, 360.0) * (pi / 180.0) + 0.0;  // + 0.0: 0, not -0
  out.theta2_rate = -s.inner.radians_per_second();
  const double a2 = s.frame_angle_deg * (pi / 180.0), a3 = pi - s.tilt_deg * (pi / 180.0);
  if (!GravitySeries::of_gravity(m).period_s()) out.reason = "the gravity does not move in the sample (the turning axis is vertical): the path is a point";
  else if (s.outer.is_zero() || s.inner.is_zero()) out.reason = "a single-axis machine (one speed is 0): the path is a circle";
  else if (m.axes_parallel()) out.reason = "the axes are parallel (frame angle 0 or 180 degrees): the path is a circle";
  else if (!m.turns_with_outer()) out.reason = "the outer axis is vertical (tilt 0 or 180 degrees): the path is a circle";
  else if (!carrier_twist_in_range(a2)) out.reason = "the frame angle is within 1e-6 rad of 0 or 180 degrees";
  if (!out.reason.empty()) return out;
  const std::optional<Ratio> n = detail::speed_ratio(s.outer, s.inner, out.reason);
  if (!n) return out;
  // theta_p = n phi_i0 - phi_o0, reduced into [0, 2 pi) in long double (n phi_i0 may be large).
  const long double two_pi = 2 * static_cast<long double>(pi);
  long double phase = static_cast<long double>(n->p()) * (-out.theta2_at_0) / n->q() -
                      std::fmod(s.phase_outer_deg, 360.0) * (static_cast<long double>(pi) / 180);
  phase = std::fmod(phase, two_pi) + 0.0L;  // + 0: 0, not -0
  if (phase < 0) phase += two_pi;
  try {  // GearTrain's own limits (a planet that barely turns, a3 rounding to pi, ...): no train, said why
    out.train.emplace(a2, a3, *n, static_cast<double>(phase));
  } catch (const InvalidInput& e) {
    out.reason = "no gear train: " + e.message();
  }
  return out;
}

}  // namespace sphtroch
