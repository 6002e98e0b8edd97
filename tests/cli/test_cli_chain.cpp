// `sphtroch chain trace`, run as the real executable: for k = 2 (rates 1,n, phases 0,theta_p)
// the bytes of `sphtroch trace` on random trains, with and without --velocity --kinematics; for
// k = 3, 4 every row against a product of Eigen AngleAxis rotations in long double written here
// from the model; the period and the default count from the rates; bad input (exit 2, one line
// naming the option, nothing on stdout, no file).
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
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

TEST_CASE("chain trace, k = 2: the bytes of sphtroch trace", "[cli][chain]") {
  TempDir dir;
  std::mt19937 rng(2045);
  std::uniform_real_distribution<double> angle(0.01, 3.13), phase(0, 6.28);
  std::uniform_int_distribution<int> num(-7, 7), den(1, 7);
  for (int trial = 0; trial < 200; ++trial) {
    const double a2 = angle(rng), a3 = angle(rng), ph = phase(rng);
    const int p = num(rng), q = den(rng);
    if (p == 0) continue;
    const std::string n = std::to_string(p) + "/" + std::to_string(q), extra = trial % 3 == 0 ? " --velocity --kinematics" : "";
    const Result chain = run("chain trace --twists " + shortest_g(a2) + "," + shortest_g(a3) + " --rates 1," + n + " --phases 0," + shortest_g(ph) + extra, dir);
    const Result trace = run("trace --a2 " + shortest_g(a2) + " --a3 " + shortest_g(a3) + " --n " + n + " --phase " + shortest_g(ph) + extra, dir);
    REQUIRE(chain.status == 0);
    REQUIRE(trace.status == 0);
    INFO("a2 " << shortest_g(a2) << " a3 " << shortest_g(a3) << " n " << n << " phase " << shortest_g(ph));
    CHECK(chain.out == trace.out);
  }
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
           {"--twists 1,2 --rates 1,2 --phases 0,inf", "--phases"}, {"--twists 1,2 --rates 1,999999/1000000 -o out.csv", "--rates"},
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
