// sphtroch/classify.hpp — include this to call classify() (classification.hpp): the declaration,
// and its definition (analysis.hpp, with CGAL) unless SPHTROCH_SEPARATE_EXACT is defined.
//
//   #include <sphtroch/classify.hpp>                  // needs sphtroch::exact
//   sphtroch::Classification c = sphtroch::classify(train);
//
// Separate compilation. By default every file that calls classify() parses CGAL and compiles
// the whole census: 11.9 s of g++ 12 -O2 per file (docs/library.md). Define
// SPHTROCH_SEPARATE_EXACT for the whole project (target_compile_definitions) and this header
// only declares classify(): 1.5 s. Exactly one file of the program then includes
// <sphtroch/exact_implementation.hpp>, which defines and instantiates it (the stb / fmt pattern).
// classify() is a function template (Settings = ClassifySettings) so that files of either mode
// and the implementation file may share one program without an ODR clash.
#pragma once

#include "sphtroch/exact/classification.hpp"

#if !defined(SPHTROCH_SEPARATE_EXACT)
#include "sphtroch/exact/analysis.hpp"
#endif
