// sphtroch/core/types.hpp — every Eigen alias and per-Scalar constant the library uses.
//
//   sphtroch::Vector3<double> p = ...;        // a point on the unit sphere
//   double pi = sphtroch::Constants<double>::pi();
//
// Scalar may be float, double, long double or mpfr::mpreal (include
// <sphtroch/exact/mpreal_support.hpp> first for the last one).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include <cmath>

namespace sphtroch {

template <typename Scalar>
using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
template <typename Scalar>
using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;

using Vector3f = Vector3<float>;
using Vector3d = Vector3<double>;
using Matrix3d = Matrix3<double>;

/// Constants in the precision of Scalar (for mpreal: the current default precision).
template <typename Scalar>
struct Constants {
  static Scalar pi() {
    using std::acos;
    return acos(Scalar(-1));
  }
  static Scalar two_pi() { return Scalar(2) * pi(); }
};

template <>
struct Constants<double> {
  static constexpr double pi() { return 3.14159265358979323846; }
  static constexpr double two_pi() { return 6.28318530717958647692; }
};

/// Radians to degrees, r * 180 / pi (two roundings: within 1.5 ulp of the exact value); read back
/// as d * pi / 180 it is within 4 ulp (1e-15 relative) of r. For printing (--degrees).
inline double degrees(double r) { return r * 180.0 / Constants<double>::pi(); }

template <>
struct Constants<float> {
  static constexpr float pi() { return 3.14159265358979323846f; }
  static constexpr float two_pi() { return 6.28318530717958647692f; }
};

template <>
struct Constants<long double> {
  static constexpr long double pi() { return 3.141592653589793238462643383279502884L; }
  static constexpr long double two_pi() { return 6.283185307179586476925286766559005768L; }
};

}  // namespace sphtroch
