// sphtroch/chain/chain_family_events.hpp — where a rotation chain's census changes as
// any one of its twists or phases varies over a range: `sphtroch chain boundaries --vary
// NAME:LO:HI` for every family (chain/chain_events.hpp computes the families that have closed
// forms, and is used for them).
//
//   const sphtroch::RotationChain chain({{1.2, sphtroch::ChainRate(1), 0.0}, {0.9, sphtroch::ChainRate(2), 0.0},
//                                        {0.7, sphtroch::ChainRate(-3), 0.0}});
//   const sphtroch::ChainEvents e = sphtroch::chain_family_events(chain, sphtroch::parse_chain_vary("A3:0.9:0.95", 3));
//   e.certified;   // every event of the range found, each within e.accuracy
//   e.events;      // BoundaryEvent: kind, value (its a3 field), node points and cusps below and above
//
// Method (ours; docs/chains.md "Events along a family").
//  1. Slabs: the range is swept by slabs [a, b], each given one census for the whole slab
//     (chain_census_over: the interval enclosures hold for every value of the slab, so a box the
//     Krawczyk test isolates holds exactly one branch pair for every value and a box it clears
//     none; touching pairs and pairs sharing a branch's range are not accepted). A certified slab
//     has one census throughout: no event in it. After a certified slab the next is tried twice
//     as wide, after a failed one half as wide, down to kChainEventWidth, where it stays failed.
//  2. Brackets: each run of failed slabs, with the certified counts on either side. The censuses
//     at single values (chain_census) inside it are bisected to kChainChangeWidth; a middle whose
//     census is not certified stops the bisection (the change is known to that width), a middle
//     with counts of neither side is a second change (both halves are searched). With the same
//     counts on both sides, kChainBracketProbes values are probed first. Changes within
//     kChainBandWidth, the first into a band state (merge_bands), are one event: the census
//     reports a cusp where |P'| <= kChainCuspResolution Omega (a band around a cusp birth), one
//     node of three branches around a triple point, one touching node at a self-tangency.
//  3. Kinds, from the counts and the census at the event's value: a cusp (P parallel to omega:
//     the cusps differ, or the value shows one more); the same branch pairs on both sides (or a
//     node of three branches at the value): a triple point, when the census at the middle shows
//     three nodes within kChainTripleDistance times the bracket's width (else the bracket is no
//     event: the censuses at its ends and at the probes agree and nothing is about to meet; a
//     bracket wider than kChainQuietWidth is then not certified: events that cancel could hide);
//     otherwise a self-tangency.
//  4. Roots: each event certified as the root of its square system (chain_event_roots.hpp); its
//     value is then the root's (ChainEvents::roots; else the bracket's middle).
// Certified: outside the brackets the census is constant (ChainEvents::uncovered is the
// brackets' total width); the counts either side of each event are certified censuses. Known
// limit: inside a bracket, changes closer than one bisection step that cancel are not seen.
// A range end whose census shows a band state (a cusp, a node of three branches, two branches
// touching) lies at an event or within its resolution band: not certified (move the end).
// Twist ranges are searched within [kChainTwistMargin, pi - kChainTwistMargin]: at 0 and pi two
// joints become coaxial and the chain is another one (its period and census jump).
// Phase ranges lie within [-4 pi, 4 pi] and are at most 2 pi long (the family repeats every 2 pi;
// InvalidInput "vary" beyond). Widths are absolute (twists lie in [0, pi]).
// Cost: one census per slab (about 1 to 3 ms for three stages of rates of height <= 3), each
// stopped at kFamilyBoxesPerArc boxes per arc, plus ~40 censuses per bracket; at most
// kFamilyWork / (arcs x stages) slabs, at most kMaxFamilySlabs (then not certified, `why` says
// so); chains allowing fewer than kMinFamilySlabs are refused up front (InvalidInput "rates").
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_family_events.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/chain/chain_census.hpp"
#include "sphtroch/chain/chain_event_roots.hpp"
#include "sphtroch/chain/chain_events.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// Slabs are halved down to this width (radians): the brackets' least width.
constexpr double kChainEventWidth = 1e-5;
/// Bisection inside a bracket stops at this width (radians; values are within 4 pi of 0).
constexpr double kChainChangeWidth = 1e-12;
/// A bracket with the same counts on both sides is probed at this many values first.
constexpr std::size_t kChainBracketProbes = 8;
/// Two changes closer than this (radians) around a cusp are one cusp birth.
constexpr double kChainBandWidth = 1e-5;
/// A bracket with the same counts on both sides is a triple point when three nodes of the census
/// at its middle lie within this times its width (at least 1e-6) of each other.
constexpr double kChainTripleDistance = 10;
/// A bracket with the same counts on both sides, no change at its probes and no triple point is
/// no event when at most this wide (radians); wider, the search is not certified (events that
/// cancel could hide there).
constexpr double kChainQuietWidth = 1e-4;
/// Phase ranges lie within [-kChainPhaseBound, kChainPhaseBound] (radians).
constexpr double kChainPhaseBound = 4 * 3.141592653589793;
/// The widest slab is the range over this.
constexpr std::size_t kChainFirstSlabs = 16;
/// The work one search may do, in arcs times stages summed over its slab censuses (about 0.5 us
/// each: 3 stages of 1257 arcs take ~2 ms a census); the slab budget is this over one census's.
constexpr double kFamilyWork = 2.5e7;
/// At most this many slab censuses, and chains allowing fewer than kMinFamilySlabs are refused
/// (InvalidInput "rates").
constexpr std::size_t kMaxFamilySlabs = 20000;
constexpr std::size_t kMinFamilySlabs = 1000;
/// A slab census examines at most this many boxes per arc (then it fails: the slab is halved).
constexpr std::size_t kFamilyBoxesPerArc = 50;
/// Twist ranges are searched this far inside [0, pi] (see header).
constexpr double kChainTwistMargin = 1e-6;

namespace chain_family_detail {

/// What a census says that an event changes: node points, branch pairs, cusps.
struct CensusCounts {
  std::int64_t nodes = 0, pairs = 0, cusps = 0;
  bool multiple = false;  // a node of three or more branches
  bool touching = false;  // a node where two branches touch (within the rounding of double)
  bool operator==(const CensusCounts& o) const { return nodes == o.nodes && pairs == o.pairs && cusps == o.cusps; }
};

inline CensusCounts counts_of(const ChainCensus& c) {
  CensusCounts k;
  k.nodes = static_cast<std::int64_t>(c.nodes.size());
  k.cusps = static_cast<std::int64_t>(c.cusps.size());
  for (const Node& n : c.nodes) {
    k.pairs += static_cast<std::int64_t>(n.branches * (n.branches - 1) / 2);
    k.multiple = k.multiple || n.branches >= 3;
    k.touching = k.touching || n.tangency_pairs > 0;
  }
  return k;
}

/// A slab of the range and, when its census is certified, its counts.
struct Slab {
  double lo = 0, hi = 0;
  std::optional<CensusCounts> counts;
};

/// The slabs of [lo, hi], ascending: certified ones and failed ones no wider than the event
/// width. A sweep: a certified slab is kept and the next one tried twice as wide, a failed one
/// is tried again half as wide (down to the event width, where it is kept as failed).
/// `exhausted` when `budget` censuses were not enough.
inline std::vector<Slab> search_slabs(const RotationChain& chain, const ChainVary& vary, std::size_t budget, std::size_t max_boxes,
                                      bool& exhausted) {
  std::vector<Slab> done;
  const double widest = (vary.hi - vary.lo) / static_cast<double>(kChainFirstSlabs);
  double lo = vary.lo, width = widest;
  for (std::size_t censuses = 0; lo < vary.hi; ++censuses) {
    if (censuses == budget) {
      exhausted = true;
      return done;
    }
    const double least = kChainEventWidth;
    width = std::min(std::max(width, least), std::max(widest, least));
    const double hi = vary.hi - lo <= 1.5 * width ? vary.hi : lo + width;
    ChainVary range = vary;
    range.lo = lo, range.hi = hi;
    const ChainCensus c = chain_census_over(chain, range, max_boxes);
    if (!c.certified && width > least) {
      width *= 0.5;
      continue;
    }
    done.push_back({lo, hi, c.certified ? std::optional<CensusCounts>(counts_of(c)) : std::nullopt});
    lo = hi;
    if (c.certified) width *= 2;
  }
  return done;
}

/// An event's bracket [lo, hi] (a run of failed slabs) and the certified counts on either side
/// (none at a range end).
struct Bracket {
  double lo = 0, hi = 0;
  std::optional<CensusCounts> below, above;
};

/// Runs of failed slabs as brackets. `why` is set when two certified neighbours disagree.
inline std::vector<Bracket> brackets_of(const std::vector<Slab>& slabs, std::string& why) {
  std::vector<Bracket> out;
  for (std::size_t i = 0; i < slabs.size(); ++i) {
    const Slab& s = slabs[i];
    const Slab* before = i > 0 ? &slabs[i - 1] : nullptr;
    if (s.counts) {
      if (before && before->counts && !(*before->counts == *s.counts)) why = "two certified neighbouring ranges disagree";
      if (before && !before->counts) out.back().above = s.counts;
      continue;
    }
    if (before && !before->counts) out.back().hi = s.hi;
    else out.push_back({s.lo, s.hi, before ? before->counts : std::nullopt, std::nullopt});
  }
  return out;
}

/// Where a bracket's census changes: the value (to kChainChangeWidth), the counts just below
/// and just above.
struct Change {
  double lo = 0, hi = 0;
  CensusCounts below, above;
};

/// The counts of the census at one value of the family; none when it is not certified.
inline std::optional<CensusCounts> fixed_counts(const RotationChain& chain, const ChainVary& vary, double value) {
  const ChainCensus c = chain_census(chain_at(chain, vary, value));
  if (!c.certified) return std::nullopt;
  return counts_of(c);
}

/// The changes within [lo, hi] (counts cl at lo, ch at hi), by bisection: a middle with the counts
/// of one end moves that end; with other counts both halves are searched; a middle whose census
/// is not certified ends the bisection there (the change is known to [lo, hi]).
inline void bisect_changes(const RotationChain& chain, const ChainVary& vary, double lo, const CensusCounts& cl, double hi,
                           const CensusCounts& ch, std::vector<Change>& out, int depth = 0) {
  while (true) {
    const double m = 0.5 * (lo + hi);
    const bool narrow = !(lo < m && m < hi) || hi - lo <= kChainChangeWidth || depth > 200;
    const std::optional<CensusCounts> cm = narrow ? std::nullopt : fixed_counts(chain, vary, m);
    if (!cm) {
      out.push_back({lo, hi, cl, ch});
      return;
    }
    if (*cm == cl) lo = m;
    else if (*cm == ch) hi = m;
    else {
      bisect_changes(chain, vary, lo, cl, m, *cm, out, depth + 1);
      bisect_changes(chain, vary, m, *cm, hi, ch, out, depth + 1);
      return;
    }
  }
}

/// The counts at a range end (no certified slab beside the bracket); `why` when not certified.
inline CensusCounts end_counts(const RotationChain& chain, const ChainVary& vary, double value, std::string& why) {
  const std::optional<CensusCounts> c = fixed_counts(chain, vary, value);
  if (!c) why = "the census at " + vary.name() + " = " + number_text(value) + " is not certified";
  return c.value_or(CensusCounts{});
}

/// The changes of a bracket: bisection between its two sides; with the same counts on both
/// sides, kChainBracketProbes values inside are tried first, and a bracket where none differs
/// is one change at its middle (a triple point, or two events within it that cancel).
inline std::vector<Change> changes_of(const RotationChain& chain, const ChainVary& vary, const Bracket& b, std::string& why) {
  const CensusCounts below = b.below ? *b.below : end_counts(chain, vary, b.lo, why);
  const CensusCounts above = b.above ? *b.above : end_counts(chain, vary, b.hi, why);
  std::vector<Change> out;
  double lo = b.lo;
  CensusCounts at_lo = below;
  for (std::size_t k = 1; below == above && k < kChainBracketProbes; ++k) {
    const double x = b.lo + (b.hi - b.lo) * static_cast<double>(k) / static_cast<double>(kChainBracketProbes);
    const std::optional<CensusCounts> cx = fixed_counts(chain, vary, x);
    if (!cx || *cx == at_lo) continue;
    bisect_changes(chain, vary, lo, at_lo, x, *cx, out);
    lo = x, at_lo = *cx;
  }
  if (below == above && out.empty()) return {{b.lo, b.hi, below, above}};
  bisect_changes(chain, vary, lo, at_lo, b.hi, above, out);
  return out;
}

/// Whether counts `in` show an event in the census's resolution band (header) that `out` does
/// not: more cusps (|P'| <= kChainCuspResolution Omega), a node of three branches (three nodes
/// closer than the census's node tolerance are one), two branches touching within rounding.
inline bool band_state(const CensusCounts& in, const CensusCounts& out) {
  return in.cusps > out.cusps || (in.multiple && !out.multiple) || (in.touching && !out.touching);
}

/// An event's resolution band: changes closer than kChainBandWidth, the first into a band state
/// (band_state), are one change (a cusp birth's loop node may appear inside its band; a triple
/// point's three nodes are one node inside its band; two touching branches are one node).
inline std::vector<Change> merge_bands(const std::vector<Change>& changes) {
  std::vector<Change> out;
  for (const Change& c : changes) {
    if (!out.empty()) {
      Change& last = out.back();
      const bool band = c.lo - last.hi <= kChainBandWidth && last.above == c.below && last.above.multiple == c.below.multiple &&
                        last.above.touching == c.below.touching && band_state(last.above, last.below);
      if (band) {
        last.hi = c.hi, last.above = c.above;
        continue;
      }
    }
    out.push_back(c);
  }
  return out;
}

/// Whether the census shows three nodes within `distance` of each other, or a node of three
/// branches or more: a triple point near.
inline bool near_triple(const ChainCensus& c, double distance) {
  for (const Node& n : c.nodes)
    if (n.branches >= 3) return true;
  for (std::size_t a = 0; a < c.nodes.size(); ++a)
    for (std::size_t b = a + 1; b < c.nodes.size(); ++b) {
      if ((c.nodes[a].position - c.nodes[b].position).norm() > distance) continue;
      for (std::size_t m = b + 1; m < c.nodes.size(); ++m)
        if ((c.nodes[a].position - c.nodes[m].position).norm() <= distance && (c.nodes[b].position - c.nodes[m].position).norm() <= distance)
          return true;
    }
  return false;
}

/// The event of a change: its value (the middle), kind (header) and counts. None for a bracket
/// with the same counts on both sides whose middle shows no near triple point (no change seen;
/// `why` set when it is wider than kChainQuietWidth).
inline std::optional<BoundaryEvent> event_of(const RotationChain& chain, const ChainVary& vary, const Change& c, std::string& why) {
  BoundaryEvent e;
  e.a3 = 0.5 * (c.lo + c.hi);
  e.a3_precise = e.a3;
  e.nodes_below = c.below.nodes, e.nodes_above = c.above.nodes;
  e.cusps_below = c.below.cusps, e.cusps_above = c.above.cusps;
  const ChainCensus at = chain_census(chain_at(chain, vary, e.a3));
  const CensusCounts there = counts_of(at);
  const bool seen = at.certified || at.multiple_unproved || at.touching_unproved;  // its nodes are known (to rounding)
  if (c.below.cusps != c.above.cusps || (at.certified && there.cusps > std::max(c.below.cusps, c.above.cusps))) {
    e.kind = BoundaryEventKind::cusp;
    e.name = "cusp birth (P parallel to omega)";
  } else if (c.below.pairs == c.above.pairs || (seen && there.multiple)) {
    if (c.below == c.above && !(seen && near_triple(at, std::max(1e-6, kChainTripleDistance * (c.hi - c.lo))))) {
      if (c.hi - c.lo > kChainQuietWidth)
        why = "no census holds over a slab of [" + number_text(c.lo) + ", " + number_text(c.hi) + "] and none changes at " +
              std::to_string(kChainBracketProbes + 1) + " values in it: events that cancel could hide there";
      return std::nullopt;
    }
    e.kind = BoundaryEventKind::triple_point;
    e.name = "three or more branches through one point";
  } else {
    e.kind = BoundaryEventKind::tangency;
    e.name = "self-tangency (two branches touch)";
  }
  return e;
}

/// `why` when the census at a range end shows an event's band state (band_state: a cusp, a node
/// of three branches, two branches touching): the end lies at an event or within its resolution
/// band, where the census at one value does not give the counts on either side of it.
inline void check_range_end(const RotationChain& chain, const ChainVary& vary, double end, std::string& why) {
  const ChainCensus c = chain_census(chain_at(chain, vary, end));
  const CensusCounts k = counts_of(c);
  if (!(c.certified || c.multiple_unproved || c.touching_unproved) || !band_state(k, CensusCounts{})) return;
  const std::string what = k.cusps > 0 ? "a cusp (|P'| <= " + number_text(kChainCuspResolution) + " sum |N_i|)"
                           : k.multiple ? "a node of three or more branches" : "two branches touching";
  why = "the range ends at an event or within its resolution band: the census at " + vary.name() + " = " + number_text(end) +
        " shows " + what + "; move that end";
}

}  // namespace chain_family_detail

/// The events of the family (see header), ascending, with `certified`, `why` and `accuracy`.
/// Families with closed forms (chain/chain_events.hpp) are answered by chain_events, except A2 of
/// a two-stage chain whose A1 lies within kChainTwistMargin of 0 or pi (the map refuses that a2;
/// at exactly 0 or pi the joints are coaxial and the curve a circle for every A2). Throws
/// InvalidInput as chain_census does, ("vary") for a twist range within kChainTwistMargin of
/// 0 or pi only, or a phase range beyond [-4 pi, 4 pi] or longer than 2 pi (every family).
inline ChainEvents chain_family_events(const RotationChain& chain, const ChainVary& vary) {
  namespace d = chain_family_detail;
  const double first = chain.stages()[0].twist, pi = Constants<double>::pi();
  const bool near_coaxial = std::min(first, pi - first) < kChainTwistMargin;  // the map refuses such an a2: searched
  if (!vary.twist && !(vary.hi - vary.lo <= 2 * Constants<double>::pi() && vary.lo >= -kChainPhaseBound && vary.hi <= kChainPhaseBound))
    throw InvalidInput("vary", vary.name() + ":" + number_text(vary.lo) + ":" + number_text(vary.hi),
                       "a phase range longer than 2 pi or beyond 4 pi (the family repeats every 2 pi)",
                       "a phase range within [-4 pi, 4 pi], HI - LO <= 2 pi");
  if (closed_form_family(chain, vary) && !(chain.size() == 2 && vary.twist && near_coaxial)) return chain_events(chain, vary);
  ChainEvents out{vary, {}, "", true, "", kEventAccuracy, 0.0, {}, {}};
  ChainVary range = vary;
  if (vary.twist) {
    range.lo = std::max(vary.lo, kChainTwistMargin);
    range.hi = std::min(vary.hi, Constants<double>::pi() - kChainTwistMargin);
    if (!(range.lo < range.hi))
      throw InvalidInput("vary", vary.name() + ":" + number_text(vary.lo) + ":" + number_text(vary.hi), "the range lies within " + number_text(kChainTwistMargin) + " of 0 or pi",
                         "a twist range reaching into [" + number_text(kChainTwistMargin) + ", pi - " + number_text(kChainTwistMargin) + "]");
  }
  const ChainVary middle{vary.twist, vary.stage, 0.5 * (range.lo + range.hi), 0.5 * (range.lo + range.hi)};
  if (!varies_curve(chain_at(chain, vary, middle.lo), middle)) {
    out.note = vary.name() + " turns the tool axis about itself: the curve does not change";
    return out;
  }
  const double arcs = chain_census_arcs(chain_at(chain, vary, middle.lo));
  const double slabs_allowed = std::min(static_cast<double>(kMaxFamilySlabs), kFamilyWork / (arcs * static_cast<double>(chain.size())));
  if (!(slabs_allowed >= static_cast<double>(kMinFamilySlabs)))
    throw InvalidInput("rates", chain.rates_text(), "the family search needs censuses of " + number_text(arcs) + " arcs of " + std::to_string(chain.size()) + " stages",
                       "chains whose arcs (period 2 pi L / g times sum |N_i| / " + number_text(kChainArcTurn) + ") times stages are at most " +
                           number_text(kFamilyWork / static_cast<double>(kMinFamilySlabs)));
  const auto budget = static_cast<std::size_t>(slabs_allowed);
  const std::size_t max_boxes = std::max<std::size_t>(2000, kFamilyBoxesPerArc * static_cast<std::size_t>(arcs));
  bool exhausted = false;
  const std::vector<d::Slab> slabs = d::search_slabs(chain, range, budget, max_boxes, exhausted);
  double accuracy = 0, uncovered = 0;
  for (const d::Bracket& b : d::brackets_of(slabs, out.why)) {
    uncovered += b.hi - b.lo;
    for (const d::Change& c : d::merge_bands(d::changes_of(chain, range, b, out.why)))
      if (std::optional<BoundaryEvent> e = d::event_of(chain, range, c, out.why)) {
        const EventRoot root = event_root(chain, range, e->kind, c.lo, c.hi);
        if (root.certified) e->a3 = e->a3_precise = 0.5 * (root.lo + root.hi);
        out.events.push_back(*e);
        out.roots.push_back(root);
        out.accuracies.push_back(root.certified ? root.hi - root.lo : 0.5 * (c.hi - c.lo));
        accuracy = std::max(accuracy, out.accuracies.back());
      }
  }
  for (const double end : {range.lo, range.hi}) d::check_range_end(chain, range, end, out.why);
  if (exhausted) out.why = "the search stopped at its bound of " + std::to_string(budget) + " slab censuses";
  out.accuracy = out.events.empty() ? kChainChangeWidth : accuracy;
  out.uncovered = uncovered;
  out.certified = out.why.empty();
  if (out.events.empty() && out.certified) out.note = "one census holds over the whole range";
  return out;
}

}  // namespace sphtroch
