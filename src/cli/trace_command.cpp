// sphtroch trace — the trajectory as CSV (t,x,y,z[,vx,vy,vz]) or NumPy .npy, streamed in blocks
// (sphtroch/io/trace_output.hpp): memory does not grow with --samples.
#include "cli_common.hpp"

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/io/trace_output.hpp"
#include "step_output.hpp"

#include <algorithm>
#include <cmath>

namespace sphtroch::cli {

namespace {

struct TraceOptions {
  TrainOptions train;
  std::string samples, turns, output, format, threads, radius, tolerance;
  bool velocity = false, kinematics = false, degrees = false;
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

#if defined(SPHTROCH_HAVE_STEP)
constexpr const char* kTraceFormats = "csv, npy, dxf (3-D polyline), obj (polyline), step (B-spline, AP214)";
#else
constexpr const char* kTraceFormats = "csv, npy, dxf (3-D polyline), obj (polyline)";
#endif

/// A format name: csv, npy, dxf, obj (step is handled before: step_requested).
TraceFormat format_named(const std::string& name, const std::string& field, const std::string& value) {
  if (name == "csv") return TraceFormat::csv;
  if (name == "npy") return TraceFormat::npy;
  if (name == "dxf") return TraceFormat::dxf;
  if (name == "obj") return TraceFormat::obj;
  if (name == "step" || name == "stp")
    throw InvalidInput(field, value, "STEP needs the OpenCASCADE component, which this build of sphtroch does not have",
                       kTraceFormats);
  throw InvalidInput(field, value, "not a known format", kTraceFormats);
}

std::string lower_case(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}


/// --format, or by the output's suffix (any case): .npy, .dxf, .obj (.step, .stp: STEP, or
/// refused in a build without it); .csv, .txt or a suffix that names no format: CSV; another
/// format's suffix (.stl, .json, ...) is refused.
TraceFormat trace_format(const TraceOptions& o) {
  if (!o.format.empty()) return format_named(lower_case(o.format), "format", o.format);
  const std::string lower = lower_case(o.output);
  for (const char* ext : {"npy", "dxf", "obj", "step", "stp"})
    if (ends_with(lower, std::string(".") + ext)) return format_named(ext, "output", o.output);
  check_output_suffix(o.output, "output", {"csv", "txt", "text", "npy", "dxf", "obj", "step", "stp"});  // .stl, .json: refused
  return TraceFormat::csv;
}

#if defined(SPHTROCH_HAVE_STEP)
/// Whether STEP is asked for: --format step|stp, or (no --format) -o ending in .step or .stp.
bool step_requested(const TraceOptions& o) {
  const std::string f = lower_case(o.format), out = lower_case(o.output);
  if (!o.format.empty()) return f == "step" || f == "stp";
  return ends_with(out, ".step") || ends_with(out, ".stp");
}

/// trace to STEP: the checked B-spline (cad/step_export.hpp); --samples and the extra columns do
/// not apply (the tolerance sets the points).
void run_step_trace(const TraceOptions& o, const GearTrain& train, std::optional<double> turns) {
  for (const auto& [given, name] : {std::pair{!o.samples.empty(), "--samples"}, std::pair{o.velocity, "--velocity"},
                                    std::pair{o.kinematics, "--kinematics"}, std::pair{o.degrees, "--degrees"},
                                    std::pair{!o.threads.empty(), "--threads"}})
    if (given)
      throw UsageError{std::string(name) + ": a STEP file holds the path as one B-spline fitted to --tolerance; valid: " +
                       name + " with CSV or .npy"};
  StepOutputOptions step;
  step.radius = parse_radius(o.radius);
  step.turns = turns;
  if (!o.tolerance.empty()) step.tolerance = parse_tolerance(o.tolerance);
  write_step_output(train, step, o.output);
}
#endif

/// trace: the sampled path as CSV, .npy, DXF or OBJ (or STEP above); --radius R, the cone distance
/// in any unit in [1e-100, 1e100] (core/cone_distance.hpp), scales positions and velocities.
void run_trace(const TraceOptions& o) {
  const GearTrain train = o.train.train();
  if (!o.samples.empty() && !o.turns.empty())
    throw UsageError{"--turns = " + o.turns + ": cannot be combined with --samples = " + o.samples +
                     "; valid: either --samples N (closed curve) or --turns K (open curve)"};
  std::optional<double> turns;
  if (!o.turns.empty()) {
    turns = parse_turns(o.turns);
  }
#if defined(SPHTROCH_HAVE_STEP)
  if (step_requested(o)) return run_step_trace(o, train, turns);
#endif
  if (!o.tolerance.empty())
    throw UsageError{"--tolerance = " + o.tolerance + ": only for STEP output; valid: --tolerance with -o FILE.step"};
  const std::size_t n =
      o.samples.empty() ? trace_sample_count(train, turns) : parse_count(o.samples, "samples", kMinSamples, kMaxSamples);
  TraceWriteOptions options;
  options.format = trace_format(o);
  options.velocity = o.velocity;
  options.kinematics = o.kinematics;
  options.degrees = o.degrees;
  options.radius = parse_radius(o.radius);
  options.closed = !turns;
  if (options.format == TraceFormat::dxf || options.format == TraceFormat::obj)
    for (const auto& [flag, name] : {std::pair{o.velocity, "--velocity"}, std::pair{o.kinematics, "--kinematics"},
                                     std::pair{o.degrees, "--degrees"}})
      if (flag)
        throw UsageError{std::string(name) + ": a DXF or OBJ file holds the path only; valid: " + name +
                         " with CSV or .npy"};
  // Default: one worker per core plus one: the calling thread only writes, and while it waits on
  // the kernel the extra worker keeps both cores busy (measured: 1.49 s vs 1.66 s median for 1e7
  // rows to a CSV file on 2 cores; docs/accuracy.md).
  options.threads = o.threads.empty() ? parse_threads("") + 1 : parse_threads(o.threads);
  const TracerCurve<double> curve(train);
  const UniformSampling<double> sampling = turns ? turns_sampling(curve, *turns, n) : period_sampling(curve, n);
  OutputFile out = OutputFile::open(o.output, "--output");  // every check above comes first
  write_trace(out, curve, sampling, options);
  out.commit();
}

}  // namespace

void register_trace(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto options = std::make_shared<TraceOptions>();
  CLI::App* cmd = app.add_subcommand("trace", "print the trajectory P(theta2) (Eq. 4) as CSV t,x,y,z, or write .npy");
  cmd->footer(
      "Closed curve: N samples t_i = 2*pi*q*i/N over one period (default 360*(q+|p|)).\n"
      "Open curve (--turns K): 360*(1+|n|)*K + 1 samples over [0, 2*pi*K], both ends included\n"
      "(--samples and --turns exclude each other; a default count above 1000000 is refused).\n"
      "Sample counts: 3 .. 10000000. Numbers: the shortest form that reads back exactly.\n"
      "--kinematics adds speed (|dP/dtheta2|), geodesic_curvature and tangential_acceleration\n"
      "(d|V|/dtheta2) per unit carrier rate (core/kinematics.hpp; --radius scales them).\n"
      "Format: npy (float64 array (N, 4), 3 more columns with --velocity, 3 with --kinematics)\n"
      "when -o ends in .npy or\n"
      "with --format npy; for CAD a DXF 3-D polyline (.dxf) or an OBJ polyline (.obj), closed\n"
      "unless --turns, or a STEP AP214 B-spline (.step, .stp; needs the OpenCASCADE component)\n"
      "within --tolerance T of the path at every point (checked; mm in the file); CSV otherwise. --radius R scales the positions (the cone distance, any\n"
      "unit). Rows are streamed: memory does not grow with N.\n"
      "Example: sphtroch trace --a2 pi/2 --a3 pi/2 --n 1 --samples 8");
  options->train.add_to(*cmd);
  cmd->add_option("--samples", options->samples, "number of samples N (3 .. 10000000)")->type_name("N");
  cmd->add_option("--turns", options->turns, "open curve over K carrier turns, K in (0, 1e6]")->type_name("K");
  cmd->add_flag("--velocity", options->velocity, "add columns vx,vy,vz = dP/dtheta2 (Eq. 47a)");
  cmd->add_flag("--degrees", options->degrees, "the t column (theta2) in degrees, header t_deg");
  cmd->add_flag("--kinematics", options->kinematics,
                "add columns speed,geodesic_curvature,tangential_acceleration (per unit carrier rate)");
  cmd->add_option("--format", options->format, "csv, npy, dxf, obj or step (default: by -o's suffix, else csv)")->type_name("csv|npy|dxf|obj|step");
  cmd->add_option("--tolerance", options->tolerance,
                  "STEP only: max distance of the B-spline from the path, in --radius units (default 1e-6 * R)")->type_name("LENGTH");
  cmd->add_option("--radius", options->radius, "scale positions (and velocities) by R in [1e-100, 1e100]: the cone distance, any unit")
      ->type_name("R");
  cmd->add_option("--threads", options->threads, "worker threads computing and formatting rows (1 .. 1024; default: cores + 1)")->type_name("N");
  add_output_option(*cmd, options->output, "the trajectory");
  actions.emplace_back(cmd, [options] { run_trace(*options); });
}

}  // namespace sphtroch::cli
