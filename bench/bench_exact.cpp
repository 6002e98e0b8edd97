// bench/bench_exact.cpp — the studies that need CGAL (the only CGAL translation unit of the bench):
//   b_crossings   the exact crossing search versus N on trochoids with many nodes;
//   e_s2          the same polylines through Google S2 (when built), pairs compared to ours;
//   c_predicates  exact versus plain double predicates on hard cases: time, wrong decisions;
//   d_nodes       node position error versus time: uniform sampling + polyline chords (no
//                 refinement) versus the census (coarse sampling + Newton), against the closed
//                 forms of Eqs. 25, 39b, 44b;
//   f_classify    sphtroch::classify with the defaults (what `sphtroch classify` runs), p, q <= 5.
#include "bench_common.hpp"

#include "sphtroch/map/criteria.hpp"
#include "sphtroch/exact/arc_predicates.hpp"
#include "sphtroch/classify.hpp"
#include "sphtroch/exact/polyline_census.hpp"
#include "sphtroch/exact/self_crossings.hpp"
#include "sphtroch/core/sampling.hpp"

#ifdef SPHTROCH_BENCH_HAVE_S2
#include "s2_crossings.hpp"
#endif

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace sphtroch_bench {
namespace {

using sphtroch::ArcContact;
using V = Eigen::Vector3d;
using Polyline = std::vector<V>;
constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------- b: crossing search vs N

void bm_crossings(benchmark::State& state, CurveSpec spec, std::size_t n) {
  const Polyline& vs = cached_trochoid(spec, n);
  sphtroch::SelfCrossings r;
  state.counters["peak_bytes"] =
      static_cast<double>(peak_heap_of([&] { r = sphtroch::find_self_crossings(vs, true); }));
  for (auto _ : state) {
    sphtroch::SelfCrossings x = sphtroch::find_self_crossings(vs, true);
    benchmark::DoNotOptimize(x.crossings.data());
  }
  state.counters["vertices"] = static_cast<double>(n);
  state.counters["crossings"] = static_cast<double>(r.crossings.size());
  state.counters["touchings"] = static_cast<double>(r.touchings.size());
  state.counters["boxes"] = static_cast<double>(r.boxes);
  state.counters["candidate_pairs"] = static_cast<double>(r.candidate_pairs);
  state.counters["predicates"] = static_cast<double>(r.predicates);
  if (n <= 3000) {  // the O(N^2) reference, affordable here (the tests check larger cases)
    const sphtroch::SelfCrossings brute = sphtroch::exact_brute_force_crossings(vs, true);
    state.counters["equals_brute_force"] = (brute.crossings == r.crossings && brute.touchings == r.touchings) ? 1 : 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

// ---------------------------------------------------------------- e: Google S2

#ifdef SPHTROCH_BENCH_HAVE_S2
void bm_s2(benchmark::State& state, CurveSpec spec, std::size_t n) {
  const Polyline& vs = cached_trochoid(spec, n);
  std::vector<EdgeIndexPair> s2;
  state.counters["peak_bytes"] = static_cast<double>(peak_heap_of([&] { s2 = s2_interior_crossings(vs, true); }));
  for (auto _ : state) {
    std::vector<EdgeIndexPair> x = s2_interior_crossings(vs, true);
    benchmark::DoNotOptimize(x.data());
  }
  const sphtroch::SelfCrossings ours = sphtroch::find_self_crossings(vs, true);
  bool same = ours.crossings.size() == s2.size();
  for (std::size_t k = 0; same && k < s2.size(); ++k)
    same = ours.crossings[k].i == s2[k].i && ours.crossings[k].j == s2[k].j;
  state.counters["vertices"] = static_cast<double>(n);
  state.counters["crossings"] = static_cast<double>(s2.size());
  state.counters["ours_crossings"] = static_cast<double>(ours.crossings.size());
  state.counters["same_pairs"] = same ? 1 : 0;
  if (!same) state.SkipWithError("S2 and the exact search disagree on the crossing pairs");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
#endif

// ---------------------------------------------------------------- c: exact vs plain predicates

/// The same decision procedure as arc_predicates.hpp (classify_arcs_unchecked), with every sign
/// taken from the plain double evaluation: det[a, b, c] as (a x b) . c, 2x2 minors as p_i q_j - p_j q_i.
int plain_det_sign(const V& a, const V& b, const V& c) {
  const double d = a.cross(b).dot(c);
  return (d > 0) - (d < 0);
}
int plain_minor_sign(const V& p, const V& q, int k) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double d = p[i] * q[j] - p[j] * q[i];
  return (d > 0) - (d < 0);
}
enum class Where { outside, end, interior };
Where plain_locate(const V& p, const V& a, const V& b) {
  int k = 0, s = 0;
  for (; k < 3; ++k)
    if ((s = plain_minor_sign(a, b, k)) != 0) break;
  if (s == 0) return Where::outside;  // a x b rounds to 0: the plain version cannot tell
  const int alpha = plain_minor_sign(p, b, k) * s, beta = plain_minor_sign(a, p, k) * s;
  if (alpha < 0 || beta < 0) return Where::outside;
  return (alpha > 0 && beta > 0) ? Where::interior : Where::end;
}
ArcContact classify_plain(const V& a, const V& b, const V& c, const V& d) {
  const int sc = plain_det_sign(a, b, c), sd = plain_det_sign(a, b, d);
  if (sc == sd && sc != 0) return ArcContact::none;
  const int sa = plain_det_sign(c, d, a), sb = plain_det_sign(c, d, b);
  if (sa == sb && sa != 0) return ArcContact::none;
  if (sc != 0 && sd != 0 && sa != 0 && sb != 0) return sa == sd ? ArcContact::crossing : ArcContact::none;
  if (sc == 0 && sd == 0) {
    const Where lc = plain_locate(c, a, b), ld = plain_locate(d, a, b), la = plain_locate(a, c, d),
                lb = plain_locate(b, c, d);
    if (lc == Where::interior || ld == Where::interior || la == Where::interior || lb == Where::interior)
      return ArcContact::overlap;
    if (lc == Where::end && ld == Where::end) return ArcContact::overlap;
    if (lc != Where::outside || ld != Where::outside || la != Where::outside || lb != Where::outside)
      return ArcContact::touching;
    return ArcContact::none;
  }
  if ((sc == 0 && plain_locate(c, a, b) != Where::outside) || (sd == 0 && plain_locate(d, a, b) != Where::outside) ||
      (sa == 0 && plain_locate(a, c, d) != Where::outside) || (sb == 0 && plain_locate(b, c, d) != Where::outside))
    return ArcContact::touching;
  return ArcContact::none;
}

struct HardPolyline {
  Polyline vertices;
  bool closed = true;
};

/// One hard case: a family of polylines and every box-overlapping pair of non-adjacent edges
/// of each (the pairs a search hands to the predicates).
struct HardCase {
  std::string name;
  std::vector<HardPolyline> polylines;
  struct Pair {
    std::uint32_t polyline, i, j;
  };
  std::vector<Pair> candidates;
};

/// A fixed rotation (axis (1, 2, 3), 0.7 rad) applied to the trochoid families, so that no
/// coordinate is exactly zero by symmetry (axis-aligned data makes plain arithmetic exact).
V rotated(const V& v) {
  static const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, V(1, 2, 3).normalized()).toRotationMatrix();
  return r * v;
}

Polyline trochoid_polyline(double a2, double a3, std::int64_t p, std::int64_t q, std::size_t n) {
  const sphtroch::GearTrain train(a2, a3, sphtroch::Ratio(p, q));
  Polyline vs = sphtroch::sample_period(sphtroch::TracerCurve<double>(train), n).points;
  for (V& v : vs) v = rotated(v);
  return vs;
}

/// a2 values spread over (0, pi), avoiding the special values.
std::vector<double> a2_family(int count) {
  std::vector<double> out;
  for (int k = 0; k < count; ++k) out.push_back(0.3 + 2.5 * (k + 0.37) / count);
  return out;
}

const std::vector<HardCase>& hard_cases() {
  static std::vector<HardCase> cases;
  if (!cases.empty()) return cases;
  const int family = quick_mode() ? 8 : 40;
  // n = 1, a3 = pi/2, any a2: P(pi/2) = P(-pi/2) = (0, 1, 0), the Eq. 25 node; N divisible by 4
  // puts samples N/4 and 3N/4 on it, up to the rounding of the double samples.
  HardCase on_node{"samples_on_node_n1", {}, {}};
  HardCase snapped{"samples_exactly_on_node_n1", {}, {}};
  for (double a2 : a2_family(family))
    for (std::size_t n : {8, 16, 64, 256, 1024}) {
      Polyline vs = trochoid_polyline(a2, kPi / 2, 1, 1, n);
      on_node.polylines.push_back({vs, true});
      vs[3 * n / 4] = vs[n / 4];  // both samples the same double vector: non-adjacent edges share it
      snapped.polylines.push_back({vs, true});
    }
  cases.push_back(on_node);
  cases.push_back(snapped);
  // n = 2, a3 = pi - a2: the two Eq. 39b nodes merge into a tangency at the south pole, where the
  // samples at theta2 = 0 and pi land (Table 1 row (g) and its neighbours).
  HardCase pole{"pole_tangency_n2", {}, {}};
  for (double a2 : a2_family(family))
    for (std::size_t n : {16, 64, 256, 1024}) pole.polylines.push_back({trochoid_polyline(a2, kPi - a2, 2, 1, n), true});
  cases.push_back(pole);
  // n = 3/4, a3 = pi - a2: three branches through the south pole, each sampled on it.
  HardCase pole3{"pole_three_branches_n3_4", {}, {}};
  for (double a2 : a2_family(family / 2))
    for (std::size_t n : {192, 768, 3072}) pole3.polylines.push_back({trochoid_polyline(a2, kPi - a2, 3, 4, n), true});
  cases.push_back(pole3);
  // n = 2, a3 = pi - a2 - d: two crossings about sqrt(d) apart next to the pole.
  HardCase near{"near_tangency_n2", {}, {}};
  for (double a2 : a2_family(family / 4))
    for (double d : {1e-6, 1e-9, 1e-12, 1e-15})
      near.polylines.push_back({trochoid_polyline(a2, kPi - a2 - d, 2, 1, 1024), true});
  cases.push_back(near);
  // Vertices drawn from {-2..2}^3, then normalised: cocircular and coincident in exact terms
  // before normalisation, nearly so after.
  {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coord(-2, 2);
    HardCase c{"normalised_integer_grid", {}, {}};
    HardPolyline pl{{}, false};
    while (pl.vertices.size() < (quick_mode() ? 500u : 2000u)) {
      V v(coord(rng), coord(rng), coord(rng));
      if (v.isZero()) continue;
      v.normalize();
      if (!pl.vertices.empty() && sphtroch::relate_vertices(pl.vertices.back(), v) != sphtroch::VertexRelation::distinct)
        continue;
      pl.vertices.push_back(v);
    }
    c.polylines.push_back(pl);
    cases.push_back(c);
  }
  for (HardCase& c : cases)
    for (std::uint32_t k = 0; k < c.polylines.size(); ++k)
      sphtroch::visit_close_edge_pairs(c.polylines[k].vertices, c.polylines[k].closed, 0.0,
                                       [&](std::size_t i, std::size_t j) {
                                         c.candidates.push_back({k, static_cast<std::uint32_t>(i),
                                                                 static_cast<std::uint32_t>(j)});
                                       });
  return cases;
}

void bm_predicates(benchmark::State& state, std::size_t case_index, bool exact) {
  const HardCase& c = hard_cases()[case_index];
  // The four vertices of candidate pair k.
  const auto arcs = [&c](const HardCase::Pair& pr, const V*& a, const V*& b, const V*& cc, const V*& d) {
    const Polyline& v = c.polylines[pr.polyline].vertices;
    const std::size_t n = v.size();
    a = &v[pr.i];
    b = &v[pr.i + 1 == n ? 0 : pr.i + 1];
    cc = &v[pr.j];
    d = &v[pr.j + 1 == n ? 0 : pr.j + 1];
  };
  std::size_t wrong = 0, missed = 0, spurious = 0, exact_cross = 0, exact_touch = 0;
  for (const HardCase::Pair& pr : c.candidates) {
    const V *a, *b, *cc, *d;
    arcs(pr, a, b, cc, d);
    const ArcContact e = sphtroch::classify_arcs(*a, *b, *cc, *d);
    const ArcContact p = classify_plain(*a, *b, *cc, *d);
    exact_cross += e == ArcContact::crossing;
    exact_touch += e == ArcContact::touching || e == ArcContact::overlap;
    if (e != p) {
      ++wrong;
      missed += e == ArcContact::crossing;
      spurious += p == ArcContact::crossing;
    }
  }
  for (auto _ : state) {
    std::size_t hits = 0;
    for (const HardCase::Pair& pr : c.candidates) {
      const V *a, *b, *cc, *d;
      arcs(pr, a, b, cc, d);
      const ArcContact k = exact ? sphtroch::detail::classify_arcs_unchecked(*a, *b, *cc, *d, nullptr)
                                 : classify_plain(*a, *b, *cc, *d);
      hits += k != ArcContact::none;
    }
    benchmark::DoNotOptimize(hits);
  }
  state.counters["polylines"] = static_cast<double>(c.polylines.size());
  state.counters["candidates"] = static_cast<double>(c.candidates.size());
  state.counters["exact_crossings"] = static_cast<double>(exact_cross);
  state.counters["exact_touchings"] = static_cast<double>(exact_touch);
  state.counters["wrong_decisions"] = static_cast<double>(wrong);  // plain kind != exact kind
  state.counters["missed_crossings"] = static_cast<double>(missed);
  state.counters["spurious_crossings"] = static_cast<double>(spurious);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * c.candidates.size()));
}

// ---------------------------------------------------------------- d: node position error vs time

struct NodeCase {
  std::string name;
  sphtroch::GearTrain train;
  std::vector<V> expected;  // the closed forms
};

const std::vector<NodeCase>& node_cases() {
  static std::vector<NodeCase> cases;
  if (!cases.empty()) return cases;
  {  // n = 1: Eq. 24 holds strictly (a2/2 = 0.5 < 1.2 < pi - 0.5): one node, Eq. 25.
    NodeCase c{"eq25_n1", sphtroch::GearTrain(1.0, 1.2, sphtroch::Ratio(1)), {}};
    for (const auto& nd : sphtroch::nodes_eq25(c.train)) c.expected.push_back(nd.position);
    cases.push_back(c);
  }
  {  // n = 2, a2 = 1, a3 = 1.5: Eqs. 43 and 46 hold strictly: two nodes of Eq. 39b, two of Eq. 44b.
    NodeCase c{"eq39b_44b_n2", sphtroch::GearTrain(1.0, 1.5, sphtroch::Ratio(2)), {}};
    for (const auto& nd : sphtroch::nodes_eq39b(c.train)) c.expected.push_back(nd.position);
    for (const auto& nd : sphtroch::nodes_eq44b(c.train)) c.expected.push_back(nd.position);
    cases.push_back(c);
  }
  return cases;
}

/// Largest distance from an expected node to the nearest estimate (inf if there is none).
double node_error(const std::vector<V>& expected, const std::vector<V>& found) {
  double worst = 0.0;
  for (const V& e : expected) {
    double best = std::numeric_limits<double>::infinity();
    for (const V& f : found) best = std::min(best, (e - f).norm());
    worst = std::max(worst, best);
  }
  return worst;
}

/// No refinement: the exact crossings of the uniform polyline, each estimated by the
/// intersection of the two chords' great circles, X = (a x b) x (c x d), on the side of the arcs.
std::vector<V> chord_nodes(const sphtroch::GearTrain& train, std::size_t n) {
  const Polyline vs = sphtroch::sample_period(sphtroch::TracerCurve<double>(train), n).points;
  const sphtroch::SelfCrossings sc = sphtroch::find_self_crossings(vs, true);
  std::vector<V> out;
  out.reserve(sc.crossings.size());
  for (const sphtroch::EdgePair& e : sc.crossings) {
    const V& a = vs[e.i];
    const V& b = vs[e.i + 1 == n ? 0 : e.i + 1];
    const V& c = vs[e.j];
    const V& d = vs[e.j + 1 == n ? 0 : e.j + 1];
    V x = a.cross(b).cross(c.cross(d)).normalized();
    if (x.dot(a + b) < 0) x = -x;
    out.push_back(x);
  }
  return out;
}

void bm_nodes_uniform(benchmark::State& state, std::size_t case_index, std::size_t n) {
  const NodeCase& c = node_cases()[case_index];
  const std::vector<V> found = chord_nodes(c.train, n);
  for (auto _ : state) {
    std::vector<V> x = chord_nodes(c.train, n);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["samples"] = static_cast<double>(n);
  state.counters["nodes_expected"] = static_cast<double>(c.expected.size());
  state.counters["nodes_found"] = static_cast<double>(found.size());
  state.counters["max_error"] = node_error(c.expected, found);
}

void bm_nodes_census(benchmark::State& state, std::size_t case_index, std::size_t n) {
  const NodeCase& c = node_cases()[case_index];
  sphtroch::PolylineCensusSettings settings;
  settings.samples = n;
  const sphtroch::PolylineCensus census = sphtroch::polyline_census(c.train, settings);
  for (auto _ : state) {
    sphtroch::PolylineCensus x = sphtroch::polyline_census(c.train, settings);
    benchmark::DoNotOptimize(x.nodes.data());
  }
  std::vector<V> found;
  for (const sphtroch::Node& nd : census.nodes) found.push_back(nd.position);
  state.counters["samples"] = static_cast<double>(census.samples);
  state.counters["nodes_expected"] = static_cast<double>(c.expected.size());
  state.counters["nodes_found"] = static_cast<double>(found.size());
  state.counters["max_error"] = node_error(c.expected, found);
  state.counters["newton_steps"] = static_cast<double>(census.work.newton_steps);
}

// ---------------------------------------------------------------- f: classify with the defaults

struct ClassifyCase {
  std::string name;
  double a2, a3;
  std::int64_t p, q;
};

const std::vector<ClassifyCase>& classify_cases() {
  static const std::vector<ClassifyCase> cases = {
      {"n1", 1.0, 1.2, 1, 1},     {"n2", 1.0, 1.5, 2, 1},     {"n3_2", 1.0, 2.0, 3, 2},
      {"n5_3", 1.0, 2.0, 5, 3},   {"n4_5", 1.0, 2.0, 4, 5},   {"n5_4", 0.7, 1.3, 5, 4},
      {"n-5_2", 1.0, 2.0, -5, 2}, {"n5_1", 1.0, 2.0, 5, 1},
  };
  return cases;
}

void bm_classify(benchmark::State& state, std::size_t case_index) {
  const ClassifyCase& k = classify_cases()[case_index];
  const sphtroch::GearTrain train(k.a2, k.a3, sphtroch::Ratio(k.p, k.q));
  sphtroch::Classification r = sphtroch::classify(train);
  for (auto _ : state) {
    sphtroch::Classification x = sphtroch::classify(train);
    benchmark::DoNotOptimize(x.nodes.data());
  }
  std::vector<V> expected, found;
  if (k.p == 1 && k.q == 1)
    for (const auto& nd : sphtroch::nodes_eq25(train)) expected.push_back(nd.position);
  if (k.p == 2 && k.q == 1) {
    for (const auto& nd : sphtroch::nodes_eq39b(train)) expected.push_back(nd.position);
    for (const auto& nd : sphtroch::nodes_eq44b(train)) expected.push_back(nd.position);
  }
  for (const sphtroch::Node& nd : r.nodes) found.push_back(nd.position);
  state.counters["nodes"] = static_cast<double>(r.nodes.size());
  state.counters["agreement"] = r.agreement.ok() ? 1 : 0;
  state.counters["nodes_expected"] = static_cast<double>(expected.size());
  state.counters["max_error"] = expected.empty() ? -1.0 : node_error(expected, found);
}

}  // namespace

void register_exact_benchmarks() {
  for (const CurveSpec& spec : crossing_curves())
    for (std::size_t n : crossing_sizes()) {
      const std::string args = "/curve:" + spec.name() + "/N:" + std::to_string(n);
      benchmark::RegisterBenchmark(("b_crossings" + args).c_str(),
                                   [spec, n](benchmark::State& st) { bm_crossings(st, spec, n); })
          ->Unit(benchmark::kMillisecond);
#ifdef SPHTROCH_BENCH_HAVE_S2
      benchmark::RegisterBenchmark(("e_s2" + args).c_str(), [spec, n](benchmark::State& st) { bm_s2(st, spec, n); })
          ->Unit(benchmark::kMillisecond);
#endif
    }
  for (std::size_t k = 0; k < hard_cases().size(); ++k)
    for (bool exact : {true, false})
      benchmark::RegisterBenchmark(
          ("c_predicates/case:" + hard_cases()[k].name + "/predicate:" + (exact ? "exact" : "plain")).c_str(),
          [k, exact](benchmark::State& st) { bm_predicates(st, k, exact); })
          ->Unit(benchmark::kMicrosecond);
  const int max_log2 = quick_mode() ? 12 : 20;
  for (std::size_t k = 0; k < node_cases().size(); ++k) {
    for (int lg = 6; lg <= max_log2; lg += 2) {
      const std::size_t n = std::size_t(1) << lg;
      benchmark::RegisterBenchmark(
          ("d_nodes/case:" + node_cases()[k].name + "/method:uniform_chords/N:" + std::to_string(n)).c_str(),
          [k, n](benchmark::State& st) { bm_nodes_uniform(st, k, n); })
          ->Unit(benchmark::kMillisecond);
    }
    for (std::size_t n : {std::size_t(1024), std::size_t(4096), std::size_t(16384)})
      benchmark::RegisterBenchmark(
          ("d_nodes/case:" + node_cases()[k].name + "/method:census_newton/N:" + std::to_string(n)).c_str(),
          [k, n](benchmark::State& st) { bm_nodes_census(st, k, n); })
          ->Unit(benchmark::kMillisecond);
  }
  for (std::size_t k = 0; k < classify_cases().size(); ++k)
    benchmark::RegisterBenchmark(("f_classify/case:" + classify_cases()[k].name).c_str(),
                                 [k](benchmark::State& st) { bm_classify(st, k); })
        ->Unit(benchmark::kMillisecond);
}

}  // namespace sphtroch_bench
