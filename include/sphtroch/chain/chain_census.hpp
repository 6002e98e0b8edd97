// sphtroch/chain/chain_census.hpp — the certified census of a rotation chain's curve
// (core/rotation_chain.hpp), any number of stages: every node (a point two or more branches pass
// through) and every cusp, by interval branch and bound with the Krawczyk test. Independent of
// any polyline: the second census beside the exact crossings of a sampled chain
// (`sphtroch chain trace | sphtroch crossings`), and for k = 2 a third one beside the gear
// train's root and polyline censuses (tests/chain/test_chain_census.cpp checks all of them).
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   const sphtroch::ChainCensus c = sphtroch::chain_census(chain);
//   c.certified;          // every node and cusp found, each once (else c.why says what is left)
//   c.nodes, c.cusps;     // Node and Cusp of core/node.hpp; params are values of s in [0, period)
//
// Nodes are the solutions of P(s) = P(t), s != t modulo the period T. The period [0, T) is cut
// into arcs of width w = kChainArcTurn / Omega (Omega = sum |N_i| bounds |P'|, so the point moves
// at most kChainArcTurn rad along an arc), each with an enclosure of P over it.
//  - Arcs two or more apart whose enclosures meet (found by a sweep) are searched as boxes of
//    (s, t): a box is dropped when P(S) and P(T) cannot meet, or when its Krawczyk operator misses
//    it; it holds exactly one node when the operator maps it into its interior. The square system
//    is two coordinates of P(s) - P(t): the third, largest, has the same sign on both sides over
//    the box, so it agrees too (both are unit vectors).
//  - Within two neighbouring arcs W: (P(s) - P(t)) / (s - t) lies in the convex hull of P'(W),
//    so when the box enclosing P'(W) misses 0 no two points of W coincide. Where it does not, the
//    pairs (t, t + h), h in (0, 2w], are searched the same way in (t, h); a box touching the
//    diagonal h = 0 is dropped when the hull of P' over it misses 0.
//  - A cusp is where P' = omega x P vanishes. The near-cusp test minimises |P'| (Gauss-Newton)
//    where the diagonal cannot be cleared, and reports a cusp at s* when |P'(s*)| <=
//    kChainCuspResolution Omega (enclosed): within that resolution the curve has a cusp there (as
//    GearTrain's census reports one near a pitch cone, at its own resolution). Pairs with both
//    parameters within kChainCuspZone / Omega of s* are the cusp's own loop, not resolved and not
//    counted (ChainCensus::cusp_zone).
//  - Roots on a box's edge: a box narrower than kChainInflateWidth that is still undecided gets a
//    Newton root x* and the Krawczyk test on x* +- rho; passing, the root is known with a region
//    U where it is the only one, and boxes inside U are dropped.
//  - Boxes left undecided (two branches nearly parallel where they meet) are resolved by
//    chain_tangency.hpp: none, two crossings, or a tangency within the rounding of double.
// Nodes are assembled from the branch pairs: two parameters are one branch when their certified
// enclosures overlap (Krawczyk's, a few ulp wide), distinct however close when they do not. A
// point with m branches must show m (m - 1) / 2 pairs, and a node of three or more branches is
// not certified: its pairs' roots agreeing to rounding does not prove one point (a triple point
// is not generic; m (m - 1) / 2 crossings closer than double resolves look the same). Every pair
// isolated by Krawczyk is a transversal crossing; a node whose pairs all touch is a tangency,
// listed but not certified either (two branches touching within the rounding of double may be
// two crossings closer than double resolves: near-coaxial chains make them). Boxes still
// undecided: not certified.
// Cost: O(arcs + candidate arc pairs + boxes); arcs are refused beyond kMaxChainArcs (InvalidInput
// naming "rates"), boxes stop at max_boxes (then not certified).
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_census.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/chain/chain_box_search.hpp"
#include "sphtroch/chain/chain_tangency.hpp"
#include "sphtroch/census/node_assembly.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/rotation_chain.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace sphtroch {

/// How far (radians) the point moves along one arc at most.
constexpr double kChainArcTurn = 0.03;
/// A near-cusp whose least speed |P'| is at most this times Omega is a cusp within resolution:
/// its loop, if any, is too thin for double (the Jacobian of its branch pairs is ~h^3, h ~
/// sqrt(24 |P'| / |P'''|)), so it is not resolved. GearTrain's root census, in long double and
/// from closed forms, resolves loops down to kCuspResolution of a pitch cone (core/pitch_cone.hpp).
constexpr double kChainCuspResolution = 1e-7;
/// Half-width, times 1 / Omega in s, of the region around a cusp whose pairs are the cusp's loop
/// (the loop of a near-cusp within kChainCuspResolution spans h below 2e-3 / Omega).
constexpr double kChainCuspZone = 1e-2;
/// The census refuses chains needing more arcs than this (period T times Omega / kChainArcTurn).
constexpr std::size_t kMaxChainArcs = 400000;
/// A family's census (chain_census_over) gives up on a box narrower than this times the range.
constexpr double kChainFamilyBoxWidth = 1e-2;
/// A family's census stops (not certified) after this many undecided boxes.
constexpr std::size_t kChainFamilyUndecided = 64;

/// Why a census whose branches touch within rounding (chain_tangency.hpp) is not certified.
inline const char* const kTouchWithinRounding =
    "two branches touch within the rounding of double: one tangency, or two crossings closer than double resolves";

struct ChainCensus {
  std::vector<Node> nodes;  // params: s of each branch in [0, period), ascending; nodes by first param
  std::vector<Cusp> cusps;  // param: s in [0, period); speed |P'| there (<= kChainCuspResolution Omega)
  bool certified = true;
  std::string why;          // what is left when not certified
  bool multiple_unproved = false;  // a node of three or more branches whose pairs agree to rounding: a triple point
                                   // or crossings closer than double tells (not certified; chain boundaries' events)
  bool touching_unproved = false;  // two branches touch within the rounding of double: a tangency, or two crossings
                                   // closer than double tells (not certified; chain boundaries' events)
  std::string method = "interval branch and bound with the Krawczyk test (chain/chain_census.hpp)";
  double period = 0;        // 2 pi L / g
  double cusp_zone = 0;     // kChainCuspZone / Omega: half-width in s of each cusp's unresolved region
  std::size_t arcs = 0, arc_pairs = 0, boxes = 0, undecided = 0;
};


namespace chain_census_detail {


/// An arc of the period: its interval of s and enclosures of P and P' over it.
struct Arc {
  Interval s;
  IntervalVec3 point, velocity;
};

/// Omega = sum |N_i|: |P'| <= |omega| <= Omega.
inline double total_rate(const RotationChain& chain) {
  double omega = 0;
  for (const ChainStage& s : chain.stages()) omega += std::fabs(s.rate.value());
  return omega;
}

/// The same curve with no coaxial neighbours (twist 0 or pi between two joints) and no last joint
/// on the tool axis, and whether that curve is -P: Rz(a) Rx(0) Rz(b) = Rz(a + b);
/// Rz(a) Rx(pi) Rz(b) Rx(A) = Rz(a - b + pi) Rx(pi - A) Rz(pi) (the last Rz(pi) into the next
/// phase); a last Rx(0) z = z drops the last joint, a last Rx(pi) z = -z too and negates P.
/// With `varied`, that parameter is followed through the rules as the widening's signs (a varied
/// twist is never merged: its range is not just 0 or pi); a varied phase of a dropped last joint
/// leaves the widening all 0 (it turns the tool about itself). Throws InvalidInput ("twists")
/// when nothing moves the tool axis.
struct ReducedChain {
  std::vector<ChainStage> stages;
  bool negated = false;
  ChainWidening widening;  // signs per reduced stage (offset left 0)
};
inline ReducedChain reduced_chain(const RotationChain& chain, const ChainVary* varied = nullptr) {
  const double pi = Constants<double>::pi();
  const std::size_t k = chain.size();
  ReducedChain r{chain.stages(), false, {std::vector<int>(k, 0), std::vector<int>(k, 0), Interval(0.0)}};
  if (varied) (varied->twist ? r.widening.twist_sign : r.widening.phase_sign)[varied->stage - 1] = 1;
  std::vector<int>& ts = r.widening.twist_sign;
  std::vector<int>& ps = r.widening.phase_sign;
  const auto coaxial = [&](std::size_t i) { return ts[i] == 0 && (r.stages[i].twist == 0 || r.stages[i].twist == pi); };
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<ChainStage>& st = r.stages;
    while (!st.empty() && coaxial(st.size() - 1)) {
      r.negated ^= st.back().twist == pi;
      st.pop_back(), ts.pop_back(), ps.pop_back();
      changed = true;
    }
    for (std::size_t i = 0; i + 1 < st.size() && !changed; ++i) {
      if (!coaxial(i)) continue;
      const ChainRate a = st[i].rate, b = st[i + 1].rate;
      const bool flip = st[i].twist == pi;
      const std::int64_t sign = flip ? -1 : 1;
      st[i].rate = ChainRate(a.p() * b.q() + sign * b.p() * a.q(), a.q() * b.q());
      st[i].phase = flip ? st[i].phase - st[i + 1].phase + pi : st[i].phase + st[i + 1].phase;
      st[i].twist = flip ? pi - st[i + 1].twist : st[i + 1].twist;
      ps[i] += static_cast<int>(sign) * ps[i + 1];
      ts[i] = static_cast<int>(sign) * ts[i + 1];
      if (flip && i + 2 < st.size()) st[i + 2].phase += pi;
      st.erase(st.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      ts.erase(ts.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      ps.erase(ps.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      changed = true;
    }
  }
  const bool moves = std::any_of(r.stages.begin(), r.stages.end(), [](const ChainStage& s) { return !s.rate.is_zero(); });
  if (!moves)
    throw InvalidInput("twists", chain.twists_text(), "the tool axis does not move: every joint that turns is coaxial with it (rates " + chain.rates_text() + ")",
                       "a chain whose tool axis moves (a turning joint not on the tool axis)");
  return r;
}

/// The arcs of [0, T]: `count` of width T / count, the last reaching past T by rounding.
inline std::vector<Arc> chain_arcs(const ChainEnclosure& e, double period, std::size_t count) {
  std::vector<Arc> arcs(count);
  const double width = period / static_cast<double>(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double lo = static_cast<double>(i) * width;
    const double hi = i + 1 == count ? period * (1 + 4 * std::numeric_limits<double>::epsilon()) : static_cast<double>(i + 1) * width;
    const ChainJet j = e.sharp_jet(Interval(lo, hi));
    arcs[i] = {Interval(lo, hi), j.point, j.velocity};
  }
  return arcs;
}

/// Pairs i < j of arcs that are not neighbours (mod count) and whose enclosures of P meet: a
/// sweep over the x extents. Stops after max_pairs + 1 (each pair costs a box at least).
inline std::vector<std::pair<std::size_t, std::size_t>> meeting_arc_pairs(const std::vector<Arc>& arcs, std::size_t max_pairs) {
  const std::size_t n = arcs.size();
  std::vector<std::size_t> order(n), active;
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return arcs[a].point[0].inf() < arcs[b].point[0].inf(); });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const std::size_t i : order) {
    const double lo = arcs[i].point[0].inf();
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t a) { return arcs[a].point[0].sup() < lo; }), active.end());
    for (const std::size_t a : active) {
      const std::size_t d = a > i ? a - i : i - a;
      if (d > 1 && d + 1 < n && boxes_meet(arcs[a].point, arcs[i].point)) pairs.emplace_back(std::min(a, i), std::max(a, i));
      if (pairs.size() > max_pairs) return pairs;
    }
    active.push_back(i);
  }
  return pairs;
}

/// A cusp's region: s* and the half-width r of its unresolved zone.
struct CuspZone {
  double s = 0, speed = 0;
};

/// Whether x lies within r of a zone's s* modulo T.
inline bool near_zone(double x, const std::vector<CuspZone>& zones, double r, double period) {
  for (const CuspZone& z : zones) {
    const double d = std::remainder(x - z.s, period);
    if (std::fabs(d) <= r) return true;
  }
  return false;
}

/// Whether [lo, hi] lies within r of one zone's s* (modulo T).
inline bool inside_zone(double lo, double hi, const std::vector<CuspZone>& zones, double r, double period) {
  for (const CuspZone& z : zones) {
    const double d = std::remainder(lo - z.s, period);
    if (d >= -r && d + (hi - lo) <= r) return true;
  }
  return false;
}

/// Gauss-Newton for the minimum of |P'|^2 from s0 within [lo, hi]; a cusp when the enclosure of
/// |P'(s*)| is at most kChainCuspResolution Omega.
inline std::optional<CuspZone> near_cusp(const ChainCurve<double>& curve, const ChainEnclosure& e, double s0, double lo, double hi,
                                         double omega) {
  double s = s0;
  for (int it = 0; it < 60; ++it) {
    const Vector3d v = curve.velocity(s), a = curve.acceleration(s);
    const double aa = a.squaredNorm();
    if (!(aa > 0)) break;
    const double step = v.dot(a) / aa;
    s = std::clamp(s - step, lo, hi);
    if (std::fabs(step) < 1e-17 * std::max(1.0, std::fabs(s))) break;
  }
  const IntervalVec3 v = e.jet(Interval(s)).velocity;
  const Interval speed = CGAL::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(speed.sup() <= kChainCuspResolution * omega)) return std::nullopt;
  return CuspZone{s, speed.sup()};
}

/// What the searches found, before assembly: branch pairs (s, t) and cusps.
/// A found root as census/node_assembly.hpp's BranchPair: parameters a, b with their certified
/// enclosures (over a family too); touching: the two branches only touch.
inline BranchPair chain_pair(double a, double b, bool touching, const Interval& a_range, const Interval& b_range) {
  BranchPair p;
  p.t1 = a;
  p.t2 = b;
  p.kind = touching ? NodeKind::tangency : NodeKind::crossing;
  p.t1_range = {a_range.inf(), a_range.sup()};
  p.t2_range = {b_range.inf(), b_range.sup()};
  return p;
}

struct Findings {
  std::vector<BranchPair> pairs;
  std::vector<CuspZone> cusps;
  Search work;
};

/// The window of arcs i and i + 1 (mod count) when the hull of P' over it does not clear it: the
/// pairs (t, t + h), t in arc i, t + h up to the window's end, searched in (t, h), diagonal boxes
/// probed for a cusp once narrower than the zone.
inline void search_window(const std::vector<Arc>& arcs, std::size_t i, const ChainEnclosure& e, const ChainCurve<double>& curve,
                          double omega, double period, double zone, Findings& f) {
  const Arc& a = arcs[i];
  const Arc& b = arcs[(i + 1) % arcs.size()];
  const double end = a.s.sup() + (b.s.sup() - b.s.inf());
  const NearPairs sys{&e};
  const auto drop = [&](const Box2& box) {
    if (box.u.inf() + box.v.inf() >= end) return true;  // t + h beyond the window: the far pairs' part
    const auto absorbed = [&] { return inside_zone(box.u.inf(), box.u.sup() + box.v.sup(), f.cusps, zone, period); };
    if (absorbed()) return true;
    const double w = box.u.sup() - box.u.inf();
    if (box.v.inf() <= 0 && w <= zone && w > zone / 4 && !near_zone(mid(box.u), f.cusps, zone, period)) {
      if (const std::optional<CuspZone> c = near_cusp(curve, e, mid(box.u), a.s.inf(), end, omega)) f.cusps.push_back(*c);
      return absorbed();
    }
    return false;
  };
  std::vector<FoundRoot> roots;
  search_box(sys, Box2{a.s, Interval(0.0, end - a.s.inf())}, drop, f.work, roots);
  for (const FoundRoot& r : roots)
    if (r.v > 0) f.pairs.push_back(chain_pair(r.u, r.u + r.v, false, r.enclosure.u, r.enclosure.u + r.enclosure.v));
}



/// The cusps, reduced mod T, each once, by parameter.
inline std::vector<Cusp> assemble_cusps(const ChainCurve<double>& curve, const std::vector<CuspZone>& zones, double period, double zone,
                                        bool negated) {
  std::vector<Cusp> cusps;
  for (const CuspZone& z : zones) {
    const double s = reduce_param(z.s, period);
    if (std::any_of(cusps.begin(), cusps.end(), [&](const Cusp& c) { return std::fabs(std::remainder(c.param - s, period)) <= zone; })) continue;
    cusps.push_back({(negated ? -1.0 : 1.0) * curve.point(s), s, z.speed});
  }
  std::sort(cusps.begin(), cusps.end(), [](const Cusp& x, const Cusp& y) { return x.param < y.param; });
  return cusps;
}

/// Clusters of undecided boxes (hulls of boxes within 1e-6 of each other), each given to
/// resolve_tangency on growing regions around it; a resolved cluster's roots replace the
/// search's roots there and its boxes are no longer undecided.
inline void resolve_undecided(const ChainEnclosure& e, std::vector<Box2> boxes, std::vector<FoundRoot>& roots, Search& work) {
  std::sort(boxes.begin(), boxes.end(), [](const Box2& x, const Box2& y) { return x.u.inf() < y.u.inf(); });
  std::vector<std::pair<Box2, std::size_t>> clusters;
  for (const Box2& b : boxes) {
    const double gap = 1e-6 * std::max(1.0, std::fabs(b.u.inf()) + std::fabs(b.v.inf()));
    auto near = std::find_if(clusters.begin(), clusters.end(), [&](const std::pair<Box2, std::size_t>& c) {
      return b.u.inf() <= c.first.u.sup() + gap && b.v.inf() <= c.first.v.sup() + gap && b.v.sup() >= c.first.v.inf() - gap;
    });
    if (near == clusters.end()) { clusters.push_back({b, 1}); continue; }
    Box2& h = near->first;
    h = {Interval(std::min(h.u.inf(), b.u.inf()), std::max(h.u.sup(), b.u.sup())), Interval(std::min(h.v.inf(), b.v.inf()), std::max(h.v.sup(), b.v.sup()))};
    ++near->second;
  }
  for (const auto& [hull, count] : clusters) {
    const double w = std::max({hull.u.sup() - hull.u.inf(), hull.v.sup() - hull.v.inf(), 1e-9});
    for (const double f : {4.0, 16.0, 64.0, 256.0}) {
      const Box2 region{Interval(hull.u.inf() - f * w, hull.u.sup() + f * w), Interval(hull.v.inf() - 4 * f * w, hull.v.sup() + 4 * f * w)};
      const std::optional<TangencyVerdict> v = resolve_tangency(e, region);
      if (!v) continue;
      roots.erase(std::remove_if(roots.begin(), roots.end(), [&](const FoundRoot& r) {
                    return r.u >= region.u.inf() && r.u <= region.u.sup() && r.v >= region.v.inf() && r.v <= region.v.sup(); }),
                  roots.end());
      roots.insert(roots.end(), v->pairs.begin(), v->pairs.end());
      work.undecided -= count;
      break;
    }
  }
}

/// Runs the searches: every window not cleared by its hull, every meeting pair of far arcs.
/// `family_width` > 0 (a family's census, its range's width): its roots move by about 16 times
/// that over the range (at most 1e-3), so Newton and inflation start at 256 times it (at most
/// 1e-2), inflation tries boxes from 8 times the spread, boxes narrower than kChainFamilyBoxWidth
/// times the range are undecided (chain_tangency.hpp may still decide them), and more than
/// kChainFamilyUndecided of them end the search (not certified).
inline Findings search_chain(const RotationChain& chain, const std::vector<Arc>& arcs, const ChainEnclosure& e, double omega, double zone,
                             std::size_t max_boxes, std::size_t& arc_pairs, double family_width = 0) {
  Findings f;
  f.work.max_boxes = max_boxes;
  if (family_width > 0) {
    f.work.min_width = std::max(kChainMinBoxWidth, kChainFamilyBoxWidth * family_width);
    f.work.inflate_width = std::clamp(256 * family_width, kChainInflateWidth, 1e-2);
    f.work.root_spread = std::min(16 * family_width, 1e-3);
    f.work.max_undecided = kChainFamilyUndecided;
  }
  const ChainCurve<double> curve(chain);
  const double period = chain.period();
  for (std::size_t i = 0; i < arcs.size() && !f.work.out_of_budget; ++i)
    if (!excludes_zero(hull(arcs[i].velocity, arcs[(i + 1) % arcs.size()].velocity)))
      search_window(arcs, i, e, curve, omega, period, zone, f);
  const std::vector<std::pair<std::size_t, std::size_t>> far = meeting_arc_pairs(arcs, max_boxes);
  arc_pairs = far.size();
  if (far.size() > max_boxes) f.work.out_of_budget = true;
  const FarPairs sys{&e};
  const auto keep = [](const Box2&) { return false; };
  std::vector<FoundRoot> roots;
  for (const auto& [i, j] : far) {
    if (f.work.out_of_budget) break;
    std::vector<FoundRoot> local;
    std::vector<Box2> undecided;
    search_box(sys, Box2{arcs[i].s, arcs[j].s}, keep, f.work, local, &undecided);
    if (!undecided.empty()) resolve_undecided(e, undecided, local, f.work);
    roots.insert(roots.end(), local.begin(), local.end());
  }
  for (const FoundRoot& r : roots) f.pairs.push_back(chain_pair(r.u, r.v, r.tangency, r.enclosure.u, r.enclosure.v));
  return f;
}

}  // namespace chain_census_detail

namespace chain_census_detail {

/// The arcs a census of this (reduced) chain cuts its period into: T Omega / kChainArcTurn.
inline double arcs_needed(const RotationChain& reduced) { return std::ceil(reduced.period() * total_rate(reduced) / kChainArcTurn); }

/// Whether two parameter ranges meet modulo T (padded by 1e-12 max(1, T) for the reduction).
inline bool ranges_meet(const ParamEnclosure& x, const ParamEnclosure& y, double period) {
  const double pad = 1e-12 * std::max(1.0, period);
  const double shift = period * std::round((0.5 * (x.lo + x.hi) - 0.5 * (y.lo + y.hi)) / period);  // y's copy nearest x
  return y.lo + shift - pad <= x.hi && x.lo <= y.hi + shift + pad;
}

/// Whether two pairs' ranges meet branch by branch, in either order: the same pair.
inline bool same_pair(const BranchPair& x, const BranchPair& y, double period) {
  return (ranges_meet(x.t1_range, y.t1_range, period) && ranges_meet(x.t2_range, y.t2_range, period)) ||
         (ranges_meet(x.t1_range, y.t2_range, period) && ranges_meet(x.t2_range, y.t1_range, period));
}

/// The pairs with each found twice kept once (a family's roots found from two boxes differ by
/// their spread over the family, wider than a point's enclosure).
inline std::vector<BranchPair> distinct_pairs(std::vector<BranchPair> pairs, double period) {
  std::vector<BranchPair> out;
  for (const BranchPair& p : pairs)
    if (std::none_of(out.begin(), out.end(), [&](const BranchPair& q) { return same_pair(p, q, period); })) out.push_back(p);
  return out;
}

/// Whether two different pairs have one branch parameter range in common (mod T) but not both
/// (both: the same pair found twice): over a family, two of its nodes may then meet (three
/// branches through one point, a triple point). A sweep over the ranges reduced to [0, T).
inline bool pairs_may_meet(const std::vector<BranchPair>& pairs, double period) {
  struct Range {
    double lo, hi;
    std::size_t pair;
  };
  std::vector<Range> ranges;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    for (const ParamEnclosure& r : {pairs[i].t1_range, pairs[i].t2_range}) {
      const double shift = period * std::floor(r.lo / period);
      const double lo = r.lo - shift, hi = r.hi - shift;
      ranges.push_back({lo, hi, i});
      if (hi > period) ranges.push_back({lo - period, hi - period, i});
    }
  std::sort(ranges.begin(), ranges.end(), [](const Range& x, const Range& y) { return x.lo < y.lo; });
  const double pad = 1e-12 * std::max(1.0, period);
  for (std::size_t k = 0; k < ranges.size(); ++k)
    for (std::size_t m = k + 1; m < ranges.size() && ranges[m].lo <= ranges[k].hi + pad; ++m)
      if (ranges[m].pair != ranges[k].pair && !same_pair(pairs[ranges[m].pair], pairs[ranges[k].pair], period)) return true;
  return false;
}

/// The census of a reduced chain (its stages at the family's middle) with the enclosures of the
/// whole family `r.widening` (offset set): certified only when every box was decided for all of it.
inline ChainCensus census_of_reduced(const RotationChain& chain, const ReducedChain& reduced, std::size_t max_boxes, bool family) {
  const RotationChain curve_chain(reduced.stages);
  ChainCensus out;
  const double omega = total_rate(curve_chain), period = curve_chain.period();
  const double arcs = arcs_needed(curve_chain);
  if (!(arcs <= static_cast<double>(kMaxChainArcs)))
    throw InvalidInput("rates", chain.rates_text(), "the census needs " + number_text(arcs) + " arcs (period times sum |N_i| / " +
                       number_text(kChainArcTurn) + ")", "chains whose period 2 pi L / g times sum |N_i| is at most " +
                       number_text(kMaxChainArcs * kChainArcTurn));
  out.period = period;
  out.cusp_zone = kChainCuspZone / omega;
  out.arcs = std::max<std::size_t>(3, static_cast<std::size_t>(arcs));
  Findings f;
  {
    const RoundingGuard upward;
    const ChainEnclosure e(curve_chain, reduced.widening);
    const std::vector<Arc> arc_list = chain_arcs(e, period, out.arcs);
    const double range = reduced.widening.offset.sup() - reduced.widening.offset.inf();
    f = search_chain(curve_chain, arc_list, e, omega, out.cusp_zone, max_boxes, out.arc_pairs, family ? range : 0.0);
  }
  out.boxes = f.work.boxes;
  out.undecided = f.work.undecided;
  const ChainCurve<double> curve(curve_chain);
  std::vector<BranchPair> pairs;
  for (const BranchPair& p : f.pairs)
    if (!inside_zone(std::min(p.t1, p.t2), std::max(p.t1, p.t2), f.cusps, out.cusp_zone, period)) pairs.push_back(p);
  if (family) pairs = distinct_pairs(std::move(pairs), period);
  out.nodes = assemble_nodes_of_branches(curve, pairs, period, reduced.negated, out.why);
  out.cusps = assemble_cusps(curve, f.cusps, period, out.cusp_zone, reduced.negated);
  if (family && f.work.out_of_budget && f.work.boxes <= max_boxes) out.why = "boxes stayed undecided over the range";
  else if (f.work.out_of_budget) out.why = "the search stopped at its bound of " + std::to_string(max_boxes) + " boxes";
  else if (f.work.undecided > 0) out.why = std::to_string(f.work.undecided) + " boxes stayed undecided at the resolution of double (two branches touching?)";
  if (family && out.why.empty() && std::any_of(out.nodes.begin(), out.nodes.end(), [](const Node& n) { return n.tangency_pairs > 0; }))
    out.why = "two branches may touch within the range";
  if (family && out.why.empty() && pairs_may_meet(pairs, period)) out.why = "two nodes may meet within the range (a triple point)";
  if (!family && out.why.empty() && std::any_of(out.nodes.begin(), out.nodes.end(), [](const Node& n) { return n.tangency_pairs > 0; }))
    out.why = kTouchWithinRounding;  // its nodes are listed (kind tangency); their count is not proved
  out.certified = out.why.empty();
  out.multiple_unproved = !out.certified && out.why.find("is not proved one point") != std::string::npos;
  out.touching_unproved = !out.certified && out.why == kTouchWithinRounding;
  return out;
}

}  // namespace chain_census_detail

/// The certified census of the chain's curve (see header). Throws InvalidInput ("rates") when the
/// period needs more than kMaxChainArcs arcs, ("twists") when the tool axis does not move.
inline ChainCensus chain_census(const RotationChain& chain, std::size_t max_boxes = kMaxChainBoxes) {
  return chain_census_detail::census_of_reduced(chain, chain_census_detail::reduced_chain(chain), max_boxes, false);
}

/// The arcs chain_census cuts the chain's period into (its cost grows with them).
inline double chain_census_arcs(const RotationChain& chain) {
  return chain_census_detail::arcs_needed(RotationChain(chain_census_detail::reduced_chain(chain).stages));
}

/// Whether varying `vary`'s twist or phase (at the chain's value) changes the curve: false for
/// the phase of a last joint on the tool axis (after merging coaxial joints, reduced_chain).
inline bool varies_curve(const RotationChain& chain, const ChainVary& vary) {
  const ChainWidening w = chain_census_detail::reduced_chain(chain, &vary).widening;
  const auto any = [](const std::vector<int>& v) { return std::any_of(v.begin(), v.end(), [](int x) { return x != 0; }); };
  return any(w.twist_sign) || any(w.phase_sign);
}

/// The chain with the varied parameter set to `value` (a twist clamped to [0, pi]).
inline RotationChain chain_at(const RotationChain& chain, const ChainVary& vary, double value) {
  std::vector<ChainStage> stages = chain.stages();
  ChainStage& s = stages[vary.stage - 1];
  (vary.twist ? s.twist : s.phase) = vary.twist ? std::clamp(value, 0.0, Constants<double>::pi()) : value;
  return RotationChain(stages);
}

/// The curve a family's enclosures are built on at one value: the chain at `value` with coaxial
/// joints merged (its curve is the chain's, or its negation: equations in P = P' = 0 and P(s) =
/// P(t) keep their roots), and the varied parameter's signs per merged stage (offset 0).
struct FamilyCurve {
  RotationChain curve;
  ChainWidening signs;
};
inline FamilyCurve family_curve(const RotationChain& chain, const ChainVary& vary, double value) {
  chain_census_detail::ReducedChain r = chain_census_detail::reduced_chain(chain_at(chain, vary, value), &vary);
  return {RotationChain(r.stages), r.widening};
}

/// One census for the whole family `range` (the chain's varied parameter over [range.lo,
/// range.hi]), or not certified: when `certified`, every chain of the range has these nodes (by
/// branch count, all transversal crossings) and cusps; the parameters reported are the middle
/// chain's. Boxes narrower than kChainFamilyBoxWidth times the range are undecided, and more than
/// kChainFamilyUndecided of them end the search.
/// REQUIRES range.lo < range.hi, a twist range inside (0, pi).
inline ChainCensus chain_census_over(const RotationChain& chain, const ChainVary& range, std::size_t max_boxes = kMaxChainBoxes) {
  namespace d = chain_census_detail;
  const double middle = 0.5 * (range.lo + range.hi);
  const RotationChain at_middle = chain_at(chain, range, middle);
  d::ReducedChain reduced = d::reduced_chain(at_middle, &range);
  {
    const RoundingGuard upward;
    reduced.widening.offset = Interval((Interval(range.lo) - Interval(middle)).inf(), (Interval(range.hi) - Interval(middle)).sup());
  }
  return d::census_of_reduced(at_middle, reduced, max_boxes, true);
}

}  // namespace sphtroch
