// sphtroch/atlas/atlas_csv.hpp — the atlas as CSV text, read back, and shard slices merged into the
// file the unsharded run writes, byte for byte. Eigen only.
//
//   std::ostringstream out;
//   write_atlas_csv(out, spec, std::nullopt, cells);         // the whole atlas
//   write_atlas_csv(out, spec, AtlasShard{2, 4}, slice);     // job 2 of 4
//   AtlasCsv part = read_atlas_csv(slice_text, "slice2.csv");  // InvalidInput on anything odd
//   AtlasCsv whole = merge_atlas_slices({part1, part2});    // any order
//   write_atlas_csv(out, whole.spec, std::nullopt, whole.cells);  // == the unsharded file
//
// Format (one file = one comment line, one header line, one row per cell):
//   # sphtroch atlas n=2 grid=128 a2=0:3.1415926535897931 a3=0:3.1415926535897931 reading=default
//   i,j,a2,a3,nodes,crossings,tangencies,cusps,analytic_nodes,analytic_cusps,agree
//   0,0,0.012271846303085129,0.012271846303085129,0,0,0,0,0,0,1
//  * The comment line names everything the rows depend on: the ratio p/q, the grid, the ranges
//    (shortest round-trip form, number_text.hpp) and the reading (default | literal). A slice appends
//    " shard=I/K rows=B:E" (rows B .. E-1). The unsharded file has no shard tag.
//  * Rows are in the fixed order i (a2 index) major, j (a3 index) minor; a2, a3 printed with
//    the shortest round-trip form; analytic_nodes and agree are "NA" when the report has no node criterion (n != 1, 2);
//    agree is 1 or 0 otherwise.
//  * read_atlas_csv re-prints every row it parsed and requires the same text, so a merged file
//    regenerated from parsed rows is byte-identical to the slices' rows; it also requires
//    a2, a3 to be the cell centres of (i, j), nodes = crossings + tangencies, and agree to
//    match the counts.
//  Errors: InvalidInput with field "slice" (read, merge) or "slices" (merge), value the file name
//  (or names), problem and the valid form.
#pragma once

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/shard.hpp"
#include "sphtroch/io/parse.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace sphtroch {

/// The CSV header line (without newline).
constexpr const char* kAtlasCsvHeader = "i,j,a2,a3,nodes,crossings,tangencies,cusps,analytic_nodes,analytic_cusps,agree";

/// "# sphtroch atlas n=... grid=... a2=LO:HI a3=LO:HI reading=..." (+ " shard=I/K rows=B:E").
inline std::string atlas_csv_comment(const AtlasSpec& spec, const std::optional<AtlasShard>& shard = std::nullopt);

/// One row (without newline).
inline std::string atlas_csv_row(const AtlasCell& cell);

/// Comment, header and rows. REQUIRES: cells are the rows of the shard (or of the whole grid).
inline void write_atlas_csv(std::ostream& out, const AtlasSpec& spec, const std::optional<AtlasShard>& shard,
                            const std::vector<AtlasCell>& cells);

/// The first two lines of an atlas file or slice: which atlas, which rows.
struct AtlasCsvHead {
  std::string name;                 // where it came from (for messages)
  AtlasSpec spec;
  std::string spec_comment;         // the comment line without the shard part
  std::optional<AtlasShard> shard;  // nullopt: the whole atlas
  AtlasRows rows;
  std::size_t cell_count() const { return (rows.end - rows.begin) * spec.grid; }
};

/// A parsed atlas file or slice.
struct AtlasCsv : AtlasCsvHead {
  std::vector<AtlasCell> cells;
};

/// Parses one file; throws InvalidInput("slice", name, ...) when it is not an atlas CSV written
/// by write_atlas_csv (any row out of order, missing, or not re-printing identically).
inline AtlasCsv read_atlas_csv(std::string_view text, const std::string& name);

/// The same checks, one line at a time (for reading a slice as a stream, in bounded memory):
/// the comment and header lines, then row k (0-based, of head.cell_count()) of the file.
inline AtlasCsvHead read_atlas_csv_head(std::string_view comment, std::string_view header, const std::string& name);
inline AtlasCell read_atlas_csv_row(const AtlasCsvHead& head, std::size_t k, std::string_view line);

/// The slices of one atlas in shard order (indices into heads). Throws InvalidInput when they
/// belong to different atlases (comment lines differ), when a shard is missing or given twice,
/// or when the shard counts differ.
inline std::vector<std::size_t> atlas_slice_order(const std::vector<AtlasCsvHead>& heads);

/// Joins slices (any order) into the whole atlas, with the checks of atlas_slice_order. A single
/// unsharded file is returned as it is.
inline AtlasCsv merge_atlas_slices(std::vector<AtlasCsv> slices);

// =============================================================================================
// Implementation details follow.
// =============================================================================================

namespace atlas_csv_detail {

inline std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = s.find(sep, start);
    parts.push_back(s.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) break;
    start = at + 1;
  }
  return parts;
}

inline std::optional<std::uint64_t> to_uint(std::string_view s) {
  if (s.empty() || s.size() > 18 || s.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  return std::strtoull(std::string(s).c_str(), nullptr, 10);
}

inline std::optional<double> to_double(std::string_view s) {
  if (s.empty()) return std::nullopt;
  const std::string str(s);
  char* end = nullptr;
  const double v = std::strtod(str.c_str(), &end);
  if (end != str.c_str() + str.size()) return std::nullopt;
  return v;
}

/// "key=value" fields of the comment line after "# sphtroch atlas".
inline std::optional<std::string_view> field(const std::vector<std::string_view>& words, std::string_view key) {
  for (std::string_view w : words)
    if (w.size() > key.size() && w.substr(0, key.size()) == key && w[key.size()] == '=') return w.substr(key.size() + 1);
  return std::nullopt;
}

}  // namespace atlas_csv_detail

inline std::string atlas_csv_comment(const AtlasSpec& spec, const std::optional<AtlasShard>& shard) {
  std::string s = "# sphtroch atlas n=" + spec.ratio.str() + " grid=" + std::to_string(spec.grid) + " a2=" +
                  number_text(spec.a2.lo) + ":" + number_text(spec.a2.hi) + " a3=" + number_text(spec.a3.lo) +
                  ":" + number_text(spec.a3.hi) + " reading=" + (spec.reading.literal ? "literal" : "default");
  if (shard) {
    const AtlasRows r = shard_rows(spec.grid, *shard);
    s += " shard=" + std::to_string(shard->index) + "/" + std::to_string(shard->count) + " rows=" +
         std::to_string(r.begin) + ":" + std::to_string(r.end);
  }
  return s;
}

inline std::string atlas_csv_row(const AtlasCell& c) {
  std::string s = std::to_string(c.i) + "," + std::to_string(c.j) + "," + number_text(c.a2) + "," +
                  number_text(c.a3) + "," + std::to_string(c.nodes) + "," + std::to_string(c.crossings) + "," +
                  std::to_string(c.tangencies) + "," + std::to_string(c.cusps) + ",";
  s += c.analytic_nodes ? std::to_string(*c.analytic_nodes) : std::string("NA");
  s += "," + std::to_string(c.analytic_cusps) + ",";
  s += c.agree ? (*c.agree ? "1" : "0") : "NA";
  return s;
}

inline void write_atlas_csv(std::ostream& out, const AtlasSpec& spec, const std::optional<AtlasShard>& shard,
                            const std::vector<AtlasCell>& cells) {
  out << atlas_csv_comment(spec, shard) << '\n' << kAtlasCsvHeader << '\n';
  for (const AtlasCell& c : cells) out << atlas_csv_row(c) << '\n';
}

/// The valid form named by every InvalidInput about an atlas CSV's content.
inline const char* const kAtlasCsvForm =
    "a CSV written by sphtroch atlas (comment line, header, one row per cell in order)";

namespace atlas_csv_detail {

/// The start of a line for a message: at most 120 bytes, control bytes (NUL included) as \xNN,
/// so that the message stays one C string on one line.
inline std::string quoted_line(std::string_view line) {
  std::string out;
  for (unsigned char c : line.substr(0, 120)) {
    if (c < 0x20 || c == 0x7f) {
      const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

inline InvalidInput bad_slice(const std::string& name, const std::string& problem) {
  return InvalidInput("slice", name, problem, kAtlasCsvForm);
}

/// n=p or n=p/q in lowest terms, as Ratio::str() prints it (p may be negative). Ratio refuses
/// terms beyond kMaxTerm, and to_uint reads at most 18 digits, so nothing can overflow.
inline Ratio ratio_field(std::string_view text, const std::string& name) {
  const auto nf = split(text, '/');
  const bool negative = !nf[0].empty() && nf[0][0] == '-';
  const auto p = to_uint(nf[0].substr(negative ? 1 : 0));
  const auto q = nf.size() == 2 ? to_uint(nf[1]) : std::optional<std::uint64_t>(1);
  if (!p || !q || nf.size() > 2) throw bad_slice(name, "n=" + std::string(text) + " is not p/q");
  const auto signed_p = static_cast<std::int64_t>(*p);
  return Ratio(negative ? -signed_p : signed_p, static_cast<std::int64_t>(*q));
}

inline AngleRange range_field(std::string_view text, const std::string& name) {
  const auto r = split(text, ':');
  const auto lo = r.size() == 2 ? to_double(r[0]) : std::nullopt;
  const auto hi = r.size() == 2 ? to_double(r[1]) : std::nullopt;
  if (!lo || !hi) throw bad_slice(name, "range " + std::string(text) + " is not LO:HI");
  return AngleRange{*lo, *hi};
}

}  // namespace atlas_csv_detail

inline AtlasCsvHead read_atlas_csv_head(std::string_view comment, std::string_view header, const std::string& name) {
  using namespace atlas_csv_detail;
  auto bad = [&](const std::string& problem) { return bad_slice(name, problem); };
  AtlasCsvHead out;
  out.name = name;
  const std::string_view prefix = "# sphtroch atlas ";
  if (comment.substr(0, prefix.size()) != prefix) throw bad("first line is not \"# sphtroch atlas ...\"");
  if (header != kAtlasCsvHeader) throw bad("second line is not the atlas header");
  const std::vector<std::string_view> words = split(comment.substr(prefix.size()), ' ');

  // The spec, re-printed and compared with the comment (so every field is as written).
  const auto n = field(words, "n"), grid = field(words, "grid"), a2 = field(words, "a2"), a3 = field(words, "a3"),
             reading = field(words, "reading");
  if (!n || !grid || !a2 || !a3 || !reading) throw bad("comment line lacks n=, grid=, a2=, a3= or reading=");
  try {
    out.spec.ratio = ratio_field(*n, name);
    const auto g = to_uint(*grid);
    if (!g) throw bad("grid=" + std::string(*grid) + " is not a whole number");
    out.spec.grid = static_cast<std::size_t>(*g);
    out.spec.a2 = range_field(*a2, name);
    out.spec.a3 = range_field(*a3, name);
    out.spec.reading.literal = *reading == "literal";
    out.spec.validate();
  } catch (const InvalidInput& e) {
    if (e.field() == "slice") throw;
    throw bad(std::string("comment line: ") + e.what());
  }
  out.spec_comment = atlas_csv_comment(out.spec);
  if (const auto shard = field(words, "shard")) {
    try {
      out.shard = parse_shard(std::string(*shard), out.spec.grid, "grid (" + std::to_string(out.spec.grid) + ")");
      out.rows = shard_rows(out.spec.grid, *out.shard);
    } catch (const InvalidInput& e) {
      throw bad(std::string("comment line: ") + e.what());
    }
  } else {
    out.rows = AtlasRows{0, out.spec.grid};
  }
  if (std::string(comment) != atlas_csv_comment(out.spec, out.shard))
    throw bad("comment line is not as sphtroch atlas writes it: \"" + quoted_line(comment) + "\"");
  return out;
}

inline AtlasCell read_atlas_csv_row(const AtlasCsvHead& head, std::size_t k, std::string_view line) {
  using namespace atlas_csv_detail;
  const std::size_t g = head.spec.grid;
  auto row_error = [&](const std::string& what) {
    return bad_slice(head.name,
                     "line " + std::to_string(k + 3) + ": " + what + ": \"" + quoted_line(line) + "\"");
  };
  const auto f = split(line, ',');
  if (f.size() != 11) throw row_error("not 11 fields");
  AtlasCell c;
  const auto i = to_uint(f[0]), j = to_uint(f[1]);
  const auto a2v = to_double(f[2]), a3v = to_double(f[3]);
  const auto nodes = to_uint(f[4]), cr = to_uint(f[5]), ta = to_uint(f[6]), cu = to_uint(f[7]), ac = to_uint(f[9]);
  if (!i || !j || !a2v || !a3v || !nodes || !cr || !ta || !cu || !ac) throw row_error("malformed field");
  if (*i != head.rows.begin + k / g || *j != k % g) throw row_error("cell out of order (rows go i major, j minor)");
  c.i = static_cast<std::uint32_t>(*i);
  c.j = static_cast<std::uint32_t>(*j);
  c.a2 = *a2v;
  c.a3 = *a3v;
  c.nodes = static_cast<std::uint32_t>(*nodes);
  c.crossings = static_cast<std::uint32_t>(*cr);
  c.tangencies = static_cast<std::uint32_t>(*ta);
  c.cusps = static_cast<std::uint32_t>(*cu);
  c.analytic_cusps = static_cast<std::uint32_t>(*ac);
  c.cusps_agree = c.cusps == c.analytic_cusps;
  if (f[8] != "NA") {
    const auto an = to_uint(f[8]);
    if (!an) throw row_error("malformed analytic_nodes");
    c.analytic_nodes = static_cast<std::uint32_t>(*an);
  }
  if (f[10] != "NA") c.agree = f[10] == "1";
  if (c.nodes != c.crossings + c.tangencies) throw row_error("nodes != crossings + tangencies");
  if (c.agree.has_value() != c.analytic_nodes.has_value() ||
      (c.agree && *c.agree != (c.nodes == *c.analytic_nodes && c.cusps_agree)))
    throw row_error("agree does not match the counts");
  if (c.a2 != head.spec.a2_at(c.i) || c.a3 != head.spec.a3_at(c.j)) throw row_error("a2, a3 are not the cell centre");
  if (atlas_csv_row(c) != line) throw row_error("does not re-print identically");
  return c;
}

inline AtlasCsv read_atlas_csv(std::string_view text, const std::string& name) {
  using namespace atlas_csv_detail;
  if (text.empty() || text.back() != '\n') throw bad_slice(name, "empty or truncated (no final newline)");
  const std::vector<std::string_view> lines = split(text.substr(0, text.size() - 1), '\n');
  if (lines.size() < 2) throw bad_slice(name, "no comment and header lines");
  AtlasCsv out;
  static_cast<AtlasCsvHead&>(out) = read_atlas_csv_head(lines[0], lines[1], name);
  const std::size_t expected = out.cell_count();
  if (lines.size() - 2 != expected)
    throw bad_slice(name, std::to_string(lines.size() - 2) + " rows where rows " + std::to_string(out.rows.begin) +
                              ":" + std::to_string(out.rows.end) + " of grid " + std::to_string(out.spec.grid) +
                              " need " + std::to_string(expected));
  out.cells.reserve(expected);
  for (std::size_t k = 0; k < expected; ++k) out.cells.push_back(read_atlas_csv_row(out, k, lines[k + 2]));
  return out;
}

inline std::vector<std::size_t> atlas_slice_order(const std::vector<AtlasCsvHead>& slices) {
  const std::string form = "the slices of one atlas, each shard I/K (I = 1 .. K) exactly once";
  auto names = [&] {
    std::string s;
    for (const auto& x : slices) s += (s.empty() ? "" : " ") + x.name;
    return s;
  };
  if (slices.empty()) throw InvalidInput("slices", "(none)", "no slice given", form);
  const AtlasCsvHead& first = slices.front();
  for (const AtlasCsvHead& s : slices)
    if (s.spec_comment != first.spec_comment)
      throw InvalidInput("slice", s.name, "belongs to another atlas (\"" + s.spec_comment + "\" vs \"" +
                                              first.spec_comment + "\" in " + first.name + ")", form);
  const std::size_t k = first.shard ? first.shard->count : 1;
  for (const AtlasCsvHead& s : slices) {
    const std::size_t ks = s.shard ? s.shard->count : 1;
    if (ks != k)
      throw InvalidInput("slice", s.name, "is one of " + std::to_string(ks) + " shards, " + first.name + " one of " +
                                              std::to_string(k), form);
  }
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> by_index(k + 1, kNone);
  for (std::size_t at = 0; at < slices.size(); ++at) {
    const AtlasCsvHead& s = slices[at];
    const std::size_t i = s.shard ? s.shard->index : 1;
    if (by_index[i] != kNone)
      throw InvalidInput("slice", s.name, "shard " + std::to_string(i) + "/" + std::to_string(k) +
                                              " given twice (also " + slices[by_index[i]].name + ")", form);
    by_index[i] = at;
  }
  std::string missing;
  for (std::size_t i = 1; i <= k; ++i)
    if (by_index[i] == kNone) missing += (missing.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(k);
  if (!missing.empty()) throw InvalidInput("slices", names(), "shard " + missing + " missing", form);
  by_index.erase(by_index.begin());
  return by_index;
}

inline AtlasCsv merge_atlas_slices(std::vector<AtlasCsv> slices) {
  const std::vector<AtlasCsvHead> heads(slices.begin(), slices.end());
  const std::vector<std::size_t> order = atlas_slice_order(heads);
  AtlasCsv whole;
  for (const AtlasCsvHead& h : heads) whole.name += (whole.name.empty() ? "" : " ") + h.name;
  whole.spec = heads.front().spec;
  whole.spec_comment = heads.front().spec_comment;
  whole.rows = AtlasRows{0, whole.spec.grid};
  whole.cells.reserve(whole.spec.cells());
  for (std::size_t at : order) whole.cells.insert(whole.cells.end(), slices[at].cells.begin(), slices[at].cells.end());
  return whole;
}

}  // namespace sphtroch
