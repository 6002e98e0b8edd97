// The ratio set of a synth command (--n R | --ratios P,Q [--shard I/K]), shared by `synth points`
// and `synth fit`, with the work bound each command states. Parsing only.
#pragma once

#include "cli_common.hpp"

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/io/parse.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch::cli {

/// The ratios to solve and the JSON members that name them ("ratios", "shard").
struct RatioRequest {
  std::vector<Ratio> ratios;
  std::string json_fields;
};

/// --shard I/K of a ratio set of `size`: indices floor((I-1) size / K) .. floor(I size / K) - 1.
inline std::pair<std::size_t, std::size_t> shard_range(const std::string& text, std::size_t size) {
  const std::string valid = "I/K with 1 <= I <= K <= 1000000";
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw InvalidInput("shard", text, "not I/K", valid);
  try {
    const std::size_t k = parse_count(text.substr(slash + 1), "shard", 1, 1000000);
    const std::size_t i = parse_count(text.substr(0, slash), "shard", 1, k);
    return {(i - 1) * size / k, i * size / k};
  } catch (const InvalidInput& e) {  // name the whole I/K, not the part
    throw InvalidInput("shard", text, e.problem() + " (" + e.value() + ")", valid);
  }
}

/// The ratios of --n or --ratios [--shard]; refused (InvalidInput) when the sum over them of
/// (|p| + q)^2 exceeds max_work, the estimate of `command`'s cost.
inline RatioRequest requested_ratios(const std::string& command, const std::string& n, const std::string& ratios,
                                     const std::string& shard, double max_work) {
  if (n.empty() == ratios.empty())
    throw UsageError{command + ": give exactly one of --n R and --ratios P,Q (see docs/cli.md: " + command + ")"};
  if (!shard.empty() && ratios.empty())
    throw UsageError{"--shard = " + shard + ": shards a ratio set; valid: with --ratios P,Q"};
  RatioRequest r;
  if (!n.empty()) {
    r.ratios.push_back(parse_ratio(n, "n"));
  } else {
    const auto comma = ratios.find(',');
    if (comma == std::string::npos)
      throw InvalidInput("ratios", ratios, "not two counts P,Q", "P,Q: every p/q with 1 <= |p| <= P, 1 <= q <= Q");
    const std::size_t p = parse_count(ratios.substr(0, comma), "ratios", 1, 1000);
    const std::size_t q = parse_count(ratios.substr(comma + 1), "ratios", 1, 1000);
    r.ratios = ratio_set(static_cast<std::int64_t>(p), static_cast<std::int64_t>(q));
    r.json_fields = "\"ratios\": \"" + std::to_string(p) + "," + std::to_string(q) + "\", ";
    if (!shard.empty()) {
      const auto [begin, end] = shard_range(shard, r.ratios.size());
      r.ratios = std::vector<Ratio>(r.ratios.begin() + begin, r.ratios.begin() + end);
      r.json_fields += "\"shard\": \"" + shard + "\", ";
    }
  }
  double work = 0;
  for (const Ratio& k : r.ratios) work += std::pow(double(k.abs_p() + k.q()), 2);
  if (work > max_work)
    throw InvalidInput(n.empty() ? "ratios" : "n", n.empty() ? ratios : n,
                       "estimated work " + number_text(work) + " over the bound" + (shard.empty() ? "" : " for this shard"),
                       "sum over the ratios of (|p| + q)^2 <= " + number_text(max_work) +
                           " (--ratios 7,7 is 4832; --shard I/K splits a set)");
  return r;
}

/// A fingerprint (FNV-1a, 64 bits, hex) of what a run of a synth command computed from: its
/// points and `options` (the options as parsed), so that `synth merge` joins only shards of one run.
inline std::string run_fingerprint(const std::vector<Vector3d>& points, const std::string& options) {
  std::uint64_t h = 14695981039346656037ull;
  auto mix = [&h](const void* data, std::size_t size) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  for (const Vector3d& p : points) mix(p.data(), 3 * sizeof(double));
  mix(options.data(), options.size());
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

/// The number of ratios of shard I/K of --ratios P,Q, or refuses (InvalidInput) a shard name
/// that is not the canonical "I/K" of that set.
inline std::size_t shard_ratio_count(const std::string& ratios, const std::string& shard) {
  const auto comma = ratios.find(',');
  const std::size_t p = parse_count(ratios.substr(0, comma), "ratios", 1, 1000);
  const std::size_t q = parse_count(comma == std::string::npos ? "" : ratios.substr(comma + 1), "ratios", 1, 1000);
  if (ratios != std::to_string(p) + "," + std::to_string(q)) throw InvalidInput("ratios", ratios, "not P,Q", "P,Q as written by the run");
  const auto [begin, end] = shard_range(shard, ratio_set(static_cast<std::int64_t>(p), static_cast<std::int64_t>(q)).size());
  const auto slash = shard.find('/');
  if (shard != std::to_string(parse_count(shard.substr(0, slash), "shard", 1, 1000000)) + shard.substr(slash))
    throw InvalidInput("shard", shard, "not written as the run writes it", "I/K");
  return end - begin;
}

/// What names one shard of a ratio-set run: the set, I of K, and `run` (anything else that
/// must agree between the shards of one run, e.g. the candidate bound).
struct ShardName {
  std::string ratios;
  std::size_t index = 0, count = 0;
  std::string run;
};

/// Refuses (InvalidInput "shard") a set of shards, sorted by index, that is not I = 1..K of one
/// run, each once.
inline void check_shard_set(const std::vector<ShardName>& shards) {
  const std::string valid = "every shard I/K of one run, I = 1..K, each once";
  for (std::size_t k = 0; k < shards.size(); ++k) {
    const ShardName& s = shards[k];
    const std::string name = std::to_string(s.index) + "/" + std::to_string(s.count);
    if (s.ratios != shards[0].ratios || s.count != shards[0].count)
      throw InvalidInput("shard", name, "from another run (--ratios " + s.ratios + ", not " + shards[0].ratios + ")", valid);
    if (s.run != shards[0].run)
      throw InvalidInput("shard", name, "from another run (other points or options than shard " +
                                            std::to_string(shards[0].index) + "/" + std::to_string(shards[0].count) + ")", valid);
    if (k > 0 && s.index == shards[k - 1].index) throw InvalidInput("shard", name, "given twice", valid);
    if (s.index != k + 1) throw InvalidInput("shard", std::to_string(k + 1) + "/" + std::to_string(s.count), "missing", valid);
  }
  if (shards.back().index != shards.back().count)
    throw InvalidInput("shard", std::to_string(shards.size() + 1) + "/" + std::to_string(shards[0].count), "missing", valid);
}

/// --input, --n, --ratios and --shard (--slice) of a synth command over a ratio set.
inline void add_ratio_set_options(CLI::App& cmd, std::string& input, std::string& n, std::string& ratios,
                                  std::string& shard, const std::string& what) {
  cmd.add_option("--input", input, what + " (CSV x,y,z or .npy; - for standard input)")->required();
  cmd.add_option("--n", n, "the gear ratio p/q");
  cmd.add_option("--ratios", ratios, "every ratio p/q with |p| <= P, q <= Q, both signs");
  cmd.add_option("--shard,--slice", shard, "only part I of K of the ratio set (join the JSON parts with synth merge)");
}

/// The arguments that make `sphtroch trace` / `plot` draw this train.
inline std::string train_arguments(const GearTrain& g) {
  return "--n " + g.ratio().str() + " --a2 " + number_text(g.a2()) + " --a3 " + number_text(g.a3()) + " --phase " +
         number_text(g.phase_given());
}

}  // namespace sphtroch::cli
