// sphtroch/chain/chain_events.hpp — where a rotation chain's census changes as one of its twists or
// phases varies over a range (`sphtroch chain boundaries --vary NAME:LO:HI`), and the report. Eigen
// only; the text and JSON are written by hand as boundary_events_output.hpp's.
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {1.0, sphtroch::ChainRate(3), 0.0}});
//   const sphtroch::ChainEvents e = sphtroch::chain_events(chain, sphtroch::parse_chain_vary("A2:0:pi", 2));
//   e.events;   // BoundaryEvent: kind, value of A2 (its a3 field), node points below and above
//
// The families computed, each exactly (derivations ours):
// - P1, any k: no event. P1 enters P(s) as a left factor Rz(P1): changing it turns the whole
//   curve about z.
// - P2 of a two-stage chain: no event. With N2 != 0, P(s - d / N2; P2 + d) = Rz(-N1 d / N2) P(s; P2):
//   the curve with P2 + d is the one with P2 turned about z; with N2 = 0 only joint 1 turns and
//   the curve is a circle (or a point) for every P2.
// - A2 of a two-stage chain whose rates are both not 0: the gear train a2 = A1, n = N2 / N1
//   (gear_train_of), whose a3 is A2. Its events in a3 are the map's boundary set
//   (boundary_events.hpp: pitch cones, where a cusp is born; pole passages; self-tangencies;
//   every a3 in (0, pi) where the census changes, to kEventAccuracy), kept within [LO, HI], with
//   the node points on either side as classify counts them. With a rate 0 the curve is a circle
//   for every A2: no event.
// Every other family (A1 of a two-stage chain; a twist, or a phase other than P1, of a longer
// chain) has no closed form: chain_events refuses it (InvalidInput "vary"), and
// chain_family_events (chain/chain_family_events.hpp, CGAL intervals) searches it;
// that search uses chain_events for the families above, so every front end calls it.
// Cost: boundary_set's (cost_bounds.hpp: refused beyond the census bound, InvalidInput "n",
// reported as "rates").
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/map/boundary_events.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace sphtroch {

/// "A2:LO:HI" or "P1:LO:HI" (LO, HI in parse_angle's forms: "pi/3", "0.5"), for a chain of
/// `stages` stages: A in [0, pi], LO < HI, both finite. InvalidInput("vary") otherwise.
inline ChainVary parse_chain_vary(std::string_view text, std::size_t stages) {
  const std::string valid = "NAME:LO:HI, NAME = Ai (a twist, LO and HI in [0, pi]) or Pi (a phase), i in 1.." + std::to_string(stages) +
                            ", LO < HI radians (pi/3, 0.5)";
  const std::vector<std::string> parts = [&] {
    std::vector<std::string> p;
    std::size_t start = 0;
    for (std::size_t colon; (colon = text.find(':', start)) != std::string_view::npos; start = colon + 1)
      p.emplace_back(text.substr(start, colon - start));
    p.emplace_back(text.substr(start));
    return p;
  }();
  const std::string shown(text);
  if (parts.size() != 3 || parts[0].size() < 2 || (parts[0][0] != 'A' && parts[0][0] != 'P'))
    throw InvalidInput("vary", shown, "not NAME:LO:HI", valid);
  const std::string digits = parts[0].substr(1);
  const bool plain = digits[0] != '0' && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
  const std::optional<std::int64_t> stage = plain ? detail::strict_int(digits) : std::nullopt;
  if (!stage || *stage < 1 || static_cast<std::size_t>(*stage) > stages) throw InvalidInput("vary", shown, "no such stage", valid);
  ChainVary v;
  v.twist = parts[0][0] == 'A';
  v.stage = static_cast<std::size_t>(*stage);
  try {
    v.lo = parse_angle(parts[1], "vary");
    v.hi = parse_angle(parts[2], "vary");
  } catch (const InvalidInput& e) {
    throw InvalidInput("vary", shown, e.problem(), valid);
  }
  const double pi = Constants<double>::pi();
  if (!(v.lo < v.hi)) throw InvalidInput("vary", shown, "LO is not below HI", valid);
  if (v.twist && !(v.lo >= 0 && v.hi <= pi)) throw InvalidInput("vary", shown, "a twist range outside [0, pi]", valid);
  return v;
}

/// The events along one family (see header), ascending; `note` says why there is none when the
/// family has none by a symmetry, or that one census holds over the range.
/// An event of a family searched by census slabs (chain_family_events.hpp): the bracket where the
/// census changes and, when `certified`, the event as a root of its square system
/// (chain_event_roots.hpp): the value in [lo, hi] (radians) and the curve parameters s (t, u).
struct EventRoot {
  double bracket_lo = 0, bracket_hi = 0;
  bool certified = false;
  double lo = 0, hi = 0;
  std::vector<double> params;
};

struct ChainEvents {
  ChainVary vary;
  std::vector<BoundaryEvent> events;  // a3: the value of the varied twist or phase
  std::string note;
  bool certified = true;              // every event of the range is listed (else `why`)
  std::string why;
  double accuracy = kEventAccuracy;   // |value - true value| <= accuracy, radians (the largest over the events)
  double uncovered = 0;               // radians of the range no one census was certified over (chain_family_events)
  std::vector<double> accuracies;     // per event when known (chain_family_events), else `accuracy` for each
  std::vector<EventRoot> roots;       // per event of chain_family_events' slab search (else empty)

  double accuracy_of(std::size_t i) const { return i < accuracies.size() ? accuracies[i] : accuracy; }
};

/// Whether chain_events computes this family (see header): P1; P2 and A2 of a two-stage chain.
inline bool closed_form_family(const RotationChain& chain, const ChainVary& vary) {
  return (!vary.twist && vary.stage == 1) || (chain.size() == 2 && vary.stage == 2);
}

/// See header. Throws InvalidInput("vary") for a family not computed here (chain_family_events
/// of chain/chain_family_events.hpp computes every family), ("twists") for a first
/// twist the map refuses (within 1e-6 of 0 or pi), ("rates") beyond the census bound.
inline ChainEvents chain_events(const RotationChain& chain, const ChainVary& vary) {
  ChainEvents out{vary, {}, "", true, "", kEventAccuracy, 0.0, {}, {}};
  const bool two = chain.size() == 2;
  if (!vary.twist && vary.stage == 1) {
    out.note = "changing P1 turns the whole curve about z";
    return out;
  }
  if (two && !vary.twist) {
    out.note = "changing P2 of a two-stage chain turns the curve about z (s shifts by the change over N2)";
    return out;
  }
  if (!closed_form_family(chain, vary))
    throw InvalidInput("vary", vary.name(), "this family has no closed form",
                       "P1 (any chain); A2 or P2 of a two-stage chain; others: chain_family_events (chain/chain_family_events.hpp)");
  const ChainStage& first = chain.stages()[0];
  if (first.rate.is_zero() || chain.stages()[1].rate.is_zero()) {
    out.note = "with a rate 0 only one joint turns: the curve is a circle for every A2";
    return out;
  }
  const std::optional<Ratio> n = gear_ratio_of(chain);
  if (!n) throw InvalidInput("rates", chain.rates_text(), "N2 / N1 has a term above 1e6", "rates whose ratio N2 / N1 is p/q with |p|, q <= 1e6");
  BoundarySet set;
  try {
    set = boundary_set(first.twist, *n);
  } catch (const InvalidInput& e) {
    if (e.field() == "a2") throw InvalidInput("twists", e.value() + " (stage 1)", e.problem(), e.valid_range());
    throw InvalidInput("rates", chain.rates_text(), e.problem(), e.valid_range());
  }
  for (const BoundaryEvent& e : set.events)
    if (e.a3 >= vary.lo && e.a3 <= vary.hi) out.events.push_back(e);
  return out;
}

inline void write_chain_events_text(std::ostream& out, const RotationChain& chain, const ChainEvents& e) {
  out << "chain boundaries: " << chain.size() << " stages, rates " << chain.rates_text() << ", " << e.vary.name() << " in ["
      << report_number(e.vary.lo) << ", " << report_number(e.vary.hi) << "] rad\n";
  out << "events, ascending (" << e.vary.name() << " to " << report_number(e.accuracy)
      << " rad; node points as chain classify counts them, just below -> just above):\n";
  if (e.events.empty()) out << "  none" << (e.note.empty() ? "" : ": " + e.note) << "\n";
  for (std::size_t i = 0; i < e.events.size(); ++i) {
    const BoundaryEvent& b = e.events[i];
    out << "  " << e.vary.name() << " = " << report_number(b.a3) << "  " << to_string(b.kind) << "  nodes " << b.nodes_below << " -> "
        << b.nodes_above << "  (" << b.name << ")";
    if (i < e.roots.size()) out << (e.roots[i].certified ? "  root certified" : "  root not isolated: value to +-" + report_number(e.accuracy_of(i)));
    out << "\n";
  }
  if (!e.certified) out << "NOT CERTIFIED: " << e.why << "\n";
}

/// , "bracket": [lo, hi], "root": {"certified", "lo", "hi", "params"} (lo, hi, params when certified).
inline void write_event_root_json(std::ostream& out, const EventRoot& r) {
  out << ", \"bracket\": [" << number_text(r.bracket_lo) << ", " << number_text(r.bracket_hi) << "], \"root\": {\"certified\": "
      << (r.certified ? "true" : "false");
  if (r.certified) {
    out << ", \"lo\": " << number_text(r.lo) << ", \"hi\": " << number_text(r.hi) << ", \"params\": [";
    for (std::size_t k = 0; k < r.params.size(); ++k) out << (k ? ", " : "") << number_text(r.params[k]);
    out << "]";
  }
  out << "}";
}

/// {"chain": {"twists", "rates", "phases"}, "vary": {"name", "lo", "hi"}, "accuracy", "uncovered", "certified", "why", "note",
///  "events": [{"value", "kind", "name", "nodes_below", "nodes_above", "cusps_below", "cusps_above", "accuracy"
///  [, "bracket", "root" (write_event_root_json): events of the slab search]}]}.
inline void write_chain_events_json(std::ostream& out, const RotationChain& chain, const ChainEvents& e) {
  const auto list = [&](auto value) {
    std::string t;
    for (const ChainStage& s : chain.stages()) t += (t.empty() ? "" : ", ") + value(s);
    return "[" + t + "]";
  };
  out << "{\"chain\": {\"twists\": " << list([](const ChainStage& s) { return number_text(s.twist); })
      << ", \"rates\": " << list([](const ChainStage& s) { return "\"" + s.rate.str() + "\""; })
      << ", \"phases\": " << list([](const ChainStage& s) { return number_text(s.phase); }) << "}, \"vary\": {\"name\": \""
      << e.vary.name() << "\", \"lo\": " << number_text(e.vary.lo) << ", \"hi\": " << number_text(e.vary.hi)
      << "}, \"accuracy\": " << number_text(e.accuracy) << ", \"uncovered\": " << number_text(e.uncovered) << ", \"certified\": " << (e.certified ? "true" : "false")
      << ", \"why\": \"" << e.why << "\", \"note\": \"" << e.note << "\", \"events\": [";
  for (std::size_t i = 0; i < e.events.size(); ++i) {
    const BoundaryEvent& b = e.events[i];
    out << (i ? ", " : "") << "{\"value\": " << number_text(b.a3) << ", \"kind\": \"" << to_string(b.kind) << "\", \"name\": \""
        << b.name << "\", \"nodes_below\": " << b.nodes_below << ", \"nodes_above\": " << b.nodes_above
        << ", \"cusps_below\": " << b.cusps_below << ", \"cusps_above\": " << b.cusps_above << ", \"accuracy\": " << number_text(e.accuracy_of(i));
    if (i < e.roots.size()) write_event_root_json(out, e.roots[i]);
    out << "}";
  }
  out << "]}\n";
}

}  // namespace sphtroch
