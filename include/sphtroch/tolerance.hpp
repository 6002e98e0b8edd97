// sphtroch/tolerance.hpp — include this to call tolerance_report() (exact/tolerance_output.hpp):
// the declaration, the report's formats and Monte Carlo, and its definition
// (exact/tolerance_analysis.hpp, with CGAL) unless SPHTROCH_SEPARATE_EXACT is defined.
//
//   #include <sphtroch/tolerance.hpp>                 // needs sphtroch::exact, or sphtroch::compiled
//   const sphtroch::GearTrain train(1.0, 2.0, sphtroch::Ratio(5, 2));
//   const sphtroch::ToleranceReport r = sphtroch::tolerance_report(train, {1e-3, 1e-3, 0.0});
//   r.topology.verdict;  r.margin.lower;               // holds | changes | undecided; radians
//
// Separate compilation as for classify() (classify.hpp): with SPHTROCH_SEPARATE_EXACT this header
// parses no CGAL header and the definition comes from the one file that includes
// <sphtroch/exact_implementation.hpp>, or from libsphtroch_compiled.
#pragma once

#include "sphtroch/classify.hpp"
#include "sphtroch/exact/tolerance_output.hpp"

#if !defined(SPHTROCH_SEPARATE_EXACT)
#include "sphtroch/exact/tolerance_analysis.hpp"
#endif
