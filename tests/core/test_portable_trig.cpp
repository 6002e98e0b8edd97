// sphtroch/core/portable_trig.hpp against MPFR (300 bits): every result is the exact value
// rounded down or up (faithful: error below one ulp), on arguments of every scale from subnormal
// up to kPortableTrigMax and on the doubles nearest k pi/2 and k pi/4
// (the reduction's hardest and the quadrant borders); the invariants sin(-x) = -sin x and
// cos(-x) = cos x bit for bit; beyond kPortableTrigMax, the C library's values.
#include "catch2/catch.hpp"

#include "sphtroch/core/portable_trig.hpp"

#include <mpfr.h>

#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

using sphtroch::sin_cos;

namespace {

/// sin x or cos x to 300 bits: whether `value` is faithful (the exact value rounded down or up),
/// and whether it is the correctly rounded one.
class Reference {
 public:
  Reference() { mpfr_inits2(300, exact_, pi_, static_cast<mpfr_ptr>(nullptr)); mpfr_const_pi(pi_, MPFR_RNDN); }
  ~Reference() { mpfr_clears(exact_, pi_, static_cast<mpfr_ptr>(nullptr)); }
  Reference(const Reference&) = delete;
  Reference& operator=(const Reference&) = delete;

  bool faithful(double x, bool sine, double value) {
    evaluate(x, sine);
    return value == mpfr_get_d(exact_, MPFR_RNDD) || value == mpfr_get_d(exact_, MPFR_RNDU);
  }
  bool correctly_rounded(double x, bool sine, double value) {
    evaluate(x, sine);
    return value == mpfr_get_d(exact_, MPFR_RNDN);
  }

/// The double nearest k pi / d.
  double multiple_of_pi(std::int64_t k, long d) {
    mpfr_mul_si(exact_, pi_, static_cast<long>(k), MPFR_RNDN);
    mpfr_div_si(exact_, exact_, d, MPFR_RNDN);
    return mpfr_get_d(exact_, MPFR_RNDN);
  }

 private:
  void evaluate(double x, bool sine) {
    mpfr_set_d(exact_, x, MPFR_RNDN);
    (sine ? mpfr_sin : mpfr_cos)(exact_, exact_, MPFR_RNDN);  // 300 bits: the roundings below are exact's
  }
  mpfr_t exact_, pi_;
};

/// Whether sin and cos at x are both faithful; counts results that are not correctly rounded.
bool faithful_at(Reference& ref, double x, int& not_nearest) {
  const auto t = sin_cos(x);
  not_nearest += !ref.correctly_rounded(x, true, t.sin) + !ref.correctly_rounded(x, false, t.cos);
  return ref.faithful(x, true, t.sin) && ref.faithful(x, false, t.cos);
}

}  // namespace

TEST_CASE("portable_trig: faithful on arguments of every scale from subnormal to 2^20", "[portable_trig]") {
  Reference ref;
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int not_nearest = 0, tried = 0;
  for (int scale = -1074; scale <= 20; scale += (scale < -60 ? 7 : 1))
    for (int i = 0; i < (scale < -60 ? 20 : 2000); ++i) {
      const double x = std::ldexp(unit(rng), scale);
      if (std::fabs(x) > sphtroch::kPortableTrigMax) continue;
      ++tried;
      if (!faithful_at(ref, x, not_nearest)) FAIL_CHECK("x = " << x);
    }
  CHECK(tried > 100000);
  CHECK(not_nearest > 0);  // some results are an ulp off: the reference does tell them apart
}

TEST_CASE("portable_trig: faithful at the doubles nearest k pi/2 and k pi/4 and their neighbours", "[portable_trig]") {
  Reference ref;
  int not_nearest = 0;
  const std::int64_t last = static_cast<std::int64_t>(sphtroch::kPortableTrigMax / (3.14159265358979 / 4));
  for (std::int64_t k = 1; k <= last; k += (k < 4096 ? 1 : 61)) {
    for (long d : {2L, 4L}) {
      const double x = ref.multiple_of_pi(k, d);
      for (double y : {x, std::nextafter(x, 0.0), std::nextafter(x, INFINITY)}) {
        if (std::fabs(y) > sphtroch::kPortableTrigMax) continue;
        if (!faithful_at(ref, y, not_nearest)) FAIL_CHECK("x = " << y << " (k = " << k << ", pi/" << d << ")");
      }
    }
  }
}

TEST_CASE("portable_trig: the nearest quadrant in every rounding mode", "[portable_trig]") {
  // x just above pi/2 rounds to quadrant 1 (r = x - pi/2 tiny); nearbyint under an upward or
  // downward mode would take k = 2 or 0 and evaluate the series at |r| ~ pi/2, 200 ulp off.
  Reference ref;
  const double x = std::nextafter(1.5707963267948966, INFINITY);
  for (int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
    volatile double in = x, sine = 0.0, cosine = 0.0;  // volatile: computed between the mode changes
    std::fesetround(mode);
    const auto t = sin_cos(in);
    sine = t.sin;
    cosine = t.cos;
    std::fesetround(FE_TONEAREST);
    INFO("mode " << mode << ": " << sine << " " << cosine);
    CHECK(ref.faithful(x, true, sine));
    CHECK(ref.faithful(x, false, cosine));  // -1.608e-16
  }
}

TEST_CASE("portable_trig: sin is odd and cos even bit for bit and zero keeps its sign", "[portable_trig]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.0, sphtroch::kPortableTrigMax);
  for (int i = 0; i < 100000; ++i) {
    const double x = std::ldexp(angle(rng), -(i % 40));
    const auto a = sin_cos(x), b = sin_cos(-x);
    REQUIRE(b.sin == -a.sin);
    REQUIRE(b.cos == a.cos);
  }
  CHECK(sin_cos(0.0).sin == 0.0);
  CHECK(!std::signbit(sin_cos(0.0).sin));
  CHECK(std::signbit(sin_cos(-0.0).sin));
  CHECK(sin_cos(-0.0).cos == 1.0);
}

TEST_CASE("portable_trig: beyond 2^20 rad and for non-finite angles the C library's values", "[portable_trig]") {
  for (double x : {std::nextafter(sphtroch::kPortableTrigMax, INFINITY), 3e6, -1e300}) {
    CHECK(sin_cos(x).sin == std::sin(x));
    CHECK(sin_cos(x).cos == std::cos(x));
  }
  CHECK(std::isnan(sin_cos(NAN).sin));
  CHECK(std::isnan(sin_cos(INFINITY).cos));
}

TEST_CASE("portable_trig: sin_cos_pair gives the bits of two sin_cos calls, faithful, in every lane mix", "[portable_trig]") {
  // The pair runs two lanes of one vector: any lane may be tiny (k = 0, the reduction skipped in
  // effect), negative, near 2^20, zero, beyond 2^20 or not finite (then both go the scalar way).
  Reference ref;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  auto same = [](const sphtroch::SinCos<double>& a, const sphtroch::SinCos<double>& b) {
    return std::memcmp(&a.sin, &b.sin, sizeof(double)) == 0 && std::memcmp(&a.cos, &b.cos, sizeof(double)) == 0;
  };
  int not_nearest = 0, checked = 0;
  for (int e = -1074; e <= 20; ++e) {
    for (int i = 0; i < 40; ++i) {
      const double x = std::ldexp(mantissa(rng), e) * (i % 2 ? -1 : 1);
      const double y = std::ldexp(mantissa(rng), (e * 7 + i) % 24 - 3) * (i % 4 < 2 ? 1 : -1);
      const auto p = sphtroch::sin_cos_pair(x, y);
      REQUIRE(same(p.first, sin_cos(x)));
      REQUIRE(same(p.second, sin_cos(y)));
      if (i % 8 == 0 && std::fabs(x) <= sphtroch::kPortableTrigMax) {
        REQUIRE(faithful_at(ref, x, not_nearest));
        ++checked;
      }
    }
  }
  CHECK(checked > 1000);
  const double special[] = {0.0, -0.0, 5e-324, -5e-324, 1.0, sphtroch::kPortableTrigMax, -sphtroch::kPortableTrigMax,
                            std::nextafter(sphtroch::kPortableTrigMax, INFINITY), 1e300, INFINITY, NAN};
  for (const double x : special)
    for (const double y : special) {
      const auto p = sphtroch::sin_cos_pair(x, y);
      const auto a = sin_cos(x), b = sin_cos(y);
      CHECK((same(p.first, a) || (std::isnan(a.sin) && std::isnan(p.first.sin))));
      CHECK((same(p.second, b) || (std::isnan(b.sin) && std::isnan(p.second.sin))));
    }
}
