// Tests for sphtroch/exact/arc_predicates.hpp and sphtroch/exact/self_crossings.hpp.
//
// Expected values come from construction (exact coordinates), from an independent integer
// oracle, or from the O(N^2) brute force; never from the fast search itself.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/core/arc_crossing_point.hpp"
#include "sphtroch/exact/arc_predicates.hpp"
#include "sphtroch/exact/self_crossings.hpp"
#include "sphtroch/census/root_census.hpp"
#include "sphtroch/core/sampling.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

using sphtroch::ArcContact;
using sphtroch::CandidateSearch;
using sphtroch::EdgePair;
using sphtroch::SelfCrossings;
using V = Eigen::Vector3d;
using Polyline = std::vector<V>;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string describe(const std::vector<EdgePair>& pairs, std::size_t limit = 20) {
  std::ostringstream os;
  os << pairs.size() << " pairs:";
  for (std::size_t k = 0; k < pairs.size() && k < limit; ++k)
    os << " (" << pairs[k].i << "," << pairs[k].j << "," << sphtroch::to_string(pairs[k].kind) << ")";
  return os.str();
}

// The fast search equals the brute force pair for pair, for both candidate searches, several
// run lengths and a margin (which may only change the work).
void check_against_brute_force(const Polyline& vs, bool closed, const SelfCrossings& brute) {
  struct Variant {
    CandidateSearch search;
    std::size_t run;
    double extent;
    double margin;
  };
  const double x0 = sphtroch::kDefaultMaxRunExtent;
  const Variant variants[] = {{CandidateSearch::runs, sphtroch::kDefaultMaxRunEdges, x0, 0.0},
                              {CandidateSearch::runs, 1, x0, 0.0},
                              {CandidateSearch::runs, 3, x0, 0.0},
                              {CandidateSearch::runs, 32, 10.0, 0.0},
                              {CandidateSearch::runs, 100000, 10.0, 0.0},
                              {CandidateSearch::runs, 100000, 1e-3, 0.0},
                              {CandidateSearch::runs, 8, x0, 1e-3},
                              {CandidateSearch::edges, 0, x0, 0.0},
                              {CandidateSearch::edges, 0, x0, 1e-2}};
  for (const Variant& v : variants) {
    sphtroch::CrossingSearchOptions opt;
    opt.search = v.search;
    opt.max_run_edges = v.run;
    opt.max_run_extent = v.extent;
    opt.margin = v.margin;
    const SelfCrossings fast = sphtroch::find_self_crossings(vs, closed, opt);
    INFO("search " << (v.search == CandidateSearch::runs ? "runs" : "edges") << " run " << v.run << " extent "
                   << v.extent << " margin "
                   << v.margin << " closed " << closed << " n " << vs.size());
    INFO("fast crossings " << describe(fast.crossings) << "\nbrute crossings " << describe(brute.crossings));
    INFO("fast touchings " << describe(fast.touchings) << "\nbrute touchings " << describe(brute.touchings));
    CHECK(fast.crossings == brute.crossings);
    CHECK(fast.touchings == brute.touchings);
    CHECK(fast.edges == brute.edges);
    CHECK(fast.candidate_pairs <= brute.candidate_pairs);
  }
}

SelfCrossings check_fast_equals_brute(const Polyline& vs, bool closed) {
  const SelfCrossings brute = sphtroch::exact_brute_force_crossings(vs, closed);
  check_against_brute_force(vs, closed, brute);
  return brute;
}

Polyline random_polyline(std::uint32_t seed, std::size_t n, double step) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  Polyline vs;
  V p(g(rng), g(rng), g(rng));
  p.normalize();
  for (std::size_t i = 0; i < n; ++i) {
    vs.push_back(p * (0.5 + 0.001 * static_cast<double>(i % 7)));  // not normalised on purpose
    V q = p + step * V(g(rng), g(rng), g(rng));
    p = q.normalized();
  }
  return vs;
}

Polyline trochoid(double a2, double a3, std::int64_t p, std::int64_t q, std::size_t n) {
  sphtroch::GearTrain train(a2, a3, sphtroch::Ratio(p, q));
  sphtroch::TracerCurve<double> curve(train);
  return sphtroch::sample_period(curve, n).points;
}

// ---- An independent oracle for arcs with small integer coordinates (exact in int64) ----
using I3 = std::array<std::int64_t, 3>;
I3 cross(const I3& a, const I3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
std::int64_t dot(const I3& a, const I3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
int sgn(std::int64_t x) { return (x > 0) - (x < 0); }
I3 neg(const I3& a) { return {-a[0], -a[1], -a[2]}; }

// Where P (in the plane of AB, normal n = A x B) is: -1 outside, 0 at an endpoint, 1 interior.
// P = alpha A + beta B; alpha n.n = (P x B).n, beta n.n = (A x P).n.
int where_on_arc(const I3& p, const I3& a, const I3& b) {
  const I3 n = cross(a, b);
  const int alpha = sgn(dot(cross(p, b), n));
  const int beta = sgn(dot(cross(a, p), n));
  if (alpha < 0 || beta < 0) return -1;
  return (alpha > 0 && beta > 0) ? 1 : 0;
}

ArcContact oracle(const I3& a, const I3& b, const I3& c, const I3& d) {
  const I3 n1 = cross(a, b), n2 = cross(c, d);
  const I3 x = cross(n1, n2);
  if (x[0] != 0 || x[1] != 0 || x[2] != 0) {
    // Distinct great circles: the only candidates are +-X.
    for (const I3& pnt : {x, neg(x)}) {
      const int on_ab = where_on_arc(pnt, a, b), on_cd = where_on_arc(pnt, c, d);
      if (on_ab >= 0 && on_cd >= 0) return (on_ab == 1 && on_cd == 1) ? ArcContact::crossing : ArcContact::touching;
    }
    return ArcContact::none;
  }
  // One great circle: walk a fine set of directions? No: use the midpoints, which are exact
  // in integers as sums of (scaled) endpoints. The intersection has positive length iff it
  // contains the midpoint of a sub-arc; test the midpoints of every arc between consecutive
  // candidate endpoints lying on both arcs.
  const I3 ends[4] = {a, b, c, d};
  std::vector<I3> on_both;
  for (const I3& e : ends)
    if (where_on_arc(e, a, b) >= 0 && where_on_arc(e, c, d) >= 0) on_both.push_back(e);
  if (on_both.empty()) return ArcContact::none;
  // Normalising is not exact; compare the sub-arc between two common points by the
  // direction sum e/|e| + f/|f| scaled: use |f| e + |e| f with integer norms when they are
  // perfect squares... simpler: two distinct common directions means positive-length overlap
  // (the intersection is connected and contains both).
  for (std::size_t i = 0; i < on_both.size(); ++i)
    for (std::size_t j = i + 1; j < on_both.size(); ++j) {
      const I3 cr = cross(on_both[i], on_both[j]);
      const bool parallel = cr[0] == 0 && cr[1] == 0 && cr[2] == 0;
      if (!parallel || dot(on_both[i], on_both[j]) < 0) return ArcContact::overlap;
    }
  return ArcContact::touching;
}

V to_v(const I3& a) { return V(double(a[0]), double(a[1]), double(a[2])); }

bool valid_arc(const I3& a, const I3& b) {
  const I3 c = cross(a, b);
  return (a[0] || a[1] || a[2]) && (b[0] || b[1] || b[2]) && (c[0] || c[1] || c[2]);
}

}  // namespace

// ============================== arc_predicates.hpp ==============================

TEST_CASE("orientation_sign follows det[a, b, c]", "[arc_predicates]") {
  CHECK(sphtroch::orientation_sign(V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)) == 1);
  CHECK(sphtroch::orientation_sign(V(0, 1, 0), V(1, 0, 0), V(0, 0, 1)) == -1);
  CHECK(sphtroch::orientation_sign(V(1, 0, 0), V(0, 1, 0), V(1, 1, 0)) == 0);
  // A determinant far below rounding: exact sign all the same.
  const double t = std::ldexp(1.0, -60);
  CHECK(sphtroch::orientation_sign(V(1, 0, 0), V(0, 1, 0), V(1, 1, t)) == 1);
  CHECK(sphtroch::orientation_sign(V(1, 0, 0), V(0, 1, 0), V(1, 1, -t)) == -1);
}

TEST_CASE("orientation_sign: the floating-point filter agrees with CGAL's exact orientation", "[arc_predicates]") {
  // Random and nearly coplanar triples over many magnitudes (including products that underflow
  // or overflow, where the filter must step aside); the reference is CGAL::orientation itself.
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::mt19937_64 rng(2024);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 4);
  const double scales[] = {1.0, 1e-3, 1e3, 1e-110, 1e110};
  const double tinies[] = {0.0, 1e-18, 1e-16, 1e-14, 1e-8};
  std::size_t zeros = 0, nonzeros = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const V a = scales[pick(rng)] * V(g(rng), g(rng), g(rng));
    const V b = scales[pick(rng)] * V(g(rng), g(rng), g(rng));
    V c = scales[pick(rng)] * V(g(rng), g(rng), g(rng));
    if (trial % 2 == 0) {  // near the plane of a and b (or exactly on it when the sum is exact)
      const double s = trial % 4 == 0 ? 1.0 : g(rng), t = trial % 4 == 0 ? 1.0 : g(rng);
      c = s * a + t * b + tinies[pick(rng)] * a.norm() * V(g(rng), g(rng), g(rng));
    }
    const int expected = static_cast<int>(
        CGAL::orientation(K::Point_3(0, 0, 0), K::Point_3(a.x(), a.y(), a.z()), K::Point_3(b.x(), b.y(), b.z()),
                          K::Point_3(c.x(), c.y(), c.z())));
    const int got = sphtroch::orientation_sign(a, b, c);
    if (got != expected) {
      INFO("a " << a.transpose() << " b " << b.transpose() << " c " << c.transpose());
      REQUIRE(got == expected);
    }
    (expected == 0 ? zeros : nonzeros)++;
  }
  CHECK(zeros > 100);  // exact coplanarity occurs (c = a + b with exact sums, zero vectors after underflow)
  CHECK(nonzeros > 100000);
}

TEST_CASE("relate_vertices: same direction, antipodal, distinct", "[arc_predicates]") {
  CHECK(sphtroch::relate_vertices(V(1, 2, 3), V(2, 4, 6)) == sphtroch::VertexRelation::same_direction);
  CHECK(sphtroch::relate_vertices(V(1, 2, 3), V(-0.5, -1, -1.5)) == sphtroch::VertexRelation::antipodal);
  CHECK(sphtroch::relate_vertices(V(1, 2, 3), V(1, 2, 3 + 4.5e-16)) == sphtroch::VertexRelation::distinct);
  CHECK(sphtroch::relate_vertices(V(0, 0, 1), V(0, 0, 1e-300)) == sphtroch::VertexRelation::same_direction);
}

TEST_CASE("classify_arcs: a transversal crossing and a miss", "[arc_predicates]") {
  const V a(1, 0, 0), b(0, 1, 0), c(1, 1, -1), d(1, 1, 1);
  CHECK(sphtroch::classify_arcs(a, b, c, d) == ArcContact::crossing);
  CHECK(sphtroch::classify_arcs(c, d, a, b) == ArcContact::crossing);
  CHECK(sphtroch::classify_arcs(b, a, d, c) == ArcContact::crossing);
  CHECK(sphtroch::classify_arcs(a, b, V(1, 1, 0.5), V(1, 1, 1)) == ArcContact::none);
  std::size_t count = 0;
  sphtroch::classify_arcs(a, b, c, d, &count);
  CHECK(count == 4);
}

TEST_CASE("vertex_exactly_on_arc is a touching, not a crossing", "[arc_predicates][degenerate]") {
  // (1, 1, 0) is exactly on the arc (1,0,0)-(0,1,0); vertices need not be normalised.
  const V a(1, 0, 0), b(0, 1, 0), on(1, 1, 0);
  CHECK(sphtroch::point_on_arc(on, a, b));
  CHECK(sphtroch::point_on_arc(V(3, 3, 0), a, b));
  CHECK_FALSE(sphtroch::point_on_arc(V(-1, -1, 0), a, b));  // the antipode, on the circle only
  CHECK_FALSE(sphtroch::point_on_arc(V(1, -1, 0), a, b));
  CHECK(sphtroch::point_on_arc(V(2, 0, 0), a, b));           // an endpoint
  // An arc starting on AB and leaving it (T-junction), both orders and directions.
  CHECK(sphtroch::classify_arcs(a, b, on, V(0, 0, 1)) == ArcContact::touching);
  CHECK(sphtroch::classify_arcs(a, b, V(1, 1, 1), on) == ArcContact::touching);
  CHECK(sphtroch::classify_arcs(on, V(1, 1, -1), b, a) == ArcContact::touching);
  // A polyline through the point: edges (1,1,1)-(1,1,0) and (1,1,0)-(1,1,-1) both touch AB.
  Polyline vs = {a, b, V(0, 0, 1), V(1, 1, 1), on, V(1, 1, -1), V(0, -1, -1)};
  const SelfCrossings brute = check_fast_equals_brute(vs, false);
  CHECK(brute.crossings.empty());
  const std::vector<EdgePair> expected = {{0, 3, ArcContact::touching}, {0, 4, ArcContact::touching}};
  CHECK(brute.touchings == expected);
}

TEST_CASE("shared_vertex of non-adjacent edges is a touching", "[arc_predicates][degenerate]") {
  CHECK(sphtroch::classify_arcs(V(1, 0, 0), V(0, 1, 0), V(0, 2, 0), V(0, 0, 1)) == ArcContact::touching);
  CHECK(sphtroch::classify_arcs(V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(0.5, 0, 0)) == ArcContact::touching);
  // A figure eight through (0,0,1) visited twice: edges 1, 2 meet edges 4, 5 there.
  const Polyline vs = {V(1, 0, 0.2), V(1, 1, 1), V(0, 0, 1), V(-1, -1, 1), V(-1, 0.2, 0.2),
                       V(-1, 1, 1), V(0, 0, 2), V(1, -1, 1)};
  const SelfCrossings brute = check_fast_equals_brute(vs, true);
  std::set<std::pair<std::size_t, std::size_t>> touching;
  for (const EdgePair& e : brute.touchings) touching.insert({e.i, e.j});
  for (std::size_t i : {1, 2})
    for (std::size_t j : {5, 6}) CHECK(touching.count({i, j}) == 1);
}

TEST_CASE("overlap_on_one_great_circle", "[arc_predicates][degenerate]") {
  const V a(1, 0, 0), b(0, 1, 0);
  CHECK(sphtroch::classify_arcs(a, b, V(1, 1, 0), V(-1, 2, 0)) == ArcContact::overlap);   // partial
  CHECK(sphtroch::classify_arcs(a, b, V(2, 0, 0), V(0, 3, 0)) == ArcContact::overlap);    // same arc
  CHECK(sphtroch::classify_arcs(a, b, b, a) == ArcContact::overlap);                      // reversed
  CHECK(sphtroch::classify_arcs(a, b, V(2, 1, 0), V(1, 2, 0)) == ArcContact::overlap);    // inside
  CHECK(sphtroch::classify_arcs(a, V(1, 1, 0), V(2, 2, 0), b) == ArcContact::touching);   // end to end
  CHECK(sphtroch::classify_arcs(a, V(1, 1, 0), b, V(-1, 1, 0)) == ArcContact::none);      // same circle, apart
  CHECK(sphtroch::classify_arcs(a, b, V(-1, 0, 0), V(0, -1, 0)) == ArcContact::none);     // antipodal arc
  // A polyline running twice along the equator: edge 3 lies inside edge 0, and edges 2 and 4
  // (its neighbours) each touch edge 0 at an endpoint of edge 3.
  const Polyline vs = {V(1, 0, 0), V(0, 1, 0), V(0, 1, 1), V(2, 1, 0), V(1, 2, 0), V(0, 0, -1)};
  const SelfCrossings brute = check_fast_equals_brute(vs, false);
  INFO(describe(brute.touchings));
  const std::vector<EdgePair> expected = {
      {0, 2, ArcContact::touching}, {0, 3, ArcContact::overlap}, {0, 4, ArcContact::touching}};
  CHECK(brute.touchings == expected);
  CHECK(brute.crossings.empty());
}

TEST_CASE("antipodal_meeting of great circles does not count", "[arc_predicates][degenerate]") {
  // Equator and the meridian plane y = 0 meet at +-(1,0,0). AB contains (1,0,0), CD contains (-1,0,0):
  // every single plane test says "opposite sides", yet the arcs are disjoint.
  const V a(1, -1, 0), b(1, 1, 0);
  CHECK(sphtroch::classify_arcs(a, b, V(-1, 0, -1), V(-1, 0, 1)) == ArcContact::none);
  CHECK(sphtroch::classify_arcs(a, b, V(1, 0, -1), V(1, 0, 1)) == ArcContact::crossing);
  // An endpoint exactly at the antipode of a point of the other arc.
  CHECK(sphtroch::classify_arcs(a, b, V(-1, 0, 0), V(-1, 0, 1)) == ArcContact::none);
  CHECK(sphtroch::classify_arcs(a, b, V(1, 0, 0), V(1, 0, 1)) == ArcContact::touching);
  const Polyline vs = {a, b, V(0, 0, 1), V(-1, 0, -1), V(-1, 0, 1)};
  const SelfCrossings brute = check_fast_equals_brute(vs, false);
  CHECK(brute.crossings.empty());
  CHECK(brute.touchings.empty());
}

TEST_CASE("classify_arcs agrees with an integer oracle on cocircular and degenerate arcs", "[arc_predicates][degenerate]") {
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> coord(-2, 2);
  const auto draw = [&] { return I3{coord(rng), coord(rng), coord(rng)}; };
  std::size_t counts[4] = {0, 0, 0, 0};
  for (int trial = 0; trial < 200000; ++trial) {
    I3 a = draw(), b = draw(), c = draw(), d = draw();
    if (trial % 3 == 0) {
      // force coplanarity: c, d in the plane of a, b
      const int r = coord(rng);
      c = I3{a[0] + r * b[0], a[1] + r * b[1], a[2] + r * b[2]};
      const int s = coord(rng), t = coord(rng);
      d = I3{s * a[0] + t * b[0], s * a[1] + t * b[1], s * a[2] + t * b[2]};
    }
    if (!valid_arc(a, b) || !valid_arc(c, d)) continue;
    const ArcContact expected = oracle(a, b, c, d);
    const ArcContact got = sphtroch::classify_arcs(to_v(a), to_v(b), to_v(c), to_v(d));
    ++counts[static_cast<int>(expected)];
    if (got != expected) {
      INFO("a " << a[0] << "," << a[1] << "," << a[2] << " b " << b[0] << "," << b[1] << "," << b[2] << " c " << c[0]
                << "," << c[1] << "," << c[2] << " d " << d[0] << "," << d[1] << "," << d[2]);
      CHECK(sphtroch::to_string(got) == std::string(sphtroch::to_string(expected)));
    }
    CHECK(sphtroch::classify_arcs(to_v(c), to_v(d), to_v(a), to_v(b)) == got);
    CHECK(sphtroch::classify_arcs(to_v(b), to_v(a), to_v(d), to_v(c)) == got);
  }
  // every kind is exercised many times
  for (std::size_t k : counts) CHECK(k > 1000);
}

// ============================== self_crossings.hpp ==============================

TEST_CASE("arc_bounding_box contains the arc (the sagitta bound)", "[polyline_crossings]") {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    V a(g(rng), g(rng), g(rng)), b;
    const int mode = trial % 4;
    if (mode == 0) b = V(g(rng), g(rng), g(rng));
    else if (mode == 1) b = -a + 1e-6 * V(g(rng), g(rng), g(rng));  // nearly antipodal: arc close to pi
    else if (mode == 2) b = a + 1e-3 * V(g(rng), g(rng), g(rng));   // short
    else b = a + 0.3 * V(g(rng), g(rng), g(rng));
    a *= std::ldexp(1.0, static_cast<int>(trial % 41) - 20);           // scales need not be 1
    const sphtroch::ArcBox box = sphtroch::arc_bounding_box(a, b);
    // Sample the arc by slerp in long double.
    using L = long double;
    Eigen::Matrix<L, 3, 1> u = a.cast<L>(), v = b.cast<L>();
    u /= u.norm();
    v /= v.norm();
    const L theta = std::atan2(u.cross(v).norm(), u.dot(v));
    for (int s = 0; s <= 64; ++s) {
      const L t = L(s) / 64;
      const Eigen::Matrix<L, 3, 1> p = (std::sin((1 - t) * theta) * u + std::sin(t * theta) * v) / std::sin(theta);
      const V pd = p.cast<double>();
      INFO("trial " << trial << " s " << s);
      REQUIRE(box.contains(pd));
    }
  }
}

TEST_CASE("random spherical polylines: fast search equals brute force", "[polyline_crossings]") {
  const std::size_t sizes[] = {3, 4, 10, 60, 300, 1200};
  const double steps[] = {0.05, 0.4, 3.0};  // random walks with short steps, and jumps across the sphere
  std::uint32_t seed = 1;
  std::size_t total_crossings = 0;
  for (std::size_t n : sizes)
    for (double step : steps)
      for (bool closed : {true, false}) {
        const Polyline vs = random_polyline(seed++, n, step);
        const SelfCrossings brute = check_fast_equals_brute(vs, closed);
        total_crossings += brute.crossings.size();
      }
  CHECK(total_crossings > 1000);
}

TEST_CASE("integer-coordinate polylines: many exact degeneracies", "[polyline_crossings][degenerate]") {
  // Vertices from {-2..2}^3: shared vertices, vertices on arcs, overlapping arcs abound.
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> coord(-2, 2);
  std::size_t touch = 0, overlap = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Polyline vs;
    const std::size_t n = 20 + 10 * static_cast<std::size_t>(trial);
    while (vs.size() < n) {
      V v(coord(rng), coord(rng), coord(rng));
      if (v.isZero()) continue;
      if (!vs.empty() && sphtroch::relate_vertices(vs.back(), v) != sphtroch::VertexRelation::distinct) continue;
      vs.push_back(v);
    }
    const bool closed = trial % 2 == 0;
    if (closed && sphtroch::relate_vertices(vs.back(), vs.front()) != sphtroch::VertexRelation::distinct) vs.pop_back();
    const SelfCrossings brute = check_fast_equals_brute(vs, closed);
    for (const EdgePair& e : brute.touchings) (e.kind == ArcContact::overlap ? overlap : touch)++;
  }
  CHECK(touch > 100);
  CHECK(overlap > 10);
}

TEST_CASE("trochoid polylines: fast search equals brute force", "[polyline_crossings]") {
  struct Case {
    double a2, a3;
    std::int64_t p, q;
    std::size_t n;
  };
  const Case cases[] = {
      {kPi / 2, kPi / 2, 1, 1, 1500},    {1.0, 2.0, 1, 1, 1000},      {kPi / 2, kPi / 2, 2, 1, 1500},
      {kPi / 3, 2 * kPi / 3, 2, 1, 1500}, {1.0, 2.0, 5, 2, 2500},     {1.0, 2.0, 7, 3, 3000},
      {0.7, 1.3, 13, 5, 3000},           {kPi / 3, kPi / 3, 3, 1, 1200}, {1.0, 2.0, 7, 3, 97},
  };
  for (const Case& c : cases) {
    const Polyline vs = trochoid(c.a2, c.a3, c.p, c.q, c.n);
    INFO("a2 " << c.a2 << " a3 " << c.a3 << " n " << c.p << "/" << c.q << " samples " << c.n);
    const SelfCrossings brute = check_fast_equals_brute(vs, true);
    // Open pieces of the same curve too.
    const Polyline half(vs.begin(), vs.begin() + static_cast<std::ptrdiff_t>(vs.size() / 2));
    check_fast_equals_brute(half, false);
    if (c.p == 7 && c.n > 100) CHECK(brute.crossings.size() > 0);
  }
}

TEST_CASE("samples_on_node: vertices landing on the node (0, 1, 0)", "[polyline_crossings][degenerate]") {
  // n = 1, a2 = a3 = pi/2 (report Fig. 3): the node (0, 1, 0) at theta2 = pi/2 and 3 pi/2,
  // which 8 uniform samples from 0 hit (up to the rounding of the double samples).
  const Polyline vs = trochoid(kPi / 2, kPi / 2, 1, 1, 8);
  REQUIRE(vs.size() == 8);
  CHECK((vs[2] - V(0, 1, 0)).norm() < 1e-15);
  CHECK((vs[6] - V(0, 1, 0)).norm() < 1e-15);
  const SelfCrossings brute = check_fast_equals_brute(vs, true);
  // Whatever the 1e-17 rounding decides, the node is met by the edges around vertices 2 and 6
  // (edges 1, 2 and 5, 6) and by nothing else.
  std::size_t near_node = 0;
  for (const auto* list : {&brute.crossings, &brute.touchings})
    for (const EdgePair& e : *list) {
      const bool a = e.i == 1 || e.i == 2, b = e.j == 5 || e.j == 6;
      CHECK((a && b));
      near_node += (a && b) ? 1 : 0;
    }
  INFO(describe(brute.crossings) << " / " << describe(brute.touchings));
  CHECK(near_node >= 1);
  // With the two vertices set exactly to the node, the four edge pairs touch at a shared vertex.
  Polyline exact = vs;
  exact[2] = V(0, 1, 0);
  exact[6] = V(0, 2, 0);  // the same direction, not normalised
  const SelfCrossings ex = check_fast_equals_brute(exact, true);
  const std::vector<EdgePair> expected = {{1, 5, ArcContact::touching},
                                          {1, 6, ArcContact::touching},
                                          {2, 5, ArcContact::touching},
                                          {2, 6, ArcContact::touching}};
  CHECK(ex.crossings.empty());
  CHECK(ex.touchings == expected);
}

TEST_CASE("run box intersection: the sweep (few runs) and CGAL's segment tree (many runs) agree", "[polyline_crossings]") {
  // Up to kSweepMaxBoxes run boxes the overlapping run pairs come from a sweep, above from
  // CGAL::box_self_intersection_d. The same polyline searched both ways, each against brute force.
  const Polyline vs = trochoid(1.0, 2.0, 13, 5, 3000);
  const SelfCrossings brute = sphtroch::exact_brute_force_crossings(vs, true);
  REQUIRE(brute.crossings.size() > 100);
  sphtroch::CrossingSearchOptions few;  // the defaults: a few hundred runs here
  sphtroch::CrossingSearchOptions many;  // one edge per run: 3000 boxes
  many.max_run_edges = 1;
  const SelfCrossings a = sphtroch::find_self_crossings(vs, true, few);
  const SelfCrossings b = sphtroch::find_self_crossings(vs, true, many);
  CHECK(a.boxes <= sphtroch::detail::kSweepMaxBoxes);
  CHECK(b.boxes > sphtroch::detail::kSweepMaxBoxes);
  CHECK(a.crossings == brute.crossings);
  CHECK(b.crossings == brute.crossings);
  CHECK(a.touchings == brute.touchings);
  CHECK(b.touchings == brute.touchings);
}

#ifdef SPHTROCH_EXE
namespace {
// All pairs of non-adjacent edges, each classified exactly, with a conservative prefilter: for
// unit vectors every point p of arc AB has |p - a| <= |b - a| (the chord grows with the angle
// along the arc, which is below pi), so arcs AB and CD can meet only if
// |a - c| <= |a - b| + |c - d|; 1e-9 of slack covers the rounding of the unit vectors.
std::size_t brute_force_crossing_count(const Polyline& vs, std::size_t* touchings) {
  const std::size_t n = vs.size();
  std::vector<double> len(n);
  for (std::size_t e = 0; e < n; ++e) len[e] = (vs[(e + 1) % n] - vs[e]).norm();
  std::size_t crossings = 0;
  *touchings = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through vertex 0
      const double reach = len[i] + len[j] + 1e-9;
      if ((vs[i] - vs[j]).squaredNorm() > reach * reach) continue;
      const ArcContact k = sphtroch::classify_arcs(vs[i], vs[(i + 1) % n], vs[j], vs[(j + 1) % n]);
      crossings += k == ArcContact::crossing;
      *touchings += k == ArcContact::touching || k == ArcContact::overlap;
    }
  return crossings;
}
}  // namespace

TEST_CASE("crossings CLI on a 1e6-vertex trochoid: the count of the 2e4-vertex brute force and of the root census",
          "[polyline_crossings][cli]") {
  // n = 7/3, a2 = 1, a3 = 2 (63 nodes, every one a transversal crossing of two branches).
  const sphtroch::GearTrain train(1.0, 2.0, sphtroch::Ratio(7, 3));
  // (ii) independent of any polyline: the one-dimensional root census of the curve.
  const sphtroch::RootCensus roots = sphtroch::root_census(train);
  std::size_t simple_crossings = 0;
  for (const sphtroch::Node& node : roots.nodes)
    simple_crossings += node.branches == 2 && node.kind == sphtroch::NodeKind::crossing;
  REQUIRE(simple_crossings == roots.nodes.size());  // so each node is one crossing pair of a fine polyline
  REQUIRE(roots.nodes.size() > 50);
  // (i) all-pairs exact classification on a 2e4-vertex sample of the same curve.
  std::size_t brute_touchings = 0;
  const std::size_t brute = brute_force_crossing_count(trochoid(1.0, 2.0, 7, 3, 20000), &brute_touchings);
  CHECK(brute_touchings == 0);
  CHECK(brute == roots.nodes.size());
  // The CLI, end to end: trace 1e6 samples to CSV (t dropped), then `crossings --json`.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sphtroch-crossings-1e6-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path csv = dir / "trochoid.csv", json = dir / "out.json";
  const std::string exe = std::string("'") + SPHTROCH_EXE + "'";
  // trace writes t,x,y,z; crossings reads x,y,z (the header line x,y,z is allowed).
  REQUIRE(std::system((exe + " trace --a2 1 --a3 2 --n 7/3 --samples 1000000 | cut -d, -f2- > '" + csv.string() + "'")
                          .c_str()) == 0);
  REQUIRE(std::system((exe + " crossings --json --input '" + csv.string() + "' > '" + json.string() + "'").c_str()) == 0);
  std::ifstream in(json);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove_all(dir);
  INFO(text);
  const auto field = [&text](const std::string& key) -> long {
    const std::size_t at = text.find("\"" + key + "\":");
    REQUIRE(at != std::string::npos);
    return std::strtol(text.c_str() + at + key.size() + 3, nullptr, 10);
  };
  CHECK(field("vertices") == 1000000);
  CHECK(field("crossings") == static_cast<long>(brute));
  CHECK(field("crossings") == static_cast<long>(roots.nodes.size()));
  CHECK(field("touchings") == 0);
}
#endif

TEST_CASE("two_runs_closed_loop: two runs sharing both ends", "[polyline_crossings][degenerate]") {
  // Up along one monotone path, back down along another that crosses it near t = 1/2: with
  // unlimited runs the closed polyline is exactly two runs, adjacent at both ends.
  const V c(0.2, 0.3, 0.9), d(0.3, 0.25, 0.2), w(0.15, -0.15, 0.0);
  Polyline vs;
  for (int i = 0; i <= 20; ++i) vs.push_back(c + (i / 20.0) * d + 0.05 * std::sin(2 * kPi * i / 20.0) * w);
  for (int i = 19; i >= 1; --i) vs.push_back(c + ((i + 0.5) / 20.0) * d - 0.05 * std::sin(2 * kPi * (i + 0.5) / 20.0) * w);
  sphtroch::CrossingSearchOptions opt;
  opt.max_run_edges = 100000;
  opt.max_run_extent = 10.0;
  CHECK(sphtroch::find_self_crossings(vs, true, opt).boxes == 2);
  const SelfCrossings brute = check_fast_equals_brute(vs, true);
  // The up path meets the down edge 30 (t from 0.525 to 0.475) at its vertex 10 (t = 1/2), up to rounding.
  REQUIRE(brute.crossings.size() + brute.touchings.size() == 1);
  const EdgePair e = brute.crossings.empty() ? brute.touchings[0] : brute.crossings[0];
  CHECK((e.i == 9 || e.i == 10));
  CHECK(e.j == 30);
}

TEST_CASE("visit_close_edge_pairs visits every pair closer than the margin", "[polyline_crossings]") {
  const Polyline vs = trochoid(1.0, 2.0, 7, 3, 600);
  const double margin = 0.05;
  const std::size_t n = vs.size();
  std::set<std::pair<std::size_t, std::size_t>> visited;
  bool duplicate = false;
  const bool completed = sphtroch::visit_close_edge_pairs(vs, true, margin, [&](std::size_t i, std::size_t j) {
    CHECK(i < j);
    duplicate = duplicate || !visited.insert({i, j}).second;
    return true;
  });
  CHECK(completed);
  CHECK_FALSE(duplicate);
  // Brute force on sampled arc points: a sampled distance below the margin proves the arcs are closer.
  std::vector<std::vector<V>> samples(n);
  for (std::size_t e = 0; e < n; ++e)
    for (int s = 0; s <= 8; ++s) {
      const double t = s / 8.0;
      samples[e].push_back(((1 - t) * vs[e] + t * vs[(e + 1) % n]).normalized());
    }
  std::size_t required = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      double best = 10;
      for (const V& p : samples[i])
        for (const V& q : samples[j]) best = std::min(best, (p - q).norm());
      if (best < margin) {
        ++required;
        INFO("edges " << i << " " << j << " at distance " << best);
        CHECK(visited.count({i, j}) == 1);
      }
    }
  CHECK(required > 100);
  // Same with per-edge boxes.
  std::set<std::pair<std::size_t, std::size_t>> visited_edges;
  sphtroch::visit_close_edge_pairs(
      vs, true, margin, [&](std::size_t i, std::size_t j) { visited_edges.insert({i, j}); }, CandidateSearch::edges);
  CHECK(visited_edges.size() >= required);
}

TEST_CASE("visit_close_edge_pairs stops when the visitor returns false", "[polyline_crossings]") {
  const Polyline vs = trochoid(1.0, 2.0, 7, 3, 2000);
  for (CandidateSearch search : {CandidateSearch::runs, CandidateSearch::edges}) {
    int calls = 0;
    const bool completed = sphtroch::visit_close_edge_pairs(
        vs, true, 0.01, [&](std::size_t, std::size_t) { return ++calls < 3; }, search);
    CHECK_FALSE(completed);
    CHECK(calls == 3);
  }
}

TEST_CASE("invalid polylines throw InvalidInput naming the vertices", "[polyline_crossings]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto throws_vertices = [](const Polyline& vs, bool closed, const std::string& needle) {
    try {
      sphtroch::find_self_crossings(vs, closed);
    } catch (const sphtroch::InvalidInput& e) {
      INFO(e.what());
      CHECK(e.field() == "vertices");
      CHECK(std::string(e.what()).find(needle) != std::string::npos);
      return;
    }
    FAIL("no exception for " << needle);
  };
  throws_vertices({V(1, 0, 0), V(0, 1, 0)}, true, "too few");
  throws_vertices({V(1, 0, 0)}, false, "too few");
  throws_vertices({}, false, "too few");
  throws_vertices({V(1, 0, 0), V(0, 1, 0), V(nan, 0, 1)}, true, "index 2");
  throws_vertices({V(1, 0, 0), V(0, inf, 0), V(0, 0, 1)}, true, "index 1");
  throws_vertices({V(1, 0, 0), V(0, 0, 0), V(0, 0, 1)}, true, "index 1");
  throws_vertices({V(1, 0, 0), V(0, 1, 0), V(0, 2, 0), V(0, 0, 1)}, true, "index 1");  // same direction
  throws_vertices({V(1, 0, 0), V(0, 1, 0), V(0, -3, 0), V(0, 0, 1)}, false, "antipodal");
  throws_vertices({V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 0)}, true, "index 3");  // closing edge
  // One pass checks vertices and edges: a bad vertex is still named before an earlier bad edge,
  // and the first bad edge before a later one.
  throws_vertices({V(1, 0, 0), V(2, 0, 0), V(0, 1, 0), V(0, 0, 1), V(nan, 0, 1)}, true, "index 4");
  throws_vertices({V(1, 0, 0), V(2, 0, 0), V(0, 1, 0), V(0, -1, 0), V(0, 0, 1)}, true, "index 0");
  throws_vertices({V(1, 0, 0), V(0, 1, 0), V(0, -1, 0), V(0, 0, 1), V(0, 0, 2)}, false, "index 1");
  CHECK_NOTHROW(sphtroch::find_self_crossings({V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 0)}, false));
  CHECK_NOTHROW(sphtroch::find_self_crossings({V(1, 0, 0), V(0, 1, 0)}, false));
  CHECK_THROWS_AS(sphtroch::exact_brute_force_crossings({V(1, 0, 0), V(-1, 0, 0)}, false), sphtroch::InvalidInput);
  sphtroch::CrossingSearchOptions bad;
  bad.margin = -1;
  CHECK_THROWS_AS(sphtroch::find_self_crossings({V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)}, true, bad),
                  sphtroch::InvalidInput);
  CHECK_THROWS_AS(sphtroch::visit_close_edge_pairs({V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)}, true, nan,
                                                   [](std::size_t, std::size_t) { return true; }),
                  sphtroch::InvalidInput);
}

TEST_CASE("triangles and tiny polylines have no non-adjacent pairs", "[polyline_crossings]") {
  const SelfCrossings tri = sphtroch::find_self_crossings({V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)}, true);
  CHECK(tri.crossings.empty());
  CHECK(tri.touchings.empty());
  CHECK(tri.candidate_pairs == 0);
  // An open polyline of 3 edges folding onto itself at non-adjacent edges 0 and 2.
  const SelfCrossings z = check_fast_equals_brute({V(1, 0, -1), V(1, 0, 1), V(1, 1, -1), V(1, 1, 1)}, false);
  CHECK(z.crossings.empty());
  const Polyline cross = {V(1, -1, 0), V(1, 1, 0), V(1, 0, 1), V(1, 0, -1)};
  const SelfCrossings x = check_fast_equals_brute(cross, false);
  const std::vector<EdgePair> expected = {{0, 2, ArcContact::crossing}};
  CHECK(x.crossings == expected);
}

// ---- Timing (hidden: not run by ctest). ./test_exact "[.timing]" ----
TEST_CASE("timing: closed trochoid a2 = 1, a3 = 2, n = 7/3", "[.timing]") {
  for (std::size_t n : {std::size_t(10000), std::size_t(100000), std::size_t(1000000)}) {
    const Polyline vs = trochoid(1.0, 2.0, 7, 3, n);
    for (CandidateSearch search : {CandidateSearch::runs, CandidateSearch::edges}) {
      std::vector<double> times;
      SelfCrossings r;
      for (int rep = 0; rep < 7; ++rep) {
        sphtroch::CrossingSearchOptions opt;
        opt.search = search;
        const auto t0 = std::chrono::steady_clock::now();
        r = sphtroch::find_self_crossings(vs, true, opt);
        times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
      std::sort(times.begin(), times.end());
      std::printf("n %8zu search %-5s median %.4f s min %.4f s crossings %zu touchings %zu boxes %zu candidates %zu "
                  "predicates %zu\n",
                  n, search == CandidateSearch::runs ? "runs" : "edges", times[times.size() / 2], times[0],
                  r.crossings.size(), r.touchings.size(), r.boxes, r.candidate_pairs, r.predicates);
    }
  }
}

TEST_CASE("arc_crossing_point: on both circles, on both arcs, either order, degenerate pairs refused", "[crossings][point]") {
  const double s = std::sqrt(0.5);
  const Eigen::Vector3d a(1, 0, 0), b(0, 1, 0);                              // the equator, x to y
  const Eigen::Vector3d c = Eigen::Vector3d(s, s, -0.5).normalized(), d = Eigen::Vector3d(s, s, 0.5).normalized();
  const Eigen::Vector3d expected(s, s, 0);                                    // meridian at 45 deg meets it
  for (const auto& x : {sphtroch::arc_crossing_point(a, b, c, d), sphtroch::arc_crossing_point(c, d, a, b),
                        sphtroch::arc_crossing_point(b, a, d, c), sphtroch::arc_crossing_point(d, c, b, a)}) {
    CHECK((x - expected).norm() < 4e-16);
    CHECK(std::abs(x.norm() - 1.0) < 4e-16);
  }
  // The crossing of report Fig. 3's trajectory (a2 = a3 = pi/2, n = 1) is its node (0, 1, 0) of
  // Eq. 25, up to the chord error of the sampling (~h^2, h = 2 pi / 4000).
  const sphtroch::GearTrain fig3(kPi / 2, kPi / 2, sphtroch::Ratio(1));
  const auto tr = sphtroch::sample_period(sphtroch::TracerCurve<double>(fig3), 4000);
  const sphtroch::SelfCrossings sc = sphtroch::find_self_crossings(tr.points, true);
  REQUIRE(sc.crossings.size() == 1);
  const auto& e = sc.crossings[0];
  const std::size_t n = tr.points.size();
  const Eigen::Vector3d x = sphtroch::arc_crossing_point(tr.points[e.i], tr.points[(e.i + 1) % n], tr.points[e.j],
                                                         tr.points[(e.j + 1) % n]);
  CHECK((x - Eigen::Vector3d(0, 1, 0)).norm() < 1e-5);
  // One great circle twice, or a zero-length arc: refused.
  CHECK(sphtroch::test::expect_invalid([&] { sphtroch::arc_crossing_point(a, b, b, a); }).field() == "arcs");
  CHECK(sphtroch::test::expect_invalid([&] { sphtroch::arc_crossing_point(a, a, c, d); }).field() == "arcs");
}

namespace {
// Independent random unit vectors: long arcs, Theta(N^2) crossings (issue 17, D2).
Polyline random_directions(std::uint32_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  Polyline vs(n);
  for (V& p : vs) p = V(g(rng), g(rng), g(rng)) * (1.0 + 0.1 * static_cast<double>(seed % 3));
  return vs;
}
}  // namespace

TEST_CASE("count_self_crossings and visit_self_crossings equal the brute force (D2)", "[polyline_crossings][count]") {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    for (bool closed : {true, false}) {
      const Polyline vs = seed == 3 ? random_polyline(seed, 400, 0.3) : random_directions(seed, 300);
      const SelfCrossings brute = sphtroch::exact_brute_force_crossings(vs, closed);
      REQUIRE(brute.crossings.size() > (seed == 3 ? 0u : 1000u));  // the random directions cross a lot
      for (CandidateSearch search : {CandidateSearch::runs, CandidateSearch::edges}) {
        sphtroch::CrossingSearchOptions opt;
        opt.search = search;
        const sphtroch::CrossingCounts c = sphtroch::count_self_crossings(vs, closed, opt);
        CHECK(c.complete());
        CHECK(c.crossings == brute.crossings.size());
        CHECK(c.touchings == brute.touchings.size());
        CHECK(c.vertices == vs.size());
        std::vector<EdgePair> seen;
        const sphtroch::CrossingCounts v =
            sphtroch::visit_self_crossings(vs, closed, [&](const EdgePair& e) { seen.push_back(e); }, opt);
        std::sort(seen.begin(), seen.end());
        std::vector<EdgePair> all = brute.crossings;
        all.insert(all.end(), brute.touchings.begin(), brute.touchings.end());
        std::sort(all.begin(), all.end());
        CHECK(seen == all);
        CHECK(v.candidate_pairs == c.candidate_pairs);
      }
    }
  }
}

TEST_CASE("crossing search limits: max_contacts, max_work, the up-front estimate (D2)", "[polyline_crossings][count]") {
  const Polyline vs = random_directions(7, 400);
  const SelfCrossings brute = sphtroch::exact_brute_force_crossings(vs, true);
  const std::size_t total = brute.crossings.size() + brute.touchings.size();
  REQUIRE(total > 1000);
  sphtroch::CrossingSearchOptions opt;
  opt.max_contacts = total;  // exactly enough: complete
  CHECK(sphtroch::count_self_crossings(vs, true, opt).complete());
  opt.max_contacts = total - 1;  // one short: stops at the last one found
  sphtroch::CrossingCounts c = sphtroch::count_self_crossings(vs, true, opt);
  CHECK(c.stop == sphtroch::SearchStop::contacts);
  CHECK(c.crossings + c.touchings == total);
  opt.max_contacts = 100;
  std::size_t visited = 0;
  c = sphtroch::visit_self_crossings(vs, true, [&](const EdgePair&) { ++visited; }, opt);
  CHECK(c.stop == sphtroch::SearchStop::contacts);
  CHECK(c.crossings + c.touchings == 101);
  CHECK(visited == 100);
  CHECK_THROWS_AS(sphtroch::check_search_complete(c, opt, "max-crossings", "max-work"), sphtroch::InvalidInput);
  // find_self_crossings keeps what it found before the limit, a subset of the brute force's.
  const SelfCrossings partial = sphtroch::find_self_crossings(vs, true, opt);
  CHECK(partial.stop == sphtroch::SearchStop::contacts);
  CHECK(partial.crossings.size() + partial.touchings.size() == 100);
  for (const EdgePair& e : partial.crossings)
    CHECK(std::binary_search(brute.crossings.begin(), brute.crossings.end(), e));
  // Work: the whole search's work is enough, one unit less is not.
  sphtroch::CrossingSearchOptions w;
  const sphtroch::CrossingCounts full = sphtroch::count_self_crossings(vs, true, w);
  REQUIRE(full.complete());
  w.max_work = full.work();
  CHECK(sphtroch::count_self_crossings(vs, true, w).complete());
  w.max_work = full.work() - 1;
  c = sphtroch::count_self_crossings(vs, true, w);
  CHECK((c.stop == sphtroch::SearchStop::work || c.stop == sphtroch::SearchStop::estimate));
  CHECK(c.work() <= full.work());
  // The up-front estimate (more than 2048 run boxes: the CGAL path) refuses a hopeless search
  // before any box pair is examined; its estimate is within 20% of the exact box pair count.
  const Polyline big = random_directions(8, 5000);
  const sphtroch::CrossingCounts exact_big = sphtroch::count_self_crossings(big, true);
  REQUIRE(exact_big.complete());
  REQUIRE(exact_big.boxes > 2048);
  sphtroch::CrossingSearchOptions e;
  e.max_work = exact_big.box_pairs / 4;
  c = sphtroch::count_self_crossings(big, true, e);
  CHECK(c.stop == sphtroch::SearchStop::estimate);
  CHECK(c.box_pairs == 0);
  CHECK(c.candidate_pairs == 0);
  CHECK(std::fabs(c.estimated_box_pairs - static_cast<double>(exact_big.box_pairs)) <
        0.2 * static_cast<double>(exact_big.box_pairs));
  // Near the limit the estimate does not refuse; the exact count then stops the search.
  e.max_work = exact_big.box_pairs * 3 / 4;
  c = sphtroch::count_self_crossings(big, true, e);
  CHECK(c.stop == sphtroch::SearchStop::work);
  CHECK(c.work() == e.max_work + 1);
  try {
    sphtroch::check_search_complete(c, e, "max-crossings", "max-work");
    FAIL("not refused");
  } catch (const sphtroch::InvalidInput& x) {
    CHECK(x.field() == "max-work");
    CHECK(x.value() == std::to_string(e.max_work));
  }
}

TEST_CASE("arc predicates refuse degenerate arcs with InvalidInput instead of aborting (D3)", "[arc_predicates]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const V x(1, 0, 0), y(0, 1, 0), z(0, 0, 1), zero(0, 0, 0);
  CHECK_THROWS_AS(sphtroch::relate_vertices(zero, x), sphtroch::InvalidInput);
  CHECK_THROWS_AS(sphtroch::relate_vertices(x, V(nan, 0, 1)), sphtroch::InvalidInput);
  CHECK_THROWS_AS(sphtroch::classify_arcs(x, V(2, 0, 0), y, z), sphtroch::InvalidInput);
  CHECK_THROWS_AS(sphtroch::classify_arcs(x, y, z, V(0, 0, -1)), sphtroch::InvalidInput);
  CHECK_THROWS_AS(sphtroch::point_on_arc(zero, x, y), sphtroch::InvalidInput);
  CHECK_THROWS_AS(sphtroch::point_on_arc(z, x, x), sphtroch::InvalidInput);
  CHECK_THROWS_AS(sphtroch::arc_bounding_box(x, V(-1, 0, 0)), sphtroch::InvalidInput);
  // Unchecked: where the degenerate arc is detected (no arc plane), an exception, not abort().
  CHECK_THROWS_AS(sphtroch::classify_arcs_unchecked(x, V(3, 0, 0), V(1, 1, 0), V(1, -1, 0)), sphtroch::InvalidInput);
}
