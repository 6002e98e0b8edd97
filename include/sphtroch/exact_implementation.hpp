// sphtroch/exact_implementation.hpp — include in exactly ONE .cpp file of a program built with
// SPHTROCH_SEPARATE_EXACT (classification.hpp): defines and instantiates classify(),
// tolerance_report(), precision_points_with_census() and fit_with_census(), so that every other
// file includes classify.hpp, tolerance.hpp and synthesis.hpp without CGAL.
//
//   // sphtroch_impl.cpp, the only file that pays for CGAL:
//   #include <sphtroch/exact_implementation.hpp>
//
// Harmless without SPHTROCH_SEPARATE_EXACT (the instantiation then merges with the implicit ones).
#pragma once

#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/exact/classification.hpp"
#include "sphtroch/exact/path_fit_analysis.hpp"
#include "sphtroch/exact/precision_points_analysis.hpp"
#include "sphtroch/exact/tolerance_analysis.hpp"

namespace sphtroch {
template Classification classify<ClassifySettings>(const GearTrain&, const ClassifySettings&);
template ToleranceReport tolerance_report<ToleranceBox>(const GearTrain&, const ToleranceBox&);
template std::vector<RatioPrecisionPoints> precision_points_with_census<PrecisionPointsOptions>(
    const std::vector<Vector3d>&, const std::vector<Ratio>&, const PrecisionPointsOptions&, bool);
template std::vector<RatioFit> fit_with_census<FitOptions>(const std::vector<Vector3d>&, const std::vector<Ratio>&, const FitOptions&);
}  // namespace sphtroch
