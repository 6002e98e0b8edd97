// sphtroch/core/portable_trig.hpp against MPFR (300 bits, correctly rounded): every result is
// the correctly rounded sin or cos or its neighbour (faithful: error below one ulp), on
// arguments of every scale up to kPortableTrigMax and on the doubles nearest k pi/2 and k pi/4
// (the reduction's hardest and the quadrant borders); the invariants sin(-x) = -sin x and
// cos(-x) = cos x bit for bit; beyond kPortableTrigMax, the C library's values.
#include "catch2/catch.hpp"

#include "sphtroch/core/portable_trig.hpp"

#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using sphtroch::sin_cos;

namespace {

/// sin x or cos x to 300 bits, and its error from `value` in ulps of the correctly rounded result.
class Reference {
 public:
  Reference() { mpfr_inits2(300, exact_, diff_, pi_, static_cast<mpfr_ptr>(nullptr)); mpfr_const_pi(pi_, MPFR_RNDN); }
  ~Reference() { mpfr_clears(exact_, diff_, pi_, static_cast<mpfr_ptr>(nullptr)); }
  Reference(const Reference&) = delete;
  Reference& operator=(const Reference&) = delete;

  double ulp_error(double x, bool sine, double value) {
    mpfr_set_d(exact_, x, MPFR_RNDN);
    (sine ? mpfr_sin : mpfr_cos)(exact_, exact_, MPFR_RNDN);
    const double rounded = std::fabs(mpfr_get_d(exact_, MPFR_RNDN));
    const double ulp = std::nextafter(rounded, INFINITY) - rounded;
    mpfr_set_d(diff_, value, MPFR_RNDN);
    mpfr_sub(diff_, diff_, exact_, MPFR_RNDN);
    return std::fabs(mpfr_get_d(diff_, MPFR_RNDN)) / ulp;
  }

  /// The double nearest k pi / d.
  double multiple_of_pi(std::int64_t k, long d) {
    mpfr_mul_si(exact_, pi_, static_cast<long>(k), MPFR_RNDN);
    mpfr_div_si(exact_, exact_, d, MPFR_RNDN);
    return mpfr_get_d(exact_, MPFR_RNDN);
  }

 private:
  mpfr_t exact_, diff_, pi_;
};

/// The larger error of sin and cos at x, in ulps.
double worst_error(Reference& ref, double x) {
  const auto t = sin_cos(x);
  return std::max(ref.ulp_error(x, true, t.sin), ref.ulp_error(x, false, t.cos));
}

}  // namespace

TEST_CASE("portable_trig: faithful on arguments of every scale from 2^-40 to 2^20", "[portable_trig]") {
  Reference ref;
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  double worst = 0.0;
  for (int scale = -40; scale <= 20; ++scale)
    for (int i = 0; i < 2000; ++i) {
      const double x = std::ldexp(unit(rng), scale);
      if (std::fabs(x) > sphtroch::kPortableTrigMax) continue;
      const double e = worst_error(ref, x);
      worst = std::max(worst, e);
      if (!(e < 1.0)) FAIL_CHECK("x = " << x << ": " << e << " ulp");
    }
  CHECK(worst < 1.0);
  CHECK(worst > 0.5);  // some results are not correctly rounded: the reference does see the errors
}

TEST_CASE("portable_trig: faithful at the doubles nearest k pi/2 and k pi/4 and their neighbours", "[portable_trig]") {
  Reference ref;
  const std::int64_t last = static_cast<std::int64_t>(sphtroch::kPortableTrigMax / (3.14159265358979 / 4));
  double worst = 0.0;
  for (std::int64_t k = 1; k <= last; k += (k < 4096 ? 1 : 61)) {
    for (long d : {2L, 4L}) {
      const double x = ref.multiple_of_pi(k, d);
      for (double y : {x, std::nextafter(x, 0.0), std::nextafter(x, INFINITY)}) {
        if (std::fabs(y) > sphtroch::kPortableTrigMax) continue;
        const double e = worst_error(ref, y);
        worst = std::max(worst, e);
        if (!(e < 1.0)) FAIL_CHECK("x = " << y << " (k = " << k << ", pi/" << d << "): " << e << " ulp");
      }
    }
  }
  CHECK(worst < 1.0);
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
