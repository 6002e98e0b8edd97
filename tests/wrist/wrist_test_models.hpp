// tests/wrist: the library's Wrist built from a reference WristModel (wrist_reference.hpp), and
// the random wrists and directions the wrist tests draw.
#pragma once

#include "wrist/wrist_reference.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"

#include <Eigen/Dense>

#include <random>
#include <utility>
#include <vector>

namespace sphtroch::test {

/// The library's Wrist of the model (the same twists, phases, coupling and tool axis).
inline Wrist library_wrist(const WristModel& m) {
  std::vector<WristJoint> joints;
  std::vector<std::vector<ChainRate>> coupling;
  for (std::size_t i = 0; i < m.twist.size(); ++i) {
    joints.push_back({m.twist[i], m.phase[i]});
    std::vector<ChainRate> row;
    for (const auto& [p, q] : m.coupling[i]) row.push_back(ChainRate(p, q));
    coupling.push_back(row);
  }
  return Wrist(joints, coupling, m.axis);
}

/// A random 2-motor wrist, k = 3 or 4, entries p/q with |p|, q <= 5 (a third of them 0), twists in
/// [0.1, pi - 0.1], phases in [-pi, pi]; redrawn until its coupling has rank 2 and its torus needs
/// at most `max_start` start boxes (the test's time: larger ones cost in proportion).
inline WristModel random_wrist(std::mt19937& rng, double max_start) {
  std::uniform_int_distribution<int> joints(3, 4), num(-5, 5), den(1, 5), zero(0, 2);
  std::uniform_real_distribution<double> twist(0.1, 3.04), phase(-3.14, 3.14);
  while (true) {
    WristModel m;
    const int k = joints(rng);
    for (int i = 0; i < k; ++i) {
      m.twist.push_back(twist(rng));
      m.phase.push_back(phase(rng));
      std::vector<std::pair<int, int>> row;
      for (int j = 0; j < 2; ++j) row.push_back(zero(rng) == 0 ? std::pair{0, 1} : std::pair{num(rng), den(rng)});
      m.coupling.push_back(row);
    }
    try {
      if (wrist_ik_start_boxes(library_wrist(m)) <= max_start) return m;
    } catch (const InvalidInput&) {  // rank below 2: drawn again
    }
  }
}

/// A uniformly random unit vector.
inline Eigen::Vector3d random_direction(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Eigen::Vector3d v(g(rng), g(rng), g(rng));
  while (v.norm() < 1e-3) v = Eigen::Vector3d(g(rng), g(rng), g(rng));
  return v.normalized();
}

}  // namespace sphtroch::test
