// sphtroch/io/urdf_chain.hpp — a gear-coupled rotation chain (core/rotation_chain.hpp) read from
// a URDF robot description, through urdfdom's parser (written as one: io/urdf_writer.hpp).
// Needs the sphtroch::urdf component (Debian's liburdfdom-dev; defines SPHTROCH_HAVE_URDF).
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {0.5, sphtroch::ChainRate(-2, 3), 0.3}});
//   const std::string xml = sphtroch::chain_to_urdf(chain, "wrist");
//   const sphtroch::UrdfChain read = sphtroch::read_urdf_chain(xml, "base_link", "tool", {0.0, 0.0, 1.0});
//   read.chain.rates_text();   // "1,-2/3": each joint's rate relative to the motor joint_1
//   read.joints.size();        // 2: joint_1, joint_2
//
// The model (rotation_chain.hpp): P(s) = Rz(N1 s + P1) Rx(A1) ... Rz(Nk s + Pk) Rx(Ak) z, k
// revolute joints whose axis lines meet at one point, joint i turning N_i s when one motor turns
// by s. In a URDF the coupling is <mimic joint="motor" multiplier="N_i" offset="..."/>: the
// joint's angle is multiplier * (the mimicked joint's angle) + offset (radians); a joint that
// mimics a mimic joint composes the two (multipliers multiply).
//
// Reading (read_urdf_chain, chain_from_urdf): the joints on the path from from_link down to
// to_link (to_link must lie below from_link in the kinematic tree). Revolute and continuous
// joints become the stages, in order from from_link (limits are ignored: every joint turns
// freely); fixed joints and every joint's origin rotation (rpy) are folded into twists and
// phases; positions matter only for the common-centre check. How: joint i gets a frame whose z is
// its axis; the fixed rotation from joint i's frame (after it turns) to joint i+1's frame is
// split as ZXZ Euler angles Rz(alpha) Rx(A_i) Rz(beta), A_i in [0, pi]: alpha joins P_i, beta
// joins P_{i+1}; the tool axis in the last joint's frame is Rz(phi) Rx(A_k) z: its polar angle
// is the last twist, phi joins P_k. Mimic offsets join the phases too.
//   The parameter s is the motor's angle (radians): the motor is the joint that the stages'
//   mimic references lead to (it may lie off the path: a motor elsewhere in the tree that
//   drives the chain's joints through gears). Its rate is 1; each multiplier (a double in
//   urdfdom) becomes the exact fraction p/q with the smallest q within 1e-12 relative of it
//   (continued fractions), refused unless |p|, q <= 1e6; the composed rates are exact products.
//   The curve is expressed in joint 1's frame (z = joint 1's axis): the tool axis in from_link's
//   frame is base_rotation * ChainCurve<double>(chain).point(s).
// Refused, with InvalidInput naming the joint or link and saying why (field "urdf", or "from",
// "to", "axis" for the arguments): a document urdfdom cannot parse, a missing link, to_link not
// below from_link, no revolute or continuous joint on the path, a prismatic, planar or floating
// joint, a zero axis, a joint origin that is not finite, an axis line that misses the common
// centre (by more than kUrdfCentreTolerance m plus the rounding of the lengths composed), a
// joint driven by another motor than joint 1's (two independent joints), a mimic of a missing or non-revolute joint, a mimic cycle, a multiplier that is no
// fraction, rates the chain refuses (RotationChain's contract), a zero or non-finite tool axis.
// Nothing aborts; urdfdom's own log (console_bridge) is silenced while it parses.
//
// Writing: io/urdf_writer.hpp (chain_to_urdf, no urdfdom). The shape check before urdfdom parses:
// io/xml_shape.hpp.
#pragma once

#if !defined(SPHTROCH_HAVE_URDF)
#error "sphtroch/io/urdf_chain.hpp needs the sphtroch::urdf component (liburdfdom-dev)"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/io/urdf_writer.hpp"
#include "sphtroch/io/xml_shape.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// Axis lines may miss the common centre by this many metres, plus the rounding of the distances
/// composed to place them (kUrdfCentreRounding times the sum of the origins' lengths along the
/// path): a joint far out along its own axis (which the rotation does not see) widens the
/// tolerance only by the rounding its coordinates bring, not in proportion to its distance.
constexpr double kUrdfCentreTolerance = 1e-9;
constexpr double kUrdfCentreRounding = 64 * std::numeric_limits<double>::epsilon();
/// A mimic multiplier is the fraction p/q, |p|, q <= kUrdfMaxDenominator, within this relative distance.
constexpr double kUrdfMultiplierTolerance = 1e-12;
constexpr std::int64_t kUrdfMaxDenominator = 1000000;

/// A chain read from a URDF, with the frames and names that tie it to the robot.
struct UrdfChain {
  RotationChain chain;             ///< stage i is joints[i]; its curve in joint 1's frame
  Matrix3d base_rotation;          ///< from_R_joint1: tool axis in from_link's frame = base_rotation * point(s)
  std::vector<std::string> joints; ///< the revolute and continuous joints, from from_link to to_link
  std::string motor;               ///< the joint whose angle (radians) is s; may lie off the path
  Vector3d centre;                 ///< where the axis lines meet, in from_link's frame (metres)
};

/// The chain from from_link to to_link of the URDF document urdf_xml, with the tool axis
/// tool_axis (any nonzero length; in to_link's frame). Throws InvalidInput (list above).
inline UrdfChain read_urdf_chain(const std::string& urdf_xml, const std::string& from_link, const std::string& to_link,
                                 const Vector3<double>& tool_axis);
/// read_urdf_chain(...).chain.
inline RotationChain chain_from_urdf(const std::string& urdf_xml, const std::string& from_link, const std::string& to_link,
                                     const Vector3<double>& tool_axis);


// Implementation details follow.
namespace urdf_chain_detail {

inline std::string quoted(const std::string& name) { return "\"" + name + "\""; }

inline InvalidInput joint_error(const std::string& joint, const std::string& problem, const std::string& valid) {
  return InvalidInput("urdf", "joint " + quoted(joint), problem, valid);
}

const char* const kValidJoint = "revolute or continuous joints (and fixed ones) whose axis lines meet at one point, one motor";
const char* const kValidMimic = "a mimic of the motor (or of a joint that mimics it) with a multiplier p/q, |p|, q <= 1e6";

/// The chain of the stages read, its refusals (RotationChain's contract) naming "urdf": the
/// user gave a file, not --twists or --rates.
inline RotationChain checked_chain(const std::vector<ChainStage>& stages) {
  try {
    return RotationChain(stages);
  } catch (const InvalidInput& e) {
    throw InvalidInput("urdf", e.field() + " " + e.value(), e.problem(), e.valid_range());
  }
}

/// The model urdfdom parses from xml; InvalidInput when it cannot.
inline urdf::ModelInterfaceSharedPtr parse_model(const std::string& xml) {
  const std::string valid = "a URDF document (<robot name=...> with links and joints)";
  check_xml_shape(xml, "urdf", "a URDF document");
  urdf::ModelInterfaceSharedPtr model;
  // urdfdom logs its parse errors through console_bridge on stderr: quiet while it parses, so
  // that a refusal is the one line of InvalidInput (the caller's log level is restored).
  const console_bridge::LogLevel level = console_bridge::getLogLevel();
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
  try {
    model = urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    console_bridge::setLogLevel(level);
    throw InvalidInput("urdf", "the document", std::string("urdfdom refused it: ") + e.what(), valid);
  }
  console_bridge::setLogLevel(level);
  if (!model) throw InvalidInput("urdf", "the document", "urdfdom could not parse it (malformed XML or not a valid URDF)", valid);
  return model;
}

/// The joints from from_link down to to_link, in that order.
inline std::vector<urdf::JointConstSharedPtr> joint_path(const urdf::ModelInterface& model, const std::string& from,
                                                         const std::string& to) {
  const auto check = [&](const char* field, const std::string& name) {
    if (!model.getLink(name)) throw InvalidInput(field, "link " + quoted(name), "no such link in the robot", "a link name of the URDF");
  };
  check("from", from);
  check("to", to);
  std::vector<urdf::JointConstSharedPtr> path;
  for (urdf::LinkConstSharedPtr link = model.getLink(to); link->name != from;) {
    const urdf::JointConstSharedPtr joint = link->parent_joint;
    if (!joint || path.size() > model.joints_.size())
      throw InvalidInput("to", "link " + quoted(to), "not below link " + quoted(from) + " in the kinematic tree (they are not connected that way)",
                         "a link reached from the from link through child joints");
    path.push_back(joint);
    link = model.getLink(joint->parent_link_name);
  }
  std::reverse(path.begin(), path.end());
  return path;
}

/// |x| as the exact fraction num / 2^e (num odd or e = 0). REQUIRES 1e-7 <= |x| <= 1e6.
struct BinaryFraction {
  __extension__ typedef __int128 Int;
  Int num = 0, den = 1;
};
inline BinaryFraction binary_fraction(double x) {
  int exponent = 0;
  const double mantissa = std::frexp(std::fabs(x), &exponent);  // |x| = mantissa 2^exponent, mantissa in [0.5, 1)
  BinaryFraction f;
  f.num = static_cast<std::int64_t>(std::ldexp(mantissa, 53));
  int e = 53 - exponent;  // in [33, 76] for |x| in [1e-7, 1e6]
  while (e > 0 && f.num % 2 == 0) f.num /= 2, --e;
  f.den = BinaryFraction::Int(1) << e;
  return f;
}

/// True when h / k is within kUrdfMultiplierTolerance relative of f (exact in 128-bit integers).
inline bool close_fraction(const BinaryFraction& f, BinaryFraction::Int h, BinaryFraction::Int k) {
  BinaryFraction::Int d = f.num * k - h * f.den;
  if (d < 0) d = -d;
  return static_cast<long double>(d) <=
         static_cast<long double>(kUrdfMultiplierTolerance) * static_cast<long double>(f.num) * static_cast<long double>(k);
}

/// The fraction p/q with the smallest q within the tolerance of |x|, if p, q <= kUrdfMaxDenominator
/// (ChainRate's bound); REQUIRES 1e-7 <= |x| <= 1e6; q = 0 when there is none (pi: the first
/// fraction within 1e-12 is 1146408/364913). It is a best approximation of |x| (every fraction
/// with a smaller q is farther away), hence a convergent or semiconvergent of |x|'s continued
/// fraction: these are tried in order of increasing q (and p). The semiconvergents
/// (h0 + j h1) / (k0 + j k1) of a term a approach |x| monotonically in j = 1 .. a, so the
/// smallest close j is found by bisection.
inline std::pair<std::int64_t, std::int64_t> smallest_fraction(double x) {
  using Int = BinaryFraction::Int;
  const BinaryFraction exact = binary_fraction(x);
  BinaryFraction f = exact;      // the remainder, as a fraction num / den
  Int h0 = 0, k0 = 1, h1 = 1, k1 = 0;  // the two convergents before the current term
  while (true) {
    const Int a = f.num / f.den;
    Int j_max = k1 == 0 ? a : std::min<Int>(a, (kUrdfMaxDenominator - k0) / k1);  // q <= 1e6
    if (h1 > 0) j_max = std::min<Int>(j_max, (kUrdfMaxDenominator - h0) / h1);        // p <= 1e6
    const auto close = [&](Int j) { return close_fraction(exact, h0 + j * h1, k0 + j * k1); };
    if (j_max >= 1 && close(j_max)) {
      Int lo = 1, hi = j_max;
      while (lo < hi) {
        const Int mid = lo + (hi - lo) / 2;
        if (close(mid)) hi = mid;
        else lo = mid + 1;
      }
      return {static_cast<std::int64_t>(h0 + lo * h1), static_cast<std::int64_t>(k0 + lo * k1)};
    }
    const Int rest = f.num - a * f.den;
    if (j_max < a || rest == 0) return {0, 0};  // beyond the denominator bound, or |x| reached
    const Int h = h0 + a * h1, k = k0 + a * k1;
    h0 = h1, k0 = k1, h1 = h, k1 = k;
    f = BinaryFraction{f.den, rest};
  }
}

/// The mimic multiplier of joint as an exact rate; InvalidInput naming the joint otherwise.
inline ChainRate multiplier_rate(const std::string& joint, double multiplier) {
  const std::string shown = "multiplier " + number_text(multiplier);
  if (multiplier == 0) return ChainRate(0);
  const bool in_range = std::isfinite(multiplier) && std::fabs(multiplier) >= 1e-7 && std::fabs(multiplier) <= 1e6;
  const std::pair<std::int64_t, std::int64_t> pq = in_range ? smallest_fraction(multiplier) : std::pair<std::int64_t, std::int64_t>{0, 0};
  if (pq.second == 0)
    throw joint_error(joint, "its mimic " + shown + " is not a fraction p/q with |p|, q <= 1e6 (within 1e-12 relative)", kValidMimic);
  return ChainRate(multiplier < 0 ? -pq.first : pq.first, pq.second);
}

/// A joint's angle as rate * (the motor's angle) + offset (radians).
struct Drive {
  std::string motor;
  ChainRate rate{1};
  double offset = 0;
};

inline bool is_revolute(const urdf::Joint& j) { return j.type == urdf::Joint::REVOLUTE || j.type == urdf::Joint::CONTINUOUS; }

/// The drive of joint: its mimic references followed to the joint that mimics none (the motor).
inline Drive drive_of(const urdf::ModelInterface& model, const urdf::Joint& joint) {
  Drive d{joint.name, ChainRate(1), 0.0};
  const urdf::Joint* j = &joint;
  for (std::size_t steps = 0; j->mimic; ++steps) {
    if (steps > model.joints_.size()) throw joint_error(joint.name, "its mimic references form a cycle", kValidMimic);
    const ChainRate m = multiplier_rate(j->name, j->mimic->multiplier);
    d.offset += d.rate.value() * j->mimic->offset;
    try {
      d.rate = ChainRate(d.rate.p() * m.p(), d.rate.q() * m.q());
    } catch (const InvalidInput&) {
      throw joint_error(joint.name, "its composed mimic multiplier has a term beyond 1e6", kValidMimic);
    }
    const urdf::JointConstSharedPtr next = model.getJoint(j->mimic->joint_name);
    if (!next) throw joint_error(j->name, "it mimics joint " + quoted(j->mimic->joint_name) + ", which the robot does not have", kValidMimic);
    if (!is_revolute(*next))
      throw joint_error(j->name, "it mimics joint " + quoted(next->name) + ", which is not revolute or continuous", kValidMimic);
    j = next.get();
  }
  d.motor = j->name;
  return d;
}

inline Matrix3d rotation_of(const urdf::Pose& pose) {
  const urdf::Rotation& r = pose.rotation;
  return Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
}
inline Vector3d position_of(const urdf::Pose& pose) { return Vector3d(pose.position.x, pose.position.y, pose.position.z); }

/// The revolute and continuous joints of a path and the fixed rotations between them.
struct PathGeometry {
  std::vector<urdf::JointConstSharedPtr> joints;  ///< base to tip
  /// fixed[i]: joint i's frame in the frame of the link before it (after joint i-1 turns;
  /// from_link's for i = 0), fixed joints folded in; fixed[k]: to_link's frame in link_k's.
  std::vector<Matrix3d> fixed;
  std::vector<Vector3d> axes;         ///< each joint's unit axis in its own frame
  std::vector<Vector3d> origins_base; ///< each joint's origin in from_link's frame, all angles 0 (metres)
  std::vector<Vector3d> axes_base;    ///< each joint's unit axis in from_link's frame, all angles 0
  std::vector<double> reach;          ///< the sum of the origins' lengths composed up to each joint (metres)
};

/// joint's unit axis; InvalidInput for a joint that is not revolute, continuous or fixed, or a zero axis.
inline Vector3d checked_axis(const urdf::Joint& joint) {
  const char* kind = joint.type == urdf::Joint::PRISMATIC ? "prismatic" : joint.type == urdf::Joint::PLANAR ? "planar"
                     : joint.type == urdf::Joint::FLOATING ? "floating" : "of an unknown type";
  if (!is_revolute(joint)) throw joint_error(joint.name, std::string("a ") + kind + " joint: a rotation chain has only revolute ones", kValidJoint);
  const Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
  const double m = axis.cwiseAbs().maxCoeff();  // scaled first: a huge axis is a direction too
  if (!axis.allFinite() || !(m > 0)) throw joint_error(joint.name, "its axis is zero (or not finite)", kValidJoint);
  const Vector3d scaled = axis / m;
  return scaled / scaled.norm();
}

inline PathGeometry path_geometry(const std::vector<urdf::JointConstSharedPtr>& path) {
  PathGeometry g;
  Matrix3d pending = Matrix3d::Identity(), base_r = Matrix3d::Identity();  // base_r, base_t: the current frame in from_link's
  Vector3d base_t = Vector3d::Zero();
  double reach = 0;
  for (const urdf::JointConstSharedPtr& joint : path) {
    const Matrix3d r = rotation_of(joint->parent_to_joint_origin_transform);
    const Vector3d position = position_of(joint->parent_to_joint_origin_transform);
    const double length = position.cwiseAbs().sum();
    if (!std::isfinite(length) || !std::isfinite(reach + length))
      throw joint_error(joint->name, "its origin xyz is not finite or too far (the lengths along the path overflow)",
                        "joint origins with finite coordinates (metres)");
    reach += length;
    base_t += base_r * position;
    base_r = base_r * r;
    pending = pending * r;
    if (joint->type == urdf::Joint::FIXED) continue;
    const Vector3d axis = checked_axis(*joint);
    g.joints.push_back(joint);
    g.fixed.push_back(pending);
    g.axes.push_back(axis);
    g.origins_base.push_back(base_t);
    g.axes_base.push_back(base_r * axis);
    g.reach.push_back(reach);
    pending = Matrix3d::Identity();
  }
  g.fixed.push_back(pending);
  return g;
}

/// The distance (metres) from point c to the line through o along unit d.
inline double line_distance(const Vector3d& c, const Vector3d& o, const Vector3d& d) { return (c - o).cross(d).norm(); }

/// The point where every axis line meets (all angles 0; the joints turn about it, so it stays
/// put). Reference: joint 1's line and the line most oblique to it (their nearest point on joint
/// 1's line); every line within kUrdfCentreTolerance m of it, plus the rounding of the lengths
/// composed (kUrdfCentreRounding times the reach of both joints and the centre's distance), or
/// InvalidInput naming the first joint whose line is not.
inline Vector3d common_centre(const PathGeometry& g) {
  const std::vector<Vector3d>& o = g.origins_base;
  const std::vector<Vector3d>& d = g.axes_base;
  std::size_t other = 0;
  for (std::size_t i = 1; i < d.size(); ++i)
    if (d[0].cross(d[i]).norm() > d[0].cross(d[other]).norm()) other = i;
  Vector3d centre = o[0];
  double centre_reach = g.reach[0];
  if (other != 0 && d[0].cross(d[other]).norm() > 1e-9) {
    const Vector3d n = d[0].cross(d[other]);  // nearest point of line 0 to line `other`: o0 + t d0
    const double t = (o[other] - o[0]).cross(d[other]).dot(n) / n.squaredNorm();
    centre = o[0] + t * d[0];
    centre_reach = (g.reach[0] + g.reach[other]) / n.norm();  // t's rounding grows as the lines turn parallel
  }
  for (std::size_t i = 0; i < o.size(); ++i) {
    const double miss = line_distance(centre, o[i], d[i]);
    const double tolerance = kUrdfCentreTolerance + kUrdfCentreRounding * (centre_reach + g.reach[i] + centre.norm());
    if (!(miss <= tolerance))
      throw joint_error(g.joints[i]->name,
                        "its axis line passes " + number_text(miss) + " m from the point where the axis lines of joints " +
                            quoted(g.joints[0]->name) + " and " + quoted(g.joints[other]->name) + " meet (tolerance " + number_text(tolerance) + " m)",
                        kValidJoint);
  }
  return centre;
}

/// A rotation whose z column is the unit vector axis.
inline Matrix3d axis_frame(const Vector3d& axis) { return Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), axis).toRotationMatrix(); }

/// g = Rz(alpha) Rx(twist) Rz(beta), twist in [0, pi].
struct ZxzAngles {
  double alpha = 0, twist = 0, beta = 0;
};

/// The ZXZ angles of rotation g. alpha from g's last column (its direction is sharp to
/// ~1e-16 / sin(twist), and alpha moves the result by sin(twist) times its error); alpha + beta
/// (twist <= pi / 2) or alpha - beta (twist > pi / 2) from the upper 2x2 block, where it is sharp
/// to ~1e-16: the rotation rebuilt is within a few ulp of g. At twist 0 or pi, alpha = 0.
inline ZxzAngles zxz_angles(const Matrix3d& g) {
  ZxzAngles a;
  a.twist = std::atan2(std::hypot(g(0, 2), g(1, 2)), g(2, 2));
  a.alpha = g(0, 2) == 0 && g(1, 2) == 0 ? 0.0 : std::atan2(g(0, 2), -g(1, 2));
  if (g(2, 2) >= 0) a.beta = std::atan2(g(1, 0) - g(0, 1), g(0, 0) + g(1, 1)) - a.alpha;  // alpha + beta
  else a.beta = a.alpha - std::atan2(g(1, 0) + g(0, 1), g(0, 0) - g(1, 1));               // alpha - beta
  return a;
}

/// The unit tool axis in to_link's frame; InvalidInput("axis") for a zero or non-finite one.
inline Vector3d unit_tool_axis(const Vector3d& axis) {
  const double n = axis.cwiseAbs().maxCoeff();  // scaled first: 1e300,1e300,0 is a direction too
  if (!axis.allFinite() || !(n > 0))
    throw InvalidInput("axis", report_number(axis.x()) + "," + number_text(axis.y()) + "," + number_text(axis.z()), "zero or not finite",
                       "a nonzero direction X,Y,Z in the to link's frame");
  const Vector3d scaled = axis / n;
  return scaled / scaled.norm();
}

/// Every stage's drive; InvalidInput naming a joint driven by another motor than joint 1's.
inline std::vector<Drive> stage_drives(const urdf::ModelInterface& model, const PathGeometry& g) {
  std::vector<Drive> drives;
  for (const urdf::JointConstSharedPtr& joint : g.joints) {
    drives.push_back(drive_of(model, *joint));
    if (drives.back().motor != drives.front().motor)
      throw joint_error(joint->name,
                        "it is driven by joint " + quoted(drives.back().motor) + ", not by " + quoted(drives.front().motor) +
                            " (joint " + quoted(g.joints[0]->name) + "'s motor): two independent joints",
                        kValidMimic);
  }
  return drives;
}

/// The stages: twists and phases from the fixed rotations (the ZXZ split), rates and offsets
/// from the drives.
inline std::vector<ChainStage> chain_stages(const PathGeometry& g, const std::vector<Drive>& drives, const Vector3d& tool) {
  const std::size_t k = g.joints.size();
  std::vector<Matrix3d> frames;
  for (const Vector3d& axis : g.axes) frames.push_back(axis_frame(axis));
  std::vector<ChainStage> stages(k);
  for (std::size_t i = 0; i < k; ++i) {
    stages[i].rate = drives[i].rate;
    stages[i].phase += drives[i].offset;
    if (i + 1 == k) break;
    const ZxzAngles a = zxz_angles(Matrix3d(frames[i].transpose() * g.fixed[i + 1] * frames[i + 1]));
    stages[i].twist = a.twist;
    stages[i].phase += a.alpha;
    stages[i + 1].phase += a.beta;
  }
  const Vector3d t = frames[k - 1].transpose() * g.fixed[k] * tool;  // = Rz(phi) Rx(A_k) z
  stages[k - 1].twist = std::atan2(std::hypot(t.x(), t.y()), t.z());
  stages[k - 1].phase += t.x() == 0 && t.y() == 0 ? 0.0 : std::atan2(t.x(), -t.y());
  return stages;
}

}  // namespace urdf_chain_detail

inline UrdfChain read_urdf_chain(const std::string& urdf_xml, const std::string& from_link, const std::string& to_link,
                                 const Vector3<double>& tool_axis) {
  namespace d = urdf_chain_detail;
  const Vector3d tool = d::unit_tool_axis(tool_axis);
  const urdf::ModelInterfaceSharedPtr model = d::parse_model(urdf_xml);
  const d::PathGeometry g = d::path_geometry(d::joint_path(*model, from_link, to_link));
  if (g.joints.empty())
    throw InvalidInput("to", "link " + d::quoted(to_link), "no revolute or continuous joint between it and link " + d::quoted(from_link),
                       "links with at least one revolute or continuous joint between them");
  const Vector3d centre = d::common_centre(g);
  const std::vector<d::Drive> drives = d::stage_drives(*model, g);
  std::vector<std::string> names;
  for (const urdf::JointConstSharedPtr& joint : g.joints) names.push_back(joint->name);
  return UrdfChain{d::checked_chain(d::chain_stages(g, drives, tool)), Matrix3d(g.fixed[0] * d::axis_frame(g.axes[0])), names,
                   drives.front().motor, centre};
}

inline RotationChain chain_from_urdf(const std::string& urdf_xml, const std::string& from_link, const std::string& to_link,
                                     const Vector3<double>& tool_axis) {
  return read_urdf_chain(urdf_xml, from_link, to_link, tool_axis).chain;
}

}  // namespace sphtroch
