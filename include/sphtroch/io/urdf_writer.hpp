// sphtroch/io/urdf_writer.hpp — a rotation chain (core/rotation_chain.hpp) written as a URDF robot
// description whose joints are coupled by <mimic>; read back by io/urdf_chain.hpp (urdfdom). No
// XML library: the document is written here.
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {0.5, sphtroch::ChainRate(-2, 3), 0.3}});
//   const std::string xml = sphtroch::chain_to_urdf(chain, "wrist");
//
// chain_to_urdf: links base_link, link_1 .. link_k, tool; joint_i (continuous, axis z)
// from link_{i-1} (base_link for i = 1) to link_i, origin rpy (A_{i-1}, 0, 0) (identity for i =
// 1); a fixed joint tool_joint from link_k to tool, origin rpy (A_k, 0, 0): the tool axis is the
// tool link's z. The motor is the first joint with a nonzero rate N_m; every other joint mimics
// it with multiplier N_i / N_m and offset P_i - (N_i / N_m) P_m, so that the motor's angle is
// u = N_m s + P_m. Numbers are written as the shortest decimals that read back as the same
// doubles (number_text: at most 17 significant digits), the XML by hand (urdfdom 3.0's exporter
// writes 6 significant digits). Round trip: read_urdf_chain(chain_to_urdf(c), "base_link", "tool", z) gives rates
// N_i / N_m exactly (the motor's 1), twists within a few ulp, phases P_i - (N_i / N_m) P_m, and a
// curve whose point at u = N_m s + P_m is c's point at s (the parameter is defined up to such a
// change: compare chains by their curves and by their rates' ratios); base_rotation is I.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/rotation_chain.hpp"

#include <cmath>
#include <string>

namespace sphtroch {

/// The chain as a URDF document (layout above). REQUIRES a nonempty robot_name; the ratios
/// N_i / N_m in lowest terms p/q with |p| q < 0.9999e12 (so that the reader recovers them
/// exactly). Throws InvalidInput naming "robot name" or "rates" otherwise.
inline std::string chain_to_urdf(const RotationChain& chain, const std::string& robot_name);

namespace urdf_writer_detail {

/// A value for an XML attribute in double quotes.
inline std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else if (c == '\'') out += "&apos;";
    else out += c;
  }
  return out;
}

/// N_i / N_m in lowest terms, refused unless the reader recovers it exactly (|p| q < 0.9999e12:
/// then every other fraction with q' <= 1e6 is more than 1e-12 relative away from it).
inline ChainRate rate_ratio(const ChainRate& n, const ChainRate& motor, std::size_t stage) {
  const std::string shown = n.str() + " / " + motor.str() + " (stage " + std::to_string(stage + 1) + ")";
  const char* valid = "rates whose ratios to the motor's are p/q with |p|, q <= 1e6 and |p| q < 0.9999e12";
  ChainRate r;
  try {
    r = ChainRate(n.p() * motor.q(), n.q() * motor.p());
  } catch (const InvalidInput&) {
    throw InvalidInput("rates", shown, "the ratio to the motor's rate has a term beyond 1e6", valid);
  }
  if (std::fabs(static_cast<double>(r.p())) * static_cast<double>(r.q()) >= 0.9999e12)
    throw InvalidInput("rates", shown, "the ratio to the motor's rate could not be recovered exactly from its decimal", valid);
  return r;
}

/// One <joint> element of chain_to_urdf's layout.
inline std::string joint_xml(std::size_t i, double twist_before, const std::string& mimic) {
  const std::string parent = i == 0 ? "base_link" : "link_" + std::to_string(i);
  return "  <joint name=\"joint_" + std::to_string(i + 1) + "\" type=\"continuous\">\n    <parent link=\"" + parent +
         "\"/>\n    <child link=\"link_" + std::to_string(i + 1) + "\"/>\n    <origin xyz=\"0 0 0\" rpy=\"" + number_text(twist_before) +
         " 0 0\"/>\n    <axis xyz=\"0 0 1\"/>\n" + mimic + "  </joint>\n";
}

}  // namespace urdf_writer_detail

inline std::string chain_to_urdf(const RotationChain& chain, const std::string& robot_name) {
  namespace d = urdf_writer_detail;
  if (robot_name.empty()) throw InvalidInput("robot name", "\"\"", "empty", "a nonempty name");
  const std::vector<ChainStage>& stages = chain.stages();
  std::size_t m = 0;
  while (stages[m].rate.is_zero()) ++m;  // RotationChain: some rate is not 0
  std::string xml = "<?xml version=\"1.0\"?>\n<robot name=\"" + d::xml_escaped(robot_name) + "\">\n  <link name=\"base_link\"/>\n";
  for (std::size_t i = 0; i < stages.size(); ++i) xml += "  <link name=\"link_" + std::to_string(i + 1) + "\"/>\n";
  xml += "  <link name=\"tool\"/>\n";
  for (std::size_t i = 0; i < stages.size(); ++i) {
    std::string mimic;
    if (i != m) {
      const ChainRate r = d::rate_ratio(stages[i].rate, stages[m].rate, i);
      const double offset = stages[i].phase - r.value() * stages[m].phase;
      mimic = "    <mimic joint=\"joint_" + std::to_string(m + 1) + "\" multiplier=\"" + number_text(r.value()) + "\" offset=\"" +
              number_text(offset) + "\"/>\n";
    }
    xml += d::joint_xml(i, i == 0 ? 0.0 : stages[i - 1].twist, mimic);
  }
  xml += "  <joint name=\"tool_joint\" type=\"fixed\">\n    <parent link=\"link_" + std::to_string(stages.size()) +
         "\"/>\n    <child link=\"tool\"/>\n    <origin xyz=\"0 0 0\" rpy=\"" + number_text(stages.back().twist) + " 0 0\"/>\n  </joint>\n";
  return xml + "</robot>\n";
}

}  // namespace sphtroch
