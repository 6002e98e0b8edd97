// python/src/bind_gear_train.cpp — the class sphtroch.GearTrain (bindings.hpp): its properties,
// trace, classify, nodes, cusps, classify_roots, repr, equality and pickling.
#include "bindings.hpp"
#include "exact_calls.hpp"

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/kinematics.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/mark_density.hpp"
#include "sphtroch/draw/svg.hpp"
#include "sphtroch/draw/svg_plot.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch::python {
namespace {

/// What makes two trains the same train: the doubles a2, a3, the reduced phase, n = p/q, and how a3
/// is given (a reference such as the pitch cone and the offset from it: "ap" stays on the cone
/// whatever a2's rounding, the double it names does not). Texts that read as the same values
/// ("60deg", "pi/3") give equal keys; -0.0 and 0.0 hash alike (Python floats). The phase is the
/// reduced double in [-pi, pi] with -pi taken as pi (one angle); phases that differ by a rounding
/// (0 and the double 2pi, which reduces to -2.4e-16) are different trains.
py::tuple value_key(const Train& t) {
  const GearTrain& g = t.train;
  const double pi = Constants<double>::pi();
  return py::make_tuple(g.a2(), g.a3(), g.phase() == -pi ? pi : g.phase(), g.ratio().p(), g.ratio().q(), static_cast<int>(g.a3_reference()),
                        g.a3_offset(), g.a2_is_right_angle());
}

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

/// tolerance(): `sphtroch tolerance --json` as a dict; half-widths as angles (radians, "0.1deg", ...).
py::object tolerance(const Train& self, py::handle da2, py::handle da3, py::handle dphase, py::handle samples, py::handle seed,
                     py::handle progress_callback) {
  std::string typed;
  const double d2 = angle_arg(da2, "da2", typed), d3 = angle_arg(da3, "da3", typed), dp = angle_arg(dphase, "dphase", typed);
  const std::size_t n = samples.is_none() ? 0 : count_arg(samples, "samples", 1, kMaxToleranceSamples);
  const std::uint64_t s = count_arg(seed, "seed", 0, std::size_t(1) << 62);
  const ParallelProgress progress = interruptible(progress_callback);  // one report per Monte Carlo train
  std::string text;
  {
    py::gil_scoped_release release;  // the half-widths are checked there (InvalidInput "da2", ...)
    text = tolerance_json_text(self.text, self.train, d2, d3, dp, n, s, progress);
  }
  return from_json(text);
}

/// margin(): the certified distance to the nearest boundary of the design map, as a dict.
py::object margin(const Train& self) {
  std::string text;
  {
    py::gil_scoped_release release;
    text = topology_margin_json_text(self.train);
  }
  return from_json(text);
}

/// svg(): `sphtroch plot` as SVG text (the picture options: plot_options_arg).
std::string svg(const Train& self, py::handle view, py::handle size, py::handle labels, py::handle markers,
                py::handle style, py::handle literal_flag, py::handle samples) {
  const PlotOptions options = plot_options_arg(view, size, labels, markers, style);
  const bool literal = flag_arg(literal_flag, "literal");
  const std::size_t s = census_samples_arg(samples);
  py::gil_scoped_release release;
  return plot_svg_text(self.text, self.train, literal, s, options);
}

/// _repr_svg_'s bounds on the census it runs, from the library's cost estimates
/// (core/cost_bounds.hpp): estimated_nodes, |p| (|p| + q) node points (the node lists and their
/// drawing grow with it), and (|p| + q)^3, the classify cost of kMaxToleranceSampleWork (about
/// 0.007 ms a unit, an upper estimate: 1.5e5 is about 1 s there, measured <= 0.05 s for svg()).
/// Within both the picture is svg()'s (13/5, 7/3, 19/7, 40/9); beyond either the census is not run
/// (101/40: 14241 points; 1/1000: (|p| + q)^3 = 1e9, its census ~1.5 s). Measured times:
/// docs/python.md (Jupyter's picture).
constexpr double kReprCensusNodes = 2000;
constexpr double kReprCensusCube = 1.5e5;

bool repr_census_is_cheap(const GearTrain& g) {
  const double size = static_cast<double>(g.ratio().abs_p() + g.ratio().q());
  return estimated_nodes(g.ratio()) <= kReprCensusNodes && size * size * size <= kReprCensusCube;
}

/// The samples of the curve-only picture (beyond the bounds): plot_sample_count capped, drawn
/// with arcs of up to 0.5 rad as single segments, so that sampling and drawing stay within ~0.1 s
/// and the SVG within ~0.6 MB (a curve of thousands of lobes is a band at any sample count that
/// fits a page).
constexpr std::size_t kReprCurveSamples = 8000;

/// A small valid SVG document showing one line of text (the picture of a failure).
std::string message_svg(const std::string& message) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"520\" "
         "height=\"40\" viewBox=\"0 0 520 40\"><text x=\"8\" y=\"24\" font-family=\"sans-serif\" font-size=\"13\">" +
         xml_escape(one_line_text(message)) + "</text></svg>\n";
}

/// The curve alone (no census: no markers, kReprCurveSamples samples at most), its caption saying
/// that the census was not run and what svg() does.
std::string curve_only_svg(const Train& self) {
  const GearTrain& g = self.train;
  const double nodes = estimated_nodes(g.ratio());
  PlotOptions options;
  options.markers = MarkMode::none;
  options.max_arc_step = 0.5;
  options.caption = "a2 = " + self.text.a2 + ", a3 = " + self.text.a3 + ", n = " + g.ratio().str() + self.text.teeth_note() +
                    (g.phase() != 0.0 ? ", phase = " + self.text.phase : "") + " — census not run (about " +
                    number_text(nodes) + " node points); " +
                    (nodes > kMaxCensusNodes ? "beyond the census bound of .svg()" : ".svg() runs it");
  py::gil_scoped_release release;
  const TracerCurve<double> curve(g);
  const std::size_t n = std::min(plot_sample_count(g), kReprCurveSamples);
  return render_sphere_svg(sample(curve, period_sampling(curve, n), false), {}, {}, options);
}

/// Jupyter's picture: svg() when the census is cheap (repr_census_is_cheap), else the curve alone;
/// never raises: a failure (or Ctrl-C) is drawn as its one-line message.
std::string repr_svg(const Train& self) {
  try {
    if (repr_census_is_cheap(self.train))
      return svg(self, py::none(), py::none(), py::str("auto"), py::str("auto"), py::str("curve"), py::bool_(false),
                 py::none());
    return curve_only_svg(self);
  } catch (const py::error_already_set& e) {  // the Python error is held by e and cleared with it
    return message_svg(std::string("sphtroch: ") + e.what());
  } catch (const std::exception& e) {
    return message_svg(std::string("sphtroch: ") + e.what());
  }
}

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
    raise_uncertified(message, all["nodes"], all["polyline_nodes"], all["root_nodes"]);
  }
  return all[key];
}

py::object classify_roots(const Train& self, py::handle literal_flag) {
  const bool literal = flag_arg(literal_flag, "literal");
  std::string text;
  {
    py::gil_scoped_release release;
    text = root_classification_json_text(self.train, literal);
  }
  return from_json(text);
}

std::string train_repr(const Train& t) {
  const std::string ratio = t.text.teeth.empty() ? "n=" + repr_of(py::str(t.text.n)) : "teeth=" + repr_of(py::str(t.text.teeth));
  return "GearTrain(a2=" + repr_of(py::str(t.text.a2)) + ", a3=" + repr_of(py::str(t.text.a3)) + ", " + ratio +
         ", phase=" + repr_of(py::str(t.text.phase)) + ")";
}

/// The largest |t| kinematics() takes: the tool's open-curve range, 1e6 carrier turns (beyond it
/// an ulp of t approaches a degree and n t may overflow).
constexpr double kMaxKinematicsAngle = 2 * 3.141592653589793 * 1e6;

/// kinematics(t): speed, geodesic curvature, tangential acceleration at each carrier angle.
py::dict kinematics(const Train& self, py::handle t) {
  return kinematics_dict(TracerCurve<double>(self.train), t, kMaxKinematicsAngle, "an (N,) array of finite radians, |t| <= 2 pi 1e6");
}

/// report(): the text `sphtroch classify` prints.
std::string report(const Train& self, py::handle literal_flag, py::handle samples) {
  const bool literal = flag_arg(literal_flag, "literal");
  const std::size_t s = census_samples_arg(samples);
  py::gil_scoped_release release;
  return classification_report_text(self.text, self.train, literal, s);
}

/// scene(): a scene's JSON text (or a dict, dumped by json.dumps) run without files.
py::object scene(py::handle scene_arg) {
  const std::string valid = "a scene as JSON text or a dict (docs/cli.md: sphtroch scene)";
  std::string text;
  if (py::isinstance<py::dict>(scene_arg)) {
    try {
      text = py::module_::import("json").attr("dumps")(scene_arg).cast<std::string>();
    } catch (const py::error_already_set& e) {
      throw InvalidInput("scene", repr_of(scene_arg), std::string("not JSON: ") + e.what(), valid);
    }
  } else if (py::isinstance<py::str>(scene_arg)) {
    text = text_arg(scene_arg, "scene", valid);
  } else {
    throw InvalidInput("scene", repr_of(scene_arg), "neither a str nor a dict", valid);
  }
  std::string json;
  {
    py::gil_scoped_release release;
    json = scene_json_text(text);
  }
  return from_json(json);
}

}  // namespace

void bind_gear_train(py::module_& m) {
  m.def("scene", &scene, py::arg("scene"), doc("scene"));
  py::class_<Train>(m, "GearTrain", doc("GearTrain"))
      .def(py::init([](py::handle a2, py::handle a3, py::handle n, py::handle phase, py::handle teeth) {
             return make_train(a2, a3, n, phase, teeth);
           }),
           py::arg("a2"), py::arg("a3"), py::arg("n") = py::none(), py::arg("phase") = 0.0, py::arg("teeth") = py::none(),
           doc("GearTrain.__init__"))
      .def_property_readonly("a2", [](const Train& t) { return t.train.a2(); }, doc("GearTrain.a2"))
      .def_property_readonly("a3", [](const Train& t) { return t.train.a3(); }, doc("GearTrain.a3"))
      .def_property_readonly("n", checked(+[](const Train& t) { return t.train.n(); }), doc("GearTrain.n"))
      .def_property_readonly("ratio", checked(+[](const Train& t) { return t.train.ratio().str(); }), doc("GearTrain.ratio"))
      .def_property_readonly("p", checked(+[](const Train& t) { return t.train.ratio().p(); }), doc("GearTrain.p"))
      .def_property_readonly("q", checked(+[](const Train& t) { return t.train.ratio().q(); }), doc("GearTrain.q"))
      .def_property_readonly("phase", checked(+[](const Train& t) { return t.train.phase(); }), doc("GearTrain.phase"))
      .def_property_readonly("planet_cone", checked(+[](const Train& t) { return t.train.planet_cone(); }), doc("GearTrain.planet_cone"))
      .def_property_readonly("sun_cone", checked(+[](const Train& t) { return t.train.sun_cone(); }), doc("GearTrain.sun_cone"))
      .def_property_readonly("period", checked(+[](const Train& t) { return t.train.period(); }), doc("GearTrain.period"))
      .def_property_readonly("teeth", checked(+[](const Train& t) -> py::object {
        return t.text.teeth.empty() ? py::object(py::none()) : py::object(py::str(t.text.teeth));
      }), doc("GearTrain.teeth"))
      .def_property_readonly("texts", checked(+[](const Train& t) {
        return py::make_tuple(t.text.a2, t.text.a3, t.text.n.empty() ? t.train.ratio().str() : t.text.n, t.text.phase);
      }), doc("GearTrain.texts"))
      .def("trace", checked(&trace), py::kw_only(), py::arg("samples") = py::none(), py::arg("turns") = py::none(),
           py::arg("velocity") = false, doc("GearTrain.trace"))
      .def("classify", checked(&classify), py::kw_only(), py::arg("literal") = false, py::arg("samples") = py::none(), doc("GearTrain.classify"))
      .def("nodes", checked(+[](const Train& t, py::handle literal, py::handle s) { return nodes_and_cusps(t, literal, s, "nodes"); }),
           py::kw_only(), py::arg("literal") = false, py::arg("samples") = py::none(), doc("GearTrain.nodes"))
      .def("cusps", checked(+[](const Train& t, py::handle literal, py::handle s) { return nodes_and_cusps(t, literal, s, "cusps"); }),
           py::kw_only(), py::arg("literal") = false, py::arg("samples") = py::none(), doc("GearTrain.cusps"))
      .def("svg", checked(&svg), py::kw_only(), py::arg("view") = py::none(), py::arg("size") = py::none(),
           py::arg("labels") = "auto", py::arg("markers") = "auto", py::arg("style") = "curve", py::arg("literal") = false, py::arg("samples") = py::none(), doc("GearTrain.svg"))
      .def("_repr_svg_", checked(&repr_svg), doc("GearTrain._repr_svg_"))
      .def("kinematics", checked(&kinematics), py::arg("t"), doc("GearTrain.kinematics"))
      .def("report", checked(&report), py::kw_only(), py::arg("literal") = false, py::arg("samples") = py::none(), doc("GearTrain.report"))
      .def("classify_roots", checked(&classify_roots), py::kw_only(), py::arg("literal") = false, doc("GearTrain.classify_roots"))
      .def("margin", checked(&margin), doc("GearTrain.margin"))
      .def("tolerance", checked(&tolerance), py::kw_only(), py::arg("da2"), py::arg("da3"), py::arg("dphase") = 0.0,
           py::arg("samples") = py::none(), py::arg("seed") = 1, py::arg("progress") = py::none(), doc("GearTrain.tolerance"))
      .def("__repr__", checked(&train_repr))
      // By value (value_key): GearTrain("60deg", ...) == GearTrain("pi/3", ...). Another type:
      // NotImplemented (so train == 5 is False, and the other operand may decide).
      .def("__eq__", checked(+[](const Train& a, py::handle other) -> py::object {
        if (!py::isinstance<Train>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
        return py::bool_(value_key(a).equal(value_key(value_of<Train>(other))));
      }), doc("GearTrain.__eq__"))
      .def("__hash__", checked(+[](const Train& t) { return py::hash(value_key(t)); }), doc("GearTrain.__hash__"))
      // Pickling (every protocol, also 0 and 1) calls the constructor again with the four input
      // texts: a tampered pickle is validated like any other input (InvalidInput).
      .def("__reduce__", [](py::object self) {
        const Train& t = value_of<Train>(self);
        const py::object n = t.text.teeth.empty() ? py::object(py::str(t.text.n)) : py::object(py::none());
        const py::object teeth = t.text.teeth.empty() ? py::object(py::none()) : py::object(py::str(t.text.teeth));
        return py::make_tuple(py::type::of(self), py::make_tuple(t.text.a2, t.text.a3, n, t.text.phase, teeth));
      });
}

}  // namespace sphtroch::python
