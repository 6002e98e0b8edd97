// sphtroch/map/boundary_events_output.hpp — the boundary set (boundary_events.hpp) as text, JSON and CSV: what
// `sphtroch boundaries` prints. Eigen only; no JSON library (the JSON is written by hand: every
// string is a fixed ASCII name, every number the shortest round-trip form, number_text.hpp; the
// text's numbers as report_number writes them).
//
//   write_boundary_text(std::cout, boundary_set(a2, n));
//   write_boundary_json(std::cout, boundary_set(a2, n));   // {"n","a2","events":[...]}
//   write_loci_csv(std::cout, n, 0.01, 3.13, 720, boundary_loci(n, 0.01, 3.13, 720));  // a2 from, to, steps
//
// JSON: {"n": "5/2", "n_value": 2.5, "a2": A, "accuracy": 1e-12, "events": [{"a3", "kind", "name",
//   "nodes_below", "nodes_above", "cusps_below", "cusps_above", "b", "m", "label"}, ...]}; "m" and
//   "label" are null except for tangencies.
// CSV: one comment line "# sphtroch boundaries n=P/Q a2=LO:HI steps=S", the header
//   locus,kind,m,label,a2,a3,b   and one row per point, loci in order, points by ascending a2
//   (m, label empty except for tangencies; locus numbers from 0); in degrees the angle columns
//   are a2_deg,a3_deg,b_deg (--degrees). JSON stays in radians.
#pragma once

#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/core/number_text.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace sphtroch {

/// One line per event: "a3  kind  nodes below -> above  (name; witness)"; a3 and b in degrees
/// ("a3 = 18.3 deg") when `in_degrees`.
inline void write_boundary_text(std::ostream& out, const BoundarySet& s, bool in_degrees = false) {
  const auto angle = [&](double r) { return in_degrees ? report_number(degrees(r)) + " deg" : report_number(r); };
  out << "boundaries: n = " << s.ratio.str() << ", a2 = " << report_number(s.a2) << " rad\n";
  out << "events in a3 (0, pi), ascending (a3 to " << report_number(kEventAccuracy)
      << " rad; node points as classify counts them, just below -> just above):\n";
  if (s.events.empty()) out << "  none\n";
  for (const BoundaryEvent& e : s.events) {
    out << "  a3 = " << angle(e.a3) << "  " << to_string(e.kind) << "  nodes " << e.nodes_below << " -> "
        << e.nodes_above << ", cusps " << e.cusps_below << " -> " << e.cusps_above << "  (" << e.name << "; b = "
        << angle(e.b);
    if (e.kind == BoundaryEventKind::tangency) out << ", g = " << e.m;
    out << ")\n";
  }
}

inline void write_boundary_json(std::ostream& out, const BoundarySet& s) {
  out << "{\"n\": \"" << s.ratio.str() << "\", \"n_value\": " << number_text(s.ratio.value())
      << ", \"a2\": " << number_text(s.a2) << ", \"accuracy\": " << number_text(kEventAccuracy) << ", \"events\": [";
  for (std::size_t i = 0; i < s.events.size(); ++i) {
    const BoundaryEvent& e = s.events[i];
    const bool t = e.kind == BoundaryEventKind::tangency;
    out << (i ? ", " : "") << "{\"a3\": " << number_text(e.a3) << ", \"kind\": \"" << to_string(e.kind)
        << "\", \"name\": \"" << e.name << "\", \"nodes_below\": " << e.nodes_below
        << ", \"nodes_above\": " << e.nodes_above << ", \"cusps_below\": " << e.cusps_below
        << ", \"cusps_above\": " << e.cusps_above << ", \"b\": " << number_text(e.b)
        << ", \"m\": " << (t ? std::to_string(e.m) : "null") << ", \"label\": " << (t ? std::to_string(e.label) : "null")
        << "}";
  }
  out << "]}\n";
}

inline void write_loci_csv(std::ostream& out, const Ratio& n, double a2_lo, double a2_hi, std::size_t steps,
                           const std::vector<Locus>& loci, bool in_degrees = false) {
  const auto angle = [&](double r) { return number_text(in_degrees ? degrees(r) : r); };
  out << "# sphtroch boundaries n=" << n.str() << " a2=" << number_text(a2_lo) << ":" << number_text(a2_hi)
      << " steps=" << steps << "\n";
  out << (in_degrees ? "locus,kind,m,label,a2_deg,a3_deg,b_deg\n" : "locus,kind,m,label,a2,a3,b\n");
  for (std::size_t i = 0; i < loci.size(); ++i) {
    const Locus& l = loci[i];
    const bool t = l.kind == BoundaryEventKind::tangency;
    const std::string m = t ? std::to_string(l.m) : "", label = t ? std::to_string(l.label) : "";
    for (const LocusPoint& p : l.points)
      out << i << "," << to_string(l.kind) << "," << m << "," << label << "," << angle(p.a2) << "," << angle(p.a3) << ","
          << angle(p.b) << "\n";
  }
}

}  // namespace sphtroch
