// sphtroch/census/node_sets.hpp — whether two censuses found the same node points (the certificate of
// a node count: two independent methods agree).
//
//   const std::vector<sphtroch::Node> a = sphtroch::root_census(train).nodes, b = a;
//   std::string why;
//   bool same = sphtroch::same_node_sets(a, b, why);  // true; else why: the first difference
//
// Contract: one-to-one agreement. Every node of `a` is paired with the NEAREST unused node of
// `b` within kAgreementDistance (chord) of the same kind and branch count (nearest, because
// crossings of a cluster near a pole can be closer to each other than kAgreementDistance); the
// sets agree when every node is paired and the sizes are equal. Eigen only.
#pragma once

#include "sphtroch/core/node.hpp"
#include "sphtroch/core/number_text.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace sphtroch {

/// Node points of the two censuses match when closer than this (chord).
constexpr double kAgreementDistance = 1e-8;

inline bool same_node_sets(const std::vector<Node>& a, const std::vector<Node>& b, std::string& why) {
  if (a.size() != b.size()) {
    why = std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " node points";
    return false;
  }
  std::vector<std::size_t> order(b.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return b[i].position.x() < b[j].position.x(); });
  std::vector<bool> used(b.size(), false);
  for (const Node& n : a) {
    auto it = std::lower_bound(order.begin(), order.end(), n.position.x() - kAgreementDistance,
                               [&](std::size_t j, double x) { return b[j].position.x() < x; });
    std::size_t hit = b.size();
    double best = kAgreementDistance;
    for (; it != order.end() && b[*it].position.x() <= n.position.x() + kAgreementDistance; ++it) {
      const Node& m = b[*it];
      const double gap = (m.position - n.position).norm();
      if (!used[*it] && gap <= best && m.kind == n.kind && m.branches == n.branches) {
        hit = *it;
        best = gap;
      }
    }
    if (hit == b.size()) {
      why = "no match for the " + std::string(to_string(n.kind)) + " node at (" + number_text(n.position.x()) + ", " +
            number_text(n.position.y()) + ", " + number_text(n.position.z()) + ")";
      return false;
    }
    used[hit] = true;
  }
  return true;
}

}  // namespace sphtroch
