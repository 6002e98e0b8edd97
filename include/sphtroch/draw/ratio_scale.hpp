// sphtroch/draw/ratio_scale.hpp — a colour scale for non-negative amounts read against their mean
// (a dwell map: seconds per cell): each amount as its ratio to the mean, on a logarithmic axis
// symmetric about 1, clipped at robust percentiles so that a few extreme cells (a clinostat's
// poles) do not wash the rest out. Zero amounts (cells never visited) are off the scale: the
// picture gives them a colour of their own. No dependencies.
//
//   const sphtroch::RatioScale s = sphtroch::ratio_scale({0.0, 1.0, 2.0, 3.0, 4.0, 10.0});
//   s.mean;              // 3.3333...: the sum over every amount (zeros too) / their number
//   s.position(s.mean);  // 0.5: the centre of the scale
//   s.ticks();           // the ratios 1/2, 1, 2 (powers of two inside the scale), with their text
//
// Contracts:
//  1. mean = (sum of the amounts) / (their number), zeros included: an even spread is 1 everywhere.
//  2. The scale runs over log2(ratio) in [-half_range, half_range], half_range = the larger of 1
//     (the scale spans at least 1/2 .. 2) and |log2(q / mean)| for q the amounts at the clip
//     percentiles of the non-zero amounts (clip_share and 1 - clip_share, nearest rank: the
//     sorted positive amounts' entries floor(clip_share (n - 1)) and n - 1 minus that).
//  3. position(a) = 1/2 + log2(a / mean) / (2 half_range), clamped to [0, 1]: 0.5 at the mean, 0
//     and 1 at the clipped ends (amounts beyond take the end). REQUIRES a > 0 (a zero amount has no
//     position).
//  4. ticks(): the ratios 2^k with |k| <= half_range, k a multiple of ceil(half_range / 4) (at most
//     nine ticks), with their text ("1/4", "1/2", "1", "2", "4").
//  REQUIRES: finite amounts >= 0; no positive amount: mean 0 and half_range 1 (nothing to place).
#pragma once

#include "sphtroch/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace sphtroch {

struct RatioScale {
  double mean = 0.0;        ///< contract 1 (the amounts' unit)
  double half_range = 1.0;  ///< contract 2, in log2 units
  double clip_share = 0.05;

  /// Where amount a > 0 lies on the scale, in [0, 1] (contract 3).
  double position(double a) const {
    SPHTROCH_ASSERT(a > 0 && mean > 0, "RatioScale::position: a positive amount");
    return std::clamp(0.5 + std::log2(a / mean) / (2 * half_range), 0.0, 1.0);
  }
  /// The clipped ends as ratios to the mean: 2^-half_range and 2^half_range.
  double low_ratio() const { return std::exp2(-half_range); }
  double high_ratio() const { return std::exp2(half_range); }

  struct Tick {
    double ratio;      ///< 2^k
    double position;   ///< on the scale, in [0, 1]
    std::string text;  ///< "1/4", "1", "8"
  };
  /// Contract 4.
  std::vector<Tick> ticks() const {
    std::vector<Tick> out;
    const int step = std::max(1, static_cast<int>(std::ceil(half_range / 4 - 1e-12)));
    const int top = static_cast<int>(std::floor(half_range + 1e-12)) / step * step;
    for (int k = -top; k <= top; k += step) {
      const std::string power = std::to_string(1LL << std::min(std::abs(k), 62));
      out.push_back({std::exp2(k), 0.5 + k / (2 * half_range), k < 0 ? "1/" + power : power});
    }
    return out;
  }
};

/// The scale of `amounts` (contracts 1, 2); clip_share in [0, 0.5).
inline RatioScale ratio_scale(const std::vector<double>& amounts, double clip_share = 0.05) {
  SPHTROCH_ASSERT(clip_share >= 0 && clip_share < 0.5, "ratio_scale: clip_share in [0, 0.5)");
  RatioScale s;
  s.clip_share = clip_share;
  std::vector<double> positive;
  double sum = 0;
  for (const double a : amounts) {
    SPHTROCH_ASSERT(std::isfinite(a) && a >= 0, "ratio_scale: finite amounts >= 0");
    sum += a;
    if (a > 0) positive.push_back(a);
  }
  if (positive.empty()) return s;
  s.mean = sum / static_cast<double>(amounts.size());
  std::sort(positive.begin(), positive.end());
  const std::size_t low = static_cast<std::size_t>(std::floor(clip_share * static_cast<double>(positive.size() - 1)));
  const double low_end = std::fabs(std::log2(positive[low] / s.mean));
  const double high_end = std::fabs(std::log2(positive[positive.size() - 1 - low] / s.mean));
  s.half_range = std::max({1.0, low_end, high_end});
  return s;
}

}  // namespace sphtroch
