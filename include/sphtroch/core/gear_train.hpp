// sphtroch/core/gear_train.hpp — the validated parameters of one spherical planetary gear train.
//
//   using namespace sphtroch;
//   GearTrain fig3(kPi / 2, kPi / 2, Ratio(1));               // report Fig. 3
//   GearTrain nephroid = GearTrain::on_cone(kPi / 2, A3Reference::pitch_cone, 0.0, Ratio(2));
//   nephroid.planet_cone();  // a_p = atan2(sin a2, cos a2 + n)
//   nephroid.period();       // 2*pi*q
//
// Model (Lin & Tsai 1990, Sec. 2): carrier twist a2 (sun axis Z1 to planet axis Z2) and tracer
// twist a3 (planet axis to tracer), both in (0, pi) radians; gear ratio n = sin a_s / sin a_p
// with a2 = a_s + a_p (Eq. 2), hence a_p = atan2(sin a2, cos a2 + n), a_s = a2 - a_p; planet
// angle theta3 = n*theta2 + theta_p (Eq. 3).
//
// a3 may be given relative to a reference angle that depends on a2 (the pitch cone a_p, its
// mirror pi - a_p, a2 or pi - a2) plus an offset. The reference is kept symbolically, so every
// Scalar type evaluates sin a3 and cos a3 of *that* angle in its own precision: a tracer "on the
// pitch cone" is exactly on it in float, double, long double and MPFR alike.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace sphtroch {

/// What a3 is measured from. `given` means a3 is the plain number supplied.
enum class A3Reference { given, a2, pi_minus_a2, pitch_cone, mirror_pitch_cone };

inline const char* to_string(A3Reference r) {
  switch (r) {
    case A3Reference::given: return "given";
    case A3Reference::a2: return "a2";
    case A3Reference::pi_minus_a2: return "pi-a2";
    case A3Reference::pitch_cone: return "ap";
    case A3Reference::mirror_pitch_cone: return "pi-ap";
  }
  return "?";
}

/// The carrier twist must stay this far from 0 and pi (radians, bounds included; see
/// carrier_twist_in_range). Closer, the curve is nearly a multiply covered circle whose nodes lie
/// within the censuses' merge distances (1e-9) of each other: both censuses lose nodes below
/// ~1e-9 (measured), so the bound keeps a factor 1000.
constexpr double kMinCarrierTwist = 1e-6;

/// True when kMinCarrierTwist <= a2 <= pi - kMinCarrierTwist. The upper bound allows 2 ulp(pi)
/// (8.9e-16) for the rounding of a typed "pi-1e-6"; nothing else is rounded in the caller's favour
/// (9.9e-7 and pi-9.9e-7 are refused).
inline bool carrier_twist_in_range(double a2) {
  const double pi = Constants<double>::pi();
  const double two_ulp_pi = 8.881784197001252e-16;
  return a2 >= kMinCarrierTwist && a2 < pi && pi - a2 >= kMinCarrierTwist - two_ulp_pi;
}
/// |omega| = |Z1 + n Z2| = sqrt(1 + n^2 + 2 n cos a2), the planet's angular speed per unit carrier
/// speed. Below this (n = -1 with a2 near 0, n = 1 with a2 near pi) the pitch cone a_p is
/// ill-conditioned (da_p/da2 ~ 1/|omega|^2): a tracer within kPitchConeGuard of it, or given
/// relative to it, is refused — there the censuses disagreed from |omega| ~ 1e-5 (measured; the
/// bound keeps a factor 100). Tracers away from the cones stay fine (tested down to 1e-6).
constexpr double kMinPlanetSpeed = 1e-3;
constexpr double kPitchConeGuard = 0.01;

/// The phase reduced to [-pi, pi]: unchanged when already there; for |p| < 2^30 p - 2 pi k with
/// k = round(p / 2 pi) (moved by one when the rounded quotient puts the result past -pi or pi),
/// 2 pi in two parts and each step one fma: IEEE operations only, so every C library — glibc
/// natively, musl in the WebAssembly build — gives the same double, within an ulp of the true
/// p mod 2 pi or, next to a multiple of 2 pi, within 1e-23 rad (the two parts' own error times k);
/// beyond 2^30, atan2(sin p, cos p) — the C library's sin and cos reduce any double exactly
/// (Payne-Hanek), so the result is within a few ulp even for p = 1e300. Adding 2 pi k to the
/// phase turns theta3 by 2 pi k and leaves every point of the curve where it was (Eq. 3, 4).
inline double reduce_phase(double phase) {
  const double pi = Constants<double>::pi();
  if (phase >= -pi && phase <= pi) return phase;
  if (std::fabs(phase) < 0x1p30) {
    constexpr double two_pi_high = 6.283185307179586;        // 2 pi rounded to double
    constexpr double two_pi_low = 2.4492935982947064e-16;    // 2 pi - two_pi_high
    const auto reduced = [&](double k) { return std::fma(-k, two_pi_low, std::fma(-k, two_pi_high, phase)); };
    double k = std::nearbyint(phase / two_pi_high);
    double r = reduced(k);
    if (r > pi) r = reduced(++k);   // the quotient rounded down across a half (an odd multiple of pi)
    if (r < -pi) r = reduced(--k);  // ... or up
    return std::min(pi, std::max(-pi, r));
  }
  return std::atan2(std::sin(phase), std::cos(phase));
}

/// sin and cos of both twist angles in one Scalar type; the only way the curve sees a2 and a3.
template <typename Scalar>
struct TwistTrig {
  Scalar sin_a2, cos_a2, sin_a3, cos_a3;
};

class GearTrain {
 public:
  /// The report's Fig. 3 train, a2 = a3 = pi/2, n = 1, phase 0 (a valid train, so that
  /// GearTrain, and results holding one, are default-constructible regular value types).
  GearTrain() : GearTrain(Constants<double>::pi() / 2, Constants<double>::pi() / 2, Ratio(1)) {}

  /// REQUIRES: a2, a3 in (0, pi); phase finite. Throws InvalidInput naming "a2", "a3" or "phase".
  GearTrain(double a2, double a3, Ratio n, double phase = 0.0)
      : GearTrain(a2, A3Reference::given, a3, n, phase) {}

  /// a3 = reference(a2, n) + offset (radians). REQUIRES: the resulting a3 in (0, pi).
  static GearTrain on_cone(double a2, A3Reference reference, double offset, Ratio n, double phase = 0.0) {
    return GearTrain(a2, reference, offset, n, phase);
  }

  double a2() const noexcept { return a2_; }
  /// The tracer twist as a double (reference + offset, rounded once).
  double a3() const noexcept { return a3_; }
  A3Reference a3_reference() const noexcept { return reference_; }
  /// a3 minus its reference (equals a3 when the reference is `given`).
  double a3_offset() const noexcept { return offset_; }
  const Ratio& ratio() const noexcept { return ratio_; }
  double n() const noexcept { return ratio_.value(); }
  /// The phase in [-pi, pi] (reduce_phase of the given one); what every computation uses.
  double phase() const noexcept { return phase_; }
  /// The phase as given.
  double phase_given() const noexcept { return phase_given_; }

  /// Planet pitch-cone angle a_p = atan2(sin a2, cos a2 + n), in (0, pi) (report Sec. 5).
  double planet_cone() const { return planet_cone_of(a2_, ratio_); }
  /// Sun pitch-cone angle a_s = a2 - a_p; may be negative for internal gearing (n < 0).
  double sun_cone() const { return a2_ - planet_cone(); }
  /// theta2 span after which the curve closes: 2*pi*q for n = p/q in lowest terms.
  double period() const { return Constants<double>::two_pi() * static_cast<double>(ratio_.q()); }

  /// True when a2 is taken as exactly pi/2 (see with_right_angle_a2()).
  bool a2_is_right_angle() const noexcept { return a2_right_angle_; }

  /// The same train with a2 taken as exactly pi/2 in every Scalar (sin a2 = 1, cos a2 = 0).
  /// Used by the boundary snapping of the node census; the caller decides the tolerance.
  GearTrain with_right_angle_a2() const {
    GearTrain g = *this;
    g.a2_right_angle_ = true;
    g.a2_ = Constants<double>::pi() / 2;
    g.a3_ = g.reference_angle() + g.offset_;
    return g;
  }

  /// The same train with a3 re-expressed as reference + offset (offset 0: exactly on it).
  GearTrain with_a3_reference(A3Reference reference, double offset = 0.0) const {
    GearTrain g = *this;
    g.reference_ = reference;
    g.offset_ = offset;
    g.a3_ = g.reference_angle() + offset;
    return g;
  }

  static double planet_cone_of(double a2, const Ratio& n) { return std::atan2(std::sin(a2), std::cos(a2) + n.value()); }

  /// sin/cos of a2 and a3 evaluated in Scalar; a3 follows its symbolic reference (see header).
  template <typename Scalar>
  TwistTrig<Scalar> trig() const {
    using std::sqrt;
    const SinCos<Scalar> carrier = sin_cos(Scalar(a2_));
    TwistTrig<Scalar> t{carrier.sin, carrier.cos, Scalar(0), Scalar(0)};
    if (a2_right_angle_) {
      t.sin_a2 = Scalar(1);
      t.cos_a2 = Scalar(0);
    }
    // sin/cos of the reference angle, exact identities of sin/cos a2 where they exist.
    Scalar s_ref(0), c_ref(0);
    switch (reference_) {
      case A3Reference::given: s_ref = Scalar(0); c_ref = Scalar(1); break;  // reference angle 0
      case A3Reference::a2: s_ref = t.sin_a2; c_ref = t.cos_a2; break;
      case A3Reference::pi_minus_a2: s_ref = t.sin_a2; c_ref = -t.cos_a2; break;
      case A3Reference::pitch_cone:
      case A3Reference::mirror_pitch_cone: {
        // The screw axis in the carrier frame is (0, sin a2, cos a2 + n) (Eq. 47b); a_p is its
        // angle from Z2, so sin a_p and cos a_p are its normalised components.
        const Scalar wy = t.sin_a2;
        const Scalar wz = t.cos_a2 + Scalar(ratio_.p()) / Scalar(ratio_.q());
        const Scalar w = sqrt(wy * wy + wz * wz);
        s_ref = wy / w;
        c_ref = reference_ == A3Reference::pitch_cone ? Scalar(wz / w) : Scalar(-wz / w);
        break;
      }
    }
    if (offset_ == 0.0) {
      t.sin_a3 = s_ref;
      t.cos_a3 = c_ref;
    } else {
      const SinCos<Scalar> d = sin_cos(Scalar(offset_));
      t.sin_a3 = s_ref * d.cos + c_ref * d.sin;  // sin(ref + d)
      t.cos_a3 = c_ref * d.cos - s_ref * d.sin;  // cos(ref + d)
    }
    return t;
  }

  /// The value a3 is measured from (radians): 0 (given), a2, pi - a2, a_p or pi - a_p.
  double reference_angle() const {
    const double pi = Constants<double>::pi();
    switch (reference_) {
      case A3Reference::given: return 0.0;
      case A3Reference::a2: return a2_;
      case A3Reference::pi_minus_a2: return pi - a2_;
      case A3Reference::pitch_cone: return planet_cone_of(a2_, ratio_);
      case A3Reference::mirror_pitch_cone: return pi - planet_cone_of(a2_, ratio_);
    }
    return 0.0;
  }
 private:
  GearTrain(double a2, A3Reference reference, double offset, Ratio n, double phase)
      : a2_(a2), a3_(0.0), reference_(reference), offset_(offset), ratio_(n), phase_(0.0), phase_given_(phase) {
    const double pi = Constants<double>::pi();
    if (!(a2 > 0.0 && a2 < pi)) throw InvalidInput("a2", report_number(a2), "outside the valid range", "(0, pi) radians");
    if (!carrier_twist_in_range(a2))
      throw InvalidInput("a2", report_number(a2), "within 1e-6 rad of 0 or pi (the curve degenerates into a multiply covered circle)",
                         "[1e-6, pi - 1e-6] radians");
    const double nv = n.value(), speed = std::sqrt(std::max(0.0, 1.0 + nv * nv + 2.0 * nv * std::cos(a2)));
    if (!std::isfinite(offset)) throw InvalidInput("a3", report_number(offset), "not a finite number", "(0, pi) radians");
    if (!std::isfinite(phase)) throw InvalidInput("phase", report_number(phase), "not a finite number", "any finite angle in radians");
    phase_ = reduce_phase(phase);
    a3_ = reference_angle() + offset;
    const double ap = planet_cone_of(a2, n);
    const bool near_cone = reference == A3Reference::pitch_cone || reference == A3Reference::mirror_pitch_cone ||
                           std::abs(a3_ - ap) < kPitchConeGuard || std::abs(a3_ - (pi - ap)) < kPitchConeGuard;
    if (!(speed >= kMinPlanetSpeed) && near_cone)
      throw InvalidInput("a2", report_number(a2),
                         "with n = " + n.str() + " the planet barely turns in space (|Z1 + n Z2| = " + number_text(speed) +
                             ") and a3 is on or near its ill-defined pitch cone",
                         "a2 with sqrt(1 + n^2 + 2 n cos a2) >= 1e-3, or a3 at least 0.01 rad from the pitch cones");
    if (!(a3_ > 0.0 && a3_ < pi)) {
      const std::string shown = reference == A3Reference::given
                                    ? number_text(a3_)
                                    : std::string(to_string(reference)) + (offset < 0 ? "" : "+") + number_text(offset) +
                                          " = " + number_text(a3_);
      throw InvalidInput("a3", shown, "outside the valid range", "(0, pi) radians");
    }
  }



  double a2_;
  double a3_;
  A3Reference reference_;
  double offset_;
  Ratio ratio_;
  double phase_;        // reduced to [-pi, pi]
  double phase_given_;  // as given
  bool a2_right_angle_ = false;
};

/// A parsed tracer twist: a3 = reference(a2, n) + offset; reference `given` means a3 = offset.
struct A3Spec {
  A3Reference reference = A3Reference::given;
  double offset = 0.0;
};

/// The gear train of parsed values (validates ranges; throws InvalidInput).
inline GearTrain make_gear_train(double a2, const A3Spec& a3, const Ratio& n, double phase = 0.0) {
  if (a3.reference == A3Reference::given) return GearTrain(a2, a3.offset, n, phase);
  return GearTrain::on_cone(a2, a3.reference, a3.offset, n, phase);
}

}  // namespace sphtroch
