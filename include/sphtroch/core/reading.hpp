// sphtroch/core/reading.hpp — how a train near a boundary is read (the meaning of `--literal`):
// the default reading puts an input within a tolerance of a boundary on it and lets branches
// within kTangencyTolerance touch; the literal reading analyses the doubles as given.
//
//   sphtroch::Reading r;                       // default: r.boundary() == 1e-10, r.tangency() == 1e-10
//   sphtroch::Reading{true}.boundary();         // literal: 0
//   sphtroch::Reading{false, 1e-8}.validate();  // InvalidInput unless 0 <= tolerance <= 1e-3
//
// All tolerances in radians (kTangencyTolerance in units of the root function g, about radians).
#pragma once

#include "sphtroch/core/errors.hpp"

namespace sphtroch {

/// Default tolerance (radians) within which a3 is taken to lie on a boundary.
///
/// Why 1e-10: inputs typed as multiples of pi ("2pi/3", "pi - a_p") reach us rounded to double,
/// so their margin to the boundary they were meant to hit is a few 1e-16 (Table 1 row (g),
/// a2 = pi/3, a3 = 2pi/3, has a2 + a3 = pi - 3.4e-16); the tolerance must swallow that with a wide
/// safety factor. From above it is bounded by resolution: at a3 = a_p + d the node of a near-cusp
/// loop lies within O(d) of the cusp and its two branch parameters are O(sqrt d) apart; below
/// d ~ 1e-9 rad that loop is smaller than double precision evaluation of the curve (and Newton on
/// P(t1) = P(t2)) can separate from a cusp, so calling it a cusp is the honest answer. 1e-10 sits
/// between the two with six orders of magnitude above the rounding and one below the resolution.
constexpr double kBoundaryTolerance = 1e-10;

/// Default tolerance on |g - integer| at a stationary point of the root census's g for calling it
/// a tangency (root_census.hpp): two branches that come this close (in units of g, about radians
/// times O(1)) are one touching node.
constexpr double kTangencyTolerance = 1e-10;

/// The largest boundary tolerance accepted (radians): beyond it the default reading would move
/// trains visibly.
constexpr double kMaxBoundaryTolerance = 1e-3;

/// How a train near a boundary is read, decided once: by default an input within
/// boundary_tolerance of a boundary is analysed on it and branches within kTangencyTolerance
/// touch; `literal` analyses the doubles as given (both tolerances 0).
struct Reading {
  bool literal = false;
  double boundary_tolerance = kBoundaryTolerance;  // default reading only; [0, kMaxBoundaryTolerance]
  /// The tolerance in effect for boundaries (0 when literal), radians.
  double boundary() const { return literal ? 0.0 : boundary_tolerance; }
  /// The tolerance in effect for tangencies (0 when literal).
  double tangency() const { return literal ? 0.0 : kTangencyTolerance; }
  /// Throws InvalidInput("boundary_tolerance", ...) unless 0 <= boundary_tolerance <= 1e-3.
  void validate() const {
    if (!(boundary_tolerance >= 0.0 && boundary_tolerance <= kMaxBoundaryTolerance))
      throw InvalidInput("boundary_tolerance", report_number(boundary_tolerance), "outside the valid range",
                         "[0, 1e-3] radians");
  }
};

}  // namespace sphtroch
