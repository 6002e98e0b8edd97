// sphtroch/core/parallel_for.hpp — produce blocks of output on worker threads, consume them in order.
//
//   sphtroch::for_each_block_in_order(blocks, threads,
//       [&](std::size_t b, std::string& text) { text = format_rows(b); },   // any thread
//       [&](const std::string& text) { out.write(text); });                 // calling thread, b = 0, 1, ...
//
// Worker w produces blocks w, w + T, w + 2T, ... into one of 2T reusable buffers, so memory is
// 2T buffers however many blocks there are, and a slow consumer holds the workers back. The
// consumer runs on the calling thread in block order. An exception from a producer or the
// consumer stops every worker and is rethrown here (the first one). threads <= 1: no thread.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace sphtroch {

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
