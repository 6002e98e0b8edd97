// sphtroch/sphtroch.hpp — umbrella header: every header the linked CMake components provide, by layer.
//   sphtroch::sphtroch (Eigen, nlohmann-json; header-only): core/ (the train, the curve, sampling), io/ (numbers, parsing,
//     CSV/.npy readers and writers; POSIX), draw/ (SVG), map/ (closed-form boundaries, the report's
//     criteria, the root function, the boundary events), census/ (the root census), atlas/,
//     synthesis/ (identify, path distance, path fit), machine/ (clinostats: the gravity path, its
//     gear train, window means, the worst window mean, the time to epsilon, the report and its JSON),
//     wrist/'s model, targets, typed options and reports, the cap's and the fold atlas's results and reports, the
//     regions' grid, checks, reports and picture (geared
//     wrists with 2 or 3 motors).
//   sphtroch::healpix (HEALPix's C++ library; defines SPHTROCH_HAVE_HEALPIX): adds machine/dwell_map.hpp.
//   sphtroch::urdf (urdfdom; defines SPHTROCH_HAVE_URDF): adds io/urdf_chain.hpp (rotation chains read
//     from URDF; io/urdf_writer.hpp writes them without it).
//   sphtroch::interval (CGAL's headers only; defines SPHTROCH_HAVE_INTERVAL): adds interval/ (interval
//     arithmetic, interval 3-vectors, the one Krawczyk step, certified root isolation), chain/ (the
//     certified census of rotation chains and its events along a family; chain/chain_events.hpp, the
//     events' types and closed forms, is Eigen only), tolerance/ (the certified topology margin,
//     box topology and node enclosures of a tolerance box), synthesis/'s precision points
//     (fixed frame, free axis) and wrist/'s certified inverse kinematics (every solution on the
//     motor torus), fold function, fold-free cap about home and fold atlas.
//   sphtroch::exact (CGAL, GMP, MPFR, nlohmann-json; defines SPHTROCH_HAVE_EXACT and links
//     sphtroch::interval): adds exact/: the exact crossing search, the polyline census, classify(),
//     the lazy Analysis, the classification output (text/JSON), scenes, and the reports of the
//     inverse design (each train confirmed by classify()).
//   sphtroch::mpfr (defines SPHTROCH_HAVE_MPFR): adds the mpfr::mpreal Scalar (exact/mpreal_support.hpp).
//   sphtroch::step (OpenCASCADE; defines SPHTROCH_HAVE_STEP): adds cad/: the path as a STEP B-spline.
// Separate mode (SPHTROCH_SEPARATE_EXACT, classify.hpp): of exact/ the umbrella then gives only
// the declarations of classify(), tolerance_report(), precision_points_with_census() and
// fit_with_census() with their result types and formats (classify.hpp, tolerance.hpp,
// synthesis.hpp), none of the solvers of interval/, chain/, tolerance/, synthesis/ or wrist/, and
// parses no CGAL header; a file that needs more of exact/ includes those headers itself and pays
// CGAL's parse.
#pragma once

#if defined(SPHTROCH_HAVE_MPFR)
#include "sphtroch/exact/mpreal_support.hpp"  // first: Eigen's MPRealSupport must precede other Eigen use
#endif

#include "sphtroch/version.hpp"

#include "sphtroch/core/arc_crossing_point.hpp"
#include "sphtroch/core/cone_distance.hpp"
#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/kinematics.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/core/parameters.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/reading.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/shard.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/core/work.hpp"

#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/input_file.hpp"
#include "sphtroch/io/node_csv.hpp"
#include "sphtroch/io/npy.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/output_file.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/polyline_input.hpp"
#include "sphtroch/io/ratio_set.hpp"
#include "sphtroch/io/trace_output.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/io/urdf_writer.hpp"
#include "sphtroch/io/xml_shape.hpp"
#if defined(SPHTROCH_HAVE_URDF)
#include "sphtroch/io/urdf_chain.hpp"
#endif

#include "sphtroch/draw/curve_view.hpp"
#include "sphtroch/draw/diverging_colour.hpp"
#include "sphtroch/draw/dwell_raster.hpp"
#include "sphtroch/draw/mark_density.hpp"
#include "sphtroch/draw/ratio_scale.hpp"
#include "sphtroch/draw/svg.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/draw/text_layout.hpp"

#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/map/boundary_events_output.hpp"
#include "sphtroch/map/boundary_snap.hpp"
#include "sphtroch/map/closed_form_boundaries.hpp"
#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/extremes_and_symmetry.hpp"
#include "sphtroch/map/map_cells.hpp"
#include "sphtroch/map/root_function.hpp"

#include "sphtroch/census/node_assembly.hpp"
#include "sphtroch/census/node_json.hpp"
#include "sphtroch/census/node_sets.hpp"
#include "sphtroch/census/polyline_census_result.hpp"
#include "sphtroch/census/refinement.hpp"
#include "sphtroch/census/root_census.hpp"
#include "sphtroch/census/root_classification.hpp"
#include "sphtroch/census/tangency_refinement.hpp"

#include "sphtroch/chain/chain_events.hpp"  // Eigen only; the rest of chain/ needs sphtroch::interval

#include "sphtroch/tolerance/tolerance_report.hpp"  // the results, no CGAL; the solvers need sphtroch::interval
#include "sphtroch/tolerance/tolerance_types.hpp"
#include "sphtroch/interval/isolated_roots.hpp"  // a plain result type
#include "sphtroch/synthesis/precision_solution.hpp"

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/atlas/atlas_boundary_check.hpp"
#include "sphtroch/atlas/atlas_csv.hpp"
#include "sphtroch/atlas/atlas_summary.hpp"
#include "sphtroch/atlas/atlas_svg.hpp"

#include "sphtroch/synthesis/identify.hpp"
#include "sphtroch/synthesis/fit_grid.hpp"
#include "sphtroch/synthesis/path_distance.hpp"
#include "sphtroch/synthesis/path_fit.hpp"
#include "sphtroch/atlas/atlas_slices.hpp"

#include "sphtroch/machine/clinostat.hpp"
#include "sphtroch/machine/clinostat_design.hpp"
#include "sphtroch/machine/clinostat_design_output.hpp"
#include "sphtroch/machine/clinostat_plot.hpp"
#include "sphtroch/machine/clinostat_report.hpp"
#include "sphtroch/machine/clinostat_text.hpp"
#include "sphtroch/machine/clinostat_train.hpp"
#include "sphtroch/machine/dwell_map_result.hpp"
#include "sphtroch/machine/gravity_series.hpp"
#include "sphtroch/machine/rpm.hpp"
#include "sphtroch/machine/running_mean.hpp"
#include "sphtroch/machine/time_to_epsilon.hpp"
#include "sphtroch/machine/window_band.hpp"
#include "sphtroch/machine/worst_window_mean.hpp"
#if defined(SPHTROCH_HAVE_HEALPIX)
#include "sphtroch/machine/dwell_map.hpp"
#endif

#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_atlas_output.hpp"
#include "sphtroch/wrist/wrist_atlas_result.hpp"
#include "sphtroch/wrist/wrist_cap_output.hpp"
#include "sphtroch/wrist/wrist_cap_result.hpp"
#include "sphtroch/wrist/wrist_ik_output.hpp"
#include "sphtroch/wrist/wrist_ik_result.hpp"
#include "sphtroch/wrist/wrist_regions_checks.hpp"
#include "sphtroch/wrist/wrist_regions_output.hpp"
#include "sphtroch/wrist/wrist_regions_result.hpp"
#include "sphtroch/wrist/wrist_regions_svg.hpp"
#include "sphtroch/wrist/wrist_sphere_grid.hpp"
#include "sphtroch/wrist/wrist_target.hpp"
#include "sphtroch/wrist/wrist_text.hpp"

#if defined(SPHTROCH_HAVE_INTERVAL) && !defined(SPHTROCH_SEPARATE_EXACT)  // separate mode parses no CGAL header
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/interval_vector.hpp"
#include "sphtroch/interval/krawczyk.hpp"
#include "sphtroch/interval/root_isolation.hpp"
#include "sphtroch/chain/chain_box_search.hpp"
#include "sphtroch/chain/chain_census.hpp"
#include "sphtroch/chain/chain_census_output.hpp"
#include "sphtroch/chain/chain_enclosure.hpp"
#include "sphtroch/chain/chain_event_roots.hpp"
#include "sphtroch/chain/chain_family_events.hpp"
#include "sphtroch/chain/chain_picture.hpp"
#include "sphtroch/chain/chain_tangency.hpp"
#include "sphtroch/tolerance/boundary_enclosure.hpp"
#include "sphtroch/tolerance/node_tolerance.hpp"
#include "sphtroch/tolerance/tolerance_box.hpp"
#include "sphtroch/tolerance/topology_margin.hpp"
#include "sphtroch/synthesis/free_axis_points.hpp"
#include "sphtroch/synthesis/precision_points.hpp"
#include "sphtroch/wrist/wrist_atlas.hpp"
#include "sphtroch/wrist/wrist_cap.hpp"
#include "sphtroch/wrist/wrist_critical.hpp"
#include "sphtroch/wrist/wrist_cusps.hpp"
#include "sphtroch/wrist/wrist_enclosure.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_ik_search.hpp"
#include "sphtroch/wrist/wrist_ik_system.hpp"
#include "sphtroch/wrist/wrist_regions.hpp"
#endif

#if defined(SPHTROCH_HAVE_EXACT)
#include "sphtroch/classify.hpp"
#include "sphtroch/synthesis.hpp"   // declared; defined unless separate
#include "sphtroch/tolerance.hpp"   // declared; defined unless separate
#include "sphtroch/exact/path_fit_output.hpp"
#include "sphtroch/exact/precision_points_output.hpp"
#include "sphtroch/exact/tolerance_output.hpp"
#if !defined(SPHTROCH_SEPARATE_EXACT)
#include "sphtroch/exact/path_fit_analysis.hpp"
#include "sphtroch/exact/precision_points_analysis.hpp"
#include "sphtroch/exact/tolerance_analysis.hpp"
#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/exact/arc_predicates.hpp"
#include "sphtroch/exact/certified_census.hpp"
#include "sphtroch/exact/chain_classification.hpp"
#include "sphtroch/exact/classification.hpp"
#include "sphtroch/exact/classification_output.hpp"
#include "sphtroch/exact/polyline_census.hpp"
#include "sphtroch/exact/scene.hpp"
#include "sphtroch/exact/self_crossings.hpp"
#endif
#endif

#if defined(SPHTROCH_HAVE_STEP)
#include "sphtroch/cad/step_export.hpp"
#endif
