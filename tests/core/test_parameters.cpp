// Tests of parameters.hpp: reduction modulo the period, distance on the circle of parameters,
// theta2 at a planet angle (checked against Eq. 3 directly) and the frames (checked against
// Eigen's AngleAxis, an independent construction of the same rotations).
#include "test_support.hpp"

#include "sphtroch/core/parameters.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

using namespace sphtroch;

namespace {
const double kPi = Constants<double>::pi();
}

TEST_CASE("reduce_to_period lands in 0 <= t < period, also at the edges", "[parameters]") {
  const double period = 2 * kPi * 3;
  CHECK(reduce_to_period(0.0, period) == 0.0);
  CHECK(reduce_to_period(period, period) == 0.0);
  CHECK(reduce_to_period(-period, period) == 0.0);
  // -tiny + period rounds to period in double: the edge rule gives 0, never period.
  CHECK(reduce_to_period(-1e-300, period) == 0.0);
  CHECK(reduce_to_period(-1e-20L, static_cast<long double>(period)) == 0.0L);
  for (double x : {-100.5, -3.0, 0.25, 7.0, 1e6, -1e6}) {
    const double r = reduce_to_period(x, period);
    CHECK(r >= 0.0);
    CHECK(r < period);
    const double turns = (x - r) / period;  // an integer number of periods was removed
    CHECK(std::abs(turns - std::round(turns)) < 1e-9);
  }
}

TEST_CASE("periodic_distance is symmetric, at most half the period, and ignores whole periods", "[parameters]") {
  const double period = 2 * kPi;
  CHECK(periodic_distance(0.1, period - 0.1, period) == Approx(0.2).margin(1e-15));
  CHECK(periodic_distance(period - 0.1, 0.1, period) == Approx(0.2).margin(1e-15));
  CHECK(periodic_distance(1.0, 1.0 + 5 * period, period) == Approx(0.0).margin(1e-14));
  CHECK(periodic_distance(0.0, kPi, period) == Approx(kPi).margin(1e-15));
  for (double a : {0.0, 1.0, 4.0, -2.0})
    for (double b : {0.5, 3.0, 6.2, -7.0}) CHECK(periodic_distance(a, b, period) <= period / 2 + 1e-15);
}

TEST_CASE("theta2_at_planet_angle solves Eq. 3 for every ratio sign and phase", "[parameters]") {
  for (const Ratio& n : {Ratio(1), Ratio(5, 2), Ratio(-3, 2), Ratio(7, 3), Ratio(-4)}) {
    for (double phase : {0.0, 0.4, -2.5}) {
      const GearTrain train(1.0, 2.0, n, phase);
      for (double theta3 : {0.0, kPi, 1.0}) {
        const std::vector<double> ts = params_at_planet_angle(train, theta3);
        REQUIRE(ts.size() == static_cast<std::size_t>(n.abs_p()));
        for (std::size_t i = 0; i < ts.size(); ++i) {
          CHECK(ts[i] >= 0.0);
          CHECK(ts[i] < train.period());
          if (i > 0) CHECK(ts[i] > ts[i - 1]);
          // Eq. 3: n theta2 + theta_p = theta3 (mod 2 pi), with the train's reduced phase.
          const double th = n.value() * ts[i] + train.phase() - theta3;
          CHECK(std::abs(std::remainder(th, 2 * kPi)) < 1e-12 * (1 + std::abs(n.value()) * train.period()));
        }
      }
    }
  }
}

TEST_CASE("base_R_carrier is Rz(theta2) Rx(a2) (Eq. 4) and uses the train's exact cosines", "[parameters]") {
  const GearTrain train(0.7, 1.9, Ratio(2));
  for (double t : {0.0, 0.3, 2.5, -1.0}) {
    const Matrix3d expected = (Eigen::AngleAxisd(t, Vector3d::UnitZ()) * Eigen::AngleAxisd(0.7, Vector3d::UnitX())).toRotationMatrix();
    const Matrix3d r = base_R_carrier(t, train.trig<double>());
    CHECK((r - expected).norm() < 1e-15);
    CHECK((r.transpose() * r - Matrix3d::Identity()).norm() < 1e-15);
  }
  // a2 taken as exactly pi/2 (as classify reads it): cos a2 is exactly 0 in the frame
  // (GearTrain::trig), not cos(double(pi/2)) = 6e-17.
  const GearTrain right = GearTrain(kPi / 2, 1.0, Ratio(1)).with_right_angle_a2();
  CHECK(base_R_carrier(0.0, right.trig<double>())(1, 1) == 0.0);
  CHECK((rotation_z(kPi / 2) * Vector3d::UnitX() - Vector3d::UnitY()).norm() < 1e-15);
}
