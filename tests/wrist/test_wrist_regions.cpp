// wrist/: the regions of the fold atlas (include/sphtroch/wrist/wrist_regions.hpp) against what is
// written here independently. The base x gear train wrist (twists 0, a2, a3; coupling 1,0;0,1;0,n,
// n = p/q) has the zone cos(a2 + a3) < z < cos(a2 - a3) with 2 |p| solutions and the two caps
// beyond it with none (the report's Eqs. 14/15): every region's count is one of them, its point in
// the right band, every cell of it wholly on the right side of both circles, and the workspace's
// area bracket holds 2 pi (z_hi - z_lo). On random 2-motor wrists a region's count is, at random
// targets in its cells, the grid and Gauss-Newton count of tests/wrist/wrist_reference.hpp and
// wrist_ik's count; targets in the fold band are counted, not compared. The estimated cusps
// (wrist_cusps.hpp): none on the base x gear train's circles; at each one on two other wrists the
// reference (the fold determinant of wrist_reference.hpp by central differences, the kernel of dP by
// Eigen's SVD) has the kernel's component along grad D change sign along the critical curve. The
// checks on a result made by hand: 2 -> 4 across one strand passes, 0 -> 4 is a violation, counts of
// two parities fail, a region without a count is not certified.
#include "catch2/catch.hpp"
#include "test_support.hpp"
#include "wrist/wrist_reference.hpp"
#include "wrist/wrist_test_models.hpp"

#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_atlas.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_regions.hpp"
#include "sphtroch/wrist/wrist_regions_svg.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace sphtroch;
using namespace sphtroch::test;

constexpr double kPi = 3.141592653589793;

struct TargetTally {
  std::size_t compared = 0, in_band = 0, disagreements = 0;
};

/// `targets` random directions per wrist on `wrists` random wrists: a target in a region cell has
/// the region's count = the reference count = wrist_ik's certified count.
TargetTally check_random_targets(unsigned seed, int wrists, int targets) {
  std::mt19937 rng(seed);
  TargetTally tally;
  for (int mechanism = 0; mechanism < wrists; ++mechanism) {
    const WristModel m = random_wrist(rng, 200);
    const Wrist wrist = library_wrist(m);
    const WristAtlasResult atlas = wrist_fold_atlas(wrist, 0.05);
    const WristRegionsResult r = wrist_regions(wrist, atlas, 0.02);
    INFO("wrist " << mechanism << " coupling " << wrist.coupling_text() << " twists " << wrist.twists_text() << ": " << r.why);
    CHECK(r.certified);
    CHECK(r.parity_ok);
    const GridCount reference(m, 0.15);
    for (int k = 0; k < targets; ++k) {
      const Eigen::Vector3d t = random_direction(rng);
      const std::optional<std::size_t> g = r.region_of(t);
      if (!g) {
        ++tally.in_band;
        continue;
      }
      const WristRegion& region = r.regions[*g];
      if (!region.counted) continue;
      ++tally.compared;
      const std::size_t grid = reference.roots(t).size();
      const WristIkResult ik = wrist_ik(wrist, WristTarget::pointing(t));
      INFO("target " << t.transpose() << " region R" << *g + 1 << " count " << region.count << ", grid " << grid << ", wrist ik "
                     << ik.solutions.size() << (ik.certified ? "" : " (not certified)"));
      CHECK(ik.certified);
      CHECK(region.count == grid);
      CHECK(region.count == ik.solutions.size());
      if (region.count != grid || region.count != ik.solutions.size()) ++tally.disagreements;
    }
  }
  return tally;
}

/// The reference cusp function at u: grad D (central differences of fold_det) and the kernel of
/// dP (the right singular vector of the 3 x 2 Jacobian with the smaller singular value).
void reference_kernel(const WristModel& m, const std::array<double, 2>& u, Eigen::Vector2d& grad, Eigen::Vector2d& kernel) {
  const double h = 1e-6;
  for (int j = 0; j < 2; ++j) {
    double a[2] = {u[0], u[1]}, b[2] = {u[0], u[1]};
    a[j] += h, b[j] -= h;
    grad[j] = (fold_det<double>(m, a) - fold_det<double>(m, b)) / (2 * h);
  }
  const double w[2] = {u[0], u[1]};
  Eigen::Vector3d p;
  Eigen::Matrix<double, 3, 2> jac;
  m.point_and_jacobian(w, p, jac);
  kernel = Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>>(jac, Eigen::ComputeFullV).matrixV().col(1);
}

/// u moved onto D = 0 by Newton steps along grad D (the reference determinant).
std::array<double, 2> onto_fold(const WristModel& m, std::array<double, 2> u) {
  for (int it = 0; it < 20; ++it) {
    Eigen::Vector2d g, k;
    reference_kernel(m, u, g, k);
    const double d[2] = {u[0], u[1]};
    const double step = fold_det<double>(m, d) / g.squaredNorm();
    u[0] -= step * g[0], u[1] -= step * g[1];
  }
  return u;
}

/// Whether k . grad D (each of one sense on both sides) changes sign between the fold points s
/// motor radians either side of u along the critical curve.
bool reference_cusp_within(const WristModel& m, const std::array<double, 2>& u, double s) {
  Eigen::Vector2d g, k, g2, k2;
  reference_kernel(m, u, g, k);
  const Eigen::Vector2d t = Eigen::Vector2d(-g[1], g[0]).normalized();
  const std::array<double, 2> a = onto_fold(m, {u[0] - s * t[0], u[1] - s * t[1]}), b = onto_fold(m, {u[0] + s * t[0], u[1] + s * t[1]});
  reference_kernel(m, a, g, k);
  reference_kernel(m, b, g2, k2);
  if (k.dot(k2) < 0) k2 = -k2;
  if (g.dot(g2) < 0) g2 = -g2;
  return k.dot(g.normalized()) * k2.dot(g2.normalized()) < 0;
}

}  // namespace

TEST_CASE("wrist atlas: the estimated cusps: none on the base x gear train, the reference's sign change at each on two wrists", "[wrist][regions][cusps]") {
  const Wrist train({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}}, {{ChainRate(1), ChainRate(0)}, {ChainRate(0), ChainRate(1)}, {ChainRate(0), ChainRate(-3, 2)}});
  CHECK(wrist_fold_atlas(train, 0.05).cusps.empty());
  const std::vector<WristModel> models{
      {{kPi / 2, kPi / 2, kPi / 3}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{1, 2}, {1, 2}}, {{-1, 2}, {1, 2}}}},
      {{kPi / 2, 1.0, kPi / 3, 0.7}, {0.0, 0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}, {{0, 1}, {2, 3}}, {{1, 2}, {-1, 1}}}}};
  for (const WristModel& m : models) {
    const WristAtlasResult atlas = wrist_fold_atlas(library_wrist(m), 0.05);
    INFO("coupling " << library_wrist(m).coupling_text());
    CHECK(!atlas.cusps.empty());
    for (const WristCusp& c : atlas.cusps) {
      INFO("cusp at u = (" << c.motors[0] << ", " << c.motors[1] << ")");
      const bool seen = reference_cusp_within(m, c.motors, 0.03) || reference_cusp_within(m, c.motors, 0.06) ||
                        reference_cusp_within(m, c.motors, 0.12);
      CHECK(seen);
    }
  }
}

TEST_CASE("wrist regions: the base x gear train's zone has 2 |p| solutions, its caps none (Eqs. 14/15)", "[wrist][regions]") {
  struct Case {
    double a2, a3;
    int p, q;
  };
  for (const Case& c : std::vector<Case>{{1.0, 0.5, 2, 1}, {1.2, 0.4, -3, 2}, {2.0, 0.6, 1, 2}, {0.9, 0.7, -1, 1}, {0.6, 0.3, 3, 1}}) {
    const Wrist wrist({{0.0, 0.0}, {c.a2, 0.0}, {c.a3, 0.0}},
                      {{ChainRate(1), ChainRate(0)}, {ChainRate(0), ChainRate(1)}, {ChainRate(0), ChainRate(c.p, c.q)}});
    const WristAtlasResult atlas = wrist_fold_atlas(wrist, 0.05);
    const WristRegionsResult r = wrist_regions(wrist, atlas, 0.02);
    INFO("a2 " << c.a2 << " a3 " << c.a3 << " n " << c.p << "/" << c.q << " " << r.why);
    CHECK(r.certified);
    const double z_lo = std::cos(c.a2 + c.a3), z_hi = std::cos(c.a2 - c.a3);
    for (const WristFoldCell& cell : atlas.cells)  // the folds are the circles
      CHECK(std::min(std::fabs(cell.point[2] - z_lo), std::fabs(cell.point[2] - z_hi)) < 1e-14);
    std::size_t zone = 0, caps = 0;
    for (const WristRegion& g : r.regions) {
      REQUIRE(g.counted);
      const bool inside = g.point[2] > z_lo && g.point[2] < z_hi;
      CHECK(g.count == (inside ? std::size_t(2 * std::abs(c.p)) : 0));
      (inside ? zone : caps) += 1;
    }
    CHECK(zone >= 1);
    CHECK(caps >= 1);  // none of these zones reaches a pole
    std::size_t wrong_side = 0;
    for (std::size_t cell = 0; cell < r.grid.size(); ++cell) {
      if (r.cell_region[cell] < 0) continue;
      const std::array<double, 4> b = r.grid.bounds(cell);  // z runs over [cos theta_1, cos theta_0]
      const bool counted_inside = r.regions[std::size_t(r.cell_region[cell])].count > 0;
      const bool inside = std::cos(b[1]) > z_lo && std::cos(b[0]) < z_hi;
      const bool outside = std::cos(b[0]) < z_lo || std::cos(b[1]) > z_hi;
      if (counted_inside ? !inside : !outside) ++wrong_side;
    }
    CHECK(wrong_side == 0);
    const double area = 2 * kPi * (z_hi - z_lo);
    CHECK(r.workspace_area <= area);
    CHECK(r.workspace_area + r.fold_band_area >= area);
    CHECK(r.workspace_area + r.void_area + r.fold_band_area == Approx(4 * kPi).epsilon(1e-12));
    CHECK(r.violations.empty());
    const WristRegionsResult two = wrist_regions(wrist, atlas, 0.02, 2);  // the same on 2 threads
    REQUIRE(two.regions.size() == r.regions.size());
    for (std::size_t k = 0; k < r.regions.size(); ++k) {
      CHECK(two.regions[k].count == r.regions[k].count);
      CHECK(two.regions[k].point == r.regions[k].point);
    }
  }
}

TEST_CASE("wrist regions: 10 random wrists x 20 targets: a region's count is the grid count and wrist ik's", "[wrist][regions]") {
  const TargetTally tally = check_random_targets(6102, 10, 20);
  WARN("compared " << tally.compared << ", in the fold band " << tally.in_band);
  CHECK(tally.disagreements == 0);
  CHECK(tally.compared >= 100);
}

TEST_CASE("wrist regions: 10 random wrists x 100 targets (10^3): a region's count is the grid count and wrist ik's", "[wrist][regions][full]") {
  const TargetTally tally = check_random_targets(6103, 10, 100);
  WARN("compared " << tally.compared << ", in the fold band " << tally.in_band);
  CHECK(tally.disagreements == 0);
  CHECK(tally.compared >= 600);
}

TEST_CASE("wrist regions: the sphere grid's cells tile the sphere and their caps hold them", "[wrist][regions]") {
  const WristSphereGrid grid(0.05);
  double area = 0;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t outside = 0, asymmetric = 0;
  for (std::size_t c = 0; c < grid.size(); ++c) {
    area += grid.area(c);
    const std::array<double, 4> b = grid.bounds(c);
    for (int k = 0; k < 20; ++k) {  // points of the cell, by its polar angle and azimuth
      const double t = b[0] + (b[1] - b[0]) * unit(rng), p = b[2] + (b[3] - b[2]) * unit(rng);
      const Eigen::Vector3d v(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
      if (std::atan2(grid.centre(c).cross(v).norm(), grid.centre(c).dot(v)) > grid.cap_radius(c)) ++outside;
    }
    for (const std::size_t n : grid.neighbours(c)) {
      const std::vector<std::size_t> back = grid.neighbours(n);
      if (std::find(back.begin(), back.end(), c) == back.end()) ++asymmetric;
    }
  }
  CHECK(area == Approx(4 * kPi).epsilon(1e-12));
  CHECK(outside == 0);
  CHECK(asymmetric == 0);
  for (int k = 0; k < 1000; ++k) {  // every cell a cap may meet is visited
    const Eigen::Vector3d c = random_direction(rng), v = random_direction(rng);
    const double r = 0.3 * unit(rng), d = std::atan2(c.cross(v).norm(), c.dot(v));
    if (d > r) continue;
    bool seen = false;
    grid.for_cells_near(c, r, [&](std::size_t cell) { seen = seen || cell == grid.cell_of(v); });
    CHECK(seen);
  }
}

TEST_CASE("wrist regions: the picture is one SVG with a legend of the counts", "[wrist][regions]") {
  const Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}}, {{ChainRate(1), ChainRate(0)}, {ChainRate(0), ChainRate(1)}, {ChainRate(0), ChainRate(2)}});
  const WristAtlasResult atlas = wrist_fold_atlas(wrist, 0.1);
  const WristRegionsResult r = wrist_regions(wrist, atlas, 0.05);
  const std::string svg = wrist_regions_svg(atlas, r);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.find("</svg>") != std::string::npos);
  CHECK(svg.find(">4</text>") != std::string::npos);
  CHECK(svg.find(">0 (void)</text>") != std::string::npos);
  CHECK(svg.find("fold band (no count)") != std::string::npos);
  CHECK(svg.find("stroke:#a50f15") != std::string::npos);  // the folds
}

TEST_CASE("wrist regions: refusals name --sphere-cell", "[wrist][regions]") {
  for (const double step : {0.0, 1e-3, 0.6, std::nan("")}) {
    try {
      check_wrist_regions_cost(step);
      FAIL("accepted " << step);
    } catch (const InvalidInput& e) {
      CHECK(e.field() == "sphere-cell");
    }
  }
  CHECK_NOTHROW(check_wrist_regions_cost(0.02));
}

TEST_CASE("wrist regions: the checks: a jump of 4 across one strand, counts of two parities, a region without a count", "[wrist][regions]") {
  WristAtlasResult atlas;
  atlas.complete = true;
  atlas.periods = {2 * kPi, 2 * kPi};
  atlas.cells.resize(1);
  atlas.cells[0].motors = {{{0.0, 0.1}, {0.0, 0.1}}};
  const auto make = [&](std::size_t count0, std::size_t count1, bool counted1) {
    WristRegionsResult r;
    r.grid = WristSphereGrid(0.5);
    r.cell_region.assign(r.grid.size(), 0);
    const std::size_t row = 3;
    r.cell_region[r.grid.index(row, 1)] = -1;  // one band cell between region 0 (west) and region 1 (east)
    r.cell_region[r.grid.index(row, 2)] = 1;
    r.regions.resize(2);
    r.regions[0].count = count0, r.regions[0].counted = true;
    r.regions[1].count = count1, r.regions[1].counted = counted1;
    std::vector<std::vector<std::size_t>> meets(r.grid.size());
    meets[r.grid.index(row, 1)] = {0};
    wrist_regions_check(atlas, meets, r);
    return r;
  };
  const WristRegionsResult two = make(2, 4, true);
  CHECK(two.certified);
  CHECK(two.crossings >= 1);
  CHECK(two.crossings_by_two >= 1);
  const WristRegionsResult four = make(0, 4, true);
  CHECK(!four.certified);
  REQUIRE(!four.violations.empty());
  CHECK(four.violations.front().strands == 1);
  CHECK(std::labs(four.violations.front().delta) == 4);
  CHECK(four.why.find("+-2 rule") != std::string::npos);
  const WristRegionsResult odd = make(2, 3, true);
  CHECK(!odd.parity_ok);
  CHECK(!odd.certified);
  const WristRegionsResult missing = make(2, 0, false);
  CHECK(!missing.certified);
  CHECK(missing.why.find("without a certified count") != std::string::npos);
  CHECK(missing.voids.empty());
}
