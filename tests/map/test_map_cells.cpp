// Tests of map_cells.hpp: the cells along one a2 cover (0, pi) without a gap, and each cell's node
// count is what classify() (the exact polyline census, an independent computation) counts at its
// middle; a train's map_margin is no larger than its a3 distance to any event at its a2, and a
// move in a3 by less than the margin keeps classify()'s count.
#include "catch2/catch.hpp"
#include "sphtroch/classify.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/map/map_cells.hpp"

#include <cmath>
#include <random>
#include <vector>

using namespace sphtroch;

namespace {

constexpr double kPi = 3.141592653589793;

std::int64_t classified_nodes(double a2, double a3, const Ratio& n) {
  const Classification c = classify(GearTrain(a2, a3, n, 0.0));
  REQUIRE(c.agreement.ok());
  return static_cast<std::int64_t>(c.nodes.size());
}

}  // namespace

TEST_CASE("map_cells: contiguous from 0 to pi, each cell's count classify()'s at its middle", "[map_cells]") {
  for (const Ratio& n : {Ratio(2), Ratio(-5, 3), Ratio(7, 5), Ratio(1, 2)})
    for (const double a2 : {0.4, 1.1, 2.3}) {
      INFO("n = " << n.str() << ", a2 = " << a2);
      const std::vector<MapCell> cells = map_cells(a2, n);
      REQUIRE(!cells.empty());
      CHECK(cells.front().lo == 0.0);
      CHECK(cells.back().hi == kPi);
      for (std::size_t k = 0; k < cells.size(); ++k) {
        if (k > 0) CHECK(cells[k].lo == cells[k - 1].hi);
        CHECK(cells[k].lo <= cells[k].hi);
        if (cells[k].hi - cells[k].lo < 1e-3) continue;  // too thin to classify its middle robustly
        const double mid = 0.5 * (cells[k].lo + cells[k].hi);
        CHECK(cells[k].nodes == classified_nodes(a2, mid, n));
      }
    }
}

TEST_CASE("map_margin: within every event's a3 distance, and a move inside it keeps the count", "[map_cells]") {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> angle(0.2, kPi - 0.2);
  const Ratio ratios[] = {Ratio(2), Ratio(-7, 3), Ratio(5, 2)};
  for (int k = 0; k < 12; ++k) {
    const Ratio n = ratios[k % 3];
    const double a2 = angle(rng), a3 = angle(rng);
    INFO("n = " << n.str() << ", a2 = " << a2 << ", a3 = " << a3);
    const double m = map_margin(a2, a3, n);
    REQUIRE(m >= 0);
    for (const BoundaryEvent& e : boundary_set(a2, n).events) CHECK(m <= std::abs(a3 - e.a3) + 1e-15);
    if (m < 1e-3) continue;
    const std::int64_t here = classified_nodes(a2, a3, n);
    for (const double s : {-0.5, 0.5}) CHECK(classified_nodes(a2, a3 + s * m, n) == here);
  }
  CHECK_THROWS_AS(map_margin(1.0, std::nan(""), Ratio(2)), InvalidInput);
  CHECK_THROWS_AS(map_margin(0.0, 1.0, Ratio(2)), InvalidInput);
}
