// sphtroch/polyline_crossings.hpp — the exact self-crossings of a spherical polyline.
//
// What it is for: given the vertices of a polyline on the sphere (edges are great-circle arcs),
// list every pair of non-adjacent edges that cross, and separately every pair that only touches
// or overlaps, exactly for the double vertices as given (arc_predicates.hpp). Candidate pairs
// come from an O(N log N + K) box search (CGAL::box_self_intersection_d), never from all pairs.
// Usable on any spherical polyline, not only on trajectories.
//
//   #include <sphtroch/polyline_crossings.hpp>   // needs the sphtroch::exact target (CGAL)
//   sphtroch::TracerCurve<double> curve(train);
//   auto tr = sphtroch::sample_period(curve, 100000);
//   sphtroch::SelfCrossings sc = sphtroch::find_self_crossings(tr.points, /*closed=*/true);
//   for (const sphtroch::EdgePair& e : sc.crossings) { /* edges e.i < e.j cross */ }
//
//   // near misses: every pair of non-adjacent edges closer than 1e-6 (and maybe a few more)
//   sphtroch::visit_close_edge_pairs(tr.points, true, 1e-6, [&](std::size_t i, std::size_t j) {
//     ...; return true;   // false stops the visit
//   });
//
// The polyline: vertices v_0 .. v_{n-1} (directions: need not be normalised); edge e joins v_e to
// v_{e+1}, and when `closed` edge n-1 joins v_{n-1} to v_0. Edges i and j are adjacent when they
// share a polyline vertex: |i - j| = 1, or {0, n-1} when closed. Adjacent pairs are never reported.
//
// API, with contracts:
//
//   void validate_spherical_polyline(vertices, closed)
//     Throws sphtroch::InvalidInput with field "vertices" (the value names the index) when: fewer
//     than 3 vertices (closed) or 2 (open); a vertex has a NaN or infinite coordinate, or is the
//     zero vector; two consecutive vertices (including v_{n-1}, v_0 when closed) are the same
//     direction or antipodal, decided exactly. After it passes, every edge is an arc shorter than pi.
//
//   SelfCrossings find_self_crossings(vertices, closed, CrossingSearchOptions options = {})
//     crossings: every pair {i < j} of non-adjacent edges whose arcs cross (ArcContact::crossing);
//     touchings: every pair that touches or overlaps (kind ArcContact::touching or ::overlap);
//     both sorted by (i, j). Exactly equal to exact_brute_force_crossings (tested pair for pair).
//     Work counters: candidate pairs tested exactly, exact predicates evaluated, boxes searched.
//     REQUIRES: validate_spherical_polyline passes (it is called; throws InvalidInput);
//     options.margin finite and >= 0 (throws InvalidInput field "margin").
//
//   bool visit_close_edge_pairs(vertices, closed, margin, visitor, search = CandidateSearch::runs)
//     Calls visitor(i, j), i < j, once for every pair of non-adjacent edges whose axis-aligned
//     boxes, each inflated by `margin`, overlap. Guarantee: every pair of edges whose arcs (on the
//     unit sphere) come within chordal distance `margin` of each other is visited, in particular
//     every pair that meets; pairs farther apart may be visited too. Order unspecified.
//     The visitor returns bool (false stops the visit) or void. Returns false iff it was stopped.
//     REQUIRES: as find_self_crossings; margin finite and >= 0.
//
//   SelfCrossings exact_brute_force_crossings(vertices, closed)
//     The O(N^2) reference: every non-adjacent pair classified. For tests and small inputs.
//
//   ArcBox arc_bounding_box(a, b, margin = 0)
//     An axis-aligned box that provably contains the arc from a/|a| to b/|b| on the unit sphere,
//     inflated by margin. REQUIRES a, b finite, nonzero, not the same direction, not antipodal.
//
// The box bound (the sagitta bound). Let u, v be unit vectors at angle theta < pi, h = theta/2,
// c = |u - v| = 2 sin h the chord. In the plane of the arc take the unit bisector m and the unit
// chord direction t: u = cos h m - sin h t, v = cos h m + sin h t, and an arc point is
// p = cos phi m + sin phi t with |phi| <= h. The point q = cos h m + sin phi t lies on the chord
// segment [u, v] (its t-coordinate is within +-sin h), so q is in the box of {u, v}; and
// p - q = (cos phi - cos h) m with 0 <= cos phi - cos h <= 1 - cos h. Hence every coordinate of p
// is within the sagitta s = 1 - cos h of the box of the two endpoints. Without trigonometry:
// s = sin^2 h / (1 + cos h) <= sin^2 h = c^2 / 4 (cos h >= 0 as h < pi/2): we use s <= c^2/4,
// at most twice the true sagitta (which is about c^2/8 for short arcs, a negligible padding).
// A run of consecutive arcs is contained in the box of all its vertices padded by the largest
// sagitta of its arcs, as the union of the per-arc boxes is.
//
// Rounding (kArcBoxRoundingMargin): boxes are computed in double from the normalised vertices.
// With eps = DBL_EPSILON: each normalised coordinate (scale by the largest |component|, divide by
// the norm) is within 4 eps of the exact unit vector's; so the endpoint box moves by <= 4 eps; the
// exact chord exceeds the computed one by <= 2 * sqrt(3) * 4 eps < 14 eps, which raises c^2/4
// (c <= 2) by <= 14 eps, and computing c^2/4 itself errs by <= 4 eps; forming the pad S + margin
// and lo = min - pad, hi = max + pad adds <= 3 eps. Total < 25 eps; we pad by 64 eps (1.4e-14).
//
// The candidate search (CandidateSearch::runs, the default). Split the polyline into runs of
// consecutive edges along which every coordinate of the (normalised) vertices is monotone, at
// most options.max_run_edges edges each. Box each run (its vertices' box padded by its largest
// sagitta), and find overlapping runs with CGAL::box_self_intersection_d (CLOSED boxes). Within
// one run and within each overlapping pair of runs, the edges' intervals along one axis are
// already sorted (monotone coordinates: the lower ends are sorted in index order, or reversed),
// so the overlapping edge pairs are found by merging the two sorted interval lists in
// O(L_a + L_b + overlaps), then checked on the other two axes; exact predicates only on the
// survivors. An edge's box uses its run's largest sagitta, so edge boxes lie inside run boxes and
// no pair is lost. CandidateSearch::edges boxes every edge separately (the simple first version,
// kept for comparison and tests).
// CAVEAT: adjacent edges are skipped even if one folds back along the other (an exact 180-degree
// turn at a vertex, which makes the two edges overlap); such a polyline is not rejected either.
//
// Implementation details follow.
#pragma once

#include "sphtroch/arc_predicates.hpp"
#include "sphtroch/errors.hpp"

#include <CGAL/box_intersection_d.h>
#include <Eigen/Core>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace sphtroch {

/// Absolute padding added to every box for the rounding of its computation (derivation above).
constexpr double kArcBoxRoundingMargin = 64 * DBL_EPSILON;

/// Default number of edges in one run of the candidate search.
constexpr std::size_t kDefaultMaxRunEdges = 32;

/// Two edges of a polyline, i < j, and how their arcs meet.
struct EdgePair {
  std::size_t i = 0;
  std::size_t j = 0;
  ArcContact kind = ArcContact::none;
};

inline bool operator==(const EdgePair& x, const EdgePair& y) { return x.i == y.i && x.j == y.j && x.kind == y.kind; }
inline bool operator!=(const EdgePair& x, const EdgePair& y) { return !(x == y); }
inline bool operator<(const EdgePair& x, const EdgePair& y) { return x.i != y.i ? x.i < y.i : x.j < y.j; }

/// How candidate pairs are found.
enum class CandidateSearch {
  runs,   // boxes around monotone runs of edges, then a sorted merge inside run pairs (default)
  edges,  // one box per edge
};

struct CrossingSearchOptions {
  double margin = 0.0;  // every box inflated by this distance; changes only the work, not the result
  CandidateSearch search = CandidateSearch::runs;
  std::size_t max_run_edges = kDefaultMaxRunEdges;  // >= 1
};

struct SelfCrossings {
  std::vector<EdgePair> crossings;  // kind == crossing, sorted by (i, j)
  std::vector<EdgePair> touchings;  // kind == touching or overlap, sorted by (i, j)
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t boxes = 0;            // boxes given to box_self_intersection_d (0 for brute force)
  std::size_t candidate_pairs = 0;  // non-adjacent edge pairs tested with exact predicates
  std::size_t predicates = 0;       // exact predicates evaluated by those tests
};

/// An axis-aligned box.
struct ArcBox {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Zero();
  bool contains(const Eigen::Vector3d& p) const {
    return lo.x() <= p.x() && p.x() <= hi.x() && lo.y() <= p.y() && p.y() <= hi.y() && lo.z() <= p.z() &&
           p.z() <= hi.z();
  }
  bool overlaps(const ArcBox& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y() &&
           lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
  }
};

namespace detail {

/// v / |v| without overflow or underflow in the norm: scale by the largest |component| first.
inline Eigen::Vector3d normalised_direction(const Eigen::Vector3d& v) {
  const double m = std::max({std::fabs(v.x()), std::fabs(v.y()), std::fabs(v.z())});
  const Eigen::Vector3d w = v / m;
  return w / w.norm();
}

/// Upper bound c^2/4 on the sagitta of the arc between unit vectors u and v.
inline double sagitta_bound(const Eigen::Vector3d& u, const Eigen::Vector3d& v) { return 0.25 * (u - v).squaredNorm(); }

inline std::string vertex_text(const std::vector<Eigen::Vector3d>& vs, std::size_t i) {
  const Eigen::Vector3d& v = vs[i];
  return "index " + std::to_string(i) + ": (" + to_text(v.x()) + ", " + to_text(v.y()) + ", " + to_text(v.z()) + ")";
}

inline void validate_margin(double margin) {
  if (!(std::isfinite(margin) && margin >= 0.0))
    throw InvalidInput("margin", to_text(margin), "not a finite non-negative distance", "[0, inf)");
}

/// The polyline prepared for the box search: unit vectors and the edge count.
struct PreparedPolyline {
  std::vector<Eigen::Vector3d> unit;
  std::size_t n = 0;
  std::size_t edges = 0;
  bool closed = true;
  std::size_t head(std::size_t e) const { return e + 1 == n ? 0 : e + 1; }
  bool adjacent(std::size_t i, std::size_t j) const {  // REQUIRES i < j
    return j == i + 1 || (closed && i == 0 && j + 1 == n);
  }
};

inline PreparedPolyline prepare(const std::vector<Eigen::Vector3d>& vertices, bool closed) {
  PreparedPolyline p;
  p.n = vertices.size();
  p.closed = closed;
  p.edges = closed ? p.n : p.n - 1;
  p.unit.resize(p.n);
  for (std::size_t i = 0; i < p.n; ++i) p.unit[i] = normalised_direction(vertices[i]);
  return p;
}

/// A run of consecutive edges [first, first + count) with monotone vertex coordinates.
struct Run {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  std::int8_t dir[3] = {0, 0, 0};  // +1 nondecreasing, -1 nonincreasing, 0 constant
  double pad = 0.0;                // largest sagitta + rounding margin + user margin
  double lo[3] = {0, 0, 0};        // the run box, padded
  double hi[3] = {0, 0, 0};
};

inline std::vector<Run> build_runs(const PreparedPolyline& p, double margin, std::size_t max_edges) {
  std::vector<Run> runs;
  runs.reserve(p.edges / std::max<std::size_t>(1, max_edges / 4) + 1);
  std::size_t e = 0;
  while (e < p.edges) {
    Run r;
    r.first = static_cast<std::uint32_t>(e);
    double vlo[3], vhi[3];
    const Eigen::Vector3d& u0 = p.unit[e];
    for (int k = 0; k < 3; ++k) vlo[k] = vhi[k] = u0[k];
    double sag = 0.0;
    for (; e < p.edges && r.count < max_edges; ++e) {
      const Eigen::Vector3d& a = p.unit[e];
      const Eigen::Vector3d& b = p.unit[p.head(e)];
      std::int8_t d[3];
      bool fits = true;
      for (int k = 0; k < 3; ++k) {
        d[k] = static_cast<std::int8_t>((b[k] > a[k]) - (b[k] < a[k]));
        if (d[k] != 0 && r.dir[k] != 0 && d[k] != r.dir[k]) fits = false;
      }
      if (!fits) break;
      for (int k = 0; k < 3; ++k) {
        if (d[k] != 0) r.dir[k] = d[k];
        vlo[k] = std::min(vlo[k], b[k]);
        vhi[k] = std::max(vhi[k], b[k]);
      }
      sag = std::max(sag, sagitta_bound(a, b));
      ++r.count;
    }
    r.pad = sag + kArcBoxRoundingMargin + margin;
    for (int k = 0; k < 3; ++k) {
      r.lo[k] = vlo[k] - r.pad;
      r.hi[k] = vhi[k] + r.pad;
    }
    runs.push_back(r);
  }
  return runs;
}

/// One edge's interval along one axis, padded with its run's pad.
struct EdgeInterval {
  double lo;
  double hi;
  std::uint32_t edge;
};

/// The run's edge intervals along axis k, sorted by lower end (by monotonicity: index order or
/// reversed; rounding is monotone, so the computed lower ends are sorted too).
inline void sorted_intervals(const PreparedPolyline& p, const Run& r, int k, std::vector<EdgeInterval>& out) {
  out.clear();
  const auto push = [&](std::uint32_t e) {
    const double a = p.unit[e][k];
    const double b = p.unit[p.head(e)][k];
    out.push_back({std::min(a, b) - r.pad, std::max(a, b) + r.pad, e});
  };
  if (r.dir[k] >= 0) {
    for (std::uint32_t e = r.first; e < r.first + r.count; ++e) push(e);
  } else {
    for (std::uint32_t e = r.first + r.count; e-- > r.first;) push(e);
  }
}

/// Whether edges e (pad pe) and f (pad pf) overlap on axis k.
inline bool overlap_on_axis(const PreparedPolyline& p, std::uint32_t e, double pe, std::uint32_t f, double pf, int k) {
  const double e0 = p.unit[e][k], e1 = p.unit[p.head(e)][k];
  const double f0 = p.unit[f][k], f1 = p.unit[p.head(f)][k];
  return std::min(e0, e1) - pe <= std::max(f0, f1) + pf && std::min(f0, f1) - pf <= std::max(e0, e1) + pe;
}

/// Calls the visitor; converts a void visitor to "continue".
template <typename Visitor>
bool call_visitor(Visitor& visitor, std::size_t i, std::size_t j) {
  if constexpr (std::is_void_v<decltype(visitor(i, j))>) {
    visitor(i, j);
    return true;
  } else {
    return static_cast<bool>(visitor(i, j));
  }
}

/// Reports a candidate (after the other two axes and adjacency). Returns false to stop.
template <typename Visitor>
bool offer_pair(const PreparedPolyline& p, std::uint32_t e, double pe, std::uint32_t f, double pf, int sweep_axis,
                Visitor& visitor) {
  for (int k = 0; k < 3; ++k)
    if (k != sweep_axis && !overlap_on_axis(p, e, pe, f, pf, k)) return true;
  const std::size_t i = std::min(e, f), j = std::max(e, f);
  if (i == j || p.adjacent(i, j)) return true;
  return call_visitor(visitor, i, j);
}

inline int longest_axis(const Run& a, const Run& b) {
  int best = 0;
  double best_len = -1.0;
  for (int k = 0; k < 3; ++k) {
    const double len = (a.hi[k] - a.lo[k]) + (b.hi[k] - b.lo[k]);
    if (len > best_len) {
      best_len = len;
      best = k;
    }
  }
  return best;
}

/// Edge pairs inside one run. Returns false if the visitor stopped.
template <typename Visitor>
bool visit_within_run(const PreparedPolyline& p, const Run& r, std::vector<EdgeInterval>& buf, Visitor& visitor) {
  if (r.count < 3) return true;  // fewer than 3 consecutive edges: every pair adjacent
  const int k = longest_axis(r, r);
  sorted_intervals(p, r, k, buf);
  for (std::size_t x = 0; x < buf.size(); ++x)
    for (std::size_t y = x + 1; y < buf.size() && buf[y].lo <= buf[x].hi; ++y)
      if (!offer_pair(p, buf[x].edge, r.pad, buf[y].edge, r.pad, k, visitor)) return false;
  return true;
}

/// Edge pairs between two different runs: merge of two sorted interval lists along one axis.
template <typename Visitor>
bool visit_between_runs(const PreparedPolyline& p, const Run& ra, const Run& rb, std::vector<EdgeInterval>& la,
                        std::vector<EdgeInterval>& lb, Visitor& visitor) {
  const int k = longest_axis(ra, rb);
  sorted_intervals(p, ra, k, la);
  sorted_intervals(p, rb, k, lb);
  std::size_t i = 0, j = 0;
  while (i < la.size() && j < lb.size()) {
    if (la[i].lo <= lb[j].lo) {
      for (std::size_t y = j; y < lb.size() && lb[y].lo <= la[i].hi; ++y)
        if (!offer_pair(p, la[i].edge, ra.pad, lb[y].edge, rb.pad, k, visitor)) return false;
      ++i;
    } else {
      for (std::size_t x = i; x < la.size() && la[x].lo <= lb[j].hi; ++x)
        if (!offer_pair(p, la[x].edge, ra.pad, lb[j].edge, rb.pad, k, visitor)) return false;
      ++j;
    }
  }
  return true;
}

using SearchBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t>;

struct VisitStats {
  bool completed = true;
  std::size_t boxes = 0;
};

template <typename Visitor>
VisitStats visit_runs(const PreparedPolyline& p, double margin, std::size_t max_run_edges, Visitor& visitor) {
  VisitStats stats;
  const std::vector<Run> runs = build_runs(p, margin, max_run_edges);
  std::vector<SearchBox> boxes;
  boxes.reserve(runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) {
    double lo[3] = {runs[r].lo[0], runs[r].lo[1], runs[r].lo[2]};
    double hi[3] = {runs[r].hi[0], runs[r].hi[1], runs[r].hi[2]};
    boxes.emplace_back(lo, hi, static_cast<std::uint32_t>(r));
  }
  stats.boxes = boxes.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> run_pairs;
  run_pairs.reserve(2 * runs.size());
  CGAL::box_self_intersection_d(
      boxes.begin(), boxes.end(),
      [&run_pairs](const SearchBox& a, const SearchBox& b) {
        run_pairs.emplace_back(std::min(a.info(), b.info()), std::max(a.info(), b.info()));
      },
      std::ptrdiff_t(10), CGAL::Box_intersection_d::CLOSED);
  std::sort(run_pairs.begin(), run_pairs.end());  // locality and a deterministic visiting order
  std::vector<EdgeInterval> la, lb;
  la.reserve(max_run_edges);
  lb.reserve(max_run_edges);
  std::size_t next_pair = 0;
  for (std::uint32_t r = 0; r < runs.size(); ++r) {
    if (!visit_within_run(p, runs[r], la, visitor)) return {false, stats.boxes};
    for (; next_pair < run_pairs.size() && run_pairs[next_pair].first == r; ++next_pair) {
      if (!visit_between_runs(p, runs[r], runs[run_pairs[next_pair].second], la, lb, visitor))
        return {false, stats.boxes};
    }
  }
  return stats;
}

template <typename Visitor>
VisitStats visit_edges(const PreparedPolyline& p, double margin, Visitor& visitor) {
  VisitStats stats;
  std::vector<SearchBox> boxes;
  boxes.reserve(p.edges);
  for (std::size_t e = 0; e < p.edges; ++e) {
    const Eigen::Vector3d& a = p.unit[e];
    const Eigen::Vector3d& b = p.unit[p.head(e)];
    const double pad = sagitta_bound(a, b) + kArcBoxRoundingMargin + margin;
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(a[k], b[k]) - pad;
      hi[k] = std::max(a[k], b[k]) + pad;
    }
    boxes.emplace_back(lo, hi, static_cast<std::uint32_t>(e));
  }
  stats.boxes = boxes.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  CGAL::box_self_intersection_d(
      boxes.begin(), boxes.end(),
      [&pairs, &p](const SearchBox& a, const SearchBox& b) {
        const std::uint32_t i = std::min(a.info(), b.info()), j = std::max(a.info(), b.info());
        if (!p.adjacent(i, j)) pairs.emplace_back(i, j);
      },
      std::ptrdiff_t(10), CGAL::Box_intersection_d::CLOSED);
  std::sort(pairs.begin(), pairs.end());
  for (const auto& ij : pairs)
    if (!call_visitor(visitor, ij.first, ij.second)) return {false, stats.boxes};
  return stats;
}

template <typename Visitor>
VisitStats visit_prepared(const PreparedPolyline& p, double margin, CandidateSearch search, std::size_t max_run_edges,
                          Visitor& visitor) {
  if (search == CandidateSearch::edges) return visit_edges(p, margin, visitor);
  return visit_runs(p, margin, std::max<std::size_t>(1, max_run_edges), visitor);
}

inline void record_contact(SelfCrossings& out, std::size_t i, std::size_t j, ArcContact kind) {
  if (kind == ArcContact::crossing) out.crossings.push_back({i, j, kind});
  else if (kind != ArcContact::none) out.touchings.push_back({i, j, kind});
}

}  // namespace detail

/// Throws InvalidInput (field "vertices") unless the polyline is a valid spherical polyline.
inline void validate_spherical_polyline(const std::vector<Eigen::Vector3d>& vertices, bool closed) {
  const std::size_t min_n = closed ? 3 : 2;
  if (vertices.size() < min_n)
    throw InvalidInput("vertices", std::to_string(vertices.size()) + " vertices", "too few vertices",
                       std::string("at least ") + (closed ? "3 for a closed" : "2 for an open") + " polyline");
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!detail::finite_nonzero(vertices[i]))
      throw InvalidInput("vertices", detail::vertex_text(vertices, i), "not a finite nonzero vector",
                         "finite coordinates, not all zero (a direction from the sphere centre)");
  }
  const std::size_t n = vertices.size();
  const std::size_t edges = closed ? n : n - 1;
  for (std::size_t e = 0; e < edges; ++e) {
    const std::size_t h = e + 1 == n ? 0 : e + 1;
    const VertexRelation rel = relate_vertices(vertices[e], vertices[h]);
    if (rel == VertexRelation::distinct) continue;
    throw InvalidInput("vertices", detail::vertex_text(vertices, e),
                       std::string(rel == VertexRelation::same_direction ? "the same point as" : "antipodal to") +
                           " the next vertex (index " + std::to_string(h) + ")" +
                           (rel == VertexRelation::same_direction && h == 0 && closed
                                ? "; a closed polyline lists each vertex once"
                                : ""),
                       "consecutive vertices distinct and not antipodal (each edge a great-circle arc shorter than pi)");
  }
}

/// Visits every pair of non-adjacent edges whose boxes, inflated by margin, overlap (see top).
template <typename Visitor>
bool visit_close_edge_pairs(const std::vector<Eigen::Vector3d>& vertices, bool closed, double margin,
                            Visitor&& visitor, CandidateSearch search = CandidateSearch::runs) {
  detail::validate_margin(margin);
  validate_spherical_polyline(vertices, closed);
  const detail::PreparedPolyline p = detail::prepare(vertices, closed);
  return detail::visit_prepared(p, margin, search, kDefaultMaxRunEdges, visitor).completed;
}

/// Every crossing and touching pair of non-adjacent edges, exactly (see top).
inline SelfCrossings find_self_crossings(const std::vector<Eigen::Vector3d>& vertices, bool closed,
                                         const CrossingSearchOptions& options = {}) {
  detail::validate_margin(options.margin);
  validate_spherical_polyline(vertices, closed);
  const detail::PreparedPolyline p = detail::prepare(vertices, closed);
  SelfCrossings out;
  out.vertices = p.n;
  out.edges = p.edges;
  auto visitor = [&](std::size_t i, std::size_t j) {
    ++out.candidate_pairs;
    const ArcContact kind = detail::classify_arcs_unchecked(vertices[i], vertices[p.head(i)], vertices[j],
                                                            vertices[p.head(j)], &out.predicates);
    detail::record_contact(out, i, j, kind);
    return true;
  };
  out.boxes = detail::visit_prepared(p, options.margin, options.search, options.max_run_edges, visitor).boxes;
  std::sort(out.crossings.begin(), out.crossings.end());
  std::sort(out.touchings.begin(), out.touchings.end());
  return out;
}

/// The O(N^2) reference: every pair of non-adjacent edges classified exactly.
inline SelfCrossings exact_brute_force_crossings(const std::vector<Eigen::Vector3d>& vertices, bool closed) {
  validate_spherical_polyline(vertices, closed);
  const std::size_t n = vertices.size();
  SelfCrossings out;
  out.vertices = n;
  out.edges = closed ? n : n - 1;
  const auto head = [n](std::size_t e) { return e + 1 == n ? std::size_t(0) : e + 1; };
  for (std::size_t i = 0; i < out.edges; ++i) {
    for (std::size_t j = i + 2; j < out.edges; ++j) {
      if (closed && i == 0 && j + 1 == n) continue;  // edges n-1 and 0 share vertex 0
      ++out.candidate_pairs;
      detail::record_contact(out, i, j,
                             detail::classify_arcs_unchecked(vertices[i], vertices[head(i)], vertices[j],
                                                             vertices[head(j)], &out.predicates));
    }
  }
  return out;
}

/// A box containing the arc from a/|a| to b/|b|, inflated by margin (see the sagitta bound above).
/// REQUIRES a, b finite, nonzero, neither the same direction nor antipodal (checked); margin >= 0.
inline ArcBox arc_bounding_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double margin = 0.0) {
  SPHTROCH_ASSERT(relate_vertices(a, b) == VertexRelation::distinct, "arc endpoints equal or antipodal");
  const Eigen::Vector3d u = detail::normalised_direction(a);
  const Eigen::Vector3d v = detail::normalised_direction(b);
  const double pad = detail::sagitta_bound(u, v) + kArcBoxRoundingMargin + margin;
  ArcBox box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = std::min(u[k], v[k]) - pad;
    box.hi[k] = std::max(u[k], v[k]) + pad;
  }
  return box;
}

}  // namespace sphtroch
