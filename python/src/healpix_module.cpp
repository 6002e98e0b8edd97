// python/src/healpix_module.cpp — the extension `sphtroch._sphtroch_healpix`: a clinostat's dwell
// map (machine/dwell_map.hpp), the one part of the Python module that needs HEALPix (and, through
// it, cfitsio and its network libraries). Clinostat.coverage imports it on first use
// (bind_clinostat.cpp), so that `import sphtroch` loads none of them.
//
//   dwell_map(outer_num, outer_den, inner_num, inner_den, tilt, frame_angle, phase_outer, phase_inner,
//             offset_x, offset_y, offset_z, start, duration, nside)
//     -> {"dwell_s": float64 array, "start_s", "duration_s", "nside", "bound_s", "visited",
//         "fraction", "dwell_cv"}, or {"error": (field, value, problem, valid range)} for what
//         dwell_map refuses (the caller raises sphtroch.InvalidInput), computed without the GIL.
// In a build without HEALPix every call gives the "coverage" refusal.
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/machine/clinostat.hpp"
#if defined(SPHTROCH_HAVE_HEALPIX)
#include "sphtroch/machine/dwell_map.hpp"
#endif

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <vector>

namespace py = pybind11;

namespace {

py::dict error_dict(const sphtroch::InvalidInput& e) {
  py::dict d;
  d["error"] = py::make_tuple(e.field(), e.value(), e.problem(), e.valid_range());
  return d;
}

py::dict dwell(std::int64_t outer_num, std::int64_t outer_den, std::int64_t inner_num, std::int64_t inner_den, double tilt, double frame,
               double phase_outer, double phase_inner, double ox, double oy, double oz, double start, double duration, int nside) {
  using namespace sphtroch;
  try {
#if defined(SPHTROCH_HAVE_HEALPIX)
    ClinostatSettings s;
    s.outer = Rpm(outer_num, outer_den, "outer");
    s.inner = Rpm(inner_num, inner_den, "inner");
    s.tilt_deg = tilt, s.frame_angle_deg = frame, s.phase_outer_deg = phase_outer, s.phase_inner_deg = phase_inner;
    s.offset_m = Vector3d(ox, oy, oz);
    auto map = std::make_unique<DwellMap>();
    {
      py::gil_scoped_release release;
      *map = dwell_map(Clinostat(s), start, duration, nside);
    }
    py::dict d;
    d["start_s"] = map->start_s;
    d["duration_s"] = map->duration_s;
    d["nside"] = map->nside;
    d["bound_s"] = map->bound_s;
    d["visited"] = map->visited;
    d["fraction"] = map->visited_fraction;
    d["dwell_cv"] = map->dwell_cv;
    const DwellMap* m = map.get();
    const py::capsule owner(map.release(), [](void* p) { delete static_cast<DwellMap*>(p); });
    d["dwell_s"] = py::array_t<double>(static_cast<py::ssize_t>(m->dwell_s.size()), m->dwell_s.data(), owner);
    return d;
#else
    (void)outer_num, (void)outer_den, (void)inner_num, (void)inner_den, (void)tilt, (void)frame, (void)phase_outer, (void)phase_inner;
    (void)ox, (void)oy, (void)oz, (void)start, (void)nside;
    throw InvalidInput("coverage", number_text(duration), "this build of sphtroch has no HEALPix (libhealpix-cxx-dev)",
                       "coverage in a build with HEALPix");
#endif
  } catch (const InvalidInput& e) {
    return error_dict(e);
  }
}

}  // namespace

PYBIND11_MODULE(_sphtroch_healpix, m) {
  m.doc() = "sphtroch's dwell maps (HEALPix), imported by Clinostat.coverage on first use";
  m.def("dwell_map", &dwell);
}
