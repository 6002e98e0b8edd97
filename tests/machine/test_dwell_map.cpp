// Tests of machine/dwell_map.hpp. Expected values: an independent fine-sampling count — the gravity
// from Eigen AngleAxis rotations (not the library's), sampled at the midpoints of steps dt, each
// sample's cell by HEALPix's own vec2pix (RING) — whose own error per cell is at most dt per entry
// or exit it sees plus the time of excursions shorter than dt; the library's stated bound_s.
#include "catch2/catch.hpp"
#include "sphtroch/machine/dwell_map.hpp"
#include "test_support.hpp"

#include <healpix_base.h>

using namespace sphtroch;

namespace {

Vector3d model_gravity(const ClinostatSettings& s, double t) {
  const double pi = Constants<double>::pi();
  const double psi = s.tilt_deg * pi / 180, beta = s.frame_angle_deg * pi / 180;
  const Vector3d u(std::sin(psi), 0, std::cos(psi)), w(-std::cos(psi), 0, std::sin(psi));
  const Vector3d v = std::cos(beta) * u + std::sin(beta) * w;
  const double po = s.phase_outer_deg * pi / 180 + 2 * pi * s.outer.value() * t / 60;
  const double pi_ = s.phase_inner_deg * pi / 180 + 2 * pi * s.inner.value() * t / 60;
  const Matrix3d frame = (Eigen::AngleAxisd(po, u) * Eigen::AngleAxisd(pi_, v)).toRotationMatrix();
  return frame.transpose() * Vector3d(0, 0, -1);
}

struct FineCount {
  std::vector<double> dwell, edges;  // seconds per cell; dt per entry or exit seen
};

FineCount fine_count(const ClinostatSettings& s, double start, double duration, int nside, double dt) {
  const T_Healpix_Base<int> base(nside, RING, SET_NSIDE);
  FineCount out{std::vector<double>(static_cast<std::size_t>(base.Npix()), 0.0),
                std::vector<double>(static_cast<std::size_t>(base.Npix()), 0.0)};
  const long steps = std::lround(duration / dt);
  int last = -1;
  for (long k = 0; k < steps; ++k) {
    const Vector3d p = model_gravity(s, start + (k + 0.5) * dt);
    const int cell = base.vec2pix(vec3(p.x(), p.y(), p.z()));
    out.dwell[static_cast<std::size_t>(cell)] += dt;
    if (cell != last) {
      out.edges[static_cast<std::size_t>(cell)] += dt;
      if (last >= 0) out.edges[static_cast<std::size_t>(last)] += dt;
    }
    last = cell;
  }
  return out;
}

ClinostatSettings machine(std::int64_t outer_centi, std::int64_t inner_centi, double tilt, double frame) {
  ClinostatSettings s;
  s.outer = Rpm(outer_centi, 100);
  s.inner = Rpm(inner_centi, 100);
  s.tilt_deg = tilt;
  s.frame_angle_deg = frame;
  s.phase_outer_deg = 11;
  s.phase_inner_deg = 29;
  return s;
}

}  // namespace

TEST_CASE("dwell map: each cell's time agrees with fine sampling by HEALPix's vec2pix within the bounds", "[dwell]") {
  for (const auto& [s, nside, duration] : {std::tuple{machine(133, 200, 90, 90), 8, 300.0}, std::tuple{machine(-70, 130, 75, 80), 4, 400.0},
                                           std::tuple{machine(500, 0, 40, 90), 16, 30.0}}) {
    const DwellMap d = dwell_map(Clinostat(s), 12.5, duration, nside);
    REQUIRE(d.dwell_s.size() == static_cast<std::size_t>(12 * nside * nside));
    const FineCount fine = fine_count(s, 12.5, duration, nside, 1e-3);
    double total = 0;
    std::size_t visited_fine = 0, disagree = 0;
    for (std::size_t i = 0; i < d.dwell_s.size(); ++i) {
      total += d.dwell_s[i];
      CHECK(std::fabs(d.dwell_s[i] - fine.dwell[i]) <= d.bound_s + fine.edges[i] + 1e-9);
      visited_fine += fine.dwell[i] > 0;
      disagree += (fine.dwell[i] > 0) != (d.dwell_s[i] > 0);
    }
    CHECK(total == Approx(duration).epsilon(1e-12));
    CHECK(d.bound_s <= 0.01);
    CHECK(disagree == 0);
    CHECK(d.visited == visited_fine);
    CHECK(d.visited_fraction == Approx(static_cast<double>(visited_fine) / d.dwell_s.size()));
    // The coefficient of variation from the definition (population standard deviation / mean).
    const double mean = duration / d.dwell_s.size();
    double square = 0;
    for (const double x : d.dwell_s) square += (x - mean) * (x - mean);
    CHECK(d.dwell_cv == Approx(std::sqrt(square / d.dwell_s.size()) / mean).epsilon(1e-12));
  }
}

TEST_CASE("dwell map: a path along cell edges or on a vertex is walked within the query budget, its bound holding", "[dwell]") {
  // One speed 0 with the default frames: the outer-only circle x = 0 runs along the meridians that
  // bound HEALPix's polar cells; the inner-only machine's axis is vertical, so gravity sits on the
  // south pole, a vertex of four cells. Refining such steps cannot settle them; the walk must stop.
  for (const auto& [s, nside, duration, dt] : {std::tuple{machine(1, 0, 90, 90), 1, 6000.0, 0.01}, std::tuple{machine(100, 0, 90, 90), 2, 60.0, 1e-3},
                                               std::tuple{machine(100, 0, 90, 90), 8, 60.0, 1e-3}, std::tuple{machine(0, 100, 90, 90), 8, 60.0, 1e-3}}) {
    const DwellMap d = dwell_map(Clinostat(s), 0.0, duration, nside);
    const FineCount fine = fine_count(s, 0.0, duration, nside, dt);
    double total = 0;
    for (std::size_t i = 0; i < d.dwell_s.size(); ++i) {
      total += d.dwell_s[i];
      CHECK(std::fabs(d.dwell_s[i] - fine.dwell[i]) <= d.bound_s + fine.edges[i] + 1e-9);
    }
    CHECK(total == Approx(duration).epsilon(1e-12));
    CHECK(d.bound_s <= duration * (1 + 1e-9));
  }
}

TEST_CASE("dwell map: a late start is as precise as t = 0 (whole periods later, the same map within the bounds)", "[dwell]") {
  const ClinostatSettings s = machine(133, 200, 90, 90);  // period 6000 s
  const Clinostat m(s);
  const DwellMap early = dwell_map(m, 12.5, 120.0, 8), late = dwell_map(m, 6000.0 * 166666 + 12.5, 120.0, 8);
  REQUIRE(late.bound_s <= 0.01);
  for (std::size_t i = 0; i < early.dwell_s.size(); ++i) CHECK(std::fabs(early.dwell_s[i] - late.dwell_s[i]) <= early.bound_s + late.bound_s);
  const FineCount fine = fine_count(s, 6000.0 * 166666 + 12.5, 120.0, 8, 1e-3);
  for (std::size_t i = 0; i < late.dwell_s.size(); ++i) CHECK(std::fabs(late.dwell_s[i] - fine.dwell[i]) <= late.bound_s + fine.edges[i] + 1e-9);
}

TEST_CASE("dwell map: a duration of whole periods and a rest equals the walk of each part", "[dwell]") {
  const ClinostatSettings s = machine(100, 200, 90, 90);  // period 60 s
  const Clinostat m(s);
  const DwellMap whole = dwell_map(m, 5.0, 150.0, 4), one = dwell_map(m, 5.0, 60.0, 4), rest = dwell_map(m, 5.0, 30.0, 4);
  for (std::size_t i = 0; i < whole.dwell_s.size(); ++i)
    CHECK(std::fabs(whole.dwell_s[i] - (2 * one.dwell_s[i] + rest.dwell_s[i])) <= whole.bound_s + 2 * one.bound_s + rest.bound_s);
}

TEST_CASE("dwell map: the coefficient of variation of a tiny duration (one cell of 768: sqrt(767))", "[dwell]") {
  const Clinostat m(machine(133, 200, 90, 90));
  for (const double d : {1e-300, 1e-200, 1e-160, 1e-6}) {
    const DwellMap map = dwell_map(m, 0, d, 8);
    REQUIRE(map.visited == 1);
    CHECK(map.dwell_cv == Approx(std::sqrt(767.0)).epsilon(1e-12));
  }
}

TEST_CASE("dwell map: bad requests are refused naming the option", "[dwell]") {
  const Clinostat m(machine(133, 200, 90, 90));
  for (const int nside : {0, 3, 6, 2048, -8}) CHECK(test::expect_invalid([&] { dwell_map(m, 0, 60, nside); }).field() == "nside");
  CHECK(test::expect_invalid([&] { dwell_map(m, 0, 0, 8); }).field() == "coverage");
  CHECK(test::expect_invalid([&] { dwell_map(m, 0, std::nan(""), 8); }).field() == "coverage");
  ClinostatSettings fast;  // period 1000 min at ~1000 rpm: 7e9 steps at nside 1024
  fast.outer = Rpm(999999, 1000);
  fast.inner = Rpm(1000);
  CHECK(test::expect_invalid([&] { dwell_map(Clinostat(fast), 0, 1e12, 1024); }).field() == "coverage");
}
