// root_classification.hpp: the Eigen-only classification of one train and the a3 sweep.
// Expected values: the report's stated cases (data/reference/paper_cases.csv), its criteria
// written out here (Eq. 24 for n = 1), and a closed form for n = 3 (below); never the code's output.
#include "test_support.hpp"

#include "sphtroch/census/root_classification.hpp"

#include <cmath>
#include <limits>
#include <vector>

using namespace sphtroch;
using sphtroch::test::expect_invalid;

namespace {
const double kPi = Constants<double>::pi();
}

TEST_CASE("classify_roots: every case the report states (nodes, cusps, class)", "[root_classification][paper]") {
  for (const auto& row : sphtroch::test::paper_cases()) {
    INFO(row.id);
    const RootClassification c = classify_roots(GearTrain(row.a2, row.a3, Ratio(row.n_num, row.n_den)));
    CHECK(c.nodes == row.nodes);
    CHECK(c.cusps == row.cusps);
    CHECK(c.curve_class == curve_class(row.nodes, row.cusps));
    CHECK(c.nodes == c.crossings + c.tangencies);
    CHECK(c.node_points.size() == c.nodes);
    CHECK(c.agrees_with_report());
    for (const Node& n : c.node_points) CHECK(std::abs(n.position.norm() - 1.0) < 1e-14);
  }
}

TEST_CASE("CurveClass: names as the report's, from counts", "[root_classification]") {
  CHECK(std::string(to_string(CurveClass::simple_curve)) == "simple curve");
  CHECK(std::string(to_string(CurveClass::nodes_and_cusps)) == "nodes and cusps");
  CHECK(curve_class(0, 0) == CurveClass::simple_curve);
  CHECK(curve_class(2, 0) == CurveClass::nodes);
  CHECK(curve_class(0, 1) == CurveClass::cusps);
  CHECK(curve_class(1, 1) == CurveClass::nodes_and_cusps);
  const std::vector<RootClassification> many(200);  // a regular value type: default-constructible
  CHECK(many[199].curve_class == CurveClass::simple_curve);
}

TEST_CASE("classify_roots refuses a bad boundary tolerance with InvalidInput, never aborts", "[root_classification][errors]") {
  const GearTrain fig3(kPi / 2, kPi / 2, Ratio(1));
  for (double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity(), 0.01}) {
    INFO(bad);
    RootClassificationSettings s;
    s.boundary_tolerance = bad;
    const InvalidInput e = expect_invalid([&] { classify_roots(fig3, s); });
    CHECK(e.field() == "boundary_tolerance");
    CHECK(e.valid_range() == "[0, 1e-3] radians");
  }
  RootClassificationSettings zero;
  zero.boundary_tolerance = 0.0;
  CHECK(classify_roots(fig3, zero).nodes == 1);
}

TEST_CASE("classify_a3_range, n = 1: one node exactly where Eq. 24 holds, a2/2 < a3 < pi - a2/2", "[root_classification][sweep]") {
  for (double a2 : {kPi / 2, 2.0, 0.7}) {
    INFO(a2);
    const std::vector<A3Interval> runs = classify_a3_range(a2, Ratio(1), 0.01, kPi - 0.01, 1001);
    REQUIRE(runs.size() == 3);
    CHECK(runs[0].curve_class == CurveClass::simple_curve);
    CHECK(runs[1].curve_class == CurveClass::nodes);
    CHECK(runs[1].nodes == 1);
    CHECK(runs[2].curve_class == CurveClass::simple_curve);
    // Eq. 24's ends fall between the neighbouring samples.
    CHECK(runs[0].a3_last < a2 / 2);
    CHECK(runs[1].a3_first > a2 / 2);
    CHECK(runs[1].a3_last < kPi - a2 / 2);
    CHECK(runs[2].a3_first > kPi - a2 / 2);
    std::size_t samples = 0;
    for (const A3Interval& r : runs) samples += r.samples;
    CHECK(samples == 1001);
  }
}

TEST_CASE("classify_a3_range, n = 3, a2 = pi/2: 3 nodes become 9 at a3 = atan(3 sqrt 3)", "[root_classification][sweep]") {
  // Independent closed form: at a2 = pi/2, n = 3 three pairs of branches touch on the mirror planes
  // at a3 = atan(3 sqrt(3)) and pi - atan(3 sqrt(3)).
  const double edge = std::atan(3 * std::sqrt(3.0));
  // 101 samples put one exactly on the edge (to rounding): there the three pairs touch, 3
  // crossings + 3 tangency nodes = 6 node points; just below 3, just above 9.
  const std::vector<A3Interval> runs = classify_a3_range(kPi / 2, Ratio(3), edge - 0.05, edge + 0.05, 101);
  REQUIRE(runs.size() == 3);
  CHECK(runs[0].nodes == 3);
  CHECK(runs[0].a3_last < edge);
  CHECK(runs[1].nodes == 6);
  CHECK(runs[1].samples == 1);
  CHECK(std::abs(runs[1].a3_first - edge) < 1e-12);
  CHECK(runs[2].nodes == 9);
  CHECK(runs[2].a3_first > edge);
  // 100 samples straddle the edge: 3 then 9, the edge between them.
  const std::vector<A3Interval> even = classify_a3_range(kPi / 2, Ratio(3), edge - 0.05, edge + 0.05, 100);
  REQUIRE(even.size() == 2);
  CHECK(even[0].nodes == 3);
  CHECK(even[1].nodes == 9);
  CHECK(even[0].a3_last < edge);
  CHECK(even[1].a3_first > edge);
}

TEST_CASE("classify_a3_range refuses bad ranges and counts", "[root_classification][errors]") {
  CHECK(expect_invalid([] { classify_a3_range(1.0, Ratio(2), 0.0, 1.0, 10); }).field() == "a3_range");
  CHECK(expect_invalid([] { classify_a3_range(1.0, Ratio(2), 2.0, 1.0, 10); }).field() == "a3_range");
  CHECK(expect_invalid([] { classify_a3_range(1.0, Ratio(2), 1.0, kPi, 10); }).field() == "a3_range");
  CHECK(expect_invalid([] { classify_a3_range(1.0, Ratio(2), 0.5, 1.0, 1); }).field() == "count");
  CHECK(expect_invalid([] { classify_a3_range(1.0, Ratio(2), 0.5, 1.0, 2000000); }).field() == "count");
  CHECK(expect_invalid([] { classify_a3_range(0.0, Ratio(2), 0.5, 1.0, 10); }).field() == "a2");
}
