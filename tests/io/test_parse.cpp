// Tests for sphtroch/io/parse.hpp: every accepted form of angles, ratios and tracer twists, and
// every rejection, each with an InvalidInput that names the field it was asked to parse.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/io/parse.hpp"

#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <limits>
#include <set>
#include <string>
#include <utility>

using namespace sphtroch;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();

/// |a - b| within k ulp of the larger magnitude (parsing does at most a few roundings).
bool near(double a, double b, double k = 2) { return std::abs(a - b) <= k * kEps * std::max(std::abs(a), std::abs(b)); }

using sphtroch::test::expect_invalid;
}  // namespace

TEST_CASE("parse_angle accepts radians, multiples of pi and degrees", "[parse][angle]") {
  CHECK(parse_angle("1.25", "a2") == 1.25);
  CHECK(parse_angle("2", "a2") == 2.0);
  CHECK(parse_angle(".5", "a2") == 0.5);
  CHECK(parse_angle("1e-3", "a2") == 1e-3);
  CHECK(parse_angle("-0.75", "phase") == -0.75);
  CHECK(parse_angle("  1.5 ", "a2") == 1.5);
  CHECK(parse_angle("pi", "a2") == kPi);
  CHECK(near(parse_angle("pi/2", "a2"), kPi / 2));
  CHECK(near(parse_angle("2pi/3", "a2"), 2 * kPi / 3));
  CHECK(near(parse_angle("2*pi/3", "a2"), 2 * kPi / 3));
  CHECK(near(parse_angle("0.75pi", "a2"), 0.75 * kPi));
  CHECK(near(parse_angle("0.75*pi", "a2"), 0.75 * kPi));
  CHECK(near(parse_angle("-pi/4", "phase"), -kPi / 4));
  CHECK(near(parse_angle("+pi/4", "phase"), kPi / 4));
  CHECK(near(parse_angle("-2pi", "phase"), -2 * kPi));
  CHECK(near(parse_angle("90deg", "a2"), kPi / 2));
  CHECK(near(parse_angle("45.5deg", "a2"), 45.5 * kPi / 180));
  CHECK(near(parse_angle("-30deg", "phase"), -kPi / 6));
}

TEST_CASE("parse_angle rejects nan, inf, empty, words, zero divisors and overflow, naming the field",
          "[parse][angle][errors]") {
  for (const char* text : {"nan", "NaN", "inf", "-inf", "infinity", "", " ", "abc", "pi/0", "1e999", "-1e999",
                           "1e999deg", "deg", "pi/", "2pi3", "pi/abc", "1..2", "1.2.3", "0x10", "1,5", "2 pi", "pi*2",
                           "--1", "1e", "pi/nan", "nanpi"}) {
    INFO("text = '" << text << "'");
    const InvalidInput e = expect_invalid([&] { parse_angle(text, "a2"); });
    CHECK(e.field() == "a2");
    CHECK(e.value() == text);
    CHECK_FALSE(e.valid_range().empty());
  }
  CHECK(expect_invalid([] { parse_angle("nan", "phase"); }).field() == "phase");
}

TEST_CASE("parse_ratio accepts integers, p/q and decimals as exact rationals in lowest terms",
          "[parse][ratio]") {
  CHECK(parse_ratio("2") == Ratio(2));
  CHECK(parse_ratio("1") == Ratio(1));
  CHECK(parse_ratio("5/2") == Ratio(5, 2));
  CHECK(parse_ratio("2.5") == Ratio(5, 2));
  CHECK(parse_ratio("-3/2") == Ratio(-3, 2));
  CHECK(parse_ratio("-1.5") == Ratio(-3, 2));
  CHECK(parse_ratio("0.4") == Ratio(2, 5));
  CHECK(parse_ratio("10/4") == Ratio(5, 2));
  CHECK(parse_ratio("10/4").p() == 5);
  CHECK(parse_ratio("10/4").q() == 2);
  CHECK(parse_ratio("3/-2") == Ratio(-3, 2));
  CHECK(parse_ratio("-7") == Ratio(-7));
  CHECK(parse_ratio("+2") == Ratio(2));
  CHECK(parse_ratio(".25") == Ratio(1, 4));
  CHECK(parse_ratio("1.000000000") == Ratio(1));  // 9 places, reduced before the range check
  CHECK(parse_ratio("0.125") == Ratio(1, 8));
  CHECK(parse_ratio(" 5/2 ") == Ratio(5, 2));
}

TEST_CASE("parse_ratio rejects n = 0, zero denominators, non-numbers and overflow with field n",
          "[parse][ratio][errors]") {
  for (const char* text : {"0", "-0", "0/5", "0.0", "1/0", "nan", "inf", "", "abc", "1e999", "2.5.1", "1/2/3", "1.5/2",
                           "pi", "2e3", "1.", "1.0000000001", "99999999999999999999", "1/99999999999", "1000001", "0.333333333",
                           "--2", "2x"}) {
    INFO("text = '" << text << "'");
    const InvalidInput e = expect_invalid([&] { parse_ratio(text, "n"); });
    CHECK(e.field() == "n");
    CHECK(e.value() == text);
    CHECK_FALSE(e.valid_range().empty());
  }
}

TEST_CASE("parse_a3 accepts angles and the references ap, pi-ap, a2, pi-a2 with offsets", "[parse][a3]") {
  auto is = [](const A3Spec& s, A3Reference r, double offset) { return s.reference == r && s.offset == offset; };
  CHECK(is(parse_a3("1.25"), A3Reference::given, 1.25));
  CHECK(parse_a3("pi/2").reference == A3Reference::given);
  CHECK(near(parse_a3("pi/2").offset, kPi / 2));
  CHECK(is(parse_a3("ap"), A3Reference::pitch_cone, 0.0));
  CHECK(is(parse_a3("pi-ap"), A3Reference::mirror_pitch_cone, 0.0));
  CHECK(is(parse_a3("a2"), A3Reference::a2, 0.0));
  CHECK(is(parse_a3("pi-a2"), A3Reference::pi_minus_a2, 0.0));
  CHECK(is(parse_a3("ap+1e-6"), A3Reference::pitch_cone, 1e-6));
  CHECK(is(parse_a3("ap-1e-6"), A3Reference::pitch_cone, -1e-6));
  CHECK(is(parse_a3("pi-ap-1e-9"), A3Reference::mirror_pitch_cone, -1e-9));
  CHECK(is(parse_a3("pi-ap+1e-9"), A3Reference::mirror_pitch_cone, 1e-9));
  CHECK(is(parse_a3("a2+0.25"), A3Reference::a2, 0.25));
  CHECK(is(parse_a3("pi-a2-0.5"), A3Reference::pi_minus_a2, -0.5));
  CHECK(parse_a3("ap+1deg").reference == A3Reference::pitch_cone);
  CHECK(near(parse_a3("ap+1deg").offset, kPi / 180));
  CHECK(near(parse_a3("a2-pi/100").offset, -kPi / 100));
}

TEST_CASE("parse_a3 rejects malformed references and non-numbers with field a3", "[parse][a3][errors]") {
  for (const char* text : {"", "nan", "inf", "abc", "ap+", "ap-", "ap*2", "apx", "pi-", "pi-ap+nan", "a2+inf",
                           "ap+1e999", "a3", "pi/0"}) {
    INFO("text = '" << text << "'");
    const InvalidInput e = expect_invalid([&] { parse_a3(text, "a3"); });
    CHECK(e.field() == "a3");
    CHECK(e.value() == text);
  }
}

TEST_CASE("make_gear_train turns parsed a3 references into the a3 of Eq. 4", "[parse][a3]") {
  const Ratio n = parse_ratio("2");
  const double a2 = parse_angle("pi/2", "a2");
  // a_p = atan(sin a2 / (cos a2 + 2)) = atan(1/2) for a2 = pi/2, n = 2 (Sec. 5).
  CHECK(std::abs(make_gear_train(a2, parse_a3("ap"), n).a3() - std::atan(0.5)) <= 2 * kEps);
  CHECK(std::abs(make_gear_train(a2, parse_a3("pi-ap"), n).a3() - (kPi - std::atan(0.5))) <= 4 * kEps);
  CHECK(std::abs(make_gear_train(a2, parse_a3("ap+1e-6"), n).a3() - (std::atan(0.5) + 1e-6)) <= 2 * kEps);
  CHECK(make_gear_train(a2, parse_a3("1"), n).a3() == 1.0);
  CHECK(make_gear_train(a2, parse_a3("a2"), n).a3() == a2);
  const InvalidInput e = expect_invalid([&] { make_gear_train(a2, parse_a3("pi-a2+pi"), n); });
  CHECK(e.field() == "a3");
}

TEST_CASE("parse_angle accepts a pi term plus or minus radians (pi-1e-6, pi/2+0.1)", "[parse][angle]") {
  CHECK(parse_angle("pi-1e-6", "a2") == kPi - 1e-6);
  CHECK(parse_angle("pi/2+0.1", "a2") == kPi / 2 + 0.1);
  CHECK(parse_angle("2pi/3-1e-9", "a3") == 2 * kPi / 3 - 1e-9);
  CHECK(parse_angle("pi+1e-3", "phase") == kPi + 1e-3);
  for (const char* bad : {"pi-", "pi/2+", "pi-x", "pi--1", "pi/2+1e"}) {
    INFO(bad);
    CHECK_THROWS_AS(parse_angle(bad, "a2"), InvalidInput);
  }
}

TEST_CASE("an angle below the smallest subnormal reads as zero, like every number (fuzz finding)", "[parse]") {
  // fuzz_parse: "+1e-906" was a number (parse_number: 0) but not an angle; both read it as 0 now.
  CHECK(sphtroch::parse_angle("+1e-906", "phase") == 0.0);
  CHECK(std::signbit(sphtroch::parse_angle("-1e-906", "phase")));
  CHECK(sphtroch::parse_angle("1e-906deg", "phase") == 0.0);
  sphtroch::test::expect_invalid([] { sphtroch::parse_angle("1e906", "phase"); });
}

TEST_CASE("teeth: ZS:ZP is n = ZS/ZP, a range's ratio set is every pair of counts in it, reduced", "[teeth]") {
  CHECK(sphtroch::parse_teeth("39:15").ratio() == sphtroch::Ratio(13, 5));
  CHECK(sphtroch::parse_teeth("-24:12").ratio() == sphtroch::Ratio(-2));
  CHECK(sphtroch::parse_teeth("39:15").str() == "39:15");
  for (const char* bad : {"39", "39:0", "0:15", "39:-15", "1001:1", "a:b", "39:15:2", ""}) {
    INFO(bad);
    CHECK_THROWS_AS(sphtroch::parse_teeth(bad), sphtroch::InvalidInput);
  }
  for (const char* bad : {"12", "0..5", "7..6", "1..1001", "x..9", "3..."}) {
    INFO(bad);
    CHECK_THROWS_AS(sphtroch::parse_tooth_range(bad), sphtroch::InvalidInput);
  }
  // Independent: every pair (Zs, Zp) of counts in the range, both signs, reduced by hand.
  for (const auto& [lo, hi] : {std::pair<long, long>{1, 7}, {12, 30}, {17, 17}, {5, 11}}) {
    std::set<std::pair<long, long>> expected;
    for (long zs = lo; zs <= hi; ++zs)
      for (long zp = lo; zp <= hi; ++zp) {
        long a = zs, b = zp;
        while (b) a = std::exchange(b, a % b);  // a = gcd
        expected.insert({zs / a, zp / a});
        expected.insert({-zs / a, zp / a});
      }
    const auto set = sphtroch::ratio_set(sphtroch::ToothRange{lo, hi});
    std::set<std::pair<long, long>> got;
    for (const auto& n : set) got.insert({n.p(), n.q()});
    CHECK(got == expected);
    CHECK(got.size() == set.size());  // no ratio twice
    for (std::size_t k = 1; k < set.size(); ++k) CHECK(set[k - 1].value() < set[k].value());
    // The echoed teeth are in the range, give n, and no smaller multiple is in the range.
    for (const auto& n : set) {
      const auto t = sphtroch::smallest_teeth(n, {lo, hi});
      REQUIRE(t);
      CHECK(t->ratio() == n);
      CHECK(std::min(std::labs(t->sun), t->planet) >= lo);
      CHECK(std::max(std::labs(t->sun), t->planet) <= hi);
      const long k = t->planet / n.q();
      CHECK((k == 1 || std::min(n.abs_p(), n.q()) * (k - 1) < lo));
    }
  }
  CHECK(sphtroch::ratio_set(sphtroch::ToothRange{1, 4}).size() == sphtroch::ratio_set(4, 4).size());
  CHECK_FALSE(sphtroch::smallest_teeth(sphtroch::Ratio(13, 5), {12, 30}));  // 26:10 has a 10, 39:15 a 39
}
