// wrist/: the certified fold-free cap about home (include/sphtroch/wrist/wrist_cap.hpp) against
// what is written here independently: the base x gear train wrist's folds are the circles
// z = cos(a2 +- a3) (the report's Eqs. 14/15), so the radius is the distance in polar angle to the
// nearer circle; on random 2-motor wrists the bracket's lower end is at most the distance to every
// sign change of det[P, dP/du1, dP/du2] on a dense torus grid (tests/wrist/wrist_reference.hpp:
// products of rotation matrices, bisection), its upper end at least their least distance minus
// the grid's resolution, and the count is the grid and Gauss-Newton count at a random direction
// inside the cap; the fold function's enclosure holds the reference determinant's sign. The fold
// atlas (wrist_atlas.hpp): the base x gear train's critical curve is the 2 |p| lines n u2 = k pi,
// each a closed polyline whose points lie on the circles; on random wrists every grid sign change
// lies in a listed cell, within the enclosure of that cell's point, and every point has det ~ 0.
#include "catch2/catch.hpp"
#include "test_support.hpp"
#include "wrist/wrist_reference.hpp"
#include "wrist/wrist_test_models.hpp"

#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_atlas.hpp"
#include "sphtroch/wrist/wrist_cap.hpp"
#include "sphtroch/wrist/wrist_critical.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace sphtroch;
using namespace sphtroch::test;

constexpr double kPi = 3.141592653589793;
constexpr long double kPiL = 3.141592653589793238462643383279502884L;

/// The angle between two directions, atan2(|a x b|, a . b), in long double.
long double angle_between(const Vec3L& a, const Vec3L& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

/// The angles from home to the fold points of a dense grid (wrist_reference.hpp's fold_sign_changes).
std::vector<long double> grid_fold_angles(const WristModel& m, double h, const Eigen::Vector3d& home) {
  std::vector<long double> out;
  for (const auto& u : fold_sign_changes(m, h)) out.push_back(angle_between(m.point({u[0], u[1]}), home.cast<long double>()));
  return out;
}

}  // namespace

TEST_CASE("wrist cap: the base x gear train wrist's radius is the polar distance to z = cos(a2 +- a3)", "[wrist][cap]") {
  struct Case {
    double a2, a3;
    int p, q;
    double polar, azimuth;
  };
  const std::vector<Case> cases{{1.0, 0.5, 2, 1, 0.6435, 0.0},  {1.0, 0.5, -3, 2, 1.2, 2.0},   {1.2, 0.4, 3, 1, 0.2, -1.0},
                                {0.9, 0.7, -1, 1, 1.3, 0.5},    {2.0, 0.6, 5, 3, 2.0, 3.0},    {0.6, 1.1, 1, 2, 2.5, 1.0},
                                {1.5, 1.4, -2, 3, 0.05, -2.5},  {2.4, 0.3, 4, 1, 2.75, 0.3},
                                {1.0, 0.5, -3, 2, 0.0, 0.0},    {0.6, 1.1, 5, 2, 0.0, 0.0}};  // home on the axis: whole circles nearest
  for (const Case& c : cases) {
    const Wrist wrist({{0.0, 0.0}, {c.a2, 0.0}, {c.a3, 0.0}},
                      {{ChainRate(1), ChainRate(0)}, {ChainRate(0), ChainRate(1)}, {ChainRate(0), ChainRate(c.p, c.q)}});
    const Eigen::Vector3d home(std::sin(c.polar) * std::cos(c.azimuth), std::sin(c.polar) * std::sin(c.azimuth), std::cos(c.polar));
    const double near = std::fabs(c.a2 - c.a3), far = std::min(c.a2 + c.a3, 2 * kPi - c.a2 - c.a3);  // the circles' polar angles
    const double expected = std::min(std::fabs(c.polar - near), std::fabs(c.polar - far));
    const WristCapResult r = wrist_cap(wrist, home);
    INFO("a2 " << c.a2 << " a3 " << c.a3 << " n " << c.p << "/" << c.q << " polar " << c.polar << ": [" << r.lower << ", " << r.upper
               << "] expected " << expected << " " << r.why);
    CHECK(r.certified);
    CHECK(r.lower <= expected + 1e-15);
    CHECK(r.upper >= expected - 1e-15);
    CHECK(r.upper - r.lower <= 1e-9);
    const bool inside = c.polar > near && c.polar < far;
    REQUIRE(r.count);
    CHECK(*r.count == (inside ? std::size_t(2 * std::abs(c.p)) : 0u));
    REQUIRE(r.has_fold_point);
    const double z = r.fold_point[2];  // on one of the circles, within the bracket of home
    CHECK(std::min(std::fabs(z - std::cos(near)), std::fabs(z - std::cos(far))) < 1e-12);
  }
}

TEST_CASE("wrist cap: random 2-motor wrists against the grid's sign changes of the reference determinant", "[wrist][cap]") {
  std::mt19937 rng(6161);
  const double h = 0.02;  // radians of joint motion per grid step
  std::size_t certified = 0, counted = 0;
  const int wrists = 16;
  for (int mechanism = 0; mechanism < wrists; ++mechanism) {
    const WristModel m = random_wrist(rng, 120);
    const Wrist wrist = library_wrist(m);
    const Eigen::Vector3d home = random_direction(rng);
    const WristCapResult r = wrist_cap(wrist, home, 400000);
    const std::vector<long double> angles = grid_fold_angles(m, h, home);
    REQUIRE(!angles.empty());  // a torus cannot cover the sphere without folds
    const double least = double(*std::min_element(angles.begin(), angles.end()));
    INFO("wrist " << mechanism << " coupling " << wrist.coupling_text() << " twists " << wrist.twists_text() << ": [" << r.lower << ", "
                  << r.upper << "] grid least " << least << " " << r.why);
    CHECK(r.lower <= least + 1e-12);                       // no fold point nearer than the lower end
    CHECK(r.upper >= least - 2.01 * h);                    // the nearest fold point is within a grid cell of a sign change
    CHECK(r.lower <= r.upper);
    if (r.radius_certified) {
      ++certified;
      CHECK(r.upper - r.lower <= 1e-9);
    }
    if (!r.count || !(r.lower > 0)) continue;
    // A random direction inside the cap: its count is the count at home.
    const Eigen::Vector3d side = home.cross(random_direction(rng)).normalized();
    const double rho = std::uniform_real_distribution<double>(0.1, 0.9)(rng) * std::min(r.lower, 1.0);
    const Eigen::Vector3d t = (std::cos(rho) * home + std::sin(rho) * side).normalized();
    const GridCount grid(m, 0.05);
    CHECK(grid.roots(t).size() == *r.count);
    ++counted;
  }
  CHECK(certified >= wrists - 2);  // a degenerate fold (a whole arc at the nearest distance) may stop one
  CHECK(counted >= wrists - 3);
}

TEST_CASE("wrist cap: a base motor and home on its axis: the grid's sign changes on the whole torus agree", "[wrist][cap]") {
  std::mt19937 rng(4242);
  std::uniform_int_distribution<int> num(1, 5), den(1, 5);
  for (int mechanism = 0; mechanism < 8; ++mechanism) {
    WristModel m = random_wrist(rng, 120);
    m.coupling[0][0] = {mechanism % 2 == 0 ? num(rng) : -num(rng), den(rng)};  // motor 1 turns the first joint only
    for (std::size_t i = 1; i < m.coupling.size(); ++i) m.coupling[i][0] = {0, 1};
    bool rank_two = false;
    for (std::size_t i = 1; i < m.coupling.size(); ++i) rank_two = rank_two || m.coupling[i][1].first != 0;
    if (!rank_two) m.coupling[1][1] = {1, 1};
    const Wrist wrist = library_wrist(m);
    const Eigen::Vector3d home(0, 0, mechanism % 3 == 0 ? -1.0 : 1.0);
    const WristCapResult r = wrist_cap(wrist, home, 400000);
    const std::vector<long double> angles = grid_fold_angles(m, 0.02, home);
    REQUIRE(!angles.empty());
    const double least = double(*std::min_element(angles.begin(), angles.end()));
    INFO("wrist " << mechanism << " coupling " << wrist.coupling_text() << " twists " << wrist.twists_text() << ": [" << r.lower << ", "
                  << r.upper << "] grid least " << least << " " << r.why);
    CHECK(r.radius_certified);
    CHECK(r.upper - r.lower <= 1e-9);
    CHECK(r.lower <= least + 1e-12);
    CHECK(r.upper >= least - 2.01 * 0.02);
    CHECK(r.boxes < 100000);  // one-dimensional: no whole circle to tile
  }
}

TEST_CASE("wrist cap: a search stopped at its budget keeps a valid bracket and says why", "[wrist][cap]") {
  const Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}}, {{ChainRate(1), ChainRate(0)}, {ChainRate(0), ChainRate(1)}, {ChainRate(0), ChainRate(2)}});
  const double polar = 0.9;  // the fold z = cos 1.5 is nearest: 0.6 away
  const WristCapResult r = wrist_cap(wrist, Eigen::Vector3d(std::sin(polar), 0, std::cos(polar)), 60);
  INFO("[" << r.lower << ", " << r.upper << "] " << r.why);
  CHECK(!r.radius_certified);
  CHECK(!r.certified);
  CHECK(r.why.find("budget") != std::string::npos);
  CHECK(r.lower <= 0.6 + 1e-15);
  CHECK(r.upper >= 0.6 - 1e-15);
  CHECK(r.upper - r.lower > 1e-9);
  REQUIRE(r.count);
  CHECK(*r.count == 4);  // the count does not depend on the bracket
}

TEST_CASE("wrist critical: D's enclosure holds the reference determinant's sign, and proved fold points are on it", "[wrist][cap]") {
  std::mt19937 rng(17);
  for (int mechanism = 0; mechanism < 20; ++mechanism) {
    const WristModel m = random_wrist(rng, 400);
    const Wrist wrist = library_wrist(m);
    const RoundingGuard upward;
    const WristCritical critical(wrist);
    std::uniform_real_distribution<double> u0(0, double(m.period(0))), u1(0, double(m.period(1))), w(1e-6, 0.05);
    for (int k = 0; k < 50; ++k) {
      const double a = u0(rng), b = u1(rng), r = w(rng);
      const IntervalBox<2> box{Interval(a - r, a + r), Interval(b - r, b + r)};
      const auto v = critical.over(box);
      const double u[2] = {a + 0.3 * r, b - 0.7 * r};
      const double d = fold_det<double>(m, u);  // |P| = 1: D = det exactly
      if (std::fabs(d) > 1e-12) CHECK((d > 0 ? v.det.sup() > 0 : v.det.inf() < 0));
      const auto on = critical.fold_point_on_line({a, b}, {mid(v.det_gradient[0]), mid(v.det_gradient[1])}, 0.5);
      if (!on) continue;
      const double c[2] = {mid((*on)[0]), mid((*on)[1])};
      CHECK(std::fabs(fold_det<double>(m, c)) < 1e-12);
      CHECK(box_width<2>(*on) < 1e-10);  // K is a few ulps of t, times d = grad D
    }
  }
}

TEST_CASE("wrist cap: refusals (3 motors, a home not unit, beyond the cost bound) are InvalidInput naming the option", "[wrist][cap]") {
  const Wrist three({{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}},
                    {{ChainRate(1), ChainRate(0), ChainRate(0)}, {ChainRate(0), ChainRate(1), ChainRate(0)}, {ChainRate(0), ChainRate(0), ChainRate(1)}});
  CHECK_THROWS_WITH(wrist_cap(three, Eigen::Vector3d::UnitZ()), Catch::Contains("coupling") && Catch::Contains("m = 3"));
  const Wrist two({{1.0, 0.0}, {1.0, 0.0}}, {{ChainRate(1), ChainRate(0)}, {ChainRate(0), ChainRate(1)}});
  CHECK_THROWS_WITH(wrist_cap(two, Eigen::Vector3d(1, 1, 0)), Catch::Contains("home"));
  CHECK_THROWS_WITH(wrist_cap(two, Eigen::Vector3d(std::nan(""), 0, 1)), Catch::Contains("home"));
  const Wrist costly({{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}},
                     {{ChainRate(5), ChainRate(1, 1000)}, {ChainRate(3), ChainRate(999, 1000)}, {ChainRate(1), ChainRate(7)}});
  CHECK_THROWS_WITH(wrist_cap(costly, Eigen::Vector3d::UnitZ()), Catch::Contains("start boxes"));
}

namespace {

/// The index of a cell holding u (motors moved by whole periods into the cells' ranges), or -1.
long cell_holding(const WristAtlasResult& r, const std::array<long double, 2>& u) {
  for (std::size_t i = 0; i < r.cells.size(); ++i) {
    bool in = true;
    for (std::size_t j = 0; j < 2 && in; ++j) {
      const auto& range = r.cells[i].motors[j];
      long double v = u[j] - r.periods[j] * std::floor((u[j] - range[0]) / r.periods[j]);  // in [lo, lo + T)
      in = v <= range[1] + 1e-12L || v >= range[0] + r.periods[j] - 1e-12L;
    }
    if (in) return long(i);
  }
  return -1;
}

}  // namespace

TEST_CASE("wrist atlas: the base x gear train's critical curve is 2 |p| closed lines on the circles z = cos(a2 +- a3)", "[wrist][atlas]") {
  struct Case {
    double a2, a3;
    int p, q;
  };
  for (const Case& c : std::vector<Case>{{1.0, 0.5, 2, 1}, {1.2, 0.4, -3, 2}, {2.0, 0.6, 1, 2}, {0.9, 0.7, -1, 1}}) {
    const Wrist wrist({{0.0, 0.0}, {c.a2, 0.0}, {c.a3, 0.0}},
                      {{ChainRate(1), ChainRate(0)}, {ChainRate(0), ChainRate(1)}, {ChainRate(0), ChainRate(c.p, c.q)}});
    const WristAtlasResult r = wrist_fold_atlas(wrist, 0.05);
    INFO("a2 " << c.a2 << " a3 " << c.a3 << " n " << c.p << "/" << c.q << " " << r.why);
    CHECK(r.certified);
    CHECK(r.polylines.size() == std::size_t(2 * std::abs(c.p)));
    for (const WristFoldPolyline& l : r.polylines) CHECK(l.closed);
    for (const WristFoldCell& cell : r.cells) {
      REQUIRE(cell.has_point);
      CHECK(std::min(std::fabs(cell.point[2] - std::cos(c.a2 - c.a3)), std::fabs(cell.point[2] - std::cos(c.a2 + c.a3))) < 1e-12);
    }
    // Every point of the lines n u2 = k pi (u2 = k pi q / p) lies in a cell.
    const WristModel m{{0.0, c.a2, c.a3}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}, {{0, 1}, {c.p, c.q}}}};
    std::size_t missing = 0;
    for (int k = 0; k < 2 * std::abs(c.p); ++k)
      for (int s = 0; s < 200; ++s) {
        const std::array<long double, 2> u{m.period(0) * (s + 0.37L) / 200, kPiL * k * c.q / std::abs(c.p)};
        if (cell_holding(r, u) < 0) ++missing;
      }
    CHECK(missing == 0);
  }
}

TEST_CASE("wrist atlas: random 2-motor wrists: every grid sign change of the reference determinant is enclosed", "[wrist][atlas]") {
  std::mt19937 rng(1961);
  std::size_t certified = 0;
  const int wrists = 12;
  for (int mechanism = 0; mechanism < wrists; ++mechanism) {
    const WristModel m = random_wrist(rng, 120);
    const Wrist wrist = library_wrist(m);
    const WristAtlasResult r = wrist_fold_atlas(wrist, 0.05);
    INFO("wrist " << mechanism << " coupling " << wrist.coupling_text() << " twists " << wrist.twists_text() << ": " << r.why);
    if (r.certified) ++certified;
    for (const WristFoldCell& cell : r.cells) {
      if (!cell.has_point) continue;
      const double u[2] = {cell.point_motors[0], cell.point_motors[1]};
      CHECK(std::fabs(fold_det<double>(m, u)) < 1e-9);
      CHECK(double(angle_between(m.point({u[0], u[1]}), Vec3L(cell.point[0], cell.point[1], cell.point[2]))) < 1e-12);
    }
    std::size_t outside = 0, beyond = 0;
    for (const auto& u : fold_sign_changes(m, 0.02)) {
      const long i = cell_holding(r, u);
      if (i < 0) {
        ++outside;
        continue;
      }
      const WristFoldCell& cell = r.cells[std::size_t(i)];
      if (r.certified && angle_between(m.point({u[0], u[1]}), Vec3L(cell.point[0], cell.point[1], cell.point[2])) > r.enclosure + 1e-9) ++beyond;
    }
    CHECK(outside == 0);
    CHECK(beyond == 0);
  }
  CHECK(certified >= wrists - 1);
}

TEST_CASE("wrist cap and atlas: a degenerate wrist (D = 0 everywhere) is not certified at once, without a search", "[wrist][cap][atlas]") {
  // Twist A2 = 0 joins joints 2 and 3: P depends on u1 + u2 only, so the reference determinant
  // (products of rotation matrices) is 0 everywhere; all twists 0 leave P = z. The base x gear
  // train wrist is not degenerate: its reference determinant is not 0 at a point of its zone.
  const std::vector<WristModel> degenerate = {
      {{1.0, 0.0, 0.5}, {0.0, 0.0, 0.0}, {{{1, 1}, {1, 1}}, {{0, 1}, {1, 1}}, {{1, 1}, {0, 1}}}},
      {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}, {{0, 1}, {2, 1}}}}};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(0, 20);
  for (const WristModel& m : degenerate) {
    for (int k = 0; k < 50; ++k) {
      const long double u[2] = {angle(rng), angle(rng)};
      REQUIRE(std::fabs(static_cast<double>(fold_det<long double>(m, u))) < 1e-15);  // the model's truth
    }
    const Wrist w = library_wrist(m);
    CHECK(wrist_fold_vanishes_everywhere(w));
    const WristCapResult cap = wrist_cap(w, Vector3d(0.6, 0, 0.8));
    CHECK_FALSE(cap.certified);
    CHECK(cap.lower == 0);
    CHECK(cap.upper >= 3.14159);
    CHECK(cap.boxes == 0);
    CHECK(cap.why.find("degenerate") != std::string::npos);
    const WristAtlasResult atlas = wrist_fold_atlas(w);
    CHECK_FALSE(atlas.certified);
    CHECK_FALSE(atlas.complete);
    CHECK(atlas.boxes == 0);
  }
  const WristModel train{{0.0, 1.0, 0.5}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}, {{0, 1}, {2, 1}}}};
  const long double at[2] = {0.3L, 0.7L};
  REQUIRE(std::fabs(static_cast<double>(fold_det<long double>(train, at))) > 1e-3);
  CHECK_FALSE(wrist_fold_vanishes_everywhere(library_wrist(train)));
}
