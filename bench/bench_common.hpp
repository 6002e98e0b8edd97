// bench/bench_common.hpp — shared pieces of the benchmark executable: the heap counter (peak
// bytes of one call, for "memory linear"), the benchmark naming scheme, cached test polylines.
//
// Naming: every benchmark is registered as "<study>/<key>:<value>/<key>:<value>/...", e.g.
// "b_crossings/curve:7_3/N:1000000"; bench_report.cpp parses these names. Values computed once
// outside the timed loop (errors, counts, bytes) are benchmark counters, so they travel with the
// timing in the same JSON.
#pragma once

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/sampling.hpp"

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace sphtroch_bench {

/// Heap use through the global operator new/delete of this executable (bench_main.cpp).
struct HeapCounter {
  static void reset_peak();            // peak := current
  static std::int64_t current_bytes();
  static std::int64_t peak_bytes();    // since the last reset_peak
};

/// Peak heap bytes allocated by f() beyond what was in use before the call.
template <typename F>
std::int64_t peak_heap_of(F&& f) {
  HeapCounter::reset_peak();
  const std::int64_t before = HeapCounter::current_bytes();
  f();
  return HeapCounter::peak_bytes() - before;
}

/// A trochoid of the benchmark family: P(t_i) (Eq. 4) at N uniform samples over one period.
struct CurveSpec {
  double a2;
  double a3;
  std::int64_t p;
  std::int64_t q;
  std::string name() const { return std::to_string(p) + "_" + std::to_string(q); }
};

/// The closed polyline of `spec` with n vertices, generated once per (spec, n) and kept.
inline const std::vector<Eigen::Vector3d>& cached_trochoid(const CurveSpec& spec, std::size_t n) {
  static std::map<std::tuple<double, double, std::int64_t, std::int64_t, std::size_t>, std::vector<Eigen::Vector3d>> cache;
  auto key = std::make_tuple(spec.a2, spec.a3, spec.p, spec.q, n);
  auto it = cache.find(key);
  if (it == cache.end()) {
    const sphtroch::GearTrain train(spec.a2, spec.a3, sphtroch::Ratio(spec.p, spec.q));
    const sphtroch::TracerCurve<double> curve(train);
    it = cache.emplace(key, sphtroch::sample_period(curve, n).points).first;
  }
  return it->second;
}

/// The curves of study b/e: many nodes each (a2 = 1, a3 = 2 rad).
inline std::vector<CurveSpec> crossing_curves() { return {{1.0, 2.0, 7, 3}, {1.0, 2.0, 13, 5}, {1.0, 2.0, 101, 40}}; }

/// Vertex counts of studies b/e.
std::vector<std::size_t> crossing_sizes();
/// True when the executable runs in --quick mode (set by bench_main before registration).
bool quick_mode();

// Registration hooks, one per translation unit (called by main before RunSpecifiedBenchmarks).
void register_trace_benchmarks();     // bench_trace.cpp, study a
void register_exact_benchmarks();     // bench_exact.cpp, studies b, c, d, e and classify

}  // namespace sphtroch_bench
