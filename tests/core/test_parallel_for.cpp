// Tests of core/parallel_for.hpp and of every parallel loop built on it: each index runs once,
// results do not depend on the thread count, and an exception thrown inside a worker reaches the
// caller (never std::terminate) — for parallel_for itself and for compute_atlas,
// check_atlas_boundaries and boundary_loci, through the test seam SPHTROCH_PARALLEL_FAULT_INJECTION
// (this executable only).
#include "catch2/catch.hpp"
#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/atlas/atlas_boundary_check.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/map/boundary_events.hpp"

#include <atomic>
#include <chrono>
#include <thread>
#include <stdexcept>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

/// Sets the injected fault index for one scope.
struct InjectedFault {
  explicit InjectedFault(std::size_t i) { parallel_detail::fault_index = i; }
  ~InjectedFault() { parallel_detail::fault_index = static_cast<std::size_t>(-1); }
};

bool message_contains(const std::exception& e, const std::string& s) { return std::string(e.what()).find(s) != std::string::npos; }

}  // namespace

TEST_CASE("parallel_for: every index exactly once, for any thread count and chunk", "[parallel_for]") {
  for (std::size_t threads : {1, 2, 3, 8})
    for (std::size_t chunk : {1, 7, 64})
      for (std::size_t count : {0, 1, 5, 1000}) {
        std::vector<std::atomic<int>> hits(count);
        parallel_for(count, threads, [&](std::size_t i) { ++hits[i]; }, chunk);
        for (std::size_t i = 0; i < count; ++i) REQUIRE(hits[i].load() == 1);
      }
}

TEST_CASE("parallel_for: a body's exception is rethrown on the calling thread, the others stop", "[parallel_for]") {
  for (std::size_t threads : {1, 2, 4}) {
    std::atomic<std::size_t> ran{0};
    auto body = [&](std::size_t i) {
      ++ran;
      if (i == 3) throw std::invalid_argument("body 3 failed");
    };
    CHECK_THROWS_AS(parallel_for(100000, threads, body), std::invalid_argument);
    CHECK(ran.load() < 100000);  // handing out stopped (every thread checks the flag per chunk)
  }
  // With a progress callback the calling thread only reports; the worker's exception still arrives.
  std::size_t reports = 0;
  CHECK_THROWS_AS(parallel_for(
                      10, 2, [](std::size_t i) { if (i == 9) throw std::out_of_range("last"); }, 1,
                      [&](std::size_t, std::size_t) { ++reports; }),
                  std::out_of_range);
}

TEST_CASE("parallel_for: progress reports done <= total and ends at total", "[parallel_for]") {
  std::size_t last_done = 0, last_total = 0;
  bool monotone = true;
  parallel_for(
      500, 2, [](std::size_t) {}, 8,
      [&](std::size_t done, std::size_t total) {
        monotone = monotone && done >= last_done && done <= total;
        last_done = done;
        last_total = total;
      });
  CHECK(monotone);
  CHECK(last_done == 500);
  CHECK(last_total == 500);
}

TEST_CASE("parallel_for: an exception from progress (an interrupt) stops the workers and is rethrown", "[parallel_for]") {
  // Before the fix the exception left parallel_for with joinable threads: std::terminate.
  std::atomic<std::size_t> ran{0};
  const std::size_t count = 100000;
  CHECK_THROWS_WITH(parallel_for(
                        count, 2,
                        [&](std::size_t) {
                          std::this_thread::sleep_for(std::chrono::microseconds(50));
                          ++ran;
                        },
                        4, [](std::size_t, std::size_t) { throw std::runtime_error("interrupted"); }),
                    "interrupted");
  CHECK(ran.load() < count);  // stopped early: 100000 x 50 us is 2.5 s per worker
}

TEST_CASE("parallel loops: a fault inside a worker of each reaches the caller", "[parallel_for]") {
  const double pi = Constants<double>::pi();
  AtlasSpec spec;
  spec.ratio = Ratio(3);
  spec.grid = 8;
  SECTION("compute_atlas, with and without progress") {
    InjectedFault fault(37);
    for (std::size_t threads : {1, 2, 3}) {
      try {
        (void)compute_atlas(spec, {0, spec.grid}, threads);
        FAIL("no exception");
      } catch (const std::runtime_error& e) {
        CHECK(message_contains(e, "injected fault at index 37"));
      }
      CHECK_THROWS_AS(compute_atlas(spec, {0, spec.grid}, threads, [](std::size_t, std::size_t) {}), std::runtime_error);
    }
  }
  SECTION("check_atlas_boundaries") {
    const std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);
    InjectedFault fault(5);
    for (std::size_t threads : {1, 2, 4})
      CHECK_THROWS_AS(check_atlas_boundaries(spec, cells, threads), std::runtime_error);
  }
  SECTION("boundary_loci") {
    InjectedFault fault(11);
    for (std::size_t threads : {1, 2, 4})
      CHECK_THROWS_AS(boundary_loci(Ratio(5, 2), 0.1, pi - 0.1, 40, threads), std::runtime_error);
  }
  SECTION("without the fault the same calls succeed and do not depend on the thread count") {
    const auto one = compute_atlas(spec, {0, spec.grid}, 1), three = compute_atlas(spec, {0, spec.grid}, 3);
    REQUIRE(one.size() == three.size());
    for (std::size_t k = 0; k < one.size(); ++k) CHECK(one[k].nodes == three[k].nodes);
    const auto l1 = boundary_loci(Ratio(5, 2), 0.1, pi - 0.1, 40, 1), l4 = boundary_loci(Ratio(5, 2), 0.1, pi - 0.1, 40, 4);
    REQUIRE(l1.size() == l4.size());
    for (std::size_t k = 0; k < l1.size(); ++k) CHECK(l1[k].points.size() == l4[k].points.size());
  }
}
