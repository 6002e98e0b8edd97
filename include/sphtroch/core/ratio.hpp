// sphtroch/core/ratio.hpp — the gear ratio n = p/q as an exact rational in lowest terms.
//
//   sphtroch::Ratio n(5, 2);     // n = 5/2: the curve closes after theta2 spans 2*pi*q = 4*pi
//   n.p() == 5; n.q() == 2; n.value() == 2.5;
//
// Negative ratios are allowed (p < 0). The denominator is always >= 1 after normalisation.
#pragma once

#include "sphtroch/core/errors.hpp"

#include <cstdint>
#include <numeric>
#include <algorithm>
#include <string>
#include <vector>

namespace sphtroch {

class Ratio {
 public:
  /// Largest |p| and q accepted; keeps 2*pi*q and p*theta2 far from overflow and the node
  /// count (which grows like p*q) printable.
  static constexpr std::int64_t kMaxTerm = 1000000;

  /// n = 1 (a regular value type: default-constructible, e.g. std::vector<Ratio>(k)).
  Ratio() : Ratio(1) {}

  /// REQUIRES: q != 0, p != 0, |p| and |q| <= kMaxTerm; otherwise throws InvalidInput (field "n").
  explicit Ratio(std::int64_t p, std::int64_t q = 1) : p_(p), q_(q) {
    if (q == 0 || p == 0 || p > kMaxTerm || p < -kMaxTerm || q > kMaxTerm || q < -kMaxTerm) {
      throw InvalidInput("n", std::to_string(p) + "/" + std::to_string(q),
                         p == 0 ? "the gear ratio must not be zero" : "numerator or denominator out of range",
                         "p/q with p != 0, q != 0, |p|, |q| <= " + std::to_string(kMaxTerm));
    }
    if (q_ < 0) {
      p_ = -p_;
      q_ = -q_;
    }
    const std::int64_t g = std::gcd(p_ < 0 ? -p_ : p_, q_);
    p_ /= g;
    q_ /= g;
  }

  std::int64_t p() const noexcept { return p_; }
  std::int64_t q() const noexcept { return q_; }
  /// |p|: cusps per period on the pitch cone, and the order of the curve's rotational symmetry.
  std::int64_t abs_p() const noexcept { return p_ < 0 ? -p_ : p_; }
  double value() const noexcept { return static_cast<double>(p_) / static_cast<double>(q_); }
  std::string str() const { return q_ == 1 ? std::to_string(p_) : std::to_string(p_) + "/" + std::to_string(q_); }

  friend bool operator==(const Ratio& a, const Ratio& b) { return a.p_ == b.p_ && a.q_ == b.q_; }
  friend bool operator!=(const Ratio& a, const Ratio& b) { return !(a == b); }

 private:
  std::int64_t p_;
  std::int64_t q_;
};

/// The ratio set of `--ratios P,Q`: every n = p/q in lowest terms with 1 <= |p| <= max_p and
/// 1 <= q <= max_q, both signs, in increasing order of n. REQUIRES 1 <= max_p, max_q <= Ratio::kMaxTerm
/// (InvalidInput "ratios" otherwise); the caller bounds the cost (2 P Q entries at most).
inline std::vector<Ratio> ratio_set(std::int64_t max_p, std::int64_t max_q) {
  if (max_p < 1 || max_q < 1 || max_p > Ratio::kMaxTerm || max_q > Ratio::kMaxTerm)
    throw InvalidInput("ratios", std::to_string(max_p) + "," + std::to_string(max_q), "bounds out of range",
                       "P,Q with 1 <= P, Q <= " + std::to_string(Ratio::kMaxTerm));
  std::vector<Ratio> set;
  for (std::int64_t q = 1; q <= max_q; ++q)
    for (std::int64_t p = 1; p <= max_p; ++p)
      if (std::gcd(p, q) == 1) {
        set.emplace_back(p, q);
        set.emplace_back(-p, q);
      }
  std::sort(set.begin(), set.end(), [](const Ratio& a, const Ratio& b) { return a.p() * b.q() < b.p() * a.q(); });
  return set;
}

}  // namespace sphtroch
