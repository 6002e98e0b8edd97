// python/src/bind_wrist.cpp — the class sphtroch.Wrist (bindings.hpp): a geared spherical wrist
// with 2 or 3 motors (wrist/wrist.hpp) read from twists, coupling, phases and tool axis as
// `sphtroch wrist` reads them (wrist/wrist_text.hpp: each argument is turned into the CLI's text,
// so that the one reader checks it), with ik, cap, atlas (the very JSON objects `sphtroch wrist
// ik|cap|atlas --json` print), motors, periods, repr, equality and pickling.
#include "bindings.hpp"

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_atlas.hpp"
#include "sphtroch/wrist/wrist_atlas_output.hpp"
#include "sphtroch/wrist/wrist_cap.hpp"
#include "sphtroch/wrist/wrist_cap_output.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_ik_output.hpp"
#include "sphtroch/wrist/wrist_regions.hpp"
#include "sphtroch/wrist/wrist_regions_output.hpp"
#include "sphtroch/wrist/wrist_text.hpp"

#include <string>

namespace sphtroch::python {
namespace {

/// A wrist and its arguments as the CLI's text (what repr and pickling give back).
struct PyWrist {
  WristText text;
  Wrist wrist;
};

constexpr std::size_t kMaxJoints = 6;

std::string angle_text(py::handle a, const char* field) {
  std::string text;
  angle_arg(a, field, text);
  return text;
}

/// A real number as the CLI reads it: the shortest text that reads back to the same double.
std::string number_item(py::handle v, const std::string& field, const std::string& valid) {
  return number_text(real_arg(v, field, valid));
}

/// The coupling: the CLI's "c11,c12;c21,c22;..." or a sequence of rows, each a sequence of exact rates.
std::string coupling_text(py::handle v) {
  const std::string valid = std::string("a list of k rows of m ") + kExactRateForms + " (m = 2 or 3), or the CLI's \"1,0;0,1;0,3/2\"";
  return list_text(v, "coupling", valid,
                   [&](py::handle row) {
                     return list_text(row, "coupling", valid, [](py::handle c) { return exact_rate_text(c, "coupling"); }, 3);
                   },
                   kMaxJoints, ";");
}

/// A vector argument (X,Y,Z, a quaternion, a matrix by rows) as the CLI's comma-separated text.
std::string vector_text(py::handle v, const char* field, const std::string& valid, std::size_t max_items) {
  if (!py::isinstance<py::str>(v) && py::isinstance<py::array>(v) && py::reinterpret_borrow<py::array>(v).ndim() == 2)
    return vector_text(py::module_::import("numpy").attr("ravel")(v), field, valid, max_items);  // a 3 x 3 matrix
  return list_text(v, field, valid, [&](py::handle x) { return number_item(x, field, valid); }, max_items);
}

PyWrist make_wrist(py::handle twists, py::handle coupling, py::handle phases, py::handle axis) {
  WristText text;
  text.twists = list_text(twists, "twists", "a list of k angles in [0, pi] (radians or text), or the CLI's \"A1,...,Ak\"",
                          [](py::handle a) { return angle_text(a, "twists"); }, kMaxJoints);
  text.coupling = coupling_text(coupling);
  if (!phases.is_none())
    text.phases = list_text(phases, "phases", "a list of k angles (radians or text), or the CLI's \"P1,...,Pk\"",
                            [](py::handle a) { return angle_text(a, "phases"); }, kMaxJoints);
  if (!axis.is_none()) text.axis = vector_text(axis, "axis", "X,Y,Z: the tool axis in the last body", 3);
  return PyWrist{text, text.wrist()};
}

/// ik(target=None, *, frame=None): `sphtroch wrist ik --json`'s object.
py::object ik(const PyWrist& self, py::handle target, py::handle frame) {
  WristText text = self.text;
  if (!target.is_none()) text.target = vector_text(target, "target", "X,Y,Z: a unit vector (2 motors)", 3);
  if (!frame.is_none())
    text.target_frame = vector_text(frame, "target-frame", "a unit quaternion w,x,y,z or a rotation matrix (9 numbers by rows, or 3 x 3)", 9);
  const WristTarget t = text.wrist_target(self.wrist);
  check_wrist_ik_cost(self.wrist);
  std::string json;
  {
    py::gil_scoped_release release;
    json = wrist_ik_json(self.wrist, t, wrist_ik(self.wrist, t)).dump();
  }
  return from_json(json);
}

/// cap(home): `sphtroch wrist cap --json`'s object.
py::object cap(const PyWrist& self, py::handle home) {
  WristText text = self.text;
  text.home = vector_text(home, "home", "X,Y,Z: a unit vector", 3);
  const Vector3d h = text.home_direction();
  std::string json;
  {
    py::gil_scoped_release release;
    json = wrist_cap_json(self.wrist, h, wrist_cap(self.wrist, h)).dump();
  }
  return from_json(json);
}

/// atlas(width=None, sphere_cell=None): `sphtroch wrist atlas --json`'s object (one worker thread:
/// the result does not depend on their number).
py::object atlas(const PyWrist& self, py::handle width, py::handle sphere_cell) {
  const double w = width.is_none() ? kWristAtlasDefaultWidth : real_arg(width, "width", "radians of joint motion per cell, 0.001 to 1");
  const double step = sphere_cell.is_none() ? kWristRegionsDefaultStep
                                            : real_arg(sphere_cell, "sphere-cell", "radians per sphere cell, 0.003 to 0.5");
  check_wrist_regions_cost(step);
  std::string json;
  {
    py::gil_scoped_release release;
    const WristAtlasResult a = wrist_fold_atlas(self.wrist, w);
    json = wrist_atlas_report_json(self.wrist, a, wrist_regions(self.wrist, a, step)).dump();
  }
  return from_json(json);
}

py::tuple state(const PyWrist& w) { return py::make_tuple(w.text.twists, w.text.coupling, w.text.phases, w.text.axis); }

std::string repr(const PyWrist& w) {
  std::string r = "Wrist(twists=" + repr_of(py::str(w.text.twists)) + ", coupling=" + repr_of(py::str(w.text.coupling));
  if (!w.text.phases.empty()) r += ", phases=" + repr_of(py::str(w.text.phases));
  if (!w.text.axis.empty()) r += ", axis=" + repr_of(py::str(w.text.axis));
  return r + ")";
}

}  // namespace

void bind_wrist(py::module_& m) {
  py::class_<PyWrist>(m, "Wrist", doc("Wrist"))
      .def(py::init(&make_wrist), py::arg("twists"), py::arg("coupling"), py::arg("phases") = py::none(),
           py::arg("axis") = py::none(), doc("Wrist.__init__"))
      .def_property_readonly("motors", [](const PyWrist& w) { return w.wrist.motors(); }, doc("Wrist.motors"))
      .def_property_readonly("periods",
                             [](const PyWrist& w) {
                               py::list out;
                               for (std::size_t j = 0; j < w.wrist.motors(); ++j) out.append(w.wrist.period(j));
                               return out;
                             },
                             doc("Wrist.periods"))
      .def("ik", &ik, py::arg("target") = py::none(), py::kw_only(), py::arg("frame") = py::none(), doc("Wrist.ik"))
      .def("cap", &cap, py::arg("home"), doc("Wrist.cap"))
      .def("atlas", &atlas, py::arg("width") = py::none(), py::arg("sphere_cell") = py::none(), doc("Wrist.atlas"))
      .def("__repr__", &repr)
      .def("__eq__", [](const PyWrist& a, const PyWrist& b) { return state(a).equal(state(b)); })
      .def("__hash__", [](const PyWrist& w) { return py::hash(state(w)); })
      .def(py::pickle([](const PyWrist& w) { return state(w); },
                      [](const py::tuple& t) {
                        if (t.size() != 4) throw std::runtime_error("Wrist: bad pickle state");
                        WristText text;
                        text.twists = t[0].cast<std::string>();
                        text.coupling = t[1].cast<std::string>();
                        text.phases = t[2].cast<std::string>();
                        text.axis = t[3].cast<std::string>();
                        return PyWrist{text, text.wrist()};
                      }));
}

}  // namespace sphtroch::python
