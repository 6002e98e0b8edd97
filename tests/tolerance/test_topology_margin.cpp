// Tests of tolerance/topology_margin.hpp and boundary_enclosure.hpp. Expected values: the
// boundary set of map/boundary_events.hpp (an independent computation: sampled g, long double
// roots, no intervals) — its events at one a2 decide a vertical segment exactly, and at sampled
// a2 they are boundary points whose distance bounds the margin from above; and invariants (a
// proved point is an event of the boundary set; a box half as wide as the margin holds).
#include "catch2/catch.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/tolerance/topology_margin.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <tuple>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();

#ifdef SPHTROCH_SANITIZED_BUILD
constexpr int kRandomTrains = 12, kPlacedTrains = 6;
#else
constexpr int kRandomTrains = 120, kPlacedTrains = 40;
#endif

Ratio random_ratio(std::mt19937_64& rng) {
  const auto p = static_cast<std::int64_t>(1 + rng() % 7), q = static_cast<std::int64_t>(1 + rng() % 7);
  return Ratio(rng() % 2 ? p : -p, q);
}

/// The L-infinity distance from (a2, a3) to the nearest event of boundary_set at `steps` + 1
/// samples of a2 across [a2 - reach, a2 + reach] (a boundary point each: >= the true distance).
double scanned_distance(double a2, double a3, const Ratio& n, double reach, int steps) {
  double best = 1e9;
  for (int i = 0; i <= steps; ++i) {
    const double x = a2 - reach + 2 * reach * i / steps;
    if (!(x > 1e-6 && x < kPi - 1e-6)) continue;
    for (const BoundaryEvent& e : boundary_set(x, n).events) best = std::min(best, std::max(std::fabs(x - a2), std::fabs(e.a3 - a3)));
  }
  return best;
}

/// Whether boundary_set at a2 has an event with a3 in [lo, hi].
bool event_between(double a2, const Ratio& n, double lo, double hi) {
  for (const BoundaryEvent& e : boundary_set(a2, n).events)
    if (e.a3 >= lo && e.a3 <= hi) return true;
  return false;
}

}  // namespace

TEST_CASE("topology_margin: the bracket holds every scanned boundary point's distance, and its witness is an event", "[interval][margin]") {
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> angle(0.05, kPi - 0.05);
  for (int k = 0; k < kRandomTrains; ++k) {
    const Ratio n = random_ratio(rng);
    const double a2 = angle(rng), a3 = angle(rng);
    const TopologyMargin m = topology_margin(GearTrain(a2, a3, n));
    INFO("n = " << n.str() << ", a2 = " << a2 << ", a3 = " << a3 << ": [" << m.lower << ", " << m.upper << "]");
    REQUIRE(m.lower <= m.upper);
    REQUIRE(m.nearest);
    CHECK(m.converged);
    CHECK(m.upper - m.lower <= std::max(1e-9, 1e-6 * m.upper));
    // Every boundary point is at least `lower` away.
    CHECK(scanned_distance(a2, a3, n, std::min(1.2 * m.upper, 3.0), 24) >= m.lower);
    // The witness is an event of the boundary set at its a2, of the same kind, within its segment.
    const BoundaryWitness& w = *m.nearest;
    bool found = false;
    for (const BoundaryEvent& e : boundary_set(w.a2(), n).events)
      found = found || (e.kind == event_kind(w.boundary) && std::fabs(e.a3 - w.a3()) <= 1e-9 + (w.at.a3_hi - w.at.a3_lo));
    if (w.at.a2_lo == w.at.a2_hi) CHECK(found);
    // Its distance is at most upper.
    CHECK(std::max(std::fabs(w.a2() - a2), std::fabs(w.a3() - a3)) <= m.upper * (1 + 1e-12));
  }
}

TEST_CASE("topology_margin is as narrow as stated where |p| = q and a2 runs to the edge a tangency locus tends to", "[interval][margin]") {
  // n = -1 (1) near a2 = 0 (pi): the pitch-cone function vanishes along that edge and a tangency
  // locus G_l = m runs into it, so boxes there span a2 over a factor ~100 of their distance to it.
  std::mt19937_64 rng(1128);
  std::uniform_real_distribution<double> edge(0.01, 0.6), angle(0.05, kPi - 0.05);
  for (int k = 0; k < kPlacedTrains; ++k) {
    const bool minus = k % 2 == 0;
    const std::int64_t q = static_cast<std::int64_t>(1 + rng() % 7);
    const Ratio n(minus ? -q : q, q);
    const double a2 = minus ? edge(rng) : kPi - edge(rng), a3 = angle(rng);
    const TopologyMargin m = topology_margin(GearTrain(a2, a3, n));
    INFO("n = " << n.str() << ", a2 = " << a2 << ", a3 = " << a3 << ": [" << m.lower << ", " << m.upper << "]");
    CHECK(m.converged);
    CHECK(m.upper - m.lower <= std::max(1e-9, 1e-6 * m.upper));
    CHECK(scanned_distance(a2, a3, n, std::min(1.2 * m.upper, 3.0), 24) >= m.lower);
  }
  // Where the nearest point is a meeting of two boundaries (a mirror pitch cone and the tangency
  // locus that ends on it), found by a random sweep: each takes 50,000 to 90,000 boxes.
  for (const auto& [n, a2, a3] : {std::tuple<Ratio, double, double>{Ratio(4, 1), 1.7446715106528006, 2.7532075885174518},
                                  {Ratio(-6, 1), 1.3238136184044602, 2.7196956296829056}}) {
    const TopologyMargin m = topology_margin(GearTrain(a2, a3, n));
    CHECK(m.converged);
    CHECK(scanned_distance(a2, a3, n, 1.2 * m.upper, 24) >= m.lower);
  }
}

TEST_CASE("box_topology on a segment of fixed a2: changes exactly when the boundary set has an event on it", "[interval][margin]") {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> angle(0.2, kPi - 0.2);
  int by_kind[3] = {0, 0, 0};
  for (int k = 0; k < kPlacedTrains; ++k) {
    const Ratio n = random_ratio(rng);
    const double a2 = angle(rng);
    const BoundarySet set = boundary_set(a2, n);
    for (const BoundaryEvent& e : set.events)
      for (const double eps : {1e-6, 1e-5, 1e-4, 1e-3})
        for (const double side : {-1.0, 1.0}) {
          const double a3 = e.a3 + side * eps;
          if (!(a3 > 1e-3 && a3 < kPi - 1e-3)) continue;
          const GearTrain train(a2, a3, n);
          for (const double half : {0.5 * eps, 2 * eps}) {
            const BoxTopology b = box_topology(train, 0.0, half);
            INFO("n = " << n.str() << ", a2 = " << a2 << ", event " << e.name << " at " << e.a3 << ", a3 = " << a3 << ", +- " << half);
            REQUIRE(b.verdict != BoxTopology::Verdict::undecided);
            // The boundary set's events are accurate to 1e-12: decide only what that settles.
            const bool inside = event_between(a2, n, a3 - half + 1e-11, a3 + half - 1e-11);
            const bool outside = !event_between(a2, n, a3 - half - 1e-11, a3 + half + 1e-11);
            if (inside) CHECK(b.verdict == BoxTopology::Verdict::changes);
            if (outside) CHECK(b.verdict == BoxTopology::Verdict::holds);
          }
          ++by_kind[static_cast<int>(e.kind)];
        }
  }
  CHECK(by_kind[0] > 0);  // pitch cones
  CHECK(by_kind[1] > 0);  // poles
  CHECK(by_kind[2] > 0);  // tangencies
}

TEST_CASE("box_topology on squares: never holds with a scanned event inside, holds within the margin", "[interval][margin]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.1, kPi - 0.1);
  for (int k = 0; k < kPlacedTrains; ++k) {
    const Ratio n = random_ratio(rng);
    const double a2 = angle(rng), a3 = angle(rng);
    const GearTrain train(a2, a3, n);
    const TopologyMargin m = topology_margin(train);
    INFO("n = " << n.str() << ", a2 = " << a2 << ", a3 = " << a3 << ", margin [" << m.lower << ", " << m.upper << "]");
    auto fits = [&](double h) { return a2 - h > 1e-6 && a2 + h < kPi - 1e-6 && a3 - h > 1e-6 && a3 + h < kPi - 1e-6; };
    if (m.lower > 0 && fits(m.lower)) CHECK(box_topology(train, 0.999 * m.lower, 0.999 * m.lower).verdict == BoxTopology::Verdict::holds);
    // A square reaching a scanned boundary point (a real event) cannot hold.
    const double scanned = scanned_distance(a2, a3, n, std::min(1.2 * m.upper, 3.0), 16);
    if (fits(scanned * (1 + 1e-9))) CHECK(box_topology(train, scanned * (1 + 1e-9), scanned * (1 + 1e-9)).verdict != BoxTopology::Verdict::holds);
  }
}

TEST_CASE("box_topology refuses a negative, NaN or range-leaving half-width", "[interval][margin]") {
  const GearTrain train(1.0, 2.0, Ratio(5, 2));
  CHECK_THROWS_AS(box_topology(train, -1e-3, 0.0), InvalidInput);
  CHECK_THROWS_AS(box_topology(train, std::nan(""), 0.0), InvalidInput);
  CHECK_THROWS_AS(box_topology(train, 0.0, 1.5), InvalidInput);
  CHECK_THROWS_AS(box_topology(train, 1.0, 0.0), InvalidInput);
}

TEST_CASE("topology_margin next to the range's edge: a2 within 3e-6 of 0 or pi, where a pitch cone may leave the range", "[interval][margin]") {
  for (const double a2 : {1e-6, 2e-6, 3e-6, kPi - 3e-6, kPi - 1e-6})
    for (const Ratio n : {Ratio(1), Ratio(2), Ratio(-2), Ratio(5, 2), Ratio(3), Ratio(-3, 2), Ratio(1, 2)})
      for (const double a3 : {0.5, 2.0}) {
        const TopologyMargin m = topology_margin(GearTrain(a2, a3, n));
        INFO("n = " << n.str() << ", a2 = " << a2 << ", a3 = " << a3 << ": [" << m.lower << ", " << m.upper << "]");
        CHECK(m.lower <= m.upper);
        // No square about the train wider than its distance to the range's far edge fits in it.
        CHECK(m.lower <= std::max(kPi - a2, a2));
        // Every scanned boundary point of the range is at least `lower` away.
        CHECK(scanned_distance(a2, a3, n, std::min(1.2 * m.upper, 3.0), 24) >= m.lower);
        if (m.nearest) CHECK(std::max(std::fabs(m.nearest->a2() - a2), std::fabs(m.nearest->a3() - a3)) <= m.upper * (1 + 1e-12));
      }
}
