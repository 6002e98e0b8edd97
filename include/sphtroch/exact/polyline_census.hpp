// sphtroch/exact/polyline_census.hpp — the node census from the sampled polyline: exact crossings
// (CGAL), near misses, Newton on the true curve, near-tangency analysis, node assembly.
//
//   #include <sphtroch/exact/polyline_census.hpp>          // needs sphtroch::exact (CGAL)
//   sphtroch::PolylineCensus c = sphtroch::polyline_census(train);
//   c.nodes;   // every node point (node.hpp), positions refined on the true curve
//
// Stages (each counted in `work`):
//  1. Sampling: N uniform samples over the period (default census_sample_count()), plus graded
//     dense samples around every near-cusp parameter (theta3 = pi when a3 is near a_p, theta3 = 0
//     when a3 is near pi - a_p), where a loop of size ~|a3 - a_p| and parameter half-length
//     ~sqrt(|a3 - a_p|)/|n| may hide between uniform samples.
//  2. Exact combinatorics: pairs of non-adjacent arcs that cross or touch (self_crossings.hpp),
//     plus near misses: non-adjacent edges closer than a quarter of the local edge length and far
//     apart in parameter (branches that approach each other without the polyline crossing).
//  3. Refinement: each seed runs refine_branch_pair in long double; converged pairs with a residual
//     below kNodeResidual are meeting points.
//  4. Kind: a meeting point whose branches cross at an angle >= kTransversalAngle is a crossing.
//     Otherwise, if the pair put on the tangency conditions (tangency_refinement.hpp) meets within
//     the tangency tolerance, it is a tangency there. Otherwise the gap between the branches is
//     modelled locally as a quadratic in the arc
//     parameter of one branch, gap(s) = c0 + c1 s + c2 s^2 (long double, sampled at s = 0, +-h):
//     its minimum |c0 - c1^2 / 4 c2| below the tangency tolerance makes one tangency (the two
//     crossings of a rounding-split tangency merge back into it); otherwise its real roots are
//     the crossings (both refined). Tiny near-cusp loops (branches closer in parameter than
//     kCuspLoopParam) are crossings.
//  5. Deduplication: meetings found from several seeds (unordered pairs, modulo the period).
//  6. Assembly into nodes (node_assembly.hpp), pairs at a pole the curve passes exactly put on it.
// Each stage is a function of namespace sphtroch::census below (tested in test_polyline_census.cpp);
// polyline_census() runs them in order.
#pragma once

// Header-only without GMP and MPFR: SPHTROCH_EXACT_WITHOUT_GMP with CGAL_NO_GMP=1 (arc_predicates.hpp).
#if !defined(SPHTROCH_HAVE_EXACT) && \
    !(defined(SPHTROCH_EXACT_WITHOUT_GMP) && defined(CGAL_NO_GMP) && CGAL_NO_GMP)
#error "sphtroch/exact/polyline_census.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself, or (header-only, no GMP or MPFR) define SPHTROCH_EXACT_WITHOUT_GMP and CGAL_NO_GMP=1"
#endif

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/census/node_assembly.hpp"
#include "sphtroch/core/parameters.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/census/polyline_census_result.hpp"
#include "sphtroch/exact/self_crossings.hpp"
#include "sphtroch/census/refinement.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/census/tangency_refinement.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <utility>
#include <vector>

namespace sphtroch {

/// A refined pair is a meeting point when |P(t1) - P(t2)| is below this (long double refinement
/// reaches ~1e-18 at crossings; touching branches converge linearly to ~1e-12 or better).
constexpr double kNodeResidual = 1e-11;
/// Crossing angles at or above this are transversal: no tangency analysis.
constexpr double kTransversalAngle = 1e-3;
/// Branch pairs closer than this in parameter are a near-cusp loop (never a tangency).
constexpr double kCuspLoopParam = 1e-2;
/// Refined pairs closer than this in parameter are one branch (Newton slid into t1 = t2 near a
/// cusp), not a node: a near-cusp loop resolved at all (|a3 - a_p| >= kCuspResolution) has its
/// branches ~sqrt(6 |a3 - a_p|) / |n| >= 1e-5 / |n| apart.
constexpr long double kMinBranchSeparation = 1e-8L;
/// Crossings at angles below this are checked for a second crossing of the same two branches
/// close by (a lens hidden between polyline edges; see census::MeetingFinder). A lens of
/// length L between branches whose geodesic curvatures differ by dk has crossing angles ~dk L / 2;
/// hidden lenses are shorter than about two edges.
constexpr double kLensScanAngle = 0.5;
/// The lens scan covers |s| <= kLensScanSpan sample spacings along the second branch ...
constexpr double kLensScanSpan = 3.0;
/// ... at this many points (even).
constexpr int kLensScanSamples = 4;
/// Consecutive polyline vertices closer than this are merged (the exact search needs distinct ones).
constexpr double kMinVertexSeparation = 1e-14;
/// Literal mode: the gap-model tolerance is the evaluation noise of long double, not a boundary.
constexpr double kLiteralGapTolerance = 1e-17;
/// Sampling: a tracer within this of a pitch cone or its mirror (radians of a3) gets graded dense
/// samples around each near-cusp parameter ...
constexpr double kDenseConeDistance = 0.3;
/// ... kDenseFineSamples fine samples on each side, spread over 4 sqrt(6 d) / |n| (d clamped
/// below at kDenseMinConeDistance), at most kDenseMaxSpacings uniform spacings ...
constexpr int kDenseFineSamples = 64;
constexpr double kDenseMinConeDistance = 1e-13;
constexpr double kDenseMaxSpacings = 8;
/// ... then offsets growing by this factor up to two uniform spacings.
constexpr double kDenseGrowth = 1.25;
/// Sample parameters closer than this fraction of the period are one sample.
constexpr double kSameSampleFraction = 1e-15;
/// Near misses: edges within this many uniform spacings in parameter are one branch ...
constexpr double kBranchNeighbourSpacings = 6;
/// ... pairs closer than this fraction of the longest chord are candidates ...
constexpr double kNearMissChordFraction = 0.25;
/// ... and a candidate within this many edges (in both indices) of an exact contact is that contact.
constexpr int kContactNeighbourhood = 2;
/// Newton on a seed may move each parameter by kRefineTravelSpacings uniform spacings plus kRefineTravelSlack.
constexpr double kRefineTravelSpacings = 4;
constexpr double kRefineTravelSlack = 0.05;
/// The quadratic gap model samples the gap at arc lengths 0, +-kGapModelArc (radians) ...
constexpr long double kGapModelArc = 1e-3L;
/// ... and is trusted within kGapModelReachSpacings uniform spacings of the refined pair.
constexpr double kGapModelReachSpacings = 4;
/// Projection of a point onto a branch: Newton steps.
constexpr int kProjectionSteps = 8;
/// Meetings closer than this in both parameters (radians of theta2) are one.
constexpr long double kSameMeetingParam = 1e-10L;
/// A meeting of branches closer in parameter than kCuspLoopParam is a loop only if the curve
/// leaves the meeting point: its residual must be below this fraction of the chords from
/// P(t1) and P(t2) to the point between them, P(t_mid). Near a cusp the curve barely moves, so
/// two parameters 1e-7 apart can have |P(t1) - P(t2)| ~ 1e-16 < kNodeResidual without any loop
/// (issue 17, D1: 13 one-branch "nodes" at n = 52/35); there the chords equal the residual.
/// A genuine loop of size ~d (d >= kCuspResolution = 1e-10) has chords ~d and residual ~1e-18.
constexpr long double kLoopResidualFraction = 1e-3L;
/// A short meeting must also be a crossing: the gap between the branches changes sign between
/// +-kLoopGapFraction times their parameter separation along branch 2 (census::MeetingFinder).
/// Measured on a loop 1e-9 rad from a cone (n = 45/46): gaps of +-6.5e-16 against a long
/// double noise of ~1e-19; a false meeting on the two sides of a near-cusp keeps one sign.
constexpr long double kLoopGapFraction = 1e-2L;

namespace census {

/// Stage 1. Uniform parameters over the period plus graded refinement around near-cusp
/// parameters (see header), ascending, distinct.
inline std::vector<double> census_parameters(const GearTrain& train, std::size_t n, unsigned escalation = 0) {
  const double period = train.period();
  const double h = period / static_cast<double>(n);
  std::vector<double> ts(n);
  for (std::size_t i = 0; i < n; ++i) ts[i] = period * static_cast<double>(i) / static_cast<double>(n);
  const double pi = Constants<double>::pi();
  const auto& r = train.ratio();
  const double abs_n = std::abs(r.value());
  struct Cone {
    double distance;
    double theta3;  // the planet angle of the near-cusp parameters
  };
  const Cone cones[] = {{std::abs(train.a3() - train.planet_cone()), pi}, {std::abs(train.a3() - (pi - train.planet_cone())), 0.0}};
  for (const Cone& c : cones) {
    if (c.distance > kDenseConeDistance) continue;
    // Loop parameter half-length ~ sqrt(6 d) in theta3, i.e. / |n| in theta2; cover 4x that.
    const double w = std::min(kDenseMaxSpacings * h, 4.0 * std::sqrt(6.0 * std::max(c.distance, kDenseMinConeDistance)) / abs_n);
    const int fine_samples = kDenseFineSamples << escalation;
    const double fine = w / fine_samples;
    for (std::int64_t k = 0; k < r.abs_p(); ++k) {
      const double tc = reduce_to_period(theta2_at_planet_angle(r, train.phase(), c.theta3, k), period);
      for (int j = -fine_samples; j <= fine_samples; ++j) ts.push_back(reduce_to_period(tc + fine * j, period));
      for (double off = w * kDenseGrowth; off < 2 * h; off *= kDenseGrowth) {
        ts.push_back(reduce_to_period(tc + off, period));
        ts.push_back(reduce_to_period(tc - off, period));
      }
    }
  }
  std::sort(ts.begin(), ts.end());
  std::vector<double> out;
  out.reserve(ts.size());
  for (double t : ts)
    if (out.empty() || t - out.back() > kSameSampleFraction * period) out.push_back(t);
  if (out.size() > 1 && period - out.back() + out.front() <= kSameSampleFraction * period) out.pop_back();
  return out;
}

/// The closed polyline of the census: parameters and distinct unit vertices.
struct SampledPolyline {
  std::vector<double> t;
  std::vector<Vector3d> points;
  double period = 0;

  std::size_t size() const { return t.size(); }
  /// Parameters at the ends of edge e (points[e] -> points[e + 1], the last edge closing the loop).
  double edge_start(std::size_t e) const { return t[e]; }
  double edge_end(std::size_t e) const { return e + 1 < t.size() ? t[e + 1] : t[0] + period; }
  double edge_mid(std::size_t e) const { return 0.5 * (edge_start(e) + edge_end(e)); }
};

/// Stage 1. The census polyline of n uniform samples (plus dense ones); vertices closer than
/// kMinVertexSeparation to the previous one are dropped.
inline SampledPolyline sample_polyline(const GearTrain& train, std::size_t n, PolylineWork& work,
                                       unsigned escalation = 0) {
  const TracerCurve<double> curve(train);
  SampledPolyline poly;
  poly.period = train.period();
  for (double t : census_parameters(train, n, escalation)) {
    const Vector3d p = curve.point(t);
    ++work.points_evaluated;
    // Refined samples at a (near-)cusp move by less than rounding: keep distinct vertices only.
    if (!poly.points.empty() && (p - poly.points.back()).norm() <= kMinVertexSeparation) continue;
    poly.t.push_back(t);
    poly.points.push_back(p);
  }
  while (poly.points.size() > 3 && (poly.points.back() - poly.points.front()).norm() <= kMinVertexSeparation) {
    poly.points.pop_back();
    poly.t.pop_back();
  }
  return poly;
}

/// A pair of parameters to refine into a meeting of two branches.
struct Seed {
  double t1, t2;
};
using EdgePair = std::pair<std::size_t, std::size_t>;

/// Stage 2a. Edge pairs (i < j) of the exact crossings and touchings of the polyline, sorted;
/// counts and work go to `out`.
inline std::vector<EdgePair> exact_contacts(const SampledPolyline& poly, PolylineCensus& out) {
  const SelfCrossings sc = find_self_crossings(poly.points, true);
  out.polyline_crossings = sc.crossings.size();
  out.polyline_touchings = sc.touchings.size();
  out.work.predicates += sc.predicates;
  out.work.candidate_pairs += sc.candidate_pairs;
  std::vector<EdgePair> contacts;
  for (const auto& e : sc.crossings) contacts.emplace_back(e.i, e.j);
  for (const auto& e : sc.touchings) contacts.emplace_back(e.i, e.j);
  std::sort(contacts.begin(), contacts.end());
  return contacts;
}

/// Distance between the chords of edges i and j (segments in R^3), a proxy for the arcs' distance.
inline double chord_distance(const SampledPolyline& poly, std::size_t i, std::size_t j) {
  const std::size_t m = poly.size();
  const auto& pts = poly.points;
  const Vector3d a = pts[i], b = pts[(i + 1) % m], c = pts[j], d = pts[(j + 1) % m];
  auto point_seg = [](const Vector3d& p, const Vector3d& s0, const Vector3d& s1) {
    const Vector3d u = s1 - s0;
    const double l2 = u.squaredNorm();
    const double f = l2 > 0 ? std::clamp((p - s0).dot(u) / l2, 0.0, 1.0) : 0.0;
    return (p - (s0 + f * u)).norm();
  };
  const double ends = std::min({(a - c).norm(), (a - d).norm(), (b - c).norm(), (b - d).norm()});
  return std::min({ends, point_seg(a, c, d), point_seg(b, c, d), point_seg(c, a, b), point_seg(d, a, b)});
}

/// True when (i, j) lies within kContactNeighbourhood edges of a pair in `contacts` (sorted).
inline bool near_contact(const std::vector<EdgePair>& contacts, std::size_t m, std::size_t i, std::size_t j) {
  const int r = kContactNeighbourhood;
  for (int di = -r; di <= r; ++di)
    for (int dj = -r; dj <= r; ++dj) {
      std::size_t a = (i + m + di) % m, b = (j + m + dj) % m;
      if (a > b) std::swap(a, b);
      if (std::binary_search(contacts.begin(), contacts.end(), std::make_pair(a, b))) return true;
    }
  return false;
}

/// The most close vertex pairs (close_pair_estimate) a census polyline may have: beyond, the
/// crossing and near-miss searches (O(N log N + K) in the K pairs of edges closer than a chord;
/// K is 1 to 6 times the estimate, ~40 ns a pair) would run for minutes or hours, so the train is
/// refused up front. At the bound one search visits ~1e8 pairs (~4 s).
constexpr double kMaxCloseVertexPairs = 2e7;

/// An estimate of K, the pairs of the polyline's vertices closer than its longest chord, the
/// searches' cost beyond N log N: the vertices hashed into cubes of that side, sum over the cubes
/// of c (c - 1) / 2 (pairs across neighbouring cubes are not counted: within a small factor of
/// K). O(N log N). A curve that winds many times within a thin band (a carrier twist near 0 with
/// a large denominator: n = 1/1908, a2 = 0.01 winds 1909 times within 0.02 rad) has K ~ N times
/// its windings.
inline double close_pair_estimate(const std::vector<Vector3d>& points) {
  const std::size_t m = points.size();
  double side = 0;
  for (std::size_t e = 0; e < m; ++e) side = std::max(side, (points[(e + 1) % m] - points[e]).norm());
  if (!(side > 0)) return 0;
  std::vector<std::uint64_t> keys(m);
  for (std::size_t e = 0; e < m; ++e) {
    std::uint64_t key = 0;
    for (int c = 0; c < 3; ++c) key = key * 1048576 + static_cast<std::uint64_t>(std::floor((points[e][c] + 1.5) / side)) % 1048576;
    keys[e] = key;
  }
  std::sort(keys.begin(), keys.end());
  double pairs = 0;
  for (std::size_t a = 0; a < m;) {
    std::size_t b = a;
    while (b < m && keys[b] == keys[a]) ++b;
    const double c = static_cast<double>(b - a);
    pairs += c * (c - 1) / 2;
    a = b;
  }
  return pairs;
}

/// InvalidInput when the polyline's close_pair_estimate exceeds kMaxCloseVertexPairs, naming the
/// estimate and what makes it (the curve's windings near one circle): "a2" when the carrier twist
/// is below 0.1 (the windings lie in a band ~2 a2 wide), else "n" (many windings).
inline void check_close_pairs(const GearTrain& train, const std::vector<Vector3d>& points) {
  const double k = close_pair_estimate(points);
  const bool thin = std::min(train.a2(), Constants<double>::pi() - train.a2()) < 0.1;
  if (k > kMaxCloseVertexPairs)
    throw InvalidInput(thin ? "a2" : "n", thin ? number_text(train.a2()) : train.ratio().str(),
                       "with n = " + train.ratio().str() + " the curve winds " + std::to_string(train.ratio().abs_p() + train.ratio().q()) +
                           " times close to itself: the census would compare ~" + number_text(std::round(k)) + " pairs of close edges (at most " +
                           number_text(kMaxCloseVertexPairs) + ")",
                       "a larger carrier twist a2 or a ratio with a smaller denominator");
}

/// Stage 2b. Near misses: edge pairs (i < j) of different branches (more than
/// kBranchNeighbourSpacings uniform spacings h apart in parameter) whose chords come closer than
/// kNearMissChordFraction of the longest chord, at a local minimum of that distance over
/// (i +- 1, j +- 1), and not next to an exact contact.
inline std::vector<EdgePair> near_misses(const SampledPolyline& poly, double h, const std::vector<EdgePair>& contacts) {
  const std::size_t m = poly.size();
  double max_chord = 0;
  for (std::size_t e = 0; e < m; ++e) max_chord = std::max(max_chord, (poly.points[(e + 1) % m] - poly.points[e]).norm());
  const double margin = kNearMissChordFraction * max_chord;
  struct NearMiss {
    double distance;
    std::size_t i, j;
  };
  std::vector<NearMiss> near;
  visit_close_edge_pairs(poly.points, true, margin, [&](std::size_t i, std::size_t j) {
    if (periodic_distance(poly.edge_mid(i), poly.edge_mid(j), poly.period) < kBranchNeighbourSpacings * h) return true;
    const double d = chord_distance(poly, i, j);
    if (d <= margin) near.push_back({d, i, j});
    return true;
  });
  const auto by_edges = [](const NearMiss& a, const NearMiss& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; };
  std::sort(near.begin(), near.end(), by_edges);
  auto find_near = [&](std::size_t i, std::size_t j) -> const NearMiss* {
    auto it = std::lower_bound(near.begin(), near.end(), NearMiss{0, i, j}, by_edges);
    return it != near.end() && it->i == i && it->j == j ? &*it : nullptr;
  };
  std::vector<EdgePair> out;
  for (const auto& nm : near) {
    bool is_min = true;
    for (int di = -1; di <= 1 && is_min; ++di)
      for (int dj = -1; dj <= 1 && is_min; ++dj) {
        if (di == 0 && dj == 0) continue;
        const std::size_t i2 = (nm.i + m + di) % m, j2 = (nm.j + m + dj) % m;
        const NearMiss* o = find_near(std::min(i2, j2), std::max(i2, j2));
        if (o && o->distance < nm.distance) is_min = false;
      }
    if (is_min && !near_contact(contacts, m, nm.i, nm.j)) out.emplace_back(nm.i, nm.j);
  }
  return out;
}

/// Signed gap from P(t2 + s) to the branch through t1 (projection by Newton), long double.
/// Adds the TracerCurve calls and projection Newton steps it makes to `work`; the projection's
/// parameter on branch 1 goes to *t1_out.
inline long double branch_gap(const TracerCurve<long double>& curve, long double t1, long double t2, long double s,
                              PolylineWork& work, long double* t1_out = nullptr) {
  const Vector3<long double> x = curve.point(t2 + s);
  ++work.points_evaluated;
  long double tau = t1;
  for (int it = 0; it < kProjectionSteps; ++it) {
    const Vector3<long double> p = curve.point(tau), v = curve.velocity(tau), a = curve.acceleration(tau);
    work.points_evaluated += 3;
    ++work.newton_steps;
    const long double phi = (p - x).dot(v);
    const long double dphi = v.squaredNorm() + (p - x).dot(a);
    if (dphi == 0) break;
    tau -= phi / dphi;
  }
  if (t1_out) *t1_out = tau;
  const Vector3<long double> p = curve.point(tau), v = curve.velocity(tau);
  work.points_evaluated += 2;
  const Vector3<long double> normal = p.cross(v).normalized();
  return (x - p).dot(normal);
}

/// A meeting of two branches on the true curve (long double parameters).
struct Meeting {
  long double t1, t2;
  NodeKind kind;
};

/// Stages 3 and 4: refine seeds into meetings and tell their kind (see header). Counts
/// newton_failures and work in the census it is given.
class MeetingFinder {
 public:
  using LD = long double;

  /// h: uniform sample spacing; gap_tolerance: a gap-model minimum below it is one tangency.
  MeetingFinder(const GearTrain& train, double h, long double gap_tolerance, PolylineCensus& out)
      : curve_(train), period_(train.period()), h_(h), gap_tolerance_(gap_tolerance), out_(out) {
    // On a pitch cone (within resolution) there is no near-cusp loop: meetings of branches a few
    // parameters apart around the cusp are the cusp itself (Newton creeping into it), not nodes.
    const ConeMargins cones = cone_margins(train);
    on_a_cone_ = cones.on_pitch_cone() || cones.on_mirror_cone();
    settings_.max_travel = kRefineTravelSpacings * h + kRefineTravelSlack;
  }

  /// Refine one seed; every meeting it yields is appended to meetings().
  void add_seed(const Seed& s) {
    const auto r = refine(s.t1, s.t2);
    const LD dt = separation(r.t1, r.t2);
    if (r.status == RefineStatus::left_bracket || dt < kMinBranchSeparation) {
      ++out_.newton_failures;
      return;
    }
    const Vector3<LD> v1 = curve_.velocity(r.t1), v2 = curve_.velocity(r.t2);
    out_.work.points_evaluated += 2;
    const double angle = tangent_line_angle(v1.cast<double>(), v2.cast<double>());
    if (dt < kCuspLoopParam && on_a_cone_) {
      ++out_.newton_failures;
      return;
    }
    if (dt < kCuspLoopParam && (!leaves_meeting_point(r) || !gap_changes_sign(r.t1, r.t2, dt))) {
      ++out_.newton_failures;
      return;
    }
    if (dt < kCuspLoopParam || angle >= kTransversalAngle) {
      if (r.residual <= kNodeResidual) {
        meetings_.push_back({r.t1, r.t2, NodeKind::crossing});
        if (dt >= kCuspLoopParam && angle < kLensScanAngle) scan_lens(r.t1, r.t2);
      } else {
        ++out_.newton_failures;
      }
      return;
    }
    split_near_tangency(r, v2.norm());
  }

  const std::vector<Meeting>& meetings() const { return meetings_; }

 private:
  LD separation(LD a, LD b) const { return periodic_distance<LD>(a, b, period_); }
  /// Every meeting must join two different branches (not t1 = t2 modulo the period).
  bool distinct_branches(LD a, LD b) const { return separation(a, b) >= kMinBranchSeparation; }

  /// The curve between the branches of a short meeting goes somewhere (see kLoopResidualFraction).
  bool leaves_meeting_point(const RefinedPair<LD>& r) {
    const LD a = r.t1, b = a + std::remainder(r.t2 - r.t1, static_cast<LD>(period_));  // the short way round
    const Vector3<LD> p1 = curve_.point(a), p2 = curve_.point(b), mid = curve_.point((a + b) / 2);
    out_.work.points_evaluated += 3;
    return r.residual <= kLoopResidualFraction * ((mid - p1).norm() + (mid - p2).norm());
  }

  /// The branches cross: the signed gap of branch 2 from branch 1 changes sign across the meeting,
  /// sampled kLoopGapFraction of the branch separation away on either side. Near a cusp its two
  /// sides run within ~1e-14 of each other without crossing, and Newton stalls there with a
  /// residual below kNodeResidual (issue 17: 45/46 next to the mirror cone).
  bool gap_changes_sign(LD t1, LD t2, LD dt) {
    const LD s = kLoopGapFraction * dt;
    const LD plus = gap(t1, t2, s), minus = gap(t1, t2, -s);
    return (plus < 0 && minus > 0) || (plus > 0 && minus < 0);
  }

  RefinedPair<LD> refine(LD a, LD b) {
    const auto r = refine_branch_pair(curve_, a, b, settings_);
    out_.work.newton_steps += r.iterations;
    out_.work.points_evaluated += r.evaluations;
    return r;
  }
  TangencyPair to_tangency_conditions(LD t1, LD t2) {
    const TangencyPair tp = refine_tangency_pair(curve_.train(), t1, t2);
    out_.work.points_evaluated += tp.points_evaluated;
    return tp;
  }
  LD gap(LD t1, LD t2, LD s, LD* t1_out = nullptr) { return branch_gap(curve_, t1, t2, s, out_.work, t1_out); }

  /// Refine a crossing guessed at s along branch 2 from (t1, t2); keep it if it converges.
  void add_crossing_near(LD t1, LD t2, LD s) {
    LD t1s;
    gap(t1, t2, s, &t1s);
    const auto rr = refine(t1s, t2 + s);
    if (rr.status != RefineStatus::left_bracket && rr.residual <= kNodeResidual && distinct_branches(rr.t1, rr.t2))
      meetings_.push_back({rr.t1, rr.t2, NodeKind::crossing});
  }

  // A lens: two branches that cross twice within about one pair of polyline edges. Two chords
  // cross at most once, so the polyline shows one crossing or a near miss, and Newton finds one
  // of the two. Around a crossing (t1, t2) found at an angle below kLensScanAngle, the gap
  // f(s) = gap(t2 + s) / s (the known root s = 0 divided out) is sampled at kLensScanSamples
  // points over |s| <= kLensScanSpan * h; each sign change is refined as a crossing of its own
  // (duplicates are removed by unique_meetings).
  void scan_lens(LD t1, LD t2) {
    const LD span = kLensScanSpan * static_cast<LD>(h_);
    const int half = kLensScanSamples / 2;
    LD prev_s = 0, prev_f = 0;
    for (int k = -half; k <= half; ++k) {
      if (k == 0) continue;
      const LD s = span * k / half;
      const LD f = gap(t1, t2, s) / s;
      if (k != -half && (f < 0) != (prev_f < 0))
        add_crossing_near(t1, t2, prev_s + (s - prev_s) * prev_f / (prev_f - f));  // secant guess of the root
      prev_s = s;
      prev_f = f;
    }
  }

  // Near-tangent branches. First the tangency conditions (tangency_refinement.hpp): branches
  // that meet within the tangency tolerance on them touch. This decides tiny curves (a2, a3 ~
  // 1e-2 near a pole), where the quadratic model below is too coarse to see the touching.
  // Otherwise the gap along branch 2 as a quadratic c0 + c1 s + c2 s^2 (see header).
  void split_near_tangency(const RefinedPair<LD>& r, LD speed2) {
    const TangencyPair on_conditions = to_tangency_conditions(r.t1, r.t2);
    if (on_conditions.moved && on_conditions.gap <= gap_tolerance_ && distinct_branches(on_conditions.t1, on_conditions.t2)) {
      meetings_.push_back({on_conditions.t1, on_conditions.t2, NodeKind::tangency});
      return;
    }
    const LD hs = kGapModelArc / std::max<LD>(speed2, kGapModelArc);
    const LD g0 = gap(r.t1, r.t2, 0);
    const LD gp = gap(r.t1, r.t2, hs);
    const LD gm = gap(r.t1, r.t2, -hs);
    const LD c0 = g0, c1 = (gp - gm) / (2 * hs), c2 = (gp - 2 * g0 + gm) / (2 * hs * hs);
    if (c2 == 0) {
      if (r.residual <= kNodeResidual) meetings_.push_back({r.t1, r.t2, NodeKind::crossing});
      return;
    }
    const LD s_star = -c1 / (2 * c2);
    const LD gap_min = c0 - c1 * c1 / (4 * c2);
    if (std::abs(gap_min) <= gap_tolerance_) {
      LD t1s;
      gap(r.t1, r.t2, s_star, &t1s);
      if (distinct_branches(t1s, r.t2 + s_star)) {
        // Onto the tangency conditions (well conditioned; tangency_refinement.hpp).
        const TangencyPair tp = to_tangency_conditions(t1s, r.t2 + s_star);
        meetings_.push_back({tp.t1, tp.t2, NodeKind::tangency});
      }
      return;
    }
    const LD disc = c1 * c1 - 4 * c0 * c2;
    if (disc < 0) return;  // a near miss, not a node
    for (LD sgn : {-1.0L, 1.0L}) {
      const LD s = (-c1 + sgn * std::sqrt(disc)) / (2 * c2);
      // The quadratic model holds near s = 0 only; a crossing farther away has its own seed.
      if (!(std::abs(s) <= kGapModelReachSpacings * static_cast<LD>(h_))) continue;
      add_crossing_near(r.t1, r.t2, s);
    }
  }

  TracerCurve<LD> curve_;
  double period_;
  double h_;
  LD gap_tolerance_;
  bool on_a_cone_ = false;
  RefineSettings settings_;
  PolylineCensus& out_;
  std::vector<Meeting> meetings_;
};

/// Stage 5. Meetings with both parameters within kSameMeetingParam (modulo the period, either
/// order) are one; the first in order of t1 is kept. Returns canonical meetings: parameters in
/// [0, period), t1 <= t2, ascending in t1.
inline std::vector<Meeting> unique_meetings(std::vector<Meeting> meetings, long double period) {
  using LD = long double;
  const LD tol = kSameMeetingParam;
  auto close = [&](LD a, LD b) {
    const LD d = std::abs(reduce_to_period(a, period) - reduce_to_period(b, period));
    return std::min(d, period - d) <= tol;
  };
  // Canonical order (t1 <= t2 after reduction), sorted: duplicates become neighbours in t1.
  for (auto& mt : meetings) {
    mt.t1 = reduce_to_period(mt.t1, period);
    mt.t2 = reduce_to_period(mt.t2, period);
    if (mt.t2 < mt.t1) std::swap(mt.t1, mt.t2);
  }
  std::sort(meetings.begin(), meetings.end(), [](const Meeting& a, const Meeting& b) { return a.t1 < b.t1; });
  std::vector<Meeting> unique;
  for (const Meeting& m : meetings) {
    bool dup = false;
    // Look back over the meetings whose t1 is within the tolerance ...
    for (std::size_t b = unique.size(); b-- > 0 && !dup;) {
      if (m.t1 - unique[b].t1 > tol && unique[b].t1 > tol) break;
      dup = close(unique[b].t1, m.t1) && close(unique[b].t2, m.t2);
    }
    // ... and across the wrap (t1 near 0 may pair with t2 near the period).
    for (std::size_t b = 0; b < unique.size() && !dup && unique[b].t1 <= tol; ++b)
      dup = (close(unique[b].t1, m.t2) && close(unique[b].t2, m.t1)) ||
            (close(unique[b].t1, m.t1) && close(unique[b].t2, m.t2));
    if (!dup) unique.push_back(m);
  }
  return unique;
}

/// Stage 6 (first half). Branch pairs of unique meetings: parameters in double, reduced, ordered;
/// the position is the normalised midpoint of the two branch points (long double).
inline std::vector<BranchPair> branch_pairs(const GearTrain& train, const std::vector<Meeting>& meetings,
                                            PolylineWork& work) {
  const TracerCurve<long double> curve(train);
  const double period = train.period();
  std::vector<BranchPair> out;
  for (const auto& u : meetings) {
    BranchPair bp;
    bp.t1 = reduce_to_period(static_cast<double>(reduce_to_period<long double>(u.t1, period)), period);
    bp.t2 = reduce_to_period(static_cast<double>(reduce_to_period<long double>(u.t2, period)), period);
    if (bp.t2 < bp.t1) std::swap(bp.t1, bp.t2);
    bp.position = ((curve.point(u.t1) + curve.point(u.t2)) / 2).normalized().cast<double>();
    work.points_evaluated += 2;
    bp.kind = u.kind;
    out.push_back(bp);
  }
  return out;
}

/// The planet angles b at which the tracer's circle passes EXACTLY through a pole, as the root
/// census decides it (root_census.hpp: y of C(0) = -sin(a2 + a3), of C(pi) = sin(a3 - a2), in long
/// double from the train's exact sines and cosines): b = 0 (south pole, a3 = pi - a2) and b = pi
/// (north pole, a3 = a2).
struct PoleCrossing {
  long double planet_angle;
  double z;  // -1 south, +1 north
};
inline std::vector<PoleCrossing> poles_on_curve(const GearTrain& train) {
  const auto t = train.trig<long double>();
  std::vector<PoleCrossing> out;
  if (t.sin_a3 * t.cos_a2 + t.cos_a3 * t.sin_a2 == 0) out.push_back({0.0L, -1.0});
  if (t.sin_a3 * t.cos_a2 - t.cos_a3 * t.sin_a2 == 0) out.push_back({Constants<long double>::pi(), 1.0});
  return out;
}

/// Stage 6 (between the halves). On a train through a pole, branch pairs whose both parameters
/// lie within kBranchParamTolerance of pole parameters ARE the pole pair: put exactly on it
/// (parameters theta2 where theta3 = b_pole, Eq. 3; position the pole). Touching branches at a
/// pole are refined on the tangency conditions, whose solution is ill conditioned there and may
/// stop ~1e-9 of parameter (1e-11 rad) away: without the snap that pair is a second node.
inline void snap_pairs_to_poles(const GearTrain& train, std::vector<BranchPair>& pairs) {
  const double period = train.period();
  for (const PoleCrossing& pole : poles_on_curve(train)) {
    std::vector<double> ts;
    for (std::int64_t k = 0; k < train.ratio().abs_p(); ++k)
      ts.push_back(reduce_to_period(
          static_cast<double>(theta2_at_planet_angle(train.ratio(), static_cast<long double>(train.phase()), pole.planet_angle, k)),
          period));
    auto nearest = [&](double t) -> const double* {
      for (const double& tp : ts)
        if (periodic_distance(t, tp, period) <= kBranchParamTolerance) return &tp;
      return nullptr;
    };
    for (BranchPair& bp : pairs) {
      const double *a = nearest(bp.t1), *b = nearest(bp.t2);
      if (!a || !b || a == b) continue;
      bp.t1 = std::min(*a, *b);
      bp.t2 = std::max(*a, *b);
      bp.position = Vector3d(0, 0, pole.z);
    }
  }
}

}  // namespace census

/// The polyline node census of one gear train (see header). The train is analysed as given.
inline PolylineCensus polyline_census(const GearTrain& train, const PolylineCensusSettings& settings = {}) {
  check_census_cost(train.ratio());  // InvalidInput up front instead of hours or gigabytes
  PolylineCensus out;
  const bool literal = settings.tangency_tolerance <= 0;
  const long double gap_tolerance = literal ? kLiteralGapTolerance : settings.tangency_tolerance;

  const std::size_t n = escalated_samples(settings.samples ? settings.samples : census_sample_count(train),
                                          settings.escalation);
  out.escalation = settings.escalation;
  const census::SampledPolyline poly = census::sample_polyline(train, n, out.work, settings.escalation);
  out.samples = poly.size();
  census::check_close_pairs(train, poly.points);  // refused before the searches whose cost it bounds
  const double h = train.period() / static_cast<double>(n);

  const std::vector<census::EdgePair> contacts = census::exact_contacts(poly, out);
  const std::vector<census::EdgePair> near = census::near_misses(poly, h, contacts);
  out.near_misses = near.size();
  std::vector<census::Seed> seeds;
  for (const auto& [i, j] : contacts) seeds.push_back({poly.edge_mid(i), poly.edge_mid(j)});
  for (const auto& [i, j] : near) seeds.push_back({poly.edge_mid(i), poly.edge_mid(j)});
  out.work.seeds = seeds.size();

  census::MeetingFinder finder(train, h, gap_tolerance, out);
  for (const census::Seed& s : seeds) finder.add_seed(s);
  const auto unique = census::unique_meetings(finder.meetings(), static_cast<long double>(train.period()));

  out.pairs = census::branch_pairs(train, unique, out.work);
  census::snap_pairs_to_poles(train, out.pairs);
  out.nodes = assemble_nodes(out.pairs, TracerCurve<double>(train), kNodeMergeDistance, &out.single_branch_groups);
  out.work.points_evaluated += assembly_evaluations(out.nodes);
  return out;
}

}  // namespace sphtroch
