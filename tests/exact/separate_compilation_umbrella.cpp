// The umbrella header in separate mode (compiled with SPHTROCH_SEPARATE_EXACT, tests/CMakeLists.txt):
// <sphtroch/sphtroch.hpp> must then give classify()'s declaration and every Eigen-only header but
// parse no CGAL header: the compile-time promise of separate mode holds for a file that includes
// the umbrella, as sphtroch.hpp states (nlohmann-json, header-only like Eigen, serves the Eigen-only
// layers' JSON: the clinostat report, the node lists).
#include "sphtroch/sphtroch.hpp"

#if !defined(SPHTROCH_SEPARATE_EXACT)
#error "this file must be compiled with SPHTROCH_SEPARATE_EXACT"
#endif
#if defined(CGAL_VERSION_NR)
#error "the umbrella in separate mode must not pull in CGAL"
#endif

#include <cstddef>

/// Nodes of the train by classify() (defined in separate_compilation_impl.cpp) and by the
/// Eigen-only root census, both reached through the umbrella alone.
std::size_t classify_nodes_via_umbrella(double a2, double a3, std::int64_t p, std::int64_t q, std::size_t& root_nodes) {
  const sphtroch::GearTrain train(a2, a3, sphtroch::Ratio(p, q));
  root_nodes = sphtroch::classify_roots(train).nodes;
  return sphtroch::classify(train).nodes.size();
}
