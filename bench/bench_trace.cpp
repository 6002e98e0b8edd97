// bench/bench_trace.cpp — study a: what a trace point costs, and how accurate it is, per Scalar
// type and evaluation method. Eigen + MPFR only (no CGAL).
//
// Curve: a2 = 1, a3 = 2 rad, n = 7/3 (period 6 pi), N = 4096 uniform samples t_i = 6 pi i / N.
// Methods:
//   direct      the library's sample_period (TracerCurve::point: sin/cos of theta2 and theta3 per
//               sample, the Eq. 4 chain);
//   recurrence  (cos, sin) of theta2 and theta3 advanced by a fixed rotation per sample (one
//               complex multiplication each), the Eq. 4 chain written out; k = 0: never
//               re-anchored; k > 0: recomputed with sin/cos every k samples.
// Error: max over the samples of |P - P_ref|, P_ref = Eq. 4 in MPFR at 256 bits at the exact
// t_i (computed once, outside the timing). The mpreal Scalar runs at 128 bits.
#include "bench_common.hpp"

#include "sphtroch/core/curve.hpp"
#include "sphtroch/exact/mpreal_support.hpp"
#include "sphtroch/core/sampling.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

namespace sphtroch_bench {
namespace {

using sphtroch::mpfr_real;

constexpr long kReferenceBits = 256;
constexpr long kMpfrBits = 128;
const sphtroch::GearTrain& trace_train() {
  static const sphtroch::GearTrain train(1.0, 2.0, sphtroch::Ratio(7, 3));
  return train;
}
std::size_t trace_samples() { return quick_mode() ? 1024 : 4096; }

/// The recurrence (see the header comment). out must have n entries.
template <typename S>
void trace_recurrence(const sphtroch::GearTrain& train, std::size_t n, std::size_t k,
                      std::vector<sphtroch::Vector3<S>>& out) {
  using std::cos;
  using std::sin;
  const sphtroch::TwistTrig<S> tw = train.trig<S>();
  const S p(static_cast<double>(train.ratio().p()));
  const S q(static_cast<double>(train.ratio().q()));
  const S phase(train.phase());
  const S span = sphtroch::Constants<S>::two_pi() * q;
  const S h2 = span / S(static_cast<double>(n));
  const S h3 = p * h2 / q;
  const S ch2 = cos(h2), sh2 = sin(h2), ch3 = cos(h3), sh3 = sin(h3);
  S c2(1), s2(0), c3(1), s3(0);
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0 || (k > 0 && i % k == 0)) {
      const S t = span * S(static_cast<double>(i)) / S(static_cast<double>(n));
      const S t3 = p * t / q + phase;  // Eq. 3
      c2 = cos(t);
      s2 = sin(t);
      c3 = cos(t3);
      s3 = sin(t3);
    } else {
      const S c2n = c2 * ch2 - s2 * sh2, s2n = s2 * ch2 + c2 * sh2;
      const S c3n = c3 * ch3 - s3 * sh3, s3n = s3 * ch3 + c3 * sh3;
      c2 = c2n;
      s2 = s2n;
      c3 = c3n;
      s3 = s3n;
    }
    // Eq. 4: carrier_p = Rz(theta3) Rx(a3) z; base_p = Rz(theta2) Rx(a2) carrier_p.
    const S x = s3 * tw.sin_a3, y = -c3 * tw.sin_a3, z = tw.cos_a3;
    const S y1 = tw.cos_a2 * y - tw.sin_a2 * z, z1 = tw.sin_a2 * y + tw.cos_a2 * z;
    out[i] = sphtroch::Vector3<S>(c2 * x - s2 * y1, s2 * x + c2 * y1, z1);
  }
}

/// P_ref at the exact t_i, 256-bit MPFR (computed once per n).
const std::vector<sphtroch::Vector3<mpfr_real>>& reference(std::size_t n) {
  static std::size_t cached_n = 0;
  static std::vector<sphtroch::Vector3<mpfr_real>> ref;
  if (cached_n != n) {
    const long saved = mpfr_real::get_default_prec();
    mpfr_real::set_default_prec(kReferenceBits);
    const sphtroch::TracerCurve<mpfr_real> curve(trace_train());
    ref = sphtroch::sample_period(curve, n).points;
    mpfr_real::set_default_prec(saved);
    cached_n = n;
  }
  return ref;
}

template <typename S>
double max_error(const std::vector<sphtroch::Vector3<S>>& pts) {
  const long saved = mpfr_real::get_default_prec();
  mpfr_real::set_default_prec(kReferenceBits);
  const auto& ref = reference(pts.size());
  mpfr_real worst(0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    sphtroch::Vector3<mpfr_real> d;
    for (int c = 0; c < 3; ++c) d[c] = mpfr_real(pts[i][c]) - ref[i][c];
    const mpfr_real e = sqrt(d.squaredNorm());
    if (e > worst) worst = e;
  }
  const double out = worst.toDouble();
  mpfr_real::set_default_prec(saved);
  return out;
}

template <typename S>
void run_direct(benchmark::State& state) {
  const std::size_t n = trace_samples();
  const sphtroch::TracerCurve<S> curve(trace_train());
  state.counters["max_error"] = max_error(sphtroch::sample_period(curve, n).points);
  for (auto _ : state) {
    auto tr = sphtroch::sample_period(curve, n);
    benchmark::DoNotOptimize(tr.points.data());
  }
  state.counters["points"] = static_cast<double>(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

template <typename S>
void run_recurrence(benchmark::State& state, std::size_t k) {
  const std::size_t n = trace_samples();
  std::vector<sphtroch::Vector3<S>> pts(n);
  trace_recurrence(trace_train(), n, k, pts);
  state.counters["max_error"] = max_error(pts);
  for (auto _ : state) {
    trace_recurrence(trace_train(), n, k, pts);
    benchmark::DoNotOptimize(pts.data());
    benchmark::ClobberMemory();
  }
  state.counters["points"] = static_cast<double>(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

template <typename S>
void register_scalar(const char* scalar_name) {
  const std::string base = std::string("a_trace/scalar:") + scalar_name;
  const auto with_prec = [](auto fn) {
    return [fn](benchmark::State& st) {
      if constexpr (std::is_same_v<S, mpfr_real>) {
        const long saved = mpfr_real::get_default_prec();
        mpfr_real::set_default_prec(kMpfrBits);
        fn(st);
        mpfr_real::set_default_prec(saved);
      } else {
        fn(st);
      }
    };
  };
  benchmark::RegisterBenchmark((base + "/method:direct/k:0").c_str(), with_prec([](benchmark::State& st) {
                                 run_direct<S>(st);
                               }))
      ->Unit(benchmark::kMicrosecond);
  for (std::size_t k : {std::size_t(0), std::size_t(16), std::size_t(256)}) {
    benchmark::RegisterBenchmark((base + "/method:recurrence/k:" + std::to_string(k)).c_str(),
                                 with_prec([k](benchmark::State& st) { run_recurrence<S>(st, k); }))
        ->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace

void register_trace_benchmarks() {
  register_scalar<float>("float");
  register_scalar<double>("double");
  register_scalar<long double>("long_double");
  register_scalar<mpfr_real>("mpfr128");
}

}  // namespace sphtroch_bench
