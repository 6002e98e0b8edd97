// `sphtroch boundaries`, run as the real executable (SPHTROCH_EXE): the events at one a2 as JSON
// and text (the counts checked against `sphtroch classify` just off each event), the loci CSV
// (the same bytes with 1 or 2 threads), and bad input (exit 2, one stderr line, nothing on stdout,
// no file).
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace sphtroch::test;
using nlohmann::json;

std::string num(double v) { return shortest_g(v); }

/// Node points `sphtroch classify` counts at (a2, a3).
long classify_nodes(const std::string& n, double a2, double a3, const TempDir& dir) {
  const Result r = run("classify --n " + n + " --a2 " + num(a2) + " --a3 " + num(a3) + " --json", dir);
  REQUIRE(r.status == 0);
  const json j = json::parse(r.out);
  return j["counts"]["crossings"].get<long>() + j["counts"]["tangencies"].get<long>();
}

}  // namespace

TEST_CASE("boundaries --json: n = 3, a2 = pi/2: the tangencies of the issue, counts 3 <-> 9", "[cli][boundaries]") {
  TempDir dir;
  const Result r = run("boundaries --n 3 --a2 pi/2 --json", dir);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const json j = json::parse(r.out);
  CHECK(j["n"] == "3");
  CHECK(j["a2"].get<double>() == 1.5707963267948966);
  std::vector<json> tangencies;
  double prev = 0;
  for (const json& e : j["events"]) {
    CHECK(e["a3"].get<double>() >= prev);
    prev = e["a3"].get<double>();
    for (const char* key : {"a3", "kind", "nodes_below", "nodes_above", "cusps_below", "cusps_above"})
      CHECK(e.contains(key));
    if (e["kind"] == "tangency") tangencies.push_back(e);
  }
  REQUIRE(tangencies.size() == 2);
  const double t = std::atan(3 * std::sqrt(3.0));
  CHECK(std::abs(tangencies[0]["a3"].get<double>() - t) <= 1e-13);
  CHECK(std::abs(tangencies[1]["a3"].get<double>() - (3.141592653589793 - t)) <= 1e-13);
  CHECK(tangencies[0]["nodes_below"] == 3);
  CHECK(tangencies[0]["nodes_above"] == 9);
  CHECK(tangencies[1]["nodes_below"] == 9);
  CHECK(tangencies[1]["nodes_above"] == 3);
  // Text: one line per event.
  const Result text = run("boundaries --n 3 --a2 pi/2", dir);
  REQUIRE(text.status == 0);
  CHECK(contains(text.out, "a3 = " + num(1.3806707234484299) + "  tangency  nodes 3 -> 9"));
  CHECK(count_lines(text.out) == 2 + j["events"].size());
}

TEST_CASE("boundaries --json: classify just below and above every event agrees", "[cli][boundaries]") {
  TempDir dir;
  for (const auto& [n, a2] : std::vector<std::pair<std::string, double>>{{"5/2", 1.2}, {"-3/2", 2.0}, {"7/3", 0.7}}) {
    const Result r = run("boundaries --n " + n + " --a2 " + num(a2) + " --json", dir);
    REQUIRE(r.status == 0);
    const json j = json::parse(r.out);
    const auto& ev = j["events"];
    for (std::size_t i = 0; i < ev.size(); ++i) {
      const double a3 = ev[i]["a3"].get<double>();
      INFO("n = " << n << " a2 = " << a2 << " event " << ev[i]["kind"] << " at " << a3);
      if (i == 0 || ev[i - 1]["a3"].get<double>() < a3 - 3e-7)
        CHECK(classify_nodes(n, a2, a3 - 1e-7, dir) == ev[i]["nodes_below"].get<long>());
      if (i + 1 == ev.size() || ev[i + 1]["a3"].get<double>() > a3 + 3e-7)
        CHECK(classify_nodes(n, a2, a3 + 1e-7, dir) == ev[i]["nodes_above"].get<long>());
    }
  }
}

TEST_CASE("boundaries -o curves.csv: layout, and the same bytes with 1 or 2 threads", "[cli][boundaries]") {
  TempDir dir;
  const Result one = run("boundaries --n 5/2 --a2 0.2:3 --steps 40 --threads 1 -o one.csv", dir, true);
  REQUIRE(one.status == 0);
  CHECK(one.out.empty());
  const Result two = run("boundaries --n 5/2 --a2 0.2:3 --steps 40 --threads 2 -o two.csv", dir, true);
  REQUIRE(two.status == 0);
  const std::string a = slurp(dir.path / "one.csv"), b = slurp(dir.path / "two.csv");
  CHECK(a == b);
  CHECK(a.rfind("# sphtroch boundaries n=5/2 a2=0.2:3 steps=40\nlocus,kind,m,label,a2,a3,b\n", 0) == 0);
  CHECK(contains(a, ",tangency,-2,0,"));
  CHECK(contains(a, ",pitch_cone,,,"));
  CHECK(contains(a, ",pole,,,"));
}

TEST_CASE("boundaries: bad input is exit 2, one stderr line naming the option, no output", "[cli][boundaries]") {
  TempDir dir;
  for (const std::string args : {"--n 3 --a2 4", "--n 3 --a2 0", "--n 0 --a2 1", "--n 3 --a2 nan", "--n 3 --a2 1:0",
                                 "--n 3 --a2 0:4", "--n 3 --a2 1 --steps 10", "--n 3 --a2 0:1 --json",
                                 "--n 3 --a2 0:1 --steps 0", "--n 1001/400 --a2 1", "--n 3 --a2 x:1",
                                 // as classify: the curve degenerates within 1e-6 of 0 or pi
                                 "--n 3 --a2 1e-300", "--n 3 --a2 pi-1e-15", "--n 3 --a2 0:1e-300",
                                 "--n 3 --a2 1e-300:1e-299", "--n 3 --a2 0:1 --steps 10001"}) {
    const Result r = run("boundaries " + args + " -o out.txt", dir, true);
    INFO(args << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.rfind("sphtroch: --", 0) == 0);
    CHECK(dir.entries().empty());
  }
}

TEST_CASE("boundaries --teeth: a ratio over the census bound is refused naming --teeth, as given", "[cli][boundaries]") {
  TempDir dir;
  for (const std::string args : {"--teeth 1000:999 --a2 1", "--teeth -1000:1 --a2 1", "--teeth 1000:999 --a2 0:pi --steps 5"}) {
    const Result r = run("boundaries " + args, dir, true);
    INFO(args << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.rfind("sphtroch: --teeth = ", 0) == 0);
  }
}

TEST_CASE("classify at a self-tangency typed as a double: crossings + tangencies, censuses agree, boundary named",
          "[cli][boundaries][classify]") {
  TempDir dir;
  const Result r = run("classify --n 5/2 --a2 pi/2 --a3 1.0938177365904715 --json", dir);
  REQUIRE(r.status == 0);
  const json j = json::parse(r.out);
  CHECK(j["agreement"]["ok"] == true);
  CHECK(j["counts"]["crossings"] == 10);
  CHECK(j["counts"]["tangencies"] == 5);
  REQUIRE(j["boundaries"]["on"].size() == 1);
  CHECK(contains(j["boundaries"]["on"][0]["boundary"].get<std::string>(), "self-tangency locus"));
  CHECK(std::abs(j["boundaries"]["on"][0]["margin"].get<double>()) <= 1e-15);
  const Result text = run("classify --n 5/2 --a2 pi/2 --a3 1.0938177365904715", dir);
  REQUIRE(text.status == 0);
  CHECK(contains(text.out, "on self-tangency locus g = -2"));
  CHECK(contains(text.out, "agreement: yes"));
  // --literal reads the doubles as given: no boundary named.
  const Result lit = run("classify --n 5/2 --a2 pi/2 --a3 1.0938177365904715 --json --literal", dir);
  REQUIRE(lit.status == 0);
  CHECK(json::parse(lit.out)["boundaries"]["on"].empty());
}

TEST_CASE("boundaries: events near the degenerate ends stay sorted and chained", "[cli][boundaries]") {
  // a2 = pi - 1e-6: the pitch cone and the pole passage lie 1e-16 apart near a3 = 1e-6.
  TempDir dir;
  for (const std::string args : {"--n 2 --a2 pi-1e-6", "--n -2 --a2 1e-6", "--n 3 --a2 1e-6", "--n 7/3 --a2 pi-1e-6"}) {
    const Result r = run("boundaries " + args + " --json", dir);
    INFO(args);
    REQUIRE(r.status == 0);
    const json events = json::parse(r.out)["events"];
    REQUIRE(!events.empty());
    for (std::size_t k = 0; k < events.size(); ++k) {
      const double a3 = events[k]["a3"].get<double>();
      CHECK(a3 > 0.0);
      CHECK(a3 < 3.141592653589793);
      if (k == 0) continue;
      const double prev = events[k - 1]["a3"].get<double>();
      CHECK(prev <= a3);
      if (a3 - prev > 1e-12) CHECK(events[k]["nodes_below"] == events[k - 1]["nodes_above"]);
    }
  }
}
