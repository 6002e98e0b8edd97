// sphtroch clinostat — a two-axis clinostat or random positioning machine: its gravity path as a
// gear train, the mean over a period, the worst window mean, the time to epsilon, the dwell map;
// or (--trace) the gravity seen by the sample as CSV t,gx,gy,gz or .npy. Eigen (+ HEALPix for
// --coverage, opened on demand: dwell_input.hpp); the library's machine/ layer does the work and
// writes the report (machine/clinostat_report.hpp; docs/clinostat.md).
#include "cli_common.hpp"
#include "dwell_input.hpp"
#include "png_output.hpp"

#include "sphtroch/io/chain_text.hpp"  // split_list
#include "sphtroch/io/npy.hpp"
#include "sphtroch/io/trace_output.hpp"
#include "sphtroch/machine/clinostat_plot.hpp"
#include "sphtroch/machine/clinostat_report.hpp"
#include "sphtroch/machine/clinostat_text.hpp"

#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>

namespace sphtroch::cli {

namespace {

constexpr int kMaxPlotNside = 32;

struct ClinostatOptions {
  ClinostatText machine;
  std::string window, epsilon, resolution, coverage, nside, start, duration, samples, output, plot, running_mean, target_g, tolerance;
  bool json = false, trace = false, band = false;
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

/// A gravity in g0: a finite number >= 0 (the target and its tolerance).
double parse_gravity(const std::string& text, const std::string& field) {
  const std::optional<double> v = parse_number(text);
  if (!v || !std::isfinite(*v) || *v < 0 || *v > 1e9) throw InvalidInput(field, text, "not a finite number >= 0", "a finite number in [0, 1e9], units of g0");
  return *v;
}

/// --band, --target-g and --tolerance: the band needs --window, the target the band, both of its values.
void read_band(const ClinostatOptions& o, ClinostatRequest& r) {
  if (o.band && o.window.empty()) throw UsageError{"--band: only with --window; valid: --window S --band"};
  if (!o.target_g.empty() && !o.band)
    throw UsageError{"--target-g = " + o.target_g + ": only with --band; valid: --window S --band --target-g G --tolerance D"};
  if (!o.tolerance.empty() && o.target_g.empty())
    throw UsageError{"--tolerance = " + o.tolerance + ": only with --target-g; valid: --window S --band --target-g G --tolerance D"};
  if (!o.target_g.empty() && o.tolerance.empty())
    throw UsageError{"--target-g = " + o.target_g + ": needs --tolerance; valid: --window S --band --target-g G --tolerance D"};
  r.band = o.band;
  if (!o.target_g.empty()) {
    r.target_g = parse_gravity(o.target_g, "target-g");
    r.tolerance = parse_gravity(o.tolerance, "tolerance");
  }
}

/// What the report computes, read and checked before any of it runs.
ClinostatRequest read_request(const ClinostatOptions& o) {
  ClinostatRequest r;
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
  read_band(o, r);
  r.start = parse_time(o.start, "start");
  for (const std::string& item : split_list(o.running_mean))
    r.running_mean_s.push_back(parse_positive(item, "running-mean", Clinostat::kMaxTime, "T1,T2,...: durations in (0, 1e12] seconds"));
  return r;
}

/// --plot: the library's composition (clinostat_report.hpp) with the dwell map of the report's
/// coverage, or of clinostat_plot_dwell_s, in a build with HEALPix (the plugin).
std::string plot_svg(const ClinostatReport& r) {
  std::optional<DwellMap> dwell = r.dwell;
  if (!dwell && std::string(healpix_plugin_state()) == "yes")
    dwell = dwell_map_by_plugin(r.settings, r.request.start, clinostat_plot_dwell_s(r), r.request.nside);
  return clinostat_plot_svg(clinostat_report_plot(r, dwell ? &*dwell : nullptr, dwell ? cell_outlines_by_plugin(dwell->nside)
                                                                                        : std::vector<std::vector<Vector3d>>{}));
}

/// --plot's file: FILE.svg or FILE.png (any case), not standard output; its map at most nside 32
/// (12,288 cells drawn; the SVG grows as the cells).
void check_plot_request(const std::string& plot, const ClinostatRequest& q) {
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
  const ClinostatRequest q = read_request(o);
  if (!o.plot.empty()) check_plot_request(o.plot, q);
  if (!o.start.empty() && !q.coverage && o.plot.empty() && q.running_mean_s.empty())
    throw UsageError{"--start = " + o.start + ": only with --coverage, --running-mean, --plot or --trace; valid: --coverage S --start T"};
  if (q.coverage) require_dwell_maps("coverage", o.coverage);  // refused now, not after the other numbers
  ClinostatReport r = clinostat_report(m, q);
  if (q.coverage) r.dwell = dwell_map_by_plugin(m.settings(), q.start, *q.coverage, q.nside);
  std::vector<std::string> written;
  if (!o.plot.empty()) {
    write_output(o.plot, [&](std::ostream& out) { out << picture_bytes(plot_svg(r), o.plot); }, "--plot", kPictureOutputs);
    written.push_back(o.plot);
  }
  write_stdout_after_outputs(written, [&](std::ostream& out) {
    if (o.json) out << clinostat_report_json(r).dump(2) << "\n";
    else write_clinostat_report_text(out, r);
  });
  if (!clinostat_report_certified(r)) throw UncertifiedResult{"clinostat: " + clinostat_report_uncertified(r)};
}

/// --trace: N samples over [start, start + duration], both ends included; CSV or .npy (by -o).
void run_trace(const ClinostatOptions& o, const Clinostat& m) {
  for (const auto& [given, name] : {std::pair{!o.window.empty(), "--window"}, std::pair{!o.epsilon.empty(), "--epsilon"},
                                    std::pair{!o.coverage.empty(), "--coverage"}, std::pair{o.json, "--json"},
                                    std::pair{!o.plot.empty(), "--plot"}, std::pair{!o.running_mean.empty(), "--running-mean"},
                                    std::pair{o.band, "--band"}, std::pair{!o.target_g.empty(), "--target-g"},
                                    std::pair{!o.tolerance.empty(), "--tolerance"},
                                    std::pair{!o.machine.gravity.empty(), "--gravity"}})
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
      "--gravity G: the environment's gravity (g0; default 1): every mean, bracket and running mean is of\n"
      "G g_s (with --offset of R^T(G (0,0,-1) - a/g0)); --epsilon, --target-g, --tolerance stay in g0 as typed.\n"
      "Speeds are read exactly (1.33 = 133/100 rpm). With --offset the averages are of the effective\n"
      "gravity R^T((0,0,-1) - a/g0) at that point; the gear train and the coverage are of g_s.\n"
      "--window W: M(W), the largest |mean| over every window of W s (certified bracket, width <= 1e-9).\n"
      "--band (with --window W): the smallest and the largest |mean| over every window of W s, each a\n"
      "certified bracket (width <= 1e-9) with a start time reaching it; --target-g G --tolerance D: whether\n"
      "every window mean lies in [G - D, G + D] (certified yes, or no with a start time that leaves it).\n"
      "--epsilon E: the shortest window (a multiple of --resolution) with M(W) <= E, and the one from\n"
      "which every longer window is below (M is not monotone).\n"
      "--running-mean T1,T2,...: the mean over [--start, --start + T] for each T (closed form).\n"
      "--coverage D: seconds per HEALPix cell (RING, --nside K, default 8) over [--start, --start + D].\n"
      "--plot FILE.svg|.png: the dwell map (of --coverage, else one period up to an hour) and M(W)\n"
      "against W (up to 1.25 x the time to epsilon, else three periods up to two hours), epsilon dashed.\n"
      "--trace --duration S --samples N: t,gx,gy,gz (N samples, both ends included; .npy by -o's suffix).\n"
      "Exit 3: a bracket or a comparison not certified (the output says which).\n"
      "Choosing speeds: sphtroch clinostat design (and clinostat merge for its --shard parts).\n"
      "Example: sphtroch clinostat --outer 1.33 --inner 2 --window 600 --epsilon 0.01");
  cmd->add_option("--outer", o->machine.outer, "outer frame's speed, rpm (signed; exact decimal or p/q); required")->type_name("RPM");
  cmd->add_option("--inner", o->machine.inner, "inner frame's speed, rpm (signed; exact decimal or p/q); required")->type_name("RPM");
  cmd->add_option("--tilt", o->machine.tilt, "outer axis from the vertical, degrees in [0, 180] (default 90)")->type_name("DEG");
  cmd->add_option("--frame-angle", o->machine.frame_angle, "angle between the axes, degrees in [0, 180] (default 90)")->type_name("DEG");
  cmd->add_option("--phase-outer", o->machine.phase_outer, "outer frame's angle at t = 0, degrees (default 0)")->type_name("DEG");
  cmd->add_option("--phase-inner", o->machine.phase_inner, "inner frame's angle at t = 0, degrees (default 0)")->type_name("DEG");
  cmd->add_option("--gravity", o->machine.gravity, "the environment's gravity G, units of g0 in [0.001, 1000] (default 1): scales every gravity figure")
      ->type_name("G");
  cmd->add_option("--offset", o->machine.offset, "the sample point X,Y,Z in metres (sample frame; default the centre)")->type_name("X,Y,Z");
  cmd->add_option("--window", o->window, "M(W) for this window length, seconds")->type_name("S");
  cmd->add_flag("--band", o->band, "with --window: the certified min and max of |window mean| over every start time");
  cmd->add_option("--target-g", o->target_g, "with --band: whether every window mean lies in G +- --tolerance, units of g0")->type_name("G");
  cmd->add_option("--tolerance", o->tolerance, "with --target-g: the half-width D of the target, units of g0 (>= 0)")->type_name("D");
  cmd->add_option("--epsilon", o->epsilon, "the time to epsilon for this bound, units of g0")->type_name("G0");
  cmd->add_option("--resolution", o->resolution, "the step of W for --epsilon, seconds (default 1)")->type_name("S");
  cmd->add_option("--coverage", o->coverage, "the dwell map over this many seconds")->type_name("S");
  cmd->add_option("--nside", o->nside, "HEALPix nside for --coverage, a power of two 1 .. 1024 (default 8: 768 cells)")->type_name("K");
  cmd->add_option("--start", o->start, "start time of --coverage, --running-mean and --trace, seconds (default 0)")->type_name("S");
  cmd->add_option("--running-mean", o->running_mean, "T1,T2,...: the mean gravity over [--start, --start + T] for each T, seconds")
      ->type_name("S,S,...");
  cmd->add_flag("--json", o->json, "the report as JSON (schema: docs/clinostat.md)");
  cmd->add_option("--plot", o->plot, "also write the dwell map (Mollweide) and M(W) against W as FILE.svg or FILE.png")->type_name("FILE");
  cmd->add_flag("--trace", o->trace, "write the gravity over time instead of the report");
  cmd->add_option("--duration", o->duration, "--trace: seconds covered")->type_name("S");
  cmd->add_option("--samples", o->samples, "--trace: number of samples N (2 .. 10000000; default 1001)")->type_name("N");
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
