// tests/fuzz/fuzz_synth_merge.cpp — `sphtroch synth merge`: the readers of the JSON shards of
// `synth points` and `synth fit` (--ratios P,Q | --teeth MIN..MAX --shard I/K --json) and their
// join. Run through the tool's own registration and dispatch (register_synth, as main.cpp does),
// so the target follows the command whatever its readers become.
//
// Input: up to 8 shard files separated by NUL bytes, written to a scratch directory and merged
// with `synth merge -o OUT SHARD...`; then again with the shards in the reverse order. A part
// carries "digest": the FNV-1a (64 bits) of its bytes with the digest's 16 digits as zeros
// (synth_ratios.hpp: signed_part), so nearly every mutation is refused as "edited"; for three
// inputs in four (by a hash of the bytes) the harness signs each part again, as the run would,
// so that the members behind the digest are reached. FUZZ_VERBOSE=1 prints each merge's result.
// Expected: sphtroch::InvalidInput (a one-line problem and valid form), UsageError (a non-empty
// message) or UncertifiedResult (exit 3: the output is written, complete, and says so); the two
// orders agree (both merge, to the same bytes, or both refuse: "shards in any order"); a merge
// writes one JSON object that is itself no shard (merging it alone is refused). Anything else
// thrown (a JSON library exception, std::out_of_range, an output error ...) crashes: the tool
// would report it as an internal error (exit 1) instead of a one-line input error (exit 2).
#include "fuzz_common.hpp"
#include "fuzz_files.hpp"

#include "cli_common.hpp"

#include "sphtroch/core/errors.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

using sphtroch::InvalidInput;
using sphtroch::cli::UncertifiedResult;
using sphtroch::cli::UsageError;

enum class Result { merged, uncertified, refused };

const bool verbose = std::getenv("FUZZ_VERBOSE") != nullptr;

/// `part` with the 16 digits after its one `"digest": "` replaced by the FNV-1a of the part
/// with them as zeros (what signed_part writes); unchanged without exactly one such member.
std::string signed_again(std::string part) {
  const std::string key = "\"digest\": \"";
  const std::size_t at = part.find(key);
  if (at == std::string::npos || part.find(key, at + 1) != std::string::npos || part.size() < at + key.size() + 16) return part;
  part.replace(at + key.size(), 16, std::string(16, '0'));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fuzz::fnv1a(part)));
  part.replace(at + key.size(), 16, hex);
  return part;
}

/// `sphtroch synth merge -o OUT PATHS...` as main() runs it: parse, then the selected action.
Result merge(const std::vector<std::string>& paths, const std::string& out) {
  CLI::App app{"sphtroch (fuzz)", "sphtroch"};
  app.require_subcommand(1);
  app.option_defaults()->disable_flag_override();
  std::vector<std::pair<CLI::App*, sphtroch::cli::Action>> actions;
  sphtroch::cli::register_synth(app, actions);
  std::vector<std::string> args{"sphtroch", "synth", "merge", "-o", out};
  args.insert(args.end(), paths.begin(), paths.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  app.parse(static_cast<int>(argv.size()), argv.data());  // our own words: a CLI::ParseError is a bug here
  try {
    std::size_t ran = 0;
    for (auto& [command, action] : actions)
      if (command->parsed()) {
        ++ran;
        action();
      }
    FUZZ_CHECK(ran == 1);
    if (verbose) std::fprintf(stderr, "merged\n");
    return Result::merged;
  } catch (const InvalidInput& e) {
    if (verbose) std::fprintf(stderr, "merge refused: %s\n", e.what());
    FUZZ_CHECK(!e.field().empty() && fuzz::one_line(e.problem()) && fuzz::one_line(e.valid_range()));
  } catch (const UsageError& e) {
    if (verbose) std::fprintf(stderr, "merge refused: %s\n", e.message.c_str());
    FUZZ_CHECK(!e.message.empty());
  } catch (const UncertifiedResult& e) {
    if (verbose) std::fprintf(stderr, "merge uncertified: %s\n", e.message.c_str());
    FUZZ_CHECK(!e.message.empty());
    return Result::uncertified;  // after the output was written
  }
  return Result::refused;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const bool sign = fuzz::fnv1a(input) % 4 != 0;
  std::vector<std::string> paths;
  for (std::size_t start = 0; paths.size() < 8;) {
    const std::size_t nul = input.find('\0', start);
    const std::string_view shard = input.substr(start, nul == std::string_view::npos ? std::string_view::npos : nul - start);
    const std::string name = "shard" + std::to_string(paths.size()) + ".json";
    paths.push_back(fuzz::write_file(name, sign ? signed_again(std::string(shard)) : std::string(shard)));
    if (nul == std::string_view::npos) break;
    start = nul + 1;
  }

  const std::string out = fuzz::scratch_dir() + "/merged.json";
  const std::string out_reversed = fuzz::scratch_dir() + "/merged-reversed.json";
  ::unlink(out.c_str());
  ::unlink(out_reversed.c_str());
  const Result forward = merge(paths, out);
  const Result backward = merge(std::vector<std::string>(paths.rbegin(), paths.rend()), out_reversed);
  FUZZ_CHECK(forward == backward);
  std::string merged, merged_reversed;
  if (forward == Result::refused) {
    FUZZ_CHECK(!fuzz::read_file(out, merged) && !fuzz::read_file(out_reversed, merged_reversed));  // nothing written
    return 0;
  }
  FUZZ_CHECK(fuzz::read_file(out, merged) && fuzz::read_file(out_reversed, merged_reversed));
  FUZZ_CHECK(merged == merged_reversed);
  FUZZ_CHECK(!merged.empty() && merged.back() == '\n');
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(merged);
  } catch (const nlohmann::json::exception&) {
    FUZZ_CHECK(!"the merged output is JSON");
  }
  FUZZ_CHECK(j.is_object() && !j.contains("shard") && !j.contains("run"));
  FUZZ_CHECK(j.contains("solutions") != j.contains("candidates"));
  FUZZ_CHECK(j.contains("ratios") != j.contains("teeth"));
  // The joined output is what the unsharded run prints: no shard, so merging it is refused.
  const std::string again = fuzz::scratch_dir() + "/merged-again.json";
  ::unlink(again.c_str());
  FUZZ_CHECK(merge({out}, again) == Result::refused);
  return 0;
}
