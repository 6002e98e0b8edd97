// Tests of machine/gravity_series.hpp, machine/worst_window_mean.hpp and
// machine/time_to_epsilon.hpp. Expected values: window means by composite Gauss-Legendre
// quadrature (8 nodes per piece of at most 0.5 s, long double) of an independent rotation model
// (Eigen AngleAxis products in long double); the mean over a period from its closed form
// -cos(psi) cos(beta) v (no resonance); M(W) against a dense scan of start times; the time to
// epsilon against a closed form (one axis) and a dense scan in W and the start between grid points.
#include "catch2/catch.hpp"
#include "sphtroch/machine/time_to_epsilon.hpp"
#include "test_support.hpp"

#include <cstdlib>
#include <random>
#include <string>

using namespace sphtroch;

namespace {

using Vec3L = Eigen::Matrix<long double, 3, 1>;

/// g_s(t) = (Rot(u, phi_o) Rot(v, phi_i))^T (0, 0, -1), written from the convention.
Vec3L model_gravity(const ClinostatSettings& s, long double t) {
  const long double pi = 3.141592653589793238462643383279502884L;
  const long double psi = s.tilt_deg * pi / 180, beta = s.frame_angle_deg * pi / 180;
  const Vec3L u(std::sin(psi), 0, std::cos(psi)), w(-std::cos(psi), 0, std::sin(psi));
  const Vec3L v = std::cos(beta) * u + std::sin(beta) * w;
  const auto angle = [&](const Rpm& r, double phase) {
    long double turns = static_cast<long double>(r.num()) * t / (60.0L * r.den());
    turns -= std::floor(turns);
    return 2 * pi * turns + phase * pi / 180;
  };
  const Eigen::Matrix<long double, 3, 3> frame =
      Eigen::AngleAxis<long double>(angle(s.outer, s.phase_outer_deg), u).toRotationMatrix() *
      Eigen::AngleAxis<long double>(angle(s.inner, s.phase_inner_deg), v).toRotationMatrix();
  return frame.transpose() * Vec3L(0, 0, -1);
}

/// The mean of model_gravity over [t0, t0 + W], Gauss-Legendre with 8 nodes per piece of <= 0.5 s
/// (speeds <= 12 rpm: <= 0.32 rad per piece, truncation ~1e-25).
Vec3L quadrature_mean(const ClinostatSettings& s, long double t0, long double w) {
  static const long double x[4] = {0.1834346424956498049394761L, 0.5255324099163289858177390L, 0.7966664774136267395915539L,
                                   0.9602898564975362316835609L};
  static const long double c[4] = {0.3626837833783619829651504L, 0.3137066458778872873379622L, 0.2223810344533744705443560L,
                                   0.1012285362903762591525314L};
  const long double pieces = std::ceil(w * 2);
  const long double h = w / pieces;
  Vec3L sum = Vec3L::Zero();
  for (long double k = 0; k < pieces; ++k) {
    const long double mid = t0 + (k + 0.5L) * h;
    for (int i = 0; i < 4; ++i) sum += c[i] * (model_gravity(s, mid - x[i] * h / 2) + model_gravity(s, mid + x[i] * h / 2));
  }
  return sum * (h / 2) / w;
}

ClinostatSettings machine(const char* outer, const char* inner, double tilt = 90, double frame = 90) {
  ClinostatSettings s;
  s.outer = Rpm(static_cast<std::int64_t>(std::llround(std::atof(outer) * 100)), 100);
  s.inner = Rpm(static_cast<std::int64_t>(std::llround(std::atof(inner) * 100)), 100);
  s.tilt_deg = tilt;
  s.frame_angle_deg = frame;
  s.phase_outer_deg = 23;
  s.phase_inner_deg = -41;
  return s;
}

}  // namespace

TEST_CASE("window mean: closed form equals quadrature of the rotation model", "[window_mean]") {
  std::mt19937_64 rng(46);
  std::uniform_int_distribution<int> speed(-600, 600);
  std::uniform_real_distribution<double> angle(0, 180), start(0, 1e5), length(0.5, 900);
  for (int i = 0; i < 200; ++i) {
    ClinostatSettings s;
    s.outer = Rpm(speed(rng), 100);
    s.inner = Rpm(speed(rng) | 1, 100);
    s.tilt_deg = angle(rng);
    s.frame_angle_deg = angle(rng);
    s.phase_outer_deg = angle(rng);
    s.phase_inner_deg = -angle(rng);
    const GravitySeries g = GravitySeries::of_gravity(Clinostat(s));
    const double t0 = start(rng), w = length(rng);
    const Vec3L want = quadrature_mean(s, t0, w);
    INFO("t0 " << t0 << " W " << w << " outer " << s.outer.str() << " inner " << s.inner.str() << " diff " << static_cast<double>((g.window_mean(t0, w).cast<long double>() - want).norm()));
    CHECK(static_cast<double>((g.window_mean(t0, w).cast<long double>() - want).norm()) <= 1e-12);
    CHECK(static_cast<double>((g.value(t0).cast<long double>() - model_gravity(s, t0)).norm()) <= 1e-13);
  }
}

TEST_CASE("window mean: the mean over a period is -cos(psi) cos(beta) v without resonance", "[window_mean]") {
  std::mt19937_64 rng(47);
  std::uniform_real_distribution<double> angle(0, 180);
  for (int i = 0; i < 50; ++i) {
    ClinostatSettings s = machine("1.33", "2", angle(rng), angle(rng));
    const Clinostat m(s);
    const GravitySeries g = GravitySeries::of_gravity(m);
    const double pi = Constants<double>::pi();
    const Vector3d want = -std::cos(s.tilt_deg * pi / 180) * std::cos(s.frame_angle_deg * pi / 180) * m.inner_axis();
    CHECK((g.period_mean() - want).norm() <= 1e-14);
    REQUIRE(g.period_s());
    CHECK(*g.period_s() == 6000);  // 1.33 and 2 rpm: both frames back after 100 min
    // The mean over any whole period from any start is the period mean (quadrature).
    CHECK(static_cast<double>((quadrature_mean(s, 1234.5L, 6000) - g.period_mean().cast<long double>()).norm()) <= 1e-12);
  }
  // The period of a single-axis machine is that axis's turn; of equal speeds (a resonance), 1 turn.
  CHECK(*GravitySeries::of_gravity(Clinostat(machine("0", "2.5"))).period_s() == 24);
  CHECK(*GravitySeries::of_gravity(Clinostat(machine("3", "3", 60, 60))).period_s() == 20);
  // Outer axis vertical: the outer frame does not turn gravity; only the inner speed sets the period.
  CHECK(*GravitySeries::of_gravity(Clinostat(machine("1.33", "2", 0, 50))).period_s() == 30);
}

TEST_CASE("worst window mean: the bracket holds a dense scan's maximum and is at most 1e-9 wide", "[window_mean]") {
  for (const auto& s : {machine("1.33", "2"), machine("1", "2"), machine("-0.7", "1.3", 75, 80), machine("2.5", "0"),
                        machine("0.31", "0.5", 120, 90)}) {
    const GravitySeries g = GravitySeries::of_gravity(Clinostat(s));
    const double period = *g.period_s();
    for (const double w : {7.0, 60.0, 333.0, 1000.0}) {
      const WorstWindowMean m = worst_window_mean(g, w);
      CHECK(m.certified);
      CHECK(m.upper - m.lower <= 1e-9);
      double scan = 0;
      for (double t = 0; t < period; t += period / 200000) scan = std::max(scan, g.window_mean(t, w).norm());
      CHECK(scan <= m.upper);  // no start time beats the upper bound
      // The start reported reaches the lower bound (quadrature of the model).
      CHECK(static_cast<double>(quadrature_mean(s, m.start_s, w).norm()) >= m.lower - 1e-12);
    }
  }
}

TEST_CASE("harmonic amplitude: the largest |a cos th + b sin th|, against a dense scan of th", "[window_mean]") {
  std::mt19937 rng(44);
  std::uniform_real_distribution<double> coefficient(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const Vector3d a(coefficient(rng), coefficient(rng), coefficient(rng));
    const Vector3d b = trial % 2 ? Vector3d(a.y(), -a.x(), 0.3 * coefficient(rng)) : Vector3d(coefficient(rng), coefficient(rng), coefficient(rng));
    const double amplitude = semi_major_axis(a, b);
    double scan = 0;
    for (int k = 0; k < 100000; ++k) {
      const double th = 2 * Constants<double>::pi() * k / 100000;
      scan = std::max(scan, (a * std::cos(th) + b * std::sin(th)).norm());
    }
    CHECK(amplitude >= scan);
    CHECK(amplitude <= scan * (1 + 1e-8));  // the scan's step is 6e-5 rad: it misses at most ~1e-9 relative
  }
}

TEST_CASE("torus bound: above a dense scan of |window mean| over both frame angles, below the triangle bound", "[window_mean]") {
  // The window mean at a start lies on F(x, y) = c + sum_k s_k (a_k cos(j x + l y) + b_k sin(j x + l y)),
  // written here from the harmonics; the bound must hold over the whole torus of (x, y).
  for (const auto& s : {machine("1.33", "2"), machine("-0.7", "1.3", 75, 80), machine("0.31", "0.5", 120, 60), machine("2.5", "0", 30, 90)}) {
    const GravitySeries g = GravitySeries::of_gravity(Clinostat(s));
    const TorusGramBound bound(g);
    for (const double w : {3.0, 40.0, 333.0, 2000.0}) {
      double scan = 0, triangle = g.period_mean().norm();
      for (const GravityHarmonic& h : g.oscillating()) triangle += std::fabs(GravitySeries::sinc(h.omega * w / 2)) * h.amplitude;
      for (int i = 0; i < 400; ++i)
        for (int k = 0; k < 400; ++k) {
          const double x = 2 * Constants<double>::pi() * i / 400, y = 2 * Constants<double>::pi() * k / 400;
          Vector3d f = g.period_mean();
          for (const GravityHarmonic& h : g.oscillating()) {
            const double th = h.j * x + h.l * y;
            f += std::sin(h.omega * w / 2) / (h.omega * w / 2) * (h.a * std::cos(th) + h.b * std::sin(th));
          }
          scan = std::max(scan, f.norm());
        }
      CHECK(bound.upper(w) >= scan);
      CHECK(bound.upper(w) <= triangle * (1 + 1e-12) + 1e-13);
    }
  }
}

TEST_CASE("worst window mean of a very short window: certified at 1 (a mean of unit vectors is at most 1 long)", "[window_mean]") {
  const GravitySeries g = GravitySeries::of_gravity(Clinostat(machine("1.33", "2")));
  for (const double w : {1e-3, 1e-9, 1e-300}) {
    const WorstWindowMean m = worst_window_mean(g, w);
    CHECK(m.certified);
    CHECK(m.upper <= 1);
    CHECK(m.lower >= 1 - 1e-9);
  }
}

TEST_CASE("time to epsilon: a mean over a period within rounding of epsilon is not decided, and says so", "[window_mean]") {
  // Speeds 1 and -1 rpm resonate: the mean over a period is 1/2 in exact arithmetic.
  const GravitySeries g = GravitySeries::of_gravity(Clinostat(machine("1", "-1")));
  REQUIRE(std::fabs(g.period_mean().norm() - 0.5) <= 1e-15);
  const TimeToEpsilon t = time_to_epsilon(g, 0.5, 1.0);
  CHECK_FALSE(t.certified);
  CHECK(t.reason.find("within rounding") != std::string::npos);
  CHECK(time_to_epsilon(g, 0.49, 1.0).certified);  // above epsilon: none, certified
  CHECK_FALSE(time_to_epsilon(g, 0.49, 1.0).first_s);
}

TEST_CASE("time to epsilon near a resonance (0.999 / 1 rpm): certified, below at W, above at W - resolution", "[window_mean]") {
  ClinostatSettings s = machine("1", "1");
  s.outer = Rpm(999, 1000);  // period 60000 s, a 1000-min beat
  const GravitySeries g = GravitySeries::of_gravity(Clinostat(s));
  const TimeToEpsilon t = time_to_epsilon(g, 0.01, 1.0);
  REQUIRE(t.certified);
  REQUIRE(t.first_s);
  REQUIRE(t.stays_below_from_s);
  const auto side = [&](double w) { return compare_worst_window_mean(g, w, 0.01); };
  CHECK(side(*t.first_s) == WindowSide::below);
  CHECK(side(*t.first_s - 1) == WindowSide::above);
  REQUIRE(t.above_s);  // a length above epsilon within two resolutions below stays
  CHECK(side(*t.above_s) == WindowSide::above);
  CHECK(*t.above_s >= *t.stays_below_from_s - 2);
  for (double w = *t.stays_below_from_s; w < *t.stays_below_from_s + 5000; w += 499) CHECK(side(w) == WindowSide::below);
  // The beat alone: M(W) ~ |sinc(W_beat W / 2)| / 2 drops below 0.01 near W_beat W / 2 = pi (W = 60000 s).
  CHECK(*t.first_s > 50000);
  CHECK(*t.first_s < 60000);
}

TEST_CASE("time to epsilon: M(W) below at W, above at W - resolution, tilted frames never reach it", "[window_mean]") {
  for (const auto& s : {machine("1.33", "2"), machine("1", "2"), machine("3.2", "-1.7", 60, 90)}) {
    const GravitySeries g = GravitySeries::of_gravity(Clinostat(s));
    for (const double eps : {0.05, 0.01}) {
      const TimeToEpsilon t = time_to_epsilon(g, eps, 1.0);
      REQUIRE(t.certified);
      REQUIRE(t.first_s);
      REQUIRE(t.stays_below_from_s);
      CHECK(worst_window_mean(g, *t.first_s).upper <= eps);
      if (*t.first_s > 1) CHECK(worst_window_mean(g, *t.first_s - 1).lower > eps);
      CHECK(*t.stays_below_from_s >= *t.first_s);
      if (*t.stays_below_from_s > *t.first_s) {
        REQUIRE(t.above_s);
        CHECK(worst_window_mean(g, *t.above_s).lower > eps);
        CHECK(*t.above_s >= *t.stays_below_from_s - 2);
      }
      for (double w = *t.stays_below_from_s; w < *t.stays_below_from_s + 200; w += 7) CHECK(worst_window_mean(g, w).upper <= eps);
    }
  }
  const GravitySeries tilted = GravitySeries::of_gravity(Clinostat(machine("1.33", "2", 60, 70)));  // mean 0.17 g0
  const TimeToEpsilon t = time_to_epsilon(tilted, 0.01, 1.0);
  CHECK_FALSE(t.first_s);
  CHECK_FALSE(t.stays_below_from_s);
  CHECK(t.reason.find("mean over a period") != std::string::npos);
  CHECK(test::expect_invalid([&] { time_to_epsilon(tilted, 0.0, 1.0); }).field() == "epsilon");
  CHECK(test::expect_invalid([&] { time_to_epsilon(tilted, 0.01, -1.0); }).field() == "resolution");
  CHECK(test::expect_invalid([&] { worst_window_mean(tilted, 0.0); }).field() == "window");
}

TEST_CASE("time to epsilon: the grid of a decimal resolution is of decimals (k x 0.01 s and not k * 0.01)", "[window_mean]") {
  // 8760 * 0.01 is 87.60000000000001 in doubles; the grid's window is the double nearest 87.6.
  REQUIRE(8760 * 0.01 != 87.6);
  const GravitySeries g = GravitySeries::of_gravity(Clinostat(machine("1.33", "2")));
  for (const double resolution : {0.01, 0.1, 0.25, 1.0}) {
    for (const double eps : {0.03, 0.05}) {
      INFO("resolution " << resolution << ", epsilon " << eps);
      const TimeToEpsilon t = time_to_epsilon(g, eps, resolution);
      REQUIRE(t.first_s);
      REQUIRE(t.stays_below_from_s);
      // k steps of r = R / 100 (R = 1, 10, 25, 100): the decimal k R / 100, read by strtod.
      const long long hundredths = std::llround(resolution * 100);
      const auto decimal = [&](long long k) { return std::strtod((std::to_string(k * hundredths) + "e-2").c_str(), nullptr); };
      const long long first = std::llround(*t.first_s / resolution);
      CHECK(*t.first_s == decimal(first));
      CHECK(*t.stays_below_from_s == decimal(std::llround(*t.stays_below_from_s / resolution)));
      CHECK(worst_window_mean(g, *t.first_s).upper <= eps);
      if (first > 1) CHECK(worst_window_mean(g, decimal(first - 1)).lower > eps);
    }
  }
}

TEST_CASE("time to epsilon holds for every real window length: one axis at 60 rpm, whose period divides the resolution", "[window_mean]") {
  // Gravity turns in a great circle at w = 2 pi rad/s: |mean over W| = |sin(w W / 2)| / (w W / 2)
  // for every start, so M(W) = |sin(pi W)| / (pi W). Every grid W (whole periods) has M = 0,
  // yet W = 31.5 s has M = 1 / (31.5 pi) > 0.01. The last W with M > 0.01 from that formula, by
  // a scan down from 40 s and bisection in long double.
  ClinostatSettings s;
  s.outer = Rpm(60);
  s.inner = Rpm(0);
  const GravitySeries g = GravitySeries::of_gravity(Clinostat(s));
  const long double pi = 3.141592653589793238462643383279502884L;
  const auto m = [&](long double w) { return std::fabs(std::sin(pi * w)) / (pi * w); };
  long double hi = 40, lo = 40;
  while (m(lo) <= 0.01L) lo -= 1e-3L;
  for (int it = 0; it < 100; ++it) {
    const long double mid = (lo + hi) / 2;
    (m(mid) > 0.01L ? lo : hi) = mid;
  }
  const double threshold = static_cast<double>(hi);  // ~31.55 s
  REQUIRE(threshold > 31.5);
  REQUIRE(threshold < 31.6);
  const TimeToEpsilon t = time_to_epsilon(g, 0.01, 1.0);
  REQUIRE(t.certified);
  REQUIRE(t.stays_below_from_s);
  CHECK(*t.stays_below_from_s >= threshold);
  CHECK(*t.stays_below_from_s <= threshold + 2);
  REQUIRE(t.above_s);
  CHECK(m(*t.above_s) > 0.01L);
  CHECK(*t.above_s >= *t.stays_below_from_s - 2);
  // the claim, off the grid: every W from stays on (steps of 0.013 s over 200 s) is below
  for (double w = *t.stays_below_from_s; w < *t.stays_below_from_s + 200; w += 0.013) CHECK(m(w) <= 0.01L);
  // a finer resolution gives the threshold to within it
  const TimeToEpsilon fine = time_to_epsilon(g, 0.01, 0.01);
  REQUIRE(fine.stays_below_from_s);
  CHECK(*fine.stays_below_from_s >= threshold);
  CHECK(*fine.stays_below_from_s <= threshold + 0.02);
}

TEST_CASE("time to epsilon holds for every real window length: 60 / 120 rpm, against a dense scan in W and the start", "[window_mean]") {
  ClinostatSettings s;
  s.outer = Rpm(60);
  s.inner = Rpm(120);
  const GravitySeries g = GravitySeries::of_gravity(Clinostat(s));
  REQUIRE(g.period_s());
  REQUIRE(*g.period_s() == 1.0);  // every grid window of 1 s steps is a whole number of periods
  const double eps = 0.01;
  // M(W) from below: the largest |window mean| over 400 starts in one period (window_mean is the
  // closed form checked against quadrature above).
  const auto scan = [&](double w) {
    double best = 0;
    for (int k = 0; k < 400; ++k) best = std::max(best, g.window_mean(k / 400.0, w).norm());
    return best;
  };
  const TimeToEpsilon t = time_to_epsilon(g, eps, 1.0);
  REQUIRE(t.certified);
  REQUIRE(t.stays_below_from_s);
  CHECK(*t.stays_below_from_s > 1);  // not the grid's answer (every whole second averages to 0)
  for (double w = *t.stays_below_from_s; w < *t.stays_below_from_s + 60; w += 0.0137) CHECK(scan(w) <= eps);
  double above = 0;  // the scan finds a window above epsilon within two resolutions below stays
  for (double w = *t.stays_below_from_s - 2; w < *t.stays_below_from_s; w += 0.001) above = std::max(above, scan(w));
  CHECK(above > eps);
}
