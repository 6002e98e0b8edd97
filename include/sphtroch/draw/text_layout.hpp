// sphtroch/draw/text_layout.hpp — text on a picture without a text engine: how wide a line of
// sans-serif is (a bound, from DejaVu Sans's advance widths), lines wrapped to a width, and numbers
// short enough to read (at most 6 significant digits). The sphere picture's notes and caption
// (svg_plot.hpp), the chain caption (chain/chain_picture.hpp) and the clinostat picture use it.
//
//   sphtroch::text_width_em("N12");                       // 0.75 + 2 x 0.64 = 2.03 em
//   sphtroch::wrap_text("a2 = pi/2, a3 = pi/2, n = 133/200 — 26602 node(s)", 240, 12);
//   // {"a2 = pi/2, a3 = pi/2, n = 133/200 —", "26602 node(s)"}: each line at most 240 px wide
//   sphtroch::picture_number(1.5707963267948966);       // "1.5708"
//
// Contracts:
//  1. text_width_em(s) is the sum of per-character advance widths in em: DejaVu Sans Book's (the
//     sans-serif of most Linux systems, and the widest of the common ones: Arial, Helvetica and
//     Liberation Sans are narrower), each rounded up to 0.01 em; a character outside ASCII counts
//     1 em (the em dash is 1 em). Kerning is ignored.
//  2. wrap_text(text, width_px, font_px) splits text into lines of width at most width_px by
//     contract 1. A text wider than one line breaks first after every " — " (an em dash between
//     spaces: a caption's sections; the dash ends its line), then each section greedily, after a
//     space (dropped at the break) or after a comma (kept);
//     a piece with no break that is wider than a line is cut between characters (never inside a
//     UTF-8 sequence; a single character wider than the line stands alone). The lines are the
//     text with the spaces at the breaks dropped. Empty text: no lines.
//  3. picture_number(v, digits) is v rounded to `digits` (1 .. 17) significant digits, in the
//     shortest form that reads back as the rounded value (number_text's): "1.5708", "2192",
//     "0.000123", "1e-08".
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace sphtroch {

/// Width of `text` in em (contract 1).
inline double text_width_em(std::string_view text) {
  // Advance widths of ' ' (32) .. '~' (126), DejaVu Sans Book, in 0.01 em, rounded up.
  static const unsigned char widths[95] = {
      32, 41, 46, 84, 64, 96, 78, 28, 40, 40, 50, 84, 32, 37, 32, 34,  // space ! " # $ % & ' ( ) * + , - . /
      64, 64, 64, 64, 64, 64, 64, 64, 64, 64, 34, 34, 84, 84, 84, 54,  // 0-9 : ; < = > ?
      100, 69, 69, 70, 77, 64, 49, 78, 76, 30, 30, 64, 56, 87, 75, 79,  // @ A-O
      56, 79, 68, 64, 45, 74, 61, 93, 69, 48, 69, 40, 34, 40, 84, 50,   // P-Z [ \ ] ^ _
      50, 62, 64, 55, 64, 62, 36, 64, 64, 28, 28, 57, 28, 98, 64, 62,   // ` a-o
      64, 64, 42, 53, 40, 64, 60, 82, 60, 60, 53, 64, 34, 64, 84};      // p-z { | } ~
  double sum = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 32 && c < 127) sum += widths[c - 32] / 100.0;
    else if (c < 0x80 || c >= 0xC0) sum += 1.0;  // a control character, or the lead byte of a UTF-8 sequence
  }
  return sum;
}

namespace detail {

/// One section of wrap_text: greedy breaks after spaces and commas, cuts inside wider pieces.
inline std::vector<std::string> wrap_section(std::string_view text, double width_em) {
  std::vector<std::string> lines;
  std::string line;
  const auto flush = [&] {
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (!line.empty()) lines.push_back(line);
    line.clear();
  };
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find_first_of(" ,", at);  // a piece runs up to and including its break
    end = end == std::string_view::npos ? text.size() : end + 1;
    const std::string piece(text.substr(at, end - at));
    at = end;
    const std::string body = piece.back() == ' ' ? piece.substr(0, piece.size() - 1) : piece;  // a space at a break is dropped
    if (!line.empty() && text_width_em(line + body) > width_em) flush();
    if (!line.empty() || text_width_em(body) <= width_em) {
      line += piece;
      continue;
    }
    for (std::size_t c = 0; c < piece.size();) {  // wider than a line: cut between characters
      std::size_t next = c + 1;
      while (next < piece.size() && (static_cast<unsigned char>(piece[next]) & 0xC0) == 0x80) ++next;
      const std::string glyph = piece.substr(c, next - c);
      if (!line.empty() && text_width_em(line + glyph) > width_em) flush();
      line += glyph;
      c = next;
    }
  }
  flush();
  return lines;
}

}  // namespace detail

/// `text` in lines at most width_px wide at font_px (contract 2).
inline std::vector<std::string> wrap_text(std::string_view text, double width_px, double font_px) {
  SPHTROCH_ASSERT(width_px > 0 && font_px > 0, "wrap_text: positive width and font size");
  const double width_em = width_px / font_px;
  if (text_width_em(text) <= width_em) return detail::wrap_section(text, width_em);
  const std::string_view dash = " \u2014 ";
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t found = text.find(dash, at);
    const std::size_t end = found == std::string_view::npos ? text.size() : found + dash.size() - 1;  // the dash ends the section
    for (std::string& line : detail::wrap_section(text.substr(at, end - at), width_em)) lines.push_back(std::move(line));
    at = found == std::string_view::npos ? text.size() : end + 1;  // the space after the dash is dropped
  }
  return lines;
}

/// v to `digits` significant digits, shortest form (contract 3). REQUIRES: v finite.
inline std::string picture_number(double v, int digits = 6) {
  SPHTROCH_ASSERT(std::isfinite(v) && digits >= 1 && digits <= 17, "picture_number: finite v, 1 .. 17 digits");
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*e", digits - 1, v);
  return number_text(std::strtod(buf, nullptr) + 0.0);  // + 0.0: -0 is written 0
}

}  // namespace sphtroch
