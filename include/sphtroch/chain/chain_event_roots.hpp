// sphtroch/chain/chain_event_roots.hpp — an event of a chain family (chain_family_events.hpp)
// certified as the root of its square system: the exact value of the varied twist or phase where
// a cusp is born, two branches touch or three branches meet, enclosed to a few ulps, with the
// curve parameters of the event.
//
//   const sphtroch::RotationChain chain({{1.2, sphtroch::ChainRate(1), 0.0}, {0.9, sphtroch::ChainRate(2), 0.0},
//                                        {0.7, sphtroch::ChainRate(-3), 0.0}});
//   const sphtroch::ChainVary a3 = sphtroch::parse_chain_vary("A3:0.8:0.94", 3);
//   const sphtroch::EventRoot r = sphtroch::event_root(chain, a3, sphtroch::BoundaryEventKind::cusp, 0.8212, 0.8213);
//   r.certified;   // one root of the cusp system, its value in [r.lo, r.hi] (0.82124284860366) meeting [0.8212, 0.8213]
//
// The systems, in x = (curve parameters, d) with the varied value lambda = lambda0 + d (lambda0 the
// bracket's middle) and (e1, e2) a tangent frame at the event's point P0, every point of the box
// required in P0's open hemisphere (so the two tangent components vanish only where the vectors do):
//   cusp (s, d):              e . P'(s) = 0 for e = e1, e2              (P' = omega x P = 0: P || omega)
//   tangency (s, t, d):       e . (P(s) - P(t)) = 0,  P(s) . (P'(s) x P'(t)) = 0   (one point, parallel tangents)
//   triple point (s, t, u, d): e . (P(s) - P(t)) = 0,  e . (P(s) - P(u)) = 0
// Each is square, and its root is regular at a generic event of the family. The Jacobians use
// dP/dd and dP'/dd of ChainEnclosure::family_jet.
// Method: a start from the censuses either side of the bracket (the two nodes that meet, the three
// nodes that meet) or, for a cusp, from the slowest point of the curve at lambda0; Newton's method
// in double; then Krawczyk's test K(X) = c - Y F(c) + (I - Y J(X)) (X - c), Y = (mid J(X))^-1, on
// boxes of radius 1e-7 down to 1e-13 (times max(1, |x_i|)) about Newton's point. K(X) inside X
// proves exactly one root in X (Krawczyk 1969; Moore's interval analysis). The root counts only
// when its value meets the bracket [lo, hi] (where the census changes). Not certified: a start not
// found, Newton not converging, or no box proved: a degenerate event, whose root is singular (a
// cusp where P'' = 0 too; at a mirror-symmetric chain, three crossings of the same two branches
// born at once: a tangency of third order).
// Cost: one or two censuses at single values, a scan of the period (cusp), a few dozen enclosures.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_event_roots.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/chain/chain_census.hpp"
#include "sphtroch/interval/krawczyk.hpp"
#include "sphtroch/chain/chain_events.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace sphtroch {

namespace chain_event_detail {

/// F over a box and its Jacobian J[row][column] over it; `ok` false when a point of the box may
/// leave P0's hemisphere (the system is then not the event's).
template <std::size_t n>
struct SystemEnclosure {
  IntervalBox<n> f;
  std::array<IntervalBox<n>, n> jacobian;
  bool ok = true;
};


/// The header's systems: n = 2 cusp, 3 tangency, 4 triple point. REQUIRES rounding upward.
template <std::size_t n>
class EventSystem {
 public:
  EventSystem(const RotationChain& curve, const ChainWidening& signs, const Vector3d& p0) : curve_(curve), signs_(signs) {
    const Vector3d a = p0.unitOrthogonal();
    p0_ = thin_vector(p0);
    frame_ = {thin_vector(a), thin_vector(p0.cross(a))};
  }

  SystemEnclosure<n> operator()(const IntervalBox<n>& x) const {
    ChainWidening w = signs_;
    w.offset = x[n - 1];
    const ChainEnclosure e(curve_, w);
    std::array<FamilyJet, n - 1> jets;
    SystemEnclosure<n> out;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      jets[i] = e.family_jet(x[i]);
      out.ok = out.ok && dot(p0_, jets[i].jet.point).inf() > 0;
    }
    if constexpr (n == 2) cusp_rows(jets[0], out);
    else {
      coincidence_rows(jets[0], jets[1], 1, 0, out);
      if constexpr (n == 3) parallel_row(jets[0], jets[1], out);
      else coincidence_rows(jets[0], jets[2], 2, 2, out);
    }
    return out;
  }

 private:
  static Interval zero() { return Interval(0.0); }
  /// e . P'(s) for both e: columns s, d.
  void cusp_rows(const FamilyJet& s, SystemEnclosure<n>& out) const {
    for (std::size_t r = 0; r < 2; ++r) {
      out.f[r] = dot(frame_[r], s.jet.velocity);
      out.jacobian[r][0] = dot(frame_[r], s.jet.acceleration);
      out.jacobian[r][n - 1] = dot(frame_[r], s.velocity_d);
    }
  }
  /// Rows `row`, `row` + 1: e . (P(s) - P(v)) with v the parameter in column `column` (1 or 2).
  void coincidence_rows(const FamilyJet& s, const FamilyJet& v, std::size_t column, std::size_t row, SystemEnclosure<n>& out) const {
    for (std::size_t r = 0; r < 2; ++r) {
      IntervalBox<n>& j = out.jacobian[row + r];
      out.f[row + r] = dot(frame_[r], difference(s.jet.point, v.jet.point));
      j.fill(zero());
      j[0] = dot(frame_[r], s.jet.velocity);
      j[column] = -dot(frame_[r], v.jet.velocity);
      j[n - 1] = dot(frame_[r], difference(s.point_d, v.point_d));
    }
  }
  /// Row 2 of the tangency: P(s) . (P'(s) x P'(t)).
  void parallel_row(const FamilyJet& s, const FamilyJet& t, SystemEnclosure<n>& out) const {
    const IntervalVec3& p = s.jet.point;
    const IntervalVec3 vv = cross(s.jet.velocity, t.jet.velocity);
    out.f[2] = dot(p, vv);
    out.jacobian[2][0] = dot(p, cross(s.jet.acceleration, t.jet.velocity));
    out.jacobian[2][1] = dot(p, cross(s.jet.velocity, t.jet.acceleration));
    out.jacobian[2][2] = dot(s.point_d, vv) + dot(p, cross(s.velocity_d, t.jet.velocity)) + dot(p, cross(s.jet.velocity, t.velocity_d));
  }

  RotationChain curve_;
  ChainWidening signs_;
  IntervalVec3 p0_;
  std::array<IntervalVec3, 2> frame_;
};

/// Newton's method from x in double (the system's middles; krawczyk.hpp's correction); nothing
/// unless it converges.
template <std::size_t n>
std::optional<PointN<n>> newton(const EventSystem<n>& system, PointN<n> x) {
  constexpr int N = int(n);
  for (int it = 0; it < 40; ++it) {
    const SystemEnclosure<n> v = system(point_box<n>(x));
    if (!v.ok) return std::nullopt;
    DoubleVector<n> f;
    for (int i = 0; i < N; ++i) f(i) = mid(v.f[std::size_t(i)]);
    const DoubleVector<n> step = newton_correction<n>(midpoint<n>(v.jacobian), f);
    if (!step.allFinite()) return std::nullopt;
    double size = 0, scale = 1;
    for (int i = 0; i < N; ++i) {
      x[std::size_t(i)] -= step(i);
      size = std::max(size, std::fabs(step(i)));
      scale = std::max(scale, std::fabs(x[std::size_t(i)]));
    }
    if (!std::isfinite(size)) return std::nullopt;
    if (size <= 1e-15 * scale) return x;
  }
  return std::nullopt;
}

/// Krawczyk's step (krawczyk.hpp, Y the inverse of mid J(X)) on X, then on its result, six times
/// (header): the box holding the one root of X, or nothing when not proved.
template <std::size_t n>
std::optional<IntervalBox<n>> proved_root(const EventSystem<n>& system, IntervalBox<n> x) {
  bool proved = false;
  for (int it = 0; it < 6; ++it) {
    const PointN<n> c = centre<n>(x);
    const SystemEnclosure<n> at = system(point_box<n>(c)), over = system(x);
    if (!at.ok || !over.ok) return std::nullopt;
    const std::optional<DoubleMatrix<n>> inverse = midpoint_inverse<n>(midpoint<n>(over.jacobian));
    if (!inverse) return std::nullopt;
    const KrawczykStep<n> k = krawczyk_step<n>(x, c, at.f, over.jacobian, *inverse);
    if (k.verdict == KrawczykVerdict::none) return std::nullopt;  // no root in X
    proved = proved || k.verdict == KrawczykVerdict::unique;
    x = k.box;
  }
  if (!proved) return std::nullopt;
  return x;
}

/// Epsilon-inflation (krawczyk.hpp) about a Newton point: boxes of radius 1e-7 down to 1e-13
/// (times max(1, |x_i|)), each given to proved_root (header).
template <std::size_t n>
std::optional<IntervalBox<n>> isolate(const EventSystem<n>& system, const PointN<n>& start) {
  const std::optional<PointN<n>> x = newton(system, start);
  if (!x) return std::nullopt;
  return epsilon_inflation(1e-7, 0.01, 1e-13, [&](double radius) { return proved_root(system, box_about<n>(*x, radius, true)); });
}

/// p's copy (p + k T) nearest q.
inline double nearest_copy(double p, double q, double period) { return p + period * std::round((q - p) / period); }

/// Distance of two parameters modulo the period.
inline double param_distance(double a, double b, double period) { return std::fabs(nearest_copy(a, b, period) - b); }

/// The parameters of the two nodes of a census closest to each other branch by branch (the two
/// crossings a tangency merges): the middles, as (s, t); nothing without two two-branch nodes.
inline std::optional<std::array<double, 2>> merging_pair(const ChainCensus& c) {
  std::optional<std::array<double, 2>> best;
  double closest = 0;
  for (std::size_t a = 0; a < c.nodes.size(); ++a)
    for (std::size_t b = a + 1; b < c.nodes.size(); ++b) {
      const Node& x = c.nodes[a];
      const Node& y = c.nodes[b];
      if (x.branches != 2 || y.branches != 2) continue;
      for (const bool swap : {false, true}) {
        const double y0 = y.params[swap ? 1 : 0], y1 = y.params[swap ? 0 : 1];
        const double gap = std::max(param_distance(x.params[0], y0, c.period), param_distance(x.params[1], y1, c.period));
        if (best && gap >= closest) continue;
        closest = gap;
        best = std::array<double, 2>{0.5 * (x.params[0] + nearest_copy(y0, x.params[0], c.period)),
                                     0.5 * (x.params[1] + nearest_copy(y1, x.params[1], c.period))};
      }
    }
  return best;
}

/// The three branch parameters of the three two-branch nodes of a census closest to each other
/// (largest pairwise distance least); nothing without three.
inline std::optional<std::array<double, 3>> meeting_triple(const ChainCensus& c) {
  std::optional<std::array<double, 3>> best;
  double closest = 0;
  const std::size_t m = c.nodes.size();
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b)
      for (std::size_t k = b + 1; k < m; ++k) {
        const Node* t[3] = {&c.nodes[a], &c.nodes[b], &c.nodes[k]};
        if (t[0]->branches != 2 || t[1]->branches != 2 || t[2]->branches != 2) continue;
        const double spread = std::max({(t[0]->position - t[1]->position).norm(), (t[0]->position - t[2]->position).norm(),
                                        (t[1]->position - t[2]->position).norm()});
        if (best && spread >= closest) continue;
        const double s = t[0]->params[0], u = t[0]->params[1];
        double third = t[1]->params[0];  // the parameter of b and k farthest from both of a's
        for (const Node* x : {t[1], t[2]})
          for (const double p : x->params)
            if (std::min(param_distance(p, s, c.period), param_distance(p, u, c.period)) >
                std::min(param_distance(third, s, c.period), param_distance(third, u, c.period)))
              third = p;
        closest = spread;
        best = std::array<double, 3>{s, u, third};
      }
  return best;
}

/// Parameters where |P'| has its least local minima at the chain (the slowest first, at most 4).
inline std::vector<double> slowest_points(const RotationChain& curve_chain) {
  const ChainCurve<double> curve(curve_chain);
  const double period = curve.period();
  const auto samples = static_cast<std::size_t>(std::clamp(16 * chain_census_arcs(curve_chain), 1024.0, 1e6));
  std::vector<double> speed(samples);
  for (std::size_t i = 0; i < samples; ++i) speed[i] = curve.velocity(period * static_cast<double>(i) / static_cast<double>(samples)).norm();
  std::vector<std::size_t> minima;
  for (std::size_t i = 0; i < samples; ++i)
    if (speed[i] <= speed[(i + samples - 1) % samples] && speed[i] <= speed[(i + 1) % samples]) minima.push_back(i);
  std::sort(minima.begin(), minima.end(), [&](std::size_t a, std::size_t b) { return speed[a] < speed[b]; });
  std::vector<double> out;
  for (std::size_t i = 0; i < minima.size() && i < 4; ++i) out.push_back(period * static_cast<double>(minima[i]) / static_cast<double>(samples));
  return out;
}

/// The root of the event system from `start` (curve parameters; d = `d0`), as an EventRoot
/// (value lambda0 + d), certified when proved with its value meeting [lo, hi].
template <std::size_t n>
EventRoot root_from(const RotationChain& curve_chain, const ChainWidening& signs, double lambda0, const std::array<double, n - 1>& start,
                    double d0, double lo, double hi) {
  EventRoot out;
  const Vector3d p0 = ChainCurve<double>(curve_chain).point(start[0]);
  const RoundingGuard upward;
  const EventSystem<n> system(curve_chain, signs, p0);
  PointN<n> x;
  std::copy(start.begin(), start.end(), x.begin());
  x[n - 1] = d0;
  const std::optional<IntervalBox<n>> root = isolate(system, x);
  if (!root) return out;
  const Interval value = Interval(lambda0) + (*root)[n - 1];
  if (value.sup() < lo || value.inf() > hi) return out;
  out.certified = true;
  out.lo = value.inf(), out.hi = value.sup();
  for (std::size_t i = 0; i + 1 < n; ++i) out.params.push_back(mid((*root)[i]));
  return out;
}

}  // namespace chain_event_detail

/// The event of `kind` (cusp, tangency or triple_point) of the family whose census changes in
/// [lo, hi], certified as the root of its square system (header); `certified` false otherwise.
/// REQUIRES lo <= hi inside the family's range, the chain's varied parameter free to move there.
inline EventRoot event_root(const RotationChain& chain, const ChainVary& vary, BoundaryEventKind kind, double lo, double hi) {
  namespace d = chain_event_detail;
  EventRoot out;
  out.bracket_lo = lo, out.bracket_hi = hi;
  const double lambda0 = 0.5 * (lo + hi);
  const FamilyCurve family = family_curve(chain, vary, lambda0);
  const RotationChain& curve = family.curve;
  const auto keep = [&](EventRoot r) {
    r.bracket_lo = lo, r.bracket_hi = hi;
    return r;
  };
  if (kind == BoundaryEventKind::cusp) {
    for (const double s : d::slowest_points(curve)) {
      const EventRoot r = d::root_from<2>(curve, family.signs, lambda0, {s}, 0.0, lo, hi);
      if (r.certified) return keep(r);
    }
    return out;
  }
  if (kind == BoundaryEventKind::tangency) {
    for (const double side : {lo, hi}) {
      const ChainCensus c = chain_census(chain_at(chain, vary, side));
      const std::optional<std::array<double, 2>> st = c.certified ? d::merging_pair(c) : std::nullopt;
      if (!st) continue;
      const EventRoot r = d::root_from<3>(curve, family.signs, lambda0, *st, side - lambda0, lo, hi);
      if (r.certified) return keep(r);
    }
    return out;
  }
  if (kind == BoundaryEventKind::triple_point) {
    for (const double side : {lo, lambda0, hi}) {
      const ChainCensus c = chain_census(chain_at(chain, vary, side));
      const std::optional<std::array<double, 3>> stu = d::meeting_triple(c);
      if (!stu) continue;
      const EventRoot r = d::root_from<4>(curve, family.signs, lambda0, *stu, side - lambda0, lo, hi);
      if (r.certified) return keep(r);
    }
  }
  return out;
}

}  // namespace sphtroch
