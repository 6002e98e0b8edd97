// Tests of core/kinematics.hpp. Expected values: finite differences of the 256-bit MPFR trace
// (Eq. 4 through TracerCurve<mpreal>, central differences with h = 1e-25: truncation 1e-50),
// the cusps of the pitch-cone criterion (map/criteria.hpp, an independent code path), and a brute
// force scan of the speed for the dwell points.
#include "catch2/catch.hpp"
#include "sphtroch/exact/mpreal_support.hpp"  // first: Eigen's MPRealSupport
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/kinematics.hpp"
#include "sphtroch/map/criteria.hpp"

#include <cmath>
#include <random>
#include <vector>

using namespace sphtroch;
using mpfr::mpreal;

namespace {

const double kPi = Constants<double>::pi();

struct Reference {
  double speed, tangential_acceleration, geodesic_curvature;
};

/// speed, d|V|/dtheta2 and det(P, V, A)/|V|^3 from central differences of the MPFR curve.
Reference mpfr_reference(const GearTrain& train, double theta2) {
  mpreal::set_default_prec(256);
  const TracerCurve<mpreal> curve(train);
  const mpreal t(theta2), h("1e-25");
  const Vector3<mpreal> p0 = curve.point(t), pp = curve.point(t + h), pm = curve.point(t - h);
  const Vector3<mpreal> v = (pp - pm) / (2 * h);
  const Vector3<mpreal> a = (pp - 2 * p0 + pm) / (h * h);
  const mpreal speed = v.norm();
  return {speed.toDouble(), (v.dot(a) / speed).toDouble(), (p0.dot(v.cross(a)) / (speed * speed * speed)).toDouble()};
}

GearTrain random_train(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto term = [&] { return static_cast<std::int64_t>(1 + rng() % 7); };
  const std::int64_t p = (rng() % 2 ? -1 : 1) * term();
  return GearTrain(0.15 + u(rng) * (kPi - 0.3), 0.15 + u(rng) * (kPi - 0.3), Ratio(p, term()), 2 * kPi * u(rng));
}

}  // namespace

TEST_CASE("kinematics: speed, tangential acceleration and geodesic curvature equal MPFR finite differences",
          "[kinematics]") {
  std::mt19937_64 rng(47);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (int k = 0; k < 200; ++k) {
    const GearTrain train = random_train(rng);
    const TracerCurve<double> curve(train);
    const double theta2 = u(rng) * train.period();
    const PathKinematics got = path_kinematics(curve, theta2);
    const Reference ref = mpfr_reference(train, theta2);
    const double accel = curve.acceleration(theta2).norm();  // the scale of d|V|
    INFO("train " << train.a2() << ", " << train.a3() << ", " << train.ratio().str() << ", theta2 " << theta2);
    if (ref.speed < 1e-3) continue;  // next to a cusp the curvature is ill-conditioned (see header)
    CHECK(std::fabs(got.speed - ref.speed) <= 1e-9 * ref.speed);
    CHECK(std::fabs(got.tangential_acceleration - ref.tangential_acceleration) <= 1e-9 * std::max(accel, 1.0));
    CHECK(std::fabs(got.geodesic_curvature - ref.geodesic_curvature) <= 1e-9 * std::max(std::fabs(ref.geodesic_curvature), 1.0));
    // Eq. 47a: the speed is |omega x P|, omega = Z1 + n Z2.
    CHECK(std::fabs(got.speed - curve.screw_axis(theta2).cross(curve.point(theta2)).norm()) <= 1e-15 * got.speed);
    ++checked;
  }
  CHECK(checked >= 190);
}

TEST_CASE("kinematics: on a pitch cone the cusps are dwell points at speed 0, and no other one is", "[kinematics]") {
  for (const Ratio n : {Ratio(1), Ratio(2), Ratio(5, 2), Ratio(-3, 2), Ratio(7, 3)}) {
    for (const double a2 : {0.4, 1.0, 2.2}) {
      const GearTrain base(a2, 1.0, n, 0.3);
      const GearTrain on_cone(a2, base.planet_cone(), n, 0.3);
      const TracerCurve<double> curve(on_cone);
      const std::vector<DwellPoint> dwell = dwell_points(curve);
      const std::vector<AnalyticCusp> cusps = pitch_cone_cusps(on_cone);
      INFO("n = " << n.str() << ", a2 = " << a2);
      CHECK(cusps.size() == static_cast<std::size_t>(std::llabs(n.p())));  // one contact per planet turn
      std::size_t stops = 0;
      for (const DwellPoint& d : dwell) {
        bool at_a_cusp = false;
        for (const AnalyticCusp& c : cusps) at_a_cusp = at_a_cusp || (c.position - d.position).norm() <= 1e-9;
        if (at_a_cusp) {
          CHECK(d.speed <= 1e-12);
          ++stops;
        } else {
          CHECK(d.speed > 1e-3);  // a slow point between cusps, not a stop
        }
      }
      CHECK(stops == cusps.size());
    }
  }
}

TEST_CASE("kinematics: dwell points are exactly the local speed minima a fine scan finds", "[kinematics]") {
  std::mt19937_64 rng(48);
  for (int k = 0; k < 40; ++k) {
    const GearTrain train = random_train(rng);
    const TracerCurve<double> curve(train);
    const std::vector<DwellPoint> dwell = dwell_points(curve);
    // Brute force: 200 (|p| + q) samples, discrete local minima of the speed.
    const std::size_t m = 200 * static_cast<std::size_t>(std::llabs(train.ratio().p()) + train.ratio().q());
    const double step = train.period() / double(m);
    std::vector<double> speed(m);
    for (std::size_t i = 0; i < m; ++i) speed[i] = curve.velocity(step * double(i)).norm();
    std::size_t minima = 0;
    for (std::size_t i = 0; i < m; ++i) {
      if (!(speed[i] < speed[(i + m - 1) % m] && speed[i] <= speed[(i + 1) % m])) continue;
      ++minima;
      bool listed = false;
      for (const DwellPoint& d : dwell) {
        const double gap = std::fabs(std::remainder(d.param - step * double(i), train.period()));
        listed = listed || (gap <= step && d.speed <= speed[i] + 1e-15);
      }
      INFO("train " << train.a2() << ", " << train.a3() << ", " << train.ratio().str() << ", sample " << i);
      CHECK(listed);
    }
    CHECK(dwell.size() == minima);
    for (const DwellPoint& d : dwell) {  // each is a local minimum
      CHECK(d.param >= 0.0);
      CHECK(d.param < train.period());
      CHECK(curve.velocity(d.param + 1e-5).norm() >= d.speed);
      CHECK(curve.velocity(d.param - 1e-5).norm() >= d.speed);
    }
  }
}

TEST_CASE("kinematics: two shallow speed minima close together (a3 next to atan2(cos a2 + n, sin a2)) are both found",
          "[kinematics]") {
  // Found by a review: a scan of 64 (|p| + q) samples stepped over the pair. A brute-force scan of
  // 400,000 samples (step 1.6e-5 rad, the pair ~0.008 rad apart for eps = 1e-4) is the reference.
  for (const double eps : {1e-3, 1e-4, 1e-6}) {
    const GearTrain train(1.0, std::atan2(std::cos(1.0) + 2.0, std::sin(1.0)) + eps, Ratio(2), 0.2);
    const TracerCurve<double> curve(train);
    const std::size_t m = 400000;
    const double step = train.period() / double(m);
    std::vector<double> speed(m);
    for (std::size_t i = 0; i < m; ++i) speed[i] = curve.velocity(step * double(i)).norm();
    std::size_t minima = 0;
    for (std::size_t i = 0; i < m; ++i)
      minima += speed[i] < speed[(i + m - 1) % m] && speed[i] <= speed[(i + 1) % m];
    INFO("eps = " << eps);
    if (eps >= 1e-4) CHECK(minima == 4);  // at 1e-6 the pair is 8e-4 apart but 1e-12 deep: below the scan's rounding
    CHECK(dwell_points(curve).size() == 4);
  }
}

