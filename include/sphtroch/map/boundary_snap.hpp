// sphtroch/map/boundary_snap.hpp — put an input that lies within a tolerance of a boundary exactly
// on it, symbolically, so that every later stage sees the boundary case the user meant.
//
//   sphtroch::SnappedTrain s = sphtroch::snap_to_boundaries(train);   // tolerance kBoundaryTolerance
//   s.train;          // a2 exactly pi/2 and/or a3 exactly on a2, pi - a2, a_p or pi - a_p
//   s.hits;           // which boundaries, with the input's margin to each
//
// Why: a tangency or a cusp is ill-conditioned. Row (g) of Table 1 typed as "--a2 pi/3 --a3 2pi/3"
// rounds to a2 + a3 = pi - 3.4e-16, whose literal curve has two crossings 4e-8 apart instead of the
// report's touching point at the pole. Snapping re-expresses a3 as "reference + 0" (GearTrain keeps
// the reference symbolically, so sin/cos a3 are exact identities of sin/cos a2 in every Scalar) and
// a2 within tolerance of pi/2 as exactly pi/2 (sin 1, cos 0: the case a2 = pi - a2 of rows d and
// Fig. 3). An a3 within tolerance of a self-tangency locus (and of no closed-form boundary) is
// put on the double nearest the locus (boundary_events.hpp, nearest_tangency), named as a hit of
// kind `tangency`. A tolerance of 0 (the `--literal` reading) changes nothing.
#pragma once

#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/map/criteria.hpp"
#include "sphtroch/core/gear_train.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sphtroch {

struct SnappedTrain {
  GearTrain train;               // the train analysed
  std::vector<Boundary> hits;    // boundaries within tolerance, margins of the INPUT
  bool a2_snapped = false;       // a2 taken as exactly pi/2
  double a2_margin = 0.0;        // input a2 - pi/2
  double tolerance = 0.0;
};

inline A3Reference reference_of(BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::pitch_cone:
    case BoundaryKind::half_a2: return A3Reference::pitch_cone;  // a2/2 = a_p when n = 1
    case BoundaryKind::mirror_pitch_cone:
    case BoundaryKind::pi_minus_half_a2: return A3Reference::mirror_pitch_cone;
    case BoundaryKind::a2: return A3Reference::a2;
    case BoundaryKind::pi_minus_a2: return A3Reference::pi_minus_a2;
    case BoundaryKind::tangency: return A3Reference::given;
  }
  return A3Reference::given;
}

/// Snaps a2 to pi/2 and a3 to its nearest boundary when within `tolerance` (radians).
inline SnappedTrain snap_to_boundaries(const GearTrain& input, double tolerance = kBoundaryTolerance) {
  SnappedTrain out{input, {}, false, input.a2() - Constants<double>::pi() / 2, tolerance};
  if (!(tolerance > 0)) return out;
  GearTrain train = input;
  if (std::abs(out.a2_margin) <= tolerance && !input.a2_is_right_angle()) {
    train = train.with_right_angle_a2();
    out.a2_snapped = true;
  }
  out.hits = boundaries_hit(input, tolerance);
  if (!out.hits.empty()) {
    // The nearest boundary decides the reference; when a2 = pi/2, a2 and pi - a2 coincide and
    // snapping to either puts both poles on the curve exactly.
    const auto nearest = std::min_element(out.hits.begin(), out.hits.end(), [](const Boundary& a, const Boundary& b) {
      return std::abs(a.margin) < std::abs(b.margin);
    });
    train = train.with_a3_reference(reference_of(nearest->kind), 0.0);
  } else if (const auto t = nearest_tangency(train.a2(), input.a3(), input.ratio(), tolerance)) {
    // A self-tangency locus (boundary_events.hpp): a3 becomes the double nearest the locus.
    out.hits.push_back(Boundary{BoundaryKind::tangency,
                                "self-tangency locus g = " + std::to_string(t->m) + " (two branches touch off the poles)",
                                t->a3, t->margin});
    train = train.with_a3_reference(A3Reference::given, t->a3);
  }
  out.train = train;
  return out;
}

}  // namespace sphtroch
