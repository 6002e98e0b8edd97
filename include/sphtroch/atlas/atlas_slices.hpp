// sphtroch/atlas/atlas_slices.hpp — atlas-merge's reader: the CSV slices of a sharded atlas run
// (atlas_csv.hpp), streamed row by row in memory bounded by one block and one line per slice.
// Eigen only; POSIX files (io/input_file.hpp).
//
//   std::ofstream("part1.csv") << slice_text;  // a slice written by `sphtroch atlas --shard 2/4`
//   std::vector<sphtroch::AtlasSlice> s = sphtroch::open_atlas_slices({"part1.csv"});  // heads only
//   sphtroch::for_each_atlas_row(s[0], [&](const sphtroch::AtlasCell&, std::string_view) {});  // each row, in order
//
// Contracts:
//  1. open_atlas_slices reads each slice's comment and header line. A regular file is read again
//     (head and rows) when for_each_atlas_row comes to it, never held; standard input ("-"), a
//     pipe or a FIFO can be read only once, so its text is held (at most kMaxHeldSliceBytes).
//  2. Two kinds of error. A slice that cannot be read at all (missing, a directory, a read error,
//     too large from a pipe, a head line over kMaxAtlasLine) throws UnreadableSlice. A slice that
//     reads but is not an atlas CSV — a bad head or row, a row line over kMaxAtlasLine, too few or
//     too many rows, no final newline, a head that changed between the two reads — throws
//     InvalidInput("slice", path, problem, kAtlasCsvForm).
//  3. for_each_atlas_row checks every row as read_atlas_csv does and calls row(cell, line) in
//     order; an exception from `row` passes through unchanged.
#pragma once

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/atlas/atlas_csv.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/io/input_file.hpp"

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sphtroch {

/// Atlas lines are under 200 bytes; a longer one is not an atlas line.
constexpr std::size_t kMaxAtlasLine = 4096;
/// A slice read from a pipe is held in memory: at most this many bytes (~13 M cells).
constexpr std::size_t kMaxHeldSliceBytes = std::size_t(1) << 30;

/// A slice that cannot be read as a file (contract 2). what(): "slice = PATH: PROBLEM".
class UnreadableSlice : public std::runtime_error {
 public:
  UnreadableSlice(std::string path, std::string problem)
      : std::runtime_error("slice = " + path + ": " + problem), path_(std::move(path)), problem_(std::move(problem)) {}
  const std::string& path() const noexcept { return path_; }
  const std::string& problem() const noexcept { return problem_; }

 private:
  std::string path_, problem_;
};

/// One slice: its path, its head, and its text when it could be read only once.
struct AtlasSlice {
  std::string path;
  AtlasCsvHead head;
  std::optional<std::string> held;
};

namespace atlas_slices_detail {

inline InvalidInput bad(const std::string& path, const std::string& problem) {
  return InvalidInput("slice", path, problem, kAtlasCsvForm);
}

/// lines.next where any failure means the file cannot be read (the head lines).
inline bool next_head_line(InputLines& lines, std::string_view& line, const std::string& path) {
  try {
    return lines.next(line);
  } catch (const InvalidInput& e) {
    throw UnreadableSlice(path, e.problem());
  }
}

/// lines.next for rows: a line over the bound is content that is not an atlas row.
inline bool next_row_line(InputLines& lines, std::string_view& line, const std::string& path) {
  try {
    return lines.next(line);
  } catch (const LineTooLong& e) {
    throw bad(path, e.problem());
  } catch (const InvalidInput& e) {
    throw UnreadableSlice(path, e.problem());
  }
}

/// The comment and header lines of a slice, checked as read_atlas_csv checks them.
inline AtlasCsvHead read_head(InputLines& lines, const std::string& path) {
  std::string_view line;
  if (!next_head_line(lines, line, path)) throw bad(path, "empty or truncated (no final newline)");
  const std::string comment(line);  // the view ends with the next call
  if (!next_head_line(lines, line, path) || !lines.last_ended_with_newline())
    throw bad(path, "no comment and header lines");
  try {
    return read_atlas_csv_head(comment, line, path);
  } catch (const InvalidInput& e) {  // a head value out of its range (n = 0/1, grid = 0): not an atlas head
    if (e.field() == "slice") throw;
    throw bad(path, "head " + e.field() + " = " + e.value() + ": " + e.problem());
  }
}

/// The whole of standard input, a pipe or a FIFO (contract 1), or UnreadableSlice.
inline std::string read_held(InputFile& in, const std::string& path) {
  std::string text;
  std::vector<char> block(std::size_t(1) << 16);
  try {
    while (const std::size_t k = in.read(block.data(), block.size())) {
      text.append(block.data(), k);
      if (text.size() > kMaxHeldSliceBytes)
        throw UnreadableSlice(path, "larger than " + std::to_string(kMaxHeldSliceBytes) + " bytes from a pipe");
      if (k < block.size()) break;
    }
  } catch (const InvalidInput& e) {
    throw UnreadableSlice(path, e.problem());
  }
  return text;
}

inline InputFile open_file(const std::string& path) {
  try {
    return InputFile::open(path, "slice");
  } catch (const InvalidInput& e) {
    throw UnreadableSlice(path, e.problem());
  }
}

inline AtlasSlice open_slice(const std::string& path) {
  AtlasSlice s;
  s.path = path;
  InputFile in = open_file(path);
  if (path == "-" || !in.size()) s.held = read_held(in, path);  // read once: stdin, a pipe, a FIFO
  std::optional<InputLines> lines;
  if (s.held) lines.emplace(*s.held, path, "slice", kMaxAtlasLine);
  else lines.emplace(in, kMaxAtlasLine);
  s.head = read_head(*lines, path);
  return s;
}

}  // namespace atlas_slices_detail

/// The head of every slice, in the order given (contract 1, errors contract 2).
inline std::vector<AtlasSlice> open_atlas_slices(const std::vector<std::string>& paths) {
  std::vector<AtlasSlice> slices;
  for (const std::string& path : paths) slices.push_back(atlas_slices_detail::open_slice(path));
  return slices;
}

/// Calls row(cell, line) for every row of the slice, in order, with read_atlas_csv's checks (the
/// head again, row count, final newline); memory: one block and one line.
template <class Row>
void for_each_atlas_row(const AtlasSlice& s, const Row& row) {
  using namespace atlas_slices_detail;
  std::optional<InputFile> file;
  std::optional<InputLines> lines;
  if (s.held) {
    lines.emplace(*s.held, s.path, "slice", kMaxAtlasLine);
  } else {
    file.emplace(open_file(s.path));
    lines.emplace(*file, kMaxAtlasLine);
  }
  const AtlasCsvHead again = read_head(*lines, s.path);
  if (again.spec_comment != s.head.spec_comment || again.rows.begin != s.head.rows.begin)
    throw bad(s.path, "changed while being merged");
  std::string_view line;
  const std::size_t expected = s.head.cell_count();
  std::size_t k = 0;
  for (; next_row_line(*lines, line, s.path); ++k)
    if (k < expected) row(read_atlas_csv_row(s.head, k, line), line);
  if (k != 0 && !lines->last_ended_with_newline()) throw bad(s.path, "empty or truncated (no final newline)");
  if (k != expected)
    throw bad(s.path, std::to_string(k) + " rows where rows " + std::to_string(s.head.rows.begin) + ":" +
                          std::to_string(s.head.rows.end) + " of grid " + std::to_string(s.head.spec.grid) + " need " +
                          std::to_string(expected));
}

}  // namespace sphtroch
