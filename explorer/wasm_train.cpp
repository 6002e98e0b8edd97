// explorer/wasm_train.cpp — one train on the sphere and its exports: the trace (points, velocities,
// the default view), the trace CSV and the sphere picture (the bytes of `sphtroch trace` and
// `sphtroch plot`: the library's writers), the marker rule, and numbers as the CLI prints them.
#include "wasm_common.hpp"

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/curve_view.hpp"
#include "sphtroch/draw/mark_density.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/trace_output.hpp"

#include <cstdint>
#include <sstream>

namespace sphtroch::wasm {

namespace {

/// Which node and cusp markers a picture of `nodes` nodes and `cusps` cusps draws in `mode` ("auto",
/// "all", "none"; the library's rule, draw/mark_density.hpp, as `sphtroch plot --markers`):
/// {draw, note, dense} (dense: the automatic rule hides them), or {error} naming "markers".
val marks(const std::string& mode, double nodes, double cusps) {
  return guarded([&] {
    const MarkChoice m = choose_marks(parse_mark_mode(mode), static_cast<std::size_t>(nodes), static_cast<std::size_t>(cusps));
    val out = val::object();
    out.set("draw", m.draw);
    out.set("note", m.note);
    out.set("dense", dense_curve(static_cast<std::size_t>(nodes), static_cast<std::size_t>(cusps)));
    return out;
  });
}

/// A sample count the page may ask for: an integer 3 .. 1e6 (InvalidInput "samples" otherwise).
std::size_t page_samples(double samples) {
  if (!(samples >= 3 && samples <= 1e6 && samples == static_cast<double>(static_cast<std::int64_t>(samples))))
    throw InvalidInput("samples", number_text(samples), "outside the valid range", "integer 3 .. 1000000");
  return static_cast<std::size_t>(samples);
}

/// `samples` points of one period (the CLI's trace --samples), as x0 y0 z0 x1 ... (unit vectors),
/// and with `velocity` their velocities dP/dtheta2 = omega x P (Eq. 47a; the CLI's --velocity) as
/// `velocities`, laid out the same; `view`: the direction `sphtroch plot` looks from by default,
/// chosen from these points (draw/curve_view.hpp), [x, y, z].
val trace(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
          const std::string& teeth, double samples, bool velocity) {
  return guarded([&] {
    const GearTrain t = train_text(a2, a3, n, phase, teeth).train();
    const TracerCurve<double> curve(t);
    const auto sampled = sample_period(curve, page_samples(samples), velocity);
    val out = val::object();
    out.set("points", float64_array(flat(sampled.points)));
    if (velocity) out.set("velocities", float64_array(flat(sampled.velocities)));
    out.set("params", float64_array(sampled.t));
    const std::vector<Vector3d> points(sampled.points.begin(), sampled.points.end());
    const Vector3d view = view_of_curve(points, true).direction;
    out.set("view", float64_array(std::vector<double>{view.x(), view.y(), view.z()}));
    return out;
  });
}

/// The trace CSV of `samples` points of one period of the train as given: {text}, the bytes
/// `sphtroch trace --samples N` prints for the same texts (io/trace_output.hpp's writer).
val trace_csv(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
              const std::string& teeth, double samples) {
  return guarded([&] {
    const GearTrain t = train_text(a2, a3, n, phase, teeth).train();
    std::ostringstream out;
    write_trajectory_csv(out, sample_period(TracerCurve<double>(t), page_samples(samples)));
    return text_object(out.str());
  });
}

/// The caption of `sphtroch plot` (draw/svg_plot.hpp's plot_caption_text, the tool's words); a
/// count page_certified does not certify is said so.
std::string plot_caption(const TrainText& text, const PageCensus& census, std::size_t cusps) {
  const RootClassification& c = census.roots;
  const std::string caption = plot_caption_text(text, census.analysed, c.crossings, c.tangencies, cusps);
  return page_certified(census) ? caption : caption + " — count not certified in the page: run sphtroch plot";
}

/// The sphere picture of `sphtroch plot` for the same texts (draw/svg_plot.hpp's renderer, the
/// default view and size): {text}. The curve, the cusps and the caption's train are those of the
/// train read onto its boundaries, as the CLI's; the node marks are the page's census (the root
/// census, the CLI's count when certified; its marks agree with the CLI's at the picture's
/// precision, labelled in the same order, by the first branch parameter), drawn as `markers`
/// says ("auto", "all", "none": `sphtroch plot --markers`). Runs the certified census (the
/// caption says when it does not certify).
val plot_svg(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
             const std::string& teeth, const std::string& markers) {
  return guarded([&] {
    const TrainText text = train_text(a2, a3, n, phase, teeth);
    const PageCensus census = page_census(text.train());
    const std::vector<Cusp> cusps = cusp_points(census.analysed);
    PlotOptions options;
    options.markers = parse_mark_mode(markers);
    options.caption = plot_caption(text, census, cusps.size());
    const Trajectory<double> trajectory = sample_period(TracerCurve<double>(census.analysed), plot_sample_count(census.analysed));
    return text_object(render_sphere_svg(trajectory, census.roots.node_points, cusps, options));
  });
}

/// A shortest round-trip text of a double (what the CLI prints for it).
std::string shortest_text(double v) { return number_text(v); }

}  // namespace

void register_train() {
  emscripten::function("marks", &marks);
  emscripten::function("trace", &trace);
  emscripten::function("traceCsv", &trace_csv);
  emscripten::function("plotSvg", &plot_svg);
  emscripten::function("numberText", &shortest_text);
}

}  // namespace sphtroch::wasm
