// sphtroch/core/cone_distance.hpp — the cone distance R, the length that scales the unit-sphere
// curve into a user's unit (mm, ...) in every output that takes one (trace CSV/.npy/DXF/OBJ/STEP,
// the nodes table): positions and velocities times R, the geodesic curvature divided by R.
//
//   sphtroch::check_cone_distance(25.0);  // fine: 1e-300 or 1e300 would throw InvalidInput("radius", ...)
//
// Valid: [1e-100, 1e100]. Within it every scaled value the library writes is a finite, normal
// double: a position or velocity is at most R (1 + |n|) <= 1e106 (|n| <= 1e6), an acceleration
// at most R (1 + |n|)^2 <= 1e112, a curvature (at most |A| / (8 eps |omega|)^2 on the unit
// sphere: below that speed a cusp is reported) over R far below 1e308; and x * R is rounded once
// (subnormal results only for |x| < 1e-208, which no nonzero coordinate of the curve reaches).
// Every value has at most 3 exponent digits, which the STEP writer's number buffer needs.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"

#include <string>

namespace sphtroch {

constexpr double kMinConeDistance = 1e-100;
constexpr double kMaxConeDistance = 1e100;

/// Throws InvalidInput naming `field` unless kMinConeDistance <= radius <= kMaxConeDistance
/// (NaN and infinities included). `given` is the text the user typed, if any (else the number).
inline void check_cone_distance(double radius, const std::string& field = "radius", const std::string& given = "") {
  if (radius >= kMinConeDistance && radius <= kMaxConeDistance) return;
  throw InvalidInput(field, given.empty() ? number_text(radius) : given, "outside the valid range",
                     "a length in [1e-100, 1e100] (the cone distance, any unit)");
}

}  // namespace sphtroch
