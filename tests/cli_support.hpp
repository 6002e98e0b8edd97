// tests/cli_support.hpp — running the `sphtroch` executable from a Catch2 test: a fresh
// directory per test case, the exit status and both output streams captured.
// REQUIRES: SPHTROCH_EXE (the executable's path) defined by CMake. The environment variable
// SPHTROCH_TEST_EXE, when set, names another build of the tool to run instead: CI runs this
// suite, built once in Release, against the sanitizer build's tool (.ci/run).
#pragma once

#include "catch2/catch.hpp"

#include <sys/wait.h>
#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sphtroch::test {

namespace fs = std::filesystem;

struct Result {
  int status = -1;
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh directory per test case, removed at the end.
struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "sphtroch-test-XXXXXX").string();
    std::vector<char> buf(tmpl.begin(), tmpl.end());
    buf.push_back('\0');
    REQUIRE(mkdtemp(buf.data()) != nullptr);
    path = buf.data();
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  /// Every entry (relative path, recursively) except the capture files.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(path)) {
      const std::string name = e.path().filename().string();
      if (name != "stdout.txt" && name != "stderr.txt") names.push_back(fs::relative(e.path(), path).string());
    }
    return names;
  }
};

/// Runs `command` through the shell with stdout and stderr redirected to the files `out` and
/// `err`; returns the exit status (-1 if it did not exit) and both texts, the files removed.
inline Result capture(const std::string& command, const fs::path& out, const fs::path& err) {
  const std::string cmd = command + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  Result r;
  r.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

/// The executable under test: $SPHTROCH_TEST_EXE when set and not empty, else SPHTROCH_EXE.
inline const std::string& tool_path() {
  static const std::string path = [] {
    const char* env = std::getenv("SPHTROCH_TEST_EXE");
    return std::string(env != nullptr && *env != '\0' ? env : SPHTROCH_EXE);
  }();
  return path;
}

/// tool_path() shell-quoted (single quotes), for command lines.
inline std::string quoted_tool() { return "'" + tool_path() + "'"; }

/// Whether the tool under test was built with AddressSanitizer (its dynamic symbols name
/// __asan_init): its shadow memory alone exceeds any data or address-space limit, so the tests
/// of memory bounds leave those limits out for it (the Release run checks them).
inline bool tool_has_address_sanitizer() {
  static const bool has = [] {
    const std::string bytes = slurp(tool_path());
    return bytes.find("__asan_init") != std::string::npos;
  }();
  return has;
}

/// Whether the tool under test has an optional component, as its --version line says ("step
/// yes", "png yes", ...): a sanitizer build of the tool has neither STEP nor PNG, whatever the
/// build of this suite has.
inline bool tool_has_component(const std::string& name) {
  static const std::string version = [] {
    std::string out;
    if (FILE* p = popen((quoted_tool() + " --version 2>/dev/null").c_str(), "r")) {
      char buf[512];
      while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
      pclose(p);
    }
    return out;
  }();
  return version.find(name + " yes") != std::string::npos;
}

/// Runs `sphtroch <args>` through the shell (args already shell-quoted where needed), capturing
/// stdout, stderr and the exit status in files of `dir`. With `in_dir`, runs inside `dir` so that
/// relative paths land there.
inline Result run(const std::string& args, const TempDir& dir, bool in_dir = false) {
  const fs::path out = dir.path / "stdout.txt", err = dir.path / "stderr.txt";
  const std::string cd = in_dir ? "cd '" + dir.path.string() + "' && " : std::string();
  return capture(cd + quoted_tool() + " " + args, out, err);
}

/// Runs a bash command line (with pipefail) inside `dir`, for pipes and redirections around the
/// tool; captures stdout, stderr and the exit status as run() does.
inline Result shell(const std::string& line, const TempDir& dir) {
  const fs::path out = dir.path / "stdout.txt", err = dir.path / "stderr.txt", script = dir.path / "cmd.sh";
  std::ofstream(script) << "set -o pipefail\ncd '" << dir.path.string() << "'\n" << line << "\n";
  const Result r = capture("bash '" + script.string() + "'", out, err);
  fs::remove(script);
  return r;
}

inline std::size_t count_lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

/// The shortest "%.*g" form (1 to 17 digits) that reads back as v: how the tool prints numbers,
/// computed here with printf/strtod, independently of the tool's std::to_chars.
inline std::string shortest_g(double v) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

/// A field printed in the shortest round-trip form: it parses whole, and with one significant
/// digit fewer the value would be lost. (The exponent spelling may differ from printf's.)
inline bool is_shortest_round_trip(const std::string& field) {
  char* end = nullptr;
  const double v = std::strtod(field.c_str(), &end);
  if (field.empty() || end != field.c_str() + field.size()) return false;
  std::string digits;
  for (char c : field.substr(0, field.find('e')))
    if (c >= '0' && c <= '9') digits += c;
  digits.erase(0, digits.find_first_not_of('0'));
  if (digits.find_last_not_of('0') != std::string::npos) digits.erase(digits.find_last_not_of('0') + 1);
  if (digits.size() < 2) return true;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", static_cast<int>(digits.size() - 1), v);
  return std::strtod(buf, nullptr) != v;
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace sphtroch::test
