// The STEP plugin (CMake MODULE sphtroch_step, the one binary of the tool that links
// OpenCASCADE): a step_request.hpp request in, through sphtroch/cad/step_export.hpp; out the
// STEP AP214 file's bytes ("write"), or nothing once the options pass check_step_options
// ("check"). The C ABI and its error contract: output_plugin.hpp.
#include "output_plugin.hpp"
#include "step_request.hpp"

#include "sphtroch/cad/step_export.hpp"
#include "sphtroch/version.hpp"

#include <string>

namespace {

std::string run_step_request(const std::string& text) {
  using namespace sphtroch;
  const cli::StepRequest request = cli::parse_step_request(text);
  StepOptions o;
  o.radius = request.options.radius;
  o.turns = request.options.turns;
  o.tolerance = request.options.tolerance;
  if (request.check_only) {
    check_step_options(request.train, o);
    return {};
  }
  return step_text(step_path(request.train, o), std::string("sphtroch ") + SPHTROCH_VERSION_STRING);
}

}  // namespace

SPHTROCH_OUTPUT_PLUGIN(run_step_request)
