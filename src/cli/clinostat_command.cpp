// sphtroch clinostat — a two-axis clinostat or random positioning machine: its gravity path as a
// gear train, the mean over a period, the worst window mean, the time to epsilon, the dwell map;
// or (--trace) the gravity seen by the sample as CSV t,gx,gy,gz or .npy. Eigen (+ HEALPix for
// --coverage, opened on demand: dwell_input.hpp); the library's machine/ layer does the work (docs/clinostat.md).
#include "cli_common.hpp"
#include "dwell_input.hpp"
#include "png_output.hpp"

#include "sphtroch/io/npy.hpp"
#include "sphtroch/io/trace_output.hpp"
#include "sphtroch/machine/clinostat_plot.hpp"
#include "sphtroch/machine/clinostat_text.hpp"
#include "sphtroch/machine/clinostat_train.hpp"
#include "sphtroch/machine/dwell_map_result.hpp"
#include "sphtroch/machine/time_to_epsilon.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>

namespace sphtroch::cli {

namespace {

constexpr int kMaxPlotNside = 32;

struct ClinostatOptions {
  ClinostatText machine;
  std::string window, epsilon, resolution, coverage, nside, start, duration, samples, output, plot;
  bool json = false, trace = false;
};

double parse_positive(const std::string& text, const std::string& field, double max, const std::string& valid) {
  const std::optional<double> v = parse_number(text);
  if (!v || !(*v > 0) || *v > max) throw InvalidInput(field, text, "not a positive number in range", valid);
  return *v;
}

double parse_time(const std::string& text, const std::string& field) {
  if (text.empty()) return 0;
  const std::optional<double> v = parse_number(text);
  if (!v || std::fabs(*v) > Clinostat::kMaxTime) throw InvalidInput(field, text, "not a finite time", "|t| <= 1e12 seconds");
  return *v;
}

/// What the report computes, read and checked before any of it runs.
struct Request {
  std::optional<double> window, epsilon, coverage;
  double resolution = 1, start = 0;
  int nside = 8;
};

Request read_request(const ClinostatOptions& o) {
  Request r;
  if (!o.window.empty()) r.window = parse_positive(o.window, "window", 1e9, "seconds in (0, 1e9]");
  if (!o.epsilon.empty()) r.epsilon = parse_positive(o.epsilon, "epsilon", 1e9, "a bound in units of g0, > 0");
  if (!o.resolution.empty()) {
    if (!r.epsilon) throw UsageError{"--resolution = " + o.resolution + ": only with --epsilon; valid: --epsilon E --resolution S"};
    r.resolution = parse_positive(o.resolution, "resolution", 1e6, "seconds in (0, 1e6]");
  }
  if (!o.coverage.empty()) r.coverage = parse_positive(o.coverage, "coverage", Clinostat::kMaxTime, "seconds in (0, 1e12]");
  if (!o.nside.empty()) {
    if (!r.coverage) throw UsageError{"--nside = " + o.nside + ": only with --coverage; valid: --coverage S --nside K"};
    r.nside = static_cast<int>(parse_count(o.nside, "nside", 1, 1024));
    if ((r.nside & (r.nside - 1)) != 0) throw InvalidInput("nside", o.nside, "not a power of two", "1, 2, 4, ..., 1024");
  }
  r.start = parse_time(o.start, "start");
  return r;
}

nlohmann::json vector_json(const Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

nlohmann::json train_json(const ClinostatTrain& ct) {
  if (!ct.train) return nullptr;
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) rows.push_back(vector_json(ct.rotation.row(i).transpose()));
  return {{"n", ct.train->ratio().str()}, {"a2", ct.train->a2()}, {"a3", ct.train->a3()}, {"phase", ct.train->phase()},
          {"theta2_at_0", ct.theta2_at_0}, {"theta2_rate", ct.theta2_rate}, {"rotation", rows}};
}

/// The report's numbers, computed once for the text and the JSON.
struct Report {
  ClinostatTrain train;
  const GravitySeries* series = nullptr;
  std::optional<WorstWindowMean> worst;
  std::optional<TimeToEpsilon> time_to;
  std::optional<DwellMap> dwell;
  bool effective = false;
};

nlohmann::json report_json(const Report& r, const Request& q) {
  nlohmann::json out;
  out["train"] = train_json(r.train);
  if (!r.train.train) out["train_note"] = r.train.reason;
  out["averaged"] = r.effective ? "effective gravity at the offset" : "gravity";
  out["period_s"] = r.series->period_s() ? nlohmann::json(*r.series->period_s()) : nlohmann::json(nullptr);
  out["mean_over_period"] = vector_json(r.series->period_mean());
  if (r.worst)
    out["worst_window_mean"] = {{"window_s", r.worst->window_s}, {"lower", r.worst->lower}, {"upper", r.worst->upper},
                                {"start_s", r.worst->start_s}, {"certified", r.worst->certified}};
  if (r.time_to) {
    const auto or_null = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
    out["time_to_epsilon"] = {{"epsilon", r.time_to->epsilon}, {"resolution_s", q.resolution},
                              {"first_s", or_null(r.time_to->first_s)}, {"stays_below_from_s", or_null(r.time_to->stays_below_from_s)},
                              {"above_s", or_null(r.time_to->above_s)},
                              {"reason", r.time_to->reason}, {"certified", r.time_to->certified}};
  }
  if (r.dwell)
    out["coverage"] = {{"start_s", r.dwell->start_s}, {"duration_s", r.dwell->duration_s}, {"nside", r.dwell->nside},
                       {"order", "RING"}, {"fraction", r.dwell->visited_fraction}, {"dwell_cv", r.dwell->dwell_cv},
                       {"bound_s", r.dwell->bound_s}, {"dwell_s", r.dwell->dwell_s}};
  return out;
}

std::string degrees(double radians) { return number_text(radians * 180 / Constants<double>::pi()); }

void write_report_text(std::ostream& out, const Clinostat& m, const Report& r, const Request& q) {
  const ClinostatSettings& s = m.settings();
  out << "clinostat: outer " << s.outer.str() << " rpm, inner " << s.inner.str() << " rpm, tilt " << number_text(s.tilt_deg)
      << " deg, frame angle " << number_text(s.frame_angle_deg) << " deg\n";
  if (r.train.train) {
    const GearTrain& t = *r.train.train;
    out << "gravity path: the spherical trochoid of the gear train n = " << t.ratio().str() << ", a2 = " << degrees(t.a2())
        << " deg, a3 = " << degrees(t.a3()) << " deg, phase = " << number_text(t.phase()) << " rad\n"
        << "  traced by: sphtroch trace --a2 " << number_text(t.a2()) << " --a3 " << number_text(t.a3()) << " --n "
        << t.ratio().str() << " --phase " << number_text(t.phase()) << "\n"
        << "  g_s(t) = rotation * P(theta2), theta2 = " << number_text(r.train.theta2_at_0)
        << (r.train.theta2_rate < 0 ? " - " : " + ") << number_text(std::fabs(r.train.theta2_rate)) << " t rad (t in s; --json gives the rotation)\n";
  } else {
    out << "gravity path: " << r.train.reason << "\n";
  }
  if (r.series->period_s())
    out << "period: " << number_text(*r.series->period_s()) << " s (" << number_text(*r.series->period_s() / 60)
        << " min): both frames back at their start\n";
  else
    out << "period: none (the gravity does not move in the sample)\n";
  const Vector3d c = r.series->period_mean();
  out << "mean " << (r.effective ? "effective gravity" : "gravity") << " over a period: (" << number_text(c.x()) << ", "
      << number_text(c.y()) << ", " << number_text(c.z()) << ") g0, |mean| = " << number_text(c.norm()) << " g0\n";
  if (r.worst)
    out << "worst window mean, W = " << number_text(r.worst->window_s) << " s: M(W) in [" << number_text(r.worst->lower) << ", "
        << number_text(r.worst->upper) << "] g0, reached by the window starting at " << number_text(r.worst->start_s) << " s"
        << (r.worst->certified ? "" : " (NOT CERTIFIED: the bracket is wider than 1e-9)") << "\n";
  if (r.time_to) {
    out << "time to epsilon = " << number_text(r.time_to->epsilon) << " g0 (windows in steps of " << number_text(q.resolution) << " s): ";
    if (r.time_to->first_s)
      out << "the first window below is " << number_text(*r.time_to->first_s) << " s; every window from "
          << number_text(*r.time_to->stays_below_from_s) << " s on, of any length, is below"
          << (r.time_to->above_s ? " (one of " + number_text(*r.time_to->above_s) + " s is above)" : std::string()) << "\n";
    else
      out << (r.time_to->certified ? "none: " : "NOT CERTIFIED: ") << r.time_to->reason << "\n";
  }
  if (r.dwell)
    out << "coverage over [" << number_text(r.dwell->start_s) << ", " << number_text(r.dwell->start_s + r.dwell->duration_s)
        << "] s on " << r.dwell->dwell_s.size() << " HEALPix cells (nside " << r.dwell->nside << "): " << number_text(100 * r.dwell->visited_fraction)
        << "% visited, dwell coefficient of variation " << number_text(r.dwell->dwell_cv) << "; each cell's time within "
        << number_text(r.dwell->bound_s) << " s (--json gives the dwell per cell)\n";
}

/// --plot: the dwell map of the report's coverage (or of one period, at most an hour) and M(W)
/// at 100 windows up to 1.25 times the time to epsilon (or three periods, at most two hours), by
/// window_curve (searched, or the torus bound when 100 searches would cost more than
/// kMaxCurvePieces: the picture's cost is bounded whatever the period).
std::string plot_svg(const Clinostat& m, const GravitySeries& series, const Report& r, const Request& q) {
  ClinostatPlot plot;
  const ClinostatSettings& s = m.settings();
  plot.title = "clinostat " + s.outer.str() + " / " + s.inner.str() + " rpm, tilt " + number_text(s.tilt_deg) + " deg, frame angle " +
               number_text(s.frame_angle_deg) + " deg";
  const double period = series.period_s().value_or(60.0);
  if (r.dwell || std::string(healpix_plugin_state()) == "yes") {  // the dwell panel: in a build with HEALPix
    const DwellMap dwell = r.dwell ? *r.dwell : dwell_map_by_plugin(m.settings(), q.start, std::min(period, 3600.0), q.nside);
    plot.cells = cell_outlines_by_plugin(dwell.nside);
    plot.dwell_s = dwell.dwell_s;
    plot.title += "; dwell over " + number_text(dwell.duration_s) + " s";
  }
  plot.epsilon = q.epsilon;
  const double longest = r.time_to && r.time_to->stays_below_from_s ? 1.25 * *r.time_to->stays_below_from_s : std::min(3 * period, 7200.0);
  const WindowCurve curve = window_curve(series, longest, 100);
  for (const WorstWindowMean& w : curve.points) plot.windows.push_back({w.window_s, w.lower, w.upper});
  if (curve.torus) plot.window_note = "the period is too long to search: the upper bound over every frame angle";
  return clinostat_plot_svg(plot);
}

/// --plot's file: FILE.svg or FILE.png (any case), not standard output; its map at most nside 32
/// (12,288 cells drawn; the SVG grows as the cells).
void check_plot_request(const std::string& plot, const Request& q) {
  std::string lower = plot;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto ends = [&](const char* e) { return lower.size() > 4 && lower.compare(lower.size() - 4, 4, e) == 0; };
  if (!ends(".svg") && !ends(".png")) throw InvalidInput("plot", plot, "not a picture file name", "FILE.svg or FILE.png");
  check_svg_name(plot, "plot");
  require_png_writer(plot, "plot");
  if (q.nside > kMaxPlotNside)
    throw InvalidInput("nside", std::to_string(q.nside), "too many cells to draw with --plot", "nside <= 32 with --plot (12,288 cells)");
}

void run_report(const ClinostatOptions& o, const Clinostat& m) {
  const Request q = read_request(o);
  if (!o.plot.empty()) check_plot_request(o.plot, q);
  if (!o.start.empty() && !q.coverage && o.plot.empty())
    throw UsageError{"--start = " + o.start + ": only with --coverage, --plot or --trace; valid: --coverage S --start T"};
  if (q.coverage) require_dwell_maps("coverage", o.coverage);  // refused now, not after the other numbers
  Report r;
  r.effective = m.has_offset();
  const GravitySeries series = r.effective ? GravitySeries::of_effective_gravity(m) : GravitySeries::of_gravity(m);
  r.series = &series;
  r.train = clinostat_train(m);
  if (q.window || q.epsilon) worst_window_mean_cost(series);  // refuse a period too long up front
  if (q.window) r.worst = worst_window_mean(series, *q.window);
  if (q.epsilon) r.time_to = time_to_epsilon(series, *q.epsilon, q.resolution);
  if (q.coverage) r.dwell = dwell_map_by_plugin(m.settings(), q.start, *q.coverage, q.nside);
  std::vector<std::string> written;
  if (!o.plot.empty()) {
    write_output(o.plot, [&](std::ostream& out) { out << picture_bytes(plot_svg(m, series, r, q), o.plot); }, "--plot", kPictureOutputs);
    written.push_back(o.plot);
  }
  write_stdout_after_outputs(written, [&](std::ostream& out) {
    if (o.json) out << report_json(r, q).dump(2) << "\n";
    else write_report_text(out, m, r, q);
  });
  if ((r.worst && !r.worst->certified) || (r.time_to && !r.time_to->certified))
    throw UncertifiedResult{"clinostat: " + std::string(r.worst && !r.worst->certified ? "the worst window mean's bracket is wider than 1e-9"
                                                                                        : r.time_to->reason)};
}

/// --trace: N samples over [start, start + duration], both ends included; CSV or .npy (by -o).
void run_trace(const ClinostatOptions& o, const Clinostat& m) {
  for (const auto& [given, name] : {std::pair{!o.window.empty(), "--window"}, std::pair{!o.epsilon.empty(), "--epsilon"},
                                    std::pair{!o.coverage.empty(), "--coverage"}, std::pair{o.json, "--json"},
                                    std::pair{!o.plot.empty(), "--plot"}})
    if (given) throw UsageError{std::string(name) + ": not with --trace; valid: --trace --duration S --samples N [-o FILE]"};
  if (o.duration.empty()) throw UsageError{"--trace needs --duration S; valid: --trace --duration S --samples N [-o FILE]"};
  const double duration = parse_positive(o.duration, "duration", Clinostat::kMaxTime, "seconds in (0, 1e12]");
  const double start = parse_time(o.start, "start");
  const std::size_t n = o.samples.empty() ? 1001 : parse_count(o.samples, "samples", 2, kMaxSamples);
  check_output_suffix(o.output, "output", {"csv", "txt", "text", "npy"});
  std::string lower = o.output;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool npy = lower.size() >= 4 && lower.compare(lower.size() - 4, 4, ".npy") == 0;
  const bool effective = m.has_offset();
  OutputFile out = OutputFile::open(o.output, "--output");
  if (npy) out.write(npy_header(n, 4));
  else out.write("t,gx,gy,gz\n");
  std::string block;
  for (std::size_t i = 0; i < n; ++i) {
    const double dt = duration * static_cast<double>(i) / static_cast<double>(n - 1);
    const Vector3d g = effective ? m.effective_gravity_at(m.outer_angle(start, dt), m.inner_angle(start, dt))
                                 : m.gravity_at(m.outer_angle(start, dt), m.inner_angle(start, dt));
    const double row[4] = {start + dt, g.x() + 0.0, g.y() + 0.0, g.z() + 0.0};  // + 0.0: no -0 in the table
    if (npy) {
      block.append(reinterpret_cast<const char*>(row), sizeof row);
    } else {
      char text[4 * (kMaxNumberChars + 1)];
      block.append(text, static_cast<std::size_t>(write_csv_numbers(text, row, 4) - text));
    }
    if (block.size() > (1 << 16)) {
      out.write(block);
      block.clear();
    }
  }
  out.write(block);
  out.commit();
}

void run_clinostat(const ClinostatOptions& o) {
  if (o.machine.outer.empty() || o.machine.inner.empty())
    throw UsageError{"clinostat: give --outer RPM and --inner RPM (or clinostat design | merge; see docs/clinostat.md)"};
  const Clinostat m(o.machine.settings());
  if (o.trace) return run_trace(o, m);
  for (const auto& [given, name] : {std::pair{!o.duration.empty(), "--duration"}, std::pair{!o.samples.empty(), "--samples"},
                                    std::pair{!o.output.empty(), "--output"}})
    if (given) throw UsageError{std::string(name) + ": only with --trace; valid: --trace --duration S --samples N [-o FILE]"};
  run_report(o, m);
}

}  // namespace

void register_clinostat(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<ClinostatOptions>();
  CLI::App* cmd = app.add_subcommand("clinostat", "a clinostat or random positioning machine: gravity path, mean gravity, time to epsilon, coverage");
  cmd->footer(
      "Convention (docs/clinostat.md): lab Z up, gravity (0,0,-1) g0; outer axis u = (sin tilt, 0, cos tilt);\n"
      "inner axis v = cos(frame) u + sin(frame) (-cos tilt, 0, sin tilt), carried by the outer frame;\n"
      "sample frame R(t) = Rot(u, phi_o(t)) Rot(v, phi_i(t)); the sample feels g_s = R^T (0,0,-1).\n"
      "Speeds are read exactly (1.33 = 133/100 rpm). With --offset the averages are of the effective\n"
      "gravity R^T((0,0,-1) - a/g0) at that point; the gear train and the coverage are of g_s.\n"
      "--window W: M(W), the largest |mean| over every window of W s (certified bracket, width <= 1e-9).\n"
      "--epsilon E: the shortest window (a multiple of --resolution) with M(W) <= E, and the one from\n"
      "which every longer window is below (M is not monotone).\n"
      "--coverage D: seconds per HEALPix cell (RING, --nside K, default 8) over [--start, --start + D].\n"
      "--plot FILE.svg|.png: the dwell map (of --coverage, else one period up to an hour) and M(W)\n"
      "against W (up to 1.25 x the time to epsilon, else three periods up to two hours), epsilon dashed.\n"
      "--trace --duration S --samples N: t,gx,gy,gz (N samples, both ends included; .npy by -o's suffix).\n"
      "Exit 3: a bracket or a comparison not certified (the output says which).\n"
      "Choosing speeds: sphtroch clinostat design (and clinostat merge for its --shard parts).\n"
      "Example: sphtroch clinostat --outer 1.33 --inner 2 --window 600 --epsilon 0.01");
  cmd->add_option("--outer", o->machine.outer, "outer frame's speed, rpm (signed; exact decimal or p/q); required");
  cmd->add_option("--inner", o->machine.inner, "inner frame's speed, rpm (signed; exact decimal or p/q); required");
  cmd->add_option("--tilt", o->machine.tilt, "outer axis from the vertical, degrees in [0, 180] (default 90)");
  cmd->add_option("--frame-angle", o->machine.frame_angle, "angle between the axes, degrees in [0, 180] (default 90)");
  cmd->add_option("--phase-outer", o->machine.phase_outer, "outer frame's angle at t = 0, degrees (default 0)");
  cmd->add_option("--phase-inner", o->machine.phase_inner, "inner frame's angle at t = 0, degrees (default 0)");
  cmd->add_option("--offset", o->machine.offset, "the sample point X,Y,Z in metres (sample frame; default the centre)");
  cmd->add_option("--window", o->window, "M(W) for this window length, seconds");
  cmd->add_option("--epsilon", o->epsilon, "the time to epsilon for this bound, units of g0");
  cmd->add_option("--resolution", o->resolution, "the step of W for --epsilon, seconds (default 1)");
  cmd->add_option("--coverage", o->coverage, "the dwell map over this many seconds");
  cmd->add_option("--nside", o->nside, "HEALPix nside for --coverage, a power of two 1 .. 1024 (default 8: 768 cells)");
  cmd->add_option("--start", o->start, "start time of --coverage and --trace, seconds (default 0)");
  cmd->add_flag("--json", o->json, "the report as JSON (schema: docs/clinostat.md)");
  cmd->add_option("--plot", o->plot, "also write the dwell map (Mollweide) and M(W) against W as FILE.svg or FILE.png");
  cmd->add_flag("--trace", o->trace, "write the gravity over time instead of the report");
  cmd->add_option("--duration", o->duration, "--trace: seconds covered");
  cmd->add_option("--samples", o->samples, "--trace: number of samples N (2 .. 10000000; default 1001)");
  add_output_option(*cmd, o->output, "the --trace table");
  actions.emplace_back(cmd, [o, cmd] {
    if (cmd->get_subcommands().empty()) return run_clinostat(*o);
    // design or merge runs; an option of clinostat itself given before it would be lost
    for (const CLI::Option* opt : cmd->get_options())
      if (opt->count() > 0 && opt->get_name() != "--help")
        throw UsageError{opt->get_name() + ": an option of clinostat, given before " + cmd->get_subcommands()[0]->get_name() +
                         "; valid: the options after the subcommand (sphtroch clinostat " + cmd->get_subcommands()[0]->get_name() + " --help)"};
  });
  register_clinostat_design(*cmd, actions);
}

}  // namespace sphtroch::cli
