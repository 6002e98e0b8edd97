// sphtroch/io/chain_text.hpp — a rotation chain as typed: comma-separated twists, rates and
// phases (the `sphtroch chain` options; one reader for every front end).
//
//   sphtroch::ChainText text;
//   text.twists = "pi/2,1.2,0.4";
//   text.rates = "1,-2/3,5/3";
//   const sphtroch::RotationChain chain = text.chain();   // phases all 0
//
// Twists and phases in any angle form of parse_angle ("pi/2", "0.3", "2*pi/3"); twists in
// [0, pi]. Rates exactly: integers, decimals (up to 9 places) or p/q, and 0 (a joint that does
// not turn). Errors name the option ("twists", "rates", "phases") and the stage; lists of
// different lengths are refused naming the shorter or longer one.
// Or from a robot description: urdf (a file, - for stdin, at most kMaxUrdfBytes), from and to
// (links), axis (the tool axis in the to link's frame, "X,Y,Z", default "0,0,1"), read by
// `urdf_reader`: io/urdf_chain.hpp's chain_from_urdf when the build has urdfdom
// (SPHTROCH_HAVE_URDF), or a front end's own (the tool's opens urdfdom only when it reads one);
// none: refused naming "urdf".
// One source only: twists/rates/phases with urdf, or from/to/axis without it, are refused.
#pragma once

#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/io/input_file.hpp"
#include "sphtroch/io/parse.hpp"
#if defined(SPHTROCH_HAVE_URDF)
#include "sphtroch/io/urdf_chain.hpp"
#endif

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sphtroch {

/// The items of a comma-separated list, each as typed (an empty list: none; an empty item: "").
inline std::vector<std::string> split_list(std::string_view text) {
  std::vector<std::string> items;
  if (detail::trim(text).empty()) return items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    items.emplace_back(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return items;
    start = comma + 1;
  }
}

/// True for a zero written as parse_ratio's forms would write it: "0", "-0", "0/7", "0.0", "-0.000".
inline bool is_zero_rate_text(std::string_view s) {
  if (const std::size_t slash = s.find('/'); slash != std::string_view::npos)
    return detail::strict_int(s.substr(0, slash)) == std::optional<std::int64_t>(0) && detail::strict_int(s.substr(slash + 1)).value_or(0) != 0;
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
  const std::size_t dot = s.find('.');
  const std::string_view whole = s.substr(0, dot), fraction = dot == std::string_view::npos ? std::string_view() : s.substr(dot + 1);
  const auto zeros = [](std::string_view t) { return t.find_first_not_of('0') == std::string_view::npos; };
  if (dot != std::string_view::npos && (fraction.empty() || fraction.size() > 9)) return false;
  return !(whole.empty() && fraction.empty()) && zeros(whole) && zeros(fraction);
}

/// A joint rate: 0 in any form (is_zero_rate_text), else parse_ratio's exact forms.
inline ChainRate parse_chain_rate(std::string_view text, const std::string& field = "rates") {
  if (is_zero_rate_text(detail::trim(text))) return ChainRate(0);
  const Ratio r = parse_ratio(text, field);
  return ChainRate(r.p(), r.q());
}

/// The largest URDF file read (a robot description is kilobytes; this bounds the parser's memory).
constexpr std::size_t kMaxUrdfBytes = std::size_t{16} << 20;

/// The chain of a URDF document between two links with a tool axis (chain_from_urdf's contract).
using UrdfChainReader = RotationChain (*)(const std::string& xml, const std::string& from, const std::string& to, const Vector3d& axis);

/// chain_from_urdf when this build has urdfdom, else none.
inline UrdfChainReader built_in_urdf_reader() {
#if defined(SPHTROCH_HAVE_URDF)
  return [](const std::string& xml, const std::string& from, const std::string& to, const Vector3d& axis) {
    return chain_from_urdf(xml, from, to, axis);
  };
#else
  return nullptr;
#endif
}

struct ChainText {
  std::string twists, rates, phases;  ///< comma-separated; phases "" = all 0
  std::string urdf, from, to, axis;   ///< a URDF file, its links, the tool axis "X,Y,Z" ("" = 0,0,1)
  UrdfChainReader urdf_reader = built_in_urdf_reader();  ///< reads `urdf`; none: refused naming "urdf"

  RotationChain chain() const {
    if (!urdf.empty()) return urdf_chain();
    for (const auto& [value, field] : {std::pair{&from, "from"}, std::pair{&to, "to"}, std::pair{&axis, "axis"}})
      if (!value->empty()) throw InvalidInput(field, *value, "given without --urdf", "--from, --to and --axis with --urdf FILE");
    if (twists.empty() && rates.empty())
      throw InvalidInput("twists", "", "no chain given", "--twists A1,...,Ak --rates N1,...,Nk, or --urdf FILE --from LINK --to LINK");
    return typed_chain();
  }

 private:
  RotationChain typed_chain() const {
    const std::vector<std::string> a = split_list(twists), n = split_list(rates), p = split_list(phases);
    if (a.empty()) throw InvalidInput("twists", twists, "no twist", "A1,...,Ak: k angles in [0, pi]");
    for (const auto& [list, field] : {std::pair{&a, "twists"}, std::pair{&n, "rates"}, std::pair{&p, "phases"}})
      for (const std::string& item : *list)
        if (detail::trim(item).empty())
          throw InvalidInput(field, field == std::string("twists") ? twists : field == std::string("rates") ? rates : phases,
                             "an empty item", "comma-separated values, one per stage");
    if (n.size() != a.size())
      throw InvalidInput("rates", rates, std::to_string(n.size()) + " rate(s) for " + std::to_string(a.size()) + " twist(s)",
                         "one rate per twist: N1,...,Nk");
    if (!p.empty() && p.size() != a.size())
      throw InvalidInput("phases", phases, std::to_string(p.size()) + " phase(s) for " + std::to_string(a.size()) + " twist(s)",
                         "one phase per twist: P1,...,Pk (or none: all 0)");
    std::vector<ChainStage> stages;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string stage = " (stage " + std::to_string(i + 1) + ")";
      ChainStage s;
      s.twist = parse_angle_item(a[i], "twists", stage);
      s.rate = parse_rate_item(n[i], stage);
      s.phase = p.empty() ? 0.0 : parse_angle_item(p[i], "phases", stage);
      stages.push_back(s);
    }
    return RotationChain(stages);
  }

  RotationChain urdf_chain() const {
    for (const auto& [value, field] : {std::pair{&twists, "twists"}, std::pair{&rates, "rates"}, std::pair{&phases, "phases"}})
      if (!value->empty()) throw InvalidInput(field, *value, "given with --urdf", "either --urdf FILE or --twists/--rates/--phases");
    if (from.empty()) throw InvalidInput("from", "", "missing", "--from LINK: the link the chain starts at");
    if (to.empty()) throw InvalidInput("to", "", "missing", "--to LINK: the link that carries the tool axis");
    if (!urdf_reader) throw InvalidInput("urdf", urdf, "this build has no urdfdom", "a build with sphtroch::urdf (Debian's liburdfdom-dev)");
    const std::string xml = read_whole_input(urdf, "urdf", kMaxUrdfBytes);
    return urdf_reader(xml, from, to, tool_axis());
  }

  Vector3d tool_axis() const {
    if (axis.empty()) return Vector3d::UnitZ();
    const std::vector<std::string> items = split_list(axis);
    const std::string valid = "X,Y,Z: three finite numbers, not all 0";
    if (items.size() != 3) throw InvalidInput("axis", axis, std::to_string(items.size()) + " number(s)", valid);
    Vector3d v;
    for (int k = 0; k < 3; ++k) {
      const std::optional<double> x = detail::strict_double(detail::trim(items[static_cast<std::size_t>(k)]));
      if (!x) throw InvalidInput("axis", axis, "not a number: " + items[static_cast<std::size_t>(k)], valid);
      v[k] = *x;
    }
    return v;  // zero or huge: refused by read_urdf_chain, naming "axis"
  }

  /// A rate; a refusal names the stage and the chain's valid forms (0 included).
  static ChainRate parse_rate_item(const std::string& item, const std::string& stage) {
    try {
      return parse_chain_rate(item, "rates");
    } catch (const InvalidInput& e) {
      throw InvalidInput("rates", item + stage, e.problem(),
                         "an exact rate: an integer, p/q or a decimal (at most 9 places) that is p/q with |p|, |q| <= 1000000 in lowest terms, or 0");
    }
  }

  static double parse_angle_item(const std::string& item, const std::string& field, const std::string& stage) {
    try {
      return parse_angle(item, field);
    } catch (const InvalidInput& e) {
      throw InvalidInput(field, item + stage, e.problem(), e.valid_range());
    }
  }
};

}  // namespace sphtroch
