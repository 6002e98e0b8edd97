// sphtroch/census/root_census.hpp — the node census by one-dimensional root counting, independent
// of any polyline sampling: the integer values of the root function g(b) (map/root_function.hpp).
// Used to certify the polyline census (exact/polyline_census.hpp, exact/certified_census.hpp).
//
//   sphtroch::RootCensus c = sphtroch::root_census(train);
//   c.nodes;            // every node point with its branches (node.hpp)
//   c.roots;            // roots of g in (0, pi), each standing for |p| branch pairs (NodeRoot)
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
#include "sphtroch/map/root_function.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/parameters.hpp"
#include "sphtroch/core/reading.hpp"
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

/// The root census's settings for a reading (core/reading.hpp), as classify and the explorer run it.
inline RootCensusSettings root_census_settings(const Reading& reading) {
  RootCensusSettings rs;
  rs.tangency_tolerance = reading.tangency();
  return rs;
}

/// One root of g on (0, pi).
struct NodeRoot {
  double beta = 0.0;       // planet angle b of the first branch, radians in (0, pi)
  long double beta_precise = 0.0L;  // the same root as solved, in long double
  std::int64_t value = 0;  // the integer g(b)
  NodeKind kind = NodeKind::crossing;
  double margin = 0.0;     // tangency: |g - m| at the stationary point; crossing: |g'|*pi
};

struct RootCensus {
  std::vector<NodeRoot> roots;       // roots of g in (0, pi), ascending
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

namespace root_census_detail {

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

using Real = long double;

/// g on (0, pi) cut into monotone pieces: breaks 0, the stationary points kept, pi; g there; and
/// for each interior break whether it is a tangency (a double root).
struct MonotonePieces {
  std::vector<Real> breaks;
  std::vector<Real> values;
  std::vector<bool> tangency_at;
};

/// Stage 1: decides every stationary point of g. One whose value is an end's integer within
/// kCuspNeighbourhood of that end and below resolution (or on a cusp cone) is a near-cusp loop
/// merged into the end (out.cusp_within_resolution, a note); the others become breaks, tangencies
/// when |g - m| <= tangency_tol.
inline MonotonePieces monotone_pieces(const RootFunction<Real>& f, const GearTrain& train, Real tangency_tol,
                                      RootCensus& out) {
  const Real pi = Constants<Real>::pi();
  const Real err = out.error_bound;
  // Within kCuspResolution of a pitch cone a near-cusp loop is not resolved (pitch_cone.hpp).
  const ConeMargins cones = cone_margins(train);
  const bool pole0 = f.y_at_0() == 0, pole_pi = f.y_at_pi() == 0;
  MonotonePieces pieces{{0}, {f.g_limit_at_0()}, {}};
  for (Real b : f.stationary_points()) {
    out.stationary.push_back(static_cast<double>(b));
    const Real gb = f.g(b);
    const Real m = std::nearbyint(gb);
    const Real gap = std::abs(gb - m);
    const bool near0 = b < kCuspNeighbourhood && !pole0 && m == f.g_at_0();
    const bool near_pi = pi - b < kCuspNeighbourhood && !pole_pi && m == f.g_at_pi();
    const bool unresolved = gap <= err || (near0 && cones.on_mirror_cone()) || (near_pi && cones.on_pitch_cone());
    if ((near0 || near_pi) && unresolved) {
      out.cusp_within_resolution = true;
      out.notes.push_back("near-cusp loop at b = " + std::string(near0 ? "0" : "pi") +
                          " below resolution (|g - m| = " + number_text(static_cast<double>(gap)) +
                          " <= error bound " + number_text(out.error_bound) + "): reported as a cusp within resolution");
      continue;
    }
    pieces.breaks.push_back(b);
    pieces.values.push_back(gb);
    pieces.tangency_at.push_back(!(near0 || near_pi) && gap <= tangency_tol);
  }
  pieces.breaks.push_back(pi);
  pieces.values.push_back(f.g_limit_at_pi());
  return pieces;
}

/// A crossing root: the b in [lo, hi] with g(b) = m.
inline NodeRoot crossing_root(const RootFunction<Real>& f, Real lo, Real hi, Real m) {
  NodeRoot r;
  r.beta_precise = f.solve(lo, hi, m);
  r.beta = static_cast<double>(r.beta_precise);
  r.value = static_cast<std::int64_t>(m);
  r.kind = NodeKind::crossing;
  r.margin = static_cast<double>(std::abs(f.dg_db(r.beta)) * Constants<Real>::pi());
  return r;
}

/// A tangency root: the stationary point b with g(b) = gb within the tangency tolerance.
inline NodeRoot tangency_root(Real b, Real gb) {
  NodeRoot r;
  r.beta_precise = b;
  r.beta = static_cast<double>(r.beta_precise);
  r.value = static_cast<std::int64_t>(std::nearbyint(gb));
  r.kind = NodeKind::tangency;
  r.margin = static_cast<double>(std::abs(gb - std::nearbyint(gb)));
  return r;
}

/// Stage 2: the roots, ascending in b: the integers strictly inside each monotone piece (a
/// count, then one solve each), plus the tangencies at stationary points.
inline void collect_roots(const RootFunction<Real>& f, const MonotonePieces& pieces, RootCensus& out) {
  const auto& breaks = pieces.breaks;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const Real g_lo = pieces.values[i], g_hi = pieces.values[i + 1];
    const Real lo_v = std::min(g_lo, g_hi), hi_v = std::max(g_lo, g_hi);
    // Integers m with lo_v < m < hi_v, excluding those claimed by a tangency at either end.
    const bool tan_lo = i > 0 && pieces.tangency_at[i - 1];
    const bool tan_hi = i + 1 < breaks.size() - 1 && pieces.tangency_at[i];
    for (Real m = std::floor(lo_v) + 1; m < hi_v; m += 1) {
      if (tan_lo && std::nearbyint(g_lo) == m) continue;
      if (tan_hi && std::nearbyint(g_hi) == m) continue;
      out.roots.push_back(crossing_root(f, breaks[i], breaks[i + 1], m));
    }
    if (tan_hi) out.roots.push_back(tangency_root(breaks[i + 1], g_hi));
  }
  std::sort(out.roots.begin(), out.roots.end(), [](const auto& a, const auto& b) { return a.beta < b.beta; });
}

/// Stage 3: the |p| branch pairs of each root (the rotated copies of one node, see header).
inline void add_root_pairs(const GearTrain& train, const RootFunction<Real>& f, RootCensus& out) {
  const std::int64_t p = train.ratio().p(), q = train.ratio().q();
  const std::int64_t abs_p = p < 0 ? -p : p;
  const Real pi = Constants<Real>::pi(), two_pi = 2 * pi;
  const double period = train.period();
  const std::int64_t p_inv = q == 1 ? 0 : mod_inverse(((p % q) + q) % q, q);
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
      const Real t1 = theta2_at_planet_angle(train.ratio(), static_cast<Real>(train.phase()), b, k);
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
}

/// Stage 4: the branch pairs through a pole the circle C passes (b_pole = 0 or pi, z = -1 or 1):
/// branches k, l touch iff 2 q (l - k) / p is an integer, else they cross (see header).
inline void add_pole_pairs(const GearTrain& train, Real b_pole, double z, RootCensus& out) {
  const std::int64_t p = train.ratio().p(), q = train.ratio().q();
  const std::int64_t abs_p = p < 0 ? -p : p;
  const double period = train.period();
  std::vector<double> ts;
  for (std::int64_t k = 0; k < abs_p; ++k)
    ts.push_back(reduce_to_period(
        static_cast<double>(theta2_at_planet_angle(train.ratio(), static_cast<Real>(train.phase()), b_pole, k)), period));
  for (std::int64_t k = 0; k < abs_p; ++k)
    for (std::int64_t l = k + 1; l < abs_p; ++l) {
      BranchPair bp;
      bp.t1 = std::min(ts[k], ts[l]);
      bp.t2 = std::max(ts[k], ts[l]);
      bp.position = Vector3d(0, 0, z);
      bp.kind = (2 * q * (l - k)) % abs_p == 0 ? NodeKind::tangency : NodeKind::crossing;
      out.pairs.push_back(bp);
    }
}

}  // namespace root_census_detail

/// Counts and locates every node of the train's curve by root counting (see header).
/// The train is analysed as given: snap it to its boundaries first (boundary_snap.hpp) to get
/// the report's boundary cases; pass settings.tangency_tolerance = 0 for the literal curve.
inline RootCensus root_census(const GearTrain& train, const RootCensusSettings& settings = {}) {
  using namespace root_census_detail;
  check_census_cost(train.ratio());  // InvalidInput up front instead of hours or gigabytes
  const RootFunction<Real> f(train);
  const std::int64_t abs_p = train.ratio().abs_p(), q = train.ratio().q();
  RootCensus out;
  out.error_bound = static_cast<double>(kRootCensusErrorFactor * LDBL_EPSILON * (abs_p + q));
  const Real tangency_tol = std::max<Real>(settings.tangency_tolerance, out.error_bound);
  collect_roots(f, monotone_pieces(f, train, tangency_tol, out), out);
  add_root_pairs(train, f, out);
  if (abs_p >= 2 && f.y_at_pi() == 0) {
    out.north_pole_node = true;
    add_pole_pairs(train, Constants<Real>::pi(), 1.0, out);
  }
  if (abs_p >= 2 && f.y_at_0() == 0) {
    out.south_pole_node = true;
    add_pole_pairs(train, 0, -1.0, out);
  }
  out.nodes = assemble_nodes(out.pairs, TracerCurve<double>(train));
  out.evaluations = f.evaluations;
  return out;
}

}  // namespace sphtroch
