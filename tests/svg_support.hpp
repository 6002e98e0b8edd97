// Reading the SVG documents the tool and the library write, for tests that measure pictures: the
// elements with their attributes, the groups they sit in and their text; style values, font sizes,
// colours as sRGB and their relative luminance. A scanner for the documents svg.hpp writes
// (attributes in double quotes, no CDATA, no comments), written here independently of the writer.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

namespace svg_test {

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::vector<std::string> groups;  ///< the id of every enclosing <g> (outermost first; "" for one without)
  std::string text;                 ///< a <text> element's content, entities decoded
  bool in_group(const std::string& id) const { return std::find(groups.begin(), groups.end(), id) != groups.end(); }
  bool has(const std::string& attribute) const { return attributes.count(attribute) != 0; }
  double number(const std::string& attribute) const { return std::stod(attributes.at(attribute)); }
};

inline std::string decode_entities(std::string s) {
  static const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities)
    for (std::size_t at; (at = s.find(from)) != std::string::npos;) s.replace(at, std::string(from).size(), to);
  return s;
}

/// The attributes name="value" of a tag's text (after its name), scanned by hand: std::regex
/// recurses per character and a path's data runs to hundreds of kB.
inline std::map<std::string, std::string> attributes(const std::string& tag) {
  std::map<std::string, std::string> out;
  for (std::size_t at = tag.find(' '); at != std::string::npos && at < tag.size();) {
    const std::size_t eq = tag.find("=\"", at);
    if (eq == std::string::npos) break;
    const std::size_t end = tag.find('"', eq + 2);
    if (end == std::string::npos) throw std::runtime_error("unterminated attribute");
    std::size_t name = tag.find_last_of(" \n", eq);
    name = name == std::string::npos ? 0 : name + 1;
    out[tag.substr(name, eq - name)] = decode_entities(tag.substr(eq + 2, end - eq - 2));
    at = end + 1;
  }
  return out;
}

/// Every element of the document, in document order.
inline std::vector<Element> elements(const std::string& svg) {
  std::vector<Element> out;
  std::vector<std::string> groups;
  for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
    if (svg.compare(at, 2, "<?") == 0 || svg.compare(at, 2, "<!") == 0) continue;
    const std::size_t close = svg.find('>', at);
    if (close == std::string::npos) throw std::runtime_error("unterminated tag");
    if (svg[at + 1] == '/') {
      if (svg.compare(at, 4, "</g>") == 0 && !groups.empty()) groups.pop_back();
      continue;
    }
    const std::string tag = svg.substr(at + 1, close - at - 1);
    Element e;
    e.name = tag.substr(0, tag.find_first_of(" \n/"));
    e.attributes = attributes(tag);
    e.groups = groups;
    const bool self_closing = tag.back() == '/';
    if (e.name == "text" && !self_closing) e.text = decode_entities(svg.substr(close + 1, svg.find("</text>", close) - close - 1));
    if (e.name == "g" && !self_closing) groups.push_back(e.has("id") ? e.attributes.at("id") : "");
    out.push_back(std::move(e));
  }
  return out;
}

/// The value of CSS property `name` in the element's style attribute, or its attribute `name`.
inline std::optional<std::string> style(const Element& e, const std::string& name) {
  if (e.has("style")) {
    const std::string& s = e.attributes.at("style");
    for (std::size_t at = 0; at < s.size();) {
      const std::size_t end = std::min(s.find(';', at), s.size()), colon = s.find(':', at);
      if (colon < end && s.substr(at, colon - at) == name) return s.substr(colon + 1, end - colon - 1);
      at = end + 1;
    }
  }
  if (e.has(name)) return e.attributes.at(name);
  return std::nullopt;
}

/// The font size in px of a text element: "font-size:Npx", or the size in the "font:" shorthand.
inline double font_px(const Element& e) {
  if (const auto size = style(e, "font-size")) return std::stod(*size);
  if (const auto font = style(e, "font")) {
    static const std::regex size_re("([0-9.]+)px");
    std::smatch m;
    if (std::regex_search(*font, m, size_re)) return std::stod(m[1]);
  }
  throw std::runtime_error("text without a font size: " + e.text);
}

/// "#rrggbb" as three components in [0, 255].
inline std::array<int, 3> rgb(const std::string& hex) {
  if (hex.size() != 7 || hex[0] != '#') throw std::runtime_error("not #rrggbb: " + hex);
  return {std::stoi(hex.substr(1, 2), nullptr, 16), std::stoi(hex.substr(3, 2), nullptr, 16), std::stoi(hex.substr(5, 2), nullptr, 16)};
}

/// The relative luminance of an sRGB colour (WCAG 2: linearised components, weights 0.2126,
/// 0.7152, 0.0722), in [0, 1].
inline double luminance(const std::string& hex) {
  const auto c = rgb(hex);
  const auto linear = [](int v) {
    const double s = v / 255.0;
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(c[0]) + 0.7152 * linear(c[1]) + 0.0722 * linear(c[2]);
}

/// The q-quantile (0 <= q <= 1) of `values` by linear interpolation between order statistics.
inline double quantile(std::vector<double> values, double q) {
  if (values.empty()) throw std::runtime_error("quantile of nothing");
  std::sort(values.begin(), values.end());
  const double at = q * static_cast<double>(values.size() - 1);
  const std::size_t i = static_cast<std::size_t>(std::floor(at));
  const std::size_t j = std::min(i + 1, values.size() - 1);
  return values[i] + (at - static_cast<double>(i)) * (values[j] - values[i]);
}

}  // namespace svg_test
