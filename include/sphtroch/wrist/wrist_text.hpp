// sphtroch/wrist/wrist_text.hpp — a wrist and its target as typed (the `sphtroch wrist ik`
// options; one reader for every front end).
//
//   sphtroch::WristText text;
//   text.twists = "0,pi/3,pi/4";
//   text.coupling = "1,0;0,1;0,3/2";
//   text.target = "0.6,0,0.8";
//   const sphtroch::Wrist wrist = text.wrist();            // phases all 0, tool axis z
//   const sphtroch::WristTarget t = text.wrist_target(wrist);
//
// Twists and phases in any angle form of parse_angle ("pi/2", "0.3", "90deg"); the coupling by
// rows separated by ';', entries by ',', each exact: an integer, p/q, a decimal (at most 9
// places) or 0 (io/chain_text.hpp's rate forms). The tool axis "X,Y,Z" (default 0,0,1). The
// target: `target` "X,Y,Z" (a unit vector: pointing, 2 motors) or `target_frame`, 4 numbers
// w,x,y,z (a unit quaternion) or 9 (a rotation matrix by rows) (orientation, 3 motors); exactly one
// of them, of the wrist's kind. Errors (InvalidInput) name the option without "--": "twists",
// "coupling", "phases", "axis", "target", "target-frame", "home", with the item, the problem and the
// valid forms. `home` (wrist cap): "X,Y,Z", three finite numbers.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/io/chain_text.hpp"  // split_list, parse_chain_rate
#include "sphtroch/io/parse.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_target.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sphtroch {

struct WristText {
  std::string twists, coupling, phases, axis;  ///< phases "" = all 0; axis "" = 0,0,1
  std::string target, target_frame;            ///< exactly one (wrist ik)
  std::string home;                             ///< wrist cap: the home direction X,Y,Z

  /// The home direction as typed: three finite numbers (its length is checked by wrist_cap,
  /// naming "home": within 1e-6 of unit).
  Vector3d home_direction() const {
    if (detail::trim(home).empty()) throw InvalidInput("home", home, "missing", "X,Y,Z: a unit vector (|h| within 1e-6 of 1)");
    return numbers(home, "home", {3});
  }

  Wrist wrist() const {
    const std::vector<std::string> a = items(twists, "twists"), p = items(phases, "phases");
    if (a.empty()) throw InvalidInput("twists", twists, "no twist", "A1,...,Ak: k angles in [0, pi], 1 <= k <= 6");
    if (!p.empty() && p.size() != a.size())
      throw InvalidInput("phases", phases, std::to_string(p.size()) + " phase(s) for " + std::to_string(a.size()) + " twist(s)",
                         "one phase per twist: P1,...,Pk (or none: all 0)");
    std::vector<WristJoint> joints;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string at = " (joint " + std::to_string(i + 1) + ")";
      joints.push_back({angle_item(a[i], "twists", at), p.empty() ? 0.0 : angle_item(p[i], "phases", at)});
    }
    std::vector<std::vector<ChainRate>> rows = coupling_rows();  // in this order: the first bad option is named
    const Vector3d tool = tool_axis();
    return Wrist(joints, std::move(rows), tool);
  }

  /// The target of the wrist's kind (see header).
  WristTarget wrist_target(const Wrist& wrist) const {
    if (!target.empty() && !target_frame.empty())
      throw InvalidInput("target", target, "given with --target-frame", "either --target X,Y,Z (2 motors) or --target-frame (3 motors)");
    if (target.empty() && target_frame.empty())
      throw InvalidInput("target", "", "missing", "--target X,Y,Z (a unit vector, 2 motors) or --target-frame w,x,y,z | 9 numbers (3 motors)");
    if (!target.empty()) {
      if (wrist.motors() != 2)
        throw InvalidInput("target", target, "a direction for a 3-motor wrist (its solutions form curves)",
                           "--target X,Y,Z with a 2-column --coupling; with 3 columns, --target-frame");
      return WristTarget::pointing(numbers(target, "target", {3}), "target");
    }
    if (wrist.motors() != 3)
      throw InvalidInput("target-frame", target_frame, "an orientation for a 2-motor wrist (3 conditions, 2 motors)",
                         "--target-frame with a 3-column --coupling; with 2 columns, --target X,Y,Z");
    if (!axis.empty()) throw InvalidInput("axis", axis, "given with --target-frame", "--axis with --target X,Y,Z only (an orientation fixes every axis)");
    const Eigen::VectorXd v = numbers(target_frame, "target-frame", {4, 9});
    if (v.size() == 4) return WristTarget::orientation(Eigen::Quaterniond(v[0], v[1], v[2], v[3]), "target-frame");
    Matrix3d r;
    r << v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8];
    return WristTarget::orientation(r, "target-frame");
  }

 private:
  /// The comma-separated items; an empty item refused naming the option.
  static std::vector<std::string> items(const std::string& text, const std::string& field) {
    const std::vector<std::string> out = split_list(text);
    for (const std::string& item : out)
      if (detail::trim(item).empty()) throw InvalidInput(field, text, "an empty item", "comma-separated values, one per joint");
    return out;
  }

  static double angle_item(const std::string& item, const std::string& field, const std::string& at) {
    try {
      return parse_angle(item, field);
    } catch (const InvalidInput& e) {
      throw InvalidInput(field, item + at, e.problem(), e.valid_range());
    }
  }

  /// "c11,c12;c21,c22;...": rows by ';', entries by ','; each an exact fraction (0 allowed).
  std::vector<std::vector<ChainRate>> coupling_rows() const {
    const std::string valid = "rows separated by ';', entries by ',', each an exact number: an integer, p/q or a decimal (1,0;0,1;0,3/2)";
    if (detail::trim(coupling).empty()) throw InvalidInput("coupling", coupling, "missing", valid);
    std::vector<std::vector<ChainRate>> rows;
    std::size_t start = 0;
    while (true) {
      const std::size_t semicolon = coupling.find(';', start);
      const std::string row = coupling.substr(start, semicolon == std::string::npos ? std::string::npos : semicolon - start);
      std::vector<ChainRate> entries;
      for (const std::string& item : split_list(row)) {
        const std::string at = " (row " + std::to_string(rows.size() + 1) + ", column " + std::to_string(entries.size() + 1) + ")";
        if (detail::trim(item).empty()) throw InvalidInput("coupling", coupling, "an empty entry" + at, valid);
        try {
          entries.push_back(parse_chain_rate(item, "coupling"));
        } catch (const InvalidInput& e) {
          throw InvalidInput("coupling", item + at, e.problem(), valid);
        }
      }
      if (entries.empty()) throw InvalidInput("coupling", coupling, "an empty row (row " + std::to_string(rows.size() + 1) + ")", valid);
      rows.push_back(entries);
      if (semicolon == std::string::npos) return rows;
      start = semicolon + 1;
    }
  }

  Vector3d tool_axis() const {
    if (axis.empty()) return Vector3d::UnitZ();
    return numbers(axis, "axis", {3});  // zero: refused by Wrist, naming "axis"
  }

  /// The comma-separated finite numbers of `text`, as many as one of `counts`.
  static Eigen::VectorXd numbers(const std::string& text, const std::string& field, const std::vector<std::size_t>& counts) {
    const std::vector<std::string> parts = split_list(text);
    std::string want;
    for (const std::size_t c : counts) want += (want.empty() ? "" : " or ") + std::to_string(c);
    const std::string valid = want + " comma-separated finite numbers";
    bool count_ok = false;
    for (const std::size_t c : counts) count_ok = count_ok || parts.size() == c;
    if (!count_ok) throw InvalidInput(field, text, std::to_string(parts.size()) + " number(s)", valid);
    Eigen::VectorXd v(static_cast<Eigen::Index>(parts.size()));
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const std::optional<double> x = detail::strict_double(detail::trim(parts[k]));
      if (!x) throw InvalidInput(field, text, "not a finite number: " + parts[k], valid);
      v[static_cast<Eigen::Index>(k)] = *x;
    }
    return v;
  }
};

}  // namespace sphtroch
