// python/src/module.cpp — the extension module sphtroch._sphtroch (pybind11): one call per topic
// (bindings.hpp). The Python contract (names, arguments, returned dicts) is
// python/sphtroch/__init__.pyi.
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
#include "bindings.hpp"

#include "sphtroch/version.hpp"

#include <string>

PYBIND11_MODULE(_sphtroch, m) {
  namespace python = sphtroch::python;
  // The signatures come from the stub (python::doc): pybind11's own would name the arguments the
  // bindings validate themselves `handle` and their results `object`.
  pybind11::options options;
  options.disable_function_signatures();
  m.doc() = "sphtroch: trajectories of spherical planetary gear trains (Lin & Tsai 1990); see __init__.pyi";
  m.attr("__version__") = SPHTROCH_VERSION_STRING;
  python::bind_errors(m);
  python::bind_gear_train(m);
  python::bind_design_map(m);
  python::bind_crossings(m);
  python::bind_synthesis(m);
  python::bind_clinostat(m);
  python::bind_chain(m);
  python::bind_wrist(m);
  // The stub's docstring of `name`, for the package's pure-Python parts (python/sphtroch/_arrays.py).
  m.def("_doc", [](const std::string& name) { return std::string(python::python_doc(name.c_str())); });
}
