// Tests of synthesis/identify.hpp: the train of a timed trace. Expected values come from the
// hidden train the samples were drawn from (the forward model, TracerCurve, Eq. 4), never from
// identify itself; the random problems are seeded.
#include "catch2/catch.hpp"
#include "test_support.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/synthesis/identify.hpp"

#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();

struct Problem {
  GearTrain hidden{1.0, 1.0, Ratio(1)};
  std::vector<double> t;
  std::vector<Vector3d> points;
};

/// A random train (|p|, q <= 7, both signs, a2, a3 in [0.15, pi - 0.15], any phase) sampled from a
/// random start over 1 to 1.5 periods with a random count dense enough to follow the planet.
Problem random_problem(std::mt19937_64& rng, double sigma = 0.0) {
  std::uniform_int_distribution<int> term(1, 7), sign(0, 1);
  std::uniform_real_distribution<double> angle(0.15, kPi - 0.15), phase(-kPi, kPi), start(-50, 50), more(1.0, 1.5);
  std::int64_t p = term(rng), q = term(rng);
  while (std::gcd(p, q) != 1) q = term(rng);
  if (sign(rng)) p = -p;
  Problem pr;
  pr.hidden = GearTrain(angle(rng), angle(rng), Ratio(p, q), phase(rng));
  const double span = pr.hidden.period() * more(rng);
  const auto dense = static_cast<int>(std::ceil(4.0 * std::abs(static_cast<double>(p)) * span / pr.hidden.period() * q)) + 8;
  const int count = std::uniform_int_distribution<int>(std::max(dense, 16), 2000)(rng);
  const double t0 = start(rng);
  const TracerCurve<double> curve(pr.hidden);
  std::normal_distribution<double> noise(0.0, sigma);
  for (int i = 0; i < count; ++i) {
    const double t = t0 + span * i / (count - 1);
    Vector3d x = curve.point(t);
    if (sigma > 0) x = (x + Vector3d(noise(rng), noise(rng), noise(rng))).normalized();
    pr.t.push_back(t);
    pr.points.push_back(x);
  }
  return pr;
}

/// max |P_hidden(t_i) - P_identified(t_i)| by the forward model.
double curve_distance(const GearTrain& a, const GearTrain& b, const std::vector<double>& t) {
  const TracerCurve<double> ca(a), cb(b);
  double worst = 0;
  for (double x : t) worst = std::max(worst, (ca.point(x) - cb.point(x)).norm());
  return worst;
}

}  // namespace

TEST_CASE("simplest_fraction: the fraction of smallest denominator in an interval", "[identify]") {
  CHECK(simplest_fraction(0.33, 0.34, 1000) == Ratio(1, 3));
  CHECK(simplest_fraction(2.5 - 1e-9, 2.5 + 1e-9, 1000) == Ratio(5, 2));
  CHECK(simplest_fraction(-1.7, -1.6, 1000) == Ratio(-5, 3));
  CHECK(simplest_fraction(2.9, 3.2, 1000) == Ratio(3));
  CHECK(simplest_fraction(101.0 / 40 - 1e-12, 101.0 / 40 + 1e-12, 1000) == Ratio(101, 40));
  CHECK_FALSE(simplest_fraction(-0.1, 0.2, 1000));                   // n = 0 is no ratio
  CHECK_FALSE(simplest_fraction(0.33333, 0.333334, 2));                 // needs q = 3
  CHECK(simplest_fraction(0.33333, 0.333334, 3) == Ratio(1, 3));
}

TEST_CASE("identify: 1000 random trains, n exact and the curve reproduced within 1e-9", "[identify]") {
  std::mt19937_64 rng(19);
  int exact = 0;
  for (int k = 0; k < 1000; ++k) {
    const Problem pr = random_problem(rng);
    INFO("problem " << k << ": n = " << pr.hidden.ratio().str() << ", a2 = " << pr.hidden.a2() << ", a3 = "
                    << pr.hidden.a3() << ", phase = " << pr.hidden.phase() << ", " << pr.t.size() << " samples");
    const Identified id = identify(pr.t, pr.points);
    REQUIRE(id.train.ratio() == pr.hidden.ratio());
    CHECK(std::abs(id.train.a2() - pr.hidden.a2()) < 1e-9);
    CHECK(std::abs(id.train.a3() - pr.hidden.a3()) < 1e-9);
    const double d = curve_distance(id.train, pr.hidden, pr.t);
    CHECK(d < 1e-9);
    CHECK(id.residual < 1e-9);
    exact += d < 1e-9;
  }
  CHECK(exact == 1000);
}

TEST_CASE("identify: noise sigma = 1e-4 rad: n right, a2 and a3 within 10 sigma", "[identify]") {
  std::mt19937_64 rng(2026);
  const double sigma = 1e-4;
  for (int k = 0; k < 300; ++k) {
    const Problem pr = random_problem(rng, sigma);
    INFO("problem " << k << ": n = " << pr.hidden.ratio().str() << ", a2 = " << pr.hidden.a2() << ", a3 = "
                    << pr.hidden.a3() << ", " << pr.t.size() << " samples");
    const Identified id = identify(pr.t, pr.points);
    REQUIRE(id.train.ratio() == pr.hidden.ratio());
    CHECK(std::abs(id.train.a2() - pr.hidden.a2()) < 10 * sigma);
    CHECK(std::abs(id.train.a3() - pr.hidden.a3()) < 10 * sigma);
    CHECK(id.noise < 3 * sigma);
  }
}

TEST_CASE("identify: the report's Fig. 3 from trace's own sampling, and trace's open curves", "[identify]") {
  const GearTrain fig3(kPi / 2, kPi / 2, Ratio(1));
  const Trajectory<double> closed = sample_period(TracerCurve<double>(fig3), 360);
  const Identified a = identify(closed.t, closed.points);
  CHECK(a.train.ratio() == Ratio(1));
  CHECK(std::abs(a.train.a2() - kPi / 2) < 1e-12);
  CHECK(std::abs(a.train.a3() - kPi / 2) < 1e-12);
  const GearTrain g(2.0, 0.5, Ratio(-13, 5), -2.5);
  const Trajectory<double> open = sample_turns(TracerCurve<double>(g), 7.0, 9000);
  const Identified b = identify(open.t, open.points);
  CHECK(b.train.ratio() == Ratio(-13, 5));
  CHECK(curve_distance(b.train, g, open.t) < 1e-9);
}

TEST_CASE("identify: a planet circle of radius down to 5e-5 (a3 near 0 or pi) still gives n exactly", "[identify]") {
  // The planet angles carry the points' rounding divided by sin a3: the ratio's window must hold
  // it (a3 = 1e-4 gave a slope 2.2e-12 off n = 2, refused before).
  for (const double a3 : {5e-5, 1e-4, 2e-4, kPi - 1e-5, kPi - 1e-4}) {
    for (const Ratio n : {Ratio(2), Ratio(1, 7), Ratio(5, 3), Ratio(-3, 2)}) {
      const GearTrain g(1.3, a3, n, 0.4);
      const Trajectory<double> tr = sample_period(TracerCurve<double>(g), 1000);
      INFO("a3 = " << a3 << ", n = " << n.str());
      const Identified r = identify(tr.t, tr.points);
      CHECK(r.train.ratio() == n);
      CHECK(curve_distance(r.train, g, tr.t) < 1e-9);
    }
  }
}

TEST_CASE("identify: bad samples are one InvalidInput naming the field", "[identify][errors]") {
  std::mt19937_64 rng(7);
  const Problem pr = random_problem(rng);
  auto field_of = [](const std::vector<double>& t, const std::vector<Vector3d>& p) {
    return test::expect_invalid([&] { identify(t, p); }).field();
  };
  CHECK(field_of({pr.t.begin(), pr.t.begin() + 5}, {pr.points.begin(), pr.points.begin() + 5}) == "samples");
  std::vector<double> t = pr.t;
  t[3] = t[2];  // a duplicate sample time
  CHECK(field_of(t, pr.points) == "t");
  t = pr.t;
  t[4] = std::nan("");
  CHECK(field_of(t, pr.points) == "t");
  std::vector<Vector3d> p = pr.points;
  p[5] *= 1.01;  // off the sphere
  CHECK(field_of(pr.t, p) == "points");
  p = pr.points;
  p[6] = Vector3d(std::nan(""), 0, 1);
  CHECK(field_of(pr.t, p) == "points");
  CHECK(field_of(pr.t, {pr.points.begin(), pr.points.end() - 1}) == "samples");
  // Two trains mixed: no planet circle.
  p = pr.points;
  const TracerCurve<double> other(GearTrain(0.4, 2.6, Ratio(3)));
  for (std::size_t i = 0; i < p.size(); i += 2) p[i] = other.point(pr.t[i]);
  CHECK(field_of(pr.t, p) == "samples");
  // Too sparse to follow the planet: 3 samples per planet turn.
  const GearTrain fast(1.0, 1.0, Ratio(7));
  std::vector<double> ts;
  std::vector<Vector3d> ps;
  for (int i = 0; i < 40; ++i) {
    ts.push_back(i * 2 * kPi / 7 / 2.2);
    ps.push_back(TracerCurve<double>(fast).point(ts.back()));
  }
  CHECK(field_of(ts, ps) == "samples");
  // Bounds too tight for the ratio.
  IdentifyOptions tight;
  tight.max_q = 2;
  const Trajectory<double> tr = sample_period(TracerCurve<double>(GearTrain(1.0, 1.0, Ratio(5, 3))), 900);
  CHECK(test::expect_invalid([&] { identify(tr.t, tr.points, tight); }).field() == "samples");
}

TEST_CASE("identify: D1 a planet circle below the samples' resolution (a3 1e-12 .. 1e-3, near pi) never gives a wrong n",
          "[identify]") {
  // |p|, q <= 50: every exit-0 answer must be the hidden ratio; a refusal names the samples. With
  // exact samples the accepted rms is 1e-6, so a3 <= 1e-6 cannot determine n (any ratio fits within
  // sin a3) and must be refused, while a3 >= 1e-4 is well resolved and must be identified.
  std::mt19937_64 rng(40);
  std::uniform_int_distribution<int> term(1, 50), sign(0, 1);
  std::uniform_real_distribution<double> a2s(0.2, kPi - 0.2), phases(-kPi, kPi);
  std::vector<double> a3s;
  for (const double a3 : {1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 2e-6, 5e-6, 1e-5, 3e-5, 1e-4, 1e-3}) {
    a3s.push_back(a3);
    a3s.push_back(kPi - a3);
  }
  int identified = 0, refused = 0;
  for (int k = 0; k < 12; ++k) {
    std::int64_t p = term(rng), q = term(rng);
    while (std::gcd(p, q) != 1) q = term(rng);
    if (sign(rng)) p = -p;
    const double a2 = a2s(rng), phase = phases(rng);
    for (const double a3 : a3s) {
      const GearTrain hidden(a2, a3, Ratio(p, q), phase);
      const Trajectory<double> tr = sample_period(TracerCurve<double>(hidden), std::size_t(std::max<std::int64_t>(1000, 20 * (std::abs(p) + q))));
      const double offset = std::min(a3, kPi - a3);
      INFO("n = " << hidden.ratio().str() << ", a2 = " << a2 << ", a3 = " << a3);
      try {
        const Identified id = identify(tr.t, tr.points);
        CHECK(id.train.ratio() == hidden.ratio());
        CHECK(offset > 1e-6);
        ++identified;
      } catch (const InvalidInput& e) {
        CHECK(e.field() == "samples");
        CHECK(offset < 1e-4);
        if (offset <= 1e-6) CHECK(e.problem().find("below the samples' resolution") != std::string::npos);
        ++refused;
      }
    }
  }
  CHECK(identified > 0);
  CHECK(refused > 0);
}

TEST_CASE("identify: D2 two trains mixed along t (a2 0.70, then 0.71) are a systematic misfit and refused", "[identify]") {
  for (const Ratio n : {Ratio(2), Ratio(5, 2), Ratio(-1, 3)}) {
    for (const double a3 : {1.0, 2.5}) {
      const GearTrain first(0.70, a3, n), second(0.71, a3, n);
      const Trajectory<double> a = sample_period(TracerCurve<double>(first), 2000);
      const Trajectory<double> b = sample_period(TracerCurve<double>(second), 2000);
      std::vector<double> t;
      std::vector<Vector3d> p;
      for (std::size_t i = 0; i < 2000; ++i) {
        t.push_back(a.t[i]);
        p.push_back(i < 1000 ? a.points[i] : b.points[i]);
      }
      INFO("n = " << n.str() << ", a3 = " << a3);
      const InvalidInput e = test::expect_invalid([&] { identify(t, p); });
      CHECK(e.field() == "samples");
      // Either the circle or the systematic-misfit check refuses; never an answer.
      CHECK((e.problem().find("systematically") != std::string::npos || e.problem().find("circle") != std::string::npos ||
             e.problem().find("fits them") != std::string::npos));
    }
  }
  // The same samples from one train with white noise of the mixture's size are identified.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 2e-3);
  const GearTrain one(0.70, 1.0, Ratio(2));
  const Trajectory<double> tr = sample_period(TracerCurve<double>(one), 2000);
  std::vector<Vector3d> noisy;
  for (const Vector3d& x : tr.points) noisy.push_back((x + Vector3d(noise(rng), noise(rng), noise(rng))).normalized());
  CHECK(identify(tr.t, noisy).train.ratio() == Ratio(2));
}

TEST_CASE("identify: D6 one point repeated 5000 times is refused as the samples' problem, not as a fitted a2",
          "[identify][errors]") {
  const Vector3d point = Vector3d(0.3, -0.5, 0.8).normalized();
  std::vector<double> t;
  std::vector<Vector3d> p;
  for (int i = 0; i < 5000; ++i) {
    t.push_back(0.001 * i);
    p.push_back(point);
  }
  const InvalidInput e = test::expect_invalid([&] { identify(t, p); });
  CHECK(e.field() == "samples");
  CHECK(e.problem().find("sun axis") != std::string::npos);
}
