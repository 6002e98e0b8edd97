// sphtroch/census/node_assembly.hpp — turn branch pairs (t1, t2 with P(t1) = P(t2)) into nodes.
//
//   std::vector<sphtroch::Node> nodes = sphtroch::assemble_nodes(pairs, curve);  // pairs: BranchPair of any census
//
// Pairs whose points lie within `merge_distance` of each other are one node (a point where
// k branches meet yields up to k(k-1)/2 pairs, one node). A node is a `crossing` when at least
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
#include <numeric>
#include <vector>

namespace sphtroch {

/// One pair of branches through one point.
struct BranchPair {
  double t1 = 0.0;  // theta2 of the first branch, [0, period)
  double t2 = 0.0;  // theta2 of the second branch, [0, period), != t1
  Vector3d position = Vector3d::Zero();
  NodeKind kind = NodeKind::crossing;
};

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

/// The TracerCurve calls assemble_nodes made for `nodes` (one velocity per branch of each node).
inline std::size_t assembly_evaluations(const std::vector<Node>& nodes) {
  std::size_t n = 0;
  for (const Node& node : nodes) n += node.params.size();
  return n;
}

}  // namespace sphtroch
