// sphtroch/synthesis/path_fit.hpp — the inverse question for an untimed path: which trains of ratio
// n draw a curve through (near) these points, optionally with a wanted node and/or cusp count?
// Ranked candidates, each with its distance to the points and its margin to the nearest boundary
// of the (a2, a3) map. Eigen only: the node count a candidate is kept to is the root count
// (map/root_function.hpp); exact/path_fit_output.hpp confirms every candidate by classify().
//
//   const sphtroch::GearTrain hidden(1.1, 0.9, sphtroch::Ratio(2), 0.4);
//   const auto points = sphtroch::sample_period(sphtroch::TracerCurve<double>(hidden), 200).points;
//   sphtroch::FitOptions o;  o.nodes = 4;                       // or o.cusps = 2, or both, or neither
//   sphtroch::PathFit f = sphtroch::fit_path(points, sphtroch::Ratio(2), o);
//   f.candidates[0].train;  f.candidates[0].rms;  f.candidates[0].margin;   // best first
//   f.reason;               // why there is none, e.g. "n = 2: node points come in sets of |p| = 2 ..."
//
// What is minimised: the spherical distances d_i (radians) of the points to the curve, each point
// to its nearest curve point (path_distance.hpp), sum d_i^2. The point order is not used.
// Unknowns: a2, a3, phase (free); a2, phase on a pitch cone (cusps wanted: a3 = a_p(a2) or pi -
// a_p(a2), exactly, GearTrain::on_cone); the phase alone where both cones meet (a2 = acos(-n),
// a3 = pi/2, |n| < 1: 2|p| cusps).
//  1. Screening: every shape of a grid (kFitGrid^2 for a2, a3; kFitGrid^2 a2 on a cone), and the
//     shapes the points' z range gives (z_max = cos(a2 - a3), z_min = cos(a2 + a3) for a full
//     period), is scored on up to kFitScreenPoints points with the latitude estimate
//     (path_distance.hpp): each point votes for the turn about Z that puts it on a crossing of its
//     latitude; the best turns are scored by the estimated distances. The kFitSeeds best distinct
//     shapes are refined.
//  2. Refinement: Levenberg–Marquardt with the feet eliminated (variable projection: each point's
//     theta2 is its nearest curve point's, the Jacobian is dP/d(parameters) with the tangent
//     component removed); the feet are found again globally after convergence. The reported
//     distances (rms, max_deviation, and the max_deviation filter) use certified feet
//     (nearest_param_certified: a local foot of a far point can be another branch's).
//  3. Wanted node count K: a step is taken only to shapes whose root count is K (halved until it
//     is), so the fit never leaves the cells of the map with K nodes; seeds come from those cells
//     only (grid shapes with K nodes and the midpoint of every a3 interval with K nodes of the
//     boundary set at each grid a2). A constrained candidate is moved to kFitBoundaryClearance in
//     a3 from the boundary that bounds it (the true census there is unambiguous).
//  4. A count no cell allows is answered with no candidate and the reason: node points come in sets
//     of |p| (the |p|-fold symmetry); the counts the boundary set shows at the grid a2 (a cell
//     narrower than one grid step in a2 that lies between grid columns is not seen); cusps are 0,
//     |p| on a pitch cone, or 2|p| where both cones meet (|n| < 1).
//  5. A node at a given point N (FitOptions::node_at): the squared distances of N to the curve on
//     its two nearest branches (two_branch_feet) join the sum, weighted kFitNodeWeights[k] times
//     the point count in turn, so a self-crossing is pulled onto N; a candidate whose two branches
//     pass farther than node_tolerance from N is dropped (the census confirms it, exact layer).
//  6. A minimum margin D (FitOptions::min_margin, free family): a step is taken only to shapes
//     whose D-square (a2 +- D, a3 +- D, inside the trains' range) keeps, at its 8 edge points
//     (corners and edge midpoints), the centre's root count and the centre's sides of the pitch
//     cones and (|p| >= 2) the pole lines — the pole lines exactly, as straight lines at 45 deg are
//     first met at a corner; so the fit stays inside its cell shrunk by D, up to a tangency locus
//     that bulges into the square between those points. The exact layer keeps only candidates
//     whose certified margin (topology_margin.hpp) is at least D and whose D-square lies in the
//     range (a design built to +-D, a box `sphtroch tolerance` checks). Cusps (on a pitch cone, margin
//     0) and D > 0 are refused together.
// Margin: the distance in the (a2, a3) plane (radians) to the nearest boundary of the map, to first
// order (map/map_cells.hpp's map_margin). The cone a cusp candidate lies on is not counted.
// Cost: about kFitGrid^2 screenings on <= 120 points, kFitSeeds refinements on
// <= 100 points, one per candidate on <= 2000 points; kFitGrid boundary sets when a node count is wanted.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/map/map_cells.hpp"
#include "sphtroch/synthesis/fit_grid.hpp"
#include "sphtroch/synthesis/path_distance.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace sphtroch {

/// Fewest points fit accepts (three unknowns, plus one).
constexpr std::size_t kMinFitPoints = 4;
/// Most points fit accepts (the cost is linear in them).
constexpr std::size_t kMaxFitPoints = 1000000;
/// Points must be unit vectors to this.
constexpr double kFitUnitTolerance = 1e-6;
/// Shapes refined per ratio (three times as many for paths of few points, where refining is
/// cheap and the screening less sure), and the subsets of points screening and refinement use.
constexpr std::size_t kFitSeeds = 8, kFitFewPoints = 50, kFitScreenPoints = 120, kFitRefinePoints = 100;
/// Points the final polish of a candidate uses (its distances are then measured on all points).
constexpr std::size_t kFitPolishPoints = 2000;
/// a2, a3 of every candidate lie in [kFitMinTwist, pi - kFitMinTwist] (as GearTrain requires for a2).
constexpr double kFitMinTwist = 1e-6;
/// Candidates closer than this in a2, a3 and phase (modulo 2 pi / q), radians, are one design: the
/// better is kept (a flat minimum ends refinements from different seeds a little apart).
constexpr double kFitSameDesign = 1e-3;
/// a3 distance a node-constrained candidate keeps from the events bounding its cell (radians).
constexpr double kFitBoundaryClearance = 1e-7;
/// A node at a given point: weights of its two branch distances, per point of the fit, in turn
/// (the first finds the node, the last holds it to ~1e-6 of the path's residual).
constexpr double kFitNodeWeights[] = {1e2, 1e6};

struct FitOptions {
  std::optional<std::int64_t> nodes;  // wanted node points (crossings and tangencies), or any
  std::optional<std::int64_t> cusps;  // wanted cusps, or any
  std::size_t max_candidates = 5;     // at most this many, best first
  double max_deviation = std::numeric_limits<double>::infinity();  // radians: drop farther candidates
  std::optional<Vector3d> node_at;    // a node wanted at this point (unit vector), or anywhere
  double node_tolerance = 1e-6;       // radians: how near node_at the curve's node must be
  /// Radians: constrained candidates are placed at least this far (in a3) from the boundary that
  /// bounds them, and the exact layer keeps only candidates whose certified margin
  /// (topology_margin.hpp) is at least this (0: no requirement).
  double min_margin = 0.0;
};

/// The largest FitOptions::min_margin (a quarter of the map's side).
constexpr double kMaxFitMinMargin = 0.785;

/// Whether the square [a2 -+ d] x [a3 -+ d] lies in the trains' range [kFitMinTwist, pi -
/// kFitMinTwist]^2: a design built to +-d (and a tolerance box `sphtroch tolerance` can check).
inline bool square_in_range(const GearTrain& train, double d) {
  const double lo = kFitMinTwist, hi = Constants<double>::pi() - kFitMinTwist;
  return train.a2() - d >= lo && train.a2() + d <= hi && train.a3() - d >= lo && train.a3() + d <= hi;
}

struct FitCandidate {
  GearTrain train;               // n, a2, a3, phase in [0, 2 pi / q)
  double rms = 0.0;              // RMS spherical distance of the points to the curve (radians)
  double max_deviation = 0.0;    // largest of those distances (radians)
  double margin = 0.0;           // to the nearest boundary of the map (see header), radians
  std::int64_t root_nodes = 0;   // node points by the root count (classify confirms, exact layer)
  std::vector<double> params;    // theta2 of each point's nearest curve point, in [0, 2 pi q)
  /// With node_at: the larger distance (radians) from node_at to the curve on its two nearest
  /// branches (0 when the curve crosses itself there); exact/path_fit_output.hpp measures the
  /// distance to the census's node instead.
  double node_distance = 0.0;
};

struct PathFit {
  Ratio ratio;
  std::vector<FitCandidate> candidates;  // best (smallest rms) first
  std::string reason;                    // empty when there are candidates
};

/// Ranked candidate trains of ratio n for the points (see header). Throws InvalidInput naming
/// "points" (count, not unit, NaN), "nodes" or "cusps" (negative), or "n" (beyond the census
/// cost bound, cost_bounds.hpp).
inline PathFit fit_path(const std::vector<Vector3d>& points, const Ratio& n, const FitOptions& options = {});

/// Bound on a fit's work: sum over the ratios of points x (2|p| + 5 (|p| + q) + 40) +
/// kFitRatioWork (each candidate's distances are measured on every point: 2|p| latitude
/// crossings and Newton steps, then the certified foot's search over ~4.5 (|p| + q) spans;
/// kFitRatioWork: the screening and refinement on subsampled points, ~0.26 s a ratio). Measured
/// 2026-11-27 on this 2-core machine (one core): ~0.65 us per unit (n = 2 and 100,000 points
/// 3.8 s; --ratios 3,3 and 1,000 / 20,000 / 100,000 points 4.3 / 15 / 65 s), so the bound is ~30 s.
constexpr double kFitRatioWork = 4e5;
constexpr double kMaxFitPointWork = 4.6e7;

/// Work per point of one ratio (see kMaxFitPointWork).
inline double fit_point_work(const Ratio& n) {
  const double p = static_cast<double>(n.abs_p()), q = static_cast<double>(n.q());
  return 2 * p + 5 * (p + q) + 40;
}

/// Refuses (InvalidInput "points") a fit of this many points over these ratios beyond
/// kMaxFitPointWork, before any work.
inline void check_fit_cost(std::size_t points, const std::vector<Ratio>& ratios) {
  double work = 0;
  for (const Ratio& n : ratios) work += static_cast<double>(points) * fit_point_work(n) + kFitRatioWork;
  if (work > kMaxFitPointWork)
    throw InvalidInput("points", std::to_string(points) + " points",
                       "too many for these ratios (sum of points x (2|p| + 5 (|p| + q) + 40) + 4e5 = " + number_text(work) + ")",
                       "sum over the ratios of points x (2|p| + 5 (|p| + q) + 40) + 4e5 <= 4.6e7 (e.g. 772,881 points for "
                       "n = 2, 2,968 for --ratios 7,7)");
}


// =============================================================================================
// Implementation details follow.
// =============================================================================================

namespace path_fit_detail {

constexpr double kPi = Constants<double>::pi();

enum class Family { free, pitch_cone, mirror_cone, both_cones };

/// The parameters x a family varies (shape parameters, then the phase) and what they mean.
struct Parametrisation {
  Family family = Family::free;
  double n = 1.0;
  int dim() const { return family == Family::free ? 3 : family == Family::both_cones ? 1 : 2; }
  double cone(double a2) const { return std::atan2(std::sin(a2), std::cos(a2) + n); }
  /// (a2, a3) of x.
  std::pair<double, double> shape(const Eigen::VectorXd& x) const {
    switch (family) {
      case Family::free: return {x(0), x(1)};
      case Family::pitch_cone: return {x(0), cone(x(0))};
      case Family::mirror_cone: return {x(0), kPi - cone(x(0))};
      case Family::both_cones: return {std::acos(-n), kPi / 2};
    }
    return {x(0), x(1)};
  }
  FitShape fit_shape(const Eigen::VectorXd& x) const {
    const auto [a2, a3] = shape(x);
    return {a2, a3, n, x(dim() - 1)};
  }
  /// d(a2, a3, phase)/dx, 3 x dim.
  Eigen::MatrixXd chain(const Eigen::VectorXd& x) const {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(3, dim());
    m(2, dim() - 1) = 1;
    if (family == Family::free) {
      m(0, 0) = 1;
      m(1, 1) = 1;
    } else if (family != Family::both_cones) {
      const double c2 = std::cos(x(0));
      const double slope = (1 + n * c2) / (1 + 2 * n * c2 + n * n);  // d a_p / d a2
      m(0, 0) = 1;
      m(1, 0) = family == Family::pitch_cone ? slope : -slope;
    }
    return m;
  }
  Eigen::VectorXd make(double a2, double a3, double phase) const {
    Eigen::VectorXd x(dim());
    if (family == Family::free) x << a2, a3, phase;
    else if (family == Family::both_cones) x << phase;
    else x << a2, phase;
    return x;
  }
};

/// Node points at (a2, a3) by the root count; on a pitch cone (family), the count of the side
/// without the near-cusp loop (the smaller).
inline std::int64_t root_nodes(double a2, double a3, const Ratio& n, Family family) {
  if (family == Family::free) return node_count_off_events(a2, a3, n);
  const double d = 1e-7;
  return std::min(node_count_off_events(a2, a3 - d, n), node_count_off_events(a2, a3 + d, n));
}

/// What a candidate must satisfy besides the range of a2, a3.
struct Constraint {
  Ratio n;
  Parametrisation par;
  std::optional<std::int64_t> nodes;
  bool avoid_cones = false;  // cusps = 0 wanted
  std::optional<Vector3d> node_at;
  double clearance = kFitBoundaryClearance;  // radians in a3 from the boundary bounding a candidate
  double min_margin = 0;                     // radians: the D-square that must stay in the cell (free family)
  bool admissible(double a2, double a3) const {
    if (!admissible_point(a2, a3)) return false;
    return !(min_margin > 0 && par.family == Family::free) || square_in_cell(a2, a3);
  }
  /// Whether the min_margin square lies in the trains' range and its 8 edge points see the census
  /// of (a2, a3) (see header, 6).
  bool square_in_cell(double a2, double a3) const {
    const std::int64_t centre = nodes ? *nodes : root_nodes(a2, a3, n, par.family);
    const auto sides = [this](double x, double y) {
      const double ap = par.cone(x);
      return std::array<bool, 4>{y > ap, y > kPi - ap, n.abs_p() >= 2 && y > x, n.abs_p() >= 2 && x + y > kPi};
    };
    const std::array<bool, 4> own = sides(a2, a3);
    // A hair wider than D: beyond the certified bracket's width (max(1e-9, 1e-6 upper)), so that
    // a fit that ends on the wall still passes the exact layer's test lower >= D.
    const double d = min_margin * (1 + 4e-6) + 4e-9;
    for (int i = -1; i <= 1; ++i)
      for (int k = -1; k <= 1; ++k) {
        const double x = a2 + i * d, y = a3 + k * d;
        if (i == 0 && k == 0) continue;
        if (!(x >= kFitMinTwist && x <= kPi - kFitMinTwist && y >= kFitMinTwist && y <= kPi - kFitMinTwist)) return false;
        if (sides(x, y) != own || root_nodes(x, y, n, par.family) != centre) return false;
      }
    return true;
  }
  bool admissible_point(double a2, double a3) const {
    if (!(a2 >= kFitMinTwist && a2 <= kPi - kFitMinTwist && a3 >= kFitMinTwist && a3 <= kPi - kFitMinTwist))
      return false;
    const double ap = par.cone(a2);
    const bool near_cone = std::abs(a3 - ap) < 1e-9 || std::abs(a3 - (kPi - ap)) < 1e-9;
    if (avoid_cones && near_cone) return false;
    // GearTrain refuses a3 on or near the pitch cone where the planet barely turns in space.
    const double nv = par.n, speed = std::sqrt(std::max(0.0, 1 + nv * nv + 2 * nv * std::cos(a2)));
    if (!(speed >= kMinPlanetSpeed) && (par.family != Family::free || std::abs(a3 - ap) < kPitchConeGuard ||
                                        std::abs(a3 - (kPi - ap)) < kPitchConeGuard))
      return false;
    if (!nodes) return true;
    if (par.family == Family::free && (near_cone || std::abs(a3 - a2) < 1e-9 || std::abs(a3 - (kPi - a2)) < 1e-9))
      return false;  // on a closed-form boundary the root count is that of one side
    return root_nodes(a2, a3, n, par.family) == *nodes;
  }
};

// ---- Screening ---------------------------------------------------------------------------

struct Seed {
  double a2 = 0, a3 = 0, phase = 0, score = 0;
};

/// Every k-th point, at most `most` of them.
inline std::vector<Vector3d> subsample(const std::vector<Vector3d>& p, std::size_t most) {
  if (p.size() <= most) return p;
  std::vector<Vector3d> out;
  for (std::size_t k = 0; k < most; ++k) out.push_back(p[k * p.size() / most]);
  return out;
}

/// The best turns of the shape (a2, a3) about Z for the points (see header, step 1), as seeds.
inline void screen_shape(double a2, double a3, const Ratio& ratio, const std::vector<Vector3d>& pts,
                         std::vector<Seed>& out) {
  const double n = ratio.value(), ring = 2 * kPi / static_cast<double>(ratio.abs_p());
  const std::size_t bins = 64;
  const FitShape shape(a2, a3, n, 0.0);
  const double s2 = shape.s2, c2 = shape.c2, s3 = shape.s3;
  const Vector3d omega(0, -n * s2, 1 + n * c2);
  struct Vote {
    double beta, lat, beyond, offset[2], factor[2];
  };
  std::vector<Vote> votes(pts.size());
  std::vector<double> histogram(bins, 0.0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vector3d& P = pts[i];
    const LatitudeMatch m = latitude_match(shape, P.z());
    Vote& v = votes[i];
    v.beta = std::atan2(P.y(), P.x());
    v.lat = std::hypot(P.x(), P.y());
    v.beyond = m.beyond;
    for (int s = 0; s < 2; ++s) {
      const double u = s == 0 ? m.u : -m.u;
      const Vector3d cc = planet_circle_point(shape, u);
      v.offset[s] = u / n + std::atan2(cc.y(), cc.x());
      const double speed = omega.cross(cc).norm(), horizontal = std::hypot(cc.x(), cc.y());
      const double sin_gamma = std::abs(n * s2 * s3 * std::sin(u)) / std::max(horizontal * speed, 1e-300);
      v.factor[s] = std::clamp(sin_gamma, 0.2, 1.0);
      const double turn = std::fmod(std::fmod(v.beta - v.offset[s], ring) + ring, ring);
      histogram[std::min(bins - 1, static_cast<std::size_t>(turn / ring * bins))] += 1;
    }
  }
  auto wrap = [ring](double a) { return a - ring * std::nearbyint(a / ring); };  // into [-ring/2, ring/2]
  auto score = [&](double turn) {
    double sum = 0;
    for (const Vote& v : votes) {
      double best = 0.01;  // cap: 0.1 rad
      for (int s = 0; s < 2; ++s) {
        const double d = wrap(v.beta - turn - v.offset[s]) * v.lat * v.factor[s];
        best = std::min(best, v.beyond * v.beyond + d * d);
      }
      sum += best;
    }
    return sum / static_cast<double>(votes.size());
  };
  std::vector<double> smooth(bins);
  for (std::size_t b = 0; b < bins; ++b)
    smooth[b] = histogram[(b + bins - 1) % bins] + histogram[b] + histogram[(b + 1) % bins];
  std::vector<std::size_t> order(bins);
  for (std::size_t b = 0; b < bins; ++b) order[b] = b;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return smooth[a] > smooth[b]; });
  std::vector<std::size_t> peaks;
  for (std::size_t b : order) {
    if (peaks.size() == 2) break;
    bool apart = true;
    for (std::size_t p : peaks) apart = apart && std::min((b + bins - p) % bins, (p + bins - b) % bins) >= 3;
    if (apart) peaks.push_back(b);
  }
  for (std::size_t b : peaks) {
    const double width = ring / static_cast<double>(bins);
    double best_turn = (static_cast<double>(b) + 0.5) * width, best = score(best_turn);
    for (double step = width; step > width / 16; step /= 2)
      for (double t : {best_turn - step, best_turn + step})
        if (const double sc = score(t); sc < best) {
          best = sc;
          best_turn = t;
        }
    out.push_back({a2, a3, -n * best_turn, best});  // phase f turns the curve by -f/n
  }
}

// ---- Refinement --------------------------------------------------------------------------

struct Refined {
  Eigen::VectorXd x;
  std::vector<double> t;                 // feet
  double cost = 0;                       // sum of squared chords (+ the node's, weighted)
  std::pair<double, double> node_t{};    // with node_at: the feet of its two branches
};

inline double cost_of(const FitShape& s, const std::vector<Vector3d>& pts, const std::vector<double>& t) {
  double c = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) c += (curve_point(s, t[i]) - pts[i]).squaredNorm();
  return c;
}

inline std::vector<double> global_feet(const FitShape& s, const Ratio& n, const std::vector<Vector3d>& pts) {
  const double period = 2 * kPi * static_cast<double>(n.q());
  std::vector<double> t(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) t[i] = nearest_param(s, n.abs_p(), period, pts[i]);
  return t;
}

/// The feet of the reported distances: global_feet's, certified (nearest_param_certified).
inline std::vector<double> certified_feet(const FitShape& s, const Ratio& n, const std::vector<Vector3d>& pts) {
  const double period = 2 * kPi * static_cast<double>(n.q());
  std::vector<double> t = global_feet(s, n, pts);
  for (std::size_t i = 0; i < pts.size(); ++i) t[i] = nearest_param_certified(s, period, pts[i], t[i]);
  return t;
}

inline std::pair<double, double> node_feet(const Constraint& con, const FitShape& s) {
  return two_branch_feet(s, con.n.abs_p(), 2 * kPi * static_cast<double>(con.n.q()), *con.node_at);
}

/// The node's feet followed locally from `from`, or found again when they merge.
inline std::pair<double, double> follow_node_feet(const Constraint& con, const FitShape& s, std::pair<double, double> from) {
  const double a = nearest_param_from(s, *con.node_at, from.first, 4), b = nearest_param_from(s, *con.node_at, from.second, 4);
  if (std::abs(std::remainder(a - b, 2 * kPi * static_cast<double>(con.n.q()))) > 1e-6) return {a, b};
  return node_feet(con, s);
}

inline double node_cost(const Constraint& con, const FitShape& s, std::pair<double, double> t) {
  if (!con.node_at) return 0;
  return (curve_point(s, t.first) - *con.node_at).squaredNorm() + (curve_point(s, t.second) - *con.node_at).squaredNorm();
}

/// Adds the Gauss–Newton terms of the foot t of `target` (weight w) to H and g.
inline void add_foot_terms(const FitShape& s, const Eigen::MatrixXd& chain, double t, const Vector3d& target, double w,
                           Eigen::MatrixXd& H, Eigen::VectorXd& g) {
  const CurveJet j = curve_jet(s, t);
  Eigen::Matrix3d d;
  d << j.d_a2, j.d_a3, j.d_phase;
  Eigen::MatrixXd J = d * chain;
  const double speed = j.d_t.norm();
  if (speed > 0) {
    const Vector3d tangent = j.d_t / speed;
    J -= tangent * (tangent.transpose() * J);
  }
  H += w * J.transpose() * J;
  g += w * J.transpose() * (j.point - target);
}

/// The points a step of refine_with tries, in order: x + step, and with a minimum margin (free
/// family) also the step with a2 or a3 held, so that the fit slides along the wall of its shrunk
/// cell instead of stalling against it.
inline std::vector<Eigen::VectorXd> trials(const Constraint& con, const Eigen::VectorXd& x, const Eigen::VectorXd& step) {
  std::vector<Eigen::VectorXd> out{x + step};
  if (con.min_margin > 0 && con.par.family == Family::free)
    for (int held = 0; held < 2; ++held) {
      Eigen::VectorXd slide = step;
      slide(held) = 0;
      out.push_back(x + slide);
    }
  return out;
}

/// Levenberg–Marquardt with the feet eliminated (see header, step 2), inside the constraint;
/// with node_at, its two branch distances weighted by `node_weight`.
inline Refined refine_with(const Constraint& con, const std::vector<Vector3d>& pts, Eigen::VectorXd x, int max_iterations,
                           double node_weight) {
  const Parametrisation& par = con.par;
  auto total = [&](const FitShape& s, const std::vector<double>& t, std::pair<double, double> nt) {
    return cost_of(s, pts, t) + node_weight * node_cost(con, s, nt);
  };
  Refined r{x, global_feet(par.fit_shape(x), con.n, pts), 0, {}};
  if (con.node_at) r.node_t = node_feet(con, par.fit_shape(x));
  r.cost = total(par.fit_shape(x), r.t, r.node_t);
  for (int round = 0; round < 3; ++round) {
    double mu = 1e-3;
    int stalled = 0;
    for (int it = 0; it < max_iterations && mu < 1e8 && stalled < 2; ++it) {
      const FitShape s = par.fit_shape(r.x);
      const Eigen::MatrixXd chain = par.chain(r.x);
      Eigen::MatrixXd H = Eigen::MatrixXd::Zero(par.dim(), par.dim());
      Eigen::VectorXd g = Eigen::VectorXd::Zero(par.dim());
      for (std::size_t i = 0; i < pts.size(); ++i) add_foot_terms(s, chain, r.t[i], pts[i], 1.0, H, g);
      if (con.node_at)
        for (double t : {r.node_t.first, r.node_t.second}) add_foot_terms(s, chain, t, *con.node_at, node_weight, H, g);
      Eigen::MatrixXd A = H;
      A.diagonal() += mu * H.diagonal() + Eigen::VectorXd::Constant(par.dim(), 1e-15);
      Eigen::VectorXd step = A.ldlt().solve(-g);
      if (!step.allFinite()) break;
      bool moved = false;
      for (int halving = 0; halving < 40 && !moved; ++halving, step /= 2) {
        for (const Eigen::VectorXd& trial : trials(con, r.x, step)) {
          const auto [a2, a3] = par.shape(trial);
          if (!con.admissible(a2, a3)) continue;
          moved = true;
          const FitShape ts = par.fit_shape(trial);
          std::vector<double> t = r.t;
          for (std::size_t i = 0; i < pts.size(); ++i) t[i] = nearest_param_from(ts, pts[i], t[i], 4);
          const auto nt = con.node_at ? follow_node_feet(con, ts, r.node_t) : r.node_t;
          const double c = total(ts, t, nt);
          if (c < r.cost) {
            stalled = r.cost - c <= 1e-12 * r.cost ? stalled + 1 : 0;
            r = {trial, std::move(t), c, nt};
            mu = std::max(mu / 3, 1e-12);
          } else {
            mu *= 4;
          }
          break;
        }
      }
      if (!moved) mu *= 10;
    }
    // Feet may jump to another branch: find them again globally.
    const FitShape s = par.fit_shape(r.x);
    const std::vector<double> t = global_feet(s, con.n, pts);
    const auto nt = con.node_at ? node_feet(con, s) : r.node_t;
    const double c = total(s, t, nt);
    if (!(c < r.cost * (1 - 1e-9))) break;
    r = {r.x, t, c, nt};
  }
  return r;
}

/// refine_with, in turn at each node weight (kFitNodeWeights, per point) when a node is wanted.
inline Refined refine(const Constraint& con, const std::vector<Vector3d>& pts, Eigen::VectorXd x, int max_iterations) {
  if (!con.node_at) return refine_with(con, pts, std::move(x), max_iterations, 0);
  Refined r;
  for (double w : kFitNodeWeights) {
    r = refine_with(con, pts, std::move(x), max_iterations, w * static_cast<double>(pts.size()));
    x = r.x;
  }
  return r;
}

// ---- Counts the map allows ---------------------------------------------------------------

inline std::string count_list(const std::set<std::int64_t>& counts, std::int64_t step) {
  if (counts.empty()) return "none";
  const std::int64_t lo = *counts.begin(), hi = *counts.rbegin();
  if (counts.size() == 1) return std::to_string(lo);
  if (static_cast<std::int64_t>(counts.size()) == (hi - lo) / step + 1 && (hi - lo) % step == 0)
    return std::to_string(lo) + ".." + std::to_string(hi) + (step > 1 ? " in steps of " + std::to_string(step) : "");
  std::string s;
  std::size_t k = 0;
  for (auto it = counts.begin(); it != counts.end(); ++it, ++k) {
    if (k == 8 && counts.size() > 10) return s + ", ... (" + std::to_string(counts.size()) + " counts up to " + std::to_string(hi) + ")";
    s += (s.empty() ? "" : ", ") + std::to_string(*it);
  }
  return s;
}

inline void check_fit_inputs(const std::vector<Vector3d>& points, const Ratio& n, const FitOptions& o) {
  if (points.size() < kMinFitPoints || points.size() > kMaxFitPoints)
    throw InvalidInput("points", std::to_string(points.size()) + " points", "too few or too many",
                       "4 .. 1000000 points x,y,z on the unit sphere (a path: more is better)");
  std::vector<Vector3d> distinct;  // up to kMinFitPoints pairwise distinct points
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double norm = points[i].norm();
    if (!std::isfinite(norm) || std::abs(norm - 1.0) > kFitUnitTolerance)
      throw InvalidInput("points", "point " + std::to_string(i + 1) + " with |P| = " + number_text(norm),
                         "not on the unit sphere", "|P| within 1e-6 of 1");
    if (distinct.size() < kMinFitPoints &&
        std::all_of(distinct.begin(), distinct.end(), [&](const Vector3d& d) { return (points[i] - d).norm() > 1e-9; }))
      distinct.push_back(points[i]);
  }
  if (distinct.size() < kMinFitPoints)
    throw InvalidInput("points", std::to_string(points.size()) + " points", "fewer than 4 distinct points",
                       "at least 4 distinct points (chord >= 1e-9)");
  if (o.nodes && *o.nodes < 0) throw InvalidInput("nodes", std::to_string(*o.nodes), "negative", "a count >= 0");
  if (o.cusps && *o.cusps < 0) throw InvalidInput("cusps", std::to_string(*o.cusps), "negative", "a count >= 0");
  if (o.max_candidates < 1) throw InvalidInput("candidates", "0", "none asked for", "1 or more");
  if (!(o.max_deviation > 0)) throw InvalidInput("max-deviation", report_number(o.max_deviation), "not positive", "radians > 0");
  if (o.node_at && !(std::abs(o.node_at->norm() - 1.0) <= kFitUnitTolerance))
    throw InvalidInput("node-at", report_number(o.node_at->x()) + "," + number_text(o.node_at->y()) + "," + number_text(o.node_at->z()),
                       "not on the unit sphere", "x,y,z with |P| within 1e-6 of 1");
  if (!(o.node_tolerance > 0 && o.node_tolerance <= kPi))
    throw InvalidInput("node-tolerance", report_number(o.node_tolerance), "not an angle in (0, pi]", "radians in (0, pi]");
  if (!(o.min_margin >= 0 && o.min_margin <= kMaxFitMinMargin))
    throw InvalidInput("min-margin", report_number(o.min_margin), "outside the valid range", "radians in [0, 0.785]");
  if (o.min_margin > 0 && o.cusps && *o.cusps > 0)
    throw InvalidInput("min-margin", report_number(o.min_margin) + " with " + std::to_string(*o.cusps) + " cusps",
                       "a train with cusps lies on a pitch cone, a boundary of the map (margin 0)", "0 when cusps > 0 are wanted");
  check_census_cost(n);
}

/// The families the cusp request allows, or a reason why none does.
inline std::vector<Family> families(const Ratio& n, const FitOptions& o, std::string& reason) {
  if (!o.cusps || *o.cusps == 0) return {Family::free};
  const std::int64_t p = n.abs_p();
  if (*o.cusps == p) return {Family::pitch_cone, Family::mirror_cone};
  if (*o.cusps == 2 * p && std::abs(n.value()) < 1) return {Family::both_cones};
  const bool both = std::abs(n.value()) < 1;  // the cones meet at a2 = acos(-n), a3 = pi/2
  reason = "n = " + n.str() + " has " + (both ? "0, " + std::to_string(p) + " or " + std::to_string(2 * p) : "0 or " + std::to_string(p)) +
           " cusps (" + std::to_string(p) + " on a pitch cone a3 = a_p or pi - a_p" +
           (both ? ", " + std::to_string(2 * p) + " where both meet, a2 = acos(-n), a3 = pi/2" : "") + "), not " +
           std::to_string(*o.cusps);
  return {};
}

/// Seeds of one family inside the constraint; `seen` collects the node counts met.
inline std::vector<Seed> seeds(const Constraint& con, const std::vector<Vector3d>& pts, std::set<std::int64_t>& seen) {
  std::vector<std::pair<double, double>> shapes;
  const Parametrisation& par = con.par;
  if (par.family == Family::free) {
    for (int i = 0; i < kFitGrid; ++i)
      for (int k = 0; k < kFitGrid; ++k) shapes.push_back({fit_grid_angle(i), fit_grid_angle(k)});
    double zmax = -1, zmin = 1;
    for (const Vector3d& p : pts) {
      zmax = std::max(zmax, p.z());
      zmin = std::min(zmin, p.z());
    }
    const double d = std::acos(std::clamp(zmax, -1.0, 1.0)), s = std::acos(std::clamp(zmin, -1.0, 1.0));
    for (double sum : {s, 2 * kPi - s})
      for (double diff : {d, -d}) shapes.push_back({(sum + diff) / 2, (sum - diff) / 2});
    if (con.nodes)
      for (int i = 0; i < kFitGrid; ++i)
        for (const MapCell& c : fit_grid_column(i, con.n)) {
          seen.insert(c.nodes);
          if (c.nodes == *con.nodes && c.hi - c.lo > 4 * con.clearance)
            shapes.push_back({fit_grid_angle(i), (c.lo + c.hi) / 2});
        }
  } else if (par.family == Family::both_cones) {
    shapes.push_back(par.shape(par.make(0, 0, 0)));
  } else {
    for (int i = 0; i < kFitGrid * kFitGrid; ++i) {
      const double a2 = (static_cast<double>(i) + 0.5) * kPi / (kFitGrid * kFitGrid);
      shapes.push_back(par.shape(par.make(a2, 0, 0)));
    }
  }
  std::vector<Seed> out;
  for (const auto& [a2, a3] : shapes) {
    if (con.nodes && par.family != Family::free && a2 > kFitMinTwist && a2 < kPi - kFitMinTwist)
      seen.insert(root_nodes(a2, a3, con.n, par.family));
    if (con.admissible(a2, a3)) screen_shape(a2, a3, con.n, pts, out);
  }
  std::sort(out.begin(), out.end(), [](const Seed& a, const Seed& b) { return a.score < b.score; });
  // The best seeds, at most one per neighbourhood of 1.5 grid steps (and one turn).
  std::vector<Seed> picked;
  const double near = 1.5 * kPi / kFitGrid;
  for (const Seed& s : out) {
    if (picked.size() == (pts.size() <= kFitFewPoints ? 3 * kFitSeeds : kFitSeeds)) break;
    bool distinct = true;
    for (const Seed& q : picked)
      distinct = distinct && !(std::abs(q.a2 - s.a2) < near && std::abs(q.a3 - s.a3) < near &&
                               std::abs(std::remainder((q.phase - s.phase) / con.n.value(),
                                                       2 * kPi / static_cast<double>(con.n.abs_p()))) < 0.2);
    if (distinct) picked.push_back(s);
  }
  return picked;
}

/// The same train (a2, a3, and phase modulo 2 pi / q) within tol.
inline bool same_train(const FitCandidate& a, const FitCandidate& b, double tol) {
  const double q = static_cast<double>(a.train.ratio().q());
  return std::abs(a.train.a2() - b.train.a2()) < tol && std::abs(a.train.a3() - b.train.a3()) < tol &&
         std::abs(std::remainder(a.train.phase_given() - b.train.phase_given(), 2 * kPi / q)) < tol;
}

/// x with its phase reduced to [0, 2 pi / q) (the same curve; the feet found after it fit it).
inline Eigen::VectorXd with_reduced_phase(const Constraint& con, Eigen::VectorXd x) {
  const double q_turn = 2 * kPi / static_cast<double>(con.n.q());
  double& phase = x(con.par.dim() - 1);
  phase = std::fmod(phase, q_turn);
  if (phase < 0) phase += q_turn;
  if (!(phase < q_turn)) phase = 0;  // -tiny + q_turn rounds to q_turn
  return x;
}

/// The candidate of a refined x (phase reduced): the train (exactly on its cone), distances,
/// feet, and the margin when `with_margin`.
inline FitCandidate candidate(const Constraint& con, const std::vector<Vector3d>& pts, const Refined& r, bool with_margin) {
  const Parametrisation& par = con.par;
  const auto [a2, a3] = par.shape(r.x);
  const double phase = r.x(par.dim() - 1);
  FitCandidate c;
  switch (par.family) {
    case Family::free: c.train = GearTrain(a2, a3, con.n, phase); break;
    case Family::pitch_cone: c.train = GearTrain::on_cone(a2, A3Reference::pitch_cone, 0, con.n, phase); break;
    case Family::mirror_cone: c.train = GearTrain::on_cone(a2, A3Reference::mirror_pitch_cone, 0, con.n, phase); break;
    case Family::both_cones: c.train = GearTrain::on_cone(a2, A3Reference::pitch_cone, 0, con.n, phase); break;
  }
  const FitShape s(a2, a3, con.n.value(), phase);
  double sum = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double d = sphere_distance(curve_point(s, r.t[i]), pts[i]);
    sum += d * d;
    c.max_deviation = std::max(c.max_deviation, d);
  }
  c.rms = std::sqrt(sum / static_cast<double>(pts.size()));
  c.params = r.t;
  if (con.node_at) {
    const auto [ta, tb] = node_feet(con, s);
    c.node_distance = std::max(sphere_distance(curve_point(s, ta), *con.node_at), sphere_distance(curve_point(s, tb), *con.node_at));
  }
  c.root_nodes = root_nodes(a2, a3, con.n, par.family);
  if (with_margin) c.margin = map_margin(a2, a3, con.n, par.family != Family::free);
  return c;
}

/// A free candidate closer than con.clearance (a3) to an event of its column (node-constrained, or
/// with a minimum margin) is moved away from it in a3 by the clearance, or with a minimum margin
/// by the first of 1, 1.5, 2, 3 times it that is admissible (a boundary at 45 deg, a pole line,
/// needs 2 for the square of min_margin to clear it); x unchanged if none is.
inline Eigen::VectorXd clear_of_boundaries(const Constraint& con, Eigen::VectorXd x) {
  if (!(con.nodes || con.min_margin > 0) || con.par.family != Family::free) return x;
  const BoundarySet b = boundary_set(x(0), con.n);
  for (const BoundaryEvent& e : b.events) {
    const double gap = x(1) - e.a3;
    if (std::abs(gap) >= con.clearance) continue;
    for (const double times : {1.0, 1.5, 2.0, 3.0}) {
      if (times > 1 && !(con.min_margin > 0)) break;
      Eigen::VectorXd moved = x;
      moved(1) = e.a3 + (gap >= 0 ? times : -times) * con.clearance;
      if (!con.admissible(moved(0), moved(1))) continue;
      x = moved;
      break;
    }
  }
  return x;
}

}  // namespace path_fit_detail

inline PathFit fit_path(const std::vector<Vector3d>& input, const Ratio& n, const FitOptions& options) {
  using namespace path_fit_detail;
  check_fit_inputs(input, n, options);
  check_fit_cost(input.size(), {n});
  std::vector<Vector3d> points;
  for (const Vector3d& p : input) points.push_back(p / p.norm());
  PathFit out;
  out.ratio = n;
  const std::int64_t p = n.abs_p();
  if (options.nodes && *options.nodes % p != 0) {
    out.reason = "n = " + n.str() + ": node points come in sets of |p| = " + std::to_string(p) +
                 " (the curve's " + std::to_string(p) + "-fold symmetry about the sun axis); " +
                 std::to_string(*options.nodes) + " is not a multiple of " + std::to_string(p);
    return out;
  }
  const std::vector<Family> fams = families(n, options, out.reason);
  const std::vector<Vector3d> screen_pts = subsample(points, kFitScreenPoints);
  const std::vector<Vector3d> refine_pts = subsample(points, kFitRefinePoints);
  const std::vector<Vector3d> polish_pts = subsample(points, kFitPolishPoints);
  std::set<std::int64_t> seen;
  std::vector<std::pair<Constraint, Refined>> refined;
  for (Family f : fams) {
    const Constraint con{n, Parametrisation{f, n.value()}, options.nodes, options.cusps && *options.cusps == 0,
                         options.node_at ? std::optional<Vector3d>(options.node_at->normalized()) : std::nullopt,
                         std::max(kFitBoundaryClearance, options.min_margin), options.min_margin};
    for (const Seed& s : seeds(con, screen_pts, seen))
      refined.push_back({con, refine(con, refine_pts, con.par.make(s.a2, s.a3, s.phase), 60)});
  }
  std::sort(refined.begin(), refined.end(), [](const auto& a, const auto& b) { return a.second.cost < b.second.cost; });
  for (const auto& [con, r] : refined) {
    if (out.candidates.size() == options.max_candidates) break;
    Refined full = refine(con, polish_pts, r.x, 30);
    Eigen::VectorXd x = clear_of_boundaries(con, full.x);
    if (con.min_margin > 0 && x != full.x) {  // set back from the wall: polish along the shrunk cell's wall
      full = refine(con, polish_pts, x, 30);
      x = full.x;
    }
    full.x = with_reduced_phase(con, x);
    const auto [a2, a3] = con.par.shape(full.x);
    if (!con.admissible(a2, a3)) continue;
    // The same design as a kept one, or farther than allowed from a polish point (a subset of
    // the points, so the full maximum is at least as large): skipped before the full pass.
    full.t = certified_feet(con.par.fit_shape(full.x), n, polish_pts);
    FitCandidate sketch;
    try {
      sketch = candidate(con, polish_pts, full, false);
    } catch (const InvalidInput&) {  // a shape GearTrain refuses (admissible() should have kept it out)
      continue;
    }
    bool repeated = false;
    for (const FitCandidate& k : out.candidates) repeated = repeated || same_train(k, sketch, kFitSameDesign);
    if (repeated || sketch.max_deviation > options.max_deviation) continue;
    if (options.node_at && !(sketch.node_distance <= options.node_tolerance)) continue;
    full.t = certified_feet(con.par.fit_shape(full.x), n, points);
    FitCandidate c = candidate(con, points, full, true);
    if (c.max_deviation <= options.max_deviation) out.candidates.push_back(std::move(c));
  }
  std::sort(out.candidates.begin(), out.candidates.end(), [](const auto& a, const auto& b) { return a.rms < b.rms; });
  if (out.candidates.empty() && out.reason.empty()) {
    if (options.nodes && !seen.count(*options.nodes))
      out.reason = "n = " + n.str() + (options.cusps ? " with " + std::to_string(*options.cusps) + " cusps" : "") +
                   ": the boundary set at " + std::to_string(kFitGrid) + " carrier twists a2 shows " + count_list(seen, p) +
                   " node points, not " + std::to_string(*options.nodes) + " (a cell narrower than pi/" +
                   std::to_string(kFitGrid) + " in a2 between them is not seen)";
    else if (options.node_at)
      out.reason = "no train of n = " + n.str() + " with the wanted counts found with a node within " +
                   number_text(options.node_tolerance) + " rad of the node point (a search, not a proof that none exists)";
    else if (std::isfinite(options.max_deviation))
      out.reason = "no train of n = " + n.str() + " with the wanted counts passes within " +
                   number_text(options.max_deviation) + " rad of every point";
    else
      out.reason = "no candidate of n = " + n.str() + " converged inside the wanted cells of the map";
  }
  return out;
}

}  // namespace sphtroch
