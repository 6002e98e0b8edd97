// sphtroch/machine/clinostat.hpp — a two-axis clinostat or random positioning machine run at
// constant speeds: the frames' angles at time t, the sample's frame, the gravity it feels.
//
//   sphtroch::ClinostatSettings s;
//   s.outer = sphtroch::Rpm(133, 100);   // 1.33 rpm
//   s.inner = sphtroch::Rpm(2);          // 2 rpm
//   sphtroch::Clinostat machine(s);
//   machine.gravity(60.0);               // the unit gravity vector in the sample's frame at t = 60 s
//
// Convention (docs/clinostat.md, with a figure):
// - Lab frame: Z up, gravity (0, 0, -1) in units of g0 = 9.80665 m/s^2.
// - Outer axis u = (sin psi, 0, cos psi), fixed in the lab; psi = tilt, the angle from the vertical.
// - Inner axis v = cos beta u + sin beta w, w = (-cos psi, 0, sin psi), fixed in the outer frame;
//   beta = frame angle, the angle between the axes.
// - Speeds in rpm, signed (right-hand rule about u and v); phi_o(t) = phi_o0 + 2 pi w_o t / 60,
//   phi_i(t) = phi_i0 + 2 pi w_i t / 60, t in seconds; phases in degrees.
// - Sample frame R(t) = Rot(u, phi_o(t)) Rot(v, phi_i(t)); gravity seen by the sample
//   g_s(t) = R(t)^T (0, 0, -1).
// - A sample point at r (metres, sample frame) feels R^T ((0, 0, -1) - a / g0), a = d^2/dt^2 (R r):
//   in the sample's frame R^T a = W_o^2 Ri^T [u]x^2 Ri r + 2 W_o W_i Ri^T [u]x [v]x Ri r + W_i^2 [v]x^2 r
//   with Ri = Rot(v, phi_i), W = 2 pi rpm / 60 (the outer rotation commutes with [u]x).
// Angles at t are reduced exactly: the whole turns of w t / 60 are removed in 128-bit integers
// (the speed is an exact rational), so that g_s at t = 1e6 s keeps ~1e-15 of accuracy.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/machine/rpm.hpp"

#include <cmath>
#include <string>

namespace sphtroch {

/// What a machine is: two speeds, two angles of its axes, two start phases and where the sample sits.
struct ClinostatSettings {
  Rpm outer;                        ///< outer frame's speed about u (rpm, signed)
  Rpm inner;                        ///< inner frame's speed about v (rpm, signed)
  double tilt_deg = 90;             ///< psi: outer axis from the vertical, [0, 180] degrees
  double frame_angle_deg = 90;      ///< beta: angle between the axes, [0, 180] degrees
  double phase_outer_deg = 0;       ///< phi_o0, |phase| <= 1e6 degrees
  double phase_inner_deg = 0;       ///< phi_i0, |phase| <= 1e6 degrees
  Vector3d offset_m = Vector3d::Zero();  ///< the sample point r (metres, sample frame), |r| <= 10 m
  double gravity_g0 = 1;            ///< G: the environment's gravity, units of g0, [0.001, 1000]
};

/// sin and cos of an angle in degrees, exact (0, +-1) at whole multiples of 90 degrees, so that a
/// vertical or horizontal axis typed as such is exactly that (the period depends on it).
inline SinCos<double> degree_sin_cos(double degrees) {
  const double quarter = degrees / 90.0;
  if (quarter == std::floor(quarter) && std::fabs(quarter) < 1e15) {
    const long long k = static_cast<long long>(quarter) % 4;
    const int q = static_cast<int>(k < 0 ? k + 4 : k);
    const double sines[4] = {0, 1, 0, -1}, cosines[4] = {1, 0, -1, 0};
    return {sines[q], cosines[q]};
  }
  return sin_cos(degrees * (Constants<double>::pi() / 180.0));
}

/// Rot(k, angle) from the angle's sine and cosine (Rodrigues): c I + s [k]x + (1 - c) k k^T.
inline Matrix3d rotation_about(const Vector3d& k, const SinCos<double>& angle) {
  Matrix3d cross;
  cross << 0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0;
  return angle.cos * Matrix3d::Identity() + angle.sin * cross + (1 - angle.cos) * k * k.transpose();
}

/// frac(w t / 60) in [0, 1): the turns of a frame turning at w rpm after t seconds, with the whole
/// turns removed exactly. REQUIRES |t| <= Clinostat::kMaxTime.
inline long double turn_fraction(const Rpm& w, double t) {
  const double whole = std::floor(t);
  const __int128 per_turn = static_cast<__int128>(60) * w.den();  // w t / 60 = num t / per_turn
  __int128 k = static_cast<__int128>(w.num()) * static_cast<long long>(whole) % per_turn;
  if (k < 0) k += per_turn;
  long double x = static_cast<long double>(k) / static_cast<long double>(per_turn) +
                  static_cast<long double>(w.num()) * static_cast<long double>(t - whole) / static_cast<long double>(per_turn);
  x -= std::floor(x);
  return x;
}

class Clinostat {
 public:
  static constexpr double kStandardGravity = 9.80665;  ///< g0, m/s^2
  static constexpr double kMaxTime = 1e12;             ///< |t| accepted, seconds
  static constexpr double kMaxOffset = 10;             ///< |r| accepted, metres
  static constexpr double kMaxPhase = 1e6;             ///< |phase| accepted, degrees
  static constexpr double kMaxGravity = 1000;          ///< the environment's gravity accepted, g0
  /// The least environment's gravity accepted, g0: the proofs' rounding terms are absolute (in g0),
  /// so a G far below them would make a bracket's width and slack meaningless; no environment of
  /// a clinostat lab is below a milli-g.
  static constexpr double kMinGravity = 0.001;

  /// Throws InvalidInput naming the setting: both speeds 0 ("inner", the machine does not turn),
  /// an angle outside [0, 180] or not finite ("tilt", "frame-angle"), a phase not finite or beyond
  /// 1e6 degrees, an offset not finite or beyond 10 m.
  explicit Clinostat(const ClinostatSettings& s) : s_(s) {
    if (s.outer.is_zero() && s.inner.is_zero())
      throw InvalidInput("inner", "0", "both speeds are 0: the machine does not turn", "at least one speed non-zero");
    check_angle("tilt", s.tilt_deg);
    check_angle("frame-angle", s.frame_angle_deg);
    check_phase("phase-outer", s.phase_outer_deg);
    check_phase("phase-inner", s.phase_inner_deg);
    if (!(s.gravity_g0 >= kMinGravity && s.gravity_g0 <= kMaxGravity))
      throw InvalidInput("gravity", number_text(s.gravity_g0), "not an environment's gravity", "[0.001, 1000] g0");
    if (!s.offset_m.allFinite() || s.offset_m.norm() > kMaxOffset)
      throw InvalidInput("offset", report_number(s.offset_m.x()) + "," + number_text(s.offset_m.y()) + "," + number_text(s.offset_m.z()),
                         "not a finite point within 10 m of the centre", "X,Y,Z in metres, |r| <= 10");
    tilt_ = degree_sin_cos(s.tilt_deg);
    frame_ = degree_sin_cos(s.frame_angle_deg);
    u_ = Vector3d(tilt_.sin, 0, tilt_.cos);
    w_ = Vector3d(-tilt_.cos, 0, tilt_.sin);
    v_ = frame_.cos * u_ + frame_.sin * w_;
    phase_outer_ = std::fmod(s.phase_outer_deg, 360.0) * (Constants<double>::pi() / 180.0);  // fmod is exact
    phase_inner_ = std::fmod(s.phase_inner_deg, 360.0) * (Constants<double>::pi() / 180.0);
  }

  const ClinostatSettings& settings() const noexcept { return s_; }
  const Vector3d& outer_axis() const noexcept { return u_; }        ///< u, in the lab
  const Vector3d& inner_axis() const noexcept { return v_; }        ///< v, in the outer frame
  const Vector3d& outer_cross_axis() const noexcept { return w_; }  ///< w = (-cos psi, 0, sin psi)
  const SinCos<double>& tilt() const noexcept { return tilt_; }
  const SinCos<double>& frame_angle() const noexcept { return frame_; }
  bool has_offset() const noexcept { return !s_.offset_m.isZero(0); }

  /// True when the gravity's direction in the sample depends on the outer frame's angle (the
  /// outer axis is not vertical), and when it depends on the inner frame's angle apart from the
  /// outer one (the axes are not parallel). Exact: decided from the angles as typed.
  bool turns_with_outer() const noexcept { return tilt_.sin != 0; }
  bool axes_parallel() const noexcept { return frame_.sin == 0; }

  /// phi_o(t + dt), phi_i(t + dt) in radians, reduced into [phi_0, phi_0 + 2 pi) exactly
  /// (turn_fraction of t and of dt, added: t + dt is never rounded).
  double outer_angle(double t, double dt = 0) const { return phase_outer_ + two_pi_turns(s_.outer, checked_time(t), dt); }
  double inner_angle(double t, double dt = 0) const { return phase_inner_ + two_pi_turns(s_.inner, checked_time(t), dt); }

  /// The sample frame R = Rot(u, phi_o) Rot(v, phi_i) at given frame angles.
  Matrix3d frame_at(double phi_o, double phi_i) const {
    return rotation_about(u_, sin_cos(phi_o)) * rotation_about(v_, sin_cos(phi_i));
  }
  Matrix3d frame(double t) const { return frame_at(outer_angle(t), inner_angle(t)); }

  /// g_s = R^T (0, 0, -1) at given frame angles, and at t (units of g0).
  Vector3d gravity_at(double phi_o, double phi_i) const { return -frame_at(phi_o, phi_i).row(2).transpose(); }
  Vector3d gravity(double t) const { return gravity_at(outer_angle(t), inner_angle(t)); }

  /// -R^T a / g0 at the inner angle (the offset's acceleration term, units of g0; the outer angle
  /// does not enter it). Zero without an offset.
  Vector3d acceleration_term_at(double phi_i) const {
    const Vector3d& r = s_.offset_m;
    const Matrix3d ri = rotation_about(v_, sin_cos(phi_i));
    const double wo = s_.outer.radians_per_second(), wi = s_.inner.radians_per_second();
    const Vector3d ri_r = ri * r;
    const Vector3d a = wo * wo * (ri.transpose() * u_.cross(u_.cross(ri_r))) +
                       2 * wo * wi * (ri.transpose() * u_.cross(v_.cross(ri_r))) + wi * wi * v_.cross(v_.cross(r));
    return -a / kStandardGravity;
  }
  /// The effective gravity R^T (G (0, 0, -1) - a / g0), G the environment's gravity (settings'
  /// gravity_g0), at given frame angles and at t (units of g0).
  Vector3d effective_gravity_at(double phi_o, double phi_i) const {
    return s_.gravity_g0 * gravity_at(phi_o, phi_i) + acceleration_term_at(phi_i);
  }
  Vector3d effective_gravity(double t) const { return effective_gravity_at(outer_angle(t), inner_angle(t)); }

 private:
  static void check_angle(const char* field, double deg) {
    if (!(deg >= 0 && deg <= 180)) throw InvalidInput(field, number_text(deg), "outside [0, 180] or not finite", "[0, 180] degrees");
  }
  static void check_phase(const char* field, double deg) {
    if (!(std::fabs(deg) <= kMaxPhase)) throw InvalidInput(field, number_text(deg), "not a finite phase", "|phase| <= 1e6 degrees");
  }
  static double checked_time(double t) {
    if (!(std::fabs(t) <= kMaxTime)) throw InvalidInput("t", report_number(t), "not a finite time", "|t| <= 1e12 seconds");
    return t;
  }
  static double two_pi_turns(const Rpm& w, double t, double dt) {
    long double turns = turn_fraction(w, t) + (dt == 0 ? 0 : turn_fraction(w, checked_time(dt)));
    turns -= std::floor(turns);
    return static_cast<double>(2 * static_cast<long double>(Constants<double>::pi()) * turns);
  }

  ClinostatSettings s_;
  SinCos<double> tilt_{}, frame_{};
  Vector3d u_, v_, w_;
  double phase_outer_ = 0, phase_inner_ = 0;
};

}  // namespace sphtroch
