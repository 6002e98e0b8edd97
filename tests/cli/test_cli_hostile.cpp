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
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <fstream>
#include <regex>
#include <algorithm>

using namespace sphtroch::test;
namespace fs = std::filesystem;

namespace {

const std::string kExe = quoted_tool();


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

TEST_CASE("hostile: fifo_output_without_reader fails after a bounded wait, with a reader it is written", "[cli][hostile][fifo]") {
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
  // (scene --explain, with its output written before stdout fails: status 4, see D8 below)
  for (const std::string& cmd : {std::string("crossings --input c.csv"), std::string("nodes --a2 1 --a3 2 --n 2"),
                                 std::string("--help"), std::string("--version")}) {
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

namespace {

/// A scene of `trains` trains, each asking the five cheap effects (3 samples) into `dir`/.
std::string cheap_scene(int trains, const std::string& dir, const std::string& extra_train = "") {
  std::string s = "{\"trains\":[";
  for (int i = 0; i < trains; ++i) {
    const std::string k = std::to_string(i);
    s += std::string(i ? "," : "") + "{\"name\":\"t" + k + "\",\"a2\":\"1\",\"a3\":\"2\",\"n\":\"2\",\"samples\":3,\"effects\":{" +
         "\"trace\":\"" + dir + "/trace" + k + ".csv\",\"velocity\":\"" + dir + "/velocity" + k + ".csv\",\"extrema\":\"" +
         dir + "/extrema" + k + ".json\",\"cusps\":\"" + dir + "/cusps" + k + ".csv\",\"screw_axis\":\"" + dir + "/screw" + k +
         ".csv\"}}";
  }
  return s + extra_train + "]}";
}

std::size_t count_entries(const fs::path& dir, const std::string& prefix) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().rfind(prefix, 0) == 0;
  return n;
}

/// A .npy header by hand (numpy.lib.format 1.0): magic, version, length, dict padded to 64 bytes.
std::string npy_header_by_hand(const std::string& dict) {
  std::string d = dict;
  while ((10 + d.size() + 1) % 64) d += ' ';
  d += '\n';
  return std::string("\x93NUMPY\x01\x00", 8) + static_cast<char>(d.size() & 0xff) + static_cast<char>(d.size() >> 8) + d;
}

}  // namespace

TEST_CASE("hostile: D4 nul_in_scene_output_path is refused naming the field (no colliding outputs)", "[cli][hostile][scene]") {
  TempDir dir;
  // "o.csv\u0000x" would reach o.csv, the trace's path: two outputs colliding.
  write_file(dir.path / "z.json",
             "{\"trains\":[{" + kTrain + ",\"effects\":{\"trace\":\"o.csv\",\"velocity\":\"o.csv\\u0000x\"}}]}");
  check_refused(shell(kExe + " scene z.json", dir), "z.json: trains[0].effects.velocity = \"o.csv\\u0000x\": an output path with a NUL byte");
  write_file(dir.path / "z2.json", "{\"trains\":[{" + kTrain + ",\"effects\":{\"trace\":\"\\u0000\"}}]}");
  check_refused(shell(kExe + " scene z2.json --output-dir .", dir), "trains[0].effects.trace");
  std::vector<std::string> left = dir.entries();
  std::sort(left.begin(), left.end());
  CHECK(left == std::vector<std::string>{"z.json", "z2.json"});
}

TEST_CASE("hostile: D5 sigterm_with_100_staged_outputs leaves no temporary and no output", "[cli][hostile][scene][signals]") {
  TempDir dir;
  fs::create_directory(dir.path / "out");
  // 100 cheap outputs first, then a node census that takes seconds (n = 301/100: 1.2e5 nodes).
  write_file(dir.path / "s.json",
             cheap_scene(20, "out", ",{\"name\":\"slow\",\"a2\":\"1\",\"a3\":\"2\",\"n\":\"301/100\",\"effects\":{\"nodes\":\"out/slow.csv\"}}"));
  const Result r = shell(kExe + " scene s.json & pid=$!\n"
                                "for i in $(seq 400); do [ $(ls -A out | grep -c '^.sphtroch-') -ge 100 ] && break; sleep 0.05; done\n"
                                "echo staged $(ls -A out | grep -c '^.sphtroch-')\n"
                                "kill -TERM $pid; wait $pid; echo status $?",
                         dir);
  INFO(r.out << r.err);
  CHECK(contains(r.out, "staged 100\n"));  // more than the 64 slots the registry used to have
  CHECK(contains(r.out, "status 143"));    // killed by SIGTERM (128 + 15), mid-run
  CHECK(count_entries(dir.path / "out", "") == 0);  // no temporary, no output
}

TEST_CASE("hostile: D6 scene_with_1100_outputs succeeds under ulimit -n 256, above 100000 outputs refused up front",
          "[cli][hostile][scene]") {
  TempDir dir;
  fs::create_directory(dir.path / "out");
  write_file(dir.path / "s.json", cheap_scene(220, "out"));
  const Result r = shell("ulimit -n 256 && " + kExe + " scene s.json", dir);
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(count_entries(dir.path / "out", "") == 1100);
  CHECK(count_entries(dir.path / "out", ".sphtroch-") == 0);
  CHECK(count_lines(slurp(dir.path / "out" / "trace219.csv")) == 4);  // header + 3 samples
  // 20001 trains x 5 = 100005 outputs: refused while parsing, nothing computed or written.
  fs::remove_all(dir.path / "out");
  fs::create_directory(dir.path / "out");
  write_file(dir.path / "big.json", cheap_scene(20001, "out"));
  check_refused(shell(kExe + " scene big.json", dir), "big.json: trains[20000].effects: output 100005 of the scene: more than 100000");
  CHECK(count_entries(dir.path / "out", "") == 0);
}

TEST_CASE("hostile: D7 fifo_input_with_silent_writer is read like cat, past the 10 s wait for a writer", "[cli][hostile][fifo]") {
  TempDir dir;
  REQUIRE(::mkfifo((dir.path / "ff").c_str(), 0666) == 0);
  write_file(dir.path / "tri.csv", "1,0,0\n0,1,0\n0,0,1\n");
  // The writer opens the FIFO at once (the redirection), then stays silent 11 s (> 10 s).
  const Result r = shell("{ sleep 11; cat tri.csv; } > ff &\n" + kExe + " crossings --input ff --json", dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(nlohmann::json::parse(r.out)["vertices"] == 3);
}

TEST_CASE("hostile: D8 stdout_fails_after_outputs: exit 4 naming the files written, which stay complete", "[cli][hostile][device]") {
  TempDir dir;
  REQUIRE(::mknod((dir.path / "full").c_str(), S_IFCHR | 0666, makedev(1, 7)) == 0);  // a copy of /dev/full
  const auto check_status_4 = [](const Result& r, const std::string& files) {
    INFO(r.err);
    CHECK(r.status == 4);
    CHECK(r.err.find('\n') == r.err.size() - 1);
    CHECK(contains(r.err, "outputs written: " + files + "; stdout failed: stdout = -: write failed"));
  };
  check_status_4(shell(kExe + " atlas --n 2 --grid 4 -o A.csv --svg S.svg > full", dir), "A.csv, S.svg");
  CHECK(count_lines(slurp(dir.path / "A.csv")) == 2 + 16);  // comment, header, 4 x 4 cells
  CHECK(contains(slurp(dir.path / "S.svg"), "</svg>"));
  REQUIRE(shell(kExe + " atlas --n 2 --grid 4 --shard 1/2 -o s1.csv", dir).status == 0);
  REQUIRE(shell(kExe + " atlas --n 2 --grid 4 --shard 2/2 -o s2.csv", dir).status == 0);
  check_status_4(shell(kExe + " atlas-merge -o M.csv s1.csv s2.csv > full", dir), "M.csv");
  CHECK(slurp(dir.path / "M.csv") == slurp(dir.path / "A.csv"));
  write_file(dir.path / "s.json", "{\"trains\":[{" + kTrain + ",\"effects\":{\"trace\":\"o.csv\"}}]}");
  check_status_4(shell(kExe + " scene s.json --explain > full", dir), "o.csv");
  CHECK(count_lines(slurp(dir.path / "o.csv")) > 1);
  // Without an output file the failed stdout is bad output as before: status 2.
  const Result plain = shell(kExe + " atlas --n 2 --grid 4 > full", dir);
  CHECK(plain.status == 2);
}

TEST_CASE("hostile: D9 stdin_aliasing_the_output and output_symlink_loops are refused", "[cli][hostile][output]") {
  TempDir dir;
  REQUIRE(shell(kExe + " trace --a2 1 --a3 2 --n 7/3 -o in.csv", dir).status == 0);
  const std::string before = slurp(dir.path / "in.csv");
  check_refused(shell(kExe + " crossings --input - -o in.csv < in.csv", dir), "--output = in.csv: is the same file as --input = -");
  check_refused(shell(kExe + " crossings --input - --pairs ./in.csv < in.csv", dir), "--input = -");
  CHECK(slurp(dir.path / "in.csv") == before);
  // From a pipe, standard input is no file: the same output is legal.
  CHECK(shell("cat in.csv | " + kExe + " crossings --input - -o other.csv", dir).status == 0);
  // A symlink loop: a shell's > fails with ELOOP; so does -o, naming it, and the links stay.
  fs::create_symlink("loop", dir.path / "loop");
  fs::create_symlink("b", dir.path / "a");
  fs::create_symlink("a", dir.path / "b");
  check_refused(shell(kExe + " crossings --input in.csv -o loop", dir), "--output = loop: is a loop of symbolic links");
  check_refused(shell(kExe + " trace --a2 1 --a3 2 --n 2 -o a", dir), "--output = a: is a loop of symbolic links");
  CHECK(fs::is_symlink(dir.path / "loop"));
  CHECK(fs::is_symlink(dir.path / "a"));
  CHECK(fs::is_symlink(dir.path / "b"));
  CHECK(count_entries(dir.path, ".sphtroch-") == 0);
}

TEST_CASE("hostile: D10 sparse_inputs report their first bad row (exit 2), never out of memory", "[cli][hostile][input]") {
  TempDir dir;
  // 4 GB: far below what reserving the sizes would take; none for a tool under AddressSanitizer,
  // whose shadow memory alone exceeds any address-space limit.
  const std::string limit = tool_has_address_sanitizer() ? std::string() : "ulimit -v 4000000 && ";
  write_file(dir.path / "big.csv", "1,0,0\n0,1,0\n");
  fs::resize_file(dir.path / "big.csv", std::uintmax_t(64) << 30);  // 64 GiB, sparse: NUL bytes, no disk
  check_refused(shell(limit + kExe + " crossings --input big.csv", dir), "--input = big.csv: line 3 ");
  const std::string header = npy_header_by_hand("{'descr': '<f8', 'fortran_order': False, 'shape': (3000000000, 3), }");
  write_file(dir.path / "big.npy", header);
  fs::resize_file(dir.path / "big.npy", header.size() + std::uintmax_t(3000000000) * 24);
  check_refused(shell(limit + kExe + " crossings --input big.npy", dir),
                "--input = big.npy: row 0 (0, 0, 0) is not a finite nonzero vector");
}

TEST_CASE("hostile: D12 messages: a NUL in a .npy descr escaped, the CSV field that is not a number, the real --turns bound",
          "[cli][hostile][input]") {
  TempDir dir;
  const char dict[] = "{'descr': '<f\0" "8', 'fortran_order': False, 'shape': (3, 3), }";
  write_file(dir.path / "n.npy", npy_header_by_hand(std::string(dict, sizeof dict - 1)) + std::string(72, '\x01'));
  check_refused(shell(kExe + " crossings --input n.npy", dir), "dtype <f\\x008 is not float64 or float32; valid: a NumPy");
  write_file(dir.path / "e1.csv", "1,0,0\n1e,0.5,1\n0,0,1\n");
  check_refused(shell(kExe + " crossings --input e1.csv", dir), "line 2 column 1 is not a finite number: \"1e\"");
  write_file(dir.path / "e2.csv", "1,0,0\n0.5,0x1p3,1\n0,0,1\n");
  check_refused(shell(kExe + " crossings --input e2.csv", dir), "line 2 column 2 is not a finite number: \"0x1p3\"");
  // n = 1000000/3: K <= (1e6 - 1) / (360 (1 + n)) = 0.0083333000000999..., not "K <= 0".
  const Result r = shell(kExe + " trace --a2 1 --a3 2 --n 1000000/3 --turns 1", dir);
  check_refused(r, "K <= 0.00833");
  std::smatch m;
  REQUIRE(std::regex_search(r.err, m, std::regex("K <= ([0-9.e+-]+) carrier turns")));
  const double k = std::stod(m[1]);
  const double bound = 999999.0 / (360.0 * (1.0 + 1000000.0 / 3.0));
  CHECK(k <= bound * (1 + 1e-15));
  CHECK(k >= bound * (1 - 1e-12));
  const Result ok = shell(kExe + " trace --a2 1 --a3 2 --n 1000000/3 --turns " + m[1].str() + " | wc -l", dir);
  CHECK(ok.status == 0);
  CHECK(ok.out == "1000001\n");  // header + ceil(360 (1 + n) K + 1) = 1000000 samples
}

TEST_CASE("hostile: D13 the a2 bound 1e-6 is inclusive and nothing below passes, a JSON float n is refused", "[cli][hostile][twist]") {
  TempDir dir;
  const std::string t = kExe + " trace --n 2 --a3 1 --samples 3 --a2 ";
  CHECK(shell(t + "1e-6", dir).status == 0);
  CHECK(shell(t + "pi-1e-6", dir).status == 0);
  check_refused(shell(t + "9.9e-7", dir), "--a2 = 9.9e-7: within 1e-6 rad of 0 or pi");
  check_refused(shell(t + "9.99999e-7", dir), "--a2 = 9.99999e-7");
  check_refused(shell(t + "pi-9.9e-7", dir), "within 1e-6 rad of 0 or pi");
  write_file(dir.path / "a.json", "{\"trains\":[{\"name\":\"a\",\"a2\":9.9e-7,\"a3\":\"1\",\"n\":\"2\",\"effects\":{\"trace\":\"o.csv\"}}]}");
  check_refused(shell(kExe + " scene a.json", dir), "a.json: trains[0].a2 = 9.9e-07");
  for (const char* n : {"2.5", "2.0", "2e0"}) {
    INFO(n);
    write_file(dir.path / "n.json", std::string("{\"trains\":[{\"name\":\"a\",\"a2\":\"1\",\"a3\":\"1\",\"n\":") + n +
                                        ",\"effects\":{\"trace\":\"o.csv\"}}]}");
    check_refused(shell(kExe + " scene n.json", dir), "trains[0].n = ");
  }
  CHECK_FALSE(fs::exists(dir.path / "o.csv"));
  write_file(dir.path / "n.json", "{\"trains\":[{\"name\":\"a\",\"a2\":\"1\",\"a3\":\"1\",\"n\":2,\"effects\":{\"trace\":\"o.csv\"}}]}");
  CHECK(shell(kExe + " scene n.json", dir).status == 0);
  write_file(dir.path / "n.json", "{\"trains\":[{\"name\":\"a\",\"a2\":\"1\",\"a3\":\"1\",\"n\":\"2.5\",\"effects\":{\"trace\":\"p.csv\"}}]}");
  CHECK(shell(kExe + " scene n.json", dir).status == 0);
}

TEST_CASE("hostile: D3 extreme_radius: 1e100 and 1e-100 give finite kinematics in CSV and .npy, beyond them refused",
          "[cli][hostile][radius]") {
  TempDir dir;
  // n = 3 with a3 on the pitch cone: cusps (speed 0) and a near-cusp's large curvature; n = 1000:
  // large speeds and accelerations.
  for (const std::string train : {"--n 3 --a2 1 --a3 ap+1e-9", "--n 1000 --a2 1 --a3 2"}) {
    for (const std::string radius : {"1e100", "1e-100"}) {
      const Result csv = shell(kExe + " trace " + train + " --samples 2000 --radius " + radius + " --kinematics --velocity", dir);
      INFO(train << " --radius " << radius << ": " << csv.err);
      REQUIRE(csv.status == 0);
      std::istringstream rows(csv.out);
      std::string line;
      std::getline(rows, line);  // header
      std::size_t values = 0;
      while (std::getline(rows, line)) {
        std::istringstream fields(line);
        std::string field;
        while (std::getline(fields, field, ',')) {
          const double v = std::strtod(field.c_str(), nullptr);
          CHECK(std::isfinite(v));
          CHECK((v == 0.0 || std::abs(v) >= 2.2250738585072014e-308));  // normal, not subnormal
          ++values;
        }
      }
      CHECK(values == 2000 * 10);
      REQUIRE(shell(kExe + " trace " + train + " --samples 2000 --radius " + radius + " --kinematics -o k.npy", dir).status == 0);
      const std::string npy = slurp(dir.path / "k.npy");
      const std::size_t header = npy.find('\n') + 1;
      REQUIRE(npy.size() == header + 2000 * 7 * sizeof(double));
      for (std::size_t at = header; at < npy.size(); at += sizeof(double)) {
        double v;
        std::memcpy(&v, npy.data() + at, sizeof v);
        CHECK(std::isfinite(v));
      }
    }
  }
  write_file(dir.path / "keep.csv", "old");
  for (const std::string radius : {"1e308", "1e101", "9.9e-101", "1e-310", "0", "-1", "inf", "nan"}) {
    check_refused(shell(kExe + " trace --n 2 --a2 1 --a3 1 --kinematics --radius " + radius + " -o keep.csv", dir),
                  "--radius = " + radius + ": ");
    CHECK(slurp(dir.path / "keep.csv") == "old");
  }
  check_refused(shell(kExe + " nodes --n 2 --a2 1 --a3 1 --radius 1e-300", dir), "valid: a length in [1e-100, 1e100]");
}

TEST_CASE("hostile: D1 D6 identify_of_a_tiny_planet_circle says the samples do not determine n (exit 2), never one ratio",
          "[cli][hostile][identify]") {
  TempDir dir;
  for (const std::string a3 : {"1e-9", "1e-8", "1e-6", "pi-1e-6", "pi-1e-9"}) {
    const Result r = shell(kExe + " trace --n 2 --a2 1 --a3 " + a3 + " | " + kExe + " synth identify --input -", dir);
    INFO("a3 = " << a3);
    check_refused(r, "below the samples' resolution");
    CHECK(!contains(r.err, "at least one period"));
  }
  const Result ok = shell(kExe + " trace --n 2 --a2 1 --a3 1e-4 | " + kExe + " synth identify --input -", dir);
  CHECK(ok.status == 0);
  CHECK(contains(ok.out, "n = 2\n"));
}
