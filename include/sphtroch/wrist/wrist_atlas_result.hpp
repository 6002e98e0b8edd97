// sphtroch/wrist/wrist_atlas_result.hpp — what wrist_fold_atlas (wrist_atlas.hpp) answers: the
// critical curve D(u) = 0 of a 2-motor wrist enclosed in cells of the motor torus, each cell's
// image on the sphere and a fold point proved in it, and the fold set drawn as polylines through
// those points.
//
//   sphtroch::WristAtlasResult r;           // filled by sphtroch::wrist_fold_atlas (wrist_atlas.hpp)
//   sphtroch::WristFoldCell cell;
//   cell.motors = {{{0.0, 0.05}, {1.5, 1.55}}};   // motor 1 in [0, 0.05], motor 2 in [1.5, 1.55]
//   r.cells.push_back(cell);
//   r.cells.front().motors[1][0];           // motor 2's lower end, radians
//
// No dependency: the front ends (the tool's text and JSON, wrist_atlas_output.hpp) read it without
// the interval headers.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace sphtroch {

/// A cell of the torus where D may vanish: motors[j] = {lo, hi} (radians, motor j's range as
/// searched: [-0.0137 T_j, 0.9863 T_j]); image[x] = {lo, hi}, the box holding P(u) over the cell; a
/// fold point proved in it or, when the curve only clips a corner, within twice the cell's width of
/// its centre (has_point): its unit P and its motors (the exact point within 1e-12 rad).
struct WristFoldCell {
  std::array<std::array<double, 2>, 2> motors{};
  std::array<std::array<double, 2>, 3> image{};
  bool has_point = false;
  std::array<double, 3> point{};
  std::array<double, 2> point_motors{};
};

/// Fold points of 8-adjacent cells (modulo the periods), in order: indices into cells; closed when
/// the last cell is adjacent to the first.
struct WristFoldPolyline {
  std::vector<std::size_t> cells;
  bool closed = false;
};

/// Where a polyline passes a cusp of the fold set (wrist_cusps.hpp): an estimate, not a proof. point
/// (unit) on the sphere, the motors of the nearer fold point (radians), the polyline's index.
struct WristCusp {
  std::array<double, 3> point{};
  std::array<double, 2> motors{};
  std::size_t polyline = 0;
};

struct WristAtlasResult {
  std::vector<WristFoldCell> cells;           ///< every cell where D may vanish (all others proved D != 0)
  std::vector<WristFoldPolyline> polylines;   ///< through the cells' fold points
  std::vector<WristCusp> cusps;               ///< estimated along the polylines (not certified)
  double cell_width = 0;                      ///< radians of joint motion: each cell's widest side times sum_i |C_ij|
  double enclosure = 0;                       ///< radians: every fold point is within this of a cell's proved fold point
  std::size_t cells_without_point = 0;        ///< cells where D may vanish but no fold point was proved (none may be there)
  bool complete = false;                      ///< the search finished: every u with D(u) = 0 lies in a listed cell
  bool certified = false;                     ///< the enclosure is complete and every cell has its point
  std::string why;                            ///< not certified: what is missing
  std::vector<double> periods;                ///< T_j = 2 pi L_j, radians
  std::size_t boxes = 0;                      ///< boxes evaluated (the work)
};

}  // namespace sphtroch
