// Tests of ratio_set.hpp: a request's ratios against a brute-force enumeration of the fractions it
// names, shards that partition the set in order, the JSON members a run writes, the work bound,
// and every malformed request refused naming its field.
#include "catch2/catch.hpp"
#include "sphtroch/io/ratio_set.hpp"

#include <numeric>
#include <set>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

/// Every p/q in lowest terms with 1 <= |p| <= P, 1 <= q <= Q, both signs, as (p, q) pairs.
std::set<std::pair<std::int64_t, std::int64_t>> brute_force(std::int64_t P, std::int64_t Q) {
  std::set<std::pair<std::int64_t, std::int64_t>> out;
  for (std::int64_t p = -P; p <= P; ++p)
    for (std::int64_t q = 1; q <= Q; ++q)
      if (p != 0 && std::gcd(p < 0 ? -p : p, q) == 1) out.insert({p, q});
  return out;
}

std::string field_of(const RatioRequestText& r) {
  try {
    parse_ratio_set(r);
  } catch (const InvalidInput& e) {
    return e.field();
  }
  return "";
}

}  // namespace

TEST_CASE("ratio_set: --ratios P,Q is every fraction it names, in increasing order", "[ratio_set]") {
  for (const auto& [P, Q] : std::vector<std::pair<int, int>>{{1, 1}, {3, 2}, {7, 7}, {5, 12}}) {
    const RatioSet s = parse_ratio_set({"", std::to_string(P) + "," + std::to_string(Q), "", ""});
    std::set<std::pair<std::int64_t, std::int64_t>> got;
    for (std::size_t k = 0; k < s.ratios.size(); ++k) {
      got.insert({s.ratios[k].p(), s.ratios[k].q()});
      if (k > 0) CHECK(s.ratios[k - 1].p() * s.ratios[k].q() < s.ratios[k].p() * s.ratios[k - 1].q());
    }
    CHECK(got == brute_force(P, Q));
    CHECK(got.size() == s.ratios.size());
    CHECK(s.json_members() == "\"ratios\": \"" + std::to_string(P) + "," + std::to_string(Q) + "\", ");
  }
}

TEST_CASE("ratio_set: the K shards of a set partition it in order, each named in the JSON", "[ratio_set]") {
  const std::vector<Ratio> whole = parse_ratio_set({"", "6,5", "", ""}).ratios;
  for (const std::size_t k : {std::size_t(1), std::size_t(3), std::size_t(7), whole.size(), whole.size() + 5}) {
    std::vector<Ratio> joined;
    for (std::size_t i = 1; i <= k; ++i) {
      const std::string shard = std::to_string(i) + "/" + std::to_string(k);
      const RatioSet part = parse_ratio_set({"", "6,5", "", shard});
      CHECK(part.json_members() == "\"ratios\": \"6,5\", \"shard\": \"" + shard + "\", ");
      joined.insert(joined.end(), part.ratios.begin(), part.ratios.end());
    }
    CHECK(joined == whole);
  }
}

TEST_CASE("ratio_set: n, a tooth pair and a tooth range", "[ratio_set]") {
  const RatioSet n = parse_ratio_set({"10/4", "", "", ""});
  CHECK(n.ratios == std::vector<Ratio>{Ratio(5, 2)});
  CHECK(n.json_members().empty());
  const RatioSet pair = parse_ratio_set({"", "", "39:15", ""});
  CHECK(pair.ratios == std::vector<Ratio>{Ratio(13, 5)});
  CHECK(pair.json_members() == "\"teeth\": \"39:15\", ");
  REQUIRE(pair.teeth.of(Ratio(13, 5)).has_value());
  const RatioSet range = parse_ratio_set({"", "", "12..20", ""});
  for (const Ratio& r : range.ratios) {  // both counts of some multiple in 12..20
    bool found = false;
    for (std::int64_t k = 1; k * std::max(r.abs_p(), r.q()) <= 20; ++k)
      found = found || (k * std::min(r.abs_p(), r.q()) >= 12);
    CHECK(found);
  }
  CHECK(range.json_members() == "\"teeth\": \"12..20\", ");
}

TEST_CASE("ratio_set: the work bound and malformed requests", "[ratio_set]") {
  // (|p| + q)^2 summed by hand for --ratios 2,1: n = -2, -1, 1, 2 -> 9 + 4 + 4 + 9.
  CHECK(ratio_work(parse_ratio_set({"", "2,1", "", ""}).ratios) == 26.0);
  CHECK_NOTHROW(check_ratio_work(parse_ratio_set({"", "2,1", "", ""}), "ratios", "2,1", 26.0));
  CHECK_THROWS_AS(check_ratio_work(parse_ratio_set({"", "2,1", "", ""}), "ratios", "2,1", 25.0), InvalidInput);
  CHECK(field_of({"", "", "", ""}) == "n");
  CHECK(field_of({"2", "2,2", "", ""}) == "n");
  CHECK(field_of({"2", "", "", "1/2"}) == "shard");
  CHECK(field_of({"", "2", "", ""}) == "ratios");
  CHECK(field_of({"", "2,0", "", ""}) == "ratios");
  CHECK(field_of({"", "1001,1", "", ""}) == "ratios");
  CHECK(field_of({"", "2,2", "", "3/2"}) == "shard");
  CHECK(field_of({"", "2,2", "", "0/2"}) == "shard");
  CHECK(field_of({"", "2,2", "", "1"}) == "shard");
  CHECK(field_of({"", "", "12..5", ""}) == "teeth");
  CHECK(field_of({"x", "", "", ""}) == "n");
  CHECK_THROWS_AS(named_ratio_set("ratios", "02,2"), InvalidInput);  // not as a run writes it
  CHECK(named_ratio_set("ratios", "2,2").size() == brute_force(2, 2).size());
}
