// `sphtroch wrist ik`, run as the real executable: the JSON's schema and numbers (the base x gear
// train wrist's 2 |p| solutions, each pointing the tool as the product of AngleAxis rotations in
// long double says; the 3R wrist's two frames), the text report, exit 3 with one line on a fold,
// and bad input: exit 2, one line on stderr naming the option, nothing on stdout (a rank-deficient
// coupling, rows != k, a zero denominator, a non-unit target, NaN, a problem beyond the cost bound).
// `sphtroch wrist cap`: the JSON's fields against the base x gear train's fold circle, the text,
// home on a fold (radius 0, said), and its refusals (--home not unit, NaN, missing; 3 motors; cost).
// `sphtroch wrist atlas`: the base x gear train's polylines on its circles, the fields, refusals;
// its regions in the JSON (counts 4 in the zone and 0 beyond, areas against 2 pi (z_hi - z_lo)),
// the picture (well-formed, a legend, text >= 9.5 px), refusals of --sphere-cell and of -o x.pdf;
// exit 3 with the report when no region is proved.
#include "catch2/catch.hpp"
#include "cli_support.hpp"
#include "wrist/wrist_reference.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace {

using namespace sphtroch::test;

std::vector<long double> motors_of(const nlohmann::json& s) {
  std::vector<long double> u;
  for (const auto& x : s["motors"]) u.push_back(x.get<double>());
  return u;
}

}  // namespace

TEST_CASE("wrist ik --json: the base x gear train wrist's 2 |p| solutions, each on the target", "[wrist][cli]") {
  TempDir dir;
  const Result r = run("wrist ik --twists 0,1,0.5 --coupling '1,0;0,1;0,3/2' --target 0.6,0,0.8 --json", dir);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["certified"] == true);
  CHECK(j["on_fold"] == false);
  CHECK(j["count"] == 6);  // n = 3/2: 2 |p| = 6, z = 0.8 inside (cos 1.5, cos 0.5)
  REQUIRE(j["solutions"].size() == 6);
  const WristModel m{{0.0, 1.0, 0.5}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}, {{0, 1}, {3, 2}}}};
  CHECK(j["wrist"]["periods"][1].get<double>() == 4 * 3.141592653589793);
  for (const auto& s : j["solutions"]) {
    const std::vector<long double> u = motors_of(s);
    REQUIRE(u.size() == 2);
    CHECK((u[0] >= 0 && u[0] < m.period(0) && u[1] >= 0 && u[1] < m.period(1)));
    CHECK(double((m.point(u) - Vec3L(0.6L, 0, 0.8L)).norm()) < 1e-12);
    CHECK(s["box_radius"].get<double>() < 1e-12);
  }
  const Result text = run("wrist ik --twists 0,1,0.5 --coupling '1,0;0,1;0,3/2' --target 0.6,0,0.8", dir);
  CHECK(text.status == 0);
  CHECK(contains(text.out, "solutions: 6 (certified"));
  CHECK(count_lines(text.out) == 3 + 6);
}

TEST_CASE("wrist ik --target-frame: the 3R wrist's two solutions hold the frame", "[wrist][cli]") {
  TempDir dir;
  const WristModel m{{1.0, 1.2, 0.7}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}, {0, 1}}, {{0, 1}, {1, 1}, {0, 1}}, {{0, 1}, {0, 1}, {1, 1}}}};
  const Mat3L f = m.frame({0.3L, 2.0L, 5.0L});
  std::string rows;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) rows += (rows.empty() ? "" : ",") + shortest_g(double(f(i, k)));
  const Result r = run("wrist ik --twists 1,1.2,0.7 --coupling '1,0,0;0,1,0;0,0,1' --target-frame " + rows + " --json", dir);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["certified"] == true);
  REQUIRE(j["count"] == 2);
  for (const auto& s : j["solutions"]) CHECK(double((m.frame(motors_of(s)) - f).cwiseAbs().maxCoeff()) < 1e-12);
}

TEST_CASE("wrist ik: a target on a fold exits 3 with one line, the report complete and saying so", "[wrist][cli]") {
  TempDir dir;
  // Twists pi/2, pi/4 and the target at z = cos(pi/4) on the fold circle z = cos(A1 - A2).
  const Result r = run("wrist ik --twists 1.5707963267948966,0.7853981633974483 --coupling '1,0;0,1' "
                       "--target 0.7071067811865476,0,0.7071067811865476 --json", dir);
  CHECK(r.status == 3);
  CHECK(count_lines(r.err) == 1);
  CHECK(contains(r.err, "fold"));
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["certified"] == false);
  CHECK(j["on_fold"] == true);
}

TEST_CASE("wrist ik: bad input exits 2 with one line naming the option and nothing on stdout", "[wrist][cli]") {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--twists 1,1,1 --coupling '1,2;2,4;3,6' --target 0,0,1", "--coupling"},        // rank 1
      {"--twists 1,1,1 --coupling '1,0;0,1' --target 0,0,1", "--coupling"},            // rows != k
      {"--twists 1,1,1 --coupling '1/0,0;0,1;0,1' --target 0,0,1", "--coupling"},      // zero denominator
      {"--twists 1,1,1 --coupling '1,0;0,1;0,2' --target 1,1,1", "--target"},          // not unit
      {"--twists 1,1,1 --coupling '1,0;0,1;0,2' --target nan,0,1", "--target"},        // NaN
      {"--twists 1,nan,1 --coupling '1,0;0,1;0,2' --target 0,0,1", "--twists"},        // NaN
      {"--twists 1,1,1 --coupling '1,0;0,1;0,2'", "--target"},                         // no target
      {"--twists 1,1,1 --coupling '1,0;0,1;0,2' --target-frame 1,0,0,0", "--target-frame"},
      {"--twists 1,1,1 --coupling '1,0,0;0,1,0;0,0,1' --target-frame 1,0,0,0 --axis 1,0,0", "--axis"},
      {"--twists 1,1,1 --coupling '5,1/1000;3,999/1000;1,7' --target 0,0,1", "--coupling"},  // beyond the cost bound
  };
  for (const auto& [args, option] : cases) {
    const Result r = run("wrist ik " + args, dir);
    INFO(args << "\n" << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, option));
  }
  const Result cost = run("wrist ik --twists 1,1,1 --coupling '5,1/1000;3,999/1000;1,7' --target 0,0,1", dir);
  CHECK(contains(cost.err, "start boxes"));
}

TEST_CASE("wrist cap --json: the base x gear train wrist's cap, its fold point and count", "[wrist][cli]") {
  TempDir dir;
  // Twists 0, 1, 0.5, n = 2; home at polar angle acos 0.8 ~ 0.6435: the fold z = cos 0.5 is nearest.
  const Result r = run("wrist cap --twists 0,1,0.5 --coupling '1,0;0,1;0,2' --home 0.6,0,0.8 --json", dir);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const double expected = std::acos(0.8L) - 0.5L;
  CHECK(j["certified"] == true);
  CHECK(j["home_on_fold"] == false);
  CHECK(j["count"] == 4);
  CHECK(j["radius"]["lower"].get<double>() <= expected);
  CHECK(j["radius"]["upper"].get<double>() >= expected);
  CHECK(j["radius"]["upper"].get<double>() - j["radius"]["lower"].get<double>() <= 1e-9);
  CHECK(j["radius"]["width"].get<double>() <= 1e-9);
  REQUIRE(j["nearest_fold_point"].size() == 3);
  CHECK(std::fabs(j["nearest_fold_point"][2].get<double>() - std::cos(0.5)) < 1e-12);
  const WristModel m{{0.0, 1.0, 0.5}, {0.0, 0.0, 0.0}, {{{1, 1}, {0, 1}}, {{0, 1}, {1, 1}}, {{0, 1}, {2, 1}}}};
  const std::vector<long double> u = motors_of(j);
  const Vec3L p = m.point(u), q(j["nearest_fold_point"][0].get<double>(), j["nearest_fold_point"][1].get<double>(),
                                j["nearest_fold_point"][2].get<double>());
  CHECK(double((p - q).norm()) < 1e-12);
  CHECK(j["motors_radius"].get<double>() < 1e-12);
  CHECK(j["wrist"]["periods"].size() == 2);
  CHECK(j["certificate"]["why"] == "");
  const Result text = run("wrist cap --twists 0,1,0.5 --coupling '1,0;0,1;0,2' --home 0.6,0,0.8", dir);
  CHECK(text.status == 0);
  CHECK(contains(text.out, "cap radius: in ["));
  CHECK(contains(text.out, "count inside the cap: 4"));
}

TEST_CASE("wrist cap: home on a fold has radius 0 and says so", "[wrist][cli]") {
  TempDir dir;
  // Twists pi/2, pi/4 (identity coupling): the fold circle z = cos(pi/4) passes through home.
  const Result r = run("wrist cap --twists 1.5707963267948966,0.7853981633974483 --coupling '1,0;0,1' "
                       "--home 0.7071067811865476,0,0.7071067811865476 --json", dir);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["home_on_fold"] == true);
  CHECK(j["radius"]["lower"].get<double>() == 0.0);
  CHECK(j["radius"]["upper"].get<double>() <= 1e-9);
  const Result text = run("wrist cap --twists 1.5707963267948966,0.7853981633974483 --coupling '1,0;0,1' "
                          "--home 0.7071067811865476,0,0.7071067811865476", dir);
  CHECK(contains(text.out, "home is on a fold"));
}

TEST_CASE("wrist cap: bad input exits 2 with one line naming the option and nothing on stdout", "[wrist][cli]") {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--twists 1,1,1 --coupling '1,0;0,1;0,2' --home 1,1,1", "--home"},        // not unit
      {"--twists 1,1,1 --coupling '1,0;0,1;0,2' --home nan,0,1", "--home"},      // NaN
      {"--twists 1,1,1 --coupling '1,0;0,1;0,2' --home 0,1", "--home"},          // two numbers
      {"--twists 1,1,1 --coupling '1,0;0,1;0,2'", "--home"},                     // missing
      {"--twists 1,1,1 --coupling '1,0,0;0,1,0;0,0,1' --home 0,0,1", "--coupling"},  // m = 3
      {"--twists 1,1,1 --coupling '5,1/1000;3,999/1000;1,7' --home 0,0,1", "--coupling"},  // beyond the cost bound
  };
  for (const auto& [args, option] : cases) {
    const Result r = run("wrist cap " + args, dir);
    INFO(args << "\n" << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, option));
  }
}

TEST_CASE("wrist atlas --json: the base x gear train wrist's fold polylines on its circles, and refusals", "[wrist][cli]") {
  TempDir dir;
  const Result r = run("wrist atlas --twists 0,1,0.5 --coupling '1,0;0,1;0,2' --width 0.1 --json", dir);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["certified"] == true);
  CHECK(j["cells_without_point"] == 0);
  CHECK(j["cell_width"].get<double>() <= 0.1);
  CHECK(j["enclosure"].get<double>() > 0);
  REQUIRE(j["polylines"].size() == 4);  // n u2 = 0, pi, 2 pi, 3 pi
  for (const auto& l : j["polylines"]) {
    CHECK(l["closed"] == true);
    CHECK(l["points"].size() == l["motors"].size());
    for (const auto& p : l["points"]) {
      const double z = p[2].get<double>();
      CHECK(std::min(std::fabs(z - std::cos(0.5)), std::fabs(z - std::cos(1.5))) < 1e-12);
    }
  }
  REQUIRE(!j["cells"].empty());
  CHECK(j["cells"][0]["motors"].size() == 2);
  CHECK(j["cells"][0]["image"].size() == 3);
  CHECK(j["wrist"]["periods"].size() == 2);
  const Result text = run("wrist atlas --twists 0,1,0.5 --coupling '1,0;0,1;0,2' --width 0.1", dir);
  CHECK(text.status == 0);
  CHECK(contains(text.out, "fold polylines: 4"));
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"--twists 0,1,0.5 --coupling '1,0;0,1;0,2' --width 0", "--width"},
           {"--twists 0,1,0.5 --coupling '1,0;0,1;0,2' --width abc", "--width"},
           {"--twists 0,1,0.5 --coupling '1,0;0,1;0,2' --width nan", "--width"},
           {"--twists 1,1,1 --coupling '1,0,0;0,1,0;0,0,1'", "--coupling"}}) {
    const Result bad = run("wrist atlas " + args, dir);
    INFO(args << "\n" << bad.err);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(count_lines(bad.err) == 1);
    CHECK(contains(bad.err, option));
  }
}

TEST_CASE("wrist atlas: the regions in the JSON, the picture, and refusals of --sphere-cell and -o x.pdf", "[wrist][cli][regions]") {
  TempDir dir;
  const std::string wrist = "wrist atlas --twists 0,1,0.5 --coupling '1,0;0,1;0,2' --width 0.1 --sphere-cell 0.05";
  const Result r = run(wrist + " --json", dir);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["certified"] == true);
  CHECK(j["regions_certified"] == true);
  REQUIRE(j["regions"].size() >= 3);  // the zone and the two caps
  const double z_lo = std::cos(1.5), z_hi = std::cos(0.5);
  double cells = 0;
  for (const auto& g : j["regions"]) {
    const double z = g["point"][2].get<double>();
    CHECK(g["count"].get<int>() == (z > z_lo && z < z_hi ? 4 : 0));
    CHECK(g["area_sr"]["cells"].get<double>() <= g["area_sr"]["upper"].get<double>());
    CHECK(g["cells"].get<int>() > 0);
    cells += g["area_sr"]["cells"].get<double>();
  }
  const double band = j["fold_band_area_sr"].get<double>(), zone = 2 * 3.141592653589793 * (z_hi - z_lo);
  CHECK(cells + band == Approx(4 * 3.141592653589793).epsilon(1e-12));
  CHECK(j["workspace_area_sr"]["cells"].get<double>() <= zone);
  CHECK(j["workspace_area_sr"]["upper"].get<double>() >= zone);
  CHECK(j["voids"].size() == 2);
  CHECK(j["checks"]["parity"] == true);
  CHECK(j["checks"]["violations"].empty());
  CHECK(j["sphere_grid"]["cells"].get<int>() > 0);
  CHECK(j["fold_radius"].get<double>() > 0);
  const Result svg = run(wrist + " -o " + (dir.path / "atlas.svg").string(), dir);
  REQUIRE(svg.status == 0);
  CHECK(svg.out.empty());
  const std::string picture = slurp((dir.path / "atlas.svg").string());
  CHECK(picture.rfind("<?xml", 0) == 0);
  CHECK(contains(picture, "</svg>"));
  CHECK(contains(picture, "IK solutions"));
  CHECK(contains(picture, ">4</text>"));
  std::size_t at = 0, sizes = 0;  // every text at least 9.5 px
  while ((at = picture.find("font-size:", at)) != std::string::npos) {
    at += 10;
    CHECK(std::stod(picture.substr(at)) >= 9.5);
    ++sizes;
  }
  CHECK(sizes > 3);
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {" --sphere-cell 0", "--sphere-cell"},
           {" --sphere-cell 0.001", "--sphere-cell"},
           {" --sphere-cell 0.9", "--sphere-cell"},
           {" --sphere-cell abc", "--sphere-cell"},
           {" --threads 0", "--threads"},
           {" -o " + (dir.path / "atlas.pdf").string(), "--output"}}) {
    const Result bad = run("wrist atlas --twists 0,1,0.5 --coupling '1,0;0,1;0,2'" + args, dir);
    INFO(args << "\n" << bad.err);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(count_lines(bad.err) == 1);
    CHECK(contains(bad.err, option));
  }
}

TEST_CASE("wrist atlas: no region proved (a coarse sphere grid) exits 3 after the complete report, one line naming it", "[wrist][cli][regions]") {
  TempDir dir;
  const Result r = run("wrist atlas --twists 2.4617,1.8544,1.9130,1.9478 --coupling '0,4/3;0,0;0,-1/4;-4/1,-2/3' --sphere-cell 0.5 --width 0.2 --json", dir);
  CHECK(r.status == 3);
  CHECK(count_lines(r.err) == 1);
  CHECK(contains(r.err, "regions not certified"));
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["certified"] == false);
  CHECK(j["regions_certified"] == false);
  CHECK(j["atlas_certified"] == true);
  CHECK(j["regions"].empty());
  CHECK(!j["regions_why"].get<std::string>().empty());
}
