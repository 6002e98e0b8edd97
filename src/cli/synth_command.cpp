// sphtroch synth — the inverse question, which train draws a wanted path (synthesis/). Today:
// `synth identify`, the train of a timed trace (synthesis/identify.hpp); `synth points` is in
// synth_points_command.cpp (CGAL). Parsing and printing only.
#include "cli_common.hpp"

#include "sphtroch/io/polyline_input.hpp"
#include "sphtroch/synthesis/identify.hpp"

#include <ostream>

namespace sphtroch::cli {

namespace {

struct IdentifyOptions {
  std::string input, output, max_terms;
  bool json = false;
};

/// --max-terms P,Q: the bounds |p| <= P, q <= Q of the identified ratio.
sphtroch::IdentifyOptions identify_bounds(const std::string& text) {
  sphtroch::IdentifyOptions bounds;
  if (text.empty()) return bounds;
  const auto [p, q] = parse_count_pair(text, "max-terms", 1, Ratio::kMaxTerm, "P,Q with 1 <= P, Q <= 1000000 (|p| <= P, q <= Q)");
  bounds.max_p = static_cast<std::int64_t>(p);
  bounds.max_q = static_cast<std::int64_t>(q);
  return bounds;
}

/// The identified train as text: one fact per line and the command that traces it.
void write_identified_text(std::ostream& out, const Identified& id) {
  const GearTrain& g = id.train;
  out << "n = " << g.ratio().str() << "\n"
      << "a2 = " << report_number(g.a2()) << " rad\n"
      << "a3 = " << report_number(g.a3()) << " rad\n"
      << "phase = " << report_number(g.phase()) << " rad\n"
      << "residual = " << report_number(id.residual) << " (max |P(t_i) - P_i|), rms " << report_number(id.rms)
      << ", noise off the planet circle " << report_number(id.noise) << "\n"
      << "trace it: sphtroch trace --n " << g.ratio().str() << " --a2 " << report_number(g.a2()) << " --a3 "
      << report_number(g.a3()) << " --phase " << report_number(g.phase()) << "\n";
}

/// {"n", "a2", "a3", "phase", "residual", "rms", "noise"} (angles in radians).
void write_identified_json(std::ostream& out, const Identified& id) {
  const GearTrain& g = id.train;
  out << "{\"n\": \"" << g.ratio().str() << "\", \"a2\": " << number_text(g.a2()) << ", \"a3\": " << number_text(g.a3())
      << ", \"phase\": " << number_text(g.phase()) << ", \"residual\": " << number_text(id.residual)
      << ", \"rms\": " << number_text(id.rms) << ", \"noise\": " << number_text(id.noise) << "}\n";
}

void run_identify(const IdentifyOptions& o) {
  const sphtroch::IdentifyOptions bounds = identify_bounds(o.max_terms);
  check_distinct_files({{o.output, "--output"}}, {{o.input, "--input"}});
  const PolylineInput in = read_timed_polyline(o.input, "input");
  const Identified id = [&] {
    try {
      return identify(in.t, in.vertices, bounds);
    } catch (const InvalidInput& e) {  // the library names its argument (t, points, samples): here the file
      throw InvalidInput("input", o.input, e.field() + " " + e.value() + ": " + e.problem(), e.valid_range());
    }
  }();
  write_output(o.output, [&](std::ostream& out) { o.json ? write_identified_json(out, id) : write_identified_text(out, id); });
}

}  // namespace

void register_synth(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  CLI::App* synth = app.add_subcommand("synth", "the inverse question: which gear train draws a given path");
  synth->require_subcommand(1);
  auto o = std::make_shared<IdentifyOptions>();
  CLI::App* cmd = synth->add_subcommand("identify", "the train (n exact, a2, a3, phase) of a timed trace");
  cmd->footer(
      "--input FILE: CSV with a header naming t, x, y, z (what `sphtroch trace` writes) or .npy (N, 4) or\n"
      "(N, 7); - for standard input. The samples must cover one period, densely enough that the planet\n"
      "turns by less than 3pi/4 between two. Prints n as the simplest fraction that fits (|p|, q <= 1000,\n"
      "--max-terms P,Q), a2, a3, the phase and the residual max |P(t_i) - P_i|; JSON with --json.\n"
      "Example: sphtroch trace --n 5/2 --a2 1 --a3 2 | sphtroch synth identify --input -");
  cmd->add_option("--input", o->input, "the timed samples (CSV t,x,y,z or .npy; - for standard input)")->type_name("FILE")->required();
  cmd->add_option("--max-terms", o->max_terms, "bounds P,Q of the ratio: |p| <= P, q <= Q (default 1000,1000)")->type_name("P,Q");
  cmd->add_flag("--json", o->json, "{\"n\", \"a2\", \"a3\", \"phase\", \"residual\", \"rms\", \"noise\"}");
  add_output_option(*cmd, o->output, "the identified train");
  actions.emplace_back(cmd, [o] { run_identify(*o); });
#ifdef SPHTROCH_HAVE_ANALYSIS
  register_synth_points(*synth, actions);  // CGAL: synth_points_command.cpp
#endif
}

}  // namespace sphtroch::cli
