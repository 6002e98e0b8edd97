// python/src/urdf_module.cpp — the extension `sphtroch._sphtroch_urdf`: a rotation chain read from
// a URDF robot description (io/urdf_chain.hpp), the one part of the Python module that links
// urdfdom. Chain.from_urdf imports it on first use (bind_chain.cpp), so that `import sphtroch`
// loads no urdfdom.
//
//   read_chain(xml, from_link, to_link, axis_x, axis_y, axis_z)
//     -> [(twist, rate_num, rate_den, phase), ...] one per stage (radians; the rate exact), or
//        {"error": (field, value, problem, valid range)} for what read_urdf_chain refuses (the
//        caller raises sphtroch.InvalidInput).
// In a build without urdfdom every call gives the "urdf" refusal that the tool gives.
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/types.hpp"
#if defined(SPHTROCH_HAVE_URDF)
#include "sphtroch/io/urdf_chain.hpp"
#endif

#include <pybind11/pybind11.h>

#include <string>

namespace py = pybind11;

namespace {

py::object read_chain(const std::string& xml, const std::string& from, const std::string& to, double ax, double ay, double az) {
  using namespace sphtroch;
  try {
#if defined(SPHTROCH_HAVE_URDF)
    const RotationChain chain = chain_from_urdf(xml, from, to, Vector3d(ax, ay, az));
    py::list stages;
    for (const ChainStage& s : chain.stages()) stages.append(py::make_tuple(s.twist, s.rate.p(), s.rate.q(), s.phase));
    return std::move(stages);
#else
    (void)xml, (void)from, (void)to, (void)ax, (void)ay, (void)az;
    throw InvalidInput("urdf", "", "this build has no urdfdom", "a build with sphtroch::urdf (Debian's liburdfdom-dev)");
#endif
  } catch (const InvalidInput& e) {
    py::dict d;
    d["error"] = py::make_tuple(e.field(), e.value(), e.problem(), e.valid_range());
    return std::move(d);
  }
}

}  // namespace

PYBIND11_MODULE(_sphtroch_urdf, m) {
  m.doc() = "sphtroch's URDF reader (urdfdom), imported by Chain.from_urdf on first use";
  m.def("read_chain", &read_chain);
}
