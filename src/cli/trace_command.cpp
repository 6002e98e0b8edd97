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

/// Default sample counts: 360 per unit of (q + |p|) for a closed curve (about 0.5 degree of
/// planet or carrier motion per step), 360*(1 + |n|) per carrier turn for an open one.
std::size_t default_samples(const GearTrain& train, std::optional<double> turns) {
  const auto& r = train.ratio();
  const double n = turns ? 360.0 * (1.0 + std::abs(r.value())) * *turns + 1.0
                         : 360.0 * static_cast<double>(r.q() + r.abs_p());
  return static_cast<std::size_t>(std::clamp(std::ceil(n), static_cast<double>(kMinSamples), 1.0e6));
}

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
      o.samples.empty() ? default_samples(train, turns) : parse_count(o.samples, "samples", kMinSamples, kMaxSamples);
  const TracerCurve<double> curve(train);
  const Trajectory<double> tr = turns ? sample_turns(curve, *turns, n, o.velocity) : sample_period(curve, n, o.velocity);
  write_output(o.output, [&](std::ostream& out) {
    out << (o.velocity ? "t,x,y,z,vx,vy,vz\n" : "t,x,y,z\n");
    for (std::size_t i = 0; i < tr.size(); ++i) {
      const auto& p = tr.points[i];
      out << number(tr.t[i]) << ',' << number(p.x()) << ',' << number(p.y()) << ',' << number(p.z());
      if (o.velocity) {
        const auto& v = tr.velocities[i];
        out << ',' << number(v.x()) << ',' << number(v.y()) << ',' << number(v.z());
      }
      out << '\n';
    }
  });
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
