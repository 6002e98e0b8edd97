// The STEP output of `sphtroch trace` (step_output.cpp; in a build with STEP,
// SPHTROCH_HAVE_STEP). OpenCASCADE is in the STEP plugin (step_plugin.cpp), which the
// tool opens only when it writes STEP (plugin_loader.hpp).
#pragma once

#include "sphtroch/core/gear_train.hpp"

#include <optional>
#include <string>

namespace sphtroch::cli {

struct StepOutputOptions {
  double radius = 1.0;
  std::optional<double> tolerance;  // none: 1e-6 * radius
  std::optional<double> turns;      // an open path
};

/// --tolerance T: a finite number > 0 (checked against the radius by step_path).
double parse_tolerance(const std::string& text);

/// For --version, in a build with STEP: "yes" (the plugin file present) or "missing".
const char* step_plugin_state() noexcept;

/// The path as STEP to `output` ("" or "-": stdout), through OutputFile (never left partial).
/// Throws UsageError if the STEP plugin cannot be opened, and InvalidInput (radius, tolerance,
/// turns, n) for what check_step_options refuses, both before the output is opened.
void write_step_output(const GearTrain& train, const StepOutputOptions& options, const std::string& output);

}  // namespace sphtroch::cli
