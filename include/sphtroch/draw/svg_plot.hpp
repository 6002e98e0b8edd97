// sphtroch/draw/svg_plot.hpp — a trajectory on the unit sphere as a standalone SVG picture:
// orthographic view, front half solid and back half dashed, the sphere outline, equator and
// prime meridian, the X/Y/Z axes, nodes and cusps marked and labelled, and a caption
// (the report's Figs. 3-5). Eigen only.
//
//   using namespace sphtroch;
//   const double pi = Constants<double>::pi();
//   GearTrain train(pi / 2, pi / 2, Ratio(1));                   // report Fig. 3
//   TracerCurve<double> curve(train);
//   Trajectory<double> tr = sample_period(curve, 2000);
//   RootCensus census = root_census(train);                      // or any census
//   PlotOptions opt;
//   opt.caption = "a2 = pi/2, a3 = pi/2, n = 1 - 1 node (crossing), 0 cusps";
//   std::string svg = render_sphere_svg(tr, census.nodes, {}, opt);  // nodes, cusps; write it to a .svg file
//
// The view: the viewer looks at the origin from the direction
//   view = (cos el cos az, cos el sin az, sin el)
// (default: chosen from the curve, curve_view.hpp: its mean direction unless a principal axis shows
// clearly more of it in front), with the screen's up the projection of +Z. A point P of the sphere
// is drawn at centre + radius * (P.right, -P.up) (SVG's y grows downwards); it is on the front half
// when P.view >= -kSilhouetteTolerance. The picture states its view (azimuth, elevation in degrees
// and, when chosen from the curve, why) in a note above the caption; a view chosen from the curve
// is rounded to whole degrees, so the note states exactly the view drawn.
//
// Contracts:
//  1. project(view) is the picture centre; every point with P.view = 0 lands on the outline
//     circle (distance radius from the centre, up to rounding).
//  2. Edges of the trajectory are great-circle arcs. An arc whose ends lie on different halves
//     is split at the exact point where its great circle crosses the silhouette plane
//     (P.view = 0), so front and back pieces meet on the outline. Arcs longer than
//     PlotOptions::max_arc_step are subdivided along their great circle before projection.
//  3. The curve is drawn as one <path> for the front half and one for the back half, whatever
//     the sample count; grid lines likewise. Numbers carry PlotOptions::decimals digits, and
//     each projected run is simplified (Douglas-Peucker, PlotOptions::simplify_px) so that
//     the file size follows the picture, not the sample count (2e3 or 2e6 samples of a
//     n = 13/5 curve: about 22 kB either way; 2e6 samples render in 0.7 s).
//  4. Node i (0-based) is drawn as a ring at its projected position and labelled "N<i+1>";
//     cusp j as a triangle labelled "C<j+1>" (the order of the node and cusp lists, i.e. the rows
//     of `sphtroch nodes`); markers on the back half are faded. Ring colour tells the node kind
//     (crossing / tangency); a legend explains the marks. PlotOptions::labels: `numbers` labels
//     every mark; `none` none; `automatic` (the default) labels the marks in order, front half
//     first, skipping a label whose box would overlap one already placed (boxes from the font
//     size: 0.86 em for the letter, 0.72 em per digit, 1.2 em high, bounds on the boxes a browser
//     lays sans-serif bold out in), so a dense curve stays readable; the legend then says how many
//     labels it shows.
//  5. The caption is escaped (svg.hpp), so any text is safe; the document is valid SVG 1.1.
//  6. Markers (PlotOptions::markers, mark_density.hpp): automatic draws the node and cusp markers
//     of a curve with at most kAutoMarkLimit of them and none above, all and none as named; a
//     note above the caption says how many were hidden. Hidden markers leave the legend too.
//  7. PlotStyle::density draws, instead of the curve's lines, the front half's dwell raster
//     (dwell_raster.hpp, kDwellCells per side; the trajectory must be a period uniform in the
//     carrier angle, as sample_period gives): each cell the tracer visits is filled by its share
//     of the period per steradian on a viridis ramp (low light yellow, high dark violet) from 0 to
//     the 98th percentile of the visited cells' densities (denser cells darkest), clipped to the
//     disc; the legend shows the ramp and its top ("0.0912+"), a note says the back half is not
//     shown.
//  REQUIRES: trajectory points, node and cusp positions finite (assertion); options valid
//  (InvalidInput naming the field otherwise).
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/curve_view.hpp"
#include "sphtroch/draw/dwell_raster.hpp"
#include "sphtroch/draw/mark_density.hpp"
#include "sphtroch/draw/svg.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sphtroch {

/// A point whose P.view lies within this of 0 counts as on the front half (and on the
/// silhouette): it stops the rounding noise of a curve lying in the silhouette plane (e.g. a
/// great circle seen face-on) from being chopped into many pieces. 64 ulp of 1, far below a
/// pixel (1e-12 of the radius).
constexpr double kSilhouetteTolerance = 64 * 2.220446049250313e-16;

namespace detail {
/// Axes are drawn from the centre to this multiple of the radius.
constexpr double kAxisReach = 1.22;
/// The length of a picture vector, sqrt(dx^2 + dy^2): correctly rounded IEEE operations only, the
/// same bits natively and in the explorer (the C libraries' hypot differ in the last bit, which
/// can flip a choice of the Douglas-Peucker simplification). Pixel sizes: no overflow.
inline double screen_length(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }
}  // namespace detail

/// Samples of the trajectory drawn by `sphtroch plot` (and the analysis object's plot stage):
/// 720 per unit of (q + |p|), clamped to [1440, 400000] (the picture needs ~0.25 degree steps).
inline std::size_t plot_sample_count(const GearTrain& train) {
  const auto& r = train.ratio();
  return std::clamp<std::size_t>(720 * static_cast<std::size_t>(r.q() + r.abs_p()), 1440, 400000);
}

/// Samples of a rotation chain's curve drawn by `sphtroch chain plot`: 720 per unit of s times
/// sum |N_i| over the period (twice chain_trace_sample_count's density; for k = 2 with rates 1,
/// p/q plot_sample_count's), clamped to [1440, 400000].
inline std::size_t chain_plot_sample_count(const RotationChain& chain) {
  return static_cast<std::size_t>(std::clamp(720.0 * chain.total_turns(), 1440.0, 400000.0));
}

/// Which marks get their N<i>/C<j> label (contract 4).
enum class PlotLabels { automatic, numbers, none };

/// The curve as lines (front solid, back dashed), or its dwell on the front half (contract 7).
enum class PlotStyle { curve, density };

/// Cells per side of the density view's raster (dwell_raster.hpp): ~8 px at the default size.
constexpr std::size_t kDwellCells = 64;

struct PlotOptions {
  /// Direction of the viewer, radians: azimuth about +Z from +X towards +Y, elevation above
  /// the XY plane; used when view_from_curve is false. Must be finite; elevation in [-pi/2, pi/2].
  double azimuth = std::atan2(0.6, 1.0);
  double elevation = std::atan2(0.5, std::sqrt(1.36));
  /// Choose the view from the curve (curve_view.hpp), ignoring azimuth and elevation (the default;
  /// set_plot_view turns it off).
  bool view_from_curve = true;
  /// Which node and cusp markers are drawn (contract 6).
  MarkMode markers = MarkMode::automatic;
  /// Lines, or the density view (contract 7).
  PlotStyle style = PlotStyle::curve;
  /// Width and height of the picture in px, caption included. Valid: [64, 8192].
  double size_px = 520;
  /// One line under the picture (empty: none). Any text; it is XML-escaped.
  std::string caption;
  bool draw_axes = true;    // X, Y, Z from the centre, with labels
  bool draw_grid = true;    // equator and prime meridian, faint
  bool draw_legend = true;  // what the marks mean (only the kinds present)
  PlotLabels labels = PlotLabels::automatic;  // contract 4
  /// Digits after the decimal point of every coordinate. Valid: [0, 6].
  int decimals = 2;
  /// Longest great-circle arc drawn as one straight segment, radians. Valid: (0, 0.5].
  double max_arc_step = 0.5 * Constants<double>::pi() / 180.0;
  /// Projected polylines are simplified (Douglas-Peucker) so that the drawn line stays within
  /// this many px of every projected sample: dense samples cost no file size. 0 keeps every
  /// vertex that differs at the printed precision. Valid: [0, 5].
  double simplify_px = 0.15;
};

/// A view as the CLI writes it: "auto" (chosen from the curve, the default), "top" (along the sun
/// axis Z: +X right, +Y up), "front" (from -Y: +X right, +Z up), "side" (from +X: +Y right, +Z up)
/// or "AZ,EL" (angles in parse.hpp's syntax, EL in [-pi/2, pi/2]); sets options.view_from_curve,
/// .azimuth and .elevation. Throws InvalidInput(field).
inline void set_plot_view(PlotOptions& options, std::string_view text, const std::string& field = "view");

/// "auto" (automatic), "numbers" or "none". Throws InvalidInput(field).
inline PlotLabels parse_plot_labels(std::string_view text, const std::string& field = "labels");

/// "curve" or "density". Throws InvalidInput(field).
inline PlotStyle parse_plot_style(std::string_view text, const std::string& field = "style") {
  if (text == "curve") return PlotStyle::curve;
  if (text == "density") return PlotStyle::density;
  throw InvalidInput(field, std::string(text), "not a plot style",
                     "curve (lines, back half dashed), density (time spent per steradian, front half)");
}

/// A projected point: picture coordinates in px and the depth P.view (>= 0: front half).
struct ScreenPoint {
  double x = 0.0;
  double y = 0.0;
  double depth = 0.0;
};

/// The orthographic camera and where the sphere sits on the page.
struct SphereView {
  Vector3d view = Vector3d::UnitX();   // unit vector towards the viewer
  Vector3d right = Vector3d::UnitY();  // screen +x
  Vector3d up = Vector3d::UnitZ();     // screen up (SVG -y)
  double cx = 0.0, cy = 0.0;           // picture coordinates of the sphere centre
  double radius = 1.0;                 // px

  /// Camera from azimuth/elevation (see the header comment), centred at (cx, cy).
  static SphereView looking_from(double azimuth, double elevation, double cx, double cy, double radius);
  ScreenPoint project(const Vector3d& p) const;
  bool is_front(const Vector3d& p) const { return p.dot(view) >= -kSilhouetteTolerance; }
};

/// Sizes derived from the options: the camera, marker and font sizes, the caption line.
struct PlotLayout {
  SphereView sphere;
  double width = 0.0, height = 0.0;
  double font_px = 12.0;        // labels; the caption uses 1.1x
  double marker_radius = 5.0;   // node ring radius, cusp triangle half-size
  double caption_y = 0.0;       // baseline of the caption
};

/// REQUIRES: valid options (throws InvalidInput naming the field otherwise).
inline PlotLayout plot_layout(const PlotOptions& options);

/// Where the label of a marker at `at` goes: pushed away from the sphere centre, past the mark.
/// `anchor_end` is true when the text should end there (labels left of the centre).
struct LabelPlacement {
  double x = 0.0, y = 0.0;
  bool anchor_end = false;
};
inline LabelPlacement label_position(const PlotLayout& layout, const ScreenPoint& at);

/// A spherical polyline cut into maximal runs on each half of the sphere.
struct HemisphereSplit {
  std::vector<std::vector<Vector3d>> front;  // each run: consecutive points, >= 2 of them
  std::vector<std::vector<Vector3d>> back;
  std::size_t silhouette_crossings = 0;      // edges (after subdivision) that change half
};

/// Cuts the polyline `points` (closed: an edge joins the last point to the first) into runs
/// on the front (P.view >= -kSilhouetteTolerance) and back halves. Edges are great-circle arcs
/// shorter than pi; arcs longer than max_step are subdivided along the great circle. A changing
/// edge is split at the point of its arc on the silhouette plane, normalised onto the sphere
/// and shared by both runs. For a closed polyline the run through the first point is not cut
/// there. REQUIRES: unit, finite points; view a unit vector; max_step > 0.
inline HemisphereSplit split_by_silhouette(const std::vector<Vector3d>& points, bool closed, const Vector3d& view,
                                    double max_step);

/// The whole picture as a standalone SVG 1.1 document (see the header comment).
inline std::string render_sphere_svg(const Trajectory<double>& trajectory, const std::vector<Node>& nodes,
                              const std::vector<Cusp>& cusps, const PlotOptions& options);

/// The caption of `sphtroch plot`: "a2 = A2, a3 = A3, n = p/q[ (teeth ZS:ZP)][, phase = PH] — N
/// node(s)[ (C crossing, T tangency)], K cusp(s)", the angles as typed, the phase shown when the
/// analysed phase is not 0, N = crossings + tangencies. One text for the tool, Python and the
/// explorer; what a census says of its certificate is appended by the caller.
inline std::string plot_caption_text(const TrainText& text, const GearTrain& analysed, std::size_t crossings,
                                     std::size_t tangencies, std::size_t cusps) {
  std::string caption = "a2 = " + text.a2 + ", a3 = " + text.a3 + ", n = " + analysed.ratio().str() + text.teeth_note();
  if (analysed.phase() != 0.0) caption += ", phase = " + text.phase;
  caption += " — " + std::to_string(crossings + tangencies) + " node(s)";
  if (crossings + tangencies != 0)
    caption += " (" + std::to_string(crossings) + " crossing, " + std::to_string(tangencies) + " tangency)";
  return caption + ", " + std::to_string(cusps) + " cusp(s)";
}

// ---------------------------------------------------------------------------------------------
// Implementation details follow.
// ---------------------------------------------------------------------------------------------

inline void set_plot_view(PlotOptions& options, std::string_view text, const std::string& field) {
  const double pi = Constants<double>::pi();
  const char* const forms =
      "auto, top, front, side, or AZ,EL: azimuth (any angle) and elevation in [-pi/2, pi/2] (30deg,45deg)";
  options.view_from_curve = text == "auto";
  if (options.view_from_curve) return;
  if (text == "top" || text == "front" || text == "side") {
    options.azimuth = text == "side" ? 0.0 : -pi / 2;
    options.elevation = text == "top" ? pi / 2 : 0.0;
    return;
  }
  const auto comma = text.find(',');
  if (comma == std::string_view::npos) throw InvalidInput(field, std::string(text), "not a view", forms);
  const double azimuth = parse_angle(std::string(text.substr(0, comma)), field);
  const double elevation = parse_angle(std::string(text.substr(comma + 1)), field);
  if (!(std::fabs(elevation) <= pi / 2))
    throw InvalidInput(field, std::string(text), "elevation outside the valid range", forms);
  options.azimuth = azimuth;
  options.elevation = elevation;
}

inline PlotLabels parse_plot_labels(std::string_view text, const std::string& field) {
  if (text == "auto") return PlotLabels::automatic;
  if (text == "numbers") return PlotLabels::numbers;
  if (text == "none") return PlotLabels::none;
  throw InvalidInput(field, std::string(text), "not a label mode", "auto (no overlaps), numbers (all), none");
}

inline SphereView SphereView::looking_from(double azimuth, double elevation, double cx, double cy, double radius) {
  SphereView v;
  const SinCos<double> a = sin_cos(azimuth), e = sin_cos(elevation);  // portable_trig.hpp: the explorer's bits too
  const double ca = a.cos, sa = a.sin, ce = e.cos, se = e.sin;
  v.view = Vector3d(ce * ca, ce * sa, se);
  v.right = Vector3d(-sa, ca, 0.0);          // Z x view, normalised (horizontal)
  v.up = Vector3d(-se * ca, -se * sa, ce);   // view x right
  v.cx = cx;
  v.cy = cy;
  v.radius = radius;
  return v;
}

inline ScreenPoint SphereView::project(const Vector3d& p) const {
  return ScreenPoint{cx + radius * p.dot(right), cy - radius * p.dot(up), p.dot(view)};
}

inline PlotLayout plot_layout(const PlotOptions& o) {
  const double pi = Constants<double>::pi();
  if (!std::isfinite(o.azimuth))
    throw InvalidInput("azimuth", report_number(o.azimuth), "not a finite number", "any finite angle in radians");
  if (!(std::isfinite(o.elevation) && std::fabs(o.elevation) <= pi / 2))
    throw InvalidInput("elevation", report_number(o.elevation), "outside the valid range", "[-pi/2, pi/2] radians");
  if (!(o.size_px >= 64 && o.size_px <= 8192))
    throw InvalidInput("size", report_number(o.size_px), "outside the valid range", "[64, 8192] px");
  if (!(o.decimals >= 0 && o.decimals <= 6))
    throw InvalidInput("decimals", std::to_string(o.decimals), "outside the valid range", "integer 0 .. 6");
  if (!(o.simplify_px >= 0 && o.simplify_px <= 5))
    throw InvalidInput("simplify_px", report_number(o.simplify_px), "outside the valid range", "[0, 5] px");
  if (!(o.max_arc_step > 0 && o.max_arc_step <= 0.5))
    throw InvalidInput("max_arc_step", report_number(o.max_arc_step), "outside the valid range", "(0, 0.5] radians");

  PlotLayout l;
  l.width = l.height = o.size_px;
  l.font_px = std::max(9.0, o.size_px / 42.0);
  l.marker_radius = std::max(3.5, o.size_px / 95.0);
  const double caption_band = o.caption.empty() ? 0.0 : 2.2 * l.font_px;
  const double legend_band = o.draw_legend ? 1.7 * l.font_px : 0.3 * l.font_px;
  const double avail_h = l.height - caption_band - legend_band;
  // Extents around the centre in units of the radius: the sphere (plus the marker rings on
  // its rim), and the axes' tips at kAxisReach R with their labels about 0.2 R further out.
  const SphereView unit = SphereView::looking_from(o.azimuth, o.elevation, 0.0, 0.0, 1.0);
  double left = 1.05, right = 1.05, top = 1.05, bottom = 1.05;
  if (o.draw_axes) {
    for (int k = 0; k < 3; ++k) {
      const ScreenPoint tip = unit.project(detail::kAxisReach * Vector3d::Unit(k));
      left = std::max(left, -tip.x + 0.22);
      right = std::max(right, tip.x + 0.22);
      top = std::max(top, -tip.y + 0.22);
      bottom = std::max(bottom, tip.y + 0.22);
    }
  }
  const double radius = std::min(l.width / (left + right), avail_h / (top + bottom));
  const double cx = left * radius + 0.5 * (l.width - (left + right) * radius);
  const double cy = legend_band + top * radius + 0.5 * (avail_h - (top + bottom) * radius);
  l.sphere = SphereView::looking_from(o.azimuth, o.elevation, cx, cy, radius);
  l.caption_y = l.height - 0.75 * l.font_px;
  return l;
}

inline LabelPlacement label_position(const PlotLayout& layout, const ScreenPoint& at) {
  // Outward from the centre, bent towards the upper right so that a mark on an axis (a pole,
  // the centre) does not put its label on the axis line.
  double dx = at.x - layout.sphere.cx, dy = at.y - layout.sphere.cy;
  const double len = detail::screen_length(dx, dy);
  if (len > 1e-9 * layout.sphere.radius) {
    dx /= len;
    dy /= len;
  } else {
    dx = dy = 0.0;
  }
  dx += std::sqrt(0.5);
  dy -= std::sqrt(0.5);
  const double len2 = detail::screen_length(dx, dy);
  if (len2 > 1e-3) {
    dx /= len2;
    dy /= len2;
  } else {  // straight down-left of the centre: go right
    dx = 1.0;
    dy = 0.0;
  }
  const double gap = layout.marker_radius + 0.3 * layout.font_px;
  LabelPlacement p;
  p.x = at.x + dx * gap;
  p.y = at.y + dy * gap + 0.35 * layout.font_px * (1.0 + dy);  // baseline: glyphs clear of the mark
  p.anchor_end = dx < -0.3;
  return p;
}

namespace detail {

/// Points strictly inside the great-circle arc a->b splitting it into pieces of at most
/// max_step (normalised linear interpolation in angle; exact points of the arc).
inline void arc_interior(const Vector3d& a, const Vector3d& b, double max_step, std::vector<Vector3d>& out) {
  const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
  if (!(angle > max_step)) return;
  const std::size_t pieces = static_cast<std::size_t>(std::ceil(angle / max_step));
  const double s = std::sin(angle);
  for (std::size_t k = 1; k < pieces; ++k) {
    const double f = static_cast<double>(k) / static_cast<double>(pieces);
    // slerp; the arc is shorter than pi so sin(angle) > 0
    Vector3d p = (std::sin((1 - f) * angle) / s) * a + (std::sin(f * angle) / s) * b;
    out.push_back(p.normalized());
  }
}

/// The point of the arc a->b on the plane P.view = 0, when a and b lie on different halves.
/// With da = a.view and db = b.view of opposite signs, |db| a + |da| b is on the plane and
/// between a and b on their great circle; the component along view is removed once more so
/// that the result is on the silhouette also when a or b lies within the tolerance of it.
inline Vector3d silhouette_crossing(const Vector3d& a, const Vector3d& b, const Vector3d& view) {
  const double da = a.dot(view), db = b.dot(view);
  Vector3d c = std::fabs(db) * a + std::fabs(da) * b;
  c -= c.dot(view) * view;
  const double n = c.norm();
  if (!(n > 0)) return a;  // a = -b: not an arc shorter than pi (precondition), keep going
  return c / n;
}

}  // namespace detail

inline HemisphereSplit split_by_silhouette(const std::vector<Vector3d>& points, bool closed, const Vector3d& view,
                                           double max_step) {
  SPHTROCH_ASSERT(max_step > 0, "split_by_silhouette: max_step > 0");
  HemisphereSplit split;
  if (points.size() < 2) return split;
  auto front_of = [&](const Vector3d& p) { return p.dot(view) >= -kSilhouetteTolerance; };

  struct Run {
    bool front;
    std::vector<Vector3d> pts;
  };
  std::vector<Run> runs;
  runs.push_back(Run{front_of(points[0]), {points[0]}});
  std::vector<Vector3d> interior;
  auto step_to = [&](const Vector3d& b) {
    Run& cur = runs.back();
    const Vector3d& a = cur.pts.back();
    const bool fb = front_of(b);
    if (fb == cur.front) {
      cur.pts.push_back(b);
      return;
    }
    const Vector3d c = detail::silhouette_crossing(a, b, view);
    cur.pts.push_back(c);
    ++split.silhouette_crossings;
    runs.push_back(Run{fb, {c, b}});
  };
  const std::size_t m = points.size();
  const std::size_t edges = closed ? m : m - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const Vector3d& a = points[i];
    const Vector3d& b = points[(i + 1) % m];
    SPHTROCH_ASSERT(std::isfinite(a.x()) && std::isfinite(a.y()) && std::isfinite(a.z()),
                    "split_by_silhouette: finite points");
    interior.clear();
    detail::arc_interior(a, b, max_step, interior);
    for (const auto& p : interior) step_to(p);
    step_to(b);
  }
  // A closed polyline started in the middle of a run: join its two ends there.
  if (closed && runs.size() > 1 && runs.front().front == runs.back().front) {
    Run& last = runs.back();
    last.pts.insert(last.pts.end(), runs.front().pts.begin() + 1, runs.front().pts.end());
    runs.front() = std::move(last);
    runs.pop_back();
  }
  for (auto& r : runs) {
    if (r.pts.size() < 2) continue;
    (r.front ? split.front : split.back).push_back(std::move(r.pts));
  }
  return split;
}

namespace detail {

/// Distance from p to the segment a-b (to a when a = b).
inline double segment_distance(const ScreenPoint& p, const ScreenPoint& a, const ScreenPoint& b) {
  const double ux = b.x - a.x, uy = b.y - a.y;
  const double len2 = ux * ux + uy * uy;
  double t = len2 > 0 ? ((p.x - a.x) * ux + (p.y - a.y) * uy) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return screen_length(p.x - (a.x + t * ux), p.y - (a.y + t * uy));
}

/// Douglas-Peucker: which vertices to keep so that the kept polyline stays within `tol` of
/// every vertex. Iterative (no recursion depth limit); ends always kept.
inline std::vector<bool> simplify_keep(const std::vector<ScreenPoint>& pts, double tol) {
  std::vector<bool> keep(pts.size(), tol <= 0);
  if (pts.empty()) return keep;
  keep.front() = keep.back() = true;
  if (tol <= 0) return keep;
  std::vector<std::pair<std::size_t, std::size_t>> todo{{0, pts.size() - 1}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    if (j <= i + 1) continue;
    double worst = -1.0;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
      const double d = segment_distance(pts[k], pts[i], pts[j]);
      if (d > worst) {
        worst = d;
        at = k;
      }
    }
    if (worst > tol) {
      keep[at] = true;
      todo.emplace_back(i, at);
      todo.emplace_back(at, j);
    }
  }
  return keep;
}

inline void append_runs(SvgPath& d, const std::vector<std::vector<Vector3d>>& runs, const SphereView& cam,
                        double simplify_px) {
  std::vector<ScreenPoint> screen;
  for (const auto& run : runs) {
    screen.clear();
    for (const auto& p : run) screen.push_back(cam.project(p));
    const std::vector<bool> keep = simplify_keep(screen, simplify_px);
    d.move_to(screen.front().x, screen.front().y);
    for (std::size_t i = 1; i < screen.size(); ++i)
      if (keep[i]) d.line_to(screen[i].x, screen[i].y);
  }
}

inline std::vector<Vector3d> great_circle(const Vector3d& u, const Vector3d& v, std::size_t n) {
  std::vector<Vector3d> pts;
  pts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = Constants<double>::two_pi() * static_cast<double>(i) / static_cast<double>(n);
    const SinCos<double> s = sin_cos(t);  // portable_trig.hpp: the same bits natively and in the explorer
    pts.push_back(s.cos * u + s.sin * v);
  }
  return pts;
}

inline std::string triangle_path(double x, double y, double r, int decimals) {
  SvgPath d(decimals);
  // Equilateral, pointing up, centred on (x, y).
  d.move_to(x, y - r * 1.15);
  d.line_to(x + r, y + r * 0.6);
  d.line_to(x - r, y + r * 0.6);
  d.close();
  return d.str();
}

/// The colour at f in [0, 1] of viridis reversed (0 light yellow, 1 dark violet): linear in sRGB
/// between five of viridis's published stops (f clamped).
inline std::string viridis_colour(double f) {
  static const int stops[5][3] = {{253, 231, 37}, {94, 201, 98}, {33, 145, 140}, {59, 82, 139}, {68, 1, 84}};
  const double x = std::clamp(f, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(x));
  const double w = x - i;
  static const char* const hex = "0123456789abcdef";
  std::string out = "#";
  for (int c = 0; c < 3; ++c) {
    const int v = static_cast<int>(std::lround((1 - w) * stops[i][c] + w * stops[i + 1][c]));
    out += hex[v / 16];
    out += hex[v % 16];
  }
  return out;
}

constexpr const char* kCurveColour = "#1f5fa8";
constexpr const char* kCrossingColour = "#d62728";
constexpr const char* kTangencyColour = "#8e44ad";
constexpr const char* kCuspColour = "#e67e00";
constexpr const char* kGridColour = "#8a96a3";
constexpr const char* kAxisColour = "#444444";

}  // namespace detail

namespace detail {

/// The sphere picture being drawn (contracts 1-5): layout, view, writer and base line width, with
/// one method per layer. render_sphere_svg calls them back to front.
class SphereCanvas {
 public:
  explicit SphereCanvas(const PlotOptions& options)
      : opt_(options), L_(plot_layout(options)), cam_(L_.sphere), svg_(L_.width, L_.height, options.decimals),
        lw_(std::max(1.0, L_.width / 300.0)) {
    svg_.title(options.caption.empty() ? std::string("sphtroch trajectory") : options.caption);
  }

  /// Sphere disc, lightly filled so the picture reads as a ball.
  void disc() { svg_.circle(cam_.cx, cam_.cy, cam_.radius, "fill:#f3f6fa;stroke:none"); }

  /// Grid: equator (XY plane) and prime meridian (XZ plane, through +X), split once; back half dashed.
  void grid_back() {
    if (!opt_.draw_grid) return;
    grid_eq_ = split(great_circle(Vector3d::UnitX(), Vector3d::UnitY(), 360), true);
    grid_mer_ = split(great_circle(Vector3d::UnitX(), Vector3d::UnitZ(), 360), true);
    svg_.path(runs_path(grid_eq_.back, grid_mer_.back),
              stroke(kGridColour, 0.6) + ";stroke-dasharray:" + num(lw_) + " " + num(3 * lw_));
  }

  /// The curve's back half: dashed and faded, under everything in front (contract 2, 3).
  void curve_back(const HemisphereSplit& curve) {
    svg_.path(runs_path(curve.back, {}), curve_back_style() + ";stroke-linejoin:round");
  }

  /// The outline, then the front grid.
  void outline_and_grid_front() {
    svg_.circle(cam_.cx, cam_.cy, cam_.radius, stroke("#333333", 1.1));
    if (opt_.draw_grid) svg_.path(runs_path(grid_eq_.front, grid_mer_.front), stroke(kGridColour, 0.7));
  }

  /// Axes from the centre to kAxisReach R with arrow heads; one pointing away is dashed.
  void axes() {
    if (!opt_.draw_axes) return;
    SvgPath solid(dec()), dashed(dec()), heads(dec());
    for (int k = 0; k < 3; ++k) axis(k, solid, dashed, heads);
    const std::string base = stroke(kAxisColour, 0.9);
    svg_.path(solid, base);
    svg_.path(dashed, base + ";stroke-dasharray:" + num(3 * lw_) + " " + num(2 * lw_));
    svg_.path(heads, std::string("fill:") + kAxisColour + ";stroke:none");
  }

  /// The density view (contract 7): a rect per visited cell, coloured by its density, clipped to
  /// the disc.
  void dwell(const DwellRaster& raster) {
    peak_density_ = ramp_top(raster);
    if (!(peak_density_ > 0)) return;
    const double side = 2.0 * cam_.radius / static_cast<double>(raster.cells);
    svg_.raw("<defs><clipPath id=\"disc\"><circle cx=\"" + num(cam_.cx) + "\" cy=\"" + num(cam_.cy) + "\" r=\"" +
             num(cam_.radius) + "\"/></clipPath></defs>\n");
    svg_.begin_group("shape-rendering:crispEdges", "id=\"dwell\" clip-path=\"url(#disc)\"");
    for (std::size_t row = 0; row < raster.cells; ++row)
      for (std::size_t col = 0; col < raster.cells; ++col) {
        if (raster.time[raster.index(col, row)] == 0.0) continue;
        svg_.rect(cam_.cx + cam_.radius * raster.centre_x(col) - 0.5 * side,
                  cam_.cy - cam_.radius * raster.centre_y(row) - 0.5 * side, side, side,
                  std::string("stroke:none;fill:") + viridis_colour(raster.density(col, row) / peak_density_));
      }
    svg_.end_group();
  }

  /// The curve's front half.
  void curve_front(const HemisphereSplit& curve) {
    svg_.path(runs_path(curve.front, {}), stroke(kCurveColour, 1.7) + ";stroke-linejoin:round;stroke-linecap:round");
  }

  /// Node i as a ring labelled N<i+1>, coloured by kind, faded on the back half (contract 4).
  void node_markers(const std::vector<Node>& nodes) {
    svg_.begin_group("", "id=\"nodes\"");
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const Node& node = nodes[i];
      SPHTROCH_ASSERT(std::isfinite(node.position.norm()), "render_sphere_svg: finite node position");
      const ScreenPoint s = cam_.project(node.position);
      const bool front = s.depth >= -kSilhouetteTolerance;
      const char* colour = node.kind == NodeKind::crossing ? kCrossingColour : kTangencyColour;
      (node.kind == NodeKind::crossing ? have_crossing_ : have_tangency_) = true;
      svg_.circle(s.x, s.y, L_.marker_radius, stroke(colour, 1.6) + (front ? "" : back_mark()));
    }
    svg_.end_group();
    svg_.begin_group("", "id=\"node-labels\"");
    for (const bool front_half : {true, false})  // front labels first: they win a place
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const ScreenPoint s = cam_.project(nodes[i].position);
        const bool front = s.depth >= -kSilhouetteTolerance;
        if (front != front_half) continue;
        const char* colour = nodes[i].kind == NodeKind::crossing ? kCrossingColour : kTangencyColour;
        marker_label(s, "N" + std::to_string(i + 1), colour, front);
      }
    svg_.end_group();
  }

  /// Cusp j as a triangle labelled C<j+1> (contract 4).
  void cusp_markers(const std::vector<Cusp>& cusps) {
    svg_.begin_group("", "id=\"cusps\"");
    for (std::size_t j = 0; j < cusps.size(); ++j) {
      SPHTROCH_ASSERT(std::isfinite(cusps[j].position.norm()), "render_sphere_svg: finite cusp position");
      const ScreenPoint s = cam_.project(cusps[j].position);
      const bool front = s.depth >= -kSilhouetteTolerance;
      svg_.path(triangle_path(s.x, s.y, 1.1 * L_.marker_radius, dec()),
                stroke(kCuspColour, 1.6) + ";stroke-linejoin:round" + (front ? "" : back_mark()));
      marker_label(s, "C" + std::to_string(j + 1), kCuspColour, front);
    }
    svg_.end_group();
  }

  /// The notes above the caption, right-aligned, one line each from the bottom up: the view, then
  /// what the labels and markers leave out (contracts 4, 6).
  void notes(const std::string& view, const MarkChoice& marks) {
    std::vector<std::string> lines{view};
    if (label_boxes_.size() < labels_wanted_ && opt_.labels == PlotLabels::automatic)
      lines.push_back(std::to_string(label_boxes_.size()) + " of " + std::to_string(labels_wanted_) +
                      " labels (no overlaps; all: --labels numbers, the list: sphtroch nodes)");
    if (!marks.note.empty()) lines.push_back(marks.note + " (--markers all draws them)");
    if (opt_.style == PlotStyle::density)
      lines.push_back("density view: the front half's dwell in " + std::to_string(kDwellCells) + " x " +
                      std::to_string(kDwellCells) + " cells, the back half not shown");
    for (std::size_t i = 0; i < lines.size(); ++i)
      label(L_.width - 0.4 * L_.font_px, L_.caption_y - (1.3 + 1.05 * static_cast<double>(i)) * L_.font_px, lines[i],
            "font-family:sans-serif;font-size:" + num(0.8 * L_.font_px) + "px;fill:#555555", "end");
  }

  /// Legend: one line along the top, only for what is drawn.
  void legend(bool with_cusps) {
    if (!opt_.draw_legend) return;
    LegendPen pen{0.6 * L_.font_px, 1.1 * L_.font_px};
    const double r = 0.8 * L_.marker_radius;
    if (opt_.style == PlotStyle::density) {
      legend_ramp(pen);
    } else {
      legend_line(pen, std::string("stroke:") + kCurveColour + ";stroke-width:" + num(1.7 * lw_), "front");
      legend_line(pen, "stroke:" + curve_back_style().substr(std::string("fill:none;stroke:").size()), "back");
    }
    if (have_crossing_) {
      svg_.circle(pen.x + r, pen.mid(L_), r, stroke(kCrossingColour, 1.4));
      legend_mark(pen, r, "node (crossing)");
    }
    if (have_tangency_) {
      svg_.circle(pen.x + r, pen.mid(L_), r, stroke(kTangencyColour, 1.4));
      legend_mark(pen, r, "node (tangency)");
    }
    if (with_cusps) {
      svg_.path(triangle_path(pen.x + r, pen.mid(L_), r, dec()), stroke(kCuspColour, 1.4));
      legend_mark(pen, r, "cusp");
    }
  }

  /// The caption, shrunk to fit the width (a sans-serif glyph averages about 0.55 em).
  void caption() {
    if (opt_.caption.empty()) return;
    const double fit = 0.95 * L_.width / (0.55 * static_cast<double>(std::max<std::size_t>(1, opt_.caption.size())));
    svg_.text(0.5 * L_.width, L_.caption_y, opt_.caption,
              "font-family:sans-serif;font-size:" + num(std::min(1.1 * L_.font_px, fit)) + "px;fill:#111111", "middle");
  }

  HemisphereSplit split(const std::vector<Vector3d>& points, bool closed) const {
    return split_by_silhouette(points, closed, cam_.view, opt_.max_arc_step);
  }
  std::string finish() { return svg_.finish(); }
  const SphereView& camera() const { return cam_; }

 private:
  /// A label's box in picture px (x, y: top left).
  struct LabelBox {
    double x, y, w, h;
    bool overlaps(const LabelBox& o) const { return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h; }
  };
  std::vector<LabelBox> label_boxes_;
  std::size_t labels_wanted_ = 0;

  /// Where the next legend item goes: x advances, y is the text baseline.
  struct LegendPen {
    double x, y;
    double mid(const PlotLayout& L) const { return y - 0.3 * L.font_px; }
  };

  int dec() const { return opt_.decimals; }
  std::string num(double v) const { return svg_number(v, dec()); }
  /// The one stroke style: no fill, a colour, `width` times the base line width.
  std::string stroke(const char* colour, double width) const {
    return std::string("fill:none;stroke:") + colour + ";stroke-width:" + num(width * lw_);
  }
  std::string curve_back_style() const {
    return std::string("fill:none;stroke:") + kCurveColour + ";stroke-opacity:0.45;stroke-width:" + num(1.1 * lw_) +
           ";stroke-dasharray:" + num(4 * lw_) + " " + num(2.5 * lw_);
  }
  std::string back_mark() const { return ";stroke-opacity:0.6;stroke-dasharray:" + num(2 * lw_) + " " + num(1.5 * lw_); }

  SvgPath runs_path(const std::vector<std::vector<Vector3d>>& a, const std::vector<std::vector<Vector3d>>& b) const {
    SvgPath d(dec());
    append_runs(d, a, cam_, opt_.simplify_px);
    append_runs(d, b, cam_, opt_.simplify_px);
    return d;
  }

  /// A label: a white halo under the glyphs keeps it readable over curve and grid lines.
  void label(double x, double y, const std::string& text, const std::string& style, const char* anchor) {
    svg_.text(x, y, text, style + ";stroke:#ffffff;stroke-width:" + num(2.5 * lw_) + ";stroke-linejoin:round", anchor);
    svg_.text(x, y, text, style, anchor);
  }
  /// A mark's label, unless PlotOptions::labels leaves it out (contract 4).
  void marker_label(const ScreenPoint& s, const std::string& text, const char* colour, bool front) {
    ++labels_wanted_;
    if (opt_.labels == PlotLabels::none) return;
    const LabelPlacement lp = label_position(L_, s);
    // The box a browser lays the text out in (sans-serif bold, e.g. DejaVu Sans Bold: N 0.84 em,
    // digits 0.70 em, ascent 0.93 em, descent 0.24 em), rounded up.
    const double w = L_.font_px * (0.86 + 0.72 * static_cast<double>(text.size() - 1));
    const LabelBox box{lp.anchor_end ? lp.x - w : lp.x, lp.y - 0.95 * L_.font_px, w, 1.2 * L_.font_px};
    if (opt_.labels == PlotLabels::automatic &&
        std::any_of(label_boxes_.begin(), label_boxes_.end(), [&](const LabelBox& b) { return b.overlaps(box); }))
      return;
    label_boxes_.push_back(box);
    label(lp.x, lp.y, text,
          "font-family:sans-serif;font-weight:bold;font-size:" + num(L_.font_px) + "px;fill:" + colour +
              (front ? "" : ";fill-opacity:0.6"),
          lp.anchor_end ? "end" : "start");
  }

  /// Axis k: its line (solid or dashed), an arrow head unless seen nearly end-on, its label.
  void axis(int k, SvgPath& solid, SvgPath& dashed, SvgPath& heads) {
    static const char* const names[3] = {"X", "Y", "Z"};
    const Vector3d e = Vector3d::Unit(k);
    const ScreenPoint tip = cam_.project(kAxisReach * e);
    const double dx = tip.x - cam_.cx, dy = tip.y - cam_.cy;
    const double len = detail::screen_length(dx, dy);
    SvgPath& d = e.dot(cam_.view) >= 0 ? solid : dashed;
    d.move_to(cam_.cx, cam_.cy);
    d.line_to(tip.x, tip.y);
    const double ux = len > 1e-9 ? dx / len : 0.0, uy = len > 1e-9 ? dy / len : -1.0;
    if (len > 0.15 * cam_.radius) {
      const double h = 2.2 * L_.marker_radius, w = 0.8 * L_.marker_radius;
      heads.move_to(tip.x + ux * 0.6 * h, tip.y + uy * 0.6 * h);
      heads.line_to(tip.x - ux * 0.4 * h - uy * w, tip.y - uy * 0.4 * h + ux * w);
      heads.line_to(tip.x - ux * 0.4 * h + uy * w, tip.y - uy * 0.4 * h - ux * w);
      heads.close();
    }
    const double gap = 1.6 * L_.font_px;
    label(tip.x + ux * gap, tip.y + uy * gap + 0.35 * L_.font_px, names[k],
          "font-family:sans-serif;font-style:italic;font-size:" + num(1.1 * L_.font_px) + "px;fill:" + kAxisColour,
          "middle");
  }

  /// The density the ramp's darkest colour stands for: the 98th percentile of the visited cells'
  /// densities, so that a few cells at a pole, where a dense curve passes most often, do not
  /// wash the rest out (denser cells take the darkest colour).
  static double ramp_top(const DwellRaster& raster) {
    std::vector<double> visited;
    for (std::size_t row = 0; row < raster.cells; ++row)
      for (std::size_t col = 0; col < raster.cells; ++col)
        if (raster.time[raster.index(col, row)] > 0) visited.push_back(raster.density(col, row));
    if (visited.empty()) return 0.0;
    const std::size_t at = static_cast<std::size_t>(0.98 * static_cast<double>(visited.size() - 1));
    std::nth_element(visited.begin(), visited.begin() + static_cast<std::ptrdiff_t>(at), visited.end());
    return visited[at];
  }

  /// The density view's ramp: "0", ten steps of the colours, the largest density, the unit.
  void legend_ramp(LegendPen& pen) {
    legend_text(pen, "time per sr: 0");
    pen.x -= 0.8 * L_.font_px;
    const double step = 0.5 * L_.font_px, h = 0.8 * L_.font_px;
    for (int k = 0; k < 10; ++k) {
      svg_.rect(pen.x, pen.mid(L_) - 0.5 * h, step, h, std::string("stroke:none;fill:") + viridis_colour((k + 0.5) / 10.0));
      pen.x += step;
    }
    pen.x += 0.4 * L_.font_px;
    char peak[32];
    std::snprintf(peak, sizeof peak, "%.3g", peak_density_);
    legend_text(pen, std::string(peak) + "+ of the period");
  }

  void legend_text(LegendPen& pen, const std::string& t) {
    svg_.text(pen.x, pen.y, t, "font-family:sans-serif;font-size:" + num(0.9 * L_.font_px) + "px;fill:#333333");
    pen.x += 0.5 * L_.font_px * static_cast<double>(t.size()) + 1.2 * L_.font_px;  // rough text width
  }
  void legend_line(LegendPen& pen, const std::string& style, const std::string& t) {
    svg_.line(pen.x, pen.mid(L_), pen.x + 1.8 * L_.font_px, pen.mid(L_), style);
    pen.x += 2.2 * L_.font_px;
    legend_text(pen, t);
  }
  /// After a mark of radius r: the text beside it.
  void legend_mark(LegendPen& pen, double r, const std::string& t) {
    pen.x += 2 * r + 0.4 * L_.font_px;
    legend_text(pen, t);
  }

  const PlotOptions& opt_;
  const PlotLayout L_;
  const SphereView& cam_;
  SvgWriter svg_;
  const double lw_;  // base line width
  HemisphereSplit grid_eq_, grid_mer_;
  bool have_crossing_ = false, have_tangency_ = false;
  double peak_density_ = 0.0;  // the density view's largest cell density
};

}  // namespace detail

namespace detail {

/// "view from az A deg, el E deg[ (REASON)]", whole degrees.
inline std::string view_note(const PlotOptions& o, const std::string& reason) {
  const double deg = 180.0 / Constants<double>::pi();
  auto whole = [](double v) { return std::to_string(static_cast<long>(std::lround(v))); };
  return "view from az " + whole(o.azimuth * deg) + " deg, el " + whole(o.elevation * deg) + " deg" +
         (reason.empty() ? "" : " (" + reason + ")");
}

}  // namespace detail

/// The picture (see header): the view, then the layers back to front.
inline std::string render_sphere_svg(const Trajectory<double>& trajectory, const std::vector<Node>& nodes,
                                     const std::vector<Cusp>& cusps, const PlotOptions& options) {
  const std::vector<Vector3d> points(trajectory.points.begin(), trajectory.points.end());
  PlotOptions o = options;
  std::string reason;
  if (o.view_from_curve) {
    // Rounded to whole degrees: the view drawn is the one the note states (`--view AZ,EL` draws
    // it again), and last-bit differences of the sums (native or WebAssembly) do not move it.
    const CurveView view = view_of_curve(points, trajectory.closed);
    const double deg = Constants<double>::pi() / 180.0;
    o.azimuth = std::round(view.azimuth() / deg) * deg;
    o.elevation = std::round(view.elevation() / deg) * deg;
    reason = view.reason;
  }
  const MarkChoice marks = choose_marks(o.markers, nodes.size(), cusps.size());
  detail::SphereCanvas canvas(o);
  canvas.disc();
  const bool density = o.style == PlotStyle::density;
  const SphereView& cam = canvas.camera();
  if (density) canvas.dwell(dwell_raster(points, cam.view, cam.right, cam.up, kDwellCells));
  canvas.grid_back();
  const HemisphereSplit curve = density ? HemisphereSplit{} : canvas.split(points, trajectory.closed);
  canvas.curve_back(curve);
  canvas.outline_and_grid_front();
  canvas.axes();
  canvas.curve_front(curve);
  if (marks.draw) {
    canvas.node_markers(nodes);
    canvas.cusp_markers(cusps);
  }
  canvas.legend(marks.draw && !cusps.empty());
  canvas.notes(detail::view_note(o, reason), marks);
  canvas.caption();
  return canvas.finish();
}

}  // namespace sphtroch
