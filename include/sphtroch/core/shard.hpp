// sphtroch/core/shard.hpp — one job's part of a divided run: job I of K takes the I-th of K
// consecutive pieces of a list (the atlas's a2 rows, a ratio set's ratios), so that the K parts
// cover the list once, in order. Used by `atlas --shard I/K` and the synth commands' --shard I/K;
// io/parse.hpp's parse_shard reads the text "I/K".
//
//   const sphtroch::Shard s{2, 4};                     // job 2 of 4
//   const auto [begin, end] = sphtroch::shard_range(10, s);   // items [2, 5) of 10
#pragma once

#include "sphtroch/core/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

namespace sphtroch {

/// Job `index` of `count` (1-based).
struct Shard {
  std::size_t index = 1, count = 1;
  std::string str() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// Items floor((I - 1) size / K) .. floor(I size / K) - 1 of a list of `size`, as [begin, end).
/// Throws InvalidInput("shard") unless 1 <= I <= K. Exact for size, K < 2^32 (64-bit products).
inline std::pair<std::size_t, std::size_t> shard_range(std::size_t size, const Shard& shard) {
  const std::uint64_t n = size, i = shard.index, k = shard.count, limit = std::uint64_t(1) << 32;
  if (!(i >= 1 && i <= k && k < limit && n < limit))
    throw InvalidInput("shard", shard.str(), "outside the valid range", "I/K with 1 <= I <= K < 2^32");
  return {static_cast<std::size_t>((i - 1) * n / k), static_cast<std::size_t>(i * n / k)};
}

}  // namespace sphtroch
