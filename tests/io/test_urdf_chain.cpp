// Tests of sphtroch/io/urdf_chain.hpp: chains written as URDF and read back through urdfdom (the
// same curve after the motor's reparametrisation u = N_m s + P_m), a geared wrist in a real robot
// description against an independent product of Eigen AngleAxis rotations taken from the URDF's
// own numbers, and every refusal naming its joint or link.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/io/urdf_chain.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = std::acos(-1.0);

/// A random chain: k = 1..5, twists in [0, pi] (0 and pi exactly one time in six each), rates p/q
/// with |p|, q <= 7 (some 0, never all), phases in [-pi, pi].
RotationChain random_chain(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> stages(1, 5), numerator(-7, 7), denominator(1, 7), sixth(0, 5);
  std::uniform_real_distribution<double> angle(0.0, kPi), phase(-kPi, kPi);
  std::vector<ChainStage> s(static_cast<std::size_t>(stages(rng)));
  for (ChainStage& stage : s) {
    const int pick = sixth(rng);
    stage.twist = pick == 0 ? 0.0 : pick == 1 ? kPi : angle(rng);
    stage.rate = ChainRate(numerator(rng), denominator(rng));
    stage.phase = phase(rng);
  }
  if (s.back().rate.is_zero()) s.back().rate = ChainRate(denominator(rng), denominator(rng));
  return RotationChain(s);
}

/// The first stage with a nonzero rate: chain_to_urdf's motor.
std::size_t motor_stage(const RotationChain& chain) {
  std::size_t m = 0;
  while (chain.stages()[m].rate.is_zero()) ++m;
  return m;
}

/// The rotation of a URDF origin's rpy: Rz(yaw) Ry(pitch) Rx(roll) (fixed axes x, y, z in turn).
Eigen::Matrix3d rpy(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

/// The opening lines of the wrist's pitch and roll joints (name, type, origin, limit, mimic).
const char* const kPitchJoint = R"(<joint name="wrist_pitch" type="revolute">
    <origin xyz="0 0 0" rpy="1.2 0.3 -0.5"/>
    <limit lower="-3" upper="3" effort="10" velocity="2"/>
    <mimic joint="wrist_yaw" multiplier="0.5" offset="0.25"/>)";
const char* const kRollJoint = R"(<joint name="wrist_roll" type="continuous">
    <origin xyz="0 0 0.05" rpy="0 0 0.2"/>
    <mimic joint="wrist_pitch" multiplier="-1.5" offset="-0.1"/>)";

/// A 3-joint geared wrist as a robot description lays it out: a yaw joint (the motor) at the
/// wrist centre (0.1, 0.2, 0.3), a fixed housing mount, a revolute pitch joint geared 1:2 to yaw,
/// a roll joint geared -3:2 to pitch whose origin sits 5 cm along its own axis, a fixed flange;
/// a camera on another branch. `pitch` and `roll` replace the pitch and roll joints' opening lines.
std::string wrist_urdf(const std::string& pitch = kPitchJoint, const std::string& roll = kRollJoint) {
  return R"(<?xml version="1.0"?>
<robot name="geared_wrist">
  <link name="base_link"/>
  <link name="yaw_link"/>
  <link name="housing"/>
  <link name="pitch_link"/>
  <link name="roll_link"/>
  <link name="flange"/>
  <link name="camera"/>
  <joint name="wrist_yaw" type="continuous">
    <parent link="base_link"/>
    <child link="yaw_link"/>
    <origin xyz="0.1 0.2 0.3" rpy="0.2 -0.1 0.4"/>
    <axis xyz="0 0 1"/>
  </joint>
  <joint name="housing_mount" type="fixed">
    <parent link="yaw_link"/>
    <child link="housing"/>
    <origin xyz="0 0 0" rpy="0.3 0.1 0"/>
  </joint>
  )" + pitch + R"(
    <parent link="housing"/>
    <child link="pitch_link"/>
    <axis xyz="0 1 0"/>
  </joint>
  )" + roll + R"(
    <parent link="pitch_link"/>
    <child link="roll_link"/>
    <axis xyz="0 0 1"/>
  </joint>
  <joint name="flange_mount" type="fixed">
    <parent link="roll_link"/>
    <child link="flange"/>
    <origin xyz="0 0 0.08" rpy="0 0.4 0.3"/>
  </joint>
  <joint name="camera_mount" type="fixed">
    <parent link="base_link"/>
    <child link="camera"/>
    <origin xyz="0.5 0 0" rpy="0 0 0"/>
  </joint>
</robot>
)";
}

/// The tool axis (1, 0, 1)/sqrt 2 of the flange in base_link's frame when the yaw motor is at u,
/// as the product of the URDF's own rotations (each joint: origin rpy, then its turn about its axis).
Eigen::Vector3d wrist_tool_axis(double u) {
  const double yaw = u, pitch = 0.5 * u + 0.25, roll = -1.5 * pitch - 0.1;  // the mimic equations
  const Eigen::Matrix3d base_R_flange = rpy(0.2, -0.1, 0.4) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                                        rpy(0.3, 0.1, 0) * rpy(1.2, 0.3, -0.5) *
                                        Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()).toRotationMatrix() * rpy(0, 0, 0.2) *
                                        Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix() * rpy(0, 0.4, 0.3);
  return base_R_flange * Eigen::Vector3d(1, 0, 1).normalized();
}

/// The InvalidInput read_urdf_chain throws for xml.
InvalidInput refusal(const std::string& xml, const std::string& from = "base_link", const std::string& to = "flange",
                     const Eigen::Vector3d& axis = Eigen::Vector3d(1, 0, 1)) {
  return test::expect_invalid([&] { read_urdf_chain(xml, from, to, axis); });
}

bool names(const InvalidInput& e, const std::string& what) { return e.message().find("\"" + what + "\"") != std::string::npos; }

}  // namespace

TEST_CASE("urdf chain: 200 random chains written and read back by urdfdom draw the same curve, rates relative to the motor") {
  std::mt19937_64 rng(20240611);
  for (int trial = 0; trial < 200; ++trial) {
    const RotationChain chain = random_chain(rng);
    const std::string xml = chain_to_urdf(chain, "chain_" + std::to_string(trial));
    const UrdfChain read = read_urdf_chain(xml, "base_link", "tool", Eigen::Vector3d(0, 0, 1));
    INFO("trial " << trial << ": rates " << chain.rates_text() << "\n" << xml);
    REQUIRE(read.chain.size() == chain.size());
    const std::size_t m = motor_stage(chain);
    const ChainStage& motor = chain.stages()[m];
    CHECK(read.motor == "joint_" + std::to_string(m + 1));
    CHECK(read.base_rotation.isApprox(Eigen::Matrix3d::Identity(), 1e-15));
    for (std::size_t i = 0; i < chain.size(); ++i) {
      CHECK(read.joints[i] == "joint_" + std::to_string(i + 1));
      const ChainRate& n = chain.stages()[i].rate;
      CHECK(read.chain.stages()[i].rate == ChainRate(n.p() * motor.rate.q(), n.q() * motor.rate.p()));  // N_i / N_m exactly
      CHECK(std::fabs(read.chain.stages()[i].twist - chain.stages()[i].twist) <= 1e-15);
    }
    // The read chain's parameter is the motor's angle u = N_m s + P_m (long double: the angles
    // over a whole period, up to ~2e4 rad, keep ~1e-15 rad).
    const ChainCurve<long double> original(chain), read_back(read.chain);
    const long double period = original.period();
    for (int j = 0; j < 50; ++j) {
      const long double s = period * j / 50;
      const long double u = s * motor.rate.p() / motor.rate.q() + motor.phase;
      const double miss = static_cast<double>((original.point(s) - read_back.point(u)).norm());
      CHECK(miss <= 1e-12);
    }
  }
}

TEST_CASE("urdf chain: chain_to_urdf's motor is the first joint with a nonzero rate, written with the shortest exact decimals") {
  const RotationChain chain({{0.4, ChainRate(0), 0.5}, {1.0, ChainRate(2, 3), -0.2}, {kPi, ChainRate(-5, 7), 1.0}});
  const std::string xml = chain_to_urdf(chain, "a&b");
  CHECK(xml.find("<robot name=\"a&amp;b\">") != std::string::npos);
  CHECK(xml.find("<joint name=\"joint_2\" type=\"continuous\">") != std::string::npos);
  CHECK(xml.find("<mimic joint=\"joint_2\" multiplier=\"0\" offset=\"0.5\"/>") != std::string::npos);  // joint 1 does not turn
  CHECK(xml.find("multiplier=\"-1.0714285714285714\"") != std::string::npos);                      // (-5/7) / (2/3) = -15/14
  const UrdfChain read = read_urdf_chain(xml, "base_link", "tool", Eigen::Vector3d(0, 0, 1));
  CHECK(read.motor == "joint_2");
  CHECK(read.chain.rates_text() == "0,1,-15/14");
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);  // urdfdom's own view
  REQUIRE(model);
  CHECK(model->getJoint("joint_3")->mimic->multiplier == -15.0 / 14.0);
  CHECK(test::expect_invalid([&] { chain_to_urdf(chain, ""); }).field() == "robot name");
}

TEST_CASE("urdf chain: a geared wrist with rpy origins, a fixed mount and composed mimics matches the URDF's rotation product") {
  const UrdfChain read = read_urdf_chain(wrist_urdf(), "base_link", "flange", Eigen::Vector3d(2, 0, 2));
  CHECK(read.joints == std::vector<std::string>{"wrist_yaw", "wrist_pitch", "wrist_roll"});
  CHECK(read.motor == "wrist_yaw");
  CHECK(read.chain.rates_text() == "1,1/2,-3/4");  // roll: -1.5 * 0.5
  CHECK((read.centre - Eigen::Vector3d(0.1, 0.2, 0.3)).norm() <= 1e-15);
  CHECK(read.chain.period() == Approx(8 * kPi).epsilon(1e-15));
  const ChainCurve<double> curve(read.chain);
  for (int j = 0; j < 50; ++j) {
    const double u = read.chain.period() * j / 50 - 3.0;
    const Eigen::Vector3d base_point = read.base_rotation * curve.point(u);
    CHECK((base_point - wrist_tool_axis(u)).norm() <= 1e-12);
  }
  CHECK(chain_from_urdf(wrist_urdf(), "base_link", "flange", Eigen::Vector3d(1, 0, 1)).rates_text() == "1,1/2,-3/4");
}

TEST_CASE("urdf chain: a motor off the path drives the chain, its angle the parameter") {
  const UrdfChain read = read_urdf_chain(wrist_urdf(), "housing", "flange", Eigen::Vector3d(0, 0, 1));
  CHECK(read.joints == std::vector<std::string>{"wrist_pitch", "wrist_roll"});
  CHECK(read.motor == "wrist_yaw");
  CHECK(read.chain.rates_text() == "1/2,-3/4");
}

TEST_CASE("urdf chain: refusals name the joint or link and say why") {
  SECTION("an axis line off the common centre") {
    const InvalidInput e = refusal(wrist_urdf(R"(<joint name="wrist_pitch" type="continuous">
    <origin xyz="0.01 0 0" rpy="1.2 0.3 -0.5"/>
    <mimic joint="wrist_yaw" multiplier="0.5"/>)"));
    CHECK(e.field() == "urdf");
    CHECK(names(e, "wrist_pitch"));
    CHECK(e.problem().find("axis line passes") != std::string::npos);
  }
  SECTION("a prismatic joint") {
    const InvalidInput e = refusal(wrist_urdf(R"(<joint name="wrist_pitch" type="prismatic">
    <limit lower="0" upper="0.1" effort="10" velocity="1"/>)"));
    CHECK(names(e, "wrist_pitch"));
    CHECK(e.problem().find("prismatic") != std::string::npos);
  }
  SECTION("two independent joints") {
    const InvalidInput e = refusal(wrist_urdf(kPitchJoint, R"(<joint name="wrist_roll" type="continuous">)"));
    CHECK(names(e, "wrist_roll"));
    CHECK(e.problem().find("two independent joints") != std::string::npos);
  }
  SECTION("a missing link") {
    const InvalidInput e = refusal(wrist_urdf(), "base_link", "gripper");
    CHECK(e.field() == "to");
    CHECK(names(e, "gripper"));
  }
  SECTION("links on different branches") {
    const InvalidInput e = refusal(wrist_urdf(), "camera", "flange");
    CHECK(e.field() == "to");
    CHECK(names(e, "flange"));
    CHECK(names(e, "camera"));
  }
  SECTION("malformed XML") {
    const std::string xml = wrist_urdf();
    const InvalidInput e = refusal(xml.substr(0, xml.size() / 2));
    CHECK(e.field() == "urdf");
    CHECK(e.problem().find("could not parse") != std::string::npos);
  }
  SECTION("a multiplier that is no fraction") {
    const InvalidInput e = refusal(wrist_urdf(R"(<joint name="wrist_pitch" type="revolute">
    <limit lower="-3" upper="3" effort="10" velocity="2"/>
    <mimic joint="wrist_yaw" multiplier="3.141592653589793"/>)"));
    CHECK(names(e, "wrist_pitch"));
    CHECK(e.problem().find("not a fraction") != std::string::npos);
  }
  SECTION("a mimic of a joint the robot does not have") {
    const InvalidInput e = refusal(wrist_urdf(R"(<joint name="wrist_pitch" type="continuous">
    <mimic joint="elbow" multiplier="2"/>)"));
    CHECK(names(e, "wrist_pitch"));
    CHECK(names(e, "elbow"));
  }
  SECTION("a zero tool axis") { CHECK(refusal(wrist_urdf(), "base_link", "flange", Eigen::Vector3d::Zero()).field() == "axis"); }
}

namespace {

/// The wrist description with `text` right after its <robot ...> opening tag.
std::string inside_robot(const std::string& text) {
  std::string xml = wrist_urdf();
  xml.insert(xml.find('>', xml.find("<robot")) + 1, text);
  return xml;
}

/// 50,000 elements opened by `open` (e.g. "<a>") nested, each closed by </a>.
std::string nested(const std::string& open) {
  std::string opens, closes;
  for (int k = 0; k < 50000; ++k) opens += open, closes += "</a>";
  return inside_robot(opens + closes);
}

/// The <robot> element with 100,000 attributes a<k>=<value>.
std::string wide(const std::string& value) {
  std::string xml = wrist_urdf(), attributes;
  for (int k = 0; k < 100000; ++k) attributes += " a" + std::to_string(k) + "=" + value;
  xml.insert(xml.find("<robot") + 6, attributes);
  return xml;
}

}  // namespace

TEST_CASE("urdf chain: documents nesting deeper than 64 elements or with an element of more than 64 attributes are refused before urdfdom") {
  // 50,000 nested elements overflow urdfdom's recursive parser; 100,000 attributes take it minutes.
  const InvalidInput d = refusal(nested("<a>"));
  CHECK(d.field() == "urdf");
  CHECK(d.problem().find("nest") != std::string::npos);
  const InvalidInput w = refusal(wide("\"1\""));
  CHECK(w.field() == "urdf");
  CHECK(w.problem().find("attributes") != std::string::npos);
  // A legal document is as deep as 64 and as wide as 64.
  CHECK_NOTHROW(read_urdf_chain(wrist_urdf(), "base_link", "flange", Eigen::Vector3d(1, 0, 1)));
}

TEST_CASE("urdf chain: the shape check follows XML's quoting, so nesting and attributes hidden in quoted values are refused") {
  // '>' and "/>" inside a quoted attribute value are text: each <a x="/>"> opens an element.
  const InvalidInput d = refusal(nested("<a x=\"/>\">"));
  CHECK(d.field() == "urdf");
  CHECK(d.problem().find("nest") != std::string::npos);
  const InvalidInput w = refusal(wide("\">\""));
  CHECK(w.field() == "urdf");
  CHECK(w.problem().find("attributes") != std::string::npos);
  // TinyXML's own reading: "<1 x='>" is an unknown node that ends at its first '>' (no quoting),
  // so the <a> after it nest; a declaration reads its quoted values, so a '>' in one is refused;
  // a malformed UTF-8 lead byte swallows what follows it in TinyXML: refused.
  std::string opens;
  for (int k = 0; k < 50000; ++k) opens += "<a>";
  CHECK(refusal(inside_robot("<1 x='>" + opens)).problem().find("nest") != std::string::npos);
  CHECK(refusal(inside_robot("<?xml version='></a>'?>")).problem().find("declaration") != std::string::npos);
  CHECK(refusal(inside_robot("\xE0</a>")).problem().find("UTF-8") != std::string::npos);
}

TEST_CASE("urdf chain: comments, CDATA and declarations hold no elements or attributes (a xacro-generated layout is read)") {
  // The layout xacro writes for public arm and gripper descriptions: a declaration, a banner
  // comment of '=' characters, xacro-style names, and a gripper whose fingers mimic one joint.
  std::string banner = "<!-- " + std::string(300, '=') + " -->\n<!-- |    This document was autogenerated by xacro    | -->\n<!-- " +
                       std::string(300, '=') + " -->\n";
  std::string xml = wrist_urdf();
  xml.insert(xml.find("<robot"), banner);
  const std::string gripper = R"(
  <!-- fingers: <a b="c"> = = = -->
  <link name="robotiq_85_left_knuckle_link"/>
  <link name="robotiq_85_right_knuckle_link"/>
  <joint name="robotiq_85_left_knuckle_joint" type="revolute">
    <parent link="flange"/>
    <child link="robotiq_85_left_knuckle_link"/>
    <origin xyz="0.0306 0 0.0548" rpy="0 0 0"/>
    <axis xyz="0 -1 0"/>
    <limit lower="0" upper="0.8" effort="1000" velocity="2.0"/>
  </joint>
  <joint name="robotiq_85_right_knuckle_joint" type="revolute">
    <parent link="flange"/>
    <child link="robotiq_85_right_knuckle_link"/>
    <origin xyz="-0.0306 0 0.0548" rpy="0 0 3.14159265358979"/>
    <axis xyz="0 -1 0"/>
    <limit lower="0" upper="0.8" effort="1000" velocity="2.0"/>
    <mimic joint="robotiq_85_left_knuckle_joint" multiplier="1" offset="0"/>
  </joint>
  <![CDATA[ <x y="1" z="2"> ]]>
)";
  xml.insert(xml.rfind("</robot>"), gripper);
  const std::size_t equals = static_cast<std::size_t>(std::count(xml.begin(), xml.end(), '='));
  REQUIRE(equals > 600);  // counted as attributes, the banner alone would pass 64
  const UrdfChain read = read_urdf_chain(xml, "base_link", "flange", Eigen::Vector3d(1, 0, 1));
  CHECK(read.chain.rates_text() == "1,1/2,-3/4");
  for (double u : {0.0, 0.7, -2.1}) CHECK((read.base_rotation * ChainCurve<double>(read.chain).point(u) - wrist_tool_axis(u)).norm() <= 1e-12);
}

TEST_CASE("urdf chain: the centre check does not scale with distances that do not matter, and refuses infinite ones") {
  // The roll joint's origin 1e12 m out along its own axis: its axis line still passes the
  // centre, accepted; moved 1 m off that line as well: refused (1 m is no rounding of 1e12).
  const auto roll_at = [](const std::string& xyz) {
    return R"(<joint name="wrist_roll" type="continuous">
    <origin xyz=")" + xyz + R"(" rpy="0 0 0.2"/>
    <mimic joint="wrist_pitch" multiplier="-1.5" offset="-0.1"/>)";
  };
  CHECK_NOTHROW(read_urdf_chain(wrist_urdf(kPitchJoint, roll_at("0 0 1e12")), "base_link", "flange", Eigen::Vector3d(1, 0, 1)));
  const InvalidInput miss = refusal(wrist_urdf(kPitchJoint, roll_at("1 0 1e12")));
  CHECK(names(miss, "wrist_roll"));
  CHECK(miss.problem().find("axis line passes") != std::string::npos);
  const InvalidInput far = refusal(wrist_urdf(kPitchJoint, roll_at("1e308 1e308 1e308")));
  CHECK(far.field() == "urdf");
  CHECK(names(far, "wrist_roll"));
}
