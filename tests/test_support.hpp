// tests/test_support.hpp — small helpers shared by the Catch2 tests.
#pragma once

#include "catch2/catch.hpp"
#include "sphtroch/core/errors.hpp"

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sphtroch::test {

/// The lines of `text`, without their '\n'.
inline std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line)) out.push_back(line);
  return out;
}

/// Runs f, expects sphtroch::InvalidInput, and returns it for inspection (fails the test otherwise).
template <typename F>
InvalidInput expect_invalid(F&& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e;
  }
  FAIL("no InvalidInput thrown");
  return InvalidInput("", "", "", "");
}

#ifdef SPHTROCH_REFERENCE_DIR
/// One row of data/reference/paper_cases.csv: a case the report states outright.
struct PaperCase {
  std::string id;
  std::int64_t n_num = 1, n_den = 1;
  std::string a2_symbolic, a3_symbolic;  // as the report writes them ("pi/2", "a_p", ...)
  double a2 = 0, a3 = 0;  // radians, as the CSV gives them
  std::size_t nodes = 0, cusps = 0;
};

inline std::vector<PaperCase> paper_cases() {
  std::ifstream in(std::string(SPHTROCH_REFERENCE_DIR) + "/paper_cases.csv");
  REQUIRE(in.good());
  std::string line;
  std::getline(in, line);
  REQUIRE(line.rfind("id,n_num,n_den,a2_symbolic,a3_symbolic,a2_rad,a3_rad,nodes,cusps", 0) == 0);
  std::vector<PaperCase> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    // The first nine fields hold no commas or quotes; the tenth (source) is quoted free text.
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    for (int i = 0; i < 9 && std::getline(ss, cell, ','); ++i) f.push_back(cell);
    REQUIRE(f.size() == 9);
    rows.push_back(PaperCase{f[0], std::stoll(f[1]), std::stoll(f[2]), f[3], f[4], std::stod(f[5]), std::stod(f[6]),
                             static_cast<std::size_t>(std::stoul(f[7])), static_cast<std::size_t>(std::stoul(f[8]))});
  }
  REQUIRE(rows.size() >= 10);
  return rows;
}
#endif

}  // namespace sphtroch::test
