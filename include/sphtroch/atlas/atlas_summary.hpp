// sphtroch/atlas/atlas_summary.hpp — the summary `sphtroch atlas` and `atlas-merge` print after the
// map: what was computed, the cells per class and per node count, and every disagreement of the
// census with the report's criteria, each with its nearest boundary. Eigen only.
//
//   const auto cells = sphtroch::compute_atlas(spec, {0, spec.grid}, threads);
//   const sphtroch::AtlasSummary s = sphtroch::summarize_atlas(cells, spec.ratio);
//   sphtroch::AtlasRun run{{0, spec.grid}, std::nullopt, seconds, threads};
//   sphtroch::write_atlas_summary(std::cout, spec, s, sphtroch::listed_disagreements(s, cells), run);
//
// Lines: "atlas: n = ..., grid G x G, a2 in [LO, HI], a3 in [LO, HI], cell centres; <reading>;
// cusp resolution ...", "cells: N (a2 rows B .. E of G)", "classes (root-count census): ...",
// "node counts: K: cells, ... cells; T with a tangency node", "report's criteria: ...",
// "disagreements (census vs report): D (W within BAND rad of a boundary, F elsewhere)", one line
// per listed disagreeing cell, "  ... and M more (agree = 0 in the CSV)" when some are not listed,
// and, when the run was timed, "time: S s on T thread(s), X ms per cell per thread".
// Numbers as report_number writes them (number_text.hpp); the time with printf %.3f.
#pragma once

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/map/closed_form_boundaries.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/census/root_census.hpp"

#include <cstdio>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace sphtroch {

/// Disagreeing cells listed one per line in the summary; the rest are counted (the CSV has all).
constexpr std::size_t kMaxListedDisagreements = 200;

/// How the summarised cells were computed.
struct AtlasRun {
  AtlasRows rows;                    // the a2 rows computed
  std::optional<AtlasShard> shard;   // nullopt: not a shard job
  std::optional<double> seconds;     // wall time; nullopt: not timed (atlas-merge)
  std::size_t threads = 1;
};

/// The first kMaxListedDisagreements disagreeing cells of `s` (indices into `cells`), in order.
inline std::vector<AtlasCell> listed_disagreements(const AtlasSummary& s, const std::vector<AtlasCell>& cells);

/// The summary (see top). `listed`: the first disagreeing cells, at most kMaxListedDisagreements.
inline void write_atlas_summary(std::ostream& out, const AtlasSpec& spec, const AtlasSummary& s,
                                const std::vector<AtlasCell>& listed, const AtlasRun& run);

// ---------------------------------------------------------------------------------------------
// Implementation details follow.

inline std::vector<AtlasCell> listed_disagreements(const AtlasSummary& s, const std::vector<AtlasCell>& cells) {
  std::vector<AtlasCell> listed;
  for (std::size_t k : s.disagreements)
    if (listed.size() < kMaxListedDisagreements) listed.push_back(cells[k]);
  return listed;
}

namespace atlas_report_detail {

inline void head(std::ostream& out, const AtlasSpec& spec, const AtlasSummary& s, const AtlasRun& run) {
  out << "atlas: n = " << spec.ratio.str() << (spec.teeth ? " (teeth " + spec.teeth->str() + ")" : "") << ", grid " << spec.grid << " x " << spec.grid << ", a2 in ["
      << report_number(spec.a2.lo) << ", " << report_number(spec.a2.hi) << "], a3 in [" << report_number(spec.a3.lo) << ", "
      << report_number(spec.a3.hi) << "], cell centres; "
      << (spec.reading.literal ? "literal reading (tolerances 0)"
                       : "default reading (boundary tolerance " + report_number(spec.reading.boundary_tolerance) +
                             " rad, tangency " + report_number(kTangencyTolerance) + ")")
      << "; cusp resolution " << report_number(kCuspResolution) << " rad"
      << "\n";
  out << "cells: " << s.cells << " (";
  if (run.shard) out << "shard " << run.shard->index << "/" << run.shard->count << ": ";
  out << "a2 rows " << run.rows.begin << " .. " << (run.rows.end == 0 ? 0 : run.rows.end - 1) << " of " << spec.grid
      << ")\n";
}

inline void counts(std::ostream& out, const AtlasSpec& spec, const AtlasSummary& s) {
  out << "classes (root-count census): simple curve " << s.by_class[0] << ", nodes " << s.by_class[1] << ", cusps "
      << s.by_class[2] << ", nodes and cusps " << s.by_class[3] << "\n";
  out << "node counts:";
  bool first = true;
  for (const auto& [n, c] : s.by_nodes) {
    out << (first ? " " : ", ") << n << ": " << c;
    first = false;
  }
  out << " cells; " << s.with_tangencies << " with a tangency node\n";
  const bool n1 = spec.ratio == Ratio(1), n2 = spec.ratio == Ratio(2);
  if (n1 || n2)
    out << "report's criteria: " << (n1 ? "Eq. 24" : "Eqs. 43, 46") << " and the pitch-cone criterion, predicted for "
        << s.predicted << " cells\n";
  else
    out << "report's criteria: the pitch-cone criterion (cusps) only; no node criterion for n = " << spec.ratio.str()
        << " (analytic_nodes, agree = NA)\n";
}

inline void disagreements(std::ostream& out, const AtlasSpec& spec, const AtlasSummary& s,
                          const std::vector<AtlasCell>& listed) {
  out << "disagreements (census vs report): " << s.disagreement_count << " ("
      << s.disagreement_count - s.disagreements_off_boundaries << " within " << report_number(kAtlasBoundaryBand)
      << " rad of a boundary, " << s.disagreements_off_boundaries << " elsewhere)\n";
  for (const AtlasCell& c : listed) {
    const NearestBoundary b = nearest_boundary(c.a2, c.a3, spec.ratio);
    out << "  i=" << c.i << " j=" << c.j << " a2=" << report_number(c.a2) << " a3=" << report_number(c.a3) << ": census "
        << c.nodes << " node(s), " << c.cusps << " cusp(s); report "
        << (c.analytic_nodes ? std::to_string(*c.analytic_nodes) : std::string("NA")) << " node(s), "
        << c.analytic_cusps << " cusp(s); nearest boundary " << b.name << " at " << report_number(b.distance) << " rad\n";
  }
  if (s.disagreement_count > listed.size())
    out << "  ... and " << s.disagreement_count - listed.size() << " more (agree = 0 in the CSV)\n";
}

inline void timing(std::ostream& out, const AtlasSummary& s, const AtlasRun& run) {
  if (!run.seconds) return;
  const double seconds = *run.seconds;
  const double per_cell = s.cells ? seconds * static_cast<double>(run.threads) / static_cast<double>(s.cells) : 0.0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "time: %.3f s on %zu thread(s), %.4f ms per cell per thread\n", seconds, run.threads,
                per_cell * 1e3);
  out << buf;
}

}  // namespace atlas_report_detail

inline void write_atlas_summary(std::ostream& out, const AtlasSpec& spec, const AtlasSummary& s,
                                const std::vector<AtlasCell>& listed, const AtlasRun& run) {
  atlas_report_detail::head(out, spec, s, run);
  atlas_report_detail::counts(out, spec, s);
  atlas_report_detail::disagreements(out, spec, s, listed);
  atlas_report_detail::timing(out, s, run);
}

}  // namespace sphtroch
