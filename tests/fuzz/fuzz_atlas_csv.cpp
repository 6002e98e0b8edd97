// tests/fuzz/fuzz_atlas_csv.cpp — read_atlas_csv and merge_atlas_slices (atlas_csv.hpp).
//
// Input: one or more atlas CSV files separated by NUL bytes (at most 8; a NUL has no place in an
// atlas file). Each is parsed; a parsed file must re-print (write_atlas_csv) byte for byte and
// parse again to the same cells. The parsed files are merged; a merged atlas must re-print as
// the unsharded file, which parses again.
// Expected: sphtroch::InvalidInput. Anything else thrown crashes; a broken invariant traps.
#include "fuzz_common.hpp"

#include "sphtroch/atlas/atlas_csv.hpp"
#include "sphtroch/core/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

using sphtroch::AtlasCsv;
using sphtroch::InvalidInput;

bool same_cells(const std::vector<sphtroch::AtlasCell>& a, const std::vector<sphtroch::AtlasCell>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (sphtroch::atlas_csv_row(a[k]) != sphtroch::atlas_csv_row(b[k])) return false;
  return true;
}

std::string print(const AtlasCsv& f) {
  std::ostringstream out;
  sphtroch::write_atlas_csv(out, f.spec, f.shard, f.cells);
  return out.str();
}

void check_parsed(const AtlasCsv& f, std::string_view text) {
  FUZZ_CHECK(f.rows.begin <= f.rows.end && f.rows.end <= f.spec.grid);
  FUZZ_CHECK(f.cells.size() == (f.rows.end - f.rows.begin) * f.spec.grid);
  FUZZ_CHECK(f.spec_comment == sphtroch::atlas_csv_comment(f.spec));
  // read_atlas_csv accepts only what write_atlas_csv writes: the same bytes again.
  const std::string again = print(f);
  FUZZ_CHECK(again == text);
  const AtlasCsv reread = sphtroch::read_atlas_csv(again, f.name);  // must not throw
  FUZZ_CHECK(reread.spec_comment == f.spec_comment && reread.shard.has_value() == f.shard.has_value());
  FUZZ_CHECK(same_cells(reread.cells, f.cells));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string_view> texts;
  for (std::size_t start = 0; texts.size() < 8;) {
    const std::size_t nul = input.find('\0', start);
    texts.push_back(input.substr(start, nul == std::string_view::npos ? std::string_view::npos : nul - start));
    if (nul == std::string_view::npos) break;
    start = nul + 1;
  }

  std::vector<AtlasCsv> parsed;
  for (std::size_t k = 0; k < texts.size(); ++k) {
    const std::string name = "slice" + std::to_string(k + 1) + ".csv";
    try {
      AtlasCsv f = sphtroch::read_atlas_csv(texts[k], name);
      FUZZ_CHECK(f.name == name);
      check_parsed(f, texts[k]);
      parsed.push_back(std::move(f));
    } catch (const InvalidInput& e) {
      FUZZ_CHECK(e.field() == "slice" && e.value() == name && !e.problem().empty());
    }
  }
  if (parsed.empty()) return 0;

  std::size_t cells = 0;
  for (const AtlasCsv& f : parsed) cells += f.cells.size();
  try {
    const AtlasCsv whole = sphtroch::merge_atlas_slices(parsed);
    FUZZ_CHECK(whole.cells.size() == cells);
    FUZZ_CHECK(whole.cells.size() == whole.spec.cells());
    for (std::size_t k = 0; k < whole.cells.size(); ++k)
      FUZZ_CHECK(whole.cells[k].i == k / whole.spec.grid && whole.cells[k].j == k % whole.spec.grid);
    std::ostringstream out;
    sphtroch::write_atlas_csv(out, whole.spec, std::nullopt, whole.cells);
    const AtlasCsv reread = sphtroch::read_atlas_csv(out.str(), "merged.csv");  // must not throw
    FUZZ_CHECK(!reread.shard && same_cells(reread.cells, whole.cells));
    FUZZ_CHECK(reread.spec_comment == whole.spec_comment);
  } catch (const InvalidInput& e) {
    FUZZ_CHECK((e.field() == "slice" || e.field() == "slices") && !e.problem().empty());
  }
  return 0;
}
