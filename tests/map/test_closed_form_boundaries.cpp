// closed_form_boundaries.hpp: the boundary vocabulary. Expected values from the definitions (a_p from Eq. 2:
// tan a_p = sin a2 / (cos a2 + n)) and the report's boundary cases.
#include "test_support.hpp"

#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/closed_form_boundaries.hpp"

#include <cmath>
#include <limits>

using namespace sphtroch;

namespace {
const double kPi = Constants<double>::pi();
}

TEST_CASE("boundaries: values and margins from the definitions, exact margin when a3 is given on a cone", "[boundaries]") {
  const double a2 = kPi / 3;
  const double ap = std::atan2(std::sin(a2), std::cos(a2) + 2.0);  // Eq. 2, n = 2
  const GearTrain t(a2, 1.0, Ratio(2));
  CHECK(std::abs(boundary_value(t, BoundaryKind::pitch_cone) - ap) < 1e-15);
  CHECK(std::abs(boundary_value(t, BoundaryKind::mirror_pitch_cone) - (kPi - ap)) < 1e-15);
  CHECK(boundary_value(t, BoundaryKind::a2) == a2);
  CHECK(std::abs(boundary_margin(t, BoundaryKind::pi_minus_a2) - (1.0 - (kPi - a2))) < 1e-15);
  CHECK(boundaries(t).size() == 4);  // n = 1 adds a2/2 and pi - a2/2
  CHECK(boundaries(GearTrain(a2, 1.0, Ratio(1))).size() == 6);
  // Given relative to the cone, the margin is the offset itself (exact), and it is "hit".
  const GearTrain on = GearTrain::on_cone(a2, A3Reference::pitch_cone, 3e-12, Ratio(2));
  CHECK(boundary_margin(on, BoundaryKind::pitch_cone) == 3e-12);
  REQUIRE(boundaries_hit(on, 1e-10).size() == 1);
  CHECK(boundaries_hit(on, 1e-10)[0].kind == BoundaryKind::pitch_cone);
  CHECK(boundaries_hit(on, 0.0).empty());
  CHECK(std::string(boundary_name(BoundaryKind::pitch_cone)) == "a3 = a_p (pitch cone)");
}

TEST_CASE("boundaries: bad tolerances and wrong ratios throw InvalidInput, never abort", "[boundaries][errors]") {
  const GearTrain n2(kPi / 3, 1.0, Ratio(2));
  for (double bad : {-1.0, std::nan("")}) {
    INFO(bad);
    CHECK(test::expect_invalid([&] { boundaries_hit(n2, bad); }).field() == "boundary_tolerance");
    CHECK(test::expect_invalid([&] { classify_analytic(n2, bad); }).field() == "boundary_tolerance");
  }
  const InvalidInput e = test::expect_invalid([&] { criterion_eq24(n2); });
  CHECK(e.field() == "n");
  CHECK(e.value() == "2");
  CHECK(test::expect_invalid([&] { criterion_eq43(GearTrain(1.0, 1.0, Ratio(1))); }).field() == "n");
  CHECK(test::expect_invalid([&] { nodes_eq39b(GearTrain(1.0, 1.0, Ratio(3))); }).field() == "n");
}

TEST_CASE("nearest_boundary: the closest curve of the map in a3", "[boundaries]") {
  const double a2 = 2.0;
  const double ap = GearTrain::planet_cone_of(a2, Ratio(2));
  const NearestBoundary b = nearest_boundary(a2, ap + 1e-4, Ratio(2));
  CHECK(b.kind == BoundaryKind::pitch_cone);
  CHECK(std::abs(b.distance - 1e-4) < 1e-15);
  CHECK(nearest_boundary(a2, kPi - a2 - 2e-3, Ratio(2)).kind == BoundaryKind::pi_minus_a2);
  // |p| = 1: the poles are not boundaries of the map.
  CHECK(atlas_boundary_kinds(Ratio(1)).size() == 2);
  CHECK(atlas_boundary_kinds(Ratio(-3, 2)).size() == 4);
}
