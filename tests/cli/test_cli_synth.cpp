// `sphtroch synth identify`, run as a real executable: trace's own output (CSV through a pipe,
// .npy, an open curve) gives back the train that traced it; bad input is one stderr line, exit 2,
// nothing on stdout. Expected values: the trace's own arguments (the hidden train).
#include "catch2/catch.hpp"
#include "cli_support.hpp"
#include "sphtroch/core/number_text.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace sphtroch::test;

namespace {

std::string exe() { return quoted_tool(); }

/// FNV-1a, 64 bits (offset basis 14695981039346656037, prime 1099511628211).
std::uint64_t fnv1a64(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return h;
}

/// A part with its "digest" computed again as docs/cli.md (synth points) defines it: the FNV-1a
/// of the part's bytes with the digest's 16 digits as 0. Unchanged without a "digest".
std::string resigned(std::string part) {
  const std::string key = "\"digest\": \"";
  const auto at = part.find(key);
  if (at == std::string::npos) return part;
  part.replace(at + key.size(), 16, std::string(16, '0'));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(part)));
  return part.replace(at + key.size(), 16, hex);
}

void write_text(const TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.path / name, std::ios::binary) << text;
}

/// The text of a number member `"key": V` in `line` replaced by `value`.
std::string with_member(std::string line, const std::string& key, const std::string& value) {
  const std::string tag = "\"" + key + "\": ";
  const auto at = line.find(tag);
  REQUIRE(at != std::string::npos);
  const auto begin = at + tag.size(), end = line.find_first_of(",}", begin);
  return line.replace(begin, end - begin, value);
}

/// Line k (0 = the first) of text.
std::string line_of(const std::string& text, std::size_t k) {
  std::size_t begin = 0;
  for (std::size_t i = 0; i < k; ++i) begin = text.find('\n', begin) + 1;
  return text.substr(begin, text.find('\n', begin) - begin);
}

/// A train's line as JSON (without the comma that follows all but the last).
nlohmann::json train_of(std::string line) {
  if (!line.empty() && line.back() == ',') line.pop_back();
  return nlohmann::json::parse(line);
}

/// Line k (0 = the first) of text replaced by f(line).
template <class F>
std::string with_line(const std::string& text, std::size_t k, F f) {
  std::size_t begin = 0;
  for (std::size_t i = 0; i < k; ++i) begin = text.find('\n', begin) + 1;
  const auto end = text.find('\n', begin);
  return text.substr(0, begin) + f(text.substr(begin, end - begin)) + text.substr(end);
}

/// `synth merge ARGS -o merged.json` refused: exit 2, one stderr line naming `part` and holding
/// each of `words`, nothing on stdout, no merged.json.
void check_merge_refused(const TempDir& dir, const std::string& args, const std::string& part, const std::vector<std::string>& words) {
  INFO(args);
  const Result r = run("synth merge -o merged.json " + args, dir, true);
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  CHECK(contains(r.err, part));
  for (const std::string& w : words) CHECK(contains(r.err, w));
  CHECK_FALSE(std::filesystem::exists(dir.path / "merged.json"));
}

}  // namespace

TEST_CASE("cli synth identify: trace's CSV, .npy and open curves give back their train", "[cli][synth]") {
  TempDir dir;
  struct Case {
    std::string trace_args, n;
    double a2, a3, phase;
  };
  for (const Case& c : {Case{"--n 5/2 --a2 1 --a3 2", "5/2", 1, 2, 0}, Case{"--n -7/3 --a2 0.5 --a3 2.5 --phase 1 --turns 3", "-7/3", 0.5, 2.5, 1},
                        Case{"--n 13/5 --a2 2.9 --a3 0.2 --phase -2 --samples 20000", "13/5", 2.9, 0.2, -2}}) {
    INFO(c.trace_args);
    for (const char* file : {"t.csv", "t.npy"}) {
      REQUIRE(run("trace " + c.trace_args + " -o " + file, dir, true).status == 0);
      const Result r = run(std::string("synth identify --json --input ") + file, dir, true);
      REQUIRE(r.status == 0);
      CHECK(r.err.empty());
      const nlohmann::json j = nlohmann::json::parse(r.out);
      CHECK(j["n"] == c.n);
      CHECK(std::abs(j["a2"].get<double>() - c.a2) < 1e-12);
      CHECK(std::abs(j["a3"].get<double>() - c.a3) < 1e-12);
      CHECK(std::abs(std::remainder(j["phase"].get<double>() - c.phase, 2 * M_PI)) < 1e-12);
      CHECK(j["residual"].get<double>() < 1e-12);
    }
  }
  const Result piped = shell(exe() + " trace --n 3 --a2 pi/2 --a3 pi/3 | " + exe() + " synth identify --input -", dir);
  REQUIRE(piped.status == 0);
  CHECK(contains(piped.out, "n = 3\n"));
  CHECK(contains(piped.out, "trace it: sphtroch trace --n 3 --a2 1.5707963267948966 --a3 1.047197551196597"));
}

TEST_CASE("cli synth identify: bad input is one stderr line naming the input, exit 2, no stdout", "[cli][synth][errors]") {
  TempDir dir;
  REQUIRE(run("trace --n 2 --a2 1 --a3 1 --samples 100 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\n' > nt.csv && head -5 t.csv > few.csv", dir).status == 0);
  for (const std::string& args : {std::string("--input nt.csv"), std::string("--input few.csv"),
                                  std::string("--input missing.csv"), std::string("--input t.csv --max-terms 1,1"),
                                  std::string("--input t.csv --max-terms 3"), std::string("--input t.csv --max-terms 0,5")}) {
    INFO(args);
    const Result r = run("synth identify " + args, dir, true);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK((contains(r.err, "--input") || contains(r.err, "--max-terms")));
  }
  const Result none = run("synth", dir, true);
  CHECK(none.status == 2);
  CHECK(none.out.empty());
}

TEST_CASE("cli synth points: three points of a trace give back its train among all, certified", "[cli][synth]") {
  TempDir dir;
  // Samples 1, 10 and 28 (CSV lines 3, 12, 30) of a 40-sample trace of the hidden train.
  REQUIRE(run("trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 40 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; sed -n '3p;12p;30p' t.csv | cut -d, -f2-4) > pts.csv", dir).status == 0);
  const Result r = run("synth points --input pts.csv --n 1/2 --json", dir, true);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["complete"] == true);
  bool hidden = false;
  for (const auto& s : j["solutions"]) {
    CHECK(s["n"] == "1/2");
    CHECK(s["residual"].get<double>() <= 1e-12);
    CHECK(s["params"].size() == 3);
    CHECK(s["census_certified"] == true);
    CHECK(s["counts"]["nodes"].get<int>() == s["counts"]["crossings"].get<int>() + s["counts"]["tangencies"].get<int>());
    // The certified margin: a bracket; classify at the corners of the 0.99 lower square draws the
    // solution's census (the proof's claim, checked by the census).
    const double lower = s["certified_margin"]["lower"].get<double>(), upper = s["certified_margin"]["upper"].get<double>();
    CHECK(lower > 0);
    CHECK(lower <= upper);
    for (const double da2 : {-0.99 * lower, 0.99 * lower})
      for (const double da3 : {-0.99 * lower, 0.99 * lower}) {
        const double a2 = s["a2"].get<double>() + da2, a3 = s["a3"].get<double>() + da3;
        const Result c = run("classify --n 1/2 --a2 " + sphtroch::number_text(a2) + " --a3 " + sphtroch::number_text(a3) + " --json", dir, true);
        REQUIRE(c.status == 0);
        const nlohmann::json cj = nlohmann::json::parse(c.out);
        CHECK(cj["nodes"].size() == s["counts"]["nodes"].get<std::size_t>());
        CHECK(cj["cusps"].size() == s["counts"]["cusps"].get<std::size_t>());
      }
    hidden = hidden || (std::abs(s["a2"].get<double>() - 1) < 1e-9 && std::abs(s["a3"].get<double>() - 2) < 1e-9 &&
                        std::abs(std::remainder(s["phase"].get<double>() - 0.3, M_PI)) < 1e-9);
  }
  CHECK(hidden);
  const Result text = run("synth points --input pts.csv --n 1/2", dir, true);
  REQUIRE(text.status == 0);
  CHECK(contains(text.out, "all of them (certified)"));
  CHECK(contains(text.out, "plot it: sphtroch plot --n 1/2 --a2 1 --a3 2 --phase "));
  CHECK(contains(text.out, "; certified margin "));
}

TEST_CASE("cli synth points: bad input is one stderr line, exit 2, no stdout", "[cli][synth][errors]") {
  TempDir dir;
  REQUIRE(shell("printf 'x,y,z\\n1,0,0\\n0,1,0\\n' > two.csv && printf 'x,y,z\\n1,0,0\\n0,1,0\\n1,0,0\\n' > dup.csv && "
                "printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1.00001\\n' > off.csv && printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\n' > ok.csv && "
                "printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\n-1,0,0\\n0,-1,0\\n' > five.csv",
                dir).status == 0);
  for (const std::string& args : {std::string("--input two.csv --n 1"), std::string("--input dup.csv --n 1"),
                                  std::string("--input off.csv --n 1"), std::string("--input ok.csv"),
                                  std::string("--input ok.csv --n 1 --ratios 2,2"), std::string("--input ok.csv --ratios 30,30"),
                                  std::string("--input ok.csv --n 200/3"), std::string("--input ok.csv --ratios 3"),
                                  std::string("--input ok.csv --n 40"),  // (41)^2 is in the bound, 40 (41)^2 with the censuses not
                                  std::string("--input ok.csv --teeth 40:1"),
                                  std::string("--input ok.csv --n 1 --free-axis"),  // three points: five needed
                                  std::string("--input ok.csv --n 1 --threads 2"),  // threads only with --free-axis
                                  std::string("--input five.csv --ratios 7,7 --free-axis"),  // over the free axis's bound
                                  std::string("--input five.csv --n 1 --free-axis --threads 0")}) {
    INFO(args);
    const Result r = run("synth points " + args, dir, true);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
  }
}

TEST_CASE("cli synth: a bad count pair is named whole, a negative count as out of range", "[cli][synth][errors]") {
  TempDir dir;
  REQUIRE(shell("printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\n' > ok.csv && "
                "printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\n-1,0,0\\n0,-1,0\\n' > five.csv",
                dir).status == 0);
  const Result three = run("synth points --input ok.csv --ratios 1,1,1", dir, true);
  CHECK(three.status == 2);
  CHECK(three.out.empty());
  CHECK(contains(three.err, "ratios = 1,1,1: not two counts P,Q"));
  const Result part = run("synth points --input ok.csv --ratios 2,x", dir, true);
  CHECK(part.status == 2);
  CHECK(part.out.empty());
  CHECK(contains(part.err, "ratios = 2,x: not a whole number (x)"));
  REQUIRE(run("trace --n 1 --a2 1 --a3 1 --samples 40 -o t.csv", dir, true).status == 0);
  const Result terms = run("synth identify --input t.csv --max-terms 1,1,1", dir, true);
  CHECK(terms.status == 2);
  CHECK(terms.out.empty());
  CHECK(contains(terms.err, "max-terms = 1,1,1: not two counts P,Q"));
  const Result negative = run("synth points --input five.csv --n 1 --free-axis --threads -1", dir, true);
  CHECK(negative.status == 2);
  CHECK(contains(negative.err, "threads = -1: outside the valid range"));
}

TEST_CASE("cli synth points --free-axis: five points of a turned trace give back its train, sun axis and frame",
          "[cli][synth]") {
  TempDir dir;
  // The trace turned by the cyclic permutation (x, y, z) -> (y, z, x): the sun axis is then Y.
  REQUIRE(run("trace --n 1 --a2 1.2 --a3 0.8 --phase 0.5 --samples 50 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; sed -n '3p;11p;20p;34p;45p' t.csv | awk -F, '{print $3\",\"$4\",\"$2}') > pts.csv", dir).status == 0);
  const Result r = run("synth points --input pts.csv --n 1 --free-axis --json", dir, true);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["complete"] == true);
  int hidden = 0;
  for (const auto& s : j["solutions"]) {
    REQUIRE(s["frame"].size() == 3);
    CHECK(s["axis"] == s["frame"][2]);
    CHECK(s["params"].size() == 5);
    CHECK(s["residual"].get<double>() < 1e-12);
    const double ay = s["axis"][1].get<double>(), a3 = s["a3"].get<double>();
    // The axis is reported with z > 0, else y > 0: Y itself, with a3 as traced.
    if (std::abs(ay - 1.0) < 1e-9 && std::abs(s["a2"].get<double>() - 1.2) < 1e-9 && std::abs(a3 - 0.8) < 1e-9) ++hidden;
  }
  CHECK(hidden == 1);
  const Result text = run("synth points --input pts.csv --n 1 --free-axis --threads 1", dir, true);
  CHECK(text.status == 0);
  CHECK(text.out.find("sun axis [") != std::string::npos);
  CHECK(text.out.find("all of them (certified)") != std::string::npos);
}

TEST_CASE("cli synth points --shard and synth merge: the shards joined equal the unsharded run", "[cli][synth]") {
  TempDir dir;
  REQUIRE(run("trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 40 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; sed -n '3p;12p;30p' t.csv | cut -d, -f2-4) > pts.csv", dir).status == 0);
  REQUIRE(run("synth points --input pts.csv --ratios 3,2 --json -o all.json", dir, true).status == 0);
  for (int i = 1; i <= 3; ++i)
    REQUIRE(run("synth points --input pts.csv --ratios 3,2 --json --shard " + std::to_string(i) + "/3 -o part" +
                    std::to_string(i) + ".json", dir, true).status == 0);
  REQUIRE(run("synth merge part3.json part1.json part2.json -o merged.json", dir, true).status == 0);
  CHECK(shell("cmp all.json merged.json", dir).status == 0);
  const nlohmann::json j = nlohmann::json::parse(shell("cat all.json", dir).out);
  CHECK(j["ratios"] == "3,2");
  CHECK(j["solutions"].size() > 0);
  // Refusals: a shard missing, given twice, of another run, not a shard; --shard without --ratios.
  REQUIRE(run("synth points --input pts.csv --ratios 2,2 --json --shard 1/3 -o other.json", dir, true).status == 0);
  for (const std::string& args : {std::string("synth merge part1.json part2.json"), std::string("synth merge part1.json part1.json part2.json"),
                                  std::string("synth merge other.json part2.json part3.json"), std::string("synth merge pts.csv"),
                                  std::string("synth points --input pts.csv --n 1 --shard 1/2"),
                                  std::string("synth points --input pts.csv --ratios 3,2 --shard 4/3")}) {
    INFO(args);
    const Result r = run(args, dir, true);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
  }
}

TEST_CASE("cli synth fit: a trace's path gives back its train first, and a wanted count holds for every candidate", "[cli][synth]") {
  TempDir dir;
  REQUIRE(run("trace --n 2 --a2 1.1 --a3 0.9 --phase 0.4 --samples 300 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; tail -n +2 t.csv | cut -d, -f2-4) > path.csv", dir).status == 0);
  const Result r = run("synth fit --input path.csv --n 2 --json", dir, true);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const nlohmann::json j = nlohmann::json::parse(r.out);
  REQUIRE(j["candidates"].size() >= 1);
  const auto& best = j["candidates"][0];
  CHECK(std::abs(best["a2"].get<double>() - 1.1) < 1e-7);
  CHECK(std::abs(best["a3"].get<double>() - 0.9) < 1e-7);
  CHECK(std::abs(std::remainder(best["phase"].get<double>() - 0.4, 2 * M_PI)) < 1e-7);  // n = 2: q = 1
  CHECK(best["rms"].get<double>() < 1e-9);
  CHECK(j["reason"] == "");
  // The census of the hidden train, by `classify --json`, is the best candidate's.
  const nlohmann::json hidden = nlohmann::json::parse(run("classify --n 2 --a2 1.1 --a3 0.9 --json", dir, true).out);
  CHECK(best["counts"]["nodes"].get<std::size_t>() == hidden["nodes"].size());
  // Another count that exists at this a2 (boundaries: 0, 2 and 4 node points): every candidate has it.
  const nlohmann::json other = nlohmann::json::parse(run("synth fit --input path.csv --n 2 --nodes 4 --json", dir, true).out);
  REQUIRE(other["candidates"].size() >= 1);
  for (const auto& c : other["candidates"]) {
    CHECK(c["counts"]["nodes"] == 4);
    CHECK(c["census_certified"] == true);
    CHECK(c["margin"].get<double>() >= 0);
  }
  const Result cusps = run("synth fit --input path.csv --n 2 --cusps 2 --candidates 2", dir, true);
  REQUIRE(cusps.status == 0);
  CHECK(contains(cusps.out, "2 cusp(s) (certified)"));
  CHECK(contains(cusps.out, "plot it: sphtroch plot --n 2 --a2 "));
  // Impossible requests: no candidate, the reason, exit 0.
  for (const std::string& args : {std::string("--nodes 3"), std::string("--nodes 8"), std::string("--cusps 1")}) {
    INFO(args);
    const Result none = run("synth fit --input path.csv --n 2 --json " + args, dir, true);
    CHECK(none.status == 0);
    const nlohmann::json n = nlohmann::json::parse(none.out);
    CHECK(n["candidates"].empty());
    CHECK_FALSE(n["reason"].get<std::string>().empty());
  }
}

TEST_CASE("cli synth fit text: the margin line says what each of its numbers measures", "[cli][synth]") {
  // n = 2, a2 = 1.1, a3 = 0.9: the nearest change of the census is the pole line a3 = a2 (the
  // tracer through the pole), a line at 45 deg. Its distance is |a2 - a3| / sqrt 2 = 0.1414...
  // (the margin, first order: exact for a straight line); the largest square about the train that
  // it does not meet has half-width |a2 - a3| / 2 = 0.1 (the certified margin's bracket).
  TempDir dir;
  REQUIRE(run("trace --n 2 --a2 1.1 --a3 0.9 --phase 0.4 --samples 300 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; tail -n +2 t.csv | cut -d, -f2-4) > path.csv", dir).status == 0);
  const nlohmann::json j = nlohmann::json::parse(run("synth fit --input path.csv --n 2 --candidates 1 --json", dir, true).out);
  REQUIRE(j["candidates"].size() == 1);
  const auto& best = j["candidates"][0];
  const double margin = best["margin"], lower = best["certified_margin"]["lower"], upper = best["certified_margin"]["upper"];
  CHECK(std::abs(margin - 0.2 / std::sqrt(2.0)) < 1e-6);
  CHECK(lower <= 0.1 + 1e-12);
  CHECK(upper >= 0.1 - 1e-12);
  CHECK(upper - lower < 1e-6);
  const Result text = run("synth fit --input path.csv --n 2 --candidates 1", dir, true);
  REQUIRE(text.status == 0);
  CHECK(contains(text.out, "; margin " + shortest_g(margin) + " (distance to the nearest change of the census, first order), " +
                               "change-free square of half-width " + shortest_g(lower) + " .. " + shortest_g(upper) + " (certified); "));
}

TEST_CASE("cli synth fit: bad input is one stderr line, exit 2, no stdout", "[cli][synth][errors]") {
  TempDir dir;
  REQUIRE(shell("printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\n' > three.csv && printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\n0,0,1.00001\\n' > off.csv && "
                "printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\nnan,0,1\\n' > nan.csv && printf 'x,y,z\\n1,0,0\\n1,0,0\\n0,1,0\\n0,1,0\\n' > dup.csv && "
                "printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,1,0\\n0,1,0\\n' > two.csv && printf 'x,y,z\\n1,0,0\\n0,1,0\\n0,0,1\\n0.6,0.8,0\\n' > ok.csv",
                dir).status == 0);
  for (const std::string& args :
       {std::string("--input three.csv --n 1"), std::string("--input off.csv --n 1"), std::string("--input nan.csv --n 1"),
        std::string("--input dup.csv --n 1"), std::string("--input two.csv --n 1"), std::string("--input ok.csv"),
        std::string("--input ok.csv --n 1 --ratios 2,2"),
        std::string("--input ok.csv --ratios 30,30"), std::string("--input ok.csv --n 1 --nodes -1"),
        std::string("--input ok.csv --n 1 --cusps x"), std::string("--input ok.csv --n 1 --candidates 0"),
        std::string("--input ok.csv --n 1 --max-deviation 0"), std::string("--input ok.csv --n 1001")}) {
    INFO(args);
    const Result r = run("synth fit " + args, dir, true);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
  }
}

TEST_CASE("cli synth fit --slice and synth merge: the shards joined equal the unsharded run", "[cli][synth]") {
  TempDir dir;
  REQUIRE(run("trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 60 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; tail -n +2 t.csv | cut -d, -f2-4) > path.csv", dir).status == 0);
  REQUIRE(run("synth fit --input path.csv --ratios 2,2 --json -o all.json", dir, true).status == 0);
  for (int i = 1; i <= 2; ++i)
    REQUIRE(run("synth fit --input path.csv --ratios 2,2 --json --slice " + std::to_string(i) + "/2 -o part" + std::to_string(i) +
                    ".json", dir, true).status == 0);
  REQUIRE(run("synth merge part2.json part1.json -o merged.json", dir, true).status == 0);
  CHECK(shell("cmp all.json merged.json", dir).status == 0);
  const nlohmann::json j = nlohmann::json::parse(shell("cat all.json", dir).out);
  // n = 1/2 and n = -1/2 at (pi - a2, pi - a3) draw the same curve: both pass the points exactly.
  CHECK(j["candidates"][0]["rms"].get<double>() < 1e-9);
  bool hidden = false;
  for (const auto& c : j["candidates"])
    hidden = hidden || (c["n"] == "1/2" && std::abs(c["a2"].get<double>() - 1) < 1e-7 && c["rms"].get<double>() < 1e-9);
  CHECK(hidden);
  // Refused: a part missing, a part of another run (other options), a part edited by hand.
  REQUIRE(run("synth fit --input path.csv --ratios 2,2 --nodes 2 --json --slice 2/2 -o other.json", dir, true).status == 0);
  REQUIRE(shell("sed '2s/\"a2\": [0-9.]*/\"a2\": 7/' part1.json > edited.json", dir).status == 0);
  for (const std::string& args : {std::string("synth merge part1.json"), std::string("synth merge part1.json other.json"),
                                  std::string("synth merge edited.json part2.json")}) {
    INFO(args);
    const Result r = run(args, dir, true);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
  }
}

TEST_CASE("cli synth fit / points --teeth: ZS:ZP is n = ZS/ZP and is echoed, MIN..MAX is every ratio of two counts in it",
          "[cli][synth]") {
  TempDir dir;
  REQUIRE(run("trace --n 13/5 --a2 1.1 --a3 0.9 --phase 0.2 --samples 300 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; tail -n +2 t.csv | cut -d, -f2-4) > path.csv", dir).status == 0);
  const Result r = run("synth fit --input path.csv --teeth 39:15 --candidates 1 --json", dir, true);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["teeth"] == "39:15");
  REQUIRE(j["candidates"].size() == 1);
  CHECK(j["candidates"][0]["n"] == "13/5");
  CHECK(j["candidates"][0]["teeth"] == "39:15");
  CHECK(std::abs(j["candidates"][0]["a3"].get<double>() - 0.9) < 1e-7);
  CHECK(contains(run("synth fit --input path.csv --teeth 39:15 --candidates 1", dir, true).out, "n = 13/5 (teeth 39:15), "));
  // Three points of another path: the hidden train is among synth points' trains, each echoing 12:24.
  REQUIRE(run("trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 60 -o h.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; sed -n '2p;22p;42p' h.csv | cut -d, -f2-4) > pts.csv", dir).status == 0);
  const Result pts = run("synth points --input pts.csv --teeth 12:24 --json", dir, true);
  REQUIRE(pts.status == 0);
  bool hidden = false;
  const nlohmann::json solutions = nlohmann::json::parse(pts.out)["solutions"];
  REQUIRE_FALSE(solutions.empty());
  for (const auto& s : solutions) {
    CHECK(s["teeth"] == "12:24");
    hidden = hidden || (std::abs(s["a2"].get<double>() - 1) < 1e-9 && std::abs(s["a3"].get<double>() - 2) < 1e-9);
  }
  CHECK(hidden);
  // A range set, sharded and merged: byte for byte the unsharded run; every candidate's teeth in range.
  REQUIRE(run("synth fit --input path.csv --teeth 2..3 --json -o all.json", dir, true).status == 0);
  for (int i = 1; i <= 2; ++i)
    REQUIRE(run("synth fit --input path.csv --teeth 2..3 --json --slice " + std::to_string(i) + "/2 -o part" +
                    std::to_string(i) + ".json", dir, true).status == 0);
  REQUIRE(run("synth merge part2.json part1.json -o merged.json", dir, true).status == 0);
  CHECK(shell("cmp all.json merged.json", dir).status == 0);
  // A part whose echoed teeth were edited is refused (the run writes the smallest pair in range).
  REQUIRE(shell("sed '2s/\"teeth\": \"[-0-9]*:[0-9]*\"/\"teeth\": \"9:9\"/' part1.json > edited.json", dir).status == 0);
  REQUIRE(shell("grep -q '9:9' edited.json", dir).status == 0);
  const Result edited = run("synth merge edited.json part2.json", dir, true);
  CHECK(edited.status == 2);
  CHECK(count_lines(edited.err) == 1);
  const nlohmann::json all = nlohmann::json::parse(shell("cat all.json", dir).out);
  CHECK(all["teeth"] == "2..3");
  REQUIRE_FALSE(all["candidates"].empty());
  for (const auto& c : all["candidates"]) {
    const std::string t = c["teeth"];
    const long zs = std::labs(std::stol(t.substr(0, t.find(':')))), zp = std::stol(t.substr(t.find(':') + 1));
    CHECK((zs >= 2 && zs <= 3 && zp >= 2 && zp <= 3));
  }
  for (const std::string& args : {std::string("--teeth 39:0"), std::string("--teeth 0..3"), std::string("--teeth 3..2"),
                                  std::string("--teeth 39:15 --n 13/5"), std::string("--teeth 39:15 --slice 1/2"),
                                  std::string("--teeth 1..60")}) {
    INFO(args);
    const Result bad = run("synth fit --input path.csv " + args, dir, true);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(count_lines(bad.err) == 1);
  }
}

TEST_CASE("cli synth fit --node-at: a node of the traced train gives it back, with the node there by the census",
          "[cli][synth]") {
  TempDir dir;
  REQUIRE(run("trace --n 2 --a2 1.1 --a3 0.9 --phase 0.4 --samples 300 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; tail -n +2 t.csv | cut -d, -f2-4) > path.csv", dir).status == 0);
  // The node point as `sphtroch nodes` prints it (kind,x,y,z,...): the expected node.
  REQUIRE(run("nodes --n 2 --a2 1.1 --a3 0.9 --phase 0.4 -o nodes.csv", dir, true).status == 0);
  const std::string node = shell("sed -n 2p nodes.csv | cut -d, -f2-4", dir).out;
  REQUIRE(count_lines(node) == 1);
  const std::string at = node.substr(0, node.size() - 1);
  const Result r = run("synth fit --input path.csv --n 2 --node-at " + at + " --json", dir, true);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  REQUIRE_FALSE(j["candidates"].empty());
  const auto& best = j["candidates"][0];
  CHECK(std::abs(best["a2"].get<double>() - 1.1) < 1e-7);
  CHECK(std::abs(best["a3"].get<double>() - 0.9) < 1e-7);
  for (const auto& c : j["candidates"]) CHECK(c["node_distance"].get<double>() <= 1e-6);
  CHECK(contains(run("synth fit --input path.csv --n 2 --node-at " + at, dir, true).out, " rad away (certified)"));
  for (const std::string& args : {std::string("--node-at 0.97,-0.2,0.14"), std::string("--node-at 1,0"),
                                  std::string("--node-at 1,0,x"), std::string("--node-tolerance 1e-3"),
                                  std::string("--node-at 1,0,0 --node-tolerance 0")}) {
    INFO(args);
    const Result bad = run("synth fit --input path.csv --n 2 " + args, dir, true);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(count_lines(bad.err) == 1);
  }
}

TEST_CASE("cli synth merge: hand edits that keep every value plausible (a2 + 0.05, rms 1e-30, counts 99) are refused by the digest",
          "[cli][synth][errors]") {
  TempDir dir;
  REQUIRE(run("trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 60 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; tail -n +2 t.csv | cut -d, -f2-4) > path.csv && (echo x,y,z; sed -n '3p;12p;30p' t.csv | cut -d, -f2-4) > pts.csv",
                dir).status == 0);
  for (int i = 1; i <= 2; ++i) {
    const std::string part = std::to_string(i) + "/2 -o ";
    REQUIRE(run("synth fit --input path.csv --ratios 2,2 --json --shard " + part + "fit" + std::to_string(i) + ".json", dir, true).status == 0);
    REQUIRE(run("synth points --input pts.csv --ratios 2,2 --json --shard " + part + "points" + std::to_string(i) + ".json", dir, true).status == 0);
  }
  REQUIRE(run("synth merge fit2.json fit1.json -o fit.json", dir, true).status == 0);  // unedited: merged
  const std::string fit = slurp(dir.path / "fit1.json"), points = slurp(dir.path / "points1.json");
  // The first candidate of part 1 (line 2): each edit leaves it inside every range synth fit prints.
  const double a2 = train_of(line_of(fit, 1))["a2"].get<double>();
  REQUIRE(a2 + 0.05 < M_PI);
  const std::vector<std::pair<std::string, std::string>> edits{
      {"a2.json", with_line(fit, 1, [&](const std::string& l) { return with_member(l, "a2", shortest_g(a2 + 0.05)); })},
      {"rms.json", with_line(fit, 1, [](const std::string& l) { return with_member(l, "rms", "1e-30"); })},
      {"counts.json", with_line(fit, 1, [](const std::string& l) {
         return with_member(with_member(with_member(with_member(l, "nodes", "99"), "crossings", "99"), "tangencies", "0"), "cusps", "0");
       })}};
  for (const auto& [name, text] : edits) {
    REQUIRE(text != fit);
    write_text(dir, name, text);
    check_merge_refused(dir, name + " fit2.json", name, {"digest"});
  }
  // A solution of a synth points part, a2 moved by 1e-3 (inside [1e-6, pi - 1e-6]).
  REQUIRE(contains(points, "\n  {"));
  const double a2_points = train_of(line_of(points, 1))["a2"].get<double>();
  const std::string moved = with_line(points, 1, [&](const std::string& l) { return with_member(l, "a2", shortest_g(a2_points + 1e-3)); });
  REQUIRE(moved != points);
  write_text(dir, "solution.json", moved);
  check_merge_refused(dir, "solution.json points2.json", "solution.json", {"digest"});
}

TEST_CASE("cli synth merge: a points part edited and re-signed is still refused member by member", "[cli][synth][errors]") {
  TempDir dir;
  REQUIRE(run("trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 40 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; sed -n '3p;12p;30p' t.csv | cut -d, -f2-4) > pts.csv", dir).status == 0);
  for (int i = 1; i <= 3; ++i)
    REQUIRE(run("synth points --input pts.csv --ratios 3,2 --json --shard " + std::to_string(i) + "/3 -o part" + std::to_string(i) + ".json",
                dir, true).status == 0);
  const std::string p1 = slurp(dir.path / "part1.json"), p2 = slurp(dir.path / "part2.json"), p3 = slurp(dir.path / "part3.json");
  CHECK(resigned(p1) == p1);  // the digest as docs/cli.md defines it
  REQUIRE(run("synth merge part1.json part2.json part3.json -o all.json", dir, true).status == 0);
  // Solutions are lines "  {...}" (",") between the first line and the last ("], ...").
  REQUIRE(contains(p1, "\n  {"));
  REQUIRE(contains(p3, "\n  {"));
  // The first train of part 3 (its ratios come after part 1's) appended to part 1's trains.
  std::string train3 = line_of(p3, 1);
  if (train3.back() == ',') train3.pop_back();
  const std::string n3 = train_of(train3)["n"];
  std::string moved = p1;
  moved.insert(moved.rfind("\n], "), ",\n" + train3);
  struct Edit {
    std::string name, text, part_of;
    std::vector<std::string> words;
  };
  const std::vector<Edit> edits{
      {"undecided.json", resigned(with_member(p2, "undecided_boxes", "-1")), "2", {"undecided_boxes", "-1"}},
      {"incomplete.json", resigned(with_member(p2, "undecided_boxes", "5")), "2", {"undecided_boxes", "5", "complete"}},
      {"moved.json", resigned(moved), "1", {"n = " + n3}},
      {"a2.json", resigned(with_line(p1, 1, [](const std::string& l) { return with_member(l, "a2", "7"); })), "1", {"a2", "7"}},
      {"counts.json", resigned(with_line(p1, 1, [](const std::string& l) { return with_member(l, "tangencies", "1"); })), "1",
       {"counts"}},
      {"n.json", resigned(with_line(p1, 1, [](const std::string& l) { return with_member(l, "n", "\"-6/2\""); })), "1", {"-6/2"}},
      // A member twice (a reader keeping the first would see lower 0.3 > upper), a number JSON has not.
      {"twice.json", resigned(with_line(p1, 1, [](std::string l) { return l.insert(l.find("\"lower\": "), "\"lower\": 0.3, "); })), "1",
       {"\"lower\"", "twice"}},
      {"nan.json", resigned(with_line(p1, 1, [](const std::string& l) { return with_member(l, "residual", "NaN"); })), "1",
       {"not JSON", "NaN"}}};
  for (const Edit& e : edits) {
    write_text(dir, e.name, e.text);
    std::string args;
    for (const char* i : {"1", "2", "3"}) args += std::string(" ") + (e.part_of == i ? e.name : "part" + std::string(i) + ".json");
    check_merge_refused(dir, args, e.name, e.words);
  }
}

TEST_CASE("cli synth merge: a part relabelled to another shard count is named with the counts that differ", "[cli][synth][errors]") {
  TempDir dir;
  REQUIRE(run("trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 40 -o t.csv", dir, true).status == 0);
  REQUIRE(shell("(echo x,y,z; sed -n '3p;12p;30p' t.csv | cut -d, -f2-4) > pts.csv", dir).status == 0);
  for (int i = 1; i <= 3; ++i)
    REQUIRE(run("synth points --input pts.csv --ratios 2,2 --json --shard " + std::to_string(i) + "/3 -o part" + std::to_string(i) + ".json",
                dir, true).status == 0);
  const std::string p1 = slurp(dir.path / "part1.json");
  REQUIRE(contains(p1, "\"shard\": \"1/3\""));
  const std::string relabelled = with_member(p1, "shard", "\"1/4\"");
  for (const std::string& text : {relabelled, resigned(relabelled)}) {
    write_text(dir, "four.json", text);
    // Parts 2/3 and 3/3 say K = 3: the part that says 4 is named, with "1/4", 4 and 3.
    check_merge_refused(dir, "part3.json four.json part2.json", "four.json", {"\"1/4\"", "4 parts", "3"});
    const Result r = run("synth merge part3.json four.json part2.json", dir, true);
    CHECK_FALSE(contains(r.err, "\"ratios\": \"2,2\", not"));
  }
}
