// sphtroch/machine/clinostat_text.hpp — a clinostat's settings as typed (CLI options, Python
// arguments, the explorer's URL), read into ClinostatSettings with errors naming the option.
//
//   sphtroch::ClinostatText text;
//   text.outer = "1.33";          // read exactly: 133/100 rpm
//   text.inner = "2";
//   text.tilt = "90";             // degrees
//   const sphtroch::Clinostat machine(text.settings());
//
// Speeds: an integer, a decimal with up to 6 places or p/q (|speed| <= 1000 rpm); no exponent, so
// that the exact fraction is the one typed. Angles and phases: decimal degrees. Offset: "X,Y,Z"
// in metres. InvalidInput's field is the option's name without "--".
#pragma once

#include "sphtroch/io/parse.hpp"
#include "sphtroch/machine/clinostat.hpp"

#include <algorithm>
#include <string>
#include <string_view>

namespace sphtroch {

constexpr const char* kRpmForms = "rpm as an integer, a decimal with up to 6 places or p/q (1.33, -2, 4/3), |rpm| <= 1000";

/// A speed as an exact fraction of rpm. Throws InvalidInput(field) for any other text.
inline Rpm parse_rpm(std::string_view text, const std::string& field) {
  const std::string shown(text);
  const std::string_view s = detail::trim(text);
  const auto bad = [&](const char* problem) { return InvalidInput(field, shown, problem, kRpmForms); };
  if (const auto slash = s.find('/'); slash != std::string_view::npos) {
    const auto p = detail::strict_int(s.substr(0, slash)), q = detail::strict_int(s.substr(slash + 1));
    if (!p || !q) throw bad("not a ratio of integers");
    if (*q == 0) throw bad("zero denominator");
    if (std::llabs(*p) > 1000000000LL || std::llabs(*q) > 1000000000LL) throw bad("too large");
    try {
      return Rpm(*p, *q, field);
    } catch (const InvalidInput& e) {
      throw bad(e.problem().c_str());
    }
  }
  std::string_view body = s;
  const bool negative = !body.empty() && body.front() == '-';
  if (!body.empty() && (body.front() == '-' || body.front() == '+')) body.remove_prefix(1);
  const auto dot = body.find('.');
  const std::string_view whole = body.substr(0, dot), fraction = dot == std::string_view::npos ? "" : body.substr(dot + 1);
  if (whole.empty() && fraction.empty()) throw bad("not a number");
  if (dot != std::string_view::npos && fraction.empty()) throw bad("not a number");
  for (const std::string_view part : {whole, fraction})
    for (const char c : part)
      if (c < '0' || c > '9') throw bad("not a number");
  if (fraction.size() > 6) throw bad("more than 6 decimal places");
  const std::string_view digits = whole.substr(std::min(whole.find_first_not_of('0'), whole.size()));  // 00001 is 1
  if (digits.size() > 4) throw bad("too fast");
  std::int64_t num = 0, den = 1;
  for (const char c : digits) num = num * 10 + (c - '0');
  for (const char c : fraction) {
    num = num * 10 + (c - '0');
    den *= 10;
  }
  try {
    return Rpm(negative ? -num : num, den, field);
  } catch (const InvalidInput& e) {
    throw bad(e.problem().c_str());
  }
}

/// Degrees as a finite decimal number. Throws InvalidInput(field) otherwise (ranges: Clinostat).
inline double parse_degrees(std::string_view text, const std::string& field, const char* valid) {
  const auto v = detail::strict_double(text);
  if (!v) throw InvalidInput(field, std::string(text), "not a number of degrees", valid);
  return *v;
}

/// "X,Y,Z" in metres. Throws InvalidInput(field) unless three finite numbers.
inline Vector3d parse_offset(std::string_view text, const std::string& field) {
  const std::string_view s = detail::trim(text);
  const std::string valid = "X,Y,Z in metres (sample frame), e.g. 0.05,0,0";
  const auto c1 = s.find(','), c2 = c1 == std::string_view::npos ? c1 : s.find(',', c1 + 1);
  if (c2 == std::string_view::npos || s.find(',', c2 + 1) != std::string_view::npos)
    throw InvalidInput(field, std::string(text), "not three numbers X,Y,Z", valid);
  const auto x = detail::strict_double(s.substr(0, c1)), y = detail::strict_double(s.substr(c1 + 1, c2 - c1 - 1)),
             z = detail::strict_double(s.substr(c2 + 1));
  if (!x || !y || !z) throw InvalidInput(field, std::string(text), "not three numbers X,Y,Z", valid);
  return Vector3d(*x, *y, *z);
}

/// The settings as typed; empty strings take the defaults (90, 90, 0, 0, no offset, gravity 1 g0).
struct ClinostatText {
  std::string outer, inner, tilt, frame_angle, phase_outer, phase_inner, offset, gravity;

  ClinostatSettings settings() const {
    ClinostatSettings s;
    s.outer = parse_rpm(outer, "outer");
    s.inner = parse_rpm(inner, "inner");
    if (!tilt.empty()) s.tilt_deg = parse_degrees(tilt, "tilt", "[0, 180] degrees");
    if (!frame_angle.empty()) s.frame_angle_deg = parse_degrees(frame_angle, "frame-angle", "[0, 180] degrees");
    if (!phase_outer.empty()) s.phase_outer_deg = parse_degrees(phase_outer, "phase-outer", "|phase| <= 1e6 degrees");
    if (!phase_inner.empty()) s.phase_inner_deg = parse_degrees(phase_inner, "phase-inner", "|phase| <= 1e6 degrees");
    if (!offset.empty()) s.offset_m = parse_offset(offset, "offset");
    if (!gravity.empty()) {
      const auto g = detail::strict_double(gravity);
      if (!g) throw InvalidInput("gravity", gravity, "not a number", "[0.001, 1000] g0");
      s.gravity_g0 = *g;  // its range: Clinostat's constructor
    }
    return s;
  }
};

}  // namespace sphtroch
