// python/src/bindings.hpp — what the binding files of the extension module sphtroch._sphtroch share:
// the argument converters (arguments.cpp), the exception classes (bind_errors.cpp) and one bind_*
// function in each of seven topic files (bind_gear_train.cpp, bind_design_map.cpp, bind_crossings.cpp,
// bind_synthesis.cpp, bind_clinostat.cpp, bind_chain.cpp, bind_wrist.cpp), called by module.cpp.
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
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/kinematics.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/draw/svg_plot.hpp"  // PlotOptions
#include "sphtroch/io/train_text.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch::python {

namespace py = pybind11;

// --- docstrings (arguments.cpp) -------------------------------------------------------------
/// The docstring the stub (python/sphtroch/__init__.pyi, the one source) gives `name` ("atlas",
/// "GearTrain", "GearTrain.trace"), from the header python/gen_docstrings.py generates at build
/// time. Throws std::logic_error for a name the stub does not have (the import fails: the stub
/// and the bindings cannot drift apart). For a function: CPython's text signature block
/// ("name(a, *, b=None)\n--\n\n", read into __text_signature__ for inspect.signature), the
/// stub's typed signature line(s), then the docstring; module.cpp turns pybind11's own signature
/// lines off, so help() shows these.
const char* doc(const char* name);
/// The same without the text signature block: for functions defined in Python (python/sphtroch/*.py).
const char* python_doc(const char* name);

// --- bind_errors.cpp -----------------------------------------------------------------------
/// sphtroch.InvalidInput (a ValueError) and sphtroch.UncertifiedResult (a RuntimeError), with the
/// translator that raises the first for the library's InvalidInput.
void bind_errors(py::module_& m);
/// Raises sphtroch.UncertifiedResult(message) carrying .nodes, .polyline_nodes and .root_nodes.
[[noreturn]] void raise_uncertified(const std::string& message, py::handle nodes, py::handle polyline_nodes,
                                    py::handle root_nodes);

// --- arguments.cpp: Python values -> C++ values, else InvalidInput naming the argument -----
// The one home of argument conversion: no binding casts a user's value with pybind11 (whose
// failures are RuntimeError / TypeError) or lets NumPy convert text, bool or complex silently.
std::string repr_of(py::handle v);
/// Not a number whatever float() or __index__ would make of it: bool and numpy.bool_, None, text,
/// complex numbers, NumPy values of a dtype other than integer or float.
bool not_a_real(py::handle v);
/// A str as UTF-8, else InvalidInput: "not a string", or not encodable (a lone surrogate "\ud800").
std::string text_arg(py::handle v, const std::string& field, const std::string& valid);
/// A flag: True or False (also numpy.bool_); truthy objects ("yes", 1, None) are refused.
bool flag_arg(py::handle v, const std::string& field);
/// A real number (anything float() accepts: int, float, NumPy integer and float scalars, Fraction),
/// except bool and numpy.bool_, None, str and bytes, complex (also NumPy's) and NumPy values of
/// another dtype (a 0-d text array).
double real_arg(py::handle v, const std::string& field, const std::string& valid);
/// A whole number in [lo, hi] (int or any integer type with __index__; not bool or numpy.bool_).
std::size_t count_arg(py::handle v, const std::string& field, std::size_t lo, std::size_t hi);
/// None (nullopt), or count_arg(v, field, lo, hi).
std::optional<std::size_t> optional_count_arg(py::handle v, const std::string& field, std::size_t lo, std::size_t hi);
/// (P, Q): a sequence of exactly two whole numbers in [lo, hi] (not text); InvalidInput names the whole value.
std::pair<std::size_t, std::size_t> count_pair_arg(py::handle v, const std::string& field, std::size_t lo, std::size_t hi);
/// A C-contiguous float64 NumPy array.
using RealArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
/// An array argument as RealArray: the same object when it already is one, anything array-like
/// converted once (numpy.asarray); else InvalidInput(field, .., valid). Only integer and float
/// dtypes: text (NumPy would parse "1.5"), bool, complex (its imaginary part would be dropped) and
/// object arrays are refused. The shape is the caller's to check (shape_text names it).
RealArray real_array_arg(py::handle v, const std::string& field, const std::string& valid);
/// "array of shape (N, 3)", an array's shape as InvalidInput's value.
std::string shape_text(const py::array& a);
/// The exact rates a chain or a wrist's coupling takes, as InvalidInput's valid forms.
extern const char* const kExactRateForms;
/// One exact rate as the CLI's text (io/chain_text.hpp reads it): a str as given, an integer's
/// digits, a Fraction's "p/q", a float's repr; InvalidInput(field) for bool, None, complex, text arrays.
std::string exact_rate_text(py::handle v, const std::string& field);
/// A list argument as the CLI's text: a str is that text already; a sequence (list, tuple, 1-D
/// array) of at most max_items gives one item per element, turned into text by `item` and joined
/// by `separator`; an item holding the separator or ';' is refused. InvalidInput(field, .., valid) otherwise.
std::string list_text(py::handle v, const std::string& field, const std::string& valid,
                      const std::function<std::string(py::handle)>& item, std::size_t max_items, const char* separator = ",");
/// An angle: radians as a real number, or the CLI's text; `text` receives the text kept for reports.
double angle_arg(py::handle v, const std::string& field, std::string& text);
/// a3: an angle, or the CLI's cone references ("ap", "pi-ap+1e-6").
A3Spec a3_arg(py::handle v, std::string& text);
/// n: an integer, a Fraction, the CLI's text, or a float that is a short decimal.
Ratio ratio_arg(py::handle v);
/// A speed in rpm as the text io's parse_rpm reads (machine/clinostat_text.hpp): a str as given, an
/// integer's digits, a Fraction's "p/q", a float's repr ("1.33"); InvalidInput(field) for other types.
std::string rpm_text_arg(py::handle v, const std::string& field);
/// (lo, hi) of angles, or the CLI's "LO:HI" text.
std::pair<double, double> range_arg(py::handle v, const std::string& field);
/// svg()'s picture options (GearTrain.svg, Chain.svg): view "auto", "top", "front", "side",
/// "AZ,EL" or (az, el) angles; size 64 .. 8192; labels, markers, style as `sphtroch plot` reads them.
PlotOptions plot_options_arg(py::handle view, py::handle size, py::handle labels, py::handle markers, py::handle style);
/// The census's samples: None (the default count) or a count in [kMinCensusSamples, kMaxSamples].
std::size_t census_samples_arg(py::handle samples);

/// kinematics(t) of GearTrain and Chain: {"speed", "geodesic_curvature", "tangential_acceleration"}
/// (core/kinematics.hpp's path_kinematics of `curve`, built with the GIL released) at the
/// parameters t, a 1-D array of finite numbers with |t| <= max_abs; else InvalidInput("t", .., valid).
template <typename Curve>
py::dict kinematics_dict(const Curve& curve, py::handle t_arg, double max_abs, const std::string& valid) {
  const RealArray t = real_array_arg(t_arg, "t", valid);
  if (t.ndim() != 1) throw InvalidInput("t", shape_text(t), "not a 1-D array", valid);
  const std::vector<double> in(t.data(), t.data() + t.shape(0));  // copied with the GIL held
  for (std::size_t i = 0; i < in.size(); ++i)
    if (!(std::fabs(in[i]) <= max_abs))
      throw InvalidInput("t", "t[" + std::to_string(i) + "] = " + number_text(in[i]), "not finite or too large", valid);
  const std::size_t n = in.size();
  py::array_t<double> speed(n), curvature(n), tangential(n);
  double *s = speed.mutable_data(), *k = curvature.mutable_data(), *a = tangential.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) {
      const PathKinematics pk = path_kinematics(curve, in[i]);
      s[i] = pk.speed, k[i] = pk.geodesic_curvature, a[i] = pk.tangential_acceleration;
    }
  }
  py::dict d;
  d["speed"] = speed;
  d["geodesic_curvature"] = curvature;
  d["tangential_acceleration"] = tangential;
  return d;
}

/// The fewest milliseconds between two reports of a progress callback (the last one, done ==
/// total, always goes through).
constexpr int kProgressIntervalMs = 100;
/// The progress of a long call (atlas, boundary_loci, synth_points, fit), run on the calling
/// thread with the GIL taken only while it runs: Ctrl-C (PyErr_CheckSignals) raises
/// KeyboardInterrupt out of the call at every report; the user's `callback` is reported to at most
/// once per kProgressIntervalMs and always at done == total: a function as callback(done, total),
/// a bar (an object with .update, e.g. tqdm) by setting .total when it differs and calling
/// .update(done - its count so far). An exception it raises stops the call and propagates.
/// Throws InvalidInput("progress") unless callback is None, callable or has .update.
ParallelProgress interruptible(py::handle callback);

/// A gear train and the text of its inputs (TrainText: a2, a3, n, phase, as classify --json reports them).
struct Train {
  GearTrain train;
  TrainText text;
};
/// The train of GearTrain(a2, a3, n, phase, teeth): exactly one of n and teeth (not None).
Train make_train(py::handle a2, py::handle a3, py::handle n, py::handle phase, py::handle teeth);

/// A capsule owning `owner`: the base of arrays viewing its data, deleting it with the last of them.
template <typename Owner>
py::capsule capsule_of(std::unique_ptr<Owner> owner) {
  return py::capsule(owner.release(), [](void* p) { delete static_cast<Owner*>(p); });
}

/// JSON text -> Python objects (json.loads), so the dicts are exactly the CLI's JSON.
py::object from_json(const std::string& text);

/// The C++ value behind a bound object (GearTrain, Chain, Clinostat); InvalidInput("self") when
/// the object was made by __new__ without __init__ (Chain.__new__(Chain), or a pickle's NEWOBJ):
/// pybind11 would hand such a method uninitialised memory.
template <typename T>
const T& value_of(py::handle self) {
  auto* inst = reinterpret_cast<py::detail::instance*>(self.ptr());
  py::detail::value_and_holder vh = inst->get_value_and_holder(py::detail::get_type_info(typeid(T)));
  if (!vh.holder_constructed())
    throw InvalidInput("self", py::str(py::type::of(self).attr("__name__")).cast<std::string>() + " object without __init__",
                       "not initialised", "an object made by calling the class");
  return *static_cast<const T*>(vh.value_ptr());
}

/// A method bound through value_of: f(const T&, args...) as g(self, args...).
template <typename T, typename R, typename... A>
auto checked(R (*f)(const T&, A...)) {
  return [f](py::handle self, A... args) -> R { return f(value_of<T>(self), args...); };
}

// --- one function per topic ----------------------------------------------------------------
void bind_gear_train(py::module_& m);  // class GearTrain: trace, classify, nodes, cusps, classify_roots
void bind_design_map(py::module_& m);  // classify_a3_range, atlas
void bind_crossings(py::module_& m);   // crossings
void bind_synthesis(py::module_& m);   // identify
void bind_clinostat(py::module_& m);   // class Clinostat: gravity, window means, time to epsilon, coverage
void bind_chain(py::module_& m);       // class Chain: a rotation chain's trace, kinematics, classify, nodes, cusps, report
void bind_wrist(py::module_& m);       // class Wrist: a geared wrist's ik, cap, atlas

}  // namespace sphtroch::python
