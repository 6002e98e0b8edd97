// Tests for sphtroch/draw/svg.hpp (SvgWriter, SvgPath, numbers, escaping) and sphtroch/draw/svg_plot.hpp
// (projection, front/back split at the silhouette, markers, caption, well-formed output).
#include "catch2/catch.hpp"

#include "sphtroch/draw/svg.hpp"
#include "sphtroch/draw/svg_plot.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();

// --- a tiny well-formedness checker: tags balanced, attributes quoted, no raw & or < in text ---
struct XmlCheck {
  bool ok = true;
  std::string error;
  std::string root;
};

bool valid_entity_at(const std::string& s, std::size_t i) {
  static const char* entities[] = {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"};
  for (const char* e : entities)
    if (s.compare(i, std::char_traits<char>::length(e), e) == 0) return true;
  return false;
}

bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' || c == '.';
}

XmlCheck check_xml(const std::string& s) {
  XmlCheck r;
  auto fail = [&](const std::string& why, std::size_t at) {
    if (r.ok) r.error = why + " at offset " + std::to_string(at);
    r.ok = false;
  };
  std::vector<std::string> stack;
  std::size_t i = 0;
  bool seen_root = false;
  while (i < s.size() && r.ok) {
    const char c = s[i];
    if (c == '&') {
      if (!valid_entity_at(s, i)) fail("raw & in text", i);
      ++i;
      continue;
    }
    if (c == '>') {
      fail("raw > outside a tag", i);
      break;
    }
    if (c != '<') {
      if (stack.empty() && !std::isspace(static_cast<unsigned char>(c))) fail("text outside the root", i);
      ++i;
      continue;
    }
    if (s.compare(i, 5, "<?xml") == 0) {
      if (i != 0) fail("XML declaration not at the start", i);
      const std::size_t end = s.find("?>", i);
      if (end == std::string::npos) fail("unterminated declaration", i);
      i = end + 2;
      continue;
    }
    if (s.compare(i, 4, "<!--") == 0) {
      const std::size_t end = s.find("-->", i);
      if (end == std::string::npos) fail("unterminated comment", i);
      i = end + 3;
      continue;
    }
    const bool closing = i + 1 < s.size() && s[i + 1] == '/';
    std::size_t j = i + (closing ? 2 : 1);
    const std::size_t name_start = j;
    while (j < s.size() && is_name_char(s[j])) ++j;
    const std::string name = s.substr(name_start, j - name_start);
    if (name.empty()) {
      fail("tag without a name", i);
      break;
    }
    if (closing) {
      while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      if (j >= s.size() || s[j] != '>') {
        fail("malformed end tag", i);
        break;
      }
      if (stack.empty() || stack.back() != name) {
        fail("end tag </" + name + "> does not match " + (stack.empty() ? "nothing" : "<" + stack.back() + ">"), i);
        break;
      }
      stack.pop_back();
      i = j + 1;
      continue;
    }
    // attributes: name="value" ... then > or />
    bool self_closing = false;
    while (true) {
      while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      if (j >= s.size()) {
        fail("unterminated tag", i);
        break;
      }
      if (s[j] == '>') {
        ++j;
        break;
      }
      if (s[j] == '/' && j + 1 < s.size() && s[j + 1] == '>') {
        self_closing = true;
        j += 2;
        break;
      }
      const std::size_t an = j;
      while (j < s.size() && is_name_char(s[j])) ++j;
      if (j == an || j >= s.size() || s[j] != '=') {
        fail("malformed attribute in <" + name + ">", j);
        break;
      }
      ++j;
      if (j >= s.size() || (s[j] != '"' && s[j] != '\'')) {
        fail("unquoted attribute in <" + name + ">", j);
        break;
      }
      const char q = s[j++];
      while (j < s.size() && s[j] != q) {
        if (s[j] == '<') fail("< inside an attribute", j);
        if (s[j] == '&' && !valid_entity_at(s, j)) fail("raw & inside an attribute", j);
        ++j;
      }
      if (j >= s.size()) {
        fail("unterminated attribute value", an);
        break;
      }
      ++j;
    }
    if (!r.ok) break;
    if (stack.empty()) {
      if (seen_root) fail("second root element <" + name + ">", i);
      seen_root = true;
      r.root = name;
    }
    if (!self_closing) stack.push_back(name);
    i = j;
  }
  if (r.ok && !stack.empty()) fail("unclosed <" + stack.back() + ">", s.size());
  if (r.ok && !seen_root) fail("no root element", 0);
  return r;
}

/// Count non-overlapping occurrences of `needle`.
std::size_t count_of(const std::string& hay, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = hay.find(needle); at != std::string::npos; at = hay.find(needle, at + needle.size())) ++n;
  return n;
}

/// A closed great circle through u and v (orthonormal), n points.
std::vector<Vector3d> great_circle(const Vector3d& u, const Vector3d& v, int n) {
  std::vector<Vector3d> pts;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    pts.push_back(std::cos(t) * u + std::sin(t) * v);
  }
  return pts;
}

Trajectory<double> trajectory_of(const std::vector<Vector3d>& pts, bool closed) {
  Trajectory<double> tr;
  tr.closed = closed;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    tr.t.push_back(static_cast<double>(i));
    tr.points.push_back(pts[i]);
  }
  return tr;
}

/// The report's Fig. 3 curve (n = 1, a2 = a3 = pi/2) from Eq. 4 written out, so that these
/// tests do not depend on the curve header: P = Rz(t) Rx(a2) Rz(t) Rx(a3) z.
std::vector<Vector3d> fig3_curve(int n) {
  std::vector<Vector3d> pts;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(t, Vector3d::UnitZ()) * Eigen::AngleAxisd(kPi / 2, Vector3d::UnitX()) *
                               Eigen::AngleAxisd(t, Vector3d::UnitZ()) * Eigen::AngleAxisd(kPi / 2, Vector3d::UnitX()))
                                  .toRotationMatrix();
    pts.push_back(r * Vector3d::UnitZ());
  }
  return pts;
}

double angle_between(const Vector3d& a, const Vector3d& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

}  // namespace

// --------------------------------------------------------------------------------------------
// svg.hpp
// --------------------------------------------------------------------------------------------

TEST_CASE("svg_number: fixed, limited precision, no trailing zeros, no -0", "[svg]") {
  CHECK(svg_number(12.5) == "12.5");
  CHECK(svg_number(3.0) == "3");
  CHECK(svg_number(-0.25) == "-0.25");
  CHECK(svg_number(1.23456) == "1.23");
  CHECK(svg_number(1.235, 3) == "1.235");
  CHECK(svg_number(-0.001) == "0");
  CHECK(svg_number(-0.0) == "0");
  CHECK(svg_number(1e-7, 2) == "0");
  CHECK(svg_number(250.0, 0) == "250");
  CHECK(svg_number(99.996) == "100");
  CHECK(svg_number(123456789.0) == "123456789");
}

TEST_CASE("xml_escape replaces the five special characters", "[svg]") {
  CHECK(xml_escape("a < b & c > \"d\" 'e'") == "a &lt; b &amp; c &gt; &quot;d&quot; &apos;e&apos;");
  CHECK(xml_escape("plain pi/2") == "plain pi/2");
  CHECK(xml_escape("") == "");
}

TEST_CASE("SvgPath: one M per subpath, shared L, vertices that round together dropped", "[svg]") {
  SvgPath d(2);
  d.move_to(1, 2);
  d.line_to(3.004, 4);
  d.line_to(3.001, 4.002);  // rounds to the previous vertex: dropped
  d.line_to(5, 6);
  d.move_to(10.5, -1);
  d.line_to(11, -2);
  d.close();
  CHECK(d.str() == "M1 2L3 4 5 6M10.5 -1L11 -2Z");
  CHECK(d.subpaths() == 2);
}

TEST_CASE("SvgWriter: declaration, namespace, escaped text, balanced groups", "[svg]") {
  SvgWriter w(200, 100);
  w.title("t < 1 & u");
  w.begin_group("stroke:red");
  w.begin_group();
  w.circle(10, 20, 5, "fill:none");
  w.rect(0, 0, 200, 100, "fill:#fff");
  w.line(0, 0, 1.239, 2, "stroke:#000");
  w.text(5, 6, "x<y", "font-size:10px", "middle");
  w.path(std::string_view(""), "fill:none");  // empty: no element
  const std::string doc = w.finish();          // closes both groups
  CHECK(doc.rfind("<?xml version=\"1.0\"", 0) == 0);
  CHECK(doc.find("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"200\" height=\"100\" "
                 "viewBox=\"0 0 200 100\">") != std::string::npos);
  CHECK(doc.find("<title>t &lt; 1 &amp; u</title>") != std::string::npos);
  CHECK(doc.find(">x&lt;y</text>") != std::string::npos);
  CHECK(doc.find("x2=\"1.24\"") != std::string::npos);
  CHECK(doc.find("<path") == std::string::npos);
  CHECK(count_of(doc, "<g") == 2);
  CHECK(count_of(doc, "</g>") == 2);
  const XmlCheck x = check_xml(doc);
  INFO(x.error);
  CHECK(x.ok);
  CHECK(x.root == "svg");
}

TEST_CASE("the XML checker itself rejects broken documents", "[svg]") {
  CHECK(check_xml("<svg><g></svg>").ok == false);
  CHECK(check_xml("<svg><text>a & b</text></svg>").ok == false);
  CHECK(check_xml("<svg><text>a < b</text></svg>").ok == false);
  CHECK(check_xml("<svg width=3></svg>").ok == false);
  CHECK(check_xml("<svg></svg><svg></svg>").ok == false);
  CHECK(check_xml("<svg a=\"x&y\"/>").ok == false);
  CHECK(check_xml("<svg a=\"x&amp;y\"><g/></svg>").ok == true);
}

// --------------------------------------------------------------------------------------------
// svg_plot.hpp: projection
// --------------------------------------------------------------------------------------------

TEST_CASE("the fixed view (azimuth, elevation as PlotOptions sets them) looks from (1, 0.6, 0.5) with Z up",
          "[svg_plot][projection]") {
  const PlotOptions opt;
  const PlotLayout L = plot_layout(opt);
  const SphereView& cam = L.sphere;
  const Vector3d expected = Vector3d(1, 0.6, 0.5).normalized();
  CHECK((cam.view - expected).norm() < 1e-15);
  // An orthonormal right-handed screen frame: right x up = view.
  CHECK(std::fabs(cam.right.dot(cam.up)) < 1e-15);
  CHECK((cam.right.cross(cam.up) - cam.view).norm() < 1e-15);
  CHECK(cam.right.z() == 0.0);  // horizontal: Z stays vertical on screen
  // Z projects straight above the centre (SVG y grows downwards).
  const ScreenPoint z = cam.project(Vector3d::UnitZ());
  CHECK(z.x == Approx(cam.cx).margin(1e-9));
  CHECK(z.y < cam.cy);
  // The picture fits: sphere inside the page.
  CHECK(cam.cx - cam.radius > 0);
  CHECK(cam.cx + cam.radius < L.width);
  CHECK(cam.cy - cam.radius > 0);
  CHECK(cam.cy + cam.radius < L.height);
}

TEST_CASE("projection: the view direction lands on the centre, silhouette points on the outline",
          "[svg_plot][projection]") {
  for (double az : {0.0, 0.5404, 2.0, -2.9}) {
    for (double el : {-1.2, 0.0, 0.405, 1.5707963267948966}) {
      const SphereView cam = SphereView::looking_from(az, el, 250, 200, 180);
      const ScreenPoint c = cam.project(cam.view);
      CHECK(c.x == Approx(250).margin(1e-12));
      CHECK(c.y == Approx(200).margin(1e-12));
      CHECK(c.depth == Approx(1.0));
      CHECK(cam.project(-cam.view).depth == Approx(-1.0));
      // Every unit vector perpendicular to view projects to distance radius from the centre.
      for (int k = 0; k < 12; ++k) {
        const double t = 2 * kPi * k / 12;
        const Vector3d p = std::cos(t) * cam.right + std::sin(t) * cam.up;
        const ScreenPoint s = cam.project(p);
        CHECK(std::hypot(s.x - 250, s.y - 200) == Approx(180).epsilon(1e-14));
        CHECK(std::fabs(s.depth) < 1e-15);
        CHECK(cam.is_front(p));
      }
      // A point on the back half is not on the front.
      CHECK_FALSE(cam.is_front(Vector3d(-cam.view + 0.1 * cam.right).normalized()));
    }
  }
}

TEST_CASE("projection of known points from the +X axis", "[svg_plot][projection]") {
  const SphereView cam = SphereView::looking_from(0.0, 0.0, 100, 100, 50);  // view = +X, right = +Y, up = +Z
  const ScreenPoint y = cam.project(Vector3d::UnitY());
  CHECK(y.x == Approx(150));
  CHECK(y.y == Approx(100));
  const ScreenPoint z = cam.project(Vector3d::UnitZ());
  CHECK(z.x == Approx(100));
  CHECK(z.y == Approx(50));
  const ScreenPoint mid = cam.project(Vector3d(1, 1, 1).normalized());
  CHECK(mid.x == Approx(100 + 50 / std::sqrt(3.0)));
  CHECK(mid.y == Approx(100 - 50 / std::sqrt(3.0)));
}

// --------------------------------------------------------------------------------------------
// svg_plot.hpp: front/back split
// --------------------------------------------------------------------------------------------

TEST_CASE("great circle seen edge-on: one front run, one back run, two crossings on the silhouette",
          "[svg_plot][split]") {
  const Vector3d view = Vector3d(1, 0.6, 0.5).normalized();
  const Vector3d side = view.cross(Vector3d::UnitZ()).normalized();  // in the silhouette plane
  // The circle's plane contains the view direction: it projects onto a diameter.
  for (int n : {7, 8, 360, 1001}) {
    for (double start_turn : {0.0, 0.3, 0.61}) {
      std::vector<Vector3d> pts = great_circle(view, side, n);
      std::rotate(pts.begin(), pts.begin() + static_cast<long>(start_turn * n), pts.end());
      const HemisphereSplit s = split_by_silhouette(pts, true, view, 0.05);
      INFO("n = " << n << ", start " << start_turn);
      REQUIRE(s.front.size() == 1);
      REQUIRE(s.back.size() == 1);
      CHECK(s.silhouette_crossings == 2);
      // The runs meet at their ends, on the silhouette, on the unit sphere.
      for (const auto* run : {&s.front[0], &s.back[0]}) {
        for (const Vector3d* end : {&run->front(), &run->back()}) {
          CHECK(std::fabs(end->dot(view)) < 1e-15);
          CHECK(end->norm() == Approx(1.0).epsilon(1e-15));
        }
      }
      CHECK((s.front[0].front() - s.back[0].back()).norm() < 1e-15);
      CHECK((s.front[0].back() - s.back[0].front()).norm() < 1e-15);
      for (const auto& p : s.front[0]) CHECK(p.dot(view) >= -kSilhouetteTolerance);
      for (const auto& p : s.back[0]) CHECK(p.dot(view) <= kSilhouetteTolerance);
    }
  }
}

TEST_CASE("great circle seen face-on lies on the silhouette: one front run, not chopped by rounding",
          "[svg_plot][split]") {
  const Vector3d view = Vector3d(1, 0.6, 0.5).normalized();
  const Vector3d u = view.cross(Vector3d::UnitZ()).normalized();
  const Vector3d v = view.cross(u);
  const HemisphereSplit s = split_by_silhouette(great_circle(u, v, 3600), true, view, 0.01);
  CHECK(s.front.size() == 1);
  CHECK(s.back.empty());
  CHECK(s.silhouette_crossings == 0);
}

TEST_CASE("tilted great circle: split counts do not depend on where a closed polyline starts",
          "[svg_plot][split]") {
  const Vector3d view = Vector3d(0.2, -0.4, 0.9).normalized();
  const Vector3d u = Vector3d(1, 1, 0).normalized(), v = Vector3d(-0.3, 0.3, 1).normalized();
  const Vector3d w = (v - v.dot(u) * u).normalized();
  for (int start = 0; start < 50; start += 7) {
    auto pts = great_circle(u, w, 50);
    std::rotate(pts.begin(), pts.begin() + start, pts.end());
    const HemisphereSplit s = split_by_silhouette(pts, true, view, 0.5);
    CHECK(s.front.size() == 1);
    CHECK(s.back.size() == 1);
    CHECK(s.silhouette_crossings == 2);
    // Every vertex once (the run through the first point is joined there), and the two
    // crossing points each shared by the two runs that meet there.
    const std::size_t total = s.front[0].size() + s.back[0].size();
    CHECK(total == 50 + 4);
  }
}

TEST_CASE("open polyline: the crossing point is on the arc and on the silhouette", "[svg_plot][split]") {
  const Vector3d view = Vector3d::UnitX();
  const Vector3d a = Vector3d(0.3, 0.5, 0.8).normalized();   // front
  const Vector3d b = Vector3d(-0.2, 0.9, 0.1).normalized();  // back
  const HemisphereSplit s = split_by_silhouette({a, b}, false, view, 0.5);  // arc ~0.9 rad: subdivided
  REQUIRE(s.front.size() == 1);
  REQUIRE(s.back.size() == 1);
  CHECK(s.silhouette_crossings == 1);
  const Vector3d c = s.front[0].back();
  CHECK((c - s.back[0].front()).norm() == 0.0);
  CHECK(std::fabs(c.dot(view)) < 1e-16);
  CHECK(c.norm() == Approx(1.0).epsilon(1e-15));
  // On the great-circle arc between a and b: the angles add up.
  CHECK(angle_between(a, c) + angle_between(c, b) == Approx(angle_between(a, b)).epsilon(1e-14));
  CHECK(s.front[0].front() == a);
  CHECK(s.back[0].back() == b);
}

TEST_CASE("long arcs are subdivided along the great circle", "[svg_plot][split]") {
  const Vector3d a = Vector3d::UnitX(), b = Vector3d(std::cos(1.0), std::sin(1.0), 0);  // 1 rad apart
  const HemisphereSplit s = split_by_silhouette({a, b}, false, Vector3d::UnitZ(), 0.1);
  REQUIRE(s.front.size() == 1);
  CHECK(s.front[0].size() == 11);
  for (std::size_t i = 0; i + 1 < s.front[0].size(); ++i)
    CHECK(angle_between(s.front[0][i], s.front[0][i + 1]) == Approx(0.1).epsilon(1e-12));
  for (const auto& p : s.front[0]) CHECK(std::fabs(p.z()) < 1e-16);
}

TEST_CASE("fig3 curve: the split runs alternate and every crossing is on the outline", "[svg_plot][split]") {
  const SphereView cam = plot_layout(PlotOptions{}).sphere;
  const auto pts = fig3_curve(997);
  const HemisphereSplit s = split_by_silhouette(pts, true, cam.view, 0.01);
  CHECK(s.front.size() == s.back.size());  // a closed curve crosses the silhouette an even number of times
  CHECK(s.silhouette_crossings == 2 * s.front.size());
  CHECK(s.silhouette_crossings >= 2);
  for (const auto& run : s.back) {
    for (const Vector3d* end : {&run.front(), &run.back()}) {
      const ScreenPoint e = cam.project(*end);
      CHECK(std::hypot(e.x - cam.cx, e.y - cam.cy) == Approx(cam.radius).epsilon(1e-12));
    }
  }
  // The sample count does not change the picture's topology.
  const HemisphereSplit s2 = split_by_silhouette(fig3_curve(4001), true, cam.view, 0.01);
  CHECK(s2.silhouette_crossings == s.silhouette_crossings);
}

// --------------------------------------------------------------------------------------------
// svg_plot.hpp: the picture
// --------------------------------------------------------------------------------------------

TEST_CASE("render: node and cusp markers with labels at their projected coordinates", "[svg_plot][render]") {
  PlotOptions opt;
  opt.view_from_curve = false;  // the fixed view from (1, 0.6, 0.5): one node on the back half
  opt.caption = "a2 = pi/2, a3 = pi/2, n = 1";
  const PlotLayout L = plot_layout(opt);
  const auto num = [&](double v) { return svg_number(v, opt.decimals); };

  Node crossing;  // Fig. 3 node (Eq. 25): (0, sin a3, cos a3) = (0, 1, 0)
  crossing.position = Vector3d(0, 1, 0);
  crossing.params = {kPi / 2, 3 * kPi / 2};
  crossing.branches = 2;
  Node tangency;  // a pole, like Table 1 row (d)
  tangency.position = Vector3d(0, 0, 1);
  tangency.kind = NodeKind::tangency;
  Node hidden;    // on the back half
  hidden.position = Vector3d(-1, 0, 0);
  Cusp cusp;
  cusp.position = Vector3d(0, std::sqrt(0.5), std::sqrt(0.5));
  cusp.param = kPi;

  const std::string svg =
      render_sphere_svg(trajectory_of(fig3_curve(720), true), {crossing, tangency, hidden}, {cusp}, opt);

  const std::vector<Vector3d> at = {crossing.position, tangency.position, hidden.position};
  for (std::size_t i = 0; i < at.size(); ++i) {
    const ScreenPoint s = L.sphere.project(at[i]);
    INFO("node " << i + 1);
    CHECK(svg.find("<circle cx=\"" + num(s.x) + "\" cy=\"" + num(s.y) + "\" r=\"" + num(L.marker_radius) + "\"") !=
          std::string::npos);
    const LabelPlacement lp = label_position(L, s);
    CHECK(svg.find("<text x=\"" + num(lp.x) + "\" y=\"" + num(lp.y) + "\"") != std::string::npos);
    CHECK(count_of(svg, ">N" + std::to_string(i + 1) + "</text>") == 2);  // halo + label
  }
  CHECK(count_of(svg, ">N4</text>") == 0);
  // Colours by kind: two crossing rings, one tangency ring (plus one each in the legend).
  CHECK(count_of(svg, "stroke:#d62728") == 3);
  CHECK(count_of(svg, "stroke:#8e44ad") == 2);
  // The back node is faded.
  const ScreenPoint h = L.sphere.project(hidden.position);
  CHECK(h.depth < 0);
  const std::size_t hidden_at = svg.find("<circle cx=\"" + num(h.x) + "\" cy=\"" + num(h.y) + "\"");
  REQUIRE(hidden_at != std::string::npos);
  CHECK(svg.substr(hidden_at, svg.find("/>", hidden_at) - hidden_at).find("stroke-dasharray") != std::string::npos);

  // The cusp: a triangle around its projection and the label C1 next to it.
  const ScreenPoint c = L.sphere.project(cusp.position);
  const double r = 1.1 * L.marker_radius;
  CHECK(svg.find("d=\"M" + num(c.x) + " " + num(c.y - r * 1.15) + "L") != std::string::npos);
  const LabelPlacement cl = label_position(L, c);
  CHECK(svg.find("<text x=\"" + num(cl.x) + "\" y=\"" + num(cl.y) + "\"") != std::string::npos);
  CHECK(count_of(svg, ">C1</text>") == 2);
  // Legend entries for exactly what is drawn.
  CHECK(svg.find(">node (crossing)</text>") != std::string::npos);
  CHECK(svg.find(">node (tangency)</text>") != std::string::npos);
  CHECK(svg.find(">cusp</text>") != std::string::npos);
  // Axes labelled.
  for (const char* axis : {">X</text>", ">Y</text>", ">Z</text>"}) CHECK(count_of(svg, axis) == 2);

  const XmlCheck x = check_xml(svg);
  INFO(x.error);
  CHECK(x.ok);
}

TEST_CASE("render: no markers, no legend entries for absent kinds, no axes when asked", "[svg_plot][render]") {
  PlotOptions opt;
  opt.draw_axes = false;
  opt.draw_grid = false;
  const std::string svg = render_sphere_svg(trajectory_of(fig3_curve(360), true), {}, {}, opt);
  CHECK(svg.find(">N1</text>") == std::string::npos);
  CHECK(svg.find(">C1</text>") == std::string::npos);
  CHECK(svg.find("node (") == std::string::npos);
  CHECK(svg.find(">cusp</text>") == std::string::npos);
  CHECK(svg.find(">X</text>") == std::string::npos);
  CHECK(check_xml(svg).ok);
}

TEST_CASE("render: the curve is two <path> elements whatever the sample count, numbers have 2 decimals",
          "[svg_plot][render]") {
  PlotOptions opt;
  opt.view_from_curve = false;  // from (1, 0.6, 0.5) the curve has a front and a back half
  opt.draw_legend = false;
  opt.draw_axes = false;
  opt.draw_grid = false;
  std::size_t paths_small = 0;
  for (int n : {100, 20000}) {
    const std::string svg = render_sphere_svg(trajectory_of(fig3_curve(n), true), {}, {}, opt);
    const std::size_t paths = count_of(svg, "<path ");
    CHECK(paths == 2);  // front + back
    if (n == 100) paths_small = paths;
    CHECK(paths == paths_small);
    // No coordinate with more than 2 digits after the point.
    CHECK_FALSE(std::regex_search(svg, std::regex("[0-9]\\.[0-9]{3}")));
    // 20000 samples collapse at 0.01 px resolution: the file stays small.
    CHECK(svg.size() < 120000);
  }
}

TEST_CASE("render: caption escaped and present once (plus the title)", "[svg_plot][render]") {
  PlotOptions opt;
  opt.caption = "a2 < pi & a3 > 0 \u2014 \"quoted\" 'x'";
  const std::string svg = render_sphere_svg(trajectory_of(fig3_curve(200), true), {}, {}, opt);
  const std::string escaped = "a2 &lt; pi &amp; a3 &gt; 0 \u2014 &quot;quoted&quot; &apos;x&apos;";
  CHECK(count_of(svg, escaped) == 2);
  CHECK(svg.find("<title>" + escaped + "</title>") != std::string::npos);
  CHECK(svg.find("a2 < pi") == std::string::npos);
  const XmlCheck x = check_xml(svg);
  INFO(x.error);
  CHECK(x.ok);
}

TEST_CASE("render: open trajectories and every view give well-formed SVG", "[svg_plot][render]") {
  for (double el : {-1.5707963267948966, -0.3, 0.0, 0.7, 1.5707963267948966}) {
    PlotOptions opt;
    opt.elevation = el;
    opt.azimuth = 2.5;
    opt.size_px = 300;
    opt.decimals = 1;
    opt.caption = "view test";
    auto pts = fig3_curve(300);
    pts.resize(200);
    Node node;
    node.position = Vector3d(0, 1, 0);
    const std::string svg = render_sphere_svg(trajectory_of(pts, false), {node}, {}, opt);
    const XmlCheck x = check_xml(svg);
    INFO("elevation " << el << ": " << x.error);
    CHECK(x.ok);
    // 300 px wide; the sphere's square 300 px high, the view note and the caption under it
    // (contract 8): at least two lines of 9.5 px text more.
    const auto at = svg.find("width=\"300\" height=\"");
    REQUIRE(at != std::string::npos);
    CHECK(std::stod(svg.substr(at + 20)) >= 300 + 2 * 9.5);
    const auto caption = svg.find(">view test</text>");
    REQUIRE(caption != std::string::npos);
    CHECK(std::stod(svg.substr(svg.rfind(" y=\"", caption) + 4)) > 300);
  }
}

TEST_CASE("invalid plot options are rejected naming the field", "[svg_plot][errors]") {
  auto field_of = [](const PlotOptions& o) {
    try {
      plot_layout(o);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return std::string("none");
  };
  PlotOptions o;
  CHECK(field_of(o) == "none");
  o.size_px = 10;
  CHECK(field_of(o) == "size");
  o = PlotOptions{};
  o.elevation = 2.0;
  CHECK(field_of(o) == "elevation");
  o = PlotOptions{};
  o.azimuth = std::nan("");
  CHECK(field_of(o) == "azimuth");
  o = PlotOptions{};
  o.decimals = 9;
  CHECK(field_of(o) == "decimals");
  o = PlotOptions{};
  o.max_arc_step = 0.0;
  CHECK(field_of(o) == "max_arc_step");
  CHECK_THROWS_AS(render_sphere_svg(trajectory_of(fig3_curve(10), true), {}, {}, o), InvalidInput);
}

TEST_CASE("render: xmllint accepts the document (skipped when xmllint is absent)", "[svg_plot][render]") {
  if (std::system("command -v xmllint >/dev/null 2>&1") != 0) {
    WARN("xmllint not found (Debian package libxml2-utils): external XML validation skipped");
    return;
  }
  PlotOptions opt;
  opt.caption = "a2 = pi/3, a3 = pi/2, n = 2 & <more>";
  Node node;
  node.position = Vector3d(0, 0, -1);
  Cusp cusp;
  cusp.position = Vector3d(1, 0, 0);
  const std::string svg = render_sphere_svg(trajectory_of(fig3_curve(500), true), {node}, {cusp}, opt);
  const std::string path = "test_svg_plot_xmllint.svg";
  {
    std::ofstream f(path);
    f << svg;
  }
  const int rc = std::system(("xmllint --noout " + path).c_str());
  CHECK(rc == 0);
  std::remove(path.c_str());
}
