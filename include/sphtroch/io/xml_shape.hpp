// sphtroch/io/xml_shape.hpp — the shape of an XML document checked before a parser reads it: how
// deep its elements nest and how many attributes one carries, following XML's lexical rules
// (comments, CDATA, declarations, quoted values). No XML library: a scan of the text, linear in it.
//
//   sphtroch::check_xml_shape(text, "urdf", "a URDF document");   // InvalidInput("urdf", ...) when too deep or too wide
#pragma once

#include "sphtroch/core/errors.hpp"

#include <cctype>
#include <cstddef>
#include <string>

namespace sphtroch {

/// Robot descriptions nest a few levels and carry a few attributes per element; deeper or wider
/// documents are refused before a recursive parser sees them (urdfdom's: a deep one overflows
/// its stack, a wide one takes quadratic time).
constexpr std::size_t kMaxXmlDepth = 64, kMaxXmlAttributes = 64;

namespace xml_shape_detail {

/// The position after the first `close` at or after i (xml.size() when there is none).
inline std::size_t skip_past(const std::string& xml, std::size_t i, const char* close) {
  const std::size_t at = xml.find(close, i);
  return at == std::string::npos ? xml.size() : at + std::char_traits<char>::length(close);
}

/// The position after the '>' that ends the tag opened at i, with XML's quoting: a value quoted
/// right after an attribute's '=' is text ('>' and '/' in it are not markup; a quote anywhere
/// else is an ordinary character, as the parser reads it). Counts the '=' (the attributes) and
/// says whether the tag closes itself ("/>").
struct TagEnd {
  std::size_t next = 0, attributes = 0;
  bool self_closing = false;
};
inline TagEnd scan_tag(const std::string& xml, std::size_t i) {
  TagEnd t;
  char last = 0;
  for (; i < xml.size(); ++i) {
    const char c = xml[i];
    if (c == '=') {
      ++t.attributes;
      std::size_t v = i + 1;
      while (v < xml.size() && std::isspace(static_cast<unsigned char>(xml[v]))) ++v;
      if (v < xml.size() && (xml[v] == '"' || xml[v] == '\'')) {
        const std::size_t close = xml.find(xml[v], v + 1);
        if (close == std::string::npos) break;  // unterminated: the parser refuses the document
        i = close, last = xml[v];
        continue;
      }
    } else if (c == '>') {
      t.next = i + 1, t.self_closing = last == '/';
      return t;
    }
    if (!std::isspace(static_cast<unsigned char>(c))) last = c;
  }
  t.next = xml.size();
  return t;
}

}  // namespace xml_shape_detail

/// InvalidInput when an element of xml nests deeper than kMaxXmlDepth or has more than
/// kMaxXmlAttributes attributes. The scan follows the lexical rules of XML as urdfdom's parser
/// (TinyXML) reads them, erring towards more elements: comments (to "-->") and CDATA sections (to
/// "]]>") hold no markup; other "<!" and "<?" constructs (DOCTYPE, declarations) end at their
/// first '>'; a quoted attribute value holds no markup. Malformed documents are left to the
/// parser, which refuses them, within these two bounds.
inline void check_xml_shape(const std::string& xml, const std::string& field, const std::string& what) {
  using xml_shape_detail::skip_past;
  const std::string valid = what + " nesting at most 64 elements, each with at most 64 attributes";
  std::size_t depth = 0;
  for (std::size_t i = xml.find('<'); i < xml.size(); i = xml.find('<', i)) {
    if (xml.compare(i, 4, "<!--") == 0) { i = skip_past(xml, i + 4, "-->"); continue; }
    if (xml.compare(i, 9, "<![CDATA[") == 0) { i = skip_past(xml, i + 9, "]]>"); continue; }
    if (xml.compare(i, 2, "<!") == 0 || xml.compare(i, 2, "<?") == 0) { i = skip_past(xml, i + 2, ">"); continue; }
    if (xml.compare(i, 2, "</") == 0) {
      depth = depth > 0 ? depth - 1 : 0;
      i = skip_past(xml, i + 2, ">");
      continue;
    }
    const xml_shape_detail::TagEnd tag = xml_shape_detail::scan_tag(xml, i + 1);
    if (depth + 1 > kMaxXmlDepth) throw InvalidInput(field, "the document", "elements nest deeper than 64", valid);
    if (tag.attributes > kMaxXmlAttributes) throw InvalidInput(field, "the document", "an element has more than 64 attributes", valid);
    if (!tag.self_closing) ++depth;
    i = tag.next;
  }
}

}  // namespace sphtroch
