// `sphtroch clinostat design` and `clinostat merge`, run as the real executable. Expected values
// from the test's own reading of the request: the grid's pairs (counted here with integer
// hundredths), n = outer / inner in lowest terms, the smallest tooth pair in the range (searched
// here over every pair of counts); invariants of the ranking (sorted by the stated keys) and of the
// Pareto front (brute-force dominance over the rows); each row's time to epsilon against the
// single-machine command; the merge of K parts byte for byte the unsharded run; edited, missing and
// foreign parts refused (exit 2, one line, no file); bad input refused naming the option.
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <numeric>
#include <set>
#include <string>

namespace {

using namespace sphtroch::test;
using nlohmann::json;

std::string hundredths(long v) {  // 125 -> "1.25", 100 -> "1", 50 -> "0.5"
  std::string s = std::to_string(v / 100);
  long f = v % 100;
  if (f == 0) return s;
  return s + (f % 10 == 0 ? "." + std::to_string(f / 10) : (f < 10 ? ".0" : ".") + std::to_string(f));
}

std::string ratio_text(long p, long q) {  // outer / inner, both in hundredths
  const long g = std::gcd(p, q);
  p /= g, q /= g;
  return q == 1 ? std::to_string(p) : std::to_string(p) + "/" + std::to_string(q);
}

}  // namespace

TEST_CASE("clinostat design: every pair of the grid once, n exact, ranked by the stated keys", "[cli][clinostat]") {
  TempDir dir;
  const Result r = run("clinostat design --outer 0:2 --inner 0.5:2 --step 0.25 --window 1800 --epsilon 0.02 --coverage 300 --nside 2 --json", dir);
  REQUIRE(r.status == 0);
  const json d = json::parse(r.out);
  std::set<std::pair<std::string, std::string>> expected;
  for (long o = 0; o <= 200; o += 25)
    for (long i = 50; i <= 200; i += 25) expected.insert({hundredths(o), hundredths(i)});
  std::set<std::pair<std::string, std::string>> seen;
  for (const json& row : d["rows"]) seen.insert({row["outer"].get<std::string>(), row["inner"].get<std::string>()});
  CHECK(seen == expected);
  CHECK(d["rows"].size() == expected.size());
  CHECK(d["pairs"] == expected.size());
  std::size_t reach = 0, never = 0;
  for (std::size_t k = 0; k < d["rows"].size(); ++k) {
    const json& row = d["rows"][k];
    CHECK(row["rank"] == k + 1);
    const long o = std::lround(std::stod(row["outer"].get<std::string>()) * 100), i = std::lround(std::stod(row["inner"].get<std::string>()) * 100);
    CHECK(row["n"] == ratio_text(o, i));
    REQUIRE(row["certified"] == true);
    // Perpendicular frames: the mean over a period is 0 unless the speeds resonate (outer = inner);
    // with the outer frame still the inner axis is vertical, and gravity does not move (mean 1).
    if (o != i && o != 0) CHECK(row["mean_over_period"].get<double>() < 1e-12);
    if (o == 0) CHECK(row["mean_over_period"].get<double>() == Approx(1).epsilon(1e-15));
    if (row["stays_below_from_s"].is_null()) {
      ++never;
      CHECK(row["mean_over_period"].get<double>() >= 0.02);
    } else {
      ++reach;
      CHECK(row["first_s"].get<double>() <= row["stays_below_from_s"].get<double>());
      CHECK(never == 0);  // the rows that reach epsilon come first
    }
    if (k > 0 && !row["stays_below_from_s"].is_null()) {
      const json& before = d["rows"][k - 1];
      const double a = before["stays_below_from_s"], b = row["stays_below_from_s"];
      CHECK(a <= b);
      if (a == b) CHECK(before["first_s"].get<double>() <= row["first_s"].get<double>());
    }
  }
  CHECK(d["reach_epsilon"] == reach);
  CHECK(d["never_below"] == never);
  // The Pareto front by brute force: a reaching row no other beats in both (time no longer,
  // coverage no smaller, one strictly).
  std::vector<std::size_t> front;
  for (std::size_t k = 0; k < d["rows"].size(); ++k) {
    const json& a = d["rows"][k];
    if (a["stays_below_from_s"].is_null()) continue;
    bool dominated = false;
    for (const json& b : d["rows"]) {
      if (b["stays_below_from_s"].is_null()) continue;
      const double ta = a["stays_below_from_s"], tb = b["stays_below_from_s"], ca = a["coverage"], cb = b["coverage"];
      dominated = dominated || (tb <= ta && cb >= ca && (tb < ta || cb > ca));
    }
    if (!dominated) front.push_back(k + 1);
  }
  CHECK(d["pareto"].get<std::vector<std::size_t>>() == front);
}

TEST_CASE("clinostat design: a row's times are the single machine's", "[cli][clinostat]") {
  TempDir dir;
  const Result r = run("clinostat design --outer 1:2 --inner 1.5:2.5 --step 0.5 --window 900 --epsilon 0.01 --json", dir);
  REQUIRE(r.status == 0);
  const json d = json::parse(r.out);  // kept: a range over a temporary's member would dangle
  for (const json& row : d["rows"]) {
    const Result one = run("clinostat --outer " + row["outer"].get<std::string>() + " --inner " + row["inner"].get<std::string>() +
                               " --window 900 --epsilon 0.01 --json", dir);
    REQUIRE(one.status == 0);
    const json m = json::parse(one.out);
    CHECK(row["first_s"] == m["time_to_epsilon"]["first_s"]);
    CHECK(row["stays_below_from_s"] == m["time_to_epsilon"]["stays_below_from_s"]);
    CHECK(row["worst_window_mean"]["upper"] == m["worst_window_mean"]["upper"]);
    CHECK(row["period_s"] == m["period_s"]);
  }
}

TEST_CASE("clinostat design --teeth: only ratios two tooth counts in the range give, each with its smallest pair", "[cli][clinostat]") {
  TempDir dir;
  const Result r = run("clinostat design --outer 0.5:3 --inner 0.5:3 --step 0.25 --window 600 --epsilon 0.05 --teeth 12..30 --json", dir);
  REQUIRE(r.status == 0);
  const json d = json::parse(r.out);
  std::size_t expected = 0;
  for (long o = 50; o <= 300; o += 25)
    for (long i = 50; i <= 300; i += 25) {
      const long g = std::gcd(o, i), p = o / g, q = i / g;
      long best = 0;  // the smallest multiple k with both k p, k q in [12, 30]
      for (long k = 1; k * std::max(p, q) <= 30 && !best; ++k)
        if (k * std::min(p, q) >= 12) best = k;
      if (!best) continue;
      ++expected;
      bool found = false;
      for (const json& row : d["rows"])
        if (row["outer"] == hundredths(o) && row["inner"] == hundredths(i)) {
          found = true;
          CHECK(row["teeth"] == std::to_string(best * p) + ":" + std::to_string(best * q));
        }
      CHECK(found);
    }
  CHECK(d["rows"].size() == expected);
}

TEST_CASE("clinostat merge: K parts join into the unsharded run's bytes, and edited, missing and foreign parts are refused", "[cli][clinostat]") {
  TempDir dir;
  const std::string request = "clinostat design --outer 0.5:2 --inner 0.5:2 --step 0.5 --window 600 --epsilon 0.02 --json";
  const Result whole = run(request, dir, true);
  REQUIRE(whole.status == 0);
  for (int k = 1; k <= 3; ++k) REQUIRE(run(request + " --shard " + std::to_string(k) + "/3 -o part" + std::to_string(k) + ".json", dir, true).status == 0);
  const Result merged = run("clinostat merge --json part2.json part3.json part1.json", dir, true);
  REQUIRE(merged.status == 0);
  CHECK(merged.out == whole.out);
  const Result text = run("clinostat merge part1.json part2.json part3.json", dir, true);
  CHECK(text.status == 0);
  CHECK(contains(text.out, "16 speed pairs"));

  const Result missing = run("clinostat merge part1.json part3.json -o joined.json", dir, true);
  CHECK(missing.status == 2);
  CHECK(contains(missing.err, "2/3"));
  std::string edited = slurp(dir.path / "part2.json");
  const auto at = edited.find("\"first_s\": ");
  REQUIRE(at != std::string::npos);
  edited.insert(at + 11, "1");
  std::ofstream(dir.path / "edited.json") << edited;
  const Result bad = run("clinostat merge part1.json edited.json part3.json -o joined.json", dir, true);
  CHECK(bad.status == 2);
  CHECK(contains(bad.err, "edited.json"));
  REQUIRE(run("clinostat design --outer 0.5:2 --inner 0.5:2 --step 0.5 --window 600 --epsilon 0.03 --json --shard 2/3 -o other.json", dir, true).status == 0);
  const Result foreign = run("clinostat merge part1.json other.json part3.json -o joined.json", dir, true);
  CHECK(foreign.status == 2);
  CHECK(contains(foreign.err, "other.json"));
  std::ofstream(dir.path / "deep.json") << std::string(100000, '[') << std::string(100000, ']');  // nesting that would recurse
  const Result deep = run("clinostat merge part1.json deep.json part3.json -o joined.json", dir, true);
  CHECK(deep.status == 2);
  CHECK(contains(deep.err, "deep.json"));
  for (const Result& r : {missing, bad, foreign, deep}) {
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
  }
  CHECK_FALSE(fs::exists(dir.path / "joined.json"));
}

TEST_CASE("clinostat design: bad input is refused with one line naming the option, nothing on stdout", "[cli][clinostat]") {
  {
    TempDir options_dir;  // an option of clinostat itself, given before design, would be lost: refused
    const Result before = run("clinostat --tilt 75 design --outer 1:2 --inner 1:2 --step 0.5 --window 60 --epsilon 0.1", options_dir, true);
    CHECK(before.status == 2);
    CHECK(before.out.empty());
    CHECK(contains(before.err, "--tilt"));
  }
  TempDir dir;
  const std::string base = "--window 600 --epsilon 0.01";
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"--outer 1:2 --inner 1:2 --step 0 " + base, "--step"}, {"--outer 2:1 --inner 1:2 --step 0.5 " + base, "--outer"},
           {"--outer 1 --inner 1:2 --step 0.5 " + base, "--outer"}, {"--outer 1:2 --inner 1:nan --step 0.5 " + base, "--inner"},
           {"--outer 0:1000 --inner 0:1000 --step 0.001 " + base, "--outer"}, {"--outer 1:2 --inner 1:2 --step 0.5 --window 0 --epsilon 0.01", "--window"},
           {"--outer 1:2 --inner 1:2 --step 0.5 --window 600 --epsilon -1", "--epsilon"},
           {"--outer 1:2 --inner 1:2 --step 0.5 --coverage 60 --nside 3 " + base, "--nside"},
           {"--outer 1:2 --inner 1:2 --step 0.5 --teeth 5..2 " + base, "--teeth"}, {"--outer 1:2 --inner 1:2 --step 0.5 --json --shard 9/4 " + base, "--shard"},
           {"--outer 1:2 --inner 1:2 --step 0.5 --shard 1/2 " + base, "--shard"}, {"--outer 1:2 --inner 1:2 --step 0.5", "--window"},
           {"--outer 1:2 --inner 1:2 --step 0.5 --tilt 181 " + base, "--tilt"}, {"--outer 1:2 --inner 1:2 --step 0.5 --frame-angle -1 " + base, "--frame-angle"},
           {"--outer 1:2 --inner 1:2 --step 0.5 --window 600 --epsilon 1e10", "--epsilon"},
           {"--outer 1:2 --inner 1:2 --step 0.5 --coverage 60 --nside 128 " + base, "--nside"},
           {"--outer 0:0 --inner 0:0 --step 1 " + base, "--outer"}, {"--outer 1:317 --inner 1:316 --step 1 " + base, "--step"}}) {
    const Result r = run("clinostat design " + args, dir, true);
    INFO(args << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, option));
    CHECK(dir.entries().empty());
  }
}

TEST_CASE("clinostat design: the recommendation is the fastest reaching pair with its lead and the grid edges it sits at", "[cli][clinostat]") {
  TempDir dir;
  const Result r = run("clinostat design --outer 0.5:2 --inner 0.5:2 --step 0.5 --window 1800 --epsilon 0.02 --coverage 300 --nside 2 --json", dir);
  REQUIRE(r.status == 0);
  const json d = json::parse(r.out);
  const json& rec = d["recommendation"];
  REQUIRE(rec.is_object());
  // The pick, found here from the rows alone: the smallest stays_below_from_s (ties: first_s,
  // then coverage larger, then outer, inner), and the runner-up the next reaching row.
  std::vector<const json*> reaching;
  for (const json& row : d["rows"])
    if (!row["stays_below_from_s"].is_null()) reaching.push_back(&row);
  REQUIRE(reaching.size() >= 2);
  const auto before = [](const json* a, const json* b) {
    const double ta = (*a)["stays_below_from_s"], tb = (*b)["stays_below_from_s"];
    if (ta != tb) return ta < tb;
    const double fa = (*a)["first_s"], fb = (*b)["first_s"];
    if (fa != fb) return fa < fb;
    const double ca = (*a)["coverage"], cb = (*b)["coverage"];
    if (ca != cb) return ca > cb;
    return std::stod((*a)["outer"].get<std::string>()) * 1000 + std::stod((*a)["inner"].get<std::string>()) <
           std::stod((*b)["outer"].get<std::string>()) * 1000 + std::stod((*b)["inner"].get<std::string>());
  };
  std::vector<const json*> sorted = reaching;
  std::stable_sort(sorted.begin(), sorted.end(), before);
  CHECK(rec["outer"] == (*sorted[0])["outer"]);
  CHECK(rec["inner"] == (*sorted[0])["inner"]);
  CHECK(rec["stays_below_from_s"] == (*sorted[0])["stays_below_from_s"]);
  CHECK(rec["lead_s"].get<double>() ==
        (*sorted[1])["stays_below_from_s"].get<double>() - (*sorted[0])["stays_below_from_s"].get<double>());
  // The edges: a speed equal to 0.5 or 2 of its range is at the lower or upper end.
  std::set<std::string> edges, expected_edges;
  for (const json& e : rec["at_edge"]) edges.insert(e["speed"].get<std::string>() + " " + e["end"].get<std::string>() + " " + e["rpm"].get<std::string>());
  for (const char* speed : {"outer", "inner"}) {
    const std::string v = rec[speed];
    if (v == "0.5") expected_edges.insert(std::string(speed) + " lower 0.5");
    if (v == "2") expected_edges.insert(std::string(speed) + " upper 2");
  }
  CHECK(edges == expected_edges);
  // The text says the same pick in words.
  const Result text = run("clinostat design --outer 0.5:2 --inner 0.5:2 --step 0.5 --window 1800 --epsilon 0.02 --coverage 300 --nside 2", dir);
  REQUIRE(text.status == 0);
  CHECK_THAT(text.out, Catch::Contains("recommendation: rank 1, outer " + rec["outer"].get<std::string>() + " rpm, inner " +
                                       rec["inner"].get<std::string>() + " rpm"));
  if (!expected_edges.empty()) CHECK_THAT(text.out, Catch::Contains("at the grid's edge: "));
}

TEST_CASE("clinostat design: no pair reaching epsilon gives no recommendation and says why", "[cli][clinostat]") {
  TempDir dir;
  // Outer speeds 0 only: the inner axis is vertical and gravity does not move (mean 1 g0 > epsilon).
  const Result r = run("clinostat design --outer 0:0 --inner 1:2 --step 1 --window 600 --epsilon 0.01 --json", dir);
  REQUIRE(r.status == 0);
  CHECK(json::parse(r.out)["recommendation"].is_null());
  const Result text = run("clinostat design --outer 0:0 --inner 1:2 --step 1 --window 600 --epsilon 0.01", dir);
  CHECK_THAT(text.out, Catch::Contains("recommendation: none: no pair of the grid reaches epsilon 0.01 g0"));
}

TEST_CASE("clinostat design --offset: each row is the single machine's with the same offset", "[cli][clinostat]") {
  TempDir dir;
  const std::string grid = "clinostat design --outer 1:2 --inner 1.5:2 --step 0.5 --window 900 --epsilon 0.01 --json";
  const Result off = run(grid + " --offset 0.1,0,0", dir), centre = run(grid, dir);
  REQUIRE(off.status == 0);
  REQUIRE(centre.status == 0);
  const json d = json::parse(off.out), c = json::parse(centre.out);
  CHECK(d["request"]["offset_m"] == json::array({0.1, 0.0, 0.0}));
  CHECK(c["request"]["offset_m"].is_null());
  bool any_differs = false;
  for (const json& row : d["rows"]) {
    const Result one = run("clinostat --outer " + row["outer"].get<std::string>() + " --inner " + row["inner"].get<std::string>() +
                               " --offset 0.1,0,0 --window 900 --epsilon 0.01 --json", dir);
    REQUIRE(one.status == 0);
    const json m = json::parse(one.out);
    CHECK(row["stays_below_from_s"] == m["time_to_epsilon"]["stays_below_from_s"]);
    CHECK(row["worst_window_mean"]["upper"] == m["worst_window_mean"]["upper"]);
    for (const json& centred : c["rows"])
      if (centred["outer"] == row["outer"] && centred["inner"] == row["inner"])
        any_differs = any_differs || centred["worst_window_mean"]["upper"] != row["worst_window_mean"]["upper"];
  }
  CHECK(any_differs);  // 10 cm off the centre at 1-2 rpm: the frames' accelerations enter M(W)
  const Result bad = run(grid + " --offset 0.1,0", dir);
  CHECK(bad.status == 2);
  CHECK(bad.out.empty());
  CHECK_THAT(bad.err, Catch::StartsWith("sphtroch: --offset = 0.1,0: "));
}
