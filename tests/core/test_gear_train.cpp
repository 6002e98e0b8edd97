// Tests for sphtroch/core/gear_train.hpp and sphtroch/core/ratio.hpp: validation (the typed InvalidInput
// names field, value and range) and the derived quantities a_p, a_s and the closing period, each
// checked against its definition in the report (n = sin a_s / sin a_p, a2 = a_s + a_p, Eq. 2;
// a_p = atan(sin a2 / (cos a2 + 2)) for n = 2, Sec. 5; a_p = a_s = a2/2 for n = 1, Sec. 4.2).
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/ratio.hpp"

#include <cmath>
#include <vector>
#include <limits>
#include <string>

using sphtroch::A3Reference;
using sphtroch::GearTrain;
using sphtroch::InvalidInput;
using sphtroch::Ratio;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

using sphtroch::test::expect_invalid;
}  // namespace

TEST_CASE("Ratio is stored in lowest terms with a positive denominator", "[ratio]") {
  CHECK(Ratio(10, 4) == Ratio(5, 2));
  CHECK(Ratio(10, 4).p() == 5);
  CHECK(Ratio(10, 4).q() == 2);
  CHECK(Ratio(3, -2).p() == -3);
  CHECK(Ratio(3, -2).q() == 2);
  CHECK(Ratio(-6, -4) == Ratio(3, 2));
  CHECK(Ratio(-7).abs_p() == 7);
  CHECK(Ratio(5, 2).value() == 2.5);
  CHECK(Ratio(5, 2).str() == "5/2");
  CHECK(Ratio(-3).str() == "-3");
}

TEST_CASE("Ratio rejects n = 0, q = 0 and terms beyond kMaxTerm with field n", "[ratio][errors]") {
  for (auto make : {+[] { Ratio(0); }, +[] { Ratio(0, 3); }, +[] { Ratio(1, 0); },
                    +[] { Ratio(Ratio::kMaxTerm + 1); }, +[] { Ratio(1, -Ratio::kMaxTerm - 1); }}) {
    const InvalidInput e = expect_invalid(make);
    CHECK(e.field() == "n");
    CHECK_FALSE(e.valid_range().empty());
  }
  CHECK(contains(expect_invalid([] { Ratio(0); }).problem(), "zero"));
}

TEST_CASE("GearTrain rejects a2 and a3 outside (0, pi), NaN and inf, naming field, value and range",
          "[gear_train][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    double a2, a3;
    const char* field;
  };
  const Case cases[] = {{0.0, 1.0, "a2"},  {kPi, 1.0, "a2"},     {4.0, 1.0, "a2"},  {-0.5, 1.0, "a2"},
                        {nan, 1.0, "a2"},  {inf, 1.0, "a2"},     {-inf, 1.0, "a2"}, {1.0, 0.0, "a3"},
                        {1.0, kPi, "a3"},  {1.0, -1e-300, "a3"}, {1.0, nan, "a3"},  {1.0, inf, "a3"},
                        {1.0, 3.5, "a3"}};
  for (const Case& c : cases) {
    INFO("a2 = " << c.a2 << ", a3 = " << c.a3);
    const InvalidInput e = expect_invalid([&] { GearTrain(c.a2, c.a3, Ratio(1)); });
    CHECK(e.field() == c.field);
    CHECK(contains(e.valid_range(), "(0, pi)"));
    CHECK(contains(e.what(), c.field));
    CHECK(contains(e.what(), "(0, pi)"));
    CHECK_FALSE(e.value().empty());
    // std::invalid_argument is the documented base class.
    CHECK_THROWS_AS(GearTrain(c.a2, c.a3, Ratio(1)), std::invalid_argument);
  }
  // The value is named as given.
  CHECK(expect_invalid([] { GearTrain(4.0, 1.0, Ratio(1)); }).value() == "4");
  CHECK(expect_invalid([&] { GearTrain(nan, 1.0, Ratio(1)); }).value() == "nan");
  CHECK(contains(expect_invalid([&] { GearTrain(1.0, inf, Ratio(1)); }).value(), "inf"));
}

TEST_CASE("GearTrain rejects a non-finite phase with field phase", "[gear_train][errors]") {
  for (double ph : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const InvalidInput e = expect_invalid([&] { GearTrain(1.0, 1.0, Ratio(1), ph); });
    CHECK(e.field() == "phase");
  }
  CHECK_NOTHROW(GearTrain(1.0, 1.0, Ratio(1), -100.0));
}

TEST_CASE("GearTrain accepts a3 just inside (0, pi) and a2 down to 1e-6 from 0 and pi", "[gear_train]") {
  const double lo = std::nextafter(0.0, 1.0);
  const double hi = std::nextafter(kPi, 0.0);
  CHECK_NOTHROW(GearTrain(1.0, lo, Ratio(1)));
  CHECK_NOTHROW(GearTrain(1.0, hi, Ratio(-3, 2)));
  CHECK_NOTHROW(GearTrain(1e-6, 1.0, Ratio(2)));
  CHECK_NOTHROW(GearTrain(kPi - 1e-6, 1.0, Ratio(2)));
  // Closer to 0 or pi the carrier twist is refused (kMinCarrierTwist), never a NaN later.
  for (double a2 : {lo, 1e-300, 1e-10, 9e-7, hi, kPi - 9e-7}) {
    INFO(a2);
    const InvalidInput e = sphtroch::test::expect_invalid([&] { GearTrain(a2, 1.0, Ratio(2)); });
    CHECK(e.field() == "a2");
    CHECK(e.valid_range() == "[1e-6, pi - 1e-6] radians");
  }
}

TEST_CASE("planet and sun cone angles satisfy n = sin a_s / sin a_p and a2 = a_s + a_p (Eq. 2)",
          "[gear_train][cones]") {
  const Ratio ratios[] = {Ratio(1), Ratio(2), Ratio(3), Ratio(5, 2), Ratio(1, 3), Ratio(-3, 2), Ratio(-1, 4), Ratio(7, 5)};
  for (double a2 : {0.3, kPi / 3, kPi / 2, 2.0, 2 * kPi / 3, 3.0}) {
    for (const Ratio& n : ratios) {
      INFO("a2 = " << a2 << ", n = " << n.str());
      const GearTrain train(a2, 1.0, n);
      const double ap = train.planet_cone();
      const double as = train.sun_cone();
      CHECK(ap > 0.0);
      CHECK(ap < kPi);
      CHECK(std::abs((as + ap) - a2) <= 4 * kEps);
      // n sin a_p = sin a_s (Eq. 2): both sides are O(1), so a few ulp.
      CHECK(std::abs(n.value() * std::sin(ap) - std::sin(as)) <= 16 * kEps * (1 + std::abs(n.value())));
    }
  }
}

TEST_CASE("n = 1: the pitch cones are equal, a_p = a_s = a2/2 (Sec. 4.2)", "[gear_train][cones]") {
  for (double a2 : {0.2, 1.0, kPi / 2, 2.5, 3.1}) {
    const GearTrain train(a2, 1.0, Ratio(1));
    CHECK(std::abs(train.planet_cone() - a2 / 2) <= 2 * kEps);
    CHECK(std::abs(train.sun_cone() - a2 / 2) <= 2 * kEps);
  }
}

TEST_CASE("n = 2: a_p = atan(sin a2 / (cos a2 + 2)) (Sec. 5, Typical trajectories)", "[gear_train][cones]") {
  for (double a2 : {0.2, kPi / 3, kPi / 2, 2 * kPi / 3, 3.0}) {
    const GearTrain train(a2, 1.0, Ratio(2));
    // cos a2 + 2 > 0, so the principal arctangent is the cone angle.
    CHECK(std::abs(train.planet_cone() - std::atan(std::sin(a2) / (std::cos(a2) + 2))) <= 4 * kEps);
  }
  // a2 = pi/2: tan a_p = 1/2 exactly.
  CHECK(std::abs(GearTrain(kPi / 2, 1.0, Ratio(2)).planet_cone() - std::atan(0.5)) <= 4 * kEps);
}

TEST_CASE("the closing period is 2 pi q for n = p/q in lowest terms", "[gear_train][period]") {
  CHECK(GearTrain(1.0, 1.0, Ratio(1)).period() == 2 * kPi);
  CHECK(GearTrain(1.0, 1.0, Ratio(3)).period() == 2 * kPi);
  CHECK(GearTrain(1.0, 1.0, Ratio(5, 2)).period() == 4 * kPi);
  CHECK(GearTrain(1.0, 1.0, Ratio(10, 4)).period() == 4 * kPi);
  CHECK(GearTrain(1.0, 1.0, Ratio(-3, 2)).period() == 4 * kPi);
  CHECK(std::abs(GearTrain(1.0, 1.0, Ratio(2, 7)).period() - 14 * kPi) <= 14 * kPi * kEps);
}

TEST_CASE("a3 references: ap, pi-ap, a2, pi-a2 plus an offset", "[gear_train][a3]") {
  const double a2 = 1.1;
  const Ratio n(5, 2);
  const double ap = std::atan2(std::sin(a2), std::cos(a2) + 2.5);
  CHECK(GearTrain::on_cone(a2, A3Reference::pitch_cone, 0.0, n).a3() == ap);
  CHECK(std::abs(GearTrain::on_cone(a2, A3Reference::mirror_pitch_cone, 0.0, n).a3() - (kPi - ap)) <= 2 * kEps);
  CHECK(GearTrain::on_cone(a2, A3Reference::a2, 0.0, n).a3() == a2);
  CHECK(std::abs(GearTrain::on_cone(a2, A3Reference::pi_minus_a2, 0.0, n).a3() - (kPi - a2)) <= 2 * kEps);
  CHECK(std::abs(GearTrain::on_cone(a2, A3Reference::pitch_cone, 1e-6, n).a3() - (ap + 1e-6)) <= 2 * kEps);
  CHECK(GearTrain::on_cone(a2, A3Reference::pitch_cone, 1e-6, n).a3_offset() == 1e-6);
  CHECK(GearTrain::on_cone(a2, A3Reference::pitch_cone, 1e-6, n).a3_reference() == A3Reference::pitch_cone);

  // The symbolic reference evaluates sin/cos of the cone angle itself.
  const auto t = GearTrain::on_cone(a2, A3Reference::pitch_cone, 0.0, n).trig<double>();
  CHECK(std::abs(t.sin_a3 - std::sin(ap)) <= 4 * kEps);
  CHECK(std::abs(t.cos_a3 - std::cos(ap)) <= 4 * kEps);
  const auto m = GearTrain::on_cone(a2, A3Reference::mirror_pitch_cone, -1e-3, n).trig<double>();
  CHECK(std::abs(m.sin_a3 - std::sin(kPi - ap - 1e-3)) <= 4 * kEps);
  CHECK(std::abs(m.cos_a3 - std::cos(kPi - ap - 1e-3)) <= 4 * kEps);

  // A reference plus an offset that leaves (0, pi) is rejected as a3.
  const InvalidInput e = expect_invalid([&] { GearTrain::on_cone(a2, A3Reference::pitch_cone, -1.0, n); });
  CHECK(e.field() == "a3");
  CHECK(contains(e.value(), "ap"));
  CHECK(expect_invalid([&] { GearTrain::on_cone(a2, A3Reference::pi_minus_a2, 2.5, n); }).field() == "a3");
}

TEST_CASE("Ratio and GearTrain are default-constructible: n = 1 and the report's Fig. 3 train", "[gear_train]") {
  const std::vector<Ratio> ratios(3);
  CHECK(ratios[2] == Ratio(1));
  const std::vector<GearTrain> trains(200);
  CHECK(trains[199].a2() == kPi / 2);
  CHECK(trains[199].a3() == kPi / 2);
  CHECK(trains[199].ratio() == Ratio(1));
  CHECK(trains[199].phase() == 0.0);
}

TEST_CASE("GearTrain: D7 a slow planet (|Z1 + n Z2| < 1e-3) is refused only with the tracer near a pitch cone, as "
          "docs/cli.md's limits table says", "[gear_train][errors]") {
  // n = -1: |Z1 + n Z2| = sqrt(2 - 2 cos a2) = 2 sin(a2 / 2), 1e-4 at a2 = 1e-4.
  const double a2 = 1e-4, speed = 2 * std::sin(a2 / 2);
  REQUIRE(speed < sphtroch::kMinPlanetSpeed);
  const double ap = GearTrain::planet_cone_of(a2, Ratio(-1));
  CHECK_NOTHROW(GearTrain(a2, 1.0, Ratio(-1)));                     // far from the cones: accepted
  CHECK_NOTHROW(GearTrain(a2, ap + 2 * sphtroch::kPitchConeGuard, Ratio(-1)));  // beyond the guard
  CHECK(expect_invalid([&] { GearTrain(a2, ap + 0.5 * sphtroch::kPitchConeGuard, Ratio(-1)); }).field() == "a2");
  CHECK(expect_invalid([&] { GearTrain::on_cone(a2, A3Reference::pitch_cone, 0.5, Ratio(-1)); }).field() == "a2");
  // A fast planet near its cone is fine.
  CHECK_NOTHROW(GearTrain(1.0, GearTrain::planet_cone_of(1.0, Ratio(-1)) + 1e-9, Ratio(-1)));
}
