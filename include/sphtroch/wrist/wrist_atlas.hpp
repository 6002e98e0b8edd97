// sphtroch/wrist/wrist_atlas.hpp — the critical curve D(u) = 0 of a 2-motor wrist (the fold
// function of wrist_critical.hpp) enclosed on its whole motor torus: the cells of a grid where D
// may vanish (every other cell proved D != 0), a fold point proved in each, and the fold set on the
// sphere as polylines through those points, with the enclosure's width.
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   const sphtroch::WristAtlasResult r = sphtroch::wrist_fold_atlas(wrist, 0.1);
//   r.polylines.size();   // 4 closed loops: n u2 = 0, pi, 2 pi, 3 pi, the circles z = cos(1 +- 0.5)
//
// Method: the torus (wrist_ik's start grid, shifted by kWristStartOffset of a period) is divided into
// N_1 x N_2 cells, N_j = pieces_j 2^L_j the least with each cell at most `width` radians of joint
// motion (its side times sum_i |C_ij|); ranges of cells are bisected from the start boxes down, and
// a range is dropped when D's enclosure (natural extension met with the mean-value form) excludes 0.
// A cell left is resolved: a fold point proved in it (Newton along grad D from its centre, then the
// Krawczyk step on that line: WristCritical::fold_point_at; kept when its box lies in the cell), else
// its halves, ... down to kWristAtlasResolveDepth halvings: dropped when every piece excludes 0;
// else a fold point within twice the cell's width of its centre (the curve clipping a corner), or
// the cell is kept without a point. Polylines: from each cell with a point not yet drawn, walk to an
// unvisited 8-adjacent cell with a point (modulo the periods; edge neighbours first), both ways.
// Cusps along the polylines are estimated by wrist_cusps.hpp (not a claim).
// Guarantee: every u with D(u) = 0 lies in a listed cell; each listed point has D = 0 within its
// 1e-12 box; when `certified` (every cell has its point, no budget stop) every fold point P(u) lies
// within `enclosure` radians of a listed point (the largest angle from a cell's point to its image
// box). The polylines' segments are a drawing of the order, not a claim.
// Cost: refused (InvalidInput "width") when N_1 N_2 > kMaxWristAtlasCells or width is outside
// [kWristAtlasMinWidth, 1]; wrist_ik's start-grid bound (InvalidInput "coupling"); a search stops,
// not certified, after max_boxes boxes. 3 motors: InvalidInput "coupling".
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_atlas.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/krawczyk.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_atlas_result.hpp"
#include "sphtroch/wrist/wrist_cap.hpp"  // wrist_chord_angle_above
#include "sphtroch/wrist/wrist_critical.hpp"
#include "sphtroch/wrist/wrist_cusps.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_ik_search.hpp"  // kWristStartOffset, kWristStartWidth

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// The cells' default width and the range accepted (radians of joint motion).
constexpr double kWristAtlasDefaultWidth = 0.05;
constexpr double kWristAtlasMinWidth = 1e-3;
/// Grids of more cells are refused up front.
constexpr double kMaxWristAtlasCells = 4e7;
/// The search's default budget of boxes evaluated (then it stops, not certified).
constexpr std::size_t kMaxWristAtlasBoxes = 4000000;
/// A cell without a proved point is halved this many times at most before it is kept without one.
constexpr int kWristAtlasResolveDepth = 10;

/// The grid's cells N_1 N_2 for this width (see wrist_atlas.hpp's header).
inline std::array<std::size_t, 2> wrist_atlas_grid(const Wrist& wrist, double width) {
  std::array<std::size_t, 2> n{};
  for (std::size_t j = 0; j < 2; ++j) {
    const double length = wrist.period(j) * wrist.joint_speed(j);
    double cells = std::max(1.0, std::ceil(length / kWristStartWidth));
    while (length / cells > width && cells < 1e12) cells *= 2;
    n[j] = static_cast<std::size_t>(cells);
  }
  return n;
}

/// Refuses (InvalidInput "width") a width outside [kWristAtlasMinWidth, 1] or a grid above kMaxWristAtlasCells.
inline void check_wrist_atlas_cost(const Wrist& wrist, double width) {
  if (!(width >= kWristAtlasMinWidth && width <= 1.0))
    throw InvalidInput("width", number_text(width), "outside [0.001, 1]", "radians of joint motion per cell, 0.001 to 1 (default 0.05)");
  const std::array<std::size_t, 2> n = wrist_atlas_grid(wrist, width);
  const double cells = static_cast<double>(n[0]) * static_cast<double>(n[1]);
  if (cells > kMaxWristAtlasCells)
    throw InvalidInput("width", number_text(width), "too costly: the torus needs a grid of " + number_text(cells) + " cells",
                       "a grid of at most " + number_text(kMaxWristAtlasCells) + " cells: a larger width, or smaller rates or denominators");
}

class WristAtlasSearch {
  using Box = IntervalBox<2>;
  using Cell = std::pair<std::size_t, std::size_t>;

 public:
  WristAtlasSearch(const Wrist& wrist, double width, std::size_t max_boxes)
      : critical_(make_critical(wrist)), n_(wrist_atlas_grid(wrist, width)), max_boxes_(max_boxes) {
    const RoundingGuard upward;
    const Vector3d a = wrist.axis();
    inv_a_ = 1.0 / CGAL::sqrt(Interval(a.x()) * a.x() + Interval(a.y()) * a.y() + Interval(a.z()) * a.z());
    for (std::size_t j = 0; j < 2; ++j) {
      periods_[j] = wrist.period(j);
      lo_[j] = -kWristStartOffset * periods_[j];
      const Interval two_pi(6.283185307179586, std::nextafter(6.283185307179586, 7.0));
      hi_[j] = lo_[j] + (two_pi * Interval(static_cast<double>(wrist.period_turns(j)))).sup();
      cell_width_ = std::max(cell_width_, periods_[j] * wrist.joint_speed(j) / static_cast<double>(n_[j]));
      pieces_[j] = static_cast<std::size_t>(std::max(1.0, std::ceil(periods_[j] * wrist.joint_speed(j) / kWristStartWidth)));
    }
  }

  WristAtlasResult run() {
    const RoundingGuard upward;
    std::vector<std::array<std::size_t, 4>> stack;  // cell ranges [a0, a1) x [b0, b1)
    const std::size_t p0 = pieces_[0], p1 = pieces_[1];  // the start grid: N_j = pieces_j 2^L_j
    for (std::size_t a = 0; a < p0; ++a)
      for (std::size_t b = 0; b < p1; ++b) stack.push_back({a * (n_[0] / p0), (a + 1) * (n_[0] / p0), b * (n_[1] / p1), (b + 1) * (n_[1] / p1)});
    while (!stack.empty() && boxes_ < max_boxes_) {
      const auto r = stack.back();
      stack.pop_back();
      if (!may_vanish_over(box_of(r[0], r[1], r[2], r[3]))) continue;
      if (r[1] - r[0] == 1 && r[3] - r[2] == 1) {
        keep_cell(r[0], r[2]);
        continue;
      }
      const bool first = r[3] - r[2] == 1 || (r[1] - r[0] > 1 && (r[1] - r[0]) * n_[1] >= (r[3] - r[2]) * n_[0]);
      const std::size_t m = first ? (r[0] + r[1]) / 2 : (r[2] + r[3]) / 2;
      stack.push_back(first ? std::array<std::size_t, 4>{m, r[1], r[2], r[3]} : std::array<std::size_t, 4>{r[0], r[1], m, r[3]});
      stack.push_back(first ? std::array<std::size_t, 4>{r[0], m, r[2], r[3]} : std::array<std::size_t, 4>{r[0], r[1], r[2], m});
    }
    return result(!stack.empty());
  }

 private:
  static WristCritical make_critical(const Wrist& wrist) {
    const RoundingGuard upward;
    return WristCritical(wrist);
  }

  /// Cell a's edge of motor j (the last edge is hi_j).
  double edge(std::size_t j, std::size_t a) const {
    if (a >= n_[j]) return hi_[j];
    return lo_[j] + (hi_[j] - lo_[j]) * static_cast<double>(a) / static_cast<double>(n_[j]);
  }
  Box box_of(std::size_t a0, std::size_t a1, std::size_t b0, std::size_t b1) const {
    return {Interval(edge(0, a0), edge(0, a1)), Interval(edge(1, b0), edge(1, b1))};
  }

  /// Whether D's enclosure over x (natural met with the mean-value form) holds 0.
  bool may_vanish_over(const Box& x) {
    ++boxes_;
    const WristFoldValue<Interval> vx = critical_.over(x);
    const PointN<2> c = centre<2>(x);
    const WristFoldValue<Interval> vc = critical_.over(point_box<2>(c));
    const Box dx{x[0] - c[0], x[1] - c[1]};
    const Interval mv = mean_value<2>(vc.det, vx.det_gradient.data(), dx.data());
    return may_vanish(vx.det) && may_vanish(mv);
  }

  /// A fold point proved inside x (Newton from its centre along grad D, the Krawczyk step), or,
  /// when not `inside`, within twice x's width of its centre.
  std::optional<Box> point_in(const Box& x, bool inside = true) const {
    const PointN<2> c = centre<2>(x);
    const WristFoldValue<double> v = critical_.at(c);
    const PointN<2> d{v.det_gradient[0], v.det_gradient[1]};
    const double reach = (inside ? 1.0 : 2.0) * std::max(x[0].sup() - x[0].inf(), x[1].sup() - x[1].inf());
    const std::optional<Box> p = critical_.fold_point_on_line(c, d, reach);
    if (!p || !inside) return p;
    for (std::size_t j = 0; j < 2; ++j)
      if ((*p)[j].inf() < x[j].inf() || (*p)[j].sup() > x[j].sup()) return std::nullopt;
    return p;
  }

  /// x's point, or its halves' (recursively to `depth`); excluded when every piece excludes 0.
  /// {excluded, point}.
  std::pair<bool, std::optional<Box>> resolve(const Box& x, int depth) {
    if (const auto p = point_in(x)) return {false, p};
    if (depth == 0 || boxes_ >= max_boxes_) return {false, std::nullopt};
    const std::size_t j = (x[0].sup() - x[0].inf()) >= (x[1].sup() - x[1].inf()) ? 0 : 1;
    Box halves[2] = {x, x};
    halves[0][j] = Interval(x[j].inf(), mid(x[j]));
    halves[1][j] = Interval(mid(x[j]), x[j].sup());
    bool excluded = true;
    for (const Box& h : halves) {
      if (!may_vanish_over(h)) continue;
      const auto [gone, point] = resolve(h, depth - 1);
      if (point) return {false, point};
      excluded = excluded && gone;
    }
    return {excluded, std::nullopt};
  }

  void keep_cell(std::size_t a, std::size_t b) {
    const Box x = box_of(a, a + 1, b, b + 1);
    auto [excluded, point] = resolve(x, kWristAtlasResolveDepth);
    if (excluded) return;
    if (!point) point = point_in(x, false);  // the curve clips a corner: a point just outside bounds the cell as well
    WristFoldCell cell;
    const WristFoldValue<Interval> v = critical_.over(x);
    for (std::size_t j = 0; j < 2; ++j) cell.motors[j] = {x[j].inf(), x[j].sup()};
    for (int k = 0; k < 3; ++k) cell.image[k] = {v.point[k].inf(), v.point[k].sup()};
    if (point) set_point(cell, *point, v);
    index_[{a, b}] = cells_.size();
    cells_.push_back(cell);
  }

  /// The cell's point (unit P at the proved box's middle) and the angle from it to the cell's image.
  void set_point(WristFoldCell& cell, const Box& p, const WristFoldValue<Interval>& over_cell) {
    const WristFoldValue<Interval> vp = critical_.over(p);
    Vector3d q(mid(vp.point[0]), mid(vp.point[1]), mid(vp.point[2]));
    q.normalize();
    cell.has_point = true;
    cell.point = {q.x(), q.y(), q.z()};
    cell.point_motors = {mid(p[0]), mid(p[1])};
    Interval chord2(0.0);  // |P - P_v|^2 / |a|^2 over the cell, P_v the proved point's P
    for (int k = 0; k < 3; ++k) {
      const double r = radius(over_cell.point[k] - vp.point[k]);
      chord2 += Interval(r) * r;
    }
    chord2 *= inv_a_ * inv_a_;
    enclosure_ = std::max(enclosure_, wrist_chord_angle_above(chord2.sup()));
  }

  /// The 8 neighbours of a cell (modulo the grid) that are kept and have a point; edge ones first.
  std::vector<Cell> neighbours(const Cell& c) const {
    std::vector<Cell> out;
    for (int pass = 0; pass < 2; ++pass)
      for (int da = -1; da <= 1; ++da)
        for (int db = -1; db <= 1; ++db) {
          if ((da == 0 && db == 0) || ((da == 0 || db == 0) != (pass == 0))) continue;
          const Cell nb{(c.first + n_[0] + da) % n_[0], (c.second + n_[1] + db) % n_[1]};
          const auto it = index_.find(nb);
          if (it != index_.end() && cells_[it->second].has_point && nb != c) out.push_back(nb);
        }
    return out;
  }

  /// Walks from `from` to unvisited neighbours while there are any; the cells in order.
  std::vector<std::size_t> walk(const Cell& from, std::map<Cell, bool>& visited) const {
    std::vector<std::size_t> out;
    Cell at = from;
    while (true) {
      const std::vector<Cell> next = neighbours(at);
      const auto it = std::find_if(next.begin(), next.end(), [&](const Cell& c) { return !visited[c]; });
      if (it == next.end()) return out;
      at = *it;
      visited[at] = true;
      out.push_back(index_.at(at));
    }
  }

  void draw_polylines() {
    std::map<Cell, bool> visited;
    for (const auto& [cell, i] : index_) {
      if (!cells_[i].has_point || visited[cell]) continue;
      visited[cell] = true;
      const std::vector<std::size_t> forward = walk(cell, visited), backward = walk(cell, visited);
      WristFoldPolyline line;
      line.cells.assign(backward.rbegin(), backward.rend());
      line.cells.push_back(i);
      line.cells.insert(line.cells.end(), forward.begin(), forward.end());
      const auto key = [&](std::size_t k) { return cell_of_.at(k); };
      if (line.cells.size() > 2) {
        const std::vector<Cell> around = neighbours(key(line.cells.back()));
        line.closed = std::find(around.begin(), around.end(), key(line.cells.front())) != around.end();
      }
      polylines_.push_back(line);
    }
  }

  WristAtlasResult result(bool stopped) {
    for (const auto& [cell, i] : index_) cell_of_[i] = cell;
    draw_polylines();
    WristAtlasResult r;
    r.cells = cells_;
    r.polylines = polylines_;
    r.cell_width = cell_width_;
    r.enclosure = enclosure_;
    r.periods.assign(periods_.begin(), periods_.end());
    r.boxes = boxes_;
    r.cells_without_point = static_cast<std::size_t>(std::count_if(cells_.begin(), cells_.end(), [](const WristFoldCell& c) { return !c.has_point; }));
    r.complete = !stopped;
    r.certified = !stopped && r.cells_without_point == 0;
    if (stopped) r.why = "the search stopped at its budget of " + std::to_string(max_boxes_) + " boxes";
    else if (r.cells_without_point > 0)
      r.why = std::to_string(r.cells_without_point) + " cell(s) where D may vanish hold no proved fold point (a degenerate fold, or none there)";
    return r;
  }

  WristCritical critical_;
  std::array<std::size_t, 2> n_;
  std::size_t max_boxes_;
  std::array<std::size_t, 2> pieces_{};
  Interval inv_a_{1.0};
  std::array<double, 2> periods_{}, lo_{}, hi_{};
  double cell_width_ = 0, enclosure_ = 0;
  std::vector<WristFoldCell> cells_;
  std::map<Cell, std::size_t> index_;
  std::map<std::size_t, Cell> cell_of_;
  std::vector<WristFoldPolyline> polylines_;
  std::size_t boxes_ = 0;
};

/// The fold atlas of a 2-motor wrist (see header): cells of at most `width` radians of joint
/// motion. REQUIRES 2 motors (InvalidInput "coupling"); refuses beyond the cost bounds. In the
/// caller's rounding mode.
inline WristAtlasResult wrist_fold_atlas(const Wrist& wrist, double width = kWristAtlasDefaultWidth,
                                         std::size_t max_boxes = kMaxWristAtlasBoxes) {
  if (wrist.motors() != 2)
    throw InvalidInput("coupling", wrist.coupling_text(), "3 motors: the fold atlas (a curve on the motor torus) is a 2-motor notion",
                       "a 2-column coupling (the tool axis driven by 2 motors)");
  check_wrist_ik_cost(wrist);
  check_wrist_atlas_cost(wrist, width);
  if (wrist_fold_vanishes_everywhere(wrist)) {  // a degenerate wrist: every point a fold (see there)
    WristAtlasResult r;
    for (std::size_t j = 0; j < 2; ++j) r.periods.push_back(wrist.period(j));
    r.why = "the fold function D vanishes on the whole motor torus (the map u -> P has rank below 2 everywhere: "
            "a degenerate wrist); its fold set is its whole image, no enclosure is proved";
    return r;
  }
  WristAtlasResult r = WristAtlasSearch(wrist, width, max_boxes).run();
  r.cusps = wrist_fold_cusps(wrist, r);
  return r;
}

}  // namespace sphtroch
