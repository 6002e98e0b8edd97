// src/cli/step_request.hpp — what the tool asks of the STEP plugin (step_plugin.cpp, through
// output_plugin.hpp): a gear train, the STEP options and the mode ("check": the refusals that need
// no computation, no output; "write": the STEP file's bytes). Text, one "key value" a line; every
// double as the 16 hex digits of its bits, so that the plugin rebuilds the very train the tool
// parsed (a2, a3's reference and offset, n, the phase as given, the right-angle flag).
#pragma once

#include "step_output.hpp"

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/ratio.hpp"

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sphtroch::cli {

struct StepRequest {
  bool check_only = false;  // true: check_step_options only; false: the file
  GearTrain train;
  StepOutputOptions options;
};

namespace step_request_detail {

inline std::string bits(double x) {
  std::uint64_t u = 0;
  std::memcpy(&u, &x, sizeof u);
  char text[24];
  std::snprintf(text, sizeof text, "%016" PRIx64, u);
  return text;
}

inline double from_bits(const std::string& text) {
  std::size_t used = 0;
  const std::uint64_t u = std::stoull(text, &used, 16);
  if (used != text.size() || text.size() != 16) throw std::invalid_argument(text);
  double x = 0;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

inline std::string optional_bits(const std::optional<double>& x) { return x ? bits(*x) : "none"; }
inline std::optional<double> optional_from_bits(const std::string& text) {
  if (text == "none") return std::nullopt;
  return from_bits(text);
}

}  // namespace step_request_detail

/// The request as text (the format above, "sphtroch-step-request 1" first).
inline std::string step_request_text(const StepRequest& r) {
  using namespace step_request_detail;
  const GearTrain& t = r.train;
  std::ostringstream out;
  out << "sphtroch-step-request 1\nmode " << (r.check_only ? "check" : "write") << "\na2 " << bits(t.a2())
      << "\na3_reference " << static_cast<int>(t.a3_reference()) << "\na3_offset " << bits(t.a3_offset()) << "\np "
      << t.ratio().p() << "\nq " << t.ratio().q() << "\nphase " << bits(t.phase_given()) << "\na2_right_angle "
      << (t.a2_is_right_angle() ? 1 : 0) << "\nradius " << bits(r.options.radius) << "\ntolerance "
      << optional_bits(r.options.tolerance) << "\nturns " << optional_bits(r.options.turns) << "\n";
  return out.str();
}

/// The request step_request_text wrote. Throws std::runtime_error for any other text.
inline StepRequest parse_step_request(const std::string& text) {
  using namespace step_request_detail;
  std::istringstream in(text);
  std::map<std::string, std::string> field;
  for (std::string key, value; in >> key >> value;) field[key] = value;
  try {
    if (field.at("sphtroch-step-request") != "1") throw std::invalid_argument("version");
    StepRequest r;
    r.check_only = field.at("mode") == "check";
    const auto reference = static_cast<A3Reference>(std::stoi(field.at("a3_reference")));
    r.train = GearTrain::on_cone(from_bits(field.at("a2")), reference, from_bits(field.at("a3_offset")),
                                 Ratio(std::stoll(field.at("p")), std::stoll(field.at("q"))), from_bits(field.at("phase")));
    if (field.at("a2_right_angle") == "1") r.train = r.train.with_right_angle_a2();
    r.options.radius = from_bits(field.at("radius"));
    r.options.tolerance = optional_from_bits(field.at("tolerance"));
    r.options.turns = optional_from_bits(field.at("turns"));
    return r;
  } catch (const InvalidInput&) {
    throw;  // the train's own check (a tool's train passes it)
  } catch (const std::logic_error&) {  // std::out_of_range (a key missing), std::invalid_argument
    throw std::runtime_error("STEP plugin: a malformed request (a tool and a plugin of different builds?)");
  }
}

}  // namespace sphtroch::cli
