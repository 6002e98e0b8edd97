// sphtroch/draw/svg.hpp — a tiny writer for standalone SVG 1.1 documents: numbers with limited
// precision, XML escaping, compact path data and a handful of elements. No geometry here; the
// sphere picture (svg_plot.hpp) and the design-atlas chart build on it.
//
//   sphtroch::SvgWriter svg(400, 300);                 // <?xml ...?><svg xmlns=... width=400 ...>
//   sphtroch::SvgPath d(2);                            // 2 decimals
//   d.move_to(10, 10); d.line_to(100, 50); d.line_to(120, 80);
//   svg.path(d, "fill:none;stroke:#1f77b4");           // one <path> for many segments
//   svg.circle(60, 40, 5, "fill:none;stroke:red");
//   svg.text(60, 30, "a2 = pi/2 & a3 < pi", "font-size:12px", "middle");  // escaped
//   std::string doc = svg.finish();                    // closes every open group and </svg>
//
// Contracts:
//  1. Every number is written by svg_number(): fixed notation with at most `decimals` digits
//     after the point, trailing zeros removed, "-0" written as "0", independent of the C locale.
//     Non-finite numbers are a programmer error (SPHTROCH_ASSERT): SVG has no NaN.
//  2. Every text and attribute value passes through xml_escape() (& < > " '), so any caption
//     is safe. Style strings are caller-written CSS and are escaped too.
//  3. finish() returns a well-formed document: the XML declaration, one <svg> root with the
//     SVG namespace and version="1.1", balanced elements. After finish() the writer is spent.
#pragma once

#include "sphtroch/core/errors.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace sphtroch {

/// `value` in fixed notation with at most `decimals` (0..9) digits after the point, trailing
/// zeros dropped ("12.5", "3", "-0.25"); "-0" becomes "0". REQUIRES: value finite.
inline std::string svg_number(double value, int decimals = 2);

/// `text` with & < > " ' replaced by their XML entities.
inline std::string xml_escape(std::string_view text);

/// The extension (lower case) of a path that names a picture format other than SVG (png, jpg,
/// pdf, ...), or none: SVG bytes must not go into a file whose name promises another format.
inline std::optional<std::string> other_picture_format(const std::string& path);

/// Path data built incrementally ("M x y L x y x y ..."), in as few characters as the
/// precision allows: a vertex that rounds to the previous one is dropped, and consecutive
/// line-to commands share one "L".
class SvgPath {
 public:
  explicit SvgPath(int decimals = 2) : decimals_(decimals) {}
  void move_to(double x, double y);
  void line_to(double x, double y);
  void close();  // "Z"
  bool empty() const noexcept { return data_.empty(); }
  const std::string& str() const noexcept { return data_; }
  /// Number of subpaths begun with move_to (for tests and statistics).
  std::size_t subpaths() const noexcept { return subpaths_; }

 private:
  int decimals_;
  std::string data_;
  std::string last_x_, last_y_;
  char last_command_ = 0;
  std::size_t subpaths_ = 0;
};

/// Appends SVG elements to a document; see the header comment for the contracts.
class SvgWriter {
 public:
  /// Opens the document: width x height px, viewBox "0 0 width height".
  /// REQUIRES: width, height > 0 and finite.
  SvgWriter(double width, double height, int decimals = 2);

  int decimals() const noexcept { return decimals_; }
  std::string num(double v) const { return svg_number(v, decimals_); }

  /// <title> (shown as tooltip / accessible name). Call first, at most once.
  void title(std::string_view text);
  /// <g style="..." [extra]>; ends with end_group(). `extra` is raw attribute text the caller
  /// writes itself (e.g. `id="curve"`), already escaped.
  void begin_group(std::string_view style = {}, std::string_view extra = {});
  void end_group();

  void path(const SvgPath& d, std::string_view style);
  void path(std::string_view d, std::string_view style);
  void circle(double cx, double cy, double r, std::string_view style);
  void rect(double x, double y, double w, double h, std::string_view style);
  void line(double x1, double y1, double x2, double y2, std::string_view style);
  /// Text at (x, y) (baseline); anchor is "start", "middle" or "end".
  void text(double x, double y, std::string_view content, std::string_view style, std::string_view anchor = "start");
  /// Raw markup appended as is (the caller guarantees it is well-formed), e.g. <defs>.
  void raw(std::string_view markup) { out_.append(markup); }

  /// Closes open groups and the root; returns the document. The writer is spent afterwards.
  std::string finish();

 private:
  void open_element(std::string_view name);
  void attr(std::string_view name, double v);
  void attr(std::string_view name, std::string_view v);
  std::string out_;
  int decimals_;
  int open_groups_ = 0;
  bool finished_ = false;
};

// ---------------------------------------------------------------------------------------------
// Implementation details follow.
// ---------------------------------------------------------------------------------------------

inline std::string svg_number(double value, int decimals) {
  SPHTROCH_ASSERT(std::isfinite(value), "svg_number: SVG has no NaN or infinity");
  SPHTROCH_ASSERT(decimals >= 0 && decimals <= 9, "svg_number: decimals in 0..9");
  char buf[64];
  // Fixed notation; huge values would overflow the buffer, and nothing on a page is that big.
  if (!(std::fabs(value) < 1e30)) value = value < 0 ? -1e30 : 1e30;
#if defined(__cpp_lib_to_chars)
  std::string s(buf, std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals).ptr);
#else
  std::string s(buf, static_cast<std::size_t>(std::snprintf(buf, sizeof buf, "%.*f", decimals, value)));
#endif
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

inline std::optional<std::string> other_picture_format(const std::string& path) {
  const auto dot = path.rfind('.'), slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (const char* other : {"png", "jpg", "jpeg", "gif", "webp", "bmp", "tif", "tiff", "pdf", "eps", "ps", "emf"})
    if (ext == other) return ext;
  return std::nullopt;
}

inline std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

inline void SvgPath::move_to(double x, double y) {
  data_ += 'M';
  const std::string sx = svg_number(x, decimals_), sy = svg_number(y, decimals_);
  data_ += sx;
  data_ += ' ';
  data_ += sy;
  last_x_ = sx;
  last_y_ = sy;
  last_command_ = 'M';
  ++subpaths_;
}

inline void SvgPath::line_to(double x, double y) {
  SPHTROCH_ASSERT(last_command_ != 0, "SvgPath::line_to before move_to");
  const std::string sx = svg_number(x, decimals_), sy = svg_number(y, decimals_);
  if (sx == last_x_ && sy == last_y_) return;  // no visible step at this precision
  if (last_command_ != 'L') {
    data_ += 'L';
    last_command_ = 'L';
  } else {
    data_ += ' ';
  }
  data_ += sx;
  data_ += ' ';
  data_ += sy;
  last_x_ = sx;
  last_y_ = sy;
}

inline void SvgPath::close() {
  SPHTROCH_ASSERT(last_command_ != 0, "SvgPath::close before move_to");
  data_ += 'Z';
  last_command_ = 'Z';
}

inline SvgWriter::SvgWriter(double width, double height, int decimals) : decimals_(decimals) {
  SPHTROCH_ASSERT(std::isfinite(width) && std::isfinite(height) && width > 0 && height > 0,
                  "SvgWriter: positive finite size");
  out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
  out_ += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"";
  attr("width", width);
  attr("height", height);
  out_ += " viewBox=\"0 0 " + num(width) + " " + num(height) + "\">\n";
}

inline void SvgWriter::open_element(std::string_view name) {
  SPHTROCH_ASSERT(!finished_, "SvgWriter used after finish()");
  out_ += '<';
  out_.append(name);
}

inline void SvgWriter::attr(std::string_view name, double v) {
  out_ += ' ';
  out_.append(name);
  out_ += "=\"" + num(v) + "\"";
}

inline void SvgWriter::attr(std::string_view name, std::string_view v) {
  out_ += ' ';
  out_.append(name);
  out_ += "=\"" + xml_escape(v) + "\"";
}

inline void SvgWriter::title(std::string_view text) {
  open_element("title");
  out_ += '>' + xml_escape(text) + "</title>\n";
}

inline void SvgWriter::begin_group(std::string_view style, std::string_view extra) {
  open_element("g");
  if (!style.empty()) attr("style", style);
  if (!extra.empty()) {
    out_ += ' ';
    out_.append(extra);
  }
  out_ += ">\n";
  ++open_groups_;
}

inline void SvgWriter::end_group() {
  SPHTROCH_ASSERT(open_groups_ > 0, "SvgWriter::end_group without begin_group");
  out_ += "</g>\n";
  --open_groups_;
}

inline void SvgWriter::path(const SvgPath& d, std::string_view style) { path(std::string_view(d.str()), style); }

inline void SvgWriter::path(std::string_view d, std::string_view style) {
  if (d.empty()) return;  // an empty path element is legal but useless
  open_element("path");
  attr("d", d);
  if (!style.empty()) attr("style", style);
  out_ += "/>\n";
}

inline void SvgWriter::circle(double cx, double cy, double r, std::string_view style) {
  open_element("circle");
  attr("cx", cx);
  attr("cy", cy);
  attr("r", r);
  if (!style.empty()) attr("style", style);
  out_ += "/>\n";
}

inline void SvgWriter::rect(double x, double y, double w, double h, std::string_view style) {
  open_element("rect");
  attr("x", x);
  attr("y", y);
  attr("width", w);
  attr("height", h);
  if (!style.empty()) attr("style", style);
  out_ += "/>\n";
}

inline void SvgWriter::line(double x1, double y1, double x2, double y2, std::string_view style) {
  open_element("line");
  attr("x1", x1);
  attr("y1", y1);
  attr("x2", x2);
  attr("y2", y2);
  if (!style.empty()) attr("style", style);
  out_ += "/>\n";
}

inline void SvgWriter::text(double x, double y, std::string_view content, std::string_view style,
                            std::string_view anchor) {
  open_element("text");
  attr("x", x);
  attr("y", y);
  if (!anchor.empty() && anchor != "start") attr("text-anchor", anchor);
  if (!style.empty()) attr("style", style);
  out_ += '>' + xml_escape(content) + "</text>\n";
}

inline std::string SvgWriter::finish() {
  SPHTROCH_ASSERT(!finished_, "SvgWriter::finish called twice");
  while (open_groups_ > 0) end_group();
  out_ += "</svg>\n";
  finished_ = true;
  return std::move(out_);
}

}  // namespace sphtroch
