// sphtroch/atlas/atlas.hpp — the classification map over (a2, a3) for one gear ratio: per cell of a
// G x G grid, the node census (crossings, tangencies) and the cusps, side by side with the class
// the report's criteria predict (Eq. 24 for n = 1, Eqs. 43/46 for n = 2, the pitch-cone cusp
// criterion for every n). Eigen only (no CGAL): the census per cell is the root-count census
// (root_census.hpp), which needs no sampling.
//
//   using namespace sphtroch;
//   AtlasSpec spec;  spec.ratio = Ratio(2);  spec.grid = 128;       // a2, a3 in (0, pi)
//   std::vector<AtlasCell> cells = compute_atlas(spec, {0, spec.grid}, 2);  // rows 0..127, 2 threads
//   cells[i * 128 + j].nodes;                   // a2 = spec.a2_at(i), a3 = spec.a3_at(j)
//   cells[k].agree;                             // census == report (n = 1, 2), nullopt otherwise
//   AtlasRows slice = shard_rows(spec.grid, AtlasShard{1, 4});   // rows of job 1 of 4
//
// Decisions
//  (1) Cells are sampled at their centres: a = lo + (k + 1/2)(hi - lo)/G, k = 0 .. G-1, so no
//      sample is 0 or pi. With equal a2 and a3 ranges the diagonal cells (i = j) lie exactly on
//      a3 = a2 and the anti-diagonal ones (i + j = G - 1) within rounding on a3 = pi - a2:
//      there the curve passes through a pole, which for |p| >= 2 is a node (Table 1 rows d, g).
//      They are boundary cases, analysed as below, and they agree with the report.
//  (2) Each cell is analysed exactly as `sphtroch classify` analyses one train (classification.hpp):
//      the default reading snaps an input within spec.reading.boundary_tolerance of a boundary onto it
//      (boundary_snap.hpp) and uses the tangency tolerance kTangencyTolerance; spec.reading.literal
//      analyses the doubles as given (tolerances 0). Nodes and their kinds come from
//      root_census() of the snapped train; cusps from pitch_cone_cusps(snapped, kCuspResolution),
//      as classify counts them. The report's prediction is classify_analytic(snapped, tolerance).
//  (3) `agree` compares node and cusp counts with the report's prediction for n = 1, 2 and is
//      nullopt for every other n (the report predicts no node count there); `cusps_agree`
//      compares the cusp counts for every n.
//  (4) Cells are stored row-major, a2 index i major, a3 index j minor; compute_atlas writes each
//      result at its index, so the output does not depend on the number of threads.
//  (5) Shards: job I of K (1 <= I <= K <= G) owns the contiguous rows
//      [floor((I-1) G / K), floor(I G / K)); the K slices partition the rows.
//
// Contracts
//  REQUIRES (else InvalidInput naming the field): 1 <= grid <= kAtlasMaxGrid;
//  0 <= lo < hi <= pi for both ranges; 1 <= threads <= kAtlasMaxThreads; 1 <= I <= K <= grid.
//  compute_atlas never throws for a valid spec (root_census and the criteria are total); an
//  exception thrown in a worker is rethrown on the calling thread.
#pragma once

#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/closed_form_boundaries.hpp"
#include "sphtroch/map/boundary_snap.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/core/shard.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/census/root_census.hpp"
#include "sphtroch/census/root_classification.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/io/parse.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// Largest grid side: 4096^2 = 16.8 M cells (about 1 GB of cells held at once; shard above that).
constexpr std::size_t kAtlasMaxGrid = 4096;
/// A disagreement within this distance (in a3, radians) of a boundary of atlas_boundary_kinds is a
/// boundary case: the census and the criterion read an equality that holds up to rounding
/// differently (e.g. --literal on the anti-diagonal, where a2 + a3 rounds to pi in double but not
/// in the census's long double). Between the boundary tolerance 1e-10 and the 1e-9 size below
/// which a near-cusp loop cannot be told from a cusp (criteria.hpp, kBoundaryTolerance).
constexpr double kAtlasBoundaryBand = 1e-9;
/// Largest thread count accepted.
constexpr std::size_t kAtlasMaxThreads = 1024;

struct AtlasSpec {
  Ratio ratio{2};
  std::optional<Teeth> teeth;  // the tooth counts n was given as (echoed next to n); ratio == teeth->ratio()
  std::size_t grid = 128;  // G: G x G cells
  AngleRange a2;           // horizontal axis, index i
  AngleRange a3;           // vertical axis, index j
  Reading reading;         // default, or literal: the doubles as given (core/reading.hpp)
  /// The boundary reading of every cell (closed_form_boundaries.hpp).

  std::size_t cells() const { return grid * grid; }
  /// Cell centre lo + (k + 1/2)(hi - lo)/G.
  double a2_at(std::size_t i) const { return centre(a2, i); }
  double a3_at(std::size_t j) const { return centre(a3, j); }
  /// Throws InvalidInput ("grid", "a2", "a3") unless the contract holds.
  void validate() const;

 private:
  double centre(const AngleRange& r, std::size_t k) const {
    return r.lo + (static_cast<double>(k) + 0.5) * (r.hi - r.lo) / static_cast<double>(grid);
  }
};

/// The class of a curve (root_classification.hpp); the atlas's old name for it.
using AtlasClass = CurveClass;
inline AtlasClass atlas_class(std::size_t nodes, std::size_t cusps) { return curve_class(nodes, cusps); }

struct AtlasCell {
  std::uint32_t i = 0, j = 0;  // a2 index, a3 index
  double a2 = 0.0, a3 = 0.0;   // the cell centre, radians (as given to the census)
  std::uint32_t nodes = 0;     // node points (crossings + tangencies), root-count census
  std::uint32_t crossings = 0;
  std::uint32_t tangencies = 0;
  std::uint32_t cusps = 0;
  std::optional<std::uint32_t> analytic_nodes;  // the report's count; nullopt unless n = 1, 2
  std::uint32_t analytic_cusps = 0;             // pitch-cone criterion (every n)
  std::optional<bool> agree;                    // nodes and cusps equal the report's (n = 1, 2)
  bool cusps_agree = true;                      // cusps equal the pitch-cone criterion's

  AtlasClass numeric_class() const { return atlas_class(nodes, cusps); }
};

/// A half-open range of a2 rows [begin, end).
struct AtlasRows {
  std::size_t begin = 0, end = 0;
};

/// Job `index` of `count` (1-based): core/shard.hpp's Shard.
using AtlasShard = Shard;

/// Rows of one shard (decision 5). Throws InvalidInput("shard") unless 1 <= index <= count <= grid.
inline AtlasRows shard_rows(std::size_t grid, const AtlasShard& shard);

/// One cell (decision 2). REQUIRES: spec valid, i, j < grid.
inline AtlasCell atlas_cell(const AtlasSpec& spec, std::size_t i, std::size_t j);

/// Progress callback: (cells done, cells total); called on the calling thread only, about
/// every 0.1 s and once at the end.
using AtlasProgress = ParallelProgress;

/// Every cell of rows [rows.begin, rows.end), row-major, on `threads` worker threads.
/// REQUIRES: spec valid, rows.begin <= rows.end <= grid, 1 <= threads <= kAtlasMaxThreads.
inline std::vector<AtlasCell> compute_atlas(const AtlasSpec& spec, AtlasRows rows, std::size_t threads,
                                            const AtlasProgress& progress = {});

/// Counts over a set of cells.
struct AtlasSummary {
  std::size_t cells = 0;
  std::size_t by_class[4] = {0, 0, 0, 0};            // indexed by AtlasClass
  std::map<std::uint32_t, std::size_t> by_nodes;     // node count -> cells
  std::size_t with_tangencies = 0;                   // cells with a tangency node
  std::size_t predicted = 0;                         // cells with a node prediction (n = 1, 2)
  std::vector<std::size_t> disagreements;            // indices: agree == false or cusps differ
  std::size_t disagreement_count = 0;                // all of them (disagreements may keep fewer)
  std::size_t disagreements_off_boundaries = 0;      // of those, farther than kAtlasBoundaryBand
};
inline AtlasSummary summarize_atlas(const std::vector<AtlasCell>& cells, const Ratio& ratio);

/// Adds one cell, the k-th of the cells summarised (for a stream of cells, in bounded memory:
/// indices of disagreeing cells are kept only while fewer than max_kept are; disagreement_count
/// counts them all).
inline void add_to_summary(AtlasSummary& s, const AtlasCell& c, std::size_t k, const Ratio& ratio,
                           std::size_t max_kept = static_cast<std::size_t>(-1));


// =============================================================================================
// Implementation details follow.
// =============================================================================================

inline void AtlasSpec::validate() const {
  if (grid < 1 || grid > kAtlasMaxGrid)
    throw InvalidInput("grid", std::to_string(grid), "outside the valid range",
                       "integer 1 .. " + std::to_string(kAtlasMaxGrid));
  const double pi = Constants<double>::pi();
  auto check = [&](const AngleRange& r, const char* field) {
    if (!(std::isfinite(r.lo) && std::isfinite(r.hi) && r.lo >= 0.0 && r.lo < r.hi && r.hi <= pi))
      throw InvalidInput(field, number_text(r.lo) + ":" + number_text(r.hi), "not a valid range",
                         "LO:HI with 0 <= LO < HI <= pi");
  };
  check(a2, "a2");
  check(a3, "a3");
  if (teeth && !(teeth->ratio() == ratio))
    throw InvalidInput("teeth", teeth->str(), "not the ratio n = " + ratio.str(), "tooth counts ZS:ZP with ZS/ZP = n");
  if (!(reading.boundary_tolerance >= 0.0))
    throw InvalidInput("boundary_tolerance", report_number(reading.boundary_tolerance), "negative", ">= 0 radians");
  // The carrier-twist bounds up front, for every row: a row whose pitch cone is ill-defined would
  // refuse the cells near it (GearTrain), so the whole range is refused instead.
  for (std::size_t i = 0; i < grid; ++i) GearTrain::on_cone(a2_at(i), A3Reference::pitch_cone, 0.0, ratio);
  check_census_cost(ratio);  // every cell runs a root census
}

inline AtlasRows shard_rows(std::size_t grid, const AtlasShard& shard) {
  if (!(shard.index >= 1 && shard.index <= shard.count && shard.count <= grid))
    throw InvalidInput("shard", shard.str(), "outside the valid range", "I/K with 1 <= I <= K <= grid (" + std::to_string(grid) + ")");
  const auto [begin, end] = shard_range(grid, shard);
  return AtlasRows{begin, end};
}

inline AtlasCell atlas_cell(const AtlasSpec& spec, std::size_t i, std::size_t j) {
  SPHTROCH_ASSERT(i < spec.grid && j < spec.grid, "atlas_cell: index outside the grid");
  AtlasCell cell;
  cell.i = static_cast<std::uint32_t>(i);
  cell.j = static_cast<std::uint32_t>(j);
  cell.a2 = spec.a2_at(i);
  cell.a3 = spec.a3_at(j);
  const RootClassification c = classify_roots(GearTrain(cell.a2, cell.a3, spec.ratio), spec.reading);
  cell.crossings = static_cast<std::uint32_t>(c.crossings);
  cell.tangencies = static_cast<std::uint32_t>(c.tangencies);
  cell.nodes = static_cast<std::uint32_t>(c.nodes);
  cell.cusps = static_cast<std::uint32_t>(c.cusps);
  cell.analytic_cusps = static_cast<std::uint32_t>(c.analytic_cusps);
  cell.cusps_agree = cell.cusps == cell.analytic_cusps;
  if (c.analytic_nodes) {
    cell.analytic_nodes = static_cast<std::uint32_t>(*c.analytic_nodes);
    cell.agree = c.agrees_with_report();
  }
  return cell;
}

inline std::vector<AtlasCell> compute_atlas(const AtlasSpec& spec, AtlasRows rows, std::size_t threads,
                                            const AtlasProgress& progress) {
  spec.validate();
  SPHTROCH_ASSERT(rows.begin <= rows.end && rows.end <= spec.grid, "compute_atlas: rows outside the grid");
  if (threads < 1 || threads > kAtlasMaxThreads)
    throw InvalidInput("threads", std::to_string(threads), "outside the valid range",
                       "integer 1 .. " + std::to_string(kAtlasMaxThreads));
  const std::size_t g = spec.grid;
  const std::size_t total = (rows.end - rows.begin) * g;
  std::vector<AtlasCell> cells(total);
  // Each result goes to its index: the cells do not depend on the thread count.
  constexpr std::size_t kChunk = 64;
  parallel_for(total, threads, [&](std::size_t k) { cells[k] = atlas_cell(spec, rows.begin + k / g, k % g); }, kChunk,
               progress);
  return cells;
}

inline void add_to_summary(AtlasSummary& s, const AtlasCell& c, std::size_t k, const Ratio& ratio,
                           std::size_t max_kept) {
  ++s.cells;
  ++s.by_class[static_cast<int>(c.numeric_class())];
  ++s.by_nodes[c.nodes];
  if (c.tangencies > 0) ++s.with_tangencies;
  if (c.analytic_nodes) ++s.predicted;
  if ((c.agree && !*c.agree) || !c.cusps_agree) {
    ++s.disagreement_count;
    if (s.disagreements.size() < max_kept) s.disagreements.push_back(k);
    if (nearest_boundary(c.a2, c.a3, ratio).distance > kAtlasBoundaryBand) ++s.disagreements_off_boundaries;
  }
}

inline AtlasSummary summarize_atlas(const std::vector<AtlasCell>& cells, const Ratio& ratio) {
  AtlasSummary s;
  for (std::size_t k = 0; k < cells.size(); ++k) add_to_summary(s, cells[k], k, ratio);
  return s;
}


}  // namespace sphtroch
