// sphtroch/io/parse.hpp — angles, gear ratios and tracer twists written the way people type them.
//
//   sphtroch::parse_angle("2pi/3", "a2");        // 2 pi / 3; also "90deg", "-pi/4", "1.25", "pi-1e-6"
//   sphtroch::parse_ratio("5/2", "n");           // Ratio(5, 2); also "2.5", "-3", "10/4"
//   sphtroch::parse_a3("ap+1e-6", "a3");         // {A3Reference::pitch_cone, 1e-6}; "pi-ap-1e-9", "a2"
//   sphtroch::parse_teeth("39:15", "teeth");     // Teeth{39, 15}: n = 13/5 (core/teeth.hpp)
//   sphtroch::parse_tooth_range("12..60", "teeth");   // ToothRange{12, 60}
//   sphtroch::parse_unit_point("0.6,0,0.8", "node-at");  // Vector3d(0.6, 0, 0.8)
//   sphtroch::parse_count("64", "grid", 1, 4096);        // 64: a whole number in [lo, hi]
//   sphtroch::parse_count_pair("7,5", "ratios", 1, 1000, "P,Q");  // {7, 5}
//   sphtroch::parse_shard("2/4", 64, "grid (64)");          // Shard{2, 4}
//
// Grammar (no spaces inside a value; surrounding spaces are ignored):
//   angle  := number | number "deg" | [sign][coef]["*"]"pi"["/" number][("+"|"-") number]
//   ratio  := [sign] integer ["/" integer] | [sign] digits "." digits     (decimal, <= 9 places)
//   a3     := angle | ref [("+" | "-") angle]     ref := "ap" | "pi-ap" | "a2" | "pi-a2"
//   teeth  := [sign] integer ":" integer          tooth range := integer ".." integer
//   count  := digits (no sign, no spaces)         count pair := count "," count
//   shard  := count "/" count
// Every failure throws InvalidInput naming the field, the text and the accepted forms.
// Range checks (a2 in (0, pi) ...) are the GearTrain's; parsing only rejects non-numbers,
// NaN and infinities.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/core/shard.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

namespace sphtroch {

constexpr const char* kAngleForms = "radians (1.25), multiples of pi (pi/2, 2pi/3, 0.75pi, -pi/4) or degrees (90deg)";
constexpr const char* kRatioForms = "p/q or a decimal (2, 5/2, 2.5, -3/2), p != 0";

namespace detail {

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n')) s.remove_suffix(1);
  return s;
}

/// A whole string as a finite double, or nothing (one leading sign; the number as parse_number reads it).
inline std::optional<double> strict_double(std::string_view s) {
  if (s.empty()) return std::nullopt;
  bool negative = false;
  if (s.front() == '+' || s.front() == '-') {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s.front())) || s.front() == '.')) return std::nullopt;
  const std::optional<double> v = parse_number(s);  // number_text.hpp: 1e999 refused, 1e-400 is 0
  if (!v) return std::nullopt;
  return negative ? -*v : *v;
}

/// A whole string as an integer of at most 18 digits ("+-3", "--3" and overflow refused), so
/// that |v| < 1e18 and negating it or taking llabs is always defined.
inline std::optional<std::int64_t> strict_int(std::string_view s) {
  if (s.empty()) return std::nullopt;
  if (s.front() == '+') {
    s.remove_prefix(1);
    if (s.empty() || !std::isdigit(static_cast<unsigned char>(s.front()))) return std::nullopt;
  }
  const std::string_view digits = !s.empty() && s.front() == '-' ? s.substr(1) : s;
  if (digits.empty() || digits.size() > 18 || !std::isdigit(static_cast<unsigned char>(digits.front())))
    return std::nullopt;
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

inline std::optional<double> angle_value(std::string_view s) {
  s = trim(s);
  if (s.size() > 3 && s.substr(s.size() - 3) == "deg") {
    const auto v = strict_double(s.substr(0, s.size() - 3));
    if (!v) return std::nullopt;
    return *v * (Constants<double>::pi() / 180.0);
  }
  const auto pi_at = s.find("pi");
  if (pi_at == std::string_view::npos) return strict_double(s);
  std::string_view coef = s.substr(0, pi_at);
  std::string_view rest = s.substr(pi_at + 2);
  if (!coef.empty() && coef.back() == '*') coef.remove_suffix(1);
  double c = 1.0;
  if (coef == "-") c = -1.0;
  else if (coef == "+" || coef.empty()) c = 1.0;
  else if (const auto v = strict_double(coef)) c = *v;
  else return std::nullopt;
  // An optional offset in radians after the pi term: "pi-1e-6", "pi/2+0.1".
  double offset = 0.0;
  for (std::size_t i = 1; i < rest.size(); ++i) {
    if ((rest[i] == '+' || rest[i] == '-') && rest[i - 1] != 'e' && rest[i - 1] != 'E') {
      const auto v = strict_double(rest.substr(i));
      if (!v) return std::nullopt;
      offset = *v;
      rest = rest.substr(0, i);
      break;
    }
  }
  double d = 1.0;
  if (!rest.empty()) {
    if (rest.front() == '+' || rest.front() == '-') {  // "pi-1e-6": the offset starts right after pi
      const auto v = strict_double(rest);
      if (!v) return std::nullopt;
      return c * Constants<double>::pi() + *v;
    }
    if (rest.front() != '/') return std::nullopt;
    const auto v = strict_double(rest.substr(1));
    if (!v || *v == 0.0) return std::nullopt;
    d = *v;
  }
  // c*pi/d (+ offset): one rounding of pi, then of the product, the quotient and the sum.
  return c * Constants<double>::pi() / d + offset;
}

}  // namespace detail

/// An angle in radians. Throws InvalidInput(field, text, ...) unless it is finite and well formed.
inline double parse_angle(std::string_view text, const std::string& field) {
  const auto v = detail::angle_value(text);
  if (!v) throw InvalidInput(field, std::string(text), "not a finite angle", kAngleForms);
  return *v;
}

/// A gear ratio as an exact rational. Throws InvalidInput("n"...) for malformed text or n = 0.
inline Ratio parse_ratio(std::string_view text, const std::string& field = "n") {
  const std::string_view s = detail::trim(text);
  const std::string shown(text);
  auto bad = [&](const char* problem) { return InvalidInput(field, shown, problem, kRatioForms); };
  if (const auto slash = s.find('/'); slash != std::string_view::npos) {
    const auto p = detail::strict_int(s.substr(0, slash));
    const auto q = detail::strict_int(s.substr(slash + 1));
    if (!p || !q) throw bad("not a ratio of integers");
    if (*q == 0) throw bad("zero denominator");
    if (*p == 0) throw bad("the gear ratio must not be zero");
    if (std::llabs(*p) > Ratio::kMaxTerm || std::llabs(*q) > Ratio::kMaxTerm) throw bad("numerator or denominator too large (max 1000000)");
    return Ratio(*p, *q);
  }
  if (const auto dot = s.find('.'); dot != std::string_view::npos) {
    std::string_view whole = s.substr(0, dot), frac = s.substr(dot + 1);
    bool negative = false;
    if (!whole.empty() && (whole.front() == '-' || whole.front() == '+')) {
      negative = whole.front() == '-';
      whole.remove_prefix(1);
    }
    if (frac.empty() || frac.size() > 9) throw bad("not a decimal with 1 to 9 places");
    for (char ch : frac)
      if (!std::isdigit(static_cast<unsigned char>(ch))) throw bad("not a number");
    for (char ch : whole)
      if (!std::isdigit(static_cast<unsigned char>(ch))) throw bad("not a number");
    const auto w = whole.empty() ? std::optional<std::int64_t>(0) : detail::strict_int(whole);
    const auto f = detail::strict_int(frac);
    if (!w || !f || *w > Ratio::kMaxTerm) throw bad("not a number");
    std::int64_t q = 1;
    for (std::size_t i = 0; i < frac.size(); ++i) q *= 10;
    std::int64_t p = *w * q + *f;
    if (p == 0) throw bad("the gear ratio must not be zero");
    if (negative) p = -p;
    // Reduce before the range check: 2.5 = 25/10 = 5/2.
    const std::int64_t g = std::gcd(p < 0 ? -p : p, q);
    if (std::llabs(p / g) > Ratio::kMaxTerm || q / g > Ratio::kMaxTerm) throw bad("numerator or denominator too large (max 1000000)");
    return Ratio(p / g, q / g);
  }
  const auto p = detail::strict_int(s);
  if (!p) throw bad("not a number");
  if (*p == 0) throw bad("the gear ratio must not be zero");
  if (std::llabs(*p) > Ratio::kMaxTerm) throw bad("too large (max 1000000)");
  return Ratio(*p, 1);
}

/// A tracer twist: an angle, or a reference cone plus an optional signed offset (radians or
/// any angle form): "ap", "pi-ap", "a2", "pi-a2", "ap+1e-6", "pi-ap-1e-9".
inline A3Spec parse_a3(std::string_view text, const std::string& field = "a3") {
  const std::string_view s = detail::trim(text);
  struct Ref {
    std::string_view name;
    A3Reference reference;
  };
  // Longest names first so that "pi-ap" is not read as "pi" followed by garbage.
  constexpr Ref refs[] = {{"pi-ap", A3Reference::mirror_pitch_cone},
                          {"pi-a2", A3Reference::pi_minus_a2},
                          {"ap", A3Reference::pitch_cone},
                          {"a2", A3Reference::a2}};
  for (const auto& r : refs) {
    if (s.substr(0, r.name.size()) != r.name) continue;
    const std::string_view rest = s.substr(r.name.size());
    if (rest.empty()) return {r.reference, 0.0};
    if (rest.front() != '+' && rest.front() != '-') break;
    const auto v = detail::angle_value(rest.substr(1));
    if (!v) break;
    return {r.reference, rest.front() == '-' ? -*v : *v};
  }
  const auto v = detail::angle_value(s);
  if (!v)
    throw InvalidInput(field, std::string(text), "not a finite angle",
                       std::string(kAngleForms) + ", or ap, pi-ap, a2, pi-a2 with an optional +/- offset");
  return {A3Reference::given, *v};
}

/// A closed angle range [lo, hi] of a2 or a3, radians; 0 <= lo < hi <= pi.
struct AngleRange {
  double lo = 0.0;
  double hi = Constants<double>::pi();
};

/// The forms of an angle range, as the CLI (--a2, --a3 of atlas and boundaries) and Python take it.
constexpr const char* kAngleRangeForms = "LO:HI with 0 <= LO < HI <= pi (angles: 1.2, pi/6, 5pi/6, 90deg)";

/// "LO:HI" (each an angle in the forms of parse_angle) as a range with 0 <= LO < HI <= pi.
/// Throws InvalidInput(field, text, problem, valid): "spaces inside a range", "not a range
/// LO:HI", "not two finite angles LO:HI" or "outside the valid range".
inline AngleRange parse_angle_range(std::string_view text, const std::string& field,
                                    const std::string& valid = kAngleRangeForms) {
  const std::string as_given(text);
  if (text.find_first_of(" \t\r\n") != std::string_view::npos)
    throw InvalidInput(field, as_given, "spaces inside a range", valid);
  const auto colon = text.find(':');
  if (colon == std::string_view::npos) throw InvalidInput(field, as_given, "not a range LO:HI", valid);
  const auto lo = detail::angle_value(text.substr(0, colon));
  const auto hi = detail::angle_value(text.substr(colon + 1));
  if (!lo || !hi) throw InvalidInput(field, as_given, "not two finite angles LO:HI", valid);
  if (!(*lo >= 0.0 && *lo < *hi && *hi <= Constants<double>::pi()))
    throw InvalidInput(field, as_given, "outside the valid range", valid);
  return AngleRange{*lo, *hi};
}

/// The carrier turns K of an open trajectory, typed as a plain number: K in (0, kMaxTurns]
/// (sampling.hpp). Throws InvalidInput("turns", text, ...) otherwise.
inline double parse_turns(std::string_view text) {
  const auto k = detail::strict_double(text);
  if (!k) throw InvalidInput("turns", std::string(text), "outside the valid range", kTurnsRange);
  check_turns(*k, std::string(text));
  return *k;
}

constexpr const char* kTeethForms = "ZS:ZP, sun:planet tooth counts (39:15; ZS < 0: internal gearing)";
constexpr const char* kToothRangeForms = "MIN..MAX, tooth counts of either gear (12..60)";

/// "ZS:ZP" as tooth counts (checked_teeth's range).
inline Teeth parse_teeth(std::string_view text, const std::string& field = "teeth") {
  const std::string_view s = detail::trim(text);
  const auto colon = s.find(':');
  const auto sun = colon == std::string_view::npos ? std::nullopt : detail::strict_int(s.substr(0, colon));
  const auto planet = colon == std::string_view::npos ? std::nullopt : detail::strict_int(s.substr(colon + 1));
  if (!sun || !planet || s[colon + 1] == '+' || s[colon + 1] == '-')
    throw InvalidInput(field, std::string(text), "not two tooth counts", kTeethForms);
  try {
    return checked_teeth(*sun, *planet);
  } catch (const InvalidInput& e) {
    throw InvalidInput(field, std::string(text), e.problem(), e.valid_range());
  }
}

/// "MIN..MAX" as a range of tooth counts (checked_range's bounds).
inline ToothRange parse_tooth_range(std::string_view text, const std::string& field = "teeth") {
  const std::string_view s = detail::trim(text);
  const auto dots = s.find("..");
  const auto min = dots == std::string_view::npos ? std::nullopt : detail::strict_int(s.substr(0, dots));
  const auto max = dots == std::string_view::npos ? std::nullopt : detail::strict_int(s.substr(dots + 2));
  if (!min || !max) throw InvalidInput(field, std::string(text), "not a range of tooth counts", kToothRangeForms);
  try {
    return checked_range(*min, *max);
  } catch (const InvalidInput& e) {
    throw InvalidInput(field, std::string(text), e.problem(), e.valid_range());
  }
}

/// "X,Y,Z": a point on the unit sphere (|P| within 1e-6 of 1), returned normalised.
inline Vector3d parse_unit_point(std::string_view text, const std::string& field) {
  const std::string_view s = detail::trim(text);
  const auto c1 = s.find(','), c2 = c1 == std::string_view::npos ? c1 : s.find(',', c1 + 1);
  const std::string valid = "X,Y,Z, a unit vector (|P| within 1e-6 of 1), e.g. 0.6,0,0.8";
  if (c2 == std::string_view::npos || s.find(',', c2 + 1) != std::string_view::npos)
    throw InvalidInput(field, std::string(text), "not three numbers X,Y,Z", valid);
  const auto x = detail::strict_double(s.substr(0, c1)), y = detail::strict_double(s.substr(c1 + 1, c2 - c1 - 1)),
             z = detail::strict_double(s.substr(c2 + 1));
  if (!x || !y || !z) throw InvalidInput(field, std::string(text), "not three numbers X,Y,Z", valid);
  const Vector3d p(*x, *y, *z);
  if (!(std::abs(p.norm() - 1.0) <= 1e-6))
    throw InvalidInput(field, std::string(text), "not on the unit sphere (|P| = " + number_text(p.norm()) + ")", valid);
  return p.normalized();
}

/// A whole number in [lo, hi] written as digits only (no sign, space or exponent: leading zeros
/// allowed); InvalidInput naming `field` otherwise.
inline std::size_t parse_count(const std::string& text, const std::string& field, std::size_t lo, std::size_t hi) {
  const std::string range = "integer " + std::to_string(lo) + " .. " + std::to_string(hi);
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
    const bool negative = text.size() > 1 && text[0] == '-' && text.find_first_not_of("0123456789", 1) == std::string::npos &&
                          text.find_first_not_of('0', 1) != std::string::npos;  // (-0 is not below 0)
    throw InvalidInput(field, text, negative ? "outside the valid range" : "not a whole number", range);
  }
  const std::size_t first = std::min(text.find_first_not_of('0'), text.size() - 1);  // leading zeros
  std::uint64_t v = 0;
  const auto [end, error] = std::from_chars(text.data() + first, text.data() + text.size(), v);
  if (error == std::errc::result_out_of_range || end != text.data() + text.size() || v < lo || v > hi)
    throw InvalidInput(field, text, "outside the valid range", range);
  return static_cast<std::size_t>(v);
}

/// Two counts "P,Q", each in [lo, hi]; InvalidInput naming the whole text (and the bad part) with
/// `valid` as the valid range otherwise.
inline std::pair<std::size_t, std::size_t> parse_count_pair(const std::string& text, const std::string& field,
                                                            std::size_t lo, std::size_t hi, const std::string& valid) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw InvalidInput(field, text, "not two counts P,Q", valid);
  try {
    return {parse_count(text.substr(0, comma), field, lo, hi), parse_count(text.substr(comma + 1), field, lo, hi)};
  } catch (const InvalidInput& e) {  // name the whole P,Q, not the part
    throw InvalidInput(field, text, e.problem() + " (" + e.value() + ")", valid);
  }
}

/// "I/K" (counts, 1 <= I <= K <= max_count) as a Shard; InvalidInput("shard") naming the whole
/// text otherwise, with the valid range "I/K with 1 <= I <= K <= " + `max_name` (e.g. "grid (64)").
inline Shard parse_shard(const std::string& text, std::size_t max_count, const std::string& max_name) {
  const std::string valid = "I/K with 1 <= I <= K <= " + max_name;
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw InvalidInput("shard", text, "not I/K", valid);
  try {
    const std::size_t k = parse_count(text.substr(slash + 1), "shard", 1, max_count);
    return Shard{parse_count(text.substr(0, slash), "shard", 1, k), k};
  } catch (const InvalidInput& e) {  // name the whole I/K, not the part
    throw InvalidInput("shard", text, e.problem() + " (" + e.value() + ")", valid);
  }
}

}  // namespace sphtroch
