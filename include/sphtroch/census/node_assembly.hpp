// sphtroch/census/node_assembly.hpp — turn branch pairs (t1, t2 with P(t1) = P(t2)) into nodes.
//
//   std::vector<sphtroch::Node> nodes = sphtroch::assemble_nodes(pairs, curve);  // pairs: BranchPair of any census
//
// One BranchPair for every census; two ways to group pairs into nodes. assemble_nodes (the gear
// train's root and polyline censuses): pairs whose points lie within `merge_distance` of each
// other are one node (a point where k branches meet yields up to k(k-1)/2 pairs, one node).
// assemble_nodes_of_branches (the chain census, whose pairs carry certified enclosures of their
// parameters): parameters whose enclosures overlap are one branch, and pairs sharing a branch
// are one node. A node is a `crossing` when at least
// one of its pairs crosses, a `tangency` when every pair only touches. Its `angle` is the
// largest angle between the tangent lines of two of its branches.
#pragma once

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/parameters.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

namespace sphtroch {

/// An enclosure [lo, hi] of a branch parameter.
struct ParamEnclosure {
  double lo = 0.0, hi = 0.0;
};

/// One pair of branches through one point.
struct BranchPair {
  double t1 = 0.0;  // the first branch's parameter (theta2 of a gear train, in [0, period))
  double t2 = 0.0;  // the second branch's, != t1
  Vector3d position = Vector3d::Zero();  // the point (assemble_nodes; assemble_nodes_of_branches takes it from the curve)
  NodeKind kind = NodeKind::crossing;
  ParamEnclosure t1_range, t2_range;  // certified enclosures of t1 and t2 (assemble_nodes_of_branches)
};

/// x reduced to [0, period): a branch parameter in one period.
inline double reduce_param(double x, double period) {
  double r = x - period * std::floor(x / period);
  if (r >= period || r < 0) r = 0;
  return r;
}

/// Default distance (chord, radians for small values) under which two pair points are one node.
/// Node positions are accurate to ~1e-15 for transversal crossings; multi-branch points found
/// from different pairs agree to that. 1e-9 keeps genuinely distinct nodes (the closest the
/// hard cases produce are ~4e-8 apart) separate.
constexpr double kNodeMergeDistance = 1e-9;
/// Branch parameters of one node closer than this (modulo the period, along a chain of
/// neighbours) are one branch. Pairs merged into one node may meet one branch at points up to a
/// few merge distances apart (a cluster of crossings near a pole, ~1e-9 wide), i.e. at
/// parameters ~1e-9 apart; distinct branches through one point are further apart than the
/// shortest near-cusp loop resolved (parameters ~sqrt(kCuspResolution) = 1e-5 apart).
constexpr double kBranchParamTolerance = 1e-7;

/// The distinct branches among the parameters `ts` (each in [0, period)): sorted, then split
/// where neighbours are more than `tolerance` apart, the last run joined to the first across
/// the period. One representative (the run's first parameter) per branch, ascending. The
/// result does not depend on the order of `ts`.
inline std::vector<double> distinct_branches(std::vector<double> ts, double period,
                                             double tolerance = kBranchParamTolerance) {
  std::sort(ts.begin(), ts.end());
  std::vector<double> runs;
  for (std::size_t i = 0; i < ts.size(); ++i)
    if (i == 0 || ts[i] - ts[i - 1] > tolerance) runs.push_back(ts[i]);
  // Wrap-around: the last run continues into the first one.
  if (runs.size() > 1 && ts.front() + period - ts.back() <= tolerance) runs.erase(runs.begin());
  std::sort(runs.begin(), runs.end());
  return runs;
}

/// Angle between the tangent lines of two velocity vectors, in [0, pi/2]; 0 when either is zero.
inline double tangent_line_angle(const Vector3d& u, const Vector3d& v) {
  const double cross = u.cross(v).norm();
  const double dot = std::abs(u.dot(v));
  if (cross == 0.0 && dot == 0.0) return 0.0;
  return std::atan2(cross, dot);
}

/// Groups pairs into nodes. A group whose pairs name fewer than two distinct branches (a pair
/// with t1, t2 within kBranchParamTolerance) is not a node: it is dropped and counted in
/// *single_branch_groups when given. REQUIRES: pair params in [0, period).
inline std::vector<Node> assemble_nodes(const std::vector<BranchPair>& pairs, const TracerCurve<double>& curve,
                                        double merge_distance = kNodeMergeDistance,
                                        std::size_t* single_branch_groups = nullptr) {
  const double period = curve.period();
  const std::size_t m = pairs.size();
  // Union-find over pairs whose points are close; candidates from a sweep in x.
  std::vector<std::size_t> parent(m);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return pairs[a].position.x() < pairs[b].position.x(); });
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = a + 1; b < m; ++b) {
      const auto& pa = pairs[order[a]].position;
      const auto& pb = pairs[order[b]].position;
      if (pb.x() - pa.x() > merge_distance) break;
      if ((pa - pb).norm() <= merge_distance) parent[find(order[a])] = find(order[b]);
    }
  }
  std::vector<std::vector<std::size_t>> groups(m);
  for (std::size_t i = 0; i < m; ++i) groups[find(i)].push_back(i);

  std::vector<Node> nodes;
  for (const auto& g : groups) {
    if (g.empty()) continue;
    Node node;
    Vector3d sum = Vector3d::Zero();
    std::vector<double> params;
    for (std::size_t i : g) {
      sum += pairs[i].position;
      params.push_back(pairs[i].t1);
      params.push_back(pairs[i].t2);
      if (pairs[i].kind == NodeKind::crossing) ++node.crossing_pairs;
      else ++node.tangency_pairs;
    }
    node.params = distinct_branches(std::move(params), period);
    if (node.params.size() < 2) {  // a node has two branches at least
      if (single_branch_groups) ++*single_branch_groups;
      continue;
    }
    node.position = sum.normalized();
    node.branches = node.params.size();
    node.kind = node.crossing_pairs > 0 ? NodeKind::crossing : NodeKind::tangency;
    std::vector<Vector3d> velocities;
    for (double t : node.params) velocities.push_back(curve.velocity(t));
    for (std::size_t a = 0; a < velocities.size(); ++a)
      for (std::size_t b = a + 1; b < velocities.size(); ++b)
        node.angle = std::max(node.angle, tangent_line_angle(velocities[a], velocities[b]));
    nodes.push_back(std::move(node));
  }
  // Deterministic order: by the first branch parameter.
  std::sort(nodes.begin(), nodes.end(), [](const Node& a, const Node& b) { return a.params.front() < b.params.front(); });
  return nodes;
}

/// A branch parameter reduced to [0, T) with its enclosure shifted alike (padded by the reduction's
/// rounding, 4 ulp of max(1, T)).
struct BranchParam {
  double value = 0, lo = 0, hi = 0;
};
inline BranchParam reduced_branch(double value, const ParamEnclosure& enclosure, double period) {
  const double r = reduce_param(value, period), shift = value - r;
  const double pad = 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, period);
  return {r, std::min(enclosure.lo, value) - shift - pad, std::max(enclosure.hi, value) - shift + pad};
}

/// Parameters whose enclosures overlap (circularly, mod T) as one branch: the cluster index of
/// each. Enclosures that are disjoint are distinct branches, however close (the certified
/// enclosures of Krawczyk's roots are a few ulp wide); overlapping ones cannot be told apart.
inline std::vector<std::size_t> branch_clusters(const std::vector<BranchParam>& params, double period) {
  const std::size_t n = params.size();
  std::vector<std::size_t> order(n), cluster(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return params[a].lo < params[b].lo; });
  std::size_t current = 0;
  double reach = -std::numeric_limits<double>::infinity();  // the largest hi of the current cluster
  for (std::size_t k = 0; k < n; ++k) {
    const BranchParam& p = params[order[k]];
    if (k > 0 && p.lo > reach) ++current, reach = -std::numeric_limits<double>::infinity();
    reach = std::max(reach, p.hi);
    cluster[order[k]] = current;
  }
  const bool wraps = current > 0 && reach >= params[order[0]].lo + period;
  if (wraps && current > 0)  // the wrap: the last cluster is the first
    for (std::size_t k = 0; k < n; ++k)
      if (cluster[k] == current) cluster[k] = 0;
  return cluster;
}

/// Nodes from branch pairs with certified parameter enclosures (the chain census): parameters
/// clustered into branches by their enclosures (branch_clusters), pairs joined into points by the
/// branches they share; a point of m branches must have m (m - 1) / 2 pairs (else `why` is set);
/// its position is the mean of its branches' points, negated when `negated`. Curve: anything with
/// point(s) and velocity(s) (ChainCurve<double>).
template <class Curve>
std::vector<Node> assemble_nodes_of_branches(const Curve& curve, const std::vector<BranchPair>& pairs, double period, bool negated,
                                             std::string& why) {
  std::vector<BranchParam> params;
  for (const BranchPair& p : pairs) params.push_back(reduced_branch(p.t1, p.t1_range, period)), params.push_back(reduced_branch(p.t2, p.t2_range, period));
  const std::vector<std::size_t> cluster = branch_clusters(params, period);
  std::size_t clusters = 0;
  for (const std::size_t c : cluster) clusters = std::max(clusters, c + 1);
  std::vector<std::size_t> parent(clusters);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto find = [&](std::size_t x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
  std::vector<std::tuple<std::size_t, std::size_t, bool>> edges;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    std::size_t a = cluster[2 * k], b = cluster[2 * k + 1];
    if (a == b) { why = "a node's two branches have the same parameter"; continue; }
    edges.emplace_back(std::min(a, b), std::max(a, b), pairs[k].kind == NodeKind::tangency);
    parent[find(a)] = find(b);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());  // the same pair found twice
  std::vector<double> value(clusters, 0.0);
  for (std::size_t k = 0; k < params.size(); ++k) value[cluster[k]] = params[k].value;
  std::vector<Node> nodes;
  std::vector<std::size_t> node_of(clusters, SIZE_MAX);
  for (const auto& [a, b, touching] : edges) {
    const std::size_t root = find(a);
    if (node_of[root] == SIZE_MAX) node_of[root] = nodes.size(), nodes.emplace_back();
    Node& n = nodes[node_of[root]];
    for (const std::size_t c : {a, b})
      if (std::find(n.params.begin(), n.params.end(), value[c]) == n.params.end()) n.params.push_back(value[c]);
    ++(touching ? n.tangency_pairs : n.crossing_pairs);
    n.angle = std::max(n.angle, tangent_line_angle(curve.velocity(value[a]), curve.velocity(value[b])));
  }
  for (Node& n : nodes) {
    std::sort(n.params.begin(), n.params.end());
    n.branches = n.params.size();
    n.kind = n.crossing_pairs > 0 ? NodeKind::crossing : NodeKind::tangency;
    if (n.crossing_pairs + n.tangency_pairs != n.branches * (n.branches - 1) / 2) why = "a node's branches do not all meet pairwise";
    else if (n.branches > 2 && why.empty())  // pairwise roots a few ulp apart: one point, or crossings closer than double tells
      why = "a node of " + std::to_string(n.branches) + " branches is not proved one point (its pairs' roots agree to the rounding of double)";
    Vector3d sum = Vector3d::Zero();
    for (const double p : n.params) sum += curve.point(p);
    n.position = (negated ? -1.0 : 1.0) * sum.normalized();
  }
  std::sort(nodes.begin(), nodes.end(), [](const Node& x, const Node& y) { return x.params.front() < y.params.front(); });
  return nodes;
}

/// The TracerCurve calls assemble_nodes made for `nodes` (one velocity per branch of each node).
inline std::size_t assembly_evaluations(const std::vector<Node>& nodes) {
  std::size_t n = 0;
  for (const Node& node : nodes) n += node.params.size();
  return n;
}

}  // namespace sphtroch
