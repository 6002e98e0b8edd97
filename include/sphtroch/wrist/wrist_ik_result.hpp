// sphtroch/wrist/wrist_ik_result.hpp — what a wrist's inverse kinematics answers (wrist_ik.hpp):
// every solution on the motor torus with the radius of its certified box, whether the list is
// certified complete, and when it is not, what is undecided.
//
//   sphtroch::WristIkResult r;              // filled by sphtroch::wrist_ik (wrist_ik.hpp)
//   r.certified = true;
//   r.solutions.push_back({{0.5, 2.25}, 1e-15});
//   r.solutions.front().motors[1];          // motor 2's angle, radians in [0, T_2)
//
// No dependency: the front ends (the tool's text and JSON, wrist_ik_output.hpp) read it without
// the interval headers.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sphtroch {

/// One solution: the motor angles (radians, motor j in [0, T_j)); the root lies within
/// box_radius (radians) of them in every motor.
struct WristSolution {
  std::vector<double> motors;
  double box_radius = 0;
};

struct WristIkResult {
  std::vector<WristSolution> solutions;  ///< lexicographic order of the motors
  bool certified = false;                ///< every box decided: the list is every solution, once
  bool on_fold = false;                  ///< not certified, and every undecided box may hold a root where J is singular
  std::string why;                       ///< not certified: what is undecided ("" when certified)
  std::vector<double> periods;           ///< T_j = 2 pi L_j, radians
  std::size_t boxes = 0;                 ///< boxes examined (the work)
  std::size_t undecided = 0;             ///< boxes left undecided
  std::vector<std::vector<double>> undecided_at;  ///< centres of the first undecided boxes (at most 16), reduced to [0, T_j)
};

}  // namespace sphtroch
