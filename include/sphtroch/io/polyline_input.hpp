// sphtroch/io/polyline_input.hpp — a spherical polyline read from a file or standard input: CSV or
// NumPy .npy, told apart by the file's first bytes (the .npy magic), not by its name.
//
//   std::ofstream("p.csv") << "x,y,z\n1,0,0\n0,1,0\n0,0,1\n";
//   sphtroch::PolylineInput in = sphtroch::read_polyline("p.csv", "input");  // "-": standard input
//   in.vertices;   // std::vector<Eigen::Vector3d>, not normalised (validate_spherical_polyline does that)
//   in.format;     // "csv", "csv with header", "npy <f8 (N, 4)", ...
//
// CSV: rows of numbers separated by ','; blank lines are skipped, '\r\n' line ends and spaces
// around numbers are allowed. The first non-blank row is a header when any of its fields is not
// a number: it must name the columns x, y and z (once each, any case, optionally quoted); other
// columns (t, vx, vy, vz, ...) are ignored, not parsed. Without a header every row is exactly
// 3 numbers x,y,z. Every row has as many fields as the first. Numbers are parsed with
// std::from_chars and must be finite.
// NumPy: float64 or float32, C order, shape (N, 3) = x,y,z, or (N, 4) / (N, 7) = the arrays that
// `sphtroch trace` writes (t,x,y,z[,vx,vy,vz]): columns 1..3 are taken (see npy.hpp); each row
// is checked as it is read (finite, not all zero), so a bad row is named before memory grows.
// Sizes (a regular file's, a shape) only hint how much to reserve: toward the hint in steps of at
// most kMaxReservedVertices or kReserveGrowth times the rows already read (reserve_ahead).
// Errors: InvalidInput(field, path, problem naming the line or what is wrong, the valid form).
// Cost: one pass over the bytes in 4 MiB blocks, CSV rows parsed on `threads` threads (default 2);
// memory: the vertices (24 bytes each, about 5% reserved beyond them) plus two blocks.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/io/input_file.hpp"
#include "sphtroch/io/npy.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace sphtroch {

struct PolylineInput {
  std::vector<Vector3d> vertices;
  std::string format;  // what was read, for reports
  std::vector<double> t;  // read_timed_polyline only: theta2 of each vertex (the column t)
};

/// The valid forms of a CSV polyline, quoted in errors.
constexpr const char* kPolylineCsvValid =
    "CSV rows of 3 numbers x,y,z, or a header naming x, y, z (other columns ignored), or a .npy file";
/// The valid forms of a timed polyline (read_timed_polyline), quoted in errors.
constexpr const char* kTimedPolylineValid =
    "CSV with a header naming t, x, y, z (as `sphtroch trace` writes), or a .npy array (N, 4) or (N, 7): t,x,y,z[,vx,vy,vz]";

namespace polyline_input_detail {

constexpr std::size_t kBlockBytes = std::size_t(4) << 20;

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// The columns of a CSV: how many fields per row, and where x, y, z are.
struct CsvLayout {
  std::size_t fields = 3;
  std::array<std::size_t, 3> xyz{0, 1, 2};
  bool header = false;
  std::optional<std::size_t> t;  // the header's column t, if any
};

/// Splits one line (without '\n') at commas.
inline std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

/// Text of the input for a one-line message: control bytes as '?', at most 40 bytes.
inline std::string printable(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 40)) out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
  return s.size() > 40 ? out + "..." : out;
}

/// Decides the layout from the first non-blank line. Throws InvalidInput.
inline CsvLayout layout_from_first_line(std::string_view line, const std::string& field, const std::string& path) {
  const std::vector<std::string_view> cells = split_fields(line);
  bool all_numbers = true;
  for (std::string_view c : cells) all_numbers = all_numbers && parse_number(trim(c)).has_value();
  CsvLayout layout;
  layout.fields = cells.size();
  if (all_numbers) {
    if (cells.size() != 3)
      throw InvalidInput(field, path, "line 1 has " + std::to_string(cells.size()) + " numbers and no header",
                         kPolylineCsvValid);
    return layout;
  }
  layout.header = true;
  std::array<bool, 3> seen{false, false, false};
  for (std::size_t k = 0; k < cells.size(); ++k) {
    std::string_view name = trim(cells[k]);
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
    if (name.size() != 1) continue;
    if ((name[0] | 0x20) == 't') {
      if (layout.t) throw InvalidInput(field, path, "the header names column t twice", kPolylineCsvValid);
      layout.t = k;
      continue;
    }
    const int axis = (name[0] | 0x20) - 'x';  // x, y, z in any case
    if (axis < 0 || axis > 2) continue;
    if (seen[static_cast<std::size_t>(axis)])
      throw InvalidInput(field, path, "the header names column " + std::string(1, name[0]) + " twice", kPolylineCsvValid);
    seen[static_cast<std::size_t>(axis)] = true;
    layout.xyz[static_cast<std::size_t>(axis)] = k;
  }
  for (std::size_t a = 0; a < 3; ++a)
    if (!seen[a])
      throw InvalidInput(field, path,
                         "line 1 is a header (" + printable(line) + ") without a column " + std::string(1, char('x' + a)),
                         kPolylineCsvValid);
  return layout;
}

/// A declared or estimated vertex count is a hint (a sparse 64 GB file declares a lot and holds
/// nothing): the vertices are reserved toward it in steps of at most kMaxReservedVertices or
/// kReserveGrowth times the vertices already read and checked, whichever is more; a step short of
/// the hint reserves at most half of it, so that the copy at the next step (old and new storage
/// both held) stays within the hint's own size. Past the hint the vector doubles; a reservation
/// that fails is skipped. The memory peak of a real file of N vertices is thus about its 24 N
/// bytes (plus the hint's margin), not the up to 2 x 24 N of doubling.
constexpr std::size_t kMaxReservedVertices = std::size_t(1) << 20;  // 24 MiB
constexpr double kReserveGrowth = 16;

/// Makes room for `more` vertices after v's (see kMaxReservedVertices); `expected` is the hint of
/// the total (0: none).
inline void reserve_ahead(std::vector<Vector3d>& v, std::size_t more, double expected) {
  const std::size_t want = v.size() + more;
  if (v.capacity() >= want) return;
  const double hint = std::max(expected, 0.0);
  const double bound = std::max(static_cast<double>(kMaxReservedVertices), kReserveGrowth * static_cast<double>(v.size()));
  const double step = hint <= bound ? hint : std::min(bound, hint / 2);
  const std::size_t target = step >= static_cast<double>(want) ? static_cast<std::size_t>(step) : std::max(want, 2 * v.size());
  try {
    v.reserve(target);
  } catch (const std::bad_alloc&) {  // only a hint: the vector grows as it must
  }
}

/// Where a row failed: its line index within the parsed range and what was wrong.
struct RowError {
  std::size_t line = 0;
  std::string problem;
};

/// Parses whole lines in [first, last) (last is just after a '\n' or the end of the input).
/// Appends vertices to `out`; returns the number of lines (counting blank ones). Stops at the
/// first bad row and fills `error`.
inline std::size_t parse_rows(const char* first, const char* last, const CsvLayout& layout,
                              std::vector<Vector3d>& out, std::optional<RowError>& error,
                              std::vector<double>* times = nullptr) {
  std::size_t lines = 0;
  std::array<int, 64> role{};  // field k: 0 ignored, 1 + axis, 4 the time t (only with `times`)
  const bool wide = layout.fields > role.size();
  const bool timed = times && layout.t;
  if (!wide) {
    for (std::size_t a = 0; a < 3; ++a) role[layout.xyz[a]] = static_cast<int>(a) + 1;
    if (timed) role[*layout.t] = 4;
  }
  auto role_of = [&](std::size_t k) -> int {
    if (!wide) return role[k];
    for (std::size_t a = 0; a < 3; ++a)
      if (layout.xyz[a] == k) return static_cast<int>(a) + 1;
    return timed && *layout.t == k ? 4 : 0;
  };
  const char* p = first;
  while (p < last) {
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(last - p)));
    const char* end = nl ? nl : last;
    const std::size_t line = lines++;
    const char* q = p;
    while (q < end && is_blank(*q)) ++q;
    if (q == end) {
      p = nl ? nl + 1 : last;
      continue;
    }
    double xyz[4] = {0, 0, 0, 0};
    q = p;
    for (std::size_t k = 0; k < layout.fields; ++k) {
      const char* field_end = end;  // the field's ',' or the line's end
      if (const int r = role_of(k); r == 0) {
        if (const char* c = static_cast<const char*>(std::memchr(q, ',', static_cast<std::size_t>(end - q)))) field_end = c;
      } else {
        // The number read in place: the field is one when it ends, after blanks, at ',' or the line's
        // end (no character of a number is ',' or blank, so this is parse_number of the trimmed field).
        const char* s = q;
        while (s < end && is_blank(*s)) ++s;
        double v = 0;
        const char* after = parse_number_prefix(s, end, v);
        while (after != nullptr && after < end && is_blank(*after)) ++after;
        if (after == nullptr || (after < end && *after != ',') || !std::isfinite(v)) {
          const char* c = static_cast<const char*>(std::memchr(q, ',', static_cast<std::size_t>(end - q)));
          const std::string_view text = trim(std::string_view(q, static_cast<std::size_t>((c ? c : end) - q)));
          error = RowError{line, "column " + std::to_string(k + 1) + " is not a finite number: \"" + printable(text) + "\""};
          return lines;  // the whole field: "1e" and "0x1p3" are not numbers
        }
        xyz[r - 1] = v;
        field_end = after;
      }
      const bool comma = field_end < end;
      if (k + 1 < layout.fields && !comma) {
        error = RowError{line, "has " + std::to_string(k + 1) + " fields, not " + std::to_string(layout.fields)};
        return lines;
      }
      if (k + 1 == layout.fields && comma) {
        error = RowError{line, "has more than " + std::to_string(layout.fields) + " fields"};
        return lines;
      }
      q = field_end + (comma ? 1 : 0);
    }
    out.emplace_back(xyz[0], xyz[1], xyz[2]);
    if (timed) times->push_back(xyz[3]);
    p = nl ? nl + 1 : last;
  }
  return lines;
}

/// Parses [first, last) on up to two threads (split at a line end near the middle).
inline void parse_block(const char* first, const char* last, const CsvLayout& layout, std::size_t threads,
                        std::size_t line_base, std::vector<Vector3d>& out, const std::string& field,
                        const std::string& path, std::size_t& lines_total, std::vector<double>* times) {
  const char* mid = last;
  if (threads > 1 && last - first > (1 << 16)) {
    const char* nl = static_cast<const char*>(std::memchr(first + (last - first) / 2, '\n', static_cast<std::size_t>(last - (first + (last - first) / 2))));
    if (nl && nl + 1 < last) mid = nl + 1;
  }
  std::vector<Vector3d> second;
  std::vector<double> second_times;
  std::optional<RowError> e1, e2;
  std::size_t lines2 = 0;
  std::thread helper;
  if (mid != last) {
    second.reserve(static_cast<std::size_t>(last - mid) / 48);
    helper = std::thread([&] { lines2 = parse_rows(mid, last, layout, second, e2, times ? &second_times : nullptr); });
  }
  const std::size_t lines1 = parse_rows(first, mid, layout, out, e1, times);
  if (helper.joinable()) helper.join();
  const auto fail = [&](std::size_t line, const std::string& problem) {
    throw InvalidInput(field, path, "line " + std::to_string(line_base + line + 1) + " " + problem, kPolylineCsvValid);
  };
  if (e1) fail(e1->line, e1->problem);
  if (e2) fail(lines1 + e2->line, e2->problem);
  out.insert(out.end(), second.begin(), second.end());
  if (times) times->insert(times->end(), second_times.begin(), second_times.end());
  lines_total = lines1 + lines2;
}

inline void read_csv(InputFile& in, std::string block, std::size_t threads, PolylineInput& result, bool timed = false) {
  const std::string& field = in.field();
  const std::string& path = in.path();
  if (block.size() >= 3 && block.compare(0, 3, "\xEF\xBB\xBF") == 0) block.erase(0, 3);  // UTF-8 BOM
  std::optional<CsvLayout> layout;
  std::size_t line_base = 0;
  // The bytes not parsed yet are buffer[begin, begin + filled): reads land right after them (no
  // copy) at a page boundary (the kernel copies faster there); only a block's unfinished last
  // line moves, to end just before a page boundary.
  constexpr std::size_t kPage = 4096;
  const std::size_t capacity = std::max(2 * kBlockBytes, block.size() + kBlockBytes) + 2 * kPage;
  std::unique_ptr<char[]> storage(new char[capacity]);
  char* const buffer = storage.get() + (kPage - reinterpret_cast<std::uintptr_t>(storage.get()) % kPage) % kPage;
  std::size_t begin = 0, filled = block.size();
  std::memcpy(buffer, block.data(), filled);
  bool eof = false;
  std::uint64_t consumed = 0;
  while (filled > 0 || !eof) {
    if (!eof && filled < kBlockBytes) {
      const std::size_t got = in.read(buffer + begin + filled, kBlockBytes);
      filled += got;
      eof = got < kBlockBytes;
      if (!eof) continue;
    }
    const std::string_view view(buffer + begin, filled);
    // The complete lines of the block; at the end of the input, the last line needs no '\n'.
    std::size_t complete = filled;
    if (!eof) {
      const std::size_t nl = view.rfind('\n');
      if (nl == std::string::npos)
        throw InvalidInput(field, path, "line " + std::to_string(line_base + 1) + " is longer than 4 MiB", kPolylineCsvValid);
      complete = nl + 1;
    }
    std::size_t start = 0;
    while (!layout && start < complete) {  // find the first non-blank line
      const std::size_t nl = view.find('\n', start);
      const std::size_t end = nl == std::string::npos || nl > complete ? complete : nl;
      const std::string_view line = trim(view.substr(start, end - start));
      start = end < complete ? end + 1 : complete;
      ++line_base;
      if (line.empty()) continue;
      layout = layout_from_first_line(line, field, path);
      if (!layout->header) {  // a data row: parse it again as a row
        start = 0;
        line_base = 0;
      }
    }
    if (layout) {
      std::size_t lines = 0;
      if (timed && !layout->t)
        throw InvalidInput(field, path, "no column t (line 1 must be a header naming t, x, y, z)", kTimedPolylineValid);
      parse_block(view.data() + start, view.data() + complete, *layout, threads, line_base, result.vertices, field,
                  path, lines, timed ? &result.t : nullptr);
      line_base += lines;
    }
    consumed += complete;
    if (!eof && result.vertices.size() > 0) {  // room for the next two blocks, at the rows' density so far
      const double per_byte = static_cast<double>(result.vertices.size()) / static_cast<double>(consumed);
      double ahead = 2.0 * kBlockBytes;
      if (in.size()) ahead = std::min(ahead, static_cast<double>(*in.size() - std::min(*in.size(), consumed)));
      reserve_ahead(result.vertices, static_cast<std::size_t>(per_byte * ahead * 1.05) + 1024,
                    in.size() ? per_byte * static_cast<double>(*in.size()) * 1.05 + 1024 : 0.0);
    }
    filled -= complete;
    const std::size_t to = (kPage - filled % kPage) % kPage;  // buffer + to + filled: page-aligned offset
    std::memmove(buffer + to, buffer + begin + complete, filled);
    begin = to;
    if (eof && filled == 0) break;
  }
  result.format = layout && layout->header ? "csv with header" : "csv";
}

inline bool finite_nonzero_row(const double (&xyz)[3]) {
  // By the bits (one pass, no branch a coordinate): an exponent of all ones is inf or NaN; a
  // coordinate is zero when all but the sign bit are.
  std::uint64_t b[3];
  std::memcpy(b, xyz, sizeof b);
  constexpr std::uint64_t exponent = 0x7ff0000000000000u;
  const bool finite = (b[0] & exponent) != exponent && (b[1] & exponent) != exponent && (b[2] & exponent) != exponent;
  return finite && ((b[0] | b[1] | b[2]) << 1) != 0;
}

inline std::string shape_text(const NpyHeader& h) {
  std::string s = "(";
  for (std::size_t k = 0; k < h.shape.size(); ++k) s += (k ? ", " : "") + std::to_string(h.shape[k]);
  return s + (h.shape.size() == 1 ? ",)" : ")");
}

inline void read_npy(InputFile& in, std::string block, PolylineInput& result, bool timed = false) {
  const std::string& field = in.field();
  const std::string& path = in.path();
  const std::size_t preamble = npy_preamble_length(block, field, path);
  if (block.size() < preamble) {
    const std::size_t have = block.size();
    block.resize(preamble);
    block.resize(have + in.read(block.data() + have, preamble - have));
  }
  const NpyHeader h = parse_npy_header(block, field, path);
  const std::uint64_t cols = h.cols();
  if (h.shape.size() != 2 || !(cols == 3 || cols == 4 || cols == 7))
    throw InvalidInput(field, path, "an array of shape " + shape_text(h), kNpyValid);
  if (timed && cols == 3)
    throw InvalidInput(field, path, "an array of shape " + shape_text(h) + " has no column t", kTimedPolylineValid);
  const std::uint64_t bytes = npy_data_bytes(h, field, path);
  const auto truncated = [&](std::uint64_t have) {
    return InvalidInput(field, path,
                        "truncated: shape " + shape_text(h) + " needs " + std::to_string(bytes) +
                            " bytes of data, the input has " + std::to_string(have),
                        kNpyValid);
  };
  if (in.size()) {  // a regular file: check its size before reading or allocating anything
    const std::uint64_t have = *in.size() - std::min<std::uint64_t>(*in.size(), h.data_offset);
    if (have < bytes) throw truncated(have);
    if (have > bytes) throw InvalidInput(field, path, std::to_string(have - bytes) + " bytes after the array's data", kNpyValid);
  }
  const std::size_t first = cols == 3 ? 0 : 1;  // x,y,z, or t,x,y,z[,vx,vy,vz]
  const std::size_t row_bytes = static_cast<std::size_t>(cols) * h.item_bytes;
  std::string data = block.substr(std::min(block.size(), h.data_offset));
  std::unique_ptr<char[]> chunk(new char[kBlockBytes]);
  std::uint64_t rows_left = h.rows();
  for (;;) {
    const std::size_t whole = static_cast<std::size_t>(std::min<std::uint64_t>(data.size() / row_bytes, rows_left));
    reserve_ahead(result.vertices, whole, static_cast<double>(h.rows()));
    const std::uint64_t row0 = h.rows() - rows_left;
    const auto take = [&](auto item) {  // item: a value of the array's type, double or float
      using Item = decltype(item);
      const std::size_t base = result.vertices.size();
      result.vertices.resize(base + whole);  // reserved; Eigen's vectors are not initialised
      Vector3d* out = result.vertices.data() + base;
      const char* row = data.data();
      for (std::size_t r = 0; r < whole; ++r, row += row_bytes) {
        Item f[3];
        std::memcpy(f, row + first * sizeof(Item), sizeof f);
        const double xyz[3] = {f[0], f[1], f[2]};
        if (!finite_nonzero_row(xyz)) {  // refused as it is read: a sparse (3e9, 3) file fails at its first row
          result.vertices.resize(base + r);
          throw InvalidInput(field, path,
                             "row " + std::to_string(row0 + r) + " (" + number_text(xyz[0]) + ", " +
                                 number_text(xyz[1]) + ", " + number_text(xyz[2]) + ") is not a finite nonzero vector",
                             kNpyValid);
        }
        out[r] = Vector3d(xyz[0], xyz[1], xyz[2]);
      }
      if (timed) {
        row = data.data();
        for (std::size_t r = 0; r < whole; ++r, row += row_bytes) {
          Item t;
          std::memcpy(&t, row, sizeof t);
          result.t.push_back(t);
        }
      }
    };
    if (h.item_bytes == 8) take(double{});
    else take(float{});
    rows_left -= whole;
    data.erase(0, whole * row_bytes);
    if (rows_left == 0) break;
    const std::size_t got = in.read(chunk.get(), kBlockBytes);
    if (got == 0) throw truncated((h.rows() - rows_left) * row_bytes + data.size());
    data.append(chunk.get(), got);
  }
  if (!data.empty() || in.read(chunk.get(), 1) != 0)
    throw InvalidInput(field, path, "bytes after the array's data", kNpyValid);
  result.format = std::string("npy ") + (h.item_bytes == 8 ? "<f8" : "<f4") + " " + shape_text(h);
}

}  // namespace polyline_input_detail

/// Reads a polyline from `path` ("-": standard input), CSV or .npy by its first bytes. Throws
/// InvalidInput(field, path, ...) for anything it cannot read (see the top of this header). An
/// input with no rows (empty, blank lines only, a header only, shape (0, 3)) gives no vertices:
/// too few vertices is the caller's refusal (validate_spherical_polyline).
inline PolylineInput read_polyline(const std::string& path, const std::string& field = "input", std::size_t threads = 2) {
  namespace d = polyline_input_detail;
  InputFile in = InputFile::open(path, field);
  std::string start(16, '\0');
  start.resize(in.read(start.data(), start.size()));
  PolylineInput result;
  if (looks_like_npy(start)) d::read_npy(in, std::move(start), result);
  else d::read_csv(in, std::move(start), threads, result);
  return result;
}

/// A timed polyline: the vertices and their carrier angles t, from a CSV whose header names t, x,
/// y, z (what `sphtroch trace` writes) or a .npy array (N, 4) / (N, 7) (column 0 is t). Throws
/// InvalidInput(field, path, ...) as read_polyline does, and when there is no column t; in a CSV
/// a t that is not a finite number is refused with its line, in a .npy t is not checked here.
/// Finite, increasing t is the caller's check (identify names the first t that is not).
inline PolylineInput read_timed_polyline(const std::string& path, const std::string& field = "input",
                                         std::size_t threads = 2) {
  namespace d = polyline_input_detail;
  InputFile in = InputFile::open(path, field);
  std::string start(16, '\0');
  start.resize(in.read(start.data(), start.size()));
  PolylineInput result;
  if (looks_like_npy(start)) d::read_npy(in, std::move(start), result, true);
  else d::read_csv(in, std::move(start), threads, result, true);
  return result;
}

}  // namespace sphtroch
