// sphtroch/sphtroch.hpp — umbrella header: everything that needs Eigen only.
// The exact crossing search, the polyline census and the classification need CGAL
// (target sphtroch::exact): include sphtroch/polyline_crossings.hpp, polyline_census.hpp,
// classification.hpp or analysis.hpp (the lazy analysis object) yourself.
// The MPFR Scalar: sphtroch/mpreal_support.hpp (sphtroch::mpfr).
#pragma once

#include "sphtroch/analytic.hpp"
#include "sphtroch/atlas.hpp"
#include "sphtroch/atlas_csv.hpp"
#include "sphtroch/atlas_svg.hpp"
#include "sphtroch/boundary_snap.hpp"
#include "sphtroch/curve.hpp"
#include "sphtroch/errors.hpp"
#include "sphtroch/gear_train.hpp"
#include "sphtroch/node.hpp"
#include "sphtroch/node_assembly.hpp"
#include "sphtroch/parse.hpp"
#include "sphtroch/pitch_cone.hpp"
#include "sphtroch/ratio.hpp"
#include "sphtroch/refinement.hpp"
#include "sphtroch/root_census.hpp"
#include "sphtroch/sampling.hpp"
#include "sphtroch/svg.hpp"
#include "sphtroch/svg_plot.hpp"
#include "sphtroch/types.hpp"
#include "sphtroch/version.hpp"
