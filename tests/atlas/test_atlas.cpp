// atlas.hpp, atlas_csv.hpp, atlas_svg.hpp (Eigen only): the map agrees with the report's
// criteria written out here from the paper (Eq. 24; Eqs. 43/46 with a_p from Sec. 5), the class
// changes exactly across a3 = a_p, results do not depend on the thread count, shards partition
// the rows and merge back byte for byte, and the SVG carries the boundary curves and a legend.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/atlas/atlas_csv.hpp"
#include "sphtroch/atlas/atlas_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Report Sec. 5, n = 2: a_p = atan(sin a2 / (cos a2 + 2)); cos a2 + 2 > 0, so atan is enough.
double report_ap_n2(double a2) { return std::atan(std::sin(a2) / (std::cos(a2) + 2.0)); }

/// Eq. 24 (n = 1): one node when a2/2 < a3 < pi - a2/2 holds strictly.
unsigned report_nodes_n1(double a2, double a3) { return (a2 / 2 < a3 && a3 < kPi - a2 / 2) ? 1u : 0u; }

/// Eqs. 43 and 46 (n = 2): two nodes for each that holds strictly (Eq. 39b, Eq. 44b).
unsigned report_nodes_n2(double a2, double a3) {
  const double ap = report_ap_n2(a2);
  return (ap < a3 && a3 < kPi - a2 ? 2u : 0u) + (a2 < a3 && a3 < kPi - ap ? 2u : 0u);
}

/// Distance in a3 to the nearest line where the report's class can change.
double distance_n1(double a2, double a3) {
  return std::min(std::abs(a3 - a2 / 2), std::abs(a3 - (kPi - a2 / 2)));
}
double distance_n2(double a2, double a3) {
  const double ap = report_ap_n2(a2);
  return std::min({std::abs(a3 - ap), std::abs(a3 - (kPi - ap)), std::abs(a3 - a2), std::abs(a3 - (kPi - a2))});
}

std::string csv_of(const AtlasSpec& spec, const std::vector<AtlasCell>& cells,
                   const std::optional<AtlasShard>& shard = std::nullopt) {
  std::ostringstream out;
  write_atlas_csv(out, spec, shard, cells);
  return out.str();
}

std::size_t count_of(const std::string& hay, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = hay.find(needle); at != std::string::npos; at = hay.find(needle, at + needle.size())) ++n;
  return n;
}

AtlasSpec spec_of(Ratio n, std::size_t grid) {
  AtlasSpec s;
  s.ratio = n;
  s.grid = grid;
  return s;
}

}  // namespace

TEST_CASE("off the boundaries every cell follows Eq. 24 (n = 1)", "[atlas][criteria]") {
  for (std::size_t grid : {24u, 25u}) {
    const AtlasSpec spec = spec_of(Ratio(1), grid);
    const std::vector<AtlasCell> cells = compute_atlas(spec, {0, grid}, 2);
    REQUIRE(cells.size() == grid * grid);
    std::size_t off = 0;
    for (const AtlasCell& c : cells) {
      INFO("a2 = " << c.a2 << ", a3 = " << c.a3);
      REQUIRE(c.analytic_nodes.has_value());
      CHECK(c.agree == std::optional<bool>(true));  // none anywhere on this grid
      if (distance_n1(c.a2, c.a3) <= 1e-3) continue;
      ++off;
      CHECK(c.nodes == report_nodes_n1(c.a2, c.a3));
      CHECK(c.crossings == c.nodes);  // a transversal double point (Eq. 25)
      CHECK(c.cusps == 0);
    }
    CHECK(off >= grid * grid * 9 / 10);  // the check is not vacuous
  }
}

TEST_CASE("off the boundaries every cell follows Eqs. 43 and 46 (n = 2)", "[atlas][criteria]") {
  for (std::size_t grid : {24u, 25u}) {
    const AtlasSpec spec = spec_of(Ratio(2), grid);
    const std::vector<AtlasCell> cells = compute_atlas(spec, {0, grid}, 2);
    std::size_t off = 0, four = 0;
    for (const AtlasCell& c : cells) {
      INFO("a2 = " << c.a2 << ", a3 = " << c.a3);
      CHECK(c.agree == std::optional<bool>(true));
      if (distance_n2(c.a2, c.a3) <= 1e-3) continue;
      ++off;
      CHECK(c.nodes == report_nodes_n2(c.a2, c.a3));
      CHECK(c.crossings == c.nodes);
      CHECK(c.cusps == 0);
      four += c.nodes == 4;
    }
    CHECK(off >= grid * grid * 8 / 10);
    CHECK(four > 0);  // Table 1 row (f): both criteria at once occur on the grid
  }
}

TEST_CASE("diagonal cells lie on a3 = a2: a tangency at the north pole (Table 1 row d)", "[atlas][criteria]") {
  // Equal ranges: cell (i, i) has a3 = a2 exactly; for n = 2 Eq. 46 holds with equality at its
  // lower end (one touching node at the pole), and Eq. 43 adds two crossings where it holds.
  const std::size_t grid = 20;
  const AtlasSpec spec = spec_of(Ratio(2), grid);
  const std::vector<AtlasCell> cells = compute_atlas(spec, {0, grid}, 1);
  for (std::size_t i = 0; i < grid; ++i) {
    const AtlasCell& c = cells[i * grid + i];
    INFO("a2 = a3 = " << c.a2);
    REQUIRE(c.a2 == c.a3);
    const double ap = report_ap_n2(c.a2);
    const bool eq43 = ap < c.a3 && c.a3 < kPi - c.a2;
    CHECK(c.tangencies == 1);
    CHECK(c.crossings == (eq43 ? 2u : 0u));
    CHECK(c.agree == std::optional<bool>(true));
  }
}

TEST_CASE("the class changes across a3 = a_p between the straddling cells and nowhere else", "[atlas][boundary]") {
  // n = 2, a2 near 2: a_p(2) = 0.5208; pi - a2 = 1.14, so for a3 in [0.3, 0.8] Eq. 43 decides
  // alone (Eq. 46 needs a3 > a2): simple curve below a_p, two nodes above.
  AtlasSpec spec = spec_of(Ratio(2), 40);
  spec.a2 = AngleRange{1.9, 2.1};
  spec.a3 = AngleRange{0.3, 0.8};
  const std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);
  for (std::size_t i = 0; i < spec.grid; ++i) {
    const double ap = report_ap_n2(spec.a2_at(i));
    std::vector<std::size_t> changes;
    for (std::size_t j = 0; j + 1 < spec.grid; ++j)
      if (cells[i * spec.grid + j].numeric_class() != cells[i * spec.grid + j + 1].numeric_class()) changes.push_back(j);
    INFO("a2 = " << spec.a2_at(i) << ", a_p = " << ap);
    REQUIRE(changes.size() == 1);
    const std::size_t j = changes.front();
    CHECK(spec.a3_at(j) < ap);
    CHECK(spec.a3_at(j + 1) > ap);
    CHECK(cells[i * spec.grid + j].numeric_class() == AtlasClass::simple_curve);
    CHECK(cells[i * spec.grid + j + 1].nodes == 2);
  }
  // n = 1 across a3 = a2/2 (Eq. 24): simple curve below, one node above.
  AtlasSpec one = spec_of(Ratio(1), 30);
  one.a2 = AngleRange{1.0, 1.2};
  one.a3 = AngleRange{0.3, 0.8};
  const std::vector<AtlasCell> c1 = compute_atlas(one, {0, one.grid}, 2);
  for (std::size_t i = 0; i < one.grid; ++i) {
    const double half = one.a2_at(i) / 2;
    for (std::size_t j = 0; j < one.grid; ++j) CHECK(c1[i * one.grid + j].nodes == (one.a3_at(j) > half ? 1u : 0u));
  }
}

TEST_CASE("literal reading: disagreements only where a2 + a3 rounds to pi, none off the boundaries",
          "[atlas][criteria][literal]") {
  // Cell (i, G-1-i) has a2 + a3 = pi up to rounding: in double the report's margin is 0
  // (equality: a pole tangency), while the long-double census sees the pole just missed.
  AtlasSpec spec = spec_of(Ratio(2), 64);
  spec.reading.literal = true;
  const std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);
  const AtlasSummary s = summarize_atlas(cells, spec.ratio);
  CHECK(s.disagreements_off_boundaries == 0);
  CHECK_FALSE(s.disagreements.empty());  // the literal reading does differ on this grid
  for (std::size_t k : s.disagreements) {
    const AtlasCell& c = cells[k];
    INFO("i = " << c.i << ", j = " << c.j);
    CHECK(c.i + c.j == spec.grid - 1);
    CHECK(std::abs(c.a2 + c.a3 - kPi) < 1e-15);
    CHECK(nearest_boundary(c.a2, c.a3, spec.ratio).kind == BoundaryKind::pi_minus_a2);
  }
  // Everything off the anti-diagonal agrees, as in the default reading.
  for (const AtlasCell& c : cells)
    if (c.i + c.j != spec.grid - 1) CHECK(c.agree == std::optional<bool>(true));
}

TEST_CASE("a cell centred on the pitch cone has the report's two cusps (Fig. 5b)", "[atlas][cusp]") {
  // grid 1: the only cell is the centre of the ranges; a3 centred on a_p(a2 = 1.5) up to rounding.
  AtlasSpec spec = spec_of(Ratio(2), 1);
  spec.a2 = AngleRange{1.0, 2.0};
  const double ap = report_ap_n2(1.5);
  spec.a3 = AngleRange{ap - 0.25, ap + 0.25};
  const AtlasCell c = atlas_cell(spec, 0, 0);
  CHECK(std::abs(c.a3 - ap) < 1e-15);
  CHECK(c.cusps == 2);
  CHECK(c.nodes == 0);
  CHECK(c.numeric_class() == AtlasClass::cusps);
  CHECK(c.analytic_cusps == 2);
  CHECK(c.agree == std::optional<bool>(true));
}

TEST_CASE("other ratios: no node criterion, agree is NA, cusps still compared", "[atlas][criteria]") {
  const AtlasSpec spec = spec_of(Ratio(5, 2), 6);
  const std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);
  for (const AtlasCell& c : cells) {
    CHECK_FALSE(c.analytic_nodes.has_value());
    CHECK_FALSE(c.agree.has_value());
    CHECK(c.cusps_agree);
  }
  const std::string csv = csv_of(spec, cells);
  CHECK(csv.find("# sphtroch atlas n=5/2 grid=6 ") == 0);
  CHECK(count_of(csv, ",NA,") == spec.cells());  // analytic_nodes
  CHECK(count_of(csv, ",NA\n") == spec.cells());  // agree
}

TEST_CASE("results do not depend on the thread count", "[atlas][threads]") {
  const AtlasSpec spec = spec_of(Ratio(2), 23);  // 529 cells: chunks of 64 end mid-row
  const std::string one = csv_of(spec, compute_atlas(spec, {0, spec.grid}, 1));
  CHECK(one == csv_of(spec, compute_atlas(spec, {0, spec.grid}, 2)));
  CHECK(one == csv_of(spec, compute_atlas(spec, {0, spec.grid}, 7)));
  std::size_t calls = 0, last = 0;
  const auto with_progress =
      compute_atlas(spec, {0, spec.grid}, 2, [&](std::size_t done, std::size_t total) {
        ++calls;
        CHECK(total == spec.cells());
        CHECK(done >= last);
        last = done;
      });
  CHECK(one == csv_of(spec, with_progress));
  CHECK(calls >= 1);
  CHECK(last == spec.cells());
}

TEST_CASE("shards partition the rows into contiguous, non-empty slices", "[atlas][shard]") {
  for (std::size_t grid : {1u, 2u, 7u, 128u, 4096u})
    for (std::size_t k : {1u, 2u, 3u, 7u, 128u}) {
      if (k > grid) continue;
      std::size_t next = 0;
      for (std::size_t i = 1; i <= k; ++i) {
        const AtlasRows r = shard_rows(grid, AtlasShard{i, k});
        CHECK(r.begin == next);
        CHECK(r.end > r.begin);
        next = r.end;
      }
      CHECK(next == grid);
    }
  CHECK(test::expect_invalid([] { shard_rows(8, AtlasShard{0, 3}); }).field() == "shard");
  CHECK(test::expect_invalid([] { shard_rows(8, AtlasShard{4, 3}); }).field() == "shard");
  CHECK(test::expect_invalid([] { shard_rows(8, AtlasShard{9, 9}); }).field() == "shard");
}

TEST_CASE("slices merge (any order) into the unsharded file, byte for byte", "[atlas][shard][csv]") {
  AtlasSpec spec = spec_of(Ratio(2), 10);
  spec.a2 = AngleRange{kPi / 6, 5 * kPi / 6};
  const std::string whole = csv_of(spec, compute_atlas(spec, {0, spec.grid}, 2));
  std::vector<AtlasCsv> parts;
  for (std::size_t i = 1; i <= 3; ++i) {
    const AtlasShard shard{i, 3};
    const std::string text = csv_of(spec, compute_atlas(spec, shard_rows(spec.grid, shard), 1), shard);
    CHECK(text.find(" shard=" + std::to_string(i) + "/3 rows=") != std::string::npos);
    parts.push_back(read_atlas_csv(text, "slice" + std::to_string(i)));
  }
  std::mt19937 rng(7);
  for (int round = 0; round < 4; ++round) {
    std::shuffle(parts.begin(), parts.end(), rng);
    const AtlasCsv merged = merge_atlas_slices(parts);
    CHECK(csv_of(merged.spec, merged.cells) == whole);
  }
  // The unsharded file reads back and re-prints identically.
  const AtlasCsv back = read_atlas_csv(whole, "whole");
  CHECK(csv_of(back.spec, back.cells) == whole);

  SECTION("a missing shard is refused") {
    std::sort(parts.begin(), parts.end(), [](const AtlasCsv& a, const AtlasCsv& b) { return a.shard->index < b.shard->index; });
    const auto e = test::expect_invalid([&] { merge_atlas_slices({parts[0], parts[2]}); });
    CHECK(std::string(e.what()).find("shard 2/3 missing") != std::string::npos);
  }
  SECTION("a repeated shard is refused") {
    const auto e = test::expect_invalid([&] { merge_atlas_slices({parts[0], parts[1], parts[2], parts[1]}); });
    CHECK(std::string(e.what()).find("given twice") != std::string::npos);
  }
  SECTION("a slice of another atlas is refused") {
    AtlasSpec other = spec;
    other.grid = 9;
    const AtlasShard shard{2, 3};
    const AtlasCsv alien = read_atlas_csv(csv_of(other, compute_atlas(other, shard_rows(9, shard), 1), shard), "alien");
    std::vector<AtlasCsv> mixed = parts;
    for (auto& p : mixed)
      if (p.shard->index == 2) p = alien;
    const auto e = test::expect_invalid([&] { merge_atlas_slices(mixed); });
    CHECK(e.value() == "alien");
    CHECK(std::string(e.what()).find("another atlas") != std::string::npos);
  }
  SECTION("a tampered or truncated file is refused") {
    std::string flipped = whole;
    flipped.replace(flipped.rfind(",1\n"), 3, ",0\n");  // agree no longer matches the counts
    CHECK_THROWS_AS(read_atlas_csv(flipped, "flipped"), InvalidInput);
    std::string moved = whole;
    const std::size_t row = moved.find('\n', moved.find('\n') + 1) + 1;  // first data row
    moved.insert(row + 4, "9");                                          // its a2 is no cell centre
    CHECK_THROWS_AS(read_atlas_csv(moved, "moved"), InvalidInput);
    CHECK_THROWS_AS(read_atlas_csv(whole.substr(0, whole.size() - 1), "truncated"), InvalidInput);
    CHECK_THROWS_AS(read_atlas_csv(whole.substr(0, whole.rfind('\n', whole.size() - 2) + 1), "short"), InvalidInput);
    CHECK_THROWS_AS(read_atlas_csv("a,b\n", "junk"), InvalidInput);
  }
}

TEST_CASE("spec validation names the field", "[atlas][errors]") {
  AtlasSpec s = spec_of(Ratio(2), 0);
  CHECK(test::expect_invalid([&] { s.validate(); }).field() == "grid");
  s.grid = kAtlasMaxGrid + 1;
  CHECK(test::expect_invalid([&] { s.validate(); }).field() == "grid");
  s.grid = 8;
  s.a2 = AngleRange{2.0, 1.0};
  CHECK(test::expect_invalid([&] { s.validate(); }).field() == "a2");
  s.a2 = AngleRange{};
  s.a3 = AngleRange{0.0, 4.0};
  CHECK(test::expect_invalid([&] { s.validate(); }).field() == "a3");
  s.a3 = AngleRange{};
  CHECK(test::expect_invalid([&] { compute_atlas(s, {0, 8}, 0); }).field() == "threads");
}

TEST_CASE("nearest boundary: the report's lines, by distance in a3", "[atlas][boundary]") {
  const double a2 = 2.0, ap = report_ap_n2(a2);
  const NearestBoundary b = nearest_boundary(a2, ap + 1e-4, Ratio(2));
  CHECK(b.kind == BoundaryKind::pitch_cone);
  CHECK(b.distance == Approx(1e-4).epsilon(1e-9));
  CHECK(nearest_boundary(a2, kPi - a2 - 2e-3, Ratio(2)).kind == BoundaryKind::pi_minus_a2);
  // n = 1: the poles are no class boundary (a single branch through a pole is no node).
  CHECK(nearest_boundary(1.0, 1.0 + 1e-6, Ratio(1)).kind == BoundaryKind::pitch_cone);
}

TEST_CASE("SVG map: well formed, boundary curves, legend, disagreements outlined", "[atlas][svg]") {
  for (int n : {1, 2, 3}) {
    const AtlasSpec spec = spec_of(Ratio(n), 16);
    std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);
    const std::string svg = render_atlas_svg(spec, cells);
    INFO("n = " << n);
    CHECK(svg.rfind("<?xml", 0) == 0);
    CHECK(svg.size() >= 7);
    CHECK(svg.substr(svg.size() - 7) == "</svg>\n");
    CHECK(count_of(svg, "<g") == count_of(svg, "</g>"));
    // n = 3 also has its two self-tangency loci (a3 = atan(3 sqrt 3) and its mirror at a2 = pi/2,
    // issue 13); n = 1, 2 have none (the report's criteria are complete there).
    const std::size_t tangency_loci = n == 3 ? 2 : 0;
    const std::size_t boundaries = (n == 1 ? 2 : 4) + tangency_loci;
    CHECK(count_of(svg, "class=\"boundary\"") == boundaries);
    CHECK(count_of(svg, "data-kind=\"tangency\"") == tangency_loci);
    CHECK(count_of(svg, "data-kind=\"pitch_cone\"") == 1);
    CHECK(count_of(svg, "data-kind=\"mirror_pitch_cone\"") == 1);
    CHECK(count_of(svg, "data-kind=\"a2\"") == (n == 1 ? 0u : 1u));
    CHECK(count_of(svg, "class=\"legend\"") == 1);
    CHECK(count_of(svg, "census ≠ report: 0 cells (0 off the boundaries)") == 1);
    if (n == 1) CHECK(count_of(svg, ": Eq. 24, ") == 2);  // both ends of Eq. 24 in the legend
    if (n == 2) {
      CHECK(count_of(svg, ": Eq. 43, ") == 2);  // lower end a_p, upper end pi - a2
      CHECK(count_of(svg, ": Eq. 46, ") == 2);  // lower end a2, upper end pi - a_p
      CHECK(count_of(svg, ">4 nodes (") == 1);
      CHECK(count_of(svg, ">2 nodes (") == 1);
    }
    CHECK(count_of(svg, ">simple curve (") == 1);
    // Equal cells merge: far fewer rects than cells.
    CHECK(count_of(svg, "<rect") < spec.cells() / 2);
    // A disagreement is outlined and counted.
    cells[5].agree = false;
    const std::string marked = render_atlas_svg(spec, cells);
    CHECK(count_of(marked, "census ≠ report: 1 cells (1 off the boundaries)") == 1);
    const std::size_t at = marked.find("class=\"disagreements\"");
    REQUIRE(at != std::string::npos);
    CHECK(count_of(marked.substr(at, marked.find("</g>", at) - at), "<rect") == 1);
  }
  // An external validator, when present.
  if (std::system("command -v xmllint >/dev/null 2>&1") == 0) {
    const AtlasSpec spec = spec_of(Ratio(2), 12);
    const std::string path = "test_atlas_xmllint.svg";
    std::ofstream(path) << render_atlas_svg(spec, compute_atlas(spec, {0, spec.grid}, 1));
    CHECK(std::system(("xmllint --noout " + path).c_str()) == 0);
    std::remove(path.c_str());
  } else {
    WARN("xmllint not found (Debian package libxml2-utils): external XML validation skipped");
  }
}

TEST_CASE("node shades: distinct counts get distinct blues, darker for more, > 8 counts share the last",
          "[atlas][svg]") {
  auto cells_with = [](std::initializer_list<std::uint32_t> counts) {
    std::vector<AtlasCell> cells;
    for (std::uint32_t n : counts) {
      AtlasCell c;
      c.a2 = 0.3;  // off the pole boundaries a3 = a2, pi - a2
      c.a3 = 1.0;
      c.nodes = c.crossings = n;
      cells.push_back(c);
    }
    return cells;
  };
  const AtlasNodeShades few(cells_with({4, 2, 0, 2, 1, 3}), Ratio(2));
  REQUIRE(few.entries().size() == 4);  // 1, 2, 3, 4 (0 is the simple curve)
  for (std::size_t k = 0; k + 1 < few.entries().size(); ++k) {
    CHECK(few.entries()[k].nodes < few.entries()[k + 1].nodes);
    CHECK(std::string(few.entries()[k].colour) > std::string(few.entries()[k + 1].colour));  // hex: darker = smaller
  }
  CHECK(few.entries()[1].cells == 2);
  AtlasCell simple;
  CHECK(std::string(few.colour(simple)) == atlas_class_colour(AtlasClass::simple_curve));
  const AtlasNodeShades many(cells_with({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}), Ratio(2));
  REQUIRE(many.entries().size() == 8);
  CHECK(many.entries().back().nodes == 8);
  CHECK(many.entries().back().and_more);
  CHECK(many.entries().back().cells == 3);
}
