// sphtroch/map/boundary_events.hpp — the boundary set of the (a2, a3) map for any n = p/q: every a3 at
// one a2 where the node or cusp count of the curve changes, with the counts on either side, and
// the boundary curves (loci) over an a2 range. Eigen only (no CGAL); belongs with the boundary
// vocabulary (closed_form_boundaries.hpp).
//
//   sphtroch::BoundarySet s = sphtroch::boundary_set(kPi / 2, sphtroch::Ratio(3));
//   for (const sphtroch::BoundaryEvent& e : s.events) e.kind, e.a3, e.nodes_below, e.nodes_above;
//   sphtroch::boundary_loci(sphtroch::Ratio(5, 2), 0.01, 3.13);   // polylines in (a2, a3)
//   sphtroch::nearest_tangency(a2, a3, n, 1e-10);                 // a tangency locus within tol
//
// Which events exist (derivation ours; notation of root_function.hpp / root_census.hpp). At fixed a2,
// the non-pole node points of the curve are |p| times the number of b in (0, pi) where g(b) is an
// integer. g is continuous in b on (0, pi) and in a3, and has at most two stationary points
// (quadratic in cos b). So, as a3 moves, the number of roots changes only where
//   (a) a root enters or leaves through an end b = 0, pi. At an end g is the integer of a trivial
//       root t1 = t2, and a root can leave there only when g'(end) = 0 — exactly a3 = a_p (b = pi)
//       or a3 = pi - a_p (b = 0): the pitch cones, where a near-cusp loop shrinks to a cusp — or
//       when the end value itself jumps: g(pi) jumps from q to q - p when C(pi) crosses the north
//       pole (a3 = a2), g(0) from 0 to -p when C(0) crosses the south pole (a3 = pi - a2): the
//       pole passages. Kinds `pitch_cone` and `pole` (closed forms, closed_form_boundaries.hpp).
//   (b) two roots merge (or split) inside (0, pi): a double root, g(b*) = m integer with
//       g'(b*) = 0 — two branches touch (a tangency node) away from the poles. Kind `tangency`:
//       the locus G_l(a2, a3) := g(b*_l(a2, a3); a2, a3) = m for a stationary-point label l (0, 1,
//       root_function.hpp) and an integer m. The witness is (b*, m, l); the node lies on the mirror
//       plane at azimuth az(C(b*)) of the carrier frame (root_census.hpp step 2).
//   (c) a triple root (g = m, g' = 0, g'' = 0) is where two tangency loci of one m end together
//       (the two stationary points merge); at a generic a2 it is not crossed; it is a point of (b).
//   Three branches through one point off the poles cannot happen: any two branches through a
//   point have planet angles b and -b (root_census.hpp step 1, since z = ca2 ca3 - sa2 sa3 cos b
//   fixes cos b), so among three branches two have EQUAL planet angles, which forces the point
//   onto the Z1 axis (step 1): a pole. Hence (a) and (b) are all the events, and the number of
//   node points off the events is |p| x RootFunction::node_roots().
//   Cusps exist only ON a pitch cone (zero speed iff a3 = a_p or pi - a_p, docs/design.md), so
//   cusps_below = cusps_above = 0 for every event; they are reported for the interface's sake.
//
// How the tangencies are found at one a2: for each label l, G_l(a3) is sampled on a grid of
// a3 (uniform, plus geometric refinement towards 0, pi and every closed-form event, where G is
// steep), each cell is split at the extremum of G_l when dG_l/da3 changes sign in it (so a pair
// of tangencies closer than a cell is still found), and every integer strictly between the
// values at the ends of a monotone piece is a tangency, solved by safeguarded Newton in long
// double (dG/da3 = dg/da3 at b*, envelope theorem). The grid is sampled in double where every
// decision holds by kScanMargin, else in long double (scan_sample): the same events as a scan in
// long double, 2.3x faster natively and ~5x in WebAssembly (software long double). Accuracy: |a3 - a3*| <= kEventAccuracy
// (1e-12) for the long double root; the double a3 reported adds its rounding (<= 2.2e-16 a3).
// Known limit: two extrema of G_l inside one grid cell (cell <= 1.6e-3 rad) can hide a pair.
// A stationary value equal to the end integer within 1e-8 of a pitch cone is the near-cusp loop
// of (a), not a tangency, and is dropped.
//
// The counts on either side of an event are the counts at the midpoints between consecutive
// distinct events (the count is constant between events), by RootFunction::node_roots.
#pragma once

#include "sphtroch/map/closed_form_boundaries.hpp"
#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/map/root_function.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// Bound on |a3 - a3*| of every tangency the boundary set reports (long double root), radians.
constexpr double kEventAccuracy = 1e-12;
/// Events closer than this in a3 are one group: they share the counts on either side.
constexpr double kEventCoincidence = 1e-12;
/// The most a2 samples boundary_loci takes.
constexpr std::size_t kMaxLocusSteps = 10000;  // ~2 ms per step and core for p, q <= 7: <= ~20 s
/// Two events of one (label, m) at consecutive a2 samples belong to one locus when closer than
/// this in a3 (radians).
constexpr double kLocusJump = 0.25;

/// cusp and triple_point: a rotation chain's events (chain/chain_family_events.hpp).
enum class BoundaryEventKind { pitch_cone, pole, tangency, cusp, triple_point };
inline const char* to_string(BoundaryEventKind k) {
  switch (k) {
    case BoundaryEventKind::pitch_cone: return "pitch_cone";
    case BoundaryEventKind::pole: return "pole";
    case BoundaryEventKind::tangency: return "tangency";
    case BoundaryEventKind::cusp: return "cusp";
    case BoundaryEventKind::triple_point: return "triple_point";
  }
  return "?";
}

/// One a3 at which the census changes (see header).
struct BoundaryEvent {
  BoundaryEventKind kind = BoundaryEventKind::pitch_cone;
  std::string name;          // "a3 = a_p (pitch cone)", "tangency g = 2 (stationary point 0)", ...
  double a3 = 0.0;           // radians: tangency, the long double root rounded; closed forms, their
                             // double value as closed_form_boundaries.hpp computes it (atlas_boundary_a3)
  long double a3_precise = 0.0L;
  double b = 0.0;            // witness: planet angle (pitch cone / north pole: pi, mirror / south: 0)
  std::int64_t m = 0;        // tangency: the integer g(b*); otherwise 0
  int label = -1;            // tangency: stationary-point label (root_function.hpp); else -1
  std::int64_t nodes_below = 0, nodes_above = 0;  // node points just below / above a3
  std::int64_t cusps_below = 0, cusps_above = 0;  // 0: cusps exist only on a pitch cone
};

struct BoundarySet {
  Ratio ratio;
  double a2 = 0.0;
  std::vector<BoundaryEvent> events;  // ascending a3
};

/// Node points of the curve at (a2, a3) off every event (|p| x RootFunction::node_roots; on an
/// event, the count of one side). Radians; REQUIRES a2, a3 in (0, pi).
inline std::int64_t node_count_off_events(double a2, double a3, const Ratio& n);

/// Every event in a3 in (0, pi) at this a2 (see header). Throws InvalidInput("a2") unless
/// a2 is finite in (0, pi), InvalidInput("n") beyond the census cost bound (cost_bounds.hpp).
inline BoundarySet boundary_set(double a2, const Ratio& n);

/// A tangency locus (or a closed-form boundary) as a polyline over a2.
struct LocusPoint {
  double a2 = 0.0, a3 = 0.0, b = 0.0;
};
struct Locus {
  BoundaryEventKind kind = BoundaryEventKind::tangency;
  std::string name;
  std::int64_t m = 0;
  int label = -1;
  std::vector<LocusPoint> points;  // ascending a2, consecutive samples of the a2 grid
};

/// Every boundary curve over a2 in [a2_lo, a2_hi] (0 <= lo < hi <= pi), sampled at the centres
/// a2_k = lo + (hi - lo)(k + 1/2)/steps, k = 0 .. steps - 1, each point refined as boundary_set
/// does: pitch cones, poles (|p| >= 2) and tangency loci, a tangency locus being the run of
/// events of one (label, m) continued from one sample to the next, the nearest in a3 within
/// kLocusJump. A locus ends where its stationary point leaves (0, pi) (on a pitch cone), merges
/// with the other one (a triple root) or at the range's edge; it is then resolved to the a2 step.
/// The samples are computed on `threads` threads; `progress`, if given, is called on the calling
/// thread about every 100 ms with (samples done, steps), and an exception it throws stops the
/// work and is rethrown (parallel_for.hpp). Throws InvalidInput("a2") for a bad range,
/// InvalidInput("steps") unless 1 <= steps <= kMaxLocusSteps, InvalidInput("n") beyond the
/// census cost bound (cost_bounds.hpp).
inline std::vector<Locus> boundary_loci(const Ratio& n, double a2_lo, double a2_hi, std::size_t steps = 720,
                                        std::size_t threads = 1, const ParallelProgress& progress = {});

/// The event of `set` nearest a3 (the first of equals), or nothing when the set has none.
inline std::optional<BoundaryEvent> nearest_event(const BoundarySet& set, double a3) {
  const BoundaryEvent* best = nullptr;
  for (const BoundaryEvent& e : set.events)
    if (!best || std::abs(e.a3 - a3) < std::abs(best->a3 - a3)) best = &e;
  if (!best) return std::nullopt;
  return *best;
}

/// A tangency locus within `tolerance` (radians, in a3) of (a2, a3), the nearest, or nothing.
struct TangencyHit {
  double a3 = 0.0;        // the locus's a3 at this a2 (nearest double)
  double margin = 0.0;    // input a3 - locus a3
  double b = 0.0;
  std::int64_t m = 0;
  int label = 0;
};
inline std::optional<TangencyHit> nearest_tangency(double a2, double a3, const Ratio& n, double tolerance);

// =============================================================================================
// Implementation details follow.
// =============================================================================================

namespace boundary_set_detail {

using Real = long double;

struct Sample {
  Real a3 = 0;
  bool ok = false;  // the stationary point of this label exists in (0, pi)
  Real b = 0, G = 0, dG = 0;
  bool precise = true;  // computed in Real (else in double: a scan sample, see scan_sample)
};

inline Sample sample(Real sa2, Real ca2, Real a3, const Ratio& n, int label) {
  Sample s;
  s.a3 = a3;
  const RootFunction<Real> h(sa2, ca2, std::sin(a3), std::cos(a3), n);
  if (const auto b = h.stationary(label)) {
    s.ok = true;
    s.b = *b;
    s.G = h.g(*b);
    s.dG = h.dg_da3(*b);
  }
  return s;
}

/// Margin of the double scan: a decision taken in double must hold by this much, relative to the
/// size of the terms it is computed from (the discriminant: stationary_margin) or to |p| + q (G's
/// distance to an integer, |dG/da3|). Where the double's error could approach it — C(b*) within
/// kScanPoleDistance of a pole, where the azimuth az(b*) and so G and dG are ill-conditioned
/// (error ~ eps / distance^2) — the sample is taken in Real whatever the margins say.
constexpr double kScanMargin = 1e-9;
constexpr double kScanPoleDistance = 1e-3;

/// A grid sample for the scan, in double when every decision the scan takes on it — whether the
/// stationary point exists (discriminant, cos b* inside (-1, 1)), the sign of dG, which integers
/// lie below G — holds by kScanMargin; otherwise in Real. The scan then decides exactly as a scan
/// in Real, and every cell it refines gets Real samples at its ends (precise()), so the events
/// are those of an all-Real scan, at a fraction of its cost where Real is slow (long double is
/// software quad in WebAssembly: 35 -> ~4 ms per a2 there).
inline Sample scan_sample(double sa2, double ca2, Real a3, const Ratio& n, int label, Real sa2_r, Real ca2_r) {
  const double a3d = static_cast<double>(a3);
  const RootFunction<double> h(sa2, ca2, std::sin(a3d), std::cos(a3d), n);
  const double scale = static_cast<double>(n.abs_p() + n.q());
  Sample s;
  s.a3 = a3;
  s.precise = false;
  const std::optional<double> c = h.stationary_cos(label);
  const bool clearly_absent = !c || *c < -1 - kScanMargin || *c > 1 + kScanMargin;
  if (clearly_absent && h.stationary_margin() > kScanMargin) return s;
  if (c && std::abs(*c) < 1 - kScanMargin && h.stationary_margin() > kScanMargin) {
    const double b = std::acos(*c);
    const Vector3<double> at = h.circle_point(b);
    if (std::hypot(at.x(), at.y()) < kScanPoleDistance) return sample(sa2_r, ca2_r, a3, n, label);
    const double G = h.g(b), dG = h.dg_da3(b);
    const double to_integer = std::abs(G - std::nearbyint(G));
    if (to_integer > kScanMargin * scale && std::abs(dG) > kScanMargin * scale) {
      s.ok = true;
      s.b = b;
      s.G = G;
      s.dG = dG;
      return s;
    }
  }
  return sample(sa2_r, ca2_r, a3, n, label);
}

/// s itself when computed in Real, else s again in Real.
inline Sample precise(const Sample& s, Real sa2, Real ca2, const Ratio& n, int label) {
  return s.precise ? s : sample(sa2, ca2, s.a3, n, label);
}

/// The a3 grid: uniform plus geometric refinement towards 0, pi and the closed-form events.
inline std::vector<Real> grid(Real a2, Real a_p) {
  const Real pi = RootFunction<Real>::pi();
  std::vector<Real> g;
  constexpr int kUniform = 2048;
  for (int i = 1; i < kUniform; ++i) g.push_back(pi * i / kUniform);
  const Real specials[] = {Real(0), pi, a_p, pi - a_p, a2, pi - a2};
  for (Real s : specials)
    for (Real d = 1e-13L; d < 0.05L; d *= 1.12L)
      for (Real x : {s - d, s + d})
        if (x > 1e-13L && x < pi - 1e-13L) g.push_back(x);
  std::sort(g.begin(), g.end());
  g.erase(std::unique(g.begin(), g.end()), g.end());
  return g;
}

/// Root of G_label(a3) = m on [lo, hi] (values of G - m of opposite signs at the ends).
inline Sample solve(Real sa2, Real ca2, const Ratio& n, int label, Real m, Sample lo, Sample hi) {
  Sample best = std::abs(lo.G - m) < std::abs(hi.G - m) ? lo : hi;
  const bool lo_neg = lo.G - m < 0;
  for (int it = 0; it < 200 && hi.a3 - lo.a3 > 1e-18L; ++it) {
    Real x = best.a3 - (best.G - m) / best.dG;
    if (!(x > lo.a3 && x < hi.a3) || !(best.dG != 0)) x = (lo.a3 + hi.a3) / 2;
    Sample s = sample(sa2, ca2, x, n, label);
    if (!s.ok) {  // the stationary point vanished inside: bisect instead
      x = (lo.a3 + hi.a3) / 2;
      s = sample(sa2, ca2, x, n, label);
      if (!s.ok) break;
    }
    if (s.G == m) return s;
    if ((s.G - m < 0) == lo_neg) lo = s;
    else hi = s;
    const Real step = std::abs(s.a3 - best.a3);
    best = s;
    if (step < 1e-19L) break;
  }
  return best;
}

/// The extremum of G_label on [lo, hi] where dG changes sign (bisection on dG).
inline Sample extremum(Real sa2, Real ca2, const Ratio& n, int label, Sample lo, Sample hi) {
  const bool lo_pos = lo.dG > 0;
  for (int it = 0; it < 80 && hi.a3 - lo.a3 > 1e-18L; ++it) {
    const Sample s = sample(sa2, ca2, (lo.a3 + hi.a3) / 2, n, label);
    if (!s.ok) return s;
    if ((s.dG > 0) == lo_pos) lo = s;
    else hi = s;
  }
  return sample(sa2, ca2, (lo.a3 + hi.a3) / 2, n, label);
}

inline std::string tangency_name(std::int64_t m, int label) {
  return "tangency g = " + std::to_string(m) + " (stationary point " + std::to_string(label) + ")";
}

/// Every tangency at this a2, unsorted.
inline std::vector<BoundaryEvent> tangencies(Real a2, const Ratio& n) {
  const Real sa2 = std::sin(a2), ca2 = std::cos(a2);
  const Real pi = RootFunction<Real>::pi();
  const Real a_p = std::atan2(sa2, ca2 + static_cast<Real>(n.p()) / static_cast<Real>(n.q()));
  const std::vector<Real> g = grid(a2, a_p);
  std::vector<BoundaryEvent> out;
  for (int label = 0; label < 2; ++label) {
    auto add_roots = [&](const Sample& u, const Sample& v) {  // G monotone on [u, v]
      const Real lo = std::min(u.G, v.G), hi = std::max(u.G, v.G);
      for (Real m = std::floor(lo) + 1; m < hi; m += 1) {
        const Sample rr = solve(sa2, ca2, n, label, m, u, v);  // u.a3 < v.a3
        // A stationary value equal to the end integer next to a pitch cone: the near-cusp loop.
        const RootFunction<Real> h(sa2, ca2, std::sin(rr.a3), std::cos(rr.a3), n);
        if ((std::abs(rr.a3 - a_p) < 1e-8L && m == h.g_at_pi()) || (std::abs(rr.a3 - (pi - a_p)) < 1e-8L && m == h.g_at_0()))
          continue;
        BoundaryEvent e;
        e.kind = BoundaryEventKind::tangency;
        e.a3_precise = rr.a3;
        e.a3 = static_cast<double>(rr.a3);
        e.b = static_cast<double>(rr.b);
        e.m = static_cast<std::int64_t>(m);
        e.label = label;
        e.name = tangency_name(e.m, label);
        out.push_back(e);
      }
    };
    // A cell is refined from Real samples: those of an all-Real scan (scan_sample).
    auto integer_between = [](const Sample& u, const Sample& v) {
      return std::floor(std::min(u.G, v.G)) + 1 < std::max(u.G, v.G);
    };
    const double sa2d = static_cast<double>(sa2), ca2d = static_cast<double>(ca2);
    Sample prev = scan_sample(sa2d, ca2d, g[0], n, label, sa2, ca2);
    for (std::size_t i = 1; i < g.size(); ++i) {
      Sample cur = scan_sample(sa2d, ca2d, g[i], n, label, sa2, ca2);
      if (prev.ok && cur.ok) {
        if ((prev.dG > 0) != (cur.dG > 0)) {
          prev = precise(prev, sa2, ca2, n, label);
          cur = precise(cur, sa2, ca2, n, label);
          const Sample e = extremum(sa2, ca2, n, label, prev, cur);
          if (e.ok) {
            add_roots(prev, e);
            add_roots(e, cur);
          } else {
            add_roots(prev, cur);
          }
        } else if (integer_between(prev, cur)) {
          prev = precise(prev, sa2, ca2, n, label);
          cur = precise(cur, sa2, ca2, n, label);
          add_roots(prev, cur);
        }
      }
      prev = cur;
    }
  }
  return out;
}

inline std::int64_t node_count(Real sa2, Real ca2, Real a3, const Ratio& n) {
  const RootFunction<Real> h(sa2, ca2, std::sin(a3), std::cos(a3), n);
  return n.abs_p() * h.node_roots();
}

/// a2 as GearTrain accepts it: in (0, pi) and not within kMinCarrierTwist of either end, where
/// the curve degenerates (classify refuses the same values).
inline bool a2_in_range(double a2) {
  const double pi = Constants<double>::pi();
  return std::isfinite(a2) && a2 > 0 && a2 < pi && carrier_twist_in_range(a2);
}

inline void check_a2(double a2) {
  if (!(std::isfinite(a2) && a2 > 0 && a2 < Constants<double>::pi()))
    throw InvalidInput("a2", report_number(a2), "outside the valid range", "(0, pi) radians");
  if (!a2_in_range(a2))
    throw InvalidInput("a2", report_number(a2), "within 1e-6 rad of 0 or pi (the curve degenerates into a multiply covered circle)",
                       "[1e-6, pi - 1e-6] radians");
}

}  // namespace boundary_set_detail

inline std::int64_t node_count_off_events(double a2, double a3, const Ratio& n) {
  using Real = boundary_set_detail::Real;
  const Real A2 = a2;
  return boundary_set_detail::node_count(std::sin(A2), std::cos(A2), a3, n);
}

inline BoundarySet boundary_set(double a2, const Ratio& n) {
  using namespace boundary_set_detail;
  check_a2(a2);
  check_census_cost(n);
  const Real A2 = a2;
  const Real sa2 = std::sin(A2), ca2 = std::cos(A2);
  const Real pi = RootFunction<Real>::pi();
  const Real a_p = std::atan2(sa2, ca2 + static_cast<Real>(n.p()) / static_cast<Real>(n.q()));
  BoundarySet s;
  s.ratio = n;
  s.a2 = a2;
  auto closed = [&](BoundaryEventKind kind, BoundaryKind which, Real a3, Real b) {
    BoundaryEvent e;
    e.kind = kind;
    e.name = boundary_name(which);
    e.a3_precise = a3;
    // The double of the closed form as closed_form_boundaries.hpp evaluates it: the value classify snaps.
    e.a3 = atlas_boundary_a3(which, a2, n);
    e.b = static_cast<double>(b);
    return e;
  };
  std::vector<BoundaryEvent> ev = tangencies(A2, n);
  ev.push_back(closed(BoundaryEventKind::pitch_cone, BoundaryKind::pitch_cone, a_p, pi));
  ev.push_back(closed(BoundaryEventKind::pitch_cone, BoundaryKind::mirror_pitch_cone, pi - a_p, 0));
  std::vector<BoundaryEvent> poles{closed(BoundaryEventKind::pole, BoundaryKind::a2, A2, pi),
                                   closed(BoundaryEventKind::pole, BoundaryKind::pi_minus_a2, pi - A2, 0)};
  std::sort(ev.begin(), ev.end(), [](const BoundaryEvent& a, const BoundaryEvent& b) { return a.a3_precise < b.a3_precise; });
  // Counts between groups of coincident events.
  auto count_between = [&](Real lo, Real hi) { return node_count(sa2, ca2, (lo + hi) / 2, n); };
  for (BoundaryEvent& pole : poles) {
    // A pole passage is an event when the pole is a node (|p| >= 2) or the count changes there.
    Real below = 0, above = pi;
    for (const BoundaryEvent& e : ev) {
      if (e.a3_precise < pole.a3_precise - kEventCoincidence) below = std::max(below, e.a3_precise);
      if (e.a3_precise > pole.a3_precise + kEventCoincidence) above = std::min(above, e.a3_precise);
    }
    const bool changes = count_between(below, pole.a3_precise) != count_between(pole.a3_precise, above);
    if (n.abs_p() >= 2 || changes) ev.push_back(pole);
  }
  std::sort(ev.begin(), ev.end(), [](const BoundaryEvent& a, const BoundaryEvent& b) { return a.a3_precise < b.a3_precise; });
  std::size_t i = 0;
  Real prev_end = 0;
  while (i < ev.size()) {
    std::size_t j = i + 1;
    while (j < ev.size() && ev[j].a3_precise - ev[j - 1].a3_precise <= kEventCoincidence) ++j;
    const Real next = j < ev.size() ? ev[j].a3_precise : pi;
    const std::int64_t below = count_between(prev_end, ev[i].a3_precise);
    const std::int64_t above = count_between(ev[j - 1].a3_precise, next);
    for (std::size_t k = i; k < j; ++k) {
      ev[k].nodes_below = below;
      ev[k].nodes_above = above;
    }
    prev_end = ev[j - 1].a3_precise;
    i = j;
  }
  // Printed order: the doubles (a coincident group may round in another order; its members
  // share the counts, so the chain of counts is the same).
  std::stable_sort(ev.begin(), ev.end(), [](const BoundaryEvent& a, const BoundaryEvent& b) { return a.a3 < b.a3; });
  s.events = std::move(ev);
  return s;
}

inline std::vector<Locus> boundary_loci(const Ratio& n, double a2_lo, double a2_hi, std::size_t steps,
                                        std::size_t threads, const ParallelProgress& progress) {
  using namespace boundary_set_detail;
  const double pi = Constants<double>::pi();
  const std::string range = number_text(a2_lo) + ":" + number_text(a2_hi);
  if (!(a2_lo >= 0 && a2_lo < a2_hi && a2_hi <= pi))
    throw InvalidInput("a2", range, "not a valid range", "LO:HI with 0 <= LO < HI <= pi");
  if (steps < 1 || steps > kMaxLocusSteps)
    throw InvalidInput("steps", std::to_string(steps), "outside the valid range", "integer 1 .. 10000");
  check_census_cost(n);
  std::vector<double> a2s(steps);
  for (std::size_t k = 0; k < steps; ++k)
    a2s[k] = a2_lo + (a2_hi - a2_lo) * (static_cast<double>(k) + 0.5) / static_cast<double>(steps);
  if (!boundary_set_detail::a2_in_range(a2s.front()) || !boundary_set_detail::a2_in_range(a2s.back()))
    throw InvalidInput("a2", range, "samples within 1e-6 rad of 0 or pi (the curve degenerates there)",
                       "a range whose a2 samples lie in [1e-6, pi - 1e-6]");
  for (std::size_t k = 0; k < steps; ++k)
    if (!(a2s[k] > 0 && a2s[k] < pi && (k == 0 || a2s[k] > a2s[k - 1])))
      throw InvalidInput("a2", range, "too narrow for the steps: the sample a2 are not distinct angles in (0, pi)",
                         "a wider range or fewer steps");
  std::vector<Locus> out;
  auto closed = [&](BoundaryKind which) {
    Locus l;
    l.kind = which == BoundaryKind::pitch_cone || which == BoundaryKind::mirror_pitch_cone ? BoundaryEventKind::pitch_cone
                                                                                          : BoundaryEventKind::pole;
    l.name = boundary_name(which);
    const double b = which == BoundaryKind::pitch_cone || which == BoundaryKind::a2 ? pi : 0.0;
    for (double a2 : a2s) l.points.push_back({a2, atlas_boundary_a3(which, a2, n), b});
    return l;
  };
  for (BoundaryKind k : atlas_boundary_kinds(n)) out.push_back(closed(k));
  // The tangencies of every sample (independent: spread over the threads), then linked.
  std::vector<std::vector<BoundaryEvent>> events(steps);
  parallel_for(steps, threads, [&](std::size_t k) {
    events[k] = tangencies(a2s[k], n);
    std::sort(events[k].begin(), events[k].end(), [](const BoundaryEvent& a, const BoundaryEvent& b) { return a.a3 < b.a3; });
  }, 1, progress);
  // Tangency loci: events of one (label, m) continued from sample to sample (nearest in a3).
  std::vector<std::size_t> open;  // indices into out of loci that reached the previous sample
  for (std::size_t k = 0; k < steps; ++k) {
    std::vector<std::size_t> next_open;
    std::vector<bool> taken(out.size(), false);
    for (const BoundaryEvent& e : events[k]) {
      std::size_t best = out.size();
      double best_d = kLocusJump;
      for (std::size_t idx : open) {
        const Locus& l = out[idx];
        if (taken[idx] || l.m != e.m || l.label != e.label) continue;
        const double d = std::abs(l.points.back().a3 - e.a3);
        if (d < best_d) {
          best_d = d;
          best = idx;
        }
      }
      if (best == out.size()) {
        Locus l;
        l.kind = BoundaryEventKind::tangency;
        l.name = e.name;
        l.m = e.m;
        l.label = e.label;
        out.push_back(l);
        taken.push_back(false);
      }
      taken[best] = true;
      out[best].points.push_back({a2s[k], e.a3, e.b});
      next_open.push_back(best);
    }
    open = std::move(next_open);
  }
  return out;
}

inline std::optional<TangencyHit> nearest_tangency(double a2, double a3, const Ratio& n, double tolerance) {
  using namespace boundary_set_detail;
  if (!(tolerance > 0) || !(a2 > 0 && a2 < Constants<double>::pi()) || !(a3 > 0 && a3 < Constants<double>::pi()))
    return std::nullopt;
  const Real sa2 = std::sin(static_cast<Real>(a2)), ca2 = std::cos(static_cast<Real>(a2));
  std::optional<TangencyHit> best;
  for (int label = 0; label < 2; ++label) {
    const Sample s = sample(sa2, ca2, a3, n, label);
    if (!s.ok || !(s.dG != 0)) continue;
    const Real m = std::nearbyint(s.G);
    // A first-order estimate of the distance, then a bracketed solve if it is within reach.
    if (std::abs((s.G - m) / s.dG) > 4 * static_cast<Real>(tolerance) + 1e-15L) continue;
    const Real w = 8 * static_cast<Real>(tolerance) + 1e-14L;
    const Sample lo = sample(sa2, ca2, a3 - w, n, label), hi = sample(sa2, ca2, a3 + w, n, label);
    if (!lo.ok || !hi.ok || (lo.G - m < 0) == (hi.G - m < 0)) continue;
    const Sample r = solve(sa2, ca2, n, label, m, lo, hi);
    const double margin = static_cast<double>(static_cast<Real>(a3) - r.a3);
    if (std::abs(margin) > tolerance) continue;
    // Not the near-cusp loop of a pitch cone (see header).
    const RootFunction<Real> h(sa2, ca2, std::sin(r.a3), std::cos(r.a3), n);
    const Real a_p = std::atan2(sa2, ca2 + static_cast<Real>(n.p()) / static_cast<Real>(n.q()));
    const Real pi = RootFunction<Real>::pi();
    if ((std::abs(r.a3 - a_p) < 1e-8L && m == h.g_at_pi()) || (std::abs(r.a3 - (pi - a_p)) < 1e-8L && m == h.g_at_0()))
      continue;
    if (!best || std::abs(margin) < std::abs(best->margin))
      best = TangencyHit{static_cast<double>(r.a3), margin, static_cast<double>(r.b), static_cast<std::int64_t>(m), label};
  }
  return best;
}

}  // namespace sphtroch
