// Tests of sphtroch/atlas/atlas_summary.hpp: the atlas summary of a summary built by hand here (so
// every count is known), read back line by line against the format documented in the header.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/atlas/atlas_summary.hpp"

#include <sstream>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {


bool has(const std::string& line, const std::string& part) { return line.find(part) != std::string::npos; }

AtlasSummary hand_summary() {
  AtlasSummary s;
  s.cells = 16;
  s.by_class[0] = 1, s.by_class[1] = 7, s.by_class[2] = 3, s.by_class[3] = 5;
  s.by_nodes = {{0, 4}, {3, 12}};
  s.with_tangencies = 2;
  s.predicted = 16;
  s.disagreement_count = 250;  // more than the two listed: the rest are counted
  s.disagreements_off_boundaries = 9;
  return s;
}

AtlasCell disagreeing_cell(std::uint32_t i, std::uint32_t j, double a2, double a3) {
  AtlasCell c;
  c.i = i, c.j = j, c.a2 = a2, c.a3 = a3;
  c.nodes = 2, c.cusps = 0, c.analytic_nodes = 1, c.analytic_cusps = 0, c.agree = false;
  return c;
}

}  // namespace

TEST_CASE("atlas summary: every count of the summary, the listed cells, the rest counted, no time untimed") {
  AtlasSpec spec;
  spec.ratio = Ratio(2);
  spec.grid = 4;
  const std::vector<AtlasCell> listed = {disagreeing_cell(1, 2, 0.25, 1.5), disagreeing_cell(3, 0, 1.0 / 3.0, 0.125)};
  std::ostringstream out;
  write_atlas_summary(out, spec, hand_summary(), listed, AtlasRun{AtlasRows{0, 4}, std::nullopt, std::nullopt, 1});
  const auto l = sphtroch::test::split_lines(out.str());
  REQUIRE(l.size() == 6 + listed.size() + 1);  // 6 fixed lines, the listed cells, "... and N more"
  CHECK(l[0].rfind("atlas: n = 2, grid 4 x 4", 0) == 0);
  CHECK(has(l[0], "default reading"));
  CHECK(l[1].rfind("cells: 16 (", 0) == 0);
  CHECK(has(l[1], "rows 0 .. 3 of 4"));
  CHECK(has(l[2], "simple curve 1"));
  CHECK(has(l[2], "nodes 7"));
  CHECK(has(l[2], "cusps 3"));
  CHECK(has(l[2], "nodes and cusps 5"));
  CHECK(has(l[3], "0: 4"));
  CHECK(has(l[3], "3: 12"));
  CHECK(has(l[3], "2 with a tangency node"));
  CHECK(has(l[4], "Eqs. 43, 46"));
  CHECK(has(l[4], "predicted for 16 cells"));  // n = 2: the report's node criteria
  CHECK(has(l[5], ": 250 (241 within"));
  CHECK(has(l[5], "9 elsewhere"));
  CHECK(has(l[6], "i=1 j=2 a2=0.25 a3=1.5"));
  CHECK(has(l[7], "i=3 j=0 a2=" + number_text(1.0 / 3.0)));  // round-trip form, all digits
  CHECK(has(l[8], "and 248 more"));
  for (const auto& line : l) CHECK(line.rfind("time:", 0) != 0);
}

TEST_CASE("atlas summary: a shard names itself, a timed run ends with its time, n without node criteria says NA") {
  AtlasSpec spec;
  spec.ratio = Ratio(5, 2);
  spec.grid = 8;
  spec.reading.literal = true;
  AtlasSummary s = hand_summary();
  s.disagreement_count = 0, s.disagreements_off_boundaries = 0;
  std::ostringstream out;
  write_atlas_summary(out, spec, s, {}, AtlasRun{AtlasRows{4, 6}, AtlasShard{3, 4}, 2.0, 4});
  const auto l = sphtroch::test::split_lines(out.str());
  REQUIRE(l.size() == 7);
  CHECK(has(l[0], "n = 5/2"));
  CHECK(has(l[0], "literal reading"));
  CHECK(has(l[1], "shard 3/4"));
  CHECK(has(l[1], "rows 4 .. 5 of 8"));
  CHECK(has(l[4], "no node criterion for n = 5/2"));
  CHECK(l[6].rfind("time: 2.000 s on 4 thread(s), ", 0) == 0);
  CHECK(has(l[6], "500.0000 ms per cell per thread"));  // 2 s x 4 threads / 16 cells
}

TEST_CASE("atlas summary: listed_disagreements keeps the first kMaxListedDisagreements, in order") {
  std::vector<AtlasCell> cells(kMaxListedDisagreements + 50);
  AtlasSummary s;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    cells[k].i = static_cast<std::uint32_t>(k);
    if (k % 2 == 0 || k > 100) s.disagreements.push_back(k);
  }
  const auto listed = listed_disagreements(s, cells);
  REQUIRE(listed.size() == kMaxListedDisagreements);
  for (std::size_t k = 0; k < listed.size(); ++k) CHECK(listed[k].i == s.disagreements[k]);
}
