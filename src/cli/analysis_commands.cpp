// sphtroch classify | nodes | plot | crossings — the node census and its reports. One of the two
// CLI translation units that include CGAL (through analysis.hpp; the other is scene_command.cpp).
// The printers (reports.hpp) are shared with `sphtroch scene`: one printer per output format.
#include "cli_common.hpp"
#include "reports.hpp"

#include "sphtroch/analysis.hpp"
#include "sphtroch/parse.hpp"
#include "sphtroch/polyline_input.hpp"
#include "sphtroch/sampling.hpp"
#include "sphtroch/svg_plot.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <chrono>
#include <fstream>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sphtroch::cli {

namespace {

std::string vec_text(const Vector3d& v) { return "(" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + ")"; }

double degrees(double r) { return r * 180.0 / Constants<double>::pi(); }

nlohmann::json vec_json(const Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

}  // namespace

nlohmann::json z_extremes_json(const ZExtremes& z) {
  using nlohmann::json;
  json zmax = json::array(), zmin = json::array();
  for (const auto& p : z.maxima) zmax.push_back({{"param", p.param}, {"position", vec_json(p.position)}});
  for (const auto& p : z.minima) zmin.push_back({{"param", p.param}, {"position", vec_json(p.position)}});
  return {{"z_max", z.z_max}, {"z_min", z.z_min}, {"maxima", zmax}, {"minima", zmin}};
}

nlohmann::json classification_json(const TrainOptions& text, const Classification& c) {
  using nlohmann::json;
  const GearTrain& in = c.input;
  const GearTrain& tr = c.snapped.train;
  json j;
  j["inputs"] = {{"a2", in.a2()}, {"a3", in.a3()}, {"a2_text", text.a2}, {"a3_text", text.a3},
                 {"n", in.ratio().str()}, {"n_value", in.n()}, {"phase", in.phase_given()}, {"phase_reduced", in.phase()}, {"literal", c.literal}};
  j["cone_angles"] = {{"a_p", tr.planet_cone()}, {"a_s", tr.sun_cone()}};
  j["period"] = tr.period();
  j["class"] = to_string(c.curve_class);
  j["counts"] = {{"nodes", c.nodes.size()}, {"cusps", c.cusps.size()}, {"crossings", c.crossings},
                 {"tangencies", c.tangencies}};
  json nodes = json::array();
  for (const Node& n : c.nodes) {
    nodes.push_back({{"position", vec_json(n.position)},
                     {"longitude", std::atan2(n.position.y(), n.position.x())},
                     {"latitude", std::asin(std::clamp(n.position.z(), -1.0, 1.0))},
                     {"params", n.params},
                     {"branches", n.branches},
                     {"kind", to_string(n.kind)},
                     {"angle", n.angle},
                     {"crossing_pairs", n.crossing_pairs},
                     {"tangency_pairs", n.tangency_pairs}});
  }
  j["nodes"] = nodes;
  json cusps = json::array();
  for (const Cusp& k : c.cusps) cusps.push_back({{"position", vec_json(k.position)}, {"param", k.param}, {"speed", k.speed}});
  j["cusps"] = cusps;
  j["cusp_within_resolution"] = c.cusp_within_resolution;
  json hits = json::array();
  for (const Boundary& b : c.snapped.hits) hits.push_back({{"boundary", b.name}, {"value", b.value}, {"margin", b.margin}});
  j["boundaries"] = {{"on", hits},
                     {"a2_right_angle", c.snapped.a2_snapped},
                     {"tolerance", c.snapped.tolerance},
                     {"pitch_cone_margin", c.cone.pitch},
                     {"mirror_pitch_cone_margin", c.cone.mirror}};
  j["z_extremes"] = z_extremes_json(c.z);
  json planes = json::array();
  for (const auto& p : c.symmetry_planes.planes)
    planes.push_back({{"normal", vec_json(p.normal)}, {"azimuth", p.azimuth}, {"param_offset", p.param_offset}});
  j["symmetry"] = {{"rotation_order", c.symmetry_planes.rotation_order}, {"mirror_planes", planes}};
  json criteria = json::array();
  for (const Criterion& k : c.analytic.criteria)
    criteria.push_back({{"equation", k.equation},
                        {"statement", k.statement},
                        {"status", to_string(k.status)},
                        {"lower", k.lower},
                        {"upper", k.upper},
                        {"lower_margin", k.lower_margin},
                        {"upper_margin", k.upper_margin},
                        {"prediction", k.prediction}});
  j["analytic"] = {{"applicable", c.analytic.applicable},
                   {"predicted_nodes", c.analytic.predicted_nodes ? json(*c.analytic.predicted_nodes) : json(nullptr)},
                   {"predicted_cusps", c.analytic.predicted_cusps},
                   {"class", c.analytic.curve_class},
                   {"criteria", criteria}};
  j["censuses"] = {
      {"polyline",
       {{"nodes", c.polyline.nodes.size()},
        {"samples", c.polyline.samples},
        {"polyline_crossings", c.polyline.polyline_crossings},
        {"polyline_touchings", c.polyline.polyline_touchings},
        {"near_misses", c.polyline.near_misses},
        {"newton_rejected", c.polyline.newton_failures}}},
      {"root_count",
       {{"nodes", c.root.nodes.size()},
        {"roots", c.root.roots.size()},
        {"north_pole_node", c.root.north_pole_node},
        {"south_pole_node", c.root.south_pole_node},
        {"error_bound", c.root.error_bound}}}};
  j["agreement"] = {{"ok", c.agreement.ok()},
                    {"censuses_agree", c.agreement.censuses_agree},
                    {"analytic_agrees", c.agreement.analytic_agrees ? json(*c.agreement.analytic_agrees) : json(nullptr)},
                    {"notes", c.agreement.notes}};
  j["tolerances"] = {{"boundary", c.snapped.tolerance},      {"cusp_resolution", kCuspResolution},
                     {"tangency", c.tangency_tolerance},     {"node_residual", kNodeResidual},
                     {"node_merge_distance", kNodeMergeDistance}, {"agreement_distance", kAgreementDistance},
                     {"branch_grouping", kBranchParamTolerance}, {"lens_scan_angle", kLensScanAngle}};
  j["work"] = {{"points_evaluated", c.work.points_evaluated},
               {"predicates", c.work.predicates},
               {"newton_steps", c.work.newton_steps},
               {"root_function_evaluations", c.work.root_evaluations},
               {"seconds", c.work.seconds}};
  return j;
}

void write_classification_text(std::ostream& out, const TrainOptions& text, const Classification& c) {
  const GearTrain& in = c.input;
  const GearTrain& tr = c.snapped.train;
  out << "sphtroch classify — spherical planetary gear train (Lin & Tsai 1990)\n\n";
  out << "inputs\n";
  out << "  a2 = " << text.a2 << " = " << number(in.a2()) << " rad (" << number(degrees(in.a2())) << " deg)\n";
  out << "  a3 = " << text.a3 << " = " << number(in.a3()) << " rad (" << number(degrees(in.a3())) << " deg)\n";
  out << "  n = " << in.ratio().str() << ", phase = " << number(in.phase_given()) << " rad";
  if (in.phase() != in.phase_given()) out << " (reduced to " << number(in.phase()) << ")";
  out << "\n";
  out << "  reading: " << (c.literal ? "literal (the given doubles)" : "default (boundaries within tolerance are snapped)") << "\n";
  out << "cone angles\n  a_p = " << number(tr.planet_cone()) << " rad, a_s = " << number(tr.sun_cone())
      << " rad; period 2*pi*q = " << number(tr.period()) << " rad\n";
  out << "boundaries (tolerance " << number(c.snapped.tolerance) << " rad)\n";
  if (c.snapped.a2_snapped) out << "  a2 = pi/2 (margin " << number(c.snapped.a2_margin) << ")\n";
  for (const Boundary& b : c.snapped.hits) out << "  on " << b.name << " (margin " << number(b.margin) << ")\n";
  if (!c.snapped.a2_snapped && c.snapped.hits.empty()) out << "  none within tolerance\n";
  out << "  margin to pitch cone a3 - a_p = " << number(c.cone.pitch) << ", to mirror a3 - (pi - a_p) = "
      << number(c.cone.mirror) << "\n\n";

  out << "class: " << to_string(c.curve_class) << " — " << c.nodes.size() << " node(s) (" << c.crossings << " crossing, "
      << c.tangencies << " tangency), " << c.cusps.size() << " cusp(s)"
      << (c.cusp_within_resolution ? " [cusp within resolution " + number(kCuspResolution) + " rad]" : "") << "\n";
  std::size_t i = 0;
  for (const Node& n : c.nodes) {
    out << "  node " << ++i << ": " << to_string(n.kind) << ", " << n.branches << " branches, at " << vec_text(n.position)
        << "\n          lon " << number(degrees(std::atan2(n.position.y(), n.position.x()))) << " deg, lat "
        << number(degrees(std::asin(std::clamp(n.position.z(), -1.0, 1.0)))) << " deg; theta2 =";
    for (double t : n.params) out << ' ' << number(t);
    out << "; angle " << number(n.angle) << " rad\n";
  }
  i = 0;
  for (const Cusp& k : c.cusps)
    out << "  cusp " << ++i << ": at " << vec_text(k.position) << ", theta2 = " << number(k.param) << ", speed "
        << number(k.speed) << "\n";
  out << "\nz extremes (Eqs. 14/15, 32-35 generalised)\n  z_max = " << number(c.z.z_max) << " at theta2 =";
  for (const auto& p : c.z.maxima) out << ' ' << number(p.param);
  out << "\n  z_min = " << number(c.z.z_min) << " at theta2 =";
  for (const auto& p : c.z.minima) out << ' ' << number(p.param);
  out << "\nsymmetry: " << c.symmetry_planes.rotation_order << "-fold about Z1; mirror planes with normals at azimuth";
  for (const auto& p : c.symmetry_planes.planes) out << ' ' << number(p.azimuth);
  out << " rad\n\nthe report's criteria\n";
  for (const Criterion& k : c.analytic.criteria)
    out << "  " << k.equation << ": " << k.statement << " — " << to_string(k.status) << " (margins "
        << number(k.lower_margin) << ", " << number(k.upper_margin) << "): " << k.prediction << "\n";
  out << "  predicted: "
      << (c.analytic.predicted_nodes ? std::to_string(*c.analytic.predicted_nodes) + " node(s)" : std::string("nodes not given by the report for this n"))
      << ", " << c.analytic.predicted_cusps << " cusp(s)\n";
  out << "\ncensuses side by side\n";
  out << "  polyline (exact CGAL predicates + Newton): " << c.polyline.nodes.size() << " node(s) from "
      << c.polyline.samples << " samples, " << c.polyline.polyline_crossings << " polyline crossings, "
      << c.polyline.polyline_touchings << " touchings, " << c.polyline.near_misses << " near misses\n";
  out << "  root count (1D, interval of b in (0, pi)): " << c.root.nodes.size() << " node(s) from "
      << c.root.roots.size() << " root(s)" << (c.root.north_pole_node ? " + north pole" : "")
      << (c.root.south_pole_node ? " + south pole" : "") << "\n";
  out << "  agreement: " << (c.agreement.ok() ? "yes" : "NO") << "\n";
  for (const auto& note : c.agreement.notes) out << "    DISAGREEMENT: " << note << "\n";
  out << "\ntolerances: boundary " << shortest_number(c.snapped.tolerance) << " rad, cusp resolution " << shortest_number(kCuspResolution)
      << " rad, tangency " << shortest_number(c.tangency_tolerance) << ", node residual " << shortest_number(kNodeResidual)
      << ", node merge " << shortest_number(kNodeMergeDistance) << ", agreement " << shortest_number(kAgreementDistance)
      << ", branch grouping " << shortest_number(kBranchParamTolerance) << " rad, lens scan below " << shortest_number(kLensScanAngle)
      << " rad\n";
  out << "work: " << c.work.points_evaluated << " points evaluated, " << c.work.predicates << " exact predicates, "
      << c.work.newton_steps << " Newton steps, " << c.work.root_evaluations << " root-function evaluations, "
      << seconds_text(c.work.seconds) << " s\n";
}

void write_nodes_csv(std::ostream& out, const std::vector<Node>& nodes, const std::vector<Cusp>& cusps) {
  out << "kind,x,y,z,t1,t2,branches\n";
  for (const Node& n : nodes) {
    out << to_string(n.kind) << ',' << number(n.position.x()) << ',' << number(n.position.y()) << ','
        << number(n.position.z()) << ',' << number(n.params.front()) << ',' << number(n.params.size() > 1 ? n.params[1] : n.params.front())
        << ',' << n.branches << '\n';
  }
  for (const Cusp& k : cusps)
    out << "cusp," << number(k.position.x()) << ',' << number(k.position.y()) << ',' << number(k.position.z()) << ','
        << number(k.param) << ',' << number(k.param) << ",1\n";
}

std::string plot_svg(const TrainOptions& text, const GearTrain& analysed, const Trajectory<double>& trajectory,
                     const std::vector<Node>& nodes, const std::vector<Cusp>& cusps) {
  std::size_t crossings = 0, tangencies = 0;
  for (const Node& n : nodes) (n.kind == NodeKind::crossing ? crossings : tangencies)++;
  PlotOptions po;
  std::ostringstream caption;
  caption << "a2 = " << text.a2 << ", a3 = " << text.a3 << ", n = " << analysed.ratio().str();
  if (analysed.phase() != 0.0) caption << ", phase = " << text.phase;
  caption << " — " << nodes.size() << " node(s)";
  if (!nodes.empty()) caption << " (" << crossings << " crossing, " << tangencies << " tangency)";
  caption << ", " << cusps.size() << " cusp(s)";
  po.caption = caption.str();
  return render_sphere_svg(trajectory, nodes, cusps, po);
}

namespace {

struct AnalysisOptions {
  TrainOptions train;
  std::string samples, output;
  bool literal = false;
  bool json = false;
};

void add_analysis_options(CLI::App& cmd, AnalysisOptions& o) {
  o.train.add_to(cmd);
  cmd.add_flag("--literal", o.literal,
               "analyse the given doubles exactly as given (no snapping onto boundaries within 1e-10 rad)");
  cmd.add_option("--samples", o.samples, "uniform samples of the polyline census (1024 .. 10000000; default 256*(q+|p|))");
  add_output_option(cmd, o.output, "the result");
}

AnalysisSettings analysis_settings(const AnalysisOptions& o) {
  AnalysisSettings s;
  s.literal = o.literal;
  if (!o.samples.empty()) s.census_samples = parse_count(o.samples, "samples", kMinCensusSamples, kMaxSamples);
  return s;
}

void run_classify(const AnalysisOptions& o) {
  const GearTrain train = o.train.train();  // first: its errors come before those of --samples
  const Analysis a(train, analysis_settings(o));  // a.classification() is classify(train, settings)
  const Classification& c = a.classification();
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << classification_json(o.train, c).dump(2) << "\n";
    else write_classification_text(out, o.train, c);
  });
}

// nodes and plot need the crossing and cusp stages only: no root-count census.
void run_nodes(const AnalysisOptions& o) {
  const GearTrain train = o.train.train();
  const Analysis a(train, analysis_settings(o));
  write_output(o.output, [&](std::ostream& out) { write_nodes_csv(out, a.nodes(), a.cusps()); });
}

void run_plot(const AnalysisOptions& o) {
  const GearTrain train = o.train.train();
  const Analysis a(train, analysis_settings(o));
  const std::string svg = plot_svg(o.train, a.analysed(), a.plot_trajectory(), a.nodes(), a.cusps());
  write_output(o.output, [&](std::ostream& out) { out << svg; });
}

struct CrossingsOptions {
  std::string input, pairs, output, threads;
  bool open = false;
  bool json = false;
};

void write_pairs_csv(OutputFile& file, const SelfCrossings& sc) {
  std::vector<EdgePair> all = sc.crossings;
  all.insert(all.end(), sc.touchings.begin(), sc.touchings.end());
  std::sort(all.begin(), all.end());
  file.write("i,j,kind\n");
  for (const EdgePair& e : all) {
    char* p = file.reserve(64);
    p = std::to_chars(p, p + 20, e.i).ptr;
    *p++ = ',';
    p = std::to_chars(p, p + 20, e.j).ptr;
    *p++ = ',';
    const std::string_view kind = to_string(e.kind);
    p = std::copy(kind.begin(), kind.end(), p);
    *p++ = '\n';
    file.advance(p);
  }
}

void run_crossings(const CrossingsOptions& o) {
  using clock = std::chrono::steady_clock;
  const std::size_t threads = parse_threads(o.threads);
  check_distinct_files({{o.output, "--output"}, {o.pairs, "--pairs"}}, {{o.input, "--input"}});
  const auto start_read = clock::now();
  const PolylineInput input = read_polyline(o.input, "input", std::min<std::size_t>(threads, 2));
  const double seconds_read = std::chrono::duration<double>(clock::now() - start_read).count();
  const std::vector<Vector3d>& vertices = input.vertices;
  SelfCrossings sc;
  double seconds = 0;
  try {
    validate_spherical_polyline(vertices, !o.open);
    const auto start = clock::now();
    sc = find_self_crossings(vertices, !o.open);
    seconds = std::chrono::duration<double>(clock::now() - start).count();
  } catch (const InvalidInput& e) {
    throw UsageError{"--input = " + o.input + ": " + e.value() + ": " + e.problem() + "; valid: " + e.valid_range()};
  }
  StagedOutputs outputs;  // --pairs and -o appear together or not at all
  if (!o.pairs.empty()) write_pairs_csv(outputs.open(o.pairs, "--pairs"), sc);
  outputs.stage(o.output, "--output", [&](std::ostream& out) {
    if (o.json) {
      nlohmann::json j = {{"vertices", vertices.size()},           {"closed", !o.open},
                          {"crossings", sc.crossings.size()},      {"touchings", sc.touchings.size()},
                          {"candidate_pairs", sc.candidate_pairs}, {"predicates", sc.predicates},
                          {"input_format", input.format},          {"seconds_read", seconds_read},
                          {"seconds_search", seconds}};
      out << j.dump(2) << "\n";
    } else {
      out << "vertices " << vertices.size() << (o.open ? " (open)" : " (closed)") << ", read as " << input.format
          << "\ncrossings " << sc.crossings.size() << "\ntouchings " << sc.touchings.size() << "\ncandidate pairs "
          << sc.candidate_pairs << ", exact predicates " << sc.predicates << "\nseconds_read "
          << seconds_text(seconds_read) << "\nseconds_search " << seconds_text(seconds) << "\n";
    }
  });
  outputs.commit();
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
    CLI::App* cmd = app.add_subcommand("nodes", "nodes and cusps as CSV: kind,x,y,z,t1,t2,branches");
    add_analysis_options(*cmd, *o);
    cmd->footer("kind is crossing, tangency or cusp; t1, t2 are the first two branch parameters (theta2, radians).");
    actions.emplace_back(cmd, [o] { run_nodes(*o); });
  }
  {
    auto o = std::make_shared<AnalysisOptions>();
    CLI::App* cmd = app.add_subcommand("plot", "the curve on the sphere as SVG, nodes and cusps marked");
    add_analysis_options(*cmd, *o);
    cmd->footer("Example: sphtroch plot --a2 pi/3 --a3 pi/2 --n 2 -o fig5f.svg");
    actions.emplace_back(cmd, [o] { run_plot(*o); });
  }
  {
    auto o = std::make_shared<CrossingsOptions>();
    CLI::App* cmd = app.add_subcommand("crossings", "exact self-crossings of any spherical polyline given as CSV x,y,z");
    cmd->add_option("--input", o->input,
                    "the polyline: CSV (rows x,y,z, or a header naming x,y,z), NumPy .npy (N,3|4|7), - for stdin")
        ->required();
    cmd->add_flag("--open", o->open, "the polyline is open (default: closed, the last vertex joins the first)");
    cmd->add_option("--pairs", o->pairs, "write the edge-index pairs as CSV i,j,kind to FILE");
    cmd->add_flag("--json", o->json, "one JSON object: vertices, crossings, touchings, seconds_read, seconds_search, ...");
    cmd->add_option("--threads", o->threads, "threads parsing CSV (1 .. 1024; default: all cores, at most 2 used)");
    add_output_option(*cmd, o->output, "the summary");
    cmd->footer(
        "Edge e joins vertex e to e+1; adjacent edges are never counted. The format is told by the\n"
        "first bytes (.npy magic), not the name: a CSV with a header takes the columns x, y, z by\n"
        "name (so `sphtroch trace` output works); .npy float64/float32 (N, 3) x,y,z or (N, 4)/(N, 7)\n"
        "trace arrays. Reading and searching are timed separately (seconds_read, seconds_search).\n"
        "Example: sphtroch trace --a2 1 --a3 2 --n 7/3 | sphtroch crossings --input - --json");
    actions.emplace_back(cmd, [o] { run_crossings(*o); });
  }
}

}  // namespace sphtroch::cli
