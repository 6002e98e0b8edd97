// sphtroch trace — the trajectory as CSV (t,x,y,z[,vx,vy,vz]), 17 significant digits.
#include "cli_common.hpp"

#include "sphtroch/curve.hpp"
#include "sphtroch/parse.hpp"
#include "sphtroch/sampling.hpp"

#include <algorithm>
#include <cmath>

namespace sphtroch::cli {

namespace {

struct TraceOptions {
  TrainOptions train;
  std::string samples, turns, output;
  bool velocity = false;
};

void run_trace(const TraceOptions& o) {
  const GearTrain train = o.train.train();
  if (!o.samples.empty() && !o.turns.empty())
    throw UsageError{"--turns = " + o.turns + ": cannot be combined with --samples = " + o.samples +
                     "; valid: either --samples N (closed curve) or --turns K (open curve)"};
  std::optional<double> turns;
  if (!o.turns.empty()) {
    const auto k = detail::strict_double(o.turns);
    if (!k || !(*k > 0.0 && *k <= kMaxTurns))
      throw InvalidInput("turns", o.turns, "outside the valid range", "a number in (0, 1e6] carrier turns");
    turns = *k;
  }
  const std::size_t n =
      o.samples.empty() ? trace_sample_count(train, turns) : parse_count(o.samples, "samples", kMinSamples, kMaxSamples);
  const TracerCurve<double> curve(train);
  const Trajectory<double> tr = turns ? sample_turns(curve, *turns, n, o.velocity) : sample_period(curve, n, o.velocity);
  write_output(o.output, [&](std::ostream& out) { write_trajectory_csv(out, tr, tr.velocities); });
}

}  // namespace

void register_trace(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto options = std::make_shared<TraceOptions>();
  CLI::App* cmd = app.add_subcommand("trace", "print the trajectory P(theta2) (Eq. 4) as CSV: t,x,y,z");
  cmd->footer(
      "Closed curve: N samples t_i = 2*pi*q*i/N over one period (default 360*(q+|p|)).\n"
      "Open curve (--turns K): 360*(1+|n|)*K + 1 samples over [0, 2*pi*K], both ends included\n"
      "(--samples and --turns exclude each other; default counts are capped at 1000000).\n"
      "Sample counts: 3 .. 10000000. Numbers are printed with 17 significant digits.\n"
      "Example: sphtroch trace --a2 pi/2 --a3 pi/2 --n 1 --samples 8");
  options->train.add_to(*cmd);
  cmd->add_option("--samples", options->samples, "number of samples N (3 .. 10000000)");
  cmd->add_option("--turns", options->turns, "open curve over K carrier turns, K in (0, 1e6]");
  cmd->add_flag("--velocity", options->velocity, "add columns vx,vy,vz = dP/dtheta2 (Eq. 47a)");
  add_output_option(*cmd, options->output, "the CSV");
  actions.emplace_back(cmd, [options] { run_trace(*options); });
}

}  // namespace sphtroch::cli
