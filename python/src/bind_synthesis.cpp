// python/src/bind_synthesis.cpp — the inverse question (bindings.hpp): sphtroch.identify(t, P), the
// train of a timed trace (synthesis/identify.hpp), sphtroch.synth_points(P, n=...), every train
// through three points (synthesis/precision_points.hpp), and sphtroch.fit(P, n=..., nodes=..., cusps=...),
// ranked trains nearest a path (synthesis/path_fit.hpp); NumPy in, a dict out, the GIL released.
#include "bindings.hpp"
#include "exact_calls.hpp"

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/ratio_set.hpp"
#include "sphtroch/synthesis/identify.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace sphtroch::python {
namespace {

constexpr const char* kTimesValid = "a 1-D array of carrier angles theta2 (radians), one per point";
constexpr const char* kPointsValid = "an (N, 3) array of unit vectors x, y, z, one per time";

/// The (N, 3) rows of an array argument (real_array_arg: integer or float dtypes only).
std::vector<Vector3d> rows_arg(py::handle points, const char* field, const char* valid) {
  const RealArray pa = real_array_arg(points, field, valid);
  if (pa.ndim() != 2 || pa.shape(1) != 3) throw InvalidInput(field, shape_text(pa), "not an (N, 3) array", valid);
  std::vector<Vector3d> p(static_cast<std::size_t>(pa.shape(0)));
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = Vector3d(pa.at(i, 0), pa.at(i, 1), pa.at(i, 2));
  return p;
}

py::dict identify_dict(py::handle t, py::handle points) {
  const RealArray ta = real_array_arg(t, "t", kTimesValid);
  if (ta.ndim() != 1) throw InvalidInput("t", shape_text(ta), "not a 1-D array", kTimesValid);
  const std::vector<double> times(ta.data(), ta.data() + ta.shape(0));
  const std::vector<Vector3d> p = rows_arg(points, "points", kPointsValid);
  Identified id{};
  {
    py::gil_scoped_release release;
    id = identify(times, p);
  }
  py::dict d;
  d["n"] = id.train.ratio().str();
  d["a2"] = id.train.a2();
  d["a3"] = id.train.a3();
  d["phase"] = id.train.phase();
  d["residual"] = id.residual;
  d["rms"] = id.rms;
  d["noise"] = id.noise;
  return d;
}

/// The (N, 3) points of a synthesis call.
std::vector<Vector3d> points_arg(py::handle points, const char* valid) { return rows_arg(points, "points", valid); }

/// The ratios of n=R, teeth="ZS:ZP" | "MIN..MAX" or ratios=(P, Q), read as the CLI reads --n,
/// --teeth and --ratios (io/ratio_set.hpp), within the work bound `max_work` (core/cost_bounds.hpp).
RatioSet ratios_arg(py::handle n, py::handle ratios, py::handle teeth_text, double max_work) {
  if (int(!n.is_none()) + int(!ratios.is_none()) + int(!teeth_text.is_none()) != 1) {
    const bool by_teeth = !teeth_text.is_none();
    throw InvalidInput(by_teeth ? "teeth" : "n", repr_of(by_teeth ? teeth_text : n), "give exactly one of n, teeth and ratios",
                       "n=R, teeth='ZS:ZP' or 'MIN..MAX', or ratios=(P, Q) as `--ratios P,Q`");
  }
  RatioRequestText request;
  if (!n.is_none()) {
    request.n = ratio_arg(n).str();
  } else if (!teeth_text.is_none()) {
    request.teeth = text_arg(teeth_text, "teeth", "'ZS:ZP' (39:15) or 'MIN..MAX' (12..60)");
    if (request.teeth.empty()) parse_teeth(request.teeth, "teeth");  // refused naming teeth, not taken as "not given"
  } else {
    const auto bounds = count_pair_arg(ratios, "ratios", 1, 1000);
    request.ratios = std::to_string(bounds.first) + "," + std::to_string(bounds.second);
  }
  const RatioSet set = parse_ratio_set(request);
  const char* field = !n.is_none() ? "n" : !ratios.is_none() ? "ratios" : "teeth";
  check_ratio_work(set, field, ratios.is_none() ? request.n + request.teeth : repr_of(ratios), max_work);
  return set;
}

/// What a synth_points call computes from: its points, ratios and searches at once.
struct PointsCall {
  std::vector<Vector3d> points;
  RatioSet request;
  bool free_axis = false;
  std::size_t workers = 1;
};

/// The arguments of synth_points / synth_points_text, checked as the CLI checks them.
PointsCall points_call(py::handle points, py::handle n, py::handle ratios, py::handle teeth_text, py::handle free_axis_flag,
                       py::handle threads) {
  PointsCall c;
  c.free_axis = flag_arg(free_axis_flag, "free_axis");
  c.points = points_arg(points, c.free_axis ? "a (5, 3) array of unit vectors x, y, z" : "a (3, 3) array of unit vectors x, y, z");
  c.request = ratios_arg(n, ratios, teeth_text, c.free_axis ? kMaxFreeAxisWork : kMaxPointsWork);
  if (!c.free_axis) {
    const char* field = !n.is_none() ? "n" : !ratios.is_none() ? "ratios" : "teeth";
    check_points_census_work(c.request.ratios, field, repr_of(!n.is_none() ? n : !ratios.is_none() ? ratios : teeth_text));
  }
  c.workers = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 1024);
  if (!threads.is_none()) {
    if (!c.free_axis)
      throw InvalidInput("threads", repr_of(threads), "only with free_axis=True", "None or an integer 1 .. 1024, with free_axis=True");
    c.workers = *optional_count_arg(threads, "threads", 1, 1024);
  }
  return c;
}

/// The report of a synth_points call, the GIL released: JSON text, or with `text` the CLI's text;
/// `progress_callback` (None, a function or a bar) told the ratios done (interruptible).
std::string points_report(const PointsCall& c, bool text, py::handle progress_callback) {
  const ParallelProgress progress = interruptible(progress_callback);
  py::gil_scoped_release release;
  return precision_points_report(c.points, c.request.ratios, c.request.json_members(), c.request.teeth, c.free_axis,
                                 c.workers, text, progress);
}

/// sphtroch.synth_points(P, n=...): every train of ratio n through the three points (fixed
/// frame), as `sphtroch synth points --json` prints it (a dict; json.loads of the library's JSON).
py::object synth_points(py::handle points, py::handle n, py::handle ratios, py::handle teeth_text, py::handle free_axis_flag,
                        py::handle threads, py::handle progress) {
  const PointsCall c = points_call(points, n, ratios, teeth_text, free_axis_flag, threads);
  return py::module_::import("json").attr("loads")(points_report(c, false, progress));
}

/// sphtroch.synth_points_text(P, n=...): the same, as the text `sphtroch synth points` prints.
py::str synth_points_text(py::handle points, py::handle n, py::handle ratios, py::handle teeth_text,
                          py::handle free_axis_flag, py::handle threads, py::handle progress) {
  return py::str(points_report(points_call(points, n, ratios, teeth_text, free_axis_flag, threads), true, progress));
}

/// What a fit call computes from: the path's points, the ratios and the options.
struct FitCall {
  std::vector<Vector3d> points;
  RatioSet request;
  FitOptions options;
};

/// The arguments of fit / fit_text, checked as the CLI checks them.
FitCall fit_call(py::handle points, py::handle n, py::handle ratios, py::handle teeth_text, py::handle nodes,
                 py::handle cusps, py::handle candidates, py::handle max_deviation, py::handle node_at,
                 py::handle node_tolerance, py::handle min_margin) {
  FitCall c{points_arg(points, "an (N, 3) array of unit vectors x, y, z, N >= 4"), ratios_arg(n, ratios, teeth_text, kMaxFitWork), {}};
  FitOptions& o = c.options;
  const auto count = [](const std::optional<std::size_t>& k) {
    return k ? std::optional<std::int64_t>(static_cast<std::int64_t>(*k)) : std::nullopt;
  };
  o.nodes = count(optional_count_arg(nodes, "nodes", 0, kMaxWantedCount));
  o.cusps = count(optional_count_arg(cusps, "cusps", 0, kMaxWantedCount));
  o.max_candidates = count_arg(candidates, "candidates", 1, 1000);  // the CLI's --candidates
  o.max_deviation = real_arg(max_deviation, "max-deviation", "radians > 0");
  if (!node_at.is_none()) {
    const char* const valid = "None or (x, y, z), a unit vector";
    const RealArray a = real_array_arg(node_at, "node-at", valid);
    if (a.ndim() != 1 || a.shape(0) != 3) throw InvalidInput("node-at", shape_text(a), "not three numbers", valid);
    o.node_at = Vector3d(a.at(0), a.at(1), a.at(2));
  }
  if (!node_tolerance.is_none()) {
    if (!o.node_at) throw InvalidInput("node-tolerance", repr_of(node_tolerance), "without node_at", "None, or an angle with node_at");
    o.node_tolerance = real_arg(node_tolerance, "node-tolerance", "radians in (0, pi]");
  }
  o.min_margin = real_arg(min_margin, "min-margin", "radians in [0, 0.785]");  // range: check_fit_inputs
  return c;
}

/// The report of a fit call, the GIL released: JSON text, or with `text` the CLI's text;
/// `progress_callback` told the ratios done (interruptible).
std::string fit_call_report(const FitCall& c, bool text, py::handle progress_callback) {
  const ParallelProgress progress = interruptible(progress_callback);
  py::gil_scoped_release release;
  return fit_report(c.points, c.request.ratios, c.options, c.request.json_members(), c.request.teeth, text, progress);
}

/// sphtroch.fit(P, n=..., nodes=None, cusps=None): ranked trains nearest the path, as `sphtroch
/// synth fit --json` prints it (a dict).
py::object fit(py::handle points, py::handle n, py::handle ratios, py::handle teeth_text, py::handle nodes,
               py::handle cusps, py::handle candidates, py::handle max_deviation, py::handle node_at, py::handle node_tolerance,
               py::handle min_margin, py::handle progress) {
  const FitCall c =
      fit_call(points, n, ratios, teeth_text, nodes, cusps, candidates, max_deviation, node_at, node_tolerance, min_margin);
  return py::module_::import("json").attr("loads")(fit_call_report(c, false, progress));
}

/// sphtroch.fit_text(P, n=...): the same, as the text `sphtroch synth fit` prints.
py::str fit_text_report(py::handle points, py::handle n, py::handle ratios, py::handle teeth_text, py::handle nodes,
                        py::handle cusps, py::handle candidates, py::handle max_deviation, py::handle node_at,
                        py::handle node_tolerance, py::handle min_margin, py::handle progress) {
  return py::str(fit_call_report(
      fit_call(points, n, ratios, teeth_text, nodes, cusps, candidates, max_deviation, node_at, node_tolerance, min_margin), true,
      progress));
}

}  // namespace

void bind_synthesis(py::module_& m) {
  m.def("identify", &identify_dict, py::arg("t"), py::arg("points"), doc("identify"));
  m.def("synth_points", &synth_points, py::arg("points"), py::kw_only(), py::arg("n") = py::none(),
        py::arg("ratios") = py::none(), py::arg("teeth") = py::none(), py::arg("free_axis") = false,
        py::arg("threads") = py::none(), py::arg("progress") = py::none(), doc("synth_points"));
  m.def("synth_points_text", &synth_points_text, py::arg("points"), py::kw_only(), py::arg("n") = py::none(),
        py::arg("ratios") = py::none(), py::arg("teeth") = py::none(), py::arg("free_axis") = false,
        py::arg("threads") = py::none(), py::arg("progress") = py::none(), doc("synth_points_text"));
  m.def("fit", &fit, py::arg("points"), py::kw_only(), py::arg("n") = py::none(), py::arg("ratios") = py::none(),
        py::arg("teeth") = py::none(), py::arg("nodes") = py::none(), py::arg("cusps") = py::none(), py::arg("candidates") = 5,
        py::arg("max_deviation") = std::numeric_limits<double>::infinity(), py::arg("node_at") = py::none(),
        py::arg("node_tolerance") = py::none(), py::arg("min_margin") = 0.0, py::arg("progress") = py::none(), doc("fit"));
  m.def("fit_text", &fit_text_report, py::arg("points"), py::kw_only(), py::arg("n") = py::none(),
        py::arg("ratios") = py::none(), py::arg("teeth") = py::none(), py::arg("nodes") = py::none(),
        py::arg("cusps") = py::none(), py::arg("candidates") = 5,
        py::arg("max_deviation") = std::numeric_limits<double>::infinity(), py::arg("node_at") = py::none(),
        py::arg("node_tolerance") = py::none(), py::arg("min_margin") = 0.0, py::arg("progress") = py::none(),
        doc("fit_text"));
}

}  // namespace sphtroch::python
