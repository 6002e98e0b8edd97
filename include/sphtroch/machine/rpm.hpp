// sphtroch/machine/rpm.hpp — a machine's speed in revolutions per minute, as an exact rational.
//
//   sphtroch::Rpm outer(133, 100);   // 1.33 rpm exactly
//   outer.value();                   // 1.33 (the nearest double)
//   sphtroch::Rpm::frequency(1, outer, -1, sphtroch::Rpm(2));   // 1.33 - 2 = -67/100 rpm, exact
//
// A speed typed as a decimal ("1.33") is read as the fraction it names (133/100), so that ratios
// of speeds, periods and exact resonances (a combination of the two speeds that is exactly zero)
// are decided in integers, never by comparing doubles. io/parse.hpp's parse_rpm reads the text.
#pragma once

#include "sphtroch/core/errors.hpp"

#include <cstdint>
#include <numeric>
#include <string>

namespace sphtroch {

class Rpm {
 public:
  /// The largest |speed| accepted (rpm): clinostats and random positioning machines run at a few
  /// rpm to ~100 rpm; the bound keeps every exact combination below in 128-bit integers.
  static constexpr std::int64_t kMaxRpm = 1000;
  /// The largest denominator accepted (six decimal places).
  static constexpr std::int64_t kMaxDenominator = 1000000;

  /// 0 rpm (a stopped frame).
  Rpm() = default;

  /// num/den rpm. REQUIRES den != 0, |num/den| <= kMaxRpm and the reduced den <= kMaxDenominator;
  /// otherwise throws InvalidInput(field).
  explicit Rpm(std::int64_t num, std::int64_t den = 1, const std::string& field = "rpm") {
    const std::string shown = std::to_string(num) + "/" + std::to_string(den);
    const std::string valid = "a speed in rpm, |speed| <= 1000, at most 6 decimal places";
    if (den == 0) throw InvalidInput(field, shown, "zero denominator", valid);
    if (den < 0) {
      num = -num;
      den = -den;
    }
    const std::int64_t g = std::gcd(num < 0 ? -num : num, den);
    num_ = num / g;
    den_ = den / g;
    if (den_ > kMaxDenominator) throw InvalidInput(field, shown, "too many decimal places", valid);
    const __int128 limit = static_cast<__int128>(kMaxRpm) * den_;
    if (num_ > limit || -static_cast<__int128>(num_) > limit) throw InvalidInput(field, shown, "too fast", valid);
  }

  std::int64_t num() const noexcept { return num_; }
  std::int64_t den() const noexcept { return den_; }
  bool is_zero() const noexcept { return num_ == 0; }
  double value() const noexcept { return static_cast<double>(num_) / static_cast<double>(den_); }
  /// Angular speed in rad/s: 2 pi value / 60.
  double radians_per_second() const noexcept { return 6.283185307179586 * value() / 60.0; }
  /// "1.33" style text when the denominator is a power of ten, else "p/q".
  std::string str() const;

  /// The exact frequency j*a + k*b (rpm) of a harmonic of two speeds, as num / den over 128 bits
  /// (never overflows: |j|, |k| <= 4, numerators <= 1e9, denominators <= 1e6).
  struct Frequency {
    __int128 num;
    __int128 den;
    bool is_zero() const noexcept { return num == 0; }
    double value() const noexcept { return static_cast<double>(num) / static_cast<double>(den); }
  };
  static Frequency frequency(int j, const Rpm& a, int k, const Rpm& b) noexcept {
    const __int128 den = static_cast<__int128>(a.den_) / std::gcd(a.den_, b.den_) * b.den_;
    return {j * static_cast<__int128>(a.num_) * (den / a.den_) + k * static_cast<__int128>(b.num_) * (den / b.den_),
            den};
  }

 private:
  std::int64_t num_ = 0;
  std::int64_t den_ = 1;
};

inline std::string Rpm::str() const {
  std::int64_t power = 1;
  int places = 0;
  while (power % den_ != 0 && places < 6) {
    power *= 10;
    ++places;
  }
  if (power % den_ != 0) return std::to_string(num_) + "/" + std::to_string(den_);
  const std::int64_t scaled = (num_ < 0 ? -num_ : num_) * (power / den_);
  std::string text = (num_ < 0 ? "-" : "") + std::to_string(scaled / power);
  if (places == 0) return text;
  std::string fraction = std::to_string(scaled % power);
  fraction.insert(0, static_cast<std::size_t>(places) - fraction.size(), '0');
  return text + "." + fraction;
}

}  // namespace sphtroch
