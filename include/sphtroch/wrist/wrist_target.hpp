// sphtroch/wrist/wrist_target.hpp — what a wrist's inverse kinematics asks for: a direction of
// the tool axis (pointing, 2 motors) or an orientation of the last body (3 motors).
//
//   const sphtroch::WristTarget look = sphtroch::WristTarget::pointing(sphtroch::Vector3d(0.6, 0, 0.8));
//   const sphtroch::WristTarget hold = sphtroch::WristTarget::orientation(Eigen::Quaterniond(1, 0, 0, 0));
//   hold.rotation_matrix();   // the identity
//
// What is solved, exactly: pointing, P(u) parallel to `direction` and of the same sense (the
// direction as the double vector stored; it is normalised, so within 1e-16 of unit); orientation,
// F(u) equal to the rotation of the quaternion `rotation` (w, x, y, z doubles; the rotation of
// q / |q| in real arithmetic, so exactly a rotation even though the stored q is unit only to
// 1e-16). A rotation matrix is taken as the rotation of its quaternion (Eigen's conversion), within
// ~1e-15 of the matrix given.
// Tolerances (InvalidInput naming `field` beyond them): a direction within 1e-6 of unit length; a
// quaternion within 1e-6 of unit length; a matrix with |R^T R - I| <= 1e-6 entrywise and det R > 0.
// Non-finite numbers are refused.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/types.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <string>

namespace sphtroch {

/// How far from unit length (or orthonormal) a typed target may be before it is refused.
constexpr double kWristTargetTolerance = 1e-6;

struct WristTarget {
  enum class Kind { pointing, orientation };
  Kind kind = Kind::pointing;
  Vector3d direction = Vector3d::UnitZ();                    ///< pointing: unit
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< orientation: unit (w, x, y, z)

  /// The tool axis along t. REQUIRES t finite, | |t| - 1 | <= kWristTargetTolerance.
  static WristTarget pointing(const Vector3d& t, const std::string& field = "target") {
    const std::string shown = number_text(t.x()) + "," + number_text(t.y()) + "," + number_text(t.z());
    if (!t.allFinite()) throw InvalidInput(field, shown, "not finite", "X,Y,Z: a unit vector (|t| within 1e-6 of 1)");
    if (!(std::fabs(t.norm() - 1.0) <= kWristTargetTolerance))
      throw InvalidInput(field, shown, "not a unit vector (|t| = " + number_text(t.norm()) + ")", "X,Y,Z: a unit vector (|t| within 1e-6 of 1)");
    WristTarget w;
    w.kind = Kind::pointing;
    w.direction = t.normalized();
    return w;
  }

  /// The last body's frame equal to the rotation of q. REQUIRES q finite, | |q| - 1 | <= kWristTargetTolerance.
  static WristTarget orientation(const Eigen::Quaterniond& q, const std::string& field = "target-frame") {
    const std::string shown = number_text(q.w()) + "," + number_text(q.x()) + "," + number_text(q.y()) + "," + number_text(q.z());
    const std::string valid = "w,x,y,z: a unit quaternion (|q| within 1e-6 of 1), or 9 numbers: a rotation matrix by rows";
    if (!q.coeffs().allFinite()) throw InvalidInput(field, shown, "not finite", valid);
    if (!(std::fabs(q.norm() - 1.0) <= kWristTargetTolerance))
      throw InvalidInput(field, shown, "not a unit quaternion (|q| = " + number_text(q.norm()) + ")", valid);
    WristTarget w;
    w.kind = Kind::orientation;
    w.rotation = q.normalized();
    return w;
  }

  /// The last body's frame equal to r (by rows: r(0, 0), r(0, 1), ...). REQUIRES r finite,
  /// orthonormal within kWristTargetTolerance, det r > 0.
  static WristTarget orientation(const Matrix3d& r, const std::string& field = "target-frame") {
    std::string shown;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) shown += (shown.empty() ? "" : ",") + number_text(r(i, j));
    const std::string valid = "9 numbers: a rotation matrix by rows (R^T R = I within 1e-6, det R = +1), or w,x,y,z: a unit quaternion";
    if (!r.allFinite()) throw InvalidInput(field, shown, "not finite", valid);
    const double off = (r.transpose() * r - Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(off <= kWristTargetTolerance))
      throw InvalidInput(field, shown, "not orthonormal (|R^T R - I| = " + number_text(off) + ")", valid);
    if (!(r.determinant() > 0)) throw InvalidInput(field, shown, "a reflection (det R = -1)", valid);
    return orientation(Eigen::Quaterniond(r).normalized(), field);
  }

  /// The target orientation as a matrix (orientation targets).
  Matrix3d rotation_matrix() const { return rotation.toRotationMatrix(); }
};

}  // namespace sphtroch
