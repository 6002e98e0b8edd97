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
//   const nlohmann::json run = sphtroch::design_run_json(nlohmann::json::object(), {j}, {k});
//   run["rows"][0]["rank"];                                    // 1
//
// JSON (docs/clinostat.md): {"request", "pairs", "reach_epsilon", "never_below", "undecided",
// "certified", "pareto" (ranks), "rows": [{"outer", "inner", "n", "teeth"?, "period_s",
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

/// The whole run from its rows in the pairs' order and their ranks: ranked (stable, design_less),
/// counted, the Pareto front.
inline nlohmann::json design_run_json(const nlohmann::json& request, const std::vector<nlohmann::json>& rows,
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
  nlohmann::json front = nlohmann::json::array();
  for (const std::size_t k : pareto_front(ranked)) front.push_back(k + 1);
  return {{"request", request}, {"pairs", rows.size()}, {"reach_epsilon", groups[0]}, {"never_below", groups[1]},
          {"undecided", groups[2]}, {"certified", groups[2] == 0}, {"pareto", front}, {"rows", out_rows}};
}

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
}

}  // namespace sphtroch
