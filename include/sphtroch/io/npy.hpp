// sphtroch/io/npy.hpp — the NumPy .npy array format: the header that `numpy.save` writes and
// `numpy.load` reads (format versions 1.0, 2.0, 3.0), for 2-D float arrays in C order.
//
//   std::string h = sphtroch::npy_header(rows, 4);        // '<f8', C order, shape (rows, 4)
//   // then rows * 4 little-endian doubles, row by row
//
//   std::size_t len = sphtroch::npy_preamble_length(first_bytes, "input", "a.npy");
//   sphtroch::NpyHeader h = sphtroch::parse_npy_header(std::string_view(bytes, len), "input", "a.npy");
//
// Layout (numpy.lib.format): the magic "\x93NUMPY", a major and a minor version byte, the header
// length (uint16 little-endian for 1.0, uint32 for 2.0 and 3.0), then the header: a Python dict
// literal {'descr': '<f8', 'fortran_order': False, 'shape': (N, 4), } padded with spaces and
// ended by '\n' so that the data starts at a multiple of 64 bytes.
// Accepted on reading: descr '<f8' or '<f4' (also '=f8'/'=f4', native = little here), C order,
// a 2-D shape. Everything else — another dtype, big-endian data, Fortran order, a malformed or
// truncated header, an unknown key — throws InvalidInput(field, name, what is wrong, kNpyValid).
#pragma once

#include "sphtroch/core/errors.hpp"

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sphtroch {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the .npy reader and writer assume a little-endian host");

constexpr std::string_view kNpyMagic("\x93NUMPY", 6);
/// The bytes before the header length: magic + 2 version bytes.
constexpr std::size_t kNpyVersionEnd = 8;
/// The valid form quoted in errors.
constexpr const char* kNpyValid =
    "a NumPy .npy file (format 1.0-3.0) of little-endian float64 or float32 in C order, shape (N, 3) x,y,z, "
    "or (N, 4) / (N, 7) as written by sphtroch trace";

struct NpyHeader {
  std::size_t item_bytes = 8;          // 8: float64, 4: float32
  std::vector<std::uint64_t> shape;    // as given
  std::size_t data_offset = 0;         // bytes before the data
  std::uint64_t rows() const { return shape.empty() ? 0 : shape[0]; }
  std::uint64_t cols() const { return shape.size() < 2 ? 1 : shape[1]; }
};

/// True when `bytes` starts like a .npy file (the magic string).
inline bool looks_like_npy(std::string_view bytes) { return bytes.substr(0, kNpyMagic.size()) == kNpyMagic; }

/// The header (preamble and dict) of a float64 C-order array of shape (rows, cols), version 1.0
/// (2.0 if the dict would not fit a 16-bit length, which cannot happen for 2-D shapes).
inline std::string npy_header(std::uint64_t rows, std::uint64_t cols) {
  std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(rows) + ", " +
                     std::to_string(cols) + "), }";
  const std::size_t fixed = kNpyVersionEnd + 2;
  const std::size_t total = (fixed + dict.size() + 1 + 63) / 64 * 64;
  dict.append(total - fixed - dict.size() - 1, ' ');
  dict.push_back('\n');
  std::string h(kNpyMagic);
  h += '\x01';
  h += '\x00';
  h += static_cast<char>(dict.size() & 0xff);
  h += static_cast<char>((dict.size() >> 8) & 0xff);
  return h + dict;
}

namespace npy_detail {

[[noreturn]] inline void bad(const std::string& field, const std::string& name, const std::string& problem) {
  throw InvalidInput(field, name, problem, kNpyValid);
}

/// Text from the header as shown in a message: control bytes (NUL included) as \xNN, so that the
/// message is one line and never cut at a NUL; at most 40 bytes.
inline std::string shown(std::string_view s) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  for (const char ch : s.substr(0, 40)) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    else out += ch;
  }
  return s.size() > 40 ? out + "..." : out;
}

/// A cursor over the header dict: just enough of Python's literal syntax for numpy.save's output.
struct DictReader {
  std::string_view s;
  std::size_t i = 0;
  const std::string& field;
  const std::string& name;

  void skip_space() {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
  }
  bool eat(char c) {
    skip_space();
    if (i < s.size() && s[i] == c) {
      ++i;
      return true;
    }
    return false;
  }
  void expect(char c, const char* what) {
    if (!eat(c)) bad(field, name, std::string("malformed header: expected ") + what);
  }
  std::string string_literal() {
    skip_space();
    if (i >= s.size() || (s[i] != '\'' && s[i] != '"')) bad(field, name, "malformed header: expected a quoted string");
    const char quote = s[i++];
    const std::size_t start = i;
    while (i < s.size() && s[i] != quote) {
      if (s[i] == '\\') bad(field, name, "malformed header: escapes are not supported");
      ++i;
    }
    if (i >= s.size()) bad(field, name, "malformed header: unterminated string");
    return std::string(s.substr(start, i++ - start));
  }
  bool boolean() {
    skip_space();
    for (const auto& [word, value] : {std::pair<std::string_view, bool>{"True", true}, {"False", false}})
      if (s.substr(i, word.size()) == word) {
        i += word.size();
        return value;
      }
    bad(field, name, "malformed header: fortran_order is not True or False");
  }
  std::uint64_t integer() {
    skip_space();
    std::uint64_t v = 0;
    const std::size_t start = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
      if (v > (UINT64_MAX - 9) / 10) bad(field, name, "shape too large");
      v = v * 10 + static_cast<std::uint64_t>(s[i++] - '0');
    }
    if (i == start) bad(field, name, "malformed header: shape is not a tuple of whole numbers");
    if (i < s.size() && (s[i] == 'L' || s[i] == 'l')) ++i;  // Python 2 long suffix
    return v;
  }
  std::vector<std::uint64_t> tuple() {
    expect('(', "'(' for shape");
    std::vector<std::uint64_t> v;
    while (!eat(')')) {
      v.push_back(integer());
      if (eat(')')) break;
      expect(',', "',' in shape");
      if (v.size() > 32) bad(field, name, "malformed header: shape has more than 32 dimensions");
    }
    return v;
  }
};

}  // namespace npy_detail

/// The number of bytes up to and including the header dict. `start` holds the first bytes of
/// the file (at least 12, or the whole file if shorter).
inline std::size_t npy_preamble_length(std::string_view start, const std::string& field, const std::string& name) {
  using npy_detail::bad;
  if (!looks_like_npy(start)) bad(field, name, "not a .npy file (no \\x93NUMPY magic)");
  if (start.size() < kNpyVersionEnd + 2) bad(field, name, "truncated header");
  const auto byte = [&](std::size_t k) { return static_cast<std::uint32_t>(static_cast<unsigned char>(start[k])); };
  const std::uint32_t major = byte(6);
  if (major < 1 || major > 3)
    bad(field, name, "format version " + std::to_string(major) + "." + std::to_string(byte(7)) + " is not supported");
  if (major == 1) return kNpyVersionEnd + 2 + (byte(8) | byte(9) << 8);
  if (start.size() < kNpyVersionEnd + 4) bad(field, name, "truncated header");
  const std::uint64_t len = byte(8) | byte(9) << 8 | byte(10) << 16 | static_cast<std::uint64_t>(byte(11)) << 24;
  if (len > (std::uint64_t(1) << 20)) bad(field, name, "header of " + std::to_string(len) + " bytes (more than 1 MiB)");
  return kNpyVersionEnd + 4 + static_cast<std::size_t>(len);
}

/// Parses and checks the whole preamble (npy_preamble_length bytes).
inline NpyHeader parse_npy_header(std::string_view preamble, const std::string& field, const std::string& name) {
  using npy_detail::bad;
  const std::size_t len = npy_preamble_length(preamble, field, name);
  if (preamble.size() < len) bad(field, name, "truncated header");
  const std::size_t dict_start = static_cast<unsigned char>(preamble[6]) == 1 ? kNpyVersionEnd + 2 : kNpyVersionEnd + 4;
  npy_detail::DictReader r{preamble.substr(dict_start, len - dict_start), 0, field, name};
  std::string descr;
  bool have_descr = false, have_order = false, have_shape = false, fortran = false;
  NpyHeader h;
  r.expect('{', "'{'");
  while (!r.eat('}')) {
    const std::string key = r.string_literal();
    r.expect(':', "':' after a key");
    if (key == "descr" && !have_descr) {
      r.skip_space();
      if (r.i < r.s.size() && r.s[r.i] == '[') bad(field, name, "structured dtype (a list descr) is not supported");
      descr = r.string_literal();
      have_descr = true;
    } else if (key == "fortran_order" && !have_order) {
      fortran = r.boolean();
      have_order = true;
    } else if (key == "shape" && !have_shape) {
      h.shape = r.tuple();
      have_shape = true;
    } else {
      bad(field, name, "malformed header: unexpected or repeated key '" + npy_detail::shown(key) + "'");
    }
    if (r.eat('}')) break;
    r.expect(',', "',' between entries");
  }
  r.skip_space();
  if (r.i != r.s.size()) bad(field, name, "malformed header: characters after the dict");
  if (!have_descr || !have_order || !have_shape)
    bad(field, name, "malformed header: needs the keys descr, fortran_order and shape");
  if (descr.size() == 3 && descr[0] == '>' && descr[1] == 'f')
    bad(field, name, "big-endian data (dtype " + npy_detail::shown(descr) + ")");
  if (descr == "<f8" || descr == "=f8") h.item_bytes = 8;
  else if (descr == "<f4" || descr == "=f4") h.item_bytes = 4;
  else bad(field, name, "dtype " + npy_detail::shown(descr) + " is not float64 or float32");
  if (fortran) bad(field, name, "Fortran order (fortran_order: True)");
  h.data_offset = len;
  return h;
}

/// Bytes of data the header announces, or InvalidInput when that overflows 64 bits.
inline std::uint64_t npy_data_bytes(const NpyHeader& h, const std::string& field, const std::string& name) {
  std::uint64_t n = h.item_bytes;
  for (std::uint64_t d : h.shape) {
    if (d != 0 && n > UINT64_MAX / d) npy_detail::bad(field, name, "shape too large");
    n *= d;
  }
  return n;
}

}  // namespace sphtroch
