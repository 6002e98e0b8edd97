// sphtroch/tolerance/topology_margin.hpp — how far a train is from a change of its node or
// cusp census, certified: the margin (the largest half-width of a square of (a2, a3) about the
// train that no boundary of the design map meets) and the topology of a tolerance box (does any
// train in it draw another census). The boundaries and the per-box proofs are
// boundary_enclosure.hpp's.
//
//   const sphtroch::GearTrain train(1.0, 2.0, sphtroch::Ratio(5, 2));
//   const sphtroch::TopologyMargin m = sphtroch::topology_margin(train);
//   m.lower, m.upper;        // radians: the margin lies in [lower, upper]
//   m.nearest->boundary;     // the boundary met at distance <= upper, and where (m.nearest->at)
//   const sphtroch::BoxTopology b = sphtroch::box_topology(train, 1e-3, 1e-3);
//   b.verdict;               // holds | changes | undecided (b.why)
//
// Margin: a best-first branch and bound over the square of half-width `upper` about (a2, a3),
// clipped to the trains' range [kMinCarrierTwist, pi - kMinCarrierTwist]^2: a box proved free of
// boundaries is dropped; in another, a point of a boundary proved on a midline lowers `upper` to
// its distance; the box nearest the train (L-infinity) bounds `lower`. Stops when
// upper - lower <= max(1e-9, 1e-6 upper) (converged) or after kMaxMarginBoxes boxes (`lower` is
// still a proved bound). Distances are rounded outward. The phase plays no part: a phase change
// turns the curve about the sun axis (P(s + d) = Rz(d) P(s) with the phase moved by n d), so the
// census depends on (a2, a3) only.
// Box topology: the same tests over [a2 -+ da2] x [a3 -+ da3] (a zero half-width fixes that
// angle): `holds` when every part is proved free, `changes` with a proved boundary point inside,
// `undecided` when a part narrower than kMinTopologyBox (1e-12 rad) is neither — a boundary then
// passes within about that of the box's edge, or through a point where two boundaries meet.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/tolerance/topology_margin.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/tolerance/boundary_enclosure.hpp"
#include "sphtroch/tolerance/tolerance_types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <queue>
#include <string>
#include <vector>

namespace sphtroch {



/// The most boxes topology_margin examines (~2-4 us each).
constexpr std::size_t kMaxMarginBoxes = 200000;
/// The narrowest part of a tolerance box that box_topology still splits, radians.
constexpr double kMinTopologyBox = 1e-12;
/// The most boxes box_topology examines.
constexpr std::size_t kMaxTopologyBoxes = 50000;

/// The certified margin of the train (see header).
inline TopologyMargin topology_margin(const GearTrain& train);


/// Whether every train with a2 in [a2 - da2, a2 + da2] and a3 in [a3 - da3, a3 + da3] has the
/// census of `train` (see header). Throws InvalidInput("tol_a2" / "tol_a3") unless the half-widths
/// are finite, >= 0 and keep the box inside [kMinCarrierTwist, pi - kMinCarrierTwist].
inline BoxTopology box_topology(const GearTrain& train, double da2, double da3);

// ------------------------------------------------------------------------------------------------

namespace topology_margin_detail {

/// The L-infinity distance from (a2, a3) to the box, rounded down (0 inside).
inline double distance_below(const TwistBox& b, double a2, double a3) {
  const Interval d[4] = {Interval(b.a2_lo) - a2, Interval(a2) - b.a2_hi, Interval(b.a3_lo) - a3, Interval(a3) - b.a3_hi};
  double m = 0;
  for (const Interval& x : d) m = std::max(m, x.inf());
  return m;
}

/// The largest L-infinity distance from (a2, a3) to a point of the box, rounded up.
inline double distance_above(const TwistBox& b, double a2, double a3) {
  const Interval d[4] = {Interval(b.a2_lo) - a2, Interval(b.a2_hi) - a2, Interval(b.a3_lo) - a3, Interval(b.a3_hi) - a3};
  double m = 0;
  for (const Interval& x : d) m = std::max(m, std::max(x.sup(), -x.inf()));
  return m;
}

/// Where a box is cut, as a share of its longer side: off the middle by an irrational amount, so
/// that a boundary placed at a round share of the box (a tolerance of twice the distance to an
/// event) does not stay on the cuts, where no sign change can prove it.
constexpr double kCutShare = 0.4801;

/// Two parts across the longer side (a point side is never cut).
inline std::pair<TwistBox, TwistBox> halves(const TwistBox& b) {
  TwistBox l = b, r = b;
  if (b.a2_hi - b.a2_lo >= b.a3_hi - b.a3_lo) {
    l.a2_hi = r.a2_lo = b.a2_lo + kCutShare * (b.a2_hi - b.a2_lo);
  } else {
    l.a3_hi = r.a3_lo = b.a3_lo + kCutShare * (b.a3_hi - b.a3_lo);
  }
  return {l, r};
}

/// A proved point of one of `may_meet` on a midline of the box (or on the box, if it is a segment).
inline std::optional<BoundaryWitness> witness_in(const TwistBox& b, const std::vector<MapBoundary>& may_meet, const Ratio& n) {
  for (const MapBoundary& m : may_meet) {
    if (m.label < 0 && m.kind == MapBoundary::Kind::tangency) continue;
    if (b.a3_hi > b.a3_lo)
      if (auto at = boundary_point_on(m, TwistBox{b.a2_mid(), b.a2_mid(), b.a3_lo, b.a3_hi}, n)) return BoundaryWitness{m, *at};
    if (b.a2_hi > b.a2_lo)
      if (auto at = boundary_point_on(m, TwistBox{b.a2_lo, b.a2_hi, b.a3_mid(), b.a3_mid()}, n)) return BoundaryWitness{m, *at};
  }
  return std::nullopt;
}

inline double tolerance_of(double upper) { return std::max(1e-9, 1e-6 * upper); }

struct Queued {
  double distance;
  TwistBox box;
  bool operator<(const Queued& o) const { return distance > o.distance; }  // nearest first
};

}  // namespace topology_margin_detail

inline TopologyMargin topology_margin(const GearTrain& train) {
  namespace d = topology_margin_detail;
  const RoundingGuard upward;
  const double a2 = train.a2(), a3 = train.a3();
  const Ratio& n = train.ratio();
  const double lo = kMinCarrierTwist, hi = Constants<double>::pi() - kMinCarrierTwist;
  TopologyMargin r;
  r.upper = std::numeric_limits<double>::infinity();
  // A first upper bound: the pitch cone above or below the train (it crosses every a2).
  const TwistBox column{a2, a2, lo, hi};
  for (const MapBoundary& cone : {MapBoundary{MapBoundary::Kind::pitch_cone}, MapBoundary{MapBoundary::Kind::mirror_pitch_cone}})
    if (auto at = boundary_point_on(cone, column, n)) {
      const double u = d::distance_above(*at, a2, a3);
      if (u < r.upper) r = TopologyMargin{0, u, BoundaryWitness{cone, *at}, false, 0};
    }
  const double reach = std::isfinite(r.upper) ? r.upper : hi - lo;
  std::priority_queue<d::Queued> queue;
  const TwistBox square{std::max(lo, a2 - reach), std::min(hi, a2 + reach), std::max(lo, a3 - reach), std::min(hi, a3 + reach)};
  queue.push({0.0, square});
  bool stopped = false;  // by convergence or the box bound (else: every box nearer than upper was proved free)
  while (!queue.empty()) {
    const d::Queued top = queue.top();
    queue.pop();
    r.lower = std::min(top.distance, r.upper);
    if (std::isfinite(r.upper) && r.upper - r.lower <= d::tolerance_of(r.upper)) {
      stopped = true;
      break;
    }
    if (++r.boxes > kMaxMarginBoxes) {
      stopped = true;
      break;
    }
    const std::vector<MapBoundary> may_meet = boundaries_possibly_in(top.box, n);
    if (may_meet.empty()) continue;
    if (auto w = d::witness_in(top.box, may_meet, n)) {
      const double u = d::distance_above(w->at, a2, a3);
      if (u < r.upper) {
        r.upper = u;
        r.nearest = w;
      }
    }
    const auto [left, right] = d::halves(top.box);
    for (const TwistBox& h : {left, right}) {
      const double dist = d::distance_below(h, a2, a3);
      if (dist < r.upper) queue.push({dist, h});
    }
  }
  if (!stopped) r.lower = std::isfinite(r.upper) ? r.upper : reach;  // nothing nearer than upper (or in the square)
  // No boundary proved anywhere in the trains' range: none there (a pitch cone crosses every column
  // a2, but may lie outside [1e-6, pi - 1e-6] in a3); the bracket then says only "at least lower".
  if (!std::isfinite(r.upper)) r.upper = std::max(r.lower, Constants<double>::pi());
  r.converged = r.nearest && r.upper - r.lower <= d::tolerance_of(r.upper);
  return r;
}


inline BoxTopology box_topology(const GearTrain& train, double da2, double da3) {
  namespace d = topology_margin_detail;
  const double lo = kMinCarrierTwist, hi = Constants<double>::pi() - kMinCarrierTwist;
  const std::string range = "a half-width >= 0 radians that keeps the angle in [1e-6, pi - 1e-6]";
  if (!(da2 >= 0) || !std::isfinite(da2) || !(train.a2() - da2 >= lo && train.a2() + da2 <= hi))
    throw InvalidInput("tol_a2", report_number(da2), "outside the valid range", range);
  if (!(da3 >= 0) || !std::isfinite(da3) || !(train.a3() - da3 >= lo && train.a3() + da3 <= hi))
    throw InvalidInput("tol_a3", report_number(da3), "outside the valid range", range);
  const RoundingGuard upward;
  const Ratio& n = train.ratio();
  BoxTopology r;
  std::vector<TwistBox> stack{{train.a2() - da2, train.a2() + da2, train.a3() - da3, train.a3() + da3}};
  while (!stack.empty()) {
    const TwistBox box = stack.back();
    stack.pop_back();
    if (++r.boxes > kMaxTopologyBoxes) {
      r.why = "more than " + std::to_string(kMaxTopologyBoxes) + " boxes";
      return r;
    }
    const std::vector<MapBoundary> may_meet = boundaries_possibly_in(box, n);
    if (may_meet.empty()) continue;
    if ((r.event = d::witness_in(box, may_meet, n))) {
      r.verdict = BoxTopology::Verdict::changes;
      return r;
    }
    if (box.width() <= kMinTopologyBox) {
      r.why = "a boundary (" + boundary_text(may_meet.front()) + ") passes within " + number_text(kMinTopologyBox) +
              " rad of a2 = " + number_text(box.a2_mid()) + ", a3 = " + number_text(box.a3_mid()) +
              ": neither inside nor outside the box could be proved";
      return r;
    }
    const auto [left, right] = d::halves(box);
    stack.push_back(left);
    stack.push_back(right);
  }
  r.verdict = BoxTopology::Verdict::holds;
  return r;
}

}  // namespace sphtroch
