// bench/bench_main.cpp — main() of sphtroch_bench, and the heap counter (global new/delete).
//
//   sphtroch_bench [--quick] [Google Benchmark flags...]
//
// --quick: small sizes only (a smoke run while developing); every other flag goes to Google
// Benchmark (--benchmark_repetitions, --benchmark_out, --benchmark_filter, ...).
#include "bench_common.hpp"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

namespace {
std::int64_t g_current = 0;
std::int64_t g_peak = 0;
bool g_quick = false;

// Each block carries its size in a 16-byte header so that delete can subtract it.
constexpr std::size_t kHeader = 16;

void* counted_alloc(std::size_t n) {
  void* raw = std::malloc(n + kHeader);
  if (raw == nullptr) throw std::bad_alloc();
  *static_cast<std::size_t*>(raw) = n;
  g_current += static_cast<std::int64_t>(n);
  if (g_current > g_peak) g_peak = g_current;
  return static_cast<char*>(raw) + kHeader;
}

void counted_free(void* p) noexcept {
  if (p == nullptr) return;
  void* raw = static_cast<char*>(p) - kHeader;
  g_current -= static_cast<std::int64_t>(*static_cast<std::size_t*>(raw));
  std::free(raw);
}
}  // namespace

// Over-aligned new/delete (alignment > 16) are left to the library: nothing here uses them.
void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }

namespace sphtroch_bench {

void HeapCounter::reset_peak() { g_peak = g_current; }
std::int64_t HeapCounter::current_bytes() { return g_current; }
std::int64_t HeapCounter::peak_bytes() { return g_peak; }

bool quick_mode() { return g_quick; }

std::vector<std::size_t> crossing_sizes() {
  if (g_quick) return {1000, 10000};
  return {1000, 3000, 10000, 30000, 100000, 300000, 1000000};
}

#ifndef SPHTROCH_BENCH_HAVE_EXACT
void register_exact_benchmarks() {}
#endif

}  // namespace sphtroch_bench

int main(int argc, char** argv) {
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      g_quick = true;
      continue;
    }
    args.push_back(argv[i]);
  }
  int n = static_cast<int>(args.size());
#ifdef SPHTROCH_BENCH_HAVE_S2
  benchmark::AddCustomContext("s2", "built (Debian libs2-dev)");
#else
  benchmark::AddCustomContext("s2", "skipped: not found at configure time (apt-get install libs2-dev)");
#endif
  benchmark::AddCustomContext("quick", g_quick ? "yes" : "no");
  benchmark::Initialize(&n, args.data());
  if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 1;
  sphtroch_bench::register_trace_benchmarks();
  sphtroch_bench::register_exact_benchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
