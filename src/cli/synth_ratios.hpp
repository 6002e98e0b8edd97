// The ratio set of a synth command (--n R | --teeth ZS:ZP | --ratios P,Q | --teeth MIN..MAX, with
// --shard I/K for a set; read by io/ratio_set.hpp), shared by `synth points` and `synth fit`, and
// the headers and trains of their parts (shard_parts.hpp holds what every part file shares).
#pragma once

#include "cli_common.hpp"
#include "shard_parts.hpp"

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/ratio_set.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch::cli {

/// The JSON member that names a ratio set in a run's output: "ratios": "P,Q" or "teeth": "MIN..MAX".
inline std::string set_member(const std::string& name, const std::string& text) {
  return "\"" + name + "\": \"" + text + "\"";
}

/// The ratios of --n, --teeth (ZS:ZP, or a range MIN..MAX) or --ratios [--shard] (io/ratio_set.hpp);
/// refused (InvalidInput) when their work (ratio_work) exceeds max_work, `command`'s bound.
inline RatioSet requested_ratios(const std::string& command, const RatioRequestText& request, double max_work) {
  if (int(!request.n.empty()) + int(!request.ratios.empty()) + int(!request.teeth.empty()) != 1)
    throw UsageError{command + ": give exactly one of --n R, --teeth ZS:ZP|MIN..MAX and --ratios P,Q (see docs/cli.md: " +
                     command + ")"};
  if (!request.shard.empty() && !names_a_set(request))
    throw UsageError{"--shard = " + request.shard + ": shards a ratio set; valid: with --ratios P,Q or --teeth MIN..MAX"};
  const RatioSet r = parse_ratio_set(request);
  const std::string field = !request.n.empty() ? "n" : !request.ratios.empty() ? "ratios" : "teeth";
  const std::string& given = !request.n.empty() ? request.n : !request.ratios.empty() ? request.ratios : request.teeth;
  check_ratio_work(r, field, given, max_work);
  return r;
}

/// A fingerprint (FNV-1a, 64 bits, hex) of what a run of a synth command computed from: its
/// points and `options` (the options as parsed), so that `synth merge` joins only shards of one run.
inline std::string run_fingerprint(const std::vector<Vector3d>& points, const std::string& options) {
  std::uint64_t h = 14695981039346656037ull;
  for (const Vector3d& p : points) h = fnv1a(p.data(), 3 * sizeof(double), h);
  return hex16(fnv1a(options.data(), options.size(), h));
}

/// What a shard's JSON says of itself: its set (as its JSON member, set_member), I of K, and the
/// ratios of the set that are its own.
struct ShardHeader {
  std::string set, set_name, set_text;  // set = set_member(set_name, set_text)
  std::size_t index = 0, count = 0;
  std::vector<Ratio> own;           // this part's ratios, in the set's order
  std::optional<ToothRange> teeth;  // the set is a tooth range: what each train echoes
};

/// The header of a shard of synth points / fit (member "ratios" or "teeth", "shard"), checked:
/// the set and "I/K" written as a run writes them; InvalidInput or a JSON exception otherwise.
inline ShardHeader read_shard_header(const nlohmann::json& j) {
  if (j.contains("teeth") && j.contains("ratios"))
    throw InvalidInput("shard", "teeth and ratios", "two ratio sets", "one of \"ratios\" and \"teeth\", as the run writes it");
  const std::string name = j.contains("teeth") ? "teeth" : "ratios";
  const std::string text = j.at(name).get<std::string>();
  const std::string shard = j.at("shard").get<std::string>();
  const std::vector<Ratio> set = named_ratio_set(name, text);
  const auto [begin, end] = shard_range(shard, set.size());
  const auto slash = shard.find('/');
  ShardHeader h{set_member(name, text), name, text, parse_count(shard.substr(0, slash), "shard", 1, 1000000),
                parse_count(shard.substr(slash + 1), "shard", 1, 1000000),
                std::vector<Ratio>(set.begin() + static_cast<std::ptrdiff_t>(begin), set.begin() + static_cast<std::ptrdiff_t>(end)),
                std::nullopt};
  if (shard != std::to_string(h.index) + "/" + std::to_string(h.count))
    throw InvalidInput("shard", shard, "not written as the run writes it", "I/K");
  if (name == "teeth") h.teeth = parse_tooth_range(text, "teeth");
  return h;
}

/// The "n" of a train of a part: a ratio written as the run writes it (5/2, not 10/4 or 2.5).
inline Ratio ratio_member(const nlohmann::json& train, const std::string& where) {
  const nlohmann::json& v = train.at("n");
  const std::string text = v.is_string() ? v.get<std::string>() : brief_json(v);
  const Ratio n = parse_ratio(text, "n");
  if (!v.is_string() || n.str() != text) throw InvalidInput("shard", where + "\"n\" " + brief_json(v), "not written as the run writes it", "p/q in lowest terms, q > 0 (q = 1: p)");
  return n;
}

/// The position of n among a part's own ratios; InvalidInput "shard" when it is not one of them.
inline std::size_t own_ratio_index(const ShardHeader& h, const Ratio& n, const std::string& where) {
  const auto it = std::find(h.own.begin(), h.own.end(), n);
  if (it == h.own.end()) {
    const std::string range = h.own.empty() ? "none" : h.own.front().str() + " .. " + h.own.back().str();
    throw InvalidInput("shard", where + "n = " + n.str(), "not one of this part's ratios",
                       "the ratios of shard " + std::to_string(h.index) + "/" + std::to_string(h.count) + " of " + h.set +
                           ": " + std::to_string(h.own.size()) + " ratio(s), " + range);
  }
  return static_cast<std::size_t>(it - h.own.begin());
}

/// Refuses (InvalidInput "shard") a train's "teeth" member that is not what the run writes: the
/// smallest pair of the range for its n, and none without a range.
inline void check_train_teeth(const nlohmann::json& train, const Ratio& n, const std::optional<ToothRange>& range) {
  const auto expected = range ? smallest_teeth(n, *range) : std::nullopt;
  const bool ok = expected ? train.contains("teeth") && train.at("teeth") == expected->str() : !train.contains("teeth");
  if (!ok) throw InvalidInput("shard", "teeth of n = " + n.str(), "not what the run writes", "the smallest tooth pair in the range");
}

/// --input, --n, --ratios and --shard (--slice) of a synth command over a ratio set.
inline void add_ratio_set_options(CLI::App& cmd, std::string& input, std::string& n, std::string& ratios,
                                  std::string& teeth, std::string& shard, const std::string& what) {
  cmd.add_option("--input", input, what + " (CSV x,y,z or .npy; - for standard input)")->type_name("FILE")->required();
  cmd.add_option("--n", n, "the gear ratio p/q")->type_name("P/Q");
  cmd.add_option("--ratios", ratios, "every ratio p/q with |p| <= P, q <= Q, both signs")->type_name("P,Q");
  cmd.add_option("--teeth", teeth,
                 "ZS:ZP, sun:planet tooth counts (n = ZS/ZP; ZS < 0: internal), or MIN..MAX: every n = +-ZS/ZP "
                 "with both counts in the range")->type_name("ZS:ZP|MIN..MAX");
  cmd.add_option("--shard,--slice", shard, "only part I of K of the ratio set (join the JSON parts with synth merge)")->type_name("I/K");
}

}  // namespace sphtroch::cli
