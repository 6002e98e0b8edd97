// sphtroch/exact_implementation.hpp — include in exactly ONE .cpp file of a program built with
// SPHTROCH_SEPARATE_EXACT (classification.hpp): defines classify() and instantiates it for
// ClassifySettings, so that every other file includes classification.hpp without CGAL.
//
//   // sphtroch_impl.cpp, the only file that pays for CGAL:
//   #include <sphtroch/exact_implementation.hpp>
//
// Harmless without SPHTROCH_SEPARATE_EXACT (the instantiation then merges with the implicit ones).
#pragma once

#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/exact/classification.hpp"

namespace sphtroch {
template Classification classify<ClassifySettings>(const GearTrain&, const ClassifySettings&);
}  // namespace sphtroch
