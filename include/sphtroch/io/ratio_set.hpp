// sphtroch/io/ratio_set.hpp — the ratios an inverse-design request names, read the same way by
// every front end (the synth commands' --n, --teeth, --ratios and --shard; Python's n=, teeth=,
// ratios=; the explorer): one ratio, or a set in increasing order of n, or one shard of a set.
//
//   sphtroch::RatioSet s = sphtroch::parse_ratio_set({"", "3,2", "", "2/3"});  // --ratios 3,2 --shard 2/3
//   s.ratios;          // the shard's 3 of the set's 10: -1, -1/2, 1/2
//   s.json_members();  // "\"ratios\": \"3,2\", \"shard\": \"2/3\", " (a run's JSON names its set so)
//   sphtroch::check_ratio_work(s, "ratios", "3,2", sphtroch::kMaxPointsWork);  // fine: 22 <= 20000
//
// Forms: n as parse_ratio reads it; teeth "ZS:ZP" (one ratio, n = ZS/ZP) or "MIN..MAX" (every
// n = ±ZS/ZP in lowest terms with both counts in the range); ratios "P,Q" (every p/q in lowest
// terms with 1 <= |p| <= P, 1 <= q <= Q, both signs; P, Q <= 1000); shard "I/K" (1 <= I <= K <=
// 1e6) of a set: ratios floor((I - 1) R / K) .. floor(I R / K) - 1 of its R. Every failure throws
// InvalidInput naming the field, the text and the accepted forms.
#pragma once

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/io/parse.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// A request as typed: exactly one of n, ratios and teeth is non-empty; shard only with a set.
struct RatioRequestText {
  std::string n, ratios, teeth, shard;
};

/// The ratios a request names, and how a run's report names them.
struct RatioSet {
  std::vector<Ratio> ratios;  // one, or the set's (the shard's) in increasing order of n
  std::string set_name;       // "ratios" or "teeth" (a tooth pair or range); "" for n
  std::string set_text;       // canonical: "3,2", "12..60", "39:15" (as a run writes it)
  std::string shard;          // "I/K" or ""
  TeethSpec teeth;            // what each train's report echoes

  /// The JSON members that name the request, each followed by ", ": "" for n; "\"teeth\":
  /// \"39:15\", "; "\"ratios\": \"3,2\", \"shard\": \"2/3\", ". Canonical texts need no escaping.
  std::string json_members() const {
    std::string m = set_name.empty() ? "" : "\"" + set_name + "\": \"" + set_text + "\", ";
    return shard.empty() ? m : m + "\"shard\": \"" + shard + "\", ";
  }
};

/// The largest K of a ratio set's --shard I/K.
constexpr std::size_t kMaxRatioShards = 1000000;

/// Ratios [begin, end) of a set of `size` for "I/K" (core/shard.hpp's split; K <= kMaxRatioShards).
inline std::pair<std::size_t, std::size_t> shard_range(const std::string& text, std::size_t size) {
  return shard_range(size, parse_shard(text, kMaxRatioShards, std::to_string(kMaxRatioShards)));
}

/// The set "ratios" = "P,Q" or "teeth" = "MIN..MAX", refused (InvalidInput) unless `text` is
/// written as a run writes it (canonical), so that the parts of a sharded run compare by text.
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

/// The set of a request that names one (ratios, or teeth as a range), sharded when asked.
inline RatioSet parse_named_set(const RatioRequestText& request) {
  RatioSet r;
  r.set_name = request.teeth.empty() ? "ratios" : "teeth";
  if (!request.teeth.empty()) {
    r.teeth.range = parse_tooth_range(request.teeth, "teeth");
    r.set_text = r.teeth.range->str();
  } else {
    const auto [p, q] = parse_count_pair(request.ratios, "ratios", 1, 1000,
                                         "P,Q: every p/q with 1 <= |p| <= P, 1 <= q <= Q (each 1 .. 1000)");
    r.set_text = std::to_string(p) + "," + std::to_string(q);
  }
  r.ratios = named_ratio_set(r.set_name, r.set_text);
  if (!request.shard.empty()) {
    const auto [begin, end] = shard_range(request.shard, r.ratios.size());
    r.ratios = std::vector<Ratio>(r.ratios.begin() + static_cast<std::ptrdiff_t>(begin),
                                  r.ratios.begin() + static_cast<std::ptrdiff_t>(end));
    r.shard = request.shard;
  }
  return r;
}

/// Whether a request names a set (ratios, or a tooth range) rather than one ratio.
inline bool names_a_set(const RatioRequestText& request) {
  return !request.ratios.empty() || request.teeth.find("..") != std::string::npos;
}

/// The ratios of a request. REQUIRES (InvalidInput otherwise): exactly one of n, ratios and teeth;
/// shard only with a set.
inline RatioSet parse_ratio_set(const RatioRequestText& request) {
  const int given = int(!request.n.empty()) + int(!request.ratios.empty()) + int(!request.teeth.empty());
  if (given != 1)
    throw InvalidInput("n", request.n, given == 0 ? "no ratio given" : "more than one of n, teeth and ratios",
                       "exactly one of n (p/q), teeth (ZS:ZP or MIN..MAX) and ratios (P,Q)");
  if (!request.shard.empty() && !names_a_set(request))
    throw InvalidInput("shard", request.shard, "shards a ratio set", "with ratios P,Q or teeth MIN..MAX");
  if (names_a_set(request)) return parse_named_set(request);
  RatioSet r;
  if (!request.n.empty()) {
    r.ratios.push_back(parse_ratio(request.n, "n"));
    return r;
  }
  r.teeth.pair = parse_teeth(request.teeth, "teeth");
  r.ratios.push_back(r.teeth.pair->ratio());
  r.set_name = "teeth";
  r.set_text = r.teeth.pair->str();
  return r;
}

/// The estimated work of a set: the sum over its ratios of (|p| + q)^2 (core/cost_bounds.hpp).
inline double ratio_work(const std::vector<Ratio>& ratios) {
  double work = 0;
  for (const Ratio& k : ratios) work += double(k.abs_p() + k.q()) * double(k.abs_p() + k.q());
  return work;
}

/// Refuses (InvalidInput `field` = `given`) a set whose ratio_work exceeds `max_work`.
inline void check_ratio_work(const RatioSet& set, const std::string& field, const std::string& given, double max_work) {
  const double work = ratio_work(set.ratios);
  if (work > max_work)
    throw InvalidInput(field, given,
                       "estimated work " + number_text(work) + " over the bound" + (set.shard.empty() ? "" : " for this shard"),
                       "sum over the ratios of (|p| + q)^2 <= " + number_text(max_work) +
                           " (--ratios 3,3 is 208, 7,7 is 4832; --shard I/K splits a set)");
}

}  // namespace sphtroch
