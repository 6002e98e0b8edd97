// sphtroch trace -o FILE.step: the checked B-spline of cad/step_export.hpp, made by the STEP
// plugin (step_plugin.cpp, opened only here: plugin_loader.hpp), written through OutputFile.
#include "step_output.hpp"

#include "plugin_loader.hpp"
#include "step_request.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/io/output_file.hpp"
#include "sphtroch/io/parse.hpp"

#include <cmath>

namespace sphtroch::cli {

namespace {

/// The MODULE sphtroch_step (file name set in src/cli/CMakeLists.txt).
constexpr OutputPlugin kStepPlugin{"sphtroch_step.so", "STEP", "OpenCASCADE",
                                   "another --format: csv, npy, dxf (3-D polyline), obj (polyline)"};

}  // namespace

const char* step_plugin_state() noexcept { return output_plugin_state(kStepPlugin); }

double parse_tolerance(const std::string& text) {
  const std::optional<double> t = parse_number(text);
  if (!t || !(*t > 0) || !std::isfinite(*t))
    throw InvalidInput("tolerance", text, "not a positive number", "a finite number > 0, in --radius units");
  return *t;
}

void write_step_output(const GearTrain& train, const StepOutputOptions& options, const std::string& output) {
  const std::string named = "--output = " + (output.empty() ? std::string("-") : output);
  StepRequest request{true, train, options};
  run_output_plugin(kStepPlugin, named, step_request_text(request));  // the input first (check_step_options),
  OutputFile out = OutputFile::open(output, "--output");              // then the output (staged: nothing partial),
  request.check_only = false;
  out.write(run_output_plugin(kStepPlugin, named, step_request_text(request)));  // then the work
  out.commit();
}

}  // namespace sphtroch::cli
