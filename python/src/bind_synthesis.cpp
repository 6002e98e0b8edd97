// python/src/bind_synthesis.cpp — the inverse question (bindings.hpp): sphtroch.identify(t, P), the
// train of a timed trace (synthesis/identify.hpp), sphtroch.synth_points(P, n=...), every train
// through three points (exact/precision_points.hpp), and sphtroch.fit(P, n=..., nodes=..., cusps=...),
// ranked trains nearest a path (synthesis/path_fit.hpp); NumPy in, a dict out, the GIL released.
#include "bindings.hpp"
#include "exact_calls.hpp"

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/io/parse.hpp"
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

py::dict identify_dict(py::handle t, py::handle points) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Array ta = Array::ensure(t), pa = Array::ensure(points);
  if (!ta || ta.ndim() != 1) throw InvalidInput("t", repr_of(py::type::of(t).attr("__name__")), "not a 1-D array", kTimesValid);
  if (!pa || pa.ndim() != 2 || pa.shape(1) != 3)
    throw InvalidInput("points", repr_of(py::type::of(points).attr("__name__")), "not an (N, 3) array", kPointsValid);
  const std::vector<double> times(ta.data(), ta.data() + ta.shape(0));
  std::vector<Vector3d> p(static_cast<std::size_t>(pa.shape(0)));
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = Vector3d(pa.at(i, 0), pa.at(i, 1), pa.at(i, 2));
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

/// sphtroch.synth_points(P, n=...): every train of ratio n through the three points (fixed
/// frame), as `sphtroch synth points --json` prints it (a dict; json.loads of the library's JSON).
/// The (N, 3) points of a synthesis call.
std::vector<Vector3d> points_arg(py::handle points, const char* valid) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Array pa = Array::ensure(points);
  if (!pa || pa.ndim() != 2 || pa.shape(1) != 3)
    throw InvalidInput("points", repr_of(py::type::of(points).attr("__name__")), "not an (N, 3) array", valid);
  std::vector<Vector3d> p(static_cast<std::size_t>(pa.shape(0)));
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = Vector3d(pa.at(i, 0), pa.at(i, 1), pa.at(i, 2));
  return p;
}

/// Bound on the sum over the ratios of (|p| + q)^2: the CLI's work bound (synth points / fit),
/// and that of synth points --free-axis.
constexpr double kMaxRatioWork = 20000;
constexpr double kMaxFreeAxisWork = 500;

/// Refuses (InvalidInput `field`) a set of ratios beyond the CLI's work bound `max_work`.
void check_ratio_work(const std::vector<Ratio>& set, const char* field, const std::string& value,
                      double max_work = kMaxRatioWork) {
  double work = 0;
  for (const Ratio& k : set) work += double(k.abs_p() + k.q()) * double(k.abs_p() + k.q());
  if (work > max_work)
    throw InvalidInput(field, value, "estimated work " + number_text(work) + " over the bound",
                       "sum over the ratios of (|p| + q)^2 <= " + number_text(max_work) +
                           " (the CLI's bound; ratios=(7, 7) is 4832)");
}

/// The ratios of n=R, teeth="ZS:ZP" | "MIN..MAX" (the CLI's --teeth) or ratios=(P, Q) (P, Q <= 7),
/// within the CLI's work bound; sets `fields` (the JSON members naming a set) and `teeth` (what
/// is echoed).
std::vector<Ratio> ratios_arg(py::handle n, py::handle ratios, py::handle teeth_text, std::string& fields, TeethSpec& teeth) {
  if (int(!n.is_none()) + int(!ratios.is_none()) + int(!teeth_text.is_none()) != 1) {
    const bool by_teeth = !teeth_text.is_none();
    throw InvalidInput(by_teeth ? "teeth" : "n", repr_of(by_teeth ? teeth_text : n), "give exactly one of n, teeth and ratios",
                       "n=R, teeth='ZS:ZP' or 'MIN..MAX', or ratios=(P, Q) as `--ratios P,Q`");
  }
  std::vector<Ratio> set;
  if (!n.is_none()) {
    set = {ratio_arg(n)};
    check_ratio_work(set, "n", set[0].str());
  } else if (!teeth_text.is_none()) {
    if (!py::isinstance<py::str>(teeth_text))
      throw InvalidInput("teeth", repr_of(teeth_text), "not a string", "'ZS:ZP' (39:15) or 'MIN..MAX' (12..60)");
    const std::string text = teeth_text.cast<std::string>();
    if (text.find("..") == std::string::npos) {
      teeth.pair = parse_teeth(text, "teeth");
      fields = "\"teeth\": \"" + teeth.pair->str() + "\", ";
      set = {teeth.pair->ratio()};
    } else {
      teeth.range = parse_tooth_range(text, "teeth");
      fields = "\"teeth\": \"" + teeth.range->str() + "\", ";
      set = ratio_set(*teeth.range);
    }
    check_ratio_work(set, "teeth", text);
  } else {
    const auto bounds = ratios.cast<std::pair<std::int64_t, std::int64_t>>();
    if (bounds.first < 1 || bounds.second < 1 || bounds.first > 7 || bounds.second > 7)
      throw InvalidInput("ratios", repr_of(ratios), "bounds out of range", "(P, Q) with 1 <= P, Q <= 7 (the CLI's work bound)");
    fields = "\"ratios\": \"" + std::to_string(bounds.first) + "," + std::to_string(bounds.second) + "\", ";
    set = ratio_set(bounds.first, bounds.second);
  }
  return set;
}

std::optional<std::int64_t> count_arg(py::handle v, const char* field);

py::object synth_points(py::handle points, py::handle n, py::handle ratios, py::handle teeth_text, bool free_axis,
                        py::handle threads) {
  const std::vector<Vector3d> p =
      points_arg(points, free_axis ? "a (5, 3) array of unit vectors x, y, z" : "a (3, 3) array of unit vectors x, y, z");
  std::string fields;
  TeethSpec teeth;
  const std::vector<Ratio> set = ratios_arg(n, ratios, teeth_text, fields, teeth);
  const char* field = !n.is_none() ? "n" : !ratios.is_none() ? "ratios" : "teeth";
  const std::string given = repr_of(!n.is_none() ? n : !ratios.is_none() ? ratios : teeth_text);
  if (free_axis)
    check_ratio_work(set, field, given, kMaxFreeAxisWork);
  else
    check_points_census_work(set, field, given);
  std::size_t workers = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 1024);
  if (!threads.is_none()) {
    const auto k = count_arg(threads, "threads");
    if (!free_axis || *k < 1 || *k > 1024)
      throw InvalidInput("threads", repr_of(threads), free_axis ? "outside the valid range" : "only with free_axis=True",
                         "None or an integer 1 .. 1024, with free_axis=True");
    workers = static_cast<std::size_t>(*k);
  }
  std::string json;
  {
    py::gil_scoped_release release;
    json = precision_points_json_text(p, set, fields, teeth, free_axis, workers);
  }
  return py::module_::import("json").attr("loads")(json);
}

/// A count argument: None or an int >= 0.
std::optional<std::int64_t> count_arg(py::handle v, const char* field) {
  if (v.is_none()) return std::nullopt;
  if (!py::isinstance<py::int_>(v) || py::isinstance<py::bool_>(v))
    throw InvalidInput(field, repr_of(v), "not an integer", "None or an integer >= 0");
  std::int64_t k = 0;
  try {
    k = v.cast<std::int64_t>();
  } catch (const py::cast_error&) {
    throw InvalidInput(field, repr_of(v), "too large", "None or an integer >= 0 below 2**63");
  }
  if (k < 0) throw InvalidInput(field, repr_of(v), "negative", "None or an integer >= 0");
  return k;
}

/// sphtroch.fit(P, n=..., nodes=None, cusps=None): ranked trains nearest the path, as `sphtroch
/// synth fit --json` prints it (a dict).
py::object fit(py::handle points, py::handle n, py::handle ratios, py::handle teeth_text, py::handle nodes,
               py::handle cusps, py::handle candidates, double max_deviation, py::handle node_at, py::handle node_tolerance) {
  const std::vector<Vector3d> p = points_arg(points, "an (N, 3) array of unit vectors x, y, z, N >= 4");
  std::string fields;
  TeethSpec teeth;
  const std::vector<Ratio> set = ratios_arg(n, ratios, teeth_text, fields, teeth);
  FitOptions o;
  o.nodes = count_arg(nodes, "nodes");
  o.cusps = count_arg(cusps, "cusps");
  const auto wanted = count_arg(candidates, "candidates");
  if (!wanted || *wanted < 1 || *wanted > 1000)
    throw InvalidInput("candidates", repr_of(candidates), "outside the valid range", "an integer 1 .. 1000 (the CLI's --candidates)");
  o.max_candidates = static_cast<std::size_t>(*wanted);
  o.max_deviation = max_deviation;
  if (!node_at.is_none()) {
    using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
    const Array a = Array::ensure(node_at);
    if (!a || a.ndim() != 1 || a.shape(0) != 3)
      throw InvalidInput("node-at", repr_of(node_at), "not three numbers", "None or (x, y, z), a unit vector");
    o.node_at = Vector3d(a.at(0), a.at(1), a.at(2));
  }
  if (!node_tolerance.is_none()) {
    if (!o.node_at) throw InvalidInput("node-tolerance", repr_of(node_tolerance), "without node_at", "None, or an angle with node_at");
    o.node_tolerance = node_tolerance.cast<double>();
  }
  std::string json;
  {
    py::gil_scoped_release release;
    json = fit_json_text(p, set, o, fields, teeth);
  }
  return py::module_::import("json").attr("loads")(json);
}

}  // namespace

void bind_synthesis(py::module_& m) {
  m.def("identify", &identify_dict, py::arg("t"), py::arg("points"), doc("identify"));
  m.def("synth_points", &synth_points, py::arg("points"), py::kw_only(), py::arg("n") = py::none(),
        py::arg("ratios") = py::none(), py::arg("teeth") = py::none(), py::arg("free_axis") = false,
        py::arg("threads") = py::none(), doc("synth_points"));
  m.def("fit", &fit, py::arg("points"), py::kw_only(), py::arg("n") = py::none(), py::arg("ratios") = py::none(),
        py::arg("teeth") = py::none(), py::arg("nodes") = py::none(), py::arg("cusps") = py::none(), py::arg("candidates") = 5,
        py::arg("max_deviation") = std::numeric_limits<double>::infinity(), py::arg("node_at") = py::none(),
        py::arg("node_tolerance") = py::none(), doc("fit"));
}

}  // namespace sphtroch::python
