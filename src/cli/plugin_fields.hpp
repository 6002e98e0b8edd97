// src/cli/plugin_fields.hpp — the request and reply texts of the tool's reading plugins (URDF,
// HEALPix): a list of fields, each written as its length in decimal, ':', then its bytes, so that
// any bytes (an XML document, raw doubles) pass unchanged. The plugin and the tool are one build:
// doubles go as their shortest round-trip text (number_text) or as raw bytes.
//
//   const std::string text = sphtroch::cli::join_fields({"base_link", "tool", xml});
//   const std::vector<std::string> back = sphtroch::cli::split_fields(text, 3);   // the same three
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sphtroch::cli {

inline std::string join_fields(const std::vector<std::string>& fields) {
  std::string out;
  for (const std::string& f : fields) out += std::to_string(f.size()) + ":" + f;
  return out;
}

/// The fields of `text`; std::runtime_error (a bug: the tool and its plugin disagree) for a text
/// not so written or, when `count` is given, not of exactly `count` fields.
inline std::vector<std::string> split_fields(const std::string& text, std::size_t count = SIZE_MAX) {
  std::vector<std::string> fields;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t colon = text.find(':', at);
    if (colon == std::string::npos || colon == at || colon - at > 19) throw std::runtime_error("plugin fields: no length");
    std::size_t size = 0;
    for (std::size_t i = at; i < colon; ++i) {
      if (text[i] < '0' || text[i] > '9') throw std::runtime_error("plugin fields: a bad length");
      size = size * 10 + static_cast<std::size_t>(text[i] - '0');
    }
    if (size > text.size() - colon - 1) throw std::runtime_error("plugin fields: a field past the end");
    fields.push_back(text.substr(colon + 1, size));
    at = colon + 1 + size;
  }
  if (count != SIZE_MAX && fields.size() != count) throw std::runtime_error("plugin fields: " + std::to_string(fields.size()) + " fields, not " + std::to_string(count));
  return fields;
}

}  // namespace sphtroch::cli
