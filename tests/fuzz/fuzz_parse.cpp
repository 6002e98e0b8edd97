// tests/fuzz/fuzz_parse.cpp — parse_angle, parse_ratio, parse_a3, make_gear_train (parse.hpp) and
// parse_number / number_text (number_text.hpp).
//
// Input: lines separated by '\n'. Lines 1-4 are a2, a3, n, phase (phase "0" when absent); every
// line (at most 8) and the whole input also go through every parser. The first 8 bytes, read as a
// double, go through number_text -> parse_number.
// Expected: sphtroch::InvalidInput (naming the field and the text as given). Anything else thrown
// crashes; a broken invariant traps (FUZZ_CHECK).
#include "fuzz_common.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

using sphtroch::A3Reference;
using sphtroch::A3Spec;
using sphtroch::InvalidInput;
using sphtroch::Ratio;

/// Every InvalidInput names the field it was asked about and the text exactly as given.
void check_error(const InvalidInput& e, const std::string& field, std::string_view text) {
  FUZZ_CHECK(e.field() == field);
  FUZZ_CHECK(e.value() == text);
  FUZZ_CHECK(!e.problem().empty() && !e.valid_range().empty());
}

std::optional<double> angle(std::string_view text) {
  try {
    const double v = sphtroch::parse_angle(text, "a2");
    FUZZ_CHECK(std::isfinite(v));  // "parsing only rejects non-numbers, NaN and infinities"
    return v;
  } catch (const InvalidInput& e) {
    check_error(e, "a2", text);
    return std::nullopt;
  }
}

std::optional<Ratio> ratio(std::string_view text) {
  try {
    const Ratio r = sphtroch::parse_ratio(text, "n");
    FUZZ_CHECK(r.p() != 0 && r.q() > 0);
    FUZZ_CHECK(r.abs_p() <= Ratio::kMaxTerm && r.q() <= Ratio::kMaxTerm);
    FUZZ_CHECK(std::gcd(r.abs_p(), r.q()) == 1);
    // Its printed form reads back as the same ratio.
    const Ratio again = sphtroch::parse_ratio(r.str(), "n");
    FUZZ_CHECK(again == r);
    return r;
  } catch (const InvalidInput& e) {
    check_error(e, "n", text);
    return std::nullopt;
  }
}

std::optional<A3Spec> a3(std::string_view text) {
  try {
    const A3Spec s = sphtroch::parse_a3(text, "a3");
    FUZZ_CHECK(std::isfinite(s.offset));
    if (s.reference == A3Reference::given) {
      // A plain angle: exactly what parse_angle reads.
      const auto v = angle(text);
      FUZZ_CHECK(v.has_value() && fuzz::same_bits(*v, s.offset));
    } else {
      // A reference cone: the trimmed text starts with its name.
      const std::string_view name = sphtroch::to_string(s.reference);
      FUZZ_CHECK(sphtroch::detail::trim(text).substr(0, name.size()) == name);
    }
    return s;
  } catch (const InvalidInput& e) {
    check_error(e, "a3", text);
    return std::nullopt;
  }
}

/// parse_number: finite, and its shortest form reads back bit-exactly; a number is also an angle.
void number(std::string_view text) {
  const std::optional<double> v = sphtroch::parse_number(text);
  if (!v) return;
  FUZZ_CHECK(std::isfinite(*v));
  const std::string printed = sphtroch::number_text(*v);
  const std::optional<double> back = sphtroch::parse_number(printed);
  FUZZ_CHECK(back && fuzz::same_bits(*back, *v));
  // The grammar: angle := number | ...; a number (no spaces: parse_number skips none) is the
  // same angle in radians.
  const auto a = angle(text);
  FUZZ_CHECK(a && fuzz::same_bits(*a, *v));
}

/// number_text of any double: the shortest form (at most kMaxNumberChars characters), which
/// parse_number reads back bit-exactly when finite and refuses otherwise.
void round_trip(double v) {
  char wide[64];
  const auto [end, ec] = std::to_chars(wide, wide + sizeof wide, v);
  FUZZ_CHECK(ec == std::errc());
  const std::string printed = sphtroch::number_text(v);
  FUZZ_CHECK(printed.size() <= sphtroch::kMaxNumberChars);
  FUZZ_CHECK(printed == std::string(wide, end));
  const std::optional<double> back = sphtroch::parse_number(printed);
  if (std::isfinite(v)) FUZZ_CHECK(back && fuzz::same_bits(*back, v));
  else FUZZ_CHECK(!back);
}

void every_parser(std::string_view text) {
  (void)angle(text);
  (void)ratio(text);
  (void)a3(text);
  number(text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  if (size >= 8) {
    double v;
    std::memcpy(&v, data, sizeof v);
    round_trip(v);
  }

  std::vector<std::string_view> lines;
  for (std::size_t start = 0; lines.size() < 8;) {
    const std::size_t nl = input.find('\n', start);
    lines.push_back(input.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start));
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  every_parser(input);  // newlines and all: trim() strips a trailing "\r\n"
  for (std::string_view line : lines) every_parser(line);

  // A gear train of lines 1-4, as the command line reads --a2 --a3 --n --phase.
  if (lines.size() < 3) return 0;
  const auto a2 = angle(lines[0]);
  const auto spec = a3(lines[1]);
  const auto n = ratio(lines[2]);
  const auto phase = lines.size() > 3 ? angle(lines[3]) : std::optional<double>(0.0);
  if (!a2 || !spec || !n || !phase) return 0;
  try {
    const sphtroch::GearTrain t = sphtroch::make_gear_train(*a2, *spec, *n, *phase);
    const double pi = sphtroch::Constants<double>::pi();
    FUZZ_CHECK(t.a2() > 0 && t.a2() < pi);
    FUZZ_CHECK(t.a3() > 0 && t.a3() < pi);
    FUZZ_CHECK(t.phase() >= -pi && t.phase() <= pi);
    FUZZ_CHECK(fuzz::same_bits(t.phase_given(), *phase));
    FUZZ_CHECK(t.ratio() == *n);
    FUZZ_CHECK(t.a3_reference() == spec->reference);
  } catch (const InvalidInput& e) {
    FUZZ_CHECK(e.field() == "a2" || e.field() == "a3" || e.field() == "n" || e.field() == "phase");
  }
  return 0;
}
