// explorer/wasm_synthesis.cpp — inverse design: the trains nearest a path (fit: synthesis/path_fit.hpp,
// `sphtroch synth fit`) and every train through three points (points: the certified
// synthesis/precision_points.hpp, `sphtroch synth points`), each within the page's bound on work
// (both run on the page's main thread).
#include "wasm_common.hpp"

#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/polyline_input.hpp"
#include "sphtroch/synthesis/path_fit.hpp"
#include "sphtroch/synthesis/precision_points.hpp"

#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace sphtroch::wasm {

namespace {

/// The points of a text as `sphtroch synth fit/points --input` reads them: the text goes to a file
/// of the module's memory file system named "points" (so errors name it) and the CLI's reader.
std::vector<Vector3d> read_page_points(const std::string& text) {
  FILE* f = std::fopen("points", "wb");
  const bool written = f && std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (!f || std::fclose(f) != 0 || !written) throw std::runtime_error("the points could not be handed to the reader");
  return read_polyline("points", "points", 1).vertices;
}

/// The page's bound on a fit's work (fit_path's unit: points x (2|p| + 30), ~0.5 us each natively):
/// about a second natively, a few in the page, whose main thread waits for it.
constexpr double kPageFitWork = 2e6;

/// Inverse design: the trains of ratio n (or teeth) nearest a path given as the text of `sphtroch
/// synth fit --input` (CSV rows x,y,z, or a header naming x, y, z), best first, optionally with a
/// wanted node count ("" = any). Read by the CLI's reader (read_page_points) and fitted by
/// fit_path, one thread. Each candidate: {n, a2, a3, phase, rms, maxDeviation, margin, rootNodes}
/// (radians); the page then classifies it as any state (its count check). {candidates: [],
/// reason} when none can be.
val fit(const std::string& points, const std::string& n, const std::string& teeth, const std::string& nodes) {
  return guarded([&] {
    const Ratio ratio = ratio_of(n, teeth);
    FitOptions options;
    if (!nodes.empty()) {
      // As `sphtroch synth fit --nodes` reads it.
      const std::size_t k = parse_count(nodes, "nodes", 0, kMaxWantedCount);
      options.nodes = static_cast<std::int64_t>(k);
    }
    const std::vector<Vector3d> path = read_page_points(points);
    const double per_point = 2 * static_cast<double>(ratio.abs_p()) + 30;  // fit_path's work per point
    if (static_cast<double>(path.size()) * per_point > kPageFitWork)
      throw InvalidInput("points", std::to_string(path.size()) + " points", "more than the page fits at once (points x (2|p| + 30) > 2e6)",
                         "at most " + std::to_string(static_cast<long long>(kPageFitWork / per_point)) + " points for n = " +
                             ratio.str() + " (sphtroch synth fit takes more)");
    const PathFit r = fit_path(path, ratio, options);
    val list = val::array();
    for (const FitCandidate& c : r.candidates) {
      val item = train_object(c.train);
      item.set("rms", c.rms);
      item.set("maxDeviation", c.max_deviation);
      item.set("margin", c.margin);
      item.set("rootNodes", static_cast<double>(c.root_nodes));
      list.call<void>("push", item);
    }
    val out = val::object();
    out.set("candidates", list);
    out.set("reason", r.reason);
    return out;
  });
}

/// The page's bounds on a precision-points search, which runs on its main thread: the estimated
/// work (|p| + q)^2 (`sphtroch synth points`' unit: the lists of Delta span 2 pi q and turn |n|
/// times faster), refused up front above kPagePointsWork (the CLI allows 20000); and the boxes,
/// beyond which the list is shown as not certified. Measured in the docs (docs/explorer.md).
constexpr double kPagePointsWork = 400;
constexpr std::size_t kPagePointsBoxes = 1000000;

/// Every train of ratio n (or teeth) whose tracer passes through three points (the text of
/// `sphtroch synth points --input`), fixed frame, certified as synthesis/precision_points.hpp says
/// (the module's intervals: CGAL_ALWAYS_ROUND_TO_NEAREST, see explorer/CMakeLists.txt).
/// {solutions: [{n, a2, a3, phase, params, residual, isolated}], certified, undecided, boxes,
/// boxLimit}; the page classifies each solution as any state.
val points(const std::string& text, const std::string& n, const std::string& teeth) {
  return guarded([&] {
    const Ratio ratio = ratio_of(n, teeth);
    const double size = static_cast<double>(ratio.abs_p()) + static_cast<double>(ratio.q());
    if (size * size > kPagePointsWork)
      throw InvalidInput(teeth.empty() ? "n" : "teeth", teeth.empty() ? n : teeth,
                         "too much work for the page's precision points ((|p| + q)^2 = " + number_text(size * size) + ")",
                         "(|p| + q)^2 <= 400, e.g. |p| + q <= 20 (sphtroch synth points allows 20000)");
    PrecisionPointsOptions options;
    options.max_boxes = kPagePointsBoxes;
    const PrecisionPoints r = precision_points(read_page_points(text), ratio, options);
    val list = val::array();
    for (const PrecisionSolution& x : r.solutions) {
      val item = train_object(x.train);
      item.set("params", float64_array(x.params));
      item.set("residual", x.residual);
      item.set("isolated", x.isolated);
      list.call<void>("push", item);
    }
    val out = val::object();
    out.set("solutions", list);
    out.set("certified", r.certified);
    out.set("undecided", static_cast<double>(r.undecided));
    out.set("boxes", static_cast<double>(r.boxes));
    out.set("boxLimit", static_cast<double>(kPagePointsBoxes));
    return out;
  });
}

}  // namespace

void register_synthesis() {
  emscripten::function("fit", &fit);
  emscripten::function("points", &points);
}

}  // namespace sphtroch::wasm
