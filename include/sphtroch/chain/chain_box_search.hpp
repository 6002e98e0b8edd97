// sphtroch/chain/chain_box_search.hpp — the branch and bound with the Krawczyk test
// behind the chain census (chain_census.hpp, whose header states the method): boxes of two
// parameters, the two systems (pairs of far arcs in (s, t); pairs near the diagonal in (t, h)),
// the chart, the Krawczyk step, Newton with inflation for roots on a box's edge, and the search.
//
//   namespace d = sphtroch::chain_census_detail;
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   sphtroch::RoundingGuard upward;   // REQUIRED throughout
//   const sphtroch::ChainEnclosure e(chain);
//   d::Search work;
//   std::vector<d::FoundRoot> roots;
//   d::search_box(d::FarPairs{&e}, d::Box2{sphtroch::Interval(0.4, 0.5), sphtroch::Interval(8.9, 9.1)},
//                 [](const d::Box2&) { return false; }, work, roots);   // roots: the node at s = 0.43, t = 8.99
//
// Guarantee of search_box: every root of the system in the starting box that `drop` does not
// exclude is in `roots` (once per search), each with a box U where it is the only root, unless
// work.undecided > 0 (the undecided boxes are listed when asked) or work.out_of_budget.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_box_search.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/chain/chain_enclosure.hpp"
#include "sphtroch/interval/krawczyk.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace sphtroch {

/// Boxes narrower than this (in s, times max(1, |s|)) that are undecided try Newton and inflation.
constexpr double kChainInflateWidth = 1e-6;
/// Boxes narrower than this (times max(1, |s|)) that are still undecided are left to
/// chain_tangency.hpp (two branches nearly parallel where they meet), else counted undecided.
constexpr double kChainMinBoxWidth = 1e-11;
/// Boxes examined at most by one census (then not certified).
constexpr std::size_t kMaxChainBoxes = 1000000;

namespace chain_census_detail {

/// A box of two parameters: (s, t) for arcs apart, (t, h) near the diagonal.
struct Box2 {
  Interval u, v;
  double width() const { return std::max(u.sup() - u.inf(), v.sup() - v.inf()); }
};
inline bool inside(const Box2& a, const Box2& b) {
  return a.u.inf() >= b.u.inf() && a.u.sup() <= b.u.sup() && a.v.inf() >= b.v.inf() && a.v.sup() <= b.v.sup();
}

/// What a system gives the search over a box: the difference vector D (P(s) - P(t), or P(t + h)
/// - P(t)) enclosed, its two parameter derivatives enclosed, and the two points' enclosures
/// (to choose the chart); `cleared` when a cheaper test already excludes every root.
struct BoxEvaluation {
  bool cleared = false;
  IntervalVec3 difference, d_du, d_dv, first, second;
};

/// The intersection of two enclosures of one quantity (they meet: both hold it).
inline Interval meet(const Interval& a, const Interval& b) {
  const double lo = std::max(a.inf(), b.inf()), hi = std::min(a.sup(), b.sup());
  return lo <= hi ? Interval(lo, hi) : a;
}

/// Pairs of far arcs: u = s, v = t, D = P(s) - P(t).
struct FarPairs {
  const ChainEnclosure* enclosure;
  BoxEvaluation evaluate(const Box2& b) const {
    const ChainJet s = enclosure->sharp_jet(b.u), t = enclosure->sharp_jet(b.v);
    BoxEvaluation e;
    e.first = s.point;
    e.second = t.point;
    e.cleared = !boxes_meet(s.point, t.point);
    for (int x = 0; x < 3; ++x) {
      e.difference[x] = s.point[x] - t.point[x];
      e.d_du[x] = s.velocity[x];
      e.d_dv[x] = -t.velocity[x];
    }
    return e;
  }
  IntervalVec3 difference_at(double u, double v) const {
    const IntervalVec3 a = enclosure->jet(Interval(u)).point, b = enclosure->jet(Interval(v)).point;
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  }
};

/// Pairs within a window: u = t, v = h > 0, D = P(t + h) - P(t); boxes of h from 0 up.
struct NearPairs {
  const ChainEnclosure* enclosure;
  BoxEvaluation evaluate(const Box2& b) const {
    BoxEvaluation e;
    // (P(t + h) - P(t)) / h lies in the hull of P' over [t, t + h] (h < 0 too: Newton's iterates).
    const Interval end = b.u + b.v;
    const ChainJet span = enclosure->sharp_jet(Interval(std::min(b.u.inf(), end.inf()), std::max(b.u.sup(), end.sup())));
    if (excludes_zero(span.velocity)) {
      e.cleared = true;
      return e;
    }
    const ChainJet t = enclosure->sharp_jet(b.u), s = enclosure->sharp_jet(b.u + b.v);
    e.first = s.point;
    e.second = t.point;
    e.cleared = b.v.inf() > 0 && !boxes_meet(s.point, t.point);
    // Differences over [t, t + h] are h times a mean: h P'(span) and h P''(span) (tight for small h).
    for (int x = 0; x < 3; ++x) {
      e.difference[x] = meet(s.point[x] - t.point[x], b.v * span.velocity[x]);
      e.d_du[x] = meet(s.velocity[x] - t.velocity[x], b.v * span.acceleration[x]);
      e.d_dv[x] = s.velocity[x];
    }
    return e;
  }
  IntervalVec3 difference_at(double u, double v) const {
    const IntervalVec3 a = enclosure->jet(Interval(u) + Interval(v)).point, b = enclosure->jet(Interval(u)).point;
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  }
};

/// The two coordinates of the chart over a box: the third (index `drop`) has one sign on both
/// points over the box. nullopt when no coordinate does; `apart` when one has opposite signs.
struct Chart {
  int a = 0, b = 1, drop = 2;
  bool apart = false;
};
inline std::optional<Chart> chart_of(const IntervalVec3& first, const IntervalVec3& second) {
  int best = -1;
  double best_size = 0;
  for (int x = 0; x < 3; ++x) {
    const bool one_sign = !may_vanish(first[x]) && !may_vanish(second[x]);
    if (!one_sign) continue;
    if ((first[x].inf() > 0) != (second[x].inf() > 0)) return Chart{0, 1, x, true};
    const double size = std::min(std::fabs(mid(first[x])), std::fabs(mid(second[x])));
    if (size > best_size) best = x, best_size = size;
  }
  if (best < 0) return std::nullopt;
  return Chart{(best + 1) % 3, (best + 2) % 3, best, false};
}

/// One Krawczyk step (krawczyk.hpp) on box b in the chart c: the rows c.a, c.b of D, Y the inverse
/// of J's midpoint over b (none below a relative determinant of 1e-14: two nearly parallel
/// branches, left to bisection and chain_tangency.hpp). The verdict and box: K (unique), b meets K
/// (narrowed), b (none, or no step).
template <class System>
KrawczykStep<2> chart_step(const System& sys, const Box2& b, const BoxEvaluation& e, const Chart& c) {
  KrawczykStep<2> r;
  r.box = {b.u, b.v};
  const IntervalMatrix<2> j{{{e.d_du[c.a], e.d_dv[c.a]}, {e.d_du[c.b], e.d_dv[c.b]}}};
  const std::optional<DoubleMatrix<2>> inverse = midpoint_inverse<2>(midpoint<2>(j), 1e-14);
  if (!inverse) return r;
  const PointN<2> y{mid(b.u), mid(b.v)};
  const IntervalVec3 dy = sys.difference_at(y[0], y[1]);
  return krawczyk_step<2>(r.box, y, {dy[c.a], dy[c.b]}, j, *inverse);
}

/// The box of a step's result.
inline Box2 box_of(const KrawczykStep<2>& k) { return {k.box[0], k.box[1]}; }

/// A node's branch pair found by the search, as (u, v) of its system and its region of uniqueness.
struct FoundRoot {
  double u = 0, v = 0;
  Box2 unique;
  bool tangency = false;  // two branches that touch (chain_tangency.hpp), not a transversal crossing
  Box2 enclosure;         // holds the root (for every chain of a family's enclosure)
};

/// Search state shared by every system: the found roots, the work and the budget.
struct Search {
  std::size_t boxes = 0, undecided = 0, max_boxes = kMaxChainBoxes;
  bool out_of_budget = false;
  double min_width = kChainMinBoxWidth;       // undecided below this width (times max(1, |s|))
  double inflate_width = kChainInflateWidth;   // Newton and inflation below this width (times max(1, |s|))
  double root_spread = 0;                      // a family's: how far its roots may move (inflate's least rho / 8)
  std::size_t max_undecided = SIZE_MAX;        // a family's: more undecided boxes end the search (out_of_budget)
};

/// A box K known to hold exactly one root, narrowed by further Krawczyk steps while they shrink
/// it by a tenth at least (each keeps the root; from a wide box the first steps may shrink it
/// slowly before the quadratic ones): its middle is the reported root, the box its enclosure
/// (a few ulp wide, which the node assembly relies on to tell close branches apart).
template <class System>
Box2 contracted(const System& sys, Box2 k) {
  for (int it = 0; it < 40; ++it) {
    const BoxEvaluation e = sys.evaluate(k);
    const std::optional<Chart> c = chart_of(e.first, e.second);
    if (!c || c->apart) break;
    const KrawczykStep<2> next = chart_step(sys, k, e, *c);
    const Box2 n = next.verdict == KrawczykVerdict::none ? k : box_of(next);
    if (!(n.width() < 0.9 * k.width())) {
      if (n.width() <= k.width()) k = n;
      break;
    }
    k = n;
  }
  return k;
}

/// Newton from the box's middle (krawczyk.hpp's correction, 8 steps), then epsilon-inflation: the
/// Krawczyk test on x* +- rho, rho from 8 box widths down by 16: a root certified there joins
/// `known` (unless one already holds it). True when `known` grew.
template <class System>
bool inflate(const System& sys, const Box2& b, std::vector<FoundRoot>& known, double spread = 0) {
  double u = mid(b.u), v = mid(b.v);
  for (int it = 0; it < 8; ++it) {
    const BoxEvaluation e = sys.evaluate(Box2{Interval(u), Interval(v)});
    const std::optional<Chart> c = chart_of(e.first, e.second);
    if (!c || c->apart) return false;
    const IntervalMatrix<2> j{{{e.d_du[c->a], e.d_dv[c->a]}, {e.d_du[c->b], e.d_dv[c->b]}}};
    const DoubleVector<2> step = newton_correction<2>(midpoint<2>(j), DoubleVector<2>(mid(e.difference[c->a]), mid(e.difference[c->b])));
    u -= step(0);
    v -= step(1);
    if (!std::isfinite(u) || !std::isfinite(v)) return false;
  }
  const double reach = std::max(b.width(), spread);
  if (std::fabs(u - mid(b.u)) > 4 * reach || std::fabs(v - mid(b.v)) > 4 * reach) return false;
  // The first box x proved and its K(x).
  const auto proved = epsilon_inflation(8 * reach, 1.0 / 16, 1e-15 * std::max(1.0, std::fabs(u)), [&](double rho) -> std::optional<std::pair<Box2, Box2>> {
    const Box2 x{Interval(u - rho, u + rho), Interval(v - rho, v + rho)};
    const BoxEvaluation e = sys.evaluate(x);
    const std::optional<Chart> c = chart_of(e.first, e.second);
    if (!c || c->apart) return std::nullopt;
    const KrawczykStep<2> k = chart_step(sys, x, e, *c);
    if (k.verdict != KrawczykVerdict::unique) return std::nullopt;
    return std::make_pair(x, box_of(k));
  });
  if (!proved) return false;
  for (const FoundRoot& r : known)
    if (inside(proved->second, r.unique)) return false;  // already known: nothing new
  const Box2 root = contracted(sys, proved->second);
  known.push_back({mid(root.u), mid(root.v), proved->first, false, root});
  return true;
}

/// Branch and bound over one starting box of a system; `drop(box)` says a box needs no search
/// (outside the system's region, or inside a cusp's zone). Found roots go to `roots`.
template <class System, class Drop>
void search_box(const System& sys, const Box2& start, const Drop& drop, Search& work, std::vector<FoundRoot>& roots,
                std::vector<Box2>* undecided = nullptr) {
  std::vector<FoundRoot> local;
  std::vector<Box2> stack{start};
  while (!stack.empty()) {
    Box2 b = stack.back();
    stack.pop_back();
    if (++work.boxes > work.max_boxes) {
      work.out_of_budget = true;
      return;
    }
    if (drop(b) || std::any_of(local.begin(), local.end(), [&](const FoundRoot& r) { return inside(b, r.unique); })) continue;
    bool split = true;
    for (int round = 0; round < 4 && split; ++round) {
      const BoxEvaluation e = sys.evaluate(b);
      if (e.cleared) { split = false; break; }
      const std::optional<Chart> c = chart_of(e.first, e.second);
      if (c && c->apart) { split = false; break; }
      if (!c) break;
      const KrawczykStep<2> k = chart_step(sys, b, e, *c);
      if (k.verdict == KrawczykVerdict::none) { split = false; break; }
      if (k.verdict == KrawczykVerdict::unique) {
        const Box2 root = contracted(sys, box_of(k));
        local.push_back({mid(root.u), mid(root.v), b, false, root});
        split = false;
        break;
      }
      const bool shrank = box_of(k).width() < 0.7 * b.width();
      b = box_of(k);
      if (!shrank) break;
    }
    if (!split) continue;
    const double scale = std::max({1.0, std::fabs(b.u.inf()), std::fabs(b.v.inf())});
    if (b.width() < work.inflate_width * scale && inflate(sys, b, local, work.root_spread)) {
      stack.push_back(b);  // looked at again: inside the new region U, or split around it
      continue;
    }
    if (b.width() < work.min_width * scale) {
      ++work.undecided;
      if (undecided) undecided->push_back(b);
      if (work.undecided > work.max_undecided) {
        work.out_of_budget = true;
        return;
      }
      continue;
    }
    const bool along_u = b.u.sup() - b.u.inf() >= b.v.sup() - b.v.inf();
    const Interval& w = along_u ? b.u : b.v;
    const double m = mid(w);
    const Interval lo(w.inf(), m), hi(m, w.sup());
    stack.push_back(along_u ? Box2{lo, b.v} : Box2{b.u, lo});
    stack.push_back(along_u ? Box2{hi, b.v} : Box2{b.u, hi});
  }
  roots.insert(roots.end(), local.begin(), local.end());
}

}  // namespace chain_census_detail

}  // namespace sphtroch
