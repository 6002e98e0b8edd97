// sphtroch synth fit — ranked trains whose curve passes nearest an untimed path, optionally with a
// wanted node / cusp count confirmed by classify (synthesis/path_fit.hpp, exact/path_fit_output.hpp);
// and the merge of its shards. Parsing and printing only. CGAL: a separate translation unit.
#include "cli_common.hpp"
#include "synth_ratios.hpp"

#include "sphtroch/classify.hpp"
#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/synthesis.hpp"
#include "sphtroch/io/input_file.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/polyline_input.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>
#include <ostream>
#include <sstream>
#include <utility>

namespace sphtroch::cli {

namespace {

struct FitCommandOptions {
  std::string input, output, n, ratios, teeth, shard, nodes, cusps, candidates, max_deviation, node_at, node_tolerance, min_margin;
  bool json = false;
};

FitOptions fit_options(const FitCommandOptions& o) {
  FitOptions f;
  if (!o.nodes.empty()) f.nodes = static_cast<std::int64_t>(parse_count(o.nodes, "nodes", 0, kMaxWantedCount));
  if (!o.cusps.empty()) f.cusps = static_cast<std::int64_t>(parse_count(o.cusps, "cusps", 0, kMaxWantedCount));
  if (!o.candidates.empty()) f.max_candidates = parse_count(o.candidates, "candidates", 1, 1000);
  if (!o.max_deviation.empty()) {
    const double v = parse_angle(o.max_deviation, "max-deviation");
    if (!(v > 0)) throw InvalidInput("max-deviation", o.max_deviation, "not a positive angle", "an angle > 0 (radians, or e.g. 1deg, pi/180)");
    f.max_deviation = v;
  }
  if (!o.node_at.empty()) f.node_at = parse_unit_point(o.node_at, "node-at");
  if (!o.node_tolerance.empty()) {
    if (o.node_at.empty()) throw UsageError{"--node-tolerance = " + o.node_tolerance + ": applies to a node point; valid: with --node-at X,Y,Z"};
    const double v = parse_angle(o.node_tolerance, "node-tolerance");
    if (!(v > 0 && v <= Constants<double>::pi()))
      throw InvalidInput("node-tolerance", o.node_tolerance, "not an angle in (0, pi]", "an angle in (0, pi] (radians, or e.g. 0.01deg)");
    f.node_tolerance = v;
  }
  if (!o.min_margin.empty()) {
    const double v = parse_angle(o.min_margin, "min-margin");
    if (!(v >= 0 && v <= kMaxFitMinMargin))
      throw InvalidInput("min-margin", o.min_margin, "outside the valid range", "an angle in [0, 0.785] (radians, or e.g. 0.1deg)");
    f.min_margin = v;
  }
  return f;
}



/// The options a fit computed with, as text (part of the run's fingerprint).
std::string options_text(const FitOptions& f) {
  std::string node = "anywhere";
  if (f.node_at)
    node = number_text(f.node_at->x()) + "," + number_text(f.node_at->y()) + "," + number_text(f.node_at->z()) + " within " +
           number_text(f.node_tolerance);
  return "nodes " + (f.nodes ? std::to_string(*f.nodes) : "any") + " cusps " + (f.cusps ? std::to_string(*f.cusps) : "any") +
         " max_deviation " + number_text(f.max_deviation) + " candidates " + std::to_string(f.max_candidates) + " node " + node +
         (f.min_margin > 0 ? " min_margin " + number_text(f.min_margin) : "");
}

/// Shard members the merge needs besides the unsharded output: the run's fingerprint, the part's
/// digest (filled in by signed_part), the candidate bound and every ratio's reason.
std::string shard_fields(const std::vector<RatioFit>& all, const FitOptions& f, const std::string& run) {
  nlohmann::json reasons = nlohmann::json::array();
  for (const RatioFit& rf : all) reasons.push_back(rf.reason);
  return "\"run\": \"" + run + "\", " + digest_placeholder() + "\"max_candidates\": " + std::to_string(f.max_candidates) +
         ", \"reasons\": " + reasons.dump() + ", ";
}

void run_fit(const FitCommandOptions& o) {
  const RatioSet request = requested_ratios("synth fit", {o.n, o.ratios, o.teeth, o.shard}, kMaxFitWork);
  const FitOptions f = fit_options(o);
  check_distinct_files({{o.output, "--output"}}, {{o.input, "--input"}});
  const PolylineInput in = read_polyline(o.input, "input");
  const std::vector<RatioFit> all = [&] {
    try {
      return fit_with_census(in.vertices, request.ratios, f);
    } catch (const InvalidInput& e) {  // the library names its argument (points): here the file
      if (e.field() != "points") throw;
      throw InvalidInput("input", o.input, e.value() + ": " + e.problem(), e.valid_range());
    }
  }();
  const std::string fields =
      request.json_members() + (o.shard.empty() ? "" : shard_fields(all, f, run_fingerprint(in.vertices, options_text(f))));
  write_output(o.output, [&](std::ostream& out) {
    if (!o.json) out << fit_text(all, f, request.teeth);
    else if (o.shard.empty()) out << fit_json(all, f, fields, request.teeth);
    else out << signed_part(fit_json(all, f, fields, request.teeth));
  });
  for (const auto* c : ranked_candidates(all, f))
    if (!c->census.certified())
      throw UncertifiedResult{"synth fit: the census of a candidate of n = " + c->candidate.train.ratio().str() +
                              " is not certified (exit status 3; see docs/cli.md: Certified counts)"};
}

/// One shard of `synth fit --ratios P,Q --shard I/K --json`: its header and members (parsed and
/// checked), and its candidate lines as printed with their rms (kept verbatim so that the merge
/// equals the unsharded output).
struct FitShard {
  std::string path, text, run, digest;
  ShardHeader header;
  std::size_t max_candidates = 0, dropped = 0;
  std::vector<std::string> reasons;
  std::vector<Ratio> ratios;                          // each candidate's n
  std::vector<std::pair<double, std::string>> lines;  // (rms, the candidate's line as printed)
};

const std::string kFitPart = "the JSON of sphtroch synth fit --ratios P,Q | --teeth MIN..MAX --shard I/K --json";

/// One candidate as synth fit prints it (path_fit_output.hpp), every member checked; returns its n
/// and rms.
std::pair<Ratio, double> checked_candidate(const nlohmann::json& c, const std::optional<ToothRange>& range, std::size_t k) {
  std::string where = "candidate " + std::to_string(k + 1) + ": ";
  if (!c.is_object() || !c.contains("n")) throw InvalidInput("shard", where + brief_json(c), "not a candidate", "{\"n\", \"a2\", ...}");
  const Ratio n = ratio_member(c, where);
  where = "candidate " + std::to_string(k + 1) + " (n = " + n.str() + "): ";
  std::vector<std::string> names{"n", "a2", "a3", "phase", "rms", "max_deviation", "margin", "certified_margin", "counts", "census_certified"};
  if (c.contains("teeth")) names.push_back("teeth");
  if (c.contains("node_distance")) names.push_back("node_distance");
  check_members(c, where + "candidate", names);
  check_train_teeth(c, n, range);
  const double pi = Constants<double>::pi();
  number_member(c, where, "a2", 0, pi);
  number_member(c, where, "a3", 0, pi);
  number_member(c, where, "phase", 0, 2 * pi / double(n.q()));
  const double rms = number_member(c, where, "rms", 0, pi);
  number_member(c, where, "max_deviation", rms * (1 - 4 * std::numeric_limits<double>::epsilon()), pi);  // rms <= max, to rounding
  number_member(c, where, "margin", 0, pi);
  const nlohmann::json& cm = c.at("certified_margin");
  check_members(cm, where + "\"certified_margin\"", {"lower", "upper"});
  const double lower = number_member(cm, where + "\"certified_margin\" ", "lower", 0, pi);
  number_member(cm, where + "\"certified_margin\" ", "upper", lower, pi);
  if (c.contains("node_distance")) number_member(c, where, "node_distance", 0, pi);
  const nlohmann::json& k4 = c.at("counts");
  check_members(k4, where + "\"counts\"", {"nodes", "crossings", "tangencies", "cusps"});
  if (count_member(k4, where, "nodes") != count_member(k4, where, "crossings") + count_member(k4, where, "tangencies"))
    throw InvalidInput("shard", where + "\"counts\" " + brief_json(k4), "nodes != crossings + tangencies", "the census as classify counts it");
  count_member(k4, where, "cusps");
  bool_member(c, where, "census_certified");
  return {n, rms};
}

/// A part read and checked on its own: every member (InvalidInput "shard" = path naming the first
/// that is not as the run writes it). What depends on the other parts is checked by check_fit_part.
FitShard read_fit_shard(const std::string& path, const std::string& text) {
  FitShard s;
  s.path = path;
  s.text = text;
  try {
    const nlohmann::json j = parse_part_json(text);
    s.header = read_shard_header(j);
    check_members(j, "the part",
                  {s.header.set_name, "shard", "run", "digest", "max_candidates", "reasons", "candidates", "reason", "dropped"});
    s.run = j.at("run").get<std::string>();
    s.digest = j.at("digest").get<std::string>();
    if (!is_hex16(s.run)) throw InvalidInput("shard", "\"run\" " + brief_json(j.at("run")), "not a fingerprint", "16 hex digits as the run writes them");
    if (!is_hex16(s.digest)) throw InvalidInput("shard", "\"digest\" " + brief_json(j.at("digest")), "not a digest", "16 hex digits as the run writes them");
    s.max_candidates = count_member(j, "", "max_candidates");
    if (s.max_candidates < 1 || s.max_candidates > 1000)
      throw InvalidInput("shard", "\"max_candidates\" " + std::to_string(s.max_candidates), "out of range", "1 .. 1000 (--candidates)");
    s.dropped = count_member(j, "", "dropped");
    s.reasons = j.at("reasons").get<std::vector<std::string>>();
    const nlohmann::json& candidates = j.at("candidates");
    if (!candidates.is_array() || candidates.size() > s.max_candidates)
      throw InvalidInput("shard", "\"candidates\"", "more than \"max_candidates\" " + std::to_string(s.max_candidates),
                         "at most max_candidates candidates");
    std::vector<RatioFit> reasons;
    for (const std::string& r : s.reasons) reasons.push_back(RatioFit{Ratio(1), {}, r, 0});
    const std::string reason = candidates.empty() ? fit_reason(reasons) : "";
    if (!j.at("reason").is_string() || j.at("reason") != reason)
      throw InvalidInput("shard", "\"reason\" " + brief_json(j.at("reason")), "not what its \"reasons\" give",
                         "\"\" with candidates, else the ratios' reasons once each");
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const auto [n, rms] = checked_candidate(candidates[k], s.header.teeth, k);
      if (k > 0 && rms < s.lines.back().first)
        throw InvalidInput("shard", "candidate " + std::to_string(k + 1) + " rms " + number_text(rms), "not best first",
                           "candidates in increasing rms");
      s.ratios.push_back(n);
      s.lines.push_back({rms, ""});
    }
    // The lines copied into the merge: one per candidate, each the candidate it stands for.
    std::istringstream lines(text);
    std::size_t k = 0;
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("  {", 0) == 0) {
        if (line.back() == ',') line.pop_back();
        if (k >= candidates.size() || nlohmann::json::parse(line) != candidates[k])
          throw InvalidInput("shard", "candidate line " + std::to_string(k + 1), "not laid out as synth fit prints it", "one candidate per line");
        s.lines[k++].second = line;
      }
    if (k != candidates.size()) throw InvalidInput("shard", "candidate lines", "not laid out as synth fit prints it", "one candidate per line");
  } catch (const nlohmann::json::exception&) {
    throw InvalidInput("shard", path, "not a synth fit shard", kFitPart);
  } catch (const InvalidInput& e) {
    throw InvalidInput("shard", path, e.value() + ": " + e.problem(), e.valid_range());
  }
  return s;
}

/// What a part holds that depends on its place in the run (checked once the parts form one run):
/// a reason per own ratio, every candidate's n among the own ratios, with an empty reason; then
/// its digest.
void check_fit_part(const FitShard& s) {
  try {
    if (s.reasons.size() != s.header.own.size())
      throw InvalidInput("shard", "\"reasons\" of " + std::to_string(s.reasons.size()) + " ratio(s)", "not one per ratio of the part",
                         std::to_string(s.header.own.size()) + " reasons (shard " + std::to_string(s.header.index) + "/" +
                             std::to_string(s.header.count) + " of " + s.header.set + ")");
    for (std::size_t k = 0; k < s.ratios.size(); ++k) {
      const std::string where = "candidate " + std::to_string(k + 1) + ": ";
      const std::size_t at = own_ratio_index(s.header, s.ratios[k], where);
      if (!s.reasons[at].empty())
        throw InvalidInput("shard", where + "n = " + s.ratios[k].str(), "has a candidate and a reason why there is none",
                           "an empty reason for a ratio with candidates");
    }
  } catch (const InvalidInput& e) {
    throw InvalidInput("shard", s.path, e.value() + ": " + e.problem(), e.valid_range());
  }
  check_part_digest(s.path, s.text, s.digest, kFitPart + " (unedited)");
}

}  // namespace

/// The shards of `synth fit --ratios P,Q --shard I/K --json`, in any order, joined into what the
/// unsharded run prints: the candidates of all shards ranked again (stable, by rms, in ratio
/// order), the reasons of every ratio when none is left.
void run_fit_merge(const std::vector<std::string>& paths, const std::vector<std::string>& texts,
                   const std::string& output) {
  std::vector<FitShard> shards;
  for (std::size_t k = 0; k < paths.size(); ++k) shards.push_back(read_fit_shard(paths[k], texts[k]));
  std::stable_sort(shards.begin(), shards.end(), [](const auto& a, const auto& b) { return a.header.index < b.header.index; });
  std::vector<ShardName> names;
  for (const FitShard& s : shards)
    names.push_back({s.path, s.header.index, s.header.count,
                     {{s.header.set_name, nlohmann::json(s.header.set_text).dump()},
                      {"run", nlohmann::json(s.run).dump()},
                      {"max_candidates", std::to_string(s.max_candidates)}}});
  check_shard_set(names);
  for (const FitShard& s : shards) check_fit_part(s);
  std::vector<std::pair<double, std::string>> lines;
  std::vector<RatioFit> reasons;  // only the reasons matter when nothing is left
  std::size_t dropped = 0;
  for (const FitShard& s : shards) {
    lines.insert(lines.end(), s.lines.begin(), s.lines.end());
    for (const std::string& r : s.reasons) reasons.push_back(RatioFit{Ratio(1), {}, r, 0});
    if (s.dropped > std::numeric_limits<std::size_t>::max() - dropped)
      throw InvalidInput("shard", s.path, "\"dropped\" " + std::to_string(s.dropped) + ": the sum over the parts overflows",
                         "counts whose sum is below 2^64");
    dropped += s.dropped;
  }
  std::stable_sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (lines.size() > shards[0].max_candidates) lines.resize(shards[0].max_candidates);
  std::string reason = lines.empty() ? fit_reason(reasons) : "";
  std::string out = "{" + shards[0].header.set + ", \"candidates\": [";
  for (std::size_t k = 0; k < lines.size(); ++k) out += (k ? ",\n" : "\n") + lines[k].second;
  out += std::string(lines.empty() ? "" : "\n") + "], \"reason\": " + nlohmann::json(reason).dump() +
         ", \"dropped\": " + std::to_string(dropped) + "}\n";
  write_output(output, [&](std::ostream& o) { o << out; });
  for (const auto& line : lines)
    if (!nlohmann::json::parse(line.second).at("census_certified").get<bool>())
      throw UncertifiedResult{"synth merge: the census of a candidate is not certified (exit status 3; see docs/cli.md: Certified counts)"};
}

void register_synth_fit(CLI::App& synth, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<FitCommandOptions>();
  CLI::App* cmd = synth.add_subcommand("fit", "ranked trains nearest an untimed path, with a wanted node / cusp count");
  cmd->footer(
      "--input FILE: CSV with a header x,y,z (or .npy (N, 3)), 4 or more unit vectors along the wanted\n"
      "path (sampled or drawn, possibly noisy; their order is not used); - for standard input. The sun\n"
      "axis is Z. For each ratio (--n R, --teeth, --ratios P,Q) it minimises the spherical distances of the\n"
      "points to the curve. --nodes K / --cusps C keep the search inside the cells of the (a2, a3) map\n"
      "with that census; every candidate printed has it, confirmed by classify. None possible: no\n"
      "candidate and the reason (exit 0). Example: sphtroch synth fit --input path.csv --n 2 --nodes 2");
  add_ratio_set_options(*cmd, o->input, o->n, o->ratios, o->teeth, o->shard, "the path's points");
  cmd->add_option("--nodes", o->nodes, "wanted node points K (crossings and tangencies)")->type_name("N");
  cmd->add_option("--cusps", o->cusps, "wanted cusps C (0; |p| on a pitch cone; 2|p| where both meet, |n| < 1)")->type_name("N");
  cmd->add_option("--candidates", o->candidates, "at most M candidates (1 .. 1000, default 5)")->type_name("N");
  cmd->add_option("--max-deviation", o->max_deviation, "drop candidates farther than D radians from a point")->type_name("RAD");
  cmd->add_option("--node-at", o->node_at, "X,Y,Z: a node (self-crossing) wanted at this point of the sphere")->type_name("X,Y,Z");
  cmd->add_option("--node-tolerance", o->node_tolerance, "how near --node-at the certified node must be (default 1e-6 rad)")->type_name("RAD");
  cmd->add_option("--min-margin", o->min_margin, "keep candidates at least D (certified) from a change of their census (radians, or 0.1deg)")
      ->type_name("RAD");
  cmd->add_flag("--json", o->json, "{\"candidates\": [{\"n\", \"a2\", \"a3\", \"phase\", \"rms\", \"max_deviation\", "
                                   "\"margin\", \"counts\", ...}], \"reason\", \"dropped\"} (docs/cli.md: synth fit)");
  add_output_option(*cmd, o->output, "the candidates");
  actions.emplace_back(cmd, [o] { run_fit(*o); });
}

}  // namespace sphtroch::cli
