// python/src/bind_design_map.cpp — the design map (bindings.hpp): classify_a3_range (the class
// intervals of an a3 sweep), atlas (the (a2, a3) map as NumPy arrays), boundaries (the events at
// one a2, as `sphtroch boundaries --json`) and boundary_loci (the boundary curves over an a2 range).
#include "bindings.hpp"

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/atlas/atlas_boundary_check.hpp"
#include "sphtroch/atlas/atlas_svg.hpp"
#include "sphtroch/atlas/atlas_summary.hpp"
#include "sphtroch/census/root_classification.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/map/boundary_events_output.hpp"

#include <sstream>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

namespace sphtroch::python {
namespace {

py::list classify_a3_range_list(py::handle a2, py::handle n, py::handle a3, py::handle count, py::handle literal_flag) {
  std::string ignored;
  const double a2v = angle_arg(a2, "a2", ignored);
  const Ratio nv = ratio_arg(n);
  auto [lo, hi] = range_arg(a3, "a3");
  // Ranges read the same everywhere (0 <= lo < hi <= pi, as atlas): an end within 1e-6 of 0 or
  // pi, where no train exists, is sampled 1e-6 inside (kMinCarrierTwist).
  const double pi = Constants<double>::pi();
  if (lo >= 0.0 && lo < kMinCarrierTwist && hi > kMinCarrierTwist) lo = kMinCarrierTwist;
  if (hi <= pi && hi > pi - kMinCarrierTwist && lo < pi - kMinCarrierTwist) hi = pi - kMinCarrierTwist;
  const std::size_t k = count_arg(count, "count", 2, 1000000);
  const bool literal = flag_arg(literal_flag, "literal");
  std::vector<A3Interval> runs;
  try {
    py::gil_scoped_release release;
    runs = classify_a3_range(a2v, nv, lo, hi, k, Reading{literal});
  } catch (const InvalidInput& e) {  // the library's "a3_range" is the argument a3 here
    if (e.field() != "a3_range") throw;
    throw InvalidInput("a3", e.value(), e.problem(), "(lo, hi) with 0 <= lo < hi <= pi radians, hi - lo > 1e-6 inside");
  }
  py::list out;
  for (const A3Interval& r : runs) {
    py::dict d;
    d["a3_first"] = r.a3_first;
    d["a3_last"] = r.a3_last;
    d["samples"] = r.samples;
    d["class"] = to_string(r.curve_class);
    d["nodes"] = r.nodes;
    d["cusps"] = r.cusps;
    out.append(d);
  }
  return out;
}

/// A std::vector<T> handed to NumPy as a (G, G) array (no copy).
template <typename T>
py::array square(std::vector<T> values, std::size_t g) {
  auto owner = std::make_unique<std::vector<T>>(std::move(values));
  const T* data = owner->data();
  const auto side = static_cast<py::ssize_t>(g);
  return py::array_t<T>(std::vector<py::ssize_t>{side, side}, data, capsule_of(std::move(owner)));
}

py::dict atlas(py::handle n, py::handle grid, py::handle a2, py::handle a3, py::handle threads, py::handle literal_flag,
               py::handle progress_callback, py::handle svg_flag) {
  const bool literal = flag_arg(literal_flag, "literal");
  const bool with_svg = flag_arg(svg_flag, "svg");
  AtlasSpec spec;
  spec.ratio = ratio_arg(n);
  spec.grid = count_arg(grid, "grid", 1, kAtlasMaxGrid);
  const auto r2 = range_arg(a2, "a2"), r3 = range_arg(a3, "a3");
  spec.a2 = AngleRange{r2.first, r2.second};
  spec.a3 = AngleRange{r3.first, r3.second};
  spec.reading.literal = literal;
  const std::size_t workers =
      threads.is_none() ? std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, kAtlasMaxThreads)
                        : count_arg(threads, "threads", 1, kAtlasMaxThreads);
  const ParallelProgress progress = interruptible(progress_callback);
  std::vector<AtlasCell> cells;
  std::string svg, summary, uncertified;
  {
    py::gil_scoped_release release;
    spec.validate();
    const auto start = std::chrono::steady_clock::now();
    cells = compute_atlas(spec, AtlasRows{0, spec.grid}, workers, progress);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const AtlasSummary s = summarize_atlas(cells, spec.ratio);
    const AtlasBoundaryCheck check = check_atlas_boundaries(spec, cells, workers);
    std::ostringstream text;  // the summary `sphtroch atlas` prints, with its certificate
    write_atlas_summary(text, spec, s, listed_disagreements(s, cells), AtlasRun{AtlasRows{0, spec.grid}, {}, seconds, workers});
    write_atlas_boundary_check(text, check, cells);
    write_atlas_certificate(text, s, &check);
    summary = text.str();
    uncertified = atlas_uncertified(s, &check);
    if (with_svg) svg = render_atlas_svg(spec, cells);  // `sphtroch atlas --svg`
  }
  const std::size_t m = cells.size();
  std::vector<double> a2s(m), a3s(m);
  std::vector<std::int64_t> nodes(m), crossings(m), tangencies(m), cusps(m), analytic_nodes(m), analytic_cusps(m);
  std::vector<std::int8_t> agree(m);
  std::vector<std::uint8_t> cusps_agree(m);
  for (std::size_t k = 0; k < m; ++k) {
    const AtlasCell& c = cells[k];
    a2s[k] = c.a2;
    a3s[k] = c.a3;
    nodes[k] = c.nodes;
    crossings[k] = c.crossings;
    tangencies[k] = c.tangencies;
    cusps[k] = c.cusps;
    analytic_nodes[k] = c.analytic_nodes ? static_cast<std::int64_t>(*c.analytic_nodes) : -1;
    analytic_cusps[k] = c.analytic_cusps;
    agree[k] = c.agree ? static_cast<std::int8_t>(*c.agree) : std::int8_t{-1};
    cusps_agree[k] = c.cusps_agree ? 1 : 0;
  }
  py::dict d;
  d["a2"] = square(std::move(a2s), spec.grid);
  d["a3"] = square(std::move(a3s), spec.grid);
  d["nodes"] = square(std::move(nodes), spec.grid);
  d["crossings"] = square(std::move(crossings), spec.grid);
  d["tangencies"] = square(std::move(tangencies), spec.grid);
  d["cusps"] = square(std::move(cusps), spec.grid);
  d["analytic_nodes"] = square(std::move(analytic_nodes), spec.grid);
  d["analytic_cusps"] = square(std::move(analytic_cusps), spec.grid);
  d["agree"] = square(std::move(agree), spec.grid);
  d["cusps_agree"] = square(std::move(cusps_agree), spec.grid).attr("astype")("bool");
  d["n"] = spec.ratio.str();
  d["threads"] = workers;
  d["summary"] = summary;
  d["uncertified"] = uncertified;
  if (with_svg) d["svg"] = svg;
  return d;
}

/// The events at one a2: the dict `sphtroch boundaries --json` prints, read back from the same
/// writer (the same doubles, bit for bit).
py::object boundaries(py::handle n, py::handle a2) {
  std::string ignored;
  const Ratio nv = ratio_arg(n);
  const double a2v = angle_arg(a2, "a2", ignored);
  std::ostringstream json;
  {
    py::gil_scoped_release release;
    write_boundary_json(json, boundary_set(a2v, nv));
  }
  return from_json(json.str());
}

py::list boundary_loci_list(py::handle n, py::handle a2, py::handle steps, py::handle threads,
                            py::handle progress_callback) {
  const Ratio nv = ratio_arg(n);
  const auto [lo, hi] = range_arg(a2, "a2");
  const std::size_t k = count_arg(steps, "steps", 1, kMaxLocusSteps);
  const std::size_t workers =
      threads.is_none() ? std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, kAtlasMaxThreads)
                        : count_arg(threads, "threads", 1, kAtlasMaxThreads);
  const ParallelProgress progress = interruptible(progress_callback);
  std::vector<Locus> loci;
  {
    py::gil_scoped_release release;
    loci = boundary_loci(nv, lo, hi, k, workers, progress);
  }
  py::list out;
  for (const Locus& locus : loci) {
    py::dict d;
    d["kind"] = to_string(locus.kind);
    d["name"] = locus.name;
    const bool tangency = locus.kind == BoundaryEventKind::tangency;
    d["m"] = tangency ? py::object(py::int_(locus.m)) : py::object(py::none());
    d["label"] = tangency ? py::object(py::int_(locus.label)) : py::object(py::none());
    std::vector<double> a2s, a3s, bs;
    for (const LocusPoint& p : locus.points) {
      a2s.push_back(p.a2);
      a3s.push_back(p.a3);
      bs.push_back(p.b);
    }
    d["a2"] = py::array_t<double>(static_cast<py::ssize_t>(a2s.size()), a2s.data());
    d["a3"] = py::array_t<double>(static_cast<py::ssize_t>(a3s.size()), a3s.data());
    d["b"] = py::array_t<double>(static_cast<py::ssize_t>(bs.size()), bs.data());
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_design_map(py::module_& m) {
  m.def("boundaries", &boundaries, py::arg("n"), py::arg("a2"), doc("boundaries"));
  m.def("boundary_loci", &boundary_loci_list, py::arg("n"), py::arg("a2") = py::make_tuple(0.0, sphtroch::Constants<double>::pi()),
        py::arg("steps") = 720, py::arg("threads") = py::none(), py::kw_only(), py::arg("progress") = py::none(),
        doc("boundary_loci"));
  m.def("atlas", &atlas, py::arg("n"), py::arg("grid") = 128,
        py::arg("a2") = py::make_tuple(0.0, sphtroch::Constants<double>::pi()),
        py::arg("a3") = py::make_tuple(0.0, sphtroch::Constants<double>::pi()), py::arg("threads") = py::none(),
        py::arg("literal") = false, py::kw_only(), py::arg("progress") = py::none(), py::arg("svg") = false, doc("atlas"));
  m.def("classify_a3_range", &classify_a3_range_list, py::arg("a2"), py::arg("n"), py::arg("a3"),
        py::arg("count") = 721, py::arg("literal") = false, doc("classify_a3_range"));
}

}  // namespace sphtroch::python
