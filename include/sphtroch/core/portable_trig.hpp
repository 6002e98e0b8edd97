// sphtroch/core/portable_trig.hpp — sin and cos of a double, the same bits on every IEEE-754
// platform (glibc natively, musl in the explorer's WebAssembly module), so that the page draws
// the tool's curve to the last bit. Other scalar types use their own sin and cos.
//
//   const sphtroch::SinCos<double> t = sphtroch::sin_cos(0.3);   // t.sin, t.cos
//
// Method (textbook, written here): x = k pi/2 + r with k = round(x 2/pi); r as a double-double by
// Cody-Waite with pi/2 in four parts, the first three of 31, 32 and 28 bits, so that k times each
// is exact for |k| <= 2^20 and the first subtraction is exact (Sterbenz); the rest are error-free
// sums. The reduction's error is ~2^-106 of r (measured with MPFR; no double below 2^20 lies
// within 2^-60 of a multiple of pi/2, where r would cancel most). Then the Taylor series of sin r
// and cos r through r^17 and r^18 (truncation < 2^-62 relative for |r| <= pi/4 + 2^-30), with
// r's low part and the rounding of r^2 carried as corrections, and the quadrant k mod 4.
// Error: below one ulp (faithful: the result is the correctly rounded value or its neighbour);
// tests/core/test_portable_trig.cpp checks that against MPFR on 10^6 arguments of every scale and
// on the doubles nearest k pi/2 and k pi/4. Identical bits need IEEE double arithmetic in
// round-to-nearest without FMA contraction (-ffp-contract=off: the project's flags; WebAssembly
// has neither other modes nor contraction); in another rounding mode the result is within a few
// ulp (k = floor(|x| 2/pi + 1/2) is a nearest integer in any mode, up to ties where either works).
// Outside |x| <= kPortableTrigMax (2^20 rad): the C library's sin and cos.
#pragma once

#include <cmath>

namespace sphtroch {

/// sin and cos of one angle.
template <typename Scalar>
struct SinCos {
  Scalar sin, cos;
};

/// The largest |x| (radians) whose sin_cos is computed here; beyond, the C library's.
constexpr double kPortableTrigMax = 0x1p20;

/// sin x and cos x, x in radians, the same bits everywhere for |x| <= kPortableTrigMax (see
/// header); error below one ulp.
inline SinCos<double> sin_cos(double x);

/// sin x and cos x in any other scalar type (long double, MPFR, ...): its own functions.
template <typename Scalar>
SinCos<Scalar> sin_cos(const Scalar& x) {
  using std::cos;
  using std::sin;
  return {Scalar(sin(x)), Scalar(cos(x))};
}

/// sin and cos of two angles.
template <typename Scalar>
struct SinCosPair {
  SinCos<Scalar> first, second;
};

/// sin_cos(x) and sin_cos(y), the same bits as two calls; in double the two are evaluated
/// together, two lanes of one vector (one evaluation instead of two).
inline SinCosPair<double> sin_cos_pair(double x, double y);

/// Other scalar types: two calls.
template <typename Scalar>
SinCosPair<Scalar> sin_cos_pair(const Scalar& x, const Scalar& y) {
  return {sin_cos(x), sin_cos(y)};
}

// Implementation details follow.
namespace portable_trig_detail {

/// pi/2 = kPio2[0] + kPio2[1] + kPio2[2] + kPio2[3] + O(2^-157): 31, 32, 28 and 53 bits.
constexpr double kPio2[4] = {0x1.921fb544p+0, 0x1.0b4611a6p-34, 0x1.3198a2ep-69, 0x1.b839a252049c1p-104};
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;  // 2/pi rounded

/// 1/k! rounded to nearest, k = 0 .. 18, as exact hexadecimal literals: written out, not 1.0 / k!,
/// because under -frounding-math (added by CGAL's targets to whatever links them, the tool
/// included) a quotient of constants is divided at run time, in the current mode: 16 divisions a call.
constexpr double kInvFactorial[19] = {
    0x1p+0,                 0x1p+0,                 0x1p-1,                 0x1.5555555555555p-3,
    0x1.5555555555555p-5,   0x1.1111111111111p-7,   0x1.6c16c16c16c17p-10,  0x1.a01a01a01a01ap-13,
    0x1.a01a01a01a01ap-16,  0x1.71de3a556c734p-19,  0x1.27e4fb7789f5cp-22,  0x1.ae64567f544e4p-26,
    0x1.1eed8eff8d898p-29,  0x1.6124613a86d09p-33,  0x1.93974a8c07c9dp-37,  0x1.ae7f3e733b81fp-41,
    0x1.ae7f3e733b81fp-45,  0x1.952c77030ad4ap-49,  0x1.6827863b97d97p-53};

/// Lanes: double, or two doubles evaluated together (GCC/Clang vector extension: each lane takes
/// the same IEEE operations as a double, so the same bits; sin_cos_pair below).
#if defined(__GNUC__) || defined(__clang__)
#define SPHTROCH_PORTABLE_TRIG_LANES 1
typedef double Lanes2 __attribute__((vector_size(16)));
#endif

template <typename Lanes>
struct DoubleDouble {
  Lanes hi, lo;
};

/// a + b = hi + lo exactly (Knuth's two-sum).
template <typename Lanes>
DoubleDouble<Lanes> two_sum(Lanes a, Lanes b) {
  const Lanes s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

/// a * a = hi + lo exactly (Dekker's product; |a| < 2^995).
template <typename Lanes>
DoubleDouble<Lanes> two_square(Lanes a) {
  const Lanes t = 134217729.0 * a;  // 2^27 + 1: splits a into two 26-bit halves
  const Lanes high = t - (t - a), low = a - high;
  const Lanes p = a * a;
  return {p, ((high * high - p) + 2.0 * high * low) + low * low};
}

/// x - k pi/2 as a double-double, for |k| <= 2^20 and k = round(x 2/pi) (see header). For k = 0
/// (either sign) it is exactly {x, +0}.
template <typename Lanes>
DoubleDouble<Lanes> reduce(Lanes x, Lanes k) {
  const Lanes r1 = x - k * kPio2[0];                   // exact
  const DoubleDouble<Lanes> a = two_sum(r1, -(k * kPio2[1]));  // k kPio2[1] exact: a exact
  const DoubleDouble<Lanes> c = two_sum(a.hi, -(k * kPio2[2]));
  return two_sum(c.hi, (a.lo + c.lo) - k * kPio2[3]);
}

/// sin r for r = hi + lo, |hi| <= pi/4 + 2^-30, |lo| <= ulp(hi).
template <typename Lanes>
Lanes sin_kernel(const DoubleDouble<Lanes>& r) {
  const Lanes z = r.hi * r.hi;
  const Lanes s = -kInvFactorial[3] + z * (kInvFactorial[5] + z * (-kInvFactorial[7] + z * (kInvFactorial[9] +
                  z * (-kInvFactorial[11] + z * (kInvFactorial[13] + z * (-kInvFactorial[15] + z * kInvFactorial[17]))))));
  return r.hi + (r.hi * z * s + r.lo * (1.0 - 0.5 * z));
}

/// cos r for r = hi + lo as above: 1 - r^2/2 with the roundings of r^2 and of 1 - r^2/2 carried.
template <typename Lanes>
Lanes cos_kernel(const DoubleDouble<Lanes>& r) {
  const DoubleDouble<Lanes> z = two_square(r.hi);
  const Lanes c = kInvFactorial[4] + z.hi * (-kInvFactorial[6] + z.hi * (kInvFactorial[8] + z.hi * (-kInvFactorial[10] +
                  z.hi * (kInvFactorial[12] + z.hi * (-kInvFactorial[14] + z.hi * (kInvFactorial[16] +
                  z.hi * -kInvFactorial[18]))))));
  const Lanes half = 0.5 * z.hi, w = 1.0 - half;
  return w + (((1.0 - w) - half) + (z.hi * z.hi * c - (0.5 * z.lo + r.hi * r.lo)));
}

/// k = round(x 2/pi) as a double: not nearbyint (the same in every rounding mode); of |x|, so that
/// sin stays odd bit for bit.
inline double quadrant_count(double x) { return std::copysign(std::floor(std::fabs(x) * kTwoOverPi + 0.5), x); }

/// sin and cos of x = k pi/2 + r from sin r and cos r.
inline SinCos<double> in_quadrant(double s, double c, double k) {
  switch (static_cast<long>(k) & 3) {
    case 0: return {s, c};
    case 1: return {c, -s};
    case 2: return {-s, -c};
    default: return {-c, s};
  }
}

/// Whether sin_cos computes x here (not the C library, not the x = 0 shortcut).
inline bool in_kernel_range(double x) { return std::fabs(x) <= kPortableTrigMax && x != 0.0; }

}  // namespace portable_trig_detail

inline SinCos<double> sin_cos(double x) {
  using namespace portable_trig_detail;
  if (!(std::fabs(x) <= kPortableTrigMax)) return {std::sin(x), std::cos(x)};  // also inf, NaN
  if (x == 0.0) return {x, 1.0};                                                 // keeps -0
  const double k = quadrant_count(x);
  const DoubleDouble<double> r = reduce(x, k);
  return in_quadrant(sin_kernel(r), cos_kernel(r), k);
}

inline SinCosPair<double> sin_cos_pair(double x, double y) {
  using namespace portable_trig_detail;
#if defined(SPHTROCH_PORTABLE_TRIG_LANES)
  if (in_kernel_range(x) && in_kernel_range(y)) {
    const double kx = quadrant_count(x), ky = quadrant_count(y);
    const DoubleDouble<Lanes2> r = reduce(Lanes2{x, y}, Lanes2{kx, ky});
    const Lanes2 s = sin_kernel(r), c = cos_kernel(r);
    return {in_quadrant(s[0], c[0], kx), in_quadrant(s[1], c[1], ky)};
  }
#endif
  return {sin_cos(x), sin_cos(y)};
}

}  // namespace sphtroch
