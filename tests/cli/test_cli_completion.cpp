// Tests of `sphtroch completion bash|zsh`. Expected values: the tool's --help texts of each command
// (CLI11's own listing of its subcommands and options), parsed here; the script is sourced by bash
// and asked to complete as a user's shell would (COMP_WORDS, COMP_CWORD, then _sphtroch).
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace sphtroch::test;

namespace {

/// The words of a --help text's section ("Subcommands:" names, "Options:" --long names).
std::set<std::string> help_words(const std::string& help, const std::string& section) {
  std::set<std::string> out;
  std::istringstream in(help);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind(section, 0) == 0) {
      inside = true;
      continue;
    }
    if (inside && (line.empty() || line[0] != ' ')) inside = !line.empty() && line.back() != ':' && inside;
    if (!inside || line.size() < 3 || line[0] != ' ') continue;
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (section == "Subcommands:") {
      out.insert(first);
    } else {
      std::istringstream names(first);  // "-h,--help" or "--a2"
      std::string name;
      while (std::getline(names, name, ','))
        if (name.rfind("--", 0) == 0) out.insert(name);
    }
  }
  return out;
}

/// What bash completes after `sphtroch <typed>` (the last word being completed, maybe empty).
std::set<std::string> completions(const TempDir& dir, const std::vector<std::string>& typed) {
  std::string words = "sphtroch";
  for (const std::string& w : typed) words += " '" + w + "'";
  const Result r = shell("source ./completion.bash\nCOMP_WORDS=(" + words + ")\nCOMP_CWORD=" + std::to_string(typed.size()) +
                             "\n_sphtroch\nprintf '%s\\n' \"${COMPREPLY[@]}\"",
                         dir);
  REQUIRE(r.status == 0);
  std::set<std::string> out;
  std::istringstream in(r.out);
  for (std::string w; std::getline(in, w);)
    if (!w.empty()) out.insert(w);
  return out;
}

}  // namespace

TEST_CASE("cli completion bash: every command and option of the registry, as --help lists them", "[cli][completion]") {
  TempDir dir;
  REQUIRE(run("completion bash -o x", dir, true).status == 2);  // no such option
  const Result script = run("completion bash", dir, true);
  REQUIRE(script.status == 0);
  { std::ofstream(dir.path / "completion.bash") << script.out; }
  const std::set<std::string> top = help_words(run("--help", dir).out, "Subcommands:");
  REQUIRE(top.count("trace") == 1);
  REQUIRE(top.count("completion") == 1);
  CHECK(completions(dir, {""}) == [&] { auto s = top; s.insert({"--help", "--version"}); return s; }());
  for (const std::string& command : top) {
    INFO("command " << command);
    const std::string help = run(command + " --help", dir).out;
    std::set<std::string> want = help_words(help, "Options:");
    for (const std::string& sub : help_words(help, "Subcommands:")) {
      want.insert(sub);
      INFO("subcommand " << sub);
      CHECK(completions(dir, {command, sub, "--"}) == help_words(run(command + " " + sub + " --help", dir).out, "Options:"));
    }
    CHECK(completions(dir, {command, ""}) == want);
  }
  // A prefix narrows; values and files are the shell's (no word offered).
  CHECK(completions(dir, {"tr"}) == std::set<std::string>{"trace"});
  CHECK(completions(dir, {"tolerance", "--tol-"}) == std::set<std::string>{"--tol-a2", "--tol-a3", "--tol-phase"});
}

TEST_CASE("cli completion zsh: the same script behind bashcompinit, another shell is refused", "[cli][completion][errors]") {
  TempDir dir;
  const Result zsh = run("completion zsh", dir), bash = run("completion bash", dir);
  REQUIRE(zsh.status == 0);
  CHECK(zsh.out.find("autoload -U +X bashcompinit && bashcompinit\n") != std::string::npos);
  CHECK(zsh.out.size() > bash.out.size());
  CHECK(zsh.out.compare(zsh.out.size() - bash.out.size(), bash.out.size(), bash.out) == 0);
  const Result fish = run("completion fish", dir);
  CHECK(fish.status == 2);
  CHECK(fish.out.empty());
  CHECK(count_lines(fish.err) == 1);
  CHECK(fish.err.find("fish") != std::string::npos);
}
