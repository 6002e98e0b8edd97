// src/cli/clinostat_fields.hpp — a clinostat's settings as plugin fields (plugin_fields.hpp) and
// back, exactly: speeds as their fractions num/den, angles and the offset as round-trip decimals.
#pragma once

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/machine/clinostat.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace sphtroch::cli {

constexpr std::size_t kClinostatFields = 9;

inline std::vector<std::string> clinostat_fields(const ClinostatSettings& s) {
  const auto rpm = [](const Rpm& r) { return std::to_string(r.num()) + "/" + std::to_string(r.den()); };
  return {rpm(s.outer), rpm(s.inner), number_text(s.tilt_deg), number_text(s.frame_angle_deg), number_text(s.phase_outer_deg),
          number_text(s.phase_inner_deg), number_text(s.offset_m.x()), number_text(s.offset_m.y()), number_text(s.offset_m.z())};
}

/// The settings of fields [at, at + kClinostatFields); std::runtime_error when they are not
/// clinostat_fields' (a bug: the tool and its plugin disagree).
inline ClinostatSettings clinostat_settings(const std::vector<std::string>& f, std::size_t at) {
  const auto number = [&](std::size_t k) {
    const std::optional<double> v = detail::strict_double(f.at(at + k));
    if (!v) throw std::runtime_error("clinostat fields: not a number: " + f.at(at + k));
    return *v;
  };
  const auto rpm = [&](std::size_t k) {
    const std::string& t = f.at(at + k);
    const std::size_t slash = t.find('/');
    const std::optional<std::int64_t> p = detail::strict_int(t.substr(0, slash)), q = detail::strict_int(t.substr(slash + 1));
    if (slash == std::string::npos || !p || !q) throw std::runtime_error("clinostat fields: not a speed: " + t);
    return Rpm(*p, *q);
  };
  ClinostatSettings s;
  s.outer = rpm(0);
  s.inner = rpm(1);
  s.tilt_deg = number(2), s.frame_angle_deg = number(3), s.phase_outer_deg = number(4), s.phase_inner_deg = number(5);
  s.offset_m = Vector3d(number(6), number(7), number(8));
  return s;
}

}  // namespace sphtroch::cli
