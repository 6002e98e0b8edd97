// sphtroch/core/errors.hpp — the two tiers of errors.
//
//   try { sphtroch::GearTrain bad(4.0, 1.0, sphtroch::Ratio(1)); }
//   catch (const sphtroch::InvalidInput& e) { e.field(); e.value(); e.valid_range(); }  // "a2", "4", "(0, pi) radians"
//
// 1. User input is validated; a bad value throws sphtroch::InvalidInput, a
//    std::invalid_argument that names the field, the offending value and the valid range:
//
//      try { GearTrain train(4.0, 1.0, Ratio(1)); }
//      catch (const sphtroch::InvalidInput& e) { e.field() == "a2"; e.valid_range() == "(0, pi) radians"; }
//
// 2. Programmer errors (broken preconditions inside the library) are assertions:
//    SPHTROCH_ASSERT(cond, message). Define SPHTROCH_ASSERT before including any sphtroch
//    header to route them elsewhere; by default they call std::abort() with a message, also
//    in release builds (they guard cheap conditions only).
#pragma once

#include "sphtroch/core/number_text.hpp"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>

namespace sphtroch {

/// Thrown for invalid user input. what() reads "<field> = <value>: <problem>; valid: <range>".
class InvalidInput : public std::invalid_argument {
 public:
  InvalidInput(std::string field, std::string value, std::string problem, std::string valid_range)
      : std::invalid_argument(field + " = " + value + ": " + problem + "; valid: " + valid_range),
        field_(std::move(field)),
        value_(std::move(value)),
        problem_(std::move(problem)),
        valid_range_(std::move(valid_range)) {}

  const std::string& field() const noexcept { return field_; }
  const std::string& value() const noexcept { return value_; }
  const std::string& problem() const noexcept { return problem_; }
  const std::string& valid_range() const noexcept { return valid_range_; }
  /// what()'s text as a std::string: whole even when the value holds a NUL byte (what() is a C
  /// string and stops there).
  std::string message() const { return field_ + " = " + value_ + ": " + problem_ + "; valid: " + valid_range_; }

 private:
  std::string field_;
  std::string value_;
  std::string problem_;
  std::string valid_range_;
};

/// `message` on one line: newline, carriage return, tab as \n, \r, \t, other control bytes as
/// \xHH (what the tool prints to stderr, and str() of the Python module's InvalidInput).
inline std::string one_line_text(const std::string& message) {
  std::string out;
  for (const char ch : message) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else out += ch;
  }
  return out;
}

namespace detail {
[[noreturn]] inline void assertion_failed(const char* condition, const char* message, const char* file,
                                          int line) {
  std::fprintf(stderr, "sphtroch: assertion failed: %s (%s) at %s:%d\n", condition, message, file, line);
  std::abort();
}
}  // namespace detail

}  // namespace sphtroch

#ifndef SPHTROCH_ASSERT
#define SPHTROCH_ASSERT(condition, message) \
  ((condition) ? static_cast<void>(0)       \
               : ::sphtroch::detail::assertion_failed(#condition, message, __FILE__, __LINE__))
#endif
