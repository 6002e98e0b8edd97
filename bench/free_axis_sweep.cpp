// sphtroch_free_axis_sweep — precision points with the sun axis free (synthesis/free_axis_points.hpp)
// on random problems: the success rate (hidden train among the solutions), how many lists are
// certified complete, the number of trains, and the time per problem (median, 90th percentile, max).
//
//   build/bin/sphtroch_free_axis_sweep 20 3 2026 2     # problems, max |p| and q, seed, threads
//
// A problem: n = p/q with 1 <= |p|, q <= T (both signs), a2, a3 in [0.15, pi - 0.15], any phase,
// five carrier angles uniform over a period, the curve turned by a uniformly random rotation.
#include "sphtroch/core/curve.hpp"
#include "sphtroch/synthesis/free_axis_points.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace sphtroch;

namespace {

/// The hidden train among the solutions: the sun axis up to sign, a2, and a3 (pi - a3 reversed).
bool found(const PrecisionPoints& r, const GearTrain& hidden, const Vector3d& axis) {
  const double pi = Constants<double>::pi();
  return std::any_of(r.solutions.begin(), r.solutions.end(), [&](const PrecisionSolution& s) {
    const Vector3d z = s.frame.col(2);
    if (std::abs(s.train.a2() - hidden.a2()) > 1e-9) return false;
    if ((z - axis).norm() < 1e-9) return std::abs(s.train.a3() - hidden.a3()) < 1e-9;
    return (z + axis).norm() < 1e-9 && std::abs(pi - s.train.a3() - hidden.a3()) < 1e-9;
  });
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 20;
  const int max_term = argc > 2 ? std::atoi(argv[2]) : 3;
  std::mt19937_64 rng(argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 2026);
  PrecisionPointsOptions options;
  options.threads = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  const double pi = Constants<double>::pi();
  int hits = 0, certified = 0;
  std::vector<double> ms;
  for (int k = 0; k < count; ++k) {
    const std::int64_t p = (rng() % 2 ? -1 : 1) * static_cast<std::int64_t>(1 + rng() % max_term);
    const Ratio n(p, static_cast<std::int64_t>(1 + rng() % max_term));
    const GearTrain hidden(0.15 + u(rng) * (pi - 0.3), 0.15 + u(rng) * (pi - 0.3), n, 2 * pi * u(rng));
    const Eigen::Matrix3d turn = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
    const TracerCurve<double> curve(hidden);
    std::vector<Vector3d> points;
    for (int i = 0; i < 5; ++i) points.push_back(turn * curve.point(u(rng) * hidden.period()));
    const auto start = std::chrono::steady_clock::now();
    const PrecisionPoints r = free_axis_points(points, n, options);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    const bool hit = found(r, hidden, turn.col(2));
    hits += hit;
    certified += r.certified;
    std::printf("problem %d: n = %s: %zu trains, %s, %s, %zu boxes, %.0f ms\n", k, n.str().c_str(), r.solutions.size(),
                hit ? "found" : "NOT FOUND", r.certified ? "certified" : "NOT certified", r.boxes, ms.back());
    std::fflush(stdout);
  }
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  std::printf("%d problems (|p|, q <= %d, %zu threads): hidden train found in %d, certified complete %d; "
              "ms per problem: median %.0f, p90 %.0f, max %.0f\n",
              count, max_term, options.threads, hits, certified, sorted[sorted.size() / 2],
              sorted[sorted.size() * 9 / 10], sorted.back());
  return hits == count ? 0 : 1;
}
