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
// That is the form of data: files, tables, JSON, the texts front ends exchange.
//
// Sentences people read (text reports, explanations) use report_number: the same digits, written
// as a person writes them: 0.0001, 37.55, 1e-5, 2.5e-11, 1e16 (fixed notation for 1e-4 <= |v| <
// 1e16, as Python's repr; an exponent without '+' or leading zeros), and 0 for -0.0. It reads back
// as the same double but for the sign of a zero. Measured times are seconds_text: 3 significant
// digits in the same form.
//
// Where the standard library has no floating-point to_chars/from_chars (__cpp_lib_to_chars unset:
// emscripten's libc++, the explorer's WebAssembly build) the same texts come from
// detail::shortest_text and detail::read_decimal (snprintf/strtod in the "C" locale, digit
// counts tried upward): byte-identical to std::to_chars / std::from_chars, tested against them
// natively on random and extreme doubles (tests/io/test_io.cpp).
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace sphtroch {

/// Characters write_number may write: "-2.2250738585072014e-308" has 24.
constexpr std::size_t kMaxNumberChars = 24;

namespace detail {

/// The shortest round-trip text of v, as std::to_chars(first, last, v) writes it: the fewest
/// significant digits that read back as v (the nearest such decimal), then fixed or scientific
/// notation, whichever is shorter (fixed on a tie); "nan", "-nan", "inf", "-inf", "0", "-0".
/// Writes at most kMaxNumberChars characters at out and returns the end.
inline char* shortest_text(char* out, double v) noexcept;

/// std::from_chars(first, last, v) for doubles in the general format: [-]digits[.digits][e[+-]digits]
/// (a decimal point needs a digit on one side; a bare exponent mark is not part of the number),
/// or inf, infinity, nan, nan(chars) in any case. Out-of-range (beyond the largest double, or a
/// nonzero decimal that rounds to zero): ec = result_out_of_range, v unchanged.
inline std::from_chars_result read_decimal(const char* first, const char* last, double& v) noexcept;

}  // namespace detail

/// Writes the shortest round-trip form of v at out (room for kMaxNumberChars) and returns the end.
inline char* write_number(char* out, double v) noexcept {
#if defined(__cpp_lib_to_chars)
  return std::to_chars(out, out + kMaxNumberChars, v).ptr;
#else
  return detail::shortest_text(out, v);
#endif
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

/// The shortest round-trip decimal of |v| (v finite, not 0): its significant digits, without
/// leading or trailing zeros, and the decimal exponent of the first (|v| reads as
/// d1.d2d3... x 10^exponent): 37.55 is {"3755", 1}, 0.01 is {"1", -2}, 1200 is {"12", 3}.
struct DecimalDigits {
  std::string digits;
  int exponent = 0;
};
inline DecimalDigits decimal_digits(double v) {
  const std::string text = number_text(std::fabs(v));
  const std::size_t e_at = std::min(text.find('e'), text.size());
  const std::size_t point = std::min(text.find('.'), e_at);
  DecimalDigits d;
  for (std::size_t i = 0; i < e_at; ++i)
    if (text[i] != '.') d.digits += text[i];
  const std::size_t lead = std::min(d.digits.find_first_not_of('0'), d.digits.size());
  d.exponent = static_cast<int>(point) - 1 - static_cast<int>(lead) + (e_at < text.size() ? std::atoi(text.c_str() + e_at + 1) : 0);
  d.digits.erase(0, lead);
  d.digits.erase(std::min(d.digits.find_last_not_of('0') + 1, d.digits.size()));
  return d;
}

/// v for a sentence a person reads (see the header): number_text's digits, fixed notation for
/// 1e-4 <= |v| < 1e16, else d.ddde-5 / d.ddde16; -0.0 as "0"; "nan", "inf", "-inf" as number_text.
inline std::string report_number(double v) {
  if (v == 0) return "0";
  if (!std::isfinite(v)) return number_text(v);
  const DecimalDigits d = decimal_digits(v);
  const std::size_t count = d.digits.size();
  std::string out = v < 0 ? "-" : "";
  if (d.exponent < -4 || d.exponent > 15) {
    out += d.digits.substr(0, 1) + (count > 1 ? "." + d.digits.substr(1) : "") + "e" + std::to_string(d.exponent);
  } else if (d.exponent < 0) {
    out += "0." + std::string(static_cast<std::size_t>(-d.exponent - 1), '0') + d.digits;
  } else {
    const std::size_t whole = static_cast<std::size_t>(d.exponent) + 1;
    out += count <= whole ? d.digits + std::string(whole - count, '0') : d.digits.substr(0, whole) + "." + d.digits.substr(whole);
  }
  return out;
}

/// A measured time in seconds for text reports: 3 significant digits (timings are noisy; JSON
/// reports keep every digit with number_text / the JSON writer), written as report_number does.
inline std::string seconds_text(double seconds) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.3g", seconds);
  return report_number(std::strtod(buf, nullptr));
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
#if defined(__cpp_lib_to_chars)
  const auto [end, ec] = std::from_chars(first, last, value);
#else
  const auto [end, ec] = detail::read_decimal(first, last, value);
#endif
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

// ---------------------------------------------------------------------------------------------
// Implementation details follow.
// ---------------------------------------------------------------------------------------------

namespace detail {

/// The digits of |v| (no trailing zeros) and its decimal exponent (|v| = d.ddd x 10^exponent)
/// in the fewest significant digits that read back as v; the nearest such decimal.
struct ShortestDigits {
  char digits[18];
  int count = 0;
  int exponent = 0;
};

/// The P-digit decimal nearest |v| (correctly rounded, snprintf "%.*e") as digits and exponent.
inline ShortestDigits rounded_digits(double magnitude, int precision) noexcept {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*e", precision - 1, magnitude);
  ShortestDigits d;
  const char* p = buf;
  for (; *p != 'e'; ++p)
    if (*p != '.') d.digits[d.count++] = *p;
  d.exponent = std::atoi(p + 1);
  return d;
}

/// The decimal digits.exponent read back as a double.
inline double digits_value(const ShortestDigits& d) noexcept {
  char buf[48];
  std::memcpy(buf, d.digits, static_cast<std::size_t>(d.count));
  std::snprintf(buf + d.count, sizeof buf - static_cast<std::size_t>(d.count), "e%d",
                d.exponent - (d.count - 1));
  return std::strtod(buf, nullptr);
}

/// d with its last digit moved by +1 or -1 (carrying; a result of fewer digits is not formed).
inline bool step_last_digit(ShortestDigits& d, int step) noexcept {
  int i = d.count - 1;
  if (step > 0) {
    while (i >= 0 && d.digits[i] == '9') d.digits[i--] = '0';
    if (i < 0) return false;
    ++d.digits[i];
  } else {
    while (i >= 0 && d.digits[i] == '0') d.digits[i--] = '9';
    if (i < 0 || (i == 0 && d.digits[0] == '1' && d.count > 1)) return false;
    --d.digits[i];
  }
  return true;
}

inline ShortestDigits shortest_digits(double magnitude) noexcept {
  for (int precision = 1; precision < 17; ++precision) {
    const ShortestDigits nearest = rounded_digits(magnitude, precision);
    if (digits_value(nearest) == magnitude) return nearest;
    // Next to a power of two the round-trip interval is lopsided: a neighbour of the nearest
    // decimal may read back as v although the nearest does not.
    for (const int step : {1, -1}) {
      ShortestDigits other = nearest;
      if (step_last_digit(other, step) && digits_value(other) == magnitude) return other;
    }
  }
  return rounded_digits(magnitude, 17);
}

inline char* shortest_text(char* out, double v) noexcept {
  if (std::signbit(v)) *out++ = '-';
  if (std::isnan(v) || std::isinf(v)) {
    const char* word = std::isnan(v) ? "nan" : "inf";
    return std::copy(word, word + 3, out);
  }
  const double magnitude = std::fabs(v);
  if (magnitude == 0.0) {
    *out++ = '0';
    return out;
  }
  ShortestDigits d = shortest_digits(magnitude);
  while (d.count > 1 && d.digits[d.count - 1] == '0') --d.count;
  // Scientific: d[.ddd]e+XX (two exponent digits at least).
  char sci[32];
  int sci_len = 0;
  sci[sci_len++] = d.digits[0];
  if (d.count > 1) {
    sci[sci_len++] = '.';
    for (int i = 1; i < d.count; ++i) sci[sci_len++] = d.digits[i];
  }
  sci_len += std::snprintf(sci + sci_len, sizeof sci - static_cast<std::size_t>(sci_len), "e%c%02d",
                           d.exponent < 0 ? '-' : '+', d.exponent < 0 ? -d.exponent : d.exponent);
  // Fixed: the digits placed by the exponent, zeros filled in.
  const int fixed_len = d.exponent >= 0 ? std::max(d.count, d.exponent + 1) + (d.count > d.exponent + 1 ? 1 : 0)
                                        : 2 + (-d.exponent - 1) + d.count;
  if (sci_len < fixed_len) return std::copy(sci, sci + sci_len, out);
  if (d.exponent >= d.count) {
    // An integer written out: of the equally long texts that read back as v the exact one is
    // the nearest (to_chars writes 2^56 as 72057594037927936, not ...940).
    char whole[kMaxNumberChars + 1];
    std::snprintf(whole, sizeof whole, "%.0f", magnitude);
    return std::copy(whole, whole + d.exponent + 1, out);
  }
  if (d.exponent >= 0) {
    for (int i = 0; i <= d.exponent || i < d.count; ++i) {
      if (i == d.exponent + 1) *out++ = '.';
      *out++ = i < d.count ? d.digits[i] : '0';
    }
    return out;
  }
  *out++ = '0';
  *out++ = '.';
  for (int i = 0; i < -d.exponent - 1; ++i) *out++ = '0';
  return std::copy(d.digits, d.digits + d.count, out);
}

/// Case-insensitive match of the word at [p, last).
inline bool starts_with_word(const char* p, const char* last, const char* word) noexcept {
  for (; *word != '\0'; ++p, ++word)
    if (p == last || (*p | 0x20) != *word) return false;
  return true;
}

inline std::from_chars_result read_decimal(const char* first, const char* last, double& v) noexcept {
  const char* p = first;
  const bool negative = p != last && *p == '-';
  if (negative) ++p;
  if (starts_with_word(p, last, "inf")) {
    v = negative ? -HUGE_VAL : HUGE_VAL;
    return {p + (starts_with_word(p, last, "infinity") ? 8 : 3), std::errc()};
  }
  if (starts_with_word(p, last, "nan")) {
    const char* end = p + 3;
    if (end != last && *end == '(') {
      const char* q = end + 1;
      while (q != last && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
      if (q != last && *q == ')') end = q + 1;
    }
    v = negative ? -std::nan("") : std::nan("");
    return {end, std::errc()};
  }
  const char* q = p;
  while (q != last && *q >= '0' && *q <= '9') ++q;
  bool any_digit = q != p;
  if (q != last && *q == '.') {
    const char* fraction = ++q;
    while (q != last && *q >= '0' && *q <= '9') ++q;
    any_digit = any_digit || q != fraction;
  }
  if (!any_digit) return {first, std::errc::invalid_argument};
  if (q != last && (*q == 'e' || *q == 'E')) {
    const char* e = q + 1;
    if (e != last && (*e == '+' || *e == '-')) ++e;
    const char* exponent_digits = e;
    while (e != last && *e >= '0' && *e <= '9') ++e;
    if (e != exponent_digits) q = e;
  }
  const std::string text(first, q);  // strtod needs a terminated copy
  errno = 0;
  const double value = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && (std::isinf(value) || value == 0.0)) return {q, std::errc::result_out_of_range};
  v = value;
  return {q, std::errc()};
}

}  // namespace detail

}  // namespace sphtroch
