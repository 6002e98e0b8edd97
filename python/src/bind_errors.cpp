// python/src/bind_errors.cpp — sphtroch.InvalidInput and sphtroch.UncertifiedResult (bindings.hpp).
#include "bindings.hpp"

#include "sphtroch/core/errors.hpp"

#include <exception>
#include <string>

namespace sphtroch::python {
namespace {

/// The C++ type behind sphtroch.UncertifiedResult (never thrown: raise_uncertified raises the Python class).
struct UncertifiedMarker : std::exception {};

/// The Python classes (the module object keeps them alive).
py::handle g_invalid_input;
py::handle g_uncertified;

void translate_invalid_input(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const InvalidInput& e) {
    py::object err = py::reinterpret_borrow<py::object>(g_invalid_input)(one_line_text(e.message()));  // one line, NUL bytes escaped too
    err.attr("field") = e.field();
    err.attr("value") = e.value();
    err.attr("problem") = e.problem();
    err.attr("valid") = e.valid_range();
    PyErr_SetObject(g_invalid_input.ptr(), err.ptr());
  }
}

}  // namespace

void bind_errors(py::module_& m) {
  static py::exception<sphtroch::InvalidInput> invalid_input(m, "InvalidInput", PyExc_ValueError);
  g_invalid_input = invalid_input;
  invalid_input.attr("__doc__") = doc("InvalidInput");
  invalid_input.attr("__module__") = "sphtroch";
  for (const char* a : {"field", "value", "problem", "valid"}) invalid_input.attr(a) = py::none();
  py::register_exception_translator(&translate_invalid_input);
  static py::exception<UncertifiedMarker> uncertified(m, "UncertifiedResult", PyExc_RuntimeError);
  g_uncertified = uncertified;
  uncertified.attr("__doc__") = doc("UncertifiedResult");
  uncertified.attr("__module__") = "sphtroch";
}

void raise_uncertified(const std::string& message, py::handle nodes, py::handle polyline_nodes, py::handle root_nodes) {
  py::object err = py::reinterpret_borrow<py::object>(g_uncertified)(message);
  err.attr("nodes") = nodes;
  err.attr("polyline_nodes") = polyline_nodes;
  err.attr("root_nodes") = root_nodes;
  PyErr_SetObject(g_uncertified.ptr(), err.ptr());
  throw py::error_already_set();
}

}  // namespace sphtroch::python
