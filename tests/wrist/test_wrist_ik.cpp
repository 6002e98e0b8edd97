// wrist/: the certified inverse kinematics of geared wrists (include/sphtroch/wrist/) against
// what is written here independently (tests/wrist/wrist_reference.hpp): on random 2-motor wrists
// (k = 3, 4, coupling entries of height <= 5) the certified count equals a grid + Gauss-Newton
// count and every solution points the tool within 1e-12 (a product of AngleAxis rotations in long
// double); the base x gear train wrist has 2 |p| solutions inside the zone of the report's Eqs.
// 14/15 and none outside; the spherical 3R wrist (identity coupling) has its closed-form
// solutions; a target on a fold is reported undecided (on_fold); the cost bound and the model's
// refusals.
#include "catch2/catch.hpp"
#include "test_support.hpp"
#include "wrist/wrist_reference.hpp"
#include "wrist/wrist_test_models.hpp"

#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_text.hpp"

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace sphtroch;
using namespace sphtroch::test;

constexpr long double kPiL = 3.141592653589793238462643383279502884L;

std::vector<long double> as_long(const std::vector<double>& u) { return {u.begin(), u.end()}; }

}  // namespace

TEST_CASE("wrist ik: 200 random 2-motor wrists x 50 targets: the certified count is the grid and Newton count", "[wrist]") {
  std::mt19937 rng(61);
  std::size_t problems = 0, certified = 0, solutions = 0, disagreements = 0;
  double worst = 0;
  for (int mechanism = 0; mechanism < 200; ++mechanism) {
    const WristModel m = random_wrist(rng, 400);
    const Wrist wrist = library_wrist(m);
    const GridCount reference(m, 0.15);
    for (int target = 0; target < 50; ++target) {
      const Eigen::Vector3d t = random_direction(rng);
      const WristIkResult r = wrist_ik(wrist, WristTarget::pointing(t));
      ++problems;
      for (const WristSolution& s : r.solutions) {
        const double error = double((m.point(as_long(s.motors)) - t.cast<long double>()).norm());
        worst = std::max(worst, error);
        for (std::size_t j = 0; j < 2; ++j) CHECK((s.motors[j] >= 0 && s.motors[j] < double(m.period(j))));
      }
      if (!r.certified) continue;
      ++certified;
      solutions += r.solutions.size();
      const auto roots = reference.roots(t);
      if (roots.size() != r.solutions.size()) {
        ++disagreements;
        UNSCOPED_INFO("coupling " << wrist.coupling_text() << " twists " << wrist.twists_text() << " target " << t.transpose()
                                  << ": certified " << r.solutions.size() << ", grid " << roots.size());
        continue;
      }
      for (const WristSolution& s : r.solutions)
        CHECK(std::any_of(roots.begin(), roots.end(), [&](const std::vector<long double>& v) { return reference.same(as_long(s.motors), v); }));
    }
  }
  INFO(problems << " problems, " << certified << " certified, " << solutions << " solutions, worst |P - t| " << worst);
  CHECK(disagreements == 0);
  CHECK(worst < 1e-12);
  CHECK(certified >= problems * 99 / 100);  // random targets are off the folds: undecided ones are rare
  CHECK(solutions > problems);              // the sample is not trivial
}

TEST_CASE("wrist ik: the base x gear train wrist has 2 |p| solutions inside the zone of Eqs. 14/15 and none outside", "[wrist]") {
  // Twists (0, a2, a3), coupling 1,0;0,1;0,n: P(u) = Rz(u1) P_train(u2), P_train the report's Eq. 4
  // with theta2 = u2, whose z = cos a2 cos a3 - sin a2 sin a3 cos(n u2) runs over [cos(a2 + a3),
  // cos(a2 - a3)] (Eqs. 14/15: the z extremes). For z strictly inside, cos(n u2) = c has 2 |p|
  // roots u2 in motor 2's period 2 pi q (n u2 sweeps 2 pi |p|), and each fixes u1 (mod 2 pi) by the
  // azimuth (|z| < 1); outside, none.
  std::mt19937 rng(1415);
  std::uniform_real_distribution<double> angle(0.2, 2.9), uniform(0, 1);
  const std::vector<std::pair<int, int>> ratios{{1, 1}, {2, 1}, {3, 2}, {-5, 3}, {7, 4}, {-1, 2}, {4, 1}};
  std::size_t inside = 0, outside = 0;
  for (const auto& [p, q] : ratios)
    for (int trial = 0; trial < 12; ++trial) {
      WristModel m{{0.0, angle(rng), angle(rng)}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}, {{0, 1}, {p, q}}}};
      const double zmin = std::cos(m.twist[1] + m.twist[2]), zmax = std::cos(m.twist[1] - m.twist[2]);
      const bool in = trial % 3 != 0;
      const double z = in ? zmin + (0.02 + 0.96 * uniform(rng)) * (zmax - zmin)
                          : (uniform(rng) < 0.5 && zmax < 0.98 ? zmax + (0.01 + 0.98 * uniform(rng)) * (1 - zmax)
                                                               : zmin - (0.01 + 0.98 * uniform(rng)) * (zmin + 1));
      if (!in && (zmin < -0.98 && zmax > 0.98)) continue;  // no room outside the zone
      const double azimuth = 6.283185307179586 * uniform(rng), rho = std::sqrt(1 - z * z);
      const Eigen::Vector3d t(rho * std::cos(azimuth), rho * std::sin(azimuth), z);
      const WristIkResult r = wrist_ik(library_wrist(m), WristTarget::pointing(t));
      INFO("n = " << p << "/" << q << ", a2 = " << m.twist[1] << ", a3 = " << m.twist[2] << ", z = " << z);
      REQUIRE(r.certified);
      CHECK(r.solutions.size() == (in ? 2u * std::size_t(std::abs(p)) : 0u));
      for (const WristSolution& s : r.solutions) {
        const long double zu = std::cos((long double)m.twist[1]) * std::cos((long double)m.twist[2]) -
                               std::sin((long double)m.twist[1]) * std::sin((long double)m.twist[2]) *
                                   std::cos((long double)p * s.motors[1] / q);
        CHECK(std::fabs(double(zu) - z) < 1e-12);
        CHECK(double((m.point(as_long(s.motors)) - t.cast<long double>()).norm()) < 1e-12);
      }
      (in ? inside : outside) += 1;
    }
  CHECK(inside >= 50);
  CHECK(outside >= 20);
}

namespace {

/// The closed-form solutions of the spherical 3R wrist F = Rz(u1 + f1) Rx(A1) Rz(u2 + f2) Rx(A2)
/// Rz(u3 + f3) Rx(A3) = R: with G = R Rx(A3)^T, w = G z = Rz(t1) Rx(A1) Rz(t2) Rx(A2) z, so
/// w_z = cA1 cA2 - sA1 sA2 cos t2 (two t2 or none), t1 by the azimuth of w, t3 from what is left.
std::vector<std::vector<long double>> three_r_solutions(const WristModel& m, const Mat3L& r, long double& cosine) {
  const long double a1 = m.twist[0], a2 = m.twist[1], a3 = m.twist[2];
  const Mat3L g = r * Eigen::AngleAxis<long double>(a3, Vec3L::UnitX()).toRotationMatrix().transpose();
  const Vec3L w = g.col(2);
  cosine = (std::cos(a1) * std::cos(a2) - w.z()) / (std::sin(a1) * std::sin(a2));
  std::vector<std::vector<long double>> out;
  if (std::fabs(cosine) >= 1) return out;
  for (const long double t2 : {std::acos(cosine), -std::acos(cosine)}) {
    const Vec3L v(std::sin(a2) * std::sin(t2), -std::cos(a1) * std::sin(a2) * std::cos(t2) - std::sin(a1) * std::cos(a2),
                  -std::sin(a1) * std::sin(a2) * std::cos(t2) + std::cos(a1) * std::cos(a2));
    const long double t1 = std::atan2(w.y(), w.x()) - std::atan2(v.y(), v.x());
    const Mat3L head = Eigen::AngleAxis<long double>(t1, Vec3L::UnitZ()).toRotationMatrix() *
                       Eigen::AngleAxis<long double>(a1, Vec3L::UnitX()).toRotationMatrix() *
                       Eigen::AngleAxis<long double>(t2, Vec3L::UnitZ()).toRotationMatrix() *
                       Eigen::AngleAxis<long double>(a2, Vec3L::UnitX()).toRotationMatrix();
    const Mat3L rest = head.transpose() * g;
    const long double t3 = std::atan2(rest(1, 0), rest(0, 0));
    std::vector<long double> u{t1 - m.phase[0], t2 - m.phase[1], t3 - m.phase[2]};
    for (long double& x : u) x -= 2 * kPiL * std::floor(x / (2 * kPiL));
    out.push_back(u);
  }
  return out;
}

}  // namespace

TEST_CASE("wrist ik: the spherical 3R wrist has its closed-form solutions (10^4 orientations)", "[wrist]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> twist(0.2, 2.94), phase(-3.14, 3.14);
  std::normal_distribution<double> g;
  std::size_t compared = 0, two = 0, near_singular = 0;
  double worst = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    WristModel m{{twist(rng), twist(rng), twist(rng)}, {phase(rng), phase(rng), phase(rng)},
                 {{{1, 1}, {0, 1}, {0, 1}}, {{0, 1}, {1, 1}, {0, 1}}, {{0, 1}, {0, 1}, {1, 1}}}};
    const Eigen::Quaterniond q = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
    const WristTarget target = WristTarget::orientation(q);
    long double cosine = 0;
    const auto expected = three_r_solutions(m, q.cast<long double>().toRotationMatrix(), cosine);
    if (std::fabs(std::fabs(cosine) - 1) < 1e-6) {  // within 1e-6 of a singular orientation: a near-double root
      ++near_singular;
      continue;
    }
    const WristIkResult r = wrist_ik(library_wrist(m), target);
    INFO("twists " << m.twist[0] << "," << m.twist[1] << "," << m.twist[2] << ", cos t2 = " << double(cosine));
    REQUIRE(r.certified);
    REQUIRE(r.solutions.size() == expected.size());
    for (const WristSolution& s : r.solutions) {
      double best = 1;
      for (const auto& e : expected) {
        double d = 0;
        for (std::size_t j = 0; j < 3; ++j) d = std::max(d, double(std::fabs(std::remainder((long double)s.motors[j] - e[j], 2 * kPiL))));
        best = std::min(best, d);
      }
      worst = std::max(worst, best);
    }
    ++compared;
    two += expected.size() == 2;
  }
  INFO(compared << " compared, " << two << " with two solutions, " << near_singular << " near a singular orientation, worst " << worst);
  CHECK(worst < 1e-12);
  CHECK(compared >= 9900);
  CHECK(two >= 3000);
}

TEST_CASE("wrist ik: a target on a fold is a double root, reported undecided (on_fold)", "[wrist]") {
  // Twists (pi/2, pi/4), identity coupling: z = cos A1 cos A2 - sin A1 sin A2 cos u2 reaches its
  // largest value cos(A1 - A2) = sqrt(2)/2 (a fold: dz/du2 = 0) at u2 = pi, a double root of z(u2) = z_t.
  const WristModel m{{1.5707963267948966, 0.7853981633974483}, {0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}}};
  const double z = std::cos(m.twist[0] - m.twist[1]);
  const Eigen::Vector3d t(std::sqrt(1 - z * z), 0, z);
  const WristIkResult r = wrist_ik(library_wrist(m), WristTarget::pointing(t));
  CHECK_FALSE(r.certified);
  CHECK(r.on_fold);
  CHECK(r.why.find("fold") != std::string::npos);
  REQUIRE_FALSE(r.undecided_at.empty());
  CHECK(std::fabs(r.undecided_at.front()[1] - 3.141592653589793) < 1e-6);  // at u2 = pi
  // Just inside the zone the two roots are apart and certified; just outside there is none.
  for (const double dz : {-1e-6, 1e-6}) {
    const double z2 = z + dz;
    const WristIkResult s = wrist_ik(library_wrist(m), WristTarget::pointing(Eigen::Vector3d(std::sqrt(1 - z2 * z2), 0, z2)));
    CHECK(s.certified);
    CHECK(s.solutions.size() == (dz < 0 ? 2u : 0u));
  }
}

TEST_CASE("wrist ik: a problem beyond the cost bound is refused up front with its cost", "[wrist]") {
  // Column 2 has denominators 1000: motor 2's period is 2000 pi, and both columns turn joints fast.
  const Wrist big({{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}},
                  {{ChainRate(5), ChainRate(1, 1000)}, {ChainRate(3), ChainRate(999, 1000)}, {ChainRate(1), ChainRate(7)}});
  const double start = wrist_ik_start_boxes(big);
  CHECK(start == std::ceil(2 * 3.141592653589793 * 9) * std::ceil(2000 * 3.141592653589793 * (0.001 + 0.999 + 7)));
  const InvalidInput e = expect_invalid([&] { wrist_ik(big, WristTarget::pointing(Eigen::Vector3d::UnitZ())); });
  CHECK(e.field() == "coupling");
  CHECK(e.problem().find("start boxes") != std::string::npos);
  // A legal problem stopped by a small budget is not certified and says so.
  const WristModel m{{0.0, 1.0, 0.5}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}, {{0, 1}, {2, 1}}}};
  const WristIkResult r = wrist_ik(library_wrist(m), WristTarget::pointing(Eigen::Vector3d(0.6, 0, 0.8)), 10);
  CHECK_FALSE(r.certified);
  CHECK_FALSE(r.on_fold);
  CHECK(r.why.find("budget") != std::string::npos);
}

TEST_CASE("wrist: the model refuses bad input naming the field", "[wrist]") {
  const auto refused = [](const std::string& twists, const std::string& coupling, const std::string& target) {
    WristText t;
    t.twists = twists;
    t.coupling = coupling;
    t.target = target;
    return expect_invalid([&] { t.wrist_target(t.wrist()); });
  };
  CHECK(refused("1,1,1", "1,2;2,4;3,6", "0,0,1").field() == "coupling");          // rank 1
  CHECK(refused("1,1,1", "1,0;0,1", "0,0,1").field() == "coupling");              // 2 rows for 3 twists
  CHECK(refused("1,1,1", "1/0,0;0,1;0,1", "0,0,1").field() == "coupling");        // zero denominator
  CHECK(refused("1,1,1", "1,0;0,1;0,1001", "0,0,1").field() == "coupling");       // a term above 1000
  CHECK(refused("1,1,1", "1,0;0,1;0,1", "1,1,1").field() == "target");            // not unit
  CHECK(refused("1,1,1", "1,0;0,1;0,1", "nan,0,1").field() == "target");          // not a number
  CHECK(refused("4,1,1", "1,0;0,1;0,1", "0,0,1").field() == "twists");            // beyond pi
  CHECK(refused("1,1,1,1,1,1,1", "1,0;0,1;0,1;0,1;0,1;0,1;0,1", "0,0,1").field() == "twists");  // k = 7
  CHECK(refused("1,1,1", "1,0,0;0,1,0;0,0,1", "0,0,1").field() == "target");      // a direction for 3 motors
  CHECK(refused("1,1,1", "1;2;3", "0,0,1").field() == "coupling");                // one motor
  WristText t;
  t.twists = "1,1,1";
  t.coupling = "1,0;0,1;0,2";
  t.target_frame = "1,0,0,0";
  CHECK(expect_invalid([&] { t.wrist_target(t.wrist()); }).field() == "target-frame");  // a frame for 2 motors
  t.coupling = "1,0,0;0,1,0;0,0,1";
  t.target_frame = "1,0,0,0,1,0,0,0.5,1";
  CHECK(expect_invalid([&] { t.wrist_target(t.wrist()); }).field() == "target-frame");  // not orthonormal
  t.target_frame = "0.9,0,0,0";
  CHECK(expect_invalid([&] { t.wrist_target(t.wrist()); }).field() == "target-frame");  // not a unit quaternion
}
