// sphtroch/core/number_text.hpp — doubles as text and back: the one number format of every file and
// report the library writes.
//
//   char buf[sphtroch::kMaxNumberChars];
//   char* end = sphtroch::write_number(buf, 0.1);        // "0.1"
//   std::optional<double> v = sphtroch::parse_number("1e-300");
//
// Form: the shortest decimal that reads back as the same double (std::to_chars without a
// precision: Ryu-style, e.g. 0.1, 1e-11, -0, 5e-324, 1.7976931348623157e+308). Every value
// round-trips exactly, including subnormals and -0.0; the text is at most 24 characters and
// 2-20% shorter than 17 significant digits, so files are smaller and faster to write and read.
// Non-finite values are written "nan", "inf", "-inf" (the tool never writes them in data rows).
// Parsing is std::from_chars (general format, round-to-nearest): exact inverse of the above.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace sphtroch {

/// Characters write_number may write: "-2.2250738585072014e-308" has 24.
constexpr std::size_t kMaxNumberChars = 24;

/// Writes the shortest round-trip form of v at out (room for kMaxNumberChars) and returns the end.
inline char* write_number(char* out, double v) noexcept {
  return std::to_chars(out, out + kMaxNumberChars, v).ptr;
}

/// The shortest round-trip form of v as a string.
inline std::string number_text(double v) {
  char buf[kMaxNumberChars];
  return std::string(buf, write_number(buf, v));
}

namespace detail {

/// For a decimal [-]digits[.digits][e[+-]digits] that from_chars found out of range: whether its
/// magnitude is below 1 (so it underflowed) rather than above (overflowed). The decimal exponent
/// of the first nonzero digit decides; a value with no nonzero digit is not out of range.
inline bool decimal_underflows(const char* first, const char* last) noexcept {
  const char* p = first;
  if (p != last && *p == '-') ++p;
  const char* digits_end = p;
  while (digits_end != last && (*digits_end == '.' || (*digits_end >= '0' && *digits_end <= '9'))) ++digits_end;
  const char* point = std::find(p, digits_end, '.');
  const char* nonzero = std::find_if(p, digits_end, [](char c) { return c >= '1' && c <= '9'; });
  if (nonzero == digits_end) return false;
  // Decimal exponent of the first nonzero digit: 10^(digits up to the point - 1) ... 10^-1, 10^-2, ...
  const long long lead = nonzero < point ? static_cast<long long>(point - nonzero) - 1
                                         : -static_cast<long long>(nonzero - point);
  long long exponent = 0;
  p = digits_end;
  if (p != last && (*p == 'e' || *p == 'E')) {
    ++p;
    const bool negative = p != last && *p == '-';
    if (p != last && (*p == '-' || *p == '+')) ++p;
    for (; p != last && *p >= '0' && *p <= '9'; ++p)
      if (exponent < 1000000000LL) exponent = exponent * 10 + (*p - '0');
    if (negative) exponent = -exponent;
  }
  return lead + exponent < 0;
}

}  // namespace detail

/// A measured time in seconds for text reports: 3 significant digits, printf "%.3g" (timings are
/// noisy; JSON reports keep every digit with number_text / the JSON writer).
inline std::string seconds_text(double seconds) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.3g", seconds);
  return buf;
}

/// Parses a number at [first, last): an optional '+' or '-', digits with an optional point and
/// exponent ("1", "-0.5", "2.5e-3", "+1e10"; also "inf", "nan" — callers reject non-finite values).
/// A magnitude beyond the largest double (1e999) is not a number here; one below the smallest
/// subnormal (1e-400) is a signed zero.
/// Returns the end of the number, or nullptr when no number starts at first. No space skipping.
inline const char* parse_number_prefix(const char* first, const char* last, double& value) noexcept {
  if (first != last && *first == '+') {
    ++first;
    if (first == last || *first == '-' || *first == '+') return nullptr;
  }
  const auto [end, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) {
    // Too large (1e999: not a double, refused) or too small (1e-400: rounds to zero, read as
    // a signed zero, as strtod and JSON readers do).
    if (!detail::decimal_underflows(first, end)) return nullptr;
    value = *first == '-' ? -0.0 : 0.0;
  }
  return ec == std::errc() || ec == std::errc::result_out_of_range ? end : nullptr;
}

/// The whole of `text` as a finite double, or nullopt (empty, trailing characters, out of range,
/// nan or inf).
inline std::optional<double> parse_number(std::string_view text) noexcept {
  double v = 0;
  const char* end = parse_number_prefix(text.data(), text.data() + text.size(), v);
  if (end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace sphtroch
