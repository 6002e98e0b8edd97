// sphtroch/polyline_census.hpp — the node census from the sampled polyline: exact crossings
// (CGAL), near misses, Newton on the true curve, near-tangency analysis, node assembly.
//
//   #include <sphtroch/polyline_census.hpp>          // needs sphtroch::exact (CGAL)
//   sphtroch::PolylineCensus c = sphtroch::polyline_census(train);
//   c.nodes;   // every node point (node.hpp), positions refined on the true curve
//
// Stages (each counted in `work`):
//  1. Sampling: N uniform samples over the period (default census_sample_count()), plus graded
//     dense samples around every near-cusp parameter (theta3 = pi when a3 is near a_p, theta3 = 0
//     when a3 is near pi - a_p), where a loop of size ~|a3 - a_p| and parameter half-length
//     ~sqrt(|a3 - a_p|)/|n| may hide between uniform samples.
//  2. Exact combinatorics: pairs of non-adjacent arcs that cross or touch (polyline_crossings.hpp),
//     plus near misses: non-adjacent edges closer than a quarter of the local edge length and far
//     apart in parameter (branches that approach each other without the polyline crossing).
//  3. Refinement: each seed runs refine_branch_pair in long double; converged pairs with a residual
//     below kNodeResidual are meeting points.
//  4. Kind: a meeting point whose branches cross at an angle >= kTransversalAngle is a crossing.
//     Otherwise, if the pair put on the tangency conditions (tangency_refinement.hpp) meets within
//     the tangency tolerance, it is a tangency there. Otherwise the gap between the branches is modelled locally as a quadratic in the arc
//     parameter of one branch, gap(s) = c0 + c1 s + c2 s^2 (long double, sampled at s = 0, +-h):
//     its minimum |c0 - c1^2 / 4 c2| below the tangency tolerance makes one tangency (the two
//     crossings of a rounding-split tangency merge back into it); otherwise its real roots are
//     the crossings (both refined). Tiny near-cusp loops (branches closer in parameter than
//     kCuspLoopParam) are crossings.
//  5. Assembly into nodes (node_assembly.hpp).
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/polyline_census.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself"
#endif

#include "sphtroch/cost_bounds.hpp"
#include "sphtroch/curve.hpp"
#include "sphtroch/gear_train.hpp"
#include "sphtroch/node.hpp"
#include "sphtroch/node_assembly.hpp"
#include "sphtroch/pitch_cone.hpp"
#include "sphtroch/polyline_census_result.hpp"
#include "sphtroch/polyline_crossings.hpp"
#include "sphtroch/refinement.hpp"
#include "sphtroch/sampling.hpp"
#include "sphtroch/tangency_refinement.hpp"
#include "sphtroch/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
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
/// close by (a lens hidden between polyline edges; see scan_lens in polyline_census). A lens of
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


namespace detail {

/// Uniform parameters plus graded refinement around near-cusp parameters (see header).
inline std::vector<double> census_parameters(const GearTrain& train, std::size_t n) {
  const double period = train.period();
  const double h = period / static_cast<double>(n);
  std::vector<double> ts(n);
  for (std::size_t i = 0; i < n; ++i) ts[i] = period * static_cast<double>(i) / static_cast<double>(n);
  const double pi = Constants<double>::pi();
  const auto& r = train.ratio();
  const double abs_n = std::abs(r.value());
  struct Cone {
    double distance;
    double theta3;
  };
  const Cone cones[] = {{std::abs(train.a3() - train.planet_cone()), pi}, {std::abs(train.a3() - (pi - train.planet_cone())), 0.0}};
  for (const Cone& c : cones) {
    if (c.distance > 0.3) continue;
    // Loop parameter half-length ~ sqrt(6 d) in theta3, i.e. / |n| in theta2; cover 4x that.
    const double w = std::min(8 * h, 4.0 * std::sqrt(6.0 * std::max(c.distance, 1e-13)) / abs_n);
    const double fine = w / 64;
    for (std::int64_t k = 0; k < r.abs_p(); ++k) {
      const double tc = wrap_param((c.theta3 - train.phase() + 2 * pi * static_cast<double>(k)) / r.value(), period);
      for (int j = -64; j <= 64; ++j) ts.push_back(wrap_param(tc + fine * j, period));
      for (double off = w * 1.25; off < 2 * h; off *= 1.25) {
        ts.push_back(wrap_param(tc + off, period));
        ts.push_back(wrap_param(tc - off, period));
      }
    }
  }
  std::sort(ts.begin(), ts.end());
  std::vector<double> out;
  out.reserve(ts.size());
  for (double t : ts)
    if (out.empty() || t - out.back() > 1e-15 * period) out.push_back(t);
  if (out.size() > 1 && period - out.back() + out.front() <= 1e-15 * period) out.pop_back();
  return out;
}

/// Signed gap from P(t2 + s) to the branch through t1 (projection by Newton), long double.
/// Adds the TracerCurve calls and projection Newton steps it makes to `work`.
inline long double branch_gap(const TracerCurve<long double>& curve, long double t1, long double t2, long double s,
                              PolylineWork& work, long double* t1_out = nullptr) {
  const Vector3<long double> x = curve.point(t2 + s);
  ++work.points_evaluated;
  long double tau = t1;
  for (int it = 0; it < 8; ++it) {
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

}  // namespace detail

/// The polyline node census of one gear train (see header). The train is analysed as given.
inline PolylineCensus polyline_census(const GearTrain& train, const PolylineCensusSettings& settings = {}) {
  check_census_cost(train.ratio());  // InvalidInput up front instead of hours or gigabytes
  using LD = long double;
  PolylineCensus out;
  const TracerCurve<double> curve(train);
  const TracerCurve<LD> curve_ld(train);
  const double period = train.period();
  const bool literal = settings.tangency_tolerance <= 0;
  const long double gap_tol = literal ? kLiteralGapTolerance : settings.tangency_tolerance;
  // On a pitch cone (within resolution) there is no near-cusp loop: meetings of branches a few
  // parameters apart around the cusp are the cusp itself (Newton creeping into it), not nodes.
  const ConeMargins cones = cone_margins(train);
  const bool on_a_cone = cones.on_pitch_cone() || cones.on_mirror_cone();

  // 1. Sampling.
  const std::size_t n = settings.samples ? settings.samples : census_sample_count(train);
  std::vector<double> ts;
  std::vector<Vector3d> pts;
  for (double t : detail::census_parameters(train, n)) {
    const Vector3d p = curve.point(t);
    ++out.work.points_evaluated;
    // Refined samples at a (near-)cusp move by less than rounding: keep distinct vertices only.
    if (!pts.empty() && (p - pts.back()).norm() <= kMinVertexSeparation) continue;
    ts.push_back(t);
    pts.push_back(p);
  }
  while (pts.size() > 3 && (pts.back() - pts.front()).norm() <= kMinVertexSeparation) {
    pts.pop_back();
    ts.pop_back();
  }
  out.samples = ts.size();
  const std::size_t m = ts.size();
  auto edge_t0 = [&](std::size_t e) { return ts[e]; };
  auto edge_t1 = [&](std::size_t e) { return e + 1 < m ? ts[e + 1] : ts[0] + period; };

  // 2. Seeds: exact crossings and touchings, then near misses.
  struct Seed {
    double t1, t2;
  };
  std::vector<Seed> seeds;
  const SelfCrossings sc = find_self_crossings(pts, true);
  out.polyline_crossings = sc.crossings.size();
  out.polyline_touchings = sc.touchings.size();
  out.work.predicates += sc.predicates;
  out.work.candidate_pairs += sc.candidate_pairs;
  auto mid = [&](std::size_t e) { return 0.5 * (edge_t0(e) + edge_t1(e)); };
  std::vector<std::pair<std::size_t, std::size_t>> contacts;
  for (const auto& e : sc.crossings) contacts.emplace_back(e.i, e.j);
  for (const auto& e : sc.touchings) contacts.emplace_back(e.i, e.j);
  std::sort(contacts.begin(), contacts.end());
  for (const auto& [i, j] : contacts) seeds.push_back({mid(i), mid(j)});
  auto near_contact = [&](std::size_t i, std::size_t j) {
    for (int di = -2; di <= 2; ++di)
      for (int dj = -2; dj <= 2; ++dj) {
        std::size_t a = (i + m + di) % m, b = (j + m + dj) % m;
        if (a > b) std::swap(a, b);
        if (std::binary_search(contacts.begin(), contacts.end(), std::make_pair(a, b))) return true;
      }
    return false;
  };

  const double h = period / static_cast<double>(n);
  double max_chord = 0;
  for (std::size_t e = 0; e < m; ++e) max_chord = std::max(max_chord, (pts[(e + 1) % m] - pts[e]).norm());
  const double margin = 0.25 * max_chord;
  auto chord_distance = [&](std::size_t i, std::size_t j) {
    // Distance between two chords (segments in R^3), a proxy for the arcs' distance.
    const Vector3d a = pts[i], b = pts[(i + 1) % m], c = pts[j], d = pts[(j + 1) % m];
    double best = std::min({(a - c).norm(), (a - d).norm(), (b - c).norm(), (b - d).norm()});
    auto point_seg = [](const Vector3d& p, const Vector3d& s0, const Vector3d& s1) {
      const Vector3d u = s1 - s0;
      const double l2 = u.squaredNorm();
      const double f = l2 > 0 ? std::clamp((p - s0).dot(u) / l2, 0.0, 1.0) : 0.0;
      return (p - (s0 + f * u)).norm();
    };
    best = std::min({best, point_seg(a, c, d), point_seg(b, c, d), point_seg(c, a, b), point_seg(d, a, b)});
    return best;
  };
  struct NearMiss {
    double distance;
    std::size_t i, j;
  };
  std::vector<NearMiss> near;
  visit_close_edge_pairs(pts, true, margin, [&](std::size_t i, std::size_t j) {
    double dt = std::abs(mid(i) - mid(j));
    dt = std::min(dt, period - dt);
    if (dt < 6 * h) return true;  // neighbours along one branch
    const double d = chord_distance(i, j);
    if (d <= margin) near.push_back({d, i, j});
    return true;
  });
  // Keep local minima of the distance over (i +- 1, j +- 1) only.
  std::sort(near.begin(), near.end(), [](const NearMiss& a, const NearMiss& b) {
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  auto find_near = [&](std::size_t i, std::size_t j) -> const NearMiss* {
    auto it = std::lower_bound(near.begin(), near.end(), NearMiss{0, i, j},
                               [](const NearMiss& a, const NearMiss& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
    return it != near.end() && it->i == i && it->j == j ? &*it : nullptr;
  };
  for (const auto& nm : near) {
    bool is_min = true;
    for (int di = -1; di <= 1 && is_min; ++di)
      for (int dj = -1; dj <= 1 && is_min; ++dj) {
        if (di == 0 && dj == 0) continue;
        const std::size_t i2 = (nm.i + m + di) % m, j2 = (nm.j + m + dj) % m;
        const NearMiss* o = find_near(std::min(i2, j2), std::max(i2, j2));
        if (o && o->distance < nm.distance) is_min = false;
      }
    if (is_min && !near_contact(nm.i, nm.j)) {
      seeds.push_back({mid(nm.i), mid(nm.j)});
      ++out.near_misses;
    }
  }
  out.work.seeds = seeds.size();

  // 3. + 4. Refinement and kinds.
  struct Meeting {
    LD t1, t2;
    NodeKind kind;
  };
  std::vector<Meeting> meetings;
  // Every meeting must join two different branches (not t1 = t2 modulo the period).
  auto distinct_branches = [&](LD a, LD b) {
    LD d = std::fmod(std::abs(a - b), static_cast<LD>(period));
    return std::min(d, static_cast<LD>(period) - d) >= kMinBranchSeparation;
  };
  RefineSettings rs;
  rs.max_travel = 4 * h + 0.05;
  auto refine = [&](LD a, LD b) { 
    const auto r = refine_branch_pair(curve_ld, a, b, rs);
    out.work.newton_steps += r.iterations;
    out.work.points_evaluated += r.evaluations;
    return r;
  };
  // A lens: two branches that cross twice within about one pair of polyline edges. Two chords
  // cross at most once, so the polyline shows one crossing or a near miss, and Newton finds one
  // of the two. Around a crossing (t1, t2) found at an angle below kLensScanAngle, the gap
  // f(s) = gap(t2 + s) / s (the known root s = 0 divided out) is sampled at kLensScanSamples
  // points over |s| <= kLensScanSpan * h; each sign change is refined as a crossing of its own
  // (duplicates are removed below).
  auto scan_lens = [&](LD t1, LD t2) {
    const LD span = kLensScanSpan * static_cast<LD>(h);
    const int half = kLensScanSamples / 2;
    LD prev_s = 0, prev_f = 0;
    for (int k = -half; k <= half; ++k) {
      if (k == 0) continue;
      const LD s = span * k / half;
      const LD f = detail::branch_gap(curve_ld, t1, t2, s, out.work) / s;
      if (k != -half && (f < 0) != (prev_f < 0)) {
        const LD sm = prev_s + (s - prev_s) * prev_f / (prev_f - f);  // secant guess of the root
        LD t1s;
        detail::branch_gap(curve_ld, t1, t2, sm, out.work, &t1s);
        const auto rr = refine(t1s, t2 + sm);
        if (rr.status != RefineStatus::left_bracket && rr.residual <= kNodeResidual && distinct_branches(rr.t1, rr.t2))
          meetings.push_back({rr.t1, rr.t2, NodeKind::crossing});
      }
      prev_s = s;
      prev_f = f;
    }
  };
  for (const Seed& s : seeds) {
    const auto r = refine(s.t1, s.t2);
    LD dt = std::fmod(std::abs(r.t1 - r.t2), static_cast<LD>(period));
    dt = std::min(dt, static_cast<LD>(period) - dt);
    if (r.status == RefineStatus::left_bracket || dt < kMinBranchSeparation) {
      ++out.newton_failures;
      continue;
    }
    const Vector3<LD> v1 = curve_ld.velocity(r.t1), v2 = curve_ld.velocity(r.t2);
    out.work.points_evaluated += 2;
    const double angle = tangent_line_angle(v1.cast<double>(), v2.cast<double>());
    if (dt < kCuspLoopParam && on_a_cone) {
      ++out.newton_failures;
      continue;
    }
    if (dt < kCuspLoopParam || angle >= kTransversalAngle) {
      if (r.residual <= kNodeResidual) {
        meetings.push_back({r.t1, r.t2, NodeKind::crossing});
        if (dt >= kCuspLoopParam && angle < kLensScanAngle) scan_lens(r.t1, r.t2);
      } else {
        ++out.newton_failures;
      }
      continue;
    }
    // Near-tangent branches. First the tangency conditions (tangency_refinement.hpp): branches
    // that meet within the tangency tolerance on them touch. This decides tiny curves (a2, a3 ~
    // 1e-2 near a pole), where the quadratic model below is too coarse to see the touching.
    {
      const TangencyPair tp = refine_tangency_pair(train, r.t1, r.t2);
      out.work.points_evaluated += tp.points_evaluated;
      if (tp.moved && tp.gap <= gap_tol && distinct_branches(tp.t1, tp.t2)) {
        meetings.push_back({tp.t1, tp.t2, NodeKind::tangency});
        continue;
      }
    }
    // Otherwise a quadratic model of the gap along branch 2.
    const LD speed2 = v2.norm();
    const LD hs = 1e-3L / std::max<LD>(speed2, 1e-3L);
    const LD g0 = detail::branch_gap(curve_ld, r.t1, r.t2, 0, out.work);
    const LD gp = detail::branch_gap(curve_ld, r.t1, r.t2, hs, out.work);
    const LD gm = detail::branch_gap(curve_ld, r.t1, r.t2, -hs, out.work);
    const LD c0 = g0, c1 = (gp - gm) / (2 * hs), c2 = (gp - 2 * g0 + gm) / (2 * hs * hs);
    if (c2 == 0) {
      if (r.residual <= kNodeResidual) meetings.push_back({r.t1, r.t2, NodeKind::crossing});
      continue;
    }
    const LD s_star = -c1 / (2 * c2);
    const LD gap_min = c0 - c1 * c1 / (4 * c2);
    if (std::abs(gap_min) <= gap_tol) {
      LD t1s;
      detail::branch_gap(curve_ld, r.t1, r.t2, s_star, out.work, &t1s);
      if (distinct_branches(t1s, r.t2 + s_star)) {
        // Onto the tangency conditions (well conditioned; tangency_refinement.hpp).
        const TangencyPair tp = refine_tangency_pair(train, t1s, r.t2 + s_star);
        out.work.points_evaluated += tp.points_evaluated;
        meetings.push_back({tp.t1, tp.t2, NodeKind::tangency});
      }
      continue;
    }
    const LD disc = c1 * c1 - 4 * c0 * c2;
    if (disc < 0) continue;  // a near miss, not a node
    for (LD sgn : {-1.0L, 1.0L}) {
      const LD s = (-c1 + sgn * std::sqrt(disc)) / (2 * c2);
      // The quadratic model holds near s = 0 only; a crossing farther away has its own seed.
      if (!(std::abs(s) <= 4 * static_cast<LD>(h))) continue;
      LD t1s;
      detail::branch_gap(curve_ld, r.t1, r.t2, s, out.work, &t1s);
      const auto rr = refine(t1s, r.t2 + s);
      if (rr.status != RefineStatus::left_bracket && rr.residual <= kNodeResidual && distinct_branches(rr.t1, rr.t2))
        meetings.push_back({rr.t1, rr.t2, NodeKind::crossing});
    }
  }

  // Deduplicate (unordered pairs modulo the period) and assemble.
  const LD P = period;
  auto wrap = [&](LD t) {
    LD r = std::fmod(t, P);
    if (r < 0) r += P;
    return r;
  };
  auto close = [&](LD a, LD b) {
    const LD d = std::abs(wrap(a) - wrap(b));
    return std::min(d, P - d) <= 1e-10L;
  };
  // Canonical order (t1 <= t2 after wrapping), sorted: duplicates become neighbours in t1.
  for (auto& mt : meetings) {
    mt.t1 = wrap(mt.t1);
    mt.t2 = wrap(mt.t2);
    if (mt.t2 < mt.t1) std::swap(mt.t1, mt.t2);
  }
  std::sort(meetings.begin(), meetings.end(), [](const Meeting& a, const Meeting& b) { return a.t1 < b.t1; });
  std::vector<Meeting> unique;
  for (std::size_t a = 0; a < meetings.size(); ++a) {
    bool dup = false;
    // Look back over the meetings whose t1 is within the tolerance (and across the wrap).
    for (std::size_t b = unique.size(); b-- > 0 && !dup;) {
      if (meetings[a].t1 - unique[b].t1 > 1e-10L && unique[b].t1 > 1e-10L) break;
      dup = (close(unique[b].t1, meetings[a].t1) && close(unique[b].t2, meetings[a].t2));
    }
    for (std::size_t b = 0; b < unique.size() && !dup && unique[b].t1 <= 1e-10L; ++b)
      dup = (close(unique[b].t1, meetings[a].t2) && close(unique[b].t2, meetings[a].t1)) ||
            (close(unique[b].t1, meetings[a].t1) && close(unique[b].t2, meetings[a].t2));
    if (!dup) unique.push_back(meetings[a]);
  }
  for (const auto& u : unique) {
    BranchPair bp;
    bp.t1 = wrap_param(static_cast<double>(wrap(u.t1)), period);
    bp.t2 = wrap_param(static_cast<double>(wrap(u.t2)), period);
    if (bp.t2 < bp.t1) std::swap(bp.t1, bp.t2);
    bp.position = ((curve_ld.point(u.t1) + curve_ld.point(u.t2)) / 2).normalized().cast<double>();
    out.work.points_evaluated += 2;
    bp.kind = u.kind;
    out.pairs.push_back(bp);
  }
  out.nodes = assemble_nodes(out.pairs, curve);
  out.work.points_evaluated += assembly_evaluations(out.nodes);
  return out;
}

}  // namespace sphtroch
