// Tests of sphtroch/io/train_text.hpp: the four texts parsed into the train they name (values
// computed here from the design's formulas), and errors naming the first bad field.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/io/train_text.hpp"

#include <cmath>

using namespace sphtroch;

namespace {
const double kPi = std::acos(-1.0);
}

TEST_CASE("input text: forms of parse.hpp become the train, phase defaulting to 0") {
  const TrainText text{"pi/2", "2pi/3", "5/2"};
  CHECK(text.phase == "0");
  const GearTrain t = text.train();
  CHECK(t.a2() == kPi / 2);
  CHECK(t.a3() == Approx(2 * kPi / 3).epsilon(1e-15));
  CHECK(t.ratio().p() == 5);
  CHECK(t.ratio().q() == 2);
  CHECK(t.phase_given() == 0.0);
}

TEST_CASE("input text: a3 relative to the planet's pitch cone a_p = atan2(sin a2, cos a2 + n)") {
  const TrainText text{"1", "ap+1e-6", "2", "90deg"};
  const GearTrain t = text.train();
  const double ap = std::atan2(std::sin(1.0), std::cos(1.0) + 2.0);  // docs/design.md: the model
  CHECK(t.a3() == Approx(ap + 1e-6).epsilon(1e-14));
  CHECK(t.phase_given() == Approx(kPi / 2).epsilon(1e-15));
}

TEST_CASE("input text: the first text that is not a value, in the order a2, a3, n, phase, is the one named") {
  CHECK(test::expect_invalid([] { TrainText{"x", "x", "0", "y"}.train(); }).field() == "a2");
  CHECK(test::expect_invalid([] { TrainText{"1", "x", "0", "y"}.train(); }).field() == "a3");
  CHECK(test::expect_invalid([] { TrainText{"1", "1", "0", "y"}.train(); }).field() == "n");
  const InvalidInput e = test::expect_invalid([] { TrainText{"1", "1", "2", "nan"}.train(); });
  CHECK(e.field() == "phase");
  CHECK(e.value() == "nan");
}

TEST_CASE("input text: values out of range are named after every text parsed") {
  const InvalidInput e = test::expect_invalid([] { TrainText{"4", "1", "2"}.train(); });
  CHECK(e.field() == "a2");
  CHECK(e.value().rfind("4", 0) == 0);
}
