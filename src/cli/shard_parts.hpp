// The part files of a divided run (--shard I/K), shared by `synth merge` and `clinostat merge`:
// a part's digest (FNV-1a 64 of its bytes, so an edited part shows), its JSON read strictly
// (no repeated member, finite decimal numbers), member and value checks that name what is wrong,
// and the check that a set of parts is I = 1..K of one run, each once.
#pragma once

#include "cli_common.hpp"

#include "sphtroch/core/number_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch::cli {

/// FNV-1a (64 bits) of `size` bytes, continuing from `h` (the offset basis by default).
inline std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t h = 14695981039346656037ull) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ b[i]) * 1099511628211ull;
  return h;
}

/// 64 bits as 16 lowercase hex digits.
inline std::string hex16(std::uint64_t h) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

/// True for 16 lowercase hex digits (a fingerprint or a digest as a run writes it).
inline bool is_hex16(const std::string& s) {
  return s.size() == 16 && s.find_first_not_of("0123456789abcdef") == std::string::npos;
}

/// The "digest" member of a part (a shard's JSON): written as 16 zeros among the part's first
/// members, then filled in by signed_part with the FNV-1a (64 bits) of the whole part as it is
/// with those zeros. `synth merge` recomputes it: any edit of a part's bytes shows.
inline const std::string kDigestKey = "\"digest\": \"";
inline std::string digest_placeholder() { return kDigestKey + std::string(16, '0') + "\", "; }

/// `text`, a whole part holding "digest": "0000000000000000" once, with its digest filled in.
inline std::string signed_part(std::string text) {
  const auto at = text.find(kDigestKey + std::string(16, '0')) + kDigestKey.size();
  text.replace(at, 16, hex16(fnv1a(text.data(), text.size())));
  return text;
}

/// Refuses (InvalidInput "shard" = path) a part whose "digest" is not the FNV-1a of its bytes
/// with the digest's 16 digits as zeros (see signed_part): a part edited after its run.
inline void check_part_digest(const std::string& path, const std::string& text, const std::string& recorded,
                              const std::string& valid) {
  const auto at = text.find(kDigestKey);
  if (at == std::string::npos || text.find(kDigestKey, at + 1) != std::string::npos ||
      text.compare(at + kDigestKey.size(), 16, recorded) != 0)
    throw InvalidInput("shard", path, "its \"digest\" is not one member as the run writes it", valid);
  std::string zeroed = text;
  zeroed.replace(at + kDigestKey.size(), 16, std::string(16, '0'));
  const std::string computed = hex16(fnv1a(zeroed.data(), zeroed.size()));
  if (computed != recorded)
    throw InvalidInput("shard", path,
                       "its bytes do not match its \"digest\": they hash to " + computed + ", the digest says " + recorded +
                           " (FNV-1a 64 of the part with the digest's 16 digits as 0): edited after its run",
                       valid);
}

constexpr int kMaxPartDepth = 16;

/// A part's text parsed as JSON, refusing (InvalidInput "shard") what the run never writes and a
/// reader would take in more than one way: a member given twice in one object (nlohmann keeps the
/// last, another reader the first), and text that is not JSON (named by its byte offset and the
/// bytes there, control and non-ASCII bytes as '?': NaN, Infinity, 0x1p-3 ...).
inline nlohmann::json parse_part_json(const std::string& text) {
  std::vector<std::vector<std::string>> keys;  // the member names seen in each open object
  const auto check = [&keys](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (depth > kMaxPartDepth)  // parts nest 5 deep; copying or printing a deeper value recurses without bound
      throw InvalidInput("shard", "nesting depth " + std::to_string(depth), "deeper than a part", "JSON nested at most 16 levels");
    if (event == E::object_start) keys.emplace_back();
    if (event == E::object_end && !keys.empty()) keys.pop_back();
    if (event == E::key && !keys.empty()) {
      const std::string name = parsed.get<std::string>();
      if (std::find(keys.back().begin(), keys.back().end(), name) != keys.back().end())
        throw InvalidInput("shard", "member \"" + name + "\" given twice in one object", "a repeated member", "each member once, as the run writes it");
      keys.back().push_back(name);
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, check);
  } catch (const nlohmann::json::parse_error& e) {
    const std::size_t at = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    std::string near = text.substr(at >= 12 ? at - 12 : 0, 24);
    for (char& c : near)  // printable ASCII only: the message stays one line whatever the bytes
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
    throw InvalidInput("shard", "byte " + std::to_string(e.byte) + " (near \"" + near + "\")", "not JSON",
                       "JSON as the run writes it: numbers finite and decimal, no NaN or Infinity");
  }
}

/// Refuses (InvalidInput "shard") a JSON object whose members are not exactly `names`.
inline void check_members(const nlohmann::json& j, const std::string& where, const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  bool ok = j.is_object() && j.size() == names.size();
  for (const std::string& n : names) ok = ok && j.contains(n);
  if (!ok) throw InvalidInput("shard", where, "not the members the run writes", "exactly the members " + list);
}

/// A JSON value as text for a message: at most 60 bytes of it, then "...".
inline std::string brief_json(const nlohmann::json& v) {
  const std::string text = v.dump();
  return text.size() <= 60 ? text : text.substr(0, 60) + "...";
}

/// The number v inside [lo, hi] (InvalidInput "shard" = what and v otherwise).
inline double checked_number(const nlohmann::json& v, const std::string& what, double lo, double hi) {
  const double x = v.is_number() ? v.get<double>() : std::nan("");
  if (!(x >= lo && x <= hi))
    throw InvalidInput("shard", what + " " + brief_json(v), v.is_number() ? "out of range" : "not a number",
                       "a number in [" + number_text(lo) + ", " + number_text(hi) + "]");
  return x;
}

/// A number member `key` of `j` inside [lo, hi] (InvalidInput "shard" naming it and its value otherwise).
inline double number_member(const nlohmann::json& j, const std::string& where, const std::string& key, double lo, double hi) {
  return checked_number(j.at(key), where + "\"" + key + "\"", lo, hi);
}

/// Element i of the array j inside [lo, hi].
inline double number_member(const nlohmann::json& j, const std::string& where, std::size_t i, double lo, double hi) {
  return checked_number(j.at(i), where + "[" + std::to_string(i) + "]", lo, hi);
}

/// A count member `key` of `j`: an integer >= 0 (not -3, 2.5 or 1e20), InvalidInput "shard" otherwise.
inline std::size_t count_member(const nlohmann::json& j, const std::string& where, const std::string& key) {
  const nlohmann::json& v = j.at(key);
  if (!v.is_number_unsigned()) throw InvalidInput("shard", where + "\"" + key + "\" " + brief_json(v), "not a count", "an integer >= 0");
  return v.get<std::size_t>();
}

/// A boolean member `key` of `j`, InvalidInput "shard" otherwise.
inline bool bool_member(const nlohmann::json& j, const std::string& where, const std::string& key) {
  const nlohmann::json& v = j.at(key);
  if (!v.is_boolean()) throw InvalidInput("shard", where + "\"" + key + "\" " + brief_json(v), "not true or false", "true or false");
  return v.get<bool>();
}

/// What names one shard of a ratio-set run: its file, I of K, and the members that every part
/// of one run writes alike (JSON name, value as JSON text: the set, "run", ...).
struct ShardName {
  std::string path;
  std::size_t index = 0, count = 0;
  std::vector<std::pair<std::string, std::string>> members;
};

/// Refuses (InvalidInput "shard") a set of shards, sorted by index, that is not I = 1..K of one
/// run, each once. A part whose K or member differs from what most parts say is named, with what
/// differs and a part that says otherwise.
inline void check_shard_set(const std::vector<ShardName>& shards) {
  const std::string valid = "every shard I/K of one run, I = 1..K, each once";
  auto shard_text = [](const ShardName& s) { return "\"shard\": \"" + std::to_string(s.index) + "/" + std::to_string(s.count) + "\""; };
  // The value most parts have (ties: the lowest shard's); returns a part that has it.
  auto most = [&shards](auto value) {
    std::size_t best = 0, best_votes = 0;
    for (std::size_t a = 0; a < shards.size(); ++a) {
      std::size_t votes = 0;
      for (const ShardName& b : shards) votes += value(b) == value(shards[a]);
      if (votes > best_votes) best = a, best_votes = votes;
    }
    return shards[best];
  };
  const ShardName& by_count = most([](const ShardName& s) { return s.count; });
  for (const ShardName& s : shards)
    if (s.count != by_count.count)
      throw InvalidInput("shard", s.path,
                         "its shard count differs: " + shard_text(s) + " is one of " + std::to_string(s.count) + " parts, " +
                             by_count.path + "'s " + shard_text(by_count) + " one of " + std::to_string(by_count.count),
                         valid);
  for (std::size_t m = 0; m < shards[0].members.size(); ++m) {
    const ShardName& usual = most([m](const ShardName& s) { return s.members[m].second; });
    for (const ShardName& s : shards)
      if (s.members[m] != usual.members[m])
        throw InvalidInput("shard", s.path,
                           "from another run: its \"" + s.members[m].first + "\": " + s.members[m].second + ", " + usual.path +
                               "'s \"" + usual.members[m].first + "\": " + usual.members[m].second,
                           valid);
  }
  for (std::size_t k = 0; k < shards.size(); ++k) {
    const ShardName& s = shards[k];
    if (k > 0 && s.index == shards[k - 1].index)
      throw InvalidInput("shard", s.path, shard_text(s) + " given twice (also " + shards[k - 1].path + ")", valid);
    if (s.index != k + 1) throw InvalidInput("shard", std::to_string(k + 1) + "/" + std::to_string(s.count), "missing", valid);
  }
  if (shards.back().index != shards.back().count)
    throw InvalidInput("shard", std::to_string(shards.size() + 1) + "/" + std::to_string(shards[0].count), "missing", valid);
}

}  // namespace sphtroch::cli
