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

/// Whether every byte >= 0x80 of s belongs to a UTF-8 sequence in form: a lead byte 0xC2 ..
/// 0xF4 and its 1 .. 3 continuation bytes 0x80 .. 0xBF. TinyXML takes a lead byte's sequence as one
/// character without checking it: a malformed one could swallow a '<' or a quote that a byte scan
/// sees. In a sequence in form no byte is ASCII, so both read the markup alike.
inline bool utf8_in_form(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t length = c < 0x80 ? 1 : c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (length == 0 || i + length > s.size()) return false;
    for (std::size_t k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    i += length;
  }
  return true;
}

/// What TinyXML makes of "<" followed by c: an element when c starts a name (a letter, '_', or a
/// byte >= 0x80), else (end tags, comments, CDATA, declarations aside) an unknown node that ends
/// at its first '>'.
inline bool starts_name(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u >= 0x80 || std::isalpha(u) || c == '_';
}

/// Whether the text from i (just after "<?") is an XML declaration ("xml", any case), which
/// TinyXML reads with quoted attribute values.
inline bool is_declaration(const std::string& xml, std::size_t i) {
  if (i + 3 > xml.size()) return false;
  for (std::size_t k = 0; k < 3; ++k)
    if (std::tolower(static_cast<unsigned char>(xml[i + k])) != "xml"[k]) return false;
  return true;
}

}  // namespace xml_shape_detail

/// InvalidInput when an element of xml nests deeper than kMaxXmlDepth or has more than
/// kMaxXmlAttributes attributes. The scan follows the lexical rules of XML as urdfdom's parser
/// (TinyXML) reads them, erring towards more elements: comments (to "-->") and CDATA sections (to
/// "]]>") hold no markup; a declaration "<?xml" ends at its "?>" and may hold no other '>' (its
/// quoted values are TinyXML's, not a byte scan's: refused); other "<!", "<?" and "<" not followed
/// by a name end at their first '>'; a value quoted right after '=' holds no markup; bytes that
/// are not UTF-8 in form are refused (utf8_in_form). Malformed documents are left to the parser,
/// which refuses them, within these two bounds.
inline void check_xml_shape(const std::string& xml, const std::string& field, const std::string& what) {
  namespace d = xml_shape_detail;
  const std::string valid = what + " in UTF-8, nesting at most 64 elements, each with at most 64 attributes";
  if (!d::utf8_in_form(xml)) throw InvalidInput(field, "the document", "bytes that are not UTF-8", valid);
  std::size_t depth = 0;
  for (std::size_t i = xml.find('<'); i < xml.size(); i = xml.find('<', i)) {
    const char next = i + 1 < xml.size() ? xml[i + 1] : '\0';
    if (xml.compare(i, 4, "<!--") == 0) { i = d::skip_past(xml, i + 4, "-->"); continue; }
    if (xml.compare(i, 9, "<![CDATA[") == 0) { i = d::skip_past(xml, i + 9, "]]>"); continue; }
    if (next == '?' && d::is_declaration(xml, i + 2)) {
      const std::size_t close = xml.find('>', i + 2);
      if (close != std::string::npos && xml[close - 1] != '?')
        throw InvalidInput(field, "the document", "an XML declaration holds a '>' before its \"?>\"", valid);
      i = close == std::string::npos ? xml.size() : close + 1;
      continue;
    }
    if (next == '/') {
      depth = depth > 0 ? depth - 1 : 0;
      i = d::skip_past(xml, i + 2, ">");
      continue;
    }
    if (!d::starts_name(next)) { i = d::skip_past(xml, i + 1, ">"); continue; }  // "<!", "<?", "<1": to the first '>'
    const d::TagEnd tag = d::scan_tag(xml, i + 1);
    if (depth + 1 > kMaxXmlDepth) throw InvalidInput(field, "the document", "elements nest deeper than 64", valid);
    if (tag.attributes > kMaxXmlAttributes) throw InvalidInput(field, "the document", "an element has more than 64 attributes", valid);
    if (!tag.self_closing) ++depth;
    i = tag.next;
  }
}

}  // namespace sphtroch
