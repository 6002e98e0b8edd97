// Tests for sphtroch/core/sampling.hpp: sample counts, the closed trajectory over one period
// (2 pi q, no duplicate endpoint), the open trajectory over K carrier turns (both ends), the
// velocity columns, and the bounds on sample counts and turns.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/core/sampling.hpp"

#include <cmath>
#include <limits>

using namespace sphtroch;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();

using sphtroch::test::expect_invalid;
}  // namespace

TEST_CASE("sample_period: N samples t_i = 2 pi q i / N over 0 <= t < 2 pi q, closed, no duplicate endpoint",
          "[sampling][closed]") {
  for (const Ratio& n : {Ratio(1), Ratio(2), Ratio(5, 2), Ratio(-3, 2), Ratio(2, 7)}) {
    const TracerCurve<double> curve(GearTrain(kPi / 2, 1.1, n, 0.2));
    const double period = 2 * kPi * static_cast<double>(n.q());
    for (std::size_t count : {std::size_t(3), std::size_t(8), std::size_t(1000)}) {
      INFO("n = " << n.str() << " N = " << count);
      const auto tr = sample_period(curve, count);
      CHECK(tr.closed);
      REQUIRE(tr.size() == count);
      REQUIRE(tr.points.size() == count);
      CHECK(tr.velocities.empty());
      CHECK(tr.t.front() == 0.0);
      for (std::size_t i = 0; i < count; ++i) {
        CHECK(std::abs(tr.t[i] - period * static_cast<double>(i) / static_cast<double>(count)) <= 2 * kEps * period);
        if (i > 0) CHECK(tr.t[i] > tr.t[i - 1]);
        // Each point is P(t_i) (the chain itself is tested in test_curve.cpp).
        CHECK((tr.points[i] - curve.point(tr.t[i])).norm() == 0.0);
      }
      // The last sample is one step short of the period: the closing edge joins it to the first.
      CHECK(tr.t.back() < period);
      CHECK(std::abs((period - tr.t.back()) - period / static_cast<double>(count)) <= 4 * kEps * period);
      // No duplicate endpoint: the last point is not the first one again.
      CHECK((tr.points.back() - tr.points.front()).norm() > 1e-6);
      // ... while P(period) is (closure), so one more step would duplicate it.
      CHECK((curve.point(period) - tr.points.front()).norm() <= 1e-13);
    }
  }
}

TEST_CASE("sample_turns: N samples over [0, 2 pi K], both ends included, open", "[sampling][open]") {
  const TracerCurve<double> curve(GearTrain(1.0, 2.0, Ratio(355, 113)));
  for (double turns : {0.5, 1.0, 2.5, 7.0}) {
    for (std::size_t count : {std::size_t(3), std::size_t(17), std::size_t(2001)}) {
      INFO("K = " << turns << " N = " << count);
      const auto tr = sample_turns(curve, turns, count);
      CHECK_FALSE(tr.closed);
      REQUIRE(tr.size() == count);
      CHECK(tr.t.front() == 0.0);
      const double end = 2 * kPi * turns;
      CHECK(std::abs(tr.t.back() - end) <= 2 * kEps * end);
      for (std::size_t i = 1; i < count; ++i) {
        CHECK(tr.t[i] > tr.t[i - 1]);
        CHECK(std::abs(tr.t[i] - end * static_cast<double>(i) / static_cast<double>(count - 1)) <= 2 * kEps * end);
      }
    }
  }
}

TEST_CASE("sampling with velocity stores dP/dtheta2 at every sample", "[sampling][velocity]") {
  const TracerCurve<double> curve(GearTrain(kPi / 3, kPi / 2, Ratio(2)));
  const auto closed = sample_period(curve, 36, true);
  REQUIRE(closed.velocities.size() == 36);
  for (std::size_t i = 0; i < closed.size(); ++i) CHECK((closed.velocities[i] - curve.velocity(closed.t[i])).norm() == 0.0);
  const auto open = sample_turns(curve, 1.5, 10, true);
  REQUIRE(open.velocities.size() == 10);
}

TEST_CASE("sample counts outside 3 .. 10000000 and turns outside 0 < K <= 1e6 throw InvalidInput", "[sampling][errors]") {
  const TracerCurve<double> curve(GearTrain(1.0, 1.0, Ratio(1)));
  CHECK(kMinSamples == 3);
  CHECK(kMaxSamples == 10000000);
  for (std::size_t bad : {std::size_t(0), std::size_t(1), std::size_t(2), kMaxSamples + 1,
                          std::numeric_limits<std::size_t>::max()}) {
    INFO("N = " << bad);
    const InvalidInput e = expect_invalid([&] { sample_period(curve, bad); });
    CHECK(e.field() == "samples");
    CHECK(e.valid_range().find("3") != std::string::npos);
    CHECK(e.valid_range().find("10000000") != std::string::npos);
    CHECK(expect_invalid([&] { sample_turns(curve, 1.0, bad); }).field() == "samples");
  }
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     kMaxTurns * 2}) {
    INFO("K = " << bad);
    CHECK(expect_invalid([&] { sample_turns(curve, bad, 10); }).field() == "turns");
  }
  CHECK_NOTHROW(sample_period(curve, 3));
  CHECK_NOTHROW(sample_turns(curve, kMaxTurns, 3));
}

TEST_CASE("min_samples_for_short_arcs keeps every closed-curve step below pi", "[sampling]") {
  // |dP/dtheta2| <= |omega| <= 1 + |n|, so a step of 2 pi q / N moves P by an arc of at most
  // 2 pi q (1 + |n|) / N = 2 pi (q + |p|) / N < pi when N > 2 (q + |p|).
  for (const Ratio& n : {Ratio(1), Ratio(3), Ratio(5, 2), Ratio(-7, 3)}) {
    const GearTrain train(2.0, 2.5, n);
    const std::size_t m = min_samples_for_short_arcs(train);
    CHECK(m > static_cast<std::size_t>(2 * (n.q() + n.abs_p())));
    const TracerCurve<double> curve(train);
    const auto tr = sample_period(curve, m);
    for (std::size_t i = 0; i < tr.size(); ++i) {
      const auto& a = tr.points[i];
      const auto& b = tr.points[(i + 1) % tr.size()];
      CHECK(std::atan2(a.cross(b).norm(), a.dot(b)) < kPi);
    }
  }
}
