// The ratio set of a synth command (--n R | --teeth ZS:ZP | --ratios P,Q | --teeth MIN..MAX, with
// --shard I/K for a set), shared by `synth points` and `synth fit`, with the work bound each
// command states. Parsing only.
#pragma once

#include "cli_common.hpp"

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/io/parse.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch::cli {

/// The ratios to solve, the JSON members that name them ("ratios" or "teeth", "shard"), and the
/// teeth each report echoes.
struct RatioRequest {
  std::vector<Ratio> ratios;
  std::string json_fields;
  TeethSpec teeth;
};

/// The JSON member that names a ratio set in a run's output: "ratios": "P,Q" or "teeth": "MIN..MAX".
inline std::string set_member(const std::string& name, const std::string& text) {
  return "\"" + name + "\": \"" + text + "\"";
}

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

/// The set of --ratios P,Q (name "ratios") or --teeth MIN..MAX (name "teeth"), refused
/// (InvalidInput) unless `text` is written as a run writes it (canonical), so shards compare by text.
inline std::vector<Ratio> named_ratio_set(const std::string& name, const std::string& text) {
  if (name == "teeth") {
    const ToothRange range = parse_tooth_range(text, "teeth");
    if (text != range.str()) throw InvalidInput("teeth", text, "not MIN..MAX", "MIN..MAX as written by the run");
    return ratio_set(range);
  }
  const auto comma = text.find(',');
  if (comma == std::string::npos)
    throw InvalidInput("ratios", text, "not two counts P,Q", "P,Q: every p/q with 1 <= |p| <= P, 1 <= q <= Q");
  const std::size_t p = parse_count(text.substr(0, comma), "ratios", 1, 1000);
  const std::size_t q = parse_count(text.substr(comma + 1), "ratios", 1, 1000);
  if (text != std::to_string(p) + "," + std::to_string(q)) throw InvalidInput("ratios", text, "not P,Q", "P,Q as written by the run");
  return ratio_set(static_cast<std::int64_t>(p), static_cast<std::int64_t>(q));
}

/// The ratios of --n, --teeth (ZS:ZP, or a range MIN..MAX) or --ratios [--shard]; refused
/// (InvalidInput) when the sum over them of (|p| + q)^2 exceeds max_work, the estimate of `command`'s cost.
inline RatioRequest requested_ratios(const std::string& command, const std::string& n, const std::string& ratios,
                                     const std::string& teeth, const std::string& shard, double max_work) {
  if (int(!n.empty()) + int(!ratios.empty()) + int(!teeth.empty()) != 1)
    throw UsageError{command + ": give exactly one of --n R, --teeth ZS:ZP|MIN..MAX and --ratios P,Q (see docs/cli.md: " +
                     command + ")"};
  const bool is_set = !ratios.empty() || teeth.find("..") != std::string::npos;
  if (!shard.empty() && !is_set)
    throw UsageError{"--shard = " + shard + ": shards a ratio set; valid: with --ratios P,Q or --teeth MIN..MAX"};
  RatioRequest r;
  const std::string field = !n.empty() ? "n" : !ratios.empty() ? "ratios" : "teeth";
  const std::string& given = !n.empty() ? n : !ratios.empty() ? ratios : teeth;
  if (!n.empty()) {
    r.ratios.push_back(parse_ratio(n, "n"));
  } else if (!is_set) {
    r.teeth.pair = parse_teeth(teeth, "teeth");
    r.ratios.push_back(r.teeth.pair->ratio());
    r.json_fields = set_member("teeth", r.teeth.pair->str()) + ", ";
  } else {
    std::string canonical = ratios;
    if (!teeth.empty()) {
      r.teeth.range = parse_tooth_range(teeth, "teeth");
      canonical = r.teeth.range->str();
    } else {
      const auto [p, q] = parse_count_pair(ratios, "ratios", 1, 1000, "P,Q: every p/q with 1 <= |p| <= P, 1 <= q <= Q (each 1 .. 1000)");
      canonical = std::to_string(p) + "," + std::to_string(q);
    }
    r.ratios = named_ratio_set(field, canonical);
    r.json_fields = set_member(field, canonical) + ", ";
    if (!shard.empty()) {
      const auto [begin, end] = shard_range(shard, r.ratios.size());
      r.ratios = std::vector<Ratio>(r.ratios.begin() + begin, r.ratios.begin() + end);
      r.json_fields += "\"shard\": \"" + shard + "\", ";
    }
  }
  double work = 0;
  for (const Ratio& k : r.ratios) work += std::pow(double(k.abs_p() + k.q()), 2);
  if (work > max_work)
    throw InvalidInput(field, given,
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

/// What a shard's JSON says of itself: its set (as its JSON member, set_member), I of K, and how
/// many ratios of the set are its own.
struct ShardHeader {
  std::string set;
  std::size_t index = 0, count = 0, ratios = 0;
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
  const auto [begin, end] = shard_range(shard, named_ratio_set(name, text).size());
  const auto slash = shard.find('/');
  ShardHeader h{set_member(name, text), parse_count(shard.substr(0, slash), "shard", 1, 1000000),
                parse_count(shard.substr(slash + 1), "shard", 1, 1000000), end - begin, std::nullopt};
  if (shard != std::to_string(h.index) + "/" + std::to_string(h.count))
    throw InvalidInput("shard", shard, "not written as the run writes it", "I/K");
  if (name == "teeth") h.teeth = parse_tooth_range(text, "teeth");
  return h;
}

/// Refuses (InvalidInput "shard") a train's "teeth" member that is not what the run writes: the
/// smallest pair of the range for its n, and none without a range.
inline void check_train_teeth(const nlohmann::json& train, const Ratio& n, const std::optional<ToothRange>& range) {
  const auto expected = range ? smallest_teeth(n, *range) : std::nullopt;
  const bool ok = expected ? train.contains("teeth") && train.at("teeth") == expected->str() : !train.contains("teeth");
  if (!ok) throw InvalidInput("shard", "teeth of n = " + n.str(), "not what the run writes", "the smallest tooth pair in the range");
}

/// What names one shard of a ratio-set run: the set, I of K, and `run` (anything else that
/// must agree between the shards of one run, e.g. the candidate bound).
struct ShardName {
  std::string ratios;  // the set's JSON member (set_member)
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
      throw InvalidInput("shard", name, "from another run (" + s.ratios + ", not " + shards[0].ratios + ")", valid);
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
                                  std::string& teeth, std::string& shard, const std::string& what) {
  cmd.add_option("--input", input, what + " (CSV x,y,z or .npy; - for standard input)")->required();
  cmd.add_option("--n", n, "the gear ratio p/q");
  cmd.add_option("--ratios", ratios, "every ratio p/q with |p| <= P, q <= Q, both signs");
  cmd.add_option("--teeth", teeth,
                 "ZS:ZP, sun:planet tooth counts (n = ZS/ZP; ZS < 0: internal), or MIN..MAX: every n = +-ZS/ZP "
                 "with both counts in the range");
  cmd.add_option("--shard,--slice", shard, "only part I of K of the ratio set (join the JSON parts with synth merge)");
}

/// " (teeth 39:15)" when the report echoes teeth for n, else "".
inline std::string teeth_text(const TeethSpec& teeth, const Ratio& n) {
  const auto t = teeth.of(n);
  return t ? " (teeth " + t->str() + ")" : "";
}

/// The arguments that make `sphtroch trace` / `plot` draw this train.
inline std::string train_arguments(const GearTrain& g) {
  return "--n " + g.ratio().str() + " --a2 " + number_text(g.a2()) + " --a3 " + number_text(g.a3()) + " --phase " +
         number_text(g.phase_given());
}

}  // namespace sphtroch::cli
