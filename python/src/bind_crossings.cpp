// python/src/bind_crossings.cpp — sphtroch.crossings (bindings.hpp): the exact self-crossings of
// a spherical polyline given as an (N, 3) array, as `sphtroch crossings`.
#include "bindings.hpp"
#include "exact_calls.hpp"

#include "sphtroch/core/cost_bounds.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sphtroch::python {
namespace {

constexpr const char* kPointsValid =
    "an (N, 3) array of x, y, z rows (float64; other integer or float dtypes are converted)";

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
  const bool closed = flag_arg(closed_flag, "closed");
  const bool with_pairs = flag_arg(pairs_flag, "pairs");
  const std::size_t limit_contacts = count_arg(max_crossings, "max_crossings", 0, kMaxCrossingLimit);
  const std::size_t limit_work = count_arg(max_work, "max_work", 0, kMaxCrossingLimit);
  const RealArray a = real_array_arg(points, "points", kPointsValid);  // the same object when already C-contiguous float64
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

}  // namespace

void bind_crossings(py::module_& m) {
  m.def("crossings", &crossings, py::arg("points"), py::arg("closed") = true, py::kw_only(), py::arg("pairs") = false,
        py::arg("max_crossings") = sphtroch::kDefaultMaxCrossings, py::arg("max_work") = sphtroch::kDefaultMaxCrossingWork, doc("crossings"));
}

}  // namespace sphtroch::python
