// sphtroch/mpreal_support.hpp — use mpfr::mpreal (Debian libmpfrc++-dev) as a sphtroch Scalar.
//
//   #include <sphtroch/mpreal_support.hpp>   // before or instead of other sphtroch headers
//   mpfr::mpreal::set_default_prec(256);
//   sphtroch::TracerCurve<sphtroch::mpfr_real> curve(train);
//
// Pulls in Eigen's MPRealSupport module (which includes <mpreal.h>); link with -lmpfr -lgmp
// (the CMake target sphtroch::mpfr does this).
#pragma once

#if !defined(SPHTROCH_HAVE_MPFR)
#error "sphtroch/mpreal_support.hpp needs MPFR and GMP: link the CMake target sphtroch::mpfr (find_package(sphtroch CONFIG REQUIRED COMPONENTS mpfr)), or define SPHTROCH_HAVE_MPFR and link mpfr and gmp yourself"
#endif

#include <Eigen/Core>
#include <unsupported/Eigen/MPRealSupport>

namespace sphtroch {
using mpfr_real = mpfr::mpreal;
}  // namespace sphtroch
