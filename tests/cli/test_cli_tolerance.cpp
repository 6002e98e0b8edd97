// `sphtroch tolerance`, run as the real executable (SPHTROCH_EXE): the JSON of the issue's
// interface, its verdicts against the closed-form pole line a3 = a2 (|p| >= 2) and against
// `sphtroch boundaries` at the train's a2, --degrees, exit 3 when undecided, and bad input (exit 2,
// one stderr line, nothing on stdout, no file).
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace {

using namespace sphtroch::test;
using nlohmann::json;

const char* kTrain = "--a2 1 --a3 2 --n 5/2";

}  // namespace

TEST_CASE("tolerance --json: the interface's members, holds inside the margin, changes across the pole line", "[cli][tolerance]") {
  TempDir dir;
  const Result r = run(std::string("tolerance ") + kTrain + " --tol-a2 1e-3 --tol-a3 1e-3 --tol-phase 1e-3 --json", dir);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const json j = json::parse(r.out);
  CHECK(j["topology"] == "holds");
  CHECK(j["event"].is_null());
  // The nearest boundary of (1, 2) for n = 5/2 is the south pole line a3 = pi - a2, at L-infinity
  // distance (pi - a2 - a3)/2 (the square's corner touches the line).
  const double pole = (3.141592653589793 - 3.0) / 2;
  CHECK(j["margin"]["lower"].get<double>() <= pole);
  CHECK(j["margin"]["upper"].get<double>() >= pole);
  CHECK(j["margin"]["upper"].get<double>() - j["margin"]["lower"].get<double>() <= std::max(1e-9, 1e-6 * pole));
  CHECK(j["margin"]["nearest"]["kind"] == "pole");
  REQUIRE(j["nodes"].size() == j["census"]["nodes"].get<std::size_t>());
  for (const json& n : j["nodes"]) {
    for (const char* key : {"id", "position", "max_displacement", "d_da2", "d_da3", "d_dphase"}) CHECK(n.contains(key));
    CHECK(n["position"].size() == 3);
    CHECK(n["max_displacement"].get<double>() > 0);
    CHECK(n["max_displacement"].get<double>() < 0.05);
  }
  CHECK(j["cusps"].empty());
  // A box reaching past the pole line changes; the event lies in the box.
  const Result c = run(std::string("tolerance ") + kTrain + " --tol-a2 0.1 --tol-a3 0.1 --json", dir);
  REQUIRE(c.status == 0);
  const json k = json::parse(c.out);
  CHECK(k["topology"] == "changes");
  CHECK(k["event"]["kind"] == "pole");
  CHECK(std::fabs(k["event"]["a2"].get<double>() + k["event"]["a3"].get<double>() - 3.141592653589793) <= 1e-9);
  CHECK(std::fabs(k["event"]["a2"].get<double>() - 1) <= 0.1);
}

TEST_CASE("tolerance: a3 on a segment of fixed a2 against `sphtroch boundaries`", "[cli][tolerance]") {
  TempDir dir;
  const Result b = run("boundaries --n 3 --a2 pi/2 --json", dir);
  REQUIRE(b.status == 0);
  const json events = json::parse(b.out)["events"];  // kept: a range-for over a temporary's member dangles
  REQUIRE(events.size() >= 4);
  for (const json& e : events) {
    const double a3 = e["a3"].get<double>();
    const std::string at = " --n 3 --a2 pi/2 --a3 " + shortest_g(a3 + 1e-4) + " --tol-a2 0 --json --tol-a3 ";
    const Result near = run("tolerance" + at + "2e-4", dir), far = run("tolerance" + at + "5e-5", dir);
    // Exit 3 may come from a node whose move is not proved (a near-cusp loop next to a pitch cone
    // crosses at a small angle): the verdict is what is checked here.
    REQUIRE((near.status == 0 || near.status == 3));
    REQUIRE((far.status == 0 || far.status == 3));
    CHECK(json::parse(near.out)["topology"] == "changes");
    CHECK(json::parse(far.out)["topology"] == "holds");
  }
}

TEST_CASE("tolerance --degrees reads the half-widths as degrees, and the text names the verdict", "[cli][tolerance]") {
  TempDir dir;
  const Result d = run(std::string("tolerance ") + kTrain + " --tol-a2 0.1 --tol-a3 0.05 --degrees --json", dir);
  const Result s = run(std::string("tolerance ") + kTrain + " --tol-a2 0.1deg --tol-a3 pi/3600 --json", dir);
  REQUIRE(d.status == 0);
  REQUIRE(s.status == 0);
  CHECK(json::parse(d.out)["box"] == json::parse(s.out)["box"]);
  CHECK(std::fabs(json::parse(d.out)["box"]["a2"].get<double>() - 3.141592653589793 / 1800) <= 1e-18);
  const Result t = run(std::string("tolerance ") + kTrain + " --tol-a2 0.1 --tol-a3 0.1 --degrees", dir);
  REQUIRE(t.status == 0);
  CHECK(contains(t.out, "topology: holds (certified"));
  CHECK(contains(t.out, "margin: "));
}

TEST_CASE("tolerance: a box whose edge lies on the pole line is undecided, exit 3, and says why", "[cli][tolerance]") {
  TempDir dir;
  const Result r = run("tolerance --a2 1 --a3 a2+0.001 --n 5/2 --tol-a2 0 --tol-a3 0.001 --json", dir);
  CHECK(r.status == 3);
  const json j = json::parse(r.out);
  CHECK(j["topology"] != "holds");
  if (j["topology"] == "undecided") CHECK(!j["why"].is_null());
  CHECK(contains(r.err, "tolerance"));
}

TEST_CASE("tolerance --samples: Monte Carlo beside a holding proof sees only the nominal census", "[cli][tolerance]") {
  TempDir dir;
  const Result r = run(std::string("tolerance ") + kTrain + " --tol-a2 1e-3 --tol-a3 1e-3 --samples 30 --seed 9 --json", dir);
  REQUIRE(r.status == 0);
  const json j = json::parse(r.out);
  CHECK(j["monte_carlo"]["samples"] == 30);
  CHECK(j["monte_carlo"]["same_census"] == 30);
  double largest = 0;
  for (const json& n : j["nodes"]) largest = std::max(largest, n["max_displacement"].get<double>());
  CHECK(j["monte_carlo"]["max_node_shift"].get<double>() <= largest);
}

TEST_CASE("tolerance --samples: refused up front beyond the work bound, 25 times lower next to a pitch cone", "[cli][tolerance][errors]") {
  TempDir dir;
  // n = 5/2: (|p| + q)^3 = 343, so 1e7 allows 29,154 samples off the cones and 1,166 within 1e-3
  // rad of one (a classify there takes ~20 times as long: the near-cusp loops).
  const std::string off = "tolerance --a2 1 --a3 2 --n 5/2 --tol-a2 0 --tol-a3 0 ";
  const std::string on = "tolerance --a2 1 --a3 ap+5e-4 --n 5/2 --tol-a2 0 --tol-a3 0 ";
  for (const std::string& args : {off + "--samples 29155", on + "--samples 1167", on + "--samples 29000"}) {
    INFO(args);
    const Result r = run(args + " -o out.json", dir, true);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, "--samples"));
    CHECK(dir.entries().empty());
  }
  CHECK(contains(run(on + "--samples 1167", dir).err, "next to a pitch cone"));
  CHECK(run(on + "--samples 2 --json", dir).status == 0);  // within the bound: runs
}

TEST_CASE("tolerance: bad half-widths: one line, exit 2, nothing on stdout, no file", "[cli][tolerance]") {
  TempDir dir;
  for (const std::string bad : {"--tol-a2 -1e-3 --tol-a3 0", "--tol-a2 nan --tol-a3 0", "--tol-a2 0 --tol-a3 1.5",
                                "--tol-a2 0 --tol-a3 0 --tol-phase 7", "--tol-a2 0 --tol-a3 0 --samples 0", "--tol-a2 x --tol-a3 0"}) {
    INFO(bad);
    const Result r = run(std::string("tolerance ") + kTrain + " " + bad + " -o out.json", dir, true);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(dir.entries().empty());
  }
}
