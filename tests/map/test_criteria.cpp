// Tests for sphtroch/map/criteria.hpp: the report's analytic criteria, nodes, cusps, z extremes and
// mirror planes. Expected values come from the report's equations (Lin & Tsai 1990) or from
// invariants of the curve evaluated by TracerCurve (points equal at both node parameters, zero
// velocity at cusps, stationary z, reflected points on the curve) — never from criteria.hpp itself.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/extremes_and_symmetry.hpp"
#include "sphtroch/core/curve.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

const double kPiD = Constants<double>::pi();
const double kTwoPiD = Constants<double>::two_pi();

/// Distance of two parameters on the circle of length `period`.
double param_distance(double a, double b, double period) {
  double d = std::fmod(std::abs(a - b), period);
  return std::min(d, period - d);
}

double speed(const TracerCurve<double>& curve, double t) { return curve.velocity(t).norm(); }

struct Ratios {
  std::int64_t p, q;
};

const std::vector<Ratios> kRatios{{1, 1}, {2, 1}, {3, 1}, {1, 2}, {1, 3}, {3, 2}, {5, 2}, {7, 3}, {-2, 1}, {-1, 3}, {13, 5}};

using CsvRow = sphtroch::test::PaperCase;
std::vector<CsvRow> read_paper_cases() { return sphtroch::test::paper_cases(); }

/// Every node: on the curve at both parameters, the parameters distinct mod the period.
void check_nodes_on_curve(const GearTrain& train, const std::vector<AnalyticNode>& nodes, double tol = 1e-14) {
  TracerCurve<double> curve(train);
  for (const AnalyticNode& node : nodes) {
    INFO("node " << node.equation << " at " << node.position.transpose());
    REQUIRE(node.params.size() == 2);
    CHECK(std::abs(node.position.norm() - 1.0) < 1e-14);
    for (double t : node.params) {
      CHECK(t >= 0.0);
      CHECK(t < train.period());
      CHECK((curve.point(t) - node.position).norm() < tol);
    }
    CHECK(node.params[0] <= node.params[1]);
    CHECK(param_distance(node.params[0], node.params[1], train.period()) > 1e-9);
  }
}

Matrix3d rot_z(double angle) {
  Matrix3d r;
  r << std::cos(angle), -std::sin(angle), 0, std::sin(angle), std::cos(angle), 0, 0, 0, 1;
  return r;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Boundaries
// ---------------------------------------------------------------------------------------------

TEST_CASE("boundaries: the list per ratio and exact margins for symbolic inputs", "[analytic][boundary]") {
  const GearTrain n1(kPiD / 2, 1.0, Ratio(1));
  const std::vector<Boundary> b1 = boundaries(n1);
  REQUIRE(b1.size() == 6);
  const GearTrain n2(kPiD / 2, 1.0, Ratio(2));
  const std::vector<Boundary> b2 = boundaries(n2);
  REQUIRE(b2.size() == 4);
  for (const Boundary& b : b2) CHECK(b.margin == Approx(1.0 - b.value).margin(1e-15));
  // Values from the report: a_p = atan(sin a2 / (cos a2 + 2)) (Sec. 5), pi - a_p, a2, pi - a2.
  const double ap = std::atan(1.0 / 2.0);
  CHECK(b2[0].value == Approx(ap).margin(1e-15));
  CHECK(b2[1].value == Approx(kPiD - ap).margin(1e-15));
  CHECK(b2[2].value == Approx(kPiD / 2).margin(1e-15));
  CHECK(b2[3].value == Approx(kPiD / 2).margin(1e-15));
  CHECK(b1[4].value == Approx(kPiD / 4).margin(1e-15));      // a2/2
  CHECK(b1[5].value == Approx(3 * kPiD / 4).margin(1e-15));  // pi - a2/2

  SECTION("tracer_near_pitch_cone_1e-12: on the boundary by default, margin exact") {
    const GearTrain t = GearTrain::on_cone(kPiD / 3, A3Reference::pitch_cone, 1e-12, Ratio(5, 2));
    const std::vector<Boundary> hit = boundaries_hit(t);
    REQUIRE(hit.size() == 1);
    CHECK(hit[0].kind == BoundaryKind::pitch_cone);
    CHECK(hit[0].margin == 1e-12);
    CHECK(boundaries_hit(t, 0.0).empty());  // literal reading
  }
  SECTION("tracer_near_pitch_cone_1e-9: outside the tolerance") {
    const GearTrain t = GearTrain::on_cone(kPiD / 3, A3Reference::mirror_pitch_cone, -1e-9, Ratio(2));
    CHECK(boundaries_hit(t).empty());
    CHECK(boundary_margin(t, BoundaryKind::mirror_pitch_cone) == -1e-9);
  }
  SECTION("typed_pi_multiples: row (g) typed as doubles is within rounding of pi - a2") {
    const GearTrain g(kPiD / 3, 2 * kPiD / 3, Ratio(2));
    const std::vector<Boundary> hit = boundaries_hit(g);
    REQUIRE(hit.size() == 1);
    CHECK(hit[0].kind == BoundaryKind::pi_minus_a2);
    CHECK(std::abs(hit[0].margin) < 1e-15);
    CHECK(boundaries_hit(g, 0.0).size() == (hit[0].margin == 0.0 ? 1u : 0u));
  }
  SECTION("pole_node: row (d) lies on a3 = a2 and a3 = pi - a2 at once") {
    const GearTrain d(kPiD / 2, kPiD / 2, Ratio(2));
    std::vector<BoundaryKind> kinds;
    for (const Boundary& b : boundaries_hit(d)) kinds.push_back(b.kind);
    CHECK(kinds == std::vector<BoundaryKind>{BoundaryKind::a2, BoundaryKind::pi_minus_a2});
  }
  SECTION("n = 1 cardioid: a2/2 and a_p hit together") {
    const GearTrain e(kPiD / 2, kPiD / 4, Ratio(1));
    std::vector<BoundaryKind> kinds;
    for (const Boundary& b : boundaries_hit(e)) kinds.push_back(b.kind);
    CHECK(kinds == std::vector<BoundaryKind>{BoundaryKind::pitch_cone, BoundaryKind::half_a2});
  }
}

// ---------------------------------------------------------------------------------------------
// n = 1
// ---------------------------------------------------------------------------------------------

TEST_CASE("n = 1 grid: Eq. 24 agrees with Eq. 23, the Eq. 25 node is on the curve twice", "[analytic][n1]") {
  std::size_t pairs = 0, with_node = 0, simple = 0;
  for (int i = 0; i < 16; ++i) {
    for (int j = 0; j < 16; ++j) {
      // Offsets keep the grid off the exact boundaries a3 = a2/2, pi - a2/2.
      const double a2 = (i + 0.5) * kPiD / 16.0;
      const double a3 = (j + 0.31) * kPiD / 16.0;
      const double phase = ((i + j) % 3) * 0.45;  // 0, 0.45, 0.9
      const GearTrain train(a2, a3, Ratio(1), phase);
      ++pairs;
      INFO("a2 = " << a2 << ", a3 = " << a3 << ", phase = " << phase);
      // Eq. 22b's argument; Eq. 23: two real solutions iff it lies in [-1, 1].
      const double arg = -std::sin(a2) * std::cos(a3) / (std::sin(a3) * (1.0 + std::cos(a2)));
      REQUIRE(std::abs(std::abs(arg) - 1.0) > 1e-6);  // grid stays off the boundary
      const bool eq23 = std::abs(arg) < 1.0;
      const Criterion c = criterion_eq24(train);
      CHECK(c.equation == "Eq. 24");
      CHECK((c.status == CriterionStatus::holds_strictly) == eq23);
      CHECK((c.status == CriterionStatus::fails) == !eq23);
      CHECK(c.lower == Approx(a2 / 2).margin(1e-15));
      CHECK(c.upper == Approx(kPiD - a2 / 2).margin(1e-15));
      const AnalyticClassification a = classify_analytic(train);
      REQUIRE(a.applicable);
      REQUIRE(a.predicted_nodes.has_value());
      CHECK(*a.predicted_nodes == (eq23 ? 1u : 0u));
      CHECK(a.predicted_cusps == 0u);
      if (eq23) {
        ++with_node;
        REQUIRE(a.nodes.size() == 1);
        const AnalyticNode& node = a.nodes[0];
        CHECK(node.kind == NodeKind::crossing);
        // Eq. 25 rotated by -theta_p/n about Z1 (Eq. 8).
        const Vector3d eq25 = rot_z(-phase) * Vector3d(0.0, std::sin(a3), std::cos(a3));
        CHECK((node.position - eq25).norm() < 1e-14);
        // Parameters: +-acos(Eq. 22b) shifted by -theta_p/n (Eq. 8): cos(t + phase) = arg.
        for (double t : node.params) CHECK(std::cos(t + phase) == Approx(arg).margin(1e-13));
        check_nodes_on_curve(train, a.nodes);
        CHECK(a.curve_class == "nodes");
      } else {
        ++simple;
        CHECK(a.nodes.empty());
        CHECK(a.curve_class == "simple curve");
      }
    }
  }
  CHECK(pairs >= 200);
  CHECK(with_node > 50);
  CHECK(simple > 20);
}

TEST_CASE("n = 1 cardioids: equality in Eq. 24 is one cusp at Eq. 25's point", "[analytic][n1][cusp]") {
  for (double phase : {0.0, 1.3}) {
    for (double a2 : {kPiD / 3, kPiD / 2, 2 * kPiD / 3}) {
      for (A3Reference ref : {A3Reference::pitch_cone, A3Reference::mirror_pitch_cone}) {
        const GearTrain train = GearTrain::on_cone(a2, ref, 0.0, Ratio(1), phase);
        INFO("a2 = " << a2 << " ref " << to_string(ref) << " phase " << phase);
        const Criterion c = criterion_eq24(train);
        CHECK(c.status == (ref == A3Reference::pitch_cone ? CriterionStatus::equality_at_lower
                                                           : CriterionStatus::equality_at_upper));
        CHECK(c.predicted_cusps == 1u);
        const AnalyticClassification a = classify_analytic(train);
        CHECK(*a.predicted_nodes == 0u);
        REQUIRE(a.cusps.size() == 1);
        const double a3 = train.a3();
        CHECK((a.cusps[0].position - rot_z(-phase) * Vector3d(0.0, std::sin(a3), std::cos(a3))).norm() < 1e-14);
        CHECK(a.curve_class == "cusps");
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// n = 2
// ---------------------------------------------------------------------------------------------

TEST_CASE("n = 2 grid: Eqs. 43/46 agree with Eqs. 40/45, nodes of Eqs. 39b/44b on the curve twice",
          "[analytic][n2]") {
  std::size_t with43 = 0, with46 = 0, pairs = 0;
  for (int i = 0; i < 14; ++i) {
    for (int j = 0; j < 14; ++j) {
      const double a2 = (i + 0.5) * kPiD / 14.0;
      const double a3 = (j + 0.37) * kPiD / 14.0;
      for (double phase : {0.0, 0.9}) {
        const GearTrain train(a2, a3, Ratio(2), phase);
        ++pairs;
        INFO("a2 = " << a2 << ", a3 = " << a3 << ", phase = " << phase);
        const double den = 2.0 * std::sin(a3) * (1.0 + std::cos(a2));
        const double S = std::sin(a2 + a3) / den;  // Eq. 40: sin^2 theta2 of Eq. 39b
        const double C = std::sin(a3 - a2) / den;  // Eq. 45: cos^2 theta2 of Eq. 44b
        REQUIRE(std::min(std::abs(S), std::abs(S - 1)) > 1e-6);
        REQUIRE(std::min(std::abs(C), std::abs(C - 1)) > 1e-6);
        const bool eq40 = S > 0 && S < 1, eq45 = C > 0 && C < 1;
        CHECK((criterion_eq43(train).status == CriterionStatus::holds_strictly) == eq40);
        CHECK((criterion_eq46(train).status == CriterionStatus::holds_strictly) == eq45);
        const std::vector<AnalyticNode> n39 = nodes_eq39b(train);
        const std::vector<AnalyticNode> n44 = nodes_eq44b(train);
        CHECK(n39.size() == (eq40 ? 2u : 0u));
        CHECK(n44.size() == (eq45 ? 2u : 0u));
        with43 += eq40;
        with46 += eq45;
        check_nodes_on_curve(train, n39);
        check_nodes_on_curve(train, n44);
        const AnalyticClassification a = classify_analytic(train);
        CHECK(*a.predicted_nodes == n39.size() + n44.size());
        CHECK(a.predicted_cusps == 0u);
        if (phase == 0.0) {
          for (const AnalyticNode& nd : n39) {
            CHECK(std::abs(nd.position.y()) < 1e-15);  // Eq. 39b nodes on the plane y = 0
            for (double t : nd.params) CHECK(std::sin(t) * std::sin(t) == Approx(S).margin(1e-13));
          }
          for (const AnalyticNode& nd : n44) {
            CHECK(std::abs(nd.position.x()) < 1e-15);  // Eq. 44b nodes on the plane x = 0
            for (double t : nd.params) CHECK(std::cos(t) * std::cos(t) == Approx(C).margin(1e-13));
          }
        }
      }
    }
  }
  CHECK(pairs >= 200);
  CHECK(with43 > 20);
  CHECK(with46 > 20);
}

TEST_CASE("n = 2 Table 1 rows (a) and (c) with chosen values", "[analytic][n2][table1]") {
  SECTION("row (a): a_p < a3 < pi - a2, Eq. 46 fails -> 2 nodes") {
    const GearTrain a(kPiD / 3, kPiD / 4, Ratio(2));  // a_p = 0.333 < pi/4 < 2pi/3; pi/4 < a2
    const AnalyticClassification c = classify_analytic(a);
    CHECK(c.criteria[0].status == CriterionStatus::holds_strictly);
    CHECK(c.criteria[1].status == CriterionStatus::fails);
    CHECK(*c.predicted_nodes == 2u);
    CHECK(c.predicted_cusps == 0u);
    check_nodes_on_curve(a, c.nodes);
  }
  SECTION("row (c): neither criterion -> simple curve") {
    for (double a3 : {kPiD / 8, 15 * kPiD / 16}) {  // a_p = atan(1/2) = 0.464 for a2 = pi/2
      const GearTrain t(kPiD / 2, a3, Ratio(2));
      const AnalyticClassification c = classify_analytic(t);
      CHECK(c.criteria[0].status == CriterionStatus::fails);
      CHECK(c.criteria[1].status == CriterionStatus::fails);
      CHECK(*c.predicted_nodes == 0u);
      CHECK(c.predicted_cusps == 0u);
      CHECK(c.curve_class == "simple curve");
    }
  }
}

TEST_CASE("paper_cases.csv: predicted counts reproduce every row, Table 1 columns", "[analytic][paper]") {
  const std::vector<CsvRow> rows = read_paper_cases();
  REQUIRE(rows.size() >= 10);
  // Table 1 of the report: status of Eq. 43 and Eq. 46 for each figure of Fig. 5.
  using S = CriterionStatus;
  const std::map<std::string, std::pair<S, S>> table1{
      {"fig5b", {S::equality_at_lower, S::fails}},           {"fig5d", {S::equality_at_upper, S::equality_at_lower}},
      {"fig5e", {S::fails, S::equality_at_upper}},           {"fig5f", {S::holds_strictly, S::holds_strictly}},
      {"fig5g", {S::equality_at_upper, S::holds_strictly}},  {"fig5h", {S::fails, S::holds_strictly}}};
  for (const CsvRow& r : rows) {
    INFO("case " << r.id);
    const GearTrain train(r.a2, r.a3, Ratio(r.n_num, r.n_den));
    const AnalyticClassification a = classify_analytic(train);
    REQUIRE(a.predicted_nodes.has_value());
    CHECK(*a.predicted_nodes == r.nodes);
    CHECK(a.predicted_cusps == r.cusps);
    check_nodes_on_curve(train, a.nodes, 1e-13);
    TracerCurve<double> curve(train);
    for (const AnalyticCusp& cusp : a.cusps) {
      CHECK(speed(curve, cusp.param) < 1e-13);
      CHECK((curve.point(cusp.param) - cusp.position).norm() < 1e-13);
    }
    const auto it = table1.find(r.id);
    if (it != table1.end()) {
      REQUIRE(a.criteria.size() == 3);
      CHECK(a.criteria[0].equation == "Eq. 43");
      CHECK(a.criteria[1].equation == "Eq. 46");
      CHECK(a.criteria[0].status == it->second.first);
      CHECK(a.criteria[1].status == it->second.second);
    }
  }
}

TEST_CASE("pole_node: rows (d) and (g) have tangencies at the poles", "[analytic][n2][pole]") {
  SECTION("row (d): a2 = a3 = pi/2 -> nodes at both poles, both tangencies") {
    const GearTrain d(kPiD / 2, kPiD / 2, Ratio(2));
    const AnalyticClassification a = classify_analytic(d);
    REQUIRE(a.nodes.size() == 2);
    CHECK((a.nodes[0].position - Vector3d(0, 0, -1)).norm() < 1e-15);
    CHECK((a.nodes[1].position - Vector3d(0, 0, 1)).norm() < 1e-15);
    for (const AnalyticNode& n : a.nodes) CHECK(n.kind == NodeKind::tangency);
    // z_min = cos(a2 + a3) at theta2 = 0, pi (Eqs. 34, 35), z_max at pi/2, 3pi/2 (Eqs. 32, 33).
    CHECK(a.nodes[0].params == std::vector<double>{0.0, kPiD});
    CHECK(a.nodes[1].params == std::vector<double>{kPiD / 2, 3 * kPiD / 2});
    check_nodes_on_curve(d, a.nodes);
  }
  SECTION("row (g): two Eq. 44b crossings and one tangency at (0,0,-1)") {
    const GearTrain g(kPiD / 3, 2 * kPiD / 3, Ratio(2), 0.6);
    const AnalyticClassification a = classify_analytic(g);
    REQUIRE(a.nodes.size() == 3);
    std::size_t tangencies = 0;
    for (const AnalyticNode& n : a.nodes) {
      if (n.kind == NodeKind::tangency) {
        ++tangencies;
        CHECK((n.position - Vector3d(0, 0, -1)).norm() < 1e-15);
      }
    }
    CHECK(tangencies == 1);
    check_nodes_on_curve(g, a.nodes);
  }
  SECTION("literal reading of typed row (g): two crossings 4e-8 apart instead of the tangency") {
    const GearTrain g(kPiD / 3, 2 * kPiD / 3, Ratio(2));
    const double m = boundary_margin(g, BoundaryKind::pi_minus_a2);
    const AnalyticClassification a = classify_analytic(g, 0.0);
    if (m < 0.0) {  // a2 + a3 < pi in doubles: Eq. 43 holds strictly
      REQUIRE(*a.predicted_nodes == 4u);
      check_nodes_on_curve(g, a.nodes, 1e-13);
      const std::vector<AnalyticNode> split = nodes_eq39b(g, 0.0);
      REQUIRE(split.size() == 2);
      CHECK((split[0].position - split[1].position).norm() < 1e-6);
    } else {
      CHECK(*a.predicted_nodes == (m == 0.0 ? 3u : 2u));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Cusps, every n
// ---------------------------------------------------------------------------------------------

TEST_CASE("pitch-cone cusps for every ratio: zero velocity, |p| per period", "[analytic][cusp]") {
  for (const Ratios& r : kRatios) {
    const Ratio n(r.p, r.q);
    for (double a2 : {kPiD / 3, kPiD / 2, 2 * kPiD / 3}) {
      for (double phase : {0.0, 0.7}) {
        for (A3Reference ref : {A3Reference::pitch_cone, A3Reference::mirror_pitch_cone}) {
          const GearTrain train = GearTrain::on_cone(a2, ref, 0.0, n, phase);
          INFO("n = " << n.str() << " a2 = " << a2 << " phase = " << phase << " ref " << to_string(ref));
          const double ap = train.planet_cone();
          const bool both = std::abs(ap - kPiD / 2) <= kBoundaryTolerance;
          const std::vector<AnalyticCusp> cusps = pitch_cone_cusps(train);
          REQUIRE(cusps.size() == static_cast<std::size_t>(n.abs_p()) * (both ? 2u : 1u));
          CHECK(classify_analytic(train).predicted_cusps == cusps.size());
          TracerCurve<double> curve(train);
          const double scale = curve.screw_axis(0.0).norm();
          for (std::size_t i = 0; i < cusps.size(); ++i) {
            const AnalyticCusp& c = cusps[i];
            CHECK(c.param >= 0.0);
            CHECK(c.param < train.period());
            if (i > 0) CHECK(c.param > cusps[i - 1].param + 1e-6);
            CHECK(speed(curve, c.param) < 1e-13 * scale);
            CHECK((curve.point(c.param) - c.position).norm() < 1e-13);
            // A cusp is isolated: the speed grows linearly away from it.
            for (double dt : {-1e-3, 1e-3}) CHECK(speed(curve, c.param + dt) > 1e-5);
          }
        }
        // Off both cones: no cusps.
        const GearTrain off = GearTrain::on_cone(a2, A3Reference::pitch_cone, 1e-3, n, phase);
        if (std::abs(off.a3() - (kPiD - off.planet_cone())) > 1e-6) CHECK(pitch_cone_cusps(off).empty());
      }
    }
  }
}

TEST_CASE("tracer_on_both_cones: a_p = pi/2 gives 2|p| cusps", "[analytic][cusp]") {
  // a_p = atan2(sin a2, cos a2 + n) = pi/2 needs cos a2 = -n: internal gearing with |n| < 1.
  for (const Ratios& r : std::vector<Ratios>{{-1, 2}, {-1, 3}, {-2, 3}}) {
    const Ratio n(r.p, r.q);
    const GearTrain train = GearTrain::on_cone(std::acos(-n.value()), A3Reference::pitch_cone, 0.0, n);
    INFO("n = " << n.str() << " a_p - pi/2 = " << train.planet_cone() - kPiD / 2);
    const Criterion c = pitch_cone_criterion(train);
    CHECK(c.status == CriterionStatus::equality_at_both);
    const std::vector<AnalyticCusp> cusps = pitch_cone_cusps(train);
    REQUIRE(cusps.size() == 2 * static_cast<std::size_t>(n.abs_p()));
    TracerCurve<double> curve(train);
    for (const AnalyticCusp& cusp : cusps) CHECK(speed(curve, cusp.param) < 1e-13);
    const AnalyticClassification a = classify_analytic(train);
    CHECK_FALSE(a.applicable);
    CHECK_FALSE(a.predicted_nodes.has_value());
    CHECK(a.curve_class == "cusps (nodes not predicted)");
  }
}

TEST_CASE("near-cusp loops: tolerance decides cusp vs node", "[analytic][cusp][n1]") {
  SECTION("near_cusp_loop_1e-11: within kBoundaryTolerance -> cusp; literal -> node") {
    const GearTrain t = GearTrain::on_cone(kPiD / 2, A3Reference::pitch_cone, 1e-11, Ratio(1));
    CHECK(classify_analytic(t).predicted_cusps == 1u);
    CHECK(*classify_analytic(t).predicted_nodes == 0u);
    const AnalyticClassification lit = classify_analytic(t, 0.0);
    CHECK(lit.predicted_cusps == 0u);
    CHECK(*lit.predicted_nodes == 1u);
  }
  for (double d : {1e-3, 1e-6, 1e-9}) {
    for (std::int64_t p : {1, 2}) {
      const GearTrain t = GearTrain::on_cone(kPiD / 2, A3Reference::pitch_cone, d, Ratio(p));
      INFO("near_cusp_loop d = " << d << " n = " << p);
      const AnalyticClassification a = classify_analytic(t);
      CHECK(a.predicted_cusps == 0u);
      // n = 1: the loop's node (Eq. 25); n = 2: two Eq. 39b nodes, plus the Eq. 44b ones? Eq. 46
      // fails at a2 = pi/2 with a3 ~ a_p < a2, so only the loop nodes.
      REQUIRE(*a.predicted_nodes == static_cast<std::size_t>(p));
      check_nodes_on_curve(t, a.nodes, 1e-13);
      // Parameter length of the loop ~ sqrt(d) (issue 3): well separated from a cusp's single value.
      for (const AnalyticNode& n : a.nodes)
        CHECK(param_distance(n.params[0], n.params[1], t.period()) > 0.1 * std::sqrt(d));
    }
  }
}

TEST_CASE("other ratios: only the cusp criterion applies", "[analytic]") {
  const GearTrain t(kPiD / 3, kPiD / 3, Ratio(3));
  const AnalyticClassification a = classify_analytic(t);
  CHECK_FALSE(a.applicable);
  CHECK_FALSE(a.predicted_nodes.has_value());
  CHECK(a.nodes.empty());
  REQUIRE(a.criteria.size() == 1);
  CHECK(a.criteria[0].status == CriterionStatus::holds_strictly);
  CHECK(a.predicted_cusps == 0u);
  CHECK(a.curve_class == "no cusps (nodes not predicted)");
}

// ---------------------------------------------------------------------------------------------
// Phase (Eq. 8)
// ---------------------------------------------------------------------------------------------

TEST_CASE("phase rotates the predicted nodes by -theta_p/n about Z1 (Eq. 8)", "[analytic][phase]") {
  for (const auto& c : std::vector<std::pair<double, double>>{{kPiD / 3, kPiD / 2}, {kPiD / 3, 2 * kPiD / 3}}) {
    const GearTrain zero(c.first, c.second, Ratio(2));
    const double phase = 0.8;
    const GearTrain turned(c.first, c.second, Ratio(2), phase);
    const AnalyticClassification a0 = classify_analytic(zero), a1 = classify_analytic(turned);
    REQUIRE(a0.nodes.size() == a1.nodes.size());
    for (std::size_t i = 0; i < a0.nodes.size(); ++i)
      CHECK((a1.nodes[i].position - rot_z(-phase / 2) * a0.nodes[i].position).norm() < 1e-15);
    check_nodes_on_curve(turned, a1.nodes);
  }
}

// ---------------------------------------------------------------------------------------------
// z extremes
// ---------------------------------------------------------------------------------------------

TEST_CASE("z extremes: Eqs. 14/15 (n = 1) and 32-35 (n = 2) at phase 0", "[analytic][extremes]") {
  const double a2 = 1.1, a3 = 0.7;
  const ZExtremes z1 = z_extremes(GearTrain(a2, a3, Ratio(1)));
  REQUIRE(z1.maxima.size() == 1);
  REQUIRE(z1.minima.size() == 1);
  CHECK(z1.maxima[0].param == Approx(kPiD));                                                         // Eq. 14
  CHECK((z1.maxima[0].position - Vector3d(0, std::sin(a2 - a3), std::cos(a2 - a3))).norm() < 1e-15);  // Eq. 14
  CHECK(z1.minima[0].param == 0.0);                                                                   // Eq. 15
  CHECK((z1.minima[0].position - Vector3d(0, -std::sin(a2 + a3), std::cos(a2 + a3))).norm() < 1e-15);
  CHECK(z1.z_max == Approx(std::cos(a2 - a3)).margin(1e-15));
  CHECK(z1.z_min == Approx(std::cos(a2 + a3)).margin(1e-15));

  const ZExtremes z2 = z_extremes(GearTrain(a2, a3, Ratio(2)));
  REQUIRE(z2.maxima.size() == 2);
  REQUIRE(z2.minima.size() == 2);
  CHECK(z2.maxima[0].param == Approx(kPiD / 2));  // Eq. 33
  CHECK((z2.maxima[0].position - Vector3d(std::sin(a2 - a3), 0, std::cos(a2 - a3))).norm() < 1e-15);
  CHECK(z2.maxima[1].param == Approx(3 * kPiD / 2));  // Eq. 32 (theta2 = -pi/2)
  CHECK((z2.maxima[1].position - Vector3d(-std::sin(a2 - a3), 0, std::cos(a2 - a3))).norm() < 1e-15);
  CHECK(z2.minima[0].param == 0.0);  // Eq. 34
  CHECK((z2.minima[0].position - Vector3d(0, -std::sin(a2 + a3), std::cos(a2 + a3))).norm() < 1e-15);
  CHECK(z2.minima[1].param == Approx(kPiD));  // Eq. 35
  CHECK((z2.minima[1].position - Vector3d(0, std::sin(a2 + a3), std::cos(a2 + a3))).norm() < 1e-15);
}

TEST_CASE("z extremes for every ratio: stationary, on the curve, equal to dense-sample max/min",
          "[analytic][extremes]") {
  for (const Ratios& r : kRatios) {
    const Ratio n(r.p, r.q);
    for (double phase : {0.0, 1.1}) {
      const GearTrain train(1.2, 2.0, n, phase);
      INFO("n = " << n.str() << " phase = " << phase);
      TracerCurve<double> curve(train);
      const ZExtremes z = z_extremes(train);
      CHECK(z.maxima.size() == static_cast<std::size_t>(n.abs_p()));
      CHECK(z.minima.size() == static_cast<std::size_t>(n.abs_p()));
      for (const auto* list : {&z.maxima, &z.minima}) {
        for (const CurvePoint& e : *list) {
          CHECK((curve.point(e.param) - e.position).norm() < 1e-13);
          CHECK(std::abs(curve.velocity(e.param).z()) < 1e-13);  // dz/dtheta2 = 0 (Eqs. 13, 31)
          CHECK(e.position.z() == Approx(list == &z.maxima ? z.z_max : z.z_min).margin(1e-14));
        }
      }
      // Dense sampling: |z - z_ext| <= |z''|/2 (h/2)^2 with |z''| <= n^2 sin a2 sin a3 <= n^2.
      const std::size_t N = 200000;
      const double h = train.period() / N;
      double zmax = -2, zmin = 2;
      for (std::size_t i = 0; i < N; ++i) {
        const double zz = curve.point(h * i).z();
        zmax = std::max(zmax, zz);
        zmin = std::min(zmin, zz);
      }
      const double bound = 0.5 * train.n() * train.n() * 0.25 * h * h + 1e-14;
      CHECK(zmax <= z.z_max + 1e-14);
      CHECK(zmax >= z.z_max - bound);
      CHECK(zmin >= z.z_min - 1e-14);
      CHECK(zmin <= z.z_min + bound);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Mirror symmetry
// ---------------------------------------------------------------------------------------------

TEST_CASE("mirror planes: |p| vertical planes, M P(t) = P(t') on a grid, with phase", "[analytic][symmetry]") {
  for (const Ratios& r : kRatios) {
    const Ratio n(r.p, r.q);
    for (double phase : {0.0, 0.7, -2.3}) {
      const GearTrain train(1.0, 1.9, n, phase);
      INFO("n = " << n.str() << " phase = " << phase);
      TracerCurve<double> curve(train);
      const Symmetry s = symmetry(train);
      CHECK(s.rotation_order == static_cast<std::size_t>(n.abs_p()));
      REQUIRE(s.planes.size() == static_cast<std::size_t>(n.abs_p()));
      // Rotational symmetry: Rz(2 pi / |p|) maps the curve to itself.
      const Vector3d rotated = rot_z(kTwoPiD / n.abs_p()) * curve.point(0.3);
      double closest = 10;
      for (int i = 0; i < 20000 * r.q; ++i) closest = std::min(closest, (curve.point(train.period() * i / (20000.0 * r.q)) - rotated).norm());
      CHECK(closest < 1e-3);
      for (std::size_t i = 0; i < s.planes.size(); ++i) {
        const MirrorPlane& pl = s.planes[i];
        CHECK(std::abs(pl.normal.norm() - 1.0) < 1e-15);
        CHECK(pl.normal.z() == 0.0);
        for (std::size_t j = 0; j < i; ++j) CHECK(std::abs(pl.normal.dot(s.planes[j].normal)) < 1.0 - 1e-9);
        const Matrix3d M = Matrix3d::Identity() - 2.0 * pl.normal * pl.normal.transpose();
        for (int k = 0; k < 97; ++k) {
          const double t = train.period() * (k + 0.123) / 97.0;
          const double tp = mirror_parameter(pl, t, train.period());
          CHECK(tp >= 0.0);
          CHECK(tp < train.period());
          CHECK((M * curve.point(t) - curve.point(tp)).norm() < 1e-13);
        }
      }
    }
  }
  SECTION("n = 1: the Y-Z plane (Sec. 4.2); n = 2: the Y-Z and X-Z planes (Sec. 5.1)") {
    const Symmetry s1 = symmetry(GearTrain(1.0, 1.0, Ratio(1)));
    REQUIRE(s1.planes.size() == 1);
    CHECK((s1.planes[0].normal - Vector3d::UnitX()).norm() < 1e-15);
    const Symmetry s2 = symmetry(GearTrain(1.0, 1.0, Ratio(2)));
    REQUIRE(s2.planes.size() == 2);
    CHECK((s2.planes[0].normal - Vector3d::UnitX()).norm() < 1e-15);
    CHECK((s2.planes[1].normal - Vector3d::UnitY()).norm() < 1e-15);
  }
}
