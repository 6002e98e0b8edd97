// sphtroch synth points — every train through three precision points (synthesis/precision_points.hpp),
// each with its census (classify). Parsing and printing only. CGAL: a separate translation unit.
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
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <ostream>
#include <utility>

namespace sphtroch::cli {

namespace {

struct PointsOptions {
  std::string input, output, n, ratios, teeth, shard, threads;
  bool json = false, free_axis = false;
};

using RatioSolutions = RatioPrecisionPoints;


/// After the output is complete: exit 3 when the list is not certified complete or a census is not.
void check_points_certified(const std::vector<RatioSolutions>& all) {
  for (const auto& rs : all) {
    if (!rs.result.certified)
      throw UncertifiedResult{"synth points: n = " + rs.ratio.str() + ": " + std::to_string(rs.result.undecided) +
                              " box(es) undecided, the list may miss a train (exit status 3; see docs/cli.md: synth points)"};
    for (const auto& c : rs.census)
      if (!c.certified())
        throw UncertifiedResult{"synth points: the census of a train of n = " + rs.ratio.str() +
                                " is not certified (exit status 3; see docs/cli.md: Certified counts)"};
  }
}

void run_points(const PointsOptions& o) {
  const RatioSet request =
      requested_ratios("synth points", {o.n, o.ratios, o.teeth, o.shard}, o.free_axis ? kMaxFreeAxisWork : kMaxPointsWork);
  if (!o.free_axis)
    check_points_census_work(request.ratios, !o.n.empty() ? "n" : !o.ratios.empty() ? "ratios" : "teeth",
                             !o.n.empty() ? o.n : !o.ratios.empty() ? o.ratios : o.teeth);
  PrecisionPointsOptions options;
  options.threads = parse_threads(o.threads);
  if (!o.threads.empty() && !o.free_axis)
    throw UsageError{"--threads = " + o.threads + ": only with --free-axis (the fixed frame runs on one core)"};
  check_distinct_files({{o.output, "--output"}}, {{o.input, "--input"}});
  const PolylineInput in = read_polyline(o.input, "input");
  const std::vector<RatioSolutions> all = [&] {
    try {
      return precision_points_with_census(in.vertices, request.ratios, options, o.free_axis);
    } catch (const InvalidInput& e) {  // the library names its argument (points): here the file
      throw InvalidInput("input", o.input, e.value() + ": " + e.problem(), e.valid_range());
    }
  }();
  // A shard names its run (points and ratio set), so that synth merge joins only one run's shards,
  // and carries a digest of its bytes, so that it refuses an edited one.
  const std::string fields =
      request.json_members() + (o.shard.empty() ? "" : "\"run\": \"" + run_fingerprint(in.vertices, o.free_axis ? "points free-axis" : "points") +
                                                         "\", " + digest_placeholder());
  write_output(o.output, [&](std::ostream& out) {
    if (!o.json) out << precision_points_text(all, request.teeth);
    else if (o.shard.empty()) out << precision_points_json(all, fields, request.teeth);
    else out << signed_part(precision_points_json(all, fields, request.teeth));
  });
  check_points_certified(all);
}

/// Bytes a shard file may hold (a shard of points --ratios 7,7 with every census is ~100 KB).
constexpr std::size_t kMaxShardBytes = std::size_t(1) << 30;

/// One shard of `synth points --ratios P,Q --shard I/K --json`: its header, members and
/// solutions (parsed and checked), and its solution lines as printed (kept verbatim so that the
/// merge equals the unsharded output).
struct PointsShard {
  std::string path, text, run, digest;
  ShardHeader header;
  bool complete = true;
  std::size_t undecided = 0;
  std::optional<bool> free_axis;          // unknown without solutions
  std::vector<Ratio> ratios;              // each solution's n
  std::vector<std::string> solution_lines;
};

const std::string kPointsPart = "the JSON of sphtroch synth points --ratios P,Q | --teeth MIN..MAX --shard I/K --json";

/// A vector member [x, y, z] of unit length (within 1e-9).
Vector3d unit_vector(const nlohmann::json& v, const std::string& what) {
  bool ok = v.is_array() && v.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) ok = v[i].is_number();
  const Vector3d x = ok ? Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>()) : Vector3d::Zero();
  if (!ok || !(std::fabs(x.norm() - 1) <= 1e-9))
    throw InvalidInput("shard", what + " " + brief_json(v), "not a unit vector", "[x, y, z] with |(x, y, z)| within 1e-9 of 1");
  return x;
}

/// One solution as synth points prints it (precision_points_output.hpp), every member checked;
/// sets (or checks against) free_axis: whether the part's trains carry "axis" and "frame".
Ratio check_solution(const nlohmann::json& s, const ShardHeader& h, std::size_t k, std::optional<bool>& free_axis) {
  std::string where = "solution " + std::to_string(k + 1) + ": ";
  if (!s.is_object() || !s.contains("n")) throw InvalidInput("shard", where + brief_json(s), "not a train", "{\"n\", \"a2\", ...}");
  const Ratio n = ratio_member(s, where);
  where = "solution " + std::to_string(k + 1) + " (n = " + n.str() + "): ";
  const bool axis = s.contains("axis");
  if (free_axis && *free_axis != axis)
    throw InvalidInput("shard", where + (axis ? "\"axis\"" : "no \"axis\""), "fixed-frame and free-axis trains mixed",
                       "every train with \"axis\" and \"frame\" (--free-axis) or none");
  free_axis = axis;
  std::vector<std::string> names{"n", "a2", "a3", "phase", "params", "residual", "certified_margin", "counts", "census_certified", "isolated"};
  if (s.contains("teeth")) names.push_back("teeth");
  if (axis) names.insert(names.end(), {"axis", "frame"});
  check_members(s, where + "train", names);
  check_train_teeth(s, n, h.teeth);
  const double pi = Constants<double>::pi();
  number_member(s, where, "a2", kMinCarrierTwist, pi - kMinCarrierTwist + 8.881784197001252e-16);  // carrier_twist_in_range's 2 ulp
  number_member(s, where, "a3", kMinCarrierTwist, pi - kMinCarrierTwist);
  number_member(s, where, "phase", 0, 2 * pi / double(n.q()));
  if (axis) {
    const nlohmann::json& f = s.at("frame");
    if (!f.is_array() || f.size() != 3) throw InvalidInput("shard", where + "\"frame\"", "not three vectors", "[X, Y, Z], orthonormal, Z = \"axis\"");
    const Vector3d x = unit_vector(f[0], where + "\"frame\" X"), y = unit_vector(f[1], where + "\"frame\" Y"),
                   z = unit_vector(f[2], where + "\"frame\" Z");
    unit_vector(s.at("axis"), where + "\"axis\"");
    if (f[2] != s.at("axis") || !(std::fabs(x.dot(y)) <= 1e-9 && std::fabs(x.dot(z)) <= 1e-9 && std::fabs(y.dot(z)) <= 1e-9))
      throw InvalidInput("shard", where + "\"frame\" " + brief_json(f), "not orthonormal with Z = \"axis\"", "[X, Y, Z], orthonormal, Z = \"axis\"");
  }
  const nlohmann::json& params = s.at("params");
  const std::size_t points = axis ? 5 : 3;
  if (!params.is_array() || params.size() != points)
    throw InvalidInput("shard", where + "\"params\" " + brief_json(params), "not theta2 at each point",
                       std::to_string(points) + " numbers (one per point)");
  for (std::size_t i = 0; i < points; ++i) number_member(params, where + "\"params\"", i, 0, 2 * pi * double(n.q()));
  number_member(s, where, "residual", 0, std::numeric_limits<double>::max());
  const nlohmann::json& cm = s.at("certified_margin");
  check_members(cm, where + "\"certified_margin\"", {"lower", "upper"});
  const double lower = number_member(cm, where + "\"certified_margin\" ", "lower", 0, pi);
  number_member(cm, where + "\"certified_margin\" ", "upper", lower, pi);
  const nlohmann::json& c = s.at("counts");
  check_members(c, where + "\"counts\"", {"nodes", "crossings", "tangencies", "cusps"});
  if (count_member(c, where, "nodes") != count_member(c, where, "crossings") + count_member(c, where, "tangencies"))
    throw InvalidInput("shard", where + "\"counts\" " + brief_json(c), "nodes != crossings + tangencies", "the census as classify counts it");
  count_member(c, where, "cusps");
  bool_member(s, where, "census_certified");
  bool_member(s, where, "isolated");
  return n;
}

/// A part read and checked on its own: every member (InvalidInput "shard" = path naming the first
/// that is not as the run writes it). What depends on the other parts is checked by run_merge.
PointsShard read_points_shard(const std::string& path, const std::string& text) {
  PointsShard s;
  s.path = path;
  s.text = text;
  try {
    const nlohmann::json j = parse_part_json(text);
    s.header = read_shard_header(j);
    check_members(j, "the part", {s.header.set_name, "shard", "run", "digest", "solutions", "complete", "undecided_boxes"});
    s.run = j.at("run").get<std::string>();
    s.digest = j.at("digest").get<std::string>();
    if (!is_hex16(s.run)) throw InvalidInput("shard", "\"run\" " + brief_json(j.at("run")), "not a fingerprint", "16 hex digits as the run writes them");
    if (!is_hex16(s.digest)) throw InvalidInput("shard", "\"digest\" " + brief_json(j.at("digest")), "not a digest", "16 hex digits as the run writes them");
    s.complete = bool_member(j, "", "complete");
    s.undecided = count_member(j, "", "undecided_boxes");
    if (s.complete != (s.undecided == 0))
      throw InvalidInput("shard", "\"undecided_boxes\" " + std::to_string(s.undecided) + " with \"complete\" " + (s.complete ? "true" : "false"),
                         "contradictory", "0 exactly when complete is true");
    const nlohmann::json& solutions = j.at("solutions");
    if (!solutions.is_array()) throw InvalidInput("shard", "\"solutions\"", "not a list", "[train, ...]");
    for (std::size_t k = 0; k < solutions.size(); ++k) s.ratios.push_back(check_solution(solutions[k], s.header, k, s.free_axis));
    // The lines copied into the merge: one per solution, each the solution it stands for.
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("  {", 0) == 0) {
        if (line.back() == ',') line.pop_back();
        const std::size_t k = s.solution_lines.size();
        if (k >= solutions.size() || nlohmann::json::parse(line) != solutions[k])
          throw InvalidInput("shard", "solution line " + std::to_string(k + 1), "not laid out as synth points prints it", "one train per line");
        s.solution_lines.push_back(line);
      }
    if (s.solution_lines.size() != solutions.size())
      throw InvalidInput("shard", "solution lines", "not laid out as synth points prints it", "one train per line");
  } catch (const nlohmann::json::exception&) {
    throw InvalidInput("shard", path, "not a synth points shard", kPointsPart);
  } catch (const InvalidInput& e) {
    throw InvalidInput("shard", path, e.value() + ": " + e.problem(), e.valid_range());
  }
  return s;
}

/// What a part holds that depends on its place in the run (checked once the parts form one run):
/// every train's n among the part's own ratios, in their order; then its digest.
void check_points_part(const PointsShard& s) {
  try {
    std::size_t last = 0;
    for (std::size_t k = 0; k < s.ratios.size(); ++k) {
      const std::string where = "solution " + std::to_string(k + 1) + ": ";
      const std::size_t at = own_ratio_index(s.header, s.ratios[k], where);
      if (at < last)
        throw InvalidInput("shard", where + "n = " + s.ratios[k].str(), "out of order", "the trains in the order of their ratios in the set");
      last = at;
    }
  } catch (const InvalidInput& e) {
    throw InvalidInput("shard", s.path, e.value() + ": " + e.problem(), e.valid_range());
  }
  check_part_digest(s.path, s.text, s.digest, kPointsPart + " (unedited)");
}

/// The shards, in any order, joined into what the unsharded run prints.
void run_merge(const std::vector<std::string>& paths, const std::string& output) {
  std::vector<std::string> texts;
  for (const std::string& p : paths) texts.push_back(read_whole_input(p, "shard", kMaxShardBytes));
  if (texts[0].find("\"candidates\": [") != std::string::npos) return run_fit_merge(paths, texts, output);
  std::vector<PointsShard> shards;
  for (std::size_t k = 0; k < paths.size(); ++k) shards.push_back(read_points_shard(paths[k], texts[k]));
  std::stable_sort(shards.begin(), shards.end(), [](const auto& a, const auto& b) { return a.header.index < b.header.index; });
  std::vector<ShardName> names;
  for (const PointsShard& s : shards)
    names.push_back({s.path, s.header.index, s.header.count,
                     {{s.header.set_name, nlohmann::json(s.header.set_text).dump()}, {"run", nlohmann::json(s.run).dump()}}});
  check_shard_set(names);
  const PointsShard* with_trains = nullptr;  // the first part with a train: free-axis or not
  for (const PointsShard& s : shards) {
    if (!with_trains && s.free_axis) with_trains = &s;
    if (s.free_axis && *s.free_axis != *with_trains->free_axis)
      throw InvalidInput("shard", s.path, "its trains are " + std::string(*s.free_axis ? "free-axis" : "fixed-frame") + ", " +
                                              with_trains->path + "'s are not", "the parts of one run");
    check_points_part(s);
  }
  bool complete = true;
  std::size_t undecided = 0;
  std::string out = "{" + shards[0].header.set + ", \"solutions\": [";
  bool first = true;
  for (const PointsShard& s : shards) {
    complete = complete && s.complete;
    if (s.undecided > std::numeric_limits<std::size_t>::max() - undecided)
      throw InvalidInput("shard", s.path, "\"undecided_boxes\" " + std::to_string(s.undecided) + ": the sum over the parts overflows",
                         "counts whose sum is below 2^64");
    undecided += s.undecided;
    for (const std::string& line : s.solution_lines) {
      out += (first ? "\n" : ",\n") + line;
      first = false;
    }
  }
  out += std::string(first ? "" : "\n") + "], \"complete\": " + (complete ? "true" : "false") +
         ", \"undecided_boxes\": " + std::to_string(undecided) + "}\n";
  write_output(output, [&](std::ostream& o) { o << out; });
  if (!complete)
    throw UncertifiedResult{"synth merge: a shard's list is not certified complete (exit status 3; see docs/cli.md: synth points)"};
}

void register_synth_merge(CLI::App& synth, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto paths = std::make_shared<std::vector<std::string>>();
  auto output = std::make_shared<std::string>();
  CLI::App* cmd = synth.add_subcommand("merge", "join the JSON shards of synth points or synth fit --ratios P,Q --shard I/K");
  cmd->footer("Shards in any order; the result is byte for byte what the unsharded run prints.\n"
              "Example: sphtroch synth merge -o all.json part-*.json");
  cmd->add_option("shards", *paths, "the shard files (JSON)")->type_name("FILE")->required();
  add_output_option(*cmd, *output, "the joined JSON");
  actions.emplace_back(cmd, [paths, output] {
    check_distinct_files({{*output, "--output"}}, [&] {
      std::vector<NamedFile> in;
      for (const auto& p : *paths) in.push_back({p, "shard"});
      return in;
    }());
    run_merge(*paths, *output);
  });
}

}  // namespace

void register_synth_points(CLI::App& synth, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<PointsOptions>();
  CLI::App* cmd = synth.add_subcommand("points", "every train through three precision points (fixed frame) or five (--free-axis), certified");
  cmd->footer(
      "--input FILE: CSV with a header x,y,z (or .npy (N, 3)), exactly 3 unit vectors (5 with --free-axis);\n"
      "- for standard input. The sun axis is Z, or anywhere with --free-axis (each train then gives its\n"
      "sun axis and frame). For each ratio (--n R, or --ratios P,Q: every p/q with 1 <= |p| <= P,\n"
      "1 <= q <= Q, both signs) it prints ALL trains with a2, a3 in [1e-6, pi - 1e-6] whose tracer passes\n"
      "through the points, with theta2 at each point, the residual and the census. Exit 3 if the list is\n"
      "not certified complete. Example: sphtroch synth points --input pts.csv --n 1/2 --json");
  add_ratio_set_options(*cmd, o->input, o->n, o->ratios, o->teeth, o->shard, "the three points (five with --free-axis)");
  cmd->add_flag("--free-axis", o->free_axis, "five points; the sun axis may be placed anywhere (docs/cli.md: synth points)");
  cmd->add_option("--threads", o->threads, "with --free-axis: worker threads (1 .. 1024; default: all cores)")->type_name("N");
  cmd->add_flag("--json", o->json, "{\"solutions\": [{\"n\", \"a2\", \"a3\", \"phase\", \"params\", \"residual\", \"counts\", ...}], "
                                   "\"complete\", ...} (docs/cli.md: synth points)");
  add_output_option(*cmd, o->output, "the trains");
  actions.emplace_back(cmd, [o] { run_points(*o); });
  register_synth_merge(synth, actions);
  register_synth_fit(synth, actions);
}

}  // namespace sphtroch::cli
