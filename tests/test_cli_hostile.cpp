// Hostile input (issue 10): each test is named after the hazard it guards against. Every bad
// input exits 2 with one line on stderr, nothing on stdout, and no file lost or replaced; legal
// inputs that would run away are refused up front; legal inputs get the right answer.
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <fstream>

using namespace sphtroch::test;
namespace fs = std::filesystem;

namespace {

const std::string kExe = std::string("'") + SPHTROCH_EXE + "'";


/// Exit 2, nothing on stdout, exactly one line on stderr containing `part`.
void check_refused(const Result& r, const std::string& part) {
  INFO("stderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(!r.err.empty());
  CHECK(r.err.find('\n') == r.err.size() - 1);
  CHECK(contains(r.err, part));
}

void write_file(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

const std::string kTrain = R"("name":"a","a2":"1","a3":"1","n":"2")";

}  // namespace

TEST_CASE("hostile: scene_deep_nesting is refused (no stack overflow)", "[cli][hostile][scene]") {
  TempDir dir;
  std::string nested;
  for (int i = 0; i < 100000; ++i) nested += "{\"x\":";
  nested += "1";
  nested += std::string(100000, '}');
  write_file(dir.path / "d.json", "{\"trains\":[{\"name\":\"a\",\"a2\":" + nested +
                                      ",\"a3\":\"1\",\"n\":\"2\",\"effects\":{\"trace\":\"o.csv\"}}]}");
  check_refused(shell(kExe + " scene d.json", dir), "nested deeper than 16 levels");
  CHECK_FALSE(fs::exists(dir.path / "o.csv"));
}

TEST_CASE("hostile: scene_output_aliases_the_scene_file through a symlinked directory", "[cli][hostile][scene]") {
  TempDir dir;
  fs::create_directory(dir.path / "real");
  fs::create_directory_symlink(dir.path / "real", dir.path / "out");
  const std::string scene = "{\"trains\":[{" + kTrain + ",\"effects\":{\"trace\":\"out/../scene.json\"}}]}";
  // The kernel resolves out -> real, then ".." -> the parent of real: out/../scene.json IS the
  // scene file, although the strings differ.
  write_file(dir.path / "scene.json", scene);
  check_refused(shell(kExe + " scene scene.json", dir), "the scene file itself");
  CHECK(slurp(dir.path / "scene.json") == scene);
  // A hard link to the scene is the same file too.
  fs::create_hard_link(dir.path / "scene.json", dir.path / "alias.json");
  write_file(dir.path / "s2.json", "{\"trains\":[{" + kTrain + ",\"effects\":{\"trace\":\"s2.json\"}}]}");
  check_refused(shell(kExe + " scene s2.json", dir), "the scene file itself");
}

TEST_CASE("hostile: scene_trailing_garbage and NUL bytes are not valid JSON", "[cli][hostile][scene]") {
  TempDir dir;
  const std::string ok = "{\"trains\":[{" + kTrain + ",\"effects\":{\"trace\":\"o.csv\"}}]}";
  write_file(dir.path / "g1.json", ok + " xyz");
  write_file(dir.path / "g2.json", ok + "}");
  write_file(dir.path / "g3.json", ok + std::string("\n\0", 2));
  for (const char* f : {"g1.json", "g2.json", "g3.json"}) {
    INFO(f);
    check_refused(shell(kExe + " scene " + f, dir), "not valid JSON");
  }
  CHECK_FALSE(fs::exists(dir.path / "o.csv"));
}

TEST_CASE("hostile: fuzz_findings: a number overflowing JSON, a BOM-only CSV, a ratio overflowing int64 in a slice", "[cli][hostile][fuzz]") {
  // Found by tests/fuzz (fuzz_scene, fuzz_atlas_csv): both used to end in an uncaught exception
  // or undefined behaviour (a double beyond int64 cast to int64).
  TempDir dir;
  write_file(dir.path / "big.json", "{\"trains\":[{\"name\":\"a\",\"a2\":33e333,\"a3\":\"1\",\"n\":\"2\","
                                    "\"effects\":{\"trace\":\"o.csv\"}}]}");
  check_refused(shell(kExe + " scene big.json", dir), "number overflow");
  CHECK_FALSE(fs::exists(dir.path / "o.csv"));

  // A file holding only a UTF-8 byte order mark: no rows (used to divide 0 by 0 sizing a buffer).
  write_file(dir.path / "bom.csv", "\xef\xbb\xbf");
  check_refused(shell(kExe + " crossings --input bom.csv", dir), "0 vertices");

  REQUIRE(shell(kExe + " atlas --n 2 --grid 2 -o a.csv", dir).status == 0);
  std::string text = slurp(dir.path / "a.csv");
  const std::string n_eq = "n=2 ";
  REQUIRE(text.find(n_eq) != std::string::npos);
  for (const char* n : {"n=33333333333333333333333333333333/1 ", "n=1e80 ", "n=-0/1 ", "n=2.5 "}) {
    INFO(n);
    std::string bad = text;
    bad.replace(bad.find(n_eq), n_eq.size(), n);
    write_file(dir.path / "bad.csv", bad);
    check_refused(shell(kExe + " atlas-merge -o m.csv bad.csv", dir), "bad.csv");
    CHECK_FALSE(fs::exists(dir.path / "m.csv"));
  }
}

TEST_CASE("hostile: output_through_symlinks: a dangling link gets its target created, the link kept", "[cli][hostile][output]") {
  TempDir dir;
  fs::create_directory(dir.path / "real");
  fs::create_symlink("real/new.csv", dir.path / "dangling.csv");  // target does not exist yet
  const Result r = shell(kExe + " trace --a2 1 --a3 2 --n 2 --samples 8 -o dangling.csv", dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(fs::is_symlink(dir.path / "dangling.csv"));        // as a shell's > would: the link stays
  CHECK(fs::is_regular_file(dir.path / "real" / "new.csv"));  // and its target is the file
  CHECK(count_lines(slurp(dir.path / "real" / "new.csv")) == 9);
  // A link to an existing file: the file is replaced, the link stays.
  REQUIRE(shell(kExe + " trace --a2 1 --a3 2 --n 2 --samples 5 -o dangling.csv", dir).status == 0);
  CHECK(fs::is_symlink(dir.path / "dangling.csv"));
  CHECK(count_lines(slurp(dir.path / "real" / "new.csv")) == 6);
  // atlas-merge: stdin twice is refused by name; a full stdout is named "stdout".
  check_refused(shell(kExe + " atlas-merge -o m.csv - - < /dev/null", dir), "standard input given twice");
}

TEST_CASE("hostile: names_with_newlines are escaped so that errors stay one line", "[cli][hostile][scene]") {
  TempDir dir;
  write_file(dir.path / "k.json", "{\"trains\":[{" + kTrain + ",\"a\\nb\":1,\"effects\":{\"trace\":\"o.csv\"}}]}");
  check_refused(shell(kExe + " scene k.json", dir), "a\\nb");
  check_refused(shell(kExe + " trace --a2 $'1\\n2' --a3 1 --n 2", dir), "1\\n2");
}

TEST_CASE("hostile: empty_option_values, flags_with_values, odd signs and overflow are refused", "[cli][hostile][options]") {
  TempDir dir;
  const std::string t = kExe + " trace --a2 1 --a3 1 --n 2";
  check_refused(shell(t + " --samples ''", dir), "--samples");
  check_refused(shell(kExe + " trace --a2 1 --a3 1 --n 2 --turns ''", dir), "--turns");
  check_refused(shell(kExe + " atlas --n 2 --grid 4 --threads ''", dir), "--threads");
  check_refused(shell(t + " --velocity=value", dir), "--velocity");
  check_refused(shell(t + " --velocity=true", dir), "--velocity");
  check_refused(shell(kExe + " trace --a2 1 --a3 1 --n +-3", dir), "--n = +-3");
  check_refused(shell(kExe + " trace --a2 1 --a3 1 --n -9223372036854775808", dir), "--n");
  check_refused(shell(kExe + " trace --a2 1 --a3 1 --n 9223372036854775807/3", dir), "--n");
  check_refused(shell(kExe + " atlas --n 2 --grid 4 --a2 '0 :1'", dir), "--a2 = 0 :1");
  check_refused(shell(kExe + " atlas --n 2 --grid 4 --a2 0:4.9e-324", dir), "--a2 = 0:4.9e-324");
}

TEST_CASE("hostile: unknown_command is named with the list of commands", "[cli][hostile][options]") {
  TempDir dir;
  for (const char* word : {"tracer", "boundary"}) {  // ("boundaries" is a command since issue 13)
    INFO(word);
    check_refused(shell(kExe + " " + word, dir), std::string(word) + ": not a command; valid: trace, ");
  }
}

TEST_CASE("hostile: pairs_errors_name_pairs, and -o/--pairs/--input aliases are refused", "[cli][hostile][crossings]") {
  TempDir dir;
  REQUIRE(shell(kExe + " trace --a2 1 --a3 2 --n 7/3 -o c.csv", dir).status == 0);
  check_refused(shell(kExe + " crossings --input c.csv --pairs missing/p.csv", dir), "--pairs = missing/p.csv");
  const std::string before = slurp(dir.path / "c.csv");
  check_refused(shell(kExe + " crossings --input c.csv -o ./c.csv", dir), "an input would be replaced");
  check_refused(shell(kExe + " crossings --input c.csv --pairs c.csv", dir), "an input would be replaced");
  check_refused(shell(kExe + " crossings --input c.csv --pairs p.csv -o p.csv", dir), "same file");
  CHECK(slurp(dir.path / "c.csv") == before);
}

TEST_CASE("hostile: legal_but_huge ratios are refused up front, fast, with the bound", "[cli][hostile][cost]") {
  TempDir dir;
  check_refused(shell(kExe + " atlas --n 1000000 --grid 4", dir), "|p|(|p|+q) <= 200000");
  check_refused(shell(kExe + " atlas --n 1/1000000 --grid 4", dir), "|p|(|p|+q) <= 200000");
  check_refused(shell(kExe + " classify --a2 1 --a3 2 --n 1000000", dir), "|p|(|p|+q) <= 200000");
  check_refused(shell(kExe + " classify --a2 1 --a3 2 --n 999999/1000000", dir), "|p|(|p|+q) <= 200000");
  check_refused(shell(kExe + " nodes --a2 1 --a3 2 --n 1001/400", dir), "|p|(|p|+q) <= 200000");
  check_refused(shell(kExe + " trace --a2 1 --a3 2 --n 999999/1000000", dir), "give the number of samples explicitly");
  check_refused(shell(kExe + " trace --a2 1 --a3 2 --n 2 --turns 1e6", dir), "K <= 925");
  // With an explicit count the same trace is legal and bounded.
  const Result r = shell(kExe + " trace --a2 1 --a3 2 --n 999999/1000000 --samples 1000 | wc -l", dir);
  CHECK(r.status == 0);
  CHECK(r.out == "1001\n");
  // A scene asking a census of a huge ratio is refused before anything is written.
  write_file(dir.path / "big.json",
             "{\"trains\":[{\"name\":\"ok\",\"a2\":\"1\",\"a3\":\"2\",\"n\":\"2\",\"effects\":{\"trace\":\"t.csv\"}},"
             "{\"name\":\"big\",\"a2\":\"1\",\"a3\":\"2\",\"n\":\"1000000\",\"effects\":{\"nodes\":\"n.csv\"}}]}");
  check_refused(shell(kExe + " scene big.json", dir), "trains[1].effects.nodes");
  CHECK_FALSE(fs::exists(dir.path / "t.csv"));
}

TEST_CASE("hostile: huge_phase is reduced exactly: the node count of phase 0, |P| = 1", "[cli][hostile][phase]") {
  TempDir dir;
  // The phase only turns the curve (Eq. 8): Eq. 43 holds for a2 = pi/2, a3 = pi/3, n = 2 -> 2 nodes.
  for (const char* phase : {"0", "1e10", "-1e15", "1e300"}) {
    INFO(phase);
    const Result r = shell(kExe + " classify --a2 pi/2 --a3 pi/3 --n 2 --json --phase=" + phase, dir);
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["counts"]["nodes"] == 2);
    CHECK(j["agreement"]["ok"] == true);
    CHECK(std::abs(j["inputs"]["phase_reduced"].get<double>()) <= 3.141592653589794);
  }
  // 1e10 mod 2 pi, independently: 1e10 = 1591549430 * 2 pi + r, with 2 pi in long double
  // (error 1.6e9 * 2 pi * 5e-20 ~ 5e-10, far below the check).
  const auto j = nlohmann::json::parse(shell(kExe + " classify --a2 pi/2 --a3 pi/3 --n 2 --json --phase 1e10", dir).out);
  const long double two_pi = 6.283185307179586476925286766559L;
  long double r = 1e10L - 1591549430.0L * two_pi;
  if (r > two_pi / 2) r -= two_pi;
  CHECK(std::abs(j["inputs"]["phase_reduced"].get<double>() - static_cast<double>(r)) <= 1e-8);
  const Result t = shell(kExe + " trace --a2 pi/2 --a3 pi/3 --n 2 --samples 100 --phase 1e300", dir);
  REQUIRE(t.status == 0);
  std::istringstream rows(t.out);
  std::string line;
  std::getline(rows, line);
  int n = 0;
  while (std::getline(rows, line)) {
    double v[4];
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3]) == 4);
    CHECK(std::abs(std::sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3]) - 1) <= 1e-15);
    ++n;
  }
  CHECK(n == 100);
}

TEST_CASE("hostile: tiny_carrier_twists are refused below 1e-6 rad, never NaN", "[cli][hostile][twist]") {
  TempDir dir;
  check_refused(shell(kExe + " classify --a2 1e-10 --a3 1 --n 2", dir), "--a2 = 1e-10");
  check_refused(shell(kExe + " trace --a2 1e-300 --a3 ap --n -1 --samples 3", dir), "--a2 = 1e-300");
  check_refused(shell(kExe + " trace --a2 1e-160 --a3 1 --n 2 --samples 3", dir), "--a2 = 1e-160");
  check_refused(shell(kExe + " nodes --a2 1e-300 --a3 a2 --n 2", dir), "--a2 = 1e-300");
  check_refused(shell(kExe + " classify --a2 pi-1e-9 --a3 1 --n 2", dir), "--a2");
  check_refused(shell(kExe + " classify --a2 1e-5 --a3 ap --n -1", dir), "barely turns");
  // At the bound itself, both censuses agree with the report (Eqs. 43/46: 4 nodes).
  const Result r = shell(kExe + " classify --a2 1e-6 --a3 1 --n 2 --json", dir);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["counts"]["nodes"] == 4);
  CHECK(j["agreement"]["ok"] == true);
}

TEST_CASE("hostile: fifo_input_without_writer fails after a bounded wait instead of blocking", "[cli][hostile][fifo]") {
  TempDir dir;
  REQUIRE(::mkfifo((dir.path / "ff").c_str(), 0666) == 0);
  check_refused(shell("timeout 30 " + kExe + " crossings --input ff", dir), "no writer opened within 10 s");
}

TEST_CASE("hostile: fifo_output_without_reader fails after a bounded wait; with a reader it is written", "[cli][hostile][fifo]") {
  TempDir dir;
  REQUIRE(::mkfifo((dir.path / "ff").c_str(), 0666) == 0);
  check_refused(shell("timeout 30 " + kExe + " boundaries --n 3 --a2 1 -o ff", dir), "no reader opened within 10 s");
  // A reader that opens it: the events arrive through the FIFO (cat waits for the writer).
  const Result r = shell("(cat ff > got.txt &) ; timeout 30 " + kExe + " boundaries --n 3 --a2 pi/2 -o ff; sleep 0.2; cat got.txt", dir);
  CHECK(r.status == 0);
  CHECK(r.out.find("tangency") != std::string::npos);
}

TEST_CASE("hostile: stdout_write_errors of every command give one line and status 2", "[cli][hostile][device]") {
  TempDir dir;
  REQUIRE(::mknod((dir.path / "full").c_str(), S_IFCHR | 0666, makedev(1, 7)) == 0);
  REQUIRE(shell(kExe + " trace --a2 1 --a3 2 --n 7/3 -o c.csv", dir).status == 0);
  write_file(dir.path / "s.json", "{\"trains\":[{" + kTrain + ",\"effects\":{\"trace\":\"o.csv\"}}]}");
  for (const std::string& cmd : {std::string("crossings --input c.csv"), std::string("scene s.json --explain"),
                                 std::string("nodes --a2 1 --a3 2 --n 2"), std::string("--help"), std::string("--version")}) {
    INFO(cmd);
    const Result r = shell(kExe + " " + cmd + " > full", dir);
    CHECK(r.status == 2);
    CHECK(r.err.find('\n') == r.err.size() - 1);
  }
}

TEST_CASE("hostile: long_file_names up to 255 bytes work (short temporary names)", "[cli][hostile][output]") {
  TempDir dir;
  const std::string name(255, 'n');
  const Result r = shell(kExe + " trace --a2 1 --a3 2 --n 2 --samples 5 -o " + name, dir);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(count_lines(slurp(dir.path / name)) == 6);
}

TEST_CASE("hostile: second_output_fails: atlas -o A --svg S leaves no A when S cannot be written", "[cli][hostile][output]") {
  TempDir dir;
  fs::create_directory(dir.path / "svgdir");
  write_file(dir.path / "A.csv", "previous\n");
  const Result r = shell(kExe + " atlas --n 2 --grid 4 -o A.csv --svg svgdir", dir);
  CHECK(r.status == 2);
  CHECK(contains(r.err, "--svg"));
  CHECK(slurp(dir.path / "A.csv") == "previous\n");
}
