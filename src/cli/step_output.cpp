// sphtroch trace -o FILE.step: the checked B-spline of cad/step_export.hpp through OutputFile.
#include "step_output.hpp"

#include "sphtroch/cad/step_export.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/output_file.hpp"
#include "sphtroch/io/parse.hpp"

#include <cmath>

namespace sphtroch::cli {

double parse_tolerance(const std::string& text) {
  const std::optional<double> t = parse_number(text);
  if (!t || !(*t > 0) || !std::isfinite(*t))
    throw InvalidInput("tolerance", text, "not a positive number", "a finite number > 0, in --radius units");
  return *t;
}

void write_step_output(const GearTrain& train, const StepOutputOptions& options, const std::string& output) {
  StepOptions o;
  o.radius = options.radius;
  o.turns = options.turns;
  o.tolerance = options.tolerance;
  check_step_options(train, o);                          // the input first,
  OutputFile out = OutputFile::open(output, "--output");  // then the output (staged: nothing partial),
  out.write(step_text(step_path(train, o)));              // then the work
  out.commit();
}

}  // namespace sphtroch::cli
