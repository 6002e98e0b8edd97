// sphtroch/exact/mpreal_support.hpp — use mpfr::mpreal (Debian libmpfrc++-dev) as a sphtroch Scalar.
//
//   #include <sphtroch/exact/mpreal_support.hpp>   // before or instead of other sphtroch headers
//   sphtroch::MpfrPrecision bits(256);         // this thread, until `bits` goes out of scope
//   sphtroch::TracerCurve<sphtroch::mpfr_real> curve(train);
//
// Precision: every mpfr_real the library creates takes MPFR's *default* precision, and that is
// per thread (Debian's MPFR is built thread-safe: the default lives in thread-local storage). A
// new thread starts at 53 bits, so a worker that does not set it computes "mpreal" results that
// are only double-accurate. Set it explicitly in every thread that evaluates mpfr_real, with
// MpfrPrecision (tested in tests/core/test_scalar_types.cpp, from a second thread). MPFR also keeps
// per-thread caches (constants such as pi): a thread should call mpfr_free_cache() before it
// ends, or LeakSanitizer reports them.
//
// Pulls in Eigen's MPRealSupport module (which includes <mpreal.h>); link with -lmpfr -lgmp
// (the CMake target sphtroch::mpfr does this).
#pragma once

#if !defined(SPHTROCH_HAVE_MPFR)
#error "sphtroch/exact/mpreal_support.hpp needs MPFR and GMP: link the CMake target sphtroch::mpfr (find_package(sphtroch CONFIG REQUIRED COMPONENTS mpfr)), or define SPHTROCH_HAVE_MPFR and link mpfr and gmp yourself"
#endif

#include <Eigen/Core>
#include <unsupported/Eigen/MPRealSupport>

#include "sphtroch/core/errors.hpp"

#include <string>

namespace sphtroch {
using mpfr_real = mpfr::mpreal;

/// Sets MPFR's default precision of the calling thread to `bits` for this object's lifetime and
/// restores the previous one after. Throws InvalidInput("precision") unless
/// MPFR_PREC_MIN <= bits <= 1e6 (the cost of one operation grows with bits).
class MpfrPrecision {
 public:
  explicit MpfrPrecision(long bits) : previous_(mpfr::mpreal::get_default_prec()) {
    if (bits < static_cast<long>(MPFR_PREC_MIN) || bits > 1000000)
      throw InvalidInput("precision", std::to_string(bits), "outside the valid range",
                         "integer " + std::to_string(static_cast<long>(MPFR_PREC_MIN)) + " .. 1000000 bits");
    mpfr::mpreal::set_default_prec(static_cast<mpfr_prec_t>(bits));
  }
  ~MpfrPrecision() { mpfr::mpreal::set_default_prec(previous_); }
  MpfrPrecision(const MpfrPrecision&) = delete;
  MpfrPrecision& operator=(const MpfrPrecision&) = delete;

 private:
  mpfr_prec_t previous_;
};
}  // namespace sphtroch
