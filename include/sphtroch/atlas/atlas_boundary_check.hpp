// sphtroch/atlas/atlas_boundary_check.hpp — is every class change of the atlas explained by a boundary?
// For each pair of neighbouring cells (same a2 column, consecutive a3; or same a3 row, consecutive
// a2) whose classes differ (curve class or node count), checks that a curve of the boundary set
// (boundary_events.hpp: pitch cones, poles, self-tangency loci) passes between their centres. Eigen
// only.
//
//   AtlasBoundaryCheck c = check_atlas_boundaries(spec, cells, threads);
//   c.class_changes;  c.uncrossed.size();   // the latter must be 0
//
// Decision rule (exact up to the events' accuracy, 1e-12 rad):
//  * vertical pair (a2_i; a3_j, a3_j+1): crossed iff an event of boundary_set(a2_i) lies in
//    [a3_j - band, a3_j+1 + band], band = kAtlasBoundaryBand (the centres and the closed-form
//    events are rounded differently: a3 = pi - a2 in double vs in long double);
//  * horizontal pair (a2_i, a2_i+1; a3_j): crossed iff, for some boundary (a kind and name; a
//    tangency locus is identified by its (label, m)), the number of its events below a3_j differs
//    between the two columns — i.e. a curve of that boundary passes between the two centres (or
//    ends between them below a3_j, on a pitch cone).
// A cell the atlas read ON a boundary (its centre within kAtlasBoundaryBand of an event of its
// column, e.g. on the diagonal a3 = a2) can differ from both neighbours: every pair with such a
// cell counts as crossed (the boundary passes through the cell's centre).
#pragma once

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/core/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// Walk from a2 = lo to hi at fixed a3 = h in steps of at most kAtlasWalkStep (at most
/// kAtlasWalkSamples): true when the events below h (per boundary) change from one step to the
/// next, i.e. a boundary crosses a3 = h between the columns. Used for the horizontal pairs whose
/// end columns alone do not decide it (a coarse grid: a locus may begin or end between them).
constexpr double kAtlasWalkStep = 1e-2;
constexpr std::size_t kAtlasWalkSamples = 256;
inline bool crossed_between(double lo, double hi, double h, const Ratio& n) {
  const std::size_t steps =
      std::min(kAtlasWalkSamples, std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil((hi - lo) / kAtlasWalkStep))));
  auto keyed_below = [&](double a2) {
    std::map<std::string, int> k;
    for (const BoundaryEvent& e : boundary_set(a2, n).events)
      if (e.a3 < h) ++k[e.kind == BoundaryEventKind::tangency ? "t" + std::to_string(e.label) + ":" + std::to_string(e.m) : e.name];
    return k;
  };
  std::map<std::string, int> previous = keyed_below(lo);
  for (std::size_t s = 1; s <= steps; ++s) {
    std::map<std::string, int> current = keyed_below(lo + (hi - lo) * static_cast<double>(s) / static_cast<double>(steps));
    if (current != previous) return true;
    previous = std::move(current);
  }
  return false;
}

struct AtlasBoundaryCheck {
  std::size_t class_changes = 0;                             // neighbouring pairs of different class
  std::vector<std::pair<std::size_t, std::size_t>> uncrossed;  // indices into cells of pairs not crossed
};

/// The check over the cells of compute_atlas (all rows or a shard's rows, row-major). Computes
/// one boundary_set per a2 column (on `threads` threads).
inline AtlasBoundaryCheck check_atlas_boundaries(const AtlasSpec& spec, const std::vector<AtlasCell>& cells,
                                                 std::size_t threads = 1) {
  AtlasBoundaryCheck out;
  const std::size_t g = spec.grid;
  if (cells.empty()) return out;
  const std::size_t i0 = cells.front().i, columns = cells.size() / g;
  std::vector<std::vector<BoundaryEvent>> events(columns);
  parallel_for(columns, threads, [&](std::size_t c) { events[c] = boundary_set(spec.a2_at(i0 + c), spec.ratio).events; });
  auto key = [](const BoundaryEvent& e) {
    return e.kind == BoundaryEventKind::tangency ? "t" + std::to_string(e.label) + ":" + std::to_string(e.m) : e.name;
  };
  auto below = [&](std::size_t c, double h) {
    std::map<std::string, int> k;
    for (const BoundaryEvent& e : events[c])
      if (e.a3 < h) ++k[key(e)];
    return k;
  };
  // A cell centre within kAtlasBoundaryBand of an event of its column is read on that boundary.
  auto on = [&](std::size_t c, double h) {
    return std::any_of(events[c].begin(), events[c].end(),
                       [&](const BoundaryEvent& e) { return std::abs(e.a3 - h) <= kAtlasBoundaryBand; });
  };
  auto differ = [](const AtlasCell& a, const AtlasCell& b) {
    return a.numeric_class() != b.numeric_class() || a.nodes != b.nodes;
  };
  for (std::size_t c = 0; c < columns; ++c) {
    for (std::size_t j = 0; j < g; ++j) {
      const std::size_t k = c * g + j;
      if (j + 1 < g && differ(cells[k], cells[k + 1])) {
        ++out.class_changes;
        const double lo = cells[k].a3, hi = cells[k + 1].a3;
        const bool crossed = std::any_of(events[c].begin(), events[c].end(),
                                         [&](const BoundaryEvent& e) { return e.a3 >= lo - kAtlasBoundaryBand && e.a3 <= hi + kAtlasBoundaryBand; });
        if (!crossed) out.uncrossed.emplace_back(k, k + 1);
      }
      if (c + 1 < columns && differ(cells[k], cells[k + g])) {
        ++out.class_changes;
        const double h = cells[k].a3;
        if (!on(c, h) && !on(c + 1, h) && below(c, h) == below(c + 1, h) &&
            !crossed_between(spec.a2_at(i0 + c), spec.a2_at(i0 + c + 1), h, spec.ratio))
          out.uncrossed.emplace_back(k, k + g);
      }
    }
  }
  return out;
}

/// "class changes between neighbouring cells: N, not crossed by a boundary: K" and the first
/// `listed` uncrossed pairs, one line each.
inline void write_atlas_boundary_check(std::ostream& out, const AtlasBoundaryCheck& c, const std::vector<AtlasCell>& cells,
                                       std::size_t listed = 20) {
  out << "class changes between neighbouring cells: " << c.class_changes
      << "; not crossed by a boundary of the boundary set (pitch cones, poles, self-tangency loci): "
      << c.uncrossed.size() << "\n";
  for (std::size_t k = 0; k < c.uncrossed.size() && k < listed; ++k) {
    const AtlasCell &a = cells[c.uncrossed[k].first], &b = cells[c.uncrossed[k].second];
    out << "  (a2=" << number_text(a.a2) << ", a3=" << number_text(a.a3) << "): " << a.nodes << " node(s) vs (a2="
        << number_text(b.a2) << ", a3=" << number_text(b.a3) << "): " << b.nodes << " node(s)\n";
  }
  if (c.uncrossed.size() > listed) out << "  ... and " << c.uncrossed.size() - listed << " more\n";
}

/// Whether the counts of an atlas are certified (the atlas's form of certified_census.hpp): each
/// cell's root-count census agrees with the report's criteria where they give a count (n = 1, 2;
/// the pitch-cone cusps for every n), and every class change between neighbouring cells is
/// crossed by a curve of the independently computed boundary set (`check`; nullptr when it was
/// not run, e.g. atlas-merge). Returns "" when certified, else why not, in words.
inline std::string atlas_uncertified(const AtlasSummary& s, const AtlasBoundaryCheck* check) {
  std::string why;
  if (s.disagreement_count > 0) why = std::to_string(s.disagreement_count) + " cell(s) where census and report disagree";
  if (check && !check->uncrossed.empty())
    why += (why.empty() ? "" : "; ") + std::to_string(check->uncrossed.size()) +
           " class change(s) not crossed by a boundary";
  return why;
}

/// "certified: yes (...)" or "certified: NO — <why>", one line.
inline void write_atlas_certificate(std::ostream& out, const AtlasSummary& s, const AtlasBoundaryCheck* check) {
  const std::string why = atlas_uncertified(s, check);
  if (why.empty())
    out << "certified: yes (census = report in every cell where it predicts"
        << (check ? "; every class change crossed by a boundary" : "") << ")\n";
  else
    out << "certified: NO — " << why << "\n";
}

}  // namespace sphtroch
