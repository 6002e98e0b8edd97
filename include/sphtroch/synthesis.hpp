// sphtroch/synthesis.hpp — include this to call the inverse design with each train's census:
// precision_points_with_census() (exact/precision_points_output.hpp) and fit_with_census()
// (exact/path_fit_output.hpp), with their JSON and text, and their definitions
// (exact/precision_points_analysis.hpp, exact/path_fit_analysis.hpp, with CGAL) unless
// SPHTROCH_SEPARATE_EXACT is defined.
//
//   #include <sphtroch/synthesis.hpp>                 // needs sphtroch::exact, or sphtroch::compiled
//   const sphtroch::TracerCurve<double> curve(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(1, 2), 0.3));
//   const std::vector<sphtroch::Vector3d> pts = {curve.point(0.5), curve.point(2.0), curve.point(7.0)};
//   const auto all = sphtroch::precision_points_with_census(pts, {sphtroch::Ratio(1, 2)});
//   all[0].result.certified;  all[0].result.solutions.size();   // every train of n = 1/2 through them
//
// Separate compilation as for classify() (classify.hpp): with SPHTROCH_SEPARATE_EXACT this header
// parses no CGAL header and the definitions come from the one file that includes
// <sphtroch/exact_implementation.hpp>, or from libsphtroch_compiled.
#pragma once

#include "sphtroch/classify.hpp"
#include "sphtroch/exact/path_fit_output.hpp"
#include "sphtroch/exact/precision_points_output.hpp"

#if !defined(SPHTROCH_SEPARATE_EXACT)
#include "sphtroch/exact/path_fit_analysis.hpp"
#include "sphtroch/exact/precision_points_analysis.hpp"
#endif
