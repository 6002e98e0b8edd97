// sphtroch/sphtroch.hpp — umbrella header: what the linked CMake components provide.
//   sphtroch::sphtroch (Eigen only): curves, sampling, parsing, the root census, the report's
//     criteria, the atlas, SVG, and the I/O headers (CSV/.npy readers and writers; POSIX).
//   sphtroch::exact (CGAL, GMP, MPFR, nlohmann-json; defines SPHTROCH_HAVE_EXACT): adds the exact
//     crossing search, the polyline census, classify(), the lazy Analysis, the reports
//     (text/JSON) and scenes.
//   sphtroch::mpfr (defines SPHTROCH_HAVE_MPFR): adds the mpfr::mpreal Scalar (mpreal_support.hpp).
#pragma once

#if defined(SPHTROCH_HAVE_MPFR)
#include "sphtroch/mpreal_support.hpp"  // first: Eigen's MPRealSupport must precede other Eigen use
#endif

#include "sphtroch/criteria.hpp"
#include "sphtroch/arc_crossing_point.hpp"
#include "sphtroch/atlas.hpp"
#include "sphtroch/atlas_csv.hpp"
#include "sphtroch/atlas_report.hpp"
#include "sphtroch/atlas_svg.hpp"
#include "sphtroch/boundaries.hpp"
#include "sphtroch/boundary_report.hpp"
#include "sphtroch/boundary_set.hpp"
#include "sphtroch/boundary_snap.hpp"
#include "sphtroch/half_turn.hpp"
#include "sphtroch/tangency_refinement.hpp"
#include "sphtroch/atlas_boundary_check.hpp"
#include "sphtroch/cost_bounds.hpp"
#include "sphtroch/csv_io.hpp"
#include "sphtroch/curve.hpp"
#include "sphtroch/errors.hpp"
#include "sphtroch/gear_train.hpp"
#include "sphtroch/input_file.hpp"
#include "sphtroch/input_text.hpp"
#include "sphtroch/node.hpp"
#include "sphtroch/node_assembly.hpp"
#include "sphtroch/node_sets.hpp"
#include "sphtroch/npy.hpp"
#include "sphtroch/number_text.hpp"
#include "sphtroch/output_file.hpp"
#include "sphtroch/parameters.hpp"
#include "sphtroch/parse.hpp"
#include "sphtroch/pitch_cone.hpp"
#include "sphtroch/polyline_input.hpp"
#include "sphtroch/ratio.hpp"
#include "sphtroch/refinement.hpp"
#include "sphtroch/root_census.hpp"
#include "sphtroch/sampling.hpp"
#include "sphtroch/svg.hpp"
#include "sphtroch/svg_plot.hpp"
#include "sphtroch/trace_output.hpp"
#include "sphtroch/types.hpp"
#include "sphtroch/version.hpp"
#include "sphtroch/work.hpp"

#if defined(SPHTROCH_HAVE_EXACT)
#include "sphtroch/analysis.hpp"
#include "sphtroch/arc_predicates.hpp"
#include "sphtroch/certified_census.hpp"
#include "sphtroch/classification.hpp"
#include "sphtroch/classify.hpp"
#include "sphtroch/polyline_census.hpp"
#include "sphtroch/polyline_crossings.hpp"
#include "sphtroch/report.hpp"
#include "sphtroch/scene.hpp"
#endif
