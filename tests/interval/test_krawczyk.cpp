// interval/krawczyk.hpp tested directly: systems whose roots are known exactly (linear systems
// with small integer matrices and dyadic roots, so A r is exact; x^2 = 2 checked with fma, which
// gives the exact sign of x^2 - 2), no root, two close roots found by a small bisection driver
// written here, a singular midpoint, the contraction test and the inflation radii. This file is
// also compiled into test_interval_nearest (CGAL_ALWAYS_ROUND_TO_NEAREST, the WebAssembly build's
// kernel): every enclosure below must hold there too.
#include "catch2/catch.hpp"

#include "sphtroch/interval/krawczyk.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

using namespace sphtroch;

namespace {

#if defined(CGAL_ALWAYS_ROUND_TO_NEAREST)
#define KRAWCZYK_TAG "[krawczyk][nearest]"
#else
#define KRAWCZYK_TAG "[krawczyk]"
#endif

/// F(x) = A x - b over a box (A exact doubles): F at y and J = A as intervals.
struct Linear2 {
  double a[2][2];
  double b[2];
  IntervalBox<2> at(const PointN<2>& y) const {
    IntervalBox<2> f;
    for (int r = 0; r < 2; ++r) f[r] = Interval(a[r][0]) * y[0] + Interval(a[r][1]) * y[1] - b[r];
    return f;
  }
  IntervalMatrix<2> jacobian() const {
    return {{{Interval(a[0][0]), Interval(a[0][1])}, {Interval(a[1][0]), Interval(a[1][1])}}};
  }
};

KrawczykStep<2> step_of(const Linear2& f, const IntervalBox<2>& x) {
  const PointN<2> y = centre<2>(x);
  const auto inverse = midpoint_inverse<2>(midpoint<2>(f.jacobian()));
  REQUIRE(inverse);
  return krawczyk_step<2>(x, y, f.at(y), f.jacobian(), *inverse);
}

bool holds(const Interval& x, double v) { return x.inf() <= v && v <= x.sup(); }

/// F(x) = (x0^2 - d^2, x1 - x0 / 2): the roots (-d, -d/2) and (d, d/2). (Not x1 alone: an exactly
/// linear row makes K's row a point, X meeting K degenerate, and a degenerate side is never
/// strictly inside itself.)
struct TwoRoots {
  double d;
  void eval(const IntervalBox<2>& x, IntervalBox<2>& f, IntervalMatrix<2>& j) const {
    f = {x[0] * x[0] - Interval(d) * d, x[1] - 0.5 * x[0]};
    j = {{{2.0 * x[0], Interval(0.0)}, {Interval(-0.5), Interval(1.0)}}};
  }
};

/// The step of TwoRoots on x about its centre; nothing when the midpoint is singular.
std::optional<KrawczykStep<2>> two_roots_step(const TwoRoots& sys, const IntervalBox<2>& x) {
  IntervalBox<2> f, fy;
  IntervalMatrix<2> j, jy;
  sys.eval(x, f, j);
  const PointN<2> y = centre<2>(x);
  sys.eval(point_box<2>(y), fy, jy);
  const auto inverse = midpoint_inverse<2>(midpoint<2>(j));
  if (!inverse) return std::nullopt;
  return krawczyk_step<2>(x, y, fy, j, *inverse);
}

/// Bisection with the step (a test driver, independent of root_isolation.hpp): the boxes proved
/// to hold one root each; `undecided` counts boxes left narrower than 1e-12.
std::vector<IntervalBox<2>> isolate_all(const TwoRoots& sys, IntervalBox<2> start, int& undecided) {
  std::vector<IntervalBox<2>> stack{start}, roots;
  undecided = 0;
  while (!stack.empty()) {
    IntervalBox<2> x = stack.back();
    stack.pop_back();
    if (const std::optional<KrawczykStep<2>> step = two_roots_step(sys, x)) {
      const KrawczykStep<2>& k = *step;
      if (k.verdict == KrawczykVerdict::none) continue;
      if (k.verdict == KrawczykVerdict::unique) {
        roots.push_back(k.box);
        continue;
      }
      x = k.box;
    }
    if (box_width<2>(x) < 1e-12) {
      ++undecided;
      continue;
    }
    const int k = x[0].sup() - x[0].inf() >= x[1].sup() - x[1].inf() ? 0 : 1;
    const double m = mid(x[k]);
    IntervalBox<2> lo = x, hi = x;
    lo[k] = Interval(x[k].inf(), m);
    hi[k] = Interval(m, x[k].sup());
    stack.push_back(lo);
    stack.push_back(hi);
  }
  return roots;
}

}  // namespace

TEST_CASE("Krawczyk step: linear systems with an exact dyadic root prove one root and enclose it", KRAWCZYK_TAG) {
  const RoundingGuard upward;
  std::mt19937 rng(59);
  std::uniform_int_distribution<int> entry(-9, 9), numerator(-4096, 4096);
  int proved = 0;
  for (int trial = 0; trial < 500; ++trial) {
    Linear2 f{};
    for (auto& row : f.a)
      for (double& v : row) v = entry(rng);
    if (f.a[0][0] * f.a[1][1] - f.a[0][1] * f.a[1][0] == 0) continue;
    const PointN<2> r{numerator(rng) / 1024.0, numerator(rng) / 1024.0};  // A r exact: small integers times dyadics
    for (int k = 0; k < 2; ++k) f.b[k] = f.a[k][0] * r[0] + f.a[k][1] * r[1];
    const double w = std::ldexp(1.0, -(trial % 30));
    const IntervalBox<2> x{Interval(r[0] - 0.3 * w, r[0] + 0.7 * w), Interval(r[1] - 0.6 * w, r[1] + 0.4 * w)};
    const KrawczykStep<2> k = step_of(f, x);
    CAPTURE(trial, w);
    REQUIRE(k.verdict == KrawczykVerdict::unique);  // J constant: Y J = I up to rounding, K a tiny box about r
    CHECK(holds(k.box[0], r[0]));
    CHECK(holds(k.box[1], r[1]));
    ++proved;
    // The same system on a box beside the root (r outside by a box width): never "unique".
    const IntervalBox<2> away{Interval(r[0] + 2 * w, r[0] + 3 * w), x[1]};
    CHECK(step_of(f, away).verdict == KrawczykVerdict::none);
  }
  CHECK(proved > 400);
}

TEST_CASE("Krawczyk step: x^2 = 2 is proved in a box of sqrt 2 whose ends straddle it exactly", KRAWCZYK_TAG) {
  const RoundingGuard upward;
  for (const double w : {0.1, 1e-4, 1e-9, 1e-14}) {
    const IntervalBox<1> x{Interval(1.4142135 - w, 1.4142136 + w)};
    const PointN<1> y = centre<1>(x);
    const IntervalBox<1> fy{Interval(y[0]) * y[0] - 2.0};
    const IntervalMatrix<1> j{{{2.0 * x[0]}}};
    const KrawczykStep<1> k = krawczyk_step<1>(x, y, fy, j, *midpoint_inverse<1>(midpoint<1>(j)));
    CAPTURE(w, k.box[0].inf(), k.box[0].sup());
    REQUIRE(k.verdict == KrawczykVerdict::unique);
    // fma(a, a, -2) is a^2 - 2 rounded once: its sign is exact.
    CHECK(std::fma(k.box[0].inf(), k.box[0].inf(), -2.0) <= 0.0);
    CHECK(std::fma(k.box[0].sup(), k.box[0].sup(), -2.0) >= 0.0);
  }
}

TEST_CASE("Krawczyk step: a box without a real root is narrowed and then excluded", KRAWCZYK_TAG) {
  const RoundingGuard upward;
  // x^2 + 1 = 0 has no real root. Over [0.5, 2]: y = 1.25, Y = 1/2.5, K = 0.225 + [-0.6, 0.6] [-0.75, 0.75]
  // = [-0.225, 0.675] meets X (narrowed to [0.5, 0.675]); the next step misses it.
  IntervalBox<1> x{Interval(0.5, 2.0)};
  std::vector<KrawczykVerdict> verdicts;
  for (int step = 0; step < 10 && (verdicts.empty() || verdicts.back() == KrawczykVerdict::narrowed); ++step) {
    const PointN<1> y = centre<1>(x);
    const IntervalMatrix<1> j{{{2.0 * x[0]}}};
    const KrawczykStep<1> k = krawczyk_step<1>(x, y, {Interval(y[0]) * y[0] + 1.0}, j, *midpoint_inverse<1>(midpoint<1>(j)));
    verdicts.push_back(k.verdict);
    x = k.box;
  }
  REQUIRE(verdicts.size() == 2);
  CHECK(verdicts[0] == KrawczykVerdict::narrowed);
  CHECK(verdicts[1] == KrawczykVerdict::none);
}

TEST_CASE("Krawczyk step: two roots 2e-6 apart are never one and bisection with the step isolates both", KRAWCZYK_TAG) {
  const RoundingGuard upward;
  const TwoRoots sys{1e-6};
  // Over a box holding both, the step cannot prove uniqueness.
  {
    const IntervalBox<2> x{Interval(-1e-5, 1.1e-5), Interval(-1e-5, 1e-5)};
    const std::optional<KrawczykStep<2>> step = two_roots_step(sys, x);
    REQUIRE(step);
    CHECK(step->verdict != KrawczykVerdict::unique);
  }
  int undecided = 0;
  const std::vector<IntervalBox<2>> roots = isolate_all(sys, {Interval(-1.0, 1.3), Interval(-0.7, 1.0)}, undecided);
  CHECK(undecided == 0);
  REQUIRE(roots.size() == 2);
  const bool first_negative = roots[0][0].sup() < 0;
  const IntervalBox<2>& neg = first_negative ? roots[0] : roots[1];
  const IntervalBox<2>& pos = first_negative ? roots[1] : roots[0];
  CHECK(holds(neg[0], -1e-6));
  CHECK(holds(pos[0], 1e-6));
  CHECK(holds(neg[1], -0.5e-6));
  CHECK(holds(pos[1], 0.5e-6));
  CHECK(neg[0].sup() < pos[0].inf());  // disjoint
}

TEST_CASE("Krawczyk: a singular midpoint has no inverse and a near-singular one is refused below the caller's floor", KRAWCZYK_TAG) {
  DoubleMatrix<2> singular;
  singular << 1, 2, 2, 4;
  CHECK_FALSE(midpoint_inverse<2>(singular));
  DoubleMatrix<2> near;
  near << 1, 2, 1, 2 + 1e-15;
  CHECK(midpoint_inverse<2>(near));              // invertible in doubles
  CHECK_FALSE(midpoint_inverse<2>(near, 1e-14));  // |det| ~ 9e-16 <= 1e-14 * 2^2
  DoubleMatrix<2> fine;
  fine << 2, 1, 1, 3;
  const auto y = midpoint_inverse<2>(fine, 1e-14);
  REQUIRE(y);
  CHECK(((*y) * fine - DoubleMatrix<2>::Identity()).cwiseAbs().maxCoeff() < 1e-15);
}

TEST_CASE("Krawczyk: the contraction test holds for Y = J^-1 and fails for a poor Y", KRAWCZYK_TAG) {
  const RoundingGuard upward;
  // J over U = [[2 + e, 1], [1, 3]], e in [-0.1, 0.1]: with Y = mid(J)^-1, ||I - Y J|| ~ 0.1 * |Y| < 1.
  const IntervalMatrix<2> ju{{{Interval(1.9, 2.1), Interval(1.0)}, {Interval(1.0), Interval(3.0)}}};
  const auto y = midpoint_inverse<2>(midpoint<2>(ju));
  REQUIRE(y);
  CHECK(contracts<2>(*y, ju));
  CHECK_FALSE(contracts<2>(DoubleMatrix<2>::Zero(), ju));  // ||I|| = 1: not < 1
  // The row sum bound is exact enough to tell: Y = 0.5 I gives row 1 |1 - 0.5 [1.9, 2.1]| + 0.5 = 0.55 + 0.5.
  CHECK_FALSE(contracts<2>(0.5 * DoubleMatrix<2>::Identity(), ju));
}

TEST_CASE("Krawczyk: inflation visits its radii in order and stops at the first proof", KRAWCZYK_TAG) {
  std::vector<double> seen;
  const auto none = epsilon_inflation(1e-7, 0.01, 1e-13, [&](double r) -> std::optional<double> {
    seen.push_back(r);
    return std::nullopt;
  });
  CHECK_FALSE(none);
  REQUIRE(seen.size() == 4);  // 1e-7, 1e-9, 1e-11, 1e-13 (up to rounding of the products)
  CHECK(seen[3] == Approx(1e-13).epsilon(1e-12));
  seen.clear();
  const auto third = epsilon_inflation(8.0, 1.0 / 16, 1e-3, [&](double r) -> std::optional<double> {
    seen.push_back(r);
    return seen.size() == 3 ? std::optional<double>(r) : std::nullopt;
  });
  REQUIRE(third);
  CHECK(*third == 8.0 / 256);
  CHECK(seen.size() == 3);
}

TEST_CASE("Krawczyk: inflation from an infinite radius or to a floor of 0 tries nothing instead of looping", KRAWCZYK_TAG) {
  int calls = 0;
  const auto count = [&](double) -> std::optional<double> {
    ++calls;
    return std::nullopt;
  };
  CHECK_FALSE(epsilon_inflation(std::numeric_limits<double>::infinity(), 0.5, 1e-9, count));
  CHECK_FALSE(epsilon_inflation(1.0, 0.5, 0.0, count));
  CHECK_FALSE(epsilon_inflation(1.0, 1.0, 1e-9, count));
  CHECK(calls == 0);
}

TEST_CASE("Krawczyk: boxes about a point are relative or absolute as asked and the centre is inside", KRAWCZYK_TAG) {
  const IntervalBox<2> b = box_about<2>(PointN<2>{100.0, 0.5}, 1e-3, true);
  CHECK(b[0].sup() - b[0].inf() == Approx(0.2));
  CHECK(b[1].sup() - b[1].inf() == Approx(2e-3));
  const IntervalBox<2> a = box_about<2>(PointN<2>{100.0, 0.5}, 1e-3, false);
  CHECK(a[0].sup() - a[0].inf() == Approx(2e-3));
  const PointN<2> c = centre<2>(b);
  CHECK(holds(b[0], c[0]));
  CHECK(holds(b[1], c[1]));
  CHECK(box_width<2>(b) == Approx(0.2));
}
