// sphtroch/synthesis/precision_solution.hpp — what the precision-point searches return
// (precision_points.hpp, free_axis_points.hpp): each train through the points with its parameters
// and frame, the list's certificate, the search's options and the input's tolerances. Plain types
// (no CGAL), so that a result can be read where the search is not compiled (sphtroch::compiled).
//
//   sphtroch::PrecisionPoints r;                 // IsolatedRoots<PrecisionSolution>
//   r.certified;  r.solutions;                   // every train, each proved alone in its box
//   sphtroch::sort_solutions(r);                 // by a2, then a3
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/interval/isolated_roots.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace sphtroch {

struct PrecisionPointsOptions {
  std::size_t max_boxes = 4000000;  // work bound: beyond it the result is returned uncertified
                                    // (free axis: the bound of each of its 18 searches)
  std::size_t threads = 1;          // free axis: searches run at once (the result is the same)
};

struct PrecisionSolution {
  GearTrain train;               // phase reduced to [0, 2 pi / q)
  std::vector<double> params;    // theta2 at each point (input order), in [0, 2 pi q)
  double residual = 0.0;         // max |P(params[i]) - points[i]| (chord), measured in double
  /// false: Newton's limit in a box the certificate could not decide (a near-singular root, e.g.
  /// two roots closer than the arithmetic resolves); it passes the points (residual <= 1e-12)
  /// but is not proven to be a single root, and the list is then not certified.
  bool isolated = true;
  /// Columns x, y, z of the train's frame in the points' coordinates (z: the sun axis), so that
  /// points[i] = frame * P(params[i]); the identity for a fixed frame.
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
};

/// solutions by a2, then a3; certified, undecided, boxes: as root_isolation.hpp's IsolatedRoots.
using PrecisionPoints = IsolatedRoots<PrecisionSolution>;

/// Orders a problem's solutions by a2, then a3.
inline void sort_solutions(PrecisionPoints& r) {
  std::sort(r.solutions.begin(), r.solutions.end(), [](const PrecisionSolution& a, const PrecisionSolution& b) {
    return std::make_pair(a.train.a2(), a.train.a3()) < std::make_pair(b.train.a2(), b.train.a3());
  });
}

/// Input points must be unit vectors to this, and no two closer than kDistinctPoints (chord).
constexpr double kPrecisionUnitTolerance = 1e-6;
constexpr double kDistinctPoints = 1e-9;

}  // namespace sphtroch
