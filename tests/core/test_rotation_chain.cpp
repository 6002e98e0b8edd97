// Tests of core/rotation_chain.hpp. Expected values: for k = 2, TracerCurve (the report's Eq. 4,
// curve.hpp) bit for bit; for k = 3, 4 a product of Eigen AngleAxis rotations in long double
// written here from the model P(s) = prod_i Rz(N_i s + P_i) Rx(A_i) z; velocity and acceleration
// against central differences of that model (Richardson-extrapolated, long double); the period
// from the joints' angles (each N_i T a whole number of turns, exactly, in integers); MPFR at 60
// digits against double.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/exact/mpreal_support.hpp"  // first: Eigen's MPRealSupport
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/rotation_chain.hpp"

#include <Eigen/Geometry>

#include <optional>
#include <random>

using namespace sphtroch;

namespace {

using Vec3L = Eigen::Matrix<long double, 3, 1>;

Vec3L model_point(const RotationChain& c, long double s) {
  Eigen::Matrix<long double, 3, 3> r = Eigen::Matrix<long double, 3, 3>::Identity();
  for (const ChainStage& st : c.stages()) {
    const long double theta = static_cast<long double>(st.rate.p()) * s / static_cast<long double>(st.rate.q()) + st.phase;
    r = r * Eigen::AngleAxis<long double>(theta, Vec3L::UnitZ()).toRotationMatrix() *
        Eigen::AngleAxis<long double>(st.twist, Vec3L::UnitX()).toRotationMatrix();
  }
  return r.col(2);
}

/// d^k P / ds^k (k = 1, 2) of the model by central differences with one Richardson step.
Vec3L model_derivative(const RotationChain& c, long double s, int k) {
  const auto diff = [&](long double h) {
    if (k == 1) return Vec3L((model_point(c, s + h) - model_point(c, s - h)) / (2 * h));
    return Vec3L((model_point(c, s + h) - 2 * model_point(c, s) + model_point(c, s - h)) / (h * h));
  };
  const long double h = k == 1 ? 1e-4L : 1e-3L;
  return (4 * diff(h / 2) - diff(h)) / 3;
}

RotationChain random_chain(std::mt19937& rng, std::size_t k) {
  std::uniform_real_distribution<double> twist(0.05, 3.09), phase(-3, 3);
  std::uniform_int_distribution<int> num(-5, 5), den(1, 5);
  std::vector<ChainStage> stages;
  for (std::size_t i = 0; i < k; ++i) stages.push_back({twist(rng), ChainRate(i == 0 ? 1 : num(rng), i == 0 ? 1 : den(rng)), phase(rng)});
  return RotationChain(stages);
}

}  // namespace

TEST_CASE("rotation chain, k = 2: the gear train's curve bit for bit, its derivatives within 1e-14", "[chain]") {
  std::mt19937 rng(45);
  std::uniform_real_distribution<double> angle(0.01, 3.13), phase(0, 6.28), s(-50, 50);
  std::uniform_int_distribution<int> num(-9, 9), den(1, 9);
  for (int trial = 0; trial < 1000; ++trial) {
    const int p = num(rng) == 0 ? 1 : num(rng);
    if (p == 0) continue;
    const GearTrain train(angle(rng), angle(rng), Ratio(p, den(rng)), phase(rng));
    const RotationChain chain({{train.a2(), ChainRate(1), 0.0}, {train.a3(), ChainRate(train.ratio().p(), train.ratio().q()), train.phase()}});
    const RotationChain converted = chain_of(train);
    REQUIRE(converted.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK(converted.stages()[i].twist == chain.stages()[i].twist);
      CHECK(converted.stages()[i].rate == chain.stages()[i].rate);
      CHECK(converted.stages()[i].phase == chain.stages()[i].phase);
    }
    const std::optional<GearTrain> back = gear_train_of(chain);
    REQUIRE(back.has_value());
    CHECK(back->a2() == train.a2());
    CHECK(back->a3() == train.a3());
    CHECK(back->ratio() == train.ratio());
    CHECK(back->phase() == train.phase());
    const TracerCurve<double> curve(train);
    const ChainCurve<double> chained(chain);
    CHECK(chain.period() == curve.period());
    for (int k = 0; k < 5; ++k) {
      const double t = s(rng);
      const Vector3d a = curve.point(t), b = chained.point(t);
      CHECK(a == b);
      CHECK((curve.velocity(t) - chained.velocity(t)).norm() <= 1e-14 * (1 + curve.velocity(t).norm()));
      CHECK((curve.acceleration(t) - chained.acceleration(t)).norm() <= 1e-14 * (1 + curve.acceleration(t).norm()));
      CHECK((curve.screw_axis(t) - chained.angular_velocity(t)).norm() <= 1e-14 * (1 + curve.screw_axis(t).norm()));
    }
  }
}

TEST_CASE("rotation chain, k = 2 with any motor rate: gear_train_of gives the same curve, theta2 = N1 s + P1", "[chain]") {
  std::mt19937 rng(46);
  std::uniform_real_distribution<double> angle(0.05, 3.09), phase(-3, 3), s(-20, 20);
  std::uniform_int_distribution<int> num(-6, 6), den(1, 6);
  for (int trial = 0; trial < 300; ++trial) {
    const int p1 = num(rng), p2 = num(rng);
    if (p1 == 0 || p2 == 0) continue;
    const RotationChain chain({{angle(rng), ChainRate(p1, den(rng)), phase(rng)}, {angle(rng), ChainRate(p2, den(rng)), phase(rng)}});
    const std::optional<GearTrain> train = gear_train_of(chain);
    REQUIRE(train.has_value());
    const TracerCurve<double> curve(*train);
    const double n1 = chain.stages()[0].rate.value(), p = chain.stages()[0].phase;
    for (int k = 0; k < 5; ++k) {
      const double t = s(rng), theta2 = n1 * t + p;
      CHECK((model_point(chain, t) - curve.point(theta2).cast<long double>()).norm() < 1e-12);
      CHECK(std::fabs(chain_param_of_theta2(chain, theta2) - t) < 1e-12 * (1 + std::fabs(t)));
    }
  }
  // Not a gear train: k = 3, a rate 0, a twist of 0.
  CHECK_FALSE(gear_train_of(RotationChain({{1.0, ChainRate(1), 0.0}, {1.0, ChainRate(2), 0.0}, {1.0, ChainRate(3), 0.0}})).has_value());
  CHECK_FALSE(gear_train_of(RotationChain({{1.0, ChainRate(0), 0.0}, {1.0, ChainRate(2), 0.0}})).has_value());
  CHECK_FALSE(gear_train_of(RotationChain({{0.0, ChainRate(1), 0.0}, {1.0, ChainRate(2), 0.0}})).has_value());
}

TEST_CASE("rotation chain, k = 3 and 4: a product of rotation matrices, its derivatives, its period", "[chain]") {
  std::mt19937 rng(4545);
  std::uniform_real_distribution<double> s(-20, 20);
  for (int trial = 0; trial < 400; ++trial) {
    const RotationChain chain = random_chain(rng, trial % 2 ? 3 : 4);
    const ChainCurve<double> curve(chain);
    for (int k = 0; k < 4; ++k) {
      const double t = s(rng);
      const Vec3L expected = model_point(chain, t);
      CHECK((curve.point(t).cast<long double>() - expected).norm() <= 1e-13L);
      const Vec3L v = model_derivative(chain, t, 1), a = model_derivative(chain, t, 2);
      CHECK((curve.velocity(t).cast<long double>() - v).norm() <= 1e-7L * (1 + v.norm()));
      CHECK((curve.acceleration(t).cast<long double>() - a).norm() <= 1e-5L * (1 + a.norm()));
    }
    // The period: N_i L / g is an integer for every joint (each turns whole turns), and for no
    // smaller s do all of them (the gcd of those integers is 1).
    std::int64_t g = 0;
    for (const ChainStage& st : chain.stages()) {
      const std::int64_t scaled = st.rate.p() * (chain.common_denominator() / st.rate.q());
      CHECK(scaled % chain.numerator_gcd() == 0);
      g = std::gcd(g, scaled / chain.numerator_gcd());
    }
    CHECK(g == 1);
    const double t = s(rng);
    CHECK((model_point(chain, t) - model_point(chain, static_cast<long double>(t) + chain.period())).norm() <= 1e-12L);
  }
}

TEST_CASE("rotation chain: MPFR at 60 digits agrees with double", "[chain]") {
  const MpfrPrecision precision(200);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const RotationChain chain = random_chain(rng, 3 + trial % 3);
    const ChainCurve<double> d(chain);
    const ChainCurve<mpfr_real> m(chain);
    const double t = 0.37 * trial - 5;
    const Vector3<mpfr_real> p = m.point(mpfr_real(t));
    for (int i = 0; i < 3; ++i) CHECK(std::fabs(d.point(t)(i) - p(i).toDouble()) <= 1e-14);
    CHECK(mpfr::abs(p.norm() - 1) <= mpfr_real("1e-50"));
  }
}

TEST_CASE("rotation chain: bad chains are refused naming the option", "[chain]") {
  const double nan = std::nan("");
  CHECK(test::expect_invalid([] { RotationChain({}); }).field() == "twists");
  CHECK(test::expect_invalid([&] { RotationChain({{nan, ChainRate(1), 0}}); }).field() == "twists");
  CHECK(test::expect_invalid([] { RotationChain({{-0.1, ChainRate(1), 0}}); }).field() == "twists");
  CHECK(test::expect_invalid([] { RotationChain({{3.2, ChainRate(1), 0}}); }).field() == "twists");
  CHECK(test::expect_invalid([] { RotationChain({{1, ChainRate(1), std::numeric_limits<double>::infinity()}}); }).field() == "phases");
  CHECK(test::expect_invalid([] { RotationChain({{1, ChainRate(0), 0}, {2, ChainRate(0, 7), 0}}); }).field() == "rates");
  CHECK(test::expect_invalid([] { ChainRate(1, 0); }).field() == "rates");
  CHECK(test::expect_invalid([] { ChainRate(2000000, 1); }).field() == "rates");
  CHECK(test::expect_invalid([] {
          RotationChain({{1, ChainRate(1, 999983), 0}, {1, ChainRate(1, 999979), 0}, {1, ChainRate(1, 999961), 0}});
        }).field() == "rates");  // three large primes: the lcm is ~1e18
  // A joint turning 1e12 times a period: its angle would lose whole radians in double.
  CHECK(test::expect_invalid([] { RotationChain({{1, ChainRate(1000000), 0}, {1, ChainRate(1, 999983), 0}}); }).field() == "rates");
  // Twists 0 and pi (coaxial joints) are chains.
  CHECK(RotationChain({{0.0, ChainRate(1), 0}, {Constants<double>::pi(), ChainRate(2), 0}}).size() == 2);
}
