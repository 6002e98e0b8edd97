// sphtroch/core/parallel_for.hpp — the library's two ways to use threads, each passing a worker's
// exception back to the caller: parallel_for (independent indices, results stored by index, so
// the output does not depend on the thread count) and for_each_block_in_order (blocks produced on
// workers, consumed in order on the calling thread: streamed output).
//
//   std::vector<double> r(rows);
//   sphtroch::parallel_for(rows, threads, [&](std::size_t i) { r[i] = std::sqrt(double(i)); });
//   sphtroch::for_each_block_in_order(blocks, threads,
//       [&](std::size_t b, std::string& text) { text = format_rows(b); },   // any thread
//       [&](const std::string& text) { out.write(text); });                 // calling thread, b = 0, 1, ...
//
// Worker w produces blocks w, w + T, w + 2T, ... into one of 2T reusable buffers, so memory is
// 2T buffers however many blocks there are, and a slow consumer holds the workers back. The
// consumer runs on the calling thread in block order. An exception from a producer or the
// consumer stops every worker and is rethrown here (the first one). threads <= 1: no thread.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>
#if defined(SPHTROCH_PARALLEL_FAULT_INJECTION)
#include <stdexcept>
#endif

namespace sphtroch {

/// Progress of a parallel_for: (indices done, total), called on the calling thread only.
using ParallelProgress = std::function<void(std::size_t done, std::size_t total)>;

#if defined(SPHTROCH_PARALLEL_FAULT_INJECTION)
namespace parallel_detail {
/// Test seam (tests/core/test_parallel_for.cpp only): the body of this index throws instead of running.
inline std::atomic<std::size_t> fault_index{static_cast<std::size_t>(-1)};
}  // namespace parallel_detail
#endif

/// Calls body(i) once for every i in [0, count), on min(threads, chunks) threads, handing out
/// indices in chunks of `chunk` by an atomic counter. Without `progress` the calling thread is
/// one of the workers; with it, the calling thread reports progress about every 100 ms (and once
/// at the end) while the workers run (it is woken as soon as they end: no 100 ms floor). The first exception a body or `progress` throws stops the
/// handing out (a chunk started is finished); it is rethrown here after every thread has joined.
/// threads <= 1 and no progress: no thread is started.
template <typename Body>
void parallel_for(std::size_t count, std::size_t threads, Body body, std::size_t chunk = 1,
                  const ParallelProgress& progress = {}) {
  chunk = std::max<std::size_t>(1, chunk);
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  // The reporter waits on `wake` (at most 100 ms): a worker that ends the work or fails wakes it.
  std::mutex wake_mutex;
  std::condition_variable wake;
  const auto wake_reporter = [&] {
    { const std::lock_guard<std::mutex> lock(wake_mutex); }  // no wake-up lost between check and wait
    wake.notify_all();
  };
  auto worker = [&] {
    try {
      for (;;) {
        const std::size_t start = next.fetch_add(chunk);
        if (start >= count || failed.load()) return;
        const std::size_t stop = std::min(count, start + chunk);
        for (std::size_t i = start; i < stop; ++i) {
#if defined(SPHTROCH_PARALLEL_FAULT_INJECTION)
          if (i == parallel_detail::fault_index.load()) throw std::runtime_error("injected fault at index " + std::to_string(i));
#endif
          body(i);
        }
        if (done.fetch_add(stop - start) + (stop - start) == count && progress) wake_reporter();
      }
    } catch (...) {
      {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
      if (progress) wake_reporter();
    }
  };
  const std::size_t workers = std::min(std::max<std::size_t>(1, threads), std::max<std::size_t>(1, (count + chunk - 1) / chunk));
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(worker);
  if (!progress) {
    worker();  // the calling thread is one of the workers
  } else {
    pool.emplace_back(worker);
    try {
      const auto finished = [&] { return done.load() >= count || failed.load(); };
      while (!finished()) {
        progress(done.load(), count);
        std::unique_lock<std::mutex> lock(wake_mutex);
        wake.wait_for(lock, std::chrono::milliseconds(100), finished);
      }
    } catch (...) {  // e.g. the caller's interrupt: the workers stop after their chunk
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
  }
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (progress) progress(done.load(), count);
}

/// Produces blocks 0 .. blocks-1 on worker threads and consumes them in order (see header).
template <typename Produce, typename Consume>
void for_each_block_in_order(std::size_t blocks, std::size_t threads, Produce produce, Consume consume) {
  if (threads <= 1 || blocks <= 1) {
    std::string buffer;
    for (std::size_t b = 0; b < blocks; ++b) {
      produce(b, buffer);
      consume(static_cast<const std::string&>(buffer));
    }
    return;
  }
  const std::size_t slots = 2 * threads;
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::string> buffer(slots);
  std::vector<std::size_t> ready(slots, kNone);  // block held by each slot, kNone: free
  std::size_t consumed = 0;                       // blocks handed to the consumer so far
  bool stop = false;
  std::exception_ptr error;
  std::mutex m;
  std::condition_variable changed;

  auto worker = [&](std::size_t w) {
    for (std::size_t b = w; b < blocks; b += threads) {
      const std::size_t s = b % slots;
      {
        std::unique_lock<std::mutex> lock(m);  // slot s is free once block b - slots is consumed
        changed.wait(lock, [&] { return stop || (ready[s] == kNone && consumed + slots > b); });
        if (stop) return;
      }
      try {
        produce(b, buffer[s]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        if (!error) error = std::current_exception();
        stop = true;
        changed.notify_all();
        return;
      }
      std::lock_guard<std::mutex> lock(m);
      ready[s] = b;
      changed.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 0; w < threads; ++w) pool.emplace_back(worker, w);
  try {
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t s = b % slots;
      {
        std::unique_lock<std::mutex> lock(m);
        changed.wait(lock, [&] { return stop || ready[s] == b; });
        if (stop) break;
      }
      consume(static_cast<const std::string&>(buffer[s]));
      std::lock_guard<std::mutex> lock(m);
      ready[s] = kNone;
      ++consumed;
      changed.notify_all();
    }
  } catch (...) {
    std::lock_guard<std::mutex> lock(m);
    if (!error) error = std::current_exception();
    stop = true;
    changed.notify_all();
  }
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace sphtroch
