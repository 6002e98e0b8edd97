// Tests of synthesis/path_distance.hpp, synthesis/path_fit.hpp and exact/path_fit_output.hpp.
// Expected values: the hidden train the noisy points were drawn from (forward model TracerCurve,
// Eq. 4), its census by classify() (the certified census, run here on the hidden train and again
// on every returned train), the counts the boundary set lists at the hidden a2, finite
// differences for derivatives and a dense brute-force search for the nearest curve point. Seeded.
#include "catch2/catch.hpp"
#include "sphtroch/classify.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/synthesis.hpp"
#include "sphtroch/exact/self_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();
constexpr double kSigma = 1e-4;  // radians, the noise of the acceptance targets

#ifdef SPHTROCH_SANITIZED_BUILD
constexpr int kNoisyTargets = 8;  // two per test case  // each fit and census is ~5x slower under the sanitizers
#else
constexpr int kNoisyTargets = 200;  // bench/path_fit_sweep.cpp runs more and reports the time
#endif

struct Target {
  GearTrain hidden{1.0, 1.0, Ratio(1)};
  std::vector<Vector3d> points;
};

/// A random train (|p|, q <= 7, both signs; a2, a3 in [0.1, pi - 0.1]; any phase) and 60 .. 200
/// points at random carrier angles over one period (sorted: a path), each moved by a tangent
/// Gaussian of sigma per direction.
Target random_target(std::mt19937_64& rng, double sigma) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  std::int64_t p = 0, q = 0;
  do {
    p = 1 + static_cast<std::int64_t>(rng() % 7);
    q = 1 + static_cast<std::int64_t>(rng() % 7);
  } while (std::gcd(p, q) != 1);
  Target t{GearTrain(0.1 + u(rng) * (kPi - 0.2), 0.1 + u(rng) * (kPi - 0.2), Ratio(rng() % 2 ? -p : p, q), 2 * kPi * u(rng)), {}};
  const TracerCurve<double> curve(t.hidden);
  std::vector<double> ts(60 + rng() % 141);
  for (double& x : ts) x = u(rng) * t.hidden.period();
  std::sort(ts.begin(), ts.end());
  for (double x : ts) {
    const Vector3d P = curve.point(x);
    Vector3d e(g(rng), g(rng), g(rng));
    e -= P * P.dot(e);
    t.points.push_back((P + sigma * e).normalized());
  }
  return t;
}

/// The node counts the boundary set lists at a2 (either side of every event).
std::vector<std::int64_t> counts_at(double a2, const Ratio& n) {
  std::vector<std::int64_t> out;
  for (const BoundaryEvent& e : boundary_set(a2, n).events) {
    out.push_back(e.nodes_below);
    out.push_back(e.nodes_above);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// Every returned train has the wanted counts, certified (its census as returned); and, an
/// independent count, the exact self-crossings of a dense polyline of the best train
/// (self_crossings.hpp) equal its crossing node points, when it is at least 1e-3 from every
/// boundary (closer, a near-tangent crossing needs a finer polyline) and has no tangency node.
void check_counts(const std::vector<RatioFit>& fits, const FitOptions& o) {
  for (const RatioFit& rf : fits)
    for (std::size_t k = 0; k < rf.candidates.size(); ++k) {
      const ConfirmedCandidate& c = rf.candidates[k];
      const Classification& census = c.census;
      INFO("candidate a2 = " << c.candidate.train.a2() << " a3 = " << c.candidate.train.a3());
      CHECK(census.input.a3() == c.candidate.train.a3());
      CHECK(census.certified());
      if (o.nodes) CHECK(static_cast<std::int64_t>(census.nodes.size()) == *o.nodes);
      if (o.cusps) CHECK(static_cast<std::int64_t>(census.cusps.size()) == *o.cusps);
      CHECK(c.candidate.margin >= 0);
      if (k == 0 && c.candidate.margin > 1e-3 && census.tangencies == 0 && census.cusps.empty()) {
        const auto polyline = sample_period(TracerCurve<double>(c.candidate.train),
                                            20000 * static_cast<std::size_t>(c.candidate.train.ratio().q()));
        CHECK(find_self_crossings(polyline.points, true).crossings.size() == census.crossings);
      }
    }
}

/// Each point lies within the candidate's max_deviation of its train's curve point at params[i]
/// (the forward model), and the RMS is that of those distances.
void check_params(const PathFit& f, const std::vector<Vector3d>& points) {
  for (const FitCandidate& c : f.candidates) {
    REQUIRE(c.params.size() == points.size());
    const TracerCurve<double> curve(c.train);
    double sum = 0, worst = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double d = sphere_distance(curve.point(c.params[i]), points[i]);
      sum += d * d;
      worst = std::max(worst, d);
    }
    CHECK(worst <= c.max_deviation + 1e-12);
    CHECK(std::abs(std::sqrt(sum / double(points.size())) - c.rms) <= 1e-12 + 1e-9 * c.rms);
  }
}

}  // namespace

TEST_CASE("curve_jet: the forward model's point and finite-difference derivatives", "[synthesis]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.1, 3.0);
  for (int k = 0; k < 50; ++k) {
    const GearTrain g(u(rng), u(rng), Ratio(k % 2 ? -5 : 3, k % 3 + 1), u(rng));
    const FitShape s{g.a2(), g.a3(), g.n(), g.phase()};
    const double t = 4 * u(rng), h = 1e-6;
    const CurveJet j = curve_jet(s, t);
    CHECK((j.point - TracerCurve<double>(g).point(t)).norm() < 1e-14);
    auto fd = [&](FitShape a, FitShape b, double dt) {
      return Vector3d((curve_jet(b, t + dt).point - curve_jet(a, t - dt).point) / (2 * h));
    };
    CHECK((fd(s, s, h) - j.d_t).norm() < 1e-8);
    CHECK(((curve_jet(s, t + h).d_t - curve_jet(s, t - h).d_t) / (2 * h) - j.d_tt).norm() < 1e-7);
    CHECK((curve_point(s, t) - j.point).norm() < 1e-15);
    FitShape lo(s.a2 - h, s.a3, s.n, s.phase), hi(s.a2 + h, s.a3, s.n, s.phase);
    CHECK((fd(lo, hi, 0) - j.d_a2).norm() < 1e-8);
    lo = FitShape(s.a2, s.a3 - h, s.n, s.phase), hi = FitShape(s.a2, s.a3 + h, s.n, s.phase);
    CHECK((fd(lo, hi, 0) - j.d_a3).norm() < 1e-8);
    lo = FitShape(s.a2, s.a3, s.n, s.phase - h), hi = FitShape(s.a2, s.a3, s.n, s.phase + h);
    CHECK((fd(lo, hi, 0) - j.d_phase).norm() < 1e-8);
  }
}

TEST_CASE("nearest_param: no nearer curve point than a dense brute-force search finds", "[synthesis]") {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int k = 0; k < 40; ++k) {
    const Target t = random_target(rng, 0.0);
    const GearTrain& h = t.hidden;
    const FitShape s{h.a2(), h.a3(), h.n(), h.phase()};
    const TracerCurve<double> curve(h);
    const std::size_t samples = 20000 * static_cast<std::size_t>(h.ratio().q());
    Vector3d P = t.points[0] + (k % 2 ? 0.02 : 1e-4) * Vector3d(g(rng), g(rng), g(rng));
    P.normalize();
    double brute = 10;
    for (std::size_t i = 0; i < samples; ++i)
      brute = std::min(brute, sphere_distance(curve.point(h.period() * double(i) / double(samples)), P));
    const double found = sphere_distance(curve.point(nearest_param(s, h.ratio().abs_p(), h.period(), P)), P);
    INFO("n = " << h.ratio().str() << " a2 = " << h.a2() << " a3 = " << h.a3());
    CHECK(found <= brute + 1e-12);
    // A point on the curve is at distance 0 from it.
    CHECK(sphere_distance(curve.point(nearest_param(s, h.ratio().abs_p(), h.period(), t.points[1])), t.points[1]) < 1e-12);
  }
}

TEST_CASE("nearest_param_certified: far points get the global nearest point, where a local foot can be another branch's",
          "[synthesis]") {
  // The fit of an n = 2 path by n = 1/3 with both cusps (a poor fit, points up to ~1 rad away):
  // the latitude-based foot of some points is a farther branch's. The certified foot must be no
  // farther than a dense search's nearest sample (period / 200000 apart), and so must the feet of
  // random points for random trains.
  const auto brute = [](const TracerCurve<double>& curve, double period, const Vector3d& x, std::size_t samples) {
    double best = 10;
    for (std::size_t i = 0; i < samples; ++i) best = std::min(best, sphere_distance(curve.point(period * double(i) / double(samples)), x));
    return best;
  };
  const GearTrain far(std::acos(-1.0 / 3), kPi / 2, Ratio(1, 3), 0.6438734786750422);
  const FitShape s{far.a2(), far.a3(), far.n(), far.phase()};
  const TracerCurve<double> curve(far);
  const std::vector<Vector3d> path = sample_period(TracerCurve<double>(GearTrain(1.1, 0.9, Ratio(2), 0.4)), 60).points;
  int local_wrong = 0;
  for (const Vector3d& x : path) {
    const double b = brute(curve, far.period(), x, 200000);
    const double found = sphere_distance(curve.point(nearest_param_certified(s, far.period(), x, nearest_param(s, 1, far.period(), x))), x);
    CHECK(found <= b + 1e-9);
    local_wrong += sphere_distance(curve.point(nearest_param(s, 1, far.period(), x)), x) > b + 1e-3;
  }
  CHECK(local_wrong > 0);  // the case the certified search is for is exercised
  std::mt19937_64 rng(8);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int k = 0; k < 20; ++k) {
    const GearTrain& h = random_target(rng, 0.0).hidden;
    const FitShape r{h.a2(), h.a3(), h.n(), h.phase()};
    const TracerCurve<double> c(h);
    const Vector3d x = Vector3d(g(rng), g(rng), g(rng)).normalized();
    const double found = sphere_distance(c.point(nearest_param_certified(r, h.period(), x, 0.0)), x);
    INFO("n = " << h.ratio().str() << " a2 = " << h.a2() << " a3 = " << h.a3());
    CHECK(found <= brute(c, h.period(), x, 20000 * static_cast<std::size_t>(h.ratio().q())) + 1e-9);
  }
}

TEST_CASE("fit: exact points give back the hidden train first", "[exact][synthesis]") {
  std::mt19937_64 rng(7);
  for (int k = 0; k < (kNoisyTargets >= 200 ? 20 : 3); ++k) {
    const Target t = random_target(rng, 0.0);
    const PathFit f = fit_path(t.points, t.hidden.ratio());
    INFO("n = " << t.hidden.ratio().str() << " a2 = " << t.hidden.a2() << " a3 = " << t.hidden.a3());
    REQUIRE_FALSE(f.candidates.empty());
    const GearTrain& best = f.candidates[0].train;
    CHECK(f.candidates[0].rms < 1e-9);
    CHECK(std::abs(best.a2() - t.hidden.a2()) < 1e-7);
    CHECK(std::abs(best.a3() - t.hidden.a3()) < 1e-7);
    CHECK(std::abs(std::remainder(best.phase() - t.hidden.phase(), 2 * kPi / double(best.ratio().q()))) < 1e-7);
    for (std::size_t i = 1; i < f.candidates.size(); ++i) CHECK(f.candidates[i].rms >= f.candidates[i - 1].rms);
    check_params(f, t.points);
  }
}

/// kNoisyTargets / 4 targets of the seed (four test cases, so that ctest -j2 runs them side by side).
static void fit_noisy_targets(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  int others = 0;
  for (int k = 0; k < kNoisyTargets / 4; ++k) {
    const Target t = random_target(rng, kSigma);
    const Classification hidden = classify(t.hidden);
    if (!hidden.certified()) continue;  // the request below must be the hidden train's certified count
    const Ratio n = t.hidden.ratio();
    INFO("target " << k << ": n = " << n.str() << " a2 = " << t.hidden.a2() << " a3 = " << t.hidden.a3()
                   << " nodes = " << hidden.nodes.size());
    FitOptions o;
    o.nodes = static_cast<std::int64_t>(hidden.nodes.size());
    const auto fits = fit_with_census(t.points, {n}, o);
    REQUIRE_FALSE(fits[0].candidates.empty());
    CHECK(fits[0].candidates[0].candidate.rms <= 2 * kSigma);
    check_counts(fits, o);
    if (k % 4 == 0) {  // another count that exists at this a2
      for (std::int64_t other : counts_at(t.hidden.a2(), n)) {
        if (other == *o.nodes) continue;
        FitOptions w;
        w.nodes = other;
        INFO("asking for " << other << " nodes");
        const auto f = fit_with_census(t.points, {n}, w);
        CHECK_FALSE(f[0].candidates.empty());
        check_counts(f, w);
        ++others;
        break;
      }
    }
    if (k % 10 == 0) {  // impossible counts: none, with a reason
      FitOptions w;
      w.nodes = 1000 * n.abs_p();
      const auto f = fit_with_census(t.points, {n}, w);
      CHECK(f[0].candidates.empty());
      CHECK(f[0].reason.find("node points, not " + std::to_string(*w.nodes)) != std::string::npos);
      w.nodes.reset();
      if (n.abs_p() > 1) w.nodes = n.abs_p() + 1;  // not a multiple of |p|
      w.cusps = 3 * n.abs_p() + 1;                   // not 0, |p| or 2|p|
      const auto g = fit_with_census(t.points, {n}, w);
      CHECK(g[0].candidates.empty());
      CHECK_FALSE(g[0].reason.empty());
    }
    if (k % 10 == 5) {  // cusps: on a pitch cone, exactly |p| of them
      FitOptions w;
      w.cusps = n.abs_p();
      const auto f = fit_with_census(t.points, {n}, w);
      CHECK_FALSE(f[0].candidates.empty());
      check_counts(f, w);
    }
  }
  CHECK(others > 0);
}

TEST_CASE("fit with a node count on noisy targets (1 of 4): never a wrong count, the hidden train's RMS", "[exact][synthesis]") {
  fit_noisy_targets(2026);
}
TEST_CASE("fit with a node count on noisy targets (2 of 4)", "[exact][synthesis]") { fit_noisy_targets(2027); }
TEST_CASE("fit with a node count on noisy targets (3 of 4)", "[exact][synthesis]") { fit_noisy_targets(2028); }
TEST_CASE("fit with a node count on noisy targets (4 of 4)", "[exact][synthesis]") { fit_noisy_targets(2029); }

/// kNoisyTargets / 2 targets of the seed with --min-margin D and the hidden node count: every
/// candidate certified at least D from a change of its census, and (an independent check of the
/// proof, for one candidate in three) classify at the four corners of its 0.99 D square draws the
/// candidate's census.
static void fit_min_margin_targets(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  int with_margin = 0, asked = 0;
  for (int k = 0; k < kNoisyTargets / 2; ++k) {
    const Target t = random_target(rng, kSigma);
    const Classification hidden = classify(t.hidden);
    if (!hidden.certified()) continue;
    const Ratio n = t.hidden.ratio();
    INFO("target " << k << ": n = " << n.str() << " a2 = " << t.hidden.a2() << " a3 = " << t.hidden.a3());
    FitOptions o;
    o.nodes = static_cast<std::int64_t>(hidden.nodes.size());
    o.min_margin = 0.01;
    const auto f = fit_with_census(t.points, {n}, o);
    check_counts(f, o);
    with_margin += f[0].candidates.empty() ? 0 : 1;
    ++asked;
    for (std::size_t i = 0; i < f[0].candidates.size(); ++i) {
      const ConfirmedCandidate& c = f[0].candidates[i];
      CHECK(c.certified_margin.lower >= o.min_margin);
      const GearTrain& t = c.census.snapped.train;  // the D-square in the range: buildable to +-D
      CHECK((t.a2() - o.min_margin >= 1e-6 && t.a2() + o.min_margin <= kPi - 1e-6 && t.a3() - o.min_margin >= 1e-6 &&
             t.a3() + o.min_margin <= kPi - 1e-6));
      if ((k + i) % 3 != 0) continue;
      const GearTrain& g = c.census.snapped.train;
      for (const double da2 : {-0.99 * o.min_margin, 0.99 * o.min_margin})
        for (const double da3 : {-0.99 * o.min_margin, 0.99 * o.min_margin}) {
          const Classification corner = classify(GearTrain(g.a2() + da2, g.a3() + da3, n, g.phase()));
          CHECK(corner.nodes.size() == c.census.nodes.size());
          CHECK(corner.cusps.size() == c.census.cusps.size());
        }
    }
  }
  CHECK(with_margin * 2 >= asked);  // most wanted counts have a cell wider than 2 D
}

TEST_CASE("fit --min-margin on noisy targets (1 of 2): every candidate certified at least D from a topology change", "[exact][synthesis]") {
  fit_min_margin_targets(4051);
}
TEST_CASE("fit --min-margin on noisy targets (2 of 2)", "[exact][synthesis]") { fit_min_margin_targets(4052); }

TEST_CASE("fit with cusps: |p| on a pitch cone, 2|p| where both cones meet (|n| < 1)", "[exact][synthesis]") {
  const GearTrain hidden(1.0, 2.0, Ratio(1, 2), 0.3);
  const std::vector<Vector3d> points = sample_period(TracerCurve<double>(hidden), 200).points;
  for (std::int64_t cusps : {1, 2}) {
    FitOptions o;
    o.cusps = cusps;
    o.max_candidates = 2;
    const auto f = fit_with_census(points, {hidden.ratio()}, o);
    INFO("cusps " << cusps);
    REQUIRE_FALSE(f[0].candidates.empty());
    check_counts(f, o);
    for (const auto& c : f[0].candidates) {
      // On a cone exactly (both for 2|p|): a3 is the cone's angle by construction (its reference,
      // offset 0), so cone_margins' long double evaluation of the identity gives 0 to its rounding.
      const GearTrain& t = c.candidate.train;
      CHECK(t.a3_offset() == 0.0);
      CHECK((t.a3_reference() == A3Reference::pitch_cone || t.a3_reference() == A3Reference::mirror_pitch_cone));
      const ConeMargins m = cone_margins(t);
      CHECK((m.on_pitch_cone(1e-18) || m.on_mirror_cone(1e-18)));
      if (cusps == 2) CHECK((m.on_pitch_cone(1e-12) && m.on_mirror_cone(1e-12)));
    }
  }
  FitOptions three;
  three.cusps = 3;
  const auto none = fit_with_census(points, {hidden.ratio()}, three);
  CHECK(none[0].candidates.empty());
  CHECK(none[0].reason.find("0, 1 or 2 cusps") != std::string::npos);
}

TEST_CASE("fit: bad input is refused naming the field", "[exact][synthesis][errors]") {
  const std::vector<Vector3d> ok{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, Vector3d(1, 1, 0).normalized()};
  auto field_of = [](const std::vector<Vector3d>& p, const FitOptions& o = {}, Ratio n = Ratio(1)) {
    try {
      fit_path(p, n, o);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return std::string("none");
  };
  CHECK(field_of({ok[0], ok[1], ok[2]}) == "points");
  CHECK(field_of({ok[0], ok[1], ok[2], Vector3d(0, 0, 1.00001)}) == "points");
  CHECK(field_of({ok[0], ok[1], ok[2], Vector3d(NAN, 0, 1)}) == "points");
  CHECK(field_of({ok[0], ok[0], ok[0], ok[0], ok[1]}) == "points");  // 2 distinct points
  CHECK(field_of({ok[0], ok[1], ok[1], ok[2], ok[2]}) == "points");  // 3 distinct points
  CHECK(field_of({ok[0], ok[1], ok[1], ok[2], ok[3]}) == "none");    // 4 distinct points
  FitOptions neg;
  neg.nodes = -1;
  CHECK(field_of(ok, neg) == "nodes");
  neg.nodes.reset();
  neg.cusps = -2;
  CHECK(field_of(ok, neg) == "cusps");
  FitOptions cusps_and_margin;  // cusps lie on a pitch cone: margin 0
  cusps_and_margin.cusps = 1;
  cusps_and_margin.min_margin = 0.01;
  CHECK(field_of(ok, cusps_and_margin) == "min-margin");
  cusps_and_margin.cusps = 0;
  CHECK(field_of(ok, cusps_and_margin) == "none");
  cusps_and_margin.min_margin = 0.786;
  CHECK(field_of(ok, cusps_and_margin) == "min-margin");
  CHECK(field_of(ok, {}, Ratio(1001)) == "n");
  std::vector<Vector3d> many(1000000, ok[0]);
  std::copy(ok.begin(), ok.end(), many.begin());
  try {  // over the work that grows with the points: refused before any
    fit_path(many, Ratio(97));
    FAIL("not refused");
  } catch (const InvalidInput& e) {
    CHECK(e.field() == "points");
    CHECK(e.problem().find("too many") != std::string::npos);
  }
  // The bound's own examples (sum over the ratios of points x (2|p| + 5 (|p| + q) + 40) + 4e5
  // <= 4.6e7): 772,881 points for n = 2 (59 each); for --ratios 7,7 (70 ratios, 6064 a point)
  // 2,968; n = 1/140 (747 a point) 61,044.
  CHECK_NOTHROW(check_fit_cost(772881, {Ratio(2)}));
  CHECK_THROWS_AS(check_fit_cost(772882, {Ratio(2)}), InvalidInput);
  CHECK_NOTHROW(check_fit_cost(61044, {Ratio(1, 140)}));
  CHECK_THROWS_AS(check_fit_cost(61045, {Ratio(1, 140)}), InvalidInput);
  std::vector<Ratio> seven;
  for (std::int64_t p = 1; p <= 7; ++p)
    for (std::int64_t q = 1; q <= 7; ++q)
      if (std::gcd(p, q) == 1) seven.insert(seven.end(), {Ratio(p, q), Ratio(-p, q)});
  REQUIRE(seven.size() == 70);
  CHECK_NOTHROW(check_fit_cost(2968, seven));
  CHECK_THROWS_AS(check_fit_cost(2969, seven), InvalidInput);
  FitOptions node;
  node.node_at = Vector3d(0, 0, 1.01);
  CHECK(field_of(ok, node) == "node-at");
  node.node_at = Vector3d(NAN, 0, 1);
  CHECK(field_of(ok, node) == "node-at");
  node.node_at = Vector3d(0, 0, 1);
  node.node_tolerance = 0;
  CHECK(field_of(ok, node) == "node-tolerance");
}

namespace {

/// Distance (radians) from `at` to the nearest node of classify()'s census of the train, run here.
double nearest_census_node(const GearTrain& train, const Vector3d& at) {
  const Classification c = classify(train);
  REQUIRE(c.certified());
  double best = 1e300;
  for (const Node& node : c.nodes) best = std::min(best, std::atan2(node.position.cross(at).norm(), node.position.dot(at)));
  return best;
}

}  // namespace

TEST_CASE("fit with a node point: the hidden train's node gives it back, and every candidate has a node there",
          "[exact][synthesis]") {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int tried = 0, hits = 0;
  while (tried < kNoisyTargets / 25 + 2) {
    const Target t = random_target(rng, kSigma);
    if (t.hidden.ratio().abs_p() > 4 || t.hidden.ratio().q() > 3) continue;  // a few nodes: keeps the census quick
    const Classification hidden = classify(t.hidden);
    if (hidden.nodes.empty() || !hidden.certified()) continue;
    ++tried;
    const Vector3d at = hidden.nodes[rng() % hidden.nodes.size()].position;
    FitOptions o;
    o.node_at = at;
    o.max_candidates = 3;
    const auto fits = fit_with_census(t.points, {t.hidden.ratio()}, o);
    INFO("n = " << t.hidden.ratio().str() << " a2 = " << t.hidden.a2() << " a3 = " << t.hidden.a3());
    REQUIRE_FALSE(fits[0].candidates.empty());
    hits += fits[0].candidates[0].candidate.rms <= 2 * kSigma;
    for (const ConfirmedCandidate& c : fits[0].candidates) CHECK(nearest_census_node(c.candidate.train, at) <= o.node_tolerance);
    // A point 0.01 rad off that node: a compromise, but still a node there, by the census.
    const Vector3d off = (at + 0.01 * at.cross(Vector3d(u(rng), u(rng), u(rng))).normalized()).normalized();
    o.node_at = off;
    const auto off_fits = fit_with_census(t.points, {t.hidden.ratio()}, o);
    REQUIRE_FALSE(off_fits[0].candidates.empty());
    for (const ConfirmedCandidate& c : off_fits[0].candidates) {
      CHECK(nearest_census_node(c.candidate.train, off) <= o.node_tolerance);
      CHECK(c.candidate.node_distance <= o.node_tolerance);
    }
  }
  CHECK(hits == tried);
}
