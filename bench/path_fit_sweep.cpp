// sphtroch_fit_sweep — fit with a wanted node count (exact/path_fit_output.hpp) on random noisy
// targets: how often every candidate has the wanted census (it must be always), how often the best
// candidate's RMS is within 2 sigma of the noise, how often the hidden train is found, and the
// time per target (median, 90th percentile, max; fit + classify of the candidates), one core.
//
//   build/bin/sphtroch_fit_sweep 1000 7 2026 0.0001 [free]   # targets, max |p| and q, seed, sigma
//
// A target: n = p/q with 1 <= |p|, q <= T (both signs), a2, a3 in [0.1, pi - 0.1], any phase,
// 60 .. 200 points at uniform random carrier angles over a period, each moved by a tangent Gaussian
// of sigma per direction; the wanted count is the hidden train's (classify); "free" fits without one.
#include "sphtroch/classify.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/synthesis.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <random>
#include <vector>

using namespace sphtroch;

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int max_term = argc > 2 ? std::atoi(argv[2]) : 7;
  std::mt19937_64 rng(argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 2026);
  const double sigma = argc > 4 ? std::atof(argv[4]) : 1e-4;
  const bool free_fit = argc > 5 && std::strcmp(argv[5], "free") == 0;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  const double pi = Constants<double>::pi();
  int right_counts = 0, within = 0, hidden_found = 0, targets = 0;
  std::vector<double> ms;
  while (targets < count) {
    std::int64_t p = 0, q = 0;
    do {
      p = 1 + static_cast<std::int64_t>(rng() % max_term);
      q = 1 + static_cast<std::int64_t>(rng() % max_term);
    } while (std::gcd(p, q) != 1);
    const GearTrain hidden(0.1 + u(rng) * (pi - 0.2), 0.1 + u(rng) * (pi - 0.2), Ratio(rng() % 2 ? -p : p, q), 2 * pi * u(rng));
    const TracerCurve<double> curve(hidden);
    std::vector<double> ts(60 + rng() % 141);
    for (double& t : ts) t = u(rng) * hidden.period();
    std::sort(ts.begin(), ts.end());
    std::vector<Vector3d> points;
    for (double t : ts) {
      const Vector3d P = curve.point(t);
      Vector3d e(g(rng), g(rng), g(rng));
      e -= P * P.dot(e);
      points.push_back((P + sigma * e).normalized());
    }
    const Classification census = classify(hidden);
    if (!census.certified()) continue;
    ++targets;
    FitOptions o;
    if (!free_fit) o.nodes = static_cast<std::int64_t>(census.nodes.size());
    const auto start = std::chrono::steady_clock::now();
    const auto fits = fit_with_census(points, {hidden.ratio()}, o);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    const auto& cands = fits[0].candidates;
    bool counts_ok = true;
    for (const auto& c : cands)
      counts_ok = counts_ok && c.census.certified() && (!o.nodes || static_cast<std::int64_t>(c.census.nodes.size()) == *o.nodes);
    right_counts += counts_ok;
    within += !cands.empty() && cands[0].candidate.rms <= 2 * sigma;
    hidden_found += !cands.empty() && std::abs(cands[0].candidate.train.a2() - hidden.a2()) < 10 * sigma + 1e-3 &&
                    std::abs(cands[0].candidate.train.a3() - hidden.a3()) < 10 * sigma + 1e-3;
  }
  std::sort(ms.begin(), ms.end());
  std::printf("fit%s: %d targets, |p|, q <= %d, sigma %g: every candidate's census as wanted %d, best rms <= 2 sigma %d, "
              "hidden train first %d; time per target median %.0f ms, p90 %.0f ms, max %.0f ms\n",
              free_fit ? " (no count wanted)" : " (node count wanted)", targets, max_term, sigma, right_counts, within,
              hidden_found, ms[ms.size() / 2], ms[ms.size() * 9 / 10], ms.back());
}
