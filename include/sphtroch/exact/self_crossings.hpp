// sphtroch/exact/self_crossings.hpp — the exact self-crossings of a spherical polyline.
//
// What it is for: given the vertices of a polyline on the sphere (edges are great-circle arcs),
// list every pair of non-adjacent edges that cross, and separately every pair that only touches
// or overlaps, exactly for the double vertices as given (arc_predicates.hpp). Candidate pairs
// come from an O(N log N + K) box intersection (CGAL::box_self_intersection_d), never from all pairs.
// Usable on any spherical polyline, not only on trajectories.
//
//   #include <sphtroch/exact/self_crossings.hpp>   // needs the sphtroch::exact target (CGAL)
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
// The polyline: vertices v_0 .. v_{n-1} (directions: need not be normalised; find_self_crossings also
// takes a VertexSpan, a pointer and a count viewing packed x,y,z doubles without a copy); edge e joins v_e to
// v_{e+1}, and when `closed` edge n-1 joins v_{n-1} to v_0. Edges i and j are adjacent when they
// share a polyline vertex: |i - j| = 1, or {0, n-1} when closed. Adjacent pairs are never reported.
//
// API, with contracts:
//
//   void validate_spherical_polyline(vertices, closed)
//     Throws sphtroch::InvalidInput with field "vertices" (the value names the index) when: fewer
//     than 3 vertices (closed) or 2 (open), or 2^32 - 1 or more; a vertex has a NaN or infinite
//     coordinate, or is the zero vector; two consecutive vertices (including v_{n-1}, v_0 when
//     closed) are the same direction or antipodal, decided exactly. After it passes, every edge is
//     an arc shorter than pi. Cost: O(N), an exact predicate only where a float filter is unsure.
//
//   SelfCrossings find_self_crossings(vertices, closed, CrossingSearchOptions options = {})
//     crossings: every pair {i < j} of non-adjacent edges whose arcs cross (ArcContact::crossing);
//     touchings: every pair that touches or overlaps (kind ArcContact::touching or ::overlap);
//     both sorted by (i, j). Exactly equal to exact_brute_force_crossings (tested pair for pair).
//     Work counters: candidate pairs tested exactly, exact predicates evaluated, boxes searched.
//     Memory O(N + pairs found): random vertices have Theta(N^2) crossings; use the limits below,
//     or count_self_crossings / visit_self_crossings.
//     REQUIRES: validate_spherical_polyline passes (it is called; throws InvalidInput);
//     options.margin finite and >= 0 (throws InvalidInput field "margin"); the vertices do not
//     change during the call (they are read in place; validation does not hold otherwise).
//
//   CrossingCounts count_self_crossings(vertices, closed, options = {})
//   CrossingCounts visit_self_crossings(vertices, closed, visitor, options = {})
//     The same search without storing pairs: counts only, or visitor(const EdgePair&) per
//     crossing / touching / overlap (in the search's deterministic order, not sorted). Memory
//     O(N): boxes of runs, and overlapping box pairs in sorted chunks of kPairChunk.
//     Limits (also for find_self_crossings): the search stops, with `stop` saying why, when the
//     contacts found (crossings + touchings) would exceed options.max_contacts (then
//     max_contacts + 1 are counted), or the work, candidate_pairs + box_pairs, options.max_work.
//     Time: O(N log N + work) (each unit of work costs at most one exact arc test, or one
//     box-pair test over at most 2 max_run_edges edges). With a finite max_work, a search
//     whose run-box pairs alone are estimated (sampled, O(N log N + 2^24)) above 2 max_work is
//     refused before it starts (stop = SearchStop::estimate, estimated_box_pairs).
//
//   bool visit_close_edge_pairs(vertices, closed, margin, visitor, search = CandidateSearch::runs)
//     Calls visitor(i, j), i < j, once for every pair of non-adjacent edges whose axis-aligned
//     boxes (which contain the arcs, see below), each inflated by `margin`, overlap. Guarantee: every pair of edges whose arcs (on the
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
//     inflated by margin. REQUIRES a, b finite, nonzero, not the same direction, not antipodal
//     (else InvalidInput, field "vertices").
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
// Rounding (kArcBoxRoundingMargin): boxes are computed in double from unit vectors: the vertices
// themselves when |fl(|v|^2) - 1| <= kUnitNormTolerance = 8 eps (then ||v| - 1| <= 5 eps), else
// normalised copies (scale by the largest |component|, divide by the norm: within 4 eps). With
// eps = DBL_EPSILON: each coordinate is within 5 eps of the exact unit vector's, so the endpoint
// box moves by <= 5 eps; the exact chord exceeds the computed one by <= 2 sqrt(3) 5 eps < 18 eps,
// which raises c^2/4 (c <= 2) by <= 18 eps; computing c^2/4 itself errs by <= 4 eps; forming the
// pad S + margin and lo = min - pad, hi = max + pad adds <= 3 eps. Total < 30 eps; we pad by
// 64 eps (1.4e-14).
//
// The candidate search (CandidateSearch::runs, the default). Split the polyline into runs of
// consecutive edges along which every coordinate of the (unit) vertices is monotone, with at most
// options.max_run_edges edges and an unpadded box at most options.max_run_extent wide. Box each
// run (its vertices' box padded by its largest sagitta), and find overlapping runs with
// CGAL::box_self_intersection_d (CLOSED boxes), or, for at most kSweepMaxBoxes runs, with a
// plain sweep that reports the same pairs (at about a quarter of the cost of that step). An
// edge's box uses its run's pad, so edge boxes lie inside run boxes and no pair is lost. Then,
// with exact predicates only on the survivors:
//   - within a run: nothing to do when every edge steps by more than 2.25 pad along some axis
//     (the edge between two non-adjacent edges of a monotone run separates their boxes); else a
//     sweep over the edges' intervals along one axis, sorted by construction (monotone
//     coordinates: lower ends in index order, or reversed);
//   - consecutive runs (sharing one vertex v): if both are monotone the same way along some axis
//     k, one run ends at v_k and the other starts there, so only the few edges within
//     pad_a + pad_b of v_k along k can overlap: a walk outwards from v. Otherwise as below;
//   - other overlapping run pairs: keep the edges of each run whose boxes meet the other run's
//     box (none, often); pair few survivors directly, else merge their sorted interval lists
//     along one axis in O(L_a + L_b + overlaps); then check the other two axes.
// The visited set is exactly the set of non-adjacent pairs whose (run-padded) edge boxes overlap;
// the work is O(N) plus O(R log R + K_runs) for the box intersection over R runs, plus the merges.
// CandidateSearch::edges boxes every edge separately (the simple first version, kept for
// comparison and tests).
// CAVEAT: adjacent edges are skipped even if one folds back along the other (an exact 180-degree
// turn at a vertex, which makes the two edges overlap); such a polyline is not rejected either.
//
// Implementation details follow.
#pragma once

// Header-only without GMP and MPFR: SPHTROCH_EXACT_WITHOUT_GMP with CGAL_NO_GMP=1 (arc_predicates.hpp).
#if !defined(SPHTROCH_HAVE_EXACT) && \
    !(defined(SPHTROCH_EXACT_WITHOUT_GMP) && defined(CGAL_NO_GMP) && CGAL_NO_GMP)
#error "sphtroch/exact/self_crossings.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself, or (header-only, no GMP or MPFR) define SPHTROCH_EXACT_WITHOUT_GMP and CGAL_NO_GMP=1"
#endif

#include "sphtroch/exact/arc_predicates.hpp"
#include "sphtroch/core/cost_bounds.hpp"  // kDefaultMaxCrossings, kDefaultMaxCrossingWork
#include "sphtroch/core/errors.hpp"

#include <CGAL/box_intersection_d.h>
#include <Eigen/Core>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace sphtroch {

/// Absolute padding added to every box for the rounding of its computation (derivation above).
constexpr double kArcBoxRoundingMargin = 64 * DBL_EPSILON;

/// A vertex v with |fl(|v|^2) - 1| <= kUnitNormTolerance is boxed as it is, without normalising:
/// then ||v| - 1| <= 5 eps, so each coordinate is within 5 eps of v/|v|'s (see the derivation).
constexpr double kUnitNormTolerance = 8 * DBL_EPSILON;

/// Default limits of one run of the candidate search: at most this many edges, and a box at most
/// this wide along every axis (before padding). Tuned on trochoid polylines of 1e4..1e6 vertices
/// with 4 to 14000 crossings (n = 2, 7/3, 13/5, 101/40): the extent limit keeps run boxes small
/// where branches cross densely, the count limit keeps the number of boxes low where they do not.
constexpr std::size_t kDefaultMaxRunEdges = 256;
constexpr double kDefaultMaxRunExtent = 1.0 / 64;
/// A run keeps at least this many edges (when monotone) even beyond max_run_extent: coarse
/// polylines (long edges) then still get a few edges per box, which halved the time at 1e3..1e4
/// vertices on sparse-crossing curves and did not change it measurably on dense ones.
constexpr std::size_t kMinRunEdges = 8;

/// The vertices of a polyline, not owned: a std::vector<Eigen::Vector3d> converts implicitly;
/// (data, size) views any contiguous array of x,y,z doubles (e.g. a NumPy (N, 3) float64 array
/// through Eigen::Vector3d, which is three packed doubles). REQUIRES the array outlives the view.
class VertexSpan {
 public:
  VertexSpan(const std::vector<Eigen::Vector3d>& v) : data_(v.data()), size_(v.size()) {}  // NOLINT: implicit
  VertexSpan(const Eigen::Vector3d* data, std::size_t size) : data_(data), size_(size) {}
  std::size_t size() const noexcept { return size_; }
  const Eigen::Vector3d* data() const noexcept { return data_; }
  const Eigen::Vector3d& operator[](std::size_t i) const { return data_[i]; }
  const Eigen::Vector3d* begin() const noexcept { return data_; }
  const Eigen::Vector3d* end() const noexcept { return data_ + size_; }

 private:
  const Eigen::Vector3d* data_;
  std::size_t size_;
};
static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "VertexSpan views packed x,y,z doubles");

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
  std::size_t max_run_edges = kDefaultMaxRunEdges;  // >= 1 (runs search only)
  double max_run_extent = kDefaultMaxRunExtent;     // > 0; runs shorter than kMinRunEdges may exceed it
  /// Limits (the search stops, result `stopped`, when one would be exceeded): contacts found
  /// (crossings + touchings), and work (candidate_pairs + box_pairs, see CrossingCounts).
  std::size_t max_contacts = std::numeric_limits<std::size_t>::max();
  std::size_t max_work = std::numeric_limits<std::size_t>::max();
};

/// Why a search ended.
enum class SearchStop {
  complete,   // every pair was searched
  contacts,   // more than max_contacts crossings + touchings (max_contacts + 1 were found)
  work,       // more than max_work candidate pairs + box pairs
  estimate,   // refused before the search: about estimated_box_pairs > 2 max_work (see below)
  visitor,    // the visitor returned false
};

/// The counts of a search (count_self_crossings, visit_self_crossings): memory O(N).
struct CrossingCounts {
  std::size_t crossings = 0;
  std::size_t touchings = 0;        // touching or overlap
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t boxes = 0;            // boxes given to the box intersection
  std::size_t box_pairs = 0;        // pairs of overlapping run boxes examined (runs search)
  std::size_t candidate_pairs = 0;  // non-adjacent edge pairs tested with exact predicates
  std::size_t predicates = 0;       // exact predicates evaluated by those tests
  SearchStop stop = SearchStop::complete;
  double estimated_box_pairs = 0;   // the up-front estimate, when one was made (else 0)
  bool complete() const { return stop == SearchStop::complete; }
  std::size_t work() const { return candidate_pairs + box_pairs; }
};

struct SelfCrossings {
  std::vector<EdgePair> crossings;  // kind == crossing, sorted by (i, j)
  std::vector<EdgePair> touchings;  // kind == touching or overlap, sorted by (i, j)
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t boxes = 0;            // boxes given to box_self_intersection_d (0 for brute force)
  std::size_t candidate_pairs = 0;  // non-adjacent edge pairs tested with exact predicates
  std::size_t predicates = 0;       // exact predicates evaluated by those tests
  std::size_t box_pairs = 0;        // as CrossingCounts
  SearchStop stop = SearchStop::complete;  // not complete: the lists hold the pairs found before a limit
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

inline std::string vertex_text(VertexSpan vs, std::size_t i) {
  const Eigen::Vector3d& v = vs[i];
  return "index " + std::to_string(i) + ": (" + number_text(v.x()) + ", " + number_text(v.y()) + ", " + number_text(v.z()) + ")";
}

inline void validate_margin(double margin) {
  if (!(std::isfinite(margin) && margin >= 0.0))
    throw InvalidInput("margin", report_number(margin), "not a finite non-negative distance", "[0, inf)");
}

/// Validates (see validate_spherical_polyline) and returns whether every vertex is already a
/// unit vector within kUnitNormTolerance, so that the boxes may use it without normalising.
inline bool validate_polyline(VertexSpan vertices, bool closed) {
  const std::size_t min_n = closed ? 3 : 2;
  if (vertices.size() < min_n)
    throw InvalidInput("vertices", std::to_string(vertices.size()) + " vertices", "too few vertices",
                       std::string("at least ") + (closed ? "3 for a closed" : "2 for an open") + " polyline");
  if (vertices.size() >= std::numeric_limits<std::uint32_t>::max())
    throw InvalidInput("vertices", std::to_string(vertices.size()) + " vertices", "too many vertices",
                       "fewer than 2^32 - 1");
  // One pass over the vertices (they may be hundreds of MB): each vertex, then the edge that ends
  // at it. A vertex's fault is reported before any edge's, the first edge's before later ones.
  const std::size_t n = vertices.size();
  const std::size_t no_edge = std::numeric_limits<std::size_t>::max();
  std::size_t bad_edge = no_edge;  // the first edge e whose ends coincide or are antipodal
  auto edge_ok = [&](std::size_t e, std::size_t h) {
    return surely_distinct(vertices[e], vertices[h]) || relate_vertices(vertices[e], vertices[h]) == VertexRelation::distinct;
  };
  bool all_unit = true;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& v = vertices[i];
    if (!finite_nonzero(v))
      throw InvalidInput("vertices", vertex_text(vertices, i), "not a finite nonzero vector",
                         "finite coordinates, not all zero (a direction from the sphere centre)");
    all_unit = all_unit && std::fabs(v.squaredNorm() - 1.0) <= kUnitNormTolerance;
    if (i > 0 && bad_edge == no_edge && !edge_ok(i - 1, i)) bad_edge = i - 1;
  }
  if (closed && bad_edge == no_edge && !edge_ok(n - 1, 0)) bad_edge = n - 1;
  if (bad_edge == no_edge) return all_unit;
  const std::size_t e = bad_edge, h = e + 1 == n ? 0 : e + 1;
  const bool same = relate_vertices(vertices[e], vertices[h]) == VertexRelation::same_direction;
  throw InvalidInput("vertices", vertex_text(vertices, e),
                     std::string(same ? "the same point as" : "antipodal to") + " the next vertex (index " +
                         std::to_string(h) + ")" +
                         (same && h == 0 && closed ? "; a closed polyline lists each vertex once" : ""),
                     "consecutive vertices distinct and not antipodal (each edge a great-circle arc shorter than pi)");
}

/// The polyline prepared for the box intersection: (nearly) unit vectors and the edge count. Points
/// at the caller's vertices when they are unit within kUnitNormTolerance, else at normalised copies.
class PreparedPolyline {
 public:
  PreparedPolyline(VertexSpan vertices, bool closed, bool all_unit)
      : n(vertices.size()), edges(closed ? vertices.size() : vertices.size() - 1), closed(closed) {
    if (all_unit) {
      pts_ = vertices.data();
    } else {
      storage_.reserve(n);
      for (const Eigen::Vector3d& v : vertices) storage_.push_back(normalised_direction(v));
      pts_ = storage_.data();
    }
  }
  PreparedPolyline(const PreparedPolyline&) = delete;
  PreparedPolyline& operator=(const PreparedPolyline&) = delete;

  const Eigen::Vector3d& u(std::size_t i) const { return pts_[i]; }
  std::size_t head(std::size_t e) const { return e + 1 == n ? 0 : e + 1; }
  bool adjacent(std::size_t i, std::size_t j) const {  // REQUIRES i < j
    return j == i + 1 || (closed && i == 0 && j + 1 == n);
  }

  const std::size_t n;
  const std::size_t edges;
  const bool closed;

 private:
  const Eigen::Vector3d* pts_ = nullptr;
  std::vector<Eigen::Vector3d> storage_;
};

/// A run of consecutive edges [first, first + count) with monotone vertex coordinates.
struct Run {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  std::int8_t dir[3] = {0, 0, 0};  // +1 nondecreasing, -1 nonincreasing, 0 constant
  bool self_free = false;          // no two non-adjacent edges of the run have overlapping boxes
  double pad = 0.0;                // largest sagitta + rounding margin + user margin
  double lo[3] = {0, 0, 0};        // the run box, padded
  double hi[3] = {0, 0, 0};
};

/// Splits the edges into monotone runs of at most max_edges edges and boxes them.
/// self_free: if every edge g of a run moves by more than 2.25 pad along some axis (its largest
/// |step|), then for non-adjacent edges e < f of the run the edge e+1 between them separates
/// their boxes along that axis of e+1 (all coordinates are monotone along the run): the gap is
/// at least that step, more than 2 pad plus the rounding of lo/hi (pad >= 64 eps).
inline std::vector<Run> build_runs(const PreparedPolyline& p, double margin, std::size_t max_edges,
                                   double max_extent) {
  std::vector<Run> runs;
  runs.reserve(p.edges / std::max<std::size_t>(1, std::min(max_edges, kMinRunEdges)) + 1);
  // One pass, branch-light (this loop is most of the O(N) cost of the search). Per run, `moved`
  // collects for each axis k a bit "some edge stepped up" (bit 2k) and "stepped down" (bit 2k+1);
  // an edge that would set both bits of an axis ends the run (coordinates no longer monotone).
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d must be 3 packed doubles");
  const double* const v = p.u(0).data();  // the vertices as 3n contiguous doubles
  std::size_t e = 0;
  while (e < p.edges) {
    Run r;
    r.first = static_cast<std::uint32_t>(e);
    double lo0 = v[3 * e], lo1 = v[3 * e + 1], lo2 = v[3 * e + 2];
    double hi0 = lo0, hi1 = lo1, hi2 = lo2;
    double sag = 0.0;
    double min_step = std::numeric_limits<double>::infinity();
    unsigned moved = 0;
    std::size_t count = 0;
    const std::size_t end = std::min(p.edges, e + max_edges);
    for (; e < end; ++e) {
      const double* a = v + 3 * e;
      const double* b = v + 3 * p.head(e);
      const double d0 = b[0] - a[0], d1 = b[1] - a[1], d2 = b[2] - a[2];
      const unsigned m = static_cast<unsigned>(d0 > 0.0) | static_cast<unsigned>(d0 < 0.0) << 1 |
                         static_cast<unsigned>(d1 > 0.0) << 2 | static_cast<unsigned>(d1 < 0.0) << 3 |
                         static_cast<unsigned>(d2 > 0.0) << 4 | static_cast<unsigned>(d2 < 0.0) << 5;
      const unsigned acc = moved | m;
      if ((acc & (acc >> 1) & 0x15u) != 0) break;  // some axis would turn
      const double nlo0 = std::min(lo0, b[0]), nlo1 = std::min(lo1, b[1]), nlo2 = std::min(lo2, b[2]);
      const double nhi0 = std::max(hi0, b[0]), nhi1 = std::max(hi1, b[1]), nhi2 = std::max(hi2, b[2]);
      if (count >= kMinRunEdges &&
          !(nhi0 - nlo0 <= max_extent && nhi1 - nlo1 <= max_extent && nhi2 - nlo2 <= max_extent))
        break;
      moved = acc;
      lo0 = nlo0, lo1 = nlo1, lo2 = nlo2, hi0 = nhi0, hi1 = nhi1, hi2 = nhi2;
      sag = std::max(sag, 0.25 * (d0 * d0 + d1 * d1 + d2 * d2));
      min_step = std::min(min_step, std::max({std::fabs(d0), std::fabs(d1), std::fabs(d2)}));
      ++count;
    }
    r.count = static_cast<std::uint32_t>(count);
    for (int k = 0; k < 3; ++k)
      r.dir[k] = static_cast<std::int8_t>((moved >> (2 * k)) & 1u ? 1 : ((moved >> (2 * k + 1)) & 1u ? -1 : 0));
    r.pad = sag + kArcBoxRoundingMargin + margin;
    r.self_free = min_step > 2.25 * r.pad;
    r.lo[0] = lo0 - r.pad, r.lo[1] = lo1 - r.pad, r.lo[2] = lo2 - r.pad;
    r.hi[0] = hi0 + r.pad, r.hi[1] = hi1 + r.pad, r.hi[2] = hi2 + r.pad;
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

/// Edge e of run r as an interval along axis k, padded with the run's pad.
inline EdgeInterval edge_interval(const PreparedPolyline& p, const Run& r, std::uint32_t e, int k) {
  const double a = p.u(e)[k];
  const double b = p.u(p.head(e))[k];
  return {std::min(a, b) - r.pad, std::max(a, b) + r.pad, e};
}

/// The run's edge intervals along axis k, sorted by lower end (by monotonicity: index order or
/// reversed; rounding is monotone, so the computed lower ends are sorted too).
inline void sorted_intervals(const PreparedPolyline& p, const Run& r, int k, std::vector<EdgeInterval>& out) {
  out.clear();
  const auto push = [&](std::uint32_t e) { out.push_back(edge_interval(p, r, e, k)); };
  if (r.dir[k] >= 0) {
    for (std::uint32_t e = r.first; e < r.first + r.count; ++e) push(e);
  } else {
    for (std::uint32_t e = r.first + r.count; e-- > r.first;) push(e);
  }
}

/// Whether the boxes of edges e (pad pe) and f (pad pf) overlap on axis k.
inline bool overlap_on_axis(const PreparedPolyline& p, std::uint32_t e, double pe, std::uint32_t f, double pf, int k) {
  const double e0 = p.u(e)[k], e1 = p.u(p.head(e))[k];
  const double f0 = p.u(f)[k], f1 = p.u(p.head(f))[k];
  return std::min(e0, e1) - pe <= std::max(f0, f1) + pf && std::min(f0, f1) - pf <= std::max(e0, e1) + pe;
}

/// Calls the visitor; converts a void visitor to "continue".
template <typename Visitor, typename... Args>
bool call_visitor(Visitor& visitor, const Args&... args) {
  if constexpr (std::is_void_v<decltype(visitor(args...))>) {
    visitor(args...);
    return true;
  } else {
    return static_cast<bool>(visitor(args...));
  }
}

/// Reports a candidate if the boxes overlap on every axis but `known_axis` (-1: check all three)
/// and the edges are not adjacent. Returns false to stop.
template <typename Visitor>
bool offer_pair(const PreparedPolyline& p, std::uint32_t e, double pe, std::uint32_t f, double pf, int known_axis,
                Visitor& visitor) {
  for (int k = 0; k < 3; ++k)
    if (k != known_axis && !overlap_on_axis(p, e, pe, f, pf, k)) return true;
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
  if (r.count < 3 || r.self_free) return true;  // < 3 edges: every pair adjacent
  const int k = longest_axis(r, r);
  sorted_intervals(p, r, k, buf);
  for (std::size_t x = 0; x < buf.size(); ++x)
    for (std::size_t y = x + 1; y < buf.size() && buf[y].lo <= buf[x].hi; ++y)
      if (!offer_pair(p, buf[x].edge, r.pad, buf[y].edge, r.pad, k, visitor)) return false;
  return true;
}

/// The edges of run `r` (in index order) whose boxes (padded with r's pad) overlap the box of
/// run `other`. Every edge of r whose box overlaps the box of some edge of `other` is among them,
/// since the edge boxes of a run lie inside its run box.
inline void edges_meeting_box(const PreparedPolyline& p, const Run& r, const Run& other,
                              std::vector<std::uint32_t>& out) {
  out.clear();
  for (std::uint32_t e = r.first; e < r.first + r.count; ++e) {
    const Eigen::Vector3d& a = p.u(e);
    const Eigen::Vector3d& b = p.u(p.head(e));
    bool meets = true;
    for (int k = 0; k < 3; ++k)
      meets = meets && std::min(a[k], b[k]) - r.pad <= other.hi[k] && other.lo[k] <= std::max(a[k], b[k]) + r.pad;
    if (meets) out.push_back(e);
  }
}

/// The intervals along axis k of the given edges of run r (in index order), sorted by lower end:
/// along a monotone run the lower ends follow the index order, or its reverse.
inline void sorted_intervals_of(const PreparedPolyline& p, const Run& r, const std::vector<std::uint32_t>& edges, int k,
                                std::vector<EdgeInterval>& out) {
  out.clear();
  const auto push = [&](std::uint32_t e) { out.push_back(edge_interval(p, r, e, k)); };
  if (r.dir[k] >= 0) {
    for (std::uint32_t e : edges) push(e);
  } else {
    for (std::size_t x = edges.size(); x-- > 0;) push(edges[x]);
  }
}

/// Scratch space of the run-pair visits, reused across pairs.
struct RunPairScratch {
  std::vector<EdgeInterval> la, lb;
  std::vector<std::uint32_t> ea, eb;
};

/// Edge pairs between two different runs. First each run is cut down to its edges whose boxes
/// meet the other run's box (often none: the run boxes overlap only at a corner); few survivors
/// are paired directly, more are merged as two sorted interval lists along one axis.
template <typename Visitor>
bool visit_between_runs(const PreparedPolyline& p, const Run& ra, const Run& rb, RunPairScratch& sc, Visitor& visitor) {
  edges_meeting_box(p, ra, rb, sc.ea);
  if (sc.ea.empty()) return true;
  edges_meeting_box(p, rb, ra, sc.eb);
  if (sc.eb.empty()) return true;
  if (sc.ea.size() * sc.eb.size() <= 64) {
    for (std::uint32_t e : sc.ea)
      for (std::uint32_t f : sc.eb)
        if (!offer_pair(p, e, ra.pad, f, rb.pad, -1, visitor)) return false;
    return true;
  }
  const int k = longest_axis(ra, rb);
  std::vector<EdgeInterval>& la = sc.la;
  std::vector<EdgeInterval>& lb = sc.lb;
  sorted_intervals_of(p, ra, sc.ea, k, la);
  sorted_intervals_of(p, rb, sc.eb, k, lb);
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

/// Edge pairs between consecutive runs sharing exactly one polyline vertex v (the head of the
/// last edge of `before`, the tail of the first edge of `after`). If along some axis k both runs
/// are monotone in the same direction, `before` approaches v_k from one side and `after` leaves
/// it to the other, so boxes can overlap only for edges of `before` whose head, and edges of
/// `after` whose tail, is within pad_before + pad_after (+ rounding) of v_k: a short suffix and
/// prefix, found by walking outwards from v and stopping at the first edge beyond 2 (pad + pad).
/// Without such an axis (all coordinates turn at v), the general merge.
template <typename Visitor>
bool visit_adjacent_runs(const PreparedPolyline& p, const Run& before, const Run& after, RunPairScratch& sc,
                         Visitor& visitor) {
  const std::uint32_t before_end = before.first + before.count;  // one past its last edge
  const std::size_t v = p.head(before_end - 1);
  SPHTROCH_ASSERT(v == after.first, "runs are not consecutive");
  int k = -1;
  double best_step = -1.0;
  for (int a = 0; a < 3; ++a) {
    if (before.dir[a] == 0 || before.dir[a] != after.dir[a]) continue;
    const double step = std::fabs(p.u(p.head(after.first))[a] - p.u(before_end - 1)[a]);
    if (step > best_step) {
      best_step = step;
      k = a;
    }
  }
  if (k < 0) return visit_between_runs(p, before, after, sc, visitor);
  const double vk = p.u(v)[k];
  const double reach = 2.0 * (before.pad + after.pad);
  std::uint32_t b_start = before_end;
  while (b_start > before.first && std::fabs(p.u(p.head(b_start - 1))[k] - vk) <= reach) --b_start;
  const std::uint32_t after_end = after.first + after.count;
  std::uint32_t a_stop = after.first;
  while (a_stop < after_end && std::fabs(p.u(a_stop)[k] - vk) <= reach) ++a_stop;
  for (std::uint32_t e = b_start; e < before_end; ++e)
    for (std::uint32_t f = after.first; f < a_stop; ++f)
      if (!offer_pair(p, e, before.pad, f, after.pad, -1, visitor)) return false;
  return true;
}

using SearchBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t>;

/// The cutoff of box_self_intersection_d (below it, the streamed segment tree scans boxes
/// directly). CGAL's default is 10; on run boxes of trochoid polylines (4e3..4e4 boxes, up to
/// 6e4 overlapping pairs) 300..1000 was 2..4 times faster than 10 and than 3000.
constexpr std::ptrdiff_t kBoxIntersectionCutoff = 512;

/// Up to this many run boxes, the overlapping pairs come from sweep_overlapping_runs instead of
/// box_self_intersection_d. Both report exactly the pairs of closed boxes that overlap; below
/// CGAL's cutoff CGAL scans too, but copies and sorts its 56-byte boxes twice (on 144 run boxes
/// of a 1e3-vertex trochoid it spent ~1000 instructions per box, the sweep ~250; on 1270 boxes
/// of a 1e4-vertex one the whole search took 10% fewer instructions with the sweep). The sweep's
/// worst case (every box overlapping every other along the sweep axis) is R^2/2 = 2e6 box tests
/// here, a few milliseconds; beyond it the segment tree's O(R log^3 R + pairs) bound is kept.
constexpr std::size_t kSweepMaxBoxes = 2048;

/// Every pair (r < s) of runs whose closed boxes overlap, given to emit.push(r, s) (false stops), by a sweep along the axis where the
/// boxes are thinnest relative to their spread: sort by lower end, scan forward while the lower
/// end is within the current box, check the other two axes. O(R log R + pairs overlapping along
/// that axis); meant for few boxes (see kSweepMaxBoxes), where that is no worse than the tree.
/// The axis along which the run boxes are thinnest relative to their spread.
inline int sweep_axis(const std::vector<Run>& runs) {
  int axis = 0;
  double best = -1.0;
  for (int k = 0; k < 3; ++k) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, width = 0.0;
    for (const Run& r : runs) {
      lo = std::min(lo, r.lo[k]);
      hi = std::max(hi, r.hi[k]);
      width += r.hi[k] - r.lo[k];
    }
    const double score = (hi - lo) / (width + DBL_MIN);
    if (score > best) {
      best = score;
      axis = k;
    }
  }
  return axis;
}

template <typename Emit>
bool sweep_overlapping_runs(const std::vector<Run>& runs, Emit& emit) {
  const int axis = sweep_axis(runs);
  std::vector<std::uint32_t> order(runs.size());
  for (std::uint32_t r = 0; r < order.size(); ++r) order[r] = r;
  std::sort(order.begin(), order.end(), [&runs, axis](std::uint32_t x, std::uint32_t y) {
    return runs[x].lo[axis] < runs[y].lo[axis] || (runs[x].lo[axis] == runs[y].lo[axis] && x < y);
  });
  const int k1 = (axis + 1) % 3, k2 = (axis + 2) % 3;
  for (std::size_t a = 0; a < order.size(); ++a) {
    const Run& ra = runs[order[a]];
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const Run& rb = runs[order[b]];
      if (rb.lo[axis] > ra.hi[axis]) break;
      if (ra.lo[k1] <= rb.hi[k1] && rb.lo[k1] <= ra.hi[k1] && ra.lo[k2] <= rb.hi[k2] && rb.lo[k2] <= ra.hi[k2] &&
          !emit.push(order[a], order[b]))
        return false;
    }
  }
  return true;
}

struct VisitStats {
  bool completed = true;
  std::size_t boxes = 0;
};

/// The work of one search and its limit, shared by the box intersection (box pairs) and the visitor
/// (candidate pairs): exceeded once box_pairs + candidate_pairs > limit.
struct WorkBudget {
  std::size_t limit = std::numeric_limits<std::size_t>::max();
  std::size_t box_pairs = 0;
  std::size_t candidate_pairs = 0;
  double estimate = 0;  // box_pairs_may_fit's estimate of the box pairs (0: not estimated)
  bool spend_box_pair() { return ++box_pairs <= limit - std::min(limit, candidate_pairs); }
  bool spend_candidate() { return ++candidate_pairs <= limit - std::min(limit, box_pairs); }
};

/// Whether the run-box pairs may fit in budget.limit, decided before the box intersection so that a
/// hopeless search (random vertices: Theta(N^2) pairs) is refused at once. Cost O(R log R + S R)
/// with S <= 256, S R <= ~2^24: the pairs overlapping along one axis are counted exactly (an
/// upper bound); only if they exceed the limit, S evenly spaced boxes are tested against all R
/// and the estimate R/2 * mean overlaps is stored in budget.estimate; false when it exceeds
/// 2 limit (the factor 2 leaves room for sampling error; the search's own count is exact).
inline bool box_pairs_may_fit(const std::vector<Run>& runs, WorkBudget& budget) {
  const double r = static_cast<double>(runs.size());
  const double limit = static_cast<double>(budget.limit);
  if (r * (r - 1) / 2 <= limit) return true;
  const int k = sweep_axis(runs);
  std::vector<double> lo, hi;
  lo.reserve(runs.size());
  hi.reserve(runs.size());
  for (const Run& x : runs) {
    lo.push_back(x.lo[k]);
    hi.push_back(x.hi[k]);
  }
  std::sort(lo.begin(), lo.end());
  std::sort(hi.begin(), hi.end());
  double along_axis = 0;  // ordered pairs (a, b), a != b, overlapping along k
  for (const Run& a : runs)
    along_axis += static_cast<double>(std::upper_bound(lo.begin(), lo.end(), a.hi[k]) - lo.begin()) -
                  static_cast<double>(std::lower_bound(hi.begin(), hi.end(), a.lo[k]) - hi.begin()) - 1;
  if (along_axis / 2 <= limit) return true;
  const std::size_t samples = std::clamp<std::size_t>((std::size_t(1) << 24) / runs.size(), 16, 256);
  double hits = 0;
  for (std::size_t s = 0; s < samples; ++s) {
    const Run& a = runs[s * runs.size() / samples];
    for (const Run& b : runs)
      hits += static_cast<double>(a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] &&
                                  b.lo[1] <= a.hi[1] && a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2]);
    hits -= 1;  // a itself
  }
  budget.estimate = hits / static_cast<double>(samples) * r / 2;
  return budget.estimate <= 2 * limit;
}

/// Thrown out of CGAL's callback to end box_self_intersection_d early (caught in this file only).
struct StopSearch {};

/// Overlapping box pairs are visited in sorted chunks of at most this many: the memory of a
/// search stays O(N + kPairChunk) however many boxes overlap (Theta(N^2) for random vertices).
constexpr std::size_t kPairChunk = std::size_t(1) << 16;

/// Collects pairs (a, b) as (min, max) and hands each full chunk, sorted (locality, and a
/// deterministic order: the box intersections are deterministic), to visit(i, j) -> bool.
template <typename Visit>
class PairChunks {
 public:
  explicit PairChunks(Visit& visit) : visit_(visit) {}
  bool push(std::uint32_t a, std::uint32_t b) {
    buf_.emplace_back(std::min(a, b), std::max(a, b));
    return buf_.size() < kPairChunk || flush();
  }
  bool flush() {
    std::sort(buf_.begin(), buf_.end());
    for (const auto& ij : buf_)
      if (!visit_(ij.first, ij.second)) return false;
    buf_.clear();
    return true;
  }

 private:
  Visit& visit_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> buf_;
};

/// Every overlapping pair of `boxes` (CLOSED) to chunks.push; false if a push stopped the search.
template <typename Chunks>
bool overlapping_box_pairs(std::vector<SearchBox>& boxes, Chunks& chunks, const PreparedPolyline* skip_adjacent) {
  try {
    CGAL::box_self_intersection_d(
        boxes.begin(), boxes.end(),
        [&chunks, skip_adjacent](const SearchBox& a, const SearchBox& b) {
          const std::uint32_t i = std::min(a.info(), b.info()), j = std::max(a.info(), b.info());
          if (skip_adjacent != nullptr && skip_adjacent->adjacent(i, j)) return;
          if (!chunks.push(i, j)) throw StopSearch{};
        },
        kBoxIntersectionCutoff, CGAL::Box_intersection_d::CLOSED);
  } catch (const StopSearch&) {
    return false;
  }
  return true;
}

/// Within-run pairs first, then run pairs in sorted chunks. budget (may be null): one unit per
/// run pair examined; the search stops when it is exceeded.
template <typename Visitor>
VisitStats visit_runs(const PreparedPolyline& p, double margin, std::size_t max_run_edges, double max_run_extent,
                      Visitor& visitor, WorkBudget* budget) {
  VisitStats stats;
  const std::vector<Run> runs = build_runs(p, margin, max_run_edges, max_run_extent);
  stats.boxes = runs.size();
  if (budget != nullptr && !box_pairs_may_fit(runs, *budget)) return {false, stats.boxes};
  RunPairScratch sc;
  sc.la.reserve(std::min<std::size_t>(max_run_edges, p.edges));
  sc.lb.reserve(std::min<std::size_t>(max_run_edges, p.edges));
  sc.ea.reserve(std::min<std::size_t>(max_run_edges, p.edges));
  sc.eb.reserve(std::min<std::size_t>(max_run_edges, p.edges));
  for (const Run& r : runs)
    if (!visit_within_run(p, r, sc.la, visitor)) return {false, stats.boxes};
  const std::size_t last = runs.size() - 1;
  // Closed with exactly 2 runs: they share two vertices; use the general merge for them.
  const bool wrap_adjacent = p.closed && runs.size() >= 3;
  auto visit_pair = [&](std::uint32_t r, std::uint32_t s) {
    if (budget != nullptr && !budget->spend_box_pair()) return false;
    if (s == r + 1 && !(p.closed && runs.size() == 2)) return visit_adjacent_runs(p, runs[r], runs[s], sc, visitor);
    if (wrap_adjacent && r == 0 && s == last) return visit_adjacent_runs(p, runs[last], runs[0], sc, visitor);
    return visit_between_runs(p, runs[r], runs[s], sc, visitor);
  };
  PairChunks<decltype(visit_pair)> chunks(visit_pair);
  bool go = true;
  if (runs.size() <= kSweepMaxBoxes) {
    go = sweep_overlapping_runs(runs, chunks);
  } else {
    std::vector<SearchBox> boxes;
    boxes.reserve(runs.size());
    for (std::size_t r = 0; r < runs.size(); ++r) {
      double lo[3] = {runs[r].lo[0], runs[r].lo[1], runs[r].lo[2]};
      double hi[3] = {runs[r].hi[0], runs[r].hi[1], runs[r].hi[2]};
      boxes.emplace_back(lo, hi, static_cast<std::uint32_t>(r));
    }
    go = overlapping_box_pairs(boxes, chunks, nullptr);
  }
  stats.completed = go && chunks.flush();
  return stats;
}

template <typename Visitor>
VisitStats visit_edges(const PreparedPolyline& p, double margin, Visitor& visitor) {
  VisitStats stats;
  std::vector<SearchBox> boxes;
  boxes.reserve(p.edges);
  for (std::size_t e = 0; e < p.edges; ++e) {
    const Eigen::Vector3d& a = p.u(e);
    const Eigen::Vector3d& b = p.u(p.head(e));
    const double pad = sagitta_bound(a, b) + kArcBoxRoundingMargin + margin;
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(a[k], b[k]) - pad;
      hi[k] = std::max(a[k], b[k]) + pad;
    }
    boxes.emplace_back(lo, hi, static_cast<std::uint32_t>(e));
  }
  stats.boxes = boxes.size();
  auto visit_pair = [&visitor](std::uint32_t i, std::uint32_t j) { return call_visitor(visitor, i, j); };
  PairChunks<decltype(visit_pair)> chunks(visit_pair);
  stats.completed = overlapping_box_pairs(boxes, chunks, &p) && chunks.flush();
  return stats;
}

template <typename Visitor>
VisitStats visit_prepared(const PreparedPolyline& p, double margin, CandidateSearch search, std::size_t max_run_edges,
                          double max_run_extent, Visitor& visitor, WorkBudget* budget = nullptr) {
  if (search == CandidateSearch::edges) return visit_edges(p, margin, visitor);
  return visit_runs(p, margin, std::max<std::size_t>(1, max_run_edges), max_run_extent, visitor, budget);
}

inline void record_contact(SelfCrossings& out, std::size_t i, std::size_t j, ArcContact kind) {
  if (kind == ArcContact::crossing) out.crossings.push_back({i, j, kind});
  else if (kind != ArcContact::none) out.touchings.push_back({i, j, kind});
}

}  // namespace detail

/// Throws InvalidInput (field "vertices") unless the polyline is a valid spherical polyline.
inline void validate_spherical_polyline(const std::vector<Eigen::Vector3d>& vertices, bool closed) {
  detail::validate_polyline(vertices, closed);
}

/// Visits every pair of non-adjacent edges whose boxes, inflated by margin, overlap (see top).
template <typename Visitor>
bool visit_close_edge_pairs(const std::vector<Eigen::Vector3d>& vertices, bool closed, double margin,
                            Visitor&& visitor, CandidateSearch search = CandidateSearch::runs) {
  detail::validate_margin(margin);
  const detail::PreparedPolyline p(vertices, closed, detail::validate_polyline(vertices, closed));
  return detail::visit_prepared(p, margin, search, kDefaultMaxRunEdges, kDefaultMaxRunExtent, visitor).completed;
}

/// Calls visitor(const EdgePair&) (returning bool, false stops, or void) for every crossing,
/// touching or overlapping pair of non-adjacent edges, in the search's order (deterministic, not
/// sorted), and returns the counts. Stops early at options.max_contacts / max_work (see top).
/// Memory O(N) (the pairs are not stored). The vertices are read in place: REQUIRES they do not
/// change during the call (a caller sharing them with other threads must copy them first).
template <typename Visitor>
CrossingCounts visit_self_crossings(VertexSpan vertices, bool closed, Visitor&& visitor,
                                    const CrossingSearchOptions& options = {}) {
  detail::validate_margin(options.margin);
  const detail::PreparedPolyline p(vertices, closed, detail::validate_polyline(vertices, closed));
  CrossingCounts out;
  out.vertices = p.n;
  out.edges = p.edges;
  detail::WorkBudget budget;
  budget.limit = options.max_work;
  auto test = [&](std::size_t i, std::size_t j) {
    if (!budget.spend_candidate()) {
      out.stop = SearchStop::work;
      return false;
    }
    const ArcContact kind =
        classify_arcs_unchecked(vertices[i], vertices[p.head(i)], vertices[j], vertices[p.head(j)], &out.predicates);
    if (kind == ArcContact::none) return true;
    const bool over = out.crossings + out.touchings >= options.max_contacts;
    ++(kind == ArcContact::crossing ? out.crossings : out.touchings);
    if (over) {
      out.stop = SearchStop::contacts;
      return false;
    }
    const EdgePair e{i, j, kind};
    if (!detail::call_visitor(visitor, e)) {
      out.stop = SearchStop::visitor;
      return false;
    }
    return true;
  };
  const detail::VisitStats stats = detail::visit_prepared(p, options.margin, options.search, options.max_run_edges,
                                                          options.max_run_extent, test, &budget);
  out.estimated_box_pairs = budget.estimate;
  if (!stats.completed && out.stop == SearchStop::complete)  // stopped by the box intersection
    out.stop = budget.box_pairs == 0 && budget.estimate > 0 ? SearchStop::estimate : SearchStop::work;
  out.boxes = stats.boxes;
  out.box_pairs = budget.box_pairs;
  out.candidate_pairs = budget.candidate_pairs;
  return out;
}

/// Throws InvalidInput naming the limit that stopped the search (contacts_field: the option of
/// max_contacts, work_field: of max_work), with the cost found so far and how to raise it.
/// Does nothing when c is complete or was stopped by the visitor.
inline void check_search_complete(const CrossingCounts& c, const CrossingSearchOptions& o,
                                  const std::string& contacts_field, const std::string& work_field) {
  const std::string found = std::to_string(c.crossings) + " crossings and " + std::to_string(c.touchings) + " touchings";
  const std::string raise = " (up to " + std::to_string(kMaxCrossingLimit) + "); memory stays O(N) without pairs, ";
  if (c.stop == SearchStop::contacts)
    throw InvalidInput(contacts_field, std::to_string(o.max_contacts),
                       "the polyline has more than " + std::to_string(o.max_contacts) +
                           " crossings + touchings (the search stopped at " + found + ", after " +
                           std::to_string(c.work()) + " units of work)",
                       "at least its crossings + touchings: raise it" + raise +
                           "each pair listed costs a row");
  if (c.stop == SearchStop::work || c.stop == SearchStop::estimate)
    throw InvalidInput(
        work_field, std::to_string(o.max_work),
        c.stop == SearchStop::estimate
            ? "the search would need about " + number_text(std::round(c.estimated_box_pairs)) +
                  " units of work (overlapping box pairs, estimated before searching), more than 2 x " +
                  std::to_string(o.max_work)
            : "the search needs more than " + std::to_string(o.max_work) +
                  " units of work (candidate edge pairs + overlapping box pairs; stopped at " + found + ")",
        "at least the work of the search: raise it" + raise +
            "time about 0.1-0.2 s per 1e6 units (random vertices: about N^2 units)");
}

/// The counts of find_self_crossings without storing a pair: memory O(N), time as find_self_crossings.
inline CrossingCounts count_self_crossings(VertexSpan vertices, bool closed, const CrossingSearchOptions& options = {}) {
  return visit_self_crossings(vertices, closed, [](const EdgePair&) {}, options);
}

/// Every crossing and touching pair of non-adjacent edges, exactly (see top). The vertices are
/// read in place (a VertexSpan: no copy of a caller's array). Memory O(N + pairs found).
inline SelfCrossings find_self_crossings(VertexSpan vertices, bool closed,
                                         const CrossingSearchOptions& options = {}) {
  SelfCrossings out;
  const CrossingCounts c = visit_self_crossings(
      vertices, closed, [&out](const EdgePair& e) { detail::record_contact(out, e.i, e.j, e.kind); }, options);
  out.vertices = c.vertices;
  out.edges = c.edges;
  out.boxes = c.boxes;
  out.candidate_pairs = c.candidate_pairs;
  out.predicates = c.predicates;
  out.box_pairs = c.box_pairs;
  out.stop = c.stop;
  std::sort(out.crossings.begin(), out.crossings.end());
  std::sort(out.touchings.begin(), out.touchings.end());
  return out;
}

/// The same for a std::vector (and a braced list of vertices in a call).
inline SelfCrossings find_self_crossings(const std::vector<Eigen::Vector3d>& vertices, bool closed,
                                         const CrossingSearchOptions& options = {}) {
  return find_self_crossings(VertexSpan(vertices), closed, options);
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
                             classify_arcs_unchecked(vertices[i], vertices[head(i)], vertices[j],
                                                             vertices[head(j)], &out.predicates));
    }
  }
  return out;
}

/// A box containing the arc from a/|a| to b/|b|, inflated by margin (see the sagitta bound above).
/// REQUIRES a, b finite, nonzero, neither the same direction nor antipodal (else InvalidInput); margin >= 0.
inline ArcBox arc_bounding_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double margin = 0.0) {
  if (relate_vertices(a, b) != VertexRelation::distinct)  // which refuses zero / non-finite vertices
    throw InvalidInput("vertices", "an arc's endpoints", "the same direction or antipodal",
                       "the two endpoints of an arc distinct and not antipodal");
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
