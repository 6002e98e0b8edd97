// sphtroch classify | nodes | plot | crossings | tolerance — the node census and its reports. One of
// the five CLI translation units that include CGAL through exact/analysis.hpp (with scene_command.cpp,
// chain_census_command.cpp, synth_points_command.cpp and synth_fit_command.cpp).
// Every format is the library's (sphtroch/exact/classification_output.hpp, node_csv.hpp), shared with `sphtroch scene`.
#include "cli_common.hpp"
#include "png_output.hpp"

#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/io/node_csv.hpp"
#include "sphtroch/io/polyline_input.hpp"
#include "sphtroch/exact/classification_output.hpp"
#include "sphtroch/tolerance.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>

namespace sphtroch::cli {

namespace {

struct AnalysisOptions {
  TrainOptions train;
  std::string samples, output;
  bool literal = false;
  bool json = false;
  PlotFlags plot;                   // plot only
  std::string radius;               // nodes only
  bool degrees = false;             // nodes only
};

void add_analysis_options(CLI::App& cmd, AnalysisOptions& o) {
  o.train.add_to(cmd);
  cmd.add_flag("--literal", o.literal,
               "analyse the given doubles exactly as given (no snapping onto boundaries within 1e-10 rad)");
  cmd.add_option("--samples", o.samples, "uniform samples of the polyline census (1024 .. 10000000; default 256*(q+|p|))")->type_name("N");
  add_output_option(cmd, o.output, "the result");
}

AnalysisSettings analysis_settings(const AnalysisOptions& o) {
  AnalysisSettings s;
  s.reading.literal = o.literal;
  if (!o.samples.empty()) s.census_samples = parse_count(o.samples, "samples", kMinCensusSamples, kMaxSamples);
  return s;
}

/// After the outputs are complete: an uncertified count ends the tool with kUncertified.
void check_certified(const CensusCertificate& cert, bool analytic_agrees = true) {
  if (cert.certified && analytic_agrees) return;
  std::string counts = cert.certified ? "the censuses agree but the report's criteria do not"
                                      : "polyline census " + std::to_string(cert.polyline_nodes.back()) +
                                            " node(s), root-count census " + std::to_string(cert.root_nodes);
  throw UncertifiedResult{"the node count is not certified: " + counts + (cert.stopped.empty() ? "" : "; " + cert.stopped) +
                          " (exit status 3; see docs/cli.md: Certified counts)"};
}

void run_classify(const AnalysisOptions& o) {
  const GearTrain train = o.train.train();  // first: its errors come before those of --samples
  const Analysis a(train, analysis_settings(o));  // a.classification() is classify(train, settings)
  const Classification& c = a.classification();
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << classification_json(o.train, c).dump(2) << "\n";
    else write_classification_text(out, o.train, c);
  });
  check_certified(c.certificate, c.agreement.analytic_agrees.value_or(true));
}

// nodes and plot need the (certified) crossing stage and the cusps, not the whole classification.
void run_nodes(const AnalysisOptions& o) {
  const GearTrain train = o.train.train();
  const NodesCsvOptions csv{parse_radius(o.radius), o.degrees};  // checked before the work
  const Analysis a(train, analysis_settings(o));
  write_output(o.output, [&](std::ostream& out) { write_nodes_csv(out, a.nodes(), a.cusps(), csv); });
  check_certified(a.certificate());
}

void run_plot(const AnalysisOptions& o) {
  check_svg_name(o.output, "output");
  const GearTrain train = o.train.train();
  const Analysis a(train, analysis_settings(o));
  const PlotOptions options = o.plot.options();
  const std::string svg =
      plot_svg(o.train, a.analysed(), a.plot_trajectory(), a.nodes(), a.cusps(), &a.certificate(), options);
  const std::string bytes = picture_bytes(svg, o.output);  // PNG for FILE.png
  write_output(o.output, [&](std::ostream& out) { out << bytes; }, "--output", kPictureOutputs);
  check_certified(a.certificate());
}

struct CrossingsOptions {
  std::string input, pairs, output, threads, max_crossings, max_work;
  bool open = false;
  bool json = false;
};

// Counts only (memory O(N)), or pairs streamed into --pairs as found; bounded by --max-crossings
// and --max-work (refused with exit 2, no file left, when a limit is reached).
void run_crossings(const CrossingsOptions& o) {
  using clock = std::chrono::steady_clock;
  const std::size_t threads = parse_threads(o.threads);
  CrossingSearchOptions search;
  search.max_contacts = o.max_crossings.empty() ? kDefaultMaxCrossings
                                                : parse_count(o.max_crossings, "max-crossings", 0, kMaxCrossingLimit);
  search.max_work = o.max_work.empty() ? kDefaultMaxCrossingWork : parse_count(o.max_work, "max-work", 0, kMaxCrossingLimit);
  check_distinct_files({{o.output, "--output"}, {o.pairs, "--pairs"}}, {{o.input, "--input"}});
  const auto start_read = clock::now();
  const PolylineInput input = read_polyline(o.input, "input", std::min<std::size_t>(threads, 2));
  const double seconds_read = std::chrono::duration<double>(clock::now() - start_read).count();
  const std::vector<Vector3d>& vertices = input.vertices;
  const auto bad_input = [&](const InvalidInput& e) {
    return UsageError{"--input = " + o.input + ": " + e.value() + ": " + e.problem() + "; valid: " + e.valid_range()};
  };
  try {
    validate_spherical_polyline(vertices, !o.open);
  } catch (const InvalidInput& e) {
    throw bad_input(e);
  }
  StagedOutputs outputs;  // --pairs and -o appear together or not at all
  OutputFile* pairs = o.pairs.empty() ? nullptr : &outputs.open(o.pairs, "--pairs");
  if (pairs != nullptr) write_edge_pairs_header(*pairs);
  const auto start = clock::now();
  CrossingCounts counts;
  try {
    counts = pairs != nullptr
                 ? visit_self_crossings(vertices, !o.open, [pairs](const EdgePair& e) { write_edge_pair_row(*pairs, e); }, search)
                 : count_self_crossings(vertices, !o.open, search);
  } catch (const InvalidInput& e) {
    throw bad_input(e);
  }
  const double seconds = std::chrono::duration<double>(clock::now() - start).count();
  check_search_complete(counts, search, "max-crossings", "max-work");  // InvalidInput: exit 2, no file kept
  const CrossingsSummary summary = crossings_summary(counts, !o.open, input.format, seconds_read, seconds);
  outputs.stage(o.output, "--output", [&](std::ostream& out) {
    if (o.json) out << crossings_summary_json(summary).dump(2) << "\n";
    else write_crossings_summary_text(out, summary);
  });
  outputs.commit();
}

struct ToleranceOptions {
  TrainOptions train;
  std::string tol_a2, tol_a3, tol_phase = "0", samples, seed = "1", output;
  bool degrees = false, json = false;
};

/// A half-width as typed: an angle (io/parse.hpp: 1e-3, pi/1800, 0.1deg); with --degrees a plain
/// number is degrees. The sign and range are check_tolerance_box's.
double parse_tolerance(const std::string& text, const std::string& field, bool degrees) {
  const double v = parse_angle(text, field);
  const bool plain = text.find("deg") == std::string::npos && text.find("pi") == std::string::npos;
  return degrees && plain ? v * (Constants<double>::pi() / 180) : v;
}

void run_tolerance(const ToleranceOptions& o) {
  const GearTrain train = o.train.train();
  const ToleranceBox box{parse_tolerance(o.tol_a2, "tol-a2", o.degrees), parse_tolerance(o.tol_a3, "tol-a3", o.degrees),
                         parse_tolerance(o.tol_phase, "tol-phase", o.degrees)};
  try {
    check_tolerance_box(train, box, {"tol-a2", "tol-a3", "tol-phase"});
  } catch (const InvalidInput& e) {  // name the value as typed
    const std::string& typed = e.field() == "tol-a2" ? o.tol_a2 : (e.field() == "tol-a3" ? o.tol_a3 : o.tol_phase);
    throw InvalidInput(e.field(), typed, e.problem(), e.valid_range());
  }
  const std::size_t samples = o.samples.empty() ? 0 : parse_count(o.samples, "samples", 1, kMaxToleranceSamples);
  const std::uint64_t seed = parse_count(o.seed, "seed", 0, std::size_t(1) << 62);
  if (samples > 0) check_monte_carlo_cost(train, box, samples);  // refused up front
  ToleranceReport r = tolerance_report(train, box);
  if (samples > 0) run_monte_carlo(r, samples, seed);
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << tolerance_json(o.train, r).dump(2) << "\n";
    else out << tolerance_text(o.train, r);
  });
  if (!tolerance_certified(r))
    throw UncertifiedResult{"tolerance: " + std::string(r.census_certified ? "" : "the nominal census is not certified; ") +
                            (r.topology.verdict == BoxTopology::Verdict::undecided ? "the topology is undecided: " + r.topology.why
                                                                                 : "a node's move over the box is not proved") +
                            " (exit status 3; see docs/cli.md: tolerance)"};
}

void register_tolerance(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<ToleranceOptions>();
  CLI::App* cmd = app.add_subcommand("tolerance", "will a train made within tolerances draw the same nodes and cusps? (certified)");
  o->train.add_to(*cmd);
  cmd->add_option("--tol-a2", o->tol_a2, "half-width of the a2 tolerance, radians (degrees with --degrees); 0 fixes a2")
      ->type_name("ANGLE")->required();
  cmd->add_option("--tol-a3", o->tol_a3, "half-width of the a3 tolerance, radians (degrees with --degrees); 0 fixes a3")
      ->type_name("ANGLE")->required();
  cmd->add_option("--tol-phase", o->tol_phase, "half-width of the phase tolerance (0 .. 2 pi)")->type_name("RAD")->capture_default_str();
  cmd->add_flag("--degrees", o->degrees, "read the tolerances as degrees (the train's angles take a deg suffix: 90deg)");
  cmd->add_option("--samples", o->samples, "also classify N random trains of the box (1 .. 100000): the spread sampling sees")->type_name("N");
  cmd->add_option("--seed", o->seed, "the samples' random seed (0 .. 2^62)")->type_name("N")->capture_default_str();
  cmd->add_flag("--json", o->json, "one JSON object: topology, event, margin, nodes, cusps, ... (docs/cli.md: tolerance)");
  add_output_option(*cmd, o->output, "the report");
  cmd->footer("topology: holds (certified: every train of the box draws the nominal census), changes (certified:\n"
              "a boundary of the design map lies in the box, named) or undecided (exit 3). margin: the certified\n"
              "distance [lower, upper] to the nearest boundary (half-width of the largest free square about a2, a3).\n"
              "Example: sphtroch tolerance --a2 1 --a3 2 --n 5/2 --tol-a2 0.1 --tol-a3 0.1 --degrees");
  actions.emplace_back(cmd, [o] { run_tolerance(*o); });
}

}  // namespace

void register_analysis(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  {
    auto o = std::make_shared<AnalysisOptions>();
    CLI::App* cmd = app.add_subcommand("classify", "nodes, cusps and the report's criteria for one gear train (text or --json)");
    add_analysis_options(*cmd, *o);
    cmd->add_flag("--json", o->json, "print one JSON object instead of text");
    cmd->footer("Example: sphtroch classify --a2 pi/2 --a3 pi/2 --n 2 --json");
    actions.emplace_back(cmd, [o] { run_classify(*o); });
  }
  {
    auto o = std::make_shared<AnalysisOptions>();
    CLI::App* cmd = app.add_subcommand("nodes", "nodes and cusps as CSV: kind,x,y,z,t1,t2,branches,id");
    add_analysis_options(*cmd, *o);
    cmd->add_option("--radius", o->radius, "scale the positions x,y,z by R in [1e-100, 1e100]: the cone distance, any unit")->type_name("R");
    cmd->add_flag("--degrees", o->degrees, "t1, t2 in degrees (header t1_deg,t2_deg)");
    cmd->footer("kind is crossing, tangency or cusp; t1, t2 are the first two branch parameters (theta2, radians;\n"
                "degrees with --degrees); id N1.. / C1.. as plot labels them.");
    actions.emplace_back(cmd, [o] { run_nodes(*o); });
  }
  {
    auto o = std::make_shared<AnalysisOptions>();
    CLI::App* cmd = app.add_subcommand("plot", "the curve on the sphere as SVG, nodes and cusps marked");
    add_analysis_options(*cmd, *o);
    o->plot.add_to(*cmd);
    cmd->footer("Labels N<i>, C<j> are the rows of `sphtroch nodes` (nodes, then cusps).\n"
                "Example: sphtroch plot --a2 pi/3 --a3 pi/2 --n 2 -o fig5f.svg");
    actions.emplace_back(cmd, [o] { run_plot(*o); });
  }
  {
    auto o = std::make_shared<CrossingsOptions>();
    CLI::App* cmd = app.add_subcommand("crossings", "exact self-crossings of any spherical polyline given as CSV x,y,z");
    cmd->add_option("--input", o->input,
                    "the polyline: CSV (rows x,y,z, or a header naming x,y,z), NumPy .npy (N,3|4|7), - for stdin")->type_name("FILE")
        ->required();
    cmd->add_flag("--open", o->open, "the polyline is open (default: closed, the last vertex joins the first)");
    cmd->add_option("--pairs", o->pairs, "write the edge-index pairs as CSV i,j,kind to FILE (in the search's order)")->type_name("FILE");
    cmd->add_option("--max-crossings", o->max_crossings,
                    "refuse (exit 2) a polyline with more crossings + touchings (0 .. 1e15; default 1e7)")->type_name("N");
    cmd->add_option("--max-work", o->max_work,
                    "refuse (exit 2) a search needing more candidate + box pairs (0 .. 1e15; default 5e7, ~5 s)")->type_name("N");
    cmd->add_flag("--json", o->json, "one JSON object: vertices, crossings, touchings, seconds_read, seconds_search, ...");
    cmd->add_option("--threads", o->threads, "threads parsing CSV (1 .. 1024; default: all cores, at most 2 used)")->type_name("N");
    add_output_option(*cmd, o->output, "the summary");
    cmd->footer(
        "Edge e joins vertex e to e+1; adjacent edges are never counted. The format is told by the\n"
        "first bytes (.npy magic), not the name: a CSV with a header takes the columns x, y, z by\n"
        "name (so `sphtroch trace` output works); .npy float64/float32 (N, 3) x,y,z or (N, 4)/(N, 7)\n"
        "trace arrays. Reading and searching are timed separately (seconds_read, seconds_search).\n"
        "Example: sphtroch trace --a2 1 --a3 2 --n 7/3 | sphtroch crossings --input - --json");
    actions.emplace_back(cmd, [o] { run_crossings(*o); });
    register_tolerance(app, actions);
  }
}

}  // namespace sphtroch::cli
