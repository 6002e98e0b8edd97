// sphtroch/tolerance/boundary_enclosure.hpp — which boundaries of the (a2, a3) design map
// may meet a box of twist angles, and a certified point of one of them on a segment: the two
// questions that topology_margin.hpp's branch and bound asks. Interval arithmetic (interval.hpp).
//
//   sphtroch::RoundingGuard upward;
//   const sphtroch::TwistBox box{1.0, 1.01, 2.0, 2.01};
//   const auto may_meet = sphtroch::boundaries_possibly_in(box, sphtroch::Ratio(5, 2));  // empty: none does
//   for (const sphtroch::MapBoundary& b : may_meet)
//     if (auto w = sphtroch::boundary_point_on(b, sphtroch::TwistBox{1.005, 1.005, 2.0, 2.01}, sphtroch::Ratio(5, 2)))
//       w->a3_lo, w->a3_hi;   // a point of b lies on this segment (certified)
//
// The boundaries (map/boundary_events.hpp derives them; notation of map/root_function.hpp), each
// the zero set in (0, pi)^2 of a function that is continuous where it is used:
//   pitch cone          q sin(a3 - a2) + p sin a3   (g'(pi) = 0: a3 = a_p = atan2(q sa2, q ca2 + p),
//                                                    its only zero in a3 for each a2)
//   mirror pitch cone   q sin(a2 + a3) + p sin a3   (g'(0) = 0: a3 = pi - a_p)
//   pole lines          a3 - a2 and a2 + a3 - pi    (|p| >= 2 only: for |p| = 1 a pole on the curve
//                                                    is no node, and the boundary set has no pole event)
//   tangency (l, m)     G_l - m, G_l(a2, a3) = g(b*_l) the value of g at its stationary point of
//                       label l (0: the larger b), where b*_l is real and in (0, pi).
// Enclosing G_l over a box: the stationary cosine c_l (the quadratic of root_function.hpp, A < 0
// in the open square, so c_0 = (-B + sqrt D)/(2A)), D clamped at 0 (values where b*_l does not
// exist only widen the result), b = acos(c_l); then G_l lies in g(b_m) + g'(B)(B - b_m) over the
// box (mean value in b: g' vanishes at b*, so this is sharp to second order), with
// g = (p (2 atan(y/x) - pi) + 2 q b)/(2 pi) (x > 0 inside (0, pi)) and, near an end whose y has a
// fixed sign, g = g(end) + (p daz + q (b - end))/pi with daz = -atan(x/y), intersected.
// One integer is never a tangency value: g is strictly monotone between b*_0 and pi (no other zero
// of g' there), so G_0 != g(pi) while the end pi is not a pole (and G_1 != g(0)). This is what lets
// a box next to a pitch cone, where G_0 tends to g(pi), be cleared.
// Contract: a boundary that meets the box is in boundaries_possibly_in (the converse need not
// hold); boundary_point_on returns a segment only when the function changes sign between its ends
// with certified signs and is continuous along it (for a tangency: D > 0 and c_l in (-1, 1)
// proved over the segment). REQUIRES the rounding mode upward (RoundingGuard) and a box inside
// (0, pi)^2.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/tolerance/boundary_enclosure.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/ratio.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/tolerance/tolerance_types.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// Every boundary that may meet the box (empty: certified that none does). A box where G_l cannot
/// be enclosed (a pole of the curve's circle inside, or more than 64 integers in reach) reports a
/// tangency with label -1: it must be split.
inline std::vector<MapBoundary> boundaries_possibly_in(const TwistBox& box, const Ratio& n);

/// A certified point of `b` on the segment `seg` (a2_lo == a2_hi or a3_lo == a3_hi), narrowed by
/// bisection to the shortest sub-segment still proved (at most 60 steps); nothing if unproved.
inline std::optional<TwistBox> boundary_point_on(const MapBoundary& b, const TwistBox& seg, const Ratio& n);

// ------------------------------------------------------------------------------------------------

namespace boundary_enclosure_detail {

inline Interval pi_interval() { return Interval(3.141592653589793, 3.1415926535897936); }

struct BoxTrig {
  Interval a2, a3, sa2, ca2, sa3, ca3;
};

inline BoxTrig box_trig(const TwistBox& box) {
  BoxTrig t;
  t.a2 = Interval(box.a2_lo, box.a2_hi);
  t.a3 = Interval(box.a3_lo, box.a3_hi);
  const auto sc = interval_sincos_all<2>({t.a2, t.a3});
  t.sa2 = sc[0].first;
  t.ca2 = sc[0].second;
  t.sa3 = sc[1].first;
  t.ca3 = sc[1].second;
  return t;
}

/// The closed-form boundary functions over the box.
inline Interval closed_form(MapBoundary::Kind kind, const BoxTrig& t, const Ratio& n) {
  const double p = static_cast<double>(n.p()), q = static_cast<double>(n.q());
  switch (kind) {
    case MapBoundary::Kind::pitch_cone: return q * interval_sin(t.a3 - t.a2) + p * t.sa3;
    case MapBoundary::Kind::mirror_pitch_cone: return q * interval_sin(t.a2 + t.a3) + p * t.sa3;
    case MapBoundary::Kind::north_pole: return t.a3 - t.a2;
    case MapBoundary::Kind::south_pole: return t.a2 + t.a3 - pi_interval();
    case MapBoundary::Kind::tangency: break;
  }
  return Interval(-1.0, 1.0);
}

/// A pitch-cone function over the box, sharp where its terms cancel: the natural form intersected
/// with the mean-value form about the box's centre (partial derivatives enclosed over the box).
/// With |p| = q the function vanishes identically along a2 = 0 or a2 = pi (q sin(a3 - a2) - q sin a3
/// = -2 q cos(a3 - a2/2) sin(a2/2)), where the natural form alone cannot prove a sign next to it.
inline Interval cone_function(MapBoundary::Kind kind, const BoxTrig& t, const Ratio& n) {
  const Interval natural = closed_form(kind, t, n);
  if (kind != MapBoundary::Kind::pitch_cone && kind != MapBoundary::Kind::mirror_pitch_cone) return natural;
  const double p = static_cast<double>(n.p()), q = static_cast<double>(n.q());
  const Interval c2 = centre_of(t.a2), c3 = centre_of(t.a3);
  const BoxTrig centre = box_trig(TwistBox{c2.inf(), c2.inf(), c3.inf(), c3.inf()});
  const bool mirror = kind == MapBoundary::Kind::mirror_pitch_cone;
  const Interval cos_pair = interval_cos(mirror ? t.a2 + t.a3 : t.a3 - t.a2);  // over the box
  const Interval df[2] = {mirror ? q * cos_pair : -q * cos_pair, q * cos_pair + p * t.ca3};
  const Interval dx[2] = {t.a2 - c2, t.a3 - c3};
  const Interval mv = mean_value<2>(closed_form(kind, centre, n), df, dx);
  const double lo = std::max(natural.inf(), mv.inf()), hi = std::min(natural.sup(), mv.sup());
  return lo <= hi ? Interval(lo, hi) : natural;  // both enclose it: they meet
}

/// G_l over the box, or nothing when it cannot be enclosed; `exists`: b*_l is real and in (0, pi)
/// over the whole box (D > 0, c_l in (-1, 1)); `none`: b*_l exists nowhere in the box.
struct StationaryValue {
  bool none = false, exists = false;
  std::optional<Interval> value;
  /// G_l lies strictly inside (open_lo, open_hi) however b*_l lies in its interval B: with
  /// az in (-pi/2, pi/2) (x > 0 for b in (0, pi)), g = p (az/pi - 1/2) + q b/pi lies in
  /// (min(-p, 0), max(-p, 0)) + q B/pi. Coarse, but it holds where `value` cannot be had (a pole of
  /// the circle at an end of B).
  double open_lo = 0, open_hi = 0;
};

/// c_l over the box, narrowed by interval Newton steps on Q(c) = A c^2 + B c + C (Q'(c_l) =
/// -+sqrt D is away from 0 where the roots are apart); nothing when a step proves no root.
/// The quadratic is divided by sa2 > 0 (same roots; the discriminant's sign is kept): A = -q sa2
/// sa3^2, B = sa3 ca3 (2 q ca2 + p), C = q sa2 + sa3^2 ca2 K with K = (q ca2 + p)/sa2, K taken in
/// half angles ((p + q) - 2 q sin^2(a2/2) below pi/2, (p - q) + 2 q cos^2(a2/2) above) so that it
/// does not cancel where p = -+q and a2 -> 0 or pi: there A, B and C all vanish with sa2 and the
/// undivided quadratic leaves c unbounded over any box.
inline std::optional<Interval> stationary_cos(const BoxTrig& t, double p, double q, int label, Interval& disc) {
  const auto [s_half, c_half] = interval_sincos(t.a2 / 2);
  const Interval K = (t.a2.sup() <= 1.5707963267948966 ? (p + q) - 2 * q * square(s_half) : (p - q) + 2 * q * square(c_half)) / t.sa2;
  const Interval A = -q * t.sa2 * square(t.sa3);
  const Interval B = t.sa3 * t.ca3 * (2 * q * t.ca2 + p);
  const Interval C = q * t.sa2 + square(t.sa3) * t.ca2 * K;
  disc = square(B) - 4 * A * C;
  const Interval root = sqrt(Interval(std::max(disc.inf(), 0.0), std::max(disc.sup(), 0.0)));
  // Both forms of the root, (-B -+ sqrt D)/(2A) = 2C/(-B +- sqrt D), intersected: the second is
  // the sharp one where the first cancels (and where A -> 0 at the edges of the square).
  Interval c = (label == 0 ? -B + root : -B - root) / (2 * A);
  const Interval other = label == 0 ? -B - root : -B + root;
  if (!may_vanish(other)) {
    const Interval alt = 2 * C / other;
    const double lo = std::max(c.inf(), alt.inf()), hi = std::min(c.sup(), alt.sup());
    if (lo > hi) return std::nullopt;
    c = Interval(lo, hi);
  }
  for (int step = 0; step < 3; ++step) {
    const Interval slope = 2 * A * c + B;
    if (may_vanish(slope) || !(c.sup() - c.inf() < 1e300)) break;
    const double mid = 0.5 * (c.inf() + c.sup());
    const Interval next = mid - (A * square(Interval(mid)) + B * mid + C) / slope;
    const double lo = std::max(c.inf(), next.inf()), hi = std::min(c.sup(), next.sup());
    if (lo > hi) return std::nullopt;
    if (!(hi - lo < 0.5 * (c.sup() - c.inf()))) {
      c = Interval(lo, hi);
      break;
    }
    c = Interval(lo, hi);
  }
  return c;
}

/// g at the planet angle b (an interval) over the box's twists; nothing if no formula applies.
inline std::optional<Interval> g_over(const Interval& b, const BoxTrig& t, double p, double q) {
  const Interval pi = pi_interval();
  const auto [sb, cb] = interval_sincos(b);
  const Interval x = t.sa3 * sb, y = -(t.sa3 * t.ca2 * cb + t.ca3 * t.sa2);
  std::optional<Interval> g;
  if (x.inf() > 0) g = (p * (2 * interval_atan(y / x) - pi) + 2 * q * b) / (2 * pi);
  const bool near_pi = b.inf() + b.sup() > 3.141592653589793;
  const Interval y_end = near_pi ? t.sa3 * t.ca2 - t.ca3 * t.sa2 : -(t.sa3 * t.ca2 + t.ca3 * t.sa2);
  const bool same_sign = (y_end.inf() > 0 && y.inf() > 0) || (y_end.sup() < 0 && y.sup() < 0);
  if (same_sign) {
    const double g_end = near_pi ? (y_end.inf() > 0 ? q : q - p) : (y_end.sup() < 0 ? -p : 0.0);
    const Interval end = near_pi ? pi : Interval(0.0);
    const Interval relative = g_end + (p * -interval_atan(x / y) + q * (b - end)) / pi;
    if (!g) return relative;
    const double lo = std::max(g->inf(), relative.inf()), hi = std::min(g->sup(), relative.sup());
    if (lo <= hi) return Interval(lo, hi);
  }
  return g;
}

/// g'(b) over an interval b and the box (root_function.hpp's dg_db); nothing if x^2 + y^2 may vanish.
inline std::optional<Interval> dg_db_over(const Interval& b, const BoxTrig& t, double p, double q) {
  const auto [sb, cb] = interval_sincos(b);
  const Interval x = t.sa3 * sb, y = -(t.sa3 * t.ca2 * cb + t.ca3 * t.sa2);
  const Interval r2 = square(x) + square(y);
  if (!(r2.inf() > 0)) return std::nullopt;
  return (p * (square(t.sa3) * t.ca2 + t.sa3 * t.ca3 * t.sa2 * cb) / r2 + q) / pi_interval();
}

inline StationaryValue stationary_value(const BoxTrig& t, const Ratio& n, int label);

/// The partial derivatives of g in a2 and a3 at planet angles `b` over the box's twists (with
/// x' = 0, y' = sa3 sa2 cb - ca3 ca2 in a2; x' = ca3 sb, y' = sa3 sa2 - ca3 ca2 cb in a3; g_a =
/// p (x y' - y x') / (pi (x^2 + y^2))); nothing if x^2 + y^2 may vanish.
inline std::optional<std::array<Interval, 2>> dg_dtwists_over(const Interval& b, const BoxTrig& t, double p) {
  const auto [sb, cb] = interval_sincos(b);
  const Interval x = t.sa3 * sb, y = -(t.sa3 * t.ca2 * cb + t.ca3 * t.sa2);
  const Interval r2 = square(x) + square(y);
  if (!(r2.inf() > 0)) return std::nullopt;
  const Interval scale = p / (pi_interval() * r2);
  return std::array<Interval, 2>{scale * x * (t.sa3 * t.sa2 * cb - t.ca3 * t.ca2),
                                 scale * (x * (t.sa3 * t.sa2 - t.ca3 * t.ca2 * cb) - y * t.ca3 * sb)};
}

/// Narrows G_l over a box where b*_l exists throughout (so G_l is C^1 there) by its mean-value
/// form in the twists: G_l(centre) + dG/da2 (a2 - c2) + dG/da3 (a3 - c3), where by the envelope
/// theorem (g_b = 0 at b*) dG/da = g_a(b*, a), enclosed with b* in `b`. Sharp where G_l - m is
/// small over a box much wider than its distance to the boundary (a tangency locus running into
/// a2 = 0 or pi, where the box's own enclosure loses the factor a2_lo / a2_hi).
inline void narrow_by_envelope(StationaryValue& s, const BoxTrig& t, const Interval& b, const Ratio& n, int label) {
  if (t.a2.inf() == t.a2.sup() && t.a3.inf() == t.a3.sup()) return;
  const Interval c2 = centre_of(t.a2), c3 = centre_of(t.a3);
  const StationaryValue at_centre = stationary_value(box_trig(TwistBox{c2.inf(), c2.inf(), c3.inf(), c3.inf()}), n, label);
  const auto partials = dg_dtwists_over(b, t, static_cast<double>(n.p()));
  if (!at_centre.value || !partials) return;
  const Interval dx[2] = {t.a2 - c2, t.a3 - c3};
  const Interval mv = mean_value<2>(*at_centre.value, partials->data(), dx);
  const double lo = std::max(s.value->inf(), mv.inf()), hi = std::min(s.value->sup(), mv.sup());
  if (lo <= hi) s.value = Interval(lo, hi);
}

inline StationaryValue stationary_value(const BoxTrig& t, const Ratio& n, int label) {
  const double p = static_cast<double>(n.p()), q = static_cast<double>(n.q());
  StationaryValue s;
  Interval disc;
  const std::optional<Interval> c = stationary_cos(t, p, q, label, disc);
  if (!c || disc.sup() < 0 || c->sup() <= -1 || c->inf() >= 1) {
    s.none = true;
    return s;
  }
  s.exists = disc.inf() > 0 && c->inf() > -1 && c->sup() < 1;
  const Interval b = interval_acos(*c);
  const Interval pi = pi_interval();
  // At the ends (b = 0, b/pi = 1) the bounds are integers, taken exactly: an interval kernel that
  // steps every result outward (CGAL_ALWAYS_ROUND_TO_NEAREST, the WebAssembly build) would move
  // them off the integer and let an excluded value back in.
  s.open_lo = b.inf() <= 0 ? std::min(-p, 0.0) : (std::min(-p, 0.0) + q * Interval(b.inf()) / pi).inf();
  s.open_hi = b.sup() >= 3.141592653589793 ? std::max(-p, 0.0) + q  // b/pi <= 1
                                           : (std::max(-p, 0.0) + q * (Interval(b.sup()) / pi)).sup();
  const Interval b_mid(0.5 * (b.inf() + b.sup()));
  const auto g_mid = g_over(b_mid, t, p, q);
  const auto slope = dg_db_over(b, t, p, q);
  if (g_mid && slope) s.value = *g_mid + *slope * (b - b_mid);
  if (s.exists && s.value) narrow_by_envelope(s, t, b, n, label);
  return s;
}

/// The integer G_0 (G_1) never equals: g at the end pi (0). Where b*_0 exists, c_0 > -1, so
/// Q(-1) = sin(a3 - a2) (q sin(a3 - a2) + p sin a3) < 0 (A < 0): the end's y = sin(a3 - a2) has the
/// sign opposite to the pitch-cone function (for b*_1 and the end 0: Q(1) = sin(a2 + a3) times the
/// mirror function, y = -sin(a2 + a3), the same sign). So g(end) is one integer over the box where
/// that function keeps its sign, even across a pole line.
inline std::optional<std::int64_t> excluded_value(const BoxTrig& t, const Ratio& n, int label) {
  const Interval h = closed_form(label == 0 ? MapBoundary::Kind::pitch_cone : MapBoundary::Kind::mirror_pitch_cone, t, n);
  if (may_vanish(h)) return std::nullopt;
  if (label == 0) return h.sup() < 0 ? n.q() : n.q() - n.p();  // y(pi) > 0 exactly when h < 0
  return h.sup() < 0 ? -n.p() : 0;                             // y(0) < 0 exactly when h < 0
}

constexpr std::int64_t kMaxIntegersInReach = 64;

inline std::vector<MapBoundary> closed_forms(const Ratio& n) {
  std::vector<MapBoundary> k{{MapBoundary::Kind::pitch_cone}, {MapBoundary::Kind::mirror_pitch_cone}};
  if (n.abs_p() >= 2) k.insert(k.end(), {{MapBoundary::Kind::north_pole}, {MapBoundary::Kind::south_pole}});
  return k;
}

/// The certified sign of a boundary function at a point (0: unknown), and for a tangency whether
/// b*_l exists there.
inline int sign_at(const MapBoundary& b, double a2, double a3, const Ratio& n) {
  const BoxTrig t = box_trig(TwistBox{a2, a2, a3, a3});
  Interval v;
  if (b.kind == MapBoundary::Kind::tangency) {
    const StationaryValue s = stationary_value(t, n, b.label);
    if (!s.exists || !s.value) return 0;
    v = *s.value - static_cast<double>(b.m);
  } else {
    v = closed_form(b.kind, t, n);
  }
  return v.inf() > 0 ? 1 : (v.sup() < 0 ? -1 : 0);
}

}  // namespace boundary_enclosure_detail


inline std::vector<MapBoundary> boundaries_possibly_in(const TwistBox& box, const Ratio& n) {
  namespace d = boundary_enclosure_detail;
  const d::BoxTrig t = d::box_trig(box);
  std::vector<MapBoundary> out;
  for (const MapBoundary& b : d::closed_forms(n))
    if (may_vanish(d::cone_function(b.kind, t, n))) out.push_back(b);
  for (int label = 0; label < 2; ++label) {
    const d::StationaryValue s = d::stationary_value(t, n, label);
    if (s.none) continue;
    // Integers m with open_lo < m < open_hi (the open bound) and inside the closed one.
    double first = std::floor(s.open_lo) + 1, last = std::ceil(s.open_hi) - 1;
    if (s.value) {
      first = std::max(first, std::ceil(s.value->inf()));
      last = std::min(last, std::floor(s.value->sup()));
    }
    if (!(last - first < double(d::kMaxIntegersInReach))) {
      out.push_back({MapBoundary::Kind::tangency, -1, 0});
      continue;
    }
    const auto excluded = d::excluded_value(t, n, label);
    for (double m = first; m <= last; m += 1.0)
      if (!excluded || static_cast<std::int64_t>(m) != *excluded)
        out.push_back({MapBoundary::Kind::tangency, label, static_cast<std::int64_t>(m)});
  }
  return out;
}

inline std::optional<TwistBox> boundary_point_on(const MapBoundary& b, const TwistBox& seg, const Ratio& n) {
  namespace d = boundary_enclosure_detail;
  if (b.kind == MapBoundary::Kind::tangency) {  // continuity along the whole segment first
    if (b.label < 0 || !d::stationary_value(d::box_trig(seg), n, b.label).exists) return std::nullopt;
  }
  const bool vertical = seg.a2_lo == seg.a2_hi;
  auto at = [&](double s) { return vertical ? d::sign_at(b, seg.a2_lo, s, n) : d::sign_at(b, s, seg.a3_lo, n); };
  double lo = vertical ? seg.a3_lo : seg.a2_lo, hi = vertical ? seg.a3_hi : seg.a2_hi;
  const int s_lo = at(lo), s_hi = at(hi);
  if (s_lo == 0 || s_hi == 0 || s_lo == s_hi) return std::nullopt;
  for (int step = 0; step < 60; ++step) {
    const double mid = lo + 0.5 * (hi - lo);
    if (!(mid > lo && mid < hi)) break;
    const int s_mid = at(mid);
    if (s_mid == 0) break;
    (s_mid == s_lo ? lo : hi) = mid;
  }
  return vertical ? TwistBox{seg.a2_lo, seg.a2_lo, lo, hi} : TwistBox{lo, hi, seg.a3_lo, seg.a3_lo};
}

}  // namespace sphtroch
