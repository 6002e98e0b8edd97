// sphtroch chain trace | export — a gear-coupled rotation chain (core/rotation_chain.hpp):
// its curve written by the same writer as `sphtroch trace` (io/trace_output.hpp): CSV t,x,y,z (t the motor
// parameter s), .npy, DXF or OBJ. For k = 2 with rates 1,n and phases 0,theta_p the bytes are
// those of `sphtroch trace --a2 A1 --a3 A2 --n n --phase theta_p` (ChainCurve computes the same
// bits as TracerCurve, and the default sample count is the same). export writes a URDF
// (io/urdf_writer.hpp); --urdf is read through the URDF plugin (urdf_input.hpp). classify, nodes, plot and boundaries need the census: chain_census_command.cpp.
#include "cli_common.hpp"
#include "urdf_input.hpp"

#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/trace_output.hpp"
#include "sphtroch/io/urdf_writer.hpp"

#include <cctype>
#include <cmath>

namespace sphtroch::cli {

namespace {

struct ChainOptions {
  ChainText chain;
  std::string samples, output, format, threads, radius;
  bool velocity = false, kinematics = false, degrees = false;
};

TraceFormat chain_format(const ChainOptions& o) {
  std::string lower = o.output;  // suffixes in any case, as trace reads them
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto ends = [&](const char* ext) {
    const std::string e = std::string(".") + ext;
    return lower.size() >= e.size() && lower.compare(lower.size() - e.size(), e.size(), e) == 0;
  };
  const std::string f = o.format;
  if (f == "npy" || (f.empty() && ends("npy"))) return TraceFormat::npy;
  if (f == "dxf" || (f.empty() && ends("dxf"))) return TraceFormat::dxf;
  if (f == "obj" || (f.empty() && ends("obj"))) return TraceFormat::obj;
  if (f.empty()) check_output_suffix(o.output, "output", {"csv", "txt", "text", "npy", "dxf", "obj"});  // .step, .stl: refused
  if (f.empty() || f == "csv") return TraceFormat::csv;
  throw InvalidInput("format", f, "not a format of chain trace", "csv, npy, dxf (3-D polyline), obj (polyline)");
}

void run_chain_trace(const ChainOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {{o.chain.urdf, "--urdf"}});
  const RotationChain chain = o.chain.chain();
  const std::size_t n = o.samples.empty() ? chain_trace_sample_count(chain) : parse_count(o.samples, "samples", kMinSamples, kMaxSamples);
  TraceWriteOptions options;
  options.format = chain_format(o);
  options.velocity = o.velocity;
  options.kinematics = o.kinematics;
  options.degrees = o.degrees;
  options.radius = parse_radius(o.radius);
  if (options.format == TraceFormat::dxf || options.format == TraceFormat::obj)
    for (const auto& [flag, name] : {std::pair{o.velocity, "--velocity"}, std::pair{o.kinematics, "--kinematics"}, std::pair{o.degrees, "--degrees"}})
      if (flag) throw UsageError{std::string(name) + ": a DXF or OBJ file holds the path only; valid: " + name + " with CSV or .npy"};
  options.threads = o.threads.empty() ? parse_threads("") + 1 : parse_threads(o.threads);
  const ChainCurve<double> curve(chain);
  const UniformSampling<double> sampling{curve.period(), n, n, true};
  OutputFile out = OutputFile::open(o.output, "--output");  // every check above comes first
  write_trace(out, curve, sampling, options);
  out.commit();
}


struct ChainExportOptions {
  ChainText chain;
  std::string urdf, name;
};

/// chain export --urdf FILE: the chain as a URDF (io/urdf_writer.hpp), joint_1.. with <mimic>.
void run_chain_export(const ChainExportOptions& o) {
  const RotationChain chain = o.chain.chain();
  const std::string xml = chain_to_urdf(chain, o.name.empty() ? "sphtroch_chain" : o.name);
  OutputFile out = OutputFile::open(o.urdf, "--urdf");
  out.write(xml);
  out.commit();
}

}  // namespace

void add_chain_options(CLI::App& cmd, ChainText& chain) {
  chain.urdf_reader = &urdf_chain_by_plugin;  // urdfdom opened only when --urdf is read
  cmd.add_option("--twists", chain.twists, "A1,...,Ak: the twist after each joint, radians in [0, pi] (any angle form: pi/2)")->type_name("RAD,...");
  cmd.add_option("--rates", chain.rates, "N1,...,Nk: each joint's rate, exact (p/q, decimals, 0)")->type_name("P/Q,...");
  cmd.add_option("--phases", chain.phases, "P1,...,Pk: each joint's angle at s = 0, radians (default all 0)")->type_name("RAD,...");
  cmd.add_option("--urdf", chain.urdf, "or read the chain from a URDF FILE (- for stdin) whose joints are coupled by <mimic>")->type_name("FILE");
  cmd.add_option("--from", chain.from, "with --urdf: the link the chain starts at (the curve is in its first joint's frame)")->type_name("LINK");
  cmd.add_option("--to", chain.to, "with --urdf: the link that carries the tool axis")->type_name("LINK");
  cmd.add_option("--axis", chain.axis, "with --urdf: the tool axis X,Y,Z in the --to link's frame (default 0,0,1)")->type_name("X,Y,Z");
}

void register_chain(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  CLI::App* chain = app.add_subcommand("chain", "a gear-coupled rotation chain: the curve of its tool axis (k = 2: the gear train)");
  chain->require_subcommand(1);
  auto o = std::make_shared<ChainOptions>();
  CLI::App* cmd = chain->add_subcommand("trace", "print the chain's curve P(s) as CSV t,x,y,z, or write .npy, DXF, OBJ");
  cmd->footer(
      "P(s) = Rz(N1 s + P1) Rx(A1) Rz(N2 s + P2) Rx(A2) ... Rz(Nk s + Pk) Rx(Ak) z (docs/cli.md: chain).\n"
      "Closed curve: N samples over one period 2 pi L / g (L the lcm of the rates' denominators, g the\n"
      "gcd of the numerators of N_i L); default 360 sum |N_i| L / g, at most 1000000. The t column is s.\n"
      "With --twists A2,A3 --rates 1,n --phases 0,PHASE the bytes are `sphtroch trace`'s.\n"
      "Example: sphtroch chain trace --twists pi/2,1.2,0.4 --rates 1,-2/3,5/3 --samples 8");
  add_chain_options(*cmd, o->chain);
  cmd->add_option("--samples", o->samples, "number of samples N (3 .. 10000000)")->type_name("N");
  cmd->add_flag("--velocity", o->velocity, "add columns vx,vy,vz = dP/ds = omega x P");
  cmd->add_flag("--degrees", o->degrees, "the t column (s) in degrees, header t_deg");
  cmd->add_flag("--kinematics", o->kinematics, "add columns speed,geodesic_curvature,tangential_acceleration (per unit s)");
  cmd->add_option("--format", o->format, "csv, npy, dxf or obj (default: by -o's suffix, else csv)")->type_name("csv|npy|dxf|obj");
  cmd->add_option("--radius", o->radius, "scale positions (and velocities) by R in [1e-100, 1e100]")->type_name("R");
  cmd->add_option("--threads", o->threads, "worker threads computing and formatting rows (1 .. 1024; default: cores + 1)")->type_name("N");
  add_output_option(*cmd, o->output, "the curve");
  actions.emplace_back(cmd, [o] { run_chain_trace(*o); });
  auto e = std::make_shared<ChainExportOptions>();
  CLI::App* exp = chain->add_subcommand("export", "write the chain as a URDF robot description (--urdf FILE)");
  exp->add_option("--twists", e->chain.twists, "A1,...,Ak: the twist after each joint, radians in [0, pi]")->type_name("RAD,...");
  exp->add_option("--rates", e->chain.rates, "N1,...,Nk: each joint's rate, exact (p/q, decimals, 0)")->type_name("P/Q,...");
  exp->add_option("--phases", e->chain.phases, "P1,...,Pk: each joint's angle at s = 0, radians (default all 0)")->type_name("RAD,...");
  exp->add_option("--urdf", e->urdf, "the URDF file to write (- for stdout)")->type_name("FILE")->required();
  exp->add_option("--name", e->name, "the robot's name (default sphtroch_chain)")->type_name("NAME");
  exp->footer("joint_1.. are continuous joints about z, the first turning one the motor, the others <mimic> it\n"
              "(multiplier N_i / N_m); `chain classify --urdf FILE --from base_link --to tool` reads it back.");
  actions.emplace_back(exp, [e] { run_chain_export(*e); });
#ifdef SPHTROCH_HAVE_ANALYSIS
  register_chain_census(*chain, actions);
#endif
}

}  // namespace sphtroch::cli
