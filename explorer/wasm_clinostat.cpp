// explorer/wasm_clinostat.cpp — the clinostat panel: the machine of `sphtroch clinostat` read by
// the CLI's reader (ClinostatText), its report as the JSON text that `sphtroch clinostat --json`
// prints (machine/clinostat_report.hpp: the library writes the object, the page parses it), and
// two pictures: the gravity path over a period and the M(W) curve of `--plot`. The dwell map
// needs HEALPix, which the module does not have.
#include "wasm_common.hpp"

#include "sphtroch/machine/clinostat_report.hpp"
#include "sphtroch/machine/clinostat_text.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace sphtroch::wasm {

namespace {

/// The machine of `sphtroch clinostat --outer O --inner I [--tilt T] [--frame-angle F]` ("" takes
/// the CLI's default), read by the CLI's reader: InvalidInput naming the CLI's option.
Clinostat page_clinostat(const std::string& outer, const std::string& inner, const std::string& tilt,
                         const std::string& frame_angle) {
  ClinostatText text;
  text.outer = outer;
  text.inner = inner;
  text.tilt = tilt;
  text.frame_angle = frame_angle;
  return Clinostat(text.settings());
}

/// A positive number as `sphtroch clinostat` reads --window, --epsilon and --resolution:
/// parse_number, then (0, max], refused in the words of src/cli/clinostat_command.cpp's
/// parse_positive.
double clinostat_positive(const std::string& text, const std::string& field, double max, const std::string& valid) {
  const std::optional<double> v = parse_number(text);
  if (!v || !(*v > 0) || *v > max) throw InvalidInput(field, text, "not a positive number in range", valid);
  return *v;
}

/// What the report computes beyond the train, period and mean: --window, --epsilon and
/// --resolution as the CLI's read_request reads them ("" = not given; src/cli/clinostat_command.cpp).
/// That reader is the CLI's own (not in the library), so this copies its bounds and words;
/// page_test.js checks the lines agree.
ClinostatRequest page_request(const std::string& window, const std::string& epsilon, const std::string& resolution) {
  ClinostatRequest r;
  if (!window.empty()) r.window = clinostat_positive(window, "window", 1e9, "seconds in (0, 1e9]");
  if (!epsilon.empty()) r.epsilon = clinostat_positive(epsilon, "epsilon", 1e9, "a bound in units of g0, > 0");
  if (!resolution.empty()) {
    if (!r.epsilon) throw InvalidInput("resolution", resolution, "only with --epsilon", "--epsilon E --resolution S");
    r.resolution = clinostat_positive(resolution, "resolution", 1e6, "seconds in (0, 1e6]");
  }
  return r;
}

/// The report of `sphtroch clinostat --outer ... --window W --epsilon E --resolution S` for the same
/// texts, read and refused in the CLI's order (the machine, then the request, then a period too
/// long to search).
ClinostatReport page_report(const std::string& outer, const std::string& inner, const std::string& tilt,
                            const std::string& frame_angle, const std::string& window, const std::string& epsilon,
                            const std::string& resolution) {
  const Clinostat m = page_clinostat(outer, inner, tilt, frame_angle);
  return clinostat_report(m, page_request(window, epsilon, resolution));
}

/// {json: the JSON text `sphtroch clinostat ... --json` prints for the same texts}
/// (clinostat_report_json; "" for window, epsilon, resolution: not asked), or {error}: the CLI's line.
val clinostat_report_export(const std::string& outer, const std::string& inner, const std::string& tilt,
                            const std::string& frame_angle, const std::string& window, const std::string& epsilon,
                            const std::string& resolution) {
  return guarded([&] {
    val out = val::object();
    out.set("json", clinostat_report_json(page_report(outer, inner, tilt, frame_angle, window, epsilon, resolution)).dump());
    return out;
  });
}

/// {path: g_s at times evenly over one period from t = 0, x0 y0 z0 x1 ... (the machine's gravity(t),
/// the points of --trace)}: 100 samples per turn of |outer| + |inner| over a period, within [360,
/// maxSamples]; one point when the gravity does not move.
val clinostat_path(const std::string& outer, const std::string& inner, const std::string& tilt, const std::string& frame_angle,
                   double max_samples) {
  return guarded([&] {
    const Clinostat m = page_clinostat(outer, inner, tilt, frame_angle);
    const std::optional<double> period = GravitySeries::of_gravity(m).period_s();
    const double rpm = std::fabs(m.settings().outer.value()) + std::fabs(m.settings().inner.value());
    const std::size_t count =
        period ? static_cast<std::size_t>(std::clamp(std::ceil(100 * *period * rpm / 60), 360.0, std::max(360.0, std::floor(max_samples))))
               : 1;
    std::vector<Vector3d> points;
    points.reserve(count);
    for (std::size_t k = 0; k < count; ++k)
      points.push_back(m.gravity(period ? *period * static_cast<double>(k) / static_cast<double>(count) : 0.0));
    val out = val::object();
    out.set("path", float64_array(flat(points)));
    return out;
  });
}

/// The M(W) panel of `sphtroch clinostat ... --plot` for the same texts (clinostat_report_plot: its
/// windows, their brackets and epsilon): {windows, lower, upper: Float64Array, epsilon (null when
/// not given), note ("" when the curve is searched; else why it is the bound over every frame
/// angle)}, or {error}.
val clinostat_windows(const std::string& outer, const std::string& inner, const std::string& tilt,
                      const std::string& frame_angle, const std::string& window, const std::string& epsilon,
                      const std::string& resolution) {
  return guarded([&] {
    const ClinostatPlot plot =
        clinostat_report_plot(page_report(outer, inner, tilt, frame_angle, window, epsilon, resolution), nullptr, {});
    std::vector<double> windows, lower, upper;
    for (const ClinostatPlot::Window& w : plot.windows) {
      windows.push_back(w.window_s);
      lower.push_back(w.lower);
      upper.push_back(w.upper);
    }
    val out = val::object();
    out.set("windows", float64_array(windows));
    out.set("lower", float64_array(lower));
    out.set("upper", float64_array(upper));
    out.set("epsilon", plot.epsilon ? val(*plot.epsilon) : val::null());
    out.set("note", plot.window_note);
    return out;
  });
}

}  // namespace

void register_clinostat() {
  emscripten::function("clinostatReport", &clinostat_report_export);
  emscripten::function("clinostatPath", &clinostat_path);
  emscripten::function("clinostatWindows", &clinostat_windows);
}

}  // namespace sphtroch::wasm
