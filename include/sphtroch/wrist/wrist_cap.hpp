// sphtroch/wrist/wrist_cap.hpp — the largest spherical cap about a home direction that no fold of
// a 2-motor wrist enters: its radius (the angle from home to the nearest point P(u) with D(u) = 0,
// wrist_critical.hpp) as a certified bracket of width <= kWristCapWidth, and the inverse-kinematics
// count inside it (the same at every direction of the open cap: no fold, no change).
//
//   // the base x gear train wrist (twists 0, 1, 0.5; n = 2): folds at z = cos 1.5 and z = cos 0.5
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   const sphtroch::WristCapResult r = sphtroch::wrist_cap(wrist, sphtroch::Vector3d(std::sin(1.0), 0, std::cos(1.0)));
//   r.lower;    // <= 0.5 <= r.upper: home at polar angle 1, the folds at polar angles 0.5 and 1.5
//   *r.count;   // 4 = 2 |p|: home inside the zone
//
// Method: best-first interval branch and bound over the motor torus (the start grid of wrist_ik,
// shifted by kWristStartOffset of a period). A box is discarded when D's enclosure (natural
// extension met with the mean-value form) excludes 0 (no fold point in it), or when its lower
// bound on the angle exceeds the best upper bound. The lower bound is a lower bound of the squared
// chord q(u) = |P^(u) - h^|^2 (unit vectors, enclosed) over the box's fold points: the largest of
// q's natural extension, its mean-value form, and the mean-value form of q - lambda D (lambda =
// grad q . grad D / |grad D|^2 at the centre; q - lambda D = q on the fold, and its gradient nearly
// vanishes at the nearest fold point, so the bound's error shrinks with the square of the box);
// the angle is 2 atan(sqrt(q / (4 - q))), outward rounded. The upper bound comes from points proved
// on the fold: from the centre of each box taken, Newton along grad D in doubles, then the Krawczyk
// step of interval/krawczyk.hpp on that line (WristCritical::fold_point_at); the angle to the box
// it proves, rounded up. The box of least lower bound is taken next; the search stops when the best
// upper bound is within kWristCapWidth of it. A motor that turns the first joint only, with home
// on the z axis (exactly), changes neither D nor the angle (P(u) = Rz(C_1j u_j) P(u with u_j = 0)):
// that motor is held at 0 and the search is one-dimensional (a whole fold circle about home would
// otherwise lie at the nearest distance along its length).
// Guarantee: the nearest fold point is at an angle in [lower, upper] from home (radians); when
// radius_certified, upper - lower <= kWristCapWidth. count: wrist_ik's certified count at home.
// Cost: refused up front like wrist_ik (check_wrist_ik_cost: InvalidInput "coupling" beyond
// kMaxWristStartBoxes start boxes); a search stops, not certified, after max_boxes boxes or when a
// box below kWristCapMinWidth (radians of joint motion) is taken (a degenerate fold: a whole arc of
// it at the nearest distance, or D vanishing to second order there). 3 motors: InvalidInput
// "coupling" (caps about an orientation are not available).
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_cap.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/interval_vector.hpp"
#include "sphtroch/interval/krawczyk.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_cap_result.hpp"
#include "sphtroch/wrist/wrist_critical.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_ik_search.hpp"  // kWristStartOffset, kWristStartWidth
#include "sphtroch/wrist/wrist_target.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <queue>
#include <string>
#include <vector>

namespace sphtroch {

/// The bracket's width wrist_cap aims at (radians).
constexpr double kWristCapWidth = 1e-9;
/// The cap search's default budget of boxes evaluated (then it stops, not certified).
constexpr std::size_t kMaxWristCapBoxes = 3000000;
/// Boxes narrower than this (radians of joint motion) are not split: the search stops there.
constexpr double kWristCapMinWidth = 1e-13;

namespace wrist_cap_detail {

/// A box of the torus and the lower bound of the angle to home over its fold points.
struct Item {
  double lower = 0;
  IntervalBox<2> box;
};
struct LeastLowerFirst {
  bool operator()(const Item& a, const Item& b) const { return a.lower > b.lower; }
};

/// The intersection of two enclosures of one quantity (both hold it: they meet; else a).
inline Interval meet(const Interval& a, const Interval& b) {
  const double lo = std::max(a.inf(), b.inf()), hi = std::min(a.sup(), b.sup());
  return lo <= hi ? Interval(lo, hi) : a;
}

}  // namespace wrist_cap_detail

/// The angle between unit vectors whose squared chord is q, 2 atan(sqrt(q / (4 - q))): a value
/// below it for q = q_lo (0 for q_lo <= 0) and above it for q = q_hi (pi, raised, for q_hi >= 4).
/// REQUIRES rounding upward.
inline double wrist_chord_angle_below(double q_lo) {
  if (!(q_lo > 0)) return 0.0;
  const Interval q(q_lo), gap = 4.0 - q;
  if (!(gap.inf() > 0)) return 3.141592653589793;  // below pi
  return std::max(0.0, (2.0 * interval_atan(CGAL::sqrt(q / gap))).inf());
}
inline double wrist_chord_angle_above(double q_hi) {
  const double pi_up = 3.1415926535897936;  // above pi
  if (!(q_hi > 0)) return 0.0;
  const Interval q(q_hi), gap = 4.0 - q;
  if (!(gap.inf() > 0)) return pi_up;
  return std::min(pi_up, (2.0 * interval_atan(CGAL::sqrt(q / gap))).sup());
}


/// The search of one wrist and home (see header). REQUIRES a 2-motor wrist, home finite and not 0
/// (normalised). run() in any rounding mode, once.
class WristCapSearch {
  using Item = wrist_cap_detail::Item;
  using Box = IntervalBox<2>;

 public:
  WristCapSearch(const Wrist& wrist, const Vector3d& home, std::size_t max_boxes)
      : critical_(make_critical(wrist)), max_boxes_(max_boxes) {
    const RoundingGuard upward;
    const Interval two_pi(6.283185307179586, std::nextafter(6.283185307179586, 7.0));
    const Vector3d a = wrist.axis(), h = home.normalized();
    const Interval inv_a = 1.0 / CGAL::sqrt(Interval(a.x()) * a.x() + Interval(a.y()) * a.y() + Interval(a.z()) * a.z());
    const Interval inv_h = 1.0 / CGAL::sqrt(Interval(h.x()) * h.x() + Interval(h.y()) * h.y() + Interval(h.z()) * h.z());
    inv_a_ = inv_a;
    for (int x = 0; x < 3; ++x) home_[x] = Interval(h[x]) * inv_h;
    for (std::size_t j = 0; j < 2; ++j) {
      scale_[j] = std::max(wrist.joint_speed(j), 1e-300);
      period_[j] = two_pi * Interval(static_cast<double>(wrist.period_turns(j)));
      periods_[j] = wrist.period(j);
      lo_[j] = -kWristStartOffset * periods_[j];
      hi_[j] = lo_[j] + period_[j].sup();
      pieces_[j] = static_cast<std::size_t>(std::max(1.0, std::ceil(periods_[j] * scale_[j] / kWristStartWidth)));
      about_axis_[j] = turns_first_joint_only(wrist, j) && h.x() == 0 && h.y() == 0;
      if (about_axis_[j]) pieces_[j] = 1;
    }
  }

  /// Whether motor j turns the first joint only: then P(u) = Rz(C_1j u_j) P(u with u_j = 0) and D
  /// does not depend on u_j (omega_j = C_1j z is fixed by Rz), and neither does the angle to a home
  /// on the z axis: the search runs on u_j = 0 alone.
  static bool turns_first_joint_only(const Wrist& wrist, std::size_t j) {
    for (std::size_t i = 1; i < wrist.joints(); ++i)
      if (!wrist.coupling(i, j).is_zero()) return false;
    return true;
  }

  WristCapResult run() {
    const RoundingGuard upward;
    start();
    while (!queue_.empty()) {
      const Item top = queue_.top();
      if (best_hi_ - top.lower <= kWristCapWidth) break;  // rounded up: certified
      if (boxes_ >= max_boxes_) return result("the search stopped at its budget of " + std::to_string(max_boxes_) + " boxes");
      queue_.pop();
      if (top.lower > best_hi_) continue;
      try_upper(top.box);
      if (top.lower > best_hi_) continue;
      if (scaled_width(top.box) < kWristCapMinWidth)
        return result("a box below " + number_text(kWristCapMinWidth) + " rad of joint motion is undecided near u = (" +
                      number_text(mid(top.box[0])) + ", " + number_text(mid(top.box[1])) + ") (a degenerate fold)");
      split(top.box);
    }
    return result("");
  }

 private:
  static WristCritical make_critical(const Wrist& wrist) {
    const RoundingGuard upward;
    return WristCritical(wrist);
  }

  /// q = |P^ - h^|^2 and its gradient 2 (P^ - h^) . (omega_l x P^), P^ = P / |a|.
  template <typename T>
  std::pair<T, std::array<T, 2>> chord(const WristFoldValue<T>& v) const {
    Vec3<T> p, e;
    for (int x = 0; x < 3; ++x) p[x] = v.point[x] * inv_a_, e[x] = p[x] - home_[x];
    std::array<T, 2> g;
    for (std::size_t l = 0; l < 2; ++l) g[l] = 2.0 * dot(e, cross(v.omega[l], p));
    return {dot(e, e), g};
  }

  /// The box's item: excluded (nothing) or its lower bound (see header).
  std::optional<Item> bound(const Box& x) const {
    const WristFoldValue<Interval> vx = critical_.over(x);
    const PointN<2> c = centre<2>(x);
    const WristFoldValue<Interval> vc = critical_.over(point_box<2>(c));
    const Box dx{x[0] - c[0], x[1] - c[1]};
    const Interval det = wrist_cap_detail::meet(vx.det, mean_value<2>(vc.det, vx.det_gradient.data(), dx.data()));
    if (!may_vanish(det)) return std::nullopt;
    const auto [qx, gx] = chord(vx);
    const auto [qc, gc] = chord(vc);
    double q_lo = std::max(qx.inf(), mean_value<2>(qc, gx.data(), dx.data()).inf());
    const double gd0 = mid(vc.det_gradient[0]), gd1 = mid(vc.det_gradient[1]);
    const double nn = gd0 * gd0 + gd1 * gd1;
    if (nn > 0 && std::isfinite(nn)) {
      const double lambda = (mid(gc[0]) * gd0 + mid(gc[1]) * gd1) / nn;
      const Interval lagrange = combined_mean_value<2, 2>({1.0, -lambda}, {qc, vc.det}, {gx.data(), vx.det_gradient.data()}, dx.data());
      q_lo = std::max(q_lo, lagrange.inf());
    }
    const double lower = wrist_chord_angle_below(q_lo);
    if (lower > best_hi_) return std::nullopt;
    return Item{lower, x};
  }

  /// The start grid of pieces_[j] boxes per motor over [lo_j, hi_j], bounded.
  void start() {
    for (std::size_t a = 0; a < pieces_[0]; ++a)
      for (std::size_t b = 0; b < pieces_[1]; ++b) {
        const Box x{piece(0, a), piece(1, b)};
        ++boxes_;
        if (const auto item = bound(x)) queue_.push(*item);
      }
  }
  Interval piece(std::size_t j, std::size_t a) const {
    if (about_axis_[j]) return Interval(0.0);
    const double step = (hi_[j] - lo_[j]) / static_cast<double>(pieces_[j]);
    const double from = a == 0 ? lo_[j] : lo_[j] + step * static_cast<double>(a);
    const double to = a + 1 == pieces_[j] ? hi_[j] : lo_[j] + step * static_cast<double>(a + 1);
    return Interval(from, to);
  }

  /// Halves x across its motor of largest scaled width; the halves bounded and queued.
  void split(const Box& x) {
    const std::size_t j = (x[0].sup() - x[0].inf()) * scale_[0] >= (x[1].sup() - x[1].inf()) * scale_[1] ? 0 : 1;
    const double m = mid(x[j]);
    Box a = x, b = x;
    a[j] = Interval(x[j].inf(), m);
    b[j] = Interval(m, x[j].sup());
    for (const Box& half : {a, b}) {
      ++boxes_;
      if (const auto item = bound(half)) queue_.push(*item);
    }
  }

  double scaled_width(const Box& x) const {
    return std::max((x[0].sup() - x[0].inf()) * scale_[0], (x[1].sup() - x[1].inf()) * scale_[1]);
  }

  /// A fold point from x's centre along grad D (within twice the box), proved, kept when nearer
  /// than the best so far (estimated in doubles first: most lines are not worth a proof).
  void try_upper(const Box& x) {
    const PointN<2> c = centre<2>(x);
    const WristFoldValue<double> v = critical_.at(c);
    const PointN<2> d{v.det_gradient[0], v.det_gradient[1]};
    const double reach = 2 * std::max(x[0].sup() - x[0].inf(), x[1].sup() - x[1].inf());
    const std::optional<double> t = critical_.line_root(c, d, reach);
    if (!t) return;
    const WristFoldValue<double> on = critical_.at({c[0] + *t * d[0], c[1] + *t * d[1]});
    double q_estimate = 0;
    for (int x3 = 0; x3 < 3; ++x3) q_estimate += std::pow(on.point[x3] * mid(inv_a_) - mid(home_[x3]), 2);
    if (2 * std::asin(std::min(1.0, std::sqrt(q_estimate) / 2)) >= best_hi_) return;
    const std::optional<Box> proved = critical_.fold_point_at(c, d, *t);
    if (!proved) return;
    const Interval q = chord(critical_.over(*proved)).first;
    const double hi = wrist_chord_angle_above(q.sup());
    if (hi >= best_hi_) return;
    best_hi_ = hi;
    best_lo_ = wrist_chord_angle_below(q.inf());
    best_box_ = *proved;
    found_ = true;
  }

  /// The bracket (the least lower bound of the boxes left and of the best point), the best point.
  WristCapResult result(const std::string& stopped) const {
    WristCapResult r;
    r.periods.assign(periods_.begin(), periods_.end());
    r.boxes = boxes_;
    r.upper = best_hi_;
    r.lower = std::min(best_lo_, queue_.empty() ? best_hi_ : queue_.top().lower);
    r.radius_certified = stopped.empty() && found_ && r.upper - r.lower <= kWristCapWidth;
    r.home_on_fold = r.lower <= 0;
    if (!r.radius_certified)
      r.why = (stopped.empty() ? std::string(found_ ? "" : "no fold point was proved") : stopped) + ": the radius is in [" +
              number_text(r.lower) + ", " + number_text(r.upper) + "] rad, " + number_text(r.upper - r.lower) + " wide";
    if (found_) fold_point_of(r);
    return r;
  }

  /// The best point's P (unit) and its motors reduced to [0, T_j) with their radius.
  void fold_point_of(WristCapResult& r) const {
    const WristFoldValue<Interval> v = critical_.over(best_box_);
    Vector3d p(mid(v.point[0]), mid(v.point[1]), mid(v.point[2]));
    p.normalize();
    r.has_fold_point = true;
    r.fold_point = {p.x(), p.y(), p.z()};
    double radius = 0;
    for (std::size_t j = 0; j < 2; ++j) {
      const double turns = std::floor(mid(best_box_[j]) / periods_[j]);
      const Interval k = best_box_[j] - Interval(turns) * period_[j];
      r.fold_motors[j] = std::clamp(mid(k), 0.0, std::nextafter(periods_[j], 0.0));
      radius = std::max({radius, k.sup() - r.fold_motors[j], -(r.fold_motors[j] - k.inf())});  // rounded up
    }
    r.fold_motor_radius = radius;
  }

  WristCritical critical_;
  std::size_t max_boxes_;
  Interval inv_a_{1.0};
  Vec3<Interval> home_;
  std::array<double, 2> scale_{}, periods_{}, lo_{}, hi_{};
  std::array<Interval, 2> period_;
  std::array<std::size_t, 2> pieces_{};
  std::array<bool, 2> about_axis_{};
  std::priority_queue<Item, std::vector<Item>, wrist_cap_detail::LeastLowerFirst> queue_;
  double best_hi_ = 3.1415926535897936, best_lo_ = 3.1415926535897936;
  Box best_box_;
  bool found_ = false;
  std::size_t boxes_ = 0;
};

/// The cap about `home` (see header): REQUIRES a 2-motor wrist (InvalidInput "coupling" for 3),
/// home finite and within kWristTargetTolerance of unit length (InvalidInput "home"); refuses a
/// wrist above the cost bound (check_wrist_ik_cost). In the caller's rounding mode.
inline WristCapResult wrist_cap(const Wrist& wrist, const Vector3d& home, std::size_t max_boxes = kMaxWristCapBoxes) {
  if (wrist.motors() != 2)
    throw InvalidInput("coupling", wrist.coupling_text(), "3 motors: caps about a home orientation (m = 3) are not available",
                       "a 2-column coupling (the tool axis driven by 2 motors)");
  const WristTarget at_home = WristTarget::pointing(home, "home");
  check_wrist_ik_cost(wrist);
  if (wrist_fold_vanishes_everywhere(wrist)) {  // a degenerate wrist: every point of its image a fold
    WristCapResult r;
    for (std::size_t j = 0; j < 2; ++j) r.periods.push_back(wrist.period(j));
    r.why = "the fold function D vanishes on the whole motor torus (the map u -> P has rank below 2 everywhere: "
            "a degenerate wrist); the bracket [0, pi] is all that is proved";
    return r;
  }
  WristCapResult r = WristCapSearch(wrist, at_home.direction, max_boxes).run();
  const WristIkResult ik = wrist_ik(wrist, at_home);
  r.ik_boxes = ik.boxes;
  if (ik.certified) r.count = ik.solutions.size();
  r.certified = r.radius_certified && (r.count || r.home_on_fold);
  if (r.radius_certified && !r.certified) r.why = "the count at home is not certified: " + ik.why;
  return r;
}

}  // namespace sphtroch
