// sphtroch/tolerance/tolerance_types.hpp — what the tolerance questions answer, as plain types:
// a tolerance box and the check of its half-widths, a box of twist angles, a boundary of the
// design map and a certified point of it, the certified margin, a box's topology and each node's
// enclosure. No CGAL: a program built against sphtroch::compiled (SPHTROCH_SEPARATE_EXACT) reads
// a ToleranceReport with these; the solvers that fill them (topology_margin.hpp,
// node_tolerance.hpp, tolerance_box.hpp) need CGAL's interval headers.
//
//   const sphtroch::GearTrain train(1.0, 2.0, sphtroch::Ratio(5, 2));
//   const sphtroch::ToleranceBox box{1e-3, 1e-3, 0.0};   // half-widths, radians
//   sphtroch::check_tolerance_box(train, box);            // InvalidInput naming "da2", "da3" or "dphase"
//   const sphtroch::MapBoundary cone{sphtroch::MapBoundary::Kind::pitch_cone};
//   sphtroch::boundary_text(cone);                        // its name in map/boundary_events.hpp's words
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/map/boundary_events.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// Half-widths of a tolerance box, radians (0 fixes that parameter).
struct ToleranceBox {
  double da2 = 0, da3 = 0, dphase = 0;
};

/// The largest phase half-width (a whole turn).
constexpr double kMaxPhaseTolerance = 6.283185307179586;

/// Throws InvalidInput naming fields[k] unless each half-width is finite and >= 0, the box's a2 and
/// a3 stay in [kMinCarrierTwist, pi - kMinCarrierTwist] and dphase <= kMaxPhaseTolerance.
inline void check_tolerance_box(const GearTrain& train, const ToleranceBox& box,
                                const std::array<std::string, 3>& fields = {"da2", "da3", "dphase"}) {
  const double lo = kMinCarrierTwist, hi = Constants<double>::pi() - kMinCarrierTwist;
  const std::string twist = "a half-width >= 0 radians that keeps the angle in [1e-6, pi - 1e-6]";
  auto check = [&](double d, double centre, const std::string& field) {
    if (!(std::isfinite(d) && d >= 0)) throw InvalidInput(field, number_text(d), "not a finite half-width >= 0", twist);
    if (!(centre - d >= lo && centre + d <= hi))
      throw InvalidInput(field, number_text(d), "the box leaves the trains' range (" + number_text(centre - d) + " .. " +
                                                    number_text(centre + d) + ")", twist);
  };
  check(box.da2, train.a2(), fields[0]);
  check(box.da3, train.a3(), fields[1]);
  if (!(std::isfinite(box.dphase) && box.dphase >= 0 && box.dphase <= kMaxPhaseTolerance))
    throw InvalidInput(fields[2], number_text(box.dphase), "outside the valid range", "a half-width in [0, 2 pi] radians");
}

/// [a2_lo, a2_hi] x [a3_lo, a3_hi], radians (a side may be a point).
struct TwistBox {
  double a2_lo = 0, a2_hi = 0, a3_lo = 0, a3_hi = 0;
  double a2_mid() const { return a2_lo + 0.5 * (a2_hi - a2_lo); }
  double a3_mid() const { return a3_lo + 0.5 * (a3_hi - a3_lo); }
  double width() const { return std::max(a2_hi - a2_lo, a3_hi - a3_lo); }
};

/// One boundary curve of the design map (see the header).
struct MapBoundary {
  enum class Kind { pitch_cone, mirror_pitch_cone, north_pole, south_pole, tangency };
  Kind kind = Kind::pitch_cone;
  int label = -1;      // tangency: the stationary point (0: larger b)
  std::int64_t m = 0;  // tangency: the integer value of g
};

/// The boundary in the words of map/boundary_events.hpp's events: "a3 = a_p (pitch cone)", ...
inline std::string boundary_text(const MapBoundary& b);
/// Its event kind as `boundaries` prints it: pitch_cone, pole or tangency.
inline BoundaryEventKind event_kind(const MapBoundary& b);

/// A boundary and a certified point of it: it meets the segment `at`.
struct BoundaryWitness {
  MapBoundary boundary;
  TwistBox at;
  double a2() const { return at.a2_mid(); }
  double a3() const { return at.a3_mid(); }
};

/// The certified margin of a train (topology_margin.hpp).
struct TopologyMargin {
  double lower = 0, upper = 0;             // radians: lower <= margin <= upper
  std::optional<BoundaryWitness> nearest;  // a boundary point at L-infinity distance <= upper
  bool converged = false;                  // upper - lower <= max(1e-9, 1e-6 upper)
  std::size_t boxes = 0;                   // boxes examined
};

/// Whether every train of a box draws the census of the nominal one (topology_margin.hpp).
struct BoxTopology {
  enum class Verdict { holds, changes, undecided };
  Verdict verdict = Verdict::undecided;
  std::optional<BoundaryWitness> event;  // changes: a boundary point inside the box
  std::string why;                       // undecided: the reason
  std::size_t boxes = 0;
};
inline const char* to_string(BoxTopology::Verdict v);

/// One node's or cusp's tolerance (node_tolerance.hpp).
struct NodeTolerance {
  Vector3d position = Vector3d::Zero();
  std::optional<double> max_displacement;           // radians, proved; nothing if not proved
  std::optional<Vector3d> d_da2, d_da3;             // nothing for a cusp or a tangency node
  Vector3d d_dphase = Vector3d::Zero();
};

/// What is proved about a tolerance box (see header).
struct BoxTolerance {
  TopologyMargin margin;
  BoxTopology topology;
  std::vector<NodeTolerance> nodes, cusps;  // in the order of the census given
};

// ------------------------------------------------------------------------------------------------

inline std::string boundary_text(const MapBoundary& b) {
  switch (b.kind) {
    case MapBoundary::Kind::pitch_cone: return boundary_name(BoundaryKind::pitch_cone);
    case MapBoundary::Kind::mirror_pitch_cone: return boundary_name(BoundaryKind::mirror_pitch_cone);
    case MapBoundary::Kind::north_pole: return boundary_name(BoundaryKind::a2);
    case MapBoundary::Kind::south_pole: return boundary_name(BoundaryKind::pi_minus_a2);
    case MapBoundary::Kind::tangency: break;
  }
  return "tangency g = " + std::to_string(b.m) + " (stationary point " + std::to_string(b.label) + ")";
}

inline BoundaryEventKind event_kind(const MapBoundary& b) {
  switch (b.kind) {
    case MapBoundary::Kind::pitch_cone:
    case MapBoundary::Kind::mirror_pitch_cone: return BoundaryEventKind::pitch_cone;
    case MapBoundary::Kind::north_pole:
    case MapBoundary::Kind::south_pole: return BoundaryEventKind::pole;
    case MapBoundary::Kind::tangency: break;
  }
  return BoundaryEventKind::tangency;
}

inline const char* to_string(BoxTopology::Verdict v) {
  switch (v) {
    case BoxTopology::Verdict::holds: return "holds";
    case BoxTopology::Verdict::changes: return "changes";
    case BoxTopology::Verdict::undecided: return "undecided";
  }
  return "?";
}

}  // namespace sphtroch
