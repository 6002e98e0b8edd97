// sphtroch/machine/clinostat_design_output.hpp — the formats of `sphtroch clinostat design` (and of
// `clinostat merge`, which joins its parts): the request and each row as JSON, the ranked run
// (rows in the order of design_less, counts, the Pareto front) and its text. The rows are ranked
// as structs (DesignRank, clinostat_design.hpp); a part's rows read back give their ranks by
// design_rank_of_json.
//
//   sphtroch::DesignRow row;                                   // a pair's row (evaluate_pair)
//   row.pair.outer = sphtroch::Rpm(1);
//   row.pair.inner = sphtroch::Rpm(2);
//   const nlohmann::json j = sphtroch::design_row_json(row);   // {"outer": "1", "inner": "2", ...}
//   const sphtroch::DesignRank k = sphtroch::design_rank(row); // the ranking reads the struct
//   sphtroch::DesignRequest r;                                 // the grid the rows come from
//   const nlohmann::json run = sphtroch::design_run_json(r, {j}, {k});
//   run["rows"][0]["rank"];                                    // 1
//   run["recommendation"];                                     // null: no pair reaches epsilon here
//
// JSON (docs/clinostat.md): {"request", "pairs", "reach_epsilon", "never_below", "undecided",
// "certified", "pareto" (ranks), "recommendation": null | {"rank", "outer", "inner",
// "stays_below_from_s", "runner_up_rank", "lead_s", "at_edge": [{"speed", "end", "rpm"}],
// "more_coverage_rank"}, "rows": [{"outer", "inner", "n", "teeth"?, "period_s",
// "mean_over_period", "worst_window_mean" {"lower", "upper"} | null, "first_s",
// "stays_below_from_s", "coverage", "dwell_cv", "certified", "reason", "rank"}]}.
#pragma once

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/machine/clinostat_design.hpp"
#include "sphtroch/machine/clinostat_text.hpp"  // parse_rpm
#include "sphtroch/machine/rpm.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace sphtroch {

namespace design_output_detail {
inline nlohmann::json or_null(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }
/// A text cell: "-" for null, a string as it is, a number as its shortest text.
inline std::string cell(const nlohmann::json& v) {
  return v.is_null() ? "-" : v.is_string() ? v.get<std::string>() : report_number(v.get<double>());
}
}  // namespace design_output_detail

/// The request as JSON (its members name the run: every part carries it).
inline nlohmann::json design_request_json(const DesignRequest& r) {
  const auto range = [](const SpeedRange& s) { return s.lo.str() + ":" + s.hi.str(); };
  nlohmann::json j = {{"outer", range(r.outer)}, {"inner", range(r.inner)}, {"step", r.outer.step.str()},
                      {"tilt", r.tilt_deg}, {"frame_angle", r.frame_angle_deg}, {"window_s", r.window_s},
                      {"epsilon", r.epsilon}, {"resolution_s", r.resolution_s}};
  j["coverage_s"] = r.coverage_s ? nlohmann::json(*r.coverage_s) : nlohmann::json(nullptr);
  j["nside"] = r.nside;
  j["teeth"] = r.teeth ? nlohmann::json(r.teeth->str()) : nlohmann::json(nullptr);
  j["offset_m"] = r.offset_m.isZero(0) ? nlohmann::json(nullptr) : nlohmann::json{r.offset_m.x(), r.offset_m.y(), r.offset_m.z()};
  return j;
}

/// One pair's row as JSON (without its rank).
inline nlohmann::json design_row_json(const DesignRow& row) {
  using design_output_detail::or_null;
  nlohmann::json j = {{"outer", row.pair.outer.str()}, {"inner", row.pair.inner.str()}};
  j["n"] = row.n.empty() ? nlohmann::json(nullptr) : nlohmann::json(row.n);
  if (row.pair.teeth) j["teeth"] = row.pair.teeth->str();
  j["period_s"] = or_null(row.period_s);
  j["mean_over_period"] = row.period_mean;
  j["worst_window_mean"] = row.worst ? nlohmann::json{{"lower", row.worst->lower}, {"upper", row.worst->upper}} : nlohmann::json(nullptr);
  j["first_s"] = row.time_to ? or_null(row.time_to->first_s) : nlohmann::json(nullptr);
  j["stays_below_from_s"] = row.time_to ? or_null(row.time_to->stays_below_from_s) : nlohmann::json(nullptr);
  j["coverage"] = or_null(row.coverage);
  j["dwell_cv"] = or_null(row.dwell_cv);
  j["certified"] = row.decided();
  std::string reason = !row.refused.empty() ? row.refused : row.time_to ? row.time_to->reason : std::string();
  if (reason.empty() && row.worst && !row.worst->certified)
    reason = "M(W)'s bracket [" + report_number(row.worst->lower) + ", " + report_number(row.worst->upper) + "] is wider than 1e-9";
  j["reason"] = reason;
  return j;
}

/// The rank of a row read back from a part (design_row_json's members): design_rank of the row.
/// REQUIRES a row as design_row_json writes it (the merge checks that first).
inline DesignRank design_rank_of_json(const nlohmann::json& row) {
  DesignRank k;
  k.outer = parse_rpm(row.at("outer").get<std::string>(), "outer").value();
  k.inner = parse_rpm(row.at("inner").get<std::string>(), "inner").value();
  if (!row.at("certified").get<bool>()) return k;
  k.group = row.at("stays_below_from_s").is_null() ? 1 : 0;
  if (k.group == 0) {
    k.stays_s = row.at("stays_below_from_s").get<double>();
    k.first_s = row.at("first_s").get<double>();
  }
  k.coverage = row.at("coverage").is_null() ? -1 : row.at("coverage").get<double>();
  return k;
}

namespace design_output_detail {
/// The recommendation as JSON: the pick's rank, speeds and time, its lead over the runner-up, the
/// ends of the grid it sits at, the front's pair of more coverage; and the sentence the text prints.
inline nlohmann::json recommendation_json(const DesignRequest& r, const std::optional<DesignRecommendation>& rec,
                                          const nlohmann::json& rows) {
  if (!rec) return nullptr;
  const nlohmann::json& pick = rows[rec->position];
  nlohmann::json j = {{"rank", rec->position + 1}, {"outer", pick.at("outer")}, {"inner", pick.at("inner")},
                      {"stays_below_from_s", pick.at("stays_below_from_s")}};
  j["runner_up_rank"] = rec->runner_up ? nlohmann::json(*rec->runner_up + 1) : nlohmann::json(nullptr);
  j["lead_s"] = rec->runner_up ? nlohmann::json(rec->lead_s) : nlohmann::json(nullptr);
  j["at_edge"] = nlohmann::json::array();
  for (const DesignEdge& e : rec->edges) {
    const SpeedRange& range = e.speed == "outer" ? r.outer : r.inner;
    j["at_edge"].push_back({{"speed", e.speed}, {"end", e.upper ? "upper" : "lower"}, {"rpm", (e.upper ? range.hi : range.lo).str()}});
  }
  j["more_coverage_rank"] = rec->more_coverage ? nlohmann::json(*rec->more_coverage + 1) : nlohmann::json(nullptr);
  return j;
}
}  // namespace design_output_detail

/// The whole run from its rows in the pairs' order and their ranks: ranked (stable, design_less),
/// counted, the Pareto front, the recommendation (recommend_design; null when no pair reaches epsilon).
inline nlohmann::json design_run_json(const DesignRequest& r, const std::vector<nlohmann::json>& rows,
                                      const std::vector<DesignRank>& ranks) {
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return design_less(ranks[a], ranks[b]); });
  std::vector<DesignRank> ranked;
  nlohmann::json out_rows = nlohmann::json::array();
  std::size_t groups[3] = {0, 0, 0};
  for (std::size_t k = 0; k < order.size(); ++k) {
    ranked.push_back(ranks[order[k]]);
    ++groups[ranks[order[k]].group];
    nlohmann::json row = rows[order[k]];
    row["rank"] = k + 1;
    out_rows.push_back(row);
  }
  const std::vector<std::size_t> pareto = pareto_front(ranked);
  nlohmann::json front = nlohmann::json::array();
  for (const std::size_t k : pareto) front.push_back(k + 1);
  const nlohmann::json recommendation =
      design_output_detail::recommendation_json(r, recommend_design(r, ranked, pareto), out_rows);
  return {{"request", design_request_json(r)}, {"pairs", rows.size()}, {"reach_epsilon", groups[0]},
          {"never_below", groups[1]}, {"undecided", groups[2]}, {"certified", groups[2] == 0}, {"pareto", front},
          {"recommendation", recommendation}, {"rows", out_rows}};
}

namespace design_output_detail {
/// The recommendation for people: which pair, why, how decisive, and what the grid's edge suggests.
inline void write_recommendation(std::ostream& out, const nlohmann::json& run) {
  const nlohmann::json& q = run.at("request");
  const nlohmann::json& rec = run.at("recommendation");
  if (rec.is_null()) {
    out << "recommendation: none: no pair of the grid reaches epsilon " << cell(q.at("epsilon"))
        << " g0 (wider or faster speed ranges, or a larger --epsilon)\n";
    return;
  }
  const nlohmann::json& pick = run.at("rows")[rec.at("rank").get<std::size_t>() - 1];
  out << "recommendation: rank " << rec.at("rank").get<std::size_t>() << ", outer " << cell(pick.at("outer")) << " rpm, inner "
      << cell(pick.at("inner")) << " rpm (n = " << cell(pick.at("n")) << "): every window of " << cell(pick.at("stays_below_from_s"))
      << " s or longer averages below " << cell(q.at("epsilon")) << " g0, the shortest such time of the "
      << run.at("reach_epsilon").get<std::size_t>() << " pairs that reach epsilon";
  if (rec.at("runner_up_rank").is_null()) out << " (the only one)\n";
  else if (rec.at("lead_s").get<double>() == 0) out << " (tied with rank " << rec.at("runner_up_rank").get<std::size_t>() << ")\n";
  else out << " (rank " << rec.at("runner_up_rank").get<std::size_t>() << " needs " << cell(rec.at("lead_s")) << " s more)\n";
  for (const nlohmann::json& e : rec.at("at_edge"))
    out << "  at the grid's edge: " << e.at("speed").get<std::string>() << " " << cell(e.at("rpm")) << " rpm is the "
        << e.at("end").get<std::string>() << " end of --" << e.at("speed").get<std::string>() << " " << cell(q.at(e.at("speed").get<std::string>()))
        << ": a wider range may hold a better pair\n";
  if (!rec.at("more_coverage_rank").is_null()) {
    const nlohmann::json& more = run.at("rows")[rec.at("more_coverage_rank").get<std::size_t>() - 1];
    out << "  for more coverage: rank " << more.at("rank").get<std::size_t>() << " (outer " << cell(more.at("outer")) << ", inner "
        << cell(more.at("inner")) << " rpm) covers " << cell(more.at("coverage")) << " of the cells, below epsilon from "
        << cell(more.at("stays_below_from_s")) << " s\n";
  }
}
}  // namespace design_output_detail

/// The run for people: the request, the counts, the first `top` rows and the Pareto front.
inline void write_design_text(std::ostream& out, const nlohmann::json& run, std::size_t top) {
  using design_output_detail::cell;
  const nlohmann::json& q = run.at("request");
  out << "clinostat design: " << run.at("pairs").get<std::size_t>() << " speed pairs (outer " << cell(q.at("outer")) << ", inner "
      << cell(q.at("inner")) << " rpm, step " << cell(q.at("step")) << " rpm" << (q.at("teeth").is_null() ? "" : ", gear-driven, teeth " + cell(q.at("teeth")))
      << "), tilt " << cell(q.at("tilt")) << " deg, frame angle " << cell(q.at("frame_angle")) << " deg\n"
      << "epsilon " << cell(q.at("epsilon")) << " g0 (windows in steps of " << cell(q.at("resolution_s")) << " s): "
      << run.at("reach_epsilon").get<std::size_t>() << " pairs reach it, " << run.at("never_below").get<std::size_t>()
      << " never do (the mean over a period is above it), " << run.at("undecided").get<std::size_t>() << " not certified\n"
      << "rank  outer  inner  n  period_s  M(" << cell(q.at("window_s")) << " s) upper  first_s  stays_below_from_s"
      << (q.at("coverage_s").is_null() ? "" : "  coverage(" + cell(q.at("coverage_s")) + " s)") << "\n";
  const nlohmann::json& rows = run.at("rows");
  for (std::size_t k = 0; k < rows.size() && k < top; ++k) {
    const nlohmann::json& r = rows[k];
    out << r.at("rank").get<std::size_t>() << "  " << cell(r.at("outer")) << "  " << cell(r.at("inner")) << "  " << cell(r.at("n"))
        << (r.contains("teeth") ? " (teeth " + cell(r.at("teeth")) + ")" : "") << "  " << cell(r.at("period_s")) << "  "
        << (r.at("worst_window_mean").is_null() ? "-" : cell(r.at("worst_window_mean").at("upper"))) << "  " << cell(r.at("first_s"))
        << "  " << cell(r.at("stays_below_from_s")) << (q.at("coverage_s").is_null() ? "" : "  " + cell(r.at("coverage")))
        << (r.at("certified").get<bool>() ? "" : "  NOT CERTIFIED: " + r.at("reason").get<std::string>()) << "\n";
  }
  if (rows.size() > top) out << "... " << rows.size() - top << " more (--top N, or --json for every pair)\n";
  if (!q.at("coverage_s").is_null()) {
    out << "Pareto front (shorter time to epsilon, larger coverage): ranks";
    for (const auto& k : run.at("pareto")) out << " " << k.get<std::size_t>();
    out << "\n";
  }
  design_output_detail::write_recommendation(out, run);
}

}  // namespace sphtroch
