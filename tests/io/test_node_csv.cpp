// Tests of sphtroch/io/node_csv.hpp: the nodes, screw-axis and edge-pair tables, read back with an
// independent parser here (split on ',', std::strtod) and compared with the values written.
#include "catch2/catch.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

#include "sphtroch/io/node_csv.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) f.push_back(cell);
  return f;
}

std::vector<std::vector<std::string>> table(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line)) rows.push_back(split(line));
  return rows;
}

double num(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  REQUIRE(end == s.c_str() + s.size());  // the whole field is the number
  return v;
}

// Values chosen to need all 17 digits, a subnormal and a negative zero: a format that rounds
// or drops the sign fails the exact comparisons below.
const double kThird = 1.0 / 3.0;
const double kTiny = std::numeric_limits<double>::denorm_min();

Node two_branch_node() {
  Node n;
  n.position = Vector3d(kThird, -0.0, std::sqrt(1.0 - kThird * kThird));
  n.params = {0.1, 2.0 / 3.0, 5.5};
  n.branches = 3;
  n.kind = NodeKind::tangency;
  return n;
}

Node one_branch_node() {  // degenerate input: a node with one parameter repeats it as t2
  Node n;
  n.position = Vector3d(0, 0, 1);
  n.params = {kTiny};
  n.branches = 1;
  n.kind = NodeKind::crossing;
  return n;
}

}  // namespace

TEST_CASE("nodes csv: header, node rows then cusp rows, numbers round-trip exactly") {
  Cusp k;
  k.position = Vector3d(-1e-300, 0.5, -0.75);
  k.param = 3.0 * kThird;
  std::ostringstream out;
  write_nodes_csv(out, {two_branch_node(), one_branch_node()}, {k});
  const auto rows = table(out.str());
  REQUIRE(rows.size() == 1 + 2 + 1);
  CHECK(rows[0] == std::vector<std::string>{"kind", "x", "y", "z", "t1", "t2", "branches", "id"});
  for (const auto& r : rows) CHECK(r.size() == 8);
  CHECK(rows[1][7] == "N1");  // the plot's labels: nodes N1, N2, ..., cusps C1, ...
  CHECK(rows[2][7] == "N2");
  CHECK(rows[3][7] == "C1");

  CHECK(rows[1][0] == "tangency");
  CHECK(num(rows[1][1]) == kThird);
  CHECK(num(rows[1][2]) == 0.0);
  CHECK(std::signbit(num(rows[1][2])));  // -0 keeps its sign
  CHECK(num(rows[1][3]) == std::sqrt(1.0 - kThird * kThird));
  CHECK(num(rows[1][4]) == 0.1);
  CHECK(num(rows[1][5]) == 2.0 / 3.0);  // the second branch, not the third
  CHECK(rows[1][6] == "3");

  CHECK(rows[2][0] == "crossing");
  CHECK(num(rows[2][4]) == kTiny);
  CHECK(num(rows[2][5]) == kTiny);  // t2 = t1 with one branch
  CHECK(rows[2][6] == "1");

  CHECK(rows[3][0] == "cusp");
  CHECK(num(rows[3][1]) == -1e-300);
  CHECK(num(rows[3][4]) == k.param);
  CHECK(num(rows[3][5]) == k.param);
  CHECK(rows[3][6] == "1");
  CHECK(out.str().back() == '\n');
}

TEST_CASE("nodes csv: nothing found is the header alone") {
  std::ostringstream out;
  write_nodes_csv(out, {}, {});
  CHECK(out.str() == std::string(kNodesCsvHeader) + "\n");
}

TEST_CASE("screw axis csv: one row per parameter, t,wx,wy,wz") {
  const std::vector<double> t = {0.0, kThird, 1e-17};
  const std::vector<Vector3d> w = {Vector3d(1, 2, 3), Vector3d(-kThird, 0.1, 1e300), Vector3d(0, 0, -0.0)};
  std::ostringstream out;
  write_screw_axis_csv(out, t, w);
  const auto rows = table(out.str());
  REQUIRE(rows.size() == 4);
  CHECK(rows[0] == std::vector<std::string>{"t", "wx", "wy", "wz"});
  for (std::size_t i = 0; i < t.size(); ++i) {
    REQUIRE(rows[i + 1].size() == 4);
    CHECK(num(rows[i + 1][0]) == t[i]);
    for (int c = 0; c < 3; ++c) CHECK(num(rows[i + 1][c + 1]) == w[i][c]);
  }
}

namespace pairs_test {
enum class Kind { crossing, touching };
const char* to_string(Kind k) { return k == Kind::crossing ? "crossing" : "touching"; }
struct Pair {
  std::size_t i = 0, j = 0;
  Kind kind = Kind::crossing;
};
}  // namespace pairs_test

TEST_CASE("edge pairs csv: crossings and touchings merged in (i, j) order, kinds by name") {
  using pairs_test::Kind;
  using pairs_test::Pair;
  const std::vector<Pair> crossings = {{2, 9, Kind::crossing}, {0, 5, Kind::crossing}, {18446744073709551615u, 1, Kind::crossing}};
  const std::vector<Pair> touchings = {{2, 4, Kind::touching}, {0, 7, Kind::touching}};
  test::TempDir dir;
  const std::string path = (dir.path / "pairs.csv").string();
  OutputFile file = OutputFile::open(path, "pairs");
  write_edge_pairs_csv(file, crossings, touchings);
  file.commit();
  const auto rows = table(test::slurp(path));
  REQUIRE(rows.size() == 6);
  CHECK(rows[0] == std::vector<std::string>{"i", "j", "kind"});
  const std::vector<std::vector<std::string>> expected = {{"0", "5", "crossing"},
                                                          {"0", "7", "touching"},
                                                          {"2", "4", "touching"},
                                                          {"2", "9", "crossing"},
                                                          {"18446744073709551615", "1", "crossing"}};
  for (std::size_t r = 0; r < expected.size(); ++r) CHECK(rows[r + 1] == expected[r]);
}
