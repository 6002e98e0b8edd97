// The interval solvers as the WebAssembly build runs them: this file is compiled with
// CGAL_ALWAYS_ROUND_TO_NEAREST (explorer/CMakeLists.txt's flag: no rounding modes, every interval
// result stepped outward by an ulp, exact ones too). Expected values: the report's pitch-cone
// function q sin(a3 - a2) + p sin a3 = 0 (Eq. of the pitch cone) solved by hand on the square
// about the train: for n = 1 and a2 = a3 = x the corner a2 = x + h, a3 = x - h meets it when
// sin(x - h) = sin 2h, h = x / 3 (pi/6 at x = pi/2, 0.5 at x = 1.5).
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/tolerance/topology_margin.hpp"

#include <cmath>

using namespace sphtroch;

#if !defined(CGAL_ALWAYS_ROUND_TO_NEAREST)
#error "test_nearest_rounding.cpp tests the round-to-nearest interval kernel: compile it with CGAL_ALWAYS_ROUND_TO_NEAREST"
#endif

TEST_CASE("round to nearest (the WebAssembly kernel): the topology margin of n = 1 trains converges on the closed form", "[nearest]") {
  const double pi = Constants<double>::pi();
  for (const double x : {pi / 2, 1.5, 1.2}) {
    const TopologyMargin m = topology_margin(GearTrain(x, x, Ratio(1)));
    CAPTURE(x, m.lower, m.upper);
    CHECK(m.converged);
    CHECK(m.lower <= x / 3 + 1e-12);
    CHECK(m.upper >= x / 3 - 1e-12);
    CHECK(m.upper - m.lower <= 1e-6);
  }
}

TEST_CASE("round to nearest: n = -1/2 and -1 converge, the witness on its boundary's closed form at the margin", "[nearest]") {
  const double pi = Constants<double>::pi();
  for (const Ratio n : {Ratio(-1, 2), Ratio(-1), Ratio(1, 2)}) {
    const GearTrain train(pi / 2, pi / 2, n);
    const TopologyMargin m = topology_margin(train);
    CAPTURE(n.str(), m.lower, m.upper);
    CHECK(m.converged);
    REQUIRE(m.nearest);
    const double p = static_cast<double>(n.p()), q = static_cast<double>(n.q()), a2 = m.nearest->a2(), a3 = m.nearest->a3();
    const double f = m.nearest->boundary.kind == MapBoundary::Kind::pitch_cone ? q * std::sin(a3 - a2) + p * std::sin(a3)
                     : m.nearest->boundary.kind == MapBoundary::Kind::mirror_pitch_cone ? q * std::sin(a2 + a3) + p * std::sin(a3)
                                                                                     : 0.0;
    CHECK(std::fabs(f) <= 1e-6);
    CHECK(std::max(std::fabs(a2 - pi / 2), std::fabs(a3 - pi / 2)) <= m.upper + 1e-9);
  }
}
