// sphtroch synth fit — ranked trains whose curve passes nearest an untimed path, optionally with a
// wanted node / cusp count confirmed by classify (synthesis/path_fit.hpp, exact/path_fit_output.hpp);
// and the merge of its shards. Parsing and printing only. CGAL: a separate translation unit.
#include "cli_common.hpp"
#include "synth_ratios.hpp"

#include "sphtroch/classify.hpp"
#include "sphtroch/exact/path_fit_output.hpp"
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

/// Bound on the estimated work of one call: the sum over the ratio set of (|p| + q)^2 (the
/// screening and the census grow with |p| and q; measured: --ratios 7,7 on 300 points 11 s).
constexpr double kMaxFitWork = 20000;

struct FitCommandOptions {
  std::string input, output, n, ratios, teeth, shard, nodes, cusps, candidates, max_deviation, node_at, node_tolerance;
  bool json = false;
};

FitOptions fit_options(const FitCommandOptions& o) {
  FitOptions f;
  if (!o.nodes.empty()) f.nodes = static_cast<std::int64_t>(parse_count(o.nodes, "nodes", 0, 100000000));
  if (!o.cusps.empty()) f.cusps = static_cast<std::int64_t>(parse_count(o.cusps, "cusps", 0, 100000000));
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
  return f;
}

std::string wanted_text(const FitOptions& f) {
  std::string s;
  if (f.nodes) s += std::to_string(*f.nodes) + " node(s)";
  if (f.cusps) s += (s.empty() ? "" : ", ") + std::to_string(*f.cusps) + " cusp(s)";
  if (f.node_at)
    s += (s.empty() ? "" : ", ") + std::string("a node within ") + number_text(f.node_tolerance) + " rad of " +
         number_text(f.node_at->x()) + "," + number_text(f.node_at->y()) + "," + number_text(f.node_at->z());
  return s.empty() ? "any counts" : s + " wanted";
}

void write_fit_text(std::ostream& out, const std::vector<RatioFit>& all, const FitOptions& f, const TeethSpec& teeth) {
  const auto ranked = ranked_candidates(all, f);
  out << "fit: " << ranked.size() << " candidate(s), " << wanted_text(f)
      << "; distances and margins in radians, best first\n";
  if (ranked.empty()) out << "no candidate: " << fit_reason(all) << "\n";
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    const FitCandidate& c = ranked[k]->candidate;
    const Classification& census = ranked[k]->census;
    out << "  " << k + 1 << ". n = " << c.train.ratio().str() << teeth_text(teeth, c.train.ratio()) << ", a2 = " << number_text(c.train.a2())
        << ", a3 = " << number_text(c.train.a3()) << ", phase = " << number_text(c.train.phase_given()) << "; rms "
        << number_text(c.rms) << ", max " << number_text(c.max_deviation) << "; margin " << number_text(c.margin) << "; "
        << census.nodes.size() << " node(s), " << census.cusps.size() << " cusp(s)"
        << (f.node_at ? "; node point " + number_text(c.node_distance) + " rad away" : "")
        << (census.certified() ? " (certified)" : " (census NOT certified)") << "\n"
        << "     plot it: sphtroch plot " << train_arguments(c.train) << " -o candidate" << k + 1 << ".svg\n";
  }
}

/// The options a fit computed with, as text (part of the run's fingerprint).
std::string options_text(const FitOptions& f) {
  std::string node = "anywhere";
  if (f.node_at)
    node = number_text(f.node_at->x()) + "," + number_text(f.node_at->y()) + "," + number_text(f.node_at->z()) + " within " +
           number_text(f.node_tolerance);
  return "nodes " + (f.nodes ? std::to_string(*f.nodes) : "any") + " cusps " + (f.cusps ? std::to_string(*f.cusps) : "any") +
         " max_deviation " + number_text(f.max_deviation) + " candidates " + std::to_string(f.max_candidates) + " node " + node;
}

/// Shard members the merge needs besides the unsharded output: the run's fingerprint, the
/// candidate bound and every ratio's reason.
std::string shard_fields(const std::vector<RatioFit>& all, const FitOptions& f, const std::string& run) {
  nlohmann::json reasons = nlohmann::json::array();
  for (const RatioFit& rf : all) reasons.push_back(rf.reason);
  return "\"run\": \"" + run + "\", \"max_candidates\": " + std::to_string(f.max_candidates) + ", \"reasons\": " +
         reasons.dump() + ", ";
}

void run_fit(const FitCommandOptions& o) {
  const RatioRequest request = requested_ratios("synth fit", o.n, o.ratios, o.teeth, o.shard, kMaxFitWork);
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
      request.json_fields + (o.shard.empty() ? "" : shard_fields(all, f, run_fingerprint(in.vertices, options_text(f))));
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << fit_json(all, f, fields, request.teeth);
    else write_fit_text(out, all, f, request.teeth);
  });
  for (const auto* c : ranked_candidates(all, f))
    if (!c->census.certified())
      throw UncertifiedResult{"synth fit: the census of a candidate of n = " + c->candidate.train.ratio().str() +
                              " is not certified (exit status 3; see docs/cli.md: Certified counts)"};
}

struct FitShard {
  std::string ratios, run;
  std::size_t index = 0, count = 0, max_candidates = 0, dropped = 0;
  std::vector<std::string> reasons;
  std::vector<std::pair<double, std::string>> lines;  // (rms, the candidate's line as printed)
};

/// A count member: an unsigned integer (not -3, 2.5 or 1e20).
std::size_t count_member(const nlohmann::json& j, const char* key) {
  const nlohmann::json& v = j.at(key);
  if (!v.is_number_unsigned()) throw InvalidInput("shard", key, "not a count", "an integer >= 0");
  return v.get<std::size_t>();
}

/// One candidate line as synth fit prints it, its values checked; returns its rms.
double checked_candidate(const std::string& line, const std::optional<ToothRange>& range) {
  const nlohmann::json c = nlohmann::json::parse(line);
  const Ratio n = parse_ratio(c.at("n").get<std::string>(), "n");
  const double pi = Constants<double>::pi();
  auto number = [&](const char* key, double lo, double hi) {
    const double v = c.at(key).get<double>();
    if (!(v >= lo && v <= hi)) throw InvalidInput("shard", std::string(key) + " " + number_text(v), "out of range", "as synth fit prints it");
    return v;
  };
  number("a2", 0, pi);
  number("a3", 0, pi);
  number("phase", 0, 2 * pi / double(n.q()));
  const double rms = number("rms", 0, pi);
  number("max_deviation", rms, pi);
  number("margin", 0, pi);
  const nlohmann::json& k = c.at("counts");
  if (count_member(k, "nodes") != count_member(k, "crossings") + count_member(k, "tangencies"))
    throw InvalidInput("shard", "counts", "nodes != crossings + tangencies", "as synth fit prints it");
  count_member(k, "cusps");
  check_train_teeth(c, n, range);
  if (c.contains("node_distance")) number("node_distance", 0, pi);
  if (!c.at("census_certified").is_boolean() || c.size() != 9u + c.contains("teeth") + c.contains("node_distance") || k.size() != 4)
    throw InvalidInput("shard", "candidate", "not as synth fit prints it", "the members of docs/cli.md: synth fit");
  return rms;
}

FitShard read_fit_shard(const std::string& path, const std::string& text) {
  const std::string valid = "the JSON of sphtroch synth fit --ratios P,Q | --teeth MIN..MAX --shard I/K --json";
  FitShard s;
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    const ShardHeader header = read_shard_header(j);
    s.ratios = header.set;
    s.index = header.index;
    s.count = header.count;
    const std::size_t ratios_here = header.ratios;
    s.run = j.at("run").get<std::string>();
    s.max_candidates = count_member(j, "max_candidates");
    s.reasons = j.at("reasons").get<std::vector<std::string>>();
    s.dropped = count_member(j, "dropped");
    const auto& candidates = j.at("candidates");
    if (s.reasons.size() != ratios_here || candidates.size() > s.max_candidates || s.max_candidates < 1 ||
        s.max_candidates > 1000)
      throw InvalidInput("shard", path, "its reasons or candidates do not fit its ratios", valid);
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("  {", 0) == 0) {
        if (line.back() == ',') line.pop_back();
        const double rms = checked_candidate(line, header.teeth);
        if (!s.lines.empty() && rms < s.lines.back().first) throw InvalidInput("shard", path, "candidates not best first", valid);
        s.lines.push_back({rms, line});
      }
    if (s.lines.size() != candidates.size()) throw InvalidInput("shard", path, "not laid out as synth fit prints it", valid);
  } catch (const nlohmann::json::exception&) {
    throw InvalidInput("shard", path, "not a synth fit shard", valid);
  } catch (const InvalidInput& e) {
    throw InvalidInput("shard", path, e.value() + ": " + e.problem(), valid);
  }
  return s;
}

}  // namespace

/// The shards of `synth fit --ratios P,Q --shard I/K --json`, in any order, joined into what the
/// unsharded run prints: the candidates of all shards ranked again (stable, by rms, in ratio
/// order), the reasons of every ratio when none is left.
void run_fit_merge(const std::vector<std::string>& paths, const std::vector<std::string>& texts,
                   const std::string& output) {
  std::vector<FitShard> shards;
  for (std::size_t k = 0; k < paths.size(); ++k) shards.push_back(read_fit_shard(paths[k], texts[k]));
  std::sort(shards.begin(), shards.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  std::vector<ShardName> names;
  for (const FitShard& s : shards) names.push_back({s.ratios, s.index, s.count, s.run + " " + std::to_string(s.max_candidates)});
  check_shard_set(names);
  std::vector<std::pair<double, std::string>> lines;
  std::vector<RatioFit> reasons;  // only the reasons matter when nothing is left
  std::size_t dropped = 0;
  for (const FitShard& s : shards) {
    lines.insert(lines.end(), s.lines.begin(), s.lines.end());
    for (const std::string& r : s.reasons) reasons.push_back(RatioFit{Ratio(1), {}, r, 0});
    dropped += s.dropped;
  }
  std::stable_sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (lines.size() > shards[0].max_candidates) lines.resize(shards[0].max_candidates);
  std::string reason = lines.empty() ? fit_reason(reasons) : "";
  std::string out = "{" + shards[0].ratios + ", \"candidates\": [";
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
  cmd->add_option("--nodes", o->nodes, "wanted node points K (crossings and tangencies)");
  cmd->add_option("--cusps", o->cusps, "wanted cusps C (0; |p| on a pitch cone; 2|p| where both meet, |n| < 1)");
  cmd->add_option("--candidates", o->candidates, "at most M candidates (1 .. 1000, default 5)");
  cmd->add_option("--max-deviation", o->max_deviation, "drop candidates farther than D radians from a point");
  cmd->add_option("--node-at", o->node_at, "X,Y,Z: a node (self-crossing) wanted at this point of the sphere");
  cmd->add_option("--node-tolerance", o->node_tolerance, "how near --node-at the certified node must be (default 1e-6 rad)");
  cmd->add_flag("--json", o->json, "{\"candidates\": [{\"n\", \"a2\", \"a3\", \"phase\", \"rms\", \"max_deviation\", "
                                   "\"margin\", \"counts\", ...}], \"reason\", \"dropped\"} (docs/cli.md: synth fit)");
  add_output_option(*cmd, o->output, "the candidates");
  actions.emplace_back(cmd, [o] { run_fit(*o); });
}

}  // namespace sphtroch::cli
