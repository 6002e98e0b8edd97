// Tests of synthesis/free_axis_points.hpp: precision points with the sun axis free. Expected values:
// the hidden train and the hidden rotation the five points were drawn with (forward model
// TracerCurve, Eq. 4, then a random rotation), the invariant that every solution passes its
// points, and the fixed-frame solver (synthesis/precision_points.hpp, another formulation) where the
// sun axis is Z. Seeded.
#include "catch2/catch.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/synthesis/free_axis_points.hpp"

#include <cmath>
#include <random>
#include <tuple>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();

#ifdef SPHTROCH_SANITIZED_BUILD
constexpr int kFacePairProblems = 1;  // each search is ~5x slower under the sanitizers
#else
constexpr int kFacePairProblems = 4;
#endif

struct FreeProblem {
  GearTrain hidden{1.0, 1.0, Ratio(1)};
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // points = rotation * curve points
  std::vector<Vector3d> points;
  std::vector<double> thetas;
};

/// |p|, q <= 3, both signs; a2, a3 in [0.15, pi - 0.15]; any phase; five carrier angles over a
/// period; a uniformly random rotation (or none).
FreeProblem random_free_problem(std::mt19937_64& rng, bool rotate = true) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  const auto term = [&] { return static_cast<std::int64_t>(1 + rng() % 3); };
  const std::int64_t p = (rng() % 2 ? -1 : 1) * term();
  FreeProblem pr;
  pr.hidden = GearTrain(0.15 + u(rng) * (kPi - 0.3), 0.15 + u(rng) * (kPi - 0.3), Ratio(p, term()), 2 * kPi * u(rng));
  if (rotate) pr.rotation = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
  const TracerCurve<double> curve(pr.hidden);
  for (int i = 0; i < 5; ++i) {
    pr.thetas.push_back(u(rng) * pr.hidden.period());
    pr.points.push_back(pr.rotation * curve.point(pr.thetas.back()));
  }
  return pr;
}

/// The hidden train as one solution: the same sun axis up to sign, a2, and a3 (pi - a3 when the
/// axis is reversed: the same motion seen from the other side), to `tol`.
bool is_hidden(const PrecisionSolution& s, const FreeProblem& pr, double tol) {
  const Vector3d axis = pr.rotation.col(2), z = s.frame.col(2);
  if (std::abs(s.train.a2() - pr.hidden.a2()) > tol) return false;
  if ((z - axis).norm() < tol) return std::abs(s.train.a3() - pr.hidden.a3()) < tol;
  if ((z + axis).norm() < tol) return std::abs(kPi - s.train.a3() - pr.hidden.a3()) < tol;
  return false;
}

/// The train (1.2, 0.8, n = 1, phase 0.5) at five carrier angles, turned by `rotation`.
FreeProblem nephroid_problem(const std::vector<double>& thetas, const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  FreeProblem pr;
  pr.hidden = GearTrain(1.2, 0.8, Ratio(1), 0.5);
  pr.rotation = rotation;
  pr.thetas = thetas;
  for (const double t : pr.thetas) pr.points.push_back(rotation * TracerCurve<double>(pr.hidden).point(t));
  return pr;
}

/// The whole search on two threads, certified, holding the hidden train once.
PrecisionPoints certified_search(const std::vector<Vector3d>& points, const FreeProblem& pr) {
  PrecisionPointsOptions options;
  options.threads = 2;
  const PrecisionPoints r = free_axis_points(points, pr.hidden.ratio(), options);
  REQUIRE(r.certified);
  CHECK(std::count_if(r.solutions.begin(), r.solutions.end(), [&](const PrecisionSolution& s) { return is_hidden(s, pr, 1e-9); }) == 1);
  return r;
}

/// Every solution passes its points at its parameters, with a right-handed orthonormal frame.
void check_solutions_pass_points(const PrecisionPoints& r, const std::vector<Vector3d>& points) {
  for (const PrecisionSolution& s : r.solutions) {
    CHECK((s.frame.transpose() * s.frame - Eigen::Matrix3d::Identity()).norm() < 1e-14);
    CHECK(std::abs(s.frame.determinant() - 1.0) < 1e-14);
    REQUIRE(s.params.size() == 5);
    const TracerCurve<double> curve(s.train);
    for (int i = 0; i < 5; ++i) CHECK((s.frame * curve.point(s.params[i]) - points[i]).norm() < 1e-12);
  }
}

/// The cube face of the largest component of a (0..2: +x, +y, +z; 3..5: the negative ones).
int face_of(const Vector3d& a) {
  int k = 0;
  for (int j = 1; j < 3; ++j)
    if (std::abs(a[j]) > std::abs(a[k])) k = j;
  return a[k] > 0 ? k : k + 3;
}

/// The hidden root's face pair: s on a positive face (with w reversed with it), w on any.
std::pair<int, int> hidden_faces(const FreeProblem& pr) {
  Vector3d s = pr.rotation.col(2);
  const double a2 = pr.hidden.a2(), t = pr.thetas[0];
  Vector3d w = pr.rotation * Vector3d(std::sin(a2) * std::sin(t), -std::sin(a2) * std::cos(t), std::cos(a2));
  if (face_of(s) >= 3) s = -s, w = -w;
  return {face_of(s), face_of(w)};
}

/// The chart coordinates (u, v) of unit axis a on cube face f (face_axis's inverse).
std::pair<double, double> chart_coordinates(const Vector3d& a, int face) {
  const int k = face % 3;
  const double scale = (face < 3 ? 1.0 : -1.0) / a[k];  // |c| = 1 / |a_k|
  return {a[(k + 1) % 3] * scale, a[(k + 2) % 3] * scale};
}

/// The hidden root (s_u, s_v, w_u, w_v, Delta_2..Delta_5) on its face pair (hidden_faces).
std::array<double, 8> hidden_root(const FreeProblem& pr, int sun, int planet) {
  Vector3d s = pr.rotation.col(2);
  const double a2 = pr.hidden.a2(), t = pr.thetas[0], period = pr.hidden.period();
  Vector3d w = pr.rotation * Vector3d(std::sin(a2) * std::sin(t), -std::sin(a2) * std::cos(t), std::cos(a2));
  const double sign = face_of(s) >= 3 ? -1.0 : 1.0;  // (s, w, Delta) and (-s, -w, -Delta): one motion
  s *= sign, w *= sign;
  std::array<double, 8> x{};
  std::tie(x[0], x[1]) = chart_coordinates(s, sun);
  std::tie(x[2], x[3]) = chart_coordinates(w, planet);
  for (int i = 1; i < 5; ++i) {
    const double d = std::fmod(sign * (pr.thetas[i] - t), period);
    x[3 + i] = d < 0 ? d + period : d;
  }
  return x;
}

}  // namespace

TEST_CASE("free axis: boxes around the hidden root keep it (each point's test and the slabs' narrowing)",
          "[synthesis][exact]") {
  // Every box holding the hidden root must pass may_hold for each point's item holding its Delta,
  // and narrow_outer must neither drop the box nor narrow the root out of it (boxes 1/4..1/64,
  // the root anywhere but within 5% of an edge: its doubles are within 1e-14 of the true root).
  // Boxes 1/4..1/16 also test every item of each list's whole range after the root's: the slabs
  // of those that pass are joined with the root's (a hull that kept only the last slab fails here).
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> offset(0.05, 0.95);
  int narrowed = 0, joined = 0;
  for (int k = 0; k < 20; ++k) {
    const FreeProblem pr = random_free_problem(rng);
    const auto [sun, planet] = hidden_faces(pr);
    const FreeAxisSystem system(checked_precision_points(pr.points, 5, "test"), pr.hidden.ratio(), sun, planet);
    const std::array<double, 8> root = hidden_root(pr, sun, planet);
    const RoundingGuard upward;
    for (double width = 0.25; width >= 1.0 / 64; width /= 2) {
      INFO("problem " << k << ": n = " << pr.hidden.ratio().str() << ", width " << width);
      FreeAxisSystem::Outer box;
      for (int j = 0; j < 4; ++j) {
        const double lo = root[j] - offset(rng) * width;
        box[j] = Interval(lo, lo + width);
      }
      auto view = system.view(box);
      for (int i = 0; i < 4; ++i) {  // the root's item, then every item of the whole range: slabs joined
        const double h = width / system.list_scale(), lo = root[4 + i] - offset(rng) * h;
        auto item = system.list_item(Interval(lo, lo + h), i);
        REQUIRE(system.may_hold(view, item, i));
        CHECK((item.d.inf() <= root[4 + i] + 1e-12 && item.d.sup() >= root[4 + i] - 1e-12));  // narrowed, it keeps the root
        CHECK((item.d.inf() >= lo && item.d.sup() <= lo + h));                                  // inside the old item
        for (double d = 0.0; width >= 1.0 / 16 && d < system.list_max(); d += h) {
          auto other = system.list_item(Interval(d, d + h), i);
          joined += system.may_hold(view, other, i);
        }
      }
      FreeAxisSystem::Outer narrower = box;
      REQUIRE(system.narrow_outer(view, narrower));
      for (int j = 0; j < 4; ++j) {
        CHECK(narrower[j].inf() <= root[j] + 1e-12);
        CHECK(narrower[j].sup() >= root[j] - 1e-12);
        narrowed += narrower[j].sup() - narrower[j].inf() < 0.7 * width;
      }
    }
  }
  CHECK(narrowed > 0);  // the narrowing is exercised (else this test proves nothing)
  CHECK(joined > 0);    // and slabs of two items of one list joined
}

TEST_CASE("free axis: a root anywhere in a box keeps the box (points built from the root)", "[synthesis][exact]") {
  // A root x = (s, w, Delta_2..Delta_5) placed anywhere in a random box (up to 0.1% of its width
  // from an edge, where the mean-value forms' columns are at their widest) and the points built
  // from it: P_1 random, P_i = R_s(Delta_i) R_w(n Delta_i) P_1 (the header's equations). Each
  // point's test must pass the item holding Delta_i, and narrow_outer must keep x. A column of
  // the recursive form enclosed at the centre instead of over the box fails here.
  std::mt19937_64 rng(1990);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<Ratio> ratios{Ratio(1), Ratio(-1), Ratio(3, 2), Ratio(-2, 3), Ratio(3)};
  int narrowed_items = 0;
  for (int k = 0; k < 400; ++k) {
    const Ratio n = ratios[k % ratios.size()];
    const int sun = static_cast<int>(rng() % 3), planet = static_cast<int>(rng() % 6);
    const double width = std::ldexp(1.0, -1 - static_cast<int>(rng() % 6));  // 1/2 .. 1/64
    const auto near_edge = [&] { return 0.001 + 0.998 * (u(rng) < 0.5 ? u(rng) : std::round(u(rng))); };
    FreeAxisSystem::Outer box;
    std::array<double, 4> x{};
    for (int j = 0; j < 4; ++j) {
      const double lo = -1.0 + u(rng) * (2.0 - width);
      box[j] = Interval(lo, lo + width);
      x[j] = lo + near_edge() * width;
    }
    const auto axis = [&](int face, double a, double b) {
      const auto c = free_axis_detail::face_axis(face, a, b).a;
      return Vector3d(c[0], c[1], c[2]);
    };
    const Vector3d s = axis(sun, x[0], x[1]), w = axis(planet, x[2], x[3]);
    // items as wide as the outer box, or as wide as the search starts them (kListWidth times)
    const double scale = 1.0 + std::abs(n.value()), period = 2 * kPi * double(n.q());
    const double h = (k % 2 ? FreeAxisSystem::kListWidth : 1.0) * width / scale;
    std::vector<Vector3d> points{Eigen::Quaterniond::UnitRandom().toRotationMatrix().col(0)};
    std::array<double, 4> item_lo{}, delta{};
    for (int i = 0; i < 4; ++i) {
      item_lo[i] = u(rng) * (period - h);
      delta[i] = item_lo[i] + near_edge() * h;
      points.push_back(Eigen::AngleAxisd(delta[i], s) * (Eigen::AngleAxisd(n.value() * delta[i], w) * points[0]));
    }
    INFO("case " << k << ": n = " << n.str() << ", faces " << sun << ", " << planet << ", width " << width);
    const FreeAxisSystem system(points, n, sun, planet);
    const RoundingGuard upward;
    auto view = system.view(box);
    for (int i = 0; i < 4; ++i) {
      auto item = system.list_item(Interval(item_lo[i], item_lo[i] + h), i);
      REQUIRE(system.may_hold(view, item, i));
      // may_hold may narrow the item (Delta's Newton steps): never past the root's Delta_i
      CHECK((item.d.inf() <= delta[i] + 1e-12 && item.d.sup() >= delta[i] - 1e-12));
      CHECK((item.d.inf() >= item_lo[i] && item.d.sup() <= item_lo[i] + h));  // inside the old item
      narrowed_items += item.d.sup() - item.d.inf() < h;
    }
    FreeAxisSystem::Outer narrower = box;
    REQUIRE(system.narrow_outer(view, narrower));
    for (int j = 0; j < 4; ++j) CHECK((narrower[j].inf() <= x[j] + 1e-12 && narrower[j].sup() >= x[j] - 1e-12));
  }
  CHECK(narrowed_items > 0);  // the items' narrowing is exercised
}

TEST_CASE("free axis: centred_sum encloses sum_k G_k dx_k over a centred box", "[synthesis][exact]") {
  // Against the plain interval products, and at sampled points g_k in G_k, x_k in dx_k (both signs,
  // intervals off 0 too): the sum must hold every such value; it is no wider than the products.
  std::mt19937_64 rng(2020);
  std::uniform_real_distribution<double> u(-1.0, 1.0), t(0.0, 1.0);
  const RoundingGuard upward;
  for (int trial = 0; trial < 1000; ++trial) {
    Interval g[4], dx[4];
    double r[4];
    for (int k = 0; k < 4; ++k) {
      const double a = u(rng), b = a + 0.5 * t(rng), c = u(rng), w = 0.1 * t(rng);
      g[k] = Interval(a, b);
      dx[k] = (Interval(c - w, c + w)) - Interval(c);  // a box minus its centre
      r[k] = radius(dx[k]);
    }
    const Interval sum = centred_sum<4>(g, r);
    Interval products(0.0);
    for (int k = 0; k < 4; ++k) products += g[k] * dx[k];
    CHECK(sum.sup() - sum.inf() <= (products.sup() - products.inf()) * (1 + 1e-12) + 1e-300);
    double sample = 0.0;  // (rounded: a margin of 1e-15 below)
    for (int k = 0; k < 4; ++k) sample += (g[k].inf() + t(rng) * (g[k].sup() - g[k].inf())) * (dx[k].inf() + t(rng) * (dx[k].sup() - dx[k].inf()));
    CHECK((sum.inf() <= sample + 1e-15 && sum.sup() >= sample - 1e-15));
    CHECK((sum.inf() <= products.inf() + 1e-15 && sum.sup() >= products.sup() - 1e-15));
  }
}

TEST_CASE("free axis: on the face pair of the hidden root the search finds it and certifies its list", "[synthesis][exact]") {
  std::mt19937_64 rng(1990);
  for (int k = 0; k < kFacePairProblems; ++k) {
    const FreeProblem pr = random_free_problem(rng);
    const auto [sun, planet] = hidden_faces(pr);
    INFO("problem " << k << ": n = " << pr.hidden.ratio().str() << ", faces " << sun << ", " << planet);
    const FreeAxisSystem system(checked_precision_points(pr.points, 5, "test"), pr.hidden.ratio(), sun, planet);
    const PrecisionPoints r = RootIsolation<FreeAxisSystem>(system, 20000000).run();
    CHECK(r.certified);
    CHECK(std::any_of(r.solutions.begin(), r.solutions.end(), [&](const PrecisionSolution& s) { return is_hidden(s, pr, 1e-9); }));
    check_solutions_pass_points(r, pr.points);
  }
}

TEST_CASE("free axis: the whole search holds the hidden train once and agrees with the fixed frame where the axis is Z",
          "[synthesis][exact]") {
  const FreeProblem pr = nephroid_problem({0.3, 1.4, 2.6, 4.0, 5.3});  // the sun axis is Z: the fixed frame can check
  const PrecisionPoints r = certified_search(pr.points, pr);
  check_solutions_pass_points(r, pr.points);
  // Every train with the sun axis Z is among the fixed-frame trains through the first three points.
  const PrecisionPoints fixed = precision_points({pr.points[0], pr.points[1], pr.points[2]}, pr.hidden.ratio());
  REQUIRE(fixed.certified);
  int on_z = 0;
  for (const PrecisionSolution& s : r.solutions) {
    if ((s.frame.col(2) - Vector3d::UnitZ()).norm() > 1e-9) continue;
    ++on_z;
    CHECK((s.frame - Eigen::Matrix3d::Identity()).norm() < 1e-9);  // the frame rule: x from the X axis
    const double sector = 2 * kPi / double(s.train.ratio().q());
    CHECK(std::any_of(fixed.solutions.begin(), fixed.solutions.end(), [&](const PrecisionSolution& f) {
      return std::abs(f.train.a2() - s.train.a2()) < 1e-9 && std::abs(f.train.a3() - s.train.a3()) < 1e-9 &&
             std::abs(std::remainder(f.train.phase() - s.train.phase(), sector)) < 1e-9;
    }));
  }
  CHECK(on_z >= 1);
}

TEST_CASE("free axis: a sun axis on a corner of the cube charts is found once, certified", "[synthesis][exact]") {
  // s = (1, 1, 1) / sqrt(3) lies on the edges of the faces +x, +y, +z (u = v = 1 on each): each
  // face's domain reaches past its edges, so the root is inside three of them and listed once.
  const FreeProblem pr = nephroid_problem(
      {0.3, 1.4, 2.6, 4.0, 5.3}, Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), Vector3d(1, 1, 1).normalized()).toRotationMatrix());
  check_solutions_pass_points(certified_search(pr.points, pr), pr.points);
}

TEST_CASE("free axis: the points in another order give the same trains, each passing them at its params",
          "[synthesis][exact]") {
  // The search writes the points against a reference chosen from their geometry (the close pair
  // below, wherever it is put), and reports params in input order: checked on a permutation.
  const FreeProblem pr = nephroid_problem({0.3, 1.4, 2.6, 4.0, 4.05});
  const std::vector<int> order = {4, 0, 3, 2, 1};  // permuted[i] = points[order[i]]
  std::vector<Vector3d> permuted;
  for (const int i : order) permuted.push_back(pr.points[i]);
  // Without 3 or without 4 the same closest pair is left: the tie goes to the smaller sum of chords.
  const auto chords_from = [&](int r) {
    double sum = 0.0;
    for (const Vector3d& x : pr.points) sum += (x - pr.points[r]).norm();
    return sum;
  };
  const std::size_t reference = chords_from(3) < chords_from(4) ? 3 : 4;
  CHECK(free_axis_detail::reference_point(pr.points) == reference);
  CHECK(permuted[free_axis_detail::reference_point(permuted)] == pr.points[reference]);  // not the order
  const PrecisionPoints r = certified_search(pr.points, pr), p = certified_search(permuted, pr);
  check_solutions_pass_points(r, pr.points);
  check_solutions_pass_points(p, permuted);
  REQUIRE(r.solutions.size() == p.solutions.size());
  for (std::size_t k = 0; k < r.solutions.size(); ++k) {
    const PrecisionSolution &a = r.solutions[k], &b = p.solutions[k];
    CHECK((a.frame - b.frame).norm() < 1e-9);
    CHECK(std::abs(a.train.a2() - b.train.a2()) < 1e-9);
    CHECK(std::abs(a.train.a3() - b.train.a3()) < 1e-9);
    CHECK(std::abs(std::remainder(a.train.phase() - b.train.phase(), 2 * kPi / double(a.train.ratio().q()))) < 1e-9);
    for (int i = 0; i < 5; ++i) CHECK(std::abs(std::remainder(a.params[order[i]] - b.params[i], a.train.period())) < 1e-9);
  }
}

TEST_CASE("free axis: the Jacobian of every chart is the derivative of its equations (central differences)",
          "[synthesis][exact]") {
  // An exclusion or a Krawczyk proof with a wrong J would be wrong: J against (F(x + h) - F(x - h)) / 2h.
  std::mt19937_64 rng(47);
  std::uniform_real_distribution<double> u(-1.0, 1.0), d(0.0, 12.0);
  const FreeProblem pr = random_free_problem(rng);
  const std::vector<Vector3d> points = checked_precision_points(pr.points, 5, "test");
  for (int trial = 0; trial < 40; ++trial) {
    const FreeAxisSystem system(points, Ratio(-2, 3), trial % 3, trial % 6);
    std::array<double, 8> x{u(rng), u(rng), u(rng), u(rng), d(rng), d(rng), d(rng), d(rng)};
    const int chart = int(rng() % 81);  // each point's dropped component, base 3
    std::array<double, 8> f{};
    std::array<std::array<double, 8>, 8> jac{};
    system.equations(x, f, &jac, chart);
    for (int k = 0; k < 8; ++k) {
      const double h = 1e-6;
      std::array<double, 8> xp = x, xm = x, fp{}, fm{};
      xp[k] += h;
      xm[k] -= h;
      system.equations(xp, fp, static_cast<std::array<std::array<double, 8>, 8>*>(nullptr), chart);
      system.equations(xm, fm, static_cast<std::array<std::array<double, 8>, 8>*>(nullptr), chart);
      for (int r = 0; r < 8; ++r) CHECK(std::abs((fp[r] - fm[r]) / (2 * h) - jac[r][k]) < 1e-7);
    }
  }
}

TEST_CASE("free axis: bad points are refused naming them", "[synthesis][exact][errors]") {
  const std::vector<Vector3d> three = {Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ()};
  CHECK_THROWS_AS(free_axis_points(three, Ratio(1)), InvalidInput);
  std::vector<Vector3d> five = {Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ(), -Vector3d::UnitX(),
                                Vector3d(0.6, 0.8, 0.0)};
  five[4].x() = std::nan("");
  try {
    free_axis_points(five, Ratio(1));
    FAIL("no exception");
  } catch (const InvalidInput& e) {
    CHECK(e.field() == "points");
  }
  five[4] = five[0];
  CHECK_THROWS_AS(free_axis_points(five, Ratio(1)), InvalidInput);
}
