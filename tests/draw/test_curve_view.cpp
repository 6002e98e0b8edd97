// tests/draw/test_curve_view.cpp — the view chosen from the curve (draw/curve_view.hpp) and the
// marker rule (draw/mark_density.hpp), against curves whose best view is known in closed form and
// the report's curves written out from Eq. 4 with Eigen's rotations.
#include "catch2/catch.hpp"

#include "sphtroch/draw/curve_view.hpp"
#include "sphtroch/draw/mark_density.hpp"
#include "sphtroch/draw/svg_plot.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = 3.14159265358979323846;

/// A closed small circle of angular radius rho about the unit vector c, n points.
std::vector<Vector3d> small_circle(const Vector3d& c, double rho, int n) {
  const Vector3d u = c.unitOrthogonal(), v = c.cross(u);
  std::vector<Vector3d> pts;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    pts.push_back(std::cos(rho) * c + std::sin(rho) * (std::cos(t) * u + std::sin(t) * v));
  }
  return pts;
}

/// Eq. 4 written out: P = Rz(t) Rx(a2) Rz(p t / q) Rx(a3) z over one period 2 pi q, n points.
std::vector<Vector3d> eq4_curve(double a2, double a3, int p, int q, int n) {
  std::vector<Vector3d> pts;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * q * i / n;
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(t, Vector3d::UnitZ()) * Eigen::AngleAxisd(a2, Vector3d::UnitX()) *
                               Eigen::AngleAxisd(p * t / q, Vector3d::UnitZ()) * Eigen::AngleAxisd(a3, Vector3d::UnitX()))
                                  .toRotationMatrix();
    pts.push_back(r * Vector3d::UnitZ());
  }
  return pts;
}

/// The share of the closed polyline's length on the front half for `view`, by its own sum (chord
/// lengths, split at the plane by linear interpolation along the chord).
double front_share_of(const std::vector<Vector3d>& pts, const Vector3d& view) {
  double front = 0, total = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vector3d& a = pts[i];
    const Vector3d& b = pts[(i + 1) % pts.size()];
    const double len = (b - a).norm(), da = a.dot(view), db = b.dot(view);
    total += len;
    if (da >= 0 && db >= 0) front += len;
    else if (da > 0 || db > 0) front += len * std::fmax(da, db) / std::fabs(da - db);
  }
  return front / total;
}

Trajectory<double> closed_trajectory(const std::vector<Vector3d>& pts) {
  Trajectory<double> tr;
  tr.closed = true;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    tr.t.push_back(static_cast<double>(i));
    tr.points.push_back(pts[i]);
  }
  return tr;
}

}  // namespace

TEST_CASE("view_of_curve: a small circle is seen from its centre, all of it in front", "[curve_view]") {
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(-1, 1), rho(0.1, 1.5);
  for (int k = 0; k < 50; ++k) {
    Vector3d c(u(rng), u(rng), u(rng));
    if (c.norm() < 0.1) continue;
    c.normalize();
    const CurveView v = view_of_curve(small_circle(c, rho(rng), 400), true);
    INFO("centre " << c.transpose());
    CHECK((v.direction - c).norm() < 1e-12);
    CHECK(v.front_share == 1.0);
    CHECK(v.reason == "mean direction of the curve");
  }
}

TEST_CASE("view_of_curve: a great circle is seen face-on, along its normal", "[curve_view]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 50; ++k) {
    Vector3d normal(u(rng), u(rng), u(rng));
    if (normal.norm() < 0.1) continue;
    normal.normalize();
    const CurveView v = view_of_curve(small_circle(normal, kPi / 2, 360), true);
    INFO("normal " << normal.transpose());
    CHECK(v.direction.cross(normal).norm() < 1e-9);
    CHECK(v.front_share == 1.0);
    CHECK(v.reason == "a principal axis of the curve");
  }
}

TEST_CASE("view_of_curve: the README's n = 13/5 example and Fig. 3 show at least 80% of their length in front",
          "[curve_view]") {
  struct Case {
    double a2, a3;
    int p, q;
  };
  // (Not every curve can: Fig. 5(f), n = 2 at a3 = pi/2, is symmetric about the centre.)
  for (const Case c : {Case{0.7, 2.5, 13, 5}, Case{kPi / 2, kPi / 2, 1, 1}, Case{0.5, 0.4, 3, 1}}) {
    const CurveView v = view_of_curve(eq4_curve(c.a2, c.a3, c.p, c.q, 4000 * c.q), true);
    const double share = front_share_of(eq4_curve(c.a2, c.a3, c.p, c.q, 40000 * c.q), v.direction);
    INFO("n = " << c.p << "/" << c.q << ", a2 = " << c.a2 << ", a3 = " << c.a3 << ", view " << v.direction.transpose());
    CHECK(share >= 0.8);
    CHECK(std::fabs(share - v.front_share) < 1e-3);
  }
}

TEST_CASE("view_of_curve: never worse than the fixed view by more than the slack", "[curve_view]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0.05, kPi - 0.05);
  std::uniform_int_distribution<int> pq(1, 7);
  const Vector3d fixed = Vector3d(1, 0.6, 0.5).normalized();
  for (int k = 0; k < 40; ++k) {
    const double a2 = angle(rng), a3 = angle(rng);
    const int p = pq(rng) * (k % 2 ? 1 : -1), q = pq(rng);
    const std::vector<Vector3d> pts = eq4_curve(a2, a3, p, q, 2000 * q);
    const CurveView v = view_of_curve(pts, true);
    INFO("n = " << p << "/" << q << ", a2 = " << a2 << ", a3 = " << a3);
    CHECK(std::fabs(v.direction.norm() - 1) < 1e-15);
    CHECK(front_share_of(pts, v.direction) >= front_share_of(pts, fixed) - kFrontShareSlack - 1e-3);
  }
}

TEST_CASE("view_of_curve: equal second moments give axes fixed by the rule, not by rounding", "[curve_view]") {
  // Fig. 5(f) (n = 2, a2 = pi/3, a3 = pi/2): balanced about the centre, equal moments about X and Y.
  // Every view shows half of it; the first candidate is the projection of (1, 0.6, 0.5) onto XY.
  const CurveView v = view_of_curve(eq4_curve(kPi / 3, kPi / 2, 2, 1, 3000), true);
  CHECK((v.direction - Vector3d(1, 0.6, 0).normalized()).norm() < 1e-9);
  CHECK(v.front_share == Approx(0.5).margin(1e-6));
}

TEST_CASE("view_of_curve: a view along Z puts +X to the right, as the top view", "[curve_view]") {
  const CurveView v = view_of_curve(small_circle(Vector3d::UnitZ(), 0.3, 100), true);
  CHECK(v.elevation() == Approx(kPi / 2));
  CHECK(v.azimuth() == Approx(-kPi / 2));
}

TEST_CASE("render: the picture states its view, chosen from the curve unless one is set", "[curve_view][render]") {
  const std::vector<Vector3d> cap = small_circle(Vector3d(0, 0, -1), 0.4, 200);
  PlotOptions opt;
  const std::string chosen = render_sphere_svg(closed_trajectory(cap), {}, {}, opt);
  CHECK(chosen.find(">view from az -90 deg, el -90 deg (mean direction of the curve)</text>") != std::string::npos);
  set_plot_view(opt, "front");
  const std::string front = render_sphere_svg(closed_trajectory(cap), {}, {}, opt);
  CHECK(front.find(">view from az -90 deg, el 0 deg</text>") != std::string::npos);
  set_plot_view(opt, "auto");
  CHECK(opt.view_from_curve);
}

TEST_CASE("markers: automatic draws up to kAutoMarkLimit marks, none above, and says so", "[curve_view][markers]") {
  CHECK(choose_marks(MarkMode::automatic, kAutoMarkLimit, 0).draw);
  CHECK(choose_marks(MarkMode::automatic, kAutoMarkLimit - 3, 3).draw);
  CHECK(choose_marks(MarkMode::automatic, kAutoMarkLimit, 0).note.empty());
  const MarkChoice dense = choose_marks(MarkMode::automatic, 26602, 0);
  CHECK_FALSE(dense.draw);
  CHECK(dense.note == "26602 node and cusp markers hidden (more than 200)");
  CHECK(choose_marks(MarkMode::all, 26602, 5).draw);
  CHECK(choose_marks(MarkMode::none, 3, 1).note == "4 node and cusp markers hidden");
  CHECK(choose_marks(MarkMode::none, 0, 0).note.empty());
  CHECK(dense_curve(kAutoMarkLimit + 1, 0));
  CHECK_FALSE(dense_curve(kAutoMarkLimit, 0));
  CHECK(parse_mark_mode("all") == MarkMode::all);
  CHECK_THROWS_AS(parse_mark_mode("some"), InvalidInput);

  // In the picture: rings drawn for 200 nodes; none, no node legend and the note for 201.
  const std::vector<Vector3d> curve = small_circle(Vector3d::UnitZ(), 1.0, 400);
  for (const std::size_t count : {kAutoMarkLimit, kAutoMarkLimit + 1}) {
    std::vector<Node> nodes(count);
    for (std::size_t i = 0; i < count; ++i) nodes[i].position = curve[i];
    const std::string svg = render_sphere_svg(closed_trajectory(curve), nodes, {}, PlotOptions{});
    const std::size_t group = svg.find("id=\"nodes\"");
    const bool drawn = count <= kAutoMarkLimit;
    INFO(count << " nodes");
    CHECK((group != std::string::npos) == drawn);
    CHECK((svg.find(">node (crossing)</text>") != std::string::npos) == drawn);
    CHECK((svg.find("markers hidden (more than 200)") != std::string::npos) == !drawn);
  }
}
