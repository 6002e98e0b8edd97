// python/src/bind_clinostat.cpp — the class sphtroch.Clinostat (bindings.hpp): a two-axis clinostat's
// gravity, its window means, the worst window mean, the time to epsilon, the dwell map (HEALPix)
// and the gear train of its path, with the numbers `sphtroch clinostat --json` prints
// (src/cli/clinostat_command.cpp): the same library calls on the same settings.
//
// Decisions
//  * The settings go through the CLI's own reader (machine/clinostat_text.hpp): speeds as the
//    text parse_rpm reads (rpm_text_arg), angles and the offset as the shortest text of their
//    doubles, which reads back as the same doubles. So every refusal is the CLI's, naming its
//    option ("outer", "frame-angle", ...), and the machine is the one the CLI builds.
//  * The averages (period, mean over a period, window means, M(W), time to epsilon) are of the
//    effective gravity when an offset is given, else of g_s, as the CLI's report; the train and
//    the dwell map are of g_s.
//  * The gear train is computed once, with the machine; the object is immutable and every
//    computation runs with the GIL released.
#include "bindings.hpp"

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/machine/clinostat_report.hpp"
#include "sphtroch/machine/clinostat_text.hpp"
#include "sphtroch/machine/clinostat_train.hpp"
#include "sphtroch/machine/time_to_epsilon.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch::python {
namespace {

/// A machine and what the CLI's report computes once for it.
struct Machine {
  Clinostat machine;
  GravitySeries averaged;          ///< of the effective gravity with an offset, else of g_s
  ClinostatTrain train;            ///< the train and its map (train empty: reason)
  std::optional<Train> gear_train; ///< train.train as the Python GearTrain
  bool offset_given = false;
};

/// Degrees as the text ClinostatText reads: the shortest text of the double (the same double back).
std::string degrees_text(py::handle v, const char* field, const char* valid) { return number_text(real_arg(v, field, valid)); }

/// The offset as "X,Y,Z" text (ClinostatText), "" for None.
std::string offset_text(py::handle v) {
  if (v.is_none()) return "";
  const std::string valid = "None or (x, y, z) in metres (sample frame), |r| <= 10";
  const RealArray a = real_array_arg(v, "offset", valid);
  if (a.ndim() != 1 || a.shape(0) != 3) throw InvalidInput("offset", shape_text(a), "not three numbers X,Y,Z", valid);
  return number_text(a.data()[0]) + "," + number_text(a.data()[1]) + "," + number_text(a.data()[2]);
}

/// The GearTrain of a clinostat's train, its texts the shortest text of its doubles (so that it
/// prints, compares and pickles as GearTrain(a2, a3, n, phase) of those doubles).
Train python_train(const GearTrain& g) {
  TrainText text;
  text.a2 = number_text(g.a2());
  text.a3 = number_text(g.a3());
  text.n = g.ratio().str();
  text.phase = number_text(g.phase_given());
  return Train{g, text};
}

Machine make_machine(py::handle outer, py::handle inner, py::handle tilt, py::handle frame_angle, py::handle phase_outer,
                     py::handle phase_inner, py::handle offset, py::handle gravity) {
  ClinostatText text;
  text.outer = rpm_text_arg(outer, "outer");
  text.inner = rpm_text_arg(inner, "inner");
  text.tilt = degrees_text(tilt, "tilt", "[0, 180] degrees");
  text.frame_angle = degrees_text(frame_angle, "frame-angle", "[0, 180] degrees");
  text.phase_outer = degrees_text(phase_outer, "phase-outer", "|phase| <= 1e6 degrees");
  text.phase_inner = degrees_text(phase_inner, "phase-inner", "|phase| <= 1e6 degrees");
  text.offset = offset_text(offset);
  text.gravity = number_text(real_arg(gravity, "gravity", "(0, 1000] g0"));  // its range: Clinostat's constructor
  const Clinostat m(text.settings());  // InvalidInput naming the CLI's option
  GravitySeries averaged = m.has_offset() ? GravitySeries::of_effective_gravity(m) : GravitySeries::of_gravity(m);
  ClinostatTrain train = clinostat_train(m);  // empty with the reason where no GearTrain draws the path
  std::optional<Train> gear_train;
  if (train.train) gear_train = python_train(*train.train);
  return Machine{m, std::move(averaged), std::move(train), std::move(gear_train), !offset.is_none()};
}

/// A time in seconds, |t| <= 1e12 (the CLI's --start), else InvalidInput(field).
double time_arg(py::handle v, const char* field) {
  const double t = real_arg(v, field, "|t| <= 1e12 seconds");
  if (!(std::fabs(t) <= Clinostat::kMaxTime)) throw InvalidInput(field, number_text(t), "not a finite time", "|t| <= 1e12 seconds");
  return t;
}

/// A number in (0, max], else InvalidInput(field) as the CLI's options --window, --epsilon, ...
double positive_arg(py::handle v, const char* field, double max, const char* valid) {
  const double x = real_arg(v, field, valid);
  if (!(x > 0) || x > max) throw InvalidInput(field, number_text(x), "not a positive number in range", valid);
  return x;
}

py::array_t<double> vector_array(const Vector3d& v) { return py::array_t<double>(3, v.data()); }

py::object or_none(const std::optional<double>& v) { return v ? py::object(py::float_(*v)) : py::object(py::none()); }

/// g_s (or the effective gravity) at the times t: (3,) for a scalar, (N, 3) for an (N,) array.
py::array_t<double> gravity_at_times(const Machine& self, py::handle t_arg, bool effective) {
  const std::string valid = "seconds, |t| <= 1e12: a number or an (N,) array";
  const RealArray t = real_array_arg(t_arg, "t", valid);
  if (t.ndim() > 1) throw InvalidInput("t", shape_text(t), "not a number or a 1-D array of times", valid);
  const std::size_t n = t.ndim() == 0 ? 1 : static_cast<std::size_t>(t.shape(0));
  const std::vector<double> times(t.data(), t.data() + n);  // copied with the GIL held
  for (std::size_t i = 0; i < n; ++i)
    if (!(std::fabs(times[i]) <= Clinostat::kMaxTime))
      throw InvalidInput("t", (t.ndim() == 0 ? "" : "t[" + std::to_string(i) + "] = ") + number_text(times[i]), "not a finite time",
                         valid);
  py::array_t<double> out = t.ndim() == 0 ? py::array_t<double>(3)
                                          : py::array_t<double>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), 3});
  double* o = out.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) {
      const Vector3d g = effective ? self.machine.effective_gravity(times[i]) : self.machine.gravity(times[i]);
      o[3 * i] = g.x(), o[3 * i + 1] = g.y(), o[3 * i + 2] = g.z();
    }
  }
  return out;
}

py::array_t<double> window_mean(const Machine& self, py::handle t0_arg, py::handle window_arg) {
  const double t0 = time_arg(t0_arg, "t0");
  const char* const valid = "seconds in [0, 1e9]";
  const double w = real_arg(window_arg, "window", valid);
  if (!(w >= 0 && w <= 1e9)) throw InvalidInput("window", number_text(w), "not a window length in range", valid);
  Vector3d mean;
  {
    py::gil_scoped_release release;
    mean = self.averaged.window_mean(t0, w);
  }
  return vector_array(mean);
}

/// M(W): `--window W --json`'s "worst_window_mean" (the period's cost refused up front, as the CLI).
py::dict worst(const Machine& self, py::handle window) {
  const double w = positive_arg(window, "window", 1e9, "seconds in (0, 1e9]");
  WorstWindowMean r;
  {
    py::gil_scoped_release release;
    worst_window_mean_cost(self.averaged);
    r = worst_window_mean(self.averaged, w);
  }
  py::dict d;
  d["window_s"] = r.window_s;
  d["lower"] = r.lower;
  d["upper"] = r.upper;
  d["start_s"] = r.start_s;
  d["certified"] = r.certified;
  return d;
}

/// `--epsilon E --resolution S --json`'s "time_to_epsilon".
py::dict time_to(const Machine& self, py::handle epsilon, py::handle resolution) {
  const double e = positive_arg(epsilon, "epsilon", 1e9, "a bound in units of g0, > 0");
  const double r = positive_arg(resolution, "resolution", 1e6, "seconds in (0, 1e6]");
  TimeToEpsilon t;
  {
    py::gil_scoped_release release;
    worst_window_mean_cost(self.averaged);
    t = time_to_epsilon(self.averaged, e, r);
  }
  py::dict d;
  d["epsilon"] = t.epsilon;
  d["resolution_s"] = r;
  d["first_s"] = or_none(t.first_s);
  d["stays_below_from_s"] = or_none(t.stays_below_from_s);
  d["above_s"] = or_none(t.above_s);
  d["reason"] = t.reason;
  d["certified"] = t.certified;
  return d;
}

/// The dwell map's request, checked as the CLI's --coverage, --nside, --start.
struct DwellRequest {
  double duration, start;
  int nside;
};

DwellRequest dwell_request(py::handle duration, py::handle nside_arg, py::handle start) {
  DwellRequest q{};
  q.duration = positive_arg(duration, "coverage", Clinostat::kMaxTime, "seconds in (0, 1e12]");
  const std::size_t nside = count_arg(nside_arg, "nside", 1, 1024);
  if ((nside & (nside - 1)) != 0) throw InvalidInput("nside", std::to_string(nside), "not a power of two", "1, 2, 4, ..., 1024");
  q.nside = static_cast<int>(nside);
  q.start = time_arg(start, "start");
  return q;
}

/// The dwell map from sphtroch._sphtroch_healpix (healpix_module.cpp), imported here on first use
/// so that `import sphtroch` loads no HEALPix: its dict, or InvalidInput as dwell_map refuses.
py::dict dwell(const Machine& self, const DwellRequest& q) {
  const ClinostatSettings& s = self.machine.settings();
  const py::object dwell_map = py::module_::import("sphtroch._sphtroch_healpix").attr("dwell_map");
  py::dict d = dwell_map(s.outer.num(), s.outer.den(), s.inner.num(), s.inner.den(), s.tilt_deg, s.frame_angle_deg, s.phase_outer_deg,
                         s.phase_inner_deg, s.offset_m.x(), s.offset_m.y(), s.offset_m.z(), q.start, q.duration, q.nside);
  if (d.contains("error")) {
    const py::tuple e = d["error"];
    throw InvalidInput(e[0].cast<std::string>(), e[1].cast<std::string>(), e[2].cast<std::string>(), e[3].cast<std::string>());
  }
  return d;
}

py::object coverage(const Machine& self, py::handle duration, py::handle nside, py::handle start) {
  return dwell(self, dwell_request(duration, nside, start))["dwell_s"];
}

py::dict coverage_summary(const Machine& self, py::handle duration, py::handle nside, py::handle start) {
  const py::dict m = dwell(self, dwell_request(duration, nside, start));
  py::dict d;
  for (const char* key : {"start_s", "duration_s", "nside"}) d[key] = m[key];
  d["fraction"] = m["fraction"];
  d["dwell_cv"] = m["dwell_cv"];
  d["bound_s"] = m["bound_s"];
  return d;
}

/// The dwell map of the healpix module's dict (dwell()) as the library's DwellMap.
DwellMap dwell_map_of(const py::dict& d) {
  DwellMap m;
  m.start_s = d["start_s"].cast<double>();
  m.duration_s = d["duration_s"].cast<double>();
  m.nside = d["nside"].cast<int>();
  m.bound_s = d["bound_s"].cast<double>();
  m.visited = d["visited"].cast<std::size_t>();
  m.visited_fraction = d["fraction"].cast<double>();
  m.dwell_cv = d["dwell_cv"].cast<double>();
  const auto dwell_s = d["dwell_s"].cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
  m.dwell_s.assign(dwell_s.data(), dwell_s.data() + dwell_s.size());
  return m;
}

/// Clinostat.report(...): machine/clinostat_report.hpp's JSON object, the one `sphtroch clinostat
/// --json` prints, read by Python's json module (so the dict is that object, member for member).
py::object report(const Machine& self, py::handle window, py::handle epsilon, py::handle resolution, py::handle coverage,
                  py::handle nside, py::handle start, py::handle running_mean, py::handle band, py::handle target_g, py::handle tolerance) {
  ClinostatRequest q;
  q.band = flag_arg(band, "band");
  if (q.band && window.is_none()) throw InvalidInput("band", "True", "only with window", "window=W, band=True");
  if (!target_g.is_none() && !q.band) throw InvalidInput("target-g", repr_of(target_g), "only with band", "window=W, band=True, target_g=G, tolerance=D");
  if (target_g.is_none() != tolerance.is_none())
    throw InvalidInput(target_g.is_none() ? "target-g" : "tolerance", "None", "missing: target_g and tolerance go together",
                       "window=W, band=True, target_g=G, tolerance=D");  // names the one to add
  if (!target_g.is_none()) {
    q.target_g = real_arg(target_g, "target-g", "a finite number >= 0, units of g0");
    q.tolerance = real_arg(tolerance, "tolerance", "a finite number >= 0, units of g0");
    check_window_target(*q.target_g, q.tolerance);
  }
  q.start = time_arg(start, "start");
  if (!running_mean.is_none())
    for (const py::handle t : running_mean)
      q.running_mean_s.push_back(positive_arg(t, "running-mean", Clinostat::kMaxTime, "T1,T2,...: durations in (0, 1e12] seconds"));
  if (!window.is_none()) q.window = positive_arg(window, "window", 1e9, "seconds in (0, 1e9]");
  if (!epsilon.is_none()) q.epsilon = positive_arg(epsilon, "epsilon", 1e9, "a bound in units of g0, > 0");
  if (!resolution.is_none()) {
    if (!q.epsilon) throw InvalidInput("resolution", repr_of(resolution), "only with epsilon", "epsilon=E, resolution=S");
    q.resolution = positive_arg(resolution, "resolution", 1e6, "seconds in (0, 1e6]");
  }
  std::optional<DwellMap> map;
  if (!coverage.is_none()) {
    const DwellRequest d = dwell_request(coverage, nside, start);
    q.coverage = d.duration;
    q.nside = d.nside;
    q.start = d.start;
    map = dwell_map_of(dwell(self, d));
  }
  std::string text;
  {
    py::gil_scoped_release release;
    text = clinostat_report_json(clinostat_report(self.machine, q, std::move(map))).dump();
  }
  return py::module_::import("json").attr("loads")(text);
}

py::object train_map(const Machine& self) {
  if (!self.train.train) return py::none();
  py::array_t<double> rotation(std::vector<py::ssize_t>{3, 3});
  double* r = rotation.mutable_data();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[3 * i + j] = self.train.rotation(i, j);
  py::dict d;
  d["theta2_at_0"] = self.train.theta2_at_0;
  d["theta2_rate"] = self.train.theta2_rate;
  d["rotation"] = rotation;
  return py::object(std::move(d));
}

/// Clinostat(outer_rpm='1.33', inner_rpm='2', tilt=90.0, ...): the settings, as the call that makes them.
std::string machine_repr(const Machine& self) {
  const ClinostatSettings& s = self.machine.settings();
  const auto real = [](double x) { return repr_of(py::float_(x)); };
  const Vector3d& r = s.offset_m;
  const std::string offset = self.offset_given ? "(" + real(r.x()) + ", " + real(r.y()) + ", " + real(r.z()) + ")" : "None";
  return "Clinostat(outer_rpm=" + repr_of(py::str(s.outer.str())) + ", inner_rpm=" + repr_of(py::str(s.inner.str())) +
         ", tilt=" + real(s.tilt_deg) + ", frame_angle=" + real(s.frame_angle_deg) + ", phase_outer=" + real(s.phase_outer_deg) +
         ", phase_inner=" + real(s.phase_inner_deg) + ", offset=" + offset +
         (s.gravity_g0 != 1 ? ", gravity_g0=" + real(s.gravity_g0) : std::string()) + ")";
}

}  // namespace

void bind_clinostat(py::module_& m) {
  using M = const Machine&;
  py::class_<Machine>(m, "Clinostat", doc("Clinostat"))
      .def(py::init(&make_machine), py::arg("outer_rpm"), py::arg("inner_rpm"), py::kw_only(), py::arg("tilt") = 90.0,
           py::arg("frame_angle") = 90.0, py::arg("phase_outer") = 0.0, py::arg("phase_inner") = 0.0, py::arg("offset") = py::none(),
           py::arg("gravity_g0") = 1.0, doc("Clinostat.__init__"))
      .def_property_readonly("outer_rpm", checked(+[](M c) { return c.machine.settings().outer.str(); }), doc("Clinostat.outer_rpm"))
      .def_property_readonly("inner_rpm", checked(+[](M c) { return c.machine.settings().inner.str(); }), doc("Clinostat.inner_rpm"))
      .def_property_readonly("tilt", checked(+[](M c) { return c.machine.settings().tilt_deg; }), doc("Clinostat.tilt"))
      .def_property_readonly("frame_angle", checked(+[](M c) { return c.machine.settings().frame_angle_deg; }), doc("Clinostat.frame_angle"))
      .def_property_readonly("phase_outer", checked(+[](M c) { return c.machine.settings().phase_outer_deg; }), doc("Clinostat.phase_outer"))
      .def_property_readonly("phase_inner", checked(+[](M c) { return c.machine.settings().phase_inner_deg; }), doc("Clinostat.phase_inner"))
      .def_property_readonly("offset", checked(+[](M c) -> py::object {
        const Vector3d& r = c.machine.settings().offset_m;
        return c.offset_given ? py::object(py::make_tuple(r.x(), r.y(), r.z())) : py::object(py::none());
      }), doc("Clinostat.offset"))
      .def_property_readonly("gravity_g0", checked(+[](M c) { return c.machine.settings().gravity_g0; }), doc("Clinostat.gravity_g0"))
      .def_property_readonly("period", checked(+[](M c) { return or_none(c.averaged.period_s()); }), doc("Clinostat.period"))
      .def_property_readonly("mean_over_period", checked(+[](M c) { return vector_array(c.averaged.period_mean()); }),
                             doc("Clinostat.mean_over_period"))
      .def_property_readonly("train", checked(+[](M c) -> py::object { return c.gear_train ? py::cast(*c.gear_train) : py::object(py::none()); }),
                             doc("Clinostat.train"))
      .def_property_readonly("train_map", checked(&train_map), doc("Clinostat.train_map"))
      .def_property_readonly("train_note", checked(+[](M c) { return c.train.reason; }), doc("Clinostat.train_note"))
      .def("gravity", checked(+[](M c, py::handle t) { return gravity_at_times(c, t, false); }), py::arg("t"), doc("Clinostat.gravity"))
      .def("effective_gravity", checked(+[](M c, py::handle t) { return gravity_at_times(c, t, true); }), py::arg("t"),
           doc("Clinostat.effective_gravity"))
      .def("window_mean", checked(&window_mean), py::arg("t0"), py::arg("window"), doc("Clinostat.window_mean"))
      .def("worst_window_mean", checked(&worst), py::arg("window"), doc("Clinostat.worst_window_mean"))
      .def("time_to", checked(&time_to), py::arg("epsilon"), py::arg("resolution") = 1.0, doc("Clinostat.time_to"))
      .def("coverage", checked(&coverage), py::arg("duration"), py::arg("nside") = 8, py::arg("start") = 0.0, doc("Clinostat.coverage"))
      .def("coverage_summary", checked(&coverage_summary), py::arg("duration"), py::arg("nside") = 8, py::arg("start") = 0.0,
           doc("Clinostat.coverage_summary"))
      .def("report", checked(&report), py::kw_only(), py::arg("window") = py::none(), py::arg("epsilon") = py::none(),
           py::arg("resolution") = py::none(), py::arg("coverage") = py::none(), py::arg("nside") = 8, py::arg("start") = 0.0,
           py::arg("running_mean") = py::none(), py::arg("band") = false, py::arg("target_g") = py::none(),
           py::arg("tolerance") = py::none(), doc("Clinostat.report"))
      .def("_repr_svg_", checked(+[](M c) -> py::object {
        return c.gear_train ? py::cast(*c.gear_train).attr("_repr_svg_")() : py::object(py::none());
      }), doc("Clinostat._repr_svg_"))
      .def("__repr__", checked(&machine_repr));
}

}  // namespace sphtroch::python
