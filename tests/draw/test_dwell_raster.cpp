// tests/draw/test_dwell_raster.cpp — the density view's raster (draw/dwell_raster.hpp) against
// counts made here and a uniform distribution of known density 1/(4 pi) per steradian, and the
// density picture of svg_plot.hpp (contract 7).
#include "catch2/catch.hpp"

#include "sphtroch/draw/dwell_raster.hpp"
#include "sphtroch/draw/svg_plot.hpp"

#include <cmath>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = 3.14159265358979323846;

/// n points spread evenly over the sphere (the golden-angle spiral: equal area per point).
std::vector<Vector3d> even_sphere(int n) {
  std::vector<Vector3d> pts;
  const double golden = kPi * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z);
    pts.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return pts;
}

}  // namespace

TEST_CASE("dwell_raster: the shares sum to the front half's share of the samples", "[dwell]") {
  const Vector3d view = Vector3d(1, 0.6, 0.5).normalized();
  const Vector3d right = Vector3d::UnitZ().cross(view).normalized(), up = view.cross(right);
  const std::vector<Vector3d> pts = even_sphere(10001);
  std::size_t front = 0;
  for (const Vector3d& p : pts) front += p.dot(view) >= 0 ? 1 : 0;
  const DwellRaster r = dwell_raster(pts, view, right, up, 32);
  double sum = 0;
  for (double t : r.time) sum += t;
  CHECK(sum == Approx(static_cast<double>(front) / 10001).epsilon(1e-12));
}

TEST_CASE("dwell_raster: a uniform dwell is 1/(4 pi) per steradian in every cell well inside the disc", "[dwell]") {
  const std::vector<Vector3d> pts = even_sphere(2000000);
  const DwellRaster r = dwell_raster(pts, Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ(), 16);
  int checked = 0;
  for (std::size_t row = 0; row < 16; ++row)
    for (std::size_t col = 0; col < 16; ++col) {
      const double x = r.centre_x(col), y = r.centre_y(row);
      if (x * x + y * y > 0.6) continue;  // first order in the cell size: away from the rim
      INFO("cell " << col << ", " << row);
      CHECK(r.density(col, row) == Approx(1 / (4 * kPi)).epsilon(0.05));
      ++checked;
    }
  CHECK(checked > 100);
}

TEST_CASE("dwell_raster: a point goes to the cell holding its projection, rows from the top", "[dwell]") {
  // Seen from +X: right = +Y, up = +Z. (0, 0.3, 0.9) projects to (0.3, 0.9): 8 cells per side of
  // width 0.25 -> column floor((0.3 + 1) / 0.25) = 5, row from the top 7 - floor((0.9 + 1) / 0.25) = 0.
  const Vector3d p = Vector3d(std::sqrt(1 - 0.09 - 0.81), 0.3, 0.9);
  const Vector3d back = Vector3d(-1, 0, 0);
  const DwellRaster r = dwell_raster({p, back}, Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ(), 8);
  CHECK(r.time[r.index(5, 0)] == 0.5);  // one of two samples; the other is behind
  double sum = 0;
  for (double t : r.time) sum += t;
  CHECK(sum == 0.5);
  CHECK_THROWS_AS(dwell_raster({p}, Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ(), 3), InvalidInput);
  CHECK_THROWS_AS(dwell_raster({p}, Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ(), 513), InvalidInput);
}

TEST_CASE("render: the density style draws the dwell cells instead of the curve's lines", "[dwell][render]") {
  Trajectory<double> tr;
  for (const Vector3d& p : even_sphere(5000)) {
    tr.t.push_back(static_cast<double>(tr.t.size()));
    tr.points.push_back(p);
  }
  PlotOptions opt;
  opt.style = PlotStyle::density;
  const std::string svg = render_sphere_svg(tr, {}, {}, opt);
  CHECK(svg.find("id=\"dwell\" clip-path=\"url(#disc)\"") != std::string::npos);
  CHECK(svg.find(">time per sr: 0</text>") != std::string::npos);
  CHECK(svg.find("the back half not shown") != std::string::npos);
  CHECK(svg.find(">front</text>") == std::string::npos);
  CHECK(parse_plot_style("curve") == PlotStyle::curve);
  CHECK_THROWS_AS(parse_plot_style("heat"), InvalidInput);
}
