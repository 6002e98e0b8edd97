// python/src/module.cpp — the extension module sphtroch._sphtroch (pybind11): GearTrain, trace,
// classify, nodes, cusps, classify_roots, classify_a3_range, crossings, atlas, InvalidInput.
// The Python contract (names, arguments, returned dicts) is python/sphtroch/__init__.pyi.
//
// Decisions
//  * Every computation runs with the GIL released, on C++ values only (a GearTrain is an
//    immutable value; no state is shared between calls): Python threads run in parallel.
//  * Arrays go out without a copy: the C++ vectors move to the heap and a py::capsule owns them
//    (the array's base); the (N, 3) arrays view std::vector<Eigen::Vector3d> (3 packed doubles).
//  * Points come in without a copy when C-contiguous float64 (else converted once by NumPy).
//  * Every bad argument raises sphtroch.InvalidInput (a ValueError) with .field, .value, .valid
//    (and .problem): the library's own InvalidInput, or one raised here with the same contract.
//  * Angles are stored with their text (the CLI's strings, or the shortest round-trip text of a
//    float) so that classify() reports a2_text/a3_text as the CLI does and pickling is exact.
#include "exact_calls.hpp"

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/census/polyline_census_result.hpp"
#include "sphtroch/census/root_classification.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/version.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace sphtroch::python {
namespace {

/// The C++ type behind sphtroch.UncertifiedResult (never thrown: nodes() raises the Python class).
struct UncertifiedMarker : std::exception {};

/// The Python class sphtroch.InvalidInput (the module object keeps it alive).
py::handle g_invalid_input;

constexpr const char* kPointsValid =
    "an (N, 3) array of x, y, z rows (float64; other integer or float dtypes are converted)";

std::string repr_of(py::handle v) { return py::repr(v).cast<std::string>(); }

/// A str as UTF-8, else InvalidInput (a lone surrogate such as "\ud800" cannot be encoded).
std::string text_arg(py::handle v, const std::string& field, const std::string& valid) {
  Py_ssize_t size = 0;
  const char* p = PyUnicode_AsUTF8AndSize(v.ptr(), &size);
  if (p == nullptr) {
    PyErr_Clear();
    throw InvalidInput(field, repr_of(v), "not valid Unicode text (not encodable as UTF-8)", valid);
  }
  return std::string(p, static_cast<std::size_t>(size));
}

/// A flag: True or False (also numpy.bool_), else InvalidInput. Truthy objects ("yes", 1, None)
/// are refused, not read as bool.
bool flag_arg(py::handle v, const std::string& field) {
  if (v.ptr() == Py_True) return true;
  if (v.ptr() == Py_False) return false;
  const py::object np_bool = py::module_::import("numpy").attr("bool_");
  if (py::isinstance(v, np_bool)) return v.ptr() == Py_True || PyObject_IsTrue(v.ptr()) == 1;
  throw InvalidInput(field, repr_of(v), "not a flag", "True or False");
}

/// A real number (anything float() accepts, except bool, None and str), else InvalidInput.
double real_arg(py::handle v, const std::string& field, const std::string& valid) {
  if (v.is_none() || py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v))
    throw InvalidInput(field, repr_of(v), "not a real number", valid);
  PyObject* f = PyNumber_Float(v.ptr());
  if (f == nullptr) {
    PyErr_Clear();
    throw InvalidInput(field, repr_of(v), "not a real number", valid);
  }
  const double x = PyFloat_AsDouble(f);
  Py_DECREF(f);
  return x;
}

/// A whole number in [lo, hi] (int or any integer type with __index__; not bool), else InvalidInput.
std::size_t count_arg(py::handle v, const std::string& field, std::size_t lo, std::size_t hi) {
  const std::string valid = "integer " + std::to_string(lo) + " .. " + std::to_string(hi);
  if (py::isinstance<py::bool_>(v) || !PyIndex_Check(v.ptr())) throw InvalidInput(field, repr_of(v), "not a whole number", valid);
  PyObject* i = PyNumber_Index(v.ptr());
  if (i == nullptr) {
    PyErr_Clear();
    throw InvalidInput(field, repr_of(v), "not a whole number", valid);
  }
  int overflow = 0;
  const long long x = PyLong_AsLongLongAndOverflow(i, &overflow);
  Py_DECREF(i);
  if (overflow != 0 || x < 0 || static_cast<unsigned long long>(x) < lo || static_cast<unsigned long long>(x) > hi)
    throw InvalidInput(field, repr_of(v), "outside the valid range", valid);
  return static_cast<std::size_t>(x);
}

/// An angle: radians as a real number, or the CLI's text ("2pi/3", "90deg"). `text` receives
/// the text kept for reports (the shortest round-trip form of a real number).
double angle_arg(py::handle v, const std::string& field, std::string& text) {
  if (py::isinstance<py::str>(v)) {
    text = text_arg(v, field, kAngleForms);
    return parse_angle(text, field);
  }
  const double x = real_arg(v, field, kAngleForms);
  text = number_text(x);
  return x;
}

/// a3: an angle, or the CLI's cone references ("ap", "pi-ap+1e-6").
A3Spec a3_arg(py::handle v, std::string& text) {
  if (py::isinstance<py::str>(v)) {
    text = text_arg(v, "a3", kAngleForms);
    return parse_a3(text, "a3");
  }
  const double x = real_arg(v, "a3", kAngleForms);
  text = number_text(x);
  return {A3Reference::given, x};
}

/// n: int (or any integer type), fractions.Fraction (anything with integer numerator and
/// denominator), the CLI's text ("5/2", "2.5"), or a float read as its shortest decimal text
/// (2.5 -> 5/2; a float that is no decimal of at most 9 places, e.g. 1/3, is refused: give "1/3").
Ratio ratio_arg(py::handle v) {
  if (py::isinstance<py::str>(v)) return parse_ratio(text_arg(v, "n", kRatioForms), "n");
  if (v.is_none() || py::isinstance<py::bool_>(v)) throw InvalidInput("n", repr_of(v), "not a gear ratio", kRatioForms);
  if (py::hasattr(v, "numerator") && py::hasattr(v, "denominator") && !py::isinstance<py::float_>(v)) {
    const py::object p = v.attr("numerator"), q = v.attr("denominator");
    if (!PyIndex_Check(p.ptr()) || !PyIndex_Check(q.ptr())) throw InvalidInput("n", repr_of(v), "not a gear ratio", kRatioForms);
    int op = 0, oq = 0;
    const long long pv = PyLong_AsLongLongAndOverflow(py::int_(p).ptr(), &op);
    const long long qv = PyLong_AsLongLongAndOverflow(py::int_(q).ptr(), &oq);
    if (op != 0 || oq != 0) throw InvalidInput("n", repr_of(v), "numerator or denominator too large (max 1000000)", kRatioForms);
    if (pv == 0) throw InvalidInput("n", repr_of(v), "the gear ratio must not be zero", kRatioForms);
    return Ratio(pv, qv);  // range-checked (InvalidInput "n")
  }
  return parse_ratio(number_text(real_arg(v, "n", kRatioForms)), "n");
}

/// A gear train and the text of its inputs (TrainText: a2, a3, n, phase, as classify --json reports them).
struct Train {
  GearTrain train;
  TrainText text;
};

Train make_train(py::handle a2, py::handle a3, py::handle n, py::handle phase) {
  Train t;
  const double a2v = angle_arg(a2, "a2", t.text.a2);
  const A3Spec a3v = a3_arg(a3, t.text.a3);
  const Ratio nv = ratio_arg(n);
  t.text.n = nv.str();
  const double phv = angle_arg(phase, "phase", t.text.phase);
  t.train = make_gear_train(a2v, a3v, nv, phv);
  return t;
}

/// A capsule owning `owner`: the base of arrays viewing its data, deleting it with the last of them.
template <typename Owner>
py::capsule capsule_of(std::unique_ptr<Owner> owner) {
  return py::capsule(owner.release(), [](void* p) { delete static_cast<Owner*>(p); });
}

/// JSON text -> Python objects (json.loads), so the dicts are exactly the CLI's JSON.
py::object from_json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

py::tuple trace(const Train& self, py::handle samples, py::handle turns, py::handle velocity_flag) {
  const bool velocity = flag_arg(velocity_flag, "velocity");
  std::optional<double> k;
  if (!turns.is_none()) {
    k = real_arg(turns, "turns", kTurnsRange);
    check_turns(*k, number_text(*k));
  }
  const std::size_t n = samples.is_none() ? trace_sample_count(self.train, k)
                                           : count_arg(samples, "samples", kMinSamples, kMaxSamples);
  const TracerCurve<double> curve(self.train);
  const UniformSampling<double> sampling = k ? turns_sampling(curve, *k, n) : period_sampling(curve, n);
  auto tr = std::make_unique<Trajectory<double>>();
  {
    py::gil_scoped_release release;
    *tr = sample(curve, sampling, velocity);
  }
  const Trajectory<double>& v = *tr;
  const py::capsule owner = capsule_of(std::move(tr));
  const auto rows = static_cast<py::ssize_t>(v.size());
  py::array_t<double> t(std::vector<py::ssize_t>{rows}, v.t.data(), owner);
  py::array_t<double> p(std::vector<py::ssize_t>{rows, 3}, v.points.front().data(), owner);
  if (!velocity) return py::make_tuple(t, p);
  py::array_t<double> vel(std::vector<py::ssize_t>{rows, 3}, v.velocities.front().data(), owner);
  return py::make_tuple(t, p, vel);
}

std::size_t census_samples_arg(py::handle samples) {
  return samples.is_none() ? 0 : count_arg(samples, "samples", kMinCensusSamples, kMaxSamples);
}

py::object classify(const Train& self, py::handle literal_flag, py::handle samples) {
  const bool literal = flag_arg(literal_flag, "literal");
  const std::size_t s = census_samples_arg(samples);
  std::string text;
  {
    py::gil_scoped_release release;
    text = classification_json_text(self.text, self.train, literal, s);
  }
  return from_json(text);
}

/// The Python class sphtroch.UncertifiedResult (a RuntimeError; the module object keeps it alive).
py::handle g_uncertified;

/// nodes(): the certified node list, or UncertifiedResult carrying the uncertified list and both
/// counts (the CLI's exit status 3). cusps() need no node census certificate (pitch-cone criterion).
py::object nodes_and_cusps(const Train& self, py::handle literal_flag, py::handle samples, const char* key) {
  const bool literal = flag_arg(literal_flag, "literal");
  const std::size_t s = census_samples_arg(samples);
  std::string text;
  {
    py::gil_scoped_release release;
    text = nodes_and_cusps_json_text(self.text, self.train, literal, s);
  }
  const py::object all = from_json(text);
  if (std::string(key) == "nodes" && !all["certified"].cast<bool>()) {
    const std::string message = "the node count is not certified: polyline census " +
                                py::str(all["polyline_nodes"]).cast<std::string>() + " node(s), root-count census " +
                                py::str(all["root_nodes"]).cast<std::string>() + "; " +
                                all["stopped"].cast<std::string>() + " (see docs/cli.md: Certified counts)";
    py::object err = py::reinterpret_borrow<py::object>(g_uncertified)(message);
    err.attr("nodes") = all["nodes"];
    err.attr("polyline_nodes") = all["polyline_nodes"];
    err.attr("root_nodes") = all["root_nodes"];
    PyErr_SetObject(g_uncertified.ptr(), err.ptr());
    throw py::error_already_set();
  }
  return all[key];
}

py::dict node_dict(const Node& n) {
  py::dict d;
  d["position"] = py::make_tuple(n.position.x(), n.position.y(), n.position.z());
  d["params"] = n.params;
  d["branches"] = n.branches;
  d["kind"] = to_string(n.kind);
  d["angle"] = n.angle;
  d["crossing_pairs"] = n.crossing_pairs;
  d["tangency_pairs"] = n.tangency_pairs;
  return d;
}

py::dict classify_roots_dict(const Train& self, py::handle literal_flag) {
  const bool literal = flag_arg(literal_flag, "literal");
  RootClassification c;
  {
    py::gil_scoped_release release;
    c = classify_roots(self.train, Reading{literal});
  }
  py::dict d;
  d["a2"] = c.a2;
  d["a3"] = c.a3;
  d["boundaries"] = c.boundaries;
  d["class"] = to_string(c.curve_class);
  d["nodes"] = c.nodes;
  d["crossings"] = c.crossings;
  d["tangencies"] = c.tangencies;
  d["cusps"] = c.cusps;
  d["analytic_nodes"] = c.analytic_nodes ? py::object(py::int_(*c.analytic_nodes)) : py::object(py::none());
  d["analytic_cusps"] = c.analytic_cusps;
  d["agrees_with_report"] = c.agrees_with_report();
  py::list points;
  for (const Node& n : c.node_points) points.append(node_dict(n));
  d["node_points"] = points;
  return d;
}

/// (lo, hi) of angles (radians or the CLI's text), or the CLI's "LO:HI" text, field `field`.
std::pair<double, double> range_arg(py::handle v, const std::string& field) {
  const std::string valid = "(lo, hi) with angles as numbers (radians) or text (\"pi/3\"), or \"LO:HI\"";
  if (py::isinstance<py::str>(v)) {
    const AngleRange r = parse_angle_range(v.cast<std::string>(), field, kAngleRangeForms);
    return {r.lo, r.hi};
  }
  if (!py::isinstance<py::sequence>(v) || py::len(v) != 2)
    throw InvalidInput(field, repr_of(v), "not a pair (lo, hi)", valid);
  const py::sequence s = py::reinterpret_borrow<py::sequence>(v);
  std::string ignored;
  return {angle_arg(s[0], field, ignored), angle_arg(s[1], field, ignored)};
}

py::list classify_a3_range_list(py::handle a2, py::handle n, py::handle a3, py::handle count, py::handle literal_flag) {
  std::string ignored;
  const double a2v = angle_arg(a2, "a2", ignored);
  const Ratio nv = ratio_arg(n);
  const auto [lo, hi] = range_arg(a3, "a3");
  const std::size_t k = count_arg(count, "count", 2, 1000000);
  const bool literal = flag_arg(literal_flag, "literal");
  std::vector<A3Interval> runs;
  try {
    py::gil_scoped_release release;
    runs = classify_a3_range(a2v, nv, lo, hi, k, Reading{literal});
  } catch (const InvalidInput& e) {  // the library's "a3_range" is the argument a3 here
    if (e.field() != "a3_range") throw;
    throw InvalidInput("a3", e.value(), e.problem(), e.valid_range());
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

py::dict atlas(py::handle n, py::handle grid, py::handle a2, py::handle a3, py::handle threads, py::handle literal_flag) {
  const bool literal = flag_arg(literal_flag, "literal");
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
  std::vector<AtlasCell> cells;
  {
    py::gil_scoped_release release;
    spec.validate();
    cells = compute_atlas(spec, AtlasRows{0, spec.grid}, workers);
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
  return d;
}

std::string shape_text(const py::array& a) {
  std::string s = "array of shape (";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

/// A list of the kind names, sharing one str object per kind (not one per row).
py::list kind_list(const std::vector<std::uint8_t>& kinds) {
  py::list names;
  for (std::uint8_t k = 0; k < 4; ++k) names.append(py::str(contact_name(k)));
  py::list out(kinds.size());
  for (std::size_t r = 0; r < kinds.size(); ++r) out[r] = names[kinds[r]];
  return out;
}

py::dict crossings(py::handle points, py::handle closed_flag, py::handle pairs_flag, py::handle max_crossings,
                   py::handle max_work) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const bool closed = flag_arg(closed_flag, "closed");
  const bool with_pairs = flag_arg(pairs_flag, "pairs");
  const std::size_t limit_contacts = count_arg(max_crossings, "max_crossings", 0, kMaxCrossingLimit);
  const std::size_t limit_work = count_arg(max_work, "max_work", 0, kMaxCrossingLimit);
  // Only integer and float dtypes: NumPy would parse strings ("1.5") and drop imaginary parts.
  py::object arr = py::reinterpret_borrow<py::object>(points);
  if (!py::isinstance<py::array>(points)) {
    try {
      arr = py::module_::import("numpy").attr("asarray")(points);
    } catch (const py::error_already_set&) {
      throw InvalidInput("points", "a " + std::string(py::str(py::type::of(points).attr("__name__"))),
                         "not convertible to an array", kPointsValid);
    }
  }
  const py::dtype dt = py::reinterpret_borrow<py::array>(arr).dtype();
  if (dt.kind() != 'f' && dt.kind() != 'i' && dt.kind() != 'u')
    throw InvalidInput("points", "an array of dtype " + std::string(py::str(py::handle(dt))), "not numeric real (integer or float)",
                       kPointsValid);
  Array a = Array::ensure(arr);  // the same object when already C-contiguous float64
  if (!a) throw InvalidInput("points", "a " + std::string(py::str(py::type::of(points).attr("__name__"))), "not convertible to a float64 array", kPointsValid);
  if (a.ndim() != 2 || a.shape(1) != 3) throw InvalidInput("points", shape_text(a), "not an (N, 3) array", kPointsValid);
  const bool converted = !a.is(points);
  const auto n = static_cast<std::size_t>(a.shape(0));
  // The caller's array may be written by another thread once the GIL is released: search a
  // copy made now (under the GIL), so that what is validated is what is searched. A converted
  // array is already private.
  std::vector<Eigen::Vector3d> snapshot;
  if (!converted) snapshot.assign(reinterpret_cast<const Eigen::Vector3d*>(a.data()),
                                  reinterpret_cast<const Eigen::Vector3d*>(a.data()) + n);
  const double* xyz = converted || n == 0 ? a.data() : snapshot.front().data();
  CrossingsResult r;
  {
    py::gil_scoped_release release;
    r = self_crossings(xyz, n, closed, with_pairs, limit_contacts, limit_work);
  }
  py::dict d;
  d["vertices"] = r.vertices;
  d["closed"] = closed;
  d["crossings"] = r.crossings;
  d["touchings"] = r.touchings;
  if (with_pairs) {
    py::list kinds = kind_list(r.kinds);
    auto pairs = std::make_unique<std::vector<std::int64_t>>(std::move(r.pairs));
    const std::int64_t* data = pairs->data();
    const auto k = static_cast<py::ssize_t>(pairs->size() / 2);
    d["pairs"] = py::array_t<std::int64_t>(std::vector<py::ssize_t>{k, 2}, data, capsule_of(std::move(pairs)));
    d["kinds"] = kinds;
  }
  d["candidate_pairs"] = r.candidate_pairs;
  d["predicates"] = r.predicates;
  d["input_converted"] = converted;
  py::dict timings;
  timings["seconds_search"] = r.seconds_search;
  d["timings"] = timings;
  return d;
}

void translate_invalid_input(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const InvalidInput& e) {
    py::object err = py::reinterpret_borrow<py::object>(g_invalid_input)(one_line_text(e.what()));  // one line
    err.attr("field") = e.field();
    err.attr("value") = e.value();
    err.attr("problem") = e.problem();
    err.attr("valid") = e.valid_range();
    PyErr_SetObject(g_invalid_input.ptr(), err.ptr());
  }
}

std::string train_repr(const Train& t) {
  return "GearTrain(a2=" + repr_of(py::str(t.text.a2)) + ", a3=" + repr_of(py::str(t.text.a3)) + ", n=" +
         repr_of(py::str(t.text.n)) + ", phase=" + repr_of(py::str(t.text.phase)) + ")";
}

}  // namespace
}  // namespace sphtroch::python

PYBIND11_MODULE(_sphtroch, m) {
  using namespace sphtroch::python;
  using sphtroch::python::Train;
  m.doc() = "sphtroch: trajectories of spherical planetary gear trains (Lin & Tsai 1990); see __init__.pyi";
  m.attr("__version__") = SPHTROCH_VERSION_STRING;

  static py::exception<sphtroch::InvalidInput> invalid_input(m, "InvalidInput", PyExc_ValueError);
  g_invalid_input = invalid_input;
  invalid_input.attr("__doc__") = "Bad input: .field (the argument), .value (as given), .valid (the valid range), .problem.";
  invalid_input.attr("__module__") = "sphtroch";
  for (const char* a : {"field", "value", "problem", "valid"}) invalid_input.attr(a) = py::none();
  py::register_exception_translator(&translate_invalid_input);
  static py::exception<UncertifiedMarker> uncertified(m, "UncertifiedResult", PyExc_RuntimeError);
  g_uncertified = uncertified;
  uncertified.attr("__doc__") =
      "A node count the two censuses do not agree on (docs/cli.md: Certified counts): .nodes (the polyline census's "
      "uncertified list), .polyline_nodes, .root_nodes.";
  uncertified.attr("__module__") = "sphtroch";

  py::class_<Train>(m, "GearTrain")
      .def(py::init([](py::handle a2, py::handle a3, py::handle n, py::handle phase) { return make_train(a2, a3, n, phase); }),
           py::arg("a2"), py::arg("a3"), py::arg("n"), py::arg("phase") = 0.0)
      .def_property_readonly("a2", [](const Train& t) { return t.train.a2(); })
      .def_property_readonly("a3", [](const Train& t) { return t.train.a3(); })
      .def_property_readonly("n", [](const Train& t) { return t.train.n(); })
      .def_property_readonly("ratio", [](const Train& t) { return t.train.ratio().str(); })
      .def_property_readonly("p", [](const Train& t) { return t.train.ratio().p(); })
      .def_property_readonly("q", [](const Train& t) { return t.train.ratio().q(); })
      .def_property_readonly("phase", [](const Train& t) { return t.train.phase(); })
      .def_property_readonly("planet_cone", [](const Train& t) { return t.train.planet_cone(); })
      .def_property_readonly("sun_cone", [](const Train& t) { return t.train.sun_cone(); })
      .def_property_readonly("period", [](const Train& t) { return t.train.period(); })
      .def_property_readonly("texts", [](const Train& t) {
        return py::make_tuple(t.text.a2, t.text.a3, t.text.n, t.text.phase);
      })
      .def("trace", &trace, py::kw_only(), py::arg("samples") = py::none(), py::arg("turns") = py::none(),
           py::arg("velocity") = false)
      .def("classify", &classify, py::kw_only(), py::arg("literal") = false, py::arg("samples") = py::none())
      .def("nodes", [](const Train& t, py::handle literal, py::handle s) { return nodes_and_cusps(t, literal, s, "nodes"); },
           py::kw_only(), py::arg("literal") = false, py::arg("samples") = py::none())
      .def("cusps", [](const Train& t, py::handle literal, py::handle s) { return nodes_and_cusps(t, literal, s, "cusps"); },
           py::kw_only(), py::arg("literal") = false, py::arg("samples") = py::none())
      .def("classify_roots", &classify_roots_dict, py::kw_only(), py::arg("literal") = false)
      .def("__repr__", &train_repr)
      // Another type: NotImplemented (so train == 5 is False, and the other operand may decide).
      .def("__eq__", [](const Train& a, py::handle other) -> py::object {
        if (!py::isinstance<Train>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
        const Train& b = other.cast<const Train&>();
        return py::bool_(a.text.a2 == b.text.a2 && a.text.a3 == b.text.a3 && a.text.n == b.text.n &&
                         a.text.phase == b.text.phase);
      })
      // Pickling (every protocol, also 0 and 1) calls the constructor again with the four input
      // texts: a tampered pickle is validated like any other input (InvalidInput).
      .def("__reduce__", [](py::object self) {
        const Train& t = self.cast<const Train&>();
        return py::make_tuple(py::type::of(self), py::make_tuple(t.text.a2, t.text.a3, t.text.n, t.text.phase));
      });

  m.def("crossings", &crossings, py::arg("points"), py::arg("closed") = true, py::kw_only(), py::arg("pairs") = false,
        py::arg("max_crossings") = sphtroch::kDefaultMaxCrossings, py::arg("max_work") = sphtroch::kDefaultMaxCrossingWork);
  m.def("atlas", &atlas, py::arg("n"), py::arg("grid") = 128,
        py::arg("a2") = py::make_tuple(0.0, sphtroch::Constants<double>::pi()),
        py::arg("a3") = py::make_tuple(0.0, sphtroch::Constants<double>::pi()), py::arg("threads") = py::none(),
        py::arg("literal") = false);
  m.def("classify_a3_range", &classify_a3_range_list, py::arg("a2"), py::arg("n"), py::arg("a3"),
        py::arg("count") = 721, py::arg("literal") = false);
}
