// sphtroch synth points — every train through three precision points (exact/precision_points.hpp),
// each with its census (classify). Parsing and printing only. CGAL: a separate translation unit.
#include "cli_common.hpp"

#include "sphtroch/classify.hpp"
#include "sphtroch/exact/precision_points_output.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/polyline_input.hpp"

#include <cmath>
#include <ostream>

namespace sphtroch::cli {

namespace {

/// Bound on the estimated work of one call: the sum over the ratio set of (|p| + q)^2 (the
/// unknowns Delta span 2 pi q and the equations turn |n| times faster; measured in bench/).
constexpr double kMaxPointsWork = 20000;

struct PointsOptions {
  std::string input, output, n, ratios;
  bool json = false;
};

using RatioSolutions = RatioPrecisionPoints;

std::vector<Ratio> requested_ratios(const PointsOptions& o) {
  if (o.n.empty() == o.ratios.empty())
    throw UsageError{"synth points: give exactly one of --n R and --ratios P,Q (see docs/cli.md: synth points)"};
  std::vector<Ratio> set;
  if (!o.n.empty()) {
    set.push_back(parse_ratio(o.n, "n"));
  } else {
    const auto comma = o.ratios.find(',');
    if (comma == std::string::npos)
      throw InvalidInput("ratios", o.ratios, "not two counts P,Q", "P,Q: every p/q with 1 <= |p| <= P, 1 <= q <= Q");
    set = ratio_set(static_cast<std::int64_t>(parse_count(o.ratios.substr(0, comma), "ratios", 1, 1000)),
                    static_cast<std::int64_t>(parse_count(o.ratios.substr(comma + 1), "ratios", 1, 1000)));
  }
  double work = 0;
  for (const Ratio& r : set) work += std::pow(double(r.abs_p() + r.q()), 2);
  if (work > kMaxPointsWork)
    throw InvalidInput(o.n.empty() ? "ratios" : "n", o.n.empty() ? o.ratios : o.n,
                       "estimated work " + number_text(work) + " over the bound",
                       "sum over the ratios of (|p| + q)^2 <= 20000 (--ratios 7,7 is 4832)");
  return set;
}

std::string train_arguments(const GearTrain& g) {
  return "--n " + g.ratio().str() + " --a2 " + number_text(g.a2()) + " --a3 " + number_text(g.a3()) + " --phase " +
         number_text(g.phase_given());
}

void write_points_text(std::ostream& out, const std::vector<RatioSolutions>& all) {
  std::size_t index = 0;
  for (const auto& rs : all) {
    out << "n = " << rs.ratio.str() << ": " << rs.result.solutions.size() << " train(s)"
        << (rs.result.certified ? ", all of them (certified)" : ", NOT certified complete") << "\n";
    for (std::size_t k = 0; k < rs.result.solutions.size(); ++k) {
      const PrecisionSolution& s = rs.result.solutions[k];
      const Classification& c = rs.census[k];
      out << "  " << ++index << ". a2 = " << number_text(s.train.a2()) << ", a3 = " << number_text(s.train.a3())
          << ", phase = " << number_text(s.train.phase_given()) << "; theta2 at the points:";
      for (const double t : s.params) out << " " << number_text(t);
      out << "; residual " << number_text(s.residual) << "; " << c.nodes.size() << " node(s), " << c.cusps.size()
          << " cusp(s)" << (c.certified() ? "" : " (census NOT certified)")
          << (s.isolated ? "" : " (root NOT isolated: near-singular)") << "\n"
          << "     plot it: sphtroch plot " << train_arguments(s.train) << " -o train" << index << ".svg\n";
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
  const std::vector<Ratio> ratios = requested_ratios(o);
  check_distinct_files({{o.output, "--output"}}, {{o.input, "--input"}});
  const PolylineInput in = read_polyline(o.input, "input");
  const std::vector<RatioSolutions> all = [&] {
    try {
      return precision_points_with_census(in.vertices, ratios);
    } catch (const InvalidInput& e) {  // the library names its argument (points): here the file
      throw InvalidInput("input", o.input, e.value() + ": " + e.problem(), e.valid_range());
    }
  }();
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << precision_points_json(all);
    else write_points_text(out, all);
  });
  check_points_certified(all);
}

}  // namespace

void register_synth_points(CLI::App& synth, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<PointsOptions>();
  CLI::App* cmd = synth.add_subcommand("points", "every train through three precision points (fixed frame), certified");
  cmd->footer(
      "--input FILE: CSV with a header x,y,z (or .npy (N, 3)), exactly 3 unit vectors; - for standard input.\n"
      "The sun axis is Z. For each ratio (--n R, or --ratios P,Q: every p/q with 1 <= |p| <= P, 1 <= q <= Q,\n"
      "both signs) it prints ALL trains with a2, a3 in [1e-6, pi - 1e-6] whose tracer passes through the\n"
      "three points, with theta2 at each point, the residual and the census. Exit 3 if the list is not\n"
      "certified complete. Example: sphtroch synth points --input pts.csv --n 1/2 --json");
  cmd->add_option("--input", o->input, "the three points (CSV x,y,z or .npy; - for standard input)")->required();
  cmd->add_option("--n", o->n, "the gear ratio p/q");
  cmd->add_option("--ratios", o->ratios, "every ratio p/q with |p| <= P, q <= Q, both signs");
  cmd->add_flag("--json", o->json, "{\"solutions\": [{\"n\", \"a2\", \"a3\", \"phase\", \"params\", \"residual\", \"counts\"}]}");
  add_output_option(*cmd, o->output, "the trains");
  actions.emplace_back(cmd, [o] { run_points(*o); });
}

}  // namespace sphtroch::cli
