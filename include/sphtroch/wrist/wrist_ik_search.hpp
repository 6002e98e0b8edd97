// sphtroch/wrist/wrist_ik_search.hpp — the branch and bound behind wrist_ik (wrist_ik.hpp, whose
// header states the method and the guarantee): the torus's start grid, the probe of a box (the
// exclusion tests and the Krawczyk step), roots recorded with their regions, Newton's method with
// epsilon-inflation, bisection, and the result with its motors reduced to the periods.
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   sphtroch::WristIkSearch<2> search(wrist, sphtroch::WristTarget::pointing(sphtroch::Vector3d(0.6, 0, 0.8)), 100000);
//   search.run().solutions.size();   // 4 (wrist_ik() also checks the cost first)
//
// Every verdict on a box comes from krawczyk_step (interval/krawczyk.hpp) or from an enclosure
// that misses what a root needs; Newton's iterates are only starting points for a proof.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/wrist/wrist_ik_search.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/krawczyk.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_ik_result.hpp"
#include "sphtroch/wrist/wrist_ik_system.hpp"
#include "sphtroch/wrist/wrist_target.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// Start boxes span at most this much joint motion (radians) per motor: width_j sum_i |C_ij|.
constexpr double kWristStartWidth = 1.0;
/// The torus grid starts at -kWristStartOffset T_j (and ends a period later): round values of the
/// motors (0, pi / 2, ...) then lie inside boxes, not on their faces.
constexpr double kWristStartOffset = 0.0137;
/// The search's default budget of boxes (then it stops, not certified).
constexpr std::size_t kMaxWristBoxes = 4000000;
/// Undecided boxes of scaled width below this try Newton's method and epsilon-inflation.
constexpr double kWristNewtonWidth = 0.05;
/// Undecided boxes of scaled width below this are left undecided...
constexpr double kWristMinWidth = 1e-9;
/// ... with the box of this scaled radius about them (an undecided region: the boxes inside it are
/// not searched; a double root leaves a cluster of undecided boxes ~1e-7 wide, one region).
constexpr double kWristUndecidedRadius = 1e-6;
/// The search stops after this many undecided regions (a continuum of solutions).
constexpr std::size_t kMaxWristUndecided = 64;

namespace wrist_search_detail {

template <std::size_t M>
using Box = IntervalBox<M>;

template <std::size_t M>
bool inside(const Box<M>& a, const Box<M>& b) {
  for (std::size_t j = 0; j < M; ++j)
    if (a[j].inf() < b[j].inf() || a[j].sup() > b[j].sup()) return false;
  return true;
}
template <std::size_t M>
bool inside(const PointN<M>& y, const Box<M>& b) {
  for (std::size_t j = 0; j < M; ++j)
    if (!(y[j] >= b[j].inf() && y[j] <= b[j].sup())) return false;
  return true;
}
template <std::size_t M>
bool overlap(const Box<M>& a, const Box<M>& b) {
  for (std::size_t j = 0; j < M; ++j)
    if (a[j].sup() < b[j].inf() || b[j].sup() < a[j].inf()) return false;
  return true;
}
/// The intersection of two enclosures of one quantity (both hold it: they meet; else a).
inline Interval meet(const Interval& a, const Interval& b) {
  const double lo = std::max(a.inf(), b.inf()), hi = std::min(a.sup(), b.sup());
  return lo <= hi ? Interval(lo, hi) : a;
}
/// {x + s : s in shift} shrunk to what holds for every s: [x.inf + shift.sup, x.sup + shift.inf],
/// rounded inward (a region moved by an enclosed period stays a subset of the true one).
/// REQUIRES rounding upward; nothing when empty.
inline std::optional<Interval> inner_shift(const Interval& x, const Interval& shift) {
  const double lo = x.inf() + shift.sup();        // rounded up: inward
  const double hi = -((-x.sup()) - shift.inf());  // rounded down: inward
  if (!(lo <= hi)) return std::nullopt;
  return Interval(lo, hi);
}
/// Whether the interval determinant of J (2 x 2 or 3 x 3) may vanish.
template <std::size_t M>
bool may_be_singular(const IntervalMatrix<M>& j) {
  if constexpr (M == 2) return may_vanish(j[0][0] * j[1][1] - j[0][1] * j[1][0]);
  else
    return may_vanish(j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                      j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]));
}

/// A root of the system: its enclosure (a few ulps), a region U holding no other root (Krawczyk's
/// box, or a box where ||I - Y J(U)|| < 1), whether it is a true root, its solution's index (-1: none).
template <std::size_t M>
struct Known {
  Box<M> enclosure, region;
  bool genuine = false;
  long solution = -1;
};

/// What one look at a box gives: excluded, or the Krawczyk step (none when J at the centre is
/// singular), with J at the centre (for the choice of the motor to split).
template <std::size_t M>
struct Probe {
  bool excluded = false;
  std::optional<KrawczykStep<M>> step;
  DoubleMatrix<M> jac_centre = DoubleMatrix<M>::Zero();
};

}  // namespace wrist_search_detail

/// The search of one wrist and target (see wrist_ik.hpp). REQUIRES M == wrist.motors() and a
/// target of that kind; run() in any rounding mode, once.
template <std::size_t M>
class WristIkSearch {
  using Box = wrist_search_detail::Box<M>;
  using Known = wrist_search_detail::Known<M>;
  using Probe = wrist_search_detail::Probe<M>;

 public:
  WristIkSearch(const Wrist& wrist, const WristTarget& target, std::size_t max_boxes)
      : system_(make_system(wrist, target)), max_boxes_(max_boxes) {
    const RoundingGuard upward;
    const Interval two_pi(6.283185307179586, std::nextafter(6.283185307179586, 7.0));  // 2 pi is between them
    for (std::size_t j = 0; j < M; ++j) {
      scale_[j] = std::max(wrist.joint_speed(j), 1e-300);
      period_[j] = two_pi * Interval(static_cast<double>(wrist.period_turns(j)));
      periods_[j] = wrist.period(j);
      lo_[j] = -kWristStartOffset * periods_[j];
      hi_[j] = lo_[j] + period_[j].sup();
      pieces_[j] = static_cast<std::size_t>(std::max(1.0, std::ceil(periods_[j] * scale_[j] / kWristStartWidth)));
    }
  }

  WristIkResult run() {
    {
      const RoundingGuard upward;  // the interval arithmetic's mode throughout the search
      std::vector<Box> stack = start_boxes();
      while (!stack.empty() && !stopped()) {
        const Box x = stack.back();
        stack.pop_back();
        ++boxes_;
        examine(x, stack);
      }
      if (!stack.empty()) left_ += stack.size();
    }
    return result();
  }

 private:
  static WristIkSystem<M> make_system(const Wrist& wrist, const WristTarget& target) {
    const RoundingGuard upward;
    return WristIkSystem<M>(wrist, target);
  }

  bool stopped() const { return boxes_ >= max_boxes_ || undecided_.size() > kMaxWristUndecided; }
  bool over_budget() const { return boxes_ >= max_boxes_; }

  /// The grid of pieces_[j] boxes per motor over [lo_j, hi_j].
  std::vector<Box> start_boxes() const {
    std::size_t total = 1;
    for (std::size_t j = 0; j < M; ++j) total *= pieces_[j];
    std::vector<Box> out;
    out.reserve(total);
    for (std::size_t n = 0; n < total; ++n) {
      Box b;
      std::size_t rest = n;
      for (std::size_t j = 0; j < M; ++j) {
        const std::size_t a = rest % pieces_[j];
        rest /= pieces_[j];
        const double step = (hi_[j] - lo_[j]) / static_cast<double>(pieces_[j]);
        const double from = a == 0 ? lo_[j] : lo_[j] + step * static_cast<double>(a);
        const double to = a + 1 == pieces_[j] ? hi_[j] : lo_[j] + step * static_cast<double>(a + 1);
        b[j] = Interval(from, to);
      }
      out.push_back(b);
    }
    return out;
  }

  /// One box: excluded, decided by Krawczyk (repeated while it narrows the box), given to
  /// Newton, left undecided, or bisected.
  void examine(Box x, std::vector<Box>& stack) {
    Probe p;
    for (int round = 0; round < 4; ++round) {
      if (in_known_region(x)) return;
      p = probe(x);
      if (p.excluded) return;
      if (!p.step) break;  // J singular at the centre: split
      if (p.step->verdict == KrawczykVerdict::none) return;
      if (p.step->verdict == KrawczykVerdict::unique) {
        if (record_unique(x, p.step->box)) return;
        break;
      }
      const bool shrank = width_ratio(p.step->box, x) < 0.7;
      x = p.step->box;
      if (!shrank) break;
    }
    const double w = scaled_width(x);
    if (w < kWristNewtonWidth && newton_root(x)) {
      stack.push_back(x);  // looked at again: inside the new region, or split around it
      return;
    }
    if (w < kWristMinWidth) {
      undecided_.push_back(about(centre<M>(x), kWristUndecidedRadius));
      return;
    }
    bisect(x, p, stack);
  }

  /// The exclusion tests and one Krawczyk step on x about its centre y (see wrist_ik.hpp).
  Probe probe(const Box& x) const {
    Probe p;
    const auto vx = system_.over(x);
    const PointN<M> y = centre<M>(x);
    const auto vy = system_.over(point_box<M>(y));
    Box dx;
    for (std::size_t l = 0; l < M; ++l) dx[l] = x[l] - y[l];
    for (std::size_t r = 0; r < M; ++r) {
      Interval mv = vy.f[r];
      for (std::size_t l = 0; l < M; ++l) mv += vx.jac[r][l] * dx[l];
      if (!may_vanish(wrist_search_detail::meet(vx.f[r], mv))) p.excluded = true;
    }
    Interval sign = vy.sign;
    for (std::size_t l = 0; l < M; ++l) sign += vx.sign_gradient[l] * dx[l];
    if (wrist_search_detail::meet(vx.sign, sign).sup() < system_.peak().inf()) p.excluded = true;
    if (p.excluded) return p;
    p.jac_centre = midpoint<M>(vy.jac);
    if (const auto inverse = midpoint_inverse<M>(p.jac_centre)) p.step = krawczyk_step<M>(x, y, vy.f, vx.jac, *inverse);
    return p;
  }

  /// The largest ratio of a side of a to the same side of b.
  static double width_ratio(const Box& a, const Box& b) {
    double r = 0;
    for (std::size_t j = 0; j < M; ++j) r = std::max(r, (a[j].sup() - a[j].inf()) / std::max(b[j].sup() - b[j].inf(), 1e-300));
    return r;
  }

  double scaled_width(const Box& x) const {
    double w = 0;
    for (std::size_t j = 0; j < M; ++j) w = std::max(w, (x[j].sup() - x[j].inf()) * scale_[j]);
    return w;
  }

  /// Halves x across the motor of largest smear (its width times its largest |dF/du| at the
  /// centre), or of largest scaled width when J is not known there.
  void bisect(const Box& x, const Probe& p, std::vector<Box>& stack) const {
    std::size_t best = 0;
    double best_size = -1;
    for (std::size_t l = 0; l < M; ++l) {
      double column = 0;
      for (std::size_t r = 0; r < M; ++r) column = std::max(column, std::fabs(p.jac_centre(int(r), int(l))));
      double size = (x[l].sup() - x[l].inf()) * (std::isfinite(column) && p.step ? column : scale_[l]);
      if ((x[l].sup() - x[l].inf()) * scale_[l] < kWristMinWidth) size = -0.5;  // never split a side below the floor
      if (size > best_size) best = l, best_size = size;
    }
    const double m = mid(x[best]);
    Box a = x, b = x;
    a[best] = Interval(x[best].inf(), m);
    b[best] = Interval(m, x[best].sup());
    stack.push_back(b);
    stack.push_back(a);
  }

  /// Whether x lies in a known root's region or in an undecided region.
  bool in_known_region(const Box& x) const {
    return std::any_of(known_.begin(), known_.end(), [&](const Known& k) { return wrist_search_detail::inside<M>(x, k.region); }) ||
           std::any_of(undecided_.begin(), undecided_.end(), [&](const Box& u) { return wrist_search_detail::inside<M>(x, u); });
  }
  bool in_known_region(const PointN<M>& y) const {
    return std::any_of(known_.begin(), known_.end(), [&](const Known& k) { return wrist_search_detail::inside<M>(y, k.region); });
  }

  /// Krawczyk on k while it narrows (each step keeps the one root of k): a few ulps.
  Box contracted(Box k) const {
    for (int it = 0; it < 40; ++it) {
      const auto vk = system_.over(k);
      const PointN<M> y = centre<M>(k);
      const auto vy = system_.over(point_box<M>(y));
      const auto inverse = midpoint_inverse<M>(midpoint<M>(vy.jac));
      if (!inverse) break;
      const KrawczykStep<M> s = krawczyk_step<M>(k, y, vy.f, vk.jac, *inverse);
      if (s.verdict == KrawczykVerdict::none) break;  // (k holds a root: not reached)
      const bool shrank = width_ratio(s.box, k) < 0.9;
      k = s.box;
      if (!shrank) break;
    }
    return k;
  }

  /// The one root of f in `region`, inside k: recorded (true root or not) unless its sign stays
  /// undecided (then false, and the caller goes on with the box).
  bool record_unique(const Box& region, const Box& k) {
    const Box tight = contracted(k);
    const Interval sign = system_.over(tight).sign;
    if (!(sign.inf() > system_.threshold()) && !(sign.sup() < system_.threshold())) return false;
    add_known(tight, region, sign.inf() > system_.threshold());
    return true;
  }

  /// Known roots with copies moved by whole periods where those meet the domain, so that a root
  /// near one end of a motor's range is known at the other end too.
  void add_known(const Box& enclosure, const Box& region, bool genuine) {
    long solution = -1;
    if (genuine) {
      solution = matching_solution(enclosure, region);
      if (solution == -2) return;  // ambiguous: counted undecided
      if (solution == -1) {
        solution = static_cast<long>(solutions_.size());
        solutions_.push_back(enclosure);
      }
    }
    add_copies(Known{enclosure, region, genuine, solution}, 0);
  }

  /// Adds k moved by -T_j, 0 or +T_j in motors j, j + 1, ... (moves only where the region still meets the domain).
  void add_copies(const Known& k, std::size_t j) {
    if (j == M) {
      known_.push_back(k);
      return;
    }
    add_copies(k, j + 1);
    for (const double sign : {-1.0, 1.0}) {
      const Interval shift = sign > 0 ? period_[j] : -period_[j];
      const auto region = wrist_search_detail::inner_shift(k.region[j], shift);
      if (!region || region->sup() < lo_[j] || region->inf() > hi_[j]) continue;
      Known moved = k;
      moved.region[j] = *region;
      moved.enclosure[j] = k.enclosure[j] + shift;
      add_copies(moved, j + 1);
    }
  }

  /// The index of the solution this root is (its enclosure in that root's region, or that root's
  /// enclosure in this region, up to whole periods: the copies), -1 for a new one, -2 when it
  /// cannot be told (enclosures that overlap with neither inside: counted undecided).
  long matching_solution(const Box& enclosure, const Box& region) {
    for (const Known& k : known_) {
      if (!k.genuine) continue;
      if (wrist_search_detail::inside<M>(enclosure, k.region) || wrist_search_detail::inside<M>(k.enclosure, region)) return k.solution;
    }
    for (const Known& k : known_)
      if (k.genuine && wrist_search_detail::overlap<M>(enclosure, k.enclosure)) {
        ambiguous_.push_back(enclosure);
        return -2;
      }
    return -1;
  }

  /// Newton from the centre of x in doubles, then epsilon-inflation about its limit (brought into
  /// the domain): a root proved there, not yet known, is recorded with the largest region about
  /// it where ||I - Y J(U)|| < 1. Whether a root was added.
  bool newton_root(const Box& x) {
    std::optional<PointN<M>> y = newton_limit(centre<M>(x));
    if (!y || in_known_region(*y)) return false;
    const auto proved = epsilon_inflation(1e-6, 1.0 / 16, 1e-15, [&](double rho) -> std::optional<std::pair<Box, Box>> {
      const Box b = about(*y, rho);
      const auto vb = system_.over(b);
      const auto vy = system_.over(point_box<M>(*y));
      const auto inverse = midpoint_inverse<M>(midpoint<M>(vy.jac));
      if (!inverse) return std::nullopt;
      const KrawczykStep<M> s = krawczyk_step<M>(b, *y, vy.f, vb.jac, *inverse);
      if (s.verdict != KrawczykVerdict::unique) return std::nullopt;
      return std::make_pair(b, s.box);
    });
    if (!proved || in_known_region(proved->second)) return false;
    const Box region = grown_region(*y, proved->first);
    const std::size_t before = known_.size();
    record_unique(region, proved->second);
    return known_.size() > before;
  }

  /// Newton's iterates from y (at most 16 steps), reduced into the domain, when they converge.
  std::optional<PointN<M>> newton_limit(PointN<M> y) const {
    double last = 1;
    for (int it = 0; it < 16 && last > 0; ++it) {
      const auto v = system_.at(y);
      const DoubleVector<M> dy = newton_correction<M>(to_matrix<M>(v.jac), Eigen::Map<const DoubleVector<M>>(v.f.data()));
      if (!dy.allFinite()) return std::nullopt;
      last = 0;
      for (std::size_t j = 0; j < M; ++j) {
        y[j] -= dy(int(j));
        last = std::max(last, std::fabs(dy(int(j))) * scale_[j]);
      }
      if (last > 1.0) return std::nullopt;  // thrown off
      if (last < 1e-13) break;
    }
    if (!(last < 1e-9)) return std::nullopt;
    for (std::size_t j = 0; j < M; ++j) {
      y[j] = lo_[j] + std::fmod(y[j] - lo_[j], periods_[j]);
      if (y[j] < lo_[j]) y[j] += periods_[j];
    }
    return y;
  }

  /// The box y +- rho / scale_j.
  Box about(const PointN<M>& y, double rho) const {
    Box b;
    for (std::size_t j = 0; j < M; ++j) b[j] = Interval(y[j] - rho / scale_[j], y[j] + rho / scale_[j]);
    return b;
  }

  /// The largest box about y (radii rho 2^i / scale_j up to 0.5 / scale_j) holding `proof` with
  /// ||I - Y J(U)|| < 1 (krawczyk.hpp's contracts): at most one root there. At least `proof`.
  Box grown_region(const PointN<M>& y, const Box& proof) const {
    Box best = proof;
    const auto inverse = midpoint_inverse<M>(midpoint<M>(system_.over(point_box<M>(y)).jac));
    if (!inverse) return best;
    for (double rho = 1e-9; rho <= 0.5; rho *= 2) {
      const Box u = about(y, rho);
      if (!wrist_search_detail::inside<M>(proof, u)) continue;
      if (!contracts<M>(*inverse, system_.over(u).jac)) break;
      best = u;
    }
    return best;
  }

  /// x's side j as an interval of motor j reduced to [0, T_j) (by a period, enclosed).
  Interval reduced(const Interval& x, std::size_t j) const {
    if (mid(x) < 0) return x + period_[j];
    if (mid(x) >= periods_[j]) return x - period_[j];
    return x;
  }

  /// The point of a box reduced to [0, T_j) and the largest distance from it to the box
  /// (REQUIRES rounding upward).
  std::pair<std::vector<double>, double> motors_of(const Box& x) const {
    std::vector<double> u(M);
    double radius = 0;
    for (std::size_t j = 0; j < M; ++j) {
      const Interval k = reduced(x[j], j);
      u[j] = std::clamp(mid(k), 0.0, std::nextafter(periods_[j], 0.0));
      radius = std::max({radius, k.sup() - u[j], -(u[j] - k.inf())});  // both rounded up
    }
    return {u, radius};
  }

  /// The list, sorted, and what is undecided (see WristIkResult).
  WristIkResult result() const {
    const RoundingGuard upward;
    WristIkResult r;
    r.periods.assign(periods_.begin(), periods_.end());
    r.boxes = boxes_;
    for (const Box& k : solutions_) {
      const auto [u, radius] = motors_of(k);
      r.solutions.push_back({u, radius});
    }
    std::sort(r.solutions.begin(), r.solutions.end(), [](const WristSolution& a, const WristSolution& b) { return a.motors < b.motors; });
    r.undecided = undecided_.size() + ambiguous_.size() + left_;
    r.certified = r.undecided == 0;
    for (const std::vector<Box>* list : {&ambiguous_, &undecided_})
      for (const Box& x : *list)
        if (r.undecided_at.size() < 16) r.undecided_at.push_back(motors_of(x).first);
    r.on_fold = !r.certified && !over_budget() && ambiguous_.empty() && undecided_.size() <= kMaxWristUndecided &&
                std::all_of(undecided_.begin(), undecided_.end(), [&](const Box& x) {
                  return wrist_search_detail::may_be_singular<M>(system_.over(x).jac);
                });
    r.why = why(r);
    return r;
  }

  /// One line: what keeps the list from being certified ("" when it is).
  std::string why(const WristIkResult& r) const {
    if (r.certified) return "";
    std::string at;
    if (!r.undecided_at.empty()) {
      for (const double u : r.undecided_at.front()) at += (at.empty() ? "" : ", ") + number_text(u);
      at = " near u = (" + at + ")";
    }
    if (over_budget())
      return "the search stopped at its budget of " + std::to_string(max_boxes_) + " boxes with " + std::to_string(left_) + " unexamined";
    if (undecided_.size() > kMaxWristUndecided)
      return "the search stopped after " + std::to_string(undecided_.size()) + " undecided regions (a continuum of solutions?)" + at;
    if (!ambiguous_.empty()) return "two root enclosures overlap without a proof that they are one root" + at;
    if (r.on_fold)
      return "the target is on a fold (or within rounding of one): a double root (J singular) may lie in " + std::to_string(undecided_.size()) + " undecided region(s)" + at;
    return std::to_string(undecided_.size()) + " undecided region(s)" + at;
  }

  WristIkSystem<M> system_;
  std::size_t max_boxes_;
  std::array<double, M> scale_{}, periods_{}, lo_{}, hi_{};
  std::array<Interval, M> period_;
  std::array<std::size_t, M> pieces_{};
  std::vector<Known> known_;
  std::vector<Box> solutions_, undecided_, ambiguous_;
  std::size_t boxes_ = 0, left_ = 0;
};

}  // namespace sphtroch
