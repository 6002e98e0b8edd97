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
//     every mark beside it (label_position); `none` none; `automatic` (the default) labels the
//     marks in order (the nodes on the front half, then those on the back, then the cusps), each at
//     the first of sixteen places around its mark (label_position's turns 0, 1, -1, 2, -2, 3, -3,
//     4: outward first, then turning by 45 degrees either way; beside the mark, then 0.6 em
//     farther) whose box keeps kLabelGapEm em (12.4 px at the default size) from every label
//     already placed and stays between the legend band and the text band; a label with no such
//     place is left out, and a note says how many labels the picture shows. The boxes bound what a browser draws in
//     sans-serif bold (e.g. DejaVu Sans Bold: N 0.84 em, digits 0.70 em, ascent 0.93 em, descent
//     0.24 em): 0.86 em for the letter, 0.72 em per digit, from 0.95 em above the baseline to
//     0.25 em below. The camera follows the curve, so marks gather where it is dense: the gap, not
//     the view, keeps their labels apart.
//  5. The caption is escaped (svg.hpp), so any text is safe; the document is valid SVG 1.1. The
//     <title> holds the caption whole.
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
//  8. Layout (plot_layout, plot_text_band): the picture is size_px wide; the legend band along the
//     top, then the sphere with its axes fill a square size_px high; under it the text band: the
//     notes (right-aligned, 0.8 em), then the caption (centred, 1 em), each wrapped to the width
//     (text_layout.hpp), so the height is size_px plus the band's lines, rounded up to a whole px.
//     Every text of the picture is at least kMinTextPx (9.5 px), and nothing in the text band
//     reaches the sphere's disc or its axes.
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
#include "sphtroch/draw/text_layout.hpp"
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

/// The smallest text of the picture, px (contract 8).
constexpr double kMinTextPx = 9.5;
/// The least gap between the boxes of two labels in automatic labelling, in em of the label font
/// (contract 4).
constexpr double kLabelGapEm = 1.0;

/// Sizes derived from the options: the camera, marker and font sizes, the bands (contract 8).
struct PlotLayout {
  SphereView sphere;
  double width = 0.0;
  double height = 0.0;          // the square's (plot_layout); plot_text_band adds the text band
  double font_px = 12.0;        // labels and the caption; the legend 0.9x, the notes 0.8x (at least kMinTextPx)
  double marker_radius = 5.0;   // node ring radius, cusp triangle half-size
  double legend_bottom = 0.0;   // the legend band above the sphere ends here
  double band_top = 0.0;        // the text band under the sphere begins here
};

/// REQUIRES: valid options (throws InvalidInput naming the field otherwise).
inline PlotLayout plot_layout(const PlotOptions& options);

/// A line of the text band under the sphere: its text, baseline position, size, and whether it
/// is a note (right-aligned at x) or the caption (centred at x).
struct BandLine {
  std::string text;
  double x = 0.0, y = 0.0, font_px = 0.0;
  bool note = false;
};

/// The text band (contract 8): `notes` (one line each, wrapped when too wide) then the caption,
/// wrapped; sets layout.height to the picture's whole height.
inline std::vector<BandLine> plot_text_band(PlotLayout& layout, const std::vector<std::string>& notes,
                                            const std::string& caption);

/// Where the label of a marker at `at` goes: pushed away from the sphere centre, past the mark,
/// then turned by `turn` x 45 degrees, 0.6 em farther when `farther` (contract 4's other places).
/// `anchor_end` is true when the text should end there (labels left of the mark).
struct LabelPlacement {
  double x = 0.0, y = 0.0;
  bool anchor_end = false;
};
inline LabelPlacement label_position(const PlotLayout& layout, const ScreenPoint& at, int turn = 0, bool farther = false);

/// A mark's label where place_labels put it.
struct PlacedLabel {
  std::string text;       // "N3", "C1"
  LabelPlacement at;
  const char* colour;     // the mark's
  bool front = true;      // the mark is on the front half
  bool node = true;       // a node's label (else a cusp's)
};

/// The labels of the marks (contract 4) and how many marks there are to label.
struct LabelPlan {
  std::vector<PlacedLabel> labels;
  std::size_t wanted = 0;
};
inline LabelPlan place_labels(const PlotLayout& layout, const std::vector<Node>& nodes, const std::vector<Cusp>& cusps,
                              PlotLabels mode);

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
  throw InvalidInput(field, std::string(text), "not a label mode", "auto (kept one em apart), numbers (all), none");
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
  l.font_px = std::max(kMinTextPx, o.size_px / 42.0);
  l.marker_radius = std::max(3.5, o.size_px / 95.0);
  const double legend_band = o.draw_legend ? 1.7 * l.font_px : 0.3 * l.font_px;
  // Under the lowest mark, room for its label at label_position's turn 0 (at most 0.4 ring radii
  // and 0.9 em below the ring's centre): the text band never meets a label.
  const double label_margin = 0.4 * l.marker_radius + 0.9 * l.font_px;
  const double avail_h = l.height - legend_band - label_margin;
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
  l.legend_bottom = legend_band;
  l.band_top = l.height;
  return l;
}

inline std::vector<BandLine> plot_text_band(PlotLayout& layout, const std::vector<std::string>& notes,
                                            const std::string& caption) {
  const double margin = 0.4 * layout.font_px, width = layout.width - 2 * margin;
  const double note_px = std::max(kMinTextPx, 0.8 * layout.font_px), caption_px = std::max(kMinTextPx, layout.font_px);
  std::vector<BandLine> lines;
  double y = layout.band_top;
  for (const std::string& note : notes)
    for (const std::string& line : wrap_text(note, width, note_px)) {
      y += 1.25 * note_px;
      lines.push_back({line, layout.width - margin, y, note_px, true});
    }
  if (!caption.empty()) y += 0.3 * caption_px;
  for (const std::string& line : wrap_text(caption, width, caption_px)) {
    y += 1.25 * caption_px;
    lines.push_back({line, 0.5 * layout.width, y, caption_px, false});
  }
  // The last line's descent (0.24 em) and a margin.
  layout.height = std::ceil(y + (lines.empty() ? 0.0 : 0.6 * lines.back().font_px));
  return lines;
}

inline LabelPlacement label_position(const PlotLayout& layout, const ScreenPoint& at, int turn, bool farther) {
  // Outward from the centre, bent towards the upper right so that a mark on an axis (a pole,
  // the centre) does not put its label on the axis line; then turned.
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
  if (turn % 8 != 0) {  // by turn x 45 degrees: cosine and sine exact at the quarter turns
    constexpr double h = 0.70710678118654752440;
    static const double cos_sin[8][2] = {{1, 0}, {h, h}, {0, 1}, {-h, h}, {-1, 0}, {-h, -h}, {0, -1}, {h, -h}};
    const double* cs = cos_sin[((turn % 8) + 8) % 8];
    const double rx = cs[0] * dx - cs[1] * dy, ry = cs[1] * dx + cs[0] * dy;
    dx = rx;
    dy = ry;
  }
  const double gap = layout.marker_radius + (farther ? 0.9 : 0.3) * layout.font_px;
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

/// A box in picture px (x, y: top left).
struct Box {
  double x, y, w, h;
  /// The distance between the two boxes (0 when they touch or overlap).
  double gap(const Box& o) const {
    const double dx = std::max({0.0, o.x - (x + w), x - (o.x + o.w)}), dy = std::max({0.0, o.y - (y + h), y - (o.y + o.h)});
    return screen_length(dx, dy);
  }
};

/// The box of a label of `chars` characters placed at p (contract 4's bound on the glyphs).
inline Box label_box(const PlotLayout& layout, const LabelPlacement& p, std::size_t chars) {
  const double w = layout.font_px * (0.86 + 0.72 * static_cast<double>(chars - 1));
  return Box{p.anchor_end ? p.x - w : p.x, p.y - 0.95 * layout.font_px, w, 1.2 * layout.font_px};
}

/// Automatic labelling's first free place for `text` at mark `at` (contract 4): a place whose box
/// keeps the gap from `placed`, inside the picture between the bands; none: false.
inline bool free_place(const PlotLayout& layout, const ScreenPoint& at, const std::string& text, const std::vector<Box>& placed,
                       LabelPlacement& out) {
  const double gap = kLabelGapEm * layout.font_px;
  for (const bool farther : {false, true})
    for (const int turn : {0, 1, -1, 2, -2, 3, -3, 4}) {
      const LabelPlacement p = label_position(layout, at, turn, farther);
      const Box b = label_box(layout, p, text.size());
      if (b.x < 0 || b.x + b.w > layout.width || b.y < layout.legend_bottom || b.y + b.h > layout.band_top) continue;
      if (std::any_of(placed.begin(), placed.end(), [&](const Box& o) { return b.gap(o) < gap; })) continue;
      out = p;
      return true;
    }
  return false;
}

}  // namespace detail

inline LabelPlan place_labels(const PlotLayout& layout, const std::vector<Node>& nodes, const std::vector<Cusp>& cusps,
                              PlotLabels mode) {
  struct Mark {
    ScreenPoint at;
    PlacedLabel label;
  };
  std::vector<Mark> marks;  // in labelling order: front nodes, back nodes, cusps
  for (const bool front_half : {true, false})
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const ScreenPoint s = layout.sphere.project(nodes[i].position);
      const bool front = s.depth >= -kSilhouetteTolerance;
      if (front != front_half) continue;
      const char* colour = nodes[i].kind == NodeKind::crossing ? detail::kCrossingColour : detail::kTangencyColour;
      marks.push_back({s, {"N" + std::to_string(i + 1), {}, colour, front, true}});
    }
  for (std::size_t j = 0; j < cusps.size(); ++j) {
    const ScreenPoint s = layout.sphere.project(cusps[j].position);
    marks.push_back({s, {"C" + std::to_string(j + 1), {}, detail::kCuspColour, s.depth >= -kSilhouetteTolerance, false}});
  }
  LabelPlan plan;
  plan.wanted = marks.size();
  if (mode == PlotLabels::none) return plan;
  std::vector<detail::Box> placed;
  for (const Mark& m : marks) {
    PlacedLabel label = m.label;
    if (mode == PlotLabels::numbers) label.at = label_position(layout, m.at);
    else if (!detail::free_place(layout, m.at, label.text, placed, label.at)) continue;
    placed.push_back(detail::label_box(layout, label.at, label.text.size()));
    plan.labels.push_back(std::move(label));
  }
  return plan;
}

namespace detail {

/// The sphere picture being drawn (contracts 1-8): layout (with its text band: plot_text_band),
/// view, writer and base line width, with one method per layer. render_sphere_svg calls them back
/// to front.
class SphereCanvas {
 public:
  SphereCanvas(const PlotOptions& options, const PlotLayout& layout)
      : opt_(options), L_(layout), cam_(L_.sphere), svg_(L_.width, L_.height, options.decimals),
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

  /// Node i as a ring, coloured by kind, faded on the back half (contract 4).
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
  }

  /// The nodes' labels as `plan` placed them (contract 4).
  void node_labels(const LabelPlan& plan) {
    svg_.begin_group("", "id=\"node-labels\"");
    for (const PlacedLabel& l : plan.labels)
      if (l.node) marker_label(l);
    svg_.end_group();
  }

  /// Cusp j as a triangle, with its label when `plan` placed one (contract 4).
  void cusp_markers(const std::vector<Cusp>& cusps, const LabelPlan& plan) {
    svg_.begin_group("", "id=\"cusps\"");
    for (std::size_t j = 0; j < cusps.size(); ++j) {
      SPHTROCH_ASSERT(std::isfinite(cusps[j].position.norm()), "render_sphere_svg: finite cusp position");
      const ScreenPoint s = cam_.project(cusps[j].position);
      const bool front = s.depth >= -kSilhouetteTolerance;
      svg_.path(triangle_path(s.x, s.y, 1.1 * L_.marker_radius, dec()),
                stroke(kCuspColour, 1.6) + ";stroke-linejoin:round" + (front ? "" : back_mark()));
    }
    for (const PlacedLabel& l : plan.labels)
      if (!l.node) marker_label(l);
    svg_.end_group();
  }

  /// The text band under the sphere (contract 8): the notes, right-aligned, then the caption.
  void text_band(const std::vector<BandLine>& lines) {
    svg_.begin_group("", "id=\"caption\"");
    for (const BandLine& line : lines) {
      const std::string style = "font-family:sans-serif;font-size:" + num(line.font_px) + "px;fill:" + (line.note ? "#555555" : "#111111");
      svg_.text(line.x, line.y, line.text, style, line.note ? "end" : "middle");
    }
    svg_.end_group();
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

  HemisphereSplit split(const std::vector<Vector3d>& points, bool closed) const {
    return split_by_silhouette(points, closed, cam_.view, opt_.max_arc_step);
  }
  std::string finish() { return svg_.finish(); }
  const SphereView& camera() const { return cam_; }

 private:
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
  /// A mark's label where place_labels put it, faded on the back half.
  void marker_label(const PlacedLabel& l) {
    label(l.at.x, l.at.y, l.text,
          "font-family:sans-serif;font-weight:bold;font-size:" + num(L_.font_px) + "px;fill:" + l.colour +
              (l.front ? "" : ";fill-opacity:0.6"),
          l.at.anchor_end ? "end" : "start");
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
    const double size = std::max(kMinTextPx, 0.9 * L_.font_px);
    svg_.text(pen.x, pen.y, t, "font-family:sans-serif;font-size:" + num(size) + "px;fill:#333333");
    pen.x += text_width_em(t) * size + 1.2 * L_.font_px;
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

/// The notes of the text band, top to bottom: what the markers, the labels and the density view
/// leave out, then the view (contracts 4, 6, 7).
inline std::vector<std::string> plot_notes(const PlotOptions& o, const std::string& view, const MarkChoice& marks,
                                           const LabelPlan& plan) {
  std::vector<std::string> lines;
  if (!marks.note.empty()) lines.push_back(marks.note + " (--markers all draws them)");
  if (plan.labels.size() < plan.wanted && o.labels == PlotLabels::automatic)
    lines.push_back(std::to_string(plan.labels.size()) + " of " + std::to_string(plan.wanted) +
                    " labels (kept apart; all: --labels numbers, the list: sphtroch nodes)");
  if (o.style == PlotStyle::density)
    lines.push_back("density view: the front half's dwell in " + std::to_string(kDwellCells) + " x " +
                    std::to_string(kDwellCells) + " cells, the back half not shown");
  lines.push_back(view);
  return lines;
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
  PlotLayout layout = plot_layout(o);
  const LabelPlan plan = marks.draw ? place_labels(layout, nodes, cusps, o.labels) : LabelPlan{};
  const std::vector<BandLine> band = plot_text_band(layout, detail::plot_notes(o, detail::view_note(o, reason), marks, plan), o.caption);
  detail::SphereCanvas canvas(o, layout);
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
    canvas.node_labels(plan);
    canvas.cusp_markers(cusps, plan);
  }
  canvas.legend(marks.draw && !cusps.empty());
  canvas.text_band(band);
  return canvas.finish();
}

}  // namespace sphtroch
