// sphtroch/exact/path_fit_output.hpp — fit over a set of ratios with every candidate confirmed by
// classify(), and the reports: the JSON that `sphtroch synth fit --json` and Python's fit print, and
// the text that `sphtroch synth fit` and Python's fit_text print.
//
//   const sphtroch::GearTrain hidden(1.1, 0.9, sphtroch::Ratio(2), 0.4);
//   const auto points = sphtroch::sample_period(sphtroch::TracerCurve<double>(hidden), 200).points;
//   sphtroch::FitOptions o;  o.nodes = 2;
//   auto fits = sphtroch::fit_with_census(points, {sphtroch::Ratio(2)}, o);
//   std::string json = sphtroch::fit_json(fits, o);   // {"candidates": [...], "reason": ""}
//   std::string text = sphtroch::fit_text(fits, o);   // "fit: 1 candidate(s), 2 node(s) wanted; ..."
//
// The promise: with a wanted node (cusp) count, every candidate listed has exactly that count by
// classify(), certified; a candidate whose census is not certified or differs (a shape the root
// count put in the cell but too close to a boundary for the census to agree) is dropped and
// counted in "dropped". Without a wanted count, candidates keep their census as it is, certified
// or not ("census_certified"). With a node point (options.node_at), every candidate's certified
// census has a node within options.node_tolerance of it ("node_distance": to the nearest node).
// JSON: {"candidates": [{"n": "p/q", "teeth": "ZS:ZP" (only with a TeethSpec), "a2", "a3", "phase",
// "rms", "max_deviation", "margin" (map_margin: the distance in the (a2, a3) plane to the nearest
// change of the census, to first order), "certified_margin": {"lower", "upper"} (topology_margin.hpp:
// the half-width of the largest square of (a2, a3) about the train that no change meets lies in
// [lower, upper]; a square's half-width, so up to sqrt 2 below the distance, at a boundary at 45 deg),
// "node_distance" (only with node_at) (radians),
// "counts": {"nodes", "crossings", "tangencies", "cusps"}, "census_certified"}], best (smallest rms)
// first over all ratios, at most options.max_candidates; "reason": why there is none, or "";
// "dropped": candidates removed because the census did not confirm the wanted counts, or because
// their certified margin is below options.min_margin}. The text says when the best candidate
// lies within kFitHugMargin of a change of its census, and names both margins on each candidate's
// line: "margin D (distance to the nearest change of the census, first order), change-free square
// of half-width LO .. HI (certified)".
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/path_fit_output.hpp needs CGAL: link the CMake target sphtroch::exact"
#endif

#include "sphtroch/exact/classification.hpp"  // classify()'s result
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/tolerance/tolerance_types.hpp"
#include "sphtroch/synthesis/path_fit.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace sphtroch {

/// Candidates fit_with_census asks for beyond the wanted number (replacements for dropped ones).
constexpr std::size_t kFitSpareCandidates = 3;

/// One candidate and its census.
struct ConfirmedCandidate {
  FitCandidate candidate;
  Classification census;
  TopologyMargin certified_margin;  // topology_margin of the candidate's train
};

/// A best candidate whose certified margin is below this (radians, ~0.06 deg) is reported as
/// hugging a boundary: a train built to that tolerance may draw other counts.
constexpr double kFitHugMargin = 1e-3;

/// The fit of one ratio, its candidates confirmed (see header).
struct RatioFit {
  Ratio ratio;
  std::vector<ConfirmedCandidate> candidates;  // best first
  std::string reason;                          // why there is none, or ""
  std::size_t dropped = 0;                     // not confirmed by classify, or nearer than min_margin
  std::size_t too_near = 0;                    // of those: certified margin below options.min_margin
};

/// Spherical distance (radians) from `at` to the nearest node of the census, or infinity.
inline double census_node_distance(const Classification& c, const Vector3d& at) {
  double best = std::numeric_limits<double>::infinity();
  for (const Node& node : c.nodes) best = std::min(best, sphere_distance(node.position, at.normalized()));
  return best;
}

/// True when the census has the wanted counts, certified (nothing wanted: always).
inline bool census_confirms(const Classification& c, const FitOptions& o) {
  if (!o.nodes && !o.cusps) return true;
  return c.certified() && (!o.nodes || static_cast<std::int64_t>(c.nodes.size()) == *o.nodes) &&
         (!o.cusps || static_cast<std::int64_t>(c.cusps.size()) == *o.cusps);
}

/// fit_path for each ratio, then classify() and topology_margin() of every candidate (see header;
/// defined in path_fit_analysis.hpp). A function template (Options = FitOptions), like
/// classify(), so that files built with and without SPHTROCH_SEPARATE_EXACT share one program.
template <typename Options = FitOptions>
std::vector<RatioFit> fit_with_census(const std::vector<Vector3d>& points, const std::vector<Ratio>& ratios,
                                      const Options& options = {});

/// The best candidates over all ratios, best first, at most options.max_candidates.
inline std::vector<const ConfirmedCandidate*> ranked_candidates(const std::vector<RatioFit>& all, const FitOptions& options) {
  std::vector<const ConfirmedCandidate*> out;
  for (const RatioFit& rf : all)
    for (const ConfirmedCandidate& c : rf.candidates) out.push_back(&c);
  std::stable_sort(out.begin(), out.end(), [](const auto* a, const auto* b) { return a->candidate.rms < b->candidate.rms; });
  if (out.size() > options.max_candidates) out.resize(options.max_candidates);
  return out;
}

/// Why no ratio gave a candidate: the reason of each ratio, the same reasons once, at most five.
inline std::string fit_reason(const std::vector<RatioFit>& all) {
  std::vector<std::string> reasons;
  std::set<std::string> seen;
  for (const RatioFit& rf : all) {
    if (!rf.candidates.empty()) return "";
    if (seen.insert(rf.reason).second) reasons.push_back(rf.reason);
  }
  std::string out;
  for (std::size_t k = 0; k < reasons.size() && k < 5; ++k) out += (k ? "; " : "") + reasons[k];
  if (reasons.size() > 5) out += "; and " + std::to_string(reasons.size() - 5) + " more";
  return out;
}

/// One candidate as a JSON object (see header).
inline std::string fit_candidate_json(const ConfirmedCandidate& cc, const TeethSpec& teeth = {}, bool node_at = false) {
  const FitCandidate& f = cc.candidate;
  const Classification& c = cc.census;
  std::ostringstream out;
  out << "{\"n\": \"" << f.train.ratio().str() << "\", ";
  if (const auto t = teeth.of(f.train.ratio())) out << "\"teeth\": \"" << t->str() << "\", ";
  out << "\"a2\": " << number_text(f.train.a2())
      << ", \"a3\": " << number_text(f.train.a3()) << ", \"phase\": " << number_text(f.train.phase_given())
      << ", \"rms\": " << number_text(f.rms) << ", \"max_deviation\": " << number_text(f.max_deviation)
      << ", \"margin\": " << number_text(f.margin) << ", \"certified_margin\": {\"lower\": " << number_text(cc.certified_margin.lower)
      << ", \"upper\": " << number_text(cc.certified_margin.upper) << "}";
  if (node_at) out << ", \"node_distance\": " << number_text(f.node_distance);
  out << ", \"counts\": {\"nodes\": " << c.nodes.size()
      << ", \"crossings\": " << c.crossings << ", \"tangencies\": " << c.tangencies << ", \"cusps\": " << c.cusps.size()
      << "}, \"census_certified\": " << (c.certified() ? "true" : "false") << "}";
  return out.str();
}

/// The whole result as JSON (see header), one candidate per line. `fields`, if any, are more
/// members written first.
inline std::string fit_json(const std::vector<RatioFit>& all, const FitOptions& options, const std::string& fields = "",
                            const TeethSpec& teeth = {}) {
  std::string out = "{" + fields + "\"candidates\": [";
  const auto ranked = ranked_candidates(all, options);
  for (std::size_t k = 0; k < ranked.size(); ++k) out += (k ? ",\n  " : "\n  ") + fit_candidate_json(*ranked[k], teeth, options.node_at.has_value());
  std::size_t dropped = 0;
  for (const RatioFit& rf : all) dropped += rf.dropped;
  out += std::string(ranked.empty() ? "" : "\n") + "], \"reason\": " + nlohmann::json(fit_reason(all)).dump() +
         ", \"dropped\": " + std::to_string(dropped) + "}\n";  // the reason escaped as JSON (control characters too)
  return out;
}

/// The counts a fit was asked for, in words: "4 node(s), 2 cusp(s) wanted", "any counts".
inline std::string wanted_text(const FitOptions& f) {
  std::string s;
  if (f.nodes) s += std::to_string(*f.nodes) + " node(s)";
  if (f.cusps) s += (s.empty() ? "" : ", ") + std::to_string(*f.cusps) + " cusp(s)";
  if (f.node_at)
    s += (s.empty() ? "" : ", ") + std::string("a node within ") + report_number(f.node_tolerance) + " rad of " +
         report_number(f.node_at->x()) + "," + report_number(f.node_at->y()) + "," + report_number(f.node_at->z());
  return s.empty() ? "any counts" : s + " wanted";
}

/// The ranked candidates as text for people (what `sphtroch synth fit` prints): a header line, the
/// reason when there is none, then each candidate with its distances, margin, census and the
/// command that plots it.
inline std::string fit_text(const std::vector<RatioFit>& all, const FitOptions& f, const TeethSpec& teeth = {}) {
  std::ostringstream out;
  const auto ranked = ranked_candidates(all, f);
  out << "fit: " << ranked.size() << " candidate(s), " << wanted_text(f)
      << "; distances and margins in radians, best first\n";
  if (ranked.empty()) out << "no candidate: " << fit_reason(all) << "\n";
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    const FitCandidate& c = ranked[k]->candidate;
    const Classification& census = ranked[k]->census;
    out << "  " << k + 1 << ". n = " << c.train.ratio().str() << teeth_text(teeth, c.train.ratio()) << ", a2 = " << report_number(c.train.a2())
        << ", a3 = " << report_number(c.train.a3()) << ", phase = " << report_number(c.train.phase_given()) << "; rms "
        << report_number(c.rms) << ", max " << report_number(c.max_deviation) << "; margin " << report_number(c.margin)
        << " (distance to the nearest change of the census, first order), change-free square of half-width "
        << report_number(ranked[k]->certified_margin.lower) << " .. " << report_number(ranked[k]->certified_margin.upper) << " (certified); "
        << census.nodes.size() << " node(s), " << census.cusps.size() << " cusp(s)"
        << (f.node_at ? "; node point " + report_number(c.node_distance) + " rad away" : "")
        << (census.certified() ? " (certified)" : " (census NOT certified)") << "\n"
        << "     plot it: sphtroch plot " << train_arguments(c.train) << " -o candidate" << k + 1 << ".svg\n";
  }
  if (!ranked.empty() && ranked[0]->certified_margin.upper < kFitHugMargin) {
    const TopologyMargin& m = ranked[0]->certified_margin;
    out << "note: candidate 1 lies within " << report_number(m.upper) << " rad of a change of its census"
        << (m.nearest ? " (" + boundary_text(m.nearest->boundary) + ")" : std::string())
        << ": a train built to that tolerance may draw other counts; --min-margin D keeps candidates at least D away\n";
  }
  return out.str();
}

}  // namespace sphtroch
