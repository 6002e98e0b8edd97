// sphtroch/map/closed_form_boundaries.hpp — the boundary vocabulary: the a3 values where the class of the curve
// can change (pitch cones, pole passages, Eq. 24's ends), their names, values and margins for a
// train, the default tolerance of the boundary reading, and the boundary curves of the (a2, a3)
// map with the nearest one to a point. Eigen only; criteria.hpp, boundary_snap.hpp and atlas.hpp
// build on it.
//
//   for (const sphtroch::Boundary& b : sphtroch::boundaries(train)) b.name, b.value, b.margin;
//   sphtroch::boundaries_hit(train, 1e-10);                   // those within the tolerance
//   sphtroch::nearest_boundary(a2, a3, sphtroch::Ratio(2));   // kind, name, distance in a3
//
// Margins are exact when a3 was given relative to that boundary (GearTrain::on_cone): then
// margin = offset. All angles in radians.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/reading.hpp"
#include "sphtroch/core/types.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace sphtroch {

/// The a3 values where the shape of the curve changes kind.
enum class BoundaryKind {
  pitch_cone,         // a3 = a_p: cusps (Eq. 20b, 43, pitch-cone criterion)
  mirror_pitch_cone,  // a3 = pi - a_p: cusps (Eq. 20b, 46)
  a2,                 // a3 = a2: the north pole (0,0,1) is on the curve (z_max = cos(a2 - a3) = 1)
  pi_minus_a2,        // a3 = pi - a2: the south pole is on the curve (z_min = cos(a2 + a3) = -1)
  half_a2,            // a3 = a2/2 (n = 1 only, Eq. 24; equals a_p there)
  pi_minus_half_a2,   // a3 = pi - a2/2 (n = 1 only, Eq. 24; equals pi - a_p there)
  tangency,           // a self-tangency locus (boundary_events.hpp): no closed form; never in boundaries()
};

inline const char* to_string(BoundaryKind kind);

/// The boundary in words, as Boundary::name gives it: "a3 = a_p (pitch cone)", ...
inline const char* boundary_name(BoundaryKind kind);

struct Boundary {
  BoundaryKind kind = BoundaryKind::pitch_cone;
  std::string name;     // e.g. "a3 = a_p (pitch cone)"
  double value = 0.0;   // the boundary's a3, radians
  double margin = 0.0;  // a3 - value, radians (exact when a3 was given relative to this boundary)
};

/// The boundaries that matter for this train: a_p, pi - a_p, a2, pi - a2 for every n; for n = 1
/// also a2/2 and pi - a2/2 (the same two values as a_p, pi - a_p: their margins are defined as
/// the pitch-cone margins so that every decision about them agrees).
inline std::vector<Boundary> boundaries(const GearTrain& train);

/// The boundaries with |margin| <= tolerance. Throws InvalidInput("boundary_tolerance") unless
/// tolerance >= 0.
inline std::vector<Boundary> boundaries_hit(const GearTrain& train, double tolerance = kBoundaryTolerance);

/// a3 - value of one boundary (the margin of `boundaries`, for any kind and any n; for n != 1,
/// half_a2 and pi_minus_half_a2 are plain a3 - a2/2 and a3 - (pi - a2/2)).
inline double boundary_margin(const GearTrain& train, BoundaryKind kind);

/// The boundary's a3 for this train: a_p, pi - a_p, a2, pi - a2, a2/2, pi - a2/2 (radians); NaN
/// for `tangency`, which has no closed form (boundary_events.hpp's nearest_tangency gives it).
inline double boundary_value(const GearTrain& train, BoundaryKind kind);

/// Whether the GearTrain reference `ref` measures a3 from this boundary exactly.
inline bool reference_matches(A3Reference ref, BoundaryKind kind);

/// The curves in the (a2, a3) plane where the class can change, for this ratio: a3 = a_p(a2)
/// and pi - a_p(a2) for every n (cusps; for n = 1 these are Eq. 24's ends a2/2, pi - a2/2);
/// a3 = a2 and pi - a2 when |p| >= 2 (a pole on the curve is a node; for n = 2 the other ends of
/// Eqs. 43 and 46). For n other than 1, 2 the class can also change where two branches touch
/// away from the poles (a stationary value of the root census's g is an integer); those curves
/// are not in the report and not listed here: boundary_events.hpp computes them.
inline std::vector<BoundaryKind> atlas_boundary_kinds(const Ratio& ratio);

/// a3 on a boundary at a2: a_p, pi - a_p, a2 or pi - a2.
inline double atlas_boundary_a3(BoundaryKind kind, double a2, const Ratio& ratio);

/// The boundary nearest to (a2, a3) in a3, and the distance |a3 - boundary(a2)| in radians.
struct NearestBoundary {
  BoundaryKind kind = BoundaryKind::pitch_cone;
  std::string name;
  double distance = 0.0;
};
inline NearestBoundary nearest_boundary(double a2, double a3, const Ratio& ratio);

// =============================================================================================
// Implementation details follow.
// =============================================================================================

inline const char* boundary_name(BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::pitch_cone: return "a3 = a_p (pitch cone)";
    case BoundaryKind::mirror_pitch_cone: return "a3 = pi - a_p (mirror pitch cone)";
    case BoundaryKind::a2: return "a3 = a2 (north pole on the curve)";
    case BoundaryKind::pi_minus_a2: return "a3 = pi - a2 (south pole on the curve)";
    case BoundaryKind::half_a2: return "a3 = a2/2 (Eq. 24 lower end; = a_p for n = 1)";
    case BoundaryKind::pi_minus_half_a2: return "a3 = pi - a2/2 (Eq. 24 upper end; = pi - a_p for n = 1)";
    case BoundaryKind::tangency: return "self-tangency locus (two branches touch off the poles)";
  }
  return "?";
}

inline const char* to_string(BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::pitch_cone: return "pitch_cone";
    case BoundaryKind::mirror_pitch_cone: return "mirror_pitch_cone";
    case BoundaryKind::a2: return "a2";
    case BoundaryKind::pi_minus_a2: return "pi_minus_a2";
    case BoundaryKind::half_a2: return "half_a2";
    case BoundaryKind::pi_minus_half_a2: return "pi_minus_half_a2";
    case BoundaryKind::tangency: return "tangency";
  }
  return "?";
}

inline double boundary_value(const GearTrain& train, BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::pitch_cone: return train.planet_cone();
    case BoundaryKind::mirror_pitch_cone: return Constants<double>::pi() - train.planet_cone();
    case BoundaryKind::a2: return train.a2();
    case BoundaryKind::pi_minus_a2: return Constants<double>::pi() - train.a2();
    case BoundaryKind::half_a2: return 0.5 * train.a2();
    case BoundaryKind::pi_minus_half_a2: return Constants<double>::pi() - 0.5 * train.a2();
    case BoundaryKind::tangency: return std::numeric_limits<double>::quiet_NaN();  // boundary_events.hpp
  }
  return 0.0;
}

inline bool reference_matches(A3Reference ref, BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::pitch_cone: return ref == A3Reference::pitch_cone;
    case BoundaryKind::mirror_pitch_cone: return ref == A3Reference::mirror_pitch_cone;
    case BoundaryKind::a2: return ref == A3Reference::a2;
    case BoundaryKind::pi_minus_a2: return ref == A3Reference::pi_minus_a2;
    default: return false;
  }
}

inline double boundary_margin(const GearTrain& train, BoundaryKind kind) {
  // n = 1: a_p = a2/2 identically (Eq. 20a <=> 20b); use one margin for both names.
  if (train.ratio() == Ratio(1) && kind == BoundaryKind::half_a2) kind = BoundaryKind::pitch_cone;
  if (train.ratio() == Ratio(1) && kind == BoundaryKind::pi_minus_half_a2) kind = BoundaryKind::mirror_pitch_cone;
  if (reference_matches(train.a3_reference(), kind)) return train.a3_offset();
  if (train.a3_reference() == A3Reference::given) return train.a3() - boundary_value(train, kind);
  return (train.reference_angle() - boundary_value(train, kind)) + train.a3_offset();
}

inline std::vector<Boundary> boundaries(const GearTrain& train) {
  std::vector<BoundaryKind> kinds{BoundaryKind::pitch_cone, BoundaryKind::mirror_pitch_cone, BoundaryKind::a2,
                                  BoundaryKind::pi_minus_a2};
  if (train.ratio() == Ratio(1)) {
    kinds.push_back(BoundaryKind::half_a2);
    kinds.push_back(BoundaryKind::pi_minus_half_a2);
  }
  std::vector<Boundary> out;
  for (BoundaryKind k : kinds) out.push_back(Boundary{k, boundary_name(k), boundary_value(train, k), boundary_margin(train, k)});
  return out;
}

inline std::vector<Boundary> boundaries_hit(const GearTrain& train, double tolerance) {
  if (!(tolerance >= 0.0))
    throw InvalidInput("boundary_tolerance", report_number(tolerance), "not a number >= 0", ">= 0 radians");
  std::vector<Boundary> out;
  for (const Boundary& b : boundaries(train))
    if (std::abs(b.margin) <= tolerance) out.push_back(b);
  return out;
}

inline std::vector<BoundaryKind> atlas_boundary_kinds(const Ratio& ratio) {
  std::vector<BoundaryKind> kinds{BoundaryKind::pitch_cone, BoundaryKind::mirror_pitch_cone};
  if (ratio.abs_p() >= 2) {
    kinds.push_back(BoundaryKind::a2);
    kinds.push_back(BoundaryKind::pi_minus_a2);
  }
  return kinds;
}

inline double atlas_boundary_a3(BoundaryKind kind, double a2, const Ratio& ratio) {
  const double pi = Constants<double>::pi();
  const double a_p = GearTrain::planet_cone_of(a2, ratio);
  switch (kind) {
    case BoundaryKind::pitch_cone:
    case BoundaryKind::half_a2: return a_p;
    case BoundaryKind::mirror_pitch_cone:
    case BoundaryKind::pi_minus_half_a2: return pi - a_p;
    case BoundaryKind::a2: return a2;
    case BoundaryKind::pi_minus_a2: return pi - a2;
    case BoundaryKind::tangency: return std::numeric_limits<double>::quiet_NaN();
  }
  return a_p;
}

inline NearestBoundary nearest_boundary(double a2, double a3, const Ratio& ratio) {
  NearestBoundary best;
  best.distance = std::numeric_limits<double>::infinity();
  for (BoundaryKind k : atlas_boundary_kinds(ratio)) {
    const double d = std::abs(a3 - atlas_boundary_a3(k, a2, ratio));
    if (d < best.distance) {
      best.kind = k;
      best.distance = d;
    }
  }
  best.name = boundary_name(best.kind);
  return best;
}

}  // namespace sphtroch
