// The I/O boundary of the tool (issue 9): pipes between commands, files in both formats,
// numpy round trips (Debian's python3-numpy), streamed output under a memory limit, write
// failures on devices made in a temporary directory, closed pipes, signals.
#include "catch2/catch.hpp"
#include "cli_support.hpp"

#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <chrono>
#include <thread>

using namespace sphtroch::test;
namespace fs = std::filesystem;

namespace {

const std::string kExe = quoted_tool();
const std::string kTrain = "trace --a2 1 --a3 2 --n 7/3";


nlohmann::json json_of(const Result& r) {
  INFO(r.err);
  REQUIRE(r.status == 0);
  return nlohmann::json::parse(r.out);
}

bool one_line(const std::string& err) { return !err.empty() && err.find('\n') == err.size() - 1; }

}  // namespace

TEST_CASE("cli io: trace piped into crossings, trace's CSV and .npy files, all give the root census's count",
          "[cli][io][pipe]") {
  TempDir dir;
  // The reference: classify's root-count census (one-dimensional, independent of the polyline).
  const auto c = json_of(shell(kExe + " classify --a2 1 --a3 2 --n 7/3 --json", dir));
  const int nodes = c["censuses"]["root_count"]["nodes"];
  REQUIRE(nodes > 0);
  const auto piped = json_of(shell(kExe + " " + kTrain + " | " + kExe + " crossings --input - --json", dir));
  CHECK(piped["crossings"] == nodes);
  CHECK(piped["vertices"] == 3600);
  CHECK(piped["input_format"] == "csv with header");
  CHECK(piped.contains("seconds_read"));
  CHECK(piped.contains("seconds_search"));
  for (const std::string file : {"c.csv", "c.npy", "v.csv", "v.npy"}) {
    INFO(file);
    const std::string velocity = file[0] == 'v' ? " --velocity" : "";
    REQUIRE(shell(kExe + " " + kTrain + velocity + " -o " + file, dir).status == 0);
    const auto j = json_of(shell(kExe + " crossings --input " + file + " --json", dir));
    CHECK(j["crossings"] == nodes);
    CHECK(j["touchings"] == 0);
    CHECK(j["vertices"] == 3600);
  }
  // The format follows the bytes, not the name; --format npy to stdout, read from stdin.
  REQUIRE(shell(kExe + " " + kTrain + " --format npy > looks_like.csv", dir).status == 0);
  CHECK(json_of(shell(kExe + " crossings --input looks_like.csv --json", dir))["input_format"] == "npy <f8 (3600, 4)");
  CHECK(json_of(shell("cat c.npy | " + kExe + " crossings --input - --json", dir))["crossings"] == nodes);
}

TEST_CASE("cli io: numpy.load reads what trace writes, crossings reads what numpy.save writes", "[cli][io][numpy]") {
  TempDir dir;
  REQUIRE(shell(kExe + " " + kTrain + " --samples 5000 --velocity -o t.npy && " + kExe + " " + kTrain +
                    " --samples 5000 --velocity -o t.csv",
                dir)
              .status == 0);
  // Debian's numpy: the arrays are equal bit for bit to the CSV parsed by numpy itself, |P| = 1,
  // and the velocity is orthogonal to P (dP/dt of a unit vector).
  const Result py = shell(
      "/usr/bin/python3 - <<'EOF'\n"
      "import numpy as np\n"
      "a = np.load('t.npy')\n"
      "b = np.loadtxt('t.csv', delimiter=',', skiprows=1)\n"
      "assert a.dtype == np.float64 and a.shape == (5000, 7) and a.flags['C_CONTIGUOUS'], (a.dtype, a.shape)\n"
      "assert np.array_equal(a, b)\n"
      "assert np.max(np.abs(np.linalg.norm(a[:, 1:4], axis=1) - 1)) < 1e-15\n"
      "assert np.max(np.abs(np.sum(a[:, 1:4] * a[:, 4:7], axis=1))) < 1e-14\n"
      "np.save('xyz64.npy', a[:, 1:4].copy())\n"
      "np.save('xyz32.npy', a[:, 1:4].astype(np.float32))\n"
      "np.save('t4.npy', a[:, 0:4].copy())\n"
      "np.save('fortran.npy', np.asfortranarray(a[:, 1:4]))\n"
      "np.save('big_endian.npy', a[:, 1:4].astype('>f8'))\n"
      "np.save('ints.npy', np.zeros((10, 3), dtype=np.int32))\n"
      "print('ok')\n"
      "EOF",
      dir);
  INFO(py.err);
  REQUIRE(py.status == 0);
  CHECK(py.out == "ok\n");
  const auto ref = json_of(shell(kExe + " crossings --input t.csv --json", dir));
  for (const std::string f : {"xyz64.npy", "xyz32.npy", "t4.npy"}) {
    INFO(f);
    const auto j = json_of(shell(kExe + " crossings --input " + f + " --json", dir));
    CHECK(j["crossings"] == ref["crossings"]);
    CHECK(j["vertices"] == 5000);
  }
  for (const std::string f : {"fortran.npy", "big_endian.npy", "ints.npy"}) {
    INFO(f);
    const Result r = shell(kExe + " crossings --input " + f, dir);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(one_line(r.err));
    CHECK(contains(r.err, "--input = " + f + ": "));
  }
}

TEST_CASE("cli io: bad CSV and .npy inputs exit 2 with one line naming the file, nothing on stdout", "[cli][io][errors]") {
  TempDir dir;
  REQUIRE(shell(kExe + " " + kTrain + " -o c.npy && head -c 1000 c.npy > cut.npy && head -c 40 c.npy > cuthead.npy", dir)
              .status == 0);
  std::ofstream(dir.path / "four.csv") << "0,0,1,5\n1,0,1,5\n0,1,1,5\n";
  std::ofstream(dir.path / "noz.csv") << "t,x,y\n0,1,0\n";
  std::ofstream(dir.path / "text.csv") << "x,y,z\n1,0,0\n0,1,0\nhello,0,1\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"crossings --input cut.npy", "truncated"},
      {"crossings --input cuthead.npy", "truncated header"},
      {"crossings --input - < cut.npy", "--input = -: truncated"},
      {"crossings --input four.csv", "line 1 has 4 numbers"},
      {"crossings --input noz.csv", "without a column z"},
      {"crossings --input text.csv", "line 4 column 1"},
      {"crossings --input missing.csv", "cannot be read"},
      {"crossings --input .", "is a directory"},
  };
  for (const auto& [args, problem] : cases) {
    INFO(args);
    const Result r = shell(kExe + " " + args, dir);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(one_line(r.err));
    CHECK(contains(r.err, problem));
  }
}

TEST_CASE("cli io: write failures: a full device gives one line and status 2, a device is never replaced",
          "[cli][io][device]") {
  TempDir dir;
  const fs::path full = dir.path / "full";
  REQUIRE(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) == 0);  // a copy of /dev/full
  const std::vector<std::string> commands = {kTrain + " > full", kTrain + " -o full", kTrain + " -o full --format npy",
                                             "classify --a2 1 --a3 2 --n 7/3 > full", "atlas --n 2 --grid 4 > full"};
  for (const std::string& args : commands) {
    INFO(args);
    const Result r = shell(kExe + " " + args, dir);
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK(contains(r.err, "No space left on device"));
    CHECK(fs::is_character_file(full));
  }
  // crossings --pairs P -o X: when X fails, P is not left behind.
  REQUIRE(shell(kExe + " " + kTrain + " -o c.csv", dir).status == 0);
  const Result r = shell(kExe + " crossings --input c.csv --pairs pairs.csv -o full", dir);
  CHECK(r.status == 2);
  CHECK(one_line(r.err));
  CHECK_FALSE(fs::exists(dir.path / "pairs.csv"));
}

TEST_CASE("cli io: a closed pipe ends trace quietly, like other filters", "[cli][io][pipe]") {
  TempDir dir;
  const Result r = shell(kExe + " " + kTrain + " --samples 10000000 | head -3; echo \"status ${PIPESTATUS[0]}\"", dir);
  CHECK(r.err.empty());
  CHECK(count_lines(r.out) == 4);
  CHECK(contains(r.out, "status 141"));  // killed by SIGPIPE after cleaning up, as `cat` would be
}

TEST_CASE("cli io: -o /dev/stdout writes into the redirected file, an existing file keeps its mode", "[cli][io][output]") {
  TempDir dir;
  const Result r = shell(kExe + " " + kTrain + " --samples 5 -o /dev/stdout > redirected.csv && " + kExe + " " +
                             kTrain + " --samples 5 > plain.csv && cmp redirected.csv plain.csv && ls -A",
                         dir);
  CHECK(r.status == 0);
  CHECK((r.out == "cmd.sh\nplain.csv\nredirected.csv\nstderr.txt\nstdout.txt\n" ||
         r.out == "cmd.sh\nplain.csv\nredirected.csv\nstdout.txt\nstderr.txt\n"));
  const fs::path mine = dir.path / "mine.csv";
  std::ofstream(mine) << "old";
  fs::permissions(mine, fs::perms::owner_read | fs::perms::owner_write);  // 0600
  REQUIRE(shell(kExe + " " + kTrain + " --samples 5 -o mine.csv", dir).status == 0);
  CHECK((fs::status(mine).permissions() & fs::perms::all) == (fs::perms::owner_read | fs::perms::owner_write));
  CHECK(count_lines(slurp(mine)) == 6);
}

TEST_CASE("cli io: SIGTERM or SIGINT during a long trace leaves neither the file nor a temporary", "[cli][io][signal]") {
  for (const char* sig : {"TERM", "INT"}) {
    TempDir dir;
    // set -m: the background job gets the default signal dispositions (job control).
    const Result r = shell("set -m; " + kExe + " " + kTrain + " --samples 10000000 --threads 1 -o big.csv & pid=$!; sleep 0.4; kill -" +
                               sig + " $pid; wait $pid; echo \"status $?\"; ls -A",
                           dir);
    INFO(r.out << r.err);
    CHECK(contains(r.out, std::string("status ") + (sig[0] == 'T' ? "143" : "130")));
    CHECK_FALSE(contains(r.out, "big.csv"));
    CHECK_FALSE(contains(r.out, ".sphtroch-"));
  }
}

TEST_CASE("cli io: trace streams: 1e7 samples run under a 64 MiB data limit that a whole-buffer command exceeds",
          "[cli][io][memory]") {
  if (tool_has_address_sanitizer()) {
    SUCCEED("not under AddressSanitizer: its shadow memory alone exceeds any data limit (the Release run checks this)");
    return;
  }
  TempDir dir;
  const std::string limit = "prlimit --data=" + std::to_string(64 << 20) + " ";
  // The streamed trace: 1e7 rows (~780 MB of CSV) through the limit.
  const Result r = shell(limit + kExe + " " + kTrain + " --samples 10000000 | wc -l", dir);
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.out == "10000001\n");
  // Control: the same rows held in memory (crossings keeps 24 bytes per vertex, 240 MB) must
  // fail under the same limit, so the limit is real and the test could fail.
  const Result whole = shell(kExe + " " + kTrain + " --samples 10000000 | " + limit + kExe + " crossings --input -", dir);
  CHECK(whole.status != 0);
}

TEST_CASE("cli io: crossings of random directions: counts in O(N) memory under a data limit, cost bounds refuse (D2)",
          "[cli][io][memory][crossings]") {
  if (tool_has_address_sanitizer()) {
    SUCCEED("not under AddressSanitizer: its shadow memory alone exceeds any data limit (the Release run checks this)");
    return;
  }
  TempDir dir;
  // Random directions (long arcs): N = 1500 with a numpy O(N^2) sign-test count as the
  // reference, N = 8000 (~4e6 crossings) and N = 60000 (~1e9). numpy writes the .npy files.
  const Result py = shell(
      "/usr/bin/python3 - <<'EOF'\n"
      "import numpy as np\n"
      "for n, seed in ((1500, 1), (8000, 2), (60000, 3)):\n"
      "    np.save('r%d.npy' % n, np.random.default_rng(seed).normal(size=(n, 3)))\n"
      "P = np.load('r1500.npy'); n = len(P); e = n\n"
      "M = np.cross(P, np.roll(P, -1, axis=0)) @ P.T\n"
      "sc = np.sign(M); sd = np.sign(np.roll(M, -1, axis=1)); sa = sc.T; sb = sd.T\n"
      "c = np.triu((sc == -sd) & (sa == -sb) & (sa == sd) & (sc != 0) & (sa != 0), 2)\n"
      "c[0, e - 1] = False\n"
      "print(int(c.sum()))\n"
      "EOF",
      dir);
  INFO(py.err);
  REQUIRE(py.status == 0);
  const long expected = std::stol(py.out);
  REQUIRE(expected > 100000);
  // 48 MiB of data: the count-only search of ~4e6 crossings fits; storing them (>= 16 bytes
  // each, 64 MB) would not, so this fails if memory grows with the crossing count.
  const std::string limit = "prlimit --data=" + std::to_string(48 << 20) + " ";
  const auto j1500 = json_of(shell(limit + kExe + " crossings --input r1500.npy --json", dir));
  CHECK(j1500["crossings"] == expected);
  CHECK(j1500["touchings"] == 0);
  const Result big = shell(limit + kExe + " crossings --input r8000.npy --max-work 1000000000 --json", dir);
  INFO(big.err);
  REQUIRE(big.status == 0);
  const auto j8000 = nlohmann::json::parse(big.out);
  CHECK(j8000["crossings"] > 3000000);
  CHECK(j8000["vertices"] == 8000);
  // The same with --pairs: streamed to the file under the same limit, one row per crossing.
  const Result streamed = shell(limit + kExe + " crossings --input r8000.npy --max-work 1000000000 --pairs p.csv -o s.json && wc -l < p.csv", dir);
  INFO(streamed.err);
  REQUIRE(streamed.status == 0);
  CHECK(std::stol(streamed.out) == j8000["crossings"].get<long>() + 1);
  // Control: the limit is real (a process that allocates 64 MB fails under it).
  CHECK(shell(limit + "/usr/bin/python3 -c 'b = bytearray(64 << 20)'", dir).status != 0);
  // 60,000 vertices (~1e9 crossings): refused by the estimate before searching, one line, exit 2.
  const Result r = shell(limit + kExe + " crossings --input r60000.npy --pairs p6.csv -o out.json", dir);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(one_line(r.err));
  CHECK(contains(r.err, "--max-work = 50000000: "));
  CHECK(contains(r.err, "estimated"));
  CHECK_FALSE(fs::exists(dir.path / "p6.csv"));
  CHECK_FALSE(fs::exists(dir.path / "out.json"));
  // With the work bound lifted, the crossings bound stops the search (memory still O(N)).
  const Result k = shell(limit + kExe + " crossings --input r60000.npy --max-work 1000000000000000 --max-crossings 200000 --pairs p6.csv", dir);
  CHECK(k.status == 2);
  CHECK(k.out.empty());
  CHECK(one_line(k.err));
  CHECK(contains(k.err, "--max-crossings = 200000: the polyline has more than 200000 crossings + touchings"));
  CHECK_FALSE(fs::exists(dir.path / "p6.csv"));
  for (const std::string bad : {"--max-crossings -1", "--max-work x", "--max-crossings 1e99"}) {
    const Result b = shell(kExe + " crossings --input r1500.npy " + bad, dir);
    CHECK(b.status == 2);
    CHECK(one_line(b.err));
  }
}
