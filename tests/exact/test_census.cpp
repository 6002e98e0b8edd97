// Tests of the node census: classification.hpp, polyline_census.hpp, root_census.hpp,
// refinement.hpp, node_assembly.hpp, boundary_snap.hpp (issue 3, item 8).
//
// Expected values come from the report's equations evaluated HERE (Eq. 24/25 for n = 1, Eq. 28
// with Eqs. 39b/44b and Table 1 for n = 2, Eq. 47a for cusps), from invariants of the curve
// (a node is P(t1) = P(t2); a cusp has zero speed; the phase rotates the curve by -phase/n,
// Eq. 8), or from the other census as an independent method — never from the output of the
// code under test. Each hard case is named after what makes it hard.
#include "sphtroch/exact/mpreal_support.hpp"  // first: Eigen's MPRealSupport

#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/map/criteria.hpp"
#include "sphtroch/classify.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/census/node_assembly.hpp"
#include "sphtroch/census/node_sets.hpp"
#include "sphtroch/exact/polyline_census.hpp"
#include "sphtroch/census/refinement.hpp"
#include "sphtroch/census/root_census.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();

using PaperRow = sphtroch::test::PaperCase;  // data/reference/paper_cases.csv (test_support.hpp)

GearTrain train_of(const PaperRow& r) {
  if (r.a3_symbolic == "a_p") return GearTrain::on_cone(r.a2, A3Reference::pitch_cone, 0.0, Ratio(r.n_num, r.n_den));
  return GearTrain(r.a2, r.a3, Ratio(r.n_num, r.n_den));
}

/// Eq. 28 (n = 2, theta_p = 0), written out from the report.
Vector3d eq28(double a2, double a3, double t) {
  const double s = std::sin(t), c = std::cos(t);
  const double k = std::sin(a3) * (1 + std::cos(a2));
  return Vector3d(s * (2 * (1 - s * s) * k + std::sin(a2 - a3)), c * (2 * (1 - c * c) * k - std::sin(a2 + a3)),
                  -std::cos(2 * t) * std::sin(a2) * std::sin(a3) + std::cos(a2) * std::cos(a3));
}

/// The report's n = 2 nodes: Eq. 39b (on y = 0) when Eq. 43 holds strictly, Eq. 44b (on x = 0)
/// when Eq. 46 holds strictly. Each with its two parameters.
struct ReportNode {
  Vector3d position;
  double t1, t2;
  bool on_xz_plane;  // Eq. 39b: y = 0; Eq. 44b: x = 0
};

std::vector<ReportNode> report_nodes_n2(double a2, double a3) {
  std::vector<ReportNode> out;
  const double ap = std::atan2(std::sin(a2), std::cos(a2) + 2);
  const double k = std::sin(a3) * (1 + std::cos(a2));
  const double den = 2 * k;
  const double sa2 = std::sin(a2), sa3 = std::sin(a3), ca2 = std::cos(a2), ca3 = std::cos(a3);
  if (ap < a3 && a3 < kPi - a2) {  // Eq. 43 strictly: sin^2 theta2 = s(a2 + a3) / den (Eq. 39b)
    const double s2 = std::sin(a2 + a3) / den;
    for (double sg : {1.0, -1.0}) {
      // Eq. 28 with sin theta2 = s: x and z depend on s only, y = 0 (the X-Z plane).
      const double s = sg * std::sqrt(s2);
      const Vector3d x(s * (2 * (1 - s2) * k + std::sin(a2 - a3)), 0.0, -(1 - 2 * s2) * sa2 * sa3 + ca2 * ca3);
      const double t = std::asin(s);
      out.push_back({x, t, kPi - t, true});
    }
  }
  if (a2 < a3 && a3 < kPi - ap) {  // Eq. 46 strictly: cos^2 theta2 = s(a3 - a2) / den (Eq. 44b)
    const double c2 = std::sin(a3 - a2) / den;
    for (double sg : {1.0, -1.0}) {
      // Eq. 28 with cos theta2 = c: y and z depend on c only, x = 0 (the Y-Z plane).
      const double c = sg * std::sqrt(c2);
      const Vector3d x(0.0, c * (2 * (1 - c2) * k - std::sin(a2 + a3)), -(2 * c2 - 1) * sa2 * sa3 + ca2 * ca3);
      const double t = std::acos(c);
      out.push_back({x, t, 2 * kPi - t, false});
    }
  }
  return out;
}

double param_distance(double a, double b, double period) {
  double d = std::fmod(std::abs(a - b), period);
  return std::min(d, period - d);
}

/// The node of `nodes` nearest to x (nullptr when empty).
const Node* nearest(const std::vector<Node>& nodes, const Vector3d& x) {
  const Node* best = nullptr;
  for (const Node& n : nodes)
    if (!best || (n.position - x).norm() < (best->position - x).norm()) best = &n;
  return best;
}

/// Node-for-node agreement of two node sets (census/node_sets.hpp, tested on its own in
/// test_certified_census.cpp): same size, nearest nodes paired one to one within 1e-8 with equal
/// kinds and branch counts.
void check_same_nodes(const std::vector<Node>& a, const std::vector<Node>& b) {
  std::string why;
  const bool same = same_node_sets(a, b, why);
  INFO(why);
  CHECK(same);
}

/// Every branch parameter of every node puts the curve on the node (to `tol`).
void check_on_curve(const GearTrain& train, const std::vector<Node>& nodes, double tol) {
  const TracerCurve<long double> curve(train);
  for (const Node& n : nodes) {
    CHECK(n.branches == n.params.size());
    CHECK(n.branches >= 2);
    for (double t : n.params) {
      const Vector3d p = curve.point(t).cast<double>();
      INFO("node (" << n.position.transpose() << ") branch theta2 = " << t);
      CHECK((p - n.position).norm() <= tol);
    }
  }
}

bool finite_nodes(const std::vector<Node>& nodes) {
  for (const Node& n : nodes) {
    if (!n.position.allFinite() || !std::isfinite(n.angle)) return false;
    for (double t : n.params)
      if (!std::isfinite(t)) return false;
  }
  return true;
}

std::size_t count_kind(const std::vector<Node>& nodes, NodeKind k) {
  return static_cast<std::size_t>(std::count_if(nodes.begin(), nodes.end(), [&](const Node& n) { return n.kind == k; }));
}

/// Eq. 47a: omega = Z1 + n Z2 in the base frame.
Vector3d omega_eq47a(double a2, double n, double t) {
  return Vector3d(n * std::sin(t) * std::sin(a2), -n * std::cos(t) * std::sin(a2), 1 + n * std::cos(a2));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The report's cases (data/reference/paper_cases.csv)
// ---------------------------------------------------------------------------------------------

TEST_CASE("census: every paper case: node and cusp counts, kinds and positions from the report", "[census][paper]") {
  const auto rows = sphtroch::test::paper_cases();
  REQUIRE(rows.size() >= 10);
  for (const PaperRow& r : rows) {
    INFO("case " << r.id << ": a2 = " << r.a2_symbolic << ", a3 = " << r.a3_symbolic << ", n = " << r.n_num << "/" << r.n_den);
    const GearTrain train = train_of(r);
    const Classification c = classify(train);
    CHECK(c.nodes.size() == r.nodes);
    CHECK(c.cusps.size() == r.cusps);
    CHECK(finite_nodes(c.nodes));
    check_on_curve(c.snapped.train, c.nodes, 1e-12);
    check_same_nodes(c.polyline.nodes, c.root.nodes);
    const double a2 = r.a2, a3 = r.a3;

    // Cusps: zero speed, P parallel to omega (Eq. 47a), exactly |p| of them here.
    const TracerCurve<double> curve(c.snapped.train);
    for (const Cusp& k : c.cusps) {
      CHECK(curve.velocity(k.param).norm() <= 1e-14);
      const Vector3d w = omega_eq47a(a2, train.n(), k.param).normalized();
      CHECK(std::abs(std::abs(w.dot(k.position)) - 1) <= 1e-14);
      CHECK((curve.point(k.param) - k.position).norm() <= 1e-15);
    }

    if (r.n_num == 1 && r.n_den == 1) {
      // Eq. 24 strictly: one crossing at Eq. 25, (0, sin a3, cos a3); equality: the cusp is there.
      const Vector3d eq25(0, std::sin(a3), std::cos(a3));
      for (const Node& n : c.nodes) {
        CHECK(n.kind == NodeKind::crossing);
        CHECK((n.position - eq25).norm() <= 1e-13);
      }
      if (r.cusps > 0) {  // fig4e, fig4g: "the location of the cusp can also be expressed by Eq. 25"
        REQUIRE(c.cusps.size() == 1);
        CHECK((c.cusps[0].position - eq25).norm() <= 1e-13);
      }
    } else if (r.id == "fig5d") {
      // a3 = a2 = pi - a2: both poles on the curve, each passed twice, the branches touching.
      REQUIRE(c.nodes.size() == 2);
      CHECK(c.tangencies == 2);
      CHECK(c.crossings == 0);
      const Node* north = nearest(c.nodes, Vector3d(0, 0, 1));
      const Node* south = nearest(c.nodes, Vector3d(0, 0, -1));
      REQUIRE(north != south);
      CHECK((north->position - Vector3d(0, 0, 1)).norm() <= 1e-12);
      CHECK((south->position - Vector3d(0, 0, -1)).norm() <= 1e-12);
      CHECK(north->kind == NodeKind::tangency);
      CHECK(south->kind == NodeKind::tangency);
    } else if (r.id == "fig5g") {
      // Eq. 43 at its upper end: the Eq. 39b pair merges into a tangency at (0,0,-1); Eq. 46
      // strictly: two crossings of Eq. 44b on x = 0.
      REQUIRE(c.nodes.size() == 3);
      CHECK(c.crossings == 2);
      CHECK(c.tangencies == 1);
      const Node* south = nearest(c.nodes, Vector3d(0, 0, -1));
      CHECK(south->kind == NodeKind::tangency);
      CHECK((south->position - Vector3d(0, 0, -1)).norm() <= 1e-12);
      std::vector<ReportNode> expected;
      for (const auto& e : report_nodes_n2(a2, a3))
        if (!e.on_xz_plane) expected.push_back(e);  // the Eq. 44b pair
      REQUIRE(expected.size() == 2);
      for (const auto& e : expected) {
        const Node* n = nearest(c.nodes, e.position);
        CHECK((n->position - e.position).norm() <= 1e-13);
        CHECK(n->kind == NodeKind::crossing);
        CHECK(std::abs(n->position.x()) <= 1e-14);
      }
    } else if (r.n_num == 2 && r.n_den == 1 && r.cusps == 0) {
      const auto expected = report_nodes_n2(a2, a3);
      CHECK(expected.size() == r.nodes);
      for (const auto& e : expected) {
        const Node* n = nearest(c.nodes, e.position);
        REQUIRE(n != nullptr);
        CHECK((n->position - e.position).norm() <= 1e-13);
        CHECK(n->kind == NodeKind::crossing);
        CHECK(std::abs(e.on_xz_plane ? n->position.y() : n->position.x()) <= 1e-14);
      }
    }
    // The analytic header's closed forms (Eqs. 25, 39b, 44b) name the same points.
    for (const AnalyticNode& an : c.analytic.nodes) {
      const Node* n = nearest(c.nodes, an.position);
      REQUIRE(n != nullptr);
      CHECK((n->position - an.position).norm() <= 1e-12);
      CHECK(n->kind == an.kind);
    }
    CHECK(c.analytic.nodes.size() == r.nodes);
    CHECK(c.agreement.ok());
  }
}

// ---------------------------------------------------------------------------------------------
// Grids against the report's criteria
// ---------------------------------------------------------------------------------------------

TEST_CASE("census: n = 1 grid of 15 x 15 (a2, a3) against Eq. 24 and the node of Eq. 25", "[census][grid][eq24][eq25]") {
  std::size_t tested = 0, with_node = 0;
  for (int i = 1; i <= 15; ++i)
    for (int j = 1; j <= 15; ++j) {
      const double a2 = 3.1 * i / 16.0 + 0.013, a3 = 3.1 * j / 16.0 + 0.007;
      // Keep 1e-3 away from the boundaries of Eq. 24 (a3 = a2/2 and pi - a2/2: cusps there).
      if (std::abs(a3 - a2 / 2) < 1e-3 || std::abs(a3 - (kPi - a2 / 2)) < 1e-3) continue;
      INFO("a2 = " << a2 << ", a3 = " << a3);
      const GearTrain train(a2, a3, Ratio(1));
      const Classification c = classify(train);
      ++tested;
      const bool eq24 = a2 / 2 < a3 && a3 < kPi - a2 / 2;
      REQUIRE(c.nodes.size() == (eq24 ? 1u : 0u));
      CHECK(c.cusps.empty());
      check_same_nodes(c.polyline.nodes, c.root.nodes);
      if (!eq24) continue;
      ++with_node;
      const Node& n = c.nodes.front();
      CHECK((n.position - Vector3d(0, std::sin(a3), std::cos(a3))).norm() <= 1e-13);  // Eq. 25
      CHECK(n.kind == NodeKind::crossing);
      CHECK(n.branches == 2);
      // Eq. 22b: theta2 = +-acos(-s a2 c a3 / (s a3 (1 + c a2))).
      const double t = std::acos(-std::sin(a2) * std::cos(a3) / (std::sin(a3) * (1 + std::cos(a2))));
      REQUIRE(n.params.size() == 2);
      CHECK(std::abs(n.params[0] - t) <= 1e-9);
      CHECK(std::abs(n.params[1] - (2 * kPi - t)) <= 1e-9);
    }
  CHECK(tested >= 200);
  CHECK(with_node >= 50);
}

TEST_CASE("census: n = 2 grid against Eqs. 43/46 (Table 1 logic) with the nodes of Eqs. 39b/44b",
          "[census][grid][eq43][eq46]") {
  std::size_t tested = 0, both = 0;
  for (int i = 1; i <= 15; ++i)
    for (int j = 1; j <= 15; ++j) {
      const double a2 = 3.1 * i / 16.0 + 0.011, a3 = 3.1 * j / 16.0 + 0.005;
      const double ap = std::atan2(std::sin(a2), std::cos(a2) + 2);
      bool near_boundary = false;
      for (double b : {ap, kPi - ap, a2, kPi - a2}) near_boundary = near_boundary || std::abs(a3 - b) < 1e-3;
      if (near_boundary) continue;
      INFO("a2 = " << a2 << ", a3 = " << a3);
      const GearTrain train(a2, a3, Ratio(2));
      const Classification c = classify(train);
      ++tested;
      const auto expected = report_nodes_n2(a2, a3);
      both += expected.size() == 4;
      REQUIRE(c.nodes.size() == expected.size());
      CHECK(c.cusps.empty());
      check_same_nodes(c.polyline.nodes, c.root.nodes);
      const TracerCurve<double> curve(train);
      for (const auto& e : expected) {
        const Node* n = nearest(c.nodes, e.position);
        CHECK((n->position - e.position).norm() <= 1e-13);
        CHECK(std::abs(e.on_xz_plane ? n->position.y() : n->position.x()) <= 1e-13);  // symmetry plane
        CHECK(n->kind == NodeKind::crossing);
        // On the curve at both of the report's parameters (Eq. 28 itself, and the D-H chain).
        CHECK((eq28(a2, a3, e.t1) - e.position).norm() <= 1e-13);
        CHECK((eq28(a2, a3, e.t2) - e.position).norm() <= 1e-13);
        CHECK((curve.point(e.t1) - n->position).norm() <= 1e-13);
        CHECK((curve.point(e.t2) - n->position).norm() <= 1e-13);
      }
    }
  CHECK(tested >= 200);
  CHECK(both >= 5);
}

// ---------------------------------------------------------------------------------------------
// The two numeric censuses against each other; phase (Eq. 8)
// ---------------------------------------------------------------------------------------------

TEST_CASE("census: polyline and root-count censuses agree node for node on a sweep of ratios, angles and phases",
          "[census][agreement][phase][eq8]") {
  const std::vector<std::pair<std::int64_t, std::int64_t>> ratios{{1, 3}, {1, 2}, {3, 2}, {2, 1},  {5, 2}, {3, 1},
                                                                  {7, 3}, {4, 1}, {13, 5}, {-2, 1}, {-1, 3}};
  const std::vector<std::pair<double, double>> angles{{1.0, 1.3}, {kPi / 2, 0.9}, {2.0, 2.4}, {0.7, 2.2}, {2.6, 0.5}};
  std::size_t total_nodes = 0;
  for (const auto& [p, q] : ratios)
    for (const auto& [a2, a3] : angles) {
      const Ratio n(p, q);
      INFO("n = " << n.str() << ", a2 = " << a2 << ", a3 = " << a3);
      const GearTrain train0(a2, a3, n);
      const PolylineCensus poly0 = polyline_census(train0);
      const RootCensus root0 = root_census(train0);
      check_same_nodes(poly0.nodes, root0.nodes);
      check_on_curve(train0, poly0.nodes, 1e-12);
      total_nodes += poly0.nodes.size();
      for (double phase : {0.7, -2.1}) {
        INFO("phase = " << phase);
        const GearTrain train(a2, a3, n, phase);
        const PolylineCensus poly = polyline_census(train);
        const RootCensus root = root_census(train);
        check_same_nodes(poly.nodes, root.nodes);
        check_on_curve(train, poly.nodes, 1e-12);
        // Eq. 8: the phase turns the node set about Z1 by -phase/n.
        const double turn = -phase / n.value();
        const Matrix3d rz = Eigen::AngleAxisd(turn, Vector3d::UnitZ()).toRotationMatrix();
        std::vector<Node> rotated = poly0.nodes;
        for (Node& r : rotated) r.position = rz * r.position;
        check_same_nodes(rotated, poly.nodes);
      }
    }
  CHECK(total_nodes >= 40);
}

// ---------------------------------------------------------------------------------------------
// Hard cases
// ---------------------------------------------------------------------------------------------

namespace {
/// Nodes expected near the pitch cone a3 = reference + offset, for the loop side and the other.
struct ConeCase {
  Ratio n;
  A3Reference cone;
};
}  // namespace

TEST_CASE("census: near_cusp_loop at a3 = a_p +- 1e-3, 1e-6, 1e-9: the loop is on exactly one side",
          "[census][hard][near_cusp_loop]") {
  const double a2 = kPi / 2;
  // Which side: n = 1, Eq. 24 (a2/2 = a_p < a3 < pi - a2/2 = pi - a_p): loops inside the
  // interval, i.e. a3 > a_p and a3 < pi - a_p. n = 2: Eq. 43 (a_p < a3) and Eq. 46 (a3 < pi -
  // a_p) likewise, and with a2 = pi/2 the other criterion fails near either cone, so the loop
  // side has 2 nodes and the other 0. Other n: the root-count census decides, and the polyline
  // census (the other method) must agree; the difference is |p| loops, one near each cusp.
  const std::vector<ConeCase> cases{{Ratio(1), A3Reference::pitch_cone},        {Ratio(1), A3Reference::mirror_pitch_cone},
                                    {Ratio(2), A3Reference::pitch_cone},        {Ratio(2), A3Reference::mirror_pitch_cone},
                                    {Ratio(3), A3Reference::pitch_cone},        {Ratio(5, 2), A3Reference::pitch_cone},
                                    {Ratio(5, 2), A3Reference::mirror_pitch_cone}};
  for (const ConeCase& cc : cases)
    for (double d : {1e-3, 1e-6, 1e-9})
      for (bool literal : {false, true}) {
        const double sign_loop = cc.cone == A3Reference::pitch_cone ? 1.0 : -1.0;  // loop side
        const GearTrain exact = GearTrain::on_cone(a2, cc.cone, 0.0, cc.n);
        const GearTrain loop = GearTrain::on_cone(a2, cc.cone, sign_loop * d, cc.n);
        const GearTrain plain = GearTrain::on_cone(a2, cc.cone, -sign_loop * d, cc.n);
        INFO("n = " << cc.n.str() << ", a3 = " << to_string(cc.cone) << " +- " << d << (literal ? " literal" : " default"));
        ClassifySettings s;
        s.reading.literal = literal;
        const Classification cl = classify(loop, s), cp = classify(plain, s);
        CHECK(cl.cusps.empty());
        CHECK(cp.cusps.empty());
        CHECK_FALSE(cl.cusp_within_resolution);
        check_same_nodes(cl.polyline.nodes, cl.root.nodes);
        check_same_nodes(cp.polyline.nodes, cp.root.nodes);
        const std::size_t abs_p = static_cast<std::size_t>(cc.n.abs_p());
        if (cc.n == Ratio(1)) {
          CHECK(cl.nodes.size() == 1);
          CHECK(cp.nodes.empty());
        } else if (cc.n == Ratio(2)) {
          CHECK(cl.nodes.size() == 2);
          CHECK(cp.nodes.empty());
        }
        REQUIRE(cl.nodes.size() == cp.nodes.size() + abs_p);
        // Every node of the loop side that is not one of the other side's is near a cusp of the
        // exact cone (theta3 = pi for a_p, 0 for pi - a_p; Eq. 3), within O(d).
        const TracerCurve<double> cone_curve(exact);
        std::vector<Vector3d> cusp_points;
        const double theta3 = cc.cone == A3Reference::pitch_cone ? kPi : 0.0;
        for (std::int64_t k = 0; k < cc.n.abs_p(); ++k)
          cusp_points.push_back(cone_curve.point((theta3 + 2 * kPi * k) / cc.n.value()));
        std::size_t near_cusp = 0;
        for (const Node& nd : cl.nodes) {
          double best = 1e9;
          for (const Vector3d& x : cusp_points) best = std::min(best, (nd.position - x).norm());
          if (best <= 10 * d) {
            ++near_cusp;
            CHECK(nd.kind == NodeKind::crossing);
            REQUIRE(nd.params.size() == 2);
            const double dt = param_distance(nd.params[0], nd.params[1], loop.period());
            CHECK(dt > 0);
            CHECK(dt <= 10 * std::sqrt(d));  // the loop's parameter length shrinks like sqrt(d)
          }
        }
        CHECK(near_cusp == abs_p);
        check_on_curve(loop, cl.nodes, 1e-12);  // each node on the curve at both parameters
      }
}

TEST_CASE("census: tracer_on_pitch_cone within 1e-12: a cusp within resolution, no spurious node",
          "[census][hard][tracer_on_pitch_cone]") {
  const double a2 = kPi / 2;
  for (const Ratio& n : {Ratio(1), Ratio(2), Ratio(3)})
    for (A3Reference cone : {A3Reference::pitch_cone, A3Reference::mirror_pitch_cone})
      for (double d : {1e-12, -1e-12}) {
        const GearTrain train = GearTrain::on_cone(a2, cone, d, n);
        INFO("n = " << n.str() << ", a3 = " << to_string(cone) << " + " << d);
        // Nodes the exact cone has (n = 1, 2 with a2 = pi/2: none; Eqs. 24, 43, 46 at equality).
        const GearTrain exact = GearTrain::on_cone(a2, cone, 0.0, n);
        const RootCensus root_exact = root_census(exact);
        for (bool literal : {false, true}) {
          ClassifySettings s;
          s.reading.literal = literal;
          const Classification c = classify(train, s);
          INFO((literal ? "literal" : "default"));
          CHECK(c.cusps.size() == static_cast<std::size_t>(n.abs_p()));
          if (literal) CHECK(c.cusp_within_resolution);
          if (n.abs_p() <= 2) CHECK(c.nodes.empty());
          check_same_nodes(c.nodes, root_exact.nodes);
          CHECK(finite_nodes(c.nodes));
          const TracerCurve<double> curve(c.snapped.train);
          for (const Cusp& k : c.cusps) CHECK(curve.velocity(k.param).norm() <= 1e-11);
        }
      }
}

TEST_CASE("census: pole_node with 3 branches: n = 3, a2 = a3 = pi/3 has 7 node points from 9 crossing pairs",
          "[census][hard][pole_node][multi_branch]") {
  const GearTrain train(kPi / 3, kPi / 3, Ratio(3));
  const Classification c = classify(train);
  REQUIRE(c.nodes.size() == 7);
  CHECK(c.crossings == 7);
  std::size_t pairs = 0;
  for (const Node& n : c.nodes) pairs += n.crossing_pairs + n.tangency_pairs;
  CHECK(pairs == 9);
  const Node* pole = nearest(c.nodes, Vector3d(0, 0, 1));
  CHECK((pole->position - Vector3d(0, 0, 1)).norm() <= 1e-12);
  CHECK(pole->branches == 3);
  CHECK(pole->crossing_pairs == 3);
  // a3 = a2: z = 1 where theta3 = 3 theta2 = pi (mod 2 pi): theta2 = pi/3, pi, 5 pi/3 (Eq. 3).
  REQUIRE(pole->params.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(pole->params[k] - kPi * (2 * k + 1) / 3) <= 1e-9);
  for (const Node& n : c.nodes)
    if (&n != pole) CHECK(n.branches == 2);
  check_same_nodes(c.polyline.nodes, c.root.nodes);
  check_on_curve(c.snapped.train, c.nodes, 1e-12);
}

TEST_CASE("census: pole_node with 4 branches: n = 4, a2 = a3 = pi/3 has 9 node points from 14 pairs",
          "[census][hard][pole_node][multi_branch]") {
  const GearTrain train(kPi / 3, kPi / 3, Ratio(4));
  const Classification c = classify(train);
  REQUIRE(c.nodes.size() == 9);
  std::size_t pairs = 0;
  for (const Node& n : c.nodes) pairs += n.crossing_pairs + n.tangency_pairs;
  CHECK(pairs == 14);
  const Node* pole = nearest(c.nodes, Vector3d(0, 0, 1));
  CHECK((pole->position - Vector3d(0, 0, 1)).norm() <= 1e-12);
  CHECK(pole->branches == 4);
  // Branches k, l at the pole are turned by 2 pi (l - k) / 4: opposite ones (a half turn) have the
  // same tangent line and touch, the others cross: 4 crossing + 2 touching pairs, kind crossing.
  CHECK(pole->crossing_pairs == 4);
  CHECK(pole->tangency_pairs == 2);
  CHECK(pole->kind == NodeKind::crossing);
  check_same_nodes(c.polyline.nodes, c.root.nodes);
  check_on_curve(c.snapped.train, c.nodes, 1e-12);
}

TEST_CASE("census: samples_landing_on_node: n = 1, a2 = a3 = pi/2 with 1024 samples hits theta2 = pi/2, 3 pi/2",
          "[census][hard][samples_on_node]") {
  const GearTrain train(kPi / 2, kPi / 2, Ratio(1));
  for (std::size_t samples : {1024u, 2048u, 4096u, 1000u}) {
    INFO("samples = " << samples);
    PolylineCensusSettings s;
    s.samples = samples;
    // The sample theta2 = 2 pi * 256 / 1024 is pi/2 (to rounding): a polyline vertex on the node.
    const PolylineCensus c = polyline_census(train, s);
    REQUIRE(c.nodes.size() == 1);
    const Node& n = c.nodes.front();
    CHECK((n.position - Vector3d(0, 1, 0)).norm() <= 1e-13);  // Eq. 25 with a3 = pi/2
    CHECK(n.branches == 2);
    CHECK(n.kind == NodeKind::crossing);
    REQUIRE(n.params.size() == 2);
    CHECK(std::abs(n.params[0] - kPi / 2) <= 1e-12);
    CHECK(std::abs(n.params[1] - 3 * kPi / 2) <= 1e-12);
  }
}

// With a2 or a3 within 1e-6 of 0 or pi the curve is nearly a multiply covered circle (a2 -> 0:
// P -> Rz((1 + n) t) Rx(a3) z) or a tiny curve: many near-tangent branches. Where the input sits
// on two boundaries at once within the tolerance (n = 2, a2 = a3 = pi - 1e-6 is on a3 = a2 and on
// a3 = pi - a_p, which the exact model cannot both satisfy), the censuses may differ, and the
// classification must then say so instead of hiding it.
TEST_CASE("census: angles_near_0_or_pi within 1e-6: no NaN, polyline census equals root census",
          "[census][hard][degenerate_angles]") {
  const double e = 1e-6;
  const std::vector<std::pair<double, double>> angles{{e, 1.0},       {kPi - e, 1.0}, {1.0, e},          {1.0, kPi - e},
                                                      {e, kPi / 2},   {kPi / 2, e},   {kPi - e, kPi - e}, {2.0, kPi - e}};
  for (const Ratio& n : {Ratio(1), Ratio(2), Ratio(3), Ratio(5, 2), Ratio(-2)})
    for (const auto& [a2, a3] : angles) {
      INFO("n = " << n.str() << ", a2 = " << a2 << ", a3 = " << a3);
      const GearTrain train(a2, a3, n);
      const Classification c = classify(train);
      CHECK(finite_nodes(c.nodes));
      CHECK(finite_nodes(c.root.nodes));
      for (const Node& nd : c.nodes) CHECK(nd.branches >= 2);  // a node is two or more branches
      if (c.snapped.hits.size() >= 2) {  // several boundaries at once: disagreement must be reported
        CHECK(c.agreement.censuses_agree == c.agreement.notes.empty());
        continue;
      }
      check_same_nodes(c.polyline.nodes, c.root.nodes);
      if (n == Ratio(2)) {  // Table 1 logic: 2 per strictly satisfied Eq. 43 / Eq. 46 (none of these on a boundary)
        const double ap = std::atan2(std::sin(a2), std::cos(a2) + 2);
        const bool eq43 = ap < a3 && a3 < kPi - a2, eq46 = a2 < a3 && a3 < kPi - ap;
        if (std::abs(a3 - a2) > 1e-3 && std::abs(a3 - (kPi - a2)) > 1e-3 && std::abs(a3 - ap) > 1e-3 &&
            std::abs(a3 - (kPi - ap)) > 1e-3)
          CHECK(c.nodes.size() == 2u * eq43 + 2u * eq46);
      }
      for (const Cusp& k : c.cusps) CHECK(k.position.allFinite());
      if (n == Ratio(1)) {  // Eq. 24 (none of these is within 1e-3 of a2/2 or pi - a2/2)
        const bool eq24 = a2 / 2 < a3 && a3 < kPi - a2 / 2;
        CHECK(c.nodes.size() == (eq24 ? 1u : 0u));
      }
    }
}

TEST_CASE("census: distinct_branches groups a node's parameters independently of their order", "[census][assembly]") {
  const double period = 4 * kPi;
  // One branch met at three points 1e-9 apart (a chain: the ends are 2e-9 apart), a second
  // branch, and a third one straddling the period's end.
  std::vector<double> ts{1.0, 1.0 + 1e-9, 1.0 + 2e-9, 2.5, period - 1e-9, 1e-9};
  const std::vector<double> expected{1.0, 2.5, period - 1e-9};
  for (int k = 0; k < 6; ++k) {
    std::rotate(ts.begin(), ts.begin() + 1, ts.end());
    CHECK(distinct_branches(ts, period) == expected);
    std::vector<double> reversed(ts.rbegin(), ts.rend());
    CHECK(distinct_branches(reversed, period) == expected);
  }
  CHECK(distinct_branches({1.0, 1.0 + 1e-5}, period).size() == 2u);  // a near-cusp loop's two branches
}

TEST_CASE("census: near_pole_cluster: |p| branches passing within 1e-9 .. 1e-5 of a pole, both censuses agree",
          "[census][hard][pole]") {
  // a3 = a2 + d (or pi - a2 + d): the tracer circle misses the pole by |d|; the |p| passes near
  // it cross pairwise at points ~|d| apart, at the scale of the node merge distance (1e-9). Whatever
  // the grouping at that scale, the two censuses must group the same pairs into the same nodes.
  // Even |p|: passes k and k + |p|/2 run antiparallel on either side of the pole and cross twice,
  // ~sqrt(|d|) apart: a lens within one pair of polyline edges (at d = 1e-6 the polyline shows
  // one crossing or none; Newton alone found one of the two).
  for (const Ratio& n : {Ratio(-7, 2), Ratio(-7, 4), Ratio(-7, 5), Ratio(5, 3), Ratio(3), Ratio(-4), Ratio(6), Ratio(4, 3)})
    for (const A3Reference ref : {A3Reference::a2, A3Reference::pi_minus_a2})
      for (const double d : {1e-9, -1e-9, 3e-9, -3e-9, 1e-8, -1e-7, 1e-6, -1e-6, 1e-5})
        for (const double a2 : {0.712459, 1.310113, 1.749942, 2.591109}) {
          INFO("n = " << n.str() << ", a2 = " << a2 << ", a3 = " << to_string(ref) << " + " << d);
          const Classification c = classify(GearTrain::on_cone(a2, ref, d, n));
          check_same_nodes(c.polyline.nodes, c.root.nodes);
          CHECK(c.agreement.censuses_agree);
          for (const Node& nd : c.nodes) CHECK(nd.branches >= 2);
        }
}

TEST_CASE("census: sample_count_doubling leaves the node set unchanged", "[census][hard][resolution]") {
  struct Case {
    double a2, a3;
    Ratio n;
  };
  const std::vector<Case> cases{{kPi / 3, kPi / 2, Ratio(2)}, {kPi / 3, kPi / 3, Ratio(3)}, {1.0, 1.3, Ratio(7, 3)},
                                {2.0, 2.4, Ratio(13, 5)},     {kPi / 2, kPi / 2, Ratio(2)}, {0.7, 2.2, Ratio(4)}};
  for (const Case& k : cases) {
    const GearTrain train = snap_to_boundaries(GearTrain(k.a2, k.a3, k.n)).train;
    INFO("n = " << k.n.str() << ", a2 = " << k.a2 << ", a3 = " << k.a3);
    PolylineCensusSettings s;
    s.samples = census_sample_count(train);
    const PolylineCensus base = polyline_census(train, s);
    for (int doubling = 1; doubling <= 2; ++doubling) {
      s.samples *= 2;
      check_same_nodes(base.nodes, polyline_census(train, s).nodes);
    }
  }
}

TEST_CASE("census: literal_row_g: a2 + a3 = pi - 3.4e-16 splits the pole tangency into two crossings 4e-8 apart",
          "[census][hard][literal][tangency]") {
  const GearTrain train(kPi / 3, 2 * kPi / 3, Ratio(2));
  // The doubles: a2 + a3 falls short of pi by e (long double arithmetic, exact for these).
  const long double e = Constants<long double>::pi() - (static_cast<long double>(train.a2()) + train.a3());
  REQUIRE(e > 0);
  REQUIRE(e < 1e-15L);
  ClassifySettings s;
  s.reading.literal = true;
  const Classification c = classify(train, s);
  REQUIRE(c.nodes.size() == 4);
  CHECK(c.crossings == 4);
  CHECK(c.tangencies == 0);
  CHECK(count_kind(c.nodes, NodeKind::crossing) == 4);
  check_same_nodes(c.polyline.nodes, c.root.nodes);
  std::vector<const Node*> polar;
  for (const Node& n : c.nodes)
    if ((n.position - Vector3d(0, 0, -1)).norm() < 1e-6) polar.push_back(&n);
  REQUIRE(polar.size() == 2);
  // A tangency moved off its boundary by e splits into crossings ~sqrt(e) apart (sqrt(3.4e-16) =
  // 1.8e-8); the factor between is O(1).
  const double gap = (polar[0]->position - polar[1]->position).norm();
  CHECK(gap > 0.5 * std::sqrt(static_cast<double>(e)));
  CHECK(gap < 10 * std::sqrt(static_cast<double>(e)));
  // The other two are the Eq. 44b crossings on x = 0 (Eq. 46 holds strictly).
  for (const Node& n : c.nodes)
    if (&n != polar[0] && &n != polar[1]) CHECK(std::abs(n.position.x()) <= 1e-13);
  check_on_curve(train, c.nodes, 1e-12);
  // Default reading: the same doubles are row (g) of Table 1.
  const Classification d = classify(train);
  CHECK(d.nodes.size() == 3);
  CHECK(d.tangencies == 1);
}

namespace {
/// Fig. 5(f) node of Eq. 39b in Scalar: sin^2 theta2 = s(a2 + a3) / (2 s a3 (1 + c a2)) = 1/6
/// for a2 = pi/3, a3 = pi/2; theta2 = asin(sqrt(1/6)) and pi - that.
template <typename Scalar>
void check_refine_scalar(double tol, const char* name) {
  using std::abs;
  using std::asin;
  using std::sqrt;
  const GearTrain train(kPi / 3, kPi / 2, Ratio(2));
  const TracerCurve<Scalar> curve(train);
  const Scalar pi = Constants<Scalar>::pi();
  // The doubles a2, a3 are not exactly pi/3, pi/2: evaluate Eq. 39b with the curve's own sin/cos.
  const auto tr = train.trig<Scalar>();
  const Scalar s_sum = tr.sin_a2 * tr.cos_a3 + tr.cos_a2 * tr.sin_a3;  // s(a2 + a3)
  const Scalar t1_exact = asin(sqrt(s_sum / (Scalar(2) * tr.sin_a3 * (Scalar(1) + tr.cos_a2))));
  const Scalar t2_exact = pi - t1_exact;
  const RefinedPair<Scalar> r = refine_branch_pair(curve, Scalar(0.43), Scalar(2.70));
  INFO(name);
  CHECK(r.status == RefineStatus::converged);
  CHECK(static_cast<double>(abs(Scalar(r.t1 - t1_exact))) <= tol);
  CHECK(static_cast<double>(abs(Scalar(r.t2 - t2_exact))) <= tol);
  CHECK(static_cast<double>(r.residual) <= tol);
}
}  // namespace

TEST_CASE("census: every_scalar_type: refine_branch_pair<float, double, long double, mpreal> reaches the Eq. 39b node",
          "[census][scalar][refinement]") {
  mpfr::mpreal::set_default_prec(256);
  check_refine_scalar<float>(2e-6, "float");
  check_refine_scalar<double>(1e-14, "double");
  check_refine_scalar<long double>(1e-17, "long double");
  check_refine_scalar<mpfr::mpreal>(1e-70, "mpreal 256 bits");
}

TEST_CASE("census: large_ratio 101/40 (thousands of nodes): both censuses agree", "[census][hard][large_ratio]") {
  const GearTrain train(1.1, 1.4, Ratio(101, 40));
  const auto start = std::chrono::steady_clock::now();
  const PolylineCensus poly = polyline_census(train);
  const RootCensus root = root_census(train);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO("seconds: " << seconds);
  CHECK(poly.nodes.size() >= 101);
  CHECK(poly.nodes.size() % 101 == 0);  // |p|-fold symmetry: nodes come in orbits of 101
  check_same_nodes(poly.nodes, root.nodes);
  check_on_curve(train, poly.nodes, 1e-11);
  CHECK(finite_nodes(poly.nodes));
}
