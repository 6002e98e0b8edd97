// sphtroch/wrist/wrist_cap_result.hpp — what wrist_cap (wrist_cap.hpp) answers: the radius of the
// largest spherical cap about a home direction with no fold of a 2-motor wrist inside, as a
// certified bracket, the nearest fold point found, and the inverse-kinematics count inside the cap.
//
//   sphtroch::WristCapResult r;             // filled by sphtroch::wrist_cap (wrist_cap.hpp)
//   r.lower = 0.25;
//   r.upper = 0.25 + 5e-10;
//   r.upper - r.lower;                      // the bracket's width, radians
//
// No dependency: the front ends (the tool's text and JSON, wrist_cap_output.hpp) read it without
// the interval headers.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

struct WristCapResult {
  double lower = 0;                    ///< radians: the cap's radius is at least this
  double upper = 3.141592653589793;    ///< radians: and at most this (pi until a fold point is proved)
  bool radius_certified = false;       ///< upper - lower <= the width asked for (kWristCapWidth)
  bool home_on_fold = false;           ///< lower == 0: home may lie on a fold (within upper of one)
  std::optional<std::size_t> count;    ///< inverse-kinematics solutions at home, when wrist_ik certified them
  bool certified = false;              ///< radius certified, and the count known (or home on a fold)
  std::string why;                     ///< not certified: what is missing ("" when certified)
  bool has_fold_point = false;         ///< a fold point proved (then the next three are set)
  std::array<double, 3> fold_point{};  ///< P at it (unit): the nearest fold point found, at angle <= upper from home
  std::array<double, 2> fold_motors{}; ///< its motor angles, radians, motor j in [0, T_j)
  double fold_motor_radius = 0;        ///< the point with D = 0 lies within this (radians, each motor) of fold_motors
  std::vector<double> periods;         ///< T_j = 2 pi L_j, radians
  std::size_t boxes = 0;               ///< boxes of the motor torus evaluated (the work)
  std::size_t ik_boxes = 0;            ///< boxes of the count's search (wrist_ik)
};

}  // namespace sphtroch
