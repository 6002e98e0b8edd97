// Tests of boundary_events.hpp: the events of the (a2, a3) map at one a2, their accuracy, the counts
// on either side (checked with classify(), the polyline census, an independent computation), the
// loci over a2 and the tangency reading of nearest_tangency.
#include "catch2/catch.hpp"
#include "test_support.hpp"
#include "sphtroch/atlas/atlas_boundary_check.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/census/root_census.hpp"
#include "sphtroch/classify.hpp"
#include "sphtroch/map/criteria.hpp"

#include <cmath>
#include <vector>

using namespace sphtroch;

namespace {

constexpr double kPi = 3.141592653589793;

std::vector<BoundaryEvent> of_kind(const BoundarySet& s, BoundaryEventKind k) {
  std::vector<BoundaryEvent> out;
  for (const auto& e : s.events)
    if (e.kind == k) out.push_back(e);
  return out;
}

/// Node points as classify counts them (crossings + tangencies) at (a2, a3).
std::size_t classified_nodes(double a2, double a3, const Ratio& n, double phase) {
  const Classification c = classify(GearTrain(a2, a3, n, phase));
  INFO("classify n = " << n.p() << "/" << n.q() << " a2 = " << a2 << " a3 = " << a3 << " phase " << phase);
  CHECK(c.crossings + c.tangencies == c.nodes.size());
  return c.nodes.size();
}

// An independent g in long double: the direct formula g(b) = [p (2 az - pi) + 2 q b] / (2 pi) of
// the root census (report Eq. 3, 4 with the mirror argument), az = atan2(y, x) of
// C(b) = Rx(a2) Rz(b) Rx(a3) z, evaluated straight from the rotation chain.
long double g_direct(long double b, long double a2, long double a3, long double p, long double q) {
  const long double pi = 3.141592653589793238462643383279502884L;
  const long double x = std::sin(a3) * std::sin(b);
  const long double y = -(std::sin(a3) * std::cos(a2) * std::cos(b) + std::cos(a3) * std::sin(a2));
  return (p * (2 * std::atan2(y, x) - pi) + 2 * q * b) / (2 * pi);
}

/// The extreme value of g near b0 (golden section on [b0 - w, b0 + w]), in long double.
long double extreme_value(long double b0, long double a2, long double a3, long double p, long double q) {
  const long double w = 0.05L;
  long double lo = std::max(b0 - w, 1e-9L), hi = std::min(b0 + w, 3.14159265358979L);
  // Is it a maximum or a minimum? Compare the centre with the ends.
  const long double gc = g_direct(b0, a2, a3, p, q);
  const bool maximum = gc >= g_direct(lo, a2, a3, p, q) && gc >= g_direct(hi, a2, a3, p, q);
  const long double r = 0.6180339887498948482L;
  for (int it = 0; it < 200 && hi - lo > 1e-15L; ++it) {
    const long double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
    const long double f1 = g_direct(x1, a2, a3, p, q), f2 = g_direct(x2, a2, a3, p, q);
    if ((f1 > f2) == maximum) hi = x2;
    else lo = x1;
  }
  return g_direct((lo + hi) / 2, a2, a3, p, q);
}

double l_first_a2(const std::vector<Locus>& loci) { return loci.front().points.front().a2; }

}  // namespace

TEST_CASE("boundary set: n = 3, a2 = pi/2 has tangencies at atan(3 sqrt 3) and its mirror, 3 <-> 9 nodes",
          "[boundary_set]") {
  const BoundarySet s = boundary_set(kPi / 2, Ratio(3));
  const auto t = of_kind(s, BoundaryEventKind::tangency);
  REQUIRE(t.size() == 2);
  const long double expected = std::atan(3 * std::sqrt(3.0L));  // the closed form
  CHECK(std::abs(t[0].a3_precise - expected) <= 1e-13L);
  CHECK(std::abs(t[1].a3_precise - (3.141592653589793238462643383279502884L - expected)) <= 1e-13L);
  CHECK(t[0].a3 == 1.3806707234484299);
  CHECK(t[0].nodes_below == 3);
  CHECK(t[0].nodes_above == 9);
  CHECK(t[1].nodes_below == 9);
  CHECK(t[1].nodes_above == 3);
  // And classify agrees just off both (the polyline census, independent of g).
  for (const auto& e : t) {
    CHECK(classified_nodes(kPi / 2, e.a3 - 1e-7, Ratio(3), 0.0) == static_cast<std::size_t>(e.nodes_below));
    CHECK(classified_nodes(kPi / 2, e.a3 + 1e-7, Ratio(3), 0.0) == static_cast<std::size_t>(e.nodes_above));
  }
  // Events ascend; cusps are never counted off a cone.
  for (std::size_t i = 1; i < s.events.size(); ++i) CHECK(s.events[i - 1].a3_precise <= s.events[i].a3_precise);
  for (const auto& e : s.events) CHECK((e.cusps_below == 0 && e.cusps_above == 0));
}

TEST_CASE("boundary set: n = 1 and n = 2 have no tangency locus at any a2, and their counts are the report's",
          "[boundary_set]") {
  for (const Ratio n : {Ratio(1), Ratio(2), Ratio(-1), Ratio(-2)}) {
    for (int k = 1; k < 400; ++k) {
      const double a2 = kPi * k / 400;
      const BoundarySet s = boundary_set(a2, n);
      INFO("n = " << n.p() << " a2 = " << a2);
      CHECK(of_kind(s, BoundaryEventKind::tangency).empty());
    }
  }
  // The counts between events against the report's criteria (Eq. 24 for n = 1; Eqs. 43, 46 for n = 2).
  for (const Ratio n : {Ratio(1), Ratio(2)}) {
    for (double a2 : {0.4, 1.0, kPi / 2, 2.2, 2.9}) {
      const BoundarySet s = boundary_set(a2, n);
      for (const auto& e : s.events) {
        for (double side : {-1.0, 1.0}) {
          const double a3 = e.a3 + side * 1e-6;
          if (!(a3 > 0 && a3 < kPi)) continue;
          const AnalyticClassification a = classify_analytic(GearTrain(a2, a3, n));
          REQUIRE(a.predicted_nodes.has_value());
          INFO("n = " << n.p() << " a2 = " << a2 << " event " << e.name << " side " << side);
          CHECK(*a.predicted_nodes == static_cast<std::size_t>(side < 0 ? e.nodes_below : e.nodes_above));
        }
      }
    }
  }
}

TEST_CASE("boundary set: every tangency a3 is right to 1e-12 (residual of an independent long double g)",
          "[boundary_set]") {
  std::size_t checked = 0;
  for (const Ratio n : {Ratio(3), Ratio(5, 2), Ratio(5), Ratio(3, 2), Ratio(-5, 2), Ratio(7, 3), Ratio(-4, 3),
                        Ratio(7, 2), Ratio(6, 7)}) {
    for (double a2 : {0.35, 1.1, kPi / 2, 2.5}) {
      for (const auto& e : of_kind(boundary_set(a2, n), BoundaryEventKind::tangency)) {
        const long double p = n.p(), q = n.q();
        const long double G = extreme_value(e.b, a2, e.a3_precise, p, q);
        // dG/da3 by a central difference of the extreme value (envelope of g over b).
        const long double h = 1e-7L;
        const long double dG = (extreme_value(e.b, a2, e.a3_precise + h, p, q) -
                                extreme_value(e.b, a2, e.a3_precise - h, p, q)) / (2 * h);
        INFO("n = " << n.p() << "/" << n.q() << " a2 = " << a2 << " a3 = " << e.a3 << " m = " << e.m);
        CHECK(std::abs(G - e.m) <= 1e-12L * std::abs(dG));
        // The double reported is the long double root rounded.
        CHECK(std::abs(static_cast<long double>(e.a3) - e.a3_precise) <= 2.3e-16L);
        ++checked;
      }
    }
  }
  CHECK(checked >= 30);
}

TEST_CASE("boundary set: classify just below and above every event gives nodes_below / nodes_above",
          "[boundary_set][slow]") {
  struct Case {
    Ratio n;
    double a2, phase;
  };
  const std::vector<Case> cases{
      {Ratio(5, 2), kPi / 2, 0.0},  {Ratio(5, 2), 0.8, 0.7},   {Ratio(3), 2.3, 0.3},     {Ratio(5), 1.2, 0.0},
      {Ratio(3, 2), 0.6, 1.1},     {Ratio(-5, 2), 1.4, 0.0},  {Ratio(-3), 2.0, 0.4},    {Ratio(7, 3), 1.0, 0.0},
      {Ratio(4, 3), 2.6, 0.2},     {Ratio(-7, 5), 1.3, 0.0},  {Ratio(7, 2), 0.45, 0.5}, {Ratio(2, 5), 1.9, 0.0},
      {Ratio(-1, 3), 0.9, 0.0},    {Ratio(6, 5), 1.6, 0.0},
  };
  std::size_t tangencies = 0;
  for (const Case& c : cases) {
    const BoundarySet s = boundary_set(c.a2, c.n);
    for (std::size_t i = 0; i < s.events.size(); ++i) {
      const BoundaryEvent& e = s.events[i];
      // Just off this event and no other (events closer than 3e-7 are checked as a group).
      const double lo = e.a3 - 1e-7, hi = e.a3 + 1e-7;
      const bool alone_below = i == 0 || s.events[i - 1].a3 < lo - 1e-7;
      const bool alone_above = i + 1 == s.events.size() || s.events[i + 1].a3 > hi + 1e-7;
      INFO("n = " << c.n.p() << "/" << c.n.q() << " a2 = " << c.a2 << " event " << e.name << " at " << e.a3);
      if (alone_below) CHECK(classified_nodes(c.a2, lo, c.n, c.phase) == static_cast<std::size_t>(e.nodes_below));
      if (alone_above) CHECK(classified_nodes(c.a2, hi, c.n, c.phase) == static_cast<std::size_t>(e.nodes_above));
      if (e.kind == BoundaryEventKind::tangency) {
        ++tangencies;
        // A tangency changes the count by 2 |p| (two roots of g, |p| node points each).
        CHECK(std::abs(e.nodes_above - e.nodes_below) == 2 * c.n.abs_p());
      }
    }
  }
  CHECK(tangencies >= 10);
}

TEST_CASE("boundary set: loci over a2 are continuous runs of the events at each a2", "[boundary_set]") {
  const Ratio n(5, 2);
  const std::vector<Locus> loci = boundary_loci(n, 0.3, 2.8, 50, 2);
  std::size_t tangency_loci = 0;
  for (const Locus& l : loci) {
    REQUIRE(!l.points.empty());
    if (l.kind != BoundaryEventKind::tangency) {
      CHECK(l.points.size() == 50);
      continue;
    }
    ++tangency_loci;
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      const LocusPoint& pt = l.points[i];
      if (i > 0) CHECK(std::abs(pt.a2 - l.points[i - 1].a2 - 0.05) < 1e-12);
      // The point is an event of the boundary set at its a2, with the locus's m.
      bool found = false;
      for (const auto& e : of_kind(boundary_set(pt.a2, n), BoundaryEventKind::tangency))
        found = found || (e.a3 == pt.a3 && e.m == l.m && e.label == l.label);
      CHECK(found);
    }
  }
  CHECK(tangency_loci >= 4);  // at a2 = pi/2 alone there are four tangencies
  CHECK(l_first_a2(loci) == Approx(0.3 + 0.025).epsilon(1e-14));
  CHECK(test::expect_invalid([&] { boundary_loci(n, 2.0, 1.0, 10); }).field() == "a2");
  CHECK(test::expect_invalid([&] { boundary_loci(n, 0.0, 3.5, 10); }).field() == "a2");
  CHECK(test::expect_invalid([&] { boundary_loci(n, 0.1, 1.0, 0); }).field() == "steps");
}

TEST_CASE("boundary set: bad a2 is InvalidInput naming a2", "[boundary_set]") {
  for (double a2 : {0.0, kPi, -1.0, 4.0, std::nan(""), HUGE_VAL})
    CHECK(test::expect_invalid([&] { boundary_set(a2, Ratio(3)); }).field() == "a2");
}

TEST_CASE("boundary set: nearest_tangency finds the locus within the tolerance only", "[boundary_set]") {
  const double a3 = 1.0938177365904715;  // the n = 5/2 tangency at a2 = pi/2
  const auto hit = nearest_tangency(kPi / 2, a3, Ratio(5, 2), 1e-10);
  REQUIRE(hit.has_value());
  CHECK(std::abs(hit->margin) <= 1e-15);
  CHECK(hit->m == -2);
  CHECK(nearest_tangency(kPi / 2, a3 + 5e-11, Ratio(5, 2), 1e-10).has_value());
  CHECK(!nearest_tangency(kPi / 2, a3 + 2e-10, Ratio(5, 2), 1e-10).has_value());
  CHECK(!nearest_tangency(kPi / 2, 1.2, Ratio(5, 2), 1e-10).has_value());
  // Pitch cones are not tangencies (their near-cusp loop has g = the end's integer).
  const double a_p = GearTrain::planet_cone_of(1.0, Ratio(3));
  CHECK(!nearest_tangency(1.0, a_p + 1e-12, Ratio(3), 1e-10).has_value());
}

TEST_CASE("classify reads a self-tangency like the other boundaries: both censuses agree on it",
          "[boundary_set][classify]") {
  // The case, typed as a double.
  {
    const Classification c = classify(GearTrain(kPi / 2, 1.0938177365904715, Ratio(5, 2)));
    CHECK(c.agreement.ok());
    CHECK(c.crossings == 10);
    CHECK(c.tangencies == 5);
    REQUIRE(c.snapped.hits.size() == 1);
    CHECK(c.snapped.hits[0].kind == BoundaryKind::tangency);
    CHECK(std::abs(c.snapped.hits[0].margin) <= 1e-15);
  }
  // Tangency values of other ratios, at several a2 and phases: the tangency count is |p| per
  // event (a double root of g stands for |p| node points), the node count lies halfway between
  // the two sides (two crossings merge into one touching point), and the censuses agree.
  std::size_t checked = 0;
  for (const Ratio n : {Ratio(5), Ratio(3, 2), Ratio(3), Ratio(-5, 2), Ratio(7, 3), Ratio(-4, 3)}) {
    for (double a2 : {0.7, kPi / 2, 2.2}) {
      for (const auto& e : of_kind(boundary_set(a2, n), BoundaryEventKind::tangency)) {
        const double phase = 0.3 * static_cast<double>(checked % 3);
        INFO("n = " << n.p() << "/" << n.q() << " a2 = " << a2 << " a3 = " << e.a3 << " phase " << phase);
        const Classification c = classify(GearTrain(a2, e.a3, n, phase));
        CHECK(c.agreement.ok());
        for (const auto& note : c.agreement.notes) INFO(note);
        CHECK(c.tangencies == static_cast<std::size_t>(n.abs_p()));
        CHECK(2 * c.nodes.size() == static_cast<std::size_t>(e.nodes_below + e.nodes_above));
        // Within the boundary tolerance the input is read on the locus, and the report says so.
        const Classification off = classify(GearTrain(a2, e.a3 + 5e-11, n, phase));
        REQUIRE(off.snapped.hits.size() == 1);
        CHECK(off.snapped.hits[0].kind == BoundaryKind::tangency);
        CHECK(off.snapped.train.a3() == e.a3);
        CHECK(off.tangencies == c.tangencies);
        CHECK(off.agreement.ok());
        // --literal reads the doubles as given: no snapping.
        ClassifySettings literal;
        literal.reading.literal = true;
        CHECK(classify(GearTrain(a2, e.a3 + 5e-11, n, phase), literal).snapped.hits.empty());
        ++checked;
      }
    }
  }
  CHECK(checked >= 15);
}

TEST_CASE("boundary set: the atlas's root-census counts lie between the events, and every class change is crossed",
          "[boundary_set][atlas]") {
  for (const Ratio n : {Ratio(3), Ratio(5, 2), Ratio(-5, 2), Ratio(7, 3), Ratio(3, 2), Ratio(-1, 3)}) {
    AtlasSpec spec;
    spec.ratio = n;
    spec.grid = 48;
    const std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);
    // Each cell off the events has the count of its interval (the root census at the cell centre,
    // root_census.hpp, against the counts boundary_set derives between events).
    std::size_t compared = 0;
    for (std::size_t i = 0; i < spec.grid; ++i) {
      const BoundarySet s = boundary_set(spec.a2_at(i), n);
      for (std::size_t j = 0; j < spec.grid; ++j) {
        const AtlasCell& c = cells[i * spec.grid + j];
        bool near = false;
        std::int64_t expected = -1;
        for (const auto& e : s.events) {
          near = near || std::abs(e.a3 - c.a3) < 1e-6;
          if (expected < 0 && e.a3 > c.a3) expected = e.nodes_below;
        }
        if (expected < 0) expected = s.events.empty() ? 0 : s.events.back().nodes_above;
        if (near) continue;
        INFO("n = " << n.p() << "/" << n.q() << " cell a2 = " << c.a2 << " a3 = " << c.a3);
        CHECK(static_cast<std::int64_t>(c.nodes) == expected);
        ++compared;
      }
    }
    CHECK(compared > spec.grid * spec.grid / 2);
    const AtlasBoundaryCheck check = check_atlas_boundaries(spec, cells, 2);
    CHECK(check.class_changes > 0);
    CHECK(check.uncrossed.empty());
  }
}

TEST_CASE("atlas boundary check: coarse grids, where a locus begins or ends between columns, explain every change",
          "[boundary_set][atlas]") {
  // A hostile-input run found n = 7/6 at grid 7 reporting a change "not crossed" although a
  // tangency locus crosses between the columns: every class change has a boundary (invariant).
  for (const auto& [n, grid] : std::vector<std::pair<Ratio, std::size_t>>{
           {Ratio(7, 6), 7}, {Ratio(-7, 6), 7}, {Ratio(7, 6), 6}, {Ratio(-7, 5), 11}}) {
    AtlasSpec spec;
    spec.ratio = n;
    spec.grid = grid;
    const std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);
    const AtlasBoundaryCheck check = check_atlas_boundaries(spec, cells, 2);
    INFO("n = " << n.str() << ", grid " << grid);
    CHECK(check.class_changes > 0);
    CHECK(check.uncrossed.empty());
  }
}

TEST_CASE("classify at a tangency of a tiny curve next to a pole (n = 3/5, a2 = 0.02): both censuses agree",
          "[boundary_set][classify]") {
  // The curve is ~0.04 rad across and the touching points lie ~0.0025 rad from the north pole:
  // the polyline census's quadratic gap model alone split each tangency into two crossings.
  const double a2 = 0.020555332447993083;
  std::size_t checked = 0;
  for (const auto& e : of_kind(boundary_set(a2, Ratio(3, 5)), BoundaryEventKind::tangency)) {
    INFO("a3 = " << e.a3);
    const Classification c = classify(GearTrain(a2, e.a3, Ratio(3, 5), 4.067605497286147));
    CHECK(c.agreement.ok());
    CHECK(c.tangencies == 3);
    CHECK(2 * c.nodes.size() == static_cast<std::size_t>(e.nodes_below + e.nodes_above));
    ++checked;
  }
  CHECK(checked == 2);
}

// One g(b) (map/root_function.hpp) serves `boundaries` and `classify`: at the very a3 double where
// boundary_set() puts a tangency event, the root census (what `classify` counts with) must find
// that tangency — the double root m at the stationary point b* — and count the node points the
// event implies: two simple roots merge into one double root, so the count there is the mean of
// nodes_below and nodes_above (they differ by 2|p|). Not sampling around the event: if the two
// ever used different functions (or different stationary-point formulas), the event double would
// miss the census's tangency by far more than the 1e-10 tangency tolerance.
TEST_CASE("one g(b): at every tangency event of boundary_set, the root census finds that tangency and the mean count",
          "[boundary_set]") {
  const std::vector<Ratio> ratios{Ratio(3), Ratio(5, 2), Ratio(-7, 3), Ratio(7, 5), Ratio(4, 3), Ratio(-5, 2), Ratio(9, 4)};
  const std::vector<double> a2s{0.7, kPi / 2, 2.1, 0.35};
  std::size_t checked = 0;
  for (const Ratio& n : ratios)
    for (double a2 : a2s) {
      const BoundarySet s = boundary_set(a2, n);
      for (const BoundaryEvent& e : of_kind(s, BoundaryEventKind::tangency)) {
        INFO("n = " << n.p() << "/" << n.q() << ", a2 = " << a2 << ", event " << e.name << " at a3 = " << e.a3);
        REQUIRE(std::llabs(e.nodes_above - e.nodes_below) == 2 * n.abs_p());
        const RootCensus rc = root_census(GearTrain(a2, e.a3, n));
        bool found = false;
        for (const NodeRoot& r : rc.roots)
          found = found || (r.kind == NodeKind::tangency && r.value == e.m && std::abs(r.beta - e.b) < 1e-6);
        CHECK(found);
        CHECK(static_cast<std::int64_t>(rc.nodes.size()) == (e.nodes_below + e.nodes_above) / 2);
        ++checked;
      }
    }
  CHECK(checked >= 10);  // the ratios and a2 above do have tangency loci (n = 3 at pi/2: two)
}
