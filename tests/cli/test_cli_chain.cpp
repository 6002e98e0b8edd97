// `sphtroch chain trace`, run as the real executable: for k = 2 (rates 1,n, phases 0,theta_p)
// the bytes of `sphtroch trace` on random trains, with and without --velocity --kinematics; for
// k = 3, 4 every row against a product of Eigen AngleAxis rotations in long double written here
// from the model; the period and the default count from the rates; bad input (exit 2, one line
// naming the option, nothing on stdout, no file). chain classify and nodes: for k = 2 the counts,
// node positions and branches of `sphtroch classify` (the gear train's two censuses); for k = 3
// each node's two branch parameters give one point of the rotation model; the report's Fig. 3
// node at (0, 1, 0) (Eq. 25); a chain written by `chain export --urdf` reads back to the same
// census, and the text of a hand-written one prints the twists (the angles between its axes),
// rates and phases read; bad input, including URDF files, exits 2 with one line.
#include "catch2/catch.hpp"
#include "cli_support.hpp"
#include "svg_support.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace sphtroch::test;

struct Stage {
  double twist;
  int p, q;
  double phase;
};

std::string join(const std::vector<Stage>& stages, int what) {
  std::string s;
  for (const Stage& st : stages)
    s += (s.empty() ? "" : ",") +
         (what == 0 ? shortest_g(st.twist) : what == 1 ? std::to_string(st.p) + "/" + std::to_string(st.q) : shortest_g(st.phase));
  return s;
}

Eigen::Matrix<long double, 3, 1> model(const std::vector<Stage>& stages, long double s) {
  Eigen::Matrix<long double, 3, 3> r = Eigen::Matrix<long double, 3, 3>::Identity();
  for (const Stage& st : stages)
    r = r * Eigen::AngleAxis<long double>(st.p * s / st.q + st.phase, Eigen::Matrix<long double, 3, 1>::UnitZ()).toRotationMatrix() *
        Eigen::AngleAxis<long double>(st.twist, Eigen::Matrix<long double, 3, 1>::UnitX()).toRotationMatrix();
  return r.col(2);
}

}  // namespace

TEST_CASE("chain trace, k = 2: the bytes of sphtroch trace (1000 trains)", "[cli][chain]") {
  TempDir dir;
  std::mt19937 rng(2045);
  std::uniform_real_distribution<double> angle(0.01, 3.13), phase(0, 6.28);
  std::uniform_int_distribution<int> num(-7, 7), den(1, 7);
  int compared = 0;
  for (int trial = 0; trial < 1100; ++trial) {
    const double a2 = angle(rng), a3 = angle(rng), ph = phase(rng);
    const int p = num(rng), q = den(rng);
    if (p == 0) continue;
    // Every 10th train at the default sample count, the others at 97 samples (the cost is the processes).
    const std::string n = std::to_string(p) + "/" + std::to_string(q),
                      extra = std::string(trial % 3 == 0 ? " --velocity --kinematics" : "") + (trial % 10 == 0 ? "" : " --samples 97");
    const Result chain = run("chain trace --twists " + shortest_g(a2) + "," + shortest_g(a3) + " --rates 1," + n + " --phases 0," + shortest_g(ph) + extra, dir);
    const Result trace = run("trace --a2 " + shortest_g(a2) + " --a3 " + shortest_g(a3) + " --n " + n + " --phase " + shortest_g(ph) + extra, dir);
    REQUIRE(chain.status == 0);
    REQUIRE(trace.status == 0);
    INFO("a2 " << shortest_g(a2) << " a3 " << shortest_g(a3) << " n " << n << " phase " << shortest_g(ph));
    CHECK(chain.out == trace.out);
    ++compared;
  }
  CHECK(compared >= 1000);
}

TEST_CASE("chain trace, k = 3 and 4: every row is a product of rotation matrices", "[cli][chain]") {
  TempDir dir;
  std::mt19937 rng(3045);
  std::uniform_real_distribution<double> twist(0.05, 3.09), phase(-3, 3);
  std::uniform_int_distribution<int> num(-4, 4), den(1, 4);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Stage> stages;
    for (int i = 0; i < 3 + trial % 2; ++i) stages.push_back({twist(rng), i == 0 ? 1 : num(rng), i == 0 ? 1 : den(rng), phase(rng)});
    const Result r = run("chain trace --twists " + join(stages, 0) + " --rates " + join(stages, 1) + " --phases " + join(stages, 2) + " --samples 257", dir);
    REQUIRE(r.status == 0);
    std::istringstream in(r.out);
    std::string line;
    std::getline(in, line);
    CHECK(line == "t,x,y,z");
    std::size_t rows = 0;
    while (std::getline(in, line)) {
      double t, x, y, z;
      char c;
      std::istringstream row(line);
      row >> t >> c >> x >> c >> y >> c >> z;
      const auto m = model(stages, t);
      CHECK(std::fabs(x - m.x()) + std::fabs(y - m.y()) + std::fabs(z - m.z()) <= 1e-13);
      ++rows;
    }
    CHECK(rows == 257);
  }
}

TEST_CASE("chain trace: the period and the default sample count come from the rates", "[cli][chain]") {
  TempDir dir;
  // Rates 1, -2/3, 5/3: L = 3, numerators 3, -2, 5, g = 1: period 6 pi; 360 (3 + 2 + 5) = 3600 samples.
  const Result r = run("chain trace --twists pi/2,1.2,0.4 --rates 1,-2/3,5/3", dir);
  REQUIRE(r.status == 0);
  CHECK(count_lines(r.out) == 3601);
  const Result four = run("chain trace --twists pi/2,1.2,0.4 --rates 1,-2/3,5/3 --samples 4", dir);
  CHECK(contains(four.out, "\n" + shortest_g(6 * 3.14159265358979323846 * 3 / 4) + ","));
  // Rates 2, 4: g = 2, the period is pi; 360 (2 + 4) / 2 = 1080 samples.
  CHECK(count_lines(run("chain trace --twists 1,1 --rates 2,4", dir).out) == 1081);
}

TEST_CASE("chain trace: bad input is refused with one line naming the option", "[cli][chain]") {
  TempDir dir;
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"--twists 1,2 --rates 1", "--rates"}, {"--twists 1,2 --rates 1,2 --phases 0", "--phases"},
           {"--twists 1,nan --rates 1,2", "--twists"}, {"--twists 1,3.5 --rates 1,2", "--twists"},
           {"--twists 1,-0.1 --rates 1,2", "--twists"}, {"--twists 1,2 --rates 1,x", "--rates"},
           {"--twists 1,2 --rates 1,1/0", "--rates"}, {"--twists 1,2 --rates 0,0/3", "--rates"},
           {"--twists 1,2 --rates 1,2 --phases 0,inf", "--phases"}, {"--twists 1,2 --rates 1,999999/1000000 -o out.csv", "--samples"},
           {"--twists 1,2 --rates 1,2 --samples 2 -o out.csv", "--samples"}, {"--twists , --rates 1", "--twists"}}) {
    const Result r = run("chain trace " + args, dir, true);
    INFO(args << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, option));
    CHECK(dir.entries().empty());
  }
}

TEST_CASE("chain classify, k = 2: counts, node positions and branches equal classify's on random trains", "[cli][chain]") {
  TempDir dir;
  std::mt19937 rng(4545);
  std::uniform_real_distribution<double> angle(0.05, 3.09), phase(0, 6.28);
  std::uniform_int_distribution<int> num(-5, 5), den(1, 5);
  int compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const double a2 = angle(rng), a3 = angle(rng), ph = phase(rng);
    const int p = num(rng), q = den(rng);
    if (p == 0) continue;
    const std::string n = std::to_string(p) + "/" + std::to_string(q);
    const Result train = run("classify --a2 " + shortest_g(a2) + " --a3 " + shortest_g(a3) + " --n " + n + " --phase " + shortest_g(ph) + " --json", dir, true);
    const auto t = nlohmann::json::parse(train.out);
    // Within 1e-5 of a pitch cone the two censuses resolve near-cusp loops differently (docs/chains.md).
    if (std::fabs(t["boundaries"]["pitch_cone_margin"].get<double>()) < 1e-5 ||
        std::fabs(t["boundaries"]["mirror_pitch_cone_margin"].get<double>()) < 1e-5 || t["counts"]["tangencies"].get<int>() > 0)
      continue;
    const Result chain = run("chain classify --twists " + shortest_g(a2) + "," + shortest_g(a3) + " --rates 1," + n + " --phases 0," + shortest_g(ph) + " --json", dir);
    const auto c = nlohmann::json::parse(chain.out);
    INFO("a2 " << shortest_g(a2) << " a3 " << shortest_g(a3) << " n " << n << " phase " << shortest_g(ph));
    REQUIRE(train.status == 0);
    CHECK(c["certified"] == true);
    CHECK(c["counts"] == t["counts"]);
    CHECK(c["class"] == t["class"]);
    for (const auto& node : t["nodes"]) {
      const Eigen::Vector3d x(node["position"][0], node["position"][1], node["position"][2]);
      bool found = false;
      for (const auto& other : c["nodes"]) {
        const Eigen::Vector3d y(other["position"][0], other["position"][1], other["position"][2]);
        if ((x - y).norm() < 1e-9 && other["branches"] == node["branches"]) found = true;
      }
      CHECK(found);
    }
    ++compared;
  }
  CHECK(compared > 30);
}

TEST_CASE("chain classify and nodes: a k = 3 chain's table is its JSON, and the report's Fig. 3 node (Eq. 25)", "[cli][chain]") {
  TempDir dir;
  const std::string chain = "--twists pi/2,pi/3,pi/4 --rates 1,1/2,-3/2 --phases 0,0.3,0";
  const auto j = nlohmann::json::parse(run("chain classify " + chain + " --json", dir).out);
  const std::vector<std::string> rows = split_lines(run("chain nodes " + chain, dir).out);
  REQUIRE(rows.size() == 1 + j["nodes"].size() + j["cusps"].size());
  CHECK(rows[0] == "kind,x,y,z,t1,t2,branches,id");
  // Each node's two branch parameters give the same point of the model (an independent product of rotations).
  const std::vector<Stage> stages{{M_PI / 2, 1, 1, 0}, {M_PI / 3, 1, 2, 0.3}, {M_PI / 4, -3, 2, 0}};
  for (const auto& node : j["nodes"]) {
    const auto a = model(stages, node["params"][0].get<double>()), b = model(stages, node["params"][1].get<double>());
    CHECK((a - b).norm() < 1e-12);
  }
  const auto fig3 = nlohmann::json::parse(run("chain classify --twists pi/2,pi/2 --rates 1,1 --json", dir).out);
  REQUIRE(fig3["nodes"].size() == 1);
  CHECK(std::fabs(fig3["nodes"][0]["position"][1].get<double>() - 1.0) < 1e-12);
}

TEST_CASE("chain nodes, k = 2 with rates 1,n: the bytes of sphtroch nodes, tangencies and cusps included (1000 trains)", "[cli][chain]") {
  TempDir dir;
  std::mt19937 rng(4546);
  std::uniform_real_distribution<double> angle(0.05, 3.09), phase(0, 6.28);
  std::uniform_int_distribution<int> num(-5, 5), den(1, 5);
  std::vector<std::string> trains = {"pi/2 " + shortest_g(std::atan(3 * std::sqrt(3.0))) + " 3 0",  // three tangencies (closed form)
                                     "pi/2 " + shortest_g(std::atan(3 * std::sqrt(3.0)) + 3e-11) + " 3 0",  // snapped onto them by classify
                                     "pi/2 pi/2 1 0", "1 0.31987291043476807 2 0.5"};             // Fig. 3; two cusps (a3 = a_p)
  while (trains.size() < 1000) {
    const int p = num(rng), q = den(rng);
    if (p != 0) trains.push_back(shortest_g(angle(rng)) + " " + shortest_g(angle(rng)) + " " + std::to_string(p) + "/" + std::to_string(q) + " " + shortest_g(phase(rng)));
  }
  for (const std::string& t : trains) {
    std::istringstream in(t);
    std::string a2, a3, n, ph;
    in >> a2 >> a3 >> n >> ph;
    const Result chain = run("chain nodes --twists " + a2 + "," + a3 + " --rates 1," + n + " --phases 0," + ph, dir, true);
    const Result train = run("nodes --a2 " + a2 + " --a3 " + a3 + " --n " + n + " --phase " + ph, dir, true);
    INFO(t);
    CHECK(chain.status == train.status);
    CHECK(chain.out == train.out);
  }
  const auto tangent = nlohmann::json::parse(run("chain classify --twists pi/2," + shortest_g(std::atan(3 * std::sqrt(3.0))) + " --rates 1,3 --json", dir).out);
  CHECK(tangent["counts"]["tangencies"] == 3);
  const auto cusps = nlohmann::json::parse(run("chain classify --twists 1,0.31987291043476807 --rates 1,2 --json", dir).out);
  CHECK(cusps["counts"]["cusps"] == 2);
}

TEST_CASE("chain classify, k = 2 with a motor rate other than 1: each node's parameters give one point of the model", "[cli][chain]") {
  TempDir dir;
  const std::vector<Stage> stages{{1.1, 2, 1, 0.3}, {2.0, 4, 3, 0.1}};
  const auto j = nlohmann::json::parse(run("chain classify --twists 1.1,2 --rates 2,4/3 --phases 0.3,0.1 --json", dir).out);
  REQUIRE(j["certified"] == true);
  REQUIRE(!j["nodes"].empty());
  for (const auto& node : j["nodes"]) {
    const auto a = model(stages, node["params"][0].get<double>()), b = model(stages, node["params"][1].get<double>());
    CHECK((a - b).norm() < 1e-12);
    CHECK(node["params"][1].get<double>() < j["chain"]["period"].get<double>());
  }
}

TEST_CASE("chain export --urdf, read back with chain classify --urdf: the same census", "[cli][chain]") {
  TempDir dir;
  const std::string chain = "--twists pi/2,pi/3,pi/4 --rates 1,1/2,-3/2 --phases 0,0.3,0";
  REQUIRE(run("chain export " + chain + " --urdf wrist.urdf", dir, true).status == 0);
  const auto a = nlohmann::json::parse(run("chain classify " + chain + " --json", dir).out);
  const auto b = nlohmann::json::parse(run("chain classify --urdf wrist.urdf --from base_link --to tool --json", dir, true).out);
  CHECK(b["counts"] == a["counts"]);
  CHECK(b["chain"]["rates"] == a["chain"]["rates"]);
  // An output that is the --urdf input is refused before the work, the input kept.
  const std::string before = slurp(dir.path / "wrist.urdf");
  const Result same = run("chain classify --urdf wrist.urdf --from base_link --to tool -o wrist.urdf", dir, true);
  CHECK(same.status == 2);
  CHECK(contains(same.err, "--urdf"));
  CHECK(slurp(dir.path / "wrist.urdf") == before);  // the motor's rate is 1 here, so the rates are the same
  for (std::size_t k = 0; k < a["nodes"].size(); ++k)
    for (int x = 0; x < 3; ++x) CHECK(std::fabs(a["nodes"][k]["position"][x].get<double>() - b["nodes"][k]["position"][x].get<double>()) < 1e-12);
}

namespace {

/// The numbers of the text line that starts with `head` ("twists: "), comma-separated, before " rad".
std::vector<double> listed(const std::string& text, const std::string& head) {
  std::vector<double> v;
  const std::size_t at = text.find("\n" + head);
  if (at == std::string::npos) return v;
  std::istringstream in(text.substr(at + 1 + head.size(), text.find(" rad", at) - at - 1 - head.size()));
  for (std::string field; std::getline(in, field, ',');) v.push_back(std::strtod(field.c_str(), nullptr));
  return v;
}

}  // namespace

TEST_CASE("chain classify --urdf text: the twists and rates and phases read from the file", "[cli][chain]") {
  // Three joints through the origin, no joint origin turned: the axes as written are the rest
  // pose's, z1 = z, z2 = (0, sin a, cos a), z3 = (sin b, 0, cos b), and the tool axis --axis 1,0,0.
  // The twists are the angles between consecutive axes: a, acos(cos a cos b), acos(sin b).
  const double a = 0.7, b = 1.1;
  const Eigen::Vector3d z1(0, 0, 1), z2(0, std::sin(a), std::cos(a)), z3(std::sin(b), 0, std::cos(b)), tool(1, 0, 0);
  const std::vector<double> twists = {a, std::acos(std::cos(a) * std::cos(b)), std::acos(std::sin(b))};
  TempDir dir;
  {
    const auto axis = [](const Eigen::Vector3d& v) { return shortest_g(v.x()) + " " + shortest_g(v.y()) + " " + shortest_g(v.z()); };
    std::ofstream f(dir.path / "three.urdf");
    f << "<robot name='three'><link name='base'/><link name='l1'/><link name='l2'/><link name='l3'/>"
      << "<joint name='j1' type='continuous'><parent link='base'/><child link='l1'/><axis xyz='" << axis(z1) << "'/></joint>"
      << "<joint name='j2' type='continuous'><parent link='l1'/><child link='l2'/><axis xyz='" << axis(z2) << "'/>"
      << "<mimic joint='j1' multiplier='0.5' offset='0.3'/></joint>"
      << "<joint name='j3' type='continuous'><parent link='l2'/><child link='l3'/><axis xyz='" << axis(z3) << "'/>"
      << "<mimic joint='j1' multiplier='-1.5'/></joint></robot>";
  }
  const Result r = run("chain classify --urdf three.urdf --from base --to l3 --axis 1,0,0", dir, true);
  REQUIRE(r.status == 0);
  CHECK(r.out.rfind("chain: 3 stages, rates 1,1/2,-3/2, period ", 0) == 0);
  const std::vector<double> got = listed(r.out, "twists: "), phases = listed(r.out, "phases: ");
  REQUIRE(got.size() == 3);
  REQUIRE(phases.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) CHECK(std::fabs(got[i] - twists[i]) < 1e-12);
  // The phases printed, with those twists and rates, draw the tool axis of the file's joints
  // turned by s, s/2 + 0.3 and -3s/2 about their axes (up to a turn about z1: the first joint's
  // frame), so its height along z1 at every s.
  const std::vector<Stage> stages = {{got[0], 1, 1, phases[0]}, {got[1], 1, 2, phases[1]}, {got[2], -3, 2, phases[2]}};
  for (int k = 0; k < 50; ++k) {
    const double s = 0.5 * k;
    const Eigen::Vector3d p = Eigen::AngleAxisd(s, z1) * Eigen::AngleAxisd(s / 2 + 0.3, z2) * Eigen::AngleAxisd(-1.5 * s, z3) * tool;
    CHECK(std::fabs(static_cast<double>(model(stages, s).z()) - p.z()) < 1e-12);
  }
  // The JSON gives the same numbers.
  const auto j = nlohmann::json::parse(run("chain classify --urdf three.urdf --from base --to l3 --axis 1,0,0 --json", dir, true).out);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(j["chain"]["twists"][i].get<double>() == got[i]);
    CHECK(j["chain"]["phases"][i].get<double>() == phases[i]);
  }
}

TEST_CASE("chain classify, nodes, export: bad input is refused with one line naming the option", "[cli][chain]") {
  TempDir dir;
  {
    std::ofstream bad(dir.path / "bad.urdf");
    bad << "<robot name='x'><link name='a'/><joint name='j' type='prismatic'><parent link='a'/><child link='b'/>"
           "<axis xyz='0 0 1'/><limit lower='0' upper='1' effort='1' velocity='1'/></joint><link name='b'/></robot>";
  }
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"classify --twists 1,2 --rates 1", "--rates"}, {"classify --twists 1,nan --rates 1,2", "--twists"},
           {"classify --twists 1,4 --rates 1,2", "--twists"}, {"classify --twists 1,2 --rates 1,x", "--rates"},
           {"classify --twists 1,2 --rates 0,0", "--rates"}, {"classify", "--twists"},
           {"nodes --twists 1,2 --rates 1,2 --radius -1", "--radius"},
           {"classify --twists 1,2 --rates 1,1/99991 --phases 0,0", "--rates"},
           {"classify --urdf missing.urdf --from a --to b", "--urdf"}, {"classify --urdf bad.urdf --from a --to b", "--urdf"},
           {"classify --urdf bad.urdf --from a", "--to"}, {"classify --twists 1,2 --rates 1,2 --from a", "--from"},
           {"classify --urdf bad.urdf --twists 1 --from a --to b", "--twists"}, {"classify --urdf bad.urdf --from a --to b --axis 0,0", "--axis"},
           {"export --twists 1,2 --rates 1,2 --urdf out/x.urdf", "--urdf"}, {"export --twists 1,9 --rates 1,2 --urdf x.urdf", "--twists"},
           {"classify --twists 1,2 --rates 1,2/x", "(stage 2)"}, {"classify --twists 1,2,3 --rates 1,2,1/0", "(stage 3)"},
           {"plot --twists 1,2 --rates 1,2/3 -o x.pdf", "--output"}, {"plot --twists 1,2 --rates 1,2/3 --size 10 -o x.svg", "--size"},
           {"plot --twists 1,2 --rates 1,2/3 --view sideways -o x.svg", "--view"}, {"plot --twists 1,2 --rates 1 -o x.svg", "--rates"}}) {
    const Result r = run("chain " + args, dir, true);
    INFO(args << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, option));
    CHECK(dir.entries().size() == 1);  // bad.urdf only
  }
}

TEST_CASE("chain plot: for k = 2 the picture of sphtroch plot, for k = 3 the census of chain classify", "[cli][chain]") {
  TempDir dir;
  // Everything but the caption (the <title> and the <text> elements, and the picture's height,
  // which grows with the caption's lines) is plot's: the same curve bits (ChainCurve =
  // TracerCurve), the same sample count, the same census.
  const auto without_text = [](std::string svg) {
    for (const char* tag : {"title", "text"}) {
      const std::string open = std::string("<") + tag, close = std::string("</") + tag + ">";
      for (std::size_t at; (at = svg.find(open)) != std::string::npos;) svg.erase(at, svg.find(close, at) + close.size() + 1 - at);  // and its line end
    }
    const std::size_t root = svg.find("<svg"), height = svg.find(" height=\"", root);
    svg.erase(height, svg.find('>', height) - height);  // the height and the viewBox after it
    return svg;
  };
  std::mt19937 rng(4547);
  std::uniform_real_distribution<double> angle(0.05, 3.09), phase(0, 6.28);
  std::uniform_int_distribution<int> num(-5, 5), den(1, 5);
  int compared = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int p = num(rng), q = den(rng);
    const std::string a2 = shortest_g(angle(rng)), a3 = shortest_g(angle(rng)), ph = shortest_g(phase(rng));
    if (p == 0) continue;
    const std::string n = std::to_string(p) + "/" + std::to_string(q);
    const Result chain = run("chain plot --twists " + a2 + "," + a3 + " --rates 1," + n + " --phases 0," + ph + " -o c.svg", dir, true);
    const Result train = run("plot --a2 " + a2 + " --a3 " + a3 + " --n " + n + " --phase " + ph + " -o p.svg", dir, true);
    INFO(a2 << " " << a3 << " " << n << " " << ph);
    REQUIRE(chain.status == train.status);
    const std::string c = slurp(dir.path / "c.svg"), t = slurp(dir.path / "p.svg");
    CHECK(c != t);  // the captions differ
    CHECK(without_text(c) == without_text(t));
    ++compared;
  }
  CHECK(compared > 15);
  const std::string wrist = "--twists pi/2,pi/3,pi/4 --rates 1,1/2,-3/2 --phases 0,0.3,0";
  const auto j = nlohmann::json::parse(run("chain classify " + wrist + " --json", dir).out);
  REQUIRE(run("chain plot " + wrist + " -o w.svg", dir, true).status == 0);
  const std::string svg = slurp(dir.path / "w.svg");
  const std::string nodes = std::to_string(j["counts"]["nodes"].get<int>());
  CHECK(contains(svg, "rates 1,1/2,-3/2, phases 0,0.3,0 — " + nodes + " node(s)"));
  for (std::size_t i = 1; i <= j["nodes"].size(); ++i) CHECK(contains(svg, ">N" + std::to_string(i) + "<"));
  // Not certified: the picture says so in its caption, then exit 3.
  const std::string sixteen = "--twists 1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1 --rates 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16";
  const Result u = run("chain plot " + sixteen + " -o u.svg", dir, true);
  CHECK(u.status == 3);
  CHECK(contains(slurp(dir.path / "u.svg"), "NOT CERTIFIED"));
  const auto uj = nlohmann::json::parse(run("chain classify " + sixteen + " --json", dir, true).out);
  CHECK(uj["certified"] == false);
  CHECK(uj["class"] == "unknown");
}

TEST_CASE("chain plot: the caption's angles as typed or to 6 digits, wrapped at a readable size", "[cli][chain]") {
  TempDir dir;
  // The caption: the lines of the caption group that are not notes (notes end at the right
  // margin, the caption is centred), read back into one text.
  const auto caption_of = [](const std::string& text, double& smallest, std::size_t& lines) {
    std::string caption;
    smallest = 1e9;
    lines = 0;
    for (const svg_test::Element& e : svg_test::elements(text)) {
      if (e.name != "text" || !e.in_group("caption")) continue;
      smallest = std::min(smallest, svg_test::font_px(e));
      if (!e.has("text-anchor") || e.attributes.at("text-anchor") != "middle") continue;
      ++lines;
      caption += (caption.empty() || caption.back() == ',' ? "" : " ") + e.text;
    }
    return caption;
  };
  double smallest = 0;
  std::size_t lines = 0;
  REQUIRE(run("chain plot --twists pi/2,pi/3,pi/4 --rates 1,1/2,-3/2 --phases 0,0.3,0 -o w.svg", dir, true).status == 0);
  const std::string w = caption_of(slurp(dir.path / "w.svg"), smallest, lines);
  CHECK(contains(w, "twists pi/2,pi/3,pi/4, rates 1,1/2,-3/2, phases 0,0.3,0 — "));
  CHECK(smallest >= 9.5);  // the caption was 6.1 px
  CHECK(lines >= 2);       // too long for one line at that size: wrapped, not shrunk
  // Decimals of more than 6 significant digits (as Python's floats arrive) are rounded to 6.
  REQUIRE(run("chain plot --twists 1.0471975511965976,0.7853981633974483,2 --rates 1,3,-1 --phases 0,0,0.123456789 -o d.svg", dir, true)
              .status == 0);
  const std::string d = caption_of(slurp(dir.path / "d.svg"), smallest, lines);
  CHECK(contains(d, "twists 1.0472,0.785398,2, rates 1,3,-1, phases 0,0,0.123457 — "));
  CHECK(smallest >= 9.5);
}

TEST_CASE("chain --urdf: a tool axis that does not move names --urdf, a huge --axis is a direction", "[cli][chain]") {
  TempDir dir;
  REQUIRE(run("chain export --twists 0,0 --rates 1,2 --urdf still.urdf", dir, true).status == 0);
  const Result still = run("chain classify --urdf still.urdf --from base_link --to tool", dir, true);
  CHECK(still.status == 2);
  CHECK(count_lines(still.err) == 1);
  CHECK(contains(still.err, "--urdf"));
  REQUIRE(run("chain export --twists pi/2,pi/3,pi/4 --rates 1,1/2,-3/2 --urdf wrist.urdf", dir, true).status == 0);
  const auto unit = nlohmann::json::parse(run("chain classify --urdf wrist.urdf --from base_link --to tool --axis 1,1,0 --json", dir, true).out);
  const Result huge = run("chain classify --urdf wrist.urdf --from base_link --to tool --axis 1e300,1e300,0 --json", dir, true);
  REQUIRE(huge.status == 0);
  CHECK(nlohmann::json::parse(huge.out) == unit);
}

TEST_CASE("chain boundaries: along A2 of a two-stage chain, counts either side are chain classify's", "[cli][chain]") {
  TempDir dir;
  // Motor rates other than 1 (n = N2 / N1); each event's node counts just below and just above
  // against the certified census of chain classify there, and its values against `boundaries`.
  for (const auto& [twist1, rates, n] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"pi/2", "2,6", "3"}, {"1.1", "2,5", "5/2"}, {"0.7", "-3,2", "-2/3"}, {"2.2", "1,-5/2", "-5/2"}}) {
    const auto events = nlohmann::json::parse(run("chain boundaries --twists " + twist1 + ",1 --rates " + rates + " --vary A2:0:pi --json", dir).out);
    const auto train = nlohmann::json::parse(run("boundaries --n " + n + " --a2 " + twist1 + " --json", dir).out);
    REQUIRE(events["events"].size() == train["events"].size());
    REQUIRE(!events["events"].empty());
    for (std::size_t i = 0; i < events["events"].size(); ++i) {
      const auto& e = events["events"][i];
      CHECK(e["value"] == train["events"][i]["a3"]);
      const double v = e["value"].get<double>();
      bool isolated = true;
      for (const auto& other : events["events"])
        if (&other != &e && std::fabs(other["value"].get<double>() - v) < 1e-3) isolated = false;
      if (!isolated || e["kind"] == "pole") continue;
      for (const auto& [side, key] : {std::pair{-1e-5, "nodes_below"}, std::pair{1e-5, "nodes_above"}}) {
        const auto c = nlohmann::json::parse(
            run("chain classify --twists " + twist1 + "," + shortest_g(v + side) + " --rates " + rates + " --json", dir).out);
        INFO(twist1 << " " << rates << " A2 = " << shortest_g(v + side));
        CHECK(c["certified"] == true);
        CHECK(c["counts"]["nodes"] == e[key]);
      }
    }
  }
  // Phases: no event; the census is the same at any P1 (and at any P2 of two stages).
  const auto none = nlohmann::json::parse(run("chain boundaries --twists 1,2,0.5 --rates 1,2/3,-1 --vary P1:0:6 --json", dir).out);
  CHECK(none["events"].empty());
  CHECK(!none["note"].get<std::string>().empty());
  const auto counts = [&](const std::string& chain) { return nlohmann::json::parse(run("chain classify " + chain + " --json", dir).out)["counts"]; };
  CHECK(counts("--twists 1,2,0.5 --rates 1,2/3,-1 --phases 0,0.3,0") == counts("--twists 1,2,0.5 --rates 1,2/3,-1 --phases 2.5,0.3,0"));
  CHECK(counts("--twists 1,2 --rates 2,5 --phases 0,0") == counts("--twists 1,2 --rates 2,5 --phases 0,1.7"));
  // Bad ranges: exit 2 naming --vary.
  for (const std::string& vary : std::vector<std::string>{"A2:0:1e-7", "P2:0:7", "P2:1000:1006", "A+2:0:1", "A02:0:1", "X1:0:1", "A4:0:1", "A1:1:0", "A1:0:4", "A1:0", "P1:0:nan"}) {
    const std::string chain = vary == "A1:1:0" || vary == "A1:0:4" || vary == "A1:0" ? "--twists 1,2 --rates 1,2" : "--twists 1,2,3 --rates 1,2,3";
    const Result r = run("chain boundaries " + chain + " --vary " + vary, dir, true);
    INFO(vary << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, "--vary"));
  }
}

TEST_CASE("chain boundaries: A2 of two stages with a first twist of 0 or pi (coaxial joints) has no event", "[cli][chain]") {
  TempDir dir;
  // Rz(a) Rx(0) Rz(b) Rx(A2) z = Rz(a + b) Rx(A2) z (Rx(pi): Rz(a - b + pi) Rx(pi - A2) z): a circle
  // for every A2, no node and no cusp (while N1 +- N2 is not 0). Expected: no event, certified.
  for (const std::string& chain : {"--twists 0,1 --rates 1,2", "--twists pi,1 --rates 1,3", "--twists 0,1 --rates 2,-5/3"}) {
    const Result r = run("chain boundaries " + chain + " --vary A2:0.3:2.8 --json", dir, true);
    INFO(chain << " -> " << r.err);
    REQUIRE(r.status == 0);
    const auto e = nlohmann::json::parse(r.out);
    CHECK(e["certified"] == true);
    CHECK(e["events"].empty());
  }
  // N1 + N2 = 0 with coaxial joints: the tool axis does not move; refused naming --twists.
  const Result still = run("chain boundaries --twists 0,1 --rates 1,-1 --vary A2:0.3:2.8", dir, true);
  CHECK(still.status == 2);
  CHECK(still.out.empty());
  CHECK(contains(still.err, "--twists"));
}

namespace {

/// The events of `chain boundaries --twists TWISTS ... --json`, required to exit 0 and be certified.
nlohmann::json checked_events(const std::string& twists, const std::string& rates, const std::string& vary, const TempDir& dir) {
  const std::string chain = " --twists " + twists + " --rates " + rates;
  const Result r = run("chain boundaries" + chain + " --vary " + vary + " --json", dir);
  INFO(chain << " --vary " << vary << ": " << r.err);
  REQUIRE(r.status == 0);
  const auto events = nlohmann::json::parse(r.out);
  CHECK(events["certified"] == true);
  return events;
}

/// The twists with the varied one (between `before` and `after`, either may be empty) at x.
std::string twists_with(const std::string& before, double x, const std::string& after) {
  return before + (before.empty() ? "" : ",") + shortest_g(x) + (after.empty() ? "" : ",") + after;
}

/// chain classify's node count with the varied twist (between `before` and `after`) set to x.
int nodes_at(const std::string& before, double x, const std::string& after, const std::string& rates, const TempDir& dir) {
  const std::string twists = twists_with(before, x, after);
  const auto c = nlohmann::json::parse(run("chain classify --twists " + twists + " --rates " + rates + " --json", dir).out);
  INFO(twists << " " << rates);
  CHECK(c["certified"] == true);
  return c["counts"]["nodes"].get<int>();
}

}  // namespace

TEST_CASE("chain boundaries (slab search): a gear train inside a longer chain has the train's events", "[cli][chain]") {
  TempDir dir;
  // Twists a2, A2, 0: the last joint turns the tool about itself, so the chain is the gear train
  // a2, n = N2 / N1 with a3 = A2, but its A2 family goes through the slab search (three stages).
  // Expected: `boundaries` (closed forms and the root function's scan, another method): the same
  // events, kinds pitch_cone -> cusp, pole -> triple_point, each a certified root of its square
  // system with the closed form (or the scan's value, to 1e-12) within its accuracy.
  for (const auto& [a2, rates, n] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"1.1", "1,3,5", "3"}, {"0.8", "2,-3,1", "-3/2"}}) {
    const auto chain = nlohmann::json::parse(run("chain boundaries --twists " + a2 + ",1,0 --rates " + rates + " --vary A2:0.05:3.1 --json", dir).out);
    const auto train = nlohmann::json::parse(run("boundaries --n " + n + " --a2 " + a2 + " --json", dir).out);
    INFO(a2 << " " << rates);
    CHECK(chain["certified"] == true);
    std::vector<nlohmann::json> expected;
    for (const auto& e : train["events"])
      if (e["a3"].get<double>() >= 0.05 && e["a3"].get<double>() <= 3.1) expected.push_back(e);
    REQUIRE(chain["events"].size() == expected.size());
    const double accuracy = chain["accuracy"].get<double>();
    CHECK(accuracy < 1e-12);
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const auto& e = chain["events"][i];
      const std::string kind = expected[i]["kind"];
      CHECK(e["kind"] == (kind == "pitch_cone" ? "cusp" : kind == "pole" ? "triple_point" : "tangency"));
      CHECK(e["root"]["certified"] == true);
      CHECK(std::fabs(e["value"].get<double>() - expected[i]["a3"].get<double>()) <= e["accuracy"].get<double>() + 1e-12);
      CHECK(e["nodes_below"] == expected[i]["nodes_below"]);
      CHECK(e["nodes_above"] == expected[i]["nodes_above"]);
    }
  }
}

TEST_CASE("chain boundaries (slab search): three stages and A1 of two with counts either side as chain classify's", "[cli][chain]") {
  TempDir dir;
  // A3 of a three-stage chain (cusp births and self-tangencies), A1 of a two-stage one; each
  // event away from the others: chain classify (the census at one value) just below and above.
  struct Family {
    std::string before, after, rates, vary;
    double lo, hi;
  };
  for (const Family& f : {Family{"1.2,0.9", "", "1,2,-3", "A3:0.8:0.95", 0.8, 0.95}, Family{"", "1", "1,3", "A1:0.3:1.2", 0.3, 1.2},
                          Family{"", "0.6", "2,-5", "A1:0.2:1.4", 0.2, 1.4}}) {
    const auto events = checked_events(twists_with(f.before, 0.5 * (f.lo + f.hi), f.after), f.rates, f.vary, dir);
    INFO(f.before << " | " << f.after << " " << f.rates << " " << f.vary);
    CHECK(!events["events"].empty());
    std::size_t roots = 0;
    for (const auto& e : events["events"]) {
      const double v = e["value"].get<double>();
      // The value inside the bracket where the census changes (a cusp birth's is the band where
      // the census reports a cusp); a certified root's accuracy its enclosure's width, else the
      // bracket's half-width (a degenerate event: at this mirror-symmetric chain, A3 ~ 0.94254,
      // three crossings of the same two branches are born at once, a tangency of third order).
      const double lo = e["bracket"][0].get<double>(), hi = e["bracket"][1].get<double>();
      CHECK(v >= lo);
      CHECK(v <= hi);
      if (e["root"]["certified"] == true) {
        ++roots;
        CHECK(e["accuracy"].get<double>() < 1e-12);
      } else {
        CHECK(e["accuracy"].get<double>() == Approx(0.5 * (hi - lo)).epsilon(1e-6));
      }
      bool isolated = e["kind"] != "triple_point";
      for (const auto& other : events["events"])
        if (&other != &e && std::fabs(other["value"].get<double>() - v) < 1e-3) isolated = false;
      if (!isolated) continue;
      // The counts outside the bracket.
      const double below = lo - 1e-6, above = hi + 1e-6;
      CHECK(nodes_at(f.before, below, f.after, f.rates, dir) == e["nodes_below"].get<int>());
      CHECK(nodes_at(f.before, above, f.after, f.rates, dir) == e["nodes_above"].get<int>());
    }
    CHECK(roots + 1 >= events["events"].size());
    // Between consecutive events the count is constant: the middles agree with the events' sides.
    for (std::size_t i = 0; i + 1 < events["events"].size(); ++i) {
      const double middle = 0.5 * (events["events"][i]["value"].get<double>() + events["events"][i + 1]["value"].get<double>());
      CHECK(nodes_at(f.before, middle, f.after, f.rates, dir) == events["events"][i]["nodes_above"].get<int>());
    }
    CHECK(nodes_at(f.before, f.lo, f.after, f.rates, dir) == events["events"].front()["nodes_below"].get<int>());
    CHECK(nodes_at(f.before, f.hi, f.after, f.rates, dir) == events["events"].back()["nodes_above"].get<int>());
  }
}

TEST_CASE("chain boundaries (slab search): what it cannot certify exits 3 and what it cannot afford is refused", "[cli][chain]") {
  TempDir dir;
  // A range ending inside the band below a cusp birth (A3 ~ 1.00182) where no census holds over
  // a slab and none changes: not an event, and not certified either (exit 3 after the report).
  const Result quiet = run("chain boundaries --twists 1.2,0.9,0.7 --rates 1,2,-3 --vary A3:0.95:1", dir, true);
  CHECK(quiet.status == 3);
  CHECK(contains(quiet.out, "NOT CERTIFIED"));
  CHECK(count_lines(quiet.err) == 1);
  // Range ends inside the band of the cusp birth at A3 ~ 0.8212428 (where chain classify reports a
  // cusp) or at the self-tangency at A3 ~ 0.93774398878320 (two branches touching): the census at
  // that end gives the counts of neither side; exit 3 naming the band, with or without events.
  for (const std::string& vary : {"A3:0.8212430293:0.8212430294", "A3:0.8212427:0.8212429", "A3:0.8212430293:0.85"}) {
    const std::string end = vary.substr(3, vary.find(':', 3) - 3);
    const auto at = nlohmann::json::parse(run("chain classify --twists 1.2,0.9," + end + " --rates 1,2,-3 --json", dir).out);
    CHECK(at["counts"]["cusps"].get<int>() >= 1);
    const Result r = run("chain boundaries --twists 1.2,0.9,0.7 --rates 1,2,-3 --vary " + vary, dir, true);
    INFO(vary << " -> " << r.err);
    CHECK(r.status == 3);
    CHECK(contains(r.err, "resolution band"));
  }
  // A chain whose census cuts 38956 arcs: refused up front, naming --rates.
  const Result costly = run("chain boundaries --twists 1,2 --rates 1,97/89 --vary A1:0.5:1.5", dir, true);
  CHECK(costly.status == 2);
  CHECK(costly.out.empty());
  CHECK(contains(costly.err, "--rates"));
}

TEST_CASE("output suffixes: -o writes the format its suffix names or refuses it (chain trace and trace and clinostat --trace)", "[cli][chain]") {
  TempDir dir;
  for (const std::string& args : {std::string("chain trace --twists 1,2,0.5 --rates 1,2,-1 -o wrist.step"),
                                  std::string("chain trace --twists 1,2,0.5 --rates 1,2,-1 -o wrist.STL"),
                                  std::string("trace --a2 1 --a3 2 --n 2 -o path.stl"), std::string("trace --a2 1 --a3 2 --n 2 -o path.json"),
                                  std::string("clinostat --outer 1 --inner 2 --trace --duration 10 -o g.png"),
                                  std::string("classify --a2 1 --a3 2 --n 2 -o report.npy"),
                                  std::string("chain classify --twists 1,2,0.5 --rates 1,2,-1 -o report.pdf")}) {
    const Result r = run(args, dir, true);
    INFO(args << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, "output"));
    CHECK(dir.entries().empty());
  }
  // What the suffix names is written: CSV for .csv and for a name without a format's suffix.
  CHECK(run("chain trace --twists 1,2,0.5 --rates 1,2,-1 --samples 10 -o wrist.csv", dir, true).status == 0);
  CHECK(slurp(dir.path / "wrist.csv").rfind("t,x,y,z\n", 0) == 0);
  CHECK(run("chain trace --twists 1,2,0.5 --rates 1,2,-1 --samples 10 -o wrist.out", dir, true).status == 0);
  CHECK(slurp(dir.path / "wrist.out").rfind("t,x,y,z\n", 0) == 0);
}

TEST_CASE("chain: the near-coaxial chain of the hostile run has its 25 distinct crossings, certified", "[cli][chain]") {
  // twists 1, 1e-8, 1 with rates 1, 2, 3: 25 crossings at least 7.3e-9 apart near the pole. The
  // count is the exact crossings of a polyline of the same chain with a middle twist of 1e-5
  // (test_chain: no event between), written here as the test's own expectation.
  TempDir dir;
  const Result r = run("chain classify --twists 1,1e-8,1 --rates 1,2,3 --json", dir);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["certified"].get<bool>());
  CHECK(j["counts"]["nodes"].get<int>() == 25);
  for (const auto& n : j["nodes"]) CHECK(n["branches"].get<int>() == 2);
}

TEST_CASE("chain boundaries: a phase range beyond [-4 pi, 4 pi] is refused for every family, closed forms too", "[cli][chain]") {
  TempDir dir;
  const Result r = run("chain boundaries --twists 1,2 --rates 1,3 --vary P1:-100:100", dir);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  CHECK(contains(r.err, "--vary"));
}

TEST_CASE("classify and chain classify refuse up front a carrier twist near 0 with a large denominator, naming the cost", "[cli][chain]") {
  // a2 = 0.01, n = 1/1908: the curve winds 1909 times within 0.02 rad of one circle, ~1e9 close
  // edge pairs for the polyline census (it ran for more than five minutes).
  TempDir dir;
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"classify --a2 0.01 --a3 1 --n 1/1908", "--a2"}, {"chain classify --twists 0.01,1 --rates 1,1/1908", "--twists"}}) {
    const Result r = run(args, dir);
    INFO(args << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, option));
    CHECK(contains(r.err, "1909 times"));
  }
}
