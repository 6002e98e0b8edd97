// Tests of the stages of the polyline census (polyline_census.hpp, namespace sphtroch::census),
// one by one. Expected values come from the report (Fig. 3: n = 1, a2 = a3 = pi/2, one node at
// (0, 1, 0) with theta2 = +-pi/2, Eq. 25), from Eq. 3 (theta3 = n theta2 + theta_p), from
// constructions whose answer is known by design, and from the independent root census.
#include "test_support.hpp"

#include "sphtroch/exact/polyline_census.hpp"
#include "sphtroch/census/root_census.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();

GearTrain fig3() { return GearTrain(kPi / 2, kPi / 2, Ratio(1)); }

/// Planet angle theta3 = n t + theta_p (Eq. 3) reduced to [0, 2 pi), computed here.
double planet_angle(const GearTrain& train, double t) {
  const double th = train.ratio().value() * t + train.phase();
  return th - 2 * kPi * std::floor(th / (2 * kPi));
}

}  // namespace

TEST_CASE("census stage 1: uniform parameters away from the pitch cones", "[census][stages]") {
  const GearTrain train(1.0, 2.0, Ratio(5, 2));  // a_p = 0.28; |a3 - a_p|, |a3 - (pi - a_p)| > 0.3
  const std::size_t n = 2048;
  const std::vector<double> ts = census::census_parameters(train, n);
  REQUIRE(ts.size() == n);
  const double h = train.period() / n;
  for (std::size_t i = 0; i < n; ++i) CHECK(std::abs(ts[i] - h * static_cast<double>(i)) <= 4e-15 * train.period());
}

TEST_CASE("census stage 1: graded samples around every near-cusp parameter", "[census][stages]") {
  // a3 = a_p + 1e-6: near-cusp loops at theta3 = pi (Eq. 3 gives |p| = 5 parameters per period).
  const GearTrain train = GearTrain::on_cone(1.0, A3Reference::pitch_cone, 1e-6, Ratio(5, 3), 0.4);
  const std::size_t n = 2048;
  const std::vector<double> ts = census::census_parameters(train, n);
  REQUIRE(ts.size() > n);
  for (std::size_t i = 1; i < ts.size(); ++i) REQUIRE(ts[i] > ts[i - 1]);
  CHECK(ts.front() >= 0.0);
  CHECK(ts.back() < train.period());
  const double h = train.period() / n;
  std::size_t near_cusp = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    // A sample with theta3 = pi within 1e-9: its neighbours must be far closer than h.
    if (std::abs(planet_angle(train, ts[i]) - kPi) > 1e-9) continue;
    ++near_cusp;
    REQUIRE(i > 0);
    REQUIRE(i + 1 < ts.size());
    CHECK(ts[i + 1] - ts[i] < h / 100);
    CHECK(ts[i] - ts[i - 1] < h / 100);
  }
  CHECK(near_cusp == 5);
}

TEST_CASE("census stage 1: the polyline is on the sphere with distinct vertices", "[census][stages]") {
  const GearTrain train = GearTrain::on_cone(1.2, A3Reference::mirror_pitch_cone, 0.0, Ratio(-3, 2));
  PolylineWork work;
  const census::SampledPolyline poly = census::sample_polyline(train, 1024, work);
  REQUIRE(poly.size() >= 1024);
  CHECK(work.points_evaluated >= poly.size());
  for (std::size_t i = 0; i < poly.size(); ++i) {
    CHECK(std::abs(poly.points[i].norm() - 1.0) < 1e-15);
    CHECK(poly.points[i].isApprox(TracerCurve<double>(train).point(poly.t[i]), 1e-15));
    const std::size_t j = (i + 1) % poly.size();
    CHECK((poly.points[j] - poly.points[i]).norm() > kMinVertexSeparation);
  }
  CHECK(poly.edge_end(poly.size() - 1) == poly.t[0] + poly.period);
}

TEST_CASE("census stage 2: Fig. 3 has one exact contact, at theta2 = pi/2 and 3pi/2", "[census][stages]") {
  PolylineCensus out;
  const census::SampledPolyline poly = census::sample_polyline(fig3(), 1024, out.work);
  const auto contacts = census::exact_contacts(poly, out);
  REQUIRE(contacts.size() == 1);
  CHECK(out.polyline_crossings == 1);
  const auto [i, j] = contacts[0];
  CHECK(poly.edge_start(i) <= kPi / 2);
  CHECK(poly.edge_end(i) >= kPi / 2);
  CHECK(poly.edge_start(j) <= 3 * kPi / 2);
  CHECK(poly.edge_end(j) >= 3 * kPi / 2);
  // A transversal crossing: no near miss besides the contact itself.
  CHECK(census::near_misses(poly, fig3().period() / 1024, contacts).empty());
}

TEST_CASE("census stage 2: branches that approach without crossing are near misses", "[census][stages]") {
  // n = 3, a2 = pi/2: three pairs of branches touch at a3 = atan(3 sqrt 3) (issue 13; a double
  // root of the root census, an independent method, which places the three touching points).
  // 1e-5 below that value they pass close without crossing: each touching point must have a
  // near miss next to it, and no exact contact there.
  const double a3_touch = std::atan(3 * std::sqrt(3.0));
  std::vector<Vector3d> touching;
  for (const Node& node : root_census(GearTrain(kPi / 2, a3_touch, Ratio(3))).nodes)
    if (node.kind == NodeKind::tangency) touching.push_back(node.position);
  REQUIRE(touching.size() == 3);

  const GearTrain train(kPi / 2, a3_touch - 1e-5, Ratio(3));
  PolylineCensus out;
  const std::size_t n = 1024;
  const census::SampledPolyline poly = census::sample_polyline(train, n, out.work);
  const auto contacts = census::exact_contacts(poly, out);
  const auto near = census::near_misses(poly, train.period() / n, contacts);
  CAPTURE(contacts.size(), near.size());
  for (const Vector3d& x : touching) {
    std::size_t close_misses = 0, close_contacts = 0;
    for (const auto& [i, j] : near) close_misses += (poly.points[i] - x).norm() < 0.05 && (poly.points[j] - x).norm() < 0.05;
    for (const auto& [i, j] : contacts) close_contacts += (poly.points[i] - x).norm() < 0.05;
    CHECK(close_misses >= 1);
    CHECK(close_contacts == 0);
  }
  for (const auto& [i, j] : near) CHECK(census::chord_distance(poly, i, j) < 0.01);
}

TEST_CASE("census stage 3: branch_gap vanishes at the Fig. 3 node and changes sign across it", "[census][stages]") {
  const TracerCurve<long double> curve(fig3());
  PolylineWork work;
  const long double t1 = kPi / 2.0L, t2 = 3 * kPi / 2.0L;
  CHECK(std::abs(census::branch_gap(curve, t1, t2, 0, work)) < 1e-15L);
  const long double plus = census::branch_gap(curve, t1, t2, 1e-3L, work);
  const long double minus = census::branch_gap(curve, t1, t2, -1e-3L, work);
  CHECK(plus * minus < 0);
  CHECK(work.newton_steps > 0);
}

TEST_CASE("census stage 3+4: a seed near the Fig. 3 node refines to a crossing at (0, 1, 0)", "[census][stages]") {
  PolylineCensus out;
  census::MeetingFinder finder(fig3(), fig3().period() / 1024, 1e-10L, out);
  finder.add_seed({kPi / 2 + 0.01, 3 * kPi / 2 - 0.01});
  REQUIRE(finder.meetings().size() == 1);
  const census::Meeting m = finder.meetings()[0];
  CHECK(m.kind == NodeKind::crossing);
  const TracerCurve<long double> curve(fig3());
  const Vector3<long double> p1 = curve.point(m.t1), p2 = curve.point(m.t2);
  CHECK((p1 - p2).norm() < 1e-15L);
  CHECK((p1.cast<double>() - Vector3d(0, 1, 0)).norm() < 1e-12);  // Eq. 25: (0, sin a3, cos a3)
  CHECK(out.newton_failures == 0);
}

TEST_CASE("census stage 3+4: seeds near a tangency of the root census refine to tangencies", "[census][stages]") {
  // n = 3, a2 = pi/2, a3 = atan(3 sqrt 3): the root census (an independent method) finds the
  // touching points as double roots; seeds 1e-3 off them must come back as tangencies.
  const GearTrain train(kPi / 2, std::atan(3 * std::sqrt(3.0)), Ratio(3));
  const RootCensus roots = root_census(train);
  std::size_t tangency_pairs = 0;
  PolylineCensus out;
  census::MeetingFinder finder(train, train.period() / 4096, 1e-10L, out);
  for (const BranchPair& bp : roots.pairs) {
    if (bp.kind != NodeKind::tangency) continue;
    ++tangency_pairs;
    finder.add_seed({bp.t1 + 1e-3, bp.t2 - 1e-3});
  }
  REQUIRE(tangency_pairs == 3);
  REQUIRE(finder.meetings().size() == 3);
  for (const census::Meeting& m : finder.meetings()) CHECK(m.kind == NodeKind::tangency);
}

TEST_CASE("census stage 5: duplicates modulo the period and in either order are one meeting", "[census][stages]") {
  const long double period = 2 * Constants<long double>::pi();
  const std::vector<census::Meeting> meetings = {
      {1.0L, 2.0L, NodeKind::crossing},
      {2.0L + 1e-12L, 1.0L - 1e-12L, NodeKind::crossing},      // swapped, within tolerance
      {1.0L + period, 2.0L - period, NodeKind::crossing},      // shifted by whole periods
      {1.0L, 2.0L + 1e-9L, NodeKind::crossing},                // 1e-9 apart: a different meeting
      {-1e-12L, 3.0L, NodeKind::tangency},                     // across the wrap ...
      {period - 1e-12L, 3.0L, NodeKind::tangency},             // ... the same as this one
      {3.0L, 1e-13L, NodeKind::tangency},                      // ... and this one
  };
  const auto unique = census::unique_meetings(meetings, period);
  REQUIRE(unique.size() == 3);
  for (const auto& m : unique) {
    CHECK(m.t1 >= 0);
    CHECK(m.t1 <= m.t2);
    CHECK(m.t2 < period);
  }
  for (std::size_t i = 1; i < unique.size(); ++i) CHECK(unique[i - 1].t1 <= unique[i].t1);
}

TEST_CASE("census stage 6: branch pairs are reduced, ordered and placed at the midpoint", "[census][stages]") {
  PolylineWork work;
  const std::vector<census::Meeting> meetings = {{3 * kPi / 2.0L, kPi / 2.0L - 2 * kPi, NodeKind::crossing}};
  const auto pairs = census::branch_pairs(fig3(), meetings, work);
  REQUIRE(pairs.size() == 1);
  CHECK(pairs[0].t1 == Approx(kPi / 2).margin(1e-15));
  CHECK(pairs[0].t2 == Approx(3 * kPi / 2).margin(1e-15));
  CHECK((pairs[0].position - Vector3d(0, 1, 0)).norm() < 1e-15);  // Eq. 25
  CHECK(work.points_evaluated == 2);
}

TEST_CASE("census cost: the close-pair estimate is within a small factor of the pairs the search visits (small twists x large denominators)", "[census][cost]") {
  // The searches' cost beyond N log N is the pairs of edges closer than a quarter chord that the
  // box search visits (counted here by the visitor); the estimate must follow it within a factor
  // (measured 0.7 .. 5.2), so that the bound it enforces bounds the work.
  for (const double a2 : {0.02, 0.1, 0.6})
    for (const Ratio n : {Ratio(1, 60), Ratio(1, 240), Ratio(13, 5), Ratio(101, 40)}) {
      const GearTrain t(a2, 1.0, n);
      PolylineWork work;
      const census::SampledPolyline poly = census::sample_polyline(t, census_sample_count(t), work, 0);
      double longest = 0;
      for (std::size_t e = 0; e + 1 < poly.size(); ++e) longest = std::max(longest, (poly.points[e + 1] - poly.points[e]).norm());
      double visits = 0;
      visit_close_edge_pairs(poly.points, true, kNearMissChordFraction * longest, [&](std::size_t, std::size_t) { return ++visits, true; });
      const double estimate = census::close_pair_estimate(poly.points);
      CAPTURE(a2, n.str(), estimate, visits);
      CHECK(visits <= 8 * estimate + 1000);
      CHECK(estimate <= 4 * visits + 1000);
    }
}

TEST_CASE("census cost: a carrier twist near 0 with a large denominator is refused up front, naming a2 and the cost", "[census][cost]") {
  const InvalidInput e = test::expect_invalid([] { polyline_census(GearTrain(0.01, 1.0, Ratio(1, 1908))); });
  CHECK(e.field() == "a2");
  CHECK(e.problem().find("1909 times") != std::string::npos);
  const GearTrain dense(0.7, 2.5, Ratio(13, 5));  // 169 nodes: an ordinary dense curve passes
  PolylineWork work;
  CHECK_NOTHROW(census::check_close_pairs(dense, census::sample_polyline(dense, census_sample_count(dense), work, 0).points));
}
