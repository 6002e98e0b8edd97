// `sphtroch atlas` and `sphtroch atlas-merge`, run as the real executable (SPHTROCH_EXE): the CSV
// does not depend on --threads, shard slices merge (in any order) into a file byte-identical to
// the unsharded run, merge refuses missing / repeated / foreign slices, bad input gets exit
// status 2 with one stderr line naming the option and no file, and --svg writes the map.
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using namespace sphtroch::test;

/// `sphtroch <args>` run inside `dir` (relative paths land there).
Result run_here(const std::string& args, const TempDir& dir) { return run(args, dir, true); }

}  // namespace

TEST_CASE("atlas: CSV layout, and the same bytes with 1 or 2 threads", "[cli][atlas]") {
  TempDir dir;
  const Result one = run_here("atlas --n 2 --grid 12 --threads 1 -o one.csv", dir);
  REQUIRE(one.status == 0);
  CHECK(one.err.empty());  // no progress bar: stderr is not a terminal
  CHECK(contains(one.out, "disagreements (census vs report): 0 (0 within 1e-9 rad of a boundary, 0 elsewhere)\n"));
  const Result two = run_here("atlas --n 2 --grid 12 --threads 2 -o two.csv", dir);
  REQUIRE(two.status == 0);
  const std::string a = slurp(dir.path / "one.csv"), b = slurp(dir.path / "two.csv");
  CHECK(a == b);
  CHECK(a.rfind("# sphtroch atlas n=2 grid=12 a2=0:3.141592653589793 a3=0:3.141592653589793 reading=default\n"
                "i,j,a2,a3,nodes,crossings,tangencies,cusps,analytic_nodes,analytic_cusps,agree\n",
                0) == 0);
  CHECK(count_lines(a) == 2 + 144);
  // Row (i, j) = (0, 1): a2 = pi/24, a3 = 3 pi/24, printed in the shortest round-trip form.
  const std::string expected = "\n0,1," + shortest_g(3.14159265358979323846 / 12 * 0.5) + "," +
                               shortest_g(3.14159265358979323846 / 12 * 1.5) + ",";
  CHECK(contains(a, expected));
  // -o - : the CSV on stdout, the summary on stderr.
  const Result dash = run_here("atlas --n 2 --grid 12 -o -", dir);
  REQUIRE(dash.status == 0);
  CHECK(dash.out == a);
  CHECK(contains(dash.err, "disagreements (census vs report): 0 ("));
}

TEST_CASE("atlas: shards merged in any order equal the unsharded file byte for byte", "[cli][atlas][shard]") {
  TempDir dir;
  REQUIRE(run_here("atlas --n 2 --grid 11 --a2 pi/6:5pi/6 -o whole.csv", dir).status == 0);
  for (int i = 1; i <= 3; ++i) {
    const Result r = run_here("atlas --n 2 --grid 11 --a2 pi/6:5pi/6 --shard " + std::to_string(i) + "/3 -o s" +
                             std::to_string(i) + ".csv",
                         dir);
    REQUIRE(r.status == 0);
    CHECK(contains(r.out, "shard " + std::to_string(i) + "/3"));
  }
  const Result merged = run_here("atlas-merge -o merged.csv --svg merged.svg s2.csv s3.csv s1.csv", dir);
  REQUIRE(merged.status == 0);
  CHECK(slurp(dir.path / "merged.csv") == slurp(dir.path / "whole.csv"));
  CHECK(contains(slurp(dir.path / "merged.svg"), "class=\"boundary\""));
  CHECK(run_here("atlas-merge -o merged2.csv s3.csv s1.csv s2.csv", dir).status == 0);
  CHECK(slurp(dir.path / "merged2.csv") == slurp(dir.path / "whole.csv"));

  REQUIRE(run_here("atlas --n 2 --grid 10 --shard 2/3 -o other.csv", dir).status == 0);
  REQUIRE(run_here("atlas --n 2 --grid 11 --a2 pi/6:5pi/6 --shard 2/4 -o four.csv", dir).status == 0);
  struct Bad {
    const char* args;
    const char* says;
  };
  for (const Bad& bad : {Bad{"s1.csv s3.csv", "shard 2/3 missing"}, Bad{"s1.csv s2.csv s2.csv s3.csv", "given twice"},
                         Bad{"s1.csv other.csv s3.csv", "another atlas"}, Bad{"s1.csv four.csv s3.csv", "shards"},
                         Bad{"s1.csv s2.csv nowhere.csv", "cannot be read"}}) {
    INFO(bad.args);
    const Result r = run_here(std::string("atlas-merge -o out.csv ") + bad.args, dir);
    CHECK(r.status == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, bad.says));
    CHECK(r.out.empty());
    CHECK_FALSE(fs::exists(dir.path / "out.csv"));
  }
}

TEST_CASE("atlas: bad input is one stderr line naming the option, exit 2, no file", "[cli][atlas][errors]") {
  TempDir dir;
  struct Bad {
    const char* args;
    const char* option;
  };
  for (const Bad& bad : {Bad{"--n 2 --grid 0", "--grid = 0"}, Bad{"--n 2 --grid abc", "--grid = abc"},
                         Bad{"--n 2 --grid 4097", "--grid = 4097"}, Bad{"--n 2 --grid 8 --shard 4/3", "--shard = 4/3"},
                         Bad{"--n 2 --grid 8 --shard 0/3", "--shard = 0/3"},
                         Bad{"--n 2 --grid 8 --shard 9/9", "--shard = 9/9"},
                         Bad{"--n 2 --grid 8 --shard x", "--shard = x"}, Bad{"--n 2 --grid 8 --a2 2:1", "--a2 = 2:1"},
                         Bad{"--n 2 --grid 8 --a2 0:4", "--a2 = 0:4"}, Bad{"--n 2 --grid 8 --a3 pi/6", "--a3 = pi/6"},
                         Bad{"--n 2 --grid 8 --a3=-0.1:1", "--a3 = -0.1:1"},
                         Bad{"--n 2 --grid 8 --threads 0", "--threads = 0"}, Bad{"--n 0 --grid 8", "--n = 0"},
                         Bad{"--n x --grid 8", "--n = x"},
                         Bad{"--n 2 --grid 8 --shard 1/2 --svg map.svg", "--svg = map.svg"},
                         Bad{"--n 2 --grid 8 --svg nodir/map.svg", "--svg = nodir/map.svg"}}) {
    INFO(bad.args);
    const Result r = run_here(std::string("atlas ") + bad.args + " -o out.csv", dir);
    CHECK(r.status == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, bad.option));
    CHECK(contains(r.err, "valid"));
    CHECK(r.out.empty());
    CHECK(dir.entries().empty());
  }
}

TEST_CASE("atlas --svg: the map file with the report's boundaries and a legend", "[cli][atlas][svg]") {
  TempDir dir;
  const Result r = run_here("atlas --n 1 --grid 16 --svg map.svg", dir);
  REQUIRE(r.status == 0);
  const std::string svg = slurp(dir.path / "map.svg");
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(contains(svg, "Eq. 24"));
  CHECK(contains(svg, "class=\"legend\""));
  CHECK(contains(r.out, "report's criteria: Eq. 24"));
  CHECK(dir.entries().size() == 1);  // no CSV without -o
}

TEST_CASE("atlas --teeth ZS:ZP: the atlas of n = ZS/ZP, the counts echoed in the summary and the map", "[cli][atlas]") {
  TempDir dir;
  const Result by_teeth = run_here("atlas --teeth 39:15 --grid 6 -o t.csv --svg t.svg", dir);
  const Result by_n = run_here("atlas --n 13/5 --grid 6 -o n.csv", dir);
  REQUIRE(by_teeth.status == 0);
  REQUIRE(by_n.status == 0);
  CHECK(slurp(dir.path / "t.csv") == slurp(dir.path / "n.csv"));  // the curve depends on n = 39/15 = 13/5 only
  CHECK(contains(by_teeth.out, "atlas: n = 13/5 (teeth 39:15), grid 6 x 6"));
  CHECK(contains(by_n.out, "atlas: n = 13/5, grid 6 x 6"));
  CHECK(contains(slurp(dir.path / "t.svg"), "n = 13/5 (teeth 39:15)"));
  for (const std::string args : {"--teeth 39:15 --n 13/5", "--teeth 39:0", "--teeth 39", "--grid 6"}) {
    const Result bad = run_here("atlas " + args + (contains(args, "grid") ? "" : " --grid 6"), dir);
    INFO(args << ": " << bad.err);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(count_lines(bad.err) == 1);
  }
}

TEST_CASE("atlas --degrees: the map's axes in round degrees at the angles they name, the CSV unchanged", "[cli][atlas][svg]") {
  TempDir dir;
  const Result deg = run_here("atlas --n 2 --grid 8 --a2 30deg:150deg -o d.csv --svg d.svg --degrees", dir);
  const Result rad = run_here("atlas --n 2 --grid 8 --a2 30deg:150deg -o r.csv --svg r.svg", dir);
  REQUIRE(deg.status == 0);
  REQUIRE(rad.status == 0);
  CHECK(slurp(dir.path / "d.csv") == slurp(dir.path / "r.csv"));
  const std::string svg = slurp(dir.path / "d.svg");
  CHECK(contains(svg, "α2 (carrier twist), deg"));
  CHECK(contains(svg, "α3 (tracer twist), deg"));
  CHECK_FALSE(contains(svg, "π/"));  // no tick in multiples of pi (the legend names α3 = π − αp)
  // The a2 ticks: 30° .. 150° every 30° (the first round step giving >= 4 ticks), at x = left +
  // (a - lo) / (hi - lo) * map (72 px margin, 512 px map): 30° at 72, 90° at 328, 150° at 584.
  for (const auto& [label, x] : {std::pair{"30°", "72"}, std::pair{"90°", "328"}, std::pair{"150°", "584"}})
    CHECK(contains(svg, std::string("<text x=\"") + x + "\" y=\"579\" text-anchor=\"middle\" " +
                            "style=\"font-family:sans-serif;font-size:12px;fill:#333333\">" + label + "<"));
  const Result alone = run_here("atlas --n 2 --grid 8 --degrees", dir);
  CHECK(alone.status == 2);
  CHECK(contains(alone.err, "--degrees"));
}

TEST_CASE("output files get the mode of a plain open(): 0666 & ~umask, not mkstemp's 0600", "[cli][atlas]") {
  TempDir dir;
  const std::string cmd = "cd '" + dir.path.string() + "' && umask 022 && " + quoted_tool() +
                          " atlas --n 1 --grid 2 -o a.csv >/dev/null 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const fs::perms p = fs::status(dir.path / "a.csv").permissions();
  CHECK((p & fs::perms::group_read) != fs::perms::none);
  CHECK((p & fs::perms::others_read) != fs::perms::none);
  CHECK((p & fs::perms::group_write) == fs::perms::none);
}

TEST_CASE("atlas-merge streams: a slice from a pipe, checks before stdout, truncated slices", "[cli][atlas][merge]") {
  TempDir dir;
  REQUIRE(run_here("atlas --n 3/2 --grid 9 -o whole.csv", dir).status == 0);
  for (int i = 1; i <= 3; ++i)
    REQUIRE(run_here("atlas --n 3/2 --grid 9 --shard " + std::to_string(i) + "/3 -o s" + std::to_string(i) + ".csv", dir)
                .status == 0);
  const std::string whole = slurp(dir.path / "whole.csv");

  // Standard input as a slice (read once, held), the others streamed from their files.
  const Result piped = run_here("atlas-merge -o m.csv s3.csv - s1.csv < s2.csv", dir);
  INFO(piped.err);
  REQUIRE(piped.status == 0);
  CHECK(slurp(dir.path / "m.csv") == whole);
  const Result out = run_here("atlas-merge -o - s1.csv s2.csv s3.csv", dir);
  CHECK(out.status == 0);
  CHECK(out.out == whole);
  CHECK(contains(out.err, "cells: 81 "));

  // A slice cut short (last row without its newline; a row missing) or with a row too many,
  // given last: every check holds before the first byte reaches stdout.
  const std::string s3 = slurp(dir.path / "s3.csv");
  std::ofstream(dir.path / "cut.csv", std::ios::binary) << s3.substr(0, s3.size() - 1);
  const std::string without_last = s3.substr(0, s3.rfind('\n', s3.size() - 2) + 1);
  std::ofstream(dir.path / "short.csv", std::ios::binary) << without_last;
  std::ofstream(dir.path / "long.csv", std::ios::binary) << s3 << s3.substr(without_last.size());
  std::ofstream(dir.path / "wide.csv", std::ios::binary) << s3 << std::string(5000, '1') << "\n";
  struct Bad {
    const char* file;
    const char* says;
  };
  for (const Bad& bad : {Bad{"cut.csv", "no final newline"}, Bad{"short.csv", "26 rows where rows 6:9 of grid 9 need 27"},
                         Bad{"long.csv", "28 rows where"}, Bad{"wide.csv", "longer than 4096 bytes"}}) {
    INFO(bad.file);
    for (const std::string output : {"-", "m2.csv"}) {
      const Result r = run_here("atlas-merge -o " + output + " s1.csv s2.csv " + bad.file, dir);
      CHECK(r.status == 2);
      CHECK(r.out.empty());
      CHECK(count_lines(r.err) == 1);
      CHECK(contains(r.err, bad.says));
      CHECK_FALSE(fs::exists(dir.path / "m2.csv"));
    }
  }
}

TEST_CASE("atlas-merge memory is bounded by a line, not the grid (under a 12 MiB data limit)", "[cli][atlas][merge][memory]") {
  if (tool_has_address_sanitizer()) {
    SUCCEED("not under AddressSanitizer: its shadow memory alone exceeds any data limit (the Release run checks this)");
    return;
  }
  TempDir dir;
  // 512 x 512 = 262,144 cells in 3 slices (15.5 MB of CSV); holding the cells takes 56 bytes each
  // (14.7 MB), more than the limit allows.
  for (int i = 1; i <= 3; ++i)
    REQUIRE(run_here("atlas --n 1 --grid 512 --shard " + std::to_string(i) + "/3 -o s" + std::to_string(i) + ".csv", dir)
                .status == 0);
  const std::string limit = "prlimit --data=" + std::to_string(12 << 20) + " " + quoted_tool() + " ";
  const std::string cd = "cd '" + dir.path.string() + "' && ";
  CHECK(std::system((cd + limit + "atlas-merge -o m.csv s1.csv s2.csv s3.csv > /dev/null 2>&1").c_str()) == 0);
  CHECK(std::system((cd + limit + "atlas-merge -o - s1.csv s2.csv s3.csv 2>/dev/null | tail -n 1 | grep -q '^511,511,'").c_str()) == 0);
  CHECK(fs::file_size(dir.path / "m.csv") > 15000000);
  // Control: --svg keeps every cell for the picture and must fail under the same limit, so the
  // limit is real and this test could fail.
  CHECK(std::system((cd + limit + "atlas-merge -o m2.csv --svg m.svg s1.csv s2.csv s3.csv > /dev/null 2>&1").c_str()) != 0);
  CHECK_FALSE(fs::exists(dir.path / "m2.csv"));
}
