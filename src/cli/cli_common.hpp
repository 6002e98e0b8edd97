// src/cli/cli_common.hpp — plumbing shared by the sphtroch commands: reading gear-train
// options, the one-line error contract (stderr, exit 2), and output files that are never
// left partial (written to a temporary file in the same directory, then renamed).
#pragma once

#include "sphtroch/gear_train.hpp"
#include "sphtroch/sampling.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace sphtroch::cli {

/// Exit status for every kind of bad input.
constexpr int kBadInput = 2;

/// Raised by commands for bad input not covered by InvalidInput (e.g. an unwritable path).
struct UsageError {
  std::string message;  // one line, already naming the option, the value and the valid range
};

/// The gear-train options every analysis command shares (values kept as text, parsed later
/// so that errors name the option exactly as typed).
struct TrainOptions {
  std::string a2, a3, n, phase = "0";
  void add_to(CLI::App& command);
  /// Parses and validates; throws InvalidInput whose field is the option name without "--".
  GearTrain train() const;
};

/// Adds "-o,--output FILE" to a command.
void add_output_option(CLI::App& command, std::string& path, const std::string& what);

/// Writes text produced by `write` to stdout (path empty or "-") or atomically to `path`.
/// The callback runs before the file appears; on any failure no file is left behind.
void write_output(const std::string& path, const std::function<void(std::ostream&)>& write);

/// Several output files that appear together or not at all: stage() writes each to a temporary
/// file in its directory; commit() renames them all into place; the destructor removes every
/// temporary not committed (so any failure before commit() leaves no file). Error messages name
/// `field` ("--output", "trains[0].effects.trace") and the path.
class StagedOutputs {
 public:
  StagedOutputs() = default;
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;
  ~StagedOutputs();
  void stage(const std::string& path, const std::string& field, const std::function<void(std::ostream&)>& write);
  void commit();

 private:
  struct Pending {
    std::string path, field, tmp;
  };
  std::vector<Pending> pending_;
};

/// A non-negative integer option value, or InvalidInput naming the option.
std::size_t parse_count(const std::string& text, const std::string& field, std::size_t lo, std::size_t hi);

/// printf("%.17g") — every printed number round-trips to the same double.
std::string number(double v);

/// A measured time in seconds for text reports: 3 significant digits (timings are noisy; the
/// JSON reports keep every digit).
std::string seconds_text(double seconds);

/// The shortest %g form that reads back as the same double (1e-11, not 9.9999999999999994e-12):
/// for named constants in text reports.
std::string shortest_number(double v);

/// The `sphtroch trace` CSV: t,x,y,z (t,x,y,z,vx,vy,vz when `velocities` is not empty; then it
/// holds dP/dtheta2 at every trajectory.t[i]).
void write_trajectory_csv(std::ostream& out, const Trajectory<double>& trajectory,
                          const std::vector<Vector3d>& velocities = {});

/// Registers a subcommand's action; main() runs the selected one and maps errors to exit codes.
using Action = std::function<void()>;
void register_trace(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
void register_atlas(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);  // atlas, atlas-merge
#ifdef SPHTROCH_HAVE_ANALYSIS
void register_analysis(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
void register_scene(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
#endif

}  // namespace sphtroch::cli
