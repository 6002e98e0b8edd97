// sphtroch_points_sweep — precision points (synthesis/precision_points.hpp) on random problems: the
// success rate (hidden train among the solutions), how many lists are certified complete, and the
// time per problem (median, 90th percentile, max), one core.
//
//   build/bin/sphtroch_points_sweep 1000 7 2026     # problems, max |p| and q, seed
//
// A problem: n = p/q with 1 <= |p|, q <= T (both signs), a2, a3 in [0.15, pi - 0.15], any phase,
// three carrier angles uniform over a period; one in eight has its first point at a z-extreme.
#include "sphtroch/core/curve.hpp"
#include "sphtroch/synthesis/precision_points.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace sphtroch;

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int max_term = argc > 2 ? std::atoi(argv[2]) : 7;
  std::mt19937_64 rng(argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double pi = Constants<double>::pi();
  int found = 0, certified = 0;
  std::vector<double> ms;
  for (int k = 0; k < count; ++k) {
    const std::int64_t p = (rng() % 2 ? -1 : 1) * static_cast<std::int64_t>(1 + rng() % max_term);
    const Ratio n(p, static_cast<std::int64_t>(1 + rng() % max_term));
    const GearTrain hidden(0.15 + u(rng) * (pi - 0.3), 0.15 + u(rng) * (pi - 0.3), n, 2 * pi * u(rng));
    const TracerCurve<double> curve(hidden);
    std::vector<Vector3d> points;
    for (int i = 0; i < 3; ++i) {
      double t = u(rng) * hidden.period();
      if (k % 8 == 7 && i == 0) t = ((rng() % 2 ? pi : 0.0) - hidden.phase()) / n.value();
      points.push_back(curve.point(t));
    }
    const auto start = std::chrono::steady_clock::now();
    const PrecisionPoints r = precision_points(points, n);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    const double sector = 2 * pi / static_cast<double>(n.q());
    const bool hit = std::any_of(r.solutions.begin(), r.solutions.end(), [&](const PrecisionSolution& s) {
      return std::abs(s.train.a2() - hidden.a2()) < 1e-9 && std::abs(s.train.a3() - hidden.a3()) < 1e-9 &&
             std::abs(std::remainder(s.train.phase() - hidden.phase(), sector)) < 1e-9;
    });
    found += hit;
    certified += r.certified;
    if (!hit || !r.certified)
      std::printf("problem %d: n = %s, a2 = %.17g, a3 = %.17g, phase = %.17g: %s, %s (%zu boxes)\n", k, n.str().c_str(),
                  hidden.a2(), hidden.a3(), hidden.phase(), hit ? "found" : "NOT FOUND",
                  r.certified ? "certified" : "NOT certified", r.boxes);
  }
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  std::printf("%d problems (|p|, q <= %d): hidden train found in %d, certified complete %d; "
              "ms per problem: median %.1f, p90 %.1f, max %.1f\n",
              count, max_term, found, certified, sorted[sorted.size() / 2], sorted[sorted.size() * 9 / 10], sorted.back());
  return found == count ? 0 : 1;
}
