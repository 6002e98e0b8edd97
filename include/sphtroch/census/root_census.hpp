// sphtroch/census/root_census.hpp — the node census by one-dimensional root counting, independent
// of any polyline sampling. Used to cross-check the polyline census (node_census.hpp).
//
//   sphtroch::RootCensus c = sphtroch::root_census(train);
//   c.nodes;            // every node point with its branches (node.hpp)
//   c.roots;            // roots of g in (0, pi), each standing for |p| branch pairs
//
// Derivation (ours; the report treats n = 1, 2 only).
//   Write P(t) = Rz(t) C(b) with C(b) = Rx(a2) Rz(b) Rx(a3) z, b = theta3 = n t + theta_p (Eq. 3, 4).
//   C is the circle of angular radius a3 about the planet axis, fixed in the carrier frame;
//   C(b) = (sa3 sin b, -(sa3 ca2 cos b + ca3 sa2), ca2 ca3 - sa2 sa3 cos b).
//   A node is P(t1) = P(t2), t1 != t2 (mod 2 pi q), with planet angles b1, b2.
//   (1) Rotation about Z1 keeps z, so cos b1 = cos b2: b2 = b1 or b2 = -b1 (mod 2 pi).
//       b2 = b1 forces t2 - t1 = 2 pi k with n k integer, i.e. t1 = t2 mod 2 pi q — unless C(b1)
//       is on the Z1 axis: a pole node (below). So b2 = -b1 =: -b.
//   (2) C(-b) = M C(b), M the mirror x -> -x. P(t1) = P(t2) reads C(b) = Rz(d) M C(b) with
//       d = t2 - t1; Rz(d) M is the mirror in the vertical plane at azimuth pi/2 + d/2, so
//       az(C(b)) = pi/2 + d/2 (mod pi):   d = 2 az(b) - pi + 2 pi j,   j = 0 .. q-1.
//   (3) The planet angles must match: b2 - b1 = n d (mod 2 pi): -2b = n (2 az - pi + 2 pi j).
//       Multiplying by q / (2 pi):    g(b) + p j = 0 (mod q),
//          g(b) = [ p (2 az(b) - pi) + 2 q b ] / (2 pi).
//       Since gcd(p, q) = 1, a j exists iff g(b) is an INTEGER m; then j = -m p^-1 (mod q).
//   So non-pole nodes <-> b in (0, pi) with g(b) integer (b and -b give the same pair; b = 0, pi
//   are the trivial roots t1 = t2, where g is an integer: g(0) in {-p, 0}, g(pi) in {q, q-p}).
//   On (0, pi) the x component sa3 sin b is > 0, so az = atan2(y, x) is continuous there, and
//       g'(b) = [ p (sa3^2 ca2 + sa3 ca3 sa2 cos b) / (1 - z^2) + q ] / pi,
//   so g'(b) = 0 is a QUADRATIC in c = cos b:
//       -q sa2^2 sa3^2 c^2 + sa2 sa3 ca3 (2 q ca2 + p) c + q (sa2^2 + ca2^2 sa3^2) + p sa3^2 ca2 = 0.
//   Hence g has at most 2 stationary points in (0, pi) and at most 3 monotone pieces: the number
//   of roots is the number of integers strictly inside the range of each piece — a count, not a
//   search. g'(pi) = 0 exactly when a3 = a_p, g'(0) = 0 exactly when a3 = pi - a_p (the cusps).
//   Each root b gives |p| pairs: t1 = (b - theta_p + 2 pi k) q / p, k = 0..|p|-1, t2 = t1 + d;
//   they are the images of one node under the curve's |p|-fold symmetry t -> t + 2 pi q / p,
//   which turns the curve by 2 pi q / p about Z1. The phase theta_p does not enter g (Eq. 8).
//   A stationary value of g equal to an integer is a double root: two branches that touch (a
//   tangency node).
//   Pole nodes: C passes through the north pole iff a3 = a2 (at b = pi), the south pole iff
//   a3 = pi - a2 (at b = 0). The curve then passes the pole |p| times per period (branches
//   t = (b_pole - theta_p + 2 pi k) q / p); their velocities are turned by 2 pi q k / p about Z1,
//   so branches k, l are tangent iff 2 q (k - l) / p is an integer (a turn by pi maps a curve
//   germ to its point reflection: same tangent, and the difference is even: they touch), and
//   cross otherwise. A pole is a node iff |p| >= 2.
//
// Numbers: g is evaluated in long double; near the ends b = 0, pi (where the near-cusp loops
// live) g is formed relative to the exact end value, from the signed angle between the
// horizontal projections, so that g(b) - g(end) keeps its relative accuracy. Error bound on g:
// kRootCensusErrorFactor * LDBL_EPSILON * (|p| + q) (a few ulp per operation, about 20
// operations, each scaled by at most |p| + q); values of g closer than that to an integer are
// undecidable and reported as such (a near-cusp loop below resolution, or a tangency).
#pragma once

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/map/closed_form_boundaries.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/parameters.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/census/node_assembly.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace sphtroch {

/// Multiplies LDBL_EPSILON * (|p| + q) in the error bound of g (see header).
constexpr long double kRootCensusErrorFactor = 64.0L;
/// A stationary point of g closer than this to b = 0 or pi, with g there equal to the end's
/// integer, belongs to a near-cusp loop (its parameter half-length grows like sqrt(|a3 - a_p|)).
constexpr double kCuspNeighbourhood = 1e-2;

struct RootCensusSettings {
  /// |g - m| at a stationary point below which it is a tangency. literal mode: the error bound.
  double tangency_tolerance = kTangencyTolerance;
};

/// One root of g on (0, pi).
struct HalfTurnRoot {
  double beta = 0.0;       // planet angle b of the first branch, radians in (0, pi)
  long double beta_precise = 0.0L;  // the same root as solved, in long double
  std::int64_t value = 0;  // the integer g(b)
  NodeKind kind = NodeKind::crossing;
  double margin = 0.0;     // tangency: |g - m| at the stationary point; crossing: |g'|*pi
};

struct RootCensus {
  std::vector<HalfTurnRoot> roots;   // roots of g in (0, pi), ascending
  std::vector<double> stationary;    // stationary points of g in (0, pi)
  std::vector<BranchPair> pairs;     // every unordered branch pair, incl. pole pairs
  std::vector<Node> nodes;           // pairs grouped into node points
  bool north_pole_node = false;      // a3 = a2 exactly (as evaluated) and |p| >= 2
  bool south_pole_node = false;      // a3 = pi - a2 exactly and |p| >= 2
  bool cusp_within_resolution = false;  // a near-cusp loop too small to decide (see notes)
  double error_bound = 0.0;          // bound on the evaluation error of g
  std::size_t evaluations = 0;       // evaluations of g or g'
  std::vector<std::string> notes;
};

namespace detail {

/// g(b) and g'(b) on (0, pi) for one gear train (see header), in long double.
class HalfTurnFunction {
 public:
  using Real = long double;
  explicit HalfTurnFunction(const GearTrain& train) {
    const auto t = train.trig<Real>();
    sa2_ = t.sin_a2;
    ca2_ = t.cos_a2;
    sa3_ = t.sin_a3;
    ca3_ = t.cos_a3;
    p_ = static_cast<Real>(train.ratio().p());
    q_ = static_cast<Real>(train.ratio().q());
    y0_ = -(sa3_ * ca2_ + ca3_ * sa2_);  // y of C(0)  = -sin(a2 + a3)
    ypi_ = sa3_ * ca2_ - ca3_ * sa2_;    // y of C(pi) =  sin(a3 - a2)
  }

  static Real pi() { return Constants<Real>::pi(); }
  Real y_at_0() const { return y0_; }
  Real y_at_pi() const { return ypi_; }
  /// Integer values of g at the ends (trivial roots), valid when the end is not a pole.
  Real g_at_0() const { return y0_ < 0 ? -p_ : Real(0); }
  Real g_at_pi() const { return ypi_ > 0 ? q_ : q_ - p_; }
  /// Limits of g at the ends when they are poles: C(b) approaches the pole tangentially to the
  /// x axis (x ~ sa3 |b - end|, y ~ O(|b - end|^2)), so az -> 0 and g -> -p/2 or q - p/2.
  Real g_limit_at_0() const { return y0_ == 0 ? -p_ / 2 : g_at_0(); }
  Real g_limit_at_pi() const { return ypi_ == 0 ? q_ - p_ / 2 : g_at_pi(); }

  /// Horizontal projection (x, y) of C(b).
  void horizontal(Real b, Real& x, Real& y) const {
    x = sa3_ * std::sin(b);
    y = -(sa3_ * ca2_ * std::cos(b) + ca3_ * sa2_);
  }

  Real g(Real b) const {
    ++evaluations;
    Real x, y;
    horizontal(b, x, y);
    const bool near_zero = b <= pi() / 2;
    const Real y_end = near_zero ? y0_ : ypi_;
    if (y_end == 0) {  // the end is a pole: no exact end value, evaluate directly
      return (p_ * (2 * std::atan2(y, x) - pi()) + 2 * q_ * b) / (2 * pi());
    }
    // Signed angle from the end's projection (0, y_end) to (x, y).
    const Real cross = -y_end * x;  // (0, ye) x (x, y) = 0*y - ye*x
    const Real dot = y_end * y;
    const Real daz = std::atan2(cross, dot);
    const Real end = near_zero ? Real(0) : pi();
    const Real g_end = near_zero ? g_at_0() : g_at_pi();
    return g_end + (2 * p_ * daz + 2 * q_ * (b - end)) / (2 * pi());
  }

  Real dg(Real b) const {
    ++evaluations;
    const Real c = std::cos(b);
    Real x, y;
    horizontal(b, x, y);
    const Real rho2 = x * x + y * y;
    return (p_ * (sa3_ * sa3_ * ca2_ + sa3_ * ca3_ * sa2_ * c) / rho2 + q_) / pi();
  }

  /// Stationary points of g in (0, pi), ascending (roots of the quadratic in cos b).
  std::vector<Real> stationary_points() const {
    const Real A = -q_ * sa2_ * sa2_ * sa3_ * sa3_;
    const Real B = sa2_ * sa3_ * ca3_ * (2 * q_ * ca2_ + p_);
    const Real C = q_ * (sa2_ * sa2_ + ca2_ * ca2_ * sa3_ * sa3_) + p_ * sa3_ * sa3_ * ca2_;
    std::vector<Real> cs;
    const Real disc = B * B - 4 * A * C;
    if (disc >= 0) {
      const Real s = std::sqrt(disc);
      const Real r1 = (-B - (B >= 0 ? s : -s)) / (2 * A);  // A < 0, never 0
      cs.push_back(r1);
      if (r1 != 0) cs.push_back(C / (A * r1));
      else cs.push_back(-B / A);
    }
    std::vector<Real> bs;
    for (Real c : cs)
      if (c > -1 && c < 1) bs.push_back(std::acos(c));
    std::sort(bs.begin(), bs.end());
    bs.erase(std::unique(bs.begin(), bs.end()), bs.end());
    return bs;
  }

  /// The root of g(b) = m on [lo, hi] where g - m changes sign (monotone piece).
  Real solve(Real lo, Real hi, Real m) const {
    Real flo = g(lo) - m;
    for (int it = 0; it < 200 && hi - lo > 4 * LDBL_EPSILON * std::max<Real>(1, hi); ++it) {
      const Real mid = (lo + hi) / 2;
      // Newton from the midpoint when it stays inside the bracket, else bisection.
      const Real fm = g(mid) - m;
      if (fm == 0) return mid;
      if ((fm < 0) == (flo < 0)) {
        lo = mid;
        flo = fm;
      } else {
        hi = mid;
      }
      const Real d = dg(mid);
      if (d != 0) {
        const Real x = mid - fm / d;
        if (x > lo && x < hi) {
          const Real fx = g(x) - m;
          if (fx == 0) return x;
          if ((fx < 0) == (flo < 0)) {
            lo = x;
            flo = fx;
          } else {
            hi = x;
          }
        }
      }
    }
    return (lo + hi) / 2;
  }

  Real p() const { return p_; }
  Real q() const { return q_; }
  /// C(b) in carrier coordinates.
  Vector3<Real> circle_point(Real b) const {
    return Vector3<Real>(sa3_ * std::sin(b), -(sa3_ * ca2_ * std::cos(b) + ca3_ * sa2_),
                         ca2_ * ca3_ - sa2_ * sa3_ * std::cos(b));
  }

  mutable std::size_t evaluations = 0;

 private:
  Real sa2_, ca2_, sa3_, ca3_, p_, q_, y0_, ypi_;
};

inline std::int64_t mod_inverse(std::int64_t a, std::int64_t m) {
  // Extended Euclid; REQUIRES gcd(a, m) = 1, m >= 1.
  std::int64_t g = m, x = 0, x1 = 1, a1 = ((a % m) + m) % m;
  while (a1 != 0) {
    const std::int64_t k = g / a1;
    std::int64_t t = g - k * a1;
    g = a1;
    a1 = t;
    t = x - k * x1;
    x = x1;
    x1 = t;
  }
  return ((x % m) + m) % m;
}

}  // namespace detail

/// Counts and locates every node of the train's curve by root counting (see header).
/// The train is analysed as given: snap it to its boundaries first (boundary_snap.hpp) to get
/// the report's boundary cases; pass settings.tangency_tolerance = 0 for the literal curve.
inline RootCensus root_census(const GearTrain& train, const RootCensusSettings& settings = {}) {
  check_census_cost(train.ratio());  // InvalidInput up front instead of hours or gigabytes
  using Real = long double;
  const detail::HalfTurnFunction f(train);
  const TracerCurve<double> curve(train);
  const double period = train.period();
  const double phase = train.phase();
  const std::int64_t p = train.ratio().p(), q = train.ratio().q();
  const std::int64_t abs_p = p < 0 ? -p : p;
  const Real pi = Constants<Real>::pi();

  RootCensus out;
  out.error_bound = static_cast<double>(kRootCensusErrorFactor * LDBL_EPSILON * (abs_p + q));
  const Real err = out.error_bound;
  const Real tangency_tol = std::max<Real>(settings.tangency_tolerance, err);
  // Within kCuspResolution of a pitch cone a near-cusp loop is not resolved (pitch_cone.hpp).
  const ConeMargins cones = cone_margins(train);

  // Breakpoints: 0, stationary points, pi; decide each stationary point first.
  const std::vector<Real> stationary = f.stationary_points();
  const bool pole0 = f.y_at_0() == 0, pole_pi = f.y_at_pi() == 0;
  std::vector<Real> breaks{0};
  std::vector<Real> values{f.g_limit_at_0()};
  std::vector<bool> tangency_at;  // per interior break
  for (Real b : stationary) {
    out.stationary.push_back(static_cast<double>(b));
    const Real gb = f.g(b);
    const Real m = std::nearbyint(gb);
    const Real gap = std::abs(gb - m);
    const bool near0 = b < kCuspNeighbourhood && !pole0 && m == f.g_at_0();
    const bool near_pi = pi - b < kCuspNeighbourhood && !pole_pi && m == f.g_at_pi();
    const bool unresolved = gap <= err || (near0 && cones.on_mirror_cone()) || (near_pi && cones.on_pitch_cone());
    if ((near0 || near_pi) && unresolved) {
      // A near-cusp loop whose size is below what g can resolve: merge into the end (cusp).
      out.cusp_within_resolution = true;
      out.notes.push_back("near-cusp loop at b = " + std::string(near0 ? "0" : "pi") +
                          " below resolution (|g - m| = " + detail::to_text(static_cast<double>(gap)) +
                          " <= error bound " + detail::to_text(out.error_bound) + "): reported as a cusp within resolution");
      continue;
    }
    breaks.push_back(b);
    values.push_back(gb);
    tangency_at.push_back(!(near0 || near_pi) && gap <= tangency_tol);
  }
  breaks.push_back(pi);
  values.push_back(f.g_limit_at_pi());

  // Roots: integers strictly inside each monotone piece, plus tangencies at stationary points.
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const Real g_lo = values[i], g_hi = values[i + 1];
    const Real lo_v = std::min(g_lo, g_hi), hi_v = std::max(g_lo, g_hi);
    // Integers m with lo_v < m < hi_v, excluding those claimed by a tangency at either end.
    const bool tan_lo = i > 0 && tangency_at[i - 1];
    const bool tan_hi = i + 1 < breaks.size() - 1 && tangency_at[i];
    for (Real m = std::floor(lo_v) + 1; m < hi_v; m += 1) {
      if (tan_lo && std::nearbyint(g_lo) == m) continue;
      if (tan_hi && std::nearbyint(g_hi) == m) continue;
      HalfTurnRoot r;
      r.beta_precise = f.solve(breaks[i], breaks[i + 1], m);
      r.beta = static_cast<double>(r.beta_precise);
      r.value = static_cast<std::int64_t>(m);
      r.kind = NodeKind::crossing;
      r.margin = static_cast<double>(std::abs(f.dg(r.beta)) * pi);
      out.roots.push_back(r);
    }
    if (tan_hi) {
      HalfTurnRoot r;
      r.beta_precise = breaks[i + 1];
      r.beta = static_cast<double>(r.beta_precise);
      r.value = static_cast<std::int64_t>(std::nearbyint(g_hi));
      r.kind = NodeKind::tangency;
      r.margin = static_cast<double>(std::abs(g_hi - std::nearbyint(g_hi)));
      out.roots.push_back(r);
    }
  }
  std::sort(out.roots.begin(), out.roots.end(), [](const auto& a, const auto& b) { return a.beta < b.beta; });

  // Branch pairs of each root (|p| rotated copies).
  const std::int64_t p_inv = q == 1 ? 0 : detail::mod_inverse(((p % q) + q) % q, q);
  const Real two_pi = 2 * pi;
  for (const auto& r : out.roots) {
    const Real b = r.beta_precise;
    const Vector3<Real> y = f.circle_point(b);
    const std::int64_t j = q == 1 ? 0 : ((-(r.value % q) * p_inv) % q + q) % q;
    // d = 2 az(b) - pi (+ 2 pi j). At a crossing root g(b) = m, so 2 az - pi = (2 pi m - 2 q b) / p
    // exactly: this form carries the error of b with the factor 2q/p only, whereas az itself
    // is steep where C(b) passes close to a pole (daz/db ~ 1/distance: a 1e-8 miss of the pole
    // would turn the last bit of b into a 1e-8 error of the second branch's parameter).
    const Real two_az_minus_pi =
        r.kind == NodeKind::crossing
            ? (two_pi * static_cast<Real>(r.value) - 2 * static_cast<Real>(q) * b) / static_cast<Real>(p)
            : 2 * std::atan2(y.y(), y.x()) - pi;
    const Real d = two_az_minus_pi + two_pi * static_cast<Real>(j);
    for (std::int64_t k = 0; k < abs_p; ++k) {
      const Real t1 = theta2_at_planet_angle(train.ratio(), static_cast<Real>(phase), b, k);
      BranchPair bp;
      bp.t1 = reduce_to_period(static_cast<double>(t1), period);
      bp.t2 = reduce_to_period(static_cast<double>(t1 + d), period);
      const Real ct = std::cos(t1), st = std::sin(t1);
      bp.position = Vector3d(static_cast<double>(ct * y.x() - st * y.y()), static_cast<double>(st * y.x() + ct * y.y()),
                             static_cast<double>(y.z()));
      bp.kind = r.kind;
      if (bp.t2 < bp.t1) std::swap(bp.t1, bp.t2);
      out.pairs.push_back(bp);
    }
  }

  // Pole nodes.
  auto add_pole = [&](Real b_pole, double z) {
    std::vector<double> ts;
    for (std::int64_t k = 0; k < abs_p; ++k)
      ts.push_back(reduce_to_period(static_cast<double>(theta2_at_planet_angle(train.ratio(), static_cast<Real>(phase), b_pole, k)), period));
    for (std::int64_t k = 0; k < abs_p; ++k)
      for (std::int64_t l = k + 1; l < abs_p; ++l) {
        BranchPair bp;
        bp.t1 = std::min(ts[k], ts[l]);
        bp.t2 = std::max(ts[k], ts[l]);
        bp.position = Vector3d(0, 0, z);
        bp.kind = (2 * q * (l - k)) % abs_p == 0 ? NodeKind::tangency : NodeKind::crossing;
        out.pairs.push_back(bp);
      }
  };
  if (abs_p >= 2 && pole_pi) {
    out.north_pole_node = true;
    add_pole(pi, 1.0);
  }
  if (abs_p >= 2 && pole0) {
    out.south_pole_node = true;
    add_pole(0, -1.0);
  }
  out.nodes = assemble_nodes(out.pairs, curve);
  out.evaluations = f.evaluations;
  return out;
}

}  // namespace sphtroch
