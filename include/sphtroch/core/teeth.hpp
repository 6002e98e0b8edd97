// sphtroch/core/teeth.hpp — gear ratios as tooth counts: n is the sun-to-planet tooth ratio.
//
//   sphtroch::Teeth t{39, 15};                    // sun 39 teeth, planet 15
//   t.ratio() == sphtroch::Ratio(13, 5);          // the curve depends on n only; 39:15 is kept
//   sphtroch::ratio_set(sphtroch::ToothRange{12, 60});   // every n = ±Zs/Zp, 12 <= Zs, Zp <= 60
//   sphtroch::smallest_teeth(sphtroch::Ratio(-1, 2), {12, 60});   // Teeth{-12, 24}
//
// Convention: n = Zs / Zp; a negative sun count means internal gearing (n < 0). A tooth range
// [min, max] admits a ratio when some pair of counts in the range, one of each gear, gives it.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/ratio.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// Largest tooth count accepted (a catalogue's gears have a few hundred at most).
constexpr std::int64_t kMaxTeeth = 1000;

/// A pair of tooth counts: sun (negative: internal gearing) and planet (positive).
struct Teeth {
  std::int64_t sun = 1;
  std::int64_t planet = 1;

  Ratio ratio() const { return Ratio(sun, planet); }
  /// "39:15", "-24:12".
  std::string str() const { return std::to_string(sun) + ":" + std::to_string(planet); }
};

/// Tooth counts allowed for either gear: min <= |Z| <= max.
struct ToothRange {
  std::int64_t min = 1;
  std::int64_t max = 1;

  /// "12..60".
  std::string str() const { return std::to_string(min) + ".." + std::to_string(max); }
};

/// REQUIRES 1 <= |sun|, planet <= kMaxTeeth; InvalidInput (field "teeth") otherwise.
inline Teeth checked_teeth(std::int64_t sun, std::int64_t planet) {
  const std::int64_t s = sun < 0 ? -sun : sun;
  if (s < 1 || s > kMaxTeeth || planet < 1 || planet > kMaxTeeth)
    throw InvalidInput("teeth", std::to_string(sun) + ":" + std::to_string(planet), "tooth count out of range",
                       "ZS:ZP with 1 <= |ZS|, ZP <= " + std::to_string(kMaxTeeth) + " (ZS < 0: internal gearing)");
  return Teeth{sun, planet};
}

/// REQUIRES 1 <= min <= max <= kMaxTeeth; InvalidInput (field "teeth") otherwise.
inline ToothRange checked_range(std::int64_t min, std::int64_t max) {
  if (min < 1 || max < min || max > kMaxTeeth)
    throw InvalidInput("teeth", std::to_string(min) + ".." + std::to_string(max), "not a range of tooth counts",
                       "MIN..MAX with 1 <= MIN <= MAX <= " + std::to_string(kMaxTeeth));
  return ToothRange{min, max};
}

/// The pair with the fewest teeth in `range` that gives n (sun carries n's sign), or nothing.
inline std::optional<Teeth> smallest_teeth(const Ratio& n, const ToothRange& range) {
  const std::int64_t small = std::min(n.abs_p(), n.q()), large = std::max(n.abs_p(), n.q());
  const std::int64_t k = (range.min + small - 1) / small;  // the least multiple reaching min
  if (k * large > range.max) return std::nullopt;
  return Teeth{k * n.p(), k * n.q()};
}

/// Every n = ±Zs/Zp in lowest terms with both counts in `range` (both signs), in increasing order
/// of n; at most 2 max^2 entries (checked_range bounds max).
inline std::vector<Ratio> ratio_set(const ToothRange& range) {
  checked_range(range.min, range.max);
  std::vector<Ratio> set;
  for (std::int64_t q = 1; q <= range.max; ++q)
    for (std::int64_t p = 1; p <= range.max; ++p)
      if (std::gcd(p, q) == 1 && smallest_teeth(Ratio(p, q), range)) {
        set.emplace_back(p, q);
        set.emplace_back(-p, q);
      }
  std::sort(set.begin(), set.end(), [](const Ratio& a, const Ratio& b) { return a.p() * b.q() < b.p() * a.q(); });
  return set;
}

/// The teeth a report echoes for a ratio: the pair the user gave (--teeth ZS:ZP) for its ratio,
/// else the smallest pair of a given range, else none (the ratio was given as n).
struct TeethSpec {
  std::optional<Teeth> pair;
  std::optional<ToothRange> range;

  std::optional<Teeth> of(const Ratio& n) const {
    if (pair && pair->ratio() == n) return pair;
    return range ? smallest_teeth(n, *range) : std::nullopt;
  }
};

}  // namespace sphtroch
