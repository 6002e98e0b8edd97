// sphtroch synth points — every train through three precision points (exact/precision_points.hpp),
// each with its census (classify). Parsing and printing only. CGAL: a separate translation unit.
#include "cli_common.hpp"
#include "synth_ratios.hpp"

#include "sphtroch/classify.hpp"
#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/exact/precision_points_output.hpp"
#include "sphtroch/io/input_file.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/polyline_input.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <ostream>
#include <utility>

namespace sphtroch::cli {

namespace {

/// Bound on the estimated work of one call: the sum over the ratio set of (|p| + q)^2 (the
/// unknowns Delta span 2 pi q and the equations turn |n| times faster; measured in bench/).
constexpr double kMaxPointsWork = 20000;
/// The same bound with --free-axis (five points, 18 searches in eight unknowns: ~10-30 s for one
/// small ratio on two cores, measured in bench/): 500 allows --ratios 3,3 (208), not 4,4 (504).
constexpr double kMaxFreeAxisWork = 500;

struct PointsOptions {
  std::string input, output, n, ratios, teeth, shard, threads;
  bool json = false, free_axis = false;
};

using RatioSolutions = RatioPrecisionPoints;

void write_points_text(std::ostream& out, const std::vector<RatioSolutions>& all, const TeethSpec& teeth) {
  std::size_t index = 0;
  for (const auto& rs : all) {
    out << "n = " << rs.ratio.str() << teeth_text(teeth, rs.ratio) << ": " << rs.result.solutions.size() << " train(s)"
        << (rs.result.certified ? ", all of them (certified)" : ", NOT certified complete") << "\n";
    for (std::size_t k = 0; k < rs.result.solutions.size(); ++k) {
      const PrecisionSolution& s = rs.result.solutions[k];
      const Classification& c = rs.census[k];
      out << "  " << ++index << ". a2 = " << number_text(s.train.a2()) << ", a3 = " << number_text(s.train.a3())
          << ", phase = " << number_text(s.train.phase_given());
      if (rs.free_axis)
        out << "; sun axis " << vector_json(s.frame.col(2)) << ", frame x " << vector_json(s.frame.col(0)) << ", y "
            << vector_json(s.frame.col(1));
      out << "; theta2 at the points:";
      for (const double t : s.params) out << " " << number_text(t);
      out << "; residual " << number_text(s.residual) << "; " << c.nodes.size() << " node(s), " << c.cusps.size()
          << " cusp(s)" << (c.certified() ? "" : " (census NOT certified)")
          << (s.isolated ? "" : " (root NOT isolated: near-singular)") << "\n"
          << "     plot it: sphtroch plot " << train_arguments(s.train) << " -o train" << index << ".svg"
          << (rs.free_axis ? " (in the train's frame above)" : "") << "\n";
    }
  }
}

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
  const RatioRequest request =
      requested_ratios("synth points", o.n, o.ratios, o.teeth, o.shard, o.free_axis ? kMaxFreeAxisWork : kMaxPointsWork);
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
  // A shard names its run (points and ratio set), so that synth merge joins only one run's shards.
  const std::string fields =
      request.json_fields + (o.shard.empty() ? "" : "\"run\": \"" + run_fingerprint(in.vertices, o.free_axis ? "points free-axis" : "points") + "\", ");
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << precision_points_json(all, fields, request.teeth);
    else write_points_text(out, all, request.teeth);
  });
  check_points_certified(all);
}

/// Bytes a shard file may hold (a shard of points --ratios 7,7 with every census is ~100 KB).
constexpr std::size_t kMaxShardBytes = std::size_t(1) << 30;

/// One shard of `synth points --ratios P,Q --shard I/K --json`: its set, index and count, and its
/// solution lines as printed (kept verbatim so that the merge equals the unsharded output).
struct PointsShard {
  std::string ratios, run;
  std::size_t index = 0, count = 0;
  bool complete = true;
  std::size_t undecided = 0;
  std::vector<std::string> solution_lines;
};

PointsShard read_points_shard(const std::string& path, const std::string& text) {
  const std::string valid = "the JSON of sphtroch synth points --ratios P,Q | --teeth MIN..MAX --shard I/K --json";
  PointsShard s;
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    const ShardHeader header = read_shard_header(j);
    s.ratios = header.set;
    s.index = header.index;
    s.count = header.count;
    s.run = j.at("run").get<std::string>();
    s.complete = j.at("complete").get<bool>();
    s.undecided = j.at("undecided_boxes").get<std::size_t>();
    const std::size_t solutions = j.at("solutions").size();
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("  {", 0) == 0) {
        s.solution_lines.push_back(line.back() == ',' ? line.substr(0, line.size() - 1) : line);
        const nlohmann::json train = nlohmann::json::parse(s.solution_lines.back());
        check_train_teeth(train, parse_ratio(train.at("n").get<std::string>(), "n"), header.teeth);
      }
    if (s.solution_lines.size() != solutions) throw InvalidInput("shard", path, "not laid out as synth points prints it", valid);
  } catch (const nlohmann::json::exception&) {
    throw InvalidInput("shard", path, "not a synth points shard", valid);
  } catch (const InvalidInput& e) {
    throw InvalidInput("shard", path, e.problem(), valid);
  }
  return s;
}

/// The shards, in any order, joined into what the unsharded run prints.
void run_merge(const std::vector<std::string>& paths, const std::string& output) {
  std::vector<std::string> texts;
  for (const std::string& p : paths) texts.push_back(read_whole_input(p, "shard", kMaxShardBytes));
  if (texts[0].find("\"candidates\": [") != std::string::npos) return run_fit_merge(paths, texts, output);
  std::vector<PointsShard> shards;
  for (std::size_t k = 0; k < paths.size(); ++k) shards.push_back(read_points_shard(paths[k], texts[k]));
  std::sort(shards.begin(), shards.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  std::vector<ShardName> names;
  for (const PointsShard& s : shards) names.push_back({s.ratios, s.index, s.count, s.run});
  check_shard_set(names);
  bool complete = true;
  std::size_t undecided = 0;
  std::string out = "{" + shards[0].ratios + ", \"solutions\": [";
  bool first = true;
  for (const PointsShard& s : shards) {
    complete = complete && s.complete;
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
  cmd->add_option("shards", *paths, "the shard files (JSON)")->required();
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
  cmd->add_option("--threads", o->threads, "with --free-axis: worker threads (1 .. 1024; default: all cores)");
  cmd->add_flag("--json", o->json, "{\"solutions\": [{\"n\", \"a2\", \"a3\", \"phase\", \"params\", \"residual\", \"counts\", ...}], "
                                   "\"complete\", ...} (docs/cli.md: synth points)");
  add_output_option(*cmd, o->output, "the trains");
  actions.emplace_back(cmd, [o] { run_points(*o); });
  register_synth_merge(synth, actions);
  register_synth_fit(synth, actions);
}

}  // namespace sphtroch::cli
