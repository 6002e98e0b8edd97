// sphtroch clinostat design | clinostat merge — choosing a clinostat's speeds: every pair of a speed
// grid ranked by its time to epsilon, with M(window) and coverage, and the Pareto front of (time
// to epsilon, coverage) (machine/clinostat_design.hpp does the work); a grid divided with
// --shard I/K and its JSON parts joined back into the bytes of one run.
//
// One path makes both outputs (machine/clinostat_design_output.hpp): the rows as JSON (unranked,
// the pairs' order) with their ranks (structs), then design_run_json() ranks them and writes the
// whole; `merge` rebuilds the rows and their ranks from the parts and calls the same function, so
// a merged run equals the unsharded one byte for byte.
#include "cli_common.hpp"
#include "dwell_input.hpp"
#include "shard_parts.hpp"

#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/core/shard.hpp"
#include "sphtroch/io/input_file.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/machine/clinostat_design.hpp"
#include "sphtroch/machine/clinostat_design_output.hpp"
#include "sphtroch/machine/clinostat_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>

namespace sphtroch::cli {

namespace {

struct DesignOptions {
  std::string outer, inner, step, window, epsilon, resolution, coverage, nside, teeth, tilt, frame_angle, offset, top, threads, shard,
      output;
  bool json = false;
};

constexpr std::size_t kMaxDesignPartBytes = std::size_t(1) << 27;  // 128 MiB: 100000 rows are ~40 MB
constexpr std::size_t kMaxDesignNside = 64;

SpeedRange parse_speed_range(const std::string& text, const std::string& step, const std::string& field) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) throw InvalidInput(field, text, "not a range", "LO:HI in rpm, e.g. 0.5:5");
  return {parse_rpm(text.substr(0, colon), field), parse_rpm(text.substr(colon + 1), field), parse_rpm(step, "step")};
}

double parse_design_number(const std::string& text, const std::string& field, double max, const std::string& valid) {
  const std::optional<double> v = parse_number(text);
  if (!v || !(*v > 0) || *v > max) throw InvalidInput(field, text, "not a positive number in range", valid);
  return *v;
}

/// The request as parsed, and the same as JSON (its members name the run: every part carries it).
DesignRequest read_design_request(const DesignOptions& o) {
  if (o.outer.empty() || o.inner.empty() || o.step.empty() || o.window.empty() || o.epsilon.empty())
    throw UsageError{"clinostat design: give --outer LO:HI --inner LO:HI --step RPM --window S --epsilon E (see docs/clinostat.md)"};
  DesignRequest r;
  r.outer = parse_speed_range(o.outer, o.step, "outer");
  r.inner = parse_speed_range(o.inner, o.step, "inner");
  r.window_s = parse_design_number(o.window, "window", 1e9, "seconds in (0, 1e9]");
  r.epsilon = parse_design_number(o.epsilon, "epsilon", 1e9, "1e-12 <= epsilon <= 1e9 (units of g0)");
  if (r.epsilon < kMinEpsilon) throw InvalidInput("epsilon", o.epsilon, "below the rounding of the mean over a period", "1e-12 <= epsilon <= 1e9 (units of g0)");
  if (!o.resolution.empty()) r.resolution_s = parse_design_number(o.resolution, "resolution", 1e6, "seconds in (0, 1e6]");
  if (!o.coverage.empty()) r.coverage_s = parse_design_number(o.coverage, "coverage", 1e12, "seconds in (0, 1e12]");
  if (!o.nside.empty()) {
    if (!r.coverage_s) throw UsageError{"--nside = " + o.nside + ": only with --coverage; valid: --coverage S --nside K"};
    // Each worker holds a map of 12 nside^2 cells (four arrays of doubles): 64 keeps a worker's maps under 2 MB.
    r.nside = static_cast<int>(parse_count(o.nside, "nside", 1, kMaxDesignNside));
    if ((r.nside & (r.nside - 1)) != 0) throw InvalidInput("nside", o.nside, "not a power of two", "1, 2, 4, ..., 64");
  }
  r.dwell = &dwell_map_by_plugin;  // HEALPix opened only when a coverage is asked
  if (r.coverage_s) require_dwell_maps("coverage", o.coverage);  // refused now, not by every pair
  if (!o.teeth.empty()) r.teeth = parse_tooth_range(o.teeth, "teeth");
  if (!o.tilt.empty()) r.tilt_deg = parse_degrees(o.tilt, "tilt", "[0, 180] degrees");
  if (!o.frame_angle.empty()) r.frame_angle_deg = parse_degrees(o.frame_angle, "frame-angle", "[0, 180] degrees");
  if (!o.offset.empty()) r.offset_m = parse_offset(o.offset, "offset");
  ClinostatSettings check;  // the frames and the offset, checked up front as the single-machine command checks them
  check.outer = Rpm(1);
  check.tilt_deg = r.tilt_deg;
  check.frame_angle_deg = r.frame_angle_deg;
  check.offset_m = r.offset_m;
  const Clinostat checked(check);
  static_cast<void>(checked);
  return r;
}

/// The request a part or a run names, read back from its JSON (as a run writes it).
DesignRequest request_from_json(const nlohmann::json& j) {
  DesignOptions o;
  o.outer = j.at("outer").get<std::string>();
  o.inner = j.at("inner").get<std::string>();
  o.step = j.at("step").get<std::string>();
  o.window = number_text(j.at("window_s").get<double>());
  o.epsilon = number_text(j.at("epsilon").get<double>());
  o.resolution = number_text(j.at("resolution_s").get<double>());
  if (!j.at("coverage_s").is_null()) {
    o.coverage = number_text(j.at("coverage_s").get<double>());
    o.nside = std::to_string(j.at("nside").get<int>());
  }
  if (!j.at("teeth").is_null()) o.teeth = j.at("teeth").get<std::string>();
  o.tilt = number_text(j.at("tilt").get<double>());
  o.frame_angle = number_text(j.at("frame_angle").get<double>());
  if (!j.at("offset_m").is_null()) {
    const nlohmann::json& v = j.at("offset_m");
    o.offset = number_text(v.at(0).get<double>()) + "," + number_text(v.at(1).get<double>()) + "," + number_text(v.at(2).get<double>());
  }
  const DesignRequest r = read_design_request(o);
  if (design_request_json(r).dump() != j.dump())  // as text: 90 and 90.0 compare equal as numbers
    throw InvalidInput("shard", "\"request\" " + brief_json(j), "not written as the run writes it", "the request of sphtroch clinostat design");
  return r;
}

void finish_run(const nlohmann::json& run, const std::string& output, bool json, std::size_t top) {
  write_output(output, [&](std::ostream& out) {
    if (json) out << run.dump(2) << "\n";
    else write_design_text(out, run, top);
  });
  if (!run.at("certified").get<bool>())
    throw UncertifiedResult{"clinostat design: " + std::to_string(run.at("undecided").get<std::size_t>()) +
                            " pair(s) not certified (refused or past the work bound; their rows say why), the ranking leaves them last"};
}

/// InvalidInput (exit 2) when every pair that searches (all but those whose mean over a period is
/// above epsilon, marked "-") was refused for the same option of the request (--window,
/// --epsilon, --resolution, --coverage, --nside): the option, not the grid, is out of range.
void refuse_option_every_pair_refuses(const DesignOptions& o, const std::vector<std::string>& refused_by,
                                      const std::vector<nlohmann::json>& rows) {
  const std::vector<std::pair<std::string, const std::string*>> options = {
      {"window", &o.window}, {"epsilon", &o.epsilon}, {"resolution", &o.resolution}, {"coverage", &o.coverage}, {"nside", &o.nside}};
  std::size_t first = 0;
  while (first < refused_by.size() && refused_by[first] == "-") ++first;
  if (first == refused_by.size()) return;
  for (const std::string& f : refused_by)
    if (f != "-" && f != refused_by[first]) return;
  for (const auto& [field, text] : options)
    if (refused_by[first] == field)
      throw InvalidInput(field, *text, "every pair of the grid that searches refuses it: " + rows[first].at("reason").get<std::string>(),
                         "a value the machines of the grid accept (the reason names the bound)");
}

void run_design(const DesignOptions& o) {
  const DesignRequest r = read_design_request(o);
  const std::vector<DesignPair> all = design_pairs(r);
  if (all.empty())
    throw o.teeth.empty() ? InvalidInput("outer", o.outer, "no machine on the grid (outer and inner both 0 is not one)", "a grid with a speed not 0")
                          : InvalidInput("teeth", o.teeth, "no speed pair of the grid that gears in the range drive", "a grid with such a pair");
  std::optional<Shard> shard;
  if (!o.shard.empty()) {
    if (!o.json) throw UsageError{"--shard = " + o.shard + ": a part is JSON; valid: --shard I/K --json -o part.json, joined by sphtroch clinostat merge"};
    shard = parse_shard(o.shard, all.size(), "the pairs (" + std::to_string(all.size()) + ")");
  }
  const auto [begin, end] = shard ? shard_range(all.size(), *shard) : std::pair<std::size_t, std::size_t>{0, all.size()};
  const std::size_t top = o.top.empty() ? 20 : parse_count(o.top, "top", 1, kMaxDesignPairs);
  std::vector<nlohmann::json> rows(end - begin);
  std::vector<DesignRank> ranks(rows.size());
  std::vector<std::string> refused_by(rows.size());  // the option a row's refusal names ("" for none)
  parallel_for(rows.size(), parse_threads(o.threads), [&](std::size_t k) {
    const DesignRow row = evaluate_pair(r, all[begin + k]);
    // A pair whose mean over a period is above epsilon never searches: neutral ("-").
    refused_by[k] = row.refused.empty() && row.time_to && !row.time_to->first_s && row.time_to->certified ? "-" : row.refused_field;
    rows[k] = design_row_json(row);
    ranks[k] = design_rank(row);
  });
  refuse_option_every_pair_refuses(o, refused_by, rows);
  if (!shard) return finish_run(design_run_json(r, rows, ranks), o.output, o.json, top);
  nlohmann::json part = {{"request", design_request_json(r)}, {"shard", shard->str()}, {"digest", std::string(16, '0')}, {"rows", rows}};
  write_output(o.output, [&](std::ostream& out) { out << signed_part(part.dump(2) + "\n"); });
  std::size_t undecided = 0;
  for (const nlohmann::json& row : rows) undecided += row.at("certified").get<bool>() ? 0 : 1;
  if (undecided > 0)
    throw UncertifiedResult{"clinostat design: part " + shard->str() + ": " + std::to_string(undecided) +
                            " pair(s) not certified (refused or past the work bound; their rows say why)"};
}

/// One part: checked on its own (members, request, digest, its rows the pairs of its place).
struct DesignPart {
  std::string path;
  nlohmann::json request;
  Shard shard;
  std::vector<nlohmann::json> rows;
};

const std::string kDesignPart = "the JSON of sphtroch clinostat design ... --shard I/K --json";

/// Refuses (InvalidInput "shard") a row whose period or mean over a period is not the machine's
/// (computed again: a 25-point transform, no search).
void check_cheap_numbers(const nlohmann::json& row, const DesignRequest& r, const DesignPair& pair, const std::string& where) {
  std::optional<GravitySeries> series;
  try {
    series.emplace(design_series(design_machine(r, pair)));
  } catch (const InvalidInput&) {
    return;  // a pair the run refused: its row says so
  }
  const std::optional<double> period = series->period_s();
  if (row.at("period_s").is_null() != !period || (period && row.at("period_s").get<double>() != *period))
    throw InvalidInput("shard", where + "\"period_s\" " + brief_json(row.at("period_s")), "not the machine's period",
                       period ? number_text(*period) : "null");
  if (row.at("mean_over_period").get<double>() != series->period_mean().norm())
    throw InvalidInput("shard", where + "\"mean_over_period\" " + brief_json(row.at("mean_over_period")), "not the machine's mean over a period",
                       number_text(series->period_mean().norm()));
}

/// Refuses (InvalidInput "shard") a row that is not laid out as the run writes it for `pair`:
/// its members, the pair's speeds and teeth, every number finite and in range, its period and mean
/// over a period the machine's (check_cheap_numbers). The digest shows an edit of the part's bytes
/// but is no signature: an edit of the searched numbers (M(W), the times, the coverage) with the
/// digest computed again is not seen.
void check_design_row(const nlohmann::json& row, const DesignRequest& r, const DesignPair& pair, const std::string& where) {
  const bool coverage_asked = r.coverage_s.has_value();
  std::vector<std::string> names = {"outer", "inner", "n", "period_s", "mean_over_period", "worst_window_mean", "first_s",
                                    "stays_below_from_s", "coverage", "dwell_cv", "certified", "reason"};
  if (pair.teeth) names.push_back("teeth");
  check_members(row, where, names);
  if (row.at("outer") != pair.outer.str() || row.at("inner") != pair.inner.str() || (pair.teeth && row.at("teeth") != pair.teeth->str()))
    throw InvalidInput("shard", where + "outer " + brief_json(row.at("outer")) + ", inner " + brief_json(row.at("inner")),
                       "not the pair of its place", "outer " + pair.outer.str() + ", inner " + pair.inner.str());
  const auto optional_number = [&](const char* key, double lo, double hi) {
    if (!row.at(key).is_null()) number_member(row, where, key, lo, hi);
  };
  optional_number("period_s", 0, 1e13);
  number_member(row, where, "mean_over_period", 0, 10);
  optional_number("first_s", 0, 1e13);
  optional_number("stays_below_from_s", 0, 1e13);
  optional_number("coverage", 0, 1);
  optional_number("dwell_cv", 0, 1e7);
  const nlohmann::json& worst = row.at("worst_window_mean");
  if (!worst.is_null()) {
    check_members(worst, where + "\"worst_window_mean\"", {"lower", "upper"});
    number_member(worst, where, "upper", number_member(worst, where, "lower", 0, 10), 10);
  }
  if (!row.at("first_s").is_null() && !row.at("stays_below_from_s").is_null() &&
      row.at("first_s").get<double>() > row.at("stays_below_from_s").get<double>())
    throw InvalidInput("shard", where + "\"first_s\" " + brief_json(row.at("first_s")), "after \"stays_below_from_s\"", "first_s <= stays_below_from_s");
  const std::string n = pair.inner.is_zero() ? std::string() : [&] {
    const auto [num, den] = detail::speed_ratio(pair.outer, pair.inner);
    return den == 1 ? std::to_string(num) : std::to_string(num) + "/" + std::to_string(den);
  }();
  if (n.empty() ? !row.at("n").is_null() : row.at("n") != n)
    throw InvalidInput("shard", where + "\"n\" " + brief_json(row.at("n")), "not outer / inner", n.empty() ? "null" : n);
  const bool certified = bool_member(row, where, "certified");
  if (certified && row.at("coverage").is_null() == coverage_asked)
    throw InvalidInput("shard", where + "\"coverage\" " + brief_json(row.at("coverage")), "not what the request asks",
                       coverage_asked ? "a share of cells (the request has coverage_s)" : "null (the request has no coverage_s)");
  for (const char* key : {"period_s", "mean_over_period", "first_s", "stays_below_from_s", "coverage", "dwell_cv"})
    if (row.at(key).is_number_integer())  // the run writes doubles: 60.0, not 60
      throw InvalidInput("shard", where + "\"" + key + "\" " + brief_json(row.at(key)), "not written as the run writes it", "a number with a decimal point");
  if (!row.at("reason").is_string()) throw InvalidInput("shard", where + "\"reason\" " + brief_json(row.at("reason")), "not text", "a reason");
  if (certified && (worst.is_null() || row.at("first_s").is_null() != row.at("stays_below_from_s").is_null()))
    throw InvalidInput("shard", where + "\"certified\" true", "without the numbers a certified row has", "M(W), and first_s and stays_below_from_s both or neither");
  check_cheap_numbers(row, r, pair, where);
}

DesignPart read_design_part(const std::string& path, const std::string& text) {
  DesignPart p;
  p.path = path;
  try {
    const nlohmann::json j = parse_part_json(text);
    check_members(j, "the part", {"request", "shard", "digest", "rows"});
    p.request = j.at("request");
    const DesignRequest r = request_from_json(p.request);
    const std::vector<DesignPair> all = design_pairs(r);
    const std::string shard = j.at("shard").get<std::string>();
    p.shard = parse_shard(shard, all.size(), "the pairs (" + std::to_string(all.size()) + ")");
    if (shard != p.shard.str()) throw InvalidInput("shard", shard, "not written as the run writes it", "I/K");
    const auto [begin, end] = shard_range(all.size(), p.shard);
    const nlohmann::json& rows = j.at("rows");
    if (!rows.is_array() || rows.size() != end - begin)
      throw InvalidInput("shard", "\"rows\"", "not one row per pair of the part", std::to_string(end - begin) + " rows");
    for (std::size_t k = 0; k < rows.size(); ++k) {
      check_design_row(rows[k], r, all[begin + k], "row " + std::to_string(k + 1) + ": ");
      p.rows.push_back(rows[k]);
    }
    check_part_digest(path, text, j.at("digest").get<std::string>(), kDesignPart + " (unedited)");
  } catch (const nlohmann::json::exception&) {
    throw InvalidInput("shard", path, "not a clinostat design part", kDesignPart);
  } catch (const InvalidInput& e) {
    if (e.field() == "shard" && e.value() == path) throw;
    throw InvalidInput("shard", path, e.value() + ": " + e.problem(), e.valid_range());
  }
  return p;
}

void run_merge(const std::vector<std::string>& paths, const std::string& output, bool json, const std::string& top_text) {
  const std::size_t top = top_text.empty() ? 20 : parse_count(top_text, "top", 1, kMaxDesignPairs);
  std::vector<DesignPart> parts;
  for (const std::string& p : paths) parts.push_back(read_design_part(p, read_whole_input(p, "shard", kMaxDesignPartBytes)));
  std::stable_sort(parts.begin(), parts.end(), [](const DesignPart& a, const DesignPart& b) { return a.shard.index < b.shard.index; });
  std::vector<ShardName> names;
  for (const DesignPart& p : parts) names.push_back({p.path, p.shard.index, p.shard.count, {{"request", p.request.dump()}}});
  check_shard_set(names);
  std::vector<nlohmann::json> rows;
  for (const DesignPart& p : parts) rows.insert(rows.end(), p.rows.begin(), p.rows.end());
  std::vector<DesignRank> ranks;
  for (const nlohmann::json& row : rows) ranks.push_back(design_rank_of_json(row));  // the rows were checked as written
  finish_run(design_run_json(request_from_json(parts[0].request), rows, ranks), output, json, top);
}

}  // namespace

void register_clinostat_design(CLI::App& clinostat, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<DesignOptions>();
  CLI::App* cmd = clinostat.add_subcommand("design", "choose the speeds: every pair of a grid ranked by time to epsilon, with coverage");
  cmd->footer(
      "Every pair (outer, inner) of LO, LO + step, ..., HI (exact; the pair 0, 0 left out), each with its\n"
      "time to epsilon (the shortest window from which every longer window averages below epsilon), M(W)\n"
      "for --window W, and with --coverage D the share of HEALPix cells visited over [0, D]. Ranked by\n"
      "that time, then the first window below, then coverage; the Pareto front of (time, coverage). The\n"
      "recommendation: rank 1 when it reaches epsilon, its lead over the next, and whether it sits at an\n"
      "end of a speed range (then a wider range may hold a better pair). --offset X,Y,Z (metres): each\n"
      "pair averages the effective gravity at that sample point (gravity plus the frames' accelerations).\n"
      "--teeth MIN..MAX: a gear-driven machine, only ratios outer/inner of two tooth counts in the range.\n"
      "Cost: at most 100000 pairs per run; per pair ~1 ms at typical speeds, at most M(W)'s 4e6 pieces\n"
      "(~3 s: fast speeds with a short window) and 3e6 window-mean evaluations for the time to epsilon\n"
      "(then the row says it is not certified, exit 3), plus the coverage walk (--nside <= 64).\n"
      "--shard I/K computes part I of K of the pairs (JSON); sphtroch clinostat merge joins the parts.\n"
      "Example: sphtroch clinostat design --outer 0.5:5 --inner 0.5:5 --step 0.5 --window 3600 --epsilon 0.01");
  cmd->add_option("--outer", o->outer, "outer speeds LO:HI, rpm")->type_name("RPM:RPM");
  cmd->add_option("--inner", o->inner, "inner speeds LO:HI, rpm")->type_name("RPM:RPM");
  cmd->add_option("--step", o->step, "the grid's step, rpm (both ranges)")->type_name("RPM");
  cmd->add_option("--window", o->window, "the experiment's window W: M(W) of each pair, seconds")->type_name("S");
  cmd->add_option("--epsilon", o->epsilon, "the bound on the averaged gravity, units of g0")->type_name("G0");
  cmd->add_option("--resolution", o->resolution, "the step of W for the time to epsilon, seconds (default 1)")->type_name("S");
  cmd->add_option("--coverage", o->coverage, "also the share of cells visited over this many seconds")->type_name("S");
  cmd->add_option("--nside", o->nside, "HEALPix nside for --coverage, a power of two 1 .. 1024 (default 8)")->type_name("K");
  cmd->add_option("--teeth", o->teeth, "MIN..MAX: a gear-driven machine's tooth counts")->type_name("MIN..MAX");
  cmd->add_option("--tilt", o->tilt, "outer axis from the vertical, degrees in [0, 180] (default 90)")->type_name("DEG");
  cmd->add_option("--frame-angle", o->frame_angle, "angle between the axes, degrees in [0, 180] (default 90)")->type_name("DEG");
  cmd->add_option("--offset", o->offset, "the sample point X,Y,Z in metres (sample frame; default the centre): its effective gravity is averaged")
      ->type_name("X,Y,Z");
  cmd->add_option("--top", o->top, "rows of the text report (default 20)")->type_name("N");
  cmd->add_option("--threads", o->threads, "worker threads (1 .. 1024; default: all cores)")->type_name("N");
  cmd->add_option("--shard,--slice", o->shard, "only part I of K of the pairs (JSON; join with clinostat merge)")->type_name("I/K");
  cmd->add_flag("--json", o->json, "every pair as JSON (schema: docs/clinostat.md)");
  add_output_option(*cmd, o->output, "the report");
  actions.emplace_back(cmd, [o] { run_design(*o); });

  auto paths = std::make_shared<std::vector<std::string>>();
  auto merge = std::make_shared<DesignOptions>();
  CLI::App* join = clinostat.add_subcommand("merge", "join the JSON parts of clinostat design --shard I/K");
  join->footer("Parts in any order; the result is byte for byte what the unsharded run prints.\n"
               "Example: sphtroch clinostat merge --json -o design.json part-*.json");
  join->add_option("parts", *paths, "the part files (JSON)")->type_name("FILE")->required();
  join->add_flag("--json", merge->json, "the joined run as JSON (else the text report)");
  join->add_option("--top", merge->top, "rows of the text report (default 20)")->type_name("N");
  add_output_option(*join, merge->output, "the joined run");
  actions.emplace_back(join, [paths, merge] {
    check_distinct_files({{merge->output, "--output"}}, [&] {
      std::vector<NamedFile> in;
      for (const auto& p : *paths) in.push_back({p, "shard"});
      return in;
    }());
    run_merge(*paths, merge->output, merge->json, merge->top);
  });
}

}  // namespace sphtroch::cli
