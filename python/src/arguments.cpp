// python/src/arguments.cpp — Python values to C++ values (bindings.hpp), each refusal an
// InvalidInput naming the argument with its valid range.
#include "bindings.hpp"
#include "docstrings.hpp"  // generated: python/gen_docstrings.py

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/mark_density.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/machine/clinostat_text.hpp"

#include <algorithm>
#include <functional>
#include <chrono>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sphtroch::python {

std::string repr_of(py::handle v) { return py::repr(v).cast<std::string>(); }

namespace {

/// numpy (from sys.modules after the first call).
py::module_ numpy() { return py::module_::import("numpy"); }

/// The dtype kind of a NumPy scalar or array ('b' bool, 'i'/'u' integer, 'f' float, 'c' complex,
/// 'U'/'S' text, 'O' object, ...), or 0 for any other object.
char numpy_kind(py::handle v) {
  const py::module_ np = numpy();
  if (!py::isinstance(v, np.attr("generic")) && !py::isinstance<py::array>(v)) return 0;
  return py::dtype::from_args(v.attr("dtype")).kind();
}

}  // namespace

/// Not a number whatever float() or __index__ would make of it: bool and numpy.bool_, None, text
/// (str, bytes), complex numbers (also NumPy's), and NumPy values of a dtype other than integer or
/// float (a 0-d text array).
bool not_a_real(py::handle v) {
  if (v.is_none() || py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v) ||
      PyByteArray_Check(v.ptr()) || PyComplex_Check(v.ptr()))
    return true;
  const char kind = numpy_kind(v);
  return kind != 0 && kind != 'i' && kind != 'u' && kind != 'f';
}

/// A str as UTF-8, else InvalidInput: "not a string" (bytes, numbers, arrays), or not encodable
/// (a lone surrogate such as "\ud800").
std::string text_arg(py::handle v, const std::string& field, const std::string& valid) {
  if (!py::isinstance<py::str>(v)) throw InvalidInput(field, repr_of(v), "not a string", valid);
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
  if (py::isinstance(v, numpy().attr("bool_"))) return PyObject_IsTrue(v.ptr()) == 1;
  throw InvalidInput(field, repr_of(v), "not a flag", "True or False");
}

/// A real number (anything float() accepts), else InvalidInput: bool, None, text and complex
/// numbers are refused (NumPy's complex would lose its imaginary part, numpy.bool_ read as 1).
double real_arg(py::handle v, const std::string& field, const std::string& valid) {
  if (not_a_real(v)) throw InvalidInput(field, repr_of(v), "not a real number", valid);
  PyObject* f = PyNumber_Float(v.ptr());
  if (f == nullptr) {
    PyErr_Clear();
    throw InvalidInput(field, repr_of(v), "not a real number", valid);
  }
  const double x = PyFloat_AsDouble(f);
  Py_DECREF(f);
  return x;
}

namespace {

/// The value of a whole number (int or any integer type with __index__; not bool or numpy.bool_):
/// false when v is none; `overflow` when it does not fit a long long.
bool whole_number(py::handle v, long long& x, bool& overflow) {
  if (not_a_real(v) || !PyIndex_Check(v.ptr())) return false;
  PyObject* i = PyNumber_Index(v.ptr());
  if (i == nullptr) {
    PyErr_Clear();
    return false;
  }
  int o = 0;
  x = PyLong_AsLongLongAndOverflow(i, &o);
  Py_DECREF(i);
  overflow = o != 0;
  return true;
}

std::string count_range(std::size_t lo, std::size_t hi) {
  return hi >= static_cast<std::size_t>(std::numeric_limits<long long>::max())
             ? "integer >= " + std::to_string(lo)
             : "integer " + std::to_string(lo) + " .. " + std::to_string(hi);
}

}  // namespace

/// A whole number in [lo, hi] (int or any integer type with __index__; not bool), else InvalidInput.
std::size_t count_arg(py::handle v, const std::string& field, std::size_t lo, std::size_t hi) {
  const std::string valid = count_range(lo, hi);
  long long x = 0;
  bool overflow = false;
  if (!whole_number(v, x, overflow)) throw InvalidInput(field, repr_of(v), "not a whole number", valid);
  if (overflow || x < 0 || static_cast<unsigned long long>(x) < lo || static_cast<unsigned long long>(x) > hi)
    throw InvalidInput(field, repr_of(v), "outside the valid range", valid);
  return static_cast<std::size_t>(x);
}

std::optional<std::size_t> optional_count_arg(py::handle v, const std::string& field, std::size_t lo, std::size_t hi) {
  if (v.is_none()) return std::nullopt;
  try {
    return count_arg(v, field, lo, hi);
  } catch (const InvalidInput& e) {
    throw InvalidInput(field, e.value(), e.problem(), "None or " + e.valid_range());
  }
}

std::pair<std::size_t, std::size_t> count_pair_arg(py::handle v, const std::string& field, std::size_t lo, std::size_t hi) {
  const std::string valid = "(P, Q), two integers " + std::to_string(lo) + " .. " + std::to_string(hi);
  if (py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v) || PyByteArray_Check(v.ptr()) ||
      !py::isinstance<py::sequence>(v) || py::len(v) != 2)
    throw InvalidInput(field, repr_of(v), "not a pair of whole numbers", valid);
  const py::sequence s = py::reinterpret_borrow<py::sequence>(v);
  std::size_t k[2] = {0, 0};
  for (std::size_t i = 0; i < 2; ++i) {
    long long x = 0;
    bool overflow = false;
    if (!whole_number(s[i], x, overflow)) throw InvalidInput(field, repr_of(v), "not a pair of whole numbers", valid);
    if (overflow || x < 0 || static_cast<unsigned long long>(x) < lo || static_cast<unsigned long long>(x) > hi)
      throw InvalidInput(field, repr_of(v), "outside the valid range", valid);
    k[i] = static_cast<std::size_t>(x);
  }
  return {k[0], k[1]};
}

std::string shape_text(const py::array& a) {
  std::string s = "array of shape (";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

RealArray real_array_arg(py::handle v, const std::string& field, const std::string& valid) {
  const auto type_name = [&] { return "a " + std::string(py::str(py::type::of(v).attr("__name__"))); };
  if (v.is_none()) throw InvalidInput(field, "None", "not an array", valid);
  py::object arr = py::reinterpret_borrow<py::object>(v);
  if (!py::isinstance<py::array>(v)) {
    try {
      arr = numpy().attr("asarray")(v);
    } catch (const py::error_already_set&) {
      throw InvalidInput(field, type_name(), "not convertible to an array", valid);
    }
  }
  // Only integer and float dtypes: NumPy's cast would parse text ("1.5"), drop imaginary parts,
  // and read bool and objects as numbers.
  const py::dtype dt = py::reinterpret_borrow<py::array>(arr).dtype();
  if (dt.kind() != 'f' && dt.kind() != 'i' && dt.kind() != 'u')
    throw InvalidInput(field, "an array of dtype " + std::string(py::str(py::handle(dt))), "not numeric real (integer or float)",
                       valid);
  RealArray a = RealArray::ensure(arr);  // the same object when already C-contiguous float64
  if (!a) {
    PyErr_Clear();
    throw InvalidInput(field, type_name(), "not convertible to a float64 array", valid);
  }
  return a;
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
  if (not_a_real(v)) throw InvalidInput("n", repr_of(v), "not a gear ratio", kRatioForms);
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

/// A speed: a str as given; an integer (not bool) as its digits; a Fraction (integer numerator and
/// denominator) as "p/q"; any other real number as the repr of its float, so that 1.33 is read as
/// "1.33" = 133/100 rpm. parse_rpm then reads it exactly (and refuses what it refuses).
std::string rpm_text_arg(py::handle v, const std::string& field) {
  if (py::isinstance<py::str>(v)) return text_arg(v, field, kRpmForms);
  if (not_a_real(v)) throw InvalidInput(field, repr_of(v), "not a speed", kRpmForms);
  if (PyIndex_Check(v.ptr())) {
    PyObject* i = PyNumber_Index(v.ptr());
    if (i == nullptr) {
      PyErr_Clear();
      throw InvalidInput(field, repr_of(v), "not a speed", kRpmForms);
    }
    return py::str(py::reinterpret_steal<py::object>(i)).cast<std::string>();
  }
  if (py::hasattr(v, "numerator") && py::hasattr(v, "denominator") && !py::isinstance<py::float_>(v)) {
    const py::object p = v.attr("numerator"), q = v.attr("denominator");
    if (!PyIndex_Check(p.ptr()) || !PyIndex_Check(q.ptr())) throw InvalidInput(field, repr_of(v), "not a speed", kRpmForms);
    return py::str(py::int_(p)).cast<std::string>() + "/" + py::str(py::int_(q)).cast<std::string>();
  }
  return repr_of(py::float_(real_arg(v, field, kRpmForms)));
}

/// (lo, hi) of angles (radians or the CLI's text), or the CLI's "LO:HI" text, field `field`.
std::pair<double, double> range_arg(py::handle v, const std::string& field) {
  const std::string valid = "(lo, hi) with angles as numbers (radians) or text (\"pi/3\"), or \"LO:HI\"";
  if (py::isinstance<py::str>(v)) {
    const AngleRange r = parse_angle_range(text_arg(v, field, kAngleRangeForms), field, kAngleRangeForms);
    return {r.lo, r.hi};
  }
  if (py::isinstance<py::bytes>(v) || PyByteArray_Check(v.ptr()) || !py::isinstance<py::sequence>(v) || py::len(v) != 2)
    throw InvalidInput(field, repr_of(v), "not a pair (lo, hi)", valid);
  const py::sequence s = py::reinterpret_borrow<py::sequence>(v);
  std::string ignored;
  return {angle_arg(s[0], field, ignored), angle_arg(s[1], field, ignored)};
}

std::size_t census_samples_arg(py::handle samples) {
  return samples.is_none() ? 0 : count_arg(samples, "samples", kMinCensusSamples, kMaxSamples);
}

/// n, or teeth "ZS:ZP" (kept in t.text.teeth, n's text then empty, as TrainText has it).
Ratio ratio_or_teeth_arg(py::handle n, py::handle teeth, TrainText& text) {
  const char* const teeth_valid = "tooth counts 'ZS:ZP', sun:planet ('39:15' is n = 13/5; ZS < 0: internal)";
  if (teeth.is_none()) {
    if (n.is_none()) throw InvalidInput("n", "None", "not given", std::string(kRatioForms) + ", or teeth='ZS:ZP'");
    const Ratio nv = ratio_arg(n);
    text.n = nv.str();
    return nv;
  }
  if (!n.is_none()) throw InvalidInput("teeth", repr_of(teeth), "given together with n = " + repr_of(n), "one of n and teeth");
  const Teeth z = parse_teeth(text_arg(teeth, "teeth", teeth_valid), "teeth");
  text.teeth = z.str();
  return z.ratio();
}

Train make_train(py::handle a2, py::handle a3, py::handle n, py::handle phase, py::handle teeth) {
  Train t;
  const double a2v = angle_arg(a2, "a2", t.text.a2);
  const A3Spec a3v = a3_arg(a3, t.text.a3);
  const Ratio nv = ratio_or_teeth_arg(n, teeth, t.text);
  const double phv = angle_arg(phase, "phase", t.text.phase);
  t.train = make_gear_train(a2v, a3v, nv, phv);
  return t;
}

/// JSON text -> Python objects (json.loads), so the dicts are exactly the CLI's JSON.
py::object from_json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

namespace {

const stub_docs::Entry& stub_entry(const char* name) {
  for (const stub_docs::Entry& e : stub_docs::kEntries)
    if (std::string_view(e.name) == name) return e;
  throw std::logic_error(std::string("sphtroch: no docstring for ") + name + " in python/sphtroch/__init__.pyi");
}

}  // namespace

const char* doc(const char* name) { return stub_entry(name).builtin; }

const char* python_doc(const char* name) { return stub_entry(name).python; }

namespace {

/// What interruptible() calls: a function f(done, total), a bar (tqdm: .total set, .update(delta)),
/// or nothing (None: only the signal check). Held by a shared holder released with the GIL.
struct ProgressTarget {
  py::object target;
  bool bar = false;
  std::size_t shown = 0;  // the bar's count so far
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
};

}  // namespace

ParallelProgress interruptible(py::handle callback) {
  const bool bar = !callback.is_none() && py::hasattr(callback, "update");
  if (!callback.is_none() && !bar && !PyCallable_Check(callback.ptr()))
    throw InvalidInput("progress", repr_of(callback), "neither callable nor a progress bar",
                       "None, a function progress(done, total) or a bar with .update(n) and .total (tqdm)");
  // The std::function is copied around without the GIL: the object is kept in a shared holder
  // whose last copy is released with the GIL held.
  auto holder = std::shared_ptr<ProgressTarget>(new ProgressTarget{py::reinterpret_borrow<py::object>(callback), bar},
                                                [](ProgressTarget* o) {
                                                  py::gil_scoped_acquire acquire;
                                                  delete o;
                                                });
  return [holder](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    ProgressTarget& p = *holder;
    const auto now = std::chrono::steady_clock::now();
    if (p.target.is_none() || (done < total && now - p.last < std::chrono::milliseconds(kProgressIntervalMs))) return;
    p.last = now;
    if (!p.bar) {
      p.target(done, total);
      return;
    }
    const py::object shown_total = p.target.attr("total");
    if (shown_total.is_none() || !shown_total.equal(py::int_(total))) p.target.attr("total") = total;
    if (done > p.shown) p.target.attr("update")(done - p.shown);
    p.shown = std::max(p.shown, done);
  };
}

/// The picture options of svg(): view "auto", "top", "front", "side", "AZ,EL" or (az, el) angles;
/// size 64 .. 8192 px; labels, markers, style as `sphtroch plot` reads them.
PlotOptions plot_options_arg(py::handle view, py::handle size, py::handle labels, py::handle markers, py::handle style) {
  PlotOptions options;
  const char* const views = "auto, top, front, side, \"AZ,EL\" or (az, el) angles, el in [-pi/2, pi/2]";
  if (py::isinstance<py::tuple>(view) || py::isinstance<py::list>(view)) {
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(view);
    if (pair.size() != 2) throw InvalidInput("view", repr_of(view), "not a view", views);
    std::string ignored;
    set_plot_view(options, number_text(angle_arg(pair[0], "view", ignored)) + "," + number_text(angle_arg(pair[1], "view", ignored)));
  } else if (!view.is_none()) {
    set_plot_view(options, text_arg(view, "view", views));
  }
  if (!size.is_none()) options.size_px = static_cast<double>(count_arg(size, "size", 64, 8192));
  options.labels = parse_plot_labels(text_arg(labels, "labels", "auto, numbers, none"));
  options.markers = parse_mark_mode(text_arg(markers, "markers", "auto, all, none"));
  options.style = parse_plot_style(text_arg(style, "style", "curve, density"));
  return options;
}


const char* const kExactRateForms =
    "exact rates: int, fractions.Fraction, text (\"-2/3\", \"1.5\", \"0\") or a float that is a short decimal, |p|, q <= 1e6 in lowest terms";

std::string exact_rate_text(py::handle v, const std::string& field) {
  if (py::isinstance<py::str>(v)) return text_arg(v, field, kExactRateForms);
  if (not_a_real(v)) throw InvalidInput(field, repr_of(v), "not a rate", kExactRateForms);  // bool, None, complex, ...
  if (PyIndex_Check(v.ptr()) && !py::isinstance<py::array>(v)) {
    PyObject* i = PyNumber_Index(v.ptr());
    if (i != nullptr) return py::str(py::reinterpret_steal<py::object>(i)).cast<std::string>();
    PyErr_Clear();
  }
  if (py::hasattr(v, "numerator") && py::hasattr(v, "denominator") && !py::isinstance<py::float_>(v)) {
    const py::object p = v.attr("numerator"), q = v.attr("denominator");
    if (PyIndex_Check(p.ptr()) && PyIndex_Check(q.ptr()) && !PyBool_Check(v.ptr()))
      return py::str(py::int_(p)).cast<std::string>() + "/" + py::str(py::int_(q)).cast<std::string>();
  }
  return repr_of(py::float_(real_arg(v, field, kExactRateForms)));
}

std::string list_text(py::handle v, const std::string& field, const std::string& valid,
                      const std::function<std::string(py::handle)>& item, std::size_t max_items, const char* separator) {
  if (py::isinstance<py::str>(v)) return text_arg(v, field, valid);
  if (py::isinstance<py::bytes>(v) || !PySequence_Check(v.ptr()) || py::isinstance<py::dict>(v))
    throw InvalidInput(field, repr_of(v), "not a list", valid);
  if (py::isinstance<py::array>(v) && py::reinterpret_borrow<py::array>(v).ndim() != 1)
    throw InvalidInput(field, shape_text(py::reinterpret_borrow<py::array>(v)), "not a 1-D list", valid);
  std::vector<py::object> items;
  try {  // a sequence whose len() or [] raises is a bad argument, not the caller's exception
    const py::sequence seq = py::reinterpret_borrow<py::sequence>(v);
    const std::size_t n = seq.size();
    if (n > max_items)
      throw InvalidInput(field, std::to_string(n) + " items", "too many items", valid + " (at most " + std::to_string(max_items) + ")");
    for (std::size_t i = 0; i < n; ++i) items.push_back(seq[i]);
  } catch (const py::error_already_set& e) {
    const std::string raised = py::str(e.type().attr("__name__")).cast<std::string>() + " " + py::str(e.value()).cast<std::string>();
    throw InvalidInput(field, repr_of(py::type::of(v)), "not a list (it raised " + raised + ")", valid);
  }
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string one = item(items[i]);
    if (one.find(separator) != std::string::npos || one.find(';') != std::string::npos)
      throw InvalidInput(field, repr_of(items[i]), "one item holds a separator", valid);
    text += (i ? separator : "") + one;
  }
  return text;
}

}  // namespace sphtroch::python
