// Every command's --help, run as the real executable: the commands found from `sphtroch --help`
// down through each "Subcommands:" list; no option shows CLI11's generic type names (TEXT, INT,
// UINT, FLOAT): each names its unit or form (RPM, DEG, RAD, P/Q, S, FILE, N, LO:HI, ...).
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <algorithm>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace sphtroch::test;

/// The names listed under "Subcommands:" of a help text (two spaces, the name, spaces, the line).
std::vector<std::string> subcommands(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream in(help);
  bool listing = false;
  for (std::string line; std::getline(in, line);) {
    if (line == "Subcommands:") {
      listing = true;
    } else if (listing && line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ') {
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
    } else if (listing && line.empty()) {
      listing = false;
    }
  }
  return names;
}

}  // namespace

TEST_CASE("cli --help of every command: every option names its unit or form and none shows TEXT", "[cli][help]") {
  TempDir dir;
  const std::regex generic(R"(\b(TEXT|INT|UINT|FLOAT|NUMBER)\b)");
  std::vector<std::string> commands = {""}, seen;
  while (!commands.empty()) {
    const std::string command = commands.back();
    commands.pop_back();
    seen.push_back(command);
    const Result r = run(command + " --help", dir);
    INFO("sphtroch " << command << " --help");
    REQUIRE(r.status == 0);
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
      INFO(line);
      CHECK_FALSE(std::regex_search(line, generic));
    }
    for (const std::string& name : subcommands(r.out)) commands.push_back(command.empty() ? name : command + " " + name);
  }
  // The walk reached the nested commands (and so every level of the tree).
  for (const char* nested : {"trace", "synth fit", "synth points", "synth merge", "clinostat design", "clinostat merge",
                             "chain classify", "chain export", "completion"})
    CHECK(std::find(seen.begin(), seen.end(), std::string(nested)) != seen.end());
  CHECK(seen.size() >= 25);
}
