// The STEP output of `sphtroch trace` (step_output.cpp: the one translation unit that includes
// OpenCASCADE; built only with the sphtroch::step component, SPHTROCH_HAVE_STEP).
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

/// The path as STEP to `output` ("" or "-": stdout), through OutputFile (never left partial).
/// Throws InvalidInput (radius, tolerance) before anything is written.
void write_step_output(const GearTrain& train, const StepOutputOptions& options, const std::string& output);

}  // namespace sphtroch::cli
