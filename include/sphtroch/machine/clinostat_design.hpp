// sphtroch/machine/clinostat_design.hpp — choosing a clinostat's speeds: every pair of a grid of
// exact speeds, its time to epsilon, its worst window mean for the experiment's window and
// (optionally) its coverage; the pairs ranked and the Pareto front of (time to epsilon, coverage).
//
//   sphtroch::DesignRequest r;
//   r.outer = {sphtroch::Rpm(1), sphtroch::Rpm(3), sphtroch::Rpm(1, 2)};   // 1, 1.5, ..., 3 rpm
//   r.inner = {sphtroch::Rpm(1), sphtroch::Rpm(3), sphtroch::Rpm(1, 2)};
//   r.window_s = 3600;
//   r.epsilon = 0.01;
//   const std::vector<sphtroch::DesignPair> pairs = sphtroch::design_pairs(r);   // 25 pairs
//   const sphtroch::DesignRow row = sphtroch::evaluate_pair(r, pairs[7]);
//   row.time_to->stays_below_from_s;   // every window this long or longer averages below 0.01 g0
//
// The grid: lo, lo + step, ..., up to hi, exact (the speeds as typed; docs/clinostat.md). The pair
// (0, 0) is not a machine and is left out. With a tooth range (a gear-driven machine: one motor
// turns both frames), only pairs whose ratio n = outer / inner is a ratio of two tooth counts in
// the range are kept, each with its smallest tooth pair (core/teeth.hpp).
// Each pair is computed by the library's own functions (worst_window_mean.hpp,
// time_to_epsilon.hpp, dwell_map.hpp), with their certificates. A pair they refuse or cannot
// certify within the work bound is kept with the reason, and not ranked among the decided ones.
// Ranking (design_less): decided pairs whose windows stay below epsilon first, by
// stays_below_from_s, then first_s, then coverage (more first), then outer, then inner; then the
// pairs whose mean over a period is above epsilon (never below); then the refused or undecided.
// Pareto front (with coverage): the decided pairs that no other beats in both stays_below_from_s
// (shorter) and coverage fraction (larger), in rank order.
// Recommendation (recommend_design): the first ranked pair when it reaches epsilon, with its lead
// over the runner-up, whether it sits at an end of a speed range (then a wider range may hold a
// better pair), and with coverage the front's pair of most coverage.
// Off the centre (offset_m): each pair averages the effective gravity at the sample point.
// Cost: at most kMaxDesignPairs pairs per run; per pair ~1 ms at typical speeds, at most the worst
// window mean's kMaxWindowPieces (~3 s, fast speeds with a short window) plus kDesignWorkPerPair
// window-mean evaluations (~0.3 s) for the time to epsilon, plus the coverage walk (bounded by
// dwell_map.hpp's limits) when asked.
#pragma once

#include "sphtroch/core/teeth.hpp"
#include "sphtroch/machine/dwell_map_result.hpp"
#include "sphtroch/machine/time_to_epsilon.hpp"
#if defined(SPHTROCH_HAVE_HEALPIX)
#include "sphtroch/machine/dwell_map.hpp"
#endif

#include <algorithm>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

constexpr std::size_t kMaxDesignPairs = 100000;
constexpr double kDesignWorkPerPair = 3e6;

/// lo, lo + step, ..., <= hi (rpm, exact).
struct SpeedRange {
  Rpm lo, hi, step{1};
};

/// A dwell map of a machine over [start, start + duration] at nside (dwell_map's contract).
using DwellMapFunction = DwellMap (*)(const ClinostatSettings& machine, double start_s, double duration_s, int nside);

/// dwell_map (machine/dwell_map.hpp) when this build has HEALPix, else none.
inline DwellMapFunction built_in_dwell_map() {
#if defined(SPHTROCH_HAVE_HEALPIX)
  return [](const ClinostatSettings& machine, double start_s, double duration_s, int nside) {
    return dwell_map(Clinostat(machine), start_s, duration_s, nside);
  };
#else
  return nullptr;
#endif
}

struct DesignRequest {
  SpeedRange outer, inner;
  double tilt_deg = 90, frame_angle_deg = 90;
  double window_s = 3600;            ///< the experiment's window W: M(W) is reported
  double epsilon = 0.01;             ///< the bound on the averaged gravity, g0
  double resolution_s = 1;           ///< the step of W for the time to epsilon
  std::optional<double> coverage_s;  ///< the duration of the dwell map, when asked
  int nside = 8;
  std::optional<ToothRange> teeth;   ///< a gear-driven machine: n must be a ratio of tooth counts
  /// The sample point r (metres, sample frame; clinostat.hpp): off the centre the effective
  /// gravity there (gravity plus the frames' accelerations) is what each pair's windows average.
  Vector3d offset_m = Vector3d::Zero();
  DwellMapFunction dwell = built_in_dwell_map();  ///< computes the coverage (a front end may open HEALPix on demand)
};

struct DesignPair {
  Rpm outer, inner;
  std::optional<Teeth> teeth;  ///< the smallest pair in the request's range (only with a range)
};

struct DesignRow {
  DesignPair pair;
  std::string n;                        ///< outer / inner as p/q in lowest terms ("" when inner is 0)
  std::optional<double> period_s;       ///< none: gravity does not move
  double period_mean = 0;               ///< |mean over a period|, g0
  std::optional<WorstWindowMean> worst;  ///< M(window)
  std::optional<TimeToEpsilon> time_to;
  std::optional<double> coverage, dwell_cv, coverage_bound_s;
  std::string refused;                  ///< why the pair was not computed ("" when it was)
  std::string refused_field;            ///< the InvalidInput's field of that refusal ("outer", "resolution", ...)
  bool decided() const { return refused.empty() && worst && worst->certified && time_to && time_to->certified; }
};

namespace detail {

/// The speeds of a range, exact: lo + k step for k = 0, 1, ... while <= hi. Throws
/// InvalidInput(field) for a step <= 0, hi < lo, a grid finer than Rpm holds, or more than
/// kMaxDesignPairs values.
inline std::vector<Rpm> range_speeds(const SpeedRange& r, const std::string& field) {
  const std::string shown = r.lo.str() + ":" + r.hi.str() + " step " + r.step.str();
  if (!(r.step.num() > 0)) throw InvalidInput("step", r.step.str(), "not a positive step", "a speed step > 0 rpm");
  const __int128 den = std::lcm(std::lcm(r.lo.den(), r.hi.den()), r.step.den());
  if (den > Rpm::kMaxDenominator) throw InvalidInput(field, shown, "the grid's speeds need more than 6 decimal places", "LO:HI and --step with at most 6 decimals");
  const __int128 lo = static_cast<__int128>(r.lo.num()) * (den / r.lo.den()), hi = static_cast<__int128>(r.hi.num()) * (den / r.hi.den());
  const __int128 step = static_cast<__int128>(r.step.num()) * (den / r.step.den());
  if (hi < lo) throw InvalidInput(field, shown, "an empty range", "LO:HI with LO <= HI");
  if ((hi - lo) / step + 1 > static_cast<__int128>(kMaxDesignPairs))
    throw InvalidInput(field, shown, "more than " + std::to_string(kMaxDesignPairs) + " speeds", "a coarser --step or a shorter range");
  std::vector<Rpm> out;
  for (__int128 v = lo; v <= hi; v += step) out.emplace_back(static_cast<std::int64_t>(v), static_cast<std::int64_t>(den), field);
  return out;
}

/// outer / inner as a reduced fraction (p, q), q > 0; inner must not be 0.
inline std::pair<std::int64_t, std::int64_t> speed_ratio(const Rpm& outer, const Rpm& inner) {
  __int128 p = static_cast<__int128>(outer.num()) * inner.den(), q = static_cast<__int128>(outer.den()) * inner.num();
  if (q < 0) p = -p, q = -q;
  __int128 a = p < 0 ? -p : p, b = q;
  while (b != 0) a = a % b, std::swap(a, b);
  return {static_cast<std::int64_t>(p / a), static_cast<std::int64_t>(q / a)};  // |p|, q <= 1e15
}

}  // namespace detail

/// Every pair of the grid (outer-major, both in increasing order), less (0, 0), and with a tooth
/// range only the pairs that gears in it can drive. Throws InvalidInput ("outer", "inner",
/// "step") for a bad range and ("step") for more than kMaxDesignPairs pairs.
inline std::vector<DesignPair> design_pairs(const DesignRequest& r) {
  const std::vector<Rpm> outer = detail::range_speeds(r.outer, "outer"), inner = detail::range_speeds(r.inner, "inner");
  if (outer.size() * inner.size() > kMaxDesignPairs)
    throw InvalidInput("step", r.outer.step.str() + " (" + std::to_string(outer.size()) + " x " + std::to_string(inner.size()) + " pairs)",
                       "too many speed pairs", "at most " + std::to_string(kMaxDesignPairs) + " pairs per run: a coarser step or shorter ranges");
  std::vector<DesignPair> pairs;
  for (const Rpm& o : outer)
    for (const Rpm& i : inner) {
      if (o.is_zero() && i.is_zero()) continue;
      DesignPair p{o, i, std::nullopt};
      if (r.teeth) {
        if (o.is_zero() || i.is_zero()) continue;
        const auto [num, den] = detail::speed_ratio(o, i);
        if (std::max(num < 0 ? -num : num, den) > r.teeth->max) continue;
        p.teeth = smallest_teeth(Ratio(num, den), *r.teeth);
        if (!p.teeth) continue;
      }
      pairs.push_back(p);
    }
  return pairs;
}

/// The machine of one pair of the grid: its speeds, the request's frames and offset.
inline ClinostatSettings design_machine(const DesignRequest& r, const DesignPair& pair) {
  ClinostatSettings s;
  s.outer = pair.outer;
  s.inner = pair.inner;
  s.tilt_deg = r.tilt_deg;
  s.frame_angle_deg = r.frame_angle_deg;
  s.offset_m = r.offset_m;
  return s;
}

/// What a pair's windows average: the gravity, or off the centre the effective gravity at the
/// sample point. Throws InvalidInput for a machine Clinostat refuses.
inline GravitySeries design_series(const ClinostatSettings& s) {
  const Clinostat machine(s);
  return machine.has_offset() ? GravitySeries::of_effective_gravity(machine) : GravitySeries::of_gravity(machine);
}

/// One pair's numbers. Never throws for a pair the grid holds: a refusal becomes `refused`.
inline DesignRow evaluate_pair(const DesignRequest& r, const DesignPair& pair) {
  DesignRow row;
  row.pair = pair;
  if (!pair.inner.is_zero()) {
    const auto [num, den] = detail::speed_ratio(pair.outer, pair.inner);
    row.n = den == 1 ? std::to_string(num) : std::to_string(num) + "/" + std::to_string(den);
  }
  try {
    const ClinostatSettings s = design_machine(r, pair);
    const GravitySeries series = design_series(s);
    row.period_s = series.period_s();
    row.period_mean = series.period_mean().norm();
    row.worst = worst_window_mean(series, r.window_s);
    row.time_to = time_to_epsilon(series, r.epsilon, r.resolution_s, kDesignWorkPerPair);
    if (r.coverage_s) {
      if (!r.dwell)
        throw InvalidInput("coverage", report_number(*r.coverage_s), "this build of sphtroch has no HEALPix (libhealpix-cxx-dev)",
                           "coverage in a build with HEALPix");
      const DwellMap d = r.dwell(s, 0, *r.coverage_s, r.nside);
      row.coverage = d.visited_fraction;
      row.dwell_cv = d.dwell_cv;
      row.coverage_bound_s = d.bound_s;
    }
  } catch (const InvalidInput& e) {
    row.refused = e.field() + " = " + e.value() + ": " + e.problem();
    row.refused_field = e.field();
  }
  return row;
}

/// What the ranking reads of a row (the CLI's merge rebuilds it from a part's JSON).
struct DesignRank {
  int group = 2;  ///< 0: stays below from some W; 1: never below (mean over a period above epsilon); 2: refused or undecided
  double stays_s = 0, first_s = 0, coverage = -1;  ///< coverage -1: not asked
  double outer = 0, inner = 0;                     ///< rpm
};

inline DesignRank design_rank(const DesignRow& row) {
  DesignRank k;
  k.outer = row.pair.outer.value();
  k.inner = row.pair.inner.value();
  if (!row.decided()) return k;
  k.group = row.time_to->stays_below_from_s ? 0 : 1;
  if (k.group == 0) {
    k.stays_s = *row.time_to->stays_below_from_s;
    k.first_s = *row.time_to->first_s;
  }
  k.coverage = row.coverage.value_or(-1);
  return k;
}

/// The ranking of the header: true when a goes before b.
inline bool design_less(const DesignRank& a, const DesignRank& b) {
  if (a.group != b.group) return a.group < b.group;
  if (a.group == 0) {
    if (a.stays_s != b.stays_s) return a.stays_s < b.stays_s;
    if (a.first_s != b.first_s) return a.first_s < b.first_s;
    if (a.coverage != b.coverage) return a.coverage > b.coverage;
  }
  if (a.outer != b.outer) return a.outer < b.outer;
  return a.inner < b.inner;
}

/// The positions (in `ranked`, sorted by design_less) of the Pareto front of (stays_s smaller,
/// coverage larger) among the rows of group 0 with coverage; empty without coverage. Rows with
/// equal stays_s compete on coverage alone; equal (stays_s, coverage) rows are all on the front.
inline std::vector<std::size_t> pareto_front(const std::vector<DesignRank>& ranked) {
  std::vector<std::size_t> front;
  double best = -1;  // the largest coverage of the rows with shorter stays_s
  for (std::size_t k = 0; k < ranked.size() && ranked[k].group == 0;) {
    std::size_t end = k;
    double most = -1;
    for (; end < ranked.size() && ranked[end].group == 0 && ranked[end].stays_s == ranked[k].stays_s; ++end)
      most = std::max(most, ranked[end].coverage);
    if (most >= 0 && most > best) {
      for (std::size_t j = k; j < end; ++j)
        if (ranked[j].coverage == most) front.push_back(j);
      best = most;
    }
    k = end;
  }
  return front;
}

/// A speed of the recommended pair at an end of its grid range (a range of more than one speed):
/// a wider range may hold a better pair.
struct DesignEdge {
  std::string speed;  ///< "outer" or "inner"
  bool upper = true;  ///< the range's upper end (else its lower end)
};

/// The pair to use and why: the first of the ranking (design_less) when it reaches epsilon — the
/// shortest time from which every window averages below epsilon, ties broken by the first window
/// below, then coverage. How decisive: the next pair that reaches epsilon and how much later it
/// stays below; where the pick sits on the grid; with coverage, the front's pair of most coverage.
struct DesignRecommendation {
  std::size_t position = 0;                   ///< in the ranked rows (rank position + 1)
  std::optional<std::size_t> runner_up;       ///< the next ranked pair that reaches epsilon
  double lead_s = 0;                          ///< the runner-up's stays_s minus the pick's, s
  std::vector<DesignEdge> edges;              ///< the pick's speeds at an end of their range
  std::optional<std::size_t> more_coverage;   ///< the Pareto pair of largest coverage, when not the pick
};

/// The recommendation of a ranked run (`ranked` sorted by design_less, `front` its pareto_front),
/// or none when no pair reaches epsilon.
inline std::optional<DesignRecommendation> recommend_design(const DesignRequest& r, const std::vector<DesignRank>& ranked,
                                                            const std::vector<std::size_t>& front) {
  if (ranked.empty() || ranked[0].group != 0) return std::nullopt;
  DesignRecommendation rec;
  if (ranked.size() > 1 && ranked[1].group == 0) {
    rec.runner_up = 1;
    rec.lead_s = ranked[1].stays_s - ranked[0].stays_s;
  }
  const auto edge = [&](const SpeedRange& range, double speed, const char* name) {
    const double lo = range.lo.value(), hi = range.hi.value();
    if (lo == hi) return;
    if (speed == hi) rec.edges.push_back({name, true});
    else if (speed == lo) rec.edges.push_back({name, false});
  };
  edge(r.outer, ranked[0].outer, "outer");
  edge(r.inner, ranked[0].inner, "inner");
  for (const std::size_t k : front)
    if (k != 0 && (!rec.more_coverage || ranked[k].coverage > ranked[*rec.more_coverage].coverage)) rec.more_coverage = k;
  if (rec.more_coverage && ranked[*rec.more_coverage].coverage <= ranked[0].coverage) rec.more_coverage.reset();
  return rec;
}

}  // namespace sphtroch
