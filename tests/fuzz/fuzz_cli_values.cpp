// tests/fuzz/fuzz_cli_values.cpp — the option values of the synth commands (and atlas --teeth):
// parse_teeth, parse_tooth_range, parse_unit_point (--node-at), parse_count and parse_count_pair
// (--threads, --ratios P,Q, --max-terms P,Q) from io/parse.hpp; from io/ratio_set.hpp the --shard
// I/K parser (shard_range) and the shard JSON's set (named_ratio_set); and the whole request
// (src/cli/synth_ratios.hpp's requested_ratios: --n, --ratios, --teeth, --shard).
//
// Input: lines separated by '\n'. Every line (at most 8) and the whole input go through every
// value parser; lines 1-4 are also --n, --ratios, --teeth and --shard of one request ("" = not
// given). shard_range sees set sizes from the input's hash (0 .. 2,000,000: the largest set,
// --teeth 1..1000, has about 1.2 million ratios).
// Expected: sphtroch::InvalidInput naming the option and the text exactly as given, with a
// problem and a one-line valid form (the problem may quote a part of the text: line breaks only
// when the text has one); sphtroch::cli::UsageError (a non-empty one-line message) for
// combinations. A parsed value lies in its documented range and prints as text that parses
// again to it. Anything else thrown crashes; a broken invariant traps.
#include "fuzz_common.hpp"
#include "fuzz_files.hpp"

#include "cli_common.hpp"
#include "synth_ratios.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/io/parse.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

using sphtroch::InvalidInput;
using sphtroch::Ratio;
using sphtroch::cli::UsageError;

bool has_line_break(std::string_view s) { return s.find_first_of("\r\n") != std::string_view::npos; }

/// An InvalidInput names `field` and the text as given; its problem quotes no line break the text
/// does not have; its valid form is one line.
void check_error(const InvalidInput& e, const std::string& field, const std::string& text) {
  FUZZ_CHECK(e.field() == field);
  FUZZ_CHECK(e.value() == text);
  FUZZ_CHECK(!e.problem().empty() && (!has_line_break(e.problem()) || has_line_break(text)));
  FUZZ_CHECK(fuzz::one_line(e.valid_range()));
}

/// The text of a count as parse_count reads it: digits only, leading zeros dropped.
std::string canonical_count(const std::string& text) {
  const std::size_t nz = text.find_first_not_of('0');
  return nz == std::string::npos ? "0" : text.substr(nz);
}

std::optional<sphtroch::Teeth> teeth(const std::string& text) {
  try {
    const sphtroch::Teeth t = sphtroch::parse_teeth(text, "teeth");
    FUZZ_CHECK(t.sun != 0 && std::abs(t.sun) <= sphtroch::kMaxTeeth);
    FUZZ_CHECK(t.planet >= 1 && t.planet <= sphtroch::kMaxTeeth);
    FUZZ_CHECK(t.ratio() == Ratio(t.sun, t.planet) && (t.ratio().p() < 0) == (t.sun < 0));
    const sphtroch::Teeth again = sphtroch::parse_teeth(t.str(), "teeth");  // "39:15" reads back
    FUZZ_CHECK(again.sun == t.sun && again.planet == t.planet);
    return t;
  } catch (const InvalidInput& e) {
    check_error(e, "teeth", text);
    return std::nullopt;
  }
}

/// A small set, built: increasing, both signs, each ratio's smallest pair inside the range.
void check_ratio_set(const sphtroch::ToothRange& r) {
  const std::vector<Ratio> set = sphtroch::ratio_set(r);
  FUZZ_CHECK(!set.empty() && set.size() % 2 == 0 && set.size() <= std::size_t(2 * r.max * r.max));
  for (std::size_t k = 0; k < set.size(); ++k) {
    if (k > 0) FUZZ_CHECK(set[k - 1].p() * set[k].q() < set[k].p() * set[k - 1].q());
    const auto t = sphtroch::smallest_teeth(set[k], r);
    FUZZ_CHECK(t.has_value() && t->ratio() == set[k]);
    FUZZ_CHECK(std::abs(t->sun) >= r.min && std::abs(t->sun) <= r.max && t->planet >= r.min && t->planet <= r.max);
  }
}

std::optional<sphtroch::ToothRange> tooth_range(const std::string& text) {
  try {
    const sphtroch::ToothRange r = sphtroch::parse_tooth_range(text, "teeth");
    FUZZ_CHECK(r.min >= 1 && r.min <= r.max && r.max <= sphtroch::kMaxTeeth);
    const sphtroch::ToothRange again = sphtroch::parse_tooth_range(r.str(), "teeth");  // "12..60" reads back
    FUZZ_CHECK(again.min == r.min && again.max == r.max);
    if (r.max <= 24) check_ratio_set(r);
    return r;
  } catch (const InvalidInput& e) {
    check_error(e, "teeth", text);
    return std::nullopt;
  }
}

void unit_point(const std::string& text) {
  try {
    const sphtroch::Vector3d p = sphtroch::parse_unit_point(text, "node-at");
    FUZZ_CHECK(p.allFinite() && std::abs(p.norm() - 1.0) <= 1e-15);
    // As synth fit prints it (number_text of each coordinate), it reads back to the same point.
    const std::string printed = sphtroch::number_text(p.x()) + "," + sphtroch::number_text(p.y()) + "," +
                                sphtroch::number_text(p.z());
    const sphtroch::Vector3d again = sphtroch::parse_unit_point(printed, "node-at");
    FUZZ_CHECK((again - p).norm() <= 1e-15);
  } catch (const InvalidInput& e) {
    check_error(e, "node-at", text);
  }
}

std::optional<std::size_t> count(const std::string& text, const std::string& field, std::size_t lo, std::size_t hi) {
  try {
    const std::size_t v = sphtroch::parse_count(text, field, lo, hi);
    FUZZ_CHECK(v >= lo && v <= hi);
    FUZZ_CHECK(std::to_string(v) == canonical_count(text));
    return v;
  } catch (const InvalidInput& e) {
    check_error(e, field, text);
    FUZZ_CHECK(e.problem() == "not a whole number" || e.problem() == "outside the valid range");
    return std::nullopt;
  }
}

/// --ratios P,Q (1 .. 1000) or --max-terms P,Q (1 .. 1000000), with the valid forms the commands give.
std::optional<std::pair<std::size_t, std::size_t>> count_pair(const std::string& text, bool max_terms) {
  const std::string field = max_terms ? "max-terms" : "ratios";
  const std::size_t hi = max_terms ? std::size_t(Ratio::kMaxTerm) : 1000;
  const std::string valid = max_terms ? "P,Q with 1 <= P, Q <= 1000000 (|p| <= P, q <= Q)"
                                      : "P,Q: every p/q with 1 <= |p| <= P, 1 <= q <= Q (each 1 .. 1000)";
  try {
    const auto [p, q] = sphtroch::parse_count_pair(text, field, 1, hi, valid);
    FUZZ_CHECK(p >= 1 && p <= hi && q >= 1 && q <= hi);
    const std::size_t comma = text.find(',');
    FUZZ_CHECK(comma != std::string::npos && text.find(',', comma + 1) == std::string::npos);
    FUZZ_CHECK(std::to_string(p) == canonical_count(text.substr(0, comma)));
    FUZZ_CHECK(std::to_string(q) == canonical_count(text.substr(comma + 1)));
    return std::make_pair(p, q);
  } catch (const InvalidInput& e) {
    check_error(e, field, text);  // the whole P,Q, not the part
    FUZZ_CHECK(e.valid_range() == valid);
    return std::nullopt;
  }
}

/// --shard I/K of a set of `size` ratios: the I-th of K consecutive pieces covering the set.
void shard(const std::string& text, std::size_t size) {
  try {
    const auto [begin, end] = sphtroch::shard_range(text, size);
    FUZZ_CHECK(begin <= end && end <= size);
    const std::size_t slash = text.find('/');
    FUZZ_CHECK(slash != std::string::npos);
    const std::size_t i = std::stoull(canonical_count(text.substr(0, slash)));
    const std::size_t k = std::stoull(canonical_count(text.substr(slash + 1)));
    FUZZ_CHECK(i >= 1 && i <= k && k <= 1000000);
    FUZZ_CHECK(begin == (i - 1) * size / k && end == i * size / k);
    if (i == 1) FUZZ_CHECK(begin == 0);
    if (i == k) FUZZ_CHECK(end == size);
    if (i < k) FUZZ_CHECK(sphtroch::shard_range(std::to_string(i + 1) + "/" + std::to_string(k), size).first == end);
  } catch (const InvalidInput& e) {
    check_error(e, "shard", text);
  }
}

/// A shard JSON's "ratios" / "teeth" member: accepted only as a run writes it; only small sets
/// are built (ratio_set of 1000,1000 is a million gcds).
void named_set(const std::string& text) {
  for (const char* name : {"ratios", "teeth"}) {
    const bool is_teeth = std::string(name) == "teeth";
    if (is_teeth) {
      const auto r = tooth_range(text);
      if (r && r->max > 40) continue;
    } else {
      const auto pq = count_pair(text, false);
      if (pq && pq->first * pq->second > 1600) continue;
    }
    try {
      const std::vector<Ratio> set = sphtroch::named_ratio_set(name, text);
      FUZZ_CHECK(!set.empty());
      if (is_teeth) {
        FUZZ_CHECK(text == sphtroch::parse_tooth_range(text, "teeth").str());
      } else {
        const auto [p, q] = sphtroch::parse_count_pair(text, "ratios", 1, 1000, "P,Q");
        FUZZ_CHECK(text == std::to_string(p) + "," + std::to_string(q));
        for (const Ratio& r : set)
          FUZZ_CHECK(r.abs_p() <= std::int64_t(p) && r.q() <= std::int64_t(q) && std::gcd(r.abs_p(), r.q()) == 1);
      }
    } catch (const InvalidInput& e) {
      FUZZ_CHECK(e.field() == name);
      FUZZ_CHECK(!e.problem().empty() && fuzz::one_line(e.valid_range()));
    }
  }
}

/// The whole request of synth points (--n, --ratios, --teeth, --shard; "" = not given), when
/// its set is small enough to build quickly.
void request(const std::string& n, const std::string& ratios, const std::string& teeth_text, const std::string& shard_text) {
  if (!ratios.empty()) {
    try {
      const auto [p, q] = sphtroch::parse_count_pair(ratios, "ratios", 1, 1000, "P,Q");
      if (p * q > 1600) return;
    } catch (const InvalidInput&) {
    }
  }
  if (teeth_text.find("..") != std::string::npos) {
    try {
      if (sphtroch::parse_tooth_range(teeth_text, "teeth").max > 40) return;
    } catch (const InvalidInput&) {
    }
  }
  constexpr double kMaxWork = sphtroch::kMaxPointsWork;  // synth points' bound
  try {
    const sphtroch::RatioSet r = sphtroch::cli::requested_ratios("synth points", {n, ratios, teeth_text, shard_text}, kMaxWork);
    FUZZ_CHECK(int(!n.empty()) + int(!ratios.empty()) + int(!teeth_text.empty()) == 1);
    double work = 0;
    for (const Ratio& k : r.ratios) {
      FUZZ_CHECK(k.p() != 0 && k.q() >= 1);
      work += std::pow(double(k.abs_p() + k.q()), 2);
    }
    FUZZ_CHECK(work <= kMaxWork);
    if (!n.empty()) FUZZ_CHECK(r.ratios.size() == 1 && r.ratios[0] == sphtroch::parse_ratio(n, "n"));
    if (!shard_text.empty()) FUZZ_CHECK(r.json_members().find("\"shard\": ") != std::string::npos);
    if (r.teeth.pair) FUZZ_CHECK(r.ratios.size() == 1 && r.teeth.of(r.ratios[0]).has_value());
  } catch (const InvalidInput& e) {
    FUZZ_CHECK(e.field() == "n" || e.field() == "ratios" || e.field() == "teeth" || e.field() == "shard");
    FUZZ_CHECK(!e.problem().empty() && fuzz::one_line(e.valid_range()));
  } catch (const UsageError& e) {
    FUZZ_CHECK(!e.message.empty());
  }
}

void every_parser(const std::string& text, std::uint64_t hash) {
  (void)teeth(text);
  (void)tooth_range(text);
  unit_point(text);
  (void)count(text, "threads", 1, sphtroch::cli::kMaxThreads);
  (void)count_pair(text, false);
  (void)count_pair(text, true);
  named_set(text);
  // Set sizes: small ones (every shard, empty ones too) and the largest a run builds.
  shard(text, static_cast<std::size_t>(hash % 64));
  shard(text, static_cast<std::size_t>((hash >> 8) % 2000001));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;  // option values are short; longer texts only slow the search
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::uint64_t hash = fuzz::fnv1a(input);
  std::vector<std::string> lines;
  for (std::size_t start = 0; lines.size() < 8;) {
    const std::size_t nl = input.find('\n', start);
    lines.push_back(input.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  every_parser(input, hash);
  for (const std::string& line : lines) every_parser(line, hash);
  lines.resize(std::max<std::size_t>(lines.size(), 4));
  request(lines[0], lines[1], lines[2], lines[3]);
  return 0;
}
