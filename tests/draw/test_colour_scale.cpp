// Tests for sphtroch/draw/diverging_colour.hpp (the map's stops, interpolation, its gradient) and
// sphtroch/draw/ratio_scale.hpp (the mean, the clipped symmetric log range, positions, ticks),
// against values computed by hand from the headers' contracts.
#include "catch2/catch.hpp"

#include "sphtroch/draw/diverging_colour.hpp"
#include "sphtroch/draw/ratio_scale.hpp"

#include "svg_support.hpp"

#include <cmath>
#include <regex>
#include <string>
#include <vector>

using namespace sphtroch;

TEST_CASE("diverging_colour: ColorBrewer RdBu from blue to red with its neutral centre", "[colour]") {
  CHECK(diverging_colour(0.0) == "#053061");
  CHECK(diverging_colour(0.5) == "#f7f7f7");
  CHECK(diverging_colour(1.0) == "#67001f");
  CHECK(diverging_colour(-3.0) == "#053061");  // clamped
  CHECK(diverging_colour(7.0) == "#67001f");
  CHECK(diverging_colour(std::nan("")) == "#f7f7f7");
  // Halfway between the stops at 0.5 (#f7f7f7) and 0.6 (#fddbc7): (247+253)/2, (247+219)/2, (247+199)/2.
  CHECK(diverging_colour(0.55) == "#fae9df");
  // Luminance falls monotonically away from the centre on both sides (a diverging map).
  double previous = 2;
  for (int k = 50; k >= 0; --k) {
    const double l = svg_test::luminance(diverging_colour(k / 100.0));
    CHECK(l <= previous + 1e-12);
    previous = l;
  }
  previous = 2;
  for (int k = 50; k <= 100; ++k) {
    const double l = svg_test::luminance(diverging_colour(k / 100.0));
    CHECK(l <= previous + 1e-12);
    previous = l;
  }
}

TEST_CASE("diverging_gradient: the same stops as the fills, at offsets 0% .. 100%", "[colour]") {
  const std::string g = diverging_gradient("scale");
  CHECK(g.find("<linearGradient id=\"scale\"") == 0);
  const std::regex stop_re("<stop offset=\"([0-9]+)%\" stop-color=\"(#[0-9a-f]{6})\"/>");
  int count = 0;
  for (std::sregex_iterator m(g.begin(), g.end(), stop_re), end; m != end; ++m, ++count) {
    const double f = std::stoi((*m)[1]) / 100.0;
    CHECK(std::stoi((*m)[1]) == 10 * count);
    CHECK((*m)[2] == diverging_colour(f));
  }
  CHECK(count == 11);
}

TEST_CASE("ratio_scale: the mean over every amount, the range from the clip percentiles, at least 1/2 .. 2", "[colour]") {
  // 20 positive amounts 1 .. 20 and 5 zeros: mean = 210 / 25 = 8.4. Clip share 0.05: the sorted
  // positive amounts' entry floor(0.05 x 19) = 0 (the amount 1) and entry 19 (20):
  // |log2(1 / 8.4)| = 3.07, |log2(20 / 8.4)| = 1.25, so the half range is log2 8.4.
  std::vector<double> a(5, 0.0);
  for (int k = 1; k <= 20; ++k) a.push_back(k);
  const RatioScale s = ratio_scale(a);
  CHECK(s.mean == Approx(8.4).epsilon(1e-15));
  CHECK(s.half_range == Approx(std::log2(8.4)).epsilon(1e-14));
  CHECK(s.position(8.4) == Approx(0.5).margin(1e-15));
  CHECK(s.position(1.0) == Approx(0.0).margin(1e-15));
  CHECK(s.position(8.4 * 8.4) == Approx(1.0).margin(1e-15));
  CHECK(s.position(1e-9) == 0.0);  // beyond the clip: the end
  CHECK(s.position(16.8) == Approx(0.5 + 1 / (2 * std::log2(8.4))).epsilon(1e-14));
  // Ticks: half range 3.07, step ceil(3.07 / 4) = 1: 1/8 .. 8.
  const auto ticks = s.ticks();
  REQUIRE(ticks.size() == 7);
  CHECK(ticks.front().text == "1/8");
  CHECK(ticks[3].text == "1");
  CHECK(ticks[3].position == 0.5);
  CHECK(ticks.back().text == "8");
  CHECK(ticks.back().position == Approx(s.position(8 * 8.4)).epsilon(1e-14));
  // An even spread: the scale keeps its least range, 1/2 .. 2.
  const RatioScale even = ratio_scale({5.0, 5.1, 4.9, 5.0});
  CHECK(even.half_range == 1.0);
  CHECK(even.low_ratio() == 0.5);
  CHECK(even.high_ratio() == 2.0);
  CHECK(even.ticks().size() == 3);
  // A wide range: the step grows so that there are at most nine ticks.
  const RatioScale wide = ratio_scale({1.0, 1e6});
  CHECK(wide.ticks().size() <= 9);
  // Nothing visited: no mean, nothing to place.
  CHECK(ratio_scale({0.0, 0.0}).mean == 0.0);
}
