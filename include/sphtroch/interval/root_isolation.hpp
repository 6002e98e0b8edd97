// sphtroch/interval/root_isolation.hpp — certified isolation of ALL roots of a square
// system F(x) = 0 in a box: interval branch and bound with the Krawczyk operator. The engine of
// precision points (precision_points.hpp: fixed frame, 4 unknowns; free_axis_points.hpp: free
// axis, 8). Needs CGAL's Interval_nt only (headers): the CMake target sphtroch::interval.
//
//   // a System: FixedFrameSystem of precision_points.hpp, three points of a train of ratio 1/2
//   const sphtroch::TracerCurve<double> curve(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(1, 2), 0.3));
//   const sphtroch::FixedFrameSystem system({curve.point(0.5), curve.point(2.0), curve.point(7.0)},
//                                                          sphtroch::Ratio(1, 2));
//   sphtroch::PrecisionPoints r =
//       sphtroch::RootIsolation<sphtroch::FixedFrameSystem>(system, 4000000).run();  // r.solutions: unsorted
//
// A System (see FixedFrameSystem in precision_points.hpp for one) has kOuter unknowns split by the
// outer loop and kLists unknowns (one parameter per precision point) kept as lists of intervals,
// each pruned on its own: `view(outer)` computes what all the lists of an outer box share,
// `list_item(d, i)` what one interval d of list i carries down the tree (its `d` and whatever
// depends on d alone, computed once), and `may_hold(view, item, i)` whether point i's equations
// may vanish over the outer box x item.d (REQUIRES: false only when they cannot; it may note
// in the view what the tests found, for the optional `narrow_outer`, and may replace the item by
// list_item(d') with d' inside item.d holding every root of x item.d, x the view's box);
// kIsolateWidth and kContractWidth are the outer widths below which boxes go to the Krawczyk
// test in all N unknowns, and are narrowed by it; list items are split to no wider (scaled) than
// max(kListWidth times the widest outer width, kIsolateWidth). `chart(box)` picks one of the System's square
// formulations F for a box (each formulation's roots must include every true root, and the
// System's `solution` drops the others), or -1 when none is good over the whole box: the box is
// then never certified (it is bisected) and Newton uses the chart of the box's centre. Small
// boxes go to the Krawczyk test in all N unknowns:
// K(X) = y - Y F(y) + (I - Y J(X)) (X - y), y the centre, Y ~ J(y)^-1 (any Y keeps it valid):
// K(X) inside X proves exactly one root in X, K(X) disjoint from X proves none. A root found by
// Newton is certified in a tiny box and given the largest box U around it where
// ||I - Y J(U)||_inf < 1 (by the mean value theorem no second root is there). Krawczyk also
// narrows: an undecided box X is replaced by X intersected with K(X), which holds all its roots
// (repeated while it narrows; a narrowed box inside a known U holds only that root), and outer
// boxes narrower than the System's kContractWidth are narrowed the same way on the hull of their
// lists before they are split. A System may have `narrow_outer(view, outer)`, called once every
// list was filtered on the view's box: false when the lists together exclude every root of the
// box, else `outer` (the box) narrowed to where roots may be (REQUIRES: it keeps every root).
// Guarantee: when `certified`, every root in the domain is listed once (the System drops copies
// and roots outside its fundamental domain); otherwise `undecided` boxes (narrower than
// kMinBoxWidth and still undecided, or left when max_boxes was reached) may hold more, and at
// most kMaxUnisolatedSolutions trains from them are listed (isolated = false).
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/interval/root_isolation.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/types.hpp"
#include "sphtroch/interval/isolated_roots.hpp"
#include "sphtroch/interval/krawczyk.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace sphtroch {

/// A box narrower than this (radians, list unknowns scaled by the System) that is still
/// undecided is reported as such: the result is then not certified.
constexpr double kMinBoxWidth = 1e-11;
/// A train from an undecided box is listed (isolated = false) only if it passes the points to this.
constexpr double kUnisolatedResidual = 1e-12;
/// At most this many such trains per search (the list is then not certified anyway): points on a
/// continuum of near-solutions (three on the equator, n = 2: a2 -> 0, a3 = pi/2) leave thousands
/// of undecided boxes, and each listed train costs its census (measured: 11,429 trains, 135 s).
constexpr std::size_t kMaxUnisolatedSolutions = 64;


template <class System>
class RootIsolation;

// Implementation details follow.
namespace root_isolation_detail {

template <int N>
using Box = IntervalBox<N>;
template <typename T, int N>
using Jacobian = std::array<std::array<T, N>, N>;
template <int N>
using Matrix = DoubleMatrix<N>;

/// Whether System has narrow_outer(view, outer) (see header).
template <class System, class = void>
struct has_narrow_outer : std::false_type {};
template <class System>
struct has_narrow_outer<System, std::void_t<decltype(std::declval<const System&>().narrow_outer(
                                    std::declval<const typename System::View&>(), std::declval<typename System::Outer&>()))>>
    : std::true_type {};

/// The chart for Newton steps from box x: the box's, or (none fits the box) its centre's.
template <class System>
int newton_chart(const System& sys, const Box<System::N>& x) {
  const RoundingGuard upward;  // chart() computes with intervals; callers may be in any mode
  const int chart = sys.chart(x);
  if (chart >= 0) return chart;
  Box<System::N> c;
  for (int k = 0; k < System::N; ++k) c[k] = Interval(0.5 * (x[k].inf() + x[k].sup()));
  return sys.chart(c);
}

/// Y = J(y)^-1 in doubles (krawczyk.hpp's midpoint inverse at the centre y); none if singular.
template <class System>
std::optional<Matrix<System::N>> inverse_jacobian(const System& sys, const std::array<double, System::N>& y, int chart) {
  constexpr int N = System::N;
  std::array<double, N> f{};
  Jacobian<double, N> jac{};
  sys.equations(y, f, &jac, chart);
  return midpoint_inverse<N>(to_matrix<N>(jac));
}

enum class KrawczykOutcome { unique_root, no_root, undecided };

/// The Krawczyk step (krawczyk.hpp) on x in the box's chart, Y = J(centre)^-1. On `undecided` x is
/// narrowed to X intersected with K(X).
template <class System>
KrawczykOutcome krawczyk(const System& sys, Box<System::N>& x) {
  constexpr int N = System::N;
  const std::array<double, N> y = centre<N>(x);
  const int chart = sys.chart(x);
  if (chart < 0) return KrawczykOutcome::undecided;
  const auto inverse = inverse_jacobian(sys, y, chart);
  if (!inverse) return KrawczykOutcome::undecided;
  Box<N> fy{}, fx{};
  Jacobian<Interval, N> jx{};
  sys.equations(point_box<N>(y), fy, static_cast<Jacobian<Interval, N>*>(nullptr), chart);
  sys.equations(x, fx, &jx, chart);
  const KrawczykStep<N> k = krawczyk_step<N>(x, y, fy, jx, *inverse);
  if (k.verdict == KrawczykVerdict::none) return KrawczykOutcome::no_root;
  if (k.verdict == KrawczykVerdict::unique) return KrawczykOutcome::unique_root;
  x = k.box;
  return KrawczykOutcome::undecided;
}

/// Whether ||I - Y J(U)||_inf < 1 with Y = J(y)^-1 (krawczyk.hpp's contraction test), J of the
/// chart the root at y was proven in: at most one root of those equations in U, so no other true
/// root (a true root solves every chart's equations).
template <class System>
bool contraction_holds(const System& sys, const std::array<double, System::N>& y, const Box<System::N>& u, int chart) {
  constexpr int N = System::N;
  const auto inverse = inverse_jacobian(sys, y, chart);
  if (!inverse) return false;
  Box<N> fu{};
  Jacobian<Interval, N> ju{};
  sys.equations(u, fu, &ju, chart);
  return contracts<N>(*inverse, ju);
}

/// One Newton step at y in doubles: krawczyk.hpp's correction J(y)^-1 F(y) (non-finite if J is
/// singular).
template <class System>
DoubleVector<System::N> newton_step(const System& sys, const std::array<double, System::N>& y, int chart) {
  constexpr int N = System::N;
  std::array<double, N> f{};
  Jacobian<double, N> jac{};
  sys.equations(y, f, &jac, chart);
  return newton_correction<N>(to_matrix<N>(jac), Eigen::Map<const DoubleVector<N>>(f.data()));
}

/// Newton from the centre of box x in `chart` (REQUIRES for a root: the chart Krawczyk proved it in).
template <class System>
std::array<double, System::N> polish(const System& sys, const Box<System::N>& x, int chart) {
  std::array<double, System::N> y = centre<System::N>(x);
  for (int step = 0; step < 8; ++step) {
    const auto dy = newton_step(sys, y, chart);
    if (!dy.allFinite()) break;
    for (int k = 0; k < System::N; ++k) y[k] = std::clamp(y[k] - dy(k), x[k].inf(), x[k].sup());
  }
  return y;
}

/// Newton in doubles from the centre of x; its limit, wherever it is, if the steps converged.
/// (Any root may be certified and given its region: an ill-conditioned root is surrounded by
/// boxes that cannot be excluded until its uniqueness region covers them, so it must be found
/// from whichever of them is searched first.) None once an iterate (the centre too) is `known` (inside a region
/// whose one root is listed: nothing new there), which saves most of the steps.
template <class System, class Known>
std::optional<std::array<double, System::N>> newton_limit(const System& sys, const Box<System::N>& x, const Known& known) {
  std::array<double, System::N> y = centre<System::N>(x);
  if (known(y)) return std::nullopt;
  const int chart = newton_chart(sys, x);
  double last = 0.0;
  for (int step = 0; step < 12; ++step) {
    const auto dy = newton_step(sys, y, chart);
    if (!dy.allFinite()) return std::nullopt;
    for (int k = 0; k < System::N; ++k) y[k] -= dy(k);
    last = dy.cwiseAbs().maxCoeff();
    if (last < 1e-12 || last > 1.0) break;  // converged (to rounding) or thrown off
    if (known(y)) return std::nullopt;
  }
  if (!(last < 1e-9)) return std::nullopt;
  return y;
}

}  // namespace root_isolation_detail

/// Branch and bound over the outer unknowns with, per point, the list of intervals of its own
/// unknown still possible; small boxes go to the Krawczyk test in all N unknowns (see header).
template <class System>
class RootIsolation {
  template <int M>
  using Box = root_isolation_detail::Box<M>;
  using KrawczykOutcome = root_isolation_detail::KrawczykOutcome;

 public:
  static constexpr int N = System::N, kOuter = System::kOuter, kLists = System::kLists;
  using Outer = std::array<Interval, kOuter>;
  using Item = typename System::ListItem;

  using Solution = typename System::Solution;
  using Result = IsolatedRoots<Solution>;

  /// `max_boxes`: the work bound; beyond it the search stops and its result is not certified.
  RootIsolation(const System& system, std::size_t max_boxes) : sys_(system), max_boxes_(max_boxes) {}

  /// Searches the System's domain.
  Result run() {
    std::vector<Node> stack;
    {
      const RoundingGuard upward;  // the interval arithmetic's mode; doubles here are estimates only
      for (const Outer& outer : sys_.domains()) {
        Node all{outer, {}};
        for (int i = 0; i < kLists; ++i) all.lists[i].push_back(item(Interval(0.0, sys_.list_max()), i));
        stack.push_back(std::move(all));
      }
      while (!stack.empty()) {
        if (over_budget()) {
          result_.undecided += stack.size();
          break;
        }
        Node node = std::move(stack.back());
        stack.pop_back();
        step(std::move(node), stack);
      }
    }
    finish();  // in the caller's rounding mode
    return result_;
  }

 private:
  /// Widths at which the outer loop hands its boxes to the Krawczyk test.
  static constexpr double kIsolateWidth = System::kIsolateWidth;

  struct Node {
    Outer outer;
    std::array<std::vector<Item>, kLists> lists;
    int contractions = 0;  // by contract() and narrow_outer(): bounded, so that a node cannot narrow forever
  };

  static constexpr int kMaxContractions = 8;
  enum class NodeContraction { done, narrowed, unchanged };

  bool over_budget() const { return result_.boxes >= max_boxes_; }

  double scaled_width(const Box<N>& x, int k) const {
    const double w = x[k].sup() - x[k].inf();
    return k >= kOuter ? w * sys_.list_scale() : w;
  }

  void step(Node node, std::vector<Node>& stack) {
    if (sys_.outside(node.outer)) return;  // only copies of roots inside the domain
    ++result_.boxes;
    auto view = sys_.view(node.outer);  // may_hold may note its findings in it
    for (int i = 0; i < kLists; ++i) {
      auto& list = node.lists[i];
      std::size_t kept = 0;  // may_hold may narrow an item: not remove_if
      for (std::size_t k = 0; k < list.size(); ++k)
        if (sys_.may_hold(view, list[k], i)) {
          if (kept != k) list[kept] = std::move(list[k]);
          ++kept;
        }
      list.erase(list.begin() + static_cast<std::ptrdiff_t>(kept), list.end());
      if (list.empty()) return;
    }
    if constexpr (root_isolation_detail::has_narrow_outer<System>::value) {
      const NodeContraction c = narrow_outer(node, view);
      if (c == NodeContraction::done) return;
      if (c == NodeContraction::narrowed) {
        stack.push_back(std::move(node));  // its lists are tested again on the narrower box
        return;
      }
    }
    int widest = 0;
    for (int k = 1; k < kOuter; ++k)
      if (width(node.outer[k]) > width(node.outer[widest])) widest = k;
    const double wb = width(node.outer[widest]);
    if (wb <= System::kContractWidth && wb > kIsolateWidth && node.contractions < kMaxContractions) {
      const NodeContraction c = contract(node);
      if (c == NodeContraction::done) return;
      if (c == NodeContraction::narrowed) {
        stack.push_back(std::move(node));  // its lists are tested again on the narrower box
        return;
      }
    }
    if (split_lists(node, std::max(wb * System::kListWidth, kIsolateWidth))) {
      stack.push_back(std::move(node));
    } else if (wb <= kIsolateWidth) {
      std::array<std::vector<Interval>, kLists> runs;
      for (int i = 0; i < kLists; ++i) runs[i] = merge_runs(node.lists[i]);
      Box<N> x;
      for (int k = 0; k < kOuter; ++k) x[k] = node.outer[k];
      isolate_each(runs, 0, x);
    } else {
      node.contractions = 0;  // counts the narrowings of one box, not of its line
      Node other = node;
      const double mid = 0.5 * (node.outer[widest].inf() + node.outer[widest].sup());
      node.outer[widest] = Interval(node.outer[widest].inf(), mid);
      other.outer[widest] = Interval(mid, other.outer[widest].sup());
      stack.push_back(std::move(other));
      stack.push_back(std::move(node));
    }
  }

  static double width(const Interval& x) { return x.sup() - x.inf(); }

  /// The System's narrow_outer on a node whose lists were filtered on `view`: no root left
  /// (done), or the node's outer box narrowed when that takes 30% or more off some width (at
  /// most kMaxContractions times per box, with contract()'s).
  template <class View>
  NodeContraction narrow_outer(Node& node, const View& view) const {
    Outer narrowed = node.outer;
    if (!sys_.narrow_outer(view, narrowed)) return NodeContraction::done;
    if (node.contractions >= kMaxContractions || !narrowed_by(node.outer, narrowed, 0.7)) return NodeContraction::unchanged;
    ++node.contractions;
    node.outer = narrowed;
    return NodeContraction::narrowed;
  }

  /// Krawczyk on the hull X of a node (its outer box, each list's span): no root in X, or its one
  /// root recorded (done: record_wide_root); else the node narrowed to X intersected with K(X), which holds every
  /// root of X, when that takes 30% or more off some width (narrowed).
  NodeContraction contract(Node& node) {
    Box<N> x;
    for (int k = 0; k < kOuter; ++k) x[k] = node.outer[k];
    for (int i = 0; i < kLists; ++i) x[kOuter + i] = span(node.lists[i]);
    const Box<N> before = x;
    const KrawczykOutcome outcome = root_isolation_detail::krawczyk(sys_, x);
    if (outcome == KrawczykOutcome::no_root) return NodeContraction::done;
    if (outcome == KrawczykOutcome::unique_root)
      return record_wide_root(x) ? NodeContraction::done : NodeContraction::unchanged;
    if (!narrowed_by(before, x, 0.7)) return NodeContraction::unchanged;
    ++node.contractions;
    for (int k = 0; k < kOuter; ++k) node.outer[k] = x[k];
    for (int i = 0; i < kLists; ++i) {
      clip_list(node.lists[i], x[kOuter + i], i);
      if (node.lists[i].empty()) return NodeContraction::done;
    }
    return NodeContraction::narrowed;
  }

  /// The root that Krawczyk proved unique in a wide box x: Newton from x's middle, certified in a
  /// tiny box inside x in x's own chart (so that it is x's root) and listed with it, x becoming
  /// its region. False, with nothing recorded, when that fails: x is then searched as usual.
  bool record_wide_root(const Box<N>& x) {
    const int chart = sys_.chart(x);
    const auto tiny = proven_tiny_box(root_isolation_detail::polish(sys_, x, chart),
                                      [&](const Box<N>& t) { return !contains(x, t) || sys_.chart(t) != chart; });
    if (!tiny) return false;
    roots_.push_back({*tiny, chart});
    regions_.push_back(x);
    return true;
  }

  /// The smallest interval holding every item of a (non-empty) list.
  static Interval span(const std::vector<Item>& list) {
    double lo = list.front().d.inf(), hi = list.front().d.sup();
    for (const Item& d : list) lo = std::min(lo, d.d.inf()), hi = std::max(hi, d.d.sup());
    return Interval(lo, hi);
  }

  /// The list's items cut to r (items outside dropped, those across its ends recomputed).
  void clip_list(std::vector<Item>& list, const Interval& r, int i) const {
    std::vector<Item> out;
    for (const Item& d : list) {
      if (d.d.sup() < r.inf() || d.d.inf() > r.sup()) continue;
      if (d.d.inf() >= r.inf() && d.d.sup() <= r.sup())
        out.push_back(d);
      else
        out.push_back(item(Interval(std::max(d.d.inf(), r.inf()), std::min(d.d.sup(), r.sup())), i));
    }
    list = std::move(out);
  }

  /// Whether some width of `after` is below `factor` times that of `before`.
  template <std::size_t M>
  static bool narrowed_by(const std::array<Interval, M>& before, const std::array<Interval, M>& after, double factor) {
    for (std::size_t k = 0; k < M; ++k)
      if (width(after[k]) < factor * width(before[k])) return true;
    return false;
  }

  /// isolate() on every combination of one run per list.
  void isolate_each(const std::array<std::vector<Interval>, kLists>& runs, int i, Box<N>& x) {
    if (i == kLists) {
      isolate(x);
      return;
    }
    for (const Interval& d : runs[i]) {
      x[kOuter + i] = d;
      isolate_each(runs, i + 1, x);
    }
  }

  /// Adjacent intervals (in order, each starting where the last ended) joined into one.
  static std::vector<Interval> merge_runs(const std::vector<Item>& list) {
    std::vector<Interval> runs;
    for (const Item& item : list) {
      const Interval& d = item.d;
      if (!runs.empty() && runs.back().sup() == d.inf())
        runs.back() = Interval(runs.back().inf(), d.sup());
      else
        runs.push_back(d);
    }
    return runs;
  }

  Item item(const Interval& d, int i) const { return sys_.list_item(d, i); }

  /// Splits every list interval wider (scaled) than `limit` into equal pieces no wider.
  bool split_lists(Node& node, double limit) const {
    bool split = false;
    for (int i = 0; i < kLists; ++i) {
      const auto& list = node.lists[i];
      if (std::none_of(list.begin(), list.end(), [&](const Item& x) { return width(x.d) * sys_.list_scale() > limit; }))
        continue;  // nothing to split (the common case: no copy)
      std::vector<Item> out;
      for (const Item& item_i : node.lists[i]) {
        const Interval& d = item_i.d;
        const double w = width(d) * sys_.list_scale();
        const auto pieces = static_cast<std::size_t>(std::ceil(w / limit));
        if (pieces <= 1) {
          out.push_back(item_i);
          continue;
        }
        split = true;
        const double step = width(d) / static_cast<double>(pieces);
        for (std::size_t k = 0; k < pieces; ++k)
          out.push_back(item(Interval(k == 0 ? d.inf() : d.inf() + step * static_cast<double>(k),
                                      k + 1 == pieces ? d.sup() : d.inf() + step * static_cast<double>(k + 1)), i));
      }
      node.lists[i] = std::move(out);
    }
    return split;
  }

  bool excluded(const Box<N>& x) const {
    Outer outer;
    for (int k = 0; k < kOuter; ++k) outer[k] = x[k];
    auto view = sys_.view(outer);
    for (int i = 0; i < kLists; ++i) {
      Item d = item(x[kOuter + i], i);
      if (!sys_.may_hold(view, d, i)) return true;
    }
    return false;
  }

  /// Krawczyk with bisection on one box of all N unknowns; boxes inside a known uniqueness
  /// region need no more work.
  void isolate(const Box<N>& start) {
    std::vector<Box<N>> stack{start};
    while (!stack.empty()) {
      if (over_budget()) {
        result_.undecided += stack.size();
        return;
      }
      Box<N> x = stack.back();
      stack.pop_back();
      ++result_.boxes;
      if (in_known_region(x) || excluded(x)) continue;
      const KrawczykOutcome outcome = narrowing_krawczyk(x);
      if (outcome == KrawczykOutcome::no_root) continue;
      if (outcome == KrawczykOutcome::unique_root) {
        roots_.push_back({x, sys_.chart(x)});
        regions_.push_back(x);
        continue;
      }
      if (in_known_region(x)) continue;  // x (narrowed) holds every root of the box: a known one
      if (certify_newton_root(x) && in_known_region(x)) continue;
      bisect(x, stack);
    }
  }

  /// The Krawczyk test, repeated on X intersected with K(X) while that takes 20% or more off some
  /// width (at most 4 times); x ends narrowed, holding every root of the first box.
  KrawczykOutcome narrowing_krawczyk(Box<N>& x) const {
    for (int round = 1;; ++round) {
      const Box<N> before = x;
      const KrawczykOutcome outcome = root_isolation_detail::krawczyk(sys_, x);
      if (outcome != KrawczykOutcome::undecided || round == 4 || !narrowed_by(before, x, 0.8)) return outcome;
    }
  }

  /// Halves x across the unknown of largest smear (width times the largest |dF/dx_k| at the
  /// centre: the one that spreads F most), or the widest if J is not finite; a box narrower
  /// than kMinBoxWidth (scaled) is left undecided.
  void bisect(Box<N> x, std::vector<Box<N>>& stack) {
    int widest = 0;
    for (int k = 1; k < N; ++k)
      if (scaled_width(x, k) > scaled_width(x, widest)) widest = k;
    if (scaled_width(x, widest) < kMinBoxWidth) {
      ++result_.undecided;
      undecided_.push_back(x);
      return;
    }
    widest = most_smeared(x).value_or(widest);
    Box<N> other = x;
    const double mid = 0.5 * (x[widest].inf() + x[widest].sup());
    x[widest] = Interval(x[widest].inf(), mid);
    other[widest] = Interval(mid, other[widest].sup());
    stack.push_back(other);
    stack.push_back(x);
  }

  std::optional<int> most_smeared(const Box<N>& x) const {
    std::array<double, N> f{};
    root_isolation_detail::Jacobian<double, N> jac{};
    sys_.equations(centre<N>(x), f, &jac, root_isolation_detail::newton_chart(sys_, x));
    int best = -1;
    double best_smear = 0.0;
    for (int k = 0; k < N; ++k) {
      double column = 0.0;
      for (int r = 0; r < N; ++r) column = std::max(column, std::fabs(jac[r][k]));
      const double smear = column * (x[k].sup() - x[k].inf());
      if (!std::isfinite(smear)) return std::nullopt;
      if (smear > best_smear && scaled_width(x, k) >= kMinBoxWidth) best = k, best_smear = smear;
    }
    if (best < 0) return std::nullopt;
    return best;
  }

  static bool contains(const Box<N>& outer, const Box<N>& inner) {
    for (int k = 0; k < N; ++k)
      if (inner[k].inf() < outer[k].inf() || inner[k].sup() > outer[k].sup()) return false;
    return true;
  }

  bool in_known_region(const Box<N>& x) const {
    return std::any_of(regions_.begin(), regions_.end(), [&](const Box<N>& u) { return contains(u, x); });
  }
  bool in_known_region(const std::array<double, N>& y) const {
    return std::any_of(regions_.begin(), regions_.end(), [&](const Box<N>& u) {
      for (int k = 0; k < N; ++k)
        if (!(y[k] >= u[k].inf() && y[k] <= u[k].sup())) return false;
      return true;
    });
  }

  /// Newton from the centre of x; a limit (newton_limit) inside the domain and not yet known is
  /// certified (Krawczyk on a box of 1e-10 around it) and given its uniqueness region.
  /// Returns whether a region was added.
  bool certify_newton_root(const Box<N>& x) {
    const auto y = root_isolation_detail::newton_limit(sys_, x, [&](const std::array<double, N>& p) { return in_known_region(p); });
    if (!y || !in_domain(*y)) return false;
    const auto tiny = proven_tiny_box(*y, [&](const Box<N>& t) {
      return std::any_of(regions_.begin(), regions_.end(), [&](const Box<N>& u) { return contains(u, t); });
    });
    if (!tiny) return false;
    const int chart = sys_.chart(*tiny);  // the chart krawczyk() proved the root in
    roots_.push_back({*tiny, chart});
    regions_.push_back(uniqueness_region(*y, *tiny, chart));
    return true;
  }

  /// The first box y +- r (r = 1e-10, 1e-9, 1e-8, 1e-7: an ill-conditioned root, Newton's limit
  /// only good to cond * 1e-16, needs a wider box for K(X) to fit inside) in which Krawczyk proves
  /// exactly one root; none once `rejected(box)` or a box is proven empty.
  template <class Rejected>
  std::optional<Box<N>> proven_tiny_box(const std::array<double, N>& y, const Rejected& rejected) const {
    for (const double radius : {1e-10, 1e-9, 1e-8, 1e-7}) {  // a list: rounding upward here
      Box<N> tiny;
      for (int k = 0; k < N; ++k) tiny[k] = around(y, k, radius);
      if (rejected(tiny)) return std::nullopt;
      Box<N> narrowed = tiny;
      const KrawczykOutcome outcome = root_isolation_detail::krawczyk(sys_, narrowed);
      if (outcome == KrawczykOutcome::no_root) return std::nullopt;
      if (outcome == KrawczykOutcome::unique_root) return tiny;
    }
    return std::nullopt;
  }

  /// Whether y lies in one of the System's domains (lists: [0, list_max]).
  bool in_domain(const std::array<double, N>& y) const {
    for (int k = kOuter; k < N; ++k)
      if (!(y[k] >= 0.0 && y[k] <= sys_.list_max())) return false;
    for (const Outer& outer : sys_.domains()) {
      bool inside = true;
      for (int k = 0; k < kOuter; ++k) inside = inside && y[k] >= outer[k].inf() && y[k] <= outer[k].sup();
      if (inside) return true;
    }
    return false;
  }

  Interval around(const std::array<double, N>& y, int k, double radius) const {
    const double r = k >= kOuter ? radius / sys_.list_scale() : radius;
    return Interval(y[k] - r, y[k] + r);
  }

  /// The largest box y +- r (r = 1e-9 2^j <= 0.25, scaled) holding `tiny` with ||I - Y J(U)||_inf
  /// < 1 in `chart`: by the mean value theorem two roots in U would be equal. At least `tiny`.
  Box<N> uniqueness_region(const std::array<double, N>& y, const Box<N>& tiny, int chart) const {
    Box<N> best = tiny;
    for (double r = 1e-9; r <= 0.25; r *= 2) {
      Box<N> u;
      for (int k = 0; k < N; ++k) u[k] = around(y, k, r);
      if (!contains(u, tiny)) continue;
      if (!root_isolation_detail::contraction_holds(sys_, y, u, chart)) break;
      best = u;
    }
    return best;
  }

  void finish() {
    for (const auto& [x, chart] : roots_) add(sys_.solution(root_isolation_detail::polish(sys_, x, chart), true));
    std::size_t unisolated = 0;
    for (const Box<N>& x : undecided_) {
      if (unisolated == kMaxUnisolatedSolutions) break;
      unisolated += add(sys_.solution(root_isolation_detail::polish(sys_, x, root_isolation_detail::newton_chart(sys_, x)), false));
    }
    result_.certified = result_.undecided == 0;
  }

  /// Keeps a solution unless it is none (outside the domain), an unisolated one that does not
  /// pass the points, or a repeat (a root on a shared face of two boxes, or a point that is a
  /// node of the curve). Returns whether it was kept.
  bool add(std::optional<Solution> s) {
    if (!s || (!s->isolated && !(s->residual <= kUnisolatedResidual))) return false;
    for (const auto& t : result_.solutions)
      if (sys_.same(t, *s)) return false;
    result_.solutions.push_back(std::move(*s));
    return true;
  }

  const System sys_;  // a copy: a temporary System may be passed
  std::size_t max_boxes_;
  Result result_;
  std::vector<std::pair<Box<N>, int>> roots_;  // each holds exactly one root (of its chart's equations)
  std::vector<Box<N>> regions_;    // each holds at most one root, one of roots_
  std::vector<Box<N>> undecided_;  // narrower than kMinBoxWidth, still undecided
};

}  // namespace sphtroch
