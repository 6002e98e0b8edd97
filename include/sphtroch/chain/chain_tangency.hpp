// sphtroch/chain/chain_tangency.hpp — where the chain census's branch and bound leaves
// boxes undecided (two branches nearly parallel where they meet: Krawczyk's Jacobian is nearly
// singular), decide how many times the branches meet: none, two crossings, or a tangency within
// the rounding of double. Used by chain_census.hpp on pairs of far arcs.
//
//   namespace d = sphtroch::chain_census_detail;
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   sphtroch::RoundingGuard upward;   // REQUIRED throughout
//   const sphtroch::ChainEnclosure e(chain);
//   std::optional<d::TangencyVerdict> v = d::resolve_tangency(e, d::Box2{sphtroch::Interval(0.43, 0.44),
//                                                                        sphtroch::Interval(8.98, 9.0)});
//
// Method (a Lyapunov-Schmidt reduction to one parameter). Over a region S x T around the
// undecided boxes, with u the unit tangent of the first branch at the middle s0 and n = P(s0) x u:
//  1. f1(s, t) = u . (P(s) - P(t)) has df1/dt = -u . P'(t) of one sign over T, so for each s at
//     most one t(s) in T meets it; a 1-D Krawczyk test encloses t(s0), and T holding
//     t(s0) + t'(S) (S - s0), t' = (u . P'(s)) / (u . P'(t)), gives t(s) in T for every s in S.
//  2. The branches meet where phi(s) = n . (P(s) - P(t(s))) vanishes (the third coordinate, along
//     P, agrees on unit vectors this close). phi'' = n . P''(s) - n . P''(t) t'^2 - n . P'(t) t'',
//     t'' = (u . P''(s) - u . P''(t) t'^2) / (u . P'(t)), enclosed over S x T: one sign, so phi
//     has at most two zeros in S, with phi at both ends of S of that sign away from 0.
//  3. phi at the extreme s_m (phi' = 0, by bisection): the sign of phi'' (no zero), the opposite
//     sign (two zeros, each certified as a crossing by the 2-D Krawczyk test), or an enclosure
//     holding 0: the branches touch within rounding: one tangency.
// Any failed step gives nullopt: the boxes stay undecided (not certified).
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_tangency.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/chain/chain_box_search.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace sphtroch {
namespace chain_census_detail {

/// What a region holds: its branch pairs (crossings, or one tangency), none when empty.
struct TangencyVerdict {
  std::vector<FoundRoot> pairs;
};

inline Vector3d middle(const IntervalVec3& v) { return Vector3d(mid(v[0]), mid(v[1]), mid(v[2])); }

/// The t in T with u . (P(s) - P(t)) = 0 for a thin s, enclosed by 1-D Krawczyk steps (krawczyk.hpp; unique in
/// T); nullopt when T holds none or the test cannot tell.
inline std::optional<Interval> branch_partner(const ChainEnclosure& e, const IntervalVec3& u, double s, Interval t) {
  const IntervalVec3 ps = e.jet(Interval(s)).point;
  bool unique = false;
  for (int it = 0; it < 40; ++it) {
    const double t0 = mid(t);
    const Interval f = dot(u, difference(ps, e.jet(Interval(t0)).point));
    const Interval d = -dot(u, e.sharp_jet(t).velocity);
    if (may_vanish(d)) return std::nullopt;
    const IntervalMatrix<1> slope{{{d}}};
    const std::optional<DoubleMatrix<1>> y = midpoint_inverse<1>(midpoint<1>(slope));
    if (!y) return std::nullopt;
    const KrawczykStep<1> k = krawczyk_step<1>({t}, {t0}, {f}, slope, *y);  // krawczyk.hpp
    if (k.verdict == KrawczykVerdict::none) return std::nullopt;
    if (k.verdict == KrawczykVerdict::unique) unique = true;
    const Interval next = k.box[0];
    const bool shrank = next.sup() - next.inf() < 0.5 * (t.sup() - t.inf());
    t = next;
    if (unique && !shrank) break;
  }
  if (!unique) return std::nullopt;
  return t;
}

/// phi(s) enclosed (nullopt when t(s) cannot be enclosed).
inline std::optional<Interval> branch_gap(const ChainEnclosure& e, const IntervalVec3& u, const IntervalVec3& n, double s,
                                          const Interval& t) {
  const std::optional<Interval> partner = branch_partner(e, u, s, t);
  if (!partner) return std::nullopt;
  return dot(n, difference(e.jet(Interval(s)).point, e.jet(*partner).point));
}

/// phi'(s) in double (its sign locates the extreme of phi; an estimate, not a proof).
inline double gap_slope(const ChainEnclosure& e, const IntervalVec3& u, const IntervalVec3& n, double s, const Interval& t) {
  const std::optional<Interval> partner = branch_partner(e, u, s, t);
  if (!partner) return std::nan("");
  const ChainJet js = e.jet(Interval(s)), jt = e.jet(Interval(mid(*partner)));
  const double tp = mid(dot(u, js.velocity)) / mid(dot(u, jt.velocity));
  return mid(dot(n, js.velocity)) - mid(dot(n, jt.velocity)) * tp;
}

/// The zero in [lo, hi] of a function with opposite signs at the ends (bisection, doubles).
template <class F>
double bisect(const F& f, double lo, double hi) {
  const bool rising = f(hi) > f(lo);
  for (int it = 0; it < 200 && lo < hi; ++it) {
    const double m = 0.5 * (lo + hi);
    if (m <= lo || m >= hi) break;
    const double v = f(m);
    if (std::isnan(v)) return std::nan("");
    if ((v > 0) == rising) hi = m;
    else lo = m;
  }
  return 0.5 * (lo + hi);
}

/// A crossing near (s, t) certified by the 2-D Krawczyk test on a small box around it.
inline std::optional<FoundRoot> certified_crossing(const ChainEnclosure& e, double s, double t, double width) {
  const FarPairs sys{&e};
  // Epsilon-inflation (krawczyk.hpp): boxes of radius width, width / 8, ... about (s, t).
  return epsilon_inflation(width, 0.125, 1e-15 * std::max(1.0, std::fabs(s) + std::fabs(t)), [&](double rho) -> std::optional<FoundRoot> {
    const Box2 x{Interval(s - rho, s + rho), Interval(t - rho, t + rho)};
    const BoxEvaluation ev = sys.evaluate(x);
    const std::optional<Chart> c = chart_of(ev.first, ev.second);
    if (!c || c->apart) return std::nullopt;
    const KrawczykStep<2> k = chart_step(sys, x, ev, *c);
    if (k.verdict != KrawczykVerdict::unique) return std::nullopt;
    const Box2 root = contracted(sys, box_of(k));
    return FoundRoot{mid(root.u), mid(root.v), x, false, root};
  });
}

/// Steps 1 and 2 of the header over the region: u, n, and the sign of phi'' (0 when not one sign).
inline int gap_curvature(const ChainEnclosure& e, const Box2& region, const IntervalVec3& u, const IntervalVec3& n) {
  const ChainJet js = e.sharp_jet(region.u), jt = e.sharp_jet(region.v);
  const Interval ut = dot(u, jt.velocity);
  if (may_vanish(ut)) return 0;
  const Interval tp = dot(u, js.velocity) / ut;
  const Interval tpp = (dot(u, js.acceleration) - dot(u, jt.acceleration) * tp * tp) / ut;
  const Interval phi2 = dot(n, js.acceleration) - dot(n, jt.acceleration) * tp * tp - dot(n, jt.velocity) * tpp;
  if (may_vanish(phi2)) return 0;
  // t(s) stays in T: t(s0) + t'(S) (S - s0) inside T.
  const double s0 = mid(region.u);
  const std::optional<Interval> t0 = branch_partner(e, u, s0, region.v);
  if (!t0) return 0;
  const Interval reach = *t0 + tp * (region.u - s0);
  if (!strictly_inside(reach, region.v)) return 0;
  return phi2.inf() > 0 ? 1 : -1;
}

/// The header's method over `region` (s in region.u, t in region.v); nullopt when undecided.
inline std::optional<TangencyVerdict> resolve_tangency(const ChainEnclosure& e, const Box2& region) {
  const double s0 = mid(region.u);
  const ChainJet j0 = e.jet(Interval(s0));
  const Vector3d p0 = middle(j0.point), v0 = middle(j0.velocity);
  if (!(v0.norm() > 0)) return std::nullopt;
  const IntervalVec3 u = thin_vector(v0.normalized()), n = thin_vector(p0.cross(v0.normalized()));
  const int sign = gap_curvature(e, region, u, n);
  if (sign == 0) return std::nullopt;
  const auto signed_gap = [&](double s) -> std::optional<Interval> {
    const std::optional<Interval> g = branch_gap(e, u, n, s, region.v);
    if (!g) return std::nullopt;
    return sign > 0 ? *g : -*g;
  };
  const std::optional<Interval> lo = signed_gap(region.u.inf()), hi = signed_gap(region.u.sup());
  if (!lo || !hi || !(lo->inf() > 0) || !(hi->inf() > 0)) return std::nullopt;
  const auto slope = [&](double s) { return gap_slope(e, u, n, s, region.v); };
  const double s_m = bisect(slope, region.u.inf(), region.u.sup());
  const std::optional<Interval> at = std::isnan(s_m) ? std::nullopt : signed_gap(s_m);
  if (!at) return std::nullopt;
  TangencyVerdict verdict;
  if (at->inf() > 0) return verdict;  // the branches miss each other
  const auto partner_of = [&](double s) {
    const std::optional<Interval> t = branch_partner(e, u, s, region.v);
    return t ? mid(*t) : std::nan("");
  };
  if (at->sup() < 0) {  // two crossings, one each side of s_m
    const auto gap = [&](double s) {
      const std::optional<Interval> g = signed_gap(s);
      return g ? mid(*g) : std::nan("");
    };
    for (const auto& [a, b] : {std::pair{region.u.inf(), s_m}, std::pair{s_m, region.u.sup()}}) {
      const double s = bisect(gap, a, b), t = std::isnan(s) ? s : partner_of(s);
      const std::optional<FoundRoot> r = std::isnan(t) ? std::nullopt : certified_crossing(e, s, t, 0.25 * (b - a));
      if (!r) return std::nullopt;
      verdict.pairs.push_back(*r);
    }
    return verdict;
  }
  const double t_m = partner_of(s_m);
  if (std::isnan(t_m)) return std::nullopt;
  verdict.pairs.push_back(FoundRoot{s_m, t_m, region, true, region});  // they touch within rounding
  return verdict;
}

}  // namespace chain_census_detail
}  // namespace sphtroch
