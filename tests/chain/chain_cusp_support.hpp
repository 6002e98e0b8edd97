// tests/chain/chain_cusp_support.hpp — a three-stage chain built with a cusp at a chosen s0: the
// independent construction the chain census's and the event roots' tests share.
#pragma once

#include "sphtroch/core/rotation_chain.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sphtroch_test {

/// The stages with the last twist and phase set so that P(s0) is parallel to omega(s0) (omega(s0)
/// does not depend on them): the tool axis, Rz(theta3) Rx(A3) z in the second body's frame, aimed
/// along omega written in that frame. REQUIRES three stages.
inline std::vector<sphtroch::ChainStage> with_cusp_at(std::vector<sphtroch::ChainStage> st, double s0) {
  using sphtroch::Vector3d;
  const sphtroch::ChainCurve<double> probe{sphtroch::RotationChain(st)};
  const std::vector<Vector3d> axes = probe.joint_axes(s0);
  Vector3d omega = Vector3d::Zero();
  for (std::size_t i = 0; i < 3; ++i) omega += st[i].rate.value() * axes[i];
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; i < 2; ++i)
    r = r * Eigen::AngleAxisd(st[i].rate.value() * s0 + st[i].phase, Vector3d::UnitZ()) * Eigen::AngleAxisd(st[i].twist, Vector3d::UnitX());
  const Vector3d u = r.transpose() * omega.normalized();  // wanted: Rz(theta3) Rx(A3) z = u
  st[2].twist = std::acos(std::clamp(u.z(), -1.0, 1.0));
  st[2].phase = std::atan2(u.x(), -u.y()) - st[2].rate.value() * s0;
  return st;
}

}  // namespace sphtroch_test
