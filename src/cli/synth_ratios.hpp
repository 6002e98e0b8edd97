// The ratio set of a synth command (--n R | --ratios P,Q [--shard I/K]), shared by `synth points`
// and `synth fit`, with the work bound each command states. Parsing only.
#pragma once

#include "cli_common.hpp"

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/io/parse.hpp"

#include <cmath>
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

/// The arguments that make `sphtroch trace` / `plot` draw this train.
inline std::string train_arguments(const GearTrain& g) {
  return "--n " + g.ratio().str() + " --a2 " + number_text(g.a2()) + " --a3 " + number_text(g.a3()) + " --phase " +
         number_text(g.phase_given());
}

}  // namespace sphtroch::cli
