// Tests of synthesis/precision_points.hpp and interval/interval.hpp. Expected values: the hidden
// train the points were drawn from (forward model TracerCurve, Eq. 4), MPFR at 200 bits for the
// sine enclosures, and an independent Gauss-Newton on P(theta_i) = P_i in all six unknowns
// (a2, a3, phase, theta_1..3) from many random starts for completeness. Seeded.
#include "catch2/catch.hpp"
#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/exact/mpreal_support.hpp"
#include "sphtroch/synthesis/precision_points.hpp"
#include "sphtroch/io/parse.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();

#ifdef SPHTROCH_SANITIZED_BUILD
constexpr int kRandomProblems = 8;  // each solve is ~5x slower under the sanitizers
constexpr int kReferenceStride = 10, kMultistartProblems = 2;
#else
constexpr int kReferenceStride = 1, kMultistartProblems = 6;
constexpr int kRandomProblems = 64;  // bench/precision_points_sweep.cpp runs 1,000 and reports the time
#endif
/// A work bound that keeps the test short: a problem that needs more is returned uncertified,
/// and must say so (certified == false, undecided > 0); a certified one must hold the hidden train.
constexpr std::size_t kTestBoxes = 400000;

struct PointsProblem {
  GearTrain hidden{1.0, 1.0, Ratio(1)};
  std::vector<Vector3d> points;
};

/// |p|, q <= 5, both signs; a2, a3 in [0.15, pi - 0.15]; any phase; three carrier angles over a
/// period, or (near_extreme) the first at a z-extreme of the curve (theta3 = 0 or pi, Eq. 3).
PointsProblem random_points_problem(std::mt19937_64& rng, bool near_extreme = false) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto term = [&] { return static_cast<std::int64_t>(1 + rng() % 5); };
  const std::int64_t p = (rng() % 2 ? -1 : 1) * term();
  const Ratio n(p, term());
  PointsProblem pr{GearTrain(0.15 + u(rng) * (kPi - 0.3), 0.15 + u(rng) * (kPi - 0.3), n, 2 * kPi * u(rng)), {}};
  const TracerCurve<double> curve(pr.hidden);
  for (int i = 0; i < 3; ++i) {
    double t = u(rng) * pr.hidden.period();
    if (near_extreme && i == 0) t = ((rng() % 2 ? kPi : 0.0) + 2 * kPi * double(rng() % 4) - pr.hidden.phase()) / n.value();
    pr.points.push_back(curve.point(t));
  }
  return pr;
}

bool same_train(const GearTrain& a, const GearTrain& b, double tol) {
  const double sector = 2 * kPi / static_cast<double>(a.ratio().q());
  return a.ratio().p() == b.ratio().p() && a.ratio().q() == b.ratio().q() && std::abs(a.a2() - b.a2()) < tol &&
         std::abs(a.a3() - b.a3()) < tol && std::abs(std::remainder(a.phase() - b.phase(), sector)) < tol;
}

/// Every solution passes its points at its own theta2 (checked with the forward model) and none repeats.
void check_solutions(const PointsProblem& pr, const PrecisionPoints& r) {
  for (std::size_t k = 0; k < r.solutions.size(); ++k) {
    const PrecisionSolution& s = r.solutions[k];
    const TracerCurve<double> curve(s.train);
    REQUIRE(s.params.size() == 3);
    for (int i = 0; i < 3; ++i) CHECK((curve.point(s.params[i]) - pr.points[i]).norm() <= 1e-12);
    for (std::size_t j = 0; j < k; ++j) CHECK_FALSE(same_train(s.train, r.solutions[j].train, 1e-9));
  }
}

}  // namespace

TEST_CASE("interval_sin / interval_cos contain sin and cos at 200 bits over random intervals", "[exact][synthesis]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> centre(-400.0, 400.0), width(0.0, 7.0), u(0.0, 1.0);
  const RoundingGuard upward;
  int outside = 0;
  for (int k = 0; k < 20000; ++k) {
    const double lo = centre(rng), hi = lo + (k % 4 == 0 ? 1e-9 : width(rng));
    const Interval s = interval_sin(Interval(lo, hi)), c = interval_cos(Interval(lo, hi));
    for (int j = 0; j <= 8; ++j) {
      const mpfr::mpreal x(j == 0 ? lo : j == 8 ? hi : lo + (hi - lo) * u(rng), 200);
      const mpfr::mpreal sx = sin(x), cx = cos(x);
      if (sx < s.inf() || sx > s.sup() || cx < c.inf() || cx > c.sup()) ++outside;
    }
  }
  CHECK(outside == 0);
  // An extreme k pi / 2 (computed at 200 bits) inside a narrow interval: the enclosure reaches
  // +-1, also far out (k up to ~1e11, where the quarter turn count's own error is ~1e-5).
  std::vector<std::int64_t> ks;
  for (std::int64_t k = -2000; k <= 2000; ++k) ks.push_back(k);
  for (std::int64_t k = 10000001; k < 100000000000; k = k * 7 + 3) ks.insert(ks.end(), {k, -k, k + 1, k + 2});
  int missed = 0;
  for (const std::int64_t k : ks) {
    const mpfr::mpreal x = mpfr::const_pi(200) * static_cast<double>(k) / 2;
    const mpfr::mpreal w = 1e-7 + abs(x) * 1e-15;  // a few ulps of x at least
    // x inside, within an ulp of one end (below the error of the quarter turn count far out).
    for (const auto& [lo, hi] : {std::pair{x.toDouble(MPFR_RNDD), (x + w).toDouble(MPFR_RNDU)},
                                 std::pair{(x - w).toDouble(MPFR_RNDD), x.toDouble(MPFR_RNDU)}}) {
      const Interval s = interval_sin(Interval(lo, hi)), c = interval_cos(Interval(lo, hi));
      const int r = static_cast<int>(((k % 4) + 4) % 4);  // sin = 1, -1 at r = 1, 3; cos = 1, -1 at r = 0, 2
      if ((r == 1 && s.sup() != 1.0) || (r == 3 && s.inf() != -1.0) || (r == 0 && c.sup() != 1.0) || (r == 2 && c.inf() != -1.0))
        ++missed;
    }
  }
  CHECK(missed == 0);
  const Interval top = interval_sin(Interval(kPi / 2 - 1e-12, kPi / 2 + 1e-12));
  CHECK(top.sup() == 1.0);
  CHECK(top.inf() > 0.999);
}

TEST_CASE("interval_sincos of thin intervals (one evaluation at the middle) contains sin and cos at 200 bits and is sharp",
          "[exact][synthesis]") {
  // Widths from 1e-15 to just below kThinTrigWidth, log-uniform; centres anywhere up to 1e6 and
  // one in four next to an extreme k pi / 2. Sharp: no wider than the mean-value theorem's bound
  // 2 r (|cos c| + r) about the middle c (MPFR; r and c within an ulp of the ends) plus a few ulps.
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const RoundingGuard upward;
  int outside = 0, loose = 0, cases = 0;
  for (int k = 0; k < 20000; ++k) {
    const double w = 0.99 * kThinTrigWidth * std::pow(10.0, -14.0 * u(rng));
    const double scale = std::pow(10.0, u(rng) * 6.0);
    double lo = (2.0 * u(rng) - 1.0) * scale;
    if (k % 4 == 0) lo = (mpfr::const_pi(200) * static_cast<double>(static_cast<std::int64_t>(lo)) / 2).toDouble() - w * u(rng);
    const double hi = lo + w;
    if (!(hi > lo)) continue;
    ++cases;
    const auto [s, c] = interval_sincos(Interval(lo, hi));
    for (int j = 0; j <= 8; ++j) {
      const mpfr::mpreal x(j == 0 ? lo : j == 8 ? hi : lo + (hi - lo) * u(rng), 200);
      const mpfr::mpreal sx = sin(x), cx = cos(x);
      if (sx < s.inf() || sx > s.sup() || cx < c.inf() || cx > c.sup()) ++outside;
    }
    // The middle is a double: up to an ulp of the ends from the true one, so r up to an ulp more.
    const mpfr::mpreal mid = (mpfr::mpreal(lo, 200) + mpfr::mpreal(hi, 200)) / 2;
    const mpfr::mpreal r = (mpfr::mpreal(hi, 200) - mpfr::mpreal(lo, 200)) / 2 + std::ldexp(std::max(std::fabs(lo), std::fabs(hi)), -52);
    const double ulps = 16 * std::ldexp(1.0, -52);  // the widening of sin c and cos c, 2^-50 each side
    if (s.sup() - s.inf() > (2 * r * (abs(cos(mid)) + 2 * r)).toDouble() * 1.001 + ulps ||
        c.sup() - c.inf() > (2 * r * (abs(sin(mid)) + 2 * r)).toDouble() * 1.001 + ulps)
      ++loose;
  }
  CHECK(cases > 15000);
  CHECK(outside == 0);
  CHECK(loose == 0);
}

TEST_CASE("precision_points: the hidden train is among the certified solutions of random problems", "[exact][synthesis]") {
  std::mt19937_64 rng(2026);
  int found = 0, certified = 0;
  for (int k = 0; k < kRandomProblems; ++k) {
    const PointsProblem pr = random_points_problem(rng, k % 8 == 7);  // one in eight at a z-extreme
    const PrecisionPoints r = precision_points(pr.points, pr.hidden.ratio(), {kTestBoxes});
    INFO("problem " << k << ": n = " << pr.hidden.ratio().str() << " a2 = " << pr.hidden.a2() << " a3 = " << pr.hidden.a3());
    certified += r.certified;
    CHECK(r.certified == (r.undecided == 0));
    const bool hit = std::any_of(r.solutions.begin(), r.solutions.end(),
                                 [&](const PrecisionSolution& s) { return same_train(s.train, pr.hidden, 1e-9); });
    CHECK((hit || !r.certified));  // a certified list holds every train, the hidden one too
    found += hit;
    check_solutions(pr, r);
  }
  CHECK(found >= certified);
  WARN("within " << kTestBoxes << " boxes: " << certified << " of " << kRandomProblems << " certified complete, hidden train found in "
                 << found);
}

TEST_CASE("precision_points: a point at carrier angle 0 (a trace's first sample) is certified like any other",
          "[exact][synthesis]") {
  // theta_1 = 2 pi k is the edge of theta_1's period; a root there was left undecided before.
  // Also 1/16 either side: the edges of the overlapping domain the solver searches (see its header).
  std::mt19937_64 rng(7);
  for (int k = 0; k < 18; ++k) {
    PointsProblem pr = random_points_problem(rng);
    const double start = 2 * kPi * double(rng() % static_cast<std::uint64_t>(pr.hidden.ratio().q())) +
                         (k % 3 == 0 ? 0.0 : k % 3 == 1 ? 1.0 / 16 : -1.0 / 16);
    pr.points[0] = TracerCurve<double>(pr.hidden).point(start);  // theta_1, the carrier angle at point 1
    const PrecisionPoints r = precision_points(pr.points, pr.hidden.ratio(), {kTestBoxes});
    INFO("problem " << k << ": n = " << pr.hidden.ratio().str() << " a2 = " << pr.hidden.a2() << " a3 = " << pr.hidden.a3());
    CHECK(r.certified);
    CHECK(std::any_of(r.solutions.begin(), r.solutions.end(),
                      [&](const PrecisionSolution& s) { return same_train(s.train, pr.hidden, 1e-9); }));
    check_solutions(pr, r);
  }
}

namespace {

/// Gauss-Newton on the nine equations P(theta_i; a2, a3, phase) = P_i (numeric Jacobian, forward
/// model), from one start; the train if it converged to a residual below 1e-12.
std::optional<GearTrain> independent_solve(const PointsProblem& pr, const Ratio& n, Eigen::Matrix<double, 6, 1> x) {
  const auto residual = [&](const Eigen::Matrix<double, 6, 1>& v) {
    Eigen::Matrix<double, 9, 1> r;
    const auto point = [&](double t) {  // Eq. 4 with a2, a3 free (no GearTrain range checks)
      const Eigen::Matrix3d m = (Eigen::AngleAxisd(t, Vector3d::UnitZ()) * Eigen::AngleAxisd(v(0), Vector3d::UnitX()) *
                                 Eigen::AngleAxisd(n.value() * t + v(2), Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(v(1), Vector3d::UnitX())).toRotationMatrix();
      return Vector3d(m.col(2));
    };
    for (int i = 0; i < 3; ++i) r.segment<3>(3 * i) = point(v(3 + i)) - pr.points[i];
    return r;
  };
  for (int step = 0; step < 40; ++step) {
    const Eigen::Matrix<double, 9, 1> r = residual(x);
    Eigen::Matrix<double, 9, 6> j;
    for (int c = 0; c < 6; ++c) {
      Eigen::Matrix<double, 6, 1> h = x;
      h(c) += 1e-7;
      j.col(c) = (residual(h) - r) / 1e-7;
    }
    x -= j.colPivHouseholderQr().solve(r);
  }
  if (!(residual(x).norm() < 1e-12)) return std::nullopt;
  const double a2 = std::remainder(x(0), 2 * kPi), a3 = std::remainder(x(1), 2 * kPi);
  if (!(a2 > 1e-3 && a2 < kPi - 1e-3 && a3 > 1e-3 && a3 < kPi - 1e-3)) return std::nullopt;  // other sign conventions
  return GearTrain(a2, a3, n, x(2));
}

}  // namespace

TEST_CASE("precision_points: no train found by an independent multistart solver is missing", "[exact][synthesis]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < kMultistartProblems; ++k) {
    const PointsProblem pr = random_points_problem(rng);
    const Ratio n = pr.hidden.ratio();
    const PrecisionPoints r = precision_points(pr.points, n, {kTestBoxes});
    int converged = 0;
    for (int start = 0; start < 300; ++start) {
      Eigen::Matrix<double, 6, 1> x;
      x << kPi * u(rng), kPi * u(rng), 2 * kPi * u(rng), pr.hidden.period() * u(rng), pr.hidden.period() * u(rng),
          pr.hidden.period() * u(rng);
      const auto train = independent_solve(pr, n, x);
      if (!train) continue;
      ++converged;
      INFO("n = " << n.str() << " independent root a2 = " << train->a2() << " a3 = " << train->a3());
      CHECK(std::any_of(r.solutions.begin(), r.solutions.end(),
                        [&](const PrecisionSolution& s) { return same_train(s.train, *train, 1e-7); }));
    }
    CHECK(converged > 0);
  }
}

TEST_CASE("precision_points: points near the planet axis and a cluster of ill-conditioned roots are certified",
          "[exact][synthesis]") {
  // Problems 93 and 139 of bench/precision_points_sweep (1000 7 2026): points of the hidden train
  // (TracerCurve) at random carrier angles. In 93 the three points are within 0.03 rad of one
  // latitude, so trains with a3 down to ~0.01 nearly pass them (f and g carry sin a3: 2.1M boxes
  // before chart 1); 139 has 200+ roots, some with cond(J) ~ 4e4 whose neighbours cannot be
  // excluded until the root is certified (4M boxes, uncertified, before).
  struct Case {
    GearTrain hidden;
    std::vector<Vector3d> points;
  };
  const std::vector<Case> cases = {
      {GearTrain(0.62074270146464716, 0.24601039019105206, Ratio(4), -0.46681500957664501),
       {{-0.30961104751954738, -0.62035395666059501, 0.7206260942467968},
        {0.5846037191312512, 0.40925220436684229, 0.70053631226281887},
        {0.40879081199873846, -0.58518307967295868, 0.70032195116952023}}},
      {GearTrain(2.5768708870349535, 2.8895281022571937, Ratio(5, 7), 2.2796680727581018),
       {{-0.71215449637909234, -0.15491691359999366, 0.68471652759933699},
        {0.64594095037469845, 0.26397621361997442, 0.7162938274701891},
        {-0.050896979616329566, 0.69600543278650839, 0.71623036447612309}}}};
  for (const Case& c : cases) {
    const PointsProblem pr{c.hidden, c.points};
    for (const Vector3d& p : c.points) {  // the points are the hidden train's (to its rounding)
      double nearest = 1.0;
      const TracerCurve<double> curve(c.hidden);
      for (int k = 0; k < 200000; ++k) nearest = std::min(nearest, (curve.point(c.hidden.period() * k / 200000.0) - p).norm());
      REQUIRE(nearest < 1e-3);
    }
    const PrecisionPoints r = precision_points(c.points, c.hidden.ratio(), {1500000});
    INFO("n = " << c.hidden.ratio().str() << ": " << r.solutions.size() << " solutions, " << r.boxes << " boxes");
    CHECK(r.certified);
    CHECK(std::any_of(r.solutions.begin(), r.solutions.end(),
                      [&](const PrecisionSolution& s) { return same_train(s.train, c.hidden, 1e-9); }));
    check_solutions(pr, r);
  }
}

TEST_CASE("precision_points: bad points are refused naming the points", "[exact][synthesis][errors]") {
  const TracerCurve<double> curve(GearTrain(1.0, 2.0, Ratio(1, 2), 0.3));
  const std::vector<Vector3d> good = {curve.point(0.5), curve.point(2.0), curve.point(7.0)};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::vector<Vector3d>> bad = {{good[0], good[1]}, {good[0], good[1], good[2], good[0]},
                                            {good[0], good[1], good[2] * (1 + 2e-6)}, {good[0], good[1], Vector3d(nan, 0, 1)},
                                            {good[0], good[1], good[0]}};
  for (const auto& points : bad) {
    try {
      precision_points(points, Ratio(1, 2));
      FAIL("accepted " << points.size() << " points");
    } catch (const InvalidInput& e) {
      CHECK(e.field() == "points");
    }
  }
  CHECK(precision_points(good, Ratio(1, 2)).certified);
}

TEST_CASE("precision_points: the reference problems' trains (data/reference/precision_points.csv)", "[exact][synthesis]") {
  // Trains and points made by scripts/make_precision_points_reference.py (NumPy, Eq. 4): random,
  // a point at a z-extreme, two points 0.02 rad of carrier angle apart.
  std::ifstream in(std::string(SPHTROCH_REFERENCE_DIR) + "/precision_points.csv");
  REQUIRE(in);
  std::string line;
  int problems = 0, found = 0, certified = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("id,", 0) == 0) continue;
    std::vector<std::string> f;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) f.push_back(cell);
    REQUIRE(f.size() == 18);
    if (std::stoi(f[0]) % kReferenceStride != 0) {  // under the sanitizers: every tenth problem
      ++problems;
      continue;
    }
    const Ratio n = parse_ratio(f[2], "n");
    const PointsProblem pr{GearTrain(std::stod(f[3]), std::stod(f[4]), n, std::stod(f[5])),
                           {Vector3d(std::stod(f[9]), std::stod(f[10]), std::stod(f[11])),
                            Vector3d(std::stod(f[12]), std::stod(f[13]), std::stod(f[14])),
                            Vector3d(std::stod(f[15]), std::stod(f[16]), std::stod(f[17]))}};
    INFO("reference problem " << f[0] << " (" << f[1] << "), n = " << f[2]);
    const PrecisionPoints r = precision_points(pr.points, n, {kTestBoxes});
    const bool hit = std::any_of(r.solutions.begin(), r.solutions.end(),
                                 [&](const PrecisionSolution& s) { return same_train(s.train, pr.hidden, 1e-9); });
    CHECK((hit || !r.certified));
    check_solutions(pr, r);
    ++problems;
    found += hit;
    certified += r.certified;
  }
  CHECK(problems == 60);
  WARN("reference problems: " << certified << " of " << problems << " certified complete within " << kTestBoxes
                              << " boxes, the known train found in " << found);
}

TEST_CASE("precision points with censuses: the work bound's own examples, refused naming the field", "[synthesis][errors]") {
  // Sum over the ratios of |p| (|p| + q)^2 <= 30000: n = 29 (26100) and --ratios 7,7 (23318) pass,
  // 30 (30 * 31^2 = 28830) with 2 (18) passes; n = 40 (67240) and 30 with 10 (1210) are refused.
  CHECK_NOTHROW(check_points_census_work({Ratio(29)}, "n", "29"));
  std::vector<Ratio> seven;
  for (std::int64_t p = 1; p <= 7; ++p)
    for (std::int64_t q = 1; q <= 7; ++q)
      if (std::gcd(p, q) == 1) seven.insert(seven.end(), {Ratio(p, q), Ratio(-p, q)});
  CHECK(points_census_work(seven) == 23318);
  CHECK_NOTHROW(check_points_census_work(seven, "ratios", "7,7"));
  CHECK_NOTHROW(check_points_census_work({Ratio(30), Ratio(2)}, "n", "30"));
  try {
    check_points_census_work({Ratio(40)}, "n", "40");
    FAIL("not refused");
  } catch (const InvalidInput& e) {
    CHECK(e.field() == "n");
    CHECK(e.value() == "40");
  }
  CHECK_THROWS_AS(check_points_census_work({Ratio(30), Ratio(10)}, "n", "30"), InvalidInput);
}

TEST_CASE("precision points: near a continuum of solutions the list is uncertified, at most 64 unisolated trains", "[synthesis]") {
  // Three points on the equator, n = 2: as a2 -> 0 with a3 = pi/2 the tracer tends to the
  // equator, so boxes near a2 = 0 stay undecided (30,000 within 60,000 boxes, 172 distinct
  // trains from them without the bound). Each train listed from them must pass the points
  // (kUnisolatedResidual), and at most kMaxUnisolatedSolutions are listed (each costs a census).
  PrecisionPointsOptions o;
  o.max_boxes = 60000;
  const PrecisionPoints r = precision_points({Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(-1, 0, 0)}, Ratio(2), o);
  CHECK_FALSE(r.certified);
  CHECK(r.undecided > 10 * kMaxUnisolatedSolutions);
  const auto unisolated = std::count_if(r.solutions.begin(), r.solutions.end(), [](const PrecisionSolution& s) { return !s.isolated; });
  CHECK(unisolated > 0);
  CHECK(static_cast<std::size_t>(unisolated) <= kMaxUnisolatedSolutions);
  const std::vector<Vector3d> points{Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(-1, 0, 0)};
  for (const PrecisionSolution& s : r.solutions) {
    const TracerCurve<double> curve(s.train);
    for (int i = 0; i < 3; ++i) CHECK((curve.point(s.params[i]) - points[i]).norm() <= 1e-12);
  }
}

TEST_CASE("precision_points: phases on a sector boundary (a phase-0 trace) reduce into 0 .. 2 pi / q, never a few ulp below 0",
          "[exact][synthesis]") {
  // phase = k * sector rounded: phase / sector rounds to k from either side, and phase - k sector
  // is then a few ulp below 0 for some k (synth merge refused such parts: a phase below 0).
  const double pi = Constants<double>::pi();
  int below_zero_unreduced = 0;
  for (int q = 1; q <= 60; ++q) {
    const double sector = 2 * pi / q;
    for (int k = -200; k <= 200; ++k) {
      const double on = k * sector;
      for (const double phase : {on, std::nextafter(on, -1e300), std::nextafter(on, 1e300)}) {
        const auto [m, r] = precision_detail::reduce_to_sector(phase, sector);
        INFO("q = " << q << ", k = " << k << ", phase = " << phase);
        CHECK(r >= 0.0);
        CHECK(r < sector);
        CHECK(m == std::floor(m));
        CHECK(std::abs(m * sector + r - phase) <= 4 * std::numeric_limits<double>::epsilon() * (std::abs(phase) + sector));
        if (phase - std::floor(phase / sector) * sector < 0) ++below_zero_unreduced;
      }
    }
  }
  CHECK(below_zero_unreduced > 0);  // the plain formula does go below 0 on these inputs
}
