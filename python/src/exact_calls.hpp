// python/src/exact_calls.hpp — the module's calls into the CGAL part of the library (compiled
// in exact_calls.cpp only, so that module.cpp, the bindings, parse no CGAL). Plain C++: no
// Python objects here, so every call may run with the GIL released. Errors: InvalidInput.
#pragma once

#include "sphtroch/io/chain_text.hpp"  // ChainText: a chain as typed (the chain caption's angles)
#include "sphtroch/io/train_text.hpp"  // TrainText: the angles as text, as `classify --json` reports them

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/parallel_for.hpp"  // ParallelProgress
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/draw/svg_plot.hpp"  // PlotOptions (Eigen only)
#include "sphtroch/synthesis/path_fit.hpp"  // FitOptions (Eigen only)

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sphtroch::python {

/// `sphtroch classify --json` of `train` (classification_output.hpp, the printer the CLI uses), as JSON
/// text. literal: analyse the doubles as given; census_samples: 0 = the default count.
std::string classification_json_text(const TrainText& text, const GearTrain& train, bool literal,
                                      std::size_t census_samples);

/// {"nodes": [...], "cusps": [...], "certified", "polyline_nodes", "root_nodes", "stopped"}: the
/// lists as in that JSON, from the certified node census and the cusps (what `sphtroch nodes`
/// computes), and its certificate.
std::string nodes_and_cusps_json_text(const TrainText& text, const GearTrain& train, bool literal,
                                      std::size_t census_samples);

/// `sphtroch tolerance --json` of `train` and the box (tolerance_output.hpp), with `samples`
/// Monte Carlo trains (0: none) drawn with `seed`, reported to `progress`, as JSON text.
std::string tolerance_json_text(const TrainText& text, const GearTrain& train, double da2, double da3, double dphase,
                                std::size_t samples, std::uint64_t seed, const ParallelProgress& progress);

/// The certified margin of `train` (topology_margin.hpp) as the JSON of tolerance's "margin".
std::string topology_margin_json_text(const GearTrain& train);

/// `sphtroch classify` (text) of `train`: the report write_classification_text prints.
std::string classification_report_text(const TrainText& text, const GearTrain& train, bool literal,
                                       std::size_t census_samples);

/// A scene (exact/scene.hpp, the `sphtroch scene` format) run without files: JSON text
/// {"trains": [{"name", "outputs": {effect: the bytes `sphtroch scene` writes to its path},
/// "uncertified" ("" or the CLI's reason for exit status 3), "explanation": scene_explanation_json}]}. Throws SceneError (an InvalidInput).
std::string scene_json_text(const std::string& scene_text);

/// `sphtroch plot` of `train` as SVG text (the certified census; an uncertified one says so in the
/// caption, as the CLI's picture does), drawn with `options` (view, size, labels).
std::string plot_svg_text(const TrainText& text, const GearTrain& train, bool literal, std::size_t census_samples,
                          const PlotOptions& options);

/// Chain.classify(): `sphtroch chain classify --json` of the chain (classify_chain, chain_census_json),
/// the certified field inside. Chain.report(): the text `sphtroch chain classify` prints.
std::string chain_classification_json_text(const RotationChain& chain);
std::string chain_classification_report_text(const RotationChain& chain);
/// Chain.boundaries(vary): `sphtroch chain boundaries --vary VARY --json` (chain_family_events).
std::string chain_boundaries_json_text(const RotationChain& chain, const std::string& vary);
/// Chain.svg(): `sphtroch chain plot`'s SVG (chain_picture_svg of classify_chain's census), its
/// caption's angles as in `typed` (the Chain's texts: "pi/2" as given, a float as number_text).
std::string chain_plot_svg_text(const RotationChain& chain, const PlotOptions& options, const ChainText& typed);

/// Python's classify_roots(): the root-count classification (Reading{literal}) as
/// root_classification_json (classification_output.hpp), JSON text.
std::string root_classification_json_text(const GearTrain& train, bool literal);

/// `sphtroch synth points --json`, or with `text` what `sphtroch synth points` prints
/// (precision_points_output.hpp): every train of each ratio through the three points (five with
/// free_axis: `threads` searches at once), with its census. InvalidInput "points" for bad points.
/// `progress` (if set) is called on the calling thread as progress(ratios done, ratios.size()),
/// before the first and after each ratio; what it throws stops the call.
std::string precision_points_report(const std::vector<Vector3d>& points, const std::vector<Ratio>& ratios,
                                    const std::string& json_fields, const TeethSpec& teeth, bool free_axis,
                                    std::size_t threads, bool text, const ParallelProgress& progress);

/// `sphtroch synth fit --json`, or with `text` what `sphtroch synth fit` prints (path_fit_output.hpp):
/// ranked candidates of the ratios for the path's points, each confirmed by classify. InvalidInput
/// "points", "nodes", "cusps", "n". `progress` as for precision_points_report (ratios done).
std::string fit_report(const std::vector<Vector3d>& points, const std::vector<Ratio>& ratios, const FitOptions& options,
                       const std::string& json_fields, const TeethSpec& teeth, bool text, const ParallelProgress& progress);

/// The exact self-crossings of a polyline, as `sphtroch crossings` reports them.
struct CrossingsResult {
  std::size_t vertices = 0, crossings = 0, touchings = 0, candidate_pairs = 0, predicates = 0;
  std::vector<std::int64_t> pairs;  // with_pairs: k rows (i, j), i < j edge indices, both kinds, sorted
  std::vector<std::uint8_t> kinds;  // per row: an ArcContact (crossing, touching or overlap)
  double seconds_search = 0.0;      // wall time of the search (validation included)
};

/// "crossing", "touching", "overlap" for the codes in CrossingsResult::kinds.
std::string contact_name(std::uint8_t kind);

/// REQUIRES: xyz holds n packed rows x,y,z that do not change during the call (read in place).
/// Counts only (count_self_crossings, memory O(n)) unless with_pairs. Throws InvalidInput with
/// field "points" for an invalid polyline (fewer than 3 / 2 vertices, a zero or non-finite row,
/// consecutive rows equal or antipodal), "max_crossings" / "max_work" when a limit stops the search.
CrossingsResult self_crossings(const double* xyz, std::size_t n, bool closed, bool with_pairs, std::size_t max_crossings,
                               std::size_t max_work);

}  // namespace sphtroch::python
